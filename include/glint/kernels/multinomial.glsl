// glint multinomial kernel: N trials over K = 2..8 bins with probabilities p[0..K-1] (their sum
// at most 1; the remainder is an implicit rest bin, KK25 Eq. 17's dummy light for masking and
// directions below the horizon), sampled as a binary hierarchy of binomials (KK25 Sec. 6).
// Single source for C++ and GLSL 4.50; needs core.glsl and binomial.glsl (which has the variant
// codes GLINT_BINOMIAL_* and glint_binomial_variant).
//
// The root splits the K bins from the rest, each inner node splits its bins into halves; K - 1
// binomials for the bins and one for the rest, so K = 8 costs 8 binomials against 4 for K = 4.
// Every split is conservative: the counts always sum to the root's positive count.
//
// The published variants (KK25's hierarchy): the root uses the chosen variant as it is (for
// N < 2 the dual-gated variants dither, KK25 Fig. 4); a node holding N_node >= 2 gives its left
// half the variant's positive count and its right half the remainder; a node holding less than 2
// (a real count such as 1.37, or 0 or 1) sends all of it left with probability q and right
// otherwise, which is exact for N_node = 0 and 1 and keeps the mean N_node q for any real N_node.
//
// The mean-preserving variant draws every node of 4 to 63 trials exactly
// (glint_multinomial_exact_split: floor(n) trials and one of weight frac(n), each left with
// probability q), and the root too where N is from 4 to 63 and N total >= 1; below 4 trials its
// sampler is exact for whole N already (the two-point law) and cheaper. So for a whole N up to
// 63 the counts follow the multinomial law itself, not a chain of Gaussians. Larger nodes, and
// sparse roots, use the mean-preserving sampler. Against the sampler at every node this
// made the IBL grid's estimates 19% (K = 4) and 22% (K = 8) fewer instructions
// (bench/glint_frame_loop ibl K 1 under callgrind: 63.3M to 51.4M, 119.0M to 92.4M). Exact draws
// from 2 trials made glint_report's multinomial times over the binomial grid worse (median
// 45.4 ns at K = 4 against 36.8; at N = 2 twice the sampler's); exact draws of 4 to 31 trials
// only (one lane group) made examples/gl/glint_gl's IBL frames on llvmpipe (192 x 120) 15%
// slower than the sampler's (288 against 250 ms at K = 4, three alternating runs); 4 to 63, as
// here: 260 to 277 against 241 to 251 ms, 452 to 472 against 424 to 436 at K = 8.
//
// Where the root is exact and N is at most 31, the whole draw is one bit-sliced pass instead of
// the tree (glint_multinomial_exact_all: each trial's digits against the K cumulative
// probabilities at once, one loop for the root and every node): the same law, other draws. Against
// the tree of exact splits it took the IBL estimates from 50.5M to 49.5M instructions at K = 4 and
// from 91.1M to 84.6M at K = 8 (glint_frame_loop ibl K 1 under callgrind), glint_report's IBL
// glint frames (linear knob) from 10.7 and 12.5 ms to 9.1 and 9.7 ms at K = 8 (K = 4 within the
// noise: 6.5 and 7.2 ms before, 8.2 and 6.6 after; alternating runs), and examples/gl/glint_gl's
// IBL frames on llvmpipe (192 x 120) from 246 to 234 ms (K = 4) and from 437 to 391 ms (K = 8),
// two alternating runs each.

struct glint_multinomial_probabilities {
    real p[8];
};

struct glint_multinomial_counts {
    real count[8];
    real rest;  // trials that fell in none of the K bins
};

// The random words of tree node `node` (0 = root) from the seed: one PCG3D hash.
GLINT_FN uvec3 glint_multinomial_node_words(uvec3 seed, int node) {
    return glint_pcg3d(uvec3(seed.x, seed.y, seed.z + uint(node) * 0x9e3779b9u));
}

