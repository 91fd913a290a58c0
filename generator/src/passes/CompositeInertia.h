#pragma once
// The composite-inertia pass (leaves to root): Ic_k = I_k + sum over children c of X_k_c^T Ic_c X_k_c
// (body coordinates), and the first moments of mass (world) that the centre of mass and the
// momentum functions need:  m_k c_k = m_k o_k + E_0_k^T h_k.

#include <functional>
#include <vector>

#include "ForwardMotion.h"

namespace rbdgen::passes
{

/// Composite inertia of every moving joint's subtree, in that joint's body frame. final(k, Ic_k), when
/// given, runs for every joint, leaves first, as soon as Ic_k is complete (its children added; before
/// it is added to its parent's): a pass that consumes Ic_k (the mass matrix's columns) emits its
/// statements next to it, which keeps few composite inertias live at once in the compiled code.
std::vector<Inertia> compositeInertias(PassContext & ctx, const std::function<void(int k, const Inertia & Ic)> & final = {});

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
