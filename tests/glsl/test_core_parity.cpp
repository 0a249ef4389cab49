// kernels/core.glsl through Mesa llvmpipe against the C++ float path on the same inputs.
// Integer code must match bit for bit; transcendental code is compared in ulp, with the bounds
// of the tolerance table in docs/conventions.md.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glint/core.hpp>

#include "../support/core_reference.hpp"
#include "../support/ulp.hpp"
#include "parity.hpp"
#include "tolerances.hpp"

using glint_test::from_words;
using glint_test::ulp_distance;

using glint_test::compare;
using glint_test::ulp_stats;

TEST_CASE("pcg3d is bit-exact between C++ and GLSL on 1e6 inputs") {
    const std::size_t n = 1000000;
    std::vector<std::uint32_t> in(3 * n);
    std::uint32_t state = 1u;
    for (std::size_t i = 0; i < n; ++i) {
        in[3 * i] = static_cast<std::uint32_t>(i);  // counters, as shaders use them
        in[3 * i + 1] = state;
        in[3 * i + 2] = static_cast<std::uint32_t>(i) * 2654435761u;
        state = state * 747796405u + 2891336453u;
    }
    auto out = glint_test::map_words({"core.glsl"},
                                     "uvec3 h = glint_pcg3d(uvec3(in0[3u*i], in0[3u*i+1u], in0[3u*i+2u]));"
                                     " out0[3u*i] = h.x; out0[3u*i+1u] = h.y; out0[3u*i+2u] = h.z;",
                                     in, n, 3);
    std::vector<std::uint32_t> cpu(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        glm::uvec3 h = glint::pcg3d(glm::uvec3(in[3 * i], in[3 * i + 1], in[3 * i + 2]));
        cpu[3 * i] = h.x, cpu[3 * i + 1] = h.y, cpu[3 * i + 2] = h.z;
    }
    CHECK(compare(out, cpu).differing == 0u);
}

TEST_CASE("hash_u32 is bit-exact between C++ and GLSL on 1e6 inputs") {
    const std::size_t n = 1000000;
    std::vector<std::uint32_t> in(n);
    for (std::size_t i = 0; i < n; ++i) in[i] = (i % 2) ? static_cast<std::uint32_t>(i) : static_cast<std::uint32_t>(i) * 2654435761u;
    auto out = glint_test::map_words({"core.glsl"}, "out0[i] = glint_hash_u32(in0[i]);", in, n, 1);
    std::vector<std::uint32_t> cpu(n);
    for (std::size_t i = 0; i < n; ++i) cpu[i] = glint::hash_u32(in[i]);
    CHECK(compare(out, cpu).differing == 0u);
}

TEST_CASE("uniform variates are bit-exact between C++ and GLSL") {
    const std::size_t n = 1u << 20;
    std::vector<std::uint32_t> in(n);
    for (std::size_t i = 0; i < n; ++i) in[i] = static_cast<std::uint32_t>(i) * 4099u + 0x9e3779b9u * static_cast<std::uint32_t>(i >> 7);
    auto out = glint_test::map_words(
        {"core.glsl"},
        "out0[2u*i] = floatBitsToUint(glint_unit_from_bits(in0[i]));"
        " out0[2u*i+1u] = floatBitsToUint(glint_open_unit_from_bits(in0[i]));",
        in, n, 2);
    std::vector<float> cpu(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        cpu[2 * i] = glint::unit_from_bits<float>(in[i]);
        cpu[2 * i + 1] = glint::open_unit_from_bits<float>(in[i]);
    }
    CHECK(compare(from_words<float>(out), cpu).differing == 0u);
}

