// glint binomial kernels: constant-time approximate sampling of b(N, p) for real N >= 0.
// Single source for C++ and GLSL 4.50; needs core.glsl. C++ users include <glint/binomial.hpp>,
// which documents the variants and derives the mean-preserving one.
//
// Every sampler takes N (clamped to >= 0), p (clamped to [0, 1]), two uniform variates u1, u2 in
// (0, 1) (u1 for the gates, u2 for the Gaussian), and returns the number of positive and of
// negative outcomes as reals. `method` is the (1 - p)^N evaluation (GLINT_POW_*).

struct glint_binomial {
    real positive;
    real negative;
};

GLINT_FN glint_binomial glint_binomial_pair(real positive, real negative) {
    glint_binomial b;
    b.positive = positive;
    b.negative = negative;
    return b;
}

// ---------------------------------------------------------------------------------------------
// The published variants, as published.

// Ungated: a Gaussian with the binomial's mean and variance, clamped to [0, N]. Needs only u2.
GLINT_FN glint_binomial glint_binomial_ungated(real N, real p, real u2) {
    N = max(N, real(0));
    p = clamp(p, real(0), real(1));
    real n = clamp(N * p + sqrt(N * p * (real(1) - p)) * glint_normal_quantile(u2), real(0), N);
    return glint_binomial_pair(n, N - n);
}

// DB23's gated Gaussian, KK25 Eq. 22: with probability P(n >= 1) = 1 - (1 - p)^N keep one
// positive outcome and draw the rest from N(1 + (N - 1) p, (N - 1) p (1 - p)), clamped to [1, N]
// and floored. Made for integer N >= 1; for N < 1 it returns 0 (the defect KK25 Eq. 23 fixes).
GLINT_FN glint_binomial glint_binomial_gated_db23(real N, real p, real u1, real u2, int method) {
    N = max(N, real(0));
    p = clamp(p, real(0), real(1));
    real gate = (u1 < glint_any_success(p, N, method)) ? real(1) : real(0);
    real rest = max(N - real(1), real(0));
    real g = real(1) + rest * p + sqrt(rest * p * (real(1) - p)) * glint_normal_quantile(u2);
    real n = floor(gate * min(max(g, real(1)), N));
    return glint_binomial_pair(n, N - n);
}

// KK25 Eq. 23, the gated Gaussian for real N >= 0: the gate probability is min(N p, P(n >= 1))
// (N p for N < 1, KK25 Appendix B) and the Gaussian is clamped to [1, max(N, 1)], without the
// floor. For N < 1 a gated sample is exactly 1 (one microfacet, present with probability N);
// the negative count is then max(N - 1, 0) = 0.
GLINT_FN glint_binomial glint_binomial_gated(real N, real p, real u1, real u2, int method) {
    N = max(N, real(0));
    p = clamp(p, real(0), real(1));
    real n_at_least_1 = max(N, real(1));
    real gate = (u1 < min(N * p, glint_any_success(p, N, method))) ? real(1) : real(0);
    real rest = n_at_least_1 - real(1);
    real g = real(1) + rest * p + sqrt(rest * p * (real(1) - p)) * glint_normal_quantile(u2);
    real n = gate * clamp(g, real(1), n_at_least_1);
    return glint_binomial_pair(n, max(N - n, real(0)));
}

// The gates of KK25 Alg. 1 (lines 2-14), shared by the dual-gated and the mean-preserving
// samplers: n = positive_fixed + gaussian * G and n_bar = negative_fixed + gaussian * (N2 - G),
// N2 = max(N, 2), where G in [1, N2 - 1] is the sampler's Gaussian part.
struct glint_binomial_gates {
    real positive_fixed;
    real negative_fixed;
    real gaussian;  // 1 where the Gaussian part is used, else 0
};

// `all_positive_n2` = p^N2 and `all_negative_n2` = (1 - p)^N2, as the caller evaluates them.
GLINT_FN glint_binomial_gates glint_binomial_dual_gates(real N, real p, real u1, real all_positive_n2,
                                                        real all_negative_n2) {
    real N2 = max(real(2), N);
    real weight_2 = clamp(N - real(1), real(0), real(1));        // outcomes of N >= 2
    real weight_1 = max(real(0), real(1) - abs(real(1) - N));    // outcomes of N = 1
    real p_all_positive = weight_2 * all_positive_n2;            // line 5
    real p_all_negative = weight_2 * all_negative_n2;            // line 6
    real p_one_positive = weight_1 * p;                          // line 7
    real p_one_negative = weight_1 * (real(1) - p);              // line 8
    real all_positive = (u1 < p_all_positive) ? real(1) : real(0);                           // line 10
    real one_or_all_positive = (u1 < p_all_positive + p_one_positive) ? real(1) : real(0);   // line 11
    real all_negative = (real(1) - p_all_negative <= u1) ? real(1) : real(0);                // line 12
    real one_or_all_negative = (real(1) - p_all_negative - p_one_negative <= u1) ? real(1) : real(0);  // 13
    glint_binomial_gates g;
    g.positive_fixed = all_positive * (N2 - real(1)) + one_or_all_positive;   // line 21
    g.negative_fixed = all_negative * (N2 - real(1)) + one_or_all_negative;   // line 22
    g.gaussian = ((N > real(1)) ? real(1) : real(0)) * (real(1) - one_or_all_positive) *
                 (real(1) - one_or_all_negative);                             // line 14
    return g;
}

