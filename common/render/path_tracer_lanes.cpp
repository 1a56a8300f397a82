#include "render/path_tracer_lanes.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/hit.hpp"
#include "render/bounce_lanes.hpp"
#include "render/path_tracer.hpp"

namespace mcrt {

// ASSIGNMENT a4.1 BEGIN needs=a2.1 withheld stub: RenderResult render_path_tracer_lanes(const Scene& scene, const Camera& camera, const RenderSettings& settings, int max_depth) { return render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) { return estimate_path_radiance(scene, ray, max_depth, rng, count); }); }
namespace {

constexpr int k_lanes = RayLanes::k_lanes;

// The paths of one row in flight: a row's samples are numbered task = x spp + s and taken in
// that order, a chunk at a time. A chunk's radiances are kept until its last path ends, then
// added to their pixels in task order, which is each pixel's sample order.
class RowOfPaths {
 public:
  // Paths per chunk: enough that the lanes left idle while a chunk's last paths finish (at
  // most max_depth + 1 bounces) are a small part of its work.
  static constexpr std::uint64_t k_chunk = 1024;

  RowOfPaths(const Scene& scene, const Camera& camera, const RenderSettings& settings,
             int max_depth, int y)
      : scene_(scene), camera_(camera), settings_(settings), max_depth_(max_depth), y_(y) {}

  // Traces the row: its pixels' sums of radiance, its rays and its non-finite estimates.
  void trace(std::vector<Color>& pixel_sums, RayCount& count, std::uint64_t& non_finite) {
    const std::uint64_t tasks = static_cast<std::uint64_t>(camera_.width()) * settings_.spp;
    for (std::uint64_t first = 0; first < tasks; first += k_chunk) {
      chunk_first_ = first;
      chunk_end_ = std::min(tasks, first + k_chunk);
      next_task_ = first;
      trace_chunk(count);
      for (std::uint64_t task = first; task < chunk_end_; ++task) {
        const Color& radiance = radiance_[task - first];
        if (!is_finite(radiance)) ++non_finite;
        pixel_sums[task / settings_.spp] += radiance;
      }
    }
  }

 private:
  struct Path {
    Rng rng{0, 0};
    Color radiance{0.0};
    int bounce = 0;
    std::uint64_t task = 0;
  };

  // Lane l starts the chunk's next path, if any is left: its camera ray, as render() makes it.
  bool start_path(int l) {
    if (next_task_ == chunk_end_) return false;
    const std::uint64_t task = next_task_++;
    const auto x = static_cast<int>(task / settings_.spp);
    const std::uint64_t sample = settings_.first_sample + task % settings_.spp;
    const std::uint64_t pixel = static_cast<std::uint64_t>(y_) * camera_.width() + x;
    Path& path = paths_[l];
    path = Path{Rng(settings_.seed, stream_index(pixel, sample)), Color(0.0), 0, task};
    rays_.set(l, camera_.generate_ray(x, y_, path.rng.uniform2()));
    for (int axis = 0; axis < 3; ++axis) bounce_.beta[axis][l] = 1.0;  // beta_0 = 1
    return true;
  }

  Color beta(int l) const { return {bounce_.beta[0][l], bounce_.beta[1][l], bounce_.beta[2][l]}; }

  // estimate_path_radiance's loop, four paths at a time: the search for four rays, then each
  // lane's emission and stopping rules, then the bounce of the lanes that go on.
  void trace_chunk(RayCount& count) {
    std::array<bool, k_lanes> active{};
    for (int l = 0; l < k_lanes; ++l) active[l] = start_path(l);
    while (std::any_of(active.begin(), active.end(), [](bool a) { return a; })) {
      scene_.hits_in_lanes(scene_.closest_hits(rays_), rays_, bounce_.hit);
      for (int l = 0; l < k_lanes; ++l) {
        bounce_.bouncing[l] = false;
        if (!active[l] || !bounce_.hit.found(l)) continue;
        const Material& material = scene_.materials[bounce_.hit.material[l]];
        Path& path = paths_[l];
        path.radiance += beta(l) * material.emission;
        bounce_.bouncing[l] = path.bounce != max_depth_;
        if (!bounce_.bouncing[l]) continue;
        const Vec2 u = path.rng.uniform2();
        bounce_.u0[l] = u.x;
        bounce_.u1[l] = u.y;
        for (int axis = 0; axis < 3; ++axis) bounce_.albedo[axis][l] = material.albedo[axis];
      }
      bounce_lanes(bounce_, rays_);
      for (int l = 0; l < k_lanes; ++l) {
        if (!active[l]) continue;
        ++count.rays;
        // A black surface ends the path exactly: every later term would be multiplied by 0.
        if (bounce_.bouncing[l] && beta(l) != Color(0.0)) {
          ++paths_[l].bounce;
          continue;
        }
        radiance_[paths_[l].task - chunk_first_] = paths_[l].radiance;
        active[l] = start_path(l);
      }
    }
  }

  const Scene& scene_;
  const Camera& camera_;
  const RenderSettings& settings_;
  const int max_depth_;
  const int y_;
  std::uint64_t chunk_first_ = 0, chunk_end_ = 0, next_task_ = 0;
  RayLanes rays_;
  BounceLanes bounce_;
  std::array<Path, k_lanes> paths_;
  std::array<Color, k_chunk> radiance_;
};

}  // namespace

RenderResult render_path_tracer_lanes(const Scene& scene, const Camera& camera,
                                      const RenderSettings& settings, int max_depth) {
  return render_rows(camera, settings, [&](int y, Color* row, RayCount& rays,
                                           std::uint64_t& non_finite) {
    std::vector<Color> sums(camera.width(), Color(0.0));
    RowOfPaths(scene, camera, settings, max_depth, y).trace(sums, rays, non_finite);
    for (int x = 0; x < camera.width(); ++x) row[x] = sums[x] / static_cast<double>(settings.spp);
  });
}

// ASSIGNMENT a4.1 END

}  // namespace mcrt
