#pragma once
// Centre of mass: position, velocity, acceleration (world coordinates) and the CoM Jacobian.
//   M c = sum_i m_i x_i,  x_i = r_i + E_0_i^T c_i  (c_i: CoM of body i in body coordinates)
//   M cd = sum_i E_0_i^T lin(I_i v_i)                       (lin(I v) = m v_O + w x h)
//   M cdd = sum_i E_0_i^T lin(I_i a_i + v_i x* I_i v_i)     (Newton: linear part of the net force)

#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/Jacobian.h>
#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Use bodyPosW (forwardKinematics). Return the CoM in world coordinates.
template<typename T>
sva::Vector3<T> computeCoM(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  sva::Vector3<T> mc = sva::Vector3<T>::Zero();
  T M = T(0);
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & X_0_i = mbc.bodyPosW[static_cast<std::size_t>(i)];
    const auto & I = mb.body(i).inertia();
    // m x_i = m r_i + E^T h
    mc += I.mass() * X_0_i.translation() + X_0_i.rotation().transpose() * I.momentum();
    M += I.mass();
  }
  return mc / M;
}

/// Use bodyPosW (FK) and bodyVelB (FV). Return the CoM velocity in world coordinates.
template<typename T>
sva::Vector3<T> computeCoMVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  sva::Vector3<T> mcd = sva::Vector3<T>::Zero();
  T M = T(0);
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & I = mb.body(i).inertia();
    mcd += mbc.bodyPosW[k].rotation().transpose() * (I * mbc.bodyVelB[k]).force();
    M += I.mass();
  }
  return mcd / M;
}

/// Use bodyPosW (FK), bodyVelB (FV) and bodyAccB. Return the CoM acceleration in world coordinates.
/// bodyAccB must be gravity-free (forwardAcceleration(mb, mbc) with the default A_0). After
/// InverseDynamics, bodyAccB includes the fictitious base acceleration [0; gravity]: the result is
/// then cdd + gravity (subtract mbc.gravity).
template<typename T>
sva::Vector3<T> computeCoMAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  sva::Vector3<T> mcdd = sva::Vector3<T>::Zero();
  T M = T(0);
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & I = mb.body(i).inertia();
    const auto & v = mbc.bodyVelB[k];
    mcdd += mbc.bodyPosW[k].rotation().transpose() * (I * mbc.bodyAccB[k] + v.crossDual(I * v)).force();
    M += I.mass();
  }
  return mcdd / M;
}

/// Checked variants: throw std::domain_error on a size mismatch or a zero total mass.
template<typename T>
sva::Vector3<T> sComputeCoM(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
template<typename T>
sva::Vector3<T> sComputeCoMVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
template<typename T>
sva::Vector3<T> sComputeCoMAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

/// Jacobian of the (optionally weighted) CoM: J alpha = sum_i k_i xd_i, k_i = w_i m_i / M.
/// Column of joint j: with ^0S_j = [w; v_O] (world coordinates, world origin) and the subtree sums
/// K_j = sum k_i, P_j = sum k_i x_i over the bodies i supported by j: col = K_j v_O + w x P_j.
template<typename T>
class CoMJacobianTpl
{
public:
  using Scalar = T;
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector3 = sva::Vector3<T>;
  using MotionVecT = sva::MotionVec<T>;

  CoMJacobianTpl() = default;
  explicit CoMJacobianTpl(const MultiBodyTpl<T> & mb);
  /// @param weight One weight per body (1 everywhere gives the CoM Jacobian).
  CoMJacobianTpl(const MultiBodyTpl<T> & mb, std::vector<T> weight);

  /// Recompute the coefficients after a change of the body inertias of mb.
  void updateInertialParameters(const MultiBodyTpl<T> & mb);
  const std::vector<T> & weight() const { return weight_; }
  void weight(const MultiBodyTpl<T> & mb, std::vector<T> w);

  /// Use bodyPosW and motionSubspace (FK). Fill the 3 x nrDof CoM Jacobian (world coordinates).
  const MatrixX & jacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Use bodyPosW, motionSubspace (FK), bodyVelB and jointVelocity (FV). Fill d/dt jacobian().
  const MatrixX & jacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Use bodyPosW and bodyVelB. Return J alpha (the CoM velocity when unweighted).
  Vector3 velocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Use bodyPosW, bodyVelB and jointVelocity. Return Jdot alpha (CoM acceleration for alphaD = 0).
  Vector3 normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Same from precomputed body normal accelerations (computeNormalAccB in Jacobian.h):
  /// sum_i k_i E_0_i^T (a_O + wd x c_i + w x (v_O + w x c_i)).
  Vector3 normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                             const std::vector<MotionVecT> & normalAccB) const;

  // Checked variants: throw std::domain_error when mb/mbc do not match.
  const MatrixX & sJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  Vector3 sVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  Vector3 sNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

private:
  /// Subtree sums K_j, P_j (and Pd_j = sum k_i xd_i when withVelocity).
  void subtreeSums(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool withVelocity);
  void check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool needVelocity) const;

  std::vector<T> weight_;
  std::vector<T> coeff_;     ///< k_i = w_i m_i / M
  std::vector<Vector3> com_; ///< c_i, body coordinates (zero for a massless body)
  std::vector<T> subK_;
  std::vector<Vector3> subP_, subPd_;
  std::vector<MotionVecT> normalAccB_;
  MatrixX jac_, jacDot_;
};

