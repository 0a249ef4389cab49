// The glint NDF on the grid, statistically. Unbiasedness: over independent grid seeds the mean
// of R / E[R] (the glint BRDF over the smooth one) is 1, for point, sun, sphere and rectangle
// lights, roughness sqrt(alpha) in {0.1, 0.5, 0.7}, ln densities -4..6, footprints from 0.05 to
// 1e4 uv units, aspect ratios 1, 5.7 (between levels) and 16, and KK25 Fig. 13's case. Each z-test asserts its
// resolution (a 10% bias detected with probability 0.9); family-wise alpha 0.01, Sidak. Where
// the footprint holds so many microfacets that the standard error falls below float rounding,
// a deviation must also exceed 1e-5 (about 80 float ulps: R sums up to 48 rounded terms).
// Every 4th test of the same grid with the published gated sampler (DB23) and KK25's
// dual-gated one must reject somewhere. KK25 Fig. 14:
// a sun on a low-roughness plane seen at a grazing angle, no banding across LODs and
// convergence to the smooth result as density grows. The GGX visible-normal sampler against
// its density (chi-square), with power against a 5% roughness error.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glint/grid.hpp>
#include <glint/testing/stats.hpp>

#include "../support/grid_scene.hpp"

namespace gt = glint::testing;
using glint_test::grid_scene;
using glint_test::light_kind;

namespace {

std::vector<grid_scene> unbiasedness_grid(glint::binomial_variant v) {
    std::vector<grid_scene> scenes;
    for (light_kind k : {light_kind::point, light_kind::sun, light_kind::sphere, light_kind::rect})
        for (float sqrt_alpha : {0.1f, 0.5f, 0.7f})
            for (float logd : {-4.0f, -2.0f, 0.0f, 2.0f, 4.0f, 6.0f})
                for (float fp : {0.05f, 1.0f, 30.0f, 1e4f})
                    for (float ratio : {1.0f, 5.7f, 16.0f}) {
                        grid_scene s;
                        s.kind = k, s.alpha = sqrt_alpha * sqrt_alpha, s.log_density = logd, s.footprint = fp, s.ratio = ratio, s.variant = v;
                        s.prepare();
                        // The resolvable part of the grid: at least 0.02 reflecting microfacets
                        // expected per footprint (fewer: the mean needs over 1e5 samples per point).
                        if (s.expected_glints() >= 0.02) scenes.push_back(s);
                    }
    // KK25 Fig. 13: sqrt(alpha) = 0.2 under a large area light, densities e^-4, 1, e^4.
    for (float logd : {-4.0f, 0.0f, 4.0f}) {
        grid_scene s;
        s.kind = light_kind::rect, s.light_size = 4.0f, s.alpha = 0.04f, s.log_density = logd, s.footprint = 3.0f, s.variant = v;
        s.prepare();
        scenes.push_back(s);
    }
    return scenes;
}

// Samples so that the standard error is about 1.7% of the mean: n ~ (1 + 1 / glints) / 0.017^2
// (the relative variance of R is at most about 1 / glints, plus the interpolation's share).
std::size_t samples_for(const grid_scene& s) {
    const double n = (1.0 + 1.0 / s.expected_glints()) / (0.017 * 0.017);
    return static_cast<std::size_t>(std::min(std::max(n, 2000.0), 100000.0));
}

constexpr double float_allowance = 1e-5;

bool rejects(const gt::mean_test_result& t, double alpha_each) {
    return t.rejects(alpha_each) && std::fabs(t.mean - t.expected) > float_allowance;
}

struct grid_test_result {
    gt::mean_test_result test;
    grid_scene scene;
};

// How a sample's estimate is made: on the footprint's four lattice points; on one drawn per sample
// (glint::grid_pixel_setup with a lattice_u); or, a deliberately wrong variant of that, on the drawn
// point with its vertices' shares left at w_L instead of 1 (E[R] scaled by sum_L w_L^2).
enum class lattice_mode { all, one, one_unscaled };

glint::grid_estimate<float> estimate_with(const grid_scene& s, lattice_mode mode, std::uint32_t seed, glm::vec2 uv, float lattice_u) {
    if (mode == lattice_mode::all) return s.estimate(seed, uv);
    using K = glint::detail::glsl::kernels<float>;
    glm::vec2 dx, dy;
    s.derivatives(dx, dy);
    const auto g = s.params(seed);
    auto px = glint::grid_pixel_setup(uv, dx, dy, g, lattice_u);
    if (mode == lattice_mode::one_unscaled) {
        const auto k = glint::detail::to_kernel(g);
        K::glint_grid_pixel_vertices(px, k);
        const auto lat = K::glint_footprint_lattice(px.f, k.lod_scale);
        const float w = lat.weight[K::glint_lattice_choice(lat, px.lattice_u)];
        for (int i = 0; i < px.v.count; ++i) px.v.share[i] *= w;  // the skip test's bound, made for share 1, stays safe
    }
    return glint::grid_sample(px, g, s.light);
}

// The grid's tests, or every stride-th of them (each with the seeds it has in the whole grid).
std::vector<grid_test_result> run_grid(glint::binomial_variant v, double alpha_each, std::size_t& total_samples, std::uint32_t stride = 1,
                                       lattice_mode mode = lattice_mode::all) {
    std::vector<grid_test_result> out;
    std::uint32_t salt = 0;
    for (const grid_scene& s : unbiasedness_grid(v)) {
        ++salt;
        if ((salt - 1) % stride != 0) continue;
        gt::running_moments m;
        const std::size_t n = samples_for(s);
        for (std::size_t i = 0; i < n; ++i) {
            const glm::uvec3 h = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), salt, 0x51u));
            const glm::vec2 uv(glint::unit_from_bits<float>(h.x) * 97.0f * s.footprint, glint::unit_from_bits<float>(h.y) * 89.0f * s.footprint);
            const float lattice_u = glint::unit_from_bits<float>(glint::pcg3d(h).x);
            m.add(static_cast<double>(glint::modulation(estimate_with(s, mode, h.z, uv, lattice_u))));
        }
        total_samples += n;
        out.push_back({gt::mean_test(m, 1.0, alpha_each), s});
    }
    return out;
}

}  // namespace

