// Mass matrix checks (generator/src/model/MassMatrixChecks.h) and the loader's use of a URDF's own
// floating joint as the floating base (issue 17, items 2 and 3). Expected values are independent of
// the code under test: dof counts from the URDF text, the runtime's mass matrix (CRBA) for rank,
// regularity and condition number, and closed forms for the effective inertia.
//
//   world (massless) --floating--> base (2 kg) --rev y--> arm (1 kg)     [floatingUrdf]
//   base (1 kg) --rev z--> link1 (1 kg) --rev z--> link2 (m kg)          [armUrdf(m)]
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/parsers/urdf.h>

#include "model/MassMatrixChecks.h"

namespace
{

std::string box(const std::string & name, double m, const std::string & com = "0 0 0")
{
  return "<link name=\"" + name + "\"><inertial><origin xyz=\"" + com + "\"/><mass value=\"" + std::to_string(m) +
         "\"/><inertia ixx=\"" + std::to_string(0.1 * m) + "\" iyy=\"" + std::to_string(0.1 * m) + "\" izz=\"" +
         std::to_string(0.1 * m) + "\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n";
}

/// A URDF with its own floating base: massless `world`, joint `floating_base` to `base`, one
/// revolute joint. extra: more text inside <robot> (e.g. a second massless child of world).
std::string floatingUrdf(const std::string & innerType = "floating", const std::string & extra = "")
{
  return "<robot name=\"fb\"><link name=\"world\"/>\n" + box("base", 2.0) + box("arm", 1.0, "0.3 0 0") +
         "<joint name=\"floating_base\" type=\"" + innerType + "\"><parent link=\"world\"/><child link=\"base\"/>"
         "<axis xyz=\"0 0 1\"/></joint>\n"
         "<joint name=\"elbow\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/><origin xyz=\"0.2 0 0\"/>"
         "<axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n" +
         extra + "</robot>";
}

/// The runtime's mass matrix at a seeded random configuration.
Eigen::MatrixXd runtimeH(const rbd::MultiBody & mb, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  rbd::MultiBodyConfig mbc(mb);
  mbc.zero(mb);
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    auto & q = mbc.q[static_cast<std::size_t>(i)];
    for(auto & x : q) x = u(rng);
    if(q.size() == 4 || q.size() == 7)
    {
      const Eigen::Vector4d v(q[0], q[1], q[2], q[3]);
      for(int k = 0; k < 4; ++k) q[static_cast<std::size_t>(k)] = v(k) / v.norm();
    }
  }
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
  rbd::ForwardDynamics fd(mb);
  fd.computeH(mb, mbc);
  return fd.H();
}

double cond(const Eigen::MatrixXd & H)
{
  const Eigen::VectorXd l = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly).eigenvalues();
  return l.minCoeff() > 0 ? l.maxCoeff() / l.minCoeff() : HUGE_VAL;
}

bool mentions(const std::vector<std::string> & lines, const std::string & a, const std::string & b = "")
{
  for(const auto & l : lines)
    if(l.find(a) != std::string::npos && l.find(b) != std::string::npos) return true;
  return false;
}

// --- item 2: two free joints ------------------------------------------------------------------

TEST(FloatingJointAsBase, UsedAsTheBaseWithAWarning)
{
  rbd::parsers::ParserOptions floating;
  floating.fixed = false;
  const auto r = rbd::parsers::fromUrdfString(floatingUrdf(), floating, "fb.urdf");
  // One free joint (6) + one revolute (1), as the URDF's author meant; not 6 + 6 + 1.
  EXPECT_EQ(r.mb.nrDof(), 7);
  EXPECT_EQ(r.mb.nrParams(), 8);
  EXPECT_EQ(r.mb.body(0).name(), "base");
  EXPECT_FALSE(r.mbg.hasBody("world"));
  ASSERT_TRUE(mentions(r.warnings, "joint 'floating_base'", "link 'world'")) << ::testing::PrintToString(r.warnings);
  EXPECT_TRUE(mentions(r.warnings, "fb.urdf: joint 'floating_base'", "rooted at link 'base'"));
  // The mass matrix is regular (positive definite) and equals the one of the URDF loaded with a
  // fixed world (the floating joint free there), the model its author wrote.
  rbd::parsers::ParserOptions fixedWorld;
  const auto ref = rbd::parsers::fromUrdfString(floatingUrdf(), fixedWorld, "fb.urdf");
  ASSERT_EQ(ref.mb.nrDof(), 7);
  for(unsigned seed = 1; seed <= 5; ++seed)
  {
    const Eigen::MatrixXd H = runtimeH(r.mb, seed), Href = runtimeH(ref.mb, seed);
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(H).info(), Eigen::Success);
    EXPECT_LT(cond(H), 1e4);
    EXPECT_LT((H - Href).cwiseAbs().maxCoeff(), 1e-12);
  }
  const rbdgen::MassMatrixReport rep = rbdgen::checkMassMatrix(r.mb);
  EXPECT_TRUE(rep.stackedFree.empty());
  EXPECT_TRUE(rep.negligible.empty());
}

