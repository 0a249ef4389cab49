// glint Gaussian elements (YHMR16 Sec. 4, as XTXW24 Sec. 3.2 writes them) and the footprint
// P-NDF in closed form. Needs core.glsl and microfacet.glsl. Derivation, domains and measured
// errors: include/glint/gaussian.hpp.
//
// An element i sits at u_i (texels) with normal xy part s_i and Jacobian J_i = ds/du. XTXW24
// Eq. 4-5 give G_i(u, s) = c_i exp(-|du|^2 / (2 sigma_h^2) - |ds - J_i du|^2 / (2 sigma_r^2)), with
// du = u - u_i, ds = s - s_i and c_i = a_i / (4 pi^2 sigma_h^2 sigma_r^2), so that G_i integrates to
// its area a_i = h^2. Against the footprint G_P(u) = N(u; mu, Sigma_P), Eq. 6's integral is
//   I_i(s) = a_i N(u_i; mu, Sigma_P + sigma_h^2 I) N(s; s_i + J_i sigma_h^2 (Sigma_P + sigma_h^2 I)^-1 (mu - u_i), C_i),
//   C_i = sigma_r^2 I + J_i S J_i^T,  S = (Sigma_P^-1 + sigma_h^-2 I)^-1
// (the product of the two Gaussians in u, then the linear-Gaussian marginal in s). With
// Sigma_P = R diag(lambda) R^T and kappa = lambda + sigma_h^2 it is evaluated as sums of squares
// only, so nothing cancels in float (rank-1 J under huge footprints is the hard case):
//   e = R^T (mu - u_i),  w_i = a_i exp(-sum e_k^2 / (2 kappa_k)) / (2 pi sqrt(kappa_1 kappa_2)),
//   mean = s_i + J_i R diag(sigma_h^2 / kappa) e,  B = J_i R diag(sigma_h sqrt(lambda / kappa)) (B B^T = J S J^T),
//   det C = sigma_r^4 + sigma_r^2 |B|_F^2 + det(B)^2,  q = (sigma_r^2 |d|^2 + |adj(B) d|^2) / det C,
//   I_i = w_i exp(-q / 2) / (2 pi sqrt(det C)),  d = s - mean.
// Culling (YHMR16's bounds, stated as Mahalanobis radii): an element counts only where
// m = sum e_k^2 / kappa_k <= cull_u^2 and q <= cull_s^2. YHMR16 cuts the footprint off hard, so
// an element entering the ellipse as the footprint moves makes D_P jump (by 2% of D_P, measured);
// here its weight is tapered instead, by a smoothstep in m from (cull_u - 1)^2 to cull_u^2
// (glint_pndf_window), which makes D_P continuous in the footprint. What the taper and the lobe's
// cut drop of a Gaussian's mass is known in closed form (glint_pndf_window_mass,
// glint_pndf_kept_mass), and the kept parts are divided by it: the culled P-NDF keeps the
// footprint's mass and each lobe's (YHMR16's hard cut loses 1.1% at cull_u = 3).
//
// GLSL users who call glint_pndf_direct declare the elements (two vec4 each, the layout of
// glint_gaussian_element) before including this file,
//   layout(std430, binding = N) readonly buffer glint_element_buffer { vec4 glint_element_data[]; };
// or define GLINT_ELEMENT_BINDING and let this file declare it.

// One element: us = (u.x, u.y, s.x, s.y), jac = (dsx/dx, dsy/dx, dsx/dy, dsy/dy) (J's columns).
struct glint_gaussian_element {
    vec4 us;
    vec4 jac;
};

// A footprint N(u; mean, Sigma_P) in texels, prepared once per pixel for given sigma_h: the
// eigenframe of Sigma_P (axis = R's first column, lambda its eigenvalues) and the per-element
// factors that depend on it only.
struct glint_pndf_frame {
    vec2 mean;
    vec2 axis;
    vec2 lambda;
    vec2 kappa;   // lambda + sigma_h^2
    vec2 shift;   // sigma_h^2 / kappa
    vec2 spread;  // sigma_h sqrt(lambda / kappa)
    vec2 extent;  // half-extent of the culling ellipse's bounding box in u: cull_u sqrt(diag(Sigma_P) + sigma_h^2)
    real norm;    // 1 / (2 pi sqrt(kappa_1 kappa_2) E[window])
    real lobe_norm;  // 1 / (2 pi (1 - exp(-cull_s^2 / 2)))
};

