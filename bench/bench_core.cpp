// One Google Benchmark per core function (kernels/core.glsl), float and double, with the
// standard-library or Boost reference beside it. Time is per call.
#include <benchmark/benchmark.h>

#include <boost/math/special_functions/erf.hpp>
#include <cmath>

#include <glint/core.hpp>

#include "inputs.hpp"

namespace {

using glint_bench::table_size;

void pcg3d(benchmark::State& state) {
    std::uint32_t i = 0;
    for (auto _ : state) {
        glm::uvec3 h = glint::pcg3d(glm::uvec3(i, 17u, 23u));
        benchmark::DoNotOptimize(h);
        ++i;
    }
}
BENCHMARK(pcg3d);

template <class real>
void open_unit_from_bits(benchmark::State& state) {
    std::uint32_t i = 0;
    for (auto _ : state) {
        real u = glint::open_unit_from_bits<real>(i * 2654435761u);
        benchmark::DoNotOptimize(u);
        ++i;
    }
}
BENCHMARK(open_unit_from_bits<float>);
BENCHMARK(open_unit_from_bits<double>);

// Runs f over a table of arguments.
template <class real, class F>
void unary(benchmark::State& state, const std::vector<real>& xs, F f) {
    std::size_t i = 0;
    for (auto _ : state) {
        real y = f(xs[i & (table_size - 1)]);
        benchmark::DoNotOptimize(y);
        ++i;
    }
}

template <class real>
void erfinv(benchmark::State& state) {
    static const auto xs = glint_bench::signed_table<real>();
    unary(state, xs, [](real x) { return glint::erfinv(x); });
}
BENCHMARK(erfinv<float>);
BENCHMARK(erfinv<double>);

void erfinv_boost_double(benchmark::State& state) {
    static const auto xs = glint_bench::signed_table<double>();
    unary(state, xs, [](double x) { return boost::math::erf_inv(x); });
}
BENCHMARK(erfinv_boost_double);

template <class real>
void normal_quantile(benchmark::State& state) {
    static const auto us = glint_bench::uniform_table<real>();
    unary(state, us, [](real u) { return glint::normal_quantile(u); });
}
BENCHMARK(normal_quantile<float>);
BENCHMARK(normal_quantile<double>);

template <class real>
void log1p_kernel(benchmark::State& state) {
    static const auto us = glint_bench::uniform_table<real>();
    unary(state, us, [](real u) { return glint::detail::glsl::kernels<real>::glint_log1p(-u); });
}
BENCHMARK(log1p_kernel<float>);
BENCHMARK(log1p_kernel<double>);

template <class real>
void log1p_std(benchmark::State& state) {
    static const auto us = glint_bench::uniform_table<real>();
    unary(state, us, [](real u) { return std::log1p(-u); });
}
BENCHMARK(log1p_std<float>);
BENCHMARK(log1p_std<double>);

template <class real>
void expm1_kernel(benchmark::State& state) {
    static const auto us = glint_bench::uniform_table<real>();
    unary(state, us, [](real u) { return glint::detail::glsl::kernels<real>::glint_expm1_nonpositive(real(-4) * u); });
}
BENCHMARK(expm1_kernel<float>);
BENCHMARK(expm1_kernel<double>);

template <class real, glint::pow_method method, bool complement>
void pow_one_minus(benchmark::State& state) {
    static std::vector<real> p, n;
    if (p.empty()) glint_bench::pn_tables(p, n);
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i & (table_size - 1);
        real y = complement ? glint::any_success(p[k], n[k], method) : glint::pow_one_minus(p[k], n[k], method);
        benchmark::DoNotOptimize(y);
        ++i;
    }
}
BENCHMARK(pow_one_minus<float, glint::pow_method::naive, false>)->Name("pow_one_minus/naive/float");
BENCHMARK(pow_one_minus<float, glint::pow_method::kk25, false>)->Name("pow_one_minus/kk25/float");
BENCHMARK(pow_one_minus<float, glint::pow_method::log1p, false>)->Name("pow_one_minus/log1p/float");
BENCHMARK(pow_one_minus<double, glint::pow_method::log1p, false>)->Name("pow_one_minus/log1p/double");
BENCHMARK(pow_one_minus<float, glint::pow_method::kk25, true>)->Name("any_success/kk25/float");
BENCHMARK(pow_one_minus<float, glint::pow_method::log1p, true>)->Name("any_success/expm1/float");
BENCHMARK(pow_one_minus<double, glint::pow_method::log1p, true>)->Name("any_success/expm1/double");

}  // namespace

BENCHMARK_MAIN();
