// Tangent-space normal maps for normal-mapped microstructure (YHMR16, XTXW24, ZXW, AKKW): the map
// type, bilinear and periodic bicubic interpolation with the analytic Jacobian of the normal's xy
// part, a height-map conversion, and seeded periodic procedural patterns (glint/patterns.hpp).
// File readers: glint/io/normal_map.hpp.
//
//   glint::normal_map m(256, 256, normals);            // row-major, x fastest; throws glint::error
//   auto q = m.bicubic(glm::dvec2(10.3, 7.9));          // q.s = n.xy, q.jacobian = ds/du (columns d/dx, d/dy)
//
// Conventions. Texel coordinates u = (x, y) are in texels; texel (i, j) (column i, row j) is
// centred at (i + 1/2, j + 1/2). The tangent frame is (x along columns, y along rows, z = x cross
// y out of the surface): a renderer that maps the texture with tangent dP/du and bitangent dP/dv
// (v along rows) and normal T x B reads n directly. Normals are unit with z > 0. The map is
// periodic by default (the patterns are); wrap_mode::clamp extends the border texels.
//
// Interpolation. bilinear: the normals' bilinear blend, renormalised (its Jacobian jumps across
// texel centres). bicubic: Catmull-Rom cubic convolution of the normals (Keys 1981 with
// a = -1/2; C1, so the Jacobian is continuous, which the Gaussian elements need), renormalised;
// the Jacobian is the exact derivative of that renormalised interpolant. Where the blend's
// length falls below 1e-6 (only for maps whose neighbouring normals nearly cancel) it is taken
// as 1e-6.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "glint/core/error.hpp"

namespace glint {

enum class wrap_mode { periodic, clamp };

struct normal_map_options {
    wrap_mode wrap = wrap_mode::periodic;
    // Normals with z <= min_z: an error (default), or, with clamp_z, raised to z = min_z with
    // their xy part scaled to keep unit length, and counted.
    bool clamp_z = false;
    float min_z = 1e-3f;
    // Named in error messages (a file path, or what made the normals).
    std::string source = "normal_map";
};

// The normal's xy part s and its Jacobian ds/du at a point (columns: d/dx, d/dy), z = sqrt(1-|s|^2).
template <class real>
struct normal_sample {
    glm::vec<2, real, glm::defaultp> s{0};
    glm::mat<2, 2, real, glm::defaultp> jacobian{0};
    glm::vec<3, real, glm::defaultp> normal() const {
        return {s.x, s.y, std::sqrt(std::max(real(0), real(1) - s.x * s.x - s.y * s.y))};
    }
};

class normal_map {
public:
    normal_map() = default;

    // width x height normals, row-major with x fastest. Non-unit normals are renormalised (and
    // counted); a zero size, a wrong count, a non-finite or zero-length normal, or z <= min_z
    // (unless clamp_z) throw glint::error naming the source, the texel and the value.
    normal_map(int width, int height, std::vector<glm::vec3> normals, const normal_map_options& options = {})
        : width_(width), height_(height), wrap_(options.wrap), normals_(std::move(normals)) {
        const std::string& src = options.source;
        if (width <= 0 || height <= 0)
            throw error("glint::normal_map: " + src + ": size " + std::to_string(width) + " x " + std::to_string(height) + " is empty");
        const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
        if (normals_.size() != n)
            throw error("glint::normal_map: " + src + ": " + std::to_string(normals_.size()) + " normals given for " + std::to_string(width) +
                        " x " + std::to_string(height) + " texels (" + std::to_string(n) + " expected)");
        if (!(options.min_z >= 0.0f && options.min_z < 1.0f))
            throw error("glint::normal_map: " + src + ": min_z = " + std::to_string(options.min_z) + " is outside [0, 1)");
        for (std::size_t i = 0; i < n; ++i) {
            glm::vec3& v = normals_[i];
            const auto where = [&] {
                return src + ": texel (" + std::to_string(i % static_cast<std::size_t>(width)) + ", " +
                       std::to_string(i / static_cast<std::size_t>(width)) + ") normal (" + std::to_string(v.x) + ", " + std::to_string(v.y) +
                       ", " + std::to_string(v.z) + ")";
            };
            if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) throw error("glint::normal_map: " + where() + " is not finite");
            const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
            if (!(len > 1e-20f)) throw error("glint::normal_map: " + where() + " has zero length");
            if (std::fabs(len - 1.0f) > 1e-6f) v /= len, ++renormalised_;
            if (!(v.z > options.min_z)) {
                if (!options.clamp_z)
                    throw error("glint::normal_map: " + where() + ": z must exceed " + std::to_string(options.min_z) +
                                " (tangent-space normals point out of the surface; normal_map_options::clamp_z raises them)");
                const float z = options.min_z > 0 ? options.min_z : 1e-3f;
                const float r = std::sqrt(v.x * v.x + v.y * v.y);
                const float k = r > 0 ? std::sqrt(1.0f - z * z) / r : 0.0f;
                v = glm::vec3(v.x * k, v.y * k, r > 0 ? z : 1.0f);
                ++clamped_;
            }
        }
    }

