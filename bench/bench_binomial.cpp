// Google Benchmark of every binomial variant and of the multinomial, float and double, at
// representative (N, p): a sparse glint (N p = 0.01), a few glints (N p = 1), a dense footprint
// (N p = 1e4), small N with moderate p (the mean-preserving sampler's Newton refinement), and
// against std::binomial_distribution (constructed per sample, as per-pixel N and p need).
//   glint_bench_binomial [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <random>

#include <glint/binomial.hpp>
#include <glint/multinomial.hpp>

#include "inputs.hpp"

namespace {

using glint_bench::table_size;

// (N, p) by index: the cases named above.
const double cases[][2] = {{1e4, 1e-6}, {1e3, 1e-3}, {1e6, 1e-2}, {10, 0.3}, {1e12, 0.5}};

template <class real>
void binomial(benchmark::State& state, glint::binomial_variant v) {
    static const auto us = glint_bench::uniform_table<real>();
    const real N = static_cast<real>(cases[state.range(0)][0]), p = static_cast<real>(cases[state.range(0)][1]);
    std::size_t i = 0;
    for (auto _ : state) {
        auto r = glint::binomial(v, N, p, us[i & (table_size - 1)], us[(i * 7 + 3) & (table_size - 1)]);
        benchmark::DoNotOptimize(r);
        ++i;
    }
}

void std_binomial(benchmark::State& state) {
    const double N = cases[state.range(0)][0], p = cases[state.range(0)][1];
    std::mt19937_64 engine(1);
    for (auto _ : state) {
        std::binomial_distribution<long long> d(static_cast<long long>(N), p);
        benchmark::DoNotOptimize(d(engine));
    }
}

template <std::size_t K>
void multinomial(benchmark::State& state) {
    const float N = static_cast<float>(cases[state.range(0)][0]), p = static_cast<float>(cases[state.range(0)][1]);
    std::array<float, K> q;
    q.fill(p / static_cast<float>(K));
    std::uint32_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(glint::multinomial<K>(N, q, glm::uvec3(i++, 1u, 2u)));
}

void binomial_float(benchmark::State& state, glint::binomial_variant v) { binomial<float>(state, v); }
void binomial_double(benchmark::State& state, glint::binomial_variant v) { binomial<double>(state, v); }
void multinomial_2(benchmark::State& state) { multinomial<2>(state); }
void multinomial_4(benchmark::State& state) { multinomial<4>(state); }
void multinomial_8(benchmark::State& state) { multinomial<8>(state); }

#define GLINT_CASES ->DenseRange(0, 4)
BENCHMARK_CAPTURE(binomial_float, ungated, glint::binomial_variant::ungated) GLINT_CASES;
BENCHMARK_CAPTURE(binomial_float, gated_db23, glint::binomial_variant::gated_db23) GLINT_CASES;
BENCHMARK_CAPTURE(binomial_float, gated, glint::binomial_variant::gated) GLINT_CASES;
BENCHMARK_CAPTURE(binomial_float, dual_gated, glint::binomial_variant::dual_gated) GLINT_CASES;
BENCHMARK_CAPTURE(binomial_float, unbiased, glint::binomial_variant::unbiased) GLINT_CASES;
BENCHMARK_CAPTURE(binomial_double, dual_gated, glint::binomial_variant::dual_gated) GLINT_CASES;
BENCHMARK_CAPTURE(binomial_double, unbiased, glint::binomial_variant::unbiased) GLINT_CASES;
BENCHMARK(std_binomial) GLINT_CASES;
BENCHMARK(multinomial_2) GLINT_CASES;
BENCHMARK(multinomial_4) GLINT_CASES;
BENCHMARK(multinomial_8) GLINT_CASES;

}  // namespace

BENCHMARK_MAIN();
