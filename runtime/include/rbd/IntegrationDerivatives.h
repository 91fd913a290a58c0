#pragma once
// Derivatives of the configuration integration q⁺ = q ⊕ w (rbd/EulerIntegration.h,
// integrateConfiguration), its inverse (configurationDifference) and the maps between the tangent
// space and the parameter vector q of R^nq that a Runge-Kutta step on q needs.
//
// Tangent convention (that of IDDerivatives.h): a perturbation δ of q is a vector of the dof space
// (size nv, the coordinates of alpha) and q ⊕ δ = integrateConfiguration(q, δ); for free and
// spherical joints δ = [δω; δv] (δv free joints only) is a motion in the child frame. The output
// q⁺ is perturbed the same way: q⁺ ⊕ δ⁺. Then, to first order,
//     (q ⊕ δ) ⊕ (w + δw) = q⁺ ⊕ (Dq δ + Dw δw),   Dq = ∂q⁺/∂q, Dw = ∂q⁺/∂w,
// both block diagonal (one dof × dof block per joint) and functions of w only (q's quaternions are
// unit: integrateConfiguration normalises them first). Per joint type, with θ = |ω|:
//   Rev, Prism, Cylindrical: Dq = Dw = 1.
//   Spherical (quat ← quat ⊗ exp(ω)): Dq = Exp(ω)ᵀ, Dw = Jr(ω) = 1 − a ω^ + b ω^², the right
//     Jacobian of SO(3), a = (1 − cos θ)/θ², b = (θ − sin θ)/θ³.
//   Free (quat ← quat ⊗ exp(ω), r ← r + R(quat) V(ω) v, V(ω) = 1 + a ω^ + b ω^²): the rotation rows
//     are the spherical ones; the translation rows, with p = V(ω) v,
//       ∂v⁺/∂[ω v] = [−Exp(ω)ᵀ p^, Exp(ω)ᵀ]                (Dq: the adjoint of Exp(w)⁻¹)
//       ∂v⁺/∂[δω δv] = [Exp(ω)ᵀ ∂(V(ω) v)/∂ω, Exp(ω)ᵀ V(ω) = Jr(ω)]   (Dw)
//     ∂(V(ω) v)/∂ω = −a v^ + (a'/θ) (ω × v) ωᵀ + b ((ω·v) 1 + ω vᵀ − 2 v ωᵀ) + (b'/θ) (ω × (ω × v)) ωᵀ.
//   Planar ([x y] ← R2(φ)ᵀ ([x y] + V2(φ) [v_u v_w]), θ ← θ + φ; V2(φ) = [s −c; c s], s = sin φ/φ,
//     c = (1 − cos φ)/φ; the SE(2) exponential, whatever the coordinates of q): Dq = [1 0;
//     R2(−φ) J V2(φ) v, R2(−φ)], Dw = [1 0; R2(−φ) V2'(φ) v, R2(−φ) V2(φ)], J = [0 −1; 1 0].
//   Fixed: no dof.
// Every coefficient uses its Taylor series for small angles (θ < 0.5), so the derivatives are
// accurate to a few ulps at and near w = 0 (the usual case: w = alpha dt).
//
// For integrators working on q as a vector of R^nq (RK4, rbd/scene/Integrators.h):
//   configurationTangentMap(q) P (nq × nv):  d(q ⊕ δ)/dδ at δ = 0 (q with unit quaternions);
//   configurationTangentProjection(y) N (nv × nq): the tangent δ at n(y) (y's quaternions
//     normalised, as the runtime reads them) of a change dy of y: n(y + dy) = n(y) ⊕ (N dy);
//     N P = 1 at a unit q;
//   configurationDerivativeJacobians(q, alpha): ∂/∂q (nq × nq, q as a vector of R^nq, quaternions
//     as given: not normalised) and ∂/∂alpha (nq × nv) of configurationDerivative(q, alpha).

#include <cmath>

#include <Eigen/Core>

