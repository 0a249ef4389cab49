// glint: GLSL side of the single-source kernel compat layer.
// Include once, after `#version 450`, before any other glint kernel file. The kernels then see
// the same names they see when compiled as C++ (include/glint/detail/kernel_begin.hpp).
#ifndef GLINT_PRELUDE_GLSL
#define GLINT_PRELUDE_GLSL
#define GLINT_GLSL 1
#define real float
#define GLINT_FN
#define GLINT_FN_OUT_OF_LINE
#define GLINT_FN_INLINE
#define GLINT_OUT(T) out T
#define GLINT_INOUT(T) inout T
#define GLINT_IN(T) in T
#define GLINT_CONST(T) const T
#define GLINT_FLOAT_TABLE(name, n) const vec4 name[(n) / 4] = vec4[(n) / 4]
#define GLINT_TABLE_OPEN (
#define GLINT_TABLE_CLOSE )
#define GLINT_FLOAT4(a, b, c, d) vec4(a, b, c, d)
#define GLINT_TABLE_READ(name, k) name[(k) >> 2][(k) & 3]
#define GLINT_PRECISE precise
#define GLINT_ELEMENT_DATA_PARAM
#define GLINT_ELEMENT_DATA_ARG
#define GLINT_SCRATCH_DATA_PARAM
#define GLINT_SCRATCH_DATA_ARG
#define GLINT_NDF_DATA_PARAM
#define GLINT_NDF_DATA_ARG
// True in the C++ double instantiation; GLSL computes in float.
const bool GLINT_DOUBLE = false;
#endif
