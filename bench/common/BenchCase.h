#pragma once
// One robot of the benchmark: the runtime model loaded from its URDF, a pool of random states
// (the same for every implementation), and the runtime's reference results on those states.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <rbd/parsers/urdf.h>

namespace rbdbench
{

constexpr std::size_t kPoolSize = 256; ///< states in the pool (a power of two: index & (kPoolSize - 1))

/// One state in the runtime's layout (rbd::paramToVector / dofToVector order).
struct State
{
  Eigen::VectorXd q, alpha, alphaD, tau;
  Eigen::VectorXd fext; ///< 6 x nbodies: a wrench on each link, world coordinates at the world origin
};

/// The runtime's results at one state: what every other implementation is checked against.
struct Reference
{
  std::vector<sva::PTransformd> bodyPosW; ///< X_0_i, world to body i
  std::vector<sva::MotionVecd> bodyVelB;  ///< body velocity in body coordinates
  Eigen::VectorXd tauID, tauIDext, tauGravity, tauNLE, alphaDFD; ///< tauIDext: ID with the state's fext
  Eigen::MatrixXd H;    ///< nv x nv
  Eigen::MatrixXd J;    ///< 6 x nv, [angular; linear], world axes at the origin of jacobianBody
  Eigen::Vector3d com;  ///< world
};

struct BenchCase
{
  std::string name, urdf;
  bool floating = false;
  rbd::parsers::ParserResult model;
  std::vector<State> pool;
  int jacobianBody = -1;       ///< runtime body index: the body of the last joint with dof > 0
  std::string jacobianBodyName;
};

/// Loads the URDF (free root joint when floating) and draws kPoolSize seeded random states:
/// joint values in [-3, 3] (unit quaternions), velocities, accelerations, torques in [-2, 2];
/// link wrenches in [-2, 2] from a second generator (the other values as before they existed).
BenchCase loadCase(const std::string & name, const std::string & urdf, bool floating);

/// The runtime's results at state s (FK, FV, ID, gravity, NLE, H, FD by CRBA, Jacobian, CoM).
Reference reference(const BenchCase & c, const State & s);

/// ||a - b||_inf / max(1, ||b||_inf).
double relErr(const Eigen::Ref<const Eigen::MatrixXd> & a, const Eigen::Ref<const Eigen::MatrixXd> & b);

} // namespace rbdbench
