#pragma once
// Jacobian of a point fixed on a body, restricted to the joints on the path root -> body.
//
// Column block of joint j expressed in a frame F:  J_j = X_j_F S_j  (X_j_F = X_0_F X_0_j^-1).
// Time derivative:  Jdot_j = (v_c(j) - v_F) x J_j,  with v_F the velocity of the frame F and v_c(j)
// the velocity of the body in which S_j is constant (body j for a forward joint; its parent for a
// backward joint, whose S is constant in the predecessor frame), everything in F coordinates.
// Summed against alpha: Jdot alpha = sum_j (v_λ(j) - v_F) x (S_j alpha_j)   (since v_J x v_J = 0).

#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Use bodyVelB and jointVelocity (forwardVelocity). Fill normalAccB (resized to nrBodies) with the
/// body accelerations for alphaD = 0 and no gravity (body coordinates):
/// a_i = X_p_i a_λ(i) + v_i x (S_i alpha_i).
template<typename T>
void computeNormalAccB(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                       std::vector<sva::MotionVec<T>> & normalAccB)
{
  normalAccB.resize(static_cast<std::size_t>(mb.nrBodies()));
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const int p = mb.parent(i);
    const sva::MotionVec<T> vxvJ = mbc.bodyVelB[k].cross(mbc.jointVelocity[k]);
    normalAccB[k] = p < 0 ? vxvJ : mbc.parentToSon[k] * normalAccB[static_cast<std::size_t>(p)] + vxvJ;
  }
}

template<typename T>
class JacobianTpl
{
public:
  using Scalar = T;
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector3 = sva::Vector3<T>;
  using MotionVecT = sva::MotionVec<T>;
  using PTransformT = sva::PTransform<T>;

  JacobianTpl() = default;
  /// @param bodyPoint Point of the body, in body coordinates (Jacobian reference point).
  JacobianTpl(const MultiBodyTpl<T> & mb, const std::string & bodyName, const Vector3 & bodyPoint = Vector3::Zero());

  /// Joints from the root joint to the body's joint, in that order.
  const std::vector<int> & jointsPath() const { return jointsPath_; }
  /// Number of columns of the compact Jacobian (sum of the dof of jointsPath()).
  int dof() const { return dof_; }
  int bodyIndex() const { return body_; }
  const std::string & bodyName() const { return bodyName_; }
  const Vector3 & point() const { return point_; }
  void point(const Vector3 & bodyPoint) { point_ = bodyPoint; }

  /// Use bodyPosW and motionSubspace (forwardKinematics). Fill the 6 x dof() Jacobian expressed in
  /// the frame X_0_p (world to that frame): column block of joint j = X_0_p X_0_j^-1 S_j.
  const MatrixX & jacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_p);
  /// Same at the body point, world-aligned axes: J alpha = [w; v_point] in world coordinates.
  const MatrixX & jacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Same at the body point, body axes: J alpha = [w; v_point] in body coordinates.
  const MatrixX & bodyJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Use bodyPosW and motionSubspace. Fill the 3 x dof() Jacobian of the body-fixed vector vec
  /// (body coordinates) in world coordinates: d/dt(E_0_b^T vec) = w x u = -u^ J_w, u = E_0_b^T vec.
  const MatrixX & vectorJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & vec);
  /// Same in body coordinates: E_0_b d/dt(E_0_b^T vec) = w_B x vec = -vec^ J_w,B.
  const MatrixX & bodyVectorJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                     const Vector3 & vec);
  /// Use bodyPosW, motionSubspace (FK), bodyVelB and jointVelocity (FV). Fill d/dt jacobian(mb, mbc).
  const MatrixX & jacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Same for bodyJacobian(mb, mbc).
  const MatrixX & bodyJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

  /// Move the reference point of a 6-row Jacobian: res column = [w; v + w x offset], with offset
  /// the vector from the old to the new point in the Jacobian's coordinates (mbc is not read).
  void translateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                         const Vector3 & offset, MatrixX & res) const;
  /// Scatter a compact Jacobian (jac.cols() == dof()) into res (jac.rows() x nrDof, zero elsewhere).
  void fullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;

  /// Use bodyPosW and bodyVelB. Return J alpha = [w; v_point], world-aligned axes.
  MotionVecT velocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Use bodyVelB. Return J_B alpha = [w; v_point], body axes.
  MotionVecT bodyVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Use bodyPosW, bodyVelB, jointVelocity. Return Jdot alpha (world-aligned, at the point), i.e.
  /// [dw/dt; d^2p/dt^2] (classical acceleration of the point) when alphaD = 0.
  MotionVecT normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Same from precomputed normal accelerations (computeNormalAccB):
  /// X_b_F a_b + [0; w x v_point].
  MotionVecT normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                const std::vector<MotionVecT> & normalAccB) const;
  /// Use bodyVelB, jointVelocity. Return Jdot_B alpha = spatial acceleration of the body for
  /// alphaD = 0 at the point, body axes.
  MotionVecT bodyNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Same from precomputed normal accelerations: xlt(point) a_b.
  MotionVecT bodyNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                    const std::vector<MotionVecT> & normalAccB) const;

  // Checked variants: throw std::invalid_argument when mb/mbc/jac do not match this Jacobian.
  const MatrixX & sJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sBodyJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sVectorJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & vec);
  const MatrixX & sBodyVectorJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                      const Vector3 & vec);
  const MatrixX & sJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sBodyJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  void sTranslateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                          const Vector3 & offset, MatrixX & res) const;
  void sFullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;