#include <rbd/EulerIntegration.h>
#include <rbd/MultiBody.h>

namespace rbd
{

namespace detail
{

/// sin θ/θ, (1 − cos θ)/θ², (θ − sin θ)/θ³ and the derivatives of the last two divided by θ.
template<typename T>
struct ExpCoefficients
{
  T s, a, b, daOverTheta, dbOverTheta;
};

/// The coefficients of ExpCoefficients at θ ≥ 0: Taylor series below 0.5 (10 terms: error below
/// 1e-21 relative there), closed forms above (cancellation error ≤ ~100 ulps of the coefficient at
/// θ = 0.5, and the coefficients multiply powers of ω that shrink with θ).
template<typename T>
ExpCoefficients<T> expCoefficients(T theta)
{
  using std::cos;
  using std::sin;
  ExpCoefficients<T> c;
  const T t2 = theta * theta;
  if(theta < T(0.5))
  {
    // s = Σ (−θ²)^k/(2k+1)!, a = Σ (−θ²)^k/(2k+2)!, b = Σ (−θ²)^k/(2k+3)!,
    // a'/θ = Σ_{k≥1} 2k (−1)^k θ^(2k−2)/(2k+2)!, b'/θ = Σ_{k≥1} 2k (−1)^k θ^(2k−2)/(2k+3)!
    T ts = T(1), ta = T(1) / T(2), tb = T(1) / T(6);
    c.s = ts, c.a = ta, c.b = tb, c.daOverTheta = T(0), c.dbOverTheta = T(0);
    T ua = T(1) / T(2), ub = T(1) / T(6); // (−1)^k θ^(2k−2) / (2k+2)! and /(2k+3)!, times θ² at k
    for(int k = 1; k <= 10; ++k)
    {
      const T k2 = T(2 * k);
      ts *= -t2 / (k2 * (k2 + T(1)));
      ta *= -t2 / ((k2 + T(1)) * (k2 + T(2)));
      tb *= -t2 / ((k2 + T(2)) * (k2 + T(3)));
      ua *= -T(1) / ((k2 + T(1)) * (k2 + T(2)));
      ub *= -T(1) / ((k2 + T(2)) * (k2 + T(3)));
      c.s += ts;
      c.a += ta;
      c.b += tb;
      c.daOverTheta += k2 * ua;
      c.dbOverTheta += k2 * ub;
      if(k < 10) ua *= t2, ub *= t2;
    }
    return c;
  }
  const T sn = sin(theta), h = sin(theta / T(2));
  const T omc = T(2) * h * h; // 1 − cos θ without cancellation
  c.s = sn / theta;
  c.a = omc / t2;
  c.b = (theta - sn) / (t2 * theta);
  c.daOverTheta = (theta * sn - T(2) * omc) / (t2 * t2);
  c.dbOverTheta = (omc * theta - T(3) * (theta - sn)) / (t2 * t2 * theta);
  return c;
}

template<typename T>
sva::Matrix3<T> hat(const sva::Vector3<T> & w)
{
  sva::Matrix3<T> m;
  m << T(0), -w.z(), w.y(), w.z(), T(0), -w.x(), -w.y(), w.x(), T(0);
  return m;
}

/// Exp(ω) (the usual rotation matrix, child to parent), 1 + s ω^ + a ω^².
template<typename T>
sva::Matrix3<T> so3Exp(const sva::Vector3<T> & w, const ExpCoefficients<T> & c)
{
  const sva::Matrix3<T> W = hat(w);
  return sva::Matrix3<T>::Identity() + c.s * W + c.a * W * W;
}

/// Derivatives of one joint's q ⊕ w in the tangent spaces (top-left dof × dof blocks of dq, dw).
template<typename T>
void integrateJointDerivatives(JointType::Type type, const T * w, Eigen::Matrix<T, 6, 6> & dq,
                               Eigen::Matrix<T, 6, 6> & dw)
{
  using std::cos;
  using std::sin;
  using Vec3 = sva::Vector3<T>;
  using Mat3 = sva::Matrix3<T>;
  dq.setIdentity();
  dw.setIdentity();
  switch(type)
  {
    case JointType::Rev:
    case JointType::Prism:
    case JointType::Cylindrical:
    case JointType::Fixed:
      break;
    case JointType::Spherical:
    case JointType::Free:
    {
      const Vec3 om(w[0], w[1], w[2]);
      const ExpCoefficients<T> c = expCoefficients(om.norm());
      const Mat3 W = hat(om), W2 = W * W;
      const Mat3 Et = so3Exp(om, c).transpose();
      const Mat3 Jr = Mat3::Identity() - c.a * W + c.b * W2;
      dq.template topLeftCorner<3, 3>() = Et;
      dw.template topLeftCorner<3, 3>() = Jr;
      if(type == JointType::Free)
      {
        const Vec3 v(w[3], w[4], w[5]);
        const Vec3 wxv = om.cross(v), wxwxv = om.cross(wxv);
        const Vec3 p = v + c.a * wxv + c.b * wxwxv; // V(ω) v
        const Mat3 dVv = -c.a * hat(v) + c.daOverTheta * wxv * om.transpose()
                         + c.b * (om.dot(v) * Mat3::Identity() + om * v.transpose() - T(2) * v * om.transpose())
                         + c.dbOverTheta * wxwxv * om.transpose();
        dq.template bottomLeftCorner<3, 3>() = -Et * hat(p);
        dq.template bottomRightCorner<3, 3>() = Et;
        dw.template bottomLeftCorner<3, 3>() = Et * dVv;
        dw.template bottomRightCorner<3, 3>() = Jr;
      }
      break;
    }
    case JointType::Planar:
    {
      // V2(φ) = [s −c; c s] with c = φ a(φ), V2'(φ) = [s' −c'; c' s']
      const T phi = w[0];
      const ExpCoefficients<T> c = expCoefficients(phi < T(0) ? -phi : phi);
      // s(φ) = sin φ/φ (even), s'(φ) = φ (s'/φ) with s'/φ = −(a + ... ): s = 1 − φ² b ⇒ s' = −2φ b − φ³ b'
      // c(φ) = φ a (odd), c'(φ) = a + φ a'(φ) = a + φ² (a'/φ)
      const T s = c.s, cc = phi * c.a;
      const T ds = -phi * (T(2) * c.b + phi * phi * c.dbOverTheta), dc = c.a + phi * phi * c.daOverTheta;
      const T vu = w[1], vw = w[2];
      const T cp = cos(phi), sp = sin(phi);
      // R2(−φ) = [cp sp; −sp cp]
      auto rotBack = [&](T x, T y, T & ox, T & oy) {
        ox = cp * x + sp * y;
        oy = -sp * x + cp * y;
      };
      // Dq: [1 0; R2(−φ) J t, R2(−φ)], t = V2(φ) v, J t = (−t_w, t_u)
      const T tu = s * vu - cc * vw, tw = cc * vu + s * vw;
      rotBack(-tw, tu, dq(1, 0), dq(2, 0));
      dq(1, 1) = cp, dq(1, 2) = sp, dq(2, 1) = -sp, dq(2, 2) = cp;
      // Dw: [1 0; R2(−φ) V2'(φ) v, R2(−φ) V2(φ)]
      rotBack(ds * vu - dc * vw, dc * vu + ds * vw, dw(1, 0), dw(2, 0));
      rotBack(s, cc, dw(1, 1), dw(2, 1));
      rotBack(-cc, s, dw(1, 2), dw(2, 2));
      break;
    }
  }
}

/// log of a unit quaternion [w x y z] (shortest rotation: the sign is chosen with w ≥ 0): ω with
/// exp(ω) = ±quat, |ω| ≤ π.
template<typename T>
sva::Vector3<T> quaternionLog(T qw, const sva::Vector3<T> & qv)
{
  using std::atan2;
  const T sgn = qw < T(0) ? T(-1) : T(1);
  const T w = sgn * qw;
  const sva::Vector3<T> v = sgn * qv;
  const T n = v.norm();
  // θ = 2 atan2(n, w), ω = θ v/n; for n ≤ 1e-2 w: 2 atan(x)/x (x = n/w) by its series (x^10 < 1e-20)
  if(n < T(1e-2) * w)
  {
    const T x2 = n * n / (w * w);
    const T f = T(1) - x2 / T(3) + x2 * x2 / T(5) - x2 * x2 * x2 / T(7) + x2 * x2 * x2 * x2 / T(9);
    return T(2) * f / w * v;
  }
  return T(2) * atan2(n, w) / n * v;
}

} // namespace detail

/// ∂q⁺/∂q and ∂q⁺/∂w of q⁺ = q ⊕ w, nv × nv, block diagonal (see the top of this file).
template<typename T>
struct IntegrationDerivativesTpl
{
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> dq, dw;
};
using IntegrationDerivatives = IntegrationDerivativesTpl<double>;

/// Derivatives of integrateConfiguration(mb, q, w) with respect to q (tangent) and w; they depend
/// on w only (q's quaternions unit), so q is not an argument. w: size nrDof.
template<typename T>
IntegrationDerivativesTpl<T> integrateConfigurationDerivatives(const MultiBodyTpl<T> & mb,
                                                               const Eigen::Matrix<T, Eigen::Dynamic, 1> & w)
{
  const int nv = mb.nrDof();
  IntegrationDerivativesTpl<T> d;
  d.dq.setZero(nv, nv);
  d.dw.setZero(nv, nv);
  Eigen::Matrix<T, 6, 6> bq, bw;
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int n = mb.joint(i).dof(), v = mb.jointPosInDof(i);
    if(n == 0) continue;
    detail::integrateJointDerivatives(mb.joint(i).type(), w.data() + v, bq, bw);
    d.dq.block(v, v, n, n) = bq.topLeftCorner(n, n);
    d.dw.block(v, v, n, n) = bw.topLeftCorner(n, n);
  }
  return d;
}

