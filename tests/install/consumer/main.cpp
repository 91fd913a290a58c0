// A downstream program using the installed package:
//  1. the runtime (rbdgen::runtime): a 1 kg point mass on a 1 m massless rod, horizontal
//     (q = 0, rod along +x, joint axis y): the holding torque is -m g l = -9.81 N m;
//  2. the header generated at build time by generate_robot_dynamics() from robots/pendulum.urdf,
//     checked against the closed form below, and its batch header (BATCH: the same on SIMD packs,
//     over threads).
//
// robots/pendulum.urdf: revolute joint at the origin, axis +y; bob of m = 1 kg with its centre of
// mass at (0, 0, -l), l = 1 m, in the link frame, inertia I_c = 4e-5 kg m^2 about every axis.
// At angle q the link frame is rotated by R_y(q), so the centre of mass is at
// c(q) = R_y(q) (0, 0, -l) = (-l sin q, 0, -l cos q). The potential energy is V = m g c_z =
// -m g l cos q, the kinetic energy T = 1/2 (I_yy + m l^2) qd^2 (parallel axis; the rotation is about
// y, so only I_yy = I_c enters, and T does not depend on q). Lagrange's equation gives, exactly,
//     tau = (I_c + m l^2) qdd + m g l sin q          (no Coriolis term: T does not depend on q)
// hence gravity_torques(q) = m g l sin q (the small inertia plays no part) and
//     forward_dynamics(q, qd, tau) = (tau - m g l sin q) / (I_c + m l^2),  I_c + m l^2 = 1.00004.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <pendulum/batch.hpp>

#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/MultiBodyGraph.h>

namespace
{

constexpr double m = 1.0, l = 1.0, Ic = 4e-5, g = 9.81;

bool report(const char * what, double err, double tol)
{
  const bool ok = err <= tol;
  std::printf("consumer: %-40s max error %.3g (tolerance %.1g): %s\n", what, err, tol, ok ? "ok" : "FAIL");
  return ok;
}

bool runtimeHoldingTorque()
{
  rbd::MultiBodyGraph mbg;
  mbg.addBody(rbd::Body(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(), "base"));
  mbg.addBody(rbd::Body(1.0, Eigen::Vector3d(1, 0, 0), Eigen::Matrix3d::Zero(), "bob"));
  mbg.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitY(), true, "hinge"));
  mbg.linkBodies("base", sva::PTransformd::Identity(), "bob", sva::PTransformd::Identity(), "hinge");
  rbd::MultiBody mb = mbg.makeMultiBody("base", true);
  rbd::MultiBodyConfig mbc(mb);
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
  rbd::InverseDynamics id(mb);
  id.inverseDynamics(mb, mbc);
  // Gravity's torque about the hinge: r x F = (1,0,0) x (0,0,-9.81) = (0, 9.81, 0); holding needs -9.81.
  return report("runtime holding torque (-9.81 N m)", std::abs(mbc.jointTorque[1][0] + 9.81), 1e-9);
}

} // namespace

int main()
{
  static_assert(pendulum::nq == 1 && pendulum::nv == 1, "pendulum.urdf has one revolute joint");
  bool ok = runtimeHoldingTorque();

  double errG = 0, errFD = 0, errID = 0, errBatch = 0;
  double qs[25], qds[25], taus[25], fds[25];
  for(int k = -12; k <= 12; ++k)
  {
    const double q = 0.27 * k, qd = 0.5 * k - 1, tau = 3.0 - 0.4 * k, qdd = 0.9 * k + 0.1;
    qs[k + 12] = q, qds[k + 12] = qd, taus[k + 12] = tau;
    const pendulum::Config<double> Q = pendulum::Config<double>::Constant(q);
    const pendulum::Tangent<double> QD = pendulum::Tangent<double>::Constant(qd);
    const double gravity = m * g * l * std::sin(q);
    errG = std::max(errG, std::abs(pendulum::gravity_torques<double>(Q)(0) - gravity));
    const double fd = pendulum::forward_dynamics<double>(Q, QD, pendulum::Tangent<double>::Constant(tau))(0);
    errFD = std::max(errFD, std::abs(fd - (tau - gravity) / (Ic + m * l * l)));
    const double id = pendulum::inverse_dynamics<double>(Q, QD, pendulum::Tangent<double>::Constant(qdd))(0);
    errID = std::max(errID, std::abs(id - ((Ic + m * l * l) * qdd + gravity)));
  }
  pendulum::batch::forward_dynamics<double>(qs, qds, taus, fds, 25, 2); // 25 states (N x nq arrays), 2 threads
  for(int s = 0; s < 25; ++s)
    errBatch = std::max(errBatch, std::abs(fds[s] - (taus[s] - m * g * l * std::sin(qs[s])) / (Ic + m * l * l)));
  ok = report("generated gravity_torques = m g l sin q", errG, 1e-12) && ok;
  ok = report("generated forward_dynamics (closed form)", errFD, 1e-12) && ok;
  ok = report("generated inverse_dynamics (closed form)", errID, 1e-12) && ok;
  ok = report("generated batch::forward_dynamics (closed form)", errBatch, 1e-12) && ok;
  return ok ? 0 : 1;
}
