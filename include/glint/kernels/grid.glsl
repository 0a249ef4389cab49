// glint's discrete glint NDF on anisotropic grids (DB23, as KK24 and KK25 Sec. 3.3 use it;
// ../notes/anisotropic-grid.md in the repository that built this). Needs core.glsl,
// binomial.glsl, microfacet.glsl. Derivation, parameters and measured figures:
// include/glint/grid.hpp and docs/grid.md.
//
// The estimate for one pixel footprint and one light is R = sum over lattice points L (4, weights
// w_L), triangle vertices t (3, barycentrics l_t) and slope-grid vertices j (4, bilinear m_j) of
// l_t m_j c / N, where N = density x footprint area is the expected number of microfacets in
// the footprint and c ~ b(N w_L, p_j) is drawn with the vertex's own random numbers (DB23's
// "distributed" binomial laws). E[R] = sum_j m_j p_j. The glint BRDF is the smooth one times
// R / E[R] (KK25 Eq. 7 with E[N_P] = N), whose mean is the smooth BRDF exactly.

// The pixel footprint in uv: the ellipse of J^T J, J's rows the uv derivatives along x and y.
struct glint_footprint {
    real area;   // |det J|, the pixel's parallelogram in uv
    real minor;  // semi-axis lengths of the ellipse (square roots of J^T J's eigenvalues)
    real major;
    real angle;  // direction of the major axis, in [0, pi)
};

GLINT_FN glint_footprint glint_footprint_from_derivatives(vec2 duvdx, vec2 duvdy) {
    glint_footprint f;
    real a = duvdx.x * duvdx.x + duvdy.x * duvdy.x;
    real b = duvdx.x * duvdx.y + duvdy.x * duvdy.y;
    real c = duvdx.y * duvdx.y + duvdy.y * duvdy.y;
    real det = abs(duvdx.x * duvdy.y - duvdx.y * duvdy.x);
    real half_diff = real(0.5) * (a - c);
    real l2 = real(0.5) * (a + c) + sqrt(half_diff * half_diff + b * b);
    f.area = det;
    f.major = sqrt(l2);
    f.minor = (l2 > real(0)) ? det / f.major : real(0);  // sqrt(det^2 / l2) without cancellation
    // glint_atan2 (core.glsl, 3.5 ulp: docs/conventions.md) rather than the builtin: bit-identical
    // in C++ and GLSL, whose atan has no stated precision, and in C++ about a third of the
    // instructions of libm's atan2f (callgrind: 134 a call in glint_frame_loop point-stochastic 2).
    real angle = real(0.5) * glint_atan2(real(2) * b, a - c);  // [-pi/2, pi/2]
    f.angle = (angle < real(0)) ? angle + GLINT_PI : angle;
    f.angle = (f.angle >= GLINT_PI) ? real(0) : f.angle;
    return f;
}

// The lattice of grids: LOD L (cell size 2^L in uv), ratio level R (cells 2^R times longer
// along the major axis, R = 0..4), rotation bin k (level 0: one bin, isotropic; level R >= 1:
// 2^(R+1) bins over [0, pi), 90 degrees / 2^R as in DB23, each level doubling the one below).
GLINT_CONST(int) GLINT_MAX_RATIO_LEVEL = 4;  // aspect ratios are clamped to 2^4 = 16
GLINT_CONST(real) GLINT_MIN_LOD = real(-24);
GLINT_CONST(real) GLINT_MAX_LOD = real(24);

// Plain arrays, not vec4: a vector indexed in a loop costs a switch per access in C++.
struct glint_lattice {
    real weight[4];
    int lod[4];
    int level[4];
    int bin[4];
};

GLINT_FN glint_lattice glint_lattice_points(vec4 weight, ivec4 lod, ivec4 level, ivec4 bin) {
    glint_lattice o;
    weight = max(weight, vec4(real(0)));
    for (int i = 0; i < 4; ++i) {  // constant indices once unrolled
        o.weight[i] = weight[i];
        o.lod[i] = lod[i];
        o.level[i] = level[i];
        o.bin[i] = bin[i];
    }
    return o;
}

// The four lattice points around a footprint and their weights (sum 1, continuous in the
// footprint). In the (ratio, angle) plane, the strip between levels R0 and R0 + 1 is
// triangulated conformingly (one coarse bin against two fine ones: triangles A, B, C below;
// between levels 0 and 1 a fan from the single isotropic vertex);
// each triangle times [L0, L0 + 1] is a prism, split into three tetrahedra by the global order
// of its vertices, so that neighbouring prisms agree on their shared faces.
GLINT_FN glint_lattice glint_footprint_lattice(glint_footprint f, real lod_scale) {
    real major = max(f.major, real(1e-30));
    real minor = max(max(f.minor, major / real(16)), real(1e-30));
    // glint_log2 (core.glsl): the same bits in C++, GLSL and the IBL's lanes (ibl.glsl).
    real lod = clamp(glint_log2(minor * max(lod_scale, real(1e-30))), GLINT_MIN_LOD, GLINT_MAX_LOD);
    real rho = clamp(glint_log2(major / minor), real(0), real(GLINT_MAX_RATIO_LEVEL));
    int r0 = min(int(glint_floor_bounded(rho)), GLINT_MAX_RATIO_LEVEL - 1);
    real tr = rho - real(r0);
    real l0 = glint_floor_bounded(lod);
    real tl = lod - l0;
    // Triangle in the (angle, tr) strip: vertex keys level * 1024 + bin, barycentrics.
    ivec3 key;
    vec3 bary;
    int lo = r0 * 1024, hi = (r0 + 1) * 1024;
    if (r0 == 0) {
        // Level 0 is isotropic: one vertex whatever the angle (which is ill-defined for round
        // footprints), fanned to level 1's 4 bins: weights 1 - tr and tr split linearly in angle.
        real x = f.angle * real(4) / GLINT_PI;
        int j = min(int(glint_floor_bounded(x)), 3);
        real fx = x - real(j);
        key = ivec3(lo, hi + j, hi + ((j + 1) & 3));
        bary = vec3(real(1) - tr, tr * (real(1) - fx), tr * fx);
    } else {
        int n0 = 2 << r0;  // bins at level r0 >= 1 (level 1: 4, as DB23's 45 degrees)
        real x = f.angle * real(n0) / GLINT_PI;
        int k = min(int(glint_floor_bounded(x)), n0 - 1);
        real fx = x - real(k);
        int kn = (k + 1 == n0) ? 0 : k + 1;
        int t0 = 2 * k, t1 = 2 * k + 1, t2 = (2 * k + 2 == 2 * n0) ? 0 : 2 * k + 2;
        if (fx < real(0.5) * tr) {  // A: b_k, t_2k, t_2k+1
            key = ivec3(lo + k, hi + t0, hi + t1);
            bary = vec3(real(1) - tr, tr - real(2) * fx, real(2) * fx);
        } else if (fx > real(1) - real(0.5) * tr) {  // C: b_k+1, t_2k+1, t_2k+2
            real gx = real(1) - fx;
            key = ivec3(lo + kn, hi + t1, hi + t2);
            bary = vec3(real(1) - tr, real(2) * gx, tr - real(2) * gx);
        } else {  // B: b_k, t_2k+1, b_k+1
            key = ivec3(lo + k, hi + t1, lo + kn);
            bary = vec3(real(1) - fx - real(0.5) * tr, tr, fx - real(0.5) * tr);
        }
    }
    bary = max(bary, vec3(real(0)));
    // Sort the three vertices by key (the global order the prism split needs).
    if (key.x > key.y) { ivec2 s = ivec2(key.x, key.y); key.x = s.y; key.y = s.x; real b = bary.x; bary.x = bary.y; bary.y = b; }
    if (key.y > key.z) { ivec2 s = ivec2(key.y, key.z); key.y = s.y; key.z = s.x; real b = bary.y; bary.y = bary.z; bary.z = b; }
    if (key.x > key.y) { ivec2 s = ivec2(key.x, key.y); key.x = s.y; key.y = s.x; real b = bary.x; bary.x = bary.y; bary.y = b; }
    // Prism split: v1 < v2 < v3 at L0 (unprimed) and L0 + 1 (primed).
    int L0 = int(l0);
    ivec3 level = key / 1024;
    ivec3 bin = key & 1023;
    if (tl <= bary.x)  // v1, v2, v3, v1'
        return glint_lattice_points(vec4(bary.x - tl, bary.y, bary.z, tl), ivec4(L0, L0, L0, L0 + 1),
                                    ivec4(level, level.x), ivec4(bin, bin.x));
    if (tl <= bary.x + bary.y)  // v1', v2, v3, v2'
        return glint_lattice_points(vec4(bary.x, bary.x + bary.y - tl, bary.z, tl - bary.x), ivec4(L0 + 1, L0, L0, L0 + 1),
                                    ivec4(level, level.y), ivec4(bin, bin.y));
    // v1', v2', v3, v3'
    return glint_lattice_points(vec4(bary.x, bary.y, real(1) - tl, tl - bary.x - bary.y), ivec4(L0 + 1, L0 + 1, L0, L0 + 1),
                                ivec4(level, level.z), ivec4(bin, bin.z));
}

// cos and sin of a lattice rotation, bin * pi / 2^(level + 1) = k pi / 32 (level <= 4), from
// the correctly rounded values of cos(j pi / 32), j = 0..8 (mpmath, 22 digits) and the
// symmetries cos(pi/2 - x) = sin x, cos(x + pi/2) = -sin x: exact to the last bit, and without
// the libm calls, which cost about a tenth of a point-light estimate.
GLINT_FN vec2 glint_lattice_rotation(int level, int bin) {
    int k = (bin << (GLINT_MAX_RATIO_LEVEL - level)) & 31;
    int m = k & 15;
    int j = min(m, 16 - m);
    real c = real(1), s = real(0);
    switch (j) {
        case 1: c = real(0.9951847266721968862448); s = real(0.0980171403295606019942); break;
        case 2: c = real(0.9807852804032304491262); s = real(0.1950903220161282678483); break;
        case 3: c = real(0.9569403357322088649358); s = real(0.2902846772544623676362); break;
        case 4: c = real(0.9238795325112867561282); s = real(0.3826834323650897717285); break;
        case 5: c = real(0.8819212643483550297128); s = real(0.4713967368259976485564); break;
        case 6: c = real(0.8314696123025452370788); s = real(0.5555702330196022247428); break;
        case 7: c = real(0.7730104533627369608109); s = real(0.6343932841636454982152); break;
        case 8: c = real(0.7071067811865475244008); s = real(0.7071067811865475244008); break;
        default: break;
    }
    vec2 r = (m > 8) ? vec2(s, c) : vec2(c, s);    // m pi / 32 in [0, pi/2)
    return (k >= 16) ? vec2(-r.y, r.x) : r;         // plus pi/2
}

// A triangle of the skewed (equilateral, side 1) grid containing q, and q's barycentrics.
struct glint_triangle {
    ivec2 vertex[3];
    real weight[3];
};

GLINT_FN glint_triangle glint_triangle_grid(vec2 q) {
    vec2 s = vec2(q.x - q.y * real(0.577350269189625764509), q.y * real(1.15470053837925152902));  // 1/sqrt(3), 2/sqrt(3)
    s = clamp(s, vec2(real(-1073741824)), vec2(real(1073741824)));  // keep glint_floor_bounded within its range
    vec2 i = glint_floor_bounded(s);
    vec2 f = s - i;
    ivec2 base = ivec2(int(i.x), int(i.y));
    // Lower triangle (f.x + f.y < 1): base, base + (1, 0), base + (0, 1); upper: base + (1, 1),
    // base + (0, 1), base + (1, 0). Written as selects, not a branch: the choice is a coin flip
    // per lattice point, and its mispredictions took about a fifth of glint_footprint_vertices'
    // time (perf, glint_frame_loop point).
    bool upper = !(f.x + f.y < real(1));
    int u = upper ? 1 : 0;
    glint_triangle t;
    t.vertex[0] = base + ivec2(u, u);
    t.vertex[1] = base + ivec2(1 - u, u);
    t.vertex[2] = base + ivec2(u, 1 - u);
    // Lower: 1 - f.x - f.y, f.x, f.y; upper: their negatives plus (0, 1, 1); as absolute values,
    // which compile without a branch (GCC compiled a select of two floats to a branch).
    real uf = real(u);
    t.weight[0] = glint_abs(real(1) - f.x - f.y);
    t.weight[1] = glint_abs(uf - f.x);
    t.weight[2] = glint_abs(uf - f.y);
    return t;
}

// The key that seeds a lattice point's vertex hashes: its lod, level and bin, and the material's seed.
GLINT_FN uint glint_lattice_key(int lod, int level, int bin, uint seed) {
    return (uint(lod + 64) | (uint(level) << 8u) | (uint(bin) << 12u)) ^ seed;
}

