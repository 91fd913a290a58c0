// Mass ratios from 1e-6 to 1e4 kg in one robot, massless intermediate links (a URDF link without
// <inertial>), zero-mass leaves and inertias at the triangle-inequality limit: runtime double
// against long double, nothing NaN or Inf.
#include "StabilityUtils.h"

namespace
{

using stab::Bounds;
using stab::Errors;

/// Masses 1e4, 1e-6, 1e2, 1e-3, 1, 1e-6, 1e4, ... (log-spread over 10 decades, alternating).
double spreadMass(int k)
{
  static const double masses[] = {1e4, 1e-6, 1e2, 1e-3, 1.0, 1e-6, 1e4, 1e-2, 1e3, 1e-5, 10.0, 1e-6};
  return masses[k % 12];
}

TEST(MassRatios, ChainFromMicrogramsToTenTonnes)
{
  rbdtest::Rng rng(601);
  Errors worst;
  for(int m = 0; m < 5; ++m)
  {
    const auto g = stab::chainGraph(rng, 12, [](rbdtest::Rng & r, int k) {
      return rbdtest::randomInertia(r, spreadMass(k), spreadMass(k));
    }, m < 3 ? stab::JointFn(stab::randomRev) : stab::JointFn(stab::randomAnyJoint));
    const rbd::MultiBody mb = g.makeMultiBody("b0", m % 2 == 0 ? rbd::Joint::Fixed : rbd::Joint::Free);
    for(int s = 0; s < 10; ++s)
    {
      const Errors e = stab::compareRandom(rng, mb);
      // relErr is relative to the largest entry, dominated by the 1e4 kg bodies: the light
      // bodies' contributions are rounded at that scale, so the bound is the same c n eps as for
      // equal masses (c = 50, n = 12). FD: 10 n cond(H) eps. ABA may refuse (documented
      // runtime_error) only where H is numerically singular in double, cond(H) eps > 1e-3:
      // there I^A - U D^-1 U^T cancels 1e4 kg terms down to the 1e-6 kg ones.
      const bool singularInDouble = e.condH * stab::eps > 1e-3;
      EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 12 * stab::eps, 10 * 12, singularInDouble}));
      worst.max(e);
    }
  }
  stab::report("masses 1e-6 .. 1e4 kg", worst);
}

TEST(MassRatios, MasslessIntermediateLinks)
{
  // Every other link has no inertia (a URDF link without <inertial>), moved by a 1-dof joint;
  // the massive link after it by a joint of at most 5 dof, so that the two joints' 6 or fewer
  // motions are independent and H stays positive definite. (A massless link on a 6-dof joint
  // followed by any moving joint has more joint motions than its child has rigid-body motions:
  // H is singular, the generation policy's case.)
  rbdtest::Rng rng(602);
  Errors worst;
  for(int m = 0; m < 5; ++m)
  {
    const auto g = stab::chainGraph(rng, 15, [](rbdtest::Rng & r, int k) {
      return k % 2 == 1 ? stab::zeroInertia() : rbdtest::randomInertia(r);
    }, [](rbdtest::Rng & r, int k) {
      rbd::Joint j = stab::randomAnyJoint(r, k);
      while((k % 2 == 1 && j.dof() != 1) || j.dof() == 6) j = stab::randomAnyJoint(r, k);
      return j;
    });
    const rbd::MultiBody mb = g.makeMultiBody("b0", rbd::Joint::Free);
    for(int s = 0; s < 10; ++s)
    {
      const Errors e = stab::compareRandom(rng, mb);
      EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 15 * stab::eps, 10 * 15}));
      worst.max(e);
    }
  }
  stab::report("massless intermediate links", worst);
}

TEST(MassRatios, ZeroMassLeavesOnFixedJoints)
{
  // Zero-mass leaves (sensor/tool frames) on fixed joints at the end of every chain of a wide tree.
  rbdtest::Rng rng(603);
  rbd::MultiBodyGraph g = stab::wideTreeGraph(rng, 6, 3);
  for(int b = 1; b <= 18; b += 3)
  {
    const std::string leaf = "tip" + std::to_string(b + 2), jn = "fix" + std::to_string(b + 2);
    g.addBody(rbd::Body(stab::zeroInertia(), leaf));
    g.addJoint(rbd::Joint(rbd::Joint::Fixed, true, jn));
    g.linkBodies("b" + std::to_string(b + 2), rbdtest::randomTransform(rng), leaf, sva::PTransformd::Identity(), jn);
  }
  const rbd::MultiBody mb = g.makeMultiBody("b0", rbd::Joint::Free);
  Errors worst;
  for(int s = 0; s < 10; ++s)
  {
    const Errors e = stab::compareRandom(rng, mb);
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 25 * stab::eps, 10 * 25}));
    worst.max(e);
  }
  stab::report("zero-mass leaves (fixed)", worst);
}

