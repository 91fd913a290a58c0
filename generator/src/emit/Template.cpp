#include "Template.h"

#include <set>
#include <stdexcept>
#include <sstream>
#include <vector>

namespace rbdgen
{

const std::string & templateText(const std::string & name)
{
  const auto & t = embeddedTemplates();
  const auto it = t.find(name);
  if(it == t.end()) throw std::logic_error("template " + name + " is not embedded");
  return it->second;
}

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
    // a placeholder on a line of its own, filled with whole lines: the line's own end is the last one
    const bool ownLine = (open == 0 || text[open - 1] == '\n') && close + 2 < text.size() && text[close + 2] == '\n';
    if(ownLine && !it->second.empty() && it->second.back() == '\n') out.pop_back();
    used.insert(name);
    pos = close + 2;
  }
  for(const auto & [name, value] : values)
    if(!used.count(name)) throw TemplateError(templateName + ": value '" + name + "' is not used by the template");
  return out;
}

std::string selectSections(const std::string & text, const std::map<std::string, bool> & flags,
                           const std::string & templateName)
{
  std::string out;
  std::set<std::string> used;
  std::vector<std::pair<std::string, bool>> open; // section name, kept
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  auto where = [&] { return templateName + ":" + std::to_string(lineNo) + ": "; };
  while(std::getline(in, line))
  {
    ++lineNo;
    const bool isInverted = line.rfind("{{^", 0) == 0;
    const bool isOpen = isInverted || line.rfind("{{#", 0) == 0, isClose = line.rfind("{{/", 0) == 0;
    if((isOpen || isClose) && line.size() > 5 && line.compare(line.size() - 2, 2, "}}") == 0)
    {
      const std::string name = line.substr(3, line.size() - 5);
      if(isOpen)
      {
        const auto it = flags.find(name);
        if(it == flags.end()) throw TemplateError(where() + "section '" + name + "' has no flag");
        used.insert(name);
        open.emplace_back(name, it->second != isInverted);
      }
      else
      {
        if(open.empty() || open.back().first != name) throw TemplateError(where() + "unbalanced section end '" + name + "'");
        open.pop_back();
      }
      continue;
    }
    bool keep = true;
    for(const auto & o : open) keep = keep && o.second;
    if(keep) out += line + "\n";
  }
  if(!open.empty()) throw TemplateError(templateName + ": section '" + open.back().first + "' is not closed");
  if(!text.empty() && text.back() != '\n' && !out.empty()) out.pop_back();
  for(const auto & [name, value] : flags)
    if(!used.count(name)) throw TemplateError(templateName + ": flag '" + name + "' is not used by the template");
  return out;
}

std::string renderTemplate(const std::string & name, const std::map<std::string, bool> & flags,
                           std::map<std::string, std::string> values)
{
  const std::string & full = templateText(name);
  const std::string where = "templates/" + name;
  const std::string text = selectSections(full, flags, where);
  for(auto it = values.begin(); it != values.end();)
  {
    const std::string placeholder = "{{" + it->first + "}}";
    if(text.find(placeholder) == std::string::npos && full.find(placeholder) != std::string::npos) it = values.erase(it);
    else ++it;
  }
  return fillTemplate(text, values, where);
}

} // namespace rbdgen
