// A 3D tracer of an extruded scratch profile, independent of glint's 2D tracer: the profile
// extruded along u = X, its cross-section in (Y = v, Z = n); a 3D ray is tested against every
// segment's plane (no hierarchy), reflected in 3D, and attenuated by Fresnel at the 3D cosine;
// non-periodic profiles only. Used by tests/stat/test_scratch_stat.cpp and bench/report_scratch.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glint/scratch.hpp>

namespace glint_test {

struct tracer3d {
    const glint::scratch_profile& p;
    glint::scratch_fresnel fresnel;
    struct result {
        glm::dvec3 d;
        glm::dvec3 f;
        bool ok;
    };
    result trace(double y0, glm::dvec3 d) const {
        glm::dvec3 o(0, y0, 0);
        glm::dvec3 f(1);
        int last = -1;
        for (int bounce = 0; bounce < 64; ++bounce) {
            double best = 1e300;
            int hit = -1;
            for (std::size_t k = 0; k + 1 < p.x.size(); ++k) {
                if (static_cast<int>(k) == last) continue;
                const double dy = p.x[k + 1] - p.x[k], dz = p.h[k + 1] - p.h[k], l = std::hypot(dy, dz);
                const glm::dvec3 m(0, -dz / l, dy / l);
                const double dn = glm::dot(d, m);
                if (!(dn < 0)) continue;
                const double t = glm::dot(glm::dvec3(0, p.x[k], p.h[k]) - o, m) / dn;
                if (!(t > 0) || t >= best) continue;
                const double y = o.y + t * d.y;
                if (y < p.x[k] - 1e-12 || y > p.x[k + 1] + 1e-12) continue;
                best = t, hit = static_cast<int>(k);
            }
            if (hit < 0) return {d, f, d.z > 0};
            const std::size_t hk = static_cast<std::size_t>(hit);
            const double dy = p.x[hk + 1] - p.x[hk], dz = p.h[hk + 1] - p.h[hk], l = std::hypot(dy, dz);
            const glm::dvec3 m(0, -dz / l, dy / l);
            const double c = -glm::dot(d, m);
            f *= fresnel(c);
            o += best * d;
            d = glm::normalize(d + 2 * c * m);
            last = hit;
        }
        return {d, f, false};
    }
};

// The Fresnel models Eq. 2's error is measured for (RGB16 Sec. 4.2: Schlick for dielectrics, a
// conductor; notes 1.4's table).
struct eq2_model {
    const char* name;
    glint::scratch_fresnel f;
};
inline std::vector<eq2_model> eq2_models() {
    return {{"Schlick F0 = 0.53", glint::scratch_fresnel::schlick(glm::dvec3(0.53))},
            {"Schlick F0 = 0.04", glint::scratch_fresnel::schlick(glm::dvec3(0.04))},
            {"iron, exact", glint::scratch_fresnel::iron()}};
}

// The tracer's table at elevation theta: rho[o][i] (and the sums of squared weights, for
// variances) from N rays per incident bin entering at theta_i = -theta, x stratified, sin(phi_i)
// uniform in the bin; channel 0 of the Fresnel. worst_theta: the largest |theta_o - theta| seen.
struct traced_table {
    std::vector<double> sum, sum2;
    double worst_theta = 0;
};

inline double scratch_rnd(std::uint32_t i, std::uint32_t j, std::uint32_t salt) {
    return (glint::pcg3d(glm::uvec3(i, j, salt)).x + 0.5) * 2.3283064365386962890625e-10;
}

inline traced_table trace_table(const glint::scratch_profile& p, const glint::scratch_fresnel& f, int M, int N, double theta) {
    const double pi = 3.14159265358979323846;
    const tracer3d tr{p, f};
    traced_table t;
    t.sum.assign(static_cast<std::size_t>(M * M), 0.0), t.sum2.assign(static_cast<std::size_t>(M * M), 0.0);
    for (int i = 0; i < M; ++i) {
        const double s0 = std::sin(-pi / 2 + i * pi / M), s1 = std::sin(-pi / 2 + (i + 1) * pi / M);
        for (int r = 0; r < N; ++r) {
            const double s = s0 + scratch_rnd(static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(i), 91) * (s1 - s0), c = std::sqrt(1 - s * s);
            const glm::dvec3 wi(std::sin(-theta), std::cos(theta) * s, std::cos(theta) * c);
            const auto e = tr.trace(-0.5 + (r + scratch_rnd(static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(i), 92)) / N, -wi);
            if (!e.ok) continue;
            t.worst_theta = std::max(t.worst_theta, std::fabs(std::asin(e.d.x) - theta));
            const int o = glint::detail::glsl::kernels<double>::glint_scratch_bin(std::atan2(e.d.y, e.d.z), M);
            const double w = e.f.x / (N * glint::scratch_table::bin_ds(o, M));
            t.sum[static_cast<std::size_t>(o * M + i)] += w, t.sum2[static_cast<std::size_t>(o * M + i)] += w * w;
        }
    }
    return t;
}

// Eq. 2's relative L1 error (mass-weighted over the table) against a traced table at theta, the
// traced table symmetrised as the table is; nearest reads.
inline double eq2_error(const glint::scratch_table& table, const traced_table& ref, double theta) {
    const double pi = 3.14159265358979323846;
    const int M = table.resolution();
    auto v = table.view<double>();
    v.filter = glint::scratch_filter::nearest;
    double num = 0, den = 0;
    for (int o = 0; o < M; ++o)
        for (int i = 0; i < M; ++i) {
            const std::size_t b = static_cast<std::size_t>(o * M + i);
            const double w = glint::scratch_table::bin_ds(o, M) * glint::scratch_table::bin_ds(i, M);
            const double r = 0.5 * (ref.sum[b] + ref.sum[static_cast<std::size_t>(i * M + o)]);
            const double pred = v.rho(theta, -pi / 2 + (o + 0.5) * pi / M, -pi / 2 + (i + 0.5) * pi / M).x;
            num += std::fabs(pred - r) * w, den += r * w;
        }
    return num / den;
}

}  // namespace glint_test
