// Reading and writing tangent-space normal maps (needs glint::exr and glint::png):
//
//   glint::normal_map m = glint::io::read_normal_map("brushed.png");         // OpenGL green (+y up)
//   glint::io::normal_map_read_options o;  o.green = glint::io::green_axis::down;  // DirectX
//   glint::normal_map h = glint::io::read_height_map("bumps.png", 4.0f);     // heights x 4 texels
//
// Files: OpenEXR (float or half channels R, G, B holding the components in [-1, 1]) and PNG (8 or
// 16 bit RGB or RGBA, each component c stored as (c + 1) / 2, as tangent-space maps usually are).
// The file's top row is row 0 (normal_map.hpp's frame has y along rows), so the OpenGL convention
// (green = +y up the image) negates the green component and DirectX's (green down) keeps it.
// Height maps: a gray or RGB PNG (the first channel, in [0, 1]) or an EXR channel Y, else R.
// Errors (glint::error) name the file and what was wrong: a missing or corrupt file, a wrong
// channel count, a zero size, non-finite texels, z <= min_z (unless clamp_z: then counted).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "glint/io/exr.hpp"
#include "glint/io/png.hpp"
#include "glint/normal_map.hpp"

namespace glint {
namespace io {

enum class green_axis { up, down };  // up: OpenGL, Blender, glTF; down: DirectX

struct normal_map_read_options {
    green_axis green = green_axis::up;
    normal_map_options map;  // wrap mode, clamp_z, min_z (the source is set to the path)
};

namespace detail {

inline bool ends_with(const std::string& s, const std::string& tail) {
    if (s.size() < tail.size()) return false;
    std::string end = s.substr(s.size() - tail.size());
    std::transform(end.begin(), end.end(), end.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return end == tail;
}

}  // namespace detail

// A normal map from the components (x, y, z per texel, file convention), decoded from a PNG's
// [0, 1] values when `unit_encoded`.
inline normal_map normal_map_from_components(int width, int height, const std::vector<float>& xyz, bool unit_encoded,
                                             const normal_map_read_options& options, const std::string& path) {
    std::vector<glm::vec3> n(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const float gy = options.green == green_axis::up ? -1.0f : 1.0f;
    for (std::size_t i = 0; i < n.size(); ++i) {
        glm::vec3 c(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        if (unit_encoded) c = 2.0f * c - 1.0f;
        n[i] = glm::vec3(c.x, gy * c.y, c.z);
    }
    normal_map_options o = options.map;
    o.source = path;
    return normal_map(width, height, std::move(n), o);
}

// Reads a normal map from an .exr or .png file (by extension).
inline normal_map read_normal_map(const std::string& path, const normal_map_read_options& options = {}) {
    if (detail::ends_with(path, ".exr")) {
        const rgb_image img = read_exr_channels(path, {"R", "G", "B"});
        return normal_map_from_components(img.width, img.height, img.rgb, false, options, path);
    }
    if (detail::ends_with(path, ".png")) {
        const png_image_data img = read_png(path);
        if (img.channels != 3 && img.channels != 4)
            throw error("glint::io::read_normal_map: " + path + ": " + std::to_string(img.channels) +
                        " channels; a normal map needs RGB or RGBA (a gray image is a height map: read_height_map)");
        std::vector<float> xyz(3 * static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
        for (std::size_t i = 0; i < xyz.size() / 3; ++i)
            for (std::size_t c = 0; c < 3; ++c) xyz[3 * i + c] = img.values[static_cast<std::size_t>(img.channels) * i + c];
        return normal_map_from_components(img.width, img.height, xyz, true, options, path);
    }
    throw error("glint::io::read_normal_map: " + path + ": unknown file type (.exr or .png)");
}

// Reads a height map (texel units times height_scale) and converts it (normal_map::from_heights).
inline normal_map read_height_map(const std::string& path, float height_scale, const normal_map_options& options = {}) {
    normal_map_options o = options;
    o.source = path;
    if (detail::ends_with(path, ".exr")) {
        rgb_image img;
        try {
            img = read_exr_channels(path, {"Y"});
        } catch (const error&) {
            img = read_exr_channels(path, {"R"});
        }
        return normal_map::from_heights(img.width, img.height, img.rgb, height_scale, o);
    }
    if (detail::ends_with(path, ".png")) {
        const png_image_data img = read_png(path);
        std::vector<float> h(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
        for (std::size_t i = 0; i < h.size(); ++i) h[i] = img.values[static_cast<std::size_t>(img.channels) * i];
        return normal_map::from_heights(img.width, img.height, h, height_scale, o);
    }
    throw error("glint::io::read_height_map: " + path + ": unknown file type (.exr or .png)");
}

// Writes a normal map in the file convention of `green`: .exr as 32-bit float components in
// [-1, 1], .png as 16-bit RGB (c + 1) / 2.
inline void write_normal_map(const std::string& path, const normal_map& m, green_axis green = green_axis::up) {
    const float gy = green == green_axis::up ? -1.0f : 1.0f;
    const auto& n = m.normals();
    if (detail::ends_with(path, ".exr")) {
        std::vector<float> rgb(3 * n.size());
        for (std::size_t i = 0; i < n.size(); ++i) rgb[3 * i] = n[i].x, rgb[3 * i + 1] = gy * n[i].y, rgb[3 * i + 2] = n[i].z;
        write_exr(path, m.width(), m.height(), rgb, true);
        return;
    }
    if (detail::ends_with(path, ".png")) {
        std::vector<std::uint16_t> s(3 * n.size());
        const auto q = [](float c) { return static_cast<std::uint16_t>(std::lround(std::clamp((c + 1.0f) / 2.0f, 0.0f, 1.0f) * 65535.0f)); };
        for (std::size_t i = 0; i < n.size(); ++i) s[3 * i] = q(n[i].x), s[3 * i + 1] = q(gy * n[i].y), s[3 * i + 2] = q(n[i].z);
        write_png(path, m.width(), m.height(), 3, 16, s);
        return;
    }
    throw error("glint::io::write_normal_map: " + path + ": unknown file type (.exr or .png)");
}

}  // namespace io
}  // namespace glint
