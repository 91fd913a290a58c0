// The batch API (NS/batch.hpp) against the single-state generated code, for every function of every
// robot of tests/batch/CMakeLists.txt, in double and float, for N = 1, 3, 7, 100 (packs of 2 to 16
// states: remainders), threads 0 (= 1), 1, 2, 3.
//
// - Threads: the outputs are bitwise the same for every thread count, and nothing is written past
//   the N states (the padded lanes of the last pack are dropped).
// - Pack vs single state, same scalar: where the compiler cannot fuse a*b + c (a target without FMA,
//   test_batch), each lane runs the single-state operations: bitwise equal, but for the two dense
//   products of forward_dynamics_derivatives (-Minv dID), which Eigen sums in another order for a
//   scalar (vectorised) than for a pack (coefficient by coefficient): within the bound of two
//   summation orders, nv eps sum_k |Minv_ik| |dID_kj|. With FMA (test_batch_fused), g++ fuses the
//   scalar and the pack code differently (it evaluates an overloaded operator's operands in another
//   order, and its SLP vectoriser fuses scalar code even with -ffp-contract=off), so each operation
//   may round differently: the difference of two evaluations of the same algorithm, bounded like
//   test_generated's (kDouble below, grown with cond(H) for forward dynamics).
// - float batch vs double single state: test_generated's float bounds.
// - Layout::columns (structure of arrays) gives Layout::rows' values bitwise.
// - Many calls in a row with threads 2-4 equal threads = 1 (the pool's chunks and withdrawals).
// - No heap allocation with threads = 1, in either layout.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "../generator/AllocationCounter.h"
#include "BatchRobot.h"
#include "TestModels.h"

namespace rbdgentest
{
/// The robots of this executable (batch_robots.cpp, configured by CMake): names, then each robot.
const std::vector<const char *> & batchRobotNames();
bool batchRobotsRunHere(); ///< false: the CPU lacks what the adapters were compiled for
const BatchRobot & batchRobot(std::size_t i);
} // namespace rbdgentest

