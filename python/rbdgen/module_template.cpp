// A robot's generated dynamics as a Python module, written by rbdgen.compile and by
// generate_robot_dynamics(... PYTHON_MODULE name) (cmake/RbdgenPythonModule.cmake), which replace
// these words between @ signs: MODULE (the module name), NS (the namespace of the generated header
// NS/dynamics.hpp), ROBOT_STRING (the robot's name as a C++ string literal), HAS_FD and
// HAS_DERIVATIVES (0 or 1: whether the header has forward_dynamics, and the derivatives) and
// WRENCHES (1 for a scene with external wrenches: held at zero here, as rbdgen.Robot.from_scene does).
// The class is the one of rbdgen.Robot (rbdgen_py/bind.hpp), on the generated functions: a single
// state by the single-state function, the states of a batch by the batch API NS/batch.hpp (SIMD
// packs of the native width; bind.hpp hands over blocks of consecutive states, on its threads).
#include <@NS@/batch.hpp>

#include <rbdgen_py/bind.hpp>

namespace @MODULE@_ns
{

namespace g = ::@NS@;

/// Row-major R x C map (an Eigen column vector cannot be declared row-major; same layout anyway).
template<int R, int C>
using RowMajorMap = Eigen::Map<Eigen::Matrix<double, R, C, (C == 1 && R != 1) ? Eigen::ColMajor : Eigen::RowMajor>>;
using Q = g::Config<double>;
using V = g::Tangent<double>;

#if @WRENCHES@
/// The scene's external wrenches, zero: the last argument of ID, FD and their derivatives.
inline g::Wrenches<double> noWrenches()
{
  g::Wrenches<double> w;
  for(auto & x : w) x.setZero();
  return w;
}
#define RBDGEN_PY_WRENCHES , noWrenches()
#define RBDGEN_PY_BATCH_WRENCHES , nullptr
#else
#define RBDGEN_PY_WRENCHES
#define RBDGEN_PY_BATCH_WRENCHES
#endif

struct GeneratedModel
{
  struct Workspace
  {
  };
  /// Each function takes the number of states n last: 0 for one state (the single-state function),
  /// n >= 1 for n consecutive states (the batch API, on the calling thread).
  static constexpr bool kBatched = true;

  int nq() const { return g::nq; }
  int nv() const { return g::nv; }
  int nbodies() const { return g::nbodies; }
  bool hasForwardDynamics() const { return @HAS_FD@; }
  const std::string & name() const { return name_; }
  std::vector<std::string> dofNames() const { return {g::dof_names.begin(), g::dof_names.end()}; }
  std::vector<std::string> bodyNames() const { return {g::body_names.begin(), g::body_names.end()}; }
  Workspace makeWorkspace() const { return {}; }

