#pragma once
/// A deterministic parallel-for: body(i) runs once for each i in [0, count) on `threads`
/// threads. Results are deterministic whatever the thread count as long as body(i) writes only
/// to the i-th result and draws its random numbers from streams chosen by i, never by thread.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace mcrt {

/// The number of hardware threads (at least 1): the default for --threads.
inline int hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Says once, on stderr, that only `started` of `wanted` threads could be created and why.
inline void note_fewer_threads(std::size_t started, std::size_t wanted, const std::string& why) {
  static std::atomic<bool> told{false};
  if (told.exchange(true)) return;
  std::fprintf(stderr,
               "note: only %zu of %zu threads could be started (%s); the run goes on with %zu\n",
               started, wanted, why.c_str(), std::max<std::size_t>(started, 1));
}

/// Starts `body` on a detached thread. If the system gives no thread (ulimit -u), says so in
/// one line opened by `program` and exits with code 1, before any work: a run whose helper
/// thread cannot start does not start.
template <class Body>
void start_detached_or_exit(const std::string& program, Body&& body) {
  try {
    std::thread(std::forward<Body>(body)).detach();
  } catch (const std::system_error& e) {
    std::fprintf(stderr, "%s: error: cannot start a thread: %s\n", program.c_str(),
                 e.code().message().c_str());
    std::exit(1);
  }
}

template <class Body>
void parallel_for(std::size_t count, int threads, Body&& body) {
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), count);
  if (workers <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    try {
      for (std::size_t i = next++; i < count; i = next++) body(i);
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = count;  // the others stop at their next index
    }
  };
  // The calling thread only waits. Its stack holds what every worker reads on every item (the
  // body's captures: settings, camera, estimator); had it worked too, its own counters and
  // locals, written on every ray, would share cache lines with them and take those lines from
  // the other threads (the lecture's render loop ran 1.5x one thread instead of 2x).
  std::vector<std::jthread> pool;
  pool.reserve(workers);
  try {
    for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(work);
  } catch (const std::system_error& e) {
    // The system gives no more threads (ulimit -u, a container's pids limit): the run goes on
    // with those it has, or on this thread alone; its results do not depend on the count.
    note_fewer_threads(pool.size(), workers, e.code().message());
    if (pool.empty()) work();
  }
  pool.clear();  // joins
  if (failure) std::rethrow_exception(failure);
}

}  // namespace mcrt
