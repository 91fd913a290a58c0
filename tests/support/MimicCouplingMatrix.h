#pragma once
// The coupling of a robot's mimic joints built from its <mimic> elements, independently of the
// loader's rbd::parsers::coupleMimics: q_full = Gq q + o, alpha_full = Gv alpha (a chain of mimics
// composed to the joint at its end; mimics of fixed or non-1-dof joints left independent).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <rbd/parsers/urdf.h>

namespace rbdgentest
{

/// The affine map of the full coordinates on the coupled ones, from the URDF's mimic elements.
struct Coupling
{
  Eigen::MatrixXd Gq, Gv; ///< nq_full x nq, nv_full x nv
  Eigen::VectorXd o;      ///< nq_full
  std::vector<int> own;   ///< per coupled q coordinate, the full q coordinate that is itself
  std::vector<int> ownV;  ///< per coupled velocity coordinate, the full one that is itself
  int mimics = 0;         ///< coupled mimic joints
};

inline Coupling coupling(const rbd::parsers::ParserResult & robot)
{
  const rbd::MultiBody & mb = robot.mb;
  auto movingOneDof = [&](const std::string & name) {
    if(!mb.hasJoint(name)) return false;
    const auto t = mb.joint(mb.jointIndexByName(name)).type();
    return t == rbd::Joint::Rev || t == rbd::Joint::Prism;
  };
  // A mimic joint follows the end of its chain: q = m q_end + o (m, o composed along the chain).
  std::map<std::string, std::pair<std::string, std::pair<double, double>>> follows;
  for(const auto & [name, m] : robot.mimics)
  {
    if(!movingOneDof(name) || !movingOneDof(m.joint)) continue;
    std::string end = m.joint;
    double mult = m.multiplier, off = m.offset;
    while(robot.mimics.count(end) && movingOneDof(robot.mimics.at(end).joint))
    {
      const auto & next = robot.mimics.at(end);
      off += mult * next.offset;
      mult *= next.multiplier;
      end = next.joint;
    }
    follows[name] = {end, {mult, off}};
  }
  std::map<std::string, std::pair<int, int>> coupledPos; // joint -> (q, v) index in the coupled vectors
  int nq = 0, nv = 0;
  for(const rbd::Joint & j : mb.joints())
    if(!follows.count(j.name()))
    {
      coupledPos[j.name()] = {nq, nv};
      nq += j.params();
      nv += j.dof();
    }
  Coupling c;
  c.Gq = Eigen::MatrixXd::Zero(mb.nrParams(), nq);
  c.Gv = Eigen::MatrixXd::Zero(mb.nrDof(), nv);
  c.o = Eigen::VectorXd::Zero(mb.nrParams());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const rbd::Joint & j = mb.joint(i);
    const int qi = mb.jointPosInParam(i), vi = mb.jointPosInDof(i);
    if(const auto it = follows.find(j.name()); it != follows.end())
    {
      const auto [q0, v0] = coupledPos.at(it->second.first);
      c.Gq(qi, q0) = c.Gv(vi, v0) = it->second.second.first;
      c.o(qi) = it->second.second.second;
      ++c.mimics;
      continue;
    }
    const auto [q0, v0] = coupledPos.at(j.name());
    for(int k = 0; k < j.params(); ++k) c.Gq(qi + k, q0 + k) = 1, c.own.push_back(qi + k);
    for(int k = 0; k < j.dof(); ++k) c.Gv(vi + k, v0 + k) = 1, c.ownV.push_back(vi + k);
  }
  return c;
}

} // namespace rbdgentest
