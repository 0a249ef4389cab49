// PCG3D and the uniform variates built on it.
#include <doctest/doctest.h>

#include "../support/lanes_paths.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_set>
#include <vector>

#include <glint/core.hpp>

namespace {

// PCG3D written out independently of the kernel, word by word, from Jarzynski and Olano 2020
// (JCGT 9(3), Listing "pcg3d"): the LCG step, two cross-multiply rounds around a xorshift.
void pcg3d_reference(std::uint32_t& x, std::uint32_t& y, std::uint32_t& z) {
    const std::uint32_t a = 1664525u, c = 1013904223u;
    x = x * a + c;
    y = y * a + c;
    z = z * a + c;
    for (int round = 0; round < 2; ++round) {
        x += y * z;
        y += z * x;
        z += x * y;
        if (round == 0) {
            x ^= x >> 16;
            y ^= y >> 16;
            z ^= z >> 16;
        }
    }
}

}  // namespace

TEST_CASE("pcg3d matches an independent word-by-word implementation on 1e6 inputs") {
    std::uint32_t state = 12345u;
    for (int i = 0; i < 1000000; ++i) {
        // Inputs: small counters (the common case in shaders) and scrambled words.
        std::uint32_t x = (i % 2) ? static_cast<std::uint32_t>(i) : state * 2654435761u;
        std::uint32_t y = static_cast<std::uint32_t>(i) ^ 0x9e3779b9u, z = state;
        state = state * 747796405u + 2891336453u;
        glm::uvec3 k = glint::pcg3d(glm::uvec3(x, y, z));
        pcg3d_reference(x, y, z);
        REQUIRE(k.x == x);
        REQUIRE(k.y == y);
        REQUIRE(k.z == z);
    }
}

// C++'s batched PCG3D (glint_pcg3d_many: a pixel's grid vertices four or eight at a time in
// vector registers, from three arrays into three others) against the reference, every count from 0
// to 12; outputs past the count either left as they were or hashed (a block of lanes hashes them all).
template <class Many>
void check_pcg3d_many(Many many) {
    long words = 0, differ = 0;
    std::uint32_t state = 99u;
    for (int round = 0; round < 20000; ++round) {
        const int count = round % 13;
        std::uint32_t x[12], y[12], z[12];
        std::uint32_t ref[12][3];
        for (int i = 0; i < 12; ++i) {
            for (int c = 0; c < 3; ++c) {
                state = state * 747796405u + 2891336453u;
                ref[i][c] = (round % 3 == 0) ? (state >> 24) : state;  // small counters and scrambled words
            }
            x[i] = ref[i][0], y[i] = ref[i][1], z[i] = ref[i][2];
            if (i < count) pcg3d_reference(ref[i][0], ref[i][1], ref[i][2]);
        }
        std::uint32_t hx[12], hy[12], hz[12];
        std::memcpy(hx, x, sizeof(x)), std::memcpy(hy, y, sizeof(y)), std::memcpy(hz, z, sizeof(z));
        many(x, y, z, count, hx, hy, hz);
        for (int i = 0; i < 12; ++i) {
            bool same = hx[i] == ref[i][0] && hy[i] == ref[i][1] && hz[i] == ref[i][2];
            if (i >= count && !same) {  // past the count: hashed with its block
                std::uint32_t h[3] = {ref[i][0], ref[i][1], ref[i][2]};
                pcg3d_reference(h[0], h[1], h[2]);
                same = hx[i] == h[0] && hy[i] == h[1] && hz[i] == h[2];
            }
            differ += !same;
            ++words;
        }
    }
    MESSAGE(words << " words, " << differ << " differ from the reference");
    CHECK(words == 20000 * 12);
    CHECK(differ == 0);
}

TEST_CASE("C++'s batched pcg3d (four or eight words at once) equals the reference word by word") {
    glint_test::for_each_lanes_path([&](int) {
        using K = glint::detail::glsl::kernels<float>;
        using u32 = std::uint32_t;
        // Eight words at once compiled for the baseline target (two vectors of four), on any CPU...
        check_pcg3d_many([](const u32* x, const u32* y, const u32* z, int n, u32* hx, u32* hy, u32* hz) { K::glint_pcg3d_lanes<8>(x, y, z, n, hx, hy, hz); });
        // ... and for AVX2 (GCC on x86-64), run where the CPU has it, as glint_pcg3d_many runs it;
        // elsewhere glint_pcg3d_many hashes one word at a time.
        MESSAGE("eight words at once with AVX2: " << std::string(K::glint_cpu_avx2() ? "run" : "not run (a CPU without AVX2, or a build without the AVX2 path)"));
        if (K::glint_cpu_avx2())
            check_pcg3d_many([](const u32* x, const u32* y, const u32* z, int n, u32* hx, u32* hy, u32* hz) { K::glint_pcg3d_many_x8(x, y, z, n, hx, hy, hz); });
        check_pcg3d_many([](const u32* x, const u32* y, const u32* z, int n, u32* hx, u32* hy, u32* hz) { K::glint_pcg3d_many(x, y, z, n, hx, hy, hz); });
    });
}

