// OpenEXR output for glint's examples and tools (needs the glint::exr target). Host side: throws
// glint::error naming the file and the problem.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <ImfRgbaFile.h>

#include "glint/core/error.hpp"

namespace glint {
namespace io {

// Writes width x height RGB pixels (row-major, top row first, 3 floats each) as a half-float
// RGBA OpenEXR file (alpha 1).
inline void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    if (width <= 0 || height <= 0)
        throw error("glint::io::write_exr: " + path + ": image size " + std::to_string(width) + " x " + std::to_string(height) + " is empty");
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (rgb.size() != 3 * n)
        throw error("glint::io::write_exr: " + path + ": " + std::to_string(rgb.size()) + " floats given for " + std::to_string(width) +
                    " x " + std::to_string(height) + " RGB pixels (" + std::to_string(3 * n) + " expected)");
    std::vector<Imf::Rgba> pixels(n);
    for (std::size_t i = 0; i < n; ++i) pixels[i] = Imf::Rgba(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 1.0f);
    try {
        Imf::RgbaOutputFile file(path.c_str(), width, height, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(width));
        file.writePixels(height);
    } catch (const std::exception& e) {
        throw error("glint::io::write_exr: " + path + ": " + e.what());
    }
}

}  // namespace io
}  // namespace glint
