#pragma once
// Analytic derivatives of inverse dynamics, d tau / d q and d tau / d alpha (the idea of
// Carpentier & Mansard, RSS 2018: one forward pass, one backward pass of composite quantities, a
// 6-vector dot product per pair of dofs on a common path), derived in world coordinates.
//
// Tangent convention: d/dq_m is the derivative along q ⊕ ε e_m (rbd::integrateConfiguration), i.e.
// joint j of dof m moves its successor by the motion S_m: for free and spherical joints [δω; δv]
// in the child frame, the coordinates of alpha. Size nrDof x nrDof for both matrices.
//
// In world coordinates (origin and axes of the world), with s_k the motion subspace column of dof k,
// a_0 = [0; gravity], g_l = I_l a_l + v_l x* I_l v_l the inertial force of body l, G_i and F_i the
// sums over the subtree of i of g_l and g_l - fext_l, and B_l(x) = I_l (x × v_l) + x ×* I_l v_l +
// v_l ×* I_l x (summed: Bc_i; Ic_i the composite inertia):
//   moving dof m of joint j by ε moves the subtree of j rigidly by ε s_m, except that the velocity
//   and acceleration the subtree inherits (w, a_w: those of λ(j), or of j for a backward joint
//   whose S is carried by its predecessor) do not move with it. Hence, for i in the subtree of j,
//     dF_i/dq_m     = s_m ×* G_i + Ic_i (a_w × s_m + (s_m × w) × w) + Bc_i (w × s_m)
//     dF_i/dalpha_m = Ic_i (ṡ_m + w × s_m) + Bc_i s_m,   ṡ_m = v_carrier × s_m
//   for i a strict ancestor of j, dF_i = dF_j; elsewhere dF_i = 0; and
//     d tau_k/dq_m = s_k . dF_i/dq_m + (s_m × s_k) . F_i   (the second term when s_k moves with j)
//     d tau_k/dalpha_m = s_k . dF_i/dalpha_m

#include <vector>

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

template<typename T>
class InverseDynamicsDerivativesTpl
{
public:
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  using Vector6 = Eigen::Matrix<T, 6, 1>;
  using Matrix6 = Eigen::Matrix<T, 6, 6>;

  InverseDynamicsDerivativesTpl() = default;
  explicit InverseDynamicsDerivativesTpl(const MultiBodyTpl<T> & mb);

  /// Use alphaD, gravity, force and the outputs of forwardKinematics and forwardVelocity. Fill
  /// dtauDq(), dtauDalpha() and tau() (the inverse dynamics at the same state).
  void inverseDynamicsDerivatives(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    compute(mb, mbc, mbc.alphaD);
  }
  /// Checked variant: throws std::domain_error on a size mismatch.
  void sInverseDynamicsDerivatives(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

  /// The same at the accelerations alphaD (per joint) instead of mbc.alphaD.
  void compute(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
               const std::vector<std::vector<T>> & alphaD);

  const MatrixX & dtauDq() const { return dtauDq_; }
  const MatrixX & dtauDalpha() const { return dtauDalpha_; }
  const VectorX & tau() const { return tau_; }

private:
  /// World-coordinate quantities of the forward pass (per body) and of the backward pass (per subtree).
  void worldPasses(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                   const std::vector<std::vector<T>> & alphaD);
  /// Columns m of dtauDq and dtauDalpha for the dofs of joint j.
  void jointColumns(const MultiBodyTpl<T> & mb, int j);

  std::vector<Vector6> v_, a_;                 ///< body velocity, acceleration (with a_0 = [0; gravity])
  std::vector<Eigen::Matrix<T, 6, Eigen::Dynamic>> s_; ///< motion subspace
  std::vector<Vector6> G_, F_;                 ///< subtree sums of g_l and g_l - fext_l
  std::vector<Matrix6> Ic_, Bc_;               ///< subtree sums of I_l and B_l
  std::vector<std::vector<int>> subtree_;      ///< bodies of the subtree of i (i first)
  Vector6 a_0_ = Vector6::Zero();              ///< [0; gravity]
  MatrixX dtauDq_, dtauDalpha_;
  VectorX tau_;
};

using InverseDynamicsDerivatives = InverseDynamicsDerivativesTpl<double>;

// ---------------------------------------------------------------------------------------------

template<typename T>
InverseDynamicsDerivativesTpl<T>::InverseDynamicsDerivativesTpl(const MultiBodyTpl<T> & mb)
{
  const auto n = static_cast<std::size_t>(mb.nrBodies());
  v_.assign(n, Vector6::Zero());
  a_ = G_ = F_ = v_;
  s_.resize(n);
  Ic_.assign(n, Matrix6::Zero());
  Bc_ = Ic_;
  // subtree of i: i, then (parents precede children) every later body whose parent is in it
  subtree_.assign(n, {});
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    std::vector<bool> in(n, false);
    in[static_cast<std::size_t>(i)] = true;
    subtree_[static_cast<std::size_t>(i)].push_back(i);
    for(int l = i + 1; l < mb.nrBodies(); ++l)
      if(mb.parent(l) >= 0 && in[static_cast<std::size_t>(mb.parent(l))])
      {
        in[static_cast<std::size_t>(l)] = true;
        subtree_[static_cast<std::size_t>(i)].push_back(l);
      }
  }
  dtauDq_ = MatrixX::Zero(mb.nrDof(), mb.nrDof());
  dtauDalpha_ = dtauDq_;
  tau_ = VectorX::Zero(mb.nrDof());
}

