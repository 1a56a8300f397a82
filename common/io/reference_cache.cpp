#include "io/reference_cache.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>
#include <utility>
#include <variant>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "core/progress.hpp"
#include "geometry/camera.hpp"
#include "io/exclusive_file.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "io/sha256.hpp"
#include "io/usage_error.hpp"
#include "render/mis.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/russian_roulette.hpp"
#include "render/two_render_error.hpp"

namespace mcrt {

namespace fs = std::filesystem;

namespace {

// The reference's samples start here, far from every sample index a chapter's images use.
constexpr std::uint64_t k_reference_first_sample = std::uint64_t{1} << 30;

bool is_furnace(const ReferenceSpec& spec) { return spec.scene.scene == "furnace"; }

Reference furnace_reference(const ReferenceSpec& spec) {
  const SceneParams& p = spec.scene.params;
  const double value =
      spec.max_depth < 0 ? furnace_radiance_untruncated(p.furnace_albedo, p.furnace_emission)
                         : furnace_radiance(p.furnace_albedo, p.furnace_emission, spec.max_depth);
  Reference r;
  r.image = Image(spec.width, spec.height, Color(value));
  r.info = reference_settings(spec);
  r.info["estimator"] = "closed form";
  r.info["spp"] = 0;
  r.info["standard_error_rms"] = 0.0;
  return r;
}

// The cache folder, open: every file is read and written relative to this descriptor, so the
// folder checked is the folder used, whatever is renamed or planted meanwhile.
class CacheFolder {
 public:
  CacheFolder(int fd, fs::path path) : fd_(fd), path_(std::move(path)) {}
  CacheFolder(CacheFolder&& other) noexcept : fd_(std::exchange(other.fd_, -1)), path_(other.path_) {}
  CacheFolder(const CacheFolder&) = delete;
  CacheFolder& operator=(const CacheFolder&) = delete;
  ~CacheFolder() {
    if (fd_ >= 0) ::close(fd_);
  }
  int fd() const { return fd_; }
  const fs::path& path() const { return path_; }

