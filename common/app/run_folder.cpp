#include "app/run_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>
#include <tuple>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "app/interrupt.hpp"
#include "app/usage_error.hpp"
#include "io/exclusive_file.hpp"
#include "io/output.hpp"

namespace mcrt {

namespace fs = std::filesystem;

bool is_within(const fs::path& inner, const fs::path& outer) {
  return std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end()).first == outer.end();
}

fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) result = fs::absolute(path, ec).lexically_normal();
  if (result.filename().empty()) result = result.parent_path();  // "out/" is "out"
  return result;
}

std::string not_our_folder(const struct stat& info, bool sticky_ok, bool root_ok) {
  const bool group_writable = (info.st_mode & S_IWGRP) && info.st_gid != ::getegid();
  if (info.st_uid != ::geteuid() && !(root_ok && info.st_uid == 0))
    return "is owned by another user";
  if (!(sticky_ok && (info.st_mode & S_ISVTX)) && ((info.st_mode & S_IWOTH) || group_writable))
    return "can be written by other users";
  return "";
}

namespace {

// A manifest lists a run's few dozen files; anything larger is not one and is not read.
constexpr off_t k_max_manifest_bytes = 1 << 20;
constexpr const char* k_previous_suffix = "-previous";

// The folder a run into `out` replaces, links followed; UsageError for the folders that are
// never replaced whatever they hold: the root, the current folder or one above it, and the
// user's home folders ($HOME and the password database's entry: they may differ).
fs::path checked_target(const fs::path& out) {
  if (out.empty()) throw UsageError("--out: give a folder name");
  const auto refuse = [&](const std::string& why) {
    throw UsageError(fmt::format("--out '{}' is {}", out.string(), why));
  };
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(out, ec)) && !fs::exists(fs::status(out, ec)))
    refuse("a symbolic link to nothing (a dangling link); remove it or choose another folder");
  const fs::path target = resolved(out), cwd = fs::current_path(ec);
  const std::string whole = "; a run replaces its --out whole, so give a folder of its own";
  if (target == target.root_path() || (!ec && is_within(cwd, target)))
    refuse("the current folder, one above it or the root" + whole);
  const char* home = std::getenv("HOME");
  const passwd* entry = ::getpwuid(::geteuid());
  if ((home && *home && target == resolved(home)) ||
      (entry && entry->pw_dir && *entry->pw_dir && target == resolved(entry->pw_dir)))
    refuse("your home folder" + whole);
  if (fs::exists(fs::status(target, ec)) && !fs::is_directory(fs::status(target, ec)))
    refuse("a file, not a folder; choose another name");
  return target;
}

// Every entry under `dir` (links are entries, never followed), relative, folders with a
// trailing '/', in sorted order.
std::vector<std::pair<std::string, fs::file_status>> entries_under(const fs::path& dir) {
  std::vector<std::pair<std::string, fs::file_status>> entries;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::file_status status = it->symlink_status(ec);
    const std::string slash = fs::is_directory(status) ? "/" : "";
    entries.emplace_back(it->path().lexically_relative(dir).string() + slash, status);
  }
  std::sort(entries.begin(), entries.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return entries;
}

// The manifest of `dir`, opened without following a link and without blocking, and locked
// with `lock` (LOCK_EX | LOCK_NB, or 0 for none): its descriptor if it is a regular file of
// this user, else -1. A FIFO in its place is never read.
int open_manifest(const fs::path& dir, int lock = 0) {
  const int fd =
      ::open((dir / k_manifest_name).c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  struct stat info {};
  if (fd >= 0 && (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode) || info.st_uid != ::geteuid() ||
                  (lock && ::flock(fd, lock) != 0))) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// What dir's manifest lists, one entry a line; nothing without a regular manifest of ours.
std::vector<std::string> manifest_entries(const fs::path& dir) {
  const int fd = open_manifest(dir);
  struct stat info {};
  std::string text;
  if (fd >= 0 && ::fstat(fd, &info) == 0 && info.st_size <= k_max_manifest_bytes) {
    text.resize(static_cast<std::size_t>(info.st_size));
    text.resize(read_all(fd, text));
  }
  if (fd >= 0) ::close(fd);
  std::vector<std::string> entries;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) entries.push_back(line);
  return entries;
}