// Shortcuts that skip the transcendentals where the result is already decided. Each gives the
// result the full evaluation gives (tests compare the two at every grid point and at u1 next to
// every bound); the published samplers stay the functions they were.
//
// The gate probabilities as the kernels compute them, for methods kk25 and log1p (naive rounds
// 1 - p to 1 below p = 2^-25 and has no such bounds), N > 2, q = p or 1 - p:
//   1 - (1 - q)^N <= N q (Bernoulli's inequality), computed to within a relative 2.5e-4 (Eq. 25's
//   model error eps / 2 = 1.4e-4 plus the rounding of 1 - c p, 2^-25 / eps = 1.0e-4) plus an
//   absolute 6e-8 (one ulp below 1): bounded by N q 1.001 + 1e-5;
//   (1 - q)^N <= exp(-N q) <= 1 / (1 + N q), computed to within the same relative error: bounded
//   by 1.001 / (1 + 0.999 N q).

// True where the near-end gate surely fires (the near count is 0: n = 0 for p <= 1/2, n = N
// otherwise): N > 2, method kk25 or log1p, u1 beyond N min(p, 1 - p) 1.001 + 1e-5.
GLINT_FN bool glint_binomial_surely_near_end(real N, real p, real u1, int method) {
    real bound = N * min(p, real(1) - p) * real(1.001) + real(1e-5);
    bool beyond = (p <= real(0.5)) ? (u1 >= bound) : (u1 < real(1) - bound);
    return N > real(2) && method != GLINT_POW_NAIVE && beyond;
}

// The near-end result: (0, N) for p <= 1/2, (N, 0) otherwise.
GLINT_FN glint_binomial glint_binomial_near_end(real N, real p) {
    return (p <= real(0.5)) ? glint_binomial_pair(real(0), N) : glint_binomial_pair(N, real(0));
}

// KK25 Alg. 1's Gaussian part for N2 = max(N, 2): N(1 + (N2 - 2) p, (N2 - 2) p (1 - p)) clamped to
// [1, N2 - 1] (lines 16-19).
GLINT_FN real glint_binomial_dual_gated_gaussian(real N2, real p, real u2) {
    real mu = real(1) + (N2 - real(2)) * p;
    real sigma = sqrt((N2 - real(2)) * p * (real(1) - p));
    return clamp(mu + sigma * glint_normal_quantile(u2), real(1), N2 - real(1));
}

// KK25 Alg. 1, the dual-gated Gaussian, every gate evaluated, for N >= 0 and p in [0, 1] (the
// caller clamps). KK25 evaluates line 6 with Eq. 25 (method GLINT_POW_KK25). p^N2 and (1 - p)^N2
// weigh nothing for N <= 1, and the quantile nothing where the gates fix the result, so neither
// is evaluated there.
GLINT_FN glint_binomial glint_binomial_dual_gated_evaluated(real N, real p, real u1, real u2, int method) {
    real N2 = max(real(2), N);
    real all_positive = real(0), all_negative = real(0);
    if (N > real(1)) {
        all_positive = pow(p, N2);
        all_negative = glint_pow_one_minus(p, N2, method);
    }
    glint_binomial_gates g = glint_binomial_dual_gates(N, p, u1, all_positive, all_negative);
    real G = (g.gaussian > real(0.5)) ? glint_binomial_dual_gated_gaussian(N2, p, u2) : real(1);
    return glint_binomial_pair(g.positive_fixed + g.gaussian * G, g.negative_fixed + g.gaussian * (N2 - G));
}

// KK25 Alg. 1 with the shortcuts: the near-end gate, and for N > 2 the middle where u1 is surely
// above p^N and below 1 - (1 - p)^N (then n is the clamped Gaussian alone).
GLINT_FN glint_binomial glint_binomial_dual_gated(real N, real p, real u1, real u2, int method) {
    N = max(N, real(0));
    p = clamp(p, real(0), real(1));
    if (glint_binomial_surely_near_end(N, p, u1, method)) return glint_binomial_near_end(N, p);
    bool above_all_positive = u1 * (real(1) + real(0.999) * N * (real(1) - p)) >= real(1.001);
    bool below_all_negative = (real(1) - u1 - real(1e-6)) * (real(1) + real(0.999) * N * p) >= real(1.001);
    if (N > real(2) && method != GLINT_POW_NAIVE && above_all_positive && below_all_negative) {
        real G = glint_binomial_dual_gated_gaussian(N, p, u2);
        return glint_binomial_pair(G, N - G);
    }
    return glint_binomial_dual_gated_evaluated(N, p, u1, u2, method);
}