 private:
  int fd_ = -1;
  fs::path path_;
};

// Why the folder open as `fd` may not hold a cache, or "" if it may.
std::string folder_problem(int fd) {
  struct stat status {};
  if (::fstat(fd, &status) != 0) return std::strerror(errno);
  if (!S_ISDIR(status.st_mode)) return "it is not a folder";
  if (status.st_uid != ::geteuid())
    return fmt::format("it belongs to another user (uid {})", status.st_uid);
  if ((status.st_mode & S_IWOTH) && !(status.st_mode & S_ISVTX))
    return "anyone may write in it (o+w, no sticky bit)";
  return "";
}

[[noreturn]] void refuse_folder(const fs::path& dir, const std::string& why) {
  throw UsageError(fmt::format("--reference-dir: the reference cache '{}' is refused: {}; give "
                               "a folder of your own",
                               dir.string(), why));
}

// Opens `dir` without following a link at its last component; nullopt if it does not exist.
// Throws UsageError (exit 2, before any work) if it is a link, not a folder, another user's,
// or writable by others without the sticky bit.
std::optional<CacheFolder> open_cache_folder(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    const int reason = errno;
    struct stat status {};
    if (::lstat(dir.c_str(), &status) != 0 && (errno == ENOENT || errno == ENOTDIR))
      return std::nullopt;
    if (S_ISLNK(status.st_mode))
      refuse_folder(dir, "it is a symbolic link");
    if (reason == ENOTDIR) refuse_folder(dir, "it is not a folder");
    throw IoError(fmt::format("cannot open the reference cache '{}': {}", dir.string(),
                              std::strerror(reason)));
  }
  CacheFolder folder(fd, dir);
  if (const std::string why = folder_problem(fd); !why.empty()) refuse_folder(dir, why);
  return folder;
}

// The cache folder, created (mode 0755, parents as needed) if missing; `created` says so.
CacheFolder create_cache_folder(const fs::path& dir, bool& created) {
  created = false;
  if (auto folder = open_cache_folder(dir)) return std::move(*folder);
  std::error_code ec;
  if (!dir.parent_path().empty()) fs::create_directories(dir.parent_path(), ec);
  if (::mkdir(dir.c_str(), 0755) == 0)
    created = true;
  else if (errno != EEXIST)
    throw IoError(fmt::format("cannot create the reference cache '{}': {}", dir.string(),
                              std::strerror(errno)));
  if (auto folder = open_cache_folder(dir)) return std::move(*folder);
  throw IoError(fmt::format("cannot create the reference cache '{}': it vanished", dir.string()));
}

// A shared (readers) or exclusive (writers) lock on the folder, so that a reader sees a PFM and
// its JSON from one writer. Waits a bounded time: anyone who can read the folder can lock it,
// and the hash check keeps the cache correct without the lock.
class FolderLock {
 public:
  FolderLock(int fd, int operation) : fd_(fd) {
    // 100 tries 50 ms apart: 5 s, well above the milliseconds a writer holds it.
    for (int attempt = 0; attempt < 100 && !held_; ++attempt) {
      held_ = ::flock(fd_, operation | LOCK_NB) == 0;
      if (!held_) ::usleep(50'000);
    }
  }
  ~FolderLock() {
    if (held_) ::flock(fd_, LOCK_UN);
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  bool held() const { return held_; }

 private:
  int fd_;
  bool held_ = false;
};

// A cache file's bytes, or why it cannot be used. It must be a regular file of ours, no larger
// than `limit` bytes, checked before it is opened (a FIFO is never opened) and again once open.
struct FileBytes {
  std::optional<std::string> bytes;
  std::string problem;  // "" with bytes; "missing" when there is no such file
};

FileBytes read_cache_file(int dir_fd, const std::string& name, off_t limit) {
  struct stat before {};
  if (::fstatat(dir_fd, name.c_str(), &before, AT_SYMLINK_NOFOLLOW) != 0)
    return {std::nullopt, errno == ENOENT ? "missing" : std::strerror(errno)};
  if (!S_ISREG(before.st_mode)) return {std::nullopt, name + " is not a regular file"};
  if (before.st_uid != ::geteuid()) return {std::nullopt, name + " belongs to another user"};
  if (before.st_size > limit)
    return {std::nullopt, fmt::format("{} holds {} bytes, more than it may", name, before.st_size)};
  const int fd = ::openat(dir_fd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return {std::nullopt, fmt::format("{}: {}", name, std::strerror(errno))};
  struct stat opened {};
  if (::fstat(fd, &opened) != 0 || opened.st_ino != before.st_ino || !S_ISREG(opened.st_mode) ||
      opened.st_size > limit) {
    ::close(fd);
    return {std::nullopt, name + " changed while it was opened"};
  }
  std::string bytes(static_cast<std::size_t>(opened.st_size), '\0');
  const std::size_t got = read_all(fd, bytes);
  ::close(fd);
  if (got != bytes.size()) return {std::nullopt, name + " is shorter than its size"};
  return {std::move(bytes), ""};
}

// The cache's PFM: exactly the bytes encode_pfm writes for an image of the spec's size.
std::size_t expected_pfm_bytes(const ReferenceSpec& spec) {
  return fmt::format("PF\n{} {}\n-1.0\n", spec.width, spec.height).size() +
         static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) * 12;
}

// A description's JSON is a few hundred bytes; 64 KiB bounds what a reader takes in.
constexpr off_t k_largest_description = 64 * 1024;

// The cached reference, or why it cannot be used ("" when there is none or its settings are
// other than the spec's: a normal miss). Checked in order: the JSON (a regular file, its
// settings, its record of the PFM), the PFM's size before it is read, its SHA-256, then every
// value finite and non-negative.
std::variant<Reference, std::string> load_cached(const CacheFolder& folder,
                                                 const ReferenceSpec& spec) {
  const std::string stem = reference_stem(spec);
  const std::string json_name = stem + ".json", pfm_name = stem + ".pfm";
  const FolderLock lock(folder.fd(), LOCK_SH);
  FileBytes json_bytes = read_cache_file(folder.fd(), json_name, k_largest_description);
  if (!json_bytes.bytes) return json_bytes.problem == "missing" ? "" : json_bytes.problem;
  nlohmann::ordered_json info;
  try {
    info = nlohmann::ordered_json::parse(*json_bytes.bytes);
  } catch (const nlohmann::json::exception&) {
    return json_name + " is not valid JSON";
  }
  if (!info.is_object() || !info.contains("settings")) return json_name + " has no settings";
  if (info["settings"] != reference_settings(spec)) return "";
  const auto& record = info.contains("pfm") ? info["pfm"] : nlohmann::ordered_json();
  if (!record.is_object() || !record.contains("bytes") || !record["bytes"].is_number_unsigned() ||
      !record.contains("sha256") || !record["sha256"].is_string())
    return json_name + " records no size and hash of its PFM (an older or partial cache)";
  const std::size_t expected = expected_pfm_bytes(spec);
  if (record["bytes"].get<std::size_t>() != expected)
    return fmt::format("{} records a PFM of {} bytes, not the {} of a {}x{} image", json_name,
                       record["bytes"].get<std::size_t>(), expected, spec.width, spec.height);
  FileBytes pfm = read_cache_file(folder.fd(), pfm_name, static_cast<off_t>(expected));
  if (!pfm.bytes)
    return pfm.problem == "missing" ? pfm_name + " is missing" : pfm.problem;
  if (pfm.bytes->size() != expected)
    return fmt::format("{} holds {} bytes, not the {} its description records", pfm_name,
                       pfm.bytes->size(), expected);
  if (sha256_hex(*pfm.bytes) != record["sha256"].get<std::string>())
    return pfm_name + " does not match the SHA-256 its description records";
  Reference r;
  try {
    r.image = decode_pfm(*pfm.bytes, pfm_name);
  } catch (const IoError& e) {
    return e.what();
  }
  if (r.image.width != spec.width || r.image.height != spec.height)
    return pfm_name + " is not of the size its name says";
  for (const Color& pixel : r.image.pixels)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(pixel[c]) || pixel[c] < 0.0)
        return fmt::format("{} holds a value that is not finite and non-negative ({})", pfm_name,
                           pixel[c]);
  info.erase("pfm");
  r.info = std::move(info);
  return r;
}

// Writes `bytes` as `name` in the cache: a new temporary file (io/exclusive_file.hpp), then
// renamed. Throws IoError naming the file.
void write_cache_file(const CacheFolder& folder, const std::string& name, std::string_view bytes) {
  const NewFile file = create_temporary(folder.fd(), name);
  const std::string path = (folder.path() / name).string();
  if (file.fd < 0) throw IoError("cannot write '" + path + "': " + file.error.message());
  std::error_code failure = write_all(file.fd, bytes);
  if (!failure && ::renameat(folder.fd(), file.name.c_str(), folder.fd(), name.c_str()) != 0)
    failure = {errno, std::generic_category()};
  if (failure) ::unlinkat(folder.fd(), file.name.c_str(), 0);
  ::close(file.fd);  // after the rename: the lock marks a live writer until then
  if (failure) throw IoError("cannot write '" + path + "': " + failure.message());
}

// Removes what killed writers left: temporary files no one holds, and a PFM whose JSON is
// missing (a writer killed between the two renames). Only under the exclusive lock, when no
// writer is between its two renames.
void remove_leftovers(const CacheFolder& folder) {
  const FolderLock lock(folder.fd(), LOCK_EX);
  if (!lock.held()) return;
  remove_abandoned_temporaries(folder.fd());
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder.path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() < 5 || name.compare(name.size() - 4, 4, ".pfm") != 0 || name[0] == '.')
      continue;
    const std::string json = name.substr(0, name.size() - 4) + ".json";
    struct stat status {};
    if (::fstatat(folder.fd(), json.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0 &&
        errno == ENOENT)
      ::unlinkat(folder.fd(), name.c_str(), 0);
  }
}

// Two independent halves A and B (spp/2 each, at least 1): the reference is their mean, and
// E[(A - B)^2] / 2 = Var[A] gives its standard error, Var[(A + B)/2] = Var[A] / 2.
Reference render_reference(const ReferenceSpec& spec) {
  const Scene scene = make_scene(spec.scene.scene, spec.scene.params);
  const Camera camera(scene.camera, spec.width, spec.height);
  const int half = std::max(1, spec.spp / 2);
  ProgressBar progress(fmt::format("reference {}", reference_stem(spec)), 2ull * spec.height,
                       spec.quiet);
  const PathEnd end{Roulette{}, spec.max_depth};
  const auto mis = [&](const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_mis_radiance(scene, ray, end, MisHeuristic::power, rng, count);
  };
  const RenderSettings a_settings{half, k_reference_first_sample, spec.seed, spec.threads,
                                  &progress};
  RenderSettings b_settings = a_settings;
  b_settings.first_sample += static_cast<std::uint64_t>(half);
  const RenderResult a = render(camera, a_settings, mis);
  const RenderResult b = render(camera, b_settings, mis);
  progress.finish();
  Reference r;
  r.image = Image(spec.width, spec.height);
  double relative_variance = 0.0;  // mean of Var[R] / (R^2 + 0.01): its own relative MSE
  for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
    // Rounded to float, as the PFM stores it: a fresh reference and a cached one are the same.
    r.image.pixels[i] = Color(glm::vec3(0.5 * (a.image.pixels[i] + b.image.pixels[i])));
    for (int c = 0; c < 3; ++c) {
      const double d = a.image.pixels[i][c] - b.image.pixels[i][c], m = r.image.pixels[i][c];
      relative_variance += d * d / 4.0 / (m * m + 0.01);  // (A - B)^2 / 4 estimates Var[R]
    }
  }
  relative_variance /= 3.0 * static_cast<double>(r.image.pixels.size());
  r.rendered = true;
  r.seconds = a.seconds + b.seconds;
  r.info = {{"settings", reference_settings(spec)},
            {"estimator", "mis (power heuristic), Russian roulette"},
            {"seed", spec.seed},
            {"spp", 2 * half},
            {"seconds", r.seconds},
            {"rays", a.rays + b.rays},
            {"standard_error_rms", std::sqrt(two_render_mean_squared_error(a.image, b.image) / 2.0)},
            {"relative_mse_of_reference", relative_variance},
            {"mean_radiance", mean_radiance(r.image)}};
  return r;
}

}  // namespace

