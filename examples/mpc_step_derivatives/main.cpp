// MPC-style use of the generated step derivatives: iLQR (iterative LQR, the Gauss-Newton flavour of
// DDP) on a UR5e going from its zero posture to a target posture in 0.5 s (50 knots of 10 ms).
// Every iteration rolls the trajectory out with the scene's own integrator and linearises it at
// each knot with one call per knot of
//     ur5e_mpc::step_derivatives(q, alpha, tau, dt)  ->  next = step(x, tau), A = dx+/dx, B = dx+/dtau
// (x = [q; alpha], 12 x 12 and 12 x 6 fixed-size matrices, no heap), then runs the Riccati backward
// pass for the feedback gains K_k and feedforward terms k_k, and a forward pass with a line search.
// The gains of the last iteration are exactly what a discrete-time MPC applies between re-plans:
// tau = tau_k + K_k (x - x_k).
// It prints the cost per iteration, the final tracking error, the time per step_derivatives call
// and the agreement with the runtime's rbd::scene::stepDerivatives at the first knot.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Cholesky>

#include <ur5e_mpc/dynamics.hpp>

#include <rbd/scene/SceneLoader.h>
#include <rbd/scene/StepDerivatives.h>

namespace
{

namespace gen = ur5e_mpc;
constexpr int nv = gen::nv, nx = 2 * gen::nv;
constexpr int N = 50;        // knots
constexpr double dt = 0.01;  // the scene's step (ur5e_mpc.xml)
using X = Eigen::Matrix<double, nx, 1>;
using U = gen::Tangent<double>;
using MatXX = Eigen::Matrix<double, nx, nx>;
using MatUX = Eigen::Matrix<double, nv, nx>;
using MatUU = Eigen::Matrix<double, nv, nv>;

// Only revolute joints here: the tangent difference of two configurations is q1 - q0. With a free
// or spherical joint, use the log of the relative pose (rbd::configurationDifference).
X state(const gen::State<double> & s)
{
  X x;
  x << s.q, s.alpha;
  return x;
}

struct Problem
{
  X goal;
  U tauRef;                    // gravity torques at the goal: the torque that holds it
  Eigen::Matrix<double, nx, 1> Q, Qf;  // diagonal state weights (running, terminal)
  double R = 1e-4;             // torque weight
  double cost(const std::vector<X> & xs, const std::vector<U> & us) const
  {
    double c = 0;
    for(int k = 0; k < N; ++k)
      c += 0.5 * (xs[k] - goal).dot(Q.cwiseProduct(xs[k] - goal)) + 0.5 * R * (us[k] - tauRef).squaredNorm();
    return c + 0.5 * (xs[N] - goal).dot(Qf.cwiseProduct(xs[N] - goal));
  }
};

/// x_{k+1} = step(x_k, u_k) from x0 with u_k = us[k] + alpha kff[k] + K[k] (x - xs[k]) (the old xs).
double rollout(const Problem & P, const gen::State<double> & x0, const std::vector<X> & xsOld, const std::vector<U> & usOld,
               const std::vector<U> & kff, const std::vector<MatUX> & K, double a, std::vector<X> & xs, std::vector<U> & us)
{
  gen::State<double> s = x0;
  for(int k = 0; k < N; ++k)
  {
    xs[k] = state(s);
    us[k] = usOld[k] + a * kff[k] + K[k] * (xs[k] - xsOld[k]);
    gen::step<double>(s, us[k], dt);
  }
  xs[N] = state(s);
  return P.cost(xs, us);
}

} // namespace

