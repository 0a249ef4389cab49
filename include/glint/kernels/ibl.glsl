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

#if !defined(GLINT_GLSL)
// C++ only: the pass's weighted counts of a pixel's vertices, drawn by glint_ibl_sample_pixels'
// lanes, for glint_ibl_level_shares to go on from.
struct glint_ibl_predrawn {
    real weighted[8];
};
#endif

// (C++: where `pre` is given, the vertices that the bit-sliced pass takes were drawn already, and
// their weighted counts are pre->weighted.)
GLINT_FN glint_ibl_shares glint_ibl_level_shares(GLINT_INOUT(glint_grid_pixel) px, GLINT_IN(glint_grid_params) g, int K,
                                                 GLINT_IN(glint_multinomial_probabilities) lit
#if !defined(GLINT_GLSL)
                                                 , const glint_ibl_predrawn* pre = nullptr
#endif
) {
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
    if (pre) {
        for (int k = 0; k < 8; ++k) weighted[k] = pre->weighted[k];
    } else {
        glint_multinomial_exact_all_weighted(tree, in_batch, batch_N, root_x, root_y, root_z, px.v.weight, weighted);
    }
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

// The first part of glint_ibl_sample_pixel: the level probabilities `all`, o.expected = sum_k
// L_k p_k, and whether the estimate needs draws; where it does not, o is the estimate (nothing
// bright can be reflected: 0; or R's bound on the relative sd is below the tolerance: E[R]).
GLINT_FN bool glint_ibl_needs_draws(GLINT_IN(glint_grid_params) g, GLINT_IN(glint_ibl_levels) lv, GLINT_IN(glint_ibl_indicators) ind, real e_d, real d_h,
                                    real N, GLINT_OUT(glint_multinomial_probabilities) all, GLINT_OUT(glint_grid_estimate) o) {
    o.value = real(0);
    o.expected = real(0);
    o.draws = 0;
    int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    all = glint_ibl_probabilities(lv, ind, e_d, d_h);
    real second = real(0);  // sum_k L_k^2 p_k, for the variance bound
    for (int k = 1; k < 8; ++k) {
        real L = (k < K) ? lv.radiance[k] : real(0);
        o.expected += L * all.p[k];
        second += L * L * all.p[k];
    }
    if (!(o.expected > real(0))) return false;  // nothing bright can be reflected: no sampling
    // Var(sum_k L_k M_k / N) <= sum_k L_k^2 p_k / N (each multinomial count's variance is at most
    // its mean; the covariances are negative), plus the log-normal density's share.
    real var_bound = second / max(N, real(1e-30)) + glint_density_variance_factor(g) * o.expected * o.expected;
    if (var_bound <= g.smooth_tolerance * g.smooth_tolerance * o.expected * o.expected) {
        o.value = o.expected;
        return false;
    }
    return true;
}

// sum_k L_k share_k over the lit levels (KK25 Eq. 17's numerator over N).
GLINT_FN real glint_ibl_value(GLINT_IN(glint_ibl_levels) lv, GLINT_IN(glint_ibl_shares) sh) {
    int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    real value = real(0);
    for (int k = 1; k < 8; ++k) value += (k < K) ? lv.radiance[k] * sh.share[k] : real(0);
    return value;
}

// The glint estimate for one footprint under the environment (KK25 Eq. 17), in grid.glsl's
// estimate struct: value = sum_k L_k M_k / N, expected = sum_k L_k p_k, and glint_modulation
// gives the factor on the smooth result. Same grid as glint_grid_sample, without the half-vector interpolation
// (KK25 Sec. 3.3: IBL has no single half vector). On a glint_grid_pixel, so that point lights and
// the environment share one footprint's vertices.
GLINT_FN glint_grid_estimate glint_ibl_sample_pixel(GLINT_INOUT(glint_grid_pixel) px, GLINT_IN(glint_grid_params) g, GLINT_IN(glint_ibl_levels) lv,
                                                   GLINT_IN(glint_ibl_indicators) ind, real e_d, real d_h) {
    glint_grid_estimate o;
    glint_multinomial_probabilities all;
    if (!glint_ibl_needs_draws(g, lv, ind, e_d, d_h, px.N, all, o)) return o;
    int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    glint_ibl_shares sh = glint_ibl_level_shares(px, g, K, glint_ibl_lit_levels(all, K));
    o.value = glint_ibl_value(lv, sh);
    o.draws = sh.draws;
    return o;
}

// glint_ibl_sample_pixel on its own footprint.
GLINT_FN glint_grid_estimate glint_ibl_sample(vec2 uv, vec2 duvdx, vec2 duvdy, glint_grid_params g, glint_ibl_levels lv,
                                             glint_ibl_indicators ind, real e_d, real d_h) {
    glint_grid_pixel px = glint_grid_pixel_setup(uv, duvdx, duvdy, g);
    return glint_ibl_sample_pixel(px, g, lv, ind, e_d, d_h);
}

#if !defined(GLINT_GLSL)
// C++ only: glint_ibl_sample_pixel for several pixels, eight at a time in AVX2 lanes (lane v holds
// pixel v; GPUs run a fragment a thread, so GLSL keeps the single pixel). A pixel's draw is one
// bit-sliced pass over its vertices' lane groups (glint_multinomial_exact_all_weighted), six of
// eight groups at the report's density, and the bookkeeping around it is scalar; here slot s's
// vertices of eight pixels form a lane group of the pass, each lane with its pixel's thresholds,
// two slots' groups a pass (glint_multinomial_exact_lanes_pass), and the vertices' lanes, weights
// and root words are set up eight pixels a vector. The counts are the single pixel's, vertex by vertex (the same words,
// thresholds and trials); only their weighted sums are added in another order, so each estimate
// equals glint_ibl_sample_pixel's to float rounding and its draws exactly
// (tests/stat/test_ibl.cpp). The vertices that the pass does not take (N outside 4 to 63 or N total
// below 1, a published variant) are drawn after it by glint_ibl_level_shares' loop, as for one pixel.
struct glint_ibl_lanes {
    uint c[8][8];          // [k][lane]: the pixel's thresholds (glint_multinomial_exact_all_thresholds)
    uint full[8][8];       // all ones where c_k is full
    uint lead_c[8][8];     // the same with each follower set to its last leader
    uint lead_full[8][8];
    uint has_follower[8];  // all ones in the lanes with a follower
    real lit[8][8];        // [k][lane]: the lit levels' probabilities (glint_ibl_lit_levels)
    real N[8];
    real total[8];         // the tree root's total
    glint_lanes_vertices v;  // the pixels' vertices (glint_lanes_footprint_vertices, grid.glsl)
    real weighted[8][8];   // out, [k][lane]: sum over the vertices of l_t M_k
    int batched[8];        // out: the vertices drawn
    int rest;              // out: bit v set where lane v's pixel has vertices that the pass does not take
};

// Eight pixels' arrays of eight, row[v] pixel v's, as eight vectors: out[s][v] = row[v][s] (an 8 x 8
// transpose in shuffles).
template <class V, class E>
__attribute__((always_inline)) static inline void glint_lanes_transpose8(const E* const row[8], V out[8]) {
    V r[8];
    for (int v = 0; v < 8; ++v) std::memcpy(&r[v], row[v], sizeof(V));
    V t[8], u[8];
    for (int h = 0; h < 4; ++h) {
        t[2 * h] = __builtin_shufflevector(r[2 * h], r[2 * h + 1], 0, 8, 1, 9, 4, 12, 5, 13);
        t[2 * h + 1] = __builtin_shufflevector(r[2 * h], r[2 * h + 1], 2, 10, 3, 11, 6, 14, 7, 15);
    }
    for (int h = 0; h < 2; ++h)
        for (int e = 0; e < 2; ++e) {
            u[4 * h + 2 * e] = __builtin_shufflevector(t[4 * h + e], t[4 * h + 2 + e], 0, 1, 8, 9, 4, 5, 12, 13);
            u[4 * h + 2 * e + 1] = __builtin_shufflevector(t[4 * h + e], t[4 * h + 2 + e], 2, 3, 10, 11, 6, 7, 14, 15);
        }
    for (int j = 0; j < 4; ++j) {
        out[j] = __builtin_shufflevector(u[j], u[4 + j], 0, 1, 2, 3, 8, 9, 10, 11);
        out[4 + j] = __builtin_shufflevector(u[j], u[4 + j], 4, 5, 6, 7, 12, 13, 14, 15);
    }
}

// The jobs of a draw, slot-wise lane groups of the eight lanes, drawn two at a time
// (glint_multinomial_exact_lanes_pass with J = 2): [j][lane] the pending jobs'.
struct glint_ibl_lanes_jobs {
    uint lanes[2][8], frac[2][8], state[2][8], step[2][8];
    real weight[2][8], frac_weight[2][8];
    bool followers;
    int pending;
};

// The pending jobs' pass: the leaders' pass where a lane has followers, then every threshold where
// it gave up (glint_multinomial_exact_all_groups' order).
template <int T, int J>
__attribute__((always_inline)) static inline void glint_ibl_lanes_pass(GLINT_INOUT(glint_ibl_lanes) d, glint_ibl_lanes_jobs& p) {
    if (p.followers && glint_multinomial_exact_lanes_pass<T, J>(d.lead_c, d.lead_full, d.has_follower, GLINT_MULTINOMIAL_FOLLOWER_DIGITS, p.lanes, p.frac,
                                                                p.state, p.step, p.weight, p.frac_weight, d.weighted))
        return;
    glint_multinomial_exact_lanes_pass<T, J>(d.c, d.full, d.has_follower, 32, p.lanes, p.frac, p.state, p.step, p.weight, p.frac_weight,
                                             d.weighted);  // 32: never stops
}

// A job, drawn with the one pending before it, or left pending.
template <int T>
__attribute__((always_inline)) static inline void glint_ibl_lanes_job(GLINT_INOUT(glint_ibl_lanes) d, glint_ibl_lanes_jobs& p, bool followers,
                                                                   const glint_u32x8& lanes, const glint_u32x8& frac, const glint_u32x8& state,
                                                                   const glint_u32x8& step, const glint_realx8& weight, const glint_realx8& frac_weight) {
    const int j = p.pending;
    std::memcpy(p.lanes[j], &lanes, sizeof(lanes)), std::memcpy(p.frac[j], &frac, sizeof(frac));
    std::memcpy(p.state[j], &state, sizeof(state)), std::memcpy(p.step[j], &step, sizeof(step));
    std::memcpy(p.weight[j], &weight, sizeof(weight)), std::memcpy(p.frac_weight[j], &frac_weight, sizeof(frac_weight));
    p.followers = (j != 0 && p.followers) || followers;
    if (j == 0) {
        p.pending = 1;
        return;
    }
    glint_ibl_lanes_pass<T, 2>(d, p);
    p.pending = 0;
}

template <int T>
__attribute__((always_inline)) static inline void glint_ibl_lanes_draw_of(GLINT_INOUT(glint_ibl_lanes) d, bool unbiased) {
    typedef glint_u32x8 u32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_realx8 realx8;
    typedef decltype(realx8{} < realx8{}) maskx8;
    realx8 N, total;
    i32x8 count;
    std::memcpy(&N, d.N, sizeof(N)), std::memcpy(&total, d.total, sizeof(total)), std::memcpy(&count, d.v.count, sizeof(count));
    // The slots in the pass, as glint_ibl_level_shares tests them (present, and
    // glint_multinomial_exact_all_applies), and each lane's counts of both.
    const i32x8 all_ones = i32x8{} - 1;
    const i32x8 variant = unbiased ? all_ones : i32x8{};
    i32x8 batch[12], present_count = {}, batch_count = {};
    realx8 n[12];
    for (int s = 0; s < 12; ++s) {
        if (((d.v.slots >> s) & 1) == 0) {  // a slot no lane's vertex holds
            batch[s] = i32x8{};
            continue;
        }
        realx8 share, weight;  // the vertices read in place, slot by slot
        std::memcpy(&share, d.v.share[s], sizeof(share)), std::memcpy(&weight, d.v.weight[s], sizeof(weight));
        const i32x8 present = (count > s) & __builtin_convertvector(weight > real(0), i32x8);
        n[s] = N * share;
        batch[s] = present & variant &
                   __builtin_convertvector((n[s] >= GLINT_MULTINOMIAL_EXACT_SPLIT_MIN) & (n[s] <= GLINT_MULTINOMIAL_EXACT_ALL_MAX) & (n[s] * total >= real(1)),
                                           i32x8);
        present_count -= present;
        batch_count -= batch[s];
    }
    const i32x8 rest = (batch_count != present_count);  // vertices left to glint_ibl_level_shares' loop
    d.rest = 0;
    for (int v = 0; v < 8; ++v) d.rest |= (rest[v] != 0) ? (1 << v) : 0;
    std::memcpy(d.batched, &batch_count, sizeof(batch_count));
    u32x8 has_follower;
    std::memcpy(&has_follower, d.has_follower, sizeof(has_follower));
    glint_ibl_lanes_jobs jobs;
    jobs.pending = 0, jobs.followers = false;
    for (int s = 0; s < 12; ++s) {
        const i32x8 in_pass = batch[s];
        if (glint_lanes_all_zero(reinterpret_cast<u32x8>(in_pass))) continue;
        // The root words, PCG3D of the vertex's (glint_multinomial_node_words(hash, 0)).
        u32x8 x, y, z;
        std::memcpy(&x, d.v.hash_x[s], sizeof(x)), std::memcpy(&y, d.v.hash_y[s], sizeof(y)), std::memcpy(&z, d.v.hash_z[s], sizeof(z));
        glint_pcg3d_vectors(x, y, z);
        // glint_multinomial_exact_all_lanes and _frac_lanes lane-wise.
        const realx8 capped = (GLINT_MULTINOMIAL_EXACT_ALL_MAX < n[s]) ? realx8{} + GLINT_MULTINOMIAL_EXACT_ALL_MAX : n[s];
        const i32x8 whole = in_pass & __builtin_convertvector(capped, i32x8);  // 0 outside the pass
        const i32x8 two = whole >= 32;
        const u32x8 pass = reinterpret_cast<u32x8>(in_pass);
        const u32x8 shift_a = reinterpret_cast<u32x8>(two ? i32x8{} : whole), shift_b = reinterpret_cast<u32x8>(two ? whole - 32 : i32x8{});
        const u32x8 lanes_a = (reinterpret_cast<u32x8>(two) | (((u32x8{} + 2u) << shift_a) - 1u)) & pass;
        const u32x8 lanes_b = ((((u32x8{} + 2u) << shift_b) - 1u) & reinterpret_cast<u32x8>(two)) & pass;
        const u32x8 frac_a = (lanes_b == 0u) ? lanes_a ^ (lanes_a >> 1u) : u32x8{};
        const u32x8 frac_b = lanes_b ^ (lanes_b >> 1u);
        const maskx8 in = reinterpret_cast<maskx8>(in_pass);  // lanes outside the pass add nothing (no NaN from their N)
        realx8 weight;
        std::memcpy(&weight, d.v.weight[s], sizeof(weight));
        const realx8 weight_in = in ? weight : realx8{};
        const realx8 frac_share = in ? weight_in * (n[s] - __builtin_convertvector(whole, realx8)) : realx8{};
        const realx8 frac_weight_a = (reinterpret_cast<maskx8>(two)) ? realx8{} : frac_share;
        const u32x8 step = y | 1u;
        const bool followers = !glint_lanes_all_zero(has_follower & pass);
        glint_ibl_lanes_job<T>(d, jobs, followers, lanes_a, frac_a, x, step, weight_in, frac_weight_a);
        if (glint_lanes_all_zero(lanes_b)) continue;
        glint_ibl_lanes_job<T>(d, jobs, followers, lanes_b, frac_b, z, step, weight_in, frac_share);
    }
    if (jobs.pending != 0) glint_ibl_lanes_pass<T, 1>(d, jobs);  // the last job alone
}

GLINT_LANES_BODY
void glint_ibl_lanes_draw_body(GLINT_INOUT(glint_ibl_lanes) d, int T, bool unbiased) {
    switch (T) {
        case 2: glint_ibl_lanes_draw_of<2>(d, unbiased); break;
        case 3: glint_ibl_lanes_draw_of<3>(d, unbiased); break;
        case 4: glint_ibl_lanes_draw_of<4>(d, unbiased); break;
        case 5: glint_ibl_lanes_draw_of<5>(d, unbiased); break;
        case 6: glint_ibl_lanes_draw_of<6>(d, unbiased); break;
        default: glint_ibl_lanes_draw_of<7>(d, unbiased); break;
    }
}
GLINT_LANES_VARIANTS(void, glint_ibl_lanes_draw,
                     (GLINT_INOUT(glint_ibl_lanes) d, int T, bool unbiased),
                     (d, T, unbiased))

// The first part of glint_ibl_sample_pixel for lanes 0 .. n - 1 (the others repeat lane n - 1 and
// do not draw): glint_ibl_needs_draws into out[v], and where it draws, glint_ibl_lit_levels,
// glint_multinomial_tree_root, _exact_all_thresholds and the followers of
// glint_multinomial_exact_all_groups into d, lane-wise with the same operations in the same order
// (the same values bit for bit). Returns the lanes that draw (bit v).
GLINT_LANES_BODY
int glint_ibl_lanes_setup_body(GLINT_INOUT(glint_ibl_lanes) d, int n, const glint_grid_pixel* px, GLINT_IN(glint_grid_params) g, GLINT_IN(glint_ibl_levels) lv,
                               const glint_ibl_indicators* ind, const real* e_d, real d_h, glint_grid_estimate* out) {
    typedef glint_u32x8 u32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_realx8 realx8;
    typedef decltype(realx8{} < realx8{}) maskx8;
    const realx8 zero = {}, one = zero + real(1);
    realx8 e = zero, N = zero;
    const real* rows[8];
    for (int v = 0; v < 8; ++v) {
        const int i = std::min(v, n - 1);
        e[v] = e_d[i], N[v] = px[i].N, rows[v] = ind[i].w;
    }
    realx8 w[8];
    glint_lanes_transpose8(rows, w);
    const int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    // glint_ibl_probabilities
    const real area = max(d_h, real(1));
    // (The levels from K on add zeros, which change no sum: they are left out.)
    realx8 p[8], total = zero;
    for (int k = 0; k < 8; ++k) p[k] = zero;
    for (int k = 0; k < K; ++k) {
        realx8 x = e * w[k] / area;
        x = (x < zero) ? zero : x;
        x = (one < x) ? one : x;
        p[k] = x;
        total += p[k];
    }
    const realx8 scale = (total > one) ? one / total : one;
    for (int k = 0; k < K; ++k) p[k] *= scale;
    // glint_ibl_needs_draws
    realx8 expected = zero, second = zero;
    for (int k = 1; k < K; ++k) {
        const real L = lv.radiance[k];
        expected += L * p[k];
        second += L * L * p[k];
    }
    const realx8 var_bound = second / ((N < real(1e-30)) ? zero + real(1e-30) : N) + glint_density_variance_factor(g) * expected * expected;
    const maskx8 bright = expected > real(0);
    const maskx8 smooth = bright & (var_bound <= g.smooth_tolerance * g.smooth_tolerance * expected * expected);
    const realx8 value = smooth ? expected : zero;
    const maskx8 draws = bright & ~smooth & (N > real(1e-30));  // no microfacets: glint_ibl_level_shares' shares and the value are 0
    int drawing = 0;
    for (int v = 0; v < n; ++v) {
        out[v].value = value[v], out[v].expected = expected[v], out[v].draws = 0;
        drawing |= (draws[v] != 0) ? 1 << v : 0;
    }
    // glint_ibl_lit_levels, then glint_multinomial_tree_root
    const int T = clamp(K - 1, 2, 8);
    realx8 t[8], t_total = zero;
    for (int k = 0; k < 8; ++k) {
        const realx8 lit = (k < 7 && k + 1 < K) ? p[k + 1] : zero;
        std::memcpy(d.lit[k], &lit, sizeof(lit));
        const realx8 x = (lit < zero) ? zero : lit;
        t[k] = (k < T) ? x : zero;
        t_total += t[k];
    }
    const realx8 t_scale = (t_total > one) ? one / t_total : one;
    realx8 root_total = t_total * t_scale;
    root_total = (one < root_total) ? one : root_total;
    std::memcpy(d.total, &root_total, sizeof(root_total));
    // glint_multinomial_exact_all_thresholds, and the followers
    u32x8 sum = {}, reached = {}, has_follower = {}, c_before = {}, full_before = {}, lead_c = {}, lead_full = {};
    const realx8 two32 = zero + real(4294967296.0), two31 = zero + real(2147483648.0);
    for (int k = 0; k < 8; ++k) {
        if (k >= T) {  // scaled 0 from here on: the sums stay, no follower
            std::memcpy(d.c[k], &sum, sizeof(sum)), std::memcpy(d.full[k], &reached, sizeof(reached));
            std::memcpy(d.lead_c[k], &sum, sizeof(sum)), std::memcpy(d.lead_full[k], &reached, sizeof(reached));
            continue;
        }
        const realx8 scaled = t[k] * t_scale * real(4294967296.0);  // p_k 2^32, exact in float
        const u32x8 whole_word = reinterpret_cast<u32x8>(__builtin_convertvector(scaled >= two32, i32x8));
        const u32x8 no_add = whole_word | reinterpret_cast<u32x8>(__builtin_convertvector(!(scaled >= zero), i32x8));
        // uint(scaled) for scaled in [0, 2^32): from 2^31 on, as an int after subtracting 2^31 (exact)
        const maskx8 high = scaled >= two31;
        const u32x8 as_uint = reinterpret_cast<u32x8>(__builtin_convertvector(high ? scaled - two31 : scaled, i32x8)) +
                              (reinterpret_cast<u32x8>(__builtin_convertvector(high, i32x8)) & 0x80000000u);
        const u32x8 next = sum + (no_add ? u32x8{} : as_uint);
        reached |= whole_word | (next < sum);
        sum = next;
        const u32x8 follower = (k > 0) ? ((((c_before ^ sum) >> uint(32 - GLINT_MULTINOMIAL_FOLLOWER_DIGITS)) == 0u) & ~(reached | full_before)) : u32x8{};
        lead_c = follower ? lead_c : sum;
        lead_full = follower ? lead_full : reached;
        has_follower |= follower;
        std::memcpy(d.c[k], &sum, sizeof(sum)), std::memcpy(d.full[k], &reached, sizeof(reached));
        std::memcpy(d.lead_c[k], &lead_c, sizeof(lead_c)), std::memcpy(d.lead_full[k], &lead_full, sizeof(lead_full));
        c_before = sum, full_before = reached;
    }
    std::memcpy(d.has_follower, &has_follower, sizeof(has_follower));
    std::memcpy(d.N, &N, sizeof(N));
    return drawing;
}
GLINT_LANES_VARIANTS(int, glint_ibl_lanes_setup,
                     (GLINT_INOUT(glint_ibl_lanes) d, int n, const glint_grid_pixel* px, GLINT_IN(glint_grid_params) g,
                      GLINT_IN(glint_ibl_levels) lv, const glint_ibl_indicators* ind, const real* e_d, real d_h, glint_grid_estimate* out),
                     (d, n, px, g, lv, ind, e_d, d_h, out))

// out[i] = glint_ibl_sample_pixel(px[i], g, lv, ind[i], e_d[i], d_h) for i < count, to float
// rounding of the value (the draws and the expectation exactly): eight pixels at a time where the
// CPU has AVX2 (float), one at a time otherwise.
GLINT_FN void glint_ibl_sample_pixels(int count, glint_grid_pixel* px, GLINT_IN(glint_grid_params) g, GLINT_IN(glint_ibl_levels) lv,
                                      const glint_ibl_indicators* ind, const real* e_d, real d_h, glint_grid_estimate* out) {
    if constexpr (!std::is_same<real, float>::value) {
        for (int i = 0; i < count; ++i) out[i] = glint_ibl_sample_pixel(px[i], g, lv, ind[i], e_d[i], d_h);
    } else {
    const int K = clamp(lv.count, 3, GLINT_IBL_MAX_LEVELS);
    for (int first = 0; first < count; first += 8) {
        const int n = std::min(count - first, 8);
        // The lanes draw where the CPU has AVX2 and the density has no log-normal factor; else
        // each pixel draws alone.
        if (!glint_cpu_avx2() || g.density_sigma > real(0)) {
            for (int i = first; i < first + n; ++i) out[i] = glint_ibl_sample_pixel(px[i], g, lv, ind[i], e_d[i], d_h);
            continue;
        }
        // Not zeroed whole (a fifth of the set-up's instructions): the sums here, the rest where the
        // lanes fill them.
        glint_ibl_lanes d;
        std::memset(d.weighted, 0, sizeof(d.weighted));
        const int drawing = glint_ibl_lanes_setup(d, n, px + first, g, lv, ind + first, e_d + first, d_h, out + first);
        glint_lanes_footprint_vertices(d.v, n, px + first, g.lod_scale, drawing, g.seed);
        if (drawing == 0) continue;
        glint_ibl_lanes_draw(d, K - 1, g.variant == GLINT_BINOMIAL_UNBIASED);
        // glint_ibl_value of the shares weighted[k] / N, lane-wise (the same operations in the
        // same order: the same values).
        glint_realx8 N, value = {};
        std::memcpy(&N, d.N, sizeof(N));
        for (int k = 1; k < 8; ++k) {
            glint_realx8 weighted;
            std::memcpy(&weighted, d.weighted[k - 1], sizeof(weighted));
            value += (k < K) ? lv.radiance[k] * (weighted / N) : glint_realx8{};
        }
        for (int v = 0; v < n; ++v) {
            if (((drawing >> v) & 1) == 0) continue;
            glint_grid_estimate& o = out[first + v];
            if (((d.rest >> v) & 1) != 0) {  // the loop draws the other vertices, after the pass's
                glint_grid_pixel_vertices(px[first + v], g);  // where the lanes computed them, the same vertices
                glint_ibl_predrawn pre;
                glint_multinomial_probabilities lit;
                for (int k = 0; k < 8; ++k) pre.weighted[k] = d.weighted[k][v], lit.p[k] = d.lit[k][v];
                glint_ibl_shares sh = glint_ibl_level_shares(px[first + v], g, K, lit, &pre);
                o.value = glint_ibl_value(lv, sh);
                o.draws = sh.draws;
            } else {
                o.value = value[v];
                o.draws = d.batched[v] * (K - 1);
            }
        }
    }
    }
}
#endif

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
