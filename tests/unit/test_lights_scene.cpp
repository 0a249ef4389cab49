// The showcase's lights scene (examples/lights_scene.hpp): render_row, which batches the glint
// estimates of a row's pixels through glint::grid_sample_pixels, gives render_pixel's values and
// draws bit for bit, for every light, with and without glints, on four lattice points and on one.
#include <doctest/doctest.h>

#include "../support/lanes_paths.hpp"

#include <cstdint>
#include <cstring>
#include <vector>

#include "lights_scene.hpp"

using namespace glint_examples;

TEST_CASE("lights scene: render_row (batched glint estimates) equals render_pixel bit for bit, every light and mode") {
    glint_test::for_each_lanes_path([&](int) {
        const camera cam(160, 100);
        long pixels = 0, glinty = 0, differ = 0;
        std::uint64_t row_draws = 0, pixel_draws = 0;
        for (light_type t : {light_type::point, light_type::sun, light_type::area})
            for (int mode = 0; mode < 4; ++mode) {
                scene_options opt;
                opt.smooth = mode == 0;
                opt.stochastic_lattice = mode == 2;
                opt.variant = mode == 3 ? glint::binomial_variant::gated : glint::binomial_variant::unbiased;
                opt.log_density = 3.0f;
                light_setup ls;
                ls.type = t;
                shading_counters by_row, by_pixel;
                std::vector<vec3> row(160);
                for (int y = 0; y < 100; ++y) {
                    // Spans that end inside a 32-pixel chunk and one that starts inside another.
                    render_row(opt, ls, cam, y, 0, 37, row.data(), by_row);
                    render_row(opt, ls, cam, y, 37, 160, row.data() + 37, by_row);
                    for (int x = 0; x < 160; ++x) {
                        const shading_counters before = by_pixel;
                        const vec3 p = render_pixel(opt, ls, cam, x, y, by_pixel);
                        differ += std::memcmp(&p, &row[static_cast<std::size_t>(x)], sizeof(p)) != 0;
                        glinty += by_pixel.draws > before.draws;
                        ++pixels;
                    }
                }
                row_draws += by_row.draws, pixel_draws += by_pixel.draws;
            }
        MESSAGE(pixels << " pixels (" << glinty << " with draws, " << pixel_draws << " draws), " << differ << " differ");
        CHECK(glinty > pixels / 50);  // the comparison covers the glints' draws
        CHECK(differ == 0);
        CHECK(row_draws == pixel_draws);
    });
}
