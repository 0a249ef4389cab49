// Tiny-example multi-scale NDF maps (XTXW24): the P-NDF of a surface covered by transformed copies
// of a small periodic normal map (the example, 4 to 256 texels on a side), from NDF images of
// its tiles precomputed at every level (XTXW24 Sec. 5.2, Eq. 7), summed over the tiles under a
// pixel's footprint (Sec. 6.3), with the example's Gaussian elements (Eq. 6, glint/gaussian.hpp)
// for footprints smaller than a tile. Kernels (C++ and GLSL): kernels/ndf_map.glsl.
//
//   glint::ndf_map_params mp;  mp.sigma_r = 0.005;
//   auto map = glint::ndf_map<float>::build(example, mp);              // host side, may throw
//   auto tiled = glint::ndf_placement<float>::tiled();                   // or ::stochastic(cell, seed)
//   auto fp = glint::footprint_from_uv_derivatives(uv, duvdx, duvdy, texels_per_uv);   // per pixel
//   float d = map.eval(tiled, fp, glm::vec2(h.x, h.y));                 // density over the disk
//   float f = map.brdf(tiled, fp, wi, wo, eta, k);                       // Eq. 1
//
// Images (Eq. 7). Level l holds (n / 2^(l+1))^2 tiles of t = 2^(l+1) texels per side (XTXW24
// Sec. 5.2: log2 n levels, 8^2 + 4^2 + 2^2 + 1 tiles for n = 16). A tile's NDF is the mean of its
// elements' normal marginals a_i N(s; s_i, sigma_r^2 I + sigma_h^2 J_i J_i^T) over its area t^2 (the
// footprint -> infinity limit of each Eq. 6 term): a density over s that integrates to 1. Level 0
// is binned from the elements: each bin holds the bin's mean, by the midpoint rule on k x k
// sub-samples with spacing at most sigma_r / 2 (k = ceil(2 bin / sigma_r), at most 32; the
// narrowest lobe's sd is sigma_r, and the rule's error on a bin is below (spacing / sd)^2 / 24 =
// 1% of the lobe's peak there, while its total mass is exact to exp(-2 pi^2 (sd / spacing)^2) =
// 1e-34: a point sample per bin, as a bin of 2 / 128 = 0.0156 against sigma_r = 0.005 would be,
// aliases by tens of percent). Every coarser tile is the exact mean of its four children as stored
// (in double, rounded once). The window: the square around every lobe to 4.5 sd (mass outside
// below 1e-5), or [-1, 1]^2 (ndf_map_params::fit_window = false). Beyond the paper, every bin also
// holds the NDF's first moments in position, B_x, B_y (kernels/ndf_map.glsl), and the running sum
// of bin masses for sampling: 4 floats per bin (XTXW24 stores 1).
//
// Evaluation (Sec. 6.3; the paper gives no weights, the rules here are glint's):
// - the footprint N(mu, Sigma) goes into each copy's example frame, mu' = A^-1 (mu - anchor) +
//   offset, Sigma' = A^-1 Sigma A^-T, and s into s_ex (normals under A: kernels/ndf_map.glsl);
// - Eq. 8-9's M acts on the example's texel coordinates (homogeneous, third coordinate 1: the
//   paper's t_z = sqrt(1 - t_x^2 - t_y^2) would make translation depend on position); its linear
//   part is A, its translation the anchor and offset;
// - tiles of level l count with their footprint mass W = t^2 N(c_T; mu', Sigma' + (sigma_h^2 +
//   t^2 / 12) I), tapered to 0 from Mahalanobis radius cull - 1 to cull, and
//   D = sum W (B_T + t g . (B_x, B_y)_T) / sum W, g the gradient of the elements' log weight at the
//   tile's centre (first order in position; the published zero-order tiles, eval_zero_order, err
//   2 to 5 times more at footprints of 4 to 8 texels);
// - the level: tiles no wider than tau x the minor sd, and at most max_tiles in the culling
//   ellipse; the last `blend` of each octave blends the level with the next coarser, so D is
//   continuous as the footprint grows; a tiled layout at the top level is B_top (every top tile is);
// - footprints with minor sd below direct_below texels take the element path (Eq. 6 on the
//   example's elements, exact), blended into the map up to twice that;
// - stochastic layouts: each copy counts the tiles whose centres it owns (tiles at most half a
//   cell); footprints from a quarter to half a cell blend into whole copies (each copy's top image
//   weighted by cell^2 N(anchor; mu, Sigma + cell^2 / 12 I)); footprints wider than max_cells cells
//   across their culling box are narrowed to that.
// Measured errors (L1 against the direct P-NDF of the same layout) and costs: docs/ndf_map.md.
//
// Sampling: a part, a tile or element by its share, then s from the tile's bilinear image B
// exactly (or the element's lobe): its density is the zero-order P-NDF over mass (pdf()), which is
// positive wherever eval is, so eval / pdf is an unbiased weight.
//
// Domains: sigma_r in [1e-4, 1]; footprints finite (a covariance with anisotropy above 16 grows its
// minor axis to major / 16); s finite. Per-pixel calls never allocate or throw, and return 0 for
// |s| >= 1.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "glint/core/error.hpp"
#include "glint/gaussian.hpp"
#include "glint/normal_map.hpp"

