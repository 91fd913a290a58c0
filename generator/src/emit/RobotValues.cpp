#include "RobotValues.h"

#include <fmt/format.h>

namespace rbdgen::emit
{

std::string quotedList(const std::vector<std::string> & names)
{
  std::string s;
  for(const auto & n : names)
  {
    if(!s.empty()) s += ", ";
    s += "\"";
    for(char c : n)
    {
      if(c == '"' || c == '\\') s += '\\';
      s += c;
    }
    s += "\"";
  }
  return s;
}

std::map<std::string, std::string> robotTemplateValues(const RobotModel & rm)
{
  std::map<std::string, std::string> v;
  v["nq"] = std::to_string(rm.nq);
  v["nv"] = std::to_string(rm.nv);
  v["nbodies"] = std::to_string(rm.bodies.size());
  v["nframes"] = std::to_string(rm.joints.size());
  std::string bodyEnum;
  std::vector<std::string> bodyNames;
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    bodyEnum += fmt::format("  {} = {},{}", rm.bodies[i].ident, i, i + 1 < rm.bodies.size() ? "\n" : "");
    bodyNames.push_back(rm.bodies[i].name);
  }
  v["body_enum"] = bodyEnum;
  v["body_names"] = quotedList(bodyNames);
  v["dof_names"] = quotedList(rm.dofNames);
  return v;
}

} // namespace rbdgen::emit
