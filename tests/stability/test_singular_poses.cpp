// Singular arm poses (Jacobian rank loss): the Jacobian stays exact against a closed form and
// against finite differences of forward kinematics, and every dynamics output stays finite and
// accurate (a kinematic singularity does not make H singular; nothing divides by zero).
#include "StabilityUtils.h"

namespace
{

using stab::LD;

/// Planar arm: revolute joints about z, link k along x with length L[k]; the end effector is
/// the last body (a zero-length link after the last joint is not needed: we take its origin).
rbd::MultiBody planarArm(rbdtest::Rng & rng, const std::vector<double> & L)
{
  rbd::MultiBodyGraph g;
  const int n = static_cast<int>(L.size());
  for(int k = 0; k <= n; ++k) g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b" + std::to_string(k)));
  for(int k = 1; k <= n; ++k)
  {
    const std::string jn = "j" + std::to_string(k);
    g.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitZ(), true, jn));
    // joint 1 at the base origin; joint k > 1 at the end of link k-1
    const Eigen::Vector3d offset = k == 1 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(L[static_cast<std::size_t>(k - 2)], 0, 0);
    g.linkBodies("b" + std::to_string(k - 1), sva::PTransformd(offset), "b" + std::to_string(k), sva::PTransformd::Identity(), jn);
  }
  // the tool point at the end of the last link, on a fixed joint
  g.addBody(rbd::Body(rbdtest::randomInertia(rng), "tool"));
  g.addJoint(rbd::Joint(rbd::Joint::Fixed, true, "tool_joint"));
  g.linkBodies("b" + std::to_string(n), sva::PTransformd(Eigen::Vector3d(L.back(), 0, 0)), "tool",
               sva::PTransformd::Identity(), "tool_joint");
  return g.makeMultiBody("b0", true);
}

/// Closed-form world Jacobian of the tool point of planarArm (angles theta_k = sum q_1..q_k):
/// angular rows [0 0 1], linear column j = z x (p_tool - p_j).
Eigen::MatrixXd planarJacobian(const std::vector<double> & L, const std::vector<double> & q)
{
  const std::size_t n = L.size();
  std::vector<Eigen::Vector3d> p(n + 1, Eigen::Vector3d::Zero()); // p[j]: joint j+1, p[n]: tool
  double theta = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    theta += q[k];
    p[k + 1] = p[k] + L[k] * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0);
  }
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, static_cast<Eigen::Index>(n));
  for(std::size_t j = 0; j < n; ++j)
  {
    const auto c = static_cast<Eigen::Index>(j);
    J(2, c) = 1;
    J.block<3, 1>(3, c) = Eigen::Vector3d::UnitZ().cross(p[n] - p[j]);
  }
  return J;
}

TEST(SingularPoses, StretchedAndFoldedPlanarArmJacobianIsExact)
{
  rbdtest::Rng rng(801);
  const std::vector<double> L{0.7, 0.5, 0.3};
  const rbd::MultiBody mb = planarArm(rng, L);
  // stretched (q = 0), folded back (q2 = pi), and both elbows folded: rank 2 in the plane.
  for(const std::vector<double> & q : {std::vector<double>{0, 0, 0}, std::vector<double>{0.4, M_PI, 0},
                                       std::vector<double>{-1.2, M_PI, M_PI}, std::vector<double>{2.0, 0, M_PI}})
  {
    rbd::MultiBodyConfig mbc(mb);
    mbc.zero(mb);
    for(std::size_t k = 0; k < q.size(); ++k) mbc.q[k + 1] = {q[k]};
    dyntest::kinematics(mb, mbc);
    rbd::Jacobian jac(mb, "tool");
    Eigen::MatrixXd J(6, mb.nrDof());
    jac.fullJacobian(mb, jac.jacobian(mb, mbc), J);
    ASSERT_TRUE(J.allFinite());
    // The closed form uses cos/sin of sums; entries are O(1): a few eps.
    EXPECT_MAT_NEAR(J, planarJacobian(L, q), 8 * stab::eps);
    // Rank loss: the linear rows are all along one direction (the arm's line), so the 2x3 planar
    // linear block has rank 1: its second singular value is 0 up to rounding.
    const Eigen::Vector2d sv = Eigen::JacobiSVD<Eigen::MatrixXd>(J.block(3, 0, 2, 3)).singularValues();
    EXPECT_LE(sv(1), 8 * stab::eps * sv(0));
    // Dynamics at the singular pose: accurate and finite (H is not singular there).
    rbdtest::randomState(rng, mb, mbc, 0.0, 2.0);
    for(std::size_t k = 0; k < q.size(); ++k) mbc.q[k + 1] = {q[k]};
    EXPECT_TRUE(stab::withinBounds(stab::compare(mb, mbc), stab::Bounds{50 * 4 * stab::eps, 100}));
  }
}