namespace glint {

struct ndf_map_params {
    int resolution = 128;        // bins per image side, 8 to 1024
    double sigma_r = 0.005;      // intrinsic roughness of every lobe, [1e-4, 1]
    int elements_per_texel = 1;  // seeds per texel side: 1, 2 or 4
    bool fit_window = true;      // the s-window around the lobes (else [-1, 1]^2)
    int supersample = 0;         // sub-samples per bin side; 0: the rule in the header (spacing <= sigma_r / 2)
    double tau = 1;              // tiles at most tau x the footprint's minor sd on a side, (0, 8]
    double cull = 3.5;           // tile weights' culling radius (Mahalanobis; tapered from cull - 1), [2, 8]
    int max_tiles = 256;         // tiles per level per pixel, 4 to 4096 (a tile is one bilinear lookup)
    double direct_below = 1;     // the element path below this minor sd (texels), blended up to twice it, [0.125, 64]
    double blend = 0.25;         // the fraction of an octave over which two levels blend, (0, 1]
    // Called after each level-0 tile is binned (tiles done, tiles in all).
    std::function<void(int done, int total)> progress;
};

// Where the copies of the example go (XTXW24 Sec. 6.1-6.2, Eq. 8-9).
template <class real>
struct ndf_placement {
    using kernels = detail::glsl::kernels<real>;
    using mat2 = glm::mat<2, 2, real, glm::defaultp>;
    using vec2 = vec2_t<real>;
    typename kernels::glint_ndf_placement k{};

    // The example repeated without gaps, every copy mapped by A (example texels -> surface texels:
    // any invertible matrix, rotation, scale, shear or mirror), example texel (0, 0) at `origin`.
    static ndf_placement tiled(const mat2& a = mat2(real(1)), const vec2& origin = vec2(0)) {
        ndf_placement p;
        p.k.kind = kernels::GLINT_NDF_TILED;
        p.k.a = check_matrix(a, "tiled");
        p.k.origin = origin;
        p.k.seed = 0u, p.k.cell = real(1), p.k.rotation = vec2(0), p.k.scale = vec2(1), p.k.flip = real(0), p.k.max_cells = 1;
        if (!(std::isfinite(origin.x) && std::isfinite(origin.y))) throw error("glint::ndf_placement::tiled: the origin is not finite");
        return p;
    }

    // One copy per cell of side `cell` surface texels, anchored in the cell's central half, rotated
    // by an angle uniform in `rotation`, scaled by a factor uniform in `scale`, mirrored with
    // probability `flip`, offset uniformly into the example, after the base map A; every point
    // belongs to the copy with the nearest anchor. All drawn from a hash of (cell, seed).
    static ndf_placement stochastic(real cell, std::uint32_t seed, const vec2& rotation = vec2(0, real(6.283185307179586)),
                                    const vec2& scale = vec2(1), real flip = real(0.5), const mat2& a = mat2(real(1)), int max_cells = 8) {
        const std::string what = "glint::ndf_placement::stochastic: ";
        ndf_placement p;
        p.k.kind = kernels::GLINT_NDF_STOCHASTIC;
        p.k.a = check_matrix(a, "stochastic");
        p.k.origin = vec2(0);
        if (!(cell >= real(1) && cell <= real(1e6))) throw error(what + "cell = " + std::to_string(cell) + " is outside [1, 1e6] texels");
        if (!(std::isfinite(rotation.x) && std::isfinite(rotation.y))) throw error(what + "the rotation range is not finite");
        if (!(scale.x > real(0) && scale.x <= scale.y && scale.y <= real(1e3)))
            throw error(what + "scale range [" + std::to_string(scale.x) + ", " + std::to_string(scale.y) + "] must satisfy 0 < min <= max <= 1000");
        if (!(flip >= real(0) && flip <= real(1))) throw error(what + "flip = " + std::to_string(flip) + " is outside [0, 1]");
        if (max_cells < 2 || max_cells > 32) throw error(what + "max_cells = " + std::to_string(max_cells) + " is outside [2, 32]");
        p.k.seed = seed, p.k.cell = cell, p.k.rotation = rotation, p.k.scale = scale, p.k.flip = flip, p.k.max_cells = max_cells;
        return p;
    }

