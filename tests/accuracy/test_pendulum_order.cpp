// The simulation study on robots/pendulum.urdf against the closed-form equation of motion
//   (I_c + m lc^2) theta'' = -m g lc sin(theta),  m = 1, lc = 1, I_c = 4e-5, g = 9.81
// integrated in this test, in long double, by the same three integrators and by a fine RK4 reference.
// Checks: the study's trajectory errors equal the closed-form ones (so its reference, dynamics and
// error measure are right), its observed orders (RK4 ~4: halving dt divides the error by ~16;
// Euler ~1: by ~2), and its initial energy -m g lc cos(theta0).
#include <cmath>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "accuracy/SimulationStudy.h"

namespace acc = rbdgen::accuracy;

namespace
{

using LD = long double;
constexpr LD kM = 1, kLc = 1, kIc = 4e-5L, kG = 9.81L, kTheta0 = 0.5L;

LD accel(LD theta) { return -kM * kG * kLc * std::sin(theta) / (kIc + kM * kLc * kLc); }

/// theta(T) from theta0 at rest, by one of the study's integrators (names as integratorName).
LD integrate(const std::string & method, LD dt, LD horizon)
{
  LD th = kTheta0, w = 0;
  const long n = std::lround(static_cast<double>(horizon / dt));
  for(long i = 0; i < n; ++i)
  {
    if(method == "semi_implicit_euler")
    {
      w += dt * accel(th); // alpha+ = alpha + dt a(q); q+ = q + dt alpha+
      th += dt * w;
    }
    else if(method == "explicit_euler")
    {
      const LD a = accel(th); // q+ = q + dt alpha; alpha+ = alpha + dt a(q)
      th += dt * w;
      w += dt * a;
    }
    else
    {
      // classical RK4 on (theta, omega)
      const LD k1t = w, k1w = accel(th);
      const LD k2t = w + dt / 2 * k1w, k2w = accel(th + dt / 2 * k1t);
      const LD k3t = w + dt / 2 * k2w, k3w = accel(th + dt / 2 * k2t);
      const LD k4t = w + dt * k3w, k4w = accel(th + dt * k3t);
      th += dt / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
      w += dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
    }
  }
  return th;
}

class PendulumStudy : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    rbd::scene::Scene scene;
    scene.file = scene.urdf = std::string(RBDGEN_SOURCE_DIR) + "/robots/pendulum.urdf";
    scene.name = "pendulum";
    scene.initialQ["joint1"] = {static_cast<double>(kTheta0)};
    opt_.horizon = 1.0;
    opt_.dts = {8e-3, 4e-3, 2e-3, 1e-3};
    opt_.sampleDt = 8e-3;
    opt_.referenceDt = 2.5e-4;
    study_ = acc::runSimulationStudy(scene, opt_);
  }
  static acc::SimulationOptions opt_;
  static acc::SimulationStudy study_;
};
acc::SimulationOptions PendulumStudy::opt_;
acc::SimulationStudy PendulumStudy::study_;

} // namespace

TEST_F(PendulumStudy, ReferenceMatchesClosedForm)
{
  // RK4 error ~ C dt^4: at 2.5e-4 (and its x2 estimate) far below the errors being measured.
  EXPECT_LT(study_.referenceError, 1e-12);
  EXPECT_NEAR(study_.initialEnergy, static_cast<double>(-kM * kG * kLc * std::cos(kTheta0)), 1e-12);
  EXPECT_LT(study_.referenceEnergyDrift, 1e-10);
}

TEST_F(PendulumStudy, ErrorsEqualClosedFormErrors)
{
  ASSERT_EQ(study_.rows.size(), 3 * opt_.dts.size());
  const LD ref = integrate("rk4", 1e-5L, 1.0L);
  for(const acc::SimulationRow & row : study_.rows)
  {
    // |theta| < 1 here, so the study's relative error is the absolute error of theta(T).
    const double expected = static_cast<double>(std::fabs(integrate(row.integrator, row.dt, 1.0L) - ref));
    SCOPED_TRACE(row.integrator + " dt " + std::to_string(row.dt));
    EXPECT_FALSE(row.diverged);
    EXPECT_NEAR(row.trajectoryError, expected, 0.01 * expected + 1e-13);
    EXPECT_GT(row.wallPerSimSecond, 0);
  }
}

TEST_F(PendulumStudy, ObservedOrders)
{
  for(const acc::SimulationRow & row : study_.rows)
  {
    if(row.dt == opt_.dts.front()) continue; // no previous step
    SCOPED_TRACE(row.integrator + " dt " + std::to_string(row.dt));
    if(row.integrator == "rk4")
      EXPECT_NEAR(row.observedOrder, 4.0, 0.3); // halving dt divides the error by 13..20
    else
      EXPECT_NEAR(row.observedOrder, 1.0, 0.15); // by ~2
  }
}

TEST_F(PendulumStudy, CostGrowsAsStepShrinks)
{
  // Wall time per simulated second ~ 1/dt: the 8x smaller step costs clearly more; RK4's 4
  // evaluations per step cost more than semi-implicit Euler's one at the same step.
  auto find = [&](const std::string & in, double dt) {
    for(const auto & r : study_.rows)
      if(r.integrator == in && r.dt == dt) return r;
    return acc::SimulationRow{};
  };
  EXPECT_GT(find("rk4", 1e-3).wallPerSimSecond, 3 * find("rk4", 8e-3).wallPerSimSecond);
  EXPECT_GT(find("rk4", 1e-3).wallPerSimSecond, 1.5 * find("semi_implicit_euler", 1e-3).wallPerSimSecond);
}
