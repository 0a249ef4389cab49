// Reproduces glint_binomial_band_fit_scaled (kernels/binomial.glsl): the mean-preserving sampler's
// middle for N >= 32 and lambda = N p_near from 2^-7 to 17, in closed form. There the far bound
// N - 2 removes less than 1e-8 of the middle's mean, and the middle is the one-sided fit: the
// (t, sigma) that give sigma max(t + Z, 0) the mean m and variance v of n - 1 on
// {1 <= n <= N - 1} (glint/binomial.hpp, steps 1 and 2). Both depend smoothly on
// x = log2(lambda) and q = 32 / N in (0, 1] (q -> 0 is the Poisson limit), so the kernel reads
// them from polynomials in (x, q) instead of evaluating the ends (a log1p and an exp), m and v,
// and the fit (a log and an exp): a log2, a division and a sqrt.
//
// What is fitted: the Gaussian's centre sigma t and its scale sigma, both over sqrt(lambda) (the
// centre, not t, because where the clamp is far below the mean t is ill-conditioned while the
// centre is the mean itself). Where N = 32 and lambda > 16 the grid reaches p_near > 1/2, outside
// the sampler's domain; the targets there are those of the same formulas counted from n = 0, a
// smooth extension. Two pieces in x, [-7, 0] and [0, log2 17], each interpolated at the
// Chebyshev-Gauss nodes of degrees (8, 3) and (12, 5) in (x, q), then written in powers of the
// pieces' standardized variables, rounded to float.
//
// It measures, on a sweep of 401 x 81 points over both pieces (double arithmetic, float
// coefficients): the largest errors of the centre (in sigmas) and sigma (relative), and of the clamped
// offset's mean and variance against m and v (relative; glint_capped_offset_moments, whose own
// normal CDF is good to 1.2e-7), and prints them to stderr.
//   glint_fit_binomial_band            prints the kernel's function (stdout) and the errors (stderr)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glint/binomial.hpp>

#include "binomial_fit.hpp"

namespace {

using K = glint::detail::glsl::kernels<double>;

const double x_top = std::log2(17.0);

// The ends counted from n = 0 for any p (for p <= 1/2 the sampler's own, in double).
K::glint_binomial_ends ends_from_zero(double N, double p) {
    K::glint_binomial_ends e;
    e.lower = 1;
    e.all_negative = std::exp(N * std::log1p(-p));
    e.all_positive = std::exp(N * std::log(p));
    e.any_near = -std::expm1(N * std::log1p(-p));
    return e;
}

// What the polynomials give, from the centre sigma t and sigma: ((sigma t - (lambda - 1)) / sqrt(lambda),
// sigma / sqrt(lambda (1 - p))), both of order 1 and, from lambda = 2 on, close to 0 and 1.
glm::dvec2 scaled(double centre, double sigma, double lambda, double p) {
    return {(centre - (lambda - 1)) / std::sqrt(lambda), sigma / std::sqrt(lambda * (1 - p))};
}
glm::dvec2 unscaled(glm::dvec2 f, double lambda, double p) {  // (centre, sigma)
    return {lambda - 1 + f.x * std::sqrt(lambda), f.y * std::sqrt(lambda * (1 - p))};
}

// The scaled exact one-sided fit at (x, q).
glm::dvec2 exact(double x, double q) {
    const double lambda = std::exp2(x), N = 32 / q, p = lambda / N;
    const auto g = K::glint_binomial_middle_targets(N, p, ends_from_zero(N, p));
    const glm::dvec2 f = glint_bench::one_sided_exact(g.mean, g.variance);
    return scaled(f.x * f.y, f.y, lambda, p);
}

struct piece {
    double x0, x1;
    int dx, dq;
    // coefficient[k][j]: of s^j r^k, s = (x - centre) / half, r = 2 q - 1, as (centre, sigma)
    std::vector<std::vector<glm::dvec2>> coefficient;
    double centre() const { return (x0 + x1) / 2; }
    double half() const { return (x1 - x0) / 2; }
};

// The power-series coefficients of the Chebyshev polynomials T_0 .. T_n.
std::vector<std::vector<double>> chebyshev_powers(int n) {
    std::vector<std::vector<double>> T(static_cast<std::size_t>(n) + 1, std::vector<double>(static_cast<std::size_t>(n) + 1, 0.0));
    T[0][0] = 1;
    if (n >= 1) T[1][1] = 1;
    for (std::size_t j = 2; j <= static_cast<std::size_t>(n); ++j)
        for (std::size_t m = 0; m <= static_cast<std::size_t>(n); ++m) T[j][m] = (m > 0 ? 2 * T[j - 1][m - 1] : 0) - T[j - 2][m];
    return T;
}

void fit(piece& pc) {
    const int nx = pc.dx + 1, nq = pc.dq + 1;
    auto node = [](int i, int n) { return std::cos(M_PI * (i + 0.5) / n); };
    std::vector<glm::dvec2> f(static_cast<std::size_t>(nx * nq));
    for (int i = 0; i < nx; ++i)
        for (int l = 0; l < nq; ++l) f[static_cast<std::size_t>(i * nq + l)] = exact(pc.centre() + pc.half() * node(i, nx), 0.5 + 0.5 * node(l, nq));
    // Chebyshev coefficients by the discrete cosine transform on the nodes.
    std::vector<std::vector<glm::dvec2>> c(static_cast<std::size_t>(nq), std::vector<glm::dvec2>(static_cast<std::size_t>(nx), glm::dvec2(0)));
    for (int j = 0; j < nx; ++j)
        for (int k = 0; k < nq; ++k) {
            glm::dvec2 a(0);
            for (int i = 0; i < nx; ++i)
                for (int l = 0; l < nq; ++l)
                    a += f[static_cast<std::size_t>(i * nq + l)] * std::cos(j * M_PI * (i + 0.5) / nx) * std::cos(k * M_PI * (l + 0.5) / nq);
            a *= (j == 0 ? 1.0 : 2.0) / nx * (k == 0 ? 1.0 : 2.0) / nq;
            c[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] = a;
        }
    // In powers of s and r.
    const auto Tx = chebyshev_powers(pc.dx), Tq = chebyshev_powers(pc.dq);
    pc.coefficient.assign(static_cast<std::size_t>(nq), std::vector<glm::dvec2>(static_cast<std::size_t>(nx), glm::dvec2(0)));
    for (std::size_t k = 0; k < static_cast<std::size_t>(nq); ++k)
        for (std::size_t j = 0; j < static_cast<std::size_t>(nx); ++j)
            for (std::size_t b = 0; b <= k; ++b)
                for (std::size_t a = 0; a <= j; ++a) pc.coefficient[b][a] += c[k][j] * Tq[k][b] * Tx[j][a];
    for (auto& row : pc.coefficient)
        for (auto& v : row) v = glm::dvec2(static_cast<double>(static_cast<float>(v.x)), static_cast<double>(static_cast<float>(v.y)));
}

// The kernel's evaluation (Horner in s per power of r, then in r), in double.
glm::dvec2 evaluate(const piece& pc, double x, double q) {
    const double s = (x - pc.centre()) / pc.half(), r = 2 * q - 1;
    glm::dvec2 sum(0);
    for (std::size_t k = pc.coefficient.size(); k-- > 0;) {
        glm::dvec2 row(0);
        for (std::size_t j = pc.coefficient[k].size(); j-- > 0;) row = row * s + pc.coefficient[k][j];
        sum = sum * r + row;
    }
    return sum;
}

// Prints one piece's evaluation; the last piece unconditioned.
void print(const piece& pc, const char* condition) {
    const bool last = condition[0] == 0;
    const char* in = last ? "    " : "        ";
    if (!last) std::printf("    %s {\n", condition);
    std::printf("%sreal s = (x - real(%.17g)) * real(%.17g);\n", in, pc.centre(), 1 / pc.half());
    for (std::size_t k = 0; k < pc.coefficient.size(); ++k) {
        const auto& row = pc.coefficient[k];
        std::printf("%svec2 r%zu = vec2(real(%.9g), real(%.9g));\n", in, k, row.back().x, row.back().y);
        for (std::size_t j = row.size() - 1; j-- > 0;) std::printf("%sr%zu = vec2(real(%.9g), real(%.9g)) + s * r%zu;\n", in, k, row[j].x, row[j].y, k);
    }
    std::string sum = "r" + std::to_string(pc.coefficient.size() - 1);
    for (std::size_t k = pc.coefficient.size() - 1; k-- > 0;) sum = "r" + std::to_string(k) + " + r * (" + sum + ")";
    std::printf("%sreturn %s;\n", in, sum.c_str());
    if (!last) std::printf("    }\n");
}

}  // namespace

