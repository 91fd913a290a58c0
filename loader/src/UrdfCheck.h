#pragma once
// Validation of URDF text before urdfdom sees it (urdfdom logs its errors instead of returning
// them, and is lax about non-finite numbers, zero axes and physically invalid inertias).

#include <string>
#include <vector>

#include <rbd/parsers/urdf.h>

namespace rbd
{
namespace parsers
{
namespace detail
{

/// What the check learnt about a valid URDF.
struct CheckedUrdf
{
  std::string robotName;
  std::string rootLink;
  std::vector<std::string> links;  ///< in document order
  std::vector<std::string> joints; ///< in document order
  std::vector<std::string> warnings;
};

/// Throw UrdfError (naming `file`) on the first problem: malformed XML, duplicate names, missing or
/// unknown links, several roots, cycles, unknown joint types, zero/non-finite axes, negative or
/// non-finite masses, non-PSD inertias (triangle-inequality violations too with
/// opt.strictInertia, else a warning), non-finite origins, unknown base or filtered links.
CheckedUrdf checkUrdf(const std::string & xml, const std::string & file, const ParserOptions & opt);

/// Tolerance of the inertia checks (eigenvalues >= -tol, triangle inequality up to tol), with
/// tol = inertiaTolerance * trace + inertiaAbsoluteTolerance (kg m^2: point masses written with
/// 1e-35 round-off entries pass; a 1 g, 1 mm ball has 4e-10).
constexpr double inertiaTolerance = 1e-6;
constexpr double inertiaAbsoluteTolerance = 1e-12;

} // namespace detail
} // namespace parsers
} // namespace rbd
