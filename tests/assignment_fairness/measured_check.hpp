#pragma once
// One p-value-based check as the fairness measurement runs it: its single-seed p-value as a
// function of the seed, and the rule its test applies to it.

#include <cstdint>
#include <functional>
#include <string>

#include "assignments/grading.hpp"

namespace mcrt::testing::assignment {

struct MeasuredCheck {
  std::string name;             ///< row name in fairness.csv, e.g. a2_cosine_hemisphere
  std::string test;             ///< the CTest name of the test that applies it
  double alpha = k_seed_alpha;  ///< one seed rejects below this
  bool majority = true;  ///< fails on 2 of 3 grading seeds (grading.hpp); else on one fixed seed
  bool region = false;   ///< renders a reference per seed (about a second): fewer seeds
  std::function<double(std::uint64_t)> p_value;
};

}  // namespace mcrt::testing::assignment
