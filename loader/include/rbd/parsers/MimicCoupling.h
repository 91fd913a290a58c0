#pragma once
// Mimic joints coupled: <mimic joint="t" multiplier="m" offset="o"/> on joint j means
// q_j = m q_t + o. The coupled system's coordinates are those of the MultiBody without the mimic
// joints' (same order); the full coordinates are the affine image
//   q_full = G q + o,  alpha_full = G alpha,  alphaD_full = G alphaD,
// with G (full nv x coupled nv) one entry per row. Everything of the coupled system follows from the
// full model: tau = G^T tau_full, H = G^T H_full G, J = J_full G.

#include <string>
#include <vector>

#include <rbd/parsers/urdf.h>

namespace rbd::parsers
{

struct MimicCoupling
{
  /// Per full coordinate (MultiBody param / dof order): the coupled coordinate it follows, its
  /// multiplier and (positions only) its offset. Independent coordinates follow themselves (m = 1, o = 0).
  std::vector<int> qSource, vSource;
  std::vector<double> qMultiplier, qOffset, vMultiplier;
  int nq = 0, nv = 0;                    ///< sizes of the coupled system
  std::vector<std::string> dofJoints;    ///< joint owning each coupled velocity coordinate
  /// One line per coupled mimic joint: "j = m * t + o" (t the independent joint at the end of a chain).
  std::vector<std::string> coupled;

  bool empty() const { return coupled.empty(); }
};

/// Resolve the mimic elements of a loaded robot. Chains (a mimics b mimics c) compose to the
/// independent joint at their end. A mimic joint that is fixed has no coordinate: nothing to couple.
/// Errors (UrdfError, element "joint"): a cycle of mimics, a mimic joint or a followed joint that is
/// not revolute, continuous or prismatic. A mimic of a fixed joint (or of a joint dropped from the
/// model) is kept as an independent joint, with a warning appended to `warnings`.
MimicCoupling coupleMimics(const ParserResult & robot, const std::string & sourceName, std::vector<std::string> * warnings);

/// The identity coupling of a robot (mimic joints as independent joints).
MimicCoupling independentJoints(const rbd::MultiBody & mb);

} // namespace rbd::parsers
