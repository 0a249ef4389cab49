// Multinomial sampling: conservation, non-negative counts, K = 2..8, every variant, hard inputs.
#include <doctest/doctest.h>

#include "../support/lanes_paths.hpp"

#include <cmath>
#include <numeric>
#include <string>

#include <glint/multinomial.hpp>

using glint::binomial_variant;

namespace {

template <std::size_t K>
void check_conservation(binomial_variant v) {
    double worst_ulps = 0;
    for (float N : {2.5f, 3.0f, 5.0f, 10.0f, 100.0f, 1e4f, 1e6f, 1e9f, 1e16f})
        for (std::uint32_t trial = 0; trial < 400; ++trial) {
            std::array<float, K> p;
            const glm::uvec3 h = glint::pcg3d(glm::uvec3(trial, static_cast<std::uint32_t>(K), 0x77u));
            // Probabilities from 1e-12 to ~0.3, and some exact zeros.
            for (std::size_t k = 0; k < K; ++k) {
                const float u = glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(h.x, h.y, static_cast<std::uint32_t>(k))).z);
                p[k] = (u < 0.1f) ? 0.0f : std::pow(10.0f, -12.0f * u) / static_cast<float>(K);
            }
            const auto c = glint::multinomial<K>(N, p, glm::uvec3(trial, 5u, 9u), v);
            double sum = static_cast<double>(c.rest);
            REQUIRE(c.rest >= 0);
            for (float x : c.count) {
                REQUIRE(x >= 0);
                REQUIRE(std::isfinite(x));
                sum += static_cast<double>(x);
            }
            const double ulp = static_cast<double>(std::nextafter(N, 2 * N) - N);
            worst_ulps = std::max(worst_ulps, std::fabs(sum - static_cast<double>(N)) / ulp);
        }
    MESSAGE("K = " << K << ", " << std::string(glint::name(v)) << ": counts + rest within " << worst_ulps << " ulp of N");
    CHECK(worst_ulps <= 1.0);
}

}  // namespace

TEST_CASE("counts and rest sum to N within one ulp for N > 2, for K = 2..8 and the conserving variants") {
    for (binomial_variant v : {binomial_variant::dual_gated, binomial_variant::unbiased, binomial_variant::gated,
                               binomial_variant::ungated}) {
        CAPTURE(std::string(glint::name(v)));
        check_conservation<2>(v);
        check_conservation<3>(v);
        check_conservation<4>(v);
        check_conservation<5>(v);
        check_conservation<8>(v);
    }
}

TEST_CASE("N below 2 dithers at the root as KK25 does and stays non-negative") {
    for (float N : {0.0f, 1e-3f, 0.5f, 1.0f, 1.5f, 2.0f})
        for (std::uint32_t trial = 0; trial < 1000; ++trial) {
            const auto c = glint::multinomial<4>(N, std::array<float, 4>{0.1f, 0.2f, 0.3f, 0.15f}, glm::uvec3(trial, 1u, 1u));
            float sum = c.rest;
            for (float x : c.count) {
                CHECK(x >= 0);
                CHECK(x == std::floor(x));  // integer outcomes below 2
                sum += x;
            }
            CHECK(sum <= 2.0f);
        }
}

TEST_CASE("bad probabilities are tamed: negative as 0, a sum above 1 scaled down, NaN-free") {
    const auto c = glint::multinomial<4>(1e6f, std::array<float, 4>{-1.0f, 3.0f, 1.0f, 0.0f}, glm::uvec3(1u, 2u, 3u));
    CHECK(c.count[0] == 0.0f);
    CHECK(c.count[3] == 0.0f);
    CHECK(c.rest == 0.0f);
    CHECK(c.count[1] + c.count[2] == doctest::Approx(1e6f));
    CHECK(c.count[1] / 1e6f == doctest::Approx(0.75).epsilon(0.01));
    const auto d = glint::multinomial<8>(1e16f, std::array<float, 8>{}, glm::uvec3(4u, 5u, 6u));
    CHECK(d.rest == 1e16f);
    // The same within the one-pass draw's range (N from 4 to 31), where the scaled probabilities
    // sum to exactly 1 (their 32-bit sum wraps to 0).
    for (std::uint32_t i = 0; i < 100; ++i) {
        const auto e = glint::multinomial<4>(20.0f, std::array<float, 4>{-1.0f, 3.0f, 1.0f, 0.0f}, glm::uvec3(i, 2u, 3u));
        REQUIRE(e.count[0] == 0.0f);
        REQUIRE(e.count[3] == 0.0f);
        REQUIRE(e.rest == 0.0f);
        REQUIRE(e.count[1] + e.count[2] == 20.0f);
    }
}

