// A stationary material from a small sample normal map (ZXW, CGF 38(7) 2019): a large map H kept
// implicit as a table of quilted blocks of the sample I (Sec. 4.1), 4D lobes fitted once on I
// (Sec. 3, 4.2, Eq. 1-5), normal-space grids of position trees whose inner nodes carry K-lobes
// from adaptive k-means (Sec. 4.3-4.4, Eq. 6-7), and the footprint P-NDF, BRDF and half-vector
// sampling over H (Sec. 5, Eq. 8-13).
//
//   glint::quilt_params q;  q.width = q.height = 2048;                    // H, texels
//   auto h = glint::quilted_map::synthesize(sample, q);                   // the block table (host, may throw)
//   glint::lobe_params<float> l;  l.sigma_r = 0.005f;                     // Gaussian lobes (glints)
//   glint::cluster_params<float> c;  c.delta_k = 0.3f;                    // Table 2's glint setting
//   auto forest = glint::lobe_forest<float>::build(h, l, c);              // host, may throw
//   float d = forest.eval(fp, glm::vec2(hx, hy));                         // per pixel: D_P(s) over the disk
//
// Synthesis (Sec. 4.1; image quilting, Efros and Freeman 2001). Blocks of T x T texels (by default
// half the sample's side, at most 128, with O = T / 16) at a stride S = T - O over H (the last column and row of blocks narrower when S does not divide H's
// size), each a copy of the sample from its source corner, chosen in raster order among
// `candidates` random source positions by the sum of squared differences of (n_x, n_y) over its
// overlaps with the blocks already placed (left, top; with `toroidal`, the first column's and
// row's too, so that H tiles without a seam), uniformly among those within (1 + tolerance) of the
// least. Each block then gets a minimum-error cut (dynamic programming, one step per row) through
// its left overlap and one through its top overlap. A texel of H belongs to its nominal block B
// (floor(u / S)) when it lies right of B's left cut and below its top cut, else to the left
// neighbour, the upper one or the upper-left one, in that order: the blocks pasted later in raster
// order win, as in EF01. The map stores per block its source corner and its two cuts (2 T bytes);
// quilted_map::materialize() makes H explicit (for tests and the baseline).
//
// Lobes. Seeds on H's lattice of spacing h = 1 / elements_per_texel, as gaussian.hpp's
// (normal_map.hpp's periodic bicubic, the same arithmetic): a seed whose interpolation stencil
// (the texels with a non-zero weight or derivative weight) reads in H the same neighbours as in I
// around the texel its owner block B maps it to, or texels of the same values bit for bit, is the
// sample's seed at that offset in B's source, bit for bit, so it is stored once for I; any other
// seed (its stencil crosses a cut between texels that differ) is a boundary lobe, fitted on H and
// stored in H coordinates (ZXW's separate boundary lobes; the band is at most the stencil's reach:
// 1 texel each side of an ownership change at h = 1, 2 at finer steps). Comparing values, not
// only positions, matters for maps with flat or piecewise-constant regions: the report's
// scratched metal has 10107 boundary lobes instead of 147524 (0.2% of H's seeds, not 3.5%).
// Kinds:
// - gaussian (glints, YHMR16 Sec. 4): a_i N2(u; u_i, sigma_h^2 I) N2(s; n_i + J_i (u - u_i), sigma_r^2 I),
//   the element of gaussian.hpp, whose footprint integral (Eq. 11's terms) is kernels/gaussian.glsl's
//   closed form;
// - beckmann, ggx (structured, Eq. 1): a_i G_pi(u) G_ni(s), J = 0. Eq. 2 prints the normaliser as
//   1 / (2 pi |Sigma|^-0.5) and Eq. 3 gives Sigma^-1 = sigma_h^2 I; both are typos for
//   N2(u; u_i, Sigma), Sigma = sigma_h^2 I. Eq. 4-5 write tan and cos of "s - s_i": read as the angle
//   theta' between s^ = (s, sqrt(1 - |s|^2)) and m^_i = (n_i, sqrt(1 - |n_i|^2)), with the
//   Beckmann D = exp(-tan^2 theta' / a^2) / (pi a^2 cos^4 theta') and GGX
//   D = a^2 / (pi cos^4 theta' (a^2 + tan^2 theta')^2), a = sigma_r, in solid angle about m^_i; as a
//   density over the disk of s the Jacobian is d omega = ds / s^_z, so G_ni(s) = D(theta') cos theta' / s^_z,
//   which integrates to 1 less the lobe's mass below the horizon. Each lobe is cut at the tan t
//   beyond which its tail holds eps = exp(-cull_s^2 / 2) of its mass (the Gaussian lobes' share:
//   3.4e-4 at cull_s = 4) and divided by 1 - eps: Beckmann t = a sqrt(ln 1/eps) (2.83 a), GGX
//   t = a sqrt((1 - eps) / eps) (54.6 a: GGX's heavy tail makes its lobes reach most of the disk, the
//   hard case; GGX's D does not fall below eps D(0) at all for a > eps^(1/4) = 0.136).
//
// Trees (Sec. 4.3). As gaussian.hpp's hierarchy: normal-space grids from a finest one (about four
// median s-radii per cell) down to 2 x 2, with cells centred on s = 0 (m + 1 cells of 2/m per side,
// so that a flat map's normals fall in one cell, not on the corner of four); each lobe at the
// finest level where its s-box overlaps at most 8 cells, listed in each; per cell, its lobes in
// Morton order of position, and a complete binary tree over runs of 8 whose nodes hold the 4D box
// (position box, s-box union). ZXW split at the median along alternating axes; the Morton order
// splits at the median of a Z curve, which needs no stored split. Boundary lobes get a second such
// set, in H coordinates and unclustered (Sec. 4.3). (Reading them by rows of H instead, with no
// trees, built 20% faster and evaluated as fast on the report's footprints, but a render's large
// footprints then tested every boundary lobe in the ellipse: 3x slower on brushed metal.)
//
// K-lobes (Sec. 4.4, Eq. 6-7). Each inner node of the sample's trees is clustered bottom-up:
// the members' normal mean and mean squared deviation (MSE) are additive moments, so C = 1 costs
// O(1) per node; where it fails, k-means with Eq. 6's distance a |P - P'|^2 + |N - N'|^2
// (a = tau / L^2, L the node's position diagonal: a node-sized shift weighs as much as the
// threshold), k-means++ seeds from a hash of the node (C's seeds are the first C of one
// sequence), trial_iters Lloyd steps per C (ECN), C = 2 .. max_clusters (MCN); C* is the least C
// whose every cluster has MSE <= tau, then Lloyd runs to convergence (max_iters; kept only if
// still accepted); a node with no such C, or whose two children are both unclustered, has none,
// and beyond C = 1 k-means runs only where both children are clustered (or leaves) and the node
// has at most max_node members (with one child unclustered it failed at 92% of scratched metal's
// nodes, for a third of k-means' time). delta_k is the paper's coefficient, an MSE in 8-bit code
// values (ZXW's preprocessing keeps 0-255 normals): tau = delta_k (2/255)^2 in s (delta_k 0.3:
// RMS 0.0043; 5: 0.018; 30: 0.043). A K-lobe is moment-matched to its members (Eq. 7, N the
// member count): weight N a, position mean and Sigma_pj = sigma_h^2 I + Cov(u_i); Gaussian
// normal lobe N(s; mean n_i, sigma_r^2 I + Cov(n_i) + sigma_h^2 mean(J_i J_i^T)) (the members'
// marginals as the footprint grows), product lobes the same D with a^2 = sigma_r^2 + tr Cov(n_i)
// about the mean normal. Its footprint term is N a N2(mu; u_bar, Sigma_P + Sigma_pj) G_nj(s),
// with the members' footprint taper taken at u_bar.
//
// Query (Sec. 5.3, Alg. S1-S2). The footprint's culling box is cut by every block it overlaps
// (and H's periodic images): the part inside B's square is moved into I and its trees walked; a
// lobe found there counts only if its seed in H is B's own and not a boundary seed (seeds in B's
// core, whose stencils reach only texels no other block can own, skip the test), then its term is
// taken at its H position; the boundary set is walked in H. So every seed of H counts once, and
// with K-lobes off eval equals the sum over all seeds of the materialised map, gaussian_pndf's eval
// on materialize(), up to rounding (tests/unit/test_lobe_tree.cpp). With K-lobes on (ZXW's rule,
// Alg. S2), a clustered node whose position extent is at most cluster_extent times the
// footprint's smaller sd, and whose texels lie in B's interior runs (per block and row, the run of
// texels whose seeds are B's own and not boundary seeds), adds its K-lobes and stops, unless the
// footprint's taper cuts one of them at its centroid (the node straddles the footprint's edge):
// then it descends. A K-lobe whose normal lobe misses s stands in with 0, as in Eq. 13: its
// members' normals lie within the MSE tau of its mean, and its lobe is as wide as their marginals.
// Two exact prunings keep the walks short: B's box is cut to the bounding box of the texels B owns
// (the cuts rarely give B texels past its stride), and a node is skipped where an axis of the
// footprint's culling ellipse separates it (as gaussian_pndf's trees do). Footprints whose culling
// box reaches more than 24 blocks from its centre on an axis are shrunk to that (stats.clamped).
//
// Paths (lobe_path). The trees are walked once per block the footprint overlaps and per grid
// level, which small footprints cannot amortise; their seeds are few, so eval then sums the box's
// lattice instead, seed by seed through the block table (as gaussian_pndf's direct loop), and
// takes the trees once K-lobes can stand in (the footprint's smaller sd at least 8 texels over
// cluster_extent). K-lobe nodes that straddle a block's edge cannot stand in: larger blocks leave
// more of each block to K-lobes (docs/lobe_tree.md, by block size and footprint size).
//
// Sampling: a seed of H with probability w_i / W (w_i its tapered footprint weight, two passes
// over the box's lattice), then s from that seed's lobe, so its density is exactly the K-lobe-free
// eval over W; pdf() returns that (exact_pdf) or eval with K-lobes over W.
//
// Domains. sigma_r in [1e-4, 1]; footprints as gaussian.hpp's. Per-pixel calls never allocate or
// throw, and return 0 for |s| >= 1, non-finite s, or h below the horizon.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

#include "glint/core/error.hpp"
#include "glint/core/hash.hpp"
#include "glint/gaussian.hpp"
#include "glint/microfacet.hpp"
#include "glint/normal_map.hpp"

// The per-lobe loops inline the kernels' whole call chain (GCC and Clang): the frame passed by
// value to an out-of-line kernel cost a 100-byte copy per lobe (17% of eval's time in a profile).
#if defined(__GNUC__)
#define GLINT_FLATTEN __attribute__((flatten))
#else
#define GLINT_FLATTEN
#endif

namespace glint {

struct quilt_params {
    int width = 1024, height = 1024;  // H, texels
    // T and O, 1 <= O <= T / 4; 0: automatic, T half the sample's smaller side (at most 128) and
    // O = T / 16 (at least 2). ZXW's code uses 64 and 8; blocks of 128 with overlap 8 leave 81% of
    // each block's seeds to its core, where K-lobes can stand in, against 62% (docs/lobe_tree.md).
    int block = 0, overlap = 0;
    double tolerance = 0.1;           // EF01's: pick among candidates within (1 + tolerance) of the least error
    int candidates = 1024;            // random source positions scored per block (0: every position)
    bool toroidal = true;             // H tiles without a seam
    std::uint32_t seed = 1;
};

// H as its block table over the sample I.
class quilted_map {
public:
    static quilted_map synthesize(const normal_map& sample, const quilt_params& q_in) {
        const std::string what = "glint::quilted_map::synthesize: ";
        if (sample.width() <= 0 || sample.height() <= 0) throw error(what + "the sample normal map is empty");
        if (q_in.block < 0 || q_in.overlap < 0)
            throw error(what + "block = " + std::to_string(q_in.block) + ", overlap = " + std::to_string(q_in.overlap) + " (0: automatic, else positive)");
        quilt_params q = q_in;
        if (q.block == 0) q.block = std::min(128, std::min(sample.width(), sample.height()) / 2);
        if (q.overlap == 0) q.overlap = std::max(2, q.block / 16);
        if (sample.width() >= 65535 || sample.height() >= 65535)
            throw error(what + "the sample (" + std::to_string(sample.width()) + " x " + std::to_string(sample.height()) + ") is 65535 or more texels on a side");
        if (q.block < 8) throw error(what + "block = " + std::to_string(q.block) + " is below 8 texels");
        if (q.block > sample.width() || q.block > sample.height())
            throw error(what + "block = " + std::to_string(q.block) + " exceeds the sample (" + std::to_string(sample.width()) + " x " +
                        std::to_string(sample.height()) + ")");
        if (q.overlap < 1 || 4 * q.overlap > q.block)
            throw error(what + "overlap = " + std::to_string(q.overlap) + " is outside [1, block / 4] (block " + std::to_string(q.block) + ")");
        if (q.width < 2 * q.block || q.height < 2 * q.block)
            throw error(what + "the output " + std::to_string(q.width) + " x " + std::to_string(q.height) + " is smaller than two blocks per side");
        if (q.width > 65536 || q.height > 65536) throw error(what + "the output " + std::to_string(q.width) + " x " + std::to_string(q.height) + " exceeds 65536 per side");
        if (!(q.tolerance >= 0 && q.tolerance <= 10)) throw error(what + "tolerance = " + std::to_string(q.tolerance) + " is outside [0, 10]");
        if (q.candidates < 0) throw error(what + "candidates = " + std::to_string(q.candidates) + " is negative");
        quilted_map m;
        m.sample_ = sample;
        m.w_ = q.width, m.h_ = q.height, m.t_ = q.block, m.o_ = q.overlap, m.s_ = q.block - q.overlap;
        m.nbx_ = (q.width + m.s_ - 1) / m.s_, m.nby_ = (q.height + m.s_ - 1) / m.s_;
        m.toroidal_ = q.toroidal;
        const std::size_t blocks = static_cast<std::size_t>(m.nbx_) * static_cast<std::size_t>(m.nby_);
        m.src_.assign(blocks, glm::ivec2(0));
        m.origin_.resize(blocks);
        for (std::size_t b = 0; b < blocks; ++b) m.origin_[b] = glm::ivec2(static_cast<int>(b % static_cast<std::size_t>(m.nbx_)) * m.s_, static_cast<int>(b / static_cast<std::size_t>(m.nbx_)) * m.s_);
        m.cut_left_.assign(blocks * static_cast<std::size_t>(m.t_), 0);
        m.cut_top_.assign(blocks * static_cast<std::size_t>(m.t_), 0);
        m.place_blocks(q);
        m.cut_blocks();
        return m;
    }

    int width() const noexcept { return w_; }
    int height() const noexcept { return h_; }
    int block() const noexcept { return t_; }
    int overlap() const noexcept { return o_; }
    int stride() const noexcept { return s_; }
    int blocks_x() const noexcept { return nbx_; }
    int blocks_y() const noexcept { return nby_; }
    bool toroidal() const noexcept { return toroidal_; }
    const normal_map& sample() const noexcept { return sample_; }
    // Block b = bx + blocks_x() by: its corner in H and its source corner in I.
    glm::ivec2 origin(int b) const noexcept { return origin_[static_cast<std::size_t>(b)]; }
    glm::ivec2 source(int b) const noexcept { return src_[static_cast<std::size_t>(b)]; }
    // The texels of H that block bx (column) or by (row) is the nominal block of: S, or fewer for the last.
    int stride_x(int bx) const noexcept { return bx == nbx_ - 1 ? w_ - (nbx_ - 1) * s_ : s_; }
    int stride_y(int by) const noexcept { return by == nby_ - 1 ? h_ - (nby_ - 1) * s_ : s_; }
    // The left (top) cut of block b at local row (column) i: texels left of (above) it are its neighbour's.
    int cut_left(int b, int i) const noexcept { return cut_left_[static_cast<std::size_t>(b) * static_cast<std::size_t>(t_) + static_cast<std::size_t>(i)]; }
    int cut_top(int b, int i) const noexcept { return cut_top_[static_cast<std::size_t>(b) * static_cast<std::size_t>(t_) + static_cast<std::size_t>(i)]; }

