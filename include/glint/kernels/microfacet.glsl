// glint microfacet basics: GGX and Beckmann NDFs with anisotropic roughness, Smith masking,
// Fresnel, the visible NDF, the total microfacet area D_H and the NDF integrated over a light
// (KK25 Eq. 8-9). Needs core.glsl. Derivations and measured errors: include/glint/microfacet.hpp
// and docs/microfacet.md.
//
// Conventions: every direction is a unit vector in the tangent frame, the macro-normal is +z;
// alpha = (alpha_x, alpha_y) is clamped to [GLINT_MIN_ROUGHNESS, GLINT_MAX_ROUGHNESS]. The
// standardized slope of a direction v with v.z > 0 is u = (v.x / (v.z alpha_x), v.y / (v.z alpha_y)):
// in it both NDFs are isotropic.

// GLINT_PI and GLINT_INV_TWO_PI: core.glsl.
GLINT_CONST(real) GLINT_SQRT_PI = real(1.77245385090551602730);  // 21 digits
GLINT_CONST(int) GLINT_NDF_GGX = 0;
GLINT_CONST(int) GLINT_NDF_BECKMANN = 1;
GLINT_CONST(real) GLINT_MIN_ROUGHNESS = real(1e-4);
GLINT_CONST(real) GLINT_MAX_ROUGHNESS = real(4);

GLINT_FN vec2 glint_clamp_roughness(vec2 alpha) {
    return clamp(alpha, vec2(GLINT_MIN_ROUGHNESS), vec2(GLINT_MAX_ROUGHNESS));
}

// D(m), per unit solid angle of m; 0 for m.z <= 0. GGX (Trowbridge-Reitz):
// 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2); Beckmann: exp(-|u|^2) / (pi ax ay mz^4).
GLINT_FN real glint_ndf(int ndf, vec3 m, vec2 alpha) {
    alpha = glint_clamp_roughness(alpha);
    if (!(m.z > real(0))) return real(0);
    real q = (m.x / alpha.x) * (m.x / alpha.x) + (m.y / alpha.y) * (m.y / alpha.y);
    if (ndf == GLINT_NDF_BECKMANN) {
        real c2 = m.z * m.z;
        real u2 = q / c2;
        return (u2 > real(87)) ? real(0) : exp(-u2) / (GLINT_PI * alpha.x * alpha.y * c2 * c2);
    }
    real t = q + m.z * m.z;
    return real(1) / (GLINT_PI * alpha.x * alpha.y * t * t);
}

// The density of microfacet area (unprojected, as the glint count uses it) per unit of absolute
// slope s = -(m.x, m.y) / m.z: P22(s) sqrt(1 + |s|^2), where P22 is the slope density of the
// projected area (KK25 Sec. 3.2: facets are distributed by D(h) / D_H). Even in s.
// Its roughness terms, inv_alpha = 1 / alpha and norm = 1 / (pi alpha.x alpha.y) for alpha clamped
// (glint_slope_density_terms), are the same at every slope: a caller that evaluates several
// slopes of one NDF (the grid's four slope corners per light) makes them once
// (glint_slope_area_density_at), one division a slope instead of four.
struct glint_slope_density_terms {
    vec2 inv_alpha;
    real norm;
};

GLINT_FN glint_slope_density_terms glint_slope_density_terms_of(vec2 alpha) {
    alpha = glint_clamp_roughness(alpha);
    glint_slope_density_terms t;
    t.inv_alpha = vec2(real(1)) / alpha;
    t.norm = real(1) / (GLINT_PI * alpha.x * alpha.y);
    return t;
}

GLINT_FN real glint_slope_area_density_at(int ndf, vec2 s, glint_slope_density_terms t) {
    vec2 r = s * t.inv_alpha;
    real u2 = r.x * r.x + r.y * r.y;
    real j = sqrt(real(1) + dot(s, s)) * t.norm;
    if (ndf == GLINT_NDF_BECKMANN) return (u2 > real(87)) ? real(0) : j * exp(-u2);
    return j / ((real(1) + u2) * (real(1) + u2));
}

GLINT_FN real glint_slope_area_density(int ndf, vec2 s, vec2 alpha) {
    return glint_slope_area_density_at(ndf, s, glint_slope_density_terms_of(alpha));
}

