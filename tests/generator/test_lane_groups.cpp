// The derivatives' lane kernels of a generated header (templates/detail_opaque.hpp.in):
// detail::for_lane_groups hands every index of [0, N) to exactly one group, widest groups first,
// and the kernels world_body_terms_at / column_terms_at give each lane the same value at every
// width W (a vector of W lanes) as one lane at a time, so that the dispatchers world_body_terms and
// column_terms may take a rest narrower than the packet (8 bodies with AVX-512's 16 floats) in
// halved widths. Independent reference: the width-1 kernel, plain scalar code per body.
#include <ur5e/dynamics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace
{
namespace detail = ur5e::detail;

/// Built twice: with the build's flags (SSE2: packets of 4 floats, 2 doubles) and, where the compiler
/// takes it, as test_lane_groups_avx512 with -mavx512f -mfma (16 floats: the dispatchers' 40 lanes go
/// as 16 + 16 + 8, the rest path), every case skipped on a CPU without AVX-512F.
class LaneGroups : public ::testing::Test
{
protected:
  void SetUp() override
  {
#if defined(__AVX512F__)
    if(!__builtin_cpu_supports("avx512f")) GTEST_SKIP() << "this CPU has no AVX-512F";
#endif
  }
};

struct Group
{
  int width, first;
};

template<int L, int N>
std::vector<Group> groupsOf()
{
  std::vector<Group> g;
  detail::for_lane_groups<L, 0, N>([&](auto lanes, int k) { g.push_back({decltype(lanes)::value, k}); });
  return g;
}

/// Every index once, in order, widths powers of two <= L and non-increasing, floor(N / L) groups of L first.
template<int L, int N>
void checkGroups()
{
  const std::vector<Group> g = groupsOf<L, N>();
  int next = 0, previous = L;
  for(std::size_t i = 0; i < g.size(); ++i)
  {
    const Group & x = g[i];
    EXPECT_EQ(x.first, next) << "L " << L << " N " << N << " group " << i;
    EXPECT_GT(x.width, 0);
    EXPECT_EQ(x.width & (x.width - 1), 0) << "width " << x.width << " not a power of two";
    EXPECT_LE(x.width, previous) << "L " << L << " N " << N << ": widths grow";
    if(i < static_cast<std::size_t>(N / L)) EXPECT_EQ(x.width, L) << "L " << L << " N " << N << " group " << i;
    next += x.width;
    previous = x.width;
  }
  EXPECT_EQ(next, N) << "L " << L << " N " << N;
  // at most one group per halved width after the full ones
  EXPECT_LE(g.size(), static_cast<std::size_t>(N / L) + static_cast<std::size_t>(std::log2(L)));
}

template<int L, int... N>
void checkGroupsFor(std::integer_sequence<int, N...>)
{
  (checkGroups<L, N>(), ...);
}

TEST_F(LaneGroups, CoverEveryIndexOnce)
{
  const auto sizes = std::make_integer_sequence<int, 42>{};
  checkGroupsFor<1>(sizes);
  checkGroupsFor<2>(sizes);
  checkGroupsFor<4>(sizes);
  checkGroupsFor<8>(sizes);
  checkGroupsFor<16>(sizes);
  // the cases that motivated it: AVX-512 floats (16) over 8 and 40 lanes
  const std::vector<Group> g8 = groupsOf<16, 8>(), g40 = groupsOf<16, 40>();
  ASSERT_EQ(g8.size(), 1u);
  EXPECT_EQ(g8[0].width, 8);
  ASSERT_EQ(g40.size(), 3u);
  EXPECT_EQ(g40[2].width, 8);
  EXPECT_EQ(g40[2].first, 32);
}

/// max |x - ref| / max(1, max |ref|) over the entries
template<class S, std::size_t R, std::size_t C>
double worst(const S (&x)[R][C], const S (&ref)[R][C])
{
  double e = 0, m = 1;
  for(std::size_t r = 0; r < R; ++r)
    for(std::size_t c = 0; c < C; ++c)
    {
      e = std::max(e, std::abs(static_cast<double>(x[r][c]) - static_cast<double>(ref[r][c])));
      m = std::max(m, std::abs(static_cast<double>(ref[r][c])));
    }
  return e / m;
}

constexpr int kLanes = 40;

template<class S>
struct Inputs
{
  S bodies[24][kLanes];
  double constants[10][kLanes];
  S joints[49][kLanes];
};

template<class S>
Inputs<S> randomInputs(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-2, 2), positive(0.1, 3);
  Inputs<S> in;
  for(auto & row : in.bodies)
    for(S & x : row) x = S(u(rng));
  for(int r = 0; r < 10; ++r)
    for(double & x : in.constants[r]) x = r == 0 ? positive(rng) : u(rng);
  for(auto & row : in.joints)
    for(S & x : row) x = S(u(rng));
  return in;
}

