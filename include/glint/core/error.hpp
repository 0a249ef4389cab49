// glint::error: what host-side builders and loaders throw for bad input. Per-pixel kernels
// never throw.
#pragma once

#include <stdexcept>
#include <string>

namespace glint {

class error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace glint