#if !defined(GLINT_GLSL)
// C++ only: glint_lattice_rotation and glint_triangle_grid for the four lattice points at once, in
// four lanes of GCC's vector extension (SSE2 registers for float, the x86-64 baseline): the same
// operations in the same order, so the same bits (tests/unit/test_grid.cpp). The rotations come
// from a table of glint_lattice_rotation's 32 values. One lattice point at a time, the floors
// alone (a branch each, its direction a coin toss) drew 15% of glint_footprint_vertices' perf
// samples in glint_frame_loop point; in lanes the point frame took 4% less time (DEVELOPERS.md).
struct glint_lattice_triangles {
    real weight[3][4];  // of vertex t of lattice point l
    uint hash[3][12];   // PCG3D of vertex t of lattice point l, its cell (x, y) and its lattice
                        // point's key: word c at hash[c][4 t + l]
};

// The twelve vertices' PCG3D words from their cells' coordinates, four lattice points a vector
// per triangle vertex t, and the lattice points' keys: out[c][4 t + l]. Hashed here, from the
// vectors the triangles are computed in, rather than gathered from the compacted vertex array
// (glint_pcg3d_many): the gather's inserts and its loads of words stored one by one drew most of
// glint_pcg3d_many_x8's perf samples in the point-light frame. Eight and four lanes in AVX2
// registers where the CPU has them; the baseline one vertex at a time (SSE2 emulates the 32-bit
// multiply: core.glsl's glint_pcg3d_many). The same words as glint_pcg3d.
typedef uint glint_u32x4 __attribute__((vector_size(16)));
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
GLINT_LANES_BODY void glint_lattice_vertex_hashes_x8_body(glint_u32x4 x0, glint_u32x4 x1, glint_u32x4 x2, glint_u32x4 y0,
                                                          glint_u32x4 y1, glint_u32x4 y2, glint_u32x4 key,
                                                          uint out[3][12]) {
    typedef uint u32x8 __attribute__((vector_size(32)));
    u32x8 x = __builtin_shufflevector(x0, x1, 0, 1, 2, 3, 4, 5, 6, 7);
    u32x8 y = __builtin_shufflevector(y0, y1, 0, 1, 2, 3, 4, 5, 6, 7);
    u32x8 z = __builtin_shufflevector(key, key, 0, 1, 2, 3, 4, 5, 6, 7);
    glint_u32x4 x4 = x2, y4 = y2, z4 = key;
    glint_pcg3d_vectors(x, y, z);
    glint_pcg3d_vectors(x4, y4, z4);
    std::memcpy(out[0], &x, sizeof(x)), std::memcpy(out[0] + 8, &x4, sizeof(x4));
    std::memcpy(out[1], &y, sizeof(y)), std::memcpy(out[1] + 8, &y4, sizeof(y4));
    std::memcpy(out[2], &z, sizeof(z)), std::memcpy(out[2] + 8, &z4, sizeof(z4));
}
GLINT_LANES_VARIANTS(void, glint_lattice_vertex_hashes_x8,
                     (glint_u32x4 x0, glint_u32x4 x1, glint_u32x4 x2, glint_u32x4 y0, glint_u32x4 y1, glint_u32x4 y2, glint_u32x4 key,
                      uint out[3][12]),
                     (x0, x1, x2, y0, y1, y2, key, out))
#endif
GLINT_FN_INLINE void glint_lattice_vertex_hashes(glint_u32x4 x0, glint_u32x4 x1, glint_u32x4 x2, glint_u32x4 y0, glint_u32x4 y1, glint_u32x4 y2,
                                                 glint_u32x4 key, uint out[3][12]) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
    if (glint_cpu_avx2()) {
        glint_lattice_vertex_hashes_x8(x0, x1, x2, y0, y1, y2, key, out);
        return;
    }
#endif
    const glint_u32x4 xs[3] = {x0, x1, x2}, ys[3] = {y0, y1, y2};
    for (int t = 0; t < 3; ++t)
        for (int l = 0; l < 4; ++l) {
            const uvec3 h = glint_pcg3d(uvec3(xs[t][l], ys[t][l], key[l]));
            out[0][4 * t + l] = h.x, out[1][4 * t + l] = h.y, out[2][4 * t + l] = h.z;
        }
}

GLINT_FN_INLINE const vec2* glint_lattice_rotation_table() {
    static const struct table {
        vec2 r[32];
        table() {
            for (int k = 0; k < 32; ++k) r[k] = glint_lattice_rotation(GLINT_MAX_RATIO_LEVEL, k);
        }
    } t;
    return t.r;
}

GLINT_FN_INLINE glint_lattice_triangles glint_lattice_triangles_x4(vec2 uv, const glint_lattice& lat, uint seed) {
    typedef real realx4 __attribute__((vector_size(4 * sizeof(real))));
    typedef int intx4 __attribute__((vector_size(16)));
    const vec2* table = glint_lattice_rotation_table();
    // The vectors built from scalars in registers (brace initialisers), not lane by lane in memory:
    // a vector load of four words just stored one by one waits for the stores (perf: 15% of
    // glint_footprint_vertices' samples on that load).
    const intx4 lod = {lat.lod[0], lat.lod[1], lat.lod[2], lat.lod[3]};
    const intx4 level = {lat.level[0], lat.level[1], lat.level[2], lat.level[3]};
    const vec2 r0 = table[(lat.bin[0] << (GLINT_MAX_RATIO_LEVEL - lat.level[0])) & 31], r1 = table[(lat.bin[1] << (GLINT_MAX_RATIO_LEVEL - lat.level[1])) & 31],
               r2 = table[(lat.bin[2] << (GLINT_MAX_RATIO_LEVEL - lat.level[2])) & 31], r3 = table[(lat.bin[3] << (GLINT_MAX_RATIO_LEVEL - lat.level[3])) & 31];
    const realx4 c = {r0.x, r1.x, r2.x, r3.x}, s = {r0.y, r1.y, r2.y, r3.y};
    // glint_exp2_int, lane-wise: the floats whose exponent fields are n + 127.
    typedef float floatx4 __attribute__((vector_size(16)));
    const realx4 scale_x = __builtin_convertvector(reinterpret_cast<floatx4>((-lod - level + 127) << 23), realx4);
    const realx4 scale_y = __builtin_convertvector(reinterpret_cast<floatx4>((-lod + 127) << 23), realx4);
    // glint_footprint_vertices' rotation and scaling, then glint_triangle_grid, lane by lane.
    realx4 qx = (c * uv.x + s * uv.y) * scale_x;
    realx4 qy = (-s * uv.x + c * uv.y) * scale_y;
    realx4 sx = qx - qy * real(0.577350269189625764509), sy = qy * real(1.15470053837925152902);
    const realx4 lo = realx4{} + real(-1073741824), hi = realx4{} + real(1073741824);
    sx = (sx < lo) ? lo : sx, sy = (sy < lo) ? lo : sy;  // GLM's clamp: max, then min
    sx = (hi < sx) ? hi : sx, sy = (hi < sy) ? hi : sy;
    const intx4 tx = __builtin_convertvector(sx, intx4), ty = __builtin_convertvector(sy, intx4);  // glint_floor_bounded
    realx4 ix = __builtin_convertvector(tx, realx4), iy = __builtin_convertvector(ty, realx4);
    ix = (ix > sx) ? ix - real(1) : ix, iy = (iy > sy) ? iy - real(1) : iy;
    const realx4 fx = sx - ix, fy = sy - iy;
    const intx4 bx = __builtin_convertvector(ix, intx4), by = __builtin_convertvector(iy, intx4);
    const intx4 u = __builtin_convertvector(!(fx + fy < real(1)), intx4) & 1;  // upper triangle
    const realx4 uf = __builtin_convertvector(u, realx4);
    const realx4 w0 = real(1) - fx - fy, w1 = uf - fx, w2 = uf - fy;
    glint_lattice_triangles o;
    for (int l = 0; l < 4; ++l) o.weight[0][l] = glint_abs(w0[l]), o.weight[1][l] = glint_abs(w1[l]), o.weight[2][l] = glint_abs(w2[l]);
    // Vertex 0: base + (u, u); 1: base + (1 - u, u); 2: base + (u, 1 - u) (glint_triangle_grid).
    const glint_u32x4 x0 = reinterpret_cast<glint_u32x4>(bx + u), x1 = reinterpret_cast<glint_u32x4>(bx + 1 - u);
    const glint_u32x4 y0 = reinterpret_cast<glint_u32x4>(by + u), y2 = reinterpret_cast<glint_u32x4>(by + 1 - u);
    const glint_u32x4 key = {glint_lattice_key(lat.lod[0], lat.level[0], lat.bin[0], seed), glint_lattice_key(lat.lod[1], lat.level[1], lat.bin[1], seed),
                             glint_lattice_key(lat.lod[2], lat.level[2], lat.bin[2], seed), glint_lattice_key(lat.lod[3], lat.level[3], lat.bin[3], seed)};
    glint_lattice_vertex_hashes(x0, x1, x0, y0, y0, y2, key, o.hash);
    return o;
}
#endif

// The material's glint parameters.
struct glint_grid_params {
    real log_density;       // ln of the expected microfacets per unit uv area
    real density_sigma;     // sigma of a per-vertex log-normal factor exp(sigma z - sigma^2 / 2); 0: off
    real lod_scale;         // grid cell = 2^floor(log2(minor axis x lod_scale)); about 1 to 2
    real slope_cell;        // spacing of the half-vector slope grid, absolute slope units
    real smooth_tolerance;  // return the smooth result where R's relative sd is surely below this
    int variant;            // GLINT_BINOMIAL_*
    int pow_method;         // GLINT_POW_*
    uint seed;
};

// The light as the grid sees it. kind 0: a point light, p_j from the NDF at the slope vertex
// (p_j = slope_cell^2 x unprojected slope density / D_H, clamped to 1); kind 1: an extended light
// (sun, sphere, rectangle, environment level) with p = D_Omega / D_H for every slope vertex.
// `slope` is the absolute slope -(h.x, h.y) / h.z of the half vector towards the light (its
// centre for an extended light).
struct glint_grid_light {
    int kind;
    real p;
    vec2 slope;
    int ndf;
    vec2 alpha;
    real total_area;  // D_H
};

struct glint_grid_estimate {
    real value;     // R
    real expected;  // E[R]
    int draws;      // binomial draws made (0 when the smooth result or 0 was returned)
};

// The bilinear slope-grid cell around s: corner slopes and weights.
GLINT_FN vec4 glint_slope_weights(vec2 s, real cell, GLINT_OUT(ivec2) base) {
    vec2 g = clamp(s / max(cell, real(1e-30)), vec2(real(-1073741824)), vec2(real(1073741824)));
    vec2 i = glint_floor_bounded(g);
    vec2 f = g - i;
    base = ivec2(int(i.x), int(i.y));
    return vec4((real(1) - f.x) * (real(1) - f.y), f.x * (real(1) - f.y), (real(1) - f.x) * f.y, f.x * f.y);
}

// The random words of the draw at one (grid vertex, slope cell) pair. The slope cell's key is
// hashed once per light (four cells), the pair's first word from the vertex's first hash word and
// the key with one glint_hash_u32 (two multiplies; PCG3D, which this replaced, has twelve: the
// point-light frame took 10% fewer instructions on the CPU); the second word, for u2, only where
// the skip test does not decide (most pairs of sparse glints), from the first and the vertex's
// second word. Each is a bijection of a word that a good hash of the vertex makes uniform;
// tests/stat/test_uniformity.cpp checks that neighbouring cells, neighbouring vertices and the
// two words are independent.
GLINT_FN uint glint_slope_cell_key(ivec2 cell) {
    return glint_hash_u32(uint(cell.x) * 0x9e3779b9u + uint(cell.y));  // 2^32 / golden ratio: cells 1 apart map far apart
}

GLINT_FN uint glint_cell_draw_word(uint vertex_word, uint cell_key) {
    return glint_hash_u32(vertex_word ^ cell_key);
}

GLINT_FN uint glint_cell_draw_second_word(uint first_word, uint vertex_second_word) {
    return glint_hash_u32(first_word ^ vertex_second_word);
}

// The footprint's microfacets on the grid: 12 (lattice point, triangle vertex) pairs, each with
// its triangle weight l_t, its share of the footprint's N microfacets (w_L, times the per-vertex
// log-normal factor if enabled) and its hashed random numbers (PCG3D, three words). Shared by the
// single-light estimate below and the multi-level one of ibl.glsl. Slot 4 t + l holds triangle
// vertex t of lattice point l, or slot t alone (count 3) where one lattice point is chosen; a slot
// whose lattice point or triangle vertex has weight 0 holds no vertex: weight and share 0, and no
// draw. Fixed slots rather than the present vertices packed: in C++ the arrays are copies of the
// lattice lanes' (glint_lattice_triangles_x4), where packing them vertex by vertex was 6% of the
// point-light frame's instructions (DEVELOPERS.md).
struct glint_grid_vertices {
    int count;  // 12, or 3 on one lattice point
    real weight[12];
    real share[12];
    uint hash_x[12];  // the words, one array each: the skip test reads hash_x in place
    uint hash_y[12];
    uint hash_z[12];
};

