// Scratched materials across scales (RGB16, Raymond, Guennebaud and Barla 2016): scratch
// profiles, the 2D scratch BRDF table ray-traced in the profile's cross-section with every
// inter-reflection and Fresnel (Sec. 4.1-4.2), and the per-pixel kernels of kernels/scratch.glsl
// (cone parametrization, Eq. 2, importance sampling, point lights, the SV-BRDF's layer mix and the
// procedural scratch layers of Eq. 7).
//
//   auto profile = glint::make_quartic_groove(0.5);                       // steep quartic, D/W 0.5
//   auto table = glint::build_scratch_table(profile, glint::scratch_fresnel::iron());  // host, may throw
//   auto view = table.view<float>();                                      // per pixel from here
//   auto f = glint::make_scratch_frame(n, tangent);
//   auto smp = view.sample(f, wo, u1, u2);                                // L_r ~ smp.weight * L_i(smp.wi)
//   glm::vec3 L = view.light_radiance(f, wo, wl, I / r2);                 // a point light (Eq. 6)
//   auto mat = glint::scratch_material::build(table, glint::scratch_distribution{});  // layers, coverage
//   auto lit = mat.view<float>().light(f, x, a, b, wo, wl, I / r2);      // the SV-BRDF (Eq. 4, 6):
//   // radiance = lit.radiance + lit.base_weight * base_brdf(wl, wo) * cos * I / r2
//
// The table (Sec. 4.1, notes 1.3): M x M bins over (phi_o, phi_i) in [-pi/2, pi/2]^2, bins of equal
// angle. For each incident bin i, N rays enter the opening x in [-1/2, 1/2] (stratified) with
// sin(phi_i) uniform in the bin (the cosine-weighted measure ds that makes the bin averages of a
// reciprocal BRDF a symmetric matrix), are mirror-reflected in the profile until they leave (or
// reach max_bounces, counted as lost) and are counted in the bin of their exit angle phi_o. A bin
// holds rho = count / (N ds_o): the BRDF per unit projected measure, so each raw row sums (with
// weights ds) to exactly 1 - its lost fraction, and the per-ray 1 / cos(phi_o) weight of RGB16
// (unbounded variance in the edge bins) is not needed. One trace fills three slices: the mirror
// rho_m (F = 1; also the theta = pi/2 slice, where the 3D cosine is 0), rho_0 (the product of F at
// each bounce's 3D cosine cos(theta) |d.m| with theta = 0) and rho_60 (theta = pi/3: |d.m| / 2). Then
// rho <- (rho + rho^T) / 2 (reciprocity), and for profiles symmetric in x also
// rho[o][i] <- (rho[o][i] + rho[M-1-o][M-1-i]) / 2 (RGB16: up to 4x the rays for free); then per bin
// and channel Eq. 2's exponent gamma = ln r / ln(2/3), r = (rho_60 - rho_0) / (rho_m - rho_0)
// clamped to [1e-4, 1 - 1e-4] (gamma <= 22.7), gamma = 1 where rho_m - rho_0 <= 1e-6 rho_m.
//
// Colour: rho_0 and gamma per RGB channel, rho_m shared (it has no Fresnel). Rays are traced in
// double, each row from its own counter-based random stream, so the table is bit-identical for any
// thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "glint/core/error.hpp"
#include "glint/core/hash.hpp"
#include "glint/detail/kernels.hpp"
#include "glint/microfacet.hpp"

