// Implementation fidelity: each float binomial kernel against its own closed form
// (glint::testing::model_of<float>: the law the float kernel implements, with its parameters and
// gate thresholds as float computes them), where the null hypothesis is exactly true up to the
// 2^-23 resolution of the uniform variates and the normal quantile's 4.6 ulp.
//
// Every variant at every one of the 323 grid points: 20000 samples, a chi-square test over 40
// bins at the model's quantiles (pooled to expectation >= 5) and a KS test at the bin edges.
// Family-wise significance 0.01 over the 2 x 5 x 323 tests, Sidak-corrected. Power: the same
// tests must reject (a) the dual-gated kernel's samples judged against the mean-preserving
// model, at the points where their means differ by more than 5%, and (b) the mean-preserving
// kernel run with p (1 + 1%) at points whose standard deviation resolves a 1% mean shift
// (N p >= 1e4 there: the shift is 1 sd / 1.0 or more).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glint/binomial.hpp>
#include <glint/testing/binomial_metrics.hpp>
#include <glint/testing/stats.hpp>

using glint::binomial_variant;
namespace gt = glint::testing;

namespace {

const binomial_variant all_variants[] = {binomial_variant::ungated, binomial_variant::gated_db23, binomial_variant::gated,
                                         binomial_variant::dual_gated, binomial_variant::unbiased};
constexpr int samples = 20000;
constexpr int bins = 40;
const double alpha = gt::sidak_alpha(0.01, 2 * 5 * 323);

// Bin edges at the model's quantiles j / bins, each moved to the midpoint between two adjacent
// floats: a float sample lies at or below such an edge exactly when the real value it rounds
// from does, so the float rounding of the counts (0.0625 at 1e6) cannot bias the bins, and
// atoms (which sit on floats) fall on the same side in the kernel and in the model.
std::vector<double> quantile_edges(const gt::binomial_model& m, double N) {
    std::vector<double> edges;
    for (int j = 1; j < bins; ++j) {
        const double q = static_cast<double>(j) / bins;
        double lo = -1, hi = std::max(N, 2.0) + 1;
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (m.cdf(mid) >= q ? hi : lo) = mid;
        }
        const float f = static_cast<float>(hi);
        const double e = 0.5 * (static_cast<double>(f) + static_cast<double>(std::nextafter(f, 3e38f)));
        if (edges.empty() || e > edges.back()) edges.push_back(e);
    }
    return edges;
}

struct verdict {
    double chi_p = 1, ks_p = 1;
};

verdict judge(const gt::binomial_model& m, double N, const std::function<float(int)>& draw) {
    const std::vector<double> edges = quantile_edges(m, N);
    std::vector<double> observed(edges.size() + 1, 0.0), probability(edges.size() + 1, 0.0), xs(samples);
    for (int i = 0; i < samples; ++i) {
        const double x = static_cast<double>(draw(i));
        xs[static_cast<std::size_t>(i)] = x;
        observed[static_cast<std::size_t>(std::lower_bound(edges.begin(), edges.end(), x) - edges.begin())] += 1;
    }
    double previous = 0;
    for (std::size_t j = 0; j < edges.size(); ++j) {
        const double f = m.cdf(edges[j]);
        probability[j] = std::max(f - previous, 0.0);
        previous = std::max(previous, f);
    }
    probability.back() = std::max(1 - previous, 0.0);
    double total = 0;
    for (double q : probability) total += q;
    for (double& q : probability) q /= total;
    verdict v;
    v.chi_p = gt::chi_square(observed, probability).p_value;
    v.ks_p = gt::ks_test(xs, [&](double x) { return m.cdf(x); }, edges).p_value;
    return v;
}

bool rejected(const verdict& v) { return v.chi_p < alpha || v.ks_p < alpha; }

float uniform(int i, std::uint32_t point, std::uint32_t stream) {
    return glint::open_unit_from_bits<float>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), point, stream)).x);
}

}  // namespace

TEST_CASE("every float binomial kernel follows its own closed form on the whole grid") {
    int tests = 0, rejections = 0;
    std::uint32_t point = 0;
    for (double N : gt::binomial_grid_n())
        for (double p : gt::binomial_grid_p()) {
            ++point;
            for (binomial_variant v : all_variants) {
                const glint::pow_method method = glint::published_pow_method(v);
                const auto m = gt::model_of<float>(v, N, p, method);
                const float Nf = static_cast<float>(N), pf = static_cast<float>(p);
                const verdict r = judge(m, N, [&](int i) {
                    return glint::binomial(v, Nf, pf, uniform(i, point, 1), uniform(i, point, 2), method).positive;
                });
                tests += 2;
                if (rejected(r)) {
                    ++rejections;
                    CAPTURE(std::string(glint::name(v)));
                    CAPTURE(N);
                    CAPTURE(p);
                    CHECK(r.chi_p >= alpha);
                    CHECK(r.ks_p >= alpha);
                }
            }
        }
    MESSAGE(tests << " tests at alpha " << alpha << " each; " << rejections << " points rejected");
}

