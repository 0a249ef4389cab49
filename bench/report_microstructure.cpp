// The microstructure section of the accuracy-versus-time report (glint/gaussian.hpp): the P-NDF's
// cost against the footprint's size with and without the hierarchy on a 1024^2 noise map, its
// error against the brute-force reference, build time and memory per texel, elements per texel
// against the histogram of the microsurface's normals, and the culling radii against error and
// time, in one run. Writes docs/microstructure.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <glint/gaussian.hpp>
#include <glint/patterns.hpp>

#include "../tests/support/pndf_support.hpp"
#include "report.hpp"

namespace glint_report {

namespace {

glint::texel_footprint<float> footprint(glm::vec2 c, float a, float b, float t) { return glint_test::rotated_footprint(c, a, b, t); }

using query = glint_test::pndf_query;
std::vector<query> queries(const glint::pattern_params& p, float sd, int n) { return glint_test::pndf_queries(p, sd, n, 1.0f, 0x3e7u); }

double seconds_since(std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); }

}  // namespace

section microstructure_section(double min_time) {
    section out;
    std::ostringstream md;
    md << "## Normal-mapped microstructure: the footprint P-NDF (glint/gaussian.hpp)\n\n"
          "CPU, one thread, float. Maps: 1024 x 1024 texels, sigma_r = 0.005, one element per texel, cull_u = 3.5 (tapered), "
          "cull_s = 4: `flakes` (Voronoi cells of 8 texels, slope sd 0.15: flat lobes, the glinty case) and `noise` (slope rms "
          "0.1, wavelengths down to 4 texels: rough at the texel scale, every lobe as wide as the normals' spread). Queries: "
          "footprints of sd sigma_P (aspect 1 to 2, random rotation) at random centres, s within 0.01 of the normal at the centre. "
          "Brute force: every lattice point of the same culling box (eval_direct, uncapped); reference: 7-sigma box, no lobe "
          "culling (eval_reference). eval uses the hierarchy where its lists are shorter than the box's lattice, else the "
          "direct sum. Terms: the elements whose term at s is nonzero (term_count), which any exact sum of the culled P-NDF "
          "must add; ns per term shows how the cost follows them.\n\n";
    glint::pattern_params p;
    p.width = p.height = 1024, p.seed = 5;
    glint::gaussian_params<float> g;
    g.sigma_r = 0.005f, g.direct_max_side = 1 << 20;
    glint::normal_map map;
    for (const auto kind : {glint::pattern::flakes, glint::pattern::noise}) {
        p.kind = kind, p.slope_rms = kind == glint::pattern::flakes ? 0.15 : 0.1;
        map = glint::make_normal_map(p);
        auto t0 = std::chrono::steady_clock::now();
        const auto pndf = glint::gaussian_pndf<float>::build(map, g);
        const double build = seconds_since(t0);
        const double texels = static_cast<double>(p.width) * p.height;
        md << "`" << glint::pattern_name(kind) << "`: build " << fmt(build, "%.2f") << " s (" << fmt(1e9 * build / texels, "%.0f") << " ns per texel); memory "
           << fmt(static_cast<double>(pndf.memory_bytes()) / 1e6, "%.1f") << " MB (" << fmt(static_cast<double>(pndf.memory_bytes()) / texels, "%.0f")
           << " bytes per texel: 32 for the element, the rest its s-box";
        md << ", the cell lists and position trees; " << pndf.grid_size() << "^2 cells at the finest of " << pndf.level_count()
           << " normal-space levels; elements per level, finest first:";
        for (const std::size_t c : pndf.level_elements()) md << " " << c;
        glint::gaussian_params<float> none = g;
        none.hierarchy = glint::pndf_hierarchy::none;
        md << "; without the hierarchy, gaussian_params::hierarchy = none: "
           << fmt(static_cast<double>(glint::gaussian_pndf<float>::build(map, none).memory_bytes()) / texels, "%.0f") << " bytes per texel).\n\n";
        md << "| footprint sd (texels) | eval ns / query | brute force ns / query | speed-up | terms per query | eval ns / term | brute force ns / term | "
              "relative L1 error vs reference |\n|---|---|---|---|---|---|---|---|\n";
        std::vector<double> sloped_share;  // per footprint size, of the terms
        for (const float sigma : {1.0f, 8.0f, 64.0f, 512.0f}) {
            const int n = sigma >= 512 ? 4 : 32;
            const auto q = queries(p, sigma, n);
            const std::string tag = std::string(glint::pattern_name(kind)) + "_" + std::to_string(static_cast<int>(sigma));
            add("pndf_eval_" + tag, [&pndf, q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(pndf.eval(x.fp, x.s));
            }, min_time);
            add("pndf_direct_" + tag, [&pndf, q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(pndf.eval_direct(x.fp, x.s));
            }, sigma >= 512 ? 1e-3 : min_time);
            const auto ns = run_all();
            double l1 = 0, norm = 0;
            const int m = sigma >= 512 ? 2 : sigma >= 64 ? 6 : 32;
            for (int i = 0; i < m; ++i) {
                const auto& x = q[static_cast<std::size_t>(i)];
                const double ref = static_cast<double>(pndf.eval_reference(x.fp, x.s));
                l1 += std::fabs(static_cast<double>(pndf.eval(x.fp, x.s)) - ref), norm += ref;
            }
            // The terms an exact sum must add (term_count), over the timed queries, and those of
            // elements whose Jacobian is not 0 (on flakes: the cells' edges).
            double terms = 0, sloped = 0;
            for (const auto& x : q) {
                terms += static_cast<double>(pndf.term_count(x.fp, x.s));
                sloped += static_cast<double>(pndf.term_count(x.fp, x.s, [](const auto& el) { return el.jac != glm::vec4(0.0f); }));
            }
            sloped_share.push_back(sloped / std::max(terms, 1.0));
            terms /= static_cast<double>(q.size());
            const double h = ns.at("pndf_eval_" + tag), d = ns.at("pndf_direct_" + tag);
            md << "| " << sigma << " | " << fmt(h, "%.0f") << " | " << fmt(d, "%.0f") << " | " << fmt(d / h, "%.1f") << "x | " << fmt(terms, "%.0f") << " | "
               << fmt(h / std::max(terms, 1.0), "%.1f") << " | " << fmt(d / std::max(terms, 1.0), "%.1f") << " | " << fmt(l1 / norm) << " (" << m << " queries) |\n";
            out.csv_rows += "pndf," + std::string(glint::pattern_name(kind)) + " sigma_P=" + fmt(sigma) + ",float,relative L1 vs reference," + fmt(l1 / norm) +
                            "," + fmt(h) + "," + fmt(h / d) + ",brute force\n";
        }
        std::size_t sloped_elements = 0;
        for (std::size_t e = 0; e < pndf.element_count(); ++e) sloped_elements += pndf.element_data()[2 * e + 1] != glm::vec4(0.0f);
        md << "\nTerms from elements whose Jacobian is not 0 (" << fmt(100.0 * static_cast<double>(sloped_elements) / texels, "%.0f")
           << "% of the elements), at sd 1, 8, 64, 512:";
        for (const double x : sloped_share) md << " " << fmt(100 * x, "%.0f") << "%";
        md << ".\n";
        md << "\n";
    }
    const auto pndf = glint::gaussian_pndf<float>::build(map, g);  // noise, for the culling rows below
    // Elements per texel against the histogram of the interpolated normals (sigma_r = 1e-4).
    md << "\nElements per texel side against the microsurface's own normal distribution: L1 between the P-NDF's bin masses and "
          "the histogram of 2e6 bicubic normals under a footprint of sd 12 x 8 texels (64^2 noise map, slope rms 0.08, "
          "sigma_r = 1e-4, 32^2 bins over [-0.32, 0.32]^2; the test `P-NDF: a large footprint...` in tests/stat), with the "
          "time per query at that footprint:\n\n| elements per texel side | L1 vs histogram | ns / query | memory bytes per texel |\n|---|---|---|---|\n";
    {
        glint::pattern_params s = p;
        s.kind = glint::pattern::noise, s.width = s.height = 64, s.slope_rms = 0.08, s.seed = 1;
        const glint::normal_map small = glint::make_normal_map(s);
        const auto fp = footprint({30.3f, 21.7f}, 12, 8, 0.5f);
        const glint::texel_footprint<double> fpd{glm::dvec2(fp.center), glm::dmat2(fp.covariance)};
        const glint_test::normal_bins bins;
        const auto hist = glint_test::normal_histogram(small, fpd, bins, 2000000);
        for (const int r : {1, 2, 4}) {
            glint::gaussian_params<double> gd;
            gd.sigma_r = 1e-4, gd.elements_per_texel = r;
            const double l1 = glint_test::l1_distance(hist, glint_test::pndf_bin_masses(glint::gaussian_pndf<double>::build(small, gd), fpd, bins));
            glint::gaussian_params<float> gf;
            gf.sigma_r = 1e-4f, gf.elements_per_texel = r;
            const auto pf = glint::gaussian_pndf<float>::build(small, gf);
            const auto q = queries(s, 12.0f, 32);
            add("pndf_r" + std::to_string(r), [&pf, q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(pf.eval(x.fp, x.s));
            }, min_time);
            const double t = run_all().at("pndf_r" + std::to_string(r));
            md << "| " << r << " | " << fmt(l1) << " | " << fmt(t, "%.0f") << " | "
               << fmt(static_cast<double>(pf.memory_bytes()) / (64.0 * 64.0), "%.0f") << " |\n";
            out.csv_rows += "pndf,elements per texel " + std::to_string(r) + ",double,L1 vs normal histogram," + fmt(l1) + "," + fmt(t) + ",,\n";
        }
    }
    // Culling radii against error and time (sigma_P = 8 texels).
    md << "\nCulling radii (footprint sd 8 texels, the 1024^2 noise map; error: relative L1 against the reference over 32 queries):\n\n"
          "| cull_u (taper from cull_u - 1) | cull_s | relative L1 error | ns / query |\n|---|---|---|---|\n";
    const auto q8 = queries(p, 8.0f, 32);
    std::vector<double> ref;
    for (const auto& x : q8) ref.push_back(static_cast<double>(pndf.eval_reference(x.fp, x.s)));
    for (const float cu : {2.5f, 3.0f, 3.5f, 4.0f, 5.0f})
        for (const float cs : {3.0f, 4.0f, 5.0f}) {
            if (cs != 4.0f && cu != 3.5f) continue;
            glint::gaussian_params<float> gc = g;
            gc.cull_u = cu, gc.cull_s = cs;
            const auto pc = glint::gaussian_pndf<float>::build(map, gc);
            double l1 = 0, norm = 0;
            for (std::size_t i = 0; i < q8.size(); ++i) l1 += std::fabs(static_cast<double>(pc.eval(q8[i].fp, q8[i].s)) - ref[i]), norm += ref[i];
            const std::string name = "pndf_cull_" + fmt(cu) + "_" + fmt(cs);
            add(name, [&pc, &q8](std::size_t i) {
                const auto& x = q8[i % q8.size()];
                benchmark::DoNotOptimize(pc.eval(x.fp, x.s));
            }, min_time);
            const double t = run_all().at(name);
            md << "| " << fmt(cu) << " | " << fmt(cs) << " | " << fmt(l1 / norm) << " | " << fmt(t, "%.0f") << " |\n";
            out.csv_rows += "pndf,cull_u=" + fmt(cu) + " cull_s=" + fmt(cs) + ",float,relative L1 vs reference," + fmt(l1 / norm) + "," + fmt(t) + ",,\n";
        }
    // Prefiltered nodes (gaussian_params::prefilter_spread) on both maps; tau against error and
    // time on flakes.
    md << "\n### Prefiltered nodes (gaussian_params::prefilter_spread)\n\nThe maps above built with prefilter_spread = 0.5: "
          "position-tree nodes whose elements lie within 0.5 footprint sds (rms) of their mean are summed from their NDF images "
          "(glint/gaussian.hpp: 2 points per sigma_r, 16 bits, the first moment in u). Exact: eval without them (on `noise` the "
          "lattice loop, which is cheaper there than the exact hierarchy); prefiltered: eval, which takes the hierarchy with the "
          "images wherever a node qualifies. Error: the relative L1 distance over s to the exact P-NDF, estimated as the mean of "
          "|D' - D| / D at 4 s per footprint drawn from the exact P-NDF (its sampler), over the queries shown.\n\n";
    struct probe {
        glint::texel_footprint<float> fp;
        glm::vec2 s;
        double exact;
    };
    for (const auto kind : {glint::pattern::flakes, glint::pattern::noise}) {
        p.kind = kind, p.slope_rms = kind == glint::pattern::flakes ? 0.15 : 0.1;
        const glint::normal_map m = glint::make_normal_map(p);
        const auto exact = glint::gaussian_pndf<float>::build(m, g);
        glint::gaussian_params<float> gp = g;
        gp.prefilter_spread = 0.5f;
        const auto t0 = std::chrono::steady_clock::now();
        const auto pre = glint::gaussian_pndf<float>::build(m, gp);
        const double build = seconds_since(t0);
        const double texels = static_cast<double>(p.width) * p.height;
        md << "`" << glint::pattern_name(kind) << "`: build " << fmt(build, "%.1f") << " s (" << fmt(1e9 * build / texels, "%.0f")
           << " ns per texel, against the hierarchy's figure above); images " << fmt(static_cast<double>(pre.prefilter_bytes()) / 1e6, "%.1f") << " MB ("
           << fmt(static_cast<double>(pre.prefilter_bytes()) / texels, "%.0f") << " bytes per texel, " << pre.prefiltered_node_count()
           << " nodes) on top of the hierarchy's " << fmt(static_cast<double>(exact.memory_bytes()) / 1e6, "%.1f") << " MB.\n\n"
           << "| footprint sd (texels) | exact eval ns / query | prefiltered eval ns / query | speed-up | relative L1 over s |\n|---|---|---|---|---|\n";
        const auto probes = [&](const std::vector<query>& q, int n) {
            std::vector<probe> v;
            for (int i = 0; i < n; ++i)
                for (std::uint32_t k = 0; k < 4; ++k) {
                    const auto u = [&](std::uint32_t stream) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), k, stream)).x); };
                    const auto& x = q[static_cast<std::size_t>(i)];
                    const auto d = exact.sample(x.fp, u(1), u(2), u(3));
                    if (d.valid) v.push_back({x.fp, d.s, static_cast<double>(exact.eval(x.fp, d.s))});
                }
            return v;
        };
        // The mean of |D' - D| / D over the probes, D' = approx(fp, s).
        const auto l1_of = [](const std::vector<probe>& v, auto&& approx) {
            double e = 0;
            for (const auto& x : v) e += std::fabs(static_cast<double>(approx(x.fp, x.s)) - x.exact) / x.exact;
            return e / static_cast<double>(std::max<std::size_t>(v.size(), 1));
        };
        const bool flakes = kind == glint::pattern::flakes;
        std::map<float, std::pair<std::vector<query>, std::vector<probe>>> at;
        for (const float sigma : flakes ? std::vector<float>{8, 64, 128, 256, 512} : std::vector<float>{8, 64, 512}) {
            const int n = sigma >= 256 ? 8 : 32;
            const auto q = queries(p, sigma, n);
            const std::string tag = std::string(glint::pattern_name(kind)) + "_" + std::to_string(static_cast<int>(sigma));
            add("pndf_exact_" + tag, [&exact, q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(exact.eval(x.fp, x.s));
            }, sigma >= 256 ? 1e-3 : min_time);
            add("pndf_prefiltered_" + tag, [&pre, q](std::size_t i) {
                const auto& x = q[i % q.size()];
                benchmark::DoNotOptimize(pre.eval(x.fp, x.s));
            }, sigma >= 256 ? 1e-3 : min_time);
            const auto ns = run_all();
            at[sigma] = {q, probes(q, sigma >= 256 ? 8 : 16)};
            const double e = ns.at("pndf_exact_" + tag), f = ns.at("pndf_prefiltered_" + tag), l1 = l1_of(at[sigma].second, [&pre](const auto& fp, const auto& s) { return pre.eval(fp, s); });
            md << "| " << sigma << " | " << fmt(e, "%.0f") << " | " << fmt(f, "%.0f") << " | " << fmt(e / f, "%.1f") << "x | " << fmt(l1) << " ("
               << at[sigma].second.size() << " s) |\n";
            out.csv_rows += "pndf," + std::string(glint::pattern_name(kind)) + " prefiltered tau=0.5 sigma_P=" + fmt(sigma) + ",float,relative L1 vs exact," +
                            fmt(l1) + "," + fmt(f) + "," + fmt(f / e) + ",exact eval\n";
        }
        md << "\n";
        if (!flakes) continue;
        md << "prefilter_spread (tau) against error and time on `flakes` (eval_hierarchy with tau; 0 is the exact hierarchy):\n\n"
              "| tau | sd 64: ns / query | relative L1 | sd 512: ns / query | relative L1 |\n|---|---|---|---|---|\n";
        for (const float tau : {0.0f, 0.25f, 0.5f, 0.7f, 1.0f}) {
            md << "| " << fmt(tau);
            for (const float sigma : {64.0f, 512.0f}) {
                const auto& q = at[sigma].first;
                const std::string name = "pndf_tau_" + fmt(tau) + "_" + std::to_string(static_cast<int>(sigma));
                add(name, [&pre, &q, tau](std::size_t i) {
                    const auto& x = q[i % q.size()];
                    benchmark::DoNotOptimize(pre.eval_hierarchy(x.fp, x.s, tau));
                }, sigma >= 256 ? 1e-3 : min_time);
                md << " | " << fmt(run_all().at(name), "%.0f") << " | " << fmt(l1_of(at[sigma].second, [&pre, tau](const auto& fp, const auto& s) { return pre.eval_hierarchy(fp, s, tau); }));
            }
            md << " |\n";
        }
        md << "\n";
    }
    md << "\n";
    out.markdown = md.str();
    out.files["microstructure.md"] = "# Normal-mapped microstructure: measured\n\nGenerated by `glint_report --docs docs` (bench/report_microstructure.cpp); "
                                     "do not edit by hand.\n\n" + out.markdown;
    return out;
}

}  // namespace glint_report
