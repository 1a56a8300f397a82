#pragma once
/// A chapter's output folder, always whole: a run writes every file into a staging folder
/// beside --out, and only a finished run is swapped in. --out therefore holds one complete run
/// or the previous one, never a mix, and a folder that is not a chapter's output is never
/// replaced.

#include <filesystem>
#include <string>
#include <vector>

namespace mcrt {

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
  /// Accepts `out` if it does not exist, is an empty folder, or holds a previous run (a
  /// summary.json naming a chapter); follows a symbolic link to a folder. Throws UsageError
  /// (exit 2) naming --out otherwise (a file, a dangling link, a foreign folder, the current
  /// folder or one above it), and IoError (exit 1) if the staging folder cannot be created.
  explicit RunFolder(std::filesystem::path out);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// --out as given, for messages.
  const std::filesystem::path& out() const { return out_; }
  /// Where this run writes: `.<name>.staging-<pid>` beside --out.
  const std::filesystem::path& staging() const { return staging_; }
  /// Whether commit() has swapped this run in.
  bool committed() const { return committed_; }

  /// Swaps the staging folder in as --out (renameat2 RENAME_EXCHANGE when --out exists, then
  /// the previous run is removed; rename() when it does not). Throws IoError on failure, and
  /// --out then still holds the previous run.
  void commit();

  /// `text` with the staging folder's name replaced by --out's, so that messages name the
  /// folder the user asked for.
  std::string with_out_name(std::string text) const;

  /// Removes the staging folder and the parents it created, unless committed. Safe to call
  /// more than once; called by the destructor and on SIGINT or SIGTERM.
  void discard() noexcept;

 private:
  std::filesystem::path out_;      // as given
  std::filesystem::path target_;   // the folder that is replaced: --out, links followed
  std::filesystem::path staging_;
  std::vector<std::filesystem::path> created_parents_;  // innermost first
  bool committed_ = false;
};

/// Whether `dir` holds a previous run of a chapter: a summary.json whose "chapter" entry
/// names one (chNN_...).
bool holds_chapter_output(const std::filesystem::path& dir);

}  // namespace mcrt
