#pragma once
/// SIGINT and SIGTERM during a run: the staging folder is removed, child processes (gnuplot)
/// are stopped, one line is printed, and the program exits with 130 or 143 (128 + the signal).
///
/// Both signals are blocked in main before any thread starts (threads inherit the mask), and
/// one dedicated thread waits for them with sigwait(), so the cleanup is ordinary code rather
/// than a signal handler. A lock keeps it from running in the middle of a spawn or a swap.

#include <functional>
#include <string>

#include <sys/types.h>

namespace mcrt {

class RunFolder;

/// Blocks SIGINT and SIGTERM in the calling thread and starts the thread that waits for them.
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
