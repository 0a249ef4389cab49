// Reproduces the polynomial fits in glint_clamped_gaussian_fit (kernels/binomial.glsl): the
// inverse t(y) of y(t) = log(chi(t) / psi(t)^2 - 1), where psi(t) = E[max(t + Z, 0)] and
// chi(t) = E[max(t + Z, 0)^2] for a standard normal Z, and L(y) = -log psi(T(y)) of the fitted T.
// Least squares on 2000 Chebyshev nodes in double, with t(y) found by bisection; prints the
// coefficients and the maximum errors (in t, and in L, which is the relative error of the mean).
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
    std::printf("%s: s = (x - %.17g) / %.17g, max |error| %.2e\n  coefficients (s^0 first):", name, center, half, max_error);
    for (double v : c) std::printf(" %.17g", v);
    std::printf("\n");
}

}  // namespace

// One piece of the fits: T(y) ~ t(y) and L(y) ~ -log psi(T(y)), polynomials in x = y or
// x = sqrt(y), fitted on [a, b] in x.
struct piece {
    double a, b;
    bool root;
    int t_degree, l_degree;
};

int main() {
    const piece pieces[] = {{-3.6, 0, false, 10, 14}, {0, 7.3, false, 10, 14}, {std::sqrt(7.3), std::sqrt(35.7), true, 6, 8}};
    for (const piece& q : pieces) {
        auto y_of = [&](double x) { return q.root ? x * x : x; };
        const double center = (q.a + q.b) / 2, half = (q.b - q.a) / 2;
        const auto ct = fit([&](double x) { return t_of_y(y_of(x)); }, q.a, q.b, q.t_degree);
        auto T = [&](double x) { return horner(ct, (x - center) / half); };
        // L of the fitted T, so that sigma = m exp(L(y)) gives max(sigma (T + Z), 0) the mean m up
        // to L's fit error alone.
        const auto cl = fit([&](double x) { return -std::log(psi(T(x))); }, q.a, q.b, q.l_degree);
        double et = 0, el = 0;
        for (double x = q.a; x <= q.b; x += (q.b - q.a) * 1e-5) {
            et = std::max(et, std::fabs(T(x) - t_of_y(y_of(x))));
            el = std::max(el, std::fabs(horner(cl, (x - center) / half) + std::log(psi(T(x)))));
        }
        const char* x = q.root ? "sqrt(y)" : "y";
        std::printf("y in [%.4g, %.4g], x = %s, s = (x - %.17g) / %.17g\n", y_of(q.a), y_of(q.b), x, center, half);
        report("  T", ct, center, half, et);
        report("  L", cl, center, half, el);
    }
    // The middle in closed form (glint_binomial_closed_fit): w = sd / m in [1/6, 0.39] and
    // [0.38, 0.78], where the clamp is 1.3 to 6 sd below the mean. A(w) ~ w t(w) and
    // B(w) ~ 1 / (w psi(T(w))) = sigma / sd for the fitted T = A / w, so that sigma (T + Z) clamped
    // at 0 keeps the mean m up to B's fit error alone; no log or exp, as the other pieces need.
    for (const auto& range : {std::pair<double, double>{1.0 / 6, 0.39}, std::pair<double, double>{0.38, 0.78}}) {
        const double a = range.first, b = range.second, center = (a + b) / 2, half = (b - a) / 2;
        const auto ca = fit([&](double w) { return w * t_of_y(2 * std::log(w)); }, a, b, 6);
        auto T = [&](double w) { return horner(ca, (w - center) / half) / w; };
        const auto cb = fit([&](double w) { return 1 / (w * psi(T(w))); }, a, b, 6);
        double ea = 0, eb = 0;
        for (double w = a; w <= b; w += (b - a) * 1e-5) {
            ea = std::max(ea, std::fabs(horner(ca, (w - center) / half) - w * t_of_y(2 * std::log(w))));
            eb = std::max(eb, std::fabs(horner(cb, (w - center) / half) * w * psi(T(w)) - 1));
        }
        std::printf("w = sqrt(v) / m in [%.6g, %.4g], s = (w - %.17g) / %.17g\n", a, b, center, half);
        report("  A (w t)", ca, center, half, ea);
        report("  B (sigma / sd; error relative)", cb, center, half, eb);
    }
    return 0;
}