// ---------------------------------------------------------------------------------------------
// The mean-preserving variant (derivation in glint/binomial.hpp).

// The one-sided fit as a function of y = log(v / m^2): T(y), the t at which
// Var[max(t + Z, 0)] / E[max(t + Z, 0)]^2 = exp(y) (the inverse of log(chi(t) / psi(t)^2 - 1)),
// and L(y) = -log psi(T(y)), so that sigma = m exp(L) gives max(sigma (T + Z), 0) the mean m.
// L is fitted to the fitted T, so T's error moves only the variance. Least-squares polynomials
// made in double by bench/fit_clamped_gaussian.cpp, whose output gives the digits: on
// [-3.6, 0] and (0, 7.3] in y (degrees 10 and 14), on (7.3, 35.7] in sqrt(y) (degrees 6 and 8);
// max |T error| 4.7e-6, max |L error| 1.9e-7 (the mean's relative error). y is clamped to
// [-3.6, 35.7] (t from 6.05 down to -8); below -3.58 (m >= 6 sd) callers use t = m / sd.
// No transcendental but the sqrt of the last piece; each polynomial is split into its even and
// odd parts (Horner in s^2), which halves the chain of dependent multiply-adds.
GLINT_FN vec2 glint_clamped_gaussian_fit(real y) {
    y = clamp(y, real(-3.6), real(35.7));
    if (y <= real(0)) {
        real s = (y - real(-1.8)) / real(1.8);
        real s2 = s * s;
        real t_even = real(-0.010308468088042321);
        t_even = real(0.037050860364841814) + s2 * t_even;
        t_even = real(-0.054444013333632198) + s2 * t_even;
        t_even = real(0.13071049084714717) + s2 * t_even;
        t_even = real(0.78463584858073332) + s2 * t_even;
        t_even = real(2.4409131101728678) + s2 * t_even;
        real t_odd = real(0.0053725919361740614);
        t_odd = real(-0.028263419599224709) + s2 * t_odd;
        t_odd = real(0.060598304497303329) + s2 * t_odd;
        t_odd = real(-0.44010862391410144) + s2 * t_odd;
        t_odd = real(-2.3186858997638047) + s2 * t_odd;
        real t = t_even + s * t_odd;
        real l_even = real(-4.1355943758630882e-05);
        l_even = real(0.0013708845131560855) + s2 * l_even;
        l_even = real(-0.0017652475879844339) + s2 * l_even;
        l_even = real(-0.0008359210463114719) + s2 * l_even;
        l_even = real(-0.0043677635492591063) + s2 * l_even;
        l_even = real(0.024399494908224236) + s2 * l_even;
        l_even = real(0.10262096278746217) + s2 * l_even;
        l_even = real(-0.8933562617597528) + s2 * l_even;
        real l_odd = real(0.00049966200891597213);
        l_odd = real(0.00097047932315809165) + s2 * l_odd;
        l_odd = real(-0.0082451092534076096) + s2 * l_odd;
        l_odd = real(0.018805775066734826) + s2 * l_odd;
        l_odd = real(-0.035202442401896274) + s2 * l_odd;
        l_odd = real(0.10915632968954159) + s2 * l_odd;
        l_odd = real(0.94203968079589862) + s2 * l_odd;
        real l = l_even + s * l_odd;
        return vec2(t, l);
    } else if (y <= real(7.3)) {
        real s = (y - real(3.6499999999999999)) / real(3.6499999999999999);
        real s2 = s * s;
        real t_even = real(0.0042119353416058061);
        t_even = real(-0.0031351309518826537) + s2 * t_even;
        t_even = real(-0.020667094310529547) + s2 * t_even;
        t_even = real(0.048476948830804792) + s2 * t_even;
        t_even = real(0.45604755494646948) + s2 * t_even;
        t_even = real(-1.6904640841157963) + s2 * t_even;
        real t_odd = real(-0.007883666413722944);
        t_odd = real(0.018743260584426852) + s2 * t_odd;
        t_odd = real(0.0042882889673933203) + s2 * t_odd;
        t_odd = real(-0.17479258110259771) + s2 * t_odd;
        t_odd = real(-1.6533601232843811) + s2 * t_odd;
        real t = t_even + s * t_odd;
        real l_even = real(-0.00092637762144238739);
        l_even = real(0.0038659831671257359) + s2 * l_even;
        l_even = real(-0.0018628638056436336) + s2 * l_even;
        l_even = real(-0.028337951478073782) + s2 * l_even;
        l_even = real(0.040610156090553046) + s2 * l_even;
        l_even = real(0.12542798783199929) + s2 * l_even;
        l_even = real(-0.021419997731581999) + s2 * l_even;
        l_even = real(3.9783197408946505) + s2 * l_even;
        real l_odd = real(0.00099441504559921842);
        l_odd = real(-0.01163028713569085) + s2 * l_odd;
        l_odd = real(0.033190904823281492) + s2 * l_odd;
        l_odd = real(-0.0080217661863960753) + s2 * l_odd;
        l_odd = real(-0.083755938625149087) + s2 * l_odd;
        l_odd = real(-0.10767544864638232) + s2 * l_odd;
        l_odd = real(4.0165295380171653) + s2 * l_odd;
        real l = l_even + s * l_odd;
        return vec2(t, l);
    } else {
        real s = (sqrt(y) - real(4.3383994578685607)) / real(1.6365482406473015);
        real s2 = s * s;
        real t_even = real(0.00060684978664457621);
        t_even = real(0.0056332391221094883) + s2 * t_even;
        t_even = real(0.049776818499077981) + s2 * t_even;
        t_even = real(-5.5657308993254242) + s2 * t_even;
        real t_odd = real(-0.0021686196695519548);
        t_odd = real(-0.016333686667123551) + s2 * t_odd;
        t_odd = real(-2.472677074787021) + s2 * t_odd;
        real t = t_even + s * t_odd;
        real l_even = real(-0.00011855096240135236);
        l_even = real(0.00064035094124853867) + s2 * l_even;
        l_even = real(-0.0050018841421649403) + s2 * l_even;
        l_even = real(2.6084050238947181) + s2 * l_even;
        l_even = real(19.928591754565634) + s2 * l_even;
        real l_odd = real(-0.0010655800102400772);
        l_odd = real(0.0024616450769860457) + s2 * l_odd;
        l_odd = real(0.016124403598439085) + s2 * l_odd;
        l_odd = real(14.579688207436343) + s2 * l_odd;
        real l = l_even + s * l_odd;
        return vec2(t, l);
    }
}

