// glint tiny-example NDF maps (XTXW24 Sec. 5-6): the P-NDF of a surface covered by transformed
// copies of a tiny example normal map, from per-tile NDF images of the example (Eq. 7) and, for
// footprints smaller than a tile, from its Gaussian elements (Eq. 6). Needs core.glsl,
// microfacet.glsl and gaussian.glsl. Host side, derivations and measured errors:
// include/glint/ndf_map.hpp.
//
// Images. Level l (0 <= l < levels = log2 n) splits the n x n example into (n / 2^(l+1))^2 tiles of
// t_l = 2^(l+1) texels per side (XTXW24 Sec. 5.2); tile (tx, ty) of level l is image layer
// glint_ndf_level_first(n, l) + tx + (n >> (l+1)) ty. A layer holds res x res bins over s in
// [s_min, s_min + res s_bin]^2 (bin (x, y) at s_min + ((x, y) + 1/2) s_bin), four floats each:
//   x: B, the bin's mean of the tile's NDF (Eq. 7);
//   y, z: B_x, B_y, the same mean of the NDF's first moments in position, sum_i ((u_i - c_T) / t)
//         L_i(s) / N_T (c_T the tile's centre), which carry how the NDF varies across the tile;
//   w: the running sum of B x bin area over the layer's bins (row-major), for sampling; the last is
//      the tile's mass.
// x, y, z are reconstructed bilinearly between bin centres (clamped to the edge bins' value in the
// outer half bins; 0 outside the window). Read through GLINT_NDF_FETCH(layer, x, y, res) (a
// vec4): in C++ a pointer parameter (GLINT_NDF_DATA_PARAM), in GLSL a sampler2DArray (RGBA32F, one
// layer per tile, so filtering never bleeds between tiles) declared when GLINT_NDF_IMAGE_BINDING is
// defined, or any fetch the user defines first. The elements come from gaussian.glsl's element buffer.
//
// A tile's term is first order in position: sum_{i in T} w_i L_i(s) = W_T (B + t g . (B_x, B_y)) +
// O(t^2), g the gradient of log w at c_T, w_i the elements' footprint weights (glint's extension of
// Eq. 7's zero-order tiles, which err 2 to 5 times more at footprints of 4 to 8 texels, measured
// in docs/ndf_map.md).
//
// Layouts. A copy maps example texels u_ex to global texels x = anchor + A (u_ex - offset) and is
// periodic in the example (the example repeats). Tiled: one copy, A = the placement's A0.
// Stochastic: one copy per cell of a grid of side `cell`, anchored at a point jittered within the
// cell's central half, with a random rotation, scale, mirror and offset (Eq. 8-9's M), all from an
// integer hash of the cell (bit-exact in C++ and GLSL, no noise texture); a point belongs to the
// copy whose anchor is nearest (XTXW24 Fig. 3's nearest-centre rule, applied to every point: the
// cells of a Voronoi diagram, so every point has exactly one owner).
//
// Normals under A (the paper is silent; notes 4.5). The copy is the height field
// h(x) = lambda h_ex(u_ex(x)), lambda = sqrt|det A| (heights scale with the example), so slopes
// p = -s / s_z map as p_ex = M p, M = A^T / lambda, |det M| = 1. Then
//   s_ex = M s / N,  N^2 = 1 - |s|^2 + |M s|^2,  |det ds_ex / ds| = 1 / N^4
// (matrix determinant lemma), and the copy's P-NDF is D(s) = D_ex(s_ex) / N^4: mass is invariant,
// rotations rotate the NDF, and a pure scale leaves it unchanged.

#if defined(GLINT_GLSL) && !defined(GLINT_NDF_FETCH) && defined(GLINT_NDF_IMAGE_BINDING)
layout(binding = GLINT_NDF_IMAGE_BINDING) uniform sampler2DArray glint_ndf_images;
#define GLINT_NDF_FETCH(layer, x, y, res) texelFetch(glint_ndf_images, ivec3(x, y, layer), 0)
#endif

#if !defined(GLINT_GLSL) || defined(GLINT_ELEMENT_BUFFER_DECLARED) || defined(GLINT_ELEMENT_BINDING)
#define GLINT_HAS_NDF_ELEMENTS
#endif

GLINT_CONST(int) GLINT_NDF_TILED = 0;
GLINT_CONST(int) GLINT_NDF_STOCHASTIC = 1;
// What a tile or element loop accumulates: the P-NDF's numerator and weights, the weights and
// masses (for sampling), or the same until the running mass passes a target (the draw).
GLINT_CONST(int) GLINT_NDF_EVAL = 0;
GLINT_CONST(int) GLINT_NDF_MASS = 1;
GLINT_CONST(int) GLINT_NDF_SELECT = 2;
// As EVAL with zero-order tiles (B alone): the density glint_ndf_sample draws from.
GLINT_CONST(int) GLINT_NDF_DENSITY = 3;
// The largest footprint anisotropy (major / minor sd); wider ones grow their minor axis (16, as
// hardware anisotropic filtering caps it).
GLINT_CONST(real) GLINT_NDF_MAX_ANISOTROPY = real(16);
// Every point owned by an anchor lies within sqrt(2) (1/2 + 1/4) cell = 1.0607 cell of it (the
// point's own cell's anchor is at most that far), rounded up.
GLINT_CONST(real) GLINT_NDF_OWNER_REACH = real(1.061);

struct glint_ndf_map_params {
    int n;             // the example's side, texels (a power of two, 4 to 256)
    int levels;        // log2 n
    int res;           // bins per image side
    int max_tiles;     // tiles per level (a hard cap; the level choice keeps below it)
    vec2 s_min;        // the s-window's lower corner
    real s_bin;        // bin width
    real tau;          // tiles at most tau times the footprint's minor sd on a side
    real cull;         // tile weights: Mahalanobis radius, tapered from cull - 1
    real direct_below; // the element path below this minor sd (example texels), blended into the map up to twice it
    real blend;        // the fraction of an octave over which two levels blend
    glint_pndf_params el;  // the example's elements (periodic lattice, n r per side)
};

struct glint_ndf_placement {
    int kind;          // GLINT_NDF_TILED or GLINT_NDF_STOCHASTIC
    uint seed;
    vec4 a;            // A0: example texels -> global texels (columns (a.x, a.y), (a.z, a.w))
    vec2 origin;       // tiled: where example texel (0, 0) lands
    real cell;         // stochastic: cell side, global texels
    vec2 rotation;     // stochastic: rotation range, radians
    vec2 scale;        // stochastic: scale range (> 0)
    real flip;         // stochastic: probability of a mirror (across the example's x axis)
    int max_cells;     // stochastic: footprints wider than this many cells across their culling box are narrowed to it
};

