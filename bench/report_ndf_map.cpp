// The NDF-map section of the accuracy-versus-time report (glint/ndf_map.hpp, XTXW24): build time,
// the map's L1 against the direct P-NDF of the same tiled layout at every footprint size (glint's
// first-order tiles and the published zero-order ones), the bins' own error, speed against the
// direct P-NDF with its hierarchy, tiles and texture fetches per evaluation, memory against a
// full-resolution 4096^2 element hierarchy, continuity, the LOD knobs, and the stochastic
// layout. Writes docs/ndf_map.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glint/ndf_map.hpp>
#include <glint/patterns.hpp>

#include "../tests/support/ndf_map_support.hpp"
#include "../tests/support/pndf_support.hpp"
#include "report.hpp"

namespace glint_report {

namespace {

using map_t = glint::ndf_map<float>;
using placement = glint::ndf_placement<float>;

float unit(std::uint32_t i, std::uint32_t s) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, s, 0x7d3u)).x); }

glint::texel_footprint<float> fp_at(glm::vec2 c, float a, float b, float t) { return glint_test::rotated_footprint(c, a, b, t); }

using query = glint_test::pndf_query;
std::vector<query> queries(const glint::pattern_params& p, float sd, int n) { return glint_test::pndf_queries(p, sd, n, 8.0f, 0x7d3u); }

glint::ndf_map_params params(double sigma_r, int res) {
    glint::ndf_map_params mp;
    mp.sigma_r = sigma_r, mp.resolution = res;
    return mp;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The example repeated over side x side texels (the full-resolution surface of a tiled layout).
glint::normal_map tiled_surface(const glint::normal_map& ex, int side) {
    std::vector<glm::vec3> n(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) n[static_cast<std::size_t>(x) + static_cast<std::size_t>(side) * static_cast<std::size_t>(y)] = ex.texel(x, y);
    return glint::normal_map(side, side, std::move(n));
}

}  // namespace

