// The cells of bench_batch (see BatchBench.h): for each robot and algorithm,
//   single double | single float | SIMD double | SIMD float           N states in cache, CPU time
//   SIMD double columns | SIMD float columns                          the same, Layout::columns arrays
//   SIMD double, 1 thread | 2 threads | SIMD float, 1 thread | 2 threads   many states, wall-clock time
// Each iteration evaluates N states of a pool of 4 x 8192 seeded random states, starting N/4 states
// further than the previous iteration (the inputs differ from one iteration to the next), into an
// N-state output kept live. In cache: N such that the inputs and outputs of a call fit in 512 KB
// (32 to 8192 states), the speed of the code rather than of the memory; CPU time of the process.
// Threads: N = 8192 (2048 for nv > 20), so that starting a thread costs little, wall-clock time (the
// threads' work included). Counters: states/s, states/s per core (the rate / the threads), states per
// CPU second of the process (all threads: what a second thread adds to the work, whatever the load).
// At start-up, a check line per algorithm: the largest difference of the SIMD double batch from the
// single-state double code, and of the SIMD float batch from it.
#include "BatchBench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <type_traits>

#include <Eigen/Core>
#include <benchmark/benchmark.h>

namespace rbdbench
{
namespace
{

/// States per call of the threads' cells: enough that starting the threads of a call costs little.
std::size_t manyStates(const BatchRobotInfo & r)
{
  return r.nv <= 20 ? 8192 : 2048;
}

/// States per call of the in-cache cells: inputs and outputs (double) in 512 KB, a power of 2 in
/// [32, 8192] (32: 4 packs of 8 doubles; talos_reduced's mass matrix, 11.6 KB a state, fits then: at
/// 256 states its 3 MB went to L3, and the cell measured the memory of a machine shared with others),
/// less 16 states from 128 on: in Layout::columns N is the distance between an item's values, and
/// N = 256 doubles (2 KB) put all 96 values of ur5e's poses in 2 of the 64 sets of the L1 cache and
/// 64 of the L2's: forward kinematics ran 14.1M states/s there against 37.8M/s at N = 248 (N = 240:
/// 30 lines apart in double, 15 in float, every pack a whole line).
std::size_t cachedStates(const BatchRobotInfo & r, int outputSize)
{
  const std::size_t bytes = sizeof(double) * static_cast<std::size_t>(r.nq + 2 * r.nv + outputSize);
  std::size_t n = 32;
  while(2 * n * bytes <= (512u << 10) && 2 * n <= 8192) n *= 2;
  return n >= 128 ? n - 16 : n;
}

/// The pool: 4N seeded random states (unit quaternion for a free base, joints and velocities in
/// [-3, 3], the third input in [-2, 2]) in double and float.
template<class T>
struct Pool
{
  std::vector<T> q, v, u;
  Inputs<T> at(const BatchRobotInfo & r, std::size_t first) const
  {
    return {q.data() + first * static_cast<std::size_t>(r.nq), v.data() + first * static_cast<std::size_t>(r.nv),
            u.data() + first * static_cast<std::size_t>(r.nv)};
  }
};

struct Pools
{
  Pool<double> d;
  Pool<float> f;
};

std::shared_ptr<const Pools> makePools(const BatchRobotInfo & r, std::size_t states)
{
  auto p = std::make_shared<Pools>();
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u3(-3, 3), u2(-2, 2);
  p->d.q.resize(states * static_cast<std::size_t>(r.nq));
  p->d.v.resize(states * static_cast<std::size_t>(r.nv));
  p->d.u.resize(p->d.v.size());
  for(double & x : p->d.q) x = u3(rng);
  for(double & x : p->d.v) x = u3(rng);
  for(double & x : p->d.u) x = u2(rng);
  if(r.floatingBase)
    for(std::size_t s = 0; s < states; ++s) Eigen::Map<Eigen::Vector4d>(p->d.q.data() + s * static_cast<std::size_t>(r.nq)).normalize();
  p->f.q.assign(p->d.q.begin(), p->d.q.end());
  p->f.v.assign(p->d.v.begin(), p->d.v.end());
  p->f.u.assign(p->d.u.begin(), p->d.u.end());
  return p;
}

/// CPU time of the whole process (every thread), seconds.
double processCpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// max over states of max |x - ref| / max(1, max |ref|).
template<class T>
double worstRelative(const std::vector<T> & x, const std::vector<double> & ref, std::size_t N, int n)
{
  double worst = 0;
  for(std::size_t s = 0; s < N; ++s)
  {
    double e = 0, m = 1;
    for(int i = 0; i < n; ++i)
    {
      const std::size_t k = s * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
      e = std::max(e, std::abs(static_cast<double>(x[k]) - ref[k]));
      m = std::max(m, std::abs(ref[k]));
    }
    worst = std::max(worst, e / m);
  }
  return worst;
}

/// States [first, first + N) of a row-major (states x n) array as an (n x N) array (Layout::columns).
template<class T>
std::vector<T> columnsOf(const std::vector<T> & rows, int n, std::size_t first, std::size_t N)
{
  const auto nn = static_cast<std::size_t>(n);
  std::vector<T> c(nn * N);
  for(std::size_t s = 0; s < N; ++s)
    for(std::size_t k = 0; k < nn; ++k) c[k * N + s] = rows[(first + s) * nn + k];
  return c;
}

/// The inputs of 4 disjoint windows of N states of the pool in Layout::columns.
template<class T>
struct ColumnWindows
{
  std::vector<T> q[4], v[4], u[4];
  ColumnWindows(const BatchRobotInfo & r, const Pool<T> & pool, std::size_t N)
  {
    for(std::size_t w = 0; w < 4; ++w)
    {
      q[w] = columnsOf(pool.q, r.nq, w * N, N);
      v[w] = columnsOf(pool.v, r.nv, w * N, N);
      u[w] = columnsOf(pool.u, r.nv, w * N, N);
    }
  }
  Inputs<T> at(std::size_t w) const { return {q[w].data(), v[w].data(), u[w].data()}; }
};

template<class T>
const Pool<T> & poolOf(const Pools & pools)
{
  if constexpr(std::is_same_v<T, double>) return pools.d;
  else return pools.f;
}

/// One in-cache cell of the batch in Layout::columns (structure of arrays): each iteration the next
/// of 4 disjoint windows of N states, CPU time.
template<class T>
void registerColumnsCell(const BatchRobotInfo & r, const BatchAlgorithm<T> & a, const std::shared_ptr<const Pools> & pools,
                         const std::string & impl, std::size_t N)
{
  const std::string name = std::string(r.name) + "/" + a.name + "/" + impl;
  benchmark::internal::Benchmark * b = benchmark::RegisterBenchmark(name.c_str(), [r, a, pools, N](benchmark::State & st) {
    const ColumnWindows<T> windows(r, poolOf<T>(*pools), N);
    std::vector<T> out(N * static_cast<std::size_t>(a.outputSize));
    std::size_t w = 0;
    const double cpu0 = processCpuSeconds();
    for(auto _ : st)
    {
      a.columns(windows.at(w), out.data(), N);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
      w = (w + 1) % 4;
    }
    const double states = static_cast<double>(N) * static_cast<double>(st.iterations());
    st.counters["states/s"] = benchmark::Counter(states, benchmark::Counter::kIsRate);
    st.counters["states/s/core"] = benchmark::Counter(states, benchmark::Counter::kIsRate);
    st.counters["N"] = static_cast<double>(N);
    st.counters["states/cpu-s"] = states / (processCpuSeconds() - cpu0);
  });
  b->Unit(benchmark::kMicrosecond);
}

/// One cell of N states per call: `threads` = 0 for the single-state loop; wall-clock time when
/// `wall` (else CPU time).
template<class T>
void registerCell(const BatchRobotInfo & r, const BatchAlgorithm<T> & a, const std::shared_ptr<const Pools> & pools,
                  const std::string & impl, int threads, std::size_t N, bool wall)
{
  const std::string name = std::string(r.name) + "/" + a.name + "/" + impl;
  benchmark::internal::Benchmark * b = benchmark::RegisterBenchmark(name.c_str(), [r, a, pools, N, threads](benchmark::State & st) {
    const Pool<T> & pool = poolOf<T>(*pools);
    std::vector<T> out(N * static_cast<std::size_t>(a.outputSize));
    std::size_t first = 0;
    const double cpu0 = processCpuSeconds();
    for(auto _ : st)
    {
      const Inputs<T> in = pool.at(r, first);
      if(threads == 0) a.single(in, out.data(), N);
      else a.batch(in, out.data(), N, threads);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
      first = (first + N / 4) % (3 * N);
    }
    const double states = static_cast<double>(N) * static_cast<double>(st.iterations());
    st.counters["states/s"] = benchmark::Counter(states, benchmark::Counter::kIsRate);
    st.counters["states/s/core"] = benchmark::Counter(states / std::max(threads, 1), benchmark::Counter::kIsRate);
    st.counters["N"] = static_cast<double>(N);
    // the CPU time of every thread of the process: with 2 threads, the work the threads add
    st.counters["states/cpu-s"] = states / (processCpuSeconds() - cpu0);
  });
  b->Unit(benchmark::kMicrosecond);
  if(wall) b->UseRealTime();
}

/// An N-state output of algorithm a (rows layout, or columns when `columns`) as one (N x outputSize)
/// row-major array: each state's values together, its arrays (a.parts) one after the other.
template<class T>
std::vector<T> stateRows(const std::vector<T> & out, const BatchAlgorithm<double> & a, std::size_t N, bool columns)
{
  const std::vector<int> parts = a.parts.empty() ? std::vector<int>{a.outputSize} : a.parts;
  const auto m = static_cast<std::size_t>(a.outputSize);
  if(std::accumulate(parts.begin(), parts.end(), 0) != a.outputSize)
  {
    std::fprintf(stderr, "bench_batch: %s: the parts' sizes do not sum to outputSize %d\n", a.name, a.outputSize);
    std::abort();
  }
  std::vector<T> rows(N * m);
  std::size_t offset = 0; // values of a state before this part
  for(const int part : parts)
  {
    const auto n = static_cast<std::size_t>(part);
    const T * base = out.data() + N * offset;
    for(std::size_t s = 0; s < N; ++s)
      for(std::size_t k = 0; k < n; ++k) rows[s * m + offset + k] = columns ? base[k * N + s] : base[s * n + k];
    offset += n;
  }
  return rows;
}

/// The check line of one algorithm (printed before the cells run).
void check(const BatchRobotInfo & r, const BatchAlgorithm<double> & d, const BatchAlgorithm<float> & f, const Pools & pools)
{
  const std::size_t N = 256;
  const std::size_t n = N * static_cast<std::size_t>(d.outputSize);
  std::vector<double> single(n), batch(n);
  std::vector<float> batchF(n);
  d.single(pools.d.at(r, 0), single.data(), N);
  d.batch(pools.d.at(r, 0), batch.data(), N, 1);
  f.batch(pools.f.at(r, 0), batchF.data(), N, 1);
  const ColumnWindows<double> windows(r, pools.d, N);
  std::vector<double> columns(n);
  d.columns(windows.at(0), columns.data(), N);
  const std::vector<double> singleRows = stateRows(single, d, N, false), batchRows = stateRows(batch, d, N, false);
  std::printf("check %s/%s: SIMD double vs single double %.3g, SIMD float vs single double %.3g, SIMD double columns "
              "vs rows %.3g (relative, %zu states)\n",
              r.name, d.name, worstRelative(batchRows, singleRows, N, d.outputSize),
              worstRelative(stateRows(batchF, d, N, false), singleRows, N, d.outputSize),
              worstRelative(stateRows(columns, d, N, true), batchRows, N, d.outputSize), N);
}

} // namespace

int registerBatchRobot(const BatchRobotInfo & robot, std::vector<BatchAlgorithm<double>> d, std::vector<BatchAlgorithm<float>> f)
{
  const std::size_t many = manyStates(robot);
  const auto pools = makePools(robot, 4 * 8192);
  std::printf("robot %s: nq %d, nv %d, packs of %zu doubles / %zu floats; threads' cells: %zu states per call\n", robot.name,
              robot.nq, robot.nv, robot.widthDouble, robot.widthFloat, many);
  for(std::size_t k = 0; k < d.size(); ++k)
  {
    check(robot, d[k], f[k], *pools);
    const std::size_t cached = cachedStates(robot, d[k].outputSize);
    registerCell(robot, d[k], pools, "single double", 0, cached, false);
    registerCell(robot, f[k], pools, "single float", 0, cached, false);
    registerCell(robot, d[k], pools, "SIMD double", 1, cached, false);
    registerCell(robot, f[k], pools, "SIMD float", 1, cached, false);
    registerColumnsCell(robot, d[k], pools, "SIMD double columns", cached);
    registerColumnsCell(robot, f[k], pools, "SIMD float columns", cached);
    registerCell(robot, d[k], pools, "SIMD double 1 thread", 1, many, true);
    registerCell(robot, d[k], pools, "SIMD double 2 threads", 2, many, true);
    registerCell(robot, f[k], pools, "SIMD float 1 thread", 1, many, true);
    registerCell(robot, f[k], pools, "SIMD float 2 threads", 2, many, true);
  }
  return 0;
}

} // namespace rbdbench
