// The scratch kernels (kernels/scratch.glsl) through Mesa llvmpipe against the C++ float path on
// the same inputs and the same table (a std430 SSBO): the frame and cone coordinates, Eq. 2 (both
// filters), Eq. 5's sampler and its pdf, Eq. 6's point light, Eq. 4's weights, Eq. 7's indicator
// and Eq. 3's footprint estimate. Decisions (a CDF bin, a Worley threshold, the light cull) flip
// where an input lies within rounding of a boundary; their rates are bounded.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <glint/glsl.hpp>
#include <glint/scratch.hpp>

#include "parity.hpp"
#include "tolerances.hpp"

namespace {

float rnd(std::uint32_t i, std::uint32_t salt) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, salt, 0x5c3au)).x); }

glm::vec3 unit(std::uint32_t i, std::uint32_t salt) {
    const float z = 2 * rnd(i, salt) - 1, a = 6.2831853f * rnd(i, salt + 1), r = std::sqrt(std::max(0.0f, 1 - z * z));
    return {r * std::cos(a), r * std::sin(a), z};
}

using K = glint::detail::glsl::kernels<float>;

struct stats {
    double worst = 0;
    std::size_t over = 0, non_finite = 0, count = 0;
    void add(float g, float c, double floor, double threshold) {
        ++count;
        non_finite += !std::isfinite(g);
        const double d = std::fabs(static_cast<double>(g) - static_cast<double>(c)) / std::max(std::fabs(static_cast<double>(c)), floor);
        worst = std::max(worst, d);
        over += d > threshold;
    }
    double rate() const { return count ? static_cast<double>(over) / static_cast<double>(count) : 0; }
};

}  // namespace