// Smith's Lambda(w) for w.z > 0 (returns 0 otherwise; callers use G1). With
// y^2 = (ax^2 wx^2 + ay^2 wy^2) / wz^2: GGX (sqrt(1 + y^2) - 1) / 2 written without cancellation;
// Beckmann exp(-1/y^2) (y / sqrt(pi) - erfcx(1/y)) / 2, the exact form (Walter et al. 2007
// Eq. 27 with erfc scaled), 0 below y = 0.1 where it is below 1e-43.
GLINT_FN real glint_smith_lambda(int ndf, vec3 w, vec2 alpha) {
    alpha = glint_clamp_roughness(alpha);
    if (!(w.z > real(0))) return real(0);
    real y2 = ((alpha.x * w.x) * (alpha.x * w.x) + (alpha.y * w.y) * (alpha.y * w.y)) / max(w.z * w.z, real(1e-30));
    if (ndf == GLINT_NDF_BECKMANN) {
        real y = sqrt(y2);
        if (y < real(0.1)) return real(0);
        return max(real(0), real(0.5) * exp(real(-1) / y2) * (y / GLINT_SQRT_PI - glint_erfcx_of_reciprocal(y)));
    }
    return y2 / (real(2) * (real(1) + sqrt(real(1) + y2)));
}

// Smith's masking G1(w, m) = chi(w.m) chi(w.z) / (1 + Lambda(w)).
GLINT_FN real glint_smith_g1(int ndf, vec3 w, vec3 m, vec2 alpha) {
    if (!(w.z > real(0)) || !(dot(w, m) > real(0))) return real(0);
    return real(1) / (real(1) + glint_smith_lambda(ndf, w, alpha));
}

// Height-correlated masking-shadowing G2(wi, wo, m) = 1 / (1 + Lambda(wi) + Lambda(wo)) (Heitz
// 2014, Eq. 99), 0 if either direction is below the horizon or back-facing to m.
GLINT_FN real glint_smith_g2(int ndf, vec3 wi, vec3 wo, vec3 m, vec2 alpha) {
    if (!(wi.z > real(0)) || !(wo.z > real(0)) || !(dot(wi, m) > real(0)) || !(dot(wo, m) > real(0))) return real(0);
    return real(1) / (real(1) + glint_smith_lambda(ndf, wi, alpha) + glint_smith_lambda(ndf, wo, alpha));
}

// Schlick's approximation F0 + (1 - F0)(1 - cos)^5; cos is clamped to [0, 1].
GLINT_FN real glint_fresnel_schlick(real f0, real cos_theta) {
    real c = clamp(real(1) - cos_theta, real(0), real(1));
    real c2 = c * c;
    return f0 + (real(1) - f0) * c2 * c2 * c;
}

// Exact Fresnel reflectance of unpolarised light at a conductor with complex index of refraction
// eta + i k (relative to the outside medium), for one wavelength: the real-arithmetic form of
// (|rs|^2 + |rp|^2) / 2. cos is clamped to [0, 1], eta to >= 1e-4, k to >= 0.
GLINT_FN real glint_fresnel_conductor(real eta, real k, real cos_theta) {
    real c = clamp(cos_theta, real(0), real(1));
    eta = max(eta, real(1e-4));
    k = max(k, real(0));
    real c2 = c * c;
    real s2 = real(1) - c2;
    real t0 = eta * eta - k * k - s2;
    real a2b2 = sqrt(t0 * t0 + real(4) * eta * eta * k * k);  // a^2 + b^2
    // a^2 = (a2b2 + t0) / 2, rationalised where t0 < 0 (it cancels for small eta and k):
    // (a2b2 + t0)(a2b2 - t0) = 4 eta^2 k^2.
    real a = sqrt(max((t0 >= real(0)) ? real(0.5) * (a2b2 + t0) : real(2) * eta * eta * k * k / max(a2b2 - t0, real(1e-30)), real(0)));
    real t1 = a2b2 + c2;
    real t2 = real(2) * a * c;
    real rs = (t1 - t2) / (t1 + t2);
    real t3 = c2 * a2b2 + s2 * s2;
    real t4 = t2 * s2;
    real rp = rs * (t3 - t4) / (t3 + t4);
    return real(0.5) * (rs + rp);
}

