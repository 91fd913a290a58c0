#pragma once
// The runtime behind rbdgen.Robot, in the Model interface of rbdgen_py/bind.hpp:
//  - UrdfModel: a URDF loaded by the loader, evaluated by rbd:: algorithms (double), one
//    MultiBodyConfig + algorithm objects per thread (Workspace);
//  - SceneModel: a scene's robot evaluated by rbd::scene::SceneDynamics (its gravity, damping,
//    friction, armature, contacts; no external wrenches; derivatives included), reentrant, so its
//    Workspace is empty.
// A URDF's mimic joints are coupled as in the generated code (rbd/parsers/MimicCoupling.h): the
// coordinates exclude them, q_full = G q + o, results are the full model's projected (tau = G^T tau_full,
// H = G^T H_full G, J = J_full G, forward dynamics through the coupled H).
// Poses and Jacobians are those of the URDF link frames (= the MultiBody body frames except for
// bodies moved by backward joints, see ParserResult::bodyBaseTransforms), as in the generated code.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Cholesky>

#include <rbd/FD.h>
#include <rbd/FDDerivatives.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>
#include <rbd/Jacobian.h>
#include <rbd/MultiBody.h>
#include <rbd/MultiBodyConfig.h>
#include <rbd/parsers/MimicCoupling.h>
#include <rbd/parsers/urdf.h>
#include <rbd/scene/SceneDynamics.h>

namespace rbdgen_py
{

class UrdfModel
{
public:
  struct Workspace
  {
    rbd::MultiBodyConfig mbc;
    rbd::InverseDynamics id;
    rbd::ForwardDynamics fd;
    rbd::InverseDynamicsDerivatives idd;
    rbd::ForwardDynamicsDerivatives fdd;
    std::vector<std::optional<rbd::Jacobian>> jacobians; ///< per body, made on first use
    Eigen::MatrixXd fullJacobian;
    Eigen::VectorXd tau;
    Eigen::VectorXd qFull, vFull; ///< expanded coordinates (mimic joints included)
  };

  UrdfModel(const std::string & path, bool floatingBase, const std::string & baseLink);

  int nq() const { return coupling_.nq; }
  int nv() const { return coupling_.nv; }
  int nbodies() const { return mb_.nrBodies(); }
  bool hasForwardDynamics() const { return true; }
  const std::string & name() const { return name_; }
  std::vector<std::string> dofNames() const;
  std::vector<std::string> bodyNames() const;

  Workspace makeWorkspace() const;
  void forwardKinematics(Workspace & ws, const double * q, double * out) const;
  void inverseDynamics(Workspace & ws, const double * q, const double * v, const double * a, double * tau) const;
  void massMatrix(Workspace & ws, const double * q, double * H) const;
  /// (row, col) of the entries of H that are not structurally zero, row >= col, row by row.
  const std::vector<std::array<int, 2>> & massMatrixEntries() const { return massMatrixEntries_; }
  void forwardDynamics(Workspace & ws, const double * q, const double * v, const double * tau, double * a) const;
  void jacobian(Workspace & ws, int body, const double * q, double * J) const;
  void centerOfMass(Workspace & ws, const double * q, double * c) const;
  bool hasDerivatives() const { return true; }
  std::string noDerivativesReason() const { return {}; }
  void inverseDynamicsDerivatives(Workspace & ws, const double * q, const double * v, const double * a, double * dtauDq,
                                  double * dtauDv) const;
  void forwardDynamicsDerivatives(Workspace & ws, const double * q, const double * v, const double * tau, double * a,
                                  double * daDq, double * daDv, double * Minv) const;

  const std::vector<std::string> & warnings() const { return warnings_; }

private:
  /// q (and v when given) expanded into ws.mbc, then forward kinematics (and velocity).
  void setState(Workspace & ws, const double * q, const double * v) const;
  /// G x for a coupled tangent vector x (mimic joints' entries filled in).
  Eigen::VectorXd expandTangent(const double * x) const { return G_ * Eigen::Map<const Eigen::VectorXd>(x, nv()); }
  /// Forward dynamics of the coupled system at the state in ws.mbc (velocity set): G^T H G and G^T C.
  Eigen::LDLT<Eigen::MatrixXd> coupledMassMatrix(Workspace & ws, Eigen::VectorXd & C) const;

