#pragma once
// Inverse dynamics identification model: tau = Y(q, alpha, alphaD) phi, phi the stacked inertial
// parameters of the bodies, phi_i = [m, h_x, h_y, h_z, I_xx, I_xy, I_xz, I_yy, I_yz, I_zz]
// (h = m c, I the rotational inertia at the body origin; body frame).
//   f_i = I_i a_i + v_i x* I_i v_i = K(v_i, a_i) phi_i,   K(v, a) = IMPhi(a) + crf(v) IMPhi(v)
//   tau_j = S_j^T sum_{i in subtree(j)} X_j_i^T f_i  =>  Y(j, i) = S_j^T X_λ..._i^T K_i
// External forces are not part of the model (tau = Y phi holds with mbc.force = 0).

#include <stdexcept>
#include <string>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// phi = [m, h, I_xx, I_xy, I_xz, I_yy, I_yz, I_zz].
template<typename T>
Eigen::Matrix<T, 10, 1> inertiaToVector(const sva::RBInertia<T> & rbi)
{
  const auto & I = rbi.inertia();
  Eigen::Matrix<T, 10, 1> phi;
  phi << rbi.mass(), rbi.momentum(), I(0, 0), I(0, 1), I(0, 2), I(1, 1), I(1, 2), I(2, 2);
  return phi;
}

/// Inverse of inertiaToVector.
template<typename T>
sva::RBInertia<T> vectorToInertia(const Eigen::Matrix<T, 10, 1> & phi)
{
  sva::Matrix3<T> I;
  I << phi(4), phi(5), phi(6), phi(5), phi(7), phi(8), phi(6), phi(8), phi(9);
  return sva::RBInertia<T>(phi(0), sva::Vector3<T>(phi.template segment<3>(1)), I);
}

/// Stacked phi of every body of mb (size 10 nrBodies, body i at 10 i).
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> multiBodyToInertialVector(const MultiBodyTpl<T> & mb)
{
  Eigen::Matrix<T, Eigen::Dynamic, 1> phi(10 * mb.nrBodies());
  for(int i = 0; i < mb.nrBodies(); ++i) phi.template segment<10>(10 * i) = inertiaToVector(mb.body(i).inertia());
  return phi;
}

/// 6x10 matrix with I v = IMPhi(v) inertiaToVector(I), v = [w; u]:
/// I v = [I w + h x u; m u - h x w] = [L(w) I_vec - u^ h; m u + w^ h].
template<typename T>
Eigen::Matrix<T, 6, 10> IMPhi(const sva::MotionVec<T> & mv)
{
  const sva::Vector3<T> & w = mv.angular();
  const sva::Vector3<T> & u = mv.linear();
  Eigen::Matrix<T, 6, 10> K = Eigen::Matrix<T, 6, 10>::Zero();
  // angular rows: -u^ h and L(w) [I_xx I_xy I_xz I_yy I_yz I_zz]
  K.template block<3, 3>(0, 1) = -sva::vector3ToCrossMatrix(u);
  K(0, 4) = w.x(); K(0, 5) = w.y(); K(0, 6) = w.z();
  K(1, 5) = w.x(); K(1, 7) = w.y(); K(1, 8) = w.z();
  K(2, 6) = w.x(); K(2, 8) = w.y(); K(2, 9) = w.z();
  // linear rows: m u + w^ h
  K.template block<3, 1>(3, 0) = u;
  K.template block<3, 3>(3, 1) = sva::vector3ToCrossMatrix(w);
  return K;
}

/// 6x10 matrix with I a + v x* I v = newtonEulerPhi(v, a) inertiaToVector(I).
template<typename T>
Eigen::Matrix<T, 6, 10> newtonEulerPhi(const sva::MotionVec<T> & v, const sva::MotionVec<T> & a)
{
  return IMPhi(a) + sva::vector6ToCrossDualMatrix(v) * IMPhi(v);
}

