#pragma once
// One generated header's jacobian(body, q) behind a plain interface, for comparing two generators'
// output in one binary (jacobian_before_after.sh): each wrapper translation unit includes one header
// and registers itself.
#include <string>
#include <vector>

struct JacobianCase
{
  std::string robot;   ///< e.g. "solo12"
  std::string version; ///< "before" or "after"
  int nq = 0, nv = 0;
  /// The Body value of a link name, -1 if the header has no such link.
  int (*body)(const std::string & name) = nullptr;
  /// J = jacobian(body, q) (6 x nv, column-major) for one state.
  void (*eval)(int body, const double * q, double * J) = nullptr;
  /// ns per call of jacobian(body, q) over `iters` calls cycling through `count` states (row-major
  /// count x nq); every result is read (a checksum), the states change every call.
  double (*time)(int body, const double * states, int count, int iters) = nullptr;
};

std::vector<JacobianCase> & jacobianCases();
