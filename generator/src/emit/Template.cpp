#include "Template.h"

#include <set>

namespace rbdgen
{

std::string fillTemplate(const std::string & text, const std::map<std::string, std::string> & values,
                         const std::string & templateName)
{
  std::string out;
  std::set<std::string> used;
  std::size_t pos = 0;
  while(true)
  {
    const std::size_t open = text.find("{{", pos);
    if(open == std::string::npos)
    {
      out.append(text, pos, std::string::npos);
      break;
    }
    const std::size_t close = text.find("}}", open + 2);
    if(close == std::string::npos)
      throw TemplateError(templateName + ": unterminated placeholder at offset " + std::to_string(open));
    const std::string name = text.substr(open + 2, close - open - 2);
    const auto it = values.find(name);
    if(it == values.end()) throw TemplateError(templateName + ": unknown placeholder '{{" + name + "}}'");
    out.append(text, pos, open - pos);
    out += it->second;
    used.insert(name);
    pos = close + 2;
  }
  for(const auto & [name, value] : values)
    if(!used.count(name)) throw TemplateError(templateName + ": value '" + name + "' is not used by the template");
  return out;
}

} // namespace rbdgen
