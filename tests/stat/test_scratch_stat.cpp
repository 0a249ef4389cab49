// Scratched materials (glint/scratch.hpp): the statistical tests. Each states its sample count
// and significance, and each is shown to reject a deliberately wrong variant.
//   - V-groove at normal incidence: the two spikes' masses and Fresnel values against their exact
//     expectations;
//   - reciprocity of the raw table (chi-square over bin pairs), against a variant that puts every
//     ray at its bin's centre angle;
//   - an independent 3D tracer of the extruded profile (brute force over segments, 3D reflection
//     and Fresnel): theta_o = -theta_i, its slices at theta = 0 and pi/3 against the table by a
//     two-sample chi-square, and Eq. 2's error at 15, 30, 45 and 75 degrees for three Fresnel models;
//   - Eq. 5's sampler by chi-square against its pdf on four profiles and five views, against
//     variants without the bin width (a pdf lacking the Jacobian) and with phi uniform in the bin;
//     the estimator's mean against quadrature (z-test);
//   - Eq. 6's light kernel: integrated over light directions it gives Eq. 5's integral;
//   - Eq. 3's footprint estimate: unbiased over its jitter, and the stationary area at large footprints.
#include <doctest/doctest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glint/scratch.hpp>
#include <glint/testing/stats.hpp>

#include "../support/scratch_support.hpp"

namespace {

template <class real>
using K = glint::detail::glsl::kernels<real>;
namespace gt = glint::testing;

const double pi = 3.14159265358979323846;
const double deg = pi / 180;

double rnd(std::uint32_t i, std::uint32_t j, std::uint32_t salt) { return glint_test::scratch_rnd(i, j, salt); }

glint::scratch_table table(const glint::scratch_profile& p, const glint::scratch_fresnel& f, int M, int N, bool sym, std::uint32_t seed = 0) {
    glint::scratch_table_options o;
    o.resolution = M, o.rays_per_row = N, o.symmetrize = sym, o.seed = seed;
    return glint::build_scratch_table(p, f, o);
}

// Two weighted histograms of the same quantity: sum over cells of (a - b)^2 / (var_a + var_b),
// cells whose combined weight count is below `min_count` pooled into one. chi-square with as many
// degrees of freedom as cells.
struct two_sample {
    std::vector<double> a, va, b, vb, count;
    void resize(std::size_t n) { a.assign(n, 0), va.assign(n, 0), b.assign(n, 0), vb.assign(n, 0), count.assign(n, 0); }
    gt::chi_square_result test(double min_count = 20) const {
        double stat = 0, pa = 0, pva = 0, pb = 0, pvb = 0;
        int cells = 0;
        for (std::size_t k = 0; k < a.size(); ++k) {
            if (count[k] >= min_count) {
                if (va[k] + vb[k] > 0) stat += (a[k] - b[k]) * (a[k] - b[k]) / (va[k] + vb[k]), ++cells;
            } else {
                pa += a[k], pva += va[k], pb += b[k], pvb += vb[k];
            }
        }
        if (pva + pvb > 0) stat += (pa - pb) * (pa - pb) / (pva + pvb), ++cells;
        gt::chi_square_result r;
        r.statistic = stat, r.degrees_of_freedom = cells, r.cells = static_cast<std::size_t>(cells);
        r.p_value = cells > 0 ? gt::chi_square_survival(stat, cells) : 1;
        return r;
    }
};

}  // namespace

