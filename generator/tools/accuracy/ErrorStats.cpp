#include "ErrorStats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbdgen::accuracy
{

double relativeError(const Eigen::Ref<const Eigen::VectorXd> & x, const Eigen::Ref<const Eigen::VectorXd> & ref)
{
  if(!x.allFinite()) return std::numeric_limits<double>::infinity();
  const double scale = std::max(1.0, ref.lpNorm<Eigen::Infinity>());
  return (x - ref).lpNorm<Eigen::Infinity>() / scale;
}

double digits(double error)
{
  if(!std::isfinite(error) || error >= 1) return 0;
  return -std::log10(std::max(error, 1e-30));
}

ErrorStats summarize(std::vector<double> errors)
{
  ErrorStats s;
  if(errors.empty()) return s;
  for(double & e : errors)
    if(!std::isfinite(e)) e = std::numeric_limits<double>::infinity(); // NaN sorts as the worst
  std::sort(errors.begin(), errors.end());
  const std::size_t n = errors.size();
  s.max = errors.back();
  s.median = n % 2 ? errors[n / 2] : 0.5 * (errors[n / 2 - 1] + errors[n / 2]);
  return s;
}

} // namespace rbdgen::accuracy
