// glint's scratched materials (RGB16): the cone parametrization (Sec. 4.1, Eq. 1), the scratch
// BRDF from its 2D table (Eq. 2), importance sampling of the reflection cone (Sec. 5.1, Eq. 5),
// point lights through a normalised kernel (Sec. 5.2, Eq. 6), the layer mix of the SV-BRDF
// (Sec. 4.3, Eq. 3-4), the procedural scratch indicator (Sec. 5.3, Eq. 7) and the whole SV-BRDF over
// a material buffer (table, layers, coverage pyramid). Needs core.glsl. The host side (profiles, the
// ray-traced table, layer distributions, the pyramid) is in include/glint/scratch.hpp.
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

// No sample (weight 0): what the samplers return where nothing can be drawn.
GLINT_FN glint_scratch_sample glint_scratch_no_sample(vec3 n) {
    glint_scratch_sample r;
    r.wi = n;
    r.weight = vec3(real(0));
    r.phi_i = real(0);
    r.pdf_phi = real(0);
    r.valid = false;
    return r;
}

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
    glint_scratch_sample r = glint_scratch_no_sample(f.n);
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
// cone's latitude circle theta = -theta_o; exact). With a = sin(theta_o) = wo.u and b = sin(theta_l)
// (unit directions), for psi < pi/2 that is: cos(theta_o + theta_l) > 0 and |sin(theta_o + theta_l)|
// <= sin(psi), both from a and b with two square roots (no inverse trigonometry).
GLINT_FN bool glint_scratch_latitudes_meet(real a, real b, real sin_psi) {
    real ca = sqrt(max(real(1) - a * a, real(0))), cb = sqrt(max(real(1) - b * b, real(0)));
    return ca * cb - a * b > real(0) && abs(a * cb + b * ca) <= sin_psi;
}

GLINT_FN bool glint_scratch_light_reaches(glint_scratch_frame f, vec3 wo, vec3 wl, real psi) {
    real lo = length(wo), ll = length(wl);
    if (!(lo > real(0)) || !(ll > real(0))) return false;
    return glint_scratch_latitudes_meet(dot(wo, f.u) / lo, dot(wl, f.u) / ll, sin(min(psi, real(1.5))));
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
// 1 / inv_width, in the units of x), Worley threshold density d in [0, 1], offset xi_k, and the
// shared noise pattern: hash seed and period (cells, a power of two; the pattern repeats so that a
// baked coverage pyramid can hold it).
struct glint_scratch_layer {
    vec2 dir;
    vec2 offset;
    real inv_length;
    real inv_width;
    real density;
    uint seed;
    int period;
};

// The layer's noise coordinates: rotate into the layer's axes, then stretch (Eq. 7 read as
// rotate-then-stretch: stretching first, as Eq. 7's matrix order literally says, would leave every
// scratch along the tangent whatever Theta_k), then offset.
GLINT_FN vec2 glint_scratch_layer_point(glint_scratch_layer L, vec2 x) {
    return vec2(dot(L.dir, x) * L.inv_length, (L.dir.x * x.y - L.dir.y * x.x) * L.inv_width) + L.offset;
}

// The layer's footprint axis vector a (in x) in noise coordinates (the linear part of
// glint_scratch_layer_point).
GLINT_FN vec2 glint_scratch_layer_axis(glint_scratch_layer L, vec2 a) {
    return vec2(dot(L.dir, a) * L.inv_length, (L.dir.x * a.y - L.dir.y * a.x) * L.inv_width);
}

// Worley's F1 (distance to the nearest feature point), one feature point per unit cell placed by
// glint_pcg3d of the cell (modulo the period, a power of two) and the seed, over the 3 x 3 cells
// around p.
GLINT_FN real glint_worley_f1(vec2 p, uint seed, int period) {
    vec2 c = clamp(floor(p), vec2(real(-1073741824)), vec2(real(1073741824)));  // +-2^30: int stays in range
    uint mask = uint(max(period, 1) - 1);
    real best = real(8);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec2 cell = c + vec2(real(dx), real(dy));
            uvec3 h = glint_pcg3d(uvec3(uint(int(cell.x)) & mask, uint(int(cell.y)) & mask, seed));
            vec2 q = cell + vec2(glint_unit_from_bits(h.x), glint_unit_from_bits(h.y)) - p;
            best = min(best, dot(q, q));
        }
    }
    return sqrt(best);
}

