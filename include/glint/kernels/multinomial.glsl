// glint multinomial kernel: N trials over K = 2..8 bins with probabilities p[0..K-1] (their sum
// at most 1; the remainder is an implicit rest bin, KK25 Eq. 17's dummy light for masking and
// directions below the horizon), sampled as a binary hierarchy of binomials (KK25 Sec. 6).
// Single source for C++ and GLSL 4.50; needs core.glsl and binomial.glsl (which has the variant
// codes GLINT_BINOMIAL_* and glint_binomial_variant).
//
// The root splits the K bins from the rest, each inner node splits its bins into halves; K - 1
// binomials for the bins and one for the rest, so K = 8 costs 8 binomials against 4 for K = 4.
// The root uses the chosen variant as it is (for N < 2 the dual-gated variants dither, KK25
// Fig. 4). Below the root a node's count is split conservatively, so that the counts always sum
// to the root's positive count: a node holding N_node >= 2 gives its left half the variant's
// positive count and its right half the remainder; a node holding less than 2 (a real count
// such as 1.37, or 0 or 1) sends all of it left with probability q and right otherwise, which is
// exact for N_node = 0 and 1 and keeps the mean N_node q for any real N_node.

struct glint_multinomial_probabilities {
    real p[8];
};

struct glint_multinomial_counts {
    real count[8];
    real rest;  // trials that fell in none of the K bins
};

// The uniform pair for tree node `node` (0 = root) from the seed: one PCG3D hash.
GLINT_FN vec2 glint_multinomial_uniforms(uvec3 seed, int node) {
    uvec3 h = glint_pcg3d(uvec3(seed.x, seed.y, seed.z + uint(node) * 0x9e3779b9u));
    return vec2(glint_open_unit_from_bits(h.x), glint_open_unit_from_bits(h.y));
}

// The hierarchy for K bins (K clamped to 2..8; probabilities clamped to >= 0 and scaled down if
// they sum to more than 1): the root's total and, per inner node in the breadth-first order the
// draw visits them, the probability q that a trial of the node goes to its left half. They depend
// on the probabilities only: a caller that draws many multinomials with one set (the IBL's grid
// vertices of a pixel) makes them once (glint_multinomial_make_tree); a single draw makes the q
// only where the root keeps a trial (sparse glints: most draws keep none).
struct glint_multinomial_tree {
    int K;
    real total;  // the K bins' probability, at most 1
    real p[8];   // the bins' probabilities as clamped and scaled
    real q[7];   // per inner node; node 0 holds all K bins
};

// K, the probabilities and their total; the q are left to glint_multinomial_tree_splits.
GLINT_FN glint_multinomial_tree glint_multinomial_tree_root(glint_multinomial_probabilities probs, int K) {
    glint_multinomial_tree t;
    t.K = clamp(K, 2, 8);
    real total = real(0);
    for (int k = 0; k < 8; ++k) {
        t.p[k] = (k < t.K) ? max(probs.p[k], real(0)) : real(0);
        total += t.p[k];
    }
    real scale = (total > real(1)) ? real(1) / total : real(1);
    for (int k = 0; k < 8; ++k) t.p[k] *= scale;
    t.total = min(total * scale, real(1));
    for (int h = 0; h < 7; ++h) t.q[h] = real(0.5);
    return t;
}

// The nodes [lo, hi) in the order glint_multinomial_split_nodes visits them: node 0 is [0, K), and
// a node's inner children are appended to the queue, left before right.
GLINT_FN void glint_multinomial_tree_splits(GLINT_INOUT(glint_multinomial_tree) t) {
    int queue_lo[8];
    int queue_hi[8];
    queue_lo[0] = 0;
    queue_hi[0] = t.K;
    int tail = 1;
    for (int head = 0; head < 7; ++head) {
        if (head >= tail) break;
        int lo = queue_lo[head];
        int hi = queue_hi[head];
        int mid = lo + (hi - lo) / 2;
        real left = real(0);
        real right = real(0);
        for (int k = lo; k < mid; ++k) left += t.p[k];  // the same sums as over all 8 bins with zeros
        for (int k = mid; k < hi; ++k) right += t.p[k];
        t.q[head] = (left + right > real(0)) ? clamp(left / (left + right), real(0), real(1)) : real(0.5);
        if (mid - lo > 1) {
            queue_lo[tail] = lo;
            queue_hi[tail] = mid;
            ++tail;
        }
        if (hi - mid > 1) {
            queue_lo[tail] = mid;
            queue_hi[tail] = hi;
            ++tail;
        }
    }
}

GLINT_FN glint_multinomial_tree glint_multinomial_make_tree(glint_multinomial_probabilities probs, int K) {
    glint_multinomial_tree t = glint_multinomial_tree_root(probs, K);
    glint_multinomial_tree_splits(t);
    return t;
}

