// (1 - p)^N and 1 - (1 - p)^N in float against long double, on the grid of
// docs/pow_one_minus.md: p from 1e-16 to 1, N from 0 to 1e16.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include <glint/core.hpp>

#include "../support/core_reference.hpp"
#include "../support/ulp.hpp"

using doctest::Approx;
constexpr double LOG1P_MAX_ULP = 3.3;
constexpr double EXPM1_MAX_ULP = 1.3;
// glint_log2: five roundings of at most 2^-24 relative (core.glsl), at most 5 ulp of the result.
// Measured 3.00 (float) and 2.81 (double) on the sweep below.
constexpr double LOG2_MAX_ULP = 5;

namespace {

struct worst_error {
    double absolute = 0;  // of (1 - p)^N
    double relative = 0;  // of (1 - p)^N where it is at least 1e-30
    double complement_relative = 0;  // of 1 - (1 - p)^N
};

worst_error measure(glint::pow_method method) {
    worst_error w;
    for (double pd : glint_test::pow_grid_p())
        for (double nd : glint_test::pow_grid_n()) {
            const float p = static_cast<float>(pd), N = static_cast<float>(nd);
            const long double q = glint_test::pow_one_minus_exact(p, N);
            const long double s = glint_test::any_success_exact(p, N);
            const float fq = glint::pow_one_minus(p, N, method);
            const float fs = glint::any_success(p, N, method);
            REQUIRE(std::isfinite(fq));
            REQUIRE(std::isfinite(fs));
            const double ea = static_cast<double>(fabsl(fq - q));
            w.absolute = std::max(w.absolute, ea);
            if (q >= 1e-30L) w.relative = std::max(w.relative, static_cast<double>(ea / q));
            if (s > 0) w.complement_relative = std::max(w.complement_relative, static_cast<double>(fabsl(fs - s) / s));
        }
    return w;
}

}  // namespace

TEST_CASE("the grid spans the documented domain") {
    CHECK(glint_test::pow_grid_p().size() * glint_test::pow_grid_n().size() >= 2000u);
}

TEST_CASE("naive pow(1 - p, N) in float is 17% wrong at p = 1e-7, N = 1e7 (KK25 Fig. 5b)") {
    const float naive = glint::pow_one_minus(1e-7f, 1e7f, glint::pow_method::naive);
    const double exact = static_cast<double>(glint_test::pow_one_minus_exact(1e-7f, 1e7f));
    const double relative = std::fabs(static_cast<double>(naive) - exact) / exact;
    CHECK(relative > 0.15);
    CHECK(relative < 0.20);
    // The same point through the stable evaluations.
    CHECK(std::fabs(static_cast<double>(glint::pow_one_minus(1e-7f, 1e7f, glint::pow_method::log1p)) - exact) < 1e-6);
    CHECK(std::fabs(static_cast<double>(glint::pow_one_minus(1e-7f, 1e7f, glint::pow_method::kk25)) - exact) < 1e-4);
}

// Bounds documented in docs/pow_one_minus.md, measured maxima rounded up.
TEST_CASE("log1p / expm1 evaluation: within its documented bounds over the whole grid") {
    worst_error w = measure(glint::pow_method::log1p);
    MESSAGE("log1p: abs " << w.absolute << " rel " << w.relative << " complement rel " << w.complement_relative);
    CHECK(w.absolute <= 1e-7);
    // Relative error of exp(x) is |x| 2^-24 from rounding x alone; at the grid's smallest
    // results (about 1e-30, x = -69) that is 4e-6.
    CHECK(w.relative <= 1e-5);
    CHECK(w.complement_relative <= 3e-7);
}

TEST_CASE("KK25 Eq. 25: within its documented bounds, and its complement loses relative precision") {
    worst_error w = measure(glint::pow_method::kk25);
    MESSAGE("kk25: abs " << w.absolute << " rel " << w.relative << " complement rel " << w.complement_relative);
    CHECK(w.absolute <= 1e-4);
    CHECK(w.relative <= 2e-2);
    // 1 - (1 - cp)^(N/c) cancels when N p is below float epsilon: the gate probability is lost.
    CHECK(w.complement_relative >= 0.5);
}

TEST_CASE("naive evaluation fails on the grid, as KK25 Fig. 5 shows") {
    worst_error w = measure(glint::pow_method::naive);
    CHECK(w.absolute >= 0.5);
}

TEST_CASE("edge values: p = 0, p = 1, N = 0, out-of-domain inputs clamp") {
    for (auto m : {glint::pow_method::naive, glint::pow_method::kk25, glint::pow_method::log1p}) {
        CAPTURE(static_cast<int>(m));
        CHECK(glint::pow_one_minus(0.0f, 1e16f, m) == 1.0f);
        CHECK(glint::pow_one_minus(1.0f, 0.0f, m) == 1.0f);
        CHECK(glint::pow_one_minus(1.0f, 1e-3f, m) == 0.0f);
        CHECK(glint::pow_one_minus(0.5f, 0.0f, m) == 1.0f);
        CHECK(glint::any_success(0.0f, 1e16f, m) == 0.0f);
        CHECK(glint::any_success(1.0f, 0.0f, m) == 0.0f);
        CHECK(glint::any_success(1.0f, 2.0f, m) == 1.0f);
        // Out of domain: p < 0 acts as 0, p > 1 as 1, N < 0 as 0.
        CHECK(glint::pow_one_minus(-0.5f, 10.0f, m) == 1.0f);
        CHECK(glint::pow_one_minus(2.0f, 10.0f, m) == 0.0f);
        CHECK(glint::pow_one_minus(0.5f, -3.0f, m) == 1.0f);
        CHECK(std::isfinite(glint::pow_one_minus(0.5f, std::numeric_limits<float>::max(), m)));
        CHECK(std::isfinite(glint::any_success(std::numeric_limits<float>::denorm_min(), 1e16f, m)));
    }
}

