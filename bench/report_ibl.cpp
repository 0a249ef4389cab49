// The IBL section of the accuracy-versus-time report: prefiltering time for a 1024 x 512 map,
// the E_D table against its exact value, the glint estimate's time for K = 4 and 8 and linear
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
    // E_D table against the exact integral (glint::integrated_ndf_cone, 32 pieces) off the grid.
    double worst_ed = 0;
    for (int i = 0; i < 50; ++i)
        for (int j = 0; j < 50; ++j) {
            const double c = 0.02 + 0.96 * i / 49.0, sa = 0.05 + 0.95 * j / 49.0;
            const glm::dvec3 wo(std::sqrt(1 - c * c), 0, c);
            const double exact = glint::integrated_ndf_cone(glint::ndf::ggx, wo, glm::dvec2(sa * sa), glm::dvec3(0, 0, 1), 0.5 * M_PI, 32);
            worst_ed = std::max(worst_ed, std::fabs(static_cast<double>(envs[0]->visible_area(static_cast<float>(c), static_cast<float>(sa))) - exact) / exact);
        }
    // Shading: per pixel of a 160 x 100 view of the sphere, smooth against glints.
    const char* labels[] = {"K=4 linear", "K=4 log", "K=8 linear", "K=8 log"};
    for (std::size_t e = 0; e < envs.size(); ++e)
        for (int mode = 0; mode < 2; ++mode) {
            const glint::environment* env = envs[e].get();
            add("ibl_" + std::to_string(e) + "_" + std::to_string(mode), [env, mode](std::size_t it) {
                float acc = 0;
                const float sa = 0.35f, alpha = sa * sa, dh = env->total_area(alpha);
                for (int y = 0; y < 100; ++y)
                    for (int x = 0; x < 160; ++x) {
                        // A sphere seen from afar: normal from the pixel, view along -z.
                        const float px = (static_cast<float>(x) - 80) / 50, py = (50 - static_cast<float>(y)) / 50, rr = px * px + py * py;
                        if (rr >= 1) continue;
                        const glm::vec3 n(px, py, std::sqrt(1 - rr)), d(0, 0, -1);
                        const float cos_o = n.z;
                        const auto s = env->lookup(glm::reflect(d, n), sa);
                        float m = 1;
                        if (mode == 1) {
                            glint::grid_params<float> g;
                            g.log_density = 4.0f;
                            g.seed = static_cast<std::uint32_t>(it);
                            const auto est = glint::ibl_sample(glm::vec2(static_cast<float>(x), static_cast<float>(y)), glm::vec2(1, 0), glm::vec2(0, 1), g,
                                                               env->levels(), s.indicators, env->visible_area(cos_o, sa), dh);
                            m = glint::modulation(est);
                        }
                        acc += env->albedo(cos_o, sa) * s.radiance.x * m;
                    }
                benchmark::DoNotOptimize(acc);
            }, min_time * 4);
        }
    const auto ns = run_all();
    md << "## Image-based lighting of glints (glint/ibl.hpp)\n\n";
    std::ostringstream t;
    t << "Environment `sunset.exr` (" << img.width << " x " << img.height << "), 6 roughness levels, 64 GGX samples per texel, "
      << "one thread. Shading: a sphere in a 160 x 100 view (about 12600 pixels), smooth split-sum IBL against glints (ln density "
         "4), one run:\n\n"
      << "| knob | prefilter s | smooth us/frame | glints us/frame | glints / smooth |\n|---|---|---|---|---|\n";
    for (std::size_t e = 0; e < envs.size(); ++e) {
        const double s0 = ns.at("ibl_" + std::to_string(e) + "_0"), s1 = ns.at("ibl_" + std::to_string(e) + "_1");
        t << "| " << labels[e] << " | " << fmt(build_s[e]) << " | " << fmt(s0 * 1e-3, "%.0f") << " | " << fmt(s1 * 1e-3, "%.0f") << " | " << fmt(s1 / s0) << " |\n";
        csv << "ibl," << labels[e] << ",float,glints/smooth frame time," << s1 / s0 << "," << s1 << "," << s1 / s0 << ",smooth IBL frame\n";
    }
    t << "\nE_D table (" << envs[0]->table_size() << " x " << envs[0]->table_size()
      << ", bilinear) against the exact visible reflecting area (glint::integrated_ndf_cone over the hemisphere): worst relative error "
      << fmt(worst_ed) << " over cos theta_o in [0.02, 0.98], sqrt(alpha) in [0.05, 1].\n\n";
    csv << "ibl,E_D table " << envs[0]->table_size() << "x" << envs[0]->table_size() << ",float,worst relative error," << worst_ed << ",,,exact integral\n";
    md << t.str();
    out.markdown = md.str();
    out.csv_rows = csv.str();
    out.files["ibl.md"] = "# Image-based lighting of glints: cost and accuracy\n\nGenerated by `build/release/bench/glint_report --docs docs` "
                          "(`scripts/demo --docs`); one run, one machine.\n\n" +
                          t.str();
    return out;
}

}  // namespace glint_report
