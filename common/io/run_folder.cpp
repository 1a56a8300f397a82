#include "io/run_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <set>
#include <system_error>

#include <fcntl.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "io/interrupt.hpp"
#include "io/output.hpp"
#include "io/usage_error.hpp"

namespace mcrt {

namespace fs = std::filesystem;

namespace {

// A manifest lists a run's few dozen files; anything larger is not one and is not read.
constexpr off_t k_max_manifest_bytes = 1 << 20;
constexpr const char* k_staging_infix = ".staging-";
constexpr const char* k_previous_suffix = "-previous";
// The name of a staging folder made inside --out (beside its files) rather than beside it.
constexpr const char* k_inside_name = "mcrt";

// Appended piece by piece: "'" + a temporary trips a false -Wrestrict in g++ 12.
std::string quoted(const fs::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

std::string reason_of(int error) { return std::error_code(error, std::generic_category()).message(); }

// `inner` is `outer` or lies inside it (both absolute and normal).
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

// `path` absolute, links followed as far as they exist, without a trailing '/'.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) result = fs::absolute(path, ec).lexically_normal();
  if (result.filename().empty()) result = result.parent_path();  // "out/" is "out"
  return result;
}

// The user's home folders: $HOME and the password database's entry (they may differ).
std::vector<fs::path> home_folders() {
  std::vector<fs::path> homes;
  if (const char* home = std::getenv("HOME"); home && *home) homes.push_back(resolved(home));
  if (const passwd* entry = ::getpwuid(::geteuid()); entry && entry->pw_dir && *entry->pw_dir)
    homes.push_back(resolved(entry->pw_dir));
  return homes;
}

// The folder a run into `out` replaces, links followed; UsageError for the folders that are
// never replaced whatever they hold. Whether its contents may be replaced is checked later.
fs::path checked_target(const fs::path& out) {
  if (out.empty()) throw UsageError("--out: give a folder name");
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(out, ec);
  if (fs::is_symlink(link) && !fs::exists(fs::status(out, ec)))
    throw UsageError("--out " + quoted(out) +
                     " is a symbolic link to nothing (a dangling link); remove it or choose "
                     "another folder");
  const fs::path target = resolved(out);
  const fs::path cwd = fs::current_path(ec);
  if (target == target.root_path() || (!ec && is_within(cwd, target)))
    throw UsageError("--out " + quoted(out) +
                     " is the current folder, one above it or the root; a run replaces its "
                     "--out whole, so give a folder of its own");
  for (const fs::path& home : home_folders())
    if (target == home)
      throw UsageError("--out " + quoted(out) +
                       " is your home folder; a run replaces its --out whole, so give a folder "
                       "of its own");
  const fs::file_status status = fs::status(target, ec);
  if (fs::exists(status) && !fs::is_directory(status))
    throw UsageError("--out " + quoted(out) + " is a file, not a folder; choose another name");
  return target;
}

// Every entry under `dir`, relative, folders with a trailing '/', in sorted order; entries in
// `skip` (names directly in `dir`) are left out. `visit` returns false to stop.
bool walk(const fs::path& dir, const std::string& prefix, const std::set<std::string>& skip,
          const std::function<bool(const std::string&, const fs::file_status&)>& visit) {
  std::error_code ec;
  std::vector<fs::directory_entry> entries;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    entries.push_back(*it);
  std::sort(entries.begin(), entries.end());
  for (const fs::directory_entry& entry : entries) {
    const std::string name = entry.path().filename().string();
    if (prefix.empty() && skip.count(name)) continue;
    const fs::file_status status = entry.symlink_status(ec);  // a link is an entry, not followed
    const bool folder = fs::is_directory(status);
    const std::string relative = prefix + name + (folder ? "/" : "");
    if (!visit(relative, status)) return false;
    if (folder && !walk(entry.path(), relative, {}, visit)) return false;
  }
  return true;
}

// The manifest's text, if `dir` holds a regular one: opened without following a link and
// without blocking (a FIFO in its place is never read), its type checked before reading.
std::optional<std::string> read_manifest(const fs::path& dir) {
  const fs::path path = dir / k_manifest_name;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat info {};
  std::optional<std::string> text;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size <= k_max_manifest_bytes) {
    text.emplace();
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) != 0;) {
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        text.reset();
        break;
      }
      text->append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return text;
}

