// Shared by the P-NDF tests and the report: rotated Gaussian footprints, a P-NDF over a
// procedural map, and the histogram of a normal map's interpolated normals under a footprint with
// a P-NDF's masses in the same bins. D_P is a sum of Gaussian lobes
// (kernels/gaussian.glsl), each integrated over the bins by 16 x 16 stratified points through its
// Cholesky factor (lobes as thin as sigma_r = 1e-4 lie far inside a bin, so this is exact enough
// where point sampling of D_P would alias), over every element image in the 7-sigma box.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glint/core.hpp>
#include <glint/gaussian.hpp>
#include <glint/patterns.hpp>

namespace glint_test {

// The covariance with sds (a, b) along the axes rotated by angle t.
template <class real>
glm::mat<2, 2, real, glm::defaultp> rotated_covariance(real a, real b, real t) {
    using m2 = glm::mat<2, 2, real, glm::defaultp>;
    const m2 R(std::cos(t), std::sin(t), -std::sin(t), std::cos(t));
    return R * m2(a * a, 0, 0, b * b) * glm::transpose(R);
}

template <class real>
glint::texel_footprint<real> rotated_footprint(glm::vec<2, real, glm::defaultp> c, real a, real b, real t) {
    glint::texel_footprint<real> f;
    f.center = c, f.covariance = rotated_covariance(a, b, t);
    return f;
}

// A footprint and an s where the P-NDF lives, for timing queries.
struct pndf_query {
    glint::texel_footprint<float> fp;
    glm::vec2 s;
};

// n queries: footprints of sd `sd` (aspect 1 to 2, any rotation) centred uniformly over `spread`
// periods of the pattern, s within 0.01 of the pattern's normal at the centre on each axis; the
// variates from PCG3D of (i, stream, salt).
inline std::vector<pndf_query> pndf_queries(const glint::pattern_params& p, float sd, int n, float spread, std::uint32_t salt) {
    const auto unit = [salt](std::uint32_t i, std::uint32_t stream) { return glint::unit_from_bits<float>(glint::pcg3d(glm::uvec3(i, stream, salt)).x); };
    std::vector<pndf_query> q;
    for (int i = 0; i < n; ++i) {
        const auto u = static_cast<std::uint32_t>(i);
        const glm::vec2 c(static_cast<float>(p.width) * spread * unit(u, 1), static_cast<float>(p.height) * spread * unit(u, 2));
        const glm::dvec3 nrm = glint::pattern_normal(p, glm::dvec2(c));
        q.push_back({rotated_footprint(c, sd, sd * (0.5f + 0.5f * unit(u, 3)), 3.1f * unit(u, 4)),
                     glm::vec2(static_cast<float>(nrm.x), static_cast<float>(nrm.y)) + 0.02f * glm::vec2(unit(u, 5) - 0.5f, unit(u, 6) - 0.5f)});
    }
    return q;
}

// The P-NDF (default culling, one element per texel) of a square periodic pattern.
template <class real>
glint::gaussian_pndf<real> pattern_pndf(glint::pattern kind, int size, double slope_rms, real sigma_r) {
    glint::pattern_params p;
    p.kind = kind, p.width = p.height = size, p.slope_rms = slope_rms;
    glint::gaussian_params<real> g;
    g.sigma_r = sigma_r;
    return glint::gaussian_pndf<real>::build(glint::make_normal_map(p), g);
}

struct normal_bins {
    int bins = 32;
    double lo = -0.32, width = 0.02;  // bins x bins cells of `width` from (lo, lo)
    int of(glm::dvec2 s) const {
        const int bx = static_cast<int>(std::floor((s.x - lo) / width)), by = static_cast<int>(std::floor((s.y - lo) / width));
        return bx >= 0 && bx < bins && by >= 0 && by < bins ? bx + bins * by : -1;
    }
};

// The share of n points u ~ N(fp) whose bicubic normal falls in each bin (counter-based seeds).
inline std::vector<double> normal_histogram(const glint::normal_map& map, const glint::texel_footprint<double>& fp, const normal_bins& b, std::size_t n) {
    std::vector<double> hist(static_cast<std::size_t>(b.bins * b.bins), 0.0);
    const glm::dmat2& c = fp.covariance;
    const glm::dmat2 L(std::sqrt(c[0][0]), c[0][1] / std::sqrt(c[0][0]), 0, std::sqrt(c[1][1] - c[0][1] * c[0][1] / c[0][0]));
    for (std::uint32_t i = 0; i < n; ++i) {
        const double r = std::sqrt(-2 * std::log(glint::open_unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, 1u, 0x9a55u)).x)));
        const double phi = 6.283185307179586 * glint::open_unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, 2u, 0x9a55u)).x);
        const int k = b.of(map.bicubic(fp.center + L * glm::dvec2(r * std::cos(phi), r * std::sin(phi))).s);
        if (k >= 0) hist[static_cast<std::size_t>(k)] += 1.0 / static_cast<double>(n);
    }
    return hist;
}

// The P-NDF's mass in each bin (no culling: the reference's elements).
inline std::vector<double> pndf_bin_masses(const glint::gaussian_pndf<double>& pndf, const glint::texel_footprint<double>& fp, const normal_bins& b) {
    using k = glint::detail::glsl::kernels<double>;
    auto kp = pndf.kernel_params();
    kp.cull_u = 7, kp.cull_s = 0;
    const glm::dmat2& c = fp.covariance;
    const auto f = k::glint_pndf_prepare(fp.center, {c[0][0], c[1][0], c[1][1], glm::determinant(c)}, kp.sigma_h, kp.cull_u, kp.cull_s);
    double z[16];
    for (int j = 0; j < 16; ++j) z[j] = glint::normal_quantile((j + 0.5) / 16);
    std::vector<double> model(static_cast<std::size_t>(b.bins * b.bins), 0.0);
    const auto& data = pndf.element_data();
    for (int j = static_cast<int>(std::floor((fp.center.y - f.extent.y) / kp.spacing)); j * kp.spacing < fp.center.y + f.extent.y; ++j)
        for (int i = static_cast<int>(std::floor((fp.center.x - f.extent.x) / kp.spacing)); i * kp.spacing < fp.center.x + f.extent.x; ++i) {
            const int wi = ((i % kp.width) + kp.width) % kp.width, wj = ((j % kp.height) + kp.height) % kp.height;
            const std::size_t e = static_cast<std::size_t>(wi + kp.width * wj);
            const typename k::glint_gaussian_element el{data[2 * e], data[2 * e + 1]};
            const auto lobe = k::glint_pndf_element_lobe(el, {(i + 0.5) * kp.spacing, (j + 0.5) * kp.spacing}, f, kp);
            if (!(lobe.weight > 1e-14)) continue;
            const double sr2 = kp.sigma_r * kp.sigma_r, c11 = sr2 + lobe.b.x * lobe.b.x + lobe.b.z * lobe.b.z;
            const double l11 = std::sqrt(c11), l21 = (lobe.b.x * lobe.b.y + lobe.b.z * lobe.b.w) / l11, l22 = std::sqrt(std::max(lobe.det_c / c11, 0.0));
            for (int a = 0; a < 16; ++a)
                for (int q = 0; q < 16; ++q) {
                    const int bin = b.of(lobe.mean + glm::dvec2(l11 * z[a], l21 * z[a] + l22 * z[q]));
                    if (bin >= 0) model[static_cast<std::size_t>(bin)] += lobe.weight / 256;
                }
        }
    return model;
}

inline double l1_distance(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d += std::fabs(a[i] - b[i]);
    return d;
}

}  // namespace glint_test