TEST_CASE("erfinv: GLSL within the tolerance table of C++ and within its bound of the exact value") {
    std::vector<float> xs = glint_test::unit_interval_sweep(1000, 1u << 16);
    std::vector<float> signed_xs;
    for (float x : xs) signed_xs.push_back(x), signed_xs.push_back(-x);
    auto gpu = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_erfinv(x)", signed_xs));
    std::vector<float> cpu;
    double worst_exact = 0;
    for (std::size_t i = 0; i < signed_xs.size(); ++i) {
        cpu.push_back(glint::erfinv(signed_xs[i]));
        worst_exact = std::max(worst_exact, glint_test::ulp_error(gpu[i], glint_test::erfinv_exact(static_cast<double>(signed_xs[i]))));
    }
    ulp_stats s = compare(gpu, cpu);
    MESSAGE("erfinv GLSL vs C++: " << s.count << " inputs, " << s.differing << " differ (rate " << s.rate()
                                   << "), max " << s.max << " ulp; GLSL vs exact max " << worst_exact << " ulp");
    CHECK(s.count >= 1000000u);
    CHECK(s.max <= ERFINV_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst_exact <= ERFINV_GLSL_MAX_ULP_EXACT);
}

TEST_CASE("normal_quantile: GLSL within the tolerance table on every open_unit value") {
    std::vector<float> us;
    for (std::uint32_t k = 0; k < (1u << 23); ++k) us.push_back(glint::open_unit_from_bits<float>(k << 9));
    auto gpu = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_normal_quantile(x)", us));
    std::vector<float> cpu;
    double worst_exact = 0;
    for (std::size_t i = 0; i < us.size(); ++i) {
        cpu.push_back(glint::normal_quantile(us[i]));
        worst_exact = std::max(worst_exact, glint_test::ulp_error(gpu[i], glint_test::normal_quantile_exact(static_cast<double>(us[i]))));
    }
    ulp_stats s = compare(gpu, cpu);
    MESSAGE("normal_quantile GLSL vs C++: " << s.count << " inputs, " << s.differing << " differ (rate " << s.rate()
                                            << "), max " << s.max << " ulp; GLSL vs exact max " << worst_exact << " ulp");
    CHECK(s.max <= QUANTILE_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst_exact <= QUANTILE_GLSL_MAX_ULP_EXACT);
}

TEST_CASE("(1 - p)^N and 1 - (1 - p)^N: GLSL against C++ and against the exact value on the grid") {
    std::vector<float> ps, ns;
    for (double p : glint_test::pow_grid_p())
        for (double N : glint_test::pow_grid_n()) ps.push_back(static_cast<float>(p)), ns.push_back(static_cast<float>(N));
    struct method {
        const char* glsl;
        glint::pow_method cpp;
    };
    for (method m : {method{"naive", glint::pow_method::naive}, method{"kk25", glint::pow_method::kk25},
                     method{"log1p", glint::pow_method::log1p}}) {
        CAPTURE(m.glsl);
        const std::string name = m.glsl;
        const std::string complement = name == "log1p" ? "expm1" : name;
        auto gq = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_pow_one_minus_" + name + "(x, y)", ps, ns));
        auto gs = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_any_success_" + complement + "(x, y)", ps, ns));
        double worst_q = 0, worst_s = 0, worst_exact_rel = 0, worst_exact_complement_rel = 0;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            const float cq = glint::pow_one_minus(ps[i], ns[i], m.cpp), cs = glint::any_success(ps[i], ns[i], m.cpp);
            REQUIRE(std::isfinite(gq[i]));
            REQUIRE(std::isfinite(gs[i]));
            worst_q = std::max(worst_q, std::fabs(static_cast<double>(gq[i] - cq)));
            worst_s = std::max(worst_s, std::fabs(static_cast<double>(gs[i] - cs)));
            const long double q = glint_test::pow_one_minus_exact(ps[i], ns[i]);
            const long double s = glint_test::any_success_exact(ps[i], ns[i]);
            if (q >= 1e-30L) worst_exact_rel = std::max(worst_exact_rel, static_cast<double>(fabsl(gq[i] - q) / q));
            if (s > 0) worst_exact_complement_rel = std::max(worst_exact_complement_rel, static_cast<double>(fabsl(gs[i] - s) / s));
        }
        MESSAGE(name << ": GLSL vs C++ max abs difference " << worst_q << " (complement " << worst_s
                     << "); GLSL vs exact max rel " << worst_exact_rel << " (complement " << worst_exact_complement_rel << ")");
        if (name == "log1p") {
            CHECK(worst_q <= POW_LOG1P_GLSL_MAX_ABS_DIFFERENCE);
            CHECK(worst_exact_rel <= POW_LOG1P_GLSL_MAX_REL_EXACT);
            CHECK(worst_exact_complement_rel <= ANY_SUCCESS_EXPM1_GLSL_MAX_REL_EXACT);
        }
    }
}

