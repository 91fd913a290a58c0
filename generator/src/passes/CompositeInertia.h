#pragma once
// The composite-inertia pass (leaves to root): Ic_k = I_k + sum over children c of X_k_c^T Ic_c X_k_c
// (body coordinates), and the first moments of mass (world) that the centre of mass and the
// momentum functions need:  m_k c_k = m_k o_k + E_0_k^T h_k.

#include <vector>

#include "ForwardMotion.h"

namespace rbdgen::passes
{

/// Composite inertia of every moving joint's subtree, in that joint's body frame.
std::vector<Inertia> compositeInertias(PassContext & ctx);

/// First moment m c (world) of joint k's body, from its world pose X0.
Vec3 firstMoment(PassContext & ctx, int k, const Xform & X0);

/// Sum of m c over every link (the static ones included), from the world poses of a pass with poses.
Vec3 totalFirstMoment(PassContext & ctx, const std::vector<Xform> & X0);

/// Centre of mass (world): totalFirstMoment / total mass.
Vec3 centerOfMass(PassContext & ctx, const std::vector<Xform> & X0);

/// The same from the composite inertias Ic of a composite-inertia pass: the first moments of the
/// root joints' subtrees (Mc o + E^T hc), one per root instead of one per body.
Vec3 centerOfMassFromComposites(PassContext & ctx, const std::vector<Xform> & X0, const std::vector<Inertia> & Ic);

} // namespace rbdgen::passes
