#include "io/plot.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string_view>
#include <system_error>

#include <fmt/format.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/interrupt.hpp"
#include "io/output.hpp"

extern char** environ;

namespace mcrt {

namespace fs = std::filesystem;

bool gnuplot_available() {
  static const bool available = [] {
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "/usr/bin:/bin");
    for (std::string folder; std::getline(folders, folder, ':');)
      if (!folder.empty() && ::access((fs::path(folder) / "gnuplot").c_str(), X_OK) == 0)
        return true;
    return false;
  }();
  return available;
}

std::string image_file_problem(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "it was not written";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) return "it is empty";
  const std::string extension = file.extension().string();
  if (extension == ".png") {
    // The 8-byte signature, then chunks; the last is IEND: length 0, "IEND", its CRC.
    static constexpr std::string_view signature("\x89PNG\r\n\x1a\n", 8);
    static constexpr std::string_view end("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    if (bytes.compare(0, signature.size(), signature) != 0) return "it is not a PNG file";
    if (bytes.size() < signature.size() + end.size() ||
        bytes.compare(bytes.size() - end.size(), end.size(), end) != 0)
      return "the PNG file is truncated (no IEND chunk at its end)";
  } else if (extension == ".svg") {
    const std::size_t last = bytes.find_last_not_of(" \t\r\n");
    if (last == std::string::npos || last < 5 || bytes.compare(last - 5, 6, "</svg>") != 0)
      return "the SVG file is truncated (it does not end with </svg>)";
  }
  return "";
}

namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// An axis's log scale, and its range when all its values are equal, from the values it draws
// (Plot::x_values, y_values).
struct AxisSettings {
  std::string scale;  // before the plot's own settings
  std::string range;  // after them: it wins over a range that would be empty
};

AxisSettings axis_settings(char axis, bool log, const std::vector<double>& values) {
  double lowest = HUGE_VAL, highest = -HUGE_VAL, lowest_positive = HUGE_VAL;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    lowest = std::min(lowest, v);
    highest = std::max(highest, v);
    if (v > 0.0) lowest_positive = std::min(lowest_positive, v);
  }
  const bool known = lowest <= highest;
  // A log axis needs a positive value; without one it is drawn linear.
  if (log && known && !std::isfinite(lowest_positive)) log = false;
  AxisSettings s;
  if (log) s.scale = fmt::format("set logscale {0}\nset format {0} '10^{{%T}}'\n", axis);
  if (!known) return s;
  const double low = log ? lowest_positive : lowest;
  if (low == highest) {  // one value: gnuplot would warn of an empty range
    const double below = log ? low / 2.0 : (low == 0.0 ? -1.0 : low - std::abs(low) / 2.0);
    const double above = log ? low * 2.0 : (low == 0.0 ? 1.0 : low + std::abs(low) / 2.0);
    s.range = fmt::format("set {}range [{:.9g}:{:.9g}]\n", axis, below, above);
  }
  return s;
}

std::string script_text(const Plot& p) {
  std::ostringstream s;
  s << "# " << p.title << "\n"
    << "# Re-plot with: gnuplot " << p.name << ".gp   (in this folder)\n"
    << "set datafile separator ','\n"
    << "set datafile columnheaders\n"  // columns are named: using "n":"rmse"
    << "set title " << quote(p.title) << " noenhanced\n"
    << "set xlabel " << quote(p.x_label) << " noenhanced\n"
    << "set ylabel " << quote(p.y_label) << " noenhanced\n"
    << "set grid\n"
    << "set key top right\n";
  const AxisSettings x = axis_settings('x', p.log_x, p.x_values);
  const AxisSettings y = axis_settings('y', p.log_y, p.y_values);
  s << x.scale << y.scale;
  s << p.settings << (p.settings.empty() || p.settings.back() == '\n' ? "" : "\n");
  s << x.range << y.range;
  s << "set terminal pngcairo size " << p.width << "," << p.height
    << " enhanced font 'DejaVu Sans,11'\n"
    << "set output " << quote(p.name + ".png") << "\n"
    << p.plot << "\n"
    << "set terminal svg size " << p.width << "," << p.height << " enhanced dynamic\n"
    << "set output " << quote(p.name + ".svg") << "\n"
    << "replot\n"
    << "set output\n";
  return s.str();
}