template<typename T>
class IDIMTpl
{
public:
  using Scalar = T;
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

  IDIMTpl() = default;
  explicit IDIMTpl(const MultiBodyTpl<T> & mb) : Y_(MatrixX::Zero(mb.nrDof(), 10 * mb.nrBodies())) {}

  /// Use parentToSon, motionSubspace (FK), bodyVelB (FV) and bodyAccB WITH the fictitious base
  /// acceleration [0; gravity], as InverseDynamics fills it (or forwardAcceleration(mb, mbc,
  /// MotionVec(0, gravity))). Fill Y() (nrDof x 10 nrBodies): jointTorque = Y phi (no external force).
  void computeY(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    Y_.setZero();
    for(int i = 0; i < mb.nrBodies(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      // F = X_j_i^T K_i, walking from body i to the root
      Eigen::Matrix<T, 6, 10> F = newtonEulerPhi(mbc.bodyVelB[k], mbc.bodyAccB[k]);
      for(int j = i; j >= 0; j = mb.parent(j))
      {
        const auto jk = static_cast<std::size_t>(j);
        const auto & S = mbc.motionSubspace[jk];
        Y_.block(mb.jointPosInDof(j), 10 * i, S.cols(), 10).noalias() = S.transpose() * F;
        if(mb.parent(j) >= 0) F = mbc.parentToSon[jk].transMul(F);
      }
    }
  }

  /// Checked variant: throws std::domain_error when mb/mbc do not match.
  void sComputeY(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    const auto n = static_cast<std::size_t>(mb.nrBodies());
    if(Y_.rows() != mb.nrDof() || Y_.cols() != 10 * mb.nrBodies())
      throw std::domain_error("IDIM: the MultiBody does not match");
    if(mbc.parentToSon.size() != n || mbc.motionSubspace.size() != n || mbc.bodyVelB.size() != n ||
       mbc.bodyAccB.size() != n)
      throw std::domain_error("IDIM: the MultiBodyConfig does not match the MultiBody");
    for(int j = 0; j < mb.nrJoints(); ++j)
      if(mbc.motionSubspace[static_cast<std::size_t>(j)].cols() != mb.joint(j).dof())
        throw std::domain_error("IDIM: motionSubspace of joint '" + mb.joint(j).name() +
                                    "' does not match its dof");
    computeY(mb, mbc);
  }

  const MatrixX & Y() const { return Y_; }

private:
  MatrixX Y_;
};

using IDIM = IDIMTpl<double>;

extern template Eigen::Matrix<double, 10, 1> inertiaToVector(const sva::RBInertia<double> &);
extern template Eigen::Matrix<long double, 10, 1> inertiaToVector(const sva::RBInertia<long double> &);
extern template sva::RBInertia<double> vectorToInertia(const Eigen::Matrix<double, 10, 1> &);
extern template sva::RBInertia<long double> vectorToInertia(const Eigen::Matrix<long double, 10, 1> &);
extern template Eigen::Matrix<double, Eigen::Dynamic, 1> multiBodyToInertialVector(const MultiBodyTpl<double> &);
extern template Eigen::Matrix<long double, Eigen::Dynamic, 1> multiBodyToInertialVector(
    const MultiBodyTpl<long double> &);
extern template Eigen::Matrix<double, 6, 10> IMPhi(const sva::MotionVec<double> &);
extern template Eigen::Matrix<long double, 6, 10> IMPhi(const sva::MotionVec<long double> &);
extern template Eigen::Matrix<double, 6, 10> newtonEulerPhi(const sva::MotionVec<double> &,
                                                           const sva::MotionVec<double> &);
extern template Eigen::Matrix<long double, 6, 10> newtonEulerPhi(const sva::MotionVec<long double> &,
                                                                const sva::MotionVec<long double> &);
extern template class IDIMTpl<double>;
extern template class IDIMTpl<long double>;

} // namespace rbd
