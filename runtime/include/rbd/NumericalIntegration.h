#pragma once
// RBDyn's integration of one step with constant joint accelerations (its NumericalIntegration.h):
// the joint trajectory q(t), 0 ≤ t ≤ h, of alpha(t) = alpha + alphaD t, to an absolute precision
// `prec` on q, then alpha += alphaD h.
//   Rev, Prism, Cylindrical: q += alpha h + alphaD h²/2 (exact).
//   Spherical: quat' = quat ⊗ [0; ω(t)]/2, ω(t) = ω + ω̇ t (successor frame).
//   Free: the same rotation, and r' = R(quat(t)) v(t), v(t) = v + v̇ t.
//   Planar: θ(t) = θ + θ̇ t + θ̈ t²/2, p' = R2(θ(t)) [v_u v_w](t) with p = R2(θ) [x y] (the
//     successor origin in the predecessor plane; (x, y) in successor axes as the pose reads them).
// Each substep of length s applies the fourth-order Magnus step exp(s (ω_a + ω_b)/2 + s² ω_a × ω_b/12)
// to the rotation (exact for this ω(t) to O(s⁵)) and Simpson's rule to the translation; the number
// of substeps doubles from 1 until two successive results differ by less than prec (the error of
// the finer one is then about prec/15). eulerIntegration (EulerIntegration.h) is the one-exponential
// step q ⊕ (alpha h + alphaD h²/2) the scene integrators use, not this one (docs/RBDYN_DIFFERENCES.md).

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <rbd/Checks.h>
#include <rbd/MultiBodyConfig.h>

namespace rbd
{

namespace detail
{

/// exp(Ω) as a unit quaternion, Ω a rotation vector.
template<typename T>
Eigen::Quaternion<T> quaternionExp(const sva::Vector3<T> & Omega)
{
  using std::cos;
  const T theta = Omega.norm();
  const sva::Vector3<T> im = T(0.5) * sva::sinc(theta / T(2)) * Omega;
  return Eigen::Quaternion<T>(cos(theta / T(2)), im.x(), im.y(), im.z());
}

/// One Magnus step of length s for ω(t) linear from w_a to w_b: quat ⊗ exp(s (w_a + w_b)/2 + s² w_a × w_b/12).
template<typename T>
Eigen::Quaternion<T> magnusStep(const Eigen::Quaternion<T> & quat, const sva::Vector3<T> & w_a,
                                const sva::Vector3<T> & w_b, T s)
{
  return quat * quaternionExp<T>(sva::Vector3<T>(s * (w_a + w_b) / T(2) + s * s * w_a.cross(w_b) / T(12)));
}

/// q(h) of one joint with n substeps (q: params() values; alpha, alphaD: dof() values).
template<typename T>
std::vector<T> constantAccelerationStep(JointType::Type type, const std::vector<T> & q, const std::vector<T> & alpha,
                                        const std::vector<T> & alphaD, T h, int n)
{
  using Vec3 = sva::Vector3<T>;
  std::vector<T> out = q;
  const T s = h / T(n);
  auto w = [&](T t) { return Vec3(Vec3(alpha[0], alpha[1], alpha[2]) + t * Vec3(alphaD[0], alphaD[1], alphaD[2])); };
  auto v = [&](T t, int k) { return Vec3(Vec3(alpha[k], alpha[k + 1], alpha[k + 2]) + t * Vec3(alphaD[k], alphaD[k + 1], alphaD[k + 2])); };
  switch(type)
  {
    case JointType::Spherical:
    case JointType::Free:
    {
      Eigen::Quaternion<T> quat(q[0], q[1], q[2], q[3]);
      quat.normalize();
      Vec3 r = type == JointType::Free ? Vec3(q[4], q[5], q[6]) : Vec3::Zero();
      for(int k = 0; k < n; ++k)
      {
        const T t = s * T(k);
        const Eigen::Quaternion<T> mid = magnusStep(quat, w(t), w(t + s / T(2)), s / T(2));
        const Eigen::Quaternion<T> end = magnusStep(quat, w(t), w(t + s), s);
        if(type == JointType::Free) // Simpson: s/6 (R_a v_a + 4 R_m v_m + R_b v_b)
          r += s / T(6) * (quat * v(t, 3) + T(4) * (mid * v(t + s / T(2), 3)) + end * v(t + s, 3));
        quat = end;
      }
      quat.normalize();
      out = {quat.w(), quat.x(), quat.y(), quat.z()};
      if(type == JointType::Free) out.insert(out.end(), {r.x(), r.y(), r.z()});
      return out;
    }
    case JointType::Planar:
    {
      using std::cos;
      using std::sin;
      auto theta = [&](T t) { return q[0] + alpha[0] * t + alphaD[0] * t * t / T(2); };
      // R2(θ(t)) [v_u v_w](t)
      auto pd = [&](T t) {
        const T c = cos(theta(t)), sn = sin(theta(t)), vu = alpha[1] + alphaD[1] * t, vw = alpha[2] + alphaD[2] * t;
        return Eigen::Matrix<T, 2, 1>(c * vu - sn * vw, sn * vu + c * vw);
      };
      const T c0 = cos(q[0]), s0 = sin(q[0]);
      Eigen::Matrix<T, 2, 1> p(c0 * q[1] - s0 * q[2], s0 * q[1] + c0 * q[2]);
      for(int k = 0; k < n; ++k)
      {
        const T t = s * T(k);
        p += s / T(6) * (pd(t) + T(4) * pd(t + s / T(2)) + pd(t + s));
      }
      const T th = theta(h), c1 = cos(th), s1 = sin(th);
      return {th, c1 * p.x() + s1 * p.y(), -s1 * p.x() + c1 * p.y()}; // [x y] = R2(θ)ᵀ p
    }
    case JointType::Fixed:
      return out;
    default: // Rev, Prism, Cylindrical: exact
      for(std::size_t c = 0; c < out.size(); ++c) out[c] += alpha[c] * h + alphaD[c] * h * h / T(2);
      return out;
  }
}

} // namespace detail

/// Integrate joint configuration q over `step` with constant acceleration alphaD from velocity
/// alpha, to the absolute precision prec (RBDyn's jointIntegration).
template<typename T>
void jointIntegration(JointType::Type type, const std::vector<T> & alpha, const std::vector<T> & alphaD,
                      sva::detail::identity_t<T> step, std::vector<T> & q, sva::detail::identity_t<T> prec = T(1e-10))
{
  std::vector<T> coarse = detail::constantAccelerationStep(type, q, alpha, alphaD, step, 1);
  for(int n = 2; n <= (1 << 20); n *= 2)
  {
    std::vector<T> fine = detail::constantAccelerationStep(type, q, alpha, alphaD, step, n);
    T diff = T(0);
    for(std::size_t k = 0; k < fine.size(); ++k) diff = std::max(diff, T(std::abs(fine[k] - coarse[k])));
    coarse = std::move(fine);
    if(diff <= prec) break;
  }
  q = std::move(coarse);
}

/// Use alpha and alphaD. Fill q (jointIntegration of every joint) and alpha += alphaD step.
template<typename T>
void integration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc, sva::detail::identity_t<T> step,
                 sva::detail::identity_t<T> prec = T(1e-10))
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    jointIntegration(mb.joint(i).type(), mbc.alpha[k], mbc.alphaD[k], step, mbc.q[k], prec);
    for(std::size_t c = 0; c < mbc.alpha[k].size(); ++c) mbc.alpha[k][c] += mbc.alphaD[k][c] * step;
  }
}