TEST(FloatingJointAsBase, NotTouchedWithAFixedBaseOrAnotherBaseLink)
{
  const auto fixedBase = rbd::parsers::fromUrdfString(floatingUrdf(), {}, "fb.urdf");
  EXPECT_EQ(fixedBase.mb.nrDof(), 7); // fixed world, the URDF's free joint, the revolute
  EXPECT_TRUE(fixedBase.warnings.empty()) << ::testing::PrintToString(fixedBase.warnings);
  rbd::parsers::ParserOptions o;
  o.fixed = false;
  o.baseLink = "base";
  const auto other = rbd::parsers::fromUrdfString(floatingUrdf(), o, "fb.urdf");
  EXPECT_EQ(other.mb.nrDof(), 13); // Root free + the URDF's free joint (now backward) + revolute
}

TEST(StackedFreeJoints, DetectedAndTheMassMatrixIsSingular)
{
  // world has a second (massless) child: the loader leaves the tree alone, the check names the
  // two joints, and the runtime's H is rank deficient (6 of the 12 free dofs are redundant).
  const std::string marker = "<link name=\"marker\"/><joint name=\"mark\" type=\"fixed\"><parent link=\"world\"/>"
                             "<child link=\"marker\"/></joint>";
  rbd::parsers::ParserOptions o;
  o.fixed = false;
  const auto r = rbd::parsers::fromUrdfString(floatingUrdf("floating", marker), o, "fb.urdf");
  ASSERT_EQ(r.mb.nrDof(), 13);
  const rbdgen::MassMatrixReport rep = rbdgen::checkMassMatrix(r.mb);
  ASSERT_EQ(rep.stackedFree.size(), 1u);
  EXPECT_EQ(rep.stackedFree[0].first, "Root");
  EXPECT_EQ(rep.stackedFree[0].second, "floating_base");
  EXPECT_TRUE(mentions(rep.messages("fb.urdf"), "free joint 'Root'", "joint 'floating_base'"));
  for(unsigned seed = 1; seed <= 3; ++seed)
  {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(runtimeH(r.mb, seed));
    lu.setThreshold(1e-10);
    EXPECT_EQ(lu.rank(), 7);
  }
  // A planar joint under the massless link: 3 redundant dofs.
  const auto p = rbd::parsers::fromUrdfString(floatingUrdf("planar", marker), o, "fb.urdf");
  ASSERT_EQ(p.mb.nrDof(), 10);
  const rbdgen::MassMatrixReport repP = rbdgen::checkMassMatrix(p.mb);
  ASSERT_EQ(repP.stackedFree.size(), 1u);
  EXPECT_EQ(repP.stackedFree[0].second, "floating_base");
  Eigen::FullPivLU<Eigen::MatrixXd> lu(runtimeH(p.mb, 4));
  lu.setThreshold(1e-10);
  EXPECT_EQ(lu.rank(), 7);
  // The same world link with mass: no stacked joints, H regular.
  std::string text = floatingUrdf("floating", marker);
  const std::string world = "<link name=\"world\"/>";
  text.replace(text.find(world), world.size(), box("world", 1.0, "0 0.2 0"));
  const auto h = rbd::parsers::fromUrdfString(text, o, "fb.urdf");
  ASSERT_EQ(h.mb.nrDof(), 13);
  EXPECT_TRUE(rbdgen::checkMassMatrix(h.mb).stackedFree.empty());
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(runtimeH(h.mb, 5)).info(), Eigen::Success);
}

// --- item 3: near-massless bodies -------------------------------------------------------------

