// MultiBodyConfig sizes, flat-vector round trips, MultiBody::cast<long double> and ConfigConverter.
#include <sstream>

#include <gtest/gtest.h>

#include <rbd/ConfigConverter.h>
#include <rbd/FK.h>
#include <rbd/MultiBodyGraph.h>

#include "TestModels.h"

namespace
{

rbd::MultiBodyGraph mixedGraph(rbdtest::Rng & rng, int n)
{
  rbdtest::RandomTreeOptions opt;
  opt.backwardProbability = 0.3;
  return rbdtest::randomGraph(rng, n, opt);
}

} // namespace

TEST(MultiBodyConfig, SizesAndZero)
{
  rbdtest::Rng rng(41);
  const rbd::MultiBody mb = mixedGraph(rng, 12).makeMultiBody("b0", false);
  const rbd::MultiBodyConfig mbc(mb);
  ASSERT_EQ(static_cast<int>(mbc.q.size()), mb.nrJoints());
  int params = 0, dof = 0;
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_EQ(mb.jointPosInParam(i), params);
    EXPECT_EQ(mb.jointPosInDof(i), dof);
    EXPECT_EQ(mbc.q[k], mb.joint(i).zeroParam());
    EXPECT_EQ(static_cast<int>(mbc.alpha[k].size()), mb.joint(i).dof());
    EXPECT_EQ(static_cast<int>(mbc.alphaD[k].size()), mb.joint(i).dof());
    EXPECT_EQ(static_cast<int>(mbc.jointTorque[k].size()), mb.joint(i).dof());
    EXPECT_EQ(mbc.motionSubspace[k].cols(), mb.joint(i).dof());
    params += mb.joint(i).params();
    dof += mb.joint(i).dof();
  }
  EXPECT_EQ(mb.nrParams(), params);
  EXPECT_EQ(mb.nrDof(), dof);
  EXPECT_EQ(static_cast<int>(mbc.force.size()), mb.nrBodies());
  EXPECT_EQ(static_cast<int>(mbc.bodyPosW.size()), mb.nrBodies());
  EXPECT_MAT_NEAR(mbc.gravity, Eigen::Vector3d(0, 0, 9.81), 0.0);
}

TEST(MultiBodyConfig, FlatVectorRoundTrips)
{
  rbdtest::Rng rng(42);
  const rbd::MultiBody mb = mixedGraph(rng, 12).makeMultiBody("b0", false);
  rbd::MultiBodyConfig mbc(mb);
  rbdtest::randomState(rng, mb, mbc);
  // q -> flat: each joint's block at jointPosInParam.
  const Eigen::VectorXd q = rbd::paramToVector(mb, mbc.q);
  ASSERT_EQ(q.size(), mb.nrParams());
  for(int i = 0; i < mb.nrJoints(); ++i)
    for(int k = 0; k < mb.joint(i).params(); ++k)
      EXPECT_EQ(q(mb.jointPosInParam(i) + k), mbc.q[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)]);
  EXPECT_EQ(rbd::vectorToParam(mb, q), mbc.q);
  // alpha -> flat -> alpha, both overload families.
  const Eigen::VectorXd a = rbd::dofToVector(mb, mbc.alpha);
  ASSERT_EQ(a.size(), mb.nrDof());
  for(int i = 0; i < mb.nrJoints(); ++i)
    for(int k = 0; k < mb.joint(i).dof(); ++k)
      EXPECT_EQ(a(mb.jointPosInDof(i) + k), mbc.alpha[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)]);
  EXPECT_EQ(rbd::vectorToDof(mb, a), mbc.alpha);
  std::vector<std::vector<double>> back = mbc.alphaD;
  Eigen::VectorXd flat(mb.nrDof());
  rbd::dofToVector<double>(mbc.alphaD, flat);
  for(auto & v : back) std::fill(v.begin(), v.end(), 0.);
  rbd::vectorToDof<double>(flat, back);
  EXPECT_EQ(back, mbc.alphaD);
  // flat -> per joint -> flat for an arbitrary vector.
  const Eigen::VectorXd e = Eigen::VectorXd::LinSpaced(mb.nrParams(), -1, 1);
  EXPECT_EQ(rbd::paramToVector(mb, rbd::vectorToParam(mb, e)), e);
}

