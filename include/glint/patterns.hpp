// Seeded procedural normal maps for tests, examples and benchmarks: every pattern is periodic over
// its width x height texels (except the linear ramp, which is clamped), and its normal is analytic
// at any point (pattern_normal), from the exact gradient of a height field where there is one.
//
//   glint::pattern_params p;  p.kind = glint::pattern::brushed;  p.width = p.height = 256;
//   glint::normal_map m = glint::make_normal_map(p);     // normals at the texel centres
//
// Heights h(u) in texels; n = normalize(-dh/dx, -dh/dy, 1) (normal_map.hpp's frame):
// - flat: n = (0, 0, 1); tilt: the constant normal with xy part `tilt`;
// - ramp: s(u) = tilt + ramp_jacobian (u - centre), the closed-form linear field (wrap_mode::clamp);
// - sinusoid: h = A sin(2 pi cycles x / W);
// - brushed: h = sum of 24 cosines along y with distinct integer frequencies f in [1, H/4], amplitude
//   ~ 1/f, plus 4 cosines along x with a tenth of the rms slope (rank-1 Jacobian up to that term);
// - noise / anisotropic_noise: a sum of 64 cosines with distinct integer wave vectors (Heitz's
//   procedural construction restricted to periodic waves), so the texel mean of each slope
//   component squared is known exactly (pattern_slope_variance); anisotropic: wave vectors four
//   times shorter along y, so the slopes are about four times smaller along y;
// - flakes: periodic jittered Voronoi cells of about `feature` texels, each with a flat random
//   normal whose xy part is Gaussian with sd slope_rms per component (clipped to |s| <= 0.9);
// - pyramids: square pyramids of period `feature` with facet slope slope_rms (four normals);
// - scratches: a flat map crossed by 3 V-grooves 1.5 to 3 texels wide, along x, y or the diagonal
//   (square maps), with side slopes +-3 slope_rms;
// - leather: smoothed Worley F2 - F1 bumps, h = b m tanh((F2 - F1) / m), cells of `feature` texels;
// - scratched_metal: a flat map crossed by `count` V-groove segments of random direction, 1 to 2
//   texels wide and 5% to 30% of the map's smaller side long, with side slopes 2.4 to 5.6 slope_rms
//   (20 to 40 degrees at slope_rms 0.15, the AKKW notes' scratched metal); each segment repeats
//   with the period (its nearest image counts), and crossing segments add their slopes.
// The amplitudes of sinusoid, brushed and noise are set so that the rms slope (texel mean of
// |grad h|^2 / 2, per component) is slope_rms.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "glint/core/error.hpp"
#include "glint/core/hash.hpp"
#include "glint/normal_map.hpp"