// Moments of the capped offset O = min(sigma max(t + Z, 0), span) = clamp(mu + sigma Z, 0, span),
// mu = sigma t, and their derivatives in mu and sigma. With t_far = t - span / sigma:
// E[O] = sigma (psi(t) - psi(t_far)),
// E[O^2] = sigma^2 (chi(t) - chi(t_far)) - 2 span sigma psi(t_far),
// dE[O]/dmu = Phi(t) - Phi(t_far), dE[O]/dsigma = phi(t) - phi(t_far),
// dE[O^2]/dmu = 2 (E[O] - span Phi(t_far)),
// dE[O^2]/dsigma = 2 (mu (phi(t) - phi(t_far)) + sigma (Phi(t) - Phi(t_far) - t phi(t) + t_far phi(t_far))),
// where psi(t) = t Phi(t) + phi(t) and chi(t) = (t^2 + 1) Phi(t) + t phi(t).
struct glint_capped_moments {
    real mean;
    real square_mean;
    real dmean_dmu;
    real dmean_dsigma;
    real dsquare_dmu;
    real dsquare_dsigma;
};

GLINT_FN glint_capped_moments glint_capped_offset_moments(real t, real sigma, real span) {
    real t_far = max(t - span / max(sigma, real(1e-30)), real(-40));
    real cdf = glint_normal_cdf(t), pdf = glint_normal_pdf(t);
    real cdf_far = glint_normal_cdf(t_far), pdf_far = glint_normal_pdf(t_far);
    real psi = t * cdf + pdf, psi_far = t_far * cdf_far + pdf_far;
    real chi = (t * t + real(1)) * cdf + t * pdf, chi_far = (t_far * t_far + real(1)) * cdf_far + t_far * pdf_far;
    glint_capped_moments c;
    c.mean = max(sigma * (psi - psi_far), real(0));
    c.square_mean = max(sigma * sigma * (chi - chi_far) - real(2) * span * sigma * psi_far, real(0));
    c.dmean_dmu = cdf - cdf_far;
    c.dmean_dsigma = pdf - pdf_far;
    c.dsquare_dmu = real(2) * (c.mean - span * cdf_far);
    c.dsquare_dsigma = real(2) * (sigma * t * (pdf - pdf_far) + sigma * (cdf - cdf_far - t * pdf + t_far * pdf_far));
    return c;
}

// The mean-preserving sampler clamps N to 1e18: its moments square N, and (1e18)^2 is still far
// below the float range (3.4e38).
GLINT_CONST(real) GLINT_BINOMIAL_MAX_N = real(1e18);
// Newton steps for the small-N middle, at most (it stops once converged).
GLINT_CONST(int) GLINT_BINOMIAL_NEWTON_STEPS = 3;

// The parameters of the mean-preserving sampler's middle part for N > 2 (they do not depend on
// u1, u2; tests evaluate its closed-form distribution from them). The middle part is
// G = 1 + offset (lower = 1) or G = N - 1 - offset (lower = 0), offset = min(sigma max(t + s, 0),
// span) remapped by far_scale, s = +-Z.
struct glint_binomial_middle {
    real all_positive;   // p^N
    real all_negative;   // (1 - p)^N
    real lower;          // 1: offsets count up from n = 1; 0: down from n = N - 1
    real t;              // where the clamp cuts the Gaussian, in standard deviations
    real sigma;          // the Gaussian's scale
    real span;           // N - 2, the largest offset
    real far_scale;      // keeps the mean when the far bound caps the offset: k > 0 maps
                         // offset -> span - (span - offset) k, k < 0 maps offset -> offset |k|
    real two_point;      // the two-point law used up to N = 3: offset = span with this probability
    real center;         // where the Gaussian is centred in counts: 1 + sigma t, or N - 1 - sigma t
};