TEST_CASE("grid: the mean-preserving glint NDF is unbiased for every light, roughness, density and footprint") {
    const std::size_t tests = unbiasedness_grid(glint::binomial_variant::unbiased).size();
    const double alpha_each = gt::sidak_alpha(0.01, static_cast<int>(tests));
    std::size_t samples = 0;
    const auto results = run_grid(glint::binomial_variant::unbiased, alpha_each, samples);
    int rejected = 0, unresolved = 0;
    double worst_bias = 0, worst_resolution = 0;
    std::string worst;
    for (const auto& r : results) {
        rejected += rejects(r.test, alpha_each);
        unresolved += !r.test.resolves(0.1);
        worst_resolution = std::max(worst_resolution, r.test.resolution);
        if (std::fabs(r.test.mean - 1) > worst_bias) worst_bias = std::fabs(r.test.mean - 1), worst = r.scene.describe();
        if (rejects(r.test, alpha_each) || !r.test.resolves(0.1))
            MESSAGE(r.scene.describe() << ": mean " << r.test.mean << " +- " << r.test.standard_error);
    }
    MESSAGE(results.size() << " configurations, " << samples << " samples, alpha per test " << alpha_each << ": " << rejected
                           << " rejected; largest |mean - 1| " << worst_bias << " (" << worst << "), every test resolves "
                           << worst_resolution);
    CHECK(results.size() > 300);
    CHECK(unresolved == 0);
    CHECK(rejected == 0);
}

