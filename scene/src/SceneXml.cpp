// Checked reading of scene XML elements (see SceneXml.h).
#include "SceneXml.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "rbd/scene/SceneLoader.h"

namespace rbd::scene::xml
{

namespace
{

std::string oneLine(std::string s)
{
  for(char & c : s)
    if(c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string join(std::initializer_list<const char *> words)
{
  std::string out;
  for(const char * w : words) out += (out.empty() ? "" : ", ") + std::string(w);
  return out;
}

bool contains(std::initializer_list<const char *> words, const char * w)
{
  for(const char * x : words)
    if(std::strcmp(x, w) == 0) return true;
  return false;
}

/// Parse a whole finite number (no trailing characters).
std::optional<double> parseNumber(const std::string & s)
{
  const char * begin = s.c_str();
  char * end = nullptr;
  const double v = std::strtod(begin, &end);
  if(end == begin) return std::nullopt;
  while(*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r') ++end;
  if(*end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

} // namespace

void Reader::failAt(int line, const std::string & element, const std::string & name, const std::string & reason) const
{
  std::string msg = file_;
  if(line > 0) msg += ":" + std::to_string(line);
  msg += ": " + element;
  if(!name.empty()) msg += " '" + name + "'";
  msg += ": " + reason;
  throw SceneError(oneLine(msg));
}

void Reader::fail(const tinyxml2::XMLElement * e, const std::string & name, const std::string & reason) const
{
  failAt(e->GetLineNum(), e->Name(), name, reason);
}

void Reader::onlyAttributes(const tinyxml2::XMLElement * e, const std::string & name,
                            std::initializer_list<const char *> allowed) const
{
  for(const tinyxml2::XMLAttribute * a = e->FirstAttribute(); a; a = a->Next())
    if(!contains(allowed, a->Name()))
      fail(e, name,
           "unknown attribute '" + std::string(a->Name()) + "'" +
               (allowed.size() ? " (allowed: " + join(allowed) + ")" : " (it takes no attributes)"));
}

void Reader::onlyChildren(const tinyxml2::XMLElement * e, const std::string & name,
                          std::initializer_list<const char *> allowed) const
{
  for(const tinyxml2::XMLElement * c = e->FirstChildElement(); c; c = c->NextSiblingElement())
    if(!contains(allowed, c->Name()))
      failAt(c->GetLineNum(), c->Name(), "",
             "unknown element in <" + std::string(e->Name()) + (name.empty() ? "" : " '" + name + "'") + ">" +
                 (allowed.size() ? " (allowed: " + join(allowed) + ")" : " (it takes no children)"));
}

const tinyxml2::XMLElement * Reader::single(const tinyxml2::XMLElement * parent, const char * child) const
{
  const tinyxml2::XMLElement * e = parent->FirstChildElement(child);
  if(e && e->NextSiblingElement(child))
    fail(e->NextSiblingElement(child), "", "given twice (first at line " + std::to_string(e->GetLineNum()) + ")");
  return e;
}

std::optional<std::string> Reader::text(const tinyxml2::XMLElement * e, const char * attr) const
{
  const char * v = e->Attribute(attr);
  if(!v) return std::nullopt;
  return std::string(v);
}

std::string Reader::required(const tinyxml2::XMLElement * e, const std::string & name, const char * attr) const
{
  auto v = text(e, attr);
  if(!v) fail(e, name, "missing attribute '" + std::string(attr) + "'");
  if(v->empty()) fail(e, name, "attribute '" + std::string(attr) + "' is empty");
  return *v;
}

std::optional<double> Reader::number(const tinyxml2::XMLElement * e, const std::string & name, const char * attr) const
{
  auto v = text(e, attr);
  if(!v) return std::nullopt;
  auto x = parseNumber(*v);
  if(!x) fail(e, name, std::string(attr) + " = '" + *v + "' is not a finite number");
  return x;
}

std::optional<double> Reader::nonNegative(const tinyxml2::XMLElement * e, const std::string & name, const char * attr,
                                          bool strictlyPositive) const
{
  auto x = number(e, name, attr);
  if(x && (*x < 0 || (strictlyPositive && *x == 0)))
  {
    std::ostringstream os;
    os << attr << " = " << *x << " must be " << (strictlyPositive ? "> 0" : ">= 0");
    fail(e, name, os.str());
  }
  return x;
}

std::optional<std::vector<double>> Reader::numbers(const tinyxml2::XMLElement * e, const std::string & name,
                                                   const char * attr) const
{
  auto v = text(e, attr);
  if(!v) return std::nullopt;
  std::istringstream in(*v);
  std::vector<double> out;
  for(std::string word; in >> word;)
  {
    auto x = parseNumber(word);
    if(!x) fail(e, name, std::string(attr) + ": '" + word + "' is not a finite number");
    out.push_back(*x);
  }
  return out;
}

std::optional<bool> Reader::boolean(const tinyxml2::XMLElement * e, const std::string & name, const char * attr) const
{
  auto v = choice(e, name, attr, {"true", "false"});
  if(!v) return std::nullopt;
  return *v == "true";
}

std::optional<std::string> Reader::choice(const tinyxml2::XMLElement * e, const std::string & name, const char * attr,
                                          std::initializer_list<const char *> choices) const
{
  auto v = text(e, attr);
  if(v && !contains(choices, v->c_str()))
    fail(e, name, std::string(attr) + " = '" + *v + "' is not one of: " + join(choices));
  return v;
}

} // namespace rbd::scene::xml