TEST_CASE("log1p and expm1: GLSL within the tolerance table of C++ and of the exact value") {
    std::vector<float> lx, ex;
    for (std::uint32_t b = 0x00000001u; b < 0x3f800000u; b += 997u) lx.push_back(-glint_test::float_from_bits(b));
    for (std::uint32_t b = 0x00000001u; b < 0x49742400u; b += 997u) lx.push_back(glint_test::float_from_bits(b));
    for (std::uint32_t b = 0x00000001u; b < 0x42c80000u; b += 997u) ex.push_back(-glint_test::float_from_bits(b));
    auto gl = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_log1p(x)", lx));
    auto ge = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_expm1_nonpositive(x)", ex));
    using k = glint::detail::glsl::kernels<float>;
    std::vector<float> cl, ce;
    double worst_l = 0, worst_e = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) {
        cl.push_back(k::glint_log1p(lx[i]));
        worst_l = std::max(worst_l, glint_test::ulp_error(gl[i], static_cast<double>(log1pl(lx[i]))));
    }
    for (std::size_t i = 0; i < ex.size(); ++i) {
        ce.push_back(k::glint_expm1_nonpositive(ex[i]));
        worst_e = std::max(worst_e, glint_test::ulp_error(ge[i], static_cast<double>(expm1l(ex[i]))));
    }
    ulp_stats sl = compare(gl, cl), se = compare(ge, ce);
    MESSAGE("log1p GLSL vs C++: " << sl.count << " inputs, rate " << sl.rate() << ", max " << sl.max
                                  << " ulp; vs exact " << worst_l << " ulp");
    MESSAGE("expm1 GLSL vs C++: " << se.count << " inputs, rate " << se.rate() << ", max " << se.max
                                  << " ulp; vs exact " << worst_e << " ulp");
    CHECK(sl.max <= LOG1P_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst_l <= LOG1P_GLSL_MAX_ULP_EXACT);
    CHECK(se.max <= EXPM1_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst_e <= EXPM1_GLSL_MAX_ULP_EXACT);
}

TEST_CASE("log2: GLSL bit-identical to C++ and within the C++ bound of the exact value") {
    // Every 9973rd positive normal float pattern (about 2.1e5), and the clamped ends.
    std::vector<float> x;
    for (std::uint32_t b = 0x00800000u; b < 0x7f800000u; b += 9973u) x.push_back(glint_test::float_from_bits(b));
    for (const float e : {0.0f, -1.0f, 1.0f, 3.4028235e38f}) x.push_back(e);
    const auto g = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_log2(x)", x));
    using k = glint::detail::glsl::kernels<float>;
    std::vector<float> c;
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        c.push_back(k::glint_log2(x[i]));
        if (x[i] > 0) worst = std::max(worst, glint_test::ulp_error(g[i], static_cast<double>(log2l(x[i]))));
    }
    ulp_stats st = compare(g, c);
    MESSAGE("log2 GLSL vs C++: " << st.count << " inputs, rate " << st.rate() << ", max " << st.max << " ulp; vs exact " << worst << " ulp");
    CHECK(st.max <= LOG2_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst <= LOG2_GLSL_MAX_ULP_EXACT);
}