TEST_CASE("scratch V-groove at normal incidence: two spikes at +-2 beta with the expected mass and Fresnel") {
    // M = 64: bin 32 holds phi_i in [0, pi/64]; with 2 beta = 39.375 degrees (an edge, 46 pi/64 - pi/2)
    // the left facet's exits 2 beta - phi_i fill exactly bin 45 and the right facet's bin 17.
    // Expected mass: a ray of angle phi meets the left facet when it enters left of d tan(phi),
    // d = tan(beta) / 2, so P(left) = E[1/2 + tan(beta) tan(phi) / 2] over sin(phi) uniform in the bin,
    // and its Fresnel at cos(beta - phi) (at theta = pi/3: cos(beta - phi) / 2). N = 200,000 rays in the row: sd <= 0.5 / sqrt(N) = 1.1e-3
    // of the row's mass; tolerance 5 sd (two-sided p 6e-7 each).
    const int M = 64, N = 200000;
    const double beta = 0.5 * (46 * pi / M - pi / 2);
    const auto f = glint::scratch_fresnel::schlick(glm::dvec3(0.04, 0.5, 0.9));
    const auto t = table(glint::make_v_groove(beta), f, M, N, false);
    const int row = 32;
    double left = 0, right = 0, fl = 0, fr = 0, fl60 = 0;
    const double s0 = std::sin(-pi / 2 + row * pi / M), s1 = std::sin(-pi / 2 + (row + 1) * pi / M);
    const int q = 20000;
    for (int k = 0; k < q; ++k) {
        const double s = s0 + (k + 0.5) / q * (s1 - s0), phi = std::asin(s), pl = 0.5 + 0.5 * std::tan(beta) * std::tan(phi);
        left += pl / q, right += (1 - pl) / q;
        fl += pl * f(std::cos(beta - phi)).x / q, fr += (1 - pl) * f(std::cos(beta + phi)).x / q;
        fl60 += pl * f(0.5 * std::cos(beta - phi)).x / q;
    }
    // The raw table holds rho[o][i] = count(i -> o) / (N ds_o).
    const auto mass = [&](const std::vector<double>& r, int o) { return r[static_cast<std::size_t>(o * M + row)] * glint::scratch_table::bin_ds(o, M); };
    const double tol = 5 * 0.5 / std::sqrt(static_cast<double>(N));
    MESSAGE("left spike " << mass(t.rho_m(), 45) << " (expected " << left << "), right " << mass(t.rho_m(), 17) << " (" << right << ")");
    CHECK(std::fabs(mass(t.rho_m(), 45) - left) < tol);
    CHECK(std::fabs(mass(t.rho_m(), 17) - right) < tol);
    CHECK(std::fabs(mass(t.rho_0(0), 45) - fl) < tol);
    CHECK(std::fabs(mass(t.rho_0(0), 17) - fr) < tol);
    // Eq. 2's exponent of the spike's bin: ln r / ln(2/3), r = (F60 - F0) / (1 - F0) as masses
    // (at phi_i = 0 exactly: ln[(F(cos(beta)/2) - F(cos beta)) / (1 - F(cos beta))] / ln(2/3)).
    const double gamma = std::log((fl60 - fl) / (left - fl)) / std::log(2.0 / 3.0);
    MESSAGE("left spike's gamma " << t.gamma(0)[static_cast<std::size_t>(45 * M + row)] << " (expected " << gamma << ")");
    CHECK(t.gamma(0)[static_cast<std::size_t>(45 * M + row)] == doctest::Approx(gamma).epsilon(1e-3));
    double rest = 0;
    for (int o = 0; o < M; ++o)
        if (o != 45 && o != 17) rest += mass(t.rho_m(), o);
    CHECK(rest == 0);
    // The wrong facet angle (beta + 1 degree) moves the spikes: caught.
    const auto wrong = table(glint::make_v_groove(beta + 1 * deg), f, M, 20000, false);
    CHECK(std::fabs(mass(wrong.rho_m(), 45) - left) > tol);
}

