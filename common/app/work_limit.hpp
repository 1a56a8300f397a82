#pragma once
/// Refusing, before any work, a run too large to finish: a chapter predicts from its flags the
/// work (points drawn, coordinates) and compares it with a limit (app/ray_limit.hpp for rays).

#include <string_view>

namespace mcrt {

/// An upper bound of a run's work (a double: a request may exceed 2^64), its unit and what it counts.
struct Work {
  double amount = 0.0;
  std::string_view unit;     ///< e.g. "points"
  std::string_view counted;  ///< e.g. "trials x the sizes of the N grid"
};

/// Throws UsageError (exit 2) if work.amount > limit: one line naming `flags`, the amount, what
/// it counts, the limit and `remedy`.
void check_work_limit(const Work& work, double limit, std::string_view flags,
                      std::string_view remedy);

}  // namespace mcrt
