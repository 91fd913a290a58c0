// The study's arithmetic on hand-computed answers: per-call error, digits, max/median, Pareto
// front, observed order of convergence.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "accuracy/ErrorStats.h"
#include "accuracy/Pareto.h"
#include "accuracy/SimulationStudy.h"

namespace acc = rbdgen::accuracy;

TEST(AccuracyError, RelativeForLargeAbsoluteForSmall)
{
  // ||x - ref||_inf / max(1, ||ref||_inf)
  Eigen::VectorXd ref(3), x(3);
  ref << 100, -200, 3;
  x << 100.5, -200, 2;
  EXPECT_DOUBLE_EQ(acc::relativeError(x, ref), 1.0 / 200); // max |diff| = 1, scale 200
  ref << 0.1, 0.2, -0.3;
  x << 0.1, 0.2, -0.3 + 1e-6;
  EXPECT_NEAR(acc::relativeError(x, ref), 1e-6, 1e-15); // scale max(1, 0.3) = 1: absolute (1e-6 is not exact in binary)
  x(0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isinf(acc::relativeError(x, ref)));
}

TEST(AccuracyError, Digits)
{
  EXPECT_DOUBLE_EQ(acc::digits(1e-7), 7);
  EXPECT_NEAR(acc::digits(2e-16), 15.69897, 1e-5);
  EXPECT_DOUBLE_EQ(acc::digits(0), 30);   // floored at 1e-30
  EXPECT_DOUBLE_EQ(acc::digits(3), 0);    // worse than 100 %: no digit
  EXPECT_DOUBLE_EQ(acc::digits(std::numeric_limits<double>::infinity()), 0);
}

TEST(AccuracyError, MaxAndMedian)
{
  acc::ErrorStats s = acc::summarize({5, 1, 3});
  EXPECT_EQ(s.max, 5);
  EXPECT_EQ(s.median, 3);
  s = acc::summarize({4, 1, 3, 2});
  EXPECT_EQ(s.max, 4);
  EXPECT_EQ(s.median, 2.5);
  s = acc::summarize({1, std::numeric_limits<double>::quiet_NaN(), 2});
  EXPECT_TRUE(std::isinf(s.max)); // a NaN is the worst error, never hidden
  EXPECT_EQ(s.median, 2);
}

TEST(AccuracyPareto, HandMadeSet)
{
  //  error
  //   10 | a           e(inf: excluded)
  //    5 |      b   d
  //    1 |         c      f
  //      +---------------- cost
  //        1    2  3 4   6
  const std::vector<acc::CostError> pts = {
      {1, 10},                                        // a: cheapest -> front
      {2, 5},                                         // b: front
      {3, 1},                                         // c: front
      {4, 5},                                         // d: dominated by b (cheaper, same error) and c
      {5, std::numeric_limits<double>::infinity()},   // e: not finite
      {6, 1},                                         // f: dominated by c (same error, cheaper)
      {3, 1},                                         // g: equal to c: both kept
      {0.5, std::numeric_limits<double>::quiet_NaN()} // h: not finite
  };
  const std::vector<bool> expected = {true, true, true, false, false, false, true, false};
  EXPECT_EQ(acc::paretoFront(pts), expected);
  EXPECT_TRUE(acc::paretoFront({}).empty());
}

TEST(AccuracyOrder, PowerLawGivesItsExponent)
{
  // e = C dt^p exactly: the observed order is p between any two steps.
  const std::vector<double> dts = {1e-2, 5e-3, 2e-3, 1e-3};
  for(double p : {1.0, 2.0, 4.0})
  {
    std::vector<double> e;
    for(double dt : dts) e.push_back(3.0 * std::pow(dt, p));
    const auto o = acc::observedOrders(dts, e);
    EXPECT_TRUE(std::isnan(o[0]));
    for(std::size_t i = 1; i < o.size(); ++i) EXPECT_NEAR(o[i], p, 1e-9);
  }
  const auto o = acc::observedOrders({1, 0.5}, {0.0, 1e-3});
  EXPECT_TRUE(std::isnan(o[1])); // a zero error gives no order
}