private:
  /// World-aligned frame at the point: X_0_F = xlt(p_W).
  PTransformT worldPointFrame(const MultiBodyConfigTpl<T> & mbc) const;
  /// Body-aligned frame at the point: X_0_P = xlt(point) X_0_b.
  PTransformT bodyPointFrame(const MultiBodyConfigTpl<T> & mbc) const
  {
    return PTransformT(point_) * mbc.bodyPosW[static_cast<std::size_t>(body_)];
  }
  /// Jdot in frame X_0_F moving with velocity v_F (F coordinates).
  void fillDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_F,
               const MotionVecT & v_F);
  /// Jdot alpha in frame X_0_F moving with velocity v_F.
  MotionVecT normalAcc(const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_F, const MotionVecT & v_F) const;
  void check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool needVelocity) const;

  std::vector<int> jointsPath_;
  std::vector<int> jointsCol_; ///< first column of each path joint in the compact Jacobian
  int dof_ = 0;
  int body_ = -1;
  std::string bodyName_;
  Vector3 point_ = Vector3::Zero();
  MatrixX jac_, jacDot_, vecJac_;
};

using Jacobian = JacobianTpl<double>;

// ---------------------------------------------------------------------------------------------

template<typename T>
JacobianTpl<T>::JacobianTpl(const MultiBodyTpl<T> & mb, const std::string & bodyName, const Vector3 & bodyPoint)
: body_(mb.bodyIndexByName(bodyName)), bodyName_(bodyName), point_(bodyPoint)
{
  for(int j = body_; j >= 0; j = mb.parent(j)) jointsPath_.insert(jointsPath_.begin(), j);
  for(int j : jointsPath_)
  {
    jointsCol_.push_back(dof_);
    dof_ += mb.joint(j).dof();
  }
  jac_ = MatrixX::Zero(6, dof_);
  jacDot_ = MatrixX::Zero(6, dof_);
  vecJac_ = MatrixX::Zero(3, dof_);
}

