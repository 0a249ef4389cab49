// glint's core numerics in a few lines: counter-based random numbers for a pixel, a normal
// variate from them, and the probability that at least one of N microfacets reflects.
#include <cstdio>

#include <glint/core.hpp>

int main() {
    // Counter-based: the same pixel, frame and purpose always give the same numbers, on the
    // CPU and in a shader (kernels/core.glsl), so nothing has to be stored or synchronised.
    const unsigned pixel_x = 640, pixel_y = 360, purpose = 7;
    const glm::uvec3 bits = glint::pcg3d(glm::uvec3(pixel_x, pixel_y, purpose));
    const float u = glint::open_unit_from_bits<float>(bits.x);  // in (0, 1), never 0 or 1
    const float z = glint::normal_quantile(u);                 // a standard normal variate
    std::printf("pixel (%u, %u): u = %.7f, Phi^-1(u) = %+.6f\n", pixel_x, pixel_y, static_cast<double>(u),
                static_cast<double>(z));

    // P(at least one of N facets reflects) for p = 1e-7, N = 1e7: exactly 1 - e^-1 = 0.632121.
    // pow(1 - p, N) in float rounds 1 - p: (1 - p)^N comes out 17% low and this 10% high
    // (KK25 Fig. 5).
    const float p = 1e-7f, N = 1e7f;
    std::printf("1 - (1 - p)^N at p = 1e-7, N = 1e7: naive %.6f, KK25 Eq. 25 %.6f, log1p/expm1 %.6f\n",
                static_cast<double>(glint::any_success(p, N, glint::pow_method::naive)),
                static_cast<double>(glint::any_success(p, N, glint::pow_method::kk25)),
                static_cast<double>(glint::any_success(p, N)));
    return 0;
}