// The mean-preserving hierarchy's exact split (of a node, or of the root against the rest): n
// trials are floor(n) whole trials and, where n is not an integer, one more of weight frac(n);
// each goes left with probability q, independently of the others. The left count is
// Binomial(floor(n), q) plus frac(n) Bernoulli(q), mean n q; for integer n the binomial law
// itself, where KK25's hierarchy draws a clamped Gaussian. q is rounded down to a multiple of
// 2^-32 (the mean's error below n 2^-32, 1.5e-8 at n = 63).
//
// Bit-sliced, in at most 32 steps: trial i is bit i mod 32 of a lane group's words (trials 0..31
// in group a, 32..63 in group b) and goes left where its uniform X_i = 0.b1 b2 ... (binary) is
// below q = 0.q1 q2 .... Word k of a group holds its lanes' digits b_k; a lane is decided at its
// first digit that differs from q's (left where q's digit is 1), so words are drawn, most
// significant digit first, only until every lane is decided: about log2(lanes) + 1.3 words
// (5.5 a call in glint_frame_loop ibl 4 1). A lane whose 32 digits all equal q's has X >= q (the
// digits after the 32nd are q's zeros or more), so the law is exact for the rounded q. Each
// group's words are glint_hash_u32 of its own Weyl sequence (group a from the node's first word,
// b from its third, steps of the odd second), so that neither depends on how many words the
// other drew. One loop for both groups: as two loops, one per group, the IBL scene of
// examples/gl/glint_gl took about 310 instead of 245 ms a K = 4 frame on llvmpipe (192 x 120).
// For n up to 63 (above, whole trials beyond 63 are dropped); the caller draws larger nodes with
// the sampler, and smaller ones (below 4).
GLINT_CONST(real) GLINT_MULTINOMIAL_EXACT_SPLIT_MIN = real(4);
GLINT_CONST(real) GLINT_MULTINOMIAL_EXACT_SPLIT_MAX = real(63);

