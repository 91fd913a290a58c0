// The scene's sections of a header (templates/dynamics.hpp.in, assembled by emitDynamicsHeader):
// which exist (a disabled effect's section is removed whole), the emitted bodies, per-joint
// integration lines, outputs; and the scene's API in coupled coordinates (mimic joints).
#include "SceneHeader.h"
#include "RobotValues.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include <rbd/scene/Integrators.h>

#include "../passes/JointKernels.h"
#include "../passes/SharedPasses.h"
#include "../passes/SupportPath.h"
#include "Functions.h"
#include "Header.h"
#include "MimicCoupled.h"
#include "StepDerivatives.h"
#include "Template.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;
namespace
{

std::string literal(double v)
{
  return Block::literal(v);
}

int countNonZero(const std::vector<double> & v)
{
  int n = 0;
  for(double x : v) n += x != 0.0;
  return n;
}

int bodyIndex(const RobotModel & rm, const std::string & link)
{
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
    if(rm.bodies[i].name == link) return static_cast<int>(i);
  throw std::invalid_argument("link '" + link + "' is not in the scene's robot");
}

// q (+) dq, dq/dt and quaternion normalisation, one line (or block) per moving joint.
struct JointLines
{
  std::string integrate, derivative, normalize;
  bool free = false, spherical = false, planar = false;
};

JointLines jointLines(const RobotModel & rm)
{
  JointLines L;
  for(const MovingJoint & mj : rm.joints)
  {
    const int qi = mj.qIndex, vi = mj.vIndex;
    L.integrate += fmt::format("  // {} ({})\n", mj.name, describeJoint(mj));
    L.derivative += fmt::format("  // {}\n", mj.name);
    switch(mj.joint.type())
    {
      case rbd::JointType::Rev:
      case rbd::JointType::Prism:
      case rbd::JointType::Cylindrical:
        for(int c = 0; c < mj.nv; ++c)
        {
          L.integrate += fmt::format("  res[{}] += dq[{}];\n", qi + c, vi + c);
          L.derivative += fmt::format("  qd[{}] = alpha[{}];\n", qi + c, vi + c);
        }
        break;
      case rbd::JointType::Planar:
        L.planar = true;
        L.integrate += fmt::format("  detail::integrate_planar<S>(res.data() + {}, dq.data() + {});\n", qi, vi);
        // (x, y) in successor axes: d(x, y)/dt = (v_u + thetadot y, v_w - thetadot x)
        L.derivative += fmt::format("  qd[{0}] = alpha[{1}];\n"
                                    "  qd[{2}] = alpha[{3}] + alpha[{1}] * q[{5}];\n"
                                    "  qd[{5}] = alpha[{4}] - alpha[{1}] * q[{2}];\n",
                                    qi, vi, qi + 1, vi + 1, vi + 2, qi + 2);
        break;
      case rbd::JointType::Spherical:
      case rbd::JointType::Free:
      {
        const bool isFree = mj.joint.type() == rbd::JointType::Free;
        (isFree ? L.free : L.spherical) = true;
        L.integrate += isFree ? fmt::format("  detail::integrate_free<S>(res.data() + {}, dq.data() + {});\n", qi, vi)
                              : fmt::format("  detail::rotate_quaternion<S>(res.data() + {}, dq.data() + {});\n", qi, vi);
        // d/dt quat = quat (x) [0; w] / 2
        const int w = qi, x = qi + 1, y = qi + 2, z = qi + 3, a = vi, b = vi + 1, c = vi + 2;
        L.derivative += fmt::format("  qd[{0}] = S(-0.5) * (q[{1}] * alpha[{4}] + q[{2}] * alpha[{5}] + q[{3}] * alpha[{6}]);\n"
                                    "  qd[{1}] = S(0.5) * (q[{0}] * alpha[{4}] + q[{2}] * alpha[{6}] - q[{3}] * alpha[{5}]);\n"
                                    "  qd[{2}] = S(0.5) * (q[{0}] * alpha[{5}] + q[{3}] * alpha[{4}] - q[{1}] * alpha[{6}]);\n"
                                    "  qd[{3}] = S(0.5) * (q[{0}] * alpha[{6}] + q[{1}] * alpha[{5}] - q[{2}] * alpha[{4}]);\n",
                                    w, x, y, z, a, b, c);
        if(isFree)
          L.derivative += fmt::format("  qd.template segment<3>({}) = detail::quaternion_rotation<S>(q.data() + {}) * "
                                      "alpha.template segment<3>({});\n",
                                      qi + 4, qi, vi + 3);
        L.normalize += fmt::format("  state.q.template segment<4>({0}) /= state.q.template segment<4>({0}).norm();\n", qi);
        break;
      }
      default:
        throw std::logic_error("joint '" + mj.name + "': no integration rule for its type");
    }
  }
  auto trim = [](std::string & s) {
    if(!s.empty() && s.back() == '\n') s.pop_back();
  };
  trim(L.integrate);
  trim(L.derivative);
  trim(L.normalize);
  return L;
}

/// The scene's initial state as literals; with `view` (the coupled view of rm), its coupled
/// coordinates (each kept joint's own, the mimic joints' dropped).
std::string initialStateLines(const rbd::scene::Scene & scene, const rbd::scene::SceneRobot & sr, const RobotModel & rm,
                              const RobotModel * view = nullptr)
{
  const rbd::scene::SceneDynamics dyn(sr, scene);
  rbd::scene::SceneState<double> s0 = rbd::scene::initialState(dyn);
  if(view)
  {
    rbd::scene::SceneState<double> c{Eigen::VectorXd(view->nq), Eigen::VectorXd(view->nv)};
    for(const MovingJoint & vj : view->joints)
      for(const MovingJoint & mj : rm.joints)
        if(mj.name == vj.name)
        {
          c.q.segment(vj.qIndex, vj.nq) = s0.q.segment(mj.qIndex, mj.nq);
          c.alpha.segment(vj.vIndex, vj.nv) = s0.alpha.segment(mj.vIndex, mj.nv);
        }
    s0 = c;
  }
  std::string out;
  std::string q, a;
  for(Eigen::Index i = 0; i < s0.q.size(); ++i) q += (i ? ", " : "") + literal(s0.q[i]);
  for(Eigen::Index i = 0; i < s0.alpha.size(); ++i) a += (i ? ", " : "") + literal(s0.alpha[i]);
  if(s0.q.size() > 0) out += "  s.q << " + q + ";\n";
  else out += "  s.q.setZero();\n";
  if(s0.alpha.size() > 0 && !s0.alpha.isZero()) out += "  s.alpha << " + a + ";";
  else out += "  s.alpha.setZero();";
  return out;
}

/// Arguments of a coupled wrapper: the coupled q (and alpha) expanded to the full model's.
const char * const kExpandedQ = "expand_configuration<S>(q)";
const char * const kExpandedQA = "expand_configuration<S>(q), expand_tangent<S>(alpha)";

/// The outputs' functions; coupled: each a call of independent::'s on the expanded state (Jacobian
/// columns projected).
std::string outputs(const RobotModel & rm, const rbd::scene::Scene & scene, const SceneEffects & fx, bool coupled = false)
{
  const rbd::scene::Outputs & o = scene.outputs;
  // one function per listed link: templates/scene_output_<kind>.hpp.in with its body (coupled: the
  // full model's function of the same name on the expanded state: `open` call `close`)
  auto perLink = [&](const std::vector<std::string> & links, const std::string & kind, const std::string & open,
                     const std::string & close, EmittedBody (*body)(const RobotModel &, int)) {
    std::string out;
    for(const std::string & link : links)
    {
      const int b = bodyIndex(rm, link);
      const std::string & ident = rm.bodies[static_cast<std::size_t>(b)].ident;
      const std::string call = fmt::format("independent::{}_{}<S>({})", kind, ident, kExpandedQ);
      out += renderTemplate("scene_output_" + kind + ".hpp.in", {},
                            {{"link", link}, {"ident", ident},
                             {"body", coupled ? open + call + close : body(rm, b).text}});
    }
    return out;
  };
  const std::string poses = perLink(o.poses, "pose", "  res = ", ";", linkPoseBody);
  const std::string jacobians = perLink(o.jacobians, "jacobian", "  J = project_columns<S, 6>(", ");", linkJacobianBody);
  const bool potential = o.energy && fx.gravity.has_value();
  const bool com = o.com || o.kinematics; // a robot's kinematics include its centre of mass
  std::map<std::string, std::string> v{{"poses", poses}, {"jacobians", jacobians}};
  if(o.kinematics && coupled)
  {
    v["fn_forward_kinematics"] = fmt::format("  res = independent::forward_kinematics<S>({});", kExpandedQ);
    v["fn_jacobian_q_point"] =
        fmt::format("  J = project_columns<S, 6>(independent::jacobian<S>(body, {}, point));", kExpandedQ);
  }
  else if(o.kinematics)
  {
    v["support_tables"] = passes::supportPathTables(rm) + "\n\n" + supportJacobianDefinitions(rm);
    v["fn_forward_kinematics"] = forwardKinematicsBody(rm).text;
    v["fn_jacobian_q_point"] = "  detail::support_jacobian<S>(body, q, point, J);";
  }
  if(com)
    v["fn_center_of_mass"] = coupled ? fmt::format("  com = independent::center_of_mass<S>({});", kExpandedQ) : centerOfMassQBody(rm).text;
  if(o.momentum)
    v["fn_centroidal_momentum"] =
        coupled ? fmt::format("  h = independent::centroidal_momentum<S>({});", kExpandedQA) : centroidalMomentumBody(rm).text;
  if(o.energy)
  {
    v["fn_kinetic_energy"] =
        coupled ? fmt::format("  e = independent::kinetic_energy<S>({});", kExpandedQA) : energyBody(rm, fx, true).text;
    v["kinetic_doc"] = fx.hasArmature() ? "alpha^T (H + diag(armature)) alpha / 2" : "alpha^T H alpha / 2";
    v["potential_doc"] = potential ? " + potential_energy" : "";
    v["potential_call"] = potential ? " + potential_energy<S>(q)" : "";
  }
  if(potential)
    v["fn_potential_energy"] =
        coupled ? fmt::format("  e = independent::potential_energy<S>({});", kExpandedQ) : energyBody(rm, fx, false).text;
  return renderTemplate("scene_outputs.hpp.in",
              {{"com", com},
               {"momentum", o.momentum},
               {"energy", o.energy},
               {"potential", potential},
               {"kinematics", o.kinematics},
               {"own_model", !coupled}},
              v);
}

const char * integratorDoc(rbd::scene::Integrator i)
{
  switch(i)
  {
    case rbd::scene::Integrator::SemiImplicitEuler: return "semi-implicit Euler";
    case rbd::scene::Integrator::ExplicitEuler: return "explicit Euler";
    case rbd::scene::Integrator::RK4: return "classical Runge-Kutta 4";
  }
  return "";
}

/// integrate, the step's documentation and arguments, and with RK4 configuration_derivative and
/// the quaternions' normalisation.
void integrationValues(std::map<std::string, std::string> & v, const JointLines & J, rbd::scene::Integrator integrator,
                       bool wrenches)
{
  v["integrate"] = J.integrate;
  v["wrench_arg"] = wrenches ? ", wrenches" : "";
  v["wrench_doc"] = wrenches ? " and the wrenches" : "";
  v["integrator_doc"] = integratorDoc(integrator);
  if(integrator == rbd::scene::Integrator::RK4)
  {
    v["configuration_derivative"] = J.derivative;
    v["normalize_quaternions"] = J.normalize;
  }
}

} // namespace