TEST_CASE("scratch table: raw counts are reciprocal (chi-square over bin pairs), rays at bin centres are not") {
    // Under reciprocity E[count(i -> j)] / E[count(j -> i)] = ds_j / ds_i, so given the pair's total
    // n, count(i -> j) is binomial(n, ds_j / (ds_i + ds_j)). Pairs with n p (1 - p) >= 5 enter
    // individually, the rest pooled into one. M = 32, N = 40,000 rays per row (1.28e6 rays), the steep
    // quartic; family alpha 0.01 over the two tests (Sidak). With ~260 pairs the test resolves a
    // uniform relative asymmetry of about 3 / sqrt(n_pair) in every pair. The table's rays are
    // stratified in x, so its counts vary less than binomially and the statistic runs below its
    // degrees of freedom (measured 152 / 264): the test is conservative; the variant shows its power.
    const int M = 32, N = 40000;
    const double alpha = gt::sidak_alpha(0.01, 2);
    const auto reciprocity = [&](const std::vector<double>& rho) {
        double stat = 0, pooled_o = 0, pooled_e = 0, pooled_v = 0;
        int cells = 0;
        for (int i = 0; i < M; ++i)
            for (int j = i + 1; j < M; ++j) {
                const double di = glint::scratch_table::bin_ds(i, M), dj = glint::scratch_table::bin_ds(j, M);
                // count(i -> j) = rho[j][i] N ds_j.
                const double cij = std::round(rho[static_cast<std::size_t>(j * M + i)] * N * dj), cji = std::round(rho[static_cast<std::size_t>(i * M + j)] * N * di);
                const double n = cij + cji, p = dj / (di + dj), e = n * p, v = n * p * (1 - p);
                if (v >= 5) stat += (cij - e) * (cij - e) / v, ++cells;
                else pooled_o += cij, pooled_e += e, pooled_v += v;
            }
        if (pooled_v > 0) stat += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_v, ++cells;
        gt::chi_square_result r;
        r.statistic = stat, r.degrees_of_freedom = cells, r.p_value = gt::chi_square_survival(stat, cells);
        return r;
    };
    const auto profile = glint::make_quartic_groove(0.5, 256);
    const auto t = table(profile, glint::scratch_fresnel::mirror(), M, N, false, 7);
    const auto good = reciprocity(t.rho_m());
    MESSAGE("reciprocity: chi2 " << good.statistic << " / " << good.degrees_of_freedom << " dof, p " << good.p_value);
    CHECK_FALSE(good.rejects(alpha));
    // The variant: every ray of row i at the bin's centre angle (the paper's discrete phi_i).
    const glint::detail::scratch_tracer tr(profile);
    std::vector<double> biased(static_cast<std::size_t>(M * M), 0.0);
    for (int i = 0; i < M; ++i) {
        const double phi = -pi / 2 + (i + 0.5) * pi / M;
        for (int r = 0; r < N; ++r) {
            const auto e = tr.trace(-0.5 + (r + rnd(static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(i), 3)) / N, -std::sin(phi), -std::cos(phi), 64, nullptr, true);
            if (e.lost || !(e.dy > 0)) continue;
            const int j = K<double>::glint_scratch_bin(std::atan2(e.dx, e.dy), M);
            biased[static_cast<std::size_t>(j * M + i)] += 1 / (N * glint::scratch_table::bin_ds(j, M));
        }
    }
    const auto bad = reciprocity(biased);
    MESSAGE("bin-centre variant: chi2 " << bad.statistic << " / " << bad.degrees_of_freedom << " dof, p " << bad.p_value);
    CHECK(bad.rejects(alpha));
}

TEST_CASE("scratch table against an independent 3D tracer: theta_o = -theta_i, slices at 0 and pi/3, Eq. 2's error") {
    // Steep quartic (32 segments, so the brute-force tracer stays fast), M = 32. Table: 8,000 rays
    // per row; 3D tracer: 8,000 per row at each theta. The Eq. 2 errors printed here sit on this
    // size's noise floor (the error at theta = 0 and pi/3, where Eq. 2 is exact); the report
    // (bench/report_scratch.cpp) measures them with 25x the rays. Slices compared per bin by a two-sample
    // chi-square (variance: sum of squared weights for the tracer, (sum w)^2 / count for the
    // table's bins), family alpha 0.01 over the 6 tests (3 Fresnel models x 2 slices). Both sides
    // stratify their rays, so the statistic runs below its degrees of freedom (measured about 0.6
    // per degree): conservative; the wrong slice shows its power.
    const int M = 32, N = 8000;
    const auto profile = glint::make_quartic_groove(0.5, 32);
    const double alpha = gt::sidak_alpha(0.01, 6);
    double worst_theta = 0;
    for (const auto& md : glint_test::eq2_models()) {
        const auto raw = table(profile, md.f, M, N, false, 11);
        const auto sym = table(profile, md.f, M, N, true, 11);
        const double thetas[] = {0, 60, 15, 30, 45, 75};
        std::string row_text;
        for (double th_deg : thetas) {
            const double th = th_deg * deg;
            const auto traced = glint_test::trace_table(profile, md.f, M, N, th);
            const auto& sum = traced.sum;
            const auto& sum2 = traced.sum2;
            worst_theta = std::max(worst_theta, traced.worst_theta);
            if (th_deg == 0 || th_deg == 60) {
                two_sample ts;
                ts.resize(static_cast<std::size_t>(M * M));
                const auto& slice = th_deg == 0 ? raw.rho_0(0) : raw.rho_60(0);
                for (int o = 0; o < M; ++o)
                    for (int i = 0; i < M; ++i) {
                        const std::size_t b = static_cast<std::size_t>(o * M + i);
                        const double unit = 1 / (N * glint::scratch_table::bin_ds(o, M));
                        const double count = raw.rho_m()[b] / unit;
                        ts.a[b] = slice[b], ts.va[b] = count > 0 ? slice[b] * slice[b] / count : 0;
                        ts.b[b] = sum[b], ts.vb[b] = sum2[b], ts.count[b] = count + (sum[b] > 0 ? sum[b] * sum[b] / sum2[b] : 0);
                    }
                const auto r = ts.test();
                MESSAGE(std::string(md.name) << ", theta " << th_deg << ": table vs 3D tracer chi2 " << r.statistic << " / " << r.degrees_of_freedom << ", p " << r.p_value);
                CHECK_FALSE(r.rejects(alpha));
                if (th_deg == 60 && std::string(md.name) == "Schlick F0 = 0.04") {
                    // The wrong slice (theta = 0's in place of pi/3's) is rejected.
                    for (std::size_t b = 0; b < ts.a.size(); ++b) {
                        const double count = raw.rho_m()[b] * N * glint::scratch_table::bin_ds(static_cast<int>(b) / M, M);
                        ts.a[b] = raw.rho_0(0)[b], ts.va[b] = count > 0 ? ts.a[b] * ts.a[b] / count : 0;
                    }
                    const auto w = ts.test();
                    MESSAGE("  theta 0's slice in place of pi/3's: chi2 " << w.statistic << " / " << w.degrees_of_freedom << ", p " << w.p_value);
                    CHECK(w.rejects(alpha));
                }
            }
            // Eq. 2's relative L1 error over the table (mass-weighted) at this theta.
            const double err = glint_test::eq2_error(sym, traced, th);
            row_text += " " + std::to_string(static_cast<int>(th_deg)) + ": " + std::to_string(err);
            // theta = 0 and pi/3 show the noise floor (Eq. 2 is exact there).
            CHECK(err < 0.25);
        }
        MESSAGE(std::string(md.name) << ", Eq. 2 relative L1 error vs the 3D tracer by theta (deg):" << row_text);
    }
    MESSAGE("worst |theta_o + theta_i| " << worst_theta);
    CHECK(worst_theta < 1e-12);
}

