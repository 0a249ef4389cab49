// Inverse bin maps (AKKW): the filtered NDF of a large normal map over any pixel footprint, at a
// few bytes per texel, in time that hardly grows with the footprint. CPU only: the queries are
// written in the kernel subset's style (no recursion, fixed-size stacks, index arithmetic) so
// that a GPU port is mechanical.
//
//   glint::normal_map m = glint::make_normal_map(p);               // or glint::io::read_normal_map
//   glint::bin_map_options o;  o.bins_per_side = 64;               // B = 64^2 half-vector bins
//   auto bins = glint::bin_map<float>::build(m, o);                // host side, may throw glint::error
//   auto A = glint::uv_parallelogram<float>::from_differentials(uv, duvdx, duvdy);   // per pixel
//   auto e = bins.eval(A, h);          // e.pdf: density of normals per solid angle; e.ndf = pdf / h.z
//   auto s = bins.sample(A, u_pos, u_dir);   // s.h with s.pdf == eval(A, s.h).pdf
//
// The model (AKKW Sec. 2; the talk has no numbered equations, so "AKKW E2" names the display in
// its Sec. 2). The NDF of a normal map is D(h, x) = sum_k delta(t_k, h) 1_{T_k}(x) (E1: texel k's
// normal t_k over its square T_k). Averaged over a footprint A and a bin H_j it is
//   D_A^H = 1 / (|H| |A|) sum_k 1_H(t_k) |A n T_k|                                  (AKKW E2)
// glint writes it as a pdf of normals per solid angle, p_A(h) = sum_j c_j K_j(h), with the bin
// coverages c_j = sum_{k in bin j} w_k(A) / sum_k w_k(A) (so sum_j c_j = 1) and a kernel K_j:
// - box (the talk): K_j = 1_{H_j} / |H_j|, so p_A(h) = c_{bin(h)} B / (2 pi);
// - tent: the box density convolved with a box one bin wide in the bins' square coordinates,
//   which is the bilinear interpolation of c_j B between bin centres (clamped at the square's
//   edges); continuous in h, and it keeps every c_j's integral;
// - beckmann (the follow-up, Atanasov et al. 2021, "flake roughness"): K_j is the Beckmann lobe of
//   roughness alpha around bin j's centre, truncated where tan^2 theta > alpha^2 ln(1 / epsilon)
//   and divided by its kept mass 1 - epsilon (the public plugin keeps a fixed 21-bin window and does
//   not renormalise). Mass of lobes that reaches below the horizon is lost (sample() reports it as
//   a failed draw).
// The talk's D is this pdf of normals; the microfacet NDF D(h) (with integral of D cos theta_h = 1,
// the convention of glint/microfacet.hpp and the P-NDF's D_P(s)) is ndf = pdf / cos theta_h.
//
// Bins (AKKW Sec. 2 asks for B bins of equal solid angle 2 pi / B and names no layout): the
// hemisphere is the image of the unit square under Shirley and Chiu's concentric map followed by
// the Lambert (equal-area) map of the disk, z = 1 - r^2, xy = d sqrt(2 - r^2), whose Jacobian is the
// constant 2 pi; the square is cut into n x n cells, so every bin has solid angle exactly 2 pi / n^2
// and a uniform point in a cell is a uniform direction in its bin.
//
// Weights w_k(A) (the coverage rule):
// - exact_area (the talk's |A n T_k|): the area of texel k's square inside A; the normaliser is |A|;
// - texel_center (the public plugin's): 1 where texel k's centre lies in A, else 0; the normaliser
//   is the number of centres in A (one pass over A's rows). Decided per row: A's x-interval at the
//   centre's y, half-open [xa, xb), computed the same way in the count of every bin and in the
//   normaliser, so that the coverages sum to 1 exactly.
// The texture repeats (periodic wrap): A is taken over every tile copy it touches; a copy that
// covers a whole tree node adds the node's count at once (the talk's prefiltering). Beyond
// max_tile_copies copies the coverages are the global histogram (their error is A's partly
// covered tiles over all it covers, measured in docs/bin_map.md). A footprint of zero area is a
// point query (the texel holding its centre gets coverage 1), and so is a texel_center footprint
// that holds no centre; a footprint with a non-finite number gives pdf 0 and no sample.
//
// Data (AKKW Sec. 2.3: "the two N-element integer maps B and B^-1" and a kd forest over B^-1).
// - The inverse bin map: per bin the list of its texels ((y << 12) | x in 3 bytes for sides up
//   to 4096, (y << 16) | x in 4 up to 65536), all lists in one array with an offset per bin (the
//   talk's hash map is not needed: the offsets are dense). Each list is in the preorder of one
//   implicit kd tree over the whole texture, which halves the longer side (child 0 takes
//   floor(side / 2), x on ties), so every node's texels are contiguous in every list: the forest
//   of the talk with all trees sharing their splits, and with no node stored. A walk finds a
//   node's split point from its first and last texels (one child empty: most of a sparse bin's
//   path from the root) or by binary search over their coordinates, and scans a node of at most
//   leaf_size texels.
// - The bin map: per 8 x 8 block of texels a palette of its distinct bins and an index of 0, 1,
//   2, 4 or 8 bits per texel (16- or 32-bit bins where a palette would cost more): about 0.5 bytes
//   per texel on glinty maps instead of 2. A small footprint may visit its texels directly
//   through it (bin_map::direct), skipping the blocks whose palettes hold none of the bins its
//   kernel reads: the same weights as the walks, so the same result up to the order of the sums.
// - Build: the bins, one preorder pass over the texture scattering each texel into its bin's list
//   (a counting sort, stable), and the blocks' palettes: O(texels + bins).
//
// Per-pixel calls (eval, sample, coverage, count) are const, allocation-free, never throw,
// and are safe to call from many threads; they use about 26 KB of stack (the kernel's taps and
// the lobe search's window), none of it on the heap.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "glint/core/error.hpp"
#include "glint/normal_map.hpp"

namespace glint {

enum class bin_kernel { box, tent, beckmann };
enum class coverage_rule { exact_area, texel_center };

struct bin_map_options {
    int bins_per_side = 32;                        // n, B = n^2 bins: [1, 4096]
    bin_kernel kernel = bin_kernel::box;
    double alpha = 0.01;                           // beckmann: flake roughness, [0.0025, 0.5]
    double epsilon = 0.0111;                       // beckmann: mass cut from each lobe's tail, [1e-4, 0.2]
    int leaf_size = 16;                            // L (AKKW Sec. 2.3: 16): lists this short are scanned, [1, 2^20]
    coverage_rule rule = coverage_rule::exact_area;
    int max_tile_copies = 256;                     // [1, 2^20]; beyond: the global histogram
    // Footprints whose bounding box holds at most this many texels visit them directly instead of
    // walking the lists (the same weights, so the same results up to the order of the sums); -1:
    // chosen per query (bin_map::direct), 0: always walk. [-1, 2^30]
    int direct_texels = -1;
};

// A footprint in uv (the texture is [0, 1)^2, repeated): { origin + a e0 + b e1 : a, b in [0, 1) }.
template <class real>
struct uv_parallelogram {
    glm::vec<2, real, glm::defaultp> origin{0}, e0{0}, e1{0};

    // The ray-differential parallelogram of a pixel (as the public plugin: centred on uv, edges
    // duv/dx and duv/dy), with uv reduced modulo 1 so that float keeps its sub-texel bits.
    static uv_parallelogram from_differentials(const glm::vec<2, real, glm::defaultp>& uv, const glm::vec<2, real, glm::defaultp>& duvdx,
                                               const glm::vec<2, real, glm::defaultp>& duvdy) {
        const glm::vec<2, real, glm::defaultp> c = uv - glm::floor(uv);
        return {c - real(0.5) * (duvdx + duvdy), duvdx, duvdy};
    }
    static uv_parallelogram rect(const glm::vec<2, real, glm::defaultp>& lo, const glm::vec<2, real, glm::defaultp>& hi) {
        return {lo, {hi.x - lo.x, real(0)}, {real(0), hi.y - lo.y}};
    }
};

template <class real>
struct bin_eval {
    real pdf = 0;  // density of normals per solid angle (integrates to 1 over the hemisphere, less what a lobe loses below it)
    real ndf = 0;  // the microfacet NDF: pdf / cos theta_h (0 at and below the horizon)
};

template <class real>
struct bin_sample {
    glm::vec<3, real, glm::defaultp> h{0, 0, 1};
    real pdf = 0;  // eval(A, h).pdf
    bool valid = false;
};

struct bin_map_statistics {
    std::size_t texels = 0, bins = 0, nonempty_bins = 0;
    int depth = 0;          // of the implicit tree (levels below the root)
    double build_seconds = 0;
};

template <class real>
class bin_map {
public:
    using vec2 = glm::vec<2, real, glm::defaultp>;
    using vec3 = glm::vec<3, real, glm::defaultp>;

