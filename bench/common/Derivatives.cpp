#include "Derivatives.h"

#include <Eigen/Eigenvalues>

#include <rbd/EulerIntegration.h>
#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>

namespace rbdbench
{
namespace
{
using L = long double;
using VecL = Eigen::Matrix<L, Eigen::Dynamic, 1>;
using MatL = Eigen::Matrix<L, Eigen::Dynamic, Eigen::Dynamic>;

struct Evaluator
{
  explicit Evaluator(const rbd::MultiBody & mbd) : mb(mbd.cast<L>()), mbc(mb), id(mb), fd(mb) {}

  void setState(const VecL & q, const VecL & alpha)
  {
    rbd::vectorToParam<L>(q, mbc.q);
    rbd::vectorToDof<L>(alpha, mbc.alpha);
    rbd::forwardKinematics(mb, mbc);
    rbd::forwardVelocity(mb, mbc);
  }
  VecL inverseDynamics(const VecL & q, const VecL & alpha, const VecL & alphaD)
  {
    setState(q, alpha);
    rbd::vectorToDof<L>(alphaD, mbc.alphaD);
    id.inverseDynamics(mb, mbc);
    return rbd::dofToVector(mb, mbc.jointTorque);
  }
  VecL forwardDynamics(const VecL & q, const VecL & alpha, const VecL & tau)
  {
    setState(q, alpha);
    rbd::vectorToDof<L>(tau, mbc.jointTorque);
    fd.forwardDynamics(mb, mbc);
    return rbd::dofToVector(mb, mbc.alphaD);
  }

  rbd::MultiBodyTpl<L> mb;
  rbd::MultiBodyConfigTpl<L> mbc;
  rbd::InverseDynamicsTpl<L> id;
  rbd::ForwardDynamicsTpl<L> fd;
};

/// Central differences of f in the tangent space of q (columns of an n x nv matrix).
template<class F>
MatL diffQ(const rbd::MultiBodyTpl<L> & mb, const VecL & q, F f)
{
  const int nv = mb.nrDof();
  MatL d;
  for(int k = 0; k < nv; ++k)
  {
    VecL delta = VecL::Zero(nv);
    delta(k) = kDerivativeStep;
    const VecL fp = f(rbd::integrateConfiguration(mb, q, delta));
    const VecL fm = f(rbd::integrateConfiguration(mb, q, VecL(-delta)));
    if(k == 0) d = MatL(fp.size(), nv);
    d.col(k) = (fp - fm) / (2 * kDerivativeStep);
  }
  return d;
}

/// Central differences of f with respect to a vector x.
template<class F>
MatL diffV(const VecL & x, F f)
{
  MatL d;
  for(int k = 0; k < x.size(); ++k)
  {
    VecL xp = x, xm = x;
    xp(k) += kDerivativeStep;
    xm(k) -= kDerivativeStep;
    const VecL fp = f(xp), fm = f(xm);
    if(k == 0) d = MatL(fp.size(), x.size());
    d.col(k) = (fp - fm) / (2 * kDerivativeStep);
  }
  return d;
}
} // namespace

DerivativesRef derivativesReference(const BenchCase & c, const State & s)
{
  Evaluator ev(c.model.mb);
  const VecL q = s.q.cast<L>(), alpha = s.alpha.cast<L>(), alphaD = s.alphaD.cast<L>(), tau = s.tau.cast<L>();
  DerivativesRef r;
  r.dtau_dq = diffQ(ev.mb, q, [&](const VecL & x) { return ev.inverseDynamics(x, alpha, alphaD); }).cast<double>();
  r.dtau_dalpha = diffV(alpha, [&](const VecL & x) { return ev.inverseDynamics(q, x, alphaD); }).cast<double>();
  r.dalphaD_dq = diffQ(ev.mb, q, [&](const VecL & x) { return ev.forwardDynamics(x, alpha, tau); }).cast<double>();
  r.dalphaD_dalpha = diffV(alpha, [&](const VecL & x) { return ev.forwardDynamics(q, x, tau); }).cast<double>();
  r.alphaD = ev.forwardDynamics(q, alpha, tau).cast<double>();
  const MatL H = ev.fd.H();
  r.Minv = H.llt().solve(MatL::Identity(H.rows(), H.cols())).cast<double>();
  const Eigen::VectorXd lambda =
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H.cast<double>(), Eigen::EigenvaluesOnly).eigenvalues();
  r.condH = lambda.maxCoeff() / lambda.minCoeff();
  return r;
}

} // namespace rbdbench
