#pragma once
#include "BenchCase.h"

namespace rbdbench
{
/// Registers the runtime (rbd::, double) cells. Each cell starts from q (alpha, alphaD, tau) in a
/// MultiBodyConfig and includes what the algorithm needs first (forwardKinematics,
/// forwardVelocity), as the generated functions and the peers do.
void registerRuntime(const BenchCase & c);
} // namespace rbdbench
