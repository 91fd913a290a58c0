#pragma once
// The backward force pass (leaves to root) and the force sources it accumulates:
//   f_k  = I_k a_k + v_k x* I_k v_k                  inertial (body coordinates)
//        - X_0_k^* w                                 a wrench w on a link (world, at the world origin)
//        - [p x E fc; E fc]                          a world force fc at point p of the body (contacts)
//   tau_k = S_k^T f_k,   f_p += X_p_k^T f_k.
// Joint-space terms (armature, damping, friction) are added by the caller to each tau_k.

#include <functional>
#include <vector>

#include "ForwardMotion.h"

namespace rbdgen::passes
{

/// Constant rigid-body inertia of the body moved by joint k (merged links included), entries named
/// after the header's model constants (`model::<tag>.m`, `.hx`, `.I01`; see modelConstants).
Inertia bodyInertia(const MovingJoint & mj);
/// The rotational inertia bodyInertia uses: (I + I^T) / 2 of the body's inertia at its origin.
Eigen::Matrix3d symmetricInertia(const MovingJoint & mj);

/// f_k = I_k a_k (+ v_k x* I_k v_k when velocityProducts) of joint k (m holds k's quantities).
Force inertialForce(PassContext & ctx, const MotionState & m, bool velocityProducts, int k);
/// inertialForce for every joint in `joints`, zero elsewhere.
std::vector<Force> inertialForces(PassContext & ctx, const MotionState & m, bool velocityProducts,
                                  const std::vector<int> & joints);

/// f_owner -= X_0_owner^* w: wrench w (world coordinates at the world origin) on link `body`
/// (m from a pass with poses). A link that never moves takes no wrench.
void subtractWorldWrench(PassContext & ctx, std::vector<Force> & f, const MotionState & m, int body, const Force & w,
                         const std::string & hint);

/// f_owner -= [p x fb; fb], fb = E_0_owner fc: world force fc at point p (owner's body coordinates).
void subtractPointForce(PassContext & ctx, std::vector<Force> & f, const MotionState & m, int owner, const Vec3 & p,
                        const Vec3 & fc, const std::string & hint);

/// Leaves to root over every joint: tau_k = S_k^T f_k, handed to onTau(k, tau_k), then f_p += X_p_k^T f_k.
void backwardForces(PassContext & ctx, std::vector<Force> & f,
                    const std::function<void(int k, const std::vector<Scalar> & tau)> & onTau);

/// The world wrenches' part of inverse dynamics as a pass of its own (RNEA is linear in the wrenches):
///   W_k = sum of the wrenches on the links of joint k's subtree (world coordinates at the world
///   origin, so they add without transforms), tau_ext,k = S_k^T X_0_k^* W_k,
/// handed to onTau(k, tau_ext,k) for every joint; inverse dynamics with the wrenches is tau - tau_ext.
/// linkWrench: per link (body index), the C++ expression of its wrench (a 6-vector [n; f]); W_k is
/// summed as one 6-vector statement per joint (`const Wrench<S> <tag>_W = ...;`); X0: world poses of
/// every joint's body frame.
void worldWrenchTorques(PassContext & ctx, const std::vector<Xform> & X0, const std::vector<std::string> & linkWrench,
                        const std::function<void(int k, const std::vector<Scalar> & tau)> & onTau);

/// onTau that writes `<dst>[i] = tau;` for each dof i of joint k.
std::function<void(int, const std::vector<Scalar> &)> writeTorques(PassContext & ctx, const std::string & dst);

} // namespace rbdgen::passes