    // The block owning texel (x, y) of H (wrapped), and the texel's offset in that block.
    int owner(long x, long y, glm::ivec2* local = nullptr) const noexcept {
        x = wrap(x, w_), y = wrap(y, h_);
        const int bx = std::min(static_cast<int>(x / s_), nbx_ - 1), by = std::min(static_cast<int>(y / s_), nby_ - 1);
        return owner_in(bx, by, static_cast<int>(x) - bx * s_, static_cast<int>(y) - by * s_, local);
    }
    // The same for the texel at offset (lx, ly) from nominal block (bx, by)'s corner, 0 <= lx < stride_x(bx).
    int owner_in(int bx, int by, int lx, int ly, glm::ivec2* local = nullptr) const noexcept {
        const int b = bx + nbx_ * by;
        const int lb = (bx == 0 ? nbx_ - 1 : bx - 1) + nbx_ * by, ub = bx + nbx_ * (by == 0 ? nby_ - 1 : by - 1);
        const int ulb = (bx == 0 ? nbx_ - 1 : bx - 1) + nbx_ * (by == 0 ? nby_ - 1 : by - 1);
        const int sl = stride_x(bx == 0 ? nbx_ - 1 : bx - 1), su = stride_y(by == 0 ? nby_ - 1 : by - 1);
        int r = ulb, rx = lx + sl, ry = ly + su;
        if (lx >= cut_left(b, ly) && ly >= cut_top(b, lx)) r = b, rx = lx, ry = ly;
        else if (lx < o_ && ly >= cut_top(lb, lx + sl)) r = lb, rx = lx + sl, ry = ly;
        else if (ly < o_ && lx >= cut_left(ub, ly + su)) r = ub, rx = lx, ry = ly + su;
        if (local) *local = glm::ivec2(rx, ry);
        return r;
    }

    // Whether block b = (bx, by) owns the texel at offset (lx, ly) of its square, 0 <= lx, ly < T:
    // owner_in() at the nominal block of that texel (b itself, or its right, lower or lower-right
    // neighbour), without divisions.
    bool owns(int bx, int by, int lx, int ly) const noexcept {
        const int sx = stride_x(bx), sy = stride_y(by);
        int nx = bx, ny = by;
        if (lx >= sx) lx -= sx, nx = bx + 1 == nbx_ ? 0 : bx + 1;
        if (ly >= sy) ly -= sy, ny = by + 1 == nby_ ? 0 : by + 1;
        return owner_in(nx, ny, lx, ly) == bx + nbx_ * by;
    }

    // H's texel (x, y), wrapped.
    const glm::vec3& texel(long x, long y) const noexcept {
        glm::ivec2 l;
        const int b = owner(x, y, &l);
        const glm::ivec2 p = src_[static_cast<std::size_t>(b)] + l;
        return sample_.normals()[static_cast<std::size_t>(p.x) + static_cast<std::size_t>(sample_.width()) * static_cast<std::size_t>(p.y)];
    }

    // H's periodic bicubic interpolant at u (normal_map::bicubic's arithmetic).
    template <class real>
    normal_sample<real> bicubic(const glm::vec<2, real, glm::defaultp>& u) const {
        return normal_map::interpolate_with<real, 4>([this](long x, long y) -> const glm::vec3& { return texel(x, y); }, u);
    }

    // H made explicit (periodic).
    normal_map materialize() const {
        std::vector<glm::vec3> n(static_cast<std::size_t>(w_) * static_cast<std::size_t>(h_));
        for (long y = 0; y < h_; ++y)
            for (long x = 0; x < w_; ++x) n[static_cast<std::size_t>(x + w_ * y)] = texel(x, y);
        normal_map_options o;
        o.source = "glint::quilted_map::materialize";
        return normal_map(w_, h_, std::move(n), o);
    }

    // The block table: source corners and cuts (the sample is the caller's and counted apart).
    std::size_t table_bytes() const noexcept { return src_.size() * sizeof(glm::ivec2) + cut_left_.size() + cut_top_.size(); }

    // i wrapped into [0, n) (periodic maps; also lobe_forest's).
    static long wrap(long i, long n) noexcept {
        const long r = i % n;
        return r < 0 ? r + n : r;
    }

private:
    // One overlap to score: the new block's local rectangle [x0, x1) x [y0, y1) against block
    // `other` at local offset d (other's local = mine + d).
    struct overlap_rect {
        int other, x0, x1, y0, y1;
        glm::ivec2 d;
    };

    glm::vec2 sample_xy(int x, int y) const {
        const glm::vec3& n = sample_.normals()[static_cast<std::size_t>(x) + static_cast<std::size_t>(sample_.width()) * static_cast<std::size_t>(y)];
        return glm::vec2(n.x, n.y);
    }

    void place_blocks(const quilt_params& q) {
        const int px = sample_.width() - t_ + 1, py = sample_.height() - t_ + 1;
        const long positions = static_cast<long>(px) * py;
        const long count = q.candidates == 0 ? positions : std::min<long>(q.candidates, positions);
        std::vector<glm::ivec2> cand(static_cast<std::size_t>(count));
        std::vector<double> err(static_cast<std::size_t>(count));
        for (int by = 0; by < nby_; ++by)
            for (int bx = 0; bx < nbx_; ++bx) {
                const int b = bx + nbx_ * by;
                overlap_rect rects[4];
                int n = 0;
                if (bx > 0) rects[n++] = {b - 1, 0, o_, 0, t_, glm::ivec2(stride_x(bx - 1), 0)};
                if (by > 0) rects[n++] = {b - nbx_, 0, t_, 0, o_, glm::ivec2(0, stride_y(by - 1))};
                if (toroidal_ && bx == nbx_ - 1) rects[n++] = {nbx_ * by, stride_x(bx), stride_x(bx) + o_, 0, t_, glm::ivec2(-stride_x(bx), 0)};
                if (toroidal_ && by == nby_ - 1) rects[n++] = {bx, 0, t_, stride_y(by), stride_y(by) + o_, glm::ivec2(0, -stride_y(by))};
                const auto pick = [&](std::uint32_t i, std::uint32_t salt) {
                    return pcg3d(glm::uvec3(static_cast<std::uint32_t>(b), i, q.seed * 0x9e3779b9u + salt));
                };
                for (long c = 0; c < count; ++c) {
                    long k = c;
                    if (count < positions) k = static_cast<long>(pick(static_cast<std::uint32_t>(c), 1).x % static_cast<std::uint32_t>(positions));
                    cand[static_cast<std::size_t>(c)] = glm::ivec2(static_cast<int>(k % px), static_cast<int>(k / px));
                }
                if (n == 0) {
                    src_[static_cast<std::size_t>(b)] = cand[pick(0, 2).x % static_cast<std::uint32_t>(count)];
                    continue;
                }
                // Squared differences of (n_x, n_y) over the overlaps; a candidate stops once past
                // (1 + tolerance) times the best so far (it cannot be picked).
                double best = std::numeric_limits<double>::infinity();
                for (long c = 0; c < count; ++c) {
                    const glm::ivec2 p = cand[static_cast<std::size_t>(c)];
                    const double limit = best * (1 + q.tolerance);
                    double e = 0;
                    for (int r = 0; r < n && e <= limit; ++r) {
                        const overlap_rect& o = rects[r];
                        const glm::ivec2 op = src_[static_cast<std::size_t>(o.other)] + o.d;
                        for (int y = o.y0; y < o.y1 && e <= limit; ++y)
                            for (int x = o.x0; x < o.x1; ++x) {
                                const glm::vec2 a = sample_xy(p.x + x, p.y + y), d = a - sample_xy(op.x + x, op.y + y);
                                e += static_cast<double>(d.x) * static_cast<double>(d.x) + static_cast<double>(d.y) * static_cast<double>(d.y);
                            }
                    }
                    err[static_cast<std::size_t>(c)] = e;
                    best = std::min(best, e);
                }
                long within = 0;
                for (long c = 0; c < count; ++c) within += err[static_cast<std::size_t>(c)] <= best * (1 + q.tolerance) ? 1 : 0;
                long chosen = static_cast<long>(pick(0, 3).x % static_cast<std::uint32_t>(within));
                for (long c = 0; c < count; ++c)
                    if (err[static_cast<std::size_t>(c)] <= best * (1 + q.tolerance) && chosen-- == 0) {
                        src_[static_cast<std::size_t>(b)] = cand[static_cast<std::size_t>(c)];
                        break;
                    }
            }
    }

    // The minimum-error path through a T x O overlap (one column per row, moving at most one
    // column between rows): err(i, c) for row i and column c; returns the column per row.
    template <class err_t>
    void min_cut(const err_t& err, std::uint8_t* cut) const {
        std::vector<double> cost(static_cast<std::size_t>(t_ * o_));
        for (int i = 0; i < t_; ++i)
            for (int c = 0; c < o_; ++c) {
                double prev = 0;
                if (i > 0) {
                    prev = cost[static_cast<std::size_t>((i - 1) * o_ + c)];
                    if (c > 0) prev = std::min(prev, cost[static_cast<std::size_t>((i - 1) * o_ + c - 1)]);
                    if (c + 1 < o_) prev = std::min(prev, cost[static_cast<std::size_t>((i - 1) * o_ + c + 1)]);
                }
                cost[static_cast<std::size_t>(i * o_ + c)] = err(i, c) + prev;
            }
        int c = 0;
        for (int k = 1; k < o_; ++k)
            if (cost[static_cast<std::size_t>((t_ - 1) * o_ + k)] < cost[static_cast<std::size_t>((t_ - 1) * o_ + c)]) c = k;
        for (int i = t_ - 1; i >= 0; --i) {
            cut[i] = static_cast<std::uint8_t>(c);
            if (i == 0) break;
            int next = c;
            for (int k = std::max(0, c - 1); k <= std::min(o_ - 1, c + 1); ++k)
                if (cost[static_cast<std::size_t>((i - 1) * o_ + k)] < cost[static_cast<std::size_t>((i - 1) * o_ + next)]) next = k;
            c = next;
        }
    }

    void cut_blocks() {
        for (int by = 0; by < nby_; ++by)
            for (int bx = 0; bx < nbx_; ++bx) {
                const int b = bx + nbx_ * by;
                const glm::ivec2 p = src_[static_cast<std::size_t>(b)];
                if (bx > 0 || toroidal_) {
                    const int l = (bx == 0 ? nbx_ - 1 : bx - 1) + nbx_ * by, sl = stride_x(bx == 0 ? nbx_ - 1 : bx - 1);
                    const glm::ivec2 q = src_[static_cast<std::size_t>(l)];
                    min_cut([&](int i, int c) { const glm::vec2 d = sample_xy(p.x + c, p.y + i) - sample_xy(q.x + c + sl, q.y + i); return static_cast<double>(glm::dot(d, d)); },
                            &cut_left_[static_cast<std::size_t>(b) * static_cast<std::size_t>(t_)]);
                }
                if (by > 0 || toroidal_) {
                    const int u = bx + nbx_ * (by == 0 ? nby_ - 1 : by - 1), su = stride_y(by == 0 ? nby_ - 1 : by - 1);
                    const glm::ivec2 q = src_[static_cast<std::size_t>(u)];
                    min_cut([&](int i, int c) { const glm::vec2 d = sample_xy(p.x + i, p.y + c) - sample_xy(q.x + i, q.y + c + su); return static_cast<double>(glm::dot(d, d)); },
                            &cut_top_[static_cast<std::size_t>(b) * static_cast<std::size_t>(t_)]);
                }
            }
    }

