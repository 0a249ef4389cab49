// Reproduces the polynomial fits in glint_clamped_gaussian_t (kernels/binomial.glsl): the
// inverse t(y) of y(t) = log(chi(t) / psi(t)^2 - 1), where psi(t) = E[max(t + Z, 0)] and
// chi(t) = E[max(t + Z, 0)^2] for a standard normal Z. Least squares on 2000 Chebyshev nodes in
// double, with t(y) found by bisection; prints the coefficients and the maximum error in t.
//   glint_fit_clamped_gaussian
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <vector>

namespace {

double cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }
double pdf(double t) { return std::exp(-t * t / 2) / std::sqrt(2 * M_PI); }
double psi(double t) { return t * cdf(t) + pdf(t); }
double chi(double t) { return (t * t + 1) * cdf(t) + t * pdf(t); }
double y_of_t(double t) { return std::log(chi(t) / (psi(t) * psi(t)) - 1); }
double t_of_y(double y) {
    double lo = -9, hi = 9;
    for (int i = 0; i < 200; ++i) {
        const double mid = (lo + hi) / 2;
        (y_of_t(mid) > y ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Coefficients c_k of sum c_k s^k, s = (x - center) / half, fitted to g on [a, b].
std::vector<double> fit(const std::function<double(double)>& g, double a, double b, int degree) {
    const int nodes = 2000, n = degree + 1;
    const double center = (a + b) / 2, half = (b - a) / 2;
    std::vector<std::vector<double>> m(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(n) + 1, 0.0));
    for (int i = 0; i < nodes; ++i) {
        const double s = -std::cos(M_PI * (i + 0.5) / nodes), value = g(center + half * s);
        std::vector<double> power(static_cast<std::size_t>(n), 1.0);
        for (int k = 1; k < n; ++k) power[static_cast<std::size_t>(k)] = power[static_cast<std::size_t>(k - 1)] * s;
        for (int r = 0; r < n; ++r) {
            for (int k = 0; k < n; ++k) m[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] += power[static_cast<std::size_t>(r)] * power[static_cast<std::size_t>(k)];
            m[static_cast<std::size_t>(r)][static_cast<std::size_t>(n)] += power[static_cast<std::size_t>(r)] * value;
        }
    }
    for (int i = 0; i < n; ++i) {  // Gauss-Jordan with partial pivoting
        int pivot = i;
        for (int r = i + 1; r < n; ++r)
            if (std::fabs(m[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]) > std::fabs(m[static_cast<std::size_t>(pivot)][static_cast<std::size_t>(i)])) pivot = r;
        std::swap(m[static_cast<std::size_t>(i)], m[static_cast<std::size_t>(pivot)]);
        for (int r = 0; r < n; ++r) {
            if (r == i) continue;
            const double f = m[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)] / m[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)];
            for (int k = i; k <= n; ++k) m[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] -= f * m[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
        }
    }
    std::vector<double> c(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) c[static_cast<std::size_t>(i)] = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(n)] / m[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)];
    return c;
}

double horner(const std::vector<double>& c, double s) {
    double r = 0;
    for (std::size_t k = c.size(); k-- > 0;) r = r * s + c[k];
    return r;
}

void report(const char* name, const std::vector<double>& c, double center, double half, double max_error) {
    std::printf("%s: s = (x - %.17g) / %.17g, max |t error| %.2e\n  coefficients (s^0 first):", name, center, half, max_error);
    for (double v : c) std::printf(" %.17g", v);
    std::printf("\n");
}

}  // namespace

int main() {
    // Piece 1: y in [-2.2, 7.3], polynomial in y.
    const double a1 = -2.2, b1 = 7.3;
    auto c1 = fit(t_of_y, a1, b1, 8);
    double e1 = 0;
    for (double y = a1; y <= b1; y += 1e-3) e1 = std::max(e1, std::fabs(horner(c1, (y - (a1 + b1) / 2) / ((b1 - a1) / 2)) - t_of_y(y)));
    report("y in [-2.2, 7.3], x = y", c1, (a1 + b1) / 2, (b1 - a1) / 2, e1);
    // Piece 2: y in [7.3, 35.7], polynomial in sqrt(y).
    const double a2 = std::sqrt(7.3), b2 = std::sqrt(35.7);
    auto c2 = fit([](double q) { return t_of_y(q * q); }, a2, b2, 6);
    double e2 = 0;
    for (double y = 7.3; y <= 35.7; y += 1e-3) e2 = std::max(e2, std::fabs(horner(c2, (std::sqrt(y) - (a2 + b2) / 2) / ((b2 - a2) / 2)) - t_of_y(y)));
    report("y in [7.3, 35.7], x = sqrt(y)", c2, (a2 + b2) / 2, (b2 - a2) / 2, e2);
    // Below -2.2: t = exp(-y / 2).
    double e3 = 0;
    for (double t = 3.0; t <= 8.0; t += 1e-3) e3 = std::max(e3, std::fabs(std::exp(-y_of_t(t) / 2) - t) / t);
    std::printf("y < -2.2 (t > 3): t = exp(-y / 2), max relative t error %.2e\n", e3);
    return 0;
}