namespace glint {

enum class pattern { flat, tilt, ramp, sinusoid, brushed, noise, anisotropic_noise, flakes, pyramids, scratches, leather, scratched_metal };

struct pattern_params {
    pattern kind = pattern::noise;
    int width = 64, height = 64;        // the period, texels (>= 2)
    std::uint32_t seed = 1;
    double slope_rms = 0.1;             // see above; 0 < slope_rms <= 1
    double feature = 8;                 // flakes, pyramids, leather: feature size in texels (>= 1)
    int cycles = 4;                     // sinusoid: periods across the map
    int count = 200;                    // scratched_metal: segments (>= 0)
    glm::dvec2 tilt{0.2, 0.1};          // tilt and ramp: xy part of the normal (at the centre)
    glm::dmat2 ramp_jacobian{0.002, 0.0, 0.0, 0.001};  // ramp: ds/du per texel (columns d/dx, d/dy)
};

inline const char* pattern_name(pattern p) {
    switch (p) {
        case pattern::flat: return "flat";
        case pattern::tilt: return "tilt";
        case pattern::ramp: return "ramp";
        case pattern::sinusoid: return "sinusoid";
        case pattern::brushed: return "brushed";
        case pattern::noise: return "noise";
        case pattern::anisotropic_noise: return "anisotropic_noise";
        case pattern::flakes: return "flakes";
        case pattern::pyramids: return "pyramids";
        case pattern::scratches: return "scratches";
        case pattern::leather: return "leather";
        case pattern::scratched_metal: return "scratched_metal";
    }
    return "?";
}

// The pattern named `name` (as pattern_name gives it); throws glint::error listing the names.
inline pattern parse_pattern(const std::string& name) {
    for (int k = 0; k <= static_cast<int>(pattern::scratched_metal); ++k)
        if (name == pattern_name(static_cast<pattern>(k))) return static_cast<pattern>(k);
    std::string all;
    for (int k = 0; k <= static_cast<int>(pattern::scratched_metal); ++k) all += std::string(k ? ", " : "") + pattern_name(static_cast<pattern>(k));
    throw error("glint::parse_pattern: unknown pattern '" + name + "' (one of: " + all + ")");
}

namespace detail {

inline double pattern_uniform(std::uint32_t seed, std::uint32_t a, std::uint32_t b) {
    return unit_from_bits<double>(pcg3d(glm::uvec3(seed, a, b)).x);
}

struct wave {
    glm::dvec2 k;  // 2 pi (kx / W, ky / H)
    double amplitude, phase;
};

// The cosines of sinusoid, brushed and the noises, amplitudes scaled to slope_rms.
inline std::vector<wave> pattern_waves(const pattern_params& p) {
    const double two_pi = 6.283185307179586477;
    std::vector<wave> w;
    std::uint32_t draw = 0;
    const auto u = [&] { return pattern_uniform(p.seed, 17u, draw++); };
    if (p.kind == pattern::sinusoid) {
        w.push_back({{two_pi * p.cycles / p.width, 0.0}, 1.0, 0.0});
    } else if (p.kind == pattern::brushed) {
        // Distinct frequencies up to a quarter of the size, so that no two waves alias together.
        const int fmax = std::max(1, p.height / 4), gmax = std::max(1, p.width / 4);
        std::vector<int> fs, gs;
        for (int attempt = 0; attempt < 4096 && static_cast<int>(fs.size()) < std::min(24, fmax); ++attempt) {
            const int f = 1 + std::min(fmax - 1, static_cast<int>(u() * fmax));
            if (std::find(fs.begin(), fs.end(), f) != fs.end()) continue;
            fs.push_back(f);
            w.push_back({{0.0, two_pi * f / p.height}, 1.0 / f, two_pi * u()});
        }
        for (int attempt = 0; attempt < 4096 && static_cast<int>(gs.size()) < std::min(4, gmax); ++attempt) {
            const int g = 1 + std::min(gmax - 1, static_cast<int>(u() * gmax));
            if (std::find(gs.begin(), gs.end(), g) != gs.end()) continue;
            gs.push_back(g);
            w.push_back({{two_pi * g / p.width, 0.0}, 1.0 / g, two_pi * u()});
        }
    } else if (p.kind == pattern::noise || p.kind == pattern::anisotropic_noise) {
        const int kmax = std::max(1, std::min(p.width, p.height) / 4);
        const int kymax = p.kind == pattern::anisotropic_noise ? std::max(1, kmax / 4) : kmax;
        std::vector<glm::ivec2> used;
        for (int attempt = 0; attempt < 4096 && used.size() < 64; ++attempt) {
            const glm::ivec2 k(static_cast<int>(std::floor((2 * u() - 1) * (kmax + 0.999))), static_cast<int>(std::floor(u() * (kymax + 0.999))));
            if (k == glm::ivec2(0) || k.x * k.x * kymax * kymax + k.y * k.y * kmax * kmax > kmax * kmax * kymax * kymax) continue;
            bool dup = false;
            for (const auto& q : used) dup = dup || q == k || q == -k;
            if (dup) continue;
            used.push_back(k);
            w.push_back({{two_pi * k.x / p.width, two_pi * k.y / p.height}, 1.0, two_pi * u()});
        }
    }
    // Scale: the texel mean of gx^2 + gy^2 over the period is sum a^2 |k|^2 / 2 (distinct waves),
    // which must be 2 slope_rms^2; brushed splits it 1 : 0.01 between the y and the x waves.
    double main = 0, cross = 0;
    for (const auto& v : w) (p.kind == pattern::brushed && v.k.y == 0 ? cross : main) += v.amplitude * v.amplitude * glm::dot(v.k, v.k) / 2;
    const double target = 2 * p.slope_rms * p.slope_rms / (p.kind == pattern::brushed ? 1.01 : 1.0);
    for (auto& v : w) {
        if (p.kind == pattern::brushed && v.k.y == 0)
            v.amplitude *= cross > 0 ? std::sqrt(0.01 * target / cross) : 0.0;
        else
            v.amplitude *= main > 0 ? std::sqrt(target / main) : 0.0;
    }
    return w;
}

// Jittered periodic cell points: the feature point of cell (i, j) of a cells.x x cells.y grid.
inline glm::dvec2 pattern_cell_point(const pattern_params& p, glm::ivec2 cells, int i, int j) {
    const int ci = ((i % cells.x) + cells.x) % cells.x, cj = ((j % cells.y) + cells.y) % cells.y;
    const glm::dvec2 size(static_cast<double>(p.width) / cells.x, static_cast<double>(p.height) / cells.y);
    const std::uint32_t cell = static_cast<std::uint32_t>(ci + 4096 * cj);
    const glm::dvec2 jitter(0.1 + 0.8 * pattern_uniform(p.seed, 23u, 2 * cell), 0.1 + 0.8 * pattern_uniform(p.seed, 23u, 2 * cell + 1));
    return (glm::dvec2(i, j) + jitter) * size;
}

inline glm::ivec2 pattern_cells(const pattern_params& p) {
    return {std::max(1, static_cast<int>(std::lround(p.width / p.feature))), std::max(1, static_cast<int>(std::lround(p.height / p.feature)))};
}

// The nearest and second-nearest feature points to u (unwrapped images), and the nearest's cell.
inline void pattern_worley(const pattern_params& p, glm::dvec2 u, glm::dvec2& p1, glm::dvec2& p2, glm::ivec2& cell1) {
    const glm::ivec2 cells = pattern_cells(p);
    const glm::dvec2 size(static_cast<double>(p.width) / cells.x, static_cast<double>(p.height) / cells.y);
    const int ci = static_cast<int>(std::floor(u.x / size.x)), cj = static_cast<int>(std::floor(u.y / size.y));
    double d1 = 1e300, d2 = 1e300;
    for (int j = cj - 2; j <= cj + 2; ++j)
        for (int i = ci - 2; i <= ci + 2; ++i) {
            const glm::dvec2 q = pattern_cell_point(p, cells, i, j);
            const double d = glm::dot(q - u, q - u);
            if (d < d1) d2 = d1, p2 = p1, d1 = d, p1 = q, cell1 = {((i % cells.x) + cells.x) % cells.x, ((j % cells.y) + cells.y) % cells.y};
            else if (d < d2) d2 = d, p2 = q;
        }
}

inline glm::dvec3 normal_from_gradient(glm::dvec2 g) { return glm::normalize(glm::dvec3(-g.x, -g.y, 1.0)); }

// scratched_metal's segment j: centre, unit direction, half length, half width, side slope.
struct segment {
    glm::dvec2 centre, direction;
    double half_length, half_width, slope;
};
inline segment pattern_segment(const pattern_params& p, std::uint32_t j) {
    const auto u = [&](std::uint32_t k) { return pattern_uniform(p.seed, 37u, 6 * j + k); };
    const double t = 3.141592653589793 * u(2), side = std::min(p.width, p.height);
    return {{u(0) * p.width, u(1) * p.height}, {std::cos(t), std::sin(t)}, 0.5 * side * (0.05 + 0.25 * u(3)), 0.5 * (1 + u(4)), p.slope_rms * (2.4 + 3.2 * u(5))};
}
// The segment's slope contribution at u (its nearest periodic image), added to g.
inline void add_segment_slope(const pattern_params& p, const segment& sg, glm::dvec2 u, glm::dvec2& g) {
    glm::dvec2 d = u - sg.centre;
    d.x -= p.width * std::floor(d.x / p.width + 0.5), d.y -= p.height * std::floor(d.y / p.height + 0.5);
    const glm::dvec2 across_dir(-sg.direction.y, sg.direction.x);
    const double along = glm::dot(d, sg.direction), across = glm::dot(d, across_dir);
    if (std::fabs(along) <= sg.half_length && std::fabs(across) < sg.half_width) g += sg.slope * (across > 0 ? 1.0 : -1.0) * across_dir;
}

inline void check_pattern(const pattern_params& p) {
    const std::string what = std::string("glint::make_normal_map(") + pattern_name(p.kind) + "): ";
    if (p.width < 2 || p.height < 2)
        throw error(what + "size " + std::to_string(p.width) + " x " + std::to_string(p.height) + " is below 2 x 2");
    if (!(p.slope_rms > 0 && p.slope_rms <= 1)) throw error(what + "slope_rms = " + std::to_string(p.slope_rms) + " is outside (0, 1]");
    if (!(p.feature >= 1)) throw error(what + "feature = " + std::to_string(p.feature) + " is below 1 texel");
    if (p.cycles < 1) throw error(what + "cycles = " + std::to_string(p.cycles) + " is below 1");
    if (p.count < 0) throw error(what + "count = " + std::to_string(p.count) + " is negative");
    if (!(glm::length(p.tilt) < 1)) throw error(what + "|tilt| must be below 1");
}

}  // namespace detail

// The analytic normal of the pattern at texel coordinate u (any u: periodic patterns repeat).
inline glm::dvec3 pattern_normal(const pattern_params& p, glm::dvec2 u) {
    using detail::normal_from_gradient;
    const double two_pi = 6.283185307179586477;
    switch (p.kind) {
        case pattern::flat: return {0, 0, 1};
        case pattern::tilt: return {p.tilt.x, p.tilt.y, std::sqrt(1 - glm::dot(p.tilt, p.tilt))};
        case pattern::ramp: {
            const glm::dvec2 c(0.5 * p.width, 0.5 * p.height);
            const glm::dvec2 uc = glm::clamp(u, glm::dvec2(0), glm::dvec2(p.width, p.height));
            glm::dvec2 s = p.tilt + p.ramp_jacobian * (uc - c);
            const double r = glm::length(s);
            if (r > 0.99) s *= 0.99 / r;
            return {s.x, s.y, std::sqrt(1 - glm::dot(s, s))};
        }
        case pattern::sinusoid:
        case pattern::brushed:
        case pattern::noise:
        case pattern::anisotropic_noise: {
            glm::dvec2 g(0);
            for (const auto& w : detail::pattern_waves(p)) g -= w.amplitude * std::sin(glm::dot(w.k, u) + w.phase) * w.k;
            return normal_from_gradient(g);
        }
        case pattern::flakes: {
            glm::dvec2 p1(0), p2(0);
            glm::ivec2 c(0);
            detail::pattern_worley(p, u, p1, p2, c);
            const std::uint32_t cell = static_cast<std::uint32_t>(c.x + 4096 * c.y);
            // Box-Muller from two hashed uniforms.
            const double r = p.slope_rms * std::sqrt(-2 * std::log(1 - detail::pattern_uniform(p.seed, 29u, 2 * cell)));
            const double phi = two_pi * detail::pattern_uniform(p.seed, 29u, 2 * cell + 1);
            glm::dvec2 s(r * std::cos(phi), r * std::sin(phi));
            if (glm::length(s) > 0.9) s *= 0.9 / glm::length(s);
            return {s.x, s.y, std::sqrt(1 - glm::dot(s, s))};
        }
        case pattern::pyramids: {
            const double x = u.x / p.feature - std::floor(u.x / p.feature) - 0.5, y = u.y / p.feature - std::floor(u.y / p.feature) - 0.5;
            const glm::dvec2 g = std::fabs(x) > std::fabs(y) ? glm::dvec2(x > 0 ? -p.slope_rms : p.slope_rms, 0)
                                                             : glm::dvec2(0, y > 0 ? -p.slope_rms : p.slope_rms);
            return normal_from_gradient(g);
        }
        case pattern::scratches: {
            glm::dvec2 g(0);
            for (std::uint32_t j = 0; j < 3; ++j) {
                const int dir = static_cast<int>(detail::pattern_uniform(p.seed, 31u, 3 * j) * (p.width == p.height ? 3 : 2));
                const double width = 1.5 + 1.5 * detail::pattern_uniform(p.seed, 31u, 3 * j + 1);
                const double offset = detail::pattern_uniform(p.seed, 31u, 3 * j + 2);
                // Signed periodic distance to the groove's centre line, and that distance's gradient.
                double t, period;
                glm::dvec2 grad;
                if (dir == 0) t = u.y - offset * p.height, period = p.height, grad = {0, 1};
                else if (dir == 1) t = u.x - offset * p.width, period = p.width, grad = {1, 0};
                else t = (u.x - u.y - offset * p.width), period = p.width, grad = {1, -1};
                t -= period * std::floor(t / period + 0.5);
                double d = t;
                if (dir == 2) d /= std::sqrt(2.0), grad /= std::sqrt(2.0);
                if (std::fabs(d) < width / 2) g += 3 * p.slope_rms * (d > 0 ? 1.0 : -1.0) * grad;
            }
            return normal_from_gradient(g);
        }
        case pattern::leather: {
            glm::dvec2 p1(0), p2(0);
            glm::ivec2 c(0);
            detail::pattern_worley(p, u, p1, p2, c);
            const double f1 = glm::length(u - p1), f2 = glm::length(u - p2);
            const double m = 0.25 * p.feature;
            const double th = std::tanh((f2 - f1) / m);
            const glm::dvec2 g1 = f1 > 1e-12 ? (u - p1) / f1 : glm::dvec2(0), g2 = f2 > 1e-12 ? (u - p2) / f2 : glm::dvec2(0);
            // h = b m tanh((F2 - F1) / m) with b = slope_rms: dh = b (1 - tanh^2) (dF2 - dF1).
            return normal_from_gradient(p.slope_rms * (1 - th * th) * (g2 - g1));
        }
        case pattern::scratched_metal: {
            glm::dvec2 g(0);
            for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(p.count); ++j) detail::add_segment_slope(p, detail::pattern_segment(p, j), u, g);
            return normal_from_gradient(g);
        }
    }
    return {0, 0, 1};
}

