#pragma once
// Jacobian of a point fixed on a body, restricted to the joints on the path root -> body, or, with
// a reference body, on the path reference body -> body (RBDyn's Jacobian(mb, body, refBody)).
//
// Column block of joint j expressed in a frame F:  J_j = sign_j X_j_F S_j  (X_j_F = X_0_F X_0_j^-1).
// sign_j = +1 on the root (or common ancestor) -> body side; -1 for the joints between the
// reference body and the common ancestor, whose motion moves the reference frame: J alpha is the
// velocity of the point relative to the reference body (J_body - J_ref at the same point).
// Time derivative:  Jdot_j = (v_c(j) - v_F) x J_j,  with v_F the velocity of the frame F and v_c(j)
// the velocity of the body in which S_j is constant (body j for a forward joint; its parent for a
// backward joint, whose S is constant in the predecessor frame), everything in F coordinates.
// Summed against alpha: Jdot alpha = sum_j (v_λ(j) - v_F) x (S_j alpha_j)   (since v_J x v_J = 0).
//
// velocity(), normalAcceleration() and their body variants are those of the body (root path), as
// RBDyn's, also for a Jacobian with a reference body.

#include <stdexcept>
#include <string>
#include <utility>
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

/// A contiguous run of dofs of a Jacobian path: columns [startJac, startJac + length) of the
/// compact Jacobian are the dofs [startDof, startDof + length) of the model.
struct Block
{
  Block() = default;
  Block(Eigen::Index startDofIn, Eigen::Index startJacIn, Eigen::Index lengthIn)
  : startDof(startDofIn), startJac(startJacIn), length(lengthIn)
  {
  }
  Eigen::Index startDof = 0;
  Eigen::Index startJac = 0;
  Eigen::Index length = 0;
};
using Blocks = std::vector<Block>;

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
  /// Jacobian of the root -> body path. @param bodyPoint Point of the body, body coordinates.
  JacobianTpl(const MultiBodyTpl<T> & mb, const std::string & bodyName, const Vector3 & bodyPoint = Vector3::Zero());
  /// Jacobian of the refBodyName -> bodyName path: J alpha is the velocity of the point relative to
  /// the reference body. Path order (RBDyn's): the reference body's joints up to the common
  /// ancestor (excluded), then the joints below the common ancestor down to the body.
  JacobianTpl(const MultiBodyTpl<T> & mb, const std::string & bodyName, const std::string & refBodyName,
              const Vector3 & bodyPoint = Vector3::Zero());

  /// Joints of the path, in column order.
  const std::vector<int> & jointsPath() const { return jointsPath_; }
  /// +1 or -1 per path joint (see the top of this file).
  const std::vector<T> & jointsSign() const { return jointsSign_; }
  /// Number of columns of the compact Jacobian (sum of the dof of jointsPath()).
  int dof() const { return dof_; }
  int bodyIndex() const { return body_; }
  /// Index of the reference body, -1 for a root -> body Jacobian.
  int refBodyIndex() const { return refBody_; }
  const std::string & bodyName() const { return bodyName_; }
  const Vector3 & point() const { return point_; }
  void point(const Vector3 & bodyPoint) { point_ = bodyPoint; }

  /// Use bodyPosW and motionSubspace (forwardKinematics). Fill the 6 x dof() Jacobian expressed in
  /// the frame X_0_p (world to that frame): column block of joint j = sign_j X_0_p X_0_j^-1 S_j.
  const MatrixX & jacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_p);
  /// Same at the body point, world-aligned axes (reference body axes with a reference body):
  /// J alpha = [w; v_point].
  const MatrixX & jacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Same at the body point, body axes: J alpha = [w; v_point] in body coordinates.
  const MatrixX & bodyJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Use bodyPosW and motionSubspace. Fill the 6 x dof() Jacobian of the body-fixed vector vec
  /// (body coordinates) in the axes of jacobian(): linear rows d/dt(E_0_b^T vec) = w x u = -u^ J_w
  /// (u = E_0_b^T vec), angular rows zero (the linear rows of the Jacobians at point + vec and at
  /// point, subtracted, as RBDyn's).
  const MatrixX & vectorJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & vec);
  /// Same in body coordinates: linear rows E_0_b d/dt(E_0_b^T vec) = w_B x vec = -vec^ J_w,B.
  const MatrixX & vectorBodyJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                     const Vector3 & vec);
  /// Use bodyPosW, motionSubspace (FK), bodyVelB and jointVelocity (FV). Fill d/dt jacobian(mb, mbc).
  const MatrixX & jacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  /// Same for bodyJacobian(mb, mbc).
  const MatrixX & bodyJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

  /// Use bodyPosW. Move the reference point of a 6-row Jacobian in the axes of jacobian() by
  /// `point` given in body coordinates: res column = [w; v + w x r], r = point in those axes.
  void translateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                         const Vector3 & point, MatrixX & res) const;
  /// Same for a Jacobian in body axes: res column = [w; v + w x point].
  void translateBodyJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                             const Vector3 & point, MatrixX & res) const;
  /// Scatter a compact Jacobian (jac.cols() == dof()) into res (jac.rows() x nrDof, zero elsewhere).
  void fullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;
  /// Add the compact Jacobian to the path's columns of res (jac.rows() x nrDof).
  void addFullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;
  void addFullJacobian(const Blocks & compactPath, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;
  /// The path's dofs as runs of consecutive model dofs.
  Blocks compactPath(const MultiBodyTpl<T> & mb) const;
  /// A dof() x dof() matrix on the path (e.g. J^T M J) scattered onto nrDof x nrDof, zero elsewhere.
  MatrixX expand(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac) const;
  /// Add a dof() x dof() matrix on the path to the path's rows and columns of res (nrDof x nrDof).
  void expandAdd(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;
  void expandAdd(const Blocks & compactPath, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;

  /// The path as a chain MultiBody: joint k of the chain is jointsPath()[k] (reversed when its sign
  /// is -1, its successor then the body it moves, with its frame on the joint's frame), the chain's
  /// world is the reference body's frame (the world without one), its last body is the body. The
  /// chain's q are the path joints' q, its Jacobian at the last body this one's (when the body is an
  /// ancestor of the reference body, the last joint is reversed and the point is then to be given in
  /// that joint's frame, X_b_j = mb.transform(jointsPath().back())).
  MultiBodyTpl<T> subMultiBody(const MultiBodyTpl<T> & mb) const;

  /// Use bodyVelB. Return X_b_p v_b (the body velocity in frame p, X_b_p from the body).
  MotionVecT velocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_b_p) const;
  /// Use bodyPosW and bodyVelB. Return [w; v_point], world-aligned axes.
  MotionVecT velocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Use bodyVelB. Return [w; v_point], body axes.
  MotionVecT bodyVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Use bodyPosW, bodyVelB, jointVelocity. Return the classical acceleration of the point for
  /// alphaD = 0, [dw/dt; d^2p/dt^2], world-aligned axes.
  MotionVecT normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Same from precomputed normal accelerations (computeNormalAccB): X_b_F a_b + [0; w x v_point].
  MotionVecT normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                const std::vector<MotionVecT> & normalAccB) const;
  /// Use bodyVelB, jointVelocity. Return X_b_p a_b + V_b_p x (X_b_p v_b): the normal acceleration
  /// in a frame p moving with velocity V_b_p (RBDyn's form).
  MotionVecT normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                const PTransformT & X_b_p, const MotionVecT & V_b_p) const;
  /// Same from precomputed normal accelerations.
  MotionVecT normalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                const std::vector<MotionVecT> & normalAccB, const PTransformT & X_b_p,
                                const MotionVecT & V_b_p) const;
  /// Use bodyVelB, jointVelocity. Return the spatial acceleration of the body for alphaD = 0 at the
  /// point, body axes.
  MotionVecT bodyNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  /// Same from precomputed normal accelerations: xlt(point) a_b.
  MotionVecT bodyNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                    const std::vector<MotionVecT> & normalAccB) const;

  // Checked variants: throw std::domain_error when mb/mbc/jac do not match this Jacobian.
  const MatrixX & sJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_p);
  const MatrixX & sJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sBodyJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sVectorJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const Vector3 & vec);
  const MatrixX & sVectorBodyJacobian(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                      const Vector3 & vec);
  const MatrixX & sJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  const MatrixX & sBodyJacobianDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);
  void sTranslateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                          const Vector3 & point, MatrixX & res) const;
  void sFullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const;
  MultiBodyTpl<T> sSubMultiBody(const MultiBodyTpl<T> & mb) const;
  MotionVecT sVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  MotionVecT sBodyVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  MotionVecT sNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;
  MotionVecT sBodyNormalAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const;