// The probabilities of the ends, P(n = 0) and P(n = N), and P(near count >= 1), for N >= 2.
// The mean-preserving sampler works from the nearer end: the near count is n for p <= 1/2 and
// n_bar otherwise, with success probability p_near <= 1/2, which keeps every formula free of
// cancellation at both ends and makes the sampler symmetric.
struct glint_binomial_ends {
    real all_positive;  // p^N
    real all_negative;  // (1 - p)^N
    real any_near;      // P(near count >= 1)
    real lower;         // 1 for p <= 1/2
};

// Where N min(p, 1 - p) reaches this, both end probabilities fall below the smallest normal number
// as glint_binomial_unbiased_ends_evaluated computes them (methods kk25 and log1p): the near end
// is at most exp(-N p_near), the far end at most 2^-N, and exp(-88) = 6.1e-39 < 2^-126 = 1.2e-38,
// exp(-709) = 1.2e-308 < 2^-1022 = 2.2e-308. Taken as 0 they change nothing that rounding keeps
// (every term they enter is at most N p_near exp(-N p_near) against terms of order N p_near, and
// a gate compares them with u1, for which 0 and a subnormal decide alike when u1 is normal; the
// shortcut test compares results bit for bit), and they spare the subnormal arithmetic, which
// costs about 150 ns here.
GLINT_CONST(real) GLINT_BINOMIAL_UNDERFLOW_MEAN = GLINT_DOUBLE ? real(709) : real(88);

GLINT_FN glint_binomial_ends glint_binomial_unbiased_ends_evaluated(real N, real p, int method) {
    glint_binomial_ends e;
    e.lower = (p <= real(0.5)) ? real(1) : real(0);
    real p_near = (e.lower > real(0.5)) ? p : real(1) - p;
    if (N <= real(2)) {
        // N2 = 2: the squares, exactly and without a transcendental.
        e.all_positive = p * p;
        e.all_negative = (real(1) - p) * (real(1) - p);
        e.any_near = p_near * (real(2) - p_near);
    } else if (method == GLINT_POW_LOG1P) {
        // One log1p per end: x = log P(near count = 0), x_far = log P(near count = N). An end
        // below the normal range is taken as 0 (see GLINT_BINOMIAL_UNDERFLOW_MEAN), without its exp
        // (exp's underflow path costs about 20 ns) and, for the far end, without its log1p:
        // x_far <= -N log 2 since p_near <= 1/2.
        real x = N * glint_log1p(-p_near);
        bool far_underflows = N * real(0.693147180559945309417) >= GLINT_BINOMIAL_UNDERFLOW_MEAN;  // log 2, 21 digits
        real x_far = far_underflows ? real(0) : N * glint_log1p(-(real(1) - p_near));
        real none_near = (x >= -GLINT_BINOMIAL_UNDERFLOW_MEAN) ? exp(x) : real(0);
        real all_near = (far_underflows || x_far < -GLINT_BINOMIAL_UNDERFLOW_MEAN) ? real(0) : exp(x_far);
        e.any_near = (x > real(-0.346573590279972654709)) ? -glint_expm1_nonpositive(x) : real(1) - none_near;
        e.all_positive = (e.lower > real(0.5)) ? all_near : none_near;
        e.all_negative = (e.lower > real(0.5)) ? none_near : all_near;
    } else {
        e.all_positive = pow(p, N);
        e.all_negative = glint_pow_one_minus(p, N, method);
        e.any_near = glint_any_success(p_near, N, method);
    }
    return e;
}


// The ends, without a transcendental where both are below the normal range.
GLINT_FN glint_binomial_ends glint_binomial_unbiased_ends(real N, real p, int method) {
    if (N * min(p, real(1) - p) >= GLINT_BINOMIAL_UNDERFLOW_MEAN && method != GLINT_POW_NAIVE) {
        glint_binomial_ends e;
        e.lower = (p <= real(0.5)) ? real(1) : real(0);
        e.all_positive = real(0);
        e.all_negative = real(0);
        e.any_near = real(1);
        return e;
    }
    return glint_binomial_unbiased_ends_evaluated(N, p, method);
}

