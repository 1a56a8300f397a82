#pragma once
// Runs a chapter executable from build/bin/ as a student would, for the chapter tests.

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/temp_files.hpp"

namespace mcrt::testing {

struct ProgramRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

/// Runs `bin/<program> <arguments>` (arguments as one shell-quoted string).
inline ProgramRun run_program(const std::string& program, const std::string& arguments) {
  const std::filesystem::path tmp = MCRT_TEST_TMP;
  std::filesystem::create_directories(tmp);
  static int counter = 0;
  const std::string stem =
      (tmp / (program + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++)))
          .string();
  // The default reference cache (--reference-dir not given) is this build's, never the user's.
  const std::string command = "XDG_CACHE_HOME='" + (tmp / "xdg-cache").string() + "' " +
                              std::string(MCRT_BIN_DIR) + "/" + program + " " + arguments + " >" +
                              stem + ".out 2>" + stem + ".err";
  const int status = std::system(command.c_str());
  ProgramRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text(stem + ".out");
  run.err = read_text(stem + ".err");
  std::filesystem::remove(stem + ".out");
  std::filesystem::remove(stem + ".err");
  return run;
}

/// Runs `bin/<program> <arguments>` with stdout on /dev/full, where every write fails with
/// "No space left on device"; stdout of the result is empty.
inline ProgramRun run_program_to_full_stdout(const std::string& program,
                                             const std::string& arguments) {
  const std::filesystem::path tmp = MCRT_TEST_TMP;
  std::filesystem::create_directories(tmp);
  const std::string err =
      (tmp / (program + "-" + std::to_string(::getpid()) + "-full.err")).string();
  const std::string command =
      std::string(MCRT_BIN_DIR) + "/" + program + " " + arguments + " >/dev/full 2>" + err;
  const int status = std::system(command.c_str());
  ProgramRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = read_text(err);
  std::filesystem::remove(err);
  return run;
}

/// A fresh, empty folder for one test's outputs.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(MCRT_TEST_TMP) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline nlohmann::json read_json(const std::filesystem::path& path) {
  return nlohmann::json::parse(read_text(path));
}

/// Number of lines in `text` (a trailing newline does not start a new line).
inline int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines;
}

/// Files left anywhere under `dir` (to prove that a failed run wrote nothing).
inline int file_count(const std::filesystem::path& dir) {
  int n = 0;
  if (!std::filesystem::exists(dir)) return 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    n += entry.is_regular_file();
  return n;
}

/// A command line a chapter must refuse, and the flag its one-line message must name.
struct BadInput {
  std::string arguments;
  std::string flag;
};
inline void PrintTo(const BadInput& input, std::ostream* os) { *os << input.arguments; }

/// A readable test name for each BadInput: its index and its arguments.
inline std::string bad_input_name(const ::testing::TestParamInfo<BadInput>& param_info) {
  std::string name = std::to_string(param_info.index) + "_";
  for (char c : param_info.param.arguments)
    name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

/// The chapter refuses `input`: exit code 2, one line on stderr naming the flag, and no
/// output folder created (refused before any work).
inline void expect_refused(const std::string& program, const BadInput& input) {
  // One folder per test process: ctest runs the bad-input cases of a chapter side by side.
  const std::filesystem::path out =
      fresh_dir(program + "_refused_" + std::to_string(::getpid())) / "out";
  const ProgramRun run = run_program(program, input.arguments + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find(input.flag), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

/// With a regular file where the output folder should go (which stops root too), the chapter
/// exits with code 1 and one line naming the path, and writes nothing anywhere.
inline void expect_unwritable_output_fails(const std::string& program,
                                           const std::string& arguments) {
  const auto dir = fresh_dir(program + "_unwritable");
  const auto blocker = dir / "blocker";
  { std::ofstream(blocker) << "in the way\n"; }
  const auto out = blocker / "out";
  const ProgramRun run = run_program(program, arguments + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find(out.string()), std::string::npos) << run.err;
  EXPECT_EQ(file_count(dir), 1);  // the blocker alone
}

/// With stdout on /dev/full, a run that would otherwise succeed (and print its table) exits
/// with code 1 and one line on stderr naming stdout and the system's reason.
inline void expect_full_stdout_fails(const std::string& program, const std::string& arguments) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const auto out = fresh_dir(program + "_full_stdout");
  const ProgramRun run = run_program_to_full_stdout(program, arguments + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("stdout"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("No space left on device"), std::string::npos) << run.err;
}

}  // namespace mcrt::testing
