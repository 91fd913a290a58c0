// Long chains (50 and 200 links), wide trees and random trees with every joint type: every runtime
// output in double against long double.
//
// Bounds: a recursion over a chain of depth n accumulates rounding as ~n eps times the magnitudes
// involved (positions grow with n, torques with n^2 lever arms, both normalised away by relErr),
// so each bound is c * n * eps with c stated per case; forward dynamics is bounded by
// fdFactor * cond(H) * eps (see stab::Bounds).
#include "StabilityUtils.h"

namespace
{

using stab::Bounds;
using stab::Errors;

rbd::MultiBody revChain(rbdtest::Rng & rng, int n)
{
  const auto g = stab::chainGraph(rng, n, [](rbdtest::Rng & r, int) { return rbdtest::randomInertia(r); }, stab::randomRev);
  return g.makeMultiBody("b0", true);
}

TEST(LongChains, Chain50Revolute)
{
  rbdtest::Rng rng(501);
  const rbd::MultiBody mb = revChain(rng, 50);
  Errors worst;
  for(int s = 0; s < 20; ++s)
  {
    const Errors e = stab::compareRandom(rng, mb);
    // 50 links: c = 50 -> 50 * 50 * eps = 5.6e-13.
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 50 * stab::eps, 10 * 50}));
    worst.max(e);
  }
  stab::report("chain 50 revolute", worst);
}

TEST(LongChains, Chain200Revolute)
{
  rbdtest::Rng rng(2001);
  const rbd::MultiBody mb = revChain(rng, 200);
  Errors worst;
  for(int s = 0; s < 3; ++s)
  {
    const Errors e = stab::compareRandom(rng, mb);
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 200 * stab::eps, 10 * 200}));
    worst.max(e);
  }
  stab::report("chain 200 revolute", worst);
}

TEST(LongChains, Chain50AllJointTypes)
{
  rbdtest::Rng rng(502);
  Errors worst;
  for(int m = 0; m < 3; ++m)
  {
    const auto g = stab::chainGraph(rng, 50, [](rbdtest::Rng & r, int) { return rbdtest::randomInertia(r); },
                                    stab::randomAnyJoint);
    const rbd::MultiBody mb = g.makeMultiBody("b0", rbd::Joint::Free);
    for(int s = 0; s < 5; ++s)
    {
      const Errors e = stab::compareRandom(rng, mb);
      EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 50 * stab::eps, 10 * 50}));
      worst.max(e);
    }
  }
  stab::report("chain 50 all joint types", worst);
}

TEST(LongChains, WideTree)
{
  rbdtest::Rng rng(503);
  // 60 branches of 2 links from one root body: 121 bodies, depth 3.
  const rbd::MultiBody mb = stab::wideTreeGraph(rng, 60, 2).makeMultiBody("b0", rbd::Joint::Free);
  Errors worst;
  for(int s = 0; s < 5; ++s)
  {
    const Errors e = stab::compareRandom(rng, mb);
    EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 121 * stab::eps, 10 * 121}));
    worst.max(e);
  }
  stab::report("wide tree 60x2", worst);
}

TEST(LongChains, RandomTreesAllJointTypes)
{
  rbdtest::Rng rng(504);
  Errors worst;
  for(int m = 0; m < 20; ++m)
  {
    const rbd::MultiBody mb = dyntest::randomModel(rng, 20, 0.3, m % 2 == 0);
    for(int s = 0; s < 5; ++s)
    {
      const Errors e = stab::compareRandom(rng, mb);
      EXPECT_TRUE(stab::withinBounds(e, Bounds{50 * 20 * stab::eps, 10 * 20}));
      worst.max(e);
    }
  }
  stab::report("random trees 20 bodies", worst);
}

} // namespace