    normal_map sample_;
    int w_ = 0, h_ = 0, t_ = 0, o_ = 0, s_ = 0, nbx_ = 0, nby_ = 0;
    bool toroidal_ = true;
    std::vector<glm::ivec2> src_, origin_;
    std::vector<std::uint8_t> cut_left_, cut_top_;
};

enum class lobe_kind { gaussian, beckmann, ggx };

template <class real>
struct lobe_params {
    lobe_kind kind = lobe_kind::gaussian;
    real sigma_r = real(0.005);  // intrinsic roughness (gaussian: sd in s; beckmann, ggx: their a), [1e-4, 1]
    int elements_per_texel = 1;  // seeds per texel side: 1, 2 or 4 (h = 1 / that; ZXW: 2; 1 as gaussian_params)
    real cull_u = real(3.5);     // footprint culling radius, as gaussian_params
    real cull_s = real(4);       // lobe culling radius (gaussian: Mahalanobis; product: D < exp(-cull_s^2 / 2) D(0))
    bool linear_normal = true;   // gaussian: the normal varies linearly over the lobe (J_i); false: J = 0 (Eq. 1's product form)
};

template <class real>
struct cluster_params {
    real delta_k = real(0.4);  // ZXW's coefficient (header comment); 0: no K-lobes; <= 1e4
    int max_clusters = 4;      // MCN, 1 to 8
    int trial_iters = 5;       // ECN, 1 to 20
    int max_iters = 50;        // Lloyd steps for C*, >= trial_iters
    int max_node = 4096;       // nodes with more members get no k-means beyond C = 1
    std::uint32_t seed = 1;
};

// How eval finds the seeds: the trees (with K-lobes), the lattice of the footprint's box (every
// seed, as gaussian_pndf's direct loop), or whichever the footprint suits (automatic: the lattice
// while the footprint is too small for K-lobes to stand in, sd * cluster_extent < 8 texels, and
// its box holds fewer seeds than the trees would visit).
enum class lobe_path { automatic, trees, lattice };

template <class real>
struct lobe_query_options {
    bool use_klobes = true;
    real cluster_extent = real(1);  // lambda: a node's K-lobes stand in only if its extent <= lambda min sd(footprint)
    lobe_path path = lobe_path::automatic;
};

struct lobe_query_stats {
    std::uint32_t nodes = 0, lobes = 0, klobes = 0, blocks = 0;
    bool clamped = false;
};

namespace detail {

// The two cheap tests that a lobe forest's walk makes on each entry of a position-tree leaf before
// its term: s outside the entry's s-box (bound: axis (x, y), half-extents (z, w), about the lobe's
// mean normal us.zw), or the entry's position u = us.xy + u_offset outside the footprint's culling
// ellipse (its squared Mahalanobis radius, glint_pndf_offset and glint_pndf_mahalanobis_u, above
// cull2). An entry is 12 reals: the element's us and jac, then its bound.
template <class real>
bool lobe_outside_sbox(const glm::vec<4, real, glm::defaultp>& b, real mean_x, real mean_y, const vec2_t<real>& s) {
    const real dx = s.x - mean_x, dy = s.y - mean_y;
    return std::fabs(dx * b.x + dy * b.y) > b.z || std::fabs(dy * b.x - dx * b.y) > b.w;
}

// The squared Mahalanobis radius of position u in the footprint (the kernel's own arithmetic, as
// glint_pndf_element's); outside the culling ellipse where it exceeds cull2, and the term, which
// takes it (glint_pndf_weight_at, glint_pndf_element_at), is 0 there.
template <class real>
real lobe_footprint_radius(const vec2_t<real>& u, const typename glsl::kernels<real>::glint_pndf_frame& f) {
    using k = glsl::kernels<real>;
    return k::glint_pndf_mahalanobis_u(k::glint_pndf_offset(u, f), f);
}

// Bit i set where entry i of a leaf's `count` (at most 8) passes both tests; then m[i] is its
// squared Mahalanobis radius, for its term (glint_pndf_weight_at).
template <class real>
unsigned lobe_leaf_candidates_scalar(const real* entries, unsigned count, const vec2_t<real>& s, const vec2_t<real>& u_offset,
                                     const typename glsl::kernels<real>::glint_pndf_frame& f, real cull2, real m[8]) {
    unsigned keep = 0;
    for (unsigned i = 0; i < count; ++i) {
        const real* x = entries + 12 * i;
        const glm::vec<4, real, glm::defaultp> bound(x[8], x[9], x[10], x[11]);
        if (lobe_outside_sbox(bound, x[2], x[3], s)) continue;
        const real mi = lobe_footprint_radius(vec2_t<real>(x[0], x[1]) + u_offset, f);
        if (mi > cull2) continue;
        m[i] = mi;
        keep |= 1u << i;
    }
    return keep;
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
// The same in AVX2 registers, a leaf's eight entries a lane each (float; lanes past count repeat
// entry 0 and are left out): the same float operations in the same order as the scalar tests,
// without FMA (target avx2 alone), so the same bits, the radii m_out included (every lane's; the
// caller reads the kept ones; tests/unit/test_lobe_tree.cpp compares them).
// Entry by entry the tests and the loop around them took about 40 instructions an entry; in lanes
// a query takes 11% fewer instructions (glint_frame_loop lobe-tree metal 1 under callgrind: 429M
// to 381M a pass; pyramids 211M to 186M; the same sums; README, "Lobe trees").
__attribute__((noinline, target("avx2"))) inline unsigned lobe_leaf_candidates_x8(const float* entries, unsigned count, float sx, float sy, float ox,
                                                                                  float oy, const glsl::kernels<float>::glint_pndf_frame& f, float cull2,
                                                                                  float m_out[8]) {
    typedef float f32x4 __attribute__((vector_size(16)));
    typedef float f32x8 __attribute__((vector_size(32)));
    typedef int i32x8 __attribute__((vector_size(32)));
    // Rows: entry i's us (floats 0..3) and bound (8..11), transposed into one vector per field
    // (lanes 0..3 entries 0..3, lanes 4..7 entries 4..7).
    f32x8 us[4], bd[4];
    for (int part = 0; part < 2; ++part) {
        f32x8 a[4];
        for (int i = 0; i < 4; ++i) {
            f32x4 lo, hi;
            const unsigned i_lo = static_cast<unsigned>(i) < count ? static_cast<unsigned>(i) : 0u;
            const unsigned i_hi = static_cast<unsigned>(i + 4) < count ? static_cast<unsigned>(i + 4) : 0u;
            std::memcpy(&lo, entries + 12 * i_lo + 8 * part, sizeof(lo));
            std::memcpy(&hi, entries + 12 * i_hi + 8 * part, sizeof(hi));
            a[i] = __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
        }
        const f32x8 t0 = __builtin_shufflevector(a[0], a[1], 0, 8, 1, 9, 4, 12, 5, 13), t1 = __builtin_shufflevector(a[0], a[1], 2, 10, 3, 11, 6, 14, 7, 15);
        const f32x8 t2 = __builtin_shufflevector(a[2], a[3], 0, 8, 1, 9, 4, 12, 5, 13), t3 = __builtin_shufflevector(a[2], a[3], 2, 10, 3, 11, 6, 14, 7, 15);
        f32x8* out = part == 0 ? us : bd;
        out[0] = __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
        out[1] = __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
        out[2] = __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
        out[3] = __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
    }
    // lobe_outside_sbox (fabs as the sign bit cleared)
    const i32x8 magnitude = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
    const f32x8 dx = sx - us[2], dy = sy - us[3];
    const f32x8 along = reinterpret_cast<f32x8>(reinterpret_cast<i32x8>(dx * bd[0] + dy * bd[1]) & magnitude);
    const f32x8 across = reinterpret_cast<f32x8>(reinterpret_cast<i32x8>(dy * bd[0] - dx * bd[1]) & magnitude);
    const i32x8 out_s = (along > bd[2]) | (across > bd[3]);
    // lobe_footprint_radius: u = us.xy + u_offset, e = glint_pndf_offset(u, f), m = glint_pndf_mahalanobis_u(e, f)
    const f32x8 ux = us[0] + ox, uy = us[1] + oy;
    const f32x8 mx = f.mean.x - ux, my = f.mean.y - uy;
    const f32x8 ex = f.axis.x * mx + f.axis.y * my, ey = -f.axis.y * mx + f.axis.x * my;
    const f32x8 m = ex * ex / f.kappa.x + ey * ey / f.kappa.y;
    const i32x8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const i32x8 keep = ~(out_s | (m > cull2)) & (lane < static_cast<int>(count));
    std::memcpy(m_out, &m, sizeof(m));
    return static_cast<unsigned>(__builtin_ia32_movmskps256(reinterpret_cast<f32x8>(keep)));
}
#endif

// lobe_leaf_candidates_scalar, in AVX2 where the CPU has it (float).
template <class real>
unsigned lobe_leaf_candidates(const real* entries, unsigned count, const vec2_t<real>& s, const vec2_t<real>& u_offset,
                              const typename glsl::kernels<real>::glint_pndf_frame& f, real cull2, real m[8]) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GLINT_NO_AVX2)
    if constexpr (std::is_same<real, float>::value)
        if (glsl::kernels<float>::glint_cpu_avx2()) return lobe_leaf_candidates_x8(entries, count, s.x, s.y, u_offset.x, u_offset.y, f, cull2, m);
#endif
    return lobe_leaf_candidates_scalar(entries, count, s, u_offset, f, cull2, m);
}

}  // namespace detail

template <class real>
class lobe_forest {
public:
    using kernels = detail::glsl::kernels<real>;
    using element = typename kernels::glint_gaussian_element;
    using frame = typename kernels::glint_pndf_frame;
    using params = typename kernels::glint_pndf_params;
    using vec2 = vec2_t<real>;
    using vec4 = glm::vec<4, real, glm::defaultp>;

    struct build_report {
        std::size_t sample_lobes = 0, boundary_lobes = 0, listed = 0, nodes = 0, clustered_nodes = 0, klobes = 0;
        double seconds = 0;
    };

    static lobe_forest build(const quilted_map& map, const lobe_params<real>& lp, const cluster_params<real>& cp) {
        const std::string what = "glint::lobe_forest::build: ";
        if (map.width() <= 0) throw error(what + "the quilted map is empty");
        if (lp.elements_per_texel != 1 && lp.elements_per_texel != 2 && lp.elements_per_texel != 4)
            throw error(what + "elements_per_texel = " + std::to_string(lp.elements_per_texel) + " (1, 2 or 4)");
        if (!(lp.sigma_r >= real(1e-4) && lp.sigma_r <= real(1))) throw error(what + "sigma_r = " + std::to_string(lp.sigma_r) + " is outside [1e-4, 1]");
        if (!(lp.cull_u >= 2 && lp.cull_u <= 8)) throw error(what + "cull_u = " + std::to_string(lp.cull_u) + " is outside [2, 8]");
        if (!(lp.cull_s >= 1 && lp.cull_s <= 8)) throw error(what + "cull_s = " + std::to_string(lp.cull_s) + " is outside [1, 8]");
        if (!(cp.delta_k >= 0 && cp.delta_k <= real(1e4))) throw error(what + "delta_k = " + std::to_string(cp.delta_k) + " is outside [0, 1e4]");
        if (cp.max_clusters < 1 || cp.max_clusters > 8) throw error(what + "max_clusters = " + std::to_string(cp.max_clusters) + " is outside [1, 8]");
        if (cp.trial_iters < 1 || cp.trial_iters > 20) throw error(what + "trial_iters = " + std::to_string(cp.trial_iters) + " is outside [1, 20]");
        if (cp.max_iters < cp.trial_iters) throw error(what + "max_iters = " + std::to_string(cp.max_iters) + " is below trial_iters");
        if (cp.max_node < 2) throw error(what + "max_node = " + std::to_string(cp.max_node) + " is below 2");
        const long ept = lp.elements_per_texel;
        if (static_cast<long>(map.width()) * ept * static_cast<long>(map.height()) * ept > (1L << 28))
            throw error(what + "more than 2^28 seeds on H");
        const auto start = std::chrono::steady_clock::now();
        lobe_forest f;
        f.map_ = map;
        f.lp_ = lp;
        const real h = real(1) / real(lp.elements_per_texel);
        f.k_.sigma_h = h / std::sqrt(real(8) * std::log(real(2)));
        f.k_.sigma_r = lp.sigma_r;
        f.k_.spacing = h;
        f.k_.area = h * h;
        f.k_.cull_u = lp.cull_u;
        f.k_.cull_s = lp.kind == lobe_kind::gaussian ? lp.cull_s : real(0);  // product lobes cut in their own term
        f.k_.width = static_cast<int>(map.width() * ept);
        f.k_.height = static_cast<int>(map.height() * ept);
        f.k_.periodic = 1;
        f.k_.max_side = 1 << 28;
        f.tau_ = cp.delta_k * real(4.0 / (255.0 * 255.0));
        f.ept_ = lp.elements_per_texel;
        // Product lobes: the cut's tan t, where the lobe's tail holds eps = exp(-cull_s^2 / 2) of its
        // mass (as the Gaussian lobes' cut), so the kept mass is 1 - eps for both (header comment).
        const double a = static_cast<double>(lp.sigma_r), cs = static_cast<double>(lp.cull_s), eps = std::exp(-0.5 * cs * cs);
        if (lp.kind == lobe_kind::beckmann) f.tan_cut_ = static_cast<real>(a * std::sqrt(-std::log(eps)));  // 1 - exp(-t^2 / a^2) = 1 - eps
        if (lp.kind == lobe_kind::ggx) f.tan_cut_ = static_cast<real>(a * std::sqrt((1 - eps) / eps));    // t^2 / (a^2 + t^2) = 1 - eps
        f.kept_ = static_cast<real>(1 - eps);
        f.seed_shape_ = f.shape_of(lp.sigma_r);
        f.fit_sample_lobes();
        f.find_boundary();
        f.find_interiors();
        f.build_set(f.sample_set_, f.sample_lobes_);
        f.build_set(f.boundary_set_, f.boundary_lobes_);
        if (f.tau_ > 0) f.cluster(cp);
        f.scratch_centres_ = {}, f.scratch_ = {}, f.scratch_assign_ = {};  // k-means' work space, build only
        f.report_.sample_lobes = f.sample_lobes_.size();
        f.report_.boundary_lobes = f.boundary_lobes_.size();
        f.report_.listed = f.sample_set_.listed.size() + f.boundary_set_.listed.size();
        f.report_.nodes = f.sample_set_.nodes.size() + f.boundary_set_.nodes.size();
        f.report_.klobes = f.klobes_.size();
        f.report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return f;
    }

    // D_P(s) over H (Eq. 11, or Eq. 13 where K-lobes stand in).
    real eval(const texel_footprint<real>& fp, const vec2& s, const lobe_query_options<real>& o = {}, lobe_query_stats* stats = nullptr) const noexcept {
        if (!(s.x * s.x + s.y * s.y < real(1))) return real(0);
        lobe_query_stats local;
        lobe_query_stats& st = stats ? *stats : local;
        const frame f = prepare(fp, st);
        if (use_lattice(f, s, o)) return sum_lattice(f, s, st);
        return sum_sample(f, s, o, st) + sum_boundary(f, s, st);
    }

    // The brute force: every seed of H in the 7-sigma box, no lobe culling (gaussian_pndf::eval_reference's terms).
    real eval_reference(const texel_footprint<real>& fp, const vec2& s) const noexcept {
        if (!(s.x * s.x + s.y * s.y < real(1))) return real(0);
        params k = k_;
        k.cull_u = real(7);
        if (lp_.kind == lobe_kind::gaussian) k.cull_s = real(0);
        lobe_query_stats st;
        const frame f = prepare(fp, st, k.cull_u, k.cull_s);
        real sum = 0;
        const real sz = slope_z(s);
        for_each_seed(f, k, [&](long i, long j, const vec2& u) {
            const entry& e = seed(i, j);
            sum += term(e.el, u, f, s, sz, k);
        });
        return sum;
    }

    // The footprint's seed weight W = sum_i w_i (the mass sample() draws from).
    real sampling_weight(const texel_footprint<real>& fp) const noexcept {
        lobe_query_stats st;
        const frame f = prepare(fp, st);
        real sum = 0;
        for_each_seed(f, k_, [&](long, long, const vec2& u) { sum += kernels::glint_pndf_element_weight(u, f, k_); });
        return sum;
    }

    // A half vector: a seed with probability w_i / W, then s from its lobe (truncated as eval cuts it).
    pndf_sample<real> sample(const texel_footprint<real>& fp, real u0, real u1, real u2, bool exact_pdf = true,
                             const lobe_query_options<real>& o = {}) const noexcept {
        pndf_sample<real> r;
        lobe_query_stats st;
        const frame f = prepare(fp, st);
        const real total = sampling_weight(fp);
        if (!(total > real(0))) return r;
        const real target = u0 * total;
        real acc = 0;
        bool found = false;
        long ci = 0, cj = 0;
        vec2 cu(0);
        for_each_seed(f, k_, [&](long i, long j, const vec2& u) {
            if (found) return;
            const real w = kernels::glint_pndf_element_weight(u, f, k_);
            if (w > 0) {
                ci = i, cj = j, cu = u;
                acc += w;
                found = acc > target;
            }
        });
        const element el = seed(ci, cj).el;
        if (lp_.kind == lobe_kind::gaussian) {
            r.s = gaussian_pndf<real>::draw_from_lobe(kernels::glint_pndf_element_lobe(el, cu, f, k_), k_.sigma_r, k_.cull_s, u1, u2);
        } else {
            // theta' from the truncated slope distribution about m_i (Beckmann: tan^2 = -a^2 ln(1 - u (1 - eps));
            // GGX: tan^2 = a^2 v / (1 - v), v = u kept), phi uniform; then rotate into the frame of m_i.
            const real a = lp_.sigma_r;
            real t2;
            if (lp_.kind == lobe_kind::beckmann) t2 = -a * a * std::log1p(-u1 * kept_);
            else {
                const real v = u1 * kept_;
                t2 = a * a * v / (real(1) - v);
            }
            const real c = real(1) / std::sqrt(real(1) + t2), sn = std::sqrt(std::max(real(0), real(1) - c * c));
            const real phi = real(6.28318530717958647692) * u2;
            const vec3_t<real> m = axis_of(vec2(el.us.z, el.us.w));
            const vec3_t<real> t = std::fabs(m.z) < real(0.999) ? glm::normalize(glm::cross(vec3_t<real>(0, 0, 1), m)) : vec3_t<real>(1, 0, 0);
            const vec3_t<real> b = glm::cross(m, t);
            const vec3_t<real> d = m * c + (t * std::cos(phi) + b * std::sin(phi)) * sn;
            if (!(d.z > real(0))) return pndf_sample<real>{};
            r.s = vec2(d.x, d.y);
        }
        if (!(r.s.x * r.s.x + r.s.y * r.s.y < real(1))) return pndf_sample<real>{};
        r.pdf_s = pdf(fp, r.s, total, exact_pdf, o);
        if (!(r.pdf_s > 0)) return pndf_sample<real>{};
        r.h = vec3_t<real>(r.s.x, r.s.y, std::sqrt(real(1) - r.s.x * r.s.x - r.s.y * r.s.y));
        r.pdf_h = r.pdf_s * r.h.z;
        r.valid = true;
        return r;
    }

