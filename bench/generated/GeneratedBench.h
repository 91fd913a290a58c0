#pragma once
// The generated code of one robot, seen by the robot-independent parts of the bench program
// (implemented by generated_robot.cpp.in, configured once per robot).

#include "../common/BenchCase.h"
#include "../common/Checks.h"

namespace rbdbench
{
/// Checks the generated double and float functions against the runtime on a few pool states
/// (log entries "gen_double", "gen_float") and registers their cells.
void registerGenerated(const BenchCase & c, CheckLog & log);
/// Name of the algorithm behind the generated forward_dynamics().
const char * generatedForwardDynamicsAlgorithm();
} // namespace rbdbench