private:
  /// Axes of jacobian(): the world's, or the reference body's (E_0_ref).
  sva::Matrix3<T> axes(const MultiBodyConfigTpl<T> & mbc) const
  {
    return refBody_ < 0 ? sva::Matrix3<T>::Identity() : mbc.bodyPosW[static_cast<std::size_t>(refBody_)].rotation();
  }
  /// Frame of jacobian(): origin at the point, axes(): X_0_F = plx(axes, p_W).
  PTransformT pointFrame(const MultiBodyConfigTpl<T> & mbc) const;
  /// Body-aligned frame at the point: X_0_P = xlt(point) X_0_b.
  PTransformT bodyPointFrame(const MultiBodyConfigTpl<T> & mbc) const
  {
    return PTransformT(point_) * mbc.bodyPosW[static_cast<std::size_t>(body_)];
  }
  /// -u^ J_w: the linear rows of a vector Jacobian, u the vector and M_j the rotation from the
  /// frame of S_j to the result's axes.
  void fillVector(const MultiBodyConfigTpl<T> & mbc, const Vector3 & u, const sva::Matrix3<T> & E_0_out);
  /// Jdot in frame X_0_F moving with velocity v_F (F coordinates).
  void fillDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_F,
               const MotionVecT & v_F);
  /// Jdot alpha of the root path in frame X_0_F moving with velocity v_F.
  MotionVecT normalAcc(const MultiBodyConfigTpl<T> & mbc, const PTransformT & X_0_F, const MotionVecT & v_F) const;
  /// Normal acceleration of the body (root path, body coordinates).
  MotionVecT bodyNormalAccB(const MultiBodyConfigTpl<T> & mbc) const;
  void addPathJoint(const MultiBodyTpl<T> & mb, int joint, T sign);
  void checkModel(const MultiBodyTpl<T> & mb) const;
  void check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool needVelocity) const;

  std::vector<int> jointsPath_;
  std::vector<T> jointsSign_;
  std::vector<int> jointsCol_; ///< first column of each path joint in the compact Jacobian
  std::vector<int> rootPath_;  ///< joints root -> body (velocity and normal acceleration)
  int dof_ = 0;
  int body_ = -1;
  int refBody_ = -1;
  std::string bodyName_;
  Vector3 point_ = Vector3::Zero();
  MatrixX jac_, jacDot_;
};

