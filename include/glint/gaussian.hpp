// Normal-mapped microstructure as YHMR16's 4D Gaussian elements, and the P-NDF of a pixel
// footprint (XTXW24 Eq. 2-6, kernels/gaussian.glsl) with a hierarchy that makes it fast, the
// BRDF (XTXW24 Eq. 1), and importance sampling of half vectors.
//
//   glint::normal_map m = glint::make_normal_map(p);                      // or glint::io::read_normal_map
//   glint::gaussian_params<float> g;  g.sigma_r = 0.005f;                 // intrinsic roughness
//   auto pndf = glint::gaussian_pndf<float>::build(m, g);                 // host side, may throw
//   auto fp = glint::footprint_from_uv_derivatives(uv, duvdx, duvdy, texels_per_uv);   // per pixel
//   float d = pndf.eval(fp, glm::vec2(h.x, h.y));                         // density over the disk
//   float f = pndf.brdf(fp, wi, wo, eta, k);                              // Eq. 1
//
// Elements (YHMR16 Sec. 4; XTXW24 Eq. 3-5). Seeds on a lattice of spacing h = 1 / r texels
// (r = elements_per_texel, 1, 2 or 4 per texel side) at ((i + 1/2) h, (j + 1/2) h); each stores the
// periodic bicubic (Catmull-Rom) normal's xy part s_i and its analytic Jacobian J_i = ds/du
// (normal_map.hpp), weight a_i = h^2, and the seed Gaussian's sd sigma_h = h / sqrt(8 ln 2)
// (0.4247 h: its full width at half maximum is h; YHMR16's choice; Yan's released code uses
// 0.433 h). sigma_r is the intrinsic roughness of every lobe.
//
// P-NDF. D_P(s) = sum_i I_i(s), I_i the closed form of Eq. 6 (kernels/gaussian.glsl gives it and
// its float-robust evaluation). D_P is a density over the projected disk |s| < 1 of normals
// (0 outside); it integrates to sum_i w_i, the footprint's element weight, which is 1 up to the
// lattice's Poisson-summation ripple (2 exp(-2 pi^2 (sigma_h^2 + lambda_min) / h^2) per axis: 5.7%
// for a point footprint at r = 1, 4e-4 at sigma_P = h / 2, below 1e-9 for sigma_P >= h).
//
// Culling (stated bounds). An element counts where its footprint offset's Mahalanobis radius is
// at most cull_u (default 3.5), with its weight tapered smoothly to 0 between cull_u - 1 and cull_u
// (so D_P is continuous as the footprint moves: YHMR16's hard cut at 3 makes it jump by about 2%;
// at 3.5 the taper's error matches that cut's, about 1% in L1, docs/microstructure.md), and
// where s lies within cull_s (default 4) of its lobe in C's Mahalanobis metric (exp(-8) = 3.4e-4
// of each lobe's mass outside, a jump of that size in s). The kept parts are divided by the kept
// masses (kernels/gaussian.glsl: 0.9548 for the taper at cull_u = 3, 0.9878 at 3.5; YHMR16's hard
// cut at 3 keeps 0.989 and loses the rest), so the culled P-NDF keeps the footprint's mass; its error is only the
// culled elements' different normals (measured: docs/microstructure.md). The hierarchy never changes which elements
// count: it only skips those that provably fail these tests, using for element i an s-box
// oriented along the left singular vectors v_k of J_i (singular values j_k), with half-widths
//   r_ik = j_k cull_u sigma_h + cull_s sqrt(sigma_r^2 + j_k^2 sigma_h^2),
// which bound the lobe mean's shift along v_k (J_i R diag(sigma_h^2 / kappa) e has component at most
// j_k times that vector's length, itself at most cull_u sigma_h inside the ellipse since kappa >=
// sigma_h^2) plus the cull_s ellipse of C = sigma_r^2 I + B B^T along v_k (B B^T <= sigma_h^2 J J^T).
// A groove wall's rank-1 J gives a box as thin as 2 cull_s sigma_r across the groove: an
// axis-aligned box would be as wide as it is long.
//
// Hierarchy (host side). Normal-space grids over [-1, 1]^2, the finest with cells about four median
// s-radii on a side (a power of two, 8 to 256 per side), each coarser one half as many per side,
// down to one cell. Each element is listed, at the finest level where its s-box overlaps at most 8
// cells, in every cell it overlaps there, as a copy (element and s-box, so that a query reads its
// lists in order); each cell's list is sorted along a Morton curve of the lattice positions, with a
// bounding-box tree over runs of leaf_size = 32 (the position tree). A query visits the cell holding
// s at every level and, for each periodic image of the map the footprint's culling box touches, the
// nodes whose boxes it overlaps, in memory order: its cost follows the footprint's elements whose
// normals are near s, not all of them: the elements that contribute, plus those whose s-boxes hold
// s without their lobes reaching it (on the flakes map of docs/microstructure.md at footprint sd
// 64: 12 tested and 2.6 evaluated per one that contributes; term_count counts those). That count
// still grows with the footprint's area at a fixed s (flakes: 123, 3620 and 243638 terms at sd 8, 64
// and 512, at 90 to 115 ns per term): an exact sum cannot do better, and only prefiltered node NDFs
// make the cost sublinear (below). (Summing nodes of equal lobes as one
// moment-matched term saved nothing measurable there: 91 to 92% of the terms from sd 64 on come
// from the flakes' edges, whose lobes differ.) Where the lists would cost more than the footprint's
// lattice (hierarchy_pays: maps whose lobes are as wide as their normals' spread), eval sums the
// lattice directly instead; such maps can leave the hierarchy out (gaussian_params::hierarchy).
// Footprints so wide that the periodic images blur into the map's average (large_footprint below:
// error below 4e-8) use the continuum limit of the periodic sum, sum_i marginal_i(s) / map area,
// which is exact as the footprint grows (the lobe's mean shift, averaged over the images, adds
// sigma_h^4 J kappa^-1 J^T to C, which makes it sigma_h^2 J J^T).
//
// Prefiltered nodes (gaussian_params::prefilter_spread = tau > 0; off by default, since the
// images cost memory and build time: docs/microstructure.md). Under a wide footprint the weight
// w(u) = area norm exp(-m / 2) window(m) of glint_pndf_element_weight changes little across a
// position-tree node, and each lobe is close to its footprint -> infinity limit L_i (the marginal,
// cut at cull_s and divided by its kept mass as in the element term). A node whose elements' mean
// squared distance from their mean (spread2) is at most tau^2 kappa_min then adds
//   w(c(s)) sum_i L_i(s),  c(s) = mean + sum_i L_i(s) (u_i - mean) / sum_i L_i(s),
// read from the node's image (both sums on a grid over its cell in s, 2 points per sigma_r,
// bilinear, 16 bits each): c(s) is the lobes' own mean position at s, so the linear term of w
// cancels, and the error is at most (1/2) sup|Hess w| sum_i L_i(s) |u_i - c(s)|^2, which
// integrates over s to at most (1/2) sup|Hess w| N spread2. In the footprint's frame |Hess w| <=
// (2 |phi'| + 4 m |phi''|) / kappa_min with phi(m) = exp(-m / 2) window(m), at most 1.21 / kappa_min
// of w's peak (2 exp(-1/2), at m = 1), so the accepted nodes err by at most 0.61 tau^2 of their
// elements' peak weight: about 3.8 tau^2 of the footprint's mass when they fill the cull_u = 3.5
// ellipse (0.95% at tau 0.5). The grid's interpolation and the lobes' footprint shift (J_i
// sigma_h^2 kappa^-1 e, of order sigma_h / sigma_P of a lobe's width) add to it; measured on the
// flakes map of docs/microstructure.md: 0.25% to 0.9% in L1 at tau 0.5 for footprints of sd 64 to
// 512 (with the node's mean for c(s), without the moments, up to 4.7%). Nodes take the images once the footprint is wide
// enough, so D_P steps by up to that error as a footprint grows past a node's threshold. Only
// eval and brdf use them; sample and pdf stay exact (pdf is the sampler's density).
//
// Domains. sigma_r in [1e-4, 1] (the kernels clamp it below at 1e-5); footprint covariances
// finite and positive semi-definite (0 is a point footprint); s finite. Per-pixel calls never
// allocate or throw and return 0 for |s| >= 1, non-finite s, or h below the horizon.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "glint/core/error.hpp"
#include "glint/core/hash.hpp"
#include "glint/microfacet.hpp"
#include "glint/normal_map.hpp"

