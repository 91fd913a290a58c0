// step_derivatives of a scene header: per-joint blocks of the derivatives of q (+) w (Euler
// integrators) or of the maps between q in R^nq and its tangent (RK4), each emitted with the
// joint's constant indices; the rest is templates/scene_step_derivatives.hpp.in.
#include "StepDerivatives.h"

#include <map>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "../passes/JointKernels.h"
#include "Template.h"

namespace rbdgen::emit
{

namespace
{

using rbd::JointType;

void trimNewline(std::string & s)
{
  if(!s.empty() && s.back() == '\n') s.pop_back();
}

/// The Euler integrators' q+ rows [v, v + n) of A and B (indent: the lines' indentation). semi
/// (q+ = q (+) dt alpha+): A_q = scale A_alpha+ + Dq, B_q = scale B_alpha+ (plusDq: how Dq is added
/// to A's block); explicit: A(q, q) = Dq, A(q, alpha) = dt Dw (setDq, setDw: the two assignments).
std::string qRows(int n, int v, bool semi, const char * indent, const char * scale, const char * plusDq, const char * setDq,
                  const char * setDw)
{
  if(semi)
    return fmt::format("{2}d.A.template middleRows<{0}>({1}) = {3} * d.A.template middleRows<{0}>(nv + {1});\n"
                       "{2}d.A.template block<{0}, {0}>({1}, {1}){4};\n"
                       "{2}d.B.template middleRows<{0}>({1}) = {3} * d.B.template middleRows<{0}>(nv + {1});\n",
                       n, v, indent, scale, plusDq);
  return fmt::format("{2}d.A.template block<{0}, {0}>({1}, {1}){3};\n"
                     "{2}d.A.template block<{0}, {0}>({1}, nv + {1}){4};\n",
                     n, v, indent, setDq, setDw);
}

/// Euler integrators, joints whose q (+) w is q + w (revolute, prismatic, cylindrical): Dq = Dw = 1
/// on the n consecutive dofs from v, one block operation for the run. semi: rows = dt (alpha+ rows)
/// + [1 0 0]; explicit: [1, dt 1, 0] (the rows are zero before).
std::string vectorRows(const std::vector<std::string> & names, int v, int n, bool semi)
{
  std::string list;
  for(const auto & name : names) list += (list.empty() ? "" : ", ") + name;
  std::string s = fmt::format("  // {} (q (+) w = q + w: Dq = Dw = 1)\n", list);
  return s + qRows(n, v, semi, "  ", "dt", ".diagonal().array() += S(1)", ".diagonal().setConstant(S(1))",
                   ".diagonal().setConstant(dt)");
}

/// Euler integrators: the q+ rows of a spherical, free or planar joint. semi: Dq [1 0 0] + dt Dw
/// (alpha+ rows), the alpha+ rows being already in A and B; explicit: [Dq, dt Dw, 0].
std::string groupRows(const MovingJoint & mj, bool semi)
{
  const int v = mj.vIndex, n = mj.nv;
  std::string s = fmt::format("  // {} ({})\n", mj.name, passes::describeJoint(mj));
  const char * fn = mj.joint.type() == JointType::Free ? "free" : (mj.joint.type() == JointType::Planar ? "planar" : "spherical");
  s += fmt::format("  {{\n"
                   "    Eigen::Matrix<S, {0}, {0}> Dq, Dw;\n"
                   "    detail::{1}_step_blocks<S>(w.data() + {2}, Dq, Dw);\n",
                   n, fn, v);
  if(semi) s += fmt::format("    const Eigen::Matrix<S, {0}, {0}> dtDw = dt * Dw;\n", n);
  return s + qRows(n, v, semi, "    ", "dtDw", " += Dq", " = Dq", " = dt * Dw") + "  }\n";
}

/// Every joint's q+ rows, runs of consecutive vector joints merged.
std::string eulerRows(const RobotModel & rm, bool semi)
{
  std::string out;
  std::vector<std::string> run;
  int runStart = 0, runEnd = 0;
  auto flush = [&] {
    if(!run.empty()) out += vectorRows(run, runStart, runEnd - runStart, semi);
    run.clear();
  };
  for(const MovingJoint & mj : rm.joints)
  {
    switch(mj.joint.type())
    {
      case JointType::Rev:
      case JointType::Prism:
      case JointType::Cylindrical:
        if(run.empty() || mj.vIndex != runEnd)
        {
          flush();
          runStart = mj.vIndex;
        }
        run.push_back(mj.name);
        runEnd = mj.vIndex + mj.nv;
        break;
      case JointType::Spherical:
      case JointType::Free:
      case JointType::Planar:
        flush();
        out += groupRows(mj, semi);
        break;
      default:
        throw std::logic_error("joint '" + mj.name + "': no integration rule for its type");
    }
  }
  flush();
  return out;
}

/// RK4: the lines of tangent_map, tangent_projection and configuration_derivative_change for mj.
struct Rk4Lines
{
  std::string map, projection, change;
};

void rk4Lines(const MovingJoint & mj, Rk4Lines & L)
{
  const int qi = mj.qIndex, vi = mj.vIndex;
  const std::string head = fmt::format("  // {}\n", mj.name);
  L.map += head;
  L.projection += head;
  L.change += head;
  switch(mj.joint.type())
  {
    case JointType::Rev:
    case JointType::Prism:
    case JointType::Cylindrical:
      for(int c = 0; c < mj.nv; ++c)
      {
        L.map += fmt::format("  P({}, {}) = S(1);\n", qi + c, vi + c);
        L.projection += fmt::format("  out.row({}) = Y.row({});\n", vi + c, qi + c);
        L.change += fmt::format("  out.row({}) = X.row({});\n", qi + c, vi + c);
      }
      return;
    case JointType::Spherical:
    case JointType::Free:
    {
      // quaternion rows: d/dt quat = quat (x) [0; w] / 2 with quat as given
      L.map += fmt::format("  P.template block<4, 3>({}, {}) = detail::quaternion_tangent_map<S>(q.data() + {}, true);\n", qi, vi, qi);
      L.projection += fmt::format("  out.template middleRows<3>({}) = detail::quaternion_tangent_projection<S>(y.data() + {}) * "
                                  "Y.template middleRows<4>({});\n",
                                  vi, qi, qi);
      L.change += fmt::format("  out.template middleRows<4>({0}) = detail::quaternion_rate_dq<S>(alpha.data() + {1}) * "
                              "Y.template middleRows<4>({0}) +\n"
                              "      detail::quaternion_tangent_map<S>(q.data() + {0}, false) * X.template middleRows<3>({1});\n",
                              qi, vi);
      if(mj.joint.type() == JointType::Free)
      {
        // translation rows: dr/dt = R(quat / |quat|) v
        L.map += fmt::format("  P.template block<3, 3>({}, {}) = detail::quaternion_rotation<S>(q.data() + {});\n", qi + 4, vi + 3, qi);
        L.projection += fmt::format("  out.template middleRows<3>({}) = detail::quaternion_rotation<S>(y.data() + {}).transpose() * "
                                    "Y.template middleRows<3>({});\n",
                                    vi + 3, qi, qi + 4);
        L.change += fmt::format("  {{\n"
                                "    const Eigen::Matrix<S, 3, 3> R = detail::quaternion_rotation<S>(q.data() + {0});\n"
                                "    const Eigen::Matrix<S, 3, 4> dR = -R * detail::hat(alpha[{2}], alpha[{3}], alpha[{4}]) * "
                                "detail::quaternion_tangent_projection<S>(q.data() + {0});\n"
                                "    out.template middleRows<3>({1}) = dR * Y.template middleRows<4>({0}) + R * X.template middleRows<3>({5});\n"
                                "  }}\n",
                                qi, qi + 4, vi + 3, vi + 4, vi + 5, vi + 3);
      }
      return;
    }
    case JointType::Planar:
      // q = [theta x y], (x, y) in successor axes: q (+) d = [theta + d0; (x, y) + (d1, d2) - d0 J (x, y)],
      // J = [0 -1; 1 0]; its tangent map P = [1 0 0; y 1 0; -x 0 1] and projection N = P^-1
      L.map += fmt::format("  P({0}, {1}) = S(1);\n  P({2}, {1}) = q[{4}];\n  P({3}, {1}) = -q[{2}];\n"
                           "  P({2}, {5}) = S(1);\n  P({3}, {6}) = S(1);\n",
                           qi, vi, qi + 1, qi + 2, qi + 2, vi + 1, vi + 2);
      L.projection += fmt::format("  out.row({0}) = Y.row({3});\n"
                                  "  out.row({1}) = Y.row({4}) - y[{5}] * Y.row({3});\n"
                                  "  out.row({2}) = Y.row({5}) + y[{4}] * Y.row({3});\n",
                                  vi, vi + 1, vi + 2, qi, qi + 1, qi + 2);
      // d[x y]/dt = [v_u + thetadot y; v_w - thetadot x]
      L.change += fmt::format("  out.row({0}) = X.row({3});\n"
                              "  out.row({1}) = alpha[{3}] * Y.row({2}) + q[{2}] * X.row({3}) + X.row({4});\n"
                              "  out.row({2}) = -alpha[{3}] * Y.row({1}) - q[{1}] * X.row({3}) + X.row({5});\n",
                              qi, qi + 1, qi + 2, vi, vi + 1, vi + 2);
      return;
    default:
      throw std::logic_error("joint '" + mj.name + "': no integration rule for its type");
  }
}

} // namespace

std::string sceneStepDerivatives(const RobotModel & rm, rbd::scene::Integrator integrator, bool wrenches,
                                 const std::string & normalizeLines)
{
  using rbd::scene::Integrator;
  bool free = false, spherical = false, planar = false;
  for(const MovingJoint & mj : rm.joints)
  {
    free = free || mj.joint.type() == JointType::Free;
    spherical = spherical || mj.joint.type() == JointType::Spherical;
    planar = planar || mj.joint.type() == JointType::Planar;
  }
  const bool rk4 = integrator == Integrator::RK4, semi = integrator == Integrator::SemiImplicitEuler;
  const std::map<std::string, bool> flags{
      {"exp", !rk4 && (free || spherical || planar)},
      {"hat", free || spherical},
      {"rotation", !rk4 && (free || spherical)},
      {"spherical", !rk4 && spherical},
      {"free", !rk4 && free},
      {"planar_blocks", !rk4 && planar},
      {"quaternion", free || spherical},
      {"rk4", rk4},
      {"euler", !rk4},
      {"semi_implicit_euler", semi},
      {"explicit_euler", integrator == Integrator::ExplicitEuler},
  };
  std::map<std::string, std::string> v;
  v["integrator_doc"] = rk4 ? "classical Runge-Kutta 4" : (semi ? "semi-implicit Euler" : "explicit Euler");
  v["wrench_doc"] = wrenches ? " and the wrenches" : "";
  v["wrench_doc_arg"] = wrenches ? ", wrenches" : "";
  v["wrench_param"] = wrenches ? ", const Wrenches<S> & wrenches" : "";
  v["wrench_arg"] = wrenches ? ", wrenches" : "";
  if(rk4)
  {
    Rk4Lines L;
    for(const MovingJoint & mj : rm.joints) rk4Lines(mj, L);
    trimNewline(L.map);
    trimNewline(L.projection);
    trimNewline(L.change);
    v["tangent_map"] = L.map;
    v["tangent_projection"] = L.projection;
    v["configuration_derivative_change"] = L.change;
    v["normalize_quaternions"] = normalizeLines;
  }
  else
  {
    std::string rows = eulerRows(rm, semi);
    trimNewline(rows);
    v["step_rows"] = rows;
  }
  const std::string name = "scene_step_derivatives.hpp.in";
  return fillTemplate(selectSections(templateText(name), flags, "templates/" + name), v, "templates/" + name);
}

} // namespace rbdgen::emit
