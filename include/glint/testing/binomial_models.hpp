// The closed-form output distribution of each approximate binomial sampler (glint/binomial.hpp),
// evaluated in double from the kernels' own double instantiation, for tables and tests that
// judge an approximation without randomness. Every sampler's output is a mixture of atoms and
// Gaussian segments (a Gaussian density restricted to an interval), except DB23's, whose floor
// makes a floored clamped Gaussian; model::cdf, mean and variance are exact for those forms.
#pragma once

#include <cmath>
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

// The closed-form distribution of `variant` at (N, p), with (1 - p)^N evaluated by `method` in
// double.
inline binomial_model model_of(binomial_variant variant, double N, double p, pow_method method) {
    using k = glint::detail::glsl::binomial_kernels<double>;
    const int m = static_cast<int>(method);
    N = std::max(N, 0.0);
    p = std::min(std::max(p, 0.0), 1.0);
    binomial_model d;
    switch (variant) {
        case binomial_variant::ungated:
            d.add_clamped_gaussian(1, N * p, std::sqrt(N * p * (1 - p)), 0, N);
            break;
        case binomial_variant::gated_db23: {
            const double gate = k::glint_any_success(p, N, m), rest = std::max(N - 1, 0.0);
            d.atoms.push_back({0, 1 - gate});
            if (N < 1) d.atoms.push_back({0, gate});
            else d.floor_part = {gate, 1 + rest * p, std::sqrt(rest * p * (1 - p)), N};
            break;
        }
        case binomial_variant::gated: {
            const double gate = std::min(N * p, k::glint_any_success(p, N, m)), top = std::max(N, 1.0), rest = top - 1;
            d.atoms.push_back({0, 1 - gate});
            d.add_clamped_gaussian(gate, 1 + rest * p, std::sqrt(rest * p * (1 - p)), 1, top);
            break;
        }
        case binomial_variant::dual_gated:
        case binomial_variant::unbiased: {
            const double N2 = std::max(N, 2.0), weight_2 = std::min(std::max(N - 1, 0.0), 1.0),
                         weight_1 = std::max(0.0, 1 - std::fabs(1 - N));
            if (N <= 2) {  // KK25 Fig. 4: the outcomes of N = 1 and N = 2, both variants alike
                const double two = weight_2 * p * p, one = weight_1 * p + weight_2 * 2 * p * (1 - p);
                d.atoms.push_back({2, two});
                d.atoms.push_back({1, one});
                d.atoms.push_back({0, 1 - two - one});
                break;
            }
            if (variant == binomial_variant::dual_gated) {
                const double all_positive = std::pow(p, N), all_negative = k::glint_pow_one_minus(p, N, m);
                d.atoms.push_back({N, all_positive});
                d.atoms.push_back({0, all_negative});
                // P(middle) = P(n >= 1) - p^N, with P(n >= 1) as the method evaluates it.
                d.add_clamped_gaussian(std::max(k::glint_any_success(p, N, m) - all_positive, 0.0), 1 + (N - 2) * p, std::sqrt((N - 2) * p * (1 - p)), 1, N - 1);
                break;
            }
            const auto q = k::glint_binomial_unbiased_setup(N2, p, m);
            const double weight = std::max(k::glint_any_success(p, N, m) - q.all_positive, 0.0);
            d.atoms.push_back({N, q.all_positive});
            d.atoms.push_back({0, q.all_negative});
            // offset o = clamp(sigma (t + s), 0, span), remapped to a + b o.
            const double a = q.far_scale >= 0 ? q.span * (1 - q.far_scale) : 0.0, b = std::fabs(q.far_scale);
            const bool lower = q.lower > 0.5;
            auto place = [&](double offset) { return lower ? 1 + offset : N - 1 - offset; };
            if (q.span <= 1) {  // two counts, 1 and N - 1
                d.atoms.push_back({place(0), weight * (1 - q.two_point)});
                d.atoms.push_back({place(q.span), weight * q.two_point});
                break;
            }
            const double at_zero = q.sigma > 0 ? binomial_model::phi_cdf(-q.t) : 1.0;
            const double at_span = q.sigma > 0 ? binomial_model::phi_cdf(q.t - q.span / q.sigma) : 0.0;
            d.atoms.push_back({place(a), weight * at_zero});
            d.atoms.push_back({place(a + b * q.span), weight * at_span});
            if (q.sigma > 0 && b > 0 && q.span > 0) {
                const double mu = a + b * q.sigma * q.t, sd = b * q.sigma;
                if (lower) d.segments.push_back({weight, 1 + mu, sd, 1 + a, 1 + a + b * q.span});
                else d.segments.push_back({weight, N - 1 - mu, sd, N - 1 - a - b * q.span, N - 1 - a});
            }
            break;
        }
    }
    return d;
}

}  // namespace testing
}  // namespace glint
