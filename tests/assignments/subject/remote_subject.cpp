#include "assignments/subject/remote_subject.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "render/veach_plates.hpp"  // the a6 regions' pixel counts

namespace mcrt::testing::assignment {
namespace {

std::string environment_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

/// The student code's exception text as one line of the feedback that cannot pass for the
/// grader's: control characters (a newline would start a line of its own) made spaces, the
/// grader's "DIAGNOSIS" marker lowered, at most 300 bytes (the stubs' texts are under 80).
std::string student_text(std::string text) {
  if (text.size() > 300) text = text.substr(0, 300) + "...";
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  for (std::size_t at = text.find("DIAGNOSIS"); at != std::string::npos;
       at = text.find("DIAGNOSIS", at))
    text.replace(at, 9, "diagnosis");
  return text;
}

/// k_answer_seconds, or less when $MCRT_SUBJECT_ANSWER_SECONDS says so (tests of a hang).
double answer_seconds() {
  const char* text = std::getenv("MCRT_SUBJECT_ANSWER_SECONDS");
  const double lowered = text != nullptr ? std::atof(text) : 0.0;
  return lowered > 0.0 && lowered < k_answer_seconds ? lowered : k_answer_seconds;
}

}  // namespace

void RemoteSubject::start() {
#ifdef MCRT_SUBJECT_DEFAULT
  const std::string program = environment_or("MCRT_SUBJECT", MCRT_SUBJECT_DEFAULT);
#else
  const std::string program = environment_or("MCRT_SUBJECT", "");
#endif
  const std::string launcher = environment_or("MCRT_SUBJECT_LAUNCHER", "");
  if (program.empty()) throw std::runtime_error("no subject program: set MCRT_SUBJECT");
  ::signal(SIGPIPE, SIG_IGN);  // a subject gone while we write: write() fails, we say so
  int requests[2], answers[2];
  if (::pipe2(requests, O_CLOEXEC) != 0 || ::pipe2(answers, O_CLOEXEC) != 0)
    throw std::runtime_error(
        fmt::format("cannot make the subject's pipes: {}", std::strerror(errno)));
  std::vector<std::string> words;
  if (!launcher.empty()) words.push_back(launcher);
  words.push_back(program);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const bool launcher_makes_group = !launcher.empty() && ::geteuid() == 0;
  const pid_t pid = ::fork();
  if (pid < 0)
    throw std::runtime_error(fmt::format("cannot start the subject: {}", std::strerror(errno)));
  if (pid == 0) {
    // sandbox-run, as root, starts a session of its own (setsid would fork were this process
    // a group leader already); otherwise the child makes its own process group, to be killed whole
    if (!launcher_makes_group) ::setpgid(0, 0);
    ::dup2(requests[0], STDIN_FILENO);
    ::dup2(answers[1], STDOUT_FILENO);
    // nothing of the checker's environment but PATH: not where its reports go (GTEST_OUTPUT,
    // MCRT_TEST_REPORT_DIR), nor the subject's own path
    const char* path = std::getenv("PATH");
    std::string path_entry = std::string("PATH=") + (path != nullptr ? path : "/usr/bin:/bin");
    char* environment[] = {path_entry.data(), nullptr};
    ::execve(argv[0], argv.data(), environment);
    const std::string message =
        fmt::format("checker: cannot run {}: {}\n", argv[0], std::strerror(errno));
    (void)!::write(STDERR_FILENO, message.data(), message.size());
    ::_exit(127);
  }
  ::close(requests[0]);
  ::close(answers[1]);
  pid_ = pid;
  to_subject_ = requests[1];
  from_subject_ = answers[0];
  reader_.emplace(from_subject_);
  token_ = random_token();
  const std::string first = token_ + "\n";
  if (!write_all_bytes(to_subject_, first.data(), first.size()))
    broken("start", "it did not take its token");
}

void RemoteSubject::stop() {
  if (pid_ > 0) {
    ::kill(-pid_, SIGKILL);  // the whole group: whatever the student code started in it
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  if (to_subject_ >= 0) ::close(to_subject_);
  if (from_subject_ >= 0) ::close(from_subject_);
  pid_ = to_subject_ = from_subject_ = -1;
  reader_.reset();
}

void RemoteSubject::broken(const std::string& name, const std::string& problem) {
  stop();
  throw std::runtime_error(
      fmt::format("the subject program (your code) gave no valid answer to request {}: {}", name,
                  problem));
}

std::vector<double> RemoteSubject::call(const std::string& name,
                                        const std::vector<double>& params) {
  if (pid_ < 0) start();
  if (!write_frame(to_subject_, token_, name, params))
    broken(name, "it stopped reading its requests (it ended or crashed)");
  Frame frame;
  std::string problem;
  if (!reader_->read_frame(token_, frame, answer_seconds(), problem)) broken(name, problem);
  if (frame.name == "error") throw std::runtime_error(student_text(frame.text));
  if (frame.name != "ok")
    broken(name, fmt::format("an answer named {:?} instead of ok or error", frame.name));
  return std::move(frame.values);
}

double RemoteSubject::a1_disk(std::uint64_t n, std::uint64_t seed, std::uint64_t stream) {
  const std::vector<double> answer =
      call(k_request_a1_disk, {as_number(n), as_number(seed), as_number(stream)});
  if (answer.size() != 1) broken(k_request_a1_disk, "not one estimate");
  return answer[0];
}

double RemoteSubject::a1_ball(int k, std::uint64_t n, std::uint64_t seed, std::uint64_t stream) {
  const std::vector<double> answer = call(k_request_a1_ball, {static_cast<double>(k), as_number(n),
                                                              as_number(seed), as_number(stream)});
  if (answer.size() != 1) broken(k_request_a1_ball, "not one estimate");
  return answer[0];
}

std::vector<std::uint64_t> RemoteSubject::a1_ball_counts(
    const std::vector<std::array<std::uint64_t, 2>>& calls, std::uint64_t seed,
    std::uint64_t stream) {
  std::vector<double> params{as_number(seed), as_number(stream)};
  for (const auto& [k, n] : calls) params.insert(params.end(), {as_number(k), as_number(n)});
  const std::vector<double> answer = call(k_request_a1_ball_counts, params);
  if (answer.size() != calls.size()) broken(k_request_a1_ball_counts, "not one count per call");
  std::vector<std::uint64_t> counts;
  for (double c : answer) {
    if (!(c >= 0.0 && c < 0x1p53)) broken(k_request_a1_ball_counts, "a count out of range");
    counts.push_back(static_cast<std::uint64_t>(c));
  }
  return counts;
}

std::vector<std::uint64_t> RemoteSubject::predicted_rays(
    const std::vector<std::array<int, 2>>& calls) {
  std::vector<double> params;
  for (const auto& [n, k] : calls)
    params.insert(params.end(), {static_cast<double>(n), static_cast<double>(k)});
  const std::vector<double> answer = call(k_request_a3_predicted_rays, params);
  if (answer.size() != 2 * calls.size())
    broken(k_request_a3_predicted_rays, "not one count (two halves) per call");
  std::vector<std::uint64_t> counts;
  for (std::size_t i = 0; i < answer.size(); i += 2) {
    const double high = answer[i], low = answer[i + 1];
    if (!(high >= 0.0 && high < 0x1p32 && low >= 0.0 && low < 0x1p32) ||
        high != static_cast<double>(static_cast<std::uint32_t>(high)) ||
        low != static_cast<double>(static_cast<std::uint32_t>(low)))
      broken(k_request_a3_predicted_rays,
             "a half of a count that is not a whole number below 2^32");
    counts.push_back((static_cast<std::uint64_t>(high) << 32) | static_cast<std::uint64_t>(low));
  }
  return counts;
}

EstimateAndError RemoteSubject::a1_monte_carlo(A1Integrand f, double param, Segment s,
                                               std::uint64_t n, std::uint64_t seed,
                                               std::uint64_t stream) {
  const std::vector<double> answer =
      call(k_request_a1_monte_carlo, {static_cast<double>(f), param, s.lower, s.upper, as_number(n),
                                      as_number(seed), as_number(stream)});
  if (answer.size() != 2)
    broken(k_request_a1_monte_carlo, "not an estimate and its standard error");
  return {answer[0], answer[1]};
}

double RemoteSubject::a1_trapezoid(A1Integrand f, double param, Segment s, std::uint64_t n) {
  const std::vector<double> answer =
      call(k_request_a1_trapezoid, {static_cast<double>(f), param, s.lower, s.upper, as_number(n)});
  if (answer.size() != 1) broken(k_request_a1_trapezoid, "not one value");
  return answer[0];
}

std::vector<Vec3> RemoteSubject::samples(SamplerKind kind, const std::vector<Vec2>& u) {
  std::vector<double> params{static_cast<double>(kind)};
  params.reserve(1 + 2 * u.size());
  for (const Vec2& x : u) params.insert(params.end(), {x.x, x.y});
  const std::vector<double> answer = call(k_request_a2_samples, params);
  if (answer.size() != 3 * u.size())
    broken(k_request_a2_samples, fmt::format("{} numbers for {} points", answer.size(), u.size()));
  return unflatten3(answer.data(), answer.size());
}

std::vector<double> RemoteSubject::pdf_values(SamplerKind kind, const std::vector<Vec3>& points) {
  std::vector<double> params{static_cast<double>(kind)};
  const std::vector<double> flat = flatten(points);
  params.insert(params.end(), flat.begin(), flat.end());
  std::vector<double> answer = call(k_request_a2_pdf, params);
  if (answer.size() != points.size())
    broken(k_request_a2_pdf, fmt::format("{} numbers for {} points", answer.size(), points.size()));
  return answer;
}

PathSample RemoteSubject::recursive_single(double albedo, double emission, Vec3 origin,
                                           Vec3 direction, int n, int k, std::uint64_t seed,
                                           std::uint64_t stream) {
  const std::vector<double> answer =
      call(k_request_a3_single,
           {albedo, emission, origin.x, origin.y, origin.z, direction.x, direction.y, direction.z,
            static_cast<double>(n), static_cast<double>(k), as_number(seed), as_number(stream)});
  if (answer.size() != 2 || !(answer[1] >= 0.0 && answer[1] < 0x1p53))
    broken(k_request_a3_single, "not one radiance and one ray count");
  return {answer[0], static_cast<std::uint64_t>(answer[1])};
}

std::vector<double> RemoteSubject::recursive_furnace(double albedo, int n, int k, int samples,
                                                     std::uint64_t seed, std::uint64_t block) {
  std::vector<double> answer =
      call(k_request_a3_furnace, {albedo, static_cast<double>(n), static_cast<double>(k),
                                  static_cast<double>(samples), as_number(seed), as_number(block)});
  if (answer.size() != static_cast<std::size_t>(samples))
    broken(k_request_a3_furnace, fmt::format("{} numbers for {} samples", answer.size(), samples));
  return answer;
}

std::vector<double> RemoteSubject::path_furnace(double albedo, int depth, int n, std::uint64_t seed,
                                                std::uint64_t block) {
  std::vector<double> answer =
      call(k_request_a4_furnace, {albedo, static_cast<double>(depth), static_cast<double>(n),
                                  as_number(seed), as_number(block)});
  if (answer.size() != static_cast<std::size_t>(n))
    broken(k_request_a4_furnace, fmt::format("{} numbers for {} paths", answer.size(), n));
  return answer;
}

std::vector<double> RemoteSubject::path_sky(int size, int depth, int spp, std::uint64_t seed) {
  std::vector<double> answer =
      call(k_request_a4_sky, {static_cast<double>(size), static_cast<double>(depth),
                              static_cast<double>(spp), as_number(seed)});
  const auto expected = static_cast<std::size_t>(size) * static_cast<std::size_t>(size) *
                        static_cast<std::size_t>(spp);
  if (answer.size() != expected)
    broken(k_request_a4_sky, fmt::format("{} numbers for {} samples", answer.size(), expected));
  return answer;
}

PathSample RemoteSubject::path_single(double albedo, double emission, Vec3 direction, int depth,
                                      std::uint64_t seed, std::uint64_t stream) {
  const std::vector<double> answer =
      call(k_request_a4_single, {albedo, emission, direction.x, direction.y, direction.z,
                                 static_cast<double>(depth), as_number(seed), as_number(stream)});
  if (answer.size() != 2 || !(answer[1] >= 0.0))
    broken(k_request_a4_single, "not one radiance and one ray count");
  return {answer[0], static_cast<std::uint64_t>(answer[1])};
}

// a4.2's answers: 4 numbers a pixel of the 8 x 6 pixel camera, 3 a ray, 2 a furnace pixel.
std::vector<double> RemoteSubject::pixel_exact(int spp, std::uint64_t seed) {
  std::vector<double> answer =
      call(k_request_a4_pixel_exact, {static_cast<double>(spp), as_number(seed)});
  if (answer.size() != 4u * 8u * 6u)
    broken(k_request_a4_pixel_exact, fmt::format("{} numbers for 48 pixels", answer.size()));
  return answer;
}

std::vector<Vec3> RemoteSubject::pixel_rays(int x, int y, int spp, std::uint64_t seed,
                                            std::uint64_t stream) {
  const std::vector<double> answer =
      call(k_request_a4_pixel_rays, {static_cast<double>(x), static_cast<double>(y),
                                     static_cast<double>(spp), as_number(seed), as_number(stream)});
  if (answer.size() != 3u * static_cast<std::size_t>(spp))
    broken(k_request_a4_pixel_rays, fmt::format("{} numbers for {} rays", answer.size(), spp));
  return unflatten3(answer.data(), answer.size());
}

std::vector<double> RemoteSubject::pixel_furnace(double albedo, int depth, int size, int spp,
                                                 std::uint64_t seed) {
  std::vector<double> answer = call(k_request_a4_pixel_furnace,
                                    {albedo, static_cast<double>(depth), static_cast<double>(size),
                                     static_cast<double>(spp), as_number(seed)});
  if (answer.size() != 2u * static_cast<std::size_t>(size) * static_cast<std::size_t>(size))
    broken(k_request_a4_pixel_furnace,
           fmt::format("{} numbers for {} pixels", answer.size(), size * size));
  return answer;
}

std::vector<FurnacePath> RemoteSubject::a5_paths(const A5Estimator& e, double albedo, int n,
                                                 std::uint64_t seed, std::uint64_t block) {
  std::vector<double> params;
  append(params, e);
  params.insert(params.end(), {albedo, static_cast<double>(n), as_number(seed), as_number(block)});
  const std::vector<double> answer = call(k_request_a5_paths, params);
  if (answer.size() != 2 * static_cast<std::size_t>(n))
    broken(k_request_a5_paths, fmt::format("{} numbers for {} paths", answer.size(), n));
  std::vector<FurnacePath> paths(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (!(answer[2 * i + 1] >= 0.0 && answer[2 * i + 1] < 0x1p53))
      broken(k_request_a5_paths, "a ray count out of range");
    paths[i] = {answer[2 * i], static_cast<std::uint64_t>(answer[2 * i + 1])};
  }
  return paths;
}

PathSample RemoteSubject::a5_single(const A5Estimator& e, double albedo, double emission,
                                    Vec3 direction, std::uint64_t seed, std::uint64_t stream) {
  std::vector<double> params;
  append(params, e);
  params.insert(params.end(), {albedo, emission, direction.x, direction.y, direction.z,
                               as_number(seed), as_number(stream)});
  const std::vector<double> answer = call(k_request_a5_single, params);
  if (answer.size() != 2 || !(answer[1] >= 0.0 && answer[1] < 0x1p53))
    broken(k_request_a5_single, "not one radiance and one ray count");
  return {answer[0], static_cast<std::uint64_t>(answer[1])};
}

std::vector<double> RemoteSubject::a5_regions(const A5Estimator& e, int lamp_parts, int size,
                                              int spp, std::uint64_t seed) {
  std::vector<double> params;
  append(params, e);
  params.insert(params.end(), {static_cast<double>(lamp_parts), static_cast<double>(size),
                               static_cast<double>(spp), as_number(seed)});
  std::vector<double> answer = call(k_request_a5_regions, params);
  const auto expected = static_cast<std::size_t>(size) * static_cast<std::size_t>(size) *
                        static_cast<std::size_t>(spp);
  if (answer.size() != expected)
    broken(k_request_a5_regions, fmt::format("{} numbers for {} samples", answer.size(), expected));
  return answer;
}

std::vector<double> RemoteSubject::a5_wall(const A5Estimator& e, int n, std::uint64_t seed) {
  std::vector<double> params;
  append(params, e);
  params.insert(params.end(), {static_cast<double>(n), as_number(seed)});
  std::vector<double> answer = call(k_request_a5_wall, params);
  if (answer.size() != static_cast<std::size_t>(n))
    broken(k_request_a5_wall, fmt::format("{} numbers for {} rays", answer.size(), n));
  return answer;
}

std::vector<Vec3> RemoteSubject::a6_lobe_samples(double m, const std::vector<Vec2>& u) {
  std::vector<double> params{m};
  params.reserve(1 + 2 * u.size());
  for (const Vec2& x : u) params.insert(params.end(), {x.x, x.y});
  const std::vector<double> answer = call(k_request_a6_lobe_samples, params);
  if (answer.size() != 3 * u.size())
    broken(k_request_a6_lobe_samples,
           fmt::format("{} numbers for {} points", answer.size(), u.size()));
  return unflatten3(answer.data(), answer.size());
}

std::vector<double> RemoteSubject::a6_lobe_pdf(double m, Vec3 reflected,
                                               const std::vector<Vec3>& points) {
  std::vector<double> params{m, reflected.x, reflected.y, reflected.z};
  const std::vector<double> flat = flatten(points);
  params.insert(params.end(), flat.begin(), flat.end());
  std::vector<double> answer = call(k_request_a6_lobe_pdf, params);
  if (answer.size() != points.size())
    broken(k_request_a6_lobe_pdf,
           fmt::format("{} numbers for {} points", answer.size(), points.size()));
  return answer;
}

std::vector<double> RemoteSubject::a6_weights(A6Heuristic h, const std::vector<Vec2>& pairs) {
  std::vector<double> params{static_cast<double>(h)};
  for (const Vec2& p : pairs) params.insert(params.end(), {p.x, p.y});
  std::vector<double> answer = call(k_request_a6_weights, params);
  if (answer.size() != pairs.size())
    broken(k_request_a6_weights,
           fmt::format("{} numbers for {} pairs", answer.size(), pairs.size()));
  return answer;
}

std::vector<double> RemoteSubject::a6_regions(A6Strategy strategy, int width, int height, int spp,
                                              std::uint64_t seed) {
  std::vector<double> answer =
      call(k_request_a6_regions,
           {static_cast<double>(strategy), static_cast<double>(width), static_cast<double>(height),
            static_cast<double>(spp), as_number(seed)});
  std::size_t expected = 0;
  for (const PlateRegion& r : plate_regions(make_veach_plates(), width, height))
    expected += static_cast<std::size_t>(r.pixel_count()) * static_cast<std::size_t>(spp);
  if (answer.size() != expected)
    broken(k_request_a6_regions, fmt::format("{} numbers for {} samples", answer.size(), expected));
  return answer;
}

std::vector<DielectricAnswer> RemoteSubject::a6_dielectric(
    double ior, const std::vector<DielectricQuery>& queries) {
  std::vector<double> params{ior};
  params.reserve(1 + k_dielectric_query_numbers * queries.size());
  for (const DielectricQuery& q : queries)
    for (double x : {q.wo.x, q.wo.y, q.wo.z, q.n.x, q.n.y, q.n.z, q.entering ? 1.0 : 0.0, q.u})
      params.push_back(x);
  const std::vector<double> answer = call(k_request_a6_dielectric, params);
  if (answer.size() != k_dielectric_answer_numbers * queries.size())
    broken(k_request_a6_dielectric,
           fmt::format("{} numbers for {} queries", answer.size(), queries.size()));
  std::vector<DielectricAnswer> out;
  out.reserve(queries.size());
  for (std::size_t i = 0; i < answer.size(); i += k_dielectric_answer_numbers) {
    const double* a = answer.data() + i;
    // the flag travels as a number: anything but exactly 1 is "not transmitted"
    out.push_back({{a[0], a[1], a[2]}, {a[3], a[4], a[5]}, a[6] == 1.0});
  }
  return out;
}

std::vector<double> RemoteSubject::a7_points(A7PointSet kind, std::uint32_t n, unsigned d,
                                             std::uint64_t key0, std::uint32_t key_count,
                                             const std::vector<std::uint32_t>& indices) {
  std::vector<double> params{static_cast<double>(kind), static_cast<double>(n),
                             static_cast<double>(d), as_number(key0),
                             static_cast<double>(key_count)};
  for (std::uint32_t i : indices) params.push_back(static_cast<double>(i));
  std::vector<double> answer = call(k_request_a7_points, params);
  const std::size_t expected = std::size_t{key_count} * indices.size() * d;
  if (answer.size() != expected)
    broken(k_request_a7_points,
           fmt::format("{} numbers for {} coordinates", answer.size(), expected));
  return answer;
}

std::vector<double> RemoteSubject::a7_radical_inverse(std::uint32_t base,
                                                      const std::vector<std::uint32_t>& indices) {
  std::vector<double> params{static_cast<double>(base)};
  for (std::uint32_t i : indices) params.push_back(static_cast<double>(i));
  std::vector<double> answer = call(k_request_a7_radical_inverse, params);
  if (answer.size() != indices.size())
    broken(k_request_a7_radical_inverse,
           fmt::format("{} numbers for {} indices", answer.size(), indices.size()));
  return answer;
}

}  // namespace mcrt::testing::assignment
