#pragma once
// The running sums of RGB samples that give their mean and the covariance of that mean, for
// the checks that compare two renderers colour by colour.

#include <glm/glm.hpp>

#include "core/math.hpp"

namespace mcrt::testing {

/// n samples c: mean = sum c / n; covariance of the mean = the sample covariance over n,
/// (sum c c' - sum c sum c' / n) / (n - 1) / n.
struct ColorMoments {
  double n = 0.0;
  Vec3 sum{0.0};
  glm::dmat3 sum_outer{0.0};

  void add(const Color& c) {
    n += 1.0;
    sum += c;
    sum_outer += glm::outerProduct(c, c);
  }
  Vec3 mean() const { return sum / n; }
  glm::dmat3 covariance_of_mean() const {
    const glm::dmat3 covariance = (sum_outer - glm::outerProduct(sum, sum) / n) / (n - 1.0);
    return covariance / n;
  }
};

}  // namespace mcrt::testing