using Jacobian = JacobianTpl<double>;

// ---------------------------------------------------------------------------------------------

template<typename T>
void JacobianTpl<T>::addPathJoint(const MultiBodyTpl<T> & mb, int joint, T sign)
{
  jointsPath_.push_back(joint);
  jointsSign_.push_back(sign);
  jointsCol_.push_back(dof_);
  dof_ += mb.joint(joint).dof();
}

template<typename T>
JacobianTpl<T>::JacobianTpl(const MultiBodyTpl<T> & mb, const std::string & bodyName, const Vector3 & bodyPoint)
: body_(mb.bodyIndexByName(bodyName)), bodyName_(bodyName), point_(bodyPoint)
{
  for(int j = body_; j >= 0; j = mb.parent(j)) rootPath_.insert(rootPath_.begin(), j);
  for(int j : rootPath_) addPathJoint(mb, j, T(1));
  jac_ = MatrixX::Zero(6, dof_);
  jacDot_ = MatrixX::Zero(6, dof_);
}

template<typename T>
JacobianTpl<T>::JacobianTpl(const MultiBodyTpl<T> & mb, const std::string & bodyName, const std::string & refBodyName,
                            const Vector3 & bodyPoint)
: body_(mb.bodyIndexByName(bodyName)), refBody_(mb.bodyIndexByName(refBodyName)), bodyName_(bodyName),
  point_(bodyPoint)
{
  for(int j = body_; j >= 0; j = mb.parent(j)) rootPath_.insert(rootPath_.begin(), j);
  // common ancestor: the deepest body on both root paths
  std::vector<bool> aboveBody(static_cast<std::size_t>(mb.nrBodies()), false);
  for(int j : rootPath_) aboveBody[static_cast<std::size_t>(j)] = true;
  int common = refBody_;
  for(; !aboveBody[static_cast<std::size_t>(common)]; common = mb.parent(common)) addPathJoint(mb, common, T(-1));
  bool below = false;
  for(int j : rootPath_)
  {
    if(below) addPathJoint(mb, j, T(1));
    below = below || j == common;
  }
  jac_ = MatrixX::Zero(6, dof_);
  jacDot_ = MatrixX::Zero(6, dof_);
}