// One placed copy: x = anchor + A (u_ex - offset).
struct glint_ndf_copy {
    vec2 anchor;
    vec2 offset;
    vec4 a;
    vec4 a_inv;
    vec4 m;      // slopes: p_ex = M p
    vec4 m_inv;
    ivec2 cell;  // stochastic: the owning cell
};

// 2x2 matrices as vec4 columns.
GLINT_FN vec2 glint_ndf_mul(vec4 a, vec2 v) {
    return vec2(a.x * v.x + a.z * v.y, a.y * v.x + a.w * v.y);
}
GLINT_FN vec4 glint_ndf_mat_mul(vec4 a, vec4 b) {
    return vec4(a.x * b.x + a.z * b.y, a.y * b.x + a.w * b.y, a.x * b.z + a.z * b.w, a.y * b.z + a.w * b.w);
}
GLINT_FN real glint_ndf_det(vec4 a) {
    return a.x * a.w - a.z * a.y;
}
GLINT_FN vec4 glint_ndf_inverse(vec4 a) {
    real d = glint_ndf_det(a);
    return vec4(a.w, -a.y, -a.z, a.x) / d;
}

GLINT_FN glint_ndf_copy glint_ndf_make_copy(vec2 anchor, vec2 offset, vec4 a, ivec2 cell) {
    glint_ndf_copy c;
    c.anchor = anchor;
    c.offset = offset;
    c.a = a;
    c.a_inv = glint_ndf_inverse(a);
    real lambda = sqrt(abs(glint_ndf_det(a)));
    c.m = vec4(a.x, a.z, a.y, a.w) / lambda;
    c.m_inv = glint_ndf_inverse(c.m);
    c.cell = cell;
    return c;
}

// s -> (s_ex, 1 / N^4) for a copy's slope map M (header).
GLINT_FN vec3 glint_ndf_to_example_slope(vec4 m, vec2 s) {
    vec2 q = glint_ndf_mul(m, s);
    real n2 = max(real(1) - dot(s, s) + dot(q, q), real(1e-30));
    return vec3(q / sqrt(n2), real(1) / (n2 * n2));
}
// s_ex -> s (the inverse map: p = M^-1 p_ex).
GLINT_FN vec2 glint_ndf_from_example_slope(vec4 m_inv, vec2 s_ex) {
    vec2 q = glint_ndf_mul(m_inv, s_ex);
    real n2 = max(real(1) - dot(s_ex, s_ex) + dot(q, q), real(1e-30));
    return q / sqrt(n2);
}

// B Sigma B^T for cov = (xx, xy, yy, det), with det scaled by det(B)^2 (no cancellation).
GLINT_FN vec4 glint_ndf_transform_covariance(vec4 b, vec4 cov) {
    real xx = b.x * b.x * cov.x + real(2) * b.x * b.z * cov.y + b.z * b.z * cov.z;
    real yy = b.y * b.y * cov.x + real(2) * b.y * b.w * cov.y + b.w * b.w * cov.z;
    real xy = b.x * b.y * cov.x + (b.x * b.w + b.z * b.y) * cov.y + b.z * b.w * cov.z;
    real d = glint_ndf_det(b);
    return vec4(xx, xy, yy, d * d * cov.w);
}

// The eigenvalues (major, minor) of cov = (xx, xy, yy, det), the minor one as det / major.
GLINT_FN vec2 glint_ndf_eigenvalues(vec4 cov) {
    real hd = real(0.5) * (cov.x - cov.z);
    real l1 = max(real(0.5) * (cov.x + cov.z) + sqrt(hd * hd + cov.y * cov.y), real(0));
    real l2 = l1 > real(0) ? clamp(cov.w / l1, real(0), l1) : real(0);
    return vec2(l1, l2);
}

// A footprint with anisotropy above GLINT_NDF_MAX_ANISOTROPY gets minor variance major / 16^2
// (added along the minor axis); non-finite input becomes a point footprint.
GLINT_FN vec4 glint_ndf_clamp_anisotropy(vec4 cov) {
    if (!(abs(cov.x) < real(1e30) && abs(cov.y) < real(1e30) && abs(cov.z) < real(1e30) && abs(cov.w) < real(1e30))) return vec4(real(0));
    vec2 l = glint_ndf_eigenvalues(cov);
    real floor_minor = l.x / (GLINT_NDF_MAX_ANISOTROPY * GLINT_NDF_MAX_ANISOTROPY);
    if (!(l.y < floor_minor)) return cov;
    // The minor eigenvector (perpendicular to the major one), and cov + (floor - minor) v v^T.
    vec2 a1 = vec2(cov.y, l.x - cov.x);
    vec2 a2 = vec2(l.x - cov.z, cov.y);
    vec2 a = dot(a1, a1) > dot(a2, a2) ? a1 : a2;
    real len = sqrt(dot(a, a));
    vec2 v = len > real(0) ? vec2(-a.y, a.x) / len : vec2(real(0), real(1));
    real add = floor_minor - l.y;
    return vec4(cov.x + add * v.x * v.x, cov.y + add * v.x * v.y, cov.z + add * v.y * v.y, l.x * floor_minor);
}

// The first layer of level l: sum over k < l of (n / 2^(k+1))^2 = (n^2 - (n / 2^l)^2) / 3.
GLINT_FN int glint_ndf_level_first(int n, int l) {
    int m = n >> l;
    return (n * n - m * m) / 3;
}

// A float index clamped into int range.
GLINT_FN int glint_ndf_index(real x) {
    return int(clamp(x, real(-1e9), real(1e9)));
}

// ---------------------------------------------------------------------------------------------
// Stochastic placement: the cell's hash, anchor and copy, and the owner of a point.

// The cell's hashes: PCG3D of (cell, seed ^ salt); the salts (0, 0x68e31da4, 0xb5297a4d) are
// arbitrary distinct words that give each draw its own stream.
GLINT_FN uvec3 glint_ndf_cell_hash(glint_ndf_placement pl, ivec2 cell, uint salt) {
    return glint_pcg3d(uvec3(uint(cell.x), uint(cell.y), pl.seed ^ salt));
}

// The cell's anchor: uniform in the cell's central half (so a point's nearest anchor is among the
// 3 x 3 cells around it: any anchor two cells away is at least 1.25 cells off, its own at most 1.06).
GLINT_FN vec2 glint_ndf_cell_anchor(glint_ndf_placement pl, ivec2 cell) {
    uvec3 h = glint_ndf_cell_hash(pl, cell, 0u);
    GLINT_PRECISE vec2 j = vec2(real(0.25)) + real(0.5) * vec2(glint_unit_from_bits(h.x), glint_unit_from_bits(h.y));
    GLINT_PRECISE vec2 p = (vec2(cell) + j) * pl.cell;
    return p;
}

