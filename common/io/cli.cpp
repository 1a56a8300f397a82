#include "io/cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/parallel.hpp"
#include "io/output.hpp"

namespace mcrt {

void add_common_options(CLI::App& app, CommonOptions& options, const Chapter& chapter) {
  app.option_defaults()->always_capture_default();
  options.out = std::filesystem::path("out") / chapter.name;
  options.threads = hardware_threads();
  app.add_option("--out", options.out, "Output folder");
  app.add_option("--seed", options.seed, "Random seed (a non-negative integer)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--threads", options.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, k_max_threads));
  app.add_flag("--quiet", options.quiet, "No progress bar and no table on stdout");
}

void add_scene_options(CLI::App& app, SceneOptions& options) {
  app.add_option("--scene", options.scene, "Scene to render")
      ->check(CLI::IsMember(scene_names()));
  app.add_option("--albedo", options.params.furnace_albedo, "Furnace scene: albedo everywhere")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--emission", options.params.furnace_emission,
                 "Furnace scene: emitted radiance everywhere")
      ->check(CLI::Range(0.0, 1e6));
}

void add_image_options(CLI::App& app, ImageOptions& options) {
  app.add_option("--width", options.width, "Image width in pixels")
      ->check(CLI::Range(1, k_max_image_side));
  app.add_option("--height", options.height, "Image height in pixels")
      ->check(CLI::Range(1, k_max_image_side));
}

namespace {

// The comma-separated items of a list flag; an empty list or item is a usage error.
std::vector<std::string> list_items(const std::string& text, const std::string& accepted) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    items.push_back(text.substr(start, end - start));
    if (items.back().empty()) throw CLI::ValidationError(accepted + " (an item is empty)");
    if (end == text.size()) return items;
    start = end + 1;
  }
}

template <class T>
std::vector<T> sorted_unique(std::vector<T> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::vector<int> parse_int_list(const std::string& text, const std::string& flag, int lowest,
                                int highest) {
  const std::string accepted = fmt::format(
      "{}: give a comma-separated list of whole numbers from {} to {}", flag, lowest, highest);
  std::vector<int> values;
  for (const std::string& item : list_items(text, accepted)) {
    // Decimal digits only: no sign, no spaces, no octal or hex prefixes.
    if (item.size() > 9 || !std::all_of(item.begin(), item.end(), is_digit))
      throw CLI::ValidationError(accepted + fmt::format(" ('{}' is not one)", item));
    const int value = std::stoi(item);
    if (value < lowest || value > highest)
      throw CLI::ValidationError(accepted + fmt::format(" ({} is out of range)", value));
    values.push_back(value);
  }
  return sorted_unique(std::move(values));
}

std::vector<double> parse_real_list(const std::string& text, const std::string& flag,
                                    double lowest, double highest) {
  const std::string accepted = fmt::format(
      "{}: give a comma-separated list of numbers from {} to {}", flag, lowest, highest);
  std::vector<double> values;
  for (const std::string& item : list_items(text, accepted)) {
    // Decimal notation only (digits, one point, an exponent): no hex floats, nan or inf.
    const bool decimal = std::all_of(item.begin(), item.end(), [](char c) {
      return is_digit(c) || c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+';
    });
    double value = 0.0;
    std::size_t used = 0;
    try {
      if (decimal) value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (!decimal || used != item.size() || !std::isfinite(value))
      throw CLI::ValidationError(accepted + fmt::format(" ('{}' is not one)", item));
    if (value < lowest || value > highest)
      throw CLI::ValidationError(accepted + fmt::format(" ({} is out of range)", item));
    values.push_back(value);
  }
  return sorted_unique(std::move(values));
}

void add_list_option(CLI::App& app, const std::string& flag, std::vector<int>& values,
                     const std::string& description, int lowest, int highest) {
  app.add_option_function<std::string>(
         flag,
         [&values, flag, lowest, highest](const std::string& text) {
           values = parse_int_list(text, flag, lowest, highest);
         },
         description)
      ->default_str(fmt::format("{}", fmt::join(values, ",")));
}

void add_list_option(CLI::App& app, const std::string& flag, std::vector<double>& values,
                     const std::string& description, double lowest, double highest) {
  app.add_option_function<std::string>(
         flag,
         [&values, flag, lowest, highest](const std::string& text) {
           values = parse_real_list(text, flag, lowest, highest);
         },
         description)
      ->default_str(fmt::format("{}", fmt::join(values, ",")));
}

void check_image_size(const ImageOptions& options) {
  const long long pixels = static_cast<long long>(options.width) * options.height;
  if (pixels > k_max_pixels)
    throw UsageError("--width x --height: " + std::to_string(options.width) + " x " +
                     std::to_string(options.height) + " = " + std::to_string(pixels) +
                     " pixels is above the limit of " + std::to_string(k_max_pixels) +
                     " (8192 x 4096)");
}

nlohmann::ordered_json flags_json(const CLI::App& app) {
  nlohmann::ordered_json flags = nlohmann::ordered_json::object();
  for (const CLI::Option* option : app.get_options()) {
    const std::vector<std::string>& names = option->get_lnames();
    if (names.empty() || names.front() == "help") continue;
    std::string value;
    if (option->count() > 0) {
      for (const std::string& r : option->results()) value += (value.empty() ? "" : ",") + r;
    } else {
      value = option->get_default_str();
    }
    flags[names.front()] = value;
  }
  return flags;
}

int run_chapter(CLI::App& app, int argc, char** argv, const std::function<int()>& body) {
  const std::string program = app.get_name().empty() ? "chapter" : app.get_name();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << program << ": error: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    return body();
  } catch (const UsageError& e) {
    std::cerr << program << ": error: " << e.what() << '\n';
    return 2;
  } catch (const IoError& e) {
    std::cerr << program << ": error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << program << ": error: " << e.what() << '\n';
    return 1;
  }
}

ChapterApp::ChapterApp(const Chapter& chapter, CommonOptions& common)
    : CLI::App(chapter.description, chapter.name) {
  add_common_options(*this, common, chapter);
}

int ChapterApp::run(int argc, char** argv, const std::function<int()>& body) {
  return run_chapter(*this, argc, argv, body);
}

void add_render_options(CLI::App& app, SceneOptions& scene, ImageOptions& image) {
  add_scene_options(app, scene);
  add_image_options(app, image);
}

}  // namespace mcrt
