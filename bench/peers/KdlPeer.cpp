// KDL (orocos_kdl + kdl_parser) on the same URDF and states. KDL has no floating base: floating
// robots are n/a. Chains (the root -> Jacobian-link chain holds every joint): the Chain* solvers;
// other fixed-base trees: the Tree* solvers (FK, ID, gravity, NLE, Jacobian).
#include "Peers.h"

#ifndef RBDGEN_BENCH_HAVE_KDL
namespace rbdbench
{
void registerKdl(const BenchCase &, CheckLog &) {}
} // namespace rbdbench
#else

#include <map>

#include <kdl/chaindynparam.hpp>
#include <kdl/chainfdsolver_recursive_newton_euler.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainfksolvervel_recursive.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/treefksolverpos_recursive.hpp>
#include <kdl/treeidsolver_recursive_newton_euler.hpp>
#include <kdl/treejnttojacsolver.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include "../common/Register.h"

namespace rbdbench
{
namespace
{
const KDL::Vector kGravity(0, 0, -9.81);

struct KdlData
{
  KDL::Tree tree;
  KDL::Chain chain;
  bool isChain = false;
  std::vector<int> dofOf;               ///< KDL joint index -> runtime dof index
  std::vector<std::string> segments;    ///< tree mode: every non-root segment (FK)
  std::vector<KDL::JntArray> q, qd, qdd, tau, zero;
  KDL::JntArray out;
  KDL::JntSpaceInertiaMatrix H;
  KDL::Jacobian J;
  std::vector<KDL::Frame> frames;
  std::vector<KDL::FrameVel> frameVels;
  KDL::Wrenches wrenches;
  KDL::WrenchMap wrenchMap;
  std::unique_ptr<KDL::ChainFkSolverPos_recursive> fk;
  std::unique_ptr<KDL::ChainFkSolverVel_recursive> fkVel;
  std::unique_ptr<KDL::ChainIdSolver_RNE> id;
  std::unique_ptr<KDL::ChainDynParam> dyn;
  std::unique_ptr<KDL::ChainFdSolver_RNE> fd;
  std::unique_ptr<KDL::ChainJntToJacSolver> jac;
  std::unique_ptr<KDL::TreeFkSolverPos_recursive> treeFk;
  std::unique_ptr<KDL::TreeIdSolver_RNE> treeId;
  std::unique_ptr<KDL::TreeJntToJacSolver> treeJac;
};

KDL::JntArray toKdl(const Eigen::VectorXd & v, const std::vector<int> & dofOf)
{
  KDL::JntArray a(static_cast<unsigned>(dofOf.size()));
  for(std::size_t j = 0; j < dofOf.size(); ++j) a(static_cast<unsigned>(j)) = v(dofOf[j]);
  return a;
}

Eigen::VectorXd fromKdl(const KDL::JntArray & a, const std::vector<int> & dofOf, int nv)
{
  Eigen::VectorXd v = Eigen::VectorXd::Zero(nv);
  for(std::size_t j = 0; j < dofOf.size(); ++j) v(dofOf[j]) = a(static_cast<unsigned>(j));
  return v;
}

/// KDL Jacobian (rows [linear; angular], base axes, at the link origin) -> runtime layout.
Eigen::MatrixXd fromKdl(const KDL::Jacobian & J, const std::vector<int> & dofOf, int nv)
{
  Eigen::MatrixXd res = Eigen::MatrixXd::Zero(6, nv);
  for(std::size_t j = 0; j < dofOf.size(); ++j)
    for(int r = 0; r < 6; ++r) res((r + 3) % 6, dofOf[j]) = J(static_cast<unsigned>(r), static_cast<unsigned>(j));
  return res;
}

/// Pose error of a KDL frame (R body->world, p) against X_0_i (E = R^T, r = p).
double poseErr(const KDL::Frame & F, const sva::PTransformd & X_0_i)
{
  Eigen::Matrix3d R;
  for(int a = 0; a < 3; ++a)
    for(int b = 0; b < 3; ++b) R(a, b) = F.M(a, b);
  const Eigen::Vector3d p(F.p.x(), F.p.y(), F.p.z());
  return std::max(relErr(R.transpose(), X_0_i.rotation()), relErr(p, X_0_i.translation()));
}

} // namespace

void registerKdl(const BenchCase & c, CheckLog & log)
{
  if(c.floating)
  {
    benchmark::AddCustomContext("peer/kdl", "n/a: KDL has no floating base");
    return;
  }
  // Never freed: liborocos-kdl is built without AVX, so its Eigen members were allocated with
  // another alignment than this AVX-512 translation unit would free them with (a crash at exit).
  KdlData * d = new KdlData;
  if(!kdl_parser::treeFromFile(c.urdf, d->tree))
  {
    benchmark::AddCustomContext("peer/kdl", "n/a: kdl_parser cannot read the URDF");
    return;
  }
  const rbd::MultiBody & mb = c.model.mb;
  const int nv = mb.nrDof();
  const std::string root = d->tree.getRootSegment()->first;
  auto dofOfJoint = [&](const std::string & name) {
    const auto it = mb.jointIndexByName().find(name);
    return it == mb.jointIndexByName().end() ? -1 : mb.jointPosInDof(it->second);
  };
  d->isChain = d->tree.getChain(root, c.jacobianBodyName, d->chain) && static_cast<int>(d->chain.getNrOfJoints()) == nv;
  if(d->isChain)
  {
    for(const auto & seg : d->chain.segments)
      if(seg.getJoint().getType() != KDL::Joint::None) d->dofOf.push_back(dofOfJoint(seg.getJoint().getName()));
  }
  else
  {
    d->dofOf.assign(d->tree.getNrOfJoints(), -1);
    for(const auto & [name, el] : d->tree.getSegments())
    {
      const KDL::Segment & seg = GetTreeElementSegment(el);
      if(name != root) d->segments.push_back(name);
      if(seg.getJoint().getType() != KDL::Joint::None) d->dofOf[GetTreeElementQNr(el)] = dofOfJoint(seg.getJoint().getName());
    }
  }
  for(int k : d->dofOf)
    if(k < 0 || static_cast<int>(d->dofOf.size()) != nv)
    {
      benchmark::AddCustomContext("peer/kdl", "n/a: KDL joints do not map onto the runtime's");
      return;
    }
  for(const State & s : c.pool)
  {
    d->q.push_back(toKdl(s.q, d->dofOf));
    d->qd.push_back(toKdl(s.alpha, d->dofOf));
    d->qdd.push_back(toKdl(s.alphaD, d->dofOf));
    d->tau.push_back(toKdl(s.tau, d->dofOf));
  }
  d->zero.assign(1, KDL::JntArray(static_cast<unsigned>(nv)));
  d->out = KDL::JntArray(static_cast<unsigned>(nv));
  d->H = KDL::JntSpaceInertiaMatrix(static_cast<unsigned>(nv));
  d->J = KDL::Jacobian(static_cast<unsigned>(nv));
  const KDL::JntArray & zero = d->zero[0];
  const std::string r = c.name, impl = "kdl";

  if(d->isChain)
  {
    const unsigned nseg = d->chain.getNrOfSegments();
    d->frames.resize(nseg);
    d->frameVels.resize(nseg);
    d->wrenches.assign(nseg, KDL::Wrench::Zero());
    d->fk = std::make_unique<KDL::ChainFkSolverPos_recursive>(d->chain);
    d->fkVel = std::make_unique<KDL::ChainFkSolverVel_recursive>(d->chain);
    d->id = std::make_unique<KDL::ChainIdSolver_RNE>(d->chain, kGravity);
    d->dyn = std::make_unique<KDL::ChainDynParam>(d->chain, kGravity);
    d->fd = std::make_unique<KDL::ChainFdSolver_RNE>(d->chain, kGravity);
    d->jac = std::make_unique<KDL::ChainJntToJacSolver>(d->chain);
    benchmark::AddCustomContext("peer/kdl", "chain solvers, " + std::to_string(nseg) + " segments");
  }
  else
  {
    d->treeFk = std::make_unique<KDL::TreeFkSolverPos_recursive>(d->tree);
    d->treeId = std::make_unique<KDL::TreeIdSolver_RNE>(d->tree, kGravity);
    d->treeJac = std::make_unique<KDL::TreeJntToJacSolver>(d->tree);
    benchmark::AddCustomContext("peer/kdl", "tree solvers (the robot is not a chain); mass matrix and FD n/a");
  }

  // --- agreement with the runtime ---------------------------------------------------------------
  double eFK = 0, eV = 0, eID = 0, eG = 0, eC = 0, eH = 0, eFD = 0, eJ = 0;
  for(std::size_t k = 0; k < kPeerChecked; ++k)
  {
    const Reference ref = reference(c, c.pool[k]);
    if(d->isChain)
    {
      d->fk->JntToCart(d->q[k], d->frames);
      KDL::JntArrayVel qv(d->q[k], d->qd[k]);
      d->fkVel->JntToCart(qv, d->frameVels);
      for(unsigned s = 0; s < d->chain.getNrOfSegments(); ++s)
      {
        const int b = mb.bodyIndexByName(d->chain.getSegment(s).getName());
        eFK = std::max(eFK, poseErr(d->frames[s], ref.bodyPosW[static_cast<std::size_t>(b)]));
        // KDL twist: velocity of the segment origin and angular velocity, base axes
        const KDL::Twist t = d->frameVels[s].GetTwist();
        const Eigen::Matrix3d & E = ref.bodyPosW[static_cast<std::size_t>(b)].rotation();
        Eigen::Matrix<double, 6, 1> vB;
        vB << E * Eigen::Vector3d(t.rot.x(), t.rot.y(), t.rot.z()), E * Eigen::Vector3d(t.vel.x(), t.vel.y(), t.vel.z());
        eV = std::max(eV, relErr(vB, ref.bodyVelB[static_cast<std::size_t>(b)].vector()));
      }
      d->id->CartToJnt(d->q[k], d->qd[k], d->qdd[k], d->wrenches, d->out);
      eID = std::max(eID, relErr(fromKdl(d->out, d->dofOf, nv), ref.tauID));
      d->dyn->JntToGravity(d->q[k], d->out);
      eG = std::max(eG, relErr(fromKdl(d->out, d->dofOf, nv), ref.tauGravity));
      d->id->CartToJnt(d->q[k], d->qd[k], zero, d->wrenches, d->out);
      eC = std::max(eC, relErr(fromKdl(d->out, d->dofOf, nv), ref.tauNLE));
      d->dyn->JntToMass(d->q[k], d->H);
      Eigen::MatrixXd H(nv, nv);
      for(int a = 0; a < nv; ++a)
        for(int b = 0; b < nv; ++b) H(d->dofOf[static_cast<std::size_t>(a)], d->dofOf[static_cast<std::size_t>(b)]) = d->H(static_cast<unsigned>(a), static_cast<unsigned>(b));
      eH = std::max(eH, relErr(H, ref.H));
      d->fd->CartToJnt(d->q[k], d->qd[k], d->tau[k], d->wrenches, d->out);
      eFD = std::max(eFD, relErr(fromKdl(d->out, d->dofOf, nv), ref.alphaDFD));
      d->jac->JntToJac(d->q[k], d->J);
      eJ = std::max(eJ, relErr(fromKdl(d->J, d->dofOf, nv), ref.J));
    }
    else
    {
      for(const std::string & name : d->segments)
      {
        KDL::Frame F;
        d->treeFk->JntToCart(d->q[k], F, name);
        eFK = std::max(eFK, poseErr(F, ref.bodyPosW[static_cast<std::size_t>(mb.bodyIndexByName(name))]));
      }
      d->treeId->CartToJnt(d->q[k], d->qd[k], d->qdd[k], d->wrenchMap, d->out);
      eID = std::max(eID, relErr(fromKdl(d->out, d->dofOf, nv), ref.tauID));
      d->treeId->CartToJnt(d->q[k], zero, zero, d->wrenchMap, d->out);
      eG = std::max(eG, relErr(fromKdl(d->out, d->dofOf, nv), ref.tauGravity));
      d->treeId->CartToJnt(d->q[k], d->qd[k], zero, d->wrenchMap, d->out);
      eC = std::max(eC, relErr(fromKdl(d->out, d->dofOf, nv), ref.tauNLE));
      d->treeJac->JntToJac(d->q[k], d->J, c.jacobianBodyName);
      eJ = std::max(eJ, relErr(fromKdl(d->J, d->dofOf, nv), ref.J));
    }
  }
  const double tol = 1e-9;
  log.add(impl, "fk", eFK, tol, d->isChain ? "ChainFkSolverPos_recursive, every segment" : "TreeFkSolverPos_recursive, once per segment");
  log.add(impl, "id", eID, tol, d->isChain ? "ChainIdSolver_RNE" : "TreeIdSolver_RNE");
  log.add(impl, "gravity", eG, tol, d->isChain ? "ChainDynParam::JntToGravity" : "TreeIdSolver_RNE(q, 0, 0)");
  log.add(impl, "nle", eC, tol, d->isChain ? "ChainIdSolver_RNE(q, qd, 0)" : "TreeIdSolver_RNE(q, qd, 0)");
  log.add(impl, "jacobian", eJ, tol, d->isChain ? "ChainJntToJacSolver" : "TreeJntToJacSolver");
  if(d->isChain)
  {
    log.add(impl, "fk_vel", eV, tol, "ChainFkSolverVel_recursive, every segment");
    log.add(impl, "mass_matrix", eH, tol, "ChainDynParam::JntToMass");
    log.add(impl, "fd", eFD, 1e-8, "ChainFdSolver_RNE");
  }

  // --- timed cells (only those that agree) ------------------------------------------------------
  auto add = [&](const std::string & algo, auto f) {
    if(log.agrees(impl, algo)) addBench(r, algo, impl, f);
  };
  if(d->isChain)
  {
    add("fk", [d](std::size_t k) { d->fk->JntToCart(d->q[k], d->frames); benchmark::DoNotOptimize(d->frames.back()); });
    add("fk_vel", [d](std::size_t k) {
      KDL::JntArrayVel qv(d->q[k], d->qd[k]);
      d->fkVel->JntToCart(qv, d->frameVels);
      benchmark::DoNotOptimize(d->frameVels.back());
    });
    add("id", [d](std::size_t k) { d->id->CartToJnt(d->q[k], d->qd[k], d->qdd[k], d->wrenches, d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("gravity", [d](std::size_t k) { d->dyn->JntToGravity(d->q[k], d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("nle", [d](std::size_t k) { d->id->CartToJnt(d->q[k], d->qd[k], d->zero[0], d->wrenches, d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("mass_matrix", [d](std::size_t k) { d->dyn->JntToMass(d->q[k], d->H); benchmark::DoNotOptimize(d->H.data.data()); benchmark::ClobberMemory(); });
    add("fd", [d](std::size_t k) { d->fd->CartToJnt(d->q[k], d->qd[k], d->tau[k], d->wrenches, d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("jacobian", [d](std::size_t k) { d->jac->JntToJac(d->q[k], d->J); benchmark::DoNotOptimize(d->J.data.data()); benchmark::ClobberMemory(); });
  }
  else
  {
    add("fk", [d](std::size_t k) {
      for(const std::string & name : d->segments)
      {
        KDL::Frame F;
        d->treeFk->JntToCart(d->q[k], F, name);
        benchmark::DoNotOptimize(F);
      }
    });
    add("id", [d](std::size_t k) { d->treeId->CartToJnt(d->q[k], d->qd[k], d->qdd[k], d->wrenchMap, d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("gravity", [d](std::size_t k) { d->treeId->CartToJnt(d->q[k], d->zero[0], d->zero[0], d->wrenchMap, d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("nle", [d](std::size_t k) { d->treeId->CartToJnt(d->q[k], d->qd[k], d->zero[0], d->wrenchMap, d->out); benchmark::DoNotOptimize(d->out.data.data()); benchmark::ClobberMemory(); });
    add("jacobian", [d, name = c.jacobianBodyName](std::size_t k) { d->treeJac->JntToJac(d->q[k], d->J, name); benchmark::DoNotOptimize(d->J.data.data()); benchmark::ClobberMemory(); });
  }
}

} // namespace rbdbench
#endif