    // The cell that owns surface point x (stochastic), as the kernels decide it.
    glm::ivec2 owner(const vec2& x) const { return kernels::glint_ndf_owner(k, x); }

private:
    static vec4_t<real> check_matrix(const mat2& a, const char* who) {
        const real det = a[0][0] * a[1][1] - a[1][0] * a[0][1];
        if (!(std::isfinite(a[0][0]) && std::isfinite(a[0][1]) && std::isfinite(a[1][0]) && std::isfinite(a[1][1])))
            throw error(std::string("glint::ndf_placement::") + who + ": the matrix is not finite");
        const real scale = std::max({std::fabs(a[0][0]), std::fabs(a[0][1]), std::fabs(a[1][0]), std::fabs(a[1][1])});
        if (!(std::fabs(det) > real(1e-6) * scale * scale))
            throw error(std::string("glint::ndf_placement::") + who + ": the matrix is singular (det = " + std::to_string(det) + ")");
        return vec4_t<real>(a[0][0], a[0][1], a[1][0], a[1][1]);
    }
};

template <class real>
class ndf_map {
public:
    using kernels = detail::glsl::kernels<real>;
    using params = typename kernels::glint_ndf_map_params;
    using placement = ndf_placement<real>;
    using vec2 = vec2_t<real>;
    using vec3 = vec3_t<real>;
    using vec4 = vec4_t<real>;

    static ndf_map build(const normal_map& example, const ndf_map_params& mp) {
        const auto start = std::chrono::steady_clock::now();
        const std::string what = "glint::ndf_map::build: ";
        const int n = example.width();
        if (n != example.height()) throw error(what + "the example is " + std::to_string(n) + " x " + std::to_string(example.height()) + " (square only)");
        if (n < 4 || n > 256 || (n & (n - 1)) != 0) throw error(what + "example size " + std::to_string(n) + " is not a power of two in [4, 256]");
        if (example.wrap() != wrap_mode::periodic) throw error(what + "the example must be periodic (wrap_mode::periodic)");
        if (mp.resolution < 8 || mp.resolution > 1024) throw error(what + "resolution = " + std::to_string(mp.resolution) + " is outside [8, 1024]");
        if (!(mp.tau > 0 && mp.tau <= 8)) throw error(what + "tau = " + std::to_string(mp.tau) + " is outside (0, 8]");
        if (!(mp.cull >= 2 && mp.cull <= 8)) throw error(what + "cull = " + std::to_string(mp.cull) + " is outside [2, 8]");
        if (mp.max_tiles < 4 || mp.max_tiles > 4096) throw error(what + "max_tiles = " + std::to_string(mp.max_tiles) + " is outside [4, 4096]");
        if (!(mp.direct_below >= 0.125 && mp.direct_below <= 64))
            throw error(what + "direct_below = " + std::to_string(mp.direct_below) + " is outside [0.125, 64]");
        if (!(mp.blend > 0 && mp.blend <= 1)) throw error(what + "blend = " + std::to_string(mp.blend) + " is outside (0, 1]");
        if (mp.supersample < 0 || mp.supersample > 64) throw error(what + "supersample = " + std::to_string(mp.supersample) + " is outside [0, 64]");
        int levels = 0;
        while ((1 << levels) < n) ++levels;
        const long layers = (static_cast<long>(n) * n - 1) / 3;
        const long bins = static_cast<long>(mp.resolution) * mp.resolution;
        if (layers * bins > (1L << 28))
            throw error(what + std::to_string(layers) + " tiles of " + std::to_string(mp.resolution) + "^2 bins exceed 2^28 bins (4 GiB): lower the resolution");
        gaussian_params<double> gd;
        gd.sigma_r = mp.sigma_r, gd.elements_per_texel = mp.elements_per_texel, gd.hierarchy = pndf_hierarchy::none;
        gaussian_params<real> gr;
        gr.sigma_r = static_cast<real>(mp.sigma_r), gr.elements_per_texel = mp.elements_per_texel, gr.hierarchy = pndf_hierarchy::none;
        gr.direct_max_side = 64;
        // gaussian_pndf checks sigma_r and elements_per_texel (and the normals).
        const auto lattice = gaussian_pndf<double>::build(example, gd);
        ndf_map m;
        m.elements_ = gaussian_pndf<real>::build(example, gr);
        m.n_ = n, m.levels_ = levels, m.res_ = mp.resolution;
        m.bin_windows(lattice, mp);
        m.bin_level0(lattice, mp);
        m.fill_levels();
        m.fill_running_masses();
        params& k = m.k_;
        k.n = n, k.levels = levels, k.res = mp.resolution, k.max_tiles = mp.max_tiles;
        k.s_min = vec2(static_cast<real>(m.s_min_.x), static_cast<real>(m.s_min_.y));
        k.s_bin = static_cast<real>(m.s_bin_);
        k.tau = static_cast<real>(mp.tau), k.cull = static_cast<real>(mp.cull), k.direct_below = static_cast<real>(mp.direct_below);
        k.blend = static_cast<real>(mp.blend);
        k.el = m.elements_.kernel_params();
        m.build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return m;
    }

