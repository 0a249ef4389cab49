// The lobe-tree workload of the report (bench/report_lobe_tree.cpp) and of glint_frame_loop's
// "lobe-tree" mode, so that callgrind counts what the report times: a 2048^2 map quilted from a
// 256^2 sample, its lobe forest, and 200 footprints with an s each from the exact P-NDF.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glint/gaussian.hpp>
#include <glint/lobe_tree.hpp>
#include <glint/patterns.hpp>

namespace glint_bench {

using forest = glint::lobe_forest<float>;

inline double unit(std::uint32_t i, std::uint32_t k) { return glint::unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, k, 0x2e77u)).x); }

inline glint::normal_map sample(glint::pattern kind, int size) {
    glint::pattern_params p;
    p.kind = kind, p.width = p.height = size, p.seed = 3, p.slope_rms = 0.15, p.feature = 8;
    p.count = 60;  // scratched_metal: about one segment per 1100 texels
    return glint::make_normal_map(p);
}

// Automatic blocks (128, overlap 8 from a 256^2 sample) unless block > 0; tolerance 0.1, 1024
// candidates: the defaults.
inline glint::quilted_map quilt(const glint::normal_map& s, int out, int block = 0, int overlap = 0) {
    glint::quilt_params q;
    q.width = q.height = out, q.block = block, q.overlap = overlap;
    return glint::quilted_map::synthesize(s, q);
}

inline forest build(const glint::quilted_map& h, glint::lobe_kind kind, float sigma_r, float delta_k) {
    glint::lobe_params<float> l;
    l.kind = kind, l.sigma_r = sigma_r;
    glint::cluster_params<float> c;
    c.delta_k = delta_k;
    return forest::build(h, l, c);
}

struct query {
    glint::texel_footprint<float> fp;
    glm::vec2 s;
};

// 200 footprints (sd log-uniform in [lo, hi] texels, aspect 0.5 to 1, any rotation, anywhere on
// H), each with one s drawn from the exact P-NDF, where it lives.
inline std::vector<query> queries(const glint::gaussian_pndf<float>& d, int side, double lo = 1, double hi = 64, std::size_t count = 200) {
    std::vector<query> q;
    for (std::uint32_t i = 0; q.size() < count && i < 10000; ++i) {
        const double sd = lo * std::pow(hi / lo, unit(i, 1)), t = 3.14159 * unit(i, 2);
        const glm::dmat2 R(std::cos(t), std::sin(t), -std::sin(t), std::cos(t));
        glint::texel_footprint<float> fp;
        fp.center = glm::vec2(static_cast<float>(side * unit(i, 3)), static_cast<float>(side * unit(i, 4)));
        fp.covariance = glm::mat2(R * glm::dmat2(sd * sd, 0, 0, sd * sd * (0.25 + 0.75 * unit(i, 5))) * glm::transpose(R));
        const auto x = d.sample(fp, static_cast<float>(unit(i, 6)), static_cast<float>(unit(i, 7)), static_cast<float>(unit(i, 8)));
        if (x.valid) q.push_back({fp, x.s});
    }
    return q;
}

}  // namespace glint_bench