// Eq. 7: 1 where the layer has a scratch at x (F1 <= density), else 0. Each scratch is an ellipse
// 2 d / inv_length long and 2 d / inv_width wide around a feature point.
GLINT_FN real glint_scratch_indicator(glint_scratch_layer L, vec2 x) {
    return (glint_worley_f1(glint_scratch_layer_point(L, x), L.seed, L.period) <= L.density) ? real(1) : real(0);
}

// Eq. 3 with its 1/|P| (RGB16 omits it): the layer's relative area under a Gaussian footprint of
// centre x and covariance a a^T + b b^T (a, b the footprint's axis vectors, e.g. sigma_pix * duvdx
// and sigma_pix * duvdy), estimated from a 4 x 4 grid of the normal's quantiles at (i + jitter) / 4
// per axis: unbiased over a uniform jitter in [0, 1)^2 (each point then has the footprint's density).
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

// Curved scratches (RGB16 Fig. 15: the parametrization carries them): coordinates in which
// concentric circles (pitch 0) or an Archimedean spiral of the given pitch around centre c become
// straight lines along the first axis, and the surface tangent along them (lathe-turned metal).
// The first coordinate is arc length at radius r, the second the distance across the turns.
struct glint_scratch_param {
    vec2 x;
    vec2 tangent;
};

GLINT_FN glint_scratch_param glint_scratch_turned(vec2 p, vec2 c, real pitch) {
    glint_scratch_param r;
    vec2 d = p - c;
    real rad = length(d);
    real ang = glint_atan2(d.y, d.x);
    r.x = vec2(rad * ang, rad - pitch * ang * GLINT_INV_TWO_PI);
    r.tangent = (rad > real(0)) ? vec2(-d.y, d.x) / rad : vec2(real(1), real(0));
    return r;
}

#if defined(GLINT_SCRATCH_FETCH)

// A scratch material: the table, then (at index 1 + M + 2 M^2) its layers and the baked coverage
// pyramid of the shared noise pattern (include/glint/scratch.hpp, scratch_material):
//   [h]       (K layers, period P cells, T texels per cell at level 0, pyramid levels)
//   [h + 1]   (density, seed >> 16, seed & 0xffff, R0 = P T)
//   [h + 2 .. h + 5]             the start of level l at component l of these 16 floats, counted
//                                from the first level's vec4 (levels <= 14)
//   [h + 6 + 2k], [h + 7 + 2k]   layer k: (dir, offset), (inv_length, inv_width, 0, 0)
//   [h + 6 + 2K ...]             level l (R_l = R0 / 2^l texels a side, l = 0 .. levels - 1):
//                                max(1, R_l^2 / 4) vec4, texel (x, y) at component (x + R_l y) of them;
//                                each texel the fraction of its square of noise space inside a scratch.
GLINT_FN int glint_scratch_material_header(int M) {
    return 1 + M + 2 * M * M;
}

// The material's layer count (the int is unused: in C++ the data parameter needs one after it).
GLINT_FN int glint_scratch_material_layer_count(GLINT_SCRATCH_DATA_PARAM int unused) {
    int M = int(GLINT_SCRATCH_FETCH(0).x);
    return int(GLINT_SCRATCH_FETCH(glint_scratch_material_header(M)).x) + 0 * unused;
}

GLINT_FN glint_scratch_layer glint_scratch_material_layer(GLINT_SCRATCH_DATA_PARAM int k) {
    int h = glint_scratch_material_header(int(GLINT_SCRATCH_FETCH(0).x));
    vec4 head = GLINT_SCRATCH_FETCH(h), head2 = GLINT_SCRATCH_FETCH(h + 1);
    vec4 a = GLINT_SCRATCH_FETCH(h + 6 + 2 * k), b = GLINT_SCRATCH_FETCH(h + 7 + 2 * k);
    glint_scratch_layer L;
    L.dir = vec2(a.x, a.y);
    L.offset = vec2(a.z, a.w);
    L.inv_length = b.x;
    L.inv_width = b.y;
    L.density = head2.x;
    L.seed = (uint(head2.y) << 16u) | uint(head2.z);
    L.period = int(head.y);
    return L;
}

