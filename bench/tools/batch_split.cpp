// Where the batch functions' time goes: computing against writing the outputs (issue 16's forward
// kinematics and mass matrix cells). For one generated robot (its batch.hpp in namespace NS, given
// by -include), in ns a state, medians of 9 runs of 2,000 calls of N states drawn from a pool of
// 32,768 (each call N / 4 states further on):
//   single compute  the single-state function in a loop, its result kept live but not stored
//   single + store  the loop bench_batch times: the result written into the N-state output (the
//                   ratios of the SIMD rows and columns are against this one, as in bench_batch)
//   SIMD compute    the same function on packs of the native width (states loaded lane by lane
//                   outside the timing's concern: a copy of nq values a state), result kept live
//   SIMD rows/cols  the batch API, as bench_batch times it (Layout::rows, Layout::columns)
//   write only      the output's bytes written with vector stores and nothing else (the floor)
// N as bench_batch's in-cache cells: inputs and outputs (in double) in 512 KB, a power of 2 in
// [32, 8192], less 16 from 128 on (BatchBench.cpp, cachedStates). Built and run by
// bench/tools/batch_split.sh; -DSCALAR=double or float.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <type_traits>
#include <vector>

#include <xsimd/xsimd.hpp>

using T = SCALAR;
using P = xsimd::batch<T>;
constexpr std::size_t W = P::size, pool = 32768;
constexpr std::size_t nq = NS::nq, nv = NS::nv, nb = NS::nbodies;
std::size_t N = 32; // states a call, set per algorithm by inCache

/// bench_batch's N for an output of `values` a state
std::size_t inCache(std::size_t values)
{
  const std::size_t bytes = sizeof(double) * (nq + 2 * nv + values);
  std::size_t n = 32;
  while(2 * n * bytes <= (512u << 10) && 2 * n <= 8192) n *= 2;
  return n >= 128 ? n - 16 : n;
}

// median ns a state of 9 runs of 2,000 calls of f(call index)
template<class F>
double timed(F && f)
{
  std::vector<double> t;
  for(int run = 0; run < 9; ++run)
  {
    const auto t0 = std::chrono::steady_clock::now();
    for(int it = 0; it < 2000; ++it) f(it);
    t.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / (2000.0 * N));
  }
  std::sort(t.begin(), t.end());
  return t[4];
}

template<class X>
void keep(const X * p)
{
  asm volatile("" : : "r"(p) : "memory");
}

struct Row
{
  const char * name;
  std::size_t states;
  double singleCompute, singleStore, simdCompute, simdRows, simdColumns, writeOnly;
};

