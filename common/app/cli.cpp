#include "app/cli.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/interrupt.hpp"
#include "app/numbers.hpp"
#include "app/run_folder.hpp"
#include "core/parallel.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"

namespace mcrt {

void add_common_options(CLI::App& app, CommonOptions& options, const Chapter& chapter) {
  app.option_defaults()->always_capture_default();
  options.out = std::filesystem::path("out") / chapter.name;
  options.threads = hardware_threads();
  app.add_option("--out", options.out, "Output folder");
  add_number_option(app, "--seed", options.seed, "Random seed (a non-negative integer)", 0,
                    UINT64_MAX);
  add_number_option(app, "--threads", options.threads, "Worker threads (default: all cores)", 1,
                    k_max_threads);
  app.add_flag("--quiet", options.quiet, "No progress bar and no table on stdout");
}

void add_render_options(CLI::App& app, SceneOptions& scene, ImageOptions& image,
                        const std::vector<std::string>& scenes) {
  app.add_option("--scene", scene.scene, "Scene to render")->check(CLI::IsMember(scenes));
  add_number_option(app, "--albedo", scene.params.furnace_albedo,
                    "Furnace scene: albedo everywhere", 0.0, 1.0);
  add_number_option(app, "--emission", scene.params.furnace_emission,
                    "Furnace scene: emitted radiance everywhere", 0.0, 1e6);
  add_number_option(app, "--width", image.width, "Image width in pixels", 1, k_max_image_side);
  add_number_option(app, "--height", image.height, "Image height in pixels", 1, k_max_image_side);
}

namespace {

template <class T>
std::string bound(T value) {
  if constexpr (std::is_floating_point_v<T>) return plain_number(value);
  return std::to_string(value);
}

// One number of a flag, read by app/numbers (an item of a list says so in its refusal).
template <class T>
T parse_number(std::string_view text, const std::string& flag, T lowest, T highest,
               bool in_list = false) {
  if constexpr (std::is_floating_point_v<T>)
    return parse_real_number(text, flag, lowest, highest,
                             in_list ? "a comma-separated list of numbers" : "a number");
  return static_cast<T>(
      parse_whole_number(text, flag, static_cast<std::uint64_t>(std::max(lowest, T{})),
                         static_cast<std::uint64_t>(std::max(highest, T{})),
                         in_list ? "a comma-separated list of whole numbers" : "a whole number"));
}

}  // namespace

// --help shows what CLI11 shows for a range check on a T: "--width INT:INT in [1 - 16384]=640".
template <class T>
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, T& value,
                               const std::string& description, std::type_identity_t<T> lowest,
                               std::type_identity_t<T> highest) {
  if (std::is_same_v<T, int> && (lowest < T{} || highest < lowest))
    throw std::invalid_argument("add_number_option " + flag + ": needs 0 <= lowest <= highest");
  const std::string type = CLI::detail::type_name<T>();
  const auto read = [&value, flag, lowest, highest](const std::string& text) {
    value = parse_number<T>(text, flag, lowest, highest);
  };
  return app.add_option_function<std::string>(flag, read, description)
      ->type_name(type)
      ->check(CLI::Validator(type + " in [" + bound(lowest) + " - " + bound(highest) + "]"))
      ->default_str(CLI::detail::to_string(value));
}
template CLI::Option* add_number_option<int>(CLI::App&, const std::string&, int&,
                                             const std::string&, int, int);
template CLI::Option* add_number_option<std::uint64_t>(CLI::App&, const std::string&,
                                                       std::uint64_t&, const std::string&,
                                                       std::uint64_t, std::uint64_t);
template CLI::Option* add_number_option<double>(CLI::App&, const std::string&, double&,
                                                const std::string&, double, double);

