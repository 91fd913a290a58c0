// The robot's own API with mimic joints coupled (namespace NAME) against the full model
// (NAME::independent, itself checked against the runtime by test_generated) projected by a coupling
// matrix built here from the URDF's <mimic> elements: q_full = G q + o, tau = G^T tau_full,
// H = G^T H_full G, J = J_full G, forward dynamics = (G^T H_full G)^-1 (tau - G^T C_full) solved by
// Eigen, the derivatives G^T dID_full G and -H^-1 of them. Robots without mimic joints: G = I.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include "GeneratedReference.h"
#include "MimicCouplingMatrix.h"

namespace rbdgentest
{
const std::vector<const GeneratedRobot *> & generatedRobots();
} // namespace rbdgentest

namespace
{
using rbdgentest::GeneratedRobot;
using rbdgentest::Reference;
using rbdgentest::Coupling;
using rbdgentest::coupling;

std::vector<const GeneratedRobot *> urdfRobots()
{
  std::vector<const GeneratedRobot *> r;
  for(const GeneratedRobot * g : rbdgentest::generatedRobots())
    if(g->programmaticModel < 0) r.push_back(g);
  return r;
}

class MimicCoupling : public ::testing::TestWithParam<const GeneratedRobot *>
{
};

/// max |a - b| / max(1, max |b|)
double err(const Eigen::MatrixXd & a, const Eigen::MatrixXd & b)
{
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

TEST_P(MimicCoupling, EqualsTheFullModelProjected)
{
  const GeneratedRobot & g = *GetParam();
  Reference ref(g);
  const Coupling c = coupling(ref.robot);
  ASSERT_EQ(g.coupledNq, c.Gq.cols());
  ASSERT_EQ(g.coupledNv, c.Gv.cols());
  if(c.mimics == 0)
  {
    EXPECT_EQ(g.coupledNv, g.nv);
  }
  const int nq = g.coupledNq, nv = g.coupledNv, nvf = g.nv, nb = g.nbodies;
  const Eigen::MatrixXd & G = c.Gv;
  rbdtest::Rng rng(31);
  double worst = 0;
  auto check = [&](const char * what, const Eigen::MatrixXd & got, const Eigen::MatrixXd & expected, double tol) {
    const double e = err(got, expected);
    worst = std::max(worst, e);
    EXPECT_LE(e, tol) << what;
  };
  for(int s = 0; s < 20; ++s)
  {
    ref.sample(rng);
    // The coupled coordinates of a random full state: its independent coordinates (quaternions unit).
    Eigen::VectorXd qc(nq);
    for(int k = 0; k < nq; ++k) qc(k) = ref.q()(c.own[static_cast<std::size_t>(k)]);
    const Eigen::VectorXd q = c.Gq * qc + c.o;
    Eigen::VectorXd a(nv), ad(nv), tau(nv);
    for(int k = 0; k < nv; ++k)
      a(k) = rbdtest::uniform(rng, -2, 2), ad(k) = rbdtest::uniform(rng, -2, 2), tau(k) = rbdtest::uniform(rng, -5, 5);
    const Eigen::VectorXd af = G * a, adf = G * ad;

    Eigen::VectorXd poses(12 * nb), posesF(12 * nb);
    g.coupled.forwardKinematics(qc.data(), poses.data());
    g.d.forwardKinematics(q.data(), posesF.data());
    check("forward_kinematics", poses, posesF, 1e-14);

    Eigen::VectorXd out(nv), outF(nvf);
    g.coupled.inverseDynamics(qc.data(), a.data(), ad.data(), out.data());
    g.d.inverseDynamics(q.data(), af.data(), adf.data(), outF.data());
    check("inverse_dynamics", out, G.transpose() * outF, 1e-13);
    g.coupled.gravityTorques(qc.data(), out.data());
    g.d.gravityTorques(q.data(), outF.data());
    check("gravity_torques", out, G.transpose() * outF, 1e-13);

    Eigen::MatrixXd H(nv, nv), HF(nvf, nvf);
    g.coupled.massMatrix(qc.data(), H.data());
    g.d.massMatrix(q.data(), HF.data());
    const Eigen::MatrixXd Hc = G.transpose() * HF * G;
    check("mass_matrix", H, Hc, 1e-13);
    g.coupled.massMatrixPacked(qc.data(), H.data());
    check("mass_matrix_packed", H, Hc, 1e-13);

    Eigen::VectorXd C(nv), CF(nvf);
    g.coupled.nonlinearEffects(qc.data(), a.data(), C.data());
    g.d.nonlinearEffects(q.data(), af.data(), CF.data());
    check("nonlinear_effects", C, G.transpose() * CF, 1e-13);
    ASSERT_EQ(g.coupledHasForwardDynamics, g.coupled.forwardDynamics != nullptr);
    if(g.coupled.forwardDynamics)
    {
      const Eigen::LDLT<Eigen::MatrixXd> ldlt(Hc);
      const double cond = Hc.norm() * ldlt.solve(Eigen::MatrixXd::Identity(nv, nv)).norm();
      const Eigen::VectorXd expected = ldlt.solve(tau - G.transpose() * CF);
      g.coupled.forwardDynamics(qc.data(), a.data(), tau.data(), out.data());
      check("forward_dynamics", out, expected, 1e-13 * std::max(1.0, cond / 1e3));
    }

    Eigen::MatrixXd J(6, nv), JF(6, nvf);
    for(int b = 0; b < nb; ++b)
    {
      g.coupled.jacobianQ(b, qc.data(), J.data());
      g.d.jacobianQ(b, q.data(), JF.data());
      check("jacobian(body, q)", J, JF * G, 1e-14);
      Eigen::VectorXd jd(6), jdF(6);
      g.coupled.jacobianDotTimesAlpha(b, qc.data(), a.data(), jd.data());
      g.d.jacobianDotTimesAlpha(b, q.data(), af.data(), jdF.data());
      check("jacobian_dot_times_alpha", jd, jdF, 1e-13);
    }
    Eigen::MatrixXd A(6, nv), AF(6, nvf);
    g.coupled.centroidalMomentumMatrix(qc.data(), A.data());
    g.d.centroidalMomentumMatrix(q.data(), AF.data());
    check("centroidal_momentum_matrix", A, AF * G, 1e-13);
    Eigen::MatrixXd Jc(3, nv), JcF(3, nvf);
    g.coupled.comJacobian(qc.data(), Jc.data());
    g.d.comJacobian(q.data(), JcF.data());
    check("com_jacobian", Jc, JcF * G, 1e-14);

    if(g.coupled.inverseDynamicsDerivatives && g.d.inverseDynamicsDerivatives)
    {
      Eigen::MatrixXd dq(nv, nv), da(nv, nv), dqF(nvf, nvf), daF(nvf, nvf);
      g.coupled.inverseDynamicsDerivatives(qc.data(), a.data(), ad.data(), dq.data(), da.data());
      g.d.inverseDynamicsDerivatives(q.data(), af.data(), adf.data(), dqF.data(), daF.data());
      check("dtau_dq", dq, G.transpose() * dqF * G, 1e-13);
      check("dtau_dalpha", da, G.transpose() * daF * G, 1e-13);
      if(g.coupled.forwardDynamicsDerivatives)
      {
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(Hc);
        const Eigen::MatrixXd Minv = ldlt.solve(Eigen::MatrixXd::Identity(nv, nv));
        const double cond = Hc.norm() * Minv.norm();
        Eigen::VectorXd add(nv);
        Eigen::MatrixXd fdq(nv, nv), fda(nv, nv), fMinv(nv, nv);
        g.coupled.forwardDynamicsDerivatives(qc.data(), a.data(), tau.data(), add.data(), fdq.data(), fda.data(), fMinv.data());
        const Eigen::VectorXd alphaD = ldlt.solve(tau - G.transpose() * CF), alphaDF = G * alphaD;
        g.d.inverseDynamicsDerivatives(q.data(), af.data(), alphaDF.data(), dqF.data(), daF.data());
        const double tol = 1e-13 * std::max(1.0, cond / 1e3);
        check("fd: alphaD", add, alphaD, tol);
        check("fd: dalphaD_dq", fdq, -Minv * G.transpose() * dqF * G, tol);
        check("fd: dalphaD_dalpha", fda, -Minv * G.transpose() * daF * G, tol);
        check("fd: Minv", fMinv, Minv, tol);
      }
    }
  }
  std::printf("[ %-24s ] %d mimic joints coupled, nv %d -> %d, worst relative difference %.3g\n", g.name, c.mimics, nvf, nv,
              worst);
}

std::string robotName(const ::testing::TestParamInfo<const GeneratedRobot *> & info)
{
  return info.param->name;
}

INSTANTIATE_TEST_SUITE_P(Robots, MimicCoupling, ::testing::ValuesIn(urdfRobots()), robotName);

} // namespace
