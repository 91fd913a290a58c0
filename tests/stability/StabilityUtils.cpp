// The hard cases' helpers that do the work (every runtime output in double and long double, the
// comparison, the random models): compiled once, with optimisation, for every stability test
// source (which then compile at the quick tests' options; see tests/CMakeLists.txt).
#include "StabilityUtils.h"

namespace stab
{

rbd::MultiBodyGraph chainGraph(rbdtest::Rng & rng, int n, const InertiaFn & inertia, const JointFn & joint,
                               double maxOffset)
{
  rbd::MultiBodyGraph g;
  for(int k = 0; k < n; ++k) g.addBody(rbd::Body(inertia(rng, k), "b" + std::to_string(k)));
  for(int k = 1; k < n; ++k)
  {
    const rbd::Joint j = joint(rng, k);
    g.addJoint(j);
    // one draw per statement (argument evaluation order differs between g++ and clang++)
    const sva::PTransformd X_p_j = rbdtest::randomTransform(rng, maxOffset);
    const sva::PTransformd X_c_j = rbdtest::randomTransform(rng, 0.1);
    g.linkBodies("b" + std::to_string(k - 1), X_p_j, "b" + std::to_string(k), X_c_j, j.name());
  }
  return g;
}

rbd::MultiBodyGraph wideTreeGraph(rbdtest::Rng & rng, int branches, int depth)
{
  rbd::MultiBodyGraph g;
  g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b0"));
  int k = 0;
  for(int b = 0; b < branches; ++b)
  {
    std::string parent = "b0";
    for(int d = 0; d < depth; ++d)
    {
      ++k;
      const std::string name = "b" + std::to_string(k);
      g.addBody(rbd::Body(rbdtest::randomInertia(rng), name));
      const rbd::Joint j = randomRev(rng, k);
      g.addJoint(j);
      const sva::PTransformd X_p_j = rbdtest::randomTransform(rng), X_c_j = rbdtest::randomTransform(rng, 0.1);
      g.linkBodies(parent, X_p_j, name, X_c_j, j.name());
      parent = name;
    }
  }
  return g;
}

template<typename T>
Outputs<T> evaluate(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> mbc, bool withFd)
{
  Outputs<T> o;
  dyntest::kinematics(mb, mbc);
  o.poses.resize(12 * mb.nrBodies());
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & X = mbc.bodyPosW[static_cast<std::size_t>(i)];
    o.poses.template segment<9>(12 * i) = Eigen::Map<const VecX<T>>(X.rotation().data(), 9);
    o.poses.template segment<3>(12 * i + 9) = X.translation();
  }
  {
    rbd::MultiBodyConfigTpl<T> c = mbc;
    rbd::InverseDynamicsTpl<T> id(mb);
    id.inverseDynamics(mb, c);
    o.tau = rbd::dofToVector(mb, c.jointTorque);
  }
  rbd::ForwardDynamicsTpl<T> fd(mb);
  fd.computeH(mb, mbc);
  fd.computeC(mb, mbc);
  o.H = fd.H();
  o.C = fd.C();
  rbd::JacobianTpl<T> jac(mb, mb.body(mb.nrBodies() - 1).name());
  MatX<T> full(6, mb.nrDof());
  jac.fullJacobian(mb, jac.jacobian(mb, mbc), full);
  o.J = full;
  if(withFd)
  {
    rbd::MultiBodyConfigTpl<T> c = mbc;
    fd.forwardDynamics(mb, c);
    o.fdCrba = rbd::dofToVector(mb, c.alphaD);
    o.hasFd = true;
    // ABA throws std::runtime_error (documented, rbd/ABA.h) when an articulated inertia D is not
    // positive definite in T: the caller decides whether that is acceptable for the case.
    try
    {
      rbd::ForwardDynamicsABATpl<T> aba(mb);
      aba.forwardDynamics(mb, c);
      o.fdAba = rbd::dofToVector(mb, c.alphaD);
    }
    catch(const std::runtime_error &)
    {
      o.abaThrew = true;
      o.fdAba = o.fdCrba;
    }
  }
  return o;
}

