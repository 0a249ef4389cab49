// The lobe-tree sampler (glint/lobe_tree.hpp) against its exact pdf with the directional
// chi-square kit: Gaussian lobes on flakes and leather over two and four blocks of a quilted map,
// Beckmann and GGX product lobes on pyramids, on the projected disk, and for the first also (with
// the cos theta_h Jacobian, the same code for every lobe kind) on the hemisphere; and the test's power against a variant whose pdf drops the lobes'
// Jacobian J (ZXW's product form Eq. 1 judged against linearly varying normals).
//
// Significance: family-wise 0.01 over the 5 acceptance tests of this file (Sidak). Each chi-square
// uses 5e4 samples in 16 x 16 equal-measure cells, pooled to >= 5 expected (the lobes fill 39 to
// 128 cells: 400 to 1300 draws per cell, a relative sd of 3% to 5%); the draws that fail
// (below the horizon, off the disk) have their own cell. The cells' probabilities are integrated
// adaptively to depth 3 (the kit's default is 4; each pdf costs a P-NDF evaluation, about 13 us):
// its error, below 1e-3 of a cell, is far below what the test resolves. The J-dropped variant on leather with a
// footprint of sd 0.8 texels moves each lobe by |J| sigma_h ~ 0.03 in s against lobes of sd 0.01:
// a shift of the whole distribution that 5e4 samples resolve many times over.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glint/lobe_tree.hpp>
#include <glint/patterns.hpp>
#include <glint/testing/directional.hpp>
#include <glint/testing/stats.hpp>

#include "../support/pndf_support.hpp"

namespace gt = glint::testing;

namespace {

const double alpha = gt::sidak_alpha(0.01, 5);
using forest_d = glint::lobe_forest<double>;

double uniform(std::uint32_t i, std::uint32_t stream) { return glint::open_unit_from_bits<double>(glint::pcg3d(glm::uvec3(i, stream, 0x10beu)).x); }

glint::quilted_map quilt(glint::pattern kind, double feature) {
    glint::pattern_params p;
    p.kind = kind, p.width = p.height = 64, p.slope_rms = 0.15, p.feature = feature, p.seed = 4;
    glint::quilt_params q;
    q.width = q.height = 256, q.block = 32, q.overlap = 6, q.candidates = 256;
    return glint::quilted_map::synthesize(glint::make_normal_map(p), q);
}

forest_d forest(const glint::quilted_map& h, glint::lobe_kind kind, double sigma_r, double delta_k, bool linear = true) {
    glint::lobe_params<double> l;
    l.kind = kind, l.sigma_r = sigma_r, l.linear_normal = linear;
    glint::cluster_params<double> c;
    c.delta_k = delta_k;
    return forest_d::build(h, l, c);
}

struct drawn {
    std::vector<glm::dvec3> disk, hemisphere;
    std::size_t failures = 0;
};

drawn draw(const forest_d& f, const glint::texel_footprint<double>& fp, std::uint32_t stream, std::uint32_t n = 50000) {
    drawn d;
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto s = f.sample(fp, uniform(i, stream), uniform(i, stream + 1), uniform(i, stream + 2));
        if (!s.valid) {
            ++d.failures;
            continue;
        }
        d.disk.emplace_back(s.s.x, s.s.y, 0.0);
        d.hemisphere.push_back(s.h);
    }
    return d;
}

TEST_CASE("lobe-tree sampler: chi-square against its exact pdf, Gaussian and product lobes, over several blocks") {
    struct setup {
        const char* what;
        glint::pattern kind;
        double feature;
        glint::lobe_kind lobe;
        double sigma_r;
        glm::dvec2 centre;
        double sd;
    };
    // Block (3, 2) of these maps spans texels [78, 110) x [52, 84).
    const setup setups[] = {{"Gaussian lobes, flakes, a seam", glint::pattern::flakes, 5, glint::lobe_kind::gaussian, 0.03, {80.5, 70.0}, 2.0},
                            {"Gaussian lobes, leather, a corner", glint::pattern::leather, 6, glint::lobe_kind::gaussian, 0.02, {80.5, 54.5}, 2.5},
                            {"Beckmann lobes, pyramids", glint::pattern::pyramids, 8, glint::lobe_kind::beckmann, 0.1, {81.0, 55.0}, 3.0},
                            {"GGX lobes, pyramids", glint::pattern::pyramids, 8, glint::lobe_kind::ggx, 0.05, {81.0, 55.0}, 3.0}};
    int tests = 0;
    std::uint32_t stream = 10;
    for (const auto& st : setups) {
        // delta_k = 5: K-lobes in the trees; sample() returns the exact pdf regardless.
        const auto f = forest(quilt(st.kind, st.feature), st.lobe, st.sigma_r, 5.0);
        const auto fp = glint_test::rotated_footprint(st.centre, st.sd, 0.7 * st.sd, 0.5);
        const drawn d = draw(f, fp, stream += 3);
        const double W = f.sampling_weight(fp);
        const auto disk = gt::directional_chi_square(
            gt::domain::disk, 16, 16, [&](const glm::dvec3& v) { return f.pdf(fp, glm::dvec2(v.x, v.y), W); }, d.disk, d.failures, 5.0, 3);
        MESSAGE(std::string(st.what) << ": disk p = " << disk.chi2.p_value << " (" << disk.chi2.cells << " cells), failed draws " << d.failures);
        CHECK_FALSE(disk.rejects(alpha));
        ++tests;
        if (tests == 1) {
            const auto hemi = gt::directional_chi_square(
                gt::domain::hemisphere, 16, 16, [&](const glm::dvec3& v) { return f.pdf(fp, glm::dvec2(v.x, v.y), W) * v.z; }, d.hemisphere, d.failures, 5.0, 3);
            MESSAGE(std::string(st.what) << ": hemisphere p = " << hemi.chi2.p_value);
            CHECK_FALSE(hemi.rejects(alpha));
        }
    }
    CHECK(tests == 4);
}

TEST_CASE("lobe-tree sampler: the chi-square rejects a pdf without the lobes' Jacobian") {
    const auto h = quilt(glint::pattern::leather, 6);
    const auto f = forest(h, glint::lobe_kind::gaussian, 0.01, 0.0), wrong = forest(h, glint::lobe_kind::gaussian, 0.01, 0.0, false);
    const auto fp = glint_test::rotated_footprint(glm::dvec2(80.5, 54.5), 0.8, 0.6, 0.5);
    const drawn d = draw(f, fp, 301);
    const double W = wrong.sampling_weight(fp);
    // Its lobes (sd 0.01 in s) are sharper than the cells above resolve at depth 3: 24 x 24 cells
    // at the kit's default depth here.
    const auto t = gt::directional_chi_square(
        gt::domain::disk, 24, 24, [&](const glm::dvec3& v) { return wrong.pdf(fp, glm::dvec2(v.x, v.y), W); }, d.disk, d.failures);
    MESSAGE("samples with J judged by the pdf without: p = " << t.chi2.p_value);
    CHECK(t.rejects(alpha));
}

}  // namespace
