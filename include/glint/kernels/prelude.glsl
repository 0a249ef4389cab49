// glint: GLSL side of the single-source kernel compat layer.
// Include once, after `#version 450`, before any other glint kernel file. The kernels then see
// the same names they see when compiled as C++ (include/glint/detail/kernel_begin.hpp).
#ifndef GLINT_PRELUDE_GLSL
#define GLINT_PRELUDE_GLSL
#define GLINT_GLSL 1
#define real float
#define GLINT_FN
#define GLINT_OUT(T) out T
#define GLINT_INOUT(T) inout T
#define GLINT_CONST(T) const T
#define GLINT_PRECISE precise
#define GLINT_ELEMENT_DATA_PARAM
#define GLINT_ELEMENT_DATA_ARG
// True in the C++ double instantiation; GLSL computes in float.
const bool GLINT_DOUBLE = false;
#endif