namespace
{
using rbdgentest::BatchFunction;
using rbdgentest::BatchRobot;
using rbdgentest::Growth;
using rbdgentest::Layout;
using rbdgentest::Output;

constexpr std::size_t kSizes[] = {1, 3, 7, 100};
constexpr int kThreads[] = {0, 1, 2, 3};
/// Fused double pack vs fused double single state, relative to max(1, max |single|) (measured: 7e-15
/// for forward dynamics, 3e-15 for inverse dynamics).
constexpr double kDouble = 1e-13;
// float batch vs double single state, as test_generated: kinematics 2e-5, dynamics 2e-4.
constexpr double kFloatKinematics = 2e-5;
constexpr double kFloatDynamics = 2e-4;

/// max |x - ref| / max(1, max |ref|) over n values.
template<class T>
double relError(const T * x, const double * ref, int n)
{
  double e = 0, m = 1;
  for(int i = 0; i < n; ++i)
  {
    e = std::max(e, std::abs(static_cast<double>(x[i]) - ref[i]));
    m = std::max(m, std::abs(ref[i]));
  }
  return e / m;
}

/// Worst errors of one kind of comparison, printed at the end of the test.
struct Worst
{
  explicit Worst(const char * w) : what(w) {}
  const char * what;
  double value = 0;
  std::string where;
  void add(double e, const std::string & at)
  {
    if(e > value) value = e, where = at;
  }
  ~Worst() { std::printf("[ %-40s ] worst %.3g %s\n", what, value, where.c_str()); }
};

/// Seeded random inputs of N states: q in [-3, 3] (a floating base's quaternion normalised),
/// v and wrenches in [-3, 3], in the layout of the batch functions.
struct States
{
  std::vector<std::vector<double>> in;
  States(const BatchRobot & r, const std::vector<rbdgentest::Input> & kinds, std::size_t N, unsigned seed)
  {
    rbdtest::Rng rng(seed);
    for(rbdgentest::Input k : kinds)
    {
      const int n = k == rbdgentest::Input::q ? r.nq : k == rbdgentest::Input::v ? r.nv : 6 * r.nwrenches;
      std::vector<double> x(N * static_cast<std::size_t>(n));
      for(double & v : x) v = rbdtest::uniform(rng, -3, 3);
      if(k == rbdgentest::Input::q && r.floatingBase)
        for(std::size_t s = 0; s < N; ++s)
          Eigen::Map<Eigen::Vector4d>(x.data() + s * static_cast<std::size_t>(n)).normalize();
      in.push_back(std::move(x));
    }
  }
  template<class T>
  std::vector<std::vector<T>> as() const
  {
    std::vector<std::vector<T>> c;
    for(const auto & x : in) c.emplace_back(x.begin(), x.end());
    return c;
  }
};

/// Outputs of N states with room for a pack more, filled with a sentinel (to see what is written).
template<class T>
struct Outputs
{
  static constexpr T sentinel = T(-12345.5);
  std::vector<std::vector<T>> out;
  Outputs(const std::vector<Output> & o, std::size_t N, std::size_t width)
  {
    for(const Output & x : o) out.emplace_back((N + width) * static_cast<std::size_t>(x.size), sentinel);
  }
  std::vector<T *> ptrs()
  {
    std::vector<T *> p;
    for(auto & x : out) p.push_back(x.data());
    return p;
  }
};

template<class T>
std::vector<const T *> constPtrs(const std::vector<std::vector<T>> & in)
{
  std::vector<const T *> p;
  for(const auto & x : in) p.push_back(x.data());
  return p;
}

/// cond(H) of each state's mass matrix (2-norm; H is symmetric positive definite).
std::vector<double> conditioning(const BatchRobot & r, const std::vector<double> & q, std::size_t N)
{
  std::vector<double> H(N * static_cast<std::size_t>(r.nv * r.nv)), cond(N);
  const double * in[] = {q.data()};
  double * out[] = {H.data()};
  r.massMatrix(in, out, N, 1);
  for(std::size_t s = 0; s < N; ++s)
  {
    const Eigen::Map<const Eigen::MatrixXd> Hs(H.data() + s * static_cast<std::size_t>(r.nv * r.nv), r.nv, r.nv);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Hs).eigenvalues();
    cond[s] = ev.maxCoeff() / ev.minCoeff();
  }
  return cond;
}

double growth(Growth g, double cond)
{
  const double c = std::max(1.0, cond * 1e-3);
  return g == Growth::none ? 1 : (g == Growth::cond ? c : c * c);
}

/// Bound of the two summation orders of -Minv dID for output o of forward_dynamics_derivatives
/// (o = 1: dID = dtau_dq, o = 2: dtau_dalpha, at alphaD = the output's alphaD): per entry
/// 1.01 nv eps sum_k |Minv_ik| |dID_kj|. |dID_kj| is the larger of inverse_dynamics_derivatives'
/// entry and of -(Minv^-1 out_o)_kj: the dID that forward_dynamics_derivatives forms itself (below
/// 24 dofs from its own world passes, the bias accelerations and forces moved by alphaD) sums other
/// roundings, and an entry that is 0 in one may be ~1e-17 of its terms in the other.
template<class T>
std::vector<T> productBound(const BatchRobot & r, const std::vector<BatchFunction<T>> & fns, const std::vector<const T *> & in,
                            const std::vector<T *> & out, std::size_t N, int o)
{
  const BatchFunction<T> * id = nullptr;
  for(const auto & f : fns)
    if(std::string(f.name) == "inverse_dynamics_derivatives") id = &f;
  const int nv = r.nv;
  std::vector<T> dq(N * static_cast<std::size_t>(nv * nv)), da(dq.size()), bound(dq.size());
  const T * idIn[] = {in[0], in[1], out[0], in.size() > 3 ? in[3] : nullptr}; // (a scene's wrenches: in[3])
  T * idOut[] = {dq.data(), da.data()};
  id->single(idIn, idOut, N, 1);
  using M = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for(std::size_t s = 0; s < N; ++s)
  {
    const std::size_t at = s * static_cast<std::size_t>(nv * nv);
    const Eigen::Map<const M> Minv(out[3] + at, nv, nv), dID((o == 1 ? dq : da).data() + at, nv, nv), dA(out[o] + at, nv, nv);
    using Md = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const Md Mdx = Minv.template cast<double>().inverse().eval() * dA.template cast<double>();
    const M dIDmax = dID.cwiseAbs().cwiseMax(Mdx.cwiseAbs().template cast<T>());
    Eigen::Map<M>(bound.data() + at, nv, nv) = T(1.01) * T(nv) * std::numeric_limits<T>::epsilon() * (Minv.cwiseAbs() * dIDmax);
  }
  return bound;
}