    // The density of sample()'s s (exact_pdf: the K-lobe-free eval over W; else eval with o over W).
    real pdf(const texel_footprint<real>& fp, const vec2& s, real weight, bool exact_pdf = true, const lobe_query_options<real>& o = {}) const noexcept {
        if (!(weight > 0)) return real(0);
        lobe_query_options<real> q = o;
        if (exact_pdf) q.use_klobes = false;
        return eval(fp, s, q) / weight;
    }

    // Eq. 8 with eval's D_P, Smith G2 (Beckmann at alpha_g()) and the conductor Fresnel.
    real brdf(const texel_footprint<real>& fp, const vec3_t<real>& wi, const vec3_t<real>& wo, real eta, real k, const lobe_query_options<real>& o = {}) const noexcept {
        if (!(wi.z > 0) || !(wo.z > 0)) return real(0);
        const vec3_t<real> hv = wi + wo;
        if (!(hv.z > 0)) return real(0);
        const vec3_t<real> h = glm::normalize(hv);
        return kernels::glint_pndf_brdf(eval(fp, vec2(h.x, h.y), o), wi, wo, static_cast<int>(ndf::beckmann), vec2(alpha_g_), eta, k);
    }

    bool is_boundary(long i, long j) const noexcept {
        i = wrap(i, k_.width), j = wrap(j, k_.height);
        const std::size_t b = static_cast<std::size_t>(i + static_cast<long>(k_.width) * j);
        return boundary_bit(b);
    }

    std::size_t bytes() const noexcept {
        const auto set_bytes = [](const lobe_set& t) {
            return t.listed.size() * sizeof(entry) + t.cell_begin.size() * sizeof(std::uint32_t) + t.node_begin.size() * sizeof(std::uint32_t) +
                   t.nodes.size() * sizeof(node);
        };
        return sample_lobes_.size() * sizeof(entry) + boundary_lobes_.size() * sizeof(entry) + boundary_index_.size() * sizeof(std::uint32_t) +
               boundary_bits_.size() * sizeof(std::uint64_t) + set_bytes(sample_set_) + set_bytes(boundary_set_) + klobes_.size() * sizeof(klobe) +
               run_lo_.size() + run_hi_.size() + own_box_.size() * sizeof(glm::ivec4) + map_.table_bytes() + map_.sample().normals().size() * sizeof(glm::vec3);
    }
    const build_report& report() const noexcept { return report_; }
    real alpha_g() const noexcept { return alpha_g_; }
    real tau() const noexcept { return tau_; }
    const quilted_map& map() const noexcept { return map_; }
    const lobe_params<real>& lobe_settings() const noexcept { return lp_; }

    // The K-lobes, as the tests read them: weight N a, member count, position mean and covariance,
    // normal mean and covariance (Gaussian), product roughness a_K, and the members' normal MSE.
    struct klobe {
        real weight, count;
        vec2 u_mean;
        vec4 u_cov;  // xx, xy, yy, unused
        vec2 n_mean;
        vec4 n_cov;  // xx, xy, yy, the lobe's 1 / sqrt(det) (Gaussian) or a_K (product)
        vec4 n_inv;  // the inverse normal covariance xx, xy, yy; the members' MSE
    };
    const std::vector<klobe>& klobes() const noexcept { return klobes_; }
    // The clustered nodes of the sample's trees, as the tests read them: fn(first K-lobe, count,
    // the node's members) for each, the members as a pointer range into the cell's list.
    template <class fn_t>
    void for_each_clustered_node(fn_t&& fn) const {
        const lobe_set& t = sample_set_;
        for (std::size_t c = 0; c + 1 < t.cell_begin.size(); ++c) {
            const std::uint32_t begin = t.cell_begin[c], end = t.cell_begin[c + 1];
            if (begin == end) continue;
            const std::uint32_t p2 = leaves_p2(end - begin);
            for (std::uint32_t n = 1; n < p2; ++n) {
                const node& nd = t.nodes[t.node_begin[c] + n];
                if (nd.kcount == 0) continue;
                const std::uint32_t first = begin + leaf_size * leaf_first(n, p2), last = std::min(end, begin + leaf_size * leaf_last(n, p2));
                fn(klobes_.data() + nd.kfirst, nd.kcount, t.listed.data() + first, t.listed.data() + last);
            }
        }
    }

    // A seed's lobe and its oriented s-box (cos, sin, r1, r2).
    struct entry {
        element el;
        vec4 bound;
    };
    // The lobe of seed (i, j) of H (lattice indices, wrapped): the sample's or a boundary lobe.
    const entry& seed(long i, long j) const noexcept {
        i = wrap(i, k_.width), j = wrap(j, k_.height);
        const std::uint32_t idx = static_cast<std::uint32_t>(i + static_cast<long>(k_.width) * j);
        if (boundary_bit(idx)) {
            const auto it = std::lower_bound(boundary_index_.begin(), boundary_index_.end(), idx);
            return boundary_lobes_[static_cast<std::size_t>(it - boundary_index_.begin())];
        }
        glm::ivec2 local;
        const int b = map_.owner(i / ept_, j / ept_, &local);
        const glm::ivec2 src = map_.source(b);
        const long si = (src.x + local.x) * ept_ + i % ept_, sj = (src.y + local.y) * ept_ + j % ept_;
        return sample_lobes_[static_cast<std::size_t>(si + sample_w_ * sj)];
    }

private:
    struct node {
        float x0, y0, x1, y1;  // position box
        float s0x, s0y, s1x, s1y;  // s-box union
        std::uint32_t kfirst;
        std::uint32_t kcount;
    };
    struct lobe_set {
        std::vector<int> level_size;
        std::vector<std::size_t> level_first;
        std::vector<entry> listed;
        std::vector<std::uint32_t> cell_begin, node_begin;
        std::vector<node> nodes;
    };

    static long wrap(long i, long n) { return quilted_map::wrap(i, n); }
    // Whether H's seed with linear index idx (i + width j, unwrapped) is a boundary seed.
    bool boundary_bit(std::size_t idx) const noexcept { return (boundary_bits_[idx >> 6] >> (idx & 63)) & 1u; }
    // Entries per leaf of a position tree; the K-lobes cluster leaves and the nodes above them.
    // Smaller leaves give more K-lobes and fewer terms, larger ones fewer K-lobes and less error;
    // 8 was the fastest against the direct P-NDF (report's scratched metal, delta_k 0.3, 200
    // footprints, forest / direct time in one run, 2026-12-07): leaves of 4 took 0.93x the
    // direct's time (L1 1.7e-2), 8 0.84x (1.2e-2), 16 0.89x (4.1e-3), 32 1.0x (8.4e-4).
    static constexpr std::uint32_t leaf_size = 8;
    static std::uint32_t leaves_p2(std::uint32_t count) {
        const std::uint32_t leaves = (count + leaf_size - 1) / leaf_size;
        std::uint32_t p2 = 1;
        while (p2 < leaves) p2 *= 2;
        return p2;
    }

    static vec3_t<real> axis_of(const vec2& n) { return vec3_t<real>(n.x, n.y, std::sqrt(std::max(real(0), real(1) - n.x * n.x - n.y * n.y))); }

    // The z of the unit half vector whose slope is s (0 where |s| >= 1): once a query, for
    // product_lobe, rather than once a lobe (a square root whose latency every term waited for).
    static real slope_z(const vec2& s) noexcept {
        const real sz2 = real(1) - s.x * s.x - s.y * s.y;
        return sz2 > real(0) ? std::sqrt(sz2) : real(0);
    }

    // A product lobe's roughness a as its G_n needs it: a^2, pi a^2 and the cut of tan^2 theta
    // (tan_cut at sigma_r, scaled with a^2). Made once per forest for the seeds' lobes (a =
    // sigma_r; seed_shape_), which saves each seed's term a division, and once per K-lobe term.
    struct lobe_shape {
        real a2, pi_a2, t2_cut;
    };
    lobe_shape shape_of(real a) const noexcept {
        const real a2 = a * a;
        return {a2, real(3.14159265358979323846) * a2, tan_cut_ * tan_cut_ * a2 / (lp_.sigma_r * lp_.sigma_r)};
    }

    // A product lobe's G_n(s) about normal n with roughness `shape` (header comment), cut and
    // renormalised; sz = slope_z(s).
    real product_lobe(const vec2& s, real sz, const vec2& n, const lobe_shape& shape) const noexcept {
        if (!(sz > real(0))) return real(0);
        const vec3_t<real> m = axis_of(n);
        const real c = s.x * m.x + s.y * m.y + sz * m.z;
        if (!(c > real(0))) return real(0);
        const real c2 = c * c, t2 = std::max(real(0), real(1) - c2) / c2, a2 = shape.a2;
        if (t2 > shape.t2_cut) return real(0);
        real d;
        if (lp_.kind == lobe_kind::beckmann) {
            d = std::exp(-t2 / a2) / (shape.pi_a2 * c2 * c2);
        } else {
            const real q = a2 + t2;
            d = a2 / (real(3.14159265358979323846) * c2 * c2 * q * q);
        }
        return d * c / (sz * kept_);
    }

    // Seed term: the Gaussian element (kernels/gaussian.glsl) or a product lobe's w_i G_n(s).
    real term(const element& el, const vec2& u, const frame& f, const vec2& s, real sz, const params& k) const noexcept {
        if (lp_.kind == lobe_kind::gaussian) return kernels::glint_pndf_element(el, u, f, s, k);
        return product_term(el, kernels::glint_pndf_element_weight(u, f, k), s, sz);
    }
    // The same where u's squared Mahalanobis radius m is known (the walk's leaf tests computed it,
    // with the same operations), without its two divisions again.
    real term(const element& el, const vec2& u, real m, const frame& f, const vec2& s, real sz, const params& k) const noexcept {
        if (lp_.kind == lobe_kind::gaussian) return kernels::glint_pndf_element_at(el, kernels::glint_pndf_offset(u, f), m, f, s, k);
        return product_term(el, kernels::glint_pndf_weight_at(m, f, k), s, sz);
    }
    real product_term(const element& el, real w, const vec2& s, real sz) const noexcept {
        return w > real(0) ? w * product_lobe(s, sz, vec2(el.us.z, el.us.w), seed_shape_) : real(0);
    }

    frame prepare(const texel_footprint<real>& fp, lobe_query_stats& st, real cull_u, real cull_s) const noexcept {
        auto c = fp.covariance;
        // Footprints whose culling box reaches more than 24 blocks from its centre are shrunk to that.
        const real limit = real(24 * map_.stride()) / cull_u;
        const real m = std::max(c[0][0], c[1][1]);
        if (m > limit * limit && std::isfinite(m)) {
            c *= (limit * limit) / m;
            st.clamped = true;
        }
        const double det = static_cast<double>(c[0][0]) * static_cast<double>(c[1][1]) - static_cast<double>(c[1][0]) * static_cast<double>(c[1][0]);
        return kernels::glint_pndf_prepare(fp.center, vec4(c[0][0], c[1][0], c[1][1], static_cast<real>(std::max(det, 0.0))), k_.sigma_h,
                                           cull_u, cull_s);
    }
    frame prepare(const texel_footprint<real>& fp, lobe_query_stats& st) const noexcept { return prepare(fp, st, k_.cull_u, lp_.cull_s); }

    // Calls fn(i, j, u) for every H seed (lattice indices, not wrapped, and position) in f's box under k.
    template <class fn_t>
    void for_each_seed(const frame& f, const params& k, fn_t&& fn) const {
        const auto rx = kernels::glint_pndf_axis_range(f.mean.x, f.extent.x, k.spacing, k.max_side);
        const auto ry = kernels::glint_pndf_axis_range(f.mean.y, f.extent.y, k.spacing, k.max_side);
        for (int j = ry.x; j <= ry.y; ++j)
            for (int i = rx.x; i <= rx.y; ++i) fn(i, j, vec2((real(i) + real(0.5)) * k.spacing, (real(j) + real(0.5)) * k.spacing));
    }

    entry make_entry(const normal_sample<double>& q, const glm::dvec2& u) const {
        entry e;
        const bool linear = lp_.kind == lobe_kind::gaussian && lp_.linear_normal;
        e.el.us = vec4(static_cast<real>(u.x), static_cast<real>(u.y), static_cast<real>(q.s.x), static_cast<real>(q.s.y));
        if (linear) {
            e.el.jac = vec4(static_cast<real>(q.jacobian[0].x), static_cast<real>(q.jacobian[0].y), static_cast<real>(q.jacobian[1].x),
                            static_cast<real>(q.jacobian[1].y));
            e.bound = gaussian_pndf<real>::element_sbox(q.jacobian, static_cast<double>(k_.sigma_h), static_cast<double>(lp_.sigma_r),
                                                        static_cast<double>(lp_.cull_u), static_cast<double>(lp_.cull_s));
        } else if (lp_.kind == lobe_kind::gaussian) {
            e.el.jac = vec4(0);
            e.bound = gaussian_pndf<real>::element_sbox(glm::dmat2(0.0), static_cast<double>(k_.sigma_h), static_cast<double>(lp_.sigma_r),
                                                        static_cast<double>(lp_.cull_u), static_cast<double>(lp_.cull_s));
        } else {
            e.el.jac = vec4(0);
            // The chord to the cut's angle bounds |s - n_i| (2 sin(theta_c / 2)), rounded up.
            const double tc = std::atan(static_cast<double>(tan_cut_));
            const real r = static_cast<real>(2 * std::sin(0.5 * tc) * (1 + 1e-4) + 1e-6);
            e.bound = vec4(1, 0, r, r);
        }
        return e;
    }

    void fit_sample_lobes() {
        const normal_map& s = map_.sample();
        sample_w_ = s.width() * ept_;
        const long sh = static_cast<long>(s.height()) * ept_;
        sample_lobes_.resize(static_cast<std::size_t>(sample_w_ * sh));
        const double h = 1.0 / ept_;
        double slope2 = 0;
        for (long j = 0; j < sh; ++j)
            for (long i = 0; i < sample_w_; ++i) {
                const glm::dvec2 u((static_cast<double>(i) + 0.5) * h, (static_cast<double>(j) + 0.5) * h);
                const normal_sample<double> q = s.bicubic(u);
                sample_lobes_[static_cast<std::size_t>(i + sample_w_ * j)] = make_entry(q, u);
                slope2 += (q.s.x * q.s.x + q.s.y * q.s.y) / std::max(1e-12, 1 - q.s.x * q.s.x - q.s.y * q.s.y);
            }
        alpha_g_ = static_cast<real>(std::sqrt(std::max(1e-8, slope2 / static_cast<double>(sample_lobes_.size()) + 2.0 * static_cast<double>(lp_.sigma_r * lp_.sigma_r))));
    }

