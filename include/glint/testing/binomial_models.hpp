// The closed-form output distribution of each approximate binomial sampler (glint/binomial.hpp),
// evaluated in double from the kernels' own double instantiation, for tables and tests that
// judge an approximation without randomness. Every sampler's output is a mixture of atoms and
// Gaussian segments (a Gaussian density restricted to an interval), except DB23's, whose floor
// makes a floored clamped Gaussian; model::cdf, mean and variance are exact for those forms.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "glint/binomial.hpp"

namespace glint {
namespace testing {

class binomial_model {
public:
    struct atom {
        double value, probability;
    };
    // scale * (Phi((min(x, hi) - mu) / sigma) - Phi((lo - mu) / sigma)) of the CDF for x > lo.
    struct segment {
        double scale, mu, sigma, lo, hi;
    };
    // DB23: weight * P(floor(clamp(mu + sigma Z, 1, top)) <= x).
    struct floored {
        double weight = 0, mu = 0, sigma = 0, top = 0;
    };

    std::vector<atom> atoms;
    std::vector<segment> segments;
    floored floor_part;

    double cdf(double x) const {
        double f = 0;
        for (const atom& a : atoms)
            if (a.value <= x) f += a.probability;
        for (const segment& s : segments)
            if (x > s.lo) f += s.scale * (phi_cdf((std::min(x, s.hi) - s.mu) / s.sigma) - phi_cdf((s.lo - s.mu) / s.sigma));
        if (floor_part.weight > 0 && x >= 1) {
            const double j = std::floor(x) + 1;  // floor(c) <= x  <=>  c < j
            f += floor_part.weight * (j > floor_part.top ? 1.0 : (floor_part.sigma > 0 ? phi_cdf((j - floor_part.mu) / floor_part.sigma)
                                                                                        : (std::min(std::max(floor_part.mu, 1.0), floor_part.top) < j ? 1.0 : 0.0)));
        }
        return std::min(f, 1.0);
    }

    // E[n] and Var[n] (as a second moment about the mean, free of cancellation at large N).
    double mean() const { return moment(1, 0.0); }
    double variance() const { return std::max(moment(2, mean()), 0.0); }
    // E[(n - h)+] and E[(h - n)+]: the mass beyond h weighted by its distance.
    double excess_above(double h) const {
        double e = 0;
        for (const atom& a : atoms) e += a.probability * std::max(a.value - h, 0.0);
        for (const segment& s : segments) {
            if (h >= s.hi) continue;
            const double from = std::max(h, s.lo);  // E[(X - h) 1{from < X < hi}] for X ~ N(mu, sigma)
            const double al = (from - s.mu) / s.sigma, be = (s.hi - s.mu) / s.sigma;
            e += s.scale * ((s.mu - h) * (phi_cdf(be) - phi_cdf(al)) + s.sigma * (phi_pdf(al) - phi_pdf(be)));
        }
        if (floor_part.weight > 0) e += floor_part.weight * std::max(floored_moment(1, 0.0) - h, 0.0);  // bound
        return e;
    }
    double deficit_below(double h) const {
        double e = 0;
        for (const atom& a : atoms) e += a.probability * std::max(h - a.value, 0.0);
        for (const segment& s : segments) {
            if (h <= s.lo) continue;
            const double to = std::min(h, s.hi);
            const double al = (s.lo - s.mu) / s.sigma, be = (to - s.mu) / s.sigma;
            e += s.scale * ((h - s.mu) * (phi_cdf(be) - phi_cdf(al)) - s.sigma * (phi_pdf(al) - phi_pdf(be)));
        }
        if (floor_part.weight > 0 && h > 1) e += floor_part.weight * std::max(h - 1.0, 0.0) * cdf(h);  // bound
        return e;
    }
    double probability_zero() const { return cdf(0.0); }

    // Adds weight * clamp(mu + sigma Z, lo, hi): atoms at the bounds and a segment between.
    void add_clamped_gaussian(double weight, double mu, double sigma, double lo, double hi) {
        if (weight <= 0) return;
        if (!(sigma > 0) || hi <= lo) {
            atoms.push_back({std::min(std::max(mu, lo), std::max(lo, hi)), weight});
            return;
        }
        const double a = phi_cdf((lo - mu) / sigma), b = phi_cdf((hi - mu) / sigma);
        atoms.push_back({lo, weight * a});
        atoms.push_back({hi, weight * (1 - b)});
        segments.push_back({weight, mu, sigma, lo, hi});
    }

