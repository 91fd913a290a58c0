#pragma once
// Explicit instantiation of a plain header's functions for float and double
// (templates/instantiations.hpp.in), for `rbdgen generate --instantiate`: the header ends with
// their `extern template` declarations and NS/dynamics_double.cpp, NS/dynamics_float.cpp define them,
// so that a build compiles the robot's code once (two files: in parallel, half the memory each)
// instead of in every translation unit that includes the header.
#include <string>

namespace rbdgen::emit
{

/// Which of the header's optional functions exist (and are instantiated).
struct InstantiatedFunctions
{
  bool forwardDynamics = false;
  bool derivatives = false;
};

/// The header's closing section: `extern template` declarations for float and double.
std::string externInstantiations(const std::string & ns, const InstantiatedFunctions & f);

/// NS/dynamics_<scalar>.cpp: the explicit instantiation definitions for `scalar` ("double" or
/// "float"; first line: `provenance`).
std::string instantiationSource(const std::string & ns, const std::string & scalar, const InstantiatedFunctions & f,
                                const std::string & provenance);

} // namespace rbdgen::emit
