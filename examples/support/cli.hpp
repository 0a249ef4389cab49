// Command-line and preview helpers shared by the examples.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

namespace glint_examples {

// The number in `s` if it parses completely and lies in [lo, hi]; otherwise nothing (the caller
// reports the flag, the range and the text).
inline std::optional<float> parse_number(const std::string& s, float lo, float hi) {
    char* end = nullptr;
    const float v = std::strtof(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) return std::nullopt;
    return v;
}

inline std::string range_message(const std::string& flag, const std::string& s, float lo, float hi) {
    return flag + " needs a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + s + "'";
}

// Exposure, the tone curve x / (1 + x), then the sRGB transfer function, to 8 bits.
inline std::uint8_t to_srgb8(float v, float exposure) {
    v = std::max(v, 0.0f) * exposure;
    v = v / (1 + v);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0f, 1.0f) * 255));
}

}  // namespace glint_examples