section ndf_map_section(double min_time) {
    section out;
    std::ostringstream md;
    const int n = 32;
    md << "## Tiny-example NDF maps (glint/ndf_map.hpp, XTXW24)\n\n"
          "CPU, one thread, float. Examples: " << n << " x " << n << " periodic patterns (`brushed`, `noise`, `flakes`, `scratches`, `leather`; "
          "tests/support/ndf_map_support.hpp), one element per texel, tiled without a transform unless stated. The direct P-NDF of the "
          "same layout is the example's own periodic P-NDF (glint::gaussian_pndf: the same elements and culling), with its hierarchy.\n\n";

    // Build time at the size: 32^2, S = 128, the default sigma_r.
    md << "### Build\n\n`ndf_map<float>::build` on one thread, 32 x 32 example, S = 128 bins per side, sigma_r = 0.005 (the defaults; "
          "XTXW24 Table 2: 2.3 to 72 s):\n\n| example | build (s) | sub-samples per bin side | window side (s units) | images (MB) |\n|---|---|---|---|---|\n";
    for (const auto kind : glint_test::example_kinds) {
        const auto ex = glint::make_normal_map(glint_test::example_pattern(kind, n));
        const auto m = map_t::build(ex, glint::ndf_map_params{});
        md << "| " << glint::pattern_name(kind) << " | " << fmt(m.build_seconds(), "%.2f") << " | " << m.supersample() << " | "
           << fmt(m.bin_width() * m.resolution(), "%.3f") << " | " << fmt(static_cast<double>(m.image_bytes()) / 1e6, "%.1f") << " |\n";
        out.csv_rows += "ndf_map,build " + std::string(glint::pattern_name(kind)) + " 32^2 S=128,float,build seconds," + fmt(m.build_seconds()) + ",,,\n";
    }

    // Accuracy against the direct P-NDF at the map's resolution.
    md << "\n### Accuracy against the direct P-NDF\n\nL1 at the map's resolution (tests/support/ndf_map_support.hpp `binned_l1`): over the "
          "bins of the window, |the map at the bin centre - the direct P-NDF's mean over the bin (3 x 3 sub-samples, spacing under sigma_r / 2)| "
          "over the direct P-NDF's sum. It measures the tiles, their weights and levels, not the bins' width (next table). S = 64, "
          "sigma_r = 0.02, tau = 1, max_tiles = 256 (defaults); footprint sd (minor 0.7 of it, rotated 0.4 rad) in texels; glint (first-order tiles) / XTXW24's "
          "zero-order tiles (Eq. 7 alone). Below 2 texels the element path is exact by construction.\n\n| example |";
    const std::vector<float> sds = {1, 2, 4, 8, 16, 64, 512};
    for (const float sd : sds) md << " sd " << sd << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < sds.size(); ++i) md << "---|";
    md << "\n";
    double worst_from_4 = 0;
    for (const auto kind : glint_test::example_kinds) {
        const auto ex = glint::make_normal_map(glint_test::example_pattern(kind, n));
        const auto m = map_t::build(ex, params(0.02, 64));
        glint::gaussian_params<float> g;
        g.sigma_r = 0.02f;
        const auto ref = glint::gaussian_pndf<float>::build(ex, g);
        const auto pl = placement::tiled();
        md << "| " << glint::pattern_name(kind) << " |";
        for (const float sd : sds) {
            const auto fp = fp_at({13.3f, 7.7f}, sd, 0.7f * sd, 0.4f);
            const auto r = [&](glm::vec2 s) { return static_cast<double>(ref.eval(fp, s)); };
            const double first = glint_test::binned_l1(m, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, fp, s)); }, r, 3);
            const double zero = glint_test::binned_l1(m, [&](glm::vec2 s) { return static_cast<double>(m.eval_zero_order(pl, fp, s)); }, r, 3);
            if (sd >= 4) worst_from_4 = std::max(worst_from_4, first);
            md << " " << fmt(first, "%.4f") << " / " << fmt(zero, "%.4f") << " |";
            out.csv_rows += "ndf_map," + std::string(glint::pattern_name(kind)) + " sd=" + fmt(sd) + " first-order,float,L1 vs direct P-NDF (binned)," + fmt(first) + ",,,\n";
            out.csv_rows += "ndf_map," + std::string(glint::pattern_name(kind)) + " sd=" + fmt(sd) + " zero-order,float,L1 vs direct P-NDF (binned)," + fmt(zero) + ",,,\n";
        }
        md << "\n";
    }
    md << "\nLargest L1 from sd 4 texels up: " << fmt(worst_from_4, "%.4f") << " (target 0.05).\n\n";

    // The bins' own error: pointwise L1 of the bilinear image at the top level, against the direct P-NDF.
    md << "The bins' own error: pointwise L1 (a 256^2 grid over the window) between the map and the direct P-NDF at footprint sd 512 "
          "(the top image alone, exact but for its bins), against the bin width over sigma_r:\n\n"
          "| example | sigma_r | S = 32 | S = 64 | S = 128 | S = 256 |\n|---|---|---|---|---|---|\n";
    for (const auto kind : {glint::pattern::noise, glint::pattern::flakes}) {
        const auto ex = glint::make_normal_map(glint_test::example_pattern(kind, n));
        for (const double sr : {0.005, 0.02}) {
            glint::gaussian_params<float> g;
            g.sigma_r = static_cast<float>(sr);
            const auto ref = glint::gaussian_pndf<float>::build(ex, g);
            md << "| " << glint::pattern_name(kind) << " | " << sr << " |";
            for (const int res : {32, 64, 128, 256}) {
                const auto m = map_t::build(ex, params(sr, res));
                const auto fp = fp_at({13.3f, 7.7f}, 512, 400, 0.4f);
                const double l1 = glint_test::grid_l1(
                    m, [&](glm::vec2 s) { return static_cast<double>(m.eval(placement::tiled(), fp, s)); },
                    [&](glm::vec2 s) { return static_cast<double>(ref.eval(fp, s)); }, 256);
                md << " " << fmt(l1, "%.3f") << " (bin " << fmt(m.bin_width() / sr, "%.2f") << " sigma_r) |";
            }
            md << "\n";
        }
    }

    // Speed against the direct P-NDF with its hierarchy.
    md << "\n### Speed against the direct P-NDF with its hierarchy\n\nns per evaluation (32 queries, s near the normal at the footprint's "
          "centre; defaults: S = 128, sigma_r = 0.005), the hierarchy's eval (glint::gaussian_pndf on the same example: the same layout) over "
          "the map's, and the tiles (each a bilinear lookup of 4 RGBA texels) and elements an evaluation reads:\n\n"
          "| example | sd 4 | sd 8 | sd 16 | sd 32 | sd 64 | sd 128 | sd 256 | sd 512 | median speed-up |\n|---|---|---|---|---|---|---|---|---|---|\n";
    const std::vector<float> speed_sds = {4, 8, 16, 32, 64, 128, 256, 512};
    std::vector<double> all_speedups;
    for (const auto kind : glint_test::example_kinds) {
        const auto pp = glint_test::example_pattern(kind, n);
        const auto ex = glint::make_normal_map(pp);
        const auto m = map_t::build(ex, glint::ndf_map_params{});
        glint::gaussian_params<float> g;
        g.sigma_r = 0.005f;
        const auto hier = glint::gaussian_pndf<float>::build(ex, g);
        const auto pl = placement::tiled();
        std::vector<std::vector<query>> qs;
        qs.reserve(speed_sds.size());  // the benchmarks hold references into it
        for (const float sd : speed_sds) {
            qs.push_back(queries(pp, sd, 32));
            const std::string tag = std::string(glint::pattern_name(kind)) + "_" + fmt(sd);
            const auto& q = qs.back();
            add("ndf_map_" + tag, [&m, &pl, &q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(m.eval(pl, x.fp, x.s));
            }, min_time);
            add("ndf_direct_" + tag, [&hier, &q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(hier.eval(x.fp, x.s));
            }, min_time);
        }
        const auto ns = run_all();
        md << "| " << glint::pattern_name(kind) << " |";
        std::vector<double> speedups;
        for (std::size_t k = 0; k < speed_sds.size(); ++k) {
            const std::string tag = std::string(glint::pattern_name(kind)) + "_" + fmt(speed_sds[k]);
            const double a = ns.at("ndf_map_" + tag), b = ns.at("ndf_direct_" + tag);
            const auto cost = m.evaluation_cost(pl, qs[k][0].fp);
            speedups.push_back(b / a);
            all_speedups.push_back(b / a);
            md << " " << fmt(a, "%.0f") << " vs " << fmt(b, "%.0f") << " ns (" << fmt(b / a, "%.1f") << "x; " << cost.tiles << " tiles, "
               << cost.elements << " el.) |";
            out.csv_rows += "ndf_map," + std::string(glint::pattern_name(kind)) + " sd=" + fmt(speed_sds[k]) + ",float,speed-up vs hierarchy," + fmt(b / a) + "," +
                            fmt(a) + "," + fmt(a / b) + ",gaussian_pndf hierarchy\n";
        }
        md << " " << fmt(median(speedups), "%.1f") << "x |\n";
    }
    md << "\nMedian speed-up over all examples and footprints of 4 to 512 texels: " << fmt(median(all_speedups), "%.1f")
       << "x (target 5x; XTXW24 Table 3: 5.1 to 11.5x on a GPU).\n";

    // Memory.
    md << "\n### Memory\n\nThe map (images: 4 floats per bin, B and its two moments and the running mass for sampling; plus the elements) "
          "against the full-resolution element hierarchy of a 4096^2 surface covered by the same tiled layout (bytes per texel of "
          "glint::gaussian_pndf built on a 1024^2 surface of the repeated example, times 4096^2). XTXW24 Table 3 stores one float per bin "
          "(shown) and reports 0.02 to 2.6% of YHMR16's memory.\n\n"
          "| example | map (MB) | one float per bin (MB) | 4096^2 hierarchy (MB) | ratio |\n|---|---|---|---|---|\n";
    for (const auto kind : glint_test::example_kinds) {
        const auto ex = glint::make_normal_map(glint_test::example_pattern(kind, n));
        const auto m = map_t::build(ex, glint::ndf_map_params{});
        glint::gaussian_params<float> g;
        g.sigma_r = 0.005f;
        const auto full = glint::gaussian_pndf<float>::build(tiled_surface(ex, 1024), g);
        const double per_texel = static_cast<double>(full.memory_bytes()) / (1024.0 * 1024.0);
        const double map_mb = static_cast<double>(m.image_bytes() + m.element_bytes()) / 1e6, full_mb = per_texel * 4096.0 * 4096.0 / 1e6;
        md << "| " << glint::pattern_name(kind) << " | " << fmt(map_mb, "%.1f") << " | " << fmt(static_cast<double>(m.image_bytes()) / 4e6, "%.1f") << " | "
           << fmt(full_mb, "%.0f") << " (" << fmt(per_texel, "%.0f") << " B/texel) | " << fmt(100 * map_mb / full_mb, "%.2f") << "% |\n";
        out.csv_rows += "ndf_map," + std::string(glint::pattern_name(kind)) + " memory,float,map / 4096^2 hierarchy," + fmt(map_mb / full_mb) + ",,,\n";
    }

    // Continuity.
    {
        const auto ex = glint::make_normal_map(glint_test::example_pattern(glint::pattern::noise, n));
        const auto m = map_t::build(ex, params(0.01, 64));
        const auto pl = placement::tiled();
        const glm::dvec2 worst = glint_test::largest_growth_step(m, pl, {9.3f, 20.6f}, 0.7f, 0.3f, 0.5f, 600, 32);
        const double move = glint_test::largest_move_step(m, pl, 5, 6, 34, 11.2f, 32);
        md << "\n### Continuity\n\nNoise example, S = 64: the largest pointwise L1 between a footprint and the same grown by 1%, over sd 0.5 to 600 "
              "texels (every level and path switch on the way): "
           << fmt(worst.x, "%.4f") << " (at sd " << fmt(worst.y, "%.2f") << "; target 0.02). Moving a footprint of sd 5 by 1/32 texel across tile seams "
           << "and the example's seam: at most " << fmt(move, "%.5f") << ".\n";
    }

    // Knobs: tau and the tile cap.
    md << "\n### Level of detail: tau and the tile cap\n\nFlakes example, S = 64, sigma_r = 0.02: L1 (binned, as above) at sd 4 and 8, ns per "
          "evaluation at sd 8 (32 queries):\n\n| tau | max_tiles | L1 sd 4 | L1 sd 8 | tiles at sd 8 | ns at sd 8 |\n|---|---|---|---|---|---|\n";
    {
        const auto pp = glint_test::example_pattern(glint::pattern::flakes, n);
        const auto ex = glint::make_normal_map(pp);
        glint::gaussian_params<float> g;
        g.sigma_r = 0.02f;
        const auto ref = glint::gaussian_pndf<float>::build(ex, g);
        const auto q = queries(pp, 8, 32);
        for (const double tau : {0.5, 1.0, 2.0})
            for (const int cap : {16, 64, 256}) {
                if (tau != 1.0 && cap != 256) continue;
                auto mp = params(0.02, 64);
                mp.tau = tau, mp.max_tiles = cap;
                const auto m = map_t::build(ex, mp);
                const auto pl = placement::tiled();
                double l1[2];
                for (int k = 0; k < 2; ++k) {
                    const auto fp = fp_at({13.3f, 7.7f}, k ? 8.0f : 4.0f, k ? 5.6f : 2.8f, 0.4f);
                    l1[k] = glint_test::binned_l1(m, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, fp, s)); },
                                                  [&](glm::vec2 s) { return static_cast<double>(ref.eval(fp, s)); }, 3);
                }
                const std::string name = "ndf_map_tau_" + fmt(tau) + "_" + std::to_string(cap);
                add(name, [&m, &pl, &q](std::size_t i) {
                    const auto& x = q[i % q.size()];
                    benchmark::DoNotOptimize(m.eval(pl, x.fp, x.s));
                }, min_time);
                const double t = run_all().at(name);
                md << "| " << fmt(tau) << " | " << cap << " | " << fmt(l1[0], "%.4f") << " | " << fmt(l1[1], "%.4f") << " | " << m.evaluation_cost(pl, q[0].fp).tiles
                   << " | " << fmt(t, "%.0f") << " |\n";
                out.csv_rows += "ndf_map,flakes tau=" + fmt(tau) + " max_tiles=" + std::to_string(cap) + ",float,L1 vs direct P-NDF sd=8 (binned)," + fmt(l1[1]) +
                                "," + fmt(t) + ",,\n";
            }
    }

    // Stochastic layout.
    md << "\n### Stochastic layout\n\nFlakes example (S = 64, sigma_r = 0.02) in cells of 32 texels, rotation uniform in [0, 2 pi), scale "
          "0.8 to 1.25, mirrored with probability 1/2. L1 (binned, 3 x 3 sub-samples) against the layout's own element path (every owned "
          "element, glint::ndf_map::eval_direct; mean over 2 footprints), ns per evaluation, copies and tiles read:\n\n"
          "| sd | L1 vs element path | ns | copies | tiles |\n|---|---|---|---|---|\n";
    {
        const auto pp = glint_test::example_pattern(glint::pattern::flakes, n);
        const auto m = map_t::build(glint::make_normal_map(pp), params(0.02, 64));
        const auto pl = placement::stochastic(32.0f, 7u, glm::vec2(0, 6.2831853f), glm::vec2(0.8f, 1.25f), 0.5f);
        for (const float sd : {2.0f, 4.0f, 8.0f, 16.0f, 64.0f}) {
            double l1 = -1;
            if (sd <= 8) {
                l1 = 0;
                for (std::uint32_t i = 0; i < 2; ++i) {
                    const auto fp = fp_at({300 * unit(i, 7), 300 * unit(i, 8)}, sd, 0.8f * sd, unit(i, 9));
                    l1 += glint_test::binned_l1(m, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, fp, s)); },
                                                [&](glm::vec2 s) { return static_cast<double>(m.eval_direct(pl, fp, s)); }, 3) / 2;
                }
            }
            const auto q = queries(pp, sd, 32);
            const std::string name = "ndf_map_stochastic_" + fmt(sd);
            add(name, [&m, &pl, &q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(m.eval(pl, x.fp, x.s));
            }, min_time);
            const double t = run_all().at(name);
            const auto cost = m.evaluation_cost(pl, q[0].fp);
            md << "| " << sd << " | " << (l1 < 0 ? std::string("-") : fmt(l1, "%.3f")) << " | " << fmt(t, "%.0f") << " | " << cost.copies << " | " << cost.tiles << " |\n";
        }
    }
    md << "\n";
    out.markdown = md.str();
    out.files["ndf_map.md"] = "# Tiny-example NDF maps: measured\n\nGenerated by `glint_report --docs docs` (bench/report_ndf_map.cpp); do not edit by hand.\n\n" +
                              out.markdown;
    return out;
}

}  // namespace glint_report
