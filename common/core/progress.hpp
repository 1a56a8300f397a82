#pragma once
/// A progress bar with time remaining on stderr, drawn only when stderr is a terminal and the
/// chapter was not run with --quiet. Safe to advance from several threads.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace mcrt {

class ProgressBar {
 public:
  /// `total` units of work (rows, trials, rays...), described by `label`.
  ProgressBar(std::string label, std::uint64_t total, bool quiet);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void advance(std::uint64_t units = 1);
  /// Draws the full bar and ends its line (also done by the destructor).
  void finish();

  bool enabled() const { return enabled_; }

 private:
  void draw(std::uint64_t done);

  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  bool finished_ = false;
  std::atomic<std::uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  std::mutex draw_mutex_;
};

}  // namespace mcrt
