// Shared by the NDF-map tests and the report: example maps and the L1 distances between a map's
// P-NDF and a reference over the map's s-window.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

#include <glint/ndf_map.hpp>
#include <glint/patterns.hpp>

#include "pndf_support.hpp"

namespace glint_test {

// The five example kinds of XTXW24's figures, as n x n periodic patterns (seeded).
inline glint::pattern_params example_pattern(glint::pattern kind, int n, std::uint32_t seed = 3) {
    glint::pattern_params p;
    p.kind = kind, p.width = p.height = n, p.seed = seed;
    p.slope_rms = kind == glint::pattern::flakes ? 0.12 : kind == glint::pattern::scratches ? 0.1 : 0.15;
    p.feature = kind == glint::pattern::leather ? n / 2.5 : n / 5.0;
    return p;
}

inline const glint::pattern example_kinds[] = {glint::pattern::brushed, glint::pattern::noise, glint::pattern::flakes, glint::pattern::scratches,
                                               glint::pattern::leather};

// L1 at the map's resolution: sum over bins of |map at the bin's centre - the reference's mean
// over the bin (k x k midpoint sub-samples)| over the reference's sum. The map's value at a bin
// centre is its stored bin mixture, so this measures the spatial approximation alone (the
// tiles, their weights and levels), not the bins' width.
inline double binned_l1(const glint::ndf_map<float>& m, const std::function<double(glm::vec2)>& map, const std::function<double(glm::vec2)>& ref,
                        int k = 2) {
    const int res = m.resolution();
    const glm::dvec2 w0 = m.window_min();
    const double bw = m.bin_width();
    double l1 = 0, norm = 0;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const glm::vec2 c(static_cast<float>(w0.x + (x + 0.5) * bw), static_cast<float>(w0.y + (y + 0.5) * bw));
            if (!(c.x * c.x + c.y * c.y < 1.0f)) continue;
            double r = 0;
            for (int b = 0; b < k; ++b)
                for (int a = 0; a < k; ++a)
                    r += ref(glm::vec2(static_cast<float>(w0.x + (x + (a + 0.5) / k) * bw), static_cast<float>(w0.y + (y + (b + 0.5) / k) * bw)));
            r /= k * k;
            l1 += std::fabs(map(c) - r), norm += r;
        }
    return norm > 0 ? l1 / norm : 0.0;
}

// L1 between two functions on a g x g grid of points over the map's window (inside the disk).
inline double grid_l1(const glint::ndf_map<float>& m, const std::function<double(glm::vec2)>& a, const std::function<double(glm::vec2)>& b, int g) {
    const glm::dvec2 w0 = m.window_min();
    const double step = m.bin_width() * m.resolution() / g;
    double l1 = 0, norm = 0;
    for (int y = 0; y < g; ++y)
        for (int x = 0; x < g; ++x) {
            const glm::vec2 s(static_cast<float>(w0.x + (x + 0.5) * step), static_cast<float>(w0.y + (y + 0.5) * step));
            if (!(s.x * s.x + s.y * s.y < 1.0f)) continue;
            const double vb = b(s);
            l1 += std::fabs(a(s) - vb), norm += vb;
        }
    return norm > 0 ? l1 / norm : 0.0;
}

// The largest grid_l1 step of the map's P-NDF on layout pl as a footprint at `centre` (sds sd and
// aspect sd, rotated by angle) grows in 1% steps from sd = lo to hi: (the step, the sd where it is).
inline glm::dvec2 largest_growth_step(const glint::ndf_map<float>& m, const glint::ndf_placement<float>& pl, glm::vec2 centre, float aspect, float angle,
                                      float lo, float hi, int g) {
    const auto at = [&](float sd) { return rotated_footprint(centre, sd, aspect * sd, angle); };
    glm::dvec2 worst(0);
    for (float sd = lo; sd < hi; sd *= 1.01f) {
        const auto a = at(sd * 1.01f), b = at(sd);
        const double d = grid_l1(
            m, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, a, s)); }, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, b, s)); }, g);
        if (d > worst.x) worst = glm::dvec2(d, sd);
    }
    return worst;
}

// The largest grid_l1 step as an isotropic footprint of sd `sd` moves along x from x0 to x1 at
// height y in steps of 1/32 texel.
inline double largest_move_step(const glint::ndf_map<float>& m, const glint::ndf_placement<float>& pl, float sd, float x0, float x1, float y, int g) {
    double worst = 0;
    for (float x = x0; x < x1; x += 1.0f / 32) {
        const auto a = rotated_footprint(glm::vec2(x + 1.0f / 32, y), sd, sd, 0.0f), b = rotated_footprint(glm::vec2(x, y), sd, sd, 0.0f);
        worst = std::max(worst, grid_l1(
                                    m, [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, a, s)); },
                                    [&](glm::vec2 s) { return static_cast<double>(m.eval(pl, b, s)); }, g));
    }
    return worst;
}

}  // namespace glint_test
