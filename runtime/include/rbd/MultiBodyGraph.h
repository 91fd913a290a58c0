#pragma once
// MultiBodyGraph: an undirected graph of bodies linked by joints, from which MultiBody trees are
// made with any body as the root. Bodies and joints are identified by their names.
//
// linkBodies(b1, X_b1_j, b2, X_b2_j, joint, isB1toB2): X_b1_j goes from the frame of b1 to the joint
// frame on b1's side, X_b2_j from the frame of b2 to the joint frame on b2's side. The joint moves b2
// w.r.t. b1 (its pose maps b1's joint frame into b2's joint frame) when isB1toB2 == joint.forward()
// (RBDyn: a joint added backward, linked b1 -> b2, moves b1 w.r.t. b2).
//
// makeMultiBody() puts each body's frame on its parent joint's frame (RBDyn convention): body
// inertias are moved there, and bodiesBaseTransform() gives, per body, X_j_b: from that new frame
// back to the body's original frame (RBDyn's X_nb_b: original pose = X_j_b * bodyPosW).

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <rbd/MultiBody.h>

namespace rbd
{

/// The name of the root joint makeMultiBody creates (reserved: no graph joint may have it).
inline constexpr const char * rootJointName = "Root";

template<typename T>
class MultiBodyGraphTpl
{
public:
  using BodyT = BodyTpl<T>;
  using JointT = JointTpl<T>;
  using PTransformT = sva::PTransform<T>;

  /// One edge of the graph, as given to linkBodies.
  struct Link
  {
    std::string b1;
    PTransformT X_b1_j;
    std::string b2;
    PTransformT X_b2_j;
    std::string joint;
    bool isB1toB2;
  };

  /// One link seen from a body (RBDyn's MultiBodyGraph::Arc): X from the body's frame to the joint
  /// frame on its side, the joint with the direction it has from this body, the other body's name.
  struct Arc
  {
    PTransformT X;
    JointT joint;
    std::string next;
  };
  /// A body and its links (RBDyn's MultiBodyGraph::Node). nodeByName returns a copy: the graph
  /// keeps bodies and links by name, so Arc::next names the other body instead of pointing to it.
  struct Node
  {
    BodyT body;
    std::vector<Arc> arcs;
  };

  void addBody(const BodyT & b);
  void addJoint(const JointT & j);
  void linkBodies(const std::string & b1Name, const PTransformT & X_b1_j, const std::string & b2Name,
                  const PTransformT & X_b2_j, const std::string & jointName, bool isB1toB2 = true);

  /// Tree rooted at rootBodyName, attached to the world by a Fixed (isFixed) or Free root joint.
  MultiBodyTpl<T> makeMultiBody(const std::string & rootBodyName, bool isFixed,
                                const PTransformT & X_0_j0 = PTransformT::Identity(),
                                const PTransformT & X_b0_j0 = PTransformT::Identity()) const;
  /// Tree rooted at rootBodyName with a root joint of any type (named rootJointName).
  MultiBodyTpl<T> makeMultiBody(const std::string & rootBodyName, JointType::Type rootJointType,
                                const PTransformT & X_0_j0 = PTransformT::Identity(),
                                const PTransformT & X_b0_j0 = PTransformT::Identity()) const;
  /// Tree rooted at rootBodyName with the given root joint (axis, name...).
  MultiBodyTpl<T> makeMultiBody(const std::string & rootBodyName, const JointT & rootJoint,
                                const PTransformT & X_0_j0 = PTransformT::Identity(),
                                const PTransformT & X_b0_j0 = PTransformT::Identity()) const;

  /// Remove a joint and every body and joint beyond it (seen from rootBodyName).
  void removeJoint(const std::string & rootBodyName, const std::string & jointName);
  void removeJoints(const std::string & rootBodyName, const std::vector<std::string> & jointNames);

  /// Merge the bodies beyond jointName (seen from rootBodyName) into the joint's body on the root
  /// side, with the joints of that subtree held at jointPosByName (missing: zeroParam()).
  void mergeSubBodies(const std::string & rootBodyName, const std::string & jointName,
                      const std::map<std::string, std::vector<T>> & jointPosByName);

