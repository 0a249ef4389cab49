// Fixed workloads for counting instructions, where this machine's timings are too noisy to see a
// change of a few percent (valgrind --tool=callgrind counts the same on every run):
//   glint_frame_loop point FRAMES          the showcase's 160 x 100 point-light frame, glints on
//   glint_frame_loop point-smooth FRAMES   the same frame shaded smooth
//   glint_frame_loop point-stochastic FRAMES  the glint frame on one lattice point per pixel
//   glint_frame_loop point-rows[-smooth|-stochastic] FRAMES  the same frames a row at a time
//                                          (render_row: glint::grid_sample_pixels, eight pixels in AVX2 lanes)
//   glint_frame_loop ibl K FRAMES          glint::ibl_sample on bench/report_ibl.cpp's sphere; prints
//                                          the frames' mean and least wall time too (without
//                                          the environment's build), for A/B timing of two builds
//   glint_frame_loop ibl-stochastic K FRAMES  the same on one lattice point per pixel
//                                          (sunset.exr); count it alone with
//                                          --toggle-collect='glint_ibl_estimate*'
//   glint_frame_loop ibl-rows K FRAMES     the same frame a row at a time (glint::ibl_sample_pixels,
//                                          eight pixels in AVX2 lanes); count it alone with
//                                          --toggle-collect='glint_ibl_estimate_row*'
//   glint_frame_loop ibl-rows-stochastic K FRAMES  the same on one lattice point per pixel
//   glint_frame_loop ibl-lookup K FRAMES   the same sphere's environment lookups alone, of every
//                                          channel (what a glint frame reads); prints the least
//                                          frame time
//   glint_frame_loop ibl-radiance K FRAMES the lookups of the radiance alone (the smooth frame's)
//   glint_frame_loop ibl-pixels K          what the ibl frame's pixels draw: the vertices a pixel,
//                                          N, the trials a vertex, the lit levels' share
//   glint_frame_loop draw N P              2e5 draws of glint::binomial_unbiased at (N, P)
//   glint_frame_loop draw-time N P PAIRS   ns a draw at (N, P) over PAIRS uniform pairs cycled (the
//                                          report's 65536; 1024 lets the branch predictor learn the
//                                          cycle): the mean-preserving sampler, KK25 Alg. 1 (Eq.
//                                          25) and the closed-form middle alone, each the least of
//                                          7 alternating loops of 2e6 draws
//   glint_frame_loop lights K MODE REPS    the report's several-lights workload
//                                          (bench/light_pixels.hpp): its 1024 pixels with K
//                                          lights (up to 16), MODE 0 smooth, 1 one shared
//                                          footprint and the list of lights, 2 a footprint per
//                                          light, 3 as 1 on one lattice point, 4 as 1 one light
//                                          at a time, REPS times
//   glint_frame_loop lobe-tree MAP PASSES  the report's lobe-forest evaluations
//                                          (bench/lobe_tree_workload.hpp): MAP metal (scratched
//                                          metal, Gaussian lobes, delta_k 0.3) or pyramids
//                                          (Beckmann lobes, delta_k 30), its 200 queries PASSES
//                                          times; prints the least pass's ns a query. Count the
//                                          queries alone with --toggle-collect='lobe_forest_eval*'
// Each prints a sum of its results, so that two builds can be checked to compute the same.
// GLINT_LANES=1 in the environment limits the vector code to its AVX2 build, 0 to the baseline
// (glint::detail::lanes_limit; valgrind runs the AVX2 build, as its CPU has no AVX-512).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <glint/binomial.hpp>
#include <glint/ibl.hpp>
#include <glint/io/exr.hpp>

#include "../examples/lights_scene.hpp"
#include "launder.hpp"
#include "light_pixels.hpp"
#include "lobe_tree_workload.hpp"

#ifndef GLINT_DATA_DIR
#error "GLINT_DATA_DIR must point at the project's data/ folder"
#endif