GLINT_FN glint_binomial_middle glint_binomial_unbiased_middle_setup(real N, real p, glint_binomial_ends e) {
    glint_binomial_middle q;
    q.all_positive = e.all_positive;
    q.all_negative = e.all_negative;
    q.lower = e.lower;
    q.span = N - real(2);
    real p_near = (q.lower > real(0.5)) ? p : real(1) - p;
    real none_near = (q.lower > real(0.5)) ? q.all_negative : q.all_positive;  // P(near count = 0)
    real all_near = (q.lower > real(0.5)) ? q.all_positive : q.all_negative;   // P(near count = N)
    real any_near = e.any_near;                                                  // P(near count >= 1)
    real middle = max(any_near - all_near, real(0));                             // P(1 <= n <= N - 1)
    real inv_middle = (middle >= GLINT_FLT_MIN_NORMAL) ? real(1) / middle : real(0);  // 1 / denormal overflows
    real mean_near = N * p_near;
    // E[y 1_mid] = (N p - P(n >= 1)) - (N - 1) p^N, from E[n] = N p.
    real excess = mean_near - any_near;
    real mean_y = max(excess - (N - real(1)) * all_near, real(0)) * inv_middle;
    // Var[y | mid] two ways, each free of cancellation where it is used. Small means: from the
    // factorial moment E[(n - 1)(n - 2) 1_mid] = N (N - 1) p^2 - 2 (N p - P(n >= 1))
    // - (N - 1)(N - 2) p^N. Large means: from the law of total variance over {n = 0, mid, n = N},
    // N p (1 - p) = P0 (N p)^2 + PN (N (1 - p))^2 + P_mid (Var_mid + (E_mid - N p)^2), with
    // E_mid - N p = (N p P0 - N (1 - p) PN) / P_mid.
    real factorial_y = max(N * (N - real(1)) * p_near * p_near - real(2) * excess -
                               (N - real(1)) * (N - real(2)) * all_near, real(0)) * inv_middle;
    real var_small = factorial_y + mean_y - mean_y * mean_y;
    real mean_far = N * (real(1) - p_near);
    real shift = (mean_near * none_near - mean_far * all_near) * inv_middle;
    real var_large = (mean_near * (real(1) - p_near) - none_near * mean_near * mean_near -
                      all_near * mean_far * mean_far - middle * shift * shift) * inv_middle;
    real var_y = max((mean_y < real(1)) ? var_small : var_large, real(0));
    real offset_mean = clamp(mean_y, real(0), q.span);
    // N <= 3: the middle holds at most two counts, 1 and N - 1, and a Bernoulli with the right mean
    // is exact at N = 3 (and continuous down to N = 2, where it becomes the single count 1).
    // glint_binomial_unbiased_middle blends it into the Gaussian law between N = 3 and 4.
    q.two_point = (q.span > real(0)) ? offset_mean / q.span : real(0);
    // Choose (t, sigma) so that max(sigma (t + Z), 0) has mean offset_mean and variance var_y.
    // Where the mean is 6 or more standard deviations from the bound the clamp removes less than
    // Phi(-6) = 1e-9 of the mass: then t = mean / sd and sigma = sd, as the fit would give to within
    // 1e-9 relative, without its log and exp.
    real tiny = GLINT_FLT_MIN_NORMAL;
    real sd = sqrt(var_y);
    if (q.span <= real(1)) {  // N <= 3: the two-point law alone
        q.sigma = real(0);
        q.t = real(0);
    } else if (offset_mean >= real(6) * sd) {
        q.sigma = sd;
        q.t = offset_mean / max(sd, tiny);
    } else {
        vec2 f = glint_clamped_gaussian_fit(log(max(var_y, tiny) / max(offset_mean * offset_mean, tiny)));
        q.t = f.x;
        q.sigma = offset_mean * exp(f.y);
    }
    // The far bound caps the offset at span. Where it removes more than psi(-5) = 5e-8 of the
    // offset's mean (small N), refine (t, sigma) by Newton's method so that
    // min(sigma max(t + Z, 0), span) has the target mean and variance (moments and derivatives in
    // closed form from Phi and phi at t and t_far), then restore the mean exactly with an affine
    // remap of the offset (far_scale).
    real t_far = max(q.t - q.span / max(q.sigma, real(1e-30)), real(-40));
    real capped_mean = offset_mean;
    if (t_far > real(-5) && q.span > real(1)) {
        for (int i = 0; i <= GLINT_BINOMIAL_NEWTON_STEPS; ++i) {
            glint_capped_moments c = glint_capped_offset_moments(q.t, q.sigma, q.span);
            capped_mean = c.mean;
            real f1 = c.mean - offset_mean;
            real f2 = c.square_mean - (var_y + offset_mean * offset_mean);
            real det = c.dmean_dmu * c.dsquare_dsigma - c.dmean_dsigma * c.dsquare_dmu;
            // Stop once the mean is within 1e-6 and the second moment within 1e-4, relative.
            bool converged = abs(f1) <= real(1e-6) * offset_mean && abs(f2) <= real(1e-4) * (var_y + offset_mean * offset_mean);
            if (converged || i == GLINT_BINOMIAL_NEWTON_STEPS || !(abs(det) > tiny)) break;
            real dmu = (-f1 * c.dsquare_dsigma + f2 * c.dmean_dsigma) / det;
            real dsigma = (-f2 * c.dmean_dmu + f1 * c.dsquare_dmu) / det;
            real mu = q.sigma * q.t + dmu;
            q.sigma = max(q.sigma + dsigma, real(0.5) * q.sigma);
            q.t = mu / q.sigma;
        }
    }
    // offset -> span - (span - offset) k raises the mean (k <= 1); offset -> offset k lowers it.
    // Only where Newton left the mean off by more than 1e-5 relative: the remap's rounding noise
    // would otherwise make the count jitter non-monotonically in p by an ulp.
    q.far_scale = (capped_mean < offset_mean) ? (q.span - offset_mean) / max(q.span - capped_mean, tiny)
                                              : -offset_mean / max(capped_mean, tiny);
    q.far_scale = (abs(capped_mean - offset_mean) <= real(1e-5) * offset_mean) ? real(1) : q.far_scale;
    q.center = (q.lower > real(0.5)) ? real(1) + q.sigma * q.t : (N - real(1)) - q.sigma * q.t;
    return q;
}

