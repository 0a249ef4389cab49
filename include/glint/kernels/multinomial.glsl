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
// probability q), and where N is from 4 to 63 and N total >= 1 the whole draw at once
// (glint_multinomial_exact_all, below; the root's exact split before it); below 4 trials its
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
// Where the root is exact and N is at most 63, the whole draw is one bit-sliced pass instead of
// the tree (glint_multinomial_exact_all: each trial's digits against the K cumulative
// probabilities at once, one loop for the root and every node, per lane group of 32 trials): the
// same law, other draws. For N up to 31 against the tree of exact splits it took the IBL estimates
// from 50.5M to 49.5M instructions at K = 4 and from 91.1M to 84.6M at K = 8 (glint_frame_loop
// ibl K 1 under callgrind), glint_report's IBL glint frames (linear knob) from 10.7 and 12.5 ms to
// 9.1 and 9.7 ms at K = 8, and examples/gl/glint_gl's IBL frames on llvmpipe (192 x 120) from 246
// to 234 ms (K = 4) and from 437 to 391 ms (K = 8), two alternating runs each. Up to 63, with C++
// drawing four lane groups at once (then glint_multinomial_exact_all_many; now _weighted, below):
// 49.5M to 43.1M at K = 4, 84.6M to 61.8M at K = 8; glint_report's IBL glint frames (linear
// knob, two rounds alternating with the code before) 5715 and 6032 us to 4878 and 4688 at K = 4,
// 9424 and 9295 to 6608 and 5882 at K = 8; llvmpipe's (GLSL, one lane group at a time, four
// alternating rounds) 236 to 238 ms to 229 to 232 at K = 4, 390 to 393 to 366 at K = 8.

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
// vertices of a pixel) makes them once (the root, glint_multinomial_tree_root, and the q where a
// vertex draws down the tree, glint_multinomial_tree_splits); a single draw makes the q only where
// the root keeps a trial (sparse glints: most draws keep none).
struct glint_multinomial_tree {
    int K;
    real total;  // the K bins' probability, at most 1
    real p[8];   // the bins' probabilities as clamped and scaled
    real q[7];   // per inner node; node 0 holds all K bins
};

