// RBDyn's Jacobian API beyond the root -> body Jacobian: Jacobian(mb, body, refBody) against the
// difference of the two root Jacobians at the same point expressed in the reference body's axes,
// its derivative against finite differences, subMultiBody against the full model restricted to the
// path (poses, world inertias, Jacobians), expand / expandAdd / compactPath, and the
// velocity / normal acceleration forms with an explicit frame, CoMJacobianDummy. Double and long double, random trees
// (every joint type, backward joints).
#include <rbd/CoM.h>
#include <rbd/Jacobian.h>

#include "KinExtTestUtils.h"

namespace
{

template<typename T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template<typename T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

template<typename T>
class JacobianApiTest : public ::testing::Test
{
};
TYPED_TEST_SUITE(JacobianApiTest, kinext::Scalars, );

constexpr int nrCases = 12;

/// A random tree with FK and FV done, two distinct bodies and a point.
template<typename T>
struct RefCase
{
  rbd::MultiBodyTpl<T> mb;
  rbd::MultiBodyConfigTpl<T> mbc;
  int body = 0, ref = 0;
  sva::Vector3<T> point;
};

template<typename T>
RefCase<T> refCase(rbdtest::Rng & rng)
{
  RefCase<T> c;
  int n = 0;
  do // with some dof (no block of an empty matrix below: Eigen offsets a null pointer)
  {
    n = std::uniform_int_distribution<int>(4, 9)(rng);
    c.mb = kinext::randomModel<T>(rng, n, kinext::randomRoot(rng));
  } while(c.mb.nrDof() == 0);
  c.mbc = rbd::MultiBodyConfigTpl<T>(c.mb);
  rbdtest::randomState(rng, c.mb, c.mbc);
  kinext::kin(c.mb, c.mbc);
  c.body = std::uniform_int_distribution<int>(0, n - 1)(rng);
  do
    c.ref = std::uniform_int_distribution<int>(0, n - 1)(rng);
  while(c.ref == c.body);
  c.point = rbdtest::randomTransform(rng, 0.3).translation().cast<T>();
  return c;
}

template<typename T>
MatX<T> full(const rbd::MultiBodyTpl<T> & mb, const rbd::JacobianTpl<T> & jac, const MatX<T> & compact)
{
  MatX<T> out;
  jac.fullJacobian(mb, compact, out);
  return out;
}

/// blkdiag(E, E) M
template<typename T>
MatX<T> rotateRows(const sva::Matrix3<T> & E, const MatX<T> & M)
{
  if(M.cols() == 0) return M;
  MatX<T> out(6, M.cols());
  out.topRows(3) = E * M.topRows(3);
  out.bottomRows(3) = E * M.bottomRows(3);
  return out;
}

// J_ref(body, ref, p) = blkdiag(E_0_ref) (J(body, p) - J(ref, p)) with both root Jacobians at the same
// world point (world axes); its body Jacobian is the same difference in body axes.
TYPED_TEST(JacobianApiTest, RefBodyJacobianIsTheDifferenceInTheReferenceFrame)
{
  using T = TypeParam;
  rbdtest::Rng rng(71);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = refCase<T>(rng);
    const auto & X_0_b = c.mbc.bodyPosW[static_cast<std::size_t>(c.body)];
    const auto & X_0_r = c.mbc.bodyPosW[static_cast<std::size_t>(c.ref)];
    // the same world point in ref coordinates
    const sva::Vector3<T> pW = X_0_b.translation() + X_0_b.rotation().transpose() * c.point;
    const sva::Vector3<T> pR = X_0_r.rotation() * (pW - X_0_r.translation());
    rbd::JacobianTpl<T> jb(c.mb, c.mb.body(c.body).name(), c.point), jr(c.mb, c.mb.body(c.ref).name(), pR);
    rbd::JacobianTpl<T> rel(c.mb, c.mb.body(c.body).name(), c.mb.body(c.ref).name(), c.point);
    const MatX<T> diffW = full(c.mb, jb, MatX<T>(jb.jacobian(c.mb, c.mbc))) - full(c.mb, jr, MatX<T>(jr.jacobian(c.mb, c.mbc)));
    EXPECT_MAT_NEAR(full(c.mb, rel, MatX<T>(rel.jacobian(c.mb, c.mbc))), rotateRows<T>(X_0_r.rotation(), diffW),
                    kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(full(c.mb, rel, MatX<T>(rel.bodyJacobian(c.mb, c.mbc))), rotateRows<T>(X_0_b.rotation(), diffW),
                    kinext::Prec<T>::exact);
    // no column of a joint above the common ancestor: its motion moves both bodies
    EXPECT_EQ(static_cast<int>(rel.jointsSign().size()), static_cast<int>(rel.jointsPath().size()));
    EXPECT_EQ(rel.refBodyIndex(), c.ref);
  }
}

// jacobianDot / bodyJacobianDot of a reference-body Jacobian: central differences along q ⊕ alpha t.
TYPED_TEST(JacobianApiTest, RefBodyJacobianDotMatchesFiniteDifference)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(72);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = refCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.mb.body(c.body).name(), c.mb.body(c.ref).name(), c.point);
    const auto p = kinext::along(c.mb, c.mbc, h), m = kinext::along(c.mb, c.mbc, -h);
    const MatX<T> Jp = jac.jacobian(c.mb, p), Jm = jac.jacobian(c.mb, m);
    const MatX<T> JBp = jac.bodyJacobian(c.mb, p), JBm = jac.bodyJacobian(c.mb, m);
    EXPECT_MAT_NEAR(jac.jacobianDot(c.mb, c.mbc), MatX<T>((Jp - Jm) / (2 * h)), kinext::Prec<T>::fd);
    EXPECT_MAT_NEAR(jac.bodyJacobianDot(c.mb, c.mbc), MatX<T>((JBp - JBm) / (2 * h)), kinext::Prec<T>::fd);
  }
}