// All parameters of the mean-preserving sampler at (N, p), N >= 2.
GLINT_FN glint_binomial_middle glint_binomial_unbiased_setup(real N, real p, int method) {
    N = clamp(N, real(2), GLINT_BINOMIAL_MAX_N);
    return glint_binomial_unbiased_middle_setup(N, p, glint_binomial_unbiased_ends(N, p, method));
}

GLINT_FN real glint_binomial_unbiased_middle(glint_binomial_middle q, real N2, real u2) {
    // Mirrored for the upper end, so that p -> 1 - p, u2 -> 1 - u2 swaps n and n_bar.
    real u_near = (q.lower > real(0.5)) ? u2 : real(1) - u2;
    real z = glint_normal_quantile(u_near);
    // Where neither the far bound nor the blend below acts (all but small N): one rounding of
    // center + sigma z. At N = 1e16 a count's ulp is most of a standard deviation, and rounding the
    // offset first and then adding it to 1 or subtracting it from N - 1 would round twice.
    if (q.far_scale == real(1) && q.span >= real(2)) {
        real s = (q.lower > real(0.5)) ? z : -z;
        return clamp(q.center + q.sigma * s, real(1), N2 - real(1));
    }
    real offset = min(max(q.sigma * q.t + q.sigma * z, real(0)), q.span);
    // Written so that far_scale = 1 is exactly the identity (span - (span - o) rounds o to ulp(span)).
    offset = (q.far_scale >= real(0)) ? offset * q.far_scale + q.span * (real(1) - q.far_scale) : -offset * q.far_scale;
    // Up to N = 3 the middle is the two-point law of counts 1 and N - 1 (exact at N = 3); from N = 3
    // to 4 it blends into the Gaussian law comonotonically (same u), which keeps the mean and the
    // law continuous in N.
    real two_point = (u_near >= real(1) - q.two_point) ? q.span : real(0);
    offset = mix(two_point, offset, clamp(q.span - real(1), real(0), real(1)));
    return (q.lower > real(0.5)) ? real(1) + offset : (N2 - real(1)) - offset;
}

// The mean-preserving sampler for N <= 2 (the caller clamps N and p): KK25 Alg. 1's gates alone,
// exact, without a transcendental.
GLINT_FN glint_binomial glint_binomial_unbiased_small(real N, real p, real u1) {
    if (N <= real(1)) {
        // At most one outcome (KK25 Fig. 4): Alg. 1's gates with p^N2 and (1 - p)^N2 weighted by 0
        // reduce to two comparisons.
        real weight_1 = max(real(0), real(1) - abs(real(1) - N));
        real positive = (u1 < weight_1 * p) ? real(1) : real(0);
        real negative = ((real(1) <= u1) ? real(1) : real(0)) + ((real(1) - weight_1 * (real(1) - p) <= u1) ? real(1) : real(0));
        return glint_binomial_pair(positive, negative);
    }
    // The middle is the single count 1; the gates decide, from the exact squares.
    glint_binomial_gates g = glint_binomial_dual_gates(N, p, u1, p * p, (real(1) - p) * (real(1) - p));
    return glint_binomial_pair(g.positive_fixed + g.gaussian, g.negative_fixed + g.gaussian);
}

// The mean-preserving dual-gated sampler: KK25 Alg. 1's gates (exact for N <= 2), and for N > 2
// a middle part whose mean is E[n | 1 <= n <= N - 1] exactly and whose variance matches the
// binomial's on that event (glint/binomial.hpp derives it). With the same result as the
// straight-line evaluation, it skips every transcendental where the near-end gate surely fires
// (glint_binomial_surely_near_end) and for N <= 2, and the ends' where both are subnormal.
GLINT_FN glint_binomial glint_binomial_unbiased(real N, real p, real u1, real u2, int method) {
    N = clamp(N, real(0), GLINT_BINOMIAL_MAX_N);
    p = clamp(p, real(0), real(1));
    if (glint_binomial_surely_near_end(N, p, u1, method)) return glint_binomial_near_end(N, p);
    if (N <= real(2)) return glint_binomial_unbiased_small(N, p, u1);
    glint_binomial_ends e = glint_binomial_unbiased_ends(N, p, method);
    glint_binomial_gates g = glint_binomial_dual_gates(N, p, u1, e.all_positive, e.all_negative);
    // The middle's parameters only where the gates chose the middle.
    real G = real(1);
    if (g.gaussian > real(0.5)) G = glint_binomial_unbiased_middle(glint_binomial_unbiased_middle_setup(N, p, e), N, u2);
    return glint_binomial_pair(g.positive_fixed + g.gaussian * G, g.negative_fixed + g.gaussian * (N - G));
}