// One loop of draw-time: 2e6 draws at (N, p), u[mask + 1] cycled; ns a draw.
template <int Sampler>
__attribute__((noinline)) double draw_time(float N, float p, const std::vector<float>& u, std::size_t mask) {
    using K = glint::detail::glsl::kernels<float>;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t j = 0; j < 2000000; ++j) {
        const float u1 = u[j & mask], u2 = u[(j * 7 + 3) & mask];
        K::glint_binomial r;
        if (Sampler == 0) r = K::glint_binomial_unbiased(glint_bench::launder(N), glint_bench::launder(p), u1, u2, K::GLINT_POW_LOG1P);
        if (Sampler == 1) r = K::glint_binomial_dual_gated(glint_bench::launder(N), glint_bench::launder(p), u1, u2, K::GLINT_POW_KK25);
        if (Sampler == 2) r = K::glint_binomial_unbiased_sure_middle(glint_bench::launder(N), glint_bench::launder(p), u2);
        asm volatile("" : : "x"(r.positive), "x"(r.negative));
    }
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / 2e6;
}

// Out of line, so that callgrind can count the estimate alone.
// lattice_u < 0: every lattice point; else the one it picks.
__attribute__((noinline)) glint::ibl_estimate<float> glint_ibl_estimate(glm::vec2 uv, const glint::grid_params<float>& g, const glint::environment& env,
                                                                        const glint::environment::sample& s, float e_d, float d_h, float lattice_u) {
    auto px = glint::grid_pixel_setup(uv, glm::vec2(1, 0), glm::vec2(0, 1), g, lattice_u);
    return glint::ibl_sample(px, g, env.levels(), s.indicators, e_d, d_h);
}

// The same for `count` pixels of a row at once (glint::ibl_sample_pixels).
__attribute__((noinline)) void glint_ibl_estimate_row(int count, const glm::vec2* uv, const glint::grid_params<float>& g, const glint::environment& env,
                                                      const glint::ibl_indicators<float>* ind, const float* e_d, float d_h, const float* lattice_u,
                                                      glint::ibl_estimate<float>* out) {
    glint::grid_pixel<float> px[160];
    glm::vec2 duvdx[160], duvdy[160];
    for (int i = 0; i < count; ++i) duvdx[i] = glm::vec2(1, 0), duvdy[i] = glm::vec2(0, 1);
    glint::grid_pixels_setup(static_cast<std::size_t>(count), uv, duvdx, duvdy, g, lattice_u, px);
    glint::ibl_sample_pixels(count, px, g, env.levels(), ind, e_d, d_h, out);
}

// The IBL workloads' environment: sunset.exr with K levels.
glint::environment sunset_environment(int levels) {
    const auto img = glint::io::read_exr(std::string(GLINT_DATA_DIR) + "/envmaps/sunset.exr");
    glint::ibl_options o;
    o.levels = levels;
    return glint::build_environment(img.width, img.height, img.rgb, o);
}

// The IBL workloads' sphere (bench/report_ibl.cpp's): its normal at pixel (x, y) of the 160 x 100
// view, or false off the sphere.
bool sphere_normal(int x, int y, glm::vec3& n) {
    const float px = (static_cast<float>(x) - 80) / 50, py = (50 - static_cast<float>(y)) / 50, rr = px * px + py * py;
    if (rr >= 1) return false;
    n = glm::vec3(px, py, std::sqrt(1 - rr));
    return true;
}

// Calls fn(x, y, n) for every pixel of that view on the sphere.
template <class F>
void for_each_sphere_pixel(F&& fn) {
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 160; ++x) {
            glm::vec3 n;
            if (sphere_normal(x, y, n)) fn(x, y, n);
        }
}

// Runs frame(f) for f < frames and prints the frames' mean and least wall time.
template <class F>
void time_frames(const char* mode, int frames, F&& frame) {
    const auto start = std::chrono::steady_clock::now();
    double least = 1e30;
    for (int f = 0; f < frames; ++f) {
        const auto frame_start = std::chrono::steady_clock::now();
        frame(f);
        least = std::min(least, std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_start).count());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %.0f us a frame (mean of %d; the least %.0f us)\n", mode, 1e6 * seconds / std::max(frames, 1), frames, 1e6 * least);
}

