// Choice of the base link: the same robot rooted at every link gives the same link poses (fixed
// base: up to the base transform), the same link velocities and kinetic energy, and mass matrices
// related by the velocity map P (M_B = P^T M_A P, P = d alpha_A / d alpha_B) for a floating base.
#include <sstream>

#include <gtest/gtest.h>

#include "LoaderTestUtil.h"
#include "TestModels.h"

using namespace loadertest;
using rbd::parsers::fromUrdfFile;
using rbd::parsers::fromUrdfString;
using rbd::parsers::ParserOptions;
using rbd::parsers::ParserResult;

namespace
{

// base --rev--> a --prism--> b --cont--> c          (a small tree with every 1-dof type,
//   \--planar--> d --fixed--> e --rev--> f           a planar joint and a fixed joint in the
//                                                     middle; every link has mass)
std::string smallTree()
{
  auto link = [](const std::string & n, double m, const std::string & com) {
    return "<link name=\"" + n + "\"><inertial><origin xyz=\"" + com + "\" rpy=\"0.3 -0.2 0.5\"/><mass value=\"" +
           std::to_string(m) + "\"/><inertia ixx=\"0.02\" ixy=\"0.001\" ixz=\"0\" iyy=\"0.03\" iyz=\"-0.002\" izz=\"0.025\"/>"
           "</inertial></link>";
  };
  auto joint = [](const std::string & n, const std::string & type, const std::string & p, const std::string & c,
                  const std::string & xyz, const std::string & rpyText, const std::string & axis) {
    return "<joint name=\"" + n + "\" type=\"" + type + "\"><parent link=\"" + p + "\"/><child link=\"" + c +
           "\"/><origin xyz=\"" + xyz + "\" rpy=\"" + rpyText + "\"/><axis xyz=\"" + axis +
           "\"/><limit lower=\"-2\" upper=\"2\" effort=\"1\" velocity=\"1\"/></joint>";
  };
  return "<robot name=\"tree\">" + link("base", 3, "0.01 0.02 -0.03") + link("a", 1.2, "0.1 0 0") + link("b", 0.8, "0 0.1 0.05") +
         link("c", 0.5, "0.02 0.03 0.1") + link("d", 1.0, "-0.05 0 0.02") + link("e", 0.3, "0 0 0.04") + link("f", 0.6, "0.1 0.1 0") +
         joint("ja", "revolute", "base", "a", "0.2 0 0.1", "0.5 0 0.2", "0 0 1") +
         joint("jb", "prismatic", "a", "b", "0.3 0.1 0", "0 0.4 0", "0.6 0.8 0") +
         joint("jc", "continuous", "b", "c", "0 0 0.2", "-0.3 0.2 0.1", "1 0 0") +
         joint("jd", "planar", "base", "d", "-0.2 0.1 0", "0.1 0.2 0.3", "0 0.6 0.8") +
         joint("je", "fixed", "d", "e", "0.1 0.1 0.1", "0.7 0 -0.4", "1 0 0") +
         joint("jf", "revolute", "e", "f", "0 0.2 0", "0 0 0.9", "0 1 0") + "</robot>";
}

std::vector<std::pair<std::string, ParserResult (*)(const ParserOptions &)>> models()
{
  return {
      {"smallTree", [](const ParserOptions & o) { return fromUrdfString(smallTree(), o, "tree.urdf"); }},
      {"all_joints",
       [](const ParserOptions & o) { return fromUrdfFile(std::string(RBDGEN_SOURCE_DIR) + "/robots/all_joints.urdf", o); }},
      {"quadruped",
       [](const ParserOptions & o) { return fromUrdfFile(std::string(RBDGEN_SOURCE_DIR) + "/robots/quadruped.urdf", o); }},
  };
}

ParserResult load(ParserResult (*f)(const ParserOptions &), bool fixed, const std::string & base)
{
  ParserOptions o;
  o.fixed = fixed;
  o.baseLink = base;
  return f(o);
}

} // namespace