// The long double model is the same model: exact widening, exact round trip, and FK agreeing
// with double to round-off.
TEST(MultiBody, CastToLongDouble)
{
  rbdtest::Rng rng(43);
  const rbd::MultiBody mb = mixedGraph(rng, 15).makeMultiBody("b3", false);
  const rbd::MultiBodyTpl<long double> mbl = mb.cast<long double>();
  ASSERT_EQ(mbl.nrBodies(), mb.nrBodies());
  EXPECT_EQ(mbl.nrParams(), mb.nrParams());
  EXPECT_EQ(mbl.nrDof(), mb.nrDof());
  EXPECT_EQ(mbl.parents(), mb.parents());
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    EXPECT_EQ(mbl.body(i).name(), mb.body(i).name());
    EXPECT_EQ(mbl.joint(i).type(), mb.joint(i).type());
    EXPECT_EQ(mbl.joint(i).forward(), mb.joint(i).forward());
    EXPECT_EQ(mbl.body(i).inertia().matrix().cast<double>(), mb.body(i).inertia().matrix());
    // The cast re-orthonormalises rotations in long double: equal to the double ones within 1e-15,
    // and orthonormal to long double precision.
    EXPECT_LE((mbl.transform(i).rotation().cast<double>() - mb.transform(i).rotation()).cwiseAbs().maxCoeff(), 1e-15);
    const auto & El = mbl.transform(i).rotation();
    EXPECT_LE(static_cast<double>((El * El.transpose() - sva::Matrix3<long double>::Identity()).cwiseAbs().maxCoeff()), 1e-18);
    EXPECT_EQ(Eigen::Vector3d(mbl.transform(i).translation().cast<double>()), mb.transform(i).translation());
  }
  const rbd::MultiBody back = mbl.cast<double>();
  EXPECT_EQ(back.bodies(), mb.bodies());
  EXPECT_EQ(back.joints(), mb.joints());

  rbd::MultiBodyConfig mbc(mb);
  rbdtest::randomState(rng, mb, mbc);
  rbd::MultiBodyConfigTpl<long double> mbcl = rbdtest::castInputs(mbl, mbc);
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardKinematics(mbl, mbcl);
  double worst = 0;
  for(int i = 0; i < mb.nrBodies(); ++i)
    worst = std::max(worst, rbdtest::relErr(mbc.bodyPosW[static_cast<std::size_t>(i)].matrix(),
                                            mbcl.bodyPosW[static_cast<std::size_t>(i)].matrix()));
  EXPECT_LT(worst, 1e-13);
  std::ostringstream os;
  os << worst;
  RecordProperty("fk_double_vs_long_double", os.str());
}