using CoMJacobian = CoMJacobianTpl<double>;

// ---------------------------------------------------------------------------------------------

template<typename T>
CoMJacobianTpl<T>::CoMJacobianTpl(const MultiBodyTpl<T> & mb)
: CoMJacobianTpl(mb, std::vector<T>(static_cast<std::size_t>(mb.nrBodies()), T(1)))
{
}

template<typename T>
CoMJacobianTpl<T>::CoMJacobianTpl(const MultiBodyTpl<T> & mb, std::vector<T> w)
{
  const auto n = static_cast<std::size_t>(mb.nrBodies());
  subK_.resize(n);
  subP_.resize(n);
  subPd_.resize(n);
  normalAccB_.resize(n);
  jac_ = MatrixX::Zero(3, mb.nrDof());
  jacDot_ = MatrixX::Zero(3, mb.nrDof());
  weight(mb, std::move(w));
}

template<typename T>
void CoMJacobianTpl<T>::weight(const MultiBodyTpl<T> & mb, std::vector<T> w)
{
  if(static_cast<int>(w.size()) != mb.nrBodies())
    throw std::domain_error("CoMJacobian: " + std::to_string(w.size()) + " weights, model has " +
                                std::to_string(mb.nrBodies()) + " bodies");
  weight_ = std::move(w);
  updateInertialParameters(mb);
}

template<typename T>
void CoMJacobianTpl<T>::updateInertialParameters(const MultiBodyTpl<T> & mb)
{
  T M = T(0);
  for(const auto & b : mb.bodies()) M += b.inertia().mass();
  coeff_.clear();
  com_.clear();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & I = mb.body(i).inertia();
    coeff_.push_back(weight_[static_cast<std::size_t>(i)] * I.mass() / M);
    com_.push_back(I.mass() > T(0) ? Vector3(I.momentum() / I.mass()) : Vector3::Zero());
  }
}

template<typename T>
void CoMJacobianTpl<T>::subtreeSums(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool withVelocity)
{
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & X_0_i = mbc.bodyPosW[k];
    const sva::Matrix3<T> Et = X_0_i.rotation().transpose();
    subK_[k] = coeff_[k];
    subP_[k] = coeff_[k] * (X_0_i.translation() + Et * com_[k]); // k_i x_i
    if(withVelocity)
    {
      const auto & v = mbc.bodyVelB[k];
      subPd_[k] = coeff_[k] * (Et * (v.linear() + v.angular().cross(com_[k]))); // k_i xd_i
    }
  }
  for(int i = mb.nrBodies() - 1; i > 0; --i)
  {
    const auto k = static_cast<std::size_t>(i), p = static_cast<std::size_t>(mb.parent(i));
    subK_[p] += subK_[k];
    subP_[p] += subP_[k];
    if(withVelocity) subPd_[p] += subPd_[k];
  }
}

template<typename T>
const typename CoMJacobianTpl<T>::MatrixX & CoMJacobianTpl<T>::jacobian(const MultiBodyTpl<T> & mb,
                                                                        const MultiBodyConfigTpl<T> & mbc)
{
  subtreeSums(mb, mbc, false);
  for(int j = 0; j < mb.nrJoints(); ++j)
  {
    const auto k = static_cast<std::size_t>(j);
    const auto & S = mbc.motionSubspace[k];
    const sva::PTransform<T> X_j_0 = mbc.bodyPosW[k].inv();
    for(Eigen::Index c = 0; c < S.cols(); ++c)
    {
      // col = K_j v_O + w x P_j
      const MotionVecT s = X_j_0 * MotionVecT(S.col(c));
      jac_.col(mb.jointPosInDof(j) + c) = subK_[k] * s.linear() + s.angular().cross(subP_[k]);
    }
  }
  return jac_;
}