SceneEffects sceneEffects(const RobotModel & rm, const rbd::scene::Scene & scene, const rbd::scene::SceneRobot & sr)
{
  SceneEffects fx;
  fx.gravity = scene.gravity;
  if(fx.gravity && fx.gravity->isZero()) fx.gravity.reset(); // a zero vector is no gravity
  fx.velocityTerms = scene.velocityTerms;
  auto toStd = [&](const Eigen::VectorXd & v) {
    if(v.size() != rm.nv) throw std::logic_error("scene robot: per-dof effects do not match the model");
    return std::vector<double>(v.data(), v.data() + v.size());
  };
  fx.damping = toStd(sr.damping);
  fx.friction = toStd(sr.friction);
  fx.armature = toStd(sr.armature);
  fx.frictionVelocity = scene.frictionVelocity;
  fx.wrenchBodies = sr.wrenchBodies;
  for(std::size_t c = 0; c < scene.contacts.size(); ++c)
    fx.contacts.push_back(SceneContact{scene.contacts[c].name, sr.contactBodies[c], scene.contacts[c].point});
  fx.stiffness = scene.contactModel.stiffness;
  fx.contactDamping = scene.contactModel.damping;
  fx.mu = scene.contactModel.mu;
  fx.slipVelocity = scene.contactModel.slipVelocity;
  fx.groundHeight = scene.contactModel.groundHeight;
  return fx;
}

