// generate_robot_dynamics(... INSTANTIATE): ur5e_inst's functions for double and float come from the
// generated dynamics_double.cpp and dynamics_float.cpp (extern template here: this file instantiates
// none of them; `nm` shows them undefined in its object), equal to the header-only build of the same
// URDF (ur5e, checked against the runtime by test_generated).
#include <random>

#include <gtest/gtest.h>

#include <ur5e/dynamics.hpp>
#include <ur5e_inst/dynamics.hpp>

namespace
{

template<class A, class B>
double relErr(const Eigen::MatrixBase<A> & a, const Eigen::MatrixBase<B> & b)
{
  return double((a - b).cwiseAbs().maxCoeff()) / std::max(1.0, double(b.cwiseAbs().maxCoeff()));
}

template<class S>
void compare(double tol)
{
  static_assert(ur5e_inst::nv == ur5e::nv && ur5e_inst::nq == ur5e::nq);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2, 2);
  for(int s = 0; s < 20; ++s)
  {
    ur5e::Config<S> q;
    ur5e::Tangent<S> a, ad;
    for(int k = 0; k < ur5e::nv; ++k) q(k) = S(u(rng)), a(k) = S(u(rng)), ad(k) = S(u(rng));
    EXPECT_LE(relErr(ur5e_inst::inverse_dynamics<S>(q, a, ad), ur5e::inverse_dynamics<S>(q, a, ad)), tol);
    EXPECT_LE(relErr(ur5e_inst::mass_matrix<S>(q), ur5e::mass_matrix<S>(q)), tol);
    EXPECT_LE(relErr(ur5e_inst::forward_dynamics<S>(q, a, ad), ur5e::forward_dynamics<S>(q, a, ad)), tol);
    EXPECT_LE(relErr(ur5e_inst::jacobian<S>(ur5e_inst::Body::tool0, q), ur5e::jacobian<S>(ur5e::Body::tool0, q)), tol);
    const auto pi = ur5e_inst::forward_kinematics<S>(q);
    const auto pr = ur5e::forward_kinematics<S>(q);
    for(std::size_t b = 0; b < pi.size(); ++b) EXPECT_LE(relErr(pi[b].translation, pr[b].translation), tol);
    EXPECT_LE(relErr(ur5e_inst::forward_dynamics_derivatives<S>(q, a, ad).dalphaD_dq,
                     ur5e::forward_dynamics_derivatives<S>(q, a, ad).dalphaD_dq),
              100 * tol);
  }
}

TEST(Instantiated, EqualsTheHeaderOnlyBuild)
{
  compare<double>(1e-14);
  compare<float>(1e-5);
}

} // namespace
