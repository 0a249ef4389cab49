// The samplers' shortcuts (kernels/binomial.glsl: the near-end gate, the dual-gated middle, the
// underflowed ends, the sure middle's clamped count) skip transcendentals where the result is
// already decided. They must give
// bit for bit what the straight-line evaluation gives. The references below are that evaluation,
// written out from the kernels' pieces: KK25 Alg. 1 as published (every gate and the quantile
// always evaluated), and the mean-preserving sampler with its ends always computed and its middle
// always set up (neither the busy nor the sure middle's shortcut), or its walk for small N.
// Inputs: the grid, more N and p, and u1 at 2 ulps either side of every gate threshold and every
// bound.
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

// The mean-preserving sampler with its ends always evaluated (and for 2 < N < 40, where it draws
// by the walk, the walk without the near-end gate).
template <class real>
glint::binomial_result<real> unbiased_reference(real N, real p, real u1, real u2, int method) {
    N = std::min(std::max(N, real(0)), K<real>::GLINT_BINOMIAL_MAX_N);
    p = std::min(std::max(p, real(0)), real(1));
    if (K<real>::glint_binomial_walks(N, u2)) return K<real>::glint_binomial_walk(N, p, u1, u2);
    const real N2 = std::max(real(2), N);
    const auto e = K<real>::glint_binomial_unbiased_ends_evaluated(N2, p, method);
    const auto g = K<real>::glint_binomial_dual_gates(N, p, u1, e.all_positive, e.all_negative);
    real G = 1;
    if (g.gaussian > real(0.5) && N > real(2))
        G = K<real>::glint_binomial_unbiased_middle(K<real>::glint_binomial_unbiased_middle_setup(N2, p, e), N2, u2);
    return pair(g.positive_fixed + g.gaussian * G, g.negative_fixed + g.gaussian * (N2 - G));
}