std::vector<std::string> unregularisedMasslessJoints(const RobotModel & rm, const SceneEffects & fx)
{
  std::vector<std::string> out;
  for(const std::string & name : rm.masslessSubtrees)
    for(const MovingJoint & mj : rm.joints)
    {
      if(mj.name != name) continue;
      bool regular = true;
      for(int d = 0; d < mj.nv; ++d)
      {
        const auto i = static_cast<std::size_t>(mj.vIndex + d);
        regular = regular && i < fx.armature.size() && fx.armature[i] > 0.0;
      }
      if(!regular) out.push_back(name);
    }
  return out;
}

std::string describeEffects(const rbd::scene::Scene & scene, const SceneEffects & fx)
{
  // Enabled effects only: a disabled one is not named anywhere in the header.
  std::vector<std::string> e;
  if(fx.gravity) e.push_back(fmt::format("gravity ({}, {}, {})", (*fx.gravity)[0], (*fx.gravity)[1], (*fx.gravity)[2]));
  if(fx.velocityTerms) e.push_back("velocity terms (Coriolis, centrifugal)");
  if(fx.hasDamping()) e.push_back(fmt::format("damping on {} dofs", countNonZero(fx.damping)));
  if(fx.hasFriction()) e.push_back(fmt::format("Coulomb friction on {} dofs (v_s {})", countNonZero(fx.friction), fx.frictionVelocity));
  if(fx.hasArmature()) e.push_back(fmt::format("armature on {} dofs", countNonZero(fx.armature)));
  if(!scene.locked.empty()) e.push_back(fmt::format("{} locked joints", scene.locked.size()));
  if(!scene.externalWrenches.empty()) e.push_back(fmt::format("external wrenches on {}", quotedList(scene.externalWrenches)));
  if(!fx.contacts.empty())
    e.push_back(fmt::format("{} contacts (k {}, c {}, mu {}, v_slip {}, ground z {})", fx.contacts.size(), fx.stiffness,
                            fx.contactDamping, fx.mu, fx.slipVelocity, fx.groundHeight));
  if(e.empty()) e.push_back("none (inertia only)");
  std::string s;
  for(const auto & x : e) s += (s.empty() ? "" : "; ") + x;
  return s;
}

