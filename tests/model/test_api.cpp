// RBDyn's API as its users write it: Joint::OldType and name-only constructors, operator<< of Body
// and Joint, Eigen::Vector6d / Matrix6d, the s-prefixed checked accessors of MultiBody, setters,
// the flat-vector conversions called with Eigen vectors and expressions, and the exception types
// (std::domain_error for size mismatches, std::out_of_range for unknown names and indices).
#include <algorithm>
#include <sstream>
#include <type_traits>

#include <gtest/gtest.h>

#include <rbd/ConfigConverter.h>
#include <rbd/FK.h>
#include <rbd/MultiBodyConfig.h>
#include <rbd/MultiBodyGraph.h>

#include "TestModels.h"

namespace
{

static_assert(std::is_same<Eigen::Vector6d, Eigen::Matrix<double, 6, 1>>::value, "Eigen::Vector6d");
static_assert(std::is_same<Eigen::Matrix6d, Eigen::Matrix<double, 6, 6>>::value, "Eigen::Matrix6d");
static_assert(std::is_same<Eigen::Vector6<float>, Eigen::Matrix<float, 6, 1>>::value, "Eigen::Vector6<T>");
static_assert(std::is_same<Eigen::Matrix3<float>, Eigen::Matrix<float, 3, 3>>::value, "Eigen::Matrix3<T>");

TEST(RbdynApi, OldTypeConstructorsAreAxisJoints)
{
  const rbd::Joint::OldType old[] = {rbd::Joint::RevX,   rbd::Joint::RevY,   rbd::Joint::RevZ,
                                     rbd::Joint::PrismX, rbd::Joint::PrismY, rbd::Joint::PrismZ};
  for(int k = 0; k < 6; ++k)
  {
    const rbd::Joint j(old[k], k % 2 == 0, "j");
    const rbd::Joint::Type type = k < 3 ? rbd::Joint::Rev : rbd::Joint::Prism;
    EXPECT_EQ(j, rbd::Joint(type, Eigen::Vector3d::Unit(k % 3), k % 2 == 0, "j")) << k;
    EXPECT_EQ(j.pose({0.3}).matrix(), rbd::Joint(type, Eigen::Vector3d::Unit(k % 3), k % 2 == 0, "j").pose({0.3}).matrix());
  }
  const rbd::Joint fixed("weld");
  EXPECT_EQ(fixed.type(), rbd::Joint::Fixed);
  EXPECT_EQ(fixed.name(), "weld");
  EXPECT_TRUE(fixed.forward());
  EXPECT_EQ(rbd::Joint::ZeroParam(rbd::Joint::Free), (std::vector<double>{1, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(rbd::Joint::ZeroDof(rbd::Joint::Planar), (std::vector<double>{0, 0, 0}));
}

TEST(RbdynApi, StreamOperatorsPrintTheName)
{
  std::ostringstream out;
  out << rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "torso") << "|"
      << rbd::Joint(rbd::Joint::Rev, true, "elbow");
  EXPECT_EQ(out.str(), "Body: torso|Joint: elbow");
}

TEST(RbdynApi, JointCheckedVariants)
{
  const rbd::Joint j(rbd::Joint::Spherical, true, "s");
  EXPECT_EQ(j.sPose({1, 0, 0, 0}).matrix(), Eigen::Matrix6d::Identity());
  EXPECT_THROW(j.sPose({1, 0, 0}), std::domain_error);
  EXPECT_THROW(j.sMotion({1, 0}), std::domain_error);
  EXPECT_THROW(j.sTanAccel({1, 0, 0, 0}), std::domain_error);
  EXPECT_EQ(j.sMotion({1, 2, 3}).vector(), (Eigen::Vector6d() << 1, 2, 3, 0, 0, 0).finished());
}

rbd::MultiBody threeBodies()
{
  rbdtest::Rng rng(3);
  rbdtest::RandomTreeOptions opt;
  opt.types = {rbd::Joint::Rev, rbd::Joint::Free, rbd::Joint::Planar};
  return rbdtest::randomGraph(rng, 3, opt).makeMultiBody("b0", rbd::Joint::Free);
}

TEST(RbdynApi, MultiBodyCheckedAccessors)
{
  rbd::MultiBody mb = threeBodies();
  EXPECT_EQ(mb.sBody(2).name(), mb.body(2).name());
  EXPECT_EQ(mb.sJoint(1).name(), mb.joint(1).name());
  EXPECT_EQ(mb.sParent(2), mb.parent(2));
  EXPECT_EQ(mb.sPredecessor(2), mb.predecessor(2));
  EXPECT_EQ(mb.sSuccessor(2), mb.successor(2));
  EXPECT_EQ(mb.sJointPosInParam(2), mb.jointPosInParam(2));
  EXPECT_EQ(mb.sJointPosInDof(2), mb.jointPosInDof(2));
  EXPECT_EQ(mb.sTransform(1).matrix(), mb.transform(1).matrix());
  EXPECT_EQ(mb.sBodyIndexByName("b2"), 2);
  EXPECT_EQ(mb.sJointIndexByName("Root"), 0);
  for(int bad : {-1, 3})
  {
    EXPECT_THROW(mb.sBody(bad), std::out_of_range);
    EXPECT_THROW(mb.sJoint(bad), std::out_of_range);
    EXPECT_THROW(mb.sParent(bad), std::out_of_range);
    EXPECT_THROW(mb.sPredecessor(bad), std::out_of_range);
    EXPECT_THROW(mb.sSuccessor(bad), std::out_of_range);
    EXPECT_THROW(mb.sTransform(bad), std::out_of_range);
    EXPECT_THROW(mb.sJointPosInParam(bad), std::out_of_range);
    EXPECT_THROW(mb.sJointPosInDof(bad), std::out_of_range);
  }
  EXPECT_THROW(mb.sBodyIndexByName("nobody"), std::out_of_range);
  EXPECT_THROW(mb.sJointIndexByName("nojoint"), std::out_of_range);
  EXPECT_THROW(mb.sTransforms({}), std::domain_error);
  EXPECT_THROW(mb.sBodies({}), std::domain_error);

  // Setters: a renamed body is found under its new name; transforms are replaced.
  mb.sBody(1, rbd::Body(2.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "renamed"));
  EXPECT_EQ(mb.bodyIndexByName("renamed"), 1);
  EXPECT_FALSE(mb.hasBody("b1"));
  EXPECT_THROW(mb.body(2, rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "b0")),
               std::domain_error);
  std::vector<sva::PTransformd> Xt(3, sva::PTransformd(Eigen::Vector3d(1, 2, 3)));
  mb.sTransforms(Xt);
  EXPECT_EQ(mb.transform(2).translation(), Eigen::Vector3d(1, 2, 3));
}

// paramToVector & co. with Eigen::VectorXd, segments and expressions, against per-joint copies.
TEST(RbdynApi, FlatVectorConversionsTakeEigenVectors)
{
  const rbd::MultiBody mb = threeBodies();
  rbd::MultiBodyConfig mbc(mb);
  rbdtest::Rng rng(4);
  rbdtest::randomState(rng, mb, mbc);
  Eigen::VectorXd q(mb.nrParams()), alpha(mb.nrDof());
  rbd::paramToVector(mbc.q, q);
  rbd::dofToVector(mbc.alpha, alpha);
  Eigen::Index pos = 0;
  for(const auto & joint : mbc.q)
    for(double x : joint) EXPECT_EQ(q(pos++), x);
  EXPECT_EQ(alpha, rbd::dofToVector(mb, mbc.alpha));
  EXPECT_EQ(q, rbd::paramToVector(mb, mbc.q));

  // a segment of a longer vector as output, an expression as input
  Eigen::VectorXd both = Eigen::VectorXd::Zero(mb.nrParams() + mb.nrDof());
  rbd::paramToVector(mbc.q, both.head(mb.nrParams()));
  rbd::dofToVector(mbc.alpha, both.tail(mb.nrDof()));
  EXPECT_EQ(both.head(mb.nrParams()), q);
  std::vector<std::vector<double>> v = mbc.alpha;
  rbd::vectorToDof(2.0 * alpha, v);
  for(std::size_t i = 0; i < v.size(); ++i)
    for(std::size_t k = 0; k < v[i].size(); ++k) EXPECT_EQ(v[i][k], 2.0 * mbc.alpha[i][k]);
  rbd::vectorToParam(both.head(mb.nrParams()), v = mbc.q);
  EXPECT_EQ(v, mbc.q);
  EXPECT_EQ(rbd::vectorToParam(mb, q), mbc.q);
  EXPECT_EQ(rbd::vectorToDof(mb, both.tail(mb.nrDof())), mbc.alpha);

  // checked variants: std::out_of_range, as RBDyn
  EXPECT_EQ(rbd::sParamToVector(mb, mbc.q), q);
  EXPECT_THROW(rbd::sParamToVector(mb, mbc.alpha), std::out_of_range);
  EXPECT_THROW(rbd::sDofToVector(mb, mbc.q), std::out_of_range);
  EXPECT_THROW(rbd::sVectorToParam(mb, alpha), std::out_of_range);
  EXPECT_THROW(rbd::sVectorToDof(mb, q), std::out_of_range);
  EXPECT_THROW(rbd::sParamToVector(mbc.q, alpha), std::out_of_range);
  EXPECT_THROW(rbd::sVectorToParam(alpha, v = mbc.q), std::out_of_range);
  EXPECT_NO_THROW(rbd::sVectorToParam(q, v));
}

// Size mismatches in the checked algorithms are std::domain_error (RBDyn's checkMatch*).
TEST(RbdynApi, SizeErrorsAreDomainErrors)
{
  const rbd::MultiBody mb = threeBodies();
  rbd::MultiBodyConfig mbc(mb);
  mbc.q[1].push_back(0.0);
  EXPECT_THROW(rbd::sForwardKinematics(mb, mbc), std::domain_error);
  rbd::MultiBodyGraph g;
  g.addBody(rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "a"));
  EXPECT_THROW(g.addBody(rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "a")), std::domain_error);
}