namespace glint {

// A Gaussian footprint N(u; center, covariance) in texels.
template <class real>
struct texel_footprint {
    vec2_t<real> center{0};
    glm::mat<2, 2, real, glm::defaultp> covariance{0};
};

// The footprint of a pixel with uv derivatives duvdx, duvdy on a map of texels_per_uv texels per
// uv unit: Heckbert's Gaussian, covariance sigma_pix^2 T^2 (du/dx du/dx^T + du/dy du/dy^T), where
// sigma_pix is the pixel filter's sd in pixels (0.5, Yan's released code; XTXW24 Sec. 6.3).
template <class real>
texel_footprint<real> footprint_from_uv_derivatives(const vec2_t<real>& uv, const vec2_t<real>& duvdx, const vec2_t<real>& duvdy,
                                                    real texels_per_uv, real sigma_pix = real(0.5)) {
    const vec2_t<real> a = duvdx * (texels_per_uv * sigma_pix), b = duvdy * (texels_per_uv * sigma_pix);
    texel_footprint<real> f;
    f.center = uv * texels_per_uv;
    f.covariance = glm::mat<2, 2, real, glm::defaultp>(a.x * a.x + b.x * b.x, a.x * a.y + b.x * b.y, a.x * a.y + b.x * b.y, a.y * a.y + b.y * b.y);
    return f;
}

// Whether build() makes the hierarchy (eval then uses it per query where it pays), or not (eval
// sums the lattice directly: 48 bytes per element instead of 200 to 350, for maps rough at the
// texel scale, where it never pays; docs/microstructure.md). Choosing by sampling s at the
// elements' own normals was tried and dropped: on a mostly flat map with grooves it found no
// gain, and its renders were 50x (point light) to 260x (environment) slower without it.
enum class pndf_hierarchy { build, none };

template <class real>
struct gaussian_params {
    real sigma_r = real(0.005);  // intrinsic roughness, [1e-4, 1]
    int elements_per_texel = 1;  // seeds per texel side: 1, 2 or 4
    real cull_u = real(3.5);     // footprint culling radius (Mahalanobis; tapered from cull_u - 1), [2, 8]
    real cull_s = real(4);       // lobe culling radius (Mahalanobis), [1, 8]
    int direct_max_side = 128;   // eval_direct and GLSL: at most this many lattice steps each side
    pndf_hierarchy hierarchy = pndf_hierarchy::build;
    // Prefiltered nodes (header comment): 0 keeps eval exact; tau > 0 builds node NDF images and
    // lets eval and brdf sum a position-tree node as one image lookup where its elements' rms
    // distance from their mean is at most tau footprint sds (the minor axis). [0, 0.5]; needs the
    // hierarchy.
    real prefilter_spread = 0;
};

// A half vector drawn from the P-NDF: its projected-disk point s, h = (s, sqrt(1 - |s|^2)), and
// the densities of s (per unit disk area) and of h (per solid angle, pdf_s cos theta_h). valid is
// false (and the densities 0) when the draw left the disk or the footprint holds no element.
template <class real>
struct pndf_sample {
    vec2_t<real> s{0};
    vec3_t<real> h{0, 0, 1};
    real pdf_s = 0, pdf_h = 0;
    bool valid = false;
};

template <class real>
class gaussian_pndf {
public:
    using kernels = detail::glsl::kernels<real>;
    using element = typename kernels::glint_gaussian_element;
    using frame = typename kernels::glint_pndf_frame;
    using params = typename kernels::glint_pndf_params;
    using vec2 = vec2_t<real>;
    using vec4 = glm::vec<4, real, glm::defaultp>;

    static gaussian_pndf build(const normal_map& map, const gaussian_params<real>& g) {
        const std::string what = "glint::gaussian_pndf::build: ";
        if (map.width() <= 0 || map.height() <= 0) throw error(what + "the normal map is empty");
        if (g.elements_per_texel != 1 && g.elements_per_texel != 2 && g.elements_per_texel != 4)
            throw error(what + "elements_per_texel = " + std::to_string(g.elements_per_texel) + " (1, 2 or 4)");
        if (!(g.sigma_r >= real(1e-4) && g.sigma_r <= real(1))) throw error(what + "sigma_r = " + std::to_string(g.sigma_r) + " is outside [1e-4, 1]");
        if (!(g.cull_u >= 2 && g.cull_u <= 8)) throw error(what + "cull_u = " + std::to_string(g.cull_u) + " is outside [2, 8]");
        if (!(g.cull_s >= 1 && g.cull_s <= 8)) throw error(what + "cull_s = " + std::to_string(g.cull_s) + " is outside [1, 8]");
        if (g.direct_max_side < 1) throw error(what + "direct_max_side = " + std::to_string(g.direct_max_side) + " is below 1");
        if (!(g.prefilter_spread >= 0 && g.prefilter_spread <= real(0.5)))
            throw error(what + "prefilter_spread = " + std::to_string(g.prefilter_spread) + " is outside [0, 0.5]");
        if (g.prefilter_spread > 0 && g.hierarchy == pndf_hierarchy::none)
            throw error(what + "prefilter_spread = " + std::to_string(g.prefilter_spread) + " needs the hierarchy (gaussian_params::hierarchy = build)");
        const long lw = static_cast<long>(map.width()) * g.elements_per_texel, lh = static_cast<long>(map.height()) * g.elements_per_texel;
        if (lw * lh > (1L << 26)) throw error(what + "more than 2^26 elements (" + std::to_string(lw) + " x " + std::to_string(lh) + ")");
        gaussian_pndf p;
        const real h = real(1) / real(g.elements_per_texel);
        p.k_.sigma_h = h / std::sqrt(real(8) * std::log(real(2)));
        p.k_.sigma_r = g.sigma_r;
        p.k_.spacing = h;
        p.k_.area = h * h;
        p.k_.cull_u = g.cull_u;
        p.k_.cull_s = g.cull_s;
        p.k_.width = static_cast<int>(lw);
        p.k_.height = static_cast<int>(lh);
        p.k_.periodic = map.wrap() == wrap_mode::periodic ? 1 : 0;
        p.k_.max_side = g.direct_max_side;
        p.period_ = vec2(static_cast<real>(map.width()), static_cast<real>(map.height()));
        const std::size_t n = static_cast<std::size_t>(lw * lh);
        p.data_.resize(2 * n);
        p.bound_.resize(n);
        real slope2 = 0, jmax = 0;
        for (long j = 0; j < lh; ++j)
            for (long i = 0; i < lw; ++i) {
                const double hd = static_cast<double>(h);
                const glm::dvec2 u((static_cast<double>(i) + 0.5) * hd, (static_cast<double>(j) + 0.5) * hd);
                const normal_sample<double> q = map.bicubic(u);
                const std::size_t k = static_cast<std::size_t>(i + lw * j);
                p.data_[2 * k] = vec4(static_cast<real>(u.x), static_cast<real>(u.y), static_cast<real>(q.s.x), static_cast<real>(q.s.y));
                p.data_[2 * k + 1] = vec4(static_cast<real>(q.jacobian[0].x), static_cast<real>(q.jacobian[0].y), static_cast<real>(q.jacobian[1].x),
                                          static_cast<real>(q.jacobian[1].y));
                const double jf = std::sqrt(q.jacobian[0].x * q.jacobian[0].x + q.jacobian[0].y * q.jacobian[0].y + q.jacobian[1].x * q.jacobian[1].x +
                                            q.jacobian[1].y * q.jacobian[1].y);
                jmax = std::max(jmax, static_cast<real>(jf));
                p.bound_[k] = element_sbox(q.jacobian, static_cast<double>(p.k_.sigma_h), static_cast<double>(g.sigma_r), static_cast<double>(g.cull_u),
                                           static_cast<double>(g.cull_s));
                const double z2 = std::max(1e-12, 1 - q.s.x * q.s.x - q.s.y * q.s.y);
                slope2 += static_cast<real>((q.s.x * q.s.x + q.s.y * q.s.y) / z2);
            }
        p.jmax_ = jmax;
        // Smith roughness for G (notes: Beckmann alpha^2 = 2 Var(p) per axis): the mean squared
        // slope |p|^2 over both axes (isotropic: 2 Var per axis), plus the lobes' own 2 sigma_r^2.
        p.alpha_g_ = std::sqrt(std::max(real(1e-8), slope2 / static_cast<real>(n) + real(2) * g.sigma_r * g.sigma_r));
        if (g.hierarchy == pndf_hierarchy::build) p.build_grid();
        p.prefilter_spread_ = g.prefilter_spread;
        if (g.prefilter_spread > 0) p.build_node_ndfs();
        return p;
    }