// Power: every 4th test of the grid, at the whole grid's level per test. (The whole grid took 15 s
// here and 222 s under the sanitizers, and rejected 289 of 516 tests for DB23 and 255 for Alg. 1;
// a quarter shows the same at a quarter of the cost.)
TEST_CASE("grid: the same test rejects the published gated sampler (DB23) and KK25's dual-gated one") {
    for (glint::binomial_variant v : {glint::binomial_variant::gated_db23, glint::binomial_variant::dual_gated}) {
        const std::size_t tests = unbiasedness_grid(v).size();
        const double alpha_each = gt::sidak_alpha(0.01, static_cast<int>(tests));
        std::size_t samples = 0;
        const auto results = run_grid(v, alpha_each, samples, 4);
        int rejected = 0;
        const grid_test_result* worst = nullptr;
        for (const auto& r : results) {
            rejected += rejects(r.test, alpha_each);
            if (!worst || std::fabs(r.test.mean - 1) > std::fabs(worst->test.mean - 1)) worst = &r;
        }
        REQUIRE(worst);
        MESSAGE(std::string(glint::name(v)) << ": " << rejected << " of " << results.size() << " configurations (every 4th of " << tests
                                       << ") rejected; worst " << worst->scene.describe()
                               << ": mean " << worst->test.mean << " +- " << worst->test.standard_error);
        CHECK(rejected > 0);
    }
}

// One lattice point per pixel, drawn with probability w_L from a uniform per sample: every 4th test
// of the grid (its seeds and sample counts, each test resolving a 10% bias with probability 0.9, at
// the whole grid's alpha per test, family-wise 0.01 over these by Sidak), unbiased like the four
// points together; the same tests reject the variant that forgets to give the drawn point's
// vertices the whole footprint (share w_L instead of 1).
TEST_CASE("grid: one lattice point per pixel keeps the mean on every 4th test of the grid, and a variant with shares w_L is rejected") {
    const auto v = glint::binomial_variant::unbiased;
    const std::size_t tests = unbiasedness_grid(v).size();
    std::size_t samples = 0, wrong_samples = 0;
    const double alpha_each = gt::sidak_alpha(0.01, static_cast<int>((tests + 3) / 4));
    const auto results = run_grid(v, alpha_each, samples, 4, lattice_mode::one);
    const auto wrong = run_grid(v, alpha_each, wrong_samples, 4, lattice_mode::one_unscaled);
    int rejected = 0, unresolved = 0, wrong_rejected = 0;
    double worst_bias = 0;
    std::string worst;
    for (const auto& r : results) {
        rejected += rejects(r.test, alpha_each);
        unresolved += !r.test.resolves(0.1);
        if (std::fabs(r.test.mean - 1) > worst_bias) worst_bias = std::fabs(r.test.mean - 1), worst = r.scene.describe();
        if (rejects(r.test, alpha_each)) MESSAGE(r.scene.describe() << ": mean " << r.test.mean << " +- " << r.test.standard_error);
    }
    for (const auto& r : wrong) wrong_rejected += rejects(r.test, alpha_each);
    MESSAGE(results.size() << " configurations (every 4th of " << tests << "), " << samples << " samples, alpha per test "
                           << alpha_each << ": " << rejected << " rejected; largest |mean - 1| " << worst_bias << " (" << worst
                           << "); shares w_L: " << wrong_rejected << " of " << wrong.size() << " rejected");
    CHECK(results.size() > 75);
    CHECK(unresolved == 0);
    CHECK(rejected == 0);
    CHECK(wrong_rejected > static_cast<int>(wrong.size()) / 4);
}