TEST_CASE("a root cache gives exactly the uncached counts (runs of three draws at one N, as the IBL grid makes them)") {
    using MK = glint::detail::glsl::kernels<float>;
    MK::glint_multinomial_probabilities probs;
    for (int k = 0; k < 8; ++k) probs.p[k] = 0.03f * static_cast<float>(k + 1);
    long checked = 0, differ = 0;
    auto cache = MK::glint_binomial_empty_cache();
    for (float N : {2.5f, 3.0f, 7.0f, 14.0f, 40.0f, 1e3f, 1e6f})
        for (int K : {3, 4, 7, 8})
            for (std::uint32_t run = 0; run < 3; ++run) {
                const glm::uvec3 seed(run, static_cast<std::uint32_t>(K), 0x51u);
                const auto a = MK::glint_multinomial_cached(N, probs, K, seed, MK::GLINT_BINOMIAL_UNBIASED, MK::GLINT_POW_LOG1P, cache);
                const auto b = MK::glint_multinomial(N, probs, K, seed, MK::GLINT_BINOMIAL_UNBIASED, MK::GLINT_POW_LOG1P);
                bool same = a.rest == b.rest;
                for (int k = 0; k < 8; ++k) same = same && a.count[k] == b.count[k];
                differ += !same;
                ++checked;
            }
    MESSAGE(checked << " draws, " << differ << " differ");
    CHECK(checked == 84);
    CHECK(differ == 0);
}

TEST_CASE("the split tree: node q in the order the draw visits the nodes, the probabilities clamped and scaled as the draw needs") {
    using MK = glint::detail::glsl::kernels<double>;
    MK::glint_multinomial_probabilities pr;
    const double p[8] = {0.05, 0.1, -0.2, 0.15, 0.02, 0.08, 0.3, 0.9};  // a negative one, and the 8th beyond K = 7
    for (int k = 0; k < 8; ++k) pr.p[k] = p[k];
    // K = 7: bins 0..6 (the negative one as 0) sum to 0.7. Nodes breadth-first: [0,7) -> [0,3)
    // and [3,7); [0,3) -> {0} and [1,3); [3,7) -> [3,5) and [5,7); then [1,3), [3,5), [5,7).
    const auto t = MK::glint_multinomial_make_tree(pr, 7);
    CHECK(t.K == 7);
    CHECK(t.total == doctest::Approx(0.7).epsilon(1e-15));
    const double want[6] = {0.15 / 0.7, 0.05 / 0.15, 0.17 / 0.55, 0.1 / 0.1, 0.15 / 0.17, 0.08 / 0.38};
    for (int h = 0; h < 6; ++h) {
        CAPTURE(h);
        CHECK(t.q[h] == doctest::Approx(want[h]).epsilon(1e-14));
    }
    // K = 4 with probabilities summing to 2: scaled to 1, so the root keeps every trial.
    MK::glint_multinomial_probabilities big;
    for (int k = 0; k < 8; ++k) big.p[k] = 0.5;
    const auto t4 = MK::glint_multinomial_make_tree(big, 4);
    CHECK(t4.total == 1.0);
    CHECK(t4.q[0] == 0.5);
    // The draw through the tree is the draw from the probabilities, count for count.
    for (std::uint32_t i = 0; i < 200; ++i) {
        auto c1 = MK::glint_binomial_empty_cache(), c2 = MK::glint_binomial_empty_cache();
        const glm::uvec3 seed(i, 3u, 4u);
        const auto u = MK::glint_multinomial_node_words(seed, 0);
        const auto a = MK::glint_multinomial_draw(37.5, t, seed, u, MK::GLINT_BINOMIAL_UNBIASED, MK::GLINT_POW_LOG1P, c1);
        const auto b = MK::glint_multinomial_from_root(37.5, pr, 7, seed, u, MK::GLINT_BINOMIAL_UNBIASED, MK::GLINT_POW_LOG1P, c2);
        for (int k = 0; k < 8; ++k) REQUIRE(a.count[k] == b.count[k]);
        REQUIRE(a.rest == b.rest);
    }
}