// subMultiBody: a chain whose world is the reference frame (the world without one). With the path
// joints' q, its last body's pose is X_0_b X_0_ref^-1 (its frame moved onto the last joint's frame
// when that joint is reversed), each chain body carries the world inertia of the model's body of the
// same name (seen from the reference frame), and the chain's own root Jacobian of its last body at
// the same point equals the original Jacobian (body and reference axes).
TYPED_TEST(JacobianApiTest, SubMultiBodyIsThePathAsAChain)
{
  using T = TypeParam;
  rbdtest::Rng rng(73);
  for(int n = 0; n < 2 * nrCases; ++n)
  {
    auto c = refCase<T>(rng);
    const bool withRef = n % 2 == 1;
    const std::string body = c.mb.body(c.body).name(), ref = c.mb.body(c.ref).name();
    rbd::JacobianTpl<T> jac = withRef ? rbd::JacobianTpl<T>(c.mb, body, ref, c.point) : rbd::JacobianTpl<T>(c.mb, body, c.point);
    if(jac.jointsPath().empty()) continue;
    const rbd::MultiBodyTpl<T> chain = jac.sSubMultiBody(c.mb);
    ASSERT_EQ(chain.nrJoints(), static_cast<int>(jac.jointsPath().size()));
    EXPECT_EQ(chain.nrDof(), jac.dof());
    EXPECT_EQ(chain.body(chain.nrBodies() - 1).name(), body);
    rbd::MultiBodyConfigTpl<T> cc(chain);
    for(int k = 0; k < chain.nrJoints(); ++k)
    {
      cc.q[static_cast<std::size_t>(k)] = c.mbc.q[static_cast<std::size_t>(jac.jointsPath()[static_cast<std::size_t>(k)])];
      cc.alpha[static_cast<std::size_t>(k)] = c.mbc.alpha[static_cast<std::size_t>(jac.jointsPath()[static_cast<std::size_t>(k)])];
    }
    kinext::kin(chain, cc);
    const sva::PTransform<T> X_0_ref =
        withRef ? c.mbc.bodyPosW[static_cast<std::size_t>(c.ref)] : sva::PTransform<T>::Identity();
    // a path ending with a reversed joint (the body is an ancestor of the reference body) leaves the
    // body's chain frame on that joint's frame, X_b_J = Xt of the joint
    const sva::PTransform<T> X_b_J =
        jac.jointsSign().back() < T(0) ? c.mb.transform(jac.jointsPath().back()) : sva::PTransform<T>::Identity();
    const sva::Vector3<T> pointJ = X_b_J.rotation() * (c.point - X_b_J.translation());
    EXPECT_MAT_NEAR(cc.bodyPosW.back().matrix(),
                    (X_b_J * c.mbc.bodyPosW[static_cast<std::size_t>(c.body)] * X_0_ref.inv()).matrix(),
                    kinext::Prec<T>::exact);
    for(int k = 0; k < chain.nrBodies(); ++k)
    {
      const int i = c.mb.bodyIndexByName(chain.body(k).name());
      const sva::PTransform<T> X_ref_i = c.mbc.bodyPosW[static_cast<std::size_t>(i)] * X_0_ref.inv();
      EXPECT_MAT_NEAR(cc.bodyPosW[static_cast<std::size_t>(k)].transMul(chain.body(k).inertia()).matrix(),
                      X_ref_i.transMul(c.mb.body(i).inertia()).matrix(), kinext::Prec<T>::exact)
          << chain.body(k).name();
    }
    rbd::JacobianTpl<T> chainJac(chain, body, pointJ);
    EXPECT_MAT_NEAR(chainJac.bodyJacobian(chain, cc), rotateRows<T>(X_b_J.rotation(), MatX<T>(jac.bodyJacobian(c.mb, c.mbc))),
                    kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(chainJac.jacobian(chain, cc), jac.jacobian(c.mb, c.mbc), kinext::Prec<T>::exact);
  }
  // the checked variant rejects another model
  auto c = refCase<T>(rng);
  rbd::JacobianTpl<T> jac(c.mb, c.mb.body(c.mb.nrBodies() - 1).name());
  EXPECT_THROW(jac.sSubMultiBody(rbd::MultiBodyTpl<T>()), std::domain_error);
}

// compactPath covers the path's dofs; expand(J^T J) = full(J)^T full(J); expandAdd accumulates.
TYPED_TEST(JacobianApiTest, ExpandAndCompactPath)
{
  using T = TypeParam;
  rbdtest::Rng rng(74);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = refCase<T>(rng);
    rbd::JacobianTpl<T> jac = n % 2 ? rbd::JacobianTpl<T>(c.mb, c.mb.body(c.body).name(), c.mb.body(c.ref).name())
                                    : rbd::JacobianTpl<T>(c.mb, c.mb.body(c.body).name());
    const rbd::Blocks blocks = jac.compactPath(c.mb);
    Eigen::Index covered = 0;
    for(const auto & b : blocks) covered += b.length;
    EXPECT_EQ(covered, jac.dof());
    const MatX<T> J = jac.jacobian(c.mb, c.mbc);
    const MatX<T> F = full(c.mb, jac, J);
    EXPECT_MAT_NEAR(jac.expand(c.mb, MatX<T>(J.transpose() * J)), MatX<T>(F.transpose() * F), kinext::Prec<T>::exact);
    MatX<T> acc = MatX<T>::Identity(c.mb.nrDof(), c.mb.nrDof());
    jac.expandAdd(blocks, MatX<T>(J.transpose() * J), acc);
    EXPECT_MAT_NEAR(acc, MatX<T>(F.transpose() * F + MatX<T>::Identity(c.mb.nrDof(), c.mb.nrDof())),
                    kinext::Prec<T>::exact);
    MatX<T> twice = F;
    jac.addFullJacobian(c.mb, J, twice);
    EXPECT_MAT_NEAR(twice, MatX<T>(2 * F), kinext::Prec<T>::exact);
  }
}