namespace {

struct fig14_result {
    int banded = 0;     // LOD-fraction bins whose mean differs from 1
    double rms = 0;     // per-pixel rms of glint / smooth - 1
    std::string means;  // by LOD fraction
};

// KK25 Fig. 14's scene. A camera 1 unit above the plane looks along it; pixel row k sees the
// plane at distance d, footprints grow continuously with d (so the LOD passes through every
// fraction) and stretch (ratio up to 16). uv = world position x 50. Neighbouring pixels share
// grid vertices, so the test statistic is the mean over the pixels of one realisation (seed);
// independent realisations give its standard error.
fig14_result fig14(glint::binomial_variant v, float logd, int realisations, double alpha_each) {
    const float alpha = 0.01f;
    const int bins = 8;  // by the LOD's fractional part
    std::vector<gt::running_moments> by_lod(bins);  // over realisations
    double sq = 0;
    std::size_t count = 0;
    for (int r = 0; r < realisations; ++r) {
        std::vector<double> sum(bins, 0.0), n(bins, 0.0);
        for (int row = 0; row < 200; ++row) {
            const float dist = 2.0f * std::pow(1.02f, static_cast<float>(row));  // 2 .. 103
            const float pixel = 1e-3f;                                             // radians per pixel
            const float along = pixel * dist * dist;                               // footprint along the view (grazing)
            const float across = pixel * dist;
            const glm::vec3 wo = glm::normalize(glm::vec3(-dist, 0.0f, 1.0f));
            // The sun in the lobe: the mirror of wo about the normal at standardized slope (0.3, 0.2).
            const glm::vec3 mn = glm::normalize(glm::vec3(0.3f * alpha, 0.2f * alpha, 1.0f));
            const glm::vec3 sun_dir = 2 * glm::dot(wo, mn) * mn - wo;
            const glm::vec2 a(alpha);
            const float dh = glint::total_area(glint::ndf::ggx, a);
            const float p = std::min(1.0f, glint::integrated_ndf_cone(glint::ndf::ggx, wo, a, sun_dir, 0.00454f) / dh);
            const auto light = glint::grid_extended_light(p, glm::normalize(wo + sun_dir));
            const glm::vec2 dx(0.0f, across * 50.0f), dy(along * 50.0f, 0.0f);
            const float minor = std::max(across * 50.0f, along * 50.0f / 16.0f);
            const float lod = std::log2(minor * 1.5f);
            const std::size_t bin = static_cast<std::size_t>(std::min(bins - 1, static_cast<int>((lod - std::floor(lod)) * bins)));
            for (int col = 0; col < 10; ++col) {
                glint::grid_params<float> g;
                g.log_density = logd;
                g.smooth_tolerance = 0;
                g.variant = v;
                g.seed = static_cast<std::uint32_t>(r) * 2654435761u;
                const glm::vec2 uv(dist * 50.0f, static_cast<float>(col) * across * 50.0f);
                const double m = static_cast<double>(glint::modulation(glint::grid_sample(uv, dx, dy, g, light)));
                sum[bin] += m, n[bin] += 1;
                sq += (m - 1) * (m - 1);
                ++count;
            }
        }
        for (std::size_t b = 0; b < static_cast<std::size_t>(bins); ++b)
            if (n[b] > 0) by_lod[b].add(sum[b] / n[b]);
    }
    fig14_result out;
    out.rms = std::sqrt(sq / static_cast<double>(count));
    for (const auto& b : by_lod) {
        const auto t = gt::mean_test(b, 1.0, alpha_each);
        out.banded += t.rejects(alpha_each);
        out.means += " " + std::to_string(t.mean);
    }
    return out;
}

}  // namespace

