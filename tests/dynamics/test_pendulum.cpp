// Single and double pendulum: ID, CRBA (H, C), FD and ABA against the textbook Lagrange
// equations. Parameters are those of robots/pendulum.urdf and robots/double_pendulum.urdf
// (built here with MultiBodyGraph, no URDF loader):
//
//   base --joint1 (Rev y)--> link1 --joint2 (Rev y, at (0, 0, -L1))--> link2
//   link1: m1 = 1,   CoM (0, 0, -LC1 = -1),   I_c = 4e-5 1
//   link2: m2 = 0.7, CoM (0, 0, -LC2 = -0.8), I_c = 2.8e-5 1      (q = 0: hanging down)
//
//   H11 = I1 + I2 + m1 LC1² + m2 (L1² + LC2² + 2 L1 LC2 c2),  H12 = I2 + m2 (LC2² + L1 LC2 c2),
//   H22 = I2 + m2 LC2²
//   C1 = -m2 L1 LC2 s2 (2 q̇1 q̇2 + q̇2²) + (m1 LC1 + m2 L1) g s1 + m2 LC2 g s12
//   C2 =  m2 L1 LC2 s2 q̇1² + m2 LC2 g s12

#include "DynTestUtils.h"

namespace
{

using dyntest::VecX;

constexpr double G = 9.81, M1 = 1.0, LC1 = 1.0, I1 = 4e-5, L1 = 1.0, M2 = 0.7, LC2 = 0.8, I2 = 2.8e-5;

template<typename T>
rbd::BodyTpl<T> link(const char * name, double m, double lc, double Ic)
{
  const sva::Vector3<T> c(0, 0, T(-lc));
  const sva::Matrix3<T> I = sva::inertiaToOrigin<T>(sva::Matrix3<T>::Identity() * T(Ic), T(m), c,
                                                    sva::Matrix3<T>::Identity());
  return rbd::BodyTpl<T>(T(m), c, I, name);
}

/// Single (nLinks = 1) or double (nLinks = 2) pendulum.
template<typename T>
rbd::MultiBodyTpl<T> pendulum(int nLinks)
{
  using V3 = sva::Vector3<T>;
  rbd::MultiBodyGraphTpl<T> g;
  g.addBody(rbd::BodyTpl<T>(T(0), V3::Zero(), sva::Matrix3<T>::Zero(), "base"));
  g.addBody(link<T>("link1", M1, LC1, I1));
  g.addJoint(rbd::JointTpl<T>(rbd::JointType::Rev, V3::UnitY(), true, "joint1"));
  g.linkBodies("base", sva::PTransform<T>::Identity(), "link1", sva::PTransform<T>::Identity(), "joint1");
  if(nLinks == 2)
  {
    g.addBody(link<T>("link2", M2, LC2, I2));
    g.addJoint(rbd::JointTpl<T>(rbd::JointType::Rev, V3::UnitY(), true, "joint2"));
    g.linkBodies("link1", sva::PTransform<T>(V3(0, 0, T(-L1))), "link2", sva::PTransform<T>::Identity(), "joint2");
  }
  return g.makeMultiBody("base", rbd::JointType::Fixed);
}

template<typename T>
class Pendulum : public ::testing::Test
{
};
TYPED_TEST_SUITE(Pendulum, dyntest::Scalars, );

/// Run ID, CRBA and both forward dynamics on (q, qd, qdd) and compare with H, C and tau.
template<typename T>
void checkAgainst(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> & mbc, const dyntest::MatX<T> & H,
                  const VecX<T> & C, const VecX<T> & qdd, double tolerance)
{
  const VecX<T> tau = H * qdd + C;
  dyntest::kinematics(mb, mbc);
  mbc.alphaD = rbd::vectorToDof(mb, qdd);
  rbd::InverseDynamicsTpl<T> id(mb);
  id.inverseDynamics(mb, mbc);
  EXPECT_MAT_NEAR(dyntest::dofOf(mb, mbc.jointTorque), tau, tolerance);

  rbd::ForwardDynamicsTpl<T> fd(mb);
  mbc.jointTorque = rbd::vectorToDof(mb, tau);
  fd.forwardDynamics(mb, mbc);
  EXPECT_MAT_NEAR(fd.H(), H, tolerance);
  EXPECT_MAT_NEAR(fd.C(), C, tolerance);
  EXPECT_MAT_NEAR(dyntest::dofOf(mb, mbc.alphaD), qdd, tolerance);

  rbd::ForwardDynamicsABATpl<T> aba(mb);
  mbc.alphaD = rbd::vectorToDof(mb, VecX<T>::Zero(mb.nrDof()));
  aba.forwardDynamics(mb, mbc);
  EXPECT_MAT_NEAR(dyntest::dofOf(mb, mbc.alphaD), qdd, tolerance);
}

TYPED_TEST(Pendulum, SinglePendulumClosedForm)
{
  using T = TypeParam;
  using std::cos;
  using std::sin;
  const auto mb = pendulum<T>(1);
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  const auto j = static_cast<std::size_t>(mb.jointIndexByName("joint1"));
  const auto b = static_cast<std::size_t>(mb.bodyIndexByName("link1"));
  rbdtest::Rng rng(51);
  for(int trial = 0; trial < 50; ++trial)
  {
    const T q = T(rbdtest::uniform(rng, -3.2, 3.2)), qd = T(rbdtest::uniform(rng, -3, 3));
    const T qdd = T(rbdtest::uniform(rng, -3, 3)), F = T(rbdtest::uniform(rng, -5, 5));
    mbc.q[j] = {q};
    mbc.alpha[j] = {qd};
    // horizontal force F along +x at the CoM p = (-LC1 s, 0, -LC1 c): generalised force -LC1 F c
    const sva::Vector3<T> p(-T(LC1) * sin(q), 0, -T(LC1) * cos(q)), f(F, 0, 0);
    mbc.force[b] = sva::ForceVec<T>(p.cross(f), f);
    dyntest::MatX<T> H(1, 1);
    H(0, 0) = T(I1) + T(M1) * T(LC1) * T(LC1);
    VecX<T> C(1);
    C(0) = T(M1) * T(G) * T(LC1) * sin(q) + T(LC1) * F * cos(q);
    VecX<T> acc(1);
    acc(0) = qdd;
    checkAgainst(mb, mbc, H, C, acc, dyntest::tol<T>(1e-14, 1e-17));
  }
}

TYPED_TEST(Pendulum, DoublePendulumClosedForm)
{
  using T = TypeParam;
  using std::cos;
  using std::sin;
  const auto mb = pendulum<T>(2);
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  const auto j1 = static_cast<std::size_t>(mb.jointIndexByName("joint1"));
  const auto j2 = static_cast<std::size_t>(mb.jointIndexByName("joint2"));
  rbdtest::Rng rng(52);
  for(int trial = 0; trial < 50; ++trial)
  {
    const T q1 = T(rbdtest::uniform(rng, -3.2, 3.2)), q2 = T(rbdtest::uniform(rng, -3.2, 3.2));
    const T d1 = T(rbdtest::uniform(rng, -3, 3)), d2 = T(rbdtest::uniform(rng, -3, 3));
    const T g = trial % 2 == 0 ? T(G) : T(0);
    mbc.gravity = sva::Vector3<T>(0, 0, g);
    mbc.q[j1] = {q1};
    mbc.q[j2] = {q2};
    mbc.alpha[j1] = {d1};
    mbc.alpha[j2] = {d2};
    const T c2 = cos(q2), s1 = sin(q1), s2 = sin(q2), s12 = sin(q1 + q2);
    const T m1 = T(M1), m2 = T(M2), lc1 = T(LC1), lc2 = T(LC2), l1 = T(L1);
    dyntest::MatX<T> H(2, 2);
    H(0, 0) = T(I1) + T(I2) + m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + T(2) * l1 * lc2 * c2);
    H(0, 1) = H(1, 0) = T(I2) + m2 * (lc2 * lc2 + l1 * lc2 * c2);
    H(1, 1) = T(I2) + m2 * lc2 * lc2;
    VecX<T> C(2);
    C(0) = -m2 * l1 * lc2 * s2 * (T(2) * d1 * d2 + d2 * d2) + (m1 * lc1 + m2 * l1) * g * s1 + m2 * lc2 * g * s12;
    C(1) = m2 * l1 * lc2 * s2 * d1 * d1 + m2 * lc2 * g * s12;
    VecX<T> qdd(2);
    qdd << T(rbdtest::uniform(rng, -3, 3)), T(rbdtest::uniform(rng, -3, 3));
    checkAgainst(mb, mbc, H, C, qdd, dyntest::tol<T>(1e-13, 1e-16));
  }
}

} // namespace
