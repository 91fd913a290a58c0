#pragma once
// Forward dynamics by the articulated-body algorithm (Featherstone, RBDA, table 7.1), O(n).
// A class rather than a free function: it keeps the per-body workspace (I^A, p^A, U, D^-1, u, c)
// between calls, so the call itself does not allocate. Gravity enters as the base acceleration
// a_0 = [0; gravity] (as in InverseDynamics), so bodyAccB includes it.
//
// Multi-dof joints use a small dense D = S^T I^A S (dof x dof, at most 6 x 6, no heap), inverted by
// Cholesky. A D that is not positive definite (massless subtree on a moving joint) throws
// std::runtime_error: use ForwardDynamics (CRBA, with its LDLT fallback) for such models.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

template<typename T>
class ForwardDynamicsABATpl
{
public:
  using Matrix6X = Eigen::Matrix<T, 6, Eigen::Dynamic, 0, 6, 6>;
  using MatrixD = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  using VectorD = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, 6, 1>;

  ForwardDynamicsABATpl() = default;
  explicit ForwardDynamicsABATpl(const MultiBodyTpl<T> & mb) { resize(mb); }

  /// Use jointTorque, gravity, force and the outputs of forwardKinematics and forwardVelocity
  /// (parentToSon, bodyPosW, motionSubspace, jointVelocity, bodyVelB).
  /// Fill alphaD and bodyAccB (with the fictitious base acceleration [0; gravity]).
  void forwardDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
  {
    const int n = mb.nrJoints();
    if(static_cast<int>(IA_.size()) != n) resize(mb);
    // Pass 1 (root to leaves): c_i = v_i x vJ_i, I^A_i = I_i, p^A_i = v_i x* I_i v_i - X_0_i^* f_ext_i
    for(int i = 0; i < n; ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      const auto & I = mb.body(i).inertia();
      const auto & v = mbc.bodyVelB[k];
      c_[k] = v.cross(mbc.jointVelocity[k]);
      IA_[k] = sva::ABInertia<T>(I);
      pA_[k] = v.crossDual(I * v) - mbc.bodyPosW[k].dualMul(mbc.force[k]);
    }
    // Pass 2 (leaves to root): articulated inertias and bias forces.
    for(int i = n - 1; i >= 0; --i)
    {
      const auto k = static_cast<std::size_t>(i);
      const auto & S = mbc.motionSubspace[k];
      sva::Matrix6<T> Ia = IA_[k].matrix();
      Eigen::Matrix<T, 6, 1> pa = pA_[k].vector();
      if(S.cols() > 0)
      {
        // U = I^A S, D = S^T U, u = tau - S^T p
        const Matrix6X U = Ia * S;
        const MatrixD D = S.transpose() * U;
        Eigen::LLT<MatrixD> llt(D);
        if(llt.info() != Eigen::Success)
          throw std::runtime_error("forwardDynamicsABA: articulated inertia of joint '" + mb.joint(i).name() +
                                   "' is not positive definite");
        Dinv_[k] = llt.solve(MatrixD::Identity(D.rows(), D.cols()));
        UDinv_[k] = U * Dinv_[k];
        VectorD u(S.cols());
        for(Eigen::Index c = 0; c < S.cols(); ++c) u(c) = mbc.jointTorque[k][static_cast<std::size_t>(c)];
        u.noalias() -= S.transpose() * pa;
        u_[k] = u;
        // I^a = I^A - U D^-1 U^T, p^a = p^A + I^a c + U D^-1 u
        Ia.noalias() -= UDinv_[k] * U.transpose();
        pa += Ia * c_[k].vector() + UDinv_[k] * u;
      }
      else
      {
        pa += Ia * c_[k].vector(); // I^a = I^A, p^a = p^A + I^a c
      }
      const int p = mb.parent(i);
      if(p < 0) continue;
      // I^A_λ(i) += X_p_i^T I^a X_p_i, p^A_λ(i) += X_p_i^T p^a
      const auto & X_p_i = mbc.parentToSon[k];
      const sva::ABInertia<T> IaAB(Ia.template bottomRightCorner<3, 3>(), Ia.template topRightCorner<3, 3>(),
                                   Ia.template topLeftCorner<3, 3>());
      IA_[static_cast<std::size_t>(p)] += X_p_i.transMul(IaAB);
      pA_[static_cast<std::size_t>(p)] += X_p_i.transMul(sva::ForceVec<T>(pa));
    }
    // Pass 3 (root to leaves): a' = X_p_i a_λ(i) + c_i, alphaD = D^-1 (u - U^T a'), a_i = a' + S alphaD
    const sva::MotionVec<T> a_0(sva::Vector3<T>::Zero(), mbc.gravity);
    for(int i = 0; i < n; ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      const int p = mb.parent(i);
      const sva::MotionVec<T> aPrime =
          mbc.parentToSon[k] * (p < 0 ? a_0 : mbc.bodyAccB[static_cast<std::size_t>(p)]) + c_[k];
      const auto & S = mbc.motionSubspace[k];
      Eigen::Matrix<T, 6, 1> a = aPrime.vector();
      if(S.cols() > 0)
      {
        const VectorD alphaD = Dinv_[k] * u_[k] - UDinv_[k].transpose() * aPrime.vector();
        for(Eigen::Index c = 0; c < S.cols(); ++c)
        {
          using std::isfinite;
          if(!isfinite(alphaD(c)))
            throw std::runtime_error("forwardDynamicsABA: joint acceleration is not finite");
          mbc.alphaD[k][static_cast<std::size_t>(c)] = alphaD(c);
        }
        a.noalias() += S * alphaD;
      }
      mbc.bodyAccB[k] = sva::MotionVec<T>(a);
    }
  }

  /// Checked variant: throws std::domain_error on a size mismatch.
  void sForwardDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc);

  /// Articulated-body inertia I^A_i of each body after the last call (body coordinates).
  const std::vector<sva::ABInertia<T>> & articulatedInertia() const { return IA_; }
  /// Articulated bias force p^A_i of each body after the last call (body coordinates).
  const std::vector<sva::ForceVec<T>> & biasForce() const { return pA_; }

private:
  void resize(const MultiBodyTpl<T> & mb)
  {
    const auto n = static_cast<std::size_t>(mb.nrBodies());
    IA_.assign(n, sva::ABInertia<T>());
    pA_.assign(n, sva::ForceVec<T>::Zero());
    c_.assign(n, sva::MotionVec<T>::Zero());
    UDinv_.assign(n, Matrix6X());
    Dinv_.assign(n, MatrixD());
    u_.assign(n, VectorD());
  }

  std::vector<sva::ABInertia<T>> IA_;
  std::vector<sva::ForceVec<T>> pA_;
  std::vector<sva::MotionVec<T>> c_;
  std::vector<Matrix6X> UDinv_; ///< U D^-1 per joint
  std::vector<MatrixD> Dinv_;
  std::vector<VectorD> u_;
};

using ForwardDynamicsABA = ForwardDynamicsABATpl<double>;

extern template class ForwardDynamicsABATpl<double>;
extern template class ForwardDynamicsABATpl<long double>;

} // namespace rbd