// Removes `dir` and everything in it; a file created meanwhile (a worker still writing) makes
// one pass fail, so it tries a few times. Links inside are removed, never followed.
void remove_tree(const fs::path& dir) noexcept {
  std::error_code ec;
  for (int attempt = 0; attempt < 5 && (attempt == 0 || ec); ++attempt) fs::remove_all(dir, ec);
}

// UsageError naming --out when the folder at `path` (--out, or the folder it is made in) is not
// one this run can own (not_our_folder; root may own a parent, whose sticky bit, as /tmp's,
// keeps others from renaming what the run makes in it).
void refuse_unless_ours(const fs::path& path, const fs::path& out, bool parent) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return;  // a missing folder is made by this run
  if (const std::string why = not_our_folder(info, parent, parent); !why.empty())
    throw UsageError(
        fmt::format("--out '{}': {} {}; a run only writes in folders of your own, "
                    "so choose one",
                    out.string(), parent ? "the folder it is in" : "it", why));
}

// The process's umask, read without changing it (umask() would, for every thread).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.starts_with("Umask:")) return static_cast<mode_t>(std::stoul(line.substr(6), 0, 8));
  return 022;
}

// Creates the folders above `dir` that are missing; returns those it created, innermost first.
std::vector<fs::path> create_parents(const fs::path& dir, const fs::path& out) {
  std::vector<fs::path> created;
  std::error_code ec;
  for (fs::path p = dir.parent_path(); !fs::exists(fs::symlink_status(p, ec)); p = p.parent_path())
    created.insert(created.begin(), p);  // outermost first, to be made in that order
  for (std::size_t i = 0; i < created.size(); ++i)
    if (::mkdir(created[i].c_str(), 0775) != 0 && errno != EEXIST) {  // never writable by others
      const int reason = errno;
      for (std::size_t j = i; j-- > 0;) ::rmdir(created[j].c_str());
      throw IoError(
          fmt::format("cannot create output folder '{}': {}", out.string(), std::strerror(reason)));
    }
  std::reverse(created.begin(), created.end());
  return created;
}

// Makes a staging folder in `parent`, readable by this user only until the commit (nothing of
// another user's can be planted in it), with a manifest listing itself whose lock this run
// holds until the end: the folder's mark of a live run. Returns the folder and the locked
// manifest's descriptor; throws IoError naming --out.
std::pair<fs::path, int> make_staging(const fs::path& parent, const std::string& name,
                                      const fs::path& out) {
  int reason = EEXIST;
  for (int attempt = 0; attempt < 8 && reason == EEXIST; ++attempt) {
    const fs::path dir = parent / staging_name(name, random_suffix());
    if (::mkdir(dir.c_str(), 0700) != 0) {
      reason = errno;
      continue;
    }
    const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    // Locked before it gets the manifest's name: a cleaner never sees it unlocked.
    NewFile manifest = dir_fd >= 0 ? create_temporary(dir_fd, k_manifest_name) : NewFile{};
    reason = dir_fd < 0 ? errno : manifest.error.value();
    if (manifest.fd >= 0) {
      const std::string text = std::string(k_manifest_name) + "\n";
      if (const std::error_code error = write_all(manifest.fd, text))
        reason = error.value();
      else if (::renameat(dir_fd, manifest.name.c_str(), dir_fd, k_manifest_name) != 0)
        reason = errno;
    }
    if (dir_fd >= 0) ::close(dir_fd);
    if (reason == 0) return {dir, manifest.fd};
    if (manifest.fd >= 0) ::close(manifest.fd);
    remove_tree(dir);
    if (reason == EEXIST) reason = EIO;  // the folder was new: a clash inside it is not a retry
  }
  throw IoError(
      fmt::format("cannot create output folder '{}': {}", out.string(), std::strerror(reason)));
}

// The names directly in `dir`.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  return names;
}

// Removes, in `dir`, the staging folders of runs that are gone: named as staging_name() makes
// them (with "-previous" while one holds a run a commit set aside; never a name the user
// chose, such as `.draft.staging-999999`), folders of this user holding a manifest of this
// user whose lock can be taken (a live run, in any PID namespace or machine, holds it).
void remove_stale_staging(const fs::path& dir) noexcept {
  static const std::regex k_staging(R"(\..*\.staging-[0-9a-f]{16}(-previous)?)");
  for (const std::string& name : names_in(dir)) {
    struct stat info {};
    if (!std::regex_match(name, k_staging) || ::lstat((dir / name).c_str(), &info) != 0 ||
        !S_ISDIR(info.st_mode) || info.st_uid != ::geteuid())
      continue;
    const int lock = open_manifest(dir / name, LOCK_EX | LOCK_NB);
    if (lock < 0) continue;
    remove_tree(dir / name);  // under its lock: no run can be using it
    ::close(lock);
  }
}

}  // namespace