std::string where(const BatchRobot & r, const char * fn, int o, std::size_t N, std::size_t s)
{
  return std::string(r.name) + " " + fn + " output " + std::to_string(o) + ", N = " + std::to_string(N) + ", state "
         + std::to_string(s);
}

class Batch : public ::testing::TestWithParam<std::size_t>
{
protected:
  void SetUp() override
  {
    if(!rbdgentest::batchRobotsRunHere()) GTEST_SKIP() << "the CPU lacks the instructions these adapters use";
    robot_ = &rbdgentest::batchRobot(GetParam());
  }
  const BatchRobot & r() const { return *robot_; }
  const BatchRobot * robot_ = nullptr;

  /// Runs f on N states with every thread count into `first`; checks that they agree bitwise and
  /// write nothing past the N states.
  template<class T>
  void runAllThreadCounts(const BatchFunction<T> & f, const std::vector<const T *> & in, std::size_t N, std::size_t width,
                          Outputs<T> & first)
  {
    for(int th : kThreads)
    {
      Outputs<T> o(f.outputs, N, width);
      f.batch(in.data(), o.ptrs().data(), N, th, Layout::rows);
      for(std::size_t m = 0; m < f.outputs.size(); ++m)
      {
        const std::size_t n = N * static_cast<std::size_t>(f.outputs[m].size);
        for(std::size_t i = n; i < o.out[m].size(); ++i)
          ASSERT_EQ(o.out[m][i], Outputs<T>::sentinel) << f.name << ": written past the N = " << N << " states";
        if(th == kThreads[0]) first = o;
        else
          ASSERT_EQ(std::memcmp(o.out[m].data(), first.out[m].data(), n * sizeof(T)), 0)
              << f.name << " output " << m << ", N = " << N << ": threads = " << th << " differs from threads = " << kThreads[0];
      }
    }
  }

  /// Pack vs single state in the same scalar T: bitwise (products: within their bound) without
  /// fusion; with fusion (double only) within kDouble grown by the conditioning.
  template<class T>
  void compareSameScalar(const std::vector<BatchFunction<T>> & fns, std::size_t width, std::map<std::string, Worst> * fusedLog,
                         Worst & productLog)
  {
    for(const BatchFunction<T> & f : fns)
      for(std::size_t N : kSizes)
      {
        const States st(r(), f.inputs, N, static_cast<unsigned>(N) + 11);
        const std::vector<std::vector<T>> inT = st.as<T>();
        const std::vector<const T *> in = constPtrs(inT);
        Outputs<T> run(f.outputs, N, width);
        runAllThreadCounts(f, in, N, width, run);
        if(HasFatalFailure()) return;
        std::vector<std::vector<T>> & batch = run.out;
        Outputs<T> single(f.outputs, N, width);
        const std::vector<T *> sp = single.ptrs();
        f.single(in.data(), sp.data(), N, 1);
        const std::vector<double> cond = conditioning(r(), st.in[0], N);
        for(std::size_t m = 0; m < f.outputs.size(); ++m)
        {
          const Output & o = f.outputs[m];
          const std::size_t n = static_cast<std::size_t>(o.size);
          std::vector<T> bound;
          if(o.product && !r().fused)
          {
            std::vector<T *> bp;
            for(auto & b : batch) bp.push_back(b.data());
            bound = productBound(r(), fns, in, bp, N, static_cast<int>(m));
          }
          for(std::size_t s = 0; s < N; ++s)
          {
            const T * x = batch[m].data() + s * n;
            const T * y = single.out[m].data() + s * n;
            if(r().fused)
            {
              if constexpr(std::is_same_v<T, double>)
              {
                const double e = relError(x, y, o.size);
                EXPECT_LE(e, kDouble * growth(o.growth, cond[s])) << where(r(), f.name, static_cast<int>(m), N, s);
                fusedLog->try_emplace(f.name, f.name)
                    .first->second.add(e / growth(o.growth, cond[s]), where(r(), f.name, static_cast<int>(m), N, s));
              }
            }
            else if(o.product)
              for(std::size_t i = 0; i < n; ++i)
              {
                const T d = std::abs(x[i] - y[i]);
                ASSERT_LE(d, bound[s * n + i]) << where(r(), f.name, static_cast<int>(m), N, s) << ", entry " << i;
                if(bound[s * n + i] > 0) productLog.add(static_cast<double>(d / bound[s * n + i]), where(r(), f.name, static_cast<int>(m), N, s));
              }
            else
              ASSERT_EQ(std::memcmp(x, y, n * sizeof(T)), 0) << where(r(), f.name, static_cast<int>(m), N, s)
                                                              << ": the pack's lane differs from the single-state code";
          }
        }
      }
  }
};

