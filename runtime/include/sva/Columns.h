// sva: 6xN matrices whose columns are spatial vectors (motion subspaces, Jacobians): views of
// their 3-row halves and the column-wise cross product the vectorised operations are built on.
#pragma once

#include <type_traits>

#include "EigenTypedef.h"

namespace sva
{

// The 3-row halves of a 6xN matrix (writable when the matrix is): angular and linear parts of
// motion vectors, couple and force of force vectors.
template<class M>
inline auto motionAngular(M && m)
{
  return m.template topRows<3>();
}
template<class M>
inline auto motionLinear(M && m)
{
  return m.template bottomRows<3>();
}
template<class M>
inline auto forceCouple(M && m)
{
  return motionAngular(m);
}
template<class M>
inline auto forceForce(M && m)
{
  return motionLinear(m);
}

namespace detail
{

/// A 6xN matrix of scalar T (checked at compile time where the size is known, else at run time).
template<class T, class Derived>
inline void checkSixRows(const Eigen::MatrixBase<Derived> & M)
{
  static_assert(std::is_same<typename Derived::Scalar, T>::value, "sva: scalar type mismatch");
  static_assert(Derived::RowsAtCompileTime == 6 || Derived::RowsAtCompileTime == Eigen::Dynamic,
                "sva: spatial matrices must have 6 rows");
  eigen_assert(M.rows() == 6);
  (void)M;
}

/// Plain 6xN (or 3xN) matrix type with the column count of Derived.
template<class T, int Rows, class Derived>
using ColumnsOf = Eigen::Matrix<T, Rows, Derived::ColsAtCompileTime>;

/// v x M, column by column (M: 3xN, at least one column): the rows of v^ applied to M.
template<class T, class Derived>
inline ColumnsOf<T, 3, Derived> crossColumns(const Vector3<T> & v, const Eigen::MatrixBase<Derived> & M)
{
  ColumnsOf<T, 3, Derived> R(3, M.cols());
  R.row(0) = v.y() * M.row(2) - v.z() * M.row(1);
  R.row(1) = v.z() * M.row(0) - v.x() * M.row(2);
  R.row(2) = v.x() * M.row(1) - v.y() * M.row(0);
  return R;
}

/// A vectorised operation on the 6xN matrix M: fill(R) computes the 6xN result R (not called for
/// N = 0: Eigen offsets a null pointer for blocks of an empty matrix), then R is written into
/// `result` (evaluated first, so result may alias M; a const reference, as Eigen's idiom for output
/// arguments that may be blocks).
template<class T, class Derived, class Result, class Fill>
inline void columnwise(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result, Fill fill)
{
  checkSixRows<T>(M);
  ColumnsOf<T, 6, Derived> R(6, M.cols());
  if(M.cols() > 0) fill(R);
  const_cast<Eigen::MatrixBase<Result> &>(result) = R;
}

} // namespace detail

} // namespace sva
