#pragma once
// LocalSubject: every request answered by calling the student's functions in this process.
// The ordinary test suite and a kit's self-grading use it (fast, nothing to start); the
// subject program answers a checker's requests with it (subject_main.cpp). It is the only
// place of the assignment tests that calls a student's function.

#include <stdexcept>
#include <vector>

#include "assignments/a1/a1_produce.hpp"
#include "assignments/a3/a3_produce.hpp"
#include "assignments/a4/a4_produce.hpp"
#include "assignments/a5/a5_produce.hpp"
#include "assignments/a6/a6_produce.hpp"
#include "assignments/a7/a7_produce.hpp"
#include "assignments/subject/requests.hpp"
#include "integration/disk_area.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/quadrature.hpp"
#include "render/glossy_direct.hpp"
#include "render/mis.hpp"
#include "render/path_tracer.hpp"
#include "render/pixel_estimate.hpp"
#include "render/specular.hpp"
#include "sampling/cone.hpp"
#include "sampling/hemisphere.hpp"
#include "sampling/phong.hpp"
#include "sampling/plane.hpp"
#include "sampling/sphere.hpp"

namespace mcrt::testing::assignment {

/// a1's producer with the student's functions.
inline auto student_a1() {
  return a1_producer([](std::uint64_t n, Rng& rng) { return estimate_disk_area(n, rng); },
                     [](int k, std::uint64_t n, Rng& rng) {
                       return estimate_ball_volume(k, n, rng);
                     },
                     [](int k, std::uint64_t n, Rng& rng) { return count_in_ball(k, n, rng); },
                     [](const auto& f, const Segment& s, std::uint64_t n, Rng& rng) {
                       return monte_carlo(f, s, n, rng);
                     },
                     [](const auto& f, const Segment& s, std::uint64_t n) {
                       return trapezoid(f, s, n);
                     });
}

/// a5's producer with the student's three estimators.
inline auto student_a5() {
  return a5_producer(estimate_path_radiance_roulette, estimate_importance_path_radiance,
                     estimate_nee_radiance);
}

struct LocalSubject {
  /// a1: the student's estimators, each from Rng(seed, stream) (A1Producer), and the answers file.
  double a1_disk(std::uint64_t n, std::uint64_t seed, std::uint64_t stream) const {
    return student_a1().a1_disk(n, seed, stream);
  }
  double a1_ball(int k, std::uint64_t n, std::uint64_t seed, std::uint64_t stream) const {
    return student_a1().a1_ball(k, n, seed, stream);
  }
  std::vector<std::uint64_t> a1_ball_counts(const std::vector<std::array<std::uint64_t, 2>>& calls,
                                            std::uint64_t seed, std::uint64_t stream) const {
    return student_a1().a1_ball_counts(calls, seed, stream);
  }
  EstimateAndError a1_monte_carlo(A1Integrand f, double param, Segment s, std::uint64_t n,
                                  std::uint64_t seed, std::uint64_t stream) const {
    return student_a1().a1_monte_carlo(f, param, s, n, seed, stream);
  }
  double a1_trapezoid(A1Integrand f, double param, Segment s, std::uint64_t n) const {
    return student_a1().a1_trapezoid(f, param, s, n);
  }

  /// a2: the sampler `kind` at each u (a disk point with z = 0).
  std::vector<Vec3> samples(SamplerKind kind, const std::vector<Vec2>& u) const {
    std::vector<Vec3> out;
    out.reserve(u.size());
    for (const Vec2& x : u) {
      switch (kind) {
        case SamplerKind::uniform_hemisphere: out.push_back(sample_uniform_hemisphere(x)); break;
        case SamplerKind::cosine_hemisphere: out.push_back(sample_cosine_hemisphere(x)); break;
        case SamplerKind::uniform_sphere: out.push_back(sample_uniform_sphere(x)); break;
        case SamplerKind::unit_disk: {
          const Vec2 d = sample_uniform_disk(x);
          out.emplace_back(d.x, d.y, 0.0);
          break;
        }
        case SamplerKind::uniform_cone:
          out.push_back(sample_uniform_cone(x, k_a2_cone_cos_theta_max));
          break;
      }
    }
    return out;
  }