// The visible NDF D_wo(m) = G1(wo, m) max(0, wo.m) D(m) / wo.z (Heitz 2014, Eq. 38), a density
// over m that integrates to 1 for wo.z > 0; 0 for wo.z <= 0.
GLINT_FN real glint_vndf(int ndf, vec3 wo, vec3 m, vec2 alpha) {
    if (!(wo.z > real(0))) return real(0);
    return glint_smith_g1(ndf, wo, m, alpha) * max(real(0), dot(wo, m)) * glint_ndf(ndf, m, alpha) / wo.z;
}

// A sample of the GGX visible NDF for wo.z > 0 from u1, u2 in [0, 1): the hemisphere of the
// stretched configuration sampled as a spherical cap (Dupuy and Benyoub 2023, "Sampling Visible
// GGX Normals with Spherical Caps", Listing 3). Returns +z for wo.z <= 0.
GLINT_FN vec3 glint_sample_vndf_ggx(vec3 wo, vec2 alpha, real u1, real u2) {
    alpha = glint_clamp_roughness(alpha);
    if (!(wo.z > real(0))) return vec3(real(0), real(0), real(1));
    vec3 ws = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
    real phi = real(2) * GLINT_PI * u1;
    real z = (real(1) - u2) * (real(1) + ws.z) - ws.z;
    real r = sqrt(clamp(real(1) - z * z, real(0), real(1)));
    vec3 hs = vec3(r * cos(phi), r * sin(phi), z) + ws;
    return normalize(vec3(alpha.x * hs.x, alpha.y * hs.y, max(hs.z, real(0))));
}

// ---------------------------------------------------------------------------------------------
// Radial integrals. In standardized slope u (|u|^2 = T) both NDFs are isotropic: the projected
// area has density rho(|u|) = 1 / (pi (1 + T)^2) (GGX) or exp(-T) / pi (Beckmann) per unit u, and
// the unprojected area (which D_H and p count) has rho sqrt(1 + |s|^2) with |s|^2 = a2 T, where
// a2 = (ax^2 ux^2 + ay^2 uy^2) / T depends only on the direction of u. Along a ray of direction
// phi, mass(T) = integral_0^R rho sqrt(1 + a2 r^2) r dr (R^2 = T), tail(T) = the same from R to
// infinity; the total 2 pi tail(0) averaged over phi is D_H. Closed forms (derived in
// include/glint/microfacet.hpp), with W = sqrt(1 + a2 T) and
// g(z) = atanh(sqrt z) / sqrt z (z > 0), atan(sqrt -z) / sqrt -z (z < 0).

// g(z), given also 1 - z (computed by the caller without cancellation). Series below |z| = 0.01
// (truncation error below z^4 / 9 = 1.1e-9).
GLINT_FN real glint_atanh_ratio(real z, real one_minus_z) {
    if (abs(z) < real(0.01)) return real(1) + z * (real(1) / real(3) + z * (real(1) / real(5) + z * (real(1) / real(7))));
    real r = sqrt(abs(z));
    if (z < real(0)) return atan(r) / r;
    real one_minus_r = one_minus_z / (real(1) + r);
    return real(0.5) * glint_log1p(real(2) * r / one_minus_r) / r;
}

// mass(T) / T, which tends to 1 / (2 pi) as T -> 0.
GLINT_FN real glint_radial_mass_over_t(int ndf, real T, real a2) {
    if (!(T > real(1e-20))) return GLINT_INV_TWO_PI;
    real W = sqrt(real(1) + a2 * T);
    if (ndf == GLINT_NDF_BECKMANN) {
        if (T * max(a2, real(1)) <= real(0.5)) {
            // The closed form cancels for small T: 4-point Gauss-Legendre of the mean of
            // sqrt(1 + a2 t) exp(-t) over [0, T] instead (the nearest singularity, t = -1/a2, is
            // 2 interval lengths away: error below 1e-8, below the erfc fit's 1.2e-7).
            real t1 = T * real(0.0694318442029737), t2 = T * real(0.330009478207572);
            real t3 = T * real(0.669990521792428), t4 = T * real(0.930568155797026);
            real m = real(0.173927422568727) * (sqrt(real(1) + a2 * t1) * exp(-t1) + sqrt(real(1) + a2 * t4) * exp(-t4)) +
                     real(0.326072577431273) * (sqrt(real(1) + a2 * t2) * exp(-t2) + sqrt(real(1) + a2 * t3) * exp(-t3));
            return GLINT_INV_TWO_PI * m;
        }
        real a = sqrt(a2);
        real e = exp(-T);
        real m = -glint_expm1_nonpositive(-T) - e * a2 * T / (W + real(1)) +
                 real(0.5) * a * GLINT_SQRT_PI * (glint_erfcx_of_reciprocal(a) - e * glint_erfcx_of_reciprocal(a / W));
        return GLINT_INV_TWO_PI * m / T;
    }
    real d = W + real(1) + T;
    real first = (real(1) - a2 / (W + real(1))) / (real(1) + T);
    real z = (real(1) - a2) * (T / d) * (T / d);
    real wd = (W + real(1)) / d;
    real td = T / d;
    real one_minus_z = wd * wd + real(2) * td * wd + a2 * td * td;  // no overflow up to T = 1e30
    return GLINT_INV_TWO_PI * (first + a2 * glint_atanh_ratio(z, one_minus_z) / d);
}

