#include "integration/disk_area.hpp"

#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "integration/ball.hpp"

namespace mcrt {

double ball_hit_probability(int k) {
  if (k <= 1) return 1.0;  // the segment [-1, 1] is its own cube; pow and tgamma round V_1
  return unit_ball_volume(k) / std::ldexp(1.0, k);
}

double hit_count_mean(std::uint64_t n, double p) { return static_cast<double>(n) * p; }

double hit_count_variance(std::uint64_t n, double p) {
  return static_cast<double>(n) * p * (1.0 - p);
}

double hit_or_miss_std(double box_volume, double p, std::uint64_t n) {
  return box_volume * std::sqrt(p * (1.0 - p) / static_cast<double>(n));
}

double disk_area_theory_std(std::uint64_t n) {
  return hit_or_miss_std(4.0, k_disk_hit_probability, n);
}

double ball_volume_theory_std(int k, std::uint64_t n) {
  return hit_or_miss_std(std::ldexp(1.0, k), ball_hit_probability(k), n);
}

std::uint64_t count_in_ball(int k, std::uint64_t n, Rng& rng) {
  if (k < 0 || k > k_max_ball_dims)
    throw std::invalid_argument("count_in_ball: k = " + std::to_string(k) + " is outside [0, " +
                                std::to_string(k_max_ball_dims) + "]");
  // ASSIGNMENT a1.2 BEGIN stub: (void)n; (void)rng; NOT_IMPLEMENTED(count_in_ball);
  std::array<double, k_max_ball_dims> point;
  const std::span<const double> x(point.data(), static_cast<std::size_t>(k));
  std::uint64_t inside = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    for (int d = 0; d < k; ++d) point[d] = 2.0 * rng.uniform() - 1.0;
    inside += inside_unit_ball(x);
  }
  return inside;
  // ASSIGNMENT a1.2 END
}

double estimate_ball_volume(int k, std::uint64_t n, Rng& rng) {
  // ASSIGNMENT a1.2 BEGIN stub: (void)k; (void)n; (void)rng; NOT_IMPLEMENTED(estimate_ball_volume);
  return std::ldexp(static_cast<double>(count_in_ball(k, n, rng)), k) / static_cast<double>(n);
  // ASSIGNMENT a1.2 END
}

}  // namespace mcrt
