#pragma once
// URDF loader: URDF text -> rbd::MultiBodyGraph -> MultiBody + MultiBodyConfig + limits.
//
// Frames: every body frame is its URDF link frame (= the frame of the joint that moves it), so a
// joint is linked as linkBodies(parentLink, X_parent_joint, childLink, Identity, joint). The URDF
// <origin xyz rpy> gives the child frame in the parent with the usual right-handed rotation
// R = Rz(yaw) Ry(pitch) Rx(roll); in sva terms X_parent_joint = PTransform(R^T, xyz).
// When the base link is not the URDF root, joints on the path to the root become backward and
// the bodies they move get the frame of that joint on their side (see bodyBaseTransforms).
//
// Every problem in the file is reported by throwing UrdfError, whose what() is one line:
//   "<file>: <element> '<name>': <reason>"   e.g. "robots/x.urdf: link 'foo': negative mass -1"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/MultiBody.h>
#include <rbd/MultiBodyConfig.h>
#include <rbd/MultiBodyGraph.h>

namespace rbd
{
namespace parsers
{

/// A URDF that cannot be loaded; what() = "<file>: <element> '<name>': <reason>".
class UrdfError : public std::runtime_error
{
public:
  UrdfError(const std::string & file, const std::string & element, const std::string & name, const std::string & reason)
  : std::runtime_error(oneLine(file + ": " + element + " '" + name + "': " + reason)), file_(file), element_(element),
    name_(name), reason_(reason)
  {
  }
  const std::string & file() const { return file_; }
  /// "link", "joint", "robot", "xml" (not well-formed), "file" (cannot be read).
  const std::string & element() const { return element_; }
  const std::string & name() const { return name_; }
  const std::string & reason() const { return reason_; }

private:
  static std::string oneLine(std::string s)
  {
    for(char & c : s)
      if(c == '\n' || c == '\r') c = ' ';
    return s;
  }
  std::string file_, element_, name_, reason_;
};

/// Limits by joint name (every non-Fixed joint). lower/upper have params() entries (±inf when the
/// URDF gives none: continuous, floating, planar), velocity/torque dof() entries (+inf when absent).
struct Limits
{
  std::map<std::string, std::vector<double>> lower, upper, velocity, torque;
};

/// <dynamics damping friction> of a joint (zero when absent).
struct JointDynamics
{
  double damping = 0, friction = 0;
};

/// <mimic joint multiplier offset>: q = multiplier * q_joint + offset (coupled by coupleMimics(),
/// rbd/parsers/MimicCoupling.h; the MultiBody keeps the mimic joint as a joint of its own).
struct Mimic
{
  std::string joint;
  double multiplier = 1, offset = 0;
};

struct ParserOptions
{
  /// Fixed root joint (true) or Free floating base (false); the root joint is named rbd::rootJointName ("Root").
  /// With false, when the base is the URDF root link, that link is massless (no mass, no inertia)
  /// and its only joint is a `floating` one (a URDF that has its own floating base under a
  /// `world` link), that joint is the floating base: the tree is rooted at its child link by the
  /// free joint "Root", the root link and the floating joint are dropped (also from mbg), and a
  /// warning says so. Two stacked free joints would make the mass matrix singular.
  bool fixed = true;
  /// Root body of the MultiBody; empty: the URDF root link.
  std::string baseLink;
  /// Links taken out of the model together with everything beyond them (seen from the base).
  std::vector<std::string> filteredLinks;
  /// true: filtered subtrees are removed; false: they are merged (at q = 0) into their parent
  /// body, so the mass is kept but their joints disappear.
  bool removeFilteredLinks = true;
  /// true: an inertia whose principal moments violate the triangle inequality is an error.
  /// false (default): a warning, as some published URDFs have such inertias (e.g. romeo,
  /// anymal's dummy 1e-6 inertia). An inertia that is not positive semi-definite is always an error.
  bool strictInertia = false;
};

struct ParserResult
{
  rbd::MultiBodyGraph mbg;  ///< every kept link and joint (URDF fixed joints kept as Fixed)
  rbd::MultiBody mb;        ///< tree rooted at the base link
  rbd::MultiBodyConfig mbc; ///< q = zero parameters, FK and FV computed
  Limits limits;
  std::map<std::string, JointDynamics> dynamics; ///< joints with a <dynamics> element
  std::map<std::string, Mimic> mimics;           ///< joints with a <mimic> element
  std::string name;                              ///< <robot name>
  /// "<file>: <element> '<name>': <text>": urdfdom's warnings, inertias violating the triangle
  /// inequality, a URDF floating joint used as the floating base (mimics: coupleMimics()). (Mass matrix hazards are rbdgen's checks, generator/src/model/MassMatrixChecks.h.)
  std::vector<std::string> warnings;
  /// X_b_j per body: from the original URDF link frame to the MultiBody body frame
  /// (identity except for the bodies moved by backward joints when baseLink is not the root).
  std::map<std::string, sva::PTransformd> bodyBaseTransforms;
};

/// ParserResult::bodyBaseTransforms of a tree made from mbg rooted at base: X_b_j per body, the
/// inverse of what MultiBodyGraph::bodiesBaseTransform returns (X_j_b, RBDyn's convention).
std::map<std::string, sva::PTransformd> linkToBodyTransforms(const MultiBodyGraph & mbg, const std::string & base);

/// Load a URDF file. Throws UrdfError (the file name in the message is `path` as given).
ParserResult fromUrdfFile(const std::string & path, const ParserOptions & opt = {});
/// Load URDF text; sourceName stands for the file name in messages.
ParserResult fromUrdfString(const std::string & xml, const ParserOptions & opt = {},
                            const std::string & sourceName = "<string>");

} // namespace parsers
} // namespace rbd
