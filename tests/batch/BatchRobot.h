#pragma once
// A generated robot's batch API (NS/batch.hpp) next to loops of its single-state functions, all of
// one signature, so that one test program (test_batch.cpp, compiled once) checks every robot; each
// robot's headers are compiled in their own adapter translation unit (batch_adapter.cpp.in).

#include <cstddef>
#include <vector>

namespace rbdgentest
{

/// A function over N states: in[k] and out[m] are row-major arrays of N items (one per state).
template<class T>
using StatesFn = void (*)(const T * const * in, T * const * out, std::size_t N, int threads);

/// NS::batch::Layout: rows, an (N, item) array per argument; columns, an (item, N) array.
enum class Layout
{
  rows,
  columns
};

/// A batch function over N states, its arrays in `layout`.
template<class T>
using BatchFn = void (*)(const T * const * in, T * const * out, std::size_t N, int threads, Layout layout);

/// What an input is: a configuration (nq values), a tangent vector (nv values) or a scene's external
/// wrenches (nwrenches x 6 values).
enum class Input
{
  q,
  v,
  wrenches
};

/// How an output's error grows, for its bound (test_batch.cpp): kinematics and dynamics are
/// well-conditioned; forward dynamics grows with cond(H); d alphaD/dq with cond(H)^2.
enum class Growth
{
  none,
  cond,
  cond2
};

struct Output
{
  int size;      ///< values per state
  Growth growth;
  bool kinematic = false; ///< float bound of kinematics (else of dynamics), as test_generated
  /// -Minv dID (forward dynamics derivatives): an nv x nv product, which Eigen sums in another order
  /// for a scalar (vectorised) than for a pack (coefficient by coefficient)
  bool product = false;
};

template<class T>
struct BatchFunction
{
  const char * name;
  std::vector<Input> inputs;
  std::vector<Output> outputs;
  BatchFn<T> batch;   ///< NS::batch::...
  StatesFn<T> single; ///< the single-state function, state after state (threads ignored)
};

struct BatchRobot
{
  const char * name;
  int nq, nv, nbodies;
  bool floatingBase;        ///< q starts with the base quaternion
  std::size_t widthDouble, widthFloat; ///< states per pack
  bool fused;               ///< compiled for a target with FMA: the compiler may fuse a*b + c differently in scalar and pack code
  std::vector<BatchFunction<double>> d;
  std::vector<BatchFunction<float>> f;
  StatesFn<double> massMatrix; ///< single-state mass matrix (conditioning of the bounds)
  int nwrenches = 0;           ///< a scene's external wrenches (Input::wrenches)
};

} // namespace rbdgentest