// velocity / normalAcceleration with an explicit frame reproduce the world-aligned point forms:
// X_b_p = plx(E_0_b^T, point), V_b_p = [w_world; 0].
TYPED_TEST(JacobianApiTest, ExplicitFrameVelocityAndNormalAcceleration)
{
  using T = TypeParam;
  rbdtest::Rng rng(75);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = refCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.mb.body(c.body).name(), c.point);
    const auto & X_0_b = c.mbc.bodyPosW[static_cast<std::size_t>(c.body)];
    const sva::PTransform<T> X_b_p(sva::Matrix3<T>(X_0_b.rotation().transpose()), c.point);
    const sva::MotionVec<T> V(sva::Vector3<T>(X_0_b.rotation().transpose() * c.mbc.bodyVelB[static_cast<std::size_t>(c.body)].angular()),
                              sva::Vector3<T>::Zero());
    EXPECT_MAT_NEAR(jac.velocity(c.mb, c.mbc, X_b_p).vector(), jac.velocity(c.mb, c.mbc).vector(), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(jac.normalAcceleration(c.mb, c.mbc, X_b_p, V).vector(), jac.normalAcceleration(c.mb, c.mbc).vector(),
                    kinext::Prec<T>::exact);
    std::vector<sva::MotionVec<T>> normalAccB;
    rbd::computeNormalAccB(c.mb, c.mbc, normalAccB);
    EXPECT_MAT_NEAR(jac.normalAcceleration(c.mb, c.mbc, normalAccB, X_b_p, V).vector(),
                    jac.normalAcceleration(c.mb, c.mbc).vector(), kinext::Prec<T>::exact);
    // J alpha and Jdot alpha (root Jacobian)
    const VecX<T> alpha = [&] {
      VecX<T> a(jac.dof());
      Eigen::Index pos = 0;
      for(int j : jac.jointsPath())
        for(T x : c.mbc.alpha[static_cast<std::size_t>(j)]) a(pos++) = x;
      return a;
    }();
    EXPECT_MAT_NEAR(VecX<T>(jac.jacobian(c.mb, c.mbc) * alpha), jac.sVelocity(c.mb, c.mbc).vector(), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(VecX<T>(jac.bodyJacobian(c.mb, c.mbc) * alpha), jac.sBodyVelocity(c.mb, c.mbc).vector(),
                    kinext::Prec<T>::exact);
  }
}

} // namespace

