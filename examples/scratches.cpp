// glint_scratches: a scratched steel sphere on a scratched steel plane (RGB16's SV-BRDF,
// glint/scratch.hpp) under a point light or an environment map, ray cast on the CPU with every
// core; writes OpenEXR and a PNG preview. Each pixel's footprint sets the scratch layers' areas
// (the coverage pyramid), so scratches resolve into glint lines up close and into a smeared
// highlight far away.
//
//   glint_scratches [--pattern brushed|scratched|swirl|turned] [--profile quartic|shallow|v|deep|ramp]
//                   [--bounces N] [--layers K] [--light point|env] [--env PATH.exr] [--distance D]
//                   [--spp N] [--size WxH] [--out PATH.exr]
//
// Patterns (RGB16 Table 1 rows): brushed = Fig. 10b (6 layers within 5 degrees), scratched = Fig.
// 10f (32 layers, all angles), swirl = 64 layers, all angles, denser (the lit scratches ring the
// highlight), turned = concentric turning marks on the plane (a tangent field, Fig. 15); --layers
// overrides the pattern's layer count (0: the base BRDF alone). Profiles:
// quartic D/W 0.5 (steep) or 0.05 (shallow), V-grooves of 35 or 60 degree facets (v, deep), a
// 30-degree ramp. --bounces caps the inter-reflections in the table (1: single scattering, what a
// normal map would give; light that needs more bounces is lost).
// The base between the scratches is polished steel (GGX, alpha 0.03, exact iron Fresnel).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <glint/io/exr.hpp>
#include <glint/microfacet.hpp>
#include <glint/scratch.hpp>

#include "lights_scene.hpp"
#include "support/cli.hpp"
#include "support/render.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_scratches: %s\n"
                 "usage: glint_scratches [--pattern brushed|scratched|swirl|turned] [--profile quartic|shallow|v|deep|ramp]\n"
                 "                       [--bounces N] [--layers K] [--light point|env] [--env PATH.exr] [--distance D]\n"
                 "                       [--spp N] [--size WxH] [--out PATH.exr]\n",
                 problem.c_str());
    std::exit(2);
}

// Iron at 650 nm (RGB16 Fig. 7), grey, for the base.
constexpr float iron_eta = 2.91f, iron_k = 3.09f;
constexpr float base_alpha = 0.03f;

// The base BRDF times cos(theta_i): GGX with exact conductor Fresnel.
float base_brdf_cos(const vec3& wi, const vec3& wo) {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0;
    const vec3 m = glm::normalize(wi + wo);
    const vec2 a(base_alpha);
    return glint::ndf_value(glint::ndf::ggx, m, a) * glint::smith_g2(glint::ndf::ggx, wi, wo, m, a) *
           glint::fresnel_conductor(iron_eta, iron_k, glm::dot(wi, m)) / (4 * wo.z);
}

// The environment by direction (nearest texel of the equirectangular map, glint's convention).
struct envmap {
    glint::io::rgb_image img;
    vec3 operator()(const vec3& d) const {
        const vec2 uv = glint::detail::glsl::kernels<float>::glint_equirect_uv(d);
        const int x = std::min(img.width - 1, std::max(0, static_cast<int>(uv.x * static_cast<float>(img.width))));
        const int y = std::min(img.height - 1, std::max(0, static_cast<int>(uv.y * static_cast<float>(img.height))));
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x));
        return {img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]};
    }
};

float hash01(std::uint32_t a, std::uint32_t b, std::uint32_t c) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(a, b, c)).x); }

}  // namespace

