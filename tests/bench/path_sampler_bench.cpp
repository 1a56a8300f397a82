// The cost of --sampler: chapter 05's path tracer with independent streams, jittered and
// Owen-scrambled Sobol' sets, run as the chapter runs it, four paths at a time
// (render_path_tracer_lanes, --engine lanes), and one path at a time (render_sampled with
// estimate_path_radiance, --engine loop).
//
//   bench_path_sampler
//
// BM_SamplerCost<Engine><Scene> renders cornell (or cornell-spheres) at 128x96, 16 spp, depth
// 10, one thread, with each sampler in turn in every iteration (the order rotates), each render
// timed alone in the process's CPU time (std::clock): on a shared, loaded host the wall clock
// counts the time other processes took, the CPU time only this one's, so the ratios hold.
// Counters: each sampler's rays per second and sobol_ratio, jittered_ratio (its rate over
// independent's with the same engine; the goal is 0.9 or more). Rays are closest-hit queries:
// the samplers trace different paths, so the rates, not the times, compare. The label names the
// version of the Sobol' blocks the processor runs (AVX-512, AVX2 or portable).

#include <cstdint>
#include <ctime>

#include <benchmark/benchmark.h>

#include "core/cpu_features.hpp"
#include "engine/path_tracer_lanes.hpp"
#include "render/path_tracer.hpp"
#include "render/sampled_render.hpp"
#include "render/scene.hpp"

namespace {

constexpr int k_depth = 10;

enum class Engine { lanes, loop };

mcrt::RenderResult render_with(Engine engine, const mcrt::Scene& scene, const mcrt::Camera& camera,
                               const mcrt::RenderSettings& settings, mcrt::PathSampler sampler) {
  if (engine == Engine::lanes)
    return mcrt::render_path_tracer_lanes(scene, camera, settings, k_depth, sampler);
  return mcrt::render_sampled(camera, settings, sampler,
                              [&](const mcrt::Ray& ray, auto& rng, mcrt::RayCount& count) {
                                return mcrt::estimate_path_radiance(scene, ray, k_depth, rng,
                                                                    count);
                              });
}

void sampler_cost(benchmark::State& state, Engine engine, const char* scene_name) {
  const mcrt::Scene scene = mcrt::make_scene(scene_name);
  const mcrt::Camera camera(scene.camera, 128, 96);
  double seconds[3] = {0.0, 0.0, 0.0};  // by sampler
  std::uint64_t rays[3] = {0, 0, 0};
  std::uint64_t seed = 1;
  for (auto _ : state) {
    for (int k = 0; k < 3; ++k) {
      const int s = static_cast<int>((seed + k) % 3);
      const auto sampler = mcrt::k_path_samplers[s];
      const mcrt::RenderSettings settings{16, 0, seed, 1, nullptr};
      const std::clock_t start = std::clock();
      const mcrt::RenderResult result = render_with(engine, scene, camera, settings, sampler);
      seconds[s] += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
      benchmark::DoNotOptimize(result.image.pixels.data());
      rays[s] += result.rays;
    }
    ++seed;
  }
  double rate[3];
  for (int s = 0; s < 3; ++s) {
    rate[s] = static_cast<double>(rays[s]) / seconds[s];
    state.counters[mcrt::name_of(mcrt::k_path_samplers[s]) + "_rays_per_second"] = rate[s];
  }
  state.counters["jittered_ratio"] = rate[1] / rate[0];
  state.counters["sobol_ratio"] = rate[2] / rate[0];
  state.SetLabel(mcrt::cpu_has_avx512() ? "sobol blocks: AVX-512"
                 : mcrt::cpu_has_avx2() ? "sobol blocks: AVX2"
                                        : "sobol blocks: portable");
}
void BM_SamplerCostLanesCornell(benchmark::State& state) {
  sampler_cost(state, Engine::lanes, "cornell");
}
void BM_SamplerCostLanesCornellSpheres(benchmark::State& state) {
  sampler_cost(state, Engine::lanes, "cornell-spheres");
}
void BM_SamplerCostLoopCornell(benchmark::State& state) {
  sampler_cost(state, Engine::loop, "cornell");
}
void BM_SamplerCostLoopCornellSpheres(benchmark::State& state) {
  sampler_cost(state, Engine::loop, "cornell-spheres");
}
BENCHMARK(BM_SamplerCostLanesCornell)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_SamplerCostLanesCornellSpheres)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);
BENCHMARK(BM_SamplerCostLoopCornell)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_SamplerCostLoopCornellSpheres)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

}  // namespace
