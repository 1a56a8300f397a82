#pragma once
// RemoteSubject: the requests of LocalSubject sent to the subject program, a separate process
// built from the student's files alone, started through a launcher (scripts/sandbox-run: as
// `nobody` when root, a session and process group of its own, limits) and killed, its whole
// process group, by stop(). A checker (a test program built from the instructor's sources
// only) uses it, so no student code runs in the process that writes the verdicts.
//
// The program is $MCRT_SUBJECT (default: the subject built beside the checker), its launcher
// $MCRT_SUBJECT_LAUNCHER (default: none). A request that gets no valid answer (the program
// ended, printed something that is not a frame of this run, answered out of time) throws
// std::runtime_error naming the request; an "error" answer throws its message.

#include <sys/types.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "assignments/subject/protocol.hpp"
#include "assignments/subject/requests.hpp"
#include "render/russian_roulette.hpp"  // FurnacePath (the checker's tree: the instructor's file)

namespace mcrt::testing::assignment {

/// An answer takes at most this long: below the grader's 60 s per test, so that a hanging
/// subject fails its test with a message naming the request rather than by the test's limit.
inline constexpr double k_answer_seconds = 50.0;

class RemoteSubject {
 public:
  RemoteSubject() = default;
  RemoteSubject(const RemoteSubject&) = delete;
  RemoteSubject& operator=(const RemoteSubject&) = delete;
  ~RemoteSubject() { stop(); }

  double a1_disk(std::uint64_t n, std::uint64_t seed, std::uint64_t stream);
  double a1_ball(int k, std::uint64_t n, std::uint64_t seed, std::uint64_t stream);
  std::vector<std::uint64_t> a1_ball_counts(const std::vector<std::array<std::uint64_t, 2>>& calls,
                                            std::uint64_t seed, std::uint64_t stream);
  EstimateAndError a1_monte_carlo(A1Integrand f, double param, Segment s, std::uint64_t n,
                                  std::uint64_t seed, std::uint64_t stream);
  double a1_trapezoid(A1Integrand f, double param, Segment s, std::uint64_t n);
  std::vector<Vec3> samples(SamplerKind kind, const std::vector<Vec2>& u);
  std::vector<double> pdf_values(SamplerKind kind, const std::vector<Vec3>& points);
  PathSample recursive_single(double albedo, double emission, Vec3 origin, Vec3 direction, int n,
                              int k, std::uint64_t seed, std::uint64_t stream);
  std::vector<double> recursive_furnace(double albedo, int n, int k, int samples,
                                        std::uint64_t seed, std::uint64_t block);
  std::vector<std::uint64_t> predicted_rays(const std::vector<std::array<int, 2>>& calls);
  std::vector<double> path_furnace(double albedo, int depth, int n, std::uint64_t seed,
                                   std::uint64_t block);
  std::vector<double> path_sky(int size, int depth, int spp, std::uint64_t seed);
  PathSample path_single(double albedo, double emission, Vec3 direction, int depth,
                         std::uint64_t seed, std::uint64_t stream);
  std::vector<double> pixel_exact(int spp, std::uint64_t seed);
  std::vector<Vec3> pixel_rays(int x, int y, int spp, std::uint64_t seed, std::uint64_t stream);
  std::vector<double> pixel_furnace(double albedo, int depth, int size, int spp,
                                    std::uint64_t seed);
  std::vector<FurnacePath> a5_paths(const A5Estimator& e, double albedo, int n, std::uint64_t seed,
                                    std::uint64_t block);
  PathSample a5_single(const A5Estimator& e, double albedo, double emission, Vec3 direction,
                       std::uint64_t seed, std::uint64_t stream);
  std::vector<double> a5_regions(const A5Estimator& e, int lamp_parts, int size, int spp,
                                 std::uint64_t seed);
  std::vector<double> a5_wall(const A5Estimator& e, int n, std::uint64_t seed);
  std::vector<Vec3> a6_lobe_samples(double m, const std::vector<Vec2>& u);
  std::vector<double> a6_lobe_pdf(double m, Vec3 reflected, const std::vector<Vec3>& points);
  std::vector<double> a6_weights(A6Heuristic h, const std::vector<Vec2>& pairs);
  std::vector<double> a6_regions(A6Strategy strategy, int width, int height, int spp,
                                 std::uint64_t seed);
  std::vector<DielectricAnswer> a6_dielectric(double ior,
                                              const std::vector<DielectricQuery>& queries);
  std::vector<double> a7_points(A7PointSet kind, std::uint32_t n, unsigned d, std::uint64_t key0,
                                std::uint32_t key_count, const std::vector<std::uint32_t>& indices);
  std::vector<double> a7_radical_inverse(std::uint32_t base,
                                         const std::vector<std::uint32_t>& indices);

  /// Sends one request and returns the numbers of its answer (starting the program first).
  std::vector<double> call(const std::string& name, const std::vector<double>& params);
  /// Kills the subject's process group and reaps it; the next request starts a new one.
  void stop();

 private:
  void start();
  [[noreturn]] void broken(const std::string& name, const std::string& problem);
  pid_t pid_ = -1;
  int to_subject_ = -1;
  int from_subject_ = -1;
  std::string token_;
  std::optional<FrameReader> reader_;
};

}  // namespace mcrt::testing::assignment