template<typename T>
typename JacobianTpl<T>::PTransformT JacobianTpl<T>::worldPointFrame(const MultiBodyConfigTpl<T> & mbc) const
{
  const auto & X_0_b = mbc.bodyPosW[static_cast<std::size_t>(body_)];
  // p_W = r_b + E_0_b^T point
  return PTransformT(Vector3(X_0_b.translation() + X_0_b.rotation().transpose() * point_));
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::jacobian(const MultiBodyTpl<T> &,
                                                                  const MultiBodyConfigTpl<T> & mbc,
                                                                  const PTransformT & X_0_p)
{
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const auto j = static_cast<std::size_t>(jointsPath_[n]);
    const auto & S = mbc.motionSubspace[j];
    // J_j = X_j_p S_j
    const PTransformT X_j_p = X_0_p * mbc.bodyPosW[j].inv();
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      jac_.col(jointsCol_[n] + c) = (X_j_p * MotionVecT(S.col(c))).vector();
  }
  return jac_;
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::jacobian(const MultiBodyTpl<T> & mb,
                                                                  const MultiBodyConfigTpl<T> & mbc)
{
  return jacobian(mb, mbc, worldPointFrame(mbc));
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::bodyJacobian(const MultiBodyTpl<T> & mb,
                                                                      const MultiBodyConfigTpl<T> & mbc)
{
  return jacobian(mb, mbc, bodyPointFrame(mbc));
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::vectorJacobian(const MultiBodyTpl<T> &,
                                                                        const MultiBodyConfigTpl<T> & mbc,
                                                                        const Vector3 & vec)
{
  const auto & E_0_b = mbc.bodyPosW[static_cast<std::size_t>(body_)].rotation();
  const sva::Matrix3<T> mux = -sva::vector3ToCrossMatrix(Vector3(E_0_b.transpose() * vec)); // -u^
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const auto j = static_cast<std::size_t>(jointsPath_[n]);
    const auto & S = mbc.motionSubspace[j];
    // world angular columns E_0_j^T S_w, then -u^ (.)
    const sva::Matrix3<T> M = mux * mbc.bodyPosW[j].rotation().transpose();
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      vecJac_.col(jointsCol_[n] + c) = M * S.col(c).template head<3>();
  }
  return vecJac_;
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::bodyVectorJacobian(const MultiBodyTpl<T> &,
                                                                            const MultiBodyConfigTpl<T> & mbc,
                                                                            const Vector3 & vec)
{
  const auto & E_0_b = mbc.bodyPosW[static_cast<std::size_t>(body_)].rotation();
  const sva::Matrix3<T> mvx = -sva::vector3ToCrossMatrix(vec); // -vec^
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const auto j = static_cast<std::size_t>(jointsPath_[n]);
    const auto & S = mbc.motionSubspace[j];
    // body angular columns E_0_b E_0_j^T S_w, then -vec^ (.)
    const sva::Matrix3<T> M = mvx * E_0_b * mbc.bodyPosW[j].rotation().transpose();
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      vecJac_.col(jointsCol_[n] + c) = M * S.col(c).template head<3>();
  }
  return vecJac_;
}

template<typename T>
void JacobianTpl<T>::fillDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_F,
                             const MotionVecT & v_F)
{
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const auto j = static_cast<std::size_t>(jointsPath_[n]);
    const auto & S = mbc.motionSubspace[j];
    const PTransformT X_j_F = X_0_F * mbc.bodyPosW[j].inv();
    // carrier of S_j: body j (forward joint) or its parent, v_λ = v_j - v_J (backward joint)
    const MotionVecT v_c = X_j_F * (mb.joint(jointsPath_[n]).forward() ? mbc.bodyVelB[j]
                                                                         : mbc.bodyVelB[j] - mbc.jointVelocity[j]);
    const MotionVecT v_rel = v_c - v_F;
    // Jdot_j = (v_c - v_F) x X_j_F S_j
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      jacDot_.col(jointsCol_[n] + c) = v_rel.cross(X_j_F * MotionVecT(S.col(c))).vector();
  }
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::jacobianDot(const MultiBodyTpl<T> & mb,
                                                                     const MultiBodyConfigTpl<T> & mbc)
{
  // F: world-aligned, translating with the point: v_F = [0; v_point]
  fillDot(mb, mbc, worldPointFrame(mbc), MotionVecT(Vector3::Zero(), velocity(mb, mbc).linear()));
  return jacDot_;
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::bodyJacobianDot(const MultiBodyTpl<T> & mb,
                                                                         const MultiBodyConfigTpl<T> & mbc)
{
  // F: attached to the body: v_F = body velocity at the point
  fillDot(mb, mbc, bodyPointFrame(mbc), bodyVelocity(mb, mbc));
  return jacDot_;
}

template<typename T>
void JacobianTpl<T>::translateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> &,
                                       const Vector3 & offset, MatrixX & res) const
{
  res.resize(jac.rows(), jac.cols());
  for(Eigen::Index c = 0; c < jac.cols(); ++c)
  {
    // v' = v + w x offset
    res.col(c).template head<3>() = jac.col(c).template head<3>();
    res.col(c).template tail<3>() =
        jac.col(c).template tail<3>() + Vector3(jac.col(c).template head<3>()).cross(offset);
  }
}

template<typename T>
void JacobianTpl<T>::fullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac,
                                  MatrixX & res) const
{
  res.resize(jac.rows(), mb.nrDof());
  res.setZero();
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const int j = jointsPath_[n];
    const int d = mb.joint(j).dof();
    res.middleCols(mb.jointPosInDof(j), d) = jac.middleCols(jointsCol_[n], d);
  }
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::velocity(const MultiBodyTpl<T> &,
                                                             const MultiBodyConfigTpl<T> & mbc) const
{
  const auto b = static_cast<std::size_t>(body_);
  // X_b_F = plx(E_0_b^T, point)
  return PTransformT(sva::Matrix3<T>(mbc.bodyPosW[b].rotation().transpose()), point_) * mbc.bodyVelB[b];
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::bodyVelocity(const MultiBodyTpl<T> &,
                                                                 const MultiBodyConfigTpl<T> & mbc) const
{
  return PTransformT(point_) * mbc.bodyVelB[static_cast<std::size_t>(body_)];
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcc(const MultiBodyConfigTpl<T> & mbc,
                                                              const PTransformT & X_0_F,
                                                              const MotionVecT & v_F) const
{
  MotionVecT acc = MotionVecT::Zero();
  for(int jn : jointsPath_)
  {
    const auto j = static_cast<std::size_t>(jn);
    const PTransformT X_j_F = X_0_F * mbc.bodyPosW[j].inv();
    // (v_λ(j) - v_F) x v_J,j with v_λ(j) = v_j - v_J,j (body j coordinates)
    acc += (X_j_F * (mbc.bodyVelB[j] - mbc.jointVelocity[j]) - v_F).cross(X_j_F * mbc.jointVelocity[j]);
  }
  return acc;
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcceleration(const MultiBodyTpl<T> & mb,
                                                                       const MultiBodyConfigTpl<T> & mbc) const
{
  return normalAcc(mbc, worldPointFrame(mbc), MotionVecT(Vector3::Zero(), velocity(mb, mbc).linear()));
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcceleration(
    const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const std::vector<MotionVecT> & normalAccB) const
{
  const auto b = static_cast<std::size_t>(body_);
  const MotionVecT v = velocity(mb, mbc);
  // spatial acceleration at the point (world axes), then classical: pdd = a_lin + w x pd
  MotionVecT a = PTransformT(sva::Matrix3<T>(mbc.bodyPosW[b].rotation().transpose()), point_) * normalAccB[b];
  a.linear() += v.angular().cross(v.linear());
  return a;
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::bodyNormalAcceleration(const MultiBodyTpl<T> & mb,
                                                                           const MultiBodyConfigTpl<T> & mbc) const
{
  return normalAcc(mbc, bodyPointFrame(mbc), bodyVelocity(mb, mbc));
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::bodyNormalAcceleration(
    const MultiBodyTpl<T> &, const MultiBodyConfigTpl<T> &, const std::vector<MotionVecT> & normalAccB) const
{
  return PTransformT(point_) * normalAccB[static_cast<std::size_t>(body_)];
}

extern template void computeNormalAccB(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &,
                                       std::vector<sva::MotionVec<double>> &);
extern template void computeNormalAccB(const MultiBodyTpl<long double> &, const MultiBodyConfigTpl<long double> &,
                                       std::vector<sva::MotionVec<long double>> &);
extern template class JacobianTpl<double>;
extern template class JacobianTpl<long double>;

} // namespace rbd
