#pragma once
// bench_batch: states per second of the generated code, a loop of single-state calls vs the batch
// API (NS/batch.hpp: SIMD packs, then SIMD + 2 threads), double and float. Each robot's translation
// unit (batch_robot.cpp.in) registers its algorithms; BatchBench.cpp makes the cells.
#include <cstddef>
#include <vector>

namespace rbdbench
{

/// The inputs of N consecutive states, row-major: q (N x nq), v and u (N x nv; u = alphaD or tau);
/// for a `columns` function, nq x N and nv x N.
template<class T>
struct Inputs
{
  const T * q;
  const T * v;
  const T * u;
};

template<class T>
struct BatchAlgorithm
{
  const char * name;
  int outputSize; ///< values per state
  void (*single)(const Inputs<T> & in, T * out, std::size_t N);           ///< single-state calls
  void (*batch)(const Inputs<T> & in, T * out, std::size_t N, int threads); ///< NS::batch::...
  /// NS::batch::... with Layout::columns: in and out are (values x N) arrays (structure of arrays)
  void (*columns)(const Inputs<T> & in, T * out, std::size_t N);
  /// The values of a state in several arrays (the derivatives: e.g. alphaD, then three nv x nv
  /// matrices), their sizes in order, summing to outputSize; out holds them one after the other,
  /// each N states long (rows: (N x size) each; columns: (size x N) each, so the whole is
  /// (outputSize x N)). Empty: one array.
  std::vector<int> parts = {};
};

struct BatchRobotInfo
{
  const char * name;
  int nq, nv;
  bool floatingBase;
  std::size_t widthDouble, widthFloat;
};

/// Registers the cells of one robot; returns 0 (for a namespace-scope initialiser).
int registerBatchRobot(const BatchRobotInfo & robot, std::vector<BatchAlgorithm<double>> d,
                       std::vector<BatchAlgorithm<float>> f);

} // namespace rbdbench