TEST_P(Batch, MatchesSingleStatesDouble)
{
  std::printf("[ %-40s ]\n", r().fused ? "double pack vs single (fused): relative / growth" : "double pack vs single: bitwise");
  std::map<std::string, Worst> fused; // per function
  Worst product{"double -Minv dID: |difference| / bound"};
  compareSameScalar(r().d, r().widthDouble, &fused, product);
}

TEST_P(Batch, MatchesSingleStatesFloat)
{
  Worst product{"float -Minv dID: |difference| / bound"};
  compareSameScalar(r().f, r().widthFloat, nullptr, product);
}

TEST_P(Batch, FloatWithinFloatBoundsOfDouble)
{
  Worst kin{"float batch vs double single: kinematics"}, dyn{"float batch vs double single: dynamics"};
  ASSERT_EQ(r().d.size(), r().f.size());
  for(std::size_t k = 0; k < r().f.size(); ++k)
  {
    const BatchFunction<float> & f = r().f[k];
    const std::size_t N = 100;
    const States st(r(), f.inputs, N, 7);
    const std::vector<std::vector<float>> inF = st.as<float>();
    Outputs<float> batch(f.outputs, N, r().widthFloat);
    f.batch(constPtrs(inF).data(), batch.ptrs().data(), N, 2, Layout::rows);
    Outputs<double> ref(f.outputs, N, r().widthDouble);
    r().d[k].single(constPtrs(st.in).data(), ref.ptrs().data(), N, 1);
    const std::vector<double> cond = conditioning(r(), st.in[0], N);
    for(std::size_t m = 0; m < f.outputs.size(); ++m)
    {
      const Output & o = f.outputs[m];
      // as test_generated: the derivatives of forward dynamics get 10x
      const double slack = f.outputs.size() == 4 ? 10 : 1;
      for(std::size_t s = 0; s < N; ++s)
      {
        const std::size_t at = s * static_cast<std::size_t>(o.size);
        const double e = relError(batch.out[m].data() + at, ref.out[m].data() + at, o.size);
        const double tol = slack * (o.kinematic ? kFloatKinematics : kFloatDynamics) * growth(o.growth, cond[s]);
        EXPECT_LE(e, tol) << where(r(), f.name, static_cast<int>(m), N, s) << ", cond(H) = " << cond[s];
        (o.kinematic ? kin : dyn).add(e / growth(o.growth, cond[s]), where(r(), f.name, static_cast<int>(m), N, s));
      }
    }
  }
}