// The element lattice and its lobes: elements at ((i + 1/2) h, (j + 1/2) h), i < width, j < height,
// index i + width j; periodic (1) or not (0).
struct glint_pndf_params {
    real sigma_h;
    real sigma_r;
    real spacing;
    real area;
    real cull_u;
    real cull_s;
    int width;
    int height;
    int periodic;
    int max_side;  // the direct loop visits at most (2 max_side + 1)^2 lattice points
};

GLINT_CONST(real) GLINT_GAUSSIAN_MIN_SIGMA_R = real(1e-5);

// Sigma_P from cov = (xx, xy, yy, det): the determinant is passed in, computed where it does not
// cancel (from the derivatives' cross product, or in double), since xx yy - xy^2 in float loses a
// thin footprint's minor axis. Negative eigenvalues (rounding) count as 0; non-finite input as a
// point footprint at the origin.
// The mass of a 2D standard Gaussian within Mahalanobis radius `cull`, 1 - exp(-cull^2 / 2)
// (1 for cull <= 0: no cut).
GLINT_FN real glint_pndf_kept_mass(real cull) {
    return cull > real(0) ? -glint_expm1_nonpositive(real(-0.5) * cull * cull) : real(1);
}

// The footprint taper at squared Mahalanobis radius m: 1 up to (cull - 1)^2, a smoothstep t^2 (3 - 2t)
// down to 0 at cull^2, t = (cull^2 - m) / (cull^2 - (cull - 1)^2); 1 everywhere for cull <= 0.
GLINT_FN real glint_pndf_window(real m, real cull) {
    if (!(cull > real(0))) return real(1);
    real c2 = cull * cull;
    real t = clamp((c2 - m) / (real(2) * cull - real(1)), real(0), real(1));
    return t * t * (real(3) - real(2) * t);
}

// E[window(m)] for a 2D standard Gaussian (m / 2 ~ Exp(1)): with a = (cull - 1)^2 / 2, b = cull^2 / 2,
// L = b - a, integrating the cubic S(x) exp(-x) by parts (S(a) = 1, S(b) = S'(a) = S'(b) = 0,
// S'' = 6 (1 - 2 t) / L^2, S''' = 12 / L^3): 1 - exp(-a) (6/L^2 - 12/L^3) - exp(-b) (6/L^2 + 12/L^3).
// 0.95482 at cull = 3, 0.98781 at 3.5.
GLINT_FN real glint_pndf_window_mass(real cull) {
    if (!(cull > real(0))) return real(1);
    real a = real(0.5) * (cull - real(1)) * (cull - real(1));
    real b = real(0.5) * cull * cull;
    real l = b - a;
    real p2 = real(6) / (l * l);
    real p3 = real(12) / (l * l * l);
    return real(1) - exp(-a) * (p2 - p3) - exp(-b) * (p2 + p3);
}

GLINT_FN glint_pndf_frame glint_pndf_prepare(vec2 mean, vec4 cov, real sigma_h, real cull_u, real cull_s) {
    glint_pndf_frame f;
    bool finite = abs(cov.x) < real(1e30) && abs(cov.y) < real(1e30) && abs(cov.z) < real(1e30) && abs(cov.w) < real(1e30) &&
                  abs(mean.x) < real(1e30) && abs(mean.y) < real(1e30);
    if (!finite) {
        mean = vec2(real(0));
        cov = vec4(real(0));
    }
    real half_diff = real(0.5) * (cov.x - cov.z);
    real r = sqrt(half_diff * half_diff + cov.y * cov.y);
    real m = real(0.5) * (cov.x + cov.z);
    real l1 = max(m + r, real(0));
    // lambda_2 = det / lambda_1 keeps a thin footprint's minor axis from cancelling.
    real l2 = l1 > real(0) ? clamp(cov.w / l1, real(0), l1) : real(0);
    // The major axis: the eigenvector of l1, (xy, l1 - xx) or (l1 - yy, xy), whichever is longer.
    vec2 a1 = vec2(cov.y, l1 - cov.x);
    vec2 a2 = vec2(l1 - cov.z, cov.y);
    vec2 a = dot(a1, a1) > dot(a2, a2) ? a1 : a2;
    real len = sqrt(dot(a, a));
    f.axis = len > real(0) ? a / len : vec2(real(1), real(0));
    f.mean = mean;
    f.lambda = vec2(l1, l2);
    real h2 = sigma_h * sigma_h;
    f.kappa = f.lambda + vec2(h2);
    f.shift = vec2(h2) / f.kappa;
    f.spread = vec2(sigma_h) * sqrt(f.lambda / f.kappa);
    f.extent = vec2(cull_u) * sqrt(max(vec2(cov.x, cov.z), vec2(real(0))) + vec2(h2));
    f.norm = GLINT_INV_TWO_PI / (sqrt(f.kappa.x * f.kappa.y) * glint_pndf_window_mass(cull_u));
    f.lobe_norm = GLINT_INV_TWO_PI / glint_pndf_kept_mass(cull_s);
    return f;
}

