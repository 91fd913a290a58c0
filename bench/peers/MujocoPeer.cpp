// MuJoCo on a copy of the URDF: visual/collision geometry, <gazebo> and <transmission> stripped, a
// <mujoco><compiler/></mujoco> element (fixed links fused, as MuJoCo does by default; inertias
// taken from the URDF), a "floating" joint to a massless world link for floating robots.
// Armature, damping, friction loss, stiffness are zeroed; contacts, constraints, limits and passive
// forces disabled; gravity (0, 0, -9.81).
//
// Coordinates: hinge/slide joints are matched by name. Free joint: MuJoCo qpos = [x y z qw qx qy
// qz], qvel = [v_world; w_body] against ours [w_body; v_body]: qvel = T alpha with T orthogonal
// (T = [0 R; I 0] on the free block, R = body -> world), so tau = T^T qfrc, H = T^T M T,
// qacc = T alphaD + [R (w x v); 0], J = J_mj T.
#include "Peers.h"

#ifndef RBDGEN_BENCH_HAVE_MUJOCO
namespace rbdbench
{
void registerMujoco(const BenchCase &, CheckLog &) {}
} // namespace rbdbench
#else

#include <cstdio>
#include <memory>
#include <unistd.h>

#include <mujoco/mujoco.h>
#include <tinyxml2.h>

#include "../common/Register.h"

