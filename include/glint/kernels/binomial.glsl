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

// The parameters of the mean-preserving sampler's middle part for N > 2 (they do not depend on
// u1, u2; tests evaluate its closed-form distribution from them). The middle part is
// G = 1 + offset (lower = 1) or G = N - 1 - offset (lower = 0), offset = min(sigma max(t + s, 0),
// span), s = +-Z.
struct glint_binomial_middle {
    real all_positive;   // p^N
    real all_negative;   // (1 - p)^N
    real lower;          // 1: offsets count up from n = 1; 0: down from n = N - 1
    real t;              // where the clamp cuts the Gaussian, in standard deviations
    real sigma;          // the Gaussian's scale
    real span;           // N - 2, the largest offset
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

// True where the far end p_near^N is surely below exp(-GLINT_BINOMIAL_UNDERFLOW_MEAN), without a
// transcendental: with p_near = m 2^e (frexp, exact; m < 1), p_near^N <= p_near^floor(N) <
// 2^(floor(N) e), which is at most 2^-128 where floor(N) e <= -128 (2^-1024 in double), below
// exp(-88) = 2.06 * 2^-128 (exp(-709) = 2.19 * 2^-1024) by more than the log1p's rounding. Where it
// holds, the far end's log1p and exp would give 0 (x_far < -88): it saves the log1p.
GLINT_FN bool glint_binomial_far_end_underflows(real N, real p_near) {
    int e;
    frexp(p_near, e);
    return N < real(1024) && int(N) * e <= (GLINT_DOUBLE ? -1024 : -128);
}

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
        bool far_underflows = N * real(0.693147180559945309417) >= GLINT_BINOMIAL_UNDERFLOW_MEAN ||  // log 2, 21 digits
                              glint_binomial_far_end_underflows(N, p_near);
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

// The offset's target moments on the middle M = {1 <= n <= N - 1}, counted from the nearer end:
// m = E[y | M] (clamped to [0, N - 2]) and v = Var[y | M], y = n - 1 (glint/binomial.hpp, step 1).
struct glint_binomial_targets {
    real mean;
    real variance;
};

GLINT_FN glint_binomial_targets glint_binomial_middle_targets(real N, real p, glint_binomial_ends e) {
    real p_near = (e.lower > real(0.5)) ? p : real(1) - p;
    real none_near = (e.lower > real(0.5)) ? e.all_negative : e.all_positive;  // P(near count = 0)
    real all_near = (e.lower > real(0.5)) ? e.all_positive : e.all_negative;   // P(near count = N)
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
    glint_binomial_targets r;
    r.variance = max((mean_y < real(1)) ? var_small : var_large, real(0));
    r.mean = clamp(mean_y, real(0), N - real(2));
    return r;
}

// The one-sided fit: (t, sigma) such that sigma max(t + Z, 0) has mean m and variance v, the far
// bound ignored (glint/binomial.hpp, step 2). Where the mean is 6 or more standard deviations
// from the bound the clamp removes less than Phi(-6) = 1e-9 of the mass: then t = m / sd and
// sigma = sd, as the fit would give to within 1e-9 relative, without its log and exp.
GLINT_FN vec2 glint_binomial_one_sided_fit(glint_binomial_targets g) {
    real tiny = GLINT_FLT_MIN_NORMAL;
    real sd = sqrt(g.variance);
    if (g.mean >= real(6) * sd) return vec2(g.mean / max(sd, tiny), sd);
    vec2 f = glint_clamped_gaussian_fit(log(max(g.variance, tiny) / max(g.mean * g.mean, tiny)));
    return vec2(f.x, g.mean * exp(f.y));
}

// The two-sided fit for 3 <= N <= 32, where the far bound matters (glint/binomial.hpp, step 3),
// in constant time: (t', log(sigma' / sqrt(lambda))), lambda = N p_near, such that
// min(sigma' max(t' + Z, 0), N - 2) has mean m and variance v, tabulated on a 41 x 41 grid and
// read by cubic Lagrange interpolation in both axes (a 4 x 4 stencil, centred except in the edge
// cells). Rows: ((N - 3) / 29)^(1/4)
// uniform from 0 to 1 (dense near N = 3, where sigma' grows without bound as the middle tends to
// the two-point law). Columns: x = log2(p_near) + 20 p_near uniform from -20 to 9 (p_near from
// 9.5e-7 to 1/2: steps of 0.72 in log2 p where p is small, where the far bound's effect follows
// log p, and of 0.03 in p near 1/2), x clamped to that range. From N = 26 to 32 the nodes blend
// into the one-sided fit, solved exactly (bench/binomial_fit.hpp), whose polynomial fit takes
// over at N = 32 (there the far bound removes less than 1e-8 of the mean; the two fits differ by
// at most 4.7e-6 in t). The digits come from
// bench/fit_binomial_far_bound.cpp (damped Newton in double on the closed-form moments of the
// capped offset, glint_capped_offset_moments), which also measures what the interpolation
// leaves: E[n] within 2.9e-5 of N p (relative), the offset's mean within 1.1e-4 and its
// variance within 2.2e-4 of their targets (worst at N = 31.6, p = 0.014 to 0.021). It replaced
// a Newton iteration that took up to 300 ns per draw at N p of 1 to 10; scaled by sqrt(lambda)
// instead of the middle's own sd, it needs neither the ends nor m and v.
GLINT_CONST(real) GLINT_BINOMIAL_FAR_N_MIN = real(3);
GLINT_CONST(real) GLINT_BINOMIAL_FAR_N_MAX = real(32);
GLINT_CONST(real) GLINT_BINOMIAL_FAR_X_MIN = real(-20);
GLINT_CONST(real) GLINT_BINOMIAL_FAR_X_STEP = real(0.725);                  // (9 - (-20)) / 40
GLINT_CONST(int) GLINT_BINOMIAL_FAR_ROWS = 41;
GLINT_CONST(int) GLINT_BINOMIAL_FAR_COLUMNS = 41;
// In GLSL the table can come from a shader storage buffer instead of a constant array: define
// GLINT_BINOMIAL_TABLE_BINDING (this file declares the buffer at that binding) or declare
// `vec4 GLINT_BINOMIAL_FAR_TABLE[]` in a buffer yourself and define GLINT_BINOMIAL_TABLE_DECLARED,
// and fill it with glint::glsl_binomial_table() (glsl.hpp). The constant array needs no buffer,
// but GLSL indexes a constant array at run time through a private copy: the SPIR-V that glslang
// and spirv-opt -O make of glint_gl's IBL shading pass holds 64 copies of the 13 KB array per
// invocation (864 KB; 2.7 KB with the buffer), and on an NVIDIA H200 that program shaded even the
// pixels where it drew no glint 5600x slower than the smooth program (docs/gpu.md; whether the
// buffer cures it there is not yet measured).
#if defined(GLINT_GLSL) && !defined(GLINT_BINOMIAL_TABLE_DECLARED) && defined(GLINT_BINOMIAL_TABLE_BINDING)
layout(std430, binding = GLINT_BINOMIAL_TABLE_BINDING) readonly buffer glint_binomial_table_buffer { vec4 GLINT_BINOMIAL_FAR_TABLE[]; };
#endif
#if !defined(GLINT_GLSL) || !(defined(GLINT_BINOMIAL_TABLE_DECLARED) || defined(GLINT_BINOMIAL_TABLE_BINDING))
// Generated by bench/fit_binomial_far_bound.cpp: (t', log(sigma' / sqrt(lambda))) per node, row by row,
// padded to whole vec4s.
GLINT_FLOAT_TABLE(GLINT_BINOMIAL_FAR_TABLE, 3364) GLINT_TABLE_OPEN
    GLINT_FLOAT4(-4.76188993e+00f, 1.24873247e+01f, -4.65936804e+00f, 1.21194830e+01f), GLINT_FLOAT4(-4.55475521e+00f, 1.17851524e+01f, -4.44791317e+00f, 1.14745302e+01f),
    GLINT_FLOAT4(-4.33869362e+00f, 1.11827650e+01f, -4.22693205e+00f, 1.09075174e+01f), GLINT_FLOAT4(-4.11244869e+00f, 1.06480398e+01f, -3.99504280e+00f, 1.04048500e+01f),
    GLINT_FLOAT4(-3.87449408e+00f, 1.01798058e+01f, -3.75055814e+00f, 9.97657394e+00f), GLINT_FLOAT4(-3.62296915e+00f, 9.80184841e+00f, -3.49144244e+00f, 9.66849899e+00f),
    GLINT_FLOAT4(-3.35568643e+00f, 9.60547733e+00f, -3.21543479e+00f, 9.70586967e+00f), GLINT_FLOAT4(-3.07052803e+00f, 1.05816135e+01f, -2.91957855e+00f, 8.97897720e+00f),
    GLINT_FLOAT4(-2.76407123e+00f, 8.49271393e+00f, -2.60420537e+00f, 8.11511040e+00f), GLINT_FLOAT4(-2.44060946e+00f, 7.96351290e+00f, -2.27562451e+00f, 7.52387142e+00f),
    GLINT_FLOAT4(-2.11044216e+00f, 7.54960299e+00f, -1.94900870e+00f, 8.15682316e+00f), GLINT_FLOAT4(-1.79327929e+00f, 8.23276997e+00f, -1.64472437e+00f, 7.46378613e+00f),
    GLINT_FLOAT4(-1.50513887e+00f, 7.16817951e+00f, -1.37458801e+00f, 7.05820847e+00f), GLINT_FLOAT4(-1.25260258e+00f, 7.12927151e+00f, -1.13844895e+00f, 7.64367437e+00f),
    GLINT_FLOAT4(-1.03052902e+00f, 7.03264618e+00f, -9.28309679e-01f, 6.55204773e+00f), GLINT_FLOAT4(-8.31366956e-01f, 6.26389503e+00f, -7.38513589e-01f, 6.57858658e+00f),
    GLINT_FLOAT4(-6.49355888e-01f, 6.64159775e+00f, -5.63722670e-01f, 7.69809771e+00f), GLINT_FLOAT4(-4.79093850e-01f, 6.54865885e+00f, -3.96723390e-01f, 6.22445297e+00f),
    GLINT_FLOAT4(-3.16058427e-01f, 6.23968172e+00f, -2.36945465e-01f, 7.11201620e+00f), GLINT_FLOAT4(-1.56792566e-01f, 5.93068695e+00f, -7.77693987e-02f, 5.72571325e+00f),
    GLINT_FLOAT4(2.95211258e-03f, 4.70509195e+00f, -4.76188946e+00f, 1.24869633e+01f), GLINT_FLOAT4(-4.65936756e+00f, 1.21191549e+01f, -4.55475473e+00f, 1.17848454e+01f),
    GLINT_FLOAT4(-4.44791269e+00f, 1.14742355e+01f, -4.33869314e+00f, 1.11824741e+01f), GLINT_FLOAT4(-4.22693157e+00f, 1.09072275e+01f, -4.11244822e+00f, 1.06477442e+01f),
    GLINT_FLOAT4(-3.99504256e+00f, 1.04045448e+01f, -3.87449360e+00f, 1.01794844e+01f), GLINT_FLOAT4(-3.75055766e+00f, 9.97622585e+00f, -3.62296891e+00f, 9.80146122e+00f),
    GLINT_FLOAT4(-3.49144220e+00f, 9.66804886e+00f, -3.35568619e+00f, 9.60491467e+00f), GLINT_FLOAT4(-3.21543431e+00f, 9.70503807e+00f, -3.07053876e+00f, 1.06314020e+01f),
    GLINT_FLOAT4(-2.91958499e+00f, 8.98666096e+00f, -2.76407743e+00f, 8.49836540e+00f), GLINT_FLOAT4(-2.60421324e+00f, 8.12110710e+00f, -2.44061446e+00f, 7.96787596e+00f),
    GLINT_FLOAT4(-2.27566886e+00f, 7.55420065e+00f, -2.11045671e+00f, 7.56218767e+00f), GLINT_FLOAT4(-1.94901466e+00f, 8.17127609e+00f, -1.79327869e+00f, 8.23068619e+00f),
    GLINT_FLOAT4(-1.64472377e+00f, 7.46262646e+00f, -1.50513816e+00f, 7.16715860e+00f), GLINT_FLOAT4(-1.37458730e+00f, 7.05714703e+00f, -1.25260186e+00f, 7.12797117e+00f),
    GLINT_FLOAT4(-1.13844812e+00f, 7.64121008e+00f, -1.03053629e+00f, 7.04441452e+00f), GLINT_FLOAT4(-9.28318501e-01f, 6.56145620e+00f, -8.31395745e-01f, 6.28776741e+00f),
    GLINT_FLOAT4(-7.38515139e-01f, 6.58132267e+00f, -6.49357677e-01f, 6.64500046e+00f), GLINT_FLOAT4(-5.63729167e-01f, 7.72691536e+00f, -4.79092956e-01f, 6.54727888e+00f),
    GLINT_FLOAT4(-3.96722466e-01f, 6.22340679e+00f, -3.16057473e-01f, 6.23856831e+00f), GLINT_FLOAT4(-2.36948207e-01f, 7.12137032e+00f, -1.56794772e-01f, 5.93356228e+00f),
    GLINT_FLOAT4(-7.77763203e-02f, 5.73142385e+00f, 3.02409986e-03f, 4.68573713e+00f), GLINT_FLOAT4(-4.76185417e+00f, 1.24409475e+01f, -4.65933180e+00f, 1.20773888e+01f),
    GLINT_FLOAT4(-4.55471802e+00f, 1.17456055e+01f, -4.44787550e+00f, 1.14364471e+01f), GLINT_FLOAT4(-4.33865452e+00f, 1.11453524e+01f, -4.22689247e+00f, 1.08701124e+01f),
    GLINT_FLOAT4(-4.11240768e+00f, 1.06100016e+01f, -3.99500108e+00f, 1.03654833e+01f), GLINT_FLOAT4(-3.87445092e+00f, 1.01382608e+01f, -3.75051379e+00f, 9.93169594e+00f),
    GLINT_FLOAT4(-3.62292314e+00f, 9.75189114e+00f, -3.49139476e+00f, 9.61044407e+00f), GLINT_FLOAT4(-3.35563636e+00f, 9.53297234e+00f, -3.21538138e+00f, 9.59904671e+00f),
    GLINT_FLOAT4(-3.07051325e+00f, 1.06083078e+01f, -2.91956353e+00f, 8.99390697e+00f), GLINT_FLOAT4(-2.76405430e+00f, 8.50381279e+00f, -2.60419297e+00f, 8.12908936e+00f),
    GLINT_FLOAT4(-2.44062591e+00f, 8.00548840e+00f, -2.27566075e+00f, 7.57237768e+00f), GLINT_FLOAT4(-2.11043215e+00f, 7.57320690e+00f, -1.94925952e+00f, 7.75703430e+00f),
    GLINT_FLOAT4(-1.79318893e+00f, 7.96787977e+00f, -1.64463675e+00f, 7.31484222e+00f), GLINT_FLOAT4(-1.50504827e+00f, 7.03699446e+00f, -1.37449324e+00f, 6.92186213e+00f),
    GLINT_FLOAT4(-1.25250196e+00f, 6.96244764e+00f, -1.13833487e+00f, 7.33200073e+00f), GLINT_FLOAT4(-1.03047967e+00f, 7.05487251e+00f, -9.28259790e-01f, 6.57015324e+00f),
    GLINT_FLOAT4(-8.31344604e-01f, 6.30433369e+00f, -7.38441944e-01f, 6.58405495e+00f), GLINT_FLOAT4(-6.49280548e-01f, 6.64836884e+00f, -5.63650250e-01f, 7.74630976e+00f),
    GLINT_FLOAT4(-4.78965700e-01f, 6.37182999e+00f, -3.96595299e-01f, 6.09004450e+00f), GLINT_FLOAT4(-3.15926820e-01f, 6.09677029e+00f, -2.36849397e-01f, 7.13001442e+00f),
    GLINT_FLOAT4(-1.56694725e-01f, 5.94028950e+00f, -7.76715055e-02f, 5.73698616e+00f), GLINT_FLOAT4(3.18788993e-03f, 4.67335749e+00f, -4.76167345e+00f, 1.22441196e+01f),
    GLINT_FLOAT4(-4.65915060e+00f, 1.18983603e+01f, -4.55453491e+00f, 1.15772152e+01f), GLINT_FLOAT4(-4.44768953e+00f, 1.12741880e+01f, -4.33846474e+00f, 1.09859142e+01f),
    GLINT_FLOAT4(-4.22669792e+00f, 1.07107048e+01f, -4.11220789e+00f, 1.04479408e+01f), GLINT_FLOAT4(-3.99479485e+00f, 1.01978579e+01f, -3.87423706e+00f, 9.96153355e+00f),
    GLINT_FLOAT4(-3.75029063e+00f, 9.74110317e+00f, -3.62268877e+00f, 9.54029369e+00f), GLINT_FLOAT4(-3.49114537e+00f, 9.36571693e+00f, -3.35536528e+00f, 9.23038101e+00f),
    GLINT_FLOAT4(-3.21507049e+00f, 9.16662884e+00f, -3.07009244e+00f, 9.33115959e+00f), GLINT_FLOAT4(-2.91938472e+00f, 8.87021542e+00f, -2.76415563e+00f, 8.71800327e+00f),
    GLINT_FLOAT4(-2.60406637e+00f, 8.13437176e+00f, -2.44076610e+00f, 8.04633141e+00f), GLINT_FLOAT4(-2.27552915e+00f, 7.58546209e+00f, -2.11028123e+00f, 7.58202839e+00f),
    GLINT_FLOAT4(-1.94910121e+00f, 7.77486420e+00f, -1.79258561e+00f, 7.08844995e+00f), GLINT_FLOAT4(-1.64410186e+00f, 6.73914146e+00f, -1.50451124e+00f, 6.51938009e+00f),
    GLINT_FLOAT4(-1.37392974e+00f, 6.38709497e+00f, -1.25188518e+00f, 6.33186531e+00f), GLINT_FLOAT4(-1.13758600e+00f, 6.36159134e+00f, -1.03015172e+00f, 6.53628731e+00f),
    GLINT_FLOAT4(-9.28402245e-01f, 6.67836142e+00f, -8.31049979e-01f, 6.31612301e+00f), GLINT_FLOAT4(-7.38565803e-01f, 6.48920107e+00f, -6.49563074e-01f, 6.67397070e+00f),
    GLINT_FLOAT4(-5.62557578e-01f, 5.98500061e+00f, -4.78204817e-01f, 5.71160316e+00f), GLINT_FLOAT4(-3.95871103e-01f, 5.56163979e+00f, -3.15178663e-01f, 5.54054117e+00f),
    GLINT_FLOAT4(-2.35948116e-01f, 5.82278347e+00f, -1.56668082e-01f, 5.75716925e+00f), GLINT_FLOAT4(-7.80487880e-02f, 5.98385954e+00f, 3.73373367e-03f, 4.66405249e+00f),
    GLINT_FLOAT4(-4.76100969e+00f, 1.17706766e+01f, -4.65849304e+00f, 1.14605436e+01f), GLINT_FLOAT4(-4.55387592e+00f, 1.11614895e+01f, -4.44702339e+00f, 1.08714666e+01f),
    GLINT_FLOAT4(-4.33778763e+00f, 1.05892487e+01f, -4.22600460e+00f, 1.03141136e+01f), GLINT_FLOAT4(-4.11149311e+00f, 1.00456772e+01f, -3.99405336e+00f, 9.78380013e+00f),
    GLINT_FLOAT4(-3.87346244e+00f, 9.52853203e+00f, -3.74947381e+00f, 9.28007412e+00f), GLINT_FLOAT4(-3.62181830e+00f, 9.03872871e+00f, -3.49020386e+00f, 8.80482292e+00f),
    GLINT_FLOAT4(-3.35432553e+00f, 8.57853508e+00f, -3.21388078e+00f, 8.35952377e+00f), GLINT_FLOAT4(-3.06860399e+00f, 8.14610481e+00f, -2.91832471e+00f, 7.93360233e+00f),
    GLINT_FLOAT4(-2.76306772e+00f, 7.71191597e+00f, -2.60320330e+00f, 7.46555042e+00f), GLINT_FLOAT4(-2.43965316e+00f, 7.18429852e+00f, -2.27407622e+00f, 6.87826824e+00f),
    GLINT_FLOAT4(-2.10886097e+00f, 6.57165527e+00f, -1.94680893e+00f, 6.28565264e+00f), GLINT_FLOAT4(-1.79057920e+00f, 6.03245354e+00f, -1.64214301e+00f, 5.81668949e+00f),
    GLINT_FLOAT4(-1.50252068e+00f, 5.63796425e+00f, -1.37185657e+00f, 5.49291849e+00f), GLINT_FLOAT4(-1.24968123e+00f, 5.37657547e+00f, -1.13519025e+00f, 5.28296757e+00f),
    GLINT_FLOAT4(-1.02745092e+00f, 5.20524788e+00f, -9.25525367e-01f, 5.13572979e+00f), GLINT_FLOAT4(-8.28534603e-01f, 5.06656313e+00f, -7.35687971e-01f, 4.99166155e+00f),
    GLINT_FLOAT4(-6.46294117e-01f, 4.90922070e+00f, -5.59758782e-01f, 4.82281446e+00f), GLINT_FLOAT4(-4.75572348e-01f, 4.74026060e+00f, -3.93294752e-01f, 4.67205381e+00f),
    GLINT_FLOAT4(-3.12541068e-01f, 4.63118649e+00f, -2.32961237e-01f, 4.63348436e+00f), GLINT_FLOAT4(-1.54146969e-01f, 4.68310308e+00f, -7.50911012e-02f, 4.63250923e+00f),
    GLINT_FLOAT4(4.00412967e-03f, 4.61409760e+00f, -4.75920343e+00f, 1.10926495e+01f), GLINT_FLOAT4(-4.65668678e+00f, 1.08093195e+01f, -4.55205727e+00f, 1.05283813e+01f),
    GLINT_FLOAT4(-4.44518089e+00f, 1.02495995e+01f, -4.33591032e+00f, 9.97277451e+00f), GLINT_FLOAT4(-4.22408247e+00f, 9.69772243e+00f, -4.10951471e+00f, 9.42425823e+00f),
    GLINT_FLOAT4(-3.99200606e+00f, 9.15218258e+00f, -3.87133241e+00f, 8.88125992e+00f), GLINT_FLOAT4(-3.74724507e+00f, 8.61120319e+00f, -3.61947179e+00f, 8.34165001e+00f),
    GLINT_FLOAT4(-3.48771811e+00f, 8.07214355e+00f, -3.35167527e+00f, 7.80212688e+00f), GLINT_FLOAT4(-3.21103787e+00f, 7.53096294e+00f, -3.06553984e+00f, 7.25801325e+00f),
    GLINT_FLOAT4(-2.91501641e+00f, 6.98282290e+00f, -2.75950933e+00f, 6.70545769e+00f), GLINT_FLOAT4(-2.59942055e+00f, 6.42698574e+00f, -2.43570161e+00f, 6.14999151e+00f),
    GLINT_FLOAT4(-2.27001071e+00f, 5.87882042e+00f, -2.10470963e+00f, 5.61919498e+00f), GLINT_FLOAT4(-1.94257271e+00f, 5.37707758e+00f, -1.78624308e+00f, 5.15719223e+00f),
    GLINT_FLOAT4(-1.63768542e+00f, 4.96197605e+00f, -1.49791956e+00f, 4.79143667e+00f), GLINT_FLOAT4(-1.36709177e+00f, 4.64373827e+00f, -1.24473703e+00f, 4.51600409e+00f),
    GLINT_FLOAT4(-1.13005733e+00f, 4.40497828e+00f, -1.02212989e+00f, 4.30743790e+00f), GLINT_FLOAT4(-9.20029998e-01f, 4.22043419e+00f, -8.22894216e-01f, 4.14143848e+00f),
    GLINT_FLOAT4(-7.29944110e-01f, 4.06847191e+00f, -6.40490234e-01f, 4.00023460e+00f), GLINT_FLOAT4(-5.53926647e-01f, 3.93624187e+00f, -4.69721347e-01f, 3.87693739e+00f),
    GLINT_FLOAT4(-3.87404978e-01f, 3.82374668e+00f, -3.06557298e-01f, 3.77893639e+00f), GLINT_FLOAT4(-2.26784870e-01f, 3.74470043e+00f, -1.47664785e-01f, 3.71909881e+00f),
    GLINT_FLOAT4(-6.85777888e-02f, 3.68118072e+00f, 1.10824835e-02f, 3.61238623e+00f), GLINT_FLOAT4(-4.75563765e+00f, 1.04236679e+01f, -4.65307474e+00f, 1.01490307e+01f),
    GLINT_FLOAT4(-4.54838800e+00f, 9.87441063e+00f, -4.44144392e+00f, 9.59974384e+00f), GLINT_FLOAT4(-4.33209372e+00f, 9.32495213e+00f, -4.22017384e+00f, 9.04994297e+00f),
    GLINT_FLOAT4(-4.10550117e+00f, 8.77460480e+00f, -3.98787355e+00f, 8.49880791e+00f), GLINT_FLOAT4(-3.86706519e+00f, 8.22239876e+00f, -3.74282670e+00f, 7.94520950e+00f),
    GLINT_FLOAT4(-3.61488414e+00f, 7.66705656e+00f, -3.48294234e+00f, 7.38776207e+00f), GLINT_FLOAT4(-3.34669113e+00f, 7.10718298e+00f, -3.20582604e+00f, 6.82526684e+00f),
    GLINT_FLOAT4(-3.06008077e+00f, 6.54214621e+00f, -2.90929294e+00f, 6.25828314e+00f), GLINT_FLOAT4(-2.75350738e+00f, 5.97467947e+00f, -2.59312987e+00f, 5.69313192e+00f),
    GLINT_FLOAT4(-2.42911530e+00f, 5.41647148e+00f, -2.26312518e+00f, 5.14861393e+00f), GLINT_FLOAT4(-2.09752393e+00f, 4.89422131e+00f, -1.93508661e+00f, 4.65786982e+00f),
    GLINT_FLOAT4(-1.77845740e+00f, 4.44299459e+00f, -1.62960207e+00f, 4.25116158e+00f), GLINT_FLOAT4(-1.48954189e+00f, 4.08202267e+00f, -1.35842478e+00f, 3.93383002e+00f),
    GLINT_FLOAT4(-1.23578811e+00f, 3.80411100e+00f, -1.12083709e+00f, 3.69020748e+00f), GLINT_FLOAT4(-1.01265204e+00f, 3.58960009e+00f, -9.10312116e-01f, 3.50005984e+00f),
    GLINT_FLOAT4(-8.12957227e-01f, 3.41970110e+00f, -7.19810963e-01f, 3.34698749e+00f), GLINT_FLOAT4(-6.30184114e-01f, 3.28072619e+00f, -5.43467343e-01f, 3.22006774e+00f),
    GLINT_FLOAT4(-4.59121406e-01f, 3.16451192e+00f, -3.76664996e-01f, 3.11391211e+00f), GLINT_FLOAT4(-2.95661986e-01f, 3.06842089e+00f, -2.15703666e-01f, 3.02821326e+00f),
    GLINT_FLOAT4(-1.36374742e-01f, 2.99246001e+00f, -5.71697392e-02f, 2.95604873e+00f), GLINT_FLOAT4(2.24618912e-02f, 2.91218901e+00f, -4.74979925e+00f, 9.84042358e+00f),
    GLINT_FLOAT4(-4.64713049e+00f, 9.56805992e+00f, -4.54232836e+00f, 9.29514027e+00f), GLINT_FLOAT4(-4.43525696e+00f, 9.02160645e+00f, -4.32576799e+00f, 8.74738693e+00f),
    GLINT_FLOAT4(-4.21369600e+00f, 8.47240162e+00f, -4.09885693e+00f, 8.19655991e+00f), GLINT_FLOAT4(-3.98104620e+00f, 7.91976023e+00f, -3.86003733e+00f, 7.64189196e+00f),
    GLINT_FLOAT4(-3.73557925e+00f, 7.36284161e+00f, -3.60739565e+00f, 7.08250475e+00f), GLINT_FLOAT4(-3.47518945e+00f, 6.80080128e+00f, -3.33864856e+00f, 6.51771212e+00f),
    GLINT_FLOAT4(-3.19746590e+00f, 6.23333216e+00f, -3.05137396e+00f, 5.94795990e+00f), GLINT_FLOAT4(-2.90020776e+00f, 5.66222954e+00f, -2.74401164e+00f, 5.37730026e+00f),
    GLINT_FLOAT4(-2.58319139e+00f, 5.09507942e+00f, -2.41870451e+00f, 4.81842566e+00f), GLINT_FLOAT4(-2.25221729e+00f, 4.55117130e+00f, -2.08610106e+00f, 4.29778337e+00f),
    GLINT_FLOAT4(-1.92314148e+00f, 4.06256962e+00f, -1.76599240e+00f, 3.84869909e+00f), GLINT_FLOAT4(-1.61662853e+00f, 3.65754104e+00f, -1.47607732e+00f, 3.48865676e+00f),
    GLINT_FLOAT4(-1.34449053e+00f, 3.34031153e+00f, -1.22140729e+00f, 3.21012211e+00f), GLINT_FLOAT4(-1.10603368e+00f, 3.09556580e+00f, -9.97450113e-01f, 2.99427795e+00f),
    GLINT_FLOAT4(-8.94735932e-01f, 2.90418315e+00f, -7.97030807e-01f, 2.82352686e+00f), GLINT_FLOAT4(-7.03557968e-01f, 2.75086260e+00f, -6.13626719e-01f, 2.68502092e+00f),
    GLINT_FLOAT4(-5.26625812e-01f, 2.62508082e+00f, -4.42011923e-01f, 2.57034588e+00f), GLINT_FLOAT4(-3.59298050e-01f, 2.52032328e+00f, -2.78040498e-01f, 2.47468805e+00f),
    GLINT_FLOAT4(-1.97823659e-01f, 2.43317986e+00f, -1.18235663e-01f, 2.39527178e+00f), GLINT_FLOAT4(-3.88168544e-02f, 2.35916829e+00f, 4.08839136e-02f, 2.32346177e+00f),
    GLINT_FLOAT4(-4.74121189e+00f, 9.34284496e+00f, -4.63837528e+00f, 9.07114601e+00f), GLINT_FLOAT4(-4.53339291e+00f, 8.79873180e+00f, -4.42612839e+00f, 8.52554035e+00f),
    GLINT_FLOAT4(-4.31643105e+00f, 8.25150204e+00f, -4.20413399e+00f, 7.97654009e+00f), GLINT_FLOAT4(-4.08905172e+00f, 7.70056820e+00f, -3.97097802e+00f, 7.42349291e+00f),
    GLINT_FLOAT4(-3.84968328e+00f, 7.14521885e+00f, -3.72491384e+00f, 6.86565018e+00f), GLINT_FLOAT4(-3.59639072e+00f, 6.58470440e+00f, -3.46381307e+00f, 6.30233145e+00f),
    GLINT_FLOAT4(-3.32686520e+00f, 6.01854610e+00f, -3.18523598e+00f, 5.73348284e+00f), GLINT_FLOAT4(-3.03865290e+00f, 5.44748163e+00f, -2.88694739e+00f, 5.16121912e+00f),
    GLINT_FLOAT4(-2.73016000e+00f, 4.87589121e+00f, -2.56869531e+00f, 4.59343052e+00f), GLINT_FLOAT4(-2.40351200e+00f, 4.31670046e+00f, -2.23628330e+00f, 4.04951477e+00f),
    GLINT_FLOAT4(-2.06939244e+00f, 3.79629278e+00f, -1.90564203e+00f, 3.56128025e+00f), GLINT_FLOAT4(-1.74770355e+00f, 3.34758234e+00f, -1.59756768e+00f, 3.15652013e+00f),
    GLINT_FLOAT4(-1.45627284e+00f, 2.98763347e+00f, -1.32397711e+00f, 2.83919120e+00f), GLINT_FLOAT4(-1.20022190e+00f, 2.70883298e+00f, -1.08421314e+00f, 2.59407139e+00f),
    GLINT_FLOAT4(-9.75029767e-01f, 2.49258184e+00f, -8.71749341e-01f, 2.40232778e+00f), GLINT_FLOAT4(-7.73509443e-01f, 2.32158875e+00f, -6.79531217e-01f, 2.24894047e+00f),
    GLINT_FLOAT4(-5.89121997e-01f, 2.18321872e+00f, -5.01668036e-01f, 2.12348294e+00f), GLINT_FLOAT4(-4.16623205e-01f, 2.06898212e+00f, -3.33496898e-01f, 2.01912737e+00f),
    GLINT_FLOAT4(-2.51841068e-01f, 1.97346175e+00f, -1.71236128e-01f, 1.93160427e+00f), GLINT_FLOAT4(-9.12710726e-02f, 1.89311171e+00f, -1.15063442e-02f, 1.85708702e+00f),
    GLINT_FLOAT4(6.84408993e-02f, 1.82358658e+00f, -4.72954273e+00f, 8.91965199e+00f), GLINT_FLOAT4(-4.62647247e+00f, 8.64818859e+00f, -4.52124119e+00f, 8.37595940e+00f),
    GLINT_FLOAT4(-4.41371059e+00f, 8.10289955e+00f, -4.30372858e+00f, 7.82894182e+00f), GLINT_FLOAT4(-4.19112587e+00f, 7.55400753e+00f, -4.07571411e+00f, 7.27801323e+00f),
    GLINT_FLOAT4(-3.95728469e+00f, 7.00086927e+00f, -3.83560514e+00f, 6.72248268e+00f), GLINT_FLOAT4(-3.71041751e+00f, 6.44276428e+00f, -3.58143878e+00f, 6.16163778e+00f),
    GLINT_FLOAT4(-3.44836307e+00f, 5.87906218e+00f, -3.31086922e+00f, 5.59506083e+00f), GLINT_FLOAT4(-3.16863918e+00f, 5.30977774e+00f, -3.02139449e+00f, 5.02356386e+00f),
    GLINT_FLOAT4(-2.86895943e+00f, 4.73710489e+00f, -2.71136832e+00f, 4.45160389e+00f), GLINT_FLOAT4(-2.54902244e+00f, 4.16899824e+00f, -2.38288188e+00f, 3.89215207e+00f),
    GLINT_FLOAT4(-2.21462750e+00f, 3.62487483e+00f, -2.04665899e+00f, 3.37157917e+00f), GLINT_FLOAT4(-1.88180184e+00f, 3.13650131e+00f, -1.72275376e+00f, 2.92273736e+00f),
    GLINT_FLOAT4(-1.57152832e+00f, 2.73160219e+00f, -1.42918074e+00f, 2.56263304e+00f), GLINT_FLOAT4(-1.29587817e+00f, 2.41410065e+00f, -1.17116559e+00f, 2.28365016e+00f),
    GLINT_FLOAT4(-1.05424869e+00f, 2.16880178e+00f, -9.44203973e-01f, 2.06724048e+00f), GLINT_FLOAT4(-8.40105951e-01f, 1.97693908e+00f, -7.41088748e-01f, 1.89618492e+00f),
    GLINT_FLOAT4(-6.46370411e-01f, 1.82355857e+00f, -5.55255353e-01f, 1.75789547e+00f), GLINT_FLOAT4(-4.67126966e-01f, 1.69824672e+00f, -3.81436497e-01f, 1.64384270e+00f),
    GLINT_FLOAT4(-2.97690421e-01f, 1.59406233e+00f, -2.15437666e-01f, 1.54840338e+00f), GLINT_FLOAT4(-1.34255737e-01f, 1.50644457e+00f, -5.37329018e-02f, 1.46776748e+00f),
    GLINT_FLOAT4(2.65486091e-02f, 1.43189323e+00f, 1.06962271e-01f, 1.39885449e+00f), GLINT_FLOAT4(-4.71471167e+00f, 8.56087303e+00f, -4.61134243e+00f, 8.28951836e+00f),
    GLINT_FLOAT4(-4.50579262e+00f, 8.01737976e+00f, -4.39792252e+00f, 7.74439383e+00f), GLINT_FLOAT4(-4.28757715e+00f, 7.47048998e+00f, -4.17458534e+00f, 7.19559240e+00f),
    GLINT_FLOAT4(-4.05875540e+00f, 6.91961718e+00f, -3.93987489e+00f, 6.64247561e+00f), GLINT_FLOAT4(-3.81770730e+00f, 6.36407614e+00f, -3.69198990e+00f, 6.08433056e+00f),
    GLINT_FLOAT4(-3.56243420e+00f, 5.80316544e+00f, -3.42872739e+00f, 5.52053928e+00f), GLINT_FLOAT4(-3.29054117e+00f, 5.23647738e+00f, -3.14754844e+00f, 4.95112419e+00f),
    GLINT_FLOAT4(-2.99946165e+00f, 4.66482973e+00f, -2.84609532e+00f, 4.37827873e+00f), GLINT_FLOAT4(-2.68747520e+00f, 4.09267139e+00f, -2.52399611e+00f, 3.80994248e+00f),
    GLINT_FLOAT4(-2.35661793e+00f, 3.53295422e+00f, -2.18703032e+00f, 3.26551890e+00f), GLINT_FLOAT4(-2.01765275e+00f, 3.01205540e+00f, -1.85133994e+00f, 2.77681017e+00f),
    GLINT_FLOAT4(-1.69082332e+00f, 2.56289077e+00f, -1.53814733e+00f, 2.37162113e+00f), GLINT_FLOAT4(-1.39438975e+00f, 2.20254326e+00f, -1.25973105e+00f, 2.05392909e+00f),
    GLINT_FLOAT4(-1.13372147e+00f, 1.92342281e+00f, -1.01556683e+00f, 1.80854297e+00f), GLINT_FLOAT4(-9.04340982e-01f, 1.70697260e+00f, -7.99114347e-01f, 1.61668336e+00f),
    GLINT_FLOAT4(-6.99016929e-01f, 1.53596139e+00f, -6.03262663e-01f, 1.46338546e+00f), GLINT_FLOAT4(-5.11152327e-01f, 1.39778817e+00f, -4.22066152e-01f, 1.33821535e+00f),
    GLINT_FLOAT4(-3.35452497e-01f, 1.28388846e+00f, -2.50815213e-01f, 1.23417258e+00f), GLINT_FLOAT4(-1.67700678e-01f, 1.18854725e+00f, -8.56838077e-02f, 1.14657319e+00f),
    GLINT_FLOAT4(-4.35072044e-03f, 1.10783720e+00f, 7.66895786e-02f, 1.07208669e+00f), GLINT_FLOAT4(1.57834455e-01f, 1.03910804e+00f, -4.69694662e+00f, 8.25858498e+00f),
    GLINT_FLOAT4(-4.59321737e+00f, 7.98730087e+00f, -4.48728514e+00f, 7.71522617e+00f), GLINT_FLOAT4(-4.37900734e+00f, 7.44229794e+00f, -4.26822662e+00f, 7.16844702e+00f),
    GLINT_FLOAT4(-4.15476799e+00f, 6.89359617e+00f, -4.03843689e+00f, 6.61766291e+00f), GLINT_FLOAT4(-3.91901660e+00f, 6.34055758e+00f, -3.79626465e+00f, 6.06219006e+00f),
    GLINT_FLOAT4(-3.66991329e+00f, 5.78247118e+00f, -3.53966641e+00f, 5.50132704e+00f), GLINT_FLOAT4(-3.40520358e+00f, 5.21871567e+00f, -3.26618648e+00f, 4.93466043e+00f),
    GLINT_FLOAT4(-3.12227774e+00f, 4.64930153e+00f, -2.97317743e+00f, 4.36298466e+00f), GLINT_FLOAT4(-2.81868720e+00f, 4.07638741e+00f, -2.65882063e+00f, 3.79070330e+00f),
    GLINT_FLOAT4(-2.49396348e+00f, 3.50786090e+00f, -2.32507277e+00f, 3.23071980e+00f), GLINT_FLOAT4(-2.15384603e+00f, 2.96309614e+00f, -1.98272467e+00f, 2.70942307e+00f),
    GLINT_FLOAT4(-1.81459785e+00f, 2.47396731e+00f, -1.65223777e+00f, 2.25985885e+00f), GLINT_FLOAT4(-1.49772727e+00f, 2.06843901e+00f, -1.35217333e+00f, 1.89925885e+00f),
    GLINT_FLOAT4(-1.21577394e+00f, 1.75059056e+00f, -1.08808720e+00f, 1.62007415e+00f), GLINT_FLOAT4(-9.68319952e-01f, 1.50522065e+00f, -8.55543673e-01f, 1.40370560e+00f),
    GLINT_FLOAT4(-7.48824239e-01f, 1.31349373e+00f, -6.47286892e-01f, 1.23286521e+00f), GLINT_FLOAT4(-5.50140977e-01f, 1.16039348e+00f, -4.56683010e-01f, 1.09490621e+00f),
    GLINT_FLOAT4(-3.66289794e-01f, 1.03544402e+00f, -2.78406739e-01f, 9.81221974e-01f), GLINT_FLOAT4(-1.92535073e-01f, 9.31597173e-01f, -1.08218670e-01f, 8.86038721e-01f),
    GLINT_FLOAT4(-2.50296853e-02f, 8.44096184e-01f, 5.74382022e-02f, 8.05404246e-01f), GLINT_FLOAT4(1.39574587e-01f, 7.69699872e-01f, 2.21783221e-01f, 7.36724496e-01f),
    GLINT_FLOAT4(-4.67675686e+00f, 8.00612831e+00f, -4.57261753e+00f, 7.73490381e+00f), GLINT_FLOAT4(-4.46624994e+00f, 7.46288824e+00f, -4.35750818e+00f, 7.19001865e+00f),
    GLINT_FLOAT4(-4.24623251e+00f, 6.91622591e+00f, -4.13224363e+00f, 6.64143324e+00f), GLINT_FLOAT4(-4.01534271e+00f, 6.36555815e+00f, -3.89530802e+00f, 6.08851194e+00f),
    GLINT_FLOAT4(-3.77189207e+00f, 5.81020308e+00f, -3.64481950e+00f, 5.53054237e+00f), GLINT_FLOAT4(-3.51378655e+00f, 5.24945545e+00f, -3.37846279e+00f, 4.96689749e+00f),
    GLINT_FLOAT4(-3.23849940e+00f, 4.68288851e+00f, -3.09354544e+00f, 4.39756489e+00f), GLINT_FLOAT4(-2.94328618e+00f, 4.11126423e+00f, -2.78750777e+00f, 3.82465553e+00f),
    GLINT_FLOAT4(-2.62620759e+00f, 3.53892183e+00f, -2.45975804e+00f, 3.25598335e+00f), GLINT_FLOAT4(-2.28911018e+00f, 2.97869563e+00f, -2.11596751e+00f, 2.71088028e+00f),
    GLINT_FLOAT4(-1.94279325e+00f, 2.45698786e+00f, -1.77251410e+00f, 2.22131348e+00f), GLINT_FLOAT4(-1.60794914e+00f, 2.00701761e+00f, -1.45122635e+00f, 1.81546569e+00f),
    GLINT_FLOAT4(-1.30348766e+00f, 1.64622033e+00f, -1.16495323e+00f, 1.49755442e+00f), GLINT_FLOAT4(-1.03519189e+00f, 1.36709964e+00f, -9.13412929e-01f, 1.25235581e+00f),
    GLINT_FLOAT4(-7.98685610e-01f, 1.15098608e+00f, -6.90071583e-01f, 1.06094360e+00f), GLINT_FLOAT4(-5.86690784e-01f, 9.80498612e-01f, -4.87747669e-01f, 9.08216000e-01f),
    GLINT_FLOAT4(-3.92534375e-01f, 8.42916489e-01f, -3.00423920e-01f, 7.83634067e-01f), GLINT_FLOAT4(-2.10858598e-01f, 7.29577482e-01f, -1.23337075e-01f, 6.80096805e-01f),
    GLINT_FLOAT4(-3.74005288e-02f, 6.34652615e-01f, 4.73780669e-02f, 5.92798710e-01f), GLINT_FLOAT4(1.31398484e-01f, 5.54189742e-01f, 2.15057671e-01f, 5.18522561e-01f),
    GLINT_FLOAT4(2.98752338e-01f, 4.85557795e-01f, -4.65483236e+00f, 7.79742718e+00f), GLINT_FLOAT4(-4.55024815e+00f, 7.52626228e+00f, -4.44340706e+00f, 7.25430822e+00f),
    GLINT_FLOAT4(-4.33416128e+00f, 6.98150253e+00f, -4.22234726e+00f, 6.70777607e+00f), GLINT_FLOAT4(-4.10778189e+00f, 6.43305206e+00f, -3.99026179e+00f, 6.15724897e+00f),
    GLINT_FLOAT4(-3.86955976e+00f, 5.88027811e+00f, -3.74542189e+00f, 5.60204744e+00f), GLINT_FLOAT4(-3.61756539e+00f, 5.32246876e+00f, -3.48567748e+00f, 5.04146433e+00f),
    GLINT_FLOAT4(-3.34941745e+00f, 4.75898886e+00f, -3.20842290e+00f, 4.47505856e+00f), GLINT_FLOAT4(-3.06232929e+00f, 4.18980360e+00f, -2.91080379e+00f, 3.90355468e+00f),
    GLINT_FLOAT4(-2.75361419e+00f, 3.61697006e+00f, -2.59073830e+00f, 3.33122158e+00f), GLINT_FLOAT4(-2.42253137e+00f, 3.04821777e+00f, -2.24993348e+00f, 2.77080917e+00f),
    GLINT_FLOAT4(-2.07465053e+00f, 2.50282288e+00f, -1.89916587e+00f, 2.24872971e+00f), GLINT_FLOAT4(-1.72644508e+00f, 2.01285839e+00f, -1.55935764e+00f, 1.79840755e+00f),
    GLINT_FLOAT4(-1.40008163e+00f, 1.60677254e+00f, -1.24979925e+00f, 1.43753135e+00f), GLINT_FLOAT4(-1.10875702e+00f, 1.28895664e+00f, -9.76536691e-01f, 1.15866947e+00f),
    GLINT_FLOAT4(-8.52351427e-01f, 1.04415345e+00f, -7.35268891e-01f, 9.43054378e-01f), GLINT_FLOAT4(-6.24346077e-01f, 8.53309453e-01f, -5.18697739e-01f, 7.73174524e-01f),
    GLINT_FLOAT4(-4.17522937e-01f, 7.01202691e-01f, -3.20109099e-01f, 6.36204541e-01f), GLINT_FLOAT4(-2.25825310e-01f, 5.77205479e-01f, -1.34110674e-01f, 5.23406506e-01f),
    GLINT_FLOAT4(-4.44608666e-02f, 4.74149406e-01f, 4.35839370e-02f, 4.28890914e-01f), GLINT_FLOAT4(1.30445883e-01f, 3.87195677e-01f, 2.16529518e-01f, 3.48695725e-01f),
    GLINT_FLOAT4(3.02227199e-01f, 3.13093454e-01f, 3.87930959e-01f, 2.80150592e-01f), GLINT_FLOAT4(-4.63190365e+00f, 7.62662125e+00f, -4.52685261e+00f, 7.35551834e+00f),
    GLINT_FLOAT4(-4.41951609e+00f, 7.08362961e+00f, -4.30974293e+00f, 6.81089258e+00f), GLINT_FLOAT4(-4.19736528e+00f, 6.53723907e+00f, -4.08219671e+00f, 6.26259279e+00f),
    GLINT_FLOAT4(-3.96402836e+00f, 5.98687172e+00f, -3.84262753e+00f, 5.70998812e+00f), GLINT_FLOAT4(-3.71773386e+00f, 5.43184996e+00f, -3.58905602e+00f, 5.15236902e+00f),
    GLINT_FLOAT4(-3.45627236e+00f, 4.87146664e+00f, -3.31903028e+00f, 4.58909607e+00f), GLINT_FLOAT4(-3.17695427e+00f, 4.30527020e+00f, -3.02966309e+00f, 4.02011395e+00f),
    GLINT_FLOAT4(-2.87680554e+00f, 3.73395014e+00f, -2.71812797e+00f, 3.44742727e+00f), GLINT_FLOAT4(-2.55358553e+00f, 3.16170478e+00f, -2.38351202e+00f, 2.87867904e+00f),
    GLINT_FLOAT4(-2.20883274e+00f, 2.60119343e+00f, -2.03125095e+00f, 2.33308005e+00f), GLINT_FLOAT4(-1.85326695e+00f, 2.07883072e+00f, -1.67788410e+00f, 1.84281254e+00f),
    GLINT_FLOAT4(-1.50802314e+00f, 1.62826777e+00f, -1.34591603e+00f, 1.43662846e+00f), GLINT_FLOAT4(-1.19278908e+00f, 1.26749182e+00f, -1.04891753e+00f, 1.11913037e+00f),
    GLINT_FLOAT4(-9.13898349e-01f, 9.89151895e-01f, -7.86948979e-01f, 8.75019252e-01f), GLINT_FLOAT4(-6.67135239e-01f, 7.74355650e-01f, -5.53509057e-01f, 6.85076594e-01f),
    GLINT_FLOAT4(-4.45179075e-01f, 6.05418801e-01f, -3.41338217e-01f, 5.33919156e-01f), GLINT_FLOAT4(-2.41268620e-01f, 4.69374537e-01f, -1.44334808e-01f, 4.10798728e-01f),
    GLINT_FLOAT4(-4.99719977e-02f, 3.57382029e-01f, 4.23264913e-02f, 3.08458328e-01f), GLINT_FLOAT4(1.33017749e-01f, 2.63486952e-01f, 2.22527400e-01f, 2.22017303e-01f),
    GLINT_FLOAT4(3.11256796e-01f, 1.83681294e-01f, 3.99594486e-01f, 1.48179427e-01f), GLINT_FLOAT4(4.87927794e-01f, 1.15270555e-01f, -4.60860634e+00f, 7.48794413e+00f),
    GLINT_FLOAT4(-4.50308084e+00f, 7.21690464e+00f, -4.39524031e+00f, 6.94508314e+00f), GLINT_FLOAT4(-4.28493023e+00f, 6.67241764e+00f, -4.17197895e+00f, 6.39883995e+00f),
    GLINT_FLOAT4(-4.05619574e+00f, 6.12427473e+00f, -3.93736768e+00f, 5.84864092e+00f), GLINT_FLOAT4(-3.81525540e+00f, 5.57185030e+00f, -3.68959165e+00f, 5.29381227e+00f),
    GLINT_FLOAT4(-3.56007743e+00f, 5.01443768e+00f, -3.42638087e+00f, 4.73364878e+00f), GLINT_FLOAT4(-3.28813744e+00f, 4.45139599e+00f, -3.14495778e+00f, 4.16769075e+00f),
    GLINT_FLOAT4(-2.99644375e+00f, 3.88265467e+00f, -2.84222412e+00f, 3.59660339e+00f), GLINT_FLOAT4(-2.68202209e+00f, 3.31017661e+00f, -2.51576805e+00f, 3.02452135e+00f),
    GLINT_FLOAT4(-2.34377098e+00f, 2.74152327e+00f, -2.16693711e+00f, 2.46401739e+00f), GLINT_FLOAT4(-1.98696268e+00f, 2.19583917e+00f, -1.80636060e+00f, 1.94150233e+00f),
    GLINT_FLOAT4(-1.62816882e+00f, 1.70541334e+00f, -1.45535970e+00f, 1.49086368e+00f), GLINT_FLOAT4(-1.29022014e+00f, 1.29932761e+00f, -1.13402283e+00f, 1.13042533e+00f),
    GLINT_FLOAT4(-9.87073720e-01f, 9.82431114e-01f, -8.48985016e-01f, 8.52936745e-01f), GLINT_FLOAT4(-7.18978167e-01f, 7.39380002e-01f, -5.96115649e-01f, 6.39355659e-01f),
    GLINT_FLOAT4(-4.79442567e-01f, 5.50751388e-01f, -3.68059337e-01f, 4.71779019e-01f), GLINT_FLOAT4(-2.61151105e-01f, 4.00953889e-01f, -1.57992899e-01f, 3.37054521e-01f),
    GLINT_FLOAT4(-5.79430722e-02f, 2.79078722e-01f, 3.95678580e-02f, 2.26203725e-01f), GLINT_FLOAT4(1.35046542e-01f, 1.77758843e-01f, 2.28953943e-01f, 1.33189201e-01f),
    GLINT_FLOAT4(3.21714222e-01f, 9.20397565e-02f, 4.13726240e-01f, 5.39376475e-02f), GLINT_FLOAT4(5.05374789e-01f, 1.85787585e-02f, 5.97041368e-01f, -1.42817963e-02f),
    GLINT_FLOAT4(-4.58539724e+00f, 7.37576246e+00f, -4.47939777e+00f, 7.10478401e+00f), GLINT_FLOAT4(-4.37105322e+00f, 6.83302689e+00f, -4.26020622e+00f, 6.56043053e+00f),
    GLINT_FLOAT4(-4.14668179e+00f, 6.28692675e+00f, -4.03028488e+00f, 6.01244068e+00f), GLINT_FLOAT4(-3.91079664e+00f, 5.73689127e+00f, -3.78797293e+00f, 5.46019220e+00f),
    GLINT_FLOAT4(-3.66153884e+00f, 5.18225193e+00f, -3.53118706e+00f, 4.90298223e+00f), GLINT_FLOAT4(-3.39657617e+00f, 4.62230539e+00f, -3.25732946e+00f, 4.34017181e+00f),
    GLINT_FLOAT4(-3.11304331e+00f, 4.05659103e+00f, -2.96330190e+00f, 3.77168202e+00f), GLINT_FLOAT4(-2.80771399e+00f, 3.48575640e+00f, -2.64597845e+00f, 3.19944644e+00f),
    GLINT_FLOAT4(-2.47799921e+00f, 2.91389108e+00f, -2.30405855e+00f, 2.63096523e+00f), GLINT_FLOAT4(-2.12504029e+00f, 2.35349822e+00f, -1.94262934e+00f, 2.08532906e+00f),
    GLINT_FLOAT4(-1.75934720e+00f, 1.83099198e+00f, -1.57826364e+00f, 1.59493375e+00f), GLINT_FLOAT4(-1.40240097e+00f, 1.38049686e+00f, -1.23410165e+00f, 1.18920147e+00f),
    GLINT_FLOAT4(-1.07468534e+00f, 1.02069473e+00f, -9.24489856e-01f, 8.73253524e-01f), GLINT_FLOAT4(-7.83141911e-01f, 7.44452536e-01f, -6.49864852e-01f, 6.31700099e-01f),
    GLINT_FLOAT4(-5.23714840e-01f, 5.32556534e-01f, -4.03726488e-01f, 4.44875270e-01f), GLINT_FLOAT4(-2.88988441e-01f, 3.66836637e-01f, -1.78674147e-01f, 2.96928108e-01f),
    GLINT_FLOAT4(-7.20480084e-02f, 2.33904049e-01f, 3.15407552e-02f, 1.76741615e-01f), GLINT_FLOAT4(1.32666111e-01f, 1.24605440e-01f, 2.31841281e-01f, 7.68076628e-02f),
    GLINT_FLOAT4(3.29529077e-01f, 3.27836610e-02f, 4.26153868e-01f, -7.93022942e-03f), GLINT_FLOAT4(5.22112966e-01f, -4.57144231e-02f, 6.17787361e-01f, -8.08791518e-02f),
    GLINT_FLOAT4(7.13552296e-01f, -1.13674104e-01f, -4.56252146e+00f, 7.28468895e+00f), GLINT_FLOAT4(-4.45605278e+00f, 7.01376343e+00f, -4.34720898e+00f, 6.74206305e+00f),
    GLINT_FLOAT4(-4.23583031e+00f, 6.46952677e+00f, -4.12173796e+00f, 6.19608688e+00f), GLINT_FLOAT4(-4.00473213e+00f, 5.92166901e+00f, -3.88458920e+00f, 5.64619350e+00f),
    GLINT_FLOAT4(-3.76105881e+00f, 5.36957264e+00f, -3.63385963e+00f, 5.09171724e+00f), GLINT_FLOAT4(-3.50267577e+00f, 4.81253815e+00f, -3.36715531e+00f, 4.53195810e+00f),
    GLINT_FLOAT4(-3.22691035e+00f, 4.24992847e+00f, -3.08152199e+00f, 3.96645737e+00f), GLINT_FLOAT4(-2.93055701e+00f, 3.68166280e+00f, -2.77360344e+00f, 3.39585423e+00f),
    GLINT_FLOAT4(-2.61033583e+00f, 3.10966063e+00f, -2.44063044e+00f, 2.82421541e+00f), GLINT_FLOAT4(-2.26474190e+00f, 2.54138947e+00f, -2.08352900e+00f, 2.26400995e+00f),
    GLINT_FLOAT4(-1.89866388e+00f, 1.99592292e+00f, -1.71267343e+00f, 1.74168479e+00f), GLINT_FLOAT4(-1.52865624e+00f, 1.50578165e+00f, -1.34968340e+00f, 1.29160619e+00f),
    GLINT_FLOAT4(-1.17815316e+00f, 1.10072482e+00f, -1.01543343e+00f, 9.32812214e-01f), GLINT_FLOAT4(-8.61893117e-01f, 7.86148012e-01f, -7.17172623e-01f, 6.58287585e-01f),
    GLINT_FLOAT4(-5.80494106e-01f, 5.46605766e-01f, -4.50902671e-01f, 4.48622733e-01f), GLINT_FLOAT4(-3.27417135e-01f, 3.62150997e-01f, -2.09108219e-01f, 2.85332233e-01f),
    GLINT_FLOAT4(-9.51317325e-02f, 2.16619328e-01f, 1.52645269e-02f, 1.54736012e-01f), GLINT_FLOAT4(1.22743480e-01f, 9.86367539e-02f, 2.27891475e-01f, 4.74630259e-02f),
    GLINT_FLOAT4(3.31229866e-01f, 5.10038459e-04f, 4.33227003e-01f, -4.28009555e-02f), GLINT_FLOAT4(5.34310460e-01f, -8.29457119e-02f, 6.34878039e-01f, -1.20314509e-01f),
    GLINT_FLOAT4(7.35308349e-01f, -1.55225515e-01f, 8.35971057e-01f, -1.87934741e-01f), GLINT_FLOAT4(-4.54003382e+00f, 7.20971203e+00f, -4.43309975e+00f, 6.93882465e+00f),
    GLINT_FLOAT4(-4.32376194e+00f, 6.66716528e+00f, -4.21185589e+00f, 6.39467192e+00f), GLINT_FLOAT4(-4.09719944e+00f, 6.12127733e+00f, -3.97958899e+00f, 5.84690809e+00f),
    GLINT_FLOAT4(-3.85879564e+00f, 5.57148361e+00f, -3.73456287e+00f, 5.29491711e+00f), GLINT_FLOAT4(-3.60660219e+00f, 5.01711941e+00f, -3.47458935e+00f, 4.73800135e+00f),
    GLINT_FLOAT4(-3.33816195e+00f, 4.45748711e+00f, -3.19692016e+00f, 4.17552614e+00f), GLINT_FLOAT4(-3.05043006e+00f, 3.89212847e+00f, -2.89824080e+00f, 3.60741138e+00f),
    GLINT_FLOAT4(-2.73991895e+00f, 3.32168388e+00f, -2.57511401e+00f, 3.03557539e+00f), GLINT_FLOAT4(-2.40367484e+00f, 2.75022030e+00f, -2.22582746e+00f, 2.46749163e+00f),
    GLINT_FLOAT4(-2.04240584e+00f, 2.19022393e+00f, -1.85506773e+00f, 1.92227829e+00f), GLINT_FLOAT4(-1.66634476e+00f, 1.66823947e+00f, -1.47936416e+00f, 1.43263423e+00f),
    GLINT_FLOAT4(-1.29724598e+00f, 1.21890283e+00f, -1.12244439e+00f, 1.02865326e+00f), GLINT_FLOAT4(-9.56376374e-01f, 8.61582756e-01f, -7.99442649e-01f, 7.15969443e-01f),
    GLINT_FLOAT4(-6.51295364e-01f, 5.89345038e-01f, -5.11151731e-01f, 4.79045510e-01f), GLINT_FLOAT4(-3.78040612e-01f, 3.82544994e-01f, -2.50957787e-01f, 2.97608346e-01f),
    GLINT_FLOAT4(-1.28948271e-01f, 2.22331941e-01f, -1.11415796e-02f, 1.55126870e-01f), GLINT_FLOAT4(1.03237629e-01f, 9.46823806e-02f, 2.14874074e-01f, 3.99216227e-02f),
    GLINT_FLOAT4(3.24372530e-01f, -1.00400774e-02f, 4.32268977e-01f, -5.59288412e-02f), GLINT_FLOAT4(5.39043486e-01f, -9.83416885e-02f, 6.45131767e-01f, -1.37769490e-01f),
    GLINT_FLOAT4(7.50936568e-01f, -1.74614921e-01f, 8.56837809e-01f, -2.09206223e-01f), GLINT_FLOAT4(9.63202894e-01f, -2.41807416e-01f, -4.51784182e+00f, 7.14630890e+00f),
    GLINT_FLOAT4(-4.41044378e+00f, 6.87543869e+00f, -4.30061197e+00f, 6.60379601e+00f), GLINT_FLOAT4(-4.18817902e+00f, 6.33131933e+00f, -4.07295847e+00f, 6.05794239e+00f),
    GLINT_FLOAT4(-3.95474219e+00f, 5.78359032e+00f, -3.83329654e+00f, 5.50818300e+00f), GLINT_FLOAT4(-3.70835876e+00f, 5.23163319e+00f, -3.57963276e+00f, 4.95385218e+00f),
    GLINT_FLOAT4(-3.44678545e+00f, 4.67475033e+00f, -3.30944443e+00f, 4.39425039e+00f), GLINT_FLOAT4(-3.16719651e+00f, 4.11230421e+00f, -3.01959252e+00f, 3.82891989e+00f),
    GLINT_FLOAT4(-2.86616349e+00f, 3.54421616e+00f, -2.70645332e+00f, 3.25850415e+00f), GLINT_FLOAT4(-2.54008675e+00f, 2.97241640e+00f, -2.36688399e+00f, 2.68709421e+00f),
    GLINT_FLOAT4(-2.18704224e+00f, 2.40442228e+00f, -2.00137115e+00f, 2.12725544e+00f), GLINT_FLOAT4(-1.81151521e+00f, 1.85948443e+00f, -1.62001312e+00f, 1.60573494e+00f),
    GLINT_FLOAT4(-1.43002331e+00f, 1.37058163e+00f, -1.24471688e+00f, 1.15751052e+00f), GLINT_FLOAT4(-1.06660652e+00f, 9.68162179e-01f, -8.97159517e-01f, 8.02244484e-01f),
    GLINT_FLOAT4(-7.36807883e-01f, 6.58021629e-01f, -5.85213959e-01f, 5.32991529e-01f), GLINT_FLOAT4(-4.41586316e-01f, 4.24443007e-01f, -3.04931700e-01f, 3.29796672e-01f),
    GLINT_FLOAT4(-1.74215198e-01f, 2.46763065e-01f, -4.84469794e-02f, 1.73386514e-01f), GLINT_FLOAT4(7.32788369e-02f, 1.08031459e-01f, 1.91771045e-01f, 4.93468232e-02f),
    GLINT_FLOAT4(3.07746381e-01f, -3.78061389e-03f, 4.21837121e-01f, -5.22651151e-02f), GLINT_FLOAT4(5.34603477e-01f, -9.68583450e-02f, 6.46545708e-01f, -1.38178721e-01f),
    GLINT_FLOAT4(7.58115947e-01f, -1.76734895e-01f, 8.69729042e-01f, -2.12944239e-01f), GLINT_FLOAT4(9.81773496e-01f, -2.47147053e-01f, 1.09462118e+00f, -2.79616982e-01f),
    GLINT_FLOAT4(-4.49576473e+00f, 7.09054327e+00f, -4.38789797e+00f, 6.81966019e+00f), GLINT_FLOAT4(-4.27756643e+00f, 6.54800224e+00f, -4.16459942e+00f, 6.27550840e+00f),
    GLINT_FLOAT4(-4.04880714e+00f, 6.00211048e+00f, -3.92997670e+00f, 5.72773409e+00f), GLINT_FLOAT4(-3.80786848e+00f, 5.45229864e+00f, -3.68221307e+00f, 5.17571592e+00f),
    GLINT_FLOAT4(-3.55270696e+00f, 4.89789581e+00f, -3.41900802e+00f, 4.61874866e+00f), GLINT_FLOAT4(-3.28073215e+00f, 4.33819675e+00f, -3.13745284e+00f, 4.05619001e+00f),
    GLINT_FLOAT4(-2.98870492e+00f, 3.77273726e+00f, -2.83399963e+00f, 3.48795867e+00f), GLINT_FLOAT4(-2.67285776e+00f, 3.20216775e+00f, -2.50487709e+00f, 2.91600418e+00f),
    GLINT_FLOAT4(-2.32984877e+00f, 2.63062239e+00f, -2.14794064e+00f, 2.34792948e+00f), GLINT_FLOAT4(-1.95993876e+00f, 2.07081580e+00f, -1.76747763e+00f, 1.80322218e+00f),
    GLINT_FLOAT4(-1.57310760e+00f, 1.54983521e+00f, -1.38002455e+00f, 1.31529188e+00f), GLINT_FLOAT4(-1.19145691e+00f, 1.10312641e+00f, -1.00998020e+00f, 9.15000856e-01f),
    GLINT_FLOAT4(-8.37113321e-01f, 7.50614405e-01f, -6.73319638e-01f, 6.08196497e-01f), GLINT_FLOAT4(-5.18268764e-01f, 4.85192478e-01f, -3.71156693e-01f, 3.78829628e-01f),
    GLINT_FLOAT4(-2.30961949e-01f, 2.86464542e-01f, -9.66115966e-02f, 2.05745384e-01f), GLINT_FLOAT4(3.29281129e-02f, 1.34658471e-01f, 1.58607140e-01f, 7.15183318e-02f),
    GLINT_FLOAT4(2.81279922e-01f, 1.49277914e-02f, 4.01705027e-01f, -3.62642072e-02f), GLINT_FLOAT4(5.20553946e-01f, -8.30046013e-02f, 6.38422251e-01f, -1.26072600e-01f),
    GLINT_FLOAT4(7.55841434e-01f, -1.66109636e-01f, 8.73290896e-01f, -2.03643620e-01f), GLINT_FLOAT4(9.91208851e-01f, -2.39107937e-01f, 1.11000323e+00f, -2.72856086e-01f),
    GLINT_FLOAT4(1.23006165e+00f, -3.05172443e-01f, -4.47358942e+00f, 7.03914595e+00f), GLINT_FLOAT4(-4.36524248e+00f, 6.76821423e+00f, -4.25439882e+00f, 6.49650288e+00f),
    GLINT_FLOAT4(-4.14088440e+00f, 6.22394943e+00f, -4.02450514e+00f, 5.95048571e+00f), GLINT_FLOAT4(-3.90504241e+00f, 5.67603588e+00f, -3.78225136e+00f, 5.40051746e+00f),
    GLINT_FLOAT4(-3.65585566e+00f, 5.12384224e+00f, -3.52554297e+00f, 4.84591722e+00f), GLINT_FLOAT4(-3.39096165e+00f, 4.56665230e+00f, -3.25171542e+00f, 4.28596783e+00f),
    GLINT_FLOAT4(-3.10736299e+00f, 4.00381231e+00f, -2.95742178e+00f, 3.72019410e+00f), GLINT_FLOAT4(-2.80138206e+00f, 3.43523407e+00f, -2.63873935e+00f, 3.14925075e+00f),
    GLINT_FLOAT4(-2.46906328e+00f, 2.86289358e+00f, -2.29211354e+00f, 2.57733607e+00f), GLINT_FLOAT4(-2.10802841e+00f, 2.29451966e+00f, -1.91757095e+00f, 2.01738667e+00f),
    GLINT_FLOAT4(-1.72236931e+00f, 1.74995184e+00f, -1.52499270e+00f, 1.49698806e+00f), GLINT_FLOAT4(-1.32868397e+00f, 1.26321507e+00f, -1.13673878e+00f, 1.05222189e+00f),
    GLINT_FLOAT4(-9.51801777e-01f, 8.65682423e-01f, -7.75446773e-01f, 7.03263283e-01f), GLINT_FLOAT4(-6.08166635e-01f, 5.63130319e-01f, -4.49635088e-01f, 4.42649722e-01f),
    GLINT_FLOAT4(-2.99030066e-01f, 3.38966072e-01f, -1.55296177e-01f, 2.49356836e-01f), GLINT_FLOAT4(-1.73152462e-02f, 1.71397716e-01f, 1.15996867e-01f, 1.03012137e-01f),
    GLINT_FLOAT4(2.45644256e-01f, 4.24593017e-02f, 3.72535259e-01f, -1.17044812e-02f), GLINT_FLOAT4(4.97481078e-01f, -6.06693327e-02f, 6.21203303e-01f, -1.05414815e-01f),
    GLINT_FLOAT4(7.44344413e-01f, -1.46747053e-01f, 8.67479444e-01f, -1.85329705e-01f), GLINT_FLOAT4(9.91128087e-01f, -2.21709117e-01f, 1.11576593e+00f, -2.56333977e-01f),
    GLINT_FLOAT4(1.24183571e+00f, -2.89570689e-01f, 1.36975753e+00f, -3.21714461e-01f), GLINT_FLOAT4(-4.45112276e+00f, 6.98959160e+00f, -4.34227991e+00f, 6.71857405e+00f),
    GLINT_FLOAT4(-4.23090649e+00f, 6.44676828e+00f, -4.11682463e+00f, 6.17411137e+00f), GLINT_FLOAT4(-3.99983597e+00f, 5.90053415e+00f, -3.87971616e+00f, 5.62595797e+00f),
    GLINT_FLOAT4(-3.75621438e+00f, 5.35030031e+00f, -3.62904644e+00f, 5.07346916e+00f), GLINT_FLOAT4(-3.49789143e+00f, 4.79537106e+00f, -3.36238623e+00f, 4.51591301e+00f),
    GLINT_FLOAT4(-3.22212195e+00f, 4.23501205e+00f, -3.07664132e+00f, 3.95261598e+00f), GLINT_FLOAT4(-2.92544246e+00f, 3.66873193e+00f, -2.76799273e+00f, 3.38348198e+00f),
    GLINT_FLOAT4(-2.60376096e+00f, 3.09719038e+00f, -2.43228507e+00f, 2.81051993e+00f), GLINT_FLOAT4(-2.25329232e+00f, 2.52466989e+00f, -2.06688952e+00f, 2.24162722e+00f),
    GLINT_FLOAT4(-1.87381768e+00f, 1.96440470e+00f, -1.67570210e+00f, 1.69711316e+00f), GLINT_FLOAT4(-1.47513878e+00f, 1.44463933e+00f, -1.27542865e+00f, 1.21180665e+00f),
    GLINT_FLOAT4(-1.07994556e+00f, 1.00226831e+00f, -8.91412735e-01f, 8.17700148e-01f), GLINT_FLOAT4(-7.11461782e-01f, 6.57712460e-01f, -5.40614009e-01f, 5.20375609e-01f),
    GLINT_FLOAT4(-3.78542304e-01f, 4.02945459e-01f, -2.24401072e-01f, 3.02458584e-01f), GLINT_FLOAT4(-7.70947933e-02f, 2.16094792e-01f, 6.45453855e-02f, 1.41345710e-01f),
    GLINT_FLOAT4(2.01659471e-01f, 7.60655627e-02f, 3.35311949e-01f, 1.84549205e-02f), GLINT_FLOAT4(4.66471553e-01f, -3.29765528e-02f, 5.96009851e-01f, -7.94567689e-02f),
    GLINT_FLOAT4(7.24707067e-01f, -1.21995114e-01f, 8.53262544e-01f, -1.61421090e-01f), GLINT_FLOAT4(9.82306480e-01f, -1.98416740e-01f, 1.11241221e+00f, -2.33542949e-01f),
    GLINT_FLOAT4(1.24410868e+00f, -2.67260432e-01f, 1.37789202e+00f, -2.99945891e-01f), GLINT_FLOAT4(1.51423764e+00f, -3.31903875e-01f, -4.42823744e+00f, 6.94015121e+00f),
    GLINT_FLOAT4(-4.31887913e+00f, 6.66901255e+00f, -4.20695496e+00f, 6.39707565e+00f), GLINT_FLOAT4(-4.09228230e+00f, 6.12427521e+00f, -3.97465825e+00f, 5.85053968e+00f),
    GLINT_FLOAT4(-3.85385299e+00f, 5.57579041e+00f, -3.72960806e+00f, 5.29994106e+00f), GLINT_FLOAT4(-3.60163188e+00f, 5.02289867e+00f, -3.46959329e+00f, 4.74456596e+00f),
    GLINT_FLOAT4(-3.33311749e+00f, 4.46484661e+00f, -3.19178152e+00f, 4.18365622e+00f), GLINT_FLOAT4(-3.04511094e+00f, 3.90093946e+00f, -2.89258313e+00f, 3.61670280e+00f),
    GLINT_FLOAT4(-2.73364019e+00f, 3.33107042e+00f, -2.56772161e+00f, 3.04437351e+00f), GLINT_FLOAT4(-2.39433217e+00f, 2.75729251e+00f, -2.21316385e+00f, 2.47105980e+00f),
    GLINT_FLOAT4(-2.02429008e+00f, 2.18771791e+00f, -1.82843006e+00f, 1.91036701e+00f), GLINT_FLOAT4(-1.62720978e+00f, 1.64323628e+00f, -1.42325854e+00f, 1.39134836e+00f),
    GLINT_FLOAT4(-1.21994555e+00f, 1.15964937e+00f, -1.02073419e+00f, 9.51861918e-01f), GLINT_FLOAT4(-8.28434050e-01f, 7.69654036e-01f, -6.44738019e-01f, 6.12555444e-01f),
    GLINT_FLOAT4(-4.70193893e-01f, 4.78510499e-01f, -3.04469228e-01f, 3.64634335e-01f), GLINT_FLOAT4(-1.46688789e-01f, 2.67830223e-01f, 4.28835675e-03f, 1.85161918e-01f),
    GLINT_FLOAT4(1.49684474e-01f, 1.14026994e-01f, 2.90699393e-01f, 5.22029921e-02f), GLINT_FLOAT4(4.28459287e-01f, -2.16880627e-03f, 5.63996136e-01f, -5.06247841e-02f),
    GLINT_FLOAT4(6.98244929e-01f, -9.44273770e-02f, 8.32049072e-01f, -1.34610921e-01f), GLINT_FLOAT4(9.66171026e-01f, -1.72022223e-01f, 1.10130465e+00f, -2.07354918e-01f),
    GLINT_FLOAT4(1.23808908e+00f, -2.41177708e-01f, 1.37712193e+00f, -2.73957044e-01f), GLINT_FLOAT4(1.51897442e+00f, -3.06074888e-01f, 1.66420376e+00f, -3.37842017e-01f),
    GLINT_FLOAT4(-4.40489101e+00f, 6.88986158e+00f, -4.29499769e+00f, 6.61857557e+00f), GLINT_FLOAT4(-4.18250132e+00f, 6.34647799e+00f, -4.06721497e+00f, 6.07350254e+00f),
    GLINT_FLOAT4(-3.94892979e+00f, 5.79957628e+00f, -3.82741022e+00f, 5.52461767e+00f), GLINT_FLOAT4(-3.70239043e+00f, 5.24853802e+00f, -3.57356977e+00f, 4.97124100e+00f),
    GLINT_FLOAT4(-3.44060707e+00f, 4.69262743e+00f, -3.30311513e+00f, 4.41259813e+00f), GLINT_FLOAT4(-3.16065502e+00f, 4.13106441e+00f, -3.01273394e+00f, 3.84796929e+00f),
    GLINT_FLOAT4(-2.85880733e+00f, 3.56331897e+00f, -2.69828987e+00f, 3.27724028e+00f), GLINT_FLOAT4(-2.53058982e+00f, 2.99007487e+00f, -2.35517597e+00f, 2.70252371e+00f),
    GLINT_FLOAT4(-2.17170262e+00f, 2.41585922e+00f, -1.98020864e+00f, 2.13219094e+00f), GLINT_FLOAT4(-1.78139091e+00f, 1.85472119e+00f, -1.57687807e+00f, 1.58781600e+00f),
    GLINT_FLOAT4(-1.36933839e+00f, 1.33665276e+00f, -1.16221750e+00f, 1.10631263e+00f), GLINT_FLOAT4(-9.59076822e-01f, 9.00588393e-01f, -7.62818396e-01f, 7.21126258e-01f),
    GLINT_FLOAT4(-5.75197399e-01f, 5.67350268e-01f, -3.96785051e-01f, 4.37048882e-01f), GLINT_FLOAT4(-2.27237433e-01f, 3.27168614e-01f, -6.56436756e-02f, 2.34456688e-01f),
    GLINT_FLOAT4(8.91864821e-02f, 1.55846447e-01f, 2.38530159e-01f, 8.86332989e-02f), GLINT_FLOAT4(3.83645505e-01f, 3.05160694e-02f, 5.25717556e-01f, -2.04219241e-02f),
    GLINT_FLOAT4(6.65838182e-01f, -6.57591447e-02f, 8.05002749e-01f, -1.06786832e-01f), GLINT_FLOAT4(9.44116533e-01f, -1.44557282e-01f, 1.08400619e+00f, -1.79926604e-01f),
    GLINT_FLOAT4(1.22543335e+00f, -2.13591233e-01f, 1.36911118e+00f, -2.46118695e-01f), GLINT_FLOAT4(1.51572084e+00f, -2.77972847e-01f, 1.66592932e+00f, -3.09534043e-01f),
    GLINT_FLOAT4(1.82040560e+00f, -3.41114551e-01f, -4.38112164e+00f, 6.83838177e+00f), GLINT_FLOAT4(-4.27067661e+00f, 6.56693029e+00f, -4.15758896e+00f, 6.29465389e+00f),
    GLINT_FLOAT4(-4.04166794e+00f, 6.02148390e+00f, -3.92269850e+00f, 5.74734497e+00f), GLINT_FLOAT4(-3.80043888e+00f, 5.47215366e+00f, -3.67461562e+00f, 5.19581890e+00f),
    GLINT_FLOAT4(-3.54491878e+00f, 4.91824150e+00f, -3.41099572e+00f, 4.63931894e+00f), GLINT_FLOAT4(-3.27244616e+00f, 4.35894823e+00f, -3.12881470e+00f, 4.07703876e+00f),
    GLINT_FLOAT4(-2.97958922e+00f, 3.79353070e+00f, -2.82420063e+00f, 3.50843120e+00f), GLINT_FLOAT4(-2.66203547e+00f, 3.22187114e+00f, -2.49246788e+00f, 2.93420434e+00f),
    GLINT_FLOAT4(-2.31492925e+00f, 2.64615750e+00f, -2.12903285e+00f, 2.35904956e+00f), GLINT_FLOAT4(-1.93478155e+00f, 2.07506776e+00f, -1.73284936e+00f, 1.79752994e+00f),
    GLINT_FLOAT4(-1.52486920e+00f, 1.53095639e+00f, -1.31355286e+00f, 1.28069496e+00f), GLINT_FLOAT4(-1.10242927e+00f, 1.05197036e+00f, -8.95164132e-01f, 8.48640680e-01f),
    GLINT_FLOAT4(-6.94754601e-01f, 6.72311544e-01f, -5.03016531e-01f, 5.22272527e-01f), GLINT_FLOAT4(-3.20537835e-01f, 3.96124631e-01f, -1.46954685e-01f, 2.90617794e-01f),
    GLINT_FLOAT4(1.86875742e-02f, 2.02322513e-01f, 1.77631766e-01f, 1.28031209e-01f), GLINT_FLOAT4(3.31210881e-01f, 6.49320185e-02f, 4.80735809e-01f, 1.06486762e-02f),
    GLINT_FLOAT4(6.27442122e-01f, -3.67866643e-02f, 7.72470772e-01f, -7.89850056e-02f), GLINT_FLOAT4(9.16867197e-01f, -1.17255993e-01f, 1.06158984e+00f, -1.52659386e-01f),
    GLINT_FLOAT4(1.20752370e+00f, -1.86050147e-01f, 1.35549748e+00f, -2.18117341e-01f), GLINT_FLOAT4(1.50630295e+00f, -2.49417499e-01f, 1.66071606e+00f, -2.80402899e-01f),
    GLINT_FLOAT4(1.81951952e+00f, -3.11444819e-01f, 1.98352492e+00f, -3.42851818e-01f), GLINT_FLOAT4(-4.35701895e+00f, 6.78576279e+00f, -4.24600744e+00f, 6.51413679e+00f),
    GLINT_FLOAT4(-4.13231373e+00f, 6.24167061e+00f, -4.01574039e+00f, 5.96829462e+00f), GLINT_FLOAT4(-3.89606762e+00f, 5.69393158e+00f, -3.77304649e+00f, 5.41849470e+00f),
    GLINT_FLOAT4(-3.64639568e+00f, 5.14189053e+00f, -3.51579523e+00f, 4.86401749e+00f), GLINT_FLOAT4(-3.38088131e+00f, 4.58476925e+00f, -3.24123859e+00f, 4.30403996e+00f),
    GLINT_FLOAT4(-3.09639549e+00f, 4.02173567e+00f, -2.94581819e+00f, 3.73779607e+00f), GLINT_FLOAT4(-2.78891253e+00f, 3.45222831e+00f, -2.62503481e+00f, 3.16516948e+00f),
    GLINT_FLOAT4(-2.45352364e+00f, 2.87698817e+00f, -2.27376938e+00f, 2.58844113e+00f), GLINT_FLOAT4(-2.08534312e+00f, 2.30090046e+00f, -1.88820982e+00f, 2.01664162e+00f),
    GLINT_FLOAT4(-1.68301952e+00f, 1.73911285e+00f, -1.47141159e+00f, 1.47300482e+00f), GLINT_FLOAT4(-1.25614572e+00f, 1.22385049e+00f, -1.04083955e+00f, 9.97024059e-01f),
    GLINT_FLOAT4(-8.29268038e-01f, 7.96439946e-01f, -6.24523878e-01f, 6.23638809e-01f), GLINT_FLOAT4(-4.28477764e-01f, 4.77741987e-01f, -2.41724670e-01f, 3.56128693e-01f),
    GLINT_FLOAT4(-6.38690293e-02f, 2.55323082e-01f, 1.06097035e-01f, 1.71699896e-01f), GLINT_FLOAT4(2.69474924e-01f, 1.01900242e-01f, 4.27652597e-01f, 4.30049226e-02f),
    GLINT_FLOAT4(5.81987202e-01f, -7.43102049e-03f, 7.33752191e-01f, -5.14142066e-02f), GLINT_FLOAT4(8.84121120e-01f, -9.05724615e-02f, 1.03417134e+00f, -1.26217201e-01f),
    GLINT_FLOAT4(1.18489802e+00f, -1.59399793e-01f, 1.33723235e+00f, -1.90960109e-01f), GLINT_FLOAT4(1.49206340e+00f, -2.21568078e-01f, 1.65026259e+00f, -2.51759529e-01f),
    GLINT_FLOAT4(1.81271017e+00f, -2.81967282e-01f, 1.98032284e+00f, -3.12547386e-01f), GLINT_FLOAT4(2.15408278e+00f, -3.43800664e-01f, -4.33269072e+00f, 6.73223305e+00f),
    GLINT_FLOAT4(-4.22110176e+00f, 6.46042681e+00f, -4.10678816e+00f, 6.18776512e+00f), GLINT_FLOAT4(-3.98954892e+00f, 5.91417694e+00f, -3.86915708e+00f, 5.63958168e+00f),
    GLINT_FLOAT4(-3.74535704e+00f, 5.36389160e+00f, -3.61785889e+00f, 5.08700991e+00f), GLINT_FLOAT4(-3.48633218e+00f, 4.80883217e+00f, -3.35040116e+00f, 4.52924776e+00f),
    GLINT_FLOAT4(-3.20963550e+00f, 4.24814892e+00f, -3.06354523e+00f, 3.96543908e+00f), GLINT_FLOAT4(-2.91157532e+00f, 3.68105578e+00f, -2.75310421e+00f, 3.39500856e+00f),
    GLINT_FLOAT4(-2.58745623e+00f, 3.10744190e+00f, -2.41393256e+00f, 2.81874204e+00f), GLINT_FLOAT4(-2.23188043e+00f, 2.52969980e+00f, -2.04082704e+00f, 2.24174905e+00f),
    GLINT_FLOAT4(-1.84069645e+00f, 1.95726371e+00f, -1.63211584e+00f, 1.67983770e+00f), GLINT_FLOAT4(-1.41673243e+00f, 1.41434884e+00f, -1.19735825e+00f, 1.16652942e+00f),
    GLINT_FLOAT4(-9.77705181e-01f, 9.41905856e-01f, -7.61660337e-01f, 7.44435549e-01f), GLINT_FLOAT4(-5.52409410e-01f, 5.75564325e-01f, -3.51869226e-01f, 4.34206843e-01f),
    GLINT_FLOAT4(-1.60628736e-01f, 3.17483187e-01f, 2.17533410e-02f, 2.21662477e-01f), GLINT_FLOAT4(1.96347296e-01f, 1.42907351e-01f, 3.64519209e-01f, 7.76995122e-02f),
    GLINT_FLOAT4(5.27710140e-01f, 2.30153240e-02f, 6.87315464e-01f, -2.36491673e-02f), GLINT_FLOAT4(8.44631791e-01f, -6.43234402e-02f, 1.00084555e+00f, -1.00632310e-01f),
    GLINT_FLOAT4(1.15704381e+00f, -1.33867398e-01f, 1.31423664e+00f, -1.65051088e-01f), GLINT_FLOAT4(1.47338426e+00f, -1.94990650e-01f, 1.63542652e+00f, -2.24323541e-01f),
    GLINT_FLOAT4(1.80131364e+00f, -2.53556013e-01f, 1.97203839e+00f, -2.83095986e-01f), GLINT_FLOAT4(2.14866924e+00f, -3.13281447e-01f, 2.33238435e+00f, -3.44403625e-01f),
    GLINT_FLOAT4(-4.30823946e+00f, 6.67806053e+00f, -4.19606352e+00f, 6.40607071e+00f), GLINT_FLOAT4(-4.08112097e+00f, 6.13320971e+00f, -3.96320462e+00f, 5.85940456e+00f),
    GLINT_FLOAT4(-3.84208131e+00f, 5.58457327e+00f, -3.71748781e+00f, 5.30862474e+00f), GLINT_FLOAT4(-3.58912539e+00f, 5.03145933e+00f, -3.45665383e+00f, 4.75296926e+00f),
    GLINT_FLOAT4(-3.31968331e+00f, 4.47304201e+00f, -3.17776871e+00f, 4.19156504e+00f), GLINT_FLOAT4(-3.03040123e+00f, 3.90844083e+00f, -2.87700200e+00f, 3.62360549e+00f),
    GLINT_FLOAT4(-2.71692228e+00f, 3.33707094e+00f, -2.54945230e+00f, 3.04899168e+00f), GLINT_FLOAT4(-2.37385345e+00f, 2.75977397e+00f, -2.18942857e+00f, 2.47024846e+00f),
    GLINT_FLOAT4(-1.99565768e+00f, 2.18191791e+00f, -1.79242408e+00f, 1.89726734e+00f), GLINT_FLOAT4(-1.58033097e+00f, 1.62005162e+00f, -1.36103606e+00f, 1.35535324e+00f),
    GLINT_FLOAT4(-1.13740826e+00f, 1.10911596e+00f, -9.13258433e-01f, 8.87019098e-01f), GLINT_FLOAT4(-6.92586780e-01f, 6.93044126e-01f, -4.78666544e-01f, 5.28506219e-01f),
    GLINT_FLOAT4(-2.73448318e-01f, 3.92070532e-01f, -7.74990022e-02f, 2.80558705e-01f), GLINT_FLOAT4(1.09682381e-01f, 1.89957723e-01f, 2.89238036e-01f, 1.16203547e-01f),
    GLINT_FLOAT4(4.62599933e-01f, 5.56173772e-02f, 6.31257236e-01f, 5.07825008e-03f), GLINT_FLOAT4(7.96631515e-01f, -3.79623361e-02f, 9.60025430e-01f, -7.55375698e-02f),
    GLINT_FLOAT4(1.12261736e+00f, -1.09247021e-01f, 1.28548157e+00f, -1.40339226e-01f), GLINT_FLOAT4(1.44962168e+00f, -1.69785410e-01f, 1.61601043e+00f, -1.98341683e-01f),
    GLINT_FLOAT4(1.78562939e+00f, -2.26600021e-01f, 1.95950818e+00f, -2.55029887e-01f), GLINT_FLOAT4(2.13876247e+00f, -2.84012437e-01f, 2.32463050e+00f, -3.13868433e-01f),
    GLINT_FLOAT4(2.51850796e+00f, -3.44881088e-01f, -4.28375483e+00f, 6.62349939e+00f), GLINT_FLOAT4(-4.17098618e+00f, 6.35132313e+00f, -4.05540657e+00f, 6.07825994e+00f),
    GLINT_FLOAT4(-3.93680382e+00f, 5.80423450e+00f, -3.81493855e+00f, 5.52916288e+00f), GLINT_FLOAT4(-3.68954015e+00f, 5.25295115e+00f, -3.56030011e+00f, 4.97549725e+00f),
    GLINT_FLOAT4(-3.42686725e+00f, 4.69669008e+00f, -3.28883862e+00f, 4.41641331e+00f), GLINT_FLOAT4(-3.14575291e+00f, 4.13455248e+00f, -2.99708128e+00f, 3.85100651e+00f),
    GLINT_FLOAT4(-2.84222102e+00f, 3.56571245e+00f, -2.68049407e+00f, 3.27868605e+00f), GLINT_FLOAT4(-2.51115489e+00f, 2.99009204e+00f, -2.33342385e+00f, 2.70036125e+00f),
    GLINT_FLOAT4(-2.14655685e+00f, 2.41036940e+00f, -1.94998550e+00f, 2.12169647e+00f), GLINT_FLOAT4(-1.74355054e+00f, 1.83695173e+00f, -1.52783191e+00f, 1.56006706e+00f),
    GLINT_FLOAT4(-1.30450058e+00f, 1.29634666e+00f, -1.07648647e+00f, 1.05195749e+00f), GLINT_FLOAT4(-8.47703397e-01f, 8.32727253e-01f, -6.22263134e-01f, 6.42637312e-01f),
    GLINT_FLOAT4(-4.03517187e-01f, 4.82830733e-01f, -1.93434000e-01f, 3.51675898e-01f), GLINT_FLOAT4(7.46036647e-03f, 2.45655641e-01f, 1.99739605e-01f, 1.60450995e-01f),
    GLINT_FLOAT4(3.84624630e-01f, 9.17614028e-02f, 5.63609421e-01f, 3.57528329e-02f), GLINT_FLOAT4(7.38218904e-01f, -1.07785035e-02f, 9.09882426e-01f, -5.04048616e-02f),
    GLINT_FLOAT4(1.07988715e+00f, -8.51394162e-02f, 1.24938142e+00f, -1.16532244e-01f), GLINT_FLOAT4(1.41940689e+00f, -1.45765856e-01f, 1.59094572e+00f, -1.73740432e-01f),
    GLINT_FLOAT4(1.76497304e+00f, -2.01145485e-01f, 1.94251037e+00f, -2.28517845e-01f), GLINT_FLOAT4(2.12467313e+00f, -2.56286681e-01f, 2.31271434e+00f, -2.84807831e-01f),
    GLINT_FLOAT4(2.50805950e+00f, -3.14389259e-01f, 2.71234012e+00f, -3.45310181e-01f), GLINT_FLOAT4(-4.25931215e+00f, 6.56877184e+00f, -4.14594507e+00f, 6.29640722e+00f),
    GLINT_FLOAT4(-4.02972269e+00f, 6.02313948e+00f, -3.91042733e+00f, 5.74889135e+00f), GLINT_FLOAT4(-3.78781223e+00f, 5.47357607e+00f, -3.66159916e+00f, 5.19709826e+00f),
    GLINT_FLOAT4(-3.53147054e+00f, 4.91935158e+00f, -3.39706302e+00f, 4.64022207e+00f), GLINT_FLOAT4(-3.25796032e+00f, 4.35959101e+00f, -3.11368418e+00f, 4.07734060e+00f),
    GLINT_FLOAT4(-2.96368504e+00f, 3.79336810e+00f, -2.80733538e+00f, 3.50761056e+00f), GLINT_FLOAT4(-2.64392614e+00f, 3.22008872e+00f, -2.47267532e+00f, 2.93098116e+00f),
    GLINT_FLOAT4(-2.29275966e+00f, 2.64074564e+00f, -2.10338688e+00f, 2.35030890e+00f), GLINT_FLOAT4(-1.90393794e+00f, 2.06133890e+00f, -1.69421053e+00f, 1.77658045e+00f),
    GLINT_FLOAT4(-1.47476220e+00f, 1.50016069e+00f, -1.24727964e+00f, 1.23762167e+00f), GLINT_FLOAT4(-1.01475859e+00f, 9.95362759e-01f, -7.81217396e-01f, 7.79352129e-01f),
    GLINT_FLOAT4(-5.50875664e-01f, 5.93540072e-01f, -3.27149808e-01f, 4.38849807e-01f), GLINT_FLOAT4(-1.12005986e-01f, 3.13302517e-01f, 9.40903798e-02f, 2.13002682e-01f),
    GLINT_FLOAT4(2.91798294e-01f, 1.33304447e-01f, 4.82418239e-01f, 6.96686953e-02f), GLINT_FLOAT4(6.67495191e-01f, 1.81184448e-02f, 8.48569155e-01f, -2.46101376e-02f),
    GLINT_FLOAT4(1.02705073e+00f, -6.10851906e-02f, 1.20418465e+00f, -9.32711661e-02f), GLINT_FLOAT4(1.38106692e+00f, -1.22642606e-01f, 1.55869198e+00f, -1.50294960e-01f),
    GLINT_FLOAT4(1.73801422e+00f, -1.77042380e-01f, 1.92001486e+00f, -2.03499079e-01f), GLINT_FLOAT4(2.10576558e+00f, -2.30143502e-01f, 2.29648328e+00f, -2.57365912e-01f),
    GLINT_FLOAT4(2.49357510e+00f, -2.85501271e-01f, 2.69867063e+00f, -3.14850450e-01f), GLINT_FLOAT4(2.91364765e+00f, -3.45693260e-01f, -4.23497343e+00f, 6.51406908e+00f),
    GLINT_FLOAT4(-4.12100458e+00f, 6.24151421e+00f, -4.00413561e+00f, 5.96803999e+00f), GLINT_FLOAT4(-3.88414168e+00f, 5.69356728e+00f, -3.76077080e+00f, 5.41800594e+00f),
    GLINT_FLOAT4(-3.63373542e+00f, 5.14125872e+00f, -3.50270867e+00f, 4.86321592e+00f), GLINT_FLOAT4(-3.36731553e+00f, 4.58376122e+00f, -3.22712541e+00f, 4.30277205e+00f),
    GLINT_FLOAT4(-3.08164215e+00f, 4.02012730e+00f, -2.93029499e+00f, 3.73572397e+00f), GLINT_FLOAT4(-2.77243042e+00f, 3.44949961e+00f, -2.60730767e+00f, 3.16148162e+00f),
    GLINT_FLOAT4(-2.43410635e+00f, 2.87186360e+00f, -2.25195813e+00f, 2.58113527e+00f), GLINT_FLOAT4(-2.06002021e+00f, 2.29028058e+00f, -1.85762227e+00f, 2.00106454e+00f),
    GLINT_FLOAT4(-1.64451790e+00f, 1.71638310e+00f, -1.42124343e+00f, 1.44057429e+00f), GLINT_FLOAT4(-1.18950474e+00f, 1.17943501e+00f, -9.52366531e-01f, 9.39603269e-01f),
    GLINT_FLOAT4(-7.13952661e-01f, 7.27174461e-01f, -4.78582740e-01f, 5.46030223e-01f), GLINT_FLOAT4(-2.49720365e-01f, 3.96820903e-01f, -2.93054562e-02f, 2.77166784e-01f),
    GLINT_FLOAT4(1.82276905e-01f, 1.82757527e-01f, 3.85780960e-01f, 1.08604133e-01f), GLINT_FLOAT4(5.82580268e-01f, 4.99351323e-02f, 7.74250567e-01f, 2.65189609e-03f),
    GLINT_FLOAT4(9.62316215e-01f, -3.65383290e-02f, 1.14813530e+00f, -7.01650903e-02f), GLINT_FLOAT4(1.33288014e+00f, -1.00111745e-01f, 1.51757383e+00f, -1.27751306e-01f),
    GLINT_FLOAT4(1.70315683e+00f, -1.54075027e-01f, 1.89056349e+00f, -1.79803103e-01f), GLINT_FLOAT4(2.08079958e+00f, -2.05474064e-01f, 2.27501130e+00f, -2.31512353e-01f),
    GLINT_FLOAT4(2.47454071e+00f, -2.58275449e-01f, 2.68096781e+00f, -2.86083251e-01f), GLINT_FLOAT4(2.89613390e+00f, -3.15233588e-01f, 3.12216115e+00f, -3.46009225e-01f),
    GLINT_FLOAT4(-4.21078920e+00f, 6.45955229e+00f, -4.09621620e+00f, 6.18680620e+00f), GLINT_FLOAT4(-3.97869658e+00f, 5.91312408e+00f, -3.85800099e+00f, 5.63842440e+00f),
    GLINT_FLOAT4(-3.73386931e+00f, 5.36261559e+00f, -3.60600615e+00f, 5.08559656e+00f), GLINT_FLOAT4(-3.47407413e+00f, 4.80725527e+00f, -3.33768606e+00f, 4.52747202e+00f),
    GLINT_FLOAT4(-3.19639659e+00f, 4.24612093e+00f, -3.04969192e+00f, 3.96307921e+00f), GLINT_FLOAT4(-2.89697909e+00f, 3.67824173e+00f, -2.73757696e+00f, 3.39154887e+00f),
    GLINT_FLOAT4(-2.57071209e+00f, 3.10303521e+00f, -2.39552450e+00f, 2.81291270e+00f), GLINT_FLOAT4(-2.21109915e+00f, 2.52170682e+00f, -2.01654124e+00f, 2.23046589e+00f),
    GLINT_FLOAT4(-1.81112778e+00f, 1.94106221e+00f, -1.59456789e+00f, 1.65655720e+00f), GLINT_FLOAT4(-1.36737835e+00f, 1.38151753e+00f, -1.13128722e+00f, 1.12201023e+00f),
    GLINT_FLOAT4(-8.89431536e-01f, 8.84915054e-01f, -6.46038711e-01f, 6.76435411e-01f), GLINT_FLOAT4(-4.05516684e-01f, 5.00340462e-01f, -1.71353802e-01f, 3.56948495e-01f),
    GLINT_FLOAT4(5.45631871e-02f, 2.43424490e-01f, 2.71948397e-01f, 1.55010402e-01f), GLINT_FLOAT4(4.81655180e-01f, 8.63657668e-02f, 6.85114563e-01f, 3.25018987e-02f),
    GLINT_FLOAT4(8.83901358e-01f, -1.07700508e-02f, 1.07948399e+00f, -4.67323922e-02f), GLINT_FLOAT4(1.27312887e+00f, -7.78365135e-02f, 1.46590626e+00f, -1.05851412e-01f),
    GLINT_FLOAT4(1.65875387e+00f, -1.32025927e-01f, 1.85256374e+00f, -1.57236770e-01f), GLINT_FLOAT4(2.04827356e+00f, -1.82110846e-01f, 2.24694777e+00f, -2.07118943e-01f),
    GLINT_FLOAT4(2.44984221e+00f, -2.32641995e-01f, 2.65845203e+00f, -2.59013414e-01f), GLINT_FLOAT4(2.87454009e+00f, -2.86542505e-01f, 3.10015535e+00f, -3.15524578e-01f),
    GLINT_FLOAT4(3.33764768e+00f, -3.46243590e-01f, -4.18679810e+00f, 6.40535498e+00f), GLINT_FLOAT4(-4.07161999e+00f, 6.13241720e+00f, -3.95344877e+00f, 5.85852623e+00f),
    GLINT_FLOAT4(-3.83204865e+00f, 5.58359861e+00f, -3.70715308e+00f, 5.30754042e+00f), GLINT_FLOAT4(-3.57845736e+00f, 5.03024769e+00f, -3.44561410e+00f, 4.75160599e+00f),
    GLINT_FLOAT4(-3.30822349e+00f, 4.47149134e+00f, -3.16582537e+00f, 4.18977642e+00f), GLINT_FLOAT4(-3.01788640e+00f, 3.90633464e+00f, -2.86379170e+00f, 3.62106133e+00f),
    GLINT_FLOAT4(-2.70283175e+00f, 3.33389926e+00f, -2.53419900e+00f, 3.04489231e+00f), GLINT_FLOAT4(-2.35699224e+00f, 2.75427365e+00f, -2.17024851e+00f, 2.46260858e+00f),
    GLINT_FLOAT4(-1.97301948e+00f, 2.17101765e+00f, -1.76452816e+00f, 1.88149130e+00f), GLINT_FLOAT4(-1.54443967e+00f, 1.59727132e+00f, -1.31325281e+00f, 1.32317090e+00f),
    GLINT_FLOAT4(-1.07272112e+00f, 1.06554031e+00f, -8.26056063e-01f, 8.31501007e-01f), GLINT_FLOAT4(-5.77584207e-01f, 6.27339125e-01f, -3.31785470e-01f, 4.56659883e-01f),
    GLINT_FLOAT4(-9.21456963e-02f, 3.19386333e-01f, 1.39530107e-01f, 2.12174460e-01f), GLINT_FLOAT4(3.63072217e-01f, 1.29789710e-01f, 5.79427540e-01f, 6.65425882e-02f),
    GLINT_FLOAT4(7.90057123e-01f, 1.72530860e-02f, 9.96490777e-01f, -2.23160610e-02f), GLINT_FLOAT4(1.20009243e+00f, -5.53900748e-02f, 1.40199602e+00f, -8.43001381e-02f),
    GLINT_FLOAT4(1.60314727e+00f, -1.10670500e-01f, 1.80439913e+00f, -1.35610566e-01f), GLINT_FLOAT4(2.00661945e+00f, -1.59881666e-01f, 2.21078920e+00f, -1.84027061e-01f),
    GLINT_FLOAT4(2.41807628e+00f, -2.08464041e-01f, 2.62988544e+00f, -2.33543158e-01f), GLINT_FLOAT4(2.84788465e+00f, -2.59581536e-01f, 3.07401943e+00f, -2.86879092e-01f),
    GLINT_FLOAT4(3.31052470e+00f, -3.15724760e-01f, 3.55994654e+00f, -3.46398562e-01f), GLINT_FLOAT4(-4.16303301e+00f, 6.35158730e+00f, -4.04724884e+00f, 6.07845688e+00f),
    GLINT_FLOAT4(-3.92842484e+00f, 5.80435658e+00f, -3.80631900e+00f, 5.52920008e+00f), GLINT_FLOAT4(-3.68065667e+00f, 5.25289154e+00f, -3.55112529e+00f, 4.97532415e+00f),
    GLINT_FLOAT4(-3.41736603e+00f, 4.69637966e+00f, -3.27896690e+00f, 4.41593218e+00f), GLINT_FLOAT4(-3.13545156e+00f, 4.13385057e+00f, -2.98626781e+00f, 3.85000777e+00f),
    GLINT_FLOAT4(-2.83077693e+00f, 3.56429720e+00f, -2.66824079e+00f, 3.27666664e+00f), GLINT_FLOAT4(-2.49781609e+00f, 2.98717070e+00f, -2.31855989e+00f, 2.69606614e+00f),
    GLINT_FLOAT4(-2.12945914e+00f, 2.40396380e+00f, -1.92951107e+00f, 2.11206365e+00f), GLINT_FLOAT4(-1.71788359e+00f, 1.82248592e+00f, -1.49419844e+00f, 1.53866863e+00f),
    GLINT_FLOAT4(-1.25893819e+00f, 1.26568818e+00f, -1.01388538e+00f, 1.01019049e+00f), GLINT_FLOAT4(-7.62326419e-01f, 7.79533744e-01f, -5.08679211e-01f, 5.80054879e-01f),
    GLINT_FLOAT4(-2.57474661e-01f, 4.15137023e-01f, -1.21637620e-02f, 2.84240395e-01f), GLINT_FLOAT4(2.25558728e-01f, 1.83461413e-01f, 4.55650777e-01f, 1.07068010e-01f),
    GLINT_FLOAT4(6.79136336e-01f, 4.90345955e-02f, 8.97464216e-01f, 4.02859645e-03f), GLINT_FLOAT4(1.11206305e+00f, -3.21838260e-02f, 1.32413852e+00f, -6.27189651e-02f),
    GLINT_FLOAT4(1.53465593e+00f, -8.97470638e-02f, 1.74442852e+00f, -1.14724636e-01f), GLINT_FLOAT4(1.95424557e+00f, -1.38617232e-01f, 2.16499472e+00f, -1.62080705e-01f),
    GLINT_FLOAT4(2.37775350e+00f, -1.85591638e-01f, 2.59384155e+00f, -2.09530696e-01f), GLINT_FLOAT4(2.81484246e+00f, -2.34229267e-01f, 3.04260302e+00f, -2.59991974e-01f),
    GLINT_FLOAT4(3.27923346e+00f, -2.87106544e-01f, 3.52712107e+00f, -3.15849096e-01f), GLINT_FLOAT4(3.78897119e+00f, -3.46489757e-01f, -4.13951731e+00f, 6.29833841e+00f),
    GLINT_FLOAT4(-4.02312756e+00f, 6.02501488e+00f, -3.90365076e+00f, 5.75070429e+00f), GLINT_FLOAT4(-3.78083825e+00f, 5.47531843e+00f, -3.65440798e+00f, 5.19875860e+00f),
    GLINT_FLOAT4(-3.52403831e+00f, 4.92091513e+00f, -3.38935971e+00f, 4.64166689e+00f), GLINT_FLOAT4(-3.24994683e+00f, 4.36088562e+00f, -3.10530734e+00f, 4.07843637e+00f),
    GLINT_FLOAT4(-2.95486927e+00f, 3.79419041e+00f, -2.79796934e+00f, 3.50804281e+00f), GLINT_FLOAT4(-2.63384008e+00f, 3.21994543e+00f, -2.46160173e+00f, 2.92996597e+00f),
    GLINT_FLOAT4(-2.28026748e+00f, 2.63838816e+00f, -2.08877373e+00f, 2.34587359e+00f), GLINT_FLOAT4(-1.88606131e+00f, 2.05370927e+00f, -1.67124295e+00f, 1.76415801e+00f),
    GLINT_FLOAT4(-1.44389749e+00f, 1.48086953e+00f, -1.20449388e+00f, 1.20920026e+00f), GLINT_FLOAT4(-9.54846025e-01f, 9.56101477e-01f, -6.98314369e-01f, 7.29158580e-01f),
    GLINT_FLOAT4(-4.39396948e-01f, 5.34720004e-01f, -1.82648867e-01f, 3.75882208e-01f), GLINT_FLOAT4(6.85497001e-02f, 2.51572877e-01f, 3.12642038e-01f, 1.57281905e-01f),
    GLINT_FLOAT4(5.49716175e-01f, 8.67691115e-02f, 7.80842125e-01f, 3.36989053e-02f), GLINT_FLOAT4(1.00739861e+00f, -7.36213382e-03f, 1.23064661e+00f, -4.05837297e-02f),
    GLINT_FLOAT4(1.45158017e+00f, -6.89197630e-02f, 1.67097270e+00f, -9.43450704e-02f), GLINT_FLOAT4(1.88951886e+00f, -1.18137121e-01f, 2.10799026e+00f, -1.41125977e-01f),
    GLINT_FLOAT4(2.32735562e+00f, -1.63881332e-01f, 2.54884696e+00f, -1.86833605e-01f), GLINT_FLOAT4(2.77397585e+00f, -2.10341319e-01f, 3.00451493e+00f, -2.34722570e-01f),
    GLINT_FLOAT4(3.24247527e+00f, -2.60267973e-01f, 3.49010038e+00f, -2.87247568e-01f), GLINT_FLOAT4(3.74989319e+00f, -3.15918833e-01f, 4.02468681e+00f, -3.46537411e-01f),
    GLINT_FLOAT4(-4.11626911e+00f, 6.24567795e+00f, -3.99927497e+00f, 5.97216177e+00f), GLINT_FLOAT4(-3.87914562e+00f, 5.69764090e+00f, -3.75562644e+00f, 5.42202520e+00f),
    GLINT_FLOAT4(-3.62842751e+00f, 5.14521313e+00f, -3.49721813e+00f, 4.86709261e+00f), GLINT_FLOAT4(-3.36161757e+00f, 4.58754015e+00f, -3.22118688e+00f, 4.30642319e+00f),
    GLINT_FLOAT4(-3.07541680e+00f, 4.02360535e+00f, -2.92371607e+00f, 3.73895645e+00f), GLINT_FLOAT4(-2.76539588e+00f, 3.45237231e+00f, -2.59965801e+00f, 3.16381097e+00f),
    GLINT_FLOAT4(-2.42558551e+00f, 2.87335491e+00f, -2.24214673e+00f, 2.58131862e+00f), GLINT_FLOAT4(-2.04822564e+00f, 2.28841925e+00f, -1.84270620e+00f, 1.99604070e+00f),
    GLINT_FLOAT4(-1.62464571e+00f, 1.70659995e+00f, -1.39358056e+00f, 1.42397475e+00f), GLINT_FLOAT4(-1.14996874e+00f, 1.15381765e+00f, -8.95657659e-01f, 9.03392136e-01f),
    GLINT_FLOAT4(-6.34079158e-01f, 6.80495799e-01f, -3.69795263e-01f, 4.91442323e-01f), GLINT_FLOAT4(-1.07353270e-01f, 3.38970423e-01f, 1.49976358e-01f, 2.21405536e-01f),
    GLINT_FLOAT4(4.00799453e-01f, 1.33589342e-01f, 6.45324111e-01f, 6.87759742e-02f), GLINT_FLOAT4(8.84617925e-01f, 2.03607231e-02f, 1.11991596e+00f, -1.71261933e-02f),
    GLINT_FLOAT4(1.35223901e+00f, -4.77236584e-02f, 1.58232474e+00f, -7.41730407e-02f), GLINT_FLOAT4(1.81075442e+00f, -9.82307419e-02f, 2.03814602e+00f, -1.20998718e-01f),
    GLINT_FLOAT4(2.26532149e+00f, -1.43191993e-01f, 2.49340200e+00f, -1.65318772e-01f), GLINT_FLOAT4(2.72382522e+00f, -1.87781900e-01f, 2.95831013e+00f, -2.10925922e-01f),
    GLINT_FLOAT4(3.19880652e+00f, -2.35054776e-01f, 3.44745708e+00f, -2.60439634e-01f), GLINT_FLOAT4(3.70660114e+00f, -2.87327528e-01f, 3.97882891e+00f, -3.15954059e-01f),
    GLINT_FLOAT4(4.26708174e+00f, -3.46559584e-01f, -4.09330177e+00f, 6.19366121e+00f), GLINT_FLOAT4(-3.97570443e+00f, 5.91995192e+00f, -3.85492373e+00f, 5.64522076e+00f),
    GLINT_FLOAT4(-3.73069835e+00f, 5.36937523e+00f, -3.60273075e+00f, 5.09231091e+00f), GLINT_FLOAT4(-3.47068048e+00f, 4.81391287e+00f, -3.33415604e+00f, 4.53405523e+00f),
    GLINT_FLOAT4(-3.19270396e+00f, 4.25260210e+00f, -3.04579878e+00f, 3.96941543e+00f), GLINT_FLOAT4(-2.89282775e+00f, 3.68436337e+00f, -2.73307657e+00f, 3.39734387e+00f),
    GLINT_FLOAT4(-2.56571579e+00f, 3.10832238e+00f, -2.38979006e+00f, 2.81739831e+00f), GLINT_FLOAT4(-2.20422149e+00f, 2.52492023e+00f, -2.00784087e+00f, 2.23166704e+00f),
    GLINT_FLOAT4(-1.79947412e+00f, 1.93912804e+00f, -1.57812274e+00f, 1.64988804e+00f), GLINT_FLOAT4(-1.34328258e+00f, 1.36806858e+00f, -1.09540260e+00f, 1.09963322e+00f),
    GLINT_FLOAT4(-8.36365640e-01f, 8.52161884e-01f, -5.69669008e-01f, 6.33643270e-01f), GLINT_FLOAT4(-2.99918145e-01f, 4.50302452e-01f, -3.16147804e-02f, 3.04444104e-01f),
    GLINT_FLOAT4(2.32120275e-01f, 1.93722814e-01f, 4.90073264e-01f, 1.12299591e-01f), GLINT_FLOAT4(7.42546856e-01f, 5.29390611e-02f, 9.90538001e-01f, 8.82467255e-03f),
    GLINT_FLOAT4(1.23505080e+00f, -2.54738461e-02f, 1.47679508e+00f, -5.37962243e-02f), GLINT_FLOAT4(1.71622670e+00f, -7.86305740e-02f, 1.95376432e+00f, -1.01507947e-01f),
    GLINT_FLOAT4(2.19002151e+00f, -1.23373598e-01f, 2.42595506e+00f, -1.44856319e-01f), GLINT_FLOAT4(2.66290355e+00f, -1.66426823e-01f, 2.90253782e+00f, -1.88472167e-01f),
    GLINT_FLOAT4(3.14677525e+00f, -2.11323008e-01f, 3.39770532e+00f, -2.35263094e-01f), GLINT_FLOAT4(3.65756154e+00f, -2.60538012e-01f, 3.92874956e+00f, -2.87368864e-01f),
    GLINT_FLOAT4(4.21393013e+00f, -3.15970153e-01f, 4.51615000e+00f, -3.46568733e-01f), GLINT_FLOAT4(-4.07062531e+00f, 6.14233065e+00f, -3.95242596e+00f, 5.86842823e+00f),
    GLINT_FLOAT4(-3.83099532e+00f, 5.59348679e+00f, -3.70606470e+00f, 5.31741095e+00f), GLINT_FLOAT4(-3.57732868e+00f, 5.04009438e+00f, -3.44443727e+00f, 4.76141882e+00f),
    GLINT_FLOAT4(-3.30698729e+00f, 4.48125505e+00f, -3.16451120e+00f, 4.19946575e+00f), GLINT_FLOAT4(-3.01646614e+00f, 3.91590977e+00f, -2.86221814e+00f, 3.63045502e+00f),
    GLINT_FLOAT4(-2.70102668e+00f, 3.34300232e+00f, -2.53202963e+00f, 3.05352497e+00f), GLINT_FLOAT4(-2.35423255e+00f, 2.76214290e+00f, -2.16651034e+00f, 2.46924162e+00f),
    GLINT_FLOAT4(-1.96763945e+00f, 2.17566848e+00f, -1.75638700e+00f, 1.88302743e+00f), GLINT_FLOAT4(-1.53169894e+00f, 1.59408438e+00f, -1.29303169e+00f, 1.31322062e+00f),
    GLINT_FLOAT4(-1.04082823e+00f, 1.04672468e+00f, -7.77006924e-01f, 8.02493215e-01f), GLINT_FLOAT4(-5.05122066e-01f, 5.88678658e-01f, -2.29796559e-01f, 4.11356300e-01f),
    GLINT_FLOAT4(4.45564128e-02f, 2.72316039e-01f, 3.15005094e-01f, 1.68476716e-01f), GLINT_FLOAT4(5.80523908e-01f, 9.32968855e-02f, 8.41465175e-01f, 3.90849374e-02f),
    GLINT_FLOAT4(1.09866643e+00f, -1.11403526e-03f, 1.35280514e+00f, -3.26065943e-02f), GLINT_FLOAT4(1.60422063e+00f, -5.89694269e-02f, 1.85309196e+00f, -8.24121386e-02f),
    GLINT_FLOAT4(2.09974146e+00f, -1.04252055e-01f, 2.34487367e+00f, -1.25309095e-01f), GLINT_FLOAT4(2.58966613e+00f, -1.46156535e-01f, 2.83571887e+00f, -1.67244911e-01f),
    GLINT_FLOAT4(3.08493209e+00f, -1.88947856e-01f, 3.33938217e+00f, -2.11575657e-01f), GLINT_FLOAT4(3.60125208e+00f, -2.35384256e-01f, 3.87282944e+00f, -2.60589808e-01f),
    GLINT_FLOAT4(4.15656853e+00f, -2.87388355e-01f, 4.45520020e+00f, -3.15976769e-01f), GLINT_FLOAT4(4.77188349e+00f, -3.46572101e-01f, -4.04824591e+00f, 6.09172392e+00f),
    GLINT_FLOAT4(-3.92944741e+00f, 5.81762886e+00f, -3.80736828e+00f, 5.54247665e+00f), GLINT_FLOAT4(-3.68173385e+00f, 5.26617002e+00f, -3.55222988e+00f, 4.98859978e+00f),
    GLINT_FLOAT4(-3.41849732e+00f, 4.70964527e+00f, -3.28012037e+00f, 4.42917490e+00f), GLINT_FLOAT4(-3.13661790e+00f, 4.14704800e+00f, -2.98742867e+00f, 3.86312151e+00f),
    GLINT_FLOAT4(-2.83189702e+00f, 3.57726431e+00f, -2.66925597e+00f, 3.28937984e+00f), GLINT_FLOAT4(-2.49861002e+00f, 2.99945211e+00f, -2.31892443e+00f, 2.70762253e+00f),
    GLINT_FLOAT4(-2.12902570e+00f, 2.41431856e+00f, -1.92763531e+00f, 2.12046266e+00f), GLINT_FLOAT4(-1.71346092e+00f, 1.82778287e+00f, -1.48539317e+00f, 1.53923929e+00f),
    GLINT_FLOAT4(-1.24285066e+00f, 1.25948906e+00f, -9.86272335e-01f, 9.95157063e-01f), GLINT_FLOAT4(-7.17611492e-01f, 7.54453480e-01f, -4.40467685e-01f, 5.45661092e-01f),
    GLINT_FLOAT4(-1.59449607e-01f, 3.74636829e-01f, 1.21165276e-01f, 2.42572576e-01f), GLINT_FLOAT4(3.98671806e-01f, 1.45590439e-01f, 6.72225237e-01f, 7.64400661e-02f),
    GLINT_FLOAT4(9.42159772e-01f, 2.70250626e-02f, 1.20904660e+00f, -9.65905469e-03f), GLINT_FLOAT4(1.47314000e+00f, -3.87074947e-02f, 1.73437345e+00f, -6.33815601e-02f),
    GLINT_FLOAT4(1.99269378e+00f, -8.56074840e-02f, 2.24842787e+00f, -1.06518216e-01f), GLINT_FLOAT4(2.50247931e+00f, -1.26846075e-01f, 2.75631309e+00f, -1.47134215e-01f),
    GLINT_FLOAT4(3.01180029e+00f, -1.67819723e-01f, 3.27103281e+00f, -1.89256668e-01f), GLINT_FLOAT4(3.53619289e+00f, -2.11725682e-01f, 3.80951118e+00f, -2.35449433e-01f),
    GLINT_FLOAT4(4.09330606e+00f, -2.60614783e-01f, 4.39007807e+00f, -2.87396669e-01f), GLINT_FLOAT4(4.70263910e+00f, -3.15979213e-01f, 5.03427124e+00f, -3.46573293e-01f),
    GLINT_FLOAT4(-4.02616549e+00f, 6.04185295e+00f, -3.90676999e+00f, 5.76756573e+00f), GLINT_FLOAT4(-3.78404450e+00f, 5.49220324e+00f, -3.65770721e+00f, 5.21566629e+00f),
    GLINT_FLOAT4(-3.52743673e+00f, 4.93784237e+00f, -3.39286304e+00f, 4.65860939e+00f), GLINT_FLOAT4(-3.25355887e+00f, 4.37783194e+00f, -3.10902810e+00f, 4.09536791e+00f),
    GLINT_FLOAT4(-2.95869136e+00f, 3.81107187e+00f, -2.80187106e+00f, 3.52481365e+00f), GLINT_FLOAT4(-2.63777208e+00f, 3.23650074e+00f, -2.46546531e+00f, 2.94612932e+00f),
    GLINT_FLOAT4(-2.28387475e+00f, 2.65386462e+00f, -2.09177804e+00f, 2.36018109e+00f), GLINT_FLOAT4(-1.88783991e+00f, 2.06608176e+00f, -1.67070854e+00f, 1.77342999e+00f),
    GLINT_FLOAT4(-1.43922007e+00f, 1.48539352e+00f, -1.19275677e+00f, 1.20692050e+00f), GLINT_FLOAT4(-9.31755900e-01f, 9.44983184e-01f, -6.58203185e-01f, 7.08096802e-01f),
    GLINT_FLOAT4(-3.75727296e-01f, 5.04633367e-01f, -8.88849795e-02f, 3.40155929e-01f), GLINT_FLOAT4(1.98231786e-01f, 2.15174854e-01f, 4.83176082e-01f, 1.24962531e-01f),
    GLINT_FLOAT4(7.65258491e-01f, 6.15688674e-02f, 1.04470301e+00f, 1.65643692e-02f), GLINT_FLOAT4(1.32169211e+00f, -1.70035921e-02f, 1.59597135e+00f, -4.39344905e-02f),
    GLINT_FLOAT4(1.86707079e+00f, -6.71406016e-02f, 2.13479424e+00f, -8.82825255e-02f), GLINT_FLOAT4(2.39959931e+00f, -1.08351097e-01f, 2.66268730e+00f, -1.28026962e-01f),
    GLINT_FLOAT4(2.92584300e+00f, -1.47837505e-01f, 3.19117832e+00f, -1.68202266e-01f), GLINT_FLOAT4(3.46091652e+00f, -1.89444840e-01f, 3.73729014e+00f, -2.11808592e-01f),
    GLINT_FLOAT4(4.02254677e+00f, -2.35481799e-01f, 4.31902933e+00f, -2.60625839e-01f), GLINT_FLOAT4(4.62929249e+00f, -2.87399918e-01f, 4.95624352e+00f, -3.15980017e-01f),
    GLINT_FLOAT4(5.30330038e+00f, -3.46573532e-01f, 0.00000000e+00f, 0.00000000e+00f)
GLINT_TABLE_CLOSE;
#endif

// The weights of cubic Lagrange interpolation through nodes 0..3 at x (x in [0, 1] between nodes 1
// and 2, or in [-1, 0] and [2, 3] in the edge cells, where the stencil cannot be centred).
GLINT_FN vec4 glint_cubic_weights(real x) {
    real a = x + real(1), b = x, c = x - real(1), d = x - real(2);
    real ab = a * b, cd = c * d;
    return vec4(b * cd * real(-1.0 / 6.0), a * cd * real(0.5), ab * d * real(-0.5), ab * c * real(1.0 / 6.0));
}

// Node k / 2 of the two-sided fit's table (k even): its (t', log(sigma' / sqrt(v))).
GLINT_FN vec2 glint_binomial_far_node(int k) {
    return vec2(real(GLINT_TABLE_READ(GLINT_BINOMIAL_FAR_TABLE, k)), real(GLINT_TABLE_READ(GLINT_BINOMIAL_FAR_TABLE, k + 1)));
}

// Row i of the stencil, columns j .. j + 3, weighted by w.
GLINT_FN vec2 glint_binomial_far_row(int i, int j, vec4 w) {
    int k = 2 * (i * GLINT_BINOMIAL_FAR_COLUMNS + j);
    return w.x * glint_binomial_far_node(k) + w.y * glint_binomial_far_node(k + 2) + w.z * glint_binomial_far_node(k + 4) +
           w.w * glint_binomial_far_node(k + 6);
}

GLINT_FN_OUT_OF_LINE vec2 glint_binomial_two_sided_fit(real N, real p_near) {
    // 1 / 29 (the span of N) and 1 / GLINT_BINOMIAL_FAR_X_STEP.
    real fn = sqrt(sqrt(max(N - GLINT_BINOMIAL_FAR_N_MIN, real(0)) * real(0.0344827586206896552))) * real(GLINT_BINOMIAL_FAR_ROWS - 1);
    real fx = (log2(max(p_near, GLINT_FLT_MIN_NORMAL)) + real(20) * p_near - GLINT_BINOMIAL_FAR_X_MIN) * real(1.37931034482758621);
    fn = clamp(fn, real(0), real(GLINT_BINOMIAL_FAR_ROWS - 1));
    fx = clamp(fx, real(0), real(GLINT_BINOMIAL_FAR_COLUMNS - 1));
    // The 4 x 4 stencil: nodes i .. i + 3 and j .. j + 3, centred where it can be.
    int i = clamp(int(fn) - 1, 0, GLINT_BINOMIAL_FAR_ROWS - 4);
    int j = clamp(int(fx) - 1, 0, GLINT_BINOMIAL_FAR_COLUMNS - 4);
    vec4 wr = glint_cubic_weights(fn - real(i) - real(1));
    vec4 wc = glint_cubic_weights(fx - real(j) - real(1));
    return wr.x * glint_binomial_far_row(i, j, wc) + wr.y * glint_binomial_far_row(i + 1, j, wc) + wr.z * glint_binomial_far_row(i + 2, j, wc) +
           wr.w * glint_binomial_far_row(i + 3, j, wc);
}

// Whether the middle's (t, sigma) come without the ends (glint_binomial_middle_fit): N from 4 (up to
// N = 4 the two-point law needs the middle's mean) to 32, from the far bound's table; from N = 32
// on, in closed form where N p_near >= 2^-7 (below, the middle is drawn with probability under
// about N p_near, and its parameters come from the ends). (A 128 x 13 table of the exact
// one-sided fit for N >= 32 and N p_near from 2^-7 to 17 made the CPU sampler about 1.6x faster
// there, but its constant array made the GLSL frames of examples/gl/glint_gl on llvmpipe 2x
// slower: glint_binomial_band_fit_scaled's polynomials replaced it.)
GLINT_CONST(real) GLINT_BINOMIAL_BUSY_LAMBDA = real(17);
GLINT_CONST(real) GLINT_BINOMIAL_CLOSED_LAMBDA = real(3);
GLINT_CONST(real) GLINT_BINOMIAL_FIRST_ORDER_DECAY = real(9);
GLINT_CONST(real) GLINT_BINOMIAL_BAND_LAMBDA_MIN = real(0.0078125);  // 2^-7

GLINT_FN bool glint_binomial_middle_needs_no_ends(real N, real p_near) {
    return N >= real(4) && (N < GLINT_BINOMIAL_FAR_N_MAX || N * p_near >= GLINT_BINOMIAL_BAND_LAMBDA_MIN);
}

// The middle in closed form (glint_binomial_closed_fit): lambda = N p_near >= 3 with the far bound
// 5 sd or more above lambda - 1 (glint_binomial_far_bound_clear: from N = 29 on always; below,
// from N = 11.45 on, for example N = 20 at p_near from 0.15 to 0.40), the one-sided fit from the middle's moments, without the ends' log1p and exp:
// - the near end's weight eps = (1 - p_near)^N = exp(N log(1 - p_near)), the log by its series up
//   to p^6 below p_near = 0.1 (relative error below p^6 / 6.3 = 1.6e-7) and by log(1 - p_near)
//   from there on; the far end's weight p_near^N taken as 0 (at most 2.2e-7 where the far bound
//   is clear, at N = 11.45, p_near = 0.262);
// - then, for y = n - 1 on the middle, m = (lambda - 1 + eps) / (1 - eps) and
//   v = (v0 - eps (lambda^2 + v0)) / (1 - eps)^2 with v0 = lambda (1 - p_near) (the moments of
//   glint/binomial.hpp's step 1 with p^N = 0; free of cancellation). Where
//   lambda (1 + p_near / 2 + p_near^2 / 3) >= 17 (a lower bound on -N log(1 - p_near)), eps is below
//   exp(-17) = 4.1e-8 and is skipped: m = lambda - 1, v = v0 (from lambda = 17 as p_near -> 0
//   down to lambda = 11.2 at p_near = 1/2: `glint_frame_loop draw 30 0.5`, callgrind, 480 to 388
//   instructions a draw with its hashes, 383 with the first order below; on a scan of N from 6
//   to 200 and p_near in steps of 0.001, the 24272 points it newly skips keep the mean within
//   1.1e-7 and the variance within 2.1e-6).
//   Where that bound lies from 9 to 17 (eps below exp(-9) = 1.2e-4), eps is taken to first order:
//   the fit at eps = 0 times 1 + eps (dsd/deps / sd, dm/deps / m), with eps from an inline atanh
//   series and exp (no libm call), beside the fit rather than before it; it leaves out how A and
//   B change with w, for the middle offset's mean within 2.8e-6 and its variance within 3.8e-5 of
//   their targets (the band's polynomials: 2.7e-6 and 1.8e-5). Per draw 482 to 429 instructions at
//   N = 30, p = 0.3, 447 to 429 at N = 1000, p = 0.01 (`glint_frame_loop draw`, callgrind), and in
//   a timing loop of the report's kind 40 to 32 ns against Alg. 1's 15 to 17 (this 2-core AMD
//   EPYC): libm's log and exp cost more than their instructions there, and taking the
//   derivatives of A and B too (12 more polynomial steps) cost 5 of the 8 ns saved.
// (t, sigma) from w = sd / m: where 6 sd <= m (the clamp 6 sd below, cutting less than
// Phi(-6) = 1e-9 of the mass) t = m / sd and sigma = sd; above, t = A(w) / w and
// sigma = sd B(w), polynomials of degree 6 in two pieces, fitted on [1/6, 0.39] and [0.38, 0.78]
// (w <= 0.756 from lambda = 3 on) by bench/fit_clamped_gaussian.cpp (|A error| 1.1e-6 and
// 3.7e-7, B's relative error, the mean's, 7.4e-8 and 3.4e-7). Altogether the middle offset's
// mean within 7.9e-7 and its variance within 6.0e-6 of their targets where eps is exact or
// skipped (see glint_binomial_far_bound_clear), 2.8e-6 and 3.8e-5 where it is to first order. It
// replaced the band's polynomials from lambda = 3 to 17, and the far bound's table where that
// bound is clear: no log2 and no table read
// (`glint_frame_loop draw`, callgrind: 604 to 500 instructions a draw with its hashes at N = 30,
// p = 0.1, 582 to 480 at N = 30, p = 1/2, 507 to 447 at N = 1000, p = 0.01; 605 to 613 at N = 10,
// p = 1/2, which the table still serves).

// (sigma, sigma t) from the middle's sd, m and 1 / m (w = sd / m <= 0.78): the sampler reads only
// sigma and the Gaussian's centre sigma t = sd B(w) A(w) / w = m A(w) B(w), so t itself, a
// division, is left to the callers that need it.
GLINT_FN vec2 glint_binomial_closed_fit_moments(real sd, real m, real inv_m) {
    if (real(6) * sd <= m) return vec2(sd, m);
    real w = sd * inv_m;
    real a, b;
    if (w <= real(0.39)) {
        real s = (w - real(0.27833333333333332)) * real(8.955223880597014);
        a = real(0.00011943678449015837);
        a = real(0.00018302133751199874) + s * a;
        a = real(-0.00069547161469821195) + s * a;
        a = real(-0.002035638081040209) + s * a;
        a = real(-0.0020402758719174677) + s * a;
        a = real(-0.00092859049255856834) + s * a;
        a = real(0.99983447436784556) + s * a;
        b = real(-0.0001010116038187498);
        b = real(-0.00019222158274883212) + s * b;
        b = real(0.00054878094329678456) + s * b;
        b = real(0.0017921698298307932) + s * b;
        b = real(0.0018572517958501784) + s * b;
        b = real(0.00085872202306998995) + s * b;
        b = real(1.0001543519893139) + s * b;
    } else {
        real s = (w - real(0.58)) * real(5);
        a = real(0.00015238612634742497);
        a = real(-0.00054884133667327585) + s * a;
        a = real(0.0010223532290255847) + s * a;
        a = real(0.0013518004634614407) + s * a;
        a = real(-0.03745569063120377) + s * a;
        a = real(-0.09043147439997852) + s * a;
        a = real(0.94211947292798182) + s * a;
        b = real(-0.00016808807881171867);
        b = real(0.00044515029568771634) + s * b;
        b = real(-0.00041189500770965357) + s * b;
        b = real(-0.0020756671873424634) + s * b;
        b = real(0.026306288444813662) + s * b;
        b = real(0.070620399407174198) + s * b;
        b = real(1.0472905854346981) + s * b;
    }
    return vec2(sd * b, m * (a * b));
}

// A lower bound on -N log(1 - p_near) = -log(eps), eps the near end's weight (-log(1 - p) >= p +
// p^2 / 2 + p^3 / 3): glint_binomial_closed_fit skips eps from 17 on and takes it to first order
// from GLINT_BINOMIAL_FIRST_ORDER_DECAY.
GLINT_FN real glint_binomial_near_end_decay(real lambda, real p_near) {
    return lambda * (real(1) + p_near * (real(0.5) + p_near * real(1.0 / 3.0)));
}

// (sigma, sigma t) of the middle at (N, p_near), lambda = N p_near >= 3.
GLINT_FN vec2 glint_binomial_closed_fit(real N, real p_near) {
    real lambda = N * p_near;
    real v0 = lambda * (real(1) - p_near);
    real decay = glint_binomial_near_end_decay(lambda, p_near);
    real m = lambda - real(1);
    real sd, inv_m;
    vec2 first_order = vec2(real(0));  // (sigma, sigma t) = f (1 + first_order), f at eps = 0
    if (decay >= GLINT_BINOMIAL_FIRST_ORDER_DECAY) {
        sd = sqrt(v0);
        inv_m = real(1) / m;
        // From decay = 17 on eps <= exp(-17) = 4.1e-8 (from lambda = 17 at p_near -> 0 down to 11.2
        // at p_near = 1/2), and the far end weighs less still: m = lambda - 1, v = v0.
        if (decay < GLINT_BINOMIAL_BUSY_LAMBDA) {
            // eps <= exp(-9) = 1.2e-4: the fit at eps = 0 times 1 + eps (dsd/deps / sd, dm/deps /
            // m), dm/deps = lambda, dv/deps = v0 - lambda^2 at eps = 0, leaving out how A and B
            // change with w (taking their derivatives too cost 5 of the 8 ns this saves a draw).
            // eps itself without a libm call: log(1 - p) = 2 atanh(z), z = -p / (2 - p) in [-1/3,
            // 0), by its series to z^7 / 7 (relative error below (1/3)^8 / 9 = 1.7e-5), and exp(x)
            // = 2^k exp(r), k the integer nearest x / log(2) (truncation rounds for x <= 0), r in
            // [-0.347, 0.347] by Taylor's polynomial of degree 4 (relative error below 4.2e-5): eps
            // within 3.4e-4 of itself (|x| <= 17 log(2) / (2/3) = 17.7 here), which moves the mean
            // by under 5e-8.
            real z = -p_near / (real(2) - p_near);
            real z2 = z * z;
            real x = N * (real(2) * z * (real(1) + z2 * (real(1.0 / 3.0) + z2 * (real(0.2) + z2 * real(1.0 / 7.0)))));
            real y = x * real(1.4426950408889634);  // 1 / log(2)
            int k = int(y - real(0.5));
            real r = (y - real(k)) * real(0.69314718055994531);  // log(2)
            real e = real(1) + r * (real(1) + r * (real(0.5) + r * (real(1.0 / 6.0) + r * real(1.0 / 24.0))));
            real eps = e * glint_exp2_int(k);
            first_order = eps * vec2(real(0.5) - real(0.5) * lambda / (real(1) - p_near), lambda * inv_m);
        }
    } else {
        // log(1 - p_near): its series up to p^6 below p = 0.1 (relative error below p^6 / 6.3 =
        // 1.6e-7; there 1 - p would round away up to 6e-8 / p of it), log itself from there on (its
        // rounding of 1 - p: 6e-7 at most).
        real series = real(1.0 / 5.0) + p_near * real(1.0 / 6.0);
        series = real(1) + p_near * (real(0.5) + p_near * (real(1.0 / 3.0) + p_near * (real(0.25) + p_near * series)));
        real eps = exp(N * ((p_near < real(0.1)) ? -p_near * series : log(real(1) - p_near)));
        // With P(M) = 1 - eps and E[y 1_M] = lambda - 1 + eps: m = E[y 1_M] / P(M), and
        // sd = sqrt(v0 - eps (lambda^2 + v0)) / P(M), from one division.
        real mass = real(1) - eps;
        real excess = m + eps;
        real q = real(1) / (mass * excess);
        sd = sqrt(v0 - eps * (lambda * lambda + v0)) * (excess * q);
        m = excess * (excess * q);
        inv_m = mass * (mass * q);
    }
    vec2 f = glint_binomial_closed_fit_moments(sd, m, inv_m);
    return f + f * first_order;
}

// Whether the far bound N - 2 lies 5 sd or more above lambda - 1, with sd = sqrt(lambda
// (1 - p_near)), the binomial's own: there the closed form's middle offset, capped at N - 2, keeps
// its mean within 7.9e-7 and its variance within 6.0e-6 of their targets (2.8e-6 and 3.8e-5
// where eps is to first order), the cap and the far end included (on N from 6 to 40 in steps of
// 0.05 and from 40 to 3000 in factors of 1.005, x p_near in steps of 0.001 and in factors of
// 1.005; the unit test in tests/unit/test_binomial_model.cpp checks integer N). From moments that
// need no exp, so that a draw the table must serve does not pay for the closed form first.
GLINT_FN bool glint_binomial_far_bound_clear(real N, real m0, real sd0) {
    return m0 + real(5) * sd0 <= N - real(2);
}
// The one-sided fit for N >= 32 and lambda = N p_near from 2^-7 to 17 (where the far bound removes
// less than 1e-8 of the middle's mean; the sampler reads it below lambda = 3, where
// glint_binomial_closed_fit takes over), without the ends: ((sigma t - (lambda - 1)) / sqrt(lambda),
// sigma / sqrt(lambda (1 - p_near))) as polynomials in x = log2(lambda) and q = 32 / N, four
// pieces in x. The digits come from bench/fit_binomial_band.cpp (Chebyshev interpolation of the
// exact fit, written in powers), which also measures what they leave over the band: the centre
// sigma t within 6.4e-6 sigma, sigma within 9.0e-6 (relative), the offset's mean within 2.7e-6 and
// its variance within 1.8e-5 of their targets (relative). A unit test checks the kernel against
// the exact fit. In GLSL their code costs time even where no draw reaches it: examples/gl/glint_gl's
// IBL K = 4 frames (all draws N < 32) at 192 x 120 on llvmpipe took 345 to 372 ms without it and
// 378 to 413 ms with it in alternating runs (the sampler fixed by GLINT_BINOMIAL_VARIANT).
// generated: GLINT_BINOMIAL_BAND_FIT by bench/fit_binomial_band.cpp
GLINT_FN vec2 glint_binomial_band_fit_scaled(real x, real q) {
    real r = real(2) * q - real(1);
    if (x < real(-3.5)) {
        real s = (x - real(-5.25)) * real(0.5714285714285714);
        vec2 r0 = vec2(real(-0.00578719517), real(0.00122846472));
        r0 = vec2(real(0.0495187567), real(-0.0114889161)) + s * r0;
        r0 = vec2(real(-0.330219664), real(0.0863400027)) + s * r0;
        r0 = vec2(real(1.74137784), real(-0.51957096)) + s * r0;
        r0 = vec2(real(-6.4674343), real(2.33857976)) + s * r0;
        r0 = vec2(real(13.910986), real(-6.61220459)) + s * r0;
        r0 = vec2(real(-12.333276), real(9.21376731)) + s * r0;
        vec2 r1 = vec2(real(-6.19847755e-06), real(1.15312848e-06));
        r1 = vec2(real(6.15150246e-05), real(-3.50545537e-06)) + s * r1;
        r1 = vec2(real(-0.000584791833), real(5.71941919e-05)) + s * r1;
        r1 = vec2(real(0.00331107124), real(-0.000406580779)) + s * r1;
        r1 = vec2(real(-0.0173109012), real(0.00171113555)) + s * r1;
        r1 = vec2(real(0.0598593294), real(-0.00926998291)) + s * r1;
        r1 = vec2(real(-0.0793162439), real(0.0123913266)) + s * r1;
        vec2 r2 = vec2(real(-8.59284747e-08), real(-1.09009978e-09));
        r2 = vec2(real(4.19599592e-07), real(-8.38877608e-08)) + s * r2;
        r2 = vec2(real(-4.3805184e-06), real(2.49781116e-07)) + s * r2;
        r2 = vec2(real(2.86006582e-05), real(-3.36869219e-06)) + s * r2;
        r2 = vec2(real(-0.000131787654), real(1.42535003e-05)) + s * r2;
        r2 = vec2(real(0.000471509499), real(-5.99075966e-05)) + s * r2;
        r2 = vec2(real(-0.000693618568), real(0.000109222814)) + s * r2;
        return r0 + r * (r1 + r * (r2));
    }
    if (x < real(0)) {
        real s = (x - real(-1.75)) * real(0.5714285714285714);
        vec2 r0 = vec2(real(-0.00119413826), real(0.000213972222));
        r0 = vec2(real(0.0126924671), real(-0.00334237344)) + s * r0;
        r0 = vec2(real(-0.06962748), real(0.0229496164)) + s * r0;
        r0 = vec2(real(0.376485373), real(-0.135523225)) + s * r0;
        r0 = vec2(real(-1.11979437), real(0.619448328)) + s * r0;
        r0 = vec2(real(1.37431907), real(-1.44323151)) + s * r0;
        r0 = vec2(real(-0.480710426), real(2.27193921)) + s * r0;
        vec2 r1 = vec2(real(2.26384489e-05), real(4.39935304e-06));
        r1 = vec2(real(0.000106865894), real(2.91094619e-05)) + s * r1;
        r1 = vec2(real(-4.17786713e-05), real(0.000137970106)) + s * r1;
        r1 = vec2(real(0.00061603145), real(0.000163387961)) + s * r1;
        r1 = vec2(real(-0.00750297587), real(0.000703137859)) + s * r1;
        r1 = vec2(real(0.0156794442), real(-0.00550015884)) + s * r1;
        r1 = vec2(real(-0.0100616754), real(-0.00167243226)) + s * r1;
        vec2 r2 = vec2(real(6.88293353e-07), real(8.64690472e-07));
        r2 = vec2(real(4.42385268e-07), real(1.8813713e-06)) + s * r2;
        r2 = vec2(real(-6.00117134e-06), real(1.46816331e-06)) + s * r2;
        r2 = vec2(real(-5.72707894e-06), real(-2.8280847e-06)) + s * r2;
        r2 = vec2(real(-5.4850334e-05), real(-5.27050297e-06)) + s * r2;
        r2 = vec2(real(0.000162979308), real(-4.15136285e-05)) + s * r2;
        r2 = vec2(real(-0.00011148088), real(2.08457804e-05)) + s * r2;
        return r0 + r * (r1 + r * (r2));
    }
    if (x < real(2)) {
        real s = (x - real(1)) * real(1);
        vec2 r0 = vec2(real(-0.000143962013), real(0.000202916944));
        r0 = vec2(real(-0.00128905653), real(0.000226781092)) + s * r0;
        r0 = vec2(real(-0.00534810357), real(-0.000196152663)) + s * r0;
        r0 = vec2(real(0.0250645199), real(-0.0137156374)) + s * r0;
        r0 = vec2(real(-0.000445247175), real(0.0638852972)) + s * r0;
        r0 = vec2(real(-0.0679298286), real(-0.137309837)) + s * r0;
        r0 = vec2(real(0.0539563853), real(1.11776219)) + s * r0;
        vec2 r1 = vec2(real(-2.16266304e-05), real(1.61418876e-05));
        r1 = vec2(real(-0.000128005622), real(-7.26477461e-06)) + s * r1;
        r1 = vec2(real(-0.00014189117), real(-0.000106809329)) + s * r1;
        r1 = vec2(real(0.000578125715), real(3.69214402e-05)) + s * r1;
        r1 = vec2(real(0.000207220212), real(0.00124596233)) + s * r1;
        r1 = vec2(real(0.000348620843), real(0.000434526771)) + s * r1;
        r1 = vec2(real(-0.00042622486), real(-0.00682564863)) + s * r1;
        vec2 r2 = vec2(real(-1.46052304e-06), real(-1.62337345e-07));
        r2 = vec2(real(-5.60319251e-06), real(-2.08775714e-06)) + s * r2;
        r2 = vec2(real(-2.75936215e-06), real(-7.53402981e-07)) + s * r2;
        r2 = vec2(real(1.32460621e-05), real(1.9516325e-05)) + s * r2;
        r2 = vec2(real(-5.82832035e-06), real(5.53605355e-05)) + s * r2;
        r2 = vec2(real(-3.25926217e-05), real(3.56975939e-05)) + s * r2;
        r2 = vec2(real(-2.88382083e-05), real(-2.586205e-05)) + s * r2;
        return r0 + r * (r1 + r * (r2));
    }
    real s = (x - real(3.0437314206251695)) * real(0.95810088710467722);
    vec2 r0 = vec2(real(0.000743992058), real(-0.00038386024));
    r0 = vec2(real(-0.000854638961), real(0.000736122561)) + s * r0;
    r0 = vec2(real(-0.00232878104), real(0.00120407691)) + s * r0;
    r0 = vec2(real(0.00495435553), real(-0.00143398347)) + s * r0;
    r0 = vec2(real(-0.00233800081), real(-0.00639705207)) + s * r0;
    r0 = vec2(real(-0.00158159591), real(0.0135301295)) + s * r0;
    r0 = vec2(real(0.00199008697), real(-0.00985050191)) + s * r0;
    r0 = vec2(real(-0.000584994157), real(1.00259894)) + s * r0;
    vec2 r1 = vec2(real(0.000222339071), real(-0.000345371613));
    r1 = vec2(real(0.000160224419), real(-4.4309575e-05)) + s * r1;
    r1 = vec2(real(-0.000820620044), real(0.00112530022)) + s * r1;
    r1 = vec2(real(-0.000345924467), real(0.000392592331)) + s * r1;
    r1 = vec2(real(0.0013953827), real(-0.00180887386)) + s * r1;
    r1 = vec2(real(-8.79708896e-05), real(-0.00130736176)) + s * r1;
    r1 = vec2(real(-0.00100236682), real(0.00362039479)) + s * r1;
    r1 = vec2(real(0.000485049454), real(-0.00165434118)) + s * r1;
    vec2 r2 = vec2(real(1.53767019e-05), real(-0.000123269438));
    r2 = vec2(real(7.6606893e-05), real(-0.000116665182)) + s * r2;
    r2 = vec2(real(-2.17654858e-05), real(0.000294103517)) + s * r2;
    r2 = vec2(real(-0.000211700437), real(0.000377840289)) + s * r2;
    r2 = vec2(real(-1.89040265e-05), real(-0.000200919799)) + s * r2;
    r2 = vec2(real(0.000223807255), real(-0.000494934009)) + s * r2;
    r2 = vec2(real(5.47774309e-05), real(-9.34861403e-07)) + s * r2;
    r2 = vec2(real(-0.000122858189), real(0.000284706303)) + s * r2;
    return r0 + r * (r1 + r * (r2));
}
// end of generated code

// (t, sigma, sigma t) of the band's middle: a log2, a division, two sqrt, and the polynomials.
GLINT_FN vec3 glint_binomial_band_fit(real N, real p_near) {
    real lambda = N * p_near;
    vec2 f = glint_binomial_band_fit_scaled(log2(lambda), real(32) / N);
    real centre = (lambda - real(1)) + f.x * sqrt(lambda);
    real sigma = f.y * sqrt(lambda * (real(1) - p_near));
    return vec3(centre / sigma, sigma, centre);
}

// (t, sigma, sigma t) of the middle where glint_binomial_middle_needs_no_ends: glint_binomial_closed_fit
// from lambda = 3 on where the far bound is clear, else the far bound's table below N = 32 and the
// band's polynomials from there on. Out of line in C++: inlined into its callers it changed how GCC
// inlines the grid's lattice code in the same translation unit, for more instructions (callgrind,
// glint_frame_loop: point 2 105.4M against 104.9M, ibl 4 1 43.7M against 43.2M).
GLINT_FN_OUT_OF_LINE vec3 glint_binomial_middle_fit(real N, real p_near) {
    real lambda = N * p_near;
    // N > 11 only spares the sqrt: the far bound is never clear below N = 11.45 from lambda = 3 on.
    if (lambda >= GLINT_BINOMIAL_CLOSED_LAMBDA && N > real(11) &&
        glint_binomial_far_bound_clear(N, lambda - real(1), sqrt(lambda * (real(1) - p_near)))) {
        vec2 f = glint_binomial_closed_fit(N, p_near);
        return vec3(f.y / f.x, f.x, f.y);
    }
    if (N < GLINT_BINOMIAL_FAR_N_MAX) {
        vec2 f = glint_binomial_two_sided_fit(N, p_near);
        real sigma = sqrt(lambda) * exp(f.y);
        return vec3(f.x, sigma, sigma * f.x);
    }
    return glint_binomial_band_fit(N, p_near);
}

GLINT_FN glint_binomial_middle glint_binomial_unbiased_middle_setup(real N, real p, glint_binomial_ends e) {
    glint_binomial_middle q;
    q.all_positive = e.all_positive;
    q.all_negative = e.all_negative;
    q.lower = e.lower;
    q.span = N - real(2);
    real p_near = (e.lower > real(0.5)) ? p : real(1) - p;
    bool no_ends = glint_binomial_middle_needs_no_ends(N, p_near);
    // The middle's moments, where neither a table nor the closed form gives its parameters, and
    // below N = 4, where the two-point law needs the mean. N <= 3: the middle holds at most two
    // counts, 1 and N - 1, and a Bernoulli with the right mean is exact at N = 3 (and continuous
    // down to N = 2, where it becomes the single count 1). glint_binomial_unbiased_middle blends it
    // into the Gaussian law between N = 3 and 4.
    glint_binomial_targets g;
    g.mean = real(0);
    g.variance = real(0);
    if (!no_ends) g = glint_binomial_middle_targets(N, p, e);
    q.two_point = (!no_ends && q.span > real(0)) ? g.mean / q.span : real(0);
    vec3 f = vec3(real(0));
    if (q.span > real(1)) {  // N <= 3: the two-point law alone
        // One call of each fit, so that GLSL inlines each table lookup once.
        if (no_ends || N < GLINT_BINOMIAL_FAR_N_MAX) {
            f = glint_binomial_middle_fit(N, p_near);
        } else {
            vec2 h = glint_binomial_one_sided_fit(g);
            f = vec3(h.x, h.y, h.y * h.x);
        }
    }
    q.t = f.x;
    q.sigma = f.y;
    q.center = (q.lower > real(0.5)) ? real(1) + f.z : (N - real(1)) - f.z;
    return q;
}

// All parameters of the mean-preserving sampler at (N, p), N >= 2.
GLINT_FN glint_binomial_middle glint_binomial_unbiased_setup(real N, real p, int method) {
    N = clamp(N, real(2), GLINT_BINOMIAL_MAX_N);
    return glint_binomial_unbiased_middle_setup(N, p, glint_binomial_unbiased_ends(N, p, method));
}

// The middle's clamped Gaussian count from N = 4 on: center + sigma z counted from the near end (z
// from u2, mirrored with p -> 1 - p, u2 -> 1 - u2 so that n and n_bar swap), clamped to
// [1, N2 - 1]. One rounding of center + sigma z: at N = 1e16 a count's ulp is most of a standard
// deviation, and rounding the offset first and then adding it to 1 or subtracting it from N - 1
// would round twice.
GLINT_FN real glint_binomial_gaussian_count(real center, real sigma, bool lower, real u2, real N2) {
    real z = glint_normal_quantile(lower ? u2 : real(1) - u2);
    return clamp(center + sigma * (lower ? z : -z), real(1), N2 - real(1));
}

GLINT_FN real glint_binomial_unbiased_middle(glint_binomial_middle q, real N2, real u2) {
    // Mirrored for the upper end, so that p -> 1 - p, u2 -> 1 - u2 swaps n and n_bar.
    real u_near = (q.lower > real(0.5)) ? u2 : real(1) - u2;
    // From N = 4 on: glint_binomial_gaussian_count, written out (called from here it moved GCC's
    // inlining: 3% more instructions in glint_frame_loop point 2).
    if (q.span >= real(2)) {
        real z = glint_normal_quantile(u_near);
        return clamp(q.center + q.sigma * ((q.lower > real(0.5)) ? z : -z), real(1), N2 - real(1));
    }
    // Up to N = 3 the middle is the two-point law of counts 1 and N - 1 (exact at N = 3), without
    // the quantile (the blend below would weigh it 0); from N = 3 to 4 it blends into the Gaussian
    // law comonotonically (same u), which keeps the mean and the law continuous in N.
    real two_point = (u_near >= real(1) - q.two_point) ? q.span : real(0);
    real offset = two_point;
    if (q.span > real(1)) {
        real gaussian = min(max(q.sigma * q.t + q.sigma * glint_normal_quantile(u_near), real(0)), q.span);
        offset = mix(two_point, gaussian, clamp(q.span - real(1), real(0), real(1)));
    }
    return (q.lower > real(0.5)) ? real(1) + offset : (N2 - real(1)) - offset;
}

// 1 + x + x^2 / 2 + x^3 / 6 <= exp(x) for x >= 0: its reciprocal bounds exp(-x) from above.
GLINT_FN real glint_binomial_exp_taylor3(real x) {
    return real(1) + x * (real(1) + x * (real(0.5) + x * real(1.0 / 6.0)));
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

// ---------------------------------------------------------------------------------------------
// Small N: an exact draw by inversion (the walk). For 2 < N < GLINT_BINOMIAL_WALK_FULL the
// mean-preserving sampler draws from
//   L(N, p) = (1 - f) b(Na, p) N / Na + f b(Na + 1, p) N / (Na + 1),   Na = floor(N), f = N - Na,
// the binomials of the two neighbouring integers, scaled onto [0, N], mixed with the fractional
// part as weight. At integer N it is b(N, p) exactly. For real N its mean is N p, P(n = 0) is the
// randomised-rounding binomial's, (1 - f) (1 - p)^Na + f (1 - p)^(Na + 1), its values lie in
// [0, N] (the randomised-rounding binomial's reach ceil(N)), and its variance is
// N^2 p (1 - p) ((1 - f) / Na + f / (Na + 1)), at most 4.2% above N p (1 - p) (at N = 2.5; 2.1%
// at N = 3.5, 0.5% at N = 10.5, by Jensen's inequality never below). It is continuous in N,
// and at N = 2 it is b(2, p), the exact gates' law below.
// One uniform, u1, drives it: n is the largest support point x with P(n >= x) > u1 for
// p <= 1/2 and, mirrored, N minus the walk at 1 - p with 1 - u1 for p > 1/2. So n is monotone in
// p and decreasing in u1, P(n > 0) <= N p (the near-end gate's and the grid's skip test's bound
// hold per draw), and (p, u1) -> (1 - p, 1 - u1) swaps the counts. The walk visits the support
// points of both components in increasing order (they interleave: k N / (Na + 1) < k N / Na <
// (k + 1) N / (Na + 1)), subtracting each point's mass from P(n > x), without a transcendental:
// P(n > 0) = c + f p (1 - c), c = 1 - (1 - p)^Na, from c's series where Na p < 1/4 (no
// cancellation; truncated after its seventh term, relative error below (Na p)^7 / 8! = 1.5e-9)
// and from (1 - p)^Na by squaring above; the binomial masses by their ratio recurrence.
// About N p_near + 1 iterations on average: `glint_frame_loop draw 10 0.5` counts 357
// instructions a draw with its hashes against 594 for the Gaussian middle, `draw 5 0.5` 258
// against 644 (callgrind); times against KK25 Alg. 1 in docs/binomial.md.
// From N = GLINT_BINOMIAL_WALK_FULL to GLINT_BINOMIAL_WALK_END, where a walk grows long at
// p near 1/2, the sampler blends into the Gaussian middle: it walks with probability
// w = (WALK_END - N) / (WALK_END - WALK_FULL), chosen by |u2 - 1/2| < w / 2 (symmetric in u2 and
// independent of p, so the monotonicity and the symmetry per draw stay), and otherwise draws
// the Gaussian middle with u2 stretched back onto (0, 1). The law is then the mixture of the two
// with weights w and 1 - w: continuous in N, with the mean N p of both.
GLINT_CONST(real) GLINT_BINOMIAL_WALK_FULL = real(12);
GLINT_CONST(real) GLINT_BINOMIAL_WALK_END = real(16);

// The walk's state at support point 0 for 2 < N < 16 and q = p_near <= 1/2: the masses of
// component Na (a0 = b(0; Na, q)) and Na + 1 (a1), and P(n > 0).
struct glint_binomial_walk_state {
    int Na;
    real f;
    real ratio;     // q / (1 - q)
    real a0;        // b(k; Na, q) at the current k
    real a1;        // b(k; Na + 1, q)
    real survival;  // P(n > x) at the current support point x
    real rescue;    // below this, survival is summed afresh from the masses beyond x
};

GLINT_FN glint_binomial_walk_state glint_binomial_walk_start(real N, real q) {
    glint_binomial_walk_state w;
    w.Na = int(N);
    real Na = real(w.Na);
    w.f = N - Na;
    real x = real(1) - q;
    w.ratio = q / x;
    real c;  // 1 - (1 - q)^Na
    if (Na * q < real(0.25)) {
        c = real(1) - (Na - real(6)) * q * real(1.0 / 7.0);
        c = real(1) - (Na - real(5)) * q * real(1.0 / 6.0) * c;
        c = real(1) - (Na - real(4)) * q * real(0.2) * c;
        c = real(1) - (Na - real(3)) * q * real(0.25) * c;
        c = real(1) - (Na - real(2)) * q * real(1.0 / 3.0) * c;
        c = real(1) - (Na - real(1)) * q * real(0.5) * c;
        c = Na * q * c;
    } else {
        real power = real(1), square = x;  // x^Na by squaring, Na < 16
        for (int bit = 0; bit < 4; ++bit) {
            if (((w.Na >> bit) & 1) != 0) power *= square;
            square *= square;
        }
        c = real(1) - power;
    }
    w.a0 = real(1) - c;
    w.a1 = w.a0 * x;
    w.survival = c + w.f * q * (real(1) - c);
    w.rescue = w.survival * real(1.0 / 1024.0);
    return w;
}

// The binomial masses at k from those at k - 1 (a0 = b(k; Na, q), a1 = b(k; Na + 1, q)), by their
// ratio recurrence: a0 becomes 0 at k = Na + 1.
GLINT_FN void glint_binomial_walk_advance(GLINT_INOUT(glint_binomial_walk_state) w, int k) {
    real t = w.ratio / real(k);
    w.a1 *= real(w.Na + 2 - k) * t;
    w.a0 *= real(w.Na + 1 - k) * t;
}

// P(n > k N / Na): the masses of the points beyond, summed afresh from the binomial masses at k
// (a0 = b(k; Na, q), a1 = b(k; Na + 1, q)) outwards, where the running difference has lost them.
GLINT_FN real glint_binomial_walk_tail(glint_binomial_walk_state w, int k) {
    real sum = real(0);  // w is this function's copy
    for (int j = k + 1; j <= 16; ++j) {
        if (j > w.Na + 1) break;
        glint_binomial_walk_advance(w, j);
        sum += w.f * w.a1 + (real(1) - w.f) * w.a0;
    }
    return sum;
}

// Steps from support point k - 1 to the two points of index k, k N / (Na + 1) and k N / Na (the
// masses f b(k; Na + 1, q) and (1 - f) b(k; Na, q)), and returns P(n > x) at each. A running
// difference from P(n > 0) carries an absolute error of a few ulps of P(n > 0), which swamps the
// far tail (and that tail is P(n = 0) for p > 1/2): where it falls below 2^-10 of its last fresh
// value, it is summed afresh from the masses beyond (glint_binomial_walk_tail), which only draws
// in that tail pay for. The survival at the first point is the second's plus its mass, a sum.
GLINT_FN vec2 glint_binomial_walk_step(GLINT_INOUT(glint_binomial_walk_state) w, int k) {
    glint_binomial_walk_advance(w, k);
    real second_mass = (real(1) - w.f) * w.a0;
    real after_second;
    if (k == w.Na) {
        after_second = real(0);  // k N / Na = N, the top
        second_mass += w.f * w.a1 * w.ratio / real(w.Na + 1);  // and the top of component Na + 1
    } else {
        after_second = w.survival - w.f * w.a1 - second_mass;
        if (after_second < w.rescue) {
            after_second = glint_binomial_walk_tail(w, k);
            w.rescue = after_second * real(1.0 / 1024.0);
        }
    }
    w.survival = after_second;
    return vec2(after_second + second_mass, after_second);
}

// The support points of index k: k N / (Na + 1) (first) and k N / Na (second; N itself at
// k = Na).
GLINT_FN real glint_binomial_walk_point(real N, int Na, int k, bool second) {
    if (!second) return real(k) * N / real(Na + 1);
    return (k == Na) ? N : real(k) * N / real(Na);
}

// The walk for p_near = q and v = u1 (or 1 - u1 mirrored): the count from the near end.
GLINT_FN real glint_binomial_walk_near(real N, real q, real v) {
    glint_binomial_walk_state w = glint_binomial_walk_start(N, q);
    real value = real(0);
    for (int k = 1; k < 16; ++k) {
        if (!(w.survival > v) || k > w.Na) break;
        vec2 after = glint_binomial_walk_step(w, k);
        bool stops_at_first = !(after.x > v);
        value = glint_binomial_walk_point(N, w.Na, k, !stops_at_first);
        if (stops_at_first) break;
    }
    return value;
}

// The walk's draw for 2 < N < GLINT_BINOMIAL_WALK_END (the caller clamps N and p).
GLINT_FN glint_binomial glint_binomial_walk(real N, real p, real u1) {
    bool lower = p <= real(0.5);
    real n = glint_binomial_walk_near(N, lower ? p : real(1) - p, lower ? u1 : real(1) - u1);
    return lower ? glint_binomial_pair(n, N - n) : glint_binomial_pair(N - n, n);
}

// Whether the draw walks (2 < N < GLINT_BINOMIAL_WALK_END, blended away from WALK_FULL on); where
// it does not, u2 becomes the Gaussian middle's own uniform, stretched back onto (0, 1).
// The walk's share of the draws at N: 1 below WALK_FULL, falling to 0 at WALK_END (for N > 2).
GLINT_FN real glint_binomial_walk_weight(real N) {
    return min((GLINT_BINOMIAL_WALK_END - N) / (GLINT_BINOMIAL_WALK_END - GLINT_BINOMIAL_WALK_FULL), real(1));
}

GLINT_FN bool glint_binomial_walks(real N, GLINT_INOUT(real) u2) {
    if (!(N > real(2) && N < GLINT_BINOMIAL_WALK_END)) return false;
    real w = glint_binomial_walk_weight(N);
    real d = u2 - real(0.5);
    if (w >= real(1) || abs(d) < real(0.5) * w) return true;
    u2 = real(0.5) + (d > real(0) ? d - real(0.5) * w : d + real(0.5) * w) / (real(1) - w);
    return false;
}

// The busy middle, where most draws of large footprints fall: lambda = N p_near >= 17 (so
// N >= 34, where the far bound is always clear), the clamp 6 sd or more below the mean
// (glint_binomial_closed_fit's first case) and u1 in [1.03e-3, 1 - 1.03e-3]. There
// glint_binomial_unbiased's test finds the middle sure (both of its glint_binomial_exp_taylor3
// factors are at least exp_taylor3(0.999 x 17) = 978.6, and 1.001 / 978.6 = 1.0229e-3, plus 1e-6
// at the top), so this is its arithmetic without the setup: the same result
// (tests/unit/test_binomial_shortcuts.cpp), in about 175 instructions against about 250 (Alg. 1's
// middle: 170). For N > 2 and N, p clamped; false where it does not apply. It stops at the closed
// form's first case: taking the rest of the closed form from lambda = 8.5 on made glint_gl's IBL
// frames on llvmpipe 12% to 20% slower (another inlined copy of the fit in every shader).
// glint_binomial_unbiased_cached does not take it: there it cost more than it saved (callgrind,
// glint_frame_loop: IBL K = 4 estimates 70.0M instructions without it, 71.9M with it; the
// point-light frame 107.9M and 110.4M), its draws mostly reusing a warm cache.
GLINT_FN bool glint_binomial_unbiased_busy(real N, real p, real u1, real u2, int method, GLINT_OUT(glint_binomial) r) {
    real p_near = min(p, real(1) - p);
    real lambda = N * p_near;
    if (!(method != GLINT_POW_NAIVE && lambda >= GLINT_BINOMIAL_BUSY_LAMBDA && u1 >= real(1.03e-3) && u1 <= real(1) - real(1.03e-3)))
        return false;
    real m = lambda - real(1);
    real sd = sqrt(lambda * (real(1) - p_near));
    if (!(real(6) * sd <= m)) return false;
    bool lower = p <= real(0.5);
    real G = glint_binomial_gaussian_count(lower ? real(1) + m : (N - real(1)) - m, sd, lower, u2, N);
    r = glint_binomial_pair(G, N - G);
    return true;
}

// A lower bound on Phi(-t), the share of the middle's clamped Gaussian that the clamp takes to
// the near count 1 (N - 1 mirrored), where the middle's parameters need no ends
// (glint_binomial_middle_needs_no_ends), from lambda = N p_near alone, for lambda >= 2^-7
// (glint_binomial_surely_clamped says why not below). The fitted t there gives
// Phi(-t) >= exp(-0.9253 lambda) from N = 12 on, where the sure middle begins (the largest
// -log(Phi(-t)) / lambda, 0.9252, is at lambda = 2^-7, where the band begins; swept over N from 4
// to 1e16 and lambda from 2^-10 to 3.5 by tests/unit/test_binomial_shortcuts.cpp), and the bound
// is exp(-0.94 lambda) by its Taylor polynomial of degree 5, which lies below it for lambda >= 0
// (the alternating series stopped after a negative term). At u_near equal to the bound, sigma
// (t + z) is at most -0.0094 (z the quantile; the same sweep, from N = 4 on), so the clamp fires in
// float too, with room for its roundings: near 1 (lower) for every N, near N - 1 (mirrored) while
// the ulp of N is at most 2^-12 (N up to 4096). It takes the clamp's count for 0.910 of the
// middle's draws at lambda = 0.1 (of the 0.916 that the clamp takes), 0.990 at 0.01 (of 0.991),
// 0.390 at 1 (of 0.472), none from lambda = 2.32 on (the bound is negative there).
GLINT_CONST(real) GLINT_BINOMIAL_CLAMPED_MIRROR_N_MAX = real(4096);
GLINT_FN real glint_binomial_clamped_mass_bound(real lambda) {
    real x = real(0.94) * lambda;
    return real(1) - x * (real(1) - x * (real(0.5) - x * (real(1.0 / 6.0) - x * (real(1.0 / 24.0) - x * real(1.0 / 120.0)))));
}

// True where the middle's count, drawn with u2 at (N, p) by glint_binomial_middle_fit's clamped
// Gaussian, is surely the clamp's near count: 1, or N - 1 for p > 1/2 up to N = 4096. From
// lambda = N p_near = 2^-7 on and N >= 4, where the middle's parameters need no ends; below, the far
// bound's table (N < 32) keeps its clamped share near 1 - 1e-5 as lambda -> 0, while the bound
// tends to 1.
GLINT_FN bool glint_binomial_surely_clamped(real N, real p, real u2) {
    bool lower = p <= real(0.5);
    real lambda = N * (lower ? p : real(1) - p);
    return N >= real(4) && lambda >= GLINT_BINOMIAL_BAND_LAMBDA_MIN && (lower || N <= GLINT_BINOMIAL_CLAMPED_MIRROR_N_MAX) &&
           (lower ? u2 : real(1) - u2) <= glint_binomial_clamped_mass_bound(lambda);
}

// The sure middle whose parameters need no ends (glint_binomial_unbiased's surely_middle): the
// general path's arithmetic without its gates, ends and setup structs, for the same result
// (tests/unit/test_binomial_shortcuts.cpp). There N >= 4, so the middle is the clamped Gaussian
// (glint_binomial_unbiased_middle's first case). In C++ it took the instructions per draw of
// `glint_frame_loop draw 30 0.5` (the far bound's table; hashes included) from 659 to 582 and of
// `draw 1000 0.01` (the band) from 579 to 507 (callgrind); GLSL keeps the one path, which inlines
// the table read and the band's polynomials once (see glint_binomial_unbiased).
GLINT_FN glint_binomial glint_binomial_unbiased_sure_middle(real N, real p, real u2) {
    bool lower = p <= real(0.5);
    // Where u2 surely lies in the clamped Gaussian's mass at the near end, the count is the clamp's
    // bound, without the fit or the quantile (glint_binomial_clamped_mass_bound).
    if (glint_binomial_surely_clamped(N, p, u2)) {
        real G = lower ? real(1) : N - real(1);
        return glint_binomial_pair(G, N - G);
    }
    vec3 f = glint_binomial_middle_fit(N, lower ? p : real(1) - p);
    real G = glint_binomial_gaussian_count(lower ? real(1) + f.z : (N - real(1)) - f.z, f.y, lower, u2, N);
    return glint_binomial_pair(G, N - G);
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
    if (glint_binomial_walks(N, u2)) return glint_binomial_walk(N, p, u1);
    glint_binomial busy;
    if (glint_binomial_unbiased_busy(N, p, u1, u2, method, busy)) return busy;
    // Where u1 is surely above p^N and below 1 - (1 - p)^N, no gate fires, and where the middle's
    // parameters come from a table or the closed form, the ends are not needed at all: they are
    // taken as 0, which decides the gates alike. The bounds are glint_binomial_dual_gated's with
    // exp(-x) <= 1 / (1 + x + x^2 / 2 + x^3 / 6) for (1 - q)^N <= exp(-N q) in place of
    // 1 / (1 + x): at N q = 10, 0.4% of the draws left to decide from the ends instead of 9%. In
    // C++ the sure middle takes glint_binomial_unbiased_sure_middle; GLSL keeps one path for both,
    // so that the middle's setup is inlined once (twice made the frames of examples/gl/glint_gl
    // slower on llvmpipe).
    bool surely_middle = method != GLINT_POW_NAIVE && glint_binomial_middle_needs_no_ends(N, min(p, real(1) - p)) &&
                         u1 * glint_binomial_exp_taylor3(real(0.999) * N * (real(1) - p)) >= real(1.001) &&
                         (real(1) - u1 - real(1e-6)) * glint_binomial_exp_taylor3(real(0.999) * N * p) >= real(1.001);
#if !defined(GLINT_GLSL)
    if (surely_middle) return glint_binomial_unbiased_sure_middle(N, p, u2);
#endif
    glint_binomial_ends e;
    glint_binomial_gates g;
    if (surely_middle) {
        e.all_positive = real(0);
        e.all_negative = real(0);
        e.any_near = real(1);
        e.lower = (p <= real(0.5)) ? real(1) : real(0);
        // The gates with both ends 0 and 0 < u1 < 1 (the test above bounds u1 below 1): the middle.
        g.positive_fixed = real(0);
        g.negative_fixed = real(0);
        g.gaussian = real(1);
    } else {
        e = glint_binomial_unbiased_ends(N, p, method);
        g = glint_binomial_dual_gates(N, p, u1, e.all_positive, e.all_negative);
    }
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
    c.middle.two_point = real(0);
    c.middle.center = real(0);
    return c;
}

// glint_binomial_unbiased, reusing the ends and the middle's parameters where N and p are those of
// the cache's last draw with N > 2: the same result, with one setup for draws that share (N, p).
// (It does not take glint_binomial_surely_clamped's shortcut: with a warm cache that saves only the
// quantile, 0.4% of `glint_frame_loop point 2`'s instructions, 104.73M to 104.29M.)
// (glint_binomial_unbiased does not call this with an empty cache: that made it 1.35x slower in
// the median over the binomial grid, the cache's stores not optimised away.)
GLINT_FN glint_binomial glint_binomial_unbiased_cached(real N, real p, real u1, real u2, int method, GLINT_INOUT(glint_binomial_cache) cache) {
    N = clamp(N, real(0), GLINT_BINOMIAL_MAX_N);
    p = clamp(p, real(0), real(1));
    if (glint_binomial_surely_near_end(N, p, u1, method)) return glint_binomial_near_end(N, p);
    if (N <= real(2)) return glint_binomial_unbiased_small(N, p, u1);
    if (glint_binomial_walks(N, u2)) return glint_binomial_walk(N, p, u1);
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

// A GLSL shader that draws with one variant and method only (a renderer's, as opposed to a test
// that compares them) can say so: with GLINT_BINOMIAL_VARIANT and GLINT_BINOMIAL_POW_METHOD
// #defined to their codes before the kernels, glint_binomial_variant and
// glint_binomial_variant_cached use those in place of their arguments (the grid's and the IBL's
// uniforms), and the compiler leaves the other variants out of the shader. (examples/gl/glint_gl
// does, for the mean-preserving sampler and log1p: at 192 x 120 on llvmpipe, in alternating runs,
// its IBL K = 4 frames went from about 520 to 370 ms and its point-light frames from 245 to
// 150 ms.) C++ ignores them: there each caller's variant is a value the optimiser sees or a
// branch predicted alike every call.
#if defined(GLINT_GLSL) && defined(GLINT_BINOMIAL_VARIANT) && defined(GLINT_BINOMIAL_POW_METHOD)
#define GLINT_BINOMIAL_FIXED_VARIANT
#endif

GLINT_FN glint_binomial glint_binomial_variant(int variant, real N, real p, real u1, real u2, int method) {
#ifdef GLINT_BINOMIAL_FIXED_VARIANT
    variant = GLINT_BINOMIAL_VARIANT;
    method = GLINT_BINOMIAL_POW_METHOD;
#endif
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
#ifdef GLINT_BINOMIAL_FIXED_VARIANT
    variant = GLINT_BINOMIAL_VARIANT;
    method = GLINT_BINOMIAL_POW_METHOD;
#endif
    if (variant == GLINT_BINOMIAL_UNBIASED) return glint_binomial_unbiased_cached(N, p, u1, u2, method, cache);
    return glint_binomial_variant(variant, N, p, u1, u2, method);
}
