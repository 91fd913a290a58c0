#pragma once
#include "BenchCase.h"
#include "Checks.h"

namespace rbdbench
{
/// Registers the runtime (rbd::, double) cells. Each cell starts from q (alpha, alphaD, tau) in a
/// MultiBodyConfig and includes what the algorithm needs first (forwardKinematics,
/// forwardVelocity), as the generated functions and the peers do. The derivative cells
/// (rbd::InverseDynamicsDerivatives, rbd::ForwardDynamicsDerivatives in double) are checked against
/// the long double reference first (log entries "runtime/{id,fd}_derivatives") and timed if they agree.
void registerRuntime(const BenchCase & c, CheckLog & log);
} // namespace rbdbench