bool hasForwardDynamics(const RobotModel & rm, const SceneEffects & fx)
{
  return rm.checks.stackedFree.empty() && unregularisedMasslessJoints(rm, fx).empty();
}

bool coupledSceneForwardDynamics(const RobotModel & rm, const SceneEffects & fx, const rbd::parsers::MimicCoupling & c)
{
  if(!rm.checks.stackedFree.empty()) return false;
  const std::vector<std::string> unregularised = unregularisedMasslessJoints(rm, fx);
  for(const std::string & j : coupledMasslessJoints(rm, c))
    if(std::find(unregularised.begin(), unregularised.end(), j) != unregularised.end()) return false;
  return true;
}

HeaderSpec sceneHeaderSpec(const RobotModel & rm, const rbd::scene::Scene & scene, const rbd::scene::SceneRobot & sr,
                           const std::string & ns, const std::string & provenance, const rbd::parsers::MimicCoupling & coupling)
{
  HeaderSpec spec;
  spec.ns = ns;
  spec.provenance = provenance;
  spec.effects = sceneEffects(rm, scene, sr);
  spec.scene = &scene;
  spec.sceneRobot = &sr;
  spec.derivatives = scene.outputs.derivatives;
  spec.coupling = coupling;
  return spec;
}

void sceneSections(HeaderSections & h, const RobotModel & rm, const rbd::scene::Scene & scene,
                   const rbd::scene::SceneRobot & sr, const SceneEffects & fx, bool fd)
{
  const bool wrenches = !fx.wrenchBodies.empty(), contacts = !fx.contacts.empty();
  const bool genBias = h.flags.at("generalized_bias");
  const JointLines J = jointLines(rm);
  const bool rk4 = scene.integrator == rbd::scene::Integrator::RK4;
  h.flags["wrenches"] = wrenches;
  h.flags["contacts"] = contacts;
  h.flags["quaternion"] = J.free || J.spherical;
  h.flags["free"] = J.free;
  h.flags["planar"] = J.planar;
  h.flags["rk4"] = rk4;
  h.flags["semi_implicit_euler"] = scene.integrator == rbd::scene::Integrator::SemiImplicitEuler;
  h.flags["explicit_euler"] = scene.integrator == rbd::scene::Integrator::ExplicitEuler;
  auto & v = h.values;
  v["initial_state"] = initialStateLines(scene, sr, rm);
  if(wrenches)
  {
    std::string wb;
    for(int b : fx.wrenchBodies) wb += (wb.empty() ? "Body::" : ", Body::") + rm.bodies[static_cast<std::size_t>(b)].ident;
    v["nwrenches"] = std::to_string(fx.wrenchBodies.size());
    v["wrench_bodies"] = wb;
  }
  if(contacts)
  {
    std::vector<std::string> names;
    for(const auto & c : fx.contacts) names.push_back(c.name);
    v["ncontacts"] = std::to_string(fx.contacts.size());
    v["contact_names"] = quotedList(names);
    v["ground_height"] = fmt::format("{}", fx.groundHeight);
    v["contact_model"] = fmt::format("k = {} N/m, c = {} N s/m, mu = {}, slip velocity {} m/s", fx.stiffness,
                                     fx.contactDamping, fx.mu, fx.slipVelocity);
    v["fn_contact_forces"] = contactForcesBody(rm, fx).text;
  }
  v["fn_inverse_dynamics"] = sceneRneaBody(rm, fx, true).text;
  const std::string wrenchArg = wrenches ? ", wrenches" : "";
  if(genBias)
  {
    std::vector<std::string> terms;
    if(fx.gravity || fx.velocityTerms) terms.push_back("nonlinear_effects");
    if(fx.hasDamping()) terms.push_back("damping alpha");
    if(fx.hasFriction()) terms.push_back("friction alpha / sqrt(alpha^2 + v_s^2)");
    if(contacts) terms.push_back("- J_c^T contact_forces");
    if(wrenches) terms.push_back("- J_w^T wrenches");
    std::string doc;
    for(const auto & t : terms) doc += (doc.empty() ? "" : (t[0] == '-' ? " " : " + ")) + t;
    v["generalized_bias_doc"] = doc;
    v["fn_generalized_bias"] = sceneRneaBody(rm, fx, false).text;
  }
  if(fd)
  {
    const std::string M = fx.hasArmature() ? "(H + diag(armature))" : "H";
    v["fd_doc"] = "composite rigid-body algorithm for " + M + (genBias ? ", generalized_bias" : "") +
                  ", tree-sparse L^T D L factorisation";
    FdOptions fo;
    fo.biasCall = genBias ? "generalized_bias<S>(q, alpha" + wrenchArg + ")" : "";
    fo.armature = fx.armature;
    fo.massMatrixLower = true; // (massMatrixValues, same armature)
    v["fn_forward_dynamics"] = forwardDynamicsBody(rm, fo).text;
    integrationValues(v, J, scene.integrator, wrenches);
    if(h.flags.at("derivatives")) v["step_derivatives"] = sceneStepDerivatives(rm, scene.integrator, wrenches, J.normalize);
  }
  v["outputs"] = outputs(rm, scene, fx);
}

