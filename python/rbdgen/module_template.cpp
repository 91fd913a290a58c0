// A robot's generated dynamics as a Python module, written by rbdgen.compile and by
// generate_robot_dynamics(... PYTHON_MODULE name) (cmake/RbdgenPythonModule.cmake), which replace
// these words between @ signs: MODULE (the module name), NS (the namespace of the generated header
// NS/dynamics.hpp), ROBOT_STRING (the robot's name as a C++ string literal), HAS_FD and
// HAS_DERIVATIVES (0 or 1: whether the header has forward_dynamics, and the derivatives).
// The class is the one of rbdgen.Robot (rbdgen_py/bind.hpp), on the generated functions.
#include <@NS@/dynamics.hpp>

#include <rbdgen_py/bind.hpp>

namespace @MODULE@_ns
{

namespace g = ::@NS@;

/// Row-major R x C map (an Eigen column vector cannot be declared row-major; same layout anyway).
template<int R, int C>
using RowMajorMap = Eigen::Map<Eigen::Matrix<double, R, C, (C == 1 && R != 1) ? Eigen::ColMajor : Eigen::RowMajor>>;
using Q = g::Config<double>;
using V = g::Tangent<double>;

struct GeneratedModel
{
  struct Workspace
  {
  };

  int nq() const { return g::nq; }
  int nv() const { return g::nv; }
  int nbodies() const { return g::nbodies; }
  bool hasForwardDynamics() const { return @HAS_FD@; }
  const std::string & name() const { return name_; }
  std::vector<std::string> dofNames() const { return {g::dof_names.begin(), g::dof_names.end()}; }
  std::vector<std::string> bodyNames() const { return {g::body_names.begin(), g::body_names.end()}; }
  Workspace makeWorkspace() const { return {}; }

  void forwardKinematics(Workspace &, const double * q, double * out) const
  {
    const auto poses = g::forward_kinematics<double>(Q(Eigen::Map<const Q>(q)));
    for(std::size_t i = 0; i < poses.size(); ++i)
    {
      RowMajorMap<4, 4> T(out + 16 * i);
      T.setIdentity();
      T.topLeftCorner<3, 3>() = poses[i].rotation.transpose();
      T.topRightCorner<3, 1>() = poses[i].translation;
    }
  }
  void inverseDynamics(Workspace &, const double * q, const double * v, const double * a, double * tau) const
  {
    Eigen::Map<V>{tau} = g::inverse_dynamics<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                      V(Eigen::Map<const V>(a)));
  }
  void massMatrix(Workspace &, const double * q, double * H) const
  {
    RowMajorMap<g::nv, g::nv>{H} = g::mass_matrix<double>(Q(Eigen::Map<const Q>(q)));
  }
  void forwardDynamics([[maybe_unused]] Workspace & ws, [[maybe_unused]] const double * q,
                       [[maybe_unused]] const double * v, [[maybe_unused]] const double * tau,
                       [[maybe_unused]] double * a) const
  {
#if @HAS_FD@
    Eigen::Map<V>{a} = g::forward_dynamics<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                    V(Eigen::Map<const V>(tau)));
#endif
  }
  void jacobian(Workspace &, int body, const double * q, double * J) const
  {
    RowMajorMap<6, g::nv>{J} = g::jacobian<double>(static_cast<g::Body>(body), Q(Eigen::Map<const Q>(q)));
  }
  void centerOfMass(Workspace &, const double * q, double * c) const
  {
    Eigen::Map<Eigen::Vector3d>{c} = g::center_of_mass<double>(Q(Eigen::Map<const Q>(q)));
  }

  bool hasDerivatives() const { return @HAS_DERIVATIVES@; }
  std::string noDerivativesReason() const { return "generated without derivatives"; }
  void inverseDynamicsDerivatives([[maybe_unused]] Workspace & ws, [[maybe_unused]] const double * q,
                                  [[maybe_unused]] const double * v, [[maybe_unused]] const double * a,
                                  [[maybe_unused]] double * dtauDq, [[maybe_unused]] double * dtauDv) const
  {
#if @HAS_DERIVATIVES@
    const auto d = g::inverse_dynamics_derivatives<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                           V(Eigen::Map<const V>(a)));
    RowMajorMap<g::nv, g::nv>{dtauDq} = d.dtau_dq;
    RowMajorMap<g::nv, g::nv>{dtauDv} = d.dtau_dalpha;
#endif
  }
  void forwardDynamicsDerivatives([[maybe_unused]] Workspace & ws, [[maybe_unused]] const double * q,
                                  [[maybe_unused]] const double * v, [[maybe_unused]] const double * tau,
                                  [[maybe_unused]] double * a, [[maybe_unused]] double * daDq,
                                  [[maybe_unused]] double * daDv, [[maybe_unused]] double * Minv) const
  {
#if @HAS_DERIVATIVES@ && @HAS_FD@
    const auto d = g::forward_dynamics_derivatives<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                           V(Eigen::Map<const V>(tau)));
    Eigen::Map<V>{a} = d.alphaD;
    RowMajorMap<g::nv, g::nv>{daDq} = d.dalphaD_dq;
    RowMajorMap<g::nv, g::nv>{daDv} = d.dalphaD_dalpha;
    RowMajorMap<g::nv, g::nv>{Minv} = d.Minv;
#endif
  }

  std::string name_ = @ROBOT_STRING@;
};

} // namespace @MODULE@_ns

PYBIND11_MODULE(@MODULE@, m)
{
  m.doc() = "The generated dynamics of the robot " @ROBOT_STRING@ " (rbdgen); robot() gives its object";
  using @MODULE@_ns::GeneratedModel;
  rbdgen_py::bindRobot<GeneratedModel>(m, "CompiledRobot",
                                       "A robot evaluated by its generated code (rbdgen.compile); the API of rbdgen.Robot.", true);
  m.def("robot", [] { return rbdgen_py::Robot<GeneratedModel>(std::make_shared<const GeneratedModel>()); });
}
