#include "app/run_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
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
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) result = fs::absolute(path, ec).lexically_normal();
  if (result.filename().empty()) result = result.parent_path();  // "out/" is "out"
  return result;
}

namespace {

// A manifest lists a run's few dozen files; anything larger is not one and is not read.
constexpr off_t k_max_manifest_bytes = 1 << 20;
constexpr const char* k_staging_infix = ".staging-";
constexpr const char* k_previous_suffix = "-previous";

// Appended piece by piece: "'" + a temporary trips a false -Wrestrict in g++ 12.
std::string quoted(const fs::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

std::string reason_of(int error) { return std::error_code(error, std::generic_category()).message(); }

// The user's home folders: $HOME and the password database's entry (they may differ).
std::vector<fs::path> home_folders() {
  std::vector<fs::path> homes;
  if (const char* home = std::getenv("HOME"); home && *home) homes.push_back(resolved(home));
  if (const passwd* entry = ::getpwuid(::geteuid()); entry && entry->pw_dir && *entry->pw_dir)
    homes.push_back(resolved(entry->pw_dir));
  return homes;
}

// The folder a run into `out` replaces, links followed; UsageError for the folders that are
// never replaced whatever they hold.
fs::path checked_target(const fs::path& out) {
  if (out.empty()) throw UsageError("--out: give a folder name");
  const auto refuse = [&](const std::string& why) {
    throw UsageError("--out " + quoted(out) + " is " + why);
  };
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(out, ec)) && !fs::exists(fs::status(out, ec)))
    refuse("a symbolic link to nothing (a dangling link); remove it or choose another folder");
  const fs::path target = resolved(out), cwd = fs::current_path(ec);
  const std::string whole = "; a run replaces its --out whole, so give a folder of its own";
  if (target == target.root_path() || (!ec && is_within(cwd, target)))
    refuse("the current folder, one above it or the root" + whole);
  for (const fs::path& home : home_folders())
    if (target == home) refuse("your home folder" + whole);
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

// The manifest's text, if `dir` holds a regular one: opened without following a link and
// without blocking (a FIFO in its place is never read), its type and size checked first.
std::optional<std::string> read_manifest(const fs::path& dir) {
  const int fd = ::open((dir / k_manifest_name).c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat info {};
  std::optional<std::string> text;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size <= k_max_manifest_bytes) {
    text.emplace(static_cast<std::size_t>(info.st_size), '\0');
    text->resize(read_all(fd, *text));
  }
  ::close(fd);
  return text;
}

// Removes `dir` and everything in it; a file created meanwhile (a worker still writing) makes
// one pass fail, so it tries a few times. Links inside are removed, never followed.
void remove_tree(const fs::path& dir) noexcept {
  for (int attempt = 0; attempt < 5; ++attempt) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (!ec) return;
  }
}

// A staging folder's name, with "-previous" while it holds the run a commit set aside. A name
// the user chose (`.draft.staging-999999`) does not match.
bool is_staging_name(const std::string& name) {
  static const std::regex k_staging(R"(\..*\.staging-[0-9a-f]{16}(-previous)?)");
  return std::regex_match(name, k_staging);
}

// Opens the manifest of the staging folder `dir` (a regular file of this user in a folder of
// this user, never a link or a FIFO) and takes its lock without waiting: -1 when it is not a
// run's or its run is alive (it holds the lock for its whole life, in any PID namespace).
int lock_abandoned_staging(const fs::path& dir) {
  struct stat info {};
  if (::lstat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::geteuid())
    return -1;
  const int fd = ::open((dir / k_manifest_name).c_str(),
                        O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return -1;
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode) || info.st_uid != ::geteuid() ||
      ::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// UsageError naming --out when the folder at `path` (--out, or the folder it is made in) is not
// one this run can own, as git refuses a repository another user owns: owned by another user
// (root may own a parent), or writable by a user other than this one and root (the sticky bit
// of a parent such as /tmp keeps others from renaming what the run makes in it).
void refuse_unless_ours(const fs::path& path, const fs::path& out, bool parent) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return;  // a missing folder is made by this run
  const bool sticky = parent && (info.st_mode & S_ISVTX);
  const bool group_writable = (info.st_mode & S_IWGRP) && info.st_gid != ::getegid();
  std::string why;
  if (info.st_uid != ::geteuid() && !(parent && info.st_uid == 0)) why = "is owned by another user";
  else if (!sticky && ((info.st_mode & S_IWOTH) || group_writable)) why = "can be written by other users";
  if (!why.empty())
    throw UsageError("--out " + quoted(out) + ": " + (parent ? "the folder it is in " : "it ") +
                     why + "; a run only writes in folders of your own, so choose one");
}

