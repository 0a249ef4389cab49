// Image-based lighting of glints (KK25 Sec. 4-5; kernels/ibl.glsl for the per-pixel part).
//
//   auto img = glint::io::read_exr("studio.exr");            // glint/io/exr.hpp
//   glint::ibl_options o;  o.levels = 4;                      // K = 4 or 8
//   auto env = glint::build_environment(img.width, img.height, img.rgb, o);  // levels, maps, tables
//   // per pixel (n, wo in world space, reflection r, roughness alpha, footprint uv derivatives):
//   auto s = env.lookup(r, std::sqrt(alpha));                 // radiance RGB + the K indicators
//   float e_rho = env.albedo(cos_o, std::sqrt(alpha)), e_d = env.visible_area(cos_o, std::sqrt(alpha));
//   auto e = glint::ibl_sample(uv, duvdx, duvdy, grid, env.levels(), s.indicators, e_d, env.total_area(alpha));
//   radiance = F * e_rho * s.radiance * glint::modulation(e);   // mean: the smooth split-sum IBL
//   // smooth shading needs the radiance alone: F * e_rho * env.lookup_radiance(r, std::sqrt(alpha))
//
// The environment (host side, may allocate and throw glint::error):
// - radiance levels (KK25 Eq. 18) from the luminance, clipped below at the black level l, and the
//   fuzzy indicator map of each level (Eq. 19), linear by default or log;
// - a roughness chain of equirectangular maps (y up, u = 1/2 along -z; chosen over a cube map
//   for a single seamless lookup with GL_REPEAT in u and GL_CLAMP_TO_EDGE in v): level m holds
//   sqrt(alpha) = m / (M - 1), level 0 the map itself (the mirror), each level m >= 1 the radiance
//   and the indicators filtered with the same GGX kernel p(wi) ~ G2(wi, r) D(h) under
//   n = wo = r (KK25 Eq. 11, 21; Karis 2013): GGX normal samples (Hammersley) with the source read
//   at the level of detail of each sample's solid angle (Colbert and Krivanek 2007), from a box
//   pyramid of the map;
// - two tables over (sqrt(cos theta_o), sqrt alpha), 64 x 64 by default, the same for every map
//   (computed once per process): the directional albedo E_rho (F = 1, Smith G2) by 1024
//   visible-normal samples, and the visible reflecting microfacet area E_D = D_Omega of the whole
//   upper hemisphere, computed exactly (glint::integrated_ndf_cone, 32 pieces).
// Lookups filter as OpenGL's GL_LINEAR (bilinear) and trilinear between roughness levels, so a
// GLSL renderer that uploads the same arrays as textures gets the same values.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.hpp"
#include "glint/grid.hpp"
#include "glint/microfacet.hpp"
#include "glint/multinomial.hpp"
#include "glint/detail/kernels.hpp"