  /// a2: the pdf of sampler `kind` at each point (per steradian; per unit area for the disk).
  std::vector<double> pdf_values(SamplerKind kind, const std::vector<Vec3>& points) const {
    std::vector<double> out;
    out.reserve(points.size());
    for (const Vec3& w : points) {
      switch (kind) {
        case SamplerKind::uniform_hemisphere: out.push_back(uniform_hemisphere_pdf()); break;
        case SamplerKind::cosine_hemisphere: out.push_back(cosine_hemisphere_pdf(w.z)); break;
        case SamplerKind::uniform_sphere: out.push_back(uniform_sphere_pdf()); break;
        case SamplerKind::unit_disk: out.push_back(uniform_disk_pdf()); break;
        case SamplerKind::uniform_cone:
          out.push_back(uniform_cone_pdf(w.z, k_a2_cone_cos_theta_max));
          break;
      }
    }
    return out;
  }

  /// a3: one call of incident_radiance (A3Producer::recursive_single).
  PathSample recursive_single(double albedo, double emission, Vec3 origin, Vec3 direction, int n,
                              int k, std::uint64_t seed, std::uint64_t stream) const {
    return a3_producer(incident_radiance)
        .recursive_single(albedo, emission, origin, direction, n, k, seed, stream);
  }

  /// a3: furnace samples of incident_radiance (A3Producer::recursive_furnace).
  std::vector<double> recursive_furnace(double albedo, int n, int k, int samples,
                                        std::uint64_t seed, std::uint64_t block) const {
    return a3_producer(incident_radiance).recursive_furnace(albedo, n, k, samples, seed, block);
  }

  /// a3.2: max_rays_per_sample(N, k) for each (N, k).
  std::vector<std::uint64_t> predicted_rays(const std::vector<std::array<int, 2>>& calls) const {
    std::vector<std::uint64_t> out;
    out.reserve(calls.size());
    for (const auto& [n, k] : calls) out.push_back(max_rays_per_sample(n, k));
    return out;
  }

  /// a4: n furnace paths of estimate_path_radiance (furnace_values).
  std::vector<double> path_furnace(double albedo, int depth, int n, std::uint64_t seed,
                                   std::uint64_t block) const {
    return furnace_values(estimate_path_radiance<Rng>, albedo, depth, n, seed, block);
  }

  /// a4: every sample of the sky scene's size x size render (sky_values).
  std::vector<double> path_sky(int size, int depth, int spp, std::uint64_t seed) const {
    return sky_values(estimate_path_radiance<Rng>, size, depth, spp, seed);
  }

  /// a4: one furnace path from the centre along `direction` (furnace_path).
  PathSample path_single(double albedo, double emission, Vec3 direction, int depth,
                         std::uint64_t seed, std::uint64_t stream) const {
    return furnace_path(estimate_path_radiance<Rng>, albedo, emission, direction, depth, seed,
                        stream);
  }

  /// a4.2: the student's estimate_pixel, as a4_produce.hpp's producers take it.
  static auto student_pixel() {
    return [](const Camera& camera, int x, int y, int spp, auto&& radiance, Rng& rng) {
      return estimate_pixel(camera, x, y, spp, radiance, rng);
    };
  }
  std::vector<double> pixel_exact(int spp, std::uint64_t seed) const {
    return pixel_exact_values(student_pixel(), spp, seed);
  }
  std::vector<Vec3> pixel_rays(int x, int y, int spp, std::uint64_t seed,
                               std::uint64_t stream) const {
    return pixel_ray_directions(student_pixel(), x, y, spp, seed, stream);
  }
  /// a4.2 on the furnace's path law (not the student's a4.1: a4.2 is graded on its own).
  std::vector<double> pixel_furnace(double albedo, int depth, int size, int spp,
                                    std::uint64_t seed) const {
    return pixel_furnace_values(student_pixel(), albedo, depth, size, spp, seed);
  }