// The slot of the k-th vertex in draw order, lattice point by lattice point (k = 3 l + t for slot
// 4 t + l; slot k on one lattice point): the three vertices of a lattice point draw with the same
// N w_L, and the sampler's cache keeps its setup only from one draw to the next (the IBL's root
// draws; the grid's single-light draws keep this order without the cache).
GLINT_FN int glint_grid_draw_slot(int count, int k) {
    return (count == 12) ? 4 * (k % 3) + k / 3 : k;
}

// lattice_u < 0: every lattice point with its weight w_L (DB23, KK25). lattice_u in [0, 1): one
// lattice point, drawn with probability w_L by inverting their cumulative weights at lattice_u,
// with share 1 (glint_grid_pixel_setup_stochastic says why its mean and variance are the same).
GLINT_FN int glint_lattice_choice(glint_lattice lat, real lattice_u) {
    int chosen = -1;
    real below = real(0);
    for (int l = 0; l < 4; ++l) {
        if (!(lat.weight[l] > real(0))) continue;
        if (chosen < 0 || lattice_u >= below) chosen = l;  // the last point whose cumulative start is <= u
        below += lat.weight[l];
    }
    return chosen;
}

// The footprint's vertices, written into v (the pixel's): returned, the struct's 244 bytes were
// copied into the pixel, and the copy's loads waited for the stores (DEVELOPERS.md).
GLINT_FN void glint_footprint_vertices(vec2 uv, glint_footprint f, glint_grid_params g, real lattice_u, GLINT_OUT(glint_grid_vertices) v) {
    glint_lattice lat = glint_footprint_lattice(f, g.lod_scale);
    int chosen = (lattice_u >= real(0)) ? glint_lattice_choice(lat, lattice_u) : -1;
    v.count = (chosen >= 0) ? 3 : 12;
#if defined(GLINT_GLSL)
    for (int i = 0; i < 12; ++i) {
        v.weight[i] = real(0);
        v.share[i] = real(0);
        v.hash_x[i] = 0u;
        v.hash_y[i] = 0u;
        v.hash_z[i] = 0u;
    }
    for (int l = 0; l < 4; ++l) {
        if (chosen >= 0 && l != chosen) continue;
        real wl = (chosen >= 0) ? real(1) : lat.weight[l];  // the chosen point draws with the whole N
        if (!(lat.weight[l] > real(0))) continue;
        vec2 rot = glint_lattice_rotation(lat.level[l], lat.bin[l]);
        vec2 r = vec2(rot.x * uv.x + rot.y * uv.y, -rot.y * uv.x + rot.x * uv.y);
        // Cells 2^lod by 2^(lod + level): exact power-of-two scalings.
        glint_triangle tri = glint_triangle_grid(vec2(r.x * glint_exp2_int(-lat.lod[l] - lat.level[l]), r.y * glint_exp2_int(-lat.lod[l])));
        uint lattice_key = glint_lattice_key(lat.lod[l], lat.level[l], lat.bin[l], g.seed);
        for (int t = 0; t < 3; ++t) {
            int slot = (chosen >= 0) ? t : 4 * t + l;
            bool on = tri.weight[t] > real(0);
            v.weight[slot] = on ? tri.weight[t] : real(0);
            v.share[slot] = on ? wl : real(0);
            uvec3 h = glint_pcg3d(uvec3(uint(tri.vertex[t].x), uint(tri.vertex[t].y), lattice_key));
            v.hash_x[slot] = h.x;
            v.hash_y[slot] = h.y;
            v.hash_z[slot] = h.z;
        }
    }
#else
    // Every lattice point's triangle and vertex words in lanes (the same values as the GLSL loop).
    glint_lattice_triangles tris = glint_lattice_triangles_x4(uv, lat, g.seed);
    if (chosen < 0) {
        typedef real realx4 __attribute__((vector_size(4 * sizeof(real))));
        const realx4 wl = {lat.weight[0], lat.weight[1], lat.weight[2], lat.weight[3]};
        for (int t = 0; t < 3; ++t) {  // slots 4 t .. 4 t + 3, four lanes at once
            realx4 wt;
            std::memcpy(&wt, tris.weight[t], sizeof(wt));
            const auto on = (wt > real(0)) & (wl > real(0));
            const realx4 weight = on ? wt : realx4{}, share = on ? wl : realx4{};
            std::memcpy(v.weight + 4 * t, &weight, sizeof(weight));
            std::memcpy(v.share + 4 * t, &share, sizeof(share));
        }
        std::memcpy(v.hash_x, tris.hash[0], sizeof(v.hash_x));
        std::memcpy(v.hash_y, tris.hash[1], sizeof(v.hash_y));
        std::memcpy(v.hash_z, tris.hash[2], sizeof(v.hash_z));
    } else {
        for (int i = 0; i < 12; ++i) {
            real wt = (i < 3) ? tris.weight[i][chosen] : real(0);
            bool on = wt > real(0);
            int lane = (i < 3) ? 4 * i + chosen : 0;
            v.weight[i] = on ? wt : real(0);
            v.share[i] = on ? real(1) : real(0);
            v.hash_x[i] = (i < 3) ? tris.hash[0][lane] : 0u;
            v.hash_y[i] = (i < 3) ? tris.hash[1][lane] : 0u;
            v.hash_z[i] = (i < 3) ? tris.hash[2][lane] : 0u;
        }
    }
#endif
    if (g.density_sigma > real(0))
        for (int i = 0; i < 12; ++i)
            if (i < v.count)
                v.share[i] *= exp(g.density_sigma * glint_normal_quantile(glint_open_unit_from_bits(v.hash_z[i])) - real(0.5) * g.density_sigma * g.density_sigma);
}

// True where a draw of the mean-preserving sampler (with its log1p evaluation of (1 - p)^N) from
// first uniform u1 has no positive outcome for certain, so the draw can be skipped with the same
// result: its gates give n >= 1 with probability P(n >= 1) <= T p, T = glint_binomial_trials_bound(N)
// (N + 1, which covers its walk's b(ceil N, p); 2 up to N = 2), computed
// to within 5e-6 absolute (docs/pow_one_minus.csv), and n >= 1 exactly when u1 falls below it. Sparse glints
// skip most draws this way.
GLINT_FN bool glint_skip_test_applies(glint_grid_params g) {
    return g.variant == GLINT_BINOMIAL_UNBIASED && g.pow_method == GLINT_POW_LOG1P;
}

// The bound with the vertex's scale as glint_grid_pixel holds it (skip_scale: T 1.0001), for loops
// that hoist glint_skip_test_applies.
GLINT_FN bool glint_surely_no_success_scaled(real scale, real p, real u1) {
    return u1 >= scale * p + real(1e-5);
}

GLINT_FN bool glint_surely_no_success(glint_grid_params g, real N, real p, real u1) {
    return glint_skip_test_applies(g) && u1 >= glint_binomial_trials_bound(N) * p * real(1.0001) + real(1e-5);
}

// N = density x footprint area, finite in float.
GLINT_FN real glint_footprint_count(glint_grid_params g, glint_footprint f) {
    return min(exp(clamp(g.log_density, real(-80), real(80))) * f.area, real(1e30));
}

// exp(sigma^2) - 1, the squared coefficient of variation of the per-vertex log-normal density
// factor (0 when it is off, without the exp: one libm call per light on the CPU).
GLINT_FN real glint_density_variance_factor(glint_grid_params g) {
    return (g.density_sigma > real(0)) ? exp(g.density_sigma * g.density_sigma) - real(1) : real(0);
}

// One pixel's footprint on the grid, shared by every light and by the IBL levels of ibl.glsl:
// the footprint, its microfacet count N, and its lattice points' triangle vertices with their
// weights, shares and hashes (glint_footprint_vertices), computed once, when a light first needs
// draws (lights that return the smooth result or 0 need none).
struct glint_grid_pixel {
    vec2 uv;
    glint_footprint f;
    real N;
    real lattice_u;  // < 0: every lattice point; in [0, 1): the one it picks (glint_grid_pixel_setup_stochastic)
    bool ready;  // whether v holds the vertices
    glint_grid_vertices v;
    real skip_scale[12];  // T 1.0001 per vertex, T = glint_binomial_trials_bound(N share): the skip test's bound over p, less 1e-5
                          // (0 for a slot without a vertex)
};

GLINT_FN glint_grid_pixel glint_grid_pixel_setup(vec2 uv, vec2 duvdx, vec2 duvdy, glint_grid_params g) {
    glint_grid_pixel px;
    px.uv = uv;
    px.f = glint_footprint_from_derivatives(duvdx, duvdy);
    px.N = glint_footprint_count(g, px.f);
    px.lattice_u = real(-1);
    px.ready = false;
    px.v.count = 0;  // the arrays are filled by glint_grid_pixel_vertices, before any read
    return px;
}

// The same footprint on one lattice point instead of four: the point L drawn with probability w_L
// from the caller's uniform u in [0, 1) (u >= 1 counts as just below 1; u < 0 or NaN keeps all four
// points, as glint_grid_pixel_setup; a blue-noise or per-frame u suits a renderer that averages
// pixels or frames), its three triangle vertices drawing with the whole
// N (share 1, not w_L). Stochastic texture filtering (Pharr et al., "Filtering after shading with
// stochastic texture filtering", 2024) applied to KK25's lattice interpolation. Per pixel the
// estimate keeps its mean exactly (each lattice point's R alone has E[R] = sum m_j p_j) and, where
// the vertices' draws are binomial, its variance too: Var(c) = n p (1 - p) is linear in n, so
// sum_L w_L Var(sum_t l_t c_Lt / N | share 1) = sum_L Var(sum_t l_t c_Lt / N | share w_L). What
// changes is across pixels and time: a glint that the interpolation fades in and out as the
// footprint's LOD, ratio or angle moves shows, per pixel, either wholly or not at all. It costs 3
// vertices instead of up to 12 (the vertex setup and the skip test's hashes; docs/grid.md).
GLINT_FN glint_grid_pixel glint_grid_pixel_setup_stochastic(vec2 uv, vec2 duvdx, vec2 duvdy, glint_grid_params g, real u) {
    glint_grid_pixel px = glint_grid_pixel_setup(uv, duvdx, duvdy, g);
    px.lattice_u = (u < real(0)) ? real(-1) : min(u, real(0.99999994));  // 1 - 2^-24, below 1 in float
    return px;
}

// The skip test's per-vertex bound for the first `vertices` slots.
GLINT_FN void glint_grid_skip_inputs(GLINT_INOUT(glint_grid_pixel) px, int vertices) {
#if defined(GLINT_GLSL)
    for (int i = 0; i < vertices; ++i)
        px.skip_scale[i] = glint_binomial_trials_bound(px.N * px.v.share[i]) * ((px.v.weight[i] > real(0)) ? real(1.0001) : real(0));
#else
    // Four slots at once, glint_binomial_trials_bound's select lane-wise (the same values): GCC
    // unrolled the scalar loop with a branch per slot, about 140 instructions a pixel (callgrind).
    typedef real realx4 __attribute__((vector_size(4 * sizeof(real))));
    for (int b = 0; b < vertices; b += 4) {
        realx4 share, weight;
        std::memcpy(&share, px.v.share + b, sizeof(share));
        std::memcpy(&weight, px.v.weight + b, sizeof(weight));
        const realx4 n = px.N * share, none = {};
        const realx4 bound = (n > real(2)) ? n + real(1) : none + real(2);
        const realx4 scale = bound * ((weight > real(0)) ? none + real(1.0001) : none);
        std::memcpy(px.skip_scale + b, &scale, sizeof(scale));
    }
#endif
}

GLINT_FN void glint_grid_pixel_vertices(GLINT_INOUT(glint_grid_pixel) px, glint_grid_params g) {
    if (px.ready) return;
    glint_footprint_vertices(px.uv, px.f, g, px.lattice_u, px.v);
    // The skip test reads 4 vertices where there are at most 4 (one lattice point), else 12
    // (glint_skip_test_masks); each call with a constant count, whose loop GCC vectorises.
    if (px.v.count <= 4) glint_grid_skip_inputs(px, 4);
    else glint_grid_skip_inputs(px, 12);
    px.ready = true;
}

