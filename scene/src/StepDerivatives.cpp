// Derivatives of one integrator step of a scene (see rbd/scene/StepDerivatives.h).
#include "rbd/scene/StepDerivatives.h"

#include <stdexcept>

#include <rbd/EulerIntegration.h>
#include <rbd/IntegrationDerivatives.h>

namespace rbd::scene
{

template<class T>
StepDerivativesTpl<T> stepDerivatives(const SceneDynamicsTpl<T> & dyn, const typename SceneDynamicsTpl<T>::VectorX & q,
                                      const typename SceneDynamicsTpl<T>::VectorX & alpha,
                                      const typename SceneDynamicsTpl<T>::VectorX & tau,
                                      typename SceneDynamicsTpl<T>::Scalar dt, Integrator integrator,
                                      const typename SceneDynamicsTpl<T>::Wrenches & wrenches)
{
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  const MultiBodyTpl<T> & mb = dyn.mb();
  const int nv = mb.nrDof();
  if(q.size() != mb.nrParams() || alpha.size() != nv || tau.size() != nv)
    throw std::invalid_argument("stepDerivatives: q, alpha or tau does not match the scene's robot");
  StepDerivativesTpl<T> out;
  out.A = MatrixX::Zero(2 * nv, 2 * nv);
  out.B = MatrixX::Zero(2 * nv, nv);
  switch(integrator)
  {
    case Integrator::SemiImplicitEuler:
    case Integrator::ExplicitEuler:
    {
      const auto f = dyn.forwardDynamicsDerivatives(q, alpha, tau, wrenches);
      // alpha⁺ rows: dt [Fq, Fa, M⁻¹] + [0, 1, 0]
      out.A.bottomLeftCorner(nv, nv) = dt * f.dalphaDDq;
      out.A.bottomRightCorner(nv, nv) = dt * f.dalphaDDalpha;
      out.A.bottomRightCorner(nv, nv).diagonal().array() += T(1);
      out.B.bottomRows(nv) = dt * f.Minv;
      out.next.alpha = alpha + dt * f.alphaD;
      const bool semi = integrator == Integrator::SemiImplicitEuler;
      const VectorX w = dt * (semi ? out.next.alpha : alpha);
      out.next.q = integrateConfiguration(mb, q, w);
      const IntegrationDerivativesTpl<T> D = integrateConfigurationDerivatives(mb, w);
      if(semi)
      {
        // q⁺ rows: [Dq, 0, 0] + dt Dw ∂alpha⁺
        const MatrixX dtDw = dt * D.dw;
        out.A.topRows(nv).noalias() = dtDw * out.A.bottomRows(nv);
        out.A.topLeftCorner(nv, nv) += D.dq;
        out.B.topRows(nv).noalias() = dtDw * out.B.bottomRows(nv);
      }
      else
      {
        // q⁺ rows: [Dq, dt Dw, 0]
        out.A.topLeftCorner(nv, nv) = D.dq;
        out.A.topRightCorner(nv, nv) = dt * D.dw;
      }
      break;
    }
    case Integrator::RK4:
    {
      // Stage states and their derivatives with respect to z = (δq, alpha, tau) (3 nv columns).
      const int nz = 3 * nv;
      const MatrixX Q1 = [&] {
        MatrixX m = MatrixX::Zero(mb.nrParams(), nz);
        m.leftCols(nv) = configurationTangentMap(mb, q);
        return m;
      }();
      const MatrixX A1 = [&] {
        MatrixX m = MatrixX::Zero(nv, nz);
        m.middleCols(nv, nv).setIdentity();
        return m;
      }();
      // slopes (k_q, k_a) of a stage and their derivatives
      struct Slope
      {
        VectorX kq, ka;
        MatrixX dkq, dka;
      };
      auto slope = [&](const VectorX & qs, const VectorX & as, const MatrixX & dqs, const MatrixX & das) {
        Slope s;
        s.kq = configurationDerivative(mb, qs, as);
        const auto C = configurationDerivativeJacobians(mb, qs, as);
        s.dkq.noalias() = C.dq * dqs;
        s.dkq.noalias() += C.dalpha * das;
        const auto f = dyn.forwardDynamicsDerivatives(qs, as, tau, wrenches);
        s.ka = f.alphaD;
        const MatrixX dTangent = configurationTangentProjection(mb, qs) * dqs; // nv × nz
        s.dka.noalias() = f.dalphaDDq * dTangent;
        s.dka.noalias() += f.dalphaDDalpha * das;
        s.dka.rightCols(nv) += f.Minv;
        return s;
      };
      const T h = T(0.5) * dt;
      const Slope k1 = slope(q, alpha, Q1, A1);
      const Slope k2 = slope(VectorX(q + h * k1.kq), VectorX(alpha + h * k1.ka), MatrixX(Q1 + h * k1.dkq),
                             MatrixX(A1 + h * k1.dka));
      const Slope k3 = slope(VectorX(q + h * k2.kq), VectorX(alpha + h * k2.ka), MatrixX(Q1 + h * k2.dkq),
                             MatrixX(A1 + h * k2.dka));
      const Slope k4 = slope(VectorX(q + dt * k3.kq), VectorX(alpha + dt * k3.ka), MatrixX(Q1 + dt * k3.dkq),
                             MatrixX(A1 + dt * k3.dka));
      const T s6 = dt / T(6);
      const VectorX y = q + s6 * (k1.kq + T(2) * k2.kq + T(2) * k3.kq + k4.kq);
      const MatrixX dy = Q1 + s6 * (k1.dkq + T(2) * k2.dkq + T(2) * k3.dkq + k4.dkq);
      out.next.alpha = alpha + s6 * (k1.ka + T(2) * k2.ka + T(2) * k3.ka + k4.ka);
      const MatrixX dAlpha = A1 + s6 * (k1.dka + T(2) * k2.dka + T(2) * k3.dka + k4.dka);
      out.next.q = y;
      normalizeQuaternions(mb, out.next.q);
      const MatrixX dq = configurationTangentProjection(mb, y) * dy;
      out.A.topRows(nv) = dq.leftCols(2 * nv);
      out.A.bottomRows(nv) = dAlpha.leftCols(2 * nv);
      out.B.topRows(nv) = dq.rightCols(nv);
      out.B.bottomRows(nv) = dAlpha.rightCols(nv);
      break;
    }
  }
  return out;
}

template StepDerivativesTpl<double> stepDerivatives(const SceneDynamicsTpl<double> &, const Eigen::VectorXd &,
                                                    const Eigen::VectorXd &, const Eigen::VectorXd &, double, Integrator,
                                                    const std::vector<sva::ForceVec<double>> &);
template StepDerivativesTpl<long double> stepDerivatives(const SceneDynamicsTpl<long double> &,
                                                         const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
                                                         const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
                                                         const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
                                                         long double, Integrator,
                                                         const std::vector<sva::ForceVec<long double>> &);

} // namespace rbd::scene