std::string coupledSceneSections(HeaderSections h, const RobotModel & rm, const rbd::scene::Scene & scene,
                                 const rbd::scene::SceneRobot & sr, const SceneEffects & fx,
                                 const rbd::parsers::MimicCoupling & coupling, const std::string & ns)
{
  // The scene's API in the coupled coordinates: the same template, each function a call of the full
  // model's (independent::) on the expanded state, projected; forward dynamics by the dense L D L^T of
  // the coupled mass matrix; per-joint code (integrate, step derivatives) from the coupled view.
  const bool wrenches = !fx.wrenchBodies.empty(), contacts = !fx.contacts.empty();
  const bool gravity = fx.gravity.has_value(), velocity = fx.velocityTerms;
  const bool genBias = h.flags.at("generalized_bias");
  const RobotModel view = coupledView(rm, coupling);
  const JointLines Jc = jointLines(view);
  const bool fdc = coupledSceneForwardDynamics(rm, fx, coupling);
  h.flags["own_model"] = false;
  h.flags["coupled"] = true;
  h.flags["independent_alias"] = false;
  h.flags["forward_dynamics"] = fdc;
  h.flags["no_forward_dynamics"] = !fdc;
  h.flags["quaternion"] = Jc.free || Jc.spherical;
  h.flags["free"] = Jc.free;
  h.flags["planar"] = Jc.planar;
  auto & v = h.values;
  std::string list;
  for(const std::string & m : coupling.coupled) list += "\n//   " + m;
  v["provenance"] = fmt::format(
      "\n// ================================================================================================\n"
      "// The scene as the URDF means it: mimic joints coupled to the joints they follow:{}\n"
      "// The coupled coordinates are those of `independent` without the mimic joints' (same order):\n"
      "//   q_full = G q + o,  alpha_full = G alpha,  alphaD_full = G alphaD   (expand_*),\n"
      "// G (independent::nv x nv) with one multiplier per row, o the offsets; then every torque-like result is\n"
      "// G^T of the full model's, H = G^T H_full G, J = J_full G (project_*); equations of motion:\n"
      "//   G^T H_full G alphaD = tau - G^T generalized_bias_full   (wrenches and contacts act on the full model).",
      list);
  for(auto & [key, value] : coupledTemplateValues(coupling, ns)) v[key] = value;
  v["has_forward_dynamics"] = fdc ? "true" : "false";
  v["initial_state"] = initialStateLines(scene, sr, rm, &view);
  const std::string w = wrenches ? ", wrenches" : "";
  auto projected = [&](const std::string & dst, const std::string & fn, const std::string & args) {
    return fmt::format("  {} = project_tangent<S>(independent::{}<S>({}));", dst, fn, args);
  };
  if(contacts) v["fn_contact_forces"] = fmt::format("  res = independent::contact_forces<S>({});", kExpandedQA);
  v["fn_mass_matrix"] = fmt::format("  H = project_matrix<S>(independent::mass_matrix<S>({}));", kExpandedQ);
  v["mass_matrix_lower"] = "";
  v["mass_matrix_packed"] = massMatrixPackedText(nullptr, static_cast<int>(coupling.nv));
  if(gravity) v["fn_gravity_torques"] = projected("tau", "gravity_torques", kExpandedQ);
  if(velocity) v["fn_velocity_torques"] = projected("tau", "velocity_torques", kExpandedQA);
  if(gravity || velocity) v["fn_nonlinear_effects"] = projected("tau", "nonlinear_effects", kExpandedQA);
  v["fn_inverse_dynamics"] = projected("tau", "inverse_dynamics", std::string(kExpandedQA) + ", expand_tangent<S>(alphaD)" + w);
  if(genBias) v["fn_generalized_bias"] = projected("tau", "generalized_bias", kExpandedQA + w);
  const std::string bias = genBias ? " - generalized_bias<S>(q, alpha" + w + ")" : "";
  if(fdc)
  {
    v["fd_doc"] = std::string("mass matrix") + (fx.hasArmature() ? " (armature included)" : "") +
                  " and generalized bias of the full model projected, dense L D L^T factorisation";
    v["fn_forward_dynamics"] = fmt::format("  Eigen::Matrix<S, nv, nv> LD = mass_matrix<S>(q);\n"
                                           "  detail::ldlt_in_place<S>(LD);\n"
                                           "  alphaD = tau{};\n"
                                           "  detail::ldlt_solve<S, 1>(LD, alphaD);",
                                           bias);
    integrationValues(v, Jc, scene.integrator, wrenches);
  }
  else
    v["no_forward_dynamics_note"] = "// No forward dynamics: the coupled mass matrix is singular (joints moving only massless links\n"
                                    "// without armature; see independent::).";
  if(h.flags.at("derivatives"))
  {
    h.flags["idd_on_paths"] = false; // (the projection of independent::'s, whole)
    v["fn_inverse_dynamics_derivatives"] = fmt::format(
        "  const auto full = independent::inverse_dynamics_derivatives<S>({}, expand_tangent<S>(alphaD){});\n"
        "  d.dtau_dq = project_matrix<S>(full.dtau_dq);\n"
        "  d.dtau_dalpha = project_matrix<S>(full.dtau_dalpha);",
        kExpandedQA, w);
    if(fdc)
    {
      // d alphaD = -H^-1 d ID at alphaD, d alphaD / d tau = H^-1 (coupled H)
      v["fn_forward_dynamics_derivatives"] = fmt::format("  Eigen::Matrix<S, nv, nv> LD = mass_matrix<S>(q);\n"
                                                         "  detail::ldlt_in_place<S>(LD);\n"
                                                         "  d.alphaD = tau{0};\n"
                                                         "  detail::ldlt_solve<S, 1>(LD, d.alphaD);\n"
                                                         "  const IdDerivatives<S> id = inverse_dynamics_derivatives<S>(q, alpha, d.alphaD{1});\n"
                                                         "  d.dalphaD_dq = -id.dtau_dq;\n"
                                                         "  d.dalphaD_dalpha = -id.dtau_dalpha;\n"
                                                         "  d.Minv.setIdentity();\n"
                                                         "  detail::ldlt_solve<S, nv>(LD, d.dalphaD_dq);\n"
                                                         "  detail::ldlt_solve<S, nv>(LD, d.dalphaD_dalpha);\n"
                                                         "  detail::ldlt_solve<S, nv>(LD, d.Minv);",
                                                         bias, w);
      v["step_derivatives"] = sceneStepDerivatives(view, scene.integrator, wrenches, Jc.normalize);
    }
  }
  v["outputs"] = outputs(rm, scene, fx, true);
  return renderTemplate("dynamics.hpp.in", h.flags, h.values);
}

} // namespace rbdgen::emit
