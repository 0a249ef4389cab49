// glint: C++ side of the single-source kernel compat layer, closing half.
// Removes every macro kernel_begin.hpp defined.
#undef GLINT_FN
#undef GLINT_OUT
#undef GLINT_INOUT
#undef GLINT_CONST
#undef GLINT_PRECISE
#undef GLINT_KERNEL_TYPES
#undef GLINT_ELEMENT_DATA_PARAM
#undef GLINT_ELEMENT_DATA_ARG
