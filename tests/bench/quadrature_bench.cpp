// Speed of the trapezoid rule and of plain Monte Carlo: function evaluations per second.
//
//   bench_quadrature
//
// Both rules take the integrand as a template parameter, so it is inlined into their loops.
// The *StdFunction variants pass the same integrand through std::function, the type-erased
// call a generic interface would make per sample; the counter evaluations_per_second gives
// the ratios within one run. k = 4, about 10^6 evaluations per iteration.

#include <cstdint>
#include <functional>
#include <span>

#include <benchmark/benchmark.h>

#include "core/rng.hpp"
#include "integration/integrands.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/quadrature.hpp"

namespace {

constexpr int k_dims = 4;
constexpr std::uint64_t k_points_per_axis = 32;              // 32^4 = 1048576 evaluations
constexpr std::uint64_t k_samples = std::uint64_t{1} << 20;  // the same for Monte Carlo

void evaluation_rate(benchmark::State& state, std::uint64_t per_iteration) {
  state.counters["evaluations_per_second"] =
      benchmark::Counter(static_cast<double>(per_iteration) *
                             static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

template <class Integrand>
void BM_Trapezoid(benchmark::State& state) {
  const Integrand f{k_dims};
  for (auto _ : state) benchmark::DoNotOptimize(mcrt::trapezoid(f, f.domain(), k_points_per_axis));
  evaluation_rate(state, mcrt::grid_evaluations(k_points_per_axis, k_dims));
}
BENCHMARK(BM_Trapezoid<mcrt::GaussianProduct>)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_Trapezoid<mcrt::UnitBallIndicator>)->Unit(benchmark::kMillisecond)->MinTime(0.5);

template <class Integrand>
void BM_TrapezoidStdFunction(benchmark::State& state) {
  const Integrand f{k_dims};
  const std::function<double(std::span<const double>)> erased = f;
  for (auto _ : state)
    benchmark::DoNotOptimize(mcrt::trapezoid(erased, f.domain(), k_points_per_axis));
  evaluation_rate(state, mcrt::grid_evaluations(k_points_per_axis, k_dims));
}
BENCHMARK(BM_TrapezoidStdFunction<mcrt::GaussianProduct>)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);
BENCHMARK(BM_TrapezoidStdFunction<mcrt::UnitBallIndicator>)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);

template <class Integrand>
void BM_MonteCarlo(benchmark::State& state) {
  const Integrand f{k_dims};
  std::uint64_t stream = 0;
  for (auto _ : state) {
    mcrt::Rng rng(1, stream++);
    benchmark::DoNotOptimize(mcrt::monte_carlo(f, f.domain(), k_samples, rng));
  }
  evaluation_rate(state, k_samples);
}
BENCHMARK(BM_MonteCarlo<mcrt::GaussianProduct>)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_MonteCarlo<mcrt::UnitBallIndicator>)->Unit(benchmark::kMillisecond)->MinTime(0.5);

template <class Integrand>
void BM_MonteCarloStdFunction(benchmark::State& state) {
  const Integrand f{k_dims};
  const std::function<double(std::span<const double>)> erased = f;
  std::uint64_t stream = 0;
  for (auto _ : state) {
    mcrt::Rng rng(1, stream++);
    benchmark::DoNotOptimize(mcrt::monte_carlo(erased, f.domain(), k_samples, rng));
  }
  evaluation_rate(state, k_samples);
}
BENCHMARK(BM_MonteCarloStdFunction<mcrt::GaussianProduct>)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);
BENCHMARK(BM_MonteCarloStdFunction<mcrt::UnitBallIndicator>)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);

}  // namespace