  /// a5: the estimator `e` names, run by A5Producer with the student's three estimators.
  std::vector<FurnacePath> a5_paths(const A5Estimator& e, double albedo, int n, std::uint64_t seed,
                                    std::uint64_t block) const {
    return student_a5().a5_paths(e, albedo, n, seed, block);
  }
  PathSample a5_single(const A5Estimator& e, double albedo, double emission, Vec3 direction,
                       std::uint64_t seed, std::uint64_t stream) const {
    return student_a5().a5_single(e, albedo, emission, direction, seed, stream);
  }
  std::vector<double> a5_regions(const A5Estimator& e, int lamp_parts, int size, int spp,
                                 std::uint64_t seed) const {
    return student_a5().a5_regions(e, lamp_parts, size, spp, seed);
  }
  std::vector<double> a5_wall(const A5Estimator& e, int n, std::uint64_t seed) const {
    return student_a5().a5_wall(e, n, seed);
  }

  /// a6.1: the lobe's local sampler at each u, its pdf round `reflected` at each point.
  std::vector<Vec3> a6_lobe_samples(double m, const std::vector<Vec2>& u) const {
    std::vector<Vec3> out;
    out.reserve(u.size());
    for (const Vec2& x : u) out.push_back(sample_phong_lobe_local(x, m));
    return out;
  }
  std::vector<double> a6_lobe_pdf(double m, Vec3 reflected, const std::vector<Vec3>& points) const {
    std::vector<double> out;
    out.reserve(points.size());
    for (const Vec3& w : points) out.push_back(phong_lobe_pdf(w, reflected, m));
    return out;
  }

  /// a6.2: the heuristic's weight w(p_s, p_o) of each pair.
  std::vector<double> a6_weights(A6Heuristic h, const std::vector<Vec2>& pairs) const {
    std::vector<double> out;
    out.reserve(pairs.size());
    for (const Vec2& p : pairs)
      out.push_back(h == A6Heuristic::power ? power_heuristic(p.x, p.y)
                                            : balance_heuristic(p.x, p.y));
    return out;
  }

  /// a6.3: every sample of the plates' 16 regions by `strategy` (a6_region_samples), with the
  /// student's estimate_mis.
  std::vector<double> a6_regions(A6Strategy strategy, int width, int height, int spp,
                                 std::uint64_t seed) const {
    return a6_region_samples(
        [](const VeachPlates& scene, const Hit& hit, const Vec3& wo, MisHeuristic h, Rng& rng,
           RayCount& count) { return estimate_mis(scene, hit, wo, h, rng, count); },
        strategy, width, height, spp, seed);
  }

  /// a6.4: the student's sample_dielectric at each query, for glass of index `ior`.
  std::vector<DielectricAnswer> a6_dielectric(double ior,
                                              const std::vector<DielectricQuery>& queries) const {
    return dielectric_answers([](const Material& m, const Vec3& wo, const Vec3& n, bool entering,
                                 double u) { return sample_dielectric(m, wo, n, entering, u); },
                              ior, queries);
  }

  /// a7.1-a7.4: the student's point sets and radical inverse (A7Producer).
  std::vector<double> a7_points(A7PointSet kind, std::uint32_t n, unsigned d, std::uint64_t key0,
                                std::uint32_t key_count,
                                const std::vector<std::uint32_t>& indices) const {
    return a7_with().a7_points(kind, n, d, key0, key_count, indices);
  }
  std::vector<double> a7_radical_inverse(std::uint32_t base,
                                         const std::vector<std::uint32_t>& indices) const {
    return a7_with().a7_radical_inverse(base, indices);
  }

  void stop() {}  // nothing runs apart from this process
};

}  // namespace mcrt::testing::assignment