// The skip test (glint_surely_no_success: a draw happens where u1 < bound = T p 1.0001
// + 1e-5) for every vertex and slope corner of one light, before any draw: bit j of bits[i] is set
// where vertex i draws at corner j. It reads the hash word h whose top 23 bits make u1
// (glint_open_unit_from_bits): (h >> 8) 2^-24 <= u1, so every h with u1 < bound passes
// (h >> 8) < bound 2^24, which is exact to float's rounding of bound (far inside its margins of
// 1.0001 and 1e-5). It may draw where the test on u1 would not, never the other way, and a skipped
// draw is surely 0, so the estimate is the same (tests/unit/test_grid.cpp checks it against R's
// definition). The loops have no branches and read contiguous arrays, so that the C++ compiler
// vectorises them; out of line, because GCC does not once it is inlined (and C++ has an AVX2
// version below). Vertices past px.v.count up to 4 or 12 get bits too (from zero hashes and
// shares), which `any` leaves out and the draw loop never reads.
struct glint_draw_masks {
    int bits[12];
    int any;  // the bits of the pixel's px.v.count vertices or'ed: 0 where none draws at any corner
};

// The test's bits for the first `vertices` vertices.
GLINT_FN_INLINE void glint_skip_test_bits(GLINT_INOUT(glint_grid_pixel) px, GLINT_INOUT(glint_draw_masks) masks, uint corner_key[4], real corner_p[4],
                                   int vertices) {
    for (int j = 0; j < 4; ++j) {
        real p24 = corner_p[j] * real(16777216.0);  // 2^24
        uint key = corner_key[j];
        for (int i = 0; i < vertices; ++i) {
            uint word = glint_hash_u32(px.v.hash_x[i] ^ key);
            masks.bits[i] |= ((real(int(word >> 8u)) < px.skip_scale[i] * p24 + real(167.77216)) ? 1 : 0) << j;  // 1e-5 2^24
        }
    }
}

// Only the live corners draw, and all of them where the skip test does not apply; `any` from the
// pixel's `count` vertices.
GLINT_FN_INLINE void glint_draw_masks_finish(GLINT_INOUT(glint_draw_masks) masks, int count, int live, bool skip_test) {
    int always = skip_test ? 0 : live;
    masks.any = 0;
    for (int i = 0; i < 12; ++i) {
        masks.bits[i] = (masks.bits[i] | always) & live;
        masks.any |= (i < count) ? masks.bits[i] : 0;
    }
}

GLINT_FN_INLINE glint_draw_masks glint_skip_test_masks_inline(GLINT_INOUT(glint_grid_pixel) px, uint corner_key[4], real corner_p[4], int live,
                                                                bool skip_test) {
    glint_draw_masks masks;
    for (int i = 0; i < 12; ++i) masks.bits[i] = 0;
    // Four vertices where one lattice point has them (glint_grid_pixel_setup_stochastic), else
    // twelve: each call with a constant count, whose loop GCC vectorises once inlined here (a
    // variable count it did not: 20% more instructions in the point-light frame).
    if (px.v.count <= 4) glint_skip_test_bits(px, masks, corner_key, corner_p, 4);
    else glint_skip_test_bits(px, masks, corner_key, corner_p, 12);
    glint_draw_masks_finish(masks, px.v.count, live, skip_test);
    return masks;
}

// In C++ the test runs in AVX2's registers where the CPU has them (glint_cpu_avx2, float only):
// eight vertices' hashes at once, per slope corner, in two blocks of eight for twelve vertices, one
// for four (GCC's vector extension). SSE2, the baseline, emulates a four-wide 32-bit multiply in
// about six instructions: there the test took about 515 instructions a light, 243 in AVX2 (the
// loops above compiled for AVX2, which GCC vectorised across the four corners: 373); an extra
// point light 1245 instead of 1503 (callgrind, glint_frame_loop lights 8 1 4 against lights 1 1 4).
// The same bits (tests/unit/test_grid.cpp): the same integer hash, float product and sum per lane.
#if defined(GLINT_GLSL)
glint_draw_masks glint_skip_test_masks(GLINT_INOUT(glint_grid_pixel) px, uint corner_key[4], real corner_p[4], int live, bool skip_test) {
    return glint_skip_test_masks_inline(px, corner_key, corner_p, live, skip_test);
}
#else
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
GLINT_LANES_BODY glint_draw_masks glint_skip_test_masks_x8_body(const glint_grid_pixel& px, const uint corner_key[4],
                                                                const real corner_p[4], int live, bool skip_test) {
    typedef uint u32x8 __attribute__((vector_size(32)));
    typedef int i32x8 __attribute__((vector_size(32)));
    typedef real realx8 __attribute__((vector_size(8 * sizeof(real))));
    // The vertices glint_grid_skip_inputs filled (4 or 12) in blocks of eight read in place: 0..7,
    // and for twelve 4..11 (its lanes 4..7 again), so that no load reads past px.v.hash_x. The bits
    // and their finish (glint_draw_masks_finish: the same values) stay in registers until one
    // store: the copies through zero-padded stack arrays this replaced made each block's load and
    // the finish's wait for stores of other sizes (perf: a quarter of this function's samples).
    const bool one_block = px.v.count <= 4;
    const i32x8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const int always = skip_test ? 0 : live;
    i32x8 block_bits[2] = {};
    for (int b = 0; b < (one_block ? 1 : 2); ++b) {
        u32x8 word;
        realx8 scale;
        std::memcpy(&word, px.v.hash_x + 4 * b, sizeof(word));
        std::memcpy(&scale, px.skip_scale + 4 * b, sizeof(scale));
        if (one_block)  // lanes 4..7: words glint_grid_skip_inputs did not fill, kept out of the arithmetic
            for (int i = 4; i < 8; ++i) word[i] = 0u, scale[i] = real(0);
        glint_hash_u32_first_step(word);  // core.glsl: the first step once a block, not once a corner
        i32x8 bits = {};
        for (int j = 0; j < 4; ++j) {
            uint key_step = corner_key[j];
            glint_hash_u32_first_step(key_step);
            u32x8 h = word ^ key_step;
            glint_hash_u32_vector_rest(h);
            realx8 below = __builtin_convertvector(reinterpret_cast<i32x8>(h >> 8u), realx8);  // below 2^24: exact
            realx8 bound = scale * (corner_p[j] * real(16777216.0)) + real(167.77216);
            bits |= __builtin_convertvector(below < bound, i32x8) & (1 << j);
        }
        block_bits[b] = bits;
    }
    // Vertex i of the first block is lane i, of the second lane i - 4. One block: no bits past
    // the 4 vertices it tests (as the baseline).
    i32x8 first = one_block ? (lane < 4 ? block_bits[0] : i32x8{}) : block_bits[0];
    first = (first | always) & live;
    const i32x8 second = (block_bits[1] | always) & live;
    const i32x8 counted = (first & (lane < px.v.count)) | (second & (lane + 4 >= 8 && lane + 4 < px.v.count));
    int any = 0;
    for (int i = 0; i < 8; ++i) any |= counted[i];
    glint_draw_masks masks;
    std::memcpy(masks.bits, &first, sizeof(first));
    for (int i = 8; i < 12; ++i) masks.bits[i] = second[i - 4];
    masks.any = any;
    return masks;
}
GLINT_LANES_VARIANTS(glint_draw_masks, glint_skip_test_masks_x8,
                     (const glint_grid_pixel& px, const uint corner_key[4], const real corner_p[4], int live, bool skip_test),
                     (px, corner_key, corner_p, live, skip_test))
#endif
GLINT_FN_OUT_OF_LINE glint_draw_masks glint_skip_test_masks(glint_grid_pixel& px, uint corner_key[4], real corner_p[4], int live, bool skip_test) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
    if (!GLINT_DOUBLE && glint_cpu_avx2()) return glint_skip_test_masks_x8(px, corner_key, corner_p, live, skip_test);
#endif
    return glint_skip_test_masks_inline(px, corner_key, corner_p, live, skip_test);
}
#endif

// p_j at the four slope corners sbase + (j & 1, j >> 1): the light's p, or for a point light
// slope_cell^2 times the unprojected slope density at the corner over D_H (clamped to [0, 1]), with
// the NDF's roughness terms and cell^2 / D_H once a light (glint_slope_density_terms): eight
// divisions a light instead of twenty (one per corner, four for the terms).
GLINT_FN vec4 glint_grid_corner_probabilities(glint_grid_params g, glint_grid_light light, ivec2 sbase) {
    if (light.kind != 0) return vec4(clamp(light.p, real(0), real(1)));
    glint_slope_density_terms terms = glint_slope_density_terms_of(light.alpha);
    real scale = g.slope_cell * g.slope_cell / max(light.total_area, real(1));
    vec4 p;
    for (int j = 0; j < 4; ++j) {
        ivec2 c = sbase + ivec2(j & 1, j >> 1);
        p[j] = clamp(scale * glint_slope_area_density_at(light.ndf, vec2(c) * g.slope_cell, terms), real(0), real(1));
    }
    return p;
}

// The count that a vertex with words hash_x, hash_y and n = N share trials draws at the slope cell
// whose key is corner_key, with probability p.
GLINT_FN real glint_vertex_corner_count(glint_grid_params g, real n, uint hash_x, uint hash_y, uint corner_key, real p) {
    uint h1 = glint_cell_draw_word(hash_x, corner_key);
    real u1 = glint_open_unit_from_bits(h1);
    real u2 = glint_open_unit_from_bits(glint_cell_draw_second_word(h1, hash_y));
#if !defined(GLINT_GLSL)
    // The sparse draw's shortcut first (binomial.glsl; the same count): behind the skip test most
    // draws are sparse, and the sampler's calls and dispatch cost more than the bounds.
    real sparse = glint_binomial_variant_sparse(g.variant, n, p, u1, u2, g.pow_method);
    if (sparse >= real(0)) return sparse;
#endif
    return glint_binomial_variant(g.variant, n, p, u1, u2, g.pow_method).positive;
}

// The count that vertex slot i draws at the slope cell whose key is corner_key, with probability p.
GLINT_FN real glint_grid_corner_count(GLINT_IN(glint_grid_pixel) px, glint_grid_params g, int i, uint corner_key, real p) {
    return glint_vertex_corner_count(g, px.N * px.v.share[i], px.v.hash_x[i], px.v.hash_y[i], corner_key, p);
}

// R for one light on a pixel's footprint (the vertices computed on first need).
GLINT_FN glint_grid_estimate glint_grid_sample_pixel(GLINT_INOUT(glint_grid_pixel) px, glint_grid_params g, glint_grid_light light) {
    glint_grid_estimate o;
    o.value = real(0);
    o.expected = real(0);
    o.draws = 0;
    ivec2 sbase;
    vec4 mu = glint_slope_weights(light.slope, g.slope_cell, sbase);
    vec4 p = glint_grid_corner_probabilities(g, light, sbase);
    o.expected = dot(mu, p);
    if (!(o.expected > real(0))) return o;  // no microfacet can reflect this light: no sampling
    real N = px.N;
    // Var(R) <= sum_j m_j^2 p_j (1 - p_j) / N + (exp(sigma^2) - 1) E[R]^2 (the lattice and
    // triangle weights only lower it: their squares sum to at most 1).
    real var_bound = dot(mu * mu, p * (vec4(real(1)) - p)) / max(N, real(1e-30)) +
                     glint_density_variance_factor(g) * o.expected * o.expected;
    if (var_bound <= g.smooth_tolerance * g.smooth_tolerance * o.expected * o.expected) {
        o.value = o.expected;
        return o;
    }
    if (!(N > real(1e-30))) return o;  // no footprint, no microfacets
    if (!px.ready) glint_grid_pixel_vertices(px, g);  // the check inline: GCC calls the function out of line
    // The slope corners in plain arrays (a vector indexed in a loop costs a switch per access in
    // C++), the skip test's constant part hoisted out of the loops; bit j of `live` is set where
    // corner j can reflect (m_j > 0 and p_j > 0), and only those draw.
    int live = 0;
    real corner_p[4];
    uint corner_key[4];
    for (int j = 0; j < 4; ++j) {
        bool on = mu[j] > real(0) && p[j] > real(0);
        corner_p[j] = on ? p[j] : real(0);
        corner_key[j] = glint_slope_cell_key(sbase + ivec2(j & 1, j >> 1));
        live |= on ? (1 << j) : 0;
    }
    // Which vertices draw at which corners. Against the four-wide test on the float u1 per vertex
    // that this replaced: 1720 instead of 2693 instructions per extra point light on the CPU
    // (callgrind, bench/glint_frame_loop lights 8 1 4 against lights 1 1 4; 1539 since).
    glint_draw_masks masks = glint_skip_test_masks(px, corner_key, corner_p, live, glint_skip_test_applies(g));
    if (masks.any == 0) return o;  // sparse glints: most lights draw nowhere (R = 0 exactly)
    // Without the sampler's cache (glint_binomial_variant_cached): behind the skip test most
    // corners draw once a pixel, so a cache only cost its setup's bookkeeping and the cold path's
    // ends (callgrind, glint_frame_loop lights 16 1 4: 70.3M to 61.8M instructions; point 2 71.77M
    // to 71.79M, point-stochastic 2 69.52M to 69.77M; the same sums). The draws stay in the order
    // the cache wanted, lattice point by lattice point (slot 4 t + l, glint_grid_draw_slot, without
    // its division), so that the sums are those of before.
    int points = (px.v.count == 12) ? 4 : 1;
    int stride = (px.v.count == 12) ? 4 : 1;
    for (int l = 0; l < points; ++l) {
        for (int t = 0; t < 3; ++t) {
            int i = stride * t + l;
            // A slot without a vertex (skip_scale 0) passes the skip test only where u1 < 1e-5: never drawn.
            if (masks.bits[i] == 0 || !(px.v.weight[i] > real(0))) continue;
            for (int j = 0; j < 4; ++j) {
                if (((masks.bits[i] >> j) & 1) == 0) continue;
                o.value += px.v.weight[i] * mu[j] * glint_grid_corner_count(px, g, i, corner_key[j], corner_p[j]) / N;  // the draw carries w_L
                ++o.draws;
            }
        }
    }
    return o;
}


