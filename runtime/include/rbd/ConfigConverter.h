#pragma once
// ConfigConverter: copy a configuration between two MultiBodies made from the same
// MultiBodyGraph with different roots. Joints and bodies are matched by name; the root joints
// are skipped (their q and alpha mean different things). Backward joints keep the q and alpha of
// their forward twin (docs/DESIGN.md), so values are copied unchanged.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

template<typename T>
class ConfigConverterTpl
{
public:
  /// Match by name the joints (but the roots) present in both models with the same type and sizes,
  /// and the bodies present in both.
  ConfigConverterTpl(const MultiBodyTpl<T> & mb1, const MultiBodyTpl<T> & mb2);

  /// Checked construction: throws std::domain_error unless both models have the same bodies and
  /// the same non-root joints (names, types, params and dof).
  static ConfigConverterTpl sConstructor(const MultiBodyTpl<T> & mb1, const MultiBodyTpl<T> & mb2);

  /// Use q, alpha, alphaD, jointTorque (non-root joints) and force (bodies) of mbc1.
  /// Fill the same fields of mbc2 (its root joint and unmatched entries are left untouched).
  void convert(const MultiBodyConfigTpl<T> & mbc1, MultiBodyConfigTpl<T> & mbc2) const;
  /// Checked variant: throws std::domain_error when a vector does not match its model.
  void sConvert(const MultiBodyConfigTpl<T> & mbc1, MultiBodyConfigTpl<T> & mbc2) const;

  /// Per-joint values (q-like, alpha-like, or any per-joint V) in mb1's joint order -> mb2's joint
  /// order (the root joint's entry of v2 is left untouched).
  template<typename V>
  void convertJoint(const std::vector<V> & v1, std::vector<V> & v2) const
  {
    for(const auto & [i1, i2] : jointMap_) v2[static_cast<std::size_t>(i2)] = v1[static_cast<std::size_t>(i1)];
  }
  /// Same into a new vector of v1's size (RBDyn's form; unmatched entries value-initialised).
  template<typename V>
  std::vector<V> convertJoint(const std::vector<V> & v1) const
  {
    std::vector<V> v2(v1.size());
    convertJoint(v1, v2);
    return v2;
  }
  /// Checked variant: std::domain_error unless v1 and v2 have one entry per joint of their model.
  template<typename V>
  void sConvertJoint(const std::vector<V> & v1, std::vector<V> & v2) const
  {
    if(static_cast<int>(v1.size()) != mb1_.nrJoints() || static_cast<int>(v2.size()) != mb2_.nrJoints())
      throw std::domain_error("ConfigConverter: the per-joint vectors do not match the models");
    convertJoint(v1, v2);
  }
  /// Per-body values in mb1's body order -> mb2's body order.
  template<typename V>
  void convertBody(const std::vector<V> & v1, std::vector<V> & v2) const
  {
    for(const auto & [i1, i2] : bodyMap_) v2[static_cast<std::size_t>(i2)] = v1[static_cast<std::size_t>(i1)];
  }

  /// (index in mb1, index in mb2) of each matched joint / body.
  const std::vector<std::pair<int, int>> & jointMap() const { return jointMap_; }
  const std::vector<std::pair<int, int>> & bodyMap() const { return bodyMap_; }

private:
  std::vector<std::pair<int, int>> jointMap_, bodyMap_;
  MultiBodyTpl<T> mb1_, mb2_; ///< kept for the checked variants
};

using ConfigConverter = ConfigConverterTpl<double>;

template<typename T>
ConfigConverterTpl<T>::ConfigConverterTpl(const MultiBodyTpl<T> & mb1, const MultiBodyTpl<T> & mb2) : mb1_(mb1), mb2_(mb2)
{
  for(int i = 1; i < mb1.nrJoints(); ++i)
  {
    const std::string & name = mb1.joint(i).name();
    if(!mb2.hasJoint(name)) continue;
    const int k = mb2.jointIndexByName(name);
    const JointTpl<T> &j1 = mb1.joint(i), &j2 = mb2.joint(k);
    if(k != 0 && j1.type() == j2.type() && j1.params() == j2.params() && j1.dof() == j2.dof()) jointMap_.emplace_back(i, k);
  }
  for(int i = 0; i < mb1.nrBodies(); ++i)
    if(mb2.hasBody(mb1.body(i).name())) bodyMap_.emplace_back(i, mb2.bodyIndexByName(mb1.body(i).name()));
}

template<typename T>
ConfigConverterTpl<T> ConfigConverterTpl<T>::sConstructor(const MultiBodyTpl<T> & mb1, const MultiBodyTpl<T> & mb2)
{
  if(mb1.nrBodies() != mb2.nrBodies())
    throw std::domain_error("ConfigConverter: the models have " + std::to_string(mb1.nrBodies()) + " and " +
                                std::to_string(mb2.nrBodies()) + " bodies");
  for(const auto & b : mb1.bodies())
    if(!mb2.hasBody(b.name()))
      throw std::domain_error("ConfigConverter: body '" + b.name() + "' is missing from the second model");
  for(int i = 1; i < mb1.nrJoints(); ++i)
  {
    const JointTpl<T> & j1 = mb1.joint(i);
    if(!mb2.hasJoint(j1.name()) || mb2.jointIndexByName(j1.name()) == 0)
      throw std::domain_error("ConfigConverter: joint '" + j1.name() + "' is not a non-root joint of the second model");
    const JointTpl<T> & j2 = mb2.joint(mb2.jointIndexByName(j1.name()));
    if(j1.type() != j2.type() || j1.params() != j2.params() || j1.dof() != j2.dof())
      throw std::domain_error("ConfigConverter: joint '" + j1.name() + "' differs between the models");
  }
  return ConfigConverterTpl(mb1, mb2);
}

template<typename T>
void ConfigConverterTpl<T>::convert(const MultiBodyConfigTpl<T> & mbc1, MultiBodyConfigTpl<T> & mbc2) const
{
  convertJoint(mbc1.q, mbc2.q);
  convertJoint(mbc1.alpha, mbc2.alpha);
  convertJoint(mbc1.alphaD, mbc2.alphaD);
  convertJoint(mbc1.jointTorque, mbc2.jointTorque);
  // force is in world coordinates at the world origin: independent of the body frames.
  convertBody(mbc1.force, mbc2.force);
}

extern template class ConfigConverterTpl<double>;
extern template class ConfigConverterTpl<long double>;

} // namespace rbd
