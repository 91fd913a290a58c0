// The C++ side of examples/python/timing.py: the same generated forward dynamics as the module of
// rbdgen.compile, called in a plain loop over N row-major states (what one batched Python call does
// on one thread), timed. Compiled by timing.py with the module's flags and -DROBOT_HEADER / -DROBOT_NS.
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
  const long n = argc > 1 ? std::atol(argv[1]) : 100000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<double> q(static_cast<std::size_t>(n * g::nq)), v(static_cast<std::size_t>(n * g::nv)),
      tau(static_cast<std::size_t>(n * g::nv)), a(static_cast<std::size_t>(n * g::nv));
  for(auto * x : {&q, &v, &tau})
    for(double & e : *x) e = u(rng);
  std::vector<double> times;
  for(int r = 0; r < runs; ++r)
  {
    timespec t0, t1; // CPU time of this thread, as timing.py measures (robust to a shared machine)
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
    for(long i = 0; i < n; ++i)
      Eigen::Map<g::Tangent<double>>{a.data() + i * g::nv} =
          g::forward_dynamics<double>(g::Config<double>(Eigen::Map<const g::Config<double>>(q.data() + i * g::nq)),
                                      g::Tangent<double>(Eigen::Map<const g::Tangent<double>>(v.data() + i * g::nv)),
                                      g::Tangent<double>(Eigen::Map<const g::Tangent<double>>(tau.data() + i * g::nv)));
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
    times.push_back(static_cast<double>(t1.tv_sec - t0.tv_sec) + 1e-9 * static_cast<double>(t1.tv_nsec - t0.tv_nsec));
  }
  std::sort(times.begin(), times.end());
  double check = 0;
  for(double e : a) check += e;
  // best time of the loop -> states per second, ns per call; the checksum keeps the results live
  std::printf("%.6e %.3f %.17g\n", n / times.front(), 1e9 * times.front() / n, check);
  return 0;
}
