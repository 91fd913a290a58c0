// Bodies far from the origin (10-1000 m), joint values up to |q| = 1e4 rad, velocities of 1e3
// rad/s, non-normalised and near-antipodal quaternions on free and spherical joints: runtime
// double against long double, nothing NaN or Inf.
#include "StabilityUtils.h"

namespace
{

using stab::Bounds;
using stab::Errors;

rbd::MultiBody anyChain(rbdtest::Rng & rng, int n, double maxOffset, const sva::PTransformd & X_0_j0)
{
  const auto g = stab::chainGraph(rng, n, [](rbdtest::Rng & r, int) { return rbdtest::randomInertia(r); },
                                  stab::randomAnyJoint, maxOffset);
  return g.makeMultiBody("b0", rbd::Joint::Free, X_0_j0);
}

TEST(ExtremeStates, BodiesFarFromTheOrigin)
{
  rbdtest::Rng rng(701);
  Errors worst;
  for(const double offset : {10.0, 100.0, 1000.0})
  {
    // The robot's base 'offset' m away, its links 'offset'/10 m apart.
    const Eigen::Matrix3d E_0_j0 = rbdtest::randomRotation(rng);
    const sva::PTransformd X_0_j0(E_0_j0, offset * rbdtest::randomUnit(rng));
    const rbd::MultiBody mb = anyChain(rng, 10, offset / 10, X_0_j0);
    for(int s = 0; s < 10; ++s)
    {
      rbd::MultiBodyConfig mbc(mb);
      rbdtest::randomState(rng, mb, mbc);
      // The free root joint puts the base at the offset too.
      for(int c = 4; c < 7; ++c) mbc.q[0][static_cast<std::size_t>(c)] = offset * rbdtest::uniform(rng, -1, 1);
      const Errors e = stab::compare(mb, mbc);
      // relErr normalises by the largest entry (positions ~offset, torques ~offset^2 m g): the
      // chain bound c n eps with c = 50, n = 10. FD: H holds offset^2 m terms next to O(1)
      // rotational terms, so cond(H) grows like offset^2 and the cond eps bound covers it.
      EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 10 * stab::eps, 10 * 10}));
      worst.max(e);
    }
  }
  stab::report("offsets 10 .. 1000 m", worst);
}

TEST(ExtremeStates, LargeJointValues)
{
  rbdtest::Rng rng(702);
  Errors worst;
  const rbd::MultiBody mb = anyChain(rng, 12, 0.5, sva::PTransformd::Identity());
  for(int s = 0; s < 20; ++s)
  {
    // |q| up to 1e4 (rad for angles; prismatic/planar translations are then 1e4 m too). The
    // double q is exact in long double, so the reference sees the same input; sin/cos of 1e4 are
    // correctly reduced by libm in both.
    const Errors e = stab::compareRandom(rng, mb, true, 1e4, 2.0);
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 12 * stab::eps, 10 * 12}));
    worst.max(e);
  }
  stab::report("|q| up to 1e4", worst);
}

TEST(ExtremeStates, HighVelocities)
{
  rbdtest::Rng rng(703);
  Errors worst;
  const rbd::MultiBody mb = anyChain(rng, 12, 0.5, sva::PTransformd::Identity());
  for(int s = 0; s < 20; ++s)
  {
    // alpha up to 1e3 rad/s: Coriolis/centrifugal terms ~1e6 dominate; relErr is relative to them.
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc, 3.0, 1e3);
    const Errors e = stab::compare(mb, mbc);
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 12 * stab::eps, 10 * 12}));
    worst.max(e);
  }
  stab::report("velocities up to 1e3 rad/s", worst);
}

/// A tree whose root is Free and whose other joints are all Spherical.
rbd::MultiBody sphericalChain(rbdtest::Rng & rng)
{
  const auto g = stab::chainGraph(rng, 6, [](rbdtest::Rng & r, int) { return rbdtest::randomInertia(r); },
                                  [](rbdtest::Rng &, int k) {
                                    return rbd::Joint(rbd::Joint::Spherical, true, "j" + std::to_string(k));
                                  });
  return g.makeMultiBody("b0", rbd::Joint::Free);
}

/// Multiply every quaternion of q by a factor (the same rotation, a non-unit quaternion).
void scaleQuaternions(const rbd::MultiBody & mb, rbd::MultiBodyConfig & mbc, rbdtest::Rng & rng, double lo, double hi)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto t = mb.joint(i).type();
    if(t != rbd::Joint::Spherical && t != rbd::Joint::Free) continue;
    const double f = std::exp(rbdtest::uniform(rng, std::log(lo), std::log(hi)));
    for(int c = 0; c < 4; ++c) mbc.q[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] *= f;
  }
}

