// detail::sincos_all of a generated header (templates/detail_sincos.hpp.in), the sin and cos of
// every joint angle in one call, against std::sin/std::cos in long double: random angles, the
// quadrant boundaries k pi/4 where the reduction switches polynomial and sign, the ends of the
// exact reduction (where the kernel hands over to std::sin/cos), signed zeros, inf and NaN, and
// the batch sizes that exercise the vectorised loop's remainders (1, 6, 7, 13, 40). Built twice: with
// the build's flags (detail::sincos_loop), and as test_sincos_avx2 with -mavx2 -mfma (with clang++,
// detail::sincos_vectors: the same operations on vector types; with g++, the loop fused).
#include <ur5e/dynamics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
namespace detail = ur5e::detail;

template<class S>
struct Limits;
// double: the reduction is exact below 2^19 pi/2 (823549.6); fdlibm's kernels give <= 2.1e-16.
template<>
struct Limits<double>
{
  static constexpr double exactBelow = 823549.6;
  static constexpr double tolerance = 2.5e-16; // measured 1.8e-16; std::sin: 1.1e-16, half an ulp of 1
};
// float: the reduction is exact below 8192; Cephes's kernels in float give <= 9.3e-8.
template<>
struct Limits<float>
{
  static constexpr double exactBelow = 8192.0;
  static constexpr double tolerance = 1.1920929e-7; // 2^-23, one ulp of 1 (measured 9.2e-8)
};

/// Largest |sin - sinl|, |cos - cosl| over the angles, evaluated in batches of N.
template<class S, int N>
long double largestError(const std::vector<S> & angles)
{
  long double worst = 0;
  for(std::size_t start = 0; start + N <= angles.size(); start += N)
  {
    S x[N];
    for(int i = 0; i < N; ++i) x[i] = angles[start + static_cast<std::size_t>(i)];
    const detail::SinCos<S, N> sc = detail::sincos_all(x);
    for(int i = 0; i < N; ++i)
    {
      const long double xl = x[i];
      worst = std::max(worst, std::abs(static_cast<long double>(sc.s[i]) - std::sin(xl)));
      worst = std::max(worst, std::abs(static_cast<long double>(sc.c[i]) - std::cos(xl)));
    }
  }
  return worst;
}

template<class S>
std::vector<S> testAngles()
{
  std::mt19937 rng(20261122);
  std::vector<S> angles;
  for(double range : {1.0, 4.0, 50.0, 1000.0, Limits<S>::exactBelow})
  {
    std::uniform_real_distribution<double> u(-range, range);
    for(int i = 0; i < 40000; ++i) angles.push_back(static_cast<S>(u(rng)));
  }
  // Either side of k pi/4 (octant and quadrant boundaries), where the polynomial and sign switch.
  const long double quarterPi = std::acos(-1.0L) / 4;
  for(int k = -400; k <= 400; ++k)
  {
    const S boundary = static_cast<S>(k * quarterPi);
    S below = boundary, above = boundary;
    for(int step = 0; step < 4; ++step)
    {
      angles.push_back(below = std::nextafter(below, -std::numeric_limits<S>::infinity()));
      angles.push_back(above = std::nextafter(above, std::numeric_limits<S>::infinity()));
    }
    angles.push_back(boundary);
  }
  // Either side of the end of the exact reduction (the fallback to std::sin/cos).
  S edge = static_cast<S>(Limits<S>::exactBelow);
  for(int step = 0; step < 8; ++step)
  {
    angles.push_back(edge);
    angles.push_back(-edge);
    edge = std::nextafter(edge, S(0));
  }
  for(S large : {S(1e5), S(1e6), S(3e7), S(1e15)}) angles.push_back(large), angles.push_back(-large);
  angles.push_back(S(0));
  angles.push_back(-S(0));
  angles.push_back(std::numeric_limits<S>::denorm_min());
  std::shuffle(angles.begin(), angles.end(), rng); // mix large and small angles in one batch
  return angles;
}

template<class S>
class SinCosAll : public ::testing::Test
{
protected:
  void SetUp() override
  {
#if defined(__AVX2__)
    // test_sincos_avx2 (built with -mavx2 -mfma: clang++ runs detail::sincos_vectors)
    if(!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "this CPU has no AVX2 + FMA";
#endif
  }
};
using Scalars = ::testing::Types<double, float>;
TYPED_TEST_SUITE(SinCosAll, Scalars, );

TYPED_TEST(SinCosAll, MatchesLongDoubleForEveryBatchSize)
{
  using S = TypeParam;
  const std::vector<S> angles = testAngles<S>();
  const long double tolerance = Limits<S>::tolerance;
  EXPECT_LE((largestError<S, 1>(angles)), tolerance);
  EXPECT_LE((largestError<S, 6>(angles)), tolerance);
  EXPECT_LE((largestError<S, 7>(angles)), tolerance);
  EXPECT_LE((largestError<S, 13>(angles)), tolerance);
  EXPECT_LE((largestError<S, 40>(angles)), tolerance);
}

TYPED_TEST(SinCosAll, NonFiniteAnglesGiveNaNWithoutSpoilingTheOthers)
{
  using S = TypeParam;
  const S inf = std::numeric_limits<S>::infinity();
  const S x[5] = {S(0.5), inf, std::numeric_limits<S>::quiet_NaN(), -inf, S(-2)};
  const detail::SinCos<S, 5> sc = detail::sincos_all(x);
  for(int i : {1, 2, 3})
  {
    EXPECT_TRUE(std::isnan(sc.s[i])) << i;
    EXPECT_TRUE(std::isnan(sc.c[i])) << i;
  }
  for(int i : {0, 4})
  {
    EXPECT_NEAR(sc.s[i], std::sin(static_cast<long double>(x[i])), Limits<S>::tolerance) << i;
    EXPECT_NEAR(sc.c[i], std::cos(static_cast<long double>(x[i])), Limits<S>::tolerance) << i;
  }
}

TYPED_TEST(SinCosAll, ZeroIsExact)
{
  using S = TypeParam;
  const S x[2] = {S(0), -S(0)};
  const detail::SinCos<S, 2> sc = detail::sincos_all(x);
  for(int i = 0; i < 2; ++i)
  {
    EXPECT_EQ(sc.s[i], S(0));
    EXPECT_EQ(sc.c[i], S(1));
  }
}

} // namespace