// The cell holding x's nearest anchor (ties to the first in row order).
GLINT_FN ivec2 glint_ndf_owner(glint_ndf_placement pl, vec2 x) {
    ivec2 c = ivec2(glint_ndf_index(floor(x.x / pl.cell)), glint_ndf_index(floor(x.y / pl.cell)));
    ivec2 best = c;
    real best_d = real(3.4e38);
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = c + ivec2(i, j);
            vec2 p = glint_ndf_cell_anchor(pl, q);
            GLINT_PRECISE real dx = x.x - p.x;
            GLINT_PRECISE real dy = x.y - p.y;
            GLINT_PRECISE real d = dx * dx + dy * dy;
            if (d < best_d) {
                best_d = d;
                best = q;
            }
        }
    return best;
}

// The copy of a stochastic cell: A = R(theta) scale A0 F, F a mirror with probability flip, and a
// uniform offset into the periodic example.
GLINT_FN glint_ndf_copy glint_ndf_cell_copy(glint_ndf_placement pl, ivec2 cell, int n) {
    uvec3 h = glint_ndf_cell_hash(pl, cell, 0u);
    uvec3 g = glint_ndf_cell_hash(pl, cell, 0x68e31da4u);
    real theta = mix(pl.rotation.x, pl.rotation.y, glint_unit_from_bits(h.z));
    real k = mix(pl.scale.x, pl.scale.y, glint_unit_from_bits(g.x));
    real c = cos(theta) * k;
    real s = sin(theta) * k;
    vec4 a = glint_ndf_mat_mul(vec4(c, s, -s, c), pl.a);
    if (glint_unit_from_bits(g.y) < pl.flip) a = vec4(a.x, a.y, -a.z, -a.w);
    uvec3 o = glint_ndf_cell_hash(pl, cell, 0xb5297a4du);
    vec2 offset = real(n) * vec2(glint_unit_from_bits(g.z), glint_unit_from_bits(o.x));
    return glint_ndf_make_copy(glint_ndf_cell_anchor(pl, cell), offset, a, cell);
}

GLINT_FN glint_ndf_copy glint_ndf_tiled_copy(glint_ndf_placement pl) {
    return glint_ndf_make_copy(pl.origin, vec2(real(0)), pl.a, ivec2(0));
}

// The anchors that can compete with copy c's for a point it might own (within
// GLINT_NDF_OWNER_REACH cells of its anchor, so in the 5 x 5 cells around its own): a point's owner
// is among the 3 x 3 cells around the point's cell, all inside those. `before`: whether the cell
// comes first in row order (it wins a tie, as in glint_ndf_owner). `inner`: points nearer the
// anchor than 0.49 of the nearest other are the copy's without a search.
struct glint_ndf_rivals {
    vec2 q[24];
    bool before[24];
    real inner;
};

GLINT_FN glint_ndf_rivals glint_ndf_make_rivals(glint_ndf_placement pl, glint_ndf_copy c) {
    glint_ndf_rivals r;
    int k = 0;
    real d2 = real(3.4e38);
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i) {
            if (i == 0 && j == 0) continue;
            r.q[k] = glint_ndf_cell_anchor(pl, c.cell + ivec2(i, j));
            r.before[k] = j < 0 || (j == 0 && i < 0);
            vec2 d = r.q[k] - c.anchor;
            d2 = min(d2, dot(d, d));
            k += 1;
        }
    r.inner = real(0.2401) * d2;  // (0.49 d)^2
    return r;
}

// Rivals for a tiled copy (never consulted: it owns everything).
GLINT_FN glint_ndf_rivals glint_ndf_no_rivals() {
    glint_ndf_rivals r;
    for (int k = 0; k < 24; ++k) {
        r.q[k] = vec2(real(0));
        r.before[k] = false;
    }
    r.inner = real(3.4e38);
    return r;
}

// Whether copy c owns the surface point x, exactly as glint_ndf_owner decides (the same squared
// distances, the same ties), but without hashing: certain within the inner radius, impossible
// beyond the reach, else against the rivals.
GLINT_FN bool glint_ndf_copy_owns(glint_ndf_placement pl, glint_ndf_copy c, glint_ndf_rivals r, vec2 x) {
    vec2 e = x - c.anchor;
    real r2 = dot(e, e);
    if (r2 <= r.inner) return true;
    real reach = GLINT_NDF_OWNER_REACH * pl.cell;
    if (r2 > reach * reach) return false;
    GLINT_PRECISE real ex = x.x - c.anchor.x;
    GLINT_PRECISE real ey = x.y - c.anchor.y;
    GLINT_PRECISE real own = ex * ex + ey * ey;
    for (int k = 0; k < 24; ++k) {
        GLINT_PRECISE real dx = x.x - r.q[k].x;
        GLINT_PRECISE real dy = x.y - r.q[k].y;
        GLINT_PRECISE real d = dx * dx + dy * dy;
        if (d < own || (d == own && r.before[k])) return false;
    }
    return true;
}

// ---------------------------------------------------------------------------------------------
// Level of detail.

// The continuous level of a footprint whose example-frame covariance is cov: tiles of
// 2^(level+1) texels no wider than tau x its minor sd, and (one level coarser than needed, so
// that the finer of two blended levels keeps within it) at most max_tiles of them in the
// culling ellipse, about pi cull^2 sqrt(det(Sigma + sigma_h^2 I)) / t^2.
GLINT_FN real glint_ndf_level(glint_ndf_map_params p, vec4 cov) {
    vec2 l = glint_ndf_eigenvalues(cov);
    real h2 = p.el.sigma_h * p.el.sigma_h;
    real acc = log2(max(p.tau * sqrt(l.y), real(1e-30))) - real(1);
    real det = cov.w + h2 * (cov.x + cov.z) + h2 * h2;
    real t_cap = p.cull * sqrt(GLINT_PI * sqrt(det) / real(p.max_tiles));
    real cap = log2(max(t_cap, real(1e-30)));
    return max(acc, cap);
}

// ---------------------------------------------------------------------------------------------
// A tile or element loop's running sums, and what a draw chose.
struct glint_ndf_sum {
    real num;     // sum of W (density factor) B(s_ex)
    real den;     // sum of W
    real mass;    // sum of W x the tile's mass
    int tiles;
    real target;  // GLINT_NDF_SELECT: the mass to pass
    bool found;
    int layer;    // the chosen tile's layer, or -1 for an element
    vec2 u;       // the chosen element's lattice position
    ivec2 cell;   // the chosen copy's cell
};

GLINT_FN glint_ndf_sum glint_ndf_empty_sum(real target) {
    glint_ndf_sum a;
    a.num = real(0);
    a.den = real(0);
    a.mass = real(0);
    a.tiles = 0;
    a.target = target;
    a.found = false;
    a.layer = -1;
    a.u = vec2(real(0));
    a.cell = ivec2(0);
    return a;
}

#if defined(GLINT_NDF_FETCH)

