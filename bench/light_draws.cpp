// How sparse the several-lights workload's glints are (bench/light_pixels.hpp, the report's and
// glint_frame_loop's "lights"): draws a light, the share of lights that draw at all, and the mean
// N E[R], for shade_light_pixel's glint modes 1 (four lattice points) and 3 (one).
//   glint_light_draws
// Its own program, so that glint_frame_loop's instruction counts stay as GCC inlines them there.
#include <cstdio>

#include "light_pixels.hpp"

int main() {
    const glint_bench::light_pixels lp;
    const float dh = glint::total_area(glint::ndf::ggx, glm::vec2(0.25f));
    for (const int mode : {1, 3}) {
        double draws = 0, drawing = 0, n_expected = 0;
        for (int i = 0; i < glint_bench::light_pixels::pixels; ++i) {
            const auto at = static_cast<std::size_t>(i);
            const glint::grid_params<float> g = glint_bench::light_pixel_params(i);
            auto px = glint::grid_pixel_setup(lp.uv[at], lp.duvdx[at], lp.duvdy[at], g, glint_bench::light_pixel_lattice_u(i, mode));
            for (int l = 0; l < glint_bench::light_pixels::lights; ++l) {
                glm::vec3 hv;
                glint_bench::smooth_point(lp.wi[static_cast<std::size_t>(i * glint_bench::light_pixels::lights + l)], lp.wo[at], hv);
                const auto e = glint::grid_sample(px, g, glint::grid_point_light(glint::ndf::ggx, glm::vec2(0.25f), dh, hv));
                draws += e.draws, drawing += e.draws > 0 ? 1 : 0, n_expected += static_cast<double>(px.N * e.expected);
            }
        }
        const double count = glint_bench::light_pixels::pixels * glint_bench::light_pixels::lights;
        std::printf("mode %d: %.3f draws a light, %.3f of the lights draw, mean N E[R] %.4f\n", mode, draws / count, drawing / count, n_expected / count);
    }
    return 0;
}