// The footprint N(u; mean, sigma_pix^2 T^2 (du/dx du/dx^T + du/dy du/dy^T)) of a pixel whose uv
// derivatives are duvdx, duvdy, T texels per uv unit (Heckbert's Gaussian with the pixel filter's
// sd sigma_pix pixels, XTXW24 Sec. 6.3), as (xx, xy, yy, det) with det = (a x b)^2.
GLINT_FN vec4 glint_pndf_footprint_covariance(vec2 duvdx, vec2 duvdy, real texels_per_uv, real sigma_pix) {
    vec2 a = duvdx * (texels_per_uv * sigma_pix);
    vec2 b = duvdy * (texels_per_uv * sigma_pix);
    real c = a.x * b.y - a.y * b.x;
    return vec4(a.x * a.x + b.x * b.x, a.x * a.y + b.x * b.y, a.y * a.y + b.y * b.y, c * c);
}

// The lobe of element (s_i, J) at footprint offset e = R^T (mu - u_i): its mean and the factors of
// C (B's entries) packed for glint_pndf_lobe_density.
struct glint_pndf_lobe {
    vec2 mean;
    vec4 b;       // B = (b.x b.z; b.y b.w), columns (b.x, b.y), (b.z, b.w)
    real det_c;
    real weight;  // w_i, tapered by the window
    real mahalanobis_u;  // sum e_k^2 / kappa_k
};

// The footprint offset e = R^T (mu - u_i) of an element at u_i.
GLINT_FN vec2 glint_pndf_offset(vec2 u_i, glint_pndf_frame f) {
    vec2 d = f.mean - u_i;
    return vec2(f.axis.x * d.x + f.axis.y * d.y, -f.axis.y * d.x + f.axis.x * d.y);
}

// The squared Mahalanobis radius of footprint offset e, sum e_k^2 / kappa_k.
GLINT_FN real glint_pndf_mahalanobis_u(vec2 e, glint_pndf_frame f) {
    return e.x * e.x / f.kappa.x + e.y * e.y / f.kappa.y;
}

// The tapered spatial weight w_i of an element whose footprint offset has squared Mahalanobis
// radius m (0 outside the culling ellipse).
GLINT_FN real glint_pndf_weight_at(real m, glint_pndf_frame f, glint_pndf_params p) {
    if (p.cull_u > real(0) && m > p.cull_u * p.cull_u) return real(0);
    return p.area * f.norm * exp(real(-0.5) * m) * glint_pndf_window(m, p.cull_u);
}

// The same for an element at u_i.
GLINT_FN real glint_pndf_element_weight(vec2 u_i, glint_pndf_frame f, glint_pndf_params p) {
    return glint_pndf_weight_at(glint_pndf_mahalanobis_u(glint_pndf_offset(u_i, f), f), f, p);
}

// The lobe's shape at footprint offset e: its mean and C's factors (mahalanobis_u and weight left 0).
GLINT_FN glint_pndf_lobe glint_pndf_lobe_shape(glint_gaussian_element el, vec2 e, glint_pndf_frame f, glint_pndf_params p) {
    glint_pndf_lobe l;
    l.mahalanobis_u = real(0);
    l.weight = real(0);
    // J R: columns J r1, J r2 with r1 = axis, r2 = perp(axis).
    // (No swizzles: GLM's C++ vectors have none.)
    vec2 jx = vec2(el.jac.x, el.jac.y);
    vec2 jy = vec2(el.jac.z, el.jac.w);
    vec2 j1 = jx * f.axis.x + jy * f.axis.y;
    vec2 j2 = -jx * f.axis.y + jy * f.axis.x;
    l.mean = vec2(el.us.z, el.us.w) + j1 * (f.shift.x * e.x) + j2 * (f.shift.y * e.y);
    vec2 b1 = j1 * f.spread.x;
    vec2 b2 = j2 * f.spread.y;
    l.b = vec4(b1, b2);
    real sr = max(p.sigma_r, GLINT_GAUSSIAN_MIN_SIGMA_R);
    real sr2 = sr * sr;
    // det(B) = det(J R) sigma_h^2 sqrt(l1 l2 / k1 k2) = det(J) spread.x spread.y (det R = 1).
    real det_b = (el.jac.x * el.jac.w - el.jac.z * el.jac.y) * f.spread.x * f.spread.y;
    l.det_c = sr2 * sr2 + sr2 * (dot(b1, b1) + dot(b2, b2)) + det_b * det_b;
    return l;
}

