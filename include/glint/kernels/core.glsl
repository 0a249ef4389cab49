// glint core kernels: counter-based hashing, uniform variates, erfinv and the normal quantile,
// and stable evaluations of (1-p)^N and 1-(1-p)^N.
// Single source for C++ and GLSL 4.50 (docs/conventions.md). GLSL users include prelude.glsl
// first; C++ users include <glint/core.hpp>.

// ---------------------------------------------------------------------------------------------
// Hashing.

// PCG3D: Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020. Three rounds
// of a linear congruential step and cross-multiplication of the lanes; bijective on uvec3.
// 1664525 and 1013904223 are the 32-bit LCG multiplier and increment of Numerical Recipes
// (Press et al., 2nd ed., Sec. 7.1), as that paper uses them. Bit-exact on CPU and GPU: unsigned
// arithmetic wraps modulo 2^32 in both languages.
GLINT_FN uvec3 glint_pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

#if !defined(GLINT_GLSL)
// C++ only: the vector path the kernels take (docs/conventions.md): 0 the baseline code, 1 AVX2,
// 2 AVX2 with AVX-512 F, VL, DQ and BW (GLINT_LANES_VARIANTS, kernel_begin.hpp). The paths are
// built with GCC on x86-64 unless -DGLINT_NO_AVX2; the CPU must have the features (libgcc's
// check includes the operating system's support of their registers), and
// glint::detail::lanes_limit can lower the choice.
static int glint_cpu_lanes() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
    const int cpu = !__builtin_cpu_supports("avx2") ? 0
                    : (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
                       __builtin_cpu_supports("avx512bw"))
                        ? 2
                        : 1;
    const int limit = ::glint::detail::lanes_limit.load(std::memory_order_relaxed);
    return cpu < limit ? cpu : limit;
#else
    return 0;
#endif
}
// Whether the AVX2 paths run (glint_cpu_lanes() >= 1), and their AVX-512 builds (2).
static bool glint_cpu_avx2() { return glint_cpu_lanes() >= 1; }
static bool glint_cpu_avx512() { return glint_cpu_lanes() >= 2; }

// C++ only: glint_hash_u32 lane-wise on a vector of words, in place (any vector width of GCC's
// and Clang's vector extension; in place, as glint_pcg3d_vectors, since a wide vector returned by
// value from code built for the baseline changes the ABI): the same words, bit for bit.
template <class V>
__attribute__((always_inline)) static inline void glint_hash_u32_vector(V& x) {
    glint_hash_u32_first_step(x);  // below
    glint_hash_u32_vector_rest(x);
}

// C++ only: glint_hash_u32 of a ^ b for many pairs, its first step taken into the operands. That
// step, x ^ x >> 16, is linear over XOR: (a ^ b) ^ (a ^ b) >> 16 = (a ^ a >> 16) ^ (b ^ b >> 16). So
// where each word meets several others (the grid's skip tests: every vertex word against every
// slope-corner key), each operand takes the step once (glint_hash_u32_first_step, in place) and
// the hash of a pair is glint_hash_u32_vector_rest of their XOR: two operations fewer a pair, the
// same words bit for bit.
template <class V>
__attribute__((always_inline)) static inline void glint_hash_u32_first_step(V& x) {
    x ^= x >> 16u;
}
template <class V>
__attribute__((always_inline)) static inline void glint_hash_u32_vector_rest(V& x) {
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
}

// C++ only: eight values held as two vectors of four (value 4 h + i in lane i of v[h]) scaled
// down by their total where it is above 1, into out, as the GLSL loops of glint_ibl_probabilities
// and glint_multinomial_tree_root do it: the total summed in index order, which a float sum must
// keep. Returns the scale (1 or 1 / total) and the total in `total`.
template <class V>
__attribute__((always_inline)) static inline real glint_scale_to_unit_sum(const V v[2], real out[8], real& total) {
    total = real(0);
    for (int k = 0; k < 8; ++k) total += v[k >> 2][k & 3];
    const real scale = (total > real(1)) ? real(1) / total : real(1);
    for (int h = 0; h < 2; ++h) {
        const V scaled = v[h] * scale;
        std::memcpy(out + 4 * h, &scaled, sizeof(scaled));
    }
    return scale;
}

