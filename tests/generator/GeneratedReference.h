#pragma once
// The runtime model of a generated robot (same URDF and options): the reference of the tests.
#include <algorithm>

#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/parsers/urdf.h>

#include "GeneratedRobot.h"
#include "ProgrammaticModels.h"
#include "TestModels.h"

namespace rbdgentest
{

/// The runtime model of the same URDF, with the link frames the generated code reports.
struct Reference
{
  rbd::parsers::ParserResult robot;
  std::vector<sva::PTransformd> X_mb_link; // MultiBody body frame -> URDF link frame
  rbd::MultiBodyConfig mbc;

  explicit Reference(const GeneratedRobot & g)
  {
    if(g.programmaticModel >= 0)
      robot.mb = rbdgentest::programmaticModel(g.programmaticModel).mb;
    else
    {
      rbd::parsers::ParserOptions opt;
      opt.fixed = !g.floatingBase;
      opt.baseLink = g.baseLink;
      robot = rbd::parsers::fromUrdfFile(g.urdf, opt);
    }
    for(const auto & b : robot.mb.bodies())
    {
      const auto it = robot.bodyBaseTransforms.find(b.name());
      X_mb_link.push_back(it == robot.bodyBaseTransforms.end() ? sva::PTransformd::Identity() : it->second.inv());
    }
    mbc = rbd::MultiBodyConfig(robot.mb);
  }
  const rbd::MultiBody & mb() const { return robot.mb; }

  void sample(rbdtest::Rng & rng)
  {
    rbdtest::randomState(rng, mb(), mbc);
    rbd::forwardKinematics(mb(), mbc);
    rbd::forwardVelocity(mb(), mbc);
  }
  Eigen::VectorXd q() const { return rbd::paramToVector(mb(), mbc.q); }
  Eigen::VectorXd alpha() const { return rbd::dofToVector(mb(), mbc.alpha); }
  Eigen::VectorXd alphaD() const { return rbd::dofToVector(mb(), mbc.alphaD); }
  Eigen::VectorXd torque() const { return rbd::dofToVector(mb(), mbc.jointTorque); }

  /// Runtime inverse dynamics with the selected terms.
  Eigen::VectorXd id(bool velocity, bool acceleration, bool gravity) const
  {
    rbd::MultiBodyConfig c = mbc;
    if(!velocity)
      for(auto & a : c.alpha) std::fill(a.begin(), a.end(), 0.0);
    if(!acceleration)
      for(auto & a : c.alphaD) std::fill(a.begin(), a.end(), 0.0);
    if(!gravity) c.gravity.setZero();
    rbd::forwardVelocity(mb(), c);
    rbd::InverseDynamics idr(mb());
    idr.inverseDynamics(mb(), c);
    return rbd::dofToVector(mb(), c.jointTorque);
  }
};

} // namespace rbdgentest
