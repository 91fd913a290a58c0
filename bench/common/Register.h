#pragma once
// Registration of one timed cell "<robot>/<algorithm>/<implementation>": each iteration calls
// f(k) on pool state k, a different state every iteration. f keeps its result alive with
// benchmark::DoNotOptimize.

#include <string>

#include <benchmark/benchmark.h>

#include "BenchCase.h"

namespace rbdbench
{

template<class F>
void addBench(const std::string & robot, const std::string & algo, const std::string & impl, F f)
{
  benchmark::RegisterBenchmark((robot + "/" + algo + "/" + impl).c_str(), [f](benchmark::State & st) mutable {
    std::size_t k = 0;
    for(auto _ : st)
    {
      f(k);
      k = (k + 1) & (kPoolSize - 1);
    }
  });
}

} // namespace rbdbench