namespace glint {

template <class real>
using ibl_levels = typename detail::glsl::kernels<real>::glint_ibl_levels;
template <class real>
using ibl_indicators = typename detail::glsl::kernels<real>::glint_ibl_indicators;
template <class real>
using ibl_estimate = typename detail::glsl::kernels<real>::glint_grid_estimate;

// The glint estimate under the environment (kernels/ibl.glsl, glint_ibl_sample).
template <class real>
ibl_estimate<real> ibl_sample(const vec2_t<real>& uv, const vec2_t<real>& duvdx, const vec2_t<real>& duvdy, const grid_params<real>& g,
                              const ibl_levels<real>& levels, const ibl_indicators<real>& indicators, real e_d, real d_h) {
    return detail::glsl::kernels<real>::glint_ibl_sample(uv, duvdx, duvdy, detail::to_kernel(g), levels,
                                                             indicators, e_d, d_h);
}

// The same on a pixel's footprint shared with its point lights (glint::grid_pixel_setup): exactly
// ibl_sample(uv, duvdx, duvdy, ...), with the lattice vertices computed once for all of them.
template <class real>
ibl_estimate<real> ibl_sample(grid_pixel<real>& px, const grid_params<real>& g, const ibl_levels<real>& levels,
                              const ibl_indicators<real>& indicators, real e_d, real d_h) {
    return detail::glsl::kernels<real>::glint_ibl_sample_pixel(px, detail::to_kernel(g), levels, indicators, e_d, d_h);
}

// Several pixels at once, as a CPU renderer shades a row or a tile: out[i] = ibl_sample(px[i], g,
// levels, indicators[i], e_d[i], d_h) for i < count (count <= 0: nothing), the draws and the
// expectation exactly and the value to float rounding (its vertices' counts are the same; their
// weighted sums are added in another order). For float where the CPU has AVX2, eight pixels share
// each pass of their draws in vector lanes (kernels/ibl.glsl, glint_ibl_sample_pixels; docs/ibl.md
// measures it); elsewhere one pixel at a time. Nothing allocated; the arrays hold count entries.
template <class real>
void ibl_sample_pixels(int count, grid_pixel<real>* px, const grid_params<real>& g, const ibl_levels<real>& levels, const ibl_indicators<real>* indicators,
                       const real* e_d, real d_h, ibl_estimate<real>* out) {
    detail::glsl::kernels<real>::glint_ibl_sample_pixels(count, px, detail::to_kernel(g), levels, indicators, e_d, d_h, out);
}

struct ibl_options {
    int levels = 4;             // K, 3..8 (KK25: 4 or 8)
    float black_level = 1e-3f;  // l: luminances below it count as l when placing the levels
    bool log_weights = false;   // Eq. 19 in log space (KK25 found linear to show fewer artifacts)
    int roughness_levels = 6;   // M: sqrt(alpha) = 0, 1/(M-1), ..., 1
    int samples = 64;           // GGX samples per prefiltered texel
    int table_size = 64;        // E_rho and E_D tables, table_size^2 entries
    // Called with the fraction done (0..1) during the prefiltering.
    std::function<void(double)> progress;
};

// The environment as the shading needs it. Channels per texel: R, G, B, then the K indicators.
class environment {
public:
    struct map {
        int width = 0, height = 0;
        std::vector<float> data;  // width * height * channels
    };
    struct sample {
        glm::vec3 radiance{0.0f};
        ibl_indicators<float> indicators{};
    };

    int channels() const { return 3 + levels_.count; }
    const ibl_levels<float>& levels() const { return levels_; }
    const std::vector<map>& roughness_chain() const { return chain_; }
    std::size_t clamped_pixels() const { return clamped_; }

    // Trilinear lookup at direction d (world, y up) and sqrt(alpha) in [0, 1]. The channel count as
    // a constant, so that the compiler unrolls the taps' sums and keeps them four channels a vector
    // register (channel_sums): read at run time, all 3 + K channels cost 1.8x the radiance's 3
    // (glint_frame_loop ibl-lookup against ibl-radiance, K = 4: 750 against 415 us a frame); as
    // constants 1.4x (530 against 375); four channels a register 1.1x to 1.2x (DEVELOPERS.md).
    sample lookup(const glm::vec3& d, float sqrt_alpha) const {
        switch (channels()) {  // 3 to 8 levels (build_environment checks)
            case 6: return lookup_channels<6>(d, sqrt_alpha);
            case 7: return lookup_channels<7>(d, sqrt_alpha);
            case 8: return lookup_channels<8>(d, sqrt_alpha);
            case 9: return lookup_channels<9>(d, sqrt_alpha);
            case 10: return lookup_channels<10>(d, sqrt_alpha);
            default: return lookup_channels<11>(d, sqrt_alpha);
        }
    }
    // The radiance alone (the indicators left 0): what smooth shading and the background need,
    // without reading the K indicator channels that only the glints use.
    glm::vec3 lookup_radiance(const glm::vec3& d, float sqrt_alpha) const { return lookup_channels<3>(d, sqrt_alpha).radiance; }

    // E_rho(cos theta_o, sqrt alpha) and E_D(cos theta_o, sqrt alpha), bilinear (GL_CLAMP_TO_EDGE)
    // in (sqrt(cos theta_o), sqrt alpha): the square root resolves the steep grazing end.
    float albedo(float cos_o, float sqrt_alpha) const { return table(e_rho_, std::sqrt(std::max(cos_o, 0.0f)), sqrt_alpha); }
    float visible_area(float cos_o, float sqrt_alpha) const { return table(e_d_, std::sqrt(std::max(cos_o, 0.0f)), sqrt_alpha); }
    // D_H of GGX at roughness alpha.
    float total_area(float alpha) const { return glint::total_area(ndf::ggx, glm::vec2(alpha)); }
    int table_size() const { return table_size_; }
    const std::vector<float>& albedo_table() const { return e_rho_; }
    const std::vector<float>& visible_area_table() const { return e_d_; }

private:
    friend environment build_environment(int width, int height, const std::vector<float>& rgb, const ibl_options& o);