// R for one footprint and one light.
GLINT_FN glint_grid_estimate glint_grid_sample(vec2 uv, vec2 duvdx, vec2 duvdy, glint_grid_params g, glint_grid_light light) {
    glint_grid_pixel px = glint_grid_pixel_setup(uv, duvdx, duvdy, g);
    return glint_grid_sample_pixel(px, g, light);
}

// R for up to GLINT_GRID_MAX_LIGHTS lights on one footprint: the footprint, its lattice and its
// vertices once, then each light's slope cell and draws.
GLINT_CONST(int) GLINT_GRID_MAX_LIGHTS = 8;

struct glint_grid_estimates {
    glint_grid_estimate e[8];
};

GLINT_FN glint_grid_estimates glint_grid_sample_lights(vec2 uv, vec2 duvdx, vec2 duvdy, glint_grid_params g, glint_grid_light lights[8],
                                                       int count) {
    glint_grid_estimates o;
    glint_grid_pixel px = glint_grid_pixel_setup(uv, duvdx, duvdy, g);
    for (int k = 0; k < GLINT_GRID_MAX_LIGHTS; ++k) {
        o.e[k].value = real(0);
        o.e[k].expected = real(0);
        o.e[k].draws = 0;
        if (k < count) o.e[k] = glint_grid_sample_pixel(px, g, lights[k]);
    }
    return o;
}

#if !defined(GLINT_GLSL)
// C++ only: a list of lights on one pixel, out[k] = glint_grid_sample_pixel(px, g, lights[k])
// exactly (tests/unit/test_grid.cpp compares them bit for bit). Where the CPU has AVX2 (float),
// eight lights at a time share one pass, a light a lane: the per-light setup that the
// single-light estimate does in scalar code (the slope cell and its weights, the four corners'
// p_j with their divisions and square roots, E[R], the variance bound, the cell keys) and the
// skip test, which hashes each vertex against eight lights' corner keys at once instead of eight
// vertices against one light's. What is left per light is the draws of the few lights that the
// skip test lets draw (about 0.39 draws a light in bench/light_pixels.hpp's workload), each by
// glint_grid_corner_count in the single-light estimate's order, the lanes that draw and their
// vertices and corners walked by their set bits. A point light on the Beckmann NDF (whose
// density needs libm's exp per corner) sends its batch to the single-light path; lists longer
// than eight go in batches of eight. Callgrind (glint_frame_loop lights 16 1 4, whose pixels shade
// 16 point lights through the list): 91.2M instructions with each light through
// glint_grid_sample_pixel, 54.3M in batches, the same sum (docs/grid.md times it).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
// (glint_f32x8 and glint_i32x8: multinomial.glsl's eight-lane types.)
// glm's clamp, min(max(x, lo), hi) with max(x, y) = (x < y) ? y : x and min(x, y) = (y < x) ? y : x:
// the same selects lane-wise, NaN included.
__attribute__((always_inline, target("avx2"))) static inline glint_f32x8 glint_clamp_x8(glint_f32x8 x, float lo, float hi) {
    const glint_f32x8 zero = {};
    x = (x < lo) ? zero + lo : x;
    return (hi < x) ? zero + hi : x;
}
// Eight lights' set-up, a light a lane (lane l: lights[l], or for l >= count an extended light
// with p = 0, whose E[R] is 0), on footprints holding N[l] microfacets: glint_grid_sample_pixel's
// steps up to its skip test with the same operations in the same order (the same values bit for
// bit). Returns false where a lane holds a point light on the Beckmann NDF, whose density needs
// libm's exp per corner (then the caller takes the single-light path and o is not filled).
struct glint_light_lanes {
    glint_f32x8 mu[4];        // the slope corners' bilinear weights (glint_slope_weights)
    glint_f32x8 corner_p[4];  // p_j where corner j is live (m_j > 0 and p_j > 0), else 0
    glint_f32x8 p24[4];       // the skip test's p_j 2^24 (FLT_MAX for a published variant: see below)
    glint_u32x8 key[4];       // glint_slope_cell_key of corner j
    glint_u32x8 key_step[4];  // glint_hash_u32_first_step(key[j]), for the skip test (core.glsl)
    glint_i32x8 bit[4];       // bit j where corner j is live
    glint_f32x8 expected;     // E[R]
    glint_i32x8 smooth;       // all ones where R = E[R] is returned
    glint_i32x8 draws;        // all ones where the light needs draws (neither 0 nor the smooth result)
};

__attribute__((always_inline, target("avx2"))) static inline bool glint_light_lanes_setup(const glint_grid_params& g, const glint_grid_light* lights, int count,
                                                                                          const glint_f32x8& N, glint_light_lanes& o) {
    typedef glint_f32x8 f32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_u32x8 u32x8;
    const f32x8 zero = {}, one = zero + 1.0f;
    // The lights' eight 4-byte fields (kind, p, slope, ndf, alpha, total_area: one AVX2 register
    // each) transposed into one vector per field, a light a lane: 24 shuffles instead of 64 lane
    // inserts.
    static_assert(sizeof(glint_grid_light) == 32, "glint_grid_light: eight 4-byte fields");
    f32x8 r[8];
    for (int l = 0; l < 8; ++l) {
        if (l < count) {
            std::memcpy(&r[l], lights + l, sizeof(r[l]));
        } else {
            const i32x8 empty = {1, 0, 0, 0, 0, 0, 0, 0};
            r[l] = reinterpret_cast<f32x8>(empty);
        }
    }
    const i32x8 lo = {0, 8, 1, 9, 4, 12, 5, 13}, hi = {2, 10, 3, 11, 6, 14, 7, 15};
    const i32x8 even = {0, 1, 8, 9, 4, 5, 12, 13}, odd = {2, 3, 10, 11, 6, 7, 14, 15};
    const i32x8 low_halves = {0, 1, 2, 3, 8, 9, 10, 11}, high_halves = {4, 5, 6, 7, 12, 13, 14, 15};
    f32x8 t[8], u[8];
    for (int k = 0; k < 4; ++k) {
        t[2 * k] = __builtin_shuffle(r[2 * k], r[2 * k + 1], lo);
        t[2 * k + 1] = __builtin_shuffle(r[2 * k], r[2 * k + 1], hi);
    }
    for (int k = 0; k < 2; ++k) {  // u[4 k + f]: fields f and f + 4 of lights 4 k to 4 k + 3
        u[4 * k] = __builtin_shuffle(t[4 * k], t[4 * k + 2], even);
        u[4 * k + 1] = __builtin_shuffle(t[4 * k], t[4 * k + 2], odd);
        u[4 * k + 2] = __builtin_shuffle(t[4 * k + 1], t[4 * k + 3], even);
        u[4 * k + 3] = __builtin_shuffle(t[4 * k + 1], t[4 * k + 3], odd);
    }
    const i32x8 kind = reinterpret_cast<i32x8>(__builtin_shuffle(u[0], u[4], low_halves));
    const f32x8 lp = __builtin_shuffle(u[1], u[5], low_halves), sx = __builtin_shuffle(u[2], u[6], low_halves),
                sy = __builtin_shuffle(u[3], u[7], low_halves);
    const i32x8 ndf = reinterpret_cast<i32x8>(__builtin_shuffle(u[0], u[4], high_halves));
    const f32x8 ax = __builtin_shuffle(u[1], u[5], high_halves), ay = __builtin_shuffle(u[2], u[6], high_halves),
                area = __builtin_shuffle(u[3], u[7], high_halves);
    const i32x8 point = kind == 0;
    if (__builtin_ia32_movmskps256(reinterpret_cast<f32x8>(point & (ndf == GLINT_NDF_BECKMANN))) != 0) return false;
    // glint_slope_weights
    const float cell = g.slope_cell, cell_c = (cell < 1e-30f) ? 1e-30f : cell;
    const f32x8 gx = glint_clamp_x8(sx / cell_c, -1073741824.0f, 1073741824.0f), gy = glint_clamp_x8(sy / cell_c, -1073741824.0f, 1073741824.0f);
    f32x8 ix = gx, iy = gy;
    glint_lanes_floor_bounded(ix), glint_lanes_floor_bounded(iy);  // multinomial.glsl
    const f32x8 fx = gx - ix, fy = gy - iy;
    const i32x8 bx = __builtin_convertvector(ix, i32x8), by = __builtin_convertvector(iy, i32x8);
    o.mu[0] = (one - fx) * (one - fy), o.mu[1] = fx * (one - fy), o.mu[2] = (one - fx) * fy, o.mu[3] = fx * fy;
    // glint_grid_corner_probabilities: GGX's glint_slope_area_density_at for point lights, p for
    // extended ones.
    const f32x8 axc = glint_clamp_x8(ax, GLINT_MIN_ROUGHNESS, GLINT_MAX_ROUGHNESS), ayc = glint_clamp_x8(ay, GLINT_MIN_ROUGHNESS, GLINT_MAX_ROUGHNESS);
    const f32x8 inv_ax = one / axc, inv_ay = one / ayc, norm = one / (GLINT_PI * axc * ayc);
    const f32x8 scale = (cell * cell) / ((area < 1.0f) ? one : area);
    const f32x8 p_extended = glint_clamp_x8(lp, 0.0f, 1.0f);
    f32x8 p[4];
    for (int j = 0; j < 4; ++j) {
        const i32x8 cx = bx + (j & 1), cy = by + (j >> 1);
        const f32x8 csx = __builtin_convertvector(cx, f32x8) * cell, csy = __builtin_convertvector(cy, f32x8) * cell;
        const f32x8 rx = csx * inv_ax, ry = csy * inv_ay;
        const f32x8 u2 = rx * rx + ry * ry;
        const f32x8 jac = __builtin_ia32_sqrtps256(one + (csx * csx + csy * csy)) * norm;
        const f32x8 p_point = glint_clamp_x8(scale * (jac / ((one + u2) * (one + u2))), 0.0f, 1.0f);
        p[j] = point ? p_point : p_extended;
        o.key[j] = reinterpret_cast<u32x8>(cx) * 0x9e3779b9u + reinterpret_cast<u32x8>(cy);  // glint_slope_cell_key
        glint_hash_u32_vector(o.key[j]);
        o.key_step[j] = o.key[j];
        glint_hash_u32_first_step(o.key_step[j]);
    }
    o.expected = (o.mu[0] * p[0] + o.mu[1] * p[1]) + (o.mu[2] * p[2] + o.mu[3] * p[3]);
    f32x8 q[4];
    for (int j = 0; j < 4; ++j) q[j] = (o.mu[j] * o.mu[j]) * (p[j] * (one - p[j]));
    const float tol = g.smooth_tolerance;
    const f32x8 var_bound = ((q[0] + q[1]) + (q[2] + q[3])) / ((N < 1e-30f) ? zero + 1e-30f : N) + glint_density_variance_factor(g) * o.expected * o.expected;
    const i32x8 reflects = o.expected > 0.0f;
    o.smooth = reflects & (var_bound <= tol * tol * o.expected * o.expected);
    o.draws = reflects & ~o.smooth & (N > 1e-30f);
    // The live corners and the skip test's bound (glint_skip_test_masks: the same integer hash,
    // float product and sum per (vertex, corner)). Each corner's bit carries its lanes' liveness
    // (bit[j]), and where the skip test does not apply (a published variant) p24 is FLT_MAX
    // instead of p_j 2^24, a bound that every vertex with a scale passes: the live corners of
    // every vertex, as the single-light path's (b | always) & live, with two vectors fewer in
    // the loop (`always` had spilled to the stack). A slot without a vertex (scale 0) gets bits
    // from u1 < 1e-5 alone there, which nothing reads: its weight 0 keeps it from drawing.
    const bool skip_test = glint_skip_test_applies(g);
    for (int j = 0; j < 4; ++j) {
        const i32x8 on = (o.mu[j] > 0.0f) & (p[j] > 0.0f);
        o.corner_p[j] = on ? p[j] : zero;
        o.p24[j] = skip_test ? o.corner_p[j] * 16777216.0f : zero + 3.4028234663852886e38f;  // 2^24; FLT_MAX
        o.bit[j] = on & (1 << j);
    }
    return true;
}

