// sva: Pluecker transform plx(E, r), Featherstone's spatial coordinate transform.
#pragma once

#include <ostream>
#include <type_traits>

#include "ABInertia.h"
#include "EigenUtility.h"
#include "ForceVec.h"
#include "MotionVec.h"
#include "RBInertia.h"
#include "fwd.h"

namespace sva
{

/// Pluecker transform X = plx(E, r) from frame A to frame B: E maps A coordinates into B
/// coordinates (the transpose of the usual rotation of B in A), r is B's origin in A coordinates.
/// Motion transform X = [E 0; -E r^ E], force transform X* = [E -E r^; 0 E].
/// X1 * X2 applies X2 first. The default constructor leaves the data uninitialised, like Eigen.
template<class T>
class PTransform
{
public:
  using scalar_type = T;
  using Scalar = T;
  using vector3_t = Vector3<T>;
  using matrix3_t = Matrix3<T>;
  using matrix6_t = Matrix6<T>;
  using quaternion_t = Quaternion<T>;

  /// Uninitialised (Eigen semantics).
  PTransform() = default;
  /// plx(E, r)
  PTransform(const matrix3_t & rot, const vector3_t & trans) : E_(rot), r_(trans) {}
  /// plx(E(q), r) with E(q) = q.toRotationMatrix() (q is used as is: no transposition).
  PTransform(const quaternion_t & rot, const vector3_t & trans) : E_(rot.toRotationMatrix()), r_(trans) {}
  /// plx(E, 0)
  PTransform(const matrix3_t & rot) : E_(rot), r_(vector3_t::Zero()) {}
  /// plx(E(q), 0)
  PTransform(const quaternion_t & rot) : E_(rot.toRotationMatrix()), r_(vector3_t::Zero()) {}
  /// xlt(r) = plx(1, r)
  PTransform(const vector3_t & trans) : E_(matrix3_t::Identity()), r_(trans) {}
  /// From an Eigen expression: a 3x3 one is a rotation E, a 3x1 one a translation r.
  /// (Without it `PTransform(expr)` would be ambiguous between the Matrix3 and Vector3 overloads.)
  template<class Derived,
           std::enable_if_t<Derived::RowsAtCompileTime == 3
                                && (Derived::ColsAtCompileTime == 1 || Derived::ColsAtCompileTime == 3),
                            int> = 0>
  explicit PTransform(const Eigen::MatrixBase<Derived> & m)
  {
    static_assert(std::is_same<typename Derived::Scalar, T>::value, "sva::PTransform: scalar type mismatch");
    if constexpr(Derived::ColsAtCompileTime == 1)
    {
      E_.setIdentity();
      r_ = detail::toPlain<vector3_t>(m);
    }
    else
    {
      E_ = detail::toPlain<matrix3_t>(m);
      r_.setZero();
    }
  }

  static PTransform Identity()
  {
    return PTransform(matrix3_t::Identity(), vector3_t::Zero());
  }

  const matrix3_t & rotation() const
  {
    return E_;
  }
  matrix3_t & rotation()
  {
    return E_;
  }
  const vector3_t & translation() const
  {
    return r_;
  }
  vector3_t & translation()
  {
    return r_;
  }

  /// X = [E 0; -E r^ E]
  matrix6_t matrix() const
  {
    matrix6_t X;
    X.template topLeftCorner<3, 3>() = E_;
    X.template topRightCorner<3, 3>().setZero();
    X.template bottomLeftCorner<3, 3>() = -E_ * vector3ToCrossMatrix(r_);
    X.template bottomRightCorner<3, 3>() = E_;
    return X;
  }

  /// X* = X^-T = [E -E r^; 0 E]
  matrix6_t dualMatrix() const
  {
    matrix6_t X;
    X.template topLeftCorner<3, 3>() = E_;
    X.template topRightCorner<3, 3>() = -E_ * vector3ToCrossMatrix(r_);
    X.template bottomLeftCorner<3, 3>().setZero();
    X.template bottomRightCorner<3, 3>() = E_;
    return X;
  }