    // From a height field (texel units; heights[x + width y] at texel centres, scaled by
    // height_scale): n = normalize(-dh/dx, -dh/dy, 1) with central differences (one-sided at a
    // clamped border). Throws glint::error for a bad size or non-finite heights.
    static normal_map from_heights(int width, int height, const std::vector<float>& heights, float height_scale = 1.0f,
                                   const normal_map_options& options = {}) {
        if (width <= 0 || height <= 0)
            throw error("glint::normal_map::from_heights: " + options.source + ": size " + std::to_string(width) + " x " +
                        std::to_string(height) + " is empty");
        const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
        if (heights.size() != n)
            throw error("glint::normal_map::from_heights: " + options.source + ": " + std::to_string(heights.size()) + " heights given for " +
                        std::to_string(n) + " texels");
        if (!std::isfinite(height_scale))
            throw error("glint::normal_map::from_heights: " + options.source + ": height_scale is not finite");
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(heights[i]))
                throw error("glint::normal_map::from_heights: " + options.source + ": height at texel (" +
                            std::to_string(i % static_cast<std::size_t>(width)) + ", " + std::to_string(i / static_cast<std::size_t>(width)) +
                            ") is not finite");
        const bool periodic = options.wrap == wrap_mode::periodic;
        const auto h = [&](int x, int y) {
            x = periodic ? ((x % width) + width) % width : std::clamp(x, 0, width - 1);
            y = periodic ? ((y % height) + height) % height : std::clamp(y, 0, height - 1);
            return static_cast<double>(heights[static_cast<std::size_t>(x) + static_cast<std::size_t>(width) * static_cast<std::size_t>(y)]);
        };
        std::vector<glm::vec3> normals(n);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const int x0 = periodic ? x - 1 : std::max(x - 1, 0), x1 = periodic ? x + 1 : std::min(x + 1, width - 1);
                const int y0 = periodic ? y - 1 : std::max(y - 1, 0), y1 = periodic ? y + 1 : std::min(y + 1, height - 1);
                const double gx = x1 > x0 ? (h(x1, y) - h(x0, y)) / (x1 - x0) : 0.0, gy = y1 > y0 ? (h(x, y1) - h(x, y0)) / (y1 - y0) : 0.0;
                const double k = static_cast<double>(height_scale);
                const glm::dvec3 v = glm::normalize(glm::dvec3(-k * gx, -k * gy, 1.0));
                normals[static_cast<std::size_t>(x) + static_cast<std::size_t>(width) * static_cast<std::size_t>(y)] = glm::vec3(v);
            }
        return normal_map(width, height, std::move(normals), options);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    wrap_mode wrap() const { return wrap_; }
    const std::vector<glm::vec3>& normals() const { return normals_; }
    // How many input normals were renormalised, and how many had z raised (clamp_z).
    std::size_t renormalised() const { return renormalised_; }
    std::size_t clamped() const { return clamped_; }

    // The texel (x, y), with x and y wrapped (periodic) or clamped into the map.
    const glm::vec3& texel(long x, long y) const {
        const long w = width_, h = height_;
        // Inside the map needs no wrap (a 64-bit division costs about 30 cycles, and the bicubic reads 16).
        if (x < 0 || x >= w) x = wrap_ == wrap_mode::periodic ? ((x % w) + w) % w : std::clamp(x, 0L, w - 1);
        if (y < 0 || y >= h) y = wrap_ == wrap_mode::periodic ? ((y % h) + h) % h : std::clamp(y, 0L, h - 1);
        return normals_[static_cast<std::size_t>(x) + static_cast<std::size_t>(w) * static_cast<std::size_t>(y)];
    }

    template <class real>
    normal_sample<real> bilinear(const glm::vec<2, real, glm::defaultp>& u) const {
        return interpolate<real, 2>(u);
    }
    template <class real>
    normal_sample<real> bicubic(const glm::vec<2, real, glm::defaultp>& u) const {
        return interpolate<real, 4>(u);
    }

