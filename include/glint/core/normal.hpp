// erfinv and the standard normal quantile (kernels/core.glsl). Both use Giles' single-precision
// polynomial, so the double instantiation has single-precision accuracy; docs/core_numerics.md
// has the measured error.
#pragma once

#include "glint/detail/kernels.hpp"

namespace glint {

// Inverse error function. Domain (-1, 1); |x| >= 1 - 2^-24 returns +-erfinv(1 - 2^-24) = +-3.8325.
template <class real>
real erfinv(real x) {
    return detail::glsl::kernels<real>::glint_erfinv(x);
}

// Standard normal quantile Phi^-1(u). Domain (0, 1); u <= 2^-25 returns -5.4200 and
// u >= 1 - 2^-25 returns +5.4200, the quantiles at those bounds.
template <class real>
real normal_quantile(real u) {
    return detail::glsl::kernels<real>::glint_normal_quantile(u);
}

// erfc(x) (Numerical Recipes' erfcc, relative error below 1.2e-7) and the standard normal CDF.
template <class real>
real erfc(real x) {
    return detail::glsl::kernels<real>::glint_erfc(x);
}

template <class real>
real normal_cdf(real t) {
    return detail::glsl::kernels<real>::glint_normal_cdf(t);
}

}  // namespace glint
