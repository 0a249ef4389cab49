// A minimal 8-bit RGB PNG writer for the examples' previews (zlib for the compression).
#pragma once

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <zlib.h>

namespace glint_examples {

inline void write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    std::vector<std::uint8_t> raw;  // each row: filter byte 0, then the pixels
    raw.reserve(static_cast<std::size_t>(height) * (3 * static_cast<std::size_t>(width) + 1));
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        const auto row = rgb.begin() + static_cast<std::ptrdiff_t>(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(y));
        raw.insert(raw.end(), row, row + 3 * width);
    }
    uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
    std::vector<std::uint8_t> packed(packed_size);
    if (compress2(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
        throw std::runtime_error("write_png: " + path + ": zlib compression failed");
    packed.resize(packed_size);
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error("write_png: cannot open " + path + " for writing");
    auto be32 = [](std::vector<std::uint8_t>& v, std::uint32_t x) {
        for (int s = 24; s >= 0; s -= 8) v.push_back(static_cast<std::uint8_t>(x >> s));
    };
    auto chunk = [&](const char* type, const std::vector<std::uint8_t>& data) {
        std::vector<std::uint8_t> c;
        be32(c, static_cast<std::uint32_t>(data.size()));
        c.insert(c.end(), type, type + 4);
        c.insert(c.end(), data.begin(), data.end());
        const uLong crc = crc32(0L, c.data() + 4, static_cast<uInt>(c.size() - 4));
        be32(c, static_cast<std::uint32_t>(crc));
        out.write(reinterpret_cast<const char*>(c.data()), static_cast<std::streamsize>(c.size()));
    };
    const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    out.write(reinterpret_cast<const char*>(signature), 8);
    std::vector<std::uint8_t> header;
    be32(header, static_cast<std::uint32_t>(width));
    be32(header, static_cast<std::uint32_t>(height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, no filter, no interlace
    chunk("IHDR", header);
    chunk("IDAT", packed);
    chunk("IEND", {});
    if (!out) throw std::runtime_error("write_png: writing " + path + " failed");
}

}  // namespace glint_examples
