#pragma once
// The generator's model of one robot: the runtime MultiBody with fixed joints merged into their
// moving ancestor, constant transforms folded, and a name for everything the emitted code shows.
//
//   moving joint k (dof > 0), topologically sorted: parent moving joint (or -1: the static world
//   part), constant Xt (from the parent's moving body frame to the joint frame), kernel (type, axis,
//   direction), q/alpha offsets, inertia of the moved body with every rigidly attached body merged.
//   body (= every MultiBody body = every URDF link): the moving joint that carries it (or -1) and
//   the constant transform from that joint's body frame to the link frame the user sees.

#include <string>
#include <vector>

#include <rbd/MultiBody.h>

#include "MassMatrixChecks.h"

namespace rbdgen
{

struct MovingJoint
{
  std::string name;         ///< joint name (URDF), rbd::rootJointName for a floating base
  rbd::Joint joint;         ///< kernel: type, axis, direction
  int mbIndex = 0;          ///< joint index in the MultiBody
  int parent = -1;          ///< parent moving joint, -1 when attached to the static part
  sva::PTransformd Xt;      ///< from the parent's body frame (world if parent < 0) to the joint frame
  int qIndex = 0, vIndex = 0, nq = 0, nv = 0;
  sva::RBInertiad inertia;  ///< moved body + rigidly attached bodies, in the moved body's frame
  std::string tag;          ///< short identifier used in emitted local names ("j3")
};

struct BodyFrame
{
  std::string name;         ///< URDF link name
  std::string ident;        ///< C++ identifier (enum value)
  int owner = -1;           ///< moving joint carrying the body, -1: static
  sva::PTransformd X_owner_link; ///< from the owner's body frame (world if owner < 0) to the link frame
  double mass = 0.0;

  /// The link frame is its owner's body frame (X_owner_link is exactly the identity).
  bool atOwnerFrame() const
  {
    return X_owner_link.translation().isZero(0.0) && X_owner_link.rotation().isIdentity(0.0);
  }
};

struct RobotModel
{
  std::string name;          ///< robot name (URDF)
  int nq = 0, nv = 0;
  std::vector<MovingJoint> joints;
  std::vector<BodyFrame> bodies; ///< in MultiBody order
  std::vector<std::string> dofNames; ///< joint owning each velocity coordinate
  double totalMass = 0.0;
  /// Sum of m c (world coordinates) over the bodies that never move (fixed base and its fixed children).
  Eigen::Vector3d staticMoment = Eigen::Vector3d::Zero();
  /// Moving joints whose subtree carries no mass: the mass matrix is singular there.
  std::vector<std::string> masslessSubtrees;
  /// The mass matrix checks of the MultiBody (massless subtrees, stacked free joints, negligible
  /// inertias; see MassMatrixChecks.h).
  MassMatrixReport checks;

  /// false when H is singular by construction (massless subtrees, stacked free joints).
  bool regularMassMatrix() const { return masslessSubtrees.empty() && checks.stackedFree.empty(); }

  /// Ancestors of moving joint k (inclusive), from the root down.
  std::vector<int> path(int k) const;
};

/// Build the generator model from a MultiBody. X_mb_link[i] maps MultiBody body i's frame into its
/// user-visible link frame (identity when the tree is rooted where the URDF is; see
/// rbd::MultiBodyGraph::bodiesBaseTransform, whose inverse this is).
RobotModel buildRobotModel(const rbd::MultiBody & mb, const std::vector<sva::PTransformd> & X_mb_link,
                           const std::string & robotName);

/// Round rotation entries within tol of -1, 0, 1 and translations within tol of 0 to those
/// values (URDF rpy text like 1.5707963 leaves 1e-17-sized noise that would cost operations).
sva::PTransformd snapTransform(const sva::PTransformd & X, double tol = 1e-14);

/// A valid C++ identifier from any name: [A-Za-z0-9_], not starting with a digit, no "__".
std::string sanitizeIdentifier(const std::string & name);

} // namespace rbdgen
