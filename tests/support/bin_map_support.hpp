// Shared by the bin-map tests and the report: brute-force references written independently of
// glint/bin_map.hpp's tree walk (every lattice texel under the footprint's bounding box, the
// footprint's own parallelogram clipped by each texel's square, the centre test through the
// inverse map rather than per-row intervals), and random footprints.
#pragma once

#include <algorithm>
#include <utility>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glint/bin_map.hpp>
#include <glint/core.hpp>
#include <glint/normal_map.hpp>

namespace glint_test {

// A footprint in texels (double): o + a e0 + b e1, a, b in [0, 1).
struct texel_parallelogram {
    glm::dvec2 o, e0, e1;
};

template <class real>
texel_parallelogram in_texels(const glint::uv_parallelogram<real>& A, int w, int h) {
    const glm::dvec2 s(w, h);
    return {glm::dvec2(A.origin) * s, glm::dvec2(A.e0) * s, glm::dvec2(A.e1) * s};
}

// Calls fn(gx, gy) for every lattice texel (global, unwrapped) whose square meets P's bounding box.
template <class Fn>
void for_each_texel_under(const texel_parallelogram& P, Fn&& fn) {
    const glm::dvec2 c[4] = {P.o, P.o + P.e0, P.o + P.e1, P.o + P.e0 + P.e1};
    glm::dvec2 lo = c[0], hi = c[0];
    for (const auto& v : c) lo = glm::min(lo, v), hi = glm::max(hi, v);
    for (double y = std::floor(lo.y); y <= std::floor(hi.y); y += 1)
        for (double x = std::floor(lo.x); x <= std::floor(hi.x); x += 1) fn(x, y);
}

template <class real>
std::uint32_t wrapped_bin(const glint::bin_map<real>& m, double gx, double gy) {
    const long w = m.width(), h = m.height();
    const long x = ((static_cast<long>(gx) % w) + w) % w, y = ((static_cast<long>(gy) % h) + h) % h;
    return m.texel_bin(static_cast<int>(x), static_cast<int>(y));
}

// Per bin, the number of texel centres in P: (a, b) = inverse (centre - o) in [0, 1)^2.
template <class real>
std::vector<std::uint64_t> brute_counts(const glint::bin_map<real>& m, const texel_parallelogram& P) {
    std::vector<std::uint64_t> n(m.bin_count(), 0);
    const double det = P.e0.x * P.e1.y - P.e0.y * P.e1.x;
    for_each_texel_under(P, [&](double x, double y) {
        const glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - P.o;
        const double a = (d.x * P.e1.y - d.y * P.e1.x) / det, b = (P.e0.x * d.y - P.e0.y * d.x) / det;
        if (a >= 0 && a < 1 && b >= 0 && b < 1) ++n[wrapped_bin(m, x, y)];
    });
    return n;
}

// The area of P inside the square [x, x+1] x [y, y+1]: P's polygon clipped by the square's four
// half-planes (the roles reversed from the library's), shoelace.
inline double clipped_area(const texel_parallelogram& P, double x, double y) {
    glm::dvec2 poly[12] = {P.o - glm::dvec2(x, y), P.o + P.e0 - glm::dvec2(x, y), P.o + P.e0 + P.e1 - glm::dvec2(x, y), P.o + P.e1 - glm::dvec2(x, y)};
    std::size_t n = 4;
    const auto clip = [&](int axis, double bound, bool keep_below) {
        glm::dvec2 out[12];
        std::size_t m = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 p = poly[i], q = poly[(i + 1) % n];
            const bool pin = keep_below ? p[axis] <= bound : p[axis] >= bound, qin = keep_below ? q[axis] <= bound : q[axis] >= bound;
            if (pin) out[m++] = p;
            if (pin != qin) out[m++] = p + (q - p) * ((bound - p[axis]) / (q[axis] - p[axis]));
        }
        for (std::size_t i = 0; i < m; ++i) poly[i] = out[i];
        n = m;
    };
    clip(0, 0, false), clip(0, 1, true), clip(1, 0, false), clip(1, 1, true);
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % n];
        s += p.x * q.y - q.x * p.y;
    }
    return std::fabs(0.5 * s);
}

// Per bin, the exact-area coverage c_j = sum over its texels of |P n T_k| / |P|.
template <class real>
std::vector<double> brute_coverages(const glint::bin_map<real>& m, const texel_parallelogram& P) {
    std::vector<double> c(m.bin_count(), 0.0);
    for_each_texel_under(P, [&](double x, double y) { c[wrapped_bin(m, x, y)] += clipped_area(P, x, y); });
    const double area = std::fabs(P.e0.x * P.e1.y - P.e0.y * P.e1.x);
    for (double& v : c) v /= area;
    return c;
}