// The skip test's bits (bit j where the vertex may draw at corner j) of a vertex whose first hash
// word has first step `word_step` (glint_hash_u32_first_step, core.glsl) and whose bound scale is
// `scale` (glint_grid_pixel's skip_scale), lane-wise against each lane's light.
__attribute__((always_inline, target("avx2"))) static inline glint_i32x8 glint_light_lanes_skip_bits(const glint_light_lanes& o, const glint_u32x8& word_step,
                                                                                                     const glint_f32x8& scale) {
    glint_i32x8 b = {};
    for (int j = 0; j < 4; ++j) {
        glint_u32x8 h = o.key_step[j] ^ word_step;  // glint_cell_draw_word's hash after its first step
        glint_hash_u32_vector_rest(h);
        const glint_f32x8 below = __builtin_convertvector(reinterpret_cast<glint_i32x8>(h >> 8u), glint_f32x8);  // below 2^24: exact
        b |= (below < scale * o.p24[j] + 167.77216f) & o.bit[j];                                                   // 1e-5 2^24
    }
    return b;
}

// The estimates' results before any draw: E[R], and R = E[R] where the smooth result is returned.
__attribute__((always_inline, target("avx2"))) static inline void glint_light_lanes_results(const glint_light_lanes& o, int count, glint_grid_estimate* out) {
    const glint_f32x8 value = o.smooth ? o.expected : glint_f32x8{};
    for (int l = 0; l < count; ++l) {
        out[l].value = value[l];
        out[l].expected = o.expected[l];
        out[l].draws = 0;
    }
}

GLINT_LANES_BODY void glint_grid_sample_lights_x8_body(glint_grid_pixel& px, const glint_grid_params& g,
                                                       const glint_grid_light* lights, int count, glint_grid_estimate* out) {
    typedef glint_f32x8 f32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_u32x8 u32x8;
    const float N = px.N;
    glint_light_lanes o;
    if (!glint_light_lanes_setup(g, lights, count, f32x8{} + N, o)) {
        for (int k = 0; k < count; ++k) out[k] = glint_grid_sample_pixel(px, g, lights[k]);
        return;
    }
    glint_light_lanes_results(o, count, out);
    if (__builtin_ia32_movmskps256(reinterpret_cast<f32x8>(o.draws)) == 0) return;
    if (!px.ready) glint_grid_pixel_vertices(px, g);
    // The skip test (glint_light_lanes_setup's bound), vertex by vertex against the eight lights.
    i32x8 bits[12], any = {};
    for (int i = 0; i < px.v.count; ++i) {
        uint word_step = px.v.hash_x[i];
        glint_hash_u32_first_step(word_step);
        bits[i] = glint_light_lanes_skip_bits(o, u32x8{} + word_step, f32x8{} + px.skip_scale[i]);
        any |= bits[i];
    }
    // The draws of the lanes that draw (lanes past count have E[R] = 0), in glint_grid_sample_pixel's
    // order: bit 4 k + j of a lane's mask is set where the k-th vertex in that order may draw at
    // corner j (vertices 0 to 7 in `first`, 8 to 11 in `rest`), so that one loop over a lane's set
    // bits walks its vertices and corners.
    const bool four_points = px.v.count == 12;
    const int slot[12] = {0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11};  // glint_grid_draw_slot(12, k)
    u32x8 first = {}, rest = {};
    for (int k = 0; k < px.v.count; ++k) {
        const u32x8 b = reinterpret_cast<u32x8>(bits[four_points ? slot[k] : k]);
        if (k < 8) first |= b << (4 * k);
        else rest |= b << (4 * (k - 8));
    }
    for (int lanes = __builtin_ia32_movmskps256(reinterpret_cast<f32x8>(o.draws & (any != 0))); lanes != 0; lanes &= lanes - 1) {
        const int l = __builtin_ctz(static_cast<unsigned>(lanes));
        glint_grid_estimate& e = out[l];
        for (unsigned long long m = first[l] | static_cast<unsigned long long>(rest[l]) << 32; m != 0; m &= m - 1) {
            const int b = __builtin_ctzll(m), k = b >> 2, j = b & 3, i = four_points ? slot[k] : k;
            if (!(px.v.weight[i] > 0.0f)) continue;
            e.value += px.v.weight[i] * o.mu[j][l] * glint_grid_corner_count(px, g, i, o.key[j][l], o.corner_p[j][l]) / N;
            ++e.draws;
        }
    }
}
GLINT_LANES_VARIANTS(void, glint_grid_sample_lights_x8,
                     (glint_grid_pixel& px, const glint_grid_params& g, const glint_grid_light* lights, int count, glint_grid_estimate* out),
                     (px, g, lights, count, out))
#endif

GLINT_FN_OUT_OF_LINE void glint_grid_sample_pixel_lights(glint_grid_pixel& px, const glint_grid_params& g, const glint_grid_light* lights, int count,
                                                         glint_grid_estimate* out) {
    for (int first = 0; first < count; first += 8) {
        const int n = (count - first < 8) ? count - first : 8;
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
        if constexpr (!GLINT_DOUBLE) {
            // One or two lights are cheaper through the single-light path (a pass costs the same
            // for one lane as for eight): glint_frame_loop lights K 1 2000 took 0.46 s one light
            // at a time against 0.58 s in a pass at K = 1, 0.69 against 0.74 at K = 2, 0.90
            // against 0.86 at K = 3 (least of five alternating runs, this 2-core AMD EPYC).
            if (n > 2 && glint_cpu_avx2()) {
                glint_grid_sample_lights_x8(px, g, lights + first, n, out + first);
                continue;
            }
        }
#endif
        for (int k = 0; k < n; ++k) out[first + k] = glint_grid_sample_pixel(px, g, lights[first + k]);
    }
}
#endif

#if !defined(GLINT_GLSL)
// ---------------------------------------------------------------------------------------------
// C++ only: eight pixels' footprints in AVX2 lanes (lane v holds pixel v), for the batches of
// glint_grid_sample_pixels below and glint_ibl_sample_pixels (ibl.glsl).

// The lanes' vertices, slot by lane: [s][v] is slot s of pixel v, as glint_grid_vertices holds it.
struct glint_lanes_vertices {
    int count[8];  // 12 where the lane's pixel draws on its four lattice points, 3 on one, else 0
    int slots;     // bit s set where some lane may hold a vertex in slot s; the other slots are not written
    real share[12][8];
    real weight[12][8];
    uint hash_x[12][8], hash_y[12][8], hash_z[12][8];
};

// The lanes' pixels' lattice points ([l] a vector of the eight lanes; weight 0 in a lane that does
// not draw); their rotations from glint_lanes_rotation.
struct glint_lattice_lanes {
    glint_f32x8 weight[4];
    glint_i32x8 lod[4], level[4], bin[4];
};

// glint_lattice_rotation(level, bin) lane by lane from the table: (cos, sin), the same values.
// Apart from glint_lanes_lattice, so that the vertices look up the rotations of the lattice points
// that some lane weighs only (half of them at an isotropic footprint).
__attribute__((always_inline)) static inline void glint_lanes_rotation(const glint_i32x8& level, const glint_i32x8& bin, glint_f32x8& c, glint_f32x8& s) {
    static const vec2* const rotation = glint_lattice_rotation_table();
    const glint_i32x8 r = (bin << (GLINT_MAX_RATIO_LEVEL - level)) & 31;
    c = glint_f32x8{rotation[r[0]].x, rotation[r[1]].x, rotation[r[2]].x, rotation[r[3]].x, rotation[r[4]].x, rotation[r[5]].x, rotation[r[6]].x, rotation[r[7]].x};
    s = glint_f32x8{rotation[r[0]].y, rotation[r[1]].y, rotation[r[2]].y, rotation[r[3]].y, rotation[r[4]].y, rotation[r[5]].y, rotation[r[6]].y, rotation[r[7]].y};
}

// glint_log2 lane-wise, in place (a reference: a vector passed by value to a function not compiled
// for AVX would change the ABI).
__attribute__((always_inline)) static inline void glint_lanes_log2(glint_f32x8& x) {
    typedef glint_f32x8 f32x8;
    typedef glint_i32x8 i32x8;
    const f32x8 lo = f32x8{} + GLINT_FLT_MIN_NORMAL, hi = f32x8{} + real(3.40282346638528859812e38);
    x = (x < lo) ? lo : x;  // GLM's max, then min
    x = (hi < x) ? hi : x;
    const glint_u32x8 bits = reinterpret_cast<glint_u32x8>(x);
    f32x8 m = reinterpret_cast<f32x8>((bits & 0x807fffffu) | 0x3f000000u);  // frexp of a normal x
    i32x8 e = reinterpret_cast<i32x8>(bits >> 23u) - 126;
    const i32x8 low = m < real(0.70710678118654752440);
    m = low ? real(2) * m : m;
    e = low ? e - 1 : e;
    const f32x8 f = m - real(1);
    const f32x8 s = f / (real(2) + f);
    const f32x8 z = s * s;
    f32x8 t = f32x8{} + real(1) / real(13);
    t = real(1) / real(11) + z * t;
    t = real(1) / real(9) + z * t;
    t = real(1) / real(7) + z * t;
    t = real(1) / real(5) + z * t;
    t = real(1) / real(3) + z * t;
    t = real(1) + z * t;
    x = __builtin_convertvector(e, f32x8) + real(2.88539008177792681472) * (s * t);
}