namespace {

// Lane `lane` (0..31) of a bit-sliced word sequence as one 32-bit uniform: its digit k, from the
// most significant, is that bit of word k = glint_hash_u32(start + k step).
std::uint32_t lane_uniform(std::uint32_t start, std::uint32_t step, int lane) {
    std::uint32_t x = 0;
    for (std::uint32_t k = 0; k < 32; ++k) x |= ((glint::hash_u32(start + k * step) >> lane) & 1u) << (31 - k);
    return x;
}

// glint_multinomial_exact_split lane by lane: trial i's uniform X_i as a 32-bit integer whose
// digit k (from the most significant) is bit i mod 32 of word k of its lane group's sequence
// (lanes 0..31 from words.x, 32..63 from words.z, steps of words.y | 1), compared with q 2^32.
double exact_split_by_lanes(double n, double q, glm::uvec3 words) {
    if (!(q > 0) || !(n > 0)) return 0;
    if (q >= 1) return n;
    const int whole = static_cast<int>(n);
    const double frac = n - whole;
    const auto q_bits = static_cast<std::uint32_t>(q * 4294967296.0);
    const std::uint32_t step = words.y | 1u;
    double left = 0;
    for (int lane = 0; lane <= whole; ++lane) {
        const std::uint32_t start = lane < 32 ? words.x : words.z;
        if (lane_uniform(start, step, lane % 32) < q_bits) left += (lane < whole) ? 1.0 : frac;
    }
    return left;
}

}  // namespace

TEST_CASE("the exact split draws each trial from its own 32 digits, as a lane-by-lane comparison does") {
    using MK = glint::detail::glsl::kernels<double>;
    long checked = 0, differ = 0;
    double left_sum = 0, expected_sum = 0;
    for (double n : {0.0, 0.4, 1.0, 1.75, 2.0, 7.0, 19.5, 31.0, 31.5, 32.0, 40.25, 63.0})
        for (double q : {0.0, 1e-9, 0.013, 0.3, 0.5, 0.77, 0.999, 1.0})
            for (std::uint32_t i = 0; i < 300; ++i) {
                const glm::uvec3 words = glint::pcg3d(glm::uvec3(i, static_cast<std::uint32_t>(n * 4), static_cast<std::uint32_t>(q * 1e6)));
                const double a = MK::glint_multinomial_exact_split(n, q, words);
                const double b = exact_split_by_lanes(n, q, words);
                differ += a != b;
                ++checked;
                left_sum += a;
                expected_sum += n * q;
            }
    MESSAGE(checked << " splits, " << differ << " differ from the lane-by-lane draw");
    CHECK(checked == 12 * 8 * 300);
    CHECK(differ == 0);
    CHECK(left_sum == doctest::Approx(expected_sum).epsilon(0.02));  // the draws are not all 0 or n
    // float and double draw the same lanes (q 2^32 is exact in both; n - floor(n) too).
    using MF = glint::detail::glsl::kernels<float>;
    for (std::uint32_t i = 0; i < 2000; ++i) {
        const glm::uvec3 words = glint::pcg3d(glm::uvec3(i, 5u, 6u));
        const float n = 0.25f * static_cast<float>(i % 253), q = glint::unit_from_bits<float>(words.z);
        REQUIRE(static_cast<double>(MF::glint_multinomial_exact_split(n, q, words)) == MK::glint_multinomial_exact_split(n, static_cast<double>(q), words));
    }
}