/// d (size nrDof) such that q0 ⊕ d = q1 (integrateConfiguration), the inverse of ⊕: per joint
/// q1 − q0 (Rev, Prism, Cylindrical), the SO(3) log of quat0⁻¹ quat1 (Spherical; rotation angle
/// ≤ π), the SE(3) log of (R0, r0)⁻¹ (R1, r1) (Free: [ω; V(ω)⁻¹ R0ᵀ (r1 − r0)]), the SE(2) log
/// (Planar: [φ; V2(φ)⁻¹ (R2(φ) z1 − z0)], φ = θ1 − θ0 not wrapped, z = [x y]). Quaternions are
/// normalised first. Exact (to rounding) for rotations below π, so that the tests compare
/// configurations in the tangent space.
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> configurationDifference(const MultiBodyTpl<T> & mb,
                                                            const Eigen::Matrix<T, Eigen::Dynamic, 1> & q0,
                                                            const Eigen::Matrix<T, Eigen::Dynamic, 1> & q1)
{
  using std::cos;
  using std::sin;
  using Vec3 = sva::Vector3<T>;
  using Mat3 = sva::Matrix3<T>;
  Eigen::Matrix<T, Eigen::Dynamic, 1> d = Eigen::Matrix<T, Eigen::Dynamic, 1>::Zero(mb.nrDof());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const T * a = q0.data() + mb.jointPosInParam(i);
    const T * b = q1.data() + mb.jointPosInParam(i);
    T * out = d.data() + mb.jointPosInDof(i);
    switch(mb.joint(i).type())
    {
      case JointType::Rev:
      case JointType::Prism:
      case JointType::Cylindrical:
        for(int c = 0; c < mb.joint(i).dof(); ++c) out[c] = b[c] - a[c];
        break;
      case JointType::Fixed:
        break;
      case JointType::Planar:
      {
        // v = V2(φ)^-1 (R2(φ) z1 − z0), φ = θ1 − θ0, z = [x y] (successor axes)
        const T phi = b[0] - a[0];
        const T cp = cos(phi), sp = sin(phi);
        const T pu = cp * b[1] - sp * b[2] - a[1], pw = sp * b[1] + cp * b[2] - a[2];
        const detail::ExpCoefficients<T> c = detail::expCoefficients(phi < T(0) ? -phi : phi);
        const T s = c.s, cc = phi * c.a, det = s * s + cc * cc; // V2 = [s −c; c s]
        out[0] = phi;
        out[1] = (s * pu + cc * pw) / det;
        out[2] = (-cc * pu + s * pw) / det;
        break;
      }
      case JointType::Spherical:
      case JointType::Free:
      {
        Eigen::Quaternion<T> qa(a[0], a[1], a[2], a[3]), qb(b[0], b[1], b[2], b[3]);
        qa.normalize();
        qb.normalize();
        const Eigen::Quaternion<T> rel = qa.conjugate() * qb;
        const Vec3 om = detail::quaternionLog(rel.w(), Vec3(rel.vec()));
        Vec3::Map(out) = om;
        if(mb.joint(i).type() == JointType::Free)
        {
          // V(ω)⁻¹ = 1 − ω^/2 + e ω^², e = (1 − θ sin θ / (2 (1 − cos θ)))/θ² (series below 1e-2)
          const T theta = om.norm();
          T e;
          if(theta < T(1e-2))
          {
            const T t2 = theta * theta;
            e = T(1) / T(12) + t2 / T(720) + t2 * t2 / T(30240) + t2 * t2 * t2 / T(1209600);
          }
          else
          {
            const T h = sin(theta / T(2));
            e = (T(1) - theta * sin(theta) / (T(4) * h * h)) / (theta * theta);
          }
          const Mat3 W = detail::hat(om);
          const Mat3 Vinv = Mat3::Identity() - T(0.5) * W + e * W * W;
          const Vec3 dr(b[4] - a[4], b[5] - a[5], b[6] - a[6]);
          Vec3::Map(out + 3) = Vinv * (qa.toRotationMatrix().transpose() * dr);
        }
        break;
      }
    }
  }
  return d;
}