  /// X1 X2 = plx(E1 E2, r2 + E2^T r1)
  PTransform operator*(const PTransform & pt) const
  {
    return PTransform(E_ * pt.E_, pt.r_ + pt.E_.transpose() * r_);
  }

  /// X^-1 = plx(E^T, -E r)
  PTransform inv() const
  {
    matrix3_t Et = E_;
    Et.transposeInPlace();
    return PTransform(Et, -(E_ * r_));
  }

  // --- motion and force vectors ----------------------------------------------------------------

  /// X v = [E w; E (v - r x w)]
  MotionVec<T> operator*(const MotionVec<T> & mv) const
  {
    return MotionVec<T>(angularMul(mv), linearMul(mv));
  }
  /// Angular part of X v: E w
  vector3_t angularMul(const MotionVec<T> & mv) const
  {
    return E_ * mv.angular();
  }
  /// Linear part of X v: E (v - r x w)
  vector3_t linearMul(const MotionVec<T> & mv) const
  {
    return E_ * (mv.linear() - r_.cross(mv.angular()));
  }

  /// X^-1 v = [E^T w; E^T v + r x E^T w]
  MotionVec<T> invMul(const MotionVec<T> & mv) const
  {
    const vector3_t Etw = angularInvMul(mv);
    return MotionVec<T>(Etw, E_.transpose() * mv.linear() + r_.cross(Etw));
  }
  /// Angular part of X^-1 v: E^T w
  vector3_t angularInvMul(const MotionVec<T> & mv) const
  {
    return E_.transpose() * mv.angular();
  }
  /// Linear part of X^-1 v: E^T v + r x E^T w
  vector3_t linearInvMul(const MotionVec<T> & mv) const
  {
    return E_.transpose() * mv.linear() + r_.cross(angularInvMul(mv));
  }

  /// X* f = [E (n - r x f); E f]
  ForceVec<T> dualMul(const ForceVec<T> & fv) const
  {
    return ForceVec<T>(coupleDualMul(fv), forceDualMul(fv));
  }
  /// Couple of X* f: E (n - r x f)
  vector3_t coupleDualMul(const ForceVec<T> & fv) const
  {
    return E_ * (fv.couple() - r_.cross(fv.force()));
  }
  /// Force of X* f: E f
  vector3_t forceDualMul(const ForceVec<T> & fv) const
  {
    return E_ * fv.force();
  }

  /// X^T f = [E^T n + r x E^T f; E^T f]   (= (X^-1)* f)
  ForceVec<T> transMul(const ForceVec<T> & fv) const
  {
    const vector3_t Etf = forceTransMul(fv);
    return ForceVec<T>(E_.transpose() * fv.couple() + r_.cross(Etf), Etf);
  }
  /// Couple of X^T f: E^T n + r x E^T f
  vector3_t coupleTransMul(const ForceVec<T> & fv) const
  {
    return E_.transpose() * fv.couple() + r_.cross(forceTransMul(fv));
  }
  /// Force of X^T f: E^T f
  vector3_t forceTransMul(const ForceVec<T> & fv) const
  {
    return E_.transpose() * fv.force();
  }

  // --- inertias ------------------------------------------------------------------------------

  /// X* rbi(m, h, I) X^-1 = rbi(m, E (h - m r), E (I + r^ h^ + (h - m r)^ r^) E^T)
  RBInertia<T> dualMul(const RBInertia<T> & rbi) const
  {
    const T m = rbi.mass();
    const vector3_t hmr = rbi.momentum() - m * r_;
    const matrix3_t rx = vector3ToCrossMatrix(r_);
    const matrix3_t I =
        rbi.inertia() + rx * vector3ToCrossMatrix(rbi.momentum()) + vector3ToCrossMatrix(hmr) * rx;
    return RBInertia<T>(m, E_ * hmr, E_ * I * E_.transpose());
  }

