// Speed of chapter 05: rays per second of the path tracer, and closest-hit queries per second.
//
//   bench_path_tracer
//
// BM_PathTracer<Scene>/threads renders cornell-spheres and cornell at 256x192, 16 spp, depth 10
// (the settings of the speed targets) with 1 and 2 threads, four paths at a time
// (render_path_tracer_lanes, what chapter 05 runs); its counter rays_per_second counts every
// closest-hit query. BM_LectureLoopPathTracer<Scene> renders the same image with the lecture's
// loop, one path at a time (render with estimate_path_radiance). BM_ReferencePathTracer<Scene>
// runs that loop on the plain layers below it (render/path_tracer_plain_layers.hpp: a loop of
// intersect_distance over every primitive, phi's cosine and sine from the maths library). All
// three are measured in the same run, so their ratios compare.
// BM_ClosestHit answers queries for a fixed batch of rays (camera rays and bounced rays of
// real paths), so it measures the intersection loop alone; BM_ReferenceClosestHit* answers
// the same queries with the plain loop over intersect_distance.
// BM_ThreadScaling<Scene> (four lanes) and BM_ThreadScalingLectureLoop<Scene> time 1 and 2
// threads in pairs, for the ratio of the two (below); BM_HostProbe* measures the same ratio on
// three small loops, to tell what the host's two cores share.

#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/host_probe.hpp"
#include "bench/path_rays.hpp"
#include "render/path_tracer_plain_layers.hpp"
#include "render/path_tracer.hpp"
#include "engine/path_tracer_lanes.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

namespace {

constexpr int k_depth = 10;

using mcrt::testing::plain_closest_hit;  // render/path_tracer_plain_layers.hpp
using mcrt::testing::plain_path_radiance;

enum class Engine { lecture_loop, plain_layers, lanes };

// The image of the speed targets (256x192, 16 spp, depth 10) rendered by `engine`.
template <Engine engine>
mcrt::RenderResult render_with(const mcrt::Scene& scene, const mcrt::Camera& camera,
                               const mcrt::RenderSettings& settings) {
  if constexpr (engine == Engine::lanes)
    return mcrt::render_path_tracer_lanes(scene, camera, settings, k_depth);
  else
    return mcrt::render(camera, settings,
                        [&](const mcrt::Ray& ray, mcrt::Rng& rng, mcrt::RayCount& count) {
                          if constexpr (engine == Engine::plain_layers)
                            return plain_path_radiance(scene, ray, k_depth, rng, count);
                          else
                            return mcrt::estimate_path_radiance(scene, ray, k_depth, rng, count);
                        });
}

template <Engine engine>
void path_tracer(benchmark::State& state, const char* scene_name) {
  const mcrt::Scene scene = mcrt::make_scene(scene_name);
  const mcrt::Camera camera(scene.camera, 256, 192);
  const int threads = static_cast<int>(state.range(0));
  std::uint64_t rays = 0;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const mcrt::RenderSettings settings{16, 0, seed++, threads, nullptr};
    const mcrt::RenderResult result = render_with<engine>(scene, camera, settings);
    benchmark::DoNotOptimize(result.image.pixels.data());
    rays += result.rays;
  }
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
void BM_PathTracerCornellSpheres(benchmark::State& state) {
  path_tracer<Engine::lanes>(state, "cornell-spheres");
}
void BM_PathTracerCornell(benchmark::State& state) { path_tracer<Engine::lanes>(state, "cornell"); }
void BM_LectureLoopPathTracerCornellSpheres(benchmark::State& state) {
  path_tracer<Engine::lecture_loop>(state, "cornell-spheres");
}
void BM_LectureLoopPathTracerCornell(benchmark::State& state) {
  path_tracer<Engine::lecture_loop>(state, "cornell");
}
void BM_ReferencePathTracerCornellSpheres(benchmark::State& state) {
  path_tracer<Engine::plain_layers>(state, "cornell-spheres");
}
void BM_ReferencePathTracerCornell(benchmark::State& state) {
  path_tracer<Engine::plain_layers>(state, "cornell");
}
// Wall-clock time: with 2 threads the CPU time of the main thread alone would mislead.
BENCHMARK(BM_PathTracerCornellSpheres)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_LectureLoopPathTracerCornellSpheres)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_ReferencePathTracerCornellSpheres)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_PathTracerCornell)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_LectureLoopPathTracerCornell)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_ReferencePathTracerCornell)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

