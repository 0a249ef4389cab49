// The message of the glint::error that f throws ("" if none), for tests of error messages.
#pragma once

#include <functional>
#include <string>

#include <glint/core/error.hpp>

namespace glint_test {

inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const glint::error& e) {
        return e.what();
    }
    return "";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace glint_test