// A layer's (B, B_x, B_y) at s_ex: bilinear between bin centres, 0 outside the window.
GLINT_FN vec3 glint_ndf_image(GLINT_NDF_DATA_PARAM glint_ndf_map_params p, int layer, vec2 s_ex) {
    real w = real(p.res);
    vec2 x = (s_ex - p.s_min) / p.s_bin;
    if (!(x.x >= real(0) && x.y >= real(0) && x.x <= w && x.y <= w)) return vec3(real(0));
    x = clamp(x - vec2(real(0.5)), vec2(real(0)), vec2(w - real(1)));
    vec2 f0 = floor(x);
    ivec2 i0 = ivec2(f0);
    ivec2 i1 = min(i0 + ivec2(1), ivec2(p.res - 1));
    vec2 f = x - f0;
    vec4 v00 = GLINT_NDF_FETCH(layer, i0.x, i0.y, p.res);
    vec4 v10 = GLINT_NDF_FETCH(layer, i1.x, i0.y, p.res);
    vec4 v01 = GLINT_NDF_FETCH(layer, i0.x, i1.y, p.res);
    vec4 v11 = GLINT_NDF_FETCH(layer, i1.x, i1.y, p.res);
    vec3 a = mix(vec3(v00.x, v00.y, v00.z), vec3(v10.x, v10.y, v10.z), f.x);
    vec3 b = mix(vec3(v01.x, v01.y, v01.z), vec3(v11.x, v11.y, v11.z), f.x);
    return mix(a, b, f.y);
}

// A tile's mass: the last entry of its running sum.
GLINT_FN real glint_ndf_tile_mass(GLINT_NDF_DATA_PARAM glint_ndf_map_params p, int layer) {
    return GLINT_NDF_FETCH(layer, p.res - 1, p.res - 1, p.res).w;
}

// A layer's running sum at flat bin index k (row-major).
GLINT_FN real glint_ndf_running_mass(GLINT_NDF_DATA_PARAM glint_ndf_map_params p, int layer, int k) {
    int y = k / p.res;
    return GLINT_NDF_FETCH(layer, k - y * p.res, y, p.res).w;
}

// The tiles of level l of copy c whose centres lie in the culling ellipse of the example-frame
// footprint (mu, cov) (and, with `owned`, whose centres the copy owns, within box = the copy's
// reach in example texels, (x0, y0, x1, y1)), each weighted by `factor` times its footprint mass,
//   W = t^2 N(centre; mu, Sigma + (sigma_h^2 + t^2 / 12) I) window(m),
// the Gaussian smoothed by the tile's box (its variance t^2 / 12) and the seeds (sigma_h^2), m the
// centre's Mahalanobis distance squared. Rows are clipped to the ellipse, so the cost follows the
// tiles in it; at most p.max_tiles tiles.
GLINT_FN glint_ndf_sum glint_ndf_level_sum(GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl, glint_ndf_copy c, bool owned,
                                           glint_ndf_rivals rv, vec4 box, int l, real factor, vec2 mu, vec4 cov, vec2 s_ex, real jac, int mode, glint_ndf_sum acc) {
    real t = real(1 << (l + 1));
    int m = p.n >> (l + 1);
    int first = glint_ndf_level_first(p.n, l);
    real h2 = p.el.sigma_h * p.el.sigma_h + t * t / real(12);
    real det = cov.w + h2 * (cov.x + cov.z) + h2 * h2;
    real qxx = (cov.z + h2) / det;
    real qxy = -cov.y / det;
    real qyy = (cov.x + h2) / det;
    real c2 = p.cull * p.cull;
    real norm = factor * t * t * GLINT_INV_TWO_PI / sqrt(det);
    // The elements' weights: log w has gradient -(Sigma + sigma_h^2 I)^-1 (u - mu).
    real e2 = p.el.sigma_h * p.el.sigma_h;
    real det_e = cov.w + e2 * (cov.x + cov.z) + e2 * e2;
    real gxx = (cov.z + e2) / det_e;
    real gxy = -cov.y / det_e;
    real gyy = (cov.x + e2) / det_e;
    real ey = p.cull * sqrt(cov.z + h2);
    real y0 = mu.y - ey;
    real y1 = mu.y + ey;
    if (owned) {
        y0 = max(y0, box.y);
        y1 = min(y1, box.w);
    }
    int ty0 = glint_ndf_index(ceil(y0 / t - real(0.5)));
    int ty1 = min(glint_ndf_index(floor(y1 / t - real(0.5))), ty0 + 4 * p.max_tiles);
    for (int ty = ty0; ty <= ty1 && acc.tiles < p.max_tiles; ++ty) {
        real dy = (real(ty) + real(0.5)) * t - mu.y;
        real disc = qxy * qxy * dy * dy - qxx * (qyy * dy * dy - c2);
        if (!(disc > real(0))) continue;
        real r = sqrt(disc);
        real x0 = mu.x + (-qxy * dy - r) / qxx;
        real x1 = mu.x + (-qxy * dy + r) / qxx;
        if (owned) {
            x0 = max(x0, box.x);
            x1 = min(x1, box.z);
        }
        int tx0 = glint_ndf_index(ceil(x0 / t - real(0.5)));
        int tx1 = glint_ndf_index(floor(x1 / t - real(0.5)));
        for (int tx = tx0; tx <= tx1 && acc.tiles < p.max_tiles; ++tx) {
            vec2 centre = (vec2(real(tx), real(ty)) + vec2(real(0.5))) * t;
            if (owned && !glint_ndf_copy_owns(pl, c, rv, c.anchor + glint_ndf_mul(c.a, centre - c.offset))) continue;
            vec2 d = centre - mu;
            real q = qxx * d.x * d.x + real(2) * qxy * d.x * d.y + qyy * d.y * d.y;
            real w = norm * exp(real(-0.5) * q) * glint_pndf_window(q, p.cull);
            acc.tiles += 1;
            int layer = first + glint_pndf_wrap(tx, m) + m * glint_pndf_wrap(ty, m);
            acc.den += w;
            if (mode == GLINT_NDF_EVAL || mode == GLINT_NDF_DENSITY) {
                if (w > real(0)) {
                    vec3 b = glint_ndf_image(GLINT_NDF_DATA_ARG p, layer, s_ex);
                    real v = b.x;
                    if (mode == GLINT_NDF_EVAL) {
                        // t g, capped at |t g|_1 <= 2 so that the term stays >= 0 (|B_x|, |B_y| <= B / 2).
                        vec2 tg = -t * vec2(gxx * d.x + gxy * d.y, gxy * d.x + gyy * d.y);
                        real l1 = abs(tg.x) + abs(tg.y);
                        if (l1 > real(2)) tg = tg * (real(2) / l1);
                        v = max(b.x + tg.x * b.y + tg.y * b.z, real(0));
                    }
                    acc.num += w * jac * v;
                }
            } else {
                acc.mass += w * glint_ndf_tile_mass(GLINT_NDF_DATA_ARG p, layer);
                if (mode == GLINT_NDF_SELECT && !acc.found && acc.mass > acc.target) {
                    acc.found = true;
                    acc.layer = layer;
                    acc.cell = c.cell;
                }
            }
        }
    }
    return acc;
}

