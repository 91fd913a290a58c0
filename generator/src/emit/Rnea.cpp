// Inverse dynamics (recursive Newton-Euler): forward motion pass, inertial and external force
// sources, backward force pass.
#include <fmt/format.h>

#include "../passes/BackwardForce.h"
#include "Functions.h"
#include "Outputs.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

EmittedBody rneaBody(const RobotModel & rm, const RneaTerms & terms)
{
  Block b;
  PassContext ctx(b, rm);
  MotionRequest req;
  req.poses = terms.externalForces;
  req.velocity = terms.velocity;
  req.acceleration = true;
  req.alphaD = terms.acceleration;
  if(terms.gravity) req.gravity = terms.gravityVector;
  const MotionState m = forwardMotion(ctx, req, ctx.allJoints());
  std::vector<Force> f = inertialForces(ctx, m, terms.velocity, ctx.allJoints());
  if(terms.externalForces)
  {
    b.comment("external wrenches: f_k -= X_0_k^* fext (world coordinates at the world origin)");
    for(std::size_t i = 0; i < rm.bodies.size(); ++i)
    {
      const std::string slot = linkSlot(rm, "fext", static_cast<int>(i));
      subtractWorldWrench(ctx, f, m, static_cast<int>(i), {vec3Var(slot, 0), vec3Var(slot, 3)},
                          fmt::format("fx_{}", rm.bodies[i].ident));
    }
  }
  backwardForces(ctx, f, writeTorques(ctx, "tau"));
  return finish(b);
}

} // namespace rbdgen::emit