namespace {

// Draws phi_i for view phi_o from the table by the kernel's method, or a wrong variant.
enum class variant { kernel, no_jacobian, uniform_angle };

double draw(const glint::scratch_table& t, int o, double u1, double u2, variant v) {
    const int M = t.resolution();
    const auto& rm = t.rho_m();
    double total = 0;
    for (int i = 0; i < M; ++i) total += rm[static_cast<std::size_t>(o * M + i)] * (v == variant::no_jacobian ? 1 : glint::scratch_table::bin_ds(i, M));
    double acc = 0;
    int i = 0;
    for (; i < M - 1; ++i) {
        acc += rm[static_cast<std::size_t>(o * M + i)] * (v == variant::no_jacobian ? 1 : glint::scratch_table::bin_ds(i, M)) / total;
        if (acc > u1) break;
    }
    if (v == variant::uniform_angle) return -pi / 2 + (i + u2) * pi / M;
    return std::asin(std::sin(-pi / 2 + i * pi / M) + u2 * glint::scratch_table::bin_ds(i, M));
}

}  // namespace

TEST_CASE("scratch sampling (Eq. 5): chi-square of phi_i against the pdf, on the cone, wrong variants rejected") {
    // 4 profiles x 5 views, 100,000 draws each through the kernel (double, linear filter: two rows),
    // histogrammed in 4 sub-bins of equal sin(phi) per table bin (M = 32: 128 cells, each's
    // probability exact under the pdf); family alpha 0.01 over the 20 (Sidak). Variants (drawn by the test at phi_o = 45
    // degrees on the steep quartic, 400,000 draws): bins chosen without their width ds (a pdf that
    // lacks the Jacobian), and phi uniform in the bin instead of sin(phi), against the nearest row.
    const int M = 32, n = 100000;
    const int GLINT_NEAREST = K<double>::GLINT_SCRATCH_NEAREST, GLINT_LINEAR = K<double>::GLINT_SCRATCH_LINEAR;
    const double alpha = gt::sidak_alpha(0.01, 20);
    const glint::scratch_profile profiles[] = {glint::make_v_groove(30 * deg), glint::make_quartic_groove(0.05, 256), glint::make_quartic_groove(0.5, 256),
                                               glint::make_tabulated_profile({0, 1, 2, 3, 4, 5, 6, 7, 8}, {0.1, -0.2, -0.6, -0.8, -0.7, -0.4, -0.3, 0.0, 0.1})};
    const double views[] = {0, 45, -45, 89.5, -89.5};
    const auto frame = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0));
    // Cell probabilities under the kernel's pdf: its rows (two for the linear filter) by their
    // choice probabilities, each row's bin mass rho_m ds / A split evenly over the bin's 4 cells.
    const auto cells_of = [&](const glint::scratch_table& t, double phi_o, int filter) {
        std::vector<double> p(static_cast<std::size_t>(4 * M), 0.0);
        const auto rows = K<double>::glint_scratch_rows_of(phi_o, M, filter);
        const double a0 = t.row_albedo()[static_cast<std::size_t>(rows.o0)], a1 = t.row_albedo()[static_cast<std::size_t>(rows.o1)];
        const double p1 = K<double>::glint_scratch_row_choice(rows, a0, a1);
        for (int i = 0; i < M; ++i)
            for (int k = 0; k < 4; ++k) {
                const double ds = glint::scratch_table::bin_ds(i, M) / 4;
                p[static_cast<std::size_t>(4 * i + k)] = (1 - p1) * t.rho_m()[static_cast<std::size_t>(rows.o0 * M + i)] * ds / a0 +
                                                        (p1 > 0 ? p1 * t.rho_m()[static_cast<std::size_t>(rows.o1 * M + i)] * ds / a1 : 0.0);
            }
        return p;
    };
    const auto cell_of = [&](double phi) {
        const int i = K<double>::glint_scratch_bin(phi, M);
        const double s0 = std::sin(-pi / 2 + i * pi / M);
        const int k = std::min(3, std::max(0, static_cast<int>((std::sin(phi) - s0) / glint::scratch_table::bin_ds(i, M) * 4)));
        return static_cast<std::size_t>(4 * i + k);
    };
    int profile_index = 0;
    for (const auto& p : profiles) {
        const auto t = table(p, glint::scratch_fresnel::iron(), M, 10000, true);
        const auto v = t.view<double>();
        for (double view_deg : views) {
            const double theta_o = 0.3;
            const glm::dvec3 wo = glint::from_cone<double>(frame, glm::dvec2(theta_o, view_deg * deg));
            std::vector<double> counts(static_cast<std::size_t>(4 * M), 0.0);
            double worst_cone = 0;
            for (int k = 0; k < n; ++k) {
                const auto s = v.sample(frame, wo, rnd(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(profile_index), 51),
                                        rnd(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(profile_index), 52));
                REQUIRE(s.valid);
                worst_cone = std::max(worst_cone, std::fabs(glint::to_cone<double>(frame, s.wi).x + theta_o));
                CHECK(s.wi.z >= 0);
                counts[cell_of(s.phi_i)] += 1;
            }
            const auto r = gt::chi_square(counts, cells_of(t, view_deg * deg, GLINT_LINEAR));
            MESSAGE("profile " << profile_index << ", phi_o " << view_deg << ": chi2 " << r.statistic << " / " << r.degrees_of_freedom << ", p " << r.p_value);
            CHECK_FALSE(r.rejects(alpha));
            CHECK(worst_cone < 1e-12);
        }
        ++profile_index;
    }
    const auto t = table(profiles[2], glint::scratch_fresnel::iron(), M, 10000, true);
    const int o45 = K<double>::glint_scratch_bin(45 * deg, M);
    for (variant w : {variant::no_jacobian, variant::uniform_angle}) {
        std::vector<double> counts(static_cast<std::size_t>(4 * M), 0.0);
        for (int k = 0; k < 4 * n; ++k) counts[cell_of(draw(t, o45, rnd(static_cast<std::uint32_t>(k), 9, 61), rnd(static_cast<std::uint32_t>(k), 9, 62), w))] += 1;
        const auto r = gt::chi_square(counts, cells_of(t, 45 * deg, GLINT_NEAREST));
        MESSAGE(std::string(w == variant::no_jacobian ? "without the bin width" : "phi uniform in the bin") << ": chi2 " << r.statistic << " / " << r.degrees_of_freedom << ", p " << r.p_value);
        CHECK(r.rejects(alpha));
    }
}