    static constexpr int max_side = 65536;
    static constexpr int max_bins_per_side = 4096;
    static constexpr int stack_size = 40;  // the implicit tree is at most 32 levels deep for 65536^2

    // Throws glint::error when a map of width x height texels cannot be indexed ((y << 16) | x).
    static void check_size(long long width, long long height) {
        if (width < 1 || height < 1) throw error("glint::bin_map: map size " + std::to_string(width) + " x " + std::to_string(height) + " is empty");
        if (width > max_side) throw error("glint::bin_map: width " + std::to_string(width) + " > " + std::to_string(max_side) + " (texels are indexed by 16-bit x and y)");
        if (height > max_side) throw error("glint::bin_map: height " + std::to_string(height) + " > " + std::to_string(max_side) + " (texels are indexed by 16-bit x and y)");
    }

    // Throws glint::error naming the field and value for options outside their domains.
    static void check_options(const bin_map_options& o) {
        const auto bad = [](const std::string& what) { throw error("glint::bin_map: " + what); };
        if (o.bins_per_side < 1 || o.bins_per_side > max_bins_per_side)
            bad("bins_per_side " + std::to_string(o.bins_per_side) + " is outside [1, " + std::to_string(max_bins_per_side) + "]");
        if (o.leaf_size < 1 || o.leaf_size > (1 << 20)) bad("leaf_size " + std::to_string(o.leaf_size) + " is outside [1, 2^20]");
        if (o.max_tile_copies < 1 || o.max_tile_copies > (1 << 20)) bad("max_tile_copies " + std::to_string(o.max_tile_copies) + " is outside [1, 2^20]");
        if (o.direct_texels < -1 || o.direct_texels > (1 << 30)) bad("direct_texels " + std::to_string(o.direct_texels) + " is outside [-1, 2^30]");
        if (o.kernel == bin_kernel::beckmann) {
            if (!(o.alpha >= 0.0025 && o.alpha <= 0.5)) bad("alpha " + std::to_string(o.alpha) + " is outside [0.0025, 0.5]");
            if (!(o.epsilon >= 1e-4 && o.epsilon <= 0.2)) bad("epsilon " + std::to_string(o.epsilon) + " is outside [1e-4, 0.2]");
            // The bins a lobe reaches must fit the query's 64 x 64 window of cells (for_each_lobe).
            const double reach = lobe_reach_cells(o);
            if (reach > 30)
                bad("alpha " + std::to_string(o.alpha) + " spans about " + std::to_string(static_cast<int>(reach)) + " bins at bins_per_side " +
                    std::to_string(o.bins_per_side) + " (at most 30: use fewer bins or a smaller alpha)");
        }
    }

    static bin_map build(const normal_map& map, const bin_map_options& options = {}) {
        const auto t0 = std::chrono::steady_clock::now();
        check_size(map.width(), map.height());
        check_options(options);
        bin_map m;
        m.o_ = options;
        m.n_ = options.bins_per_side;
        m.w_ = map.width(), m.h_ = map.height();
        const std::size_t texels = static_cast<std::size_t>(m.w_) * static_cast<std::size_t>(m.h_);
        const std::size_t bins = static_cast<std::size_t>(m.n_) * static_cast<std::size_t>(m.n_);
        if (options.kernel == bin_kernel::beckmann) {
            const double tan2 = options.alpha * options.alpha * std::log(1 / options.epsilon);
            m.cos_cap_ = 1 / std::sqrt(1 + tan2);
            m.cos_reach_ = std::cos(std::min(std::acos(m.cos_cap_) + cell_radius(m.n_), pi()));
            if (bins <= (std::size_t(1) << 20)) {
                std::vector<glm::dvec3> c(bins);
                for (std::size_t j = 0; j < bins; ++j) c[j] = m.bin_center_d(static_cast<std::uint32_t>(j));
                m.centres_ = std::move(c);
            }
        }

        // Bin of every texel (the normal's, AKKW Sec. 2.1), and the counts per bin.
        std::vector<std::uint32_t> bin(texels);
        std::vector<std::uint32_t> count(bins + 1, 0);
        for (std::size_t k = 0; k < texels; ++k) ++count[(bin[k] = m.bin_of(vec3(map.normals()[k]))) + 1];
        m.compress_bins(bin);
        m.offset_.resize(bins + 1);
        for (std::size_t j = 0; j < bins; ++j) count[j + 1] += count[j];
        for (std::size_t j = 0; j <= bins; ++j) m.offset_[j] = count[j];

        // The texels in the preorder of the implicit tree, each scattered into its bin's list as it
        // comes (a counting sort by bin, stable: each list stays in preorder).
        m.x_bits_ = m.w_ <= 4096 && m.h_ <= 4096 ? 12 : 16;
        m.stride_ = m.x_bits_ == 12 ? 3 : 4;
        m.list_.assign(texels * static_cast<std::size_t>(m.stride_) + 1, 0);  // + 1: entries are read 4 bytes at a time
        {
            region stack[stack_size];
            int depth[stack_size];
            int top = 0;
            stack[top] = {0, 0, m.w_, m.h_}, depth[top++] = 0;
            while (top > 0) {
                --top;
                const region r = stack[top];
                const int d = depth[top];
                if (r.w == 1 && r.h == 1) {
                    const std::uint32_t k = static_cast<std::uint32_t>(r.x) + static_cast<std::uint32_t>(r.y) * static_cast<std::uint32_t>(m.w_);
                    const std::uint32_t packed = (static_cast<std::uint32_t>(r.y) << m.x_bits_) | static_cast<std::uint32_t>(r.x);
                    std::memcpy(&m.list_[static_cast<std::size_t>(count[bin[k]]++) * static_cast<std::size_t>(m.stride_)], &packed,
                                static_cast<std::size_t>(m.stride_));
                    m.stats_.depth = std::max(m.stats_.depth, d);
                    continue;
                }
                region c0, c1;
                split(r, c0, c1);
                stack[top] = c1, depth[top++] = d + 1;
                stack[top] = c0, depth[top++] = d + 1;
            }
        }
        for (std::size_t j = 0; j < bins; ++j) m.stats_.nonempty_bins += m.offset_[j + 1] > m.offset_[j] ? 1u : 0u;
        m.stats_.texels = texels, m.stats_.bins = bins;
        m.stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return m;
    }

    // --- bins ---------------------------------------------------------------------------------

    int bins_per_side() const { return n_; }
    std::uint32_t bin_count() const { return static_cast<std::uint32_t>(n_) * static_cast<std::uint32_t>(n_); }
    real bin_solid_angle() const { return real(2 * pi() / (static_cast<double>(n_) * n_)); }

    // The bin holding direction h (z >= 0; below the horizon it is clamped onto it).
    std::uint32_t bin_of(const vec3& h) const {
        return cell_of(hemisphere_to_square(glm::dvec3(h)));
    }
    vec3 bin_center(std::uint32_t j) const { return vec3(bin_center_d(j)); }

