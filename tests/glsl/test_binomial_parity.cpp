// The binomial and multinomial kernels through Mesa llvmpipe against the C++ float path on the
// same inputs. The builtins pow, exp, log and sqrt differ by a few ulp between the two, so a
// continuous count differs by a few ulp, and a discrete decision (a gate, the clamp, the
// two-point middle) may flip where an input sits within those ulp of its threshold: such flips
// are counted and their rate is bounded.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glint/binomial.hpp>
#include <glint/glsl.hpp>
#include <glint/multinomial.hpp>
#include <glint/testing/binomial_metrics.hpp>

#include "parity.hpp"
#include "tolerances.hpp"

using glint::binomial_variant;
namespace gt = glint::testing;

namespace {

struct parity {
    std::size_t count = 0, identical = 0, flips = 0;
    double max_difference = 0;  // over the counts that did not flip, relative to max(N, 1)
    float worst_gpu = 0, worst_cpu = 0, worst_n = 0;
    double rate() const { return static_cast<double>(flips) / static_cast<double>(count); }
};

// A count is identical, or agrees (within BINOMIAL_GLSL_AGREEMENT of max(N, 1)), or flipped.
void tally(parity& s, float gpu, float cpu, float N) {
    ++s.count;
    const double d = std::fabs(static_cast<double>(gpu) - static_cast<double>(cpu)) / std::max(static_cast<double>(N), 1.0);
    s.identical += gpu == cpu;
    if (d > BINOMIAL_GLSL_AGREEMENT) ++s.flips;
    else if (d > s.max_difference) s.max_difference = d, s.worst_gpu = gpu, s.worst_cpu = cpu, s.worst_n = N;
}

// The draws' inputs: every grid point with N in [N_min, N_max], `pairs` uniform pairs each from
// pcg3d(pair, salt, draw index), as floats and as the shader's input words (N, p, u1, u2).
struct draw_inputs {
    std::vector<std::uint32_t> words;
    std::vector<float> Ns, ps, u1s, u2s;
};

draw_inputs grid_inputs(std::uint32_t pairs, std::uint32_t salt, double N_min = 0, double N_max = 1e300) {
    draw_inputs d;
    for (double N : gt::binomial_grid_n()) {
        if (N < N_min || N > N_max) continue;
        for (double p : gt::binomial_grid_p())
            for (std::uint32_t s = 0; s < pairs; ++s) {
                const glm::uvec3 h = glint::pcg3d(glm::uvec3(s, salt, static_cast<std::uint32_t>(d.Ns.size())));
                d.Ns.push_back(static_cast<float>(N)), d.ps.push_back(static_cast<float>(p));
                d.u1s.push_back(glint::open_unit_from_bits<float>(h.x)), d.u2s.push_back(glint::open_unit_from_bits<float>(h.y));
                glint_test::append_words(d.words, {d.Ns.back(), d.ps.back(), d.u1s.back(), d.u2s.back()});
            }
    }
    return d;
}

// The shader's reading of draw i's inputs (grid_inputs' words).
const std::string read_inputs = "float N = in_float(4u*i), p = in_float(4u*i+1u), u1 = in_float(4u*i+2u), u2 = in_float(4u*i+3u);";

// Two GLSL counts per input against C++'s binomial_unbiased: its positive count, then its
// negative count (or its positive count again, where the shader's second word holds another
// entry point's positive count).
parity tally_unbiased(const std::vector<float>& gpu, const draw_inputs& d, bool second_is_negative) {
    parity s;
    for (std::size_t i = 0; i < d.Ns.size(); ++i) {
        const auto c = glint::binomial_unbiased(d.Ns[i], d.ps[i], d.u1s[i], d.u2s[i]);
        tally(s, gpu[2 * i], c.positive, d.Ns[i]);
        tally(s, gpu[2 * i + 1], second_is_negative ? c.negative : c.positive, d.Ns[i]);
    }
    return s;
}

}  // namespace

TEST_CASE("binomial kernels: GLSL against C++ over the grid, 256 uniform pairs per point, every variant") {
    const draw_inputs d = grid_inputs(256, 0x9au);
    const std::vector<float>&Ns = d.Ns, &ps = d.ps, &u1s = d.u1s, &u2s = d.u2s;
    for (binomial_variant v : {binomial_variant::ungated, binomial_variant::gated_db23, binomial_variant::gated,
                               binomial_variant::dual_gated, binomial_variant::unbiased}) {
        const int method = static_cast<int>(glint::published_pow_method(v));
        const std::string body =
            read_inputs + " glint_binomial r = glint_binomial_variant(" + std::to_string(static_cast<int>(v)) + ", N, p, u1, u2, " +
            std::to_string(method) + ");"
            " out0[2u*i] = floatBitsToUint(r.positive); out0[2u*i+1u] = floatBitsToUint(r.negative);";
        const auto gpu = glint_test::from_words<float>(
            glint_test::map_words({"core.glsl", "binomial.glsl"}, body, d.words, Ns.size(), 2));
        parity s;
        std::size_t non_finite = 0;
        for (std::size_t i = 0; i < Ns.size(); ++i) {
            const auto c = glint::binomial(v, Ns[i], ps[i], u1s[i], u2s[i]);
            non_finite += !std::isfinite(gpu[2 * i]) || !std::isfinite(gpu[2 * i + 1]);
            tally(s, gpu[2 * i], c.positive, Ns[i]);
            tally(s, gpu[2 * i + 1], c.negative, Ns[i]);
        }
        const double rate = s.rate();
        MESSAGE(std::string(glint::name(v)) << ": " << s.count << " counts, " << s.identical << " identical, " << s.flips
                                            << " flipped (rate " << rate << "), the others within " << s.max_difference << " of max(N, 1) (" << s.worst_gpu << " against "
                       << s.worst_cpu << " at N = " << s.worst_n << ")");
        CHECK(non_finite == 0u);
        CHECK(rate <= BINOMIAL_GLSL_MAX_FLIP_RATE);
    }
}