    // The first Read channels of the trilinear lookup (3: the radiance; channels(): all).
    template <int Read>
    sample lookup_channels(const glm::vec3& d, float sqrt_alpha) const {
        using k = detail::glsl::kernels<float>;
        const glm::vec2 uv = k::glint_equirect_uv(d);
        const float f = std::clamp(sqrt_alpha, 0.0f, 1.0f) * static_cast<float>(chain_.size() - 1);
        const std::size_t m0 = std::min(static_cast<std::size_t>(f), chain_.size() - 1), m1 = std::min(m0 + 1, chain_.size() - 1);
        const float t = f - static_cast<float>(m0);
        channel_sums<Read> v{};
        const auto add = [&v](float w, const float* texel) { v.add(w, texel); };
        for_each_tap(chain_[m0], uv, channels(), 1 - t, add);
        if (t > 0) for_each_tap(chain_[m1], uv, channels(), t, add);
        float out[16] = {};
        v.write(out);
        sample s;
        s.radiance = glm::vec3(out[0], out[1], out[2]);
        for (int k2 = 0; k2 < 8; ++k2) s.indicators.w[k2] = k2 < levels_.count ? out[3 + k2] : 0.0f;
        return s;
    }

    // The sums of channels 0 .. Read - 1, four at a time (so that the compiler keeps each four in
    // one vector register): chunk j holds channels offset(j) .. offset(j) + 3, the last chunk
    // overlapping the one before where Read is not a multiple of 4 (the shared channels summed
    // twice, with the same operations). Read = 3 reads channel 3 too: a texel has at least 6.
    template <int Read>
    struct channel_sums {
        static constexpr int chunks = (Read + 3) / 4;
        static constexpr int offset(int j) { return Read < 4 ? 0 : std::min(4 * j, Read - 4); }
        float sum[static_cast<std::size_t>(chunks)][4];

        // sum += w x channels 0 .. Read - 1 of a texel.
        void add(float w, const float* texel) {
            for (int j = 0; j < chunks; ++j)
                for (int l = 0; l < 4; ++l) sum[j][l] += w * texel[static_cast<std::size_t>(offset(j) + l)];
        }
        // out[c] = channel c's sum, for c < Read (and out[3] where Read = 3).
        void write(float* out) const {
            for (int j = 0; j < chunks; ++j)
                for (int l = 0; l < 4; ++l) out[offset(j) + l] = sum[j][l];
        }
    };

    // f(w, texel) for the four taps of the GL_LINEAR filtered texel of m (C channels a texel) at
    // uv, w the tap's bilinear weight times `weight`.
    template <class F>
    static void for_each_tap(const map& m, const glm::vec2& uv, int C, float weight, F&& f) {
        const auto taps = detail::glsl::kernels<float>::glint_bilinear(uv, m.width, m.height);
        for (int i = 0; i < 4; ++i) {
            const glm::ivec2 p = taps.texel[i];
            f(weight * taps.weight[i],
              &m.data[(static_cast<std::size_t>(p.y) * static_cast<std::size_t>(m.width) + static_cast<std::size_t>(p.x)) * static_cast<std::size_t>(C)]);
        }
    }

    float table(const std::vector<float>& t, float x, float y) const {
        const int n = table_size_;
        const float fx = std::clamp(x * static_cast<float>(n) - 0.5f, 0.0f, static_cast<float>(n - 1));
        const float fy = std::clamp(y * static_cast<float>(n) - 0.5f, 0.0f, static_cast<float>(n - 1));
        const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy), x1 = std::min(x0 + 1, n - 1), y1 = std::min(y0 + 1, n - 1);
        const float ax = fx - static_cast<float>(x0), ay = fy - static_cast<float>(y0);
        auto at = [&](int i, int j) { return t[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)]; };
        return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x1, y0)) + ay * ((1 - ax) * at(x0, y1) + ax * at(x1, y1));
    }

    ibl_levels<float> levels_{};
    std::vector<map> chain_;
    std::vector<float> e_rho_, e_d_;
    int table_size_ = 0;
    std::size_t clamped_ = 0;
};

