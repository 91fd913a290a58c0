// Inverse dynamics (recursive Newton-Euler): forward motion pass, inertial force source, backward
// force pass; with a wrench on every link, that RNEA (detail::inverse_dynamics_from) minus the
// wrenches' torques of passes::worldWrenchTorques.
#include <fmt/format.h>

#include "../passes/BackwardForce.h"
#include "../passes/SharedPasses.h"
#include "Functions.h"
#include "Outputs.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

// gravityParameter: non-empty, gravity's magnitude is that parameter (terms.gravityVector its direction)
void emitRnea(PassContext & ctx, const RneaTerms & terms, const std::string & gravityParameter = "")
{
  MotionRequest req;
  req.velocity = terms.velocity;
  req.acceleration = true;
  req.alphaD = terms.acceleration;
  if(terms.gravity) req.gravity = terms.gravityVector;
  req.gravityParameter = gravityParameter;
  // each joint's inertial force right after its motion (fewer values live at once); on a large
  // tree computed into the slots of an array kept in memory (rnea_f[k]: HomeInSlots.h,
  // RBDGEN_IN_MEMORY), which the backward pass reads: as named values, live from the forward pass
  // to the backward one, they were spilled to the stack one by one (talos_reduced + free base's
  // nonlinear_effects: 1,267 of its 5,841 instructions moved values to and from the stack)
  Block & b = ctx.block();
  const std::size_t n = ctx.model().joints.size();
  const bool inArray = SharedPasses::largeTree(ctx.model());
  if(inArray)
  {
    b.line(fmt::format("S rnea_f[{}][6];", n));
    b.line("RBDGEN_IN_MEMORY(rnea_f);");
    b.homeCopiesIn("rnea_f");
  }
  std::vector<Force> f(n, Force::zero());
  forwardMotion(ctx, req, ctx.allJoints(), [&](int k, const MotionState & m) {
    Force & fk = f[static_cast<std::size_t>(k)];
    fk = inertialForce(ctx, m, terms.velocity, k);
    if(inArray) stashScalars(b, "rnea_f", k, {&fk.n[0], &fk.n[1], &fk.n[2], &fk.f[0], &fk.f[1], &fk.f[2]});
  });
  backwardForces(ctx, f, writeTorques(ctx, "tau"));
}

} // namespace

EmittedBody rneaBody(const RobotModel & rm, const RneaTerms & terms)
{
  Block b;
  PassContext ctx(b, rm);
  // On a large tree the shared kernels, computed first and live through both passes, spill: each
  // joint's kernel is emitted at its first use instead (SharedPasses::largeTree).
  if(SharedPasses::largeTree(rm)) ctx.emitInPlace();
  emitRnea(ctx, terms);
  return finish(b);
}

EmittedBody inverseDynamicsFromKernelsBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  ctx.kernelsFromCaller();
  emitRnea(ctx, {}, "g");
  return finish(b);
}

std::string gravityLiteral()
{
  return Block::literal(RneaTerms{}.gravityVector.norm());
}

EmittedBody inverseDynamicsWrenchesBody(const RobotModel & rm)
{
  Block b;
  if(rm.joints.empty())
  {
    b.line("Tangent<S> tau = inverse_dynamics<S>(q, alpha, alphaD);");
    return finish(b);
  }
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, false), ctx.allJoints());
  ctx.kernel(0); // (declares K)
  b.line("Tangent<S> tau;");
  b.line(fmt::format("detail::inverse_dynamics_from<S>(K, alpha, alphaD, {}, tau);", gravityLiteral()));
  std::vector<std::string> w;
  for(std::size_t i = 0; i < rm.bodies.size(); ++i) w.push_back(linkSlot(rm, "fext", static_cast<int>(i)));
  worldWrenchTorques(ctx, m.X0, w, [&](int k, const std::vector<Scalar> & tau) {
    const MovingJoint & mj = ctx.joint(k);
    for(int d = 0; d < mj.nv; ++d)
      if(!tau[static_cast<std::size_t>(d)].isZero())
        b.line(fmt::format("tau[{}] -= {};", mj.vIndex + d, Block::text(tau[static_cast<std::size_t>(d)])));
  });
  return finish(b);
}

} // namespace rbdgen::emit
