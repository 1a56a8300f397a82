#pragma once
// Chapter 08's estimators by name: the five of the shoot-out and MIS with either heuristic.
// Chapters 05 and 07 cut their paths at a depth; in the shoot-out they cut at --depth when it
// is given, else at k_baseline_depth, deep enough that the light they miss (a^65 of it, a the
// albedo) is far below any error measured. The others end paths by Russian roulette (and at
// --depth when given).

#include <array>
#include <string_view>

#include "render/importance_path_tracer.hpp"
#include "render/mis.hpp"
#include "render/next_event_estimation.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"

namespace mcrt {

inline constexpr int k_baseline_depth = 64;

enum class EstimatorKind { uniform, cosine, cosine_rr, nee, mis_balance, mis_power };

struct EstimatorInfo {
  EstimatorKind kind;
  std::string_view name;
  std::string_view label;  // for figures
};

inline constexpr std::array<EstimatorInfo, 6> k_estimators{{
    {EstimatorKind::uniform, "uniform", "uniform (05)"},
    {EstimatorKind::cosine, "cosine", "cosine (07)"},
    {EstimatorKind::cosine_rr, "cosine_rr", "cosine + RR (06)"},
    {EstimatorKind::nee, "nee", "NEE"},
    {EstimatorKind::mis_balance, "mis_balance", "NEE + MIS balance"},
    {EstimatorKind::mis_power, "mis_power", "NEE + MIS power"},
}};

// The estimator as render() takes it: Color(const Ray&, Rng&, RayCount&).
inline auto make_estimator(EstimatorKind kind, const Scene& scene, int depth) {
  const PathEnd end{Roulette{}, depth};
  const int cut = depth >= 0 ? depth : k_baseline_depth;
  return [kind, &scene, end, cut](const Ray& ray, Rng& rng, RayCount& count) {
    switch (kind) {
      case EstimatorKind::uniform: return estimate_path_radiance(scene, ray, cut, rng, count);
      case EstimatorKind::cosine:
        return estimate_importance_path_radiance(scene, ray, cut, cosine_power_pdf(1), rng, count);
      case EstimatorKind::cosine_rr:
        return estimate_cosine_roulette_radiance(scene, ray, end, rng, count);
      case EstimatorKind::nee: return estimate_nee_radiance(scene, ray, end, rng, count);
      case EstimatorKind::mis_balance:
        return estimate_mis_radiance(scene, ray, end, MisHeuristic::balance, rng, count);
      case EstimatorKind::mis_power: break;
    }
    return estimate_mis_radiance(scene, ray, end, MisHeuristic::power, rng, count);
  };
}

}  // namespace mcrt