TEST_CASE("binomial kernels: GLINT_BINOMIAL_VARIANT and _POW_METHOD fix the sampler of glint_binomial_variant and _cached") {
    // The shader asks for the ungated sampler with the naive method at run time; with the macros
    // defined (the mean-preserving sampler, log1p) both entry points must draw as C++'s
    // binomial_unbiased, within the same flip rate as the test above. Without them the same shader
    // draws the ungated sampler, which the comparison must catch.
    const draw_inputs d = grid_inputs(16, 0x5bu);
    const std::string body =
        read_inputs + " glint_binomial r = glint_binomial_variant(0, N, p, u1, u2, 0);"
        " glint_binomial_cache cache = glint_binomial_empty_cache();"
        " glint_binomial c = glint_binomial_variant_cached(0, N, p, u1, u2, 0, cache);"
        " out0[2u*i] = floatBitsToUint(r.positive); out0[2u*i+1u] = floatBitsToUint(c.positive);";
    for (bool fixed : {true, false}) {
        std::vector<std::string> files = {"core.glsl", "binomial.glsl"};
        if (fixed) files.insert(files.begin(), {"#define GLINT_BINOMIAL_VARIANT 4", "#define GLINT_BINOMIAL_POW_METHOD 2"});
        const auto gpu = glint_test::from_words<float>(glint_test::map_words(files, body, d.words, d.Ns.size(), 2));
        const parity s = tally_unbiased(gpu, d, false);
        const double rate = s.rate();
        MESSAGE(std::string(fixed ? "fixed by the macros" : "without them (ungated)") << ": " << s.count << " counts, " << s.identical << " identical, "
                                                                          << s.flips << " flipped (rate " << rate << ")");
        if (fixed) CHECK(rate <= BINOMIAL_GLSL_MAX_FLIP_RATE);
        else CHECK(rate > 0.1);
    }
}

TEST_CASE("multinomial kernel: GLSL against C++, K = 4 and 8") {
    for (int K : {4, 8}) {
        const std::size_t n = 65536;
        std::vector<std::uint32_t> in;
        std::vector<float> Ns;
        for (std::size_t i = 0; i < n; ++i) {
            const float N = std::pow(10.0f, -2.0f + 18.0f * glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 3u, 3u)).x));
            Ns.push_back(N);
            in.push_back(glint_test::to_words(std::vector<float>{N})[0]);
        }
        std::string body = "glint_multinomial_probabilities pr;";
        for (int k = 0; k < 8; ++k) body += " pr.p[" + std::to_string(k) + "] = " + std::to_string(0.8 * (k + 1) / (K * (K + 1) / 2)) + ";";
        body += " glint_multinomial_counts c = glint_multinomial(in_float(i), pr, " + std::to_string(K) +
                ", uvec3(i, 7u, 1u), 4, 2);"
                " for (int k = 0; k < 8; ++k) out0[9u*i+uint(k)] = floatBitsToUint(c.count[k]);"
                " out0[9u*i+8u] = floatBitsToUint(c.rest);";
        const auto gpu = glint_test::from_words<float>(
            glint_test::map_words({"core.glsl", "binomial.glsl", "multinomial.glsl"}, body, in, n, 9));
        parity s;
        for (std::size_t i = 0; i < n; ++i) {
            std::array<float, 8> p{};
            for (int k = 0; k < 8; ++k) p[static_cast<std::size_t>(k)] = static_cast<float>(0.8 * (k + 1) / (K * (K + 1) / 2));
            using kern = glint::detail::glsl::kernels<float>;
            kern::glint_multinomial_probabilities pr;
            for (int k = 0; k < 8; ++k) pr.p[k] = p[static_cast<std::size_t>(k)];
            const auto c = kern::glint_multinomial(Ns[i], pr, K, glm::uvec3(static_cast<std::uint32_t>(i), 7u, 1u), 4, 2);
            for (int k = 0; k < 8; ++k) tally(s, gpu[9 * i + static_cast<std::size_t>(k)], c.count[k], Ns[i]);
            tally(s, gpu[9 * i + 8], c.rest, Ns[i]);
        }
        const double rate = s.rate();
        MESSAGE("K = " << K << ": " << s.count << " counts, " << s.identical << " identical, " << s.flips << " flipped (rate "
                       << rate << "), the others within " << s.max_difference << " of max(N, 1) (" << s.worst_gpu << " against "
                       << s.worst_cpu << " at N = " << s.worst_n << ")");
        CHECK(rate <= BINOMIAL_GLSL_MAX_FLIP_RATE);
    }
}
