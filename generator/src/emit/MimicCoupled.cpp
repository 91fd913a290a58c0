#include "MimicCoupled.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "../codegen/Expr.h"
#include "Functions.h"
#include "RobotValues.h"
#include "Template.h"

namespace rbdgen::emit
{

namespace
{

/// "m * x" with m folded: x, -x or S(m) * x.
std::string scaled(double m, const std::string & x)
{
  if(m == 1.0) return x;
  if(m == -1.0) return "-" + x;
  return cg::Block::literal(m) + " * " + x;
}

/// Per coupled coordinate, the full coordinates that follow it.
std::vector<std::vector<int>> followers(const std::vector<int> & source, int n)
{
  std::vector<std::vector<int>> f(static_cast<std::size_t>(n));
  for(std::size_t k = 0; k < source.size(); ++k) f[static_cast<std::size_t>(source[k])].push_back(static_cast<int>(k));
  return f;
}

std::string expandConfiguration(const rbd::parsers::MimicCoupling & c)
{
  std::string s;
  for(std::size_t k = 0; k < c.qSource.size(); ++k)
  {
    std::string rhs = scaled(c.qMultiplier[k], fmt::format("q({})", c.qSource[k]));
    if(c.qOffset[k] != 0.0) rhs += " + " + cg::Block::literal(c.qOffset[k]);
    s += fmt::format("  qf({}) = {};\n", k, rhs);
  }
  return s;
}

std::string expandTangent(const rbd::parsers::MimicCoupling & c)
{
  std::string s;
  for(std::size_t k = 0; k < c.vSource.size(); ++k)
    s += fmt::format("  af({}) = {};\n", k, scaled(c.vMultiplier[k], fmt::format("alpha({})", c.vSource[k])));
  return s;
}

/// X.col(j) = sum over the full coordinates k following j of m_k Xf.col(k).
std::string projectColumns(const rbd::parsers::MimicCoupling & c)
{
  std::string s;
  const auto f = followers(c.vSource, c.nv);
  for(int j = 0; j < c.nv; ++j)
  {
    std::string rhs;
    for(int k : f[static_cast<std::size_t>(j)])
    {
      const double m = c.vMultiplier[static_cast<std::size_t>(k)];
      const std::string col = fmt::format("Xf.col({})", k);
      if(rhs.empty()) rhs = scaled(m, col);
      else rhs += m < 0 ? " - " + scaled(-m, col) : " + " + scaled(m, col);
    }
    s += fmt::format("  X.col({}) = {};\n", j, rhs);
  }
  return s;
}

} // namespace

std::vector<std::string> coupledMasslessJoints(const RobotModel & rm, const rbd::parsers::MimicCoupling & c)
{
  auto massless = [&](const std::string & joint) {
    return std::find(rm.masslessSubtrees.begin(), rm.masslessSubtrees.end(), joint) != rm.masslessSubtrees.end();
  };
  // Joint name of every full velocity coordinate, in dof order (the coupled dofJoints plus the mimics).
  std::vector<std::string> fullJoints;
  for(const MovingJoint & mj : rm.joints)
    for(int d = 0; d < mj.nv; ++d) fullJoints.push_back(mj.name);
  std::map<int, bool> groupMassless; // coupled coordinate -> every follower massless
  for(std::size_t k = 0; k < c.vSource.size() && k < fullJoints.size(); ++k)
  {
    const auto it = groupMassless.find(c.vSource[k]);
    const bool m = massless(fullJoints[k]);
    groupMassless[c.vSource[k]] = it == groupMassless.end() ? m : (it->second && m);
  }
  std::vector<std::string> res;
  for(std::size_t k = 0; k < c.vSource.size() && k < fullJoints.size(); ++k)
    if(groupMassless[c.vSource[k]] &&
       std::find(res.begin(), res.end(), fullJoints[k]) == res.end())
      res.push_back(fullJoints[k]);
  return res;
}

bool coupledForwardDynamics(const RobotModel & rm, const rbd::parsers::MimicCoupling & c)
{
  return rm.checks.stackedFree.empty() && coupledMasslessJoints(rm, c).empty();
}

std::string mimicProjection(const rbd::parsers::MimicCoupling & c)
{
  auto lines = [](std::string s) {
    if(!s.empty() && s.back() == '\n') s.pop_back(); // the template line ends it
    return s;
  };
  return fillTemplate(templateText("mimic_projection.hpp.in"),
                      {{"expand_configuration", lines(expandConfiguration(c))},
                       {"expand_tangent", lines(expandTangent(c))},
                       {"project_columns", lines(projectColumns(c))}},
                      "templates/mimic_projection.hpp.in");
}

RobotModel coupledView(const RobotModel & rm, const rbd::parsers::MimicCoupling & c)
{
  RobotModel view = rm;
  view.joints.clear();
  for(const MovingJoint & mj : rm.joints)
  {
    const auto v0 = static_cast<std::size_t>(mj.vIndex), q0 = static_cast<std::size_t>(mj.qIndex);
    // a joint keeps its coordinates when the coupled coordinate its first dof follows is its own
    if(mj.nv == 0 || c.dofJoints[static_cast<std::size_t>(c.vSource[v0])] != mj.name) continue;
    MovingJoint j = mj;
    j.qIndex = c.qSource[q0];
    j.vIndex = c.vSource[v0];
    view.joints.push_back(j);
  }
  view.nq = c.nq;
  view.nv = c.nv;
  view.dofNames = c.dofJoints;
  return view;
}

std::map<std::string, std::string> coupledTemplateValues(const rbd::parsers::MimicCoupling & c, const std::string & ns)
{
  return {{"namespace", ns},
          {"nq", std::to_string(c.nq)},
          {"nv", std::to_string(c.nv)},
          {"dof_names", quotedList(c.dofJoints)},
          {"nmimic", std::to_string(c.coupled.size())},
          {"mimic_couplings", quotedList(c.coupled)},
          {"projection", mimicProjection(c)}};
}

std::string mimicCoupledSection(const rbd::parsers::MimicCoupling & c, const std::string & ns, bool forwardDynamics,
                                bool derivatives)
{
  std::map<std::string, std::string> v = coupledTemplateValues(c, ns);
  std::string list;
  for(const std::string & m : c.coupled) list += (list.empty() ? "" : "; ") + m;
  v["coupled_list"] = list;
  v["fd_algorithm"] = forwardDynamics ? "CRBA mass matrix of the full model projected on the coupled coordinates + RNEA bias "
                                        "+ dense L D L^T factorisation"
                                      : "none (singular coupled mass matrix)";
  v["has_forward_dynamics"] = forwardDynamics ? "true" : "false";
  v["mass_matrix_packed"] = massMatrixPackedText(nullptr, c.nv);
  const std::string text = selectSections(templateText("mimic_coupled.hpp.in"),
                                          {{"forward_dynamics", forwardDynamics},
                                           {"no_forward_dynamics", !forwardDynamics},
                                           {"derivatives", derivatives}},
                                          "templates/mimic_coupled.hpp.in");
  return fillTemplate(text, v, "templates/mimic_coupled.hpp.in");
}

} // namespace rbdgen::emit
