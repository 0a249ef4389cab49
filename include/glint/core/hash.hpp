// Counter-based hashing and uniform variates (kernels/core.glsl), bit-exact with the GLSL path;
// and Morton codes.
#pragma once

#include <cstdint>

#include "glint/detail/kernels.hpp"

namespace glint {

// PCG3D (Jarzynski and Olano 2020): a bijective hash of three 32-bit words.
inline glm::uvec3 pcg3d(glm::uvec3 v) { return detail::glsl::kernels<float>::glint_pcg3d(v); }

// Wellons' lowbias32: a bijective hash of one 32-bit word, two multiplies (grid.glsl's per slope
// cell draws).
inline std::uint32_t hash_u32(std::uint32_t x) { return detail::glsl::kernels<float>::glint_hash_u32(x); }

// k * 2^-24 in [0, 1) from the top 24 bits of h. Exact for float and double.
template <class real = float>
real unit_from_bits(std::uint32_t h) {
    return detail::glsl::kernels<real>::glint_unit_from_bits(h);
}

// (2k + 1) * 2^-24 in [2^-24, 1 - 2^-24] from the top 23 bits of h: never 0 or 1.
template <class real = float>
real open_unit_from_bits(std::uint32_t h) {
    return detail::glsl::kernels<real>::glint_open_unit_from_bits(h);
}

// The Morton (Z-order) code of (x, y), the low 16 bits of each interleaved, x in the even bits:
// the order of the P-NDF hierarchies' position trees (gaussian.hpp, lobe_tree.hpp).
inline std::uint32_t morton2(std::uint32_t x, std::uint32_t y) {
    const auto spread = [](std::uint32_t v) {
        v &= 0xffffu;
        v = (v | (v << 8)) & 0x00ff00ffu;
        v = (v | (v << 4)) & 0x0f0f0f0fu;
        v = (v | (v << 2)) & 0x33333333u;
        v = (v | (v << 1)) & 0x55555555u;
        return v;
    };
    return spread(x) | (spread(y) << 1);
}

}  // namespace glint