namespace glint {

// A scratch's cross-section: an x-monotone polyline (x strictly increasing from -1/2 to 1/2, the
// scratch's width 1) of heights h <= 0 dug into a flat base at height 0. The BRDF depends only on
// the shape (RGB16 Sec. 4.3: invariant to uniform scaling). periodic: the profile repeats with
// period 1 and is traced so (profiles with bulges above the base, RGB16 Sec. 5.3); symmetric: h(x)
// = h(-x), which lets the table average its anti-diagonal mirror.
struct scratch_profile {
    std::vector<double> x, h;
    bool periodic = false;
    bool symmetric = false;
};

namespace detail {
inline std::string scratch_number(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}

// Sizes, finiteness and x strictly increasing: the polyline itself.
inline void check_scratch_points(const std::vector<double>& x, const std::vector<double>& h, const std::string& what) {
    if (x.size() < 2 || x.size() != h.size())
        throw error(what + "a profile needs at least 2 points and as many heights as x values (got " + std::to_string(x.size()) + " x, " +
                    std::to_string(h.size()) + " h)");
    for (std::size_t k = 0; k < x.size(); ++k) {
        if (!std::isfinite(x[k]) || !std::isfinite(h[k]))
            throw error(what + "point " + std::to_string(k) + " is not finite (x = " + scratch_number(x[k]) + ", h = " + scratch_number(h[k]) + ")");
        if (k > 0 && !(x[k] > x[k - 1]))
            throw error(what + "x is not strictly increasing at point " + std::to_string(k) + " (x = " + scratch_number(x[k - 1]) + " then " +
                        scratch_number(x[k]) + ")");
    }
}

inline void check_scratch_profile(const scratch_profile& p, const std::string& what) {
    check_scratch_points(p.x, p.h, what);
    for (std::size_t k = 0; k < p.x.size(); ++k)
        if (p.h[k] > 0) throw error(what + "h = " + scratch_number(p.h[k]) + " > 0 at point " + std::to_string(k) + " (the base is at 0)");
    if (std::fabs(p.x.front() + 0.5) > 1e-12 || std::fabs(p.x.back() - 0.5) > 1e-12)
        throw error(what + "x must span [-1/2, 1/2] (got [" + scratch_number(p.x.front()) + ", " + scratch_number(p.x.back()) + "])");
    if (!p.periodic && (p.h.front() != 0 || p.h.back() != 0))
        throw error(what + "a non-periodic profile starts and ends on the base, h = 0 (got h = " + scratch_number(p.h.front()) + " and " +
                    scratch_number(p.h.back()) + ")");
    if (p.periodic && p.h.front() != p.h.back())
        throw error(what + "a periodic profile ends where it starts (got h = " + scratch_number(p.h.front()) + " and " + scratch_number(p.h.back()) + ")");
}

inline bool profile_is_symmetric(const scratch_profile& p) {
    const std::size_t n = p.x.size();
    for (std::size_t k = 0; k < n; ++k)
        if (std::fabs(p.x[k] + p.x[n - 1 - k]) > 1e-12 || std::fabs(p.h[k] - p.h[n - 1 - k]) > 1e-12 * (1 + std::fabs(p.h[k]))) return false;
    return true;
}
}  // namespace detail

// The flat profile: no groove (the table is the mirror's anti-diagonal).
inline scratch_profile make_flat_profile() {
    scratch_profile p;
    p.x = {-0.5, 0.5}, p.h = {0, 0}, p.symmetric = true;
    return p;
}

// A V-groove whose two facets rise at facet_angle (radians, in [1, 80] degrees) from the base: a
// ray at normal incidence leaves a facet at +-2 facet_angle.
inline scratch_profile make_v_groove(double facet_angle) {
    const double deg = 0.017453292519943295769;  // pi / 180, 20 digits
    if (!(facet_angle >= 1 * deg && facet_angle <= 80 * deg))
        throw error("glint::make_v_groove: facet_angle = " + detail::scratch_number(facet_angle) + " rad is outside [1, 80] degrees");
    scratch_profile p;
    p.x = {-0.5, 0, 0.5}, p.h = {0, -0.5 * std::tan(facet_angle), 0}, p.symmetric = true;
    return p;
}

// The quartic groove h = -D (1 - (2x)^4), D = depth_over_width in [0.02, 1], sampled at
// `segments` + 1 evenly spaced x (2 to 65536): flat-bottomed with walls of slope 8 D at the edges
// (RGB16 Fig. 5's shallow and steep quartics; the formula is ours, the paper gives none).
inline scratch_profile make_quartic_groove(double depth_over_width, int segments = 1024) {
    if (!(depth_over_width >= 0.02 && depth_over_width <= 1))
        throw error("glint::make_quartic_groove: depth_over_width = " + detail::scratch_number(depth_over_width) + " is outside [0.02, 1]");
    if (segments < 2 || segments > 65536) throw error("glint::make_quartic_groove: segments = " + std::to_string(segments) + " is outside [2, 65536]");
    scratch_profile p;
    for (int k = 0; k <= segments; ++k) {
        const double x = -0.5 + static_cast<double>(k) / segments, s = 2 * x;
        p.x.push_back(x);
        p.h.push_back(k == 0 || k == segments ? 0.0 : -depth_over_width * (1 - s * s * s * s));
    }
    p.symmetric = true;
    return p;
}

// A one-facet ramp: one facet falling at facet_angle (radians, [1, 60] degrees) from the left edge,
// then a wall at 85 degrees back up to the base at the right edge (asymmetric).
inline scratch_profile make_ramp_profile(double facet_angle) {
    const double deg = 0.017453292519943295769;  // pi / 180, 20 digits
    if (!(facet_angle >= 1 * deg && facet_angle <= 60 * deg))
        throw error("glint::make_ramp_profile: facet_angle = " + detail::scratch_number(facet_angle) + " rad is outside [1, 60] degrees");
    // Facet to x_w, wall from x_w to 1/2: tan(facet) (x_w + 1/2) = tan(85 deg) (1/2 - x_w).
    const double a = std::tan(facet_angle), b = std::tan(85 * deg);
    const double xw = (0.5 * b - 0.5 * a) / (a + b);
    scratch_profile p;
    p.x = {-0.5, xw, 0.5}, p.h = {0, -a * (xw + 0.5), 0};
    return p;
}

// A tabulated (measured) profile: x strictly increasing, any range (rescaled to width 1 with the
// heights, keeping the aspect). Heights above the base (bulges) make it periodic: the highest point
// becomes the base and the profile repeats (RGB16 Sec. 5.3); so does periodic = true. A non-periodic
// profile must start and end at height 0, a periodic one end at the height it starts. Throws
// glint::error naming the point and value otherwise.
inline scratch_profile make_tabulated_profile(std::vector<double> x, std::vector<double> h, bool periodic = false) {
    const std::string what = "glint::make_tabulated_profile: ";
    detail::check_scratch_points(x, h, what);
    const double width = x.back() - x.front();
    const double x0 = x.front();
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = (x[k] - x0) / width - 0.5, h[k] /= width;
    x.front() = -0.5, x.back() = 0.5;
    const double top = *std::max_element(h.begin(), h.end());
    scratch_profile p;
    p.periodic = periodic || top > 0;
    if (p.periodic)
        for (double& v : h) v -= top;
    p.x = std::move(x), p.h = std::move(h);
    detail::check_scratch_profile(p, what);
    p.symmetric = detail::profile_is_symmetric(p);
    return p;
}

// Fresnel inside the scratch, per RGB channel (host side: the table bakes it).
enum class fresnel_model {
    mirror,            // F = 1
    schlick,           // f0 + (1 - f0)(1 - c)^5 (RGB16's model for dielectrics)
    lazanyi,           // Lazanyi and Szirmay-Kalos 2005: ((n-1)^2 + k^2 + 4n(1-c)^5) / ((n+1)^2 + k^2) - a c (1-c)^alpha (RGB16's for conductors)
    dielectric_exact,  // unpolarised Fresnel of a dielectric of index eta (from outside)
    conductor_exact    // unpolarised Fresnel of a conductor eta + i k (glint_fresnel_conductor)
};

struct scratch_fresnel {
    fresnel_model model = fresnel_model::mirror;
    glm::dvec3 f0{1.0};          // schlick
    glm::dvec3 eta{1.5};         // lazanyi, dielectric_exact, conductor_exact: n > 0
    glm::dvec3 k{0.0};           // lazanyi, conductor_exact: k >= 0
    double lazanyi_a = 0;        // lazanyi's correction term (0: Schlick's form for conductors)
    double lazanyi_alpha = 6;

    static scratch_fresnel mirror() { return {}; }
    static scratch_fresnel schlick(glm::dvec3 f0) {
        scratch_fresnel f;
        f.model = fresnel_model::schlick, f.f0 = f0;
        return f;
    }
    // Iron at 650 nm, n = 2.91, k = 3.09 (RGB16 Fig. 7), exact conductor Fresnel, grey.
    static scratch_fresnel iron() {
        scratch_fresnel f;
        f.model = fresnel_model::conductor_exact, f.eta = glm::dvec3(2.91), f.k = glm::dvec3(3.09);
        return f;
    }
    // Plastic, n = 1.5 (RGB16 Fig. 12c), exact dielectric Fresnel.
    static scratch_fresnel plastic() {
        scratch_fresnel f;
        f.model = fresnel_model::dielectric_exact, f.eta = glm::dvec3(1.5);
        return f;
    }

    // F of channel ch at the cosine c (clamped to [0, 1]) of the angle to the microsurface normal.
    double channel(int ch, double c) const {
        c = std::min(std::max(c, 0.0), 1.0);
        const double n = eta[ch], kk = k[ch], m = 1 - c, m5 = m * m * m * m * m;
        double r = 1;
        switch (model) {
            case fresnel_model::mirror: r = 1; break;
            case fresnel_model::schlick: r = f0[ch] + (1 - f0[ch]) * m5; break;
            case fresnel_model::lazanyi:
                r = ((n - 1) * (n - 1) + kk * kk + 4 * n * m5) / ((n + 1) * (n + 1) + kk * kk) - lazanyi_a * c * std::pow(m, lazanyi_alpha);
                break;
            case fresnel_model::dielectric_exact: {
                const double s2 = (1 - c * c) / (n * n);
                if (s2 >= 1) return 1;
                const double ct = std::sqrt(1 - s2);
                const double rs = (c - n * ct) / (c + n * ct), rp = (n * c - ct) / (n * c + ct);
                r = 0.5 * (rs * rs + rp * rp);
                break;
            }
            case fresnel_model::conductor_exact: r = detail::glsl::kernels<double>::glint_fresnel_conductor(n, kk, c); break;
        }
        return std::min(std::max(r, 0.0), 1.0);
    }
    glm::dvec3 operator()(double c) const { return glm::dvec3(channel(0, c), channel(1, c), channel(2, c)); }
    // Whether every channel has the same parameters (one evaluation serves all three).
    bool grey() const { return f0.x == f0.y && f0.y == f0.z && eta.x == eta.y && eta.y == eta.z && k.x == k.y && k.y == k.z; }