// Two-thread scaling, measured in pairs: each iteration renders the image of BM_PathTracer
// with 1 thread and with 2 (which goes first alternates), each timed alone. The counters are
// the two rates over the whole run and their ratio, `scaling`. A pair is a fraction of a
// second apart, so a host whose speed drifts over seconds or minutes (a shared virtual
// machine's does, by 20 % or more) slows both alike, and the ratio stays where the ratio of two
// separate benchmarks, run a minute apart, would not.
template <Engine engine>
void thread_scaling(benchmark::State& state, const char* scene_name) {
  const mcrt::Scene scene = mcrt::make_scene(scene_name);
  const mcrt::Camera camera(scene.camera, 256, 192);
  double seconds[3] = {0.0, 0.0, 0.0};  // by thread count
  std::uint64_t rays[3] = {0, 0, 0};
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const int first = seed % 2 == 1 ? 1 : 2;
    for (const int threads : {first, 3 - first}) {
      const mcrt::RenderSettings settings{16, 0, seed, threads, nullptr};
      const auto start = std::chrono::steady_clock::now();
      const mcrt::RenderResult result = render_with<engine>(scene, camera, settings);
      seconds[threads] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      benchmark::DoNotOptimize(result.image.pixels.data());
      rays[threads] += result.rays;
    }
    ++seed;
  }
  const double one = static_cast<double>(rays[1]) / seconds[1];
  const double two = static_cast<double>(rays[2]) / seconds[2];
  state.counters["one_thread_rays_per_second"] = one;
  state.counters["two_threads_rays_per_second"] = two;
  state.counters["scaling"] = two / one;
}
void BM_ThreadScalingCornellSpheres(benchmark::State& state) {
  thread_scaling<Engine::lanes>(state, "cornell-spheres");
}
void BM_ThreadScalingCornell(benchmark::State& state) {
  thread_scaling<Engine::lanes>(state, "cornell");
}
void BM_ThreadScalingLectureLoopCornellSpheres(benchmark::State& state) {
  thread_scaling<Engine::lecture_loop>(state, "cornell-spheres");
}
void BM_ThreadScalingLectureLoopCornell(benchmark::State& state) {
  thread_scaling<Engine::lecture_loop>(state, "cornell");
}
BENCHMARK(BM_ThreadScalingCornellSpheres)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(4.0);
BENCHMARK(BM_ThreadScalingCornell)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(4.0);
BENCHMARK(BM_ThreadScalingLectureLoopCornellSpheres)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(4.0);
BENCHMARK(BM_ThreadScalingLectureLoopCornell)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(4.0);

// The host's own two-thread scaling, measured the same way, on the three loops of
// bench/host_probe.hpp: `work` is run by one thread, then by two at once (which goes first
// alternates), and `scaling` is twice the one thread's time over the two threads'.
template <class Work>
void host_probe(benchmark::State& state, Work work) {
  double seconds[3] = {0.0, 0.0, 0.0};  // by thread count
  int turn = 0;
  for (auto _ : state) {
    const int first = turn++ % 2 == 0 ? 1 : 2;
    for (const int threads : {first, 3 - first}) {
      const auto start = std::chrono::steady_clock::now();
      if (threads == 1) {
        work();
      } else {
        std::thread other(work);
        work();
        other.join();
      }
      seconds[threads] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  }
  state.counters["scaling"] = 2.0 * seconds[1] / seconds[2];  // twice the work in seconds[2]
}
template <int Chains>
void multiply_add_probe(benchmark::State& state) {
#if defined(__x86_64__)
  if (!mcrt::bench::cpu_has_avx2_and_fma()) {
    state.SkipWithError("the probe needs AVX2 and FMA");
    return;
  }
  constexpr std::uint64_t steps = Chains == 1 ? 40'000'000 : 10'000'000;  // 15-45 ms each
  host_probe(state,
             [] { benchmark::DoNotOptimize(mcrt::bench::multiply_add_chains<Chains>(steps)); });
#else
  state.SkipWithError("the probe is written for x86-64");
#endif
}
void BM_HostProbeDependentMultiplyAdds(benchmark::State& state) { multiply_add_probe<1>(state); }
void BM_HostProbeIndependentMultiplyAdds(benchmark::State& state) { multiply_add_probe<12>(state); }
void BM_HostProbeStoresAndLoads(benchmark::State& state) {
  host_probe(state, [] {
    volatile std::uint64_t counters[12] = {};               // on each thread's own stack
    mcrt::bench::increment_counters(counters, 20'000'000);  // some 90 ms
  });
}
BENCHMARK(BM_HostProbeDependentMultiplyAdds)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_HostProbeIndependentMultiplyAdds)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_HostProbeStoresAndLoads)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

using mcrt::bench::path_rays;

template <bool reference>
void closest_hit_queries(benchmark::State& state, const char* scene_name) {
  const mcrt::Scene scene = mcrt::make_scene(scene_name);
  const std::vector<mcrt::Ray> rays = path_rays(scene);
  for (auto _ : state) {
    for (const mcrt::Ray& ray : rays) {
      if constexpr (reference) {
        benchmark::DoNotOptimize(plain_closest_hit(scene, ray));
      } else {
        benchmark::DoNotOptimize(scene.closest_hit(ray));
      }
    }
  }
  state.counters["queries_per_second"] =
      benchmark::Counter(static_cast<double>(rays.size()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
void BM_ClosestHitCornellSpheres(benchmark::State& state) {
  closest_hit_queries<false>(state, "cornell-spheres");
}
void BM_ClosestHitCornell(benchmark::State& state) { closest_hit_queries<false>(state, "cornell"); }
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
