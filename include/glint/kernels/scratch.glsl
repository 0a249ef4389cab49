// glint's scratched materials (RGB16): the cone parametrization (Sec. 4.1, Eq. 1), the scratch
// BRDF from its 2D table (Eq. 2), importance sampling of the reflection cone (Sec. 5.1, Eq. 5),
// point lights through a normalised kernel (Sec. 5.2, Eq. 6), the layer mix of the SV-BRDF
// (Sec. 4.3, Eq. 3-4) and the procedural scratch indicator (Sec. 5.3, Eq. 7). Needs core.glsl. The
// host side (profiles, the ray-traced table, layer distributions) is in include/glint/scratch.hpp.
//
// Frame. u is the groove's direction (the tangent, made orthogonal to n), v = n x u. A direction
// w has cone coordinates theta = asin(w.u) (latitude about u) and phi = atan2(w.v, w.n) (RGB16
// Eq. 1's parametrization); |phi| <= pi/2 exactly where w.n >= 0. Highlights streak across u.
//
// Table (one vec4 buffer, read through GLINT_SCRATCH_FETCH(k): in C++ a pointer parameter, in GLSL
// an SSBO `glint_scratch_data` when GLINT_SCRATCH_BINDING is defined, or any vec4 fetch the user
// defines before including this file, e.g. a texelFetch). M bins of equal width pi/M over phi in
// [-pi/2, pi/2], edges a_j = -pi/2 + j pi/M. Layout:
//   [0]                          (M, 0, 0, 0)
//   [1 + o]                      (A_o, 0, 0, 0): row o's albedo sum_i rho_m[o][i] ds_i
//   [1 + M + 2 (o M + i)]        (rho_m, rho_0.r, rho_0.g, rho_0.b)
//   [1 + M + 2 (o M + i) + 1]    (gamma.r, gamma.g, gamma.b, cdf[o][i])
// rho values are per unit of ds = d(sin phi) (the projected measure; ds_i = sin a_{i+1} - sin a_i),
// row o is phi_o's bin and column i phi_i's; cdf[o][i] is sum_{j <= i} rho_m[o][j] ds_j / A_o.
//
// Radiance. The 3D scratch BRDF is rho_s delta(theta_i + theta_o) / cos^2 theta_o, so one scratch
// reflects L_r(w_o) = int rho_s(theta_o, phi_o, phi) L_i(-theta_o, phi) cos phi dphi (RGB16 Eq. 5's
// integral): a singular lobe, so these kernels return radiance estimates and samples, never a
// pointwise BRDF value.

#if defined(GLINT_GLSL) && !defined(GLINT_SCRATCH_FETCH)
#if defined(GLINT_SCRATCH_BINDING) && !defined(GLINT_SCRATCH_BUFFER_DECLARED)
layout(std430, binding = GLINT_SCRATCH_BINDING) readonly buffer glint_scratch_buffer { vec4 glint_scratch_data[]; };
#define GLINT_SCRATCH_BUFFER_DECLARED
#endif
#if defined(GLINT_SCRATCH_BUFFER_DECLARED)
#define GLINT_SCRATCH_FETCH(k) glint_scratch_data[k]
#endif
#endif

GLINT_CONST(real) GLINT_HALF_PI = real(1.57079632679489661923);  // pi / 2, 21 digits
GLINT_CONST(int) GLINT_SCRATCH_MAX_LAYERS = 64;
GLINT_CONST(int) GLINT_SCRATCH_MAX_LIGHT_SAMPLES = 32;
GLINT_CONST(int) GLINT_SCRATCH_NEAREST = 0;
GLINT_CONST(int) GLINT_SCRATCH_LINEAR = 1;

struct glint_scratch_frame {
    vec3 n;
    vec3 u;  // the groove direction
    vec3 v;  // n x u
};

// asin(x) = atan2(x, sqrt((1 - x)(1 + x))), x clamped to [-1, 1] (as glint_acos).
GLINT_FN real glint_asin(real x) {
    real c = clamp(x, real(-1), real(1));
    return glint_atan2(c, sqrt((real(1) - c) * (real(1) + c)));
}

