// The statistics kit itself: its special functions against Boost.Math, its bookkeeping, and
// its power: each test must reject a deliberately wrong sampler of b(N, p) (mean +1%,
// variance +5%, a gate off by one trial) while accepting the exact sampler.
//
// Samplers draw from Boost's exact binomial by inversion with counter-based uniforms (fixed
// seeds). Significance: 0.01 family-wise over the 4 acceptance checks in this file (Sidak).
#include <doctest/doctest.h>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <vector>

#include <glint/core.hpp>
#include <glint/testing/directional.hpp>
#include <glint/testing/stats.hpp>

namespace gt = glint::testing;

namespace {

const double alpha = gt::sidak_alpha(0.01, 4);

// b(N, p) by inversion of Boost's exact CDF (small N only: linear search from 0).
struct exact_binomial {
    int N;
    double p;
    std::vector<double> cdf;
    exact_binomial(int n, double q) : N(n), p(q) {
        boost::math::binomial_distribution<double> b(N, p);
        for (int k = 0; k <= N; ++k) cdf.push_back(boost::math::cdf(b, k));
        cdf.back() = 1.0;
    }
    int operator()(double u) const {
        int k = 0;
        while (cdf[static_cast<std::size_t>(k)] < u) ++k;
        return k;
    }
    double cdf_at(double x) const {
        if (x < 0) return 0;
        if (x >= N) return 1;
        return cdf[static_cast<std::size_t>(std::floor(x))];
    }
};

double uniform(std::uint32_t i, std::uint32_t stream) {
    return glint::open_unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, stream, 0x5eedu)).x);
}

// Draws `count` samples from `sampler(i)`.
template <class F>
std::vector<double> draw(std::size_t count, F sampler) {
    std::vector<double> v(count);
    for (std::size_t i = 0; i < count; ++i) v[i] = sampler(static_cast<std::uint32_t>(i));
    return v;
}

// Histogram of integer samples on 0..N.
std::vector<double> histogram(const std::vector<double>& s, int N) {
    std::vector<double> h(static_cast<std::size_t>(N) + 1);
    for (double x : s) h[static_cast<std::size_t>(x)] += 1;
    return h;
}

std::vector<double> pmf(int N, double p) {
    boost::math::binomial_distribution<double> b(N, p);
    std::vector<double> v;
    for (int k = 0; k <= N; ++k) v.push_back(boost::math::pdf(b, k));
    double total = 0;
    for (double x : v) total += x;
    for (double& x : v) x /= total;
    return v;
}

}  // namespace

TEST_CASE("gamma_q and the chi-square tail agree with Boost.Math to 1e-12 relative") {
    for (double a : {0.5, 1.0, 2.5, 10.0, 100.0, 1000.0})
        for (double x : {1e-3, 0.5, 1.0, 3.0, 10.0, 50.0, 150.0, 900.0, 1100.0}) {
            const double ours = gt::gamma_q(a, x), boost_q = boost::math::gamma_q(a, x);
            CAPTURE(a);
            CAPTURE(x);
            if (boost_q > 1e-280) CHECK(std::fabs(ours - boost_q) <= 1e-12 * boost_q + 1e-300);
        }
    boost::math::chi_squared c(7);
    CHECK(gt::chi_square_survival(14.07, 7) == doctest::Approx(boost::math::cdf(boost::math::complement(c, 14.07))).epsilon(1e-12));
}

TEST_CASE("Kolmogorov tail and normal quantile at known points") {
    // P(K > 1.358) = 0.05 and P(K > 1.628) = 0.01 (Kolmogorov's table).
    CHECK(gt::kolmogorov_survival(1.358) == doctest::Approx(0.05).epsilon(0.01));
    CHECK(gt::kolmogorov_survival(1.628) == doctest::Approx(0.01).epsilon(0.01));
    CHECK(gt::normal_upper_quantile(0.025) == doctest::Approx(1.959964).epsilon(1e-6));
    CHECK(gt::sidak_alpha(0.01, 1) == doctest::Approx(0.01));
    CHECK(gt::sidak_alpha(0.05, 10) == doctest::Approx(1 - std::pow(0.95, 0.1)).epsilon(1e-12));
}