    // The oriented s-box of an element with Jacobian J (header comment): the axes of J J^T (angle
    // theta of its larger eigenvalue), the radius along each from its singular value; rounded up by
    // 1e-4 relative plus 1e-6, so that the float kernel's own rounding stays inside. Returned as
    // (cos theta, sin theta, r_1, r_2). Shared with lobe_tree.hpp.
    static vec4 element_sbox(const glm::dmat2& jacobian, double sh, double sr, double cu, double cs) {
        const glm::dvec2 j0 = jacobian[0], j1 = jacobian[1];
        const double m11 = j0.x * j0.x + j1.x * j1.x, m22 = j0.y * j0.y + j1.y * j1.y, m12 = j0.x * j0.y + j1.x * j1.y;
        const double root = std::hypot(0.5 * (m11 - m22), m12);
        const double sv1 = std::sqrt(0.5 * (m11 + m22) + root), sv2 = std::sqrt(std::max(0.0, 0.5 * (m11 + m22) - root));
        const auto radius = [&](double sv) { return static_cast<real>((sv * cu * sh + cs * std::sqrt(sr * sr + sv * sv * sh * sh)) * (1 + 1e-4) + 1e-6); };
        // theta = atan2(2 m12, m11 - m22) / 2 by the half-angle formulas (cos 2 theta = (m11 - m22)
        // / (2 root)): no atan2, cos or sin. Isotropic J J^T (root = 0) takes theta = 0.
        const double c2 = root > 0 ? std::clamp(0.5 * (m11 - m22) / root, -1.0, 1.0) : 1.0;
        const double c = std::sqrt(0.5 * (1 + c2)), sn = std::copysign(std::sqrt(0.5 * (1 - c2)), m12);
        return vec4(static_cast<real>(c), static_cast<real>(sn), radius(sv1), radius(sv2));
    }

    // D_P(s) through the hierarchy whatever its cost (eval picks it where it pays); the same
    // elements as eval_direct without its box cap. With prefilter_spread tau > 0 (a map built
    // with node NDF images), nodes within tau footprint sds take their images (tau = 0: exact).
    real eval_hierarchy(const texel_footprint<real>& fp, const vec2& s, real prefilter_spread = 0) const {
        if (!(s.x * s.x + s.y * s.y < real(1))) return real(0);
        const frame f = prepare(fp);
        return hierarchy_sum(f, s, prefilter_spread);
    }

    // D_P(s): the hierarchy (with the prefiltered nodes where the map was built with them and the
    // footprint is wide enough for one), or the direct sum where that is cheaper, or the
    // continuum limit for footprints of many periods.
    real eval(const texel_footprint<real>& fp, const vec2& s) const {
        if (!(s.x * s.x + s.y * s.y < real(1))) return real(0);
        const frame f = prepare(fp);
        if (large_footprint(f)) return continuum_limit(s);
        const bool pays = hierarchy_pays(f, s);
        if (prefilter_applies(f, prefilter_spread_, pays ? min_ndf_spread2_ : median_ndf_spread2_)) return hierarchy_sum(f, s, prefilter_spread_);
        if (!pays) return direct_sum(f, s, sampling_params());
        return hierarchy_sum(f, s);
    }

    // D_P(s) as the GLSL kernel computes it: the lattice points in the culling box, at most
    // direct_max_side steps from the centre on each axis (the kernels' glint_pndf_direct).
    real eval_direct(const texel_footprint<real>& fp, const vec2& s) const {
        return kernels::glint_pndf_direct(data_.data(), prepare(fp), s, k_);
    }

    // The brute-force reference: every element whose spatial weight exceeds exp(-24.5) = 2.3e-11
    // of its peak (a 7-sigma box, no lobe culling, no cap): Eq. 6 summed as it stands.
    real eval_reference(const texel_footprint<real>& fp, const vec2& s) const {
        params k = reference_params();
        return kernels::glint_pndf_direct(data_.data(), prepare(fp, k.cull_u, k.cull_s), s, k);
    }

    // How many elements have a nonzero term in eval_hierarchy's sum at s: the terms any exact
    // evaluation of the culled P-NDF must add (for cost per term; a lattice loop over the box).
    // With `keep`, only the elements for which keep(element) is true (to see where terms come from).
    std::size_t term_count(const texel_footprint<real>& fp, const vec2& s) const {
        return term_count(fp, s, [](const element&) { return true; });
    }
    template <class keep_t>
    std::size_t term_count(const texel_footprint<real>& fp, const vec2& s, keep_t&& keep) const {
        if (!(s.x * s.x + s.y * s.y < real(1))) return 0;
        const frame f = prepare(fp);
        const params k = sampling_params();
        std::size_t n = 0;
        for_each_in_box(f, k, [&](std::size_t, const element& el, const vec2& u) {
            n += keep(el) && kernels::glint_pndf_element(el, u, f, s, k) > real(0);
        });
        return n;
    }

    // The footprint's element weight sum_i w_i (the integral of D_P over s, before lobe culling
    // and the disk's edge), over the same elements as eval_reference.
    real mass(const texel_footprint<real>& fp) const {
        const params k = reference_params();
        return weight_sum(prepare(fp, k.cull_u, k.cull_s), k);
    }

    // A half vector from the P-NDF: an element i with probability w_i / W among those inside the
    // cull_u ellipse (two passes over the box, no allocation), then s from its lobe N(mean_i, C_i)
    // truncated at the cull_s radius. The density of s is exactly pdf(fp, s).
    pndf_sample<real> sample(const texel_footprint<real>& fp, real u0, real u1, real u2) const {
        pndf_sample<real> r;
        const frame f = prepare(fp);
        params k = sampling_params();
        const real total = sampling_weight(fp);
        if (!(total > real(0))) return r;
        const real target = u0 * total;
        real acc = 0;
        bool found = false;
        element chosen{};
        vec2 chosen_u(0);
        for_each_in_box(f, k, [&](std::size_t, const element& el, const vec2& u) {
            const real w = kernels::glint_pndf_element_weight(u, f, k);
            if (w > 0 && !found) {
                chosen = el, chosen_u = u;
                acc += w;
                found = acc > target;
            }
        });
        r.s = draw_from_lobe(kernels::glint_pndf_element_lobe(chosen, chosen_u, f, k), k_.sigma_r, k_.cull_s, u1, u2);
        if (!(r.s.x * r.s.x + r.s.y * r.s.y < real(1))) return pndf_sample<real>{};
        r.pdf_s = pdf(fp, r.s, total);
        if (!(r.pdf_s > 0)) return pndf_sample<real>{};
        r.h = vec3_t<real>(r.s.x, r.s.y, std::sqrt(real(1) - r.s.x * r.s.x - r.s.y * r.s.y));
        r.pdf_h = r.pdf_s * r.h.z;
        r.valid = true;
        return r;
    }

