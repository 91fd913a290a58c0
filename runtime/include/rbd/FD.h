#pragma once
// Forward dynamics by the composite-rigid-body algorithm (Featherstone, RBDA, table 6.2):
//   H alphaD + C = tau,   alphaD = H^-1 (tau - C).
// H from the composite inertias I^c_i = I_i + sum_children X^T I^c_child X; C = ID with alphaD = 0.
//
// Solve policy: Cholesky (LLT) of H; if H is not numerically positive definite (e.g. a massless
// subtree), fall back to LDLT with symmetric pivoting, which treats exactly-zero pivots as a
// least-squares solve. solver() says which one ran. A non-finite alphaD (NaN/inf in the model,
// the state or the torques) throws std::runtime_error instead of being returned.

#include <stdexcept>
#include <vector>

#include <Eigen/Cholesky>

#include <rbd/ID.h>
#include <rbd/MultiBodyConfig.h>

namespace rbd
{

template<typename T>
class ForwardDynamicsTpl
{
public:
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  /// Factorisation used by the last forwardDynamics call.
  enum class Solver
  {
    None,
    LLT,
    LDLT
  };

  ForwardDynamicsTpl() = default;
  explicit ForwardDynamicsTpl(const MultiBodyTpl<T> & mb)
  : H_(MatrixX::Zero(mb.nrDof(), mb.nrDof())), C_(VectorX::Zero(mb.nrDof())),
    Ic_(static_cast<std::size_t>(mb.nrBodies())), id_(mb), llt_(mb.nrDof()), ldlt_(mb.nrDof()),
    rhs_(VectorX::Zero(mb.nrDof())), alphaD_(VectorX::Zero(mb.nrDof()))
  {
  }

  /// Use jointTorque, gravity, force and the outputs of forwardKinematics and forwardVelocity.
  /// Fill alphaD (also H(), C()). Throws std::runtime_error if the result is not finite.
  void forwardDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
  {
    computeH(mb, mbc);
    computeC(mb, mbc);
    rhs_.resize(mb.nrDof());
    dofToVector<T>(mbc.jointTorque, rhs_);
    rhs_ -= C_;
    // alphaD = H^-1 (tau - C)
    llt_.compute(H_);
    if(llt_.info() == Eigen::Success)
    {
      solver_ = Solver::LLT;
      alphaD_ = llt_.solve(rhs_);
    }
    else
    {
      solver_ = Solver::LDLT;
      ldlt_.compute(H_);
      alphaD_ = ldlt_.solve(rhs_);
    }
    if(!alphaD_.allFinite()) throw std::runtime_error("forwardDynamics: joint acceleration is not finite");
    vectorToDof<T>(alphaD_, mbc.alphaD);
  }

  /// Checked variant: throws std::domain_error on a size mismatch.
  void sForwardDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc);

  /// Use the outputs of forwardKinematics (parentToSon, motionSubspace). Fill H() and
  /// inertiaSubTree() (composite-rigid-body algorithm; H is filled in full, symmetric).
  void computeH(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    const int n = mb.nrJoints();
    H_.setZero(mb.nrDof(), mb.nrDof());
    Ic_.resize(static_cast<std::size_t>(n));
    for(int i = 0; i < n; ++i) Ic_[static_cast<std::size_t>(i)] = mb.body(i).inertia();
    // I^c_λ(i) += X_p_i^T I^c_i X_p_i
    for(int i = n - 1; i >= 0; --i)
    {
      const auto k = static_cast<std::size_t>(i);
      const int p = mb.parent(i);
      if(p >= 0) Ic_[static_cast<std::size_t>(p)] += mbc.parentToSon[k].transMul(Ic_[k]);
    }
    for(int i = 0; i < n; ++i)
    {
      const auto & S_i = mbc.motionSubspace[static_cast<std::size_t>(i)];
      const Eigen::Index di = S_i.cols(), pi = mb.jointPosInDof(i);
      if(di == 0) continue;
      // F = I^c_i S_i, H_ii = S_i^T F
      Eigen::Matrix<T, 6, Eigen::Dynamic, 0, 6, 6> F = Ic_[static_cast<std::size_t>(i)].matrix() * S_i;
      H_.block(pi, pi, di, di).noalias() = S_i.transpose() * F;
      for(Eigen::Index r = 1; r < di; ++r) // exact symmetry: mirror the lower triangle
        for(Eigen::Index c = 0; c < r; ++c) H_(pi + c, pi + r) = H_(pi + r, pi + c);
      // up the path to the root: F = X_p_j^T F, H_ij = F^T S_j (= H_ji^T)
      for(int j = i; mb.parent(j) >= 0;)
      {
        const auto & X_p_j = mbc.parentToSon[static_cast<std::size_t>(j)];
        for(Eigen::Index c = 0; c < di; ++c) F.col(c) = X_p_j.transMul(sva::ForceVec<T>(F.col(c))).vector();
        j = mb.parent(j);
        const auto & S_j = mbc.motionSubspace[static_cast<std::size_t>(j)];
        const Eigen::Index dj = S_j.cols(), pj = mb.jointPosInDof(j);
        if(dj == 0) continue;
        H_.block(pi, pj, di, dj).noalias() = F.transpose() * S_j;
        H_.block(pj, pi, dj, di) = H_.block(pi, pj, di, dj).transpose();
      }
    }
  }

  /// Use gravity, force and the outputs of forwardKinematics and forwardVelocity. Fill C()
  /// (inverse dynamics with alphaD = 0: Coriolis, centrifugal, gravity and external forces).
  void computeC(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    C_.resize(mb.nrDof());
    id_.nonLinearEffects(mb, mbc, C_);
  }

  /// Joint-space inertia matrix H (nrDof x nrDof) of the last computeH.
  const MatrixX & H() const { return H_; }
  /// Nonlinear effects C (nrDof) of the last computeC.
  const VectorX & C() const { return C_; }
  /// Composite inertia I^c_i of the subtree rooted at each body, in body i coordinates.
  const std::vector<sva::RBInertia<T>> & inertiaSubTree() const { return Ic_; }
  /// Factorisation used by the last forwardDynamics call (LLT, or LDLT when H was not found PD).
  Solver solver() const { return solver_; }

private:
  MatrixX H_;
  VectorX C_;
  std::vector<sva::RBInertia<T>> Ic_;
  InverseDynamicsTpl<T> id_;
  Eigen::LLT<MatrixX> llt_;
  Eigen::LDLT<MatrixX> ldlt_;
  VectorX rhs_, alphaD_;
  Solver solver_ = Solver::None;
};

using ForwardDynamics = ForwardDynamicsTpl<double>;

extern template class ForwardDynamicsTpl<double>;
extern template class ForwardDynamicsTpl<long double>;

} // namespace rbd
