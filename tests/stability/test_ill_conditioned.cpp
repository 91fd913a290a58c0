// Ill-conditioned mass matrices (cond(H) >= 1e10): forward dynamics in double against long double,
// by both routes (CRBA + Cholesky, ABA), and ABA against CRBA.
//
// Bound: H x = b solved by a backward-stable method has a relative forward error
// <= c(n) cond(H) eps (Higham, Accuracy and Stability, Thm 7.2 with Cholesky's backward error
// c(n) = O(n)); H itself carries a relative error of a few eps from the CRBA recursion, which
// enters the same way. We take c(n) = 10 n, and require cond(H) >= 1e10 so that the cases are
// genuinely ill-conditioned (checked in long double).
#include "StabilityUtils.h"

namespace
{

using stab::Errors;

/// A chain whose masses fall by `ratio` per link from 1e4 kg, with the given joint maker.
rbd::MultiBody fallingMassChain(rbdtest::Rng & rng, int n, double ratio, const stab::JointFn & joint)
{
  const auto g = stab::chainGraph(rng, n, [ratio](rbdtest::Rng & r, int k) {
    const double m = 1e4 * std::pow(ratio, k);
    return rbdtest::randomInertia(r, m, m);
  }, joint);
  return g.makeMultiBody("b0", rbd::Joint::Free);
}

/// Revolute joints whose axes are almost parallel (within `spread` rad of z).
stab::JointFn nearlyParallelAxes(double spread)
{
  return [spread](rbdtest::Rng & rng, int k) {
    const Eigen::Vector2d xy = spread * rbdtest::uniformVec<2>(rng, -1, 1);
    const Eigen::Vector3d a(xy[0], xy[1], 1);
    return rbd::Joint(rbd::Joint::Rev, a.normalized(), true, "j" + std::to_string(k));
  };
}

void expectIllConditionedFdBounded(const rbd::MultiBody & mb, rbdtest::Rng & rng, const char * what)
{
  Errors worst;
  double worstFactor = 0; // max error / (cond eps)
  for(int s = 0; s < 10; ++s)
  {
    const Errors e = stab::compareRandom(rng, mb);
    ASSERT_TRUE(e.finite) << e;
    EXPECT_FALSE(e.abaThrew) << e;
    EXPECT_GE(e.condH, 1e10) << "not ill-conditioned: " << e;
    const double bound = 10.0 * mb.nrDof() * e.condH * stab::eps;
    EXPECT_LE(e.fdCrba, bound) << e;
    EXPECT_LE(e.fdAba, bound) << e;
    EXPECT_LE(e.abaVsCrba, bound) << e;
    // H, C, torques themselves are not ill-conditioned: the chain bound c n eps (c = 50).
    EXPECT_LE(e.kinematicsAndDynamics(), 50 * mb.nrBodies() * stab::eps) << e;
    worstFactor = std::max(worstFactor, std::max({e.fdCrba, e.fdAba, e.abaVsCrba}) / (e.condH * stab::eps));
    worst.max(e);
  }
  stab::report(what, worst);
  std::printf("[ %-28s ] worst FD error / (cond(H) eps) = %.3g (bound %d)\n", what, worstFactor, 10 * mb.nrDof());
}

TEST(IllConditioned, MassesFallingOverTenDecades)
{
  rbdtest::Rng rng(901);
  // 1e4 kg down to 1e-6 kg over 6 links (ratio 1e-2 per link).
  expectIllConditionedFdBounded(fallingMassChain(rng, 6, 1e-2, stab::randomRev), rng, "masses 1e4 -> 1e-6 kg");
}

TEST(IllConditioned, NearlyParallelCoLocatedAxes)
{
  // A massless link between two revolute joints at the same point whose axes differ by ~1e-5
  // rad: the massive link beyond gets two nearly equal motion subspaces, the columns of H are
  // nearly dependent (cond ~ 1/spread^2 ~ 1e10), then an ordinary third joint. Unlike graded
  // masses (which Cholesky solves at full accuracy whatever cond(H)), this is genuine
  // ill-conditioning: the FD error really grows like cond(H) eps.
  rbdtest::Rng rng(902);
  rbd::MultiBodyGraph g;
  for(int k = 0; k <= 3; ++k)
    g.addBody(rbd::Body(k == 1 ? stab::zeroInertia() : rbdtest::randomInertia(rng), "b" + std::to_string(k)));
  const stab::JointFn nearZ = nearlyParallelAxes(1e-5);
  for(int k = 1; k <= 3; ++k)
  {
    const rbd::Joint j = k < 3 ? nearZ(rng, k) : stab::randomRev(rng, k);
    g.addJoint(j);
    g.linkBodies("b" + std::to_string(k - 1), k < 3 ? sva::PTransformd::Identity() : rbdtest::randomTransform(rng),
                 "b" + std::to_string(k), sva::PTransformd::Identity(), j.name());
  }
  expectIllConditionedFdBounded(g.makeMultiBody("b0", true), rng, "nearly parallel axes");
}

TEST(IllConditioned, LightTipOnHeavyArmWithAllJointTypes)
{
  rbdtest::Rng rng(903);
  expectIllConditionedFdBounded(fallingMassChain(rng, 8, 1e-2, stab::randomAnyJoint), rng, "falling masses, all types");
}

} // namespace
