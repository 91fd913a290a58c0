#pragma once
// MultiBody: the immutable, topologically sorted kinematic tree (parent[i] < i).
// Joint i is the joint whose successor is body i; joint 0 is the root joint (predecessor -1).

#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/Body.h>
#include <rbd/Joint.h>

namespace rbd
{

template<typename T>
class MultiBodyTpl
{
public:
  using Scalar = T;
  using BodyT = BodyTpl<T>;
  using JointT = JointTpl<T>;

  MultiBodyTpl() = default;
  /// @param pred  predecessor body of each joint (-1 for the root joint)
  /// @param succ  successor body of each joint
  /// @param parent parent body of each body (-1 for the root)
  /// @param Xt    X_pred_joint: from the predecessor body frame to the joint frame, per joint
  MultiBodyTpl(std::vector<BodyT> bodies,
               std::vector<JointT> joints,
               std::vector<int> pred,
               std::vector<int> succ,
               std::vector<int> parent,
               std::vector<sva::PTransform<T>> Xt);

  int nrBodies() const { return static_cast<int>(bodies_.size()); }
  int nrJoints() const { return static_cast<int>(joints_.size()); }
  /// Size of the flat q vector.
  int nrParams() const { return nrParams_; }
  /// Size of the flat alpha vector.
  int nrDof() const { return nrDof_; }

  const std::vector<BodyT> & bodies() const { return bodies_; }
  const BodyT & body(int i) const { return bodies_[static_cast<std::size_t>(i)]; }
  const std::vector<JointT> & joints() const { return joints_; }
  const JointT & joint(int i) const { return joints_[static_cast<std::size_t>(i)]; }
  const std::vector<int> & predecessors() const { return pred_; }
  int predecessor(int i) const { return pred_[static_cast<std::size_t>(i)]; }
  const std::vector<int> & successors() const { return succ_; }
  int successor(int i) const { return succ_[static_cast<std::size_t>(i)]; }
  const std::vector<int> & parents() const { return parent_; }
  int parent(int i) const { return parent_[static_cast<std::size_t>(i)]; }
  /// X_T: from the predecessor body frame to the joint frame, per joint.
  const std::vector<sva::PTransform<T>> & transforms() const { return Xt_; }
  const sva::PTransform<T> & transform(int i) const { return Xt_[static_cast<std::size_t>(i)]; }

  /// Position of joint i in the flat q vector / alpha vector.
  int jointPosInParam(int i) const { return jointPosInParam_[static_cast<std::size_t>(i)]; }
  int jointPosInDof(int i) const { return jointPosInDof_[static_cast<std::size_t>(i)]; }
  const std::vector<int> & jointsPosInParam() const { return jointPosInParam_; }
  const std::vector<int> & jointsPosInDof() const { return jointPosInDof_; }

  /// Index by name; throws std::out_of_range naming the unknown body or joint.
  int bodyIndexByName(const std::string & name) const { return lookup(bodyIndex_, name, "body"); }
  int jointIndexByName(const std::string & name) const { return lookup(jointIndex_, name, "joint"); }
  bool hasBody(const std::string & name) const { return bodyIndex_.count(name) != 0; }
  bool hasJoint(const std::string & name) const { return jointIndex_.count(name) != 0; }
  const std::map<std::string, int> & bodyIndexByName() const { return bodyIndex_; }
  const std::map<std::string, int> & jointIndexByName() const { return jointIndex_; }

  /// Change joint i's static transform (e.g. the root's X_0_j0 to place a fixed robot in the world).
  void transform(int i, const sva::PTransform<T> & X) { Xt_[static_cast<std::size_t>(i)] = X; }
  /// Replace every static transform (one per joint).
  void transforms(std::vector<sva::PTransform<T>> Xt) { Xt_ = std::move(Xt); }
  /// Replace body i (its name may change: the name index follows).
  void body(int i, const BodyT & b)
  {
    bodies_[static_cast<std::size_t>(i)] = b;
    indexNames();
  }
  /// Replace every body (one per body).
  void bodies(std::vector<BodyT> b)
  {
    bodies_ = std::move(b);
    indexNames();
  }

  // Checked accessors (RBDyn's s-prefixed names): an index or name outside the model throws
  // std::out_of_range; a vector of the wrong size std::domain_error.
  const BodyT & sBody(int i) const { return bodies_.at(at(i)); }
  void sBody(int i, const BodyT & b)
  {
    bodies_.at(at(i));
    body(i, b);
  }
  void sBodies(std::vector<BodyT> b)
  {
    sameSize(b.size(), "bodies");
    bodies(std::move(b));
  }
  const JointT & sJoint(int i) const { return joints_.at(at(i)); }
  int sPredecessor(int i) const { return pred_.at(at(i)); }
  int sSuccessor(int i) const { return succ_.at(at(i)); }
  int sParent(int i) const { return parent_.at(at(i)); }
  const sva::PTransform<T> & sTransform(int i) const { return Xt_.at(at(i)); }
  void sTransform(int i, const sva::PTransform<T> & X) { Xt_.at(at(i)) = X; }
  void sTransforms(std::vector<sva::PTransform<T>> Xt)
  {
    sameSize(Xt.size(), "transforms");
    transforms(std::move(Xt));
  }
  int sJointPosInParam(int i) const { return jointPosInParam_.at(at(i)); }
  int sJointPosInDof(int i) const { return jointPosInDof_.at(at(i)); }
  int sBodyIndexByName(const std::string & name) const { return bodyIndexByName(name); }
  int sJointIndexByName(const std::string & name) const { return jointIndexByName(name); }

