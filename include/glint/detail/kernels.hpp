// The C++ instantiation of every kernel file: glint::detail::glsl::kernels<real>, one struct per
// precision, so a type a kernel file defines (a footprint, a lattice, an estimate) is one C++ type
// in every component header that uses it. Users call the wrappers in glint/*.hpp instead.
//
// The files are included in dependency order (the order of GLINT_KERNEL_FILES in CMakeLists.txt,
// which a GLSL user follows too). A class template's members are instantiated only when used,
// so a header that calls only core functions compiles only those.
#pragma once

#include "glint/detail/kernel_begin.hpp"

namespace glint {
namespace detail {
namespace glsl {

template <class real>
struct kernels {
    GLINT_KERNEL_TYPES
#include "glint/kernels/core.glsl"
#include "glint/kernels/binomial.glsl"
#include "glint/kernels/multinomial.glsl"
#include "glint/kernels/microfacet.glsl"
#include "glint/kernels/grid.glsl"
#include "glint/kernels/ibl.glsl"
#include "glint/kernels/gaussian.glsl"
#include "glint/kernels/scratch.glsl"
#include "glint/kernels/ndf_map.glsl"
};

}  // namespace glsl
}  // namespace detail
}  // namespace glint

#include "glint/detail/kernel_end.hpp"
