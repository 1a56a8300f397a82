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

#include <atomic>
#include <chrono>
#include <optional>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/child_process.hpp"
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
  const std::string draw =
      p.multiplot ? "set multiplot\n" + p.plot + "\nunset multiplot\n" : "replot\n";
  s << "set terminal pngcairo size " << p.width << "," << p.height
    << " enhanced font 'DejaVu Sans,11'\n"
    << "set output " << quote(p.name + ".png") << "\n"
    << (p.multiplot ? draw : p.plot + "\n") << "set terminal svg size " << p.width << ","
    << p.height << " enhanced dynamic\n"
    << "set output " << quote(p.name + ".svg") << "\n"
    << draw << "set output\n";
  return s.str();
}

// gnuplot's environment: ours without the variables that change what gnuplot reads or draws
// (GNUPLOT_LIB, GNUPLOT_DRIVER_DIR, GNUTERM, ...). Its init files are skipped by -d.
std::vector<std::string> gnuplot_environment() {
  std::vector<std::string> variables;
  for (char** v = environ; *v != nullptr; ++v) {
    const std::string_view variable = *v;
    if (variable.starts_with("GNUPLOT") || variable.starts_with("GNUTERM")) continue;
    variables.emplace_back(variable);
  }
  return variables;
}

// How long one gnuplot may run: a plot of a few thousand points draws in well under a second,
// and 30 s leaves room for a machine shared by many (set_gnuplot_time_limit sets another).
std::atomic<int> g_gnuplot_seconds{30};

int gnuplot_time_limit_ms() { return g_gnuplot_seconds * 1000; }

}  // namespace

void set_gnuplot_time_limit(int seconds) { g_gnuplot_seconds = seconds; }

namespace {

struct GnuplotRun {
  int status = 0;
  std::string messages;  // what it wrote on stderr
  bool timed_out = false;
};

// Runs `gnuplot -d arguments...` in `dir` (no shell: the folder's name never reaches a command
// line or a script), without init files (-d: no gnuplotrc, no ~/.gnuplot), in a process group
// of its own, for at most gnuplot_time_limit_ms(): then the group is killed. Returns its exit
// status and what it wrote on stderr. An interruption meanwhile stops it (io/child_process.hpp).
GnuplotRun run_gnuplot(const fs::path& dir, const std::vector<std::string>& arguments) {
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
    throw IoError("cannot run gnuplot: " +
                  std::error_code(errno, std::generic_category()).message());
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
  ::posix_spawnattr_setpgroup(&attributes, 0);       // its own group: a timeout kills it all
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGXFSZ);  // ignored by the run (app/interrupt.cpp), not by gnuplot
  ::posix_spawnattr_setsigdefault(&attributes, &defaults);
  ::posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP |
                                              POSIX_SPAWN_SETSIGDEF);
  std::vector<std::string> words = {"gnuplot", "-d"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::vector<std::string> variables = gnuplot_environment();
  std::vector<char*> envp;
  for (std::string& variable : variables) envp.push_back(variable.data());
  envp.push_back(nullptr);
  pid_t child = 0;
  int spawned = 0;
  without_interruption([&] {
    spawned = ::posix_spawnp(&child, "gnuplot", &actions, &attributes, argv.data(), envp.data());
    if (spawned == 0) stop_on_interrupt(child);
  });
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attributes);
  ::close(pipe_fds[1]);
  GnuplotRun result;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(gnuplot_time_limit_ms());
  char buffer[512];
  while (spawned == 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd readable{pipe_fds[0], POLLIN, 0};
    const int ready = left.count() > 0 ? ::poll(&readable, 1, static_cast<int>(left.count())) : 0;
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {  // out of time: the whole group goes, and its stderr with it
      result.timed_out = true;
      ::kill(-child, SIGKILL);
      break;
    }
    if (ready < 0) break;
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    result.messages.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  if (spawned != 0)
    throw IoError("cannot run gnuplot: " +
                  std::error_code(spawned, std::generic_category()).message());
  while (::waitpid(child, &result.status, 0) < 0 && errno == EINTR) {
  }
  ::kill(-child, SIGKILL);  // whatever it left running in its group
  forget_child(child);
  return result;
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

// Whether this gnuplot can draw PNG and SVG, asked once: one that cannot (built without cairo,
// broken, hanging) leaves the run's scripts and data written, with a note, like a missing one.
bool gnuplot_can_draw(const fs::path& dir) {
  static const std::optional<std::string> problem = [&]() -> std::optional<std::string> {
    GnuplotRun probe;
    try {
      probe = run_gnuplot(dir, {"-e", "set terminal pngcairo; set terminal svg"});
    } catch (const IoError& e) {         // it cannot be started (no process left under ulimit -u)
      const std::string why = e.what();  // "cannot run gnuplot: <the system's reason>"
      return "it cannot be started (" + why.substr(why.find(": ") + 2) + ")";
    }
    if (probe.timed_out)
      return fmt::format("it did not answer within {} s", gnuplot_time_limit_ms() / 1000);
    const auto [message, only_warnings] = first_message(probe.messages);
    if (!WIFEXITED(probe.status) || WEXITSTATUS(probe.status) != 0 ||
        (!probe.messages.empty() && !only_warnings))
      return "it cannot draw PNG and SVG (" + (message.empty() ? "it failed" : message) + ")";
    return std::nullopt;
  }();
  if (problem) {
    static bool told = false;
    if (!told)
      std::cerr << "note: gnuplot is installed but " << *problem
                << ", so no PNG/SVG plots were "
                   "drawn; the .gp scripts and CSV files are written\n";
    told = true;
  }
  return !problem;
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
  if (!gnuplot_can_draw(dir)) return PlotResult::no_gnuplot;
  const fs::path png = dir / (plot.name + ".png"), svg = dir / (plot.name + ".svg");
  const GnuplotRun drawn = run_gnuplot(dir, {script});
  const int status = drawn.status;
  const std::string& messages = drawn.messages;
  const auto [message, only_warnings] = first_message(messages);
  std::string problem;
  if (drawn.timed_out)
    problem = fmt::format(
        "gnuplot did not finish {} within {} s (MCRT_GNUPLOT_TIMEOUT sets "
        "the limit)",
        script, gnuplot_time_limit_ms() / 1000);
  else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
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
