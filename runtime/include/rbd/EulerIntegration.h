#pragma once
// Configuration integration on the joint manifolds: q ⊕ dq, dq a tangent vector in alpha
// coordinates (see the joint table in docs/DESIGN.md). Backward joints keep the q/alpha of their
// forward twin, so they integrate the same way.
//   Rev, Prism, Cylindrical: q += dq
//   Spherical: quat ← quat ⊗ exp(ω)                         (ω in the successor frame)
//   Free: exact SE(3) exponential of the body twist [ω; v]:  quat ← quat ⊗ exp(ω),
//         r ← r + R(quat) V(ω) v,  V(ω) = 1 + (1 - cos θ)/θ² ω^ + (θ - sin θ)/θ³ ω^², θ = |ω|
//   Planar (q = [θ x y], (x, y) the successor's origin in successor axes, RBDyn): exact SE(2)
//         exponential of [φ; v_u; v_w]:   [x y] ← R2(φ)ᵀ ([x y] + V2(φ) [v_u v_w]),  θ ← θ + φ,
//         V2(φ) = [sin φ/φ, -(1 - cos φ)/φ; (1 - cos φ)/φ, sin φ/φ]
// Quaternions are normalised after each step. Both exponentials are exact for a constant velocity
// and agree to first order with the Euler updates of docs/DESIGN.md.

#include <cmath>
#include <vector>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

namespace detail
{

/// (θ - sin θ)/θ³, with its Taylor series near 0.
template<typename T>
T thetaMinusSinOverCube(T theta)
{
  using std::abs;
  using std::sin;
  if(abs(theta) < T(1e-2))
  {
    const T t2 = theta * theta;
    return T(1) / T(6) - t2 / T(120) + t2 * t2 / T(5040) - t2 * t2 * t2 / T(362880);
  }
  return (theta - sin(theta)) / (theta * theta * theta);
}

/// q ⊕ dq for one joint, in place (q: params() values, dq: dof() values).
template<typename T>
void integrateJoint(JointType::Type type, T * q, const T * dq)
{
  using std::cos;
  using std::sin;
  using Vec3 = sva::Vector3<T>;
  // quat ⊗ exp(w), exp(w) = [cos(θ/2); sin(θ/2)/θ w] (q stored [w x y z]); returns the old R(quat)
  auto rotate = [](T * qq, const Vec3 & w) {
    Eigen::Quaternion<T> quat(qq[0], qq[1], qq[2], qq[3]);
    quat.normalize();
    const T theta = w.norm();
    const Vec3 im = T(0.5) * sva::sinc(theta / T(2)) * w;
    Eigen::Quaternion<T> res = quat * Eigen::Quaternion<T>(cos(theta / T(2)), im.x(), im.y(), im.z());
    res.normalize();
    qq[0] = res.w();
    qq[1] = res.x();
    qq[2] = res.y();
    qq[3] = res.z();
    return sva::Matrix3<T>(quat.toRotationMatrix());
  };
  switch(type)
  {
    case JointType::Rev:
    case JointType::Prism:
      q[0] += dq[0];
      break;
    case JointType::Cylindrical:
      q[0] += dq[0];
      q[1] += dq[1];
      break;
    case JointType::Planar:
    {
      // [x y] ← R2(φ)ᵀ ([x y] + V2(φ) [v_u v_w]), sin φ/φ = sinc φ, (1 - cos φ)/φ = φ sinc²(φ/2)/2
      const T phi = dq[0], s = sva::sinc(phi), c = phi * T(0.5) * sva::sinc(phi / T(2)) * sva::sinc(phi / T(2));
      const T x = q[1] + s * dq[1] - c * dq[2], y = q[2] + c * dq[1] + s * dq[2];
      const T cp = cos(phi), sp = sin(phi);
      q[1] = cp * x + sp * y;
      q[2] = -sp * x + cp * y;
      q[0] += phi;
      break;
    }
    case JointType::Spherical:
      rotate(q, Vec3(dq[0], dq[1], dq[2]));
      break;
    case JointType::Free:
    {
      const Vec3 w(dq[0], dq[1], dq[2]), v(dq[3], dq[4], dq[5]);
      const T theta = w.norm(), sh = sva::sinc(theta / T(2));
      // V(ω) v = v + (1 - cos θ)/θ² ω x v + (θ - sin θ)/θ³ ω x (ω x v), (1 - cos θ)/θ² = sinc²(θ/2)/2
      const Vec3 wxv = w.cross(v);
      const Vec3 Vv = v + T(0.5) * sh * sh * wxv + thetaMinusSinOverCube(theta) * w.cross(wxv);
      const sva::Matrix3<T> R = rotate(q, w);
      const Vec3 dr = R * Vv;
      q[4] += dr.x();
      q[5] += dr.y();
      q[6] += dr.z();
      break;
    }
    case JointType::Fixed:
      break;
  }
}

} // namespace detail

/// q ⊕ dq, per joint: q (params() values per joint), dq (dof() values per joint, alpha coordinates).
template<typename T>
std::vector<std::vector<T>> integrateConfiguration(const MultiBodyTpl<T> & mb, std::vector<std::vector<T>> q,
                                                   const std::vector<std::vector<T>> & dq)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    detail::integrateJoint(mb.joint(i).type(), q[k].data(), dq[k].data());
  }
  return q;
}

