// glint's image-based lighting of glints (KK25 Sec. 4-5). Needs core.glsl, binomial.glsl,
// multinomial.glsl, microfacet.glsl and grid.glsl. The host side (levels, fuzzy indicator maps,
// prefiltering, tables) is in include/glint/ibl.hpp.
//
// The environment is split into K radiance levels L_1 = 0 < L_2 < ... < L_K (KK25 Eq. 18), each
// an area light of constant radiance whose shape is given by a fuzzy indicator map w_k (Eq. 19,
// summing to 1 per pixel). Prefiltered with the same GGX kernel as the radiance (Eq. 21), the
// indicator maps give at the reflection direction the share w_k of each level; the probability
// that one microfacet reflects level k is p_k = E_D w_k / D_H (Eq. 15, 21), E_D the visible
// reflecting microfacet area. A multinomial draw over the levels at each grid vertex gives the
// glint result as the smooth result times sum_k L_k M_k / (N sum_k L_k p_k) (Eq. 17), whose mean
// is the smooth result when the draws are mean-preserving. The black level and the microfacets
// that reflect nothing (masked, below the horizon) share the multinomial's rest bin.

GLINT_CONST(int) GLINT_IBL_MAX_LEVELS = 8;

// The radiance levels, L[0] = 0 (KK25 Eq. 18); count = K in [3, 8].
struct glint_ibl_levels {
    int count;
    real radiance[8];
};

// Per level k, the prefiltered fuzzy indicator at the pixel's reflection direction and
// roughness (sums to 1 over k up to filtering error).
struct glint_ibl_indicators {
    real w[8];
};

// KK25 Eq. 18 with a 0-based index k of K, for luminances clipped to [lo, hi] (0 < lo <= hi):
// L_0 = 0 and L_k = exp(lerp(log lo, log hi, k / (K - 1))) for k >= 1 (so L_{K-1} = hi).
GLINT_FN real glint_ibl_level(int k, int K, real lo, real hi) {
    if (k <= 0) return real(0);
    return exp(mix(log(lo), log(hi), real(k) / real(K - 1)));
}

// KK25 Eq. 19: the fuzzy indicator weights of luminance y between the levels: returns (j, t)
// with w_j = 1 - t and w_{j+1} = t (0-based j). Linear interpolation by default; `log_space`
// interpolates log y between the levels above the black one (the black level, 0, has no log:
// linear there). Luminances above the top level are all in the top level.
GLINT_FN vec2 glint_ibl_fuzzy_weight(real y, glint_ibl_levels lv, bool log_space) {
    int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    y = max(y, real(0));
    if (!(y < lv.radiance[K - 1])) return vec2(real(K - 2), real(1));
    int j = 0;
    for (int k = 1; k < 8; ++k)
        if (k < K - 1 && y >= lv.radiance[k]) j = k;
    real a = lv.radiance[j], b = lv.radiance[j + 1];
    real t = (y - a) / max(b - a, real(1e-30));
    if (log_space && j > 0) t = log(y / a) / log(b / a);
    return vec2(real(j), clamp(t, real(0), real(1)));
}

// The per-level reflection probabilities p_k = E_D w_k / D_H (KK25 Eq. 15, 21), scaled down if they
// sum to more than 1.
GLINT_FN glint_multinomial_probabilities glint_ibl_probabilities(GLINT_IN(glint_ibl_levels) lv, GLINT_IN(glint_ibl_indicators) ind, real e_d, real d_h) {
    // Each p_k computed twice, for the sum and then scaled, rather than stored and rescaled in
    // place: in C++ the rescaling's vector loads of the scalar stores waited for them (perf: an
    // eighth of glint_ibl_sample's samples).
    glint_multinomial_probabilities pr;
    int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
#if defined(GLINT_GLSL)
    real total = real(0);
    for (int k = 0; k < 8; ++k) total += (k < K) ? clamp(e_d * ind.w[k] / max(d_h, real(1)), real(0), real(1)) : real(0);
    real scale = (total > real(1)) ? real(1) / total : real(1);
    for (int k = 0; k < 8; ++k) pr.p[k] = ((k < K) ? clamp(e_d * ind.w[k] / max(d_h, real(1)), real(0), real(1)) : real(0)) * scale;
#else
    // The same values four levels at a time (GCC kept the loops scalar: sixteen divisions a
    // pixel); the clamp as GLM's max then min, which keep a NaN.
    typedef real realx4 __attribute__((vector_size(4 * sizeof(real))));
    typedef decltype(realx4{} < realx4{}) maskx4;
    const realx4 none = {}, one = none + real(1);
    realx4 v[2];
    for (int h = 0; h < 2; ++h) {
        realx4 w;
        std::memcpy(&w, ind.w + 4 * h, sizeof(w));
        realx4 x = e_d * w / max(d_h, real(1));
        x = (x < none) ? none : x;
        x = (one < x) ? one : x;
        const maskx4 level = {4 * h, 4 * h + 1, 4 * h + 2, 4 * h + 3};
        v[h] = (level < K) ? x : none;
    }
    real total;
    glint_scale_to_unit_sum(v, pr.p, total);
#endif
    return pr;
}

