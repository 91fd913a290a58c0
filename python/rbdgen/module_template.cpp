// A robot's generated dynamics (namespace @NAME@) as a Python module, written by rbdgen.compile:
// @NAME@ is the module name, @ROBOT@ the robot's name, @HAS_FD@ whether the header has forward
// dynamics. The class is the one of rbdgen.Robot (rbdgen_py/bind.hpp), on the generated functions.
#include <@NAME@/dynamics.hpp>

#include <rbdgen_py/bind.hpp>

namespace @NAME@_ns
{

namespace g = ::@NAME@;

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

  std::string name_ = "@ROBOT@";
};

} // namespace @NAME@_ns

PYBIND11_MODULE(@NAME@, m)
{
  m.doc() = "rbdgen.compile: the generated dynamics of '@ROBOT@'";
  using @NAME@_ns::GeneratedModel;
  rbdgen_py::bindRobot<GeneratedModel>(m, "CompiledRobot",
                                       "A robot evaluated by its generated code (rbdgen.compile); the API of rbdgen.Robot.", true);
  m.def("robot", [] { return rbdgen_py::Robot<GeneratedModel>(std::make_shared<const GeneratedModel>()); });
}
