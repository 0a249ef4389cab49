// PNG input and output through libpng (needs the glint::png target). Host side: throws
// glint::error naming the file and the problem; corrupt data is reported by libpng's own checks
// (CRCs, zlib stream, chunk lengths), never read past.
#pragma once

#include <csetjmp>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <png.h>

#include "glint/core/error.hpp"

namespace glint {
namespace io {

// An image as read: channels 1 (gray), 2 (gray + alpha), 3 (RGB) or 4 (RGBA); values in [0, 1]
// (the stored integers over 255 or 65535; no gamma is applied), row-major, top row first.
struct png_image_data {
    int width = 0, height = 0, channels = 0, bit_depth = 0;
    std::vector<float> values;
};

namespace detail {

struct png_error_state {
    std::jmp_buf jump;
    char message[512] = {0};
    char warning[200] = {0};  // the last warning, which often says what the error's check found
};

extern "C" inline void glint_png_error(png_structp png, png_const_charp msg) {
    auto* state = static_cast<png_error_state*>(png_get_error_ptr(png));
    if (state->warning[0])
        std::snprintf(state->message, sizeof(state->message), "%s (%s)", msg ? msg : "unknown libpng error", state->warning);
    else
        std::snprintf(state->message, sizeof(state->message), "%s", msg ? msg : "unknown libpng error");
    std::longjmp(state->jump, 1);
}
extern "C" inline void glint_png_warning(png_structp png, png_const_charp msg) {
    auto* state = static_cast<png_error_state*>(png_get_error_ptr(png));
    std::snprintf(state->warning, sizeof(state->warning), "%s", msg ? msg : "");
}

struct png_memory_reader {
    const std::uint8_t* data;
    std::size_t size, offset;
};
extern "C" inline void glint_png_read(png_structp png, png_bytep out, png_size_t count) {
    auto* r = static_cast<png_memory_reader*>(png_get_io_ptr(png));
    if (count > r->size - r->offset) png_error(png, "unexpected end of file");
    std::memcpy(out, r->data + r->offset, count);
    r->offset += count;
}

// Everything with a destructor is created before setjmp, so a longjmp from libpng skips none.
// Returns an empty string on success, else the reason.
inline std::string decode_png(const std::uint8_t* data, std::size_t size, png_image_data& img, std::vector<std::uint8_t>& raw,
                              std::vector<png_bytep>& rows, bool check_crc) {
    if (size < 8 || png_sig_cmp(data, 0, 8) != 0) return "not a PNG file (bad signature)";
    png_error_state state;
    png_memory_reader reader{data, size, 0};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, glint_png_error, glint_png_warning);
    if (!png) return "libpng could not allocate a reader";
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return "libpng could not allocate a reader";
    }
    if (setjmp(state.jump)) {
        png_destroy_read_struct(&png, &info, nullptr);
        return state.message;
    }
    png_set_read_fn(png, &reader, glint_png_read);
    if (!check_crc) png_set_crc_action(png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
    // Bound what a corrupt header can make us allocate: 2^14 per side, 2^26 pixels.
    png_set_user_limits(png, 1u << 14, 1u << 14);
    png_read_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    if (static_cast<std::uint64_t>(w) * h > (1ull << 26)) png_error(png, "image larger than 2^26 pixels");
    const int color = png_get_color_type(png, info);
    int depth = png_get_bit_depth(png, info);
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png), depth = 8;
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png), depth = 8;
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    if (depth == 16) png_set_swap(png);  // little-endian 16-bit words
    png_read_update_info(png, info);
    const int channels = png_get_channels(png, info);
    const std::size_t row_bytes = png_get_rowbytes(png, info);
    raw.resize(row_bytes * h);
    rows.resize(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = raw.data() + y * row_bytes;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    img.width = static_cast<int>(w), img.height = static_cast<int>(h), img.channels = channels, img.bit_depth = depth;
    return "";
}

}  // namespace detail

// Decodes a PNG held in memory (`name` appears in errors). Any bit depth and colour type;
// palettes and transparency chunks are expanded. check_crc = false ignores chunk checksums (for
// fuzzing the decoder behind them).
inline png_image_data read_png_memory(const std::uint8_t* data, std::size_t size, const std::string& name, bool check_crc = true) {
    png_image_data img;
    std::vector<std::uint8_t> raw;
    std::vector<png_bytep> rows;
    const std::string why = detail::decode_png(data, size, img, raw, rows, check_crc);
    if (!why.empty()) throw error("glint::io::read_png: " + name + ": " + why);
    if (img.width <= 0 || img.height <= 0) throw error("glint::io::read_png: " + name + ": empty image");
    const std::size_t n = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * static_cast<std::size_t>(img.channels);
    img.values.resize(n);
    if (img.bit_depth == 16) {
        for (std::size_t i = 0; i < n; ++i) img.values[i] = static_cast<float>(raw[2 * i] | (raw[2 * i + 1] << 8)) / 65535.0f;
    } else {
        for (std::size_t i = 0; i < n; ++i) img.values[i] = static_cast<float>(raw[i]) / 255.0f;
    }
    return img;
}

inline png_image_data read_png(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw error("glint::io::read_png: " + path + ": cannot open the file");
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return read_png_memory(bytes.data(), bytes.size(), path);
}

// Writes width x height pixels of `channels` (1..4) samples each, 8 or 16 bits per sample,
// row-major, top row first. `samples` holds the integers (below 2^bit_depth).
inline void write_png(const std::string& path, int width, int height, int channels, int bit_depth, const std::vector<std::uint16_t>& samples) {
    if (width <= 0 || height <= 0)
        throw error("glint::io::write_png: " + path + ": image size " + std::to_string(width) + " x " + std::to_string(height) + " is empty");
    if (channels < 1 || channels > 4) throw error("glint::io::write_png: " + path + ": " + std::to_string(channels) + " channels (1..4)");
    if (bit_depth != 8 && bit_depth != 16) throw error("glint::io::write_png: " + path + ": bit depth " + std::to_string(bit_depth) + " (8 or 16)");
    const std::size_t per_row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
    if (samples.size() != per_row * static_cast<std::size_t>(height))
        throw error("glint::io::write_png: " + path + ": " + std::to_string(samples.size()) + " samples for " + std::to_string(width) + " x " +
                    std::to_string(height) + " x " + std::to_string(channels));
    const std::size_t bytes = static_cast<std::size_t>(bit_depth / 8);
    std::vector<std::uint8_t> raw(per_row * bytes * static_cast<std::size_t>(height));
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (bytes == 2) raw[2 * i] = static_cast<std::uint8_t>(samples[i] >> 8), raw[2 * i + 1] = static_cast<std::uint8_t>(samples[i] & 0xff);
        else raw[i] = static_cast<std::uint8_t>(std::min<std::uint16_t>(samples[i], 255));
    }
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = raw.data() + y * per_row * bytes;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw error("glint::io::write_png: " + path + ": cannot open the file for writing");
    detail::png_error_state state;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, detail::glint_png_error, detail::glint_png_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
        throw error("glint::io::write_png: " + path + ": libpng could not allocate a writer");
    }
    if (setjmp(state.jump)) {
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
        throw error("glint::io::write_png: " + path + ": " + state.message);
    }
    png_init_io(png, file);
    const int types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bit_depth, types[channels - 1], PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fclose(file) != 0) throw error("glint::io::write_png: " + path + ": writing failed");
}

// An 8-bit RGB preview (3 bytes per pixel).
inline void write_png_rgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    write_png(path, width, height, 3, 8, std::vector<std::uint16_t>(rgb.begin(), rgb.end()));
}

}  // namespace io
}  // namespace glint
