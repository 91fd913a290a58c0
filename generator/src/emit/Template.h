#pragma once
// Template filling: `{{name}}` placeholders in a text file from templates/. A placeholder with no
// value, or a value no placeholder uses, is an error of the generator (never emitted silently).

#include <map>
#include <stdexcept>
#include <string>

namespace rbdgen
{

struct TemplateError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Replace every {{name}} in `text` (named `templateName` in errors) by values.at(name).
std::string fillTemplate(const std::string & text, const std::map<std::string, std::string> & values,
                         const std::string & templateName);

} // namespace rbdgen
