// MultiBodyGraph: graph editing and tree extraction (see rbd/MultiBodyGraph.h).
#include <rbd/MultiBodyGraph.h>

#include <algorithm>
#include <functional>
#include <set>
#include <stdexcept>

namespace rbd
{

template<typename T>
void MultiBodyGraphTpl<T>::addBody(const BodyT & b)
{
  if(b.name().empty()) throw std::domain_error("MultiBodyGraph: body name must not be empty");
  if(hasBody(b.name())) throw std::domain_error("MultiBodyGraph: duplicate body name '" + b.name() + "'");
  bodies_.push_back(b);
}

template<typename T>
void MultiBodyGraphTpl<T>::addJoint(const JointT & j)
{
  if(j.name().empty()) throw std::domain_error("MultiBodyGraph: joint name must not be empty");
  if(j.name() == rootJointName)
    throw std::domain_error(std::string("MultiBodyGraph: joint name '") + rootJointName + "' is reserved");
  if(hasJoint(j.name())) throw std::domain_error("MultiBodyGraph: duplicate joint name '" + j.name() + "'");
  joints_.push_back(j);
}

template<typename T>
void MultiBodyGraphTpl<T>::linkBodies(const std::string & b1Name, const PTransformT & X_b1_j,
                                      const std::string & b2Name, const PTransformT & X_b2_j,
                                      const std::string & jointName, bool isB1toB2)
{
  bodyPos(b1Name);
  bodyPos(b2Name);
  jointPos(jointName);
  if(b1Name == b2Name) throw std::domain_error("MultiBodyGraph: joint '" + jointName + "' links body '" + b1Name + "' to itself");
  for(const Link & l : links_)
    if(l.joint == jointName)
      throw std::domain_error("MultiBodyGraph: joint '" + jointName + "' already links two bodies");
  links_.push_back(Link{b1Name, X_b1_j, b2Name, X_b2_j, jointName, isB1toB2});
}

template<typename T>
std::shared_ptr<const typename MultiBodyGraphTpl<T>::Node> MultiBodyGraphTpl<T>::nodeByName(const std::string & name) const
{
  auto node = std::make_shared<Node>(Node{body(name), {}});
  for(const Side & s : sides(name))
  {
    JointT j = joint(links_[s.link].joint);
    j.forward(s.forward);
    node->arcs.push_back(Arc{s.X_here_j, j, s.next});
  }
  return node;
}

template<typename T>
bool MultiBodyGraphTpl<T>::movesB2(const Link & l) const
{
  return l.isB1toB2 == joint(l.joint).forward();
}

template<typename T>
bool MultiBodyGraphTpl<T>::hasBody(const std::string & name) const
{
  return std::any_of(bodies_.begin(), bodies_.end(), [&](const BodyT & b) { return b.name() == name; });
}

template<typename T>
bool MultiBodyGraphTpl<T>::hasJoint(const std::string & name) const
{
  return std::any_of(joints_.begin(), joints_.end(), [&](const JointT & j) { return j.name() == name; });
}

template<typename T>
std::size_t MultiBodyGraphTpl<T>::bodyPos(const std::string & name) const
{
  for(std::size_t i = 0; i < bodies_.size(); ++i)
    if(bodies_[i].name() == name) return i;
  throw std::out_of_range("MultiBodyGraph: no body named '" + name + "'");
}

template<typename T>
std::size_t MultiBodyGraphTpl<T>::jointPos(const std::string & name) const
{
  for(std::size_t i = 0; i < joints_.size(); ++i)
    if(joints_[i].name() == name) return i;
  throw std::out_of_range("MultiBodyGraph: no joint named '" + name + "'");
}

template<typename T>
void MultiBodyGraphTpl<T>::clear()
{
  bodies_.clear();
  joints_.clear();
  links_.clear();
}

template<typename T>
std::vector<typename MultiBodyGraphTpl<T>::Side> MultiBodyGraphTpl<T>::sides(const std::string & body) const
{
  std::vector<Side> out;
  for(std::size_t k = 0; k < links_.size(); ++k)
  {
    const Link & l = links_[k];
    const bool b1MovesB2 = movesB2(l);
    if(l.b1 == body) out.push_back(Side{k, l.X_b1_j, l.X_b2_j, l.b2, b1MovesB2});
    else if(l.b2 == body) out.push_back(Side{k, l.X_b2_j, l.X_b1_j, l.b1, !b1MovesB2});
  }
  return out;
}

// Depth-first walk in link order: visits come out topologically sorted (parent before child).
template<typename T>
std::vector<typename MultiBodyGraphTpl<T>::Visit> MultiBodyGraphTpl<T>::walk(const std::string & rootBodyName,
                                                                             const PTransformT & X_b0_j0) const
{
  bodyPos(rootBodyName);
  std::vector<Visit> visits;
  std::set<std::string> seen;
  std::function<void(const Visit &)> visit = [&](const Visit & v) {
    seen.insert(v.body);
    visits.push_back(v);
    const int me = static_cast<int>(visits.size()) - 1;
    const PTransformT X_j_b = v.X_b_j.inv();
    for(const Side & a : sides(v.body))
    {
      if(me > 0 && a.link == visits[static_cast<std::size_t>(me)].link) continue;
      if(seen.count(a.next))
        throw std::domain_error("MultiBodyGraph: joint '" + links_[a.link].joint +
                                    "' closes a kinematic loop (body '" + a.next + "' reached twice)");
      // Xt: from this body's moved frame (its joint frame) to the child joint frame on this side.
      visit(Visit{a.next, me, a.link, a.X_there_j, a.X_here_j * X_j_b, a.forward});
    }
  };
  visit(Visit{rootBodyName, -1, links_.size(), X_b0_j0, PTransformT::Identity(), true});
  return visits;
}

template<typename T>
MultiBodyTpl<T> MultiBodyGraphTpl<T>::makeMultiBody(const std::string & rootBodyName, bool isFixed,
                                                    const PTransformT & X_0_j0, const PTransformT & X_b0_j0) const
{
  return makeMultiBody(rootBodyName, isFixed ? JointType::Fixed : JointType::Free, X_0_j0, X_b0_j0);
}

template<typename T>
MultiBodyTpl<T> MultiBodyGraphTpl<T>::makeMultiBody(const std::string & rootBodyName, JointType::Type rootJointType,
                                                    const PTransformT & X_0_j0, const PTransformT & X_b0_j0) const
{
  return makeMultiBody(rootBodyName, JointT(rootJointType, true, rootJointName), X_0_j0, X_b0_j0);
}

template<typename T>
MultiBodyTpl<T> MultiBodyGraphTpl<T>::makeMultiBody(const std::string & rootBodyName, const JointT & rootJoint,
                                                    const PTransformT & X_0_j0, const PTransformT & X_b0_j0) const
{
  std::vector<BodyT> bodies;
  std::vector<JointT> joints;
  std::vector<int> pred, succ, parent;
  std::vector<PTransformT> Xt;
  for(const Visit & v : walk(rootBodyName, X_b0_j0))
  {
    const BodyT & b = body(v.body);
    // I_j = X_b_j^* I_b X_b_j^-1: the inertia seen from the body's new frame.
    bodies.emplace_back(v.X_b_j.dualMul(b.inertia()), b.name());
    if(v.parent < 0)
    {
      joints.push_back(rootJoint);
      Xt.push_back(X_0_j0);
    }
    else
    {
      JointT j = joint(links_[v.link].joint);
      j.forward(v.forward);
      joints.push_back(j);
      Xt.push_back(v.Xt);
    }
    pred.push_back(v.parent);
    succ.push_back(static_cast<int>(succ.size()));
    parent.push_back(v.parent);
  }
  return MultiBodyTpl<T>(bodies, joints, pred, succ, parent, Xt);
}

template<typename T>
std::map<std::string, typename MultiBodyGraphTpl<T>::PTransformT>
MultiBodyGraphTpl<T>::bodiesBaseTransform(const std::string & rootBodyName, const PTransformT & X_b0_j0) const
{
  std::map<std::string, PTransformT> out;
  for(const Visit & v : walk(rootBodyName, X_b0_j0)) out.emplace(v.body, v.X_b_j.inv());
  return out;
}

template<typename T>
std::map<std::string, std::vector<std::string>> MultiBodyGraphTpl<T>::successorJoints(const std::string & rootBodyName) const
{
  const std::vector<Visit> visits = walk(rootBodyName, PTransformT::Identity());
  std::map<std::string, std::vector<std::string>> out;
  for(const Visit & v : visits) out[v.body];
  for(const Visit & v : visits)
    if(v.parent >= 0) out[visits[static_cast<std::size_t>(v.parent)].body].push_back(links_[v.link].joint);
  return out;
}

template<typename T>
std::map<std::string, std::string> MultiBodyGraphTpl<T>::predecessorJoint(const std::string & rootBodyName) const
{
  std::map<std::string, std::string> out;
  for(const Visit & v : walk(rootBodyName, PTransformT::Identity()))
    if(v.parent >= 0) out.emplace(v.body, links_[v.link].joint);
  return out;
}

// Bodies beyond jointName seen from rootBodyName (the first is the joint's far body).
template<typename T>
std::vector<std::string> MultiBodyGraphTpl<T>::subtreeBeyond(const std::string & rootBodyName,
                                                             const std::string & jointName,
                                                             std::string * rootSideBody) const
{
  jointPos(jointName);
  const std::vector<Visit> visits = walk(rootBodyName, PTransformT::Identity());
  std::vector<std::string> out;
  std::set<int> inside;
  for(std::size_t i = 0; i < visits.size(); ++i)
  {
    const Visit & v = visits[i];
    const bool isCut = v.parent >= 0 && links_[v.link].joint == jointName;
    if(isCut && rootSideBody) *rootSideBody = visits[static_cast<std::size_t>(v.parent)].body;
    if(isCut || (v.parent >= 0 && inside.count(v.parent)))
    {
      inside.insert(static_cast<int>(i));
      out.push_back(v.body);
    }
  }
  if(out.empty())
    throw std::domain_error("MultiBodyGraph: joint '" + jointName + "' is not reachable from body '" + rootBodyName + "'");
  return out;
}

template<typename T>
void MultiBodyGraphTpl<T>::removeJoint(const std::string & rootBodyName, const std::string & jointName)
{
  const std::vector<std::string> gone = subtreeBeyond(rootBodyName, jointName, nullptr);
  const std::set<std::string> goneSet(gone.begin(), gone.end());
  std::set<std::string> goneJoints{jointName};
  for(const Link & l : links_)
    if(goneSet.count(l.b1) || goneSet.count(l.b2)) goneJoints.insert(l.joint);
  links_.erase(std::remove_if(links_.begin(), links_.end(), [&](const Link & l) { return goneJoints.count(l.joint) != 0; }),
               links_.end());
  joints_.erase(std::remove_if(joints_.begin(), joints_.end(), [&](const JointT & j) { return goneJoints.count(j.name()) != 0; }),
                joints_.end());
  bodies_.erase(std::remove_if(bodies_.begin(), bodies_.end(), [&](const BodyT & b) { return goneSet.count(b.name()) != 0; }),
                bodies_.end());
}

template<typename T>
void MultiBodyGraphTpl<T>::removeJoints(const std::string & rootBodyName, const std::vector<std::string> & jointNames)
{
  for(const std::string & j : jointNames)
    if(hasJoint(j)) removeJoint(rootBodyName, j);
}

template<typename T>
void MultiBodyGraphTpl<T>::mergeSubBodies(const std::string & rootBodyName, const std::string & jointName,
                                          const std::map<std::string, std::vector<T>> & jointPosByName)
{
  std::string keeper;
  const std::vector<std::string> merged = subtreeBeyond(rootBodyName, jointName, &keeper);
  // Original frame of each body relative to the keeper's original frame: X_keeper_b, composed
  // along the walk as X_b_j^-1 * X_j(q) * X_p_j (parent frame -> joint -> child frame).
  const std::vector<Visit> visits = walk(keeper, PTransformT::Identity());
  std::vector<PTransformT> X_k_b(visits.size(), PTransformT::Identity());
  sva::RBInertia<T> I = body(keeper).inertia();
  const std::set<std::string> mergedSet(merged.begin(), merged.end());
  for(std::size_t i = 1; i < visits.size(); ++i)
  {
    const Visit & v = visits[i];
    if(!mergedSet.count(v.body)) continue;
    const Link & l = links_[v.link];
    JointT j = joint(l.joint);
    j.forward(v.forward);
    auto it = jointPosByName.find(l.joint);
    const std::vector<T> q = it != jointPosByName.end() ? it->second : j.zeroParam();
    if(static_cast<int>(q.size()) != j.params())
      throw std::domain_error("MultiBodyGraph: wrong number of parameters for joint '" + l.joint + "'");
    const PTransformT X_p_jp = (l.b2 == v.body) ? l.X_b1_j : l.X_b2_j; // parent side
    const PTransformT X_k_p = X_k_b[static_cast<std::size_t>(v.parent)];
    X_k_b[i] = v.X_b_j.inv() * j.pose(q) * X_p_jp * X_k_p;
    // I_k += X_k_b^T I_b X_k_b
    I = I + X_k_b[i].transMul(body(v.body).inertia());
  }
  const std::string keeperName = keeper;
  removeJoint(rootBodyName, jointName);
  bodies_[bodyPos(keeperName)] = BodyT(I, keeperName);
}

template<typename T>
void MultiBodyGraphTpl<T>::fixJoints(const std::map<std::string, std::vector<T>> & jointPosByName)
{
  for(const auto & [name, q] : jointPosByName)
  {
    JointT & j = joints_[jointPos(name)];
    if(static_cast<int>(q.size()) != j.params())
      throw std::domain_error("MultiBodyGraph: wrong number of parameters for joint '" + name + "'");
    const PTransformT P = j.pose(q);
    for(Link & l : links_)
    {
      if(l.joint != name) continue;
      // Keep X_b1_b2 = X_b2_j^-1 P X_b1_j (or its inverse when the joint goes b2 -> b1).
      if(movesB2(l)) l.X_b2_j = P.inv() * l.X_b2_j;
      else l.X_b1_j = P.inv() * l.X_b1_j;
    }
    j = JointT(JointType::Fixed, j.forward(), name);
  }
}

template class MultiBodyGraphTpl<double>;
template class MultiBodyGraphTpl<long double>;

} // namespace rbd
