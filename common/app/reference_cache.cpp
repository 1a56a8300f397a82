#include "app/reference_cache.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/run_folder.hpp"
#include "app/usage_error.hpp"
#include "core/progress.hpp"
#include "geometry/camera.hpp"
#include "io/exclusive_file.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
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

// The settings the JSON must match for a cached reference to be reused.
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

Reference furnace_reference(const ReferenceSpec& spec) {
  const SceneParams& p = spec.scene.params;
  const double value = spec.max_depth < 0
                           ? furnace_radiance_untruncated(p.furnace_albedo, p.furnace_emission)
                           : furnace_radiance(p.furnace_albedo, p.furnace_emission, spec.max_depth);
  Reference r;
  r.image = Image(spec.width, spec.height, Color(value));
  r.info = reference_settings(spec);
  r.info["estimator"] = "closed form";
  r.info["spp"] = 0;
  r.info["standard_error_rms"] = 0.0;
  return r;
}

// The Cache Directory Tagging convention (backup tools skip a folder so tagged).
constexpr std::string_view k_tag_name = "CACHEDIR.TAG";
constexpr std::string_view k_tag_signature = "Signature: 8a477f597d28d172789f06886806bc55";
// The names of every file the cache wrote or is writing, one a line: the only files it deletes.
constexpr std::string_view k_index_name = "index.txt";

// The cache folder, open: every file is used relative to it, whatever is renamed meanwhile.
struct CacheFolder {
  int fd;
  fs::path path;
  CacheFolder(int descriptor, fs::path where) : fd(descriptor), path(std::move(where)) {}
  CacheFolder(CacheFolder&& other) noexcept : fd(std::exchange(other.fd, -1)), path(other.path) {}
  ~CacheFolder() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void refuse_folder(const fs::path& dir, const std::string& why,
                                const std::string& what_to_do = "give a folder of your own") {
  throw UsageError(fmt::format("--reference-dir: the reference cache '{}' is refused: {}; {}",
                               dir.string(), why, what_to_do));
}

// An exclusive lock on the folder while its index or tag changes. Bounded, since anyone who may
// read the folder may lock it: 100 tries 50 ms apart, far above the milliseconds a writer holds it.
struct FolderLock {
  int fd;
  bool held = false;
  explicit FolderLock(int folder_fd) : fd(folder_fd) {
    for (int attempt = 0; attempt < 100 && !held; ++attempt)
      if (!(held = ::flock(fd, LOCK_EX | LOCK_NB) == 0)) ::usleep(50'000);
  }
  ~FolderLock() {
    if (held) ::flock(fd, LOCK_UN);
  }
};

// `name` opened without following a link or blocking (a FIFO opens at once and is refused),
// if it is a regular file of ours of at most `limit` bytes: its descriptor, or -1 and
// `problem` ("missing" when there is no such file).
int open_own_file(int dir_fd, const std::string& name, off_t limit, std::string& problem) {
  const int fd = ::openat(dir_fd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  struct stat info {};
  if (fd < 0)
    problem = errno == ENOENT ? "missing" : fmt::format("{}: {}", name, std::strerror(errno));
  else if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode))
    problem = name + " is not a regular file";
  else if (info.st_uid != ::geteuid())
    problem = name + " belongs to another user";
  else if (info.st_size > limit)
    problem = fmt::format("{} holds {} bytes, more than it may", name, info.st_size);
  if (fd >= 0 && !problem.empty()) ::close(fd);
  return problem.empty() ? fd : -1;
}

// A cache file's bytes, or nullopt and why (as open_own_file says).
std::optional<std::string> read_cache_file(int dir_fd, const std::string& name, off_t limit,
                                           std::string& problem) {
  const int fd = open_own_file(dir_fd, name, limit, problem);
  struct stat info {};
  if (fd < 0 || ::fstat(fd, &info) != 0) return std::nullopt;
  std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
  if (read_all(fd, bytes) != bytes.size()) problem = name + " is shorter than its size";
  ::close(fd);
  return problem.empty() ? std::optional(std::move(bytes)) : std::nullopt;
}

bool has_tag(int dir_fd) {
  std::string problem;
  const auto tag = read_cache_file(dir_fd, std::string(k_tag_name), 4096, problem);
  return tag && tag->starts_with(k_tag_signature);
}

using NamedBytes = std::pair<std::string, std::string_view>;
void write_files(const CacheFolder& folder, const std::vector<NamedBytes>& files,
                 std::set<std::string>* index = nullptr);

// Opens `dir` (never through a link); nullopt if it does not exist. UsageError as
// check_reference_folder says; an empty folder is adopted: tagged.
std::optional<CacheFolder> open_cache_folder(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  struct stat info {};
  if (fd < 0) {
    const int reason = errno;
    if (::lstat(dir.c_str(), &info) != 0 && (errno == ENOENT || errno == ENOTDIR))
      return std::nullopt;
    if (S_ISLNK(info.st_mode)) refuse_folder(dir, "it is a symbolic link");
    if (reason == ENOTDIR) refuse_folder(dir, "it is not a folder");
    throw IoError(fmt::format("cannot open the reference cache '{}': {}", dir.string(),
                              std::strerror(reason)));
  }
  CacheFolder folder(fd, dir);
  ::fstat(fd, &info);
  // As for --out, save that a sticky cache (1777, like /tmp) keeps others from our files.
  if (const std::string why = not_our_folder(info, true, false); !why.empty())
    refuse_folder(dir, "it " + why);
  if (has_tag(fd)) return folder;
  // Locked: two runs adopting one new folder see each other's tag, not someone's files.
  const FolderLock lock(fd);
  std::error_code ec;  // the open folder itself, by its descriptor's name
  if (has_tag(fd)) return folder;
  if (!fs::is_empty(fs::path("/proc/self/fd") / std::to_string(fd), ec) || ec)
    refuse_folder(dir, fmt::format("it holds files and no {} (not a cache)", k_tag_name),
                  "give a new or empty folder");
  const std::string tag =
      fmt::format("{}\n# The cache of mcrt-companion's reference images: safe to delete.\n",
                  k_tag_signature);
  write_files(folder, {{std::string(k_tag_name), tag}});
  return folder;
}

// A relative XDG_CACHE_HOME is ignored, as the XDG Base Directory specification says.
fs::path default_cache_folder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg != nullptr && fs::path(xdg).is_absolute()) return fs::path(xdg) / "mcrt-companion";
  const char* home = std::getenv("HOME");
  if (home != nullptr && fs::path(home).is_absolute())
    return fs::path(home) / ".cache" / "mcrt-companion";
  throw UsageError(
      "--reference-dir: no folder for the reference cache: neither XDG_CACHE_HOME "
      "nor HOME is set to an absolute path; give --reference-dir a folder of your own");
}

