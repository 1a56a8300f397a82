// Speed of chapter 02's estimator: points per second of the disk count 4 M / N.
//
//   bench_disk_area
//
// BM_NaiveDiskArea is the reference a student would write: std::mt19937 with
// std::uniform_real_distribution<double>, one point at a time. BM_LectureLoop is the lecture's
// loop as the project writes it (estimate_disk_area: one point at a time from the 16 lanes).
// BM_CountInDisk is the engine behind it on one core (integration/disk_counter.hpp, the same
// count 16 lanes at a time, AVX2 when present), BM_CountInDiskPortable the same lanes without
// AVX2, BM_CountInDiskParallel the engine on every core. All are
// compiled alike (this file, the Release flags); the counter samples_per_second gives the
// ratios within one run.

#include <cstdint>
#include <random>

#include <benchmark/benchmark.h>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"

namespace {

// The textbook loop: two uniform doubles in [-1, 1), one point at a time.
double naive_disk_area(std::uint64_t n, std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uint64_t inside = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double x = uniform(generator);
    const double y = uniform(generator);
    if (x * x + y * y <= 1.0) ++inside;
  }
  return 4.0 * static_cast<double>(inside) / static_cast<double>(n);
}

void count_rate(benchmark::State& state, std::uint64_t points_per_iteration) {
  state.counters["samples_per_second"] =
      benchmark::Counter(static_cast<double>(points_per_iteration) *
                             static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void BM_NaiveDiskArea(benchmark::State& state) {
  const std::uint64_t n = std::uint64_t{1} << 21;
  std::uint32_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(naive_disk_area(n, seed++));
  count_rate(state, n);
}
BENCHMARK(BM_NaiveDiskArea)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_LectureLoop(benchmark::State& state) {
  const std::uint64_t n = std::uint64_t{1} << 22;
  std::uint64_t stream = 0;
  for (auto _ : state) {
    mcrt::Rng rng(1, stream++);
    benchmark::DoNotOptimize(mcrt::estimate_disk_area(n, rng));
  }
  count_rate(state, n);
}
BENCHMARK(BM_LectureLoop)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_CountInDisk(benchmark::State& state) {
  const std::uint64_t n = std::uint64_t{1} << 24;
  std::uint64_t stream = 0;
  for (auto _ : state) {
    mcrt::Rng rng(1, stream++);
    benchmark::DoNotOptimize(mcrt::count_in_disk(n, rng));
  }
  count_rate(state, n);
  state.SetLabel(mcrt::disk_count_uses_avx2() ? "avx2" : "portable");
}
BENCHMARK(BM_CountInDisk)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_CountInDiskPortable(benchmark::State& state) {
  const std::uint64_t n = std::uint64_t{1} << 23;
  std::uint64_t stream = 0;
  for (auto _ : state) {
    mcrt::Rng rng(1, stream++);
    benchmark::DoNotOptimize(mcrt::count_in_disk_portable(n, rng));
  }
  count_rate(state, n);
}
BENCHMARK(BM_CountInDiskPortable)->Unit(benchmark::kMillisecond)->MinTime(1.0);

// Wall-clock time: with several threads the CPU time of the main thread alone would mislead.
void BM_CountInDiskParallel(benchmark::State& state) {
  const std::uint64_t n = std::uint64_t{1} << 27;  // 32 chunks
  const int threads = mcrt::hardware_threads();
  std::uint64_t stream = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(mcrt::count_in_disk_parallel(n, 1, stream++, threads));
  count_rate(state, n);
  state.SetLabel(std::to_string(threads) + " threads");
}
BENCHMARK(BM_CountInDiskParallel)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