// C++ only: glint_pcg3d lane-wise on three vectors of words (any vector width of GCC's and
// Clang's vector extension): the same words, bit for bit (unsigned arithmetic wraps alike).
template <class V>
__attribute__((always_inline)) static inline void glint_pcg3d_vectors(V& x, V& y, V& z) {
    x = x * 1664525u + 1013904223u;
    y = y * 1664525u + 1013904223u;
    z = z * 1664525u + 1013904223u;
    x += y * z;
    y += z * x;
    z += x * y;
    x ^= x >> 16u;
    y ^= y >> 16u;
    z ^= z >> 16u;
    x += y * z;
    y += z * x;
    z += x * y;
}
// C++ only: glint_pcg3d of the words (x[i], y[i], z[i]), i < count <= 12, into (hx[i], hy[i],
// hz[i]) (and of others up to the end of their block of W or of the twelve), W at once in vector
// registers (tests/unit/test_hash.cpp compares them with glint_pcg3d). The IBL's multinomial roots
// hash a pixel's twelve vertex words (ibl.glsl; the grid hashes its vertices with their triangles,
// grid.glsl's glint_lattice_vertex_hashes); one at a time, their 32-bit multiplies lie in one
// chain per word. Three arrays, as glint_grid_vertices holds the words, read in place: lanes
// loaded whole (an array of uvec3 was gathered lane by lane), from words not just stored one by
// one (a vector load of those waits for the stores).
template <int W>
__attribute__((always_inline)) static inline void glint_pcg3d_lanes(const uint x[12], const uint y[12], const uint z[12], int count, uint hx[12],
                                                                   uint hy[12], uint hz[12]) {
    typedef uint u32x4 __attribute__((vector_size(16)));
    typedef uint u32x8 __attribute__((vector_size(32)));
    typedef typename std::conditional<W == 8, u32x8, u32x4>::type u32xw;
    // Whole blocks of W, and the last four of twelve in a vector of four: loads and stores of
    // constant size.
    int base = 0;
    for (; base + W <= 12 && base < count; base += W) {
        u32xw vx, vy, vz;
        std::memcpy(&vx, x + base, sizeof(vx)), std::memcpy(&vy, y + base, sizeof(vy)), std::memcpy(&vz, z + base, sizeof(vz));
        glint_pcg3d_vectors(vx, vy, vz);
        std::memcpy(hx + base, &vx, sizeof(vx)), std::memcpy(hy + base, &vy, sizeof(vy)), std::memcpy(hz + base, &vz, sizeof(vz));
    }
    if (base < count) {  // W = 8: words 8 .. 11
        u32x4 vx, vy, vz;
        std::memcpy(&vx, x + base, sizeof(vx)), std::memcpy(&vy, y + base, sizeof(vy)), std::memcpy(&vz, z + base, sizeof(vz));
        glint_pcg3d_vectors(vx, vy, vz);
        std::memcpy(hx + base, &vx, sizeof(vx)), std::memcpy(hy + base, &vy, sizeof(vy)), std::memcpy(hz + base, &vz, sizeof(vz));
    }
}

// Eight at a time in AVX2 registers, where the CPU has them (glint_cpu_avx2); one at a time
// otherwise: SSE2, the baseline, emulates a four-wide 32-bit multiply in about six instructions,
// and four at a time there cost more than it saved (-DGLINT_NO_AVX2: glint_frame_loop ibl 4 1's
// estimates 33.4M to 35.1M instructions; a K = 4 IBL frame 3965 against 4202 us, least of four
// alternating runs, this 2-core AMD EPYC, CPU).
GLINT_LANES_BODY
void glint_pcg3d_many_x8_body(const uint x[12], const uint y[12], const uint z[12], int count, uint hx[12], uint hy[12], uint hz[12]) {
    glint_pcg3d_lanes<8>(x, y, z, count, hx, hy, hz);
}
GLINT_LANES_VARIANTS(void, glint_pcg3d_many_x8,
                     (const uint x[12], const uint y[12], const uint z[12], int count, uint hx[12], uint hy[12], uint hz[12]),
                     (x, y, z, count, hx, hy, hz))