    // s from an element's footprint lobe N(mean, C) truncated at Mahalanobis radius cull_s (the
    // lobe term's own cut): C = sigma_r^2 I + B B^T, its Cholesky factor, a radius from the
    // truncated Rayleigh law (u1) and an angle (u2). Shared with lobe_tree.hpp.
    static vec2 draw_from_lobe(const typename kernels::glint_pndf_lobe& l, real sigma_r, real cull_s, real u1, real u2) {
        const real sr = std::max(sigma_r, real(1e-5));
        const real c11 = sr * sr + l.b.x * l.b.x + l.b.z * l.b.z, c12 = l.b.x * l.b.y + l.b.z * l.b.w;
        const real l11 = std::sqrt(c11), l21 = c12 / l11, l22 = std::sqrt(std::max(l.det_c / c11, real(0)));
        const real rho2 = real(-2) * std::log1p(-u1 * -std::expm1(real(-0.5) * cull_s * cull_s));
        const real rho = std::sqrt(std::max(rho2, real(0))), phi = real(6.28318530717958647692) * u2;
        const real z1 = rho * std::cos(phi), z2 = rho * std::sin(phi);
        return l.mean + vec2(l11 * z1, l21 * z1 + l22 * z2);
    }

    // The density of sample()'s s: D_P(s) over the sampled elements (the hierarchy's sum or the
    // uncapped lattice loop, never the continuum limit) over their weight W (each lobe term
    // already carries its truncated mass, 1 - exp(-cull_s^2 / 2)). W costs a pass over the box:
    // callers evaluating many s for one footprint pass sampling_weight(fp) once.
    real pdf(const texel_footprint<real>& fp, const vec2& s) const { return pdf(fp, s, sampling_weight(fp)); }
    real pdf(const texel_footprint<real>& fp, const vec2& s, real weight) const {
        if (!(s.x * s.x + s.y * s.y < real(1)) || !(weight > 0)) return real(0);
        const frame f = prepare(fp);
        if (!large_footprint(f) && hierarchy_pays(f, s)) return hierarchy_sum(f, s) / weight;
        return direct_sum(f, s, sampling_params()) / weight;
    }
    // W: the sum of the tapered weights of the elements sample() draws from.
    real sampling_weight(const texel_footprint<real>& fp) const {
        return weight_sum(prepare(fp), sampling_params());
    }

    // XTXW24 Eq. 1 with eval's D_P, Smith G2 (Beckmann at alpha_g()) and the conductor Fresnel.
    real brdf(const texel_footprint<real>& fp, const vec3_t<real>& wi, const vec3_t<real>& wo, real eta, real k) const {
        if (!(wi.z > 0) || !(wo.z > 0)) return real(0);
        const vec3_t<real> h = glm::normalize(wi + wo);
        if (!(h.z > 0)) return real(0);
        return kernels::glint_pndf_brdf(eval(fp, vec2(h.x, h.y)), wi, wo, static_cast<int>(ndf::beckmann), vec2(alpha_g_), eta, k);
    }

    // The elements as the GLSL kernels read them (two vec4 each; upload as std430 vec4[]).
    const std::vector<vec4>& element_data() const { return data_; }
    const params& kernel_params() const { return k_; }
    std::size_t element_count() const { return bound_.size(); }
    real sigma_h() const { return k_.sigma_h; }
    real sigma_r() const { return k_.sigma_r; }
    real spacing() const { return k_.spacing; }
    // The Smith roughness used by brdf(): sqrt(mean |slope|^2 + 2 sigma_r^2) over the elements.
    real alpha_g() const { return alpha_g_; }
    // Cells per side of the finest normal-space grid, and the number of grid levels (the coarsest
    // is one cell); 0 and 0 without the hierarchy (gaussian_params::hierarchy).
    int grid_size() const { return level_size_.empty() ? 0 : level_size_.front(); }
    int level_count() const { return static_cast<int>(level_size_.size()); }
    // How many elements are listed at each level (finest first).
    std::vector<std::size_t> level_elements() const {
        std::vector<std::size_t> count(level_size_.size(), 0);
        for (const std::uint8_t l : level_) ++count[l];
        return count;
    }
    // Elements, s-boxes, the cells' element lists and their position trees, and the node NDF images.
    std::size_t memory_bytes() const {
        return data_.size() * sizeof(vec4) + bound_.size() * sizeof(vec4) + level_.size() + cell_begin_.size() * sizeof(std::uint32_t) +
               listed_.size() * sizeof(listed_element) + node_begin_.size() * sizeof(std::uint32_t) + nodes_.size() * sizeof(box) +
               node_ndf_of_.size() * sizeof(std::int32_t) + node_ndfs_.size() * sizeof(node_ndf) + ndf_images_.size() * sizeof(std::uint16_t);
    }
    // The bytes of the node NDF images alone (0 without prefilter_spread), and how many nodes have one.
    std::size_t prefilter_bytes() const {
        return node_ndf_of_.size() * sizeof(std::int32_t) + node_ndfs_.size() * sizeof(node_ndf) + ndf_images_.size() * sizeof(std::uint16_t);
    }
    std::size_t prefiltered_node_count() const { return node_ndfs_.size(); }
    real prefilter_spread() const { return prefilter_spread_; }

    // Whether a footprint is wide enough for the continuum limit: periodic map, and the periodic
    // images' Poisson-summation error exp(-2 pi^2 k' / P^2) below 1e-8 on both axes, with
    // k' = kappa_min / (1 + jmax^2 sigma_h^4 / (kappa_min sigma_r^2)) the width of the sum's
    // terms in u (sharp lobes moving with the footprint offset narrow it).
    bool large_footprint(const frame& f) const {
        if (k_.periodic == 0) return false;
        const real kmin = std::min(f.kappa.x, f.kappa.y), sr = std::max(k_.sigma_r, real(1e-5)), sh2 = k_.sigma_h * k_.sigma_h;
        const real kp = kmin / (real(1) + jmax_ * jmax_ * sh2 * sh2 / (kmin * sr * sr));
        const real p = std::max(period_.x, period_.y);
        // 2 pi^2 0.94 = 18.55: 2 exp(-18.55) = 1.8e-8 per axis. A culling box wider than 8 periods
        // (9 images per axis) takes the limit whatever its error, which is then the ripple of sharp
        // lobes between the periodic images: the exact sum would cost (images)^2 terms per element.
        return kp >= real(0.94) * p * p || f.extent.x > real(4) * period_.x || f.extent.y > real(4) * period_.y;
    }

private:
    struct box {
        float x0, y0, x1, y1;
    };
    // The cells' lists hold copies of the element and its s-box, so that a query reads them in
    // order instead of gathering from the lattice.
    struct listed_element {
        element el;
        vec4 bound;
    };
    // Elements per leaf of a position tree. A query costs more per node it visits than per
    // element it tests in a leaf's run, which it reads in memory order (on the flakes map of
    // docs/microstructure.md, relative to runs of 8: 4 took 1.2x the time at footprint sd 64,
    // 16 0.9x, 32 0.8x, 64 0.8x but 1.1x at sd 8).
    static constexpr std::uint32_t leaf_size = 32;

    frame prepare(const texel_footprint<real>& fp, real cull_u, real cull_s) const {
        const auto& c = fp.covariance;
        // The determinant in double: xx yy - xy^2 cancels for thin footprints.
        const double det = static_cast<double>(c[0][0]) * static_cast<double>(c[1][1]) - static_cast<double>(c[1][0]) * static_cast<double>(c[1][0]);
        return kernels::glint_pndf_prepare(fp.center, vec4(c[0][0], c[1][0], c[1][1], static_cast<real>(std::max(det, 0.0))), k_.sigma_h, cull_u,
                                           cull_s);
    }
    frame prepare(const texel_footprint<real>& fp) const { return prepare(fp, k_.cull_u, k_.cull_s); }