template <class T>
std::vector<T> parse_list(const std::string& text, const std::string& flag, T lowest, T highest) {
  std::vector<T> values;
  for (std::size_t start = 0, end = 0; end != std::string::npos; start = end + 1) {
    end = text.find(',', start);
    values.push_back(parse_number<T>(std::string_view(text).substr(start, end - start), flag,
                                     lowest, highest, true));
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}
template std::vector<int> parse_list<int>(const std::string&, const std::string&, int, int);
template std::vector<double> parse_list<double>(const std::string&, const std::string&, double,
                                                double);

template <class T>
void add_list_option(CLI::App& app, const std::string& flag, std::vector<T>& values,
                     const std::string& description, std::type_identity_t<T> lowest,
                     std::type_identity_t<T> highest) {
  const auto read = [&values, flag, lowest, highest](const std::string& text) {
    values = parse_list<T>(text, flag, lowest, highest);
  };
  app.add_option_function<std::string>(flag, read, description)
      ->default_str(fmt::format("{}", fmt::join(values, ",")));
}
template void add_list_option<int>(CLI::App&, const std::string&, std::vector<int>&,
                                   const std::string&, int, int);
template void add_list_option<double>(CLI::App&, const std::string&, std::vector<double>&,
                                      const std::string&, double, double);

void add_choice_option(CLI::App& app, const std::string& flag,
                       const std::vector<std::string>& choices, const std::string& fallback,
                       const std::function<void(const std::string&)>& set,
                       const std::string& description) {
  app.add_option_function<std::string>(flag, set, description)
      ->check(CLI::IsMember(choices))
      ->default_str(fallback);
}

void add_path_option(CLI::App& app, const std::string& flag, std::filesystem::path& value,
                     const std::string& description) {
  app.add_option(flag, value, description);
}

void show_default_as(CLI::Option* option, const std::string& text) { option->default_str(text); }

void check_image_size(const ImageOptions& options) {
  const long long pixels = static_cast<long long>(options.width) * options.height;
  if (pixels > k_max_pixels)
    throw UsageError(
        fmt::format("--width x --height: {} x {} = {} pixels is above the limit of {} "
                    "(8192 x 4096)",
                    options.width, options.height, pixels, k_max_pixels));
}

namespace {

// The flags that change nothing a run computes (--reference-dir: where a reference is kept,
// which is used only if it is the one the run's settings ask for).
bool is_run_flag(const std::string& name) {
  return name == "out" || name == "threads" || name == "quiet" || name == "reference-dir";
}

// Every option with its value in this run (given or default), run flags or the others.
nlohmann::ordered_json option_values(const CLI::App& app, bool run_flags) {
  nlohmann::ordered_json flags = nlohmann::ordered_json::object();
  for (const CLI::Option* option : app.get_options()) {
    const std::vector<std::string>& names = option->get_lnames();
    if (names.empty() || names.front() == "help" || names.front() == "print-flags" ||
        is_run_flag(names.front()) != run_flags)
      continue;
    flags[names.front()] = option->count() == 0
                               ? option->get_default_str()
                               : fmt::format("{}", fmt::join(option->results(), ","));
  }
  return flags;
}

}  // namespace

nlohmann::ordered_json flags_json(const CLI::App& app) { return option_values(app, false); }

nlohmann::ordered_json run_flags_json(const CLI::App& app) { return option_values(app, true); }

namespace {

// An exception in the project's words: a filesystem_error as "cannot access 'P': reason", a
// failed write to stdout (fmt::print throws system_error; the error flag tells it apart).
std::string message_of(const std::exception& e) {
  if (const auto* file = dynamic_cast<const std::filesystem::filesystem_error*>(&e))
    return (file->path1().empty() ? std::string("a file operation failed")
                                  : "cannot access '" + file->path1().string() + "'") +
           ": " + file->code().message();
  if (const auto* system = dynamic_cast<const std::system_error*>(&e);
      system && std::ferror(stdout))
    return "cannot write to stdout: " + system->code().message();
  return e.what();
}

// Flushes stdout. If anything written to it was lost (a full disk, /dev/full, a closed pipe),
// says so in one line and turns a successful exit code into 1.
int checked_stdout(const std::string& program, int exit_code) {
  errno = 0;  // one flush sends both std::cout and stdout (synced); errno then holds the reason
  const bool flushed = std::fflush(stdout) == 0;
  const int reason = errno;
  std::cout.flush();
  if ((flushed && !std::ferror(stdout) && std::cout.good()) || exit_code != 0) return exit_code;
  std::cerr << program << ": error: cannot write to stdout: "
            << (flushed ? "a write failed" : std::strerror(reason)) << '\n';
  return 1;
}

// What is wrong with the values on the command line before CLI11 reads them: an empty value
// (`--flag=`, which CLI11 would fill with the next argument, or `--flag ""`), or one that is not
// UTF-8 (every value ends up in summary.json: what the JSON library writes is the test).
std::optional<std::string> refused_value(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument == "--") break;
    if (argument.size() < 3 || argument.substr(0, 2) != "--") continue;
    std::string flag;
    std::string_view value;
    if (const std::size_t equals = argument.find('='); equals != std::string_view::npos) {
      flag = std::string(argument.substr(0, equals));
      value = argument.substr(equals + 1);
    } else {
      const CLI::Option* option = app.get_option_no_throw(std::string(argument));
      if (!option || option->get_expected_min() == 0 || i + 1 >= argc) continue;
      flag = std::string(argument);
      value = argv[++i];
    }
    if (value.empty()) return flag + ": the value is empty; give one, or leave the flag out";
    try {
      (void)nlohmann::json(std::string(value)).dump();
    } catch (const nlohmann::json::type_error&) {  // 316: invalid UTF-8
      return flag +
             ": the value is not valid UTF-8; give it in UTF-8 (the run's JSON files record it)";
    }
  }
  return std::nullopt;
}

}  // namespace