namespace {

// glint_multinomial_exact_all lane by lane: trial i's uniform X_i as a 32-bit integer (digit k is
// bit i mod 32 of word k of its lane group's sequence: lanes 0..31 from words.x, 32..63 from
// words.z, steps of words.y | 1), placed in the first bin k with X_i < c_k, c_k = sum over m <= k
// of floor(p_m 2^32) in 64 bits (so c_k >= 2^32 holds every trial), else in the rest; the trial in
// lane floor(N) weighs frac(N).
template <std::size_t K>
std::array<double, K + 1> exact_all_by_lanes(double N, const std::array<double, K>& p, glm::uvec3 words) {
    std::array<double, K + 1> counts{};  // counts[K] is the rest
    const int whole = static_cast<int>(N);
    const double frac = N - whole;
    std::array<std::uint64_t, K> c{};
    std::uint64_t sum = 0;
    for (std::size_t k = 0; k < K; ++k) c[k] = sum += static_cast<std::uint64_t>(std::ldexp(p[k], 32));
    for (int lane = 0; lane <= whole; ++lane) {
        const std::uint64_t x = lane_uniform(lane < 32 ? words.x : words.z, words.y | 1u, lane % 32);
        std::size_t bin = 0;
        while (bin < K && !(x < c[bin])) ++bin;
        counts[bin] += (lane < whole) ? 1.0 : frac;
    }
    return counts;
}

template <std::size_t K>
void check_exact_all(long& checked, long& differ, double& first_bin, double& first_expected) {
    for (double N : {4.0, 5.5, 6.0, 13.0, 19.25, 30.0, 31.0, 31.5, 32.0, 40.75, 63.0})
        for (std::uint32_t trial = 0; trial < 200; ++trial) {
            const glm::uvec3 h = glint::pcg3d(glm::uvec3(trial, static_cast<std::uint32_t>(K), static_cast<std::uint32_t>(N * 4)));
            std::array<double, K> p;
            double total = 0;
            for (std::size_t k = 0; k < K; ++k) {
                const double u = glint::unit_from_bits<double>(glint::pcg3d(glm::uvec3(h.x, h.y, static_cast<std::uint32_t>(k))).z);
                // Zeros, tiny, and ordinary probabilities; every 8th set sums to exactly 1.
                p[k] = (u < 0.1) ? 0.0 : (u < 0.2) ? 1e-9 : u / static_cast<double>(K);
                total += p[k];
            }
            if (trial % 8 == 0 && total > 0)
                for (double& x : p) x = std::ldexp(std::floor(std::ldexp(x / total, 20)), -20);  // dyadic, sum 1 - a few 2^-20
            if (trial % 16 == 0) p[K - 1] = 1.0 - std::accumulate(p.begin(), p.end() - 1, 0.0);  // exactly 1 where dyadic
            if (N * std::accumulate(p.begin(), p.end(), 0.0) < 1) continue;  // the root's exact range only
            const glm::uvec3 seed(trial, 17u, static_cast<std::uint32_t>(K));
            const auto a = glint::multinomial<K>(N, p, seed);
            const auto b = exact_all_by_lanes<K>(N, p, glint::pcg3d(seed));  // the root's words: glint_multinomial_node_words(seed, 0)
            bool same = a.rest == b[K];
            for (std::size_t k = 0; k < K; ++k) same = same && a.count[k] == b[k];
            differ += !same;
            ++checked;
            first_bin += a.count[0];
            first_expected += N * p[0];
        }
}

}  // namespace

TEST_CASE("the one-pass draw puts each trial in the bin its 32 digits fall in, as a lane-by-lane comparison does") {
    long checked = 0, differ = 0;
    double first_bin = 0, first_expected = 0;
    check_exact_all<2>(checked, differ, first_bin, first_expected);
    check_exact_all<3>(checked, differ, first_bin, first_expected);
    check_exact_all<7>(checked, differ, first_bin, first_expected);
    check_exact_all<8>(checked, differ, first_bin, first_expected);
    MESSAGE(checked << " draws (N from 4 to 63, K = 2, 3, 7, 8), " << differ << " differ from the lane-by-lane draw");
    CHECK(checked >= 6000);
    CHECK(differ == 0);
    CHECK(first_bin == doctest::Approx(first_expected).epsilon(0.05));  // the draws are not all in one bin
}