    // Boundary seeds and their lobes, fitted on H. A seed is interior when its stencil's texels of
    // H are the same neighbours in I around the texel its owner block maps it to (then its lobe is
    // that sample seed's, bit for bit); else it is a boundary seed. Texel row by texel row, with
    // where each texel comes from in I for the five rows the stencils of a row reach.
    void find_boundary() {
        const quilted_map& m = map_;
        const long W = m.width(), H = m.height();
        const int o = m.overlap(), st = m.stride(), e = ept_;
        // Each block's owned texels' bounding box in its square (x0, y0, x1, y1 inclusive): the
        // texels past both overlap strips are its own; the strips' owners are found below.
        own_box_.resize(static_cast<std::size_t>(m.blocks_x()) * static_cast<std::size_t>(m.blocks_y()));
        for (int by = 0; by < m.blocks_y(); ++by)
            for (int bx = 0; bx < m.blocks_x(); ++bx)
                own_box_[static_cast<std::size_t>(bx + m.blocks_x() * by)] = glm::ivec4(o, o, m.stride_x(bx) - 1, m.stride_y(by) - 1);
        // Rows of `from` in a ring of 8: where each texel of H row y comes from in I, packed
        // (y << 16 | x) so that a neighbour in I is +-1 or +-2^16 (the sample is narrower than
        // 2^16 - 1: no carry fakes one).
        std::vector<std::uint32_t> ring(static_cast<std::size_t>(8 * W));
        const auto ring_row = [&](long y) { return ring.data() + static_cast<std::size_t>(y & 7) * static_cast<std::size_t>(W); };  // y mod 8, y >= -2
        const auto wrapped = [](long v, long n) { return v < 0 ? v + n : (v >= n ? v - n : v); };  // |v| < 2n
        // Texel row y's block row and its row within it.
        const auto block_row = [&](long y) {
            const long yy = wrapped(y, H);
            const int by = std::min(static_cast<int>(yy / st), m.blocks_y() - 1);
            return glm::ivec2(by, static_cast<int>(yy - static_cast<long>(by) * st));
        };
        // Whether texel row y crosses its blocks' cores (where only the texels near the blocks'
        // sides are checked below).
        const auto core_row = [&](long y) {
            const glm::ivec2 r = block_row(y);
            return r.y >= o + 2 && r.y < m.stride_y(r.x) - 2;
        };
        const auto fill_row = [&](long y) {
            std::uint32_t* row = ring_row(y);
            const glm::ivec2 bl = block_row(y);
            const int by = bl.x, ly = bl.y;
            // At one seed per texel, a row whose neighbours and itself cross the cores is read only
            // within 3 texels of each block's sides (the checks and the fits of core rows reach 1).
            const bool sides_only = e == 1 && core_row(y - 1) && core_row(y) && core_row(y + 1);
            for (int bx = 0; bx < m.blocks_x(); ++bx) {
                const glm::ivec2 src = m.source(bx + m.blocks_x() * by);
                std::uint32_t* out = row + static_cast<long>(bx) * st;
                const std::uint32_t first = (static_cast<std::uint32_t>(src.y + ly) << 16) | static_cast<std::uint32_t>(src.x);
                const int sx = m.stride_x(bx), a = sides_only ? std::min(o + 3, sx) : sx, z = sides_only ? std::max(a, sx - 3) : sx;
                for (int lx = 0; lx < a; ++lx) out[lx] = first + static_cast<std::uint32_t>(lx);
                for (int lx = z; lx < sx; ++lx) out[lx] = first + static_cast<std::uint32_t>(lx);
                // The overlap strips: owner_in() decides. Past the top strip (ly >= O > every top
                // cut) it reduces to the left cut: the left neighbour's texels lie left of it.
                if (ly >= o) {
                    const int b = bx + m.blocks_x() * by, lb = (bx == 0 ? m.blocks_x() - 1 : bx - 1) + m.blocks_x() * by;
                    const int cut = std::min(m.cut_left(b, ly), m.stride_x(bx)), sl = m.stride_x(bx == 0 ? m.blocks_x() - 1 : bx - 1);
                    const glm::ivec2 lsrc = m.source(lb);
                    glm::ivec4& box = own_box_[static_cast<std::size_t>(lb)];
                    if (cut > 0) box = glm::ivec4(std::min(box.x, sl), std::min(box.y, ly), std::max(box.z, cut - 1 + sl), std::max(box.w, ly));
                    if (cut < o) {
                        glm::ivec4& own = own_box_[static_cast<std::size_t>(b)];
                        own = glm::ivec4(std::min(own.x, cut), own.y, own.z, own.w);
                    }
                    const std::uint32_t lfirst = (static_cast<std::uint32_t>(lsrc.y + ly) << 16) | static_cast<std::uint32_t>(lsrc.x + sl);
                    for (int lx = 0; lx < cut; ++lx) out[lx] = lfirst + static_cast<std::uint32_t>(lx);
                    continue;
                }
                // Texel by texel; the owners' boxes grow once per run of one owner (its texels
                // lie on one row of its square, consecutive).
                int run_owner = -1;
                glm::ivec2 run_first(0), run_last(0);
                const auto grow = [&] {
                    if (run_owner < 0) return;
                    glm::ivec4& box = own_box_[static_cast<std::size_t>(run_owner)];
                    box = glm::ivec4(std::min(box.x, run_first.x), std::min(box.y, run_first.y), std::max(box.z, run_last.x), std::max(box.w, run_last.y));
                };
                for (int lx = 0; lx < m.stride_x(bx); ++lx) {
                    glm::ivec2 l;
                    const int r = m.owner_in(bx, by, lx, ly, &l);
                    if (r != run_owner) grow(), run_owner = r, run_first = l;
                    run_last = l;
                    const glm::ivec2 q = m.source(r) + l;
                    out[lx] = (static_cast<std::uint32_t>(q.y) << 16) | static_cast<std::uint32_t>(q.x);
                }
                grow();
            }
        };
        // The stencil (texels whose weight or derivative weight is non-zero, relative to
        // floor(u - 1/2)): at h = 1 seeds sit on texel centres, where Catmull-Rom's weights are
        // (0, 1, 0, 0) and its derivative's (-1/2, 0, 1/2, 0): the texel and its four neighbours.
        // Finer lattices use all 4 x 4. Either way rows y - 2 .. y + 2 of the seed's texel row y.
        int offsets[16][2], taps = 0;
        if (e == 1) {
            const int cross[5][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};
            for (const auto& c : cross) offsets[taps][0] = c[0], offsets[taps][1] = c[1], ++taps;
        } else
            for (int dy = -1; dy <= 2; ++dy)
                for (int dx = -1; dx <= 2; ++dx) offsets[taps][0] = dx, offsets[taps][1] = dy, ++taps;
        const long lw = k_.width, lh = k_.height;
        boundary_bits_.assign(static_cast<std::size_t>((lw * lh + 63) / 64), 0);
        boundary_index_.clear();
        boundary_lobes_.clear();
        // Room for a band of 3 seeds along each block's two seams (3.5% of H's seeds for 128^2
        // blocks, overlap 8): growing the vectors copies them.
        const std::size_t expected = static_cast<std::size_t>(m.blocks_x()) * static_cast<std::size_t>(m.blocks_y()) * 6u * static_cast<std::size_t>(m.block() * e * e);
        boundary_index_.reserve(expected), boundary_lobes_.reserve(expected);
        const auto at = [&](long x, long y) { return ring_row(y)[wrapped(x, W)]; };
        const std::vector<glm::vec3>& texels = m.sample().normals();
        const std::size_t sw = static_cast<std::size_t>(m.sample().width());
        const auto fetch = [&](long x, long y) -> const glm::vec3& {
            const std::uint32_t q = at(x, y);
            return texels[(q & 0xffffu) + sw * (q >> 16)];
        };
        const double h = 1.0 / e;
        const auto add_boundary = [&](long i, long j) {
            const std::uint32_t idx = static_cast<std::uint32_t>(i + lw * j);
            boundary_bits_[idx >> 6] |= std::uint64_t(1) << (idx & 63);
            boundary_index_.push_back(idx);
            const glm::dvec2 u((static_cast<double>(i) + 0.5) * h, (static_cast<double>(j) + 0.5) * h);
            boundary_lobes_.push_back(make_entry(normal_map::interpolate_with<double, 4>(fetch, u), u));
        };
        // A tap of H (q, where it comes from in I) reads what the sample seed's stencil reads at
        // (dx, dy) from its texel c when it is that texel of I, or another texel with the same
        // value, bit for bit (the sample's own wrap decides that texel): flat and piecewise-constant
        // maps repeat values, and a seam across them changes no lobe (94% of the scratched-metal
        // sample's texels are exactly flat).
        const normal_map& smp = m.sample();
        const auto tap_same = [&](std::uint32_t q, std::uint32_t c, long dx, long dy) {
            if (q == c + static_cast<std::uint32_t>(dx) + (static_cast<std::uint32_t>(dy) << 16)) return true;
            const glm::vec3& a = texels[(q & 0xffffu) + sw * (q >> 16)];
            const glm::vec3& b = smp.texel(static_cast<long>(c & 0xffffu) + dx, static_cast<long>(c >> 16) + dy);
            return std::memcmp(&a, &b, sizeof(glm::vec3)) == 0;
        };
        // One seed per texel: the cross of texels around it, read from the three rows directly.
        const std::uint32_t *up = nullptr, *row = nullptr, *down = nullptr;
        const auto check_centre = [&](long x, long y) {
            const long xm = x == 0 ? W - 1 : x - 1, xp = x == W - 1 ? 0 : x + 1;
            const std::uint32_t c = row[x];
            if (!tap_same(row[xm], c, -1, 0) || !tap_same(row[xp], c, 1, 0) || !tap_same(up[x], c, 0, -1) || !tap_same(down[x], c, 0, 1)) add_boundary(x, y);
        };
        const auto check = [&](long i, long j) {
            if (e == 1) return check_centre(i, j);
            const long tx = i / e - ((i % e) < e / 2 ? 1 : 0), ty = j / e - ((j % e) < e / 2 ? 1 : 0);  // floor(u - 1/2)
            // The texel holding the seed, and where the stencil's taps should be relative to it.
            const long cx = i / e, cy = j / e;
            const std::uint32_t centre = at(cx, cy);
            for (int k = 0; k < taps; ++k) {
                const long dx = tx + offsets[k][0] - cx, dy = ty + offsets[k][1] - cy;
                if (!tap_same(at(cx + dx, cy + dy), centre, dx, dy)) return add_boundary(i, j);
            }
        };
        for (long y = -2; y <= 2; ++y) fill_row(y);
        // Only seeds outside the cores (texels O + 2 .. stride - 3 of their nominal block, whose
        // stencils reach only texels no other block can own), in lattice order.
        for (int by = 0; by < m.blocks_y(); ++by)
            for (int ly = 0; ly < m.stride_y(by); ++ly) {
                const long y = static_cast<long>(by) * st + ly;
                if (y > 0) fill_row(y + 2);
                up = ring_row(y - 1), row = ring_row(y), down = ring_row(y + 1);
                const bool core_y = core_row(y);
                for (int sj = 0; sj < e; ++sj) {
                    const long j = y * e + sj;
                    for (int bx = 0; bx < m.blocks_x(); ++bx) {
                        const long i0 = static_cast<long>(bx) * st * e, i1 = i0 + static_cast<long>(m.stride_x(bx)) * e;
                        if (!core_y) {
                            for (long i = i0; i < i1; ++i) check(i, j);
                            continue;
                        }
                        for (long i = i0; i < std::min(i1, i0 + static_cast<long>(o + 2) * e); ++i) check(i, j);
                        for (long i = i0 + std::max<long>(o + 2, m.stride_x(bx) - 2) * e; i < i1; ++i) check(i, j);
                    }
                }
            }
    }

    // Per block and local texel row, a run [lo, hi) of texels whose seeds are the block's own and
    // not boundary seeds (in core rows the run out from the core; in the rows the cuts cross, the
    // run through the middle texel, or none), in sparse tables of range-max lo and range-min hi over
    // rows: a K-lobe node whose box lies in these runs on every row it spans counts exactly the
    // seeds B owns.
    void find_interiors() {
        const quilted_map& m = map_;
        const int t = m.block(), o = m.overlap();
        int levels = 1;
        while ((1 << levels) < t) ++levels;
        run_levels_ = levels;
        const std::size_t per_block = static_cast<std::size_t>(levels) * static_cast<std::size_t>(t);
        const std::size_t blocks = static_cast<std::size_t>(m.blocks_x()) * static_cast<std::size_t>(m.blocks_y());
        run_lo_.assign(blocks * per_block, static_cast<std::uint8_t>(255));
        run_hi_.assign(blocks * per_block, 0);
        for (int by = 0; by < m.blocks_y(); ++by)
            for (int bx = 0; bx < m.blocks_x(); ++bx) {
                const int b = bx + m.blocks_x() * by;
                const glm::ivec2 c = m.origin(b);
                const int sx = m.stride_x(bx), sy = m.stride_y(by);
                std::uint8_t* lo = run_lo_.data() + static_cast<std::size_t>(b) * per_block;
                std::uint8_t* hi = run_hi_.data() + static_cast<std::size_t>(b) * per_block;
                // Rows through the core: the run out from the core. Rows the cuts cross (the top
                // strip, the last rows): the run through the middle texel, where it is the block's.
                const glm::ivec4 own = own_box_[static_cast<std::size_t>(b)];
                for (int ly = own.y; ly <= std::min(own.w, sy - 1); ++ly) {
                    // B's own texels of its nominal square (owner_in's first case; past the stride
                    // B owns few, and a run may stop short), with no boundary seed. Rows past the
                    // top strip (ly >= O, below every top cut) test only the left cut.
                    const int left = m.cut_left(b, ly);
                    const bool top_strip = ly < o;
                    long y = static_cast<long>(c.y + ly);
                    if (y >= m.height()) y -= m.height();
                    const std::size_t row = static_cast<std::size_t>(k_.width) * static_cast<std::size_t>(y * ept_);
                    const auto ok = [&](int lx) {
                        if (lx >= sx || lx < left || (top_strip && ly < m.cut_top(b, lx))) return false;
                        long x = static_cast<long>(c.x + lx);
                        if (x >= m.width()) x -= m.width();
                        for (int dj = 0; dj < ept_; ++dj)
                            for (int di = 0; di < ept_; ++di) {
                                const std::size_t idx = row + static_cast<std::size_t>(k_.width) * static_cast<std::size_t>(dj) + static_cast<std::size_t>(x * ept_ + di);  // in H: no wrap
                                if (boundary_bit(idx)) return false;
                            }
                        return true;
                    };
                    const bool core = ly >= o + 2 && ly < sy - 2 && o + 2 < sx - 2;
                    int a = core ? o + 2 : sx / 2, z = core ? sx - 2 : sx / 2;
                    if (!core && !ok(a)) continue;
                    while (a > 0 && ok(a - 1)) --a;
                    while (z < t && ok(z)) ++z;
                    lo[ly] = static_cast<std::uint8_t>(a), hi[ly] = static_cast<std::uint8_t>(z);
                }
                for (int l = 1; l < levels; ++l)
                    for (int r = 0; r + (1 << l) <= t; ++r) {
                        const int q = r + (1 << (l - 1));
                        lo[l * t + r] = std::max(lo[(l - 1) * t + r], lo[(l - 1) * t + q]);
                        hi[l * t + r] = std::min(hi[(l - 1) * t + r], hi[(l - 1) * t + q]);
                    }
            }
    }

