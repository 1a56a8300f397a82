#pragma once
/// A chapter's output folder, always whole: a run writes into a staging folder beside --out
/// and only a finished run is swapped in, so --out holds one complete run or the previous one.
/// Each run lists what it wrote in a manifest, and a run replaces only a folder whose manifest
/// lists everything in it.
///
///   RunFolder folder(out);   // refuses a foreign --out, creates the staging folder
///   write_png(folder.staging() / "image.png", image);
///   folder.commit();         // --out now holds this run
///
/// Destroyed without commit(), it removes its staging folder and the parents it created.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace mcrt {

/// Every file and folder a run wrote, one relative path per line (folders end in '/').
inline constexpr const char* k_manifest_name = ".mcrt-manifest";

class RunFolder {
 public:
  /// Throws UsageError (exit 2) naming --out for: a file, a dangling link, a folder holding an
  /// entry no run wrote (named), $HOME, the root, the current folder or one above it, and a
  /// folder this user cannot own (git's safe.directory rule): --out or the folder it is made
  /// in owned by another user (root may own the latter) or writable by one (a sticky parent
  /// such as /tmp excepted). Removes abandoned staging folders first. IoError (exit 1) if the
  /// staging folder cannot be made.
  explicit RunFolder(std::filesystem::path out);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  const std::filesystem::path& out() const { return out_; }  ///< as given, for messages
  /// `.<name>.staging-<16 hex digits>` beside --out (inside an empty mount point), mode 0700,
  /// marked live by the lock this run holds on its manifest.
  const std::filesystem::path& staging() const { return staging_; }
  bool committed() const { return committed_; }

  /// Writes the manifest and swaps the staging folder in (rename, or an atomic exchange with
  /// the previous run, whose mode and group it takes; where the file system cannot exchange,
  /// the previous run is set aside and put back on failure). Throws IoError: --out then
  /// still holds the previous run, or the message says where both are.
  void commit();

  /// `text` with the staging folder's path replaced by --out's.
  std::string with_out_name(std::string text) const;

  /// Removes the staging folder and the parents it created, unless committed. Idempotent.
  void discard() noexcept;

 private:
  void commit_into_mount_point();

  std::filesystem::path out_;     // as given
  std::filesystem::path target_;  // --out, links followed
  std::filesystem::path staging_;
  int lock_fd_ = -1;  // the staging manifest, locked while this run lives
  std::vector<std::filesystem::path> created_parents_;  // innermost first
  mode_t mode_ = 0755;                                  // the mode --out gets
  bool committed_ = false;
  bool in_place_ = false;  // --out is an empty mount point: staged inside it
};

/// The first entry under `dir` (relative, folders ending in '/', sorted) that is not a
/// regular file or folder its manifest lists; nullopt when there is none. Only a regular
/// manifest is ever opened (a FIFO cannot block it).
std::optional<std::string> first_foreign_entry(const std::filesystem::path& dir);

/// `.<name>.staging-<suffix>`, `name` cut at a UTF-8 boundary to fit NAME_MAX with "-previous".
std::string staging_name(const std::string& name, const std::string& suffix);

/// Why the folder `info` describes is not one this user can own (git's safe.directory rule), or
/// "": "is owned by another user" (unless `root_ok` and root owns it), or "can be written by
/// other users" (unless `sticky_ok` and its sticky bit, as /tmp's, keeps them off our files).
std::string not_our_folder(const struct stat& info, bool sticky_ok, bool root_ok);

/// `path` absolute, links followed as far as they exist, without a trailing '/'.
std::filesystem::path resolved(const std::filesystem::path& path);

/// Whether `inner` is `outer` or lies inside it (both as resolved() gives them).
bool is_within(const std::filesystem::path& inner, const std::filesystem::path& outer);

}  // namespace mcrt
