#pragma once
// Hard-case helpers: models built to stress the numerics (long chains, wide trees, mass ratios,
// massless links, far offsets) and the comparison of every runtime output in double against the
// same computation in long double (the reference: 64-bit mantissa, u = 5.4e-20, so its own error
// is ~2000x below the double errors measured here).

#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/SVD>

#include <rbd/Jacobian.h>

#include "DynTestUtils.h"

namespace stab
{

using LD = long double;
constexpr double eps = 2.220446049250313e-16; ///< double machine epsilon (2u)

template<typename T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template<typename T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// Inertia of body k (0 = first body after the base) of a built model.
using InertiaFn = std::function<sva::RBInertiad(rbdtest::Rng &, int k)>;
/// Joint of body k (k >= 1).
using JointFn = std::function<rbd::Joint(rbdtest::Rng &, int k)>;

inline sva::RBInertiad zeroInertia()
{
  return sva::RBInertiad(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
}

/// Revolute joint about a random unit axis (half of them about a coordinate axis).
inline rbd::Joint randomRev(rbdtest::Rng & rng, int k)
{
  Eigen::Vector3d a = rbdtest::randomUnit(rng);
  if(rbdtest::uniform(rng, 0, 1) < 0.5) a = Eigen::Vector3d::Unit(k % 3);
  return rbd::Joint(rbd::Joint::Rev, a, true, "j" + std::to_string(k));
}

/// A joint of any type, random axis.
inline rbd::Joint randomAnyJoint(rbdtest::Rng & rng, int k)
{
  const rbdtest::RandomTreeOptions opt;
  const auto t = opt.types[std::uniform_int_distribution<std::size_t>(0, opt.types.size() - 1)(rng)];
  return rbd::Joint(t, rbdtest::randomUnit(rng), true, "j" + std::to_string(k));
}

/// A graph b0 - b1 - ... - b{n-1}: body k gets inertia(k), joint k links b{k-1} to b{k} with a
/// random static transform whose translation is at most maxOffset in each coordinate.
rbd::MultiBodyGraph chainGraph(rbdtest::Rng & rng, int n, const InertiaFn & inertia, const JointFn & joint,
                                double maxOffset = 0.5);

/// A star: b0 with `branches` chains of `depth` revolute links each.
rbd::MultiBodyGraph wideTreeGraph(rbdtest::Rng & rng, int branches, int depth);

/// Every runtime output the hard cases look at, for one state.
template<typename T>
struct Outputs
{
  VecX<T> poses;   ///< bodyPosW of every body: 9 rotation + 3 translation values
  VecX<T> tau;     ///< inverse dynamics (alphaD given, gravity, no external force)
  MatX<T> H;       ///< mass matrix (CRBA)
  VecX<T> C;       ///< nonlinear effects
  MatX<T> J;       ///< world Jacobian of the last body at its origin
  VecX<T> fdCrba;  ///< H^-1 (jointTorque - C) by Cholesky (ForwardDynamics)
  VecX<T> fdAba;   ///< the same by the articulated-body algorithm
  bool hasFd = false;
  bool abaThrew = false; ///< ABA found a D that is not positive definite (fdAba = fdCrba then)
};

/// Evaluate everything at the state in mbc (q, alpha, alphaD, jointTorque); FD only when withFd.
template<typename T>
Outputs<T> evaluate(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> mbc, bool withFd = true);
extern template Outputs<double> evaluate(const rbd::MultiBody &, rbd::MultiBodyConfig, bool);
extern template Outputs<LD> evaluate(const rbd::MultiBodyTpl<LD> &, rbd::MultiBodyConfigTpl<LD>, bool);

template<typename T>
bool allFinite(const Outputs<T> & o)
{
  return o.poses.allFinite() && o.tau.allFinite() && o.H.allFinite() && o.C.allFinite() && o.J.allFinite() &&
         (!o.hasFd || (o.fdCrba.allFinite() && o.fdAba.allFinite()));
}

/// Errors of the double outputs against long double: rbdtest::relErr, i.e.
/// max |double - long double| / max(1, max |long double|) per output; FD normwise relative.
struct Errors
{
  double poses = 0, tau = 0, H = 0, C = 0, J = 0, fdCrba = 0, fdAba = 0, abaVsCrba = 0;
  double condH = 0; ///< 2-norm condition number of H (long double SVD)
  double worstRatio = 0; ///< max over merged states of fdOverCondEps()
  bool finite = true;
  bool abaThrew = false; ///< ABA refused a D that is not positive definite (double or long double)
  double kinematicsAndDynamics() const { return std::max({poses, tau, H, C, J}); }
  double fdOverCondEps() const { return std::max({fdCrba, fdAba, abaVsCrba}) / (std::max(1.0, condH) * eps); }
  Errors & max(const Errors & o)
  {
    poses = std::max(poses, o.poses);
    tau = std::max(tau, o.tau);
    H = std::max(H, o.H);
    C = std::max(C, o.C);
    J = std::max(J, o.J);
    fdCrba = std::max(fdCrba, o.fdCrba);
    fdAba = std::max(fdAba, o.fdAba);
    abaVsCrba = std::max(abaVsCrba, o.abaVsCrba);
    condH = std::max(condH, o.condH);
    finite = finite && o.finite;
    abaThrew = abaThrew || o.abaThrew;
    worstRatio = std::max({worstRatio, o.worstRatio, o.fdOverCondEps()});
    return *this;
  }
};

std::ostream & operator<<(std::ostream & os, const Errors & e);

/// ||a - b|| / ||b|| (2-norms).
template<typename A, typename B>
double normRel(const Eigen::MatrixBase<A> & a, const Eigen::MatrixBase<B> & b)
{
  const long double nb = b.template cast<long double>().norm();
  if(nb == 0) return static_cast<double>((a.template cast<long double>()).norm());
  return static_cast<double>((a.template cast<long double>() - b.template cast<long double>()).norm() / nb);
}

/// 2-norm condition number of a symmetric matrix, in long double.
double conditionNumber(const MatX<LD> & H);

/// Errors of double outputs against long double ones.
Errors errorsOf(const Outputs<double> & d, const Outputs<LD> & l);

/// The state in mbc evaluated in double, against the same model and inputs in long double.
Errors compare(const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc, bool withFd = true);

/// Random state with the given ranges (quaternions unit), then the errors of compare().
Errors compareRandom(rbdtest::Rng & rng, const rbd::MultiBody & mb, bool withFd = true, double qRange = 3.0,
                     double vRange = 2.0);

/// The bounds of a hard case: every kinematic/dynamic output within kinBound (relErr), forward
/// dynamics (both routes, and ABA against CRBA) within fdFactor * cond(H) * eps (normwise): the
/// forward error of a backward-stable solve of H x = b is <= c(n) cond(H) eps, with c(n) a modest
/// polynomial in n; fdFactor is that constant for the case.
struct Bounds
{
  double kin;
  double fdFactor;
  bool abaMayThrow = false; ///< only where cond(H) eps is not small (H numerically singular)
};

::testing::AssertionResult withinBounds(const Errors & e, const Bounds & b);

/// Print the worst errors of a case (the numbers quoted in the test comments).
void report(const char * what, const Errors & e);

} // namespace stab