std::ostream & operator<<(std::ostream & os, const Errors & e)
{
  return os << "poses " << e.poses << ", tau " << e.tau << ", H " << e.H << ", C " << e.C << ", J " << e.J << ", FD(CRBA) "
            << e.fdCrba << ", FD(ABA) " << e.fdAba << ", ABA vs CRBA " << e.abaVsCrba << ", cond(H) " << e.condH
            << ", FD error / (cond(H) eps) " << std::max(e.worstRatio, e.fdOverCondEps()) << (e.abaThrew ? ", ABA threw" : "")
            << (e.finite ? "" : ", NOT FINITE");
}

double conditionNumber(const MatX<LD> & H)
{
  if(H.size() == 0) return 1;
  const VecX<LD> s = Eigen::JacobiSVD<MatX<LD>>(H).singularValues();
  return static_cast<double>(s(0) / s(s.size() - 1));
}

Errors errorsOf(const Outputs<double> & d, const Outputs<LD> & l)
{
  const bool withFd = d.hasFd && l.hasFd;
  Errors e;
  e.abaThrew = d.abaThrew || l.abaThrew;
  e.finite = allFinite(d) && allFinite(l);
  e.poses = rbdtest::relErr(d.poses, l.poses);
  e.tau = rbdtest::relErr(d.tau, l.tau);
  e.H = rbdtest::relErr(d.H, l.H);
  e.C = rbdtest::relErr(d.C, l.C);
  e.J = rbdtest::relErr(d.J, l.J);
  if(withFd)
  {
    e.fdCrba = normRel(d.fdCrba, l.fdCrba);
    e.fdAba = normRel(d.fdAba, l.fdAba);
    e.abaVsCrba = normRel(d.fdAba, d.fdCrba);
    e.condH = conditionNumber(l.H);
  }
  return e;
}

Errors compare(const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc, bool withFd)
{
  const rbd::MultiBodyTpl<LD> mbL = dyntest::castModel<LD>(mb);
  return errorsOf(evaluate(mb, mbc, withFd), evaluate(mbL, rbdtest::castInputs<LD>(mbL, mbc), withFd));
}

Errors compareRandom(rbdtest::Rng & rng, const rbd::MultiBody & mb, bool withFd, double qRange, double vRange)
{
  rbd::MultiBodyConfig mbc(mb);
  rbdtest::randomState(rng, mb, mbc, qRange, vRange);
  return compare(mb, mbc, withFd);
}

::testing::AssertionResult withinBounds(const Errors & e, const Bounds & b)
{
  if(!e.finite) return ::testing::AssertionFailure() << "NaN or Inf: " << e;
  if(e.abaThrew && !b.abaMayThrow) return ::testing::AssertionFailure() << "ABA threw: " << e;
  if(!(e.kinematicsAndDynamics() <= b.kin)) return ::testing::AssertionFailure() << "above " << b.kin << ": " << e;
  const double fdBound = b.fdFactor * std::max(1.0, e.condH) * eps;
  if(!(std::max({e.fdCrba, e.fdAba, e.abaVsCrba}) <= fdBound))
    return ::testing::AssertionFailure() << "forward dynamics above " << fdBound << ": " << e;
  return ::testing::AssertionSuccess();
}

void report(const char * what, const Errors & e)
{
  std::ostringstream os;
  os << e;
  std::printf("[ %-28s ] worst: %s\n", what, os.str().c_str());
}

template Outputs<double> evaluate(const rbd::MultiBody &, rbd::MultiBodyConfig, bool);
template Outputs<LD> evaluate(const rbd::MultiBodyTpl<LD> &, rbd::MultiBodyConfigTpl<LD>, bool);

} // namespace stab
