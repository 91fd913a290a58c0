// MultiBodyGraph: trees rooted at every body, removeJoint, mergeSubBodies, fixJoints, loops and
// bodiesBaseTransform, checked against transforms composed by hand from the graph's links.
#include <functional>
#include <set>

#include <gtest/gtest.h>

#include <rbd/ConfigConverter.h>
#include <rbd/FK.h>
#include <rbd/MultiBodyGraph.h>

#include "TestModels.h"

namespace
{

rbdtest::RandomTreeOptions mixedOptions()
{
  rbdtest::RandomTreeOptions opt;
  opt.backwardProbability = 0.3;
  return opt;
}

/// World pose of every body's ORIGINAL frame (the frame its inertia was given in).
std::map<std::string, sva::PTransformd> originalPoses(const rbd::MultiBodyGraph & g, const std::string & root,
                                                      const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc)
{
  const auto bt = g.bodiesBaseTransform(root);
  std::map<std::string, sva::PTransformd> out;
  for(int i = 0; i < mb.nrBodies(); ++i)
    out[mb.body(i).name()] = bt.at(mb.body(i).name()) * mbc.bodyPosW[static_cast<std::size_t>(i)];
  return out;
}

/// Expected X from b1's original frame to b2's for one link at joint values q (by joint name):
/// X_b1_b2 = X_b2_j^-1 P X_b1_j, P = forward pose when the joint moves b2 w.r.t. b1, else inverse.
sva::PTransformd linkTransform(const rbd::MultiBodyGraph & g, const rbd::MultiBodyGraph::Link & l,
                               const std::map<std::string, std::vector<double>> & q)
{
  rbd::Joint j = g.joint(l.joint);
  j.forward(true);
  const auto it = q.find(l.joint);
  const sva::PTransformd P = it == q.end() ? sva::PTransformd::Identity() : j.pose(it->second);
  return l.X_b2_j.inv() * (l.isB1toB2 ? P : P.inv()) * l.X_b1_j;
}

std::map<std::string, std::vector<double>> jointValues(const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc)
{
  std::map<std::string, std::vector<double>> out;
  for(int i = 1; i < mb.nrJoints(); ++i) out[mb.joint(i).name()] = mbc.q[static_cast<std::size_t>(i)];
  return out;
}

/// sum_i X_0_i^T I_i X_0_i: the whole system's spatial inertia in world coordinates.
Eigen::Matrix<double, 6, 6> worldInertia(const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc)
{
  sva::RBInertiad I(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  for(int i = 0; i < mb.nrBodies(); ++i) I = I + mbc.bodyPosW[static_cast<std::size_t>(i)].transMul(mb.body(i).inertia());
  return I.matrix();
}

/// Bodies on the far side of `joint` seen from `root`, by a walk of the graph's links.
std::set<std::string> beyond(const rbd::MultiBodyGraph & g, const std::string & root, const std::string & joint)
{
  std::set<std::string> reached{root};
  std::function<void(const std::string &)> walk = [&](const std::string & b) {
    for(const auto & l : g.links())
    {
      if(l.joint == joint) continue;
      const std::string other = l.b1 == b ? l.b2 : (l.b2 == b ? l.b1 : "");
      if(!other.empty() && reached.insert(other).second) walk(other);
    }
  };
  walk(root);
  std::set<std::string> out;
  for(const auto & b : g.bodies())
    if(!reached.count(b.name())) out.insert(b.name());
  return out;
}

} // namespace

// Rooted at every body (Fixed), at zero and at random joint values: every link's relative
// transform is X_b2_j^-1 P X_b1_j.
TEST(MultiBodyGraph, EveryRootGivesTheLinkTransforms)
{
  rbdtest::Rng rng(31);
  for(int trial = 0; trial < 4; ++trial)
  {
    const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 9, mixedOptions());
    const rbd::MultiBody mb0 = g.makeMultiBody("b0", true);
    rbd::MultiBodyConfig mbc0(mb0);
    rbdtest::randomState(rng, mb0, mbc0);
    for(bool zero : {true, false})
    {
      const auto q = zero ? std::map<std::string, std::vector<double>>{} : jointValues(mb0, mbc0);
      for(const auto & root : g.bodies())
      {
        SCOPED_TRACE(root.name() + (zero ? " zero q" : " random q"));
        const rbd::MultiBody mb = g.makeMultiBody(root.name(), true);
        rbd::MultiBodyConfig mbc(mb);
        if(!zero) rbd::ConfigConverter(mb0, mb).convert(mbc0, mbc);
        rbd::forwardKinematics(mb, mbc);
        ASSERT_EQ(mb.nrBodies(), static_cast<int>(g.nrNodes()));
        for(int i = 0; i < mb.nrBodies(); ++i) EXPECT_LT(mb.parent(i), i);
        const auto X = originalPoses(g, root.name(), mb, mbc);
        EXPECT_MAT_NEAR(X.at(root.name()).matrix(), sva::PTransformd::Identity().matrix(), 1e-15);
        for(const auto & l : g.links())
          EXPECT_MAT_NEAR(X.at(l.b2).matrix(), (linkTransform(g, l, q) * X.at(l.b1)).matrix(), 1e-12) << l.joint;
      }
    }
  }
}

