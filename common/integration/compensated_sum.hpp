#pragma once
/// Compensated (Neumaier) summation: the sum of many terms with an error of a few ulps of the
/// result instead of up to one ulp per term. Quadrature needs it: the trapezoid rule on 10^6
/// points has a truncation error near 1e-13, the size of a plain running sum's round-off.

#include <cmath>

namespace mcrt {

class CompensatedSum {
 public:
  void add(double term) {
    const double t = sum_ + term;
    // The larger of sum_ and term survives in t exactly; add back what was lost of the other.
    compensation_ += std::abs(sum_) >= std::abs(term) ? (sum_ - t) + term : (term - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

}  // namespace mcrt
