// Generated code (double and float) of the hard URDFs in tests/stability/robots against the
// runtime in long double, in hard regimes: nominal states, |q| up to 1e4, velocities up to 1e3
// rad/s and, on floating bases, non-normalised (x 1e-3 .. 1e3) and negated quaternions.
//
// Reference: the URDF loaded by the runtime, cast to long double, fed the same inputs as the
// generated function (for float: the float-rounded inputs, so that only the computation is
// measured) with unit quaternions. Error: rbdtest::relErr (max abs error / max(1, max |ref|)).
// Bounds, with n = number of bodies and u = unit roundoff of the scalar (1.1e-16 double, 6e-8
// float):
//   kinematics, inverse dynamics, mass matrix, Jacobian: 100 n u (a depth-n recursion, ~n u,
//     times the constant of the spatial products; measured well below, see the printed worst);
//   forward dynamics (ABA and CRBA + LTDL): 20 nv cond(H) u, normwise (see stab::Bounds),
//     checked where that bound is below 1 (else the problem has no correct digit in that scalar,
//     and only finiteness is required);
//   derivatives (generated with DERIVATIVES) against rbd/IDDerivatives.h and FDDerivatives.h in long
//     double: d tau/dq, d tau/dalpha like inverse dynamics, 100 n u times max(1, |alpha|^2) (the
//     centrifugal terms are quadratic in alpha: their derivatives carry the rounding of alpha^2);
//     d alphaD/dq, d alphaD/dalpha, Minv: 20 nv cond(H)^2 u (H^-1 applied to a quantity that
//     already carries alphaD's error), checked where below 1.
// Every output must be finite.
#include <cstdio>

#include <rbd/FDDerivatives.h>
#include <rbd/IDDerivatives.h>
#include <rbd/parsers/urdf.h>

#include "GeneratedRobot.h"
#include "StabilityUtils.h"

namespace rbdgentest
{
const std::vector<const GeneratedRobot *> & stabilityRobots();
} // namespace rbdgentest

namespace
{

using rbdgentest::GeneratedRobot;
using stab::LD;
template<typename T>
using VecX = stab::VecX<T>;
template<typename T>
using MatX = stab::MatX<T>;

enum class Regime
{
  Nominal,
  LargeQ,
  HighVelocity,
  ScaledQuaternions,
  NegatedQuaternions
};
const char * regimeName(Regime r)
{
  static const char * names[] = {"nominal", "|q| <= 1e4", "|alpha| <= 1e3", "quat x [1e-3, 1e3]", "-quat"};
  return names[static_cast<int>(r)];
}

/// Generated outputs at one state, in the layout of stab::Outputs (rotations column-major).
template<typename S>
stab::Outputs<S> generated(const rbdgentest::GeneratedFunctions<S> & g, const GeneratedRobot & r, const VecX<S> & q,
                           const VecX<S> & alpha, const VecX<S> & alphaD, const VecX<S> & tau)
{
  stab::Outputs<S> o;
  VecX<S> poses(12 * r.nbodies);
  g.forwardKinematics(q.data(), poses.data());
  o.poses.resize(12 * r.nbodies);
  for(int i = 0; i < r.nbodies; ++i)
  {
    for(int row = 0; row < 3; ++row)
      for(int c = 0; c < 3; ++c) o.poses(12 * i + 3 * c + row) = poses(12 * i + 3 * row + c);
    o.poses.template segment<3>(12 * i + 9) = poses.template segment<3>(12 * i + 9);
  }
  o.tau.resize(r.nv);
  g.inverseDynamics(q.data(), alpha.data(), alphaD.data(), o.tau.data());
  o.H.resize(r.nv, r.nv);
  g.massMatrix(q.data(), o.H.data());
  o.C.resize(r.nv);
  g.nonlinearEffects(q.data(), alpha.data(), o.C.data());
  o.J.resize(6, r.nv);
  g.jacobian(r.nbodies - 1, q.data(), o.J.data());
  o.fdCrba.resize(r.nv);
  o.fdAba.resize(r.nv);
  g.forwardDynamicsCrba(q.data(), alpha.data(), tau.data(), o.fdCrba.data());
  g.forwardDynamicsAba(q.data(), alpha.data(), tau.data(), o.fdAba.data());
  o.hasFd = true;
  return o;
}

/// Worst errors of one scalar over the states of a regime.
struct Worst
{
  double kin = 0, fd = 0, fdOverBound = 0, did = 0, dfd = 0;
  double cond = 0;
  int fdSkipped = 0;
};

class GeneratedHard : public ::testing::TestWithParam<const GeneratedRobot *>
{
protected:
  const GeneratedRobot & g() const { return *GetParam(); }