// Per level, sum over the footprint's grid vertices of l_t M_k / N: the reflecting microfacets
// of each level as a fraction of the footprint's N, E[share_k] = p_k. The multinomial runs over
// the levels above the black one (K - 1 bins, K >= 3); the black level joins the rest bin (both
// reflect no light), so share_0 = 0.
struct glint_ibl_shares {
    real share[8];
    int draws;
};

GLINT_FN glint_ibl_shares glint_ibl_level_shares(GLINT_INOUT(glint_grid_pixel) px, GLINT_IN(glint_grid_params) g, int K,
                                                 GLINT_IN(glint_multinomial_probabilities) lit) {
    glint_ibl_shares o;
    for (int k = 0; k < 8; ++k) o.share[k] = real(0);
    o.draws = 0;
    real N = px.N;
    if (!(N > real(1e-30))) return o;
    glint_grid_pixel_vertices(px, g);
    bool skip_test = glint_skip_test_applies(g);  // with the vertices' px.skip_scale: glint_surely_no_success
    real lit_total = real(0);
    for (int k = 0; k < 8; ++k) lit_total += lit.p[k];
    // Every vertex splits with the same probabilities: the tree once per pixel, its nodes' q where
    // a vertex draws down the tree (below; the bit-sliced pass reads the p alone). The triangle
    // vertices of a lattice point share the root's N and p (glint_grid_sample).
    glint_multinomial_tree tree = glint_multinomial_tree_root(lit, K - 1);
    glint_binomial_cache root_cache = glint_binomial_empty_cache();
    real weighted[8];  // sum over the vertices of l_t M_k, divided by N once after the loop
    for (int k = 0; k < 8; ++k) weighted[k] = real(0);
#if !defined(GLINT_GLSL)
    // C++: the vertices whose draw is one bit-sliced pass (glint_multinomial_exact_all_applies) are
    // drawn together (glint_multinomial_exact_all_weighted, four or eight lane groups at a time),
    // which adds their l_t M_k to weighted before the loop: the same counts as
    // glint_multinomial_draw vertex by vertex, as GLSL does it, summed in another order.
    // The test is glint_multinomial_exact_all_applies's with & for &&, over the 12 slots at once
    // (GCC vectorises it; the call per slot with its branches, the present list and the loop below
    // were a fifth of the K = 4 estimate's instructions where every vertex is in the batch, as in
    // the report's IBL frame).
    uint in_batch = 0u;  // bit i set where vertex i is in the batch
    real batch_N[12];
    uint root_x[12], root_y[12], root_z[12];  // glint_multinomial_node_words(hash, 0) = PCG3D(hash), every vertex together
    int batched = 0;
    int present_count = 0;
    {
        typedef real realx4 __attribute__((vector_size(4 * sizeof(real))));
        typedef decltype(realx4{} < realx4{}) maskx4;  // a comparison's lanes: all ones or 0
        typedef int i32x4 __attribute__((vector_size(16)));
        const maskx4 unbiased = maskx4{} - ((g.variant == GLINT_BINOMIAL_UNBIASED) ? 1 : 0);
        i32x4 batched_lanes = {}, present_lanes = {}, batch_bits = {};
        for (int b = 0; b < 12; b += 4) {
            realx4 share, weight;
            std::memcpy(&share, px.v.share + b, sizeof(share));
            std::memcpy(&weight, px.v.weight + b, sizeof(weight));
            const realx4 n = N * share;
            const maskx4 slot = {b, b + 1, b + 2, b + 3};
            const i32x4 present = __builtin_convertvector((slot < px.v.count) & (weight > real(0)), i32x4);
            const i32x4 batch = present & __builtin_convertvector(unbiased & (n >= GLINT_MULTINOMIAL_EXACT_SPLIT_MIN) & (n <= GLINT_MULTINOMIAL_EXACT_ALL_MAX) &
                                                                  (n * tree.total >= real(1)),
                                                                  i32x4);
            std::memcpy(batch_N + b, &n, sizeof(n));
            batch_bits |= batch & (i32x4{1, 2, 4, 8} << b);
            batched_lanes -= batch;  // -1 per lane in the batch
            present_lanes -= present;
        }
        for (int l = 0; l < 4; ++l) batched += batched_lanes[l], present_count += present_lanes[l], in_batch |= uint(batch_bits[l]);
    }
    glint_pcg3d_many(px.v.hash_x, px.v.hash_y, px.v.hash_z, px.v.count, root_x, root_y, root_z);
    glint_multinomial_exact_all_weighted(tree, in_batch, batch_N, root_x, root_y, root_z, px.v.weight, weighted);
    o.draws += batched * (K - 1);  // N total >= 1 there: the skip test below never fires
    bool rest = batched < present_count;  // vertices left to the loop below
#else
    bool rest = true;
#endif
    if (rest) {
        glint_multinomial_tree_splits(tree);
        // The slots that hold a vertex, packed: a GPU runs a fragment's loop as long as its longest
        // neighbour's, so the loop goes over the present vertices (on llvmpipe, glint_gl at 192 x 120,
        // a loop over the twelve slots took 157 ms a K = 4 frame against 139 to 151, 235 to 245 at K = 8
        // against 215 to 221).
        int present[12];
        int count = 0;
        for (int k = 0; k < 12; ++k) {
            int i = glint_grid_draw_slot(px.v.count, k);  // lattice point by lattice point: the root's cache
            present[count] = i;
            count += (i < px.v.count && px.v.weight[i] > real(0)) ? 1 : 0;
        }
        for (int j = 0; j < count; ++j) {
            int i = present[j];
#if !defined(GLINT_GLSL)
            if (((in_batch >> uint(i)) & 1u) != 0u) continue;  // drawn above
#endif
            // The vertex's words read in place: a helper taking the vertices by value (GLSL's `in`)
            // copied the arrays per call on llvmpipe, which keeps an indexed array in memory (glint_gl's
            // IBL frames about 10% slower).
            uvec3 hash = uvec3(px.v.hash_x[i], px.v.hash_y[i], px.v.hash_z[i]);
            // The multinomial's root draws the lit levels against the rest with these uniforms: if
            // it surely draws none, every count is 0 (glint_surely_no_success).
#if defined(GLINT_GLSL)
            uvec3 root_words = glint_multinomial_node_words(hash, 0);
#else
            uvec3 root_words = uvec3(root_x[i], root_y[i], root_z[i]);  // hashed with the batch
#endif
            if (skip_test && glint_surely_no_success_scaled(px.skip_scale[i], min(lit_total, real(1)), glint_open_unit_from_bits(root_words.x))) continue;
            glint_multinomial_counts c = glint_multinomial_draw(N * px.v.share[i], tree, hash, root_words, g.variant, g.pow_method, root_cache);
            for (int k = 0; k < 7; ++k) weighted[k] += px.v.weight[i] * c.count[k];
            o.draws += K - 1;
        }
    }
    for (int k = 0; k < 7; ++k) o.share[k + 1] = weighted[k] / N;
    return o;
}