TEST_CASE("grid: KK25 Fig. 14, a sun on a low-roughness plane at a grazing angle: no banding across LODs, convergence with density") {
    // 120 realisations, or 600 at ln density -4, where a bin of one realisation holds about
    // 0.25 glints and its mean needs ~150 of them to be near normal. 8 bins x 5 densities, plus
    // the 8 bins of the published sampler below: Sidak over 48.
    const double alpha_each = gt::sidak_alpha(0.01, 48);
    std::vector<double> rms_by_density;
    for (float logd : {-4.0f, -2.0f, 0.0f, 2.0f, 4.0f}) {
        const auto r = fig14(glint::binomial_variant::unbiased, logd, logd < -3 ? 600 : 120, alpha_each);
        MESSAGE("ln density " << logd << ": rms |glint / smooth - 1| per pixel " << r.rms << "; means by LOD fraction:" << r.means);
        CHECK(r.banded == 0);
        rms_by_density.push_back(r.rms);
    }
    // Convergence: the per-pixel deviation falls with density, about as density^-1/2 once glints
    // are not rare (e^-2 from ln density 0 to 4; asserted: below a quarter).
    for (std::size_t i = 1; i < rms_by_density.size(); ++i) CHECK(rms_by_density[i] < rms_by_density[i - 1]);
    CHECK(rms_by_density[4] < 0.25 * rms_by_density[2]);
    // Power: DB23's gated sampler (integer N, floored) bands where the vertices' shares drop below 1.
    const auto db23 = fig14(glint::binomial_variant::gated_db23, 0.0f, 120, alpha_each);
    MESSAGE("DB23 at ln density 0: means by LOD fraction:" << db23.means);
    CHECK(db23.banded > 0);
}

TEST_CASE("GGX visible normals: samples follow the visible NDF (chi-square), and a 5% roughness error is caught") {
    const glm::dvec2 a(0.3, 0.15);
    const glm::dvec3 wo = glm::normalize(glm::dvec3(0.6, 0.2, 0.5));
    // Cells: 20 bins of cos(theta_m) x 16 of phi_m; probabilities by 2D midpoint quadrature
    // (64 x 64 per cell) of D_wo.
    const int nt = 20, np = 16, sub = 64;
    auto cell_probabilities = [&](glm::dvec2 alpha) {
        std::vector<double> p(static_cast<std::size_t>(nt * np));
        double total = 0;
        for (int i = 0; i < nt; ++i)
            for (int j = 0; j < np; ++j) {
                double s = 0;
                for (int u = 0; u < sub; ++u)
                    for (int v = 0; v < sub; ++v) {
                        const double c = (i + (u + 0.5) / sub) / nt, phi = 2 * M_PI * (j + (v + 0.5) / sub) / np;
                        const double st = std::sqrt(1 - c * c);
                        s += glint::vndf(glint::ndf::ggx, wo, glm::dvec3(st * std::cos(phi), st * std::sin(phi), c), alpha);
                    }
                p[static_cast<std::size_t>(i * np + j)] = s / (sub * sub) * (1.0 / nt) * (2 * M_PI / np);
                total += p[static_cast<std::size_t>(i * np + j)];
            }
        for (double& x : p) x /= total;  // removes the quadrature's normalisation error (< 1e-4)
        return p;
    };
    const std::size_t n = 400000;
    std::vector<double> counts(static_cast<std::size_t>(nt * np), 0.0);
    for (std::size_t k = 0; k < n; ++k) {
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(k), 0x77u, 3u));
        const glm::vec3 m = glint::sample_vndf_ggx(glm::vec3(wo), glm::vec2(a), glint::unit_from_bits<float>(h.x), glint::unit_from_bits<float>(h.y));
        const int i = std::min(nt - 1, static_cast<int>(m.z * nt));
        double phi = std::atan2(static_cast<double>(m.y), static_cast<double>(m.x));
        if (phi < 0) phi += 2 * M_PI;
        const int j = std::min(np - 1, static_cast<int>(phi / (2 * M_PI) * np));
        counts[static_cast<std::size_t>(i * np + j)] += 1;
    }
    const double alpha_each = gt::sidak_alpha(0.01, 2);
    const auto right = gt::chi_square(counts, cell_probabilities(a));
    const auto wrong = gt::chi_square(counts, cell_probabilities(a * 1.05));
    MESSAGE(n << " samples, " << right.cells << " cells: p = " << right.p_value << "; against alpha x 1.05: p = " << wrong.p_value);
    CHECK_FALSE(right.rejects(alpha_each));
    CHECK(wrong.rejects(alpha_each));
}
