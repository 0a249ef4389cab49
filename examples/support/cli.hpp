// Command-line and preview helpers shared by the examples.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace glint_examples {

// The value after the flag argv[i], advancing i past it; `fail` if the flag is the last argument.
template <class Fail>
std::string flag_value(int argc, char** argv, int& i, Fail fail) {
    if (i + 1 >= argc) fail(std::string(argv[i]) + " needs a value");
    return argv[++i];
}

// The number in `s` if it parses completely and lies in [lo, hi]; otherwise `fail` (which does not
// return) gets a message naming the flag, the range and the text.
template <class Fail>
float parse_float(const std::string& flag, const std::string& s, float lo, float hi, Fail fail) {
    char* end = nullptr;
    const float v = std::strtof(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
        fail(flag + " needs a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + s + "'");
    return v;
}

// WxH with 1 <= W, H <= 16384 into width and height; otherwise `fail`.
template <class Fail>
void parse_size(const std::string& flag, const std::string& s, int& width, int& height, Fail fail) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(s.c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 1 || h < 1 || w > 16384 || h > 16384)
        fail(flag + " needs WxH with 1 <= W, H <= 16384, got '" + s + "'");
    width = w, height = h;
}

// An output path, which must end in .exr (the preview goes next to it as .png); otherwise `fail`.
template <class Fail>
std::string parse_exr_path(const std::string& flag, const std::string& s, Fail fail) {
    if (s.size() < 5 || s.substr(s.size() - 4) != ".exr") fail(flag + " must end in .exr, got '" + s + "'");
    return s;
}

// Exposure, the tone curve x / (1 + x), then the sRGB transfer function, to 8 bits.
inline std::uint8_t to_srgb8(float v, float exposure) {
    v = std::max(v, 0.0f) * exposure;
    v = v / (1 + v);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0f, 1.0f) * 255));
}

}  // namespace glint_examples