    // Whether texels [x0, x1] x [y0, y1] of block b's square lie in its runs.
    bool in_runs(int b, int x0, int x1, int y0, int y1) const noexcept {
        const int t = map_.block();
        if (x0 < 0 || y0 < 0 || x1 >= t || y1 >= t || x0 > x1 || y0 > y1) return false;
        const std::size_t base = static_cast<std::size_t>(b) * static_cast<std::size_t>(run_levels_) * static_cast<std::size_t>(t);
        const int n = y1 - y0 + 1;
        int l = 0;
        while ((2 << l) <= n) ++l;
        const std::size_t r0 = base + static_cast<std::size_t>(l * t + y0), r1 = base + static_cast<std::size_t>(l * t + y1 + 1 - (1 << l));
        return std::max(run_lo_[r0], run_lo_[r1]) <= x0 && std::min(run_hi_[r0], run_hi_[r1]) > x1;
    }

    // The cells listing a lobe with oriented s-box b about n (us.zw): those of the finest level where
    // b overlaps at most 8 (the coarsest level has 4 cells in all), written to found; returns their
    // count. A cell overlaps where its square, widened by the margin, meets the box (gaussian.hpp's
    // for_each_cell): the box's axis-aligned bounds give the columns and rows, and each cell of that
    // span is tested on the box's own axes.
    static int lobe_cells(const lobe_set& t, const vec4& b, const vec4& us, std::uint32_t* found) {
        const double margin = 1e-6;
        const double cs = static_cast<double>(b.x), sn = static_cast<double>(b.y), r1 = static_cast<double>(b.z), r2 = static_cast<double>(b.w);
        const double sx = static_cast<double>(us.z), sy = static_cast<double>(us.w);
        const double acs = std::fabs(cs), asn = std::fabs(sn);
        const double hx = r1 * acs + r2 * asn + margin, hy = r1 * asn + r2 * acs + margin;
        const int levels = static_cast<int>(t.level_size.size());
        for (int l = 0; l < levels; ++l) {
            const int m = t.level_size[static_cast<std::size_t>(l)];
            const double c = 2.0 / m, per = 0.5 * m;  // m is a power of 2: (v + 1) * per is (v + 1) / c exactly
            // Clamped first, then truncated: on [0, m] truncation is floor.
            const auto index = [&](double v) { return static_cast<int>(std::clamp((v + 1) * per + 0.5, 0.0, static_cast<double>(m))); };
            const int x0 = index(sx - hx), x1 = index(sx + hx), y0 = index(sy - hy), y1 = index(sy + hy);
            const bool last = l + 1 == levels;
            if (std::max(x1 - x0, y1 - y0) >= 8 && !last) continue;  // more than 8 columns or rows
            const double reach = 0.5 * c * (acs + asn) + margin;
            const std::size_t first = t.level_first[static_cast<std::size_t>(l)];
            int overlapped = 0;
            for (int y = y0; y <= y1 && overlapped <= 8; ++y)  // a ninth cell: on to the next level
                for (int x = x0; x <= x1; ++x) {
                    const double dx = -1 + x * c - sx, dy = -1 + y * c - sy;
                    if (std::fabs(dx * cs + dy * sn) > r1 + reach || std::fabs(dy * cs - dx * sn) > r2 + reach) continue;
                    if (overlapped < 8) found[overlapped] = static_cast<std::uint32_t>(first + static_cast<std::size_t>(x + (m + 1) * y));
                    ++overlapped;
                }
            if (overlapped <= 8 || last) return std::min(overlapped, 8);
        }
        return 0;  // not reached: the last level returns
    }