    void check(const std::string& what) const {
        for (int ch = 0; ch < 3; ++ch) {
            if (model == fresnel_model::schlick && !(f0[ch] >= 0 && f0[ch] <= 1))
                throw error(what + "Schlick f0 = " + detail::scratch_number(f0[ch]) + " is outside [0, 1]");
            if (model != fresnel_model::mirror && model != fresnel_model::schlick) {
                if (!(eta[ch] > 0 && std::isfinite(eta[ch]))) throw error(what + "Fresnel eta = " + detail::scratch_number(eta[ch]) + " is not positive");
                if (!(k[ch] >= 0 && std::isfinite(k[ch]))) throw error(what + "Fresnel k = " + detail::scratch_number(k[ch]) + " is negative");
            }
        }
        if (model == fresnel_model::lazanyi && !(std::isfinite(lazanyi_a) && lazanyi_alpha >= 0))
            throw error(what + "Lazanyi a = " + detail::scratch_number(lazanyi_a) + ", alpha = " + detail::scratch_number(lazanyi_alpha));
    }
};

struct scratch_table_options {
    int resolution = 256;      // M, bins per axis: [8, 4096] (RGB16 Sec. 6.1: 256)
    int rays_per_row = 10000;  // N per incident bin: [16, 1e8] (RGB16: 10,000)
    int max_bounces = 64;      // rays still inside after this many are lost (reported): [1, 4096]
    int threads = 0;           // 0: std::thread::hardware_concurrency()
    std::uint32_t seed = 0;
    bool symmetrize = true;    // false keeps the raw traced table (the reciprocity test's input)
    std::function<void(int rows_done, int rows)> progress;  // called from the workers, serialised
};

namespace detail {

// Fresnel tabulated over the cosine for the tracer: 4096 equal steps per channel, read linearly.
// Exact Fresnel costs about 15 ns per channel and bounce and dominated colour tables; the table's
// error is at most max|F''| / (8 4096^2) (Schlick: 20 / 1.3e8 = 1.5e-7); measured below 1e-6 for
// every preset (tests/unit/test_scratch.cpp: 5.3e-7 at worst, iron).
struct fresnel_table {
    static constexpr int steps = 4096;
    std::vector<glm::dvec3> v;
    explicit fresnel_table(const scratch_fresnel& f) : v(steps + 1) {
        for (int i = 0; i <= steps; ++i) v[static_cast<std::size_t>(i)] = f(static_cast<double>(i) / steps);
    }
    glm::dvec3 operator()(double c) const {
        const double t = std::min(std::max(c, 0.0), 1.0) * steps;
        const int i = std::min(static_cast<int>(t), steps - 1);
        const double w = t - i;
        const glm::dvec3 &a = v[static_cast<std::size_t>(i)], &b = v[static_cast<std::size_t>(i + 1)];
        return a + w * (b - a);
    }
    double first(double c) const {
        const double t = std::min(std::max(c, 0.0), 1.0) * steps;
        const int i = std::min(static_cast<int>(t), steps - 1);
        const double w = t - i, a = v[static_cast<std::size_t>(i)].x;
        return a + w * (v[static_cast<std::size_t>(i + 1)].x - a);
    }
};

// The profile's polyline prepared for tracing: segment normals and a binary tree of the highest
// point under each node, so a ray finds its next hit in about log2(segments) node tests: a node
// the ray passes above over the node's x range holds no hit.
struct scratch_tracer {
    std::vector<double> x, h, mx, my;  // points; unit normals of segments (pointing up)
    struct node {
        double xl, xr, top;  // x range and highest point; an empty node has xl > xr
        int lo;              // its first segment
    };
    std::vector<node> nodes;  // node 1 is the root; leaves `leaves` .. 2 leaves - 1
    int segments = 0, leaves = 1;
    bool periodic = false, convex = false;

    explicit scratch_tracer(const scratch_profile& p) : x(p.x), h(p.h), periodic(p.periodic) {
        segments = static_cast<int>(x.size()) - 1;
        for (int k = 0; k < segments; ++k) {
            const double dx = x[static_cast<std::size_t>(k + 1)] - x[static_cast<std::size_t>(k)];
            const double dh = h[static_cast<std::size_t>(k + 1)] - h[static_cast<std::size_t>(k)], l = std::hypot(dx, dh);
            mx.push_back(-dh / l), my.push_back(dx / l);
        }
        convex = !periodic;
        for (int k = 0; k + 1 < segments; ++k)
            if (my[static_cast<std::size_t>(k)] * mx[static_cast<std::size_t>(k + 1)] - mx[static_cast<std::size_t>(k)] * my[static_cast<std::size_t>(k + 1)] > 1e-12) convex = false;
        while (leaves < segments) leaves *= 2;
        const double inf = std::numeric_limits<double>::infinity();
        nodes.assign(static_cast<std::size_t>(2 * leaves), node{inf, -inf, -inf, 0});
        for (int k = 0; k < segments; ++k) {
            const std::size_t a = static_cast<std::size_t>(k);
            nodes[static_cast<std::size_t>(leaves + k)] = node{x[a], x[a + 1], std::max(h[a], h[a + 1]), k};
        }
        for (int q = leaves - 1; q >= 1; --q) {
            const node &a = nodes[static_cast<std::size_t>(2 * q)], &b = nodes[static_cast<std::size_t>(2 * q + 1)];
            nodes[static_cast<std::size_t>(q)] = node{std::min(a.xl, b.xl), std::max(a.xr, b.xr), std::max(a.top, b.top), a.lo};
        }
    }

    struct exit_ray {
        double dx, dy;
        glm::dvec3 f0, f60;  // Fresnel products at theta = 0 and pi/3
        int bounces;
        bool lost;
    };

    struct hit {
        int k;
        double x, y;
    };

    // first_hit for a convex, non-periodic profile (slopes non-decreasing: the V-groove, the
    // quartic, the ramp, flat): the region above it is convex, so f(x) = ray height - h(x) is
    // concave along the ray and, from f >= 0 at the ray's start, positive up to one crossing; a
    // binary search over the vertices ahead finds the first with f <= 0, and the crossing lies in the
    // segment ending there (computed as first_hit's leaf test computes it, so the two agree).
    hit first_hit_convex(double px, double py, double dx, double dy, int skip) const {
        hit r{-1, 0, 0};
        const double slope = dy / dx;
        const auto f = [&](int v) { return py + (x[static_cast<std::size_t>(v)] - px) * slope - h[static_cast<std::size_t>(v)]; };
        int v;  // the first vertex ahead with f <= 0
        if (dx > 0) {
            int lo = static_cast<int>(std::upper_bound(x.begin(), x.end(), px) - x.begin()), hi = segments;
            if (lo > segments || !(f(segments) <= 0)) return r;
            while (lo < hi) {
                const int mid = (lo + hi) / 2;
                if (f(mid) <= 0) hi = mid;
                else lo = mid + 1;
            }
            v = lo;
            if (v - 1 == skip) return r;
            const int k = v - 1;
            const double xl = std::max(x[static_cast<std::size_t>(k)], px), xr = x[static_cast<std::size_t>(v)];
            leaf(r, k, px, py, slope, 1, xl, xr, 0);
        } else {
            int hi = static_cast<int>(std::lower_bound(x.begin(), x.end(), px) - x.begin()) - 1, lo = 0;
            if (hi < 0 || !(f(0) <= 0)) return r;
            while (lo < hi) {
                const int mid = (lo + hi + 1) / 2;
                if (f(mid) <= 0) lo = mid;
                else hi = mid - 1;
            }
            v = lo;
            if (v == skip) return r;
            const double xl = x[static_cast<std::size_t>(v)], xr = std::min(x[static_cast<std::size_t>(v + 1)], px);
            leaf(r, v, px, py, slope, -1, xl, xr, 0);
        }
        return r;
    }

