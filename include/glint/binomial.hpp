// Constant-time approximate sampling of the binomial distribution b(N, p) for real N >= 0, as
// glint renders microfacet counts (kernels/binomial.glsl; GLSL users include core.glsl first).
//
// The variants, all taking (N, p, u1, u2) with u1, u2 uniform in (0, 1) (for example from
// glint::open_unit_from_bits) and returning {positive, negative}:
//
//   binomial_ungated      a clamped Gaussian with the binomial's mean and variance
//   binomial_gated_db23   DB23's gated Gaussian, KK25 Eq. 22 (floored; integer N >= 1)
//   binomial_gated        KK25 Eq. 23, gated for real N including N < 1; negative = N - positive
//                         (clamped at 0)
//   binomial_dual_gated   KK25 Alg. 1, symmetric in positive and negative outcomes
//   binomial_unbiased     glint's mean-preserving dual-gated sampler (below); the default
//
// Domain: N is clamped to [0, inf) (binomial_unbiased: [0, 1e18]), p to [0, 1]; u1, u2 should lie in (0, 1) (0 and 1 work but
// sit on the boundary of the gates and of the quantile's clamp). No variant allocates, throws,
// or returns NaN or Inf for finite input.
//
// Real-valued N. Every variant is exact in distribution at N = 0, 1 and 2 except where noted,
// and continuous in N. For N < 2 the dual-gated variants dither between the outcomes of the two
// neighbouring integers (KK25 Fig. 4), so positive + negative may differ from N there; for
// N > 2, positive + negative = N up to rounding. E[positive] = N p holds for every real N for the
// dual-gated variants with N <= 2 and for binomial_unbiased everywhere; the target for real N is
// the randomised-rounding binomial (b(floor N, p) or b(floor N + 1, p) with the fractional part
// as probability), which glint::testing::binomial_exact samples.
//
// The bias of the published variants and its fix. After a gate that guarantees at least one
// positive and one negative outcome, KK25 Alg. 1 draws the rest from N(1 + (N - 2) p,
// (N - 2) p (1 - p)) clamped to [1, N - 1]. But the binomial conditioned on 1 <= n <= N - 1 has
// a different mean, and the clamp at 1 shifts the Gaussian's mean up further: at (N, p) =
// (100, 1e-2) the dual-gated E[n] is 31% above N p. binomial_unbiased keeps Alg. 1's gates
// (P(n = 0) = (1 - p)^N and P(n = N) = p^N exactly) and replaces the middle part:
//
// 1. Moments of the middle. With A = P(n >= 1) = 1 - (1 - p)^N, the factorial moments
//    E[n] = N p and E[n (n - 1)] = N (N - 1) p^2 give, for y = n - 1 on M = {1 <= n <= N - 1},
//    P(M) = A - p^N,
//    E[y 1_M] = (N p - A) - (N - 1) p^N,
//    E[y (y - 1) 1_M] = N (N - 1) p^2 - 2 (N p - A) - (N - 1)(N - 2) p^N,
//    hence m = E[y | M] and v = Var[y | M] in closed form.
// 2. A one-sided clamped Gaussian with exactly these moments. Measure the offset from the
//    nearer bound (1, or N - 1 when m is past the middle) and draw it as sigma max(t + Z, 0). For
//    a standard normal Z, E[max(t + Z, 0)] = psi(t) = t Phi(t) + phi(t) and
//    E[max(t + Z, 0)^2] = chi(t) = (t^2 + 1) Phi(t) + t phi(t), so the squared coefficient of
//    variation chi / psi^2 - 1 depends on t alone and decreases monotonically from +inf to 0.
//    t solves chi(t) / psi(t)^2 - 1 = v / m^2 (a fitted inverse, glint_clamped_gaussian_fit) and
//    sigma = m / psi(t) makes the mean exact whatever t's fit error (which only perturbs the
//    variance); the same fit gives log(1 / psi) of its own t as a polynomial (error 1.9e-7, the
//    mean's relative error), which spares the erfc and one exp. The atom the clamp puts at the
//    bound plays the role of P(n = 1 | M).
// 3. The far bound. Capping the offset at N - 2 lowers its mean by sigma psi(t - (N - 2)/sigma),
//    which matters for N below about 30. There (N < 32) the sampler does not draw the Gaussian
//    at all: it inverts the law exactly (Small N, below). From N = 32 on the cap removes less than
//    1e-8 of the middle's mean. (Until the walk took N < 32, a 41 x 41 table of the two-sided fit,
//    solved offline by Newton's method, served N = 4 to 32: 45 to 52 ns a draw at N from 16 to 28
//    and p near 1/2, 3x KK25 Alg. 1, and a 13 KB constant array in every shader.)
// 4. Without the ends. The parameters depend on (N, p) alone, so where they are in closed form the sampler does not need P(n = 0) and P(n = N) for them, only for the gates,
//    and skips those too where u1 is surely between them (glint_binomial_middle_fit):
//    - N >= 32 and lambda = N p_near >= 3 (there the far bound N - 2 is always 5 sd or more
//      above lambda - 1): the one-sided fit in closed form (glint_binomial_closed_fit). The far end weighs
//      less than 2.2e-7 there and is dropped; the near end's weight eps = (1 - p_near)^N comes
//      from log(1 - p_near) (its series below p_near = 0.1) and an exp where
//      lambda (1 + p_near / 2 + p_near^2 / 3) < 9, to first order from 9 to 17 (eps < 1.2e-4:
//      an inline series and exp, and the fit at eps = 0 corrected by eps times the moments'
//      derivatives), and is 0 from 17 on (< 4.1e-8; from lambda = 11.2 on at p_near = 1/2),
//      which gives m and v in closed form; (t, sigma) come from
//      w = sqrt(v) / m by two degree-6 polynomials in two pieces (t = m / sd, sigma = sd where
//      6 sd <= m). The middle offset's mean within 7.9e-7 and its variance within 6.0e-6 of
//      their targets (2.8e-6 and 3.8e-5 where eps is taken to first order);
//    - N >= 32 and lambda from 2^-7 to 3 (the band): the one-sided fit of step 2 as a function
//      of (log2 lambda, 32 / N), polynomials in four pieces (glint_binomial_band_fit; made and
//      measured by bench/fit_binomial_band.cpp: the offset's mean within 2.7e-6 and its variance
//      within 1.8e-5 of their targets). They replaced the ends, m, v and the fit's log and exp,
//      which cost these draws 2.1x (at N p = 1) to 2.3x (at N p = 10) their time now. (A table there
//      was as fast on the CPU, but its constant array made the GLSL frames 2x slower on llvmpipe.)
//    Elsewhere (N >= 32 with lambda below 2^-7, where the middle is drawn with probability about
//    lambda; and below N = 32 for callers that set the middle up there, glint_binomial_unbiased_setup,
//    though the sampler walks) the moments are computed from the ends as in steps 1 and 2.
// The overall mean is then N p^N + P(M) (1 + m) = N p up to those errors and the rounding of the
// closed forms (about one ulp of N p). Measured figures: docs/binomial.md.
//
// Small N: exact by inversion. For 2 < N < 32 binomial_unbiased does not use steps 1 to 4: it
// draws from L(N, p) = (1 - f) b(Na, p) N / Na + f b(Na + 1, p) N / (Na + 1), Na = floor(N),
// f = N - Na (the two neighbouring binomials scaled onto [0, N], mixed by the fractional part):
// u2 picks the component (Na + 1 trials where u2 < f), and u1 inverts its CDF, a walk over the
// support from the near end without a transcendental, four support points a step
// (kernels/binomial.glsl, glint_binomial_walk). At integer N that is b(N, p) itself; for real N
// the mean is N p, P(n = 0) is the randomised-rounding binomial's, the values stay in [0, N], and
// the variance is N^2 p (1 - p) ((1 - f) / Na + f / (Na + 1)), 0% to 4.2% above N p (1 - p). The
// draw stays monotone in p, symmetric per sample and continuous in N; n > 0 only where u1 <
// 1 - (1 - p)^(Na + 1) <= (N + 1) p, the bound that the near-end gate's shortcut and the grid's
// skip test take (glint_binomial_trials_bound). From N = 32 to 40 the walk and steps 1 to 4 are
// mixed with weights (40 - N) / 8 and (N - 32) / 8, chosen by u2 (each then reads u2 stretched
// back onto (0, 1)): a walk at p = 1/2 takes about N / 2 support points, the Gaussian middle a
// constant time. About (N p_near + 1) / 4 steps a draw, the step's exit a mispredicted branch:
// over 65536 uniform pairs 28.0 ns at N = 30, p = 0.3 and 31.4 to 32.3 ns at p = 1/2 against
// KK25 Alg. 1's 18.3 to 18.7, where the closed-form middle alone (which N < 32 does not take: its
// far bound and the band's fit need N >= 29 and 32) costs 27.0 and 22 (`glint_frame_loop
// draw-time 30 0.5 65536`, CPU). The walk is the sampler's costliest path on the grid: 1.64x
// Alg. 1 at (30, 0.5) in the docs run, 1.60x at (29, 0.5) between the grid's N (docs/binomial.md).
// In the blend from N = 32 to 40 a draw near p = 1/2 costs more than either path alone (up to
// 2.35x Alg. 1 at N = 35; kernels/binomial.glsl says why).
//
// Cost. binomial_dual_gated and binomial_unbiased evaluate a transcendental only where it can
// change the result, and return bit for bit what the straight-line evaluation returns (for u1 a
// normal number; tests/unit/test_binomial_shortcuts.cpp): for N > 2 and methods kk25 and log1p,
// u1 beyond T min(p, 1 - p) 1.001 + 1e-5 (T = N + 1, glint_binomial_trials_bound) decides the near-end gate (n = 0, or n = N for
// p > 1/2) from Bernoulli's inequality; the middle needs no gate where u1 is surely between p^N
// and 1 - (1 - p)^N (bounded by 1 / (1 + x) with x = N q for Alg. 1, by 1 / (1 + x + x^2 / 2 +
// x^3 / 6) for the mean-preserving sampler); the mean-preserving sampler's end probabilities are
// taken as 0 where they fall below the normal range, the far end's without its log1p where the
// exponent of p_near already shows it (p_near^N < 2^(floor(N) e) <= 2^-128); N <= 2 needs no
// transcendental at all.
// Where the mean-preserving sampler surely draws the middle and its parameters need no ends, it
// skips the gates as well (they would give the middle). From N p_near = 17 on, where the clamp is
// 6 sd or more below the mean and u1 is in [1.03e-3, 1 - 1.03e-3], a bound that implies the sure
// middle there, it draws the Gaussian at once (glint_binomial_unbiased_busy): Alg. 1's cost for
// most draws of large footprints. Elsewhere, where the middle is sure and its parameters need no
// ends, the C++ kernel draws it without building the gates and the setup's structs
// (glint_binomial_unbiased_sure_middle; GLSL keeps the one path, which inlines the middle's fit
// once), and where u2 lies below a lower bound on the share that the clamp takes to the near count
// (a polynomial in N p_near, glint_binomial_clamped_mass_bound) it returns that count without the
// middle's fit or the quantile: at N p_near = 0.1, 0.910 of the middle's draws (of 0.916 that
// clamp). The cached kernel (glint_binomial_unbiased_cached, the IBL root's) keeps its cache instead.
// Sparse glints (N p << 1), the common case, then cost two comparisons. Where the middle is
// drawn, its setup (step 4) costs a log2, two sqrt and 21 to 24 polynomial terms per output in
// the band, or a sqrt and two polynomials from N p = 3 on (and a log from p_near = 1/10 on and an
// exp where N p_near (1 + p_near / 2 + p_near^2 / 3) < 9); elsewhere the ends (a log1p and an
// exp), the moments, and the one-sided fit (a log, two polynomials, an exp). The fit
// (glint_binomial_middle_fit) is out of line in C++: inlined, it slowed the sampler's other paths.
// In C++ the near-end gate and the busy middle are inlined into the caller, the rest is called
// (kernels/binomial.glsl says why). Measured against Alg. 1 and std::binomial_distribution:
// docs/binomial.md.
#pragma once

