#pragma once
// The passes of the inverse dynamics derivatives (runtime: rbd/IDDerivatives.h, which states the
// equations), all in world coordinates so that sums over a subtree need no transform:
//   worldBodies:  s_k = X_0_k^-1 S_k, then root to leaves in world coordinates (no body-frame pass):
//                 vJ_k = s_k alpha_k, v_k = v_p + vJ_k, a_k = a_p + s_k alphaD_k + v_p x vJ_k
//                 (a_0 = [0; -g]; the world derivative of s_k is v_carrier x s_k, and summed over
//                 the joint's dofs v_k x vJ_k = v_p x vJ_k)
//   subtreeSums:  leaves to root, each body's I_k, h_k = I_k v_k, g_k = I_k a_k + v_k x* h_k,
//                 dI_k/dt = v_k x* I_k - I_k v_k x = [[J, hd^], [hd^T, 0]],
//                 J = A + A^T - h v^T - v h^T + 2 (v.h) 1 with A = w^ Ibar, hd = w x h + m v,
//                 added into Ic, dIc/dt, Hc = sum h, Gc = sum g over each joint's subtree (computed
//                 where they are summed: nothing per body stays live across the tree; on trees of 8
//                 joints or more, for all bodies first, in SIMD lanes across bodies, and read back
//                 from arrays: detail::world_body_terms)
//   DerivativePairs: the rows u_k, b_k of each joint (joint(k)), then columns(): for dof m of joint
//                 j and dof k of joint i in the subtree of j, with
//                 u_k = Ic_i s_k, b_k = Bc_i^T s_k = dIc_i s_k - s_k x* Hc_i:
//                 dtau_k/dq_m = u_k . (a_w x s_m + w x (w x s_m)) + b_k . (w x s_m)
//                 dtau_k/dalpha_m = u_k . (sdot_m + w x s_m) + b_k . s_m
//                 (w, a_w: of j's parent; sdot_m = v_j x s_m, which is w x s_m for a 1-dof joint)
//                 and for k on a strict ancestor a of j: s_k . dF_j (the force change of j's subtree),
//                 dFa_m = Ic_j yaA + Bc_j s_m = Ic_j yaA + b_m + 2 s_m x* Hc_j.
//                 On trees of 4 joints or more, the rows u_k, b_k of the one-dof joints with a
//                 parent and yaQ, yvQ, yaA, dFq, dFa of their columns are computed first, in SIMD
//                 lanes across joints (detail::column_terms; inputs written by joint()).
//                 With u_k, b_k as the rows of UB (nv x 12) and the s_k as the rows of SM (nv x 6), a
//                 column's entries over a contiguous range of rows (j's subtree: RBDyn numbers dofs
//                 depth first; a run of consecutive ancestor dofs, e.g. a floating base's six) are one
//                 product UB[rows] [yaQ; yvQ], UB[rows] [yaA; s_m], SM[rows] dF_j, vectorised over the
//                 rows and summed over the columns of UB or SM whose factor is not zero
//                 (detail::rows_times; on trees with a subtree of 8 dofs or more; an arm's entries stay scalar).

#include <functional>
#include <string>
#include <vector>

#include "ForwardMotion.h"

namespace rbdgen::passes
{

/// dI/dt of a rigid-body inertia moving with a twist (m = 0 in the rigid-body layout).
struct InertiaRate
{
  Mat3 J;  ///< symmetric
  Vec3 hd;
};

struct WorldBody
{
  std::vector<Motion> s; ///< motion subspace columns
  Motion v, a;           ///< velocity, acceleration (gravity as a_0 = [0; -g])
};

struct SubtreeSums
{
  Inertia Ic;
  InertiaRate Idc;
  Force Hc, Gc; ///< sums of the momenta I v and of the inertial forces I a + v x* I v
};

/// s, v, a of every moving joint's body from the world poses X0 (world axes at the origin of the
/// passes), root to leaves: velocities from `alpha` (none: every v_k = 0), accelerations from
/// `alphaD` (none: alphaD = 0, the bias accelerations) and a0, the inherited acceleration of root
/// joints ([0; -g]).
std::vector<WorldBody> worldBodies(PassContext & ctx, const std::vector<Xform> & X0, bool velocity, const Motion & a0,
                                   bool acceleration = true);
/// Leaves to root: each body's world I, h = I v, g = I a + v x* h and dI/dt, emitted where they are
/// added into the sums over each joint's subtree (none of them stays live across the tree).
std::vector<SubtreeSums> subtreeSums(PassContext & ctx, const std::vector<Xform> & X0, const std::vector<WorldBody> & w);

/// A column's entries over rows [first, first + rows) as one product M y, M a matrix the passes fill
/// (pair_ub, pair_sm) and y zero but in the columns `cols` of M (values `y`).
struct BlockEntries
{
  std::string M;
  int first = 0, rows = 0;
  std::vector<int> cols;
  std::vector<std::string> y;

  bool empty() const { return cols.empty(); }
  /// the statement assigning them to rows [first, first + rows) of `column` (an Eigen column):
  /// column.segment<rows>(first) = detail::rows_times<padded, cols...>(M, first, {y...}).head<rows>()
  std::string into(const std::string & column) const;
};

/// True when the derivative pairs keep their long-lived inputs in arrays and emit each column out
/// of line (large trees: compile time).
bool derivativesInArrays(const RobotModel & rm);
/// d tau/dq and d tau/dalpha entries, handed to onEntry(row, col, dq, dalpha); entries never
/// handed over are zero. gravity: the world gravity of the forward pass (m/s^2), a_0 = [0; -gravity]
/// (zero: none). fextSums: when not empty, per joint the sum over its subtree of the external
/// wrenches (world, at the world origin) that the inverse dynamics subtracts, held constant: they
/// add s_k . (s_m x* Fext_i) to the pairs whose s_k moves with joint m. onBlock (optional, not
/// with fextSums): the entries of rows [first, first + rows) of column col (the subtree of the
/// column's joint, or a run of consecutive ancestor dofs) as products (empty: zero) of
/// `pair_ub` (row k = [u_k; b_k]) or `pair_sm` (row k = s_k), declared and filled here, instead of
/// one onEntry per entry. Emitted: the rows u_k, b_k of every joint (root first), then the columns.
void derivativePairs(PassContext & ctx, const std::vector<WorldBody> & w, const std::vector<SubtreeSums> & c,
                     const Eigen::Vector3d & gravity, const std::vector<Force> & fextSums,
                     const std::function<void(int row, int col, const Scalar & dq, const Scalar & da)> & onEntry,
                     const std::function<void(int col, const BlockEntries & dq, const BlockEntries & da)> & onBlock = {});

} // namespace rbdgen::passes