int main() {
    std::vector<piece> pieces = {{-7, -3.5, 6, 2, {}}, {-3.5, 0, 6, 2, {}}, {0, 2, 6, 2, {}}, {2, x_top, 7, 2, {}}};
    for (piece& pc : pieces) fit(pc);
    auto piece_of = [&](double x) -> const piece& {
        for (const piece& pc : pieces)
            if (x < pc.x1) return pc;
        return pieces.back();
    };
    std::printf("// generated: GLINT_BINOMIAL_BAND_FIT by bench/fit_binomial_band.cpp\n");
    std::printf("GLINT_FN vec2 glint_binomial_band_fit_scaled(real x, real q) {\n");
    std::printf("    real r = real(2) * q - real(1);\n");
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        char condition[64];
        std::snprintf(condition, sizeof condition, i + 1 < pieces.size() ? "if (x < real(%.17g))" : "", pieces[i].x1);
        print(pieces[i], condition);
    }
    std::printf("}\n// end of generated code\n");
    double e_centre = 0, e_sigma = 0, e_mean = 0, e_variance = 0;
    for (int a = 0; a <= 400; ++a)
        for (int b = 0; b <= 80; ++b) {
            const double x = -7 + (x_top + 7) * a / 400, q = std::fmax(b / 80.0, 1e-9);
            const double lambda = std::exp2(x), N = 32 / q, p = lambda / N;
            if (p > 0.5) continue;  // outside the sampler's domain
            const glm::dvec2 fitted = unscaled(evaluate(piece_of(x), x, q), lambda, p), want = unscaled(exact(x, q), lambda, p);
            e_centre = std::fmax(e_centre, std::fabs(fitted.x - want.x) / want.y);
            e_sigma = std::fmax(e_sigma, std::fabs(fitted.y / want.y - 1));
            const auto g = K::glint_binomial_middle_targets(N, p, K::glint_binomial_unbiased_ends_evaluated(N, p, K::GLINT_POW_LOG1P));
            const auto m = K::glint_capped_offset_moments(fitted.x / fitted.y, fitted.y, N - 2);
            e_mean = std::fmax(e_mean, std::fabs(m.mean / g.mean - 1));
            e_variance = std::fmax(e_variance, std::fabs((m.square_mean - m.mean * m.mean) / g.variance - 1));
        }
    std::fprintf(stderr, "largest errors: centre %.2e (in sigmas), sigma %.2e (relative); the offset's mean %.2e, variance %.2e\n", e_centre, e_sigma,
                 e_mean, e_variance);
    return 0;
}
