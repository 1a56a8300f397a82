#include "io/interrupt.hpp"

#include <algorithm>
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

// What an interruption cleans up, guarded by one lock (recursive: a spawn under
// without_interruption registers its child with the lock held).
struct Cleanup {
  std::recursive_mutex mutex;
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

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

// The waiting thread: on SIGINT or SIGTERM, stop the children, discard the staging folder,
// say so in one line and exit at once (no destructors: other threads are still running).
[[noreturn]] void wait_for_interrupt(std::string program) {
  const sigset_t set = interrupt_signals();
  int signal = 0;
  while (::sigwait(&set, &signal) != 0) {
  }
  Cleanup& state = cleanup();
  state.mutex.lock();  // held until _exit: nothing else may start a child or a swap
  for (const pid_t child : state.children) {
    ::kill(child, SIGKILL);
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
  const std::string line = fmt::format("{}: interrupted by {}; {}\n", program,
                                       signal == SIGINT ? "SIGINT" : "SIGTERM", where);
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
  ::_exit(128 + signal);
}

}  // namespace

void watch_interrupts(const std::string& program) {
  static std::once_flag once;
  std::call_once(once, [&] {
    const sigset_t set = interrupt_signals();
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
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
