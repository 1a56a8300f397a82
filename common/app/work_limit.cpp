#include "app/work_limit.hpp"

#include <fmt/format.h>

#include "app/usage_error.hpp"

namespace mcrt {

void check_work_limit(const Work& work, double limit, std::string_view flags,
                      std::string_view remedy) {
  if (work.amount <= limit) return;
  throw UsageError(
      fmt::format("{}: this run would draw {:.3g} {} ({}), above the limit of {:.3g}; {}", flags,
                  work.amount, work.unit, work.counted, limit, remedy));
}

}  // namespace mcrt
