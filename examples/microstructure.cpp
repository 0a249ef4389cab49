// glint_microstructure: a silver sphere on a silver plane, both normal-mapped with a
// microstructure (YHMR16 Gaussian elements, glint/gaussian.hpp), under a point light or an
// environment map, ray cast on the CPU with every core; writes OpenEXR and a PNG preview. The
// BRDF is XTXW24 Eq. 1 with each pixel's footprint P-NDF, so glints resolve up close and blend
// into a smooth highlight far away.
//
//   glint_microstructure [--pattern brushed|noise|flakes|scratches|leather | --normal-map PATH]
//                        [--texels-per-unit T] [--sigma-r S] [--light point|env] [--env PATH.exr]
//                        [--close] [--size WxH] [--out PATH.exr] [--prefilter TAU]
//                        [--example-size N [--ndf-map] [--placement tiled|stochastic] [--cell C]
//                         [--rotation MIN,MAX] [--scale MIN,MAX] [--flip P]]
//                        [--map-size N] [--bin-map [--bins N] [--kernel box|tent|beckmann]]
//                        [--lobe-tree [--quilt-size N] [--delta-k D]]
//
// With --example-size the surface is covered by copies of an N x N example of the pattern
// (XTXW24's tiny example): tiled, or one randomly rotated, scaled and mirrored copy per cell of C
// texels (degrees for --rotation). --ndf-map shades it with the example's NDF maps
// (glint/ndf_map.hpp); without it, with the direct P-NDF of the same layout (the example's
// element hierarchy when tiled, the element path of every copy when stochastic), for comparison.
//
// --map-size sets the procedural map's side (default 256). --bin-map shades the map with its
// inverse bin map (glint/bin_map.hpp, AKKW) instead of the P-NDF: each pixel's ray-differential
// parallelogram, the microfacet NDF of n^2 half-vector bins (default n = ceil(3.6 / alpha) with the
// flake roughness alpha = sqrt(2) sigma_r) and the beckmann kernel unless --kernel says otherwise.
//
// --lobe-tree quilts the map (the sample: give it a small --map-size, e.g. 128) into an implicit
// N x N map (default 2048) and shades that with its lobe forest (glint/lobe_tree.hpp, ZXW), with
// K-lobes at the cluster coefficient delta_k (default 0.4, ZXW's leather).
//
// --prefilter TAU builds the direct P-NDF with node NDF images (gaussian_params::prefilter_spread,
// in (0, 0.5]; 0.5 errs by about 0.5% in L1 on flakes, docs/microstructure.md): far pixels, whose
// footprints cover many texels, then shade faster, at about twice the hierarchy's memory.
//
// The environment is lit as 64 directional lights drawn once from its luminance (the same for
// every pixel, each weighted by radiance / pdf): an estimate of the environment integral that
// stays cheap for any footprint, since each light costs one P-NDF evaluation.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <glint/bin_map.hpp>
#include <glint/lobe_tree.hpp>
#include <glint/gaussian.hpp>
#include <glint/ndf_map.hpp>
#include <glint/io/exr.hpp>
#include <glint/io/normal_map.hpp>
#include <glint/patterns.hpp>

#include "lights_scene.hpp"
#include "support/cli.hpp"
#include "support/render.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_microstructure: %s\n"
                 "usage: glint_microstructure [--pattern brushed|noise|flakes|scratches|leather | --normal-map PATH]\n"
                 "                            [--texels-per-unit T] [--sigma-r S] [--light point|env] [--env PATH.exr]\n"
                 "                            [--close] [--size WxH] [--out PATH.exr] [--prefilter TAU]\n"
                 "                            [--example-size N [--ndf-map] [--placement tiled|stochastic] [--cell C]\n"
                 "                             [--rotation MIN,MAX] [--scale MIN,MAX] [--flip P]]\n"
                 "                            [--map-size N] [--bin-map [--bins N] [--kernel box|tent|beckmann]]\n"
                 "                            [--lobe-tree [--quilt-size N] [--delta-k D]]\n",
                 problem.c_str());
    std::exit(2);
}

struct directional {
    vec3 direction, radiance_over_pdf;
};

