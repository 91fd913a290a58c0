// Derivatives of the dynamics: d tau/dq, d tau/dalpha by the world-frame passes of
// passes/DynamicsDerivatives.h, and the factors of H that forward_dynamics_derivatives() solves with.
#include <fmt/format.h>

#include "../passes/DynamicsDerivatives.h"
#include "Functions.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

EmittedBody inverseDynamicsDerivativesBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  const Eigen::Vector3d gravity(0, 0, -9.81);
  MotionRequest req = MotionRequest::make(true, true, true);
  req.gravity = gravity;
  const MotionState m = forwardMotion(ctx, req, ctx.allJoints());
  const std::vector<WorldBody> w = worldBodies(ctx, m);
  const std::vector<SubtreeSums> c = subtreeSums(ctx, w);
  derivativePairs(ctx, w, c, gravity, [&](int r, int col, const Scalar & dq, const Scalar & da) {
    if(!dq.isZero()) b.line(fmt::format("d.dtau_dq({}, {}) = {};", r, col, Block::text(dq)));
    if(!da.isZero()) b.line(fmt::format("d.dtau_dalpha({}, {}) = {};", r, col, Block::text(da)));
  });
  return finish(b);
}

EmittedBody massMatrixFactorsBody(const RobotModel & rm)
{
  Block b;
  const Ltdl f = emitLtdl(b, rm, emitMassMatrix(b, rm, {}));
  for(int k = 0; k < rm.nv; ++k)
  {
    const auto kk = static_cast<std::size_t>(k);
    b.line(fmt::format("f.invD[{}] = {};", k, Block::text(f.invD[kk])));
    for(int i = f.lambda[kk]; i >= 0; i = f.lambda[static_cast<std::size_t>(i)])
      b.line(fmt::format("f.L[{}] = {};", k * rm.nv + i, Block::text(f.L[kk][static_cast<std::size_t>(i)])));
  }
  return finish(b);
}

} // namespace rbdgen::emit
