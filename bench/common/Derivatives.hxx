#pragma once
// Template part of Derivatives.h.

#include <algorithm>
#include <cstdio>

namespace rbdbench
{

/// Largest errors against a reference over several states: ID derivatives, FD derivatives raw and
/// divided by max(1, cond(H)).
struct DerivativesErrors
{
  double id = 0, fd = 0, fdRaw = 0, worstCond = 0;
  /// a: the ID derivatives (dtau_dq, dtau_dalpha), b: the FD derivatives (alphaD, dalphaD_dq, dalphaD_dalpha, Minv).
  void add(const DerivativesRef & a, const DerivativesRef & b, const DerivativesRef & ref);
};

template<class IdFn, class FdFn>
void checkDerivatives(const BenchCase & c, CheckLog & log, const std::string & impl, IdFn id, FdFn fd,
                      const std::string & idNote, const std::string & fdNote, double tolId, double tolFdPerCond)
{
  DerivativesErrors e;
  for(std::size_t k = 0; k < kDerivativesChecked && k < c.pool.size(); ++k)
    e.add(id(k), fd(k), derivativesReference(c, c.pool[k]));
  char buf[200];
  std::snprintf(buf, sizeof buf, "; vs the runtime's derivatives in long double, %zu states", kDerivativesChecked);
  log.add(impl, "id_derivatives", e.id, tolId, idNote + buf);
  std::snprintf(buf, sizeof buf, "; error / cond(H) (raw %.1e, largest cond(H) %.3g)", e.fdRaw, e.worstCond);
  log.add(impl, "fd_derivatives", e.fd, tolFdPerCond, fdNote + buf);
}

} // namespace rbdbench