// The W-group pass against W one-group passes: `pass` runs it (W = 4 or 8).
template <std::size_t W, class Pass>
void check_lane_group_pass(Pass pass) {
    using MF = glint::detail::glsl::kernels<float>;
    long groups = 0, differ = 0, batches = 0, two_passes = 0;
    for (int K : {2, 3, 4, 5, 6, 7, 8})  // every instantiation of the pass (T = K)
        for (std::uint32_t trial = 0; trial < 400; ++trial) {
            MF::glint_multinomial_probabilities pr;
            for (int k = 0; k < 8; ++k) {
                const float u = glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(trial, static_cast<std::uint32_t>(K), static_cast<std::uint32_t>(k))).x);
                pr.p[k] = (u < 0.1f) ? 0.0f : (trial % 5 == 0) ? u : u / static_cast<float>(K);  // every 5th set sums past 1
            }
            const auto t = MF::glint_multinomial_make_tree(pr, K);
            const auto c = MF::glint_multinomial_exact_all_thresholds(t);
            // W groups of different sizes (1 to 32 lanes, some empty) and words.
            std::uint32_t lanes[W], frac[W], state[W], step[W];
            for (std::size_t v = 0; v < W; ++v) {
                const glm::uvec3 h = glint::pcg3d(glm::uvec3(trial, static_cast<std::uint32_t>(v), 0x4242u));
                const int size = static_cast<int>(h.z % 34);  // 33: empty
                lanes[v] = size >= 33 ? 0u : size == 32 ? 0xffffffffu : (2u << size) - 1u;
                frac[v] = (size < 32 && h.z % 3 == 0) ? 1u << size : 0u;
                state[v] = h.x, step[v] = h.y | 1u;
            }
            ++batches;
            // Group v alone weighted (one-hot weights): its count in bin k, plus 1/2 where its
            // fractional trial fell in k, exactly in float. Bins k >= K are left as they were.
            for (std::size_t v = 0; v < W; ++v) {
                float weight[W] = {}, frac_weight[W] = {}, weighted[8];
                weight[v] = 1.0f, frac_weight[v] = 0.5f;
                for (int k = 0; k < 8; ++k) weighted[k] = -1.0f;
                two_passes += pass(c, t.K, lanes, frac, state, step, weight, frac_weight, weighted) == 2;
                const auto one = MF::glint_multinomial_exact_all_group(c, t.K, lanes[v], state[v], step[v]);
                // The bins of the one-group pass, as glint_multinomial_exact_all_counts reads them.
                std::uint32_t previous = 0;
                bool same = true;
                for (int k = 0; k < 8; ++k) {
                    const std::uint32_t in_bin = k < t.K ? one.mask[k] & ~previous : 0u;
                    previous = k < t.K ? one.mask[k] : previous;
                    const float expected = k < t.K ? static_cast<float>(MF::glint_bit_count(in_bin & ~frac[v])) + ((in_bin & frac[v]) ? 0.5f : 0.0f) - 1.0f
                                                   : -1.0f;
                    same = same && weighted[k] == expected;
                }
                differ += !same;
                ++groups;
            }
        }
    MESSAGE(batches << " sets of " << W << " groups, each group weighted alone: " << groups << " groups, " << differ
                    << " differ from their one-group pass; " << two_passes << " ran a second pass");
    CHECK(groups == 7 * 400 * static_cast<long>(W));
    CHECK(differ == 0);
}

TEST_CASE("C++'s four and eight lane groups at once give each group the counts of its own one-group pass") {
    glint_test::for_each_lanes_path([&](int) {
        using MF = glint::detail::glsl::kernels<float>;
        check_lane_group_pass<4>([](auto&&... a) { return MF::glint_multinomial_exact_all_groups_x4(a...); });
        // The eight-group pass compiled for the baseline target (two vectors of four), on any CPU...
        check_lane_group_pass<8>([](auto&&... a) { return MF::glint_multinomial_exact_all_groups<8>(a...); });
        // ... and for AVX2, where glint_multinomial_exact_all_weighted runs it (the CPU has AVX2).
        MESSAGE("eight-group pass with AVX2: " << std::string(MF::glint_cpu_avx2() ? "run" : "not run: not used here (a CPU without AVX2, or a build without the AVX2 path)"));
        if (MF::glint_cpu_avx2())
            check_lane_group_pass<8>([](auto&&... a) { return MF::glint_multinomial_exact_all_groups_x8(a...); });
    });
}