/// X_b1_b2 of one link at the joint value q: X_b2_j^-1 P X_b1_j, P the pose moving b2 (composed by
/// hand from the link's transforms: the closed form RBDyn's makeMultiBody must reproduce).
sva::PTransformd linkPose(const sva::PTransformd & X_b1_j, const sva::PTransformd & X_b2_j, const sva::PTransformd & P)
{
  return X_b2_j.inv() * P * X_b1_j;
}

// A chain b0 - b1 - b2 - b3 with rotated link transforms, rooted at b0 and re-rooted at b3, both with
// non-identity X_0_j0 and X_b0_j0: the world pose of every body's original frame, RBDyn's
// bodiesBaseTransform(root, X_b0_j0)[b] * bodyPosW[b], equals the hand-composed chain of link poses
// placed by the root's X_b0_j0^-1 X_0_j0, in both trees once ConfigConverter has copied q.
TEST(RbdynApi, ReRootedTreeWithBaseTransformGivesOriginalFramePoses)
{
  rbdtest::Rng rng(5);
  rbd::MultiBodyGraph g;
  std::vector<sva::PTransformd> Xa, Xb; // X_b(k-1)_j, X_bk_j of link k
  const Eigen::Vector3d axes[3] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 2, 3).normalized(), Eigen::Vector3d::UnitX()};
  for(int k = 0; k < 4; ++k) g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b" + std::to_string(k)));
  for(int k = 1; k < 4; ++k)
  {
    g.addJoint(rbd::Joint(rbd::Joint::Rev, axes[k - 1], true, "j" + std::to_string(k)));
    Xa.push_back(rbdtest::randomTransform(rng, 1.0));
    Xb.push_back(rbdtest::randomTransform(rng, 1.0));
    g.linkBodies("b" + std::to_string(k - 1), Xa.back(), "b" + std::to_string(k), Xb.back(), "j" + std::to_string(k));
  }
  const double q[3] = {0.7, -1.2, 2.1};
  const sva::PTransformd X_0_j0 = rbdtest::randomTransform(rng, 2.0), X_b0_j0 = rbdtest::randomTransform(rng, 2.0);

  // closed form: original frame poses along the chain
  std::vector<sva::PTransformd> expected{X_b0_j0.inv() * X_0_j0};
  for(int k = 1; k < 4; ++k)
  {
    const rbd::Joint j(rbd::Joint::Rev, axes[k - 1], true, "j");
    expected.push_back(linkPose(Xa[k - 1], Xb[k - 1], j.pose({q[k - 1]})) * expected.back());
  }


  const rbd::MultiBody mb0 = g.makeMultiBody("b0", rbd::Joint::Fixed, X_0_j0, X_b0_j0);
  rbd::MultiBodyConfig mbc0(mb0);
  for(int k = 1; k < 4; ++k) mbc0.q[static_cast<std::size_t>(k)] = {q[k - 1]};
  rbd::forwardKinematics(mb0, mbc0);
  EXPECT_MAT_NEAR(mbc0.bodyPosW[0].matrix(), X_0_j0.matrix(), 1e-15); // the root body's frame: its joint's
  const auto bt0 = g.bodiesBaseTransform("b0", X_b0_j0);
  for(int k = 0; k < 4; ++k)
    EXPECT_MAT_NEAR((bt0.at("b" + std::to_string(k)) * mbc0.bodyPosW[static_cast<std::size_t>(k)]).matrix(),
                    expected[static_cast<std::size_t>(k)].matrix(), 1e-13)
        << k;

  // re-rooted at b3: its root placement chosen to put b3's original frame where it was
  const sva::PTransformd X_b3_j0 = rbdtest::randomTransform(rng, 2.0);
  const sva::PTransformd X_0_j3 = X_b3_j0 * expected[3]; // X_0_j = X_b_j X_0_b
  const rbd::MultiBody mb3 = g.makeMultiBody("b3", rbd::Joint::Fixed, X_0_j3, X_b3_j0);
  rbd::MultiBodyConfig mbc3(mb3);
  const rbd::ConfigConverter conv = rbd::ConfigConverter::sConstructor(mb0, mb3);
  conv.sConvert(mbc0, mbc3);
  // convertJoint for any per-joint type (here the joint names)
  std::vector<std::string> names0;
  for(const auto & j : mb0.joints()) names0.push_back(j.name());
  const std::vector<std::string> names3 = conv.convertJoint(names0);
  for(int k = 1; k < mb0.nrJoints(); ++k) EXPECT_EQ(names3[static_cast<std::size_t>(mb3.jointIndexByName(names0[static_cast<std::size_t>(k)]))], names0[static_cast<std::size_t>(k)]);
  std::vector<std::string> shorter(2);
  EXPECT_THROW(conv.sConvertJoint(names0, shorter), std::domain_error);
  rbd::forwardKinematics(mb3, mbc3);
  EXPECT_MAT_NEAR(mbc3.bodyPosW[0].matrix(), X_0_j3.matrix(), 1e-15);
  const auto bt3 = g.bodiesBaseTransform("b3", X_b3_j0);
  for(int k = 0; k < 4; ++k)
  {
    const std::string name = "b" + std::to_string(k);
    EXPECT_MAT_NEAR((bt3.at(name) * mbc3.bodyPosW[static_cast<std::size_t>(mb3.bodyIndexByName(name))]).matrix(),
                    expected[static_cast<std::size_t>(k)].matrix(), 1e-12)
        << name;
  }
}