namespace detail {

inline double luminance(const float* rgb) {
    return 0.2126 * static_cast<double>(rgb[0]) + 0.7152 * static_cast<double>(rgb[1]) + 0.0722 * static_cast<double>(rgb[2]);
}

// The (i + 1/2)-th radical inverse pair of i in [0, n): a Hammersley point.
inline glm::vec2 hammersley(std::uint32_t i, std::uint32_t n) {
    std::uint32_t b = i;
    b = (b << 16u) | (b >> 16u);
    b = ((b & 0x55555555u) << 1u) | ((b & 0xAAAAAAAAu) >> 1u);
    b = ((b & 0x33333333u) << 2u) | ((b & 0xCCCCCCCCu) >> 2u);
    b = ((b & 0x0F0F0F0Fu) << 4u) | ((b & 0xF0F0F0F0u) >> 4u);
    b = ((b & 0x00FF00FFu) << 8u) | ((b & 0xFF00FF00u) >> 8u);
    return {(static_cast<float>(i) + 0.5f) / static_cast<float>(n), static_cast<float>(b) * 2.3283064365386963e-10f};  // 2^-32
}

inline void frame_of(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const glm::vec3 a = std::fabs(n.y) < 0.999f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    t = glm::normalize(glm::cross(a, n));
    b = glm::cross(n, t);
}

// The directional albedo E_rho(wo) of GGX at roughness alpha (F = 1, Smith G2): the mean of
// G2 / G1 over S visible normals at Hammersley points.
inline double directional_albedo(const glm::dvec3& wo, double alpha, int S) {
    double e = 0;
    for (int s = 0; s < S; ++s) {
        const glm::vec2 u = hammersley(static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(S));
        const glm::dvec3 h = sample_vndf_ggx(wo, glm::dvec2(alpha), static_cast<double>(u.x), static_cast<double>(u.y));
        const glm::dvec3 wi = 2 * glm::dot(wo, h) * h - wo;
        const double g1 = smith_g1(ndf::ggx, wo, h, glm::dvec2(alpha));
        if (wi.z > 0 && g1 > 0) e += smith_g2(ndf::ggx, wi, wo, h, glm::dvec2(alpha)) / g1;
    }
    return e / S;
}

// The visible reflecting microfacet area E_D(wo) of GGX: D_Omega over the whole upper hemisphere
// (glint::integrated_ndf_cone, 32 pieces per edge).
inline double visible_area(const glm::dvec3& wo, double alpha) {
    return integrated_ndf_cone(ndf::ggx, wo, glm::dvec2(alpha), glm::dvec3(0, 0, 1), 0.5 * 3.14159265358979323846, 32);
}

// E_rho (1024 samples) and E_D over (sqrt(cos theta_o), sqrt alpha) at texel centres
// (i + 1/2) / T, computed once per table size.
inline const std::pair<std::vector<float>, std::vector<float>>& ibl_tables(int T) {
    static std::map<int, std::pair<std::vector<float>, std::vector<float>>> cache;
    static std::mutex lock;
    std::lock_guard<std::mutex> guard(lock);
    auto it = cache.find(T);
    if (it != cache.end()) return it->second;
    std::vector<float> e_rho(static_cast<std::size_t>(T * T)), e_d(static_cast<std::size_t>(T * T));
    for (int j = 0; j < T; ++j)
        for (int i = 0; i < T; ++i) {
            const double q = (i + 0.5) / T, c = q * q, sa = (j + 0.5) / T, alpha = std::max(sa * sa, 1e-4);
            const glm::dvec3 wo(std::sqrt(std::max(0.0, 1 - c * c)), 0, c);
            e_rho[static_cast<std::size_t>(j * T + i)] = static_cast<float>(directional_albedo(wo, alpha, 1024));
            e_d[static_cast<std::size_t>(j * T + i)] = static_cast<float>(visible_area(wo, alpha));
        }
    return cache.emplace(T, std::make_pair(std::move(e_rho), std::move(e_d))).first->second;
}

}  // namespace detail

