#include "Reference.h"

#include <cmath>
#include <initializer_list>
#include <limits>

#include <Eigen/Eigenvalues>

#include <rbd/FD.h>
#include <rbd/FDDerivatives.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>

#include "PoseLayout.h"

namespace rbdgen::accuracy
{

Eigen::VectorXd flattenPoses(const rbd::parsers::ParserResult & robot, const std::vector<sva::PTransformd> & bodyPosW)
{
  return flattenPosesT<double>(robot, bodyPosW);
}

/// Matrices side by side, column-major, rounded to double.
static Eigen::VectorXd flattenBlocks(std::initializer_list<const Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> *> blocks)
{
  Eigen::Index n = 0;
  for(const auto * m : blocks) n += m->size();
  Eigen::VectorXd v(n);
  n = 0;
  for(const auto * m : blocks)
  {
    v.segment(n, m->size()) = Eigen::Map<const Eigen::Matrix<long double, Eigen::Dynamic, 1>>(m->data(), m->size()).cast<double>();
    n += m->size();
  }
  return v;
}

Reference computeReference(const rbd::parsers::ParserResult & robot, const std::vector<State> & states, bool derivatives)
{
  using LD = long double;
  using VecL = Eigen::Matrix<LD, Eigen::Dynamic, 1>;
  using MatL = Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>;
  const rbd::MultiBodyTpl<LD> mb = robot.mb.cast<LD>();
  rbd::MultiBodyConfigTpl<LD> mbc(mb);
  rbd::InverseDynamicsTpl<LD> id(mb);
  rbd::ForwardDynamicsTpl<LD> fd(mb);
  rbd::InverseDynamicsDerivativesTpl<LD> idd(mb);
  rbd::ForwardDynamicsDerivativesTpl<LD> fdd(mb);
  const int nv = mb.nrDof();
  Reference ref;
  for(const auto & f : {"fk", "id", "nle", "gravity", "mass_matrix", "fd_aba", "fd_crba"}) ref.outputs[f].reserve(states.size());
  const auto toDouble = [](const VecL & v) { return Eigen::VectorXd(v.cast<double>()); };
  for(const State & s : states)
  {
    const VecL q = s.q.cast<LD>(), alpha = s.alpha.cast<LD>(), alphaD = s.alphaD.cast<LD>(), tau = s.tau.cast<LD>();
    rbd::vectorToParam<LD>(q, mbc.q);
    rbd::vectorToDof<LD>(alpha, mbc.alpha);
    rbd::vectorToDof<LD>(alphaD, mbc.alphaD);
    rbd::forwardKinematics(mb, mbc);
    rbd::forwardVelocity(mb, mbc);
    ref.outputs["fk"].push_back(flattenPosesT<LD>(robot, mbc.bodyPosW));
    // tau = ID(q, alpha, alphaD)
    id.inverseDynamics(mb, mbc);
    ref.outputs["id"].push_back(toDouble(rbd::dofToVector(mb, mbc.jointTorque)));
    if(derivatives)
    {
      idd.inverseDynamicsDerivatives(mb, mbc);
      ref.outputs["id_derivatives"].push_back(flattenBlocks({&idd.dtauDq(), &idd.dtauDalpha()}));
    }
    // C(q, alpha) = ID(q, alpha, 0); H(q) by CRBA; alphaD = H^-1 (tau - C) by LLT, all in long double
    rbd::vectorToDof<LD>(tau, mbc.jointTorque);
    if(derivatives)
    {
      fdd.forwardDynamicsDerivatives(mb, mbc);
      ref.outputs["fd_derivatives"].push_back(flattenBlocks({&fdd.dalphaDDq(), &fdd.dalphaDDalpha(), &fdd.Minv()}));
    }
    fd.forwardDynamics(mb, mbc);
    ref.outputs["nle"].push_back(toDouble(fd.C()));
    const MatL H = fd.H();
    ref.outputs["mass_matrix"].push_back(toDouble(Eigen::Map<const VecL>(H.data(), H.size())));
    const Eigen::VectorXd alphaDOut = toDouble(rbd::dofToVector(mb, mbc.alphaD));
    ref.outputs["fd_aba"].push_back(alphaDOut);
    ref.outputs["fd_crba"].push_back(alphaDOut);
    const VecL lambda = Eigen::SelfAdjointEigenSolver<MatL>(H, Eigen::EigenvaluesOnly).eigenvalues();
    ref.condH.push_back(lambda.minCoeff() > 0 ? static_cast<double>(lambda.maxCoeff() / lambda.minCoeff())
                                              : std::numeric_limits<double>::infinity());
    // g(q) = ID(q, 0, 0)
    rbd::vectorToDof<LD>(VecL::Zero(nv), mbc.alpha);
    rbd::forwardVelocity(mb, mbc);
    fd.computeC(mb, mbc);
    ref.outputs["gravity"].push_back(toDouble(fd.C()));
  }
  return ref;
}

} // namespace rbdgen::accuracy
