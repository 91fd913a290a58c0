// URDF validation on the XML tree (tinyxml2), before urdfdom builds its model.
#include "UrdfCheck.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <tinyxml2.h>

#include <rbd/MultiBodyGraph.h>

namespace rbd
{
namespace parsers
{
namespace detail
{
namespace
{

using tinyxml2::XMLElement;

constexpr double maxMagnitude = 1e9;

const std::set<std::string> jointTypes{"revolute", "continuous", "prismatic", "fixed", "floating", "planar"};

std::string at(const XMLElement * e)
{
  return " (line " + std::to_string(e->GetLineNum()) + ")";
}

/// Numbers of a whitespace-separated attribute; false when a token is not a number.
bool parseNumbers(const std::string & text, std::vector<double> & out)
{
  out.clear();
  std::size_t pos = 0;
  while(true)
  {
    pos = text.find_first_not_of(" \t\r\n", pos);
    if(pos == std::string::npos) return true;
    std::size_t end = text.find_first_of(" \t\r\n", pos);
    if(end == std::string::npos) end = text.size();
    std::size_t b = pos;
    if(text[b] == '+' && end - b > 1) ++b; // from_chars does not take a leading '+'
    double v = 0;
    const auto res = std::from_chars(text.data() + b, text.data() + end, v);
    if(res.ec != std::errc() || res.ptr != text.data() + end) return false;
    out.push_back(v);
    pos = end;
  }
}

class Checker
{
public:
  Checker(const std::string & file) : file_(file) {}

  [[noreturn]] void fail(const std::string & element, const std::string & name, const std::string & reason) const
  {
    throw UrdfError(file_, element, name, reason);
  }

  /// Names end up in generated C++ (string literals, comments): no control characters; 'Root' is
  /// the joint rbdgen adds at the base.
  void checkName(const std::string & element, const std::string & name, const XMLElement * e) const
  {
    for(unsigned char c : name)
      if(c < 0x20 || c == 0x7f) fail(element, name, "name contains a control character" + at(e));
    if(element == "joint" && name == rbd::rootJointName)
      fail(element, name, std::string("the name '") + rbd::rootJointName + "' is reserved for the base joint" + at(e));
  }

  /// n finite numbers from attribute `attr` of e (absent: the defaults, when allowed).
  std::vector<double> numbers(const XMLElement * e, const char * attr, std::size_t n, const std::string & element,
                              const std::string & name, const std::string & what, bool required = false,
                              std::vector<double> defaults = {}) const
  {
    const char * text = e ? e->Attribute(attr) : nullptr;
    if(!text)
    {
      if(required) fail(element, name, what + ": missing attribute '" + attr + "'" + (e ? at(e) : ""));
      return defaults;
    }
    std::vector<double> v;
    if(!parseNumbers(text, v)) fail(element, name, what + " " + attr + "=\"" + text + "\" is not a list of numbers" + at(e));
    if(v.size() != n)
      fail(element, name, what + " " + attr + "=\"" + text + "\" has " + std::to_string(v.size()) + " values, expected " +
                              std::to_string(n) + at(e));
    for(double x : v)
      if(!std::isfinite(x)) fail(element, name, what + " " + attr + "=\"" + text + "\" is not finite" + at(e));
    // Values entering the dynamics (origins, axes, masses, inertias; not limits) within 1e9 SI
    // units: the products the algorithms form (m r^2, r x f, |axis|^2) then stay finite.
    const bool physical = what != "limit" && what != "dynamics" && what != "mimic";
    for(double x : v)
      if(physical && std::abs(x) > maxMagnitude)
        fail(element, name, what + " " + attr + "=\"" + text + "\" is out of range (|value| > 1e9)" + at(e));
    return v;
  }

  void checkOrigin(const XMLElement * parent, const std::string & element, const std::string & name,
                   const std::string & what) const
  {
    const XMLElement * o = parent->FirstChildElement("origin");
    if(!o) return;
    numbers(o, "xyz", 3, element, name, what + " origin");
    numbers(o, "rpy", 3, element, name, what + " origin");
  }

  /// Inertial of one link, checked for finite values and a non-negative mass.
  struct LinkInertial
  {
    std::string link;
    Eigen::Matrix3d I;
    const XMLElement * inertia;
  };