int main()
{
  // Target posture, held at rest; the start is the zero posture at rest.
  gen::State<double> x0 = gen::initial_state<double>();
  gen::Config<double> qGoal;
  qGoal << 0.8, -1.2, 1.0, -0.5, 0.6, 0.3;
  Problem P;
  P.goal << qGoal, U::Zero();
  P.tauRef = gen::gravity_torques<double>(qGoal);
  P.Q << U::Constant(1.0), U::Constant(0.01);
  P.Qf << U::Constant(1e3), U::Constant(10.0);

  std::vector<X> xs(N + 1), xsNew(N + 1);
  std::vector<U> us(N, P.tauRef), usNew(N), kff(N, U::Zero());
  std::vector<MatUX> K(N, MatUX::Zero());
  std::vector<gen::StepDerivatives<double>> lin(N);
  double J = rollout(P, x0, xs, us, kff, K, 0.0, xs, us);
  std::printf("iLQR on %s: %d knots of %.0f ms, nx = %d, nu = %d\n", "ur5e_mpc", N, dt * 1e3, nx, nv);
  std::printf("iteration  0: cost %.6g\n", J);

  double linTime = 0;
  int linCalls = 0;
  for(int it = 1; it <= 15; ++it)
  {
    // 1. linearise the step at every knot of the current trajectory
    const auto t0 = std::chrono::steady_clock::now();
    for(int k = 0; k < N; ++k)
      lin[k] = gen::step_derivatives<double>(xs[k].head<nv>(), xs[k].tail<nv>(), us[k], dt);
    linTime += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    linCalls += N;

    // 2. backward Riccati pass
    X Vx = P.Qf.cwiseProduct(xs[N] - P.goal);
    MatXX Vxx = P.Qf.asDiagonal();
    for(int k = N - 1; k >= 0; --k)
    {
      const MatXX & A = lin[k].A;
      const Eigen::Matrix<double, nx, nv> & B = lin[k].B;
      const X Qx = P.Q.cwiseProduct(xs[k] - P.goal) + A.transpose() * Vx;
      const U Qu = P.R * (us[k] - P.tauRef) + B.transpose() * Vx;
      const MatXX Qxx = MatXX(P.Q.asDiagonal()) + A.transpose() * Vxx * A;
      const MatUU Quu = P.R * MatUU::Identity() + B.transpose() * Vxx * B;
      const MatUX Qux = B.transpose() * Vxx * A;
      const Eigen::LLT<MatUU> llt(Quu);
      kff[k] = -llt.solve(Qu);
      K[k] = -llt.solve(Qux);
      Vx = Qx + K[k].transpose() * Quu * kff[k] + K[k].transpose() * Qu + Qux.transpose() * kff[k];
      Vxx = Qxx + K[k].transpose() * Quu * K[k] + K[k].transpose() * Qux + Qux.transpose() * K[k];
      Vxx = 0.5 * (Vxx + Vxx.transpose()).eval();
    }

    // 3. forward pass with a backtracking line search
    double a = 1.0, Jnew = J;
    for(; a > 1e-4; a *= 0.5)
    {
      Jnew = rollout(P, x0, xs, us, kff, K, a, xsNew, usNew);
      if(Jnew < J) break;
    }
    if(!(Jnew < J))
    {
      std::printf("iteration %2d: no decrease, converged\n", it);
      break;
    }
    const double dJ = J - Jnew;
    std::swap(xs, xsNew);
    std::swap(us, usNew);
    J = Jnew;
    std::printf("iteration %2d: cost %.6g (step %.3g)\n", it, J, a);
    if(dJ < 1e-9 * J) break;
  }
  std::printf("final posture error %.3g rad, final speed %.3g rad/s\n", (xs[N].head<nv>() - qGoal).cwiseAbs().maxCoeff(),
              xs[N].tail<nv>().cwiseAbs().maxCoeff());
  std::printf("step_derivatives: %.0f ns per call (%d calls)\n", 1e9 * linTime / linCalls, linCalls);

  // The runtime computes the same linearisation generically (rbd::scene::stepDerivatives).
  const rbd::scene::Scene scene = rbd::scene::loadScene(RBDGEN_MPC_SCENE);
  const rbd::scene::SceneRobot robot = rbd::scene::loadSceneRobot(scene);
  const rbd::scene::SceneDynamics dyn(robot, scene);
  const Eigen::VectorXd q = xs[0].head<nv>(), alpha = xs[0].tail<nv>(), tau = us[0];
  const rbd::scene::StepDerivatives r = rbd::scene::stepDerivatives(dyn, q, alpha, tau, dt, scene.integrator);
  const auto g = gen::step_derivatives<double>(xs[0].head<nv>(), xs[0].tail<nv>(), us[0], dt);
  const double eA = (r.A - g.A).cwiseAbs().maxCoeff(), eB = (r.B - g.B).cwiseAbs().maxCoeff();
  std::printf("generated vs runtime at knot 0: |dA| %.2g, |dB| %.2g\n", eA, eB);
  return eA < 1e-10 && eB < 1e-10 && (xs[N].head<nv>() - qGoal).cwiseAbs().maxCoeff() < 0.05 ? 0 : 1;
}
