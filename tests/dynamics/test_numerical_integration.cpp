// RBDyn's integration names: jointIntegration / integration / sIntegration / SO3Integration (the
// constant-acceleration trajectory) against an independent fine RK4 of the joint ODEs in long double,
// against the exact exponential at constant velocity, and eulerJointIntegration against q ⊕ (alpha h +
// alphaD h²/2).
#include <functional>

#include <gtest/gtest.h>

#include <rbd/EulerIntegration.h>
#include <rbd/NumericalIntegration.h>

#include "TestModels.h"

namespace
{

using LD = long double;
using V3 = Eigen::Matrix<LD, 3, 1>;

/// q(h) of one joint by classical RK4 with N steps on the ODE of the joint (long double):
/// quat' = quat ⊗ [0; w(t)]/2, r' = R(quat) v(t) (Spherical, Free); θ' = w(t), p' = R2(θ) v(t) with
/// p = R2(θ) [x y] (Planar).
std::vector<LD> referenceStep(rbd::Joint::Type type, const std::vector<double> & q, const std::vector<double> & alpha,
                              const std::vector<double> & alphaD, LD h, int N)
{
  using State = Eigen::Matrix<LD, 7, 1>;
  auto at = [&](LD t, int k) { return LD(alpha[static_cast<std::size_t>(k)]) + LD(alphaD[static_cast<std::size_t>(k)]) * t; };
  State x = State::Zero();
  std::function<State(LD, const State &)> f;
  if(type == rbd::Joint::Planar)
  {
    const LD c = std::cos(LD(q[0])), s = std::sin(LD(q[0]));
    x << LD(q[0]), c * LD(q[1]) - s * LD(q[2]), s * LD(q[1]) + c * LD(q[2]), 0, 0, 0, 0;
    f = [&](LD t, const State & y) {
      State d = State::Zero();
      d(0) = at(t, 0);
      d(1) = std::cos(y(0)) * at(t, 1) - std::sin(y(0)) * at(t, 2);
      d(2) = std::sin(y(0)) * at(t, 1) + std::cos(y(0)) * at(t, 2);
      return d;
    };
  }
  else
  {
    for(int k = 0; k < (type == rbd::Joint::Free ? 7 : 4); ++k) x(k) = LD(q[static_cast<std::size_t>(k)]);
    f = [&](LD t, const State & y) {
      const Eigen::Quaternion<LD> quat(y(0), y(1), y(2), y(3));
      const Eigen::Quaternion<LD> d = quat * Eigen::Quaternion<LD>(0, at(t, 0), at(t, 1), at(t, 2));
      State out = State::Zero();
      out.head<4>() << d.w() / 2, d.x() / 2, d.y() / 2, d.z() / 2;
      if(type == rbd::Joint::Free) out.tail<3>() = quat.normalized().toRotationMatrix() * V3(at(t, 3), at(t, 4), at(t, 5));
      return out;
    };
  }
  const LD s = h / N;
  for(int k = 0; k < N; ++k)
  {
    const LD t = s * k;
    const State k1 = f(t, x), k2 = f(t + s / 2, x + s / 2 * k1), k3 = f(t + s / 2, x + s / 2 * k2), k4 = f(t + s, x + s * k3);
    x += s / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  if(type == rbd::Joint::Planar)
  {
    const LD c = std::cos(x(0)), sn = std::sin(x(0));
    return {x(0), c * x(1) + sn * x(2), -sn * x(1) + c * x(2)};
  }
  std::vector<LD> out(x.data(), x.data() + (type == rbd::Joint::Free ? 7 : 4));
  const LD n = Eigen::Matrix<LD, 4, 1>(out[0], out[1], out[2], out[3]).norm();
  for(int k = 0; k < 4; ++k) out[static_cast<std::size_t>(k)] /= n;
  return out;
}

double maxDiff(const std::vector<double> & a, const std::vector<LD> & b)
{
  double d = 0;
  for(std::size_t k = 0; k < a.size(); ++k) d = std::max(d, static_cast<double>(std::abs(LD(a[k]) - b[k])));
  return d;
}

TEST(NumericalIntegration, JointIntegrationFollowsTheConstantAccelerationTrajectory)
{
  rbdtest::Rng rng(91);
  for(auto type : {rbd::Joint::Spherical, rbd::Joint::Free, rbd::Joint::Planar})
    for(int n = 0; n < 6; ++n)
    {
      const rbd::Joint j(type, true, "j");
      rbd::MultiBody mb({rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "b")}, {j}, {-1}, {0}, {-1},
                        {sva::PTransformd::Identity()});
      rbd::MultiBodyConfig mbc(mb);
      rbdtest::randomState(rng, mb, mbc, 2.0, 3.0);
      const double h = rbdtest::uniform(rng, 0.05, 0.6);
      const std::vector<LD> ref = referenceStep(type, mbc.q[0], mbc.alpha[0], mbc.alphaD[0], h, 4000);
      std::vector<double> q = mbc.q[0];
      rbd::jointIntegration(type, mbc.alpha[0], mbc.alphaD[0], h, q, 1e-12);
      EXPECT_LT(maxDiff(q, ref), 1e-11) << rbd::jointTypeName(type) << " h = " << h;
      // the whole model: q as jointIntegration, alpha += alphaD h
      const auto alpha0 = mbc.alpha[0];
      rbd::sIntegration(mb, mbc, h, 1e-12);
      EXPECT_EQ(mbc.q[0], q);
      for(std::size_t c = 0; c < alpha0.size(); ++c) EXPECT_DOUBLE_EQ(mbc.alpha[0][c], alpha0[c] + mbc.alphaD[0][c] * h);
      if(type == rbd::Joint::Spherical)
      {
        const Eigen::Vector3d w(alpha0[0], alpha0[1], alpha0[2]), wD(mbc.alphaD[0][0], mbc.alphaD[0][1], mbc.alphaD[0][2]);
        const auto r = rbd::SO3Integration(Eigen::Quaterniond(1, 0, 0, 0), w, wD, h);
        const std::vector<LD> refRot = referenceStep(type, {1, 0, 0, 0}, alpha0, mbc.alphaD[0], h, 4000);
        EXPECT_FALSE(r.second);
        EXPECT_LT(maxDiff({r.first.w(), r.first.x(), r.first.y(), r.first.z()}, refRot), 1e-12);
      }
    }
}

// Constant velocity: the exact exponential (integrateConfiguration); vector joints: exact quadratic.
TEST(NumericalIntegration, ConstantVelocityIsTheExponentialAndVectorJointsAreExact)
{
  rbdtest::Rng rng(92);
  for(auto type : {rbd::Joint::Rev, rbd::Joint::Prism, rbd::Joint::Cylindrical, rbd::Joint::Spherical, rbd::Joint::Free,
                   rbd::Joint::Planar, rbd::Joint::Fixed})
  {
    const rbd::Joint j(type, rbdtest::randomUnit(rng), true, "j");
    rbd::MultiBody mb({rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "b")}, {j}, {-1}, {0}, {-1},
                      {sva::PTransformd::Identity()});
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    const double h = 0.3;
    std::vector<double> dq = mbc.alpha[0];
    for(double & x : dq) x *= h;
    const auto expected = rbd::integrateConfiguration(mb, mbc.q, std::vector<std::vector<double>>{dq});
    std::vector<double> q = mbc.q[0];
    rbd::jointIntegration(type, mbc.alpha[0], std::vector<double>(mbc.alpha[0].size(), 0.0), h, q, 1e-13);
    for(std::size_t k = 0; k < q.size(); ++k) EXPECT_NEAR(q[k], expected[0][k], 1e-12) << rbd::jointTypeName(type);
    if(type == rbd::Joint::Rev || type == rbd::Joint::Prism || type == rbd::Joint::Cylindrical)
    {
      q = mbc.q[0];
      rbd::jointIntegration(type, mbc.alpha[0], mbc.alphaD[0], h, q);
      for(std::size_t k = 0; k < q.size(); ++k)
        EXPECT_DOUBLE_EQ(q[k], mbc.q[0][k] + mbc.alpha[0][k] * h + mbc.alphaD[0][k] * h * h / 2);
    }
    // eulerJointIntegration: one exponential of alpha h + alphaD h²/2
    std::vector<double> w = mbc.alpha[0];
    for(std::size_t k = 0; k < w.size(); ++k) w[k] = w[k] * h + mbc.alphaD[0][k] * h * h / 2;
    const auto euler = rbd::integrateConfiguration(mb, mbc.q, std::vector<std::vector<double>>{w});
    q = mbc.q[0];
    rbd::eulerJointIntegration(type, mbc.alpha[0], mbc.alphaD[0], h, q);
    EXPECT_EQ(q, euler[0]);
  }
  rbd::MultiBody mb({rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "b")},
                    {rbd::Joint(rbd::Joint::Free, true, "j")}, {-1}, {0}, {-1}, {sva::PTransformd::Identity()});
  rbd::MultiBodyConfig bad(mb);
  bad.alphaD[0].pop_back();
  EXPECT_THROW(rbd::sIntegration(mb, bad, 0.1), std::domain_error);
}

} // namespace
