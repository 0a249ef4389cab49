// The samplers' shortcuts (kernels/binomial.glsl: the near-end gate, the dual-gated middle, the
// underflowed ends) skip transcendentals where the result is already decided. They must give
// bit for bit what the straight-line evaluation gives. The references below are that evaluation,
// written out from the kernels' pieces: KK25 Alg. 1 as published (every gate and the quantile
// always evaluated), and the mean-preserving sampler with its ends always computed. Inputs: the
// grid, more N and p, and u1 at 2 ulps either side of every gate threshold and every bound.
// For u1 a normal number: the one difference, gate probabilities below the normal range taken
// as 0, decides the same for every normal u1.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glint/binomial.hpp>
#include <glint/testing/binomial_metrics.hpp>

namespace gt = glint::testing;

namespace {

template <class real>
using K = glint::detail::glsl::kernels<real>;

template <class real>
glint::binomial_result<real> pair(real positive, real negative) {
    return K<real>::glint_binomial_pair(positive, negative);
}

// KK25 Alg. 1 straight through.
template <class real>
glint::binomial_result<real> dual_gated_reference(real N, real p, real u1, real u2, int method) {
    N = std::max(N, real(0));
    p = std::min(std::max(p, real(0)), real(1));
    const real N2 = std::max(real(2), N);
    const auto g = K<real>::glint_binomial_dual_gates(N, p, u1, std::pow(p, N2), K<real>::glint_pow_one_minus(p, N2, method));
    const real mu = real(1) + (N2 - real(2)) * p;
    const real sigma = std::sqrt((N2 - real(2)) * p * (real(1) - p));
    const real G = std::min(std::max(mu + sigma * K<real>::glint_normal_quantile(u2), real(1)), N2 - real(1));
    return pair(g.positive_fixed + g.gaussian * G, g.negative_fixed + g.gaussian * (N2 - G));
}

// The mean-preserving sampler with its ends always evaluated.
template <class real>
glint::binomial_result<real> unbiased_reference(real N, real p, real u1, real u2, int method) {
    N = std::min(std::max(N, real(0)), K<real>::GLINT_BINOMIAL_MAX_N);
    p = std::min(std::max(p, real(0)), real(1));
    const real N2 = std::max(real(2), N);
    const auto e = K<real>::glint_binomial_unbiased_ends_evaluated(N2, p, method);
    const auto g = K<real>::glint_binomial_dual_gates(N, p, u1, e.all_positive, e.all_negative);
    real G = 1;
    if (g.gaussian > real(0.5) && N > real(2))
        G = K<real>::glint_binomial_unbiased_middle(K<real>::glint_binomial_unbiased_middle_setup(N2, p, e), N2, u2);
    return pair(g.positive_fixed + g.gaussian * G, g.negative_fixed + g.gaussian * (N2 - G));
}

// u1 values: hashed, the extremes, and 2 ulps around every threshold the gates or bounds use.
template <class real>
std::vector<real> u1_values(real N, real p, int method) {
    std::vector<real> thresholds;
    const real q = std::min(p, real(1) - p), N2 = std::max(real(2), N);
    const real bound = N * q * real(1.001) + real(1e-5);
    // The mean-preserving sampler's bounds on the ends, 1.001 / (1 + x + x^2 / 2 + x^3 / 6).
    const real x_pos = real(0.999) * N * (real(1) - p), x_neg = real(0.999) * N * p;
    auto cubic = [](real x) { return real(1) + x * (real(1) + x * (real(0.5) + x * real(1.0 / 6.0))); };
    thresholds.insert(thresholds.end(), {bound, real(1) - bound, real(1.001) / (real(1) + real(0.999) * N * (real(1) - p)),
                                         real(1) - real(1e-6) - real(1.001) / (real(1) + real(0.999) * N * p), std::pow(p, N2),
                                         real(1) - K<real>::glint_pow_one_minus(p, N2, method), real(1.001) / cubic(x_pos),
                                         real(1) - real(1e-6) - real(1.001) / cubic(x_neg)});
    const auto e = K<real>::glint_binomial_unbiased_ends_evaluated(N2, p, method);
    thresholds.insert(thresholds.end(), {e.all_positive, real(1) - e.all_negative});
    std::vector<real> us = {real(1), real(0x1p-24), real(1) - real(0x1p-24), real(0.5)};
    for (real t : thresholds) {
        // u1 is a normal number: the shortcuts take subnormal gate probabilities as 0, which
        // decides the same for every normal u1 (uniforms from 24 or 53 bits are >= 2^-25, 2^-54).
        if (!(t >= std::numeric_limits<real>::min() && t < 1)) continue;
        real below = t, above = t;
        for (int i = 0; i < 2; ++i) below = std::nextafter(below, real(0)), above = std::nextafter(above, real(1));
        us.insert(us.end(), {below, std::nextafter(below, real(1)), t, std::nextafter(t, real(1)), above});
    }
    for (std::uint32_t i = 0; i < 40; ++i)
        us.push_back(glint::open_unit_from_bits<real>(glint::pcg3d(glm::uvec3(i, static_cast<std::uint32_t>(static_cast<double>(N) * 7 + static_cast<double>(p) * 1e6), 3u)).x));
    return us;
}

template <class real>
void check_identical(const char* precision) {
    std::vector<double> ns = gt::binomial_grid_n(), ps = gt::binomial_grid_p();
    for (double extra : {2.5, 4.0, 50.0, 176.0, 180.0, 220.0, 300.0, 1418.0, 1600.0, 1e5, 1e18}) ns.push_back(extra);
    for (double extra : {0.25, 0.4999, 0.5001, 1e-7, 3e-8, 2.8e-4, 0.75, 1 - 1e-4, 88.0 / 180, 709.0 / 1418, 88.0 / 1e5, 709.0 / 1e5, 90.0 / 1e18}) ps.push_back(extra);
    const real u2s[] = {real(0x1p-24), real(0.0137), real(0.5), real(0.77), real(1) - real(0x1p-24)};
    long checked = 0, differ = 0;
    for (int method = 0; method <= 2; ++method)
        for (double nd : ns)
            for (double pd : ps) {
                const real N = static_cast<real>(nd), p = static_cast<real>(pd);
                for (real u1 : u1_values(N, p, method))
                    for (real u2 : u2s) {
                        const auto a = K<real>::glint_binomial_dual_gated(N, p, u1, u2, method);
                        const auto b = dual_gated_reference(N, p, u1, u2, method);
                        const auto c = K<real>::glint_binomial_unbiased(N, p, u1, u2, method);
                        const auto d = unbiased_reference(N, p, u1, u2, method);
                        const bool same = a.positive == b.positive && a.negative == b.negative && c.positive == d.positive &&
                                          c.negative == d.negative;
                        if (!same && differ++ < 5) {
                            CAPTURE(std::string(precision));
                            CAPTURE(method);
                            CAPTURE(N);
                            CAPTURE(p);
                            CAPTURE(u1);
                            CAPTURE(u2);
                            CHECK(a.positive == b.positive);
                            CHECK(a.negative == b.negative);
                            CHECK(c.positive == d.positive);
                            CHECK(c.negative == d.negative);
                        }
                        ++checked;
                    }
            }
    MESSAGE(std::string(precision) << ": " << checked << " inputs, " << differ << " differ from the straight-line evaluation");
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE("the samplers' shortcuts give exactly the straight-line result (float and double)") {
    check_identical<float>("float");
    check_identical<double>("double");
}

TEST_CASE("the shortcuts are taken where they should be") {
    // Sparse: at N p = 1e-3 the near-end gate decides for all u1 above 1.001e-3 + 1e-5.
    CHECK(K<float>::glint_binomial_surely_near_end(1e3f, 1e-6f, 0.5f, 2));
    CHECK(K<float>::glint_binomial_surely_near_end(1e3f, 1 - 1e-6f, 0.5f, 1));
    CHECK_FALSE(K<float>::glint_binomial_surely_near_end(1e3f, 1e-6f, 1e-3f, 2));
    CHECK_FALSE(K<float>::glint_binomial_surely_near_end(1e3f, 1e-6f, 0.5f, 0));  // naive: no bound
    CHECK_FALSE(K<float>::glint_binomial_surely_near_end(2.0f, 1e-6f, 0.5f, 2));  // N <= 2: exact gates
    // Busy: both ends underflow.
    const auto e = K<float>::glint_binomial_unbiased_ends(1e4f, 0.3f, 2);
    CHECK(e.all_positive == 0);
    CHECK(e.all_negative == 0);
    CHECK(e.any_near == 1);
}

TEST_CASE("the mean-preserving sampler with a cache gives exactly the uncached result, and reuses its setup") {
    // Runs of draws at one (N, p), as the grid's triangle vertices make them, then a neighbour
    // that differs in p only (N-major order) or in N only (p-major order): a cache that kept the
    // wrong parameters would show in the counts. Grid N and p, all methods, float.
    const std::vector<double> ns = gt::binomial_grid_n(), ps = gt::binomial_grid_p();
    long checked = 0, differ = 0, reused = 0;
    for (int method = 0; method <= 2; ++method)
        for (int order = 0; order < 2; ++order) {
            auto cache = K<float>::glint_binomial_empty_cache();
            std::uint32_t draw = 0;
            for (std::size_t a = 0; a < (order == 0 ? ns.size() : ps.size()); ++a)
                for (std::size_t b = 0; b < (order == 0 ? ps.size() : ns.size()); ++b) {
                    const float N = static_cast<float>(order == 0 ? ns[a] : ns[b]), p = static_cast<float>(order == 0 ? ps[b] : ps[a]);
                    for (int run = 0; run < 3; ++run, ++draw) {
                        const glm::uvec3 h = glint::pcg3d(glm::uvec3(draw, static_cast<std::uint32_t>(method), 11u));
                        const float u1 = glint::open_unit_from_bits<float>(h.x), u2 = glint::open_unit_from_bits<float>(h.y);
                        const bool warm = cache.state == 2 && cache.N == N && cache.p == p;
                        const auto c = K<float>::glint_binomial_unbiased_cached(N, p, u1, u2, method, cache);
                        const auto d = K<float>::glint_binomial_unbiased(N, p, u1, u2, method);
                        reused += warm;
                        differ += !(c.positive == d.positive && c.negative == d.negative);
                        ++checked;
                    }
                }
        }
    MESSAGE(checked << " draws, " << reused << " from a warm cache, " << differ << " differ from the uncached sampler");
    CHECK(reused > checked / 10);
    CHECK(differ == 0);
}