// The frame of a scratch with normal n and tangent t. n is normalised (a zero or non-finite n
// gives +z); t loses its component along n (two Gram-Schmidt passes: one leaves float's rounding
// of a t nearly parallel to n in the result). Where t is zero, non-finite or within 1e-6 of
// parallel to n, u falls back to Duff et al. 2017's branchless basis of n (documented fallback).
GLINT_FN glint_scratch_frame glint_scratch_make_frame(vec3 n, vec3 t) {
    glint_scratch_frame f;
    real ln = length(n);
    f.n = (ln > real(0) && ln < real(3.4e38)) ? n / ln : vec3(real(0), real(0), real(1));
    real lt = length(t);
    vec3 p = t - dot(t, f.n) * f.n;
    p = p - dot(p, f.n) * f.n;
    real lp = length(p);
    if (lt > real(0) && lt < real(3.4e38) && lp > real(1e-6) * lt) {
        f.u = p / lp;
    } else {
        real sgn = (f.n.z >= real(0)) ? real(1) : real(-1);
        real a = real(-1) / (sgn + f.n.z);
        real b = f.n.x * f.n.y * a;
        f.u = vec3(real(1) + sgn * f.n.x * f.n.x * a, sgn * b, -sgn * f.n.x);
    }
    f.v = cross(f.n, f.u);
    return f;
}

// (theta, phi) of a direction (RGB16 Eq. 1): theta in [-pi/2, pi/2], phi in [-pi, pi]; theta as
// atan2(w.u, |w - (w.u) u|), which keeps its precision near the poles w = +-u, where asin does not.
// w need not be unit.
GLINT_FN vec2 glint_scratch_to_cone(glint_scratch_frame f, vec3 w) {
    real a = dot(w, f.u), b = dot(w, f.v), c = dot(w, f.n);
    return vec2(glint_atan2(a, sqrt(b * b + c * c)), glint_atan2(b, c));
}

// The unit direction of cone coordinates (theta, phi): sin(theta) u + cos(theta) (sin(phi) v +
// cos(phi) n).
GLINT_FN vec3 glint_scratch_from_cone(glint_scratch_frame f, vec2 tp) {
    real ct = cos(tp.x);
    return sin(tp.x) * f.u + ct * (sin(tp.y) * f.v + cos(tp.y) * f.n);
}

// The bin of phi among M, clamped to [0, M - 1].
GLINT_FN int glint_scratch_bin(real phi, int M) {
    real x = floor((phi + GLINT_HALF_PI) * (real(M) / GLINT_PI));
    return int(clamp(x, real(0), real(M - 1)));
}

// sin of bin i's lower edge, and its width in s = sin phi, 2 cos(centre) sin(pi / 2M) (no
// cancellation near the edges, where the width is of order 1/M^2).
GLINT_FN real glint_scratch_edge_sin(int i, int M) {
    return sin(-GLINT_HALF_PI + real(i) * (GLINT_PI / real(M)));
}
GLINT_FN real glint_scratch_bin_ds(int i, int M) {
    return real(2) * cos(-GLINT_HALF_PI + (real(i) + real(0.5)) * (GLINT_PI / real(M))) * sin(GLINT_HALF_PI / real(M));
}

// Eq. 2 with R_gamma = t^gamma, t = 2|theta| / pi in [0, 1]: R rho_m + (1 - R) rho_0 per channel.
GLINT_FN vec3 glint_scratch_eq2(vec4 a, vec4 b, real t) {
    vec3 r = vec3(real(0));
    if (t > real(0)) r = pow(vec3(t), vec3(b.x, b.y, b.z));
    return r * a.x + (vec3(real(1)) - r) * vec3(a.y, a.z, a.w);
}

// A table read by GLINT_SCRATCH_FETCH: everything below needs one.
#if defined(GLINT_SCRATCH_FETCH)

GLINT_FN int glint_scratch_texel_index(int M, int o, int i) {
    return 1 + M + 2 * (o * M + i);
}

// The rows (phi_o bins) a view reads and their weights: GLINT_SCRATCH_NEAREST the bin holding
// phi_o; GLINT_SCRATCH_LINEAR the two bin centres around phi_o, linearly (constant beyond the outer
// centres), so a moving view changes the reflection smoothly. Along phi_i both read the bin holding
// phi_i: a linear blend there would give rho_s values where the row's mirror table, and so the
// sampler's pdf, is 0, and Eq. 5's estimate would lose them.
struct glint_scratch_rows {
    int o0;
    int o1;
    real w1;  // weight of row o1; row o0 has 1 - w1
};

