// The C++ instantiation of kernels/core.glsl: glint::detail::glsl::core_kernels<real>.
// Users call the wrappers in glint/core/*.hpp instead.
#pragma once

#include "glint/detail/kernel_begin.hpp"

namespace glint {
namespace detail {
namespace glsl {

template <class real>
struct core_kernels {
    GLINT_KERNEL_TYPES
#include "glint/kernels/core.glsl"
};

}  // namespace glsl
}  // namespace detail
}  // namespace glint

#include "glint/detail/kernel_end.hpp"
