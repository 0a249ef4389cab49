// The scratches section of the accuracy-versus-time report (glint/scratch.hpp, RGB16): the table's
// build time per profile against RGB16's 100-300 ms, its noise against the rays per row, Eq. 2's
// error against an independent 3D tracer at 15 to 75 degrees for three Fresnel models, memory, the
// per-call cost of each kernel, and the SV-BRDF's cost against the number of layers (with the
// culls) next to the base BRDF alone, in one run. Writes docs/scratch.md.
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <glint/microfacet.hpp>
#include <glint/scratch.hpp>

#include "../tests/support/scratch_support.hpp"
#include "report.hpp"

namespace glint_report {

namespace {

const double pi = 3.14159265358979323846, deg = pi / 180;

float unit(std::uint32_t i, std::uint32_t s) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, s, 0x5c9u)).x); }

double seconds_since(std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); }

// Best of `runs` wall times of a table build, in ms.
double build_ms(const glint::scratch_profile& p, const glint::scratch_fresnel& f, const glint::scratch_table_options& o, int runs) {
    double best = 1e300;
    for (int r = 0; r < runs; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const auto t = glint::build_scratch_table(p, f, o);
        best = std::min(best, 1e3 * seconds_since(t0));
        if (t.resolution() != o.resolution) std::abort();
    }
    return best;
}

// Mass-weighted relative L1 distance between two tables' rho_m.
double table_l1(const glint::scratch_table& a, const glint::scratch_table& b) {
    const int M = a.resolution();
    double num = 0, den = 0;
    for (int o = 0; o < M; ++o)
        for (int i = 0; i < M; ++i) {
            const std::size_t k = static_cast<std::size_t>(o * M + i);
            const double w = glint::scratch_table::bin_ds(o, M) * glint::scratch_table::bin_ds(i, M);
            num += std::fabs(a.rho_m()[k] - b.rho_m()[k]) * w, den += b.rho_m()[k] * w;
        }
    return num / den;
}

}  // namespace

