// Statistical tests of the hash-based uniform variates: 1D uniformity, serial independence of
// consecutive counters, and independence of the three lanes of one hash.
//
// Each test is a Pearson chi-square test of a histogram against the uniform distribution.
// Family-wise significance 0.01 over the 3 tests on glint's hash, Sidak-corrected:
// alpha = 1 - 0.99^(1/3) = 0.00334 per test. Each test is shown to have power: a deliberately
// wrong variant (named in the test) must be rejected at the same alpha.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <glint/core.hpp>
#include <glint/testing/stats.hpp>

namespace {

const double alpha = glint::testing::sidak_alpha(0.01, 3);

// Upper-tail p-value of Pearson's statistic for a histogram against equal expectations.
double uniform_p_value(const std::vector<std::uint64_t>& counts, std::uint64_t total) {
    const double expected = static_cast<double>(total) / static_cast<double>(counts.size());
    REQUIRE(expected >= 5.0);  // the chi-square approximation holds without pooling
    std::vector<double> observed(counts.begin(), counts.end());
    std::vector<double> p(counts.size(), 1.0 / static_cast<double>(counts.size()));
    return glint::testing::chi_square(observed, p).p_value;
}

using hash_fn = std::function<glm::uvec3(glm::uvec3)>;

glm::uvec3 glint_hash(glm::uvec3 v) { return glint::pcg3d(v); }
// Wrong on purpose: only the LCG step of PCG3D, no mixing between lanes or bits.
glm::uvec3 lcg_only(glm::uvec3 v) { return v * 1664525u + 1013904223u; }

// 1D: 2^22 samples of lane x for counters (i, 0, 0) in 1024 bins (4096 expected per bin).
// Resolves a density error of +-1% over half the bins: the statistic's excess is then
// 1024 * 0.01^2 * 4096 = 419, 9 standard deviations of the null's sqrt(2 * 1023) = 45.
double one_dimensional(const std::function<float(std::uint32_t)>& variate) {
    const std::uint64_t n = 1u << 22;
    std::vector<std::uint64_t> counts(1024);
    for (std::uint32_t i = 0; i < n; ++i) {
        float u = variate(i);
        counts[std::min<std::size_t>(1023, static_cast<std::size_t>(u * 1024.0f))]++;
    }
    return uniform_p_value(counts, n);
}

// 2D: pairs (u(i), u(i + 1)) of lane x for consecutive counters, 64 x 64 bins, 2^22 pairs.
double serial_pairs(const hash_fn& hash) {
    const std::uint64_t n = 1u << 22;
    std::vector<std::uint64_t> counts(64 * 64);
    for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t a = hash(glm::uvec3(i, 0u, 0u)).x, b = hash(glm::uvec3(i + 1u, 0u, 0u)).x;
        counts[(a >> 26) * 64 + (b >> 26)]++;
    }
    return uniform_p_value(counts, n);
}

// 3D: the three lanes of one hash, 16 x 16 x 16 bins, 2^22 hashes of counters (i, 7, 0).
double lanes(const hash_fn& hash) {
    const std::uint64_t n = 1u << 22;
    std::vector<std::uint64_t> counts(16 * 16 * 16);
    for (std::uint32_t i = 0; i < n; ++i) {
        glm::uvec3 h = hash(glm::uvec3(i, 7u, 0u));
        counts[((h.x >> 28) * 16 + (h.y >> 28)) * 16 + (h.z >> 28)]++;
    }
    return uniform_p_value(counts, n);
}

}  // namespace

TEST_CASE("1D uniformity of unit_from_bits(pcg3d(counter))") {
    const double p = one_dimensional([](std::uint32_t i) { return glint::unit_from_bits<float>(glint_hash(glm::uvec3(i, 0u, 0u)).x); });
    MESSAGE("p-value " << p << ", alpha " << alpha);
    CHECK(p > alpha);
    // Power: the same variates with density 1.01 on [0, 1/2) and 0.99 on [1/2, 1).
    const double p_wrong = one_dimensional([](std::uint32_t i) {
        float u = glint::unit_from_bits<float>(glint_hash(glm::uvec3(i, 0u, 0u)).x);
        return u < 0.505f ? u / 1.01f : 0.5f + (u - 0.505f) / 0.99f;
    });
    CHECK(p_wrong < alpha);
}

TEST_CASE("serial independence of consecutive counters") {
    const double p = serial_pairs(glint_hash);
    MESSAGE("p-value " << p << ", alpha " << alpha);
    CHECK(p > alpha);
    CHECK(serial_pairs(lcg_only) < alpha);
}

TEST_CASE("independence of the three lanes of one hash") {
    const double p = lanes(glint_hash);
    MESSAGE("p-value " << p << ", alpha " << alpha);
    CHECK(p > alpha);
    CHECK(lanes(lcg_only) < alpha);
}