// 64 directions from the map's luminance x sin(theta) (stratified inversion of the row and
// column CDFs), each with L / pdf (pdf per solid angle).
std::vector<directional> environment_lights(const glint::io::rgb_image& img, int count) {
    const int w = img.width, h = img.height;
    std::vector<double> rows(static_cast<std::size_t>(h) + 1, 0.0), cols(static_cast<std::size_t>(w * h) + static_cast<std::size_t>(h), 0.0);
    const auto lum = [&](int x, int y) {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
        return 0.2126 * static_cast<double>(img.rgb[i]) + 0.7152 * static_cast<double>(img.rgb[i + 1]) + 0.0722 * static_cast<double>(img.rgb[i + 2]) + 1e-6;
    };
    for (int y = 0; y < h; ++y) {
        const double st = std::sin(3.141592653589793 * (y + 0.5) / h);
        double* c = &cols[static_cast<std::size_t>(y) * static_cast<std::size_t>(w + 1)];
        for (int x = 0; x < w; ++x) c[x + 1] = c[x] + lum(x, y) * st;
        rows[static_cast<std::size_t>(y) + 1] = rows[static_cast<std::size_t>(y)] + c[w];
    }
    std::vector<directional> lights;
    for (int k = 0; k < count; ++k) {
        const double u1 = (k + 0.5) / count, u2 = std::fmod((k + 0.5) * 0.6180339887498949, 1.0);
        const int y = static_cast<int>(std::upper_bound(rows.begin(), rows.end(), u1 * rows.back()) - rows.begin()) - 1;
        const double* c = &cols[static_cast<std::size_t>(y) * static_cast<std::size_t>(w + 1)];
        const int x = static_cast<int>(std::upper_bound(c, c + w + 1, u2 * c[w]) - c) - 1;
        const double theta = 3.141592653589793 * (y + 0.5) / h, phi = (((x + 0.5) / w) - 0.5) * 2 * 3.141592653589793;
        const vec3 d(static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)), static_cast<float>(-std::sin(theta) * std::cos(phi)));
        // pdf per solid angle: (lum sin / total) per texel over the texel's solid angle (2 pi^2 sin / (w h)).
        const double p_texel = lum(x, y) * std::sin(theta) / rows.back();
        const double pdf = p_texel * w * h / (2 * 3.141592653589793 * 3.141592653589793 * std::sin(theta));
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
        lights.push_back({d, vec3(img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]) / static_cast<float>(pdf * count)});
    }
    return lights;
}

// "A,B" as two numbers in [lo, hi] with A <= B; otherwise usage().
void parse_range(const std::string& flag, const std::string& v, float lo, float hi, float& a, float& b) {
    const std::size_t comma = v.find(',');
    if (comma == std::string::npos) usage(flag + " needs MIN,MAX, got '" + v + "'");
    a = parse_float(flag, v.substr(0, comma), lo, hi, usage);
    b = parse_float(flag, v.substr(comma + 1), lo, hi, usage);
    if (a > b) usage(flag + " needs MIN <= MAX, got '" + v + "'");
}

}  // namespace