// The process's umask, read without changing it (umask() would, for every thread).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
  return 022;
}

// Creates the folders above `dir` that are missing; returns those it created, innermost first.
std::vector<fs::path> create_parents(const fs::path& dir, const fs::path& out) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir.parent_path(); !p.empty() && !fs::exists(fs::symlink_status(p, ec));
       p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  std::vector<fs::path> created;
  for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
    if (::mkdir(p->c_str(), 0775) != 0 && errno != EEXIST) {  // never writable by others
      const int reason = errno;
      for (const fs::path& c : created) ::rmdir(c.c_str());
      throw IoError("cannot create output folder " + quoted(out) + ": " + reason_of(reason));
    }
    created.insert(created.begin(), *p);
  }
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
      if (const std::error_code error = write_all(manifest.fd, text)) reason = error.value();
      else if (::renameat(dir_fd, manifest.name.c_str(), dir_fd, k_manifest_name) != 0) reason = errno;
    }
    if (dir_fd >= 0) ::close(dir_fd);
    if (reason == 0) return {dir, manifest.fd};
    if (manifest.fd >= 0) ::close(manifest.fd);
    remove_tree(dir);
    if (reason == EEXIST) reason = EIO;  // the folder was new: a clash inside it is not a retry
  }
  throw IoError("cannot create output folder " + quoted(out) + ": " + reason_of(reason));
}

// The names directly in `dir`.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  return names;
}

// What dir's manifest lists; nothing without a regular manifest.
std::vector<std::string> manifest_entries(const fs::path& dir) {
  std::vector<std::string> entries;
  std::istringstream lines(read_manifest(dir).value_or(""));
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) entries.push_back(line);
  return entries;
}

// The manifest of `dir`: everything under it, the manifest itself included.
std::string manifest_text(const fs::path& dir) {
  std::string text = std::string(k_manifest_name) + "\n";
  for (const auto& entry : entries_under(dir))  // a name with a newline cannot be listed
    if (entry.first != k_manifest_name && entry.first.find('\n') == std::string::npos)
      text += entry.first + "\n";
  return text;
}

// Removes, in `dir`, the staging folders of runs that are gone: named as staging_name() makes
// them, holding a manifest of this user whose lock can be taken (a live run, in any PID
// namespace or machine, holds it). Nothing else is touched.
void remove_stale_staging(const fs::path& dir) noexcept {
  try {
    for (const std::string& name : names_in(dir)) {
      if (!is_staging_name(name)) continue;
      const int lock = lock_abandoned_staging(dir / name);
      if (lock < 0) continue;
      remove_tree(dir / name);  // under its lock: no run can be using it
      ::close(lock);
    }
  } catch (...) {  // a folder that cannot be listed has nothing to clean
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
  const std::string tail = std::string(k_staging_infix).append(suffix);
  // Room for the dot, the tail and "-previous" (the name of a run a commit sets aside).
  const std::size_t room =
      NAME_MAX - 1 - tail.size() - std::char_traits<char>::length(k_previous_suffix);
  std::size_t keep = std::min(name.size(), room);
  while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80)
    --keep;  // never cut a UTF-8 character in two
  std::string result(1, '.');  // appended: "." + a temporary trips a false -Wrestrict
  return result.append(name, 0, keep).append(tail);
}

