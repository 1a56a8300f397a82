#pragma once
/// Russian roulette: chapter 05's path tracer without a depth cut, stopped at random and
/// reweighted so that its expectation is the whole infinite series.
///
///   L ~ sum over vertices j = 0, 1, 2, ... of beta_j Le(x_j)
///
/// At every vertex j >= d (d = min_depth), once Le(x_j) has been added, the path goes on with
/// probability q_j and its weight is divided by q_j:
///
///   beta_{j+1} = beta_j f_r cos(theta_i) / (p(wi) q_j)    (q_j = 1 for j < d)
///
/// A term that survives with probability P and is divided by P keeps its expectation: so
/// E[L] is the sum of every term's expectation, with no depth cut and no bias.
///
/// Two policies pick q_j:
///   fixed       q_j = q, the same at every vertex;
///   throughput  q_j = clamp(max component of beta_j, floor, 1): a path whose weight has
///               fallen carries little light and is stopped more often; one whose weight is
///               still >= 1 is never stopped. A gray weight between the floor and 1 becomes
///               beta_j / q_j = 1 on survival: the weight no longer shrinks with depth, the
///               chance of going on does.
///
/// Closed forms in the furnace (albedo a, emission Le everywhere, every ray hits), uniform
/// hemisphere sampling, so each bounce multiplies the weight by w = 2 a c with c = cos(theta_i)
/// uniform on [0,1]: E[w] = a, E[w^2] = 4 a^2 / 3 = b. Fixed q, and write
///   W_j = w_1 ... w_j        (E[W_j] = a^j, E[W_i W_j] = b^i a^(j-i) for i <= j),
///   P_j = q^max(0, j-d)      (the probability that the path reaches vertex j),
///   I_j = 1 if it does       (I_i I_j = I_max(i,j), independent of the w's),
/// so that L = Le sum_j I_j W_j / P_j.
///
/// Mean:  E[L] = Le sum_j P_j a^j / P_j = Le sum_j a^j = Le / (1 - a)      (a < 1)
///
/// Second moment: for i <= j, E[I_j W_i W_j] / (P_i P_j) = P_j b^i a^(j-i) / (P_i P_j), so
///   E[L^2] = Le^2 sum_i (b^i / P_i) (1 + 2 (a + a^2 + ...)) = Le^2 (1 + a)/(1 - a) S(q),
///   S(q)   = sum_i b^i / P_i = (1 - b^(d+1)) / (1 - b) + b^(d+1) / (q - b),
///   Var[L] = Le^2 ((1 + a)/(1 - a) S(q) - 1/(1 - a)^2),
/// finite only if q > b = 4 a^2 / 3: below it the tail sum of (b/q)^m diverges. Stopping too
/// eagerly costs variance; stopping at q <= b costs all of it. (q = 1 gives S = 1/(1 - b), the
/// untruncated series without roulette, finite only for a < sqrt(3)/2.)
///
/// Path length: the rays a path traces (its vertices, camera ray included) are
///   R = d + 1 + M,   M geometric: P(M = m) = q^m (1 - q),   m = 0, 1, 2, ...
///   E[R] = d + 1/(1 - q).
///
/// The depth cut of chapter 05 at k bounces has E[L_k] = Le (1 - a^(k+1)) / (1 - a): its bias
/// is E[L_k] - Le/(1 - a) = -Le a^(k+1) / (1 - a), the light of every longer path.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/sampling.hpp"
#include "sampling/sphere.hpp"