    // The crossing of segment k (clipped to [xl, xr], offset off) by the ray, if the ray is below
    // it at the far end in travel direction sx.
    bool leaf(hit& r, int k, double px, double py, double slope, int sx, double xl, double xr, double off) const {
        const double yl = py + (xl - px) * slope, yr = py + (xr - px) * slope;
        const double ha = h[static_cast<std::size_t>(k)], hb = h[static_cast<std::size_t>(k + 1)];
        const double xa0 = x[static_cast<std::size_t>(k)] + off, xb0 = x[static_cast<std::size_t>(k + 1)] + off;
        const double hl = ha + (xl - xa0) / (xb0 - xa0) * (hb - ha), hr = ha + (xr - xa0) / (xb0 - xa0) * (hb - ha);
        const double xn = sx > 0 ? xl : xr, xf = sx > 0 ? xr : xl;
        const double fn = (sx > 0 ? yl - hl : yr - hr), ff = (sx > 0 ? yr - hr : yl - hl);
        if (!(ff <= 0)) return false;
        const double t = fn > 0 ? fn / (fn - ff) : 0;
        const double hn = sx > 0 ? hl : hr, hf = sx > 0 ? hr : hl;
        r.k = k, r.x = xn + t * (xf - xn), r.y = hn + t * (hf - hn);
        return true;
    }

    // The first segment of the period at offset off that the ray (px, py) + t (dx, dy), t > 0,
    // crosses from above, skipping segment skip (the one it leaves); k = -1 for none.
    hit first_hit(double px, double py, double dx, double dy, double off, int skip) const {
        hit r{-1, 0, 0};
        const int sx = dx > 0 ? 1 : -1;
        const double slope = dy / dx;
        int stack[64];
        int top = 0;
        stack[top++] = 1;
        while (top > 0) {
            const std::size_t q = static_cast<std::size_t>(stack[--top]);
            const node& nd = nodes[q];
            double xl = nd.xl + off, xr = nd.xr + off;
            if (!(xl <= xr)) continue;
            if (sx > 0) {
                if (xr < px) continue;
                xl = std::max(xl, px);
            } else {
                if (xl > px) continue;
                xr = std::min(xr, px);
            }
            const double yl = py + (xl - px) * slope, yr = py + (xr - px) * slope;
            if (std::min(yl, yr) > nd.top) continue;
            if (static_cast<int>(q) >= leaves) {
                if (nd.lo != skip && leaf(r, nd.lo, px, py, slope, sx, xl, xr, off)) return r;
                continue;
            }
            // Children, the near one on top of the stack.
            const int a = 2 * static_cast<int>(q), b = a + 1;
            if (sx > 0) stack[top++] = b, stack[top++] = a;
            else stack[top++] = a, stack[top++] = b;
        }
        return r;
    }

    // Traces a ray entering the opening at (x0, 0) with direction (dx, dy), dy < 0: mirror
    // reflections until it rises above the base (heights are <= 0) or max_bounces is reached (lost).
    // fresnel: nullptr for a mirror; grey: one channel serves all three.
    exit_ray trace(double x0, double dx, double dy, int max_bounces, const fresnel_table* fresnel, bool grey) const {
        exit_ray r{dx, dy, glm::dvec3(1.0), glm::dvec3(1.0), 0, false};
        double px = x0, py = 0;
        int skip = -1;
        double skip_off = 0;
        for (;;) {
            if (r.dy > 0 && py >= 0) return r;
            hit hh{-1, 0, 0};
            double off = periodic ? std::floor(px + 0.5) : 0;
            if (r.dx == 0) {
                if (!(r.dy < 0)) return r;
                const std::size_t k = static_cast<std::size_t>(std::min(segments - 1, static_cast<int>(std::upper_bound(x.begin(), x.end(), px - off) - x.begin()) - 1));
                if (static_cast<int>(k) == skip && off == skip_off) return r;
                hh.k = static_cast<int>(k), hh.x = px, hh.y = h[k] + (px - off - x[k]) / (x[k + 1] - x[k]) * (h[k + 1] - h[k]);
            } else {
                for (int periods = 0;; ++periods) {
                    if (periods > 4096) {  // a ray creeping along a periodic profile: give up
                        r.lost = true;
                        return r;
                    }
                    hh = convex ? first_hit_convex(px, py, r.dx, r.dy, skip) : first_hit(px, py, r.dx, r.dy, off, off == skip_off ? skip : -1);
                    if (hh.k >= 0 || !periodic) break;
                    const double xe = (r.dx > 0 ? 0.5 : -0.5) + off;
                    if (r.dy > 0 && py + (xe - px) * (r.dy / r.dx) >= 0) return r;
                    off += r.dx > 0 ? 1 : -1;
                }
            }
            if (hh.k < 0) return r;  // none ahead: the ray leaves (the caller counts one still going down as lost)
            if (r.bounces >= max_bounces) {
                r.lost = true;
                return r;
            }
            const double nx = mx[static_cast<std::size_t>(hh.k)], ny = my[static_cast<std::size_t>(hh.k)];
            const double d = r.dx * nx + r.dy * ny;
            r.dx -= 2 * d * nx, r.dy -= 2 * d * ny;
            const double l = std::sqrt(r.dx * r.dx + r.dy * r.dy);
            r.dx /= l, r.dy /= l;
            if (fresnel) {
                if (grey) r.f0 *= fresnel->first(std::fabs(d)), r.f60 *= fresnel->first(0.5 * std::fabs(d));
                else r.f0 *= (*fresnel)(std::fabs(d)), r.f60 *= (*fresnel)(0.5 * std::fabs(d));
            }
            ++r.bounces;
            px = hh.x, py = hh.y, skip = hh.k, skip_off = off;
        }
    }
};

inline double scratch_unit(std::uint32_t h) { return (static_cast<double>(h) + 0.5) * 2.3283064365386962890625e-10; }  // 2^-32

}  // namespace detail

// The scratch BRDF table of a profile and Fresnel (RGB16 Sec. 4.1-4.2); see the header comment.
class scratch_table {
public:
    int resolution() const { return m_; }
    // Slices, row-major [o * M + i] (row phi_o's bin, column phi_i's), per unit ds: the mirror
    // rho_m, and per channel c rho_0, rho_60 (the theta = pi/3 slice) and Eq. 2's gamma.
    const std::vector<double>& rho_m() const { return rho_m_; }
    const std::vector<double>& rho_0(int c) const { return rho_0_[static_cast<std::size_t>(c)]; }
    const std::vector<double>& rho_60(int c) const { return rho_60_[static_cast<std::size_t>(c)]; }
    const std::vector<double>& gamma(int c) const { return gamma_[static_cast<std::size_t>(c)]; }
    // Row o's mirror albedo sum_i rho_m[o][i] ds_i.
    const std::vector<double>& row_albedo() const { return albedo_; }
    // The fraction of rays still inside after max_bounces, per incident bin; mean and max.
    const std::vector<double>& lost_fraction_per_row() const { return lost_; }
    double lost_fraction() const {
        double s = 0;
        for (double v : lost_) s += v;
        return s / static_cast<double>(lost_.size());
    }
    double max_lost_fraction() const { return *std::max_element(lost_.begin(), lost_.end()); }
    // The largest bounce count any ray needed (before the cap).
    int max_bounces_seen() const { return max_bounces_seen_; }

    // Bin i's width in s = sin(phi) among M bins (kernels/scratch.glsl).
    static double bin_ds(int i, int M) { return detail::glsl::kernels<double>::glint_scratch_bin_ds(i, M); }

    // The packed table kernels/scratch.glsl reads (its layout in that file's header), in the kernel's
    // precision.
    template <class real>
    const std::vector<glm::vec<4, real, glm::defaultp>>& data() const {
        if constexpr (std::is_same<real, float>::value) return data_f_;
        else return data_d_;
    }
    std::size_t memory_bytes() const { return data_f_.size() * sizeof(glm::vec4); }