/// Checked variant: std::domain_error when q, alpha or alphaD do not match the model.
template<typename T>
void sIntegration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc, sva::detail::identity_t<T> step,
                  sva::detail::identity_t<T> prec = T(1e-10))
{
  checkMatchQ(mb, mbc);
  checkMatchAlpha(mb, mbc);
  checkMatchAlphaD(mb, mbc);
  integration(mb, mbc, step, prec);
}

/// The rotation quat(step) of quat' = quat ⊗ [0; wi + wD t]/2 (RBDyn's SO3Integration): to the
/// precision max(absEps, relEps |Ω1|), Ω1 = (2 wi + wD step) step/2. The flag is true when that
/// precision was not reached (then, with breakOnWarning, qi is returned unchanged).
template<typename T>
std::pair<Eigen::Quaternion<T>, bool> SO3Integration(const Eigen::Quaternion<T> & qi, const sva::Vector3<T> & wi,
                                                     const sva::Vector3<T> & wD, sva::detail::identity_t<T> step,
                                                     sva::detail::identity_t<T> relEps = T(1e-12),
                                                     sva::detail::identity_t<T> absEps = std::numeric_limits<T>::epsilon(),
                                                     bool breakOnWarning = false)
{
  using std::max;
  const std::vector<T> q{qi.w(), qi.x(), qi.y(), qi.z()}, a{wi.x(), wi.y(), wi.z()}, d{wD.x(), wD.y(), wD.z()};
  const T prec = max(absEps, relEps * ((T(2) * wi + wD * step) * step / T(2)).norm());
  std::vector<T> coarse = detail::constantAccelerationStep(JointType::Spherical, q, a, d, step, 1);
  bool converged = false;
  for(int n = 2; n <= (1 << 16) && !converged; n *= 2)
  {
    std::vector<T> fine = detail::constantAccelerationStep(JointType::Spherical, q, a, d, step, n);
    T diff = T(0);
    for(std::size_t k = 0; k < 4; ++k) diff = max(diff, T(std::abs(fine[k] - coarse[k])));
    coarse = std::move(fine);
    converged = diff <= prec;
  }
  if(!converged && breakOnWarning) return {qi, true};
  return {Eigen::Quaternion<T>(coarse[0], coarse[1], coarse[2], coarse[3]), !converged};
}

extern template void integration<double>(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, double, double);
extern template void integration<long double>(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &,
                                              long double, long double);

} // namespace rbd