    // The grids, lists and trees of one lobe set.
    void build_set(lobe_set& t, const std::vector<entry>& lobes) {
        const std::size_t n = lobes.size();
        t = lobe_set{};
        if (n == 0) {
            t.level_size = {1};
            t.level_first = {0};
            t.cell_begin.assign(5, 0);
            t.node_begin.assign(4, 0);
            return;
        }
        std::vector<real> r(n);
        for (std::size_t e = 0; e < n; ++e) r[e] = std::max(lobes[e].bound.z, lobes[e].bound.w);
        std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n / 2), r.end());
        const real median = r[n / 2];
        int finest = 8;
        while (finest < 256 && real(4 * finest) * median <= real(1)) finest *= 2;
        std::size_t cells = 0;
        for (int m = finest; m >= 1; m /= 2) {
            t.level_size.push_back(m);
            t.level_first.push_back(cells);
            cells += static_cast<std::size_t>(m + 1) * static_cast<std::size_t>(m + 1);
        }
        // Each lobe's cells, found once (lobe_cells).
        std::vector<std::uint32_t> count(cells, 0), cell_first(n + 1, 0), cell_list;
        cell_list.reserve(2 * n);
        for (std::size_t e = 0; e < n; ++e) {
            std::uint32_t found[8];
            const int k = lobe_cells(t, lobes[e].bound, lobes[e].el.us, found);
            for (int q = 0; q < k; ++q) ++count[found[q]], cell_list.push_back(found[q]);
            cell_first[e + 1] = static_cast<std::uint32_t>(cell_list.size());
        }
        t.cell_begin.assign(cells + 1, 0);
        for (std::size_t c = 0; c < cells; ++c) t.cell_begin[c + 1] = t.cell_begin[c] + count[c];
        t.listed.resize(t.cell_begin.back());
        std::vector<std::uint32_t> fill(t.cell_begin.begin(), t.cell_begin.end() - 1);
        // Lobes in Morton order of their seed's lattice position (from its coordinates: the
        // boundary lobes are not a full lattice), so each cell's list comes out sorted.
        // A stable radix sort on the Morton code, 11 bits a pass (the lobes start in index order, so
        // ties keep it): std::sort took 8% of the build's time in a profile.
        std::vector<std::uint64_t> key(n), sorted(n);
        const double inv = static_cast<double>(ept_);
        std::uint32_t bits = 0;
        for (std::size_t e = 0; e < n; ++e) {
            const auto x = static_cast<std::uint32_t>(static_cast<double>(lobes[e].el.us.x) * inv);  // u >= 0: truncation is floor
            const auto y = static_cast<std::uint32_t>(static_cast<double>(lobes[e].el.us.y) * inv);
            const std::uint32_t code = morton2(x, y);
            bits |= code;
            key[e] = (static_cast<std::uint64_t>(code) << 32) | e;
        }
        for (int shift = 32; shift < 64 && (bits >> (shift - 32)) != 0; shift += 11) {
            std::array<std::uint32_t, 2049> start{};
            for (const std::uint64_t k : key) ++start[((k >> shift) & 2047u) + 1];
            for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
            for (const std::uint64_t k : key) sorted[start[(k >> shift) & 2047u]++] = k;
            key.swap(sorted);
        }
        for (const std::uint64_t k : key) {
            const std::size_t e = static_cast<std::size_t>(k & 0xffffffffu);
            for (std::uint32_t q = cell_first[e]; q < cell_first[e + 1]; ++q) t.listed[fill[cell_list[q]]++] = lobes[e];
        }
        // Position trees: a complete binary tree (heap order, root 1) over runs of 8 per cell.
        t.node_begin.assign(cells, 0);
        std::size_t total = 0;  // sized once: growing the vector would touch its pages twice
        for (std::size_t c = 0; c < cells; ++c)
            if (t.cell_begin[c + 1] > t.cell_begin[c]) total += 2 * leaves_p2(t.cell_begin[c + 1] - t.cell_begin[c]);
        t.nodes.reserve(total);
        const float big = std::numeric_limits<float>::max();
        const node empty{big, big, -big, -big, big, big, -big, -big, 0, 0};
        for (std::size_t c = 0; c < cells; ++c) {
            const std::uint32_t begin = t.cell_begin[c], end = t.cell_begin[c + 1];
            t.node_begin[c] = static_cast<std::uint32_t>(t.nodes.size());
            if (begin == end) continue;
            const std::uint32_t p2 = leaves_p2(end - begin), leaves = (end - begin + leaf_size - 1) / leaf_size;
            const std::size_t base = t.nodes.size();
            t.nodes.resize(base + 2 * p2, empty);
            for (std::uint32_t l = 0; l < leaves; ++l) {
                node b = empty;
                for (std::uint32_t q = begin + leaf_size * l; q < std::min(end, begin + leaf_size * l + leaf_size); ++q) {
                    const entry& x = t.listed[q];
                    const float px = static_cast<float>(x.el.us.x), py = static_cast<float>(x.el.us.y), mg = 1e-3f;
                    b.x0 = std::min(b.x0, px - mg), b.y0 = std::min(b.y0, py - mg), b.x1 = std::max(b.x1, px + mg), b.y1 = std::max(b.y1, py + mg);
                    const float cs = std::fabs(static_cast<float>(x.bound.x)), sn = std::fabs(static_cast<float>(x.bound.y));
                    const float hx = static_cast<float>(x.bound.z) * cs + static_cast<float>(x.bound.w) * sn + 1e-5f;
                    const float hy = static_cast<float>(x.bound.z) * sn + static_cast<float>(x.bound.w) * cs + 1e-5f;
                    const float sx = static_cast<float>(x.el.us.z), sy = static_cast<float>(x.el.us.w);
                    b.s0x = std::min(b.s0x, sx - hx), b.s0y = std::min(b.s0y, sy - hy), b.s1x = std::max(b.s1x, sx + hx), b.s1y = std::max(b.s1y, sy + hy);
                }
                t.nodes[base + p2 + l] = b;
            }
            for (std::uint32_t i = p2 - 1; i >= 1; --i) {
                const node& a = t.nodes[base + 2 * i];
                const node& b = t.nodes[base + 2 * i + 1];
                t.nodes[base + i] = node{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1),
                                         std::min(a.s0x, b.s0x), std::min(a.s0y, b.s0y), std::max(a.s1x, b.s1x), std::max(a.s1y, b.s1y), 0, 0};
            }
        }
    }

    static std::uint32_t leaf_first(std::uint32_t n, std::uint32_t p2) {
        while (n < p2) n *= 2;
        return n - p2;
    }
    static std::uint32_t leaf_last(std::uint32_t n, std::uint32_t p2) {  // one past
        while (n < p2) n = 2 * n + 1;
        return n - p2 + 1;
    }

    // Additive moments of a set of lobes (Sec. 4.4's clustering and the K-lobes' shapes).
    struct moments {
        double n = 0, ux = 0, uy = 0, uxx = 0, uxy = 0, uyy = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0, jxx = 0, jxy = 0, jyy = 0;
        void add(const entry& e) {
            const double x = e.el.us.x, y = e.el.us.y, a = e.el.us.z, b = e.el.us.w;
            n += 1, ux += x, uy += y, uxx += x * x, uxy += x * y, uyy += y * y, sx += a, sy += b, sxx += a * a, sxy += a * b, syy += b * b;
            // J J^T: rows of J are (dsx/dx, dsx/dy) and (dsy/dx, dsy/dy).
            const double j00 = e.el.jac.x, j10 = e.el.jac.y, j01 = e.el.jac.z, j11 = e.el.jac.w;
            jxx += j00 * j00 + j01 * j01, jxy += j00 * j10 + j01 * j11, jyy += j10 * j10 + j11 * j11;
        }
        void add(const moments& o) {
            n += o.n, ux += o.ux, uy += o.uy, uxx += o.uxx, uxy += o.uxy, uyy += o.uyy, sx += o.sx, sy += o.sy, sxx += o.sxx, sxy += o.sxy, syy += o.syy;
            jxx += o.jxx, jxy += o.jxy, jyy += o.jyy;
        }
        double mse() const { return n > 0 ? std::max(0.0, (sxx + syy) / n - (sx * sx + sy * sy) / (n * n)) : 0.0; }
    };

    klobe make_klobe(const moments& m) const {
        klobe k;
        const double n = m.n, sh2 = static_cast<double>(k_.sigma_h) * static_cast<double>(k_.sigma_h), sr2 = static_cast<double>(lp_.sigma_r) * static_cast<double>(lp_.sigma_r);
        const double mx = m.ux / n, my = m.uy / n, ax = m.sx / n, ay = m.sy / n;
        const double cxx = std::max(0.0, m.uxx / n - mx * mx), cxy = m.uxy / n - mx * my, cyy = std::max(0.0, m.uyy / n - my * my);
        const double nxx = std::max(0.0, m.sxx / n - ax * ax), nxy = m.sxy / n - ax * ay, nyy = std::max(0.0, m.syy / n - ay * ay);
        k.weight = static_cast<real>(n * static_cast<double>(k_.area));
        k.count = static_cast<real>(n);
        k.u_mean = vec2(static_cast<real>(mx), static_cast<real>(my));
        k.u_cov = vec4(static_cast<real>(sh2 + cxx), static_cast<real>(cxy), static_cast<real>(sh2 + cyy), 0);
        k.n_mean = vec2(static_cast<real>(ax), static_cast<real>(ay));
        const double gxx = sr2 + nxx + sh2 * m.jxx / n, gxy = nxy + sh2 * m.jxy / n, gyy = sr2 + nyy + sh2 * m.jyy / n;
        const double det = std::max(gxx * gyy - gxy * gxy, 1e-30);
        if (lp_.kind == lobe_kind::gaussian) k.n_cov = vec4(static_cast<real>(gxx), static_cast<real>(gxy), static_cast<real>(gyy), static_cast<real>(1 / std::sqrt(det)));
        else k.n_cov = vec4(static_cast<real>(gxx), static_cast<real>(gxy), static_cast<real>(gyy), static_cast<real>(std::sqrt(sr2 + nxx + nyy)));
        k.n_inv = vec4(static_cast<real>(gyy / det), static_cast<real>(-gxy / det), static_cast<real>(gxx / det), static_cast<real>(m.mse()));
        return k;
    }

    // One centre c (index q) against the members: where it is nearer than bd[r] (any, for q = 0),
    // bd[r] and best[r] take its distance and q (the index as a float: one type in the loop). The
    // arrays do not overlap, so the loop runs 4 wide.
    static void nearer(const float* __restrict px, const float* __restrict py, const float* __restrict pz, const float* __restrict pw, std::uint32_t n,
                       const glm::vec4& c, float alpha, float q, float* __restrict bd, float* __restrict best) {
        const float cx = c.x, cy = c.y, cz = c.z, cw = c.w;
        for (std::uint32_t r = 0; r < n; ++r) {
            const float a = px[r] - cx, b = py[r] - cy, u = pz[r] - cz, v = pw[r] - cw;
            const float d = alpha * (a * a + b * b) + u * u + v * v, old = q == 0 ? d : bd[r];
            const bool closer = d < old;
            best[r] = q == 0 ? 0.0f : (closer ? q : best[r]);
            bd[r] = closer ? d : old;
        }
    }

    // Adaptive k-means (Alg. 1) over listed[first, last): the K-lobes appended, or none.
    bool kmeans(const std::vector<entry>& listed, std::uint32_t first, std::uint32_t last, const node& nd, const cluster_params<real>& cp, std::uint32_t salt) {
        const std::uint32_t n = last - first;
        const double dx = static_cast<double>(nd.x1) - static_cast<double>(nd.x0), dy = static_cast<double>(nd.y1) - static_cast<double>(nd.y0);
        const float alpha = static_cast<float>(static_cast<double>(tau_) / std::max(1e-12, dx * dx + dy * dy));
        // The members' (u, s) once, one array per coordinate, u from the node's corner: single
        // precision, so the loops over members run 4 wide (an assignment may differ from double's
        // only between centres within float rounding of equidistant, which either choice serves).
        scratch_.resize(7 * static_cast<std::size_t>(n));
        float *px = scratch_.data(), *py = px + n, *pz = py + n, *pw = pz + n, *nearest = pw + n, *bd = nearest + n, *best = bd + n;
        for (std::uint32_t r = 0; r < n; ++r) {
            const vec4& us = listed[first + r].el.us;
            px[r] = static_cast<float>(us.x - static_cast<real>(nd.x0)), py[r] = static_cast<float>(us.y - static_cast<real>(nd.y0)), pz[r] = static_cast<float>(us.z), pw[r] = static_cast<float>(us.w);
        }
        const auto point = [&](std::uint32_t r) { return glm::vec4(px[r], py[r], pz[r], pw[r]); };
        const auto dist = [&](std::uint32_t r, const glm::vec4& c) {
            const float a = px[r] - c.x, b = py[r] - c.y, p = pz[r] - c.z, q = pw[r] - c.w;
            return alpha * (a * a + b * b) + p * p + q * q;
        };
        std::vector<glm::vec4>& centre = scratch_centres_;
        std::vector<std::uint8_t>& assign = scratch_assign_;
        // Two members whose normals lie more than sqrt(2 n tau) apart share no accepted cluster
        // (its SSE would be at least half their squared distance, over n tau): with k such members
        // pairwise (farthest-point picks) no C < k is accepted, so the trials start at k, and none
        // run past MCN. The distance is widened past float's rounding (of a double normal: 3e-8 a
        // coordinate; of the float arithmetic: under 1e-6 relative), so only trials that fail are
        // skipped.
        const double reach = std::sqrt(2.0 * n * static_cast<double>(tau_)) * (1 + 1e-5) + 2e-7;
        const float limit = static_cast<float>(reach * reach);
        const auto normal_d2 = [&](std::uint32_t r, std::uint32_t q) {
            const float a = pz[r] - pz[q], b = pw[r] - pw[q];
            return a * a + b * b;
        };
        int apart = 1;
        for (std::uint32_t r = 0; r < n; ++r) nearest[r] = normal_d2(r, 0);
        while (apart <= cp.max_clusters) {
            const std::uint32_t far = static_cast<std::uint32_t>(std::max_element(nearest, nearest + n) - nearest);
            if (!(nearest[far] > limit)) break;
            ++apart;
            for (std::uint32_t r = 0; r < n; ++r) nearest[r] = std::min(nearest[r], normal_d2(r, far));
        }
        if (apart > cp.max_clusters) return false;
        assign.assign(n, 0);
        // k-means++ seeds, drawn once for all C: C's are the first C (each trial's Lloyd steps
        // start from a copy), with nearest[] the distance to the nearest seed so far.
        std::array<glm::vec4, 8> seed{};
        int seeded = 0;
        const auto pick = [&](std::uint32_t i) { return unit_from_bits<double>(pcg3d(glm::uvec3(salt, cp.seed * 977u, i)).x); };
        const auto add_seed = [&] {
            std::uint32_t chosen = n - 1;
            if (seeded == 0) {
                chosen = std::min(n - 1, static_cast<std::uint32_t>(pick(0) * n));
            } else {
                double total = 0;
                for (std::uint32_t r = 0; r < n; ++r) total += static_cast<double>(nearest[r]);
                double target = pick(static_cast<std::uint32_t>(seeded)) * total;
                for (std::uint32_t r = 0; r < n; ++r) {
                    target -= static_cast<double>(nearest[r]);
                    if (target <= 0) {
                        chosen = r;
                        break;
                    }
                }
            }
            const glm::vec4 cc = seed[static_cast<std::size_t>(seeded++)] = point(chosen);
            for (std::uint32_t r = 0; r < n; ++r) nearest[r] = seeded == 1 ? dist(r, cc) : std::min(nearest[r], dist(r, cc));
        };
        for (int C = std::max(2, apart); C <= cp.max_clusters; ++C) {
            if (static_cast<std::uint32_t>(C) > n) break;
            while (seeded < C) add_seed();
            centre.assign(seed.begin(), seed.begin() + C);
            // Lloyd steps: ECN for the trial, then on to convergence for C*.
            const auto lloyd = [&](int iters) {
                for (int it = 0; it < iters; ++it) {
                    bool changed = it == 0;
                    // The nearest centre, the first of equals (centre by centre over the members).
                    for (int q = 0; q < C; ++q) nearer(px, py, pz, pw, n, centre[static_cast<std::size_t>(q)], alpha, static_cast<float>(q), bd, best);
                    for (std::uint32_t r = 0; r < n; ++r) {
                        const auto b = static_cast<std::uint8_t>(best[r]);
                        changed |= assign[r] != b, assign[r] = b;
                    }
                    if (!changed) return;
                    std::array<glm::dvec4, 8> sum{};
                    std::array<double, 8> cnt{};
                    for (std::uint32_t r = 0; r < n; ++r) {
                        sum[assign[r]] += glm::dvec4(point(r));
                        cnt[assign[r]] += 1;
                    }
                    for (int q = 0; q < C; ++q)
                        if (cnt[static_cast<std::size_t>(q)] > 0) centre[static_cast<std::size_t>(q)] = glm::vec4(sum[static_cast<std::size_t>(q)] / cnt[static_cast<std::size_t>(q)]);
                }
            };
            const auto cluster_moments = [&](std::array<moments, 8>& mo) {
                mo = {};
                for (std::uint32_t r = 0; r < n; ++r) mo[assign[r]].add(listed[first + r]);
            };
            const auto accepted = [&](const std::array<moments, 8>& mo) {
                for (int q = 0; q < C; ++q)
                    if (mo[static_cast<std::size_t>(q)].n == 0 || mo[static_cast<std::size_t>(q)].mse() > static_cast<double>(tau_)) return false;
                return true;
            };
            lloyd(cp.trial_iters);
            std::array<moments, 8> mo;
            cluster_moments(mo);
            if (!accepted(mo)) continue;
            const std::vector<std::uint8_t> trial = assign;
            lloyd(cp.max_iters - cp.trial_iters);
            cluster_moments(mo);
            if (!accepted(mo)) {
                assign = trial;
                cluster_moments(mo);
            }
            for (int q = 0; q < C; ++q) klobes_.push_back(make_klobe(mo[static_cast<std::size_t>(q)]));
            return true;
        }
        return false;
    }

    // K-lobes at the inner nodes of the sample's trees, bottom-up (header comment).
    void cluster(const cluster_params<real>& cp) {
        lobe_set& t = sample_set_;
        for (std::size_t c = 0; c + 1 < t.cell_begin.size(); ++c) {
            const std::uint32_t begin = t.cell_begin[c], end = t.cell_begin[c + 1];
            if (begin == end) continue;
            const std::uint32_t p2 = leaves_p2(end - begin), leaves = (end - begin + leaf_size - 1) / leaf_size;
            node* nodes = t.nodes.data() + t.node_begin[c];
            std::vector<moments> mo(2 * p2);
            std::vector<std::uint8_t> state(2 * p2, 0);  // 1: leaf or clustered
            for (std::uint32_t l = 0; l < leaves; ++l) {
                for (std::uint32_t q = begin + leaf_size * l; q < std::min(end, begin + leaf_size * l + leaf_size); ++q) mo[p2 + l].add(t.listed[q]);
                state[p2 + l] = 1;
            }
            for (std::uint32_t i = p2 - 1; i >= 1; --i) {
                mo[i] = mo[2 * i];
                mo[i].add(mo[2 * i + 1]);
                if (mo[i].n < 2 || (state[2 * i] == 0 && state[2 * i + 1] == 0)) continue;
                const std::uint32_t first = begin + leaf_size * leaf_first(i, p2), last = std::min(end, begin + leaf_size * leaf_last(i, p2));
                const std::uint32_t k0 = static_cast<std::uint32_t>(klobes_.size());
                bool ok = false;
                if (mo[i].mse() <= static_cast<double>(tau_)) {
                    klobes_.push_back(make_klobe(mo[i]));
                    ok = true;
                } else if (state[2 * i] == 1 && state[2 * i + 1] == 1 && last - first <= static_cast<std::uint32_t>(cp.max_node)) {
                    ok = kmeans(t.listed, first, last, nodes[i], cp, static_cast<std::uint32_t>(c * 1315423911u + i));
                }
                if (!ok) continue;
                state[i] = 1;
                nodes[i].kfirst = k0;
                nodes[i].kcount = static_cast<std::uint32_t>(klobes_.size()) - k0;
                ++report_.clustered_nodes;
            }
        }
    }

    // A K-lobe's footprint term (header comment) has three parts, each of which can make it 0: the
    // normal lobe at s, the position Gaussian of Sigma_P plus the K-lobe's position covariance, and
    // the members' taper at the centroid u_mean (in the footprint's own metric, as the seeds').
    // The normal part: G_nj(s) (times the lobe's weight terms); `misses` where the lobe misses s
    // (a Gaussian lobe past its culling radius, a product lobe 0).
    real klobe_normal(const klobe& k, const frame& f, const vec2& s, real sz, bool& misses) const noexcept {
        if (lp_.kind != lobe_kind::gaussian) {
            const real g = product_lobe(s, sz, k.n_mean, shape_of(k.n_cov.w));
            misses = !(g > real(0));
            return g;
        }
        const real q = klobe_gaussian_q(k, s);
        misses = q > k_.cull_s * k_.cull_s;
        return misses ? real(0) : std::exp(real(-0.5) * q) * f.lobe_norm * k.n_cov.w;
    }
    // A Gaussian normal lobe's squared Mahalanobis distance to s.
    static real klobe_gaussian_q(const klobe& k, const vec2& s) noexcept {
        const vec2 d = s - k.n_mean;
        return k.n_inv.x * d.x * d.x + real(2) * k.n_inv.y * d.x * d.y + k.n_inv.z * d.y * d.y;
    }
    // Sigma_P = R diag(lambda) R^T plus the K-lobe's position covariance: (xx, xy, yy, det).
    static vec4 klobe_covariance(const klobe& k, const frame& f) noexcept {
        const real c = f.axis.x, sn = f.axis.y;
        const real pxx = c * c * f.lambda.x + sn * sn * f.lambda.y, pxy = c * sn * (f.lambda.x - f.lambda.y), pyy = sn * sn * f.lambda.x + c * c * f.lambda.y;
        const real mxx = pxx + k.u_cov.x, mxy = pxy + k.u_cov.y, myy = pyy + k.u_cov.z;
        return vec4(mxx, mxy, myy, mxx * myy - mxy * mxy);
    }
    // The taper at the centroid.
    real klobe_window(const vec2& u_mean, const frame& f) const noexcept {
        return kernels::glint_pndf_window(kernels::glint_pndf_mahalanobis_u(kernels::glint_pndf_offset(u_mean, f), f), k_.cull_u);
    }
    // Whether the taper cuts a K-lobe at u_mean that would otherwise count (its normal lobe reaches
    // s and its covariance is positive definite): then its node cannot stand in. Sets `win` to
    // klobe_window's where the term can need it (0 where the lobe misses s). The cheaper test
    // first: a Gaussian lobe's cull (most of a Gaussian forest's K-lobes miss s), a product lobe's
    // taper (the lobe costs a square root, divisions and an exp; 64% of the pyramids' nodes that
    // reach their K-lobes are cut).
    bool klobe_cut(const klobe& k, const vec2& u_mean, const frame& f, const vec2& s, real sz, real& win) const noexcept {
        if (lp_.kind == lobe_kind::gaussian) {
            win = real(0);
            if (klobe_gaussian_q(k, s) > k_.cull_s * k_.cull_s) return false;
            win = klobe_window(u_mean, f);
            return !(win > real(0)) && klobe_covariance(k, f).w > real(0);
        }
        win = klobe_window(u_mean, f);
        if (win > real(0)) return false;
        bool misses = false;
        klobe_normal(k, f, s, sz, misses);
        return !misses && klobe_covariance(k, f).w > real(0);
    }
    // The term, with the window klobe_cut gave.
    real klobe_term(const klobe& k, const vec2& u_mean, real win, const frame& f, const vec2& s, real sz) const noexcept {
        bool misses = false;
        const real g = klobe_normal(k, f, s, sz, misses);
        if (misses) return real(0);
        const vec4 m = klobe_covariance(k, f);
        if (!(m.w > real(0)) || !(win > real(0))) return real(0);
        const vec2 e = f.mean - u_mean;
        const real q = (m.z * e.x * e.x - real(2) * m.y * e.x * e.y + m.x * e.y * e.y) / m.w;
        const real w = k.weight * f.norm * std::sqrt(f.kappa.x * f.kappa.y / m.w) * std::exp(real(-0.5) * q) * win;
        return w * g;
    }

    static bool outside_sbox(const vec4& b, const element& el, const vec2& s) { return detail::lobe_outside_sbox(b, el.us.z, el.us.w, s); }

    std::size_t cell_of(const lobe_set& t, const vec2& s, int l) const noexcept {
        const int m = t.level_size[static_cast<std::size_t>(l)];
        const real c = real(2) / real(m);
        const int cx = std::clamp(static_cast<int>(std::floor((s.x + real(1)) / c + real(0.5))), 0, m);
        const int cy = std::clamp(static_cast<int>(std::floor((s.y + real(1)) / c + real(0.5))), 0, m);
        return t.level_first[static_cast<std::size_t>(l)] + static_cast<std::size_t>(cx + (m + 1) * cy);
    }

    // The footprint's culling ellipse in a walk's coordinates (I for the sample set, H's periodic
    // image for the boundary set): centre, axis (the frame's), and half-axes cull_u sqrt(kappa),
    // widened by a margin that covers float rounding.
    struct ellipse {
        glm::vec2 centre, axis, radius;
    };
    ellipse culling_ellipse(const frame& f, const vec2& centre) const noexcept {
        const real cu = k_.cull_u;
        const glm::vec2 r(static_cast<float>(cu * std::sqrt(f.kappa.x)), static_cast<float>(cu * std::sqrt(f.kappa.y)));
        return {glm::vec2(centre), glm::vec2(f.axis), r * 1.0001f + glm::vec2(0.01f)};
    }

    // Walks cell c of set t over the position box [b0, b1] and the ellipse e (a node is skipped
    // where either axis of e separates it from e: a conservative test, the leaves test exactly);
    // the leaf entries that pass the cheap tests (s in their s-box, us.xy + u_offset in f's
    // culling ellipse: detail::lobe_leaf_candidates, eight at a time in AVX2) go to leaf(entry), in
    // order, and inner nodes to inner(node) first, which returns true to stop there.
    template <class leaf_t, class inner_t>
    void walk(const lobe_set& t, std::size_t c, const glm::vec2& b0, const glm::vec2& b1, const ellipse& e, const vec2& s, const frame& f, const vec2& u_offset,
              lobe_query_stats& st, leaf_t&& leaf, inner_t&& inner) const noexcept {
        static_assert(sizeof(entry) == 12 * sizeof(real) && leaf_size <= 8, "lobe_leaf_candidates: leaves of at most 8 entries of 12 reals (us, jac, bound)");
        const real cull2 = k_.cull_u * k_.cull_u;
        const std::uint32_t begin = t.cell_begin[c], end = t.cell_begin[c + 1];
        if (begin == end) return;
        const std::uint32_t p2 = leaves_p2(end - begin);
        const node* tree = t.nodes.data() + t.node_begin[c];
        const float sx = static_cast<float>(s.x), sy = static_cast<float>(s.y);
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 1;
        while (top > 0) {
            const std::uint32_t n = stack[--top];
            const node& b = tree[n];
            ++st.nodes;
            if (b.x0 > b1.x || b.x1 < b0.x || b.y0 > b1.y || b.y1 < b0.y) continue;
            if (sx < b.s0x || sx > b.s1x || sy < b.s0y || sy > b.s1y) continue;
            const float dx = e.centre.x - 0.5f * (b.x0 + b.x1), dy = e.centre.y - 0.5f * (b.y0 + b.y1);
            const float hx = 0.5f * (b.x1 - b.x0), hy = 0.5f * (b.y1 - b.y0), ax = std::fabs(e.axis.x), ay = std::fabs(e.axis.y);
            if (std::fabs(e.axis.x * dx + e.axis.y * dy) - (hx * ax + hy * ay) > e.radius.x) continue;
            if (std::fabs(e.axis.x * dy - e.axis.y * dx) - (hx * ay + hy * ax) > e.radius.y) continue;
            if (n >= p2) {
                const std::uint32_t first = begin + leaf_size * (n - p2), last = std::min(end, first + leaf_size);
                real m[8];
                for (unsigned keep = detail::lobe_leaf_candidates(reinterpret_cast<const real*>(t.listed.data() + first), last - first, s, u_offset, f, cull2, m);
                     keep != 0; keep &= keep - 1) {
                    const unsigned i = static_cast<unsigned>(__builtin_ctz(keep));
                    leaf(t.listed[first + i], m[i]);
                }
            } else {
                if (b.kcount > 0 && inner(b)) continue;
                // The left child on top, so that leaves come in memory order (as gaussian_pndf's
                // query: the hardware prefetcher follows it).
                stack[top++] = 2 * n + 1;
                stack[top++] = 2 * n;
            }
        }
    }

    // The sample set's part of D_P: per block (and periodic image) the footprint box moved into I.
    real sum_sample(const frame& f, const vec2& s, const lobe_query_options<real>& o, lobe_query_stats& st) const noexcept {
        const real sz = slope_z(s);
        const quilted_map& m = map_;
        const real W = static_cast<real>(m.width()), H = static_cast<real>(m.height());
        const real x0 = f.mean.x - f.extent.x, x1 = f.mean.x + f.extent.x, y0 = f.mean.y - f.extent.y, y1 = f.mean.y + f.extent.y;
        // The blocks (and image offsets) whose squares overlap the box, per axis.
        struct span {
            int b;
            real offset;  // H position of the block's corner
        };
        span xs[64], ys[64];
        const auto spans = [&](real lo, real hi, real period, int blocks, int stride, span* out) {
            int n = 0;
            const long i0 = static_cast<long>(std::floor((lo - real(m.block())) / period)), i1 = static_cast<long>(std::floor(hi / period));
            for (long img = i0; img <= i1; ++img)
                for (int b = 0; b < blocks && n < 64; ++b) {
                    const real corner = real(img) * period + real(b * stride);
                    if (corner + real(m.block()) > lo && corner <= hi) out[n++] = {b, corner};
                }
            return n;
        };
        const int nx = spans(x0, x1, W, m.blocks_x(), m.stride(), xs), ny = spans(y0, y1, H, m.blocks_y(), m.stride(), ys);
        const real lambda_min = f.lambda.y;  // the footprint's smaller variance
        const real reach = o.cluster_extent * std::sqrt(std::max(lambda_min, real(0)));
        const int o_core = m.overlap();
        real sum = 0;
        for (int a = 0; a < ny; ++a)
            for (int b = 0; b < nx; ++b) {
                const int blk = xs[b].b + m.blocks_x() * ys[a].b;
                ++st.blocks;
                const glm::ivec2 src = m.source(blk);
                const vec2 shift = vec2(real(src.x), real(src.y)) - vec2(xs[b].offset, ys[a].offset);  // I = H + shift
                const real t = real(m.block());
                // The box in I, cut to the texels B owns.
                const glm::ivec4 own = own_box_[static_cast<std::size_t>(blk)];
                const glm::vec2 b0(static_cast<float>(std::max(x0 + shift.x, real(src.x + own.x))), static_cast<float>(std::max(y0 + shift.y, real(src.y + own.y))));
                const glm::vec2 b1(static_cast<float>(std::min(x1 + shift.x, real(src.x + own.z + 1))), static_cast<float>(std::min(y1 + shift.y, real(src.y + own.w + 1))));
                if (b0.x > b1.x || b0.y > b1.y) continue;
                // B's core in I: seeds whose stencil lies in the texels only B can own (no test needed).
                const real cx0 = real(src.x + o_core) + real(1.5), cy0 = real(src.y + o_core) + real(1.5);
                const real cx1 = real(src.x + m.stride_x(xs[b].b)) - real(1.5), cy1 = real(src.y + m.stride_y(ys[a].b)) - real(1.5);
                const glm::ivec2 origin_i = m.origin(blk) * ept_;  // B's corner on H's lattice
                const auto leaf = [&](const entry& e, real m_u) GLINT_FLATTEN {  // past the s-box and the culling ellipse (walk)
                    const vec2 p(e.el.us.x, e.el.us.y);
                    const vec2 u = p - shift;
                    if (!(p.x >= cx0 && p.x < cx1 && p.y >= cy0 && p.y < cy1)) {
                        // Outside the core: B's own seed (its texel is B's), and not a boundary seed.
                        const real lx = p.x - real(src.x), ly = p.y - real(src.y);
                        if (!(lx >= real(0) && lx < t && ly >= real(0) && ly < t)) return;
                        if (!m.owns(xs[b].b, ys[a].b, static_cast<int>(lx), static_cast<int>(ly))) return;
                        long i = static_cast<long>(origin_i.x) + static_cast<long>(lx * real(ept_)), j = static_cast<long>(origin_i.y) + static_cast<long>(ly * real(ept_));
                        if (i >= k_.width) i -= k_.width;
                        if (j >= k_.height) j -= k_.height;
                        const std::size_t idx = static_cast<std::size_t>(i + static_cast<long>(k_.width) * j);
                        if (boundary_bit(idx)) return;
                    }
                    ++st.lobes;
                    sum += term(e.el, u, m_u, f, s, sz, k_);
                };
                const auto inner = [&](const node& nd) {
                    if (!o.use_klobes) return false;
                    if (std::max(nd.x1 - nd.x0, nd.y1 - nd.y0) > static_cast<float>(reach)) return false;
                    // The members' texels (the box carries a 1e-3 margin) in B's runs.
                    const int tx0 = static_cast<int>(std::floor(nd.x0 + 2e-3f - static_cast<float>(src.x))), tx1 = static_cast<int>(std::floor(nd.x1 - 2e-3f - static_cast<float>(src.x)));
                    const int ty0 = static_cast<int>(std::floor(nd.y0 + 2e-3f - static_cast<float>(src.y))), ty1 = static_cast<int>(std::floor(nd.y1 - 2e-3f - static_cast<float>(src.y)));
                    if (!in_runs(blk, tx0, tx1, ty0, ty1)) return false;
                    // The K-lobes stand in unless the footprint's taper cuts one at its centroid
                    // (the node straddles the footprint's edge: its members are taken one by one).
                    // Every K-lobe's cut first: then no term is needed.
                    real win[8];
                    for (std::uint32_t q = 0; q < nd.kcount; ++q) {
                        const klobe& k = klobes_[nd.kfirst + q];
                        if (klobe_cut(k, k.u_mean - shift, f, s, sz, win[q])) return false;
                    }
                    for (std::uint32_t q = 0; q < nd.kcount; ++q) {
                        const klobe& k = klobes_[nd.kfirst + q];
                        const real v = klobe_term(k, k.u_mean - shift, win[q], f, s, sz);
                        sum += v;
                        st.klobes += v > real(0) ? 1u : 0u;  // as lobes count: those past the cheap rejections
                    }
                    return true;
                };
                const ellipse el = culling_ellipse(f, f.mean + shift);
                for (int l = 0; l < static_cast<int>(sample_set_.level_size.size()); ++l) walk(sample_set_, cell_of(sample_set_, s, l), b0, b1, el, s, f, -shift, st, leaf, inner);
            }
        return sum;
    }

    // Whether eval takes the lattice path (lobe_path): K-lobes cannot stand in yet, and the box's
    // seeds are fewer than the trees' visits, estimated as the lobes listed in the cells holding s
    // at the box's share of the sample, plus a walk of 32 nodes per block and grid level.
    bool use_lattice(const frame& f, const vec2& s, const lobe_query_options<real>& o) const noexcept {
        if (o.path != lobe_path::automatic) return o.path == lobe_path::lattice;
        if (o.use_klobes && tau_ > 0 && o.cluster_extent * std::sqrt(std::max(f.lambda.y, real(0))) >= real(8)) return false;
        const double spacing = static_cast<double>(k_.spacing);
        const double box = 4.0 * static_cast<double>(f.extent.x) * static_cast<double>(f.extent.y) / (spacing * spacing);
        double listed = 0;
        for (int l = 0; l < static_cast<int>(sample_set_.level_size.size()); ++l) {
            const std::size_t c = cell_of(sample_set_, s, l);
            listed += static_cast<double>(sample_set_.cell_begin[c + 1] - sample_set_.cell_begin[c]);
        }
        const double share = box / static_cast<double>(sample_lobes_.size());
        const double blocks = (2.0 * static_cast<double>(f.extent.x) / map_.stride() + 1.0) * (2.0 * static_cast<double>(f.extent.y) / map_.stride() + 1.0);
        return box < 1.5 * listed * share + 32.0 * blocks * static_cast<double>(sample_set_.level_size.size());
    }

    // D_P(s) by the footprint box's lattice: each row cut at the blocks' nominal columns; seeds of a
    // block's core read the sample's lobes directly, the others through seed() (owner, boundary).
    real sum_lattice(const frame& f, const vec2& s, lobe_query_stats& st) const noexcept {
        const real sz = slope_z(s);
        const quilted_map& m = map_;
        const auto rx = kernels::glint_pndf_axis_range(f.mean.x, f.extent.x, k_.spacing, k_.max_side);
        const auto ry = kernels::glint_pndf_axis_range(f.mean.y, f.extent.y, k_.spacing, k_.max_side);
        const long lw = k_.width, lh = k_.height, e = ept_, st_lat = static_cast<long>(m.stride()) * e, core0 = static_cast<long>(m.overlap() + 2) * e;
        real sum = 0;
        const real cull2 = k_.cull_u * k_.cull_u;
        const auto add = [&](const entry& x, const vec2& u) GLINT_FLATTEN {
            if (outside_sbox(x.bound, x.el, s)) return;
            const real m_u = detail::lobe_footprint_radius(u, f);
            if (m_u > cull2) return;
            ++st.lobes;
            sum += term(x.el, u, m_u, f, s, sz, k_);
        };
        for (long j = ry.x; j <= ry.y; ++j) {
            const long jj = wrap(j, lh), by = std::min<long>(jj / st_lat, m.blocks_y() - 1), ly = jj - by * st_lat;
            const bool core_y = ly >= core0 && ly < static_cast<long>(m.stride_y(static_cast<int>(by))) * e - 2 * e;
            const real uy = (real(j) + real(0.5)) * k_.spacing;
            long i = rx.x;
            while (i <= rx.y) {
                const long ii = wrap(i, lw), bx = std::min<long>(ii / st_lat, m.blocks_x() - 1), lx0 = ii - bx * st_lat;
                const long width = static_cast<long>(m.stride_x(static_cast<int>(bx))) * e;
                const long run = std::min(rx.y - i + 1, width - lx0);  // seeds left in this block's columns
                const int b = static_cast<int>(bx + m.blocks_x() * by);
                const glm::ivec2 src = m.source(b);
                const long row = (static_cast<long>(src.y) * e + ly) * sample_w_ + static_cast<long>(src.x) * e;
                for (long k = 0; k < run; ++k) {
                    const long lx = lx0 + k;
                    const vec2 u((real(i + k) + real(0.5)) * k_.spacing, uy);
                    if (core_y && lx >= core0 && lx < width - 2 * e) add(sample_lobes_[static_cast<std::size_t>(row + lx)], u);
                    else add(seed(ii + k, jj), u);
                }
                i += run;
            }
        }
        return sum;
    }

    // The boundary set's part: walked in H over the box's periodic images.
    real sum_boundary(const frame& f, const vec2& s, lobe_query_stats& st) const noexcept {
        if (boundary_lobes_.empty()) return real(0);
        const real sz = slope_z(s);
        const real W = static_cast<real>(map_.width()), H = static_cast<real>(map_.height());
        const real x0 = f.mean.x - f.extent.x, x1 = f.mean.x + f.extent.x, y0 = f.mean.y - f.extent.y, y1 = f.mean.y + f.extent.y;
        const long ix0 = static_cast<long>(std::floor(x0 / W)), ix1 = static_cast<long>(std::floor(x1 / W));
        const long iy0 = static_cast<long>(std::floor(y0 / H)), iy1 = static_cast<long>(std::floor(y1 / H));
        real sum = 0;
        for (long iy = iy0; iy <= iy1; ++iy)
            for (long ix = ix0; ix <= ix1; ++ix) {
                const vec2 offset(real(ix) * W, real(iy) * H);
                const glm::vec2 b0(static_cast<float>(x0 - offset.x), static_cast<float>(y0 - offset.y));
                const glm::vec2 b1(static_cast<float>(x1 - offset.x), static_cast<float>(y1 - offset.y));
                const auto leaf = [&](const entry& e, real m_u) GLINT_FLATTEN {  // past the s-box and the culling ellipse (walk)
                    ++st.lobes;
                    sum += term(e.el, vec2(e.el.us.x, e.el.us.y) + offset, m_u, f, s, sz, k_);
                };
                const auto inner = [](const node&) { return false; };
                const ellipse el = culling_ellipse(f, f.mean - offset);
                for (int l = 0; l < static_cast<int>(boundary_set_.level_size.size()); ++l)
                    walk(boundary_set_, cell_of(boundary_set_, s, l), b0, b1, el, s, f, offset, st, leaf, inner);
            }
        return sum;
    }

    quilted_map map_;  // a copy: the sample and the block table
    lobe_params<real> lp_{};
    params k_{};
    real tau_ = 0, tan_cut_ = 0, kept_ = 1, alpha_g_ = real(0.1);
    lobe_shape seed_shape_{};  // shape_of(sigma_r)
    int ept_ = 1;
    long sample_w_ = 0;
    std::vector<entry> sample_lobes_, boundary_lobes_;
    std::vector<std::uint32_t> boundary_index_;  // H lattice index of each boundary lobe, ascending
    std::vector<std::uint64_t> boundary_bits_;   // one bit per H seed: boundary
    std::vector<glm::ivec4> own_box_;             // per block, its owned texels' bounding box (find_boundary)
    std::vector<std::uint8_t> run_lo_, run_hi_;  // per block, sparse tables of its interior runs (find_interiors)
    int run_levels_ = 0;
    lobe_set sample_set_, boundary_set_;
    std::vector<klobe> klobes_;
    std::vector<glm::vec4> scratch_centres_;
    std::vector<float> scratch_;
    std::vector<std::uint8_t> scratch_assign_;
    build_report report_{};
};

}  // namespace glint
