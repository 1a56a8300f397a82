#include "engine/path_tracer_lanes.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "geometry/hit.hpp"
#include "engine/bounce_lanes.hpp"
#include "engine/path_lanes.hpp"
#include "engine/path_starts.hpp"
#include "render/path_tracer.hpp"
#include "render/sampled_render.hpp"
#include "render/specular.hpp"
#include "sampling/path_sampler.hpp"

namespace mcrt {

// ASSIGNMENT a4.1 BEGIN needs=a2.1 withheld stub: RenderResult render_path_tracer_lanes(const Scene& scene, const Camera& camera, const RenderSettings& settings, int max_depth, PathSampler sampler) { return render_sampled(camera, settings, sampler, [&](const Ray& ray, auto& uniforms, RayCount& count) { return estimate_path_radiance(scene, ray, max_depth, uniforms, count); }); }
namespace {

constexpr int k_lanes = RayLanes::k_lanes;

// A lane's sample of a pixel's padded sets: PaddedSample's points, made when they are taken
// (the lanes of other paths hide each point's latency, so no point is made ahead).
struct LaneSample {
  PaddedPixel* pixel = nullptr;
  std::uint32_t index = 0;
  unsigned set = 0;  // the set of the next point
  Vec2 uniform2() { return pixel->point(index, set++); }
};

// The paths of one row in flight: a row's samples are numbered task = x spp + s and taken in
// that order, a chunk at a time. A chunk's radiances are kept until its last path ends, then
// added to their pixels in task order, which is each pixel's sample order.
class RowOfPaths {
 public:
  // Paths per chunk: enough that the lanes left idle while a chunk's last paths finish (at
  // most max_depth + 1 bounces) are a small part of its work.
  static constexpr std::uint64_t k_chunk = 1024;

  // With a padded sampler, `pixels` holds the row's PaddedPixels, made as their first samples
  // start (its capacity is kept from row to row).
  RowOfPaths(const Scene& scene, const Camera& camera, const RenderSettings& settings,
             int max_depth, int y, PathSampler sampler, std::vector<PaddedPixel>& pixels)
      : scene_(scene),
        camera_(camera),
        settings_(settings),
        max_depth_(max_depth),
        y_(y),
        sampler_(sampler),
        pixels_(pixels),
        tasks_(static_cast<std::uint64_t>(camera.width()) * settings.spp) {
    pixels_.clear();
    if (padded()) pixels_.reserve(static_cast<std::size_t>(camera.width()));  // no moves later
    // A diffuse scene spares shade_lanes the look at each lane's lobe.
    const bool lobes = std::ranges::any_of(scene.materials, &Material::has_lobe);
    for (PathGroup& g : groups_) g.bounce.lobes_possible = lobes;
    // A scene without mirrors or glass spares step() the look for delta lanes.
    deltas_possible_ = std::ranges::any_of(scene.materials, &Material::is_delta);
  }

  // Traces the row: its pixels' sums of radiance, its rays and its non-finite estimates.
  void trace(std::vector<Color>& pixel_sums, RayCount& count, std::uint64_t& non_finite) {
    RowSample added;  // the pixel and sample of the task whose radiance is added next
    for (std::uint64_t first = 0; first < tasks_; first += k_chunk) {
      chunk_first_ = first;
      chunk_end_ = std::min(tasks_, first + k_chunk);  // the last chunk took up to `first`
      trace_chunk(count);
      for (std::uint64_t task = first; task < chunk_end_; ++task) {
        const Color& radiance = radiance_[task - first];
        if (!is_finite(radiance)) ++non_finite;
        pixel_sums[added.x] += radiance;
        added.advance(settings_.spp);
      }
    }
  }

 private:
  // Four paths in flight, one per lane.
  struct PathGroup {
    RayLanes rays;
    BounceLanes bounce;
    PathLanes paths;
    std::array<std::uint64_t, k_lanes> task{};  // each lane's path: x spp + s
    // With a padded sampler, each lane's uniforms: its sample's points in the pixel's sets (the
    // lanes' generators are then left unused).
    std::array<LaneSample, k_lanes> sample;
  };