  rbd::MultiBody mb_;
  rbd::parsers::MimicCoupling coupling_;
  Eigen::MatrixXd G_; ///< full nv x coupled nv
  std::vector<std::array<int, 2>> massMatrixEntries_;
  std::string name_;
  std::vector<sva::PTransformd> X_body_link_; ///< per body: MultiBody body frame -> URDF link frame
  std::vector<std::string> warnings_;
};

/// A scene (rbd::scene::SceneDynamics: the scene's effects on every joint) with its URDF's mimic
/// joints coupled as in the generated scene header: each function of the full scene at the expanded
/// state, projected (tau = G^T tau_full, H = G^T (H_full + A) G, J = J_full G), forward dynamics
/// through the coupled H.
class SceneModel
{
public:
  struct Workspace
  {
  };

  explicit SceneModel(const std::string & path);

  int nq() const { return coupling_.nq; }
  int nv() const { return coupling_.nv; }
  int nbodies() const { return static_cast<int>(links_.size()); }
  bool hasForwardDynamics() const { return true; }
  const std::string & name() const { return name_; }
  std::vector<std::string> dofNames() const { return coupling_.dofJoints; }
  std::vector<std::string> bodyNames() const { return links_; }

  Workspace makeWorkspace() const { return {}; }
  void forwardKinematics(Workspace &, const double * q, double * out) const;
  void inverseDynamics(Workspace &, const double * q, const double * v, const double * a, double * tau) const;
  void massMatrix(Workspace &, const double * q, double * H) const;
  /// (row, col) of the entries of H that are not structurally zero, row >= col, row by row.
  const std::vector<std::array<int, 2>> & massMatrixEntries() const { return massMatrixEntries_; }
  void forwardDynamics(Workspace &, const double * q, const double * v, const double * tau, double * a) const;
  void jacobian(Workspace &, int body, const double * q, double * J) const;
  void centerOfMass(Workspace &, const double * q, double * c) const;
  /// Every effect of the scene, contacts included (SceneDynamics::inverseDynamicsDerivatives).
  bool hasDerivatives() const { return true; }
  std::string noDerivativesReason() const { return {}; }
  void inverseDynamicsDerivatives(Workspace &, const double * q, const double * v, const double * a, double * dtauDq,
                                  double * dtauDv) const;
  void forwardDynamicsDerivatives(Workspace &, const double * q, const double * v, const double * tau, double * a,
                                  double * daDq, double * daDv, double * Minv) const;

  const std::vector<std::string> & warnings() const { return warnings_; }

private:
  /// q_full = G q + o, and G x for a coupled tangent vector x.
  Eigen::VectorXd expandConfiguration(const double * q) const;
  Eigen::VectorXd expandTangent(const double * x) const { return G_ * Eigen::Map<const Eigen::VectorXd>(x, nv()); }
  /// alphaD of the coupled system: (G^T H G) alphaD = tau - G^T ID_full(q, G v, 0); also its H.
  Eigen::VectorXd coupledAccelerations(const Eigen::VectorXd & qf, const Eigen::VectorXd & vf, const double * tau,
                                       Eigen::LDLT<Eigen::MatrixXd> & H) const;

  std::unique_ptr<rbd::scene::SceneDynamics> dyn_;
  rbd::parsers::MimicCoupling coupling_;
  Eigen::MatrixXd G_; ///< full nv x coupled nv
  std::vector<std::array<int, 2>> massMatrixEntries_;
  std::string name_;
  std::vector<std::string> links_;
  std::vector<std::string> warnings_;
};

/// rbdgen.Robot: either model, one Python class.
class RuntimeModel
{
public:
  struct Workspace
  {
    std::variant<UrdfModel::Workspace, SceneModel::Workspace> w;
  };

private:
  // (before their use: their return types are deduced)
  template<class F>
  decltype(auto) call(F && f) const
  {
    return std::visit(std::forward<F>(f), m_);
  }
  /// f(model, its workspace)
  template<class F>
  void with(Workspace & ws, F && f) const
  {
    std::visit(
        [&](const auto & m) {
          using M = std::decay_t<decltype(m)>;
          f(m, std::get<typename M::Workspace>(ws.w));
        },
        m_);
  }

public:
  template<class M, class... A>
  explicit RuntimeModel(std::in_place_type_t<M> t, A &&... args) : m_(t, std::forward<A>(args)...)
  {
  }