section scratch_section(double min_time) {
    section out;
    std::ostringstream md;
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    md << "## Scratches (RGB16): glint/scratch.hpp\n\n";

    // 1. Build time, M = 256, N = 10,000 (RGB16 Sec. 6.1's setting), best of 3, all cores and one.
    md << "Table build, 256^2 bins, 10,000 rays per row, best of 3 wall times on this machine (" << threads
       << " threads, then 1); RGB16: 100-300 ms in CUDA on a GTX 680; target 300 ms. Tracing: binary search for convex profiles, a max tree otherwise.\n\n";
    md << "| profile | Fresnel | ms, " << threads << " threads | ms, 1 thread | lost at 64 bounces | most bounces |\n|---|---|---|---|---|---|\n";
    glint::scratch_fresnel gold;
    gold.model = glint::fresnel_model::conductor_exact, gold.eta = glm::dvec3(0.18, 0.42, 1.37), gold.k = glm::dvec3(3.42, 2.35, 1.77);
    struct profile_case {
        const char* name;
        glint::scratch_profile p;
        glint::scratch_fresnel f;
        const char* fname;
    };
    const profile_case cases[] = {
        {"V-groove 30 deg", glint::make_v_groove(30 * deg), glint::scratch_fresnel::iron(), "iron"},
        {"quartic D/W 0.5 (steep)", glint::make_quartic_groove(0.5), glint::scratch_fresnel::iron(), "iron"},
        {"quartic D/W 0.5 (steep)", glint::make_quartic_groove(0.5), gold, "gold (RGB)"},
        {"quartic D/W 0.05 (shallow)", glint::make_quartic_groove(0.05), glint::scratch_fresnel::iron(), "iron"},
        {"ramp 30 deg", glint::make_ramp_profile(30 * deg), glint::scratch_fresnel::iron(), "iron"},
        {"bulged (periodic, 9 points)", glint::make_tabulated_profile({0, 1, 2, 3, 4, 5, 6, 7, 8}, {0.1, -0.2, -0.6, -0.8, -0.7, -0.4, -0.3, 0.0, 0.1}),
         glint::scratch_fresnel::iron(), "iron"},
    };
    for (const auto& c : cases) {
        glint::scratch_table_options o;
        const double all = build_ms(c.p, c.f, o, 3);
        o.threads = 1;
        const double one = build_ms(c.p, c.f, o, 1);
        o.threads = 0;
        const auto t = glint::build_scratch_table(c.p, c.f, o);
        md << "| " << c.name << " | " << c.fname << " | " << fmt(all, "%.0f") << " | " << fmt(one, "%.0f") << " | " << fmt(t.lost_fraction(), "%.1e") << " | "
           << t.max_bounces_seen() << " |\n";
        out.csv_rows += "scratch table build," + std::string(c.name) + " " + c.fname + ",double,lost fraction," + fmt(t.lost_fraction()) + "," + fmt(all * 1e6) + ",,\n";
    }

    // 2. Noise against rays per row (M = 64, steep quartic, mirror): relative L1 of rho_m against
    // 1e6 rays per row, and the time.
    md << "\nTable noise against rays per row (M = 64, steep quartic, mirror; relative L1 of rho_m, mass-weighted, against 1e6 rays per row):\n\n"
          "| rays per row | build ms | relative L1 |\n|---|---|---|\n";
    {
        glint::scratch_table_options o;
        o.resolution = 64, o.rays_per_row = 1000000, o.seed = 99;
        const auto profile = glint::make_quartic_groove(0.5);
        const auto ref = glint::build_scratch_table(profile, glint::scratch_fresnel::mirror(), o);
        for (int n : {1000, 10000, 100000}) {
            o.rays_per_row = n, o.seed = 1;
            const double ms = build_ms(profile, glint::scratch_fresnel::mirror(), o, 1);
            const double e = table_l1(glint::build_scratch_table(profile, glint::scratch_fresnel::mirror(), o), ref);
            md << "| " << n << " | " << fmt(ms, "%.1f") << " | " << fmt(e) << " |\n";
            out.csv_rows += "scratch table,M=64 N=" + std::to_string(n) + ",double,relative L1 vs 1e6 rays," + fmt(e) + "," + fmt(ms * 1e6) + ",,\n";
        }
    }

    // 3. Eq. 2 against the 3D tracer.
    md << "\nEq. 2 (three slices and the fitted exponent) against the independent 3D tracer of tests/support/scratch_support.hpp at elevation theta: relative L1 over the "
          "table (mass-weighted), steep quartic with 32 segments, M = 32, 100,000 rays per row on both sides. Eq. 2 is exact at 0 and 60 degrees up to clamped "
          "exponents (iron's non-monotonic Fresnel), so those columns are the noise floor.\n\n"
          "| Fresnel | 0 | 15 | 30 | 45 | 60 | 75 |\n|---|---|---|---|---|---|---|\n";
    {
        const auto profile = glint::make_quartic_groove(0.5, 32);
        for (const auto& m : glint_test::eq2_models()) {
            glint::scratch_table_options o;
            o.resolution = 32, o.rays_per_row = 100000;
            const auto t = glint::build_scratch_table(profile, m.f, o);
            md << "| " << m.name;
            for (double th : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0}) {
                const double e = glint_test::eq2_error(t, glint_test::trace_table(profile, m.f, 32, 100000, th * deg), th * deg);
                md << " | " << fmt(e);
                out.csv_rows += "scratch Eq. 2," + std::string(m.name) + " theta=" + fmt(th) + ",double,relative L1 vs 3D tracer," + fmt(e) + ",,,\n";
            }
            md << " |\n";
        }
    }

    // 4. Memory and per-call costs (float, one thread).
    glint::scratch_table_options o;
    const auto table = glint::build_scratch_table(glint::make_quartic_groove(0.5), glint::scratch_fresnel::iron(), o);
    glint::scratch_distribution scratched;
    scratched.layers = 32, scratched.spread_deg = 360, scratched.length = 0.1, scratched.width = 2e-4, scratched.density = 0.05;
    const auto mat32 = glint::scratch_material::build(table, scratched);
    md << "\nMemory: the 256^2 table " << fmt(static_cast<double>(table.memory_bytes()) / 1e6, "%.2f") << " MB (1 + M + 2 M^2 vec4 of float: rho_m, rho_0 RGB, gamma "
       << "RGB, the CDF, row albedos; RGB16: 1.5 MB with one channel each), 32 bytes per layer, the coverage pyramid "
       << fmt(static_cast<double>(mat32.coverage_bytes()) / 1e6, "%.2f") << " MB (64 cells x 8 texels a side, float, shared by all layers).\n\n";
    const auto tv = table.view<float>();
    const auto f = glint::make_scratch_frame<float>(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    const int n = 4096;
    std::vector<glm::vec3> wo(n), wl(n);
    std::vector<glm::vec2> x(n), u(n);
    for (int i = 0; i < n; ++i) {
        const auto k = static_cast<std::uint32_t>(i);
        const float th = 0.8f * (unit(k, 1) - 0.5f), ph = 1.2f * (unit(k, 2) - 0.5f);
        wo[static_cast<std::size_t>(i)] = glint::from_cone<float>(f, glm::vec2(th, ph));
        wl[static_cast<std::size_t>(i)] = glint::from_cone<float>(f, glm::vec2(-th + 0.03f * (unit(k, 3) - 0.5f), 1.2f * (unit(k, 4) - 0.5f)));
        x[static_cast<std::size_t>(i)] = glm::vec2(unit(k, 5), unit(k, 6));
        u[static_cast<std::size_t>(i)] = glm::vec2(unit(k, 7), unit(k, 8));
    }
    const auto at = [&](std::size_t i) { return i & static_cast<std::size_t>(n - 1); };
    add_inline("scratch rho", [&](std::size_t i) {
        const auto c = glint::to_cone<float>(f, wo[at(i)]);
        benchmark::DoNotOptimize(tv.rho(launder(c.x), c.y, u[at(i)].x * 3 - 1.5f));
    }, min_time);
    add_inline("scratch sample", [&](std::size_t i) { benchmark::DoNotOptimize(tv.sample(f, wo[at(i)], launder(u[at(i)].x), u[at(i)].y)); }, min_time);
    add_inline("scratch light", [&](std::size_t i) { benchmark::DoNotOptimize(tv.light_radiance(f, wo[at(i)], wl[at(i)], launder(1.0f))); }, min_time);
    add_inline("scratch cull", [&](std::size_t i) { benchmark::DoNotOptimize(glint::scratch_light_reaches<float>(f, wo[at(i)], wl[at(i)], launder(0.0174533f))); }, min_time);
    const auto mv = mat32.view<float>();
    const glm::vec2 fa(1e-3f, 0), fb(0, 1e-3f);
    add_inline("scratch alpha pyramid", [&](std::size_t i) { benchmark::DoNotOptimize(mv.alpha(static_cast<int>(i & 31), x[at(i)], fa * launder(1.0f), fb)); }, min_time);
    add_inline("scratch alpha 16 points", [&](std::size_t i) {
        benchmark::DoNotOptimize(glint::scratch_alpha_footprint<float>(mat32.layers<float>()[i & 31], x[at(i)], fa * launder(1.0f), fb, u[at(i)]));
    }, min_time);
    // 5. The SV-BRDF against layer count, point light, footprints of 1e-3 (about 5 scratch
    // widths across), light 0.03 rad off the views' cones, next to the base BRDF alone.
    const auto base = [&](const glm::vec3& a, const glm::vec3& b) {
        const glm::vec3 m = glm::normalize(a + b);
        return glint::ndf_value(glint::ndf::ggx, m, glm::vec2(0.03f)) * glint::smith_g2(glint::ndf::ggx, a, b, m, glm::vec2(0.03f)) *
               glint::fresnel_conductor(2.91f, 3.09f, glm::dot(a, m)) / (4 * b.z);
    };
    add_inline("scratch base BRDF", [&](std::size_t i) { benchmark::DoNotOptimize(base(wl[at(i)], wo[at(i)] * launder(1.0f))); }, min_time);
    struct layered {
        std::string name;
        glint::scratch_material m;
    };
    std::vector<layered> mats;
    for (const char* pattern : {"brushed", "scratched"})
        for (int K : {0, 1, 6, 16, 32}) {
            glint::scratch_distribution d;
            const bool brushed = std::string(pattern) == "brushed";
            d.layers = K, d.spread_deg = brushed ? 5 : 360, d.length = 0.1, d.width = brushed ? 5e-4 : 2e-4, d.density = brushed ? 0.16 : 0.05;
            mats.push_back({std::string(pattern) + " " + std::to_string(K), glint::scratch_material::build(table, d)});
        }
    std::vector<double> shaded(mats.size(), 0.0);
    for (std::size_t k = 0; k < mats.size(); ++k) {
        const auto v = mats[k].m.view<float>();
        for (int i = 0; i < n; ++i) shaded[k] += v.light(f, x[static_cast<std::size_t>(i)], fa, fb, wo[static_cast<std::size_t>(i)], wl[static_cast<std::size_t>(i)], 1.0f).layers_shaded;
        shaded[k] /= n;
        add_inline("scratch svbrdf " + mats[k].name, [v, &f, &x, &wo, &wl, fa, fb, at, &base](std::size_t i) {
            const auto lit = v.light(f, x[at(i)], fa * launder(1.0f), fb, wo[at(i)], wl[at(i)], 1.0f);
            benchmark::DoNotOptimize(lit.radiance.x + lit.base_weight * base(wl[at(i)], wo[at(i)]));
        }, min_time);
    }
    const auto ns = run_all();
    md << "Per call, float, one thread (ns): Eq. 2 read (linear) " << fmt(ns.at("scratch rho")) << "; Eq. 5 sample " << fmt(ns.at("scratch sample")) << "; Eq. 6 point light, 4 samples, light within 0.9 degrees of the cone "
       << fmt(ns.at("scratch light")) << "; the light cull " << fmt(ns.at("scratch cull")) << "; a layer's area from the pyramid " << fmt(ns.at("scratch alpha pyramid"))
       << " (the exact 16-point estimate: " << fmt(ns.at("scratch alpha 16 points")) << ").\n\n";
    md << "The SV-BRDF under a point light against the number of layers (per shading: every layer's area from the pyramid, Eq. 4, then Eq. 6 for the layers that pass "
          "the area and light culls, plus the base GGX BRDF), float, one thread; RGB16 Table 2 (GPU, 64 spp per layer): brushed 1 -> 32 layers 21x, scratched 8x.\n\n"
          "| pattern | layers | ns per shading | x base BRDF alone | x 1 layer | layers shaded (mean) |\n|---|---|---|---|---|---|\n";
    const double nb = ns.at("scratch base BRDF");
    for (std::size_t k = 0; k < mats.size(); ++k) {
        const double t = ns.at("scratch svbrdf " + mats[k].name);
        const std::size_t one = k - (k % 5) + 1;
        md << "| " << mats[k].name.substr(0, mats[k].name.find(' ')) << " | " << mats[k].name.substr(mats[k].name.find(' ') + 1) << " | " << fmt(t) << " | " << fmt(t / nb, "%.2f") << " | "
           << fmt(t / ns.at("scratch svbrdf " + mats[one].name), "%.2f") << " | " << fmt(shaded[k], "%.2f") << " |\n";
        out.csv_rows += "scratch svbrdf," + mats[k].name + " layers,float,,," + fmt(t) + "," + fmt(t / nb) + ",base GGX BRDF\n";
    }
    md << "\n(base GGX BRDF alone: " << fmt(nb) << " ns.)\n\n";
    out.markdown = md.str();
    out.files["scratch.md"] = "# Scratches: measured\n\nGenerated by `glint_report --docs docs` (bench/report_scratch.cpp); do not edit by hand.\n\n" + out.markdown;
    return out;
}

}  // namespace glint_report