    // The unit square's point q in [0, 1]^2 as a direction (concentric disk, then Lambert's
    // equal-area map: d omega = 2 pi dq), and its inverse.
    static glm::dvec3 square_to_hemisphere(glm::dvec2 q) {
        const double a = 2 * q.x - 1, b = 2 * q.y - 1;
        double r, phi;
        if (a == 0 && b == 0) return {0, 0, 1};
        if (std::fabs(a) > std::fabs(b)) r = a, phi = 0.25 * pi() * (b / a);
        else r = b, phi = 0.5 * pi() - 0.25 * pi() * (a / b);
        const double k = r * std::sqrt(std::max(0.0, 2 - r * r));
        return {k * std::cos(phi), k * std::sin(phi), 1 - r * r};
    }
    static glm::dvec2 hemisphere_to_square(glm::dvec3 h) {
        const double z = std::clamp(h.z, 0.0, 1.0);
        const double r = std::sqrt(1 - z);
        double phi = std::atan2(h.y, h.x);
        if (!(r > 0) || !std::isfinite(phi)) return {0.5, 0.5};
        if (phi < -0.25 * pi()) phi += 2 * pi();
        double a, b;
        if (phi < 0.25 * pi()) a = r, b = phi * 4 / pi() * r;
        else if (phi < 0.75 * pi()) b = r, a = -(phi - 0.5 * pi()) * 4 / pi() * r;
        else if (phi < 1.25 * pi()) a = -r, b = -(phi - pi()) * 4 / pi() * r;
        else b = -r, a = (phi - 1.5 * pi()) * 4 / pi() * r;
        return {std::clamp(0.5 * (a + 1), 0.0, 1.0), std::clamp(0.5 * (b + 1), 0.0, 1.0)};
    }

    // --- the maps -----------------------------------------------------------------------------

    int width() const { return w_; }
    int height() const { return h_; }
    const bin_map_options& options() const { return o_; }
    // The bin of texel (x, y), 0 <= x < width, 0 <= y < height.
    std::uint32_t texel_bin(int x, int y) const {
        const int bx = x >> 3, by = y >> 3;
        return block_bin(&block_data_[block_offset_[static_cast<std::size_t>(bx) + static_cast<std::size_t>(by) * static_cast<std::size_t>(blocks_x_)]],
                         static_cast<unsigned>((x & 7) + 8 * (y & 7)));
    }
    // The bin in slot (x & 7) + 8 (y & 7) of the block at b (compress_bins).
    std::uint32_t block_bin(const std::uint8_t* b, unsigned slot) const {
        const unsigned bits = b[0];
        const std::size_t width = wide_bins() ? 4 : 2;
        const std::uint8_t* at;
        if (bits == 16) {
            at = b + 2 + slot * width;
        } else {
            const std::size_t palette = static_cast<std::size_t>(b[1]) + 1;
            const unsigned pos = slot * bits;
            const unsigned index = bits ? (b[2 + palette * width + (pos >> 3)] >> (pos & 7)) & ((1u << bits) - 1u) : 0u;
            at = b + 2 + index * width;
        }
        return read_bin(at);
    }
    // Texels per bin (the global histogram times the texel count).
    std::uint32_t bin_texels(std::uint32_t j) const { return offset_[j + 1] - offset_[j]; }
    std::size_t memory_bytes() const {
        return block_offset_.size() * 4 + block_data_.size() + list_.size() + offset_.size() * 4 + centres_.size() * sizeof(glm::dvec3);
    }
    const bin_map_statistics& statistics() const { return stats_; }

    // --- coverage ------------------------------------------------------------------------------

    // texel_center: the number of texels of bin j whose centres lie in A (over every tile copy,
    // however many; 0 for a zero-area A). Exact: the tests compare it with a count over every texel.
    std::uint64_t count(const uv_parallelogram<real>& A, std::uint32_t j) const {
        const footprint f = prepare(A);
        if (!f.finite || f.point || j >= bin_count()) return 0;
        return static_cast<std::uint64_t>(bin_weight(f, j, false) + 0.5);
    }

    // c_j under the options' rule: bin j's share of A's weight (coverages sum to 1 over the bins).
    real coverage(const uv_parallelogram<real>& A, std::uint32_t j) const {
        const footprint f = prepare(A);
        if (!f.finite || j >= bin_count()) return 0;
        return static_cast<real>(coverage_of(f, j));
    }

    // --- the filtered NDF ----------------------------------------------------------------------

    bin_eval<real> eval(const uv_parallelogram<real>& A, const vec3& h) const {
        bin_eval<real> out;
        const footprint f = prepare(A);
        if (!f.finite || !(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z))) return out;
        const glm::dvec3 hd = glm::normalize(glm::dvec3(h));
        if (!(hd.z >= 0)) return out;
        const double p = pdf_of(f, hd);
        out.pdf = static_cast<real>(p);
        out.ndf = hd.z > 0 ? static_cast<real>(p / hd.z) : real(0);
        return out;
    }

    // A normal from p_A (AKKW Sec. 2.1): a texel by its weight in A (a uniform point of A under
    // exact_area; a uniform centre in A under texel_center, by u_pos.x), then a direction from its
    // bin's kernel (u_dir). The pdf is eval's, computed in the same call.
    bin_sample<real> sample(const uv_parallelogram<real>& A, const vec2& u_pos, const vec2& u_dir) const {
        bin_sample<real> out;
        const footprint f = prepare(A);
        const auto finite = [](const vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); };
        if (!f.finite || !finite(u_pos) || !finite(u_dir)) return out;
        const std::uint32_t j = sample_texel_bin(f, glm::dvec2(u_pos));
        const int jx = static_cast<int>(j % static_cast<std::uint32_t>(n_)), jy = static_cast<int>(j / static_cast<std::uint32_t>(n_));
        const glm::dvec2 u = glm::clamp(glm::dvec2(u_dir), 0.0, std::nextafter(1.0, 0.0));
        glm::dvec3 h;
        if (o_.kernel == bin_kernel::box) {
            h = square_to_hemisphere((glm::dvec2(jx, jy) + u) / static_cast<double>(n_));
        } else if (o_.kernel == bin_kernel::tent) {
            // In-cell uniform plus a uniform jitter one cell wide is a triangle on [-1/2, 3/2) cells;
            // reflected at the square's edges, as the clamped interpolation is.
            const auto tri = [](double v) { return v < 0.5 ? -0.5 + std::sqrt(2 * v) : 1.5 - std::sqrt(2 * (1 - v)); };
            const auto reflect = [&](double x) {
                if (x < 0) x = -x;
                if (x > n_) x = 2.0 * n_ - x;
                return std::clamp(x, 0.0, static_cast<double>(n_));
            };
            h = square_to_hemisphere(glm::dvec2(reflect(jx + tri(u.x)), reflect(jy + tri(u.y))) / static_cast<double>(n_));
        } else {
            // Beckmann around the bin's centre, truncated at tan^2 = alpha^2 ln(1 / epsilon).
            const double a = o_.alpha, tan2 = -a * a * std::log(1 - u.x * (1 - o_.epsilon));
            const double c = 1 / std::sqrt(1 + tan2), s = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * pi() * u.y;
            const glm::dvec3 n = bin_center_d(j);
            glm::dvec3 t, b;
            basis(n, t, b);
            h = glm::normalize(s * std::cos(phi) * t + s * std::sin(phi) * b + c * n);
            if (!(h.z > 0)) return out;  // the lobe's mass below the horizon: a failed draw
        }
        out.h = vec3(h);
        out.pdf = static_cast<real>(pdf_of(f, h));
        out.valid = out.pdf > 0;
        return out;
    }

