#pragma once
/// Command-line glue shared by every chapter: the common flags, validated image and scene
/// flags, and one entry point that turns every failure into the right exit code:
/// 0 success (and --help), 2 bad usage (one line naming the flag), 1 input/output failure.
///
/// CLI11 stays behind this header: a file that includes <CLI/CLI.hpp> compiles about 7 s of
/// CLI11's own code (its formatter, validators and config parser), so chapter programs see
/// CLI::App and CLI::Option only as names and add their flags through the functions below.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/usage_error.hpp"
#include "render/scene.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace mcrt {

/// A chapter's identity, written once: its executable's name, its output folder
/// (out/<name>) and the "chapter" entry of summary.json.
struct Chapter {
  std::string name;         ///< e.g. "ch02_disk_area"
  std::string description;  ///< the first paragraph of --help
};

/// --out, --seed, --threads, --quiet.
struct CommonOptions {
  std::filesystem::path out;   ///< output folder, default out/<chapter>; messages name it
  /// Where the run writes its files: a staging folder beside `out`, set by ChapterApp::run and
  /// swapped in as `out` when the run succeeds (app/run_folder.hpp).
  std::filesystem::path dir;
  std::uint64_t seed = 1;      ///< the same seed gives byte-identical outputs
  int threads = 1;             ///< default: all cores
  bool quiet = false;          ///< no progress bar, no table
};

/// --width, --height.
struct ImageOptions {
  int width = 320;
  int height = 240;
};

/// The largest image any chapter renders: 8192 x 4096 pixels.
inline constexpr long long k_max_pixels = 8192LL * 4096LL;
inline constexpr int k_max_image_side = 16384;
inline constexpr int k_max_threads = 256;

void add_common_options(CLI::App& app, CommonOptions& options, const Chapter& chapter);
/// --scene (one of `names`), --albedo and --emission.
void add_scene_options(CLI::App& app, SceneOptions& options,
                       const std::vector<std::string>& names = diffuse_scene_names());
void add_image_options(CLI::App& app, ImageOptions& options);

/// A numeric flag read as written (app/numbers.hpp): a whole number in decimal digits from
/// `lowest` (>= 0) to `highest`, or for a double a finite decimal number from `lowest` to
/// `highest`. Anything else is a usage error, one line naming the flag and the range. --help
/// shows the type (INT, UINT, FLOAT) and the default; flags_json records the value as given.
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, int& value,
                               const std::string& description, int lowest, int highest);
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, std::uint64_t& value,
                               const std::string& description, std::uint64_t lowest,
                               std::uint64_t highest);
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, double& value,
                               const std::string& description, double lowest, double highest);

/// A list flag such as --dims 1,2,4: comma-separated whole numbers in [lowest, highest],
/// written in decimal. The list is sorted and duplicates are dropped; an empty list or item,
/// a number out of range or anything else is a usage error naming the flag.
void add_list_option(CLI::App& app, const std::string& flag, std::vector<int>& values,
                     const std::string& description, int lowest, int highest);

/// The same for a list of real numbers in [lowest, highest], such as --q 0.5,0.7: decimal
/// numbers (an exponent is allowed), finite, sorted, duplicates dropped.
void add_list_option(CLI::App& app, const std::string& flag, std::vector<double>& values,
                     const std::string& description, double lowest, double highest);

/// A flag whose value is one of `choices` (`fallback` when not given): `set` receives it
/// after parsing. Anything else is a usage error listing the choices.
void add_choice_option(CLI::App& app, const std::string& flag,
                       const std::vector<std::string>& choices, const std::string& fallback,
                       const std::function<void(const std::string&)>& set,
                       const std::string& description);

/// A folder or file flag such as --reference-dir.
void add_path_option(CLI::App& app, const std::string& flag, std::filesystem::path& value,
                     const std::string& description);

/// What --help shows as the default of `option`, where the value itself would mislead (a
/// depth of 0 that means "no cut": "none").
void show_default_as(CLI::Option* option, const std::string& text);

/// The parsers behind add_list_option: throw CLI::ValidationError naming `flag`.
std::vector<int> parse_int_list(const std::string& text, const std::string& flag, int lowest,
                                int highest);
std::vector<double> parse_real_list(const std::string& text, const std::string& flag,
                                    double lowest, double highest);

/// Throws UsageError if width x height exceeds k_max_pixels.
void check_image_size(const ImageOptions& options);

/// Every option of `app` with the value it had in this run (given or default), for
/// summary.json: all but those that cannot change a result (--out, --threads, --quiet), so
/// summary.json is the same whatever --threads.
nlohmann::ordered_json flags_json(const CLI::App& app);

/// The flags flags_json leaves out, for timings.json.
nlohmann::ordered_json run_flags_json(const CLI::App& app);

/// Parses argv into `app`, then runs `body`; maps errors to exit codes and one-line messages.
/// Output that cannot be written to stdout (a closed pipe, a full disk, /dev/full) is an
/// input/output failure: exit code 1, even if `body` succeeded.
int run_chapter(CLI::App& app, int argc, char** argv, const std::function<int()>& body);

/// A chapter program's command line: CLI11's App named and described by the chapter, with
/// --out, --seed, --threads and --quiet already added. It converts to the CLI::App it holds,
/// so every add_*_option above takes it.
///
///   Options o;
///   ChapterApp app(k_chapter, o.common);
///   add_render_options(app, o.scene, o.image);
///   return app.run(argc, argv, [&] { run(app, o); });
class ChapterApp {
 public:
  ChapterApp(const Chapter& chapter, CommonOptions& common);
  ~ChapterApp();
  ChapterApp(const ChapterApp&) = delete;
  ChapterApp& operator=(const ChapterApp&) = delete;

  operator CLI::App&() { return *app_; }
  operator const CLI::App&() const { return *app_; }

  /// run_chapter on this app, with exit code 0 when `body` returns. Before any thread
  /// starts, SIGINT, SIGTERM and the other handled signals are set to end the run cleanly, and
  /// SIGPIPE to fail a write rather than end the run (app/interrupt.hpp). An empty value
  /// (`--out=`) or one that is not UTF-8 is refused before parsing. After the
  /// flags are parsed, --out is checked and a staging folder made (app/run_folder.hpp):
  /// `body` writes into common.dir, and only when it returns is that folder swapped in as
  /// --out. Messages about files name them under --out, never under the staging folder.
  /// With --print-flags, `body` is not run: the flags summary.json would record (flags_json)
  /// are printed as one line of JSON instead, and nothing is written (scripts/make-figures
  /// records them, and the figure-drift test compares them with what the chapter says now).
  int run(int argc, char** argv, const std::function<void()>& body);

 private:
  std::unique_ptr<CLI::App> app_;
  CommonOptions& common_;
  bool print_flags_ = false;
};

/// --scene, --albedo, --emission, --width and --height: what every renderer takes. --scene
/// offers `scenes`: the diffuse ones unless the chapter's estimators see a glossy lobe
/// (chapters 05-07 pass scene_names()).
void add_render_options(CLI::App& app, SceneOptions& scene, ImageOptions& image,
                        const std::vector<std::string>& scenes = diffuse_scene_names());

}  // namespace mcrt
