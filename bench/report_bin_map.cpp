// The bin-map section of the accuracy-versus-time report (glint/bin_map.hpp, AKKW): build time and
// memory per texel on 2048^2 car-paint flakes and scratched metal against the direct P-NDF's
// hierarchy on the same maps; evaluation time against the footprint's side from 8 to 2048
// texels, next to visiting every texel and to the direct P-NDF; sampling time; the bins' own
// error against the unbinned texel normals, and the distance to the direct P-NDF; the knobs (n,
// leaf size, rule, kernel); the global-histogram fallback. Writes docs/bin_map.md.
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glint/bin_map.hpp>
#include <glint/gaussian.hpp>
#include <glint/patterns.hpp>

#include "../tests/support/bin_map_support.hpp"
#include "report.hpp"

namespace glint_report {

namespace {

using bmap = glint::bin_map<float>;
using parallelogram = glint::uv_parallelogram<float>;

const int side = 2048;        // the maps' size
const double sigma_r = 0.01;  // the direct P-NDF's intrinsic roughness
const double alpha = std::sqrt(2.0) * sigma_r;                         // the flake lobes matched to it (AKKW notes 1.7)
const int bins = static_cast<int>(std::ceil(3.6 / alpha));            // n = 255: bins 0.85 alpha wide at the pole

double unit(std::uint32_t i, std::uint32_t k) { return glint::unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, k, 0xb17u)).x); }

glint::pattern_params map_params(glint::pattern kind) {
    glint::pattern_params p;
    p.kind = kind, p.width = p.height = side, p.seed = 3, p.slope_rms = 0.15, p.feature = 8;
    p.count = 2400;  // scratched_metal: 150 segments per 512^2
    return p;
}

// A query: the footprint (a x 0.8a texels, rotated 0.3 rad, sheared 0.2) at a random centre, and a
// half vector near the normal of the texel at its centre (within 2 alpha), where the glints are.
struct query {
    parallelogram A;
    glint::texel_footprint<float> fp;  // the Gaussian of the same mean and covariance (the P-NDF's)
    glm::vec3 h;
};

std::vector<query> queries(const glint::normal_map& map, double a, int count, std::uint32_t seed) {
    std::vector<query> q;
    for (int i = 0; i < count; ++i) {
        const std::uint32_t k = static_cast<std::uint32_t>(i);
        const glm::dvec2 c(side * unit(k, seed), side * unit(k, seed + 1));
        const double t = 0.3;
        const glm::dvec2 e0 = a * glm::dvec2(std::cos(t), std::sin(t)), e1 = 0.8 * a * glm::dvec2(-std::sin(t + 0.2), std::cos(t + 0.2));
        query x;
        x.A.origin = glm::vec2((c - 0.5 * (e0 + e1)) / double(side)), x.A.e0 = glm::vec2(e0 / double(side)), x.A.e1 = glm::vec2(e1 / double(side));
        x.fp.center = glm::vec2(c);
        // uniform on a parallelogram: covariance (e0 e0^T + e1 e1^T) / 12
        const glm::dmat2 cov = (glm::outerProduct(e0, e0) + glm::outerProduct(e1, e1)) / 12.0;
        x.fp.covariance = glm::mat2(cov);
        const glm::dvec3 n(map.texel(static_cast<long>(c.x), static_cast<long>(c.y)));
        const glm::dvec3 jitter = 2 * alpha * glm::dvec3(unit(k, seed + 2) - 0.5, unit(k, seed + 3) - 0.5, 0);
        x.h = glm::vec3(glm::normalize(n + jitter));
        q.push_back(x);
    }
    return q;
}

glint::bin_map_options options(int n, glint::bin_kernel kernel, glint::coverage_rule rule = glint::coverage_rule::exact_area, int leaf = 16) {
    glint::bin_map_options o;
    o.bins_per_side = n, o.kernel = kernel, o.rule = rule, o.leaf_size = leaf, o.alpha = alpha;
    return o;
}

const char* kernel_name(glint::bin_kernel k) { return k == glint::bin_kernel::box ? "box" : k == glint::bin_kernel::tent ? "tent" : "beckmann"; }

