#include "RuntimeBench.h"

#include <memory>

#include <rbd/ABA.h>
#include <rbd/CoM.h>
#include <rbd/FD.h>
#include <rbd/FDDerivatives.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>
#include <rbd/Jacobian.h>

#include "Derivatives.h"
#include "Register.h"

namespace rbdbench
{
namespace
{
struct RuntimeData
{
  rbd::MultiBody mb;
  std::vector<rbd::MultiBodyConfig> pool;      ///< q, alpha, alphaD, jointTorque of each state
  std::vector<rbd::MultiBodyConfig> poolStill; ///< the same q, alpha = alphaD = 0
  std::vector<rbd::MultiBodyConfig> poolID, poolFD; ///< copies for the algorithms that write jointTorque / alphaD
  std::vector<rbd::MultiBodyConfig> poolIDext;      ///< as poolID, with the state's wrench on every link (force)
  rbd::InverseDynamics id;
  rbd::ForwardDynamics fd;
  rbd::ForwardDynamicsABA aba;
  rbd::Jacobian jac;
  rbd::InverseDynamicsDerivatives idd;
  rbd::ForwardDynamicsDerivatives fdd;
  Eigen::MatrixXd J, C;
};
} // namespace

void registerRuntime(const BenchCase & c, CheckLog & log)
{
  auto d = std::make_shared<RuntimeData>();
  d->mb = c.model.mb;
  const rbd::MultiBody & mb = d->mb;
  for(const State & s : c.pool)
  {
    rbd::MultiBodyConfig mbc(mb);
    rbd::vectorToParam<double>(s.q, mbc.q);
    rbd::MultiBodyConfig still = mbc;
    rbd::vectorToDof<double>(s.alpha, mbc.alpha);
    rbd::vectorToDof<double>(s.alphaD, mbc.alphaD);
    rbd::vectorToDof<double>(s.tau, mbc.jointTorque);
    d->pool.push_back(mbc);
    d->poolStill.push_back(still);
  }
  d->poolID = d->pool;
  d->poolFD = d->pool;
  d->poolIDext = d->pool;
  for(std::size_t k = 0; k < c.pool.size(); ++k)
    for(int b = 0; b < mb.nrBodies(); ++b)
      d->poolIDext[k].force[static_cast<std::size_t>(b)] = sva::ForceVecd(Eigen::Matrix<double, 6, 1>(c.pool[k].fext.segment<6>(6 * b)));
  d->id = rbd::InverseDynamics(mb);
  d->fd = rbd::ForwardDynamics(mb);
  d->aba = rbd::ForwardDynamicsABA(mb);
  d->jac = rbd::Jacobian(mb, c.jacobianBodyName);
  d->idd = rbd::InverseDynamicsDerivatives(mb);
  d->fdd = rbd::ForwardDynamicsDerivatives(mb);
  d->J = Eigen::MatrixXd::Zero(6, mb.nrDof());
  d->C = Eigen::MatrixXd::Zero(mb.nrDof(), 1);
  const std::string r = c.name, impl = "runtime";

  addBench(r, "fk", impl, [d](std::size_t k) {
    rbd::forwardKinematics(d->mb, d->pool[k]);
    benchmark::DoNotOptimize(d->pool[k].bodyPosW.back());
  });
  addBench(r, "fk_vel", impl, [d](std::size_t k) {
    rbd::forwardKinematics(d->mb, d->pool[k]);
    rbd::forwardVelocity(d->mb, d->pool[k]);
    benchmark::DoNotOptimize(d->pool[k].bodyVelB.back());
  });
  addBench(r, "id", impl, [d](std::size_t k) {
    auto & mbc = d->poolID[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->id.inverseDynamics(d->mb, mbc);
    benchmark::DoNotOptimize(mbc.jointTorque.front());
    benchmark::ClobberMemory();
  });
  addBench(r, "id_fext", impl, [d](std::size_t k) {
    auto & mbc = d->poolIDext[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->id.inverseDynamics(d->mb, mbc);
    benchmark::DoNotOptimize(mbc.jointTorque.front());
    benchmark::ClobberMemory();
  });
  addBench(r, "gravity", impl, [d](std::size_t k) {
    auto & mbc = d->poolStill[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->id.nonLinearEffects(d->mb, mbc, d->C);
    benchmark::DoNotOptimize(d->C.data());
    benchmark::ClobberMemory();
  });
  addBench(r, "nle", impl, [d](std::size_t k) {
    auto & mbc = d->pool[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->id.nonLinearEffects(d->mb, mbc, d->C);
    benchmark::DoNotOptimize(d->C.data());
    benchmark::ClobberMemory();
  });
  addBench(r, "mass_matrix", impl, [d](std::size_t k) {
    auto & mbc = d->pool[k];
    rbd::forwardKinematics(d->mb, mbc);
    d->fd.computeH(d->mb, mbc);
    benchmark::DoNotOptimize(d->fd.H().data());
    benchmark::ClobberMemory();
  });
  auto crba = [d](std::size_t k) {
    auto & mbc = d->poolFD[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->fd.forwardDynamics(d->mb, mbc);
    benchmark::DoNotOptimize(mbc.alphaD.front());
    benchmark::ClobberMemory();
  };
  addBench(r, "fd", impl, crba); // the runtime's ForwardDynamics is its default (CRBA + Cholesky)
  addBench(r, "fd_crba", impl, crba);
  addBench(r, "fd_aba", impl, [d](std::size_t k) {
    auto & mbc = d->poolFD[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->aba.forwardDynamics(d->mb, mbc);
    benchmark::DoNotOptimize(mbc.alphaD.front());
    benchmark::ClobberMemory();
  });
  addBench(r, "jacobian", impl, [d](std::size_t k) {
    auto & mbc = d->poolStill[k];
    rbd::forwardKinematics(d->mb, mbc);
    d->jac.fullJacobian(d->mb, d->jac.jacobian(d->mb, mbc), d->J);
    benchmark::DoNotOptimize(d->J.data());
    benchmark::ClobberMemory();
  });
  addBench(r, "com", impl, [d](std::size_t k) {
    auto & mbc = d->poolStill[k];
    rbd::forwardKinematics(d->mb, mbc);
    Eigen::Vector3d com = rbd::computeCoM(d->mb, mbc);
    benchmark::DoNotOptimize(com);
  });

  // Derivatives: from q, alpha and alphaD (ID) or tau (FD), forward kinematics and velocities first;
  // the same calls are checked and timed.
  auto idDerivatives = [d](std::size_t k) -> const rbd::InverseDynamicsDerivatives & {
    auto & mbc = d->pool[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->idd.inverseDynamicsDerivatives(d->mb, mbc);
    return d->idd;
  };
  auto fdDerivatives = [d](std::size_t k) -> const rbd::ForwardDynamicsDerivatives & {
    auto & mbc = d->pool[k];
    rbd::forwardKinematics(d->mb, mbc);
    rbd::forwardVelocity(d->mb, mbc);
    d->fdd.forwardDynamicsDerivatives(d->mb, mbc);
    return d->fdd;
  };
  checkDerivatives(
    c, log, impl,
    [idDerivatives](std::size_t k) {
      const rbd::InverseDynamicsDerivatives & res = idDerivatives(k);
      DerivativesRef out;
      out.dtau_dq = res.dtauDq();
      out.dtau_dalpha = res.dtauDalpha();
      return out;
    },
    [fdDerivatives](std::size_t k) {
      const rbd::ForwardDynamicsDerivatives & res = fdDerivatives(k);
      DerivativesRef out;
      out.alphaD = res.alphaD();
      out.dalphaD_dq = res.dalphaDDq();
      out.dalphaD_dalpha = res.dalphaDDalpha();
      out.Minv = res.Minv();
      return out;
    },
    "rbd::InverseDynamicsDerivatives", "rbd::ForwardDynamicsDerivatives");
  if(derivativesAgree(log, impl, "id_derivatives"))
    addBench(r, "id_derivatives", impl, [idDerivatives](std::size_t k) {
      const rbd::InverseDynamicsDerivatives & res = idDerivatives(k);
      benchmark::DoNotOptimize(res.dtauDq().data());
      benchmark::DoNotOptimize(res.dtauDalpha().data());
      benchmark::ClobberMemory();
    });
  if(derivativesAgree(log, impl, "fd_derivatives"))
    addBench(r, "fd_derivatives", impl, [fdDerivatives](std::size_t k) {
      const rbd::ForwardDynamicsDerivatives & res = fdDerivatives(k);
      benchmark::DoNotOptimize(res.dalphaDDq().data());
      benchmark::DoNotOptimize(res.dalphaDDalpha().data());
      benchmark::DoNotOptimize(res.Minv().data());
      benchmark::ClobberMemory();
    });
}

} // namespace rbdbench
