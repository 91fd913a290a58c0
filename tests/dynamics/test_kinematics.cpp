// FK / FV / FA against closed forms (planar 2R arm, both directions), relative poses across
// differently rooted trees, and finite differences along q ⊕ alpha t on trees with every joint
// type in both directions and random trees (1-60 bodies); configuration integration against
// Eigen's matrix exponential.

#include <cstdio>

#include <unsupported/Eigen/MatrixFunctions>

#include "DynTestUtils.h"

namespace
{

using dyntest::VecX;

template<typename T>
class Kinematics : public ::testing::Test
{
};
TYPED_TEST_SUITE(Kinematics, dyntest::Scalars, );

// ---------------------------------------------------------------------------------------------
// Planar 2R arm, closed forms.
//
//   base --j1 (Rev z)--> l1 --j2 (Rev z, at (L1, 0, 0) of l1)--> l2 [end point at (L2, 0, 0)]
//
// End point: x = L1 c1 + L2 c12, y = L1 s1 + L2 s12 (c12 = cos(q1 + q2)).

constexpr double L1 = 0.7, L2 = 0.4;

template<typename T>
rbd::MultiBodyGraphTpl<T> arm2R()
{
  using V3 = sva::Vector3<T>;
  const sva::Matrix3<T> I = sva::Matrix3<T>::Identity() * T(0.01);
  rbd::MultiBodyGraphTpl<T> g;
  g.addBody(rbd::BodyTpl<T>(T(1), V3::Zero(), I, "base"));
  g.addBody(rbd::BodyTpl<T>(T(1), V3(T(L1 / 2), 0, 0), I, "l1"));
  g.addBody(rbd::BodyTpl<T>(T(1), V3(T(L2 / 2), 0, 0), I, "l2"));
  g.addJoint(rbd::JointTpl<T>(rbd::JointType::Rev, V3::UnitZ(), true, "j1"));
  g.addJoint(rbd::JointTpl<T>(rbd::JointType::Rev, V3::UnitZ(), true, "j2"));
  g.linkBodies("base", sva::PTransform<T>::Identity(), "l1", sva::PTransform<T>::Identity(), "j1");
  g.linkBodies("l1", sva::PTransform<T>(V3(T(L1), 0, 0)), "l2", sva::PTransform<T>::Identity(), "j2");
  return g;
}

TYPED_TEST(Kinematics, Planar2RArmClosedForm)
{
  using T = TypeParam;
  using V3 = sva::Vector3<T>;
  using std::cos;
  using std::sin;
  const double tolerance = dyntest::tol<T>(1e-14, 1e-17);
  const auto g = arm2R<T>();
  const auto mb = g.makeMultiBody("base", rbd::JointType::Fixed);
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  const auto j1 = static_cast<std::size_t>(mb.jointIndexByName("j1"));
  const auto j2 = static_cast<std::size_t>(mb.jointIndexByName("j2"));
  const auto e = static_cast<std::size_t>(mb.bodyIndexByName("l2"));
  rbdtest::Rng rng(11);
  for(int trial = 0; trial < 50; ++trial)
  {
    const T q1 = T(rbdtest::uniform(rng, -3, 3)), q2 = T(rbdtest::uniform(rng, -3, 3));
    const T d1 = T(rbdtest::uniform(rng, -2, 2)), d2 = T(rbdtest::uniform(rng, -2, 2));
    const T dd1 = T(rbdtest::uniform(rng, -2, 2)), dd2 = T(rbdtest::uniform(rng, -2, 2));
    mbc.q[j1] = {q1};
    mbc.q[j2] = {q2};
    mbc.alpha[j1] = {d1};
    mbc.alpha[j2] = {d2};
    mbc.alphaD[j1] = {dd1};
    mbc.alphaD[j2] = {dd2};
    dyntest::kinematics(mb, mbc);
    rbd::forwardAcceleration(mb, mbc);

    const T c1 = cos(q1), s1 = sin(q1), c12 = cos(q1 + q2), s12 = sin(q1 + q2), w = d1 + d2, wd = dd1 + dd2;
    const V3 pe(T(L2), 0, 0); // end point, l2 coordinates
    const sva::PTransform<T> & X = mbc.bodyPosW[e];
    const sva::Matrix3<T> R = X.rotation().transpose();
    // position and orientation
    const V3 p = R * pe + X.translation();
    EXPECT_MAT_NEAR(p, V3(T(L1) * c1 + T(L2) * c12, T(L1) * s1 + T(L2) * s12, 0), tolerance);
    EXPECT_MAT_NEAR(X.rotation(), sva::RotZ(q1 + q2), tolerance);
    // velocity of the end point: v_O + w x (R pe)
    const auto & vW = mbc.bodyVelW[e];
    const V3 v = vW.linear() + vW.angular().cross(R * pe);
    EXPECT_MAT_NEAR(vW.angular(), V3(0, 0, w), tolerance);
    EXPECT_MAT_NEAR(v, V3(-T(L1) * s1 * d1 - T(L2) * s12 * w, T(L1) * c1 * d1 + T(L2) * c12 * w, 0), tolerance);
    // classical acceleration of the end point (body coordinates):
    //   a_lin + wd x pe + w x (v_lin + w x pe), from the spatial acceleration and velocity
    const auto & aB = mbc.bodyAccB[e];
    const auto & vB = mbc.bodyVelB[e];
    const V3 accB = aB.linear() + aB.angular().cross(pe) + vB.angular().cross(vB.linear() + vB.angular().cross(pe));
    const V3 accExpected(-T(L1) * (c1 * d1 * d1 + s1 * dd1) - T(L2) * (c12 * w * w + s12 * wd),
                         T(L1) * (-s1 * d1 * d1 + c1 * dd1) + T(L2) * (-s12 * w * w + c12 * wd), 0);
    EXPECT_MAT_NEAR(V3(R * accB), accExpected, tolerance);
  }
}

// The same arm rooted at l2: j2 and j1 are traversed backward.
TYPED_TEST(Kinematics, Planar2RArmBackwardClosedForm)
{
  using T = TypeParam;
  using V3 = sva::Vector3<T>;
  using std::cos;
  using std::sin;
  const double tolerance = dyntest::tol<T>(1e-14, 1e-17);
  const auto g = arm2R<T>();
  const auto fwd = g.makeMultiBody("base", rbd::JointType::Fixed);
  const auto bwd = g.makeMultiBody("l2", rbd::JointType::Fixed);
  ASSERT_FALSE(bwd.joint(bwd.jointIndexByName("j1")).forward());
  ASSERT_FALSE(bwd.joint(bwd.jointIndexByName("j2")).forward());
  rbd::MultiBodyConfigTpl<T> cf(fwd), cb(bwd);
  rbdtest::Rng rng(12);
  for(int trial = 0; trial < 50; ++trial)
  {
    for(const char * jn : {"j1", "j2"})
    {
      const T q = T(rbdtest::uniform(rng, -3, 3)), a = T(rbdtest::uniform(rng, -2, 2));
      const T ad = T(rbdtest::uniform(rng, -2, 2));
      for(auto * c : {&cf, &cb})
      {
        const auto k = static_cast<std::size_t>((c == &cf ? fwd : bwd).jointIndexByName(jn));
        c->q[k] = {q};
        c->alpha[k] = {a};
        c->alphaD[k] = {ad};
      }
    }
    dyntest::kinematics(fwd, cf);
    rbd::forwardAcceleration(fwd, cf);
    dyntest::kinematics(bwd, cb);
    rbd::forwardAcceleration(bwd, cb);
    const T q1 = cf.q[static_cast<std::size_t>(fwd.jointIndexByName("j1"))][0];
    const T q2 = cf.q[static_cast<std::size_t>(fwd.jointIndexByName("j2"))][0];
    // base origin seen from l2 (the world of bwd): Rz(-(q1+q2)) (0 - L1 (c1, s1)) = (-L1 c2, L1 s2)
    const auto base = static_cast<std::size_t>(bwd.bodyIndexByName("base"));
    EXPECT_MAT_NEAR(cb.bodyPosW[base].translation(), V3(-T(L1) * cos(q2), T(L1) * sin(q2), 0), tolerance);
    EXPECT_MAT_NEAR(cb.bodyPosW[base].rotation(), sva::RotZ(-(q1 + q2)), tolerance);
    // relative motion reversed: v_base/l2 = -X_l2_base v_l2/base, same for accelerations
    const auto l2f = static_cast<std::size_t>(fwd.bodyIndexByName("l2"));
    const sva::PTransform<T> X_l2_base = cf.bodyPosW[l2f].inv();
    EXPECT_MAT_NEAR(cb.bodyVelB[base].vector(), (-(X_l2_base * cf.bodyVelB[l2f])).vector(), tolerance);
    EXPECT_MAT_NEAR(cb.bodyAccB[base].vector(), (-(X_l2_base * cf.bodyAccB[l2f])).vector(), tolerance);
  }
}

// ---------------------------------------------------------------------------------------------
// Relative poses between bodies do not depend on the root (every joint type, both directions).

TEST(KinematicsAllJoints, RelativePosesIndependentOfRoot)
{
  rbdtest::Rng rng(21);
  const auto models = dyntest::allJointsModels(rng);
  for(int trial = 0; trial < 10; ++trial)
  {
    // one random q per graph joint, shared by every tree
    rbd::MultiBodyConfig ref(models[0].mb);
    rbdtest::randomState(rng, models[0].mb, ref);
    std::vector<std::map<std::string, sva::PTransformd>> X_0_b(models.size());
    for(std::size_t m = 0; m < models.size(); ++m)
    {
      const auto & mb = models[m].mb;
      rbd::MultiBodyConfig mbc(mb);
      rbdtest::randomState(rng, mb, mbc);
      for(int i = 1; i < mb.nrJoints(); ++i)
      {
        const int iRef = models[0].mb.jointIndexByName(mb.joint(i).name());
        mbc.q[static_cast<std::size_t>(i)] = ref.q[static_cast<std::size_t>(iRef)];
      }
      rbd::forwardKinematics(mb, mbc);
      for(int i = 0; i < mb.nrBodies(); ++i)
      {
        // body frame of the graph: X_0_b = X_j_b X_0_j
        const std::string & name = mb.body(i).name();
        X_0_b[m][name] = models[m].X_j_b.at(name) * mbc.bodyPosW[static_cast<std::size_t>(i)];
      }
    }
    for(std::size_t m = 1; m < models.size(); ++m)
      for(const auto & a : X_0_b[0])
        for(const auto & b : X_0_b[0])
        {
          const sva::PTransformd X_a_b0 = b.second * a.second.inv();
          const sva::PTransformd X_a_bm = X_0_b[m].at(b.first) * X_0_b[m].at(a.first).inv();
          EXPECT_MAT_NEAR(X_a_bm.matrix(), X_a_b0.matrix(), 1e-12) << a.first << " -> " << b.first << ", tree " << m;
        }
  }
}

// ---------------------------------------------------------------------------------------------
// FV and FA against finite differences along the trajectory (q ⊕ alpha t, alpha + alphaD t).

struct FDErrors
{
  double vel = 0, acc = 0;
};

template<typename T>
FDErrors fvFaFiniteDifferences(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> mbc)
{
  using V3 = sva::Vector3<T>;
  const int n = mb.nrBodies();
  dyntest::kinematics(mb, mbc);
  rbd::forwardAcceleration(mb, mbc);
  const VecX<T> q = dyntest::qOf(mb, mbc), alpha = dyntest::dofOf(mb, mbc.alpha),
                alphaD = dyntest::dofOf(mb, mbc.alphaD);
  const T h = T(1e-3) / (T(1) + alpha.cwiseAbs().sum());
  // Stacked [E (9, column-major); r (3)] of every body along q ⊕ alpha t.
  auto poses = [&](T t) {
    rbd::MultiBodyConfigTpl<T> c = mbc;
    c.q = rbd::vectorToParam(mb, rbd::integrateConfiguration(mb, q, VecX<T>(alpha * t)));
    rbd::forwardKinematics(mb, c);
    VecX<T> out(12 * n);
    for(int i = 0; i < n; ++i)
    {
      const auto & X = c.bodyPosW[static_cast<std::size_t>(i)];
      out.template segment<9>(12 * i) = Eigen::Map<const Eigen::Matrix<T, 9, 1>>(X.rotation().data());
      out.template segment<3>(12 * i + 9) = X.translation();
    }
    return out;
  };
  // Stacked bodyVelB along (q ⊕ alpha t, alpha + alphaD t).
  auto velocities = [&](T t) {
    rbd::MultiBodyConfigTpl<T> c = mbc;
    c.q = rbd::vectorToParam(mb, rbd::integrateConfiguration(mb, q, VecX<T>(alpha * t)));
    c.alpha = rbd::vectorToDof(mb, VecX<T>(alpha + alphaD * t));
    dyntest::kinematics(mb, c);
    VecX<T> out(6 * n);
    for(int i = 0; i < n; ++i) out.template segment<6>(6 * i) = c.bodyVelB[static_cast<std::size_t>(i)].vector();
    return out;
  };
  const VecX<T> dPoses = dyntest::derivative<T>(poses, h);
  const VecX<T> dVel = dyntest::derivative<T>(velocities, h);
  FDErrors err;
  for(int i = 0; i < n; ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const sva::Matrix3<T> & E = mbc.bodyPosW[k].rotation();
    const sva::Matrix3<T> Ed = Eigen::Map<const sva::Matrix3<T>>(dPoses.data() + 12 * i);
    const V3 rd = dPoses.template segment<3>(12 * i + 9);
    // R = E^T, Rd R^T = w_world^  =>  w_world^ = Ed^T E
    const sva::Matrix3<T> W = Ed.transpose() * E;
    const V3 wW(T(0.5) * (W(2, 1) - W(1, 2)), T(0.5) * (W(0, 2) - W(2, 0)), T(0.5) * (W(1, 0) - W(0, 1)));
    const sva::MotionVec<T> velW(wW, rd), velB(E * wW, E * rd);
    err.vel = std::max(err.vel, rbdtest::relErr(mbc.bodyVelW[k].vector(), velW.vector()));
    err.vel = std::max(err.vel, rbdtest::relErr(mbc.bodyVelB[k].vector(), velB.vector()));
    // body-coordinate acceleration = d/dt bodyVelB (v x v = 0)
    err.acc = std::max(err.acc, rbdtest::relErr(mbc.bodyAccB[k].vector(), dVel.template segment<6>(6 * i)));
  }
  return err;
}

TYPED_TEST(Kinematics, AllJointTypesBothDirectionsFiniteDifferences)
{
  using T = TypeParam;
  rbdtest::Rng rng(31);
  FDErrors worst;
  for(int trial = 0; trial < 5; ++trial)
    for(const auto & model : dyntest::allJointsModels(rng))
    {
      const auto mb = dyntest::castModel<T>(model.mb);
      rbd::MultiBodyConfigTpl<T> mbc(mb);
      rbdtest::randomState<T>(rng, mb, mbc);
      const FDErrors e = fvFaFiniteDifferences(mb, mbc);
      worst.vel = std::max(worst.vel, e.vel);
      worst.acc = std::max(worst.acc, e.acc);
    }
  EXPECT_LE(worst.vel, dyntest::tol<T>(1e-9, 1e-12));
  EXPECT_LE(worst.acc, dyntest::tol<T>(1e-9, 1e-12));
  std::printf("[ info ] FV/FA vs finite differences, all joint types: vel %.2e acc %.2e\n", worst.vel, worst.acc);
}

TYPED_TEST(Kinematics, RandomTreesFiniteDifferences)
{
  using T = TypeParam;
  rbdtest::Rng rng(32);
  FDErrors worst;
  int backward = 0;
  for(int n : {1, 2, 3, 5, 8, 13, 21, 34, 60})
    for(int trial = 0; trial < 3; ++trial)
    {
      const auto mb = dyntest::castModel<T>(dyntest::randomModel(rng, n, 0.3));
      for(const auto & j : mb.joints()) backward += j.forward() ? 0 : 1;
      rbd::MultiBodyConfigTpl<T> mbc(mb);
      rbdtest::randomState<T>(rng, mb, mbc, 3.0, 1.0);
      const FDErrors e = fvFaFiniteDifferences(mb, mbc);
      worst.vel = std::max(worst.vel, e.vel);
      worst.acc = std::max(worst.acc, e.acc);
    }
  EXPECT_GT(backward, 20);
  EXPECT_LE(worst.vel, dyntest::tol<T>(1e-8, 1e-11));
  EXPECT_LE(worst.acc, dyntest::tol<T>(1e-8, 1e-11));
  std::printf("[ info ] FV/FA vs finite differences, random trees: vel %.2e acc %.2e\n", worst.vel, worst.acc);
}

// ---------------------------------------------------------------------------------------------
// Configuration integration.

// For a forward joint, X_j(q ⊕ dq) is X_j(q) followed by the constant body twist xi = S dq for a
// unit time: g(q ⊕ dq) = g(q) exp([xi]) with g = [E^T r; 0 1] (pose of the successor frame).
TYPED_TEST(Kinematics, IntegrateMatchesMatrixExponential)
{
  using T = TypeParam;
  using M4 = Eigen::Matrix<T, 4, 4>;
  rbdtest::Rng rng(41);
  auto g = [](const sva::PTransform<T> & X) {
    M4 m = M4::Identity();
    m.template topLeftCorner<3, 3>() = X.rotation().transpose();
    m.template topRightCorner<3, 1>() = X.translation();
    return m;
  };
  double worst = 0;
  for(auto type : {rbd::JointType::Rev, rbd::JointType::Prism, rbd::JointType::Cylindrical, rbd::JointType::Planar,
                   rbd::JointType::Spherical, rbd::JointType::Free})
    for(int trial = 0; trial < 20; ++trial)
    {
      rbd::MultiBodyGraph graph;
      graph.addBody(rbd::Body(rbdtest::randomInertia(rng), "b"));
      const rbd::Joint root(type, rbdtest::randomUnit(rng), true, "Root");
      const auto mb = dyntest::castModel<T>(graph.makeMultiBody("b", root));
      rbd::MultiBodyConfigTpl<T> mbc(mb);
      rbdtest::randomState<T>(rng, mb, mbc);
      // include tiny and large rotations (series branches and the generic formulas)
      const double scale = trial % 3 == 0 ? 1e-4 : (trial % 3 == 1 ? 1e-2 : 1.5);
      const VecX<T> dq = dyntest::dofOf(mb, mbc.alpha) * T(scale);
      const VecX<T> q = dyntest::qOf(mb, mbc);
      const auto qNew = rbd::vectorToParam(mb, rbd::integrateConfiguration(mb, q, dq));
      const auto & joint = mb.joint(0);
      const Eigen::Matrix<T, 6, 1> xi = joint.motionSubspace() * dq;
      M4 twist = M4::Zero();
      twist.template topLeftCorner<3, 3>() = sva::vector3ToCrossMatrix(sva::Vector3<T>(xi.template head<3>()));
      twist.template topRightCorner<3, 1>() = xi.template tail<3>();
      const M4 expected = g(joint.pose(mbc.q[0])) * twist.exp();
      const double e = rbdtest::relErr(g(joint.pose(qNew[0])), expected);
      worst = std::max(worst, e);
      EXPECT_LE(e, dyntest::tol<T>(1e-14, 1e-17)) << rbd::jointTypeName(type) << " scale " << scale;
      // quaternions stay unit
      if(type == rbd::JointType::Spherical || type == rbd::JointType::Free)
      {
        using std::abs;
        const T norm2 = Eigen::Matrix<T, 4, 1>(qNew[0][0], qNew[0][1], qNew[0][2], qNew[0][3]).squaredNorm();
        EXPECT_LE(static_cast<double>(abs(norm2 - T(1))), dyntest::tol<T>(1e-15, 1e-18));
      }
    }
  std::printf("[ info ] integrateConfiguration vs matrix exponential: %.2e\n", worst);
}

TYPED_TEST(Kinematics, ConfigurationDerivativeMatchesIntegrate)
{
  using T = TypeParam;
  rbdtest::Rng rng(42);
  for(const auto & model : dyntest::allJointsModels(rng))
  {
    const auto mb = dyntest::castModel<T>(model.mb);
    rbd::MultiBodyConfigTpl<T> mbc(mb);
    rbdtest::randomState<T>(rng, mb, mbc);
    const VecX<T> q = dyntest::qOf(mb, mbc), alpha = dyntest::dofOf(mb, mbc.alpha);
    const VecX<T> fd = dyntest::derivative<T>(
        [&](T t) { return VecX<T>(rbd::integrateConfiguration(mb, q, VecX<T>(alpha * t))); }, T(1e-3));
    EXPECT_MAT_NEAR(rbd::configurationDerivative(mb, q, alpha), fd, dyntest::tol<T>(1e-11, 1e-13));
  }
}

// Euler with the alphaD step^2/2 term is exact for constant alphaD on vector joints, and for a
// constant body twist (alphaD = 0) on Free joints (the exponential composes exactly).
TYPED_TEST(Kinematics, EulerIntegrationExactCases)
{
  using T = TypeParam;
  rbdtest::Rng rng(43);
  rbd::MultiBodyGraph graph;
  for(const char * b : {"a", "b", "c", "d"}) graph.addBody(rbd::Body(rbdtest::randomInertia(rng), b));
  graph.addJoint(rbd::Joint(rbd::Joint::Prism, rbdtest::randomUnit(rng), true, "prism"));
  graph.addJoint(rbd::Joint(rbd::Joint::Cylindrical, rbdtest::randomUnit(rng), true, "cyl"));
  graph.addJoint(rbd::Joint(rbd::Joint::Rev, rbdtest::randomUnit(rng), false, "rev"));
  {
    const sva::PTransformd X1 = rbdtest::randomTransform(rng), X2 = rbdtest::randomTransform(rng);
    graph.linkBodies("a", X1, "b", X2, "prism");
  }
  {
    const sva::PTransformd X1 = rbdtest::randomTransform(rng), X2 = rbdtest::randomTransform(rng);
    graph.linkBodies("b", X1, "c", X2, "cyl");
  }
  {
    const sva::PTransformd X1 = rbdtest::randomTransform(rng), X2 = rbdtest::randomTransform(rng);
    graph.linkBodies("c", X1, "d", X2, "rev");
  }
  const auto mb = dyntest::castModel<T>(graph.makeMultiBody("a", rbd::Joint::Free));
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  rbdtest::randomState<T>(rng, mb, mbc);
  mbc.alphaD[0] = mb.joint(0).zeroDof();
  const rbd::MultiBodyConfigTpl<T> start = mbc;
  const int steps = 100;
  const T dt = T(0.01), total = dt * T(steps);
  for(int s = 0; s < steps; ++s) rbd::eulerIntegration(mb, mbc, dt);
  // root: q ⊕ (alpha total); vector joints: q + alpha t + alphaD t^2 / 2; alpha + alphaD t
  const VecX<T> q0 = dyntest::qOf(mb, start), a0 = dyntest::dofOf(mb, start.alpha);
  const VecX<T> ad = dyntest::dofOf(mb, start.alphaD);
  VecX<T> expectedQ = q0;
  expectedQ.tail(mb.nrParams() - 7) += (a0 * total + ad * total * total / T(2)).tail(mb.nrDof() - 6);
  VecX<T> rootOnly = VecX<T>::Zero(mb.nrDof());
  rootOnly.template head<6>() = a0.template head<6>() * total;
  expectedQ.template head<7>() = rbd::integrateConfiguration(mb, q0, rootOnly).template head<7>();
  EXPECT_MAT_NEAR(dyntest::qOf(mb, mbc), expectedQ, dyntest::tol<T>(1e-12, 1e-15));
  EXPECT_MAT_NEAR(dyntest::dofOf(mb, mbc.alpha), VecX<T>(a0 + ad * total), dyntest::tol<T>(1e-13, 1e-16));
}

TEST(KinematicsChecked, EulerIntegrationThrowsOnWrongSizes)
{
  rbdtest::Rng rng(44);
  const auto mb = dyntest::randomModel(rng, 5, 0.3, true);
  rbd::MultiBodyConfig mbc(mb);
  EXPECT_NO_THROW(rbd::sEulerIntegration(mb, mbc, 0.01));
  auto bad = mbc;
  bad.q[0].pop_back();
  EXPECT_THROW(rbd::sEulerIntegration(mb, bad, 0.01), std::domain_error);
  bad = mbc;
  bad.alphaD.pop_back();
  EXPECT_THROW(rbd::sEulerIntegration(mb, bad, 0.01), std::domain_error);
  bad = mbc;
  bad.alpha[0].push_back(0);
  EXPECT_THROW(rbd::sEulerIntegration(mb, bad, 0.01), std::domain_error);
}

} // namespace
