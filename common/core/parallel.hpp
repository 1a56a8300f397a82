#pragma once
/// A deterministic parallel-for: body(i) runs once for each i in [0, count) on `threads`
/// threads. Results are deterministic whatever the thread count as long as body(i) writes only
/// to the i-th result and draws its random numbers from streams chosen by i, never by thread.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mcrt {

/// The number of hardware threads (at least 1): the default for --threads.
inline int hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

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
  for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(work);
  pool.clear();  // joins
  if (failure) std::rethrow_exception(failure);
}

}  // namespace mcrt
