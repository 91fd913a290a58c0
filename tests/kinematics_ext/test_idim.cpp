// Inverse dynamics identification model: Y phi = inverseDynamics jointTorque on random trees (all
// joint types, 30% backward joints, random root joint), in double and long double. Y does not
// depend on the inertias: Y of one model times phi of a model with other inertias gives that model's
// torques. Parameter vector layout and the 6x10 regressors against sva's RBInertia products.

#include <rbd/ID.h>
#include <rbd/IDIM.h>

#include "KinExtTestUtils.h"

namespace
{

template<typename T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

/// The same tree with new random inertias.
template<typename T>
rbd::MultiBodyTpl<T> withRandomInertias(rbdtest::Rng & rng, const rbd::MultiBodyTpl<T> & mb)
{
  std::vector<rbd::BodyTpl<T>> bodies;
  for(const auto & b : mb.bodies()) bodies.emplace_back(rbdtest::randomInertia(rng).cast<T>(), b.name());
  return rbd::MultiBodyTpl<T>(bodies, mb.joints(), mb.predecessors(), mb.successors(), mb.parents(),
                              mb.transforms());
}

constexpr int nrCases = 30;

} // namespace

template<typename T>
class IDIMTest : public ::testing::Test
{
};
TYPED_TEST_SUITE(IDIMTest, kinext::Scalars, );

// phi layout [m, h, Ixx, Ixy, Ixz, Iyy, Iyz, Izz], round trip, stacking per body.
TYPED_TEST(IDIMTest, InertialParameterVector)
{
  using T = TypeParam;
  rbdtest::Rng rng(31);
  const sva::RBInertia<T> I = rbdtest::randomInertia(rng).cast<T>();
  const Eigen::Matrix<T, 10, 1> phi = rbd::inertiaToVector(I);
  EXPECT_EQ(phi(0), I.mass());
  EXPECT_EQ(phi.template segment<3>(1), I.momentum());
  const sva::Matrix3<T> & In = I.inertia();
  Eigen::Matrix<T, 6, 1> tri;
  tri << In(0, 0), In(1, 0), In(2, 0), In(1, 1), In(2, 1), In(2, 2);
  EXPECT_EQ(VecX<T>(phi.template tail<6>()), VecX<T>(tri));
  const sva::RBInertia<T> back = rbd::vectorToInertia(phi);
  EXPECT_EQ(back.mass(), I.mass());
  EXPECT_EQ(back.momentum(), I.momentum());
  EXPECT_EQ(back.inertia(), I.inertia());

  const auto mb = kinext::randomModel<T>(rng, 5, rbd::Joint::Free);
  const VecX<T> all = rbd::multiBodyToInertialVector(mb);
  ASSERT_EQ(all.size(), 10 * mb.nrBodies());
  for(int i = 0; i < mb.nrBodies(); ++i)
    EXPECT_EQ(VecX<T>(all.template segment<10>(10 * i)), VecX<T>(rbd::inertiaToVector(mb.body(i).inertia())));
}

// IMPhi(v) phi = I v and newtonEulerPhi(v, a) phi = I a + v x* I v, with sva's products.
TYPED_TEST(IDIMTest, RegressorsMatchInertiaProducts)
{
  using T = TypeParam;
  rbdtest::Rng rng(32);
  for(int n = 0; n < nrCases; ++n)
  {
    const sva::RBInertia<T> I = rbdtest::randomInertia(rng).cast<T>();
    auto mv = [&]() {
      return sva::MotionVec<T>(rbdtest::randomTransform(rng, 3.).translation().cast<T>(),
                               rbdtest::randomTransform(rng, 3.).translation().cast<T>());
    };
    const sva::MotionVec<T> v = mv(), a = mv();
    const Eigen::Matrix<T, 10, 1> phi = rbd::inertiaToVector(I);
    EXPECT_MAT_NEAR(VecX<T>(rbd::IMPhi(v) * phi), (I * v).vector(), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(VecX<T>(rbd::newtonEulerPhi(v, a) * phi), (I * a + v.crossDual(I * v)).vector(),
                    kinext::Prec<T>::exact);
  }
}

// Y phi = tau of inverseDynamics; Y of the kinematics times phi of other inertias = their tau.
TYPED_TEST(IDIMTest, YTimesPhiEqualsInverseDynamics)
{
  using T = TypeParam;
  rbdtest::Rng rng(33);
  for(int n = 0; n < nrCases; ++n)
  {
    const int nb = std::uniform_int_distribution<int>(2, 10)(rng);
    const auto mb = kinext::randomModel<T>(rng, nb, kinext::randomRoot(rng));
    rbd::MultiBodyConfigTpl<T> mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    kinext::kin(mb, mbc);
    rbd::InverseDynamicsTpl<T>(mb).inverseDynamics(mb, mbc); // also fills bodyAccB with gravity
    rbd::IDIMTpl<T> idim(mb);
    idim.sComputeY(mb, mbc);
    ASSERT_EQ(idim.Y().rows(), mb.nrDof());
    ASSERT_EQ(idim.Y().cols(), 10 * mb.nrBodies());
    const VecX<T> tau = rbd::dofToVector(mb, mbc.jointTorque);
    EXPECT_MAT_NEAR(VecX<T>(idim.Y() * rbd::multiBodyToInertialVector(mb)), tau, kinext::Prec<T>::exact);

    const auto mb2 = withRandomInertias(rng, mb);
    auto mbc2 = mbc;
    rbd::InverseDynamicsTpl<T>(mb2).inverseDynamics(mb2, mbc2);
    EXPECT_MAT_NEAR(VecX<T>(idim.Y() * rbd::multiBodyToInertialVector(mb2)), rbd::dofToVector(mb2, mbc2.jointTorque),
                    kinext::Prec<T>::exact);
  }
}

// Checked variant rejects a configuration of another model.
TYPED_TEST(IDIMTest, CheckedVariantThrows)
{
  using T = TypeParam;
  rbdtest::Rng rng(34);
  const auto mb = kinext::randomModel<T>(rng, 5, rbd::Joint::Free);
  const auto other = kinext::randomModel<T>(rng, 3, rbd::Joint::Free);
  rbd::MultiBodyConfigTpl<T> bad(other);
  kinext::kin(other, bad);
  rbd::IDIMTpl<T> idim(mb);
  EXPECT_THROW(idim.sComputeY(mb, bad), std::domain_error);
}
