#include "Instantiations.h"

#include <fmt/format.h>

#include "Template.h"

namespace rbdgen::emit
{

namespace
{

/// The instantiation lines for float and double, prefixed by `kw` ("template" or "extern template").
std::string lines(const std::string & kw, bool forwardDynamics, bool derivatives)
{
  const std::string text = selectSections(templateText("instantiations.hpp.in"),
                                          {{"forward_dynamics", forwardDynamics},
                                           {"derivatives", derivatives},
                                           {"fd_derivatives", derivatives && forwardDynamics}},
                                          "templates/instantiations.hpp.in");
  std::string s;
  for(const char * scalar : {"double", "float"}) s += fillTemplate(text, {{"kw", kw}, {"S", scalar}}, "templates/instantiations.hpp.in");
  return s;
}

} // namespace

std::string externInstantiations(const std::string & ns, bool forwardDynamics, bool derivatives)
{
  return fmt::format("\n// Instantiated for double and float once, in {0}/dynamics.cpp (rbdgen generate --instantiate):\n"
                     "// link it (generate_robot_dynamics(... INSTANTIATE) builds it into the target). Other scalars\n"
                     "// are instantiated where they are used, as usual.\n"
                     "namespace {0}\n{{\n{1}}} // namespace {0}\n",
                     ns, lines("extern template", forwardDynamics, derivatives));
}

std::string instantiationSource(const std::string & ns, bool forwardDynamics, bool derivatives,
                                const std::string & provenance)
{
  return fmt::format("{1}\n// The explicit instantiations of {0}/dynamics.hpp for double and float.\n"
                     "#include <{0}/dynamics.hpp>\n\nnamespace {0}\n{{\n{2}}} // namespace {0}\n",
                     ns, provenance, lines("template", forwardDynamics, derivatives));
}

} // namespace rbdgen::emit