/// P = d(q ⊕ δ)/dδ at δ = 0, nq × nv (q with unit quaternions): quaternion rows
/// ½ [−xyzᵀ; w 1 + xyz^], free translation rows R(quat), planar [1 0; −J z 1] (z = [x y],
/// J = [0 −1; 1 0]), else 1.
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> configurationTangentMap(const MultiBodyTpl<T> & mb,
                                                                         const Eigen::Matrix<T, Eigen::Dynamic, 1> & q);

/// N (nv × nq): the tangent at n(y) of a change dy of y (see the top of this file): quaternion
/// columns (2/|y|) [−xyz, w 1 − xyz^] with [w xyz] = y/|y|, free translation R(n(y))ᵀ, planar
/// [1 0; J z 1], else 1.
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> configurationTangentProjection(
    const MultiBodyTpl<T> & mb, const Eigen::Matrix<T, Eigen::Dynamic, 1> & y);

/// ∂/∂q (nq × nq) and ∂/∂alpha (nq × nv) of configurationDerivative(mb, q, alpha).
template<typename T>
struct ConfigurationDerivativeJacobiansTpl
{
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> dq, dalpha;
};
template<typename T>
ConfigurationDerivativeJacobiansTpl<T> configurationDerivativeJacobians(const MultiBodyTpl<T> & mb,
                                                                        const Eigen::Matrix<T, Eigen::Dynamic, 1> & q,
                                                                        const Eigen::Matrix<T, Eigen::Dynamic, 1> & alpha);