    params reference_params() const {
        params k = k_;
        k.cull_u = real(7);
        k.cull_s = real(0);
        k.max_side = 1 << 28;
        return k;
    }
    params sampling_params() const {
        params k = k_;
        k.max_side = 1 << 28;
        return k;
    }

    // Calls fn(index, element, its image position) for every lattice point in the culling box of f.
    template <class fn_t>
    void for_each_in_box(const frame& f, const params& k, fn_t&& fn) const {
        const auto rx = kernels::glint_pndf_axis_range(f.mean.x, f.extent.x, k.spacing, k.max_side);
        const auto ry = kernels::glint_pndf_axis_range(f.mean.y, f.extent.y, k.spacing, k.max_side);
        for (int j = ry.x; j <= ry.y; ++j) {
            if (k.periodic == 0 && (j < 0 || j >= k.height)) continue;
            const int wj = kernels::glint_pndf_wrap(j, k.height);
            for (int i = rx.x; i <= rx.y; ++i) {
                if (k.periodic == 0 && (i < 0 || i >= k.width)) continue;
                const std::size_t idx = static_cast<std::size_t>(kernels::glint_pndf_wrap(i, k.width) + k.width * wj);
                const element el{data_[2 * idx], data_[2 * idx + 1]};
                fn(idx, el, vec2((real(i) + real(0.5)) * k.spacing, (real(j) + real(0.5)) * k.spacing));
            }
        }
    }

    // The lattice loop of glint_pndf_direct under params k. (Testing each element's s-box first
    // saved 9% to 16% on the flakes map of docs/microstructure.md, where eval takes the hierarchy,
    // but cost 26% to 29% more on the noise map, where it takes this loop: the kernel's own
    // culling tests come before its exp.)
    real direct_sum(const frame& f, const vec2& s, const params& k) const { return kernels::glint_pndf_direct(data_.data(), f, s, k); }

    // sum_i marginal_i(s) / (map area): the exact limit of the periodic sum for huge footprints.
    real continuum_limit(const vec2& s) const {
        real sum = 0;
        if (level_size_.empty())  // no hierarchy: every element
            for (std::size_t e = 0; e < bound_.size(); ++e) {
                const element el{data_[2 * e], data_[2 * e + 1]};
                if (!outside(bound_[e], el, s)) sum += kernels::glint_pndf_element_marginal(el, s, k_);
            }
        for (int l = 0; l < level_count(); ++l) {
            const std::size_t c = cell_of(s, l);
            for (std::uint32_t r = cell_begin_[c]; r < cell_begin_[c + 1]; ++r) {
                const listed_element& x = listed_[r];
                if (outside(x.bound, x.el, s)) continue;
                const element& el = x.el;
                sum += kernels::glint_pndf_element_marginal(el, s, k_);
            }
        }
        return sum / (period_.x * period_.y);
    }

    // Whether the lists of the cells holding s, over the periodic images the culling box covers,
    // are shorter than the box's lattice: on maps whose lobes are as wide as their spread of
    // normals (rough at the texel scale) normal-space culling cannot pay, and the direct loop (the
    // same elements, so the same sum up to rounding) is cheaper.
    bool hierarchy_pays(const frame& f, const vec2& s) const {
        if (level_size_.empty()) return false;
        double listed = 0;
        for (int l = 0; l < level_count(); ++l) {
            const std::size_t c = cell_of(s, l);
            listed += static_cast<double>(cell_begin_[c + 1] - cell_begin_[c]);
        }
        const double area = 4.0 * static_cast<double>(f.extent.x) * static_cast<double>(f.extent.y);
        const double map_area = static_cast<double>(period_.x) * static_cast<double>(period_.y);
        const double spacing2 = static_cast<double>(k_.spacing) * static_cast<double>(k_.spacing);
        // The listed elements inside the box against every lattice point of the box, in units of
        // the direct loop's cost per lattice point (measured on the flakes and noise maps of
        // docs/microstructure.md at footprint sd 1 to 64: the hierarchy about 2000 ns a query plus
        // 4 to 16 ns per listed element in the box, the loop 8 to 17 ns per lattice point).
        return 1.2 * listed * area / map_area + 48.0 * level_count() < area / spacing2;
    }

    // The hierarchy's D_P(s): the cell holding s at every level; nodes whose elements lie within
    // tau footprint sds of their mean (tau > 0) through their NDF images.
    real hierarchy_sum(const frame& f, const vec2& s, real tau = 0) const {
        if (level_size_.empty()) return direct_sum(f, s, sampling_params());
        const float spread2 = node_ndfs_.empty() ? -1.0f : static_cast<float>(tau * tau * std::min(f.kappa.x, f.kappa.y));
        real sum = 0;
        for (int l = 0; l < level_count(); ++l) sum += query(cell_of(s, l), f, s, spread2);
        return sum;
    }

    // Whether nodes of the given spread2 are within tau footprint sds: eval takes the images where
    // some node is (the smallest spread2) and the hierarchy pays, and where the median node is
    // when the lattice loop is cheaper than the exact hierarchy (on the noise map of
    // docs/microstructure.md at footprint sd 64, the images through the hierarchy took 1.1x the
    // loop's time).
    bool prefilter_applies(const frame& f, real tau, float spread2) const {
        return !node_ndfs_.empty() && tau > 0 && spread2 <= static_cast<float>(tau * tau * std::min(f.kappa.x, f.kappa.y));
    }

    // Whether s lies outside an element's oriented s-box b, where its term is 0 for every footprint.
    static bool outside(const vec4& b, const element& el, const vec2& s) {
        const real dx = s.x - el.us.z, dy = s.y - el.us.w;
        return std::fabs(dx * b.x + dy * b.y) > b.z || std::fabs(dy * b.x - dx * b.y) > b.w;
    }

    // The sum of the tapered weights of the elements in the culling box of f under params k.
    real weight_sum(const frame& f, const params& k) const {
        real sum = 0;
        for_each_in_box(f, k, [&](std::size_t, const element&, const vec2& u) { sum += kernels::glint_pndf_element_weight(u, f, k); });
        return sum;
    }

    // The index of the cell holding s (|s| < 1) at grid level l.
    std::size_t cell_of(const vec2& s, int l) const {
        const int m = level_size_[static_cast<std::size_t>(l)];
        const real c = real(2) / real(m);
        const int cx = std::clamp(static_cast<int>((s.x + real(1)) / c), 0, m - 1), cy = std::clamp(static_cast<int>((s.y + real(1)) / c), 0, m - 1);
        return level_first_[static_cast<std::size_t>(l)] + static_cast<std::size_t>(cx + m * cy);
    }