namespace {

// Thresholds made so that a trial lies between two that share their first 16 digits (a follower,
// left out of the first pass): lane 0 of group g has its first 16 digits equal to c_j's and c_(j+1)'s
// (c_j = those digits then 16 zeros, c_(j+1) = then 16 ones), so it is undecided after 16 digits and
// lies in bin j + 1 unless its last 16 digits are all ones. The pass must run again with every
// threshold (2 passes) and give each group its one-group counts; the first pass alone, not stopped,
// must not (`spoilt` counts the groups where it differs).
template <std::size_t W, class Pass>
void check_follower_pass(Pass pass, long& calls, long& two_passes, long& differ, long& spoilt) {
    using MF = glint::detail::glsl::kernels<float>;
    for (int K : {2, 3, 5, 8})
        for (std::uint32_t trial = 0; trial < 100; ++trial) {
            std::uint32_t lanes[W], frac[W], state[W], step[W];
            for (std::size_t v = 0; v < W; ++v) {
                const glm::uvec3 h = glint::pcg3d(glm::uvec3(trial, static_cast<std::uint32_t>(v), 0x5151u + static_cast<std::uint32_t>(K)));
                lanes[v] = 0xffffffffu, frac[v] = 0u, state[v] = h.x, step[v] = h.y | 1u;
            }
            const std::size_t g = trial % W;
            std::uint32_t digits = 0;  // lane 0's first 16 digits: bit 0 of the group's words
            for (std::uint32_t d = 0; d < 16; ++d) digits = (digits << 1) | (MF::glint_hash_u32(state[g] + d * step[g]) & 1u);
            const int j = static_cast<int>(trial % static_cast<std::uint32_t>(K - 1));  // c_j and c_(j+1) share 16 digits
            MF::glint_multinomial_thresholds c;
            const double low = std::ldexp(static_cast<double>(digits), 16), high = low + 65535.0;
            for (int k = 0; k < 8; ++k) {
                // Below c_j: evenly from 0; above c_(j+1): evenly up to 2^32 - 1.
                const double x = k < j ? low * (k + 1) / (j + 1) : k == j ? low : k == j + 1 ? high
                                       : high + (4294967295.0 - high) * (k - j - 1) / (8 - j - 1);
                c.c[k] = static_cast<std::uint32_t>(x);
                c.full[k] = false;
            }
            for (std::size_t v = 0; v < W; ++v) {
                float weight[W] = {}, frac_weight[W] = {}, weighted[8] = {}, first_only[8] = {};
                weight[v] = 1.0f;
                const int passes = pass(c, K, lanes, frac, state, step, weight, frac_weight, weighted);
                // The spoilt pass: the leaders alone (as glint_multinomial_exact_all_groups picks
                // them), never stopped.
                MF::glint_multinomial_thresholds leaders = c;
                int bin[8] = {}, count = 0;
                for (int k = 0; k < K; ++k) {
                    const bool follower = k > 0 && ((c.c[k - 1] ^ c.c[k]) >> 16) == 0u;
                    leaders.c[count] = c.c[k], bin[count] = k;
                    count += follower ? 0 : 1;
                }
                MF::glint_multinomial_exact_all_groups_of<W>(leaders, count, bin, 32, lanes, frac, state, step, weight, frac_weight, first_only);
                const auto one = MF::glint_multinomial_exact_all_group(c, K, lanes[v], state[v], step[v]);
                std::uint32_t previous = 0;
                bool same = true, same_first = true;
                for (int k = 0; k < K; ++k) {
                    const float expected = static_cast<float>(MF::glint_bit_count(one.mask[k] & ~previous));
                    previous = one.mask[k];
                    same = same && weighted[k] == expected;
                    same_first = same_first && first_only[k] == expected;
                }
                ++calls;
                two_passes += passes == 2;
                differ += !same;
                spoilt += !same_first;
            }
        }
}

}  // namespace

TEST_CASE("the lane-group pass leaves out thresholds within 2^16 of the one before only while no trial lies between them") {
    glint_test::for_each_lanes_path([&](int) {
        using MF = glint::detail::glsl::kernels<float>;
        long calls = 0, two_passes = 0, differ = 0, spoilt = 0;
        check_follower_pass<4>([](auto&&... a) { return MF::glint_multinomial_exact_all_groups_x4(a...); }, calls, two_passes, differ, spoilt);
        check_follower_pass<8>([](auto&&... a) { return MF::glint_multinomial_exact_all_groups<8>(a...); }, calls, two_passes, differ, spoilt);
        if (MF::glint_cpu_avx2())
            check_follower_pass<8>([](auto&&... a) { return MF::glint_multinomial_exact_all_groups_x8(a...); }, calls, two_passes, differ, spoilt);
        MESSAGE(calls << " groups weighted alone under thresholds with a trial between two that share 16 digits: " << two_passes
                      << " ran the second pass, " << differ << " differ from their one-group pass; without the stop after 16 digits "
                      << spoilt << " would");
        CHECK(calls >= 4 * 100 * 12);
        CHECK(two_passes == calls);  // every call has the trial between c_j and c_(j+1)
        CHECK(differ == 0);
        CHECK(spoilt >= 4 * 100 / 2);  // the trial's group in bin j + 1 at least (its other digits all ones: 2^-16)
    });
}