// The levels above the black one as multinomial bins 0..K-2.
GLINT_FN glint_multinomial_probabilities glint_ibl_lit_levels(GLINT_IN(glint_multinomial_probabilities) all, int K) {
    glint_multinomial_probabilities lit;
    for (int k = 0; k < 7; ++k) lit.p[k] = (k + 1 < K) ? all.p[k + 1] : real(0);
    lit.p[7] = real(0);
    return lit;
}

// The glint estimate for one footprint under the environment (KK25 Eq. 17), in grid.glsl's
// estimate struct: value = sum_k L_k M_k / N, expected = sum_k L_k p_k, and glint_modulation
// gives the factor on the smooth result. Same grid as glint_grid_sample, without the half-vector interpolation
// (KK25 Sec. 3.3: IBL has no single half vector). On a glint_grid_pixel, so that point lights and
// the environment share one footprint's vertices.
GLINT_FN glint_grid_estimate glint_ibl_sample_pixel(GLINT_INOUT(glint_grid_pixel) px, GLINT_IN(glint_grid_params) g, GLINT_IN(glint_ibl_levels) lv,
                                                   GLINT_IN(glint_ibl_indicators) ind, real e_d, real d_h) {
    glint_grid_estimate o;
    o.value = real(0);
    o.expected = real(0);
    o.draws = 0;
    int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    glint_multinomial_probabilities all = glint_ibl_probabilities(lv, ind, e_d, d_h);
    real second = real(0);  // sum_k L_k^2 p_k, for the variance bound
    for (int k = 1; k < 8; ++k) {
        real L = (k < K) ? lv.radiance[k] : real(0);
        o.expected += L * all.p[k];
        second += L * L * all.p[k];
    }
    if (!(o.expected > real(0))) return o;  // nothing bright can be reflected: no sampling
    real N = px.N;
    // Var(sum_k L_k M_k / N) <= sum_k L_k^2 p_k / N (each multinomial count's variance is at most
    // its mean; the covariances are negative), plus the log-normal density's share.
    real var_bound = second / max(N, real(1e-30)) + glint_density_variance_factor(g) * o.expected * o.expected;
    if (var_bound <= g.smooth_tolerance * g.smooth_tolerance * o.expected * o.expected) {
        o.value = o.expected;
        return o;
    }
    glint_ibl_shares sh = glint_ibl_level_shares(px, g, K, glint_ibl_lit_levels(all, K));
    for (int k = 1; k < 8; ++k) o.value += (k < K) ? lv.radiance[k] * sh.share[k] : real(0);
    o.draws = sh.draws;
    return o;
}

