// Statistical tests of the hash-based uniform variates: 1D uniformity, serial independence of
// consecutive counters, independence of the three lanes of one hash, and independence of the
// grid's per (vertex, slope cell) draws (grid.glsl) across neighbouring cells, neighbouring
// vertices and their two words.
//
// Each test is a Pearson chi-square test of a histogram against the uniform distribution.
// Family-wise significance 0.01 over the 6 tests on glint's hashes, Sidak-corrected:
// alpha = 1 - 0.99^(1/6) = 0.00167 per test. Each test is shown to have power: a deliberately
// wrong variant (named in the test) must be rejected at the same alpha.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <glint/core.hpp>
#include <glint/grid.hpp>
#include <glint/testing/stats.hpp>

namespace {

const double alpha = glint::testing::sidak_alpha(0.01, 6);

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

// The grid's draws (grid.glsl): a vertex's words are PCG3D of its lattice coordinates and its
// lattice key, a slope cell's key is glint_slope_cell_key, a draw's first word
// glint_cell_draw_word(vertex x word, cell key) and its second glint_cell_draw_second_word(first,
// vertex y word). Each check bins 2^22 pairs of top-6-bit values in 64 x 64 bins (1024 expected
// per bin): it resolves a density error of +-1.5% over half the bins (the statistic's excess
// 4096 * 0.015^2 * 1024 = 944 is 10 standard deviations of the null's sqrt(2 * 4095) = 90).
using K = glint::detail::glsl::kernels<float>;
using draw_word_fn = std::function<std::uint32_t(std::uint32_t vertex_word, std::uint32_t cell_key)>;
using second_word_fn = std::function<std::uint32_t(std::uint32_t first, std::uint32_t vertex_word)>;

// A vertex's words as glint_footprint_vertices hashes them: its coordinates and the lattice key of
// LOD 0, level 0, bin 0 (0 + 64 = 0x40) XOR a seed (here 0x9e3779b9).
glm::uvec3 vertex_words(std::uint32_t x, std::uint32_t y) { return glint::pcg3d(glm::uvec3(x, y, 0x40u ^ 0x9e3779b9u)); }

// Pairs over vertices (i mod 2048, i / 2048) and one cell c = (5, -3) (many cells would mix the
// wrong variants' relations into an even histogram): the first words of the draw at (vertex, c)
// and at (vertex + dv, c + dc).
double cell_pairs(const draw_word_fn& draw, bool hash_vertices, glm::ivec2 dv, glm::ivec2 dc) {
    const std::uint32_t n = 1u << 22;
    std::vector<std::uint64_t> counts(64 * 64);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t vx = i % 2048u, vy = i / 2048u;
        const glm::ivec2 c(5, -3);
        const auto word = [&](std::uint32_t x, std::uint32_t y, glm::ivec2 cell) {
            const std::uint32_t vw = hash_vertices ? vertex_words(x, y).x : x + 2048u * y;
            return draw(vw, K::glint_slope_cell_key(cell));
        };
        const std::uint32_t a = word(vx, vy, c), b = word(vx + static_cast<std::uint32_t>(dv.x), vy + static_cast<std::uint32_t>(dv.y), c + dc);
        counts[(a >> 26) * 64 + (b >> 26)]++;
    }
    return uniform_p_value(counts, n);
}

// Pairs of the first and second word of one draw.
double word_pairs(const second_word_fn& second) {
    const std::uint32_t n = 1u << 22;
    std::vector<std::uint64_t> counts(64 * 64);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::uvec3 v = vertex_words(i % 2048u, i / 2048u);
        const std::uint32_t a = K::glint_cell_draw_word(v.x, K::glint_slope_cell_key(glm::ivec2(static_cast<int>(i % 7u), 3))), b = second(a, v.y);
        counts[(a >> 26) * 64 + (b >> 26)]++;
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

TEST_CASE("the grid's draws at neighbouring slope cells and neighbouring vertices are independent") {
    const draw_word_fn glint_draw = [](std::uint32_t v, std::uint32_t c) { return K::glint_cell_draw_word(v, c); };
    // Wrong on purpose: the vertex word and the cell key combined without the finaliser, whose
    // XOR leaves a fixed relation between the words of two cells.
    const draw_word_fn xor_only = [](std::uint32_t v, std::uint32_t c) { return v ^ c; };
    for (glm::ivec2 dc : {glm::ivec2(1, 0), glm::ivec2(0, 1), glm::ivec2(1, 1)}) {
        const double p = cell_pairs(glint_draw, true, glm::ivec2(0), dc);
        MESSAGE("cells (" << dc.x << ", " << dc.y << ") apart: p-value " << p << ", alpha " << alpha / 3);
        CHECK(p > alpha / 3);
        CHECK(cell_pairs(xor_only, true, glm::ivec2(0), dc) < alpha / 3);
    }
}

TEST_CASE("the grid's draws of one slope cell at neighbouring vertices are independent") {
    const draw_word_fn glint_draw = [](std::uint32_t v, std::uint32_t c) { return K::glint_cell_draw_word(v, c); };
    const double p = cell_pairs(glint_draw, true, glm::ivec2(1, 0), glm::ivec2(0));
    MESSAGE("p-value " << p << ", alpha " << alpha);
    CHECK(p > alpha);
    // Wrong on purpose: vertex words that are counters, not hashes of the vertex, XOR the key.
    CHECK(cell_pairs([](std::uint32_t v, std::uint32_t c) { return v ^ c; }, false, glm::ivec2(1, 0), glm::ivec2(0)) < alpha);
}

TEST_CASE("the two words of one grid draw are independent") {
    const double p = word_pairs([](std::uint32_t a, std::uint32_t v) { return K::glint_cell_draw_second_word(a, v); });
    MESSAGE("p-value " << p << ", alpha " << alpha);
    CHECK(p > alpha);
    // Wrong on purpose: the second word a shift of the first (u2 = 2 u1 mod 1).
    CHECK(word_pairs([](std::uint32_t a, std::uint32_t) { return a << 1; }) < alpha);
}