double seconds_since(std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); }

// eval's ns per query over the queries (cycled), through Google Benchmark.
void add_eval(const std::string& name, const bmap& m, const std::vector<query>& q, double min_time) {
    add(name, [&m, &q](std::size_t i) {
        const auto& x = q[i % q.size()];
        benchmark::DoNotOptimize(m.eval(x.A, x.h).pdf);
    }, min_time);
}

// The L1 distance between the bin map's density and the direct P-NDF's (normalised: its sampler's
// pdf, per solid angle) at a query, by sampling their mixture (mixture_l1).
std::pair<double, double> l1_to_pndf(const bmap& m, const glint::gaussian_pndf<float>& pndf, const query& x, int draws) {
    const float w = pndf.sampling_weight(x.fp);
    return glint_test::mixture_l1(
        draws,
        [&](int i) {
            const std::uint32_t k = static_cast<std::uint32_t>(i);
            const auto s = m.sample(x.A, glm::vec2(unit(k, 44u), unit(k, 45u)), glm::vec2(unit(k, 46u), unit(k, 47u)));
            return s.valid ? glm::dvec3(s.h) : glm::dvec3(0, 0, -1);
        },
        [&](int i) {
            const std::uint32_t k = static_cast<std::uint32_t>(i);
            const auto s = pndf.sample(x.fp, static_cast<float>(unit(k, 48u)), static_cast<float>(unit(k, 49u)), static_cast<float>(unit(k, 50u)));
            return s.valid ? glm::dvec3(s.h) : glm::dvec3(0, 0, -1);
        },
        [&](const glm::dvec3& h) { return static_cast<double>(m.eval(x.A, glm::vec3(h)).pdf); },
        [&](const glm::dvec3& h) { return static_cast<double>(pndf.pdf(x.fp, glm::vec2(h.x, h.y), w)) * h.z; });
}

}  // namespace