    // The elements of cell c that pass the culling, over the periodic images the box touches;
    // nodes with an NDF image whose elements' mean squared distance from their mean is at most
    // spread2 (texels^2; < 0: none) as one lookup.
    real query(std::size_t c, const frame& f, const vec2& s, float spread2) const {
        const std::uint32_t begin = cell_begin_[c], end = cell_begin_[c + 1];
        if (begin == end) return real(0);
        const std::uint32_t leaves = (end - begin + leaf_size - 1) / leaf_size;
        std::uint32_t p2 = 1;
        while (p2 < leaves) p2 *= 2;
        const box* tree = nodes_.data() + node_begin_[c];
        const real x0 = f.mean.x - f.extent.x, x1 = f.mean.x + f.extent.x, y0 = f.mean.y - f.extent.y, y1 = f.mean.y + f.extent.y;
        long ix0 = 0, ix1 = 0, iy0 = 0, iy1 = 0;
        if (k_.periodic) {
            ix0 = static_cast<long>(std::floor(x0 / period_.x)), ix1 = static_cast<long>(std::floor(x1 / period_.x));
            iy0 = static_cast<long>(std::floor(y0 / period_.y)), iy1 = static_cast<long>(std::floor(y1 / period_.y));
        }
        // The culling ellipse's bounding rectangle along its own axes (a separating-axis test on
        // them keeps thin footprints from visiting their whole axis-aligned box).
        const float ax = static_cast<float>(f.axis.x), ay = static_cast<float>(f.axis.y);
        const float e1 = static_cast<float>(k_.cull_u * std::sqrt(f.kappa.x)), e2 = static_cast<float>(k_.cull_u * std::sqrt(f.kappa.y));
        real sum = 0;
        for (long iy = iy0; iy <= iy1; ++iy)
            for (long ix = ix0; ix <= ix1; ++ix) {
                const vec2 offset(static_cast<real>(ix) * period_.x, static_cast<real>(iy) * period_.y);
                const float bx0 = static_cast<float>(x0 - offset.x), bx1 = static_cast<float>(x1 - offset.x);
                const float by0 = static_cast<float>(y0 - offset.y), by1 = static_cast<float>(y1 - offset.y);
                const float mx = static_cast<float>(f.mean.x - offset.x), my = static_cast<float>(f.mean.y - offset.y);
                std::uint32_t stack[64];
                int top = 0;
                stack[top++] = 1;
                while (top > 0) {
                    const std::uint32_t node = stack[--top];
                    const box& b = tree[node];
                    if (b.x0 > bx1 || b.x1 < bx0 || b.y0 > by1 || b.y1 < by0) continue;
                    const float cx = 0.5f * (b.x0 + b.x1) - mx, cy = 0.5f * (b.y0 + b.y1) - my, hx = 0.5f * (b.x1 - b.x0), hy = 0.5f * (b.y1 - b.y0);
                    if (std::fabs(cx * ax + cy * ay) > hx * std::fabs(ax) + hy * std::fabs(ay) + e1 * 1.001f + 1e-3f) continue;
                    if (std::fabs(-cx * ay + cy * ax) > hx * std::fabs(ay) + hy * std::fabs(ax) + e2 * 1.001f + 1e-3f) continue;
                    if (node >= p2) {
                        const std::uint32_t first = begin + leaf_size * (node - p2), last = std::min(end, first + leaf_size);
                        for (std::uint32_t r = first; r < last; ++r) {
                            const listed_element& x = listed_[r];
                            if (outside(x.bound, x.el, s)) continue;
                            sum += kernels::glint_pndf_element(x.el, vec2(x.el.us.x, x.el.us.y) + offset, f, s, k_);
                        }
                    } else {
                        if (spread2 >= 0) {
                            const std::int32_t t = node_ndf_of_[node_begin_[c] + node];
                            if (t >= 0 && node_ndfs_[static_cast<std::size_t>(t)].spread2 <= spread2) {
                                sum += node_ndf_term(node_ndfs_[static_cast<std::size_t>(t)], f, s, offset);
                                continue;
                            }
                        }
                        // The left child on top, so that leaves come in memory order (which the
                        // hardware prefetcher follows: 1.3x to 1.8x faster than the reverse).
                        stack[top++] = 2 * node + 1;
                        stack[top++] = 2 * node;
                    }
                }
            }
        return sum;
    }

    // A position-tree node's NDF image (prefilter_spread): on an n x n grid of points over its
    // cell in s (spacing 1 / inv_delta from s0), the sums over the node's elements of their culled
    // marginal lobes L_i(s) (the footprint -> infinity limit of each lobe, cut at cull_s and
    // divided by its kept mass, as the element term), as 16-bit fractions of lobe_scale, and of
    // L_i(s) (u_i - mean), as signed 16-bit fractions of moment_scale; three per point from
    // `offset` in ndf_images_.
    struct node_ndf {
        float mean_x, mean_y, spread2;  // the elements' mean position and mean squared distance from it (texels)
        float s0x, s0y, inv_delta;
        float lobe_scale, moment_scale;
        std::uint32_t n;
        std::size_t offset;  // 2^26 elements' images can pass 2^32 values
    };
    // Grid points per sigma_r (spacing sigma_r / 2): bilinear interpolation of a lobe of sd sigma_r
    // sampled at spacing d errs by at most d^2 / (8 sigma_r^2) = 3.1% of its peak per axis; the
    // measured L1 error of the whole approximation is in docs/microstructure.md (3 points per
    // sigma_r take 2.25x the memory, so nodes twice as wide under the same memory rule).
    static constexpr double ndf_points_per_sigma_r = 2;
    // Levels whose cells would need more points per side have no images (their nodes stay exact).
    static constexpr int max_ndf_points = 513;
    // The images of one height of a position tree take at most this many times the bytes of their
    // elements' copies (so all heights at most twice that). On the flakes map of
    // docs/microstructure.md at footprint sd 512, float images at most as large as their copies
    // (3 points per sigma_r) left the coarse levels' cells without nodes small enough, and eval was
    // 2.8x faster than exact at tau 0.7; at 4x (2 points per sigma_r) 7.7x at tau 0.5. 16-bit
    // values at 2x give the same nodes as float ones at 4x.
    static constexpr std::size_t ndf_memory_ratio = 2;

    // A node's terms through its image: the footprint's weight at the elements' mean position
    // where they reach s (first order in u exact; header comment) times the sum of their lobes.
    real node_ndf_term(const node_ndf& t, const frame& f, const vec2& s, const vec2& offset) const {
        const float last = static_cast<float>(t.n - 1);
        const float gx = std::clamp((static_cast<float>(s.x) - t.s0x) * t.inv_delta, 0.0f, last);
        const float gy = std::clamp((static_cast<float>(s.y) - t.s0y) * t.inv_delta, 0.0f, last);
        const std::uint32_t ix = std::min(static_cast<std::uint32_t>(gx), t.n - 2), iy = std::min(static_cast<std::uint32_t>(gy), t.n - 2);
        const float fx = gx - static_cast<float>(ix), fy = gy - static_cast<float>(iy);
        const std::uint16_t* p = ndf_images_.data() + t.offset + 3 * (ix + t.n * iy);
        const std::uint16_t* q = p + 3 * t.n;
        const float w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
        const float lobes = w00 * p[0] + w10 * p[3] + w01 * q[0] + w11 * q[3];
        if (!(lobes > 0)) return real(0);
        const auto sgn = [](std::uint16_t v) { return static_cast<float>(static_cast<std::int16_t>(v)); };
        const float mx = w00 * sgn(p[1]) + w10 * sgn(p[4]) + w01 * sgn(q[1]) + w11 * sgn(q[4]);
        const float my = w00 * sgn(p[2]) + w10 * sgn(p[5]) + w01 * sgn(q[2]) + w11 * sgn(q[5]);
        const float to_u = t.moment_scale / t.lobe_scale / lobes;
        const vec2 u(static_cast<real>(t.mean_x + mx * to_u) + offset.x, static_cast<real>(t.mean_y + my * to_u) + offset.y);
        return kernels::glint_pndf_element_weight(u, f, k_) / k_.area * static_cast<real>(lobes * t.lobe_scale);
    }

