// Pinocchio (header-only, built only with -DRBDGEN_PINOCCHIO_SOURCE_DIR=DIR, see bench/CMakeLists.txt)
// on the same states as every other implementation. The pinocchio::Model is built from OUR model
// (the rbd::MultiBody of the runtime cells, fixed joints already merged), not from Pinocchio's URDF
// parser (compiled code):
//   - one Pinocchio joint per runtime joint with dof > 0, in the runtime's joint order (so joint
//     i + 1 - (fixed joints before it) and the dof blocks follow the runtime's order):
//     Rev / Prism about an axis: JointModelRX/RY/RZ/PX/PY/PZ when the axis (S, sign included:
//     backward joints have S = -S_fwd) is ±a unit axis (a negative one via the Unaligned joint with
//     axis -e), else JointModelRevoluteUnaligned / PrismaticUnaligned; Free: JointModelFreeFlyer;
//     Spherical: JointModelSpherical. Planar, Cylindrical and backward Free/Spherical joints: n/a.
//   - joint placement = the runtime's X_p_i (transform(i)), composed with the placement of a
//     fixed parent in its Pinocchio joint; RBDyn's PTransform(E, r) has E = R^T, r = p, so
//     SE3(R = E^T, p = r).
//   - inertia: sva::RBInertia(m, h = m c, I_origin) -> pinocchio::Inertia(m, c = h / m,
//     I_com = I_origin - m (c^T c 1 - c c^T)), appended to the body's joint (identity placement;
//     a fixed body is appended to its parent's joint with its placement).
//   - a fixed body also gets a frame (BODY, on that joint, at its placement): the frames are
//     exactly the fixed links, so forwardKinematics + updateFramePlacements computes every link's
//     world pose, as our "fk" cells do.
// States: free joint q = [qw qx qy qz x y z] (orientation and position of the child in the parent),
// alpha = [w; v] in the child frame; Pinocchio free flyer q = [x y z qx qy qz qw], v = [v; w] in
// the child frame (LOCAL, linear first): the same motion, so only the order changes. Spherical:
// q = [qw qx qy qz] -> [qx qy qz qw], v = w. Tangent space: Pinocchio's derivatives w.r.t. q are
// taken along q ⊕ δ = integrate(q, δ) = q · exp6(δ) for a free flyer, δ = [δv; δω] local: the same
// perturbation as ours (rbd::integrateConfiguration, δ = [δω; δv] in the child frame), reordered.
// So every vector is mapped with a dof permutation P (ours -> Pinocchio's: the two 3-blocks of a
// free joint swapped) and every nv x nv matrix as P^T A P, rows and columns.
// Gravity 9.81 along -z in both (Pinocchio's default model.gravity).
#include "Peers.h"

#ifndef RBDGEN_BENCH_HAVE_PINOCCHIO
namespace rbdbench
{
void registerPinocchio(const BenchCase &, CheckLog &) {}
} // namespace rbdbench
#else

#include <memory>

#include <Eigen/Eigenvalues>

#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/kinematics.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody/data.hpp>
#include <pinocchio/multibody/model.hpp>

#include "../common/Derivatives.h"
#include "../common/Register.h"