/// base (1 kg, fixed) -> link1 (1 kg, COM 0.5 m out) -> link2 (m kg, COM 0.1 m beyond joint2 at
/// 1 m, Izz = 1e-4 m): both revolute about z. L = 1.1 m (link2's COM), M = 2 + m.
std::string armUrdf(double m)
{
  char inertial[256];
  std::snprintf(inertial, sizeof(inertial),
                "<inertial><origin xyz=\"0.1 0 0\"/><mass value=\"%.17g\"/><inertia ixx=\"%.17g\" iyy=\"%.17g\" "
                "izz=\"%.17g\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>",
                m, 1e-4 * m, 1e-4 * m, 1e-4 * m);
  return "<robot name=\"arm\">" + box("base", 1.0) + box("link1", 1.0, "0.5 0 0") + "<link name=\"link2\">" + inertial +
         "</link><joint name=\"j1\" type=\"continuous\"><parent link=\"base\"/><child link=\"link1\"/><axis xyz=\"0 0 1\"/>"
         "</joint><joint name=\"j2\" type=\"continuous\"><parent link=\"link1\"/><child link=\"link2\"/>"
         "<origin xyz=\"1 0 0\"/><axis xyz=\"0 0 1\"/></joint></robot>";
}

TEST(NegligibleInertia, ClosedFormRatioConditionNumberAndThreshold)
{
  // cond(H) of the runtime's H at q = 0 and at random q against the ratio: the warning fires
  // exactly for the masses whose ratio is below 1e-9, and cond(H) >= H_11 / H_22 >= ~1/ratio.
  std::printf("  %-8s %-12s %-12s %-12s %s\n", "m (kg)", "ratio", "cond(H) q=0", "cond(H) max", "warns");
  for(const double m : {1.0, 1e-3, 1e-6, 1e-9, 1e-12})
  {
    const auto r = rbd::parsers::fromUrdfString(armUrdf(m), {}, "arm.urdf");
    const rbdgen::MassMatrixReport rep = rbdgen::checkMassMatrix(r.mb);
    const double M = 2 + m, L = 1.1;
    EXPECT_NEAR(rep.totalMass, M, 1e-12);
    EXPECT_NEAR(rep.length, L, 1e-12);
    // Closed form: S^T Ic S of j2 = Izz + m d^2 = m (1e-4 + 0.01).
    const double closed = m * (1e-4 + 0.01) / (M * L * L);
    ASSERT_EQ(rep.smallest.joint, "j2");
    EXPECT_NEAR(rep.smallest.ratio, closed, 1e-12 * closed);
    rbd::MultiBodyConfig mbc(r.mb);
    mbc.zero(r.mb);
    rbd::forwardKinematics(r.mb, mbc);
    rbd::ForwardDynamics fd(r.mb);
    fd.computeH(r.mb, mbc);
    EXPECT_NEAR(fd.H()(1, 1), m * (1e-4 + 0.01), 1e-14); // the runtime's CRBA agrees with the closed form
    double condMax = cond(fd.H());
    for(unsigned seed = 1; seed <= 5; ++seed) condMax = std::max(condMax, cond(runtimeH(r.mb, seed)));
    const bool warns = !rep.negligible.empty();
    EXPECT_EQ(warns, closed < rbdgen::kNegligibleRatio) << m;
    if(warns)
    {
      EXPECT_EQ(rep.negligible[0].joint, "j2");
      EXPECT_TRUE(mentions(rep.messages("arm.urdf"), "arm.urdf: joint 'j2': negligible effective inertia"));
    }
    EXPECT_GE(cond(fd.H()), 0.1 / closed) << m;
    std::printf("  %-8.0e %-12.2e %-12.2e %-12.2e %s\n", m, closed, cond(fd.H()), condMax, warns ? "yes" : "no");
  }
}

TEST(NegligibleInertia, MasslessSubtreeIsReportedSeparately)
{
  // A massless frame on a fixed joint (a sensor) is not reported.
  {
    std::string text = armUrdf(1.0);
    text.insert(text.find("</robot>"), "<link name=\"sensor\"/><joint name=\"s\" type=\"fixed\"><parent link=\"link2\"/>"
                                       "<child link=\"sensor\"/></joint>");
    const auto r = rbd::parsers::fromUrdfString(text, {}, "arm.urdf");
    EXPECT_TRUE(rbdgen::checkMassMatrix(r.mb).masslessSubtrees.empty());
  }
  const auto r = rbd::parsers::fromUrdfString(armUrdf(0.0), {}, "arm.urdf");
  const rbdgen::MassMatrixReport rep = rbdgen::checkMassMatrix(r.mb);
  EXPECT_EQ(rep.masslessSubtrees, std::vector<std::string>{"j2"});
  EXPECT_TRUE(rep.negligible.empty());
  EXPECT_TRUE(mentions(rep.messages("arm.urdf"), "arm.urdf: joint(s) 'j2' move only massless links"));
  Eigen::FullPivLU<Eigen::MatrixXd> lu(runtimeH(r.mb, 2));
  EXPECT_EQ(lu.rank(), 1);
}

} // namespace