    // D_P(s) of the footprint over the layout `pl` (XTXW24 Sec. 6.3), a density over the disk.
    real eval(const placement& pl, const texel_footprint<real>& fp, const vec2& s) const {
        return kernels::glint_ndf_pndf(element_data().data(), images_.data(), k_, pl.k, fp.center, covariance(fp), s);
    }
    // D_P(s) with XTXW24's tiles as published: each tile's NDF alone (Eq. 7), without glint's
    // first-order moments (for comparison; sample() draws from this density).
    real eval_zero_order(const placement& pl, const texel_footprint<real>& fp, const vec2& s) const {
        return kernels::glint_ndf_pndf_mode(element_data().data(), images_.data(), k_, pl.k, fp.center, covariance(fp), s, kernels::GLINT_NDF_DENSITY);
    }
    // The element path for every footprint (Eq. 6 summed over each copy's owned elements, no
    // lattice cap): the layout's P-NDF the map approximates.
    real eval_direct(const placement& pl, const texel_footprint<real>& fp, const vec2& s) const {
        const params k = direct_params();
        return kernels::glint_ndf_pndf(element_data().data(), images_.data(), k, pl.k, fp.center, covariance(fp), s);
    }
    // The integral of eval over s (before the disk's edge): 1 up to the element path's lattice ripple.
    real mass(const placement& pl, const texel_footprint<real>& fp) const {
        return kernels::glint_ndf_mass(element_data().data(), images_.data(), k_, pl.k, fp.center, covariance(fp));
    }
    // The density of sample()'s s: the zero-order P-NDF (tiles' B alone) over mass; positive
    // wherever eval is.
    real pdf(const placement& pl, const texel_footprint<real>& fp, const vec2& s) const { return pdf(pl, fp, s, mass(pl, fp)); }
    // The same with mass(pl, fp) given (callers evaluating many s for one footprint).
    real pdf(const placement& pl, const texel_footprint<real>& fp, const vec2& s, real m) const {
        if (!(m > 0)) return real(0);
        return kernels::glint_ndf_pndf_mode(element_data().data(), images_.data(), k_, pl.k, fp.center, covariance(fp), s, kernels::GLINT_NDF_DENSITY) / m;
    }
    // A half vector drawn from pdf (its exact density, pdf_s).
    pndf_sample<real> sample(const placement& pl, const texel_footprint<real>& fp, real u0, real u1, real u2) const {
        const auto d = kernels::glint_ndf_sample(element_data().data(), images_.data(), k_, pl.k, fp.center, covariance(fp), u0, u1, u2);
        pndf_sample<real> r;
        if (!d.valid) return r;
        r.s = d.s;
        r.h = vec3(d.s.x, d.s.y, std::sqrt(std::max(real(0), real(1) - d.s.x * d.s.x - d.s.y * d.s.y)));
        r.pdf_s = d.pdf_s;
        r.pdf_h = d.pdf_s * r.h.z;
        r.valid = true;
        return r;
    }
    // XTXW24 Eq. 1 with eval's D_P, Smith G2 (Beckmann at alpha_g()) and the conductor Fresnel.
    real brdf(const placement& pl, const texel_footprint<real>& fp, const vec3& wi, const vec3& wo, real eta, real k) const {
        if (!(wi.z > 0) || !(wo.z > 0)) return real(0);
        const vec3 h = glm::normalize(wi + wo);
        if (!(h.z > 0)) return real(0);
        return kernels::glint_pndf_brdf(eval(pl, fp, vec2(h.x, h.y)), wi, wo, static_cast<int>(ndf::beckmann), vec2(alpha_g()), eta, k);
    }
    // XTXW24 Eq. 10: this map as the base (a conductor eta_b, k_b) under a clear coat of index eta_c
    // whose microstructure is `coat` placed by coat_pl.
    real coated_brdf(const placement& pl, const ndf_map& coat, const placement& coat_pl, const texel_footprint<real>& fp, const vec3& wi, const vec3& wo,
                     real eta_b, real k_b, real eta_c) const {
        if (!(wi.z > 0) || !(wo.z > 0)) return real(0);
        const vec3 h = glm::normalize(wi + wo);
        if (!(h.z > 0)) return real(0);
        const vec2 s(h.x, h.y);
        return kernels::glint_ndf_coated_brdf(eval(pl, fp, s), coat.eval(coat_pl, fp, s), wi, wo, vec2(alpha_g()), vec2(coat.alpha_g()), eta_b, k_b, eta_c);
    }