TEST(MassRatios, ZeroMassLeafOnMovingJoint)
{
  // A revolute joint moving only a massless leaf: H has a zero row and column (singular), the
  // leaf's acceleration is undefined. Kinematics, ID, H and C stay exact and finite. The runtime's
  // ForwardDynamics (Cholesky, then pivoted LDLT on failure) returns finite accelerations whose
  // other joints equal those of the model without the leaf (in long double, 10 n cond eps);
  // ABA refuses with its documented std::runtime_error. Never NaN.
  rbdtest::Rng rng(604);
  const auto g = stab::chainGraph(rng, 6, [](rbdtest::Rng & r, int k) {
    return k == 5 ? stab::zeroInertia() : rbdtest::randomInertia(r);
  }, stab::randomRev);
  const rbd::MultiBody mb = g.makeMultiBody("b0", true);
  rbd::MultiBodyGraph reducedGraph = g;
  reducedGraph.removeJoint("b0", "j5");
  const rbd::MultiBodyTpl<stab::LD> reducedL = dyntest::castModel<stab::LD>(reducedGraph.makeMultiBody("b0", true));
  Errors worst;
  double worstReduced = 0;
  for(int s = 0; s < 10; ++s)
  {
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    const Errors e = stab::compare(mb, mbc, false);
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 6 * stab::eps, 1}));
    worst.max(e);
    dyntest::kinematics(mb, mbc);
    rbd::ForwardDynamics fd(mb);
    ASSERT_NO_THROW(fd.forwardDynamics(mb, mbc));
    const Eigen::VectorXd alphaD = rbd::dofToVector(mb, mbc.alphaD);
    ASSERT_TRUE(alphaD.allFinite()) << alphaD.transpose();
    // the reduced model (joints 1..4) in long double, same inputs
    rbd::MultiBodyConfigTpl<stab::LD> red(reducedL);
    for(int i = 0; i < reducedL.nrJoints(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      red.q[k] = {};
      for(double x : mbc.q[k]) red.q[k].push_back(x);
      red.alpha[k] = {};
      for(double x : mbc.alpha[k]) red.alpha[k].push_back(x);
      red.jointTorque[k] = {};
      for(double x : mbc.jointTorque[k]) red.jointTorque[k].push_back(x);
    }
    const stab::Outputs<stab::LD> l = stab::evaluate(reducedL, red);
    const double err = stab::normRel(alphaD.head(reducedL.nrDof()), l.fdCrba);
    EXPECT_LE(err, 10 * 5 * stab::conditionNumber(l.H) * stab::eps);
    worstReduced = std::max(worstReduced, err);
    rbd::ForwardDynamicsABA aba(mb);
    EXPECT_THROW(aba.forwardDynamics(mb, mbc), std::runtime_error);
  }
  stab::report("zero-mass leaf, moving joint", worst);
  std::printf("[ zero-mass leaf, moving joint ] FD of the other joints vs the model without the leaf: %.3g\n", worstReduced);
}

/// Principal moments (a, b, c) at the triangle limit a + b = c (up to `gap`), rotated, at an
/// offset centre of mass: rods (0, I, I), flat discs (I, I, 2I), near-flat plates.
sva::RBInertiad limitInertia(rbdtest::Rng & rng, int k, double gap)
{
  const double m = rbdtest::uniform(rng, 0.5, 2.0);
  const double a = k % 3 == 0 ? 0.0 : rbdtest::uniform(rng, 0.01, 0.1), b = rbdtest::uniform(rng, 0.01, 0.1);
  const Eigen::Vector3d d(a, b, (a + b) * (1 - gap));
  const Eigen::Matrix3d R = rbdtest::randomRotation(rng);
  const Eigen::Vector3d c = rbdtest::uniformVec<3>(rng, -0.2, 0.2);
  return sva::RBInertiad(m, m * c, sva::inertiaToOrigin(Eigen::Matrix3d(R * d.asDiagonal() * R.transpose()), m, c,
                                                        Eigen::Matrix3d::Identity()));
}

TEST(MassRatios, InertiasAtTheTriangleInequalityLimit)
{
  rbdtest::Rng rng(605);
  Errors worst;
  for(const double gap : {0.0, 1e-9, 1e-6})
  {
    const auto g = stab::chainGraph(rng, 12, [gap](rbdtest::Rng & r, int k) { return limitInertia(r, k, gap); },
                                    stab::randomAnyJoint);
    const rbd::MultiBody mb = g.makeMultiBody("b0", rbd::Joint::Free);
    for(int s = 0; s < 10; ++s)
    {
      const Errors e = stab::compareRandom(rng, mb);
      EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 12 * stab::eps, 10 * 12}));
      worst.max(e);
    }
  }
  stab::report("triangle-limit inertias", worst);
}

} // namespace
