#pragma once
/// The work of several renders added up: the rays they traced, the samples that came out NaN
/// or infinite, and the seconds they took. Chapters report it per row and for the whole run.

#include <cstdint>

#include "render/render.hpp"

namespace mcrt {

struct RenderTotals {
  std::uint64_t rays = 0;
  std::uint64_t non_finite_samples = 0;
  double seconds = 0.0;

  void add(const RenderResult& result) {
    rays += result.rays;
    non_finite_samples += result.non_finite_samples;
    seconds += result.seconds;
  }
  /// rays / seconds, or 0 before any time has been measured.
  double rays_per_second() const {
    return seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0;
  }
};

/// The totals of one render.
inline RenderTotals totals_of(const RenderResult& result) {
  RenderTotals totals;
  totals.add(result);
  return totals;
}

}  // namespace mcrt