    // What an evaluation reads: tiles (each a bilinear lookup of 4 texels), elements and copies.
    struct cost {
        int tiles = 0, elements = 0, copies = 0;
        int fetches() const { return 4 * tiles + 2 * elements; }
    };
    cost evaluation_cost(const placement& pl, const texel_footprint<real>& fp) const {
        const auto plan = kernels::glint_ndf_make_plan(k_, pl.k, fp.center, covariance(fp));
        const auto a = kernels::glint_ndf_all_parts(element_data().data(), images_.data(), k_, pl.k, plan, vec2(0), kernels::GLINT_NDF_EVAL,
                                                    -1, kernels::glint_ndf_empty_parts());
        cost c;
        c.tiles = a.fine.tiles + a.coarse.tiles + a.whole.tiles;
        // A tiled layout's top level is one lookup, not counted by its sums.
        if (pl.k.kind == kernels::GLINT_NDF_TILED && plan.direct < 1) c.tiles += (plan.level == levels_ - 1) + (plan.alpha > 0 && plan.level + 1 == levels_ - 1);
        c.elements = a.direct.tiles;
        c.copies = pl.k.kind == kernels::GLINT_NDF_TILED ? 1 : (plan.cells.z - plan.cells.x + 1) * (plan.cells.w - plan.cells.y + 1);
        return c;
    }

    // The stored images: layer after layer (level 0 first, tiles row-major), res x res bins of four
    // floats (B, B_x, B_y, running mass; kernels/ndf_map.glsl), row-major: upload as RGBA32F layers.
    const std::vector<float>& images() const { return images_; }
    // Channel c of bin (x, y) of tile (tx, ty) at level l.
    float bin(int level, int tx, int ty, int x, int y, int c = 0) const {
        return images_[4 * (static_cast<std::size_t>(layer(level, tx, ty)) * bins() + static_cast<std::size_t>(x + res_ * y)) + static_cast<std::size_t>(c)];
    }
    int layer(int level, int tx, int ty) const { return kernels::glint_ndf_level_first(n_, level) + tx + (n_ >> (level + 1)) * ty; }
    int layers() const { return (n_ * n_ - 1) / 3; }
    int example_size() const { return n_; }
    int levels() const { return levels_; }
    int resolution() const { return res_; }
    std::size_t bins() const { return static_cast<std::size_t>(res_) * static_cast<std::size_t>(res_); }
    // The window: bins start at s_min, each s_bin wide.
    glm::dvec2 window_min() const { return s_min_; }
    double bin_width() const { return s_bin_; }
    const params& kernel_params() const { return k_; }
    const gaussian_pndf<real>& elements() const { return elements_; }
    const std::vector<vec4>& element_data() const { return elements_.element_data(); }
    real alpha_g() const { return elements_.alpha_g(); }
    int supersample() const { return supersample_; }
    double build_seconds() const { return build_seconds_; }
    // Bytes a renderer holds: the images (with their moments and running sums), and the elements.
    std::size_t image_bytes() const { return images_.size() * sizeof(float); }
    std::size_t element_bytes() const { return element_data().size() * sizeof(vec4); }

private:
    static vec4 covariance(const texel_footprint<real>& fp) {
        const auto& c = fp.covariance;
        const double det = static_cast<double>(c[0][0]) * static_cast<double>(c[1][1]) - static_cast<double>(c[1][0]) * static_cast<double>(c[1][0]);
        return vec4(c[0][0], c[1][0], c[1][1], static_cast<real>(std::max(det, 0.0)));
    }
    params direct_params() const {
        params k = k_;
        k.direct_below = real(1e30);
        k.el.max_side = 1 << 20;
        return k;
    }