// A joint added backward (forward = false) and linked b1 -> b2 moves b1 w.r.t. b2, like a forward
// joint linked b2 -> b1 (RBDyn's linkBodies).
TEST(RbdynApi, BackwardJointInTheGraphFollowsRbdyn)
{
  rbdtest::Rng rng(6);
  const sva::PTransformd X1 = rbdtest::randomTransform(rng), X2 = rbdtest::randomTransform(rng);
  const Eigen::Vector3d axis = rbdtest::randomUnit(rng);
  auto build = [&](bool forward, bool isB1toB2) {
    rbd::MultiBodyGraph g;
    g.addBody(rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "b1"));
    g.addBody(rbd::Body(1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), "b2"));
    g.addJoint(rbd::Joint(rbd::Joint::Rev, axis, forward, "j"));
    g.linkBodies("b1", X1, "b2", X2, "j", isB1toB2);
    const rbd::MultiBody mb = g.makeMultiBody("b1", true);
    rbd::MultiBodyConfig mbc(mb);
    mbc.q[1] = {0.8};
    rbd::forwardKinematics(mb, mbc);
    return std::make_pair(mb.joint(1).forward(), mbc.bodyPosW[1]);
  };
  const auto backwardAdded = build(false, true), linkedBackward = build(true, false), plain = build(true, true);
  EXPECT_FALSE(backwardAdded.first);
  EXPECT_FALSE(linkedBackward.first);
  EXPECT_TRUE(plain.first);
  EXPECT_MAT_NEAR(backwardAdded.second.matrix(), linkedBackward.second.matrix(), 0.0);
  EXPECT_GT((backwardAdded.second.matrix() - plain.second.matrix()).norm(), 1e-3);
  EXPECT_TRUE(build(false, false).first); // backward joint linked backward: forward again
}

