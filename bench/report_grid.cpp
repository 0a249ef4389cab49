// The grid-NDF section of the accuracy-versus-time report: D_Omega's quadrature knob (pieces per
// edge) against 2D adaptive quadrature, the glint estimate per binomial variant and slope-grid
// cell (bias of the mean over grid seeds, time per estimate), and the cost of a frame of the
// showcase scene with glints against the smooth BRDF, per light, in one run.
// Writes docs/grid.md.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glint/grid.hpp>
#include <glint/microfacet.hpp>

#include "../examples/lights_scene.hpp"
#include "../tests/support/grid_scene.hpp"
#include "../tests/support/microfacet_reference.hpp"
#include "report.hpp"

namespace glint_report {

namespace {

struct light_case {
    bool cone;
    glint::ndf d;
    glm::dvec2 alpha;
    glm::dvec3 wo, axis, p0, e1, e2;
    double radius;
};

// A subset of the unit test's lights: both NDFs, sharp to rough, normal to grazing views, the
// sun, 3- and 23-degree cones, small to large rectangles, at and near the mirror direction.
std::vector<light_case> light_cases() {
    std::vector<light_case> out;
    for (glint::ndf d : {glint::ndf::ggx, glint::ndf::beckmann})
        for (glm::dvec2 a : {glm::dvec2(2e-3), glm::dvec2(0.02, 0.08), glm::dvec2(0.2), glm::dvec2(0.5, 0.25)})
            for (double theta_o : {0.0, 0.8, 1.4}) {
                const glm::dvec3 wo(std::sin(theta_o), 0, std::cos(theta_o)), r(-wo.x, -wo.y, wo.z);
                const glm::dvec3 side = glm::normalize(glm::cross(r, glm::dvec3(0.3, 1, 0.2)));
                for (double radius : {0.00454, 0.05, 0.4})
                    for (double off : {0.0, 0.5, 1.5}) {
                        const glm::dvec3 c = std::cos(off * radius) * r + std::sin(off * radius) * side;
                        out.push_back({true, d, a, wo, c, {}, {}, {}, radius});
                    }
                for (double size : {0.05, 0.5, 3.0})
                    for (double off : {0.0, 0.5, 1.5}) {
                        const glm::dvec3 c = std::cos(off * size / 2) * r + std::sin(off * size / 2) * side;
                        glm::dvec3 e1 = glm::normalize(glm::cross(c, glm::dvec3(0, 0.2, 1))) * size;
                        glm::dvec3 e2 = glm::normalize(glm::cross(e1, c)) * size * 0.6;
                        if (glm::dot(glm::cross(e1, e2), c) > 0) std::swap(e1, e2);
                        out.push_back({false, d, a, wo, {}, c * 2.0 - 0.5 * e1 - 0.5 * e2, e1, e2, 0});
                    }
            }
    return out;
}

float d_omega_float(const light_case& c, int pieces) {
    return c.cone ? glint::integrated_ndf_cone<float>(c.d, glm::vec3(c.wo), glm::vec2(c.alpha), glm::vec3(c.axis), static_cast<float>(c.radius), pieces)
                  : glint::integrated_ndf_rect<float>(c.d, glm::vec3(c.wo), glm::vec2(c.alpha), glm::vec3(c.p0), glm::vec3(c.e1), glm::vec3(c.e2), pieces);
}

double d_omega_double(const light_case& c, int pieces) {
    return c.cone ? glint::integrated_ndf_cone(c.d, c.wo, c.alpha, c.axis, c.radius, pieces)
                  : glint::integrated_ndf_rect(c.d, c.wo, c.alpha, c.p0, c.e1, c.e2, pieces);
}

// Mean of R / E[R] over seeds for a few scenes; returns the largest |mean - 1| and its standard
// error.
struct bias_result {
    double worst = 0, se = 0;
    std::string where;
};

bias_result grid_bias(glint::binomial_variant v, float slope_cell) {
    bias_result out;
    for (glint_test::light_kind k : {glint_test::light_kind::point, glint_test::light_kind::sphere, glint_test::light_kind::rect})
        for (float logd : {0.0f, 2.0f, 4.0f}) {
            glint_test::grid_scene s;
            s.kind = k, s.alpha = 0.25f, s.log_density = logd, s.footprint = 3.0f, s.variant = v;
            s.prepare();
            glm::vec2 dx, dy;
            s.derivatives(dx, dy);
            double sum = 0, sq = 0;
            const int n = 6000;
            for (int i = 0; i < n; ++i) {
                auto g = s.params(static_cast<std::uint32_t>(i) * 2654435761u + 17u);
                g.slope_cell = slope_cell;
                const glm::uvec3 h = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 9u, 9u));
                const glm::vec2 uv(glint::unit_from_bits<float>(h.x) * 97.0f, glint::unit_from_bits<float>(h.y) * 89.0f);
                const double m = static_cast<double>(glint::modulation(glint::grid_sample(uv, dx, dy, g, s.light)));
                sum += m, sq += m * m;
            }
            const double mean = sum / n, se = std::sqrt(std::max(0.0, sq / n - mean * mean) / n);
            if (std::fabs(mean - 1) > out.worst) out.worst = std::fabs(mean - 1), out.se = se, out.where = s.describe();
        }
    return out;
}

}  // namespace