private:
    static constexpr std::uint32_t no_bin = 0xffffffffu;
    static constexpr double pi() { return 3.14159265358979323846; }
    struct region {
        int x, y, w, h;
    };

    // Halves the longer side (x on ties); child 0 takes floor(side / 2).
    static void split(const region& r, region& c0, region& c1) {
        if (r.w >= r.h) {
            const int a = r.w / 2;
            c0 = {r.x, r.y, a, r.h}, c1 = {r.x + a, r.y, r.w - a, r.h};
        } else {
            const int a = r.h / 2;
            c0 = {r.x, r.y, r.w, a}, c1 = {r.x, r.y + a, r.w, r.h - a};
        }
    }

    // A footprint in texels, in double: p(a, b) = o + a e0 + b e1; (a, b) = inv (p - o).
    struct footprint {
        glm::dvec2 o{0}, e0{0}, e1{0};
        glm::dvec2 ia{0}, ib{0};  // rows of the inverse: a = dot(ia, p - o), b = dot(ib, p - o)
        double area = 0;
        bool finite = false, point = false;  // point: a point query at the centre texel
        glm::dvec2 lo{0}, hi{0};              // bounding box
        glm::dvec2 unit_a{0}, unit_b{0};      // the ranges of a and b over a unit square, from its corner's
    };

    footprint prepare(const uv_parallelogram<real>& A) const {
        footprint f;
        const glm::dvec2 scale(w_, h_);
        f.o = glm::dvec2(A.origin) * scale, f.e0 = glm::dvec2(A.e0) * scale, f.e1 = glm::dvec2(A.e1) * scale;
        const auto finite = [](glm::dvec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); };
        f.finite = finite(f.o) && finite(f.e0) && finite(f.e1) && std::fabs(f.o.x) < 1e15 && std::fabs(f.o.y) < 1e15 &&
                   glm::length(f.e0) < 1e15 && glm::length(f.e1) < 1e15;
        if (!f.finite) return f;
        // Whole periods move nothing: keep the origin in the first tile for the precision of double.
        f.o -= glm::floor(f.o / scale) * scale;
        const double det = f.e0.x * f.e1.y - f.e0.y * f.e1.x;
        f.area = std::fabs(det);
        f.point = !(f.area > 1e-12 * std::max(1.0, glm::dot(f.e0, f.e0) + glm::dot(f.e1, f.e1)));
        if (!f.point) f.ia = glm::dvec2(f.e1.y, -f.e1.x) / det, f.ib = glm::dvec2(-f.e0.y, f.e0.x) / det;
        f.unit_a = {std::min(0.0, f.ia.x) + std::min(0.0, f.ia.y), std::max(0.0, f.ia.x) + std::max(0.0, f.ia.y)};
        f.unit_b = {std::min(0.0, f.ib.x) + std::min(0.0, f.ib.y), std::max(0.0, f.ib.x) + std::max(0.0, f.ib.y)};
        const glm::dvec2 c[4] = {f.o, f.o + f.e0, f.o + f.e1, f.o + f.e0 + f.e1};
        f.lo = glm::min(glm::min(c[0], c[1]), glm::min(c[2], c[3])), f.hi = glm::max(glm::max(c[0], c[1]), glm::max(c[2], c[3]));
        return f;
    }

    // The bin of the texel at (x, y) wrapped into the map.
    std::uint32_t wrapped_bin(long x, long y) const { return texel_bin(static_cast<int>(((x % w_) + w_) % w_), static_cast<int>(((y % h_) + h_) % h_)); }

    // The bin of the texel holding A's centre (the point query).
    std::uint32_t center_bin(const footprint& f) const {
        const glm::dvec2 c = f.o + 0.5 * (f.e0 + f.e1);
        return wrapped_bin(static_cast<long>(std::floor(c.x)), static_cast<long>(std::floor(c.y)));
    }

    // texel_center's rule: the x-interval [xa, xb) of A at height y (a point is in A when its x
    // is); the same arithmetic for every query of the same footprint.
    static void row_interval(const footprint& f, double y, double& xa, double& xb) {
        xa = -std::numeric_limits<double>::infinity(), xb = std::numeric_limits<double>::infinity();
        const double dy = y - f.o.y;
        const glm::dvec2 rows[2] = {f.ia, f.ib};
        for (const glm::dvec2& r : rows) {
            // 0 <= r.x (x - o.x) + r.y dy < 1
            const double c = r.y * dy;
            if (r.x == 0) {
                if (!(c >= 0 && c < 1)) xa = 1, xb = 0;
                continue;
            }
            double t0 = -c / r.x + f.o.x, t1 = (1 - c) / r.x + f.o.x;
            if (r.x < 0) std::swap(t0, t1);
            xa = std::max(xa, t0), xb = std::min(xb, t1);
        }
    }
    // The first integer x with x + 1/2 >= v (the comparison centre_in makes, so that rounding in
    // v - 1/2 cannot move a centre across the interval's end).
    static double first_centre(double v) {
        double x = std::ceil(v - 0.5);
        while (x - 1 + 0.5 >= v) x -= 1;
        while (x + 0.5 < v) x += 1;
        return x;
    }
    // How many centres x + 1/2 (x an integer) lie in [xa, xb).
    static double centres_in(double xa, double xb) {
        if (!(xb > xa)) return 0;
        return std::max(0.0, first_centre(xb) - first_centre(xa));
    }
    static bool centre_in(const footprint& f, double gx, double gy) {
        double xa, xb;
        row_interval(f, gy + 0.5, xa, xb);
        return gx + 0.5 >= xa && gx + 0.5 < xb;
    }

    // The number of texel centres in A (texel_center's normaliser): one pass over its rows.
    double centre_total(const footprint& f) const {
        double total = 0;
        const double y0 = std::ceil(f.lo.y - 0.5), y1 = std::floor(f.hi.y - 0.5);
        for (double y = y0; y <= y1; y += 1) {
            double xa, xb;
            row_interval(f, y + 0.5, xa, xb);
            total += centres_in(xa, xb);
        }
        return total;
    }

    // Whether a box lies inside A, outside it, or across its boundary (separating axes: the
    // box's, then A's edge normals through (a, b) at the box's corners).
    enum class overlap { outside, inside, boundary };
    static overlap classify(const footprint& f, double x0, double y0, double x1, double y1) {
        if (x1 <= f.lo.x || x0 >= f.hi.x || y1 <= f.lo.y || y0 >= f.hi.y) return overlap::outside;
        const glm::dvec2 d0(x0 - f.o.x, y0 - f.o.y);
        const double a00 = glm::dot(f.ia, d0), b00 = glm::dot(f.ib, d0);
        const double dax = f.ia.x * (x1 - x0), day = f.ia.y * (y1 - y0), dbx = f.ib.x * (x1 - x0), dby = f.ib.y * (y1 - y0);
        const double amin = a00 + std::min(0.0, dax) + std::min(0.0, day), amax = a00 + std::max(0.0, dax) + std::max(0.0, day);
        const double bmin = b00 + std::min(0.0, dbx) + std::min(0.0, dby), bmax = b00 + std::max(0.0, dbx) + std::max(0.0, dby);
        if (amax <= 0 || amin >= 1 || bmax <= 0 || bmin >= 1) return overlap::outside;
        if (amin >= 0 && amax <= 1 && bmin >= 0 && bmax <= 1) return overlap::inside;
        return overlap::boundary;
    }

    // classify for the texel [x, x+1] x [y, y+1]: the same tests with the unit square's ranges
    // of a and b precomputed.
    static overlap classify_texel(const footprint& f, double x, double y) {
        if (x + 1 <= f.lo.x || x >= f.hi.x || y + 1 <= f.lo.y || y >= f.hi.y) return overlap::outside;
        const glm::dvec2 d0(x - f.o.x, y - f.o.y);
        const double a = glm::dot(f.ia, d0), b = glm::dot(f.ib, d0);
        const double amin = a + f.unit_a.x, amax = a + f.unit_a.y, bmin = b + f.unit_b.x, bmax = b + f.unit_b.y;
        if (amax <= 0 || amin >= 1 || bmax <= 0 || bmin >= 1) return overlap::outside;
        if (amin >= 0 && amax <= 1 && bmin >= 0 && bmax <= 1) return overlap::inside;
        return overlap::boundary;
    }
    // The texel's weight under the exact-area rule.
    static double texel_weight(const footprint& f, double x, double y) {
        const overlap c = classify_texel(f, x, y);
        return c == overlap::inside ? 1.0 : c == overlap::outside ? 0.0 : texel_area(f, x, y);
    }

    // The area of { (x, y) in [0, 1]^2 : c + gx x + gy y >= 0 }: with the signs of gx and gy made
    // positive (mirroring the square), b = the larger, s = the smaller / b, the lost part is the
    // integral over x of clamp((-c - s b x) / b, 0, 1), a clamped linear function.
    static double half_plane_area(double c, double gx, double gy) {
        if (gx < 0) c += gx, gx = -gx;
        if (gy < 0) c += gy, gy = -gy;
        const double b = std::max(gx, gy), a = std::min(gx, gy);
        if (!(b > 0)) return c >= 0 ? 1.0 : 0.0;
        const double p = -c / b, slope = a / b;  // the lost part lies below y = p - slope x
        double lost;
        if (slope == 0) {
            lost = std::clamp(p, 0.0, 1.0);
        } else {
            // p - slope x is 1 at x1 and 0 at x0 (x1 < x0); clamp both into [0, 1].
            const double x1 = std::clamp((p - 1) / slope, 0.0, 1.0), x0 = std::clamp(p / slope, 0.0, 1.0);
            lost = x1 + (p * (x0 - x1) - 0.5 * slope * (x0 * x0 - x1 * x1));
        }
        return std::clamp(1 - lost, 0.0, 1.0);
    }

    // |A n [x, x+1] x [y, y+1]|: the texel's square clipped by A's four half-planes
    // (Sutherland-Hodgman) in texel-local coordinates, then the shoelace formula.
    static double texel_area(const footprint& f, double x, double y) {
        const glm::dvec2 d0(x - f.o.x, y - f.o.y);
        const double a0 = glm::dot(f.ia, d0), b0 = glm::dot(f.ib, d0);
        // Half-planes g(p) = c + gx px + gy py >= 0.
        const double planes[4][3] = {{a0, f.ia.x, f.ia.y}, {1 - a0, -f.ia.x, -f.ia.y}, {b0, f.ib.x, f.ib.y}, {1 - b0, -f.ib.x, -f.ib.y}};
        // Most texels on A's boundary meet one of its edges only: the kept part of the square is
        // then a clamped linear integral.
        int cutting = 0, which = 0;
        for (int i = 0; i < 4; ++i)
            if (planes[i][0] + std::min(0.0, planes[i][1]) + std::min(0.0, planes[i][2]) < 0) ++cutting, which = i;
        if (cutting == 1) return half_plane_area(planes[which][0], planes[which][1], planes[which][2]);
        double buf[2][2][12];  // [polygon][x or y][vertex], ping-pong
        const double square[2][4] = {{0, 1, 1, 0}, {0, 0, 1, 1}};
        for (int i = 0; i < 4; ++i) buf[0][0][i] = square[0][i], buf[0][1][i] = square[1][i];
        int count = 4, cur = 0;
        for (const auto& g : planes) {
            // A plane that keeps the whole square (most of them, for a texel on one edge of A) is skipped.
            if (g[0] + std::min(0.0, g[1]) + std::min(0.0, g[2]) >= 0) continue;
            const double* px = buf[cur][0];
            const double* py = buf[cur][1];
            double* qx = buf[1 - cur][0];
            double* qy = buf[1 - cur][1];
            int out = 0;
            for (int i = 0; i < count; ++i) {
                const int k = i + 1 == count ? 0 : i + 1;
                const double vi = g[0] + g[1] * px[i] + g[2] * py[i], vk = g[0] + g[1] * px[k] + g[2] * py[k];
                if (vi >= 0) qx[out] = px[i], qy[out] = py[i], ++out;
                if ((vi >= 0) != (vk >= 0)) {
                    const double t = vi / (vi - vk);
                    qx[out] = px[i] + t * (px[k] - px[i]), qy[out] = py[i] + t * (py[k] - py[i]), ++out;
                }
            }
            count = out, cur = 1 - cur;
            if (count == 0) return 0;
        }
        const double* px = buf[cur][0];
        const double* py = buf[cur][1];
        double s = 0;
        for (int i = 0; i < count; ++i) {
            const int k = i + 1 == count ? 0 : i + 1;
            s += px[i] * py[k] - px[k] * py[i];
        }
        return std::fabs(0.5 * s);
    }

    // The summed weight of bin j's texels in A (exact: areas; centre: counts), over every tile
    // copy A touches.
    double bin_weight(const footprint& f, std::uint32_t j, bool exact) const {
        const std::uint32_t begin = offset_[j], end = offset_[j + 1];
        if (begin == end) return 0;
        const double tx0 = std::floor(f.lo.x / w_), tx1 = std::floor(f.hi.x / w_), ty0 = std::floor(f.lo.y / h_), ty1 = std::floor(f.hi.y / h_);
        double sum = 0;
        for (double ty = ty0; ty <= ty1; ty += 1)
            for (double tx = tx0; tx <= tx1; tx += 1) sum += copy_weight(f, begin, end, tx * w_, ty * h_, exact);
        return sum;
    }

    // The list entry i: its texel's x and y.
    std::uint32_t entry(std::uint32_t i) const {
        std::uint32_t v;
        std::memcpy(&v, &list_[static_cast<std::size_t>(i) * static_cast<std::size_t>(stride_)], 4);
        return stride_ == 3 ? v & 0xffffffu : v;
    }
    std::uint32_t entry_x(std::uint32_t v) const { return v & ((1u << x_bits_) - 1u); }
    std::uint32_t entry_y(std::uint32_t v) const { return v >> x_bits_; }

    // Where child 1's texels start among a node's [begin, end) (its region split at `cut` along x
    // or y): the first texel at or beyond the cut. A node with one empty child (most of a sparse
    // bin's path from the root) is decided by its first and last texels alone.
    std::uint32_t split_point(std::uint32_t begin, std::uint32_t end, bool along_x, std::uint32_t cut) const {
        const auto coord = [&](std::uint32_t i) { const std::uint32_t v = entry(i); return along_x ? entry_x(v) : entry_y(v); };
        if (coord(begin) >= cut) return begin;
        if (coord(end - 1) < cut) return end;
        std::uint32_t lo = begin + 1, hi = end - 1;  // coord(lo - 1) < cut <= coord(hi)
        while (lo < hi) {
            const std::uint32_t m = lo + (hi - lo) / 2;
            if (coord(m) < cut) lo = m + 1;
            else hi = m;
        }
        return lo;
    }

    // One tile copy, whose texel (x, y) sits at (x + ox, y + oy): the walk of bin j's list over the
    // implicit tree; a node of at most leaf_size texels is scanned.
    double copy_weight(const footprint& f, std::uint32_t begin, std::uint32_t end, double ox, double oy, bool exact) const {
        struct item {
            region r;
            std::uint32_t begin, end;
        };
        item stack[stack_size];
        int top = 0;
        const std::uint32_t leaf = static_cast<std::uint32_t>(o_.leaf_size);
        // Down the nodes whose one child holds all of A's bounding box, without the stack or the
        // separating-axis tests.
        item it{{0, 0, w_, h_}, begin, end};
        const double lx = f.lo.x - ox, hx = f.hi.x - ox, ly = f.lo.y - oy, hy = f.hi.y - oy;
        while (it.end - it.begin > leaf) {
            region c0, c1;
            split(it.r, c0, c1);
            const bool along_x = c1.x != c0.x;
            const std::uint32_t cut = static_cast<std::uint32_t>(along_x ? c1.x : c1.y);
            const double lo = along_x ? lx : ly, hi = along_x ? hx : hy;
            if (hi <= cut) it = {c0, it.begin, split_point(it.begin, it.end, along_x, cut)};
            else if (lo >= cut) it = {c1, split_point(it.begin, it.end, along_x, cut), it.end};
            else break;
            if (it.begin == it.end) return 0;
        }
        stack[top++] = it;
        double sum = 0;
        while (top > 0) {
            it = stack[--top];
            const overlap c = classify(f, ox + it.r.x, oy + it.r.y, ox + it.r.x + it.r.w, oy + it.r.y + it.r.h);
            if (c == overlap::outside) continue;
            if (c == overlap::inside) {
                sum += it.end - it.begin;
                continue;
            }
            if (it.end - it.begin <= leaf) {
                for (std::uint32_t i = it.begin; i < it.end; ++i) {
                    const std::uint32_t v = entry(i);
                    const double x = ox + static_cast<double>(entry_x(v)), y = oy + static_cast<double>(entry_y(v));
                    if (exact) {
                        sum += texel_weight(f, x, y);
                    } else {
                        sum += centre_in(f, x, y) ? 1.0 : 0.0;
                    }
                }
                continue;
            }
            region c0, c1;
            split(it.r, c0, c1);
            const bool along_x = c1.x != c0.x;
            const std::uint32_t mid = split_point(it.begin, it.end, along_x, static_cast<std::uint32_t>(along_x ? c1.x : c1.y));
            if (it.end > mid) stack[top++] = {c1, mid, it.end};
            if (mid > it.begin) stack[top++] = {c0, it.begin, mid};
        }
        return sum;
    }

    // Whether A touches more tile copies than max_tile_copies (its coverages are then the global
    // histogram).
    bool beyond_copies(const footprint& f) const {
        const double tx = std::floor(f.hi.x / w_) - std::floor(f.lo.x / w_) + 1, ty = std::floor(f.hi.y / h_) - std::floor(f.lo.y / h_) + 1;
        return tx * ty > o_.max_tile_copies;
    }

    double coverage_of(const footprint& f, std::uint32_t j) const {
        const bool exact = o_.rule == coverage_rule::exact_area;
        if (f.point) return center_bin(f) == j ? 1 : 0;
        if (beyond_copies(f)) return static_cast<double>(bin_texels(j)) / static_cast<double>(stats_.texels);
        const double total = exact ? f.area : centre_total(f);
        if (!(total > 0)) return center_bin(f) == j ? 1 : 0;  // texel_center: no centre in A
        return bin_weight(f, j, exact) / total;
    }

    bool wide_bins() const { return bin_count() > 65536u; }
    // A bin stored at p: 2 bytes, or 4 when there are more than 65536 bins (fixed-size copies, which
    // compile to one load).
    std::uint32_t read_bin(const std::uint8_t* p) const {
        if (wide_bins()) {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }

    // The bin map in blocks of 8 x 8 texels, each a palette of its distinct bins (16 or 32 bits
    // each) and a 0-, 1-, 2-, 4- or 8-bit index per texel, or, with more than 256 distinct bins,
    // the bins themselves: [bits][palette size - 1][palette][indices] (bits = 16: [16][0][64 bins]).
    // Glinty maps have few bins per block (flakes of 8 texels: 2 bits), so about 0.5 bytes per texel
    // instead of 2.
    void compress_bins(const std::vector<std::uint32_t>& bin) {
        blocks_x_ = (w_ + 7) / 8;
        const int blocks_y = (h_ + 7) / 8;
        const std::size_t width = wide_bins() ? 4 : 2;
        block_offset_.assign(static_cast<std::size_t>(blocks_x_) * static_cast<std::size_t>(blocks_y) + 1, 0);
        block_data_.clear();
        block_data_.reserve(block_offset_.size() * 32);
        std::uint32_t slots[64], palette[64];
        const auto put = [&](std::uint32_t v) {
            const std::uint8_t* p = reinterpret_cast<const std::uint8_t*>(&v);
            block_data_.insert(block_data_.end(), p, p + width);  // little-endian
        };
        for (int by = 0; by < blocks_y; ++by)
            for (int bx = 0; bx < blocks_x_; ++bx) {
                block_offset_[static_cast<std::size_t>(bx) + static_cast<std::size_t>(by) * static_cast<std::size_t>(blocks_x_)] =
                    static_cast<std::uint32_t>(block_data_.size());
                // Slots outside the map repeat the block's first texel's bin.
                for (int i = 0; i < 64; ++i) {
                    const int x = std::min(8 * bx + i % 8, w_ - 1), y = std::min(8 * by + i / 8, h_ - 1);
                    const bool inside = 8 * bx + i % 8 < w_ && 8 * by + i / 8 < h_;
                    slots[i] = bin[static_cast<std::size_t>(inside ? x : 8 * bx) + static_cast<std::size_t>(inside ? y : 8 * by) * static_cast<std::size_t>(w_)];
                }
                // The palette in order of first appearance, and each slot's index in it.
                std::uint8_t index[64];
                int distinct = 0;
                for (int i = 0; i < 64; ++i) {
                    int k = 0;
                    while (k < distinct && palette[k] != slots[i]) ++k;
                    if (k == distinct) palette[distinct++] = slots[i];
                    index[i] = static_cast<std::uint8_t>(k);
                }
                const unsigned bits = distinct == 1 ? 0 : distinct == 2 ? 1 : distinct <= 4 ? 2 : distinct <= 16 ? 4 : 8;
                if (distinct * static_cast<int>(width) + 64 >= 64 * static_cast<int>(width)) {  // raw: no dearer than the palette with 8-bit indices
                    block_data_.push_back(16), block_data_.push_back(0);
                    for (const std::uint32_t v : slots) put(v);
                    continue;
                }
                block_data_.push_back(static_cast<std::uint8_t>(bits)), block_data_.push_back(static_cast<std::uint8_t>(distinct - 1));
                for (int i = 0; i < distinct; ++i) put(palette[i]);
                std::uint8_t packed[64] = {};
                for (unsigned i = 0; i < 64 && bits > 0; ++i) {
                    const unsigned pos = i * bits;
                    packed[pos >> 3] = static_cast<std::uint8_t>(packed[pos >> 3] | (static_cast<unsigned>(index[i]) << (pos & 7)));
                }
                block_data_.insert(block_data_.end(), packed, packed + 64 * bits / 8);
            }
        block_offset_.back() = static_cast<std::uint32_t>(block_data_.size());
        block_data_.insert(block_data_.end(), 4, 0);  // bins are read with memcpy of up to 4 bytes
    }

    glm::dvec3 bin_center_d(std::uint32_t j) const {
        if (!centres_.empty()) return centres_[j];
        const std::uint32_t n = static_cast<std::uint32_t>(n_);
        return square_to_hemisphere(glm::dvec2((j % n) + 0.5, (j / n) + 0.5) / static_cast<double>(n_));
    }

    // An angular bound on the distance from a cell's centre to any point of the cell: 2.7 / n rad
    // (2.61 / n measured by sampling the cells' boundaries for n = 1 to 512; tests/unit/test_bin_map.cpp
    // checks it), at most pi.
    static double cell_radius(int n) { return std::min(pi(), 2.7 / n); }
    // How many cells from its bin a lobe's cap (plus one cell radius) may reach: angles map to the
    // square with at most 4 / pi (the concentric map along rings) times sqrt(2) (the Lambert map
    // radially at the horizon) per unit, and a cell is 1 / n wide.
    static double lobe_reach_cells(const bin_map_options& o) {
        const double cap = std::atan(o.alpha * std::sqrt(std::log(1 / o.epsilon)));
        return (cap + cell_radius(o.bins_per_side)) * o.bins_per_side * (4 / pi()) * std::sqrt(2.0) * 0.5 + 1;
    }

    // A tangent frame around n (Duff et al. 2017).
    static void basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
        const double sign = std::copysign(1.0, n.z), a = -1 / (sign + n.z), c = n.x * n.y * a;
        t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
        b = {c, sign + n.y * n.y * a, -n.y};
    }

    // The truncated, renormalised Beckmann lobe around m, per solid angle, at h.
    double lobe(const glm::dvec3& m, const glm::dvec3& h) const {
        const double c = glm::dot(m, h);
        if (!(c >= cos_cap_)) return 0;
        const double a2 = o_.alpha * o_.alpha, c2 = c * c, tan2 = (1 - c2) / c2;
        return std::exp(-tan2 / a2) / (pi() * a2 * c2 * c) / (1 - o_.epsilon);
    }

    // Whether visiting the texels under A's bounding box costs less than the kernel's walks of
    // the lists (a few hundred ns each): with direct_texels >= 0, when the box holds at most that
    // many texels; by default, when it holds at most 256 per walk (4 blocks of the bin map, whose
    // palettes let the visit skip the blocks without the kernel's bins) and the texels likely to
    // be visited, the box's times the share of blocks that may hold those bins (at most 64 times
    // their share of the map's texels), are at most 32 per walk. `share`: the kernel's bins'
    // share of the map's texels (beckmann: direct_lobes). The constants are the crossovers of
    // bench/report_bin_map.cpp's timings on flakes and scratched metal.
    bool direct(const footprint& f, double share, int walks) const {
        if (f.point || beyond_copies(f)) return false;
        const double box = (std::floor(f.hi.x) - std::floor(f.lo.x) + 1) * (std::floor(f.hi.y) - std::floor(f.lo.y) + 1);
        if (o_.direct_texels >= 0) return box <= o_.direct_texels;
        return box <= 256.0 * walks && box * std::min(1.0, 64 * share) <= 32.0 * walks;
    }

    // The normaliser of the coverages: |A|, or the number of texel centres in A.
    double normaliser(const footprint& f) const { return o_.rule == coverage_rule::exact_area ? f.area : centre_total(f); }

    // The sum over the texels under A's bounding box of their weight in A times factor(their
    // bin) (factor >= 0): the same weights as the walks (only the order of the sums differs).
    // Blocks of the bin map whose palettes hold no bin of nonzero factor are skipped. Gives up
    // (returns -1) after visiting `budget` texels of relevant blocks.
    template <class Factor>
    double texel_sum(const footprint& f, Factor&& factor, double budget = 1e300) const {
        return texel_sum(f, factor, [&](std::uint32_t b) { return factor(b) != 0; }, budget);
    }
    // The same, with a cheaper test of whether factor(b) != 0 for the blocks' palettes.
    template <class Factor, class Nonzero>
    double texel_sum(const footprint& f, Factor&& factor, Nonzero&& nonzero, double budget) const {
        const bool exact = o_.rule == coverage_rule::exact_area;
        const std::size_t width = wide_bins() ? 4 : 2;
        const auto relevant = [&](const std::uint8_t* b) {
            if (b[0] == 16) return true;
            for (int i = 0; i <= b[1]; ++i)
                if (nonzero(read_bin(b + 2 + static_cast<std::size_t>(i) * width))) return true;
            return false;
        };
        double sum = 0;
        const long x0 = static_cast<long>(std::floor(f.lo.x)), x1 = static_cast<long>(std::floor(f.hi.x));
        const long y0 = static_cast<long>(std::floor(f.lo.y)), y1 = static_cast<long>(std::floor(f.hi.y));
        const auto wrap = [](long v, int period) { return static_cast<int>(((v % period) + period) % period); };
        // Block by block (a block's texels in one tile copy: rows ya..yb, columns xa..xb, global;
        // wy and wx where they lie in the map).
        const int wx0 = wrap(x0, w_);
        int wy = wrap(y0, h_);
        for (long ya = y0; ya <= y1;) {
            const long yb = std::min(y1, ya + (std::min(wy | 7, h_ - 1) - wy));
            int wx = wx0;
            for (long xa = x0; xa <= x1;) {
                const long xb = std::min(x1, xa + (std::min(wx | 7, w_ - 1) - wx));
                const double gx0 = static_cast<double>(xa), gy0 = static_cast<double>(ya);
                const overlap cb = classify(f, gx0, gy0, static_cast<double>(xb + 1), static_cast<double>(yb + 1));
                const std::size_t block = static_cast<std::size_t>(wx >> 3) + static_cast<std::size_t>(wy >> 3) * static_cast<std::size_t>(blocks_x_);
                const std::uint8_t* data = &block_data_[block_offset_[block]];
                if (cb != overlap::outside && relevant(data)) {
                    budget -= static_cast<double>((yb - ya + 1) * (xb - xa + 1));
                    if (budget < 0) return -1;
                    for (long y = ya; y <= yb; ++y)
                        for (long x = xa; x <= xb; ++x) {
                            const double k = factor(block_bin(data, static_cast<unsigned>(((wx + static_cast<int>(x - xa)) & 7) + 8 * ((wy + static_cast<int>(y - ya)) & 7))));
                            if (k == 0) continue;
                            const double gx = static_cast<double>(x), gy = static_cast<double>(y);
                            if (exact) {
                                sum += k * (cb == overlap::inside ? 1.0 : texel_weight(f, gx, gy));
                            } else if (centre_in(f, gx, gy)) {
                                sum += k;
                            }
                        }
                }
                wx += static_cast<int>(xb - xa + 1), xa = xb + 1;
                if (wx == w_) wx = 0;
            }
            wy += static_cast<int>(yb - ya + 1), ya = yb + 1;
            if (wy == h_) wy = 0;
        }
        return sum;
    }

    // Whether the beckmann kernel tries the texel visit first: its walks are many (one per bin of
    // the cap that holds texels) and its bins unknown before the cap's flood fill, so the visit is
    // tried on boxes of up to 1024 texels, and up to 16384 (256 blocks' palettes) unless the 3 x 3
    // bins around h hold 5% of the map (a flat map's pole: every block would count), with a
    // budget of 1024 texels; direct_texels >= 0 decides as for the other kernels.
    bool direct_lobes(const footprint& f, const glm::dvec2& q) const {
        if (o_.direct_texels >= 0 || f.point || beyond_copies(f)) return direct(f, 1, 1);
        const double box = (std::floor(f.hi.x) - std::floor(f.lo.x) + 1) * (std::floor(f.hi.y) - std::floor(f.lo.y) + 1);
        return box <= 1024 || (box <= 16384 && cells_share(q) < 0.05);
    }

    // The share of the map's texels in the 3 x 3 bins around q's.
    double cells_share(const glm::dvec2& q) const {
        const std::uint32_t c = cell_of(q), n = static_cast<std::uint32_t>(n_);
        const int cx = static_cast<int>(c % n), cy = static_cast<int>(c / n);
        double texels = 0;
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, n_ - 1); ++y)
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, n_ - 1); ++x) texels += bin_texels(static_cast<std::uint32_t>(x + y * n_));
        return texels / static_cast<double>(stats_.texels);
    }

    // The bin cell holding the square's point q.
    std::uint32_t cell_of(const glm::dvec2& q) const {
        const int ix = std::clamp(static_cast<int>(q.x * n_), 0, n_ - 1), iy = std::clamp(static_cast<int>(q.y * n_), 0, n_ - 1);
        return static_cast<std::uint32_t>(ix) + static_cast<std::uint32_t>(iy) * static_cast<std::uint32_t>(n_);
    }

    // The tent's bilinear taps at q: the (up to 4) distinct cells between whose centres q lies,
    // clamped at the square's edges, with their weights (taps that clamp to one cell merged).
    int tent_taps(const glm::dvec2& q, std::uint32_t* bins, double* weights) const {
        const double gx = q.x * n_ - 0.5, gy = q.y * n_ - 0.5;
        const double fx = std::floor(gx), fy = std::floor(gy), tx = gx - fx, ty = gy - fy;
        const int xs[2] = {std::clamp(static_cast<int>(fx), 0, n_ - 1), std::clamp(static_cast<int>(fx) + 1, 0, n_ - 1)};
        const int ys[2] = {std::clamp(static_cast<int>(fy), 0, n_ - 1), std::clamp(static_cast<int>(fy) + 1, 0, n_ - 1)};
        const double wx[2] = {1 - tx, tx}, wy[2] = {1 - ty, ty};
        int taps = 0;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const std::uint32_t b = static_cast<std::uint32_t>(xs[i] + ys[j] * n_);
                int k = 0;
                while (k < taps && bins[k] != b) ++k;
                if (k == taps) bins[taps] = b, weights[taps++] = 0;
                weights[k] += wx[i] * wy[j];
            }
        return taps;
    }

    // Calls fn(bin, lobe at h) for every bin of the beckmann kernel whose centre lies in the cap
    // of h and which holds texels: a flood fill over the cells from h's own, which a cell joins
    // while its centre is within the cap plus one cell radius (the cells along the great circle
    // from h to any centre in the cap do), in a 64 x 64 window (check_options bounds the reach by
    // 30 cells).
    template <class Fn>
    void for_each_lobe(const glm::dvec3& h, const glm::dvec2& q, Fn&& fn) const {
        const std::uint32_t jh = cell_of(q);
        const int hx = static_cast<int>(jh % static_cast<std::uint32_t>(n_)), hy = static_cast<int>(jh / static_cast<std::uint32_t>(n_));
        std::uint64_t seen[64] = {};
        std::uint16_t stack[64 * 64];
        int top = 0;
        const auto visit = [&](int x, int y) {
            if (x < 0 || y < 0 || x >= n_ || y >= n_) return;
            const int lx = x - hx + 32, ly = y - hy + 32;
            if (lx < 0 || ly < 0 || lx >= 64 || ly >= 64) return;
            if (seen[ly] >> lx & 1u) return;
            seen[ly] |= std::uint64_t(1) << lx;
            stack[top++] = static_cast<std::uint16_t>(lx + 64 * ly);
        };
        visit(hx, hy);
        while (top > 0) {
            const int l = stack[--top];
            const int x = l % 64 + hx - 32, y = l / 64 + hy - 32;
            const std::uint32_t j = static_cast<std::uint32_t>(x + y * n_);
            const glm::dvec3 m = bin_center_d(j);
            const double c = glm::dot(m, h);
            if (!(c >= cos_reach_)) continue;
            if (c >= cos_cap_ && bin_texels(j) > 0) {
                const double k = lobe(m, h);
                if (k > 0) fn(j, k);
            }
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) visit(x + dx, y + dy);
        }
    }

    // A bin the kernel reads at h, with the kernel's value there for coverage 1 (per solid angle).
    struct tap {
        std::uint32_t bin;
        double weight;
    };
    static constexpr int max_taps = 1024;

    // The kernel's taps at h over bins that hold texels; -1 when there are more than max_taps
    // (beckmann caps over many bins).
    int kernel_taps(const glm::dvec3& h, const glm::dvec2& q, tap* taps) const {
        const double density = static_cast<double>(bin_count()) / (2 * pi());  // of a bin with coverage 1
        int count = 0;
        if (o_.kernel == bin_kernel::box) {
            const std::uint32_t b = cell_of(q);
            if (bin_texels(b) > 0) taps[count++] = {b, density};
        } else if (o_.kernel == bin_kernel::tent) {
            std::uint32_t bins[4];
            double weights[4];
            const int n = tent_taps(q, bins, weights);
            for (int i = 0; i < n; ++i)
                if (bin_texels(bins[i]) > 0) taps[count++] = {bins[i], weights[i] * density};
        } else {
            for_each_lobe(h, q, [&](std::uint32_t b, double k) {
                if (count >= 0 && count < max_taps) taps[count++] = {b, k};
                else count = -1;
            });
        }
        return count;
    }

    // p_A(h) = sum over the kernel's taps of weight x coverage: the bins a small footprint holds
    // visited directly, dense bins (more than 1 / 1024 of the map's texels: a flat map's pole)
    // walked, and the others visited where that is cheaper (direct), else walked.
    double pdf_of(const footprint& f, const glm::dvec3& h) const {
        const glm::dvec2 q = hemisphere_to_square(h);
        const bool plain = !f.point && !beyond_copies(f);
        const double total = plain ? normaliser(f) : 0;
        if (o_.kernel == bin_kernel::beckmann && plain && total > 0 && direct_lobes(f, q)) {
            // The lobes of the bins under A only (the cap's other bins may be many), each once per
            // run of texels in its bin; given up after 1024 texels of relevant blocks.
            const std::uint32_t jh = cell_of(q), n = static_cast<std::uint32_t>(n_);
            const int hx = static_cast<int>(jh % n), hy = static_cast<int>(jh / n);
            std::uint32_t last = no_bin;
            double last_k = 0;
            // Bins farther than the lobe's reach (check_options: 30 cells) cannot hold h.
            const auto near = [&](std::uint32_t b) { return std::abs(static_cast<int>(b % n) - hx) <= 31 && std::abs(static_cast<int>(b / n) - hy) <= 31; };
            const double s = texel_sum(
                f,
                [&](std::uint32_t b) {
                    if (b != last) last = b, last_k = near(b) ? lobe(bin_center_d(b), h) : 0.0;
                    return last_k;
                },
                [&](std::uint32_t b) { return near(b) && glm::dot(bin_center_d(b), h) >= cos_cap_; }, o_.direct_texels >= 0 ? 1e300 : 1024);
            if (s >= 0) return s / total;
        }
        tap taps[max_taps];
        const int count = kernel_taps(h, q, taps);
        double sum = 0;
        if (count < 0 || !plain || !(total > 0)) {
            // A point, beyond the tile copies, texel_center with no centre in A, or a cap over more
            // than max_taps bins: coverage_of's cases, tap by tap.
            if (count < 0) for_each_lobe(h, q, [&](std::uint32_t b, double k) { sum += k * coverage_of(f, b); });
            for (int i = 0; i < count; ++i) sum += taps[i].weight * coverage_of(f, taps[i].bin);
            return sum;
        }
        const double texels = static_cast<double>(stats_.texels);
        const tap* dense = std::partition(taps, taps + count, [&](const tap& t) { return bin_texels(t.bin) <= texels / 1024; });
        const int sparse = static_cast<int>(dense - taps);
        double share = 0;
        for (int i = 0; i < sparse; ++i) share += static_cast<double>(bin_texels(taps[i].bin)) / texels;
        int walked = 0;
        if (sparse > 0 && direct(f, share, sparse)) {
            std::sort(taps, taps + sparse, [](const tap& a, const tap& b) { return a.bin < b.bin; });
            sum += texel_sum(f, [&](std::uint32_t b) {
                if (sparse <= 4) {
                    for (int i = 0; i < sparse; ++i)
                        if (taps[i].bin == b) return taps[i].weight;
                    return 0.0;
                }
                const tap* t = std::lower_bound(taps, taps + sparse, b, [](const tap& a, std::uint32_t v) { return a.bin < v; });
                return t != taps + sparse && t->bin == b ? t->weight : 0.0;
            });
            walked = sparse;
        }
        const bool exact = o_.rule == coverage_rule::exact_area;
        for (int i = walked; i < count; ++i) sum += taps[i].weight * bin_weight(f, taps[i].bin, exact);
        return sum / total;
    }

    // The bin of a texel drawn by its weight in A (u in [0, 1)^2).
    std::uint32_t sample_texel_bin(const footprint& f, glm::dvec2 u) const {
        u = glm::clamp(u, 0.0, std::nextafter(1.0, 0.0));
        if (f.point) return center_bin(f);
        if (beyond_copies(f))  // the global histogram: a uniform texel of the map
            return texel_bin(std::min(static_cast<int>(u.x * w_), w_ - 1), std::min(static_cast<int>(u.y * h_), h_ - 1));
        if (o_.rule == coverage_rule::exact_area) {
            const glm::dvec2 p = f.o + u.x * f.e0 + u.y * f.e1;
            return wrapped_bin(static_cast<long>(std::floor(p.x)), static_cast<long>(std::floor(p.y)));
        }
        // texel_center: the k-th centre in A, k uniform, counting row by row as centre_total does.
        const double total = centre_total(f);
        if (!(total > 0)) return center_bin(f);
        double k = std::floor(u.x * total);
        const double y0 = std::ceil(f.lo.y - 0.5), y1 = std::floor(f.hi.y - 0.5);
        for (double y = y0; y <= y1; y += 1) {
            double xa, xb;
            row_interval(f, y + 0.5, xa, xb);
            const double c = centres_in(xa, xb);
            if (k < c) {
                return wrapped_bin(static_cast<long>(first_centre(xa) + k), static_cast<long>(y));
            }
            k -= c;
        }
        return center_bin(f);  // not reached: k < total
    }

    bin_map_options o_;
    int n_ = 1, w_ = 0, h_ = 0;
    double cos_cap_ = 1, cos_reach_ = 1;
    int blocks_x_ = 0;
    std::vector<std::uint32_t> block_offset_;  // the bin map (compress_bins): blocks of 8 x 8 texels
    std::vector<std::uint8_t> block_data_;
    int x_bits_ = 16, stride_ = 4;      // list entries: (y << x_bits) | x in 3 bytes (sides <= 4096) or 4
    std::vector<std::uint8_t> list_;   // the inverse bin map: every bin's texels, bin after bin, each list in preorder
    std::vector<std::uint32_t> offset_;  // bin j's texels: entries offset_[j] to offset_[j + 1]
    std::vector<glm::dvec3> centres_;  // beckmann with B <= 2^20: the bins' centres, read by every lobe
    bin_map_statistics stats_;
};

}  // namespace glint
