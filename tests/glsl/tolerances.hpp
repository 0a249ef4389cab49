// The CPU-versus-llvmpipe tolerance table (docs/conventions.md): for each transcendental
// kernel, the largest distance between the GLSL and the C++ float result measured on the parity
// inputs (Mesa 22.3 llvmpipe, Debian 12), and the bound on the GLSL result's own error. Integer
// kernels (hashes, uniform variates) must match exactly and have no entry.
#pragma once
#include <cstdint>

// erfinv: builtin log and sqrt differ from glibc's; measured 2 ulp apart, GLSL 3.37 ulp from
// exact, within the C++ bound of 3.4.
constexpr std::int64_t ERFINV_GLSL_MAX_ULP_DISTANCE = 2;
constexpr double ERFINV_GLSL_MAX_ULP_EXACT = 3.4;
// normal_quantile: measured 4 ulp apart, GLSL 4.30 ulp from exact, within the C++ bound of 4.6.
constexpr std::int64_t QUANTILE_GLSL_MAX_ULP_DISTANCE = 4;
constexpr double QUANTILE_GLSL_MAX_ULP_EXACT = 4.6;
// log1p uses no builtin but frexp (exact): bit-identical.
constexpr std::int64_t LOG1P_GLSL_MAX_ULP_DISTANCE = 0;
constexpr double LOG1P_GLSL_MAX_ULP_EXACT = 3.3;
// log2, the same operations (its last sum declared precise): bit-identical, and within the C++
// bound from exact (5 ulp; measured 3.05).
constexpr std::int64_t LOG2_GLSL_MAX_ULP_DISTANCE = 0;
constexpr double LOG2_GLSL_MAX_ULP_EXACT = 5;
// expm1 uses the builtin exp below -ln(2)/2: measured 6 ulp apart and 5.66 ulp from exact.
constexpr std::int64_t EXPM1_GLSL_MAX_ULP_DISTANCE = 6;
constexpr double EXPM1_GLSL_MAX_ULP_EXACT = 6;
// exp(N log1p(-p)): the GLSL 4.50 spec allows exp (3 + 2|x|) ulp; with |x| <= 69 on the grid
// (results >= 1e-30) that is 141 ulp = 8.4e-6 relative. Measured: 1.8e-7 absolute from C++,
// 6.8e-6 relative from exact.
constexpr double POW_LOG1P_GLSL_MAX_ABS_DIFFERENCE = 2e-7;
constexpr double POW_LOG1P_GLSL_MAX_REL_EXACT = 1e-5;
// -expm1(N log1p(-p)): measured 4.3e-7 relative from exact (below 8 ulp).
constexpr double ANY_SUCCESS_EXPM1_GLSL_MAX_REL_EXACT = 5e-7;
// Binomial and multinomial samplers (test_binomial_parity.cpp): a count agrees when it is
// within 1e-4 of max(N, 1) of the C++ one (builtin exp, log, pow and sqrt differ by a few ulp and
// the small-N middle's Newton refinement and erfc amplify that: measured up to 1.7e-5 in the K = 8
// hierarchy); the share that does not (a discrete decision flipped by an input within a few ulp
// of its threshold, about 1e-6 per gate) is bounded. Measured: 0 of 165376 per variant and of
// 589824 per K.
constexpr double BINOMIAL_GLSL_AGREEMENT = 1e-4;
constexpr double BINOMIAL_GLSL_MAX_FLIP_RATE = 1e-4;
// atan2 and acos (core.glsl) use arithmetic, division and sqrt, which llvmpipe rounds as IEEE
// does: bit-identical (measured: 0 ulp apart on 80007 inputs). From exact: the reduced argument's
// rounding (about 2 ulp of it) plus half an ulp for each of up to three additions (pi / 6 + a,
// pi / 2 - a, pi - a): 3.5 ulp. Measured: 2.6 ulp.
constexpr std::int64_t ATAN2_GLSL_MAX_ULP_DISTANCE = 0;
constexpr double ATAN2_GLSL_MAX_ULP_EXACT = 3.5;
// erfc on [-4, 9]: the builtin exp of an argument down to -82 may be off by 3 + 2|x| = 167 ulp
// (GLSL 4.50 spec); on top of the C++ bound of 8e-6 that is 8e-6 + 167 * 2^-24 = 1.8e-5.
// Measured: 64 ulp apart (64% of inputs differ), 1.1e-5 from exact.
constexpr std::int64_t ERFC_GLSL_MAX_ULP_DISTANCE = 167;
constexpr double ERFC_GLSL_MAX_RELATIVE_EXACT = 1.8e-5;
// Microfacet kernels (test_grid_parity.cpp): Beckmann's D and Lambda take exp of arguments down
// to -100, which GLSL may compute (3 + 2|x|) ulp off (GLSL 4.50, Sec. 4.7.1): 203 ulp = 1.2e-5
// relative, and Lambda's y / sqrt(pi) - erfcx(1/y) amplifies that up to about 3x. Measured: D and
// the visible NDF 2.6e-5, Lambda 3.5e-5, G2 and D_H 2.7e-7, Fresnel and the VNDF sample (absolute,
// values in [-1, 1]) below 1e-6.
constexpr double MICROFACET_GLSL_MAX_RELATIVE = 1e-4;
// D_Omega: in float the standardized slope u = (wi + wo).xy / ((wi + wo).z alpha) amplifies one
// ulp of wi by 1 / (alpha (wi + wo).z); the parity inputs reach alpha = 0.004 at views of 87
// degrees (amplification ~5e3), and the two sides' cos, sin and sqrt differ by an ulp. Relative to
// the result, or to 1e-6 below that. Measured: cones 6.0e-4, rectangles 3.1e-4.
constexpr double D_OMEGA_GLSL_MAX_RELATIVE = 1e-3;
// The grid estimate R: agrees when within 1e-3 of max(R, E[R]); the share that does not (one of
// its 12 to 48 binomial draws flipped at a gate by a few ulp, or the ungated sampler's clamp at 0
// cancelling) is bounded. Measured over 20000 estimates per variant: 0.03% (mean-preserving)
// to 0.26% (DB23).
constexpr double GRID_GLSL_AGREEMENT = 1e-3;
constexpr double GRID_GLSL_MAX_FLIP_RATE = 1e-2;
// OpenGL's GL_LINEAR against glint_bilinear, as a fraction of the texel values' range (the GL
// specification leaves the weights' precision to the implementation; llvmpipe computes them in
// float). Measured over 50000 lookups: 3.6e-6.
constexpr double IBL_FILTER_GLSL_MAX_ABSOLUTE = 1e-5;
// glint_equirect_direction goes through the builtin sin and cos (GLSL 4.50 leaves their precision
// undefined, Sec. 4.7.1), glint_equirect_uv through glint_atan2 and glint_acos (bit-identical, see
// above). Measured: 2.4e-7 in the direction and the uv computed from it; with the builtin atan and
// acos in glint_equirect_uv the uv was 5.0e-5 off, which this bound rejects.
constexpr double IBL_EQUIRECT_GLSL_MAX_ABSOLUTE = 1e-6;
// Gaussian elements (test_gaussian_parity.cpp): a term is exp(-(m + q) / 2) times a norm, its
// exponent up to about 87 before the term is 0; GLSL 4.50 allows exp (3 + 2|x|) ulp, 177 ulp =
// 1.1e-5, plus a few ulp of sqrt and division, so 2e-5 relative. The direct P-NDF is a sum of such
// terms, compared with a floor of 1e-3 (1e-6 of a peak density): the same bound, and no value
// beyond 1e-3 relative allowed (rate 0). Measured: element term 8.6e-6, marginal 1.1e-5, BRDF 5.3e-7;
// the direct P-NDF 1.4e-6 over 4000 queries, none beyond 1e-3.
constexpr double GAUSSIAN_GLSL_MAX_RELATIVE = 2e-5;
constexpr double PNDF_GLSL_MAX_RELATIVE = 2e-5;
constexpr double PNDF_GLSL_MAX_MISMATCH_RATE = 0.0;
// Scratches (test_scratch_parity.cpp). Cone coordinates go through glint_atan2 (bit-identical) but
// dot products and sqrt round by an ulp either side, which phi amplifies near the poles w = +-u;
// from_cone through the builtin sin and cos. Measured over 20000 inputs: 2.8e-6 absolute in
// (theta, phi), 3.3e-7 in from_cone. Eq. 2's pow and the light kernel's sin/cos/weights differ by
// ulps; the share of results beyond 1e-4 (table reads) or 1e-3 (sampler, light) relative, and of
// flipped decisions (validity, light cull, indicator), is bounded. Measured: rho 7.5e-5 at most
// (none beyond), sample weight 6.5e-6, pdf 7.0e-5, point light 4.5e-4 of values beyond 1e-3
// (worst 2.6e-3, at the kernel's edge where its weight is near 0), no light-cull flip in 20000.
constexpr double SCRATCH_CONE_GLSL_MAX_ABSOLUTE = 1e-5;
constexpr double SCRATCH_GLSL_MAX_FLIP_RATE = 1e-3;
// NDF maps (test_ndf_map_parity.cpp). The P-NDF is a normalised sum of bilinear lookups weighted
// by exp of Mahalanobis distances (GLSL's exp: (3 + 2|x|) ulp, 1.1e-5 at the taper's edge), plus
// the element path's terms (GAUSSIAN_GLSL_MAX_RELATIVE): differences of a few 1e-5 of the map's
// peak density, so 1e-4 of the peak. Decisions (a tile centre's owner, a level's floor, the hard
// tile cap) take the same branches but for inputs within rounding of a boundary, where a value or
// a draw may change: the share beyond 1e-3 of the peak (or a draw moved by more than 1e-4 in s)
// is bounded by 1e-3. Measured: 8.4e-8 (tiled), 1.9e-7 (sheared), 1.5e-7 (stochastic) of the peak,
// none beyond 1e-3; no draw moved; owners and anchors bit-exact.
constexpr double NDF_MAP_GLSL_MAX_DIFFERENCE = 1e-4;
constexpr double NDF_MAP_GLSL_MAX_MISMATCH_RATE = 1e-3;