    // Adds element x's culled marginal lobe L(s) and L(s) (u - mean) to the image `img` (n x n
    // points from s0, spacing delta): each row's points inside the cull_s ellipse, exp(-q / 2)
    // stepped along the row by its ratio recurrence (q is quadratic in s).
    void splat_lobe(const listed_element& x, const glm::dvec2& mean, const glm::dvec2& s0, double delta, int n, double* img) const {
        const double sr = std::max(static_cast<double>(k_.sigma_r), 1e-5), sh2 = static_cast<double>(k_.sigma_h) * static_cast<double>(k_.sigma_h);
        const glm::dvec4 j(x.el.jac);
        const double c11 = sr * sr + sh2 * (j.x * j.x + j.z * j.z), c22 = sr * sr + sh2 * (j.y * j.y + j.w * j.w), c12 = sh2 * (j.x * j.y + j.z * j.w);
        const double det = c11 * c22 - c12 * c12;
        if (!(det > 0)) return;
        const double p11 = c22 / det, p22 = c11 / det, p12 = -c12 / det, cs2 = static_cast<double>(k_.cull_s) * static_cast<double>(k_.cull_s);
        const double norm = 1 / (6.283185307179586 * static_cast<double>(kernels::glint_pndf_kept_mass(k_.cull_s)) * std::sqrt(det));
        const glm::dvec2 c(static_cast<double>(x.el.us.z), static_cast<double>(x.el.us.w));
        const glm::dvec2 du(static_cast<double>(x.el.us.x) - mean.x, static_cast<double>(x.el.us.y) - mean.y);
        const double ry = std::sqrt(cs2 * c22);
        const int y0 = std::max(0, static_cast<int>(std::ceil((c.y - ry - s0.y) / delta))), y1 = std::min(n - 1, static_cast<int>(std::floor((c.y + ry - s0.y) / delta)));
        const double ratio_step = std::exp(-p11 * delta * delta);
        for (int iy = y0; iy <= y1; ++iy) {
            const double dy = s0.y + iy * delta - c.y;
            const double disc = p12 * p12 * dy * dy - p11 * (p22 * dy * dy - cs2);
            if (!(disc >= 0)) continue;
            const double root = std::sqrt(disc);
            const int x0 = std::max(0, static_cast<int>(std::ceil((c.x + (-p12 * dy - root) / p11 - s0.x) / delta)));
            const int x1 = std::min(n - 1, static_cast<int>(std::floor((c.x + (-p12 * dy + root) / p11 - s0.x) / delta)));
            if (x1 < x0) continue;
            const double dx0 = s0.x + x0 * delta - c.x;
            double value = norm * std::exp(-0.5 * (p11 * dx0 * dx0 + 2 * p12 * dx0 * dy + p22 * dy * dy));
            double ratio = std::exp(-0.5 * (p11 * (2 * dx0 * delta + delta * delta) + 2 * p12 * dy * delta));
            double* row = img + 3 * (static_cast<std::size_t>(iy) * static_cast<std::size_t>(n));
            for (int ix = x0; ix <= x1; ++ix) {
                row[3 * ix] += value, row[3 * ix + 1] += value * du.x, row[3 * ix + 2] += value * du.y;
                value *= ratio, ratio *= ratio_step;
            }
        }
    }