    template <class real>
    struct view_t;
    template <class real>
    view_t<real> view() const;

    friend scratch_table build_scratch_table(const scratch_profile&, const scratch_fresnel&, const scratch_table_options&);

private:
    int m_ = 0, max_bounces_seen_ = 0;
    std::vector<double> rho_m_, albedo_, lost_;
    std::vector<double> rho_0_[3], rho_60_[3], gamma_[3];
    std::vector<glm::vec4> data_f_;
    std::vector<glm::dvec4> data_d_;

    void pack() {
        const int M = m_;
        const std::size_t n = static_cast<std::size_t>(1 + M + 2 * M * M);
        data_d_.assign(n, glm::dvec4(0.0));
        data_d_[0] = glm::dvec4(M, 0, 0, 0);
        for (int o = 0; o < M; ++o) {
            data_d_[static_cast<std::size_t>(1 + o)] = glm::dvec4(albedo_[static_cast<std::size_t>(o)], 0, 0, 0);
            double cum = 0;
            for (int i = 0; i < M; ++i) {
                const std::size_t b = static_cast<std::size_t>(o * M + i), k = static_cast<std::size_t>(1 + M + 2 * (o * M + i));
                cum += rho_m_[b] * bin_ds(i, M);
                const double a = albedo_[static_cast<std::size_t>(o)];
                double cdf = a > 0 ? cum / a : static_cast<double>(i + 1) / M;
                if (i == M - 1) cdf = 1;
                data_d_[k] = glm::dvec4(rho_m_[b], rho_0_[0][b], rho_0_[1][b], rho_0_[2][b]);
                data_d_[k + 1] = glm::dvec4(gamma_[0][b], gamma_[1][b], gamma_[2][b], cdf);
            }
        }
        data_f_.resize(n);
        for (std::size_t k = 0; k < n; ++k) data_f_[k] = glm::vec4(data_d_[k]);
        // In float the CDF must stay non-decreasing and end at exactly 1 (it does: rounding is
        // monotone and 1 is exact).
    }
};

// Builds the table (host side; allocates, may throw glint::error naming the bad field and value).
inline scratch_table build_scratch_table(const scratch_profile& profile, const scratch_fresnel& fresnel, const scratch_table_options& options = {}) {
    const std::string what = "glint::build_scratch_table: ";
    detail::check_scratch_profile(profile, what);
    fresnel.check(what);
    if (options.resolution < 8 || options.resolution > 4096) throw error(what + "resolution = " + std::to_string(options.resolution) + " is outside [8, 4096]");
    if (options.rays_per_row < 16 || options.rays_per_row > 100000000)
        throw error(what + "rays_per_row = " + std::to_string(options.rays_per_row) + " is outside [16, 1e8]");
    if (options.max_bounces < 1 || options.max_bounces > 4096) throw error(what + "max_bounces = " + std::to_string(options.max_bounces) + " is outside [1, 4096]");
    if (options.threads < 0) throw error(what + "threads = " + std::to_string(options.threads) + " is negative");
    const int M = options.resolution, N = options.rays_per_row;
    const std::size_t MM = static_cast<std::size_t>(M) * static_cast<std::size_t>(M);
    const detail::scratch_tracer tracer(profile);
    const bool grey = fresnel.grey();
    const detail::fresnel_table ftable(fresnel);
    const detail::fresnel_table* fptr = fresnel.model == fresnel_model::mirror ? nullptr : &ftable;
    // Traced counts, [incident i][exit j].
    std::vector<double> wm(MM, 0.0), w0[3], w60[3];
    for (int c = 0; c < 3; ++c) w0[c].assign(MM, 0.0), w60[c].assign(MM, 0.0);
    scratch_table t;
    t.m_ = M;
    t.lost_.assign(static_cast<std::size_t>(M), 0.0);
    std::vector<int> bounces_seen(static_cast<std::size_t>(M), 0);
    using K = detail::glsl::kernels<double>;
    std::atomic<int> next{0}, done{0};
    std::mutex progress_mutex;
    // The exit bin from the exit direction's x component sin(phi_o): a table over 4M equal steps of
    // sin(phi) gives a bin at or below the answer, then the bin edges (in sin) finish it.
    std::vector<double> edge(static_cast<std::size_t>(M + 1));
    for (int j = 0; j <= M; ++j) edge[static_cast<std::size_t>(j)] = j == 0 ? -1.0 : (j == M ? 1.0 : K::glint_scratch_edge_sin(j, M));
    const int cells = 4 * M;
    std::vector<int> first_bin(static_cast<std::size_t>(cells));
    for (int c = 0, j = 0; c < cells; ++c) {
        const double lo = -1 + 2.0 * c / cells;
        while (j < M - 1 && edge[static_cast<std::size_t>(j + 1)] <= lo) ++j;
        first_bin[static_cast<std::size_t>(c)] = j;
    }
    const auto exit_bin = [&](double sx) {
        const int c = std::min(cells - 1, std::max(0, static_cast<int>((sx + 1) * (0.5 * cells))));
        int j = first_bin[static_cast<std::size_t>(c)];
        while (j < M - 1 && sx >= edge[static_cast<std::size_t>(j + 1)]) ++j;
        return j;
    };
    // Fresnel channels to trace: none for a mirror, one for grey Fresnel.
    const int channels = fresnel.model == fresnel_model::mirror ? 0 : (grey ? 1 : 3);
    const auto work = [&] {
        std::vector<double> acc(static_cast<std::size_t>(M) * 7);  // per exit bin: count, rho_0 rgb, rho_60 rgb
        for (;;) {
            const int i = next.fetch_add(1);
            if (i >= M) return;
            std::fill(acc.begin(), acc.end(), 0.0);
            const double s0 = K::glint_scratch_edge_sin(i, M), ds = K::glint_scratch_bin_ds(i, M);
            long lost = 0;
            int most = 0;
            for (int r = 0; r < N; ++r) {
                const glm::uvec3 u = pcg3d(glm::uvec3(static_cast<unsigned>(r), static_cast<unsigned>(i), options.seed ^ 0x5c7a7c4u));
                const double x0 = -0.5 + (r + detail::scratch_unit(u.x)) / N;
                const double s = std::min(1.0, std::max(-1.0, s0 + detail::scratch_unit(u.y) * ds));
                // Light arrives from phi_i: the ray travels along -(sin phi_i, cos phi_i).
                const auto e = tracer.trace(x0, -s, -std::sqrt((1 - s) * (1 + s)), options.max_bounces, fptr, grey);
                most = std::max(most, e.bounces);
                if (e.lost || !(e.dy > 0)) {  // capped, or (rounding) left below the base: lost
                    ++lost;
                    continue;
                }
                double* a = &acc[static_cast<std::size_t>(exit_bin(e.dx)) * 7];
                a[0] += 1;
                for (int c = 0; c < channels; ++c) a[1 + c] += e.f0[c], a[4 + c] += e.f60[c];
            }
            const std::size_t row = static_cast<std::size_t>(i) * static_cast<std::size_t>(M);
            for (int j = 0; j < M; ++j) {
                const double* a = &acc[static_cast<std::size_t>(j) * 7];
                const std::size_t b = row + static_cast<std::size_t>(j);
                wm[b] = a[0];
                for (int c = 0; c < 3; ++c) {
                    const int from = channels == 3 ? c : 0;
                    w0[c][b] = channels == 0 ? a[0] : a[1 + from];
                    w60[c][b] = channels == 0 ? a[0] : a[4 + from];
                }
            }
            t.lost_[static_cast<std::size_t>(i)] = static_cast<double>(lost) / N;
            bounces_seen[static_cast<std::size_t>(i)] = most;
            const int d = done.fetch_add(1) + 1;
            if (options.progress) {
                std::lock_guard<std::mutex> lock(progress_mutex);
                options.progress(d, M);
            }
        }
    };
    const int threads = std::max(1, std::min(M, options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency())));
    std::vector<std::thread> pool;
    for (int k = 1; k < threads; ++k) pool.emplace_back(work);
    work();
    for (auto& th : pool) th.join();
    t.max_bounces_seen_ = *std::max_element(bounces_seen.begin(), bounces_seen.end());
    // rho[o][i] = count[i -> o] / (N ds_o): the transpose of the traced [i][j] layout.
    t.rho_m_.assign(MM, 0.0);
    for (int c = 0; c < 3; ++c) t.rho_0_[c].assign(MM, 0.0), t.rho_60_[c].assign(MM, 0.0), t.gamma_[c].assign(MM, 1.0);
    for (int o = 0; o < M; ++o) {
        const double norm = 1.0 / (static_cast<double>(N) * scratch_table::bin_ds(o, M));
        for (int i = 0; i < M; ++i) {
            const std::size_t src = static_cast<std::size_t>(i * M + o), dst = static_cast<std::size_t>(o * M + i);
            t.rho_m_[dst] = wm[src] * norm;
            for (int c = 0; c < 3; ++c) t.rho_0_[c][dst] = w0[c][src] * norm, t.rho_60_[c][dst] = w60[c][src] * norm;
        }
    }
    if (options.symmetrize) {
        const auto sym = [&](std::vector<double>& a) {
            for (int o = 0; o < M; ++o)
                for (int i = o + 1; i < M; ++i) {
                    double& p = a[static_cast<std::size_t>(o * M + i)];
                    double& q = a[static_cast<std::size_t>(i * M + o)];
                    p = q = 0.5 * (p + q);
                }
            if (profile.symmetric)
                for (int o = 0; o < M; ++o)
                    for (int i = 0; i < M; ++i) {
                        const std::size_t k1 = static_cast<std::size_t>(o * M + i), k2 = static_cast<std::size_t>((M - 1 - o) * M + (M - 1 - i));
                        if (k1 < k2) a[k1] = a[k2] = 0.5 * (a[k1] + a[k2]);
                    }
        };
        sym(t.rho_m_);
        for (int c = 0; c < 3; ++c) sym(t.rho_0_[c]), sym(t.rho_60_[c]);
    }
    // Eq. 2's exponent per bin and channel (header comment).
    const double ln23 = std::log(2.0 / 3.0);
    for (std::size_t b = 0; b < MM; ++b)
        for (int c = 0; c < 3; ++c) {
            const double rm = t.rho_m_[b], r0 = t.rho_0_[c][b], r60 = t.rho_60_[c][b];
            if (!(rm - r0 > 1e-6 * rm)) continue;
            const double r = std::min(std::max((r60 - r0) / (rm - r0), 1e-4), 1 - 1e-4);
            t.gamma_[c][b] = std::log(r) / ln23;
        }
    t.albedo_.assign(static_cast<std::size_t>(M), 0.0);
    for (int o = 0; o < M; ++o)
        for (int i = 0; i < M; ++i) t.albedo_[static_cast<std::size_t>(o)] += t.rho_m_[static_cast<std::size_t>(o * M + i)] * scratch_table::bin_ds(i, M);
    t.pack();
    return t;
}