  void SetUp() override
  {
    rbd::parsers::ParserOptions opt;
    opt.fixed = !g().floatingBase;
    robot_ = rbd::parsers::fromUrdfFile(g().urdf, opt);
    ASSERT_EQ(robot_.mb.nrParams(), g().nq);
    ASSERT_EQ(robot_.mb.nrDof(), g().nv);
    ASSERT_EQ(robot_.mb.nrBodies(), g().nbodies);
    for(int i = 0; i < g().nbodies; ++i) ASSERT_EQ(robot_.mb.body(i).name(), g().bodyNames[i]);
    // Every hard model has a regular mass matrix (massless links only where mass lies beyond).
    ASSERT_TRUE(g().hasForwardDynamics) << g().name;
    mbL_ = dyntest::castModel<LD>(robot_.mb);
  }

  /// A random state of the regime: unit-quaternion inputs for the reference (mbc) and the
  /// inputs the generated code gets (q with scaled/negated quaternions).
  void sample(rbdtest::Rng & rng, Regime regime, rbd::MultiBodyConfig & mbc, Eigen::VectorXd & qGen)
  {
    const rbd::MultiBody & mb = robot_.mb;
    rbdtest::randomState(rng, mb, mbc, regime == Regime::LargeQ ? 1e4 : 3.0, regime == Regime::HighVelocity ? 1e3 : 2.0);
    qGen = rbd::paramToVector(mb, mbc.q);
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto t = mb.joint(i).type();
      if(t != rbd::Joint::Free && t != rbd::Joint::Spherical) continue;
      double f = 1;
      if(regime == Regime::ScaledQuaternions) f = std::exp(rbdtest::uniform(rng, std::log(1e-3), std::log(1e3)));
      if(regime == Regime::NegatedQuaternions) f = -1;
      qGen.segment(mb.jointPosInParam(i), 4) *= f;
    }
  }

  /// Compare scalar S's generated outputs with the long double runtime on the given inputs.
  template<typename S>
  void check(const rbdgentest::GeneratedFunctions<S> & gen, const rbd::MultiBodyConfig & mbc, const Eigen::VectorXd & qGen,
             Worst & w)
  {
    const rbd::MultiBody & mb = robot_.mb;
    const double u = std::numeric_limits<S>::epsilon() / 2;
    // Inputs rounded to S; the reference sees exactly those values (quaternions re-normalised).
    const VecX<S> q = qGen.cast<S>(), alpha = rbd::dofToVector(mb, mbc.alpha).cast<S>(),
                  alphaD = rbd::dofToVector(mb, mbc.alphaD).cast<S>(), tau = rbd::dofToVector(mb, mbc.jointTorque).cast<S>();
    rbd::MultiBodyConfigTpl<LD> ref(mbL_);
    VecX<LD> qL = q.template cast<LD>();
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto t = mb.joint(i).type();
      if(t == rbd::Joint::Free || t == rbd::Joint::Spherical) qL.segment(mb.jointPosInParam(i), 4).normalize();
    }
    ref.q = rbd::vectorToParam(mbL_, qL);
    ref.alpha = rbd::vectorToDof(mbL_, VecX<LD>(alpha.template cast<LD>()));
    ref.alphaD = rbd::vectorToDof(mbL_, VecX<LD>(alphaD.template cast<LD>()));
    ref.jointTorque = rbd::vectorToDof(mbL_, VecX<LD>(tau.template cast<LD>()));
    const stab::Outputs<LD> l = stab::evaluate(mbL_, ref);
    const stab::Outputs<S> o = generated<S>(gen, g(), q, alpha, alphaD, tau);
    ASSERT_TRUE(stab::allFinite(o)) << "NaN or Inf in the generated " << (sizeof(S) == 4 ? "float" : "double") << " outputs";
    const double kin = std::max({rbdtest::relErr(o.poses, l.poses), rbdtest::relErr(o.tau, l.tau),
                                 rbdtest::relErr(o.H, l.H), rbdtest::relErr(o.C, l.C), rbdtest::relErr(o.J, l.J)});
    EXPECT_LE(kin, 100 * g().nbodies * u);
    const double cond = stab::conditionNumber(l.H);
    const double fd = std::max(stab::normRel(o.fdCrba, l.fdCrba), stab::normRel(o.fdAba, l.fdAba));
    const double fdBound = 20.0 * g().nv * cond * u;
    if(fdBound < 1)
    {
      EXPECT_LE(fd, fdBound) << "cond(H) = " << cond;
      w.fd = std::max(w.fd, fd);
      w.fdOverBound = std::max(w.fdOverBound, fd / fdBound);
    }
    else ++w.fdSkipped;
    w.kin = std::max(w.kin, kin);
    w.cond = std::max(w.cond, cond);
    checkDerivatives(gen, ref, q, alpha, alphaD, tau, cond, w);
  }

  /// Generated derivatives against the long double runtime (ref: the reference's inputs).
  template<typename S>
  void checkDerivatives(const rbdgentest::GeneratedFunctions<S> & gen, rbd::MultiBodyConfigTpl<LD> ref, const VecX<S> & q,
                        const VecX<S> & alpha, const VecX<S> & alphaD, const VecX<S> & tau, double cond, Worst & w)
  {
    ASSERT_NE(gen.inverseDynamicsDerivatives, nullptr);
    const int nv = g().nv;
    const double u = std::numeric_limits<S>::epsilon() / 2;
    dyntest::kinematics(mbL_, ref);
    rbd::InverseDynamicsDerivativesTpl<LD> idL(mbL_);
    idL.inverseDynamicsDerivatives(mbL_, ref);
    rbd::ForwardDynamicsDerivativesTpl<LD> fdL(mbL_);
    fdL.forwardDynamicsDerivatives(mbL_, ref);
    MatX<S> dq(nv, nv), da(nv, nv), fq(nv, nv), fa(nv, nv), mi(nv, nv);
    VecX<S> ad(nv);
    gen.inverseDynamicsDerivatives(q.data(), alpha.data(), alphaD.data(), dq.data(), da.data());
    gen.forwardDynamicsDerivatives(q.data(), alpha.data(), tau.data(), ad.data(), fq.data(), fa.data(), mi.data());
    ASSERT_TRUE(dq.allFinite() && da.allFinite() && fq.allFinite() && fa.allFinite() && mi.allFinite())
        << "NaN or Inf in the generated derivatives";
    const double speed = std::max(1.0, static_cast<double>(alpha.template cast<double>().squaredNorm()));
    const double did = std::max(rbdtest::relErr(dq, idL.dtauDq()), rbdtest::relErr(da, idL.dtauDalpha()));
    EXPECT_LE(did, 100 * g().nbodies * u * speed) << "d tau";
    w.did = std::max(w.did, did / speed);
    const double bound = 20.0 * nv * cond * cond * u;
    if(bound < 1)
    {
      const double dfd = std::max({rbdtest::relErr(fq, fdL.dalphaDDq()), rbdtest::relErr(fa, fdL.dalphaDDalpha()),
                                   rbdtest::relErr(mi, fdL.Minv())});
      EXPECT_LE(dfd, bound) << "d alphaD, cond(H) = " << cond;
      w.dfd = std::max(w.dfd, dfd / bound);
    }
  }

  rbd::parsers::ParserResult robot_;
  rbd::MultiBodyTpl<LD> mbL_;
};

