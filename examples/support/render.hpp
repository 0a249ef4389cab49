// The examples' frame loop and output: rows rendered on every core with a progress line, then
// OpenEXR plus a PNG preview.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <glint/io/exr.hpp>
#include <glint/io/png.hpp>

#include "cli.hpp"

namespace glint_examples {

struct render_timing {
    double seconds = 0;
    unsigned threads = 0;
};

// Calls row(y) for every y in [0, height), concurrently on every core, and shows
// "label: NN% (T s)" on stderr while it runs.
template <class Row>
render_timing render_rows(int height, const std::string& label, Row row) {
    std::atomic<int> next_row{0}, rows_done{0};
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    auto work = [&] {
        for (int y = next_row++; y < height; y = next_row++) {
            row(y);
            ++rows_done;
        }
    };
    render_timing t;
    t.threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < t.threads; ++i) pool.emplace_back(work);
    // Polled every 5 ms (so that the time below is that close), shown every 200 ms.
    for (int polls = 1; rows_done < height; ++polls) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        if (polls % 40 == 0) std::fprintf(stderr, "\r%s: %3d%% (%.1f s)", label.c_str(), 100 * rows_done.load() / height, seconds());
    }
    for (auto& th : pool) th.join();
    t.seconds = seconds();
    return t;
}

// Writes width x height linear RGB pixels to `exr_path` and a preview (exposure, then
// to_srgb8) next to it with the extension .png; prints both paths. Throws glint::error or
// std::runtime_error if a file cannot be written.
inline void write_exr_and_preview(const std::string& exr_path, int width, int height, const std::vector<float>& rgb, float exposure) {
    glint::io::write_exr(exr_path, width, height, rgb);
    std::vector<std::uint8_t> preview(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) preview[i] = to_srgb8(rgb[i], exposure);
    const std::string png = exr_path.substr(0, exr_path.size() - 4) + ".png";
    glint::io::write_png_rgb8(png, width, height, preview);
    std::printf("wrote %s and %s\n", exr_path.c_str(), png.c_str());
}

}  // namespace glint_examples
