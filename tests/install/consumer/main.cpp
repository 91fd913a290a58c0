// A downstream program using the installed runtime: a 1 kg point mass on a 1 m massless rod,
// horizontal (q = 0, rod along +x, joint axis y): the gravity torque is m g l = 9.81 N m.
#include <cmath>
#include <cstdio>

#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/MultiBodyGraph.h>

int main()
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
  const double tau = mbc.jointTorque[1][0];
  // Gravity's torque about the hinge: r x F = (1,0,0) x (0,0,-9.81) = (0, 9.81, 0); holding needs -9.81.
  std::printf("consumer: holding torque %.6f N m (expected -9.81)\n", tau);
  return std::abs(tau + 9.81) < 1e-9 ? 0 : 1;
}