template<typename T>
typename JacobianTpl<T>::PTransformT JacobianTpl<T>::pointFrame(const MultiBodyConfigTpl<T> & mbc) const
{
  const auto & X_0_b = mbc.bodyPosW[static_cast<std::size_t>(body_)];
  // p_W = r_b + E_0_b^T point
  return PTransformT(axes(mbc), Vector3(X_0_b.translation() + X_0_b.rotation().transpose() * point_));
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::jacobian(const MultiBodyTpl<T> &,
                                                                  const MultiBodyConfigTpl<T> & mbc,
                                                                  const PTransformT & X_0_p)
{
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const auto j = static_cast<std::size_t>(jointsPath_[n]);
    // J_j = sign_j X_j_p S_j
    const PTransformT X_j_p = X_0_p * mbc.bodyPosW[j].inv();
    jac_.middleCols(jointsCol_[n], mbc.motionSubspace[j].cols()) = jointsSign_[n] * X_j_p.mul(mbc.motionSubspace[j]);
  }
  return jac_;
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::jacobian(const MultiBodyTpl<T> & mb,
                                                                  const MultiBodyConfigTpl<T> & mbc)
{
  return jacobian(mb, mbc, pointFrame(mbc));
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::bodyJacobian(const MultiBodyTpl<T> & mb,
                                                                      const MultiBodyConfigTpl<T> & mbc)
{
  return jacobian(mb, mbc, bodyPointFrame(mbc));
}

template<typename T>
void JacobianTpl<T>::fillVector(const MultiBodyConfigTpl<T> & mbc, const Vector3 & u, const sva::Matrix3<T> & E_0_out)
{
  const sva::Matrix3<T> mux = -sva::vector3ToCrossMatrix(u); // -u^, u in the output axes
  jac_.template topRows<3>().setZero();
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const auto j = static_cast<std::size_t>(jointsPath_[n]);
    const auto & S = mbc.motionSubspace[j];
    if(S.cols() == 0) continue; // (no block of an empty matrix: Eigen offsets a null pointer)
    // angular columns in the output axes E_0_out E_0_j^T S_w, then -u^ (.)
    const sva::Matrix3<T> M = jointsSign_[n] * mux * E_0_out * mbc.bodyPosW[j].rotation().transpose();
    jac_.block(3, jointsCol_[n], 3, S.cols()) = M * S.template topRows<3>();
  }
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::vectorJacobian(const MultiBodyTpl<T> &,
                                                                        const MultiBodyConfigTpl<T> & mbc,
                                                                        const Vector3 & vec)
{
  const sva::Matrix3<T> E_0_out = axes(mbc);
  const auto & E_0_b = mbc.bodyPosW[static_cast<std::size_t>(body_)].rotation();
  fillVector(mbc, Vector3(E_0_out * E_0_b.transpose() * vec), E_0_out);
  return jac_;
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::vectorBodyJacobian(const MultiBodyTpl<T> &,
                                                                            const MultiBodyConfigTpl<T> & mbc,
                                                                            const Vector3 & vec)
{
  fillVector(mbc, vec, mbc.bodyPosW[static_cast<std::size_t>(body_)].rotation());
  return jac_;
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
    // Jdot_j = (v_c - v_F) x J_j
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      jacDot_.col(jointsCol_[n] + c) = jointsSign_[n] * v_rel.cross(X_j_F * MotionVecT(S.col(c))).vector();
  }
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::jacobianDot(const MultiBodyTpl<T> & mb,
                                                                     const MultiBodyConfigTpl<T> & mbc)
{
  // F: at the point, axes(): translates with the point; turns with the reference body, if any.
  const PTransformT X_0_F = pointFrame(mbc);
  const Vector3 w_F = refBody_ < 0 ? Vector3::Zero()
                                   : Vector3(X_0_F.rotation() * mbc.bodyPosW[static_cast<std::size_t>(refBody_)]
                                                                     .rotation()
                                                                     .transpose()
                                                                     * mbc.bodyVelB[static_cast<std::size_t>(refBody_)].angular());
  fillDot(mb, mbc, X_0_F, MotionVecT(w_F, X_0_F.rotation() * velocity(mb, mbc).linear()));
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

namespace detail
{
/// res column = [w; v + w x r] for each column [w; v] of a 6-row Jacobian.
template<typename T, typename MatrixX>
void translateColumns(const Eigen::Ref<const MatrixX> & jac, const sva::Vector3<T> & r, MatrixX & res)
{
  res.resize(jac.rows(), jac.cols());
  res = sva::PTransform<T>(r).mul(jac);
}
} // namespace detail

template<typename T>
void JacobianTpl<T>::translateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                                       const Vector3 & point, MatrixX & res) const
{
  // the body point expressed in the Jacobian's axes: axes E_0_b^T point
  const auto & E_0_b = mbc.bodyPosW[static_cast<std::size_t>(body_)].rotation();
  detail::translateColumns<T, MatrixX>(jac, Vector3(axes(mbc) * E_0_b.transpose() * point), res);
}

template<typename T>
void JacobianTpl<T>::translateBodyJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> &,
                                           const Vector3 & point, MatrixX & res) const
{
  detail::translateColumns<T, MatrixX>(jac, point, res);
}

template<typename T>
void JacobianTpl<T>::fullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac,
                                  MatrixX & res) const
{
  res = MatrixX::Zero(jac.rows(), mb.nrDof());
  addFullJacobian(mb, jac, res);
}

template<typename T>
void JacobianTpl<T>::addFullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac,
                                     MatrixX & res) const
{
  addFullJacobian(compactPath(mb), jac, res);
}