    // The window around every marginal lobe to 4.5 sd (a square), or [-1, 1]^2.
    void bin_windows(const gaussian_pndf<double>& lattice, const ndf_map_params& mp) {
        glm::dvec2 lo(1e300), hi(-1e300);
        const auto& d = lattice.element_data();
        const double sh2 = lattice.sigma_h() * lattice.sigma_h(), sr2 = mp.sigma_r * mp.sigma_r;
        for (std::size_t e = 0; e < d.size() / 2; ++e) {
            const glm::dvec4 us = d[2 * e], j = d[2 * e + 1];
            const double cxx = sr2 + sh2 * (j.x * j.x + j.z * j.z), cyy = sr2 + sh2 * (j.y * j.y + j.w * j.w);
            lo = glm::min(lo, glm::dvec2(us.z - 4.5 * std::sqrt(cxx), us.w - 4.5 * std::sqrt(cyy)));
            hi = glm::max(hi, glm::dvec2(us.z + 4.5 * std::sqrt(cxx), us.w + 4.5 * std::sqrt(cyy)));
        }
        double half = 0.5 * std::max(hi.x - lo.x, hi.y - lo.y);
        glm::dvec2 centre = 0.5 * (lo + hi);
        if (!mp.fit_window || half >= 1) half = 1, centre = glm::dvec2(0);
        s_bin_ = 2 * half / res_;
        s_min_ = centre - glm::dvec2(half);
    }

    // Level 0: each tile's mean marginal lobe and its first moments in position, binned by the
    // midpoint rule (header).
    void bin_level0(const gaussian_pndf<double>& lattice, const ndf_map_params& mp) {
        const int r = mp.elements_per_texel, side = n_ * r, m0 = n_ / 2;
        supersample_ = mp.supersample > 0 ? mp.supersample : std::clamp(static_cast<int>(std::ceil(2 * s_bin_ / mp.sigma_r)), 1, 32);
        const int k = supersample_;
        images_.assign(4 * static_cast<std::size_t>(layers()) * bins(), 0.0f);
        const auto& d = lattice.element_data();
        const double sh2 = lattice.sigma_h() * lattice.sigma_h(), sr2 = mp.sigma_r * mp.sigma_r;
        const double per_element = 1.0 / (4.0 * r * r);  // a_i / t^2 at level 0
        std::vector<glm::dvec3> acc(bins());
        for (int ty = 0; ty < m0; ++ty)
            for (int tx = 0; tx < m0; ++tx) {
                std::fill(acc.begin(), acc.end(), glm::dvec3(0));
                const glm::dvec2 centre(2.0 * tx + 1, 2.0 * ty + 1);
                for (int j = 2 * r * ty; j < 2 * r * (ty + 1); ++j)
                    for (int i = 2 * r * tx; i < 2 * r * (tx + 1); ++i) {
                        const std::size_t e = static_cast<std::size_t>(i + side * j);
                        const glm::dvec4 us = d[2 * e], jc = d[2 * e + 1];
                        // The moments' weights (u_i - c_T) / t, t = 2 texels.
                        const glm::dvec3 moment(1.0, 0.5 * (us.x - centre.x), 0.5 * (us.y - centre.y));
                        const double cxx = sr2 + sh2 * (jc.x * jc.x + jc.z * jc.z), cyy = sr2 + sh2 * (jc.y * jc.y + jc.w * jc.w);
                        const double cxy = sh2 * (jc.x * jc.y + jc.z * jc.w);
                        const double det = cxx * cyy - cxy * cxy;
                        const double ixx = cyy / det, ixy = -cxy / det, iyy = cxx / det;
                        const double norm = per_element / (2 * 3.14159265358979323846 * std::sqrt(det)) / (k * k);
                        const auto range = [&](double c, double sd, double lo) {
                            const int a = static_cast<int>(std::floor((c - 4.5 * sd - lo) / s_bin_)), b = static_cast<int>(std::floor((c + 4.5 * sd - lo) / s_bin_));
                            return glm::ivec2(std::max(a, 0), std::min(b, res_ - 1));
                        };
                        const glm::ivec2 bx = range(us.z, std::sqrt(cxx), s_min_.x), by = range(us.w, std::sqrt(cyy), s_min_.y);
                        for (int y = by.x; y <= by.y; ++y)
                            for (int b = 0; b < k; ++b) {
                                const double dy = s_min_.y + (y + (b + 0.5) / k) * s_bin_ - us.w;
                                for (int x = bx.x; x <= bx.y; ++x) {
                                    double sum = 0;
                                    for (int a = 0; a < k; ++a) {
                                        const double dx = s_min_.x + (x + (a + 0.5) / k) * s_bin_ - us.z;
                                        sum += std::exp(-0.5 * (ixx * dx * dx + 2 * ixy * dx * dy + iyy * dy * dy));
                                    }
                                    acc[static_cast<std::size_t>(x + res_ * y)] += (norm * sum) * moment;
                                }
                            }
                    }
                float* out = images_.data() + 4 * static_cast<std::size_t>(layer(0, tx, ty)) * bins();
                for (std::size_t b = 0; b < bins(); ++b)
                    for (int c = 0; c < 3; ++c) out[4 * b + static_cast<std::size_t>(c)] = static_cast<float>(acc[b][c]);
                if (mp.progress) mp.progress(tx + m0 * ty + 1, m0 * m0);
            }
    }