template <class real>
using scratch_frame = typename detail::glsl::kernels<real>::glint_scratch_frame;
template <class real>
using scratch_sample = typename detail::glsl::kernels<real>::glint_scratch_sample;
template <class real>
using scratch_layer = typename detail::glsl::kernels<real>::glint_scratch_layer;
template <class real>
using scratch_mix = typename detail::glsl::kernels<real>::glint_scratch_mix;

// The frame of a scratch with normal n and groove tangent t (kernels/scratch.glsl: fallback basis
// where t is zero or parallel to n).
template <class real>
scratch_frame<real> make_scratch_frame(const vec3_t<real>& n, const vec3_t<real>& t) {
    return detail::glsl::kernels<real>::glint_scratch_make_frame(n, t);
}
// (theta, phi) of w (RGB16 Eq. 1), and back.
template <class real>
vec2_t<real> to_cone(const scratch_frame<real>& f, const vec3_t<real>& w) {
    return detail::glsl::kernels<real>::glint_scratch_to_cone(f, w);
}
template <class real>
vec3_t<real> from_cone(const scratch_frame<real>& f, const vec2_t<real>& theta_phi) {
    return detail::glsl::kernels<real>::glint_scratch_from_cone(f, theta_phi);
}
// The light cull of RGB16 Sec. 5.2 (exact).
template <class real>
bool scratch_light_reaches(const scratch_frame<real>& f, const vec3_t<real>& wo, const vec3_t<real>& wl, real psi) {
    return detail::glsl::kernels<real>::glint_scratch_light_reaches(f, wo, wl, psi);
}
// Eq. 4's weights from the layers' summed relative area.
template <class real>
scratch_mix<real> scratch_mix_weights(real alpha_sum) {
    return detail::glsl::kernels<real>::glint_scratch_mix_weights(alpha_sum);
}

// How a view reads the table (kernels/scratch.glsl, glint_scratch_rows_of): the bin holding
// (phi_o, phi_i), or linear across phi_o between the two nearest rows (a moving view changes
// smoothly) and the bin holding phi_i. The sampler's pdf follows the same rows, so Eq. 5 is
// unbiased for either.
enum class scratch_filter { nearest = 0, linear = 1 };

// Per-pixel access to a table (does not own it: the table must outlive the view).
template <class real>
struct scratch_table::view_t {
    using K = detail::glsl::kernels<real>;
    const glm::vec<4, real, glm::defaultp>* data = nullptr;
    scratch_filter filter = scratch_filter::linear;

    int resolution() const { return static_cast<int>(data[0].x); }
    // rho_s (Eq. 2) per RGB channel.
    vec3_t<real> rho(real theta_o, real phi_o, real phi_i) const { return K::glint_scratch_rho(data, theta_o, phi_o, phi_i, static_cast<int>(filter)); }
    // A direction on wo's reflection cone and its weight (Eq. 5).
    scratch_sample<real> sample(const scratch_frame<real>& f, const vec3_t<real>& wo, real u1, real u2) const {
        return K::glint_scratch_sample_cone(data, f, wo, u1, u2, static_cast<int>(filter));
    }
    real pdf_phi(real phi_o, real phi_i) const { return K::glint_scratch_pdf_phi(data, phi_o, phi_i, static_cast<int>(filter)); }
    // A point light of irradiance E from wl through the kernel of radius psi (Eq. 6; psi in (0, 10]
    // degrees, RGB16: 1 degree), n samples along the cone.
    vec3_t<real> light_radiance(const scratch_frame<real>& f, const vec3_t<real>& wo, const vec3_t<real>& wl, real irradiance,
                                real psi = real(0.017453292519943295769), int n = 4, real jitter = real(0.5)) const {
        return K::glint_scratch_light_radiance(data, f, wo, wl, irradiance, psi, n, jitter, static_cast<int>(filter));
    }
};

template <class real>
scratch_table::view_t<real> scratch_table::view() const {
    view_t<real> v;
    v.data = data<real>().data();
    return v;
}

