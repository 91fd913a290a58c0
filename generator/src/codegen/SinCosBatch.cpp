#include "SinCosBatch.h"

#include <algorithm>
#include <regex>

#include <fmt/format.h>

namespace rbdgen::cg
{

std::vector<std::string> batchSinCos(const std::vector<std::string> & lines)
{
  // Only the function argument q: every angle is then known before the first statement.
  static const std::regex call(R"(^const S (\w+) = std::(sin|cos)\((q\[\d+\])\);$)");
  std::vector<std::string> angles;
  std::vector<int> slot(lines.size(), -1);
  std::smatch m;
  for(std::size_t k = 0; k < lines.size(); ++k)
  {
    if(!std::regex_match(lines[k], m, call)) continue;
    const auto it = std::find(angles.begin(), angles.end(), m[3].str());
    slot[k] = static_cast<int>(it - angles.begin());
    if(it == angles.end()) angles.push_back(m[3].str());
  }
  if(angles.empty()) return lines;
  // At the top of the body: the angles are arguments, and a switch below may read them in any case.
  std::vector<std::string> out;
  out.push_back(fmt::format("const S sincos_q[{}] = {{{}}};", angles.size(), fmt::join(angles, ", ")));
  out.push_back("const auto sincos = detail::sincos_all(sincos_q);");
  for(std::size_t k = 0; k < lines.size(); ++k)
  {
    if(slot[k] < 0)
    {
      out.push_back(lines[k]);
      continue;
    }
    std::regex_match(lines[k], m, call);
    out.push_back(fmt::format("const S {} = sincos.{}[{}];", m[1].str(), m[2].str() == "sin" ? "s" : "c", slot[k]));
  }
  return out;
}

} // namespace rbdgen::cg