// tail(T); tail(0) = the total along the ray.
GLINT_FN real glint_radial_tail(int ndf, real T, real a2) {
    T = max(T, real(0));
    real W = sqrt(real(1) + a2 * T);
    if (ndf == GLINT_NDF_BECKMANN)
        return GLINT_INV_TWO_PI * exp(-T) * (W + real(0.5) * sqrt(a2) * GLINT_SQRT_PI * glint_erfcx_of_reciprocal(sqrt(a2) / W));
    real W2 = W * W;
    return GLINT_INV_TWO_PI * (W / (real(1) + T) + a2 * glint_atanh_ratio((real(1) - a2) / W2, a2 * (real(1) + T) / W2) / W);
}

// D_H = integral of D(m) over the hemisphere = E[sqrt(1 + |s|^2)] under the slope density (>= 1).
// Isotropic: one closed form. Anisotropic: the average of 2 pi tail(0) over phi by the midpoint
// rule on [0, pi/2] with 32 nodes (a2(phi) is smooth, even and pi-periodic, so the rule converges
// geometrically: measured relative error 5e-10 for GGX at aspect ratio 16, 2e-8 at 1000; 1e-14
// for Beckmann). Call it once per material, not per pixel.
GLINT_FN real glint_total_area(int ndf, vec2 alpha) {
    alpha = glint_clamp_roughness(alpha);
    if (alpha.x == alpha.y) return real(2) * GLINT_PI * glint_radial_tail(ndf, real(0), alpha.x * alpha.x);
    real sum = real(0);
    for (int k = 0; k < 32; ++k) {
        real phi = (real(k) + real(0.5)) * (real(0.5) * GLINT_PI / real(32));
        real c = cos(phi), s = sin(phi);
        sum += glint_radial_tail(ndf, real(0), alpha.x * alpha.x * c * c + alpha.y * alpha.y * s * s);
    }
    return real(2) * GLINT_PI * sum / real(32);
}

// ---------------------------------------------------------------------------------------------
// The NDF integrated over a light, D_Omega = integral over the light's solid angle of
// D(h) / (4 <h, wi>) d wi (KK25 Eq. 9) = the microfacet area whose normals reflect wo into the
// light. Method (derived in include/glint/microfacet.hpp): the region of half vectors, in
// standardized slope space, has area mass = closed curve integral of (mass(T) / T) (u x du)
// (Green's theorem with the radial closed forms above), or, when the curve neither encloses nor
// comes near u = 0, minus the integral of (tail(T) / T) (u x du), which keeps the relative
// precision of a small result. The light's boundary (clipped to the upper hemisphere) is mapped
// to u exactly; each curve is split into pieces integrated by 4-point Gauss-Legendre.

// One boundary curve: kind 0 is a straight segment in space, P(t) = p + t q, seen from the shading
// point at the origin (wi = P / |P|); kind 1 an arc of a cone, wi = p + cos(psi) q + sin(psi) r
// with psi = range.x + t (range.y - range.x). At most 6 curves (a rectangle clipped to the
// hemisphere has at most 5 edges).
struct glint_light_boundary {
    int count;
    int kind[6];
    vec3 p[6];
    vec3 q[6];
    vec3 r[6];
    vec2 range[6];
};

// One curve of a boundary, copied out of it (small, so that the inner loops pass little).
struct glint_boundary_curve {
    int kind;
    vec3 p;
    vec3 q;
    vec3 r;
    vec2 range;
};