// The unbinned reference of the beckmann kernel: the texels under P with their own normals t_k
// and areas a_k = |P n T_k|, and the density sum_k a_k K(h; t_k) / |P| (K: the truncated,
// renormalised Beckmann lobe of glint/bin_map.hpp). The bins' quantisation of t_k is its only
// difference from bin_map::eval with the beckmann kernel.
struct unbinned_texels {
    std::vector<glm::dvec3> normal;
    std::vector<double> cumulative_area;  // running sum of a_k
    double alpha = 0.01, epsilon = 0.0111;

    unbinned_texels(const glint::normal_map& map, const texel_parallelogram& P, double a, double e) : alpha(a), epsilon(e) {
        double sum = 0;
        for_each_texel_under(P, [&](double x, double y) {
            const double area = clipped_area(P, x, y);
            if (!(area > 0)) return;
            normal.push_back(glm::dvec3(map.texel(static_cast<long>(x), static_cast<long>(y))));
            cumulative_area.push_back(sum += area);
        });
    }
    double lobe(const glm::dvec3& t, const glm::dvec3& h) const {
        const double c = glm::dot(t, h), cos_cap = 1 / std::sqrt(1 + alpha * alpha * std::log(1 / epsilon));
        if (c < cos_cap) return 0;
        return std::exp(-(1 - c * c) / (c * c) / (alpha * alpha)) / (3.141592653589793 * alpha * alpha * c * c * c) / (1 - epsilon);
    }
    double pdf(const glm::dvec3& h) const {
        if (!(h.z > 0)) return 0;
        double sum = 0, previous = 0;
        for (std::size_t k = 0; k < normal.size(); ++k) sum += (cumulative_area[k] - previous) * lobe(normal[k], h), previous = cumulative_area[k];
        return sum / cumulative_area.back();
    }
    // A texel by area (u0), then its lobe (u1, u2); z <= 0 when the draw falls below the horizon.
    glm::dvec3 sample(double u0, double u1, double u2) const {
        const std::size_t k = static_cast<std::size_t>(std::upper_bound(cumulative_area.begin(), cumulative_area.end(), u0 * cumulative_area.back()) - cumulative_area.begin());
        const glm::dvec3 n = normal[std::min(k, normal.size() - 1)];
        const double tan2 = -alpha * alpha * std::log(1 - u1 * (1 - epsilon)), c = 1 / std::sqrt(1 + tan2), s = std::sqrt(1 - c * c);
        const glm::dvec3 a = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 t = glm::normalize(glm::cross(a, n)), b = glm::cross(n, t);
        const double phi = 6.283185307179586 * u2;
        return glm::normalize(s * std::cos(phi) * t + s * std::sin(phi) * b + c * n);
    }
};

// The L1 distance between two densities p and r on the hemisphere (per solid angle), by
// sampling their mixture: E over (p + r) / 2 of 2 |p - r| / (p + r). sample_p(i) and sample_r(i)
// return the i-th draw (z <= 0: lost below the horizon, where both are 0). Returns the estimate
// and its standard error.
template <class SampleP, class SampleR, class P, class R>
std::pair<double, double> mixture_l1(int draws, SampleP&& sample_p, SampleR&& sample_r, P&& p, R&& r) {
    double s = 0, s2 = 0;
    for (int i = 0; i < draws; ++i) {
        const glm::dvec3 h = i % 2 ? sample_r(i) : sample_p(i);
        double v = 0;
        if (h.z > 0) {
            const double a = p(h), b = r(h);
            v = a + b > 0 ? 2 * std::fabs(a - b) / (a + b) : 0.0;
        }
        s += v, s2 += v * v;
    }
    const double mean = s / draws;
    return {mean, std::sqrt(std::max(0.0, s2 / draws - mean * mean) / draws)};
}

// A random footprint (uv) from counter-based uniforms: centre anywhere in [-1.5, 2.5)^2 uv (so
// that it crosses seams and corners), sides log-uniform from lo to hi texels, aspect up to
// `aspect`, rotated and sheared.
template <class real>
glint::uv_parallelogram<real> random_parallelogram(std::uint32_t i, std::uint32_t seed, int w, int h, double lo, double hi, double aspect = 8) {
    const auto u = [&](std::uint32_t k) { return glint::unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, seed, k)).x); };
    const double side = lo * std::pow(hi / lo, u(0)), ratio = std::pow(aspect, u(1));
    const double t = 6.283185307179586 * u(2), shear = 0.8 * (u(3) - 0.5);
    const glm::dvec2 a(std::cos(t), std::sin(t)), b(-std::sin(t + shear), std::cos(t + shear));
    const glm::dvec2 c(-1.5 + 4 * u(4), -1.5 + 4 * u(5));
    const glm::dvec2 e0 = a * side / glm::dvec2(w, h), e1 = b * (side / ratio) / glm::dvec2(w, h);
    glint::uv_parallelogram<real> A;
    A.e0 = glm::vec<2, real, glm::defaultp>(e0), A.e1 = glm::vec<2, real, glm::defaultp>(e1);
    A.origin = glm::vec<2, real, glm::defaultp>(c - 0.5 * (e0 + e1));
    return A;
}

}  // namespace glint_test