TEST_CASE("scratch Eq. 5: the estimator's mean is the cone integral (z-test against Gauss-Legendre)") {
    // L_i(w) = 1 + 0.5 w.v + 0.3 (w.u)^2 + 0.2 w.n^4, six views; 200,000 draws each with the
    // linear filter (two rows: the weights vary) and 200,000 with nearest; quadrature: 16-point
    // Gauss-Legendre over each bin (rho_s is constant in phi_i within a bin).
    // alpha 0.01 over the 6 views (Sidak); each test states the difference it resolves.
    const int M = 32, n = 200000;
    const double alpha = gt::sidak_alpha(0.01, 12);
    const auto t = table(glint::make_quartic_groove(0.5, 256), glint::scratch_fresnel::iron(), M, 10000, true);
    const auto frame = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0));
    const auto L = [&](const glm::dvec3& w) { return 1 + 0.5 * w.y + 0.3 * w.x * w.x + 0.2 * std::pow(w.z, 4); };
    const double views[][2] = {{0, 0}, {0.3, 20}, {-0.7, -50}, {1.2, 70}, {0.5, -85}, {-0.2, 35}};
    for (const auto filter : {glint::scratch_filter::linear, glint::scratch_filter::nearest}) {
        auto v = t.view<double>();
        v.filter = filter;
        for (const auto& vw : views) {
            const double th = vw[0], ph = vw[1] * deg;
            const glm::dvec3 wo = glint::from_cone<double>(frame, glm::dvec2(th, ph));
            const auto integrand = [&](double phi) {
                return v.rho(th, ph, phi).x * std::cos(phi) * L(glint::from_cone<double>(frame, glm::dvec2(-th, phi)));
            };
            double exact = 0;
            for (int i = 0; i < M; ++i) exact += boost::math::quadrature::gauss<double, 16>::integrate(integrand, -pi / 2 + i * pi / M, -pi / 2 + (i + 1) * pi / M);
            gt::running_moments m;
            for (int k = 0; k < n; ++k) {
                const auto s = v.sample(frame, wo, rnd(static_cast<std::uint32_t>(k), 3, 71), rnd(static_cast<std::uint32_t>(k), 3, 72));
                m.add(s.valid ? s.weight.x * L(s.wi) : 0.0);
            }
            const auto r = gt::mean_test(m, exact, alpha);
            MESSAGE(std::string(filter == glint::scratch_filter::linear ? "linear" : "nearest") << " theta_o " << th << ", phi_o " << vw[1] << ": mean " << r.mean << ", quadrature " << exact
                                                                                     << ", z " << r.z << ", resolves " << r.resolution);
            CHECK_FALSE(r.rejects(alpha));
            CHECK(r.resolves(0.02 * exact));
            if (filter == glint::scratch_filter::linear && vw[1] == 70) {
                // The variant: phi_i drawn from the nearest row only, weighted with the linear rho_s
                // (where the neighbouring row reflects and the nearest does not, nothing is drawn).
                auto near = v;
                near.filter = glint::scratch_filter::nearest;
                gt::running_moments mw;
                for (int k = 0; k < n; ++k) {
                    const auto s = near.sample(frame, wo, rnd(static_cast<std::uint32_t>(k), 4, 71), rnd(static_cast<std::uint32_t>(k), 4, 72));
                    mw.add(s.valid ? v.rho(th, ph, s.phi_i).x * std::cos(s.phi_i) / s.pdf_phi * L(s.wi) : 0.0);
                }
                const auto rw = gt::mean_test(mw, exact, alpha);
                MESSAGE("  nearest-row pdf with linear rho: mean " << rw.mean << ", z " << rw.z);
                CHECK(rw.rejects(alpha));
            }
        }
    }
}