#if defined(GLINT_HAS_NDF_ELEMENTS)
// The elements of copy c in the culling box of the example-frame footprint (mu, cov) (with
// `owned`: those whose lattice positions the copy owns), each term times factor and the density
// factor jac: Eq. 6 on the example's elements. EVAL adds the P-NDF to num; MASS and SELECT add the
// elements' weights to mass (each term integrates to its weight).
GLINT_FN glint_ndf_sum glint_ndf_element_sum(GLINT_ELEMENT_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl, glint_ndf_copy c, bool owned,
                                             glint_ndf_rivals rv, vec4 box, real factor, vec2 mu, vec4 cov, vec2 s_ex, real jac, int mode, glint_ndf_sum acc) {
    glint_pndf_params e = p.el;
    glint_pndf_frame f = glint_pndf_prepare(mu, cov, e.sigma_h, e.cull_u, e.cull_s);
    real x0 = f.mean.x - f.extent.x;
    real x1 = f.mean.x + f.extent.x;
    real y0 = f.mean.y - f.extent.y;
    real y1 = f.mean.y + f.extent.y;
    if (owned) {
        x0 = max(x0, box.x);
        x1 = min(x1, box.z);
        y0 = max(y0, box.y);
        y1 = min(y1, box.w);
    }
    ivec2 rx = glint_pndf_axis_range(real(0.5) * (x0 + x1), real(0.5) * (x1 - x0), e.spacing, e.max_side);
    ivec2 ry = glint_pndf_axis_range(real(0.5) * (y0 + y1), real(0.5) * (y1 - y0), e.spacing, e.max_side);
    for (int j = ry.x; j <= ry.y; ++j) {
        int wj = glint_pndf_wrap(j, e.height);
        for (int i = rx.x; i <= rx.y; ++i) {
            vec2 u_i = vec2((real(i) + real(0.5)) * e.spacing, (real(j) + real(0.5)) * e.spacing);
            if (owned && !glint_ndf_copy_owns(pl, c, rv, c.anchor + glint_ndf_mul(c.a, u_i - c.offset))) continue;
            int index = glint_pndf_wrap(i, e.width) + e.width * wj;
            acc.tiles += 1;
            // Owned elements are not a lattice: their weights sum to 1 only on average, so the
            // part is normalised by them (glint_ndf_shares).
            if (owned) acc.den += factor * glint_pndf_element_weight(u_i, f, e);
            if (mode == GLINT_NDF_EVAL || mode == GLINT_NDF_DENSITY) {
                acc.num += factor * jac * glint_pndf_element(glint_pndf_load(GLINT_ELEMENT_DATA_ARG index), u_i, f, s_ex, e);
            } else {
                acc.mass += factor * glint_pndf_element_weight(u_i, f, e);
                if (mode == GLINT_NDF_SELECT && !acc.found && acc.mass > acc.target) {
                    acc.found = true;
                    acc.layer = -1;
                    acc.u = u_i;
                    acc.cell = c.cell;
                }
            }
        }
    }
    return acc;
}
#endif

// ---------------------------------------------------------------------------------------------
// The P-NDF of a footprint: which paths and levels it takes, and their blend.

struct glint_ndf_plan {
    vec2 mu;       // the footprint (global texels), clamped in anisotropy (and, stochastic, in size)
    vec4 cov;
    real direct;   // the element path's share, 1 below direct_below, 0 from twice it
    int level;     // the finer of the two blended levels
    real alpha;    // the coarser one's share
    real whole;    // stochastic: the share of whole copies (footprints of a quarter to half a cell)
    ivec4 cells;   // stochastic: the cells whose copies can own part of the footprint (x0, y0, x1, y1)
    vec2 ext;      // stochastic: the culling box's half-extent (global texels)
};

// The reference copy's example-frame covariance: A0's (tiled) or, stochastic, A0 at the largest
// scale (the smallest example-frame footprint, so the level suits every copy).
GLINT_FN vec4 glint_ndf_reference_covariance(glint_ndf_placement pl, vec4 cov) {
    vec4 b = glint_ndf_inverse(pl.a);
    if (pl.kind == GLINT_NDF_STOCHASTIC) b = b / pl.scale.y;
    return glint_ndf_transform_covariance(b, cov);
}

GLINT_FN glint_ndf_plan glint_ndf_make_plan(glint_ndf_map_params p, glint_ndf_placement pl, vec2 mu, vec4 cov) {
    glint_ndf_plan r;
    bool finite = abs(mu.x) < real(1e30) && abs(mu.y) < real(1e30);
    r.mu = finite ? mu : vec2(real(0));
    r.cov = glint_ndf_clamp_anisotropy(cov);
    real cull = max(p.cull, p.el.cull_u);
    if (pl.kind == GLINT_NDF_STOCHASTIC) {
        // At most max_cells cells across the culling box: wider footprints see as many copies as
        // that (their P-NDF is then an average over max_cells^2 random copies).
        real limit = real(0.5) * real(pl.max_cells) * pl.cell;
        real ext = cull * sqrt(max(r.cov.x, r.cov.z) + pl.cell * pl.cell / real(12));
        if (ext > limit) {
            real k = (limit * limit) / (ext * ext);
            r.cov = vec4(r.cov.x * k, r.cov.y * k, r.cov.z * k, r.cov.w * k * k);
        }
    }
    vec4 ce = glint_ndf_reference_covariance(pl, r.cov);
    real sd = sqrt(glint_ndf_eigenvalues(ce).y);
    r.direct = real(1) - clamp((sd - p.direct_below) / p.direct_below, real(0), real(1));
    real lv = glint_ndf_level(p, ce);
    int top = p.levels - 1;
    if (pl.kind == GLINT_NDF_STOCHASTIC) {
        // Tiles at most half a cell (in the example at the largest scale): ownership is decided
        // per tile centre.
        real cap = log2(max(pl.cell / (real(2) * pl.scale.y), real(1e-30))) - real(1);
        lv = min(lv, cap);
        top = glint_ndf_index(clamp(floor(cap), real(0), real(p.levels - 1)));
    }
    real fl = floor(lv);
    r.level = glint_ndf_index(clamp(fl, real(0), real(top)));
    r.alpha = real(0);
    if (fl >= real(0) && r.level < top) r.alpha = clamp((lv - fl - (real(1) - p.blend)) / p.blend, real(0), real(1));
    r.whole = real(0);
    r.cells = ivec4(0);
    r.ext = vec2(real(0));
    if (pl.kind == GLINT_NDF_STOCHASTIC) {
        real g = sqrt(glint_ndf_eigenvalues(r.cov).y);
        real q = real(0.25) * pl.cell;
        r.whole = clamp((g - q) / q, real(0), real(1));
        vec2 ext = vec2(cull) * sqrt(vec2(r.cov.x, r.cov.z) + vec2(pl.cell * pl.cell / real(12)));
        r.ext = ext;
        // Anchors lie in their cells' central half; one can own points of the box only within
        // GLINT_NDF_OWNER_REACH cells of it: cells j with (j + 3/4) c >= lo - reach, (j + 1/4) c <= hi + reach.
        real reach = GLINT_NDF_OWNER_REACH + real(0.75);
        r.cells = ivec4(glint_ndf_index(ceil((r.mu.x - ext.x) / pl.cell - reach)), glint_ndf_index(ceil((r.mu.y - ext.y) / pl.cell - reach)),
                        glint_ndf_index(floor((r.mu.x + ext.x) / pl.cell + reach - real(0.5))),
                        glint_ndf_index(floor((r.mu.y + ext.y) / pl.cell + reach - real(0.5))));
    }
    return r;
}

