// Multinomial sampling, statistically: the marginal means of every bin equal N p_k (z-tests that
// assert their resolution); for N = 1, 2, 3 and 6, where the mean-preserving hierarchy is exact,
// the joint law of the counts equals the multinomial (chi-square over all outcomes); and the
// exact split's law is the binomial's (chi-square at 8 (n, q), each shown to reject q 1.05).
// Family-wise significance 0.01, Sidak over the tests of this file that must not reject (5 values
// of N x (5 + 9) bins, 4 x 2 joint tests, 8 splits): alpha per test below.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <glint/multinomial.hpp>
#include <glint/testing/stats.hpp>

namespace gt = glint::testing;
using glint::binomial_variant;

namespace {

const double alpha = gt::sidak_alpha(0.01, 5 * 14 + 8 + 8);

template <std::size_t K>
std::array<float, K> probabilities() {
    std::array<float, K> p;
    for (std::size_t k = 0; k < K; ++k) p[k] = 0.8f * static_cast<float>(k + 1) / static_cast<float>(K * (K + 1) / 2);
    return p;  // sums to 0.8: the rest bin holds 0.2
}

double factorial(int n) { return std::tgamma(n + 1.0); }

}  // namespace

TEST_CASE("marginal means are N p_k for the mean-preserving hierarchy, K = 4 and 8") {
    // 2e6 samples per (K, N): each z-test must resolve 2% of its bin's mean with power 0.9 (the
    // smallest bin, p = 0.022 at K = 8 and N = 2.5, has mean 0.056 and standard error 1.6e-4).
    for (float N : {2.5f, 3.0f, 10.0f, 1e3f, 1e9f}) {
        for (int K : {4, 8}) {
            std::vector<gt::running_moments> m(static_cast<std::size_t>(K) + 1);
            std::vector<float> p(static_cast<std::size_t>(K));
            for (std::uint32_t i = 0; i < 2000000; ++i) {
                if (K == 4) {
                    const auto pp = probabilities<4>();
                    const auto c = glint::multinomial<4>(N, pp, glm::uvec3(i, 11u, 3u));
                    for (int k = 0; k < 4; ++k) m[static_cast<std::size_t>(k)].add(static_cast<double>(c.count[static_cast<std::size_t>(k)])), p[static_cast<std::size_t>(k)] = pp[static_cast<std::size_t>(k)];
                    m[4].add(static_cast<double>(c.rest));
                } else {
                    const auto pp = probabilities<8>();
                    const auto c = glint::multinomial<8>(N, pp, glm::uvec3(i, 12u, 3u));
                    for (int k = 0; k < 8; ++k) m[static_cast<std::size_t>(k)].add(static_cast<double>(c.count[static_cast<std::size_t>(k)])), p[static_cast<std::size_t>(k)] = pp[static_cast<std::size_t>(k)];
                    m[8].add(static_cast<double>(c.rest));
                }
            }
            double psum = 0;
            for (int k = 0; k <= K; ++k) {
                const double pk = k < K ? static_cast<double>(p[static_cast<std::size_t>(k)]) : 1 - psum;
                if (k < K) psum += pk;
                const double expected = static_cast<double>(N) * pk;
                const auto z = gt::mean_test(m[static_cast<std::size_t>(k)], expected, alpha);
                CAPTURE(N);
                CAPTURE(K);
                CAPTURE(k);
                REQUIRE(z.resolves(0.02 * expected));
                CHECK(!z.rejects(alpha));
            }
        }
    }
}