namespace mcrt {

/// How Russian roulette picks the probability q of going on.
enum class RoulettePolicy { fixed, throughput };

struct Roulette {
  int min_depth = 3;  ///< d: vertices 0..d-1 always go on
  RoulettePolicy policy = RoulettePolicy::throughput;
  double q = 0.8;       ///< fixed: the probability of going on
  double floor = 0.05;  ///< throughput: the least q
};

/// q_j for a path of weight beta: q (fixed) or clamp(max component of beta, floor, 1).
/// Always in (0, 1]: a q above 1 would divide the weight by more than the survival adds.
inline double survival_probability(const Roulette& roulette, const Color& beta) {
  if (roulette.policy == RoulettePolicy::fixed) return roulette.q;
  const double largest = std::max({beta.r, beta.g, beta.b});
  return std::clamp(largest, roulette.floor, 1.0);
}

/// One path's estimate of the radiance arriving along `ray`, with no depth cut: after
/// min_depth vertices the path goes on with probability q and its weight is divided by q.
/// Unbiased for the whole series. Every closest-hit query is counted in `count`.
inline Color estimate_path_radiance_roulette(const Scene& scene, Ray ray, const Roulette& roulette,
                                             Rng& rng, RayCount& count) {
  // ASSIGNMENT a5.1 BEGIN needs=a4.1 stub: (void)scene; (void)ray; (void)roulette; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_path_radiance_roulette);
  Color radiance(0.0);
  Color beta(1.0);  // path weight: product of f_r cos(theta_i) / (pdf(wi) q_j) so far
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;  // the path leaves the scene
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;  // Le(x_j) first: a path stopped here still has it

    if (bounce >= roulette.min_depth) {
      const double q = survival_probability(roulette, beta);
      if (rng.uniform() >= q) break;  // stopped with probability 1 - q ...
      beta /= q;                      // ... and the survivors carry what the stopped lost
    }

    const Vec3 wo = -ray.direction;  // towards where the path came from
    if (material.is_delta()) {       // a mirror or glass: follow the one direction it sends light
      const BsdfSample specular = sample_delta(material, *hit, wo, rng.uniform());
      beta *= specular.weight;  // f_r cos / p of a delta: the tint
      if (beta == Color(0.0)) break;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }
    const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
    const Vec3 wi = Frame(hit->normal).to_world(local);
    const double cos_theta_i = local.z;
    beta *= material.f_r(wi, wo, hit->normal) * cos_theta_i / uniform_hemisphere_pdf();
    if (beta == Color(0.0)) break;  // a black surface: every later term is 0
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
  // ASSIGNMENT a5.1 END
}

// ---------------------------------------------------------------------------------------------
// Furnace studies: many paths from the furnace's centre, where every answer is known.

/// One path of a furnace study: its radiance (the mean of its channels) and the rays it traced.
struct FurnacePath {
  double radiance = 0.0;
  std::uint64_t rays = 0;
};

/// n paths from the centre of `furnace`, path i in a uniformly random direction, all of its
/// random numbers from stream (block, i) of `seed`: the same paths whatever `threads`.
/// `estimate(ray, rng, count)` is the estimator, as render() takes it.
template <class Estimator>
std::vector<FurnacePath> trace_furnace_paths(std::uint64_t n, std::uint64_t seed,
                                             std::uint64_t block, int threads,
                                             Estimator&& estimate) {
  constexpr std::uint64_t k_chunk = 4096;  // paths per task: cheap to hand out, enough to share
  std::vector<FurnacePath> paths(n);
  parallel_for((n + k_chunk - 1) / k_chunk, threads, [&](std::size_t chunk) {
    const std::uint64_t first = chunk * k_chunk, last = std::min(n, first + k_chunk);
    for (std::uint64_t i = first; i < last; ++i) {
      Rng rng(seed, stream_index(block, i));
      const Ray ray{Vec3(0.0), sample_uniform_sphere(rng.uniform2())};
      RayCount count;
      paths[i].radiance = average(estimate(ray, rng, count));
      paths[i].rays = count.rays;
    }
  });
  return paths;
}

// ---------------------------------------------------------------------------------------------
// Furnace closed forms (derived at the top of this file). a is the albedo, Le the emission.

/// E[L] without truncation: Le / (1 - a), for a < 1.
inline double furnace_radiance_untruncated(double albedo, double emission) {
  return emission / (1.0 - albedo);
}

/// The depth cut's bias E[L_k] - Le/(1 - a) = -Le a^(k+1) / (1 - a): the missing light.
inline double furnace_depth_cut_bias(double albedo, double emission, int max_depth) {
  return -emission * std::pow(albedo, max_depth + 1) / (1.0 - albedo);
}

/// b = E[w^2] = 4 a^2 / 3: fixed-q roulette has a finite variance only for q > b.
inline double furnace_roulette_variance_threshold(double albedo) {
  return 4.0 * albedo * albedo / 3.0;
}

/// Var[L] of fixed-q roulette after min_depth d in the furnace:
/// Le^2 ((1 + a)/(1 - a) S(q) - 1/(1 - a)^2), S(q) = (1 - b^(d+1))/(1 - b) + b^(d+1)/(q - b).
/// Infinite (returned as +inf) for q <= b.
inline double furnace_roulette_variance(double albedo, double emission, int min_depth, double q) {
  const double a = albedo, b = furnace_roulette_variance_threshold(albedo);
  if (q <= b) return std::numeric_limits<double>::infinity();
  const double b_d1 = std::pow(b, min_depth + 1);
  // sum_{i=0..d} b^i; written as a sum so that b = 1 (a = sqrt(3)/2) needs no special case.
  double head = 0.0, b_i = 1.0;
  for (int i = 0; i <= min_depth; ++i, b_i *= b) head += b_i;
  const double s = head + b_d1 / (q - b);
  const double variance = (1.0 + a) / (1.0 - a) * s - 1.0 / ((1.0 - a) * (1.0 - a));
  return emission * emission * std::max(0.0, variance);
}

/// E[R], the mean rays (vertices) of a fixed-q path in the furnace: d + 1/(1 - q).
inline double furnace_roulette_mean_rays(int min_depth, double q) {
  return min_depth + 1.0 / (1.0 - q);
}

/// P(R = r): the geometric law of the rays a fixed-q path traces in the furnace,
/// q^(r - d - 1) (1 - q) for r >= d + 1, else 0.
inline double furnace_roulette_length_probability(int min_depth, double q, int rays) {
  const int m = rays - min_depth - 1;
  return m < 0 ? 0.0 : std::pow(q, m) * (1.0 - q);
}

}  // namespace mcrt
