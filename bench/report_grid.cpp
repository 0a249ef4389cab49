// The grid-NDF section of the accuracy-versus-time report: D_Omega's quadrature knob (pieces per
// edge) against 2D adaptive quadrature, the glint estimate per binomial variant and slope-grid
// cell (bias of the mean over grid seeds, time per estimate), and the cost of a frame of the
// showcase scene with glints against the smooth BRDF, per light, in one run.
// Writes docs/grid.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glint/grid.hpp>
#include <glint/microfacet.hpp>

#include "../examples/lights_scene.hpp"
#include "../tests/support/grid_scene.hpp"
#include "../tests/support/microfacet_reference.hpp"
#include "light_pixels.hpp"
#include "report.hpp"

namespace glint_report {

namespace {

// The paired extra-light benchmark's sums (below): ns for smooth with 8 and 16 lights, then glints
// with 8 and 16, and the pixels each way shaded.
double* paired_lights_ns() {
    static double ns[4] = {};
    return ns;
}
double& paired_lights_pixels() {
    static double pixels = 0;
    return pixels;
}

// R / E[R] over seeds at one scene: its mean (must be 1), standard deviation (the glints'
// contrast), the standard error of its variance ((m4 - var^2) / n, the sample variance's), and
// the fraction of footprints with any glint.
struct glint_statistics {
    double mean = 0, se = 0, sd = 0, variance_se = 0, lit = 0;
};

// one_point: each sample on one lattice point, drawn with a uniform of its own (grid_pixel_setup
// with a lattice_u); salt: other seeds and positions, for samples independent of another run's.
glint_statistics grid_statistics(const glint_test::grid_scene& s, int n, bool one_point = false, std::uint32_t salt = 0) {
    glm::vec2 dx, dy;
    s.derivatives(dx, dy);
    std::vector<double> m(static_cast<std::size_t>(n));
    double sum = 0, lit = 0;
    for (int i = 0; i < n; ++i) {
        const auto g = s.params(static_cast<std::uint32_t>(i) * 2654435761u + 17u + salt * 0x9E3779B9u);
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 9u + salt, 9u));
        const glm::vec2 uv(glint::unit_from_bits<float>(h.x) * 97.0f, glint::unit_from_bits<float>(h.y) * 89.0f);
        auto px = glint::grid_pixel_setup(uv, dx, dy, g, one_point ? glint::unit_from_bits<float>(h.z) : -1.0f);
        const double r = static_cast<double>(glint::modulation(glint::grid_sample(px, g, s.light)));
        m[static_cast<std::size_t>(i)] = r;
        sum += r, lit += r > 0;
    }
    glint_statistics o;
    o.mean = sum / n;
    double m2 = 0, m4 = 0;
    for (double r : m) {
        const double d = (r - o.mean) * (r - o.mean);
        m2 += d, m4 += d * d;
    }
    m2 /= n, m4 /= n;
    o.sd = std::sqrt(m2);
    o.se = o.sd / std::sqrt(static_cast<double>(n));
    o.variance_se = std::sqrt(std::max(0.0, m4 - m2 * m2) / n);
    o.lit = lit / n;
    return o;
}

// The largest |mean R / E[R] - 1| over a few scenes, with its standard error.
struct bias_result {
    double worst = 0, se = 0;
    std::string where;
};

bias_result grid_bias(glint::binomial_variant v) {
    bias_result out;
    for (glint_test::light_kind k : {glint_test::light_kind::point, glint_test::light_kind::sphere, glint_test::light_kind::rect})
        for (float logd : {0.0f, 2.0f, 4.0f}) {
            glint_test::grid_scene s;
            s.kind = k, s.alpha = 0.25f, s.log_density = logd, s.footprint = 3.0f, s.variant = v;
            s.prepare();
            const glint_statistics st = grid_statistics(s, 6000);
            if (std::fabs(st.mean - 1) > out.worst) out.worst = std::fabs(st.mean - 1), out.se = st.se, out.where = s.describe();
        }
    return out;
}

