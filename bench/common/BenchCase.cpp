#include "BenchCase.h"

#include <algorithm>
#include <random>

#include <rbd/CoM.h>
#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/Jacobian.h>

namespace rbdbench
{

BenchCase loadCase(const std::string & name, const std::string & urdf, bool floating)
{
  BenchCase c;
  c.name = name;
  c.urdf = urdf;
  c.floating = floating;
  rbd::parsers::ParserOptions opt;
  opt.fixed = !floating;
  c.model = rbd::parsers::fromUrdfFile(urdf, opt);
  const rbd::MultiBody & mb = c.model.mb;
  for(int i = 0; i < mb.nrJoints(); ++i)
    if(mb.joint(i).dof() > 0) c.jacobianBody = i; // joint i moves body i
  c.jacobianBodyName = mb.body(c.jacobianBody).name();

  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> u(-1, 1);
  std::mt19937 rngWrench(20261126);
  for(std::size_t s = 0; s < kPoolSize; ++s)
  {
    State st{Eigen::VectorXd(mb.nrParams()), Eigen::VectorXd(mb.nrDof()), Eigen::VectorXd(mb.nrDof()),
             Eigen::VectorXd(mb.nrDof()), Eigen::VectorXd(6 * mb.nrBodies())};
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto & j = mb.joint(i);
      const int p = mb.jointPosInParam(i);
      for(int k = 0; k < j.params(); ++k) st.q(p + k) = 3 * u(rng);
      if(j.type() == rbd::Joint::Spherical || j.type() == rbd::Joint::Free)
      {
        Eigen::Vector4d quat; // one draw per statement: the same states with g++ and clang++
        for(int k = 0; k < 4; ++k) quat[k] = u(rng);
        st.q.segment<4>(p) = quat.normalized();
      }
    }
    for(int k = 0; k < mb.nrDof(); ++k)
    {
      st.alpha(k) = 2 * u(rng);
      st.alphaD(k) = 2 * u(rng);
      st.tau(k) = 2 * u(rng);
    }
    for(Eigen::Index k = 0; k < st.fext.size(); ++k) st.fext(k) = 2 * u(rngWrench);
    c.pool.push_back(st);
  }
  return c;
}

Reference reference(const BenchCase & c, const State & s)
{
  const rbd::MultiBody & mb = c.model.mb;
  const int nv = mb.nrDof();
  Reference r;
  rbd::MultiBodyConfig mbc(mb);
  rbd::vectorToParam<double>(s.q, mbc.q);
  rbd::vectorToDof<double>(s.alpha, mbc.alpha);
  rbd::vectorToDof<double>(s.alphaD, mbc.alphaD);
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
  r.bodyPosW = mbc.bodyPosW;
  r.bodyVelB = mbc.bodyVelB;

  rbd::InverseDynamics id(mb);
  id.inverseDynamics(mb, mbc);
  r.tauID = rbd::dofToVector(mb, mbc.jointTorque);

  for(int b = 0; b < mb.nrBodies(); ++b)
    mbc.force[static_cast<std::size_t>(b)] = sva::ForceVecd(Eigen::Matrix<double, 6, 1>(s.fext.segment<6>(6 * b)));
  id.inverseDynamics(mb, mbc);
  r.tauIDext = rbd::dofToVector(mb, mbc.jointTorque);
  for(auto & f : mbc.force) f = sva::ForceVecd::Zero();

  r.tauNLE = Eigen::VectorXd(nv);
  id.nonLinearEffects(mb, mbc, r.tauNLE);

  rbd::vectorToDof<double>(s.tau, mbc.jointTorque);
  rbd::ForwardDynamics fd(mb);
  fd.forwardDynamics(mb, mbc);
  r.H = fd.H();
  r.alphaDFD = rbd::dofToVector(mb, mbc.alphaD);

  rbd::Jacobian jac(mb, c.jacobianBodyName);
  r.J = Eigen::MatrixXd::Zero(6, nv);
  jac.fullJacobian(mb, jac.jacobian(mb, mbc), r.J);
  r.com = rbd::computeCoM(mb, mbc);

  // gravity torques: ID at alpha = 0, alphaD = 0
  rbd::MultiBodyConfig mbc0(mb);
  rbd::vectorToParam<double>(s.q, mbc0.q);
  rbd::forwardKinematics(mb, mbc0);
  rbd::forwardVelocity(mb, mbc0);
  id.inverseDynamics(mb, mbc0);
  r.tauGravity = rbd::dofToVector(mb, mbc0.jointTorque);
  return r;
}

double relErr(const Eigen::Ref<const Eigen::MatrixXd> & a, const Eigen::Ref<const Eigen::MatrixXd> & b)
{
  if(a.rows() != b.rows() || a.cols() != b.cols()) return HUGE_VAL;
  const double scale = std::max(1.0, b.lpNorm<Eigen::Infinity>());
  return (a - b).lpNorm<Eigen::Infinity>() / scale;
}

} // namespace rbdbench
