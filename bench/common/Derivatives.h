#pragma once
// Derivatives of inverse and forward dynamics: the reference every implementation (generated,
// runtime, Pinocchio) is checked against, the witness the reference itself is checked against, and
// the check.
//
// Convention (the generated header's and rbd/IDDerivatives.h's): derivatives with respect to q are
// taken in the tangent space, in alpha coordinates (size nv): q ⊕ δ = rbd::integrateConfiguration(mb,
// q, δ), i.e. for a free joint δ = [δω; δv] in the child frame (quat ← quat ⊗ exp(δω), r ← r + R(quat)
// V(δω) δv), for a spherical joint δω in the child frame, q + δ for the others. Matrices are nv x nv
// in the runtime's dof order (rbd::dofToVector), free joints [ω; v].

#include <string>

#include <Eigen/Core>

#include "BenchCase.h"
#include "Checks.h"

namespace rbdbench
{

/// Inverse and forward dynamics derivatives at one state (the layout of the generated
/// inverse_dynamics_derivatives / forward_dynamics_derivatives results).
struct DerivativesRef
{
  Eigen::MatrixXd dtau_dq, dtau_dalpha;                  ///< ∂ID/∂q (tangent), ∂ID/∂alpha at (q, alpha, alphaD)
  Eigen::VectorXd alphaD;                                 ///< FD(q, alpha, tau)
  Eigen::MatrixXd dalphaD_dq, dalphaD_dalpha, Minv;       ///< ∂FD/∂q (tangent), ∂FD/∂alpha, H^-1 at (q, alpha, tau)
  double condH = 1;                                       ///< cond(H) at q (2-norm)
};

/// The reference: the runtime's analytic derivatives (rbd::InverseDynamicsDerivatives,
/// rbd::ForwardDynamicsDerivatives) evaluated in long double (eps 1.1e-19), rounded to double.
DerivativesRef derivativesReference(const BenchCase & c, const State & s);

/// Step of the central differences (long double; see derivativesDifferences).
constexpr long double kDerivativeStep = 1e-6L;

/// The witness of the reference, independent of the runtime's derivative code: central finite
/// differences of the runtime's inverse dynamics (rbd::InverseDynamics) and forward dynamics
/// (rbd::ForwardDynamics, CRBA + Cholesky) in long double, step kDerivativeStep in the tangent
/// space. Its own error: truncation h²/6 |f'''| ≈ 2e-13 |f'''| plus rounding eps_ld |f| / h ≈ 1e-13 |f|.
DerivativesRef derivativesDifferences(const BenchCase & c, const State & s);

/// Number of pool states the derivatives are checked on.
constexpr std::size_t kDerivativesChecked = 4;

/// Name of the reference in the CheckLog ("runtime_ld/id_derivatives", ".../fd_derivatives").
extern const char * const kDerivativesReference;

/// Checks the reference against the witness on the first kDerivativesChecked pool states (log
/// entries kDerivativesReference), with the tolerances of the double implementations.
void checkDerivativesReference(const BenchCase & c, CheckLog & log);

/// May the cell (impl, algo) be timed: impl agrees with the reference and the reference with the
/// witness.
bool derivativesAgree(const CheckLog & log, const std::string & impl, const std::string & algo);

/// Checks an implementation's derivatives against derivativesReference on the first
/// kDerivativesChecked pool states and logs "<impl>/id_derivatives" and "<impl>/fd_derivatives".
/// id(k) and fd(k) return DerivativesRef-shaped results (runtime layout) at pool state k (fd fills
/// alphaD, dalphaD_dq, dalphaD_dalpha, Minv; id fills dtau_dq, dtau_dalpha).
/// Tolerances (relErr, scale max(1, |ref|_inf)), defaults for double: ID derivatives 1e-9 — a
/// double evaluation is exact to a few hundred eps of the largest term; FD derivatives: error /
/// cond(H) ≤ 1e-12, the criterion of the forward-dynamics checks (a correct double solver of
/// H x = b is off by about cond(H) eps; ∂FD = -H^-1 ∂ID carries the same factor). For float: about
/// 1e-4 and 1e-4 per cond(H) (eps_f = 6e-8), as the other float checks.
template<class IdFn, class FdFn>
void checkDerivatives(const BenchCase & c, CheckLog & log, const std::string & impl, IdFn id, FdFn fd,
                      const std::string & idNote, const std::string & fdNote, double tolId = 1e-9,
                      double tolFdPerCond = 1e-12);

} // namespace rbdbench

#include "Derivatives.hxx"