// A copy's share of a wide footprint: cell^2 N(anchor; mu, Sigma + cell^2 / 12 I) window (its
// Voronoi cell's mass, the cell taken as a box of the grid's cell size).
GLINT_FN real glint_ndf_copy_weight(glint_ndf_map_params p, glint_ndf_placement pl, vec2 anchor, vec2 mu, vec4 cov) {
    real h2 = pl.cell * pl.cell / real(12);
    real det = cov.w + h2 * (cov.x + cov.z) + h2 * h2;
    vec2 d = anchor - mu;
    real q = ((cov.z + h2) * d.x * d.x - real(2) * cov.y * d.x * d.y + (cov.x + h2) * d.y * d.y) / det;
    return pl.cell * pl.cell * GLINT_INV_TWO_PI / sqrt(det) * exp(real(-0.5) * q) * glint_pndf_window(q, p.cull);
}

// The example-frame footprint of copy c: mean (wrapped into the example for a tiled copy, which
// keeps float precision far from the origin) and covariance; and the box of example texels the
// copy can own (its anchor's reach, GLINT_NDF_OWNER_REACH cells, mapped by A^-1).
struct glint_ndf_local {
    vec2 mu;
    vec4 cov;
    vec4 box;
};
GLINT_FN glint_ndf_local glint_ndf_localize(glint_ndf_map_params p, glint_ndf_placement pl, glint_ndf_copy c, vec2 mu, vec4 cov) {
    glint_ndf_local r;
    r.mu = glint_ndf_mul(c.a_inv, mu - c.anchor) + c.offset;
    if (pl.kind == GLINT_NDF_TILED) r.mu = r.mu - real(p.n) * floor(r.mu / real(p.n));
    r.cov = glint_ndf_transform_covariance(c.a_inv, cov);
    real reach = GLINT_NDF_OWNER_REACH * pl.cell;
    vec2 h = reach * sqrt(vec2(c.a_inv.x * c.a_inv.x + c.a_inv.z * c.a_inv.z, c.a_inv.y * c.a_inv.y + c.a_inv.w * c.a_inv.w));
    r.box = vec4(c.offset - h, c.offset + h);
    return r;
}

#if defined(GLINT_HAS_NDF_ELEMENTS)
// The parts of the P-NDF: the element path, the two levels' tiles and (stochastic) the whole
// copies, each as a running sum over the copies; the P-NDF is glint_ndf_combine of them.
struct glint_ndf_parts {
    glint_ndf_sum direct;
    glint_ndf_sum fine;
    glint_ndf_sum coarse;
    glint_ndf_sum whole;
};

// A tiled layout's level at the top: one tiled example under the whole footprint, every top tile
// the same image, so the part is that image alone (weight 1; a draw always picks it).
GLINT_FN glint_ndf_sum glint_ndf_top_image(GLINT_NDF_DATA_PARAM glint_ndf_map_params p, ivec2 cell, vec2 s_ex, real jac, int mode, glint_ndf_sum acc) {
    int layer = glint_ndf_level_first(p.n, p.levels - 1);
    acc.den = real(1);
    if (mode == GLINT_NDF_EVAL || mode == GLINT_NDF_DENSITY) acc.num = jac * glint_ndf_image(GLINT_NDF_DATA_ARG p, layer, s_ex).x;
    else acc.mass = glint_ndf_tile_mass(GLINT_NDF_DATA_ARG p, layer);
    if (mode == GLINT_NDF_SELECT) {
        acc.found = true;
        acc.layer = layer;
        acc.cell = cell;
    }
    return acc;
}

// What one copy adds to each part that `select` (-1: all) names: 0 direct, 1 fine, 2 coarse, 3 whole.
GLINT_FN glint_ndf_parts glint_ndf_copy_parts(GLINT_ELEMENT_DATA_PARAM GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl,
                                              glint_ndf_plan plan, glint_ndf_copy c, vec2 s, int mode, int select, glint_ndf_parts a) {
    vec3 se = glint_ndf_to_example_slope(c.m, s);
    vec2 s_ex = vec2(se.x, se.y);
    bool owned = pl.kind == GLINT_NDF_STOCHASTIC;
    glint_ndf_local lc = glint_ndf_localize(p, pl, c, plan.mu, plan.cov);
    bool tiles = plan.direct < real(1) && plan.whole < real(1);
    int top = p.levels - 1;
    bool searched = owned && (plan.direct > real(0) || tiles);
    glint_ndf_rivals rv = searched ? glint_ndf_make_rivals(pl, c) : glint_ndf_no_rivals();
    if (plan.direct > real(0) && (select < 0 || select == 0))
        a.direct = glint_ndf_element_sum(GLINT_ELEMENT_DATA_ARG p, pl, c, owned, rv, lc.box, real(1), lc.mu, lc.cov, s_ex, se.z, mode, a.direct);
    if (tiles && (select < 0 || select == 1)) {
        if (!owned && plan.level == top) {
            a.fine = glint_ndf_top_image(GLINT_NDF_DATA_ARG p, c.cell, s_ex, se.z, mode, a.fine);
        } else {
            a.fine = glint_ndf_level_sum(GLINT_NDF_DATA_ARG p, pl, c, owned, rv, lc.box, plan.level, real(1), lc.mu, lc.cov, s_ex, se.z, mode, a.fine);
        }
    }
    if (tiles && plan.alpha > real(0) && (select < 0 || select == 2)) {
        if (!owned && plan.level + 1 == top) {
            a.coarse = glint_ndf_top_image(GLINT_NDF_DATA_ARG p, c.cell, s_ex, se.z, mode, a.coarse);
        } else {
            a.coarse = glint_ndf_level_sum(GLINT_NDF_DATA_ARG p, pl, c, owned, rv, lc.box, plan.level + 1, real(1), lc.mu, lc.cov, s_ex, se.z, mode, a.coarse);
        }
    }
    if (owned && plan.direct < real(1) && plan.whole > real(0) && (select < 0 || select == 3)) {
        real w = glint_ndf_copy_weight(p, pl, c.anchor, plan.mu, plan.cov);
        int layer = glint_ndf_level_first(p.n, top);
        a.whole.den += w;
        a.whole.tiles += 1;
        if (mode == GLINT_NDF_EVAL || mode == GLINT_NDF_DENSITY) {
            if (w > real(0)) a.whole.num += w * se.z * glint_ndf_image(GLINT_NDF_DATA_ARG p, layer, s_ex).x;
        } else {
            a.whole.mass += w * glint_ndf_tile_mass(GLINT_NDF_DATA_ARG p, layer);
            if (mode == GLINT_NDF_SELECT && !a.whole.found && a.whole.mass > a.whole.target) {
                a.whole.found = true;
                a.whole.layer = layer;
                a.whole.cell = c.cell;
            }
        }
    }
    return a;
}

