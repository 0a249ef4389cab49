// The IBL section of the accuracy-versus-time report: prefiltering time for a 1024 x 512 map,
// the E_rho and E_D tables' error at 16^2 to 128^2 entries, the glint estimate's time for K = 4 and 8 and linear
// versus log weights, and the cost of shading a sphere with glints against smooth IBL, in one
// run. Writes docs/ibl.md.
#include <cmath>
#include <chrono>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glint/ibl.hpp>
#include <glint/io/exr.hpp>

#include "../examples/lights_scene.hpp"
#include "report.hpp"

#ifndef GLINT_DATA_DIR
#error "GLINT_DATA_DIR must point at the project's data/ folder"
#endif

namespace glint_report {

section ibl_section(double min_time) {
    section out;
    std::ostringstream md, csv;
    const std::string map = std::string(GLINT_DATA_DIR) + "/envmaps/sunset.exr";
    const auto img = glint::io::read_exr(map);
    // Table resolution: E_rho and E_D tables of T x T entries, each built once (the time of its
    // first build: environments share tables of one size), against references off the table's
    // grid: E_D exact (glint::integrated_ndf_cone, 32 pieces), E_rho by 16384 Hammersley VNDF
    // samples (the tables use 1024). An environment of a tiny map carries each table.
    struct table_row {
        int size;
        double build_s, worst_rho = 0, worst_d = 0;
    };
    std::vector<table_row> table_rows;
    {
        const std::vector<float> grey(3 * 8 * 4, 1.0f);
        const int P = 24;  // reference points per axis
        std::vector<double> ref_rho, ref_d, cs, sas;
        for (int i = 0; i < P; ++i)
            for (int j = 0; j < P; ++j) {
                const double c = 0.02 + 0.96 * (i + 0.37) / P, sa = 0.05 + 0.95 * (j + 0.61) / P, alpha = sa * sa;
                const glm::dvec3 wo(std::sqrt(1 - c * c), 0, c);
                cs.push_back(c), sas.push_back(sa);
                ref_rho.push_back(glint::detail::directional_albedo(wo, alpha, 16384));
                ref_d.push_back(glint::detail::visible_area(wo, alpha));
            }
        for (int T : {16, 32, 64, 128}) {
            glint::ibl_options o;
            o.table_size = T, o.samples = 1, o.roughness_levels = 2;
            const auto t0 = std::chrono::steady_clock::now();
            const auto env = glint::build_environment(8, 4, grey, o);
            table_row r{T, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
            for (std::size_t i = 0; i < cs.size(); ++i) {
                const float c = static_cast<float>(cs[i]), sa = static_cast<float>(sas[i]);
                r.worst_rho = std::max(r.worst_rho, std::fabs(static_cast<double>(env.albedo(c, sa)) - ref_rho[i]) / ref_rho[i]);
                r.worst_d = std::max(r.worst_d, std::fabs(static_cast<double>(env.visible_area(c, sa)) - ref_d[i]) / ref_d[i]);
            }
            table_rows.push_back(r);
        }
    }
    // Prefiltering time (wall clock of one build each; not a ratio, stated as measured).
    std::vector<std::unique_ptr<glint::environment>> envs;
    std::vector<double> build_s;
    for (int K : {4, 8}) {
        for (bool log_weights : {false, true}) {
            glint::ibl_options o;
            o.levels = K, o.log_weights = log_weights;
            const auto t0 = std::chrono::steady_clock::now();
            envs.push_back(std::make_unique<glint::environment>(glint::build_environment(img.width, img.height, img.rgb, o)));
            build_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
    }
    // Shading: per pixel of a 160 x 100 view of the sphere, smooth (mode 0) against glints (1), and
    // glints on one lattice point per pixel (2; glint::grid_pixel_setup with a lattice_u).
    const char* labels[] = {"K=4 linear", "K=4 log", "K=8 linear", "K=8 log"};
    // The rows first, first + step, ... of frame `it` (its seed) in a mode. Glint frames shade a
    // row's pixels together, as a CPU renderer shades a row: glint::ibl_sample_pixels, eight pixels
    // a pass in AVX2 lanes (DEVELOPERS.md measures it against one pixel at a time, and eight).
    auto frame_rows = [](const glint::environment* env, int mode, int first, int step, std::size_t it) {
        float acc = 0;
        const float sa = 0.35f, alpha = sa * sa, dh = env->total_area(alpha);
        glint::grid_params<float> g;
        g.log_density = 4.0f;
        g.seed = static_cast<std::uint32_t>(it);
        for (int y = first; y < 100; y += step) {
            glint::grid_pixel<float> pixel[160];
            glm::vec2 uv[160], duvdx[160], duvdy[160];
            glint::ibl_indicators<float> ind[160];
            glint::ibl_estimate<float> est[160];
            float e_d[160], shade[160], lattice_u[160];
            int count = 0;
            for (int x = 0; x < 160; ++x) {
                // A sphere seen from afar: normal from the pixel, view along -z.
                const float px = (static_cast<float>(x) - 80) / 50, py = (50 - static_cast<float>(y)) / 50, rr = px * px + py * py;
                if (rr >= 1) continue;
                const glm::vec3 n(px, py, std::sqrt(1 - rr)), d(0, 0, -1);
                const float cos_o = n.z;
                // Smooth shading reads the radiance alone, glints the K indicators too.
                const glm::vec3 r = glm::reflect(d, n);
                if (mode == 0) {
                    acc += env->albedo(cos_o, sa) * env->lookup_radiance(r, sa).x;
                    continue;
                }
                const auto s = env->lookup(r, sa);
                shade[count] = env->albedo(cos_o, sa) * s.radiance.x;
                ind[count] = s.indicators;
                e_d[count] = env->visible_area(cos_o, sa);
                uv[count] = glm::vec2(static_cast<float>(x), static_cast<float>(y));
                duvdx[count] = glm::vec2(1, 0), duvdy[count] = glm::vec2(0, 1);
                lattice_u[count++] = glint_examples::pixel_lattice_u(mode == 2, x, y, g.seed);  // mode 2: one lattice point
            }
            if (count == 0) continue;  // smooth
            // The footprints eight at a time (glint::grid_pixels_setup), then the estimates.
            glint::grid_pixels_setup(static_cast<std::size_t>(count), uv, duvdx, duvdy, g, lattice_u, pixel);
            glint::ibl_sample_pixels(count, pixel, g, env->levels(), ind, e_d, dh, est);
            for (int i = 0; i < count; ++i) acc += shade[i] * glint::modulation(est[i]);
        }
        benchmark::DoNotOptimize(acc);
    };
    // Each frame in round_count rounds (report.hpp), the least time of each; the linear knob's
    // smooth and glint frames also on all cores (add_all_cores). Where the vector code runs its
    // AVX-512 build, K = 4's linear glint frame also with the AVX2 build alone (lanes_limit).
    const int lanes = glint::detail::glsl::kernels<float>::glint_cpu_lanes();
    for (int round = 0; round < round_count; ++round)
        for (std::size_t e = 0; e < envs.size(); ++e)
            for (int mode = 0; mode < 3; ++mode) {
                const glint::environment* env = envs[e].get();
                add("ibl_" + std::to_string(e) + "_" + std::to_string(mode) + round_suffix(round),
                    [frame_rows, env, mode](std::size_t it) { frame_rows(env, mode, 0, 1, it); }, min_time);
                if (e == 0 && mode == 1 && lanes == 2)
                    add("ibl_avx2_" + std::to_string(e) + round_suffix(round),
                        [frame_rows, env](std::size_t it) {
                            glint::detail::lanes_limit = 1;
                            frame_rows(env, 1, 0, 1, it);
                            glint::detail::lanes_limit = 2;
                        },
                        min_time);
                if (e % 2 == 0 && mode < 2)
                    add_all_cores("ibl_all_cores_" + std::to_string(e) + "_" + std::to_string(mode) + round_suffix(round),
                                  [frame_rows, env, mode](int first, int step, std::size_t it) { frame_rows(env, mode, first, step, it); }, min_time);
            }
    const auto ns = run_all();
    md << "## Image-based lighting of glints (glint/ibl.hpp)\n\n";
    std::ostringstream t;
    t << "Environment `sunset.exr` (" << img.width << " x " << img.height << "), 6 roughness levels, 64 GGX samples per texel, "
      << "one thread. Shading: a sphere of radius 50 pixels in a 160 x 100 view (7825 pixels), smooth split-sum IBL against glints (ln density "
         "4); each frame the least time of "
      << round_count << " rounds, the frames interleaved:\n\n"
      << "| knob | prefilter s | smooth us/frame | glints us/frame | glints / smooth | one lattice point / smooth | all cores: smooth us/frame | all cores: glints us/frame | all cores: glints / smooth |\n|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t e = 0; e < envs.size(); ++e) {
        const double s0 = ns.at("ibl_" + std::to_string(e) + "_0"), s1 = ns.at("ibl_" + std::to_string(e) + "_1"),
                     s2 = ns.at("ibl_" + std::to_string(e) + "_2");
        t << "| " << labels[e] << " | " << fmt(build_s[e]) << " | " << fmt(s0 * 1e-3, "%.0f") << " | " << fmt(s1 * 1e-3, "%.0f") << " | " << fmt(s1 / s0)
          << " | " << fmt(s2 / s0) << " | ";
        if (e % 2 == 0) {
            const double a0 = ns.at("ibl_all_cores_" + std::to_string(e) + "_0"), a1 = ns.at("ibl_all_cores_" + std::to_string(e) + "_1");
            t << fmt(a0 * 1e-3, "%.0f") << " | " << fmt(a1 * 1e-3, "%.0f") << " | " << fmt(a1 / a0) << " |\n";
            csv << "ibl," << labels[e] << " all cores (" << all_cores() << " threads),float,glints/smooth frame time," << a1 / a0 << "," << a1 << "," << a1 / a0
                << ",smooth IBL frame on all cores\n";
        } else {
            t << "- | - | - |\n";
        }
        csv << "ibl," << labels[e] << ",float,glints/smooth frame time," << s1 / s0 << "," << s1 << "," << s1 / s0 << ",smooth IBL frame\n";
        csv << "ibl," << labels[e] << " one lattice point,float,glints/smooth frame time," << s2 / s0 << "," << s2 << "," << s2 / s0 << ",smooth IBL frame\n";
    }
    const char* path_names[] = {"the baseline code (no AVX2)", "its AVX2 build (this CPU has no AVX-512)", "its AVX-512 build (AVX2 code built with AVX-512 F, VL, DQ and BW, 256-bit vectors)"};
    t << "\nThe glint frames' vector code ran " << path_names[lanes] << " (glint_cpu_lanes, kernels/core.glsl)";
    if (lanes == 2) {
        const double s0 = ns.at("ibl_0_0"), sv = ns.at("ibl_avx2_0");
        t << "; with its AVX2 build alone, " << labels[0] << ": " << fmt(sv * 1e-3, "%.0f") << " us a frame, " << fmt(sv / s0) << "x smooth";
        csv << "ibl," << labels[0] << " AVX2 build alone,float,glints/smooth frame time," << sv / s0 << "," << sv << "," << sv / s0 << ",smooth IBL frame\n";
    }
    t << ".\n";
    t << "\n\"One lattice point\": glint::grid_pixel_setup with a lattice_u per pixel (one of the footprint's four lattice points, drawn "
         "with probability w_L; the same mean and per-pixel variance; docs/grid.md). \"All cores\" (the linear knob): the smooth and the "
         "glint frame on " << all_cores() << " threads at once, thread t shading rows t, t + " << all_cores() << ", ..., the wall time of a frame "
         "(bench/report.hpp, add_all_cores).\n";
    t << "\nTable resolution: E_rho and E_D at T x T entries (bilinear in (sqrt(cos theta_o), sqrt alpha)), worst relative error "
         "at 576 points off the tables' grid (cos theta_o in [0.02, 0.98], sqrt(alpha) in [0.05, 1]) against E_D exact and E_rho by "
         "16384 Hammersley VNDF samples (the tables' entries use 1024); the lookup costs the same at every size; time to build both "
         "tables once, one thread:\n\n"
      << "| T | entries per table | worst E_rho error | worst E_D error | build s |\n|---|---|---|---|---|\n";
    for (const auto& r : table_rows) {
        t << "| " << r.size << (r.size == glint::ibl_options{}.table_size ? " (default)" : "") << " | " << r.size * r.size << " | "
          << fmt(r.worst_rho) << " | " << fmt(r.worst_d) << " | " << fmt(r.build_s) << " |\n";
        csv << "ibl,tables " << r.size << "x" << r.size << ",float,worst relative error of E_D (E_rho: " << r.worst_rho << ")," << r.worst_d
            << ",,,exact integral\n";
    }
    md << t.str();
    out.markdown = md.str();
    out.csv_rows = csv.str();
    out.files["ibl.md"] = "# Image-based lighting of glints: cost and accuracy\n\nGenerated by `build/release/bench/glint_report --docs docs` "
                          "(`scripts/demo --docs`); one run, one machine.\n\n" +
                          t.str();
    return out;
}

}  // namespace glint_report