// The root's `positive` trials split down the tree into result.count (breadth-first over the inner
// nodes [lo, hi), at most K - 1 = 7 of them: a node's inner children are appended to the queue, its
// leaves written out; GLSL has no recursion).
GLINT_FN void glint_multinomial_split_nodes(real positive, glint_multinomial_tree t, uvec3 seed, int variant, int method,
                                            GLINT_INOUT(glint_multinomial_counts) result) {
    int queue_lo[8];
    int queue_hi[8];
    real queue_n[8];
    queue_lo[0] = 0;
    queue_hi[0] = t.K;
    queue_n[0] = positive;
    int tail = 1;
    for (int head = 0; head < 7; ++head) {
        if (head >= tail) break;
        int lo = queue_lo[head];
        int hi = queue_hi[head];
        real n = queue_n[head];
        int mid = lo + (hi - lo) / 2;
        real q = t.q[head];
        real n_left = real(0);
        if (n > real(0)) {  // an empty node splits into empty halves: no hash, no draw
            vec2 v = glint_multinomial_uniforms(seed, head + 1);
            n_left = (v.x < q) ? n : real(0);  // below 2: all of it to one side
            if (n >= real(2)) {
                glint_binomial split = glint_binomial_variant(variant, n, q, v.x, v.y, method);
                n_left = clamp(split.positive, real(0), n);
            }
        }
        real n_right = n - n_left;
        if (mid - lo == 1) {
            result.count[lo] = n_left;
        } else {
            queue_lo[tail] = lo;
            queue_hi[tail] = mid;
            queue_n[tail] = n_left;
            ++tail;
        }
        if (hi - mid == 1) {
            result.count[mid] = n_right;
        } else {
            queue_lo[tail] = mid;
            queue_hi[tail] = hi;
            queue_n[tail] = n_right;
            ++tail;
        }
    }
}

// The root of a draw: N trials drawn between the K bins (probability `total`) and the rest.
// Zeroes the counts, sets result.rest, and returns the bins' trials for glint_multinomial_split_nodes.
GLINT_FN real glint_multinomial_root(real N, real total, vec2 root_u, int variant, int method, GLINT_INOUT(glint_binomial_cache) root_cache,
                                     GLINT_OUT(glint_multinomial_counts) result) {
    for (int k = 0; k < 8; ++k) result.count[k] = real(0);
    glint_binomial root = glint_binomial_variant_cached(variant, max(N, real(0)), total, root_u.x, root_u.y, method, root_cache);
    result.rest = root.negative;
    return root.positive;
}

// N trials over the tree's K bins (its q made). `variant` is a GLINT_BINOMIAL_* code, `method` a
// GLINT_POW_* code, `seed` any three words (a hash of the pixel, the grid vertex and the frame).
// With the mean-preserving variant the root draw keeps its parameters in `root_cache`, for the next
// call with the same N and total (the same counts as without). `root_u` is
// glint_multinomial_uniforms(seed, 0), for callers that have it already.
GLINT_FN glint_multinomial_counts glint_multinomial_draw(real N, glint_multinomial_tree t, uvec3 seed, vec2 root_u, int variant, int method,
                                                        GLINT_INOUT(glint_binomial_cache) root_cache) {
    glint_multinomial_counts result;
    real kept = glint_multinomial_root(N, t.total, root_u, variant, method, root_cache, result);
    if (kept > real(0)) glint_multinomial_split_nodes(kept, t, seed, variant, method, result);
    return result;
}

// N trials over K bins, the tree's q made only where the root keeps a trial.
GLINT_FN glint_multinomial_counts glint_multinomial_from_root(real N, glint_multinomial_probabilities probs, int K, uvec3 seed,
                                                             vec2 root_u, int variant, int method,
                                                             GLINT_INOUT(glint_binomial_cache) root_cache) {
    glint_multinomial_tree t = glint_multinomial_tree_root(probs, K);
    glint_multinomial_counts result;
    real kept = glint_multinomial_root(N, t.total, root_u, variant, method, root_cache, result);
    if (kept > real(0)) {
        glint_multinomial_tree_splits(t);
        glint_multinomial_split_nodes(kept, t, seed, variant, method, result);
    }
    return result;
}

GLINT_FN glint_multinomial_counts glint_multinomial_cached(real N, glint_multinomial_probabilities probs, int K, uvec3 seed,
                                                          int variant, int method, GLINT_INOUT(glint_binomial_cache) root_cache) {
    return glint_multinomial_from_root(N, probs, K, seed, glint_multinomial_uniforms(seed, 0), variant, method, root_cache);
}

GLINT_FN glint_multinomial_counts glint_multinomial(real N, glint_multinomial_probabilities probs, int K, uvec3 seed,
                                                   int variant, int method) {
    glint_binomial_cache root_cache = glint_binomial_empty_cache();
    return glint_multinomial_cached(N, probs, K, seed, variant, method, root_cache);
}
