// glint_lights: a glinty sphere and plane under a point light, the sun or an area light,
// rendered on the CPU with every core; writes OpenEXR (linear radiance) and a PNG preview.
//
//   glint_lights [--light point|sun|area] [--smooth] [--seed N] [--density LOG]
//                [--roughness A] [--variant NAME] [--one-lattice-point] [--size WxH] [--out PATH.exr]
//
// --one-lattice-point shades each pixel's glints on one of its footprint's four lattice points
// (glint::grid_pixel_setup with a lattice_u): the same mean and per-pixel variance, cheaper.
//
// Bare, it renders the showcase: the sun glinting on the plane and the sphere.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "lights_scene.hpp"
#include "support/cli.hpp"
#include "support/render.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_lights: %s\n"
                 "usage: glint_lights [--light point|sun|area] [--smooth] [--seed N] [--density LOG] [--roughness A]\n"
                 "                    [--variant ungated|gated_db23|gated|dual_gated|unbiased] [--one-lattice-point] [--size WxH]\n"
                 "                    [--out PATH.exr]\n",
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
        auto value = [&] { return flag_value(argc, argv, i, usage); };
        if (a == "--light") {
            const std::string v = value();
            if (v == "point") s.scene.light = light_type::point;
            else if (v == "sun") s.scene.light = light_type::sun;
            else if (v == "area") s.scene.light = light_type::area;
            else usage("--light must be point, sun or area, got '" + v + "'");
        } else if (a == "--smooth") {
            s.scene.smooth = true;
        } else if (a == "--one-lattice-point") {
            s.scene.stochastic_lattice = true;
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
            parse_size(a, value(), s.scene.width, s.scene.height, usage);
        } else if (a == "--out") {
            s.out = parse_exr_path(a, value(), usage);
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
    std::atomic<std::uint64_t> draws{0};
    const std::string mode = std::string(name(s.scene.light)) + " light, " + (s.scene.smooth ? "smooth" : "glints");
    const render_timing t = render_rows(h, "glint_lights: " + mode + ", " + std::to_string(w) + "x" + std::to_string(h), [&](int y) {
        shading_counters c;
        vec3 row[256];
        for (int x0 = 0; x0 < w; x0 += 256) {  // the glint estimates batched (render_row)
            const int x1 = std::min(x0 + 256, w);
            render_row(s.scene, ls, cam, y, x0, x1, row, c);
            for (int x = x0; x < x1; ++x) {
                const vec3& L = row[x - x0];
                const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
                rgb[i] = L.x, rgb[i + 1] = L.y, rgb[i + 2] = L.z;
            }
        }
        draws += c.draws;
    });
    std::fprintf(stderr, "\rglint_lights: %s, %dx%d: 100%% in %.2f s on %u threads, %.1f binomial draws per pixel\n", mode.c_str(), w, h,
                 t.seconds, t.threads, static_cast<double>(draws.load()) / (static_cast<double>(w) * h));
    try {
        write_exr_and_preview(s.out, w, h, rgb, 1.6f);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_lights: %s\n", e.what());
        return 1;
    }
    return 0;
}