#include "glint/core.hpp"
#include "glint/detail/kernels.hpp"

namespace glint {

// {positive, negative} outcome counts.
template <class real>
using binomial_result = typename detail::glsl::kernels<real>::glint_binomial;

// u1 is not used; the parameter keeps the variants interchangeable.
template <class real>
binomial_result<real> binomial_ungated(real N, real p, real /*u1*/, real u2) {
    return detail::glsl::kernels<real>::glint_binomial_ungated(N, p, u2);
}

// As published, DB23 evaluates P(n >= 1) as pow(1 - p, N) (method naive).
template <class real>
binomial_result<real> binomial_gated_db23(real N, real p, real u1, real u2, pow_method method = pow_method::naive) {
    return detail::glsl::kernels<real>::glint_binomial_gated_db23(N, p, u1, u2, static_cast<int>(method));
}

// As published, KK25 evaluates (1 - p)^N with its Eq. 25 (method kk25).
template <class real>
binomial_result<real> binomial_gated(real N, real p, real u1, real u2, pow_method method = pow_method::kk25) {
    return detail::glsl::kernels<real>::glint_binomial_gated(N, p, u1, u2, static_cast<int>(method));
}

template <class real>
binomial_result<real> binomial_dual_gated(real N, real p, real u1, real u2, pow_method method = pow_method::kk25) {
    return detail::glsl::kernels<real>::glint_binomial_dual_gated(N, p, u1, u2, static_cast<int>(method));
}

template <class real>
binomial_result<real> binomial_unbiased(real N, real p, real u1, real u2, pow_method method = pow_method::log1p) {
    return detail::glsl::kernels<real>::glint_binomial_unbiased(N, p, u1, u2, static_cast<int>(method));
}

// The variants as a value, for code generic over them (glint::multinomial, tests, benches).
// The values are the kernels' GLINT_BINOMIAL_* codes.
enum class binomial_variant { ungated = 0, gated_db23 = 1, gated = 2, dual_gated = 3, unbiased = 4 };

inline const char* name(binomial_variant v) {
    switch (v) {
        case binomial_variant::ungated: return "ungated";
        case binomial_variant::gated_db23: return "gated_db23";
        case binomial_variant::gated: return "gated";
        case binomial_variant::dual_gated: return "dual_gated";
        case binomial_variant::unbiased: break;
    }
    return "unbiased";
}

// The (1 - p)^N evaluation each variant was published with (log1p for glint's own).
inline pow_method published_pow_method(binomial_variant v) {
    switch (v) {
        case binomial_variant::ungated: return pow_method::log1p;  // unused
        case binomial_variant::gated_db23: return pow_method::naive;
        case binomial_variant::gated:
        case binomial_variant::dual_gated: return pow_method::kk25;
        case binomial_variant::unbiased: break;
    }
    return pow_method::log1p;
}

template <class real>
binomial_result<real> binomial(binomial_variant v, real N, real p, real u1, real u2, pow_method method) {
    return detail::glsl::kernels<real>::glint_binomial_variant(static_cast<int>(v), N, p, u1, u2, static_cast<int>(method));
}

template <class real>
binomial_result<real> binomial(binomial_variant v, real N, real p, real u1, real u2) {
    return binomial(v, N, p, u1, u2, published_pow_method(v));
}

}  // namespace glint