// The cache folder, created if missing (the XDG base folder 0700, as its specification asks),
// opened and tagged; IoError saying what to do if it cannot be made.
CacheFolder create_cache_folder(const fs::path& dir) {
  if (auto folder = open_cache_folder(dir)) return std::move(*folder);
  std::error_code ec;
  if (!dir.parent_path().empty() && !fs::exists(dir.parent_path(), ec)) {
    fs::create_directories(dir.parent_path().parent_path(), ec);
    ::mkdir(dir.parent_path().c_str(), 0700);
  }
  if (::mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
    throw IoError(
        fmt::format("cannot create the reference cache '{}': {}; give --reference-dir a "
                    "folder you can write",
                    dir.string(), std::strerror(errno)));
  if (auto folder = open_cache_folder(dir)) return std::move(*folder);
  throw IoError(fmt::format("cannot create the reference cache '{}': it vanished", dir.string()));
}

// The names the cache wrote or is writing (none if unreadable); under the folder's lock.
std::set<std::string> read_index(int dir_fd) {
  std::string problem;
  std::istringstream lines(
      read_cache_file(dir_fd, std::string(k_index_name), 1 << 20, problem).value_or(""));
  std::set<std::string> names;
  for (std::string name; std::getline(lines, name);)
    if (!name.empty() && name.find('/') == std::string::npos && name != "." && name != "..")
      names.insert(name);
  return names;
}

// Writes each file through a new temporary, all made and written before any is renamed: a
// failure (EMFILE, a full disk) changes no file and removes only our temporaries. With
// `index`, the temporaries are named in it first. Throws IoError naming the file.
void write_files(const CacheFolder& folder, const std::vector<NamedBytes>& files,
                 std::set<std::string>* index) {
  std::vector<NewFile> temporaries;
  std::error_code failure;
  std::string failed = std::string(k_index_name);
  for (const auto& [name, bytes] : files) {
    NewFile file = create_temporary(folder.fd, name);
    if ((failure = file.error)) {
      failed = name;
      break;
    }
    if (index) index->insert({name, file.name});
    temporaries.push_back(std::move(file));
  }
  if (index && !failure) {
    std::string text;
    for (const std::string& name : *index) text += name + "\n";
    try {
      write_files(folder, {{std::string(k_index_name), text}});
    } catch (const IoError&) {
      failure = {EIO, std::generic_category()};
    }
  }
  for (std::size_t i = 0; i < temporaries.size() && !failure; ++i)
    if ((failure = write_all(temporaries[i].fd, files[i].second))) failed = files[i].first;
  for (std::size_t i = 0; i < temporaries.size() && !failure; ++i)
    if (::renameat(folder.fd, temporaries[i].name.c_str(), folder.fd, files[i].first.c_str()) != 0)
      failure = {errno, std::generic_category()}, failed = files[i].first;
  for (const NewFile& file : temporaries) {
    if (failure) ::unlinkat(folder.fd, file.name.c_str(), 0);  // ours: we hold its lock
    ::close(file.fd);  // after the rename: the lock marks a live writer until then
  }
  if (failure)
    throw IoError(
        fmt::format("cannot write '{}': {}", (folder.path / failed).string(), failure.message()));
}

bool missing(int dir_fd, const std::string& name) {
  struct stat info {};
  return ::fstatat(dir_fd, name.c_str(), &info, AT_SYMLINK_NOFOLLOW) != 0 && errno == ENOENT;
}

// Removes what killed writers left, and only that: files the index names, regular and ours,
// that are a temporary whose lock is free (a live writer in any PID namespace holds it) or a
// PFM without its JSON. Any error (EMFILE, EIO) leaves the file.
void remove_leftovers(const CacheFolder& folder) {
  const FolderLock lock(folder.fd);
  if (!lock.held) return;
  const std::set<std::string> named = read_index(folder.fd);
  std::set<std::string> kept;
  for (const std::string& name : named) {
    if (missing(folder.fd, name)) continue;  // renamed or removed: dropped from the index
    const bool temporary = name.starts_with(".") && name.find(".tmp-") != std::string::npos;
    const bool orphan_pfm = !temporary && name.ends_with(".pfm") &&
                            missing(folder.fd, name.substr(0, name.size() - 4) + ".json");
    std::string problem;
    const int fd = temporary || orphan_pfm
                       ? open_own_file(folder.fd, name, std::numeric_limits<off_t>::max(), problem)
                       : -1;
    const bool removed = fd >= 0 && (orphan_pfm || ::flock(fd, LOCK_EX | LOCK_NB) == 0) &&
                         ::unlinkat(folder.fd, name.c_str(), 0) == 0;
    if (fd >= 0) ::close(fd);
    if (!removed) kept.insert(name);
  }
  try {
    if (kept != named) write_files(folder, {}, &kept);
  } catch (const IoError&) {  // a stale index only names files that are gone
  }
}

// FNV-1a, 64 bits: it tells a PFM from another writer's or a spoiled one (no attacker here).
std::string checksum(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;  // the offset basis
  for (const unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3ull;  // the prime
  return fmt::format("{:016x}", hash);
}

// The cached reference, or why it cannot be used ("" for a normal miss). Read without a lock:
// a PFM and a JSON of two crossing writers disagree on the checksum. A JSON is a few hundred
// bytes: 64 KiB bounds what is read.
std::variant<Reference, std::string> load_cached(const CacheFolder& folder,
                                                 const ReferenceSpec& spec) {
  const std::string stem = reference_stem(spec);
  const std::string json_name = stem + ".json", pfm_name = stem + ".pfm";
  std::string problem;
  const auto json = read_cache_file(folder.fd, json_name, 64 * 1024, problem);
  if (!json) return problem == "missing" ? "" : problem;
  const auto info = nlohmann::ordered_json::parse(*json, nullptr, false);
  if (!info.is_object() || !info.contains("settings")) return json_name + " has no settings";
  if (info["settings"] != reference_settings(spec)) return "";
  if (!info.contains("pfm") || !info["pfm"].contains("fnv1a64"))
    return json_name + " records no checksum of its PFM (an older or partial cache)";
  // Exactly the bytes encode_pfm writes for an image of the spec's size.
  const std::size_t expected = fmt::format("PF\n{} {}\n-1.0\n", spec.width, spec.height).size() +
                               std::size_t{12} * spec.width * spec.height;
  const auto pfm = read_cache_file(folder.fd, pfm_name, static_cast<off_t>(expected), problem);
  if (!pfm) return problem == "missing" ? pfm_name + " is missing" : problem;
  if (pfm->size() != expected)
    return fmt::format("{} holds {} bytes, not the {} of a {}x{} image", pfm_name, pfm->size(),
                       expected, spec.width, spec.height);
  if (info["pfm"]["fnv1a64"] != checksum(*pfm))
    return pfm_name + " does not match the checksum its description records";
  Reference r;
  try {
    r.image = decode_pfm(*pfm, pfm_name);
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
  r.info = info;
  r.info.erase("pfm");
  return r;
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
            {"standard_error_rms",
             std::sqrt(two_render_mean_squared_error(a.image, b.image) / 2.0)},
            {"relative_mse_of_reference", relative_variance},
            {"mean_radiance", mean_radiance(r.image)}};
  return r;
}

}  // namespace

std::string reference_stem(const ReferenceSpec& spec) {
  std::string stem =
      fmt::format("{}_ls{}_{}x{}", spec.scene.scene,
                  spec.scene.scene == "cornell" ? spec.scene.params.light_scale : 1.0, spec.width,
                  spec.height);
  if (is_furnace(spec))
    stem += fmt::format("_a{}_e{}", spec.scene.params.furnace_albedo,
                        spec.scene.params.furnace_emission);
  if (spec.max_depth >= 0) stem += fmt::format("_d{}", spec.max_depth);
  return stem;
}

void add_reference_dir_option(CLI::App& app, std::filesystem::path& dir) {
  add_path_option(app, "--reference-dir", dir,
                  "Folder of the cached references: new, empty, or made by an earlier run (tagged "
                  "by its CACHEDIR.TAG) (default: $XDG_CACHE_HOME/mcrt-companion, else "
                  "~/.cache/mcrt-companion)");
}

fs::path reference_folder(const fs::path& flag) {
  return flag.empty() ? default_cache_folder() : flag;
}

void check_reference_folder(const fs::path& dir, const fs::path& out) {
  // Each run replaces --out whole: a cache inside it would be lost, a run inside the cache
  // would fill it with files it does not own.
  const fs::path cache = resolved(dir), run = resolved(out);
  if (!out.empty() && (is_within(cache, run) || is_within(run, cache)))
    throw UsageError(
        fmt::format("--reference-dir: the reference cache '{}' and --out '{}' may "
                    "not lie inside one another (each run replaces --out); give a "
                    "cache folder outside --out",
                    dir.string(), out.string()));
  create_cache_folder(dir);
}

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
  const CacheFolder folder = create_cache_folder(dir);
  const std::string pfm = encode_pfm(r.image);
  // Written last, the description records the PFM's size and checksum: a reader finding them
  // disagreeing (a writer killed between the two, two writers crossing) renders again.
  nlohmann::ordered_json description = r.info;
  description["pfm"] = {{"bytes", pfm.size()}, {"fnv1a64", checksum(pfm)}};
  const std::string json = description.dump(2) + "\n", stem = reference_stem(spec);
  const FolderLock lock(folder.fd);  // the index read and rewritten by one writer at a time
  std::set<std::string> index = read_index(folder.fd);
  write_files(folder, {{stem + ".pfm", pfm}, {stem + ".json", json}}, &index);
  return r;
}

double reference_predicted_rays(const ReferenceSpec& spec, double rays_per_sample) {
  return static_cast<double>(spec.width) * spec.height * 2.0 * std::max(1, spec.spp / 2) *
         rays_per_sample;
}

}  // namespace mcrt
