#include "io/child_process.hpp"

#include <algorithm>
#include <csignal>
#include <mutex>
#include <vector>

#include <sys/wait.h>

namespace mcrt {

namespace {

// Recursive: a spawn under without_interruption registers its child with the lock held.
struct Children {
  std::recursive_timed_mutex mutex;
  std::vector<pid_t> pids;
};

Children& children() {
  static Children& state = *new Children;  // never destroyed: the signal thread uses it at exit
  return state;
}

}  // namespace

void without_interruption(const std::function<void()>& action) {
  const std::lock_guard lock(children().mutex);
  action();
}

void stop_on_interrupt(pid_t child) {
  without_interruption([&] { children().pids.push_back(child); });
}

void forget_child(pid_t child) {
  without_interruption([&] { std::erase(children().pids, child); });
}

bool hold_interruption_lock(std::chrono::milliseconds patience) {
  return children().mutex.try_lock_for(patience);
}

void stop_children() noexcept {
  for (const pid_t child : children().pids) {
    ::kill(-child, SIGKILL);  // its whole group: a wrapper's children too
    ::waitpid(child, nullptr, 0);
  }
}

}  // namespace mcrt
