#pragma once
// Pareto front of (cost, error) points: a point is on the front when no other point is at least as
// good in both and strictly better in one (smaller time per call and smaller error are better).

#include <vector>

namespace rbdgen::accuracy
{

struct CostError
{
  double cost = 0;  ///< e.g. ns per call, or wall seconds per simulated second
  double error = 0; ///< e.g. max relative error
};

/// onFront[i] is true when point i is not dominated. Non-finite points are never on the front.
/// O(n log n): sort by cost (then error), keep each point whose error is below every cheaper one's.
std::vector<bool> paretoFront(const std::vector<CostError> & points);

} // namespace rbdgen::accuracy