  bool readInertial(const XMLElement * link, const std::string & name, LinkInertial & out) const
  {
    const XMLElement * in = link->FirstChildElement("inertial");
    if(!in) return false;
    checkOrigin(in, "link", name, "inertial");
    const XMLElement * massE = in->FirstChildElement("mass");
    if(!massE) fail("link", name, "<inertial> without <mass>" + at(in));
    const double m = numbers(massE, "value", 1, "link", name, "mass", true)[0];
    if(m < 0) fail("link", name, std::string("negative mass ") + massE->Attribute("value") + at(massE));
    const XMLElement * ie = in->FirstChildElement("inertia");
    if(!ie) fail("link", name, "<inertial> without <inertia>" + at(in));
    const char * keys[] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
    double v[6];
    for(int k = 0; k < 6; ++k) v[k] = numbers(ie, keys[k], 1, "link", name, "inertia", true)[0];
    out.link = name;
    out.I << v[0], v[1], v[2], v[1], v[3], v[4], v[2], v[4], v[5];
    out.inertia = ie;
    return true;
  }

  /// Principal moments of a real body: l_i >= 0 and l_i <= l_j + l_k (triangle inequality).
  /// A non-PSD inertia is an error; a triangle violation only with `strict` (else a warning).
  void checkInertia(const LinkInertial & li, bool strict, std::vector<std::string> & warnings) const
  {
    const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(li.I, Eigen::EigenvaluesOnly).eigenvalues();
    const double tol = inertiaTolerance * l.cwiseAbs().sum() + inertiaAbsoluteTolerance;
    std::ostringstream moments;
    moments << "principal moments " << l(0) << ", " << l(1) << ", " << l(2) << at(li.inertia);
    if(l.minCoeff() < -tol) fail("link", li.link, "inertia is not positive semi-definite: " + moments.str());
    for(int k = 0; k < 3; ++k)
      if(l(k) > l((k + 1) % 3) + l((k + 2) % 3) + tol)
      {
        const std::string reason = "inertia violates the triangle inequality: " + moments.str();
        if(strict) fail("link", li.link, reason);
        warnings.push_back(file_ + ": link '" + li.link + "': " + reason + " (not a physical rigid body; kept)");
        return;
      }
  }

  void checkJoint(const XMLElement * j, const std::string & name, const std::set<std::string> & links,
                  std::string & parent, std::string & child) const
  {
    const char * typeC = j->Attribute("type");
    if(!typeC) fail("joint", name, "missing attribute 'type'" + at(j));
    const std::string type = typeC;
    if(!jointTypes.count(type))
      fail("joint", name, "unknown joint type '" + type +
                              "' (expected revolute, continuous, prismatic, fixed, floating or planar)" + at(j));
    for(const char * side : {"parent", "child"})
    {
      const XMLElement * e = j->FirstChildElement(side);
      const char * link = e ? e->Attribute("link") : nullptr;
      if(!link) fail("joint", name, std::string("missing <") + side + " link=...>" + at(j));
      if(!links.count(link)) fail("joint", name, std::string(side) + " link '" + link + "' does not exist" + at(e));
      (std::string(side) == "parent" ? parent : child) = link;
    }
    if(parent == child) fail("joint", name, "links link '" + parent + "' to itself" + at(j));
    checkOrigin(j, "joint", name, "joint");
    const bool needsAxis = type == "revolute" || type == "continuous" || type == "prismatic" || type == "planar";
    if(needsAxis)
    {
      const std::vector<double> a = numbers(j->FirstChildElement("axis"), "xyz", 3, "joint", name, "axis", false, {1, 0, 0});
      if(std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) < 1e-12) fail("joint", name, "zero axis" + at(j));
    }
    const XMLElement * lim = j->FirstChildElement("limit");
    if((type == "revolute" || type == "prismatic") && !lim)
      fail("joint", name, type + " joint without <limit>" + at(j));
    if(lim)
    {
      for(const char * key : {"lower", "upper", "effort", "velocity"})
        numbers(lim, key, 1, "joint", name, "limit", std::string(key) == "effort" || std::string(key) == "velocity");
      const double lo = numbers(lim, "lower", 1, "joint", name, "limit", false, {0})[0];
      const double up = numbers(lim, "upper", 1, "joint", name, "limit", false, {0})[0];
      if((type == "revolute" || type == "prismatic") && lo > up)
        fail("joint", name, "lower limit " + std::to_string(lo) + " > upper limit " + std::to_string(up) + at(lim));
    }
    if(const XMLElement * dyn = j->FirstChildElement("dynamics"))
    {
      numbers(dyn, "damping", 1, "joint", name, "dynamics");
      numbers(dyn, "friction", 1, "joint", name, "dynamics");
    }
    if(const XMLElement * mim = j->FirstChildElement("mimic"))
    {
      numbers(mim, "multiplier", 1, "joint", name, "mimic");
      numbers(mim, "offset", 1, "joint", name, "mimic");
    }
  }