// The slope-grid cells of the study below (0.02 is grid_params' default).
const float slope_cells[] = {0.005f, 0.01f, 0.02f, 0.04f, 0.08f};

glint_test::grid_scene slope_cell_scene(float cell) {
    glint_test::grid_scene s;
    s.kind = glint_test::light_kind::point, s.alpha = 0.25f, s.log_density = 6.0f, s.footprint = 3.0f, s.slope_cell = cell;
    s.prepare();
    return s;
}

// Times one estimate of the scene, at a new seed and position each call.
void add_estimate_timing(const std::string& name, const glint_test::grid_scene& sc, double min_time) {
    add(name, [sc](std::size_t i) {
        const glm::vec2 uv(static_cast<float>(i % 997) * 0.37f, static_cast<float>(i % 991) * 0.29f);
        benchmark::DoNotOptimize(sc.estimate(static_cast<std::uint32_t>(i), uv).value);
    }, min_time);
}

}  // namespace

section grid_section(double min_time) {
    section out;
    std::ostringstream md, csv, doc;
    // --- D_Omega pieces -------------------------------------------------------------------
    // The unit test's lights without its far cones (a subset: 432 lights).
    const auto cases = glint_test::light_cases(false);
    std::vector<double> refs;
    for (const auto& c : cases) refs.push_back(glint_test::reference(c));
    const int piece_knobs[] = {4, 6, 8, 12, 16, 32};
    for (int pieces : piece_knobs) {
        add("d_omega_" + std::to_string(pieces), [&cases, pieces](std::size_t i) {
            benchmark::DoNotOptimize(glint_test::d_omega<float>(cases[i % cases.size()], pieces));
        }, min_time);
    }
    // --- grid estimate per variant and slope cell ------------------------------------------
    glint_test::grid_scene timing_scene;
    timing_scene.kind = glint_test::light_kind::sun, timing_scene.alpha = 0.25f, timing_scene.log_density = 3.0f;
    timing_scene.prepare();
    glint_test::grid_scene point_scene = timing_scene;
    point_scene.kind = glint_test::light_kind::point;
    point_scene.prepare();
    for (int v = 0; v <= 4; ++v)
        for (const glint_test::grid_scene* s : {&timing_scene, &point_scene}) {
            glint_test::grid_scene sc = *s;
            sc.variant = static_cast<glint::binomial_variant>(v);
            add_estimate_timing("grid_" + std::string(glint::name(sc.variant)) + "_" + glint_test::name(sc.kind), sc, min_time);
        }
    for (float cell : slope_cells) add_estimate_timing("grid_slope_" + std::to_string(cell), slope_cell_scene(cell), min_time);
    // --- frames ---------------------------------------------------------------------------
    using namespace glint_examples;
    constexpr int fw = 160, fh = 100;
    const camera cam(fw, fh);
    // Modes: 0 smooth; 1 glints; 2 glints, every footprint sampled; 3 glints switched off (the
    // renderer's smooth path through its glint switch); 4 and 5: glints at ln density 14 with
    // and without the smooth-result gate (where most footprints hold enough microfacets); 6: glints
    // on one lattice point per pixel (scene_options::stochastic_lattice).
    // The rows first, first + step, ... of a frame in a mode.
    auto frame_rows = [&cam](light_type t, int mode, int first, int step) {
        scene_options opt;
        opt.smooth = mode == 0 || mode == 3;
        opt.stochastic_lattice = mode == 6;
        opt.smooth_tolerance = (mode == 2 || mode == 5) ? 0.0f : 0.01f;
        if (mode == 4 || mode == 5) opt.log_density = 14.0f;
        light_setup ls;
        ls.type = t;
        shading_counters c;
        float acc = 0;
        vec3 row[fw];
        for (int y = first; y < fh; y += step) {
            render_row(opt, ls, cam, y, 0, fw, row, c);  // the glint estimates batched (glint::grid_sample_pixels)
            for (int x = 0; x < fw; ++x) acc += row[x].x;
        }
        benchmark::DoNotOptimize(acc);
    };
    // Each frame in round_count rounds (report.hpp), the least time of each; modes 0 and 1 also on
    // all cores (add_all_cores).
    for (int round = 0; round < round_count; ++round)
        for (light_type t : {light_type::point, light_type::sun, light_type::area}) {
            for (int mode = 0; mode < 7; ++mode)
                add(std::string("frame_") + name(t) + "_" + std::to_string(mode) + round_suffix(round),
                    [frame_rows, t, mode](std::size_t) { frame_rows(t, mode, 0, 1); }, min_time);
            for (int mode = 0; mode < 2; ++mode)
                add_all_cores(std::string("frame_all_cores_") + name(t) + "_" + std::to_string(mode) + round_suffix(round),
                              [frame_rows, t, mode](int first, int step, std::size_t) { frame_rows(t, mode, first, step); }, min_time);
        }
    // --- several point lights on one footprint -------------------------------------------------
    // Per pixel: k lights shaded smooth, with glints on one shared footprint (grid_pixel), and
    // with glints through a footprint of their own per light (grid_sample for each), and on one
    // shared footprint's one lattice point.
    static const glint_bench::light_pixels lp;
    for (int round = 0; round < round_count; ++round) {
        for (int k : {1, 8, 16})
            for (int mode = 0; mode < 5; ++mode)
                add_inline("lights_" + std::to_string(mode) + "_" + std::to_string(k) + round_suffix(round), [k, mode](std::size_t j) {
                    benchmark::DoNotOptimize(glint_bench::shade_light_pixel(lp, static_cast<int>(j % glint_bench::light_pixels::pixels), k, mode));
                }, min_time);
        // The extra light timed in pairs: each call shades one block of 32 pixels four ways back to
        // back (smooth and glints on one footprint with the list of lights, 8 and 16 lights each,
        // the order rotating from call to call) and adds each way's time to its sum, so that the
        // machine's slow phases, which last seconds, fall on the four alike; the separately timed
        // benchmarks above can each meet a different phase (the same code gave 1.77x and 2.06x for
        // lights 9 to 16 in two runs of the twenty-fourth session).
        add_inline("lights_paired" + round_suffix(round), [](std::size_t j) {
            constexpr int block = 32;
            const int first = static_cast<int>(j % (glint_bench::light_pixels::pixels / block)) * block;
            for (int w = 0; w < 4; ++w) {
                const int way = static_cast<int>((j + static_cast<std::size_t>(w)) % 4), mode = way / 2, k = (way % 2) ? 16 : 8;
                const auto t0 = std::chrono::steady_clock::now();
                for (int i = first; i < first + block; ++i) benchmark::DoNotOptimize(glint_bench::shade_light_pixel(lp, i, k, mode));
                paired_lights_ns()[way] += std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
            }
            paired_lights_pixels() += block;
        }, min_time);
    }
    const auto ns = run_all();

    md << "## Glint NDF on the grid, lights (glint/grid.hpp, glint/microfacet.hpp)\n\n";
    doc << "# Microfacet integrals and the glint NDF: accuracy and cost\n\n"
        << "Generated by `build/release/bench/glint_report --docs docs` (`scripts/demo --docs`); one run, one machine.\n\n";
    std::ostringstream t1;
    t1 << "D_Omega (KK25 Eq. 9) by glint's boundary integral in float, against nested adaptive Gauss-Kronrod over the light in "
          "double, over "
       << cases.size() << " lights (cones from the sun's 0.26 degrees to 23 degrees, rectangles, GGX and Beckmann, roughness "
                          "0.002 to 0.5, views to 80 degrees):\n\n"
       << "| pieces per edge | worst relative error (double) | worst relative error (float) | ns per call (float) |\n|---|---|---|---|\n";
    for (int pieces : piece_knobs) {
        double worst = 0, worst_f = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            if (refs[i] < 1e-30) continue;
            const double floor = 1e-9 * glint::total_area(cases[i].d, cases[i].alpha);
            worst = std::max(worst, std::fabs(glint_test::d_omega<double>(cases[i], pieces) - refs[i]) / std::max(refs[i], floor));
            worst_f = std::max(worst_f, std::fabs(static_cast<double>(glint_test::d_omega<float>(cases[i], pieces)) - refs[i]) / std::max(refs[i], floor));
        }
        const double t = ns.at("d_omega_" + std::to_string(pieces));
        t1 << "| " << pieces << (pieces == 8 ? " (default)" : "") << " | " << fmt(worst) << " | " << fmt(worst_f) << " | " << fmt(t, "%.0f") << " |\n";
        csv << "d_omega,pieces=" << pieces << ",float,worst relative error over " << cases.size() << " lights," << worst_f << "," << t << ",,adaptive quadrature\n";
    }
    t1 << "\n";
    std::ostringstream t2;
    t2 << "The glint estimate R / E[R] (one footprint, one light; sun and point light, alpha 0.25, ln density 3): time per "
          "estimate, and the largest |mean - 1| over point, sphere (0.1 rad) and rectangle lights at ln densities 0, 2, 4 with a "
          "footprint of 3 x 3 uv units, alpha 0.25 (6000 seeds each; the mean must be 1):\n\n"
       << "| binomial variant | ns per estimate, sun | ns per estimate, point | largest mean bias (standard error) | where |\n|---|---|---|---|---|\n";
    for (int v = 0; v <= 4; ++v) {
        const auto var = static_cast<glint::binomial_variant>(v);
        const double ts = ns.at("grid_" + std::string(glint::name(var)) + "_sun"), tp = ns.at("grid_" + std::string(glint::name(var)) + "_point");
        const auto b = grid_bias(var);
        t2 << "| " << glint::name(var) << (v == 4 ? " (default)" : "") << " | " << fmt(ts, "%.0f") << " | " << fmt(tp, "%.0f") << " | "
           << fmt(b.worst) << " (" << fmt(b.se, "%.2g") << ") | " << b.where << " |\n";
        csv << "grid," << glint::name(var) << ",float,largest |mean R/E[R] - 1| (6000 seeds),"
            << b.worst << "," << ts << ",,smooth BRDF\n";
    }
    t2 << "\n";
    std::ostringstream t4;
    t4 << "The slope-grid cell (grid_params::slope_cell, in absolute slope units) sets how many microfacet orientations a "
          "point light's half vector sees: each glint lives over a cell of half-vector slopes, so larger cells make more, dimmer "
          "glints that last longer as the light or the eye moves, and smaller cells fewer, brighter, briefer ones. The mean stays "
          "the smooth BRDF at every cell. Point light, alpha 0.25, ln density 6, footprint 3 x 3 uv units (N = "
       << fmt(std::exp(6.0) * 9.0, "%.0f") << " microfacets), 6000 seeds per cell:\n\n"
       << "| slope cell | ns per estimate | reflecting microfacets per footprint, N E[R] | footprints with a glint | sd of R / E[R] | "
          "\\|mean - 1\\| (standard error) |\n|---|---|---|---|---|---|\n";
    for (float cell : slope_cells) {
        const glint_test::grid_scene sc = slope_cell_scene(cell);
        const auto st = grid_statistics(sc, 6000);
        const double tc = ns.at("grid_slope_" + std::to_string(cell));
        t4 << "| " << fmt(cell, "%g") << (cell == glint::grid_params<float>{}.slope_cell ? " (default)" : "") << " | " << fmt(tc, "%.0f")
           << " | " << fmt(sc.expected_glints(), "%.3g") << " | " << fmt(100 * st.lit, "%.1f") << "% | " << fmt(st.sd, "%.3g") << " | "
           << fmt(std::fabs(st.mean - 1), "%.2g") << " (" << fmt(st.se, "%.2g") << ") |\n";
        csv << "grid,slope cell " << cell << " (point light),float,|mean R/E[R] - 1| (6000 seeds)," << std::fabs(st.mean - 1) << "," << tc
            << ",,smooth BRDF\n";
    }
    t4 << "\n";
    std::ostringstream t6;
    {
        const int n = 40000;
        t6 << "R / E[R] with each footprint's glints on one of its four lattice points, drawn with probability w_L (grid_pixel_setup with a "
              "lattice_u), against all four (the default): GGX alpha 0.25, footprints at 30 degrees, " << n << " footprints per column at "
              "random positions and seeds, the two columns' samples independent. The mean must be 1 in both; the per-pixel variance is the "
              "same in theory wherever the draws' variance is linear in the vertices' microfacet count (binomial); the ratio's standard "
              "error is from each sample variance's own, (m4 - var^2) / n.\n\n"
           << "| light | ln density | footprint, ratio | N E[R] | mean, four | mean, one | sd, four | sd, one | variance ratio one / four (se) |\n"
              "|---|---|---|---|---|---|---|---|---|\n";
        for (glint_test::light_kind k : {glint_test::light_kind::point, glint_test::light_kind::sun})
            for (float logd : {2.0f, 4.0f, 6.0f})
                for (float fp : {3.0f, 30.0f}) {
                    glint_test::grid_scene sc;
                    sc.kind = k, sc.alpha = 0.25f, sc.log_density = logd, sc.footprint = fp, sc.ratio = fp > 10 ? 5.7f : 1.0f;
                    sc.prepare();
                    const auto four = grid_statistics(sc, n), one = grid_statistics(sc, n, true, 1);
                    const double v4 = four.sd * four.sd, v1 = one.sd * one.sd, r = v4 > 0 ? v1 / v4 : 0;
                    const double rse = (v4 > 0 && v1 > 0) ? r * std::sqrt(std::pow(four.variance_se / v4, 2) + std::pow(one.variance_se / v1, 2)) : 0;
                    t6 << "| " << glint_test::name(k) << " | " << fmt(logd, "%g") << " | " << fmt(fp, "%g") << ", " << fmt(sc.ratio, "%g") << " | "
                       << fmt(sc.expected_glints(), "%.3g") << " | " << fmt(four.mean, "%.4f") << " | " << fmt(one.mean, "%.4f") << " | "
                       << fmt(four.sd, "%.3g") << " | " << fmt(one.sd, "%.3g") << " | " << fmt(r, "%.3f") << " (" << fmt(rse, "%.3f") << ") |\n";
                }
        t6 << "\n";
    }
    std::ostringstream t3;
    t3 << "Frame cost of the showcase scene (examples/lights_scene.hpp, " << fw << "x" << fh
       << ", one thread; each frame the least time of " << round_count
       << " rounds, the frames interleaved): glint shading against smooth shading of the same scene, ln density 5 (the showcase). Each row is "
          "shaded by render_row, which batches the glint estimates of up to 32 pixels per surface through glint::grid_sample_pixels "
          "(eight pixels a pass in AVX2 lanes; the same values as one pixel at a time, render_pixel). \"Glints\" uses the "
          "smooth-result gate (smooth_tolerance 0.01: footprints whose estimate's relative standard deviation is surely below 1% "
          "return the smooth result without drawing); \"all sampled\" turns the gate off; \"off\" switches glints off. At ln "
          "density 14 most footprints hold enough microfacets for the gate: the last columns show the time it saves. \"One lattice "
          "point\" draws one of the footprint's four lattice points per pixel with probability w_L (scene_options::stochastic_lattice, "
          "glint::grid_pixel_setup with a lattice_u): the same mean and per-pixel variance, 3 vertices instead of up to 12. \"All cores\": the smooth "
          "and the glint frame on "
       << all_cores() << " threads at once, thread t shading rows t, t + " << all_cores()
       << ", ..., the wall time of a frame (bench/report.hpp, add_all_cores).\n\n"
       << "| light | smooth ms | glints ms | glints / smooth | all cores: smooth ms | all cores: glints ms | all cores: glints / smooth | one lattice point / smooth | all sampled / smooth | off / smooth | density 14: glints / smooth | density 14: all sampled / smooth |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (light_type t : {light_type::point, light_type::sun, light_type::area}) {
        const double s0 = ns.at(std::string("frame_") + name(t) + "_0"), s1 = ns.at(std::string("frame_") + name(t) + "_1"),
                     s2 = ns.at(std::string("frame_") + name(t) + "_2");
        const double s3 = ns.at(std::string("frame_") + name(t) + "_3"), s4 = ns.at(std::string("frame_") + name(t) + "_4"),
                     s5 = ns.at(std::string("frame_") + name(t) + "_5"), s6 = ns.at(std::string("frame_") + name(t) + "_6");
        const double a0 = ns.at(std::string("frame_all_cores_") + name(t) + "_0"), a1 = ns.at(std::string("frame_all_cores_") + name(t) + "_1");
        t3 << "| " << name(t) << " | " << fmt(s0 * 1e-6) << " | " << fmt(s1 * 1e-6) << " | " << fmt(s1 / s0) << " | " << fmt(a0 * 1e-6) << " | "
           << fmt(a1 * 1e-6) << " | " << fmt(a1 / a0) << " | " << fmt(s6 / s0) << " | " << fmt(s2 / s0) << " | "
           << fmt(s3 / s0) << " | " << fmt(s4 / s0) << " | " << fmt(s5 / s0) << " |\n";
        csv << "frame," << name(t) << " light glints/smooth,float,ratio," << s1 / s0 << "," << s1 << "," << s1 / s0 << ",smooth frame\n";
        csv << "frame," << name(t) << " light glints on one lattice point/smooth,float,ratio," << s6 / s0 << "," << s6 << "," << s6 / s0 << ",smooth frame\n";
        csv << "frame," << name(t) << " light glints/smooth all cores (" << all_cores() << " threads),float,ratio," << a1 / a0 << "," << a1 << "," << a1 / a0
            << ",smooth frame on all cores\n";
    }
    t3 << "\n";
    std::ostringstream t5;
    {
        auto at = [&](int mode, int k) { return ns.at("lights_" + std::to_string(mode) + "_" + std::to_string(k)); };
        // Each extra light two ways: lights 2 to 8, (t(8) - t(1)) / 7, and lights 9 to 16, (t(16) -
        // t(8)) / 8. A list of lights shares a pass among up to eight (grid_sample_lights), whose
        // cost is nearly the same for one lane as for eight: the first measure leaves most of it in
        // t(1); the second holds a whole pass, the conservative figure, which the CSV states.
        auto second = [&](int mode) { return (at(mode, 16) - at(mode, 8)) / 8; };
        auto first = [&](int mode) { return (at(mode, 8) - at(mode, 1)) / 7; };
        t5 << "Several point lights on glinty pixels (1024 pixels of the showcase's flake paint: GGX, alpha 0.25, ln density 5, footprints "
              "of 0.4 to 0.8 uv units, N about 20 to 80; one thread; each light's smooth specular is GGX D, Smith G2 and silver's "
              "conductor Fresnel; each time the least of "
           << round_count
           << " rounds, interleaved). The cost of each extra light two ways: lights 2 to 8, (t(8 lights) - t(1 light)) / 7, and lights "
              "9 to 16, (t(16) - t(8)) / 8. A list of lights (glint::grid_sample_lights) shares one pass among up to eight lights, a "
              "light a vector lane where the CPU has AVX2, and a pass costs nearly the same for one lane as for eight: lights 9 to 16 "
              "hold a whole pass, the conservative figure.\n\n"
           << "| shading | 1 light ns | 8 lights ns | 16 lights ns | each of lights 2 to 8, ns | / its smooth cost | each of lights 9 to 16, ns | "
              "/ its smooth cost |\n|---|---|---|---|---|---|---|---|\n";
        const char* names[5] = {"smooth", "glints, one footprint, the list of lights (grid_pixel, grid_sample_lights)",
                                "glints, a footprint per light (grid_sample each)",
                                "glints, one footprint on one lattice point, the list of lights (grid_pixel_setup with a lattice_u)",
                                "glints, one footprint, one light at a time (grid_sample(px, ...) each)"};
        for (int mode : {0, 1, 4, 3, 2})
            t5 << "| " << names[mode] << " | " << fmt(at(mode, 1)) << " | " << fmt(at(mode, 8)) << " | " << fmt(at(mode, 16)) << " | "
               << fmt(first(mode)) << " | " << fmt(first(mode) / first(0)) << " | " << fmt(second(mode)) << " | " << fmt(second(mode) / second(0))
               << " |\n";
        t5 << "\n";
        // The paired benchmark's sums: lights 9 to 16 per light and pixel, smooth and glints.
        const double* pn = paired_lights_ns();
        const double pixels = paired_lights_pixels(), paired_smooth = (pn[1] - pn[0]) / (8 * pixels), paired_glints = (pn[3] - pn[2]) / (8 * pixels);
        t5 << "Timed in pairs (the four ways back to back on each block of 32 pixels, over " << fmt(pixels, "%.3g")
           << " pixels each, every round's calls summed): each of lights 9 to 16 costs " << fmt(paired_smooth) << " ns smooth and "
           << fmt(paired_glints) << " ns with glints through the list of lights, **" << fmt(paired_glints / paired_smooth)
           << "x** its smooth cost; with 8 lights a pixel " << fmt(pn[0] / pixels) << " ns smooth and " << fmt(pn[2] / pixels)
           << " ns with glints. The slow phases of a shared machine fall alike on the four ways of a block, so this is the figure to read "
              "against the target; the table's separately timed benchmarks each take the least of their own rounds.\n\n";
        csv << "lights,extra point light glints/smooth (lights 9 to 16 timed in pairs),float,ratio," << paired_glints / paired_smooth << ","
            << paired_glints << "," << paired_glints / paired_smooth << ",smooth extra light\n";
        csv << "lights,extra point light glints/smooth (lights 9 to 16),float,ratio," << second(1) / second(0) << "," << second(1) << ","
            << second(1) / second(0) << ",smooth extra light\n";
        csv << "lights,extra point light glints/smooth (lights 2 to 8),float,ratio," << first(1) / first(0) << "," << first(1) << ","
            << first(1) / first(0) << ",smooth extra light\n";
        csv << "lights,extra point light glints one at a time/smooth (lights 9 to 16),float,ratio," << second(4) / second(0) << "," << second(4)
            << "," << second(4) / second(0) << ",smooth extra light\n";
        csv << "lights,extra point light glints on one lattice point/smooth (lights 9 to 16),float,ratio," << second(3) / second(0) << ","
            << second(3) << "," << second(3) / second(0) << ",smooth extra light\n";
    }
    md << t1.str() << t2.str() << t4.str() << t6.str() << t3.str() << t5.str();
    doc << "## D_Omega\n\n" << t1.str() << "## Grid estimate\n\n" << t2.str() << "## Slope-grid resolution\n\n" << t4.str()
        << "## One lattice point per pixel\n\n" << t6.str() << "## Frame cost\n\n" << t3.str() << "## Several lights on one footprint\n\n" << t5.str();
    out.markdown = md.str();
    out.csv_rows = csv.str();
    out.files["grid.md"] = doc.str();
    return out;
}

}  // namespace glint_report