std::optional<std::string> first_foreign_entry(const fs::path& dir) {
  const std::vector<std::string> listed = manifest_entries(dir);
  for (const auto& [relative, status] : entries_under(dir))
    if (!(fs::is_regular_file(status) || fs::is_directory(status)) ||
        std::find(listed.begin(), listed.end(), relative) == listed.end())
      return relative;
  return std::nullopt;
}

std::string staging_name(const std::string& name, const std::string& suffix) {
  const std::string tail = ".staging-" + suffix;
  // Room for the dot, the tail and "-previous" (the name of a run a commit sets aside).
  const std::size_t room = NAME_MAX - 1 - tail.size() - std::strlen(k_previous_suffix);
  std::size_t keep = std::min(name.size(), room);
  while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80)
    --keep;  // never cut a UTF-8 character in two
  return fmt::format(".{}{}", name.substr(0, keep), tail);
}

RunFolder::RunFolder(fs::path out) : out_(std::move(out)), target_(checked_target(out_)) {
  const fs::path parent = target_.parent_path();
  fs::path nearest = parent;  // the folder the run makes its folders in: the parent, or above it
  std::error_code ec;
  while (!fs::exists(fs::symlink_status(nearest, ec)) && nearest != nearest.parent_path())
    nearest = nearest.parent_path();
  refuse_unless_ours(nearest, out_, true);
  struct stat target_info {
  }, parent_info{};
  const bool exists = ::stat(target_.c_str(), &target_info) == 0;
  // A mount point cannot be swapped: an empty one is written into (staged inside it).
  in_place_ = exists && ::stat(parent.c_str(), &parent_info) == 0 &&
              parent_info.st_dev != target_info.st_dev;
  if (exists) {
    refuse_unless_ours(target_, out_, false);
    if (in_place_) remove_stale_staging(target_);
    if (const std::optional<std::string> foreign = first_foreign_entry(target_)) {
      const bool listed = fs::exists(fs::symlink_status(target_ / k_manifest_name, ec));
      throw UsageError(fmt::format(
          "--out '{}' holds '{}', which no run wrote ({}); not replaced, choose a new or empty "
          "folder",
          out_.string(), *foreign,
          listed ? fmt::format("not in its {}", k_manifest_name)
                 : fmt::format("no {}: an old version's run?", k_manifest_name)));
    }
  }
  if (in_place_ && !fs::is_empty(target_, ec))
    throw UsageError(
        fmt::format("--out '{}' is a mount point holding a run, which cannot be "
                    "swapped whole; empty it or give a folder inside it",
                    out_.string()));
  remove_stale_staging(parent);
  if (!exists) created_parents_ = create_parents(target_, out_);
  try {
    std::tie(staging_, lock_fd_) =
        make_staging(in_place_ ? target_ : parent, target_.filename().string(), out_);
  } catch (const IoError&) {
    for (const fs::path& created : created_parents_) ::rmdir(created.c_str());
    throw;
  }
  struct stat info {};
  ::stat(staging_.c_str(), &info);
  // A new --out is never writable by others (the next run would refuse it), and keeps a setgid
  // parent's bit; a replaced one keeps its mode and group.
  mode_ =
      exists ? target_info.st_mode & 07777 : (0775 & ~current_umask()) | (info.st_mode & S_ISGID);
  if (exists && info.st_gid != target_info.st_gid &&
      ::chown(staging_.c_str(), static_cast<uid_t>(-1), target_info.st_gid) != 0) {
    discard();
    throw UsageError(
        fmt::format("--out '{}' belongs to a group you cannot give a new folder; a "
                    "run replaces its --out whole, so choose a folder of your own",
                    out_.string()));
  }
}

RunFolder::~RunFolder() { discard(); }

