// URDF -> model conversion against hand computations: inertias (rotated inertial frames), link
// poses (rpy conventions), limits, dynamics, mimics, warnings and the filteredLinks option.
#include <limits>

#include <gtest/gtest.h>

#include "LoaderTestUtil.h"
#include "TestModels.h"

using namespace loadertest;
using rbd::parsers::fromUrdfString;
using rbd::parsers::ParserOptions;

namespace
{

const double inf = std::numeric_limits<double>::infinity();

std::string robot(const std::string & body) { return "<robot name=\"test\">" + body + "</robot>"; }

std::string inertial(const std::string & xyz, const std::string & rpyText, double m, const std::string & inertia)
{
  return "<inertial><origin xyz=\"" + xyz + "\" rpy=\"" + rpyText + "\"/><mass value=\"" + std::to_string(m) +
         "\"/><inertia " + inertia + "/></inertial>";
}

} // namespace

// A principal inertia diag(1, 2, 3) whose frame is yawed by +90 deg: the inertial x axis lies along
// the link y axis, so in link axes Ixx = 2, Iyy = 1; the CoM offset adds m (|c|^2 1 - c c^T).
TEST(LoaderConversion, InertiaRotatedQuarterTurnClosedForm)
{
  const auto r = fromUrdfString(robot("<link name=\"a\">" +
                                      inertial("0 0 0.5", "0 0 1.5707963267948966", 2.0,
                                               "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"3\"") +
                                      "</link>"));
  const sva::RBInertiad & I = r.mb.body(0).inertia();
  EXPECT_DOUBLE_EQ(I.mass(), 2.0);
  EXPECT_MAT_NEAR(I.momentum(), Eigen::Vector3d(0, 0, 1.0), 1e-15);
  // m (|c|^2 1 - c c^T) with c = (0, 0, 0.5): diag(0.5, 0.5, 0).
  EXPECT_MAT_NEAR(I.inertia(), Eigen::Vector3d(2.5, 1.5, 3.0).asDiagonal().toDenseMatrix(), 1e-15);
}

// General case: I_o = R I_c R^T + m (|c|^2 1 - c c^T), R from hand-written rpy matrices.
TEST(LoaderConversion, InertiaGeneralRotatedFrame)
{
  const double m = 2.5;
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  const Eigen::Matrix3d R = rpy(0.3, -0.5, 0.7);
  Eigen::Matrix3d Ic;
  Ic << 0.3, 0.01, -0.02, 0.01, 0.4, 0.03, -0.02, 0.03, 0.5;
  const auto r = fromUrdfString(robot(
      "<link name=\"base\"/><joint name=\"j\" type=\"fixed\"><parent link=\"base\"/><child link=\"a\"/>"
      "<origin xyz=\"1 2 3\" rpy=\"0.1 0.2 0.3\"/></joint><link name=\"a\">" +
      inertial("0.1 -0.2 0.3", "0.3 -0.5 0.7", m,
               "ixx=\"0.3\" ixy=\"0.01\" ixz=\"-0.02\" iyy=\"0.4\" iyz=\"0.03\" izz=\"0.5\"") +
      "</link>"));
  const sva::RBInertiad & I = r.mb.body(r.mb.bodyIndexByName("a")).inertia();
  const Eigen::Matrix3d expected = R * Ic * R.transpose() + m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  EXPECT_DOUBLE_EQ(I.mass(), m);
  EXPECT_MAT_NEAR(I.momentum(), Eigen::Vector3d(m * c), 1e-15);
  EXPECT_MAT_NEAR(I.inertia(), expected, 1e-14);
  // A link without <inertial> gets a zero inertia.
  EXPECT_TRUE(r.mb.body(r.mb.bodyIndexByName("base")).inertia().matrix().isZero(0.0));
}

