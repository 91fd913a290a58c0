// Derivatives of the dynamics: d tau/dq, d tau/dalpha by the world-frame passes of
// passes/DynamicsDerivatives.h, and the factors of H that forward_dynamics_derivatives() solves with.
#include <fmt/format.h>

#include "../passes/DynamicsDerivatives.h"
#include "Functions.h"
#include "Outputs.h"
#include "SceneEffects.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

/// d.dtau_dq and d.dtau_dalpha of the rigid-body terms: gravity (or none), velocity terms (or
/// none), and the world wrenches of the bodies in wrenchBodies read from `wrenches[w]` (held constant).
void emitRigidBodyDerivatives(Block & b, const RobotModel & rm, const std::optional<Eigen::Vector3d> & gravity,
                              bool velocityTerms, const std::vector<int> & wrenchBodies)
{
  PassContext ctx(b, rm);
  MotionRequest req = MotionRequest::make(true, velocityTerms, true);
  req.velocityProducts = velocityTerms;
  req.gravity = gravity;
  const MotionState m = forwardMotion(ctx, req, ctx.allJoints());
  const std::vector<WorldBody> w = worldBodies(ctx, m);
  const std::vector<SubtreeSums> c = subtreeSums(ctx, w);
  std::vector<Force> fext;
  if(!wrenchBodies.empty())
  {
    b.comment("wrench sums over each subtree (world coordinates at the world origin)");
    fext.assign(rm.joints.size(), Force::zero());
    for(std::size_t k = 0; k < wrenchBodies.size(); ++k)
    {
      const int o = rm.bodies[static_cast<std::size_t>(wrenchBodies[k])].owner;
      const std::string slot = fmt::format("wrenches[{}]", k);
      for(int a = o; a >= 0; a = rm.joints[static_cast<std::size_t>(a)].parent)
        fext[static_cast<std::size_t>(a)] = cg::add(b, fext[static_cast<std::size_t>(a)], Force{vec3Var(slot, 0), vec3Var(slot, 3)},
                                                    rm.joints[static_cast<std::size_t>(a)].tag + "_Fe");
    }
  }
  derivativePairs(ctx, w, c, gravity.value_or(Eigen::Vector3d::Zero()), fext,
                  [&](int r, int col, const Scalar & dq, const Scalar & da) {
                    if(!dq.isZero()) b.line(fmt::format("d.dtau_dq({}, {}) = {};", r, col, Block::text(dq)));
                    if(!da.isZero()) b.line(fmt::format("d.dtau_dalpha({}, {}) = {};", r, col, Block::text(da)));
                  });
}

/// X = H^-1 [-dID/dq, -dID/dalpha, 1] by row operations along the dof tree, into d.
void emitDerivativeSolves(Block & b, const Ltdl & f, std::size_t nv)
{
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
}

/// alphaD = (H + diag(armature))^-1 (tau - bias) into d.alphaD, then the derivatives (biasCall
/// empty: no bias; idCall: the inverse_dynamics_derivatives call at d.alphaD).
EmittedBody fdDerivativesBody(const RobotModel & rm, const std::vector<double> & armature, const std::string & biasCall,
                              const std::string & idCall)
{
  Block b;
  const auto nv = static_cast<std::size_t>(rm.nv);
  if(!biasCall.empty()) b.line("const Tangent<S> C = " + biasCall + ";");
  const Ltdl f = emitLtdl(b, rm, emitMassMatrix(b, rm, armature));
  std::vector<Scalar> x(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Scalar tau = Scalar::var(fmt::format("tau[{}]", i));
    x[i] = biasCall.empty() ? tau : b.sum({Term{1.0, {tau}}, Term{-1.0, {Scalar::var(fmt::format("C[{}]", i))}}}, fmt::format("x{}", i));
  }
  x = emitLtdlSolve(b, f, std::move(x));
  for(std::size_t i = 0; i < nv; ++i) b.line(fmt::format("d.alphaD[{}] = {};", i, Block::text(x[i])));
  b.line("const IdDerivatives<S> id = " + idCall + ";");
  emitDerivativeSolves(b, f, nv);
  return finish(b);
}

} // namespace

EmittedBody inverseDynamicsDerivativesBody(const RobotModel & rm)
{
  Block b;
  emitRigidBodyDerivatives(b, rm, Eigen::Vector3d(0, 0, -9.81), true, {});
  return finish(b);
}

EmittedBody sceneInverseDynamicsDerivativesBody(const RobotModel & rm, const SceneEffects & fx)
{
  Block b;
  emitRigidBodyDerivatives(b, rm, fx.gravity, fx.velocityTerms, fx.wrenchBodies);
  // joint-space terms: damping alpha, friction alpha / sqrt(alpha^2 + v_s^2) (derivative f v_s^2 / (.)^(3/2))
  for(int i = 0; i < rm.nv; ++i)
  {
    const auto ii = static_cast<std::size_t>(i);
    const double damping = ii < fx.damping.size() ? fx.damping[ii] : 0.0;
    const double friction = ii < fx.friction.size() ? fx.friction[ii] : 0.0;
    if(damping == 0.0 && friction == 0.0) continue;
    std::string rhs = damping != 0.0 ? Block::literal(damping) : "";
    if(friction != 0.0)
    {
      const std::string a = fmt::format("alpha[{}]", i), vs2 = Block::literal(fx.frictionVelocity * fx.frictionVelocity);
      b.line(fmt::format("const S fr2_{} = {} * {} + {};", i, a, a, vs2));
      rhs += fmt::format("{}{} * {} / (fr2_{} * std::sqrt(fr2_{}))", rhs.empty() ? "" : " + ", Block::literal(friction), vs2, i, i);
    }
    b.line(fmt::format("d.dtau_dalpha({}, {}) += {};", i, i, rhs));
  }
  return finish(b);
}

EmittedBody sceneForwardDynamicsDerivativesBody(const RobotModel & rm, const SceneEffects & fx, const std::string & biasCall,
                                                 const std::string & wrenchArg)
{
  return fdDerivativesBody(rm, fx.armature, biasCall,
                           "inverse_dynamics_derivatives<S>(q, alpha, d.alphaD" + wrenchArg + ")");
}

EmittedBody forwardDynamicsDerivativesBody(const RobotModel & rm)
{
  return fdDerivativesBody(rm, {}, "nonlinear_effects<S>(q, alpha)", "inverse_dynamics_derivatives<S>(q, alpha, d.alphaD)");
}

} // namespace rbdgen::emit