GLINT_FN void glint_pcg3d_many(const uint x[12], const uint y[12], const uint z[12], int count, uint hx[12], uint hy[12], uint hz[12]) {
    if (glint_cpu_avx2()) {
        glint_pcg3d_many_x8(x, y, z, count, hx, hy, hz);
        return;
    }
    for (int i = 0; i < 12; ++i)
        if (i < count) {
            uvec3 h = glint_pcg3d(uvec3(x[i], y[i], z[i]));
            hx[i] = h.x, hy[i] = h.y, hz[i] = h.z;
        }
}
#endif

// A 32-bit finaliser: Wellons' "lowbias32" (https://nullprogram.com/blog/2018/07/31/, the
// constants found by his hash-prospector search; its avalanche bias, his measure, 0.17 against
// 0.26 for MurmurHash3's finaliser). Two multiplies against PCG3D's twelve, for one word where
// one uniform decides (grid.glsl's per slope cell draws). In C++ a loop of them over an array
// vectorises (grid.glsl's glint_skip_test_masks); the four-wide version it replaced, kept out of
// line by GCC, cost 31 instructions a call.
GLINT_FN uint glint_hash_u32(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// floor(x) for |x| <= 2^30 (the callers clamp or bound x): GLSL's floor; in C++ a truncation to
// int and a correction, because without SSE4.1 (the default x86-64 target) GCC expands std::floor
// inline into about 20 instructions, or calls libm. Exact: int(x) truncates toward zero, and
// every integer up to 2^30 is a float.
GLINT_FN real glint_floor_bounded(real x) {
#if defined(GLINT_GLSL)
    return floor(x);
#else
    real t = real(int(x));
    return (t > x) ? t - real(1) : t;
#endif
}

GLINT_FN vec2 glint_floor_bounded(vec2 x) {
    return vec2(glint_floor_bounded(x.x), glint_floor_bounded(x.y));
}

// |x|: GLSL's abs; in C++ std::fabs, one bitwise and, where GLM's abs compares and branches.
GLINT_FN real glint_abs(real x) {
#if defined(GLINT_GLSL)
    return abs(x);
#else
    return std::fabs(x);
#endif
}

// The number of bits set in x: GLSL's bitCount; in C++ the same sum of bit fields in 12
// instructions, inline (GLM's bitCount loops over masks, and GCC's __builtin_popcount without
// -mpopcnt calls libgcc: 21 instructions and a call).
GLINT_FN int glint_bit_count(uint x) {
#if defined(GLINT_GLSL)
    return bitCount(x);
#else
    x = x - ((x >> 1u) & 0x55555555u);                 // 2-bit sums
    x = (x & 0x33333333u) + ((x >> 2u) & 0x33333333u);  // 4-bit sums
    x = (x + (x >> 4u)) & 0x0f0f0f0fu;                 // byte sums
    return int((x * 0x01010101u) >> 24u);              // their total, in the top byte
#endif
}

// 2^n for n from -126 to 127, exact, without a libm call (ldexp and exp2 cost one each in C++):
// the float whose exponent field is n + 127 and whose mantissa is 0. (A division for n < 0 cost 78
// of the point-light frame's instructions per glinty pixel.)
GLINT_FN real glint_exp2_int(int n) {
    return real(uintBitsToFloat(uint(n + 127) << 23u));
}

// A uniform variate in [0, 1) from the top 24 bits of a hash: k * 2^-24, exact in float.
GLINT_FN real glint_unit_from_bits(uint h) {
    return real(h >> 8u) * real(5.9604644775390625e-8);  // 2^-24
}

// A uniform variate in the open interval (0, 1) from the top 23 bits of a hash:
// (2k + 1) * 2^-24, k < 2^23, so values run from 2^-24 to 1 - 2^-24 and are exact in float.
// Use it where 0 or 1 would be a singular input (quantiles, logarithms).
GLINT_FN real glint_open_unit_from_bits(uint h) {
    return real(((h >> 9u) << 1u) | 1u) * real(5.9604644775390625e-8);  // 2^-24
}

// ---------------------------------------------------------------------------------------------
// erfinv and the normal quantile.

// The polynomial of Giles' single-precision erfinv ("Approximating the erfinv function", GPU
// Computing Gems Jade Ed., 2011), in w = -log(1 - x^2). The central branch (w < 5) is a degree-8
// polynomial in w - 2.5, the tail branch a degree-8 polynomial in sqrt(w) - 3, fitted by Giles
// for single precision and covering w <= 16.0, i.e. every float x in (-1, 1). The coefficients
// are Giles' published digits. erfinv(x) = x * glint_erfinv_poly(w). Measured accuracy in
// docs/core_numerics.md.
GLINT_FN real glint_erfinv_poly(real w) {
    real p;
    if (w < real(5)) {
        real t = w - real(2.5);
        p = real(2.81022636e-08);
        p = real(3.43273939e-07) + p * t;
        p = real(-3.5233877e-06) + p * t;
        p = real(-4.39150654e-06) + p * t;
        p = real(0.00021858087) + p * t;
        p = real(-0.00125372503) + p * t;
        p = real(-0.00417768164) + p * t;
        p = real(0.246640727) + p * t;
        p = real(1.50140941) + p * t;
    } else {
        real t = sqrt(w) - real(3);
        p = real(-0.000200214257);
        p = real(0.000100950558) + p * t;
        p = real(0.00134934322) + p * t;
        p = real(-0.00367342844) + p * t;
        p = real(0.00573950773) + p * t;
        p = real(-0.0076224613) + p * t;
        p = real(0.00943887047) + p * t;
        p = real(1.00167406) + p * t;
        p = real(2.83297682) + p * t;
    }
    return p;
}

// The inverse error function. Domain (-1, 1); |x| is clamped to 1 - 2^-24 (the largest float
// below 1), so +-1 and beyond return +-erfinv(1 - 2^-24) = +-3.8325. NaN in, NaN out.
GLINT_FN real glint_erfinv(real x) {
    real a = min(abs(x), real(0.999999940395355224609375));  // 1 - 2^-24
    // (1 - a)(1 + a) rather than 1 - a^2: 1 - a is exact for a >= 0.5, which keeps w accurate
    // in the tail where it matters.
    real w = -log((real(1) - a) * (real(1) + a));
    return sign(x) * a * glint_erfinv_poly(w);
}

// The standard normal quantile Phi^-1(u) = sqrt(2) erfinv(2u - 1), evaluated without forming
// 2u - 1 in the tails: with t = min(u, 1 - u) (exact in float), 1 - x^2 = 4 t (1 - t), so w keeps
// full relative precision down to t = 2^-25. Domain (0, 1); t is clamped to [2^-25, 0.5], so
// u <= 2^-25 returns Phi^-1(2^-25) = -5.4200 and u >= 1 - 2^-25 returns +5.4200.
GLINT_FN real glint_normal_quantile(real u) {
    real t = clamp(min(u, real(1) - u), real(2.98023223876953125e-8), real(0.5));  // 2^-25
    real w = -log(real(4) * t * (real(1) - t));
    real x = real(1) - real(2) * t;  // |2u - 1|
    real s = (u < real(0.5)) ? real(-1) : real(1);
    // sqrt(2) to 17 significant digits.
    return s * real(1.4142135623730951) * x * glint_erfinv_poly(w);
}

// erfc(x), Numerical Recipes' Chebyshev fit "erfcc" (Press et al., Numerical Recipes in C, 2nd
// ed., 1992, Sec. 6.2; coefficients as printed there): relative error below 1.2e-7 for all x,
// measured 1.07e-7 in double (docs/core_numerics.md). One exp.
GLINT_FN real glint_erfcc_series(real t) {
    real r = real(0.17087277);
    r = real(-0.82215223) + t * r;
    r = real(1.48851587) + t * r;
    r = real(-1.13520398) + t * r;
    r = real(0.27886807) + t * r;
    r = real(-0.18628806) + t * r;
    r = real(0.09678418) + t * r;
    r = real(0.37409196) + t * r;
    r = real(1.00002368) + t * r;
    return real(-1.26551223) + t * r;
}

GLINT_FN real glint_erfc(real x) {
    real z = abs(x);
    real t = real(1) / (real(1) + real(0.5) * z);
    real e = t * exp(-z * z + glint_erfcc_series(t));
    return (x >= real(0)) ? e : real(2) - e;
}

// The scaled complement erfcx(z) = exp(z^2) erfc(z) for z >= 0, from the same fit (relative error
// below 1.2e-7), taking y = 1/z so that z = inf (y = 0, erfcx = 0) needs no division by zero.
GLINT_FN real glint_erfcx_of_reciprocal(real y) {
    y = max(y, real(0));
    real t = real(2) * y / (real(2) * y + real(1));  // 1 / (1 + z/2)
    return t * exp(glint_erfcc_series(t));
}

// The standard normal CDF Phi(t) = erfc(-t / sqrt(2)) / 2, with erfc's relative accuracy in the
// lower tail.
GLINT_FN real glint_normal_cdf(real t) {
    return real(0.5) * glint_erfc(t * real(-0.707106781186547524401));  // -1/sqrt(2), 21 digits
}

// The standard normal density.
GLINT_FN real glint_normal_pdf(real t) {
    return real(0.398942280401432677940) * exp(real(-0.5) * t * t);  // 1/sqrt(2 pi), 21 digits
}

// ---------------------------------------------------------------------------------------------
// log1p and expm1, which GLSL lacks. Neither relies on the builtin log, whose GLSL precision is
// only an absolute 2^-21 on [0.5, 2] (GLSL 4.50 spec, Sec. 4.7.1) and which Mesa llvmpipe meets
// with 2e5 ulp of relative error just below 1 (docs/conventions.md), so the identities
// log1p(x) = log(u) x / (u - 1) and expm1(x) = (u - 1) x / log(u) fail on the GPU.

// Smallest normal float, 2^-126.
GLINT_CONST(real) GLINT_FLT_MIN_NORMAL = real(1.17549435082228750797e-38);

// The logarithms' shared core, for a normal u > 0: u = m 2^e with m in [sqrt(1/2), sqrt(2)), and
// log(m) = 2 atanh(s), s = (m - 1)/(m + 1), |s| <= 0.1716, by its Taylor series in z = s^2 <=
// 0.0295, truncated after z^6 in float and z^11 in double (relative truncation error below
// z^12 / 25 = 1.7e-20): returns (s, t) with log(m) = 2 s t, and e.
GLINT_FN vec2 glint_log_reduced(real u, GLINT_OUT(int) e) {
    real m = frexp(u, e);  // u = m 2^e, m in [0.5, 1)
    bool low = m < real(0.70710678118654752440);  // sqrt(1/2) to 21 digits
    m = low ? real(2) * m : m;
    e = low ? e - 1 : e;
    real f = m - real(1);  // exact (Sterbenz)
    real s = f / (real(2) + f);
    real z = s * s;
    // Float needs the terms up to z^6 (truncation below z^7 / 15 = 1.3e-12); double up to z^11.
    real t = real(1) / real(13);
    if (GLINT_DOUBLE) {
        t = real(1) / real(23);
        t = real(1) / real(21) + z * t;
        t = real(1) / real(19) + z * t;
        t = real(1) / real(17) + z * t;
        t = real(1) / real(15) + z * t;
        t = real(1) / real(13) + z * t;
    }
    t = real(1) / real(11) + z * t;
    t = real(1) / real(9) + z * t;
    t = real(1) / real(7) + z * t;
    t = real(1) / real(5) + z * t;
    t = real(1) / real(3) + z * t;
    t = real(1) + z * t;
    return vec2(s, t);
}

// log(1 + x). Domain x > -1; x <= -1 returns log(2^-126) = -87.34. glint_log_reduced on 1 + x,
// whose rounding error is added back to first order. Measured error in docs/core_numerics.md.
GLINT_FN real glint_log1p(real x) {
    x = max(x, real(-1));
    GLINT_PRECISE real u = max(real(1) + x, GLINT_FLT_MIN_NORMAL);
    GLINT_PRECISE real c = (x - (u - real(1))) / u;  // 1 + x = u (1 + c)
    int e;
    vec2 st = glint_log_reduced(u, e);
    // ln 2 to 21 digits.
    return real(e) * real(0.693147180559945309417) + (real(2) * st.x * st.y + c);
}

// log2(x) for x > 0, with x clamped to [2^-126, FLT_MAX] (0, a subnormal or a negative x gives
// -126, +inf gives 128; NaN stays NaN): glint_log_reduced, times 2 / ln 2. Its own, not the
// builtin, for the same reason as glint_atan2: the same bits in C++ and GLSL (whose log2 has no
// stated precision near 1) and, written with operations that vector lanes have too, the same bits
// in the lanes of ibl.glsl's glint_ibl_sample_pixels as in glint_footprint_lattice. Error: five
// roundings (2 + f, the division, s t, the constant and its product) of at most 2^-24 relative
// each, at most 5 ulp of the result; the series' terms add less than 0.02 ulp. Measured in
// tests/unit/test_pow_one_minus.cpp (3.0 ulp).
GLINT_FN real glint_log2(real x) {
    x = min(max(x, GLINT_FLT_MIN_NORMAL), real(3.40282346638528859812e38));  // FLT_MAX, (2 - 2^-23) 2^127
    int e;
    vec2 st = glint_log_reduced(x, e);
    // 2 / ln 2 to 21 digits; precise, or Mesa regroups the product (1 ulp apart from C++).
    GLINT_PRECISE real r = real(e) + real(2.88539008177792681472) * (st.x * st.y);
    return r;
}

// exp(x) - 1 for x <= 0 (the only use here; x > 0 is treated as 0). For |x| < ln(2)/2 the
// Taylor series truncated after x^14/14! (relative truncation error below
// 0.347^14 / 15! = 3e-19); below that, exp(x) - 1, where the result is at most -0.29 and the
// subtraction loses nothing.
GLINT_FN real glint_expm1_nonpositive(real x) {
    x = min(x, real(0));
    // Horner form of x (1 + x/2 (1 + x/3 (... (1 + x/n)))), n = 9 in float (truncation below
    // 0.347^9 / 10! = 2.0e-11), 14 in double; the reciprocals fold at compile time.
    real t = real(1) + x * (real(1) / real(9));
    if (GLINT_DOUBLE) {
        t = real(1) + x * (real(1) / real(14));
        t = real(1) + x * (real(1) / real(13)) * t;
        t = real(1) + x * (real(1) / real(12)) * t;
        t = real(1) + x * (real(1) / real(11)) * t;
        t = real(1) + x * (real(1) / real(10)) * t;
        t = real(1) + x * (real(1) / real(9)) * t;
    }
    t = real(1) + x * (real(1) / real(8)) * t;
    t = real(1) + x * (real(1) / real(7)) * t;
    t = real(1) + x * (real(1) / real(6)) * t;
    t = real(1) + x * (real(1) / real(5)) * t;
    t = real(1) + x * (real(1) / real(4)) * t;
    t = real(1) + x * (real(1) / real(3)) * t;
    t = real(1) + x * real(0.5) * t;
    // ln(2)/2 to 21 digits.
    return (x > real(-0.346573590279972654709)) ? x * t : exp(x) - real(1);
}

// ---------------------------------------------------------------------------------------------
// (1 - p)^N: the probability that N Bernoulli(p) trials all fail, and its complement
// P(n >= 1) = 1 - (1 - p)^N. Domain p in [0, 1], N in [0, inf); p is clamped to [0, 1] and N to
// [0, inf). Three evaluations, measured against each other in docs/pow_one_minus.md.

// KK25 Eq. 25: epsilon = 10^-3.54, KK25 Sec. 6, found optimal for float by the authors.
GLINT_CONST(real) GLINT_KK25_EPSILON = real(2.8840315031266059e-4);  // 10^-3.54 = 2.88403150312660594e-4 (40-digit decimal)

// pow(1 - p, N) as written. In float it rounds 1 - p to 1 for p < 2^-25 (KK25 Fig. 5b).
GLINT_FN real glint_pow_one_minus_naive(real p, real N) {
    p = clamp(p, real(0), real(1));
    N = max(N, real(0));
    // pow(0, 0) is undefined in GLSL; the limit used here is 1.
    return (N == real(0)) ? real(1) : pow(real(1) - p, N);
}

// KK25 Eq. 25: (1 - c p)^(N / c) with c = max(1, epsilon / p). Biased by the dropped O(p^2)
// terms of Eq. 24 for p < epsilon; see docs/pow_one_minus.md for the measured error.
GLINT_FN real glint_pow_one_minus_kk25(real p, real N) {
    p = clamp(p, real(0), real(1));
    N = max(N, real(0));
    real c = max(real(1), GLINT_KK25_EPSILON / max(p, GLINT_FLT_MIN_NORMAL));  // finite for p = 0
    return (N == real(0)) ? real(1) : pow(real(1) - c * p, N / c);
}

// exp(N log1p(-p)): exact up to the rounding of log1p, the product and exp.
GLINT_FN real glint_pow_one_minus_log1p(real p, real N) {
    p = clamp(p, real(0), real(1));
    N = max(N, real(0));
    real q = (p < real(1)) ? p : real(0);  // keeps log finite; p = 1 is selected below
    real r = exp(N * glint_log1p(-q));
    return (p < real(1)) ? r : ((N > real(0)) ? real(0) : real(1));
}

// P(n >= 1) = 1 - pow(1 - p, N) as written.
GLINT_FN real glint_any_success_naive(real p, real N) {
    return real(1) - glint_pow_one_minus_naive(p, N);
}

// P(n >= 1) = 1 - (1 - p)^N as KK25 evaluates it: one minus Eq. 25.
GLINT_FN real glint_any_success_kk25(real p, real N) {
    return real(1) - glint_pow_one_minus_kk25(p, N);
}

// P(n >= 1) = -expm1(N log1p(-p)): keeps full relative precision when N p is small.
GLINT_FN real glint_any_success_expm1(real p, real N) {
    p = clamp(p, real(0), real(1));
    N = max(N, real(0));
    real q = (p < real(1)) ? p : real(0);
    real r = -glint_expm1_nonpositive(N * glint_log1p(-q));
    return (p < real(1)) ? r : ((N > real(0)) ? real(1) : real(0));
}

// Method codes for the (1 - p)^N evaluation, as in glint::pow_method.
GLINT_CONST(int) GLINT_POW_NAIVE = 0;
GLINT_CONST(int) GLINT_POW_KK25 = 1;
GLINT_CONST(int) GLINT_POW_LOG1P = 2;

// (1 - p)^N by the chosen method (GLINT_POW_*); an unknown code means GLINT_POW_LOG1P.
GLINT_FN real glint_pow_one_minus(real p, real N, int method) {
    if (method == GLINT_POW_NAIVE) return glint_pow_one_minus_naive(p, N);
    if (method == GLINT_POW_KK25) return glint_pow_one_minus_kk25(p, N);
    return glint_pow_one_minus_log1p(p, N);
}

// 1 - (1 - p)^N by the chosen method; GLINT_POW_LOG1P means -expm1(N log1p(-p)).
GLINT_FN real glint_any_success(real p, real N, int method) {
    if (method == GLINT_POW_NAIVE) return glint_any_success_naive(p, N);
    if (method == GLINT_POW_KK25) return glint_any_success_kk25(p, N);
    return glint_any_success_expm1(p, N);
}

// ---------------------------------------------------------------------------------------------
// atan2 and acos to a few ulp. GLSL leaves the precision of its atan and acos undefined (4.50,
// Sec. 4.7.1), and Mesa llvmpipe's are up to 5e-5 off in the equirectangular uv they give
// (docs/conventions.md): a texel's hundredth on a 256-wide map, enough to move an environment
// lookup by 1e-3. These use only arithmetic, division and sqrt.

GLINT_CONST(real) GLINT_PI = real(3.14159265358979323846);  // 21 digits
GLINT_CONST(real) GLINT_INV_TWO_PI = real(0.159154943091895335769);  // 1 / (2 pi), 21 digits

// atan(t) for |t| <= tan(pi / 12) = 0.268: its Taylor series t sum_k (-1)^k t^2k / (2k + 1) in
// Horner form, whose terms fall by t^2 <= 0.0718 each; truncated after k = 6 in float (error below
// 0.0718^7 / 15 = 6e-10 relative) and after k = 13 in double (below 0.0718^14 / 29 = 3e-18).
GLINT_FN real glint_atan_reduced(real t) {
    real z = t * t;
    real sum = real(0);
    if (GLINT_DOUBLE) {
        sum = real(1) / real(27) - z * sum;
        sum = real(1) / real(25) - z * sum;
        sum = real(1) / real(23) - z * sum;
        sum = real(1) / real(21) - z * sum;
        sum = real(1) / real(19) - z * sum;
        sum = real(1) / real(17) - z * sum;
        sum = real(1) / real(15) - z * sum;
    }
    sum = real(1) / real(13) - z * sum;
    sum = real(1) / real(11) - z * sum;
    sum = real(1) / real(9) - z * sum;
    sum = real(1) / real(7) - z * sum;
    sum = real(1) / real(5) - z * sum;
    sum = real(1) / real(3) - z * sum;
    sum = real(1) - z * sum;
    return t * sum;
}

// atan2(y, x) in [-pi, pi]; 0 for (0, 0) and for non-finite input. The ratio of the smaller to
// the larger magnitude, t in [0, 1], is reduced to |t'| <= tan(pi / 12) by
// atan(t) = pi / 6 + atan((t - c) / (1 + t c)), c = 1 / sqrt(3), where t > tan(pi / 12); then the
// octant and quadrant by atan(1 / t) = pi / 2 - atan(t) and the signs. Measured error in
// tests/glsl/test_core_parity.cpp.
GLINT_FN real glint_atan2(real y, real x) {
    real ax = abs(x), ay = abs(y);
    real hi = max(ax, ay), lo = min(ax, ay);
    if (!(hi > real(0)) || !(hi < real(3.4e38))) return real(0);
    real t = lo / hi;
    // One series, on t or on its reduction, selected: the choice is a coin toss per pixel, and
    // where t > tan(pi / 12) the series was computed for t and then again for the reduction, twice
    // the latency on the point-light frame's footprint.
    bool reduce = t > real(0.267949192431122706473);  // tan(pi / 12) = 2 - sqrt(3), 21 digits
    real c = real(0.577350269189625764509);           // 1 / sqrt(3), 21 digits
    real r = reduce ? (t - c) / (real(1) + t * c) : t;
    real a = (reduce ? GLINT_PI / real(6) : real(0)) + glint_atan_reduced(r);
    if (ay > ax) a = GLINT_PI / real(2) - a;
    if (x < real(0)) a = GLINT_PI - a;
    return (y < real(0)) ? -a : a;
}

// acos(x) = atan2(sqrt((1 - x)(1 + x)), x), x clamped to [-1, 1] (the product keeps 1 - x^2's
// precision near |x| = 1).
GLINT_FN real glint_acos(real x) {
    real c = clamp(x, real(-1), real(1));
    return glint_atan2(sqrt((real(1) - c) * (real(1) + c)), c);
}
