// The subject program: the student's functions (through LocalSubject) answering a checker's
// requests (protocol.hpp) on stdin/stdout. It holds no test and no hidden data: every
// parameter comes with its request. What the student's code prints goes to stderr, so only
// this dispatcher writes frames, each with the run's token.

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assignments/subject/local_subject.hpp"
#include "assignments/subject/protocol.hpp"

namespace mcrt::testing::assignment {
namespace {

/// The kind of a request: its first parameter, checked against the enum's range.
SamplerKind sampler_kind(const std::vector<double>& params) {
  if (params.empty() ||
      !(params[0] >= 0.0 && params[0] <= static_cast<double>(SamplerKind::uniform_cone)) ||
      params[0] != static_cast<int>(params[0]))
    throw std::invalid_argument("request without a valid sampler kind");
  return static_cast<SamplerKind>(static_cast<int>(params[0]));
}

void need(const std::vector<double>& params, std::size_t count, const std::string& name) {
  if (params.size() != count)
    throw std::invalid_argument(fmt::format("request {} takes {} numbers", name, count));
}

/// A whole number in [0, limit] (a depth, a size, a count).
int whole(double x, int limit) {
  if (!(x >= 0.0 && x <= limit) || x != static_cast<int>(x))
    throw std::invalid_argument("a count out of range");
  return static_cast<int>(x);
}

void need_rest(std::size_t count, std::size_t wanted, const std::string& name) {
  if (count != wanted)
    throw std::invalid_argument(
        fmt::format("request {} takes {} numbers after its estimator", name, wanted));
}

/// The A5Estimator that heads an a5 request (its kind, policy and pdf kind in range).
A5Estimator a5_estimator(const std::vector<double>& params) {
  if (params.size() < k_a5_estimator_numbers)
    throw std::invalid_argument("an a5 request without its estimator");
  A5Estimator e;
  e.kind = static_cast<A5Estimator::Kind>(whole(params[0], 2));
  e.min_depth = whole(params[1], 1 << 20);
  e.policy = whole(params[2], 1);
  e.q = params[3];
  e.floor = params[4];
  e.max_depth = params[5] == -1.0 ? -1 : whole(params[5], 1 << 20);
  e.pdf_kind = whole(params[6], 3);
  e.pdf_m = whole(params[7], 1 << 10);
  return e;
}

/// A sample count (at most 2^30: a1's largest is 2e5).
std::uint64_t count(double x) { return static_cast<std::uint64_t>(whole(x, 1 << 30)); }

A1Integrand integrand(double x) { return static_cast<A1Integrand>(whole(x, 3)); }

std::uint64_t seed(double x) {
  if (!(x >= 0.0 && x < 0x1p53) || x != static_cast<double>(static_cast<std::uint64_t>(x)))
    throw std::invalid_argument("a seed that is not a whole number below 2^53");
  return static_cast<std::uint64_t>(x);
}

std::vector<double> answer(const LocalSubject& s, const std::string& name,
                           const std::vector<double>& params) {
  if (name == k_request_a1_disk) {
    need(params, 3, name);
    return {s.a1_disk(count(params[0]), seed(params[1]), seed(params[2]))};
  }
  if (name == k_request_a1_ball) {
    need(params, 4, name);
    return {s.a1_ball(whole(params[0], 64), count(params[1]), seed(params[2]), seed(params[3]))};
  }
  if (name == k_request_a1_ball_counts) {
    if (params.size() < 2 || params.size() % 2 != 0)
      throw std::invalid_argument("a1_ball_counts takes pairs");
    std::vector<std::array<std::uint64_t, 2>> calls;
    for (std::size_t i = 2; i < params.size(); i += 2)
      calls.push_back({static_cast<std::uint64_t>(whole(params[i], 64)), count(params[i + 1])});
    std::vector<double> out;
    for (std::uint64_t c : s.a1_ball_counts(calls, seed(params[0]), seed(params[1])))
      out.push_back(static_cast<double>(c));
    return out;
  }
  if (name == k_request_a1_monte_carlo) {
    need(params, 7, name);
    const EstimateAndError e =
        s.a1_monte_carlo(integrand(params[0]), params[1], Segment{params[2], params[3]},
                         count(params[4]), seed(params[5]), seed(params[6]));
    return {e.estimate, e.standard_error};
  }
  if (name == k_request_a1_trapezoid) {
    need(params, 5, name);
    return {s.a1_trapezoid(integrand(params[0]), params[1], Segment{params[2], params[3]},
                           count(params[4]))};
  }
  if (name == k_request_a2_samples) {
    const SamplerKind kind = sampler_kind(params);
    std::vector<Vec2> u;
    for (std::size_t i = 1; i + 1 < params.size(); i += 2) u.emplace_back(params[i], params[i + 1]);
    return flatten(s.samples(kind, u));
  }
  if (name == k_request_a2_pdf) {
    const SamplerKind kind = sampler_kind(params);
    return s.pdf_values(kind, unflatten3(params.data() + 1, params.size() - 1));
  }
  if (name == k_request_a3_single) {
    need(params, 12, name);
    const PathSample p =
        s.recursive_single(params[0], params[1], {params[2], params[3], params[4]},
                           {params[5], params[6], params[7]}, whole(params[8], 64),
                           whole(params[9], 16), seed(params[10]), seed(params[11]));
    return {p.radiance, static_cast<double>(p.rays)};
  }
  if (name == k_request_a3_furnace) {
    need(params, 6, name);
    return s.recursive_furnace(params[0], whole(params[1], 64), whole(params[2], 16),
                               whole(params[3], 1 << 24), seed(params[4]), seed(params[5]));
  }
  if (name == k_request_a3_predicted_rays) {
    if (params.size() % 2 != 0) throw std::invalid_argument("a3_predicted_rays takes pairs");
    std::vector<std::array<int, 2>> calls;
    for (std::size_t i = 0; i < params.size(); i += 2)
      calls.push_back({whole(params[i], 1 << 20), whole(params[i + 1], 1 << 10)});
    std::vector<double> out;
    for (std::uint64_t r : s.predicted_rays(calls)) append_count(out, r);
    return out;
  }
  if (name == k_request_a4_furnace) {
    need(params, 5, name);
    return s.path_furnace(params[0], whole(params[1], 64), whole(params[2], 1 << 24),
                          seed(params[3]), seed(params[4]));
  }
  if (name == k_request_a4_sky) {
    need(params, 4, name);
    return s.path_sky(whole(params[0], 1024), whole(params[1], 64), whole(params[2], 1 << 16),
                      seed(params[3]));
  }
  if (name == k_request_a4_single) {
    need(params, 8, name);
    const PathSample p = s.path_single(params[0], params[1], {params[2], params[3], params[4]},
                                       whole(params[5], 64), seed(params[6]), seed(params[7]));
    return {p.radiance, static_cast<double>(p.rays)};
  }
  if (name == k_request_a4_pixel_exact) {
    need(params, 2, name);
    return s.pixel_exact(whole(params[0], 1 << 16), seed(params[1]));
  }
  if (name == k_request_a4_pixel_rays) {
    need(params, 5, name);
    // Only the recorded rays' directions travel back: the checker never sees what the
    // student's code drew from the rng, only where its rays went.
    return flatten(s.pixel_rays(whole(params[0], 7), whole(params[1], 5),
                                std::max(whole(params[2], 1 << 20), 1), seed(params[3]),
                                seed(params[4])));
  }
  if (name == k_request_a4_pixel_furnace) {
    need(params, 5, name);
    return s.pixel_furnace(params[0], whole(params[1], 64), whole(params[2], 256),
                           whole(params[3], 1 << 16), seed(params[4]));
  }
  if (name == k_request_a5_paths || name == k_request_a5_single || name == k_request_a5_regions ||
      name == k_request_a5_wall) {
    const A5Estimator e = a5_estimator(params);
    const double* rest = params.data() + k_a5_estimator_numbers;
    const std::size_t count = params.size() - k_a5_estimator_numbers;
    if (name == k_request_a5_paths) {
      need_rest(count, 4, name);
      std::vector<double> out;
      for (const FurnacePath& p :
           s.a5_paths(e, rest[0], whole(rest[1], 1 << 24), seed(rest[2]), seed(rest[3])))
        out.insert(out.end(), {p.radiance, static_cast<double>(p.rays)});
      return out;
    }
    if (name == k_request_a5_single) {
      need_rest(count, 7, name);
      const PathSample p = s.a5_single(e, rest[0], rest[1], {rest[2], rest[3], rest[4]},
                                       seed(rest[5]), seed(rest[6]));
      return {p.radiance, static_cast<double>(p.rays)};
    }
    if (name == k_request_a5_regions) {
      need_rest(count, 4, name);
      return s.a5_regions(e, whole(rest[0], 16), whole(rest[1], 1024), whole(rest[2], 1 << 16),
                          seed(rest[3]));
    }
    need_rest(count, 2, name);
    return s.a5_wall(e, whole(rest[0], 1 << 24), seed(rest[1]));
  }
  if (name == k_request_a6_lobe_samples) {
    if (params.empty() || params.size() % 2 != 1)
      throw std::invalid_argument("a6_lobe_samples takes m and pairs");
    std::vector<Vec2> u;
    for (std::size_t i = 1; i + 1 < params.size(); i += 2) u.emplace_back(params[i], params[i + 1]);
    return flatten(s.a6_lobe_samples(params[0], u));
  }
  if (name == k_request_a6_lobe_pdf) {
    if (params.size() < 4 || (params.size() - 4) % 3 != 0)
      throw std::invalid_argument("a6_lobe_pdf takes m, r and points");
    return s.a6_lobe_pdf(params[0], {params[1], params[2], params[3]},
                         unflatten3(params.data() + 4, params.size() - 4));
  }
  if (name == k_request_a6_weights) {
    if (params.empty() || params.size() % 2 != 1)
      throw std::invalid_argument("a6_weights takes a heuristic and pairs");
    std::vector<Vec2> pairs;
    for (std::size_t i = 1; i + 1 < params.size(); i += 2)
      pairs.emplace_back(params[i], params[i + 1]);
    return s.a6_weights(static_cast<A6Heuristic>(whole(params[0], 1)), pairs);
  }
  if (name == k_request_a6_regions) {
    need(params, 5, name);
    return s.a6_regions(static_cast<A6Strategy>(whole(params[0], 3)), whole(params[1], 1024),
                        whole(params[2], 1024), whole(params[3], 1 << 16), seed(params[4]));
  }
  if (name == k_request_a6_dielectric) {
    if (params.empty() || (params.size() - 1) % k_dielectric_query_numbers != 0)
      throw std::invalid_argument("a6_dielectric takes an index and queries");
    std::vector<DielectricQuery> queries;
    for (std::size_t i = 1; i < params.size(); i += k_dielectric_query_numbers) {
      const double* q = params.data() + i;
      queries.push_back({{q[0], q[1], q[2]}, {q[3], q[4], q[5]}, q[6] == 1.0, q[7]});
    }
    std::vector<double> out;
    out.reserve(k_dielectric_answer_numbers * queries.size());
    for (const DielectricAnswer& a : s.a6_dielectric(params[0], queries))
      for (double x :
           {a.wi.x, a.wi.y, a.wi.z, a.weight.x, a.weight.y, a.weight.z, a.transmitted ? 1.0 : 0.0})
        out.push_back(x);
    return out;
  }
  if (name == k_request_a7_points) {
    if (params.size() < 5)
      throw std::invalid_argument("a7_points takes a set, n, d, a key, a count and indices");
    std::vector<std::uint32_t> indices;
    for (std::size_t i = 5; i < params.size(); ++i)
      indices.push_back(static_cast<std::uint32_t>(whole(params[i], 1 << 24)));
    // n * d * keys * indices numbers at most k_max_frame_values: the frame's limit
    const int n = whole(params[1], 1 << 24), d = whole(params[2], 32),
              keys = whole(params[4], 1 << 24);
    if (n < 1 ||
        static_cast<double>(d) * keys * static_cast<double>(indices.size()) > k_max_frame_values)
      throw std::invalid_argument("a7_points: too many numbers asked");
    for (std::uint32_t i : indices)
      if (i >= static_cast<std::uint32_t>(n))
        throw std::invalid_argument("a7_points: an index >= n");
    return s.a7_points(static_cast<A7PointSet>(whole(params[0], 2)), static_cast<std::uint32_t>(n),
                       static_cast<unsigned>(d), seed(params[3]), static_cast<std::uint32_t>(keys),
                       indices);
  }
  if (name == k_request_a7_radical_inverse) {
    if (params.empty()) throw std::invalid_argument("a7_radical_inverse takes a base and indices");
    const int base = whole(params[0], 1 << 16);
    if (base < 2) throw std::invalid_argument("a7_radical_inverse: a base below 2");
    std::vector<std::uint32_t> indices;
    for (std::size_t i = 1; i < params.size(); ++i)
      indices.push_back(static_cast<std::uint32_t>(whole(params[i], 1 << 30)));
    return s.a7_radical_inverse(static_cast<std::uint32_t>(base), indices);
  }
  throw std::invalid_argument(fmt::format("unknown request {}", name));
}

int serve() {
  // frames go to the original stdout; the student's prints (stdout included) to stderr
  const int answers = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (answers < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) return 1;
  FrameReader requests(STDIN_FILENO);
  std::string token, problem;
  if (!requests.read_line(token, k_max_header_bytes, -1.0, problem)) return 1;
  const LocalSubject subject;
  for (;;) {
    Frame request;
    if (!requests.read_frame(token, request, -1.0, problem)) return 0;  // the checker is done
    bool written = false;
    try {
      const std::vector<double> values = answer(subject, request.name, request.values);
      std::fflush(nullptr);  // the student's buffered prints leave before the answer
      written = write_frame(answers, token, "ok", values);
    } catch (const std::exception& e) {
      std::fflush(nullptr);
      written = write_error_frame(answers, token, e.what());
    }
    if (!written) return 1;
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment

int main() { return mcrt::testing::assignment::serve(); }