/// q ⊕ dq on flat vectors: q (size nrParams), dq (size nrDof). Use it to perturb a configuration
/// along a tangent direction (finite differences, Runge-Kutta stages...).
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> integrateConfiguration(const MultiBodyTpl<T> & mb,
                                                           const Eigen::Matrix<T, Eigen::Dynamic, 1> & q,
                                                           const Eigen::Matrix<T, Eigen::Dynamic, 1> & dq)
{
  Eigen::Matrix<T, Eigen::Dynamic, 1> out = q;
  for(int i = 0; i < mb.nrJoints(); ++i)
    detail::integrateJoint(mb.joint(i).type(), out.data() + mb.jointPosInParam(i), dq.data() + mb.jointPosInDof(i));
  return out;
}

/// dq/dt (size nrParams) for the velocity alpha (size nrDof) at q (size nrParams): the derivative
/// of q ⊕ (alpha t) at t = 0. Quaternions: d/dt quat = quat ⊗ [0; ω]/2; Free: dr/dt = R(quat) v;
/// Planar: d[x y]/dt = [v_u + θ̇ y, v_w - θ̇ x]; other joints: alpha.
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> configurationDerivative(const MultiBodyTpl<T> & mb,
                                                            const Eigen::Matrix<T, Eigen::Dynamic, 1> & q,
                                                            const Eigen::Matrix<T, Eigen::Dynamic, 1> & alpha)
{
  using std::cos;
  using std::sin;
  Eigen::Matrix<T, Eigen::Dynamic, 1> qd = Eigen::Matrix<T, Eigen::Dynamic, 1>::Zero(mb.nrParams());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const T * qi = q.data() + mb.jointPosInParam(i);
    const T * a = alpha.data() + mb.jointPosInDof(i);
    T * out = qd.data() + mb.jointPosInParam(i);
    const auto type = mb.joint(i).type();
    switch(type)
    {
      case JointType::Planar:
        // p = R2(θ) [x y] moves with R2(θ) [v_u v_w]: d[x y]/dt = [v_u v_w] - θ̇ J [x y], J = [0 -1; 1 0]
        out[0] = a[0];
        out[1] = a[1] + a[0] * qi[2];
        out[2] = a[2] - a[0] * qi[1];
        break;
      case JointType::Spherical:
      case JointType::Free:
      {
        // d/dt quat = quat ⊗ [0; ω] / 2
        const Eigen::Quaternion<T> quat(qi[0], qi[1], qi[2], qi[3]);
        const sva::Vector3<T> w(a[0], a[1], a[2]);
        out[0] = -T(0.5) * quat.vec().dot(w);
        sva::Vector3<T>::Map(out + 1) = T(0.5) * (quat.w() * w + quat.vec().cross(w));
        // dr/dt = R(quat) v
        if(type == JointType::Free)
          sva::Vector3<T>::Map(out + 4) = quat.normalized().toRotationMatrix() * sva::Vector3<T>(a[3], a[4], a[5]);
        break;
      }
      default:
        for(int c = 0; c < mb.joint(i).dof(); ++c) out[c] = a[c];
    }
  }
  return qd;
}

/// q ← q ⊕ (alpha step + alphaD step²/2) for one joint (RBDyn's deprecated name; its current
/// jointIntegration, NumericalIntegration.h, integrates the constant-acceleration trajectory).
template<typename T>
void eulerJointIntegration(JointType::Type type, const std::vector<T> & alpha, const std::vector<T> & alphaD,
                           sva::detail::identity_t<T> step, std::vector<T> & q)
{
  T dq[6];
  for(std::size_t c = 0; c < alpha.size(); ++c) dq[c] = alpha[c] * step + T(0.5) * alphaD[c] * step * step;
  detail::integrateJoint(type, q.data(), dq);
}

/// Use alpha and alphaD. Fill q ← q ⊕ (alpha step + alphaD step²/2) and alpha ← alpha + alphaD step
/// (the alphaD step²/2 term as in RBDyn: exact for constant acceleration on vector joints).
template<typename T>
void eulerIntegration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc,
                      typename MultiBodyConfigTpl<T>::Scalar step)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    eulerJointIntegration(mb.joint(i).type(), mbc.alpha[k], mbc.alphaD[k], step, mbc.q[k]);
    for(std::size_t c = 0; c < mbc.alpha[k].size(); ++c) mbc.alpha[k][c] += mbc.alphaD[k][c] * step;
  }
}

/// Checked variant: throws std::domain_error when q, alpha or alphaD do not match the model.
template<typename T>
void sEulerIntegration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc,
                       typename MultiBodyConfigTpl<T>::Scalar step);

extern template std::vector<std::vector<double>> integrateConfiguration(const MultiBodyTpl<double> &,
                                                                        std::vector<std::vector<double>>,
                                                                        const std::vector<std::vector<double>> &);
extern template std::vector<std::vector<long double>> integrateConfiguration(
    const MultiBodyTpl<long double> &, std::vector<std::vector<long double>>,
    const std::vector<std::vector<long double>> &);
extern template Eigen::VectorXd integrateConfiguration(const MultiBodyTpl<double> &, const Eigen::VectorXd &,
                                                       const Eigen::VectorXd &);
extern template Eigen::Matrix<long double, Eigen::Dynamic, 1> integrateConfiguration(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
extern template Eigen::VectorXd configurationDerivative(const MultiBodyTpl<double> &, const Eigen::VectorXd &,
                                                        const Eigen::VectorXd &);
extern template Eigen::Matrix<long double, Eigen::Dynamic, 1> configurationDerivative(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
extern template void eulerIntegration<double>(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, double);
extern template void eulerIntegration<long double>(const MultiBodyTpl<long double> &,
                                                   MultiBodyConfigTpl<long double> &, long double);
extern template void sEulerIntegration<double>(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, double);
extern template void sEulerIntegration<long double>(const MultiBodyTpl<long double> &,
                                                    MultiBodyConfigTpl<long double> &, long double);

} // namespace rbd