private:
    // Catmull-Rom weights (taps at -1, 0, 1, 2 around t in [0, 1)) and their derivatives; bilinear
    // for taps = 2.
    template <class real, int taps>
    static void weights(real t, real* w, real* dw) {
        if (taps == 2) {
            w[0] = real(1) - t, w[1] = t, dw[0] = real(-1), dw[1] = real(1);
            return;
        }
        const real t2 = t * t, t3 = t2 * t;
        w[0] = real(0.5) * (-t3 + real(2) * t2 - t);
        w[1] = real(0.5) * (real(3) * t3 - real(5) * t2 + real(2));
        w[2] = real(0.5) * (real(-3) * t3 + real(4) * t2 + t);
        w[3] = real(0.5) * (t3 - t2);
        dw[0] = real(0.5) * (real(-3) * t2 + real(4) * t - real(1));
        dw[1] = real(0.5) * (real(9) * t2 - real(10) * t);
        dw[2] = real(0.5) * (real(-9) * t2 + real(8) * t + real(1));
        dw[3] = real(0.5) * (real(3) * t2 - real(2) * t);
    }

    template <class real, int taps>
    normal_sample<real> interpolate(const glm::vec<2, real, glm::defaultp>& u) const {
        return interpolate_with<real, taps>([this](long x, long y) -> const glm::vec3& { return texel(x, y); }, u);
    }

public:
    // The interpolation above over any texel source fetch(x, y) -> const glm::vec3& (integer texel
    // coordinates, the source does its own wrapping): the implicit quilted maps of lobe_tree.hpp
    // use it so that their lobes are bit-equal to those of the map they stand for.
    template <class real, int taps, class fetch_t>
    static normal_sample<real> interpolate_with(const fetch_t& fetch, const glm::vec<2, real, glm::defaultp>& u) {
        using v3 = glm::vec<3, real, glm::defaultp>;
        const real px = u.x - real(0.5), py = u.y - real(0.5);
        const real fx = std::floor(px), fy = std::floor(py);
        // Far from the origin a float coordinate has no sub-texel bits: indices as long as they fit.
        const long ix = static_cast<long>(std::clamp(fx, real(-1e9), real(1e9))), iy = static_cast<long>(std::clamp(fy, real(-1e9), real(1e9)));
        if (taps == 4 && px == fx && py == fy) {
            // On a texel centre Catmull-Rom's weights are (0, 1, 0, 0) and its derivative's
            // (-1/2, 0, 1/2, 0), exactly: the sums below are the loop's, term for term (the loop
            // adds only zeros besides), so the result is bit for bit the same with 5 taps of 16.
            v3 vx = real(-0.5) * v3(fetch(ix - 1, iy));
            vx += real(0.5) * v3(fetch(ix + 1, iy));
            v3 vy = real(-0.5) * v3(fetch(ix, iy - 1));
            vy += real(0.5) * v3(fetch(ix, iy + 1));
            return normalised(v3(fetch(ix, iy)), vx, vy);
        }
        real wx[4], dwx[4], wy[4], dwy[4];
        weights<real, taps>(px - fx, wx, dwx);
        weights<real, taps>(py - fy, wy, dwy);
        const long first = taps == 2 ? 0 : -1;
        v3 v(0), vx(0), vy(0);
        for (int j = 0; j < taps; ++j)
            for (int i = 0; i < taps; ++i) {
                const long x = ix + first + i, y = iy + first + j;
                const v3 n(fetch(x, y));
                v += (wx[i] * wy[j]) * n, vx += (dwx[i] * wy[j]) * n, vy += (wx[i] * dwy[j]) * n;
            }
        return normalised(v, vx, vy);
    }

private:
    // The unit normal of the interpolated v and its Jacobian from v's derivatives vx, vy.
    template <class real>
    static normal_sample<real> normalised(const glm::vec<3, real, glm::defaultp>& v, const glm::vec<3, real, glm::defaultp>& vx,
                                          const glm::vec<3, real, glm::defaultp>& vy) {
        using v3 = glm::vec<3, real, glm::defaultp>;
        const real len = std::max(std::sqrt(glm::dot(v, v)), real(1e-6));
        const v3 n = v / len;
        normal_sample<real> r;
        r.s = {n.x, n.y};
        // d(v / |v|) = (dv - n (n . dv)) / |v|
        const v3 dx = (vx - n * glm::dot(n, vx)) / len, dy = (vy - n * glm::dot(n, vy)) / len;
        r.jacobian[0] = {dx.x, dx.y};
        r.jacobian[1] = {dy.x, dy.y};
        return r;
    }

    int width_ = 0, height_ = 0;
    wrap_mode wrap_ = wrap_mode::periodic;
    std::vector<glm::vec3> normals_;
    std::size_t renormalised_ = 0, clamped_ = 0;
};

}  // namespace glint
