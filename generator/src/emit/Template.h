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

/// Embedded templates, by file name (generated from templates/ at build time).
const std::map<std::string, std::string> & embeddedTemplates();

/// The text of template `name`; an error of the generator when it is not embedded.
const std::string & templateText(const std::string & name);

/// Replace every {{name}} in `text` (named `templateName` in errors) by values.at(name).
std::string fillTemplate(const std::string & text, const std::map<std::string, std::string> & values,
                         const std::string & templateName);

/// Conditional sections: a line `{{#name}}` opens and a line `{{/name}}` closes a section (each
/// alone on its line, nesting allowed); the section's lines are kept when flags.at(name) is true and
/// removed otherwise; `{{^name}}` opens an inverted section (kept when the flag is false), closed by
/// `{{/name}}` too. A section without a flag, a flag no section uses, or an unbalanced section is
/// an error. Run before fillTemplate (placeholders of removed sections need no value).
std::string selectSections(const std::string & text, const std::map<std::string, bool> & flags,
                           const std::string & templateName);

/// Template `name` (templates/name) with its sections selected by flags and its placeholders filled
/// from values; the values of placeholders that only removed sections held are dropped (a value no
/// line of the template names is still an error).
std::string renderTemplate(const std::string & name, const std::map<std::string, bool> & flags,
                           std::map<std::string, std::string> values);

} // namespace rbdgen
