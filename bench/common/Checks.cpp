#include "Checks.h"

#include <cstdio>

#include <benchmark/benchmark.h>

namespace rbdbench
{

const std::vector<std::string> kAlgorithms = {"fk",       "fk_vel", "id",      "id_fext", "gravity", "nle", "mass_matrix",
                                              "fd",       "fd_aba", "fd_crba", "jacobian", "jacobian_kin", "com",
                                              "id_derivatives", "fd_derivatives"};

void CheckLog::add(const std::string & impl, const std::string & algo, double maxErr, double tol,
                   const std::string & note, bool modelDiffers)
{
  results_.push_back({impl, algo, maxErr, tol, note, modelDiffers});
}

bool CheckLog::agrees(const std::string & impl, const std::string & algo) const
{
  for(const auto & r : results_)
    if(r.impl == impl && r.algo == algo) return r.ok();
  return false;
}

bool CheckLog::allOk() const
{
  for(const auto & r : results_)
    if(!r.ok() && !r.modelDiffers) return false;
  return true;
}

void CheckLog::publish(const std::string & robot) const
{
  for(const auto & r : results_)
  {
    char line[160];
    std::snprintf(line, sizeof line, "%.2e %s (tol %.0e)", r.maxErr, r.ok() ? "ok" : r.modelDiffers ? "DIFFERS(model-changed)" : "DISAGREES", r.tol);
    std::printf("check %-14s %-10s %-14s %s%s%s\n", robot.c_str(), r.impl.c_str(), r.algo.c_str(), line,
                r.note.empty() ? "" : "  ", r.note.c_str());
    benchmark::AddCustomContext("check/" + r.impl + "/" + r.algo, std::string(line) + (r.note.empty() ? "" : "; ") + r.note);
  }
  std::fflush(stdout);
}

} // namespace rbdbench