/// An anthropomorphic 6R arm with offsets (UR-like kinematics); wrist singular when q5 = 0
/// (axes 4 and 6 collinear), elbow singular when q3 = 0 (arm stretched), shoulder singular when
/// the wrist centre is on axis 1.
rbd::MultiBody urLikeArm(rbdtest::Rng & rng)
{
  const std::vector<Eigen::Vector3d> axes{Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY(),
                                          Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY()};
  const std::vector<Eigen::Vector3d> offsets{{0, 0, 0.16}, {0, 0.14, 0}, {0, -0.12, 0.42}, {0, 0, 0.39}, {0, 0.09, 0}, {0, 0, 0.09}};
  rbd::MultiBodyGraph g;
  g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b0"));
  for(int k = 1; k <= 6; ++k)
  {
    const auto s = static_cast<std::size_t>(k - 1);
    g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b" + std::to_string(k)));
    g.addJoint(rbd::Joint(rbd::Joint::Rev, axes[s], true, "j" + std::to_string(k)));
    g.linkBodies("b" + std::to_string(k - 1), sva::PTransformd(offsets[s]), "b" + std::to_string(k),
                 sva::PTransformd::Identity(), "j" + std::to_string(k));
  }
  return g.makeMultiBody("b0", true);
}

/// The world Jacobian of body b by central differences (Richardson, h = 1e-4) of long double FK:
/// column j = [omega; v] with omega^ = dR/dq_j R^T, v = dp/dq_j (R, p: body orientation/origin).
Eigen::MatrixXd finiteDifferenceJacobian(const rbd::MultiBodyTpl<LD> & mb, const rbd::MultiBodyConfigTpl<LD> & mbc, int b)
{
  Eigen::MatrixXd J(6, mb.nrDof());
  const auto q0 = mbc.q;
  rbd::MultiBodyConfigTpl<LD> c = mbc;
  for(int j = 1; j < mb.nrJoints(); ++j)
  {
    auto pose = [&](LD h) {
      c.q = q0;
      c.q[static_cast<std::size_t>(j)][0] += h;
      rbd::forwardKinematics(mb, c);
      const auto & X = c.bodyPosW[static_cast<std::size_t>(b)];
      Eigen::Matrix<LD, 3, 4> m;
      m << X.rotation().transpose(), X.translation();
      return m;
    };
    const Eigen::Matrix<LD, 3, 4> d = dyntest::derivative<LD>(pose, LD(1e-4));
    const Eigen::Matrix<LD, 3, 4> p0 = pose(0);
    const Eigen::Matrix<LD, 3, 3> W = d.leftCols<3>() * p0.leftCols<3>().transpose();
    const auto col = mb.jointPosInDof(j);
    J.block<3, 1>(0, col) = Eigen::Vector3d(double(W(2, 1)), double(W(0, 2)), double(W(1, 0)));
    J.block<3, 1>(3, col) = d.col(3).cast<double>();
  }
  return J;
}

TEST(SingularPoses, UrLikeArmJacobianMatchesFiniteDifferences)
{
  rbdtest::Rng rng(802);
  const rbd::MultiBody mb = urLikeArm(rng);
  const rbd::MultiBodyTpl<LD> mbL = dyntest::castModel<LD>(mb);
  // wrist (q5 = 0), elbow (q3 = 0), both, and a regular pose for contrast.
  const std::vector<std::vector<double>> poses{{0.3, -1.0, 1.2, 0.5, 0.0, 0.7},
                                               {0.3, -1.0, 0.0, 0.5, 1.1, 0.7},
                                               {0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
                                               {0.3, -1.0, 1.2, 0.5, 1.1, 0.7}};
  for(std::size_t p = 0; p < poses.size(); ++p)
  {
    SCOPED_TRACE(p);
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    for(int k = 1; k <= 6; ++k) mbc.q[static_cast<std::size_t>(k)] = {poses[p][static_cast<std::size_t>(k - 1)]};
    dyntest::kinematics(mb, mbc);
    rbd::Jacobian jac(mb, "b6");
    Eigen::MatrixXd J(6, 6);
    jac.fullJacobian(mb, jac.jacobian(mb, mbc), J);
    ASSERT_TRUE(J.allFinite());
    const Eigen::MatrixXd Jfd = finiteDifferenceJacobian(mbL, rbdtest::castInputs<LD>(mbL, mbc), 6);
    // Richardson central differences in long double with h = 1e-4: truncation O(h^4) ~ 1e-16
    // times the 5th derivatives (O(1) for lengths < 1 m), rounding u/h ~ 5e-16.
    EXPECT_MAT_NEAR(J, Jfd, 1e-13);
    const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(J).singularValues();
    if(p < 3) EXPECT_LE(sv(5), 8 * stab::eps * sv(0)) << "not singular? " << sv.transpose();
    else EXPECT_GT(sv(5), 1e-3 * sv(0)) << sv.transpose();
    // Dynamics there: accurate and finite.
    EXPECT_TRUE(stab::withinBounds(stab::compare(mb, mbc), stab::Bounds{50 * 7 * stab::eps, 100}));
  }
}

} // namespace