  int nq() const { return call([](const auto & m) { return m.nq(); }); }
  int nv() const { return call([](const auto & m) { return m.nv(); }); }
  int nbodies() const { return call([](const auto & m) { return m.nbodies(); }); }
  bool hasForwardDynamics() const { return true; }
  const std::string & name() const { return call([](const auto & m) -> const std::string & { return m.name(); }); }
  std::vector<std::string> dofNames() const { return call([](const auto & m) { return m.dofNames(); }); }
  std::vector<std::string> bodyNames() const { return call([](const auto & m) { return m.bodyNames(); }); }
  bool isScene() const { return std::holds_alternative<SceneModel>(m_); }

  Workspace makeWorkspace() const
  {
    return call([](const auto & m) { return Workspace{m.makeWorkspace()}; });
  }
  void forwardKinematics(Workspace & ws, const double * q, double * out) const
  {
    with(ws, [&](const auto & m, auto & w) { m.forwardKinematics(w, q, out); });
  }
  void inverseDynamics(Workspace & ws, const double * q, const double * v, const double * a, double * tau) const
  {
    with(ws, [&](const auto & m, auto & w) { m.inverseDynamics(w, q, v, a, tau); });
  }
  void massMatrix(Workspace & ws, const double * q, double * H) const
  {
    with(ws, [&](const auto & m, auto & w) { m.massMatrix(w, q, H); });
  }
  std::vector<std::array<int, 2>> massMatrixEntries() const
  {
    return call([](const auto & m) { return m.massMatrixEntries(); });
  }
  /// The entries of massMatrixEntries(), in its order, from the model's mass matrix.
  void massMatrixPacked(Workspace & ws, const double * q, double * Hp) const
  {
    with(ws, [&](const auto & m, auto & w) {
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> H(m.nv(), m.nv());
      m.massMatrix(w, q, H.data());
      std::size_t k = 0;
      for(const auto & [r, c] : m.massMatrixEntries()) Hp[k++] = H(r, c);
    });
  }
  void forwardDynamics(Workspace & ws, const double * q, const double * v, const double * tau, double * a) const
  {
    with(ws, [&](const auto & m, auto & w) { m.forwardDynamics(w, q, v, tau, a); });
  }
  void jacobian(Workspace & ws, int body, const double * q, double * J) const
  {
    with(ws, [&](const auto & m, auto & w) { m.jacobian(w, body, q, J); });
  }
  void centerOfMass(Workspace & ws, const double * q, double * c) const
  {
    with(ws, [&](const auto & m, auto & w) { m.centerOfMass(w, q, c); });
  }
  bool hasDerivatives() const { return call([](const auto & m) { return m.hasDerivatives(); }); }
  std::string noDerivativesReason() const { return call([](const auto & m) { return m.noDerivativesReason(); }); }
  void inverseDynamicsDerivatives(Workspace & ws, const double * q, const double * v, const double * a, double * dtauDq,
                                  double * dtauDv) const
  {
    with(ws, [&](const auto & m, auto & w) { m.inverseDynamicsDerivatives(w, q, v, a, dtauDq, dtauDv); });
  }
  void forwardDynamicsDerivatives(Workspace & ws, const double * q, const double * v, const double * tau, double * a,
                                  double * daDq, double * daDv, double * Minv) const
  {
    with(ws, [&](const auto & m, auto & w) { m.forwardDynamicsDerivatives(w, q, v, tau, a, daDq, daDv, Minv); });
  }

private:
  std::variant<UrdfModel, SceneModel> m_;
};

} // namespace rbdgen_py
