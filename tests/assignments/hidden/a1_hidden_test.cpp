// Hidden tests of a1: the written answers' values (p = pi/4, N = 1000), 0.1% relative
// tolerance (the handout asks for 6 significant digits).

#include <gtest/gtest.h>

#include <cmath>

#include "assignments/a1/a1_produce.hpp"
#include "assignments/grading.hpp"
#include "assignments/subject/subject.hpp"
#include "core/math.hpp"

namespace mcrt::testing::assignment {
namespace {

class A1Answers : public ::testing::Test {
 protected:
  void check(const char* key, double expected, const std::string& hint) {
    // the answers file is the student's: the subject reads it (subject().a1_answers())
    const A1AnswerFile answers = subject().a1_answers();
    std::size_t i = 0;
    while (i < k_a1_answer_keys.size() && std::string(k_a1_answer_keys[i]) != key) ++i;
    ASSERT_TRUE(answers.valid && i < k_a1_answer_keys.size() && answers.values[i].has_value())
        << "not implemented: a1.5 answer " << key;
    const double given = *answers.values[i];
    EXPECT_NEAR(given, expected, 1e-3 * std::abs(expected))
        << key << " = " << given << "\n" << diagnosis(hint);
  }
  const double p = k_pi / 4.0, n = 1000.0;
};

TEST_F(A1Answers, MeanOfY) { check("E_Y", p, "Y_i is 1 with probability p: E[Y_i] = P(Y_i = 1)"); }
TEST_F(A1Answers, VarianceOfY) { check("V_Y", p * (1 - p), "a Bernoulli variable has E[Y^2] = E[Y]: V[Y] = p - p^2"); }
TEST_F(A1Answers, MeanOfM) { check("E_M", n * p, "M is a sum of N of the Y_i: linearity of expectation"); }
TEST_F(A1Answers, VarianceOfM) { check("V_M", n * p * (1 - p), "the Y_i are independent: their variances add"); }
TEST_F(A1Answers, VarianceOfTheEstimate) {
  check("V_estimate", 16.0 * p * (1 - p) / n, "V[c X] = c^2 V[X] with c = 4 / N");
}

}  // namespace
}  // namespace mcrt::testing::assignment