namespace rbdbench
{
namespace
{

/// The URDF text MuJoCo loads (see the file comment); empty on a read error.
std::string mujocoUrdf(const BenchCase & c, bool balanceInertia)
{
  tinyxml2::XMLDocument doc;
  if(doc.LoadFile(c.urdf.c_str()) != tinyxml2::XML_SUCCESS) return "";
  tinyxml2::XMLElement * robot = doc.FirstChildElement("robot");
  if(!robot) return "";
  for(const char * tag : {"gazebo", "transmission", "mujoco"})
    while(tinyxml2::XMLElement * e = robot->FirstChildElement(tag)) robot->DeleteChild(e);
  for(tinyxml2::XMLElement * link = robot->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
    for(const char * tag : {"visual", "collision"})
      while(tinyxml2::XMLElement * e = link->FirstChildElement(tag)) link->DeleteChild(e);
  if(c.floating)
  {
    tinyxml2::XMLElement * world = robot->InsertNewChildElement("link");
    world->SetAttribute("name", "rbdgen_world");
    tinyxml2::XMLElement * joint = robot->InsertNewChildElement("joint");
    joint->SetAttribute("name", "rbdgen_root");
    joint->SetAttribute("type", "floating");
    joint->InsertNewChildElement("parent")->SetAttribute("link", "rbdgen_world");
    joint->InsertNewChildElement("child")->SetAttribute("link", c.model.mb.body(0).name().c_str());
  }
  tinyxml2::XMLElement * mj = robot->InsertNewChildElement("mujoco");
  tinyxml2::XMLElement * compiler = mj->InsertNewChildElement("compiler");
  compiler->SetAttribute("discardvisual", "true");
  compiler->SetAttribute("fusestatic", "true");
  compiler->SetAttribute("balanceinertia", balanceInertia ? "true" : "false");
  compiler->SetAttribute("inertiafromgeom", "false");
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

/// MuJoCo inputs of one state, in MuJoCo coordinates.
struct MjState
{
  std::vector<mjtNum> qpos, qvel, qacc, qfrc;
  std::vector<mjtNum> qaccNLE; ///< MuJoCo acceleration for alphaD = 0: bias (non-zero with a free joint)
  Eigen::MatrixXd T;    ///< qvel = T alpha (orthogonal)
  Eigen::VectorXd bias; ///< qacc = T alphaD + bias
};

struct MujocoData
{
  mjModel * m = nullptr;
  mjData * d = nullptr;
  std::vector<MjState> pool;
  std::vector<mjtNum> M, jacp, jacr, res;
  int jacBody = -1;
  ~MujocoData()
  {
    if(d) mj_deleteData(d);
    if(m) mj_deleteModel(m);
  }
};

/// Joint correspondences; false if a joint has no MuJoCo counterpart or an unsupported type.
bool makeState(const BenchCase & c, const mjModel * m, const State & s, MjState & out)
{
  const rbd::MultiBody & mb = c.model.mb;
  const int nv = mb.nrDof();
  out.qpos.assign(static_cast<std::size_t>(m->nq), 0);
  out.T = Eigen::MatrixXd::Zero(nv, nv);
  out.bias = Eigen::VectorXd::Zero(nv);
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto & jt = mb.joint(i);
    if(jt.dof() == 0) continue;
    const std::string name = jt.type() == rbd::Joint::Free ? "rbdgen_root" : jt.name();
    const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    if(j < 0) return false;
    const int qa = m->jnt_qposadr[j], va = m->jnt_dofadr[j], p = mb.jointPosInParam(i), v = mb.jointPosInDof(i);
    if(jt.type() == rbd::Joint::Free && m->jnt_type[j] == mjJNT_FREE)
    {
      for(int k = 0; k < 3; ++k) out.qpos[static_cast<std::size_t>(qa + k)] = s.q(p + 4 + k);
      for(int k = 0; k < 4; ++k) out.qpos[static_cast<std::size_t>(qa + 3 + k)] = s.q(p + k);
      const Eigen::Quaterniond quat(s.q(p), s.q(p + 1), s.q(p + 2), s.q(p + 3));
      const Eigen::Matrix3d R = quat.normalized().toRotationMatrix(); // body -> world
      out.T.block<3, 3>(va, v + 3) = R;
      out.T.block<3, 3>(va + 3, v) = Eigen::Matrix3d::Identity();
      const Eigen::Vector3d w = s.alpha.segment<3>(v), vel = s.alpha.segment<3>(v + 3);
      out.bias.segment<3>(va) = R * w.cross(vel); // d/dt (R v) = R (vdot + w x v)
    }
    else if((jt.type() == rbd::Joint::Rev && m->jnt_type[j] == mjJNT_HINGE) ||
            (jt.type() == rbd::Joint::Prism && m->jnt_type[j] == mjJNT_SLIDE))
    {
      out.qpos[static_cast<std::size_t>(qa)] = s.q(p);
      out.T(va, v) = 1;
    }
    else
      return false;
  }
  auto toStd = [](const Eigen::VectorXd & e) { return std::vector<mjtNum>(e.data(), e.data() + e.size()); };
  out.qvel = toStd(out.T * s.alpha);
  out.qacc = toStd(out.T * s.alphaD + out.bias);
  out.qfrc = toStd(out.T * s.tau); // tau = T^T qfrc, T orthogonal
  out.qaccNLE = toStd(out.bias);
  return true;
}

void load(MujocoData & md, const MjState & s)
{
  const std::size_t nq = s.qpos.size(), nv = s.qvel.size();
  std::copy(s.qpos.begin(), s.qpos.end(), md.d->qpos);
  std::copy(s.qvel.begin(), s.qvel.end(), md.d->qvel);
  std::copy(s.qacc.begin(), s.qacc.end(), md.d->qacc);
  std::copy(s.qfrc.begin(), s.qfrc.end(), md.d->qfrc_applied);
  static_cast<void>(nq), static_cast<void>(nv);
}

Eigen::Map<const Eigen::VectorXd> vec(const mjtNum * p, int n)
{
  return Eigen::Map<const Eigen::VectorXd>(p, n);
}

} // namespace

void registerMujoco(const BenchCase & c, CheckLog & log)
{
  // MuJoCo refuses inertias that violate the triangle inequality; it can "balance" them, which
  // changes the model: the agreement checks then decide which cells remain comparable.
  auto md = std::make_shared<MujocoData>();
  std::string note;
  bool balanced = false;
  for(bool balance : {false, true})
  {
    const std::string text = mujocoUrdf(c, balance);
    if(text.empty())
    {
      benchmark::AddCustomContext("peer/mujoco", "n/a: cannot read the URDF");
      return;
    }
    const std::string path = "/tmp/rbdgen_bench_" + std::to_string(getpid()) + "_" + c.name + ".urdf";
    if(FILE * f = std::fopen(path.c_str(), "w"))
    {
      std::fputs(text.c_str(), f);
      std::fclose(f);
    }
    char err[1000] = "";
    md->m = mj_loadXML(path.c_str(), nullptr, err, sizeof err);
    std::remove(path.c_str());
    balanced = balance;
    if(md->m) break;
    std::printf("mujoco: %s: %s\n", c.name.c_str(), err);
    note = std::string("balanceinertia=true (") + err + "), ";
    for(char & ch : note)
      if(ch == '\n') ch = ' ';
    if(balance)
    {
      benchmark::AddCustomContext("peer/mujoco", std::string("n/a: mj_loadXML: ") + err);
      return;
    }
  }
  mjModel * m = md->m;
  for(int k = 0; k < m->nv; ++k) m->dof_armature[k] = m->dof_damping[k] = m->dof_frictionloss[k] = 0;
  for(int k = 0; k < m->njnt; ++k) m->jnt_stiffness[k] = 0;
  m->opt.disableflags |= mjDSBL_CONSTRAINT | mjDSBL_CONTACT | mjDSBL_LIMIT | mjDSBL_EQUALITY | mjDSBL_FRICTIONLOSS |
                         mjDSBL_PASSIVE | mjDSBL_ACTUATION | mjDSBL_SENSOR;
  m->opt.gravity[0] = 0, m->opt.gravity[1] = 0, m->opt.gravity[2] = -9.81;
  md->d = mj_makeData(m);
  const rbd::MultiBody & mb = c.model.mb;
  const int nv = mb.nrDof();
  if(m->nv != nv)
  {
    benchmark::AddCustomContext("peer/mujoco", "n/a: MuJoCo nv " + std::to_string(m->nv) + " != " + std::to_string(nv));
    return;
  }
  for(const State & s : c.pool)
  {
    MjState ms;
    if(!makeState(c, m, s, ms))
    {
      benchmark::AddCustomContext("peer/mujoco", "n/a: joints do not map onto the runtime's");
      return;
    }
    md->pool.push_back(std::move(ms));
  }
  md->jacBody = mj_name2id(m, mjOBJ_BODY, c.jacobianBodyName.c_str());
  md->M.assign(static_cast<std::size_t>(nv * nv), 0);
  md->jacp.assign(static_cast<std::size_t>(3 * nv), 0);
  md->jacr.assign(static_cast<std::size_t>(3 * nv), 0);
  md->res.assign(static_cast<std::size_t>(nv), 0);
  benchmark::AddCustomContext("peer/mujoco", note + "MuJoCo " + std::to_string(mj_version()) + ", " + std::to_string(m->nbody - 1) +
                                                 " bodies after fusing fixed links");

  // --- agreement with the runtime ---------------------------------------------------------------
  mjData * d = md->d;
  double eFK = 0, eV = 0, eID = 0, eG = 0, eC = 0, eH = 0, eFD = 0, eJ = 0, eCoM = 0;
  int posesCompared = 0;
  for(std::size_t k = 0; k < kPeerChecked; ++k)
  {
    const Reference ref = reference(c, c.pool[k]);
    const MjState & s = md->pool[k];
    const Eigen::MatrixXd & T = s.T;
    load(*md, s);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
    for(int b = 0; b < mb.nrBodies(); ++b)
    {
      const int id = mj_name2id(m, mjOBJ_BODY, mb.body(b).name().c_str());
      if(id < 0) continue;
      ++posesCompared;
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->xmat + 9 * id);
      const auto & X = ref.bodyPosW[static_cast<std::size_t>(b)];
      eFK = std::max({eFK, relErr(R.transpose(), X.rotation()), relErr(vec(d->xpos + 3 * id, 3), X.translation())});
      mjtNum v6[6];
      mj_objectVelocity(m, d, mjOBJ_XBODY, id, v6, 1); // [w; v] at the body frame origin, body axes
      eV = std::max(eV, relErr(vec(v6, 6), ref.bodyVelB[static_cast<std::size_t>(b)].vector()));
    }
    mj_rne(m, d, 1, md->res.data());
    eID = std::max(eID, relErr(T.transpose() * vec(md->res.data(), nv), ref.tauID));
    // nonlinear effects: ID at alphaD = 0, i.e. qacc = bias (alpha-dependent change of coordinates)
    std::copy(s.qaccNLE.begin(), s.qaccNLE.end(), d->qacc);
    mj_rne(m, d, 1, md->res.data());
    eC = std::max(eC, relErr(T.transpose() * vec(md->res.data(), nv), ref.tauNLE));
    eCoM = std::max(eCoM, relErr(vec(d->subtree_com, 3), ref.com));
    mj_jacBody(m, d, md->jacp.data(), md->jacr.data(), md->jacBody);
    Eigen::MatrixXd Jmj(6, nv);
    Jmj.topRows(3) = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(md->jacr.data(), 3, nv);
    Jmj.bottomRows(3) = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(md->jacp.data(), 3, nv);
    if(md->jacBody >= 0) eJ = std::max(eJ, relErr(Jmj * T, ref.J));
    mj_crb(m, d);
    mj_fullM(m, md->M.data(), d->qM);
    const Eigen::Map<const Eigen::MatrixXd> M(md->M.data(), nv, nv);
    eH = std::max(eH, relErr(T.transpose() * M * T, ref.H));
    // gravity: the same at qvel = 0
    std::fill(d->qvel, d->qvel + nv, 0.0);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
    mj_rne(m, d, 0, md->res.data());
    eG = std::max(eG, relErr(T.transpose() * vec(md->res.data(), nv), ref.tauGravity));
    load(*md, s);
    mj_forward(m, d);
    eFD = std::max(eFD, relErr(T.transpose() * (vec(d->qacc, nv) - s.bias), ref.alphaDFD));
  }
  const std::string impl = "mujoco";
  const double tol = 1e-9;
  // MuJoCo stores each inertia as principal moments + a frame (eigen-decomposition at load time),
  // which moves dynamics by ~1e-8 relative on some URDFs: same quantity, looser bound.
  const double tolDyn = 1e-6;
  log.add(impl, "fk", eFK, tol, "mj_kinematics; " + std::to_string(posesCompared / static_cast<int>(kPeerChecked)) + " bodies compared");
  log.add(impl, "fk_vel", eV, tol, "mj_kinematics + mj_comPos + mj_comVel");
  log.add(impl, "id", eID, tolDyn, "mj_kinematics + mj_comPos + mj_comVel + mj_rne(acc)", balanced);
  log.add(impl, "gravity", eG, tolDyn, "as nle with qvel = 0", balanced);
  log.add(impl, "nle", eC, tolDyn, "mj_kinematics + mj_comPos + mj_comVel + mj_rne(qacc = bias)", balanced);
  log.add(impl, "mass_matrix", eH, tolDyn, "mj_kinematics + mj_comPos + mj_crb + mj_fullM", balanced);
  log.add(impl, "fd", eFD, tolDyn, "mj_forward, constraints/contacts/passive disabled", balanced);
  if(md->jacBody >= 0) log.add(impl, "jacobian", eJ, tol, "mj_kinematics + mj_comPos + mj_jacBody");
  // Links with mass that never move are fused into MuJoCo's world body, whose mass subtree_com
  // leaves out: CoM n/a there.
  double staticMass = 0; // links that never move (root and fixed descendants): fused into the world
  std::vector<bool> isStatic(static_cast<std::size_t>(mb.nrBodies()), false);
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int p = mb.parent(i);
    isStatic[static_cast<std::size_t>(i)] = mb.joint(i).dof() == 0 && (p < 0 || isStatic[static_cast<std::size_t>(p)]);
    if(isStatic[static_cast<std::size_t>(i)]) staticMass += mb.body(i).inertia().mass();
  }
  if(staticMass == 0)
    log.add(impl, "com", eCoM, tol, "mj_kinematics + mj_comPos (subtree_com of the world)");
  else
    benchmark::AddCustomContext("peer/mujoco/com", "n/a: fixed links with mass are fused into the world body, left out of subtree_com");

  // --- timed cells (only those that agree) ------------------------------------------------------
  const std::string r = c.name;
  auto add = [&](const std::string & algo, auto f) {
    if(log.agrees(impl, algo)) addBench(r, algo, impl, f);
  };
  add("fk", [md](std::size_t k) {
    std::copy(md->pool[k].qpos.begin(), md->pool[k].qpos.end(), md->d->qpos);
    mj_kinematics(md->m, md->d);
    benchmark::DoNotOptimize(md->d->xpos);
    benchmark::ClobberMemory();
  });
  add("fk_vel", [md](std::size_t k) {
    load(*md, md->pool[k]);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    mj_comVel(md->m, md->d);
    benchmark::DoNotOptimize(md->d->cvel);
    benchmark::ClobberMemory();
  });
  add("id", [md](std::size_t k) {
    load(*md, md->pool[k]);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    mj_comVel(md->m, md->d);
    mj_rne(md->m, md->d, 1, md->res.data());
    benchmark::DoNotOptimize(md->res.data());
    benchmark::ClobberMemory();
  });
  add("gravity", [md](std::size_t k) {
    std::copy(md->pool[k].qpos.begin(), md->pool[k].qpos.end(), md->d->qpos);
    std::fill(md->d->qvel, md->d->qvel + md->m->nv, 0.0);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    mj_comVel(md->m, md->d);
    mj_rne(md->m, md->d, 0, md->res.data());
    benchmark::DoNotOptimize(md->res.data());
    benchmark::ClobberMemory();
  });
  add("nle", [md](std::size_t k) {
    load(*md, md->pool[k]);
    std::copy(md->pool[k].qaccNLE.begin(), md->pool[k].qaccNLE.end(), md->d->qacc);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    mj_comVel(md->m, md->d);
    mj_rne(md->m, md->d, 1, md->res.data());
    benchmark::DoNotOptimize(md->res.data());
    benchmark::ClobberMemory();
  });
  add("mass_matrix", [md](std::size_t k) {
    std::copy(md->pool[k].qpos.begin(), md->pool[k].qpos.end(), md->d->qpos);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    mj_crb(md->m, md->d);
    mj_fullM(md->m, md->M.data(), md->d->qM);
    benchmark::DoNotOptimize(md->M.data());
    benchmark::ClobberMemory();
  });
  add("fd", [md](std::size_t k) {
    load(*md, md->pool[k]);
    mj_forward(md->m, md->d);
    benchmark::DoNotOptimize(md->d->qacc);
    benchmark::ClobberMemory();
  });
  add("jacobian", [md](std::size_t k) {
    std::copy(md->pool[k].qpos.begin(), md->pool[k].qpos.end(), md->d->qpos);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    mj_jacBody(md->m, md->d, md->jacp.data(), md->jacr.data(), md->jacBody);
    benchmark::DoNotOptimize(md->jacp.data());
    benchmark::ClobberMemory();
  });
  add("com", [md](std::size_t k) {
    std::copy(md->pool[k].qpos.begin(), md->pool[k].qpos.end(), md->d->qpos);
    mj_kinematics(md->m, md->d);
    mj_comPos(md->m, md->d);
    benchmark::DoNotOptimize(md->d->subtree_com);
    benchmark::ClobberMemory();
  });
}

} // namespace rbdbench
#endif