GLINT_FN glint_boundary_curve glint_boundary_curve_of(glint_light_boundary b, int i) {
    glint_boundary_curve c;
    c.kind = b.kind[i];
    c.p = b.p[i];
    c.q = b.q[i];
    c.r = b.r[i];
    c.range = b.range[i];
    return c;
}

struct glint_boundary_point {
    vec3 wi;
    vec3 dwi;  // d wi / d t
};

GLINT_FN glint_boundary_point glint_boundary_eval(glint_boundary_curve b, real t) {
    glint_boundary_point o;
    if (b.kind == 1) {
        real dpsi = b.range.y - b.range.x;
        real psi = b.range.x + t * dpsi;
        real c = cos(psi), s = sin(psi);
        o.wi = b.p + c * b.q + s * b.r;
        o.dwi = (c * b.r - s * b.q) * dpsi;
        return o;
    }
    vec3 P = b.p + t * b.q;
    real len = max(length(P), real(1e-30));
    o.wi = P / len;
    o.dwi = (b.q - o.wi * dot(o.wi, b.q)) / len;
    return o;
}

// The standardized slope of the half vector of (wi, wo), unnormalised v = wi + wo; components
// clamped to 1e15 (T <= 1e30) so that half vectors at the horizon stay finite.
GLINT_FN vec2 glint_standardized_slope(vec3 v, vec2 alpha) {
    real z = max(v.z, real(1e-30));
    return clamp(vec2(v.x / alpha.x, v.y / alpha.y) / z, vec2(real(-1e15)), vec2(real(1e15)));
}

// The integrand at one boundary point: mass(T) (or -tail(T)) times d phi / dt, where
// phi = atan2(v.y / ay, v.x / ax) is the polar angle of u (v.z cancels, so half vectors at the
// horizon, T -> inf, are harmless).
GLINT_FN real glint_boundary_integrand(int ndf, vec3 wo, vec2 alpha, glint_boundary_point bp, bool tail_form) {
    vec3 v = bp.wi + wo;
    vec2 g = vec2(v.x / alpha.x, v.y / alpha.y);
    real q = dot(g, g);  // T v.z^2
    if (!(q > real(0))) return real(0);
    real T = min(q / max(v.z * v.z, real(1e-37)), real(1e30));
    real a2 = (v.x * v.x + v.y * v.y) / q;
    real dphi = (v.x * bp.dwi.y - v.y * bp.dwi.x) / (alpha.x * alpha.y * q);
    real f = tail_form ? -glint_radial_tail(ndf, T, a2) : glint_radial_mass_over_t(ndf, T, a2) * T;
    return f * dphi;
}

GLINT_FN int glint_boundary_pieces(glint_boundary_curve b, int pieces) {
    return (b.kind == 1) ? 2 * pieces : pieces;
}

// The pass-1 samples of a curve: 4 per piece, at t = k / (4 n).
GLINT_FN vec2 glint_boundary_sample(glint_boundary_curve b, real t, vec3 wo, vec2 alpha) {
    return glint_standardized_slope(glint_boundary_eval(b, t).wi + wo, alpha);
}

// How much of the integrand's variation a chord from a to b sweeps: the polar angle it subtends,
// with distances below 1 (one roughness, where the radial mass is still growing) counted as 1.
GLINT_FN real glint_chord_sweep(vec2 a, vec2 b) {
    vec2 mid = real(0.5) * (a + b);
    return abs(a.x * b.y - a.y * b.x) / max(dot(mid, mid), real(1));
}

// Gauss-Legendre with 4 nodes on [t0, t1] of a curve: nodes 1/2 -+ 0.339981043584856 / 2 and
// 1/2 -+ 0.861136311594053 / 2, weights 0.652145154862546 / 2 and 0.347854845137454 / 2
// (Abramowitz and Stegun, Table 25.4).
GLINT_FN real glint_boundary_piece(int ndf, vec3 wo, vec2 alpha, glint_boundary_curve b, real t0, real t1, bool tail_form) {
    real h = t1 - t0;
    real s = real(0.326072577431273) * (glint_boundary_integrand(ndf, wo, alpha, glint_boundary_eval(b, t0 + h * real(0.330009478207572)), tail_form) +
                                        glint_boundary_integrand(ndf, wo, alpha, glint_boundary_eval(b, t0 + h * real(0.669990521792428)), tail_form));
    s += real(0.173927422568727) * (glint_boundary_integrand(ndf, wo, alpha, glint_boundary_eval(b, t0 + h * real(0.0694318442029737)), tail_form) +
                                    glint_boundary_integrand(ndf, wo, alpha, glint_boundary_eval(b, t0 + h * real(0.930568155797026)), tail_form));
    return s * h;
}

