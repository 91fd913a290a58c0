#pragma once
// Derivatives of forward dynamics alphaD = FD(q, alpha, tau):
//   H dalphaD = dtau - dID  at alphaD = FD(q, alpha, tau), so
//   d alphaD/dq = -H^-1 d tau/dq |_(alphaD),  d alphaD/dalpha = -H^-1 d tau/dalpha |_(alphaD),
//   d alphaD/d tau = H^-1
// with the tangent convention of IDDerivatives.h (q ⊕ ε e_m moves joint j by the motion S_m).
// H^-1 is formed from the factorisation ForwardDynamics used (LLT, or LDLT when H is not found PD).

#include <rbd/FD.h>
#include <rbd/IDDerivatives.h>

namespace rbd
{

template<typename T>
class ForwardDynamicsDerivativesTpl
{
public:
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

  ForwardDynamicsDerivativesTpl() = default;
  explicit ForwardDynamicsDerivativesTpl(const MultiBodyTpl<T> & mb)
  : fd_(mb), id_(mb), alphaD_(static_cast<std::size_t>(mb.nrJoints()))
  {
  }

  /// Use jointTorque, gravity, force and the outputs of forwardKinematics and forwardVelocity.
  /// Fill alphaD(), dalphaDDq(), dalphaDDalpha() and Minv() (mbc is not modified). Throws
  /// std::runtime_error when the accelerations are not finite (as ForwardDynamics).
  void forwardDynamicsDerivatives(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    // alphaD = FD(q, alpha, tau) on a copy of the accelerations (mbc stays const)
    fd_.computeH(mb, mbc);
    fd_.computeC(mb, mbc);
    VectorX rhs(mb.nrDof());
    dofToVector<T>(mbc.jointTorque, rhs);
    rhs -= fd_.C();
    // H^-1 from the Cholesky factorisation (LDLT when H is not numerically positive definite)
    const MatrixX identity = MatrixX::Identity(mb.nrDof(), mb.nrDof());
    Eigen::LLT<MatrixX> llt(fd_.H());
    if(llt.info() == Eigen::Success) Minv_ = llt.solve(identity);
    else Minv_ = Eigen::LDLT<MatrixX>(fd_.H()).solve(identity);
    alphaDVec_ = Minv_ * rhs;
    if(!alphaDVec_.allFinite())
      throw std::runtime_error("forwardDynamicsDerivatives: joint acceleration is not finite");
    for(int i = 0; i < mb.nrJoints(); ++i)
      alphaD_[static_cast<std::size_t>(i)] = mb.joint(i).zeroDof();
    vectorToDof<T>(alphaDVec_, alphaD_);
    // d alphaD = -H^-1 d ID at alphaD
    id_.compute(mb, mbc, alphaD_);
    dalphaDDq_.noalias() = -Minv_ * id_.dtauDq();
    dalphaDDalpha_.noalias() = -Minv_ * id_.dtauDalpha();
  }

  /// Checked variant: throws std::domain_error on a size mismatch.
  void sForwardDynamicsDerivatives(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

  const VectorX & alphaD() const { return alphaDVec_; }
  const MatrixX & dalphaDDq() const { return dalphaDDq_; }
  const MatrixX & dalphaDDalpha() const { return dalphaDDalpha_; }
  /// H^-1 = d alphaD / d tau.
  const MatrixX & Minv() const { return Minv_; }
  /// The inverse dynamics derivatives at alphaD() (dtauDq, dtauDalpha).
  const InverseDynamicsDerivativesTpl<T> & inverseDynamicsDerivatives() const { return id_; }

private:
  ForwardDynamicsTpl<T> fd_;
  InverseDynamicsDerivativesTpl<T> id_;
  std::vector<std::vector<T>> alphaD_;
  VectorX alphaDVec_;
  MatrixX dalphaDDq_, dalphaDDalpha_, Minv_;
};

using ForwardDynamicsDerivatives = ForwardDynamicsDerivativesTpl<double>;

extern template class ForwardDynamicsDerivativesTpl<double>;
extern template class ForwardDynamicsDerivativesTpl<long double>;

} // namespace rbd
