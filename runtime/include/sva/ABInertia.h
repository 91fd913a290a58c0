// sva: articulated-body spatial inertia, Featherstone abi(M, H, I).
#pragma once

#include <ostream>

#include "EigenUtility.h"
#include "ForceVec.h"
#include "MotionVec.h"
#include "RBInertia.h"
#include "fwd.h"

namespace sva
{

/// Articulated-body inertia abi(M, H, I) = [I H; H^T M] with M (mass matrix) and I (rotational
/// inertia) symmetric (only their lower triangles are read) and H the generalised inertia.
/// Default construction gives the zero inertia.
template<class T>
class ABInertia
{
public:
  using scalar_type = T;
  using Scalar = T;
  using vector3_t = Vector3<T>;
  using matrix3_t = Matrix3<T>;
  using matrix6_t = Matrix6<T>;

  /// Zero inertia.
  ABInertia() : M_(matrix3_t::Zero()), H_(matrix3_t::Zero()), I_(matrix3_t::Zero()) {}
  /// abi(M, H, I) = [I H; H^T M]; lower triangles of M and I read.
  ABInertia(const matrix3_t & massMat, const matrix3_t & genInertia, const matrix3_t & inertiaMat)
  : M_(massMat.template selfadjointView<Eigen::Lower>()), H_(genInertia),
    I_(inertiaMat.template selfadjointView<Eigen::Lower>())
  {
  }
  /// rbi(m, h, I) as abi(m1, h^, I).
  explicit ABInertia(const RBInertia<T> & rbi)
  : M_(matrix3_t::Identity() * rbi.mass()), H_(vector3ToCrossMatrix(rbi.momentum())), I_(rbi.inertia())
  {
  }

  static ABInertia Zero()
  {
    return ABInertia();
  }

  /// M (full symmetric)
  const matrix3_t & massMatrix() const
  {
    return M_;
  }
  matrix3_t lowerTriangularMassMatrix() const
  {
    return M_.template triangularView<Eigen::Lower>();
  }
  /// H
  const matrix3_t & gInertia() const
  {
    return H_;
  }
  /// I (full symmetric)
  const matrix3_t & inertia() const
  {
    return I_;
  }
  matrix3_t lowerTriangularInertia() const
  {
    return I_.template triangularView<Eigen::Lower>();
  }

  /// [I H; H^T M]
  matrix6_t matrix() const
  {
    matrix3_t Ht = H_;
    Ht.transposeInPlace();
    matrix6_t A;
    A.template topLeftCorner<3, 3>() = I_;
    A.template topRightCorner<3, 3>() = H_;
    A.template bottomLeftCorner<3, 3>() = Ht;
    A.template bottomRightCorner<3, 3>() = M_;
    return A;
  }

  /// I^A v = [I w + H v; H^T w + M v]
  ForceVec<T> operator*(const MotionVec<T> & mv) const
  {
    return ForceVec<T>(I_ * mv.angular() + H_ * mv.linear(), H_.transpose() * mv.angular() + M_ * mv.linear());
  }

  /// I^A M for a 6xN matrix M of motion vectors (columns): [I Mw + H Mv; H^T Mw + M Mv]
  template<class Derived, class Result>
  void mul(const Eigen::MatrixBase<Derived> & Mv, const Eigen::MatrixBase<Result> & result) const
  {
    detail::columnwise<T>(Mv, result, [&](auto & R) {
      R.template topRows<3>() = I_ * motionAngular(Mv) + H_ * motionLinear(Mv);
      R.template bottomRows<3>() = H_.transpose() * motionAngular(Mv) + M_ * motionLinear(Mv);
    });
  }

