// SIGINT and SIGTERM during a run (common/io/interrupt.hpp), each in a child process of its own
// (a death test), in the order ChapterApp::run registers, commits and forgets its RunFolder:
// the exit code is 128 + the signal, the one line says truthfully whether --out was written,
// and --out holds either the previous run or the new one, whole. The death tests fork (the
// default style) while this process has one thread; the child starts the waiting thread.

#include "io/interrupt.hpp"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "io/run_folder.hpp"

namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("mcrt_interrupt_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string read(const fs::path& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// A run of a chapter into `out` whose summary names `seed`; `until` says how far it gets
// before `signal` is sent to the whole process (the waiting thread receives it).
enum class Until { Writing, Committed, Forgotten };

[[noreturn]] void interrupted_run(const fs::path& out, int seed, Until until, int signal) {
  mcrt::watch_interrupts("interrupt_test");
  mcrt::RunFolder folder(out);
  mcrt::discard_on_interrupt(&folder);
  write(folder.staging() / "summary.json",
        R"({"chapter": "ch01_ray_tracing", "seed": )" + std::to_string(seed) + "}");
  if (until != Until::Writing) folder.commit();
  if (until == Until::Forgotten) mcrt::discard_on_interrupt(nullptr);  // as before main returns
  ::kill(::getpid(), signal);
  ::sleep(10);  // the waiting thread exits long before this ends
  std::_Exit(0);
}

void finished_run(const fs::path& out, int seed) {
  mcrt::RunFolder folder(out);
  write(folder.staging() / "summary.json",
        R"({"chapter": "ch01_ray_tracing", "seed": )" + std::to_string(seed) + "}");
  folder.commit();
}

std::string seed_line(int seed) {
  return R"({"chapter": "ch01_ray_tracing", "seed": )" + std::to_string(seed) + "}";
}

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(InterruptTest, ASignalWhileWritingKeepsThePreviousRunAndRemovesTheStagingFolder) {
  const fs::path dir = fresh_dir("writing");
  finished_run(dir / "out", 1);
  EXPECT_EXIT(interrupted_run(dir / "out", 2, Until::Writing, SIGTERM),
              ::testing::ExitedWithCode(128 + SIGTERM),
              "interrupt_test: interrupted by SIGTERM; nothing written to '.*out'");
  EXPECT_EQ(read(dir / "out" / "summary.json"), seed_line(1));
  EXPECT_EQ(entries(dir), 1);  // no staging folder left beside --out
}

TEST(InterruptTest, ASignalAfterTheSwapSaysTheRunWasWritten) {
  const fs::path dir = fresh_dir("committed");
  finished_run(dir / "out", 1);
  EXPECT_EXIT(interrupted_run(dir / "out", 2, Until::Committed, SIGINT),
              ::testing::ExitedWithCode(128 + SIGINT),
              "interrupt_test: interrupted by SIGINT; the run was already written to '.*out'");
  EXPECT_EQ(read(dir / "out" / "summary.json"), seed_line(2));
  EXPECT_EQ(entries(dir), 1);
}

// The folder is forgotten just before main returns; a signal may still come before the
// process ends, and it must not claim that nothing was written.
TEST(InterruptTest, ASignalAfterTheFolderIsForgottenStillSaysTheRunWasWritten) {
  const fs::path dir = fresh_dir("forgotten");
  finished_run(dir / "out", 1);
  EXPECT_EXIT(interrupted_run(dir / "out", 2, Until::Forgotten, SIGINT),
              ::testing::ExitedWithCode(128 + SIGINT),
              "interrupt_test: interrupted by SIGINT; the run was already written to '.*out'");
  EXPECT_EQ(read(dir / "out" / "summary.json"), seed_line(2));
  EXPECT_EQ(entries(dir), 1);
}

}  // namespace
