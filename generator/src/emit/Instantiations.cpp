#include "Instantiations.h"

#include <vector>

#include <fmt/format.h>

#include "Template.h"

namespace rbdgen::emit
{

namespace
{

/// The instantiation lines for the scalars, prefixed by `kw` ("template" or "extern template").
std::string lines(const std::string & kw, const std::vector<std::string> & scalars, const InstantiatedFunctions & f)
{
  const std::string text = selectSections(templateText("instantiations.hpp.in"),
                                          {{"forward_dynamics", f.forwardDynamics},
                                           {"derivatives", f.derivatives},
                                           {"fd_derivatives", f.derivatives && f.forwardDynamics}},
                                          "templates/instantiations.hpp.in");
  std::string s;
  for(const std::string & scalar : scalars) s += fillTemplate(text, {{"kw", kw}, {"S", scalar}}, "templates/instantiations.hpp.in");
  return s;
}

} // namespace

std::string externInstantiations(const std::string & ns, const InstantiatedFunctions & f)
{
  return fmt::format("\n// Instantiated for double and float once, in {0}/dynamics_double.cpp and {0}/dynamics_float.cpp\n"
                     "// (rbdgen generate --instantiate): link them (generate_robot_dynamics(... INSTANTIATE) builds them\n"
                     "// into the target). Other scalars are instantiated where they are used, as usual.\n"
                     "namespace {0}\n{{\n{1}}} // namespace {0}\n",
                     ns, lines("extern template", {"double", "float"}, f));
}

std::string instantiationSource(const std::string & ns, const std::string & scalar, const InstantiatedFunctions & f,
                                const std::string & provenance)
{
  return fmt::format("{1}\n// The explicit instantiations of {0}/dynamics.hpp for {3}.\n"
                     "#include <{0}/dynamics.hpp>\n\nnamespace {0}\n{{\n{2}}} // namespace {0}\n",
                     ns, provenance, lines("template", {scalar}, f), scalar);
}

} // namespace rbdgen::emit