template<typename T>
const typename CoMJacobianTpl<T>::MatrixX & CoMJacobianTpl<T>::jacobianDot(const MultiBodyTpl<T> & mb,
                                                                           const MultiBodyConfigTpl<T> & mbc)
{
  subtreeSums(mb, mbc, true);
  for(int j = 0; j < mb.nrJoints(); ++j)
  {
    const auto k = static_cast<std::size_t>(j);
    const auto & S = mbc.motionSubspace[k];
    const sva::PTransform<T> X_j_0 = mbc.bodyPosW[k].inv();
    // carrier of S_j (world coordinates): body j (forward joint) or its parent (backward joint)
    const MotionVecT v_c =
        X_j_0 * (mb.joint(j).forward() ? mbc.bodyVelB[k] : mbc.bodyVelB[k] - mbc.jointVelocity[k]);
    for(Eigen::Index c = 0; c < S.cols(); ++c)
    {
      // d/dt(K v_O + w x P) = K vd_O + wd x P + w x Pd, with d/dt ^0S = v_c x ^0S
      const MotionVecT s = X_j_0 * MotionVecT(S.col(c));
      const MotionVecT sd = v_c.cross(s);
      jacDot_.col(mb.jointPosInDof(j) + c) =
          subK_[k] * sd.linear() + sd.angular().cross(subP_[k]) + s.angular().cross(subPd_[k]);
    }
  }
  return jacDot_;
}

template<typename T>
typename CoMJacobianTpl<T>::Vector3 CoMJacobianTpl<T>::velocity(const MultiBodyTpl<T> & mb,
                                                                const MultiBodyConfigTpl<T> & mbc) const
{
  Vector3 v = Vector3::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & vB = mbc.bodyVelB[k];
    // k_i E^T (v_O + w x c_i)
    v += coeff_[k] * (mbc.bodyPosW[k].rotation().transpose() * (vB.linear() + vB.angular().cross(com_[k])));
  }
  return v;
}

template<typename T>
typename CoMJacobianTpl<T>::Vector3 CoMJacobianTpl<T>::normalAcceleration(const MultiBodyTpl<T> & mb,
                                                                          const MultiBodyConfigTpl<T> & mbc)
{
  computeNormalAccB(mb, mbc, normalAccB_);
  return normalAcceleration(mb, mbc, normalAccB_);
}

template<typename T>
typename CoMJacobianTpl<T>::Vector3 CoMJacobianTpl<T>::normalAcceleration(
    const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const std::vector<MotionVecT> & normalAccB) const
{
  Vector3 a = Vector3::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & v = mbc.bodyVelB[k];
    const auto & acc = normalAccB[k];
    // classical acceleration of c_i: a_O + wd x c + w x (v_O + w x c)   (body coordinates)
    const Vector3 cdd = acc.linear() + acc.angular().cross(com_[k]) +
                        v.angular().cross(Vector3(v.linear() + v.angular().cross(com_[k])));
    a += coeff_[k] * (mbc.bodyPosW[k].rotation().transpose() * cdd);
  }
  return a;
}

/// The CoM Jacobian by its definition (RBDyn's "simple but slow" CoMJacobianDummy):
///   J_com = sum_i w_i m_i J_v,i / M,   M = sum_i m_i,
/// with J_v,i the linear rows of body i's Jacobian at its centre of mass (world axes). jacobianDot
/// sums the Jacobians' derivatives the same way. CoMJacobian computes the same in O(n).
template<typename T>
class CoMJacobianDummyTpl
{
public:
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

  CoMJacobianDummyTpl() = default;
  explicit CoMJacobianDummyTpl(const MultiBodyTpl<T> & mb)
  : CoMJacobianDummyTpl(mb, std::vector<T>(static_cast<std::size_t>(mb.nrBodies()), T(1)))
  {
  }
  /// @param weight One weight per body (std::domain_error otherwise).
  CoMJacobianDummyTpl(const MultiBodyTpl<T> & mb, std::vector<T> weight) : weight_(std::move(weight))
  {
    if(static_cast<int>(weight_.size()) != mb.nrBodies())
      throw std::domain_error("CoMJacobianDummy: " + std::to_string(weight_.size()) + " weights for " +
                              std::to_string(mb.nrBodies()) + " bodies");
    for(int i = 0; i < mb.nrBodies(); ++i)
    {
      const auto & I = mb.body(i).inertia();
      const sva::Vector3<T> c = I.mass() > T(0) ? sva::Vector3<T>(I.momentum() / I.mass()) : sva::Vector3<T>::Zero();
      jacs_.emplace_back(mb, mb.body(i).name(), c);
      totalMass_ += I.mass();
    }
    jac_ = MatrixX::Zero(3, mb.nrDof());
    jacDot_ = MatrixX::Zero(3, mb.nrDof());
  }

