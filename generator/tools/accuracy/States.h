#pragma once
// The seeded random states of the accuracy study, and their binary file for the compiled driver.
//   q: joint values uniform in [-3, 3], quaternions (spherical, free) uniform on the unit sphere;
//   alpha, alphaD, tau: uniform in [-2, 2].
// File (native endianness, read by templates/accuracy_driver.cpp.in):
//   int32 count, nq, nv; then per state q (nq), alpha (nv), alphaD (nv), tau (nv) as float64.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <rbd/MultiBody.h>

namespace rbdgen::accuracy
{

struct State
{
  Eigen::VectorXd q, alpha, alphaD, tau;
};

/// `count` states of the model, reproducible from `seed` (std::mt19937_64).
std::vector<State> randomStates(const rbd::MultiBody & mb, int count, std::uint64_t seed);

/// Write the states file (throws std::runtime_error naming the path on failure).
void writeStates(const std::string & path, const std::vector<State> & states, int nq, int nv);

} // namespace rbdgen::accuracy