// The parts summed over the plan's copies.
GLINT_FN glint_ndf_parts glint_ndf_all_parts(GLINT_ELEMENT_DATA_PARAM GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl,
                                             glint_ndf_plan plan, vec2 s, int mode, int select, glint_ndf_parts a) {
    if (pl.kind == GLINT_NDF_TILED)
        return glint_ndf_copy_parts(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, plan, glint_ndf_tiled_copy(pl), s, mode, select, a);
    real reach = GLINT_NDF_OWNER_REACH * pl.cell;
    for (int cy = plan.cells.y; cy <= plan.cells.w; ++cy)
        for (int cx = plan.cells.x; cx <= plan.cells.z; ++cx) {
            // Whole copies weigh every anchor; the other parts only those whose reach meets the box.
            vec2 d = abs(glint_ndf_cell_anchor(pl, ivec2(cx, cy)) - plan.mu);
            if (plan.whole == real(0) && (d.x > plan.ext.x + reach || d.y > plan.ext.y + reach)) continue;
            a = glint_ndf_copy_parts(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, plan, glint_ndf_cell_copy(pl, ivec2(cx, cy), p.n), s, mode, select, a);
        }
    return a;
}

GLINT_FN glint_ndf_parts glint_ndf_empty_parts() {
    glint_ndf_parts a;
    a.direct = glint_ndf_empty_sum(real(0));
    a.fine = glint_ndf_empty_sum(real(0));
    a.coarse = glint_ndf_empty_sum(real(0));
    a.whole = glint_ndf_empty_sum(real(0));
    return a;
}

// The parts' shares of the P-NDF: direct, fine, coarse, whole (each map part, and a stochastic
// layout's element part, divided by its weight sum; a tiled element part is the direct P-NDF as it
// stands, whose mass is 1 up to the lattice's Poisson ripple, glint/gaussian.hpp).
GLINT_FN vec4 glint_ndf_shares(glint_ndf_placement pl, glint_ndf_plan plan, glint_ndf_parts a) {
    real map = real(1) - plan.direct;
    real tiles = map * (real(1) - plan.whole);
    real direct = plan.direct;
    if (pl.kind == GLINT_NDF_STOCHASTIC) direct = a.direct.den > real(0) ? plan.direct / a.direct.den : real(0);
    return vec4(direct, a.fine.den > real(0) ? tiles * (real(1) - plan.alpha) / a.fine.den : real(0),
                a.coarse.den > real(0) ? tiles * plan.alpha / a.coarse.den : real(0), a.whole.den > real(0) ? map * plan.whole / a.whole.den : real(0));
}

// D_P(s) of the footprint N(mu, cov) (global texels; cov = (xx, xy, yy, det)), a density over the
// projected disk; 0 for |s| >= 1. `mode` EVAL: first-order tiles; DENSITY: zero-order (sampling).
GLINT_FN real glint_ndf_pndf_mode(GLINT_ELEMENT_DATA_PARAM GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl, vec2 mu, vec4 cov, vec2 s, int mode) {
    if (!(dot(s, s) < real(1))) return real(0);
    glint_ndf_plan plan = glint_ndf_make_plan(p, pl, mu, cov);
    glint_ndf_parts a = glint_ndf_all_parts(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, plan, s, mode, -1, glint_ndf_empty_parts());
    vec4 k = glint_ndf_shares(pl, plan, a);
    return max(k.x * a.direct.num + k.y * a.fine.num + k.z * a.coarse.num + k.w * a.whole.num, real(0));
}

GLINT_FN real glint_ndf_pndf(GLINT_ELEMENT_DATA_PARAM GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl, vec2 mu, vec4 cov, vec2 s) {
    return glint_ndf_pndf_mode(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, mu, cov, s, GLINT_NDF_EVAL);
}

// The P-NDF's mass over s (the integral of glint_ndf_pndf, before the disk's edge cuts it): the
// normaliser of glint_ndf_sample's density.
GLINT_FN real glint_ndf_mass(GLINT_ELEMENT_DATA_PARAM GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl, vec2 mu, vec4 cov) {
    glint_ndf_plan plan = glint_ndf_make_plan(p, pl, mu, cov);
    glint_ndf_parts a = glint_ndf_all_parts(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, plan, vec2(real(0)), GLINT_NDF_MASS, -1, glint_ndf_empty_parts());
    vec4 k = glint_ndf_shares(pl, plan, a);
    return k.x * a.direct.mass + k.y * a.fine.mass + k.z * a.coarse.mass + k.w * a.whole.mass;
}

// One axis of a draw from a bin's bilinear basis function (a tent of one bin's half-width each
// side; at the window's edges flat over the outer half bin): the offset from the bin's centre, in
// bins, from a uniform u.
GLINT_FN real glint_ndf_tent(real u, int i, int res) {
    if (i == 0 && u < real(0.5)) return u - real(0.5);
    if (i == res - 1 && u >= real(0.5)) return u - real(0.5);
    return u < real(0.5) ? sqrt(real(2) * u) - real(1) : real(1) - sqrt(real(2) * (real(1) - u));
}

struct glint_ndf_draw {
    vec2 s;
    real pdf_s;  // density of s per unit disk area
    bool valid;
};