  bool padded() const { return sampler_ != PathSampler::independent; }

  // Each group's bounce is one chain of dependent steps (the search, the hits, the shading,
  // the bounce, then the next search), so two groups take turns: the processor works on one
  // group's search while the other's bounce waits on its latencies.
  static constexpr int k_groups = 2;

  // Lane l of group g (ready for a new path: engine/path_lanes.hpp) starts the chunk's next
  // path, if any is left: its generator and its camera ray, as render() makes them. Tasks are
  // taken in order, so their starts are made a block at a time (engine/path_starts.hpp).
  void start_path(PathGroup& g, int l) {
    if (next_task_ == chunk_end_) {
      g.paths.stop(l);
      return;
    }
    if (padded()) {
      start_padded_path(g, l);
      return;
    }
    if (next_start_ == PathStarts::k_capacity) {
      const auto left =
          static_cast<int>(std::min<std::uint64_t>(tasks_ - next_task_, PathStarts::k_capacity));
      make_path_starts(camera_, settings_, y_, next_sample_, left, starts_);
      next_start_ = 0;
    }
    g.task[l] = next_task_++;
    g.paths.start_at(l, starts_.state[next_start_], starts_.increment[next_start_]);
    g.rays.set(l, starts_.ray(next_start_));
    ++next_start_;
  }

  // As render_sampled starts sample s of pixel x: the pixel's sets made when its first sample
  // starts, the ray through the sample's point of set 0.
  void start_padded_path(PathGroup& g, int l) {
    const RowSample at = next_sample_;
    next_sample_.advance(settings_.spp);
    if (at.sample == 0) {
      const std::uint64_t pixel = static_cast<std::uint64_t>(y_) * camera_.width() + at.x;
      pixels_.emplace_back(sampler_,
                           PaddedPixel::pixel_key(settings_.seed, pixel, settings_.first_sample),
                           static_cast<std::uint32_t>(settings_.spp));
    }
    g.task[l] = next_task_++;
    g.paths.start_at(l, 0, 1);  // the lane's generator is not drawn from
    g.sample[l] = {&pixels_[static_cast<std::size_t>(at.x)], static_cast<std::uint32_t>(at.sample)};
    g.rays.set(l, camera_.generate_ray(at.x, y_, g.sample[l].uniform2()));
  }

  // With a padded sampler, every bouncing lane but those at a delta takes its two uniforms from
  // its sample's next set, in place of the two shade_lanes drew from its generator.
  static void take_padded_uniforms(PathGroup& g) {
    for (int l = 0; l < k_lanes; ++l)
      if (g.bounce.bouncing[l] != 0) {
        const Vec2 u = g.sample[l].uniform2();
        g.bounce.u0[l] = u.x;
        g.bounce.u1[l] = u.y;
      }
  }

  // One pass of estimate_path_radiance's loop for the group's four paths (engine/path_lanes.hpp);
  // a lane whose path ends hands its radiance in and takes the chunk's next path. False when
  // the group has no path left.
  bool step(PathGroup& g, RayCount& count) {
    const unsigned live = g.paths.live_lanes();
    if (live == 0) return false;
    const Scene::ClosestLanes nearest = scene_.closest_hits(g.rays);
    scene_.hits_in_lanes(nearest, g.rays, g.bounce.hit);
    std::array<std::uint64_t, k_lanes> generators{};  // before shade_lanes' two draws
    if (deltas_possible_) generators = g.paths.rng.state;
    shade_lanes(scene_.materials, max_depth_, g.paths, g.bounce);
    const unsigned delta = deltas_possible_ ? delta_lanes(g) : 0u;
    if (padded()) take_padded_uniforms(g);
    bounce_lanes(g.bounce, g.rays);
    for (unsigned left = delta; left != 0; left &= left - 1)
      bounce_delta_lane(g, nearest, std::countr_zero(left), generators);
    count.rays += static_cast<std::uint64_t>(std::popcount(live));
    for (unsigned ended = end_lanes(g.paths, g.bounce); ended != 0; ended &= ended - 1) {
      const int l = std::countr_zero(ended);
      radiance_[g.task[l] - chunk_first_] = g.paths.finished_of(l);
      start_path(g, l);
    }
    return true;
  }