TEST_P(GeneratedHard, DoubleAndFloatAgainstLongDoubleRuntime)
{
  std::vector<Regime> regimes{Regime::Nominal, Regime::LargeQ, Regime::HighVelocity};
  if(g().floatingBase) regimes.insert(regimes.end(), {Regime::ScaledQuaternions, Regime::NegatedQuaternions});
  rbdtest::Rng rng(1234);
  const int states = g().nbodies > 20 ? 5 : 20;
  for(const Regime regime : regimes)
  {
    SCOPED_TRACE(regimeName(regime));
    Worst wd, wf;
    for(int s = 0; s < states; ++s)
    {
      rbd::MultiBodyConfig mbc(robot_.mb);
      Eigen::VectorXd qGen;
      sample(rng, regime, mbc, qGen);
      check<double>(g().d, mbc, qGen, wd);
      check<float>(g().f, mbc, qGen, wf);
      if(HasFatalFailure()) return;
    }
    std::printf("[ %-26s %-18s ] double: kin %.2g, FD %.2g (%.2g of bound); float: kin %.2g, FD %.2g (%.2g of bound, "
                "%d/%d beyond float); max cond(H) %.2g\n",
                g().name, regimeName(regime), wd.kin, wd.fd, wd.fdOverBound, wf.kin, wf.fd, wf.fdOverBound, wf.fdSkipped,
                states, wd.cond);
    std::printf("[ %-26s %-18s ] derivatives: d tau / max(1, |alpha|^2) double %.2g, float %.2g; d alphaD (of bound) "
                "double %.2g, float %.2g\n",
                g().name, regimeName(regime), wd.did, wf.did, wd.dfd, wf.dfd);
  }
}

INSTANTIATE_TEST_SUITE_P(HardModels, GeneratedHard, ::testing::ValuesIn(rbdgentest::stabilityRobots()),
                         [](const ::testing::TestParamInfo<const GeneratedRobot *> & p) { return std::string(p.param->name); });

} // namespace