section grid_section(double min_time) {
    section out;
    std::ostringstream md, csv, doc;
    // --- D_Omega pieces -------------------------------------------------------------------
    const auto cases = light_cases();
    std::vector<double> refs;
    for (const auto& c : cases)
        refs.push_back(c.cone ? glint_test::reference_cone(c.d, c.wo, c.alpha, c.axis, c.radius)
                              : glint_test::reference_rect(c.d, c.wo, c.alpha, c.p0, c.e1, c.e2));
    const int piece_knobs[] = {4, 6, 8, 12, 16, 32};
    for (int pieces : piece_knobs) {
        add("d_omega_" + std::to_string(pieces), [&cases, pieces](std::size_t i) {
            benchmark::DoNotOptimize(d_omega_float(cases[i % cases.size()], pieces));
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
            add("grid_" + std::string(glint::name(sc.variant)) + "_" + glint_test::name(sc.kind), [sc](std::size_t i) {
                const glm::vec2 uv(static_cast<float>(i % 997) * 0.37f, static_cast<float>(i % 991) * 0.29f);
                benchmark::DoNotOptimize(sc.estimate(static_cast<std::uint32_t>(i), uv).value);
            }, min_time);
        }
    // --- frames ---------------------------------------------------------------------------
    using namespace glint_examples;
    const int fw = 160, fh = 100;
    const camera cam(fw, fh);
    // Modes: 0 smooth; 1 glints; 2 glints, every footprint sampled; 3 glints switched off (the
    // renderer's smooth path through its glint switch); 4 and 5: glints at ln density 14 with
    // and without the smooth-result gate (where most footprints hold enough microfacets).
    for (light_type t : {light_type::point, light_type::sun, light_type::area})
        for (int mode = 0; mode < 6; ++mode) {
            add(std::string("frame_") + name(t) + "_" + std::to_string(mode), [t, mode, &cam, fw, fh](std::size_t) {
                scene_options opt;
                opt.smooth = mode == 0 || mode == 3;
                opt.smooth_tolerance = (mode == 2 || mode == 5) ? 0.0f : 0.01f;
                if (mode >= 4) opt.log_density = 14.0f;
                light_setup ls;
                ls.type = t;
                shading_counters c;
                float acc = 0;
                for (int y = 0; y < fh; ++y)
                    for (int x = 0; x < fw; ++x) acc += render_pixel(opt, ls, cam, x, y, c).x;
                benchmark::DoNotOptimize(acc);
            }, min_time * 4);
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
            worst = std::max(worst, std::fabs(d_omega_double(cases[i], pieces) - refs[i]) / std::max(refs[i], floor));
            worst_f = std::max(worst_f, std::fabs(static_cast<double>(d_omega_float(cases[i], pieces)) - refs[i]) / std::max(refs[i], floor));
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
        const auto b = grid_bias(var, 0.02f);
        t2 << "| " << glint::name(var) << (v == 4 ? " (default)" : "") << " | " << fmt(ts, "%.0f") << " | " << fmt(tp, "%.0f") << " | "
           << fmt(b.worst) << " (" << fmt(b.se, "%.2g") << ") | " << b.where << " |\n";
        csv << "grid," << glint::name(var) << ",float,largest |mean R/E[R] - 1| (6000 seeds),"
            << b.worst << "," << ts << ",,smooth BRDF\n";
    }
    t2 << "\n";
    std::ostringstream t3;
    t3 << "Frame cost of the showcase scene (examples/lights_scene.hpp, " << fw << "x" << fh
       << ", one thread): glint shading against smooth shading of the same scene, ln density 5 (the showcase). \"Glints\" uses the "
          "smooth-result gate (smooth_tolerance 0.01: footprints whose estimate's relative standard deviation is surely below 1% "
          "return the smooth result without drawing); \"all sampled\" turns the gate off; \"off\" switches glints off. At ln "
          "density 14 most footprints hold enough microfacets for the gate: the last columns show the time it saves.\n\n"
       << "| light | smooth ms | glints ms | glints / smooth | all sampled / smooth | off / smooth | density 14: glints / smooth | density 14: all sampled / smooth |\n|---|---|---|---|---|---|---|---|\n";
    for (light_type t : {light_type::point, light_type::sun, light_type::area}) {
        const double s0 = ns.at(std::string("frame_") + name(t) + "_0"), s1 = ns.at(std::string("frame_") + name(t) + "_1"),
                     s2 = ns.at(std::string("frame_") + name(t) + "_2");
        const double s3 = ns.at(std::string("frame_") + name(t) + "_3"), s4 = ns.at(std::string("frame_") + name(t) + "_4"),
                     s5 = ns.at(std::string("frame_") + name(t) + "_5");
        t3 << "| " << name(t) << " | " << fmt(s0 * 1e-6) << " | " << fmt(s1 * 1e-6) << " | " << fmt(s1 / s0) << " | " << fmt(s2 / s0) << " | "
           << fmt(s3 / s0) << " | " << fmt(s4 / s0) << " | " << fmt(s5 / s0) << " |\n";
        csv << "frame," << name(t) << " light glints/smooth,float,ratio," << s1 / s0 << "," << s1 << "," << s1 / s0 << ",smooth frame\n";
    }
    t3 << "\n";
    md << t1.str() << t2.str() << t3.str();
    doc << "## D_Omega\n\n" << t1.str() << "## Grid estimate\n\n" << t2.str() << "## Frame cost\n\n" << t3.str();
    out.markdown = md.str();
    out.csv_rows = csv.str();
    out.files["grid.md"] = doc.str();
    return out;
}

}  // namespace glint_report