std::optional<std::string> first_foreign_entry_except(const fs::path& dir,
                                                      const std::set<std::string>& skip) {
  std::set<std::string> listed;
  for (const std::string& entry : manifest_entries(dir)) listed.insert(entry);
  std::optional<std::string> foreign;
  walk(dir, "", skip, [&](const std::string& relative, const fs::file_status& status) {
    const bool ours = (fs::is_regular_file(status) || fs::is_directory(status)) &&
                      listed.count(relative) > 0;
    if (!ours) foreign = relative;
    return ours;
  });
  return foreign;
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

bool process_alive(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM; }

// The pid in a staging folder's name (`.<name>.staging-<pid>[-previous]`), or 0.
long staging_pid(const std::string& name) {
  if (name.size() < 2 || name[0] != '.') return 0;
  const std::size_t at = name.rfind(k_staging_infix);
  if (at == std::string::npos || at == 0) return 0;
  std::string digits = name.substr(at + std::char_traits<char>::length(k_staging_infix));
  const std::string previous = k_previous_suffix;
  if (digits.size() > previous.size() &&
      digits.compare(digits.size() - previous.size(), previous.size(), previous) == 0)
    digits.resize(digits.size() - previous.size());
  if (digits.empty() || digits.size() > 9 || digits[0] == '0' ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return 0;
  return std::stol(digits);
}

// A staging folder this user's runs made (a folder, not a link, of this user, holding a
// manifest or nothing): only those are ever removed by name.
bool is_our_staging(const fs::path& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::geteuid())
    return false;
  struct stat manifest {};
  if (::lstat((path / k_manifest_name).c_str(), &manifest) == 0) return S_ISREG(manifest.st_mode);
  std::error_code ec;
  return fs::is_empty(path, ec) && !ec;
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
    if (::mkdir(p->c_str(), 0777) != 0 && errno != EEXIST) {
      const int reason = errno;
      for (const fs::path& c : created) ::rmdir(c.c_str());
      throw IoError("cannot create output folder " + quoted(out) + ": " + reason_of(reason));
    }
    created.insert(created.begin(), *p);
  }
  return created;
}

// Makes the staging folder `dir`, readable by this user only until the commit (nothing of
// another user's can be planted in it), marked as a run's by a manifest listing itself.
// Returns 0 or errno.
int make_staging(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(dir, ec))) {
    if (!is_our_staging(dir)) return EEXIST;
    remove_tree(dir);  // an earlier process that had this pid
  }
  if (::mkdir(dir.c_str(), 0700) != 0) return errno;
  try {
    write_file_atomic(dir / k_manifest_name, std::string(k_manifest_name) + "\n");
  } catch (const IoError&) {
    const int reason = errno ? errno : EIO;
    remove_tree(dir);
    return reason;
  }
  return 0;
}

// The names directly in `dir`, but those in `skip`.
std::vector<std::string> names_in(const fs::path& dir, const std::set<std::string>& skip) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (!skip.count(name)) names.push_back(std::move(name));
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

std::vector<std::string> manifest_entries(const fs::path& dir) {
  std::vector<std::string> entries;
  const std::optional<std::string> text = read_manifest(dir);
  if (!text) return entries;
  std::size_t start = 0;
  while (start < text->size()) {
    const std::size_t end = std::min(text->find('\n', start), text->size());
    if (end > start) entries.push_back(text->substr(start, end - start));
    start = end + 1;
  }
  return entries;
}

std::optional<std::string> first_foreign_entry(const fs::path& dir) {
  return first_foreign_entry_except(dir, {});
}

void write_manifest(const fs::path& dir) {
  std::string text = std::string(k_manifest_name) + "\n";
  walk(dir, "", {k_manifest_name}, [&](const std::string& relative, const fs::file_status&) {
    if (relative.find('\n') == std::string::npos) text += relative + "\n";  // unlistable
    return true;
  });
  write_file_atomic(dir / k_manifest_name, text);
}

std::string staging_name(const std::string& name, long pid) {
  const std::string suffix = fmt::format("{}{}", k_staging_infix, pid);
  // Room for the dot, the suffix and "-previous" (the folder a commit moves a run aside to).
  const std::size_t room =
      NAME_MAX - 1 - suffix.size() - std::char_traits<char>::length(k_previous_suffix);
  std::size_t keep = std::min(name.size(), room);
  while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80)
    --keep;  // never cut a UTF-8 character in two
  return "." + name.substr(0, keep) + suffix;
}

void remove_stale_staging(const fs::path& dir) noexcept {
  try {
    for (const std::string& name : names_in(dir, {})) {
      const long pid = staging_pid(name);
      if (pid <= 0 || pid == ::getpid() || process_alive(pid)) continue;
      if (is_our_staging(dir / name)) remove_tree(dir / name);
    }
  } catch (...) {  // a folder that cannot be listed has nothing to clean
  }
}