template<typename T>
void JacobianTpl<T>::addFullJacobian(const Blocks & compactPath, const Eigen::Ref<const MatrixX> & jac,
                                     MatrixX & res) const
{
  for(const Block & b : compactPath) res.middleCols(b.startDof, b.length) += jac.middleCols(b.startJac, b.length);
}

template<typename T>
Blocks JacobianTpl<T>::compactPath(const MultiBodyTpl<T> & mb) const
{
  Blocks blocks;
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const int j = jointsPath_[n], d = mb.joint(j).dof();
    if(d == 0) continue;
    if(!blocks.empty() && blocks.back().startDof + blocks.back().length == mb.jointPosInDof(j))
      blocks.back().length += d;
    else
      blocks.emplace_back(mb.jointPosInDof(j), jointsCol_[n], d);
  }
  return blocks;
}

template<typename T>
typename JacobianTpl<T>::MatrixX JacobianTpl<T>::expand(const MultiBodyTpl<T> & mb,
                                                        const Eigen::Ref<const MatrixX> & jac) const
{
  MatrixX res = MatrixX::Zero(mb.nrDof(), mb.nrDof());
  expandAdd(mb, jac, res);
  return res;
}

template<typename T>
void JacobianTpl<T>::expandAdd(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const
{
  expandAdd(compactPath(mb), jac, res);
}

template<typename T>
void JacobianTpl<T>::expandAdd(const Blocks & compactPath, const Eigen::Ref<const MatrixX> & jac, MatrixX & res) const
{
  for(const Block & r : compactPath)
    for(const Block & c : compactPath)
      res.block(r.startDof, c.startDof, r.length, c.length) += jac.block(r.startJac, c.startJac, r.length, c.length);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::velocity(const MultiBodyTpl<T> &,
                                                             const MultiBodyConfigTpl<T> & mbc,
                                                             const PTransformT & X_b_p) const
{
  return X_b_p * mbc.bodyVelB[static_cast<std::size_t>(body_)];
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::velocity(const MultiBodyTpl<T> & mb,
                                                             const MultiBodyConfigTpl<T> & mbc) const
{
  // X_b_F = plx(E_0_b^T, point)
  return velocity(mb, mbc, PTransformT(sva::Matrix3<T>(mbc.bodyPosW[static_cast<std::size_t>(body_)].rotation().transpose()), point_));
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::bodyVelocity(const MultiBodyTpl<T> & mb,
                                                                 const MultiBodyConfigTpl<T> & mbc) const
{
  return velocity(mb, mbc, PTransformT(point_));
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcc(const MultiBodyConfigTpl<T> & mbc,
                                                              const PTransformT & X_0_F,
                                                              const MotionVecT & v_F) const
{
  MotionVecT acc = MotionVecT::Zero();
  for(int jn : rootPath_)
  {
    const auto j = static_cast<std::size_t>(jn);
    const PTransformT X_j_F = X_0_F * mbc.bodyPosW[j].inv();
    // (v_λ(j) - v_F) x v_J,j with v_λ(j) = v_j - v_J,j (body j coordinates)
    acc += (X_j_F * (mbc.bodyVelB[j] - mbc.jointVelocity[j]) - v_F).cross(X_j_F * mbc.jointVelocity[j]);
  }
  return acc;
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::bodyNormalAccB(const MultiBodyConfigTpl<T> & mbc) const
{
  // a_i = X_p_i a_λ(i) + v_i x v_J,i along the root path
  MotionVecT a = MotionVecT::Zero();
  for(int jn : rootPath_)
  {
    const auto j = static_cast<std::size_t>(jn);
    a = mbc.parentToSon[j] * a + mbc.bodyVelB[j].cross(mbc.jointVelocity[j]);
  }
  return a;
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcceleration(const MultiBodyTpl<T> & mb,
                                                                       const MultiBodyConfigTpl<T> & mbc) const
{
  const PTransformT X_0_F(Vector3(pointFrame(mbc).translation()));
  return normalAcc(mbc, X_0_F, MotionVecT(Vector3::Zero(), velocity(mb, mbc).linear()));
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcceleration(
    const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, const std::vector<MotionVecT> & normalAccB) const
{
  const auto b = static_cast<std::size_t>(body_);
  // X_b_F = plx(E_0_b^T, point) moving with [w; 0] relative to the body: pdd = a_lin + w x pd
  const MotionVecT w(Vector3(mbc.bodyPosW[b].rotation().transpose() * mbc.bodyVelB[b].angular()), Vector3::Zero());
  return normalAcceleration(mb, mbc, normalAccB, PTransformT(sva::Matrix3<T>(mbc.bodyPosW[b].rotation().transpose()), point_), w);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcceleration(const MultiBodyTpl<T> &,
                                                                       const MultiBodyConfigTpl<T> & mbc,
                                                                       const PTransformT & X_b_p,
                                                                       const MotionVecT & V_b_p) const
{
  return X_b_p * bodyNormalAccB(mbc) + V_b_p.cross(X_b_p * mbc.bodyVelB[static_cast<std::size_t>(body_)]);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::normalAcceleration(
    const MultiBodyTpl<T> &, const MultiBodyConfigTpl<T> & mbc, const std::vector<MotionVecT> & normalAccB,
    const PTransformT & X_b_p, const MotionVecT & V_b_p) const
{
  const auto b = static_cast<std::size_t>(body_);
  return X_b_p * normalAccB[b] + V_b_p.cross(X_b_p * mbc.bodyVelB[b]);
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

template<typename T>
MultiBodyTpl<T> JacobianTpl<T>::subMultiBody(const MultiBodyTpl<T> & mb) const
{
  std::vector<BodyTpl<T>> bodies;
  std::vector<JointTpl<T>> joints;
  std::vector<int> pred, parent;
  std::vector<PTransformT> Xt;
  for(std::size_t n = 0; n < jointsPath_.size(); ++n)
  {
    const int j = jointsPath_[n];
    const bool reversed = jointsSign_[n] < T(0);
    const bool afterReversed = n > 0 && jointsSign_[n - 1] < T(0);
    // the chain's frame before joint n: the world (n = 0), body j's parent frame, or the joint
    // frame of the previous (reversed) path joint on its predecessor's side
    const PTransformT fromPrevious = afterReversed ? mb.transform(jointsPath_[n - 1]).inv() : PTransformT::Identity();
    if(n == 0)
      Xt.push_back(reversed ? PTransformT::Identity() : mb.transform(j));
    else // X_prev_j = X_p_j X_prev_p (X1 * X2 applies X2 first)
      Xt.push_back(reversed ? fromPrevious : PTransformT(mb.transform(j) * fromPrevious));
    JointTpl<T> joint = mb.joint(j);
    if(reversed) joint.forward(!joint.forward());
    joints.push_back(joint);
    // a reversed joint moves its predecessor body, whose frame becomes the joint frame (X_p_j = Xt)
    const BodyTpl<T> & b = mb.body(reversed ? mb.parent(j) : j);
    bodies.emplace_back(reversed ? mb.transform(j).dualMul(b.inertia()) : b.inertia(), b.name());
    pred.push_back(static_cast<int>(n) - 1);
    parent.push_back(static_cast<int>(n) - 1);
  }
  std::vector<int> succ(jointsPath_.size());
  for(std::size_t n = 0; n < succ.size(); ++n) succ[n] = static_cast<int>(n);
  return MultiBodyTpl<T>(std::move(bodies), std::move(joints), std::move(pred), std::move(succ), std::move(parent),
                         std::move(Xt));
}

extern template void computeNormalAccB(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &,
                                       std::vector<sva::MotionVec<double>> &);
extern template void computeNormalAccB(const MultiBodyTpl<long double> &, const MultiBodyConfigTpl<long double> &,
                                       std::vector<sva::MotionVec<long double>> &);
extern template class JacobianTpl<double>;
extern template class JacobianTpl<long double>;

} // namespace rbd
