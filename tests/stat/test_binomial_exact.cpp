// The exact reference sampler (glint::testing::binomial_exact) against its own CDF, including
// real N (randomised rounding) and the Poisson branch for p <= 1e-8: a chi-square test over at
// most 202 cells of the support (pooled to expectation >= 5), 20000 samples per point (500 at
// N = 1e16, where Boost's CDF costs 0.5 ms), family-wise 0.01 over the 8 points plus the power
// check. Power: the same test rejects samples drawn at p (1 + 3%) where the mean is 100 (a shift
// of 0.3 standard deviations).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glint/core.hpp>
#include <glint/testing/binomial_reference.hpp>
#include <glint/testing/stats.hpp>

namespace gt = glint::testing;

namespace {

const double alpha = gt::sidak_alpha(0.01, 9);

// Cells: integer intervals (edge_{j-1}, edge_j] covering mean +- 8 sd, at most 200 of them,
// plus one below and one above.
double chi_square_p(const gt::binomial_exact& law, const gt::binomial_exact& sampler, std::uint32_t stream, int n = 20000) {
    const double mean = law.mean(), sd = std::sqrt(law.variance());
    const double lo = std::max(-1.0, std::floor(mean - 8 * sd - 2)), hi = std::ceil(mean + 8 * sd + 2);
    const double step = std::max(1.0, std::ceil((hi - lo) / 200));
    std::vector<double> edges;
    for (double e = lo; e < hi; e += step) edges.push_back(e);
    edges.push_back(hi);
    std::vector<double> observed(edges.size() + 1, 0.0), probability(edges.size() + 1, 0.0);
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
        const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, stream, 0xe7u));
        const double k = sampler.sample(glint::open_unit_from_bits<double>(h.x), glint::open_unit_from_bits<double>(h.y));
        observed[static_cast<std::size_t>(std::lower_bound(edges.begin(), edges.end(), k) - edges.begin())] += 1;
    }
    double previous = 0;
    for (std::size_t j = 0; j < edges.size(); ++j) {
        const double f = law.cdf(edges[j]);
        probability[j] = f - previous;
        previous = f;
    }
    probability.back() = 1 - previous;
    return gt::chi_square(observed, probability).p_value;
}

}  // namespace

TEST_CASE("binomial_exact samples its own law, for integer and real N and in the Poisson branch") {
    struct point {
        double N, p;
    };
    std::uint32_t stream = 0;
    for (point q : {point{10, 0.3}, point{100, 0.5}, point{2.5, 0.4}, point{37.3, 0.1}, point{1e6, 0.01}, point{1e12, 1e-10},
                    point{1e9, 1e-9}, point{1e16, 0.5}}) {
        CAPTURE(q.N);
        CAPTURE(q.p);
        gt::binomial_exact law(q.N, q.p);
        // Boost's CDF costs 0.5 ms at N = 1e16, p = 1/2: 500 samples there.
        const double p = chi_square_p(law, law, ++stream, q.N > 1e12 ? 500 : 20000);
        MESSAGE("N = " << q.N << ", p = " << q.p << ": chi-square p-value " << p);
        CHECK(p >= alpha);
    }
}

TEST_CASE("binomial_exact: the chi-square test rejects p shifted by 3% at mean 100, and bad parameters throw") {
    gt::binomial_exact law(1000, 0.1), shifted(1000, 0.103);
    CHECK(chi_square_p(law, shifted, 99) < alpha);
    CHECK_THROWS_AS(gt::binomial_exact(-1, 0.5), std::invalid_argument);
    CHECK_THROWS_AS(gt::binomial_exact(10, 1.5), std::invalid_argument);
    CHECK_THROWS_AS(gt::binomial_exact(NAN, 0.5), std::invalid_argument);
    CHECK(gt::binomial_exact(7.25, 0.2).mean() == doctest::Approx(1.45));
}