TEST_CASE("chi_square pools low-expectation cells and rejects bad input by name") {
    // Expectations 0.1, 0.1, ..., pooled into cells of at least 5.
    std::vector<double> p(100, 0.01), o(100, 1.0);
    auto r = gt::chi_square(o, p, 5.0);
    CHECK(r.cells == 20u);
    CHECK(r.degrees_of_freedom == 19);
    CHECK(r.statistic == doctest::Approx(0.0));
    CHECK_THROWS_WITH_AS(gt::chi_square({1, 2}, {0.5, 0.6}), doctest::Contains("sum to 1.1"), std::invalid_argument);
    CHECK_THROWS_AS(gt::chi_square({1, 2, 3}, {0.5, 0.5}), std::invalid_argument);
    // An observation in a cell of probability 0 is an immediate rejection.
    auto impossible = gt::chi_square({0, 10, 10, 1}, {0.0, 0.5, 0.5, 0.0}, 1.0);
    CHECK(impossible.p_value == 0.0);
}

TEST_CASE("wasserstein1 of samples and of CDFs") {
    CHECK(gt::wasserstein1(std::vector<double>{0, 1, 2}, std::vector<double>{1, 2, 3}) == doctest::Approx(1.0));
    CHECK(gt::wasserstein1(std::vector<double>{0, 0}, std::vector<double>{0, 0, 0, 3}) == doctest::Approx(0.75));
    auto step0 = [](double x) { return x >= 0 ? 1.0 : 0.0; };
    auto step2 = [](double x) { return x >= 2 ? 1.0 : 0.0; };
    CHECK(gt::wasserstein1(step0, step2, -1, 3, 4000) == doctest::Approx(2.0).epsilon(1e-3));
}

// b(40, 0.3): mean 12, variance 8.4. 2e5 samples per test.
// - chi-square over 41 cells (pooled): resolves the +5% variance sampler (tested below);
// - z-test: standard error sqrt(8.4 / 2e5) = 0.0065; resolves 1% of the mean (0.12) with
//   power 0.9 at alpha (resolution asserted);
// - KS at the half-integers: resolves the gate off by one trial (P(0) changes by 43%).
TEST_CASE("the exact sampler passes every test") {
    const int N = 40;
    const double p = 0.3;
    exact_binomial b(N, p);
    const std::size_t n = 200000;
    auto s = draw(n, [&](std::uint32_t i) { return b(uniform(i, 1)); });
    auto chi = gt::chi_square(histogram(s, N), pmf(N, p));
    MESSAGE("chi-square p " << chi.p_value << " over " << chi.cells << " cells");
    CHECK(!chi.rejects(alpha));
    gt::running_moments m;
    for (double x : s) m.add(x);
    auto z = gt::mean_test(m, N * p, alpha);
    REQUIRE(z.resolves(0.01 * N * p));
    CHECK(!z.rejects(alpha));
    std::vector<double> half;
    for (int k = 0; k < N; ++k) half.push_back(k + 0.5);
    auto ks = gt::ks_test(s, [&](double x) { return b.cdf_at(x); }, half);
    CHECK(!ks.rejects(alpha));
    // Two samples of the same law are W1-close: W1 / sigma well below 0.05.
    auto s2 = draw(n, [&](std::uint32_t i) { return b(uniform(i, 2)); });
    CHECK(gt::wasserstein1(s, s2) / std::sqrt(8.4) < 0.05);
}