// ConfigConverter between two roots of the same graph: values by name, roots untouched, and the
// converted configuration describes the same relative placement of all bodies.
TEST(ConfigConverter, ConvertsBetweenRootsOfOneGraph)
{
  rbdtest::Rng rng(44);
  for(int trial = 0; trial < 4; ++trial)
  {
    const rbd::MultiBodyGraph g = mixedGraph(rng, 10);
    const rbd::MultiBody mb1 = g.makeMultiBody("b0", true), mb2 = g.makeMultiBody("b7", false);
    rbd::MultiBodyConfig mbc1(mb1), mbc2(mb2);
    rbdtest::randomState(rng, mb1, mbc1);
    for(auto & f : mbc1.force) f = sva::ForceVecd(Eigen::Matrix<double, 6, 1>::Random());
    const std::vector<double> root2 = mbc2.q[0];
    const auto conv = rbd::ConfigConverter::sConstructor(mb1, mb2);
    conv.sConvert(mbc1, mbc2);
    EXPECT_EQ(mbc2.q[0], root2);
    EXPECT_EQ(static_cast<int>(conv.jointMap().size()), mb1.nrJoints() - 1);
    for(int i = 1; i < mb1.nrJoints(); ++i)
    {
      const auto k = static_cast<std::size_t>(mb2.jointIndexByName(mb1.joint(i).name()));
      const auto j = static_cast<std::size_t>(i);
      EXPECT_EQ(mbc2.q[k], mbc1.q[j]);
      EXPECT_EQ(mbc2.alpha[k], mbc1.alpha[j]);
      EXPECT_EQ(mbc2.alphaD[k], mbc1.alphaD[j]);
      EXPECT_EQ(mbc2.jointTorque[k], mbc1.jointTorque[j]);
    }
    for(int i = 0; i < mb1.nrBodies(); ++i)
      EXPECT_EQ(mbc2.force[static_cast<std::size_t>(mb2.bodyIndexByName(mb1.body(i).name()))], mbc1.force[static_cast<std::size_t>(i)]);

    // Same relative placement: X_0_b (original frames) relative to b0's, in both models.
    rbd::forwardKinematics(mb1, mbc1);
    rbd::forwardKinematics(mb2, mbc2);
    const auto bt1 = g.bodiesBaseTransform("b0"), bt2 = g.bodiesBaseTransform("b7");
    auto rel = [&](const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc, const std::map<std::string, sva::PTransformd> & bt,
                   const std::string & b) {
      auto pose = [&](const std::string & n) {
        return bt.at(n) * mbc.bodyPosW[static_cast<std::size_t>(mb.bodyIndexByName(n))];
      };
      return pose(b) * pose("b0").inv();
    };
    for(const auto & b : g.bodies())
      EXPECT_MAT_NEAR(rel(mb2, mbc2, bt2, b.name()).matrix(), rel(mb1, mbc1, bt1, b.name()).matrix(), 1e-12) << b.name();
  }
}

TEST(ConfigConverter, CheckedVariantsReject)
{
  rbdtest::Rng rng(45);
  rbd::MultiBodyGraph g = mixedGraph(rng, 6);
  const rbd::MultiBody mb1 = g.makeMultiBody("b0", true), mb2 = g.makeMultiBody("b5", true);
  rbd::MultiBodyGraph smaller = g;
  smaller.removeJoint("b0", "j5");
  const rbd::MultiBody mb3 = smaller.makeMultiBody("b0", true);
  EXPECT_THROW(rbd::ConfigConverter::sConstructor(mb1, mb3), std::domain_error);
  EXPECT_THROW(rbd::ConfigConverter::sConstructor(mb3, mb1), std::domain_error);
  // The unchecked constructor converts what the two have in common.
  EXPECT_EQ(static_cast<int>(rbd::ConfigConverter(mb1, mb3).jointMap().size()), mb3.nrJoints() - 1);

  const auto conv = rbd::ConfigConverter::sConstructor(mb1, mb2);
  rbd::MultiBodyConfig mbc1(mb1), mbc2(mb2), wrong(mb3);
  EXPECT_NO_THROW(conv.sConvert(mbc1, mbc2));
  EXPECT_THROW(conv.sConvert(wrong, mbc2), std::domain_error);
  EXPECT_THROW(conv.sConvert(mbc1, wrong), std::domain_error);

  // long double works the same way.
  const auto mbl1 = mb1.cast<long double>(), mbl2 = mb2.cast<long double>();
  rbd::MultiBodyConfigTpl<long double> l1(mbl1), l2(mbl2);
  l1.q[1].assign(l1.q[1].size(), 0.25L);
  rbd::ConfigConverterTpl<long double>::sConstructor(mbl1, mbl2).sConvert(l1, l2);
  EXPECT_EQ(l2.q[static_cast<std::size_t>(mbl2.jointIndexByName(mbl1.joint(1).name()))], l1.q[1]);
}