template<typename T>
void InverseDynamicsDerivativesTpl<T>::compute(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                                const std::vector<std::vector<T>> & alphaD)
{
  if(subtree_.size() != static_cast<std::size_t>(mb.nrBodies())) *this = InverseDynamicsDerivativesTpl(mb);
  worldPasses(mb, mbc, alphaD);
  dtauDq_.setZero(mb.nrDof(), mb.nrDof());
  dtauDalpha_.setZero(mb.nrDof(), mb.nrDof());
  for(int j = 0; j < mb.nrJoints(); ++j) jointColumns(mb, j);
}

template<typename T>
void InverseDynamicsDerivativesTpl<T>::worldPasses(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                                   const std::vector<std::vector<T>> & alphaD)
{
  const sva::MotionVec<T> a_0(sva::Vector3<T>::Zero(), mbc.gravity);
  a_0_ = a_0.vector();
  std::vector<sva::MotionVec<T>> aB(static_cast<std::size_t>(mb.nrBodies()));
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const int p = mb.parent(i);
    const auto & X_0_i = mbc.bodyPosW[k];
    const auto & S = mbc.motionSubspace[k];
    const auto & v_i = mbc.bodyVelB[k];
    // a_i = X_p_i a_p + S alphaD + v_i x vJ   (body coordinates, a_0 = [0; gravity])
    Vector6 aJ = Vector6::Zero();
    for(Eigen::Index c = 0; c < S.cols(); ++c) aJ += S.col(c) * alphaD[k][static_cast<std::size_t>(c)];
    aB[k] = mbc.parentToSon[k] * (p < 0 ? a_0 : aB[static_cast<std::size_t>(p)]) + sva::MotionVec<T>(aJ) +
            v_i.cross(mbc.jointVelocity[k]);
    // world coordinates: motions X_0_i^-1 m, forces and inertias X_0_i^T (.) X_0_i
    v_[k] = X_0_i.invMul(v_i).vector();
    a_[k] = X_0_i.invMul(aB[k]).vector();
    s_[k] = X_0_i.inv().mul(S);
    const sva::RBInertia<T> I = X_0_i.transMul(mb.body(i).inertia());
    const Matrix6 I6 = I.matrix();
    const sva::MotionVec<T> v(v_[k]);
    const sva::ForceVec<T> h = I * v;
    G_[k] = (I * sva::MotionVec<T>(a_[k]) + v.crossDual(h)).vector();
    F_[k] = G_[k] - mbc.force[k].vector();
    Ic_[k] = I6;
    // B(x) = I (x × v) + x ×* (I v) + v ×* (I x)
    Matrix6 hBar = Matrix6::Zero(); // x ×* h = -hBar x, h = [n; f]: hBar = [n^ f^; f^ 0]
    hBar.template topLeftCorner<3, 3>() = sva::vector3ToCrossMatrix(h.couple());
    hBar.template topRightCorner<3, 3>() = sva::vector3ToCrossMatrix(h.force());
    hBar.template bottomLeftCorner<3, 3>() = sva::vector3ToCrossMatrix(h.force());
    Bc_[k] = -I6 * sva::vector6ToCrossMatrix(v) - hBar + sva::vector6ToCrossDualMatrix(v) * I6;
  }
  // subtree sums, leaves first
  for(int i = mb.nrJoints() - 1; i >= 0; --i)
  {
    const int p = mb.parent(i);
    if(p < 0) continue;
    const auto k = static_cast<std::size_t>(i), pk = static_cast<std::size_t>(p);
    G_[pk] += G_[k];
    F_[pk] += F_[k];
    Ic_[pk] += Ic_[k];
    Bc_[pk] += Bc_[k];
  }
  // tau_k = s_k . F_i
  for(int i = 0; i < mb.nrJoints(); ++i)
    tau_.segment(mb.jointPosInDof(i), mb.joint(i).dof()).noalias() =
        s_[static_cast<std::size_t>(i)].transpose() * F_[static_cast<std::size_t>(i)];
}

