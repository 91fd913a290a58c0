// Simulation invariants with a classical RK4 written here: conservation of the total spatial
// momentum (and energy) of a free-floating tree in zero gravity, and the energy of a conservative
// double pendulum.
//
// RK4 runs on the embedded state (q in R^nrParams, alpha in R^nrDof) with
// dq/dt = configurationDerivative(q, alpha) (quaternion kinematics) and dalpha/dt = ABA; this
// is a genuine 4th-order method (stages built with q ⊕ dq on the group would only be 2nd order
// without the dexp^-1 corrections). Quaternions are renormalised after each step.

#include <cstdio>

#include "DynTestUtils.h"

namespace
{

using dyntest::VecX;

template<typename T>
class Simulation : public ::testing::Test
{
};
TYPED_TEST_SUITE(Simulation, dyntest::Scalars, );

template<typename T>
class Rk4
{
public:
  Rk4(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc) : mb_(mb), mbc_(mbc), aba_(mb) {}

  /// One step of size h from (q, alpha).
  void step(VecX<T> & q, VecX<T> & alpha, T h)
  {
    VecX<T> k1q, k1a, k2q, k2a, k3q, k3a, k4q, k4a;
    derivative(q, alpha, k1q, k1a);
    derivative(q + h / T(2) * k1q, alpha + h / T(2) * k1a, k2q, k2a);
    derivative(q + h / T(2) * k2q, alpha + h / T(2) * k2a, k3q, k3a);
    derivative(q + h * k3q, alpha + h * k3a, k4q, k4a);
    q += h / T(6) * (k1q + T(2) * k2q + T(2) * k3q + k4q);
    alpha += h / T(6) * (k1a + T(2) * k2a + T(2) * k3a + k4a);
    for(int i = 0; i < mb_.nrJoints(); ++i)
    {
      const auto t = mb_.joint(i).type();
      if(t == rbd::JointType::Spherical || t == rbd::JointType::Free) q.segment(mb_.jointPosInParam(i), 4).normalize();
    }
  }

  /// Configuration at (q, alpha) with FK and FV run (for energies and momentum).
  const rbd::MultiBodyConfigTpl<T> & at(const VecX<T> & q, const VecX<T> & alpha)
  {
    mbc_.q = rbd::vectorToParam(mb_, q);
    mbc_.alpha = rbd::vectorToDof(mb_, alpha);
    dyntest::kinematics(mb_, mbc_);
    return mbc_;
  }

private:
  void derivative(const VecX<T> & q, const VecX<T> & alpha, VecX<T> & qd, VecX<T> & alphaD)
  {
    at(q, alpha);
    aba_.forwardDynamics(mb_, mbc_);
    qd = rbd::configurationDerivative(mb_, q, alpha);
    alphaD = dyntest::dofOf(mb_, mbc_.alphaD);
  }

  const rbd::MultiBodyTpl<T> & mb_;
  rbd::MultiBodyConfigTpl<T> mbc_;
  rbd::ForwardDynamicsABATpl<T> aba_;
};

TYPED_TEST(Simulation, FreeFloatingTreeConservesMomentumAndEnergy)
{
  using T = TypeParam;
  rbdtest::Rng rng(81);
  double worstMomentum = 0, worstEnergy = 0;
  for(int trial = 0; trial < 3; ++trial)
  {
    const auto mb = dyntest::castModel<T>(dyntest::randomModel(rng, 8, 0.3, true));
    rbd::MultiBodyConfigTpl<T> mbc(mb);
    rbdtest::randomState<T>(rng, mb, mbc, 3.0, 1.0);
    mbc.gravity.setZero();
    for(auto & tau : mbc.jointTorque) std::fill(tau.begin(), tau.end(), T(0));
    Rk4<T> rk4(mb, mbc);
    VecX<T> q = dyntest::qOf(mb, mbc), alpha = dyntest::dofOf(mb, mbc.alpha);
    const Eigen::Matrix<T, 6, 1> h0 = dyntest::worldMomentum(mb, rk4.at(q, alpha));
    const T e0 = dyntest::kineticEnergy(mb, rk4.at(q, alpha));
    const T dt = T(5e-4);
    for(int s = 0; s < 2000; ++s) // 1 s
    {
      rk4.step(q, alpha, dt);
      const auto & c = rk4.at(q, alpha);
      worstMomentum = std::max(worstMomentum, rbdtest::relErr(dyntest::worldMomentum(mb, c), h0));
      worstEnergy = std::max(worstEnergy, rbdtest::relErr(VecX<T>::Constant(1, dyntest::kineticEnergy(mb, c)),
                                                          VecX<T>::Constant(1, e0)));
    }
  }
  EXPECT_LE(worstMomentum, 1e-8);
  EXPECT_LE(worstEnergy, 1e-8);
  std::printf("[ info ] free-floating tree, RK4 dt = 5e-4 over 1 s: momentum %.2e, energy %.2e\n", worstMomentum,
              worstEnergy);
}

TYPED_TEST(Simulation, DoublePendulumEnergyDrift)
{
  using T = TypeParam;
  // robots/double_pendulum.urdf parameters (see test_pendulum.cpp), rotated 1 rad and released
  using V3 = sva::Vector3<T>;
  rbd::MultiBodyGraphTpl<T> g;
  auto link = [](const char * name, double m, double lc, double Ic) {
    const V3 c(0, 0, T(-lc));
    return rbd::BodyTpl<T>(T(m), c,
                           sva::inertiaToOrigin<T>(sva::Matrix3<T>::Identity() * T(Ic), T(m), c,
                                                   sva::Matrix3<T>::Identity()),
                           name);
  };
  g.addBody(rbd::BodyTpl<T>(T(0), V3::Zero(), sva::Matrix3<T>::Zero(), "base"));
  g.addBody(link("link1", 1.0, 1.0, 4e-5));
  g.addBody(link("link2", 0.7, 0.8, 2.8e-5));
  g.addJoint(rbd::JointTpl<T>(rbd::JointType::Rev, V3::UnitY(), true, "joint1"));
  g.addJoint(rbd::JointTpl<T>(rbd::JointType::Rev, V3::UnitY(), true, "joint2"));
  g.linkBodies("base", sva::PTransform<T>::Identity(), "link1", sva::PTransform<T>::Identity(), "joint1");
  g.linkBodies("link1", sva::PTransform<T>(V3(0, 0, -1)), "link2", sva::PTransform<T>::Identity(), "joint2");
  const auto mb = g.makeMultiBody("base", rbd::JointType::Fixed);
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  Rk4<T> rk4(mb, mbc);
  VecX<T> q(2), alpha(2);
  q << T(1.0), T(-0.5);
  alpha << T(0.5), T(1.0);
  auto energy = [&](const rbd::MultiBodyConfigTpl<T> & c) {
    return dyntest::kineticEnergy(mb, c) + dyntest::potentialEnergy(mb, c);
  };
  const T e0 = energy(rk4.at(q, alpha));
  double drift = 0;
  for(int s = 0; s < 10000; ++s) // 10 s
  {
    rk4.step(q, alpha, T(1e-3));
    using std::abs;
    drift = std::max(drift, static_cast<double>(abs(energy(rk4.at(q, alpha)) - e0)));
  }
  // |E0| ~ 10 J
  EXPECT_LE(drift, 1e-8);
  std::printf("[ info ] double pendulum, RK4 dt = 1e-3 over 10 s: max |E - E0| = %.2e J (E0 = %.3f J)\n", drift,
              static_cast<double>(e0));
}

} // namespace
