#pragma once
// The functions of one generated header behind a plain interface, for comparing two generators'
// output in one binary (before_after.sh): each wrapper translation unit includes one header and
// registers itself; main.cpp checks that both versions agree, then times them alternately.
#include <string>
#include <vector>

/// One state: q (nq), alpha and alphaD (nv), a wrench per link (nbodies x 6, [n; f] world).
struct State
{
  std::vector<double> q, alpha, alphaD, fext;
};

struct FunctionCase
{
  std::string name;  ///< as the table shows it, e.g. "jacobian(body, q)"
  bool link = false; ///< takes a Body (timed per link given on the command line)
  /// The result, flattened (every entry), for one state.
  void (*eval)(int body, const State & s, std::vector<double> & out) = nullptr;
  /// ns per call over `iters` calls cycling through the states; every call's result is read (a
  /// checksum), the state changes every call, the call is not inlined into the loop. Inputs a
  /// function takes precomputed (Kinematics) are computed before the clock starts; `shift` (the
  /// run's index) places the stack frames and the inputs differently in each run.
  double (*time)(int body, const std::vector<State> & states, int iters, int shift) = nullptr;
};

struct HeaderCase
{
  std::string robot;   ///< e.g. "solo12"
  std::string version; ///< "before" or "after"
  int nq = 0, nv = 0, nbodies = 0;
  /// The Body value of a link name, -1 if the header has no such link.
  int (*body)(const std::string & name) = nullptr;
  std::vector<FunctionCase> functions;
};

std::vector<HeaderCase> & headerCases();
