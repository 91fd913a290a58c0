// rbdgen_batch::Interleaved (batch_support, in every batch.hpp; compiled with AVX-512F only): W
// items of K < W values, contiguous, as K vectors of W lanes and back, against its definition
// (vector k, lane l = value k of item l) for every K from 2 to W - 1, in doubles (W = 8) and floats
// (W = 16). The robots' checks (test_batch_avx512) reach it through ur5e's rows of 6 values only.
#include <ur5e/batch.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <utility>

namespace
{

#if defined(RBDGEN_BATCH_INTERLEAVED)
template<class T, std::size_t W, std::size_t K>
void checkSplitAndJoin()
{
  using I = rbdgen_batch::Interleaved<T, W, K>;
  T block[K * W];
  for(std::size_t i = 0; i < K * W; ++i) block[i] = T(0.5) * static_cast<T>(i + 1); // all distinct
  typename I::V r[K], x[K], back[K];
  std::memcpy(r, block, sizeof(r));
  I::split(r, x, std::make_index_sequence<K>());
  for(std::size_t k = 0; k < K; ++k)
    for(std::size_t l = 0; l < W; ++l)
      EXPECT_EQ(x[k][l], block[l * K + k]) << "W = " << W << ", K = " << K << ": value " << k << " of item " << l;
  I::join(x, back, std::make_index_sequence<K>());
  EXPECT_EQ(std::memcmp(back, block, sizeof(block)), 0) << "W = " << W << ", K = " << K << ": join(split(block)) != block";
}

template<class T, std::size_t W, std::size_t... K>
void checkRowLengths(std::index_sequence<K...>)
{
  (checkSplitAndJoin<T, W, K + 2>(), ...); // K + 2 = 2 ... W - 1
}

TEST(BatchInterleaved, SplitsAndJoinsEveryRowLengthShorterThanAPack)
{
  if(!__builtin_cpu_supports("avx512f")) GTEST_SKIP() << "this CPU has no AVX-512F";
  checkRowLengths<double, 8>(std::make_index_sequence<6>());
  checkRowLengths<float, 16>(std::make_index_sequence<14>());
}
#else
TEST(BatchInterleaved, SplitsAndJoinsEveryRowLengthShorterThanAPack)
{
  GTEST_SKIP() << "compiled without AVX-512F or __builtin_shufflevector: no Interleaved";
}
#endif

} // namespace