// D_Omega over the region bounded by b, wo.z > 0. `pieces` (clamped to [4, 64]): pieces per
// straight edge; an arc gets twice as many. Measured accuracy and cost per value: docs/grid.md.
//
// Where the pieces go. Near the point where a curve passes u = 0 at distance d, the integrand
// varies on a length max(d, 1) in u (like d(phi)/dt), which can be a tiny part of a long curve.
// Pass 1 samples each curve (4 samples per piece) and measures, chord by chord, the polar angle
// swept (glint_chord_sweep); pass 2 places the piece ends where half the sweep plus half the
// parameter reach k / n, interpolating between samples, so that pieces crowd where the integrand
// varies and still cover the rest. Any placement is exact (only the quadrature error changes).
GLINT_FN real glint_integrated_ndf_boundary(int ndf, vec3 wo, vec2 alpha, glint_light_boundary b, int pieces) {
    alpha = glint_clamp_roughness(alpha);
    pieces = clamp(pieces, 4, 64);
    if (!(wo.z > real(0)) || b.count < 1) return real(0);
    // Pass 1: the sweep of each curve, the winding number around u = 0, and the clearance
    // min over chords of (distance to u = 0 - chord length / 4), which picks the form.
    real winding = real(0);
    real clearance = real(3.0e38);
    real sweep[6];
    for (int i = 0; i < b.count; ++i) {
        glint_boundary_curve curve = glint_boundary_curve_of(b, i);
        int m = 4 * glint_boundary_pieces(curve, pieces);
        vec2 prev = glint_boundary_sample(curve, real(0), wo, alpha);
        sweep[i] = real(0);
        for (int k = 1; k <= m; ++k) {
            vec2 next = glint_boundary_sample(curve, real(k) / real(m), wo, alpha);
            vec2 e = next - prev;
            real e2 = dot(e, e);
            real s = (e2 > real(0)) ? clamp(-dot(prev, e) / e2, real(0), real(1)) : real(0);
            clearance = min(clearance, length(prev + s * e) - real(0.25) * sqrt(e2));
            winding += atan(prev.x * next.y - prev.y * next.x, dot(prev, next));
            sweep[i] += glint_chord_sweep(prev, next);
            prev = next;
        }
    }
    bool tail_form = abs(winding) < real(3.14159) && clearance >= real(1);
    // Pass 2.
    real sum = real(0);
    for (int i = 0; i < b.count; ++i) {
        glint_boundary_curve curve = glint_boundary_curve_of(b, i);
        int n = glint_boundary_pieces(curve, pieces);
        int m = 4 * n;
        real dt = real(1) / real(m);
        real mu_prev = real(0);
        real t_start = real(0);
        int done = 0;  // pieces integrated so far
        vec2 prev = glint_boundary_sample(curve, real(0), wo, alpha);
        for (int k = 1; k <= m; ++k) {
            vec2 next = glint_boundary_sample(curve, real(k) * dt, wo, alpha);
            real mu = mu_prev + real(0.5) * dt + ((sweep[i] > real(0)) ? real(0.5) * glint_chord_sweep(prev, next) / sweep[i] : real(0.5) * dt);
            mu = (k == m) ? real(1) : mu;
            for (int j = 0; j < 4 * 64; ++j) {  // the piece ends inside this sample interval
                real target = real(done + 1) / real(n);
                if (done >= n || target > mu) break;
                real t_end = (done + 1 == n) ? real(1) : real(k - 1) * dt + dt * clamp((target - mu_prev) / max(mu - mu_prev, real(1e-30)), real(0), real(1));
                sum += glint_boundary_piece(ndf, wo, alpha, curve, t_start, t_end, tail_form);
                t_start = t_end;
                ++done;
            }
            mu_prev = mu;
            prev = next;
        }
    }
    return abs(sum);
}

// A boundary with no curves (every member set: GLSL has no default initialisation).
GLINT_FN glint_light_boundary glint_empty_boundary() {
    glint_light_boundary b;
    b.count = 0;
    for (int i = 0; i < 6; ++i) {
        b.kind[i] = 0;
        b.p[i] = vec3(real(0));
        b.q[i] = vec3(real(0));
        b.r[i] = vec3(real(0));
        b.range[i] = vec2(real(0));
    }
    return b;
}

