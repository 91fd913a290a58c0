// Compiled once per generated header:
//   -DRBDGEN_NS=<namespace> -DRBDGEN_ROBOT="robot" -DRBDGEN_VERSION_TAG="before|after"
//   [-DRBDGEN_DERIVATIVES: the header has the derivatives, timed too].
#include <array>
#include <chrono>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "Case.h"

#define RBDGEN_STR2(x) #x
#define RBDGEN_STR(x) RBDGEN_STR2(x)
#include RBDGEN_STR(RBDGEN_NS/dynamics.hpp)

namespace
{
namespace ns = RBDGEN_NS;
using Config = ns::Config<double>;
using Tangent = ns::Tangent<double>;
using Wrenches = std::array<ns::Wrench<double>, ns::nbodies>;

// The states in the header's types, one array per input, so that a function's loop reads only
// what it takes (a compact array of q for the functions of q, as a user's loop would).
struct Inputs
{
  std::vector<Config> q;
  std::vector<Tangent> alpha, alphaD;
  std::vector<Wrenches> fext;
  std::vector<ns::Kinematics<double>> kin;
};

Inputs inputs(const std::vector<State> & states)
{
  Inputs in;
  for(const State & s : states)
  {
    in.q.push_back(Eigen::Map<const Config>(s.q.data()));
    in.alpha.push_back(Eigen::Map<const Tangent>(s.alpha.data()));
    in.alphaD.push_back(Eigen::Map<const Tangent>(s.alphaD.data()));
    Wrenches f;
    for(int b = 0; b < ns::nbodies; ++b)
      f[static_cast<std::size_t>(b)] = Eigen::Map<const ns::Wrench<double>>(s.fext.data() + 6 * b);
    in.fext.push_back(f);
    in.kin.push_back(ns::kinematics<double>(in.q.back()));
  }
  return in;
}

// Every entry of a result, in a fixed order.
template<class M>
void flatten(const Eigen::MatrixBase<M> & m, std::vector<double> & out)
{
  for(Eigen::Index c = 0; c < m.cols(); ++c)
    for(Eigen::Index r = 0; r < m.rows(); ++r) out.push_back(m(r, c));
}
void flatten(const ns::Pose<double> & p, std::vector<double> & out)
{
  flatten(p.rotation, out);
  flatten(p.translation, out);
}
template<class T, std::size_t N>
void flatten(const std::array<T, N> & a, std::vector<double> & out)
{
  for(const T & x : a) flatten(x, out);
}
void flatten(const ns::Kinematics<double> & k, std::vector<double> & out)
{
  flatten(k.pose, out);
  flatten(k.frame, out);
}
#if defined(RBDGEN_DERIVATIVES)
void flatten(const ns::IdDerivatives<double> & d, std::vector<double> & out)
{
  flatten(d.dtau_dq, out);
  flatten(d.dtau_dalpha, out);
}
void flatten(const ns::FdDerivatives<double> & d, std::vector<double> & out)
{
  flatten(d.alphaD, out);
  flatten(d.dalphaD_dq, out);
  flatten(d.dalphaD_dalpha, out);
  flatten(d.Minv, out);
}
#endif

// Two entries of a result, read after every call.
template<class M>
double probe(const Eigen::MatrixBase<M> & m) { return m(0, 0) + m(m.rows() - 1, m.cols() - 1); }
double probe(const ns::Pose<double> & p) { return p.rotation(0, 0) + p.translation(2); }
template<class T, std::size_t N>
double probe(const std::array<T, N> & a) { return probe(a.front()) + probe(a.back()); }
double probe(const ns::Kinematics<double> & k) { return probe(k.pose) + probe(k.frame); }
#if defined(RBDGEN_DERIVATIVES)
double probe(const ns::IdDerivatives<double> & d) { return probe(d.dtau_dq) + probe(d.dtau_dalpha); }
double probe(const ns::FdDerivatives<double> & d) { return probe(d.dalphaD_dq) + probe(d.Minv); }
#endif

// F: (Body, const Inputs &, state index) -> result, a noinline function (the call a user's code makes).
template<auto F>
void eval(int body, const State & s, std::vector<double> & out)
{
  out.clear();
  flatten(F(static_cast<ns::Body>(body), inputs({s}), 0), out);
}

template<auto F>
__attribute__((noinline)) double timeLoop(int body, const Inputs & in, int iters)
{
  double checksum = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for(int i = 0; i < iters; ++i)
    checksum += probe(F(static_cast<ns::Body>(body), in, static_cast<std::size_t>(i) % in.q.size()));
  const auto t1 = std::chrono::steady_clock::now();
  volatile double keep = checksum;
  static_cast<void>(keep);
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / iters;
}

// Run `shift` (0, 1, ...) places the data differently: the timed calls' stack frames 448 bytes
// lower per shift and the inputs further on the heap. One placement can make a function's stack
// stores and its input loads alias (same address modulo 4 KiB: a load waits for an unrelated store)
// and move one binary's time by 20-30 %; the median over placements does not depend on one.
template<auto F>
double time(int body, const std::vector<State> & states, int iters, int shift)
{
  std::vector<char> heapPad(static_cast<std::size_t>(shift) * 4160 + 64);
  const Inputs in = inputs(states);
  volatile char * stackPad = static_cast<char *>(__builtin_alloca(static_cast<std::size_t>(shift) * 448 + 64));
  stackPad[0] = 0;
  heapPad[0] = stackPad[0];
  return timeLoop<F>(body, in, iters);
}

#define RBDGEN_NOINLINE __attribute__((noinline))
RBDGEN_NOINLINE auto forwardKinematics(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::forward_kinematics<double>(x.q[i]);
}
RBDGEN_NOINLINE auto kinematics(ns::Body, const Inputs & x, std::size_t i) { return ns::kinematics<double>(x.q[i]); }
RBDGEN_NOINLINE auto jacobianKin(ns::Body b, const Inputs & x, std::size_t i)
{
  return ns::jacobian<double>(b, x.kin[i]);
}
RBDGEN_NOINLINE auto jacobianQ(ns::Body b, const Inputs & x, std::size_t i) { return ns::jacobian<double>(b, x.q[i]); }
// jacobian_dot_times_alpha from q is newer than some before headers (then left out)
template<class T, class = void>
struct HasJdotFromQ : std::false_type
{
};
template<class T>
struct HasJdotFromQ<T, std::void_t<decltype(ns::jacobian_dot_times_alpha<T>(
                          ns::Body{}, std::declval<const ns::Config<T> &>(), std::declval<const ns::Tangent<T> &>()))>>
: std::true_type
{
};
template<class T = double>
RBDGEN_NOINLINE auto jdotQ(ns::Body b, const Inputs & x, std::size_t i)
{
  return ns::jacobian_dot_times_alpha<T>(b, x.q[i], x.alpha[i]);
}
RBDGEN_NOINLINE auto comQ(ns::Body, const Inputs & x, std::size_t i) { return ns::center_of_mass<double>(x.q[i]); }
RBDGEN_NOINLINE auto comJacobianKin(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::com_jacobian<double>(x.kin[i]);
}
RBDGEN_NOINLINE auto momentumMatrix(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::centroidal_momentum_matrix<double>(x.q[i]);
}
RBDGEN_NOINLINE auto inverseDynamics(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::inverse_dynamics<double>(x.q[i], x.alpha[i], x.alphaD[i]);
}
RBDGEN_NOINLINE auto inverseDynamicsFext(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::inverse_dynamics<double>(x.q[i], x.alpha[i], x.alphaD[i], x.fext[i]);
}
RBDGEN_NOINLINE auto nonlinearEffects(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::nonlinear_effects<double>(x.q[i], x.alpha[i]);
}
RBDGEN_NOINLINE auto velocityTorques(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::velocity_torques<double>(x.q[i], x.alpha[i]);
}
RBDGEN_NOINLINE auto gravityTorques(ns::Body, const Inputs & x, std::size_t i) { return ns::gravity_torques<double>(x.q[i]); }
RBDGEN_NOINLINE auto forwardDynamics(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::forward_dynamics<double>(x.q[i], x.alpha[i], x.alphaD[i]);
}
RBDGEN_NOINLINE auto massMatrix(ns::Body, const Inputs & x, std::size_t i) { return ns::mass_matrix<double>(x.q[i]); }
#if defined(RBDGEN_DERIVATIVES) // (headers generated with --derivatives)
RBDGEN_NOINLINE auto idDerivatives(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::inverse_dynamics_derivatives<double>(x.q[i], x.alpha[i], x.alphaD[i]);
}
RBDGEN_NOINLINE auto fdDerivatives(ns::Body, const Inputs & x, std::size_t i)
{
  return ns::forward_dynamics_derivatives<double>(x.q[i], x.alpha[i], x.alphaD[i]);
}
#endif

template<auto F>
FunctionCase function(const char * name, bool link)
{
  return {name, link, &eval<F>, &time<F>};
}

template<class T>
std::vector<FunctionCase> jdotFromQ()
{
  if constexpr(HasJdotFromQ<T>::value) return {function<jdotQ<T>>("jacobian_dot_times_alpha(body, q, alpha)", true)};
  else return {};
}

int body(const std::string & name)
{
  for(int b = 0; b < ns::nbodies; ++b)
    if(name == ns::body_names[static_cast<std::size_t>(b)]) return b;
  return -1;
}

const bool registered = [] {
  const std::vector<FunctionCase> jdot = jdotFromQ<double>();
  headerCases().push_back({RBDGEN_ROBOT, RBDGEN_VERSION_TAG, ns::nq, ns::nv, ns::nbodies, &body,
                           {function<forwardKinematics>("forward_kinematics(q)", false),
                            function<kinematics>("kinematics(q)", false),
                            function<jacobianKin>("jacobian(body, kin)", true),
                            function<jacobianQ>("jacobian(body, q)", true),
                            function<comQ>("center_of_mass(q)", false),
                            function<comJacobianKin>("com_jacobian(kin)", false),
                            function<momentumMatrix>("centroidal_momentum_matrix(q)", false),
                            function<inverseDynamics>("inverse_dynamics(q, alpha, alphaD)", false),
                            function<inverseDynamicsFext>("inverse_dynamics(q, alpha, alphaD, fext)", false),
                            function<nonlinearEffects>("nonlinear_effects(q, alpha)", false),
                            function<velocityTorques>("velocity_torques(q, alpha)", false),
                            function<gravityTorques>("gravity_torques(q)", false),
                            function<forwardDynamics>("forward_dynamics(q, alpha, tau)", false),
                            function<massMatrix>("mass_matrix(q)", false)}});
  auto & functions = headerCases().back().functions;
  functions.insert(functions.begin() + 4, jdot.begin(), jdot.end());
#if defined(RBDGEN_DERIVATIVES)
  functions.push_back(function<idDerivatives>("inverse_dynamics_derivatives(q, alpha, alphaD)", false));
  functions.push_back(function<fdDerivatives>("forward_dynamics_derivatives(q, alpha, tau)", false));
#endif
  return true;
}();
} // namespace