namespace rbdbench
{
namespace
{

struct PinocchioData
{
  pinocchio::Model model;
  std::unique_ptr<pinocchio::Data> data;
  std::vector<int> perm;                      ///< perm[our dof] = Pinocchio dof
  std::vector<pinocchio::JointIndex> bodyJoint; ///< runtime body -> Pinocchio joint carrying it
  std::vector<pinocchio::SE3> bodyPlacement;  ///< runtime body frame in that joint's frame
  std::vector<pinocchio::FrameIndex> bodyFrame; ///< frame of a fixed runtime body (0: a moving body, see oMi)
  pinocchio::JointIndex jacJoint = 0;
  pinocchio::SE3 jacPlacement = pinocchio::SE3::Identity(); ///< Jacobian body in jacJoint's frame
  std::vector<Eigen::VectorXd> q, v, a, tau;  ///< pool states in Pinocchio's layout
  Eigen::MatrixXd J;                          ///< 6 x nv
};

/// Builds the model; returns an empty string or why Pinocchio is n/a for this model.
std::string buildModel(const rbd::MultiBody & mb, PinocchioData & d)
{
  using pinocchio::SE3;
  const int nb = mb.nrBodies();
  d.bodyJoint.assign(static_cast<std::size_t>(nb), 0);
  d.bodyPlacement.assign(static_cast<std::size_t>(nb), SE3::Identity());
  d.bodyFrame.assign(static_cast<std::size_t>(nb), 0);
  d.perm.assign(static_cast<std::size_t>(mb.nrDof()), -1);
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const rbd::Joint & j = mb.joint(i);
    const int b = mb.successor(i), p = mb.predecessor(i);
    if(b != i || (p >= 0 && mb.parent(b) != p)) return "joint and body indices differ";
    const pinocchio::JointIndex parentJoint = p < 0 ? 0 : d.bodyJoint[static_cast<std::size_t>(p)];
    const SE3 parentPlacement = p < 0 ? SE3::Identity() : d.bodyPlacement[static_cast<std::size_t>(p)];
    const sva::PTransformd & X = mb.transform(i);
    const SE3 placement = parentPlacement * SE3(X.rotation().transpose(), X.translation());

    // inertia at the CoM
    const sva::RBInertiad & I = mb.body(b).inertia();
    const double m = I.mass();
    const Eigen::Vector3d c = m > 0 ? Eigen::Vector3d(I.momentum() / m) : Eigen::Vector3d::Zero();
    const Eigen::Matrix3d Icom = I.inertia() - m * (c.dot(c) * Eigen::Matrix3d::Identity() - c * c.transpose());
    const pinocchio::Inertia inertia(m, c, Icom);

    if(j.dof() == 0)
    {
      // fixed: the body rides on its parent's joint
      d.bodyJoint[static_cast<std::size_t>(b)] = parentJoint;
      d.bodyPlacement[static_cast<std::size_t>(b)] = placement;
      d.model.appendBodyToJoint(parentJoint, inertia, placement);
      d.bodyFrame[static_cast<std::size_t>(b)] = d.model.addFrame(
        pinocchio::Frame(mb.body(b).name(), parentJoint, placement, pinocchio::BODY), /*append_inertia*/ false);
      continue;
    }
    pinocchio::JointIndex id = 0;
    const std::string name = j.name().empty() ? "joint" + std::to_string(i) : j.name();
    const Eigen::Matrix<double, 6, 1> S = j.motionSubspace().col(0);
    auto aligned = [](const Eigen::Vector3d & a) {
      for(int k = 0; k < 3; ++k)
        if(a(k) == 1 && a.norm() == 1) return k;
      return -1;
    };
    switch(j.type())
    {
      case rbd::Joint::Rev:
      {
        const Eigen::Vector3d axis = S.head<3>();
        switch(aligned(axis))
        {
          case 0: id = d.model.addJoint(parentJoint, pinocchio::JointModelRX(), placement, name); break;
          case 1: id = d.model.addJoint(parentJoint, pinocchio::JointModelRY(), placement, name); break;
          case 2: id = d.model.addJoint(parentJoint, pinocchio::JointModelRZ(), placement, name); break;
          default: id = d.model.addJoint(parentJoint, pinocchio::JointModelRevoluteUnaligned(axis), placement, name);
        }
        break;
      }
      case rbd::Joint::Prism:
      {
        const Eigen::Vector3d axis = S.tail<3>();
        switch(aligned(axis))
        {
          case 0: id = d.model.addJoint(parentJoint, pinocchio::JointModelPX(), placement, name); break;
          case 1: id = d.model.addJoint(parentJoint, pinocchio::JointModelPY(), placement, name); break;
          case 2: id = d.model.addJoint(parentJoint, pinocchio::JointModelPZ(), placement, name); break;
          default: id = d.model.addJoint(parentJoint, pinocchio::JointModelPrismaticUnaligned(axis), placement, name);
        }
        break;
      }
      case rbd::Joint::Free:
        if(!j.forward()) return "backward free joint";
        id = d.model.addJoint(parentJoint, pinocchio::JointModelFreeFlyer(), placement, name);
        break;
      case rbd::Joint::Spherical:
        if(!j.forward()) return "backward spherical joint";
        id = d.model.addJoint(parentJoint, pinocchio::JointModelSpherical(), placement, name);
        break;
      default:
        return std::string("joint type ") + rbd::jointTypeName(j.type()) + " not mapped";
    }
    d.model.appendBodyToJoint(id, inertia, SE3::Identity());
    d.bodyJoint[static_cast<std::size_t>(b)] = id;
    const int v0 = mb.jointPosInDof(i), pv = d.model.idx_vs[id];
    if(j.type() == rbd::Joint::Free)
      for(int k = 0; k < 3; ++k)
      {
        d.perm[static_cast<std::size_t>(v0 + k)] = pv + 3 + k;     // w
        d.perm[static_cast<std::size_t>(v0 + 3 + k)] = pv + k;     // v
      }
    else
      for(int k = 0; k < j.dof(); ++k) d.perm[static_cast<std::size_t>(v0 + k)] = pv + k;
  }
  if(d.model.nv != mb.nrDof()) return "dof count differs";
  for(int p : d.perm)
    if(p < 0) return "dof map incomplete";
  return "";
}

/// Our q (runtime layout) -> Pinocchio's.
Eigen::VectorXd toPinQ(const rbd::MultiBody & mb, const PinocchioData & d, const Eigen::VectorXd & q)
{
  Eigen::VectorXd out(d.model.nq);
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const rbd::Joint & j = mb.joint(i);
    if(j.dof() == 0) continue;
    const int p = mb.jointPosInParam(i), pq = d.model.idx_qs[d.bodyJoint[static_cast<std::size_t>(i)]];
    switch(j.type())
    {
      case rbd::Joint::Free:
        out.segment<3>(pq) = q.segment<3>(p + 4);
        out.segment<3>(pq + 3) = q.segment<3>(p + 1);
        out(pq + 6) = q(p);
        break;
      case rbd::Joint::Spherical:
        out.segment<3>(pq) = q.segment<3>(p + 1);
        out(pq + 3) = q(p);
        break;
      default:
        out.segment(pq, j.params()) = q.segment(p, j.params());
    }
  }
  return out;
}