GLINT_FN glint_pndf_lobe glint_pndf_element_lobe(glint_gaussian_element el, vec2 u_i, glint_pndf_frame f, glint_pndf_params p) {
    vec2 e = glint_pndf_offset(u_i, f);
    glint_pndf_lobe l = glint_pndf_lobe_shape(el, e, f, p);
    l.mahalanobis_u = glint_pndf_mahalanobis_u(e, f);
    l.weight = p.area * f.norm * exp(real(-0.5) * l.mahalanobis_u) * glint_pndf_window(l.mahalanobis_u, p.cull_u);
    return l;
}

// The lobe's Mahalanobis distance q of s (C^-1 through adj: C = sigma_r^2 I + B B^T).
GLINT_FN real glint_pndf_lobe_q(glint_pndf_lobe l, vec2 s, real sigma_r) {
    real sr = max(sigma_r, GLINT_GAUSSIAN_MIN_SIGMA_R);
    vec2 d = s - l.mean;
    // adj(B) = (b.w -b.z; -b.y b.x); |adj(B) d|^2
    vec2 ad = vec2(l.b.w * d.x - l.b.z * d.y, -l.b.y * d.x + l.b.x * d.y);
    return (sr * sr * dot(d, d) + dot(ad, ad)) / l.det_c;
}

// I_i(s) with culling (cull_u, cull_s; a radius <= 0 disables it).
// Both culling tests come before any exp, and one exp gives the weight's and the lobe's factors
// (exp(-m/2) exp(-q/2)): most elements that reach it are culled (on the flakes map of
// docs/microstructure.md at footprint sd 64 through the hierarchy, 2.6 reach it per nonzero term).
// From the element's footprint offset e (glint_pndf_offset) and its squared Mahalanobis radius m
// (glint_pndf_mahalanobis_u of e), for callers that have m already.
GLINT_FN real glint_pndf_element_at(glint_gaussian_element el, vec2 e, real m, glint_pndf_frame f, vec2 s, glint_pndf_params p) {
    if (p.cull_u > real(0) && m > p.cull_u * p.cull_u) return real(0);
    glint_pndf_lobe l = glint_pndf_lobe_shape(el, e, f, p);
    real q = glint_pndf_lobe_q(l, s, p.sigma_r);
    if (p.cull_s > real(0) && q > p.cull_s * p.cull_s) return real(0);
    return p.area * f.norm * glint_pndf_window(m, p.cull_u) * exp(real(-0.5) * (m + q)) * f.lobe_norm / sqrt(l.det_c);
}

// The same for an element at u_i.
GLINT_FN real glint_pndf_element(glint_gaussian_element el, vec2 u_i, glint_pndf_frame f, vec2 s, glint_pndf_params p) {
    vec2 e = glint_pndf_offset(u_i, f);
    return glint_pndf_element_at(el, e, glint_pndf_mahalanobis_u(e, f), f, s, p);
}

// The element's normal marginal a_i N(s; s_i, sigma_r^2 I + sigma_h^2 J J^T) (the footprint -> infinity
// limit divided by the footprint density; used by tile NDFs, XTXW24 Eq. 7).
GLINT_FN real glint_pndf_element_marginal(glint_gaussian_element el, vec2 s, glint_pndf_params p) {
    real sr = max(p.sigma_r, GLINT_GAUSSIAN_MIN_SIGMA_R);
    real sr2 = sr * sr;
    vec4 b = el.jac * p.sigma_h;
    real det_b = (el.jac.x * el.jac.w - el.jac.z * el.jac.y) * p.sigma_h * p.sigma_h;
    real det_c = sr2 * sr2 + sr2 * dot(b, b) + det_b * det_b;
    vec2 d = s - vec2(el.us.z, el.us.w);
    vec2 ad = vec2(b.w * d.x - b.z * d.y, -b.y * d.x + b.x * d.y);
    real q = (sr2 * dot(d, d) + dot(ad, ad)) / det_c;
    return p.area * exp(real(-0.5) * q) * GLINT_INV_TWO_PI / sqrt(det_c);
}

