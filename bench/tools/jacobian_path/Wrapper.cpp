// Compiled once per generated header: -DRBDGEN_NS=<namespace> -DRBDGEN_ROBOT="robot" -DRBDGEN_VERSION_TAG="before|after".
#include <chrono>
#include <cstring>
#include <vector>

#include <Eigen/Core>

#include "Case.h"

#define RBDGEN_STR2(x) #x
#define RBDGEN_STR(x) RBDGEN_STR2(x)
#include RBDGEN_STR(RBDGEN_NS/dynamics.hpp)

namespace
{
namespace ns = RBDGEN_NS;
using Jacobian = Eigen::Matrix<double, 6, ns::nv>;

// Not inlined into the timing loop: the call a user's code makes, the result in the caller's memory.
__attribute__((noinline)) Jacobian jacobianOf(ns::Body body, const ns::Config<double> & q)
{
  return ns::jacobian<double>(body, q);
}

int body(const std::string & name)
{
  for(int b = 0; b < ns::nbodies; ++b)
    if(name == ns::body_names[static_cast<std::size_t>(b)]) return b;
  return -1;
}

void eval(int b, const double * q, double * J)
{
  const Jacobian Jb = jacobianOf(static_cast<ns::Body>(b), Eigen::Map<const ns::Config<double>>(q));
  std::memcpy(J, Jb.data(), sizeof(double) * Jb.size());
}

double time(int b, const double * states, int count, int iters)
{
  std::vector<ns::Config<double>> qs(static_cast<std::size_t>(count));
  for(int k = 0; k < count; ++k) qs[static_cast<std::size_t>(k)] = Eigen::Map<const ns::Config<double>>(states + k * ns::nq);
  double checksum = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for(int i = 0; i < iters; ++i)
  {
    const Jacobian J = jacobianOf(static_cast<ns::Body>(b), qs[static_cast<std::size_t>(i % count)]);
    checksum += J(3, 0) + J(5, ns::nv - 1);
  }
  const auto t1 = std::chrono::steady_clock::now();
  volatile double keep = checksum;
  static_cast<void>(keep);
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / iters;
}

const bool registered = [] {
  jacobianCases().push_back({RBDGEN_ROBOT, RBDGEN_VERSION_TAG, ns::nq, ns::nv, &body, &eval, &time});
  return true;
}();
} // namespace
