// Input tables for the benchmarks: fixed, varied, and read through a mask so the compiler
// cannot fold the kernel into a constant.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glint/core.hpp>

namespace glint_bench {

constexpr std::size_t table_size = 4096;  // power of two: index with & (table_size - 1)

template <class real>
std::vector<real> uniform_table() {
    std::vector<real> v(table_size);
    for (std::size_t i = 0; i < table_size; ++i)
        v[i] = glint::open_unit_from_bits<real>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 1u, 2u)).x);
    return v;
}

// erfinv arguments: uniform on (-1, 1).
template <class real>
std::vector<real> signed_table() {
    std::vector<real> v = uniform_table<real>();
    for (real& x : v) x = real(2) * x - real(1);
    return v;
}

// (p, N) pairs log-uniform over p in [1e-16, 1], N in [1, 1e16]: the domain of KK25 Fig. 5.
template <class real>
void pn_tables(std::vector<real>& p, std::vector<real>& n) {
    p.resize(table_size);
    n.resize(table_size);
    for (std::size_t i = 0; i < table_size; ++i) {
        glm::uvec3 h = glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 3u, 4u));
        p[i] = static_cast<real>(std::pow(10.0, -16.0 * glint::unit_from_bits<double>(h.x)));
        n[i] = static_cast<real>(std::pow(10.0, 16.0 * glint::unit_from_bits<double>(h.y)));
    }
}

}  // namespace glint_bench