namespace detail
{
/// ½ [−bᵀ; a 1 + b^] for the quaternion [a b] (4 × 3): d(quat ⊗ [0; δ])/dδ / ... halved.
template<typename T>
Eigen::Matrix<T, 4, 3> quaternionRightProductHalf(const T * q)
{
  Eigen::Matrix<T, 4, 3> m;
  m << -q[1], -q[2], -q[3], q[0], -q[3], q[2], q[3], q[0], -q[1], -q[2], q[1], q[0];
  return T(0.5) * m;
}
/// (2/|y|) [−b, a 1 − b^] with [a b] = y/|y| (3 × 4).
template<typename T>
Eigen::Matrix<T, 3, 4> quaternionTangentProjection(const T * y)
{
  using std::sqrt;
  const T n = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
  const T a = y[0] / n, x = y[1] / n, yy = y[2] / n, z = y[3] / n, k = T(2) / n;
  Eigen::Matrix<T, 3, 4> m;
  m << -x, a, z, -yy, -yy, -z, a, x, -z, yy, -x, a;
  return k * m;
}
} // namespace detail

template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> configurationTangentMap(const MultiBodyTpl<T> & mb,
                                                                         const Eigen::Matrix<T, Eigen::Dynamic, 1> & q)
{
  using std::cos;
  using std::sin;
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> P =
      Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>::Zero(mb.nrParams(), mb.nrDof());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int qi = mb.jointPosInParam(i), vi = mb.jointPosInDof(i);
    const T * x = q.data() + qi;
    switch(mb.joint(i).type())
    {
      case JointType::Spherical:
      case JointType::Free:
      {
        Eigen::Quaternion<T> quat(x[0], x[1], x[2], x[3]);
        quat.normalize();
        const T u[4] = {quat.w(), quat.x(), quat.y(), quat.z()};
        P.template block<4, 3>(qi, vi) = detail::quaternionRightProductHalf(u);
        if(mb.joint(i).type() == JointType::Free) P.template block<3, 3>(qi + 4, vi + 3) = quat.toRotationMatrix();
        break;
      }
      case JointType::Planar:
        // z ⊕ δ = z + δv − δθ J z: [1 0; −J z 1], −J z = (y, −x)
        P(qi, vi) = T(1);
        P(qi + 1, vi) = x[2], P(qi + 2, vi) = -x[1];
        P(qi + 1, vi + 1) = T(1), P(qi + 2, vi + 2) = T(1);
        break;
      default:
        for(int c = 0; c < mb.joint(i).dof(); ++c) P(qi + c, vi + c) = T(1);
    }
  }
  return P;
}