  /// Use bodyPosW and motionSubspace (FK). Fill the 3 x nrDof CoM Jacobian.
  const MatrixX & jacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    return sum(mb, jac_, [&](JacobianTpl<T> & J) -> const MatrixX & { return J.jacobian(mb, mbc); });
  }
  /// Use bodyPosW, motionSubspace (FK), bodyVelB and jointVelocity (FV). Fill d/dt jacobian().
  const MatrixX & jacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    return sum(mb, jacDot_, [&](JacobianTpl<T> & J) -> const MatrixX & { return J.jacobianDot(mb, mbc); });
  }
  /// The last results.
  const MatrixX & jacobian() const { return jac_; }
  const MatrixX & jacobianDot() const { return jacDot_; }

  /// Checked variants: std::domain_error when mb / mbc do not match.
  const MatrixX & sJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    check(mb, mbc);
    return jacobian(mb, mbc);
  }
  const MatrixX & sJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    check(mb, mbc);
    return jacobianDot(mb, mbc);
  }

private:
  /// out = sum_i w_i m_i (linear rows of perBody(J_i), scattered to nrDof columns) / M
  template<typename PerBody>
  const MatrixX & sum(const MultiBodyTpl<T> & mb, MatrixX & out, PerBody perBody)
  {
    out.setZero();
    for(std::size_t i = 0; i < jacs_.size(); ++i)
    {
      if(jacs_[i].dof() == 0) continue; // (no block of an empty matrix: Eigen offsets a null pointer)
      const T k = weight_[i] * mb.body(static_cast<int>(i)).inertia().mass() / totalMass_;
      jacs_[i].addFullJacobian(mb, MatrixX(k * perBody(jacs_[i]).template bottomRows<3>()), out);
    }
    return out;
  }
  void check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const
  {
    if(static_cast<int>(jacs_.size()) != mb.nrBodies() || jac_.cols() != mb.nrDof())
      throw std::domain_error("CoMJacobianDummy: the MultiBody does not match");
    if(static_cast<int>(mbc.bodyPosW.size()) != mb.nrBodies() || mbc.motionSubspace.size() != mbc.bodyPosW.size() ||
       mbc.bodyVelB.size() != mbc.bodyPosW.size() || mbc.jointVelocity.size() != mbc.bodyPosW.size())
      throw std::domain_error("CoMJacobianDummy: the MultiBodyConfig does not match the MultiBody");
  }

  std::vector<T> weight_;
  std::vector<JacobianTpl<T>> jacs_;
  T totalMass_ = T(0);
  MatrixX jac_, jacDot_;
};

using CoMJacobianDummy = CoMJacobianDummyTpl<double>;

extern template sva::Vector3<double> computeCoM(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
extern template sva::Vector3<long double> computeCoM(const MultiBodyTpl<long double> &,
                                                     const MultiBodyConfigTpl<long double> &);
extern template sva::Vector3<double> computeCoMVelocity(const MultiBodyTpl<double> &,
                                                        const MultiBodyConfigTpl<double> &);
extern template sva::Vector3<long double> computeCoMVelocity(const MultiBodyTpl<long double> &,
                                                             const MultiBodyConfigTpl<long double> &);
extern template sva::Vector3<double> computeCoMAcceleration(const MultiBodyTpl<double> &,
                                                            const MultiBodyConfigTpl<double> &);
extern template sva::Vector3<long double> computeCoMAcceleration(const MultiBodyTpl<long double> &,
                                                                 const MultiBodyConfigTpl<long double> &);
extern template sva::Vector3<double> sComputeCoM(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
extern template sva::Vector3<long double> sComputeCoM(const MultiBodyTpl<long double> &,
                                                      const MultiBodyConfigTpl<long double> &);
extern template sva::Vector3<double> sComputeCoMVelocity(const MultiBodyTpl<double> &,
                                                         const MultiBodyConfigTpl<double> &);
extern template sva::Vector3<long double> sComputeCoMVelocity(const MultiBodyTpl<long double> &,
                                                              const MultiBodyConfigTpl<long double> &);
extern template sva::Vector3<double> sComputeCoMAcceleration(const MultiBodyTpl<double> &,
                                                             const MultiBodyConfigTpl<double> &);
extern template sva::Vector3<long double> sComputeCoMAcceleration(const MultiBodyTpl<long double> &,
                                                                  const MultiBodyConfigTpl<long double> &);
extern template class CoMJacobianDummyTpl<double>;
extern template class CoMJacobianDummyTpl<long double>;
extern template class CoMJacobianTpl<double>;
extern template class CoMJacobianTpl<long double>;

} // namespace rbd
