#pragma once
// Batches over threads: the N states are cut into `threads` contiguous chunks, each run by one
// std::thread with its own workspace, in state order. A state's result depends only on its inputs
// (a model evaluating several states at once, on SIMD packs, computes each lane independently), so
// the output is bitwise the same for every thread count. The first failure (lowest state index)
// is rethrown after every thread has joined, with the state index in the message (an InputError
// as it is: its message names the input and the state).
#include <algorithm>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace rbdgen_py
{

/// Thrown when the computation of one state fails (e.g. a singular mass matrix).
class StateError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Thrown for a bad input of one state, with a complete message: rethrown as is (the lowest state's).
class InputError : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// At most this many threads per call (more would only add start-up cost; results do not depend on it).
inline constexpr int kMaxThreads = 256;

/// For each chunk [begin, end): ws = makeWorkspace(); range(ws, begin, end, at), which evaluates the
/// chunk's states in order and keeps `at` at the state it is evaluating (the failing state when it
/// throws). Returns after every thread joined.
template<class MakeWorkspace, class Range>
void parallelFor(std::ptrdiff_t n, int threads, MakeWorkspace && makeWorkspace, Range && range)
{
  const std::ptrdiff_t nthreads = std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>({threads, n, kMaxThreads}));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(nthreads));
  std::vector<std::ptrdiff_t> failedAt(static_cast<std::size_t>(nthreads), -1);
  auto run = [&](std::ptrdiff_t t) {
    const std::ptrdiff_t begin = n * t / nthreads, end = n * (t + 1) / nthreads;
    std::ptrdiff_t at = begin;
    try
    {
      auto ws = makeWorkspace();
      range(ws, begin, end, at);
    }
    catch(...)
    {
      errors[static_cast<std::size_t>(t)] = std::current_exception();
      failedAt[static_cast<std::size_t>(t)] = at;
    }
  };
  if(nthreads == 1) run(0);
  else
  {
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(nthreads - 1));
    std::ptrdiff_t started = 1;
    try
    {
      for(; started < nthreads; ++started) pool.emplace_back(run, started);
    }
    catch(const std::system_error &) // no more threads: this one runs the chunks not started
    {
    }
    run(0);
    for(std::ptrdiff_t t = started; t < nthreads; ++t) run(t);
    for(auto & th : pool) th.join();
  }
  for(std::size_t t = 0; t < errors.size(); ++t)
    if(errors[t])
    {
      try
      {
        std::rethrow_exception(errors[t]);
      }
      catch(const InputError &)
      {
        throw;
      }
      catch(const std::exception & e)
      {
        throw StateError("state " + std::to_string(failedAt[t]) + ": " + e.what());
      }
    }
}

} // namespace rbdgen_py