// rpy conventions on closed forms: yaw 90 deg puts the child x axis along the parent y axis, roll
// 90 deg puts the child y axis along the parent z axis. sva: E = R^T, r = xyz.
TEST(LoaderConversion, OriginRpyClosedForms)
{
  const auto r = fromUrdfString(robot(
      "<link name=\"base\"/>"
      "<joint name=\"jy\" type=\"fixed\"><parent link=\"base\"/><child link=\"yawed\"/>"
      "<origin xyz=\"1 0 0\" rpy=\"0 0 1.5707963267948966\"/></joint><link name=\"yawed\"/>"
      "<joint name=\"jr\" type=\"fixed\"><parent link=\"base\"/><child link=\"rolled\"/>"
      "<origin xyz=\"0 2 0\" rpy=\"1.5707963267948966 0 0\"/></joint><link name=\"rolled\"/>"));
  const auto & X_y = r.mbc.bodyPosW[static_cast<std::size_t>(r.mb.bodyIndexByName("yawed"))];
  const auto & X_r = r.mbc.bodyPosW[static_cast<std::size_t>(r.mb.bodyIndexByName("rolled"))];
  Eigen::Matrix3d Ryaw, Rroll; // columns: child axes in parent coordinates
  Ryaw << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  Rroll << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_MAT_NEAR(X_y.rotation(), Eigen::Matrix3d(Ryaw.transpose()), 1e-15);
  EXPECT_MAT_NEAR(X_y.translation(), Eigen::Vector3d(1, 0, 0), 0.0);
  EXPECT_MAT_NEAR(X_r.rotation(), Eigen::Matrix3d(Rroll.transpose()), 1e-15);
  EXPECT_MAT_NEAR(X_r.translation(), Eigen::Vector3d(0, 2, 0), 0.0);
}

// FK of a 4-link chain (revolute with a non-unit axis, prismatic, continuous, fixed) against
// homogeneous transforms multiplied by hand: T_0_i = T_0_p * [R_o p_o] * [joint motion].
TEST(LoaderConversion, ForwardKinematicsMatchesHandComputedPoses)
{
  const std::string lim = "<limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/>";
  const auto r = fromUrdfString(robot(
      "<link name=\"base\"/>"
      "<joint name=\"j1\" type=\"revolute\"><parent link=\"base\"/><child link=\"l1\"/>"
      "<origin xyz=\"0.1 0.2 0.3\" rpy=\"0.4 -0.5 0.6\"/><axis xyz=\"0 0 2\"/>" + lim + "</joint><link name=\"l1\"/>"
      "<joint name=\"j2\" type=\"prismatic\"><parent link=\"l1\"/><child link=\"l2\"/>"
      "<origin xyz=\"-0.3 0.05 0.2\" rpy=\"1.0 0.2 -0.3\"/><axis xyz=\"1 1 0\"/>" + lim + "</joint><link name=\"l2\"/>"
      "<joint name=\"j3\" type=\"continuous\"><parent link=\"l2\"/><child link=\"l3\"/>"
      "<origin xyz=\"0 0 0.4\" rpy=\"0 1.5707963267948966 0\"/><axis xyz=\"0.6 0 0.8\"/></joint><link name=\"l3\"/>"
      "<joint name=\"j4\" type=\"fixed\"><parent link=\"l3\"/><child link=\"tip\"/>"
      "<origin xyz=\"0.05 -0.1 0.15\" rpy=\"-0.2 0.3 0.9\"/></joint><link name=\"tip\"/>"));
  const double q1 = 0.7, d2 = -0.15, q3 = 1.9;
  rbd::MultiBodyConfig mbc = r.mbc;
  mbc.q[static_cast<std::size_t>(r.mb.jointIndexByName("j1"))] = {q1};
  mbc.q[static_cast<std::size_t>(r.mb.jointIndexByName("j2"))] = {d2};
  mbc.q[static_cast<std::size_t>(r.mb.jointIndexByName("j3"))] = {q3};
  rbd::forwardKinematics(r.mb, mbc);

  auto T = [](const Eigen::Matrix3d & R, const Eigen::Vector3d & p) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = R;
    m.topRightCorner<3, 1>() = p;
    return m;
  };
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d z3 = Eigen::Vector3d::Zero();
  const Eigen::Matrix4d T1 = T(rpy(0.4, -0.5, 0.6), {0.1, 0.2, 0.3}) * T(axisAngle({0, 0, 1}, q1), z3);
  const Eigen::Matrix4d T2 =
      T1 * T(rpy(1.0, 0.2, -0.3), {-0.3, 0.05, 0.2}) * T(I3, Eigen::Vector3d(1, 1, 0).normalized() * d2);
  const Eigen::Matrix4d T3 = T2 * T(rpy(0, M_PI / 2, 0), {0, 0, 0.4}) * T(axisAngle({0.6, 0, 0.8}, q3), z3);
  const Eigen::Matrix4d T4 = T3 * T(rpy(-0.2, 0.3, 0.9), {0.05, -0.1, 0.15});
  const std::map<std::string, Eigen::Matrix4d> expected{{"l1", T1}, {"l2", T2}, {"l3", T3}, {"tip", T4}};
  for(const auto & [name, Te] : expected)
  {
    SCOPED_TRACE(name);
    const auto & X = mbc.bodyPosW[static_cast<std::size_t>(r.mb.bodyIndexByName(name))];
    EXPECT_MAT_NEAR(X.rotation(), Eigen::Matrix3d(Te.topLeftCorner<3, 3>().transpose()), 1e-14);
    EXPECT_MAT_NEAR(X.translation(), Eigen::Vector3d(Te.topRightCorner<3, 1>()), 1e-14);
  }
  // The URDF axes are normalised.
  EXPECT_MAT_NEAR(r.mb.joint(r.mb.jointIndexByName("j1")).axis(), Eigen::Vector3d(0, 0, 1), 0.0);
}

