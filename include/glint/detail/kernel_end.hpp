// glint: C++ side of the single-source kernel compat layer, closing half.
// Removes every macro kernel_begin.hpp defined.
#undef GLINT_FN
#undef GLINT_FN_OUT_OF_LINE
#undef GLINT_FN_INLINE
#undef GLINT_LANES_BODY
#undef GLINT_LANES_VARIANTS
#undef GLINT_OUT
#undef GLINT_INOUT
#undef GLINT_IN
#undef GLINT_CONST
#undef GLINT_FLOAT_TABLE
#undef GLINT_TABLE_OPEN
#undef GLINT_TABLE_CLOSE
#undef GLINT_FLOAT4
#undef GLINT_TABLE_READ
#undef GLINT_PRECISE
#undef GLINT_KERNEL_TYPES
#undef GLINT_ELEMENT_DATA_PARAM
#undef GLINT_ELEMENT_DATA_ARG
#undef GLINT_SCRATCH_DATA_PARAM
#undef GLINT_SCRATCH_DATA_ARG
#undef GLINT_SCRATCH_FETCH
#undef GLINT_NDF_DATA_PARAM
#undef GLINT_NDF_DATA_ARG
#undef GLINT_NDF_FETCH