TEST(ExtremeStates, NonNormalisedQuaternions)
{
  // A quaternion stands for its normalisation (docs/DESIGN.md): the double runtime fed
  // s * quat, s in [1e-3, 1e3], must match the long double runtime fed the unit quaternion.
  rbdtest::Rng rng(704);
  const rbd::MultiBody mb = sphericalChain(rng);
  const rbd::MultiBodyTpl<stab::LD> mbL = dyntest::castModel<stab::LD>(mb);
  Errors worst;
  for(int s = 0; s < 20; ++s)
  {
    rbd::MultiBodyConfig unit(mb);
    rbdtest::randomState(rng, mb, unit);
    rbd::MultiBodyConfig scaled = unit;
    scaleQuaternions(mb, scaled, rng, 1e-3, 1e3);
    const Errors e = stab::errorsOf(stab::evaluate(mb, scaled), stab::evaluate(mbL, rbdtest::castInputs<stab::LD>(mbL, unit)));
    // Normalising costs a few eps: the 6-body chain bounds (c n eps, FD 10 n cond(H) eps).
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 6 * stab::eps, 10 * 6}));
    worst.max(e);
  }
  stab::report("non-normalised quaternions", worst);
}

TEST(ExtremeStates, AntipodalQuaternionsGiveTheSameDynamics)
{
  // quat and -quat are the same rotation. Quaternions near w = -1 (a turn of almost 2 pi) and
  // near w = 0 (half turns): the double runtime fed -quat against long double fed quat.
  rbdtest::Rng rng(705);
  const rbd::MultiBody mb = sphericalChain(rng);
  const rbd::MultiBodyTpl<stab::LD> mbL = dyntest::castModel<stab::LD>(mb);
  Errors worst;
  for(int s = 0; s < 20; ++s)
  {
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    rbd::MultiBodyConfig flipped = mbc;
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      auto & q = mbc.q[static_cast<std::size_t>(i)];
      const double tiny = s < 10 ? 1e-9 : 1e-3;
      // near-identity (w ~ 1) for even samples, half turn (w ~ 0) for odd ones
      Eigen::Quaterniond quat = s % 2 == 0 ? Eigen::Quaterniond(1, tiny * rbdtest::uniform(rng, -1, 1), tiny, -tiny)
                                           : Eigen::Quaterniond(tiny, rbdtest::uniform(rng, -1, 1), 1, -0.5);
      quat.normalize();
      q = {quat.w(), quat.x(), quat.y(), quat.z()};
      if(mb.joint(i).type() == rbd::Joint::Free) q.insert(q.end(), {0.3, -0.2, 0.1});
      auto & f = flipped.q[static_cast<std::size_t>(i)];
      f = q;
      for(int c = 0; c < 4; ++c) f[static_cast<std::size_t>(c)] = -q[static_cast<std::size_t>(c)];
    }
    const Errors e = stab::errorsOf(stab::evaluate(mb, flipped), stab::evaluate(mbL, rbdtest::castInputs<stab::LD>(mbL, mbc)));
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 6 * stab::eps, 10 * 6}));
    worst.max(e);
  }
  stab::report("antipodal quaternions", worst);
}

TEST(ExtremeStates, IntegrationThroughTheAntipodeStaysUnitAndFinite)
{
  // Spin a spherical joint at 1e3 rad/s for 1000 steps of 1 ms (159 turns): the quaternion goes
  // through w = -1 many times; it stays unit (normalised each step) and the rotation after the
  // run is exp(w t) computed in closed form (error: 1000 steps of ~eps each).
  rbdtest::Rng rng(706);
  rbd::MultiBodyGraph g;
  g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b0"));
  g.addBody(rbd::Body(sva::RBInertiad(1, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()), "b1"));
  g.addJoint(rbd::Joint(rbd::Joint::Spherical, true, "j1"));
  g.linkBodies("b0", sva::PTransformd::Identity(), "b1", sva::PTransformd::Identity(), "j1");
  const rbd::MultiBody mb = g.makeMultiBody("b0", true);
  rbd::MultiBodyConfig mbc(mb);
  mbc.zero(mb);
  const Eigen::Vector3d w = Eigen::Vector3d(1, 2, 2) / 3 * 1e3;
  mbc.alpha[1] = {w.x(), w.y(), w.z()};
  for(int k = 0; k < 1000; ++k) rbd::eulerIntegration(mb, mbc, 1e-3);
  const auto & q = mbc.q[1];
  const Eigen::Quaterniond got(q[0], q[1], q[2], q[3]);
  EXPECT_NEAR(got.norm(), 1.0, 4 * stab::eps);
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(1e3 * 1.0, w.normalized()));
  // angular distance between the two rotations; the angle 1e3 rad itself is exact to 1e3 eps.
  EXPECT_LE(got.angularDistance(expected), 1000 * 1e3 * stab::eps) << got.coeffs().transpose();
}

} // namespace