TEST(LoaderConversion, JointTypesLimitsDynamicsAndMimicKept)
{
  const auto r = fromUrdfString(robot(
      "<link name=\"base\">" + inertial("0 0 0", "0 0 0", 1, "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"") +
      "</link>"
      "<joint name=\"rev\" type=\"revolute\"><parent link=\"base\"/><child link=\"a\"/><axis xyz=\"0 1 0\"/>"
      "<limit lower=\"-1\" upper=\"2\" effort=\"10\" velocity=\"3\"/><dynamics damping=\"0.7\" friction=\"0.2\"/></joint>"
      "<link name=\"a\">" + inertial("0.1 0 0", "0 0 0", 1, "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"") +
      "</link>"
      "<joint name=\"cont\" type=\"continuous\"><parent link=\"base\"/><child link=\"b\"/>"
      "<limit effort=\"5\" velocity=\"4\"/><mimic joint=\"rev\" multiplier=\"-2\" offset=\"0.5\"/></joint>"
      "<link name=\"b\">" + inertial("0 0.1 0", "0 0 0", 1, "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"") +
      "</link>"
      "<joint name=\"prism\" type=\"prismatic\"><parent link=\"base\"/><child link=\"c\"/><axis xyz=\"0 0 1\"/>"
      "<limit lower=\"-0.1\" upper=\"0.2\" effort=\"100\" velocity=\"0.5\"/></joint>"
      "<link name=\"c\">" + inertial("0 0 0", "0 0 0", 1, "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"") +
      "</link>"
      "<joint name=\"plan\" type=\"planar\"><parent link=\"base\"/><child link=\"d\"/><axis xyz=\"0 0 1\"/></joint>"
      "<link name=\"d\">" + inertial("0 0 0", "0 0 0", 1, "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"") +
      "</link>"
      "<joint name=\"float\" type=\"floating\"><parent link=\"base\"/><child link=\"e\"/></joint>"
      "<link name=\"e\">" + inertial("0 0 0", "0 0 0", 1, "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"") +
      "</link>"
      "<joint name=\"fix\" type=\"fixed\"><parent link=\"base\"/><child link=\"f\"/></joint><link name=\"f\"/>"));
  const auto & mb = r.mb;
  EXPECT_EQ(r.name, "test");
  EXPECT_EQ(mb.joint(mb.jointIndexByName("rev")).type(), rbd::Joint::Rev);
  EXPECT_EQ(mb.joint(mb.jointIndexByName("cont")).type(), rbd::Joint::Rev);
  EXPECT_EQ(mb.joint(mb.jointIndexByName("prism")).type(), rbd::Joint::Prism);
  EXPECT_EQ(mb.joint(mb.jointIndexByName("plan")).type(), rbd::Joint::Planar);
  EXPECT_EQ(mb.joint(mb.jointIndexByName("float")).type(), rbd::Joint::Free);
  EXPECT_EQ(mb.joint(mb.jointIndexByName("fix")).type(), rbd::Joint::Fixed);
  EXPECT_MAT_NEAR(mb.joint(mb.jointIndexByName("plan")).axis(), Eigen::Vector3d(0, 0, 1), 0.0);
  // URDF default axis (1 0 0) when <axis> is absent.
  EXPECT_MAT_NEAR(mb.joint(mb.jointIndexByName("cont")).axis(), Eigen::Vector3d(1, 0, 0), 0.0);
  EXPECT_EQ(mb.nrDof(), 1 + 1 + 1 + 3 + 6);

  const auto & L = r.limits;
  using V = std::vector<double>;
  EXPECT_EQ(L.lower.at("rev"), V{-1});
  EXPECT_EQ(L.upper.at("rev"), V{2});
  EXPECT_EQ(L.velocity.at("rev"), V{3});
  EXPECT_EQ(L.torque.at("rev"), V{10});
  EXPECT_EQ(L.lower.at("cont"), V{-inf});
  EXPECT_EQ(L.upper.at("cont"), V{inf});
  EXPECT_EQ(L.velocity.at("cont"), V{4});
  EXPECT_EQ(L.torque.at("cont"), V{5});
  EXPECT_EQ(L.lower.at("prism"), V{-0.1});
  EXPECT_EQ(L.upper.at("prism"), V{0.2});
  EXPECT_EQ(L.lower.at("plan"), V(3, -inf));
  EXPECT_EQ(L.velocity.at("plan"), V(3, inf));
  EXPECT_EQ(L.upper.at("float"), V(7, inf));
  EXPECT_EQ(L.torque.at("float"), V(6, inf));
  EXPECT_EQ(L.lower.count("fix"), 0u);

  ASSERT_EQ(r.dynamics.count("rev"), 1u);
  EXPECT_EQ(r.dynamics.at("rev").damping, 0.7);
  EXPECT_EQ(r.dynamics.at("rev").friction, 0.2);
  EXPECT_EQ(r.dynamics.count("prism"), 0u);
  ASSERT_EQ(r.mimics.size(), 1u);
  EXPECT_EQ(r.mimics.at("cont").joint, "rev");
  EXPECT_EQ(r.mimics.at("cont").multiplier, -2);
  EXPECT_EQ(r.mimics.at("cont").offset, 0.5);
  EXPECT_TRUE(r.warnings.empty()); // coupled by coupleMimics(), tests/loader/test_mimic_coupling.cpp
}

// A massless link moved by a revolute joint with nothing beyond it: the mass matrix checks report
// it (generator/src/model/MassMatrixChecks.h, tested in tests/generator_unit), not the loader, so
// that `rbdgen generate` says it once.
TEST(LoaderConversion, MasslessLeafIsNotALoaderWarning)
{
  const std::string lim = "<limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/>";
  const auto r = fromUrdfString(robot(
      "<link name=\"base\"/><joint name=\"j\" type=\"revolute\"><parent link=\"base\"/><child link=\"ghost\"/>" + lim +
      "</joint><link name=\"ghost\"/>"
      "<joint name=\"s\" type=\"fixed\"><parent link=\"base\"/><child link=\"sensor\"/></joint><link name=\"sensor\"/>"),
      {}, "leaf.urdf");
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.size();
}

// filteredLinks: removal drops the subtree; merging keeps the world-frame spatial inertia at q = 0.
TEST(LoaderConversion, FilteredLinksRemovedOrMerged)
{
  const std::string file = std::string(RBDGEN_SOURCE_DIR) + "/robots/all_joints.urdf";
  ParserOptions opt;
  const auto full = rbd::parsers::fromUrdfFile(file, opt);
  opt.filteredLinks = {"link_px", "link_rgen"};
  const auto removed = rbd::parsers::fromUrdfFile(file, opt);
  opt.removeFilteredLinks = false;
  const auto merged = rbd::parsers::fromUrdfFile(file, opt);

  // Subtrees beyond link_px and link_rgen, read off the file: link_px {link_px, link_pgen,
  // link_planar_x, ...} — count them independently from the full model's parents.
  auto inSubtree = [&](int i, const std::string & top) {
    for(; i >= 0; i = full.mb.parent(i))
      if(full.mb.body(i).name() == top) return true;
    return false;
  };
  int gone = 0;
  for(int i = 0; i < full.mb.nrBodies(); ++i) gone += inSubtree(i, "link_px") || inSubtree(i, "link_rgen");
  EXPECT_GT(gone, 2);
  EXPECT_EQ(removed.mb.nrBodies(), full.mb.nrBodies() - gone);
  EXPECT_EQ(merged.mb.nrBodies(), full.mb.nrBodies() - gone);
  EXPECT_FALSE(removed.mb.hasBody("link_px"));
  EXPECT_FALSE(removed.mb.hasBody("tool_tip"));

  // World-frame spatial inertia sum_i X_0_i^T I_i X_0_i at q = 0.
  auto worldInertia = [](const rbd::parsers::ParserResult & r) {
    sva::RBInertiad I(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
    for(int i = 0; i < r.mb.nrBodies(); ++i)
      I = I + r.mbc.bodyPosW[static_cast<std::size_t>(i)].transMul(r.mb.body(i).inertia());
    return I.matrix();
  };
  EXPECT_MAT_NEAR(worldInertia(merged), worldInertia(full), 1e-13);
  EXPECT_LT(worldInertia(removed)(5, 5), worldInertia(full)(5, 5) - 0.5);
}
