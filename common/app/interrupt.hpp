#pragma once
/// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2 and SIGALRM during a run: child processes
/// are stopped, the staging folder removed, one line printed, and the program exits with 128 +
/// the signal (130 for SIGINT). SIGPIPE and SIGXFSZ never end a run: the write fails (EPIPE,
/// EFBIG) and is reported as a failed write. The signals are blocked before any thread starts
/// and one thread waits for them (sigwait), so the cleanup is ordinary code; it takes the lock
/// of io/child_process.hpp, waiting at most two seconds so stuck I/O cannot swallow a signal.

#include <string>

#include "io/child_process.hpp"

namespace mcrt {

class RunFolder;

/// Blocks the handled signals, catches SIGPIPE, ignores SIGXFSZ, and starts the waiting thread.
/// Call it once, in main, before any other thread starts; `program` opens the printed line.
void watch_interrupts(const std::string& program);

/// The run folder an interruption discards (nullptr: none). Replacing a committed folder
/// keeps its --out, so that a signal up to the process's exit still says the run was written.
void discard_on_interrupt(RunFolder* folder);

}  // namespace mcrt