// glint_footprint_lattice of the eight footprints f[v] (major, minor, angle), lane-wise: the same
// operations in the same order (glint_log2's reduction by bits, frexp's for normal x; GLM's max and
// min as the selects (x < y) ? y : x and (y < x) ? y : x; the triangle cases and the prism split
// as selects), so the same values bit for bit; lanes not in `drawing` get weight 0. One pixel at a
// time this took about 230 instructions a pixel, a fifth of the IBL estimate's, and its log2f
// calls another 40; in lanes about 80 (callgrind, glint_frame_loop ibl-rows 4 1; DEVELOPERS.md).
__attribute__((always_inline)) static inline void glint_lanes_lattice(const glint_f32x8& major_in, const glint_f32x8& minor_in, const glint_f32x8& angle,
                                                                     real lod_scale, int drawing, glint_lattice_lanes& lat) {
    typedef glint_i32x8 i32x8;
    typedef glint_f32x8 f32x8;
    const f32x8 zero = {};
    // GLM's max(x, y) and min(x, y) as (x < y) ? y : x and (y < x) ? y : x.
    f32x8 major = (major_in < real(1e-30)) ? zero + real(1e-30) : major_in;
    const f32x8 major_16 = major / real(16);
    f32x8 minor = (minor_in < major_16) ? major_16 : minor_in;
    minor = (minor < real(1e-30)) ? zero + real(1e-30) : minor;
    f32x8 lod = minor * max(lod_scale, real(1e-30)), rho = major / minor;
    glint_lanes_log2(lod), glint_lanes_log2(rho);
    lod = (lod < GLINT_MIN_LOD) ? zero + GLINT_MIN_LOD : lod;
    lod = (GLINT_MAX_LOD < lod) ? zero + GLINT_MAX_LOD : lod;
    rho = (rho < real(0)) ? zero : rho;
    rho = (real(GLINT_MAX_RATIO_LEVEL) < rho) ? zero + real(GLINT_MAX_RATIO_LEVEL) : rho;
    f32x8 rho_floor = rho;
    glint_lanes_floor_bounded(rho_floor);
    i32x8 r0 = __builtin_convertvector(rho_floor, i32x8);
    r0 = (r0 < GLINT_MAX_RATIO_LEVEL - 1) ? r0 : i32x8{} + (GLINT_MAX_RATIO_LEVEL - 1);
    const f32x8 tr = rho - __builtin_convertvector(r0, f32x8);
    f32x8 l0 = lod;
    glint_lanes_floor_bounded(l0);
    const f32x8 tl = lod - l0;
    // The triangle in the (angle, tr) strip: level 0's fan has level 1's four bins.
    const i32x8 fan = (r0 == 0);
    const i32x8 lo = r0 * 1024, hi = (r0 + 1) * 1024;
    const i32x8 n0 = fan ? i32x8{} + 4 : (i32x8{} + 2) << r0;
    const f32x8 x = angle * __builtin_convertvector(n0, f32x8) / GLINT_PI;
    f32x8 x_floor = x;
    glint_lanes_floor_bounded(x_floor);
    i32x8 k = __builtin_convertvector(x_floor, i32x8);
    k = (k < n0 - 1) ? k : n0 - 1;
    const f32x8 fx = x - __builtin_convertvector(k, f32x8);
    const i32x8 kn = (k + 1 == n0) ? i32x8{} : k + 1;  // the fan's (k + 1) & 3
    const i32x8 t0 = 2 * k, t1 = 2 * k + 1, t2 = (2 * k + 2 == 2 * n0) ? i32x8{} : 2 * k + 2;
    const i32x8 case_a = ~fan & (fx < real(0.5) * tr), case_c = ~fan & ~case_a & (fx > real(1) - real(0.5) * tr);
    const i32x8 case_b = ~fan & ~case_a & ~case_c;
    const f32x8 gx = real(1) - fx;
    i32x8 key[3] = {fan ? lo : (case_c ? lo + kn : lo + k), fan ? hi + k : (case_b ? hi + t1 : (case_a ? hi + t0 : hi + t1)),
                    fan ? hi + kn : (case_b ? lo + kn : (case_a ? hi + t1 : hi + t2))};
    f32x8 bary[3] = {case_b ? real(1) - fx - real(0.5) * tr : real(1) - tr,
                     fan ? tr * (real(1) - fx) : (case_b ? tr : (case_a ? tr - real(2) * fx : real(2) * gx)),
                     fan ? tr * fx : (case_b ? fx - real(0.5) * tr : (case_a ? real(2) * fx : tr - real(2) * gx))};
    for (int i = 0; i < 3; ++i) bary[i] = (bary[i] < real(0)) ? zero : bary[i];
    // Sort the three vertices by key (glint_footprint_lattice's three compare-and-swaps).
    for (int a : {0, 1, 0}) {
        const int b = a + 1;
        const i32x8 swap = key[a] > key[b];
        const i32x8 ka = key[a];
        const f32x8 ba = bary[a];
        key[a] = swap ? key[b] : key[a], key[b] = swap ? ka : key[b];
        bary[a] = swap ? bary[b] : bary[a], bary[b] = swap ? ba : bary[b];
    }
    // The prism split: v1 < v2 < v3 at L0 and L0 + 1.
    const i32x8 L0 = __builtin_convertvector(l0, i32x8);
    i32x8 level[3], bin[3];
    for (int i = 0; i < 3; ++i) level[i] = key[i] >> 10, bin[i] = key[i] & 1023;  // key / 1024 for key >= 0
    const i32x8 first = (tl <= bary[0]), second = ~first & (tl <= bary[0] + bary[1]);
    const f32x8 w[4] = {first ? bary[0] - tl : bary[0], first ? bary[1] : (second ? bary[0] + bary[1] - tl : bary[1]),
                        (first | second) ? bary[2] : real(1) - tl, first ? tl : (second ? tl - bary[0] : tl - bary[0] - bary[1])};
    const i32x8 up = L0 + 1;
    const i32x8 lods[4] = {first ? L0 : up, (first | second) ? L0 : up, L0, up};
    const i32x8 last_level = first ? level[0] : (second ? level[1] : level[2]), last_bin = first ? bin[0] : (second ? bin[1] : bin[2]);
    i32x8 draws = {};
    for (int v = 0; v < 8; ++v) draws[v] = ((drawing >> v) & 1) != 0 ? -1 : 0;
    for (int l = 0; l < 4; ++l) {
        lat.weight[l] = draws ? ((w[l] < real(0)) ? zero : w[l]) : zero;
        lat.lod[l] = lods[l];
        lat.level[l] = (l < 3) ? level[l] : last_level;
        lat.bin[l] = (l < 3) ? bin[l] : last_bin;
    }
}

// glint_footprint_vertices of the lanes' pixels (no log-normal density) into d's slot arrays,
// from the pixels' uv and footprints: their lattices (glint_lanes_lattice), then
// glint_lattice_triangles_x4's operations with the pixels in the lanes instead of the lattice
// points, every lattice point in slots 4 t + l, or for a pixel with a lattice_u its chosen point's
// three vertices in slots 0 to 2 (the same values bit for bit); no pixel's vertex arrays written.
GLINT_LANES_BODY
void glint_lanes_footprint_vertices_body(glint_lanes_vertices& d, int n, const glint_grid_pixel* px, real lod_scale, int drawing, uint seed) {
    typedef glint_u32x8 u32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_f32x8 f32x8;
    // The pixels' uv and footprints, from scalars in registers (lanes n to 7 repeat pixel n - 1).
    const glint_grid_pixel* q[8];
    for (int v = 0; v < 8; ++v) q[v] = px + std::min(v, n - 1);
    const f32x8 ux = {q[0]->uv.x, q[1]->uv.x, q[2]->uv.x, q[3]->uv.x, q[4]->uv.x, q[5]->uv.x, q[6]->uv.x, q[7]->uv.x};
    const f32x8 uy = {q[0]->uv.y, q[1]->uv.y, q[2]->uv.y, q[3]->uv.y, q[4]->uv.y, q[5]->uv.y, q[6]->uv.y, q[7]->uv.y};
    const f32x8 major = {q[0]->f.major, q[1]->f.major, q[2]->f.major, q[3]->f.major, q[4]->f.major, q[5]->f.major, q[6]->f.major, q[7]->f.major};
    const f32x8 minor = {q[0]->f.minor, q[1]->f.minor, q[2]->f.minor, q[3]->f.minor, q[4]->f.minor, q[5]->f.minor, q[6]->f.minor, q[7]->f.minor};
    const f32x8 angle = {q[0]->f.angle, q[1]->f.angle, q[2]->f.angle, q[3]->f.angle, q[4]->f.angle, q[5]->f.angle, q[6]->f.angle, q[7]->f.angle};
    const f32x8 lattice_u = {q[0]->lattice_u, q[1]->lattice_u, q[2]->lattice_u, q[3]->lattice_u,
                             q[4]->lattice_u, q[5]->lattice_u, q[6]->lattice_u, q[7]->lattice_u};
    glint_lattice_lanes lat;
    glint_lanes_lattice(major, minor, angle, lod_scale, drawing, lat);
    // One lattice point (glint_grid_pixel_setup_stochastic's pixels): glint_lattice_choice lane-wise;
    // its three vertices go to slots 0 to 2 with share 1, as glint_footprint_vertices puts them.
    const i32x8 one_point = lattice_u >= real(0);
    const bool some_one = !glint_lanes_all_zero(reinterpret_cast<u32x8>(one_point));
    i32x8 chosen = i32x8{} - 1;
    f32x8 below = {};
    for (int l = 0; l < 4; ++l) {
        const i32x8 on = lat.weight[l] > real(0);
        chosen = (on & ((chosen < 0) | (lattice_u >= below))) ? i32x8{} + l : chosen;
        below = on ? below + lat.weight[l] : below;
    }
    f32x8 one_weight[3], one_share[3];  // set where some_one
    u32x8 one_hash_x[3], one_hash_y[3], one_hash_z[3];
    if (some_one)
        for (int t = 0; t < 3; ++t) one_weight[t] = one_share[t] = f32x8{}, one_hash_x[t] = one_hash_y[t] = one_hash_z[t] = u32x8{};
    for (int v = 0; v < 8; ++v) d.count[v] = ((drawing >> v) & 1) == 0 ? 0 : (one_point[v] != 0 ? 3 : 12);
    d.slots = some_one ? 0xfff : 0;
    for (int l = 0; l < 4; ++l) {
        const f32x8 wl = lat.weight[l];
        // A lattice point that no lane's footprint weighs (an isotropic footprint's second ratio
        // level) has no vertices to draw: no triangle or hashes, and its slots are left out of
        // d.slots unwritten (zeros where the one-point pixels' merge below reads every slot). In
        // the IBL's K = 4 frame (glint_frame_loop ibl-rows 4) half the lattice points: 9.10M to
        // 8.58M instructions in the estimates, the least frame 1555-1568 to 1487-1499 us; the
        // zeros' stores left out, 7.45M to 7.40M (DEVELOPERS.md).
        if (glint_lanes_all_zero(reinterpret_cast<u32x8>(wl > real(0)))) {
            const u32x8 none = {};
            for (int t = 0; t < 3 && some_one; ++t) {
                const int slot = 4 * t + l;
                std::memcpy(d.weight[slot], &none, sizeof(none)), std::memcpy(d.share[slot], &none, sizeof(none));
                std::memcpy(d.hash_x[slot], &none, sizeof(none)), std::memcpy(d.hash_y[slot], &none, sizeof(none)), std::memcpy(d.hash_z[slot], &none, sizeof(none));
            }
            continue;
        }
        d.slots |= 0x111 << l;
        const i32x8 lod = lat.lod[l], level = lat.level[l], bin = lat.bin[l];
        f32x8 c, sn;
        glint_lanes_rotation(level, bin, c, sn);
        const f32x8 scale_x = reinterpret_cast<f32x8>((-lod - level + 127) << 23), scale_y = reinterpret_cast<f32x8>((-lod + 127) << 23);
        const f32x8 qx = (c * ux + sn * uy) * scale_x, qy = (-sn * ux + c * uy) * scale_y;
        f32x8 sx = qx - qy * real(0.577350269189625764509), sy = qy * real(1.15470053837925152902);
        const f32x8 lo = f32x8{} + real(-1073741824), hi = f32x8{} + real(1073741824);
        sx = (sx < lo) ? lo : sx, sy = (sy < lo) ? lo : sy;
        sx = (hi < sx) ? hi : sx, sy = (hi < sy) ? hi : sy;
        f32x8 ix = __builtin_convertvector(__builtin_convertvector(sx, i32x8), f32x8), iy = __builtin_convertvector(__builtin_convertvector(sy, i32x8), f32x8);
        ix = (ix > sx) ? ix - real(1) : ix, iy = (iy > sy) ? iy - real(1) : iy;
        const f32x8 fx = sx - ix, fy = sy - iy;
        const i32x8 bx = __builtin_convertvector(ix, i32x8), by = __builtin_convertvector(iy, i32x8);
        const i32x8 u = (!(fx + fy < real(1))) & 1;
        const f32x8 uf = __builtin_convertvector(u, f32x8);
        const f32x8 w[3] = {real(1) - fx - fy, uf - fx, uf - fy};
        const u32x8 key = (reinterpret_cast<u32x8>(lod + 64) | (reinterpret_cast<u32x8>(level) << 8u) | (reinterpret_cast<u32x8>(bin) << 12u)) ^ seed;
        u32x8 hx[3] = {reinterpret_cast<u32x8>(bx + u), reinterpret_cast<u32x8>(bx + 1 - u), reinterpret_cast<u32x8>(bx + u)};
        u32x8 hy[3] = {reinterpret_cast<u32x8>(by + u), reinterpret_cast<u32x8>(by + u), reinterpret_cast<u32x8>(by + 1 - u)};
        u32x8 hz[3] = {key, key, key};
        for (int t = 0; t < 3; ++t) {
            glint_pcg3d_vectors(hx[t], hy[t], hz[t]);
            const f32x8 wt = reinterpret_cast<f32x8>(reinterpret_cast<u32x8>(w[t]) & 0x7fffffffu);  // glint_abs
            const auto on = (wt > real(0)) & (wl > real(0));
            const f32x8 weight = on ? wt : f32x8{}, share = on ? wl : f32x8{};
            const int slot = 4 * t + l;
            std::memcpy(d.weight[slot], &weight, sizeof(weight)), std::memcpy(d.share[slot], &share, sizeof(share));
            std::memcpy(d.hash_x[slot], &hx[t], sizeof(hx[t])), std::memcpy(d.hash_y[slot], &hy[t], sizeof(hy[t])), std::memcpy(d.hash_z[slot], &hz[t], sizeof(hz[t]));
            if (!some_one) continue;
            const i32x8 mine = (chosen == l), one_on = wt > real(0);
            one_weight[t] = mine ? (one_on ? wt : f32x8{}) : one_weight[t];
            one_share[t] = mine ? (one_on ? f32x8{} + real(1) : f32x8{}) : one_share[t];
            one_hash_x[t] = mine ? hx[t] : one_hash_x[t], one_hash_y[t] = mine ? hy[t] : one_hash_y[t], one_hash_z[t] = mine ? hz[t] : one_hash_z[t];
        }
    }
    if (!some_one) return;
    for (int slot = 0; slot < 12; ++slot) {
        f32x8 weight, share;
        std::memcpy(&weight, d.weight[slot], sizeof(weight)), std::memcpy(&share, d.share[slot], sizeof(share));
        weight = one_point ? (slot < 3 ? one_weight[slot] : f32x8{}) : weight;
        share = one_point ? (slot < 3 ? one_share[slot] : f32x8{}) : share;
        std::memcpy(d.weight[slot], &weight, sizeof(weight)), std::memcpy(d.share[slot], &share, sizeof(share));
        if (slot >= 3) continue;
        u32x8 hx, hy, hz;
        std::memcpy(&hx, d.hash_x[slot], sizeof(hx)), std::memcpy(&hy, d.hash_y[slot], sizeof(hy)), std::memcpy(&hz, d.hash_z[slot], sizeof(hz));
        hx = one_point ? one_hash_x[slot] : hx, hy = one_point ? one_hash_y[slot] : hy, hz = one_point ? one_hash_z[slot] : hz;
        std::memcpy(d.hash_x[slot], &hx, sizeof(hx)), std::memcpy(d.hash_y[slot], &hy, sizeof(hy)), std::memcpy(d.hash_z[slot], &hz, sizeof(hz));
    }
}
GLINT_LANES_VARIANTS(void, glint_lanes_footprint_vertices,
                     (glint_lanes_vertices& d, int n, const glint_grid_pixel* px, real lod_scale, int drawing, uint seed),
                     (d, n, px, lod_scale, drawing, seed))


