// Counter-based hashing and uniform variates (kernels/core.glsl), bit-exact with the GLSL path.
#pragma once

#include <cstdint>

#include "glint/detail/kernels.hpp"

namespace glint {

// PCG3D (Jarzynski and Olano 2020): a bijective hash of three 32-bit words.
inline glm::uvec3 pcg3d(glm::uvec3 v) { return detail::glsl::kernels<float>::glint_pcg3d(v); }

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

}  // namespace glint