// Coverage texel (x, y) of the level starting at vec4 index base, R texels a side, periodic.
GLINT_FN real glint_scratch_coverage_texel(GLINT_SCRATCH_DATA_PARAM int base, int R, int x, int y) {
    int t = (x & (R - 1)) + R * (y & (R - 1));
    return GLINT_SCRATCH_FETCH(base + (t >> 2))[t & 3];
}

// Bilinear read of a level at noise point p (texel centres at (i + 1/2) / T_l cells).
// p's texel coordinates are clamped to +-2^30 (int range).
GLINT_FN real glint_scratch_coverage_bilinear(GLINT_SCRATCH_DATA_PARAM int base, int R, real texels_per_cell, vec2 p) {
    vec2 q = clamp(p * texels_per_cell - vec2(real(0.5)), vec2(real(-1073741824)), vec2(real(1073741824)));
    // floor by truncation (a libm call in C++ without SSE4.1, and the hot spot here), then the
    // texel indices wrap by masking in glint_scratch_coverage_texel.
    int x = int(q.x), y = int(q.y);
    if (real(x) > q.x) x -= 1;
    if (real(y) > q.y) y -= 1;
    vec2 w = q - vec2(real(x), real(y));
    real c00 = glint_scratch_coverage_texel(GLINT_SCRATCH_DATA_ARG base, R, x, y), c10 = glint_scratch_coverage_texel(GLINT_SCRATCH_DATA_ARG base, R, x + 1, y);
    real c01 = glint_scratch_coverage_texel(GLINT_SCRATCH_DATA_ARG base, R, x, y + 1), c11 = glint_scratch_coverage_texel(GLINT_SCRATCH_DATA_ARG base, R, x + 1, y + 1);
    return mix(mix(c00, c10, w.x), mix(c01, c11, w.x), w.y);
}

// A footprint in a layer's noise space: centre p, major axis e, sd s1 along it and s2 across.
struct glint_scratch_noise_footprint {
    vec2 p;
    vec2 e;
    real s1;
    real s2;
};

GLINT_FN glint_scratch_noise_footprint glint_scratch_to_noise(glint_scratch_layer L, vec2 x, vec2 a, vec2 b) {
    glint_scratch_noise_footprint r;
    vec2 ap = glint_scratch_layer_axis(L, a), bp = glint_scratch_layer_axis(L, b);
    // The covariance a a^T + b b^T in noise space and its eigen-decomposition.
    real sxx = ap.x * ap.x + bp.x * bp.x, syy = ap.y * ap.y + bp.y * bp.y, sxy = ap.x * ap.y + bp.x * bp.y;
    real half_tr = real(0.5) * (sxx + syy), root = sqrt(max(real(0.25) * (sxx - syy) * (sxx - syy) + sxy * sxy, real(0)));
    r.s1 = sqrt(max(half_tr + root, real(0)));
    r.s2 = sqrt(max(half_tr - root, real(0)));
    // The major axis: of the two forms of the eigenvector, the longer (better conditioned).
    vec2 e1 = vec2(r.s1 * r.s1 - syy, sxy), e2 = vec2(sxy, r.s1 * r.s1 - sxx);
    vec2 e = (dot(e1, e1) >= dot(e2, e2)) ? e1 : e2;
    real le = length(e);
    r.e = (le > real(0)) ? e / le : vec2(real(1), real(0));
    r.p = glint_scratch_layer_point(L, x);
    return r;
}