std::string reference_stem(const ReferenceSpec& spec) {
  std::string stem = fmt::format("{}_ls{}_{}x{}", spec.scene.scene,
                                 spec.scene.scene == "cornell" ? spec.scene.params.light_scale : 1.0,
                                 spec.width, spec.height);
  if (is_furnace(spec))
    stem += fmt::format("_a{}_e{}", spec.scene.params.furnace_albedo,
                        spec.scene.params.furnace_emission);
  if (spec.max_depth >= 0) stem += fmt::format("_d{}", spec.max_depth);
  return stem;
}

nlohmann::ordered_json reference_settings(const ReferenceSpec& spec) {
  const SceneParams& p = spec.scene.params;
  return {{"scene", spec.scene.scene},
          {"light_scale", spec.scene.scene == "cornell" ? p.light_scale : 1.0},
          {"furnace_albedo", p.furnace_albedo},
          {"furnace_emission", p.furnace_emission},
          {"width", spec.width},
          {"height", spec.height},
          {"spp", 2 * std::max(1, spec.spp / 2)},
          {"max_depth", spec.max_depth},
          {"seed", spec.seed},
          {"estimator", "mis_power"}};
}

void check_reference_folder(const fs::path& dir) { open_cache_folder(dir); }

Reference load_or_render_reference(const fs::path& dir, const ReferenceSpec& spec) {
  if (is_furnace(spec)) return furnace_reference(spec);
  if (std::optional<CacheFolder> folder = open_cache_folder(dir)) {
    remove_leftovers(*folder);
    auto cached = load_cached(*folder, spec);
    if (auto* r = std::get_if<Reference>(&cached)) return std::move(*r);
    if (const auto& why = std::get<std::string>(cached); !why.empty())
      std::cerr << "note: rendering the reference " << reference_stem(spec)
                << " again: the cached one is not used (" << why << ")\n";
  }
  Reference r = render_reference(spec);
  bool created = false;
  const CacheFolder folder = create_cache_folder(dir, created);
  const std::string stem = reference_stem(spec);
  const std::string pfm = encode_pfm(r.image);
  // The description is written last and records the PFM's size and hash: a reader that finds
  // them disagreeing (a writer killed between the two, or two writers crossing) renders again.
  nlohmann::ordered_json description = r.info;
  description["pfm"] = {{"bytes", pfm.size()}, {"sha256", sha256_hex(pfm)}};
  try {
    // Exclusive: no reader takes a PFM of this writer with a JSON of another.
    const FolderLock lock(folder.fd(), LOCK_EX);
    write_cache_file(folder, stem + ".pfm", pfm);
    write_cache_file(folder, stem + ".json", description.dump(2) + "\n");
  } catch (...) {
    // The cache holds whole references only: no PFM without its JSON, no folder left empty.
    ::unlinkat(folder.fd(), (stem + ".pfm").c_str(), 0);
    if (created) ::rmdir(dir.c_str());  // removes it only if empty
    throw;
  }
  return r;
}

double reference_predicted_rays(const ReferenceSpec& spec, double rays_per_sample) {
  return static_cast<double>(spec.width) * spec.height * 2.0 * std::max(1, spec.spp / 2) *
         rays_per_sample;
}

}  // namespace mcrt
