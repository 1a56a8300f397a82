#include "io/run_folder.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/cli.hpp"
#include "io/interrupt.hpp"
#include "io/output.hpp"

namespace mcrt {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// `inner` is `outer` or lies inside it (both absolute and normal).
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

// The folder a run into `out` replaces, links followed; UsageError if it may not be replaced.
fs::path checked_target(const fs::path& out) {
  if (out.empty()) throw UsageError("--out: give a folder name");
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(out, ec);
  if (fs::is_symlink(link) && !fs::exists(fs::status(out, ec)))
    throw UsageError("--out " + quoted(out) +
                     " is a symbolic link to nothing (a dangling link); remove it or choose "
                     "another folder");
  fs::path target = fs::weakly_canonical(fs::absolute(out, ec), ec);
  if (ec) target = fs::absolute(out).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "out/" is "out"
  const fs::path cwd = fs::current_path(ec);
  if (target == target.root_path() || (!ec && is_within(cwd, target)))
    throw UsageError("--out " + quoted(out) +
                     " is the current folder, one above it or the root; a run replaces its "
                     "--out whole, so give a folder of its own");
  const fs::file_status status = fs::status(target, ec);
  if (!fs::exists(status)) return target;
  if (!fs::is_directory(status))
    throw UsageError("--out " + quoted(out) + " is a file, not a folder; choose another name");
  if (!fs::is_empty(target, ec) && !holds_chapter_output(target))
    throw UsageError("--out " + quoted(out) +
                     " holds files that are not a chapter's output (no summary.json naming a "
                     "chapter), so it is not replaced; choose a new or empty folder");
  return target;
}

// Creates `dir` and the parents it lacks; returns those it created, innermost first.
std::vector<fs::path> create_folders(const fs::path& dir, const fs::path& out) {
  std::vector<fs::path> missing;
  for (fs::path p = dir; !p.empty() && !fs::exists(fs::symlink_status(p)); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  std::vector<fs::path> created;
  for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
    if (::mkdir(p->c_str(), 0777) != 0 && errno != EEXIST) {
      const std::error_code reason(errno, std::generic_category());
      for (const fs::path& c : created) ::rmdir(c.c_str());
      throw IoError("cannot create output folder " + quoted(out) + ": " + reason.message());
    }
    created.insert(created.begin(), *p);
  }
  return created;
}

// Removes `dir` and everything in it; a file created meanwhile (a worker still writing) makes
// one pass fail, so it tries a few times.
void remove_tree(const fs::path& dir) noexcept {
  for (int attempt = 0; attempt < 5; ++attempt) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (!ec) return;
  }
}

}  // namespace

bool holds_chapter_output(const fs::path& dir) {
  std::ifstream file(dir / "summary.json");
  if (!file) return false;
  const nlohmann::json summary = nlohmann::json::parse(file, nullptr, false);
  if (!summary.is_object() || !summary.contains("chapter") || !summary["chapter"].is_string())
    return false;
  const std::string chapter = summary["chapter"];
  return chapter.size() > 5 && chapter.compare(0, 2, "ch") == 0 &&
         std::isdigit(static_cast<unsigned char>(chapter[2])) &&
         std::isdigit(static_cast<unsigned char>(chapter[3])) && chapter[4] == '_';
}

RunFolder::RunFolder(fs::path out) : out_(std::move(out)), target_(checked_target(out_)) {
  staging_ = target_.parent_path() /
             fmt::format(".{}.staging-{}", target_.filename().string(), ::getpid());
  remove_tree(staging_);  // a folder of an earlier process that had this id
  created_parents_ = create_folders(staging_, out_);
  if (created_parents_.empty() || created_parents_.front() != staging_)
    throw IoError("cannot create output folder " + quoted(out_) + ": a staging folder is in the way");
  created_parents_.erase(created_parents_.begin());
}

RunFolder::~RunFolder() { discard(); }

void RunFolder::discard() noexcept {
  if (committed_) return;
  remove_tree(staging_);
  for (const fs::path& parent : created_parents_) ::rmdir(parent.c_str());  // only if empty
  created_parents_.clear();
}

namespace {

// Puts `staging` in place of `target`: an atomic exchange, or where the file system cannot
// exchange, two renames (between them --out is briefly absent). Returns errno or 0.
int swap_in(const fs::path& staging, const fs::path& target, bool replacing) {
  if (!replacing) return ::rename(staging.c_str(), target.c_str()) == 0 ? 0 : errno;
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0)
    return 0;
  if (errno != EINVAL && errno != ENOSYS) return errno;
  const fs::path previous = staging.string() + "-previous";
  if (::rename(target.c_str(), previous.c_str()) != 0) return errno;
  if (::rename(staging.c_str(), target.c_str()) != 0) {
    const int reason = errno;
    ::rename(previous.c_str(), target.c_str());
    return reason;
  }
  return ::rename(previous.c_str(), staging.c_str()) == 0 ? 0 : errno;
}

}  // namespace

void RunFolder::commit() {
  without_interruption([&] {
    std::error_code ec;
    const bool replacing = fs::exists(fs::symlink_status(target_, ec));
    if (const int reason = swap_in(staging_, target_, replacing))
      throw IoError("cannot write output folder " + quoted(out_) + ": " +
                    std::error_code(reason, std::generic_category()).message());
    committed_ = true;
    if (replacing) remove_tree(staging_);  // the staging name now holds the previous run
  });
}

std::string RunFolder::with_out_name(std::string text) const {
  const std::string from = staging_.string(), to = out_.string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace mcrt
