#pragma once
// Template part of Derivatives.h.

#include <algorithm>
#include <cstdio>

namespace rbdbench
{

template<class IdFn, class FdFn>
void checkDerivatives(const BenchCase & c, CheckLog & log, const std::string & impl, IdFn id, FdFn fd,
                      const std::string & idNote, const std::string & fdNote, double tolId, double tolFdPerCond)
{
  double eId = 0, eFd = 0, eFdRaw = 0, worstCond = 0;
  for(std::size_t k = 0; k < kDerivativesChecked && k < c.pool.size(); ++k)
  {
    const DerivativesRef ref = derivativesReference(c, c.pool[k]);
    const DerivativesRef a = id(k);
    eId = std::max({eId, relErr(a.dtau_dq, ref.dtau_dq), relErr(a.dtau_dalpha, ref.dtau_dalpha)});
    const DerivativesRef b = fd(k);
    const double e = std::max({relErr(b.alphaD, ref.alphaD), relErr(b.dalphaD_dq, ref.dalphaD_dq),
                               relErr(b.dalphaD_dalpha, ref.dalphaD_dalpha), relErr(b.Minv, ref.Minv)});
    eFdRaw = std::max(eFdRaw, e);
    eFd = std::max(eFd, e / std::max(1.0, ref.condH));
    worstCond = std::max(worstCond, ref.condH);
  }
  char buf[200];
  std::snprintf(buf, sizeof buf, "; vs central differences of the runtime in long double, %zu states", kDerivativesChecked);
  log.add(impl, "id_derivatives", eId, tolId, idNote + buf);
  std::snprintf(buf, sizeof buf, "; error / cond(H) (raw %.1e, largest cond(H) %.3g)", eFdRaw, worstCond);
  log.add(impl, "fd_derivatives", eFd, tolFdPerCond, fdNote + buf);
}

} // namespace rbdbench
