#pragma once
// What a check may ask of the code under test, shared by LocalSubject (the student's functions
// called in-process), RemoteSubject (the same requests sent to the subject program) and the
// subject program's dispatcher. No student header is included here: the checker uses this.

#include <cstdint>
#include <vector>

#include "core/math.hpp"
#include "integration/domain.hpp"

namespace mcrt::testing::assignment {

/// a2's five samplers (each with its pdf).
enum class SamplerKind {
  uniform_hemisphere,
  cosine_hemisphere,
  uniform_sphere,
  unit_disk,
  uniform_cone
};
/// The cone a2.5's sampler is graded on: half-angle acos(0.75) = 41.4 degrees, wide enough that
/// its 21 x 11 cells are not slivers, narrow enough that a hemisphere sampler fails it.
inline constexpr double k_a2_cone_cos_theta_max = 0.75;

/// Request names, as they travel in frames.
inline constexpr const char* k_request_a2_samples = "a2_samples";
inline constexpr const char* k_request_a2_pdf = "a2_pdf";
inline constexpr const char* k_request_a3_single = "a3_single";
inline constexpr const char* k_request_a3_furnace = "a3_furnace";
inline constexpr const char* k_request_a3_predicted_rays = "a3_predicted_rays";

/// A count of up to 64 bits as two doubles (its high and low 32 bits): a double holds whole
/// numbers exactly only below 2^53, and a3's predictions reach 2^64 - 1.
inline void append_count(std::vector<double>& out, std::uint64_t x) {
  out.push_back(static_cast<double>(x >> 32));
  out.push_back(static_cast<double>(x & 0xffffffffULL));
}
inline constexpr const char* k_request_a4_furnace = "a4_furnace";
inline constexpr const char* k_request_a4_sky = "a4_sky";
inline constexpr const char* k_request_a4_single = "a4_single";
/// a4.2: every pixel's estimate of a known radiance, one pixel's ray directions, a furnace's
/// pixel estimates (a4_produce.hpp).
inline constexpr const char* k_request_a4_pixel_exact = "a4_pixel_exact";
inline constexpr const char* k_request_a4_pixel_rays = "a4_pixel_rays";
inline constexpr const char* k_request_a4_pixel_furnace = "a4_pixel_furnace";

/// One path's channel-mean radiance and its rays (a4's single path).
struct PathSample {
  double radiance = 0.0;
  std::uint64_t rays = 0;
};

/// a1's integrands (a1_produce.hpp): exp(-x^2), 3x + 1, x^2, a constant.
enum class A1Integrand { gaussian, line, square, constant };

/// A basic Monte Carlo estimate with its standard error (MonteCarloEstimate's fields).
struct EstimateAndError {
  double estimate = 0.0;
  double standard_error = 0.0;
};

inline constexpr const char* k_request_a1_disk = "a1_disk";
inline constexpr const char* k_request_a1_ball = "a1_ball";
inline constexpr const char* k_request_a1_ball_counts = "a1_ball_counts";
inline constexpr const char* k_request_a1_monte_carlo = "a1_monte_carlo";
inline constexpr const char* k_request_a1_trapezoid = "a1_trapezoid";

/// One of a5's estimators and its parameters, as numbers (a5_produce.hpp converts them).
struct A5Estimator {
  enum Kind { roulette, importance, nee };
  Kind kind = roulette;
  int min_depth = 0;  ///< roulette, nee: the Roulette
  int policy = 0;
  double q = 0.0;
  double floor = 0.0;
  int max_depth = -1;  ///< importance, nee
  int pdf_kind = 0;    ///< importance: the HemispherePdf
  int pdf_m = 0;
};

inline constexpr std::size_t k_a5_estimator_numbers = 8;

inline void append(std::vector<double>& out, const A5Estimator& e) {
  // One push_back per number: insert() of a list into an empty vector trips a false
  // -Wstringop-overflow in g++ 12.
  for (double x : {static_cast<double>(e.kind), static_cast<double>(e.min_depth),
                   static_cast<double>(e.policy), e.q, e.floor, static_cast<double>(e.max_depth),
                   static_cast<double>(e.pdf_kind), static_cast<double>(e.pdf_m)})
    out.push_back(x);
}

inline constexpr const char* k_request_a5_paths = "a5_paths";
inline constexpr const char* k_request_a5_single = "a5_single";
inline constexpr const char* k_request_a5_regions = "a5_regions";
inline constexpr const char* k_request_a5_wall = "a5_wall";

/// a6: the Phong lobe round +z (a6.1), a heuristic's weights (a6.2), the plates' regions (a6.3).
enum class A6Heuristic { balance, power };
/// What a6's region request renders: one of chapter 08's strategies at equal rays.
enum class A6Strategy { light, bsdf, mis_balance, mis_power };
/// The plates render of the a6 region tests: small enough that every sample of the 16 regions
/// travels in one request, large enough that each region holds 16-45 pixels.
inline constexpr int k_a6_width = 96;
inline constexpr int k_a6_height = 72;
inline constexpr const char* k_request_a6_lobe_samples = "a6_lobe_samples";
inline constexpr const char* k_request_a6_lobe_pdf = "a6_lobe_pdf";
inline constexpr const char* k_request_a6_weights = "a6_weights";
inline constexpr const char* k_request_a6_regions = "a6_regions";
/// a6.4: the dielectric's sample at each query, for glass of one index (tint 1, exact Fresnel).
inline constexpr const char* k_request_a6_dielectric = "a6_dielectric";

/// One call of sample_dielectric: wo and n unit, n facing wo, `entering` when wo is outside.
struct DielectricQuery {
  Vec3 wo;
  Vec3 n;
  bool entering = true;
  double u = 0.0;
};
/// What it returned: the direction, the weight (its channels) and whether it refracted.
struct DielectricAnswer {
  Vec3 wi;
  Vec3 weight;
  bool transmitted = false;
};
inline constexpr std::size_t k_dielectric_query_numbers = 8;
inline constexpr std::size_t k_dielectric_answer_numbers = 7;

/// a7: the point sets a student writes (the i-th point of n in [0,1)^d for a key).
enum class A7PointSet { jittered, latin_hypercube, halton };
/// Coordinates of points of a7's sets: for each of key_count keys (key0, key0 + 1, ...), each
/// index asked, each dimension j < d.
inline constexpr const char* k_request_a7_points = "a7_points";
/// phi_b(i) of a7.3 for each index asked.
inline constexpr const char* k_request_a7_radical_inverse = "a7_radical_inverse";

/// A seed, block or count sent as a double: exact below 2^53, which every request stays under.
inline double as_number(std::uint64_t x) { return static_cast<double>(x); }

/// Points travel as x, y, z triples (a disk point with z = 0).
inline std::vector<double> flatten(const std::vector<Vec3>& points) {
  std::vector<double> out;
  out.reserve(points.size() * 3);
  for (const Vec3& p : points) out.insert(out.end(), {p.x, p.y, p.z});
  return out;
}

inline std::vector<Vec3> unflatten3(const double* values, std::size_t count) {
  std::vector<Vec3> out;
  out.reserve(count / 3);
  for (std::size_t i = 0; i + 2 < count; i += 3)
    out.emplace_back(values[i], values[i + 1], values[i + 2]);
  return out;
}

}  // namespace mcrt::testing::assignment