  /// Make each named joint Fixed, holding it at the given configuration.
  void fixJoints(const std::map<std::string, std::vector<T>> & jointPosByName);
  /// RBDyn's form: a copy of `other` with the named joints (every joint with fixAllJoints) made
  /// Fixed at their zero configuration (zeroParam()).
  static MultiBodyGraphTpl fixJoints(const MultiBodyGraphTpl & other, const std::vector<std::string> & jointsToFix,
                                     bool fixAllJoints = false)
  {
    MultiBodyGraphTpl g = other;
    std::map<std::string, std::vector<T>> zero;
    for(const JointT & j : other.joints())
      if(fixAllJoints || std::find(jointsToFix.begin(), jointsToFix.end(), j.name()) != jointsToFix.end())
        zero.emplace(j.name(), j.zeroParam());
    for(const std::string & name : jointsToFix) other.joint(name); // unknown names: std::out_of_range
    g.fixJoints(zero);
    return g;
  }

  /// For every body, X_j_b: from its frame in makeMultiBody(rootBodyName, ..., X_b0_j0) back to its
  /// original frame, so that X_0_b = X_j_b * bodyPosW (RBDyn's result).
  std::map<std::string, PTransformT> bodiesBaseTransform(const std::string & rootBodyName,
                                                         const PTransformT & X_b0_j0 = PTransformT::Identity()) const;
  /// For every body, the names of the joints it supports, seen from rootBodyName.
  std::map<std::string, std::vector<std::string>> successorJoints(const std::string & rootBodyName) const;
  /// For every body but the root, the name of the joint that moves it, seen from rootBodyName.
  std::map<std::string, std::string> predecessorJoint(const std::string & rootBodyName) const;

  std::size_t nrNodes() const { return bodies_.size(); }
  std::size_t nrJoints() const { return joints_.size(); }
  const std::vector<BodyT> & bodies() const { return bodies_; }
  const std::vector<JointT> & joints() const { return joints_; }
  const std::vector<Link> & links() const { return links_; }
  const BodyT & body(const std::string & name) const { return bodies_[bodyPos(name)]; }
  const JointT & joint(const std::string & name) const { return joints_[jointPos(name)]; }
  /// The body and its links; throws std::out_of_range for an unknown name.
  std::shared_ptr<const Node> nodeByName(const std::string & name) const;
  /// The joint as added; throws std::out_of_range for an unknown name.
  std::shared_ptr<const JointT> jointByName(const std::string & name) const
  {
    return std::make_shared<const JointT>(joint(name));
  }
  bool hasBody(const std::string & name) const;
  bool hasJoint(const std::string & name) const;
  void clear();

private:
  /// An edge seen from one of its bodies.
  struct Side
  {
    std::size_t link;
    PTransformT X_here_j;  ///< from this body's frame to the joint frame on this side
    PTransformT X_there_j; ///< from the other body's frame to the joint frame on its side
    std::string next;      ///< the other body
    bool forward;          ///< the joint moves `next` w.r.t. this body
  };
  /// One body of a tree walk from a root: how it was reached.
  struct Visit
  {
    std::string body;
    int parent;          ///< index of the parent visit, -1 for the root
    std::size_t link;    ///< link used to reach it (unused for the root)
    PTransformT X_b_j;   ///< from the body's original frame to its joint frame
    PTransformT Xt;      ///< from the parent's (moved) frame to the joint frame
    bool forward;
  };

  std::vector<Side> sides(const std::string & body) const;
  std::vector<Visit> walk(const std::string & rootBodyName, const PTransformT & X_b0_j0) const;
  std::size_t bodyPos(const std::string & name) const;
  /// The link's joint moves b2 w.r.t. b1 (isB1toB2 == the joint's forward()).
  bool movesB2(const Link & l) const;
  std::size_t jointPos(const std::string & name) const;
  std::vector<std::string> subtreeBeyond(const std::string & rootBodyName, const std::string & jointName,
                                         std::string * rootSideBody) const;

  std::vector<BodyT> bodies_;
  std::vector<JointT> joints_;
  std::vector<Link> links_;
};

using MultiBodyGraph = MultiBodyGraphTpl<double>;

// Defined in src/MultiBodyGraph.cpp for double and long double.
extern template class MultiBodyGraphTpl<double>;
extern template class MultiBodyGraphTpl<long double>;

} // namespace rbd

