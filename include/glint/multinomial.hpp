// Multinomial sampling over K = 2..8 bins as a binary hierarchy of binomials (KK25 Sec. 6),
// generic over the binomial variant (kernels/multinomial.glsl documents the hierarchy).
//
//   auto c = glint::multinomial<4>(N, {p0, p1, p2, p3}, seed);            // mean-preserving
//   auto d = glint::multinomial<8>(N, p, seed, glint::binomial_variant::dual_gated);
//   c.count[k], c.rest
//
// Probabilities below 0 count as 0; if they sum to more than 1 they are scaled to sum to 1.
// The remainder 1 - sum p is the rest bin. For N > 2 the counts and the rest sum to N (up to
// rounding); for N < 2 the root dithers as the chosen variant does (KK25 Fig. 4). With the
// mean-preserving variant, whole N up to 63 (N sum p >= 1) give the exact multinomial law:
// nodes of 4 to 63 trials are drawn trial by trial, bit-sliced, and for N from 4 to 63 the
// whole draw is one such pass over every bin (kernels/multinomial.glsl).
#pragma once

#include <array>
#include <cstddef>

#include "glint/binomial.hpp"
#include "glint/detail/kernels.hpp"

namespace glint {

template <class real, std::size_t K>
struct multinomial_result {
    std::array<real, K> count;
    real rest;
};

template <std::size_t K, class real>
multinomial_result<real, K> multinomial(real N, const std::array<real, K>& p, glm::uvec3 seed,
                                        binomial_variant variant = binomial_variant::unbiased) {
    static_assert(K >= 2 && K <= 8, "glint::multinomial: K must be 2..8");
    return multinomial<K, real>(N, p, seed, variant, published_pow_method(variant));
}

template <std::size_t K, class real>
multinomial_result<real, K> multinomial(real N, const std::array<real, K>& p, glm::uvec3 seed, binomial_variant variant,
                                        pow_method method) {
    static_assert(K >= 2 && K <= 8, "glint::multinomial: K must be 2..8");
    using k = detail::glsl::kernels<real>;
    typename k::glint_multinomial_probabilities probs;
    for (std::size_t i = 0; i < 8; ++i) probs.p[i] = i < K ? p[i] : real(0);
    const auto c = k::glint_multinomial(N, probs, static_cast<int>(K), seed, static_cast<int>(variant), static_cast<int>(method));
    multinomial_result<real, K> r;
    for (std::size_t i = 0; i < K; ++i) r.count[i] = c.count[i];
    r.rest = c.rest;
    return r;
}

}  // namespace glint
