// Stable (1 - p)^N and P(n >= 1) = 1 - (1 - p)^N (kernels/core.glsl), the gate probabilities of
// the binomial samplers. docs/pow_one_minus.md compares the methods in float.
#pragma once

#include "glint/core/kernels.hpp"

namespace glint {

enum class pow_method {
    naive,  // pow(1 - p, N): wrong in float for p < 2^-25 and N > 1/p (KK25 Fig. 5b)
    kk25,   // KK25 Eq. 25 with epsilon = 10^-3.54
    log1p,  // exp(N log1p(-p)) and -expm1(N log1p(-p)): the most accurate
};

// (1 - p)^N. p is clamped to [0, 1] and N to [0, inf); (1 - 1)^0 = 1.
template <class real>
real pow_one_minus(real p, real N, pow_method method = pow_method::log1p) {
    using k = detail::glsl::core_kernels<real>;
    switch (method) {
        case pow_method::naive: return k::glint_pow_one_minus_naive(p, N);
        case pow_method::kk25: return k::glint_pow_one_minus_kk25(p, N);
        case pow_method::log1p: break;
    }
    return k::glint_pow_one_minus_log1p(p, N);
}

// 1 - (1 - p)^N, the probability that N Bernoulli(p) trials give at least one success.
// With pow_method::log1p it is -expm1(N log1p(-p)), accurate also when N p is tiny.
template <class real>
real any_success(real p, real N, pow_method method = pow_method::log1p) {
    using k = detail::glsl::core_kernels<real>;
    switch (method) {
        case pow_method::naive: return k::glint_any_success_naive(p, N);
        case pow_method::kk25: return k::glint_any_success_kk25(p, N);
        case pow_method::log1p: break;
    }
    return k::glint_any_success_expm1(p, N);
}

}  // namespace glint