// The lattice index range [lo, hi] of the elements inside the culling box on one axis (hi < lo:
// none), clamped to max_side steps around the centre.
GLINT_FN ivec2 glint_pndf_axis_range(real centre, real extent, real spacing, int max_side) {
    real c = centre / spacing - real(0.5);
    real e = extent / spacing;
    real lo = ceil(c - e);
    real hi = floor(c + e);
    real mid = floor(c + real(0.5));
    real cap = real(max_side);
    lo = max(lo, mid - cap);
    hi = min(hi, mid + cap);
    return ivec2(int(clamp(lo, real(-1e9), real(1e9))), int(clamp(hi, real(-1e9), real(1e9))));
}

GLINT_FN int glint_pndf_wrap(int i, int n) {
    int r = i - (i / n) * n;  // i % n without % on negative numbers
    return r < 0 ? r + n : r;
}

#if defined(GLINT_GLSL) && !defined(GLINT_ELEMENT_BUFFER_DECLARED) && defined(GLINT_ELEMENT_BINDING)
layout(std430, binding = GLINT_ELEMENT_BINDING) readonly buffer glint_element_buffer { vec4 glint_element_data[]; };
#endif
#if defined(GLINT_GLSL) && (defined(GLINT_ELEMENT_BUFFER_DECLARED) || defined(GLINT_ELEMENT_BINDING))
#define GLINT_HAS_ELEMENT_BUFFER
#endif
#if !defined(GLINT_GLSL)
#define GLINT_HAS_ELEMENT_BUFFER
#endif

#ifdef GLINT_HAS_ELEMENT_BUFFER
GLINT_FN glint_gaussian_element glint_pndf_load(GLINT_ELEMENT_DATA_PARAM int index) {
    glint_gaussian_element el;
    el.us = glint_element_data[2 * index];
    el.jac = glint_element_data[2 * index + 1];
    return el;
}

// The direct P-NDF D_P(s) = sum_i I_i(s) over the lattice points inside the culling box (each
// element at its periodic image's position), 0 for |s| >= 1. Cost: the box's lattice points.
GLINT_FN real glint_pndf_direct(GLINT_ELEMENT_DATA_PARAM glint_pndf_frame f, vec2 s, glint_pndf_params p) {
    if (!(dot(s, s) < real(1))) return real(0);
    ivec2 rx = glint_pndf_axis_range(f.mean.x, f.extent.x, p.spacing, p.max_side);
    ivec2 ry = glint_pndf_axis_range(f.mean.y, f.extent.y, p.spacing, p.max_side);
    real sum = real(0);
    for (int j = ry.x; j <= ry.y; ++j) {
        if (p.periodic == 0 && (j < 0 || j >= p.height)) continue;
        int wj = glint_pndf_wrap(j, p.height);
        for (int i = rx.x; i <= rx.y; ++i) {
            if (p.periodic == 0 && (i < 0 || i >= p.width)) continue;
            int wi = glint_pndf_wrap(i, p.width);
            glint_gaussian_element el = glint_pndf_load(GLINT_ELEMENT_DATA_ARG wi + p.width * wj);
            vec2 u_i = vec2((real(i) + real(0.5)) * p.spacing, (real(j) + real(0.5)) * p.spacing);
            sum += glint_pndf_element(el, u_i, f, s, p);
        }
    }
    return sum;
}
#endif
#undef GLINT_HAS_ELEMENT_BUFFER

// XTXW24 Eq. 1 for a P-NDF value d_p = D_P(h.xy) (D_P over the projected disk equals the NDF per
// solid angle, since ds = cos(theta_h) d omega_h): D G2 F / (4 cos_i cos_o), with Smith's G2 for
// `ndf` at roughness alpha_g and the conductor Fresnel (eta, k); 0 below either horizon.
GLINT_FN real glint_pndf_brdf(real d_p, vec3 wi, vec3 wo, int ndf, vec2 alpha_g, real eta, real k) {
    if (!(wi.z > real(0)) || !(wo.z > real(0))) return real(0);
    vec3 h = normalize(wi + wo);
    if (!(h.z > real(0))) return real(0);
    real g = glint_smith_g2(ndf, wi, wo, h, alpha_g);
    real fr = glint_fresnel_conductor(eta, k, dot(wi, h));
    return d_p * g * fr / (real(4) * wi.z * wo.z);
}