// nodeByName / jointByName and RBDyn's static fixJoints.
TEST(RbdynApi, GraphNodesJointsAndFixJoints)
{
  rbdtest::Rng rng(7);
  rbdtest::RandomTreeOptions opt;
  opt.types = {rbd::Joint::Rev, rbd::Joint::Prism, rbd::Joint::Spherical};
  const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 5, opt);
  const auto node = g.nodeByName("b1");
  EXPECT_EQ(node->body, g.body("b1"));
  std::size_t links = 0;
  for(const auto & l : g.links()) links += (l.b1 == "b1" || l.b2 == "b1") ? 1 : 0;
  ASSERT_EQ(node->arcs.size(), links);
  for(const auto & arc : node->arcs)
  {
    const auto & l = *std::find_if(g.links().begin(), g.links().end(), [&](const auto & x) { return x.joint == arc.joint.name(); });
    const bool here1 = l.b1 == "b1";
    EXPECT_EQ(arc.next, here1 ? l.b2 : l.b1);
    EXPECT_EQ(arc.X.matrix(), (here1 ? l.X_b1_j : l.X_b2_j).matrix());
    EXPECT_EQ(arc.joint.forward(), here1 == l.isB1toB2); // the joints of randomGraph are forward
  }
  EXPECT_EQ(*g.jointByName("j2"), g.joint("j2"));
  EXPECT_THROW(g.nodeByName("nobody"), std::out_of_range);
  EXPECT_THROW(g.jointByName("nojoint"), std::out_of_range);

  const rbd::MultiBodyGraph some = rbd::MultiBodyGraph::fixJoints(g, {"j1", "j3"});
  const rbd::MultiBodyGraph all = rbd::MultiBodyGraph::fixJoints(g, {}, true);
  EXPECT_EQ(some.joint("j1").type(), rbd::Joint::Fixed);
  EXPECT_EQ(some.joint("j2").type(), g.joint("j2").type());
  for(const auto & j : all.joints()) EXPECT_EQ(j.type(), rbd::Joint::Fixed);
  EXPECT_THROW(rbd::MultiBodyGraph::fixJoints(g, {"nojoint"}), std::out_of_range);
  // fixed at zero: the tree's poses at q = 0 are unchanged
  const rbd::MultiBody mb = g.makeMultiBody("b0", true), mbAll = all.makeMultiBody("b0", true);
  rbd::MultiBodyConfig mbc(mb), mbcAll(mbAll);
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardKinematics(mbAll, mbcAll);
  for(int i = 0; i < mb.nrBodies(); ++i)
    EXPECT_MAT_NEAR(mbcAll.bodyPosW[static_cast<std::size_t>(mbAll.bodyIndexByName(mb.body(i).name()))].matrix(),
                    mbc.bodyPosW[static_cast<std::size_t>(i)].matrix(), 1e-15);
}

} // namespace