    // The node NDF images (prefilter_spread > 0). At each grid level whose cells take at most
    // max_ndf_points per side at ndf_points_per_sigma_r, every position-tree node of at least
    // min_count elements has one, where min_count makes one height's images take at most the
    // bytes of its elements' copies (all heights at most twice): the lowest such height's images
    // from the elements, each higher one as the sum of its children's (moments moved to its mean).
    void build_node_ndfs() {
        node_ndf_of_.assign(nodes_.size(), -1);
        node_ndfs_.clear(), ndf_images_.clear();
        std::vector<float> spreads;  // of the nodes with images
        const double delta_target = std::max(static_cast<double>(k_.sigma_r), 1e-5) / ndf_points_per_sigma_r;
        for (int l = 0; l < level_count(); ++l) {
            const int m = level_size_[static_cast<std::size_t>(l)];
            const double cw = 2.0 / m;
            const int n = static_cast<int>(std::ceil(cw / delta_target)) + 1;
            if (n > max_ndf_points) continue;
            const double delta = cw / (n - 1);
            const std::size_t floats = 3 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
            int h0 = 1;
            while ((std::size_t{leaf_size} << h0) * sizeof(listed_element) * ndf_memory_ratio < floats * sizeof(std::uint16_t)) ++h0;
            for (int cy = 0; cy < m; ++cy)
                for (int cx = 0; cx < m; ++cx) {
                    const std::size_t c = level_first_[static_cast<std::size_t>(l)] + static_cast<std::size_t>(cx + m * cy);
                    const std::uint32_t begin = cell_begin_[c], end = cell_begin_[c + 1];
                    const std::uint32_t leaves = (end - begin + leaf_size - 1) / leaf_size;
                    std::uint32_t p2 = 1;
                    while (p2 < leaves) p2 *= 2;
                    if (p2 < (1u << h0)) continue;
                    const glm::dvec2 s0(-1 + cx * cw, -1 + cy * cw);
                    struct built {
                        std::vector<double> img;
                        glm::dvec2 mean{0};
                        double spread2 = 0, count = 0;
                    };
                    const std::uint32_t first_node = p2 >> h0;  // nodes [first_node, 2 first_node) are at height h0
                    std::vector<built> b(2 * first_node);
                    for (std::uint32_t i = first_node; i < 2 * first_node; ++i) {
                        const std::uint32_t e0 = begin + leaf_size * ((i << h0) - p2), e1 = std::min(end, begin + leaf_size * (((i + 1) << h0) - p2));
                        if (e0 >= e1) continue;
                        built& t = b[i];
                        t.count = e1 - e0;
                        for (std::uint32_t r = e0; r < e1; ++r) t.mean += glm::dvec2(listed_[r].el.us.x, listed_[r].el.us.y);
                        t.mean /= t.count;
                        for (std::uint32_t r = e0; r < e1; ++r) {
                            const glm::dvec2 d = glm::dvec2(listed_[r].el.us.x, listed_[r].el.us.y) - t.mean;
                            t.spread2 += glm::dot(d, d) / t.count;
                        }
                        t.img.assign(floats, 0.0);
                        for (std::uint32_t r = e0; r < e1; ++r) splat_lobe(listed_[r], t.mean, s0, delta, n, t.img.data());
                    }
                    for (std::uint32_t i = first_node - 1; i >= 1; --i) {
                        const built &a = b[2 * i], &z = b[2 * i + 1];
                        if (a.count == 0) continue;  // the left child holds the first elements
                        built& t = b[i];
                        t.count = a.count + z.count;
                        t.mean = (a.mean * a.count + z.mean * z.count) / t.count;
                        const glm::dvec2 da = a.mean - t.mean, dz = z.mean - t.mean;
                        t.spread2 = (a.count * (a.spread2 + glm::dot(da, da)) + z.count * (z.spread2 + glm::dot(dz, dz))) / t.count;
                        t.img = a.img;
                        for (std::size_t k = 0; k < floats; k += 3) {
                            t.img[k + 1] += a.img[k] * da.x, t.img[k + 2] += a.img[k] * da.y;
                            if (z.count == 0) continue;
                            t.img[k] += z.img[k], t.img[k + 1] += z.img[k + 1] + z.img[k] * dz.x, t.img[k + 2] += z.img[k + 2] + z.img[k] * dz.y;
                        }
                    }
                    for (std::uint32_t i = 1; i < 2 * first_node; ++i) {
                        const built& t = b[i];
                        if (t.count == 0) continue;
                        // 16-bit fractions of each channel's largest magnitude (rounded to nearest).
                        double top = 0, top_moment = 0;
                        for (std::size_t k = 0; k < floats; k += 3)
                            top = std::max(top, t.img[k]), top_moment = std::max({top_moment, std::fabs(t.img[k + 1]), std::fabs(t.img[k + 2])});
                        if (!(top > 0)) continue;
                        const double lobe_scale = top / 65535, moment_scale = std::max(top_moment, 1e-30 * top) / 32767;
                        node_ndf_of_[node_begin_[c] + i] = static_cast<std::int32_t>(node_ndfs_.size());
                        node_ndfs_.push_back(node_ndf{static_cast<float>(t.mean.x), static_cast<float>(t.mean.y), static_cast<float>(t.spread2),
                                                      static_cast<float>(s0.x), static_cast<float>(s0.y), static_cast<float>(1 / delta),
                                                      static_cast<float>(lobe_scale), static_cast<float>(moment_scale), static_cast<std::uint32_t>(n),
                                                      ndf_images_.size()});
                        spreads.push_back(static_cast<float>(t.spread2));
                        for (std::size_t k = 0; k < floats; k += 3) {
                            ndf_images_.push_back(static_cast<std::uint16_t>(std::lround(std::min(t.img[k] / lobe_scale, 65535.0))));
                            for (std::size_t a = 1; a <= 2; ++a)
                                ndf_images_.push_back(static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(std::clamp(t.img[k + a] / moment_scale, -32767.0, 32767.0)))));
                        }
                    }
                }
        }
        min_ndf_spread2_ = median_ndf_spread2_ = std::numeric_limits<float>::max();
        if (!spreads.empty()) {
            min_ndf_spread2_ = *std::min_element(spreads.begin(), spreads.end());
            std::nth_element(spreads.begin(), spreads.begin() + static_cast<std::ptrdiff_t>(spreads.size() / 2), spreads.end());
            median_ndf_spread2_ = spreads[spreads.size() / 2];
        }
    }

    // Calls fn(cell index) for each cell of grid level l that element e's oriented s-box overlaps
    // (separating axes: the cell's, then the box's), widened by 1e-6 so that a query's cell_of,
    // rounded in float, never finds s in a cell that does not list the element.
    template <class fn_t>
    void for_each_cell(std::size_t e, int l, fn_t&& fn) const {
        const int m = level_size_[static_cast<std::size_t>(l)];
        const double c = 2.0 / m, margin = 1e-6;
        const double cs = static_cast<double>(bound_[e].x), sn = static_cast<double>(bound_[e].y), r1 = static_cast<double>(bound_[e].z),
                     r2 = static_cast<double>(bound_[e].w);
        const double sx = static_cast<double>(data_[2 * e].z), sy = static_cast<double>(data_[2 * e].w);
        const double hx = r1 * std::fabs(cs) + r2 * std::fabs(sn) + margin, hy = r1 * std::fabs(sn) + r2 * std::fabs(cs) + margin;
        const auto index = [&](double v) { return std::clamp(static_cast<int>(std::floor((v + 1) / c)), 0, m - 1); };
        const int x0 = index(sx - hx), x1 = index(sx + hx), y0 = index(sy - hy), y1 = index(sy + hy);
        const double reach = 0.5 * c * (std::fabs(cs) + std::fabs(sn)) + margin;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double dx = -1 + (x + 0.5) * c - sx, dy = -1 + (y + 0.5) * c - sy;
                if (std::fabs(dx * cs + dy * sn) > r1 + reach || std::fabs(dy * cs - dx * sn) > r2 + reach) continue;
                fn(level_first_[static_cast<std::size_t>(l)] + static_cast<std::size_t>(x + m * y));
            }
    }

    void build_grid() {
        const std::size_t n = bound_.size();
        // The finest level's cells about four times the median s-radius on a side: a power of two,
        // 8 to 256 per side; each coarser level halves it, down to one cell.
        std::vector<real> r(n);
        for (std::size_t e = 0; e < n; ++e) r[e] = std::max(bound_[e].z, bound_[e].w);
        std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n / 2), r.end());
        const real median = r[n / 2];
        int finest = 8;
        while (finest < 256 && real(4 * finest) * median <= real(1)) finest *= 2;
        level_size_.clear(), level_first_.clear();
        std::size_t cells = 0;
        for (int m = finest; m >= 1; m /= 2) {
            level_size_.push_back(m);
            level_first_.push_back(cells);
            cells += static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
        }
        // Each element at the finest level where its s-box overlaps at most 8 cells: a thin box
        // (a groove wall's rank-1 Jacobian) stays fine and selective, a wide one goes coarse
        // instead of being listed in hundreds of cells. (Measured on the 1024^2 flakes map of
        // docs/microstructure.md: 16 cells and cells of twice the radius query up to 1.4x faster
        // at 1.6x the memory; 4 cells 1.3x slower at 0.75x.)
        level_.assign(n, 0);
        std::vector<std::uint32_t> count(cells, 0);
        for (std::size_t e = 0; e < n; ++e) {
            int l = 0;
            for (;; ++l) {
                int overlapped = 0;
                for_each_cell(e, l, [&](std::size_t) { ++overlapped; });
                if (overlapped <= 8 || l + 1 == level_count()) break;
            }
            level_[e] = static_cast<std::uint8_t>(l);
            for_each_cell(e, l, [&](std::size_t c) { ++count[c]; });
        }
        cell_begin_.assign(cells + 1, 0);
        for (std::size_t c = 0; c < cells; ++c) cell_begin_[c + 1] = cell_begin_[c] + count[c];
        listed_.resize(cell_begin_.back());
        std::vector<std::uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
        // Elements in Morton order of their lattice position, so each cell's list comes out sorted.
        std::vector<std::uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::vector<std::uint32_t> key(n);
        for (std::size_t e = 0; e < n; ++e)
            key[e] = morton2(static_cast<std::uint32_t>(e % static_cast<std::size_t>(k_.width)), static_cast<std::uint32_t>(e / static_cast<std::size_t>(k_.width)));
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
        for (const std::uint32_t e : order)
            for_each_cell(e, level_[e], [&](std::size_t c) { listed_[fill[c]++] = listed_element{element{data_[2 * e], data_[2 * e + 1]}, bound_[e]}; });
        // Position trees: a complete binary tree (heap order, root 1) over runs of leaf_size per cell.
        node_begin_.assign(cells, 0);
        nodes_.clear();
        const box empty{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                        -std::numeric_limits<float>::max()};
        for (std::size_t c = 0; c < cells; ++c) {
            const std::uint32_t begin = cell_begin_[c], end = cell_begin_[c + 1];
            node_begin_[c] = static_cast<std::uint32_t>(nodes_.size());
            if (begin == end) continue;
            const std::uint32_t leaves = (end - begin + leaf_size - 1) / leaf_size;
            std::uint32_t p2 = 1;
            while (p2 < leaves) p2 *= 2;
            const std::size_t base = nodes_.size();
            nodes_.resize(base + 2 * p2, empty);
            for (std::uint32_t l = 0; l < leaves; ++l) {
                box b = empty;
                for (std::uint32_t q = begin + leaf_size * l; q < std::min(end, begin + leaf_size * (l + 1)); ++q) {
                    const float x = static_cast<float>(listed_[q].el.us.x), y = static_cast<float>(listed_[q].el.us.y);
                    // Widened by an ulp-scale margin so the float box test never drops a boundary element.
                    const float m = 1e-3f;
                    b.x0 = std::min(b.x0, x - m), b.y0 = std::min(b.y0, y - m), b.x1 = std::max(b.x1, x + m), b.y1 = std::max(b.y1, y + m);
                }
                nodes_[base + p2 + l] = b;
            }
            for (std::uint32_t i = p2 - 1; i >= 1; --i) {
                const box& a = nodes_[base + 2 * i];
                const box& b = nodes_[base + 2 * i + 1];
                nodes_[base + i] = box{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
            }
        }
    }

    params k_{};
    vec2 period_{0};
    real alpha_g_ = real(0.1), jmax_ = 0;
    std::vector<vec4> data_;                      // two per element: (u, s), J
    std::vector<vec4> bound_;                     // the oriented s-box per element: (cos, sin) of its first axis, r_1, r_2
    std::vector<std::uint8_t> level_;             // the grid level listing each element
    std::vector<int> level_size_;                 // cells per side at each level, finest first
    std::vector<std::size_t> level_first_;        // each level's first cell
    std::vector<listed_element> listed_;
    std::vector<std::uint32_t> cell_begin_, node_begin_;
    std::vector<box> nodes_;
    // prefilter_spread: the node NDF images (node_ndf_of_ parallel to nodes_, -1 where none).
    real prefilter_spread_ = 0;
    std::vector<std::int32_t> node_ndf_of_;
    std::vector<node_ndf> node_ndfs_;
    std::vector<std::uint16_t> ndf_images_;
    float min_ndf_spread2_ = 0, median_ndf_spread2_ = 0;  // over the nodes with images
};

}  // namespace glint