  /// X^T rbi(m, h, I) X = rbi(m, E^T h + m r, E^T I E - r^ (E^T h)^ - (E^T h + m r)^ r^)
  RBInertia<T> transMul(const RBInertia<T> & rbi) const
  {
    const T m = rbi.mass();
    const vector3_t Eth = E_.transpose() * rbi.momentum();
    const vector3_t h = Eth + m * r_;
    const matrix3_t rx = vector3ToCrossMatrix(r_);
    const matrix3_t I = E_.transpose() * rbi.inertia() * E_ - rx * vector3ToCrossMatrix(Eth)
                        - vector3ToCrossMatrix(h) * rx;
    return RBInertia<T>(m, h, I);
  }

  /// X* abi(M, H, I) X^-1 = abi(E M E^T, E (H - r^ M) E^T, E (I - r^ H^T + (H - r^ M) r^) E^T)
  ABInertia<T> dualMul(const ABInertia<T> & abi) const
  {
    const matrix3_t rx = vector3ToCrossMatrix(r_);
    const matrix3_t HmrM = abi.gInertia() - rx * abi.massMatrix();
    const matrix3_t I = abi.inertia() - rx * abi.gInertia().transpose() + HmrM * rx;
    return ABInertia<T>(E_ * abi.massMatrix() * E_.transpose(), E_ * HmrM * E_.transpose(),
                        E_ * I * E_.transpose());
  }

  /// X^T abi(M, H, I) X = abi(M', H', I') with M' = E^T M E, H' = E^T H E + r^ M',
  /// I' = E^T I E + r^ (E^T H E)^T - H' r^
  ABInertia<T> transMul(const ABInertia<T> & abi) const
  {
    const matrix3_t rx = vector3ToCrossMatrix(r_);
    const matrix3_t M = E_.transpose() * abi.massMatrix() * E_;
    const matrix3_t EtHE = E_.transpose() * abi.gInertia() * E_;
    const matrix3_t H = EtHE + rx * M;
    const matrix3_t I = E_.transpose() * abi.inertia() * E_ + rx * EtHE.transpose() - H * rx;
    return ABInertia<T>(M, H, I);
  }

  // --- 6xN matrices (columns are motion vectors for mul/invMul, force vectors for dualMul/
  // transMul), e.g. motion subspaces and Jacobians. Computed with 3x3 blocks only. ------------

  /// X M (each column transformed as a motion vector)
  template<class Derived>
  Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> mul(const Eigen::MatrixBase<Derived> & M) const
  {
    checkSixRows(M);
    Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> res;
    res.resize(6, M.cols());
    if(M.cols() == 0) return res; // Eigen offsets a null pointer for blocks of an empty matrix (UBSan)
    const Eigen::Matrix<T, 3, Derived::ColsAtCompileTime> top = M.template topRows<3>();
    const Eigen::Matrix<T, 3, Derived::ColsAtCompileTime> lin =
        M.template bottomRows<3>() - vector3ToCrossMatrix(r_) * top;
    res.template topRows<3>().noalias() = E_ * top;
    res.template bottomRows<3>().noalias() = E_ * lin;
    return res;
  }

  /// Same as mul(M): X M.
  template<class Derived>
  Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> operator*(const Eigen::MatrixBase<Derived> & M) const
  {
    return mul(M);
  }

  /// X^-1 M
  template<class Derived>
  Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> invMul(const Eigen::MatrixBase<Derived> & M) const
  {
    checkSixRows(M);
    Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> res;
    res.resize(6, M.cols());
    if(M.cols() == 0) return res; // Eigen offsets a null pointer for blocks of an empty matrix (UBSan)
    res.template topRows<3>().noalias() = E_.transpose() * M.template topRows<3>();
    res.template bottomRows<3>().noalias() = E_.transpose() * M.template bottomRows<3>();
    res.template bottomRows<3>().noalias() += vector3ToCrossMatrix(r_) * res.template topRows<3>();
    return res;
  }

  /// X* M
  template<class Derived>
  Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> dualMul(const Eigen::MatrixBase<Derived> & M) const
  {
    checkSixRows(M);
    Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> res;
    res.resize(6, M.cols());
    if(M.cols() == 0) return res; // Eigen offsets a null pointer for blocks of an empty matrix (UBSan)
    const Eigen::Matrix<T, 3, Derived::ColsAtCompileTime> bottom = M.template bottomRows<3>();
    const Eigen::Matrix<T, 3, Derived::ColsAtCompileTime> ang =
        M.template topRows<3>() - vector3ToCrossMatrix(r_) * bottom;
    res.template topRows<3>().noalias() = E_ * ang;
    res.template bottomRows<3>().noalias() = E_ * bottom;
    return res;
  }