// The root joint placement: X_0_j0 puts the root joint in the world, X_b0_j0 moves the root
// body's frame (bodiesBaseTransform reports the way back, X_j0_b0 = X_b0_j0^-1, as RBDyn).
TEST(MultiBodyGraph, RootPlacementAndBodiesBaseTransform)
{
  rbdtest::Rng rng(32);
  const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 5, mixedOptions());
  const sva::PTransformd X_0_j0 = rbdtest::randomTransform(rng), X_b0_j0 = rbdtest::randomTransform(rng);
  const rbd::MultiBody mb = g.makeMultiBody("b2", rbd::Joint::Free, X_0_j0, X_b0_j0);
  EXPECT_EQ(mb.joint(0).type(), rbd::Joint::Free);
  EXPECT_EQ(mb.joint(0).name(), "Root");
  rbd::MultiBodyConfig mbc(mb);
  rbd::forwardKinematics(mb, mbc);
  EXPECT_MAT_NEAR(mbc.bodyPosW[0].matrix(), X_0_j0.matrix(), 1e-15);
  EXPECT_MAT_NEAR(g.bodiesBaseTransform("b2", X_b0_j0).at("b2").matrix(), X_b0_j0.inv().matrix(), 0.0);
  // Moved inertias and moved frames agree: the world-frame inertia of the system equals the sum
  // of the ORIGINAL inertias placed by the original frames' poses.
  const auto bt = g.bodiesBaseTransform("b2", X_b0_j0);
  sva::RBInertiad I(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & name = mb.body(i).name();
    I = I + (bt.at(name) * mbc.bodyPosW[static_cast<std::size_t>(i)]).transMul(g.body(name).inertia());
  }
  EXPECT_MAT_NEAR(worldInertia(mb, mbc), I.matrix(), 1e-12);
}

TEST(MultiBodyGraph, RemoveJointRemovesTheSubtree)
{
  rbdtest::Rng rng(33);
  for(int trial = 0; trial < 6; ++trial)
  {
    rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 10, mixedOptions());
    const std::string root = "b" + std::to_string(trial % 3);
    const std::string cut = "j" + std::to_string(1 + static_cast<int>(rbdtest::uniform(rng, 0, 8.99)));
    const std::set<std::string> gone = beyond(g, root, cut);
    ASSERT_FALSE(gone.empty());
    const rbd::MultiBody before = g.makeMultiBody(root, true);
    rbd::MultiBodyConfig mbcBefore(before);
    rbdtest::randomState(rng, before, mbcBefore);
    rbd::forwardKinematics(before, mbcBefore);
    const auto Xbefore = originalPoses(g, root, before, mbcBefore);
    const std::size_t nodes = g.nrNodes(), joints = g.nrJoints();

    g.removeJoint(root, cut);
    EXPECT_EQ(g.nrNodes(), nodes - gone.size());
    EXPECT_EQ(g.nrJoints(), joints - gone.size()); // a tree: one joint per removed body
    EXPECT_FALSE(g.hasJoint(cut));
    for(const auto & b : gone) EXPECT_FALSE(g.hasBody(b)) << b;
    // What is left moves as before.
    const rbd::MultiBody after = g.makeMultiBody(root, true);
    rbd::MultiBodyConfig mbcAfter(after);
    rbd::ConfigConverter(before, after).convert(mbcBefore, mbcAfter);
    rbd::forwardKinematics(after, mbcAfter);
    for(const auto & [name, X] : originalPoses(g, root, after, mbcAfter))
      EXPECT_MAT_NEAR(X.matrix(), Xbefore.at(name).matrix(), 1e-12) << name;
  }
}