// Parses argv, then runs body; every failure becomes its exit code and one line.
int run_chapter(CLI::App& app, int argc, char** argv, const std::function<int()>& body) {
  const std::string program = app.get_name().empty() ? "chapter" : app.get_name();
  const auto fail = [&](int code, const std::string& message) {
    std::cerr << program << ": error: " << message << (code == 2 ? " (see --help)\n" : "\n");
    return checked_stdout(program, code);
  };
  if (const std::optional<std::string> refused = refused_value(app, argc, argv))
    return fail(2, *refused);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return checked_stdout(program, app.exit(e));
  } catch (const CLI::ParseError& e) {
    return fail(2, e.what());
  }
  try {
    return checked_stdout(program, body());
  } catch (const std::exception& e) {
    std::cerr << program << ": error: " << message_of(e) << '\n';
    return checked_stdout(program, dynamic_cast<const UsageError*>(&e) ? 2 : 1);
  }
}

ChapterApp::ChapterApp(const Chapter& chapter, CommonOptions& common)
    : app_(std::make_unique<CLI::App>(chapter.description, chapter.name)), common_(common) {
  add_common_options(*app_, common, chapter);
  app_->add_flag("--print-flags", print_flags_,
                 "Print every flag a run records in summary.json (defaults included) as JSON, "
                 "and exit without running");
}

ChapterApp::~ChapterApp() = default;

int ChapterApp::run(int argc, char** argv, const std::function<void()>& body) {
  watch_interrupts(app_->get_name());
  return run_chapter(*app_, argc, argv, [&] {
    if (print_flags_) {
      std::cout << flags_json(*app_).dump() << '\n';
      return 0;
    }
    try {  // read strictly, before any work: a typo is refused, never ignored
      if (const char* seconds = std::getenv("MCRT_GNUPLOT_TIMEOUT"))
        set_gnuplot_time_limit(
            static_cast<int>(parse_whole_number(seconds, "MCRT_GNUPLOT_TIMEOUT", 1, 3600,
                                                "a whole number of seconds")));
    } catch (const CLI::ValidationError& e) {
      throw UsageError(e.what());
    }
    std::optional<RunFolder> folder;
    const auto forget = [&] {  // unregistered and removed with no interruption in between
      without_interruption([&] {
        discard_on_interrupt(nullptr);
        folder.reset();
      });
    };
    without_interruption([&] {
      folder.emplace(common_.out);
      discard_on_interrupt(&*folder);
    });
    common_.dir = folder->staging();
    try {
      body();
      folder->commit();
    } catch (const std::exception& e) {  // in the project's words, naming --out
      const std::string message = folder->with_out_name(message_of(e));
      forget();
      if (dynamic_cast<const UsageError*>(&e)) throw UsageError(message);
      throw IoError(message);
    }
    forget();
    return 0;
  });
}

}  // namespace mcrt
