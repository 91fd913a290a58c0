#pragma once
// Size checks used by the checked (s-prefixed) algorithm variants. They throw std::domain_error,
// as RBDyn's checkMatch* (whose names are defined at the end).

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
    throw std::domain_error(std::string(name) + ": " + std::to_string(v.size()) + " joints, model has " +
                                std::to_string(mb.nrJoints()));
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int want = kind == VectorKind::Param ? mb.joint(i).params() : mb.joint(i).dof();
    const auto have = v[static_cast<std::size_t>(i)].size();
    if(static_cast<int>(have) != want)
      throw std::domain_error(std::string(name) + " of joint '" + mb.joint(i).name() + "': " + std::to_string(have) +
                                  " values, expected " + std::to_string(want));
  }
}

/// Throw unless a per-body vector has one entry per body.
template<typename T, typename V>
void checkMatchBodyVector(const MultiBodyTpl<T> & mb, const V & v, const char * name)
{
  if(static_cast<int>(v.size()) != mb.nrBodies())
    throw std::domain_error(std::string(name) + ": " + std::to_string(v.size()) + " bodies, model has " +
                                std::to_string(mb.nrBodies()));
}

// RBDyn's names: each throws std::domain_error when the named vector of mbc does not match mb.
template<typename T, typename V>
void checkMatchBodiesVector(const MultiBodyTpl<T> & mb, const V & v, const std::string & name)
{
  checkMatchBodyVector(mb, v, name.c_str());
}
template<typename T, typename V>
void checkMatchJointsVector(const MultiBodyTpl<T> & mb, const V & v, const std::string & name)
{
  if(static_cast<int>(v.size()) != mb.nrJoints())
    throw std::domain_error(name + ": " + std::to_string(v.size()) + " joints, model has " + std::to_string(mb.nrJoints()));
}
template<typename T>
void checkMatchQ(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.q, "q", VectorKind::Param);
}
template<typename T>
void checkMatchAlpha(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.alpha, "alpha", VectorKind::Dof);
}
template<typename T>
void checkMatchAlphaD(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
}
template<typename T>
void checkMatchJointTorque(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.jointTorque, "jointTorque", VectorKind::Dof);
}
template<typename T>
void checkMatchForce(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchBodyVector(mb, mbc.force, "force");
}
template<typename T>
void checkMatchBodyPos(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
}
template<typename T>
void checkMatchParentToSon(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
}
template<typename T>
void checkMatchBodyVel(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchBodyVector(mb, mbc.bodyVelW, "bodyVelW");
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
}
template<typename T>
void checkMatchBodyAcc(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchBodyVector(mb, mbc.bodyAccB, "bodyAccB");
}
template<typename T>
void checkMatchJointConf(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointsVector(mb, mbc.jointConfig, "jointConfig");
}
template<typename T>
void checkMatchJointVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointsVector(mb, mbc.jointVelocity, "jointVelocity");
}
template<typename T>
void checkMatchMotionSubspace(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointsVector(mb, mbc.motionSubspace, "motionSubspace");
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto & S = mbc.motionSubspace[static_cast<std::size_t>(i)];
    if(S.rows() != 6 || S.cols() != mb.joint(i).dof())
      throw std::domain_error("motionSubspace of joint '" + mb.joint(i).name() + "': " + std::to_string(S.rows()) + "x" +
                              std::to_string(S.cols()) + ", expected 6x" + std::to_string(mb.joint(i).dof()));
  }
}

} // namespace rbd
