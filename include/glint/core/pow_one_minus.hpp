// Stable (1 - p)^N and P(n >= 1) = 1 - (1 - p)^N (kernels/core.glsl), the gate probabilities of
// the binomial samplers. docs/pow_one_minus.md compares the methods in float.
#pragma once

#include "glint/detail/kernels.hpp"

namespace glint {

enum class pow_method {
    naive = 0,  // pow(1 - p, N): wrong in float for p < 2^-25 and N > 1/p (KK25 Fig. 5b)
    kk25 = 1,   // KK25 Eq. 25 with epsilon = 10^-3.54
    log1p = 2,  // exp(N log1p(-p)) and -expm1(N log1p(-p)): the most accurate
};

// (1 - p)^N. p is clamped to [0, 1] and N to [0, inf); (1 - 1)^0 = 1.
template <class real>
real pow_one_minus(real p, real N, pow_method method = pow_method::log1p) {
    return detail::glsl::kernels<real>::glint_pow_one_minus(p, N, static_cast<int>(method));
}

// 1 - (1 - p)^N, the probability that N Bernoulli(p) trials give at least one success.
// With pow_method::log1p it is -expm1(N log1p(-p)), accurate also when N p is tiny.
template <class real>
real any_success(real p, real N, pow_method method = pow_method::log1p) {
    return detail::glsl::kernels<real>::glint_any_success(p, N, static_cast<int>(method));
}

}  // namespace glint