GLINT_FN glint_scratch_rows glint_scratch_rows_of(real phi_o, int M, int filter_mode) {
    glint_scratch_rows r;
    if (filter_mode == GLINT_SCRATCH_NEAREST) {
        r.o0 = glint_scratch_bin(phi_o, M);
        r.o1 = r.o0;
        r.w1 = real(0);
        return r;
    }
    real c = clamp((phi_o + GLINT_HALF_PI) * (real(M) / GLINT_PI) - real(0.5), real(0), real(M - 1));
    r.o0 = int(floor(c));
    r.o1 = min(r.o0 + 1, M - 1);
    r.w1 = c - real(r.o0);
    return r;
}

// rho_s(theta_o, phi_o, phi_i) (Eq. 2) from the table, rows as glint_scratch_rows_of; 0 where the
// table is empty.
GLINT_FN vec3 glint_scratch_rho(GLINT_SCRATCH_DATA_PARAM real theta_o, real phi_o, real phi_i, int filter_mode) {
    int M = int(GLINT_SCRATCH_FETCH(0).x);
    if (M < 1) return vec3(real(0));
    real t = min(abs(theta_o) * (real(2) / GLINT_PI), real(1));
    glint_scratch_rows r = glint_scratch_rows_of(phi_o, M, filter_mode);
    int i = glint_scratch_bin(phi_i, M);
    int k0 = glint_scratch_texel_index(M, r.o0, i), k1 = glint_scratch_texel_index(M, r.o1, i);
    vec3 a = glint_scratch_eq2(GLINT_SCRATCH_FETCH(k0), GLINT_SCRATCH_FETCH(k0 + 1), t);
    if (r.w1 == real(0)) return a;
    return mix(a, glint_scratch_eq2(GLINT_SCRATCH_FETCH(k1), GLINT_SCRATCH_FETCH(k1 + 1), t), r.w1);
}

// A direction drawn on the reflection cone theta_i = -theta_o (RGB16 Sec. 5.1, Eq. 5), and its
// Monte Carlo weight rho_s cos(phi_i) / pdf_phi: the estimator of L_r is weight * L_i(wi).
struct glint_scratch_sample {
    vec3 wi;
    vec3 weight;
    real phi_i;
    real pdf_phi;  // density of phi_i per radian
    bool valid;
};

// The probability of picking row o1 among the view's rows: its filter weight, rows that reflect
// nothing (albedo 0) left out. -1 where neither reflects.
GLINT_FN real glint_scratch_row_choice(glint_scratch_rows r, real a0, real a1) {
    real w0 = (a0 > real(0)) ? real(1) - r.w1 : real(0);
    real w1 = (a1 > real(0)) ? r.w1 : real(0);
    if (!(w0 + w1 > real(0))) return real(-1);
    return w1 / (w0 + w1);
}

// The row's density of phi (per radian): rho_m[o][bin(phi)] cos(phi) / A_o.
GLINT_FN real glint_scratch_row_pdf(GLINT_SCRATCH_DATA_PARAM int M, int o, real a, real phi) {
    if (!(a > real(0))) return real(0);
    return GLINT_SCRATCH_FETCH(glint_scratch_texel_index(M, o, glint_scratch_bin(phi, M))).x * cos(phi) / a;
}