// The boundary of a cone of directions (a spherical light seen from the shading point, or the
// sun): axis c (unit), angular radius with cosine cos_r and sine sin_r; the part below the
// horizon is cut off along the horizon. count = 0 if nothing is above the horizon.
GLINT_FN glint_light_boundary glint_cone_boundary(vec3 c, real cos_r, real sin_r) {
    glint_light_boundary b = glint_empty_boundary();
    real h = length(vec2(c.x, c.y));  // horizontal extent of the axis (not sqrt(1 - c.z^2): cancels near the zenith)
    if (c.z * cos_r + h * sin_r <= real(0)) return b;
    vec3 t1 = (h > real(1e-7)) ? vec3(-c.y, c.x, real(0)) / h : vec3(real(1), real(0), real(0));
    vec3 t2 = cross(c, t1);  // t2.z = h >= 0
    b.kind[0] = 1;
    b.p[0] = cos_r * c;
    b.q[0] = sin_r * t1;
    b.r[0] = sin_r * t2;
    b.count = 1;
    if (c.z * cos_r - h * sin_r >= real(0)) {
        b.range[0] = vec2(real(0), real(2) * GLINT_PI);
        return b;
    }
    // Above the horizon where sin(psi) > s: psi in (asin s, pi - asin s); closed by the chord
    // along the horizon (in the cap's plane, so its directions lie on the horizon great circle).
    real s = clamp(-cos_r * c.z / (sin_r * h), real(-1), real(1));
    real psi0 = asin(s);
    b.range[0] = vec2(psi0, GLINT_PI - psi0);
    vec3 from = b.p[0] + cos(GLINT_PI - psi0) * b.q[0] + sin(GLINT_PI - psi0) * b.r[0];
    vec3 to = b.p[0] + cos(psi0) * b.q[0] + sin(psi0) * b.r[0];
    b.kind[1] = 0;
    b.p[1] = vec3(from.x, from.y, real(0));
    b.q[1] = vec3(to.x - from.x, to.y - from.y, real(0));
    b.count = 2;
    return b;
}

// The boundary of a one-sided rectangular light with corners p0, p0 + e1, p0 + e1 + e2, p0 + e2
// (relative to the shading point, tangent frame), emitting toward cross(e1, e2); clipped to
// z >= 0 (Sutherland-Hodgman). count = 0 if the shading point sees its back or nothing of it.
GLINT_FN glint_light_boundary glint_rect_boundary(vec3 p0, vec3 e1, vec3 e2) {
    glint_light_boundary b = glint_empty_boundary();
    if (!(dot(cross(e1, e2), p0) < real(0))) return b;  // behind the light, or in its plane
    vec3 corner[4];
    corner[0] = p0;
    corner[1] = p0 + e1;
    corner[2] = p0 + e1 + e2;
    corner[3] = p0 + e2;
    vec3 clipped[6];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        vec3 a = corner[i];
        vec3 c = corner[(i + 1) & 3];
        bool a_in = a.z >= real(0);
        bool c_in = c.z >= real(0);
        if (a_in) clipped[n++] = a;
        if (a_in != c_in) {
            real t = a.z / (a.z - c.z);
            vec3 x = a + t * (c - a);
            clipped[n++] = vec3(x.x, x.y, real(0));
        }
    }
    if (n < 3) return b;
    for (int i = 0; i < n; ++i) {
        b.p[i] = clipped[i];
        b.q[i] = clipped[(i + 1 < n) ? i + 1 : 0] - clipped[i];
    }
    b.count = n;
    return b;
}

// D_Omega for a cone of directions (sphere light, sun).
GLINT_FN real glint_integrated_ndf_cone(int ndf, vec3 wo, vec2 alpha, vec3 axis, real cos_radius, real sin_radius, int pieces) {
    return glint_integrated_ndf_boundary(ndf, wo, alpha, glint_cone_boundary(axis, cos_radius, sin_radius), pieces);
}

// D_Omega for a rectangle (see glint_rect_boundary).
GLINT_FN real glint_integrated_ndf_rect(int ndf, vec3 wo, vec2 alpha, vec3 p0, vec3 e1, vec3 e2, int pieces) {
    return glint_integrated_ndf_boundary(ndf, wo, alpha, glint_rect_boundary(p0, e1, e2), pieces);
}
