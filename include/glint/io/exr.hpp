// OpenEXR input and output for glint's environment maps, examples and tools (needs the
// glint::exr target). Host side: throws glint::error naming the file and the problem.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>

#include "glint/core/error.hpp"

namespace glint {
namespace io {

// A linear RGB image, row-major, top row first, 3 floats per pixel.
struct rgb_image {
    int width = 0, height = 0;
    std::vector<float> rgb;
    // Pixels that had a negative or non-finite channel in the file; those channels read as 0.
    std::size_t clamped = 0;
};

// The channels `names` of an OpenEXR file as floats, interleaved in that order, row-major, top
// row first, exactly as stored (no clamping). Throws glint::error if the file cannot be opened or
// read, lacks a channel (the message lists those present), or is empty.
inline rgb_image read_exr_channels(const std::string& path, const std::vector<std::string>& names) {
    rgb_image img;
    const std::size_t k = names.size();
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        std::string missing;
        for (const auto& c : names)
            if (!header.channels().findChannel(c)) missing += (missing.empty() ? "" : ", ") + c;
        if (!missing.empty()) {
            std::string present;
            for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
                present += std::string(present.empty() ? "" : ", ") + it.name();
            throw error("glint::io::read_exr: " + path + ": no channel " + missing + " (channels: " + (present.empty() ? "none" : present) + ")");
        }
        const Imath::Box2i window = header.dataWindow();
        const long w = static_cast<long>(window.max.x) - window.min.x + 1, h = static_cast<long>(window.max.y) - window.min.y + 1;
        if (w <= 0 || h <= 0)
            throw error("glint::io::read_exr: " + path + ": empty image (" + std::to_string(w) + " x " + std::to_string(h) + ")");
        if (w * h > (1L << 28)) throw error("glint::io::read_exr: " + path + ": " + std::to_string(w) + " x " + std::to_string(h) + " is too large");
        img.width = static_cast<int>(w), img.height = static_cast<int>(h);
        img.rgb.assign(k * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
        Imf::FrameBuffer fb;
        // Slices are addressed through the data window's origin.
        const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(k * sizeof(float));
        char* base = reinterpret_cast<char*>(img.rgb.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * w) * stride;
        for (std::size_t c = 0; c < k; ++c)
            fb.insert(names[c].c_str(), Imf::Slice(Imf::FLOAT, base + static_cast<std::ptrdiff_t>(c * sizeof(float)), k * sizeof(float),
                                                   k * sizeof(float) * static_cast<std::size_t>(w)));
        file.setFrameBuffer(fb);
        file.readPixels(window.min.y, window.max.y);
    } catch (const error&) {
        throw;
    } catch (const std::exception& e) {
        throw error("glint::io::read_exr: " + path + ": " + e.what());
    }
    return img;
}

// Reads an OpenEXR file with channels R, G and B (A and others are ignored), half or float, any
// compression; the data window is the image. Negative and non-finite values become 0 and are
// counted in `clamped` (real captures have a few slightly negative pixels). Throws glint::error
// if the file cannot be opened or read, lacks one of R, G, B, or is empty.
inline rgb_image read_exr(const std::string& path) {
    rgb_image img = read_exr_channels(path, {"R", "G", "B"});
    for (std::size_t i = 0; i < img.rgb.size(); i += 3) {
        bool bad = false;
        for (std::size_t c = 0; c < 3; ++c) {
            float& v = img.rgb[i + c];
            if (!(std::isfinite(v) && v >= 0)) v = 0, bad = true;
        }
        img.clamped += bad;
    }
    return img;
}

// Writes width x height RGB pixels (row-major, top row first, 3 floats each) as an OpenEXR file:
// half-float RGBA (alpha 1) by default, or 32-bit float RGB with `full_float` (normal maps, data).
inline void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb, bool full_float = false) {
    if (width <= 0 || height <= 0)
        throw error("glint::io::write_exr: " + path + ": image size " + std::to_string(width) + " x " + std::to_string(height) + " is empty");
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (rgb.size() != 3 * n)
        throw error("glint::io::write_exr: " + path + ": " + std::to_string(rgb.size()) + " floats given for " + std::to_string(width) +
                    " x " + std::to_string(height) + " RGB pixels (" + std::to_string(3 * n) + " expected)");
    try {
        if (full_float) {
            Imf::Header header(width, height);
            Imf::FrameBuffer fb;
            const char* names[] = {"R", "G", "B"};
            for (int c = 0; c < 3; ++c) {
                header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
                fb.insert(names[c], Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(rgb.data() + c)), 3 * sizeof(float),
                                               3 * sizeof(float) * static_cast<std::size_t>(width)));
            }
            Imf::OutputFile file(path.c_str(), header);
            file.setFrameBuffer(fb);
            file.writePixels(height);
            return;
        }
        std::vector<Imf::Rgba> pixels(n);
        for (std::size_t i = 0; i < n; ++i) pixels[i] = Imf::Rgba(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 1.0f);
        Imf::RgbaOutputFile file(path.c_str(), width, height, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(width));
        file.writePixels(height);
    } catch (const std::exception& e) {
        throw error("glint::io::write_exr: " + path + ": " + e.what());
    }
}

}  // namespace io
}  // namespace glint