// The pyramid read trilinearly at noise point q and level of detail lod (0 = finest).
GLINT_FN real glint_scratch_coverage_trilinear(GLINT_SCRATCH_DATA_PARAM int h, vec2 q, real lod) {
    vec4 head = GLINT_SCRATCH_FETCH(h);
    int K = int(head.x), T = int(head.z), levels = int(head.w);
    int R0 = int(GLINT_SCRATCH_FETCH(h + 1).w);
    real l = clamp(lod, real(0), real(levels - 1));
    int l0 = int(floor(l));
    int l1 = min(l0 + 1, levels - 1);
    real fl = l - real(l0);
    int first = h + 6 + 2 * K;
    int b0 = first + int(GLINT_SCRATCH_FETCH(h + 2 + (l0 >> 2))[l0 & 3]), b1 = first + int(GLINT_SCRATCH_FETCH(h + 2 + (l1 >> 2))[l1 & 3]);
    real c0 = glint_scratch_coverage_bilinear(GLINT_SCRATCH_DATA_ARG b0, R0 >> l0, real(T) / real(1 << l0), q);
    if (fl == real(0)) return c0;
    return mix(c0, glint_scratch_coverage_bilinear(GLINT_SCRATCH_DATA_ARG b1, R0 >> l1, real(T) / real(1 << l1), q), fl);
}

// Layer k's relative area under the Gaussian footprint (x; axes a, b in x) from the coverage
// pyramid, as GPUs filter anisotropically: up to 16 taps evenly spaced over +-2 s1 along the major
// axis, weighted by the Gaussian exp(-z^2 / 2), each a trilinear read at the level whose texel is
// 2 max(s2, s1 / 8) wide (anisotropy capped at 8; the tap spacing at most that texel). The box and
// tent filters stand in for the Gaussian (error measured in docs/scratch.md). Footprints below half
// a level-0 texel use the exact indicator through glint_scratch_alpha_footprint with the jitter.
GLINT_FN real glint_scratch_material_alpha(GLINT_SCRATCH_DATA_PARAM int k, vec2 x, vec2 a, vec2 b, vec2 jitter) {
    int h = glint_scratch_material_header(int(GLINT_SCRATCH_FETCH(0).x));
    real T = GLINT_SCRATCH_FETCH(h).z;
    glint_scratch_layer L = glint_scratch_material_layer(GLINT_SCRATCH_DATA_ARG k);
    glint_scratch_noise_footprint n = glint_scratch_to_noise(L, x, a, b);
    if (n.s1 * T < real(0.5)) return glint_scratch_alpha_footprint(L, x, a, b, jitter);
    real s2e = max(n.s2, n.s1 / real(8));
    int taps = int(clamp(ceil(real(2) * n.s1 / s2e), real(1), real(16)));
    real lod = log2(max(real(2) * s2e * T, real(1e-30)));
    real sum = real(0), wsum = real(0);
    for (int j = 0; j < 16; ++j) {
        if (j >= taps) break;
        real z = (taps > 1) ? real(2) * ((real(2 * j + 1) / real(taps)) - real(1)) : real(0);
        real w = exp(real(-0.5) * z * z);
        sum += w * glint_scratch_coverage_trilinear(GLINT_SCRATCH_DATA_ARG h, n.p + (z * n.s1) * n.e, lod);
        wsum += w;
    }
    return sum / wsum;
}

// A cheaper, blurrier area for layers that only enter Eq. 4's sum: one bilinear read at the level
// of the footprint's major axis (isotropic: it averages along the scratches over the width of the
// footprint across them; nearest level, so it steps where the footprint crosses a level).
GLINT_FN real glint_scratch_material_alpha_coarse(GLINT_SCRATCH_DATA_PARAM int k, vec2 x, vec2 a, vec2 b) {
    int h = glint_scratch_material_header(int(GLINT_SCRATCH_FETCH(0).x));
    vec4 head = GLINT_SCRATCH_FETCH(h);
    int K = int(head.x), levels = int(head.w);
    real T = head.z;
    glint_scratch_layer L = glint_scratch_material_layer(GLINT_SCRATCH_DATA_ARG k);
    // The major axis's sd from the trace of the covariance (s1^2 <= trace <= 2 s1^2): no
    // eigen-decomposition. One bilinear read at the level nearest 2 s1's texel: with 4 T^2 trace =
    // m 2^e (frexp, exact), round(log2(2 T sqrt(trace))) = floor(e / 2).
    vec2 ap = glint_scratch_layer_axis(L, a), bp = glint_scratch_layer_axis(L, b);
    int e;
    frexp(max(real(4) * T * T * (dot(ap, ap) + dot(bp, bp)), real(1e-30)), e);
    int l = clamp((e >= 0) ? e / 2 : -((1 - e) / 2), 0, levels - 1);
    int R0 = int(GLINT_SCRATCH_FETCH(h + 1).w);
    int base = h + 6 + 2 * K + int(GLINT_SCRATCH_FETCH(h + 2 + (l >> 2))[l & 3]);
    return glint_scratch_coverage_bilinear(GLINT_SCRATCH_DATA_ARG base, R0 >> l, T / real(1 << l), glint_scratch_layer_point(L, x));
}