// Builds the environment from width x height linear RGB pixels (equirectangular, rows top to
// bottom). Throws glint::error for an empty image, a pixel count that does not match, levels
// outside 3..8, a black level <= 0, fewer than 2 roughness levels, or fewer than 1 sample.
inline environment build_environment(int width, int height, const std::vector<float>& rgb, const ibl_options& o) {
    using k = detail::glsl::kernels<float>;
    if (width < 2 || height < 2)
        throw error("glint::build_environment: the map is " + std::to_string(width) + " x " + std::to_string(height) + "; at least 2 x 2 is needed");
    if (rgb.size() != 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
        throw error("glint::build_environment: " + std::to_string(rgb.size()) + " floats for " + std::to_string(width) + " x " +
                    std::to_string(height) + " RGB pixels");
    if (o.levels < 3 || o.levels > 8) throw error("glint::build_environment: levels = " + std::to_string(o.levels) + ", must be 3..8");
    if (!(o.black_level > 0)) throw error("glint::build_environment: black_level = " + std::to_string(o.black_level) + ", must be > 0");
    if (o.roughness_levels < 2) throw error("glint::build_environment: roughness_levels = " + std::to_string(o.roughness_levels) + ", must be >= 2");
    if (o.samples < 1 || o.table_size < 2) throw error("glint::build_environment: samples and table_size must be >= 1 and >= 2");
    environment env;
    const int K = o.levels, C = 3 + K;
    // Levels (Eq. 18) from the luminance range, clipped below at the black level.
    double lo = 1e300, hi = 0;
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<float> clean(rgb);
    for (std::size_t i = 0; i < n; ++i) {
        bool bad = false;
        for (std::size_t c = 0; c < 3; ++c)
            if (!(std::isfinite(clean[3 * i + c]) && clean[3 * i + c] >= 0)) clean[3 * i + c] = 0, bad = true;
        env.clamped_ += bad;
        const double y = detail::luminance(&clean[3 * i]);
        lo = std::min(lo, y), hi = std::max(hi, y);
    }
    lo = std::max(lo, static_cast<double>(o.black_level));
    hi = std::max(hi, lo);
    env.levels_.count = K;
    for (int j = 0; j < 8; ++j) env.levels_.radiance[j] = j < K ? k::glint_ibl_level(j, K, static_cast<float>(lo), static_cast<float>(hi)) : 0.0f;
    // The source: radiance and fuzzy indicators (Eq. 19), then its box pyramid.
    std::vector<environment::map> pyramid(1);
    pyramid[0].width = width, pyramid[0].height = height;
    pyramid[0].data.assign(n * static_cast<std::size_t>(C), 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        float* px = &pyramid[0].data[i * static_cast<std::size_t>(C)];
        px[0] = clean[3 * i], px[1] = clean[3 * i + 1], px[2] = clean[3 * i + 2];
        const glm::vec2 jt = k::glint_ibl_fuzzy_weight(static_cast<float>(detail::luminance(&clean[3 * i])), env.levels_, o.log_weights);
        const int j = static_cast<int>(jt.x);
        px[3 + j] += 1 - jt.y;
        px[3 + j + 1] += jt.y;
    }
    while (pyramid.back().width > 1 && pyramid.back().height > 1) {
        const auto& s = pyramid.back();
        environment::map d;
        d.width = std::max(1, s.width / 2), d.height = std::max(1, s.height / 2);
        d.data.assign(static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height) * static_cast<std::size_t>(C), 0.0f);
        for (int y = 0; y < d.height; ++y)
            for (int x = 0; x < d.width; ++x)
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx) {
                        const int sx = std::min(2 * x + dx, s.width - 1), sy = std::min(2 * y + dy, s.height - 1);
                        for (int c = 0; c < C; ++c)
                            d.data[(static_cast<std::size_t>(y) * static_cast<std::size_t>(d.width) + static_cast<std::size_t>(x)) * static_cast<std::size_t>(C) + static_cast<std::size_t>(c)] +=
                                0.25f * s.data[(static_cast<std::size_t>(sy) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(sx)) * static_cast<std::size_t>(C) + static_cast<std::size_t>(c)];
                    }
        pyramid.push_back(std::move(d));
    }
    // Trilinear fetch from the pyramid at a fractional level of detail.
    auto fetch_lod = [&](const glm::vec3& d, float lod, float* out) {
        const glm::vec2 uv = k::glint_equirect_uv(d);
        lod = std::clamp(lod, 0.0f, static_cast<float>(pyramid.size() - 1));
        const std::size_t l0 = static_cast<std::size_t>(lod), l1 = std::min(l0 + 1, pyramid.size() - 1);
        const float t = lod - static_cast<float>(l0);
        for (int c = 0; c < C; ++c) out[c] = 0;
        for (int side = 0; side < 2; ++side) {
            const float wl = side == 0 ? 1 - t : t;
            if (wl > 0)  // every channel: C is known at run time only
                environment::for_each_tap(pyramid[side == 0 ? l0 : l1], uv, C, wl, [&](float w, const float* px) {
                    for (int c = 0; c < C; ++c) out[c] += w * px[c];
                });
        }
    };
    // The roughness chain.
    const int M = o.roughness_levels;
    env.chain_.resize(static_cast<std::size_t>(M));
    env.chain_[0] = pyramid[0];
    double work_total = 0, work_done = 0;
    for (int m = 1; m < M; ++m) work_total += static_cast<double>(std::max(8, width >> m)) * std::max(4, height >> m);
    const float texel_solid_angle = 4 * 3.14159265f / static_cast<float>(n);
    for (int m = 1; m < M; ++m) {
        const float sa = static_cast<float>(m) / static_cast<float>(M - 1), alpha = std::max(sa * sa, 1e-4f);
        environment::map& out = env.chain_[static_cast<std::size_t>(m)];
        out.width = std::max(8, width >> m), out.height = std::max(4, height >> m);
        out.data.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * static_cast<std::size_t>(C), 0.0f);
        for (int y = 0; y < out.height; ++y) {
            for (int x = 0; x < out.width; ++x) {
                const glm::vec3 r = k::glint_equirect_direction(glm::vec2((static_cast<float>(x) + 0.5f) / static_cast<float>(out.width),
                                                                          (static_cast<float>(y) + 0.5f) / static_cast<float>(out.height)));
                glm::vec3 t, b;
                detail::frame_of(r, t, b);
                double acc[16] = {}, wsum = 0;
                float v[16] = {};
                for (int s = 0; s < o.samples; ++s) {
                    const glm::vec2 u = detail::hammersley(static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(o.samples));
                    const glm::vec3 h = k::glint_sample_vndf_ggx(glm::vec3(0, 0, 1), glm::vec2(alpha), u.x, u.y);  // = NDF sampling for wo = n
                    const glm::vec3 l(2 * h.z * h.x, 2 * h.z * h.y, 2 * h.z * h.z - 1);
                    if (!(l.z > 0)) continue;
                    const float w = k::glint_smith_g2(k::GLINT_NDF_GGX, l, glm::vec3(0, 0, 1), h, glm::vec2(alpha));
                    if (!(w > 0)) continue;
                    const float pdf = k::glint_ndf(k::GLINT_NDF_GGX, h, glm::vec2(alpha)) / 4;  // of l: D (n.h) / (4 v.h), v = n
                    const float lod = 0.5f * std::log2(1.0f / (static_cast<float>(o.samples) * pdf * texel_solid_angle)) + 1.0f;
                    fetch_lod(l.x * t + l.y * b + l.z * r, lod, v);
                    for (int c = 0; c < C; ++c) acc[c] += static_cast<double>(w) * static_cast<double>(v[c]);
                    wsum += static_cast<double>(w);
                }
                float* px = &out.data[(static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x)) * static_cast<std::size_t>(C)];
                for (int c = 0; c < C; ++c) px[c] = wsum > 0 ? static_cast<float>(acc[c] / wsum) : 0.0f;
            }
            work_done += out.width;
            if (o.progress) o.progress(work_done / work_total);
        }
    }
    // Tables (shared by every environment with this table size).
    const auto& tables = detail::ibl_tables(o.table_size);
    env.table_size_ = o.table_size;
    env.e_rho_ = tables.first;
    env.e_d_ = tables.second;
    return env;
}

}  // namespace glint
