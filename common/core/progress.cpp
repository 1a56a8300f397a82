#include "core/progress.hpp"

#include <algorithm>
#include <cstdio>

#include <unistd.h>

namespace mcrt {

ProgressBar::ProgressBar(std::string label, std::uint64_t total, bool quiet)
    : label_(std::move(label)),
      total_(total == 0 ? 1 : total),
      enabled_(!quiet && ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(std::uint64_t units) {
  const std::uint64_t done = done_ += units;
  if (!enabled_) return;
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock) return;  // another thread is drawing
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100)) return;  // at most 10 redraws a second
  last_draw_ = now;
  draw(done);
}

void ProgressBar::finish() {
  if (!enabled_ || finished_) return;
  std::lock_guard lock(draw_mutex_);
  finished_ = true;
  draw(done_.load());
  std::fputc('\n', stderr);
}

void ProgressBar::draw(std::uint64_t done) {
  constexpr int width = 30;
  const double fraction = std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  char bar[width + 1];
  const int filled = static_cast<int>(fraction * width);
  for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
  bar[width] = '\0';
  std::fprintf(stderr, "\r%s [%s] %5.1f%%  %6.1fs elapsed  %6.1fs left ", label_.c_str(), bar,
               100.0 * fraction, elapsed, remaining);
  std::fflush(stderr);
}

}  // namespace mcrt