/// Vector: ours -> Pinocchio's / Pinocchio's -> ours.
Eigen::VectorXd toPin(const PinocchioData & d, const Eigen::VectorXd & x)
{
  Eigen::VectorXd out(x.size());
  for(std::size_t k = 0; k < d.perm.size(); ++k) out(d.perm[k]) = x(static_cast<Eigen::Index>(k));
  return out;
}
Eigen::VectorXd fromPin(const PinocchioData & d, const Eigen::VectorXd & x)
{
  Eigen::VectorXd out(x.size());
  for(std::size_t k = 0; k < d.perm.size(); ++k) out(static_cast<Eigen::Index>(k)) = x(d.perm[k]);
  return out;
}
/// nv x nv matrix in Pinocchio's dof order -> ours (rows and columns).
Eigen::MatrixXd fromPin(const PinocchioData & d, const Eigen::MatrixXd & A)
{
  const Eigen::Index n = static_cast<Eigen::Index>(d.perm.size());
  Eigen::MatrixXd out(n, n);
  for(Eigen::Index r = 0; r < n; ++r)
    for(Eigen::Index c = 0; c < n; ++c) out(r, c) = A(d.perm[static_cast<std::size_t>(r)], d.perm[static_cast<std::size_t>(c)]);
  return out;
}

/// The timed Jacobian: computeJointJacobian (support path only, LOCAL frame of the joint; it leaves
/// the joint's world pose in data.iMf[0]) turned to LOCAL_WORLD_ALIGNED (world axes at the joint
/// origin, [linear; angular]) by the joint's rotation. The Jacobian link is a moving link, so it
/// is its joint's frame (jacPlacement = identity, checked).
void jacobian(PinocchioData & d, std::size_t k)
{
  pinocchio::computeJointJacobian(d.model, *d.data, d.q[k], d.jacJoint, d.J);
  const Eigen::Matrix3d R = d.data->iMf[0].rotation();
  d.J.topRows<3>() = R * d.J.topRows<3>();
  d.J.bottomRows<3>() = R * d.J.bottomRows<3>();
}

} // namespace