// mergeSubBodies at given joint values keeps the world-frame spatial inertia (mass, CoM, inertia).
TEST(MultiBodyGraph, MergeSubBodiesKeepsMassAndCoM)
{
  rbdtest::Rng rng(34);
  for(int trial = 0; trial < 6; ++trial)
  {
    rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 10, mixedOptions());
    const std::string root = "b" + std::to_string(trial % 3);
    const std::string cut = "j" + std::to_string(1 + static_cast<int>(rbdtest::uniform(rng, 0, 8.99)));
    const rbd::MultiBody before = g.makeMultiBody(root, true);
    rbd::MultiBodyConfig mbcBefore(before);
    rbdtest::randomState(rng, before, mbcBefore);
    rbd::forwardKinematics(before, mbcBefore);
    // Hold the merged joints at their values in mbcBefore.
    std::map<std::string, std::vector<double>> held;
    const std::set<std::string> gone = beyond(g, root, cut);
    for(const auto & l : g.links())
      if(gone.count(l.b1) || gone.count(l.b2))
        held[l.joint] = mbcBefore.q[static_cast<std::size_t>(before.jointIndexByName(l.joint))];

    g.mergeSubBodies(root, cut, held);
    const rbd::MultiBody after = g.makeMultiBody(root, true);
    EXPECT_EQ(after.nrBodies(), before.nrBodies() - static_cast<int>(gone.size()));
    rbd::MultiBodyConfig mbcAfter(after);
    rbd::ConfigConverter(before, after).convert(mbcBefore, mbcAfter);
    rbd::forwardKinematics(after, mbcAfter);
    const auto Ib = worldInertia(before, mbcBefore), Ia = worldInertia(after, mbcAfter);
    EXPECT_NEAR(Ia(5, 5), Ib(5, 5), 1e-12); // total mass
    EXPECT_MAT_NEAR(Ia, Ib, 1e-12);         // and first and second moments (CoM, inertia)
  }
}

// fixJoints at q gives the same forward kinematics as the original at q.
TEST(MultiBodyGraph, FixJointsKeepsForwardKinematics)
{
  rbdtest::Rng rng(35);
  for(int trial = 0; trial < 6; ++trial)
  {
    rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 9, mixedOptions());
    const std::string root = "b" + std::to_string(trial % 4);
    const rbd::MultiBody before = g.makeMultiBody(root, true);
    rbd::MultiBodyConfig mbcBefore(before);
    rbdtest::randomState(rng, before, mbcBefore);
    rbd::forwardKinematics(before, mbcBefore);
    const auto Xb = originalPoses(g, root, before, mbcBefore);
    std::map<std::string, std::vector<double>> fixed;
    int fixedDof = 0;
    for(int i = 1; i < before.nrJoints(); i += 2)
    {
      fixed[before.joint(i).name()] = mbcBefore.q[static_cast<std::size_t>(i)];
      fixedDof += before.joint(i).dof();
    }
    g.fixJoints(fixed);
    const rbd::MultiBody after = g.makeMultiBody(root, true);
    EXPECT_EQ(after.nrDof(), before.nrDof() - fixedDof);
    rbd::MultiBodyConfig mbcAfter(after);
    rbd::ConfigConverter(before, after).convert(mbcBefore, mbcAfter);
    for(const auto & [name, q] : fixed) EXPECT_EQ(after.joint(after.jointIndexByName(name)).type(), rbd::Joint::Fixed);
    rbd::forwardKinematics(after, mbcAfter);
    for(const auto & [name, X] : originalPoses(g, root, after, mbcAfter))
      EXPECT_MAT_NEAR(X.matrix(), Xb.at(name).matrix(), 1e-12) << name;
  }
}

TEST(MultiBodyGraph, LoopsAndBadEditsAreRejected)
{
  rbdtest::Rng rng(36);
  rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 5);
  g.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitZ(), true, "closing"));
  g.linkBodies("b4", sva::PTransformd::Identity(), "b0", sva::PTransformd::Identity(), "closing");
  for(const auto & b : g.bodies()) EXPECT_THROW(g.makeMultiBody(b.name(), true), std::domain_error) << b.name();
  try
  {
    g.makeMultiBody("b0", true);
  }
  catch(const std::domain_error & e)
  {
    EXPECT_NE(std::string(e.what()).find("loop"), std::string::npos) << e.what();
  }
  EXPECT_THROW(g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b1")), std::domain_error);
  EXPECT_THROW(g.addJoint(rbd::Joint(rbd::Joint::Rev, true, "j1")), std::domain_error);
  EXPECT_THROW(g.addJoint(rbd::Joint(rbd::Joint::Rev, true, "Root")), std::domain_error);
  EXPECT_THROW(g.makeMultiBody("nope", true), std::out_of_range);
  EXPECT_THROW(g.fixJoints({{"j1", std::vector<double>(20, 0.)}}), std::domain_error); // wrong size
}