  CheckedUrdf run(const std::string & xml, const ParserOptions & opt)
  {
    tinyxml2::XMLDocument doc;
    if(doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
      fail("xml", "line " + std::to_string(doc.ErrorLineNum()),
           std::string("malformed URDF or XML: ") + doc.ErrorName() + " (" + doc.ErrorStr() + ")");
    const XMLElement * robot = doc.RootElement();
    if(!robot || std::string(robot->Name()) != "robot")
      fail("xml", robot ? robot->Name() : "", "malformed URDF or XML: the root element is not <robot>");
    CheckedUrdf out;
    const char * rn = robot->Attribute("name");
    if(!rn || !*rn) fail("robot", "", "missing attribute 'name'" + at(robot));
    out.robotName = rn;
    checkName("robot", rn, robot);

    // --- links: unique names, valid inertials ---
    std::map<std::string, const XMLElement *> links;
    for(const XMLElement * l = robot->FirstChildElement("link"); l; l = l->NextSiblingElement("link"))
    {
      const char * n = l->Attribute("name");
      if(!n || !*n) fail("link", "", "missing attribute 'name'" + at(l));
      checkName("link", n, l);
      if(!links.emplace(n, l).second) fail("link", n, "duplicate link name" + at(l) + ", first at line " + std::to_string(links[n]->GetLineNum()));
      out.links.push_back(n);
      LinkInertial li;
      if(readInertial(l, n, li)) checkInertia(li, opt.strictInertia, out.warnings);
    }
    if(links.empty()) fail("robot", out.robotName, "no <link> element");
    const std::set<std::string> linkSet(out.links.begin(), out.links.end());

    // --- joints: unique names, known types, existing links, one parent per link ---
    std::map<std::string, const XMLElement *> joints;
    std::map<std::string, std::string> parentJoint, parentLink; // by child link
    std::vector<const XMLElement *> mimics;
    for(const XMLElement * j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint"))
    {
      const char * n = j->Attribute("name");
      if(!n || !*n) fail("joint", "", "missing attribute 'name'" + at(j));
      checkName("joint", n, j);
      if(!joints.emplace(n, j).second) fail("joint", n, "duplicate joint name" + at(j) + ", first at line " + std::to_string(joints[n]->GetLineNum()));
      out.joints.push_back(n);
      std::string parent, child;
      checkJoint(j, n, linkSet, parent, child);
      if(parentJoint.count(child))
        fail("link", child, "child of two joints '" + parentJoint[child] + "' and '" + n + "' (kinematic loop)" + at(j));
      parentJoint[child] = n;
      parentLink[child] = parent;
      if(j->FirstChildElement("mimic")) mimics.push_back(j);
    }
    for(const XMLElement * j : mimics)
    {
      const char * target = j->FirstChildElement("mimic")->Attribute("joint");
      if(!target || !joints.count(target))
        fail("joint", j->Attribute("name"), std::string("mimics unknown joint '") + (target ? target : "") + "'" + at(j));
    }

    // --- tree: exactly one root, every link reachable from it (else a cycle) ---
    std::vector<std::string> roots;
    for(const std::string & l : out.links)
      if(!parentJoint.count(l)) roots.push_back(l);
    if(roots.size() > 1)
    {
      std::string list;
      for(const std::string & r : roots) list += (list.empty() ? "'" : ", '") + r + "'";
      fail("robot", out.robotName, "several root links (links without a parent joint): " + list);
    }
    for(const std::string & l : out.links)
    {
      // Walk up the parents: reaching a link twice means a cycle.
      std::vector<std::string> path{l};
      std::set<std::string> seen{l};
      std::string cur = l;
      while(parentLink.count(cur))
      {
        cur = parentLink[cur];
        path.push_back(cur);
        if(!seen.insert(cur).second)
        {
          std::string cycle;
          for(auto it = std::find(path.begin(), path.end(), cur); it != path.end(); ++it)
            cycle += (cycle.empty() ? "" : " <- ") + *it;
          fail("joint", parentJoint[cur], "closes a kinematic cycle: " + cycle);
        }
      }
    }
    out.rootLink = roots.at(0);

    // --- options ---
    if(!opt.baseLink.empty() && !linkSet.count(opt.baseLink))
      fail("link", opt.baseLink, "unknown base link (no such link in robot '" + out.robotName + "')");
    const std::string base = opt.baseLink.empty() ? out.rootLink : opt.baseLink;
    for(const std::string & f : opt.filteredLinks)
    {
      if(!linkSet.count(f)) fail("link", f, "unknown filtered link (no such link in robot '" + out.robotName + "')");
      if(f == base) fail("link", f, "the base link cannot be filtered out");
    }
    return out;
  }

private:
  std::string file_;
};

} // namespace

CheckedUrdf checkUrdf(const std::string & xml, const std::string & file, const ParserOptions & opt)
{
  return Checker(file).run(xml, opt);
}

} // namespace detail
} // namespace parsers
} // namespace rbd