/// A pack with one lane beyond the exact range of the sin/cos reduction (std::sin/cos for that
/// lane) and the others in range: every lane as the single-state code.
TEST_P(Batch, LargeAnglesUseStdSinCosPerLane)
{
  const BatchFunction<double> & fk = r().d.front();
  ASSERT_STREQ(fk.name, "forward_kinematics");
  const std::size_t N = 2 * r().widthDouble - 1;
  States st(r(), fk.inputs, N, 3);
  const std::size_t angle = r().floatingBase ? 7 : 0; // the first joint after the base
  if(angle >= static_cast<std::size_t>(r().nq)) GTEST_SKIP() << "no joint angle";
  st.in[0][1 * static_cast<std::size_t>(r().nq) + angle] = 1e6 + 0.25;
  st.in[0][(N - 1) * static_cast<std::size_t>(r().nq) + angle] = -3e7;
  const std::vector<const double *> in = constPtrs(st.in);
  Outputs<double> batch(fk.outputs, N, r().widthDouble), single(fk.outputs, N, r().widthDouble);
  fk.batch(in.data(), batch.ptrs().data(), N, 1, Layout::rows);
  fk.single(in.data(), single.ptrs().data(), N, 1);
  const std::size_t n = N * static_cast<std::size_t>(fk.outputs[0].size);
  if(!r().fused) EXPECT_EQ(std::memcmp(batch.out[0].data(), single.out[0].data(), n * sizeof(double)), 0);
  else EXPECT_LE(relError(batch.out[0].data(), single.out[0].data(), static_cast<int>(n)), kDouble);
}

/// Layout::columns (item x N arrays, the states last) gives the values of Layout::rows bitwise:
/// the same lanes run the same code, only the loads and stores differ. Every function, double and
/// float, N = 1, 3, 7, 100 (remainder packs), threads 1 and 2; nothing written past the N states.
TEST_P(Batch, ColumnsLayoutEqualsRows)
{
  auto run = [this](const auto & fns, std::size_t width, auto zero) {
    using T = decltype(zero);
    for(const BatchFunction<T> & f : fns)
      for(std::size_t N : kSizes)
        for(int th : {1, 2})
        {
          const States st(r(), f.inputs, N, static_cast<unsigned>(N) + 23);
          const std::vector<std::vector<T>> rowsIn = st.as<T>();
          // (N, n) -> (n, N)
          std::vector<std::vector<T>> colsIn;
          for(const std::vector<T> & x : rowsIn)
          {
            const std::size_t n = x.size() / N;
            std::vector<T> c(x.size());
            for(std::size_t s = 0; s < N; ++s)
              for(std::size_t k = 0; k < n; ++k) c[k * N + s] = x[s * n + k];
            colsIn.push_back(std::move(c));
          }
          Outputs<T> rows(f.outputs, N, width), cols(f.outputs, N, width);
          f.batch(constPtrs(rowsIn).data(), rows.ptrs().data(), N, th, Layout::rows);
          f.batch(constPtrs(colsIn).data(), cols.ptrs().data(), N, th, Layout::columns);
          for(std::size_t m = 0; m < f.outputs.size(); ++m)
          {
            const std::size_t n = static_cast<std::size_t>(f.outputs[m].size);
            for(std::size_t i = N * n; i < cols.out[m].size(); ++i)
              ASSERT_EQ(cols.out[m][i], Outputs<T>::sentinel) << f.name << ": written past the N = " << N << " states";
            for(std::size_t s = 0; s < N; ++s)
              for(std::size_t k = 0; k < n; ++k)
              {
                const T a = rows.out[m][s * n + k], b = cols.out[m][k * N + s];
                ASSERT_EQ(std::memcmp(&a, &b, sizeof(T)), 0)
                    << where(r(), f.name, static_cast<int>(m), N, s) << ", value " << k << ", threads " << th << ": rows " << a
                    << ", columns " << b;
              }
          }
        }
  };
  run(r().d, r().widthDouble, 0.0);
  run(r().f, r().widthFloat, 0.0f);
}

