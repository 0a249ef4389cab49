// The core-numerics section of the accuracy-versus-time report: for every kernel and knob, its
// error against an exact reference (Boost.Math, long double) and its time per call measured
// with Google Benchmark in the same run; docs/core_numerics.md and docs/pow_one_minus.csv.
#include "report.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <glint/core.hpp>

#include "../tests/support/core_reference.hpp"
#include "../tests/support/ulp.hpp"
#include "inputs.hpp"

namespace glint_report {
namespace {

using glint_bench::table_size;

template <class real>
void time_unary(const std::string& name, const std::vector<real>& xs, std::function<real(real)> f, double min_time) {
    benchmark::RegisterBenchmark(name.c_str(), [xs, f](benchmark::State& state) {
        std::size_t i = 0;
        for (auto _ : state) {
            real y = f(xs[i & (table_size - 1)]);
            benchmark::DoNotOptimize(y);
            ++i;
        }
    })->MinTime(min_time);
}

template <class real>
void time_binary(const std::string& name, std::function<real(real, real)> f, double min_time) {
    std::vector<real> p, n;
    glint_bench::pn_tables(p, n);
    benchmark::RegisterBenchmark(name.c_str(), [p, n, f](benchmark::State& state) {
        std::size_t i = 0;
        for (auto _ : state) {
            const std::size_t k = i & (table_size - 1);
            real y = f(p[k], n[k]);
            benchmark::DoNotOptimize(y);
            ++i;
        }
    })->MinTime(min_time);
}

// ---- accuracy -------------------------------------------------------------------------------

struct row {
    std::string kernel, variant, precision, measure;
    double error = 0;
    std::string reference;  // the benchmark name of the reference row for the time ratio
};

double erfinv_max_ulp_float() {
    double worst = 0;
    for (float x : glint_test::unit_interval_sweep(100, 1u << 16))
        worst = std::max(worst, glint_test::ulp_error(glint::erfinv(x), glint_test::erfinv_exact(static_cast<double>(x))));
    return worst;
}

double erfinv_max_rel_double() {
    double worst = 0;
    for (float xf : glint_test::unit_interval_sweep(997, 4096)) {
        const double x = static_cast<double>(xf), exact = glint_test::erfinv_exact(x);
        if (exact != 0) worst = std::max(worst, std::fabs(glint::erfinv(x) - exact) / exact);
    }
    return worst;
}

double quantile_max_ulp_float() {
    double worst = 0;
    auto check = [&](float u) {
        worst = std::max(worst, glint_test::ulp_error(glint::normal_quantile(u), glint_test::normal_quantile_exact(static_cast<double>(u))));
    };
    for (std::uint32_t k = 0; k < (1u << 23); ++k) check(glint::open_unit_from_bits<float>(k << 9));
    for (std::uint32_t b = 0x33000000u; b < 0x3f000000u; b += 100u) check(glint_test::float_from_bits(b));
    return worst;
}

double quantile_max_rel_double() {
    double worst = 0;
    for (std::uint32_t k = 0; k < (1u << 23); k += 7u) {
        const double u = glint::open_unit_from_bits<double>(k << 9), exact = glint_test::normal_quantile_exact(u);
        if (exact != 0) worst = std::max(worst, std::fabs(glint::normal_quantile(u) - exact) / std::fabs(exact));
    }
    return worst;
}

const char* method_name(glint::pow_method m) {
    switch (m) {
        case glint::pow_method::naive: return "naive";
        case glint::pow_method::kk25: return "kk25";
        case glint::pow_method::log1p: break;
    }
    return "log1p";
}

// Bands of the (1 - p)^N summary table.
const double p_edges[] = {0, 1e-12, 1e-8, 1e-4, 1.0000001};
const char* p_labels[] = {"p < 1e-12", "1e-12 <= p < 1e-8", "1e-8 <= p < 1e-4", "1e-4 <= p <= 1"};
const double n_edges[] = {0, 1, 1e4, 1e8, 1e12, 1.0000001e16};
const char* n_labels[] = {"N < 1", "1 <= N < 1e4", "1e4 <= N < 1e8", "1e8 <= N < 1e12", "1e12 <= N <= 1e16"};
int band(const double* edges, int count, double v) {
    for (int i = 0; i < count; ++i)
        if (v >= edges[i] && v < edges[i + 1]) return i;
    return count - 1;
}

struct pow_summary {
    double max_abs = 0, max_rel = 0, max_complement_rel = 0;
    double band_rel[4][5] = {};  // relative error of (1 - p)^N where it is >= 1e-30
    double band_complement_rel[4][5] = {};
};

pow_summary summarize(glint::pow_method m, std::ostream* csv) {
    pow_summary s;
    for (double pd : glint_test::pow_grid_p())
        for (double nd : glint_test::pow_grid_n()) {
            const float p = static_cast<float>(pd), N = static_cast<float>(nd);
            const long double q = glint_test::pow_one_minus_exact(p, N), c = glint_test::any_success_exact(p, N);
            const float fq = glint::pow_one_minus(p, N, m), fc = glint::any_success(p, N, m);
            const double ea = static_cast<double>(fabsl(fq - q));
            const double er = q >= 1e-30L ? static_cast<double>(fabsl(fq - q) / q) : 0;
            const double ec = c > 0 ? static_cast<double>(fabsl(fc - c) / c) : 0;
            s.max_abs = std::max(s.max_abs, ea);
            s.max_rel = std::max(s.max_rel, er);
            s.max_complement_rel = std::max(s.max_complement_rel, ec);
            const int i = band(p_edges, 4, static_cast<double>(p)), j = band(n_edges, 5, static_cast<double>(N));
            s.band_rel[i][j] = std::max(s.band_rel[i][j], er);
            s.band_complement_rel[i][j] = std::max(s.band_complement_rel[i][j], ec);
            if (csv)
                *csv << method_name(m) << ',' << static_cast<double>(p) << ',' << static_cast<double>(N) << ','
                     << static_cast<double>(q) << ',' << fq << ',' << static_cast<double>(c) << ',' << fc << '\n';
        }
    return s;
}

}  // namespace

section core_section(double min_time) {
    using glint::pow_method;
    using kf = glint::detail::glsl::kernels<float>;
    using kd = glint::detail::glsl::kernels<double>;

    // Time every row in one run.
    const auto sf = glint_bench::signed_table<float>();
    const auto sd = glint_bench::signed_table<double>();
    const auto uf = glint_bench::uniform_table<float>();
    const auto ud = glint_bench::uniform_table<double>();
    time_unary<float>("erfinv/float", sf, [](float x) { return glint::erfinv(x); }, min_time);
    time_unary<double>("erfinv/double", sd, [](double x) { return glint::erfinv(x); }, min_time);
    time_unary<double>("erfinv/boost", sd, [](double x) { return boost::math::erf_inv(x); }, min_time);
    time_unary<float>("normal_quantile/float", uf, [](float u) { return glint::normal_quantile(u); }, min_time);
    time_unary<double>("normal_quantile/double", ud, [](double u) { return glint::normal_quantile(u); }, min_time);
    time_unary<double>("normal_quantile/boost", ud, [](double u) { return -1.4142135623730951 * boost::math::erfc_inv(2 * u); }, min_time);
    time_unary<float>("log1p/float", uf, [](float u) { return kf::glint_log1p(-u); }, min_time);
    time_unary<double>("log1p/double", ud, [](double u) { return kd::glint_log1p(-u); }, min_time);
    time_unary<double>("log1p/std", ud, [](double u) { return std::log1p(-u); }, min_time);
    time_unary<float>("expm1/float", uf, [](float u) { return kf::glint_expm1_nonpositive(-4.0f * u); }, min_time);
    time_unary<double>("expm1/double", ud, [](double u) { return kd::glint_expm1_nonpositive(-4.0 * u); }, min_time);
    time_unary<double>("expm1/std", ud, [](double u) { return std::expm1(-4.0 * u); }, min_time);
    for (pow_method m : {pow_method::naive, pow_method::kk25, pow_method::log1p}) {
        const std::string n = method_name(m);
        time_binary<float>("pow_one_minus/" + n + "/float", [m](float p, float N) { return glint::pow_one_minus(p, N, m); }, min_time);
        time_binary<float>("any_success/" + n + "/float", [m](float p, float N) { return glint::any_success(p, N, m); }, min_time);
    }
    time_binary<double>("pow_one_minus/log1p/double", [](double p, double N) { return glint::pow_one_minus(p, N); }, min_time);
    time_binary<double>("any_success/log1p/double", [](double p, double N) { return glint::any_success(p, N); }, min_time);
    time_binary<double>("pow_one_minus/std/double", [](double p, double N) { return std::exp(N * std::log1p(-p)); }, min_time);
    const std::map<std::string, double> ns = run_all();
    auto time_of = [&](const std::string& name) {
        auto it = ns.find(name);
        return it == ns.end() ? 0.0 : it->second;
    };

    // Accuracy.
    std::vector<std::pair<row, std::string>> rows;  // row and its benchmark name
    auto add = [&](row r, std::string bench) { rows.emplace_back(std::move(r), std::move(bench)); };
    add({"erfinv", "Giles poly", "float", "max ulp, 1.07e7 floats", erfinv_max_ulp_float(), "erfinv/boost"}, "erfinv/float");
    add({"erfinv", "Giles poly", "double", "max rel. error", erfinv_max_rel_double(), "erfinv/boost"}, "erfinv/double");
    add({"erfinv", "Boost.Math erf_inv (reference)", "double", "-", 0, "erfinv/boost"}, "erfinv/boost");
    add({"normal_quantile", "tail-exact w, Giles poly", "float", "max ulp, 1.04e7 values", quantile_max_ulp_float(), "normal_quantile/boost"}, "normal_quantile/float");
    add({"normal_quantile", "tail-exact w, Giles poly", "double", "max rel. error", quantile_max_rel_double(), "normal_quantile/boost"}, "normal_quantile/double");
    add({"normal_quantile", "Boost.Math erfc_inv (reference)", "double", "-", 0, "normal_quantile/boost"}, "normal_quantile/boost");

    std::ostringstream grid_csv;
    grid_csv << "method,p,N,exact_pow_one_minus,float_pow_one_minus,exact_any_success,float_any_success\n";
    grid_csv.precision(9);
    std::map<std::string, pow_summary> summaries;
    for (pow_method m : {pow_method::naive, pow_method::kk25, pow_method::log1p}) {
        const std::string n = method_name(m);
        pow_summary s = summarize(m, &grid_csv);
        summaries[n] = s;
        add({"(1-p)^N", n, "float", "max rel. error (result >= 1e-30)", s.max_rel, "pow_one_minus/std/double"}, "pow_one_minus/" + n + "/float");
        add({"1-(1-p)^N", n == "log1p" ? "expm1" : n, "float", "max rel. error", s.max_complement_rel, "pow_one_minus/std/double"}, "any_success/" + n + "/float");
    }
    {
        double worst = 0, worst_c = 0;
        for (double p : glint_test::pow_grid_p())
            for (double N : glint_test::pow_grid_n()) {
                const long double q = glint_test::pow_one_minus_exact(p, N), c = glint_test::any_success_exact(p, N);
                if (q >= 1e-300L) worst = std::max(worst, static_cast<double>(fabsl(glint::pow_one_minus(p, N) - q) / q));
                if (c > 0) worst_c = std::max(worst_c, static_cast<double>(fabsl(glint::any_success(p, N) - c) / c));
            }
        add({"(1-p)^N", "log1p", "double", "max rel. error", worst, "pow_one_minus/std/double"}, "pow_one_minus/log1p/double");
        add({"1-(1-p)^N", "expm1", "double", "max rel. error", worst_c, "pow_one_minus/std/double"}, "any_success/log1p/double");
        add({"(1-p)^N", "std::exp(N std::log1p(-p)) (reference)", "double", "-", 0, "pow_one_minus/std/double"}, "pow_one_minus/std/double");
    }

    // The accuracy-versus-time table.
    std::ostringstream md;
    md << "| kernel | variant | precision | error measure | error | ns/call | time / reference |\n"
       << "|---|---|---|---|---|---|---|\n";
    std::ostringstream csv;
    for (const auto& [r, bench] : rows) {
        const double t = time_of(bench), ref = time_of(r.reference);
        const double ratio = ref > 0 ? t / ref : 0;
        md << "| " << r.kernel << " | " << r.variant << " | " << r.precision << " | " << r.measure << " | "
           << (r.measure == "-" ? std::string("-") : fmt(r.error)) << " | " << fmt(t, "%.2f") << " | " << fmt(ratio, "%.2f") << " |\n";
        csv << r.kernel << ',' << r.variant << ',' << r.precision << ',' << r.measure << ',' << r.error << ',' << t << ','
            << ratio << ',' << r.reference << '\n';
    }
    std::ostringstream bands;
    for (const char* n : {"naive", "kk25", "log1p"}) {
        const pow_summary& s = summaries[n];
        bands << "\n**" << n << "**: max absolute error " << fmt(s.max_abs) << ", max relative error " << fmt(s.max_rel)
              << " (results >= 1e-30), max relative error of 1-(1-p)^N " << fmt(s.max_complement_rel) << ".\n\n"
              << "| max rel. error of (1-p)^N / of 1-(1-p)^N |";
        for (const char* l : n_labels) bands << ' ' << l << " |";
        bands << "\n|---|---|---|---|---|---|\n";
        for (int i = 0; i < 4; ++i) {
            bands << "| " << p_labels[i] << " |";
            for (int j = 0; j < 5; ++j) bands << ' ' << fmt(s.band_rel[i][j], "%.1e") << " / " << fmt(s.band_complement_rel[i][j], "%.1e") << " |";
            bands << '\n';
        }
    }

    section out;
    std::ostringstream text;
    text << "\n## Core numerics: accuracy versus time (CPU time per call, this machine, one run)\n\n" << md.str()
         << "\n## (1-p)^N in float over p in [1e-16, 1], N in [0, 1e16] (" << glint_test::pow_grid_p().size() << " x "
         << glint_test::pow_grid_n().size() << " grid)\n" << bands.str() << "\n";
    out.markdown = text.str();
    out.csv_rows = csv.str();
    out.files["pow_one_minus.csv"] = grid_csv.str();
    std::ostringstream doc;
    doc << "# Core numerics: measured accuracy and cost\n\n"
        << "Generated by `scripts/demo --docs` (bench/report.cpp); do not edit.\n"
        << "Errors are against Boost.Math (erfinv, quantile) and long double (`(1-p)^N`); times are CPU\n"
        << "time per call from Google Benchmark in the same run, and only their ratios are meaningful\n"
        << "(shared, noisy machine). The tests assert the bounds stated in `docs/conventions.md`.\n\n"
        << "## Accuracy versus time\n\n" << md.str()
        << "\n## (1-p)^N and 1-(1-p)^N in float\n\n"
        << "Grid: p = 10^(-k/4), k = 0..64, plus 0, 0.5, 1-1e-3, 1-1e-6; N = 0, 1e-3, 0.5, 1, 1.5, 2, 3, 5 and\n"
        << "10^(j/2), j = 2..32. Inputs are rounded to float first and the reference is computed from\n"
        << "the rounded values in long double. Every point is in `pow_one_minus.csv`.\n"
        << bands.str();
    out.files["core_numerics.md"] = doc.str();
    return out;
}

}  // namespace glint_report
