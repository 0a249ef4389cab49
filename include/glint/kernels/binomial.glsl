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
// in constant time: (t', log(sigma' / sqrt(v))) such that min(sigma' max(t' + Z, 0), N - 2) has
// mean m and variance v, tabulated on a 41 x 41 grid and read by cubic Lagrange interpolation in
// both axes (a 4 x 4 stencil, centred except in the edge cells). Rows: ((N - 3) / 29)^(1/4)
// uniform from 0 to 1 (dense near N = 3, where sigma' grows without bound as the middle tends to
// the two-point law). Columns: x = log2(p_near) + 20 p_near uniform from -20 to 9 (p_near from
// 9.5e-7 to 1/2: steps of 0.72 in log2 p where p is small, where the far bound's effect follows
// log p, and of 0.03 in p near 1/2), x clamped to that range. From N = 26 to 32 the nodes blend
// into the one-sided fit, which takes over at N = 32 (there the far bound removes less than
// 1e-8 of the mean). The digits come from bench/fit_binomial_far_bound.cpp (damped Newton in
// double on the closed-form moments of the capped offset, glint_capped_offset_moments), which
// also measures what the interpolation leaves: E[n] within 2.3e-5 of N p (relative), the
// offset's mean within 7.5e-5 and its variance within 1.4e-4 of their targets. It replaces the
// Newton iteration that took up to 300 ns per draw at N p of 1 to 10 (docs/binomial.md).
GLINT_CONST(real) GLINT_BINOMIAL_FAR_N_MIN = real(3);
GLINT_CONST(real) GLINT_BINOMIAL_FAR_N_MAX = real(32);
GLINT_CONST(real) GLINT_BINOMIAL_FAR_X_MIN = real(-20);
GLINT_CONST(real) GLINT_BINOMIAL_FAR_X_STEP = real(0.725);                  // (9 - (-20)) / 40
GLINT_CONST(int) GLINT_BINOMIAL_FAR_ROWS = 41;
GLINT_CONST(int) GLINT_BINOMIAL_FAR_COLUMNS = 41;
// Generated by bench/fit_binomial_far_bound.cpp: (t', log(sigma' / sqrt(v))) per node, row by row,
// padded to whole vec4s.
GLINT_FLOAT_TABLE(GLINT_BINOMIAL_FAR_TABLE, 3364) GLINT_TABLE_OPEN
    GLINT_FLOAT4(-4.76188993e+00f, 1.30366297e+01f, -4.65936804e+00f, 1.26687880e+01f), GLINT_FLOAT4(-4.55475521e+00f, 1.23344603e+01f, -4.44791317e+00f, 1.20238380e+01f),
    GLINT_FLOAT4(-4.33869362e+00f, 1.17320728e+01f, -4.22693205e+00f, 1.14568291e+01f), GLINT_FLOAT4(-4.11244869e+00f, 1.11973553e+01f, -3.99504280e+00f, 1.09541721e+01f),
    GLINT_FLOAT4(-3.87449408e+00f, 1.07291384e+01f, -3.75055814e+00f, 1.05259237e+01f), GLINT_FLOAT4(-3.62296915e+00f, 1.03512259e+01f, -3.49144244e+00f, 1.02179251e+01f),
    GLINT_FLOAT4(-3.35568643e+00f, 1.01549778e+01f, -3.21543479e+00f, 1.02554970e+01f), GLINT_FLOAT4(-3.07055330e+00f, 1.12349873e+01f, -2.91963673e+00f, 9.65052795e+00f),
    GLINT_FLOAT4(-2.76407194e+00f, 9.04414749e+00f, -2.60420561e+00f, 8.66702461e+00f), GLINT_FLOAT4(-2.44057417e+00f, 8.49230766e+00f, -2.27562451e+00f, 8.07891464e+00f),
    GLINT_FLOAT4(-2.11044216e+00f, 8.10766602e+00f, -1.94902885e+00f, 8.71828079e+00f), GLINT_FLOAT4(-1.79327929e+00f, 8.80062866e+00f, -1.64472437e+00f, 8.03870392e+00f),
    GLINT_FLOAT4(-1.50513887e+00f, 7.75164080e+00f, -1.37458801e+00f, 7.65165329e+00f), GLINT_FLOAT4(-1.25260258e+00f, 7.73406649e+00f, -1.13844895e+00f, 8.26110649e+00f),
    GLINT_FLOAT4(-1.03054917e+00f, 7.80556679e+00f, -9.28309679e-01f, 7.19839716e+00f), GLINT_FLOAT4(-8.31375539e-01f, 6.93315220e+00f, -7.38512337e-01f, 7.25697517e+00f),
    GLINT_FLOAT4(-6.49388015e-01f, 7.38468790e+00f, -5.63723862e-01f, 8.42103958e+00f), GLINT_FLOAT4(-4.79093850e-01f, 7.28762150e+00f, -3.96723390e-01f, 6.98564148e+00f),
    GLINT_FLOAT4(-3.16058427e-01f, 7.02448988e+00f, -2.36945495e-01f, 7.92199278e+00f), GLINT_FLOAT4(-1.56792939e-01f, 6.76694679e+00f, -7.77681395e-02f, 6.59017849e+00f),
    GLINT_FLOAT4(3.06374300e-03f, 5.55673981e+00f, -4.76188946e+00f, 1.30362692e+01f), GLINT_FLOAT4(-4.65936756e+00f, 1.26684608e+01f, -4.55475473e+00f, 1.23341522e+01f),
    GLINT_FLOAT4(-4.44791269e+00f, 1.20235434e+01f, -4.33869314e+00f, 1.17317829e+01f), GLINT_FLOAT4(-4.22693157e+00f, 1.14565392e+01f, -4.11244822e+00f, 1.11970587e+01f),
    GLINT_FLOAT4(-3.99504256e+00f, 1.09538660e+01f, -3.87449360e+00f, 1.07288160e+01f), GLINT_FLOAT4(-3.75055766e+00f, 1.05255747e+01f, -3.62296891e+00f, 1.03508387e+01f),
    GLINT_FLOAT4(-3.49144220e+00f, 1.02174730e+01f, -3.35568619e+00f, 1.01544151e+01f), GLINT_FLOAT4(-3.21543431e+00f, 1.02546577e+01f, -3.07056856e+00f, 1.13136015e+01f),
    GLINT_FLOAT4(-2.91964245e+00f, 9.65819550e+00f, -2.76407814e+00f, 9.04977798e+00f), GLINT_FLOAT4(-2.60421348e+00f, 8.67304039e+00f, -2.44057870e+00f, 8.49621964e+00f),
    GLINT_FLOAT4(-2.27566886e+00f, 8.10924435e+00f, -2.11045647e+00f, 8.12025070e+00f), GLINT_FLOAT4(-1.94903553e+00f, 8.73385429e+00f, -1.79327869e+00f, 8.79854488e+00f),
    GLINT_FLOAT4(-1.64472377e+00f, 8.03754330e+00f, -1.50513816e+00f, 7.75061989e+00f), GLINT_FLOAT4(-1.37458730e+00f, 7.65059137e+00f, -1.25260186e+00f, 7.73276520e+00f),
    GLINT_FLOAT4(-1.13844812e+00f, 8.25864410e+00f, -1.03055131e+00f, 7.81014681e+00f), GLINT_FLOAT4(-9.28318501e-01f, 7.20780420e+00f, -8.31401169e-01f, 6.95449972e+00f),
    GLINT_FLOAT4(-7.38513947e-01f, 7.25972128e+00f, -6.49389386e-01f, 7.38764572e+00f), GLINT_FLOAT4(-5.63729763e-01f, 8.44731140e+00f, -4.79092956e-01f, 7.28624105e+00f),
    GLINT_FLOAT4(-3.96722466e-01f, 6.98459482e+00f, -3.16057473e-01f, 7.02337646e+00f), GLINT_FLOAT4(-2.36948222e-01f, 7.93134308e+00f, -1.56795219e-01f, 6.76989698e+00f),
    GLINT_FLOAT4(-7.77751058e-02f, 6.59591436e+00f, 3.09550716e-03f, 5.54847050e+00f), GLINT_FLOAT4(-4.76185417e+00f, 1.29902401e+01f, -4.65933180e+00f, 1.26266804e+01f),
    GLINT_FLOAT4(-4.55471802e+00f, 1.22948990e+01f, -4.44787550e+00f, 1.19857397e+01f), GLINT_FLOAT4(-4.33865452e+00f, 1.16946468e+01f, -4.22689247e+00f, 1.14194088e+01f),
    GLINT_FLOAT4(-4.11240768e+00f, 1.11593018e+01f, -3.99500108e+00f, 1.09147902e+01f), GLINT_FLOAT4(-3.87445092e+00f, 1.06875772e+01f, -3.75051379e+00f, 1.04810305e+01f),
    GLINT_FLOAT4(-3.62292314e+00f, 1.03012543e+01f, -3.49139476e+00f, 1.01598549e+01f), GLINT_FLOAT4(-3.35563636e+00f, 1.00824594e+01f, -3.21538138e+00f, 1.01486616e+01f),
    GLINT_FLOAT4(-3.07051539e+00f, 1.11685801e+01f, -2.91967034e+00f, 9.73137856e+00f), GLINT_FLOAT4(-2.76405501e+00f, 9.05519009e+00f, -2.60419321e+00f, 8.68074036e+00f),
    GLINT_FLOAT4(-2.44062734e+00f, 8.56497669e+00f, -2.27566075e+00f, 8.12740135e+00f), GLINT_FLOAT4(-2.11043215e+00f, 8.13124752e+00f, -1.94925964e+00f, 8.31940079e+00f),
    GLINT_FLOAT4(-1.79318893e+00f, 8.53570652e+00f, -1.64463675e+00f, 7.88972807e+00f), GLINT_FLOAT4(-1.50504827e+00f, 7.62041950e+00f, -1.37449324e+00f, 7.51526642e+00f),
    GLINT_FLOAT4(-1.25250196e+00f, 7.56719875e+00f, -1.13833487e+00f, 7.94938612e+00f), GLINT_FLOAT4(-1.03042042e+00f, 7.59929466e+00f, -9.28259790e-01f, 7.21644640e+00f),
    GLINT_FLOAT4(-8.31348896e-01f, 6.97011375e+00f, -7.38440692e-01f, 7.26237822e+00f), GLINT_FLOAT4(-6.49311841e-01f, 7.39052010e+00f, -5.63650727e-01f, 8.46630192e+00f),
    GLINT_FLOAT4(-4.78965700e-01f, 7.11072588e+00f, -3.96595299e-01f, 6.85116386e+00f), GLINT_FLOAT4(-3.15926820e-01f, 6.88150883e+00f, -2.36849412e-01f, 7.93991375e+00f),
    GLINT_FLOAT4(-1.56694785e-01f, 6.77616882e+00f, -7.76703283e-02f, 6.60142851e+00f), GLINT_FLOAT4(3.24122352e-03f, 5.54100561e+00f, -4.76167345e+00f, 1.27933502e+01f),
    GLINT_FLOAT4(-4.65915060e+00f, 1.24475908e+01f, -4.55453491e+00f, 1.21264458e+01f), GLINT_FLOAT4(-4.44768953e+00f, 1.18234205e+01f, -4.33846474e+00f, 1.15351477e+01f),
    GLINT_FLOAT4(-4.22669792e+00f, 1.12599401e+01f, -4.11220789e+00f, 1.09971809e+01f), GLINT_FLOAT4(-3.99479485e+00f, 1.07471037e+01f, -3.87423706e+00f, 1.05107899e+01f),
    GLINT_FLOAT4(-3.75029063e+00f, 1.02903767e+01f, -3.62268877e+00f, 1.00895948e+01f), GLINT_FLOAT4(-3.49114537e+00f, 9.91506481e+00f, -3.35536528e+00f, 9.77980614e+00f),
    GLINT_FLOAT4(-3.21507049e+00f, 9.71617889e+00f, -3.07009244e+00f, 9.88091183e+00f), GLINT_FLOAT4(-2.91938448e+00f, 9.42029762e+00f, -2.76415586e+00f, 9.26905727e+00f),
    GLINT_FLOAT4(-2.60406637e+00f, 8.68589783e+00f, -2.44076657e+00f, 8.59967995e+00f), GLINT_FLOAT4(-2.27552915e+00f, 8.14039898e+00f, -2.11028123e+00f, 8.13997269e+00f),
    GLINT_FLOAT4(-1.94910133e+00f, 8.33708668e+00f, -1.79258561e+00f, 7.65615845e+00f), GLINT_FLOAT4(-1.64410186e+00f, 7.31388807e+00f, -1.50451124e+00f, 7.10264969e+00f),
    GLINT_FLOAT4(-1.37392974e+00f, 6.98032761e+00f, -1.25188518e+00f, 6.93642712e+00f), GLINT_FLOAT4(-1.13758600e+00f, 6.97877264e+00f, -1.03015172e+00f, 7.16731405e+00f),
    GLINT_FLOAT4(-9.28402245e-01f, 7.32441187e+00f, -8.31053674e-01f, 6.98121262e+00f), GLINT_FLOAT4(-7.38565803e-01f, 7.16873407e+00f, -6.49563313e-01f, 7.37227821e+00f),
    GLINT_FLOAT4(-5.62557578e-01f, 6.70269871e+00f, -4.78204817e-01f, 6.45021057e+00f), GLINT_FLOAT4(-3.95871103e-01f, 6.32246351e+00f, -3.15178663e-01f, 6.32497787e+00f),
    GLINT_FLOAT4(-2.35948116e-01f, 6.63234043e+00f, -1.56668082e-01f, 6.59349251e+00f), GLINT_FLOAT4(-7.80487061e-02f, 6.84867001e+00f, 3.86981550e-03f, 5.50968409e+00f),
    GLINT_FLOAT4(-4.76100969e+00f, 1.23197412e+01f, -4.65849304e+00f, 1.20096092e+01f), GLINT_FLOAT4(-4.55387592e+00f, 1.17105560e+01f, -4.44702339e+00f, 1.14205332e+01f),
    GLINT_FLOAT4(-4.33778763e+00f, 1.11383171e+01f, -4.22600460e+00f, 1.08631840e+01f), GLINT_FLOAT4(-4.11149311e+00f, 1.05947514e+01f, -3.99405336e+00f, 1.03328800e+01f),
    GLINT_FLOAT4(-3.87346244e+00f, 1.00776224e+01f, -3.74947381e+00f, 9.82918072e+00f), GLINT_FLOAT4(-3.62181830e+00f, 9.58786392e+00f, -3.49020386e+00f, 9.35400295e+00f),
    GLINT_FLOAT4(-3.35432553e+00f, 9.12779045e+00f, -3.21388078e+00f, 8.90890408e+00f), GLINT_FLOAT4(-3.06860399e+00f, 8.69568920e+00f, -2.91832471e+00f, 8.48352051e+00f),
    GLINT_FLOAT4(-2.76306772e+00f, 8.26237297e+00f, -2.60320330e+00f, 8.01686764e+00f), GLINT_FLOAT4(-2.43965316e+00f, 7.73696041e+00f, -2.27407622e+00f, 7.43297100e+00f),
    GLINT_FLOAT4(-2.10886097e+00f, 7.12934113e+00f, -1.94680893e+00f, 6.84750128e+00f), GLINT_FLOAT4(-1.79057920e+00f, 6.59983158e+00f, -1.64214301e+00f, 6.39106321e+00f),
    GLINT_FLOAT4(-1.50252068e+00f, 6.22081614e+00f, -1.37185657e+00f, 6.08568811e+00f), GLINT_FLOAT4(-1.24968123e+00f, 5.98062944e+00f, -1.13519025e+00f, 5.89959764e+00f),
    GLINT_FLOAT4(-1.02745092e+00f, 5.83568239e+00f, -9.25525367e-01f, 5.78114939e+00f), GLINT_FLOAT4(-8.28534603e-01f, 5.72812366e+00f, -7.35687971e-01f, 5.67051125e+00f),
    GLINT_FLOAT4(-6.46294117e-01f, 5.60652161e+00f, -5.59758782e-01f, 5.53975916e+00f), GLINT_FLOAT4(-4.75572348e-01f, 5.47809172e+00f, -3.93294752e-01f, 5.43208265e+00f),
    GLINT_FLOAT4(-3.12541068e-01f, 5.41481256e+00f, -2.32961237e-01f, 5.44221878e+00f), GLINT_FLOAT4(-1.54146969e-01f, 5.51859283e+00f, -7.50911012e-02f, 5.49657011e+00f),
    GLINT_FLOAT4(4.00411105e-03f, 5.50875044e+00f, -4.75920343e+00f, 1.16413679e+01f), GLINT_FLOAT4(-4.65668678e+00f, 1.13580379e+01f, -4.55205727e+00f, 1.10770998e+01f),
    GLINT_FLOAT4(-4.44518089e+00f, 1.07983189e+01f, -4.33591032e+00f, 1.05214958e+01f), GLINT_FLOAT4(-4.22408247e+00f, 1.02464457e+01f, -4.10951471e+00f, 9.97298527e+00f),
    GLINT_FLOAT4(-3.99200606e+00f, 9.70091438e+00f, -3.87133241e+00f, 9.43000221e+00f), GLINT_FLOAT4(-3.74724507e+00f, 9.15996075e+00f, -3.61947179e+00f, 8.89043427e+00f),
    GLINT_FLOAT4(-3.48771811e+00f, 8.62097168e+00f, -3.35167527e+00f, 8.35102749e+00f), GLINT_FLOAT4(-3.21103787e+00f, 8.07998371e+00f, -3.06553984e+00f, 7.80723095e+00f),
    GLINT_FLOAT4(-2.91501641e+00f, 7.53236341e+00f, -2.75950933e+00f, 7.25552177e+00f), GLINT_FLOAT4(-2.59942055e+00f, 6.97788811e+00f, -2.43570161e+00f, 6.70220661e+00f),
    GLINT_FLOAT4(-2.27001071e+00f, 6.43303394e+00f, -2.10470963e+00f, 6.17633533e+00f), GLINT_FLOAT4(-1.94257271e+00f, 5.93831253e+00f, -1.78624308e+00f, 5.72387600e+00f),
    GLINT_FLOAT4(-1.63768542e+00f, 5.53556728e+00f, -1.49791956e+00f, 5.37341309e+00f), GLINT_FLOAT4(-1.36709177e+00f, 5.23553658e+00f, -1.24473703e+00f, 5.11899328e+00f),
    GLINT_FLOAT4(-1.13005733e+00f, 5.02045250e+00f, -1.02212989e+00f, 4.93662977e+00f), GLINT_FLOAT4(-9.20029998e-01f, 4.86453009e+00f, -8.22894216e-01f, 4.80160046e+00f),
    GLINT_FLOAT4(-7.29944110e-01f, 4.74585485e+00f, -6.40490234e-01f, 4.69600725e+00f), GLINT_FLOAT4(-5.53926647e-01f, 4.65160418e+00f, -4.69721347e-01f, 4.61313868e+00f),
    GLINT_FLOAT4(-3.87404978e-01f, 4.58210516e+00f, -3.06557298e-01f, 4.56085920e+00f), GLINT_FLOAT4(-2.26784870e-01f, 4.55170536e+00f, -1.47664785e-01f, 4.55284119e+00f),
    GLINT_FLOAT4(-6.85777888e-02f, 4.54348278e+00f, 1.10824835e-02f, 4.50527525e+00f), GLINT_FLOAT4(-4.75563765e+00f, 1.09717588e+01f, -4.65307474e+00f, 1.06971207e+01f),
    GLINT_FLOAT4(-4.54838800e+00f, 1.04225016e+01f, -4.44144392e+00f, 1.01478348e+01f), GLINT_FLOAT4(-4.33209372e+00f, 9.87304497e+00f, -4.22017384e+00f, 9.59803772e+00f),
    GLINT_FLOAT4(-4.10550117e+00f, 9.32270336e+00f, -3.98787355e+00f, 9.04691124e+00f), GLINT_FLOAT4(-3.86706519e+00f, 8.77051067e+00f, -3.74282670e+00f, 8.49333572e+00f),
    GLINT_FLOAT4(-3.61488414e+00f, 8.21520710e+00f, -3.48294234e+00f, 7.93595314e+00f), GLINT_FLOAT4(-3.34669113e+00f, 7.65544128e+00f, -3.20582604e+00f, 7.37363720e+00f),
    GLINT_FLOAT4(-3.06008077e+00f, 7.09070158e+00f, -2.90929294e+00f, 6.80714273e+00f), GLINT_FLOAT4(-2.75350738e+00f, 6.52403498e+00f, -2.59312987e+00f, 6.24328566e+00f),
    GLINT_FLOAT4(-2.42911530e+00f, 5.96788120e+00f, -2.26312518e+00f, 5.70194578e+00f), GLINT_FLOAT4(-2.09752393e+00f, 5.45038033e+00f, -1.93508661e+00f, 5.21800041e+00f),
    GLINT_FLOAT4(-1.77845740e+00f, 5.00843048e+00f, -1.62960207e+00f, 4.82334614e+00f), GLINT_FLOAT4(-1.48954189e+00f, 4.66242361e+00f, -1.35842478e+00f, 4.52388144e+00f),
    GLINT_FLOAT4(-1.23578811e+00f, 4.40518284e+00f, -1.12083709e+00f, 4.30359983e+00f), GLINT_FLOAT4(-1.01265204e+00f, 4.21655273e+00f, -9.10312116e-01f, 4.14177036e+00f),
    GLINT_FLOAT4(-8.12957227e-01f, 4.07734156e+00f, -7.19810963e-01f, 4.02172518e+00f), GLINT_FLOAT4(-6.30184114e-01f, 3.97374201e+00f, -5.43467343e-01f, 3.93257427e+00f),
    GLINT_FLOAT4(-4.59121406e-01f, 3.89777160e+00f, -3.76664996e-01f, 3.86925602e+00f), GLINT_FLOAT4(-2.95661986e-01f, 3.84726882e+00f, -2.15703666e-01f, 3.83209634e+00f),
    GLINT_FLOAT4(-1.36374742e-01f, 3.82304645e+00f, -5.71697392e-02f, 3.81517458e+00f), GLINT_FLOAT4(2.24618912e-02f, 3.80189466e+00f, -4.74979925e+00f, 1.03874884e+01f),
    GLINT_FLOAT4(-4.64713049e+00f, 1.01151247e+01f, -4.54232836e+00f, 9.84220600e+00f), GLINT_FLOAT4(-4.43525696e+00f, 9.56867218e+00f, -4.32576799e+00f, 9.29445362e+00f),
    GLINT_FLOAT4(-4.21369600e+00f, 9.01947021e+00f, -4.09885693e+00f, 8.74363136e+00f), GLINT_FLOAT4(-3.98104620e+00f, 8.46683598e+00f, -3.86003733e+00f, 8.18897533e+00f),
    GLINT_FLOAT4(-3.73557925e+00f, 7.90993738e+00f, -3.60739565e+00f, 7.62962103e+00f), GLINT_FLOAT4(-3.47518945e+00f, 7.34795332e+00f, -3.33864856e+00f, 7.06492329e+00f),
    GLINT_FLOAT4(-3.19746590e+00f, 6.78064251e+00f, -3.05137396e+00f, 6.49543571e+00f), GLINT_FLOAT4(-2.90020776e+00f, 6.20998096e+00f, -2.74401164e+00f, 5.92550421e+00f),
    GLINT_FLOAT4(-2.58319139e+00f, 5.64401865e+00f, -2.41870451e+00f, 5.36853170e+00f), GLINT_FLOAT4(-2.25221729e+00f, 5.10307646e+00f, -2.08610106e+00f, 4.85235596e+00f),
    GLINT_FLOAT4(-1.92314148e+00f, 4.62091637e+00f, -1.76599240e+00f, 4.41211987e+00f), GLINT_FLOAT4(-1.61662853e+00f, 4.22745228e+00f, -1.47607732e+00f, 4.06651068e+00f),
    GLINT_FLOAT4(-1.34449053e+00f, 3.92753625e+00f, -1.22140729e+00f, 3.80808949e+00f), GLINT_FLOAT4(-1.10603368e+00f, 3.70558429e+00f, -9.97450113e-01f, 3.61760068e+00f),
    GLINT_FLOAT4(-8.94735932e-01f, 3.54202294e+00f, -7.97030807e-01f, 3.47707415e+00f), GLINT_FLOAT4(-7.03557968e-01f, 3.42130399e+00f, -6.13626719e-01f, 3.37355757e+00f),
    GLINT_FLOAT4(-5.26625812e-01f, 3.33294582e+00f, -4.42011923e-01f, 3.29882264e+00f), GLINT_FLOAT4(-3.59298050e-01f, 3.27076364e+00f, -2.78040498e-01f, 3.24853349e+00f),
    GLINT_FLOAT4(-1.97823659e-01f, 3.23198318e+00f, -1.18235663e-01f, 3.22072268e+00f), GLINT_FLOAT4(-3.88168544e-02f, 3.21312475e+00f, 4.08839136e-02f, 3.20798659e+00f),
    GLINT_FLOAT4(-4.74121189e+00f, 9.88835812e+00f, -4.63837528e+00f, 9.61665821e+00f), GLINT_FLOAT4(-4.53339291e+00f, 9.34424496e+00f, -4.42612839e+00f, 9.07105350e+00f),
    GLINT_FLOAT4(-4.31643105e+00f, 8.79701710e+00f, -4.20413399e+00f, 8.52205563e+00f), GLINT_FLOAT4(-4.08905172e+00f, 8.24608517e+00f, -3.97097802e+00f, 7.96901369e+00f),
    GLINT_FLOAT4(-3.84968328e+00f, 7.69074488e+00f, -3.72491384e+00f, 7.41118574e+00f), GLINT_FLOAT4(-3.59639072e+00f, 7.13025665e+00f, -3.46381307e+00f, 6.84791183e+00f),
    GLINT_FLOAT4(-3.32686520e+00f, 6.56417465e+00f, -3.18523598e+00f, 6.27919292e+00f), GLINT_FLOAT4(-3.03865290e+00f, 5.99333048e+00f, -2.88694739e+00f, 5.70730209e+00f),
    GLINT_FLOAT4(-2.73016000e+00f, 5.42236567e+00f, -2.56869531e+00f, 5.14054871e+00f), GLINT_FLOAT4(-2.40351200e+00f, 4.86485624e+00f, -2.23628330e+00f, 4.59929085e+00f),
    GLINT_FLOAT4(-2.06939244e+00f, 4.34850168e+00f, -1.90564203e+00f, 4.11697054e+00f), GLINT_FLOAT4(-1.74770355e+00f, 3.90800166e+00f, -1.59756768e+00f, 3.72304511e+00f),
    GLINT_FLOAT4(-1.45627284e+00f, 3.56169081e+00f, -1.32397711e+00f, 3.42219806e+00f), GLINT_FLOAT4(-1.20022190e+00f, 3.30216312e+00f, -1.08421314e+00f, 3.19904470e+00f),
    GLINT_FLOAT4(-9.75029767e-01f, 3.11047006e+00f, -8.71749341e-01f, 3.03436756e+00f), GLINT_FLOAT4(-7.73509443e-01f, 2.96899748e+00f, -6.79531217e-01f, 2.91293335e+00f),
    GLINT_FLOAT4(-5.89121997e-01f, 2.86502743e+00f, -5.01668036e-01f, 2.82437134e+00f), GLINT_FLOAT4(-4.16623205e-01f, 2.79026556e+00f, -3.33496898e-01f, 2.76219058e+00f),
    GLINT_FLOAT4(-2.51841068e-01f, 2.73977828e+00f, -1.71236128e-01f, 2.72275972e+00f), GLINT_FLOAT4(-9.12710726e-02f, 2.71082950e+00f, -1.15063442e-02f, 2.70325851e+00f),
    GLINT_FLOAT4(6.84408993e-02f, 2.70030928e+00f, -4.72954273e+00f, 9.46295071e+00f), GLINT_FLOAT4(-4.62647247e+00f, 9.19148731e+00f, -4.52124119e+00f, 8.91925812e+00f),
    GLINT_FLOAT4(-4.41371059e+00f, 8.64619923e+00f, -4.30372858e+00f, 8.37224102e+00f), GLINT_FLOAT4(-4.19112587e+00f, 8.09730721e+00f, -4.07571411e+00f, 7.82131433e+00f),
    GLINT_FLOAT4(-3.95728469e+00f, 7.54417181e+00f, -3.83560514e+00f, 7.26578903e+00f), GLINT_FLOAT4(-3.71041751e+00f, 6.98607635e+00f, -3.58143878e+00f, 6.70496130e+00f),
    GLINT_FLOAT4(-3.44836307e+00f, 6.42240477e+00f, -3.31086922e+00f, 6.13843727e+00f), GLINT_FLOAT4(-3.16863918e+00f, 5.85321426e+00f, -3.02139449e+00f, 5.56710434e+00f),
    GLINT_FLOAT4(-2.86895943e+00f, 5.28082657e+00f, -2.71136832e+00f, 4.99563599e+00f), GLINT_FLOAT4(-2.54902244e+00f, 4.71355438e+00f, -2.38288188e+00f, 4.43757153e+00f),
    GLINT_FLOAT4(-2.21462750e+00f, 4.17167330e+00f, -2.04665899e+00f, 3.92049026e+00f), GLINT_FLOAT4(-1.88180184e+00f, 3.68849111e+00f, -1.72275376e+00f, 3.47897768e+00f),
    GLINT_FLOAT4(-1.57152832e+00f, 3.29340982e+00f, -1.42918074e+00f, 3.13139534e+00f), GLINT_FLOAT4(-1.29587817e+00f, 2.99121642e+00f, -1.17116559e+00f, 2.87049317e+00f),
    GLINT_FLOAT4(-1.05424869e+00f, 2.76670647e+00f, -9.44203973e-01f, 2.67750335e+00f), GLINT_FLOAT4(-8.40105951e-01f, 2.60082865e+00f, -7.41088748e-01f, 2.53495574e+00f),
    GLINT_FLOAT4(-6.46370411e-01f, 2.47846699e+00f, -5.55255353e-01f, 2.43021560e+00f), GLINT_FLOAT4(-4.67126966e-01f, 2.38928771e+00f, -3.81436497e-01f, 2.35496521e+00f),
    GLINT_FLOAT4(-2.97690421e-01f, 2.32669735e+00f, -2.15437666e-01f, 2.30407166e+00f), GLINT_FLOAT4(-1.34255737e-01f, 2.28677940e+00f, -5.37329018e-02f, 2.27454019e+00f),
    GLINT_FLOAT4(2.65486091e-02f, 2.26704454e+00f, 1.06962271e-01f, 2.26453161e+00f), GLINT_FLOAT4(-4.71471167e+00f, 9.10116386e+00f, -4.61134243e+00f, 8.82981014e+00f),
    GLINT_FLOAT4(-4.50579262e+00f, 8.55767155e+00f, -4.39792252e+00f, 8.28468513e+00f), GLINT_FLOAT4(-4.28757715e+00f, 8.01078129e+00f, -4.17458534e+00f, 7.73588371e+00f),
    GLINT_FLOAT4(-4.05875540e+00f, 7.45990849e+00f, -3.93987489e+00f, 7.18276739e+00f), GLINT_FLOAT4(-3.81770730e+00f, 6.90436935e+00f, -3.69198990e+00f, 6.62462616e+00f),
    GLINT_FLOAT4(-3.56243420e+00f, 6.34346581e+00f, -3.42872739e+00f, 6.06084919e+00f), GLINT_FLOAT4(-3.29054117e+00f, 5.77680540e+00f, -3.14754844e+00f, 5.49148703e+00f),
    GLINT_FLOAT4(-2.99946165e+00f, 5.20525694e+00f, -2.84609532e+00f, 4.91882420e+00f), GLINT_FLOAT4(-2.68747520e+00f, 4.63343000e+00f, -2.52399611e+00f, 4.35107851e+00f),
    GLINT_FLOAT4(-2.35661793e+00f, 4.07473898e+00f, -2.18703032e+00f, 3.80837917e+00f), GLINT_FLOAT4(-2.01765275e+00f, 3.55661964e+00f, -1.85133994e+00f, 3.32393289e+00f),
    GLINT_FLOAT4(-1.69082332e+00f, 3.11363935e+00f, -1.53814733e+00f, 2.92722678e+00f), GLINT_FLOAT4(-1.39438975e+00f, 2.76433516e+00f, -1.25973105e+00f, 2.62327576e+00f),
    GLINT_FLOAT4(-1.13372147e+00f, 2.50169253e+00f, -1.01556683e+00f, 2.39708519e+00f), GLINT_FLOAT4(-9.04340982e-01f, 2.30711389e+00f, -7.99114347e-01f, 2.22973299e+00f),
    GLINT_FLOAT4(-6.99016929e-01f, 2.16322279e+00f, -6.03262663e-01f, 2.10616899e+00f), GLINT_FLOAT4(-5.11152327e-01f, 2.05742574e+00f, -4.22066152e-01f, 2.01607656e+00f),
    GLINT_FLOAT4(-3.35452497e-01f, 1.98139632e+00f, -2.50815213e-01f, 1.95282173e+00f), GLINT_FLOAT4(-1.67700678e-01f, 1.92992353e+00f, -8.56838077e-02f, 1.91237581e+00f),
    GLINT_FLOAT4(-4.35072044e-03f, 1.89990485e+00f, 7.66895786e-02f, 1.89242804e+00f), GLINT_FLOAT4(1.57834455e-01f, 1.88994002e+00f, -4.69694662e+00f, 8.79496288e+00f),
    GLINT_FLOAT4(-4.59321737e+00f, 8.52367783e+00f, -4.48728514e+00f, 8.25160313e+00f), GLINT_FLOAT4(-4.37900734e+00f, 7.97867537e+00f, -4.26822662e+00f, 7.70482397e+00f),
    GLINT_FLOAT4(-4.15476799e+00f, 7.42997265e+00f, -4.03843689e+00f, 7.15403891e+00f), GLINT_FLOAT4(-3.91901660e+00f, 6.87693310e+00f, -3.79626465e+00f, 6.59856415e+00f),
    GLINT_FLOAT4(-3.66991329e+00f, 6.31884432e+00f, -3.53966641e+00f, 6.03769970e+00f), GLINT_FLOAT4(-3.40520358e+00f, 5.75508785e+00f, -3.26618648e+00f, 5.47103453e+00f),
    GLINT_FLOAT4(-3.12227774e+00f, 5.18568468e+00f, -2.97317743e+00f, 4.89938974e+00f), GLINT_FLOAT4(-2.81868720e+00f, 4.61284304e+00f, -2.65882063e+00f, 4.32726574e+00f),
    GLINT_FLOAT4(-2.49396348e+00f, 4.04463530e+00f, -2.32507277e+00f, 3.76789618e+00f), GLINT_FLOAT4(-2.15384603e+00f, 3.50099301e+00f, -1.98272467e+00f, 3.24853706e+00f),
    GLINT_FLOAT4(-1.81459785e+00f, 3.01500893e+00f, -1.65223777e+00f, 2.80375648e+00f), GLINT_FLOAT4(-1.49772727e+00f, 2.61630678e+00f, -1.35217333e+00f, 2.45234156e+00f),
    GLINT_FLOAT4(-1.21577394e+00f, 2.31020808e+00f, -1.08808720e+00f, 2.18757892e+00f), GLINT_FLOAT4(-9.68319952e-01f, 2.08197355e+00f, -8.55543673e-01f, 1.99106586e+00f),
    GLINT_FLOAT4(-7.48824239e-01f, 1.91281903e+00f, -6.47286892e-01f, 1.84551859e+00f), GLINT_FLOAT4(-5.50140977e-01f, 1.78775322e+00f, -4.56683010e-01f, 1.73837841e+00f),
    GLINT_FLOAT4(-3.66289794e-01f, 1.69647646e+00f, -2.78406739e-01f, 1.66131961e+00f), GLINT_FLOAT4(-1.92535073e-01f, 1.63233876e+00f, -1.08218670e-01f, 1.60909653e+00f),
    GLINT_FLOAT4(-2.50296853e-02f, 1.59125757e+00f, 5.74382022e-02f, 1.57859766e+00f), GLINT_FLOAT4(1.39574587e-01f, 1.57102597e+00f, 2.21783221e-01f, 1.56849360e+00f),
    GLINT_FLOAT4(-4.67675686e+00f, 8.53760242e+00f, -4.57261753e+00f, 8.26637745e+00f), GLINT_FLOAT4(-4.46624994e+00f, 7.99436188e+00f, -4.35750818e+00f, 7.72149229e+00f),
    GLINT_FLOAT4(-4.24623251e+00f, 7.44769907e+00f, -4.13224363e+00f, 7.17290592e+00f), GLINT_FLOAT4(-4.01534271e+00f, 6.89702988e+00f, -3.89530802e+00f, 6.61998177e+00f),
    GLINT_FLOAT4(-3.77189207e+00f, 6.34167004e+00f, -3.64481950e+00f, 6.06200552e+00f), GLINT_FLOAT4(-3.51378655e+00f, 5.78091240e+00f, -3.37846279e+00f, 5.49834633e+00f),
    GLINT_FLOAT4(-3.23849940e+00f, 5.21432495e+00f, -3.09354544e+00f, 4.92898560e+00f), GLINT_FLOAT4(-2.94328618e+00f, 4.64266682e+00f, -2.78750777e+00f, 4.35604239e+00f),
    GLINT_FLOAT4(-2.62620759e+00f, 4.07030821e+00f, -2.45975804e+00f, 3.78741169e+00f), GLINT_FLOAT4(-2.28911018e+00f, 3.51026416e+00f, -2.11596751e+00f, 3.24278283e+00f),
    GLINT_FLOAT4(-1.94279325e+00f, 2.98956490e+00f, -1.77251410e+00f, 2.75509953e+00f), GLINT_FLOAT4(-1.60794914e+00f, 2.54276490e+00f, -1.45122635e+00f, 2.35413313e+00f),
    GLINT_FLOAT4(-1.30348766e+00f, 2.18893480e+00f, -1.16495323e+00f, 2.04556060e+00f), GLINT_FLOAT4(-1.03519189e+00f, 1.92171609e+00f, -9.13412929e-01f, 1.81494486e+00f),
    GLINT_FLOAT4(-7.98685610e-01f, 1.72293663e+00f, -6.90071583e-01f, 1.64366555e+00f), GLINT_FLOAT4(-5.86690784e-01f, 1.57542324e+00f, -4.87747669e-01f, 1.51680279e+00f),
    GLINT_FLOAT4(-3.92534375e-01f, 1.46666181e+00f, -3.00423920e-01f, 1.42408311e+00f), GLINT_FLOAT4(-2.10858598e-01f, 1.38833809e+00f, -1.23337075e-01f, 1.35885525e+00f),
    GLINT_FLOAT4(-3.74005288e-02f, 1.33519197e+00f, 4.73780669e-02f, 1.31702042e+00f), GLINT_FLOAT4(1.31398484e-01f, 1.30413926e+00f, 2.15057671e-01f, 1.29642010e+00f),
    GLINT_FLOAT4(2.98752338e-01f, 1.29383636e+00f, -4.65483236e+00f, 8.32296944e+00f), GLINT_FLOAT4(-4.55024815e+00f, 8.05180454e+00f, -4.44340706e+00f, 7.77985048e+00f),
    GLINT_FLOAT4(-4.33416128e+00f, 7.50704432e+00f, -4.22234726e+00f, 7.23331690e+00f), GLINT_FLOAT4(-4.10778189e+00f, 6.95859241e+00f, -3.99026179e+00f, 6.68278790e+00f),
    GLINT_FLOAT4(-3.86955976e+00f, 6.40581465e+00f, -3.74542189e+00f, 6.12758017e+00f), GLINT_FLOAT4(-3.61756539e+00f, 5.84799480e+00f, -3.48567748e+00f, 5.56698084e+00f),
    GLINT_FLOAT4(-3.34941745e+00f, 5.28449011e+00f, -3.20842290e+00f, 5.00053596e+00f), GLINT_FLOAT4(-3.06232929e+00f, 4.71524572e+00f, -2.91080379e+00f, 4.42894363e+00f),
    GLINT_FLOAT4(-2.75361419e+00f, 4.14228439e+00f, -2.59073830e+00f, 3.85643649e+00f), GLINT_FLOAT4(-2.42253137e+00f, 3.57331395e+00f, -2.24993348e+00f, 3.29578972e+00f),
    GLINT_FLOAT4(-2.07465053e+00f, 3.02774787e+00f, -1.89916587e+00f, 2.77376533e+00f), GLINT_FLOAT4(-1.72644508e+00f, 2.53833532e+00f, -1.55935764e+00f, 2.32486486e+00f),
    GLINT_FLOAT4(-1.40008163e+00f, 2.13497329e+00f, -1.24979925e+00f, 1.96844387e+00f), GLINT_FLOAT4(-1.10875702e+00f, 1.82371461e+00f, -9.76536691e-01f, 1.69852984e+00f),
    GLINT_FLOAT4(-8.52351427e-01f, 1.59046078e+00f, -7.35268891e-01f, 1.49721718e+00f), GLINT_FLOAT4(-6.24346077e-01f, 1.41678643e+00f, -5.18697739e-01f, 1.34746945e+00f),
    GLINT_FLOAT4(-4.17522937e-01f, 1.28786540e+00f, -3.20109099e-01f, 1.23683631e+00f), GLINT_FLOAT4(-2.25825310e-01f, 1.19346762e+00f, -1.34110674e-01f, 1.15703154e+00f),
    GLINT_FLOAT4(-4.44608666e-02f, 1.12695575e+00f, 4.35839370e-02f, 1.10279989e+00f), GLINT_FLOAT4(1.30445883e-01f, 1.08425200e+00f, 2.16529518e-01f, 1.07109284e+00f),
    GLINT_FLOAT4(3.02227199e-01f, 1.06320345e+00f, 3.87930959e-01f, 1.06056225e+00f), GLINT_FLOAT4(-4.63190365e+00f, 8.14521885e+00f, -4.52685261e+00f, 7.87411594e+00f),
    GLINT_FLOAT4(-4.41951609e+00f, 7.60222673e+00f, -4.30974293e+00f, 7.32948971e+00f), GLINT_FLOAT4(-4.19736528e+00f, 7.05583525e+00f, -4.08219671e+00f, 6.78118801e+00f),
    GLINT_FLOAT4(-3.96402836e+00f, 6.50546503e+00f, -3.84262753e+00f, 6.22857857e+00f), GLINT_FLOAT4(-3.71773386e+00f, 5.95043564e+00f, -3.58905602e+00f, 5.67094707e+00f),
    GLINT_FLOAT4(-3.45627236e+00f, 5.39003229e+00f, -3.31903028e+00f, 5.10764122e+00f), GLINT_FLOAT4(-3.17695427e+00f, 4.82378292e+00f, -3.02966309e+00f, 4.53857517e+00f),
    GLINT_FLOAT4(-2.87680554e+00f, 4.25233126e+00f, -2.71812797e+00f, 3.96568584e+00f), GLINT_FLOAT4(-2.55358553e+00f, 3.67978096e+00f, -2.38351202e+00f, 3.39649582e+00f),
    GLINT_FLOAT4(-2.20883274e+00f, 3.11866379e+00f, -2.03125095e+00f, 2.85013008e+00f), GLINT_FLOAT4(-1.85326695e+00f, 2.59544563e+00f, -1.67788410e+00f, 2.35910058e+00f),
    GLINT_FLOAT4(-1.50802314e+00f, 2.14452505e+00f, -1.34591603e+00f, 1.95338225e+00f), GLINT_FLOAT4(-1.19278908e+00f, 1.78550732e+00f, -1.04891753e+00f, 1.63938773e+00f),
    GLINT_FLOAT4(-9.13898349e-01f, 1.51280844e+00f, -7.86948979e-01f, 1.40337205e+00f), GLINT_FLOAT4(-6.67135239e-01f, 1.30881131e+00f, -5.53509057e-01f, 1.22713065e+00f),
    GLINT_FLOAT4(-4.45179075e-01f, 1.15664351e+00f, -3.41338217e-01f, 1.09595835e+00f), GLINT_FLOAT4(-2.41268620e-01f, 1.04394436e+00f, -1.44334808e-01f, 9.99692142e-01f),
    GLINT_FLOAT4(-4.99719977e-02f, 9.62477267e-01f, 4.23264913e-02f, 9.31730926e-01f), GLINT_FLOAT4(1.33017749e-01f, 9.07024860e-01f, 2.22527400e-01f, 8.88040304e-01f),
    GLINT_FLOAT4(3.11256796e-01f, 8.74564648e-01f, 3.99594486e-01f, 8.66483510e-01f), GLINT_FLOAT4(4.87927794e-01f, 8.63777816e-01f, -4.60860634e+00f, 7.99865770e+00f),
    GLINT_FLOAT4(-4.50308084e+00f, 7.72761774e+00f, -4.39524031e+00f, 7.45579624e+00f), GLINT_FLOAT4(-4.28493023e+00f, 7.18313026e+00f, -4.17197895e+00f, 6.90955162e+00f),
    GLINT_FLOAT4(-4.05619574e+00f, 6.63498545e+00f, -3.93736768e+00f, 6.35934973e+00f), GLINT_FLOAT4(-3.81525540e+00f, 6.08255577e+00f, -3.68959165e+00f, 5.80451250e+00f),
    GLINT_FLOAT4(-3.56007743e+00f, 5.52512884e+00f, -3.42638087e+00f, 5.24432516e+00f), GLINT_FLOAT4(-3.28813744e+00f, 4.96204853e+00f, -3.14495778e+00f, 4.67830420e+00f),
    GLINT_FLOAT4(-2.99644375e+00f, 4.39320517e+00f, -2.84222412e+00f, 4.10705233e+00f), GLINT_FLOAT4(-2.68202209e+00f, 3.82046556e+00f, -2.51576805e+00f, 3.53456187e+00f),
    GLINT_FLOAT4(-2.34377098e+00f, 3.25118876e+00f, -2.16693711e+00f, 2.97314095e+00f), GLINT_FLOAT4(-1.98696268e+00f, 2.70422339e+00f, -1.80636060e+00f, 2.44895673e+00f),
    GLINT_FLOAT4(-1.62816882e+00f, 2.21181989e+00f, -1.45535970e+00f, 1.99625838e+00f), GLINT_FLOAT4(-1.29022014e+00f, 1.80397069e+00f, -1.13402283e+00f, 1.63483787e+00f),
    GLINT_FLOAT4(-9.87073720e-01f, 1.48739302e+00f, -8.48985016e-01f, 1.35946083e+00f), GLINT_FLOAT4(-7.18978167e-01f, 1.24867570e+00f, -5.96115649e-01f, 1.15279543e+00f),
    GLINT_FLOAT4(-4.79442567e-01f, 1.06984401e+00f, -3.68059337e-01f, 9.98150766e-01f), GLINT_FLOAT4(-2.61151105e-01f, 9.36337233e-01f, -1.57992899e-01f, 8.83283079e-01f),
    GLINT_FLOAT4(-5.79430722e-02f, 8.38087440e-01f, 3.95678580e-02f, 8.00033450e-01f), GLINT_FLOAT4(1.35046542e-01f, 7.68564999e-01f, 2.28953943e-01f, 7.43254483e-01f),
    GLINT_FLOAT4(3.21714222e-01f, 7.23791182e-01f, 4.13726240e-01f, 7.09968388e-01f), GLINT_FLOAT4(5.05374789e-01f, 7.01676130e-01f, 5.97041368e-01f, 6.98899269e-01f),
    GLINT_FLOAT4(-4.58539724e+00f, 7.87778282e+00f, -4.47939777e+00f, 7.60680389e+00f), GLINT_FLOAT4(-4.37105322e+00f, 7.33504677e+00f, -4.26020622e+00f, 7.06244946e+00f),
    GLINT_FLOAT4(-4.14668179e+00f, 6.78894472e+00f, -4.03028488e+00f, 6.51445770e+00f), GLINT_FLOAT4(-3.91079664e+00f, 6.23890638e+00f, -3.78797293e+00f, 5.96220303e+00f),
    GLINT_FLOAT4(-3.66153884e+00f, 5.68425703e+00f, -3.53118706e+00f, 5.40497732e+00f), GLINT_FLOAT4(-3.39657617e+00f, 5.12428379e+00f, -3.25732946e+00f, 4.84212303e+00f),
    GLINT_FLOAT4(-3.11304331e+00f, 4.55849791e+00f, -2.96330190e+00f, 4.27351618e+00f), GLINT_FLOAT4(-2.80771399e+00f, 3.98747206e+00f, -2.64597845e+00f, 3.70097160e+00f),
    GLINT_FLOAT4(-2.47799921e+00f, 3.41511416e+00f, -2.30405855e+00f, 3.13172007e+00f), GLINT_FLOAT4(-2.12504029e+00f, 2.85354996e+00f, -1.94262934e+00f, 2.58437324e+00f),
    GLINT_FLOAT4(-1.75934720e+00f, 2.32867932e+00f, -1.57826364e+00f, 2.09093142e+00f), GLINT_FLOAT4(-1.40240097e+00f, 1.87458098e+00f, -1.23410165e+00f, 1.68135095e+00f),
    GLINT_FLOAT4(-1.07468534e+00f, 1.51115656e+00f, -9.24489856e-01f, 1.36256719e+00f), GLINT_FLOAT4(-7.83141911e-01f, 1.23343992e+00f, -6.49864852e-01f, 1.12143719e+00f),
    GLINT_FLOAT4(-5.23714840e-01f, 1.02434003e+00f, -4.03726488e-01f, 9.40192699e-01f), GLINT_FLOAT4(-2.88988441e-01f, 8.67342472e-01f, -1.78674147e-01f, 8.04426789e-01f),
    GLINT_FLOAT4(-7.20480084e-02f, 7.50339568e-01f, 3.15407552e-02f, 7.04192698e-01f), GLINT_FLOAT4(1.32666111e-01f, 6.65285707e-01f, 2.31841281e-01f, 6.33070409e-01f),
    GLINT_FLOAT4(3.29529077e-01f, 6.07130945e-01f, 4.26153868e-01f, 5.87166309e-01f), GLINT_FLOAT4(5.22112966e-01f, 5.72977781e-01f, 6.17787361e-01f, 5.64462066e-01f),
    GLINT_FLOAT4(7.13552296e-01f, 5.61609745e-01f, -4.56252146e+00f, 7.77738333e+00f), GLINT_FLOAT4(-4.45605278e+00f, 7.50645781e+00f, -4.34720898e+00f, 7.23475695e+00f),
    GLINT_FLOAT4(-4.23583031e+00f, 6.96221972e+00f, -4.12173796e+00f, 6.68877935e+00f), GLINT_FLOAT4(-4.00473213e+00f, 6.41436005e+00f, -3.88458920e+00f, 6.13888168e+00f),
    GLINT_FLOAT4(-3.76105881e+00f, 5.86225700e+00f, -3.63385963e+00f, 5.58439445e+00f), GLINT_FLOAT4(-3.50267577e+00f, 5.30520439e+00f, -3.36715531e+00f, 5.02460623e+00f),
    GLINT_FLOAT4(-3.22691035e+00f, 4.74254560e+00f, -3.08152199e+00f, 4.45902443e+00f), GLINT_FLOAT4(-2.93055701e+00f, 4.17414761e+00f, -2.77360344e+00f, 3.88820434e+00f),
    GLINT_FLOAT4(-2.61033583e+00f, 3.60179234e+00f, -2.44063044e+00f, 3.31599784e+00f), GLINT_FLOAT4(-2.26474190e+00f, 3.03262234e+00f, -2.08352900e+00f, 2.75440264e+00f),
    GLINT_FLOAT4(-1.89866388e+00f, 2.48508024e+00f, -1.71267343e+00f, 2.22912025e+00f), GLINT_FLOAT4(-1.52865624e+00f, 1.99097133e+00f, -1.34968340e+00f, 1.77408445e+00f),
    GLINT_FLOAT4(-1.17815316e+00f, 1.58019483e+00f, -1.01543343e+00f, 1.40923738e+00f), GLINT_FLOAT4(-8.61893117e-01f, 1.25980210e+00f, -7.17172623e-01f, 1.12976515e+00f),
    GLINT_FLOAT4(-5.80494106e-01f, 1.01680624e+00f, -4.50902671e-01f, 9.18722808e-01f), GLINT_FLOAT4(-3.27417135e-01f, 8.33575785e-01f, -2.09108219e-01f, 7.59729087e-01f),
    GLINT_FLOAT4(-9.51317325e-02f, 6.95837259e-01f, 1.52645269e-02f, 6.40811205e-01f), GLINT_FLOAT4(1.22743480e-01f, 5.93782961e-01f, 2.27891475e-01f, 5.54067254e-01f),
    GLINT_FLOAT4(3.31229866e-01f, 5.21133006e-01f, 4.33227003e-01f, 4.94579941e-01f), GLINT_FLOAT4(5.34310460e-01f, 4.74120617e-01f, 6.34878039e-01f, 4.59568113e-01f),
    GLINT_FLOAT4(7.35308349e-01f, 4.50828850e-01f, 8.35971057e-01f, 4.47900742e-01f), GLINT_FLOAT4(-4.54003382e+00f, 7.69265556e+00f, -4.43309975e+00f, 7.42176867e+00f),
    GLINT_FLOAT4(-4.32376194e+00f, 7.15010834e+00f, -4.21185589e+00f, 6.87761402e+00f), GLINT_FLOAT4(-4.09719944e+00f, 6.60421896e+00f, -3.97958899e+00f, 6.32984781e+00f),
    GLINT_FLOAT4(-3.85879564e+00f, 6.05442047e+00f, -3.73456287e+00f, 5.77784967e+00f), GLINT_FLOAT4(-3.60660219e+00f, 5.50004387e+00f, -3.47458935e+00f, 5.22091389e+00f),
    GLINT_FLOAT4(-3.33816195e+00f, 4.94037819e+00f, -3.19692016e+00f, 4.65838337e+00f), GLINT_FLOAT4(-3.05043006e+00f, 4.37492895e+00f, -2.89824080e+00f, 4.09011841e+00f),
    GLINT_FLOAT4(-2.73991895e+00f, 3.80423903e+00f, -2.57511401e+00f, 3.51788354e+00f), GLINT_FLOAT4(-2.40367484e+00f, 3.23213100e+00f, -2.22582746e+00f, 2.94877362e+00f),
    GLINT_FLOAT4(-2.04240584e+00f, 2.67053604e+00f, -1.85506773e+00f, 2.40114689e+00f), GLINT_FLOAT4(-1.66634476e+00f, 2.14506006e+00f, -1.47936416e+00f, 1.90671778e+00f),
    GLINT_FLOAT4(-1.29724598e+00f, 1.68957102e+00f, -1.12244439e+00f, 1.49535859e+00f), GLINT_FLOAT4(-9.56376374e-01f, 1.32401860e+00f, -7.99442649e-01f, 1.17414236e+00f),
    GLINT_FLOAT4(-6.51295364e-01f, 1.04360569e+00f, -5.11151731e-01f, 9.30088401e-01f), GLINT_FLOAT4(-3.78040612e-01f, 8.31390858e-01f, -2.50957787e-01f, 7.45580494e-01f),
    GLINT_FLOAT4(-1.28948271e-01f, 6.71032310e-01f, -1.11415796e-02f, 6.06415093e-01f), GLINT_FLOAT4(1.03237629e-01f, 5.50659120e-01f, 2.14874074e-01f, 5.02916157e-01f),
    GLINT_FLOAT4(3.24372530e-01f, 4.62522119e-01f, 4.32268977e-01f, 4.28967655e-01f), GLINT_FLOAT4(5.39043486e-01f, 4.01872844e-01f, 6.45131767e-01f, 3.80968720e-01f),
    GLINT_FLOAT4(7.50936568e-01f, 3.66084516e-01f, 8.56837809e-01f, 3.57139707e-01f), GLINT_FLOAT4(9.63202894e-01f, 3.54141623e-01f, -4.51784182e+00f, 7.61929655e+00f),
    GLINT_FLOAT4(-4.41044378e+00f, 7.34842587e+00f, -4.30061197e+00f, 7.07678270e+00f), GLINT_FLOAT4(-4.18817902e+00f, 6.80430555e+00f, -4.07295847e+00f, 6.53092718e+00f),
    GLINT_FLOAT4(-3.95474219e+00f, 6.25657368e+00f, -3.83329654e+00f, 5.98116302e+00f), GLINT_FLOAT4(-3.70835876e+00f, 5.70460796e+00f, -3.57963276e+00f, 5.42681789e+00f),
    GLINT_FLOAT4(-3.44678545e+00f, 5.14770174e+00f, -3.30944443e+00f, 4.86717892e+00f), GLINT_FLOAT4(-3.16719651e+00f, 4.58519363e+00f, -3.01959252e+00f, 4.30174494e+00f),
    GLINT_FLOAT4(-2.86616349e+00f, 4.01693630e+00f, -2.70645332e+00f, 3.73105192e+00f), GLINT_FLOAT4(-2.54008675e+00f, 3.44468427e+00f, -2.36688399e+00f, 3.15891123e+00f),
    GLINT_FLOAT4(-2.18704224e+00f, 2.87552500e+00f, -2.00137115e+00f, 2.59725237e+00f), GLINT_FLOAT4(-1.81151521e+00f, 2.32782698e+00f, -1.62001312e+00f, 2.07171106e+00f),
    GLINT_FLOAT4(-1.43002331e+00f, 1.83335733e+00f, -1.24471688e+00f, 1.61622381e+00f), GLINT_FLOAT4(-1.06660652e+00f, 1.42204881e+00f, -8.97159517e-01f, 1.25075996e+00f),
    GLINT_FLOAT4(-7.36807883e-01f, 1.10092926e+00f, -5.85213959e-01f, 9.70408797e-01f), GLINT_FLOAT4(-4.41586316e-01f, 8.56856167e-01f, -3.04931700e-01f, 7.58054733e-01f),
    GLINT_FLOAT4(-1.74215198e-01f, 6.72062516e-01f, -4.84469794e-02f, 5.97253442e-01f), GLINT_FLOAT4(7.32788369e-02f, 5.32303870e-01f, 1.91771045e-01f, 4.76159066e-01f),
    GLINT_FLOAT4(3.07746381e-01f, 4.27989542e-01f, 4.21837121e-01f, 3.87154907e-01f), GLINT_FLOAT4(5.34603477e-01f, 3.53170395e-01f, 6.46545708e-01f, 3.25680792e-01f),
    GLINT_FLOAT4(7.58115947e-01f, 3.04440409e-01f, 8.69729042e-01f, 2.89298743e-01f), GLINT_FLOAT4(9.81773496e-01f, 2.80191690e-01f, 1.09462118e+00f, 2.77137876e-01f),
    GLINT_FLOAT4(-4.49576473e+00f, 7.55358219e+00f, -4.38789797e+00f, 7.28269863e+00f), GLINT_FLOAT4(-4.27756643e+00f, 7.01104021e+00f, -4.16459942e+00f, 6.73854542e+00f),
    GLINT_FLOAT4(-4.04880714e+00f, 6.46514654e+00f, -3.92997670e+00f, 6.19076824e+00f), GLINT_FLOAT4(-3.80786848e+00f, 5.91532850e+00f, -3.68221307e+00f, 5.63874006e+00f),
    GLINT_FLOAT4(-3.55270696e+00f, 5.36090994e+00f, -3.41900802e+00f, 5.08174706e+00f), GLINT_FLOAT4(-3.28073215e+00f, 4.80116796e+00f, -3.13745284e+00f, 4.51911736e+00f),
    GLINT_FLOAT4(-2.98870492e+00f, 4.23559189e+00f, -2.83399963e+00f, 3.95069361e+00f), GLINT_FLOAT4(-2.67285776e+00f, 3.66470718e+00f, -2.50487709e+00f, 3.37822556e+00f),
    GLINT_FLOAT4(-2.32984877e+00f, 3.09233141e+00f, -2.14794064e+00f, 2.80882668e+00f), GLINT_FLOAT4(-1.95993876e+00f, 2.53045487e+00f, -1.76747763e+00f, 2.26097560e+00f),
    GLINT_FLOAT4(-1.57310760e+00f, 2.00488377e+00f, -1.38002455e+00f, 1.76666462e+00f), GLINT_FLOAT4(-1.19145691e+00f, 1.54979658e+00f, -1.00998020e+00f, 1.35601914e+00f),
    GLINT_FLOAT4(-8.37113321e-01f, 1.18523812e+00f, -6.73319638e-01f, 1.03598678e+00f), GLINT_FLOAT4(-5.18268764e-01f, 9.06070054e-01f, -3.71156693e-01f, 7.93098688e-01f),
    GLINT_FLOAT4(-2.30961949e-01f, 6.94816113e-01f, -9.66115966e-02f, 6.09250546e-01f), GLINT_FLOAT4(3.29281129e-02f, 5.34757555e-01f, 1.58607140e-01f, 4.70009357e-01f),
    GLINT_FLOAT4(2.81279922e-01f, 4.13955182e-01f, 4.01705027e-01f, 3.65780205e-01f), GLINT_FLOAT4(5.20553946e-01f, 3.24864656e-01f, 6.38422251e-01f, 2.90748447e-01f),
    GLINT_FLOAT4(7.55841434e-01f, 2.63102919e-01f, 8.73290896e-01f, 2.41708145e-01f), GLINT_FLOAT4(9.91208851e-01f, 2.26436839e-01f, 1.11000323e+00f, 2.17243478e-01f),
    GLINT_FLOAT4(1.23006165e+00f, 2.14159310e-01f, -4.47358942e+00f, 7.49243498e+00f), GLINT_FLOAT4(-4.36524248e+00f, 7.22150278e+00f, -4.25439882e+00f, 6.94979095e+00f),
    GLINT_FLOAT4(-4.14088440e+00f, 6.67723656e+00f, -4.02450514e+00f, 6.40377140e+00f), GLINT_FLOAT4(-3.90504241e+00f, 6.12931919e+00f, -3.78225136e+00f, 5.85379648e+00f),
    GLINT_FLOAT4(-3.65585566e+00f, 5.57711458e+00f, -3.52554297e+00f, 5.29917860e+00f), GLINT_FLOAT4(-3.39096165e+00f, 5.01989508e+00f, -3.25171542e+00f, 4.73918009e+00f),
    GLINT_FLOAT4(-3.10736299e+00f, 4.45697403e+00f, -2.95742178e+00f, 4.17327309e+00f), GLINT_FLOAT4(-2.80138206e+00f, 3.88817716e+00f, -2.63873935e+00f, 3.60197115e+00f),
    GLINT_FLOAT4(-2.46906328e+00f, 3.31525159e+00f, -2.29211354e+00f, 3.02911091e+00f), GLINT_FLOAT4(-2.10802841e+00f, 2.74536967e+00f, -1.91757095e+00f, 2.46680403e+00f),
    GLINT_FLOAT4(-1.72236931e+00f, 2.19722104e+00f, -1.52499270e+00f, 1.94117427e+00f), GLINT_FLOAT4(-1.32868397e+00f, 1.70320570e+00f, -1.13673878e+00f, 1.48683167e+00f),
    GLINT_FLOAT4(-9.51801777e-01f, 1.29379606e+00f, -7.75446773e-01f, 1.12397456e+00f), GLINT_FLOAT4(-6.08166635e-01f, 9.75844443e-01f, -4.49635088e-01f, 8.47142816e-01f),
    GLINT_FLOAT4(-2.99030066e-01f, 7.35411465e-01f, -1.55296177e-01f, 6.38331950e-01f), GLINT_FLOAT4(-1.73152462e-02f, 5.53881824e-01f, 1.15996867e-01f, 4.80380863e-01f),
    GLINT_FLOAT4(2.45644256e-01f, 4.16478574e-01f, 3.72535259e-01f, 3.61115664e-01f), GLINT_FLOAT4(4.97481078e-01f, 3.13480288e-01f, 6.21203303e-01f, 2.72965074e-01f),
    GLINT_FLOAT4(7.44344413e-01f, 2.39129290e-01f, 8.67479444e-01f, 2.11667314e-01f), GLINT_FLOAT4(9.91128087e-01f, 1.90383464e-01f, 1.11576593e+00f, 1.75172776e-01f),
    GLINT_FLOAT4(1.24183571e+00f, 1.66007876e-01f, 1.36975753e+00f, 1.62931845e-01f), GLINT_FLOAT4(-4.45112276e+00f, 7.43348885e+00f, -4.34227991e+00f, 7.16247082e+00f),
    GLINT_FLOAT4(-4.23090649e+00f, 6.89066458e+00f, -4.11682463e+00f, 6.61800671e+00f), GLINT_FLOAT4(-3.99983597e+00f, 6.34442711e+00f, -3.87971616e+00f, 6.06984854e+00f),
    GLINT_FLOAT4(-3.75621438e+00f, 5.79418612e+00f, -3.62904644e+00f, 5.51734734e+00f), GLINT_FLOAT4(-3.49789143e+00f, 5.23923683e+00f, -3.36238623e+00f, 4.95975733e+00f),
    GLINT_FLOAT4(-3.22212195e+00f, 4.67882156e+00f, -3.07664132e+00f, 4.39636803e+00f), GLINT_FLOAT4(-2.92544246e+00f, 4.11238956e+00f, -2.76799273e+00f, 3.82698441e+00f),
    GLINT_FLOAT4(-2.60376096e+00f, 3.54043865e+00f, -2.43228507e+00f, 3.25335503e+00f), GLINT_FLOAT4(-2.25329232e+00f, 2.96684003e+00f, -2.06688952e+00f, 2.68274283e+00f),
    GLINT_FLOAT4(-1.87381768e+00f, 2.40388680e+00f, -1.67570210e+00f, 2.13414693e+00f), GLINT_FLOAT4(-1.47513878e+00f, 1.87815976e+00f, -1.27542865e+00f, 1.64054728e+00f),
    GLINT_FLOAT4(-1.07994556e+00f, 1.42487848e+00f, -8.91412735e-01f, 1.23290479e+00f), GLINT_FLOAT4(-7.11461782e-01f, 1.06446397e+00f, -5.40614009e-01f, 9.17963564e-01f),
    GLINT_FLOAT4(-3.78542304e-01f, 7.91056275e-01f, -2.24401072e-01f, 6.81199074e-01f), GLINT_FLOAT4(-7.70947933e-02f, 5.85995972e-01f, 6.45453855e-02f, 5.03358483e-01f),
    GLINT_FLOAT4(2.01659471e-01f, 4.31555182e-01f, 3.35311949e-01f, 3.69196326e-01f), GLINT_FLOAT4(4.66471553e-01f, 3.15197885e-01f, 5.96009851e-01f, 2.68735409e-01f),
    GLINT_FLOAT4(7.24707067e-01f, 2.29199588e-01f, 8.53262544e-01f, 1.96156293e-01f), GLINT_FLOAT4(9.82306480e-01f, 1.69312403e-01f, 1.11241221e+00f, 1.48487538e-01f),
    GLINT_FLOAT4(1.24410868e+00f, 1.33592114e-01f, 1.37789202e+00f, 1.24611430e-01f), GLINT_FLOAT4(1.51423764e+00f, 1.21596195e-01f, -4.42823744e+00f, 7.37513590e+00f),
    GLINT_FLOAT4(-4.31887913e+00f, 7.10399723e+00f, -4.20695496e+00f, 6.83205938e+00f), GLINT_FLOAT4(-4.09228230e+00f, 6.55925751e+00f, -3.97465825e+00f, 6.28552055e+00f),
    GLINT_FLOAT4(-3.85385299e+00f, 6.01076794e+00f, -3.72960806e+00f, 5.73491335e+00f), GLINT_FLOAT4(-3.60163188e+00f, 5.45786190e+00f, -3.46959329e+00f, 5.17951441e+00f),
    GLINT_FLOAT4(-3.33311749e+00f, 4.89977121e+00f, -3.19178152e+00f, 4.61854124e+00f), GLINT_FLOAT4(-3.04511094e+00f, 4.33575869e+00f, -2.89258313e+00f, 4.05141449e+00f),
    GLINT_FLOAT4(-2.73364019e+00f, 3.76560450e+00f, -2.56772161e+00f, 3.47861791e+00f), GLINT_FLOAT4(-2.39433217e+00f, 3.19106555e+00f, -2.21316385e+00f, 2.90407372e+00f),
    GLINT_FLOAT4(-2.02429008e+00f, 2.61952901e+00f, -1.82843006e+00f, 2.34031510e+00f), GLINT_FLOAT4(-1.62720978e+00f, 2.07039309e+00f, -1.42325854e+00f, 1.81450260e+00f),
    GLINT_FLOAT4(-1.21994555e+00f, 1.57736242e+00f, -1.02073419e+00f, 1.36260390e+00f), GLINT_FLOAT4(-8.28434050e-01f, 1.17198551e+00f, -6.44738019e-01f, 1.00529861e+00f),
    GLINT_FLOAT4(-4.70193893e-01f, 8.60868871e-01f, -3.04469228e-01f, 7.36253500e-01f), GLINT_FLOAT4(-1.46688789e-01f, 6.28816247e-01f, 4.28835675e-03f, 5.36076903e-01f),
    GLINT_FLOAT4(1.49684474e-01f, 4.55876291e-01f, 2.90699393e-01f, 3.86422276e-01f), GLINT_FLOAT4(4.28459287e-01f, 3.26276302e-01f, 5.63996136e-01f, 2.74315208e-01f),
    GLINT_FLOAT4(6.98244929e-01f, 2.29684889e-01f, 8.32049072e-01f, 1.91755250e-01f), GLINT_FLOAT4(9.66171026e-01f, 1.60079136e-01f, 1.10130465e+00f, 1.34356618e-01f),
    GLINT_FLOAT4(1.23808908e+00f, 1.14404842e-01f, 1.37712193e+00f, 1.00134008e-01f), GLINT_FLOAT4(1.51897442e+00f, 9.15294439e-02f, 1.66420376e+00f, 8.86403546e-02f),
    GLINT_FLOAT4(-4.40489101e+00f, 7.31649780e+00f, -4.29499769e+00f, 7.04521132e+00f), GLINT_FLOAT4(-4.18250132e+00f, 6.77311277e+00f, -4.06721497e+00f, 6.50013638e+00f),
    GLINT_FLOAT4(-3.94892979e+00f, 6.22620773e+00f, -3.82741022e+00f, 5.95124531e+00f), GLINT_FLOAT4(-3.70239043e+00f, 5.67515898e+00f, -3.57356977e+00f, 5.39785242e+00f),
    GLINT_FLOAT4(-3.44060707e+00f, 5.11922216e+00f, -3.30311513e+00f, 4.83916521e+00f), GLINT_FLOAT4(-3.16065502e+00f, 4.55758667e+00f, -3.01273394e+00f, 4.27441645e+00f),
    GLINT_FLOAT4(-2.85880733e+00f, 3.98964310e+00f, -2.69828987e+00f, 3.70336246e+00f), GLINT_FLOAT4(-2.53058982e+00f, 3.41586614e+00f, -2.35517597e+00f, 3.12777710e+00f),
    GLINT_FLOAT4(-2.17170262e+00f, 2.84024668e+00f, -1.98020864e+00f, 2.55520678e+00f), GLINT_FLOAT4(-1.78139091e+00f, 2.27561307e+00f, -1.57687807e+00f, 2.00552750e+00f),
    GLINT_FLOAT4(-1.36933839e+00f, 1.74980736e+00f, -1.16221750e+00f, 1.51328003e+00f), GLINT_FLOAT4(-9.59076822e-01f, 1.29964185e+00f, -7.62818396e-01f, 1.11065280e+00f),
    GLINT_FLOAT4(-5.75197399e-01f, 9.46045995e-01f, -3.96785051e-01f, 8.04052949e-01f), GLINT_FLOAT4(-2.27237433e-01f, 6.82127357e-01f, -6.56436756e-02f, 5.77536523e-01f),
    GLINT_FLOAT4(8.91864821e-02f, 4.87718165e-01f, 2.38530159e-01f, 4.10446197e-01f), GLINT_FLOAT4(3.83645505e-01f, 3.43870848e-01f, 5.25717556e-01f, 2.86503464e-01f),
    GLINT_FLOAT4(6.65838182e-01f, 2.37174511e-01f, 8.05002749e-01f, 1.94986686e-01f), GLINT_FLOAT4(9.44116533e-01f, 1.59269691e-01f, 1.08400619e+00f, 1.29539475e-01f),
    GLINT_FLOAT4(1.22543335e+00f, 1.05463006e-01f, 1.36911118e+00f, 8.68284479e-02f), GLINT_FLOAT4(1.51572084e+00f, 7.35212639e-02f, 1.66592932e+00f, 6.55062869e-02f),
    GLINT_FLOAT4(1.82040560e+00f, 6.28165975e-02f, -4.38112164e+00f, 7.25728178e+00f), GLINT_FLOAT4(-4.27067661e+00f, 6.98583031e+00f, -4.15758896e+00f, 6.71355247e+00f),
    GLINT_FLOAT4(-4.04166794e+00f, 6.44038105e+00f, -3.92269850e+00f, 6.16623974e+00f), GLINT_FLOAT4(-3.80043888e+00f, 5.89104414e+00f, -3.67461562e+00f, 5.61470222e+00f),
    GLINT_FLOAT4(-3.54491878e+00f, 5.33711386e+00f, -3.41099572e+00f, 5.05817175e+00f), GLINT_FLOAT4(-3.27244616e+00f, 4.77777004e+00f, -3.12881470e+00f, 4.49580860e+00f),
    GLINT_FLOAT4(-2.97958922e+00f, 4.21221590e+00f, -2.82420063e+00f, 3.92697573e+00f), GLINT_FLOAT4(-2.66203547e+00f, 3.64018536e+00f, -2.49246788e+00f, 3.35214138e+00f),
    GLINT_FLOAT4(-2.31492925e+00f, 3.06348157e+00f, -2.12903285e+00f, 2.77538705e+00f), GLINT_FLOAT4(-1.93478155e+00f, 2.48984218e+00f, -1.73284936e+00f, 2.20988560e+00f),
    GLINT_FLOAT4(-1.52486920e+00f, 1.93969262e+00f, -1.31355286e+00f, 1.68425024e+00f), GLINT_FLOAT4(-1.10242927e+00f, 1.44850135e+00f, -8.95164132e-01f, 1.23620605e+00f),
    GLINT_FLOAT4(-6.94754601e-01f, 1.04911458e+00f, -5.03016531e-01f, 8.86886179e-01f), GLINT_FLOAT4(-3.20537835e-01f, 7.47643709e-01f, -1.46954685e-01f, 6.28727853e-01f),
    GLINT_FLOAT4(1.86875742e-02f, 5.27307332e-01f, 1.77631766e-01f, 4.40744609e-01f), GLINT_FLOAT4(3.31210881e-01f, 3.66754889e-01f, 4.80735809e-01f, 3.03442776e-01f),
    GLINT_FLOAT4(6.27442122e-01f, 2.49277204e-01f, 7.72470772e-01f, 2.03044564e-01f), GLINT_FLOAT4(9.16867197e-01f, 1.63798243e-01f, 1.06158984e+00f, 1.30812749e-01f),
    GLINT_FLOAT4(1.20752370e+00f, 1.03544369e-01f, 1.35549748e+00f, 8.15984607e-02f), GLINT_FLOAT4(1.50630295e+00f, 6.47030771e-02f, 1.66071606e+00f, 5.26886210e-02f),
    GLINT_FLOAT4(1.81951952e+00f, 4.54734452e-02f, 1.98352492e+00f, 4.30558026e-02f), GLINT_FLOAT4(-4.35701895e+00f, 7.19755983e+00f, -4.24600744e+00f, 6.92593336e+00f),
    GLINT_FLOAT4(-4.13231373e+00f, 6.65346622e+00f, -4.01574039e+00f, 6.38008881e+00f), GLINT_FLOAT4(-3.89606762e+00f, 6.10572243e+00f, -3.77304649e+00f, 5.83028078e+00f),
    GLINT_FLOAT4(-3.64639568e+00f, 5.55366898e+00f, -3.51579523e+00f, 5.27578259e+00f), GLINT_FLOAT4(-3.38088131e+00f, 4.99651289e+00f, -3.24123859e+00f, 4.71574783e+00f),
    GLINT_FLOAT4(-3.09639549e+00f, 4.43338490e+00f, -2.94581819e+00f, 4.14934826e+00f), GLINT_FLOAT4(-2.78891253e+00f, 3.86362076e+00f, -2.62503481e+00f, 3.57629967e+00f),
    GLINT_FLOAT4(-2.45352364e+00f, 3.28768921e+00f, -2.27376938e+00f, 2.99844408e+00f), GLINT_FLOAT4(-2.08534312e+00f, 2.70978069e+00f, -1.88820982e+00f, 2.42374372e+00f),
    GLINT_FLOAT4(-1.68301952e+00f, 2.14346480e+00f, -1.47141159e+00f, 1.87324440e+00f), GLINT_FLOAT4(-1.25614572e+00f, 1.61821079e+00f, -1.04083955e+00f, 1.38342702e+00f),
    GLINT_FLOAT4(-8.29268038e-01f, 1.17271173e+00f, -6.24523878e-01f, 9.87790942e-01f), GLINT_FLOAT4(-4.28477764e-01f, 8.28230560e-01f, -2.41724670e-01f, 6.92027569e-01f),
    GLINT_FLOAT4(-6.38690293e-02f, 5.76398671e-01f, 1.06097035e-01f, 4.78411704e-01f), GLINT_FLOAT4(2.69474924e-01f, 3.95357907e-01f, 4.27652597e-01f, 3.24904531e-01f),
    GLINT_FLOAT4(5.81987202e-01f, 2.65122592e-01f, 7.33752191e-01f, 2.14450836e-01f), GLINT_FLOAT4(8.84121120e-01f, 1.71639577e-01f, 1.03417134e+00f, 1.35694161e-01f),
    GLINT_FLOAT4(1.18489802e+00f, 1.05826385e-01f, 1.33723235e+00f, 8.14163834e-02f), GLINT_FLOAT4(1.49206340e+00f, 6.19841255e-02f, 1.65026259e+00f, 4.71693501e-02f),
    GLINT_FLOAT4(1.81271017e+00f, 3.67185771e-02f, 1.98032284e+00f, 3.04782670e-02f), GLINT_FLOAT4(2.15408278e+00f, 2.83935200e-02f, -4.33269072e+00f, 7.13755655e+00f),
    GLINT_FLOAT4(-4.22110176e+00f, 6.86574984e+00f, -4.10678816e+00f, 6.59308720e+00f), GLINT_FLOAT4(-3.98954892e+00f, 6.31949663e+00f, -3.86915708e+00f, 6.04489851e+00f),
    GLINT_FLOAT4(-3.74535704e+00f, 5.76920319e+00f, -3.61785889e+00f, 5.49231243e+00f), GLINT_FLOAT4(-3.48633218e+00f, 5.21411943e+00f, -3.35040116e+00f, 4.93451071e+00f),
    GLINT_FLOAT4(-3.20963550e+00f, 4.65337133e+00f, -3.06354523e+00f, 4.37059450e+00f), GLINT_FLOAT4(-2.91157532e+00f, 4.08610106e+00f, -2.75310421e+00f, 3.79987216e+00f),
    GLINT_FLOAT4(-2.58745623e+00f, 3.51200747e+00f, -2.41393256e+00f, 3.22281981e+00f), GLINT_FLOAT4(-2.23188043e+00f, 2.93298483e+00f, -2.04082704e+00f, 2.64375877e+00f),
    GLINT_FLOAT4(-1.84069645e+00f, 2.35725427e+00f, -1.63211584e+00f, 2.07670736e+00f), GLINT_FLOAT4(-1.41673243e+00f, 1.80655587e+00f, -1.19735825e+00f, 1.55207968e+00f),
    GLINT_FLOAT4(-9.77705181e-01f, 1.31846523e+00f, -7.61660337e-01f, 1.10958111e+00f), GLINT_FLOAT4(-5.52409410e-01f, 9.27111030e-01f, -3.51869226e-01f, 7.70506144e-01f),
    GLINT_FLOAT4(-1.60628736e-01f, 6.37619197e-01f, 2.17533410e-02f, 5.25531888e-01f), GLINT_FLOAT4(1.96347296e-01f, 4.31210339e-01f, 3.64519209e-01f, 3.51877093e-01f),
    GLINT_FLOAT4(5.27710140e-01f, 2.85159528e-01f, 6.87315464e-01f, 2.29103759e-01f), GLINT_FLOAT4(8.44631791e-01f, 1.82126835e-01f, 1.00084555e+00f, 1.42949745e-01f),
    GLINT_FLOAT4(1.15704381e+00f, 1.10532768e-01f, 1.31423664e+00f, 8.40229467e-02f), GLINT_FLOAT4(1.47338426e+00f, 6.27163500e-02f, 1.63542652e+00f, 4.60343026e-02f),
    GLINT_FLOAT4(1.80131364e+00f, 3.35113704e-02f, 1.97203839e+00f, 2.47923080e-02f), GLINT_FLOAT4(2.14866924e+00f, 1.96356270e-02f, 2.33238435e+00f, 1.79216210e-02f),
    GLINT_FLOAT4(-4.30823946e+00f, 7.07752037e+00f, -4.19606352e+00f, 6.80552912e+00f), GLINT_FLOAT4(-4.08112097e+00f, 6.53266716e+00f, -3.96320462e+00f, 6.25885963e+00f),
    GLINT_FLOAT4(-3.84208131e+00f, 5.98402452e+00f, -3.71748781e+00f, 5.70806980e+00f), GLINT_FLOAT4(-3.58912539e+00f, 5.43089390e+00f, -3.45665383e+00f, 5.15238714e+00f),
    GLINT_FLOAT4(-3.31968331e+00f, 4.87243223e+00f, -3.17776871e+00f, 4.59090948e+00f), GLINT_FLOAT4(-3.03040123e+00f, 4.30770922e+00f, -2.87700200e+00f, 4.02274895e+00f),
    GLINT_FLOAT4(-2.71692228e+00f, 3.73600864e+00f, -2.54945230e+00f, 3.44759130e+00f), GLINT_FLOAT4(-2.37385345e+00f, 3.15782046e+00f, -2.18942857e+00f, 2.86739612e+00f),
    GLINT_FLOAT4(-1.99565768e+00f, 2.57761979e+00f, -1.79242408e+00f, 2.29068136e+00f), GLINT_FLOAT4(-1.58033097e+00f, 2.00993180e+00f, -1.36103606e+00f, 1.73995972e+00f),
    GLINT_FLOAT4(-1.13740826e+00f, 1.48620510e+00f, -9.13258433e-01f, 1.25397885e+00f), GLINT_FLOAT4(-6.92586780e-01f, 1.04718828e+00f, -4.78666544e-01f, 8.67453456e-01f),
    GLINT_FLOAT4(-2.73448318e-01f, 7.14087427e-01f, -7.74990022e-02f, 5.84780872e-01f), GLINT_FLOAT4(1.09682381e-01f, 4.76472825e-01f, 2.89238036e-01f, 3.86027217e-01f),
    GLINT_FLOAT4(4.62599933e-01f, 3.10603291e-01f, 6.31257236e-01f, 2.47793496e-01f), GLINT_FLOAT4(7.96631515e-01f, 1.95622802e-01f, 9.60025430e-01f, 1.52487934e-01f),
    GLINT_FLOAT4(1.12261736e+00f, 1.17079742e-01f, 1.28548157e+00f, 8.83117840e-02f), GLINT_FLOAT4(1.44962168e+00f, 6.52647242e-02f, 1.61601043e+00f, 4.71494645e-02f),
    GLINT_FLOAT4(1.78562939e+00f, 3.32882814e-02f, 1.95950818e+00f, 2.31107529e-02f), GLINT_FLOAT4(2.13876247e+00f, 1.61606167e-02f, 2.32463050e+00f, 1.21093914e-02f),
    GLINT_FLOAT4(2.51850796e+00f, 1.07733300e-02f, -4.28375483e+00f, 7.01767159e+00f), GLINT_FLOAT4(-4.17098618e+00f, 6.74549389e+00f, -4.05540657e+00f, 6.47242928e+00f),
    GLINT_FLOAT4(-3.93680382e+00f, 6.19840145e+00f, -3.81493855e+00f, 5.92332554e+00f), GLINT_FLOAT4(-3.68954015e+00f, 5.64710712e+00f, -3.56030011e+00f, 5.36964130e+00f),
    GLINT_FLOAT4(-3.42686725e+00f, 5.09081507e+00f, -3.28883862e+00f, 4.81050682e+00f), GLINT_FLOAT4(-3.14575291e+00f, 4.52859402e+00f, -2.99708128e+00f, 4.24496269e+00f),
    GLINT_FLOAT4(-2.84222102e+00f, 3.95952702e+00f, -2.68049407e+00f, 3.67226744e+00f), GLINT_FLOAT4(-2.51115489e+00f, 3.38329101e+00f, -2.33342385e+00f, 3.09293413e+00f),
    GLINT_FLOAT4(-2.14655685e+00f, 2.80192542e+00f, -1.94998550e+00f, 2.51161790e+00f), GLINT_FLOAT4(-1.74355054e+00f, 2.22428703e+00f, -1.52783191e+00f, 1.94341087e+00f),
    GLINT_FLOAT4(-1.30450058e+00f, 1.67374074e+00f, -1.07648647e+00f, 1.42088616e+00f), GLINT_FLOAT4(-8.47703397e-01f, 1.19028008e+00f, -6.22263134e-01f, 9.85853434e-01f),
    GLINT_FLOAT4(-4.03517187e-01f, 8.09138536e-01f, -1.93434000e-01f, 6.59286320e-01f), GLINT_FLOAT4(7.46036647e-03f, 5.33809304e-01f, 1.99739605e-01f, 4.29500073e-01f),
    GLINT_FLOAT4(3.84624630e-01f, 3.43122691e-01f, 5.63609421e-01f, 2.71779507e-01f), GLINT_FLOAT4(7.38218904e-01f, 2.13031635e-01f, 9.09882426e-01f, 1.64881945e-01f),
    GLINT_FLOAT4(1.07988715e+00f, 1.25700355e-01f, 1.24938142e+00f, 9.41381902e-02f), GLINT_FLOAT4(1.41940689e+00f, 6.90534860e-02f, 1.59094572e+00f, 4.94563356e-02f),
    GLINT_FLOAT4(1.76497304e+00f, 3.44758257e-02f, 1.94251037e+00f, 2.33467054e-02f), GLINT_FLOAT4(2.12467313e+00f, 1.54117849e-02f, 2.31271434e+00f, 1.01352418e-02f),
    GLINT_FLOAT4(2.50805950e+00f, 7.12205004e-03f, 2.71234012e+00f, 6.13949122e-03f), GLINT_FLOAT4(-4.25931215e+00f, 6.95819378e+00f, -4.14594507e+00f, 6.68582773e+00f),
    GLINT_FLOAT4(-4.02972269e+00f, 6.41255856e+00f, -3.91042733e+00f, 6.13830757e+00f), GLINT_FLOAT4(-3.78781223e+00f, 5.86298752e+00f, -3.66159916e+00f, 5.58650160e+00f),
    GLINT_FLOAT4(-3.53147054e+00f, 5.30874205e+00f, -3.39706302e+00f, 5.02959108e+00f), GLINT_FLOAT4(-3.25796032e+00f, 4.74892473e+00f, -3.11368418e+00f, 4.46661568e+00f),
    GLINT_FLOAT4(-2.96368504e+00f, 4.18254614e+00f, -2.80733538e+00f, 3.89662862e+00f), GLINT_FLOAT4(-2.64392614e+00f, 3.60884380e+00f, -2.47267532e+00f, 3.31930423e+00f),
    GLINT_FLOAT4(-2.29275966e+00f, 3.02836227e+00f, -2.10338688e+00f, 2.73677826e+00f), GLINT_FLOAT4(-1.90393794e+00f, 2.44596362e+00f, -1.69421053e+00f, 2.15828943e+00f),
    GLINT_FLOAT4(-1.47476220e+00f, 1.87737286e+00f, -1.24727964e+00f, 1.60814023e+00f), GLINT_FLOAT4(-1.01475859e+00f, 1.35637689e+00f, -7.81217396e-01f, 1.12763345e+00f),
    GLINT_FLOAT4(-5.50875664e-01f, 9.25845623e-01f, -3.27149808e-01f, 7.52431333e-01f), GLINT_FLOAT4(-1.12005986e-01f, 6.06355608e-01f, 9.40903798e-02f, 4.84939933e-01f),
    GLINT_FLOAT4(2.91798294e-01f, 3.84829849e-01f, 4.82418239e-01f, 3.02695811e-01f), GLINT_FLOAT4(6.67495191e-01f, 2.35589355e-01f, 8.48569155e-01f, 1.81041569e-01f),
    GLINT_FLOAT4(1.02705073e+00f, 1.37026623e-01f, 1.20418465e+00f, 1.01874508e-01f), GLINT_FLOAT4(1.38106692e+00f, 7.41808340e-02f, 1.55869198e+00f, 5.27347401e-02f),
    GLINT_FLOAT4(1.73801422e+00f, 3.64710055e-02f, 1.92001486e+00f, 2.44449768e-02f), GLINT_FLOAT4(2.10576558e+00f, 1.58257075e-02f, 2.29648328e+00f, 9.90194827e-03f),
    GLINT_FLOAT4(2.49357510e+00f, 6.09600497e-03f, 2.69867063e+00f, 3.98155861e-03f), GLINT_FLOAT4(2.91364765e+00f, 3.30269593e-03f, -4.23497343e+00f, 6.89923525e+00f),
    GLINT_FLOAT4(-4.12100458e+00f, 6.62667894e+00f, -4.00413561e+00f, 6.35320282e+00f), GLINT_FLOAT4(-3.88414168e+00f, 6.07872677e+00f, -3.76077080e+00f, 5.80316019e+00f),
    GLINT_FLOAT4(-3.63373542e+00f, 5.52640390e+00f, -3.50270867e+00f, 5.24834681e+00f), GLINT_FLOAT4(-3.36731553e+00f, 4.96886778e+00f, -3.22712541e+00f, 4.68783808e+00f),
    GLINT_FLOAT4(-3.08164215e+00f, 4.40512753e+00f, -2.93029499e+00f, 4.12061501e+00f), GLINT_FLOAT4(-2.77243042e+00f, 3.83421087e+00f, -2.60730767e+00f, 3.54589653e+00f),
    GLINT_FLOAT4(-2.43410635e+00f, 3.25579214e+00f, -2.25195813e+00f, 2.96426821e+00f), GLINT_FLOAT4(-2.06002021e+00f, 2.67212200e+00f, -1.85762227e+00f, 2.38083053e+00f),
    GLINT_FLOAT4(-1.64451790e+00f, 2.09286976e+00f, -1.42124343e+00f, 1.81200862e+00f), GLINT_FLOAT4(-1.18950474e+00f, 1.54336011e+00f, -9.52366531e-01f, 1.29289079e+00f),
    GLINT_FLOAT4(-7.13952661e-01f, 1.06626022e+00f, -4.78582740e-01f, 8.67386997e-01f), GLINT_FLOAT4(-2.49720365e-01f, 6.97546244e-01f, -2.93054562e-02f, 5.55494010e-01f),
    GLINT_FLOAT4(1.82276905e-01f, 4.38352883e-01f, 3.85780960e-01f, 3.42623860e-01f), GLINT_FLOAT4(5.82580268e-01f, 2.64892697e-01f, 7.74250567e-01f, 2.02164650e-01f),
    GLINT_FLOAT4(9.62316215e-01f, 1.51937306e-01f, 1.14813530e+00f, 1.12143174e-01f), GLINT_FLOAT4(1.33288014e+00f, 8.10531303e-02f, 1.51757383e+00f, 5.71878068e-02f),
    GLINT_FLOAT4(1.70315683e+00f, 3.92549969e-02f, 1.89056349e+00f, 2.61143874e-02f), GLINT_FLOAT4(2.08079958e+00f, 1.67634301e-02f, 2.27501130e+00f, 1.03361923e-02f),
    GLINT_FLOAT4(2.47454071e+00f, 6.10848982e-03f, 2.68096781e+00f, 3.50534194e-03f), GLINT_FLOAT4(2.89613390e+00f, 2.10936693e-03f, 3.12216115e+00f, 1.67032320e-03f),
    GLINT_FLOAT4(-4.21078920e+00f, 6.84091187e+00f, -4.09621620e+00f, 6.56816483e+00f), GLINT_FLOAT4(-3.97869658e+00f, 6.29448080e+00f, -3.85800099e+00f, 6.01977730e+00f),
    GLINT_FLOAT4(-3.73386931e+00f, 5.74396276e+00f, -3.60600615e+00f, 5.46693325e+00f), GLINT_FLOAT4(-3.47407413e+00f, 5.18857574e+00f, -3.33768606e+00f, 4.90876532e+00f),
    GLINT_FLOAT4(-3.19639659e+00f, 4.62736893e+00f, -3.04969192e+00f, 4.34425306e+00f), GLINT_FLOAT4(-2.89697909e+00f, 4.05929279e+00f, -2.73757696e+00f, 3.77239799e+00f),
    GLINT_FLOAT4(-2.57071209e+00f, 3.48355126e+00f, -2.39552450e+00f, 3.19288254e+00f), GLINT_FLOAT4(-2.21109915e+00f, 2.90078306e+00f, -2.01654124e+00f, 2.60809183e+00f),
    GLINT_FLOAT4(-1.81112778e+00f, 2.31635857e+00f, -1.59456789e+00f, 2.02817535e+00f), GLINT_FLOAT4(-1.36737835e+00f, 1.74747515e+00f, -1.13128722e+00f, 1.47956824e+00f),
    GLINT_FLOAT4(-8.89431536e-01f, 1.23060524e+00f, -6.46038711e-01f, 1.00634313e+00f), GLINT_FLOAT4(-4.05516684e-01f, 8.10657740e-01f, -1.71353802e-01f, 6.44651830e-01f),
    GLINT_FLOAT4(5.45631871e-02f, 5.06852448e-01f, 2.71948397e-01f, 3.94179940e-01f), GLINT_FLOAT4(4.81655180e-01f, 3.02997619e-01f, 6.85114563e-01f, 2.29815081e-01f),
    GLINT_FLOAT4(8.83901358e-01f, 1.71592608e-01f, 1.07948399e+00f, 1.25783756e-01f), GLINT_FLOAT4(1.27312887e+00f, 9.02592838e-02f, 1.46590626e+00f, 6.32078052e-02f),
    GLINT_FLOAT4(1.65875387e+00f, 4.30572890e-02f, 1.85256374e+00f, 2.84291059e-02f), GLINT_FLOAT4(2.04827356e+00f, 1.81189217e-02f, 2.24694777e+00f, 1.10926703e-02f),
    GLINT_FLOAT4(2.44984221e+00f, 6.48682564e-03f, 2.65845203e+00f, 3.60662281e-03f), GLINT_FLOAT4(2.87454009e+00f, 1.92092487e-03f, 3.10015535e+00f, 1.05591130e-03f),
    GLINT_FLOAT4(3.33764768e+00f, 7.91025232e-04f, -4.18679810e+00f, 6.78331566e+00f), GLINT_FLOAT4(-4.07161999e+00f, 6.51037598e+00f, -3.95344877e+00f, 6.23648262e+00f),
    GLINT_FLOAT4(-3.83204865e+00f, 5.96155119e+00f, -3.70715308e+00f, 5.68548632e+00f), GLINT_FLOAT4(-3.57845736e+00f, 5.40818214e+00f, -3.44561410e+00f, 5.12952185e+00f),
    GLINT_FLOAT4(-3.30822349e+00f, 4.84937716e+00f, -3.16582537e+00f, 4.56761122e+00f), GLINT_FLOAT4(-3.01788640e+00f, 4.28408670e+00f, -2.86379170e+00f, 3.99867582e+00f),
    GLINT_FLOAT4(-2.70283175e+00f, 3.71128702e+00f, -2.53419900e+00f, 3.42190719e+00f), GLINT_FLOAT4(-2.35699224e+00f, 3.13067627e+00f, -2.17024851e+00f, 2.83801055e+00f),
    GLINT_FLOAT4(-1.97301948e+00f, 2.54479504e+00f, -1.76452816e+00f, 2.25266075e+00f), GLINT_FLOAT4(-1.54443967e+00f, 1.96432614e+00f, -1.31325281e+00f, 1.68390083e+00f),
    GLINT_FLOAT4(-1.07272112e+00f, 1.41690278e+00f, -8.26056063e-01f, 1.16966641e+00f), GLINT_FLOAT4(-5.77584207e-01f, 9.48030889e-01f, -3.31785470e-01f, 7.55800486e-01f),
    GLINT_FLOAT4(-9.21456963e-02f, 5.93876541e-01f, 1.39530107e-01f, 4.60541040e-01f), GLINT_FLOAT4(3.63072217e-01f, 3.52512836e-01f, 5.79427540e-01f, 2.66028464e-01f),
    GLINT_FLOAT4(7.90057123e-01f, 1.97527856e-01f, 9.96490777e-01f, 1.43921077e-01f), GLINT_FLOAT4(1.20009243e+00f, 1.02598630e-01f, 1.40199602e+00f, 7.13431686e-02f),
    GLINT_FLOAT4(1.60314727e+00f, 4.82378192e-02f, 1.80439913e+00f, 3.16076912e-02f), GLINT_FLOAT4(2.00661945e+00f, 1.99957900e-02f, 2.21078920e+00f, 1.21590430e-02f),
    GLINT_FLOAT4(2.41807628e+00f, 7.06828851e-03f, 2.62988544e+00f, 3.90213542e-03f), GLINT_FLOAT4(2.84788465e+00f, 2.03181105e-03f, 3.07401943e+00f, 9.99842421e-04f),
    GLINT_FLOAT4(3.31052470e+00f, 4.97916713e-04f, 3.55994654e+00f, 3.49341397e-04f), GLINT_FLOAT4(-4.16303301e+00f, 6.72651386e+00f, -4.04724884e+00f, 6.45338154e+00f),
    GLINT_FLOAT4(-3.92842484e+00f, 6.17927837e+00f, -3.80631900e+00f, 5.90411758e+00f), GLINT_FLOAT4(-3.68065667e+00f, 5.62780142e+00f, -3.55112529e+00f, 5.35022116e+00f),
    GLINT_FLOAT4(-3.41736603e+00f, 5.07125616e+00f, -3.27896690e+00f, 4.79077482e+00f), GLINT_FLOAT4(-3.13545156e+00f, 4.50863695e+00f, -2.98626781e+00f, 4.22470045e+00f),
    GLINT_FLOAT4(-2.83077693e+00f, 3.93883657e+00f, -2.66824079e+00f, 3.65095258e+00f), GLINT_FLOAT4(-2.49781609e+00f, 3.36103988e+00f, -2.31855989e+00f, 3.06925082e+00f),
    GLINT_FLOAT4(-2.12945914e+00f, 2.77603030e+00f, -1.92951107e+00f, 2.48231506e+00f), GLINT_FLOAT4(-1.71788359e+00f, 2.18982530e+00f, -1.49419844e+00f, 1.90141761e+00f),
    GLINT_FLOAT4(-1.25893819e+00f, 1.62138987e+00f, -1.01388538e+00f, 1.35547650e+00f), GLINT_FLOAT4(-7.62326419e-01f, 1.11019313e+00f, -5.08679211e-01f, 8.91442060e-01f),
    GLINT_FLOAT4(-2.57474661e-01f, 7.02924907e-01f, -1.21637620e-02f, 5.45313179e-01f), GLINT_FLOAT4(2.25558728e-01f, 4.16633934e-01f, 4.55650777e-01f, 3.13410014e-01f),
    GLINT_FLOAT4(6.79136336e-01f, 2.31762677e-01f, 8.97464216e-01f, 1.68064579e-01f), GLINT_FLOAT4(1.11206305e+00f, 1.19161069e-01f, 1.32413852e+00f, 8.23518336e-02f),
    GLINT_FLOAT4(1.53465593e+00f, 5.53020462e-02f, 1.74442852e+00f, 3.59719098e-02f), GLINT_FLOAT4(1.95424557e+00f, 2.25871149e-02f, 2.16499472e+00f, 1.36370324e-02f),
    GLINT_FLOAT4(2.37775350e+00f, 7.87838921e-03f, 2.59384155e+00f, 4.32869606e-03f), GLINT_FLOAT4(2.81484246e+00f, 2.24460289e-03f, 3.04260302e+00f, 1.08880305e-03f),
    GLINT_FLOAT4(3.27923346e+00f, 4.92526568e-04f, 3.52712107e+00f, 2.20449001e-04f), GLINT_FLOAT4(3.78897119e+00f, 1.43252939e-04f, -4.13951731e+00f, 6.67055655e+00f),
    GLINT_FLOAT4(-4.02312756e+00f, 6.39723158e+00f, -3.90365076e+00f, 6.12291765e+00f), GLINT_FLOAT4(-3.78083825e+00f, 5.84752703e+00f, -3.65440798e+00f, 5.57095861e+00f),
    GLINT_FLOAT4(-3.52403831e+00f, 5.29310083e+00f, -3.38935971e+00f, 5.01382971e+00f), GLINT_FLOAT4(-3.24994683e+00f, 4.73301029e+00f, -3.10530734e+00f, 4.45049810e+00f),
    GLINT_FLOAT4(-2.95486927e+00f, 4.16614866e+00f, -2.79796934e+00f, 3.87982965e+00f), GLINT_FLOAT4(-2.63384008e+00f, 3.59144974e+00f, -2.46160173e+00f, 3.30100536e+00f),
    GLINT_FLOAT4(-2.28026748e+00f, 3.00866461e+00f, -2.08877373e+00f, 2.71490312e+00f), GLINT_FLOAT4(-1.88606131e+00f, 2.42071652e+00f, -1.67124295e+00f, 2.12792206e+00f),
    GLINT_FLOAT4(-1.44389749e+00f, 1.83952558e+00f, -1.20449388e+00f, 1.56002593e+00f), GLINT_FLOAT4(-9.54846025e-01f, 1.29538071e+00f, -6.98314369e-01f, 1.05228090e+00f),
    GLINT_FLOAT4(-4.39396948e-01f, 8.36669028e-01f, -1.82648867e-01f, 6.52111769e-01f), GLINT_FLOAT4(6.85497001e-02f, 4.99025196e-01f, 3.12642038e-01f, 3.75176519e-01f),
    GLINT_FLOAT4(5.49716175e-01f, 2.76903242e-01f, 7.80842125e-01f, 2.00221449e-01f), GLINT_FLOAT4(1.00739861e+00f, 1.41430840e-01f, 1.23064661e+00f, 9.72868577e-02f),
    GLINT_FLOAT4(1.45158017e+00f, 6.49636909e-02f, 1.67097270e+00f, 4.19821143e-02f), GLINT_FLOAT4(1.88951886e+00f, 2.61749085e-02f, 2.10799026e+00f, 1.56901963e-02f),
    GLINT_FLOAT4(2.32735562e+00f, 9.00449511e-03f, 2.54884696e+00f, 4.92075831e-03f), GLINT_FLOAT4(2.77397585e+00f, 2.54285662e-03f, 3.00451493e+00f, 1.23166037e-03f),
    GLINT_FLOAT4(3.24247527e+00f, 5.53262304e-04f, 3.49010038e+00f, 2.28731937e-04f), GLINT_FLOAT4(3.74989319e+00f, 9.13091499e-05f, 4.02468681e+00f, 5.42980597e-05f),
    GLINT_FLOAT4(-4.11626911e+00f, 6.61547947e+00f, -3.99927497e+00f, 6.34196091e+00f), GLINT_FLOAT4(-3.87914562e+00f, 6.06743670e+00f, -3.75562644e+00f, 5.79181528e+00f),
    GLINT_FLOAT4(-3.62842751e+00f, 5.51499414e+00f, -3.49721813e+00f, 5.23685789e+00f), GLINT_FLOAT4(-3.36161757e+00f, 4.95727968e+00f, -3.22118688e+00f, 4.67612028e+00f),
    GLINT_FLOAT4(-3.07541680e+00f, 4.39323282e+00f, -2.92371607e+00f, 4.10846853e+00f), GLINT_FLOAT4(-2.76539588e+00f, 3.82169366e+00f, -2.59965801e+00f, 3.53281784e+00f),
    GLINT_FLOAT4(-2.42558551e+00f, 3.24184489e+00f, -2.24214673e+00f, 2.94895983e+00f), GLINT_FLOAT4(-2.04822564e+00f, 2.65467405e+00f, -1.84270620e+00f, 2.36004734e+00f),
    GLINT_FLOAT4(-1.62464571e+00f, 2.06700373e+00f, -1.39358056e+00f, 1.77870953e+00f), GLINT_FLOAT4(-1.14996874e+00f, 1.49987578e+00f, -8.95657659e-01f, 1.23668849e+00f),
    GLINT_FLOAT4(-6.34079158e-01f, 9.96004939e-01f, -3.69795263e-01f, 7.83781648e-01f), GLINT_FLOAT4(-1.07353270e-01f, 6.03417039e-01f, 1.49976358e-01f, 4.55050677e-01f),
    GLINT_FLOAT4(4.00799453e-01f, 3.36190641e-01f, 6.45324111e-01f, 2.43003279e-01f), GLINT_FLOAT4(8.84617925e-01f, 1.71404839e-01f, 1.11991596e+00f, 1.17605388e-01f),
    GLINT_FLOAT4(1.35223901e+00f, 7.82343522e-02f, 1.58232474e+00f, 5.03033400e-02f), GLINT_FLOAT4(1.81075442e+00f, 3.11721079e-02f, 2.03814602e+00f, 1.85607579e-02f),
    GLINT_FLOAT4(2.26532149e+00f, 1.05809951e-02f, 2.49340200e+00f, 5.74826216e-03f), GLINT_FLOAT4(2.72382522e+00f, 2.95769656e-03f, 2.95831013e+00f, 1.42991671e-03f),
    GLINT_FLOAT4(3.19880652e+00f, 6.43033243e-04f, 3.44745708e+00f, 2.65707436e-04f), GLINT_FLOAT4(3.70660114e+00f, 9.97369280e-05f, 3.97882891e+00f, 3.52430507e-05f),
    GLINT_FLOAT4(4.26708174e+00f, 1.89344937e-05f, -4.09330177e+00f, 6.56130409e+00f), GLINT_FLOAT4(-3.97570443e+00f, 6.28759241e+00f, -3.85492373e+00f, 6.01285744e+00f),
    GLINT_FLOAT4(-3.73069835e+00f, 5.73700571e+00f, -3.60273075e+00f, 5.45993090e+00f), GLINT_FLOAT4(-3.47068048e+00f, 5.18151569e+00f, -3.33415604e+00f, 4.90162945e+00f),
    GLINT_FLOAT4(-3.19270396e+00f, 4.62012959e+00f, -3.04579878e+00f, 4.33686495e+00f), GLINT_FLOAT4(-2.89282775e+00f, 4.05168486e+00f, -2.73307657e+00f, 3.76445389e+00f),
    GLINT_FLOAT4(-2.56571579e+00f, 3.47508359e+00f, -2.38979006e+00f, 3.18358564e+00f), GLINT_FLOAT4(-2.20422149e+00f, 2.89016581e+00f, -2.00784087e+00f, 2.59537458e+00f),
    GLINT_FLOAT4(-1.79947412e+00f, 2.30034256e+00f, -1.57812274e+00f, 2.00711012e+00f), GLINT_FLOAT4(-1.34328258e+00f, 1.71901524e+00f, -1.09540260e+00f, 1.44099200e+00f),
    GLINT_FLOAT4(-8.36365640e-01f, 1.17945755e+00f, -5.69669008e-01f, 9.41423059e-01f), GLINT_FLOAT4(-2.99918145e-01f, 7.32829750e-01f, -3.16147804e-02f, 5.56874990e-01f),
    GLINT_FLOAT4(2.32120275e-01f, 4.13406402e-01f, 4.90073264e-01f, 2.99679786e-01f), GLINT_FLOAT4(7.42546856e-01f, 2.11704314e-01f, 9.90538001e-01f, 1.45293951e-01f),
    GLINT_FLOAT4(1.23505080e+00f, 9.65391546e-02f, 1.47679508e+00f, 6.18987568e-02f), GLINT_FLOAT4(1.71622670e+00f, 3.81896123e-02f, 1.95376432e+00f, 2.26121750e-02f),
    GLINT_FLOAT4(2.19002151e+00f, 1.28112398e-02f, 2.42595506e+00f, 6.91857003e-03f), GLINT_FLOAT4(2.66290355e+00f, 3.54256993e-03f, 2.90253782e+00f, 1.70770788e-03f),
    GLINT_FLOAT4(3.14677525e+00f, 7.67954101e-04f, 3.39770532e+00f, 3.18531558e-04f), GLINT_FLOAT4(3.65756154e+00f, 1.20194571e-04f, 3.92874956e+00f, 4.06628387e-05f),
    GLINT_FLOAT4(4.21393013e+00f, 1.26230589e-05f, 4.51615000e+00f, 6.04528168e-06f), GLINT_FLOAT4(-4.07062531e+00f, 6.50804472e+00f, -3.95242620e+00f, 6.23413992e+00f),
    GLINT_FLOAT4(-3.83099532e+00f, 5.95919418e+00f, -3.70606470e+00f, 5.68311119e+00f), GLINT_FLOAT4(-3.57732868e+00f, 5.40578270e+00f, -3.44443727e+00f, 5.12708807e+00f),
    GLINT_FLOAT4(-3.30698729e+00f, 4.84689331e+00f, -3.16451120e+00f, 4.56505203e+00f), GLINT_FLOAT4(-3.01646614e+00f, 4.28140974e+00f, -2.86221814e+00f, 3.99581313e+00f),
    GLINT_FLOAT4(-2.70102668e+00f, 3.70812607e+00f, -2.53202963e+00f, 3.41826272e+00f), GLINT_FLOAT4(-2.35423255e+00f, 3.12624478e+00f, -2.16651034e+00f, 2.83230114e+00f),
    GLINT_FLOAT4(-1.96763945e+00f, 2.53702569e+00f, -1.75638688e+00f, 2.24162698e+00f), GLINT_FLOAT4(-1.53169894e+00f, 1.94827020e+00f, -1.29303169e+00f, 1.66047764e+00f),
    GLINT_FLOAT4(-1.04082823e+00f, 1.38341534e+00f, -7.77006924e-01f, 1.12373245e+00f), GLINT_FLOAT4(-5.05122006e-01f, 8.88577938e-01f, -2.29796574e-01f, 6.83846235e-01f),
    GLINT_FLOAT4(4.45564017e-02f, 5.12502193e-01f, 3.15005094e-01f, 3.74092698e-01f), GLINT_FLOAT4(5.80523908e-01f, 2.65633106e-01f, 8.41465056e-01f, 1.82987064e-01f),
    GLINT_FLOAT4(1.09866655e+00f, 1.21851169e-01f, 1.35280514e+00f, 7.81531185e-02f), GLINT_FLOAT4(1.60422051e+00f, 4.81333025e-02f, 1.85309207e+00f, 2.83957087e-02f),
    GLINT_FLOAT4(2.09974146e+00f, 1.60080902e-02f, 2.34487343e+00f, 8.59813299e-03f), GLINT_FLOAT4(2.58966589e+00f, 4.38086037e-03f, 2.83571887e+00f, 2.10436853e-03f),
    GLINT_FLOAT4(3.08493209e+00f, 9.45186883e-04f, 3.33938217e+00f, 3.92883347e-04f), GLINT_FLOAT4(3.60125208e+00f, 1.49261337e-04f, 3.87282944e+00f, 5.10631908e-05f),
    GLINT_FLOAT4(4.15656805e+00f, 1.54566333e-05f, 4.45520067e+00f, 4.16184821e-06f), GLINT_FLOAT4(4.77188349e+00f, 1.70973385e-06f, -4.04824638e+00f, 6.45571423e+00f),
    GLINT_FLOAT4(-3.92944765e+00f, 6.18161535e+00f, -3.80736804e+00f, 5.90645647e+00f), GLINT_FLOAT4(-3.68173313e+00f, 5.63014078e+00f, -3.55222917e+00f, 5.35255718e+00f),
    GLINT_FLOAT4(-3.41849685e+00f, 5.07358313e+00f, -3.28012061e+00f, 4.79308033e+00f), GLINT_FLOAT4(-3.13661838e+00f, 4.51089716e+00f, -2.98742914e+00f, 4.22687531e+00f),
    GLINT_FLOAT4(-2.83189678e+00f, 3.94085789e+00f, -2.66925645e+00f, 3.65271759e+00f), GLINT_FLOAT4(-2.49861002e+00f, 3.36236167e+00f, -2.31892395e+00f, 3.06982851e+00f),
    GLINT_FLOAT4(-2.12902594e+00f, 2.77537513e+00f, -1.92763579e+00f, 2.47964025e+00f), GLINT_FLOAT4(-1.71346068e+00f, 2.18391490e+00f, -1.48539269e+00f, 1.89050329e+00f),
    GLINT_FLOAT4(-1.24285102e+00f, 1.60312307e+00f, -9.86272752e-01f, 1.32717752e+00f), GLINT_FLOAT4(-7.17611134e-01f, 1.06954598e+00f, -4.40467358e-01f, 8.37498844e-01f),
    GLINT_FLOAT4(-1.59450054e-01f, 6.36849701e-01f, 1.21165365e-01f, 4.70300555e-01f), GLINT_FLOAT4(3.98671895e-01f, 3.37096810e-01f, 6.72227144e-01f, 2.34027252e-01f),
    GLINT_FLOAT4(9.42159057e-01f, 1.56820431e-01f, 1.20904827e+00f, 1.01018086e-01f), GLINT_FLOAT4(1.47313786e+00f, 6.23370633e-02f, 1.73437309e+00f, 3.67502533e-02f),
    GLINT_FLOAT4(1.99269629e+00f, 2.06577312e-02f, 2.24842834e+00f, 1.10495081e-02f), GLINT_FLOAT4(2.50247669e+00f, 5.60586480e-03f, 2.75631142e+00f, 2.68318877e-03f),
    GLINT_FLOAT4(3.01180172e+00f, 1.20229321e-03f, 3.27103543e+00f, 4.99634014e-04f), GLINT_FLOAT4(3.53619361e+00f, 1.90802282e-04f, 3.80950928e+00f, 6.64481267e-05f),
    GLINT_FLOAT4(4.09330416e+00f, 2.07690791e-05f, 4.39007807e+00f, 5.36182961e-06f), GLINT_FLOAT4(4.70264101e+00f, 8.20995865e-07f, 5.03427172e+00f, 2.47000770e-07f),
    GLINT_FLOAT4(-4.02616644e+00f, 6.40429974e+00f, -3.90676999e+00f, 6.13000631e+00f), GLINT_FLOAT4(-3.78404379e+00f, 5.85463572e+00f, -3.65770602e+00f, 5.57808781e+00f),
    GLINT_FLOAT4(-3.52743554e+00f, 5.30025005e+00f, -3.39286232e+00f, 5.02099609e+00f), GLINT_FLOAT4(-3.25355959e+00f, 4.74018478e+00f, -3.10902905e+00f, 4.45765829e+00f),
    GLINT_FLOAT4(-2.95869207e+00f, 4.17325687e+00f, -2.80187035e+00f, 3.88682103e+00f), GLINT_FLOAT4(-2.63777304e+00f, 3.59822774e+00f, -2.46546507e+00f, 3.30738187e+00f),
    GLINT_FLOAT4(-2.28387403e+00f, 3.01434231e+00f, -2.09177852e+00f, 2.71939349e+00f), GLINT_FLOAT4(-1.88784063e+00f, 2.42322350e+00f, -1.67070782e+00f, 2.12721610e+00f),
    GLINT_FLOAT4(-1.43921936e+00f, 1.83382428e+00f, -1.19275761e+00f, 1.54696929e+00f), GLINT_FLOAT4(-9.31756496e-01f, 1.27229989e+00f, -6.58202350e-01f, 1.01692247e+00f),
    GLINT_FLOAT4(-3.75727087e-01f, 7.88205564e-01f, -8.88858289e-02f, 5.91844738e-01f), GLINT_FLOAT4(1.98232383e-01f, 4.30258960e-01f, 4.83175546e-01f, 3.02396804e-01f),
    GLINT_FLOAT4(7.65257001e-01f, 2.04839095e-01f, 1.04470563e+00f, 1.33157790e-01f), GLINT_FLOAT4(1.32169175e+00f, 8.27184096e-02f, 1.59596765e+00f, 4.89438698e-02f),
    GLINT_FLOAT4(1.86707377e+00f, 2.75240839e-02f, 2.13479757e+00f, 1.46924909e-02f), GLINT_FLOAT4(2.39959645e+00f, 7.43097719e-03f, 2.66268277e+00f, 3.54645471e-03f),
    GLINT_FLOAT4(2.92584372e+00f, 1.58597692e-03f, 3.19118285e+00f, 6.58640929e-04f), GLINT_FLOAT4(3.46091914e+00f, 2.52022030e-04f, 3.73728776e+00f, 8.86109337e-05f),
    GLINT_FLOAT4(4.02254248e+00f, 2.84404832e-05f, 4.31902885e+00f, 7.64535889e-06f), GLINT_FLOAT4(4.62929583e+00f, 1.02636807e-06f, 4.95624590e+00f, -4.36741026e-08f),
    GLINT_FLOAT4(5.30329800e+00f, 5.68396047e-07f, 0.00000000e+00f, 0.00000000e+00f)
