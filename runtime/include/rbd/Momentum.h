#pragma once
// Centroidal momentum h_G = [k_G; l]: angular momentum about the CoM and linear momentum, world axes.
//   h_G  = X_0_G^* sum_i X_0_i^T (I_i v_i),                         X_0_G = xlt(com)
//   hd_G = X_0_G^* sum_i X_0_i^T (I_i a_i + v_i x* I_i v_i) - [comDot x l; 0]
// Centroidal momentum matrix A_g (h_G = A_g alpha), column block of joint j:
//   A_g,j = X_0_G^* Ic_j ^0S_j,  Ic_j = sum over the subtree of j of the world inertias X_0_i^T I_i,
//   ^0S_j = X_0_j^-1 S_j (world coordinates, world origin).
// Its derivative: d/dt(^0I_i) = v_i x* ^0I_i - ^0I_i v_i x (world velocity v_i), d/dt(^0S_j) =
//   v_c(j) x ^0S_j (carrier of S_j, see Jacobian.h), d/dt(X_0_G^* f) = X_0_G^* fd - [comDot x f_lin; 0].

#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/Jacobian.h>
#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Use bodyPosW (FK) and bodyVelB (FV). Return h_G = [k_G; l] (world axes) about the point com.
template<typename T>
sva::ForceVec<T> computeCentroidalMomentum(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                           const sva::Vector3<T> & com)
{
  sva::ForceVec<T> h0 = sva::ForceVec<T>::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    h0 += mbc.bodyPosW[k].transMul(mb.body(i).inertia() * mbc.bodyVelB[k]); // X_0_i^T I_i v_i
  }
  return sva::PTransform<T>(com).dualMul(h0);
}

/// Use bodyPosW (FK), bodyVelB (FV) and bodyAccB, gravity-free (forwardAcceleration(mb, mbc)).
/// Return d/dt h_G for the CoM moving at comDot (with comDot the CoM velocity, the last term of the
/// formula above vanishes since l = M comDot).
template<typename T>
sva::ForceVec<T> computeCentroidalMomentumDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                              const sva::Vector3<T> & com, const sva::Vector3<T> & comDot)
{
  sva::ForceVec<T> hd0 = sva::ForceVec<T>::Zero();
  sva::Vector3<T> l = sva::Vector3<T>::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & I = mb.body(i).inertia();
    const auto & v = mbc.bodyVelB[k];
    const sva::ForceVec<T> Iv = I * v;
    hd0 += mbc.bodyPosW[k].transMul(I * mbc.bodyAccB[k] + v.crossDual(Iv)); // X_0_i^T (I a + v x* I v)
    l += mbc.bodyPosW[k].rotation().transpose() * Iv.force();
  }
  sva::ForceVec<T> hd = sva::PTransform<T>(com).dualMul(hd0);
  hd.couple() -= comDot.cross(l);
  return hd;
}

template<typename T>
class CentroidalMomentumMatrixTpl
{
public:
  using Scalar = T;
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector3 = sva::Vector3<T>;
  using MotionVecT = sva::MotionVec<T>;
  using ForceVecT = sva::ForceVec<T>;

  CentroidalMomentumMatrixTpl() = default;
  explicit CentroidalMomentumMatrixTpl(const MultiBodyTpl<T> & mb);
  /// @param weight One weight per body, scaling its inertia (1 everywhere gives A_g).
  CentroidalMomentumMatrixTpl(const MultiBodyTpl<T> & mb, std::vector<T> weight);

  /// Use bodyPosW and motionSubspace (FK). Fill matrix() (A_g, 6 x nrDof).
  void computeMatrix(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com);
  /// Use bodyPosW, motionSubspace (FK), bodyVelB and jointVelocity (FV). Fill matrixDot() (d/dt A_g).
  void computeMatrixDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                        const Vector3 & comDot);
  /// Both at once.
  void computeMatrixAndMatrixDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                                 const Vector3 & comDot);
  const MatrixX & matrix() const { return cmm_; }
  const MatrixX & matrixDot() const { return cmmDot_; }

  /// Use bodyPosW and bodyVelB. Return the (weighted) centroidal momentum h_G = A_g alpha.
  ForceVecT momentum(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com) const;
  /// Use bodyPosW, bodyVelB and jointVelocity. Return d/dt(A_g) alpha, i.e. hd_G for alphaD = 0
  /// without gravity: X_0_G^* sum_i w_i X_0_i^T (I_i a_i + v_i x* I_i v_i) - [comDot x l; 0].
  ForceVecT normalMomentumDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                              const Vector3 & comDot);
  /// Same from precomputed body normal accelerations (computeNormalAccB in Jacobian.h).
  ForceVecT normalMomentumDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                              const Vector3 & comDot, const std::vector<MotionVecT> & normalAccB) const;

  // Checked variants: throw std::domain_error when mb/mbc do not match.
  void sComputeMatrix(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com);
  void sComputeMatrixDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                         const Vector3 & comDot);
  void sComputeMatrixAndMatrixDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                                  const Vector3 & comDot);

