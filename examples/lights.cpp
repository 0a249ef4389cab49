// glint_lights: a glinty sphere and plane under a point light, the sun or an area light,
// rendered on the CPU with every core; writes OpenEXR (linear radiance) and a PNG preview.
//
//   glint_lights [--light point|sun|area] [--smooth] [--seed N] [--density LOG]
//                [--roughness A] [--variant NAME] [--size WxH] [--out PATH.exr]
//
// Bare, it renders the showcase: the sun glinting on the plane and the sphere.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <glint/io/exr.hpp>

#include "lights_scene.hpp"
#include "support/cli.hpp"
#include "support/png.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_lights: %s\n"
                 "usage: glint_lights [--light point|sun|area] [--smooth] [--seed N] [--density LOG] [--roughness A]\n"
                 "                    [--variant ungated|gated_db23|gated|dual_gated|unbiased] [--size WxH] [--out PATH.exr]\n",
                 problem.c_str());
    std::exit(2);
}

struct settings {
    scene_options scene;
    std::string out = "glint_lights.exr";
};

settings parse(int argc, char** argv) {
    settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--light") {
            const std::string v = value();
            if (v == "point") s.scene.light = light_type::point;
            else if (v == "sun") s.scene.light = light_type::sun;
            else if (v == "area") s.scene.light = light_type::area;
            else usage("--light must be point, sun or area, got '" + v + "'");
        } else if (a == "--smooth") {
            s.scene.smooth = true;
        } else if (a == "--seed") {
            s.scene.seed = static_cast<std::uint32_t>(parse_float(a, value(), 0, 4e9f, usage));
        } else if (a == "--density") {
            s.scene.log_density = parse_float(a, value(), -20, 40, usage);
        } else if (a == "--roughness") {
            s.scene.roughness = parse_float(a, value(), 1e-4f, 1, usage);
        } else if (a == "--variant") {
            const std::string v = value();
            bool found = false;
            for (int k = 0; k <= 4; ++k)
                if (v == glint::name(static_cast<glint::binomial_variant>(k))) s.scene.variant = static_cast<glint::binomial_variant>(k), found = true;
            if (!found) usage("unknown --variant '" + v + "'");
        } else if (a == "--size") {
            const std::string v = value();
            int w = 0, h = 0;
            char x = 0;
            if (std::sscanf(v.c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 1 || h < 1 || w > 16384 || h > 16384)
                usage("--size needs WxH with 1 <= W, H <= 16384, got '" + v + "'");
            s.scene.width = w, s.scene.height = h;
        } else if (a == "--out") {
            s.out = value();
            if (s.out.size() < 5 || s.out.substr(s.out.size() - 4) != ".exr") usage("--out must end in .exr, got '" + s.out + "'");
        } else if (a == "--help" || a == "-h") {
            usage("renders a glinty sphere and plane");
        } else {
            usage("unknown argument '" + a + "'");
        }
    }
    return s;
}


}  // namespace

int main(int argc, char** argv) {
    const settings s = parse(argc, argv);
    const int w = s.scene.width, h = s.scene.height;
    const camera cam(w, h);
    light_setup ls;
    ls.type = s.scene.light;
    std::vector<float> rgb(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    std::atomic<int> next_row{0}, rows_done{0};
    std::atomic<std::uint64_t> draws{0};
    const auto start = std::chrono::steady_clock::now();
    auto work = [&]() {
        shading_counters c;
        for (int y = next_row++; y < h; y = next_row++) {
            for (int x = 0; x < w; ++x) {
                const vec3 L = render_pixel(s.scene, ls, cam, x, y, c);
                const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
                rgb[i] = L.x, rgb[i + 1] = L.y, rgb[i + 2] = L.z;
            }
            ++rows_done;
        }
        draws += c.draws;
    };
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    while (rows_done < h) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "\rglint_lights: %s light, %s, %dx%d: %3d%% (%.1f s)", name(s.scene.light), s.scene.smooth ? "smooth" : "glints",
                     w, h, 100 * rows_done.load() / h, secs);
    }
    for (auto& t : pool) t.join();
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "\rglint_lights: %s light, %s, %dx%d: 100%% in %.2f s on %u threads, %.1f binomial draws per pixel\n",
                 name(s.scene.light), s.scene.smooth ? "smooth" : "glints", w, h, secs, threads,
                 static_cast<double>(draws.load()) / (static_cast<double>(w) * h));
    try {
        glint::io::write_exr(s.out, w, h, rgb);
        std::vector<std::uint8_t> preview(rgb.size());
        for (std::size_t i = 0; i < rgb.size(); ++i) preview[i] = to_srgb8(rgb[i], 1.6f);
        const std::string png = s.out.substr(0, s.out.size() - 4) + ".png";
        write_png(png, w, h, preview);
        std::printf("wrote %s and %s\n", s.out.c_str(), png.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_lights: %s\n", e.what());
        return 1;
    }
    return 0;
}