// Runs `gnuplot script` in `dir` (no shell: the folder's name never reaches a command line or
// a script) and returns its exit status and what it wrote on stderr. An interruption meanwhile
// stops it (io/interrupt.hpp).
std::pair<int, std::string> run_gnuplot(const fs::path& dir, const std::string& script) {
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
    throw IoError("cannot run gnuplot: " + std::error_code(errno, std::generic_category()).message());
  posix_spawn_file_actions_t actions;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  ::posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  ::posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawnattr_t attributes;
  ::posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  ::posix_spawnattr_setsigmask(&attributes, &none);  // main blocks SIGINT and SIGTERM
  ::posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  std::string program = "gnuplot", argument = script;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t child = 0;
  int spawned = 0;
  without_interruption([&] {
    spawned = ::posix_spawnp(&child, "gnuplot", &actions, &attributes, argv, environ);
    if (spawned == 0) stop_on_interrupt(child);
  });
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attributes);
  ::close(pipe_fds[1]);
  std::string messages;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    messages.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  if (spawned != 0)
    throw IoError("cannot run gnuplot: " + std::error_code(spawned, std::generic_category()).message());
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  forget_child(child);
  return {status, messages};
}

// The first line of gnuplot's messages that says something ("" if none), and whether every
// such line is only a warning.
std::pair<std::string, bool> first_message(const std::string& messages) {
  std::istringstream lines(messages);
  std::string first;
  bool only_warnings = true;
  for (std::string line; std::getline(lines, line);) {
    // gnuplot echoes the offending command and a caret above its message: skip those.
    if (line.find_first_not_of(" ^\t") == std::string::npos || line.find(": ") == std::string::npos)
      continue;
    std::string lower = line;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    only_warnings = only_warnings && lower.find("warning") != std::string::npos;
    if (first.empty()) first = line;
  }
  if (first.empty()) first = messages.substr(0, messages.find('\n'));
  return {first, only_warnings};
}

// gnuplot does not report a failed write, so an incomplete image is all we see. When the
// folder's file system has no block left, that is the reason, in the system's words.
std::string reason_for_incomplete(const fs::path& dir, const std::string& problem) {
  struct statvfs fs_info {};
  if (::statvfs(dir.c_str(), &fs_info) == 0 && fs_info.f_bavail == 0)
    return std::error_code(ENOSPC, std::generic_category()).message() + " (" + problem + ")";
  return problem;
}

}  // namespace

PlotResult write_plot(const fs::path& dir, const Plot& plot) {
  const std::string script = plot.name + ".gp";
  write_file_atomic(dir / script, script_text(plot));
  if (!gnuplot_available()) {
    static bool told = false;
    if (!told)
      std::cerr << "note: gnuplot not found, so no PNG/SVG plots were drawn; the .gp scripts "
                   "and CSV files are written. Install it with: sudo apt-get install gnuplot-nox\n";
    told = true;
    return PlotResult::no_gnuplot;
  }
  const fs::path png = dir / (plot.name + ".png"), svg = dir / (plot.name + ".svg");
  const auto [status, messages] = run_gnuplot(dir, script);
  const auto [message, only_warnings] = first_message(messages);
  std::string problem;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    problem = "gnuplot failed on " + script + ": " + message;
  else if (!messages.empty() && !only_warnings)
    problem = "gnuplot reported an error in " + script + ": " + message;
  else if (const std::string png_problem = image_file_problem(png); !png_problem.empty())
    problem = "cannot write '" + png.string() + "': " + reason_for_incomplete(dir, png_problem);
  else if (const std::string svg_problem = image_file_problem(svg); !svg_problem.empty())
    problem = "cannot write '" + svg.string() + "': " + reason_for_incomplete(dir, svg_problem);
  if (problem.empty()) {
    if (!messages.empty()) std::cerr << "note: gnuplot on " << script << ": " << message << '\n';
    return PlotResult::drawn;
  }
  std::error_code ignored;
  fs::remove(png, ignored);
  fs::remove(svg, ignored);
  throw IoError(problem);
}

}  // namespace mcrt