// Eq. 5's sampler, with an exact pdf: one of the view's rows (glint_scratch_rows_of) by its weight,
// using u1 (rescaled after the choice); in it the bin i by binary search of the row's CDF with u1,
// then sin(phi) uniform in bin i with u2. The pdf is the mixture over the rows of rho_m[o][i]
// cos(phi) / A_o (RGB16's PDF_phi_o = rho_m cos phi, normalised), and the weight rho_s cos(phi) /
// pdf (the cosine cancels, as the paper notes; with one row, rho_s A_o / rho_m[o][i]). Invalid
// (weight 0) for wo below the horizon or rows that reflect nothing.
GLINT_FN glint_scratch_sample glint_scratch_sample_cone(GLINT_SCRATCH_DATA_PARAM glint_scratch_frame f, vec3 wo, real u1, real u2, int filter_mode) {
    glint_scratch_sample r;
    r.wi = f.n;
    r.weight = vec3(real(0));
    r.phi_i = real(0);
    r.pdf_phi = real(0);
    r.valid = false;
    int M = int(GLINT_SCRATCH_FETCH(0).x);
    if (M < 1 || !(dot(wo, f.n) > real(0))) return r;
    vec2 co = glint_scratch_to_cone(f, wo);
    glint_scratch_rows rows = glint_scratch_rows_of(co.y, M, filter_mode);
    real a0 = GLINT_SCRATCH_FETCH(1 + rows.o0).x, a1 = GLINT_SCRATCH_FETCH(1 + rows.o1).x;
    real p1 = glint_scratch_row_choice(rows, a0, a1);
    if (p1 < real(0)) return r;
    real x = clamp(u1, real(0), real(1));
    int o = rows.o0;
    if (x < p1) {
        o = rows.o1;
        x = x / p1;
    } else {
        x = (p1 > real(0)) ? (x - p1) / (real(1) - p1) : x;
    }
    // The first bin whose cumulative mass exceeds x (the last one's is 1): at most 13 halvings
    // for M <= 4096.
    int lo = 0, hi = M - 1;
    for (int it = 0; it < 13; ++it) {
        if (lo >= hi) break;
        int mid = (lo + hi) / 2;
        if (GLINT_SCRATCH_FETCH(glint_scratch_texel_index(M, o, mid) + 1).w > x) hi = mid;
        else lo = mid + 1;
    }
    real s = glint_scratch_edge_sin(lo, M) + clamp(u2, real(0), real(1)) * glint_scratch_bin_ds(lo, M);
    real phi = clamp(glint_asin(s), -GLINT_HALF_PI, GLINT_HALF_PI);
    // The pdf of the bin actually reached (rounding may put phi on the edge of the next bin).
    real pdf = (real(1) - p1) * glint_scratch_row_pdf(GLINT_SCRATCH_DATA_ARG M, rows.o0, a0, phi) + p1 * glint_scratch_row_pdf(GLINT_SCRATCH_DATA_ARG M, rows.o1, a1, phi);
    if (!(pdf > real(0))) return r;
    r.phi_i = phi;
    r.wi = glint_scratch_from_cone(f, vec2(-co.x, phi));
    r.pdf_phi = pdf;
    r.weight = glint_scratch_rho(GLINT_SCRATCH_DATA_ARG co.x, co.y, phi, filter_mode) * (cos(phi) / pdf);
    r.valid = true;
    return r;
}

// The density of glint_scratch_sample_cone's phi_i (per radian) for a view of cone coordinate phi_o.
GLINT_FN real glint_scratch_pdf_phi(GLINT_SCRATCH_DATA_PARAM real phi_o, real phi_i, int filter_mode) {
    int M = int(GLINT_SCRATCH_FETCH(0).x);
    if (M < 1 || !(abs(phi_i) <= GLINT_HALF_PI)) return real(0);
    glint_scratch_rows rows = glint_scratch_rows_of(phi_o, M, filter_mode);
    real a0 = GLINT_SCRATCH_FETCH(1 + rows.o0).x, a1 = GLINT_SCRATCH_FETCH(1 + rows.o1).x;
    real p1 = glint_scratch_row_choice(rows, a0, a1);
    if (p1 < real(0)) return real(0);
    return (real(1) - p1) * glint_scratch_row_pdf(GLINT_SCRATCH_DATA_ARG M, rows.o0, a0, phi_i) + p1 * glint_scratch_row_pdf(GLINT_SCRATCH_DATA_ARG M, rows.o1, a1, phi_i);
}

#endif  // GLINT_SCRATCH_FETCH

// RGB16 Sec. 5.2's cull: a point light at wl can reach the reflection cone of wo through a kernel
// of angular radius psi only where |theta_l + theta_o| <= psi (the angular distance from wl to the
// cone's latitude circle theta = -theta_o; exact).
GLINT_FN bool glint_scratch_light_reaches(glint_scratch_frame f, vec3 wo, vec3 wl, real psi) {
    vec2 a = glint_scratch_to_cone(f, wo), b = glint_scratch_to_cone(f, wl);
    return abs(a.x + b.x) <= psi;
}