GLINT_TABLE_CLOSE;

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

GLINT_FN vec2 glint_binomial_two_sided_fit(real N, real p_near) {
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

GLINT_FN glint_binomial_middle glint_binomial_unbiased_middle_setup(real N, real p, glint_binomial_ends e) {
    glint_binomial_middle q;
    q.all_positive = e.all_positive;
    q.all_negative = e.all_negative;
    q.lower = e.lower;
    q.span = N - real(2);
    glint_binomial_targets g = glint_binomial_middle_targets(N, p, e);
    // N <= 3: the middle holds at most two counts, 1 and N - 1, and a Bernoulli with the right mean
    // is exact at N = 3 (and continuous down to N = 2, where it becomes the single count 1).
    // glint_binomial_unbiased_middle blends it into the Gaussian law between N = 3 and 4.
    q.two_point = (q.span > real(0)) ? g.mean / q.span : real(0);
    q.t = real(0);
    q.sigma = real(0);
    if (q.span > real(1)) {  // N <= 3: the two-point law alone
        real p_near = (q.lower > real(0.5)) ? p : real(1) - p;
        vec2 f = vec2(real(0));
        if (N < GLINT_BINOMIAL_FAR_N_MAX) {
            f = glint_binomial_two_sided_fit(N, p_near);
            f.y = sqrt(g.variance) * exp(f.y);
        } else {
            f = glint_binomial_one_sided_fit(g);
        }
        q.t = f.x;
        q.sigma = f.y;
    }
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
    // From N = 4 on: one rounding of center + sigma z. At N = 1e16 a count's ulp is most of a
    // standard deviation, and rounding the offset first and then adding it to 1 or subtracting it
    // from N - 1 would round twice.
    if (q.span >= real(2)) {
        real s = (q.lower > real(0.5)) ? z : -z;
        return clamp(q.center + q.sigma * s, real(1), N2 - real(1));
    }
    real offset = min(max(q.sigma * q.t + q.sigma * z, real(0)), q.span);
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