// A scratch distribution (RGB16 Sec. 5.3, Eq. 7, Table 1): `layers` layers, layer k oriented at
// main_deg + Theta_k, Theta_k uniform in [-spread_deg/2, spread_deg/2] (degrees, as the paper's
// Table 1), mean scratch length and width in surface units (uv), Worley threshold density d. All
// layers rotate and offset one noise pattern (RGB16 Sec. 5.3), periodic over `period` cells (a
// power of two) so that one baked coverage pyramid serves them all; layer k's offset xi_k is
// uniform over the whole period (RGB16 draws it in [-1, 1]^2, which leaves layers of similar angle
// copies of each other within a cell: ours).
struct scratch_distribution {
    int layers = 6;            // [0, 64]; 0: no scratches (the material is its base BRDF)
    double spread_deg = 5;     // Theta: [0, 360]
    double main_deg = 0;
    double length = 0.1;       // l > 0
    double width = 2e-4;       // w > 0
    double density = 0.2;      // d in [0, 1]
    int period = 64;           // cells of the noise pattern: a power of two in [1, 4096]
    std::uint32_t seed = 0;
};

namespace detail {
// The hash seed of a distribution's shared noise pattern.
inline std::uint32_t scratch_pattern_seed(std::uint32_t seed) { return pcg3d(glm::uvec3(seed, 0x9e3779b9u, 0x5c4a7c11u)).x; }
}  // namespace detail

// The layers of a distribution for glint_scratch_indicator / glint_scratch_alpha_footprint.
template <class real>
std::vector<scratch_layer<real>> make_scratch_layers(const scratch_distribution& d) {
    const std::string what = "glint::make_scratch_layers: ";
    if (d.layers < 0 || d.layers > 64) throw error(what + "layers = " + std::to_string(d.layers) + " is outside [0, 64]");
    if (!(d.spread_deg >= 0 && d.spread_deg <= 360)) throw error(what + "spread_deg = " + detail::scratch_number(d.spread_deg) + " is outside [0, 360]");
    if (!std::isfinite(d.main_deg)) throw error(what + "main_deg is not finite");
    if (!(d.length > 0 && std::isfinite(d.length))) throw error(what + "length = " + detail::scratch_number(d.length) + " is not positive");
    if (!(d.width > 0 && std::isfinite(d.width))) throw error(what + "width = " + detail::scratch_number(d.width) + " is not positive");
    if (!(d.density >= 0 && d.density <= 1)) throw error(what + "density = " + detail::scratch_number(d.density) + " is outside [0, 1]");
    if (d.period < 1 || d.period > 4096 || (d.period & (d.period - 1)) != 0)
        throw error(what + "period = " + std::to_string(d.period) + " is not a power of two in [1, 4096]");
    std::vector<scratch_layer<real>> out;
    const double deg = 0.017453292519943295769;  // pi / 180, 20 digits
    const std::uint32_t seed = detail::scratch_pattern_seed(d.seed);
    for (int k = 0; k < d.layers; ++k) {
        const glm::uvec3 h = pcg3d(glm::uvec3(static_cast<unsigned>(k), d.seed, 0x5c4a7c11u));
        const double theta = (d.main_deg + (detail::scratch_unit(h.x) - 0.5) * d.spread_deg) * deg;
        scratch_layer<real> L{};
        L.dir = vec2_t<real>(static_cast<real>(std::cos(theta)), static_cast<real>(std::sin(theta)));
        L.offset = vec2_t<real>(static_cast<real>(d.period * detail::scratch_unit(h.y)), static_cast<real>(d.period * detail::scratch_unit(h.z)));
        L.inv_length = static_cast<real>(1 / d.length);
        L.inv_width = static_cast<real>(1 / d.width);
        L.density = static_cast<real>(d.density);
        L.seed = seed;
        L.period = d.period;
        out.push_back(L);
    }
    return out;
}

template <class real>
real scratch_indicator(const scratch_layer<real>& L, const vec2_t<real>& x) {
    return detail::glsl::kernels<real>::glint_scratch_indicator(L, x);
}
template <class real>
real scratch_alpha_footprint(const scratch_layer<real>& L, const vec2_t<real>& x, const vec2_t<real>& a, const vec2_t<real>& b,
                             const vec2_t<real>& jitter = vec2_t<real>(real(0.5))) {
    return detail::glsl::kernels<real>::glint_scratch_alpha_footprint(L, x, a, b, jitter);
}

template <class real>
using scratch_lit = typename detail::glsl::kernels<real>::glint_scratch_lit;
template <class real>
using scratch_pick = typename detail::glsl::kernels<real>::glint_scratch_pick;
template <class real>
using scratch_areas = typename detail::glsl::kernels<real>::glint_scratch_areas;

// The whole SV-BRDF's data (RGB16 Sec. 4.3, 5.3): a table, a distribution's layers and the baked
// coverage pyramid of their shared noise pattern, in one vec4 buffer (layout in
// kernels/scratch.glsl, glint_scratch_material_header) that the kernels read as they read a table.
// Coverage: level 0 holds texels_per_cell^2 texels per noise cell, each the exact fraction of its
// square inside a scratch (decided from F1 at the centre where F1 is farther than the half
// diagonal from d, F1 being 1-Lipschitz, else from 4 x 4 points), then box mips down to 1 texel:
// the top is the pattern's area fraction, the stationary limit of Eq. 3.
class scratch_material {
public:
    static scratch_material build(const scratch_table& table, const scratch_distribution& d, int texels_per_cell = 8) {
        const std::string what = "glint::scratch_material::build: ";
        if (texels_per_cell < 1 || texels_per_cell > 64 || (texels_per_cell & (texels_per_cell - 1)) != 0)
            throw error(what + "texels_per_cell = " + std::to_string(texels_per_cell) + " is not a power of two in [1, 64]");
        if (static_cast<long>(d.period) * texels_per_cell > 8192)  // at most 14 levels (the header holds 16 starts)
            throw error(what + "period x texels_per_cell = " + std::to_string(static_cast<long>(d.period) * texels_per_cell) + " exceeds 8192");
        scratch_material m;
        m.layers_d_ = make_scratch_layers<double>(d);
        m.layers_f_ = make_scratch_layers<float>(d);
        const int R0 = m.layers_d_.empty() ? 1 : d.period * texels_per_cell;
        m.r0_ = R0;
        // Level 0.
        std::vector<std::vector<double>> levels(1, std::vector<double>(static_cast<std::size_t>(R0) * static_cast<std::size_t>(R0)));
        const std::uint32_t seed = detail::scratch_pattern_seed(d.seed);
        using KD = detail::glsl::kernels<double>;
        const double tpc = texels_per_cell, half_diag = 0.70710678118654752440 / tpc;  // sqrt(1/2), 20 digits
        std::atomic<int> next{0};
        const auto work = [&] {
            for (int y; (y = next.fetch_add(1)) < R0;)
                for (int x = 0; x < R0; ++x) {
                    const glm::dvec2 c((x + 0.5) / tpc, (y + 0.5) / tpc);
                    const double f1 = KD::glint_worley_f1(c, seed, d.period);
                    double v;
                    if (f1 - d.density > half_diag) v = 0;
                    else if (d.density - f1 > half_diag) v = 1;
                    else {
                        int in = 0;
                        for (int j = 0; j < 4; ++j)
                            for (int i = 0; i < 4; ++i)
                                in += KD::glint_worley_f1(glm::dvec2((x + (i + 0.5) / 4) / tpc, (y + (j + 0.5) / 4) / tpc), seed, d.period) <= d.density;
                        v = in / 16.0;
                    }
                    levels[0][static_cast<std::size_t>(x) + static_cast<std::size_t>(R0) * static_cast<std::size_t>(y)] = v;
                }
        };
        if (!m.layers_d_.empty()) {
            const int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
            std::vector<std::thread> pool;
            for (int k = 1; k < threads; ++k) pool.emplace_back(work);
            work();
            for (auto& th : pool) th.join();
        }
        for (int R = R0 / 2; R >= 1; R /= 2) {
            const auto& f = levels.back();
            std::vector<double> c(static_cast<std::size_t>(R) * static_cast<std::size_t>(R));
            const std::size_t F = static_cast<std::size_t>(2 * R);
            for (std::size_t y = 0; y < static_cast<std::size_t>(R); ++y)
                for (std::size_t x = 0; x < static_cast<std::size_t>(R); ++x)
                    c[x + static_cast<std::size_t>(R) * y] = 0.25 * (f[2 * x + F * 2 * y] + f[2 * x + 1 + F * 2 * y] + f[2 * x + F * (2 * y + 1)] + f[2 * x + 1 + F * (2 * y + 1)]);
            levels.push_back(std::move(c));
        }
        m.mean_coverage_ = levels.back()[0];
        m.levels_ = static_cast<int>(levels.size());
        // Pack: the table, the header, the layers, the levels.
        const auto pack = [&](auto& out, const auto& table_data, const auto& layers) {
            using V = typename std::decay_t<decltype(out)>::value_type;
            out = table_data;
            out.push_back(V(layers.size(), d.period, texels_per_cell, m.levels_));
            out.push_back(V(d.density, seed >> 16, seed & 0xffffu, R0));
            // The levels' starts, in vec4 from the first level's.
            std::vector<double> starts(16, 0.0);
            for (std::size_t l = 1; l < levels.size(); ++l) starts[l] = starts[l - 1] + static_cast<double>(std::max<std::size_t>(1, levels[l - 1].size() / 4));
            for (std::size_t q = 0; q < 16; q += 4) out.push_back(V(starts[q], starts[q + 1], starts[q + 2], starts[q + 3]));
            for (const auto& l : layers) {
                out.push_back(V(l.dir.x, l.dir.y, l.offset.x, l.offset.y));
                out.push_back(V(l.inv_length, l.inv_width, 0, 0));
            }
            for (const auto& lv : levels) {
                const std::size_t n = std::max<std::size_t>(1, lv.size() / 4), start = out.size();
                out.resize(start + n, V(0));
                for (std::size_t t = 0; t < lv.size(); ++t) out[start + (t >> 2)][static_cast<int>(t & 3)] = static_cast<typename V::value_type>(lv[t]);
            }
        };
        pack(m.data_f_, table.data<float>(), m.layers_f_);
        pack(m.data_d_, table.data<double>(), m.layers_d_);
        m.table_bytes_ = table.memory_bytes();
        return m;
    }

