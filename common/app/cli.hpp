#pragma once
/// Every chapter's command line: the common flags, validated numbers and lists, and one entry
/// point mapping every failure to its exit code: 0 success (and --help), 2 bad usage (one line
/// naming the flag), 1 input/output failure. CLI11 stays behind this header (including it costs
/// about 7 s of compile time per file): chapters add their flags through the functions below.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
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
  std::filesystem::path out;  ///< output folder, default out/<chapter>; messages name it
  std::filesystem::path dir;  ///< where the run writes: its staging folder (app/run_folder.hpp)
  std::uint64_t seed = 1;     ///< the same seed gives byte-identical outputs
  int threads = 1;            ///< default: all cores
  bool quiet = false;         ///< no progress bar, no table
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

/// A numeric flag (T: int, std::uint64_t or double) read as written (app/numbers.hpp), from
/// `lowest` (>= 0) to `highest`; --help shows its type, range and default; flags_json records
/// the value as given.
template <class T>
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, T& value,
                               const std::string& description, std::type_identity_t<T> lowest,
                               std::type_identity_t<T> highest);

/// A list flag such as --dims 1,2,4 or --q 0.5,0.7 (T: int or double): comma-separated numbers
/// as above, sorted, duplicates dropped; an empty item is refused. parse_list reads it.
template <class T>
void add_list_option(CLI::App& app, const std::string& flag, std::vector<T>& values,
                     const std::string& description, std::type_identity_t<T> lowest,
                     std::type_identity_t<T> highest);
template <class T>
std::vector<T> parse_list(const std::string& text, const std::string& flag, T lowest, T highest);

/// A flag whose value is one of `choices` (`fallback` when not given), passed to `set`.
void add_choice_option(CLI::App& app, const std::string& flag,
                       const std::vector<std::string>& choices, const std::string& fallback,
                       const std::function<void(const std::string&)>& set,
                       const std::string& description);

/// A folder or file flag such as --reference-dir.
void add_path_option(CLI::App& app, const std::string& flag, std::filesystem::path& value,
                     const std::string& description);

/// What --help shows as the default of `option` where the value would mislead ("none").
void show_default_as(CLI::Option* option, const std::string& text);

/// Throws UsageError if width x height exceeds k_max_pixels.
void check_image_size(const ImageOptions& options);

/// Every flag's value in this run (given or default) for summary.json, but those that cannot
/// change a result (--out, --threads, --quiet, --reference-dir), which run_flags_json gives.
nlohmann::ordered_json flags_json(const CLI::App& app);
nlohmann::ordered_json run_flags_json(const CLI::App& app);

/// Parses argv into `app`, then runs `body`; maps errors to exit codes and one-line messages.
/// Output lost on stdout (a closed pipe, a full disk) is exit 1, even if `body` succeeded.
int run_chapter(CLI::App& app, int argc, char** argv, const std::function<int()>& body);

/// A chapter's CLI::App with the common flags added; every add_*_option above takes it.
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

  /// run_chapter with signals watched (app/interrupt.hpp); an empty or non-UTF-8 value is
  /// refused before parsing. `body` writes into common.dir, a staging folder swapped in as
  /// --out when it returns (app/run_folder.hpp); messages name --out. --print-flags prints
  /// flags_json as one line and runs nothing (scripts/make-figures records it).
  int run(int argc, char** argv, const std::function<void()>& body);

 private:
  std::unique_ptr<CLI::App> app_;
  CommonOptions& common_;
  bool print_flags_ = false;
};

/// --scene (one of `scenes`), --albedo, --emission, --width and --height.
void add_render_options(CLI::App& app, SceneOptions& scene, ImageOptions& image,
                        const std::vector<std::string>& scenes = diffuse_scene_names());

}  // namespace mcrt
