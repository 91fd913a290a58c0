// The C++ side of examples/python/timing.py: the same generated forward dynamics as the module of
// rbdgen.compile over N row-major states, timed (CPU time of this thread, best run), two ways: a
// plain loop of single-state calls, and one call of the batch API (NS/batch.hpp: SIMD packs, one
// thread), which is what one batched Python call does on one thread. Compiled by timing.py with the
// module's flags and -DROBOT_HEADER (the robot's batch.hpp) / -DROBOT_NS.
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include ROBOT_HEADER

namespace g = ROBOT_NS;

int main(int argc, char ** argv)
{
  const std::size_t n = argc > 1 ? static_cast<std::size_t>(std::atol(argv[1])) : 100000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<double> q(n * g::nq), v(n * g::nv), tau(n * g::nv), a(n * g::nv);
  for(auto * x : {&q, &v, &tau})
    for(double & e : *x) e = u(rng);
  // CPU time of this thread, as timing.py measures (robust to a shared machine): the best of `runs`
  auto best = [runs](auto && f) {
    std::vector<double> times;
    for(int r = 0; r < runs; ++r)
    {
      timespec t0, t1;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
      f();
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
      times.push_back(static_cast<double>(t1.tv_sec - t0.tv_sec) + 1e-9 * static_cast<double>(t1.tv_nsec - t0.tv_nsec));
    }
    return *std::min_element(times.begin(), times.end());
  };
  double check = 0;
  const double loop = best([&] {
    for(std::size_t i = 0; i < n; ++i)
      Eigen::Map<g::Tangent<double>>{a.data() + i * g::nv} =
          g::forward_dynamics<double>(g::Config<double>(Eigen::Map<const g::Config<double>>(q.data() + i * g::nq)),
                                      g::Tangent<double>(Eigen::Map<const g::Tangent<double>>(v.data() + i * g::nv)),
                                      g::Tangent<double>(Eigen::Map<const g::Tangent<double>>(tau.data() + i * g::nv)));
  });
  for(double e : a) check += e;
  const double batch = best([&] { g::batch::forward_dynamics<double>(q.data(), v.data(), tau.data(), a.data(), n); });
  for(double e : a) check += e;
  // states per second of the loop, its ns per call, states per second of the batch call; the
  // checksum keeps the results live
  const double states = static_cast<double>(n);
  std::printf("%.6e %.3f %.6e %.17g\n", states / loop, 1e9 * loop / states, states / batch, check);
  return 0;
}
