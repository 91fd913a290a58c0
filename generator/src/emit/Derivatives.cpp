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

EmittedBody forwardDynamicsDerivativesBody(const RobotModel & rm)
{
  Block b;
  const auto nv = static_cast<std::size_t>(rm.nv);
  b.line("const Tangent<S> C = nonlinear_effects<S>(q, alpha);");
  const Ltdl f = emitLtdl(b, rm, emitMassMatrix(b, rm, {}));
  // alphaD = H^-1 (tau - C), unrolled
  std::vector<Scalar> x(nv);
  for(std::size_t i = 0; i < nv; ++i)
    x[i] = b.sum({Term{1.0, {Scalar::var(fmt::format("tau[{}]", i))}}, Term{-1.0, {Scalar::var(fmt::format("C[{}]", i))}}},
                 fmt::format("x{}", i));
  x = emitLtdlSolve(b, f, std::move(x));
  for(std::size_t i = 0; i < nv; ++i) b.line(fmt::format("d.alphaD[{}] = {};", i, Block::text(x[i])));
  b.line("const IdDerivatives<S> id = inverse_dynamics_derivatives<S>(q, alpha, d.alphaD);");
  b.comment("X = H^-1 [-dID/dq, -dID/dalpha, 1]: row operations along the dof tree (L^T, D, then L)");
  b.line("Eigen::Matrix<S, nv, 3 * nv, Eigen::RowMajor> X;");
  b.line("X << -id.dtau_dq, -id.dtau_dalpha, Eigen::Matrix<S, nv, nv>::Identity();");
  for(std::size_t i = nv; i-- > 0;)
    for(int j = f.lambda[i]; j >= 0; j = f.lambda[static_cast<std::size_t>(j)])
      if(!f.L[i][static_cast<std::size_t>(j)].isZero())
        b.line(fmt::format("X.row({}) -= {} * X.row({});", j, Block::text(f.L[i][static_cast<std::size_t>(j)]), i));
  for(std::size_t i = 0; i < nv; ++i) b.line(fmt::format("X.row({}) *= {};", i, Block::text(f.invD[i])));
  for(std::size_t i = 0; i < nv; ++i)
    for(int j = f.lambda[i]; j >= 0; j = f.lambda[static_cast<std::size_t>(j)])
      if(!f.L[i][static_cast<std::size_t>(j)].isZero())
        b.line(fmt::format("X.row({}) -= {} * X.row({});", i, Block::text(f.L[i][static_cast<std::size_t>(j)]), j));
  b.line("d.dalphaD_dq = X.template leftCols<nv>();");
  b.line("d.dalphaD_dalpha = X.template middleCols<nv>(nv);");
  b.line("d.Minv = X.template rightCols<nv>();");
  return finish(b);
}

} // namespace rbdgen::emit