TEST_CASE("scratch Eq. 6: the light kernel, integrated over light directions, gives Eq. 5's cone integral") {
    // A uniform environment of radiance 1 as point lights: int light_radiance(wl, E = dw_l) over the
    // kernel's band |theta_l + theta_o| <= psi (Gauss-Legendre, 24 points in theta_l; midpoint, 1440 in
    // phi_l; 16 stratified samples per light) against int rho_s cos(phi) dphi. Deterministic: the
    // difference is the kernel's O(psi^2) smoothing plus the quadrature's error, below 2e-3 here;
    // a kernel normalised as the paper's planar (phi_+ - phi_-) / pi would be off by far more.
    const int M = 64;
    const auto t = table(glint::make_quartic_groove(0.3, 256), glint::scratch_fresnel::schlick(glm::dvec3(0.6)), M, 4000, true);
    const auto v = t.view<double>();
    const auto frame = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0));
    const double psi = 1 * deg;
    for (const double th : {0.0, 0.6, 1.1}) {
        const double ph = 0.4;
        const glm::dvec3 wo = glint::from_cone<double>(frame, glm::dvec2(th, ph));
        double cone = 0;
        for (int i = 0; i < M; ++i)
            cone += boost::math::quadrature::gauss<double, 16>::integrate([&](double phi) { return v.rho(th, ph, phi).x * std::cos(phi); }, -pi / 2 + i * pi / M,
                                                                            -pi / 2 + (i + 1) * pi / M);
        const int nphi = 1440;
        const double dphi = pi / nphi;
        const double lit = boost::math::quadrature::gauss<double, 24>::integrate(
            [&](double tl) {
                double row = 0;
                for (int k = 0; k < nphi; ++k) {
                    const glm::dvec3 wl = glint::from_cone<double>(frame, glm::dvec2(tl, -pi / 2 + (k + 0.5) * dphi));
                    row += v.light_radiance(frame, wo, wl, 1.0, psi, 16, 0.5).x;
                }
                return row * dphi * std::cos(tl);
            },
            -th - psi, -th + psi);
        MESSAGE("theta_o " << th << ": integrated lights " << lit << ", cone integral " << cone << ", relative difference " << lit / cone - 1);
        CHECK(std::fabs(lit / cone - 1) < 2e-3);
    }
}