section bin_map_section(double min_time) {
    section out;
    std::ostringstream md;
    md << "## Inverse bin maps (glint/bin_map.hpp, AKKW)\n\n"
          "CPU, one thread, float queries. Maps: " << side << " x " << side << " texels, `flakes` (car paint: Voronoi flakes of 8 texels, slope "
          "sd 0.15) and `scratched_metal` (2400 V-groove segments, 20 to 40 degrees). The direct P-NDF (glint/gaussian.hpp) of the same map "
          "has sigma_r = " << sigma_r << ", one element per texel and its hierarchy; the bin map is matched to it as the AKKW notes say "
          "(1.7): flake lobes alpha = sqrt(2) sigma_r = " << fmt(alpha, "%.4f") << ", n = ceil(3.6 / alpha) = " << bins << " bins per side (B = "
       << bins * bins << "), leaf size 16, exact-area coverage. Queries: footprints a x 0.8a texels (rotated, sheared) at random centres, "
          "h within 2 alpha of the normal at the centre (where glints are); the P-NDF's footprint is the Gaussian of the same mean and "
          "covariance.\n\n";

    std::vector<glint::normal_map> maps;
    for (const auto kind : {glint::pattern::flakes, glint::pattern::scratched_metal}) maps.push_back(glint::make_normal_map(map_params(kind)));
    const char* map_names[2] = {"flakes", "scratched_metal"};
    const double texels = static_cast<double>(side) * side;

    // Build and memory, against the P-NDF's hierarchy.
    md << "### Build and memory\n\n| map | bin map build (ns / texel) | bin map (bytes / texel) | bins used | P-NDF build (s) | P-NDF (bytes / texel) | "
          "memory ratio |\n|---|---|---|---|---|---|---|\n";
    // Each map's direct P-NDF, built once (timed) for every table below.
    std::vector<glint::gaussian_pndf<float>> pndfs;
    std::vector<double> pndf_bytes(2);
    for (std::size_t mi = 0; mi < maps.size(); ++mi) {
        double build = 1e300;
        bmap m;
        for (int r = 0; r < 3; ++r) {  // the fastest of 3 builds: the machine is shared
            m = bmap::build(maps[mi], options(bins, glint::bin_kernel::box));
            build = std::min(build, m.statistics().build_seconds);
        }
        glint::gaussian_params<float> g;
        g.sigma_r = static_cast<float>(sigma_r);
        const auto t0 = std::chrono::steady_clock::now();
        pndfs.push_back(glint::gaussian_pndf<float>::build(maps[mi], g));
        const double pndf_build = seconds_since(t0);
        const auto& pndf = pndfs.back();
        pndf_bytes[mi] = static_cast<double>(pndf.memory_bytes());
        const double bpt = static_cast<double>(m.memory_bytes()) / texels;
        md << "| " << map_names[mi] << " | " << fmt(1e9 * build / texels, "%.0f") << " | " << fmt(bpt, "%.2f") << " | " << m.statistics().nonempty_bins << " | " << fmt(pndf_build, "%.1f") << " | " << fmt(pndf_bytes[mi] / texels, "%.0f") << " | "
           << fmt(pndf_bytes[mi] / static_cast<double>(m.memory_bytes()), "%.0f") << "x smaller |\n";
        out.csv_rows += "bin_map," + std::string(map_names[mi]) + " 2048^2 n=255 L=16,float,build ns per texel," + fmt(1e9 * build / texels) + ",,,\n";
        out.csv_rows += "bin_map," + std::string(map_names[mi]) + " 2048^2 n=255 L=16,float,bytes per texel," + fmt(bpt) + ",,,\n";
    }
    md << "\nThe talk: 144 MB at 4k (about 9 bytes per texel) against YHMR16's 25 GB (170x). Targets: at most 100 ns and about 9 bytes per "
          "texel, 50x less memory than the P-NDF.\n\n";

    // Evaluation time against the footprint's side.
    md << "### Evaluation time against the footprint\n\nns per eval (one float query); `visit all` visits every texel under the "
          "footprint's bounding box (the box kernel with direct_texels = 2^30: brute force with the same weights); the P-NDF is eval with "
          "its hierarchy (one run each; the P-NDF above 512 texels is not timed: at 512 it already takes milliseconds). Speed-up: P-NDF / "
          "bin map.\n\n";
    const std::vector<double> sides = {8, 16, 32, 64, 128, 256, 512, 1024, 2048};
    const glint::bin_kernel kernels[3] = {glint::bin_kernel::box, glint::bin_kernel::tent, glint::bin_kernel::beckmann};
    for (std::size_t mi = 0; mi < maps.size(); ++mi) {
        std::vector<bmap> ms;
        for (const auto k : kernels) ms.push_back(bmap::build(maps[mi], options(bins, k)));
        const bmap centre = bmap::build(maps[mi], options(bins, glint::bin_kernel::box, glint::coverage_rule::texel_center));
        glint::bin_map_options all = options(bins, glint::bin_kernel::box);
        all.direct_texels = 1 << 30;
        const bmap visit = bmap::build(maps[mi], all);
        const auto& pndf = pndfs[mi];
        md << "`" << map_names[mi] << "`:\n\n| side (texels) | box | tent | beckmann | box, texel centres | visit all | P-NDF | speed-up box / tent / beckmann |"
              "\n|---|---|---|---|---|---|---|---|\n";
        for (const double a : sides) {
            const auto q = queries(maps[mi], a, 256, 11u);
            const std::string tag = std::string(map_names[mi]) + "_" + fmt(a, "%.0f");
            for (std::size_t k = 0; k < 3; ++k) add_eval(std::string("bin_") + kernel_name(kernels[k]) + "_" + tag, ms[k], q, min_time);
            add_eval("bin_centre_" + tag, centre, q, min_time);
            add_eval("bin_visit_" + tag, visit, q, a >= 512 ? 1e-3 : min_time);
            if (a <= 512)
                add("pndf_" + tag, [&pndf, &q](std::size_t i) {
                    const auto& x = q[i % q.size()];
                    benchmark::DoNotOptimize(pndf.eval(x.fp, glm::vec2(x.h.x, x.h.y)));
                }, a >= 256 ? 1e-3 : min_time);
            const auto ns = run_all();
            const double box = ns.at("bin_box_" + tag), tent = ns.at("bin_tent_" + tag), beck = ns.at("bin_beckmann_" + tag);
            md << "| " << a << " | " << fmt(box, "%.0f") << " | " << fmt(tent, "%.0f") << " | " << fmt(beck, "%.0f") << " | "
               << fmt(ns.at("bin_centre_" + tag), "%.0f") << " | " << fmt(ns.at("bin_visit_" + tag), "%.0f") << " | ";
            if (a <= 512) {
                const double p = ns.at("pndf_" + tag);
                md << fmt(p, "%.0f") << " | " << fmt(p / box, "%.0f") << "x / " << fmt(p / tent, "%.0f") << "x / " << fmt(p / beck, "%.0f") << "x |\n";
                for (std::size_t k = 0; k < 3; ++k)
                    out.csv_rows += "bin_map," + std::string(map_names[mi]) + " " + kernel_name(kernels[k]) + " side=" + fmt(a) + ",float,,," +
                                    fmt(ns.at(std::string("bin_") + kernel_name(kernels[k]) + "_" + tag)) + "," +
                                    fmt(ns.at(std::string("bin_") + kernel_name(kernels[k]) + "_" + tag) / p) + ",direct P-NDF\n";
            } else {
                md << "- | - |\n";
            }
        }
        md << "\n";
    }

    // Sampling.
    md << "### Sampling\n\nns per sample (a texel by its weight in the footprint, a direction from its bin's kernel, and eval's pdf in the "
          "same call), `flakes`:\n\n| side (texels) | box | tent | beckmann | box, texel centres |\n|---|---|---|---|---|\n";
    {
        std::vector<bmap> ms;
        for (const auto k : kernels) ms.push_back(bmap::build(maps[0], options(bins, k)));
        ms.push_back(bmap::build(maps[0], options(bins, glint::bin_kernel::box, glint::coverage_rule::texel_center)));
        for (const double a : {8.0, 64.0, 512.0}) {
            const auto q = queries(maps[0], a, 256, 21u);
            for (std::size_t k = 0; k < ms.size(); ++k)
                add("sample_" + std::to_string(k), [&m = ms[k], &q](std::size_t i) {
                    const auto& x = q[i % q.size()];
                    const glm::vec2 u(static_cast<float>(unit(static_cast<std::uint32_t>(i), 1u)), static_cast<float>(unit(static_cast<std::uint32_t>(i), 2u)));
                    benchmark::DoNotOptimize(m.sample(x.A, u, glm::vec2(u.y, u.x)).pdf);
                }, min_time);
            const auto ns = run_all();
            md << "| " << a << " |";
            for (std::size_t k = 0; k < ms.size(); ++k) md << " " << fmt(ns.at("sample_" + std::to_string(k)), "%.0f") << " |";
            md << "\n";
        }
    }

    // Accuracy: the bins' quantisation against the unbinned texel normals, and the distance to the P-NDF.
    md << "\n### Accuracy\n\nL1 distance between densities of h on the hemisphere, estimated by sampling their mixture (E over (p + r) / 2 of "
          "2 |p - r| / (p + r); 2000 draws per footprint, 8 footprints; +- one standard error), `flakes`:\n\n"
          "- the bins' own error: the beckmann kernel against the same footprint and lobes around each texel's own normal (the unbinned "
          "sum, tests/support/bin_map_support.hpp), against n;\n"
          "- the distance to the direct P-NDF (normalised, its footprint the Gaussian of the same covariance): a different model (bicubic "
          "normals and a Gaussian footprint against texel normals and a parallelogram), so it shrinks only as the footprint grows and "
          "both approach the normal histogram.\n\n"
          "| side (texels) | n = 64 vs unbinned | n = 128 | n = 255 | n = 512 | n = 255 vs P-NDF |\n|---|---|---|---|---|---|\n";
    {
        const std::vector<int> ns_bins = {64, 128, bins, 512};
        std::vector<bmap> ms;
        for (const int n : ns_bins) ms.push_back(bmap::build(maps[0], options(n, glint::bin_kernel::beckmann)));
        const auto& pndf = pndfs[0];
        for (const double a : {8.0, 64.0, 512.0}) {
            const auto q = queries(maps[0], a, 8, 31u);
            const double nq = static_cast<double>(q.size());
            std::vector<double> e(ns_bins.size() + 1, 0.0), se(ns_bins.size() + 1, 0.0);
            const int draws = 2000;
            for (const auto& x : q) {
                const auto P = glint_test::in_texels(x.A, side, side);
                const glint_test::unbinned_texels ref(maps[0], P, alpha, 0.0111);
                const auto sample_ref = [&](int i) {
                    const std::uint32_t k = static_cast<std::uint32_t>(i);
                    return ref.sample(unit(k, 41u), unit(k, 42u), unit(k, 43u));
                };
                for (std::size_t b = 0; b < ms.size(); ++b) {
                    const bmap& m = ms[b];
                    const auto r = glint_test::mixture_l1(
                        draws,
                        [&](int i) {
                            const std::uint32_t k = static_cast<std::uint32_t>(i);
                            const auto s = m.sample(x.A, glm::vec2(unit(k, 44u), unit(k, 45u)), glm::vec2(unit(k, 46u), unit(k, 47u)));
                            return s.valid ? glm::dvec3(s.h) : glm::dvec3(0, 0, -1);
                        },
                        sample_ref, [&](const glm::dvec3& h) { return static_cast<double>(m.eval(x.A, glm::vec3(h)).pdf); },
                        [&](const glm::dvec3& h) { return ref.pdf(h); });
                    e[b] += r.first / nq, se[b] += r.second * r.second / (nq * nq);
                }
                // against the P-NDF (fewer draws at 512 texels, where an evaluation takes milliseconds)
                const auto r = l1_to_pndf(ms[2], pndf, x, a >= 512 ? 200 : draws);
                e.back() += r.first / nq, se.back() += r.second * r.second / (nq * nq);
            }
            md << "| " << a << " |";
            for (std::size_t b = 0; b < e.size(); ++b) md << " " << fmt(e[b], "%.3f") << " +- " << fmt(std::sqrt(se[b]), "%.3f") << " |";
            md << "\n";
            for (std::size_t b = 0; b < ns_bins.size(); ++b)
                out.csv_rows += "bin_map,flakes beckmann n=" + std::to_string(ns_bins[b]) + " side=" + fmt(a) + ",float,L1 vs unbinned texel normals," + fmt(e[b]) + ",,,\n";
            out.csv_rows += "bin_map,flakes beckmann n=255 side=" + fmt(a) + ",float,L1 vs direct P-NDF," + fmt(e.back()) + ",,,\n";
        }
    }

    // The knobs at one footprint size: n, leaf size, rule, kernel.
    md << "\n### Knobs\n\n`flakes`, footprint side 64: L1 against the direct P-NDF (as above: 1000 draws per footprint, 8 footprints; the leaf "
          "size changes no value), ns per eval and per sample, build ns per texel, bytes per texel (one run):\n\n"
          "| n | leaf size | rule | kernel | L1 vs P-NDF | eval ns | sample ns | build ns / texel | bytes / texel |\n|---|---|---|---|---|---|---|---|---|\n";
    {
        struct knob {
            int n, leaf;
            glint::coverage_rule rule;
            glint::bin_kernel kernel;
        };
        const auto exact = glint::coverage_rule::exact_area, centre = glint::coverage_rule::texel_center;
        const std::vector<knob> knobs = {{32, 16, exact, glint::bin_kernel::box},     {64, 16, exact, glint::bin_kernel::box},
                                         {bins, 16, exact, glint::bin_kernel::box},   {512, 16, exact, glint::bin_kernel::box},
                                         {bins, 1, exact, glint::bin_kernel::box},    {bins, 4, exact, glint::bin_kernel::box},
                                         {bins, 64, exact, glint::bin_kernel::box},   {bins, 16, centre, glint::bin_kernel::box},
                                         {bins, 16, exact, glint::bin_kernel::tent},  {bins, 16, exact, glint::bin_kernel::beckmann},
                                         {bins, 16, centre, glint::bin_kernel::beckmann}};
        const auto q = queries(maps[0], 64, 256, 51u);
        const auto& pndf = pndfs[0];
        const auto eq = queries(maps[0], 64, 8, 31u);
        for (std::size_t k = 0; k < knobs.size(); ++k) {
            const knob& kb = knobs[k];
            const bmap m = bmap::build(maps[0], options(kb.n, kb.kernel, kb.rule, kb.leaf));
            add_eval("knob", m, q, min_time);
            add("knob_sample", [&m, &q](std::size_t i) {
                const auto& x = q[i % q.size()];
                const glm::vec2 u(static_cast<float>(unit(static_cast<std::uint32_t>(i), 1u)), static_cast<float>(unit(static_cast<std::uint32_t>(i), 2u)));
                benchmark::DoNotOptimize(m.sample(x.A, u, glm::vec2(u.y, u.x)).pdf);
            }, min_time);
            const auto times = run_all();
            const double ns = times.at("knob"), sample_ns = times.at("knob_sample");
            double l1 = 0;
            for (const auto& x : eq) l1 += l1_to_pndf(m, pndf, x, 1000).first / static_cast<double>(eq.size());
            const char* rule = kb.rule == exact ? "exact area" : "texel centre";
            md << "| " << kb.n << " | " << kb.leaf << " | " << rule << " | " << kernel_name(kb.kernel) << " | " << fmt(l1, "%.3f") << " | " << fmt(ns, "%.0f") << " | " << fmt(sample_ns, "%.0f") << " | "
               << fmt(1e9 * m.statistics().build_seconds / texels, "%.0f") << " | " << fmt(static_cast<double>(m.memory_bytes()) / texels, "%.2f") << " |\n";
            out.csv_rows += "bin_map,flakes n=" + std::to_string(kb.n) + " L=" + std::to_string(kb.leaf) + " " + rule + " " + kernel_name(kb.kernel) +
                            " side=64,float,L1 vs direct P-NDF," + fmt(l1) + "," + fmt(ns) + ",,\n";
        }
    }

    // The global-histogram fallback: L1 between the coverages of footprints of k + 0.3 tiles a
    // side with the copies walked and with the histogram.
    md << "\n### Beyond max_tile_copies\n\nFootprints wider than max_tile_copies tile copies (default 256) take the global histogram. Its "
          "error: L1 between the exact coverages (all copies walked) and the histogram, over the bins, for footprints (k + 0.3) tiles a "
          "side on a 256^2 `flakes` map (n = 32):\n\n| k | L1 |\n|---|---|\n";
    {
        auto p = map_params(glint::pattern::flakes);
        p.width = p.height = 256;
        glint::bin_map_options o = options(32, glint::bin_kernel::box);
        o.max_tile_copies = 1 << 20;
        const auto m = bmap::build(glint::make_normal_map(p), o);
        for (const double k : {4.0, 16.0, 64.0}) {
            const auto A = parallelogram::rect(glm::vec2(0.13f, 0.41f), glm::vec2(0.13f + static_cast<float>(k) + 0.3f, 0.41f + static_cast<float>(k) + 0.3f));
            double l1 = 0;
            for (std::uint32_t j = 0; j < m.bin_count(); ++j)
                l1 += std::fabs(static_cast<double>(m.coverage(A, j)) - static_cast<double>(m.bin_texels(j)) / (256.0 * 256.0));
            md << "| " << k << " | " << fmt(l1, "%.2e") << " |\n";
            out.csv_rows += "bin_map,global histogram for " + fmt(k) + ".3 tiles,float,L1 vs exact coverages," + fmt(l1) + ",,,\n";
        }
    }
    md << "\n";
    out.markdown = md.str();
    out.files["bin_map.md"] = "# Inverse bin maps: measured\n\nGenerated by `glint_report --docs docs` (bench/report_bin_map.cpp); do not edit by hand.\n\n" +
                              out.markdown;
    return out;
}

}  // namespace glint_report
