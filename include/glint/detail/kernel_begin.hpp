// glint: C++ side of the single-source kernel compat layer, opening half.
//
// Kernel files (include/glint/kernels/*.glsl) are written in the common subset of GLSL 4.50 and
// C++17 (docs/conventions.md). On the C++ side glint/detail/kernels.hpp includes them all inside
// one class template `template <class real> struct kernels { GLINT_KERNEL_TYPES ... };` placed in
// namespace glint::detail::glsl, where GLM's functions are visible unqualified. This header
// defines the macros the kernel text needs; kernel_end.hpp removes every one of them, so nothing
// leaks into user code. No include guard: the pair is used once, by glint/detail/kernels.hpp.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace glint {
namespace detail {
// The widest of glint's vector paths that the kernels may take (glint_cpu_lanes, core.glsl):
// 0 the baseline code, 1 AVX2, 2 AVX2 with AVX-512; the CPU's features still decide. For tests
// that run every path the CPU has; renderers leave it.
inline std::atomic<int> lanes_limit{2};
namespace glsl {
// GLSL builtins (mix, clamp, exp, log, floor, ...) and types (uvec3, ...) come from GLM.
using namespace glm;  // NOLINT: confined to glint::detail::glsl
}  // namespace glsl
}  // namespace detail
}  // namespace glint

// A kernel function: a static member of the kernels class template (in GLSL: nothing).
#define GLINT_FN static
// A kernel function kept out of line in C++ (in GLSL: as GLINT_FN): for a rarely taken, long path
// whose inlined code would slow its callers' common paths.
#define GLINT_FN_OUT_OF_LINE __attribute__((noinline)) static
// Vector code that C++ builds twice where GCC targets x86-64 (not -DGLINT_NO_AVX2): GLINT_LANES_BODY
// marks the body, name_body, always inlined, and GLINT_LANES_VARIANTS(ret, name, (params), (args))
// then defines name_avx2 (target AVX2) and name_avx512 (AVX2 with AVX-512 F, VL, DQ and BW on the
// same 256-bit vectors: ternary logic, mask registers and the like where GCC finds them; no FMA,
// so the same values bit for bit), both out of line, and name, which calls the one the CPU runs
// (glint_cpu_avx512, core.glsl). Elsewhere name is one out-of-line copy of the body.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
#define GLINT_LANES_BODY __attribute__((always_inline, target("avx2"))) static inline
#define GLINT_LANES_VARIANTS(ret, name, params, args)                                                                      \
    __attribute__((noinline, target("avx2"))) static ret name##_avx2 params { return name##_body args; }                 \
    __attribute__((noinline, target("avx2,avx512f,avx512vl,avx512dq,avx512bw"))) static ret name##_avx512 params {      \
        return name##_body args;                                                                                         \
    }                                                                                                                    \
    static ret name params { return glint_cpu_avx512() ? name##_avx512 args : name##_avx2 args; }
#else
#define GLINT_LANES_BODY __attribute__((always_inline)) static inline
#define GLINT_LANES_VARIANTS(ret, name, params, args) \
    __attribute__((noinline)) static ret name params { return name##_body args; }
#endif
// A kernel function always inlined in C++ (in GLSL: as GLINT_FN): the body of a function that C++
// compiles twice, for the baseline and for AVX2 (target("avx2") code inlines it as AVX2).
#define GLINT_FN_INLINE __attribute__((always_inline)) static inline
// An out-parameter (in GLSL: `out T`).
#define GLINT_OUT(T) T&
// An in-out parameter (in GLSL: `inout T`).
#define GLINT_INOUT(T) T&
// A struct read but not written (in GLSL: `in T`, a copy): a const reference, so that C++ does
// not copy it. Copies of structs that were just written field by field cost the CPU a wait each
// (a wide load of narrow stores); in the IBL estimate the struct copies' waits were about a sixth
// of glint_ibl_sample's perf samples (DEVELOPERS.md).
#define GLINT_IN(T) const T&
// An expression the compiler must evaluate as written (in GLSL: `precise`). C++ needs nothing:
// the tests build with -ffp-contract=off and without -ffast-math.
#define GLINT_PRECISE
// The element buffer of kernels/gaussian.glsl: in C++ a parameter (and its argument), in GLSL
// nothing (a shader storage buffer named glint_element_data).
#define GLINT_ELEMENT_DATA_PARAM const vec4* glint_element_data,
#define GLINT_ELEMENT_DATA_ARG glint_element_data,
// The table of kernels/scratch.glsl: in C++ a parameter (and its argument) read by
// GLINT_SCRATCH_FETCH, in GLSL nothing (an SSBO or a fetch the user defines).
#define GLINT_SCRATCH_DATA_PARAM const vec4* glint_scratch_data,
#define GLINT_SCRATCH_DATA_ARG glint_scratch_data,
#define GLINT_SCRATCH_FETCH(k) glint_scratch_data[k]
// The NDF images of kernels/ndf_map.glsl: in C++ a float array (layer after layer, res x res
// bins of four floats each, row-major), in GLSL a sampler2DArray read by texelFetch.
#define GLINT_NDF_DATA_PARAM const float *glint_ndf_images,
#define GLINT_NDF_DATA_ARG glint_ndf_images,
#define GLINT_NDF_FETCH(layer, x, y, res) \
    vec4(::glm::make_vec4(glint_ndf_images + 4 * ((static_cast<std::ptrdiff_t>(layer) * (res) + (y)) * (res) + (x))))
// A named constant (in GLSL: `const T`).
#define GLINT_CONST(T) static constexpr T
// A constant table of n floats (n a multiple of 4), written GLINT_FLOAT_TABLE(name, n)
// GLINT_TABLE_OPEN GLINT_FLOAT4(v0, v1, v2, v3), ... GLINT_TABLE_CLOSE; and read as
// GLINT_TABLE_READ(name, k). GLSL holds it as `const vec4 name[n / 4]`: Mesa compiles a constant
// array in time that grows with the square of its element count (docs/conventions.md).
#define GLINT_FLOAT_TABLE(name, n) static constexpr float name[n] =
#define GLINT_TABLE_OPEN {
#define GLINT_TABLE_CLOSE }
#define GLINT_FLOAT4(a, b, c, d) a, b, c, d
#define GLINT_TABLE_READ(name, k) name[k]
// The vector aliases that depend on the precision `real` (in GLSL: the builtin float vectors),
// and GLINT_DOUBLE, true in the double instantiation (in GLSL: false), for series that need more
// terms in double; a branch on it is resolved at compile time.
#define GLINT_KERNEL_TYPES                                    \
    using vec2 = ::glm::vec<2, real, ::glm::defaultp>;        \
    using vec3 = ::glm::vec<3, real, ::glm::defaultp>;        \
    using vec4 = ::glm::vec<4, real, ::glm::defaultp>;        \
    static_assert(std::is_same<real, float>::value || std::is_same<real, double>::value, \
                  "glint kernels exist for float and double");                                  \
    static constexpr bool GLINT_DOUBLE = std::is_same<real, double>::value;
