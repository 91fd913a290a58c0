#pragma once
// Checks of a robot's mass matrix H made before generating code, at q = 0, in one place for
// `rbdgen generate` (a warning, an error with --strict) and `rbdgen info` (printed).
//
//  - massless subtree: a moving joint that moves no mass at all (H has a zero row and column);
//  - stacked free joint: a free joint F whose moved mass lies, but for a negligible part, beyond
//    another moving joint j (a massless link between two free joints, e.g. a URDF's own floating
//    joint under a massless `world` link loaded with a floating base): F's six dofs reproduce any
//    motion of j, so H is singular (exactly when the part between is massless);
//  - negligible inertia: a dof whose effective inertia is negligible relative to the robot's:
//      rotational dof:    S^T Ic S / (M L^2) < kNegligibleRatio
//      translational dof: S^T Ic S / M       < kNegligibleRatio
//    S: the dof's column of the motion subspace (unit axis), Ic: the composite spatial inertia of
//    the subtree the joint moves, M: the robot's total mass, L: its characteristic length (the
//    largest distance from the root body's origin to a link origin or a centre of mass, at least
//    the robot's radius of gyration about the root). S^T Ic S is the diagonal entry of H for that
//    dof at q = 0 (kg m^2 or kg), M L^2 and M the same entry for the whole robot moved rigidly at
//    arm's length, so the ratio is dimensionless. H is symmetric positive definite, so its smallest
//    eigenvalue is at most its smallest diagonal entry and its largest at least its largest one:
//    cond(H) >= max_k H_kk / (r M L^2) (rotational dof), of order 1/r for robots of metre size
//    (measured, docs/DESIGN.md: 1/r within a factor 3), and forward dynamics then loses about
//    -log10(r) digits.

#include <string>
#include <vector>

#include <rbd/MultiBody.h>

namespace rbdgen
{

/// Threshold of the negligible-inertia check (see above and docs/DESIGN.md "Mass matrix checks").
constexpr double kNegligibleRatio = 1e-9;

/// Effective inertia of one dof relative to the robot's.
struct DofInertia
{
  std::string joint;      ///< joint name
  int dof = 0;            ///< index of the dof in the joint
  bool rotational = true; ///< rotational (ratio to M L^2) or translational (ratio to M)
  double ratio = 0.0;     ///< S^T Ic S / (M L^2) or S^T Ic S / M
};

struct MassMatrixReport
{
  double totalMass = 0.0;       ///< M, kg
  double length = 0.0;          ///< L, m
  std::vector<std::string> masslessSubtrees;                  ///< moving joints that move no mass
  std::vector<std::pair<std::string, std::string>> stackedFree; ///< (free joint F, joint j beyond it)
  std::vector<DofInertia> negligible; ///< dofs with 0 < ratio < kNegligibleRatio (massless subtrees excluded)
  DofInertia smallest;          ///< the dof with the smallest ratio (massless subtrees excluded)

  /// One line per finding, "<source>: ..." (no "warning:" prefix); empty when H is fine.
  std::vector<std::string> messages(const std::string & source) const;
};

/// Read mb (joints, bodies, inertias, transforms); evaluate at q = 0.
MassMatrixReport checkMassMatrix(const rbd::MultiBody & mb);

} // namespace rbdgen
