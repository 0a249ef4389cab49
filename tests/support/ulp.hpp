// Error measures shared by the tests and the accuracy report.
#pragma once

#include <cmath>
#include <limits>

namespace glint_test {

// Error of a float result in units of the float spacing at the exact value `exact`
// (fractional: 0.5 means correctly rounded at worst).
inline double ulp_error(float computed, double exact) {
    double a = std::fabs(exact);
    double spacing = (a < static_cast<double>(std::numeric_limits<float>::min()))
                         ? std::ldexp(1.0, -149)
                         : std::ldexp(1.0, std::ilogb(a) - 23);
    return std::fabs(static_cast<double>(computed) - exact) / spacing;
}

// The same for a double result, in units of the double spacing.
inline double ulp_error_double(double computed, long double exact) {
    long double a = fabsl(exact);
    long double spacing = (a < static_cast<long double>(std::numeric_limits<double>::min()))
                              ? ldexpl(1.0L, -1074)
                              : ldexpl(1.0L, ilogbl(a) - 52);
    return static_cast<double>(fabsl(static_cast<long double>(computed) - exact) / spacing);
}

}  // namespace glint_test