// K, the probabilities and their total; the q are left to glint_multinomial_tree_splits.
GLINT_FN glint_multinomial_tree glint_multinomial_tree_root(GLINT_IN(glint_multinomial_probabilities) probs, int K) {
    glint_multinomial_tree t;
    t.K = clamp(K, 2, 8);
    // Each p_k taken twice, for the sum and then scaled, not stored and rescaled in place (in
    // C++ the rescaling's vector loads waited for the scalar stores: kernels/ibl.glsl's
    // glint_ibl_probabilities says more).
#if defined(GLINT_GLSL)
    real total = real(0);
    for (int k = 0; k < 8; ++k) total += (k < t.K) ? max(probs.p[k], real(0)) : real(0);
    real scale = (total > real(1)) ? real(1) / total : real(1);
    for (int k = 0; k < 8; ++k) t.p[k] = ((k < t.K) ? max(probs.p[k], real(0)) : real(0)) * scale;
#else
    // The same values four bins at a time (GCC kept both loops scalar: 86 instructions a pixel of
    // the IBL's K = 4 estimate); max as GLM's (x < 0 ? 0 : x, which keeps a NaN).
    typedef real realx4 __attribute__((vector_size(4 * sizeof(real))));
    typedef decltype(realx4{} < realx4{}) maskx4;
    const realx4 none = {};
    realx4 v[2];
    for (int h = 0; h < 2; ++h) {
        realx4 x;
        std::memcpy(&x, probs.p + 4 * h, sizeof(x));
        x = (x < none) ? none : x;
        const maskx4 bin = {4 * h, 4 * h + 1, 4 * h + 2, 4 * h + 3};
        v[h] = (bin < t.K) ? x : none;
    }
    real total;
    const real scale = glint_scale_to_unit_sum(v, t.p, total);
#endif
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

GLINT_FN glint_multinomial_tree glint_multinomial_make_tree(GLINT_IN(glint_multinomial_probabilities) probs, int K) {
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

// The whole draw in one bit-sliced pass, where the root is exact and N is at most 63: every
// trial's uniform X_i is compared, digit by digit as in glint_multinomial_exact_split, with the K
// cumulative probabilities c_k = p_0 + ... + p_k (each p_k rounded down to a multiple of 2^-32,
// summed exactly in 32-bit words); trial i lands in bin k where c_(k-1) <= X_i < c_k, and in the
// rest where X_i >= c_(K-1). One word sequence decides all K comparisons, so the K - 1 splits of
// the tree and the root cost one loop of about log2(lanes K) + 1.3 words instead of one such loop
// per node. Trials 0..31 are lane group a (words from words.x), 32..63 group b (from words.z),
// each its own Weyl sequence with the step words.y | 1, as in glint_multinomial_exact_split. The
// law is the multinomial's, as the tree's exact splits give it: the fractional trial (weight
// frac(N), lane floor(N)) lands in bin k with probability p_k.
GLINT_CONST(real) GLINT_MULTINOMIAL_EXACT_ALL_MAX = real(63);

// The thresholds c_k 2^32 (c_k = p_0 + ... + p_k), and per bin whether c_k reached 1 (every trial
// is below it).
struct glint_multinomial_thresholds {
    uint c[8];
    bool full[8];
};

// Per bin k, the trials (bits) of one lane group found below c_k.
struct glint_multinomial_below {
    uint mask[8];
};

GLINT_FN glint_multinomial_thresholds glint_multinomial_exact_all_thresholds(GLINT_IN(glint_multinomial_tree) t) {
    glint_multinomial_thresholds o;
    uint sum = 0u;
    bool reached = false;
    for (int k = 0; k < 8; ++k) {
        real scaled = (k < t.K) ? t.p[k] * real(4294967296.0) : real(0);  // p_k 2^32, exact in float
        bool whole_word = scaled >= real(4294967296.0);
        uint add = (whole_word || !(scaled >= real(0))) ? 0u : uint(scaled);  // NaN as 0, as the split does
        uint next = sum + add;
        reached = reached || whole_word || next < sum;  // the sum passed 2^32
        sum = next;
        o.c[k] = sum;
        o.full[k] = reached;
    }
    return o;
}

// The lanes of groups a and b: the whole trials and the fractional one (bit floor(N) overall).
GLINT_FN uvec2 glint_multinomial_exact_all_lanes(real N) {
    int whole = int(min(N, GLINT_MULTINOMIAL_EXACT_ALL_MAX));  // floor for 0 < N <= 63, the range it is for
    return (whole >= 32) ? uvec2(0xffffffffu, (2u << uint(whole - 32)) - 1u) : uvec2((2u << uint(whole)) - 1u, 0u);
}

// The fractional trial's lane, the top one of all (bit floor(N)), as a mask in group a and in
// group b, from the groups' lanes.
GLINT_FN uvec2 glint_multinomial_exact_all_frac_lanes(uvec2 lanes) {
    return uvec2((lanes.y == 0u) ? lanes.x ^ (lanes.x >> 1u) : 0u, lanes.y ^ (lanes.y >> 1u));
}

// One lane group's pass: its lanes' masks below each c_k, from the words hash(state + j step).
GLINT_FN glint_multinomial_below glint_multinomial_exact_all_group(glint_multinomial_thresholds c, int K, uint lanes, uint state, uint step) {
    uint threshold[8];
    uint open[8];
    glint_multinomial_below below;
    for (int k = 0; k < 8; ++k) {
        threshold[k] = c.c[k];
        open[k] = (c.full[k] || k >= K) ? 0u : lanes;
        below.mask[k] = c.full[k] ? lanes : 0u;
    }
    // Two copies of the loop, for at most 4 and at most 8 bins, each with a constant trip count
    // over the thresholds, so that the C++ compiler unrolls it and keeps its words in registers.
    // (One loop over 8 thresholds: 55.8M instructions for the IBL estimates at K = 4 instead of
    // 49.5M; the step as a function taking the words by reference: 50.0M and 87.0M at K = 8
    // instead of 84.6M.)
    if (K <= 4) {
        for (int digit = 0; digit < 32; ++digit) {
            if ((open[0] | open[1] | open[2] | open[3]) == 0u) break;
            uint word = glint_hash_u32(state);
            state += step;
            for (int k = 0; k < 4; ++k) {
                uint c_digit = 0u - (threshold[k] >> 31u);  // all ones where c_k's digit is 1
                threshold[k] <<= 1u;
                uint decided = open[k] & (word ^ c_digit);  // the first digit that differs from c_k's
                below.mask[k] |= decided & c_digit;         // ... is 0 where c_k's is 1: below c_k
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
                below.mask[k] |= decided & c_digit;
                open[k] &= ~decided;
            }
        }
    }
    return below;
}

// The counts from the two groups' masks. Zeroes the counts and sets every count and the rest.
GLINT_FN void glint_multinomial_exact_all_counts(real N, glint_multinomial_tree t, glint_multinomial_below a, glint_multinomial_below b,
                                                 GLINT_INOUT(glint_multinomial_counts) result) {
    real frac = N - real(int(min(N, GLINT_MULTINOMIAL_EXACT_ALL_MAX)));
    uvec2 frac_lanes = glint_multinomial_exact_all_frac_lanes(glint_multinomial_exact_all_lanes(N));
    uint frac_a = frac_lanes.x, frac_b = frac_lanes.y;
    uint previous_a = 0u, previous_b = 0u;
    real kept = real(0);
    for (int k = 0; k < 8; ++k) {
        uint in_a = (k < t.K) ? (a.mask[k] & ~previous_a) : 0u;
        uint in_b = (k < t.K) ? (b.mask[k] & ~previous_b) : 0u;
        real count = real(glint_bit_count(in_a & ~frac_a) + glint_bit_count(in_b & ~frac_b)) +
                     ((((in_a & frac_a) | (in_b & frac_b)) != 0u) ? frac : real(0));
        result.count[k] = count;
        kept += count;
        previous_a = (k < t.K) ? a.mask[k] : previous_a;
        previous_b = (k < t.K) ? b.mask[k] : previous_b;
    }
    result.rest = N - kept;
}

GLINT_FN void glint_multinomial_exact_all(real N, glint_multinomial_tree t, uvec3 words, GLINT_INOUT(glint_multinomial_counts) result) {
    glint_multinomial_thresholds c = glint_multinomial_exact_all_thresholds(t);
    uvec2 lanes = glint_multinomial_exact_all_lanes(N);
    glint_multinomial_below a = glint_multinomial_exact_all_group(c, t.K, lanes.x, words.x, words.y | 1u);
    glint_multinomial_below b;
    for (int k = 0; k < 8; ++k) b.mask[k] = 0u;
    if (lanes.y != 0u) b = glint_multinomial_exact_all_group(c, t.K, lanes.y, words.z, words.y | 1u);
    glint_multinomial_exact_all_counts(N, t, a, b, result);
}

#if !defined(GLINT_GLSL)
// The lane sums of eight vectors of W = 4 or 8 lanes, each added in pairs of lanes, then pairs of
// pairs: total[k] = sum[k][0] + ... + sum[k][W - 1]. The vectors are combined as they are added
// (shuffles that put vector 2j's pair sums in the even lanes and 2j + 1's in the odd ones, and so
// on), so that seven vector additions (W = 8) do what 56 scalar ones would, in three rounds
// rather than chains of seven.
template <typename V>
__attribute__((always_inline)) static inline void glint_pairwise_lane_sums(const V sum[8], real total[8]) {
    constexpr int W = sizeof(V) / sizeof(real);
    static_assert(W == 4 || W == 8, "four or eight lanes");
    V pairs[4];  // lane 2i + e: vector 2j + e's lanes 2i and 2i + 1
    for (int j = 0; j < 4; ++j) {
        if constexpr (W == 8)
            pairs[j] = __builtin_shufflevector(sum[2 * j], sum[2 * j + 1], 0, 8, 2, 10, 4, 12, 6, 14) +
                       __builtin_shufflevector(sum[2 * j], sum[2 * j + 1], 1, 9, 3, 11, 5, 13, 7, 15);
        else
            pairs[j] = __builtin_shufflevector(sum[2 * j], sum[2 * j + 1], 0, 4, 2, 6) + __builtin_shufflevector(sum[2 * j], sum[2 * j + 1], 1, 5, 3, 7);
    }
    // Lanes 4 h + m: vector 4 j + m's sum over lanes 4 h to 4 h + 3.
    V quads[2];
    for (int j = 0; j < 2; ++j) {
        if constexpr (W == 8)
            quads[j] = __builtin_shufflevector(pairs[2 * j], pairs[2 * j + 1], 0, 1, 8, 9, 4, 5, 12, 13) +
                       __builtin_shufflevector(pairs[2 * j], pairs[2 * j + 1], 2, 3, 10, 11, 6, 7, 14, 15);
        else
            quads[j] = __builtin_shufflevector(pairs[2 * j], pairs[2 * j + 1], 0, 1, 4, 5) + __builtin_shufflevector(pairs[2 * j], pairs[2 * j + 1], 2, 3, 6, 7);
    }
    if constexpr (W == 8) {
        const V all = __builtin_shufflevector(quads[0], quads[1], 0, 1, 2, 3, 8, 9, 10, 11) + __builtin_shufflevector(quads[0], quads[1], 4, 5, 6, 7, 12, 13, 14, 15);
        for (int k = 0; k < 8; ++k) total[k] = all[k];
    } else {
        for (int k = 0; k < 8; ++k) total[k] = quads[k >> 2][k & 3];
    }
}

// C++ only: glint_multinomial_exact_all_group for W lane groups with one set of thresholds at
// once (the IBL's grid vertices of a pixel share their probabilities), their words side by side,
// so that the hashes, comparisons and bit counts run in vector registers (GCC's and Clang's vector
// extension): W = 4 in SSE2's, the baseline of x86-64, and where the CPU has AVX2, W = 8 in its
// (GCC on x86-64; chosen at run time, glint_cpu_avx2). Each group's bins are those
// of glint_multinomial_exact_all_group: the steps that the other groups still need leave a group
// whose lanes are all decided unchanged. GPUs run one fragment a thread: GLSL keeps the single
// group.
//
// What the IBL needs of the counts is their sum weighted by the vertices' triangle weights l_t
// (ibl.glsl), so the pass returns that: for each bin k < T it adds to weighted[k] the sum over the
// groups v of weight[v] times the number of the group's trials in bin k other than the fractional
// one (lane mask frac[v], 0 where the group has none), plus frac_weight[v] where that trial fell
// in bin k. With one group of weight 1 and the others 0, weighted[k] is that group's count
// (tests/unit/test_multinomial.cpp compares each group so with its one-group pass). It replaced
// per-group bins that the caller turned into per-vertex counts and then weighted: the IBL
// estimates of glint_frame_loop ibl 4 1 count 26.3M instructions instead of 30.8M, ibl 8 1 34.9M
// instead of 42.0M (callgrind, GCC 12; the sums the same to float rounding), and the K = 4 and
// K = 8 frames took about 10% less time (DEVELOPERS.md).
//
// The pass for thresholds c_0 .. c_(T-1), T = K from 2 to 8 a compile-time constant, so that the
// compiler unrolls the loop over them and keeps their words in registers where they fit. (One
// loop for T rounded up to 4 or 8 at run time, as before, spilled the words to the stack: a digit
// took about 85 instructions at K = 3, IBL K = 4's lit levels, against 63 now; the IBL estimates
// of glint_frame_loop ibl 4 1 count 37.5M instructions instead of 43.5M, ibl 8 1 56.4M instead of
// 62.3M, the same sums; callgrind, GCC 12.) Always inlined, so that the AVX2 function below
// compiles it with AVX2.
//
// The pass compares with the thresholds it is given, c.c[0 .. T-1], and adds threshold j's bin to
// weighted[bin[j]]. Where a trial is still undecided after stop_digit digits (even; 32: never),
// it gives up and returns false before it adds anything (glint_multinomial_exact_all_groups).
template <int T, int W>
__attribute__((always_inline)) static inline bool glint_multinomial_exact_all_groups_pass(const glint_multinomial_thresholds& c, const int bin[8],
                                                                                          int stop_digit, const uint lanes_in[],
                                                                                          const uint frac_in[], const uint state_in[],
                                                                                          const uint step_in[], const real weight_in[],
                                                                                          const real frac_weight_in[], real weighted[8]) {
    typedef uint u32x4 __attribute__((vector_size(16)));
    typedef uint u32x8 __attribute__((vector_size(32)));
    typedef int i32x4 __attribute__((vector_size(16)));
    typedef int i32x8 __attribute__((vector_size(32)));
    typedef unsigned long long u64x2 __attribute__((vector_size(16)));
    typedef unsigned long long u64x4 __attribute__((vector_size(32)));
    typedef float f32x4 __attribute__((vector_size(16)));  // real's vectors (GCC ignores vector_size on a dependent type)
    typedef float f32x8 __attribute__((vector_size(32)));
    typedef double f64x4 __attribute__((vector_size(32)));
    typedef double f64x8 __attribute__((vector_size(64)));
    typedef typename std::conditional<std::is_same<real, float>::value, f32x4, f64x4>::type realx4;
    typedef typename std::conditional<std::is_same<real, float>::value, f32x8, f64x8>::type realx8;
    static_assert(W == 4 || W == 8, "four or eight lane groups");
    typedef typename std::conditional<W == 8, u32x8, u32x4>::type u32xw;
    typedef typename std::conditional<W == 8, i32x8, i32x4>::type i32xw;
    typedef typename std::conditional<W == 8, u64x4, u64x2>::type u64xw;
    typedef typename std::conditional<W == 8, realx8, realx4>::type realxw;
    u32xw lanes, frac, state, step;
    realxw weight, frac_weight;
    for (int v = 0; v < W; ++v) {
        lanes[v] = lanes_in[v];
        frac[v] = frac_in[v];
        state[v] = state_in[v];
        step[v] = step_in[v];
        weight[v] = weight_in[v];
        frac_weight[v] = frac_weight_in[v];
    }
    const u32xw none = {};
    u32xw threshold[8];  // the first T of each are used
    u32xw open[8];
    u32xw below[8];
    for (int k = 0; k < T; ++k) {
        threshold[k] = none + c.c[k];
        open[k] = c.full[k] ? none : lanes;
        below[k] = c.full[k] ? lanes : none;
    }
    // Two digits between tests of whether any trial is still open: a digit after the last one
    // needed finds every open mask empty and changes nothing but the local state and thresholds,
    // and the test (two extractions and three ors where GCC's vector code cannot say vptest) cost
    // about as much as a digit's comparisons at T = 3.
    for (int digit = 0; digit < 32; digit += 2) {
        u32xw any = open[0];
        for (int k = 1; k < T; ++k) any |= open[k];
        u64xw wide = reinterpret_cast<u64xw>(any);
        unsigned long long still_open = 0u;
        for (int h = 0; h < W / 2; ++h) still_open |= wide[h];
        if (still_open == 0u) break;
        if (digit == stop_digit) return false;
        for (int twice = 0; twice < 2; ++twice) {
            u32xw word = state;  // glint_hash_u32, W at once
            glint_hash_u32_vector(word);
            state += step;
            for (int k = 0; k < T; ++k) {
                u32xw c_digit = none - (threshold[k] >> 31u);  // all ones where c_k's digit is 1
                threshold[k] <<= 1u;
                u32xw decided = open[k] & (word ^ c_digit);
                below[k] |= decided & c_digit;
                open[k] &= ~decided;
            }
        }
    }
    u32xw previous = none;
    realxw sum[8];  // per threshold, its bin's weighted counts, one lane a group; the first T are used
    for (int k = 0; k < T; ++k) {
        u32xw in_bin = below[k] & ~previous;
        previous = below[k];
        u32xw x = in_bin & ~frac;  // glint_bit_count, W at once
        x = x - ((x >> 1u) & 0x55555555u);
        x = (x & 0x33333333u) + ((x >> 2u) & 0x33333333u);
        x = (x + (x >> 4u)) & 0x0f0f0f0fu;
        x = (x * 0x01010101u) >> 24u;
        // The counts (at most 32) and the fractional trial's 0 or 1 convert exactly.
        i32xw frac_in_bin = -((in_bin & frac) != 0u);
        sum[k] = __builtin_convertvector(reinterpret_cast<i32xw>(x), realxw) * weight + __builtin_convertvector(frac_in_bin, realxw) * frac_weight;
    }
    // Each sum's W lanes added for all thresholds at once, pairs of lanes first (lane by lane,
    // one threshold after another, they were chains of dependent additions: the IBL frames of
    // glint_frame_loop ibl K 100 took 4% (K = 4) and 6% (K = 8) longer; DEVELOPERS.md).
    const realxw zero = {};
    for (int k = T; k < 8; ++k) sum[k] = zero;
    real total[8];
    glint_pairwise_lane_sums(sum, total);
    for (int k = 0; k < T; ++k) weighted[bin[k]] += total[k];
    return true;
}

// The pass of W groups for K bins (K clamped to 2..8), where a threshold that shares its first
// GLINT_MULTINOMIAL_FOLLOWER_DIGITS binary digits with the one before (a follower) is left out
// while no trial needs it. A trial X below a follower c_k but not below c_(k-1) lies between the
// two, so its first 16 digits are theirs, which are also those of the nearest threshold before
// them that is not a follower: against that one, X is still undecided after 16 digits. So the pass
// without the followers runs first and stops where any trial is undecided after 16 digits; if none
// is, every follower's bin is empty and every other bin holds what the pass found: the same counts
// as with every threshold. Otherwise the pass runs again with all of them. Levels that reflect
// almost nothing (the sun's, a few texels of the map) make followers: in glint_frame_loop ibl K 1
// (sunset.exr), at K = 4 6864 of the 7825 passes left one of the three thresholds out; at K = 8
// 5651 kept four of the seven, 1320 five, 311 six; 40 and 61 passes ran again. The IBL estimates
// there took 19.57M to 19.11M instructions at K = 4 and 26.77M to 23.97M at K = 8 (callgrind, GCC
// 12; the same sums), the frames of glint_frame_loop ibl K 100 2251 to 2113 us and 2884 to 2502 us
// (least of seven alternating runs, this project's 2-core AMD EPYC, CPU; DEVELOPERS.md). With 14
// digits the frames took as long, with 12 longer (more passes ran again). Returns the passes run.
GLINT_CONST(int) GLINT_MULTINOMIAL_FOLLOWER_DIGITS = 16;  // even: the pass tests every second digit

template <int W>
__attribute__((always_inline)) static inline bool glint_multinomial_exact_all_groups_of(const glint_multinomial_thresholds& c, int T, const int bin[8],
                                                                                       int stop_digit, const uint lanes_in[], const uint frac_in[],
                                                                                       const uint state_in[], const uint step_in[],
                                                                                       const real weight_in[], const real frac_weight_in[],
                                                                                       real weighted[8]) {
#define GLINT_PASS(n) glint_multinomial_exact_all_groups_pass<n, W>(c, bin, stop_digit, lanes_in, frac_in, state_in, step_in, weight_in, frac_weight_in, weighted)
    switch (T) {
        case 1: return GLINT_PASS(1);
        case 2: return GLINT_PASS(2);
        case 3: return GLINT_PASS(3);
        case 4: return GLINT_PASS(4);
        case 5: return GLINT_PASS(5);
        case 6: return GLINT_PASS(6);
        case 7: return GLINT_PASS(7);
        default: return GLINT_PASS(8);
    }
#undef GLINT_PASS
}

template <int W>
__attribute__((always_inline)) static inline int glint_multinomial_exact_all_groups(const glint_multinomial_thresholds& c, int K, const uint lanes_in[],
                                                                                    const uint frac_in[], const uint state_in[], const uint step_in[],
                                                                                    const real weight_in[], const real frac_weight_in[], real weighted[8]) {
    const int T = clamp(K, 2, 8);
    glint_multinomial_thresholds leaders;  // the first `count` entries
    int leader_bin[8];
    const int all_bins[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    leaders.c[0] = c.c[0], leaders.full[0] = c.full[0], leader_bin[0] = 0;
    int count = 1;
    for (int k = 1; k < T; ++k) {
        // & rather than &&: no branches (GCC made one of each &&: 69 instructions a pixel on this line)
        const bool follower = (((c.c[k - 1] ^ c.c[k]) >> uint(32 - GLINT_MULTINOMIAL_FOLLOWER_DIGITS)) == 0u) & !(c.full[k] | c.full[k - 1]);
        leaders.c[count] = c.c[k], leaders.full[count] = c.full[k], leader_bin[count] = k;
        count += follower ? 0 : 1;
    }
    if (count < T && glint_multinomial_exact_all_groups_of<W>(leaders, count, leader_bin, GLINT_MULTINOMIAL_FOLLOWER_DIGITS, lanes_in, frac_in,
                                                              state_in, step_in, weight_in, frac_weight_in, weighted))
        return 1;
    glint_multinomial_exact_all_groups_of<W>(c, T, all_bins, 32, lanes_in, frac_in, state_in, step_in, weight_in, frac_weight_in, weighted);
    return (count < T) ? 2 : 1;
}

// Four groups, for the baseline target.
GLINT_FN_OUT_OF_LINE int glint_multinomial_exact_all_groups_x4(const glint_multinomial_thresholds& c, int K, const uint lanes_in[4],
                                                               const uint frac_in[4], const uint state_in[4], const uint step_in[4],
                                                               const real weight_in[4], const real frac_weight_in[4], real weighted[8]) {
    return glint_multinomial_exact_all_groups<4>(c, K, lanes_in, frac_in, state_in, step_in, weight_in, frac_weight_in, weighted);
}

// Eight groups in AVX2's registers, where the CPU has them (glint_cpu_avx2): eight
// 32-bit multiplies in one instruction, which SSE2 does in about six for four. On this project's
// 2-core AMD EPYC (CPU), glint_report --only ibl, two rounds alternating with the four-group pass:
// the glint frame 7.52x and 7.54x the smooth one against 8.63x and 9.47x at K = 4, 9.79x and 8.75x
// against 14.0x and 11.0x at K = 8 (linear knob; with the level shares' one division a pixel,
// ibl.glsl). Eight groups in SSE2's registers (two per vector) were slower than two four-group
// passes (each digit waits for the slowest of eight groups): the baseline keeps four.
// Without the AVX2 path (another compiler or target, or GLINT_NO_AVX2) it is the baseline's, which
// glint_multinomial_exact_all_weighted does not call: it draws four groups at a time there.
GLINT_LANES_BODY
int glint_multinomial_exact_all_groups_x8_body(const glint_multinomial_thresholds& c, int K, const uint lanes_in[8], const uint frac_in[8],
                                               const uint state_in[8], const uint step_in[8], const real weight_in[8], const real frac_weight_in[8],
                                               real weighted[8]) {
    return glint_multinomial_exact_all_groups<8>(c, K, lanes_in, frac_in, state_in, step_in, weight_in, frac_weight_in, weighted);
}
GLINT_LANES_VARIANTS(int, glint_multinomial_exact_all_groups_x8,
                     (const glint_multinomial_thresholds& c, int K, const uint lanes_in[8], const uint frac_in[8], const uint state_in[8],
                      const uint step_in[8], const real weight_in[8], const real frac_weight_in[8], real weighted[8]),
                     (c, K, lanes_in, frac_in, state_in, step_in, weight_in, frac_weight_in, weighted))


// glint_multinomial_exact_all for the draws i with bit i of draws set (each with N[i] from 4 to
// 63 and root words (words_x[i], words_y[i], words_z[i]); N total >= 1), all with tree t, their
// lane groups (one or two a draw) four or eight at a time: adds to weighted[k], k < t.K, the sum
// over those draws of weight[i] times their count in bin k (glint_multinomial_exact_all's counts,
// summed in another order).
GLINT_FN void glint_multinomial_exact_all_weighted(const glint_multinomial_tree& t, uint draws, const real N[12], const uint words_x[12],
                                                   const uint words_y[12], const uint words_z[12], const real weight[12], real weighted[8]) {
    glint_multinomial_thresholds c = glint_multinomial_exact_all_thresholds(t);
    uint lanes[32], frac[32], state[32], step[32];  // up to 24 groups and the last pass's padding
    real group_weight[32], frac_weight[32];
    int groups = 0;
    // The set bits of draws, lowest first (callgrind, ibl 4 1: 34 instructions a pixel, where a
    // loop over the twelve slots with a test each took 77).
    for (uint rest = draws; rest != 0u; rest &= rest - 1u) {
        const int i = __builtin_ctz(rest);
        uvec2 group_lanes = glint_multinomial_exact_all_lanes(N[i]);
        uvec2 frac_lanes = glint_multinomial_exact_all_frac_lanes(group_lanes);
        real frac_share = weight[i] * (N[i] - real(int(min(N[i], GLINT_MULTINOMIAL_EXACT_ALL_MAX))));
        bool two = group_lanes.y != 0u;  // floor(N) >= 32: the fractional lane is group b's
        lanes[groups] = group_lanes.x, frac[groups] = frac_lanes.x;
        state[groups] = words_x[i], step[groups] = words_y[i] | 1u;
        group_weight[groups] = weight[i], frac_weight[groups] = two ? real(0) : frac_share;
        ++groups;
        if (!two) continue;
        lanes[groups] = group_lanes.y, frac[groups] = frac_lanes.y;
        state[groups] = words_z[i], step[groups] = words_y[i] | 1u;
        group_weight[groups] = weight[i], frac_weight[groups] = frac_share;
        ++groups;
    }
    const int width = glint_cpu_avx2() ? 8 : 4;
    // The last pass's groups past `groups` hold no trial: eight of them, each array's in one copy
    // of constant size (a loop up to the next multiple of the width became five calls of memset a
    // pixel, and so did a loop of two copies).
    const uint zero_words[8] = {0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u}, one_words[8] = {1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u};
    const real zero_reals[8] = {real(0), real(0), real(0), real(0), real(0), real(0), real(0), real(0)};
    std::memcpy(lanes + groups, zero_words, sizeof(zero_words)), std::memcpy(frac + groups, zero_words, sizeof(zero_words));
    std::memcpy(state + groups, zero_words, sizeof(zero_words)), std::memcpy(step + groups, one_words, sizeof(one_words));
    std::memcpy(group_weight + groups, zero_reals, sizeof(zero_reals)), std::memcpy(frac_weight + groups, zero_reals, sizeof(zero_reals));
    for (int j = 0; j < groups; j += width) {
        if (width == 8) glint_multinomial_exact_all_groups_x8(c, t.K, lanes + j, frac + j, state + j, step + j, group_weight + j, frac_weight + j, weighted);
        else glint_multinomial_exact_all_groups_x4(c, t.K, lanes + j, frac + j, state + j, step + j, group_weight + j, frac_weight + j, weighted);
    }
}

// C++ only: the pass of glint_multinomial_exact_all_groups_pass for eight lane groups that each
// have their own thresholds: group v compares with c[k][v] (full[k][v] all ones where c_k is
// full), so that eight pixels, each with its own probabilities, draw one vertex each in one pass
// (glint_ibl_sample_pixels, ibl.glsl). Adds lane-wise, weighted[k][v] += group v's weighted count
// in bin k; where a group of stop_lanes is still undecided after stop_digit digits, it gives up and
// returns false before it adds anything. A group whose follower thresholds (those that share their
// first GLINT_MULTINOMIAL_FOLLOWER_DIGITS digits with the one before) are set to its last leader's
// value has its followers' bins empty and every other bin as with the leaders alone, the pass that
// glint_multinomial_exact_all_groups runs first: the same counts, by the argument given there.
// Eight lanes in AVX2's registers (C++ only): the lane types of the passes below and of ibl.glsl's
// eight pixels at a time.
typedef uint glint_u32x8 __attribute__((vector_size(32)));
typedef int glint_i32x8 __attribute__((vector_size(32)));
typedef unsigned long long glint_u64x4 __attribute__((vector_size(32)));
typedef float glint_f32x8 __attribute__((vector_size(32)));
typedef double glint_f64x8 __attribute__((vector_size(64)));
typedef typename std::conditional<std::is_same<real, float>::value, glint_f32x8, glint_f64x8>::type glint_realx8;

// glint_floor_bounded lane-wise, in place (a reference: a vector passed by value to a function not
// compiled for AVX would change the ABI): the same values bit for bit.
__attribute__((always_inline)) static inline void glint_lanes_floor_bounded(glint_f32x8& x) {
    const glint_f32x8 t = __builtin_convertvector(__builtin_convertvector(x, glint_i32x8), glint_f32x8);
    x = (t > x) ? t - real(1) : t;
}

// Whether every word of a vector of eight is zero: one vptest where the AVX2 path is built (the
// pass's test for open trials, 6.2 a pass in the IBL's K = 4 frame; GCC's own reduction of the
// vector takes about eight instructions), four words or'd elsewhere.
__attribute__((always_inline)) static inline bool glint_lanes_all_zero(const glint_u32x8& v) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
    typedef long long i64x4 __attribute__((vector_size(32)));
    return __builtin_ia32_ptestz256(reinterpret_cast<i64x4>(v), reinterpret_cast<i64x4>(v)) != 0;
#else
    const glint_u64x4 wide = reinterpret_cast<glint_u64x4>(v);
    return (wide[0] | wide[1] | wide[2] | wide[3]) == 0u;
#endif
}

// The pass of J = 1 or 2 jobs of eight lane groups under the same thresholds (two slots of the
// same eight pixels): job j's lanes, fractional trials, words and weights at [j][lane]. Their
// digits are compared in one loop, which runs until both jobs are decided: each threshold's
// digit is taken once for both, the two jobs' word chains overlap, and a loop ends (a
// mispredicted branch) once for two jobs. Adds job 0's weighted counts to weighted[k][lane], then
// job 1's: the sums of two passes, in their order. Returns false, adding nothing, where a lane of
// stop_lanes still has open trials at stop_digit (the followers' leaders' pass gives up).
template <int T, int J>
__attribute__((always_inline)) static inline bool glint_multinomial_exact_lanes_pass(const uint (&c)[8][8], const uint (&full)[8][8], const uint stop_lanes[8],
                                                                                    int stop_digit, const uint (&lanes_in)[2][8], const uint (&frac_in)[2][8],
                                                                                    const uint (&state_in)[2][8], const uint (&step_in)[2][8],
                                                                                    const real (&weight_in)[2][8], const real (&frac_weight_in)[2][8],
                                                                                    real (&weighted)[8][8]) {
    typedef glint_u32x8 u32x8;
    typedef glint_i32x8 i32x8;
    typedef glint_realx8 realx8;
    u32x8 stop, threshold[8], f[8];
    std::memcpy(&stop, stop_lanes, sizeof(stop));
    for (int k = 0; k < T; ++k) std::memcpy(&threshold[k], c[k], sizeof(threshold[k])), std::memcpy(&f[k], full[k], sizeof(f[k]));
    u32x8 lanes[2], state[2], step[2], open[2][8], below[2][8];  // the first T thresholds are used
    for (int j = 0; j < J; ++j) {
        std::memcpy(&lanes[j], lanes_in[j], sizeof(lanes[j]));
        std::memcpy(&state[j], state_in[j], sizeof(state[j])), std::memcpy(&step[j], step_in[j], sizeof(step[j]));
        for (int k = 0; k < T; ++k) {
            open[j][k] = lanes[j] & ~f[k];
            below[j][k] = lanes[j] & f[k];
        }
    }
    // Two digits between the tests for open trials, as glint_multinomial_exact_all_groups_pass.
    for (int digit = 0; digit < 32; digit += 2) {
        u32x8 any = open[0][0];
        for (int j = 0; j < J; ++j)
            for (int k = 0; k < T; ++k) any |= open[j][k];
        if (glint_lanes_all_zero(any)) break;
        if (digit == stop_digit && !glint_lanes_all_zero(any & stop)) return false;
        for (int twice = 0; twice < 2; ++twice) {
            u32x8 word[2];
            for (int j = 0; j < J; ++j) {
                word[j] = state[j];
                glint_hash_u32_vector(word[j]);
                state[j] += step[j];
            }
            for (int k = 0; k < T; ++k) {
                u32x8 c_digit = (u32x8{} + 0u) - (threshold[k] >> 31u);
                threshold[k] <<= 1u;
                for (int j = 0; j < J; ++j) {
                    u32x8 decided = open[j][k] & (word[j] ^ c_digit);
                    below[j][k] |= decided & c_digit;
                    open[j][k] &= ~decided;
                }
            }
        }
    }
    for (int j = 0; j < J; ++j) {
        u32x8 frac;
        realx8 weight, frac_weight;
        std::memcpy(&frac, frac_in[j], sizeof(frac));
        std::memcpy(&weight, weight_in[j], sizeof(weight)), std::memcpy(&frac_weight, frac_weight_in[j], sizeof(frac_weight));
        u32x8 previous = {};
        for (int k = 0; k < T; ++k) {
            u32x8 in_bin = below[j][k] & ~previous;
            previous = below[j][k];
            u32x8 x = in_bin & ~frac;  // glint_bit_count lane-wise
            x = x - ((x >> 1u) & 0x55555555u);
            x = (x & 0x33333333u) + ((x >> 2u) & 0x33333333u);
            x = (x + (x >> 4u)) & 0x0f0f0f0fu;
            x = (x * 0x01010101u) >> 24u;
            i32x8 frac_in_bin = -((in_bin & frac) != 0u);
            realx8 sum;
            std::memcpy(&sum, weighted[k], sizeof(sum));
            sum += __builtin_convertvector(reinterpret_cast<i32x8>(x), realx8) * weight + __builtin_convertvector(frac_in_bin, realx8) * frac_weight;
            std::memcpy(weighted[k], &sum, sizeof(sum));
        }
    }
    return true;
}
#endif

// Where the mean-preserving draw takes glint_multinomial_exact_all: N from 4 to 63 and N total >= 1
// (the root's exact range).
GLINT_FN bool glint_multinomial_exact_all_applies(real N, real total, int variant) {
    return variant == GLINT_BINOMIAL_UNBIASED && N >= GLINT_MULTINOMIAL_EXACT_SPLIT_MIN && N <= GLINT_MULTINOMIAL_EXACT_ALL_MAX &&
           N * total >= real(1);
}

// The root of a draw that glint_multinomial_exact_all does not take (N outside 4 to 63, N total
// below 1, or a published variant): N trials drawn between the K bins (probability `total`) and
// the rest with the sampler, from the uniforms of the root's words
// (glint_multinomial_node_words(seed, 0); u1 from the first). Zeroes the counts, sets
// result.rest, and returns the bins' trials for glint_multinomial_split_nodes. Where N total >= 1
// the sampler's skip test (glint_surely_no_success on u1, grid.glsl) never fires, so a caller that
// skips roots by it skips only sampler draws that surely keep nothing. (Below N = 4 the sampler
// is exact for whole N, and for N < 2 dithers to whole counts, KK25 Fig. 4.)
GLINT_FN real glint_multinomial_root(real N, real total, uvec3 root_words, int variant, int method, GLINT_INOUT(glint_binomial_cache) root_cache,
                                     GLINT_OUT(glint_multinomial_counts) result) {
    for (int k = 0; k < 8; ++k) result.count[k] = real(0);
    N = max(N, real(0));
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