  void forwardKinematics(Workspace &, const double * q, double * out, std::ptrdiff_t n) const
  {
    if(n > 0) return g::batch::forward_kinematics<double>(q, out, static_cast<std::size_t>(n));
    const auto poses = g::forward_kinematics<double>(Q(Eigen::Map<const Q>(q)));
    for(std::size_t i = 0; i < poses.size(); ++i)
    {
      RowMajorMap<4, 4> T(out + 16 * i);
      T.setIdentity();
      T.topLeftCorner<3, 3>() = poses[i].rotation.transpose();
      T.topRightCorner<3, 1>() = poses[i].translation;
    }
  }
  void inverseDynamics(Workspace &, const double * q, const double * v, const double * a, double * tau, std::ptrdiff_t n) const
  {
    if(n > 0) return g::batch::inverse_dynamics<double>(q, v, a RBDGEN_PY_BATCH_WRENCHES, tau, static_cast<std::size_t>(n));
    Eigen::Map<V>{tau} = g::inverse_dynamics<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                      V(Eigen::Map<const V>(a)) RBDGEN_PY_WRENCHES);
  }
  void massMatrix(Workspace &, const double * q, double * H, std::ptrdiff_t n) const
  {
    if(n > 0) return g::batch::mass_matrix<double>(q, H, static_cast<std::size_t>(n));
    RowMajorMap<g::nv, g::nv>{H} = g::mass_matrix<double>(Q(Eigen::Map<const Q>(q)));
  }
  std::vector<std::array<int, 2>> massMatrixEntries() const
  {
    std::vector<std::array<int, 2>> entries;
    for(const auto & e : g::mass_matrix_entries) entries.push_back({e.row, e.col});
    return entries;
  }
  void massMatrixPacked(Workspace &, const double * q, double * Hp, std::ptrdiff_t n) const
  {
    if(n > 0) return g::batch::mass_matrix_packed<double>(q, Hp, static_cast<std::size_t>(n));
    const auto packed = g::mass_matrix_packed<double>(Q(Eigen::Map<const Q>(q)));
    std::copy(packed.begin(), packed.end(), Hp);
  }
  void forwardDynamics([[maybe_unused]] Workspace & ws, [[maybe_unused]] const double * q,
                       [[maybe_unused]] const double * v, [[maybe_unused]] const double * tau,
                       [[maybe_unused]] double * a, [[maybe_unused]] std::ptrdiff_t n) const
  {
#if @HAS_FD@
    if(n > 0) return g::batch::forward_dynamics<double>(q, v, tau RBDGEN_PY_BATCH_WRENCHES, a, static_cast<std::size_t>(n));
    Eigen::Map<V>{a} = g::forward_dynamics<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                    V(Eigen::Map<const V>(tau)) RBDGEN_PY_WRENCHES);
#endif
  }
  void jacobian(Workspace &, int body, const double * q, double * J, std::ptrdiff_t n) const
  {
    if(n > 0) return g::batch::jacobian<double>(static_cast<g::Body>(body), q, J, static_cast<std::size_t>(n));
    RowMajorMap<6, g::nv>{J} = g::jacobian<double>(static_cast<g::Body>(body), Q(Eigen::Map<const Q>(q)));
  }
  void centerOfMass(Workspace &, const double * q, double * c, std::ptrdiff_t n) const
  {
    if(n > 0) return g::batch::center_of_mass<double>(q, c, static_cast<std::size_t>(n));
    Eigen::Map<Eigen::Vector3d>{c} = g::center_of_mass<double>(Q(Eigen::Map<const Q>(q)));
  }

  bool hasDerivatives() const { return @HAS_DERIVATIVES@; }
  std::string noDerivativesReason() const { return "generated without derivatives"; }
  void inverseDynamicsDerivatives([[maybe_unused]] Workspace & ws, [[maybe_unused]] const double * q,
                                  [[maybe_unused]] const double * v, [[maybe_unused]] const double * a,
                                  [[maybe_unused]] double * dtauDq, [[maybe_unused]] double * dtauDv,
                                  [[maybe_unused]] std::ptrdiff_t n) const
  {
#if @HAS_DERIVATIVES@
    if(n > 0)
      return g::batch::inverse_dynamics_derivatives<double>(q, v, a RBDGEN_PY_BATCH_WRENCHES, dtauDq, dtauDv,
                                                            static_cast<std::size_t>(n));
    const auto d = g::inverse_dynamics_derivatives<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                           V(Eigen::Map<const V>(a)) RBDGEN_PY_WRENCHES);
    RowMajorMap<g::nv, g::nv>{dtauDq} = d.dtau_dq;
    RowMajorMap<g::nv, g::nv>{dtauDv} = d.dtau_dalpha;
#endif
  }
  void forwardDynamicsDerivatives([[maybe_unused]] Workspace & ws, [[maybe_unused]] const double * q,
                                  [[maybe_unused]] const double * v, [[maybe_unused]] const double * tau,
                                  [[maybe_unused]] double * a, [[maybe_unused]] double * daDq,
                                  [[maybe_unused]] double * daDv, [[maybe_unused]] double * Minv,
                                  [[maybe_unused]] std::ptrdiff_t n) const
  {
#if @HAS_DERIVATIVES@ && @HAS_FD@
    if(n > 0)
      return g::batch::forward_dynamics_derivatives<double>(q, v, tau RBDGEN_PY_BATCH_WRENCHES, a, daDq, daDv, Minv,
                                                            static_cast<std::size_t>(n));
    const auto d = g::forward_dynamics_derivatives<double>(Q(Eigen::Map<const Q>(q)), V(Eigen::Map<const V>(v)),
                                                           V(Eigen::Map<const V>(tau)) RBDGEN_PY_WRENCHES);
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