// The mean-preserving sampler's parameters at one (N, p), kept between draws that share them (the
// three triangle vertices of a grid lattice point draw with the same N and p): the ends once
// evaluated, the middle once set up. One cache serves one `method`.
struct glint_binomial_cache {
    real N;     // N and p as clamped, valid where state > 0
    real p;
    int state;  // 0: empty; 1: the ends; 2: the ends and the middle
    glint_binomial_ends ends;
    glint_binomial_middle middle;
};

GLINT_FN glint_binomial_cache glint_binomial_empty_cache() {
    glint_binomial_cache c;
    c.N = real(0);
    c.p = real(0);
    c.state = 0;
    c.ends.all_positive = real(0);
    c.ends.all_negative = real(0);
    c.ends.any_near = real(0);
    c.ends.lower = real(0);
    c.middle.all_positive = real(0);
    c.middle.all_negative = real(0);
    c.middle.lower = real(0);
    c.middle.t = real(0);
    c.middle.sigma = real(0);
    c.middle.span = real(0);
    c.middle.far_scale = real(0);
    c.middle.two_point = real(0);
    c.middle.center = real(0);
    return c;
}

// glint_binomial_unbiased, reusing the ends and the middle's parameters where N and p are those of
// the cache's last draw with N > 2: the same result, with one setup for draws that share (N, p).
// (glint_binomial_unbiased does not call this with an empty cache: that made it 1.35x slower in
// the median over the binomial grid, the cache's stores not optimised away.)
GLINT_FN glint_binomial glint_binomial_unbiased_cached(real N, real p, real u1, real u2, int method, GLINT_INOUT(glint_binomial_cache) cache) {
    N = clamp(N, real(0), GLINT_BINOMIAL_MAX_N);
    p = clamp(p, real(0), real(1));
    if (glint_binomial_surely_near_end(N, p, u1, method)) return glint_binomial_near_end(N, p);
    if (N <= real(2)) return glint_binomial_unbiased_small(N, p, u1);
    if (!(cache.state > 0 && cache.N == N && cache.p == p)) {
        cache.N = N;
        cache.p = p;
        cache.ends = glint_binomial_unbiased_ends(N, p, method);
        cache.state = 1;
    }
    glint_binomial_gates g = glint_binomial_dual_gates(N, p, u1, cache.ends.all_positive, cache.ends.all_negative);
    real G = real(1);
    if (g.gaussian > real(0.5)) {
        if (cache.state < 2) {
            cache.middle = glint_binomial_unbiased_middle_setup(N, p, cache.ends);
            cache.state = 2;
        }
        G = glint_binomial_unbiased_middle(cache.middle, N, u2);
    }
    return glint_binomial_pair(g.positive_fixed + g.gaussian * G, g.negative_fixed + g.gaussian * (N - G));
}

// ---------------------------------------------------------------------------------------------
// Variant codes, as glint::binomial_variant, and the sampler for a code (any other code: the
// mean-preserving one).
GLINT_CONST(int) GLINT_BINOMIAL_UNGATED = 0;
GLINT_CONST(int) GLINT_BINOMIAL_GATED_DB23 = 1;
GLINT_CONST(int) GLINT_BINOMIAL_GATED = 2;
GLINT_CONST(int) GLINT_BINOMIAL_DUAL_GATED = 3;
GLINT_CONST(int) GLINT_BINOMIAL_UNBIASED = 4;

GLINT_FN glint_binomial glint_binomial_variant(int variant, real N, real p, real u1, real u2, int method) {
    if (variant == GLINT_BINOMIAL_UNGATED) return glint_binomial_ungated(N, p, u2);
    if (variant == GLINT_BINOMIAL_GATED_DB23) return glint_binomial_gated_db23(N, p, u1, u2, method);
    if (variant == GLINT_BINOMIAL_GATED) return glint_binomial_gated(N, p, u1, u2, method);
    if (variant == GLINT_BINOMIAL_DUAL_GATED) return glint_binomial_dual_gated(N, p, u1, u2, method);
    return glint_binomial_unbiased(N, p, u1, u2, method);
}

// glint_binomial_variant with a cache for the mean-preserving sampler's setup (the other variants
// have none to keep): the same result.
GLINT_FN glint_binomial glint_binomial_variant_cached(int variant, real N, real p, real u1, real u2, int method,
                                                     GLINT_INOUT(glint_binomial_cache) cache) {
    if (variant == GLINT_BINOMIAL_UNBIASED) return glint_binomial_unbiased_cached(N, p, u1, u2, method, cache);
    return glint_binomial_variant(variant, N, p, u1, u2, method);
}