    static double phi_cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }
    static double phi_pdf(double t) { return std::exp(-0.5 * t * t) / std::sqrt(2 * M_PI); }

private:
    // E[(n - c)^k] for k = 1, 2.
    double moment(int k, double c) const {
        double m = 0;
        for (const atom& a : atoms) m += a.probability * (k == 1 ? a.value - c : (a.value - c) * (a.value - c));
        for (const segment& s : segments) {
            const double al = (s.lo - s.mu) / s.sigma, be = (s.hi - s.mu) / s.sigma, mu = s.mu - c;
            const double dP = phi_cdf(be) - phi_cdf(al), dphi = phi_pdf(al) - phi_pdf(be);
            if (k == 1) m += s.scale * (mu * dP + s.sigma * dphi);
            else
                m += s.scale * (mu * mu * dP + 2 * mu * s.sigma * dphi + s.sigma * s.sigma * (dP + al * phi_pdf(al) - be * phi_pdf(be)));
        }
        if (floor_part.weight > 0) m += floor_part.weight * floored_moment(k, c);
        return m;
    }
    // E[(floor(c) - center)^k]: summed over the integers where the Gaussian has mass (at most 2e6 of
    // them); beyond that E[c^k] with floor's average shift of -1/2 (error below 1e-6 relative).
    double floored_moment(int k, double c) const {
        const floored& f = floor_part;
        const double top = std::floor(f.top);
        if (!(f.sigma > 0)) {
            const double v = std::floor(std::min(std::max(f.mu, 1.0), f.top)) - c;
            return k == 1 ? v : v * v;
        }
        const double lo = std::max(1.0, std::floor(f.mu - 40 * f.sigma)), hi = std::min(top, std::ceil(f.mu + 40 * f.sigma));
        if (hi - lo <= 2e6) {
            auto below = [&](double j) {  // P(c < j)
                if (j <= 1) return 0.0;
                if (j > f.top) return 1.0;
                return phi_cdf((j - f.mu) / f.sigma);
            };
            double m = 0;
            for (double v = lo; v <= hi; ++v) m += (below(v + 1) - below(v)) * (k == 1 ? v - c : (v - c) * (v - c));
            return m;
        }
        const double mean = f.mu - 0.5 - c;
        return k == 1 ? mean : mean * mean + f.sigma * f.sigma - 1.0 / 12;
    }
};

// The closed-form distribution of `variant` at (N, p), with (1 - p)^N evaluated by `method`.
// With real = double it is the variant's own law, its probabilities evaluated accurately in
// double. With real = float it is the law of the float kernel: every parameter is computed as
// the float kernel computes it, and each gate's probability is the width of the interval of u1
// that its float comparisons select (so 1 - (1 - P) rounded in float, where the kernel tests
// 1 - P <= u1).
template <class real = double>
binomial_model model_of(binomial_variant variant, double N_in, double p_in, pow_method method) {
    using k = glint::detail::glsl::kernels<real>;
    constexpr bool as_float = std::is_same<real, float>::value;
    const int m = static_cast<int>(method);
    const real Nr = std::max(static_cast<real>(N_in), real(0)), pr = std::min(std::max(static_cast<real>(p_in), real(0)), real(1));
    const double N = static_cast<double>(Nr), p = static_cast<double>(pr);
    // P(u1 < a) and P(u1 >= 1 - b) for thresholds computed in `real`.
    auto below = [](real a) { return std::min(std::max(static_cast<double>(a), 0.0), 1.0); };
    auto at_or_above_one_minus = [&](real b) {
        return as_float ? std::min(std::max(1.0 - static_cast<double>(real(1) - b), 0.0), 1.0) : std::min(std::max(static_cast<double>(b), 0.0), 1.0);
    };
    binomial_model d;
    switch (variant) {
        case binomial_variant::ungated: {
            const real sd = std::sqrt(Nr * pr * (real(1) - pr));
            d.add_clamped_gaussian(1, static_cast<double>(Nr * pr), static_cast<double>(sd), 0, N);
            break;
        }
        case binomial_variant::gated_db23: {
            const double gate = below(k::glint_any_success(pr, Nr, m));
            const real rest = std::max(Nr - real(1), real(0));
            d.atoms.push_back({0, 1 - gate});
            if (N < 1) d.atoms.push_back({0, gate});
            else d.floor_part = {gate, static_cast<double>(real(1) + rest * pr), static_cast<double>(std::sqrt(rest * pr * (real(1) - pr))), N};
            break;
        }
        case binomial_variant::gated: {
            const real top = std::max(Nr, real(1)), rest = top - real(1);
            const double gate = below(std::min(Nr * pr, k::glint_any_success(pr, Nr, m)));
            d.atoms.push_back({0, 1 - gate});
            d.add_clamped_gaussian(gate, static_cast<double>(real(1) + rest * pr), static_cast<double>(std::sqrt(rest * pr * (real(1) - pr))), 1,
                                   static_cast<double>(top));
            break;
        }
        case binomial_variant::dual_gated:
        case binomial_variant::unbiased: {
            const real N2 = std::max(Nr, real(2)), weight_2 = std::min(std::max(Nr - real(1), real(0)), real(1)),
                       weight_1 = std::max(real(0), real(1) - std::fabs(real(1) - Nr));
            typename k::glint_binomial_middle q{};
            real all_positive, all_negative;
            if (variant == binomial_variant::unbiased) {
                q = k::glint_binomial_unbiased_setup(N2, pr, m);
                all_positive = q.all_positive, all_negative = q.all_negative;
            } else {
                all_positive = std::pow(pr, N2), all_negative = k::glint_pow_one_minus(pr, N2, m);
            }
            // The gates of KK25 Alg. 1 as intervals of u1 (lines 10-14).
            const real a = weight_2 * all_positive, b = a + weight_1 * pr;
            const real c = weight_2 * all_negative, e = c + weight_1 * (real(1) - pr);
            const double p_all_positive = below(a), p_positive_gate = below(b);
            const double p_all_negative = at_or_above_one_minus(c), p_negative_gate = at_or_above_one_minus(e);
            double p_middle = Nr > real(1) ? std::max(1.0 - p_positive_gate - p_negative_gate, 0.0) : 0.0;
            if (!as_float) {
                // Accurately, without the cancellation of 1 - P(n = 0) - P(n = N).
                p_middle = N > 2 ? std::max(static_cast<double>(k::glint_any_success(pr, N2, m)) - p_all_positive, 0.0)
                                 : static_cast<double>(weight_2) * 2 * p * (1 - p);
            }
            if (N <= 2) {  // KK25 Fig. 4: the outcomes of N = 1 and N = 2; the middle is n = 1
                d.atoms.push_back({2, p_all_positive});
                d.atoms.push_back({1, p_positive_gate - p_all_positive + p_middle});
                d.atoms.push_back({0, std::max(1 - p_positive_gate - p_middle, 0.0)});
                break;
            }
            d.atoms.push_back({N, p_all_positive});
            d.atoms.push_back({0, p_all_negative});
            if (variant == binomial_variant::dual_gated) {
                const real rest = N2 - real(2);
                d.add_clamped_gaussian(p_middle, static_cast<double>(real(1) + rest * pr), static_cast<double>(std::sqrt(rest * pr * (real(1) - pr))), 1,
                                       N - 1);
                break;
            }
            const bool lower = q.lower > real(0.5);
            const double span = static_cast<double>(q.span), t = static_cast<double>(q.t), sigma = static_cast<double>(q.sigma);
            const double pi = static_cast<double>(q.two_point);
            const double w = std::min(std::max(span - 1, 0.0), 1.0);
            auto place = [&](double offset) { return lower ? 1 + offset : N - 1 - offset; };
            // The offset as a function of u = u_near: O(u) = w G(u) + (1 - w) span [u >= u_split],
            // with G the Gaussian law's quantile function: 0 on [0, u_a), sigma (t + z(u)) on
            // [u_a, u_b), span on [u_b, 1].
            if (span >= 2) {  // the kernel's single-rounding form: clamp(center +- sigma z, 1, N - 1)
                d.add_clamped_gaussian(p_middle, static_cast<double>(q.center), sigma, 1, N - 1);
                break;
            }
            const double u_split = 1 - pi;
            const double u_a = sigma > 0 ? binomial_model::phi_cdf(-t) : 1.0;
            const double u_b = sigma > 0 ? 1 - binomial_model::phi_cdf(t - span / sigma) : 1.0;
            auto z_of = [](double u) {  // the standard normal quantile, by bisection on the CDF
                if (u <= 0) return -40.0;
                if (u >= 1) return 40.0;
                double lo = -40, hi = 40;
                for (int i = 0; i < 200; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    (binomial_model::phi_cdf(mid) < u ? lo : hi) = mid;
                }
                return 0.5 * (lo + hi);
            };
            for (int side = 0; side < 2; ++side) {  // u below and above u_split
                const double from = side ? u_split : 0.0, to = side ? 1.0 : u_split, shift = side ? (1 - w) * span : 0.0;
                if (to <= from) continue;
                const double atom_lo = std::max(0.0, std::min(u_a, to) - from), atom_hi = std::max(0.0, to - std::max(u_b, from));
                if (atom_lo > 0) d.atoms.push_back({place(shift), p_middle * atom_lo});
                if (atom_hi > 0) d.atoms.push_back({place(shift + w * span), p_middle * atom_hi});
                const double s_lo = std::max(u_a, from), s_hi = std::min(u_b, to);
                if (s_hi <= s_lo) continue;
                const double mu = shift + w * sigma * t, sd = w * sigma;
                if (!(sd > 0)) {
                    d.atoms.push_back({place(mu), p_middle * (s_hi - s_lo)});
                    continue;
                }
                // Clipped to the offset's range: z_of saturates at +-40 where Phi underflows.
                const double x_lo = std::max(mu + sd * z_of(s_lo), shift);
                const double x_hi = std::min(mu + sd * z_of(s_hi), shift + w * span);
                if (lower) d.segments.push_back({p_middle, 1 + mu, sd, 1 + x_lo, 1 + x_hi});
                else d.segments.push_back({p_middle, N - 1 - mu, sd, N - 1 - x_hi, N - 1 - x_lo});
            }
            break;
        }
    }
    if (variant == binomial_variant::unbiased && Nr > real(2) && Nr < k::GLINT_BINOMIAL_WALK_END) {
        // The walk (kernels/binomial.glsl, glint_binomial_walk) with weight w, the Gaussian middle
        // above with 1 - w. Component M = Na + 1 with probability f, else Na; its atoms are the
        // support points k N / M, each with the share of u1 for which the kernel's count, computed
        // in `real` as the kernel computes it, is k: P(count >= k) is where glint_binomial_walk_count
        // steps down, found by bisection on u1 (the count is non-increasing in u1).
        const double w = static_cast<double>(k::glint_binomial_walk_weight(Nr));
        for (auto& a : d.atoms) a.probability *= 1 - w;
        for (auto& g : d.segments) g.scale *= 1 - w;
        const bool lower = pr <= real(0.5);
        const real q = lower ? pr : real(1) - pr;
        const int Na = static_cast<int>(Nr);
        const double f = static_cast<double>(Nr - static_cast<real>(Na));
        auto place = [&](real x) { return lower ? static_cast<double>(x) : static_cast<double>(Nr - x); };
        for (int M = Na; M <= Na + 1; ++M) {
            const double share = (M == Na) ? 1 - f : f;
            if (!(share > 0)) continue;
            double above = 1;  // P(count >= k - 1)
            for (int j = 1; j <= M; ++j) {
                double lo = 0, hi = above;  // count(lo) >= j (or lo = 0), count(hi) < j
                for (int it = 0; it < 80; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi) break;
                    (k::glint_binomial_walk_count(M, q, static_cast<real>(mid)) >= j ? lo : hi) = mid;
                }
                d.atoms.push_back({place(static_cast<real>(j - 1) * (Nr / static_cast<real>(M))), w * share * (above - lo)});
                above = lo;
            }
            d.atoms.push_back({place(Nr), w * share * above});
        }
    }
    return d;
}

}  // namespace testing
}  // namespace glint
