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

// Where the mean-preserving sampler's exact walk draws (2 < N < WALK_FULL, blended into the
// Gaussian middle up to WALK_END; see "Small N" below).
GLINT_CONST(real) GLINT_BINOMIAL_WALK_FULL = real(32);
GLINT_CONST(real) GLINT_BINOMIAL_WALK_END = real(40);

// A bound T on the trials a draw at N makes, for P(n > 0) <= T p per draw: 2 up to N = 2 (the exact
// gates), N + 1 above, which covers the walk's b(ceil N, p) (drawn with probability frac(N)) and is
// within 1 / N of the Gaussian middle's N. One add, where ceil(N) below WALK_END and N above cost
// 11 instructions a vertex in C++ (callgrind), in loops that GCC no longer vectorised.
GLINT_FN real glint_binomial_trials_bound(real N) {
    return (N > real(2)) ? N + real(1) : real(2);
}

// True where the near-end gate surely fires (the near count is 0: n = 0 for p <= 1/2, n = N
// otherwise): N > 2, method kk25 or log1p, u1 beyond glint_binomial_trials_bound(N) min(p, 1 - p)
// 1.001 + 1e-5.
GLINT_FN bool glint_binomial_surely_near_end(real N, real p, real u1, int method) {
    real bound = glint_binomial_trials_bound(N) * min(p, real(1) - p) * real(1.001) + real(1e-5);
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

// Whether the middle's (t, sigma) come without the ends (glint_binomial_middle_fit): from N = 32
// on, where N p_near >= 2^-7 (below, the middle is drawn with probability under about N p_near,
// and its parameters come from the ends). Below N = 32 the sampler walks (Small N, below), and the
// middle's parameters come from the ends' moments by the one-sided fit, for the callers that set
// it up there (glint_binomial_unbiased_setup; the sampler's law in glint::testing weighs it 0).
// (A 41 x 41 table of the two-sided fit, the far bound included, served N = 4 to 32 until the walk
// took that range: 45 to 52 ns a draw from N = 16 to 28 at p near 1/2, 3x Alg. 1, and on an NVIDIA
// H200 its 13 KB constant array made glint_gl's IBL program shade 5600x slower than the smooth one,
// docs/gpu.md. A 128 x 13 table of the exact one-sided fit for N >= 32 and N p_near from 2^-7 to
// 17 made the CPU sampler about 1.6x faster there, but its constant array made the GLSL frames of
// examples/gl/glint_gl on llvmpipe 2x slower: glint_binomial_band_fit_scaled's polynomials
// replaced it.)
GLINT_CONST(real) GLINT_BINOMIAL_BUSY_LAMBDA = real(17);
GLINT_CONST(real) GLINT_BINOMIAL_CLOSED_LAMBDA = real(3);
GLINT_CONST(real) GLINT_BINOMIAL_FIRST_ORDER_DECAY = real(9);
GLINT_CONST(real) GLINT_BINOMIAL_BAND_LAMBDA_MIN = real(0.0078125);  // 2^-7

GLINT_FN bool glint_binomial_middle_needs_no_ends(real N, real p_near) {
    return N >= GLINT_BINOMIAL_WALK_FULL && N * p_near >= GLINT_BINOMIAL_BAND_LAMBDA_MIN;
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
// p = 1/2, which the far bound's table served until the walk took N < 32).

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
// need no exp. From N = 29 on it always holds, so the sampler, whose middle starts at N = 32, finds
// it clear wherever it asks.
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

// (t, sigma, sigma t) of the middle where glint_binomial_middle_needs_no_ends (N >= 32):
// glint_binomial_closed_fit from lambda = 3 on, else the band's polynomials. Out of line in C++: inlined into its callers it changed how GCC
// inlines the grid's lattice code in the same translation unit, for more instructions (callgrind,
// glint_frame_loop: point 2 105.4M against 104.9M, ibl 4 1 43.7M against 43.2M).
GLINT_FN_OUT_OF_LINE vec3 glint_binomial_middle_fit(real N, real p_near) {
    real lambda = N * p_near;
    // The sampler asks from N = 32 on, where the far bound is always clear: below N = 32 (not the
    // sampler's) the closed form holds where glint_binomial_far_bound_clear says so.
    if (lambda >= GLINT_BINOMIAL_CLOSED_LAMBDA) {
        vec2 f = glint_binomial_closed_fit(N, p_near);
        return vec3(f.y / f.x, f.x, f.y);
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
    // The middle's moments, where neither the band nor the closed form gives its parameters, and
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
        // One call of each fit, so that GLSL inlines each once.
        if (no_ends) {
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
// u2 picks the component (M = Na + 1 where u2 < f, else Na), u1 inverts it: the count is the
// largest k with P(n >= k) > u1 under b(M, p_near) from the near end (mirrored for p > 1/2: M
// minus the count at 1 - p with 1 - u1), scaled by N / M. So n is monotone in p and decreasing in
// u1, (p, u1) -> (1 - p, 1 - u1) swaps the counts, and n > 0 only where u1 < 1 - (1 - p)^M <=
// ceil(N) p: the near-end gate's and the grid's skip test's bound take N + 1 trials
// (glint_binomial_trials_bound). The walk subtracts each support point's mass from P(n > k),
// without a transcendental: P(n > 0) = 1 - (1 - p)^M from its series where M p < 1/4 (no
// cancellation; truncated after its seventh term, relative error below (M p)^7 / 8! = 1.5e-9) and
// from (1 - p)^M by squaring above; the masses by their ratio recurrence, four support points a
// step (glint_binomial_walk_steps); where P(n > k) falls below 2^-10 of its last fresh value (the
// far tail, which is P(0) for p > 1/2) it is summed afresh from the masses beyond.
// About (M p_near + 1) / 4 steps a draw, the walk's exit a mispredicted branch: at N = 30,
// p = 1/2 31.4 to 32.3 ns against KK25 Alg. 1's 18.3 to 18.7 and the closed-form middle's 21.9 to
// 22.5 (which needs N >= 29 for its far bound), at (30, 0.3) 28.0 and 28.3 against 18.3 and 18.6
// (`glint_frame_loop draw-time 30 0.5 65536`: 65536 uniform pairs, three runs on this 2-core AMD
// EPYC, CPU; docs/binomial.md has the report's figures). Earlier walks, the same measurement at
// (30, 1/2): two support points a step with one division for both, each step's exit a branch,
// 43.5 to 44.8 ns (its chain two multiplications and two subtractions a step); four a step with
// one division for the four, 36.6 and 36.8; four a step in SSE lanes (GCC vector extensions),
// one division for each and the products and sums as shuffled scans, 42.7 and 42.9. Over 1024
// pairs, whose cycle the branch predictor learns, the two-point walk took 24.5 ns and seemed
// faster than the middle (28.8 ns then). (One uniform for both components, their support points
// interleaved, cost twice the work a point: 64 ns at (30, 1/2); one division a point, 38 ns.)
// From N = GLINT_BINOMIAL_WALK_FULL to GLINT_BINOMIAL_WALK_END, where a walk grows long at
// p near 1/2, the sampler blends into the Gaussian middle: it walks with probability
// w = (WALK_END - N) / (WALK_END - WALK_FULL), chosen by |u2 - 1/2| < w / 2 (symmetric in u2 and
// independent of p, so the monotonicity and the symmetry per draw stay; the walk then reads u2
// stretched back onto (0, 1) to pick its component), and otherwise draws the Gaussian middle with
// u2 stretched back onto (0, 1). The law is then the mixture of the two with weights w and 1 - w:
// continuous in N, with the mean N p of both.
// The blend costs more than either alone near p = 1/2: which of the two draws is a branch taken
// at random, and the middle there is the fitted one (glint_binomial_unbiased_busy's shortcut needs
// 6 sd below the mean, lambda near 20 at p = 1/2): 39.6 ns a draw at (33, 1/2), 41.8 at (35, 1/2),
// 40.2 at (37, 1/2), 35.4 at (39, 1/2) against Alg. 1's 17.1 to 18.0 (`glint_frame_loop draw-time`,
// one run each), up to 2.35x; no grid point lies there.
GLINT_CONST(int) GLINT_BINOMIAL_WALK_MAX_TRIALS = 40;  // ceil(WALK_END): the loops' constant bound

// b(M, q) at support point 0 (M < 64 trials, q = p_near <= 1/2): the mass there, P(n > 0).
struct glint_binomial_walk_state {
    real ratio;     // q / (1 - q)
    real mass;      // b(k; M, q) at the current k
    real survival;  // P(n > k)
    real rescue;    // below this, survival is summed afresh from the masses beyond k
};

GLINT_FN glint_binomial_walk_state glint_binomial_walk_start(int M, real q) {
    glint_binomial_walk_state w;
    real m = real(M);
    real x = real(1) - q;
    w.ratio = q / x;
    if (m * q < real(0.25)) {
        real c = real(1) - (m - real(6)) * q * real(1.0 / 7.0);
        c = real(1) - (m - real(5)) * q * real(1.0 / 6.0) * c;
        c = real(1) - (m - real(4)) * q * real(0.2) * c;
        c = real(1) - (m - real(3)) * q * real(0.25) * c;
        c = real(1) - (m - real(2)) * q * real(1.0 / 3.0) * c;
        c = real(1) - (m - real(1)) * q * real(0.5) * c;
        w.survival = m * q * c;
        w.mass = real(1) - w.survival;
    } else {
        // x^M by squaring. The mass is this power itself, not 1 - (1 - x^M): that difference keeps
        // only 2^-24 / x^M of it (0.1% at M = 15, p = 1/2, in the walk this replaced).
        real power = real(1), square = x;
        for (int bit = 0; bit < 6; ++bit) {
            if (((M >> bit) & 1) != 0) power *= square;
            square *= square;
        }
        w.mass = power;
        w.survival = real(1) - power;
    }
    w.rescue = w.survival * real(1.0 / 1024.0);
    return w;
}

// P(n > k) summed afresh from the mass at k outwards. It stops where the masses can no longer
// change the sum: once a mass ratio t_j is at most 1/2 (they fall with j, so every later mass is at
// most half the one before) and the mass is below 2^-25 of the sum (2^-54 in double), every later
// mass lies below half an ulp of the sum and rounds away: the same sum, bit for bit, without the
// rest of the loop's divisions. In a sparse draw (M q small, where the walk's first step falls
// below its rescue bound at once) that is a few masses instead of about M.
GLINT_FN real glint_binomial_walk_tail(int M, real ratio, real mass, int k) {
    real sum = real(0);
    real negligible = GLINT_DOUBLE ? real(5.5511151231257827e-17) : real(2.98023223876953125e-8);  // 2^-54, 2^-25
    for (int j = k + 1; j <= GLINT_BINOMIAL_WALK_MAX_TRIALS; ++j) {
        if (j > M) break;
        real t = real(M + 1 - j) * ratio / real(j);
        mass *= t;
        sum += mass;
        if (t <= real(0.5) && mass < sum * negligible) break;
    }
    return sum;
}

// 1 / j for j = 0 to GLINT_BINOMIAL_WALK_MAX_TRIALS (0 at 0, which the walk never reads), each a
// constant expression that the compiler folds on both sides, so that the walk's steps need no
// division (one division per four support points: 36.6 and 36.8 ns a draw at N = 30, p = 1/2,
// against 31.4 to 32.3 with the table; see "Small N" above).
#if defined(GLINT_GLSL)
const real glint_binomial_reciprocals[GLINT_BINOMIAL_WALK_MAX_TRIALS + 1] = real[GLINT_BINOMIAL_WALK_MAX_TRIALS + 1](
    real(0), real(1), real(1) / real(2), real(1) / real(3), real(1) / real(4), real(1) / real(5),
    real(1) / real(6), real(1) / real(7), real(1) / real(8), real(1) / real(9), real(1) / real(10),
    real(1) / real(11), real(1) / real(12), real(1) / real(13), real(1) / real(14),
    real(1) / real(15), real(1) / real(16), real(1) / real(17), real(1) / real(18),
    real(1) / real(19), real(1) / real(20), real(1) / real(21), real(1) / real(22),
    real(1) / real(23), real(1) / real(24), real(1) / real(25), real(1) / real(26),
    real(1) / real(27), real(1) / real(28), real(1) / real(29), real(1) / real(30),
    real(1) / real(31), real(1) / real(32), real(1) / real(33), real(1) / real(34),
    real(1) / real(35), real(1) / real(36), real(1) / real(37), real(1) / real(38),
    real(1) / real(39), real(1) / real(40)
);
GLINT_FN real glint_binomial_reciprocal(int j) {
    return glint_binomial_reciprocals[j];
}
#else
struct glint_binomial_reciprocal_table {
    real r[GLINT_BINOMIAL_WALK_MAX_TRIALS + 1];
    constexpr glint_binomial_reciprocal_table() : r() {
        for (int j = 1; j <= GLINT_BINOMIAL_WALK_MAX_TRIALS; ++j) r[j] = real(1) / real(j);
    }
};
GLINT_FN real glint_binomial_reciprocal(int j) {
    static constexpr glint_binomial_reciprocal_table table{};  // constant-initialised: no guard
    return table.r[j];
}
#endif

// The count of b(M, q) for v = u1 (or 1 - u1 mirrored): the largest k with P(n >= k) > v. Four
// support points a step: their mass ratios t_i = b(k + i) / b(k + i - 1) = (M - k - i + 1) q /
// ((k + i) (1 - q)) do not depend on the walk so far, so the products and sums that follow from
// them leave only one multiplication (the mass) and one subtraction (P(n > k + 4)) in the chain
// from step to step, and one branch decides the step; the count within the step is the number of
// its first three P(n > k + i) above v, without branches. Past M a ratio is 0 (M - k - i + 1 = 0),
// so are the masses after it. P(n > k) comes by difference, and where it falls below 2^-10 of
// its last fresh value, P(n > k + 4) is summed afresh from the masses beyond and the step's other
// three are that sum plus the masses between (sums of positive terms, no cancellation).
GLINT_FN int glint_binomial_walk_steps(int M, real q, real v) {
    glint_binomial_walk_state w = glint_binomial_walk_start(M, q);
    if (!(w.survival > v)) return 0;
    real d = real(M);  // M - k
    for (int k = 0; k < GLINT_BINOMIAL_WALK_MAX_TRIALS; k += 4) {
        if (k >= M) break;
        real t1 = d * w.ratio * glint_binomial_reciprocal(k + 1), t2 = (d - real(1)) * w.ratio * glint_binomial_reciprocal(k + 2);
        real t3 = (d - real(2)) * w.ratio * glint_binomial_reciprocal(k + 3), t4 = (d - real(3)) * w.ratio * glint_binomial_reciprocal(k + 4);
        real c2 = t1 * t2;  // b(k + 2) / b(k)
        real m1 = w.mass * t1, m2 = w.mass * c2, m3 = m2 * t3, m4 = w.mass * (c2 * (t3 * t4));
        real m12 = m1 + m2;
        real s1 = w.survival - m1, s2 = w.survival - m12, s3 = w.survival - (m12 + m3), s4 = w.survival - (m12 + (m3 + m4));
        if (s4 < w.rescue) {
            s4 = glint_binomial_walk_tail(M, w.ratio, m4, k + 4);
            s3 = s4 + m4;
            s2 = s3 + m3;
            s1 = s2 + m2;
            w.rescue = s4 * real(1.0 / 1024.0);
        }
        if (!(s4 > v)) return min(k + 1 + int(s1 > v) + int(s2 > v) + int(s3 > v), M);
        w.mass = m4;
        w.survival = s4;
        d -= real(4);
    }
    return M;
}

// The count of a sparse draw (M q < 1/4) where bounds decide it before the walk starts, or -1
// where the walk must decide: 0 where v >= M q, and 1 where (M q)^2 / 2 (1 + 2^-10) <= v <
// M q (1 - M q / 2) (1 - 2^-10). The walk's own count there, bit for bit (tests/unit/
// test_binomial_model.cpp compares the two over M from 3 to 40, q from 1e-7 to the switch and v
// at and around every bound and every threshold of the walk):
// - 0: glint_binomial_walk_start's series gives P(n > 0) as (M q) c with c <= 1 (each of its
//   factors is 1 less a positive product), so its float value is at most the float M q <= v, and
//   the walk returns 0 (its !(survival > v)).
// - 1: P(n > 0) = 1 - (1 - q)^M >= M q (1 - (M - 1) q / 2) and P(n > 1) <= C(M, 2) q^2 <= (M q)^2 / 2
//   (Bonferroni's inequalities), and the walk's values of both lie within 2^-19 of them relatively
//   (the series' truncation below 1.5e-9; about twenty roundings; P(n > 1) a sum of positive masses
//   from its rescue, which a sparse draw's first step always takes: P(n > 4) / P(n > 0) <=
//   (M q)^4 / 120 < 2^-10, its roundings a few ulps of P(n > 0)), well inside the margins of
//   2^-10: P(n > 0) > v >= P(n > 1), and the first step returns 1.
// In the grid's draws (bench/light_pixels.hpp's 16 lights, 6485 draws) this decides 2272 of the
// 2299 walks without the walk's series, its division or its first step.
GLINT_FN int glint_binomial_walk_sparse_count(int M, real q, real v) {
    real mq = real(M) * q;
    if (!(mq < real(0.25))) return -1;
    if (v >= mq) return 0;
    bool one = v >= real(0.5) * mq * mq * real(1.0009765625) && v < mq * (real(1) - real(0.5) * mq) * real(0.9990234375);  // 1 +- 2^-10
    return one ? 1 : -1;
}

// The count of b(M, q) for v: the sparse draw's bounds, else the walk.
GLINT_FN int glint_binomial_walk_count(int M, real q, real v) {
    int sparse = glint_binomial_walk_sparse_count(M, q, v);
    return (sparse >= 0) ? sparse : glint_binomial_walk_steps(M, q, v);
}

// The walk's component: M = floor(N) + 1 where u2 < N - floor(N), else floor(N).
GLINT_FN int glint_binomial_walk_trials(real N, real u2) {
    int Na = int(N);
    return (u2 < N - real(Na)) ? Na + 1 : Na;
}

// The walk's draw for 2 < N < GLINT_BINOMIAL_WALK_END (the caller clamps N and p; u2 in (0, 1)
// picks the component, glint_binomial_walk_trials).
GLINT_FN glint_binomial glint_binomial_walk(real N, real p, real u1, real u2) {
    bool lower = p <= real(0.5);
    int M = glint_binomial_walk_trials(N, u2);
    real scale = N / real(M);
    int k = glint_binomial_walk_count(M, lower ? p : real(1) - p, lower ? u1 : real(1) - u1);
    real n = (k >= M) ? N : real(k) * scale;
    return lower ? glint_binomial_pair(n, N - n) : glint_binomial_pair(N - n, n);
}

// Whether the draw walks (2 < N < GLINT_BINOMIAL_WALK_END, blended away from WALK_FULL on); u2
// becomes the uniform of whichever draws, stretched back onto (0, 1).
// The walk's share of the draws at N: 1 below WALK_FULL, falling to 0 at WALK_END (for N > 2).
GLINT_FN real glint_binomial_walk_weight(real N) {
    return min((GLINT_BINOMIAL_WALK_END - N) / (GLINT_BINOMIAL_WALK_END - GLINT_BINOMIAL_WALK_FULL), real(1));
}

GLINT_FN bool glint_binomial_walks(real N, GLINT_INOUT(real) u2) {
    if (!(N > real(2) && N < GLINT_BINOMIAL_WALK_END)) return false;
    real w = glint_binomial_walk_weight(N);
    if (w >= real(1)) return true;
    real d = u2 - real(0.5);
    if (abs(d) < real(0.5) * w) {
        u2 = real(0.5) + d / w;
        return true;
    }
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
// lambda = N p_near = 2^-7 on and N >= 4 (the sampler asks from N = 32 on, where the middle's
// parameters need no ends); below 2^-7 the middle's clamped share tends to 1 as lambda -> 0, and so
// does the bound, which is not below it there.
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
// the closed form and the band's polynomials once (see glint_binomial_unbiased).
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

// Where u1 is surely above p^N and below 1 - (1 - p)^N, so that no gate fires, and the middle's
// parameters need no ends (glint_binomial_unbiased_rest says why these bounds).
GLINT_FN bool glint_binomial_surely_middle(real N, real p, real u1, int method) {
    return method != GLINT_POW_NAIVE && glint_binomial_middle_needs_no_ends(N, min(p, real(1) - p)) &&
           u1 * glint_binomial_exp_taylor3(real(0.999) * N * (real(1) - p)) >= real(1.001) &&
           (real(1) - u1 - real(1e-6)) * glint_binomial_exp_taylor3(real(0.999) * N * p) >= real(1.001);
}

// glint_binomial_unbiased (below) where the near-end gate does not surely fire, N and p clamped.
GLINT_FN_OUT_OF_LINE glint_binomial glint_binomial_unbiased_rest(real N, real p, real u1, real u2, int method) {
    if (N <= real(2)) return glint_binomial_unbiased_small(N, p, u1);
    if (glint_binomial_walks(N, u2)) return glint_binomial_walk(N, p, u1, u2);
    glint_binomial busy;
    if (glint_binomial_unbiased_busy(N, p, u1, u2, method, busy)) return busy;
    // Where u1 is surely above p^N and below 1 - (1 - p)^N, no gate fires, and where the middle's
    // parameters come from the band or the closed form, the ends are not needed at all: they are
    // taken as 0, which decides the gates alike. The bounds are glint_binomial_dual_gated's with
    // exp(-x) <= 1 / (1 + x + x^2 / 2 + x^3 / 6) for (1 - q)^N <= exp(-N q) in place of
    // 1 / (1 + x): at N q = 10, 0.4% of the draws left to decide from the ends instead of 9%. In
    // C++ the sure middle takes glint_binomial_unbiased_sure_middle; GLSL keeps one path for both,
    // so that the middle's setup is inlined once (twice made the frames of examples/gl/glint_gl
    // slower on llvmpipe).
    bool surely_middle = glint_binomial_surely_middle(N, p, u1, method);
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

// The mean-preserving dual-gated sampler: KK25 Alg. 1's gates (exact for N <= 2), and for N > 2
// a middle part whose mean is E[n | 1 <= n <= N - 1] exactly and whose variance matches the
// binomial's on that event (glint/binomial.hpp derives it). With the same result as the
// straight-line evaluation, it skips every transcendental where the near-end gate surely fires
// (glint_binomial_surely_near_end) and for N <= 2, and the ends' where both are subnormal.
// In C++ the cheap cases are inlined into the caller and the rest (N <= 2, the walk, the middle)
// is called out of line: the near end (most draws of sparse glints) and, from N = WALK_END on
// (where the walk leaves u2 as it is), the busy middle (most draws of large footprints). With the
// whole sampler out of line (GCC inlines Alg. 1), a loop of the report's kind (65536 uniform pairs;
// this 2-core AMD EPYC, CPU) took 16.2 ns a draw at (1e9, 0.5) against Alg. 1's 14.3, now 14.8;
// 2.6 ns at (30, 1e-5) against 1.9, now 2.1; 4.0 ns at (100, 1) against 2.9, now 2.6. N <= 2 stays
// out of line and is tested before the near-end gate: at (0.5, 0.3), 3.6 ns a draw, it took 8.2 ns
// with its gates inlined and 11 with the near-end gate tested first (their tests on u1 became
// branches in the caller). GLSL inlines everything and keeps one copy of the busy middle, in the
// rest.
GLINT_FN_INLINE glint_binomial glint_binomial_unbiased(real N, real p, real u1, real u2, int method) {
    N = clamp(N, real(0), GLINT_BINOMIAL_MAX_N);
    p = clamp(p, real(0), real(1));
#if defined(GLINT_GLSL)
    if (glint_binomial_surely_near_end(N, p, u1, method)) return glint_binomial_near_end(N, p);
#else
    if (N > real(2)) {
        if (glint_binomial_surely_near_end(N, p, u1, method)) return glint_binomial_near_end(N, p);
        glint_binomial busy;
        if (N >= GLINT_BINOMIAL_WALK_END && glint_binomial_unbiased_busy(N, p, u1, u2, method, busy)) return busy;
    }
#endif
    return glint_binomial_unbiased_rest(N, p, u1, u2, method);  // one call: GLSL inlines it once
}

#if !defined(GLINT_GLSL)
// C++ only (GLSL keeps the sampler's one path): the mean-preserving sampler's positive count
// (glint_binomial_unbiased(N, p, u1, u2, method).positive) where a sparse draw's bounds decide it
// without the walk or the middle, else -1, for N from 0 to GLINT_BINOMIAL_MAX_N and p <= 1/2 (where
// the sampler clamps neither): up to N = 2 its exact gates (glint_binomial_unbiased_small); above,
// for a method other than naive, 0 where the near-end gate surely fires; where the walk draws
// (glint_binomial_walks, which also stretches u2 between WALK_FULL and WALK_END) its sparse count
// (glint_binomial_walk_sparse_count), scaled as the walk scales it (1 becomes N / M); where the
// middle draws and the busy middle does not apply (N p below BUSY_LAMBDA), 1 where the sure
// middle's count is surely its clamp's (glint_binomial_surely_middle,
// glint_binomial_surely_clamped). The sampler's own steps in its own order, without its calls,
// dispatch and other paths: the grid's draws (behind its skip test, so sparse) take this first.
// tests/unit/test_binomial_shortcuts.cpp compares it with the sampler at and around every bound.
GLINT_FN real glint_binomial_unbiased_sparse(real N, real p, real u1, real u2, int method) {
    if (!(N >= real(0) && N <= GLINT_BINOMIAL_MAX_N && p >= real(0) && p <= real(0.5))) return real(-1);
    if (N <= real(2)) return glint_binomial_unbiased_small(N, p, u1).positive;
    if (method == GLINT_POW_NAIVE) return real(-1);
    if (glint_binomial_surely_near_end(N, p, u1, method)) return real(0);
    real u2_drawn = u2;
    if (glint_binomial_walks(N, u2_drawn)) {
        int M = glint_binomial_walk_trials(N, u2_drawn);
        int k = glint_binomial_walk_sparse_count(M, p, u1);
        if (k == 0) return real(0);
        if (k == 1) return N / real(M);  // the walk's 1 * (N / M)
    } else if (N * p < GLINT_BINOMIAL_BUSY_LAMBDA) {
        if (glint_binomial_surely_middle(N, p, u1, method) && glint_binomial_surely_clamped(N, p, u2_drawn)) return real(1);
    }
    return real(-1);
}
#endif

// The mean-preserving sampler's parameters at one (N, p), kept between draws that share them (the
// IBL multinomial's root draws of a lattice point's three triangle vertices; the grid's draws no
// longer use it, their corners mostly drawing once a pixel behind the skip test): the ends once
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
    if (glint_binomial_walks(N, u2)) return glint_binomial_walk(N, p, u1, u2);
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

#if !defined(GLINT_GLSL)
// C++ only: glint_binomial_variant's positive count where glint_binomial_unbiased_sparse decides it
// (the mean-preserving variant), else -1.
GLINT_FN real glint_binomial_variant_sparse(int variant, real N, real p, real u1, real u2, int method) {
    return (variant == GLINT_BINOMIAL_UNBIASED) ? glint_binomial_unbiased_sparse(N, p, u1, u2, method) : real(-1);
}
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