// glint_ibl_sample_pixel on its own footprint.
GLINT_FN glint_grid_estimate glint_ibl_sample(vec2 uv, vec2 duvdx, vec2 duvdy, glint_grid_params g, glint_ibl_levels lv,
                                             glint_ibl_indicators ind, real e_d, real d_h) {
    glint_grid_pixel px = glint_grid_pixel_setup(uv, duvdx, duvdy, g);
    return glint_ibl_sample_pixel(px, g, lv, ind, e_d, d_h);
}

// ---------------------------------------------------------------------------------------------
// Texture filtering as OpenGL does it (GL_LINEAR): texel centres at (i + 1/2) / size; u repeats
// (GL_REPEAT, the equirectangular seam), v clamps to the edge (GL_CLAMP_TO_EDGE, the poles).
struct glint_bilinear_taps {
    ivec2 texel[4];  // (x, y) of the taps: (x0, y0), (x1, y0), (x0, y1), (x1, y1)
    vec4 weight;
};

GLINT_FN glint_bilinear_taps glint_bilinear(vec2 uv, int width, int height) {
    real x = uv.x * real(width) - real(0.5);
    real y = uv.y * real(height) - real(0.5);
    real fx0 = floor(x), fy0 = floor(y);
    real ax = x - fx0, ay = y - fy0;
    int x0 = int(fx0), y0 = int(fy0);
    // Repeat in x (also for |u| large: fold into [0, width)); clamp in y. The fold's division only
    // where x0 is outside (u outside [0, 1), or the first half texel).
    if (x0 < 0 || x0 >= width) x0 = x0 - width * int(floor(real(x0) / real(width)));
    int x1 = (x0 + 1 == width) ? 0 : x0 + 1;
    int ya = clamp(y0, 0, height - 1), yb = clamp(y0 + 1, 0, height - 1);
    glint_bilinear_taps t;
    t.texel[0] = ivec2(x0, ya);
    t.texel[1] = ivec2(x1, ya);
    t.texel[2] = ivec2(x0, yb);
    t.texel[3] = ivec2(x1, yb);
    t.weight = vec4((real(1) - ax) * (real(1) - ay), ax * (real(1) - ay), (real(1) - ax) * ay, ax * ay);
    return t;
}

// The equirectangular coordinates of a direction (y up; u = 1/2 looks along -z; v = 0 at the
// zenith), and back. The forward map uses glint_atan2 and glint_acos (core.glsl), not the
// builtins, whose GLSL precision is undefined.
GLINT_FN vec2 glint_equirect_uv(vec3 d) {
    return vec2(glint_atan2(d.x, -d.z) * GLINT_INV_TWO_PI + real(0.5), glint_acos(d.y) / GLINT_PI);
}

GLINT_FN vec3 glint_equirect_direction(vec2 uv) {
    real phi = (uv.x - real(0.5)) * real(2) * GLINT_PI;
    real theta = uv.y * GLINT_PI;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}
