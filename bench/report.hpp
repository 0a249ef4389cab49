// Shared pieces of the accuracy-versus-time report (glint_report): timing through Google
// Benchmark in the same run, number formatting, and the sections' entry points.
#pragma once

#include <benchmark/benchmark.h>

#include "launder.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint_report {

// The benchmarks registered by add_all_cores: timed by the wall clock, not the CPU time.
inline std::set<std::string>& all_cores_names() {
    static std::set<std::string> names;
    return names;
}

// Time per iteration (ns) of every benchmark run, by name: the CPU time, or for add_all_cores's
// benchmarks the wall time of one frame on every core.
class collector : public benchmark::BenchmarkReporter {
public:
    std::map<std::string, double> ns;
    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            const std::string& name = r.run_name.function_name;
            // With T threads Google Benchmark reports the wall time over all T threads' iterations,
            // each a T-th of a frame: T of them make a frame.
            ns[name] = all_cores_names().count(name) ? r.GetAdjustedRealTime() * static_cast<double>(r.threads) : r.GetAdjustedCPUTime();
        }
    }
};

// The threads that "all cores" frames run on: every hardware thread.
inline int all_cores() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

// Registers `body` (called once per iteration with the iteration index) as a benchmark, inlined
// into the timing loop: no std::function call per iteration (about 2 ns here, as much as the
// cheapest samplers). `body` must pass its loop-invariant inputs through
// launder() so that the compiler cannot hoist their work out of the loop.
template <class Body>
void add_inline(const std::string& name, Body body, double min_time) {
    benchmark::RegisterBenchmark(name.c_str(), [body](benchmark::State& state) {
        std::size_t i = 0;
        for (auto _ : state) body(i++);
    })->MinTime(min_time);
}

// As add_inline, through a std::function (for bodies whose call cost does not matter).
inline void add(const std::string& name, std::function<void(std::size_t)> body, double min_time) {
    add_inline(name, std::move(body), min_time);
}

// A frame on every core: `rows(first, step, i)` shades the rows first, first + step, ... of frame i;
// all_cores() threads run it at once, thread t with first = t, step = all_cores(), and the time
// recorded is a whole frame's wall time (the threads run their frames side by side, without a
// barrier between frames, as a renderer's frames overlap). The CPU frame targets (README) are for
// all cores; the report times each frame on one thread too.
template <class Rows>
void add_all_cores(const std::string& name, Rows rows, double min_time) {
    all_cores_names().insert(name);
    benchmark::RegisterBenchmark(name.c_str(), [rows](benchmark::State& state) {
        std::size_t i = 0;  // each thread's own count
        for (auto _ : state) rows(state.thread_index(), state.threads(), i++);
    })->Threads(all_cores())->UseRealTime()->MinTime(min_time);
}

using glint_bench::launder;  // launder.hpp

// Benchmarks compared as ratios (a glint frame against its smooth frame) are registered
// round_count times each, round by round, as name + round_suffix(r): run_all then times them
// interleaved and gives each name the least time over its rounds. This shared 2-core machine has
// phases up to about 1.5x slower that last seconds; timed once each, a phase fell on one body and
// not on another (the IBL section's smooth frame 491 to 889 us in one report, the same frame).
inline constexpr int round_count = 5;

inline std::string round_suffix(int round) { return "#" + std::to_string(round); }

// Runs every registered benchmark, clears them, and returns the times; names registered in
// rounds (round_suffix) are returned once, with the least time over their rounds.
inline std::map<std::string, double> run_all() {
    collector c;
    benchmark::RunSpecifiedBenchmarks(&c);
    benchmark::ClearRegisteredBenchmarks();
    std::map<std::string, double> ns;
    for (const auto& [name, t] : c.ns) {
        const std::string base = name.substr(0, name.find('#'));
        const auto it = ns.find(base);
        if (it == ns.end() || t < it->second) ns[base] = t;
    }
    return ns;
}

inline std::string fmt(double v, const char* f = "%.3g") {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// What a section produces: markdown for the terminal and docs, and files for docs/.
struct section {
    std::string markdown;
    std::string csv_rows;  // rows of accuracy_vs_time.csv (header: csv_header)
    std::map<std::string, std::string> files;  // name in docs/ -> content
};

inline const char* csv_header = "kernel,variant,precision,error_measure,error,ns_per_call,time_ratio_to_reference,reference\n";

section core_section(double min_time);
section binomial_section(double min_time);
section grid_section(double min_time);
section ibl_section(double min_time);  // when built with GLINT_REPORT_IBL
section microstructure_section(double min_time);
section lobe_tree_section(double min_time);
section scratch_section(double min_time);
section ndf_map_section(double min_time);
section bin_map_section(double min_time);

}  // namespace glint_report