namespace
{

// CoMJacobianDummy (the definition, body by body) equals CoMJacobian (subtree sums), weighted too,
// and so do their time derivatives.
TYPED_TEST(JacobianApiTest, CoMJacobianDummyEqualsCoMJacobian)
{
  using T = TypeParam;
  rbdtest::Rng rng(76);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = refCase<T>(rng);
    std::vector<T> w;
    for(int i = 0; i < c.mb.nrBodies(); ++i) w.push_back(T(rbdtest::uniform(rng, 0.2, 2.0)));
    rbd::CoMJacobianDummyTpl<T> dummy(c.mb, w);
    rbd::CoMJacobianTpl<T> fast(c.mb, w);
    EXPECT_MAT_NEAR(dummy.sJacobian(c.mb, c.mbc), fast.jacobian(c.mb, c.mbc), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(dummy.sJacobianDot(c.mb, c.mbc), fast.jacobianDot(c.mb, c.mbc), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(dummy.jacobian(), fast.jacobian(c.mb, c.mbc), kinext::Prec<T>::exact);
  }
  auto c = refCase<T>(rng);
  EXPECT_THROW(rbd::CoMJacobianDummyTpl<T>(c.mb, std::vector<T>(1, T(1))), std::domain_error);
  rbd::CoMJacobianDummyTpl<T> dummy(c.mb);
  EXPECT_THROW(dummy.sJacobian(c.mb, rbd::MultiBodyConfigTpl<T>()), std::domain_error);
}

} // namespace