// glint_grid_pixel_setup_stochastic for pixels 0 .. n - 1 (n <= 8; u < 0: every lattice point),
// their footprints lane-wise: glint_footprint_from_derivatives' and glint_atan2's operations in
// the same order (GLM's abs, max and min as x >= 0 ? x : -x, (x < y) ? y : x and (y < x) ? y : x;
// both sides of glint_atan2's selects computed), the same values bit for bit. One pixel at a time
// the footprint is a chain of two square roots and two divisions.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
GLINT_LANES_BODY void glint_grid_pixels_setup_x8_body(int n, const vec2* uv, const vec2* duvdx, const vec2* duvdy,
                                                      const glint_grid_params& g, const real* lattice_u, glint_grid_pixel* out) {
    typedef glint_f32x8 f32x8;
    typedef glint_i32x8 i32x8;
    int at[8];
    for (int v = 0; v < 8; ++v) at[v] = std::min(v, n - 1);  // lanes n to 7 repeat pixel n - 1
    const f32x8 xx = {duvdx[at[0]].x, duvdx[at[1]].x, duvdx[at[2]].x, duvdx[at[3]].x, duvdx[at[4]].x, duvdx[at[5]].x, duvdx[at[6]].x, duvdx[at[7]].x};
    const f32x8 xy = {duvdx[at[0]].y, duvdx[at[1]].y, duvdx[at[2]].y, duvdx[at[3]].y, duvdx[at[4]].y, duvdx[at[5]].y, duvdx[at[6]].y, duvdx[at[7]].y};
    const f32x8 yx = {duvdy[at[0]].x, duvdy[at[1]].x, duvdy[at[2]].x, duvdy[at[3]].x, duvdy[at[4]].x, duvdy[at[5]].x, duvdy[at[6]].x, duvdy[at[7]].x};
    const f32x8 yy = {duvdy[at[0]].y, duvdy[at[1]].y, duvdy[at[2]].y, duvdy[at[3]].y, duvdy[at[4]].y, duvdy[at[5]].y, duvdy[at[6]].y, duvdy[at[7]].y};
    const f32x8 zero = {};
    // glint_footprint_from_derivatives
    const f32x8 a = xx * xx + yx * yx, b = xx * xy + yx * yy, c = xy * xy + yy * yy;
    f32x8 det = xx * yy - xy * yx;
    det = (det >= 0.0f) ? det : -det;
    const f32x8 half_diff = 0.5f * (a - c);
    const f32x8 l2 = 0.5f * (a + c) + __builtin_ia32_sqrtps256(half_diff * half_diff + b * b);
    const f32x8 major = __builtin_ia32_sqrtps256(l2), minor = (l2 > 0.0f) ? det / major : zero;
    // glint_atan2(2 b, a - c)
    const f32x8 y = 2.0f * b, x = a - c;
    const f32x8 ax = (x >= 0.0f) ? x : -x, ay = (y >= 0.0f) ? y : -y;
    const f32x8 hi = (ax < ay) ? ay : ax, lo = (ay < ax) ? ay : ax;
    const i32x8 finite = (hi > 0.0f) & (hi < 3.4e38f);
    const f32x8 t = lo / hi;
    const i32x8 reduce = t > 0.267949192431122706473f;  // tan(pi / 12)
    const float k = 0.577350269189625764509f;            // 1 / sqrt(3)
    const f32x8 r = reduce ? (t - k) / (1.0f + t * k) : t;
    // glint_atan_reduced
    const f32x8 z = r * r;
    f32x8 sum = zero;
    sum = 1.0f / 13.0f - z * sum;
    sum = 1.0f / 11.0f - z * sum;
    sum = 1.0f / 9.0f - z * sum;
    sum = 1.0f / 7.0f - z * sum;
    sum = 1.0f / 5.0f - z * sum;
    sum = 1.0f / 3.0f - z * sum;
    sum = 1.0f - z * sum;
    f32x8 atan = (reduce ? zero + GLINT_PI / 6.0f : zero) + r * sum;
    atan = (ay > ax) ? GLINT_PI / 2.0f - atan : atan;
    atan = (x < 0.0f) ? GLINT_PI - atan : atan;
    atan = (y < 0.0f) ? -atan : atan;
    atan = finite ? atan : zero;
    f32x8 angle = 0.5f * atan;
    angle = (angle < 0.0f) ? angle + GLINT_PI : angle;
    angle = (angle >= GLINT_PI) ? zero : angle;
    // glint_footprint_count, its exp once
    const float density = exp(clamp(g.log_density, -80.0f, 80.0f));
    f32x8 N = density * det;
    N = (1e30f < N) ? zero + 1e30f : N;
    for (int v = 0; v < n; ++v) {
        glint_grid_pixel& px = out[v];
        px.uv = uv[v];
        px.f.area = det[v], px.f.minor = minor[v], px.f.major = major[v], px.f.angle = angle[v];
        px.N = N[v];
        const real u = lattice_u ? lattice_u[v] : real(-1);
        px.lattice_u = (u < real(0)) ? real(-1) : min(u, real(0.99999994));  // glint_grid_pixel_setup_stochastic
        px.ready = false;
        px.v.count = 0;
    }
}
GLINT_LANES_VARIANTS(void, glint_grid_pixels_setup_x8,
                     (int n, const vec2* uv, const vec2* duvdx, const vec2* duvdy, const glint_grid_params& g, const real* lattice_u,
                      glint_grid_pixel* out),
                     (n, uv, duvdx, duvdy, g, lattice_u, out))
#endif

// out[i] = glint_grid_pixel_setup_stochastic(uv[i], duvdx[i], duvdy[i], g, u) for i < count, u =
// lattice_u[i] or, where lattice_u is null, -1 (every lattice point): bit for bit, eight
// footprints at a time in AVX2 lanes where the CPU has them (float).
GLINT_FN_OUT_OF_LINE void glint_grid_pixels_setup(int count, const vec2* uv, const vec2* duvdx, const vec2* duvdy, const glint_grid_params& g,
                                                  const real* lattice_u, glint_grid_pixel* out) {
    for (int first = 0; first < count; first += 8) {
        const int n = (count - first < 8) ? count - first : 8;
        const real* u = lattice_u ? lattice_u + first : nullptr;
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
        if constexpr (!GLINT_DOUBLE) {
            if (glint_cpu_avx2()) {
                glint_grid_pixels_setup_x8(n, uv + first, duvdx + first, duvdy + first, g, u, out + first);
                continue;
            }
        }
#endif
        for (int k = 0; k < n; ++k)
            out[first + k] = glint_grid_pixel_setup_stochastic(uv[first + k], duvdx[first + k], duvdy[first + k], g, u ? u[k] : real(-1));
    }
}

// out[v] = glint_grid_sample_pixel(px[v], g, lights[v]) for v < n <= 8, bit for bit (a
// pixel a lane; tests/unit/test_grid.cpp): each light's set-up (glint_light_lanes_setup with the
// lane's own N), the vertices of the pixels that draw (glint_lanes_footprint_vertices, no
// log-normal density), the skip test slot by slot with the pixels in the lanes, then each drawing
// pixel's draws in glint_grid_sample_pixel's order. The pixels' own vertex arrays are not filled
// (the single-pixel fallbacks fill them, as glint_grid_sample_pixel does).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
GLINT_LANES_BODY void glint_grid_sample_pixels_x8_body(glint_grid_pixel* px, int n, const glint_grid_params& g,
                                                       const glint_grid_light* lights, glint_grid_estimate* out) {
    typedef glint_f32x8 f32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_u32x8 u32x8;
    const glint_grid_pixel* q[8];  // lanes n to 7 repeat pixel n - 1 (their lights have E[R] = 0)
    for (int v = 0; v < 8; ++v) q[v] = px + std::min(v, n - 1);
    const f32x8 N = {q[0]->N, q[1]->N, q[2]->N, q[3]->N, q[4]->N, q[5]->N, q[6]->N, q[7]->N};
    glint_light_lanes o;
    if (!glint_light_lanes_setup(g, lights, n, N, o)) {
        for (int v = 0; v < n; ++v) out[v] = glint_grid_sample_pixel(px[v], g, lights[v]);
        return;
    }
    glint_light_lanes_results(o, n, out);
    const int drawing = __builtin_ia32_movmskps256(reinterpret_cast<f32x8>(o.draws));
    if (drawing == 0) return;
    glint_lanes_vertices d;
    glint_lanes_footprint_vertices(d, n, px, g.lod_scale, drawing, g.seed);
    // The skip test: glint_grid_skip_inputs' bound lane-wise, then each slot's words against its
    // pixel's corner keys (a slot without a vertex never draws).
    i32x8 bits[12], any = {};
    for (int s = 0; s < 12; ++s) {
        if (((d.slots >> s) & 1) == 0) {
            bits[s] = i32x8{};
            continue;
        }
        f32x8 share, weight;
        u32x8 hx;
        std::memcpy(&share, d.share[s], sizeof(share)), std::memcpy(&weight, d.weight[s], sizeof(weight)), std::memcpy(&hx, d.hash_x[s], sizeof(hx));
        const f32x8 trials = N * share, zero = {};
        const f32x8 scale = ((trials > 2.0f) ? trials + 1.0f : zero + 2.0f) * ((weight > 0.0f) ? zero + 1.0001f : zero);
        glint_hash_u32_first_step(hx);  // the skip test's share of the word (core.glsl)
        bits[s] = glint_light_lanes_skip_bits(o, hx, scale) & (weight > 0.0f);
        any |= bits[s];
    }
    // The draws, lattice point by lattice point (slot 4 t + l) as glint_grid_sample_pixel makes them.
    const int slot[12] = {0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11};  // glint_grid_draw_slot(12, k)
    for (int lanes = __builtin_ia32_movmskps256(reinterpret_cast<f32x8>(o.draws & (any != 0))); lanes != 0; lanes &= lanes - 1) {
        const int v = __builtin_ctz(static_cast<unsigned>(lanes)), count = d.count[v];
        glint_grid_estimate& e = out[v];
        for (int k = 0; k < count; ++k) {
            const int i = (count == 12) ? slot[k] : k;
            for (int corners = bits[i][v]; corners != 0; corners &= corners - 1) {
                const int j = __builtin_ctz(static_cast<unsigned>(corners));
                e.value += d.weight[i][v] * o.mu[j][v] *
                           glint_vertex_corner_count(g, N[v] * d.share[i][v], d.hash_x[i][v], d.hash_y[i][v], o.key[j][v], o.corner_p[j][v]) / N[v];
                ++e.draws;
            }
        }
    }
}
GLINT_LANES_VARIANTS(void, glint_grid_sample_pixels_x8,
                     (glint_grid_pixel* px, int n, const glint_grid_params& g, const glint_grid_light* lights, glint_grid_estimate* out),
                     (px, n, g, lights, out))
#endif

// out[i] = glint_grid_sample_pixel(px[i], g, lights[i]) for i < count, bit for bit: pixel i under
// its own light, eight pixels at a time where the CPU has AVX2 (float) and the density has no
// log-normal factor, else one at a time. Batches of one or two go one at a time too, as in
// glint_grid_sample_pixel_lights (measured there for lights, not here for pixels).
GLINT_FN_OUT_OF_LINE void glint_grid_sample_pixels(glint_grid_pixel* px, const glint_grid_params& g, const glint_grid_light* lights, int count,
                                                   glint_grid_estimate* out) {
    for (int first = 0; first < count; first += 8) {
        const int n = (count - first < 8) ? count - first : 8;
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
        if constexpr (!GLINT_DOUBLE) {
            if (n > 2 && !(g.density_sigma > real(0)) && glint_cpu_avx2()) {
                glint_grid_sample_pixels_x8(px + first, n, g, lights + first, out + first);
                continue;
            }
        }
#endif
        for (int k = 0; k < n; ++k) out[first + k] = glint_grid_sample_pixel(px[first + k], g, lights[first + k]);
    }
}
#endif

// R / E[R], the factor that turns the smooth BRDF into the glint BRDF (0 if E[R] = 0).
GLINT_FN real glint_modulation(glint_grid_estimate e) {
    return (e.expected > real(0)) ? e.value / e.expected : real(0);
}
