#pragma once
// Time per call: median over `runs` runs; each run calls f(i) for every state i of the pool,
// `reps` times, where reps is calibrated so that one run lasts at least minRunNs. Inputs change
// every call; f must keep its result live (keepAlive) so the compiler cannot drop the work.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace rbdgen::accuracy
{

/// The compiler must assume the asm reads `value`.
template<class T>
inline void keepAlive(const T & value)
{
  asm volatile("" : : "g"(&value) : "memory");
}

template<class F>
double medianNsPerCall(int poolSize, F && f, int runs = 7, double minRunNs = 5e6)
{
  using Clock = std::chrono::steady_clock;
  const auto pass = [&](int reps) {
    const auto t0 = Clock::now();
    for(int r = 0; r < reps; ++r)
      for(int i = 0; i < poolSize; ++i) f(i);
    return std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
  };
  const double once = std::max(pass(1), 1.0); // also warms caches up
  const int reps = std::max(1, static_cast<int>(std::ceil(minRunNs / once)));
  std::vector<double> perCall;
  for(int r = 0; r < runs; ++r) perCall.push_back(pass(reps) / (static_cast<double>(reps) * poolSize));
  std::nth_element(perCall.begin(), perCall.begin() + runs / 2, perCall.end());
  return perCall[static_cast<std::size_t>(runs / 2)];
}

} // namespace rbdgen::accuracy