// One lobe-forest query, out of line for callgrind's --toggle-collect.
__attribute__((noinline)) float lobe_forest_eval(const glint_bench::forest& f, const glint_bench::query& q) { return f.eval(q.fp, q.s); }

int main(int argc, char** argv) {
    if (const char* lanes = std::getenv("GLINT_LANES")) glint::detail::lanes_limit = std::atoi(lanes);
    const char* mode = argc > 1 ? argv[1] : "";
    double sum = 0;
    const bool rows = !std::strncmp(mode, "point-rows", 10);
    const char* point_mode = rows ? mode + 10 : mode + 5;  // "", "-smooth" or "-stochastic"
    if (argc == 3 && !std::strncmp(mode, "point", 5) && (!std::strcmp(point_mode, "") || !std::strcmp(point_mode, "-smooth") || !std::strcmp(point_mode, "-stochastic"))) {
        using namespace glint_examples;
        const camera cam(160, 100);
        for (int frame = 0; frame < std::atoi(argv[2]); ++frame) {
            scene_options opt;
            opt.smooth = !std::strcmp(point_mode, "-smooth");
            opt.stochastic_lattice = !std::strcmp(point_mode, "-stochastic");
            light_setup ls;
            ls.type = light_type::point;
            shading_counters c;
            glm::vec3 row[160];
            for (int y = 0; y < 100; ++y) {
                if (rows) render_row(opt, ls, cam, y, 0, 160, row, c);
                for (int x = 0; x < 160; ++x) sum += static_cast<double>(rows ? row[x].x : render_pixel(opt, ls, cam, x, y, c).x);
            }
        }
    } else if (argc == 4 && (!std::strcmp(mode, "ibl") || !std::strcmp(mode, "ibl-stochastic"))) {
        const bool stochastic = !std::strcmp(mode, "ibl-stochastic");
        const auto env = sunset_environment(std::atoi(argv[2]));
        const float sa = 0.35f, dh = env.total_area(sa * sa);
        time_frames(mode, std::atoi(argv[3]), [&](int frame) {
            for_each_sphere_pixel([&](int x, int y, const glm::vec3& n) {
                const auto s = env.lookup(glm::reflect(glm::vec3(0, 0, -1), n), sa);
                glint::grid_params<float> g;
                g.log_density = 4.0f;
                g.seed = static_cast<std::uint32_t>(frame);
                const glm::vec2 uv(static_cast<float>(x), static_cast<float>(y));
                const float lattice_u = glint_examples::pixel_lattice_u(stochastic, x, y, g.seed);
                const auto e = glint_ibl_estimate(uv, g, env, s, env.visible_area(n.z, sa), dh, lattice_u);
                sum += static_cast<double>(glint::modulation(e));
            });
        });
    } else if (argc == 4 && (!std::strcmp(mode, "ibl-rows") || !std::strcmp(mode, "ibl-rows-stochastic"))) {
        const bool stochastic = !std::strcmp(mode, "ibl-rows-stochastic");
        const auto env = sunset_environment(std::atoi(argv[2]));
        const float sa = 0.35f, dh = env.total_area(sa * sa);
        time_frames(mode, std::atoi(argv[3]), [&](int frame) {
            glint::grid_params<float> g;
            g.log_density = 4.0f;
            g.seed = static_cast<std::uint32_t>(frame);
            for (int y = 0; y < 100; ++y) {
                glm::vec2 uv[160];
                glint::ibl_indicators<float> ind[160];
                float e_d[160], lattice_u[160];
                glint::ibl_estimate<float> e[160];
                int count = 0;
                for (int x = 0; x < 160; ++x) {
                    glm::vec3 n;
                    if (!sphere_normal(x, y, n)) continue;
                    ind[count] = env.lookup(glm::reflect(glm::vec3(0, 0, -1), n), sa).indicators;
                    e_d[count] = env.visible_area(n.z, sa);
                    lattice_u[count] = glint_examples::pixel_lattice_u(stochastic, x, y, g.seed);
                    uv[count++] = glm::vec2(static_cast<float>(x), static_cast<float>(y));
                }
                glint_ibl_estimate_row(count, uv, g, env, ind, e_d, dh, lattice_u, e);
                for (int i = 0; i < count; ++i) sum += static_cast<double>(glint::modulation(e[i]));
            }
        });
    } else if (argc == 4 && (!std::strcmp(mode, "ibl-lookup") || !std::strcmp(mode, "ibl-radiance"))) {
        const bool all = !std::strcmp(mode, "ibl-lookup");
        const auto env = sunset_environment(std::atoi(argv[2]));
        const float sa = 0.35f;
        const int frames = std::atoi(argv[3]);
        double least = 1e30;
        for (int frame = 0; frame < frames; ++frame) {
            const auto start = std::chrono::steady_clock::now();
            for_each_sphere_pixel([&](int, int, const glm::vec3& n) {
                const glm::vec3 r = glm::reflect(glm::vec3(0, 0, -1), n);
                if (all) {
                    const auto s = env.lookup(r, sa);
                    sum += static_cast<double>(s.radiance.x + s.indicators.w[1]);
                } else {
                    sum += static_cast<double>(env.lookup_radiance(r, sa).x);
                }
            });
            least = std::min(least, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        std::printf("%s: %.0f us a frame (the least of %d)\n", mode, 1e6 * least, frames);
    } else if (argc == 3 && !std::strcmp(mode, "ibl-pixels")) {
        using k = glint::detail::glsl::kernels<float>;
        const auto env = sunset_environment(std::atoi(argv[2]));
        const float sa = 0.35f, dh = env.total_area(sa * sa);
        long pixels = 0, vertices = 0, by_count[13] = {};
        double N_sum = 0, lit_sum = 0, n_min = 1e30, n_max = 0;
        for_each_sphere_pixel([&](int x, int y, const glm::vec3& n) {
            const auto s = env.lookup(glm::reflect(glm::vec3(0, 0, -1), n), sa);
            glint::grid_params<float> g;
            g.log_density = 4.0f;  // the ibl frame's
            auto px = glint::grid_pixel_setup(glm::vec2(static_cast<float>(x), static_cast<float>(y)), glm::vec2(1, 0), glm::vec2(0, 1), g, -1.0f);
            k::glint_grid_pixel_vertices(px, glint::detail::to_kernel(g));
            int present = 0;
            for (int i = 0; i < px.v.count; ++i) {
                if (!(px.v.weight[i] > 0)) continue;
                const double trials = static_cast<double>(px.N * px.v.share[i]);
                n_min = std::min(n_min, trials), n_max = std::max(n_max, trials);
                ++present;
            }
            const auto p = k::glint_ibl_probabilities(env.levels(), s.indicators, env.visible_area(n.z, sa), dh);
            for (int l = 1; l < env.levels().count; ++l) lit_sum += static_cast<double>(p.p[l]);
            ++pixels, vertices += present, ++by_count[present], N_sum += static_cast<double>(px.N);
        });
        std::printf("ibl-pixels: %ld pixels, %.2f vertices a pixel, N %.2f a pixel on average, %.2f to %.2f trials a vertex, lit levels' share %.3f\n", pixels,
                    static_cast<double>(vertices) / static_cast<double>(pixels), N_sum / static_cast<double>(pixels), n_min, n_max, lit_sum / static_cast<double>(pixels));
        for (int c = 0; c <= 12; ++c)
            if (by_count[c] > 0) std::printf("  %ld pixels draw %d vertices\n", by_count[c], c);
        return 0;
    } else if (argc == 4 && !std::strcmp(mode, "draw")) {
        const float N = std::strtof(argv[2], nullptr), p = std::strtof(argv[3], nullptr);
        for (std::uint32_t i = 0; i < 200000; ++i) {
            const glm::uvec3 h = glint::pcg3d(glm::uvec3(i, 1u, 2u));
            sum += static_cast<double>(glint::binomial_unbiased(N, p, glint::open_unit_from_bits<float>(h.x), glint::open_unit_from_bits<float>(h.y)).positive);
        }
    } else if (argc == 5 && !std::strcmp(mode, "draw-time")) {
        const float N = std::strtof(argv[2], nullptr), p = std::strtof(argv[3], nullptr);
        const long pairs = std::atol(argv[4]);
        if (pairs < 1 || pairs > (1L << 24) || (pairs & (pairs - 1)) != 0) {
            std::fprintf(stderr, "draw-time: PAIRS must be a power of two from 1 to 2^24\n");
            return 2;
        }
        std::vector<float> u(static_cast<std::size_t>(pairs));
        for (std::size_t i = 0; i < u.size(); ++i) u[i] = glint::open_unit_from_bits<float>(glint::pcg3d(glm::uvec3(static_cast<std::uint32_t>(i), 5u, 6u)).x);
        double t[3] = {1e30, 1e30, 1e30};
        for (int r = 0; r < 7; ++r) {
            t[0] = std::min(t[0], draw_time<0>(N, p, u, u.size() - 1));
            t[1] = std::min(t[1], draw_time<1>(N, p, u, u.size() - 1));
            t[2] = std::min(t[2], draw_time<2>(N, p, u, u.size() - 1));
        }
        std::printf("draw-time (%g, %g), %ld pairs: mean-preserving %.1f ns, KK25 Alg. 1 %.1f ns, closed-form middle alone %.1f ns a draw\n", static_cast<double>(N),
                    static_cast<double>(p), pairs, t[0], t[1], t[2]);
        return 0;  // timings only: no sum to compare
    } else if (argc == 5 && !std::strcmp(mode, "lights")) {
        const glint_bench::light_pixels lp;
        const int k = std::atoi(argv[2]), shading = std::atoi(argv[3]);
        if (k < 0 || k > glint_bench::light_pixels::lights || shading < 0 || shading > 4) {
            std::fprintf(stderr, "lights K MODE REPS: K from 0 to %d lights, MODE 0 to 4\n", glint_bench::light_pixels::lights);
            return 2;
        }
        for (int rep = 0; rep < std::atoi(argv[4]); ++rep)
            for (int i = 0; i < glint_bench::light_pixels::pixels; ++i) sum += static_cast<double>(glint_bench::shade_light_pixel(lp, i, k, shading).x);
    } else if (argc == 4 && !std::strcmp(mode, "lobe-tree") && (!std::strcmp(argv[2], "metal") || !std::strcmp(argv[2], "pyramids"))) {
        // bench/report_lobe_tree.cpp's two workloads: the queries from its direct P-NDF, the forest
        // as its delta_k 0.3 row (metal) or its Beckmann row (pyramids).
        const bool metal = !std::strcmp(argv[2], "metal");
        const auto h = glint_bench::quilt(glint_bench::sample(metal ? glint::pattern::scratched_metal : glint::pattern::pyramids, 256), 2048);
        const float sigma_r = metal ? 0.005f : 0.1f;
        const auto f = glint_bench::build(h, metal ? glint::lobe_kind::gaussian : glint::lobe_kind::beckmann, sigma_r, metal ? 0.3f : 30.0f);
        glint::gaussian_params<float> g;
        g.sigma_r = sigma_r;
        const auto q = glint_bench::queries(glint::gaussian_pndf<float>::build(h.materialize(), g), 2048);
        double least = 1e30;
        for (int pass = 0; pass < std::atoi(argv[3]); ++pass) {
            const auto start = std::chrono::steady_clock::now();
            for (const auto& x : q) sum += static_cast<double>(lobe_forest_eval(f, x));
            least = std::min(least, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / static_cast<double>(q.size()));
        }
        std::printf("lobe-tree %s: %.0f ns a query (the least of %s passes of %zu)\n", argv[2], least, argv[3], q.size());
    } else {
        std::fprintf(stderr, "usage: glint_frame_loop point|point-smooth|point-stochastic|point-rows|point-rows-smooth|point-rows-stochastic FRAMES | ibl|ibl-stochastic|ibl-rows|ibl-rows-stochastic|ibl-lookup|ibl-radiance K FRAMES | ibl-pixels K | draw N P | draw-time N P PAIRS | lights K MODE REPS | lobe-tree metal|pyramids PASSES\n");
        return 2;
    }
    std::printf("%s: sum %.9g\n", mode, sum);
    return 0;
}
