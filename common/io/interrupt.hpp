#pragma once
/// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2 and SIGALRM during a run: the staging
/// folder is removed, child processes (gnuplot) are stopped, one line is printed, and the
/// program exits with 128 + the signal (130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP, ...).
/// SIGPIPE never ends a run: a write to a closed pipe fails (EPIPE) and is reported as such.
///
/// The signals are blocked in main before any thread starts (threads inherit the mask), and
/// one dedicated thread waits for them with sigwait(), so the cleanup is ordinary code rather
/// than a signal handler. A lock keeps it from running in the middle of a spawn or a swap; it
/// waits for that lock at most two seconds, so I/O stuck under the lock cannot swallow a signal.

#include <functional>
#include <string>

#include <sys/types.h>

namespace mcrt {

class RunFolder;

/// Blocks the handled signals in the calling thread, catches SIGPIPE, and starts the thread that waits for them.
/// Call it once, in main, before any other thread starts; `program` opens the printed line.
void watch_interrupts(const std::string& program);

/// Runs `action` while no interruption is handled (the cleanup waits until it is done).
void without_interruption(const std::function<void()>& action);

/// The run folder an interruption discards (nullptr: none). Replacing a committed folder
/// keeps its --out, so that a signal after the swap, up to the process's exit, still says the
/// run was written there.
void discard_on_interrupt(RunFolder* folder);

/// A child process an interruption stops (SIGKILL, then waited for). Call both under
/// without_interruption, together with the spawn and the wait.
void stop_on_interrupt(pid_t child);
void forget_child(pid_t child);

}  // namespace mcrt