void registerPinocchio(const BenchCase & c, CheckLog & log)
{
  const rbd::MultiBody & mb = c.model.mb;
  const int nv = mb.nrDof();
  auto dp = std::make_shared<PinocchioData>();
  PinocchioData & d = *dp;
  const std::string why = buildModel(mb, d);
  if(!why.empty())
  {
    benchmark::AddCustomContext("peer/pinocchio", "n/a: " + why);
    return;
  }
  d.data = std::make_unique<pinocchio::Data>(d.model);
  d.jacJoint = d.bodyJoint[static_cast<std::size_t>(c.jacobianBody)];
  d.jacPlacement = d.bodyPlacement[static_cast<std::size_t>(c.jacobianBody)];
  d.J = Eigen::MatrixXd::Zero(6, nv);
  for(const State & s : c.pool)
  {
    d.q.push_back(toPinQ(mb, d, s.q));
    d.v.push_back(toPin(d, s.alpha));
    d.a.push_back(toPin(d, s.alphaD));
    d.tau.push_back(toPin(d, s.tau));
  }
  benchmark::AddCustomContext("peer/pinocchio", "Pinocchio " PINOCCHIO_VERSION " header-only, model built from the runtime's MultiBody: " +
                                                  std::to_string(d.model.njoints - 1) + " joints");
  pinocchio::Data & data = *d.data;
  const std::string r = c.name, impl = "pinocchio";

  // --- agreement with the runtime ---------------------------------------------------------------
  double eFK = 0, eID = 0, eH = 0, eFD = 0, eJ = 0, worstCond = 0;
  for(std::size_t k = 0; k < kPeerChecked; ++k)
  {
    const Reference ref = reference(c, c.pool[k]);
    pinocchio::forwardKinematics(d.model, data, d.q[k]);
    pinocchio::updateFramePlacements(d.model, data);
    for(int b = 0; b < mb.nrBodies(); ++b)
    {
      const auto bk = static_cast<std::size_t>(b);
      const pinocchio::SE3 & oMb = d.bodyFrame[bk] ? data.oMf[d.bodyFrame[bk]] : data.oMi[d.bodyJoint[bk]];
      const sva::PTransformd & X = ref.bodyPosW[static_cast<std::size_t>(b)];
      eFK = std::max({eFK, relErr(oMb.rotation().transpose(), X.rotation()), relErr(oMb.translation(), X.translation())});
    }
    eID = std::max(eID, relErr(fromPin(d, Eigen::VectorXd(pinocchio::rnea(d.model, data, d.q[k], d.v[k], d.a[k]))), ref.tauID));
    pinocchio::crba(d.model, data, d.q[k]);
    data.M.triangularView<Eigen::StrictlyLower>() = data.M.transpose().triangularView<Eigen::StrictlyLower>();
    eH = std::max(eH, relErr(fromPin(d, Eigen::MatrixXd(data.M)), ref.H));
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(ref.H, Eigen::EigenvaluesOnly).eigenvalues();
    const double condH = lambda.maxCoeff() / lambda.minCoeff();
    worstCond = std::max(worstCond, condH);
    eFD = std::max(eFD, relErr(fromPin(d, Eigen::VectorXd(pinocchio::aba(d.model, data, d.q[k], d.v[k], d.tau[k]))), ref.alphaDFD) /
                          std::max(1.0, condH));
    jacobian(d, k);
    Eigen::MatrixXd J(6, nv); // Pinocchio [linear; angular], its dof order -> ours [angular; linear]
    for(int col = 0; col < nv; ++col)
    {
      J.col(col).head<3>() = d.J.col(d.perm[static_cast<std::size_t>(col)]).tail<3>();
      J.col(col).tail<3>() = d.J.col(d.perm[static_cast<std::size_t>(col)]).head<3>();
    }
    eJ = std::max(eJ, relErr(J, ref.J));
  }
  if(!d.jacPlacement.isIdentity()) eJ = HUGE_VAL; // the Jacobian link is a moving link (BenchCase)
  const double tol = 1e-9;
  log.add(impl, "fk", eFK, tol, "forwardKinematics + updateFramePlacements: oMi (moving links), oMf (fixed links)");
  log.add(impl, "id", eID, tol, "rnea");
  log.add(impl, "mass_matrix", eH, tol, "crba (upper triangle), lower triangle filled");
  log.add(impl, "fd", eFD, 1e-12, "aba; error / cond(H), largest cond(H) " + std::to_string(worstCond));
  log.add(impl, "jacobian", eJ, tol, "computeJointJacobian (support path) rotated to LOCAL_WORLD_ALIGNED, rows reordered");
  checkDerivatives(
    c, log, impl,
    [&](std::size_t k) {
      pinocchio::computeRNEADerivatives(d.model, data, d.q[k], d.v[k], d.a[k]);
      DerivativesRef out;
      out.dtau_dq = fromPin(d, Eigen::MatrixXd(data.dtau_dq));
      out.dtau_dalpha = fromPin(d, Eigen::MatrixXd(data.dtau_dv));
      return out;
    },
    [&](std::size_t k) {
      pinocchio::computeABADerivatives(d.model, data, d.q[k], d.v[k], d.tau[k]);
      DerivativesRef out;
      out.alphaD = fromPin(d, Eigen::VectorXd(data.ddq));
      out.dalphaD_dq = fromPin(d, Eigen::MatrixXd(data.ddq_dq));
      out.dalphaD_dalpha = fromPin(d, Eigen::MatrixXd(data.ddq_dv));
      out.Minv = fromPin(d, Eigen::MatrixXd(data.Minv));
      return out;
    },
    "computeRNEADerivatives: dtau_dq, dtau_dv", "computeABADerivatives: ddq, ddq_dq, ddq_dv, Minv");

  // --- timed cells (only those that agree); inputs and outputs in Pinocchio's layout -------------
  auto add = [&](const std::string & algo, auto f) {
    const bool derivatives = algo == "id_derivatives" || algo == "fd_derivatives";
    if(derivatives ? derivativesAgree(log, impl, algo) : log.agrees(impl, algo)) addBench(r, algo, impl, f);
  };
  add("fk", [dp](std::size_t k) {
    pinocchio::forwardKinematics(dp->model, *dp->data, dp->q[k]);
    pinocchio::updateFramePlacements(dp->model, *dp->data);
    benchmark::DoNotOptimize(dp->data->oMi.back());
    benchmark::DoNotOptimize(dp->data->oMf.back());
    benchmark::ClobberMemory();
  });
  add("id", [dp](std::size_t k) {
    benchmark::DoNotOptimize(pinocchio::rnea(dp->model, *dp->data, dp->q[k], dp->v[k], dp->a[k]).data());
    benchmark::ClobberMemory();
  });
  // crba fills the upper triangle; the lower one is filled too, for the full matrix the others return
  add("mass_matrix", [dp](std::size_t k) {
    Eigen::MatrixXd & M = dp->data->M;
    pinocchio::crba(dp->model, *dp->data, dp->q[k]);
    M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
    benchmark::DoNotOptimize(M.data());
    benchmark::ClobberMemory();
  });
  add("fd", [dp](std::size_t k) {
    benchmark::DoNotOptimize(pinocchio::aba(dp->model, *dp->data, dp->q[k], dp->v[k], dp->tau[k]).data());
    benchmark::ClobberMemory();
  });
  add("jacobian", [dp](std::size_t k) {
    jacobian(*dp, k);
    benchmark::DoNotOptimize(dp->J.data());
    benchmark::ClobberMemory();
  });
  add("id_derivatives", [dp](std::size_t k) {
    pinocchio::computeRNEADerivatives(dp->model, *dp->data, dp->q[k], dp->v[k], dp->a[k]);
    benchmark::DoNotOptimize(dp->data->dtau_dq.data());
    benchmark::DoNotOptimize(dp->data->dtau_dv.data());
    benchmark::ClobberMemory();
  });
  add("fd_derivatives", [dp](std::size_t k) {
    pinocchio::computeABADerivatives(dp->model, *dp->data, dp->q[k], dp->v[k], dp->tau[k]);
    benchmark::DoNotOptimize(dp->data->ddq_dq.data());
    benchmark::DoNotOptimize(dp->data->ddq_dv.data());
    benchmark::DoNotOptimize(dp->data->Minv.data());
    benchmark::ClobberMemory();
  });
}

} // namespace rbdbench
#endif