// Renames the staging folder's entries into the empty mount point --out, the manifest last;
// on failure renames back what it moved, or says where both parts are.
void RunFolder::commit_into_mount_point() {
  std::vector<std::string> names = names_in(staging_), moved;
  if (names_in(target_) != std::vector<std::string>{staging_.filename().string()})
    throw IoError(
        fmt::format("cannot write output folder '{}': something appeared in it during "
                    "the run; nothing written",
                    out_.string()));
  std::stable_partition(names.begin(), names.end(), [](auto& n) { return n != k_manifest_name; });
  for (const std::string& name : names) {
    if (::rename((staging_ / name).c_str(), (target_ / name).c_str()) == 0) {
      moved.push_back(name);
      continue;
    }
    const int reason = errno;
    std::size_t back = 0;
    for (const std::string& m : moved)
      back += ::rename((target_ / m).c_str(), (staging_ / m).c_str()) == 0;
    std::string where = "nothing written";
    if (back != moved.size())  // kept, never discarded
      where = fmt::format("part of this run is in it, the rest in '{}'",
                          std::exchange(staging_, fs::path()).string());
    throw IoError(fmt::format("cannot write output folder '{}': {}; {}", out_.string(),
                              std::strerror(reason), where));
  }
  ::rmdir(staging_.c_str());
}

void RunFolder::discard() noexcept {
  if (!committed_) {
    remove_tree(staging_);
    for (const fs::path& parent : created_parents_) ::rmdir(parent.c_str());  // only if empty
    created_parents_.clear();
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);
  lock_fd_ = -1;
}

void RunFolder::commit() {
  without_interruption([&] {
    // Everything under the staging folder, the manifest itself included (a name with a newline
    // cannot be listed), written through the locked descriptor: the folder stays marked live
    // until it is --out.
    std::string manifest = std::string(k_manifest_name) + "\n";
    for (const auto& entry : entries_under(staging_))
      if (entry.first != k_manifest_name && entry.first.find('\n') == std::string::npos)
        manifest += entry.first + "\n";
    std::error_code error;
    if (::ftruncate(lock_fd_, 0) != 0 || ::lseek(lock_fd_, 0, SEEK_SET) != 0)
      error = {errno, std::generic_category()};
    if (error || (error = write_all(lock_fd_, manifest)))
      throw IoError(
          fmt::format("cannot write '{}': {}", (out_ / k_manifest_name).string(), error.message()));
    const auto fail = [&](int reason, const char* hint = "") {
      throw IoError(
          fmt::format("cannot write output folder '{}': {}{}; it still holds the "
                      "previous run",
                      out_.string(), std::strerror(reason), hint));
    };
    ::chmod(staging_.c_str(), mode_);
    struct stat info {};
    if (in_place_) {
      commit_into_mount_point();
    } else if (::stat(target_.c_str(), &info) != 0) {
      if (::rename(staging_.c_str(), target_.c_str()) != 0) fail(errno);
    } else {
      // Something added to --out during the run would be lost with the previous run.
      if (const std::optional<std::string> foreign = first_foreign_entry(target_))
        throw IoError(
            fmt::format("cannot replace output folder '{}': '{}' appeared in it during "
                        "the run and no run wrote it; nothing replaced",
                        out_.string(), *foreign));
      if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) !=
          0) {
        if (errno == EXDEV)  // overlayfs: a folder of a lower layer cannot be moved
          fail(EXDEV, " (a folder of the image's lower layer: remove it or choose a new one)");
        if (errno != EINVAL && errno != ENOSYS) fail(errno);
        // A file system that cannot exchange: the previous run is renamed aside, then back if
        // the new one cannot take its place.
        const fs::path aside = staging_.string() + k_previous_suffix;
        if (::rename(target_.c_str(), aside.c_str()) != 0) fail(errno);
        if (::rename(staging_.c_str(), target_.c_str()) != 0) {
          const int reason = errno;
          if (::rename(aside.c_str(), target_.c_str()) == 0) fail(reason);
          throw IoError(
              fmt::format("cannot write output folder '{}': {}; the previous run is in "
                          "'{}', the new one in '{}'",
                          out_.string(), std::strerror(reason), aside.string(),
                          std::exchange(staging_, fs::path()).string()));  // both kept
        }
        ::rename(aside.c_str(), staging_.c_str());  // removed below, with the staging name
      }
      committed_ = true;
      remove_tree(staging_);  // the staging name now holds the previous run
    }
    committed_ = true;
    discard();
  });
}

std::string RunFolder::with_out_name(std::string text) const {
  const std::string from = staging_.string(), to = out_.string();
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace mcrt