// Fixed base: with the joint values copied by name, X_0_link(B) = X_0_link(A) X_0_base(A)^-1.
TEST(LoaderBase, FixedBaseEveryLinkSameRelativePoses)
{
  rbdtest::Rng rng(11);
  for(const auto & [name, f] : models())
  {
    const ParserResult A = load(f, true, "");
    rbd::MultiBodyConfig mbcA = A.mbc;
    rbdtest::randomState(rng, A.mb, mbcA, 1.5);
    rbd::forwardKinematics(A.mb, mbcA);
    for(const auto & b : A.mb.bodies())
    {
      SCOPED_TRACE(name + " rooted at " + b.name());
      const ParserResult B = load(f, true, b.name());
      ASSERT_EQ(B.mb.body(0).name(), b.name());
      EXPECT_EQ(B.mb.nrDof(), A.mb.nrDof());
      rbd::MultiBodyConfig mbcB = B.mbc;
      rbd::ConfigConverter::sConstructor(A.mb, B.mb).convert(mbcA, mbcB);
      rbd::forwardKinematics(B.mb, mbcB);
      const sva::PTransformd X_base_0 = linkPose(A, mbcA, A.mb.bodyIndexByName(b.name())).inv();
      for(int i = 0; i < A.mb.nrBodies(); ++i)
      {
        const int k = B.mb.bodyIndexByName(A.mb.body(i).name());
        EXPECT_MAT_NEAR(linkPose(B, mbcB, k).matrix(), (linkPose(A, mbcA, i) * X_base_0).matrix(), 1e-12)
            << A.mb.body(i).name();
      }
    }
  }
}

// Floating base: same world poses and velocities of every link, same kinetic energy, and
// M_B = P^T M_A P with P built column by column from the state map B -> A.
TEST(LoaderBase, FloatingBaseEveryLinkSameMotionAndMassMatrix)
{
  rbdtest::Rng rng(12);
  double worst = 0;
  for(const auto & [name, f] : models())
  {
    const ParserResult A = load(f, false, "");
    rbd::MultiBodyConfig mbcA = A.mbc;
    rbdtest::randomState(rng, A.mb, mbcA, 1.5, 1.0);
    rbd::forwardKinematics(A.mb, mbcA);
    rbd::forwardVelocity(A.mb, mbcA);
    const Eigen::MatrixXd MA = massMatrixFromVelocities(A.mb, mbcA);
    for(const auto & b : A.mb.bodies())
    {
      SCOPED_TRACE(name + " rooted at " + b.name());
      const ParserResult B = load(f, false, b.name());
      rbd::MultiBodyConfig mbcB = B.mbc;
      mapFloatingState(A, mbcA, B, mbcB);
      rbd::forwardKinematics(B.mb, mbcB);
      rbd::forwardVelocity(B.mb, mbcB);
      for(int i = 0; i < A.mb.nrBodies(); ++i)
      {
        const std::string & link = A.mb.body(i).name();
        const int k = B.mb.bodyIndexByName(link);
        EXPECT_MAT_NEAR(linkPose(B, mbcB, k).matrix(), linkPose(A, mbcA, i).matrix(), 1e-12) << link;
        // Link velocity in link coordinates: X_j_link v_j with X_j_link = X_b_j^-1.
        const auto vA = A.bodyBaseTransforms.at(link).inv() * mbcA.bodyVelB[static_cast<std::size_t>(i)];
        const auto vB = B.bodyBaseTransforms.at(link).inv() * mbcB.bodyVelB[static_cast<std::size_t>(k)];
        EXPECT_MAT_NEAR(vB.vector(), vA.vector(), 1e-12) << link;
      }
      EXPECT_NEAR(kineticEnergy(B.mb, mbcB), kineticEnergy(A.mb, mbcA), 1e-12);

      // P: alpha_A for each unit alpha_B at the mapped configuration.
      const int n = B.mb.nrDof();
      Eigen::MatrixXd P(A.mb.nrDof(), n);
      rbd::MultiBodyConfig unitB = mbcB, backA = mbcA;
      for(int c = 0; c < n; ++c)
      {
        unitB.alpha = rbd::vectorToDof(B.mb, Eigen::VectorXd(Eigen::VectorXd::Unit(n, c)));
        rbd::forwardVelocity(B.mb, unitB);
        mapFloatingState(B, unitB, A, backA);
        P.col(c) = rbd::dofToVector(A.mb, backA.alpha);
      }
      // The round trip A -> B -> A gives back every joint pose (q up to the quaternion sign).
      for(int j = 0; j < A.mb.nrJoints(); ++j)
        EXPECT_MAT_NEAR(A.mb.joint(j).pose(backA.q[static_cast<std::size_t>(j)]).matrix(),
                        A.mb.joint(j).pose(mbcA.q[static_cast<std::size_t>(j)]).matrix(), 1e-12);
      const Eigen::MatrixXd MB = massMatrixFromVelocities(B.mb, mbcB);
      const Eigen::MatrixXd PtMP = P.transpose() * MA * P;
      EXPECT_MAT_NEAR(MB, PtMP, 1e-11);
      worst = std::max(worst, rbdtest::relErr(MB, PtMP));
    }
  }
  std::ostringstream os;
  os << worst;
  RecordProperty("worst_mass_matrix_relative_error", os.str());
}