// The light kernel's solid-angle normalisation int f dw = 2 pi (1 - cos psi) / 3 for
// f = (1 - t / t_psi)^2, t = |w - wl|^2 / 2 = 1 - cos(angle), t_psi = 1 - cos psi = 2 sin^2(psi/2).
GLINT_FN real glint_scratch_kernel_norm(real psi) {
    real sh = sin(real(0.5) * psi);
    return real(4) * GLINT_PI * sh * sh / real(3);
}

// The part [lo, hi] of the reflection cone theta = -theta_o within angle psi of wl, in phi, clipped
// to [-pi/2, pi/2]: by the haversine of the angle, sin^2(dphi / 2) <= (sin^2(psi/2) -
// sin^2((theta_l + theta_o)/2)) / (cos theta_o cos theta_l) (RGB16 Eq. 6's phi_+-, which drops the
// cosines); the whole range where the bound is >= 1. Empty (hi <= lo) where the light misses.
GLINT_FN vec2 glint_scratch_light_segment(vec2 cone_o, vec2 cone_l, real psi) {
    real d = abs(cone_o.x + cone_l.x);
    if (!(d <= psi)) return vec2(real(1), real(0));
    real sh = sin(real(0.5) * psi), sd = sin(real(0.5) * d);
    real den = cos(cone_o.x) * cos(cone_l.x);
    real rhs = (sh * sh - sd * sd) / max(den, real(1e-30));
    real half_width = (rhs >= real(1)) ? GLINT_PI : real(2) * glint_asin(sqrt(max(rhs, real(0))));
    return vec2(max(cone_l.y - half_width, -GLINT_HALF_PI), min(cone_l.y + half_width, GLINT_HALF_PI));
}

#if defined(GLINT_SCRATCH_FETCH)

// One scratch's radiance from a point light (RGB16 Sec. 5.2, Eq. 6): the light's irradiance E
// (I / r^2, on a surface facing it) spread over the kernel f / C_psi around wl, integrated along
// the cone's segment within psi of wl by n stratified samples (n clamped to [1, 32], shifted by
// jitter in [0, 1)): (E / C_psi) (phi_+ - phi_-) / n sum rho_s cos(phi) f. 0 when the light is below
// the horizon, wo is, or the cull says the light misses (no table read then).
GLINT_FN vec3 glint_scratch_light_radiance(GLINT_SCRATCH_DATA_PARAM glint_scratch_frame f, vec3 wo, vec3 wl, real irradiance, real psi, int n,
                                            real jitter, int filter_mode) {
    if (!(dot(wo, f.n) > real(0)) || !(dot(wl, f.n) > real(0)) || !(psi > real(0))) return vec3(real(0));
    vec2 co = glint_scratch_to_cone(f, wo), cl = glint_scratch_to_cone(f, wl);
    vec2 seg = glint_scratch_light_segment(co, cl, psi);
    if (!(seg.y > seg.x)) return vec3(real(0));
    int count = clamp(n, 1, GLINT_SCRATCH_MAX_LIGHT_SAMPLES);
    real sh = sin(real(0.5) * psi);
    real t_psi = real(2) * sh * sh;
    real step_phi = (seg.y - seg.x) / real(count);
    real j = clamp(jitter, real(0), real(1));
    vec3 sum = vec3(real(0));
    for (int k = 0; k < GLINT_SCRATCH_MAX_LIGHT_SAMPLES; ++k) {
        if (k >= count) break;
        real phi = seg.x + (real(k) + j) * step_phi;
        vec3 wi = glint_scratch_from_cone(f, vec2(-co.x, phi));
        vec3 d = wi - wl;
        real t = real(0.5) * dot(d, d);
        real w = max(real(1) - t / t_psi, real(0));
        sum += glint_scratch_rho(GLINT_SCRATCH_DATA_ARG co.x, co.y, phi, filter_mode) * (cos(phi) * w * w);
    }
    return sum * (irradiance / glint_scratch_kernel_norm(psi) * step_phi);
}

#endif  // GLINT_SCRATCH_FETCH

