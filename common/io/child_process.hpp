#pragma once
/// The child processes a run has started (gnuplot), and the lock under which a process is
/// started, a folder swapped or an interruption handled (app/interrupt.hpp), one at a time.

#include <chrono>
#include <functional>

#include <sys/types.h>

namespace mcrt {

/// Runs `action` under the lock: an interruption's cleanup waits until it is done.
void without_interruption(const std::function<void()>& action);

/// A child process (the leader of its own process group) that stop_children() ends; call both
/// under without_interruption, with the spawn and the wait.
void stop_on_interrupt(pid_t child);
void forget_child(pid_t child);

/// Takes the lock for good (until the process exits), waiting at most `patience`: false if
/// it is held longer (I/O stuck under it), so that a signal is never swallowed.
bool hold_interruption_lock(std::chrono::milliseconds patience);

/// Kills the process group of every registered child (SIGKILL) and waits for it. Call it with
/// the lock held.
void stop_children() noexcept;

}  // namespace mcrt
