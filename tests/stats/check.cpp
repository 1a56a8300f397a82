#include "stats/check.hpp"

namespace mcrt::testing {

std::vector<StatisticalCheck>& statistical_checks() {
  static std::vector<StatisticalCheck> checks;
  return checks;
}

}  // namespace mcrt::testing