// A base rigidly attached to another one gives the same mass matrix up to the order of the joints:
// in all_joints, link_fixed_b is welded to "base" by two fixed joints. Rooted at link_fixed_b
// (fixed), "base" is welded to the world; rooted at "world" (fixed), "base" is held when the
// floating_base_joint velocity is zero, so the blocks of every other joint must agree.
TEST(LoaderBase, RigidlyAttachedBaseSameMassMatrixUpToOrder)
{
  const std::string file = std::string(RBDGEN_SOURCE_DIR) + "/robots/all_joints.urdf";
  ParserOptions o;
  const ParserResult A = fromUrdfFile(file, o);
  o.baseLink = "link_fixed_b";
  const ParserResult B = fromUrdfFile(file, o);
  rbdtest::Rng rng(13);
  rbd::MultiBodyConfig mbcA = A.mbc, mbcB = B.mbc;
  rbdtest::randomState(rng, A.mb, mbcA, 1.5);
  rbd::ConfigConverter(A.mb, B.mb).convert(mbcA, mbcB);
  rbd::forwardKinematics(A.mb, mbcA);
  rbd::forwardKinematics(B.mb, mbcB);
  const Eigen::MatrixXd MA = massMatrixFromVelocities(A.mb, mbcA), MB = massMatrixFromVelocities(B.mb, mbcB);
  // Dof index of each (joint, k) of A in B, but the floating_base_joint.
  std::vector<int> ia, ib;
  for(int j = 1; j < A.mb.nrJoints(); ++j)
  {
    if(A.mb.joint(j).name() == "floating_base_joint") continue;
    const int jb = B.mb.jointIndexByName(A.mb.joint(j).name());
    for(int k = 0; k < A.mb.joint(j).dof(); ++k)
    {
      ia.push_back(A.mb.jointPosInDof(j) + k);
      ib.push_back(B.mb.jointPosInDof(jb) + k);
    }
  }
  ASSERT_EQ(static_cast<int>(ia.size()), A.mb.nrDof() - 6);
  Eigen::MatrixXd subA(ia.size(), ia.size()), subB(ia.size(), ia.size());
  for(std::size_t r = 0; r < ia.size(); ++r)
    for(std::size_t c = 0; c < ia.size(); ++c)
    {
      subA(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = MA(ia[r], ia[c]);
      subB(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = MB(ib[r], ib[c]);
    }
  EXPECT_MAT_NEAR(subB, subA, 1e-12);
}
