#pragma once
// Articulated-body inertias (sva::ABInertia [I H; H^T M], I and M symmetric) on symbols, the
// quantities of the articulated-inertia pass of the ABA (Featherstone, RBDA table 7.1), and a
// dense symbolic L D L^T solve for the joint-space D = S^T IA S of multi-dof joints.

#include <string>
#include <vector>

#include "PassContext.h"

namespace rbdgen::passes
{

/// abi(M, H, I) = [I H; H^T M], I and M symmetric.
struct ABI
{
  Mat3 M, H, I;
};

/// The articulated inertia of a rigid body: rbi(m, h, I) = [I h^; -h^ m1].
ABI fromRigid(const Inertia & rb);
/// A m = [I w + H v; H^T w + M v]
Force applyABI(Block & b, const ABI & A, const Motion & m, const std::string & hint);
/// X^T A X: M' = E^T M E, H' = E^T H E + r^ M', I' = E^T I E + r^ (E^T H E)^T - H' r^
ABI transApplyABI(Block & b, const Xform & X, const ABI & A, const std::string & hint);
ABI addABI(Block & b, const ABI & x, const ABI & y, const std::string & hint);

/// Dense symmetric positive-definite k x k system: L D L^T factorisation on symbols, then solves.
class DenseLdlt
{
public:
  DenseLdlt(Block & b, std::vector<std::vector<Scalar>> A, const std::string & hint);
  std::vector<Scalar> solve(Block & b, std::vector<Scalar> x, const std::string & hint) const;

private:
  std::vector<std::vector<Scalar>> L; // unit lower, below the diagonal
  std::vector<Scalar> invD;
};

} // namespace rbdgen::passes
