#pragma once
/// A chapter's output folder, always whole: a run writes every file into a staging folder and
/// only a finished run is swapped in. --out therefore holds one complete run or the previous
/// one, never a mix, and nothing a run did not write is ever replaced: each run lists what it
/// wrote in a manifest (k_manifest_name), and a later run replaces a folder only if its
/// manifest lists everything in it.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace mcrt {

/// The manifest a run leaves in its folder: every file and folder it wrote, one relative path
/// per line (folders end in '/'), itself included.
inline constexpr const char* k_manifest_name = ".mcrt-manifest";

/// The staging folder of one run and the --out it is swapped into.
///
///   RunFolder folder(out);            // refuses a foreign --out, creates the staging folder
///   write_png(folder.staging() / "image.png", image);
///   folder.commit();                   // --out now holds this run; the previous one is gone
///
/// A RunFolder destroyed without commit() removes its staging folder (and the parents of
/// --out it created), so a failed run leaves nothing behind.
class RunFolder {
 public:
  /// Accepts `out` if it does not exist, is an empty folder, or holds only what its manifest
  /// lists (a previous run); follows a symbolic link to a folder. Throws UsageError (exit 2)
  /// naming --out otherwise: a file, a dangling link, a folder with an entry no run wrote (the
  /// first one is named), $HOME, the root, the current folder or one above it, and a folder
  /// this run cannot own (git's safe.directory rule): --out or the folder it is made in owned
  /// by another user (root may own the latter) or writable by one (the sticky bit of a parent
  /// such as /tmp excepted). Removes the abandoned staging folders beside --out first. Throws
  /// IoError (exit 1) if the staging folder cannot be created.
  explicit RunFolder(std::filesystem::path out);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// --out as given, for messages.
  const std::filesystem::path& out() const { return out_; }
  /// Where this run writes: `.<name>.staging-<16 random hex digits>` beside --out (inside an
  /// empty mount point given as --out, which cannot be swapped), mode 0700, marked live by the
  /// lock this run holds on its manifest.
  const std::filesystem::path& staging() const { return staging_; }
  /// Whether commit() has swapped this run in.
  bool committed() const { return committed_; }

  /// Writes the manifest, then swaps the staging folder in as --out: rename() when --out does
  /// not exist, an atomic exchange when it does (the new folder gets the old one's mode and
  /// group); where the file system cannot exchange, the previous run is renamed aside first
  /// and back on failure. Throws IoError on failure, and --out then still holds the previous
  /// run (or the message says where both runs are).
  void commit();

  /// `text` with the staging folder's path replaced by --out's, so that messages name the
  /// folder the user asked for.
  std::string with_out_name(std::string text) const;

  /// Removes the staging folder and the parents it created, unless committed. Safe to call
  /// more than once; called by the destructor and on an interrupting signal.
  void discard() noexcept;

 private:
  void commit_into_mount_point();

  std::filesystem::path out_;      // as given
  std::filesystem::path target_;   // the folder that is replaced: --out, links followed
  std::filesystem::path staging_;
  int lock_fd_ = -1;               // the staging manifest, locked while this run lives
  std::vector<std::filesystem::path> created_parents_;  // innermost first
  mode_t mode_ = 0755;  // the mode --out gets
  bool committed_ = false;
  bool in_place_ = false;  // --out is an empty mount point: staged inside it, moved in entry by entry
};

/// The first entry under `dir` (a relative path, folders with a trailing '/', in sorted order)
/// that is not a regular file or folder listed in dir's manifest; nullopt when every entry is
/// listed (an empty folder). Nothing but a regular manifest is ever opened, so a FIFO cannot
/// block it.
std::optional<std::string> first_foreign_entry(const std::filesystem::path& dir);

/// What dir's manifest lists, one entry per line; empty without a regular manifest.
std::vector<std::string> manifest_entries(const std::filesystem::path& dir);

/// The manifest of `dir`: everything under it, the manifest itself included.
std::string manifest_text(const std::filesystem::path& dir);

/// The staging folder's name for an --out named `name`: `.<name>.staging-<suffix>`, `name`
/// shortened (at a UTF-8 boundary) to fit NAME_MAX with "-previous" appended.
std::string staging_name(const std::string& name, const std::string& suffix);

/// Removes, in `dir`, the staging folders of runs that are gone: named as staging_name()
/// makes them with a 16-hex-digit suffix (and an optional "-previous"), folders of this user
/// holding a regular manifest of this user whose lock can be taken. A live run holds that
/// lock, whatever its PID namespace or machine; nothing else is touched.
void remove_stale_staging(const std::filesystem::path& dir) noexcept;

}  // namespace mcrt