TEST_CASE("double instantiation of the log1p evaluation is accurate to double rounding") {
    double worst = 0;
    for (double p : glint_test::pow_grid_p())
        for (double N : glint_test::pow_grid_n()) {
            const long double q = glint_test::pow_one_minus_exact(p, N);
            if (q < 1e-300L) continue;
            worst = std::max(worst, static_cast<double>(fabsl(glint::pow_one_minus(p, N) - q) / q));
        }
    MESSAGE("log1p double: max relative error " << worst);
    // x = N log1p(-p) reaches |x| = 690 on the grid. One rounding in log1p and one in the
    // product each perturb x by |x| 2^-53 relative, which exp turns into an absolute error of x:
    // 2 * 690 * 2^-53 = 1.53e-13 relative in the result, plus exp's own ulp.
    CHECK(worst <= 1.6e-13);
}

TEST_CASE("log1p and expm1 kernels against long double on sweeps, float and double") {
    using k_float = glint::detail::glsl::kernels<float>;
    using k_double = glint::detail::glsl::kernels<double>;
    double worst_log1p = 0, worst_expm1 = 0, worst_log1p_d = 0, worst_expm1_d = 0;
    // log1p on x in (-1, 1e6): every 50th float pattern of (-1, 0) and of (0, 1e6).
    auto check_log1p = [&](float x) {
        const long double exact = log1pl(static_cast<long double>(x));
        worst_log1p = std::max(worst_log1p, glint_test::ulp_error(k_float::glint_log1p(x), static_cast<double>(exact)));
        worst_log1p_d = std::max(worst_log1p_d, glint_test::ulp_error_double(k_double::glint_log1p(static_cast<double>(x)), exact));
    };
    for (std::uint32_t b = 0x00000001u; b < 0x3f800000u; b += 50u) check_log1p(-glint_test::float_from_bits(b));
    for (std::uint32_t b = 0x00000001u; b < 0x49742400u; b += 50u) check_log1p(glint_test::float_from_bits(b));
    // expm1 on x in (-100, 0): every 50th float pattern.
    for (std::uint32_t b = 0x00000001u; b < 0x42c80000u; b += 50u) {
        const float x = -glint_test::float_from_bits(b);
        const long double exact = expm1l(static_cast<long double>(x));
        worst_expm1 = std::max(worst_expm1, glint_test::ulp_error(k_float::glint_expm1_nonpositive(x), static_cast<double>(exact)));
        worst_expm1_d = std::max(worst_expm1_d, glint_test::ulp_error_double(k_double::glint_expm1_nonpositive(static_cast<double>(x)), exact));
    }
    MESSAGE("log1p max ulp float " << worst_log1p << " double " << worst_log1p_d << "; expm1 max ulp float "
                                   << worst_expm1 << " double " << worst_expm1_d);
    // Documented in docs/core_numerics.md (measured maxima rounded up).
    CHECK(worst_log1p <= LOG1P_MAX_ULP);
    CHECK(worst_log1p_d <= LOG1P_MAX_ULP);
    CHECK(worst_expm1 <= EXPM1_MAX_ULP);
    CHECK(worst_expm1_d <= EXPM1_MAX_ULP);
    // Out of domain: finite.
    CHECK(k_float::glint_log1p(-1.0f) == Approx(-87.3365f));
    CHECK(std::isfinite(k_float::glint_log1p(-5.0f)));
    CHECK(k_float::glint_expm1_nonpositive(3.0f) == 0.0f);
}

TEST_CASE("log2 kernel against long double on every 50th float, float and double, and its clamps out of domain") {
    using k_float = glint::detail::glsl::kernels<float>;
    using k_double = glint::detail::glsl::kernels<double>;
    double worst = 0, worst_d = 0;
    // Every 50th positive normal float pattern, 2^-126 to FLT_MAX (about 4.2e7 inputs).
    for (std::uint32_t b = 0x00800000u; b < 0x7f800000u; b += 50u) {
        const float x = glint_test::float_from_bits(b);
        const long double exact = log2l(static_cast<long double>(x));
        worst = std::max(worst, glint_test::ulp_error(k_float::glint_log2(x), static_cast<double>(exact)));
        worst_d = std::max(worst_d, glint_test::ulp_error_double(k_double::glint_log2(static_cast<double>(x)), exact));
    }
    MESSAGE("log2 max ulp float " << worst << " double " << worst_d);
    CHECK(worst <= LOG2_MAX_ULP);
    CHECK(worst_d <= LOG2_MAX_ULP);
    // Exact at powers of two (s = 0), and the clamp: 0, subnormals and negatives give -126, +inf 128.
    CHECK(k_float::glint_log2(1.0f) == 0.0f);
    CHECK(k_float::glint_log2(0.5f) == -1.0f);
    CHECK(k_float::glint_log2(1024.0f) == 10.0f);
    CHECK(k_float::glint_log2(0.0f) == -126.0f);
    CHECK(k_float::glint_log2(-3.0f) == -126.0f);
    CHECK(k_float::glint_log2(std::numeric_limits<float>::denorm_min()) == -126.0f);
    CHECK(k_float::glint_log2(std::numeric_limits<float>::infinity()) == Approx(128.0f));
}