TEST_CASE("the fidelity tests reject a wrong law: Alg. 1 judged as the mean-preserving sampler") {
    int tried = 0, caught = 0;
    std::uint32_t point = 1000;
    for (double N : gt::binomial_grid_n())
        for (double p : gt::binomial_grid_p()) {
            ++point;
            const auto ours = gt::model_of<float>(binomial_variant::unbiased, N, p, glint::pow_method::log1p);
            const auto alg1 = gt::model_of<float>(binomial_variant::dual_gated, N, p, glint::pow_method::kk25);
            if (!(N * p > 0) || std::fabs(alg1.mean() / ours.mean() - 1) <= 0.05 || alg1.probability_zero() > 0.999) continue;
            const float Nf = static_cast<float>(N), pf = static_cast<float>(p);
            const verdict r = judge(ours, N, [&](int i) {
                return glint::binomial_dual_gated(Nf, pf, uniform(i, point, 1), uniform(i, point, 2)).positive;
            });
            ++tried;
            caught += rejected(r);
        }
    MESSAGE("caught " << caught << " of " << tried << " points where Alg. 1's mean differs by more than 5%");
    REQUIRE(tried >= 20);
    CHECK(caught == tried);
}

TEST_CASE("the fidelity tests reject a mean shifted by 1% where the sample resolves it") {
    int tried = 0, caught = 0;
    std::uint32_t point = 2000;
    for (double N : gt::binomial_grid_n())
        for (double p : gt::binomial_grid_p()) {
            ++point;
            if (!(N * p >= 1e4 && N * (1 - p) >= 1e4) || p * 1.01 >= 1) continue;
            const auto m = gt::model_of<float>(binomial_variant::unbiased, N, p, glint::pow_method::log1p);
            const float Nf = static_cast<float>(N), pf = static_cast<float>(p * 1.01);
            const verdict r = judge(m, N, [&](int i) {
                return glint::binomial_unbiased(Nf, pf, uniform(i, point, 1), uniform(i, point, 2)).positive;
            });
            ++tried;
            caught += rejected(r);
        }
    MESSAGE("caught " << caught << " of " << tried << " points");
    REQUIRE(tried >= 10);
    CHECK(caught == tried);
}

namespace {

// The randomised-rounding binomial at real N (glint::testing::binomial_exact) as atoms.
gt::binomial_model randomised_rounding(double N, double p) {
    const gt::binomial_exact e(N, p);
    gt::binomial_model m;
    double previous = 0;
    for (double k = 0; k <= std::ceil(N); ++k) {
        const double f = e.cdf(k);
        m.atoms.push_back({k, f - previous});
        previous = f;
    }
    return m;
}

}  // namespace

TEST_CASE("the walk at real N and its blend into the Gaussian middle (N 32 to 40) follow their closed form, and the test sees the randomised-rounding law differ") {
    // 7 N x 6 p, 20000 samples each, the chi-square and KS tests above at family-wise 0.01
    // (Sidak over the 84 tests). Power: the same samples at N = 3.5 judged against the
    // randomised-rounding binomial (support 0..4 against the walk's multiples of 3.5 / 3 and
    // 3.5 / 4) must be rejected wherever p is at least 0.1 (there 0.1 or more of the mass sits on
    // points the other law does not have).
    const double a = gt::sidak_alpha(0.01, 2 * 7 * 6);
    int rejections = 0;
    std::uint32_t point = 3000;
    for (double N : {2.5, 3.5, 7.25, 15.5, 24.5, 33.0, 38.9})
        for (double p : {0.01, 0.1, 0.3, 0.5, 0.7, 0.97}) {
            ++point;
            const auto m = gt::model_of<float>(binomial_variant::unbiased, N, p, glint::pow_method::log1p);
            const float Nf = static_cast<float>(N), pf = static_cast<float>(p);
            auto draw = [&](int i) { return glint::binomial_unbiased(Nf, pf, uniform(i, point, 1), uniform(i, point, 2)).positive; };
            const verdict r = judge(m, N, draw);
            if (r.chi_p < a || r.ks_p < a) {
                ++rejections;
                CAPTURE(N);
                CAPTURE(p);
                CHECK(r.chi_p >= a);
                CHECK(r.ks_p >= a);
            }
            if (N == 3.5 && p >= 0.1) {
                const verdict other = judge(randomised_rounding(N, p), N, draw);
                CAPTURE(p);
                CHECK(std::min(other.chi_p, other.ks_p) < a);
            }
        }
    MESSAGE(rejections << " of 42 points rejected");
}
