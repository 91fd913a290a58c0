#pragma once
// Checked reading of a scene file's XML elements (internal to the scene library): every problem
// throws SceneError "<file>:<line>: <element> '<name>': <reason>" (the name part is left out when
// the element has no name).

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

namespace rbd::scene::xml
{

class Reader
{
public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  const std::string & file() const { return file_; }

  /// Throw SceneError for element e (identified by name, may be empty).
  [[noreturn]] void fail(const tinyxml2::XMLElement * e, const std::string & name, const std::string & reason) const;
  /// Same at an explicit line (-1: no line).
  [[noreturn]] void failAt(int line, const std::string & element, const std::string & name,
                           const std::string & reason) const;

  /// Unknown attributes / child elements are errors.
  void onlyAttributes(const tinyxml2::XMLElement * e, const std::string & name,
                      std::initializer_list<const char *> allowed) const;
  void onlyChildren(const tinyxml2::XMLElement * e, const std::string & name,
                    std::initializer_list<const char *> allowed) const;
  /// An element that may appear at most once among the children of parent (nullptr if absent).
  const tinyxml2::XMLElement * single(const tinyxml2::XMLElement * parent, const char * child) const;

  std::optional<std::string> text(const tinyxml2::XMLElement * e, const char * attr) const;
  std::string required(const tinyxml2::XMLElement * e, const std::string & name, const char * attr) const;
  /// A finite number; nullopt if absent.
  std::optional<double> number(const tinyxml2::XMLElement * e, const std::string & name, const char * attr) const;
  /// Same, and >= 0 (or > 0 when strictlyPositive).
  std::optional<double> nonNegative(const tinyxml2::XMLElement * e, const std::string & name, const char * attr,
                                    bool strictlyPositive = false) const;
  /// Whitespace-separated finite numbers; nullopt if absent.
  std::optional<std::vector<double>> numbers(const tinyxml2::XMLElement * e, const std::string & name,
                                             const char * attr) const;
  /// "true" or "false"; nullopt if absent.
  std::optional<bool> boolean(const tinyxml2::XMLElement * e, const std::string & name, const char * attr) const;
  /// One of the choices; nullopt if absent.
  std::optional<std::string> choice(const tinyxml2::XMLElement * e, const std::string & name, const char * attr,
                                    std::initializer_list<const char *> choices) const;

private:
  std::string file_;
};

} // namespace rbd::scene::xml