  /// I1^A + I2^A = abi(M1 + M2, H1 + H2, I1 + I2)
  ABInertia operator+(const ABInertia & abi) const
  {
    return ABInertia(M_ + abi.M_, H_ + abi.H_, I_ + abi.I_);
  }
  /// I^A + rbi(m, h, I) = abi(M + m1, H + h^, I_A + I)
  ABInertia operator+(const RBInertia<T> & rbi) const
  {
    matrix3_t M = M_;
    M.diagonal().array() += rbi.mass();
    return ABInertia(M, H_ + vector3ToCrossMatrix(rbi.momentum()), I_ + rbi.inertia());
  }
  /// I1^A - I2^A
  ABInertia operator-(const ABInertia & abi) const
  {
    return ABInertia(M_ - abi.M_, H_ - abi.H_, I_ - abi.I_);
  }
  /// I^A - rbi(m, h, I) = abi(M - m1, H - h^, I_A - I)
  ABInertia operator-(const RBInertia<T> & rbi) const
  {
    matrix3_t M = M_;
    M.diagonal().array() -= rbi.mass();
    return ABInertia(M, H_ - vector3ToCrossMatrix(rbi.momentum()), I_ - rbi.inertia());
  }
  /// -I^A
  ABInertia operator-() const
  {
    return ABInertia(-M_, -H_, -I_);
  }
  ABInertia & operator+=(const ABInertia & abi)
  {
    M_ += abi.M_;
    H_ += abi.H_;
    I_ += abi.I_;
    return *this;
  }
  ABInertia & operator+=(const RBInertia<T> & rbi)
  {
    M_.diagonal().array() += rbi.mass();
    H_ += vector3ToCrossMatrix(rbi.momentum());
    I_ += rbi.inertia();
    return *this;
  }
  ABInertia & operator-=(const ABInertia & abi)
  {
    M_ -= abi.M_;
    H_ -= abi.H_;
    I_ -= abi.I_;
    return *this;
  }
  ABInertia & operator-=(const RBInertia<T> & rbi)
  {
    M_.diagonal().array() -= rbi.mass();
    H_ -= vector3ToCrossMatrix(rbi.momentum());
    I_ -= rbi.inertia();
    return *this;
  }
  /// I^A a
  ABInertia operator*(T scalar) const
  {
    return ABInertia(M_ * scalar, H_ * scalar, I_ * scalar);
  }

  template<class U>
  ABInertia<U> cast() const
  {
    return ABInertia<U>(M_.template cast<U>(), H_.template cast<U>(), I_.template cast<U>());
  }

  bool operator==(const ABInertia & abi) const
  {
    return M_ == abi.M_ && H_ == abi.H_ && I_ == abi.I_;
  }
  bool operator!=(const ABInertia & abi) const
  {
    return !(*this == abi);
  }

  /// Eigen's relative comparison, component by component (M, H, I).
  bool isApprox(const ABInertia & abi, T prec = Eigen::NumTraits<T>::dummy_precision()) const
  {
    return M_.isApprox(abi.M_, prec) && H_.isApprox(abi.H_, prec) && I_.isApprox(abi.I_, prec);
  }

private:
  matrix3_t M_;
  matrix3_t H_;
  matrix3_t I_;
};

/// rbi + I^A = I^A + rbi
template<class T>
inline ABInertia<T> operator+(const RBInertia<T> & rbi, const ABInertia<T> & abi)
{
  return abi + rbi;
}

/// rbi - I^A
template<class T>
inline ABInertia<T> operator-(const RBInertia<T> & rbi, const ABInertia<T> & abi)
{
  return ABInertia<T>(rbi) - abi;
}

/// a I^A
template<class T>
inline ABInertia<T> operator*(detail::identity_t<T> scalar, const ABInertia<T> & abi)
{
  return abi * scalar;
}

/// rbi(m, h, I) -> abi(m1, h^, I)
template<class T>
inline ABInertia<T> toABInertia(const RBInertia<T> & rbi)
{
  return ABInertia<T>(rbi);
}

template<class T>
inline std::ostream & operator<<(std::ostream & out, const ABInertia<T> & abi)
{
  out << abi.matrix();
  return out;
}

} // namespace sva