  /// X^T M
  template<class Derived>
  Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> transMul(const Eigen::MatrixBase<Derived> & M) const
  {
    checkSixRows(M);
    Eigen::Matrix<T, 6, Derived::ColsAtCompileTime> res;
    res.resize(6, M.cols());
    if(M.cols() == 0) return res; // Eigen offsets a null pointer for blocks of an empty matrix (UBSan)
    res.template bottomRows<3>().noalias() = E_.transpose() * M.template bottomRows<3>();
    res.template topRows<3>().noalias() = E_.transpose() * M.template topRows<3>();
    res.template topRows<3>().noalias() += vector3ToCrossMatrix(r_) * res.template bottomRows<3>();
    return res;
  }

  /// SpaceVecAlg's output-argument forms of the four products above (result: 6xN, may alias M).
  template<class Derived, class Result>
  void mul(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    const_cast<Eigen::MatrixBase<Result> &>(result) = mul(M);
  }
  template<class Derived, class Result>
  void invMul(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    const_cast<Eigen::MatrixBase<Result> &>(result) = invMul(M);
  }
  template<class Derived, class Result>
  void dualMul(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    const_cast<Eigen::MatrixBase<Result> &>(result) = dualMul(M);
  }
  template<class Derived, class Result>
  void transMul(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    const_cast<Eigen::MatrixBase<Result> &>(result) = transMul(M);
  }

  // --- misc ----------------------------------------------------------------------------------

  template<class U>
  PTransform<U> cast() const
  {
    return PTransform<U>(E_.template cast<U>(), r_.template cast<U>());
  }

  bool operator==(const PTransform & pt) const
  {
    return E_ == pt.E_ && r_ == pt.r_;
  }
  bool operator!=(const PTransform & pt) const
  {
    return !(*this == pt);
  }

  /// Eigen's relative comparison of E and of r, separately (so a zero translation is only
  /// approx. an exactly zero one).
  bool isApprox(const PTransform & pt, T prec = Eigen::NumTraits<T>::dummy_precision()) const
  {
    return E_.isApprox(pt.E_, prec) && r_.isApprox(pt.r_, prec);
  }

private:
  template<class Derived>
  static void checkSixRows(const Eigen::MatrixBase<Derived> & M)
  {
    detail::checkSixRows<T>(M);
  }

  matrix3_t E_;
  vector3_t r_;
};

template<class T>
inline std::ostream & operator<<(std::ostream & out, const PTransform<T> & pt)
{
  out << pt.matrix();
  return out;
}

/// Interpolation from `from` (tau = 0) to `to` (tau = 1): slerp of the rotations (shortest
/// path), linear interpolation of the translations.
template<class T>
inline PTransform<T> interpolate(const PTransform<T> & from, const PTransform<T> & to, detail::identity_t<T> tau)
{
  const Quaternion<T> qFrom(from.rotation());
  const Quaternion<T> qTo(to.rotation());
  return PTransform<T>(qFrom.slerp(tau, qTo), (T(1) - tau) * from.translation() + tau * to.translation());
}

/// Velocity that moves frame a to frame b in unit time (Featherstone XtoV-like, SpaceVecAlg
/// convention): [rotationVelocity(E_a_b); r_a_b].
template<class T>
inline MotionVec<T> transformVelocity(const PTransform<T> & X_a_b)
{
  return MotionVec<T>(rotationVelocity(X_a_b.rotation()), X_a_b.translation());
}

/// Error from X_a_b to X_a_c in frame a coordinates:
/// [rotationError(E_a_b, E_a_c); r_a_c - r_a_b].
template<class T>
inline MotionVec<T> transformError(const PTransform<T> & X_a_b, const PTransform<T> & X_a_c)
{
  return MotionVec<T>(rotationError(X_a_b.rotation(), X_a_c.rotation()), X_a_c.translation() - X_a_b.translation());
}

} // namespace sva