/// Calls with threads > 1 from several user threads at once (the worker pool serves one call at a
/// time, the others start their own threads): each equals the same call made alone.
TEST_P(Batch, ConcurrentCallsWithThreads)
{
  const BatchFunction<double> & f = r().d.back();
  const std::size_t N = 100;
  std::vector<std::vector<std::vector<double>>> inputs;
  std::vector<Outputs<double>> alone, together;
  for(unsigned c = 0; c < 4; ++c)
  {
    inputs.push_back(States(r(), f.inputs, N, 40 + c).in);
    alone.emplace_back(f.outputs, N, r().widthDouble);
    together.emplace_back(f.outputs, N, r().widthDouble);
    f.batch(constPtrs(inputs[c]).data(), alone[c].ptrs().data(), N, 2, Layout::rows);
  }
  std::vector<std::thread> callers;
  for(std::size_t c = 0; c < 4; ++c)
    callers.emplace_back([&, c] {
      for(int k = 0; k < 20; ++k) f.batch(constPtrs(inputs[c]).data(), together[c].ptrs().data(), N, 2 + k % 2, Layout::rows);
    });
  for(std::thread & t : callers) t.join();
  for(std::size_t c = 0; c < 4; ++c)
    for(std::size_t m = 0; m < f.outputs.size(); ++m)
      EXPECT_EQ(together[c].out[m], alone[c].out[m]) << r().name << " " << f.name << ", caller " << c << ", output " << m;
}

/// Many calls in a row with threads > 1 (chunks taken in turn; a pool thread still asleep when the
/// caller has taken the last chunk is withdrawn and must take part in the next call only): every
/// call equals threads = 1.
TEST_P(Batch, ManyCallsInARowWithThreads)
{
  const BatchFunction<double> & f = r().d.front();
  for(std::size_t N : {std::size_t{5}, std::size_t{100}})
  {
    const auto inputs = States(r(), f.inputs, N, 77).in;
    Outputs<double> one(f.outputs, N, r().widthDouble), many(f.outputs, N, r().widthDouble);
    f.batch(constPtrs(inputs).data(), one.ptrs().data(), N, 1, Layout::rows);
    for(int k = 0; k < 300; ++k)
    {
      const int th = 2 + k % 3;
      f.batch(constPtrs(inputs).data(), many.ptrs().data(), N, th, Layout::rows);
      for(std::size_t m = 0; m < f.outputs.size(); ++m)
        ASSERT_EQ(many.out[m], one.out[m]) << r().name << " " << f.name << ", N = " << N << ", call " << k << ", threads " << th;
    }
  }
}

TEST_P(Batch, NoHeapAllocation)
{
  auto run = [this](const auto & fns, std::size_t width, auto zero) {
    using T = decltype(zero);
    for(const BatchFunction<T> & f : fns)
    {
      const std::size_t N = 7;
      const States st(r(), f.inputs, N, 5);
      const std::vector<std::vector<T>> inT = st.as<T>();
      const std::vector<const T *> in = constPtrs(inT);
      Outputs<T> o(f.outputs, N, width);
      const std::vector<T *> op = o.ptrs();
      for(Layout layout : {Layout::rows, Layout::columns})
      {
        long count = -1;
        {
          rbdgentest::AllocationScope scope;
          f.batch(in.data(), op.data(), N, 1, layout);
          count = scope.count();
        }
        EXPECT_EQ(count, 0) << r().name << " " << f.name << (layout == Layout::rows ? " (rows)" : " (columns)");
      }
    }
  };
  run(r().d, r().widthDouble, 0.0);
  run(r().f, r().widthFloat, 0.0f);
  // The counter is live: a std::vector allocates.
  rbdgentest::AllocationScope scope;
  std::vector<int> v(3);
  EXPECT_GE(scope.count(), 1);
}

INSTANTIATE_TEST_SUITE_P(Robots, Batch, ::testing::Range<std::size_t>(0, rbdgentest::batchRobotNames().size()),
                         [](const ::testing::TestParamInfo<std::size_t> & i) {
                           return std::string(rbdgentest::batchRobotNames()[i.param]);
                         });

} // namespace