TEST_CASE("scratch Eq. 3: the 16-point footprint estimate is unbiased over its jitter and tends to the area fraction") {
    // A layer of scratches 0.06 long and 0.006 wide (l = 0.1, w = 0.01, d = 0.3). Reference: the
    // footprint's Gaussian sampled at 400,000 random points. Estimate: 16 points per jitter, 40,000
    // jitters (stratified 200 x 200). alpha 0.01 over the 3 footprints (Sidak).
    glint::scratch_distribution d;
    d.layers = 1, d.length = 0.1, d.width = 0.01, d.density = 0.3, d.spread_deg = 0, d.main_deg = 20;
    const auto L = glint::make_scratch_layers<double>(d)[0];
    const double alpha = gt::sidak_alpha(0.01, 3);
    const glm::dvec2 centre(0.31, 0.77);
    double fraction = 0;
    {
        // The area fraction: the indicator over a large square, 1e6 random points.
        gt::running_moments m;
        for (int k = 0; k < 1000000; ++k) m.add(glint::scratch_indicator<double>(L, glm::dvec2(10 * rnd(static_cast<std::uint32_t>(k), 1, 81), 10 * rnd(static_cast<std::uint32_t>(k), 1, 82))));
        fraction = m.mean;
    }
    for (const double size : {0.003, 0.02, 0.1}) {
        const glm::dvec2 a(size, 0.3 * size), b(-0.2 * size, 0.7 * size);
        gt::running_moments ref;
        for (int k = 0; k < 400000; ++k) {
            const double z1 = K<double>::glint_normal_quantile(rnd(static_cast<std::uint32_t>(k), 2, 83)), z2 = K<double>::glint_normal_quantile(rnd(static_cast<std::uint32_t>(k), 2, 84));
            ref.add(glint::scratch_indicator<double>(L, centre + z1 * a + z2 * b));
        }
        gt::running_moments est;
        for (int j = 0; j < 200; ++j)
            for (int i = 0; i < 200; ++i) est.add(glint::scratch_alpha_footprint<double>(L, centre, a, b, glm::dvec2((i + 0.5) / 200, (j + 0.5) / 200)));
        // Two independent means: z of the difference.
        const double se = std::sqrt(ref.variance() / ref.count + est.variance() / est.count);
        const double z = se > 0 ? (est.mean - ref.mean) / se : 0;
        MESSAGE("footprint " << size << ": estimate " << est.mean << ", reference " << ref.mean << " (z " << z << "), area fraction " << fraction);
        CHECK(std::erfc(std::fabs(z) / std::sqrt(2.0)) > alpha);
    }
    // At a footprint of many scratches, a single estimate (one jitter) is near the area fraction.
    gt::running_moments big;
    for (int k = 0; k < 200; ++k) big.add(glint::scratch_alpha_footprint<double>(L, glm::dvec2(rnd(static_cast<std::uint32_t>(k), 3, 85), rnd(static_cast<std::uint32_t>(k), 3, 86)) * 50.0, glm::dvec2(2, 0), glm::dvec2(0, 2), glm::dvec2(0.5)));
    MESSAGE("footprint 2: mean of single estimates " << big.mean << " (sd " << std::sqrt(big.variance()) << "), area fraction " << fraction);
    CHECK(std::fabs(big.mean - fraction) < 4 * std::sqrt(big.variance() / big.count) + 1e-3);
}