    template <class real>
    const std::vector<glm::vec<4, real, glm::defaultp>>& data() const {
        if constexpr (std::is_same<real, float>::value) return data_f_;
        else return data_d_;
    }
    template <class real>
    const std::vector<scratch_layer<real>>& layers() const {
        if constexpr (std::is_same<real, float>::value) return layers_f_;
        else return layers_d_;
    }
    int coverage_levels() const { return levels_; }
    int coverage_resolution() const { return r0_; }
    // The pattern's area fraction (the pyramid's top texel).
    double mean_coverage() const { return mean_coverage_; }
    std::size_t memory_bytes() const { return data_f_.size() * sizeof(glm::vec4); }
    std::size_t table_bytes() const { return table_bytes_; }
    std::size_t coverage_bytes() const { return memory_bytes() - table_bytes_ - 6 * 16 - 32 * layers_f_.size(); }

    // Per-pixel access (the material must outlive the view).
    template <class real>
    struct view_t {
        using K = detail::glsl::kernels<real>;
        using v2 = vec2_t<real>;
        using v3 = vec3_t<real>;
        const glm::vec<4, real, glm::defaultp>* data = nullptr;
        scratch_filter filter = scratch_filter::linear;
        real cull = real(1e-6);  // layers whose area is below this are skipped (RGB16 Sec. 6.1)
        int layers = 0;          // the material's layer count (set by view())

        scratch_table::view_t<real> table() const {
            scratch_table::view_t<real> t;
            t.data = data, t.filter = filter;
            return t;
        }
        int layer_count() const { return K::glint_scratch_material_layer_count(data, 0); }
        scratch_layer<real> layer(int k) const { return K::glint_scratch_material_layer(data, k); }
        // Layer k's area under the footprint (x; axes a, b in surface units), Eq. 3.
        real alpha(int k, const v2& x, const v2& a, const v2& b, const v2& jitter = v2(real(0.5))) const {
            return K::glint_scratch_material_alpha(data, k, x, a, b, jitter);
        }
        // A point light (Eq. 4 with Eq. 6 per layer); frame f's u is the surface tangent.
        scratch_lit<real> light(const scratch_frame<real>& f, const v2& x, const v2& a, const v2& b, const v3& wo, const v3& wl, real irradiance,
                                real psi = real(0.017453292519943295769), int n = 4, const v2& jitter = v2(real(0.5))) const {
            if (layers == 0) {  // scratches disabled: no kernel call (a shader branches on a uniform)
                scratch_lit<real> r{};
                r.base_weight = real(1);
                return r;
            }
            return K::glint_scratch_material_light(data, f, x, a, b, jitter, wo, wl, irradiance, psi, n, cull, static_cast<int>(filter));
        }
        // Every layer's area and Eq. 4's weights at a footprint, once per pixel for sample_with.
        scratch_areas<real> areas(const v2& x, const v2& a, const v2& b, const v2& jitter = v2(real(0.5))) const {
            return K::glint_scratch_material_areas(data, x, a, b, jitter, cull);
        }
        scratch_pick<real> sample_with(const scratch_frame<real>& f, const scratch_areas<real>& A, const v3& wo, real u0, real u1, real u2) const {
            return K::glint_scratch_material_sample_with(data, f, A, wo, u0, u1, u2, static_cast<int>(filter));
        }
        // Importance sampling (layer -1: sample the base BRDF).
        scratch_pick<real> sample(const scratch_frame<real>& f, const v2& x, const v2& a, const v2& b, const v3& wo, real u0, real u1, real u2,
                                  const v2& jitter = v2(real(0.5))) const {
            return K::glint_scratch_material_sample(data, f, x, a, b, jitter, wo, u0, u1, u2, cull, static_cast<int>(filter));
        }
    };
    template <class real>
    view_t<real> view() const {
        view_t<real> v;
        v.data = data<real>().data();
        v.layers = static_cast<int>(layers_f_.size());
        return v;
    }

private:
    std::vector<glm::vec4> data_f_;
    std::vector<glm::dvec4> data_d_;
    std::vector<scratch_layer<float>> layers_f_;
    std::vector<scratch_layer<double>> layers_d_;
    int levels_ = 0, r0_ = 0;
    double mean_coverage_ = 0;
    std::size_t table_bytes_ = 0;
};

// Curved scratches: coordinates and tangent for concentric (pitch 0) or spiral turning marks
// around centre c (kernels/scratch.glsl).
template <class real>
typename detail::glsl::kernels<real>::glint_scratch_param scratch_turned(const vec2_t<real>& p, const vec2_t<real>& c, real pitch = real(0)) {
    return detail::glsl::kernels<real>::glint_scratch_turned(p, c, pitch);
}

}  // namespace glint