// The SV-BRDF's weights (RGB16 Eq. 4): with alpha_sum the layers' summed relative areas (each
// below the cull left out), layer k weighs alpha_k * layer_scale and the base BRDF base_weight:
// rho = sum_k alpha_k rho_k / alpha_sum + 0 rho_b where alpha_sum > 1, else sum_k alpha_k rho_k +
// (1 - alpha_sum) rho_b. The weights sum to 1 and are also the probabilities of picking each.
struct glint_scratch_mix {
    real layer_scale;
    real base_weight;
};

GLINT_FN glint_scratch_mix glint_scratch_mix_weights(real alpha_sum) {
    glint_scratch_mix m;
    real a = max(alpha_sum, real(0));
    m.layer_scale = real(1) / max(a, real(1));
    m.base_weight = max(real(1) - a, real(0));
    return m;
}

// One layer of a scratch distribution (RGB16 Eq. 7): orientation dir = (cos Theta_k, sin Theta_k)
// in the surface's (tangent, bitangent) plane, mean scratch length and width (1 / inv_length,
// 1 / inv_width, in the units of x), Worley threshold density d in [0, 1], offset xi_k, hash seed.
struct glint_scratch_layer {
    vec2 dir;
    vec2 offset;
    real inv_length;
    real inv_width;
    real density;
    uint seed;
};

// The layer's noise coordinates: rotate into the layer's axes, then stretch (Eq. 7 read as
// rotate-then-stretch: stretching first, as Eq. 7's matrix order literally says, would leave every
// scratch along the tangent whatever Theta_k), then offset.
GLINT_FN vec2 glint_scratch_layer_point(glint_scratch_layer L, vec2 x) {
    return vec2(dot(L.dir, x) * L.inv_length, (L.dir.x * x.y - L.dir.y * x.x) * L.inv_width) + L.offset;
}

// Worley's F1 (distance to the nearest feature point), one feature point per unit cell placed by
// glint_pcg3d of the cell and the seed, over the 3 x 3 cells around p.
GLINT_FN real glint_worley_f1(vec2 p, uint seed) {
    vec2 c = clamp(floor(p), vec2(real(-1073741824)), vec2(real(1073741824)));  // +-2^30: int stays in range
    real best = real(8);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec2 cell = c + vec2(real(dx), real(dy));
            uvec3 h = glint_pcg3d(uvec3(uint(int(cell.x)), uint(int(cell.y)), seed));
            vec2 q = cell + vec2(glint_unit_from_bits(h.x), glint_unit_from_bits(h.y)) - p;
            best = min(best, dot(q, q));
        }
    }
    return sqrt(best);
}

// Eq. 7: 1 where the layer has a scratch at x (F1 <= density), else 0. Each scratch is an ellipse
// 2 d / inv_length long and 2 d / inv_width wide around a feature point.
GLINT_FN real glint_scratch_indicator(glint_scratch_layer L, vec2 x) {
    return (glint_worley_f1(glint_scratch_layer_point(L, x), L.seed) <= L.density) ? real(1) : real(0);
}

// Eq. 3 with its 1/|P| (RGB16 omits it): the layer's relative area under a Gaussian footprint of
// centre x and covariance sigma^2 (a a^T + b b^T) (a, b the footprint's axis vectors, e.g.
// sigma_pix * duvdx and sigma_pix * duvdy), estimated from a 4 x 4 grid of the normal's quantiles
// at (i + jitter) / 4 per axis: unbiased over a uniform jitter in [0, 1)^2 (each point then has the
// footprint's density).
GLINT_FN real glint_scratch_alpha_footprint(glint_scratch_layer L, vec2 x, vec2 a, vec2 b, vec2 jitter) {
    real sum = real(0);
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            // glint_normal_quantile clamps its argument, so the points stay finite at jitter 0.
            real ua = (real(i) + clamp(jitter.x, real(0), real(1))) * real(0.25);
            real ub = (real(j) + clamp(jitter.y, real(0), real(1))) * real(0.25);
            vec2 y = x + glint_normal_quantile(ua) * a + glint_normal_quantile(ub) * b;
            sum += glint_scratch_indicator(L, y);
        }
    }
    return sum * real(0.0625);
}