TEST_CASE("scratch material: the coverage pyramid's footprint area against the exact Gaussian footprint") {
    // One layer (l = 0.1, w = 0.01, d = 0.3, pattern of 64 cells, 8 texels per cell: the defaults);
    // 200 random pixels per footprint size, each against 20,000 points of its Gaussian (reference sd
    // about 3e-3). The pyramid replaces the Gaussian by taps of box-and-tent filters: its mean
    // |alpha - reference| measured 0.003, 0.026, 0.017, 0.019 at 0.03, 0.2, 1, 5 cells across (alpha
    // about 0.26), bounded by 0.04; the exact indicator's 16-point estimate (used below half a texel)
    // is printed for comparison.
    const auto t = table(glint::make_v_groove(30 * deg), glint::scratch_fresnel::mirror(), 16, 500, true);
    glint::scratch_distribution d;
    d.layers = 1, d.spread_deg = 0, d.main_deg = 30, d.length = 0.1, d.width = 0.01, d.density = 0.3, d.period = 64;
    const auto m = glint::scratch_material::build(t, d);
    const auto v = m.view<double>();
    const auto& L = m.layers<double>()[0];
    for (const double size : {0.0003, 0.002, 0.01, 0.05}) {
        double err = 0, err16 = 0, mean = 0;
        const int pixels = 200;
        for (int p = 0; p < pixels; ++p) {
            const glm::dvec2 x(rnd(static_cast<std::uint32_t>(p), 5, 1) * 3, rnd(static_cast<std::uint32_t>(p), 5, 2) * 3);
            const double r = rnd(static_cast<std::uint32_t>(p), 5, 3) * 6.283185307179586;
            const glm::dvec2 a = size * glm::dvec2(std::cos(r), std::sin(r)), b = 0.5 * size * glm::dvec2(-std::sin(r), std::cos(r));
            double ref = 0;
            for (int k = 0; k < 20000; ++k) {
                const double z1 = K<double>::glint_normal_quantile(rnd(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(p), 7));
                const double z2 = K<double>::glint_normal_quantile(rnd(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(p), 8));
                ref += glint::scratch_indicator<double>(L, x + z1 * a + z2 * b) / 20000;
            }
            err += std::fabs(v.alpha(0, x, a, b) - ref) / pixels;
            err16 += std::fabs(glint::scratch_alpha_footprint<double>(L, x, a, b, glm::dvec2(rnd(static_cast<std::uint32_t>(p), 5, 4), rnd(static_cast<std::uint32_t>(p), 5, 6))) - ref) / pixels;
            mean += ref / pixels;
        }
        MESSAGE("footprint sd " << size << " (" << size / d.width << " cells across): mean alpha " << mean << ", pyramid mean |error| " << err << ", 16-point " << err16);
        CHECK(err < 0.04);
    }
}

TEST_CASE("scratch material: importance sampling picks the base and each layer with its Eq. 4 weight") {
    // 4 layers of dense scratches (area sum above 1 somewhere, below elsewhere); at 50 pixels,
    // 20,000 picks each against the weights from the layers' areas: chi-square per pixel over
    // K + 1 cells, family alpha 0.01 (Sidak over 50). The variant that picks the layers uniformly
    // is rejected (where the areas, summing above 1, leave the base nothing).
    const auto t = table(glint::make_v_groove(30 * deg), glint::scratch_fresnel::mirror(), 16, 500, true);
    glint::scratch_distribution d;
    d.layers = 4, d.spread_deg = 360, d.length = 0.05, d.width = 0.01, d.density = 0.6, d.period = 32;
    const auto m = glint::scratch_material::build(t, d);
    const auto v = m.view<double>();
    const auto f = glint::make_scratch_frame<double>(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0));
    const double alpha = gt::sidak_alpha(0.01, 50);
    int over_one = 0, rejected_variant = 0;
    for (int p = 0; p < 50; ++p) {
        const glm::dvec2 x(rnd(static_cast<std::uint32_t>(p), 6, 1), rnd(static_cast<std::uint32_t>(p), 6, 2));
        const glm::dvec2 a(0.004, 0), b(0, 0.004);
        std::vector<double> al(4);
        double sum = 0;
        for (int k = 0; k < 4; ++k) al[static_cast<std::size_t>(k)] = v.alpha(k, x, a, b), sum += al[static_cast<std::size_t>(k)];
        const auto mix = glint::scratch_mix_weights<double>(sum);
        std::vector<double> probs = {mix.base_weight};
        for (double q : al) probs.push_back(q * mix.layer_scale);
        std::vector<double> counts(5, 0.0);
        for (int k = 0; k < 20000; ++k) {
            const auto s = v.sample(f, x, a, b, glm::dvec3(0.2, 0.1, 0.97), rnd(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(p), 9), 0.5, 0.5);
            counts[static_cast<std::size_t>(s.layer + 1)] += 1;
        }
        const auto r = gt::chi_square(counts, probs);
        CHECK_FALSE(r.rejects(alpha));
        if (sum > 1.05) ++over_one;
        // The variant: layers picked uniformly, whatever their areas.
        const std::vector<double> uniform = {0, 0.25, 0.25, 0.25, 0.25};
        rejected_variant += sum > 1 && gt::chi_square(counts, uniform).rejects(alpha);
    }
    MESSAGE(over_one << " of 50 pixels with area sum above 1.05; the uniform-pick variant rejected at " << rejected_variant);
    CHECK(over_one > 5);
    CHECK(2 * rejected_variant > over_one);
}