// One point light on the whole SV-BRDF (RGB16 Eq. 4 with Eq. 6 per layer) at x, with frame f (n and
// the surface tangent the layers rotate from), footprint axes a, b: first the light cull per layer
// and every layer's area (Eq. 4 needs their sum: glint_scratch_material_alpha for the layers the
// light can reach, the coarse read for the rest, which only enter the sum), then, for each layer
// the light reaches with area >= cull, its radiance (Eq. 6). Returns the scratches' radiance (weighted) and the base BRDF's weight: the caller adds
// base_weight * f_base(wi = wl, wo) * E * cos.
struct glint_scratch_lit {
    vec3 radiance;
    real base_weight;
    real alpha_sum;
    int layers_shaded;
};

GLINT_FN glint_scratch_frame glint_scratch_layer_frame(glint_scratch_frame f, glint_scratch_layer L) {
    glint_scratch_frame g;
    g.n = f.n;
    g.u = L.dir.x * f.u + L.dir.y * f.v;
    g.v = cross(f.n, g.u);
    return g;
}

GLINT_FN glint_scratch_lit glint_scratch_material_light(GLINT_SCRATCH_DATA_PARAM glint_scratch_frame f, vec2 x, vec2 a, vec2 b, vec2 jitter, vec3 wo, vec3 wl,
                                                        real irradiance, real psi, int n, real cull, int filter_mode) {
    glint_scratch_lit r;
    r.radiance = vec3(real(0));
    r.layers_shaded = 0;
    int K = min(glint_scratch_material_layer_count(GLINT_SCRATCH_DATA_ARG 0), GLINT_SCRATCH_MAX_LAYERS);
    r.base_weight = real(1);
    r.alpha_sum = real(0);
    if (K == 0) return r;  // scratches disabled: the base BRDF alone, at the cost of two reads
    real alpha[64];
    bool reach[64];
    real sum = real(0);
    real lo = length(wo), ll = length(wl);
    bool lit = dot(wo, f.n) > real(0) && dot(wl, f.n) > real(0) && lo > real(0) && ll > real(0);
    // The light cull per layer from four dot products taken once: layer k's u is dir.x f.u +
    // dir.y f.v, so sin(theta) = dir . (w.u, w.v).
    vec2 o2 = lit ? vec2(dot(wo, f.u), dot(wo, f.v)) / lo : vec2(real(0)), l2 = lit ? vec2(dot(wl, f.u), dot(wl, f.v)) / ll : vec2(real(0));
    real sin_psi = sin(min(psi, real(1.5)));
    int h = glint_scratch_material_header(int(GLINT_SCRATCH_FETCH(0).x));
    for (int k = 0; k < GLINT_SCRATCH_MAX_LAYERS; ++k) {
        if (k >= K) break;
        vec4 dk = GLINT_SCRATCH_FETCH(h + 6 + 2 * k);
        reach[k] = lit && glint_scratch_latitudes_meet(dk.x * o2.x + dk.y * o2.y, dk.x * l2.x + dk.y * l2.y, sin_psi);
        real al = reach[k] ? glint_scratch_material_alpha(GLINT_SCRATCH_DATA_ARG k, x, a, b, jitter) : glint_scratch_material_alpha_coarse(GLINT_SCRATCH_DATA_ARG k, x, a, b);
        alpha[k] = (al >= cull) ? al : real(0);
        sum += alpha[k];
    }
    glint_scratch_mix m = glint_scratch_mix_weights(sum);
    r.base_weight = m.base_weight;
    r.alpha_sum = sum;
    for (int k = 0; k < GLINT_SCRATCH_MAX_LAYERS; ++k) {
        if (k >= K) break;
        if (!reach[k] || !(alpha[k] > real(0))) continue;
        glint_scratch_frame g = glint_scratch_layer_frame(f, glint_scratch_material_layer(GLINT_SCRATCH_DATA_ARG k));
        r.radiance += (alpha[k] * m.layer_scale) * glint_scratch_light_radiance(GLINT_SCRATCH_DATA_ARG g, wo, wl, irradiance, psi, n, jitter.x, filter_mode);
        r.layers_shaded += 1;
    }
    return r;
}

