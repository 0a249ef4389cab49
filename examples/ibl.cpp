// glint_ibl: a glinty silver sphere under an environment map (image-based lighting of glints,
// KK25 Sec. 4-5), rendered on the CPU with every core; writes OpenEXR and a PNG preview.
//
//   glint_ibl [--env PATH.exr] [--k 4|8] [--smooth] [--seed N] [--density LOG] [--roughness A]
//             [--size WxH] [--out PATH.exr]
//
// Bare, it renders the showcase: the sphere in data/envmaps/sunset.exr, K = 4.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <glint/ibl.hpp>
#include <glint/io/exr.hpp>

#include "lights_scene.hpp"
#include "support/cli.hpp"
#include "support/png.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_ibl: %s\n"
                 "usage: glint_ibl [--env PATH.exr] [--k 4|8] [--smooth] [--seed N] [--density LOG] [--roughness A]\n"
                 "                 [--size WxH] [--out PATH.exr]\n",
                 problem.c_str());
    std::exit(2);
}


}  // namespace

int main(int argc, char** argv) {
    std::string env_path = std::string(GLINT_DATA_DIR) + "/envmaps/sunset.exr", out = "glint_ibl.exr";
    int K = 4, w = 640, h = 400;
    bool smooth = false;
    std::uint32_t seed = 1;
    float log_density = 5.0f, roughness = 0.12f;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--env") env_path = value();
        else if (a == "--k") {
            const std::string v = value();
            if (v != "4" && v != "8") usage("--k must be 4 or 8, got '" + v + "'");
            K = std::stoi(v);
        } else if (a == "--smooth") smooth = true;
        else if (a == "--seed") seed = static_cast<std::uint32_t>(parse_float(a, value(), 0, 4e9f, usage));
        else if (a == "--density") log_density = parse_float(a, value(), -20, 40, usage);
        else if (a == "--roughness") roughness = parse_float(a, value(), 1e-3f, 1, usage);
        else if (a == "--size") {
            const std::string v = value();
            char x = 0;
            if (std::sscanf(v.c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 1 || h < 1 || w > 16384 || h > 16384)
                usage("--size needs WxH with 1 <= W, H <= 16384, got '" + v + "'");
        } else if (a == "--out") {
            out = value();
            if (out.size() < 5 || out.substr(out.size() - 4) != ".exr") usage("--out must end in .exr, got '" + out + "'");
        } else usage("unknown argument '" + a + "'");
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
    camera cam(w, h);
    cam.eye = vec3(0.0f, 0.75f, 3.2f), cam.target = sphere_centre;
    cam.forward = glm::normalize(cam.target - cam.eye);
    cam.right = glm::normalize(glm::cross(cam.forward, vec3(0, 1, 0)));
    cam.up = glm::cross(cam.right, cam.forward);
    const float sa = std::sqrt(roughness);
    const float dh = env.total_area(roughness);
    std::vector<float> rgb(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    std::atomic<int> next_row{0}, rows_done{0};
    const auto start = std::chrono::steady_clock::now();
    auto work = [&]() {
        for (int y = next_row++; y < h; y = next_row++) {
            for (int x = 0; x < w; ++x) {
                const float fx = static_cast<float>(x) + 0.5f, fy = static_cast<float>(y) + 0.5f;
                const vec3 d = cam.ray(fx, fy);
                hit ht = intersect(cam.eye, d);
                vec3 L;
                if (!ht.found || !ht.sphere) {
                    L = env.lookup(d, 0.0f).radiance;  // the environment itself (no ground plane here)
                } else {
                    auto on_plane = [&](const vec3& dn) {
                        const float t = glm::dot(ht.p - cam.eye, ht.n) / std::min(glm::dot(dn, ht.n), -1e-6f);
                        return cam.eye + t * dn - ht.p;
                    };
                    const vec2 duvdx = uv_of_displacement(ht, on_plane(cam.ray(fx + 1, fy)));
                    const vec2 duvdy = uv_of_displacement(ht, on_plane(cam.ray(fx, fy + 1)));
                    const float cos_o = std::max(glm::dot(-d, ht.n), 1e-4f);
                    const vec3 r = glm::reflect(d, ht.n);
                    const auto s = env.lookup(r, sa);
                    float m = 1.0f;
                    if (!smooth) {
                        glint::grid_params<float> g;
                        g.log_density = log_density;
                        g.seed = seed * 0x9E3779B9u;
                        const auto e = glint::ibl_sample(ht.uv, duvdx, duvdy, g, env.levels(), s.indicators, env.visible_area(cos_o, sa), dh);
                        m = glint::modulation(e);
                    }
                    const float albedo = env.albedo(cos_o, sa);
                    for (int c = 0; c < 3; ++c) L[c] = glint::fresnel_conductor(silver_eta[c], silver_k[c], cos_o) * albedo * s.radiance[c] * m;
                }
                const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
                rgb[i] = L.x, rgb[i + 1] = L.y, rgb[i + 2] = L.z;
            }
            ++rows_done;
        }
    };
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    while (rows_done < h) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        std::fprintf(stderr, "\rglint_ibl: rendering %dx%d: %3d%%", w, h, 100 * rows_done.load() / h);
    }
    for (auto& t : pool) t.join();
    std::fprintf(stderr, "\rglint_ibl: rendered %dx%d (%s, K = %d) in %.2f s on %u threads\n", w, h, smooth ? "smooth" : "glints", K,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), threads);
    try {
        glint::io::write_exr(out, w, h, rgb);
        std::vector<std::uint8_t> preview(rgb.size());
        for (std::size_t i = 0; i < rgb.size(); ++i) preview[i] = to_srgb8(rgb[i], 1.2f);
        const std::string png = out.substr(0, out.size() - 4) + ".png";
        write_png(png, w, h, preview);
        std::printf("wrote %s and %s\n", out.c_str(), png.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_ibl: %s\n", e.what());
        return 1;
    }
    return 0;
}