    // Levels above 0 from the four stored children (summed in double, rounded once): B is their
    // mean; a child's moments are half the parent's in the parent's units, shifted by its offset
    // from the parent's centre, +-1/4 of the parent's side: B_x = mean(B_x,q / 2 +- B_q / 4).
    void fill_levels() {
        for (int l = 1; l < levels_; ++l) {
            const int m = n_ >> (l + 1);
            for (int ty = 0; ty < m; ++ty)
                for (int tx = 0; tx < m; ++tx) {
                    float* out = images_.data() + 4 * static_cast<std::size_t>(layer(l, tx, ty)) * bins();
                    const float* c[4];
                    for (int q = 0; q < 4; ++q) c[q] = images_.data() + 4 * static_cast<std::size_t>(layer(l - 1, 2 * tx + (q & 1), 2 * ty + (q >> 1))) * bins();
                    for (std::size_t b = 0; b < bins(); ++b) {
                        double v = 0, vx = 0, vy = 0;
                        for (int q = 0; q < 4; ++q) {
                            const double cb = static_cast<double>(c[q][4 * b]);
                            v += cb;
                            vx += 0.5 * static_cast<double>(c[q][4 * b + 1]) + ((q & 1) ? 0.25 : -0.25) * cb;
                            vy += 0.5 * static_cast<double>(c[q][4 * b + 2]) + ((q >> 1) ? 0.25 : -0.25) * cb;
                        }
                        out[4 * b] = static_cast<float>(0.25 * v), out[4 * b + 1] = static_cast<float>(0.25 * vx), out[4 * b + 2] = static_cast<float>(0.25 * vy);
                    }
                }
        }
    }

    // Each layer's running sum of B x bin area (row-major), in double, rounded once.
    void fill_running_masses() {
        const double area = s_bin_ * s_bin_;
        for (std::size_t l = 0; l < static_cast<std::size_t>(layers()); ++l) {
            double run = 0;
            float* v = images_.data() + 4 * l * bins();
            for (std::size_t b = 0; b < bins(); ++b) {
                run += static_cast<double>(v[4 * b]) * area;
                v[4 * b + 3] = static_cast<float>(run);
            }
        }
    }

    gaussian_pndf<real> elements_;
    params k_{};
    int n_ = 0, levels_ = 0, res_ = 0, supersample_ = 0;
    glm::dvec2 s_min_{0};
    double s_bin_ = 0, build_seconds_ = 0;
    std::vector<float> images_;
};

}  // namespace glint
