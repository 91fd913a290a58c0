#include "Pareto.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rbdgen::accuracy
{

std::vector<bool> paretoFront(const std::vector<CostError> & points)
{
  std::vector<bool> onFront(points.size(), false);
  std::vector<std::size_t> order;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(std::isfinite(points[i].cost) && std::isfinite(points[i].error)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a].cost != points[b].cost ? points[a].cost < points[b].cost : points[a].error < points[b].error;
  });
  // Walk by increasing cost: a point is dominated iff some point with cost <= its cost has a
  // smaller error, or the same error and a smaller cost (equal points are both kept).
  double bestError = std::numeric_limits<double>::infinity(), bestCost = 0;
  for(std::size_t i : order)
  {
    const CostError & p = points[i];
    const bool dominated = p.error > bestError || (p.error == bestError && p.cost > bestCost);
    if(!dominated)
    {
      onFront[i] = true;
      if(p.error < bestError) bestCost = p.cost;
      bestError = std::min(bestError, p.error);
    }
  }
  return onFront;
}

} // namespace rbdgen::accuracy
