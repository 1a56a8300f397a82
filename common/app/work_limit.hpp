#pragma once
/// Refusing a run too large to finish, before any work is done: a chapter predicts from its
/// flags how much work the run would do (points drawn, coordinates, rays traced) and compares
/// that with a limit. app/ray_limit.hpp is the same for rays, with a time estimate.

#include <string_view>

namespace mcrt {

/// What a run would do: an upper bound (a double, since a request may exceed 2^64), its unit
/// and, in words, what the prediction counts.
struct Work {
  double amount = 0.0;
  std::string_view unit;     ///< e.g. "points"
  std::string_view counted;  ///< e.g. "trials x the sizes of the N grid"
};

/// Throws UsageError (exit code 2) if work.amount > limit, with one line naming `flags`, the
/// predicted amount, what it counts, the limit and `remedy` (what to change).
void check_work_limit(const Work& work, double limit, std::string_view flags,
                      std::string_view remedy);

}  // namespace mcrt
