// Helpers for the sva tests: seeded random values and the explicit 6x6 matrices of Featherstone's
// appendix A, built by hand (independent from the sva implementation).
#pragma once

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace svatest
{

template<class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template<class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template<class T>
using Vec6 = Eigen::Matrix<T, 6, 1>;
template<class T>
using Mat6 = Eigen::Matrix<T, 6, 6>;

/// The scalar types every typed test runs with.
using Scalars = ::testing::Types<double, long double>;

/// Comparison tolerance: 1e4 machine epsilons, relative to the magnitude of the expected value.
template<class T>
T tol()
{
  return T(1e4) * std::numeric_limits<T>::epsilon();
}

template<class A, class B>
::testing::AssertionResult near(const Eigen::MatrixBase<A> & actual,
                                const Eigen::MatrixBase<B> & expected,
                                typename A::Scalar tolerance)
{
  using T = typename A::Scalar;
  if(actual.rows() != expected.rows() || actual.cols() != expected.cols())
  {
    return ::testing::AssertionFailure() << "size mismatch";
  }
  const T err = (actual - expected).norm();
  const T bound = tolerance * (T(1) + expected.norm());
  if(err <= bound)
  {
    return ::testing::AssertionSuccess();
  }
  std::ostringstream os;
  os.precision(20);
  os << "error " << static_cast<long double>(err) << " > " << static_cast<long double>(bound) << "\nactual:\n"
     << actual << "\nexpected:\n"
     << expected;
  return ::testing::AssertionFailure() << os.str();
}

template<class A, class B>
::testing::AssertionResult near(const Eigen::MatrixBase<A> & actual, const Eigen::MatrixBase<B> & expected)
{
  return near(actual, expected, tol<typename A::Scalar>());
}

template<class T>
::testing::AssertionResult nearScalar(T actual, T expected, T tolerance = tol<T>())
{
  using std::abs;
  if(abs(actual - expected) <= tolerance * (T(1) + abs(expected)))
  {
    return ::testing::AssertionSuccess();
  }
  std::ostringstream os;
  os.precision(20);
  os << static_cast<long double>(actual) << " vs " << static_cast<long double>(expected);
  return ::testing::AssertionFailure() << os.str();
}

/// Seeded random generator for one scalar type.
template<class T>
class Rand
{
public:
  explicit Rand(unsigned seed = 42) : gen_(seed) {}

  T uniform(T lo = T(-1), T hi = T(1))
  {
    std::uniform_real_distribution<long double> d(static_cast<long double>(lo), static_cast<long double>(hi));
    return static_cast<T>(d(gen_));
  }
  Vec3<T> vec3(T scale = T(1))
  {
    return Vec3<T>(uniform(), uniform(), uniform()) * scale;
  }
  Vec6<T> vec6(T scale = T(1))
  {
    Vec6<T> v;
    for(int i = 0; i < 6; ++i)
    {
      v(i) = uniform() * scale;
    }
    return v;
  }
  Mat3<T> mat3()
  {
    Mat3<T> m;
    for(int i = 0; i < 3; ++i)
    {
      for(int j = 0; j < 3; ++j)
      {
        m(i, j) = uniform();
      }
    }
    return m;
  }
  Eigen::Matrix<T, 6, Eigen::Dynamic> mat6N(int n)
  {
    Eigen::Matrix<T, 6, Eigen::Dynamic> m(6, n);
    for(int j = 0; j < n; ++j)
    {
      m.col(j) = vec6();
    }
    return m;
  }
  Vec3<T> unit3()
  {
    Vec3<T> v;
    do
    {
      v = vec3();
    } while(v.norm() < T(0.1));
    return v.normalized();
  }
  /// Random unit quaternion (uniform enough for testing).
  Eigen::Quaternion<T> quat()
  {
    Eigen::Matrix<T, 4, 1> c;
    do
    {
      c = Eigen::Matrix<T, 4, 1>(uniform(), uniform(), uniform(), uniform());
    } while(c.norm() < T(0.1));
    c.normalize();
    return Eigen::Quaternion<T>(c(0), c(1), c(2), c(3));
  }
  Mat3<T> rotation()
  {
    return quat().toRotationMatrix();
  }
  /// Random symmetric positive definite 3x3 matrix.
  Mat3<T> spd3()
  {
    const Mat3<T> a = mat3();
    const Mat3<T> s = a * a.transpose() + Mat3<T>::Identity() * T(0.1);
    return (s + s.transpose()) / T(2); // exactly symmetric
  }
  /// Random symmetric 6x6 positive definite matrix (an articulated-body inertia).
  Mat6<T> spd6()
  {
    Mat6<T> a;
    for(int j = 0; j < 6; ++j)
    {
      a.col(j) = vec6();
    }
    const Mat6<T> s = a * a.transpose() + Mat6<T>::Identity() * T(0.1);
    return (s + s.transpose()) / T(2); // exactly symmetric
  }

private:
  std::mt19937 gen_;
};

// --- Featherstone appendix A, by hand --------------------------------------------------------

/// v^ such that v^ u = v x u.
template<class T>
Mat3<T> skew(const Vec3<T> & v)
{
  Mat3<T> m = Mat3<T>::Zero();
  m(0, 1) = -v(2);
  m(0, 2) = v(1);
  m(1, 0) = v(2);
  m(1, 2) = -v(0);
  m(2, 0) = -v(1);
  m(2, 1) = v(0);
  return m;
}

template<class T>
Mat6<T> blocks(const Mat3<T> & a, const Mat3<T> & b, const Mat3<T> & c, const Mat3<T> & d)
{
  Mat6<T> m;
  m.template block<3, 3>(0, 0) = a;
  m.template block<3, 3>(0, 3) = b;
  m.template block<3, 3>(3, 0) = c;
  m.template block<3, 3>(3, 3) = d;
  return m;
}

/// crm(v) = [w^ 0; v^ w^]
template<class T>
Mat6<T> crm(const Vec6<T> & v)
{
  const Vec3<T> w = v.template head<3>(), lin = v.template tail<3>();
  return blocks<T>(skew(w), Mat3<T>::Zero(), skew(lin), skew(w));
}

/// crf(v) = [w^ v^; 0 w^]
template<class T>
Mat6<T> crf(const Vec6<T> & v)
{
  const Vec3<T> w = v.template head<3>(), lin = v.template tail<3>();
  return blocks<T>(skew(w), skew(lin), Mat3<T>::Zero(), skew(w));
}

/// Motion transform plx(E, r) = rot(E) xlt(r) = [E 0; 0 E] [1 0; -r^ 1]
template<class T>
Mat6<T> plxMotion(const Mat3<T> & E, const Vec3<T> & r)
{
  const Mat3<T> Z = Mat3<T>::Zero(), I = Mat3<T>::Identity();
  const Mat6<T> rot = blocks<T>(E, Z, Z, E);
  const Mat6<T> xlt = blocks<T>(I, Z, -skew(r), I);
  return rot * xlt;
}

/// Force transform X* = rot(E) xlt*(r) = [E 0; 0 E] [1 -r^; 0 1]
template<class T>
Mat6<T> plxForce(const Mat3<T> & E, const Vec3<T> & r)
{
  const Mat3<T> Z = Mat3<T>::Zero(), I = Mat3<T>::Identity();
  const Mat6<T> rot = blocks<T>(E, Z, Z, E);
  const Mat6<T> xlt = blocks<T>(I, -skew(r), Z, I);
  return rot * xlt;
}

/// rbi(m, h, I) = [I h^; h^T m1]
template<class T>
Mat6<T> rbiMatrix(T m, const Vec3<T> & h, const Mat3<T> & I)
{
  return blocks<T>(I, skew(h), skew(h).transpose(), Mat3<T>::Identity() * m);
}

/// mcI(m, c, Ic) = [Ic + m c^ c^T, m c^; m c^T, m1]
template<class T>
Mat6<T> mcI(T m, const Vec3<T> & c, const Mat3<T> & Ic)
{
  const Mat3<T> cx = skew(c);
  return blocks<T>(Ic + m * cx * cx.transpose(), m * cx, m * cx.transpose(), Mat3<T>::Identity() * m);
}

/// abi(M, H, I) = [I H; H^T M]
template<class T>
Mat6<T> abiMatrix(const Mat3<T> & M, const Mat3<T> & H, const Mat3<T> & I)
{
  return blocks<T>(I, H, H.transpose(), M);
}

/// The usual right-handed rotation about unit axis a by angle t (Rodrigues, by hand).
template<class T>
Mat3<T> rodrigues(const Vec3<T> & a, T t)
{
  using std::cos;
  using std::sin;
  const Mat3<T> ax = skew(a);
  return Mat3<T>::Identity() + sin(t) * ax + (T(1) - cos(t)) * ax * ax;
}

} // namespace svatest