int main(int argc, char** argv) {
    std::string pattern = "brushed", map_path, light = "point", env_path = std::string(GLINT_DATA_DIR) + "/envmaps/studio.exr", out = "glint_microstructure.exr";
    float texels_per_unit = 600.0f, sigma_r = 0.01f, prefilter = 0;
    bool close = false, use_map = false, use_bins = false, use_lobes = false;
    int quilt_size = 2048;
    float delta_k = 0.4f;
    int w = 640, h = 400, example_size = 0, map_size = 256, bins = 0;
    std::string kernel = "beckmann";
    std::string placement_kind = "tiled";
    float cell = 0, rot0 = 0, rot1 = 360, scale0 = 0.8f, scale1 = 1.25f, flip = 0.5f;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return flag_value(argc, argv, i, usage); };
        if (a == "--pattern") pattern = value();
        else if (a == "--normal-map") map_path = value();
        else if (a == "--texels-per-unit") texels_per_unit = parse_float(a, value(), 1, 1e6f, usage);
        else if (a == "--sigma-r") sigma_r = parse_float(a, value(), 1e-4f, 1, usage);
        else if (a == "--prefilter") prefilter = parse_float(a, value(), 0, 0.5f, usage);
        else if (a == "--light") {
            light = value();
            if (light != "point" && light != "env") usage("--light must be point or env, got '" + light + "'");
        } else if (a == "--env") env_path = value();
        else if (a == "--close") close = true;
        else if (a == "--size") parse_size(a, value(), w, h, usage);
        else if (a == "--out") out = parse_exr_path(a, value(), usage);
        else if (a == "--example-size") {
            example_size = static_cast<int>(parse_float(a, value(), 4, 256, usage));
            if ((example_size & (example_size - 1)) != 0) usage("--example-size must be a power of two in [4, 256]");
        } else if (a == "--ndf-map") use_map = true;
        else if (a == "--placement") {
            placement_kind = value();
            if (placement_kind != "tiled" && placement_kind != "stochastic") usage("--placement must be tiled or stochastic, got '" + placement_kind + "'");
        } else if (a == "--cell") cell = parse_float(a, value(), 1, 1e5f, usage);
        else if (a == "--rotation") parse_range(a, value(), -3600, 3600, rot0, rot1);
        else if (a == "--scale") parse_range(a, value(), 0.01f, 100, scale0, scale1);
        else if (a == "--flip") flip = parse_float(a, value(), 0, 1, usage);
        else if (a == "--map-size") map_size = static_cast<int>(parse_float(a, value(), 4, 65536, usage));
        else if (a == "--bin-map") use_bins = true;
        else if (a == "--lobe-tree") use_lobes = true;
        else if (a == "--quilt-size") quilt_size = static_cast<int>(parse_float(a, value(), 16, 65536, usage));
        else if (a == "--delta-k") delta_k = parse_float(a, value(), 0, 1e4f, usage);
        else if (a == "--bins") bins = static_cast<int>(parse_float(a, value(), 1, 4096, usage));
        else if (a == "--kernel") {
            kernel = value();
            if (kernel != "box" && kernel != "tent" && kernel != "beckmann") usage("--kernel must be box, tent or beckmann, got '" + kernel + "'");
        }
        else if (a == "--help" || a == "-h") usage("renders normal-mapped microstructure");
        else usage("unknown argument '" + a + "'");
    }
    if (use_map && example_size == 0) usage("--ndf-map needs --example-size");
    if (prefilter > 0 && (example_size > 0 || use_bins || use_lobes)) usage("--prefilter is for the direct P-NDF of a map: leave out --example-size, --bin-map and --lobe-tree");
    if (use_bins && example_size > 0) usage("--bin-map shades a whole map: leave out --example-size");
    if (use_lobes && (use_bins || example_size > 0)) usage("--lobe-tree quilts the map: leave out --bin-map and --example-size");
    if (example_size == 0 && (placement_kind != "tiled" || cell > 0)) usage("--placement and --cell need --example-size");
    glint::normal_map map;
    std::vector<directional> env_lights;
    try {
        if (!map_path.empty()) {
            map = glint::io::read_normal_map(map_path);
        } else {
            glint::pattern_params p;
            p.kind = glint::parse_pattern(pattern);
            p.width = p.height = example_size > 0 ? example_size : map_size;
            p.count = static_cast<int>(150.0 * p.width * p.height / (512.0 * 512.0));  // scratched_metal: 150 segments per 512^2
            p.seed = 3;
            p.slope_rms = p.kind == glint::pattern::flakes ? 0.12 : p.kind == glint::pattern::scratches ? 0.1 : 0.15;
            if (p.kind == glint::pattern::scratched_metal) p.slope_rms = 0.12;
            p.feature = p.kind == glint::pattern::leather ? 24 : 10;
            if (example_size > 0) p.feature = std::min(p.feature, example_size / (p.kind == glint::pattern::leather ? 2.5 : 5.0));
            map = glint::make_normal_map(p);
        }
        if (light == "env") env_lights = environment_lights(glint::io::read_exr(env_path), 64);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_microstructure: %s\n", e.what());
        return 1;
    }
    // The shading's P-NDF: the direct one of the whole map (or of the tiled example), the NDF map,
    // or the element path of a stochastic layout.
    const bool stochastic = placement_kind == "stochastic";
    const auto t0 = std::chrono::steady_clock::now();
    glint::gaussian_params<float> g;
    g.sigma_r = sigma_r;
    g.prefilter_spread = prefilter;
    glint::gaussian_pndf<float> pndf;
    glint::ndf_map<float> ndf;
    glint::ndf_placement<float> layout = glint::ndf_placement<float>::tiled();
    glint::bin_map<float> bin_map;
    glint::lobe_forest<float> forest;
    float bin_alpha_g = 0;
    try {
        if (use_lobes) {
            glint::quilt_params q;
            q.width = q.height = quilt_size;
            const auto quilted = glint::quilted_map::synthesize(map, q);
            const double synth = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            glint::lobe_params<float> l;
            l.sigma_r = sigma_r;
            glint::cluster_params<float> c;
            c.delta_k = delta_k;
            forest = glint::lobe_forest<float>::build(quilted, l, c);
            std::fprintf(stderr,
                         "glint_microstructure: %d x %d sample quilted into %d x %d (%d blocks) in %.2f s; lobe forest: %zu sample and %zu boundary lobes, "
                         "%zu K-lobes (delta_k %g), %.1f MB, built in %.2f s\n",
                         map.width(), map.height(), quilted.width(), quilted.height(), quilted.blocks_x() * quilted.blocks_y(), synth, forest.report().sample_lobes,
                         forest.report().boundary_lobes, forest.report().klobes, static_cast<double>(delta_k), static_cast<double>(forest.bytes()) / 1e6,
                         forest.report().seconds);
        } else if (use_bins) {
            glint::bin_map_options o;
            o.alpha = std::sqrt(2.0) * static_cast<double>(sigma_r);
            o.bins_per_side = bins > 0 ? bins : static_cast<int>(std::ceil(3.6 / o.alpha));
            o.kernel = kernel == "box" ? glint::bin_kernel::box : kernel == "tent" ? glint::bin_kernel::tent : glint::bin_kernel::beckmann;
            bin_map = glint::bin_map<float>::build(map, o);
            // Smith's roughness from the map's mean squared slope and the flake lobes' (as the P-NDF's alpha_g).
            double slope2 = 0;
            for (const glm::vec3& n : map.normals()) slope2 += static_cast<double>(n.x * n.x + n.y * n.y) / static_cast<double>(n.z * n.z);
            bin_alpha_g = static_cast<float>(std::sqrt(slope2 / static_cast<double>(map.normals().size()) + o.alpha * o.alpha));
            std::fprintf(stderr, "glint_microstructure: %d x %d map, bin map of %d^2 bins (%s), %.1f MB (%.2f bytes per texel), built in %.2f s\n", map.width(),
                         map.height(), o.bins_per_side, kernel.c_str(), static_cast<double>(bin_map.memory_bytes()) / 1e6,
                         static_cast<double>(bin_map.memory_bytes()) / (static_cast<double>(map.width()) * map.height()), bin_map.statistics().build_seconds);
        } else if (example_size > 0 && (use_map || stochastic)) {
            glint::ndf_map_params mp;
            mp.sigma_r = sigma_r;
            ndf = glint::ndf_map<float>::build(map, mp);
            if (stochastic)
                layout = glint::ndf_placement<float>::stochastic(cell > 0 ? cell : static_cast<float>(example_size), 7u,
                                                                 glm::vec2(rot0, rot1) * 0.017453292f, glm::vec2(scale0, scale1), flip);
            std::fprintf(stderr, "glint_microstructure: %d x %d example, %d levels, %d^2 bins per tile, %.1f MB of images, built in %.2f s\n", example_size,
                         example_size, ndf.levels(), ndf.resolution(), static_cast<double>(ndf.image_bytes()) / 1e6, ndf.build_seconds());
        } else {
            pndf = glint::gaussian_pndf<float>::build(map, g);
            std::fprintf(stderr, "glint_microstructure: %d x %d map, %zu elements, hierarchy %d^2 finest cells, %.1f MB (%.1f MB of node images), built in %.2f s\n",
                         map.width(), map.height(), pndf.element_count(), pndf.grid_size(), static_cast<double>(pndf.memory_bytes()) / 1e6,
                         static_cast<double>(pndf.prefilter_bytes()) / 1e6,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_microstructure: %s\n", e.what());
        return 1;
    }
    const bool by_map = example_size > 0 && use_map, by_elements = example_size > 0 && stochastic && !use_map;
    const float alpha_g = use_lobes ? forest.alpha_g() : use_bins ? bin_alpha_g : by_map || by_elements ? ndf.alpha_g() : pndf.alpha_g();
    const auto pndf_at = [&](const glint::texel_footprint<float>& fp, const glm::vec2& s) {
        if (use_lobes) return forest.eval(fp, s);
        if (by_map) return ndf.eval(layout, fp, s);
        if (by_elements) return ndf.eval_direct(layout, fp, s);
        return pndf.eval(fp, s);
    };
    const camera cam = close ? camera(w, h, vec3(0.45f, 1.05f, 1.5f), vec3(0.1f, 0.7f, 0.3f)) : camera(w, h);
    const light_setup ls{light_type::point};
    const float tex_per_uv = texels_per_unit / uv_per_unit;
    std::vector<float> rgb;
    const auto shade = [&](int, int, const vec3& d, const hit& ht, const vec2& duvdx, const vec2& duvdy) {
        vec3 L(0);
        const auto fp = glint::footprint_from_uv_derivatives(ht.uv, duvdx, duvdy, tex_per_uv);
        // The bin map's footprint: the pixel's parallelogram in the map's [0, 1)^2.
        const vec2 to_map = vec2(tex_per_uv / static_cast<float>(map.width()), tex_per_uv / static_cast<float>(map.height()));
        const auto A = glint::uv_parallelogram<float>::from_differentials(ht.uv * to_map, duvdx * to_map, duvdy * to_map);
        const vec3 wo = to_local(ht, -d);
        const auto add = [&](const vec3& wi_world, const vec3& radiance) {
            const vec3 wi = to_local(ht, wi_world);
            if (!(wi.z > 0) || !(wo.z > 0)) return;
            const vec3 hv = glm::normalize(wi + wo);
            if (!(hv.z > 0)) return;
            // One P-NDF value per light; the Fresnel term per channel (XTXW24 Eq. 1).
            const float dp = use_bins ? bin_map.eval(A, hv).ndf : pndf_at(fp, glm::vec2(hv.x, hv.y));
            if (!(dp > 0)) return;
            for (int c = 0; c < 3; ++c)
                L[c] += glint::detail::glsl::kernels<float>::glint_pndf_brdf(dp, wi, wo, static_cast<int>(glint::ndf::beckmann), glm::vec2(alpha_g), silver_eta[c],
                                                                             silver_k[c]) *
                        wi.z * radiance[c];
        };
        if (light == "point") {
            const vec3 dl = ls.position - ht.p;
            add(glm::normalize(dl), vec3(ls.intensity / glm::dot(dl, dl)));
            L += vec3(0.004f, 0.0036f, 0.0032f);  // a faint ambient so the surfaces read
        } else {
            for (const auto& e : env_lights) add(e.direction, e.radiance_over_pdf);
        }
        return L;
    };
    const auto miss = [&](const vec3& d) { return light == "env" ? vec3(0.02f) : background(d); };
    const render_timing t = render_scene(cam, "glint_microstructure: rendering " + std::to_string(w) + "x" + std::to_string(h), rgb, shade, miss);
    std::fprintf(stderr, "\rglint_microstructure: rendered %dx%d (%s, %s) in %.2f s on %u threads\n", w, h, map_path.empty() ? pattern.c_str() : map_path.c_str(),
                 light.c_str(), t.seconds, t.threads);
    try {
        write_exr_and_preview(out, w, h, rgb, light == "env" ? 1.5f : 2.0f);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_microstructure: %s\n", e.what());
        return 1;
    }
    return 0;
}