private:
  void compute(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
               const Vector3 & comDot, bool withMatrix, bool withDot);
  void check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;

  std::vector<T> weight_;
  std::vector<sva::RBInertia<T>> Ic_;       ///< subtree inertias, world coordinates
  std::vector<sva::Matrix6<T>> IcDot_;      ///< their time derivatives
  std::vector<MotionVecT> normalAccB_;
  MatrixX cmm_, cmmDot_;
};

using CentroidalMomentumMatrix = CentroidalMomentumMatrixTpl<double>;

// ---------------------------------------------------------------------------------------------

template<typename T>
CentroidalMomentumMatrixTpl<T>::CentroidalMomentumMatrixTpl(const MultiBodyTpl<T> & mb)
: CentroidalMomentumMatrixTpl(mb, std::vector<T>(static_cast<std::size_t>(mb.nrBodies()), T(1)))
{
}

template<typename T>
CentroidalMomentumMatrixTpl<T>::CentroidalMomentumMatrixTpl(const MultiBodyTpl<T> & mb, std::vector<T> weight)
: weight_(std::move(weight)), Ic_(static_cast<std::size_t>(mb.nrBodies())),
  IcDot_(static_cast<std::size_t>(mb.nrBodies())), normalAccB_(static_cast<std::size_t>(mb.nrBodies())),
  cmm_(MatrixX::Zero(6, mb.nrDof())), cmmDot_(MatrixX::Zero(6, mb.nrDof()))
{
  if(static_cast<int>(weight_.size()) != mb.nrBodies())
    throw std::domain_error("CentroidalMomentumMatrix: " + std::to_string(weight_.size()) +
                                " weights, model has " + std::to_string(mb.nrBodies()) + " bodies");
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::compute(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                             const Vector3 & com, const Vector3 & comDot, bool withMatrix,
                                             bool withDot)
{
  // world inertias ^0I_i = X_0_i^T (w_i I_i) and their derivatives v_i x* ^0I_i - ^0I_i v_i x
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    Ic_[k] = mbc.bodyPosW[k].transMul(mb.body(i).inertia() * weight_[k]);
    if(withDot)
    {
      const MotionVecT v0 = mbc.bodyPosW[k].invMul(mbc.bodyVelB[k]);
      const sva::Matrix6<T> I0 = Ic_[k].matrix();
      IcDot_[k] = sva::vector6ToCrossDualMatrix(v0) * I0 - I0 * sva::vector6ToCrossMatrix(v0);
    }
  }
  // subtree sums
  for(int i = mb.nrBodies() - 1; i > 0; --i)
  {
    const auto k = static_cast<std::size_t>(i), p = static_cast<std::size_t>(mb.parent(i));
    Ic_[p] += Ic_[k];
    if(withDot) IcDot_[p] += IcDot_[k];
  }
  const sva::PTransform<T> X_0_G(com);
  for(int j = 0; j < mb.nrJoints(); ++j)
  {
    const auto k = static_cast<std::size_t>(j);
    const auto & S = mbc.motionSubspace[k];
    const sva::PTransform<T> X_j_0 = mbc.bodyPosW[k].inv();
    MotionVecT v_c = MotionVecT::Zero();
    if(withDot) // carrier of S_j: body j (forward joint) or its parent (backward joint)
      v_c = X_j_0 * (mb.joint(j).forward() ? mbc.bodyVelB[k] : mbc.bodyVelB[k] - mbc.jointVelocity[k]);
    for(Eigen::Index c = 0; c < S.cols(); ++c)
    {
      const Eigen::Index col = mb.jointPosInDof(j) + c;
      const MotionVecT s = X_j_0 * MotionVecT(S.col(c)); // ^0S_j column
      const ForceVecT f = Ic_[k] * s;
      // A_g,j = X_0_G^* Ic_j ^0S_j
      if(withMatrix) cmm_.col(col) = X_0_G.dualMul(f).vector();
      if(withDot)
      {
        // d/dt: X_0_G^* (Icd s + Ic (v_c x s)) - [comDot x f_lin; 0]
        const ForceVecT fd(sva::Vector6<T>(IcDot_[k] * s.vector() + (Ic_[k] * v_c.cross(s)).vector()));
        ForceVecT g = X_0_G.dualMul(fd);
        g.couple() -= comDot.cross(f.force());
        cmmDot_.col(col) = g.vector();
      }
    }
  }
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::computeMatrix(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                                   const Vector3 & com)
{
  compute(mb, mbc, com, Vector3::Zero(), true, false);
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::computeMatrixDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                                      const Vector3 & com, const Vector3 & comDot)
{
  compute(mb, mbc, com, comDot, false, true);
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::computeMatrixAndMatrixDot(const MultiBodyTpl<T> & mb,
                                                               const MultiBodyConfigTpl<T> & mbc, const Vector3 & com,
                                                               const Vector3 & comDot)
{
  compute(mb, mbc, com, comDot, true, true);
}

template<typename T>
typename CentroidalMomentumMatrixTpl<T>::ForceVecT CentroidalMomentumMatrixTpl<T>::momentum(
    const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com) const
{
  ForceVecT h0 = ForceVecT::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    h0 += mbc.bodyPosW[k].transMul(mb.body(i).inertia() * mbc.bodyVelB[k]) * weight_[k];
  }
  return sva::PTransform<T>(com).dualMul(h0);
}

template<typename T>
typename CentroidalMomentumMatrixTpl<T>::ForceVecT CentroidalMomentumMatrixTpl<T>::normalMomentumDot(
    const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com, const Vector3 & comDot)
{
  computeNormalAccB(mb, mbc, normalAccB_);
  return normalMomentumDot(mb, mbc, com, comDot, normalAccB_);
}

template<typename T>
typename CentroidalMomentumMatrixTpl<T>::ForceVecT CentroidalMomentumMatrixTpl<T>::normalMomentumDot(
    const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & com, const Vector3 & comDot,
    const std::vector<MotionVecT> & normalAccB) const
{
  ForceVecT hd0 = ForceVecT::Zero();
  Vector3 l = Vector3::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & I = mb.body(i).inertia();
    const auto & v = mbc.bodyVelB[k];
    const ForceVecT Iv = I * v;
    hd0 += mbc.bodyPosW[k].transMul(I * normalAccB[k] + v.crossDual(Iv)) * weight_[k];
    l += weight_[k] * (mbc.bodyPosW[k].rotation().transpose() * Iv.force());
  }
  ForceVecT hd = sva::PTransform<T>(com).dualMul(hd0);
  hd.couple() -= comDot.cross(l);
  return hd;
}

extern template sva::ForceVec<double> computeCentroidalMomentum(const MultiBodyTpl<double> &,
                                                                const MultiBodyConfigTpl<double> &,
                                                                const sva::Vector3<double> &);
extern template sva::ForceVec<long double> computeCentroidalMomentum(const MultiBodyTpl<long double> &,
                                                                     const MultiBodyConfigTpl<long double> &,
                                                                     const sva::Vector3<long double> &);
extern template sva::ForceVec<double> computeCentroidalMomentumDot(const MultiBodyTpl<double> &,
                                                                   const MultiBodyConfigTpl<double> &,
                                                                   const sva::Vector3<double> &,
                                                                   const sva::Vector3<double> &);
extern template sva::ForceVec<long double> computeCentroidalMomentumDot(const MultiBodyTpl<long double> &,
                                                                        const MultiBodyConfigTpl<long double> &,
                                                                        const sva::Vector3<long double> &,
                                                                        const sva::Vector3<long double> &);
extern template class CentroidalMomentumMatrixTpl<double>;
extern template class CentroidalMomentumMatrixTpl<long double>;

} // namespace rbd