  // The bouncing lanes at a mirror or glass, as bits 0-3. bounce_lanes leaves them alone (their
  // `bouncing` is cleared here, and set again by bounce_delta_lane).
  unsigned delta_lanes(PathGroup& g) const {
    unsigned delta = 0;
    for (int l = 0; l < k_lanes; ++l)
      if (g.bounce.bouncing[l] != 0 &&
          scene_.materials[static_cast<std::size_t>(g.bounce.hit.material[l])].is_delta()) {
        delta |= 1u << l;
        g.bounce.bouncing[l] = 0;
      }
    return delta;
  }

  // estimate_path_radiance's delta branch for lane l, after bounce_lanes (which left the lane's
  // ray, the one that reached the hit, as it was): the lane's Hit from the search, as
  // closest_hit builds it (front_face included, which HitLanes does not keep); one uniform of
  // the lane's generator, from its state before shade_lanes drew two; beta times the delta's
  // weight; the specular ray. end_lanes then ends the path on a black weight, as the loop does.
  void bounce_delta_lane(PathGroup& g, const Scene::ClosestLanes& nearest, int l,
                         const std::array<std::uint64_t, k_lanes>& generators) const {
    const Ray ray = g.rays.get(l);
    const Hit hit = *scene_.hit_in_lane(nearest, l, ray);
    double u;
    if (padded()) {
      u = g.sample[l].uniform2().x;  // PaddedSample::uniform(): the set's first coordinate
    } else {
      g.paths.rng.state[l] = generators[l];
      u = g.paths.rng.next(l) * 0x1p-32;  // Rng::uniform()
    }
    const BsdfSample specular = sample_delta(scene_.material(hit), hit, -ray.direction, u);
    for (int axis = 0; axis < 3; ++axis) g.bounce.beta[axis][l] *= specular.weight[axis];
    g.rays.set(l, spawn_ray(hit, specular.wi));
    g.bounce.bouncing[l] = -1;
  }

  void trace_chunk(RayCount& count) {
    for (PathGroup& g : groups_)
      for (int l = 0; l < k_lanes; ++l) start_path(g, l);
    for (bool any = true; any;) {
      any = false;
      for (PathGroup& g : groups_) any = step(g, count) || any;
    }
  }

  const Scene& scene_;
  const Camera& camera_;
  const RenderSettings& settings_;
  const int max_depth_;
  const int y_;
  const PathSampler sampler_;
  std::vector<PaddedPixel>& pixels_;  // padded: the row's pixels whose first sample started
  bool deltas_possible_ = false;      // some material is a mirror or glass
  const std::uint64_t tasks_;         // the row's paths: width x spp
  std::uint64_t chunk_first_ = 0, chunk_end_ = 0, next_task_ = 0;
  PathStarts starts_;  // the starts of the tasks from next_task_ on, from entry next_start_
  int next_start_ = PathStarts::k_capacity;
  RowSample next_sample_;  // the sample of the first task after those in starts_ (padded: of
                           // next_task_)
  std::array<PathGroup, k_groups> groups_;
  std::array<Color, k_chunk> radiance_;
};

}  // namespace

RenderResult render_path_tracer_lanes(const Scene& scene, const Camera& camera,
                                      const RenderSettings& settings, int max_depth,
                                      PathSampler sampler) {
  return render_rows(
      camera, settings, [&](int y, Color* row, RayCount& rays, std::uint64_t& non_finite) {
        std::vector<Color> sums(camera.width(), Color(0.0));
        thread_local std::vector<PaddedPixel> pixels;  // a pixel is ~10 KiB: kept, not remade
        RowOfPaths(scene, camera, settings, max_depth, y, sampler, pixels)
            .trace(sums, rays, non_finite);
        for (int x = 0; x < camera.width(); ++x)
          row[x] = sums[x] / static_cast<double>(settings.spp);
      });
}

// ASSIGNMENT a4.1 END

}  // namespace mcrt