// atan2 over a spiral of directions (every octant, magnitudes 2^-20 to 2^20, and the axes) and
// acos over [-1, 1] with the floats next to +-1 (where 1 - x^2 matters): GLSL against C++, and both
// against the exact value (long double).
TEST_CASE("atan2 and acos: GLSL within the tolerance table of C++ and of the exact value") {
    std::vector<float> ys, xs, as;
    for (int i = 0; i < 40000; ++i) {
        const double phi = -3.14159265358979 + 6.28318530717958 * (i + 0.5) / 40000, r = std::exp2(40.0 * ((i * 7919) % 40000) / 40000.0 - 20);
        ys.push_back(static_cast<float>(r * std::sin(phi))), xs.push_back(static_cast<float>(r * std::cos(phi)));
    }
    for (const float a : {0.0f, 1.0f, -1.0f, 3.0f}) ys.push_back(a), xs.push_back(a == 3.0f ? -2.0f : 1.0f - std::fabs(a));
    for (int i = 0; i <= 40000; ++i) {
        const double t = -1 + 2.0 * i / 40000;
        as.push_back(static_cast<float>(t * t * t));  // t^3: dense near 0, and reaching the ends
    }
    as.push_back(1.0f - 6e-8f), as.push_back(-1.0f + 6e-8f);
    const auto g2 = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_atan2(x, y)", ys, xs));
    const auto ga = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_acos(x)", as));
    using k = glint::detail::glsl::kernels<float>;
    std::vector<float> c2, ca;
    double worst2 = 0, worsta = 0, worst_cpu = 0;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        c2.push_back(k::glint_atan2(ys[i], xs[i]));
        const long double exact = atan2l(ys[i], xs[i]);
        worst2 = std::max(worst2, glint_test::ulp_error(g2[i], static_cast<double>(exact)));
        worst_cpu = std::max(worst_cpu, glint_test::ulp_error(c2[i], static_cast<double>(exact)));
    }
    for (std::size_t i = 0; i < as.size(); ++i) {
        ca.push_back(k::glint_acos(as[i]));
        const long double exact = acosl(as[i]);
        worsta = std::max(worsta, glint_test::ulp_error(ga[i], static_cast<double>(exact)));
        worst_cpu = std::max(worst_cpu, glint_test::ulp_error(ca[i], static_cast<double>(exact)));
    }
    const ulp_stats s2 = compare(g2, c2), sa = compare(ga, ca);
    MESSAGE("atan2 GLSL vs C++: " << s2.count << " inputs, rate " << s2.rate() << ", max " << s2.max << " ulp; vs exact " << worst2 << " ulp");
    MESSAGE("acos GLSL vs C++: " << sa.count << " inputs, rate " << sa.rate() << ", max " << sa.max << " ulp; vs exact " << worsta
                                 << " ulp; C++ vs exact " << worst_cpu << " ulp");
    CHECK(s2.max <= ATAN2_GLSL_MAX_ULP_DISTANCE);
    CHECK(sa.max <= ATAN2_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst2 <= ATAN2_GLSL_MAX_ULP_EXACT);
    CHECK(worsta <= ATAN2_GLSL_MAX_ULP_EXACT);
    CHECK(worst_cpu <= ATAN2_GLSL_MAX_ULP_EXACT);
}

TEST_CASE("erfc: GLSL within the tolerance table of C++ and of the exact value") {
    std::vector<float> xs;
    for (double x = -4; x <= 9; x += 1e-4) xs.push_back(static_cast<float>(x));
    auto gpu = from_words<float>(glint_test::map_floats({"core.glsl"}, "float", "glint_erfc(x)", xs));
    std::vector<float> cpu;
    double worst_exact = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        cpu.push_back(glint::erfc(xs[i]));
        const long double exact = erfcl(static_cast<long double>(xs[i]));
        worst_exact = std::max(worst_exact, static_cast<double>(fabsl(gpu[i] - exact) / exact));
    }
    ulp_stats s = compare(gpu, cpu);
    MESSAGE("erfc GLSL vs C++: " << s.count << " inputs, rate " << s.rate() << ", max " << s.max << " ulp; GLSL vs exact max relative "
                                 << worst_exact);
    CHECK(s.max <= ERFC_GLSL_MAX_ULP_DISTANCE);
    CHECK(worst_exact <= ERFC_GLSL_MAX_RELATIVE_EXACT);
}