TEST_CASE("mean +1%: the z-test rejects it") {
    const int N = 40;
    exact_binomial wrong(N, 0.3 * 1.01);
    gt::running_moments m;
    for (std::uint32_t i = 0; i < 200000; ++i) m.add(wrong(uniform(i, 3)));
    auto z = gt::mean_test(m, N * 0.3, alpha);
    REQUIRE(z.resolves(0.01 * N * 0.3));
    CHECK(z.rejects(alpha));
}

TEST_CASE("variance +5% at the same mean: the chi-square test rejects it") {
    // Half the samples from b(N, p (1 + d)), half from b(N, p (1 - d)): the mean is unchanged and
    // the variance grows by (N p d)^2 = 0.05 N p (1 - p), so d = sqrt(0.05 (1 - p) / (N p)).
    const int N = 40;
    const double p = 0.3, d = std::sqrt(0.05 * (1 - p) / (N * p));
    exact_binomial hi(N, p * (1 + d)), lo(N, p * (1 - d));
    auto s = draw(200000, [&](std::uint32_t i) { return (i % 2 ? hi : lo)(uniform(i, 4)); });
    gt::running_moments m;
    for (double x : s) m.add(x);
    CHECK(m.variance() / (N * p * (1 - p)) == doctest::Approx(1.05).epsilon(0.02));
    auto chi = gt::chi_square(histogram(s, N), pmf(N, p));
    MESSAGE("chi-square p " << chi.p_value);
    CHECK(chi.rejects(alpha));
}

TEST_CASE("a gate off by one trial: KS at the half-integers rejects it") {
    // A gated sampler whose gate uses P(n >= 1) for N - 1 trials instead of N, otherwise exact
    // given n >= 1. At N = 4, p = 0.3 that moves P(0) from 0.240 to 0.343.
    const int n_small = 4;
    exact_binomial bs(n_small, 0.3);
    const double q0 = bs.cdf[0], q0_wrong = std::pow(0.7, n_small - 1);
    auto t = draw(200000, [&](std::uint32_t i) {
        if (uniform(i, 7) < q0_wrong) return 0.0;
        return static_cast<double>(bs(q0 + (1 - q0) * uniform(i, 8)));
    });
    auto ks_small = gt::ks_test(t, [&](double x) { return bs.cdf_at(x); }, {0.5, 1.5, 2.5, 3.5});
    MESSAGE("KS p " << ks_small.p_value << " (P(0) " << q0 << " vs " << q0_wrong << ")");
    CHECK(ks_small.rejects(alpha));
    auto chi = gt::chi_square(histogram(t, n_small), pmf(n_small, 0.3));
    CHECK(chi.rejects(alpha));
}

TEST_CASE("directional chi-square: precomputed cell probabilities give the same test, and a wrong cell count is an error") {
    // Uniform points on the unit disk (r = sqrt(u)) against the uniform density 1 / pi.
    std::vector<glm::dvec3> points;
    for (std::uint32_t i = 0; i < 4000; ++i) {
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, 0xd15cu, 7u));
        const double r = std::sqrt(glint::unit_from_bits<double>(h.x)), phi = 6.283185307179586 * glint::unit_from_bits<double>(h.y);
        points.emplace_back(r * std::cos(phi), r * std::sin(phi), 0.0);
    }
    const auto density = [](const glm::dvec3&) { return 0.3183098861837907; };
    const auto direct = glint::testing::directional_chi_square(glint::testing::domain::disk, 8, 8, density, points, 0);
    const auto cells = glint::testing::cell_probabilities(glint::testing::domain::disk, 8, 8, density);
    const auto reused = glint::testing::directional_chi_square(glint::testing::domain::disk, 8, 8, cells, points, 0);
    CHECK(reused.chi2.statistic == direct.chi2.statistic);
    CHECK(reused.chi2.p_value == direct.chi2.p_value);
    CHECK_THROWS_AS(glint::testing::directional_chi_square(glint::testing::domain::disk, 8, 9, cells, points, 0), std::invalid_argument);
}
