#pragma once
// Size checks used by the checked (s-prefixed) algorithm variants. They throw std::invalid_argument.

#include <stdexcept>
#include <string>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

enum class VectorKind
{
  Param,
  Dof
};

/// Throw unless v has one entry per joint of mb with params() (Param) or dof() (Dof) values.
template<typename T>
void checkMatchJointVector(const MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v, const char * name,
                           VectorKind kind)
{
  if(static_cast<int>(v.size()) != mb.nrJoints())
    throw std::invalid_argument(std::string(name) + ": " + std::to_string(v.size()) + " joints, model has " +
                                std::to_string(mb.nrJoints()));
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int want = kind == VectorKind::Param ? mb.joint(i).params() : mb.joint(i).dof();
    const auto have = v[static_cast<std::size_t>(i)].size();
    if(static_cast<int>(have) != want)
      throw std::invalid_argument(std::string(name) + " of joint '" + mb.joint(i).name() + "': " + std::to_string(have) +
                                  " values, expected " + std::to_string(want));
  }
}

/// Throw unless a per-body vector has one entry per body.
template<typename T, typename V>
void checkMatchBodyVector(const MultiBodyTpl<T> & mb, const V & v, const char * name)
{
  if(static_cast<int>(v.size()) != mb.nrBodies())
    throw std::invalid_argument(std::string(name) + ": " + std::to_string(v.size()) + " bodies, model has " +
                                std::to_string(mb.nrBodies()));
}

} // namespace rbd