template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> configurationTangentProjection(
    const MultiBodyTpl<T> & mb, const Eigen::Matrix<T, Eigen::Dynamic, 1> & y)
{
  using std::cos;
  using std::sin;
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> N =
      Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>::Zero(mb.nrDof(), mb.nrParams());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int qi = mb.jointPosInParam(i), vi = mb.jointPosInDof(i);
    const T * x = y.data() + qi;
    switch(mb.joint(i).type())
    {
      case JointType::Spherical:
      case JointType::Free:
        N.template block<3, 4>(vi, qi) = detail::quaternionTangentProjection(x);
        if(mb.joint(i).type() == JointType::Free)
          N.template block<3, 3>(vi + 3, qi + 4) =
              Eigen::Quaternion<T>(x[0], x[1], x[2], x[3]).normalized().toRotationMatrix().transpose();
        break;
      case JointType::Planar:
        // the inverse of [1 0; −J z 1]: [1 0; J z 1], J z = (−y, x)
        N(vi, qi) = T(1);
        N(vi + 1, qi) = -x[2], N(vi + 2, qi) = x[1];
        N(vi + 1, qi + 1) = T(1), N(vi + 2, qi + 2) = T(1);
        break;
      default:
        for(int c = 0; c < mb.joint(i).dof(); ++c) N(vi + c, qi + c) = T(1);
    }
  }
  return N;
}