RunFolder::RunFolder(fs::path out) : out_(std::move(out)), target_(checked_target(out_)) {
  const fs::path parent = target_.parent_path();
  fs::path nearest = parent;  // the folder the run makes its folders in: the parent, or above it
  std::error_code ec;
  while (!fs::exists(fs::symlink_status(nearest, ec)) && nearest != nearest.parent_path())
    nearest = nearest.parent_path();
  refuse_unless_ours(nearest, out_, true);
  struct stat target_info {};
  const bool exists = ::stat(target_.c_str(), &target_info) == 0;
  // A mount point cannot be swapped: an empty one is written into (staged inside it).
  struct stat parent_info {};
  in_place_ = exists && ::stat(parent.c_str(), &parent_info) == 0 &&
              parent_info.st_dev != target_info.st_dev;
  if (exists) {
    refuse_unless_ours(target_, out_, false);
    if (in_place_) remove_stale_staging(target_);
    if (const std::optional<std::string> foreign = first_foreign_entry(target_)) {
      const bool listed = fs::exists(fs::symlink_status(target_ / k_manifest_name, ec));
      throw UsageError("--out " + quoted(out_) + " holds '" + *foreign + "', which no run wrote (" +
                       (listed ? std::string("not in its ") + k_manifest_name
                               : std::string("no ") + k_manifest_name + ": an old version's run?") +
                       "); not replaced, choose a new or empty folder");
    }
  }
  if (in_place_ && !fs::is_empty(target_, ec))
    throw UsageError("--out " + quoted(out_) + " is a mount point holding a run, which cannot be "
                     "swapped whole; empty it or give a folder inside it");
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
  if (!exists) {
    // Never writable by others (the next run would refuse it); a setgid parent's bit kept.
    mode_ = (0775 & ~current_umask()) | (info.st_mode & S_ISGID);
  } else {
    mode_ = target_info.st_mode & 07777;
    if (info.st_gid != target_info.st_gid &&
        ::chown(staging_.c_str(), static_cast<uid_t>(-1), target_info.st_gid) != 0) {
      discard();
      throw UsageError("--out " + quoted(out_) + " belongs to a group you cannot give a new "
                       "folder; a run replaces its --out whole, so choose a folder of your own");
    }
  }
}

RunFolder::~RunFolder() { discard(); }

// Renames the staging folder's entries into the empty mount point --out, the manifest last;
// on failure renames back what it moved, or says where both parts are.
void RunFolder::commit_into_mount_point() {
  std::vector<std::string> names = names_in(staging_), moved;
  if (names_in(target_) != std::vector<std::string>{staging_.filename().string()})
    throw IoError("cannot write output folder " + quoted(out_) + ": something appeared in it "
                  "during the run; nothing written");
  std::stable_partition(names.begin(), names.end(), [](const std::string& n) { return n != k_manifest_name; });
  for (const std::string& name : names) {
    if (::rename((staging_ / name).c_str(), (target_ / name).c_str()) == 0) {
      moved.push_back(name);
      continue;
    }
    const int reason = errno;
    std::size_t back = 0;
    for (const std::string& m : moved) back += ::rename((target_ / m).c_str(), (staging_ / m).c_str()) == 0;
    std::string where = "; nothing written";
    if (back != moved.size()) {
      where = "; part of this run is in it, the rest in " + quoted(staging_);
      staging_.clear();  // kept, never discarded
    }
    throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(reason) + where);
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
    // Written through the locked descriptor: the folder stays marked live until it is --out.
    const std::string manifest = manifest_text(staging_);
    std::error_code error;
    if (::ftruncate(lock_fd_, 0) != 0 || ::lseek(lock_fd_, 0, SEEK_SET) != 0)
      error = {errno, std::generic_category()};
    if (!error) error = write_all(lock_fd_, manifest);
    if (error)
      throw IoError("cannot write '" + (out_ / k_manifest_name).string() + "': " + error.message());
    const auto fail = [&](int reason, const char* hint = "") {
      throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(reason) + hint +
                    "; it still holds the previous run");
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
        throw IoError("cannot replace output folder " + quoted(out_) + ": '" + *foreign +
                      "' appeared in it during the run and no run wrote it; nothing replaced");
      if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
        if (errno == EXDEV)  // overlayfs: a folder of a lower layer cannot be moved
          fail(EXDEV, " (a folder of the image's lower layer: remove it or choose a new one)");
        if (errno != EINVAL && errno != ENOSYS) fail(errno);
        // A file system that cannot exchange: the previous run is renamed aside, then back if
        // the new one cannot take its place.
        const fs::path aside = staging_.string() + k_previous_suffix;
        if (::rename(target_.c_str(), aside.c_str()) != 0) fail(errno);
        if (::rename(staging_.c_str(), target_.c_str()) != 0) {
          const int reason = errno;
          if (::rename(aside.c_str(), target_.c_str()) != 0) {
            const fs::path kept = std::exchange(staging_, fs::path());  // never discarded
            throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(reason) +
                          "; the previous run is in " + quoted(aside) + ", the new one in " +
                          quoted(kept));
          }
          fail(reason);
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
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace mcrt
