// glint_ibl: a glinty silver sphere under an environment map (image-based lighting of glints,
// KK25 Sec. 4-5), rendered on the CPU with every core; writes OpenEXR and a PNG preview.
//
//   glint_ibl [--env PATH.exr] [--k 4|8] [--smooth] [--seed N] [--density LOG] [--roughness A]
//             [--one-lattice-point] [--size WxH] [--out PATH.exr]
//
// --one-lattice-point shades each pixel's glints on one of its footprint's four lattice points
// (glint::grid_pixel_setup with a lattice_u): the same mean and per-pixel variance, cheaper.
//
// Bare, it renders the showcase: the sphere in data/envmaps/sunset.exr, K = 4.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <glint/ibl.hpp>
#include <glint/io/exr.hpp>

#include "ibl_scene.hpp"
#include "support/cli.hpp"
#include "support/render.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_ibl: %s\n"
                 "usage: glint_ibl [--env PATH.exr] [--k 4|8] [--smooth] [--seed N] [--density LOG] [--roughness A]\n"
                 "                 [--one-lattice-point] [--size WxH] [--out PATH.exr]\n",
                 problem.c_str());
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    std::string env_path = std::string(GLINT_DATA_DIR) + "/envmaps/sunset.exr", out = "glint_ibl.exr";
    int K = 4, w = 640, h = 400;
    bool smooth = false, one_lattice_point = false;
    std::uint32_t seed = 1;
    float log_density = 5.0f, roughness = 0.12f;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return flag_value(argc, argv, i, usage); };
        if (a == "--env") env_path = value();
        else if (a == "--k") {
            const std::string v = value();
            if (v != "4" && v != "8") usage("--k must be 4 or 8, got '" + v + "'");
            K = std::stoi(v);
        } else if (a == "--smooth") smooth = true;
        else if (a == "--one-lattice-point") one_lattice_point = true;
        else if (a == "--seed") seed = static_cast<std::uint32_t>(parse_float(a, value(), 0, 4e9f, usage));
        else if (a == "--density") log_density = parse_float(a, value(), -20, 40, usage);
        else if (a == "--roughness") roughness = parse_float(a, value(), 1e-3f, 1, usage);
        else if (a == "--size") parse_size(a, value(), w, h, usage);
        else if (a == "--out") out = parse_exr_path(a, value(), usage);
        else usage("unknown argument '" + a + "'");
    }
    glint::environment env;
    try {
        const auto img = glint::io::read_exr(env_path);
        if (img.clamped) std::fprintf(stderr, "glint_ibl: %s: %zu pixels had negative or non-finite values, read as 0\n", env_path.c_str(), img.clamped);
        glint::ibl_options o;
        o.levels = K;
        const auto t0 = std::chrono::steady_clock::now();
        o.progress = [&](double f) {
            static int last = -1;
            const int pct = static_cast<int>(100 * f);
            if (pct != last) std::fprintf(stderr, "\rglint_ibl: prefiltering %s: %3d%%", env_path.c_str(), pct), last = pct;
        };
        env = glint::build_environment(img.width, img.height, img.rgb, o);
        std::fprintf(stderr, "\rglint_ibl: prefiltered %s (%dx%d, K = %d) in %.2f s\n", env_path.c_str(), img.width, img.height, K,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    } catch (const glint::error& e) {
        std::fprintf(stderr, "glint_ibl: %s\n", e.what());
        return 1;
    }
    const camera cam = ibl_camera(w, h);
    ibl_settings settings;
    settings.smooth = smooth, settings.seed = seed, settings.log_density = log_density, settings.roughness = roughness;
    settings.stochastic_lattice = one_lattice_point;
    std::vector<float> rgb(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    const render_timing t = render_rows(h, "glint_ibl: rendering " + std::to_string(w) + "x" + std::to_string(h), [&](int y) {
        for (int x = 0; x < w; ++x) {
            const vec3 L = render_ibl_pixel(env, settings, cam, x, y);
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
            rgb[i] = L.x, rgb[i + 1] = L.y, rgb[i + 2] = L.z;
        }
    });
    std::fprintf(stderr, "\rglint_ibl: rendered %dx%d (%s, K = %d) in %.2f s on %u threads\n", w, h, smooth ? "smooth" : "glints", K,
                 t.seconds, t.threads);
    try {
        write_exr_and_preview(out, w, h, rgb, 1.2f);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_ibl: %s\n", e.what());
        return 1;
    }
    return 0;
}