int main()
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<T> u(-3, 3);
  std::vector<T> q(pool * nq);
  for(T & x : q) x = u(gen);
  if(nq != nv) // a free base: unit quaternions
    for(std::size_t s = 0; s < pool; ++s)
    {
      T n = 0;
      for(std::size_t k = 0; k < 4; ++k) n += q[s * nq + k] * q[s * nq + k];
      for(std::size_t k = 0; k < 4; ++k) q[s * nq + k] /= std::sqrt(n);
    }
  const auto first = [](int it) { return static_cast<std::size_t>(it) * (N / 4) % (pool - N); };
  const auto config = [&](std::size_t s) { return Eigen::Map<const NS::Config<T>>(q.data() + s * nq); };
  const auto packConfig = [&](std::size_t s) {
    NS::Config<P> qp;
    for(std::size_t k = 0; k < nq; ++k)
    {
      alignas(64) T lane[W];
      for(std::size_t l = 0; l < W; ++l) lane[l] = q[(s + l) * nq + k];
      qp[static_cast<Eigen::Index>(k)] = P::load_aligned(lane);
    }
    return qp;
  };
  std::vector<T> out(8192 * std::max(16 * nb, nv * nv) + 64);
  const auto writeOnly = [&](std::size_t values) {
    return timed([&](int it) {
      const P v(static_cast<T>(it));
      for(std::size_t k = 0; k + W <= N * values; k += W) v.store_unaligned(out.data() + k);
      keep(out.data());
    });
  };
  // one row: compute(config) on one state and on a pack (its result kept live), storeOne(s, config)
  // the single-state loop's body, batch(q, out, layout) the batch API
  const auto measure = [&](const char * name, std::size_t values, auto && compute, auto && storeOne, auto && batch) {
    N = inCache(values);
    const auto batchTimed = [&](NS::batch::Layout layout) {
      return timed([&](int it) {
        batch(q.data() + first(it) * nq, out.data(), layout);
        keep(out.data());
      });
    };
    return Row{name, N,
               timed([&](int it) {
                 for(std::size_t s = 0; s < N; ++s) keep(compute(config(first(it) + s)).data());
               }),
               timed([&](int it) {
                 for(std::size_t s = 0; s < N; ++s) storeOne(s, config(first(it) + s));
                 keep(out.data());
               }),
               timed([&](int it) {
                 for(std::size_t s = 0; s < N; s += W) keep(compute(packConfig(first(it) + s)).data());
               }),
               batchTimed(NS::batch::Layout::rows), batchTimed(NS::batch::Layout::columns), writeOnly(values)};
  };
  // the scalar (T or P) of a configuration
  const auto scalarOf = [](const auto & qs) { return typename std::decay_t<decltype(qs)>::Scalar{}; };
  std::vector<Row> rows;
  // forward kinematics: 16 values a link (the batch API's 4 x 4 homogeneous transforms)
  rows.push_back(measure(
      "forward kinematics", 16 * nb,
      [&](const auto & qs) { return NS::forward_kinematics<decltype(scalarOf(qs))>(qs); },
      [&](std::size_t s, const auto & qs) {
        const auto pose = NS::forward_kinematics<T>(qs);
        for(std::size_t b = 0; b < nb; ++b)
        {
          Eigen::Map<Eigen::Matrix<T, 4, 4, Eigen::RowMajor>> X(out.data() + (s * nb + b) * 16);
          X.template topLeftCorner<3, 3>() = pose[b].rotation.transpose();
          X.template topRightCorner<3, 1>() = pose[b].translation;
          X.template bottomRows<1>() << T(0), T(0), T(0), T(1);
        }
      },
      [&](const T * qb, T * o, NS::batch::Layout layout) { NS::batch::forward_kinematics<T>(qb, o, N, 1, layout); }));
  // mass matrix: nv x nv values written; computed only: mass_matrix_packed (its entries that are
  // not structurally zero, what the batch API computes before it writes H), on one state and on packs
  rows.push_back(measure(
      "mass matrix", nv * nv, [&](const auto & qs) { return NS::mass_matrix_packed<decltype(scalarOf(qs))>(qs); },
      [&](std::size_t s, const auto & qs) {
        Eigen::Map<Eigen::Matrix<T, nv, nv>>(out.data() + s * nv * nv) = NS::mass_matrix<T>(qs);
      },
      [&](const T * qb, T * o, NS::batch::Layout layout) { NS::batch::mass_matrix<T>(qb, o, N, 1, layout); }));
  std::printf("| algorithm | N | single compute | single + store | SIMD compute | SIMD rows | SIMD columns | write only |\n");
  std::printf("|---|--:|--:|--:|--:|--:|--:|--:|\n");
  for(const Row & r : rows)
    std::printf("| %s | %zu | %.1f | %.1f | %.1f (%.1f×) | %.1f (%.1f×) | %.1f (%.1f×) | %.1f |\n", r.name, r.states, r.singleCompute, r.singleStore,
                r.simdCompute, r.singleCompute / r.simdCompute, r.simdRows, r.singleStore / r.simdRows, r.simdColumns,
                r.singleStore / r.simdColumns, r.writeOnly);
}
