#include "app/interrupt.hpp"

#include <csignal>
#include <mutex>

#include <unistd.h>

#include <fmt/format.h>

#include "app/run_folder.hpp"
#include "core/parallel.hpp"

namespace mcrt {

namespace {

// Guarded by the lock of io/child_process.hpp; `written_to` is --out of a committed run,
// kept after its folder is unregistered.
RunFolder* g_folder = nullptr;
std::string g_written_to;

void remember_if_written() {
  if (g_folder && g_folder->committed()) g_written_to = g_folder->out().string();
}

// The user's (INT, QUIT), the system's or a job scheduler's (TERM, HUP, ALRM, USR1, USR2).
constexpr int k_handled[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM};

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (const int signal : k_handled) sigaddset(&set, signal);
  return set;
}

[[noreturn]] void say_and_exit(const std::string& program, int signal, const std::string& what) {
  const std::string line =
      fmt::format("{}: interrupted by SIG{}; {}\n", program, ::sigabbrev_np(signal), what);
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
  ::_exit(128 + signal);
}

// The waiting thread: exits at once (no destructors: other threads are still running), with
// the lock held so that nothing else starts a child or a swap.
[[noreturn]] void wait_for_interrupt(const std::string& program) {
  const sigset_t set = interrupt_signals();
  int signal = 0;
  while (::sigwait(&set, &signal) != 0) {
  }
  if (!hold_interruption_lock(std::chrono::seconds(2)))  // a lock held for seconds is stuck I/O
    say_and_exit(program, signal,
                 "a file operation did not finish, so its staging folder may "
                 "remain (the next run removes it)");
  stop_children();
  remember_if_written();
  std::string where = "nothing was written";
  if (!g_written_to.empty()) {
    where = fmt::format("the run was already written to '{}'", g_written_to);
  } else if (g_folder) {
    where = fmt::format("nothing written to '{}'", g_folder->out().string());
    g_folder->discard();
  }
  say_and_exit(program, signal, where);
}

}  // namespace

void watch_interrupts(const std::string& program) {
  static std::once_flag once;
  std::call_once(once, [&] {
    const sigset_t set = interrupt_signals();
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
    struct sigaction broken_pipe {};  // caught, not ignored: gnuplot gets the default back
    broken_pipe.sa_handler = [](int) {};
    broken_pipe.sa_flags = SA_RESTART;
    ::sigaction(SIGPIPE, &broken_pipe, nullptr);
    ::signal(SIGXFSZ, SIG_IGN);
    start_detached_or_exit(program, [program] { wait_for_interrupt(program); });
  });
}

void discard_on_interrupt(RunFolder* folder) {
  without_interruption([&] {
    remember_if_written();  // the signal may come between here and the process's exit
    g_folder = folder;
  });
}

}  // namespace mcrt