TEST_CASE("for N = 1, 2, 3, 6 the mean-preserving hierarchy is the exact multinomial, Alg. 1's is not at N = 3 and 6") {
    // 4 bins + rest, 2e5 samples; cells: every outcome (c0..c3, rest) with sum N.
    const auto pp = probabilities<4>();
    const double pr[5] = {double(pp[0]), double(pp[1]), double(pp[2]), double(pp[3]), 1.0 - double(pp[0] + pp[1] + pp[2] + pp[3])};
    for (binomial_variant v : {binomial_variant::unbiased, binomial_variant::dual_gated})
        for (int N : {1, 2, 3, 6}) {
            std::map<std::vector<int>, double> observed;
            const int n = 200000;
            for (std::uint32_t i = 0; i < n; ++i) {
                const auto c = glint::multinomial<4>(static_cast<float>(N), pp, glm::uvec3(i, 21u, static_cast<std::uint32_t>(N)), v);
                std::vector<int> key = {static_cast<int>(c.count[0]), static_cast<int>(c.count[1]), static_cast<int>(c.count[2]),
                                        static_cast<int>(c.count[3]), static_cast<int>(c.rest)};
                observed[key] += 1;
            }
            std::vector<double> obs, prob;
            for (int a = 0; a <= N; ++a)
                for (int b = 0; a + b <= N; ++b)
                    for (int c = 0; a + b + c <= N; ++c)
                        for (int d = 0; a + b + c + d <= N; ++d) {
                            const int e = N - a - b - c - d;
                            const double pmf = factorial(N) / (factorial(a) * factorial(b) * factorial(c) * factorial(d) * factorial(e)) *
                                               std::pow(pr[0], a) * std::pow(pr[1], b) * std::pow(pr[2], c) * std::pow(pr[3], d) * std::pow(pr[4], e);
                            const std::vector<int> key = {a, b, c, d, e};
                            obs.push_back(observed.count(key) ? observed[key] : 0.0);
                            observed.erase(key);
                            prob.push_back(pmf);
                        }
            double stray = 0;  // outcomes that do not sum to N
            for (const auto& kv : observed) stray += kv.second;
            obs.push_back(stray);
            prob.push_back(0.0);
            double total = 0;
            for (double q : prob) total += q;
            for (double& q : prob) q /= total;
            const auto r = gt::chi_square(obs, prob);
            CAPTURE(std::string(glint::name(v)));
            CAPTURE(N);
            MESSAGE(std::string(glint::name(v)) << " N = " << N << ": chi-square p " << r.p_value << " over " << r.cells << " cells");
            if (v == binomial_variant::unbiased || N < 3) CHECK(!r.rejects(alpha));
            else CHECK(r.rejects(alpha));  // power: Alg. 1's Gaussian middle at N = 3 is not the binomial
        }
}

TEST_CASE("the exact split is Binomial(floor n, q) plus frac(n) Bernoulli(q), and the test sees q off by 5%") {
    // 2e5 draws per (n, q), cells (whole trials left, fractional trial left); pooled to >= 5
    // expected. The same counts against q 1.05 must be rejected: at (5.25, 0.013), the weakest
    // case, that shifts the mean by 5.9 standard errors.
    using MK = glint::detail::glsl::kernels<float>;
    const double cases[8][2] = {{1, 0.3}, {7, 0.5}, {19.5, 0.3}, {31, 0.9}, {32, 0.77}, {40.25, 0.07}, {63, 0.6}, {5.25, 0.013}};
    for (const auto& c : cases) {
        const double n = c[0], q = c[1];
        const int whole = static_cast<int>(n);
        const bool has_frac = n > whole;
        const int frac_cells = has_frac ? 2 : 1;
        std::vector<double> observed(static_cast<std::size_t>((whole + 1) * frac_cells), 0.0);
        const std::uint32_t samples = 200000;
        for (std::uint32_t i = 0; i < samples; ++i) {
            const glm::uvec3 words = glint::pcg3d(glm::uvec3(i, static_cast<std::uint32_t>(n * 4), 0x5eedu));
            const float left = MK::glint_multinomial_exact_split(static_cast<float>(n), static_cast<float>(q), words);
            const int k = static_cast<int>(std::floor(left));
            const int f = (left > static_cast<float>(k)) ? 1 : 0;
            REQUIRE(k <= whole);
            observed[static_cast<std::size_t>(k * frac_cells + f)] += 1;
        }
        const auto law = [&](double qq) {
            std::vector<double> prob;
            for (int k = 0; k <= whole; ++k) {
                const double pk = factorial(whole) / (factorial(k) * factorial(whole - k)) * std::pow(qq, k) * std::pow(1 - qq, whole - k);
                if (has_frac) prob.push_back(pk * (1 - qq)), prob.push_back(pk * qq);
                else prob.push_back(pk);
            }
            return prob;
        };
        const auto r = gt::chi_square(observed, law(q));
        const auto wrong = gt::chi_square(observed, law(q * 1.05));
        CAPTURE(n);
        CAPTURE(q);
        MESSAGE("exact split n = " << n << ", q = " << q << ": chi-square p " << r.p_value << " over " << r.cells << " cells; against q 1.05: p " << wrong.p_value);
        CHECK(!r.rejects(alpha));
        CHECK(wrong.rejects(alpha));
    }
}