int main(int argc, char** argv) {
    std::string pattern = "scratched", profile = "quartic", light = "point", env_path = std::string(GLINT_DATA_DIR) + "/envmaps/studio.exr",
                out = "glint_scratches.exr";
    int w = 640, h = 400, bounces = 64, spp = 32, layers = -1;
    float distance = 1.0f;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return flag_value(argc, argv, i, usage); };
        if (a == "--pattern") {
            pattern = value();
            if (pattern != "brushed" && pattern != "scratched" && pattern != "swirl" && pattern != "turned")
                usage("--pattern must be brushed, scratched, swirl or turned, got '" + pattern + "'");
        } else if (a == "--profile") {
            profile = value();
            if (profile != "quartic" && profile != "shallow" && profile != "v" && profile != "deep" && profile != "ramp")
                usage("--profile must be quartic, shallow, v, deep or ramp, got '" + profile + "'");
        } else if (a == "--bounces") bounces = static_cast<int>(parse_float(a, value(), 1, 4096, usage));
        else if (a == "--layers") layers = static_cast<int>(parse_float(a, value(), 0, 64, usage));
        else if (a == "--light") {
            light = value();
            if (light != "point" && light != "env") usage("--light must be point or env, got '" + light + "'");
        } else if (a == "--env") env_path = value();
        else if (a == "--distance") distance = parse_float(a, value(), 0.05f, 50, usage);
        else if (a == "--spp") spp = static_cast<int>(parse_float(a, value(), 1, 4096, usage));
        else if (a == "--size") parse_size(a, value(), w, h, usage);
        else if (a == "--out") out = parse_exr_path(a, value(), usage);
        else if (a == "--help" || a == "-h") usage("renders scratched metal (RGB16)");
        else usage("unknown argument '" + a + "'");
    }
    const double deg = 0.017453292519943295769;
    glint::scratch_distribution dist;
    if (pattern == "brushed") dist.layers = 6, dist.spread_deg = 5, dist.length = 0.1, dist.width = 5e-4, dist.density = 0.16;
    else if (pattern == "scratched") dist.layers = 32, dist.spread_deg = 360, dist.length = 0.1, dist.width = 2e-4, dist.density = 0.05;
    else if (pattern == "swirl") dist.layers = 64, dist.spread_deg = 360, dist.length = 0.1, dist.width = 2e-4, dist.density = 0.08;
    else dist.layers = 4, dist.spread_deg = 2, dist.length = 0.3, dist.width = 3e-4, dist.density = 0.3;
    if (layers >= 0) dist.layers = layers;  // the pattern's layer count otherwise
    dist.seed = 7;
    envmap env;
    glint::scratch_table table;
    glint::scratch_material material;
    try {
        if (light == "env") env.img = glint::io::read_exr(env_path);
        const glint::scratch_profile p = profile == "quartic" ? glint::make_quartic_groove(0.5)
                                         : profile == "shallow" ? glint::make_quartic_groove(0.05)
                                         : profile == "v" ? glint::make_v_groove(35 * deg)
                                         : profile == "deep" ? glint::make_v_groove(60 * deg)
                                                          : glint::make_ramp_profile(30 * deg);
        glint::scratch_table_options o;
        o.max_bounces = bounces;
        o.progress = [](int done, int rows) {
            if (done % 32 == 0 || done == rows) std::fprintf(stderr, "\rglint_scratches: table %3d%%", 100 * done / rows);
        };
        const auto t0 = std::chrono::steady_clock::now();
        table = glint::build_scratch_table(p, glint::scratch_fresnel::iron(), o);
        const double t_table = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const auto t1 = std::chrono::steady_clock::now();
        material = glint::scratch_material::build(table, dist);
        std::fprintf(stderr, "\rglint_scratches: %s profile, table %d^2 in %.2f s (lost %.1e at %d bounces), %d layers, coverage %d^2 in %.2f s, %.1f MB\n",
                     profile.c_str(), table.resolution(), t_table, table.lost_fraction(), bounces, dist.layers, material.coverage_resolution(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count(), static_cast<double>(material.memory_bytes()) / 1e6);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_scratches: %s\n", e.what());
        return 1;
    }
    const auto mview = material.view<float>();
    const vec3 target(0.0f, 0.55f, 0.0f), eye0(0.0f, 1.25f, 4.2f);
    const camera cam(w, h, target + (eye0 - target) * distance, target);
    const light_setup ls{light_type::point};
    const float to_surface = 1.0f / uv_per_unit;  // scratch sizes are in scene units
    const vec2 turn_centre(0.0f, 0.0f);
    std::vector<float> rgb;
    const auto shade = [&](int x, int y, const vec3& d, const hit& ht, const vec2& duvdx, const vec2& duvdy) {
        const vec3 wo = to_local(ht, -d);
        if (!(wo.z > 0)) return vec3(0);
        // Surface coordinates and the footprint's axes (sd sigma_pix = 1/2 pixel, as the P-NDF's),
        // in scene units; a tangent-space frame whose u is the surface tangent.
        vec2 p = ht.uv * to_surface, a = 0.5f * duvdx * to_surface, b = 0.5f * duvdy * to_surface;
        vec3 tangent(1, 0, 0);
        if (pattern == "turned" && !ht.sphere) {
            const auto q = glint::scratch_turned<float>(p, turn_centre);
            const auto qa = glint::scratch_turned<float>(p + a, turn_centre), qb = glint::scratch_turned<float>(p + b, turn_centre);
            a = qa.x - q.x, b = qb.x - q.x, p = q.x;
            tangent = vec3(q.tangent, 0);
        }
        const auto f = glint::make_scratch_frame<float>(vec3(0, 0, 1), tangent);
        const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y), key = static_cast<std::uint32_t>(x + w * y);
        const vec2 jitter(hash01(ux, uy, 1), hash01(ux, uy, 2));
        if (light == "point") {
            const vec3 dl = ls.position - ht.p;
            const vec3 wl = to_local(ht, glm::normalize(dl));
            const float E = ls.intensity / glm::dot(dl, dl);
            const auto lit = mview.light(f, p, a, b, wo, wl, E, static_cast<float>(1 * deg), 4, jitter);
            // A faint ambient so the surfaces read.
            return lit.radiance + vec3(lit.base_weight * base_brdf_cos(wl, wo) * wl.z * E) + vec3(0.004f, 0.0036f, 0.0032f);
        }
        // Importance sampling of the SV-BRDF (RGB16 Sec. 5.1): the base or a layer per sample by
        // their Eq. 4 weights; the base by GGX's visible normals.
        const auto world = [&](const vec3& v) { return v.x * ht.t + v.y * ht.b + v.z * ht.n; };
        const auto areas = mview.areas(p, a, b, jitter);
        vec3 L(0);
        for (int s = 0; s < spp; ++s) {
            const auto si = static_cast<std::uint32_t>(s);
            const float u0 = hash01(key, si, 3), u1 = hash01(key, si, 4), u2 = hash01(key, si, 5);
            const auto pick = mview.sample_with(f, areas, wo, u0, u1, u2);
            if (pick.layer >= 0) {
                if (pick.s.valid) L += pick.s.weight * env(world(pick.s.wi));
                continue;
            }
            const vec3 m = glint::sample_vndf_ggx<float>(wo, vec2(base_alpha), u1, u2);
            const vec3 wi = glm::reflect(-wo, m);
            if (!(wi.z > 0)) continue;
            const float g1 = glint::smith_g1(glint::ndf::ggx, wo, m, vec2(base_alpha));
            L += glint::fresnel_conductor(iron_eta, iron_k, glm::dot(wo, m)) * glint::smith_g2(glint::ndf::ggx, wi, wo, m, vec2(base_alpha)) / std::max(g1, 1e-6f) *
                 env(world(wi));
        }
        return L / static_cast<float>(spp);
    };
    const auto miss = [&](const vec3& d) { return light == "env" ? env(d) : background(d); };
    const render_timing t = render_scene(cam, "glint_scratches: rendering " + std::to_string(w) + "x" + std::to_string(h), rgb, shade, miss);
    std::fprintf(stderr, "\rglint_scratches: rendered %dx%d (%s, %s light, distance %.2f) in %.2f s on %u threads\n", w, h, pattern.c_str(), light.c_str(),
                 static_cast<double>(distance), t.seconds, t.threads);
    try {
        write_exr_and_preview(out, w, h, rgb, light == "env" ? 1.0f : 2.0f);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_scratches: %s\n", e.what());
        return 1;
    }
    return 0;
}