RunFolder::RunFolder(fs::path out) : out_(std::move(out)), target_(checked_target(out_)) {
  const fs::path parent = target_.parent_path();
  const long pid = ::getpid();
  remove_stale_staging(parent);
  struct stat target_info {};
  const bool exists = ::stat(target_.c_str(), &target_info) == 0;
  if (exists) {
    remove_stale_staging(target_);
    if (const std::optional<std::string> foreign = first_foreign_entry(target_)) {
      std::error_code ec;
      const bool listed = fs::exists(fs::symlink_status(target_ / k_manifest_name, ec));
      throw UsageError("--out " + quoted(out_) + " holds '" + *foreign + "', which no run wrote (" +
                       (listed ? std::string("not in its ") + k_manifest_name
                               : std::string("no ") + k_manifest_name + ": an old version's run?") +
                       "); not replaced, choose a new or empty folder");
    }
  }
  staging_ = parent / staging_name(target_.filename().string(), pid);
  if (!exists) {
    created_parents_ = create_parents(staging_, out_);
    if (const int reason = make_staging(staging_)) {
      for (const fs::path& created : created_parents_) ::rmdir(created.c_str());
      throw IoError("cannot create output folder " + quoted(out_) + ": " + reason_of(reason));
    }
    struct stat info {};
    ::stat(staging_.c_str(), &info);
    mode_ = (0777 & ~current_umask()) | (info.st_mode & S_ISGID);  // a setgid parent's bit
    swap_ = Swap::rename;
    return;
  }
  // An existing --out: exchanged whole when the new folder can have its owner, group and mode;
  // otherwise (another user's shared folder, a parent this user cannot write) written into.
  mode_ = target_info.st_mode & 07777;
  swap_ = Swap::in_place;
  if (make_staging(staging_) == 0) {
    struct stat info {};
    if (::stat(staging_.c_str(), &info) == 0 && info.st_uid == target_info.st_uid &&
        info.st_gid == target_info.st_gid)
      swap_ = Swap::exchange;
    else
      remove_tree(staging_);
  }
  if (swap_ == Swap::in_place) {
    staging_ = target_ / staging_name(k_inside_name, pid);
    if (const int reason = make_staging(staging_))
      throw IoError("cannot write into output folder " + quoted(out_) + ": " + reason_of(reason));
  }
}

RunFolder::~RunFolder() { discard(); }

void RunFolder::discard() noexcept {
  if (committed_) return;
  remove_tree(staging_);
  for (const fs::path& parent : created_parents_) ::rmdir(parent.c_str());  // only if empty
  created_parents_.clear();
}

// Moves the previous run's entries in --out aside (into a folder inside it), renames the new
// ones in from `from`, the manifest last, then removes what was set aside; a failure moves
// everything back. Used where --out itself must stay (its owner and mode) or cannot be
// exchanged (overlayfs). Between the first and the last rename only SIGKILL can stop it.
void RunFolder::commit_in_place(const fs::path& from) {
  const std::string aside_name = staging_name(k_inside_name, ::getpid()) + k_previous_suffix;
  const fs::path aside = target_ / aside_name;
  const std::set<std::string> skip{k_manifest_name, from.filename().string(), aside_name};
  const std::vector<std::string> old_names = names_in(target_, skip);
  const std::vector<std::string> new_names = names_in(from, {k_manifest_name});
  if (const int reason = make_staging(aside))
    throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(reason));
  std::vector<std::string> set_aside, moved_in;
  const auto undo = [&] {
    for (const std::string& name : moved_in) ::rename((target_ / name).c_str(), (from / name).c_str());
    for (const std::string& name : set_aside) ::rename((aside / name).c_str(), (target_ / name).c_str());
    remove_tree(aside);
  };
  const auto fail = [&](int reason) {
    undo();
    throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(reason));
  };
  for (const std::string& name : old_names) {
    if (::rename((target_ / name).c_str(), (aside / name).c_str()) == 0) {
      set_aside.push_back(name);
    } else if (errno == EXDEV) {
      remove_tree(target_ / name);  // a folder overlayfs cannot move: the old run's, listed
    } else {
      fail(errno);
    }
  }
  for (const std::string& name : new_names) {
    if (::rename((from / name).c_str(), (target_ / name).c_str()) != 0) fail(errno);
    moved_in.push_back(name);
  }
  if (::rename((from / k_manifest_name).c_str(), (target_ / k_manifest_name).c_str()) != 0)
    fail(errno);
  remove_tree(aside);
  remove_tree(from);
}

void RunFolder::commit() {
  without_interruption([&] {
    write_manifest(staging_);
    struct stat info {};
    const bool exists = ::stat(target_.c_str(), &info) == 0;
    if (exists) {
      // Something added to --out during the run would be lost with the previous run.
      const std::set<std::string> skip{staging_.filename().string()};
      if (const std::optional<std::string> foreign = first_foreign_entry_except(target_, skip))
        throw IoError("cannot replace output folder " + quoted(out_) + ": '" + *foreign +
                      "' appeared in it during the run and no run wrote it; nothing replaced");
    }
    if (swap_ == Swap::in_place) {
      commit_in_place(staging_);
    } else if (!exists) {
      ::chmod(staging_.c_str(), mode_);
      if (::rename(staging_.c_str(), target_.c_str()) != 0)
        throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(errno));
    } else {
      ::chmod(staging_.c_str(), mode_);
      if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
        remove_tree(staging_);  // the staging name now holds the previous run
      } else if (errno == EXDEV || errno == EINVAL || errno == ENOSYS) {
        commit_in_place(staging_);  // overlayfs, or a file system that cannot exchange
      } else {
        throw IoError("cannot write output folder " + quoted(out_) + ": " + reason_of(errno));
      }
    }
    committed_ = true;
  });
}

std::string RunFolder::with_out_name(std::string text) const {
  const std::string from = staging_.string(), to = out_.string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace mcrt