template<typename T>
void InverseDynamicsDerivativesTpl<T>::jointColumns(const MultiBodyTpl<T> & mb, int j)
{
  const auto jk = static_cast<std::size_t>(j);
  const int p = mb.parent(j);
  const bool forward = mb.joint(j).forward();
  const Vector6 zero = Vector6::Zero();
  const Vector6 & v_p = p < 0 ? zero : v_[static_cast<std::size_t>(p)];
  // the velocity and acceleration the subtree of j inherits (not carried by the motion of dof m)
  const Vector6 & a_p = p < 0 ? a_0_ : a_[static_cast<std::size_t>(p)];
  const Vector6 & w = forward ? v_p : v_[jk];
  const Vector6 & a_w = forward ? a_p : a_[jk];
  const Vector6 & v_carrier = forward ? v_[jk] : v_p;
  auto cross = [](const Vector6 & x, const Vector6 & y) {
    return sva::MotionVec<T>(x).cross(sva::MotionVec<T>(y)).vector();
  };
  auto crossDual = [](const Vector6 & x, const Vector6 & f) {
    return sva::MotionVec<T>(x).crossDual(sva::ForceVec<T>(f)).vector();
  };
  const std::vector<int> & sub = subtree_[jk];
  for(Eigen::Index c = 0; c < s_[jk].cols(); ++c)
  {
    const Eigen::Index m = mb.jointPosInDof(j) + c;
    const Vector6 s_m = s_[jk].col(c);
    // q direction: yv = w × s_m, ya = a_w × s_m + (s_m × w) × w
    const Vector6 yvQ = cross(w, s_m);
    const Vector6 yaQ = cross(a_w, s_m) + cross(cross(s_m, w), w);
    // alpha direction: yv = s_m, ya = ṡ_m + w × s_m
    const Vector6 yaA = cross(v_carrier, s_m) + cross(w, s_m);
    for(int i : sub)
    {
      const auto ik = static_cast<std::size_t>(i);
      const Vector6 dFq = crossDual(s_m, G_[ik]) + Ic_[ik] * yaQ + Bc_[ik] * yvQ;
      const Vector6 dFa = Ic_[ik] * yaA + Bc_[ik] * s_m;
      const bool carried = i != j || forward; // s_k moves with the subtree of j
      for(Eigen::Index r = 0; r < s_[ik].cols(); ++r)
      {
        const Vector6 s_k = s_[ik].col(r);
        const Eigen::Index k = mb.jointPosInDof(i) + r;
        dtauDq_(k, m) = s_k.dot(dFq) + (carried ? cross(s_m, s_k).dot(F_[ik]) : T(0));
        dtauDalpha_(k, m) = s_k.dot(dFa);
      }
      if(i != j) continue;
      // strict ancestors of j: dF_a = dF_j
      for(int a = p; a >= 0; a = mb.parent(a))
      {
        const auto ak = static_cast<std::size_t>(a);
        for(Eigen::Index r = 0; r < s_[ak].cols(); ++r)
        {
          const Eigen::Index k = mb.jointPosInDof(a) + r;
          dtauDq_(k, m) = s_[ak].col(r).dot(dFq);
          dtauDalpha_(k, m) = s_[ak].col(r).dot(dFa);
        }
      }
    }
  }
}

extern template class InverseDynamicsDerivativesTpl<double>;
extern template class InverseDynamicsDerivativesTpl<long double>;

} // namespace rbd
