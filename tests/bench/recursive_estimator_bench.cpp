// Speed of chapter 04: rays per second of the recursive N^k estimator against bare
// closest-hit queries on the same kind of rays, on one thread.
//
//   bench_recursive_estimator
//
// BM_IncidentRadiance renders the Cornell box at 64x48, 1 spp, for (N, k); its counter
// rays_per_second counts every closest-hit query. BM_ClosestHitOnly answers the queries of
// single paths (camera ray and bounces, depth 3) without any shading, so the ratio of the two
// rates is what the recursion itself (sampling, frames, spawning, the call) costs per ray.

#include <vector>

#include <benchmark/benchmark.h>

#include "bench/path_rays.hpp"
#include "render/recursive_estimator.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

namespace {

void BM_IncidentRadiance(benchmark::State& state) {
  const mcrt::Scene scene = mcrt::make_cornell_box();
  const mcrt::Camera camera(scene.camera, 64, 48);
  const mcrt::RecursiveSettings recursion{static_cast<int>(state.range(0)),
                                          static_cast<int>(state.range(1))};
  std::uint64_t rays = 0, seed = 1;
  for (auto _ : state) {
    const mcrt::RenderSettings settings{1, 0, seed++, 1, nullptr};
    const mcrt::RenderResult result =
        mcrt::render(camera, settings,
                     [&](const mcrt::Ray& ray, mcrt::Rng& rng, mcrt::RayCount& count) {
                       return mcrt::incident_radiance(scene, ray, 0, recursion, rng, count);
                     });
    benchmark::DoNotOptimize(result.image.pixels.data());
    rays += result.rays;
  }
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_IncidentRadiance)
    ->Args({1, 3})
    ->Args({2, 3})
    ->Args({8, 3})
    ->Args({1, 8})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

using mcrt::bench::path_rays;

void BM_ClosestHitOnly(benchmark::State& state) {
  const mcrt::Scene scene = mcrt::make_cornell_box();
  const std::vector<mcrt::Ray> rays = path_rays(scene);
  std::uint64_t queries = 0;
  for (auto _ : state) {
    for (const mcrt::Ray& ray : rays) benchmark::DoNotOptimize(scene.closest_hit(ray));
    queries += rays.size();
  }
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(queries), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ClosestHitOnly)->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace
