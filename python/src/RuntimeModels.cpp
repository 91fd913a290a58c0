#include "RuntimeModels.h"

#include <rbd/CoM.h>
#include <rbd/FK.h>
#include <rbd/FV.h>

namespace rbdgen_py
{

namespace
{

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstVector = Eigen::Map<const Eigen::VectorXd>;

/// Row-major 4x4 [R p; 0 1] of the sva transform X_0_link (R = E^T, p = r).
void writePose(const sva::PTransformd & X, double * out)
{
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> T(out);
  T.setIdentity();
  T.topLeftCorner<3, 3>() = X.rotation().transpose();
  T.topRightCorner<3, 1>() = X.translation();
}

/// G (full nv x coupled nv), one multiplier per row.
Eigen::MatrixXd couplingMatrix(const rbd::parsers::MimicCoupling & c, int nvFull)
{
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(nvFull, c.nv);
  for(std::size_t k = 0; k < c.vSource.size(); ++k) G(static_cast<Eigen::Index>(k), c.vSource[k]) = c.vMultiplier[k];
  return G;
}

/// The entries (row >= col, row by row) of H = G^T H_full G that are not structurally zero: H_full(i, j)
/// can be nonzero only when the joint of dof i supports the joint of dof j or the other way round.
std::vector<std::array<int, 2>> massMatrixPattern(const rbd::MultiBody & mb, const Eigen::MatrixXd & G)
{
  const int n = mb.nrDof();
  std::vector<int> jointOf(static_cast<std::size_t>(n));
  for(int j = 0; j < mb.nrJoints(); ++j)
    for(int d = 0; d < mb.joint(j).dof(); ++d) jointOf[static_cast<std::size_t>(mb.jointPosInDof(j) + d)] = j;
  auto supports = [&mb](int a, int b) { // joint a on the path from the root to joint b
    for(; b >= 0; b = mb.parent(b))
      if(b == a) return true;
    return false;
  };
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n, n);
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const int a = jointOf[static_cast<std::size_t>(i)], b = jointOf[static_cast<std::size_t>(j)];
      if(supports(a, b) || supports(b, a)) full(i, j) = 1;
    }
  const Eigen::MatrixXd coupled = G.cwiseAbs().transpose() * full * G.cwiseAbs();
  std::vector<std::array<int, 2>> entries;
  for(int r = 0; r < G.cols(); ++r)
    for(int c = 0; c <= r; ++c)
      if(coupled(r, c) != 0) entries.push_back({r, c});
  return entries;
}

} // namespace

// --- UrdfModel -----------------------------------------------------------------------------------

UrdfModel::UrdfModel(const std::string & path, bool floatingBase, const std::string & baseLink)
{
  rbd::parsers::ParserOptions opt;
  opt.fixed = !floatingBase;
  opt.baseLink = baseLink;
  const rbd::parsers::ParserResult r = rbd::parsers::fromUrdfFile(path, opt);
  mb_ = r.mb;
  name_ = r.name;
  warnings_ = r.warnings;
  coupling_ = rbd::parsers::coupleMimics(r, path, &warnings_);
  if(coupling_.empty()) coupling_ = rbd::parsers::independentJoints(mb_);
  G_ = couplingMatrix(coupling_, mb_.nrDof());
  massMatrixEntries_ = massMatrixPattern(mb_, G_);
  for(const auto & b : mb_.bodies())
  {
    const auto it = r.bodyBaseTransforms.find(b.name());
    X_body_link_.push_back(it == r.bodyBaseTransforms.end() ? sva::PTransformd::Identity() : it->second.inv());
  }
}

std::vector<std::string> UrdfModel::dofNames() const { return coupling_.dofJoints; }

std::vector<std::string> UrdfModel::bodyNames() const
{
  std::vector<std::string> names;
  for(const auto & b : mb_.bodies()) names.push_back(b.name());
  return names;
}

UrdfModel::Workspace UrdfModel::makeWorkspace() const
{
  Workspace ws{rbd::MultiBodyConfig(mb_),
               rbd::InverseDynamics(mb_),
               rbd::ForwardDynamics(mb_),
               rbd::InverseDynamicsDerivatives(mb_),
               rbd::ForwardDynamicsDerivatives(mb_),
               {},
               {},
               Eigen::VectorXd::Zero(mb_.nrDof()),
               Eigen::VectorXd::Zero(mb_.nrParams()),
               Eigen::VectorXd::Zero(mb_.nrDof())};
  ws.jacobians.resize(static_cast<std::size_t>(nbodies()));
  return ws;
}

void UrdfModel::setState(Workspace & ws, const double * q, const double * v) const
{
  for(std::size_t k = 0; k < coupling_.qSource.size(); ++k) // q_full = G q + o
    ws.qFull(static_cast<Eigen::Index>(k)) = coupling_.qMultiplier[k] * q[coupling_.qSource[k]] + coupling_.qOffset[k];
  rbd::vectorToParam<double>(ws.qFull, ws.mbc.q);
  rbd::forwardKinematics(mb_, ws.mbc);
  if(v)
  {
    rbd::vectorToDof<double>(expandTangent(v), ws.mbc.alpha);
    rbd::forwardVelocity(mb_, ws.mbc);
  }
}

void UrdfModel::forwardKinematics(Workspace & ws, const double * q, double * out) const
{
  setState(ws, q, nullptr);
  for(std::size_t i = 0; i < ws.mbc.bodyPosW.size(); ++i) writePose(X_body_link_[i] * ws.mbc.bodyPosW[i], out + 16 * i);
}

void UrdfModel::inverseDynamics(Workspace & ws, const double * q, const double * v, const double * a, double * tau) const
{
  setState(ws, q, v);
  rbd::vectorToDof<double>(expandTangent(a), ws.mbc.alphaD);
  ws.id.inverseDynamics(mb_, ws.mbc);
  rbd::dofToVector<double>(ws.mbc.jointTorque, ws.tau);
  Eigen::Map<Eigen::VectorXd>(tau, nv()) = G_.transpose() * ws.tau;
}

void UrdfModel::massMatrix(Workspace & ws, const double * q, double * H) const
{
  setState(ws, q, nullptr);
  ws.fd.computeH(mb_, ws.mbc);
  Eigen::Map<RowMatrix>(H, nv(), nv()) = G_.transpose() * ws.fd.H() * G_;
}

Eigen::LDLT<Eigen::MatrixXd> UrdfModel::coupledMassMatrix(Workspace & ws, Eigen::VectorXd & C) const
{
  ws.fd.computeH(mb_, ws.mbc);
  ws.fd.computeC(mb_, ws.mbc);
  C = G_.transpose() * ws.fd.C();
  return Eigen::LDLT<Eigen::MatrixXd>(G_.transpose() * ws.fd.H() * G_);
}

void UrdfModel::forwardDynamics(Workspace & ws, const double * q, const double * v, const double * tau, double * a) const
{
  setState(ws, q, v);
  Eigen::Map<Eigen::VectorXd> out(a, nv());
  if(coupling_.empty())
  {
    rbd::vectorToDof<double>(ConstVector(tau, nv()), ws.mbc.jointTorque);
    ws.fd.forwardDynamics(mb_, ws.mbc); // throws std::runtime_error when the result is not finite
    rbd::dofToVector<double>(ws.mbc.alphaD, ws.tau);
    out = ws.tau;
    return;
  }
  Eigen::VectorXd C;
  const Eigen::LDLT<Eigen::MatrixXd> H = coupledMassMatrix(ws, C);
  out = H.solve(ConstVector(tau, nv()) - C);
  if(!out.allFinite()) throw std::runtime_error("forward dynamics: joint acceleration is not finite");
}

void UrdfModel::jacobian(Workspace & ws, int body, const double * q, double * J) const
{
  setState(ws, q, nullptr);
  const auto k = static_cast<std::size_t>(body);
  auto & jac = ws.jacobians[k];
  // the link origin, in the MultiBody body frame
  if(!jac) jac.emplace(mb_, mb_.body(body).name(), X_body_link_[k].translation());
  jac->fullJacobian(mb_, jac->jacobian(mb_, ws.mbc), ws.fullJacobian);
  Eigen::Map<RowMatrix>(J, 6, nv()) = ws.fullJacobian * G_;
}

void UrdfModel::centerOfMass(Workspace & ws, const double * q, double * c) const
{
  setState(ws, q, nullptr);
  Eigen::Map<Eigen::Vector3d>{c} = rbd::computeCoM(mb_, ws.mbc);
}

void UrdfModel::inverseDynamicsDerivatives(Workspace & ws, const double * q, const double * v, const double * a,
                                           double * dtauDq, double * dtauDv) const
{
  setState(ws, q, v);
  rbd::vectorToDof<double>(expandTangent(a), ws.mbc.alphaD);
  ws.idd.inverseDynamicsDerivatives(mb_, ws.mbc);
  Eigen::Map<RowMatrix>(dtauDq, nv(), nv()) = G_.transpose() * ws.idd.dtauDq() * G_;
  Eigen::Map<RowMatrix>(dtauDv, nv(), nv()) = G_.transpose() * ws.idd.dtauDalpha() * G_;
}

void UrdfModel::forwardDynamicsDerivatives(Workspace & ws, const double * q, const double * v, const double * tau,
                                           double * a, double * daDq, double * daDv, double * Minv) const
{
  setState(ws, q, v);
  if(coupling_.empty())
  {
    rbd::vectorToDof<double>(ConstVector(tau, nv()), ws.mbc.jointTorque);
    ws.fdd.forwardDynamicsDerivatives(mb_, ws.mbc); // throws std::runtime_error when the result is not finite
    Eigen::Map<Eigen::VectorXd>(a, nv()) = ws.fdd.alphaD();
    Eigen::Map<RowMatrix>(daDq, nv(), nv()) = ws.fdd.dalphaDDq();
    Eigen::Map<RowMatrix>(daDv, nv(), nv()) = ws.fdd.dalphaDDalpha();
    Eigen::Map<RowMatrix>(Minv, nv(), nv()) = ws.fdd.Minv();
    return;
  }
  // alphaD = H^-1 (tau - C), d alphaD = -H^-1 G^T dID_full G at alphaD, d alphaD / d tau = H^-1 (coupled H).
  Eigen::VectorXd C;
  const Eigen::LDLT<Eigen::MatrixXd> H = coupledMassMatrix(ws, C);
  const Eigen::VectorXd alphaD = H.solve(ConstVector(tau, nv()) - C);
  if(!alphaD.allFinite()) throw std::runtime_error("forward dynamics: joint acceleration is not finite");
  Eigen::Map<Eigen::VectorXd>(a, nv()) = alphaD;
  rbd::vectorToDof<double>(G_ * alphaD, ws.mbc.alphaD);
  ws.idd.inverseDynamicsDerivatives(mb_, ws.mbc);
  Eigen::Map<RowMatrix>(daDq, nv(), nv()) = -H.solve(G_.transpose() * ws.idd.dtauDq() * G_);
  Eigen::Map<RowMatrix>(daDv, nv(), nv()) = -H.solve(G_.transpose() * ws.idd.dtauDalpha() * G_);
  Eigen::Map<RowMatrix>(Minv, nv(), nv()) = H.solve(Eigen::MatrixXd::Identity(nv(), nv()));
}

// --- SceneModel ----------------------------------------------------------------------------------

SceneModel::SceneModel(const std::string & path)
{
  const rbd::scene::Scene scene = rbd::scene::loadScene(path);
  const rbd::scene::SceneRobot robot = rbd::scene::loadSceneRobot(scene);
  dyn_ = std::make_unique<rbd::scene::SceneDynamics>(robot, scene);
  name_ = scene.name;
  warnings_ = robot.robot.warnings;
  coupling_ = rbd::parsers::coupleMimics(robot.robot, scene.urdf, &warnings_);
  if(coupling_.empty()) coupling_ = rbd::parsers::independentJoints(dyn_->mb());
  G_ = couplingMatrix(coupling_, dyn_->nv());
  massMatrixEntries_ = massMatrixPattern(dyn_->mb(), G_);
  for(const auto & b : dyn_->mb().bodies()) links_.push_back(b.name());
}

Eigen::VectorXd SceneModel::expandConfiguration(const double * q) const
{
  Eigen::VectorXd qf(dyn_->nq());
  for(std::size_t k = 0; k < coupling_.qSource.size(); ++k)
    qf(static_cast<Eigen::Index>(k)) = coupling_.qMultiplier[k] * q[coupling_.qSource[k]] + coupling_.qOffset[k];
  return qf;
}

Eigen::VectorXd SceneModel::coupledAccelerations(const Eigen::VectorXd & qf, const Eigen::VectorXd & vf, const double * tau,
                                                 Eigen::LDLT<Eigen::MatrixXd> & H) const
{
  H.compute(G_.transpose() * dyn_->massMatrix(qf) * G_);
  const Eigen::VectorXd C = G_.transpose() * dyn_->inverseDynamics(qf, vf, Eigen::VectorXd::Zero(dyn_->nv()));
  Eigen::VectorXd a = H.solve(ConstVector(tau, nv()) - C);
  if(!a.allFinite()) throw std::runtime_error("forward dynamics: joint acceleration is not finite");
  return a;
}

void SceneModel::forwardKinematics(Workspace &, const double * q, double * out) const
{
  const Eigen::VectorXd qf = expandConfiguration(q);
  for(std::size_t i = 0; i < links_.size(); ++i) writePose(dyn_->pose(qf, links_[i]), out + 16 * i);
}

void SceneModel::inverseDynamics(Workspace &, const double * q, const double * v, const double * a, double * tau) const
{
  Eigen::Map<Eigen::VectorXd>(tau, nv()) =
      G_.transpose() * dyn_->inverseDynamics(expandConfiguration(q), expandTangent(v), expandTangent(a));
}

void SceneModel::massMatrix(Workspace &, const double * q, double * H) const
{
  Eigen::Map<RowMatrix>(H, nv(), nv()) = G_.transpose() * dyn_->massMatrix(expandConfiguration(q)) * G_;
}

void SceneModel::forwardDynamics(Workspace &, const double * q, const double * v, const double * tau, double * a) const
{
  const Eigen::VectorXd qf = expandConfiguration(q), vf = expandTangent(v);
  if(coupling_.empty())
  {
    const Eigen::VectorXd res = dyn_->forwardDynamics(qf, vf, ConstVector(tau, nv()));
    if(!res.allFinite()) throw std::runtime_error("forward dynamics: joint acceleration is not finite");
    Eigen::Map<Eigen::VectorXd>(a, nv()) = res;
    return;
  }
  Eigen::LDLT<Eigen::MatrixXd> H;
  Eigen::Map<Eigen::VectorXd>(a, nv()) = coupledAccelerations(qf, vf, tau, H);
}

void SceneModel::jacobian(Workspace &, int body, const double * q, double * J) const
{
  Eigen::Map<RowMatrix>(J, 6, nv()) = dyn_->jacobian(expandConfiguration(q), links_[static_cast<std::size_t>(body)]) * G_;
}

void SceneModel::centerOfMass(Workspace &, const double * q, double * c) const
{
  Eigen::Map<Eigen::Vector3d>{c} = dyn_->centerOfMass(expandConfiguration(q));
}

void SceneModel::inverseDynamicsDerivatives(Workspace &, const double * q, const double * v, const double * a,
                                            double * dtauDq, double * dtauDv) const
{
  const auto d = dyn_->inverseDynamicsDerivatives(expandConfiguration(q), expandTangent(v), expandTangent(a));
  Eigen::Map<RowMatrix>(dtauDq, nv(), nv()) = G_.transpose() * d.dtauDq * G_;
  Eigen::Map<RowMatrix>(dtauDv, nv(), nv()) = G_.transpose() * d.dtauDalpha * G_;
}

void SceneModel::forwardDynamicsDerivatives(Workspace &, const double * q, const double * v, const double * tau,
                                            double * a, double * daDq, double * daDv, double * Minv) const
{
  const Eigen::VectorXd qf = expandConfiguration(q), vf = expandTangent(v);
  if(coupling_.empty())
  {
    const auto d = dyn_->forwardDynamicsDerivatives(qf, vf, ConstVector(tau, nv()));
    if(!d.alphaD.allFinite()) throw std::runtime_error("forward dynamics: joint acceleration is not finite");
    Eigen::Map<Eigen::VectorXd>(a, nv()) = d.alphaD;
    Eigen::Map<RowMatrix>(daDq, nv(), nv()) = d.dalphaDDq;
    Eigen::Map<RowMatrix>(daDv, nv(), nv()) = d.dalphaDDalpha;
    Eigen::Map<RowMatrix>(Minv, nv(), nv()) = d.Minv;
    return;
  }
  // d alphaD = -H^-1 G^T dID_full G at alphaD, d alphaD / d tau = H^-1 (coupled H).
  Eigen::LDLT<Eigen::MatrixXd> H;
  const Eigen::VectorXd alphaD = coupledAccelerations(qf, vf, tau, H);
  Eigen::Map<Eigen::VectorXd>(a, nv()) = alphaD;
  const auto d = dyn_->inverseDynamicsDerivatives(qf, vf, G_ * alphaD);
  Eigen::Map<RowMatrix>(daDq, nv(), nv()) = -H.solve(G_.transpose() * d.dtauDq * G_);
  Eigen::Map<RowMatrix>(daDv, nv(), nv()) = -H.solve(G_.transpose() * d.dtauDalpha * G_);
  Eigen::Map<RowMatrix>(Minv, nv(), nv()) = H.solve(Eigen::MatrixXd::Identity(nv(), nv()));
}

} // namespace rbdgen_py