  /// The same model in another scalar type (e.g. long double as an accuracy reference).
  template<typename U>
  MultiBodyTpl<U> cast() const
  {
    std::vector<BodyTpl<U>> b;
    std::vector<JointTpl<U>> j;
    std::vector<sva::PTransform<U>> X;
    for(const auto & body : bodies_) b.push_back(body.template cast<U>());
    for(const auto & joint : joints_) j.push_back(joint.template cast<U>());
    for(const auto & x : Xt_) X.push_back(reorthonormalised(x.template cast<U>()));
    return MultiBodyTpl<U>(b, j, pred_, succ_, parent_, X);
  }

private:
  /// In a wider scalar, make the rotation orthonormal to that precision (Newton iteration for the
  /// polar factor, E <- (3 E - E E^T E) / 2), so that E^T = E^-1 holds there too.
  template<typename U>
  static sva::PTransform<U> reorthonormalised(const sva::PTransform<U> & X)
  {
    if(std::numeric_limits<U>::digits <= std::numeric_limits<T>::digits) return X;
    sva::Matrix3<U> E = X.rotation();
    for(int k = 0; k < 3; ++k) E = (U(3) * E - E * E.transpose() * E) / U(2);
    return sva::PTransform<U>(E, X.translation());
  }

  /// A negative index is out of range too (not converted to a huge size_t silently).
  static std::size_t at(int i)
  {
    if(i < 0) throw std::out_of_range("MultiBody: negative index " + std::to_string(i));
    return static_cast<std::size_t>(i);
  }
  void sameSize(std::size_t n, const char * what) const
  {
    if(n != bodies_.size())
      throw std::domain_error(std::string("MultiBody: ") + what + " has " + std::to_string(n) + " entries, expected " +
                              std::to_string(bodies_.size()));
  }
  /// Rebuild the body name index (names must stay unique).
  void indexNames()
  {
    std::map<std::string, int> index;
    for(std::size_t i = 0; i < bodies_.size(); ++i)
      if(!index.emplace(bodies_[i].name(), static_cast<int>(i)).second)
        throw std::domain_error("MultiBody: duplicate body name '" + bodies_[i].name() + "'");
    bodyIndex_ = std::move(index);
  }

  static int lookup(const std::map<std::string, int> & m, const std::string & name, const char * what)
  {
    auto it = m.find(name);
    if(it == m.end()) throw std::out_of_range(std::string("no ") + what + " named '" + name + "'");
    return it->second;
  }

  std::vector<BodyT> bodies_;
  std::vector<JointT> joints_;
  std::vector<int> pred_, succ_, parent_;
  std::vector<sva::PTransform<T>> Xt_;
  std::vector<int> jointPosInParam_, jointPosInDof_;
  int nrParams_ = 0, nrDof_ = 0;
  std::map<std::string, int> bodyIndex_, jointIndex_;
};

using MultiBody = MultiBodyTpl<double>;

template<typename T>
MultiBodyTpl<T>::MultiBodyTpl(std::vector<BodyT> bodies,
                              std::vector<JointT> joints,
                              std::vector<int> pred,
                              std::vector<int> succ,
                              std::vector<int> parent,
                              std::vector<sva::PTransform<T>> Xt)
: bodies_(std::move(bodies)), joints_(std::move(joints)), pred_(std::move(pred)), succ_(std::move(succ)),
  parent_(std::move(parent)), Xt_(std::move(Xt))
{
  const std::size_t n = bodies_.size();
  if(joints_.size() != n || pred_.size() != n || succ_.size() != n || parent_.size() != n || Xt_.size() != n)
    throw std::domain_error("MultiBody: bodies, joints, pred, succ, parent and Xt must have one entry per body");
  for(std::size_t i = 0; i < n; ++i)
  {
    if(parent_[i] >= static_cast<int>(i) || (i > 0 && parent_[i] < 0))
      throw std::domain_error("MultiBody: bodies must be topologically sorted (parent[i] < i)");
    jointPosInParam_.push_back(nrParams_);
    jointPosInDof_.push_back(nrDof_);
    nrParams_ += joints_[i].params();
    nrDof_ += joints_[i].dof();
    if(!jointIndex_.emplace(joints_[i].name(), static_cast<int>(i)).second)
      throw std::domain_error("MultiBody: duplicate joint name '" + joints_[i].name() + "'");
  }
  indexNames();
}

extern template class MultiBodyTpl<double>;
extern template class MultiBodyTpl<long double>;

} // namespace rbd
