#include "io/interrupt.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <mutex>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "core/parallel.hpp"
#include "io/run_folder.hpp"

namespace mcrt {

namespace {

// How long the waiting thread waits for the lock before it exits anyway: what holds it (a
// check of --out, a swap, a spawn) takes milliseconds, so a longer hold is I/O that is stuck
// (a hung network file system), and the user's signal must still end the run.
constexpr std::chrono::seconds k_lock_patience{2};

// What an interruption cleans up, guarded by one lock (recursive: a spawn under
// without_interruption registers its child with the lock held).
struct Cleanup {
  std::recursive_timed_mutex mutex;
  RunFolder* folder = nullptr;
  std::string written_to;  // --out of a committed run, kept after its folder is unregistered
  std::vector<pid_t> children;
};

Cleanup& cleanup() {
  static Cleanup& state = *new Cleanup;  // never destroyed: the thread may use it during exit
  return state;
}

// A committed run's --out is kept once the run is known to be written, whatever happens to
// its RunFolder after (ChapterApp::run unregisters it before main returns).
void remember_if_written(Cleanup& state) {
  if (state.folder && state.folder->committed()) state.written_to = state.folder->out().string();
}

// The signals that end a run cleanly, each with its name: the user's (INT, QUIT), the
// system's or a job scheduler's (TERM, HUP when the terminal or ssh goes, ALRM, USR1, USR2).
struct Handled {
  int signal;
  const char* name;
};
constexpr Handled k_handled[] = {{SIGINT, "SIGINT"},   {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"},
                                 {SIGQUIT, "SIGQUIT"}, {SIGUSR1, "SIGUSR1"}, {SIGUSR2, "SIGUSR2"},
                                 {SIGALRM, "SIGALRM"}};

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (const Handled& handled : k_handled) sigaddset(&set, handled.signal);
  return set;
}

const char* signal_name(int signal) {
  for (const Handled& handled : k_handled)
    if (handled.signal == signal) return handled.name;
  return "a signal";
}

// SIGPIPE is caught, not ignored: a write to a closed pipe then fails with EPIPE and is
// reported like any failed write, while gnuplot, started with exec, gets the default back.
void on_broken_pipe(int) {}

// The waiting thread: on a handled signal, stop the children, discard the staging folder,
// say so in one line and exit at once (no destructors: other threads are still running).
[[noreturn]] void wait_for_interrupt(std::string program) {
  const sigset_t set = interrupt_signals();
  int signal = 0;
  while (::sigwait(&set, &signal) != 0) {
  }
  Cleanup& state = cleanup();
  // Held until _exit: nothing else may start a child or a swap. Never waited for without
  // end: a thread stuck in I/O with the lock must not swallow the signal.
  if (!state.mutex.try_lock_for(k_lock_patience)) {
    const std::string line = fmt::format(
        "{}: interrupted by {}; a file operation did not finish, so its staging folder may "
        "remain (the next run removes it)\n",
        program, signal_name(signal));
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
    ::_exit(128 + signal);
  }
  for (const pid_t child : state.children) {
    ::kill(-child, SIGKILL);  // its whole group: a wrapper's children too
    ::waitpid(child, nullptr, 0);
  }
  remember_if_written(state);
  std::string where = "nothing was written";
  if (!state.written_to.empty()) {
    where = fmt::format("the run was already written to '{}'", state.written_to);
  } else if (state.folder) {
    where = fmt::format("nothing written to '{}'", state.folder->out().string());
    state.folder->discard();
  }
  const std::string line =
      fmt::format("{}: interrupted by {}; {}\n", program, signal_name(signal), where);
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
  ::_exit(128 + signal);
}

}  // namespace

void watch_interrupts(const std::string& program) {
  static std::once_flag once;
  std::call_once(once, [&] {
    const sigset_t set = interrupt_signals();
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
    struct sigaction broken_pipe {};
    broken_pipe.sa_handler = on_broken_pipe;
    sigemptyset(&broken_pipe.sa_mask);
    broken_pipe.sa_flags = SA_RESTART;
    ::sigaction(SIGPIPE, &broken_pipe, nullptr);
    // A file over `ulimit -f` then fails with EFBIG, reported as any failed write (exit 1).
    ::signal(SIGXFSZ, SIG_IGN);
    start_detached_or_exit(program, [program] { wait_for_interrupt(program); });
  });
}

void without_interruption(const std::function<void()>& action) {
  const std::lock_guard lock(cleanup().mutex);
  action();
}

void discard_on_interrupt(RunFolder* folder) {
  const std::lock_guard lock(cleanup().mutex);
  Cleanup& state = cleanup();
  remember_if_written(state);  // the signal may come between here and the process's exit
  state.folder = folder;
}

void stop_on_interrupt(pid_t child) {
  const std::lock_guard lock(cleanup().mutex);
  cleanup().children.push_back(child);
}

void forget_child(pid_t child) {
  const std::lock_guard lock(cleanup().mutex);
  auto& children = cleanup().children;
  children.erase(std::remove(children.begin(), children.end(), child), children.end());
}

}  // namespace mcrt