TEST_CASE("scratch kernels: GLSL against C++ (cone, Eq. 2, sampling, pdf, point light, mix, indicator, footprint)") {
    glint::scratch_fresnel gold;
    gold.model = glint::fresnel_model::conductor_exact, gold.eta = glm::dvec3(0.18, 0.42, 1.37), gold.k = glm::dvec3(3.42, 2.35, 1.77);
    glint::scratch_table_options o;
    o.resolution = 64, o.rays_per_row = 4000;
    const auto table = glint::build_scratch_table(glint::make_quartic_groove(0.5, 256), gold, o);
    const auto& data = table.data<float>();
    glint::scratch_distribution dist;
    dist.layers = 1, dist.length = 0.1f, dist.width = 0.01f, dist.density = 0.3f, dist.main_deg = 25;
    const auto layer = glint::make_scratch_layers<float>(dist)[0];
    const std::size_t n = 20000;
    const float psi = 0.0174533f;
    struct input {
        glm::vec3 n, t, wo, wl;
        float u1, u2, jitter;
        glm::vec2 x;
    };
    std::vector<input> v(n);
    std::vector<std::uint32_t> in;
    for (std::uint32_t i = 0; i < n; ++i) {
        input& q = v[i];
        q.n = unit(i, 1);
        q.n.z = std::fabs(q.n.z) + 0.2f;
        q.n = glm::normalize(q.n);
        q.t = unit(i, 3);
        const auto f = K::glint_scratch_make_frame(q.n, q.t);
        // Views over the hemisphere, a tenth near the horizon; lights within 1.5 psi of the cone.
        const float th = 1.5f * (rnd(i, 5) - 0.5f) * 2, ph = (i % 10 == 0) ? 1.5707f * (2 * rnd(i, 6) - 1) : 1.4f * (2 * rnd(i, 6) - 1);
        q.wo = K::glint_scratch_from_cone(f, glm::vec2(th, ph));
        q.wl = K::glint_scratch_from_cone(f, glm::vec2(-th + 1.5f * psi * (2 * rnd(i, 7) - 1), ph + 0.6f * (2 * rnd(i, 8) - 1)));
        q.u1 = rnd(i, 9), q.u2 = rnd(i, 10), q.jitter = rnd(i, 11);
        q.x = {rnd(i, 12) * 3, rnd(i, 13) * 3};
        glint_test::append_words(in, {q.n.x, q.n.y, q.n.z, q.t.x, q.t.y, q.t.z, q.wo.x, q.wo.y, q.wo.z, q.wl.x, q.wl.y, q.wl.z, q.u1, q.u2, q.jitter, q.x.x, q.x.y});
    }
    const auto bits = glint_test::glsl_float_bits;
    const int outs = 16;
    const std::string body =
        "    uint b = 17u * i; uint w = " + std::to_string(outs) + "u * i;\n"
        "    glint_scratch_frame f = glint_scratch_make_frame(in_vec3(b), in_vec3(b + 3u));\n"
        "    vec3 wo = in_vec3(b + 6u), wl = in_vec3(b + 9u);\n"
        "    vec2 co = glint_scratch_to_cone(f, wo), cl = glint_scratch_to_cone(f, wl);\n"
        "    out0[w] = floatBitsToUint(co.x); out0[w + 1u] = floatBitsToUint(co.y);\n"
        "    out0[w + 2u] = floatBitsToUint(glint_scratch_from_cone(f, co).x);\n"
        "    vec3 r1 = glint_scratch_rho(co.x, co.y, cl.y, 1); vec3 r0 = glint_scratch_rho(co.x, co.y, cl.y, 0);\n"
        "    out0[w + 3u] = floatBitsToUint(r1.x); out0[w + 4u] = floatBitsToUint(r1.z); out0[w + 5u] = floatBitsToUint(r0.y);\n"
        "    glint_scratch_sample s = glint_scratch_sample_cone(f, wo, in_float(b + 12u), in_float(b + 13u), 1);\n"
        "    out0[w + 6u] = floatBitsToUint(s.weight.y); out0[w + 7u] = floatBitsToUint(s.phi_i); out0[w + 8u] = floatBitsToUint(s.pdf_phi);\n"
        "    out0[w + 9u] = s.valid ? 1u : 0u;\n"
        "    out0[w + 10u] = floatBitsToUint(glint_scratch_pdf_phi(co.y, cl.y, 1));\n"
        "    out0[w + 11u] = floatBitsToUint(glint_scratch_light_radiance(f, wo, wl, 2.0, " + bits(psi) + ", 4, in_float(b + 14u), 1).x);\n"
        "    out0[w + 12u] = glint_scratch_light_reaches(f, wo, wl, " + bits(psi) + ") ? 1u : 0u;\n"
        "    glint_scratch_layer L; L.dir = vec2(" + bits(layer.dir.x) + ", " + bits(layer.dir.y) + "); L.offset = vec2(" + bits(layer.offset.x) + ", " +
           bits(layer.offset.y) + "); L.inv_length = " + bits(layer.inv_length) + "; L.inv_width = " + bits(layer.inv_width) + "; L.density = " + bits(layer.density) +
        "; L.seed = " + std::to_string(layer.seed) + "u; L.period = " + std::to_string(layer.period) + ";\n"
        "    vec2 x = vec2(in_float(b + 15u), in_float(b + 16u));\n"
        "    out0[w + 13u] = floatBitsToUint(glint_scratch_indicator(L, x));\n"
        "    out0[w + 14u] = floatBitsToUint(glint_scratch_alpha_footprint(L, x, vec2(0.02, 0.005), vec2(-0.004, 0.015), vec2(in_float(b + 13u), in_float(b + 14u))));\n"
        "    out0[w + 15u] = floatBitsToUint(glint_scratch_mix_weights(in_float(b + 12u) * 2.0).base_weight);\n";
    const auto gpu = glint_test::map_words_with_data({"core.glsl"}, "scratch.glsl", "glint_scratch_data", "GLINT_SCRATCH_BUFFER_DECLARED", body, in,
                                                     glint_test::to_words(data), n, outs);
    const auto gf = [&](std::size_t i, int k) {
        float x;
        std::memcpy(&x, &gpu[i * outs + static_cast<std::size_t>(k)], 4);
        return x;
    };
    const auto view = table.view<float>();
    stats cone, back, rho, rho0, weight, phi, pdf, pdf_at, light, footprint, mixw;
    std::size_t valid_flip = 0, reach_flip = 0, indicator_flip = 0, lit = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const input& q = v[i];
        const auto f = glint::make_scratch_frame<float>(q.n, q.t);
        const glm::vec2 co = glint::to_cone<float>(f, q.wo), cl = glint::to_cone<float>(f, q.wl);
        // Angles and unit-vector components: absolute differences.
        cone.add(gf(i, 0), co.x, 1.0, 1e-6), cone.add(gf(i, 1), co.y, 1.0, 1e-6);
        back.add(gf(i, 2), glint::from_cone<float>(f, co).x, 1.0, 1e-6);
        auto nearest = view;
        nearest.filter = glint::scratch_filter::nearest;
        const glm::vec3 r1 = view.rho(co.x, co.y, cl.y), r0 = nearest.rho(co.x, co.y, cl.y);
        rho.add(gf(i, 3), r1.x, 1e-3, 1e-4), rho.add(gf(i, 4), r1.z, 1e-3, 1e-4), rho0.add(gf(i, 5), r0.y, 1e-3, 1e-4);
        const auto s = view.sample(f, q.wo, q.u1, q.u2);
        const bool gv = gpu[i * outs + 9] != 0;
        valid_flip += gv != s.valid;
        if (gv && s.valid) {
            weight.add(gf(i, 6), s.weight.y, 1e-3, 1e-3), phi.add(gf(i, 7), s.phi_i, 1e-2, 1e-3), pdf.add(gf(i, 8), s.pdf_phi, 1e-3, 1e-3);
        }
        pdf_at.add(gf(i, 10), view.pdf_phi(co.y, cl.y), 1e-3, 1e-4);
        const glm::vec3 L = view.light_radiance(f, q.wo, q.wl, 2.0f, psi, 4, q.jitter);
        lit += L.x > 0;
        light.add(gf(i, 11), L.x, 1e-2, 1e-3);
        reach_flip += (gpu[i * outs + 12] != 0) != glint::scratch_light_reaches<float>(f, q.wo, q.wl, psi);
        indicator_flip += gf(i, 13) != glint::scratch_indicator<float>(layer, q.x);
        footprint.add(gf(i, 14), glint::scratch_alpha_footprint<float>(layer, q.x, glm::vec2(0.02f, 0.005f), glm::vec2(-0.004f, 0.015f), glm::vec2(q.u2, q.jitter)), 1.0,
                      1e-6);
        mixw.add(gf(i, 15), glint::scratch_mix_weights<float>(q.u1 * 2).base_weight, 1.0, 1e-7);
    }
    const auto report = [&](const char* name, const stats& st) {
        MESSAGE(std::string(name) << ": max difference " << st.worst << ", " << st.over << " of " << st.count << " beyond its threshold (rate " << st.rate() << ")");
        CHECK(st.non_finite == 0u);
    };
    report("cone coordinates", cone);
    report("from_cone", back);
    report("rho linear", rho);
    report("rho nearest", rho0);
    report("sample weight", weight);
    report("sample phi", phi);
    report("sample pdf", pdf);
    report("pdf_phi", pdf_at);
    report("point light", light);
    report("footprint alpha", footprint);
    report("mix", mixw);
    MESSAGE("flips: valid " << valid_flip << ", light cull " << reach_flip << ", indicator " << indicator_flip << " of " << n << "; " << lit << " lit");
    CHECK(lit > n / 4);
    CHECK(cone.worst < SCRATCH_CONE_GLSL_MAX_ABSOLUTE);
    CHECK(back.worst < SCRATCH_CONE_GLSL_MAX_ABSOLUTE);
    CHECK(rho.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(rho0.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(weight.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(pdf.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(pdf_at.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(light.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(footprint.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(static_cast<double>(valid_flip + reach_flip + indicator_flip) / n <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(mixw.worst == 0);
}

TEST_CASE("scratch material: GLSL against C++ (pyramid footprint area, SV-BRDF point light, layer pick)") {
    glint::scratch_table_options o;
    o.resolution = 32, o.rays_per_row = 2000;
    const auto table = glint::build_scratch_table(glint::make_v_groove(0.5), glint::scratch_fresnel::iron(), o);
    glint::scratch_distribution d;
    d.layers = 8, d.spread_deg = 360, d.length = 0.05, d.width = 0.004, d.density = 0.35, d.period = 32;
    const auto m = glint::scratch_material::build(table, d);
    const auto view = m.view<float>();
    const std::size_t n = 5000;
    std::vector<std::uint32_t> in;
    struct input {
        glm::vec3 wo, wl;
        glm::vec2 x, a, b, jitter;
        float u0;
    };
    std::vector<input> v(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        input& q = v[i];
        q.wo = unit(i, 21), q.wo.z = std::fabs(q.wo.z) + 0.1f, q.wo = glm::normalize(q.wo);
        q.wl = unit(i, 23), q.wl.z = std::fabs(q.wl.z) + 0.1f, q.wl = glm::normalize(q.wl);
        q.x = {rnd(i, 25), rnd(i, 26)};
        const float size = std::exp2(-14 + 12 * rnd(i, 27)), r = 6.2831853f * rnd(i, 28);
        q.a = size * glm::vec2(std::cos(r), std::sin(r)), q.b = 0.4f * size * glm::vec2(-std::sin(r), std::cos(r));
        q.jitter = {rnd(i, 29), rnd(i, 30)};
        q.u0 = rnd(i, 31);
        glint_test::append_words(in, {q.wo.x, q.wo.y, q.wo.z, q.wl.x, q.wl.y, q.wl.z, q.x.x, q.x.y, q.a.x, q.a.y, q.b.x, q.b.y, q.jitter.x, q.jitter.y, q.u0});
    }
    const int outs = 5;
    const std::string body =
        "    uint b = 15u * i; uint w = " + std::to_string(outs) + "u * i;\n"
        "    glint_scratch_frame f = glint_scratch_make_frame(vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0));\n"
        "    vec2 x = in_vec2(b + 6u), a = in_vec2(b + 8u), bb = in_vec2(b + 10u), jit = in_vec2(b + 12u);\n"
        "    out0[w] = floatBitsToUint(glint_scratch_material_alpha(3, x, a, bb, jit));\n"
        "    glint_scratch_lit l = glint_scratch_material_light(f, x, a, bb, jit, in_vec3(b), in_vec3(b + 3u), 1.0, 0.05, 4, 1e-6, 1);\n"
        "    out0[w + 1u] = floatBitsToUint(l.radiance.x); out0[w + 2u] = floatBitsToUint(l.base_weight);\n"
        "    glint_scratch_pick p = glint_scratch_material_sample(f, x, a, bb, jit, in_vec3(b), in_float(b + 14u), 0.3, 0.6, 1e-6, 1);\n"
        "    out0[w + 3u] = uint(p.layer + 1); out0[w + 4u] = floatBitsToUint(p.s.weight.x);\n";
    const auto gpu = glint_test::map_words_with_data({"core.glsl"}, "scratch.glsl", "glint_scratch_data", "GLINT_SCRATCH_BUFFER_DECLARED", body, in,
                                                     glint_test::to_words(m.data<float>()), n, outs);
    const auto gf = [&](std::size_t i, int k) {
        float x;
        std::memcpy(&x, &gpu[i * outs + static_cast<std::size_t>(k)], 4);
        return x;
    };
    const auto f = glint::make_scratch_frame<float>(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    stats alpha, light, base, weight;
    std::size_t pick_flip = 0, lit = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const input& q = v[i];
        alpha.add(gf(i, 0), view.alpha(3, q.x, q.a, q.b, q.jitter), 1.0, 1e-5);
        const auto l = view.light(f, q.x, q.a, q.b, q.wo, q.wl, 1.0f, 0.05f, 4, q.jitter);
        lit += l.radiance.x > 0;
        light.add(gf(i, 1), l.radiance.x, 1e-2, 1e-3), base.add(gf(i, 2), l.base_weight, 1.0, 1e-5);
        const auto p = view.sample(f, q.x, q.a, q.b, q.wo, q.u0, 0.3f, 0.6f, q.jitter);
        const bool same = gpu[i * outs + 3] == static_cast<std::uint32_t>(p.layer + 1);
        pick_flip += !same;
        if (same && p.layer >= 0) weight.add(gf(i, 4), p.s.weight.x, 1e-3, 1e-3);
    }
    const auto report = [&](const char* name, const stats& st) {
        MESSAGE(std::string(name) << ": max difference " << st.worst << ", " << st.over << " of " << st.count << " beyond its threshold (rate " << st.rate() << ")");
        CHECK(st.non_finite == 0u);
    };
    report("pyramid alpha (absolute)", alpha);
    report("SV-BRDF point light", light);
    report("base weight (absolute)", base);
    report("picked layer's weight", weight);
    MESSAGE("layer picks that differ: " << pick_flip << " of " << n << "; " << lit << " lit");
    CHECK(lit > n / 20);
    CHECK(alpha.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(light.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(base.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(weight.rate() <= SCRATCH_GLSL_MAX_FLIP_RATE);
    CHECK(static_cast<double>(pick_flip) / n <= SCRATCH_GLSL_MAX_FLIP_RATE);
}