// A half vector's disk point from the P-NDF: a part by its mass, a tile (or element, or copy) by
// its share of that part (two passes over the same loops), then s_ex from the tile's bilinear image
// (a bin by the running sum, u1's remainder within the bin and u2 for the tent) or the element's
// lobe (truncated at cull_s, as the element term is), mapped back through the copy. The density
// of s is exactly the zero-order P-NDF (mode DENSITY) over glint_ndf_mass, which is positive
// wherever glint_ndf_pndf is; valid is false where the draw leaves the disk.
GLINT_FN glint_ndf_draw glint_ndf_sample(GLINT_ELEMENT_DATA_PARAM GLINT_NDF_DATA_PARAM glint_ndf_map_params p, glint_ndf_placement pl, vec2 mu, vec4 cov,
                                         real u0, real u1, real u2) {
    glint_ndf_draw r;
    r.s = vec2(real(0));
    r.pdf_s = real(0);
    r.valid = false;
    glint_ndf_plan plan = glint_ndf_make_plan(p, pl, mu, cov);
    glint_ndf_parts a = glint_ndf_all_parts(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, plan, vec2(real(0)), GLINT_NDF_MASS, -1, glint_ndf_empty_parts());
    vec4 k = glint_ndf_shares(pl, plan, a);
    vec4 pm = vec4(k.x * a.direct.mass, k.y * a.fine.mass, k.z * a.coarse.mass, k.w * a.whole.mass);
    real total = pm.x + pm.y + pm.z + pm.w;
    if (!(total > real(0))) return r;
    real x = u0 * total;
    int part = 3;
    if (x < pm.x) part = 0;
    else if (x < pm.x + pm.y) part = 1;
    else if (x < pm.x + pm.y + pm.z) part = 2;
    real before = part == 0 ? real(0) : part == 1 ? pm.x : part == 2 ? pm.x + pm.y : pm.x + pm.y + pm.z;
    real share = part == 0 ? pm.x : part == 1 ? pm.y : part == 2 ? pm.z : pm.w;
    real raw = part == 0 ? a.direct.mass : part == 1 ? a.fine.mass : part == 2 ? a.coarse.mass : a.whole.mass;
    real target = clamp((x - before) / share, real(0), real(1)) * raw;
    glint_ndf_parts b = glint_ndf_empty_parts();
    b.direct.target = target;
    b.fine.target = target;
    b.coarse.target = target;
    b.whole.target = target;
    b = glint_ndf_all_parts(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, plan, vec2(real(0)), GLINT_NDF_SELECT, part, b);
    glint_ndf_sum chosen = part == 0 ? b.direct : part == 1 ? b.fine : part == 2 ? b.coarse : b.whole;
    if (!chosen.found) return r;
    glint_ndf_copy c = pl.kind == GLINT_NDF_TILED ? glint_ndf_tiled_copy(pl) : glint_ndf_cell_copy(pl, chosen.cell, p.n);
    vec2 s_ex = vec2(real(0));
    if (chosen.layer >= 0) {
        // The bin: the first whose running sum passes u1 x the tile's mass.
        int count = p.res * p.res;
        real want = u1 * glint_ndf_tile_mass(GLINT_NDF_DATA_ARG p, chosen.layer);
        int lo = 0;
        int hi = count - 1;
        while (lo < hi) {
            int mid = (lo + hi) / 2;
            if (glint_ndf_running_mass(GLINT_NDF_DATA_ARG p, chosen.layer, mid) > want) hi = mid;
            else lo = mid + 1;
        }
        int by = lo / p.res;
        int bx = lo - by * p.res;
        real c1 = glint_ndf_running_mass(GLINT_NDF_DATA_ARG p, chosen.layer, lo);
        real c0 = lo > 0 ? glint_ndf_running_mass(GLINT_NDF_DATA_ARG p, chosen.layer, lo - 1) : real(0);
        real v = c1 > c0 ? clamp((want - c0) / (c1 - c0), real(0), real(0.99999994)) : real(0.5);
        s_ex = p.s_min + (vec2(real(bx), real(by)) + vec2(real(0.5)) + vec2(glint_ndf_tent(v, bx, p.res), glint_ndf_tent(u2, by, p.res))) * p.s_bin;
    } else {
        // The element's lobe N(mean, C) in the copy's example frame, truncated at cull_s.
        glint_ndf_local lc = glint_ndf_localize(p, pl, c, plan.mu, plan.cov);
        glint_pndf_params e = p.el;
        glint_pndf_frame f = glint_pndf_prepare(lc.mu, lc.cov, e.sigma_h, e.cull_u, e.cull_s);
        int i = glint_ndf_index(floor(chosen.u.x / e.spacing));
        int j = glint_ndf_index(floor(chosen.u.y / e.spacing));
        glint_gaussian_element el = glint_pndf_load(GLINT_ELEMENT_DATA_ARG glint_pndf_wrap(i, e.width) + e.width * glint_pndf_wrap(j, e.height));
        glint_pndf_lobe l = glint_pndf_element_lobe(el, chosen.u, f, e);
        real sr = max(e.sigma_r, GLINT_GAUSSIAN_MIN_SIGMA_R);
        real c11 = sr * sr + l.b.x * l.b.x + l.b.z * l.b.z;
        real c12 = l.b.x * l.b.y + l.b.z * l.b.w;
        real l11 = sqrt(c11);
        real l21 = c12 / l11;
        real l22 = sqrt(max(l.det_c / c11, real(0)));
        real rho = sqrt(max(real(-2) * glint_log1p(-u1 * glint_pndf_kept_mass(e.cull_s)), real(0)));
        real phi = real(2) * GLINT_PI * u2;
        real z1 = rho * cos(phi);
        real z2 = rho * sin(phi);
        s_ex = l.mean + vec2(l11 * z1, l21 * z1 + l22 * z2);
    }
    if (!(dot(s_ex, s_ex) < real(1))) return r;
    r.s = glint_ndf_from_example_slope(c.m_inv, s_ex);
    if (!(dot(r.s, r.s) < real(1))) return r;
    r.pdf_s = glint_ndf_pndf_mode(GLINT_ELEMENT_DATA_ARG GLINT_NDF_DATA_ARG p, pl, mu, cov, r.s, GLINT_NDF_DENSITY) / total;
    r.valid = r.pdf_s > real(0);
    return r;
}
#endif

#endif

// XTXW24 Eq. 10: a clear coat over a base, f = f_b (1 - F_c) + f_c, each layer's BRDF from its own
// P-NDF value (XTXW24 Eq. 1, glint_pndf_brdf) and Smith roughness; the coat is a dielectric of
// index eta_c (F_c: the exact dielectric Fresnel at the half vector, glint_fresnel_conductor with
// k = 0), the base a conductor (eta_b, k_b).
GLINT_FN real glint_ndf_coated_brdf(real d_base, real d_coat, vec3 wi, vec3 wo, vec2 alpha_base, vec2 alpha_coat, real eta_b, real k_b, real eta_c) {
    if (!(wi.z > real(0)) || !(wo.z > real(0))) return real(0);
    vec3 h = normalize(wi + wo);
    if (!(h.z > real(0))) return real(0);
    real fc = glint_fresnel_conductor(eta_c, real(0), dot(wi, h));
    real base = glint_pndf_brdf(d_base, wi, wo, GLINT_NDF_BECKMANN, alpha_base, eta_b, k_b);
    real coat = glint_pndf_brdf(d_coat, wi, wo, GLINT_NDF_BECKMANN, alpha_coat, eta_c, real(0));
    return base * (real(1) - fc) + coat;
}

#undef GLINT_HAS_NDF_ELEMENTS