/// Each kernel at width W over [0, kLanes) against width 1; then the dispatchers against width 1.
/// Widths up to the packet's only (the headers use no wider one; a wider vector type passed by value
/// changes the ABI: -Wpsabi).
template<class S, int W>
void checkWidth(const Inputs<S> & in, double tolerance)
{
  if constexpr(W > detail::across_lanes<S>()) return;
  else
  {
  S bodiesW[30][kLanes] = {}, bodies1[30][kLanes] = {}, jointsW[42][kLanes] = {}, joints1[42][kLanes] = {};
  for(int k = 0; k < kLanes; ++k)
  {
    detail::world_body_terms_at<S, 1>(in.bodies, in.constants, bodies1, k);
    detail::column_terms_at<S, 1>(in.joints, joints1, k, nullptr, 0);
  }
  int k = 0;
  for(; k + W <= kLanes; k += W)
  {
    detail::world_body_terms_at<S, W>(in.bodies, in.constants, bodiesW, k);
    detail::column_terms_at<S, W>(in.joints, jointsW, k, nullptr, 0);
  }
  for(; k < kLanes; ++k) // (W = 16: lanes 32 to 39)
  {
    detail::world_body_terms_at<S, 1>(in.bodies, in.constants, bodiesW, k);
    detail::column_terms_at<S, 1>(in.joints, jointsW, k, nullptr, 0);
  }
  EXPECT_LE(worst(bodiesW, bodies1), tolerance) << "world_body_terms_at, width " << W;
  EXPECT_LE(worst(jointsW, joints1), tolerance) << "column_terms_at, width " << W;
  S bodiesD[30][kLanes] = {}, jointsD[42][kLanes] = {};
  detail::world_body_terms(in.bodies, in.constants, bodiesD);
  detail::column_terms(in.joints, jointsD);
  EXPECT_LE(worst(bodiesD, bodies1), tolerance) << "world_body_terms (width " << detail::across_lanes<S>() << " then halved)";
  EXPECT_LE(worst(jointsD, joints1), tolerance) << "column_terms (width " << detail::across_lanes<S>() << " then halved)";
  }
}

/// checkWidth at every width up to 16 (those wider than the packet skip themselves).
template<class S>
void checkEveryWidth(unsigned seed)
{
  const Inputs<S> in = randomInputs<S>(seed);
  const double tolerance = 64 * std::numeric_limits<S>::epsilon();
  checkWidth<S, 2>(in, tolerance);
  checkWidth<S, 4>(in, tolerance);
  checkWidth<S, 8>(in, tolerance);
  checkWidth<S, 16>(in, tolerance);
}

// The same operations on each lane; only an FMA contraction the compiler applies to one width and
// not the other can round differently: a few ulps of the largest value (measured 0: bitwise, g++ 12
// and clang++ 14 at -O0, -O2, -O3 -march=native).
TEST_F(LaneGroups, KernelsAgreeAtEveryWidthFloat)
{
  checkEveryWidth<float>(7);
}

TEST_F(LaneGroups, KernelsAgreeAtEveryWidthDouble)
{
  checkEveryWidth<double>(11);
}

TEST_F(LaneGroups, PacketWidthOfTheBuild)
{
#if defined(__AVX512F__)
  EXPECT_EQ(detail::across_lanes<float>(), 16);
  EXPECT_EQ(detail::across_lanes<double>(), 8);
#endif
  EXPECT_GE(detail::across_lanes<float>(), 2 * detail::across_lanes<double>());
}

} // namespace