template<typename T>
ConfigurationDerivativeJacobiansTpl<T> configurationDerivativeJacobians(const MultiBodyTpl<T> & mb,
                                                                        const Eigen::Matrix<T, Eigen::Dynamic, 1> & q,
                                                                        const Eigen::Matrix<T, Eigen::Dynamic, 1> & alpha)
{
  using std::cos;
  using std::sin;
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  ConfigurationDerivativeJacobiansTpl<T> J;
  J.dq = Mat::Zero(mb.nrParams(), mb.nrParams());
  J.dalpha = Mat::Zero(mb.nrParams(), mb.nrDof());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const int qi = mb.jointPosInParam(i), vi = mb.jointPosInDof(i);
    const T * x = q.data() + qi;
    const T * a = alpha.data() + vi;
    switch(mb.joint(i).type())
    {
      case JointType::Spherical:
      case JointType::Free:
      {
        // quat_dot = ½ quat ⊗ [0; ω] (quat as given): ∂/∂quat = ½ [0 −ωᵀ; ω −ω^], ∂/∂ω = ½ [−bᵀ; a 1 + b^]
        const sva::Vector3<T> om(a[0], a[1], a[2]);
        Eigen::Matrix<T, 4, 4> C;
        C(0, 0) = T(0);
        C.template block<1, 3>(0, 1) = -om.transpose();
        C.template block<3, 1>(1, 0) = om;
        C.template block<3, 3>(1, 1) = -detail::hat(om);
        J.dq.template block<4, 4>(qi, qi) = T(0.5) * C;
        J.dalpha.template block<4, 3>(qi, vi) = detail::quaternionRightProductHalf(x);
        if(mb.joint(i).type() == JointType::Free)
        {
          // r_dot = R(n(quat)) v: ∂/∂quat = −R v^ N_quat, ∂/∂v = R
          const sva::Matrix3<T> R = Eigen::Quaternion<T>(x[0], x[1], x[2], x[3]).normalized().toRotationMatrix();
          const sva::Vector3<T> v(a[3], a[4], a[5]);
          J.dq.template block<3, 4>(qi + 4, qi) = -R * detail::hat(v) * detail::quaternionTangentProjection(x);
          J.dalpha.template block<3, 3>(qi + 4, vi + 3) = R;
        }
        break;
      }
      case JointType::Planar:
        // f = [θ̇; v_u + θ̇ y; v_w − θ̇ x]
        J.dalpha(qi, vi) = T(1);
        J.dalpha(qi + 1, vi) = x[2], J.dalpha(qi + 2, vi) = -x[1];
        J.dalpha(qi + 1, vi + 1) = T(1), J.dalpha(qi + 2, vi + 2) = T(1);
        J.dq(qi + 1, qi + 2) = a[0];
        J.dq(qi + 2, qi + 1) = -a[0];
        break;
      default:
        for(int k = 0; k < mb.joint(i).dof(); ++k) J.dalpha(qi + k, vi + k) = T(1);
    }
  }
  return J;
}

extern template IntegrationDerivativesTpl<double> integrateConfigurationDerivatives(const MultiBodyTpl<double> &,
                                                                                    const Eigen::VectorXd &);
extern template IntegrationDerivativesTpl<long double> integrateConfigurationDerivatives(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
extern template Eigen::VectorXd configurationDifference(const MultiBodyTpl<double> &, const Eigen::VectorXd &,
                                                        const Eigen::VectorXd &);
extern template Eigen::Matrix<long double, Eigen::Dynamic, 1> configurationDifference(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
extern template Eigen::MatrixXd configurationTangentMap(const MultiBodyTpl<double> &, const Eigen::VectorXd &);
extern template Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> configurationTangentMap(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
extern template Eigen::MatrixXd configurationTangentProjection(const MultiBodyTpl<double> &, const Eigen::VectorXd &);
extern template Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> configurationTangentProjection(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
extern template ConfigurationDerivativeJacobiansTpl<double> configurationDerivativeJacobians(
    const MultiBodyTpl<double> &, const Eigen::VectorXd &, const Eigen::VectorXd &);
extern template ConfigurationDerivativeJacobiansTpl<long double> configurationDerivativeJacobians(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);

} // namespace rbd