GLINT_FN real glint_multinomial_exact_split(real n, real q, uvec3 words) {
    if (!(q > real(0)) || !(n > real(0))) return real(0);
    if (q >= real(1)) return n;
    int whole = int(min(n, GLINT_MULTINOMIAL_EXACT_SPLIT_MAX));  // floor for 0 < n <= 63, the range it is for
    real frac = n - real(whole);
    uint q_bits = uint(q * real(4294967296.0));  // q 2^32, exact in float, truncated (q < 1)
    // Lanes 0 .. whole - 1 are the whole trials, lane `whole` the fractional one; lanes 0 .. 31
    // in group a, 32 .. 63 in group b, each with its own sequence of words.
    uint open_a = (whole >= 32) ? 0xffffffffu : ((2u << uint(whole)) - 1u);
    uint open_b = (whole >= 32) ? ((2u << uint(whole - 32)) - 1u) : 0u;
    uint below_a = 0u, below_b = 0u;
    uint state_a = words.x, state_b = words.z;
    uint step = words.y | 1u;
    for (int digit = 0; digit < 32; ++digit) {
        if ((open_a | open_b) == 0u) break;
        uint q_digit = 0u - (q_bits >> 31u);  // all ones where q's digit is 1
        q_bits <<= 1u;
        uint decided_a = open_a & (glint_hash_u32(state_a) ^ q_digit);  // the first digit that differs from q's
        below_a |= decided_a & q_digit;                                  // ... is 0 where q's is 1: below q
        open_a &= ~decided_a;
        state_a += step;
        if (open_b != 0u) {
            uint decided_b = open_b & (glint_hash_u32(state_b) ^ q_digit);
            below_b |= decided_b & q_digit;
            open_b &= ~decided_b;
            state_b += step;
        }
    }
    if (whole < 32) {
        uint frac_a = 1u << uint(whole);
        return real(glint_bit_count(below_a & ~frac_a)) + (((below_a & frac_a) != 0u) ? frac : real(0));
    }
    uint frac_b = 1u << uint(whole - 32);
    return real(glint_bit_count(below_a) + glint_bit_count(below_b & ~frac_b)) + (((below_b & frac_b) != 0u) ? frac : real(0));
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
            uvec3 h = glint_multinomial_node_words(seed, head + 1);
            if (variant == GLINT_BINOMIAL_UNBIASED && n >= GLINT_MULTINOMIAL_EXACT_SPLIT_MIN && n <= GLINT_MULTINOMIAL_EXACT_SPLIT_MAX) {
                n_left = glint_multinomial_exact_split(n, q, h);
            } else {
                vec2 v = vec2(glint_open_unit_from_bits(h.x), glint_open_unit_from_bits(h.y));
                n_left = (v.x < q) ? n : real(0);  // below 2: all of it to one side
                if (n >= real(2)) {
                    glint_binomial split = glint_binomial_variant(variant, n, q, v.x, v.y, method);
                    n_left = clamp(split.positive, real(0), n);
                }
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

// The whole draw in one bit-sliced pass, where the root is exact and N is at most 31 (one lane
// group): every trial's uniform X_i is compared, digit by digit as in
// glint_multinomial_exact_split, with the K cumulative probabilities c_k = p_0 + ... + p_k (each
// p_k rounded down to a multiple of 2^-32, summed exactly in 32-bit words); trial i lands in bin
// k where c_(k-1) <= X_i < c_k, and in the rest where X_i >= c_(K-1). One word sequence decides
// all K comparisons, so the K - 1 splits of the tree and the root cost one loop of about
// log2(lanes K) + 1.3 words instead of one such loop per node. The law is the multinomial's, as the
// tree's exact splits give it: the fractional trial (weight frac(N), lane floor(N)) lands in bin k
// with probability p_k. Zeroes the counts and sets every count and the rest.
GLINT_CONST(real) GLINT_MULTINOMIAL_EXACT_ALL_MAX = real(31);

GLINT_FN void glint_multinomial_exact_all(real N, glint_multinomial_tree t, uvec3 words, GLINT_INOUT(glint_multinomial_counts) result) {
    int whole = int(min(N, GLINT_MULTINOMIAL_EXACT_ALL_MAX));  // floor for 0 < N <= 31, the range it is for
    real frac = N - real(whole);
    uint lanes = (2u << uint(whole)) - 1u;  // the whole trials and the fractional one, bit `whole`
    uint frac_lane = 1u << uint(whole);
    uint threshold[8];
    uint open[8];
    uint below[8];
    uint sum = 0u;
    bool full = false;  // c_k >= 1: every trial is below it
    for (int k = 0; k < 8; ++k) {
        real scaled = (k < t.K) ? t.p[k] * real(4294967296.0) : real(0);  // p_k 2^32, exact in float
        bool whole_word = scaled >= real(4294967296.0);
        uint add = (whole_word || !(scaled >= real(0))) ? 0u : uint(scaled);  // NaN as 0, as the split does
        uint next = sum + add;
        full = full || whole_word || next < sum;  // the sum passed 2^32
        sum = next;
        threshold[k] = sum;
        open[k] = (full || k >= t.K) ? 0u : lanes;
        below[k] = full ? lanes : 0u;
    }
    uint state = words.x;
    uint step = words.y | 1u;
    // Two copies of the loop, for at most 4 and at most 8 bins, each with a constant trip count
    // over the thresholds, so that the C++ compiler unrolls it and keeps its words in registers.
    // (One loop over 8 thresholds: 55.8M instructions for the IBL estimates at K = 4 instead of
    // 49.5M; the step as a function taking the words by reference: 50.0M and 87.0M at K = 8
    // instead of 84.6M.)
    if (t.K <= 4) {
        for (int digit = 0; digit < 32; ++digit) {
            if ((open[0] | open[1] | open[2] | open[3]) == 0u) break;
            uint word = glint_hash_u32(state);
            state += step;
            for (int k = 0; k < 4; ++k) {
                uint c_digit = 0u - (threshold[k] >> 31u);  // all ones where c_k's digit is 1
                threshold[k] <<= 1u;
                uint decided = open[k] & (word ^ c_digit);  // the first digit that differs from c_k's
                below[k] |= decided & c_digit;              // ... is 0 where c_k's is 1: below c_k
                open[k] &= ~decided;
            }
        }
    } else {
        for (int digit = 0; digit < 32; ++digit) {
            if ((open[0] | open[1] | open[2] | open[3] | open[4] | open[5] | open[6] | open[7]) == 0u) break;
            uint word = glint_hash_u32(state);
            state += step;
            for (int k = 0; k < 8; ++k) {
                uint c_digit = 0u - (threshold[k] >> 31u);
                threshold[k] <<= 1u;
                uint decided = open[k] & (word ^ c_digit);
                below[k] |= decided & c_digit;
                open[k] &= ~decided;
            }
        }
    }
    uint previous = 0u;
    real kept = real(0);
    for (int k = 0; k < 8; ++k) {
        uint in_bin = (k < t.K) ? (below[k] & ~previous) : 0u;
        real count = real(glint_bit_count(in_bin & ~frac_lane)) + (((in_bin & frac_lane) != 0u) ? frac : real(0));
        result.count[k] = count;
        kept += count;
        previous = (k < t.K) ? below[k] : previous;
    }
    result.rest = N - kept;
}

// Where the mean-preserving draw takes glint_multinomial_exact_all: N from 4 to 31 and N total >= 1
// (the root's exact range, within one lane group).
GLINT_FN bool glint_multinomial_exact_all_applies(real N, real total, int variant) {
    return variant == GLINT_BINOMIAL_UNBIASED && N >= GLINT_MULTINOMIAL_EXACT_SPLIT_MIN && N <= GLINT_MULTINOMIAL_EXACT_ALL_MAX &&
           N * total >= real(1);
}

// The root of a draw: N trials drawn between the K bins (probability `total`) and the rest, from
// the root's words (glint_multinomial_node_words(seed, 0)). Zeroes the counts, sets result.rest,
// and returns the bins' trials for glint_multinomial_split_nodes. The mean-preserving hierarchy
// draws the root exactly (glint_multinomial_exact_split) where N is from 4 to 63 and N total >= 1;
// elsewhere with the sampler, from the words' uniforms (u1 from the first). Where N total >= 1 the
// sampler's skip test (glint_surely_no_success on u1, grid.glsl) never fires, so a caller that
// skips roots by it skips only sampler draws that surely keep nothing. (Below N = 4 the sampler
// is exact for whole N, and for N < 2 dithers to whole counts, KK25 Fig. 4.)
GLINT_FN real glint_multinomial_root(real N, real total, uvec3 root_words, int variant, int method, GLINT_INOUT(glint_binomial_cache) root_cache,
                                     GLINT_OUT(glint_multinomial_counts) result) {
    for (int k = 0; k < 8; ++k) result.count[k] = real(0);
    N = max(N, real(0));
    if (variant == GLINT_BINOMIAL_UNBIASED && N >= GLINT_MULTINOMIAL_EXACT_SPLIT_MIN && N <= GLINT_MULTINOMIAL_EXACT_SPLIT_MAX && N * total >= real(1)) {
        real kept = glint_multinomial_exact_split(N, total, root_words);
        result.rest = N - kept;
        return kept;
    }
    vec2 u = vec2(glint_open_unit_from_bits(root_words.x), glint_open_unit_from_bits(root_words.y));
    glint_binomial root = glint_binomial_variant_cached(variant, N, total, u.x, u.y, method, root_cache);
    result.rest = root.negative;
    return root.positive;
}

// N trials over the tree's K bins (its q made). `variant` is a GLINT_BINOMIAL_* code, `method` a
// GLINT_POW_* code, `seed` any three words (a hash of the pixel, the grid vertex and the frame).
// With the mean-preserving variant the root draw keeps its parameters in `root_cache`, for the next
// call with the same N and total (the same counts as without). `root_words` is
// glint_multinomial_node_words(seed, 0), for callers that have it already.
GLINT_FN glint_multinomial_counts glint_multinomial_draw(real N, glint_multinomial_tree t, uvec3 seed, uvec3 root_words, int variant, int method,
                                                        GLINT_INOUT(glint_binomial_cache) root_cache) {
    glint_multinomial_counts result;
    if (glint_multinomial_exact_all_applies(N, t.total, variant)) {
        glint_multinomial_exact_all(N, t, root_words, result);
        return result;
    }
    real kept = glint_multinomial_root(N, t.total, root_words, variant, method, root_cache, result);
    if (kept > real(0)) glint_multinomial_split_nodes(kept, t, seed, variant, method, result);
    return result;
}

// N trials over K bins, the tree's q made only where the root keeps a trial.
GLINT_FN glint_multinomial_counts glint_multinomial_from_root(real N, glint_multinomial_probabilities probs, int K, uvec3 seed,
                                                             uvec3 root_words, int variant, int method,
                                                             GLINT_INOUT(glint_binomial_cache) root_cache) {
    glint_multinomial_tree t = glint_multinomial_tree_root(probs, K);
    glint_multinomial_counts result;
    if (glint_multinomial_exact_all_applies(N, t.total, variant)) {
        glint_multinomial_exact_all(N, t, root_words, result);
        return result;
    }
    real kept = glint_multinomial_root(N, t.total, root_words, variant, method, root_cache, result);
    if (kept > real(0)) {
        glint_multinomial_tree_splits(t);
        glint_multinomial_split_nodes(kept, t, seed, variant, method, result);
    }
    return result;
}

GLINT_FN glint_multinomial_counts glint_multinomial_cached(real N, glint_multinomial_probabilities probs, int K, uvec3 seed,
                                                          int variant, int method, GLINT_INOUT(glint_binomial_cache) root_cache) {
    return glint_multinomial_from_root(N, probs, K, seed, glint_multinomial_node_words(seed, 0), variant, method, root_cache);
}

GLINT_FN glint_multinomial_counts glint_multinomial(real N, glint_multinomial_probabilities probs, int K, uvec3 seed,
                                                   int variant, int method) {
    glint_binomial_cache root_cache = glint_binomial_empty_cache();
    return glint_multinomial_cached(N, probs, K, seed, variant, method, root_cache);
}
