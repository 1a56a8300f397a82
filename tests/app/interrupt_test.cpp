// SIGINT and SIGTERM during a run (common/app/interrupt.hpp), each in a child process of its own
// (a death test), in the order ChapterApp::run registers, commits and forgets its RunFolder:
// the exit code is 128 + the signal, the one line says truthfully whether --out was written,
// and --out holds either the previous run or the new one, whole. The death tests fork (the
// default style) while this process has one thread; the child starts the waiting thread.

#include "app/interrupt.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

#include <unistd.h>

#include <gtest/gtest.h>

#include "app/run_folder.hpp"
#include "support/temp_files.hpp"

namespace fs = std::filesystem;
using namespace mcrt::testing;  // support/temp_files.hpp

namespace {

fs::path fresh_dir(const std::string& name) { return fresh_temp_dir("interrupt_test", name); }

// The summary.json of a chapter's run with this seed: it tells two runs apart.
std::string summary_of(int seed) {
  return R"({"chapter": "ch01_ray_tracing", "seed": )" + std::to_string(seed) + "}";
}

void finished_run(const fs::path& out, int seed) {
  mcrt::RunFolder folder(out);
  write_text(folder.staging() / "summary.json", summary_of(seed));
  folder.commit();
}

// A run into `out` as ChapterApp::run makes it, stopped by `signal` (sent to the whole
// process, so the waiting thread receives it) when it has got as far as `until`.
enum class Until { Writing, Committed, Forgotten };

[[noreturn]] void interrupted_run(const fs::path& out, int seed, Until until, int signal) {
  mcrt::watch_interrupts("interrupt_test");
  mcrt::RunFolder folder(out);
  mcrt::discard_on_interrupt(&folder);
  write_text(folder.staging() / "summary.json", summary_of(seed));
  if (until != Until::Writing) folder.commit();
  if (until == Until::Forgotten) mcrt::discard_on_interrupt(nullptr);  // as before main returns
  ::kill(::getpid(), signal);
  ::sleep(10);  // the waiting thread exits long before this ends
  std::_Exit(0);
}

// Sends `signal` to a run that has got as far as `until`, with a previous run (seed 1) in
// --out; the run's line must match `line`, and --out must hold the run of `seed_left`.
void expect_interrupted(const std::string& name, Until until, int signal, const std::string& line,
                        int seed_left) {
  const fs::path dir = fresh_dir(name);
  finished_run(dir / "out", 1);
  EXPECT_EXIT(interrupted_run(dir / "out", 2, until, signal),
              ::testing::ExitedWithCode(128 + signal), line);
  EXPECT_EQ(read_text(dir / "out" / "summary.json"), summary_of(seed_left));
  EXPECT_EQ(entries(dir), 1);  // --out alone: no staging folder, no previous run left beside it
}

TEST(InterruptTest, ASignalWhileWritingKeepsThePreviousRunAndRemovesTheStagingFolder) {
  expect_interrupted("writing", Until::Writing, SIGTERM,
                     "interrupt_test: interrupted by SIGTERM; nothing written to '.*out'", 1);
}

TEST(InterruptTest, ASignalAfterTheSwapSaysTheRunWasWritten) {
  expect_interrupted(
      "committed", Until::Committed, SIGINT,
      "interrupt_test: interrupted by SIGINT; the run was already written to '.*out'", 2);
}

// The folder is forgotten just before main returns; a signal may still come before the
// process ends, and it must not claim that nothing was written.
TEST(InterruptTest, ASignalAfterTheFolderIsForgottenStillSaysTheRunWasWritten) {
  expect_interrupted(
      "forgotten", Until::Forgotten, SIGINT,
      "interrupt_test: interrupted by SIGINT; the run was already written to '.*out'", 2);
}

// Issue 34: SIGHUP (a closed terminal), SIGQUIT, SIGUSR1, SIGUSR2 and SIGALRM killed the run
// without a word and left its staging folder.
TEST(InterruptTest, EveryHandledSignalEndsTheRunLikeSigterm) {
  for (const auto& [signal, name] : {std::pair{SIGHUP, "SIGHUP"},
                                     {SIGQUIT, "SIGQUIT"},
                                     {SIGUSR1, "SIGUSR1"},
                                     {SIGUSR2, "SIGUSR2"},
                                     {SIGALRM, "SIGALRM"}})
    expect_interrupted(std::string("handled_") + name, Until::Writing, signal,
                       std::string("interrupt_test: interrupted by ") + name +
                           "; nothing written to '.*out'",
                       1);
}

// Issue 34: a write to a closed pipe killed the run (SIGPIPE, exit 141, no message).
TEST(InterruptTest, AWriteToAClosedPipeFailsInsteadOfKillingTheRun) {
  EXPECT_EXIT(
      {
        mcrt::watch_interrupts("interrupt_test");
        int fds[2];
        if (::pipe(fds) != 0) std::_Exit(2);
        ::close(fds[0]);
        const ssize_t written = ::write(fds[1], "x", 1);
        std::_Exit(written < 0 && errno == EPIPE ? 7 : 8);
      },
      ::testing::ExitedWithCode(7), "");
}

// Issue 34: the signal thread waited for a lock that a blocked operation held, so SIGINT and
// SIGTERM were swallowed. It waits two seconds at most, then ends the run anyway.
TEST(InterruptTest, AnOperationStuckUnderTheLockDoesNotSwallowTheSignal) {
  EXPECT_EXIT(
      {
        mcrt::watch_interrupts("interrupt_test");
        mcrt::without_interruption([] {
          ::kill(::getpid(), SIGTERM);
          ::sleep(20);  // stuck I/O: far longer than the thread's patience
        });
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(128 + SIGTERM),
      "interrupt_test: interrupted by SIGTERM; a file operation did not finish");
}

}  // namespace