// Importance sampling of the whole SV-BRDF (RGB16 Sec. 5.1, Fig. 11: layers by their weights):
// with u0 picks the base (layer = -1: the caller samples its base BRDF and weighs it as usual) or
// layer k with probability w_k, then samples that layer's cone with u1, u2. The sample's weight
// already carries rho_s cos / pdf; the pick's probability cancels Eq. 4's weight, so the estimator
// is weight * L_i(wi) either way (for the base: f_base cos / pdf_base * L_i).
struct glint_scratch_pick {
    glint_scratch_sample s;
    int layer;
};

// Every layer's area under a footprint (below cull: 0) and Eq. 4's weights, computed once per
// pixel for any number of glint_scratch_material_sample_with draws.
struct glint_scratch_areas {
    real alpha[64];
    int count;
    glint_scratch_mix mix;
};

GLINT_FN glint_scratch_areas glint_scratch_material_areas(GLINT_SCRATCH_DATA_PARAM vec2 x, vec2 a, vec2 b, vec2 jitter, real cull) {
    glint_scratch_areas r;
    r.count = min(glint_scratch_material_layer_count(GLINT_SCRATCH_DATA_ARG 0), GLINT_SCRATCH_MAX_LAYERS);
    real sum = real(0);
    for (int k = 0; k < GLINT_SCRATCH_MAX_LAYERS; ++k) {
        r.alpha[k] = real(0);
        if (k >= r.count) continue;
        real al = glint_scratch_material_alpha(GLINT_SCRATCH_DATA_ARG k, x, a, b, jitter);
        r.alpha[k] = (al >= cull) ? al : real(0);
        sum += r.alpha[k];
    }
    r.mix = glint_scratch_mix_weights(sum);
    return r;
}

GLINT_FN glint_scratch_pick glint_scratch_material_sample_with(GLINT_SCRATCH_DATA_PARAM glint_scratch_frame f, glint_scratch_areas A, vec3 wo, real u0, real u1,
                                                               real u2, int filter_mode) {
    glint_scratch_pick r;
    r.layer = -1;
    r.s = glint_scratch_no_sample(f.n);
    real t = clamp(u0, real(0), real(1)) - A.mix.base_weight;
    if (t < real(0)) return r;
    int last = -1;
    for (int k = 0; k < GLINT_SCRATCH_MAX_LAYERS; ++k) {
        if (k >= A.count) break;
        real w = A.alpha[k] * A.mix.layer_scale;
        if (!(w > real(0))) continue;
        last = k;
        if (t < w) break;
        t -= w;
    }
    // Rounding may leave t past the last weight: the last layer with one takes it.
    if (last < 0) return r;
    r.layer = last;
    r.s = glint_scratch_sample_cone(GLINT_SCRATCH_DATA_ARG glint_scratch_layer_frame(f, glint_scratch_material_layer(GLINT_SCRATCH_DATA_ARG last)), wo, u1, u2, filter_mode);
    return r;
}

GLINT_FN glint_scratch_pick glint_scratch_material_sample(GLINT_SCRATCH_DATA_PARAM glint_scratch_frame f, vec2 x, vec2 a, vec2 b, vec2 jitter, vec3 wo, real u0,
                                                          real u1, real u2, real cull, int filter_mode) {
    return glint_scratch_material_sample_with(GLINT_SCRATCH_DATA_ARG f, glint_scratch_material_areas(GLINT_SCRATCH_DATA_ARG x, a, b, jitter, cull), wo, u0, u1, u2,
                                              filter_mode);
}

#endif  // GLINT_SCRATCH_FETCH