// The pattern sampled at the texel centres (ramp: wrap_mode::clamp; the rest periodic).
inline normal_map make_normal_map(const pattern_params& p) {
    detail::check_pattern(p);
    std::vector<glm::vec3> n(static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height));
    const auto at = [&](int x, int y) -> glm::vec3& { return n[static_cast<std::size_t>(x) + static_cast<std::size_t>(p.width) * static_cast<std::size_t>(y)]; };
    if (p.kind == pattern::scratched_metal) {
        // pattern_normal at the texel centres, summed segment by segment over each one's bounding
        // box (the same sums in the same order) instead of over every segment at every texel.
        std::vector<glm::dvec2> g(n.size(), glm::dvec2(0));
        for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(p.count); ++j) {
            const detail::segment sg = detail::pattern_segment(p, j);
            const glm::dvec2 r = glm::abs(sg.direction) * sg.half_length + glm::abs(glm::dvec2(sg.direction.y, sg.direction.x)) * sg.half_width + 1.0;
            // (at most one period of texels, so that none is visited twice)
            const int y0 = static_cast<int>(std::floor(sg.centre.y - r.y)), x0 = static_cast<int>(std::floor(sg.centre.x - r.x));
            const int y1 = std::min(static_cast<int>(std::ceil(sg.centre.y + r.y)), y0 + p.height - 1);
            const int x1 = std::min(static_cast<int>(std::ceil(sg.centre.x + r.x)), x0 + p.width - 1);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const int wx = ((x % p.width) + p.width) % p.width, wy = ((y % p.height) + p.height) % p.height;
                    detail::add_segment_slope(p, sg, glm::dvec2(wx + 0.5, wy + 0.5), g[static_cast<std::size_t>(wx) + static_cast<std::size_t>(p.width) * static_cast<std::size_t>(wy)]);
                }
        }
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) at(x, y) = glm::vec3(detail::normal_from_gradient(g[static_cast<std::size_t>(x) + static_cast<std::size_t>(p.width) * static_cast<std::size_t>(y)]));
    } else {
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) at(x, y) = glm::vec3(pattern_normal(p, glm::dvec2(x + 0.5, y + 0.5)));
    }
    normal_map_options o;
    o.wrap = p.kind == pattern::ramp ? wrap_mode::clamp : wrap_mode::periodic;
    o.source = std::string("pattern ") + pattern_name(p.kind);
    return normal_map(p.width, p.height, std::move(n), o);
}

// sinusoid, brushed, noise: the exact mean over the texel centres of (dh/dx)^2 and (dh/dy)^2
// (the waves are distinct and below the Nyquist rate, so their cross terms average to 0).
inline glm::dvec2 pattern_slope_variance(const pattern_params& p) {
    detail::check_pattern(p);
    glm::dvec2 v(0);
    for (const auto& w : detail::pattern_waves(p)) v += w.amplitude * w.amplitude * w.k * w.k / 2.0;
    return v;
}

}  // namespace glint
