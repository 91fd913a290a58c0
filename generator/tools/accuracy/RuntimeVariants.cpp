#include "RuntimeVariants.h"

#include <functional>
#include <initializer_list>

#include <rbd/ABA.h>
#include <rbd/FD.h>
#include <rbd/FDDerivatives.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>

#include "PoseLayout.h"
#include "Timing.h"

namespace rbdgen::accuracy
{

std::vector<VariantResult> runRuntimeVariants(const rbd::parsers::ParserResult & robot, const std::vector<State> & states,
                                              bool derivatives)
{
  const rbd::MultiBody & mb = robot.mb;
  rbd::MultiBodyConfig mbc(mb);
  rbd::InverseDynamics id(mb);
  rbd::ForwardDynamics fd(mb);
  rbd::ForwardDynamicsABA aba(mb);
  rbd::InverseDynamicsDerivatives idd(mb);
  rbd::ForwardDynamicsDerivatives fdd(mb);
  const auto flat = [](std::initializer_list<const Eigen::MatrixXd *> blocks) {
    Eigen::Index n = 0;
    for(const auto * m : blocks) n += m->size();
    Eigen::VectorXd v(n);
    n = 0;
    for(const auto * m : blocks)
    {
      v.segment(n, m->size()) = Eigen::Map<const Eigen::VectorXd>(m->data(), m->size());
      n += m->size();
    }
    return v;
  };
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(mb.nrDof());
  // q, alpha (and alphaD, tau) of state i into mbc, then FK and FV.
  const auto set = [&](const State & s, const Eigen::VectorXd & alpha) {
    rbd::vectorToParam<double>(s.q, mbc.q);
    rbd::vectorToDof<double>(alpha, mbc.alpha);
    rbd::vectorToDof<double>(s.alphaD, mbc.alphaD);
    rbd::vectorToDof<double>(s.tau, mbc.jointTorque);
    rbd::forwardKinematics(mb, mbc);
    rbd::forwardVelocity(mb, mbc);
  };
  // function -> (run on state i, output of the last run)
  struct Fn
  {
    const char * name;
    std::function<void(const State &)> run;
    std::function<Eigen::VectorXd()> output;
  };
  std::vector<Fn> fns = {
      {"fk",
       [&](const State & s) {
         rbd::vectorToParam<double>(s.q, mbc.q);
         rbd::forwardKinematics(mb, mbc);
         keepAlive(mbc.bodyPosW.back());
       },
       [&] { return flattenPosesT<double>(robot, mbc.bodyPosW); }},
      {"id",
       [&](const State & s) {
         set(s, s.alpha);
         id.inverseDynamics(mb, mbc);
         keepAlive(mbc.jointTorque.back());
       },
       [&] { return rbd::dofToVector(mb, mbc.jointTorque); }},
      {"nle",
       [&](const State & s) {
         set(s, s.alpha);
         fd.computeC(mb, mbc);
         keepAlive(fd.C());
       },
       [&] { return Eigen::VectorXd(fd.C()); }},
      {"gravity",
       [&](const State & s) {
         set(s, zero);
         fd.computeC(mb, mbc);
         keepAlive(fd.C());
       },
       [&] { return Eigen::VectorXd(fd.C()); }},
      {"mass_matrix",
       [&](const State & s) {
         rbd::vectorToParam<double>(s.q, mbc.q);
         rbd::forwardKinematics(mb, mbc);
         fd.computeH(mb, mbc);
         keepAlive(fd.H());
       },
       [&] { return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(fd.H().data(), fd.H().size())); }},
      {"fd_aba",
       [&](const State & s) {
         set(s, s.alpha);
         aba.forwardDynamics(mb, mbc);
         keepAlive(mbc.alphaD.back());
       },
       [&] { return rbd::dofToVector(mb, mbc.alphaD); }},
      {"fd_crba",
       [&](const State & s) {
         set(s, s.alpha);
         fd.forwardDynamics(mb, mbc);
         keepAlive(mbc.alphaD.back());
       },
       [&] { return rbd::dofToVector(mb, mbc.alphaD); }},
  };
  if(derivatives)
  {
    fns.push_back({"id_derivatives",
                   [&](const State & s) {
                     set(s, s.alpha);
                     idd.inverseDynamicsDerivatives(mb, mbc);
                     keepAlive(idd.dtauDq());
                   },
                   [&] { return flat({&idd.dtauDq(), &idd.dtauDalpha()}); }});
    fns.push_back({"fd_derivatives",
                   [&](const State & s) {
                     set(s, s.alpha);
                     fdd.forwardDynamicsDerivatives(mb, mbc);
                     keepAlive(fdd.dalphaDDq());
                   },
                   [&] { return flat({&fdd.dalphaDDq(), &fdd.dalphaDDalpha(), &fdd.Minv()}); }});
  }
  std::vector<VariantResult> results;
  const int n = static_cast<int>(states.size());
  for(const Fn & fn : fns)
  {
    VariantResult r{fn.name, "runtime", "double", 0, {}};
    r.nsPerCall = medianNsPerCall(n, [&](int i) { fn.run(states[static_cast<std::size_t>(i)]); });
    for(const State & s : states)
    {
      fn.run(s);
      r.outputs.push_back(fn.output());
    }
    results.push_back(std::move(r));
  }
  return results;
}

} // namespace rbdgen::accuracy
