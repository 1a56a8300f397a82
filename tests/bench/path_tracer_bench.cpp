// Speed of chapter 05: rays per second of the path tracer, and closest-hit queries per second.
//
//   bench_path_tracer
//
// BM_PathTracer renders cornell-spheres at 256x192, 16 spp, depth 10 (the target
// setting) with 1 and 2 threads; its counter rays_per_second counts every closest-hit query.
// BM_ClosestHit answers queries for a fixed batch of rays (camera rays and bounced rays of
// real paths), so it measures the intersection loop alone; BM_ReferenceClosestHit* answers
// the same queries with the plain loop over intersect_distance, for the speed-up in one run.

#include <vector>

#include <benchmark/benchmark.h>

#include "bench/path_rays.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

namespace {

constexpr int k_depth = 10;

void BM_PathTracer(benchmark::State& state) {
  const mcrt::Scene scene = mcrt::make_scene("cornell-spheres");
  const mcrt::Camera camera(scene.camera, 256, 192);
  const int threads = static_cast<int>(state.range(0));
  std::uint64_t rays = 0;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const mcrt::RenderSettings settings{16, 0, seed++, threads, nullptr};
    const mcrt::RenderResult result =
        mcrt::render(camera, settings, [&](const mcrt::Ray& ray, mcrt::Rng& rng,
                                           mcrt::RayCount& count) {
          return mcrt::estimate_path_radiance(scene, ray, k_depth, rng, count);
        });
    benchmark::DoNotOptimize(result.image.pixels.data());
    rays += result.rays;
  }
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
// Wall-clock time: with 2 threads the CPU time of the main thread alone would mislead.
BENCHMARK(BM_PathTracer)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()
    ->MinTime(2.0);

using mcrt::bench::path_rays;

// The straightforward closest-hit loop, one intersect_distance per primitive: the baseline
// Scene::closest_hit is measured against (same rays, same answers).
std::optional<mcrt::Hit> reference_closest_hit(const mcrt::Scene& scene, const mcrt::Ray& ray) {
  mcrt::Interval range;
  std::optional<mcrt::Hit> hit;
  for (const mcrt::Sphere& s : scene.spheres())
    if (const auto t = mcrt::intersect_distance(s, ray, range)) {
      range.max = *t;
      hit = mcrt::hit_at(s, ray, *t);
    }
  for (const mcrt::Quad& q : scene.quads())
    if (const auto t = mcrt::intersect_distance(q, ray, range)) {
      range.max = *t;
      hit = mcrt::hit_at(q, ray, *t);
    }
  return hit;
}

template <bool reference>
void closest_hit_queries(benchmark::State& state, const char* scene_name) {
  const mcrt::Scene scene = mcrt::make_scene(scene_name);
  const std::vector<mcrt::Ray> rays = path_rays(scene);
  for (auto _ : state) {
    for (const mcrt::Ray& ray : rays) {
      if constexpr (reference) {
        benchmark::DoNotOptimize(reference_closest_hit(scene, ray));
      } else {
        benchmark::DoNotOptimize(scene.closest_hit(ray));
      }
    }
  }
  state.counters["queries_per_second"] = benchmark::Counter(
      static_cast<double>(rays.size()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
void BM_ClosestHitCornellSpheres(benchmark::State& state) {
  closest_hit_queries<false>(state, "cornell-spheres");
}
void BM_ClosestHitCornell(benchmark::State& state) {
  closest_hit_queries<false>(state, "cornell");
}
void BM_ReferenceClosestHitCornellSpheres(benchmark::State& state) {
  closest_hit_queries<true>(state, "cornell-spheres");
}
void BM_ReferenceClosestHitCornell(benchmark::State& state) {
  closest_hit_queries<true>(state, "cornell");
}
BENCHMARK(BM_ClosestHitCornellSpheres)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_ReferenceClosestHitCornellSpheres)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_ClosestHitCornell)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_ReferenceClosestHitCornell)->Unit(benchmark::kMicrosecond)->MinTime(1.0);

}  // namespace
