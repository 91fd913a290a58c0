#include "Derivatives.h"

#include <Eigen/Eigenvalues>

#include <rbd/EulerIntegration.h>
#include <rbd/FD.h>
#include <rbd/FDDerivatives.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>

namespace rbdbench
{
namespace
{
using L = long double;
using VecL = Eigen::Matrix<L, Eigen::Dynamic, 1>;
using MatL = Eigen::Matrix<L, Eigen::Dynamic, Eigen::Dynamic>;

/// The runtime in long double at one state.
struct Evaluator
{
  explicit Evaluator(const rbd::MultiBody & mbd) : mb(mbd.cast<L>()), mbc(mb), id(mb), fd(mb), idd(mb), fdd(mb) {}

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
  rbd::InverseDynamicsDerivativesTpl<L> idd;
  rbd::ForwardDynamicsDerivativesTpl<L> fdd;
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

/// H^-1 and cond(H) (2-norm) at q, in long double; alphaD = FD(q, alpha, tau).
void solveParts(Evaluator & ev, const VecL & q, const VecL & alpha, const VecL & tau, DerivativesRef & r)
{
  r.alphaD = ev.forwardDynamics(q, alpha, tau).cast<double>();
  const MatL H = ev.fd.H();
  r.Minv = H.llt().solve(MatL::Identity(H.rows(), H.cols())).cast<double>();
  const Eigen::VectorXd lambda =
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H.cast<double>(), Eigen::EigenvaluesOnly).eigenvalues();
  r.condH = lambda.maxCoeff() / lambda.minCoeff();
}
} // namespace

const char * const kDerivativesReference = "runtime_ld";

DerivativesRef derivativesReference(const BenchCase & c, const State & s)
{
  Evaluator ev(c.model.mb);
  const VecL q = s.q.cast<L>(), alpha = s.alpha.cast<L>(), alphaD = s.alphaD.cast<L>(), tau = s.tau.cast<L>();
  DerivativesRef r;
  solveParts(ev, q, alpha, tau, r); // leaves mbc at (q, alpha) after FK and FV, jointTorque = tau
  rbd::vectorToDof<L>(alphaD, ev.mbc.alphaD);
  ev.idd.inverseDynamicsDerivatives(ev.mb, ev.mbc);
  r.dtau_dq = ev.idd.dtauDq().cast<double>();
  r.dtau_dalpha = ev.idd.dtauDalpha().cast<double>();
  ev.fdd.forwardDynamicsDerivatives(ev.mb, ev.mbc);
  r.dalphaD_dq = ev.fdd.dalphaDDq().cast<double>();
  r.dalphaD_dalpha = ev.fdd.dalphaDDalpha().cast<double>();
  return r;
}

DerivativesRef derivativesDifferences(const BenchCase & c, const State & s)
{
  Evaluator ev(c.model.mb);
  const VecL q = s.q.cast<L>(), alpha = s.alpha.cast<L>(), alphaD = s.alphaD.cast<L>(), tau = s.tau.cast<L>();
  DerivativesRef r;
  r.dtau_dq = diffQ(ev.mb, q, [&](const VecL & x) { return ev.inverseDynamics(x, alpha, alphaD); }).cast<double>();
  r.dtau_dalpha = diffV(alpha, [&](const VecL & x) { return ev.inverseDynamics(q, x, alphaD); }).cast<double>();
  r.dalphaD_dq = diffQ(ev.mb, q, [&](const VecL & x) { return ev.forwardDynamics(x, alpha, tau); }).cast<double>();
  r.dalphaD_dalpha = diffV(alpha, [&](const VecL & x) { return ev.forwardDynamics(q, x, tau); }).cast<double>();
  solveParts(ev, q, alpha, tau, r);
  return r;
}

void DerivativesErrors::add(const DerivativesRef & a, const DerivativesRef & b, const DerivativesRef & ref)
{
  id = std::max({id, relErr(a.dtau_dq, ref.dtau_dq), relErr(a.dtau_dalpha, ref.dtau_dalpha)});
  const double e = std::max({relErr(b.alphaD, ref.alphaD), relErr(b.dalphaD_dq, ref.dalphaD_dq),
                             relErr(b.dalphaD_dalpha, ref.dalphaD_dalpha), relErr(b.Minv, ref.Minv)});
  fdRaw = std::max(fdRaw, e);
  fd = std::max(fd, e / std::max(1.0, ref.condH));
  worstCond = std::max(worstCond, ref.condH);
}

void checkDerivativesReference(const BenchCase & c, CheckLog & log)
{
  DerivativesErrors e;
  for(std::size_t k = 0; k < kDerivativesChecked && k < c.pool.size(); ++k)
  {
    const DerivativesRef ref = derivativesReference(c, c.pool[k]);
    e.add(ref, ref, derivativesDifferences(c, c.pool[k]));
  }
  char buf[200];
  std::snprintf(buf, sizeof buf, "the reference: rbd::InverseDynamicsDerivatives<long double> vs central differences (h %.0Le), %zu states",
                kDerivativeStep, kDerivativesChecked);
  log.add(kDerivativesReference, "id_derivatives", e.id, 1e-9, buf);
  std::snprintf(buf, sizeof buf, "rbd::ForwardDynamicsDerivatives<long double> vs differences; error / cond(H) (raw %.1e, largest cond(H) %.3g)",
                e.fdRaw, e.worstCond);
  log.add(kDerivativesReference, "fd_derivatives", e.fd, 1e-12, buf);
}

bool derivativesAgree(const CheckLog & log, const std::string & impl, const std::string & algo)
{
  return log.agrees(impl, algo) && log.agrees(kDerivativesReference, algo);
}

} // namespace rbdbench
