#pragma once
// The error measures of the accuracy study.
//   per call:  e = ||x - ref||_inf / max(1, ||ref||_inf)   (relative for large outputs, absolute for small)
//   per variant over the states: max and median of e; digits = -log10(e) (e floored at 1e-30: 30 digits)

#include <vector>

#include <Eigen/Core>

namespace rbdgen::accuracy
{

/// e = ||x - ref||_inf / max(1, ||ref||_inf); +inf if x has a NaN or an infinity.
double relativeError(const Eigen::Ref<const Eigen::VectorXd> & x, const Eigen::Ref<const Eigen::VectorXd> & ref);

/// Correct decimal digits of an error: -log10(max(e, 1e-30)); 0 digits for e >= 1 or non-finite e.
double digits(double error);

struct ErrorStats
{
  double max = 0;    ///< largest per-call error
  double median = 0; ///< median per-call error (mean of the two middle values for an even count)
};

/// Max and median of per-call errors (empty: zeros); a non-finite error makes max +inf.
ErrorStats summarize(std::vector<double> errors);

} // namespace rbdgen::accuracy