// Halfway into the middle's gate, 1 - (1 - q)^n with q = min(p, 1 - p), mirrored for p > 1/2.
template <class real>
real middle_gate_midpoint(real n, real p) {
    const real q = std::min(p, real(1) - p), mid = real(0.5) * (real(1) - std::pow(real(1) - q, n));
    return p <= real(0.5) ? mid : real(1) - mid;
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
    // The busy middle's bounds on u1 (glint_binomial_unbiased_busy).
    thresholds.insert(thresholds.end(), {real(1.03e-3), real(1) - real(1.03e-3)});
    // Halfway into the middle's gate: with u2 at the clamped-mass bound below, the sure middle's
    // shortcut at its edge.
    thresholds.push_back(middle_gate_midpoint(N2, p));
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
    // Also where the middle's closed form begins, N p_near = 3 (N = 12 at p = 1/4, 300 at p = 0.01),
    // and its far bound's test (clear from N = 11.45 on; N = 20 at p from 0.15 to 0.40, N = 30 up to
    // p = 1/2), N p_near = 8.5 (N = 17 at p = 1/2, 850 at p = 0.01), where the busy middle begins,
    // N p_near = 17 (also where the near end's weight is dropped: N = 34 at p = 1/2, 1700 at
    // p = 0.01), and 6 sd = N p_near - 1 (N p_near = 38.4 at p_near = 0.01: N = 3840).
    for (double extra : {2.5, 4.0, 11.45, 12.0, 17.0, 20.0, 21.0, 28.5, 29.0, 34.0, 50.0, 176.0, 180.0, 220.0, 300.0, 850.0, 1418.0, 1600.0, 1700.0,
                         3840.0, 1e5, 1e18})
        ns.push_back(extra);
    for (double extra : {0.25, 0.4999, 0.5001, 1e-7, 3e-8, 2.8e-4, 0.75, 1 - 1e-4, 0.15, 0.262, 0.4015, 0.405, 0.595, 8.5 / 21, 88.0 / 180,
                         709.0 / 1418, 88.0 / 1e5, 709.0 / 1e5, 90.0 / 1e18})
        ps.push_back(extra);
    long checked = 0, differ = 0;
    for (int method = 0; method <= 2; ++method)
        for (double nd : ns)
            for (double pd : ps) {
                const real N = static_cast<real>(nd), p = static_cast<real>(pd);
                // u2: fixed values, and 2 ulps around the sure middle's clamped-mass bound on
                // u_near (u2, or 1 - u2 for p > 1/2).
                std::vector<real> u2s = {real(0x1p-24), real(0.0137), real(0.5), real(0.77), real(1) - real(0x1p-24)};
                const real bound = K<real>::glint_binomial_clamped_mass_bound(N * std::min(p, real(1) - p));
                if (bound > 0 && bound < 1)
                    for (real t : {bound, real(1) - bound}) {
                        real below = std::nextafter(std::nextafter(t, real(0)), real(0)), above = std::nextafter(std::nextafter(t, real(1)), real(1));
                        u2s.insert(u2s.end(), {below, t, above});
                    }
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

// glint_binomial_clamped_mass_bound's claims, over the region where the sure middle reads it (its
// parameters need no ends, N >= 4): the fitted middle's clamped share Phi(-t) >= exp(-0.9253 lambda),
// and at u_near = the bound the count is the clamp's (1 for p <= 1/2; N - 1 mirrored, N <= 4096)
// with sigma (t + z) <= -0.006 to spare; so is it below (the quantile is monotone). A bound with
// 0.90 for 0.94 fails both.
template <class real>
void check_clamped_mass_bound(const char* precision) {
    double worst_decay = 0, worst_margin = -1e30;
    long points = 0, taken = 0;
    for (double nd = 4; nd < 1e16; nd *= 1.02)
        for (double lambda = 1.0 / 1024; lambda < 3.5; lambda *= 1.01) {
            const real N = static_cast<real>(nd), p_near = static_cast<real>(lambda / nd);
            if (!(p_near <= real(0.5)) || !K<real>::glint_binomial_middle_needs_no_ends(N, p_near)) continue;
            const auto f = K<real>::glint_binomial_middle_fit(N, p_near);  // (t, sigma, sigma t)
            const double share = 0.5 * std::erfc(static_cast<double>(f.x) / std::sqrt(2.0));
            if (N >= real(12)) worst_decay = std::max(worst_decay, -std::log(share) / lambda);
            ++points;
            const real bound = K<real>::glint_binomial_clamped_mass_bound(N * p_near);
            if (!(bound > 0)) continue;
            ++taken;
            const real z = K<real>::glint_normal_quantile(bound);
            worst_margin = std::max(worst_margin, static_cast<double>(f.y) * (static_cast<double>(f.x) + static_cast<double>(z)));
            // The counts the sure middle would draw at u_near = bound, both sides.
            const auto lower = K<real>::glint_binomial_gaussian_count(real(1) + f.z, f.y, true, bound, N);
            CHECK(lower == real(1));
            if (N <= K<real>::GLINT_BINOMIAL_CLAMPED_MIRROR_N_MAX) {
                const auto upper = K<real>::glint_binomial_gaussian_count((N - real(1)) - f.z, f.y, false, real(1) - bound, N);
                CHECK(upper == N - real(1));
            }
        }
    MESSAGE(std::string(precision) << ": " << points << " points, the bound positive at " << taken << "; largest -log(Phi(-t)) / lambda " << worst_decay
                      << ", largest sigma (t + z) at the bound " << worst_margin);
    CHECK(worst_decay <= 0.9253);
    CHECK(worst_margin <= -0.006);
}

TEST_CASE("the sure middle's clamped-mass bound lies below the clamped share, with room for rounding (float and double)") {
    check_clamped_mass_bound<float>("float");
    check_clamped_mass_bound<double>("double");
    // Not below N p_near = 2^-7, where the far bound's table (N < 32) keeps the clamped share near
    // 1 - 1e-5 while the bound tends to 1, nor mirrored above N = 4096. (The sure middle never
    // draws below N p_near = 1e-3, where its bounds on u1 leave no room; the cached sampler, when it
    // took the shortcut without this limit, differed from the uncached one at N = 30, p = 1e-8.)
    CHECK(K<float>::glint_binomial_surely_clamped(30.0f, 0.01f, 0.5f));
    CHECK_FALSE(K<float>::glint_binomial_surely_clamped(30.0f, 1e-8f, 0.5f));
    CHECK(K<float>::glint_binomial_surely_clamped(4096.0f, 1 - 1e-4f, 0.5f));
    CHECK_FALSE(K<float>::glint_binomial_surely_clamped(8192.0f, 1 - 1e-4f, 0.5f));
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
                    // Runs 3 and 4: the middle's gate, and u2 at the clamped-mass bound on u_near and 2
                    // ulps past it.
                    const float bound = K<float>::glint_binomial_clamped_mass_bound(N * std::min(p, 1 - p));
                    const bool edge = bound > 0 && bound < 1;
                    for (int run = 0; run < (edge ? 5 : 3); ++run, ++draw) {
                        const glm::uvec3 h = glint::pcg3d(glm::uvec3(draw, static_cast<std::uint32_t>(method), 11u));
                        float u1 = glint::open_unit_from_bits<float>(h.x);
                        float u2 = glint::open_unit_from_bits<float>(h.y);
                        if (run >= 3) {
                            u1 = middle_gate_midpoint(N, p);
                            u2 = p <= 0.5f ? bound : 1 - bound;
                            if (run == 4) u2 = std::nextafter(std::nextafter(u2, p <= 0.5f ? 1.0f : 0.0f), p <= 0.5f ? 1.0f : 0.0f);
                        }
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

namespace {

// The far end p_near^N as the log1p evaluation gives it (float): exp(N log1p(-(1 - p_near))), 0
// below exp(-88).
float far_end_by_log1p(float N, float p_near) {
    const float x = N * K<float>::glint_log1p(-(1.0f - p_near));
    return (x < -K<float>::GLINT_BINOMIAL_UNDERFLOW_MEAN) ? 0.0f : std::exp(x);
}

// The kernel's bound (glint_binomial_far_end_underflows) with another threshold on floor(N) e.
bool exponent_bound(float N, float p_near, int limit) {
    int e;
    std::frexp(p_near, &e);
    return static_cast<int>(N) * e <= limit;
}

}  // namespace

TEST_CASE("the far end's exponent bound fires only where log1p and exp give 0, and the test sees a bound set too high") {
    // N from 2.01 to 126.9 (the range where the bound is consulted; from N log 2 >= 88 on the far
    // end underflows anyway), p_near from 1e-12 to 1/2 in 4000 log steps and around every
    // threshold 2^(-128 / N), both sides of 1/2 (the far end is p^N below 1/2, (1 - p)^N above).
    std::vector<float> ns;
    for (float N = 2.01f; N < 127.0f; N *= 1.013f) ns.push_back(N);
    int fired = 0, consulted = 0, wrong_fired_on_nonzero = 0;
    for (float N : ns) {
        std::vector<float> ps;
        for (int i = 0; i <= 4000; ++i) ps.push_back(static_cast<float>(std::pow(10.0, -12.0 + (12.0 - std::log10(2.0)) * i / 4000)));
        for (double scale : {0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 2.0}) ps.push_back(static_cast<float>(std::pow(2.0, -128.0 * scale / std::floor(static_cast<double>(N)))));
        for (float p_near : ps) {
            if (!(p_near > 0 && p_near <= 0.5f) || N * 0.6931472f >= 88.0f) continue;
            ++consulted;
            const float reference = far_end_by_log1p(N, p_near);
            const bool bound = K<float>::glint_binomial_far_end_underflows(N, p_near);
            fired += bound;
            if (bound) {
                CAPTURE(N);
                CAPTURE(p_near);
                REQUIRE(reference == 0.0f);
            }
            // The kernel's ends carry the same far end either way.
            for (float p : {p_near, 1.0f - p_near}) {
                const auto e = K<float>::glint_binomial_unbiased_ends_evaluated(N, p, K<float>::GLINT_POW_LOG1P);
                const float far = (p <= 0.5f) ? e.all_positive : e.all_negative;
                CAPTURE(N);
                CAPTURE(p);
                REQUIRE(far == far_end_by_log1p(N, (p <= 0.5f) ? p : 1.0f - p));  // the kernel's own p_near
            }
            // Wrong on purpose: the threshold at floor(N) e <= -120 fires where the far end can still
            // be a normal number.
            wrong_fired_on_nonzero += exponent_bound(N, p_near, -120) && reference > 0.0f;
        }
    }
    MESSAGE("the bound fired at " << fired << " of " << consulted << " (N, p_near); the wrong bound at " << wrong_fired_on_nonzero << " where the far end is not 0");
    CHECK(fired > consulted / 4);
    CHECK(wrong_fired_on_nonzero > 0);
}

// glint_binomial_unbiased_sparse (the grid's draws take it first) must give the mean-preserving
// sampler's count bit for bit wherever it decides, in float and double: N from 0 through 2 (the
// exact gates), on both sides of the walk's ends (32, 40), between them (the blend) and up to 1e5, p from 1e-7 to 1/2, u1 at 2 ulps either side of every
// threshold of the shortcuts above and of the sparse walk's bounds for both components, u2 at and
// around the component split, the clamped-mass bound and fixed values. `lax` is a deliberately wrong
// shortcut: the sure middle's count 1 without its clamped-mass test, and the walk's 1 without its
// bound on P(n > 1); it must differ from the sampler somewhere, which shows that the inputs reach
// past the bounds.
template <class real>
long sparse_differences(bool lax, long& decided, long& checked) {
    using KR = K<real>;
    long differ = 0;
    for (int method = 0; method <= 2; ++method)
        for (double nd : {0.0, 0.3, 1.0, 1.5, 2.0, 2.5, 3.0, 4.75, 7.2, 10.5, 20.3, 31.9, 32.0, 32.5, 33.7, 36.0, 39.9, 40.0, 40.5, 60.0, 100.0, 176.0, 1000.0, 1e4, 1e5})
            for (double pd : {1e-7, 1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 0.01, 0.03, 0.1, 0.2, 0.5, 0.25 / nd, 0.2 / nd, 2.0 / nd, 16.0 / nd, 17.5 / nd}) {
                const real N = static_cast<real>(nd), p = static_cast<real>(pd);
                if (!(p <= real(0.5))) continue;
                std::vector<real> u1s = u1_values(N, p, method), edges;
                const int Na = static_cast<int>(N);
                for (int M : {Na, Na + 1}) {
                    const real mq = real(M) * p;
                    edges.insert(edges.end(), {mq, real(0.5) * mq * mq * real(1.0009765625), mq * (real(1) - real(0.5) * mq) * real(0.9990234375),
                                               real(0.5) * mq * mq});
                    if (M >= 2 && M <= 40) edges.push_back(KR::glint_binomial_walk_start(M, p).survival);
                }
                for (real t : edges) {
                    if (!(t >= std::numeric_limits<real>::min() && t < 1)) continue;
                    real below = t, above = t;
                    for (int i = 0; i < 3; ++i) {
                        u1s.insert(u1s.end(), {below, above});
                        below = std::nextafter(below, real(0)), above = std::nextafter(above, real(1));
                    }
                }
                std::vector<real> u2s = {real(0x1p-24), real(0.0137), real(0.5), real(0.77), real(1) - real(0x1p-24)};
                std::vector<real> u2_edges = {N - real(Na), KR::glint_binomial_clamped_mass_bound(N * p)};
                if (N > KR::GLINT_BINOMIAL_WALK_FULL && N < KR::GLINT_BINOMIAL_WALK_END) {
                    // The blend stretches u2 (glint_binomial_walks): its edges and the preimages of the edges above.
                    const real w = KR::glint_binomial_walk_weight(N);
                    u2_edges.insert(u2_edges.end(), {real(0.5) - real(0.5) * w, real(0.5) + real(0.5) * w, real(0.5) + (u2_edges[0] - real(0.5)) * w,
                                                     real(0.5) + (u2_edges[1] - real(0.5)) * (real(1) - w) - real(0.5) * w});
                }
                for (real t : u2_edges)
                    if (t > 0 && t < 1) u2s.insert(u2s.end(), {std::nextafter(t, real(0)), t, std::nextafter(t, real(1))});
                for (real u1 : u1s)
                    for (real u2 : u2s) {
                        real s = KR::glint_binomial_unbiased_sparse(N, p, u1, u2, method);
                        if (lax && s < 0 && method != KR::GLINT_POW_NAIVE && p > real(0)) {
                            const bool middle = N >= KR::GLINT_BINOMIAL_WALK_END && N * p < KR::GLINT_BINOMIAL_BUSY_LAMBDA &&
                                                KR::glint_binomial_surely_middle(N, p, u1, method);
                            const real mq = real(u2 < N - real(Na) ? Na + 1 : Na) * p;
                            const bool walk = N > real(2) && N <= KR::GLINT_BINOMIAL_WALK_FULL && mq < real(0.25) && u1 < mq;
                            if (middle) s = real(1);
                            if (walk) s = N / real(u2 < N - real(Na) ? Na + 1 : Na);
                        }
                        ++checked;
                        if (s < 0) continue;
                        ++decided;
                        const real full = KR::glint_binomial_unbiased(N, p, u1, u2, method).positive;
                        if (s != full && differ++ < 5 && !lax) {
                            CAPTURE(method);
                            CAPTURE(N);
                            CAPTURE(p);
                            CAPTURE(u1);
                            CAPTURE(u2);
                            CHECK(s == full);
                        }
                    }
            }
    return differ;
}

TEST_CASE("a sparse draw's count from the shortcut is the mean-preserving sampler's (float and double), and a lax shortcut differs") {
    long decided = 0, checked = 0;
    const long differ = sparse_differences<float>(false, decided, checked) + sparse_differences<double>(false, decided, checked);
    MESSAGE(checked << " draws, " << decided << " decided by the sparse shortcut, " << differ << " differ from the sampler");
    CHECK(decided > checked / 10);
    CHECK(differ == 0);
    long lax_decided = 0, lax_checked = 0;
    const long lax_differ = sparse_differences<float>(true, lax_decided, lax_checked) + sparse_differences<double>(true, lax_decided, lax_checked);
    MESSAGE("the lax shortcut: " << lax_differ << " of " << lax_decided << " decided draws differ");
    CHECK(lax_differ > 0);
}
