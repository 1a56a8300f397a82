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
  /// first one is named), $HOME, the root, the current folder or one above it. Removes the
  /// staging folders of runs whose process is gone beside and inside --out first. Throws
  /// IoError (exit 1) if the staging folder cannot be created.
  explicit RunFolder(std::filesystem::path out);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// --out as given, for messages.
  const std::filesystem::path& out() const { return out_; }
  /// Where this run writes: `.<name>.staging-<pid>` beside --out, or `.mcrt.staging-<pid>`
  /// inside an existing --out that this run may not replace as a folder (owned by someone
  /// else, another group, or a parent this user cannot write).
  const std::filesystem::path& staging() const { return staging_; }
  /// Whether commit() has swapped this run in.
  bool committed() const { return committed_; }

  /// Writes the manifest, then swaps the staging folder in as --out: rename() when --out does
  /// not exist, an atomic exchange when it does (the new folder gets the old one's mode),
  /// and, inside a folder that must keep its owner and mode or where the file system cannot
  /// exchange (overlayfs: EXDEV), the previous run's entries are moved aside and the new ones
  /// renamed in, undone on failure. Throws IoError on failure, and --out then still holds the
  /// previous run.
  void commit();

  /// `text` with the staging folder's path replaced by --out's, so that messages name the
  /// folder the user asked for.
  std::string with_out_name(std::string text) const;

  /// Removes the staging folder and the parents it created, unless committed. Safe to call
  /// more than once; called by the destructor and on an interrupting signal.
  void discard() noexcept;

 private:
  enum class Swap { rename, exchange, in_place };
  void commit_in_place(const std::filesystem::path& from);

  std::filesystem::path out_;      // as given
  std::filesystem::path target_;   // the folder that is replaced: --out, links followed
  std::filesystem::path staging_;
  std::vector<std::filesystem::path> created_parents_;  // innermost first
  Swap swap_ = Swap::rename;
  mode_t mode_ = 0755;  // the mode --out gets (rename, exchange)
  bool committed_ = false;
};

/// The first entry under `dir` (a relative path, folders with a trailing '/', in sorted order)
/// that is not a regular file or folder listed in dir's manifest; nullopt when every entry is
/// listed (an empty folder). Nothing but a regular manifest is ever opened, so a FIFO cannot
/// block it.
std::optional<std::string> first_foreign_entry(const std::filesystem::path& dir);

/// What dir's manifest lists, one entry per line; empty without a regular manifest.
std::vector<std::string> manifest_entries(const std::filesystem::path& dir);

/// Writes dir's manifest: everything under `dir`, the manifest itself included.
void write_manifest(const std::filesystem::path& dir);

/// The staging folder's name for an --out named `name`, written by process `pid`:
/// `.<name>.staging-<pid>`, `name` shortened (at a UTF-8 boundary) to fit NAME_MAX.
std::string staging_name(const std::string& name, long pid);

/// Removes, in `dir`, the staging folders of runs whose process is gone: a folder named as
/// staging_name() makes them (with an optional "-previous"), of this user, whose pid is not
/// alive and which holds a manifest or nothing. Nothing else is touched.
void remove_stale_staging(const std::filesystem::path& dir) noexcept;

}  // namespace mcrt