TEST_CASE("pcg3d is injective on a 2^16-point lattice of counters") {
    std::unordered_set<std::uint64_t> seen;
    for (std::uint32_t i = 0; i < 256; ++i)
        for (std::uint32_t j = 0; j < 256; ++j) {
            glm::uvec3 h = glint::pcg3d(glm::uvec3(i, j, 7u));
            seen.insert((static_cast<std::uint64_t>(h.x) << 32) ^ h.y ^ (static_cast<std::uint64_t>(h.z) << 11));
        }
    CHECK(seen.size() == 65536u);
}

TEST_CASE("unit_from_bits covers the unit interval in steps of 2^-24, for float and double") {
    CHECK(glint::unit_from_bits<float>(0u) == 0.0f);
    CHECK(glint::unit_from_bits<float>(0xffffffffu) == 1.0f - 0x1p-24f);
    CHECK(glint::unit_from_bits<double>(0xffffffffu) == 1.0 - 0x1p-24);
    CHECK(glint::unit_from_bits<float>(0x100u) == 0x1p-24f);
    // Only the top 24 bits matter.
    CHECK(glint::unit_from_bits<float>(0x123456ffu) == glint::unit_from_bits<float>(0x12345600u));
}

TEST_CASE("open_unit_from_bits never gives 0 or 1 and is symmetric under bit inversion") {
    CHECK(glint::open_unit_from_bits<float>(0u) == 0x1p-24f);
    CHECK(glint::open_unit_from_bits<float>(0xffffffffu) == 1.0f - 0x1p-24f);
    for (std::uint32_t k = 0; k < (1u << 23); k += 4099u) {
        std::uint32_t h = k << 9;
        float u = glint::open_unit_from_bits<float>(h);
        REQUIRE(u > 0.0f);
        REQUIRE(u < 1.0f);
        // (2k + 1) + (2 (2^23 - 1 - k) + 1) = 2^24: u(h) + u(~h) is exactly 1.
        REQUIRE(u + glint::open_unit_from_bits<float>(~h) == 1.0f);
        REQUIRE(static_cast<double>(u) == glint::open_unit_from_bits<double>(h));
    }
}

namespace {

// lowbias32 written out from Wellons' description ("Prospecting for Hash Functions", 2018): an
// xorshift by 16, a multiply by 0x7feb352d, an xorshift by 15, a multiply by 0x846ca68b, an
// xorshift by 16.
std::uint32_t lowbias32_reference(std::uint32_t x) {
    const std::uint32_t multipliers[2] = {0x7feb352du, 0x846ca68bu};
    const int shifts[3] = {16, 15, 16};
    for (int step = 0; step < 2; ++step) {
        x ^= x >> shifts[step];
        x *= multipliers[step];
    }
    return x ^ (x >> shifts[2]);
}

// The inverse of an odd multiplier modulo 2^32 by Newton's iteration y <- y (2 - a y), which
// doubles the correct low bits each step (a is its own inverse modulo 8: 3 bits to start).
std::uint32_t inverse_mod_2_32(std::uint32_t a) {
    std::uint32_t y = a;
    for (int i = 0; i < 4; ++i) y *= 2u - a * y;
    return y;
}

// The inverse of y = x ^ (x >> s): x = y ^ (y >> s) ^ (y >> 2s) ^ ... (the sum telescopes to
// x ^ (x >> ks) with ks >= 32).
std::uint32_t unxorshift(std::uint32_t y, int s) {
    std::uint32_t x = y;
    for (int k = s; k < 32; k += s) x ^= y >> k;
    return x;
}

}  // namespace

TEST_CASE("hash_u32 matches lowbias32 written out step by step, and is inverted by the inverse steps on 1e6 inputs") {
    const std::uint32_t inv1 = inverse_mod_2_32(0x7feb352du), inv2 = inverse_mod_2_32(0x846ca68bu);
    REQUIRE(inv1 * 0x7feb352du == 1u);
    REQUIRE(inv2 * 0x846ca68bu == 1u);
    std::uint32_t state = 99u;
    for (int i = 0; i < 1000000; ++i) {
        const std::uint32_t x = (i % 2) ? static_cast<std::uint32_t>(i) : state;
        state = state * 747796405u + 2891336453u;
        const std::uint32_t h = glint::hash_u32(x);
        REQUIRE(h == lowbias32_reference(x));
        // Undo the steps in reverse order: a bijection, so distinct words never collide.
        std::uint32_t y = unxorshift(h, 16);
        y *= inv2;
        y = unxorshift(y, 15);
        y *= inv1;
        y = unxorshift(y, 16);
        REQUIRE(y == x);
    }
}
