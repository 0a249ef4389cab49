// Helpers for the parity tests: one shared context, and shaders that map input arrays
// through a GLSL expression.
#pragma once

#include <string>
#include <vector>

#include "gl_compute.hpp"

namespace glint_test {

// The process-wide context (created on first use; a failure to create it fails the test).
gl_compute& gl();

// Runs `expression` (GLSL, type `result_type`, one output word) over float inputs x[i]
// (and y[i] when `y` is non-empty), with the given kernel files included.
std::vector<std::uint32_t> map_floats(const std::vector<std::string>& kernels, const std::string& result_type,
                                      const std::string& expression, const std::vector<float>& x,
                                      const std::vector<float>& y = {});

// Runs `body` with `uint i` set to the element index and buffers `uint in0[]` (binding 0) and
// `uint out0[]` (binding 1) of `out_words_per_item` words per item. `in_float(k)`, `in_vec2(k)` and
// `in_vec3(k)` read floats stored as words from in0 at word k.
std::vector<std::uint32_t> map_words(const std::vector<std::string>& kernels, const std::string& body,
                                     const std::vector<std::uint32_t>& in, std::size_t items,
                                     std::size_t out_words_per_item);

// A float as a GLSL expression of its exact bits: "uintBitsToFloat(<bits>u)".
std::string glsl_float_bits(float x);

// As map_words, with `data` (vec4s) bound read-only at binding 1 as `vec4 <data_name>[]`, the
// output at binding 2, and `declared` defined before the kernel file `data_kernel` (which reads
// that buffer, e.g. gaussian.glsl's glint_element_data with GLINT_ELEMENT_BUFFER_DECLARED) is
// included after `kernels`.
std::vector<std::uint32_t> map_words_with_data(const std::vector<std::string>& kernels, const std::string& data_kernel, const std::string& data_name,
                                               const std::string& declared, const std::string& body, const std::vector<std::uint32_t>& in,
                                               const std::vector<std::uint32_t>& data, std::size_t items, std::size_t out_words_per_item);

// How far a GLSL result array is from the C++ one: the largest ulp distance, and how many
// elements differ at all (the mismatch rate). For a discrete sampler the rate counts outcomes
// flipped by an input within rounding of a decision boundary; tests bound it.
struct ulp_stats {
    std::int64_t max = 0;
    std::size_t differing = 0;
    std::size_t count = 0;
    double rate() const { return count ? static_cast<double>(differing) / static_cast<double>(count) : 0.0; }
};
ulp_stats compare(const std::vector<float>& gpu, const std::vector<float>& cpu);
ulp_stats compare(const std::vector<std::uint32_t>& gpu, const std::vector<std::uint32_t>& cpu);

}  // namespace glint_test
