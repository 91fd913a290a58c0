#pragma once
// The forward motion pass (root to leaves), each quantity on request:
//   X_0_k = X_j,k X_T,k X_0_p                        world pose of joint k's body frame
//   v_k   = X_p_k v_p + S_k alpha_k                  body velocity (body coordinates)
//   a_k   = X_p_k a_p + S_k alphaD_k + v_k x S_k alpha_k,   a_0 = [0; -g]
// (over every joint, poses, velocities and v_k x S_k alpha_k come from the header's shared passes)
// (RBDyn: gravity enters as a fictitious upward acceleration of the world). Inputs that a request
// leaves out are zero, and the constant folding of codegen/ removes every term they touch.

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "PassContext.h"

namespace rbdgen::passes
{

struct MotionRequest
{
  bool poses = false;            ///< X_0_k
  bool velocity = false;         ///< v_k (and vJ_k = S_k alpha_k)
  bool acceleration = false;     ///< a_k
  bool alphaD = true;            ///< a_k includes S_k alphaD_k (false: alphaD = 0)
  bool velocityProducts = true;  ///< a_k includes v_k x vJ_k (when velocity)
  std::optional<Eigen::Vector3d> gravity; ///< world, m/s^2; nullopt: no gravity in a_k
  /// When set, the magnitude of gravity is this emitted scalar (m/s^2, a parameter of the function:
  /// one body serves with and without gravity) and `gravity` gives only its direction.
  std::string gravityParameter;

  static MotionRequest make(bool poses, bool velocity, bool acceleration = false)
  {
    MotionRequest r;
    r.poses = poses;
    r.velocity = velocity;
    r.acceleration = acceleration;
    return r;
  }
};

/// Per moving joint (index k); entries of joints the pass did not visit are identity / zero.
struct MotionState
{
  std::vector<Xform> X0;
  std::vector<Motion> vJ, v, a;
  bool sharedVelocities = false; ///< vJ, v are the header's shared ones (SharedPasses::velocities())
};

/// Run the pass over `joints` (ascending, closed under parents; e.g. ctx.allJoints() or a support path).
/// afterJoint(k, m), when given, runs right after joint k's quantities are emitted (m holds them and
/// its ancestors'): a pass that consumes them joint by joint (RNEA's inertial forces) emits its
/// statements next to the ones they read, which keeps few values live at once in the compiled code.
MotionState forwardMotion(PassContext & ctx, const MotionRequest & req, const std::vector<int> & joints,
                          const std::function<void(int k, const MotionState & m)> & afterJoint = {});

/// c_k = v_k x vJ_k of joint k emitted from its velocities; zero at a root joint, whose v_k is vJ_k
/// (the world does not move), so that nothing downstream multiplies a vJ x vJ the compiler cannot fold.
Motion velocityBias(Block & b, const MovingJoint & mj, const Motion & v, const Motion & vJ, const std::string & hint);

/// c_k = v_k x vJ_k of joint k (velocityBias): read from the shared velocity products when m's velocities are the
/// shared ones (declaring `VPs` in the body once), else emitted.
Motion velocityProduct(PassContext & ctx, const MotionState & m, int k, const std::string & hint);

/// The world pose of link `body`: X_0_link = X_owner_link X_0_owner (X0 from a pass with poses).
Xform linkPose(PassContext & ctx, const MotionState & m, int body);

} // namespace rbdgen::passes
