// Generic evaluation of a scene (see rbd/scene/SceneDynamics.h), for double and long double.
#include "rbd/scene/SceneDynamics.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>

#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>
#include <rbd/Jacobian.h>
#include <rbd/Momentum.h>

namespace rbd::scene
{

namespace
{

/// Point coordinates in B of a point given in A, for X_A_B = (E, r): E (p - r).
template<class T>
Eigen::Matrix<T, 3, 1> pointInB(const sva::PTransform<T> & X_A_B, const Eigen::Matrix<T, 3, 1> & p_A)
{
  return X_A_B.rotation() * (p_A - X_A_B.translation());
}

/// World position of a body point: r + E^T p (bodyPosW = (E, r)).
template<class T>
Eigen::Matrix<T, 3, 1> pointInWorld(const sva::PTransform<T> & X_0_b, const Eigen::Matrix<T, 3, 1> & p_b)
{
  return X_0_b.translation() + X_0_b.rotation().transpose() * p_b;
}

void checkSize(Eigen::Index got, int expected, const char * what)
{
  if(got != expected)
    throw std::invalid_argument(std::string("scene dynamics: ") + what + " has size " + std::to_string(got) +
                                ", expected " + std::to_string(expected));
}

} // namespace

template<class T>
SceneDynamicsTpl<T>::SceneDynamicsTpl(const SceneRobot & robot, const Scene & scene)
: scene_(scene), mb_(robot.robot.mb.template cast<T>())
{
  const int nv = mb_.nrDof();
  checkSize(robot.damping.size(), nv, "damping");
  checkSize(robot.friction.size(), nv, "friction");
  checkSize(robot.armature.size(), nv, "armature");
  damping_ = robot.damping.template cast<T>();
  friction_ = robot.friction.template cast<T>();
  armature_ = robot.armature.template cast<T>();
  gravityW_ = scene.gravity ? Vector3(scene.gravity->template cast<T>()) : Vector3::Zero();
  for(const auto & [link, X] : robot.robot.bodyBaseTransforms) linkToBody_.emplace_back(link, X.template cast<T>());
  for(const auto & b : mb_.bodies()) totalMass_ += b.inertia().mass();
  contactBodies_ = robot.contactBodies;
  wrenchBodies_ = robot.wrenchBodies;
  if(contactBodies_.size() != scene.contacts.size() || wrenchBodies_.size() != scene.externalWrenches.size())
    throw std::invalid_argument("scene dynamics: the SceneRobot was not made from this scene");
  for(const ContactPoint & c : scene.contacts)
    contactPointsB_.push_back(pointInB(linkToBody(c.body), Vector3(c.point.template cast<T>())));
}

template<class T>
sva::PTransform<T> SceneDynamicsTpl<T>::linkToBody(const std::string & link) const
{
  for(const auto & [name, X] : linkToBody_)
    if(name == link) return X;
  bodyIndex(link); // throws std::out_of_range naming the link
  return sva::PTransform<T>::Identity();
}

template<class T>
MultiBodyConfigTpl<T> SceneDynamicsTpl<T>::kinematics(const VectorX & q, const VectorX & alpha) const
{
  checkSize(q.size(), nq(), "q");
  checkSize(alpha.size(), nv(), "alpha");
  MultiBodyConfigTpl<T> mbc(mb_);
  mbc.q = vectorToParam(mb_, q);
  mbc.alpha = vectorToDof(mb_, alpha);
  forwardKinematics(mb_, mbc);
  forwardVelocity(mb_, mbc);
  return mbc;
}

template<class T>
std::vector<typename SceneDynamicsTpl<T>::Vector3> SceneDynamicsTpl<T>::contactPositions(
    const MultiBodyConfigTpl<T> & mbc) const
{
  std::vector<Vector3> p;
  for(std::size_t c = 0; c < contactPointsB_.size(); ++c)
    p.push_back(pointInWorld(mbc.bodyPosW[static_cast<std::size_t>(contactBodies_[c])], contactPointsB_[c]));
  return p;
}

template<class T>
std::vector<typename SceneDynamicsTpl<T>::Vector3> SceneDynamicsTpl<T>::contactVelocities(
    const MultiBodyConfigTpl<T> & mbc) const
{
  // v_p = E^T (v_B + w_B x p_B): velocity of the body point in world coordinates
  std::vector<Vector3> v;
  for(std::size_t c = 0; c < contactPointsB_.size(); ++c)
  {
    const auto k = static_cast<std::size_t>(contactBodies_[c]);
    const sva::MotionVec<T> & v_B = mbc.bodyVelB[k];
    v.push_back(mbc.bodyPosW[k].rotation().transpose() * (v_B.linear() + v_B.angular().cross(contactPointsB_[c])));
  }
  return v;
}

template<class T>
std::vector<typename SceneDynamicsTpl<T>::Vector3> SceneDynamicsTpl<T>::contactForces(
    const MultiBodyConfigTpl<T> & mbc) const
{
  using std::sqrt;
  const ContactModel & m = scene_.contactModel;
  const T k = T(m.stiffness), d = T(m.damping), mu = T(m.mu), vs = T(m.slipVelocity), z0 = T(m.groundHeight);
  const std::vector<Vector3> p = contactPositions(mbc), v = contactVelocities(mbc);
  std::vector<Vector3> f(p.size(), Vector3::Zero());
  for(std::size_t c = 0; c < p.size(); ++c)
  {
    // d = z0 - p_z; fn = max(0, k d - c vn) if d > 0; ft = -mu fn vt / sqrt(|vt|^2 + vs^2)
    const T pen = z0 - p[c].z();
    if(!(pen > T(0))) continue;
    const T fn = k * pen - d * v[c].z();
    if(!(fn > T(0))) continue;
    const T vx = v[c].x(), vy = v[c].y();
    const T scale = -mu * fn / sqrt(vx * vx + vy * vy + vs * vs);
    f[c] = Vector3(scale * vx, scale * vy, fn);
  }
  return f;
}

template<class T>
std::vector<sva::ForceVec<T>> SceneDynamicsTpl<T>::bodyForces(const MultiBodyConfigTpl<T> & mbc,
                                                                const Wrenches & wrenches, bool contacts) const
{
  std::vector<sva::ForceVec<T>> force(static_cast<std::size_t>(mb_.nrBodies()), sva::ForceVec<T>::Zero());
  if(!wrenches.empty())
  {
    checkSize(static_cast<Eigen::Index>(wrenches.size()), static_cast<int>(wrenchBodies_.size()), "wrenches");
    for(std::size_t w = 0; w < wrenches.size(); ++w) force[static_cast<std::size_t>(wrenchBodies_[w])] += wrenches[w];
  }
  if(!contacts || contactPointsB_.empty()) return force;
  const std::vector<Vector3> p = contactPositions(mbc), f = contactForces(mbc);
  // force f at world point p: wrench [p x f; f] at the world origin
  for(std::size_t c = 0; c < p.size(); ++c)
    force[static_cast<std::size_t>(contactBodies_[c])] += sva::ForceVec<T>(p[c].cross(f[c]), f[c]);
  return force;
}

template<class T>
typename SceneDynamicsTpl<T>::VectorX SceneDynamicsTpl<T>::rneaBias(MultiBodyConfigTpl<T> & mbc,
                                                                    const std::vector<sva::ForceVec<T>> & force) const
{
  // mbc.gravity holds -g (the fictitious base acceleration of RNEA)
  mbc.gravity = -gravityW_;
  mbc.force = force;
  VectorX b = VectorX::Zero(nv());
  InverseDynamicsTpl<T> id(mb_);
  id.nonLinearEffects(mb_, mbc, b);
  return b;
}

template<class T>
typename SceneDynamicsTpl<T>::VectorX SceneDynamicsTpl<T>::generalizedBias(const VectorX & q, const VectorX & alpha,
                                                                           const Wrenches & wrenches) const
{
  using std::sqrt;
  MultiBodyConfigTpl<T> mbc = kinematics(q, alpha);
  const std::vector<sva::ForceVec<T>> force = bodyForces(mbc, wrenches);
  // b(q, alpha) - J_c^T F_c - J_w^T W; without velocity terms b = g(q) (RNEA at alpha = 0)
  VectorX bias;
  if(scene_.velocityTerms) bias = rneaBias(mbc, force);
  else
  {
    MultiBodyConfigTpl<T> still = kinematics(q, VectorX::Zero(nv()));
    bias = rneaBias(still, force);
  }
  // + D alpha + friction alpha / sqrt(alpha^2 + v_s^2)
  const T vs = T(scene_.frictionVelocity);
  for(int i = 0; i < nv(); ++i)
    bias[i] += damping_[i] * alpha[i] + friction_[i] * alpha[i] / sqrt(alpha[i] * alpha[i] + vs * vs);
  return bias;
}

template<class T>
typename SceneDynamicsTpl<T>::VectorX SceneDynamicsTpl<T>::gravityTorques(const VectorX & q) const
{
  MultiBodyConfigTpl<T> mbc = kinematics(q, VectorX::Zero(nv()));
  return rneaBias(mbc, std::vector<sva::ForceVec<T>>(static_cast<std::size_t>(mb_.nrBodies()), sva::ForceVec<T>::Zero()));
}

template<class T>
typename SceneDynamicsTpl<T>::MatrixX SceneDynamicsTpl<T>::massMatrix(const MultiBodyConfigTpl<T> & mbc) const
{
  ForwardDynamicsTpl<T> fd(mb_);
  fd.computeH(mb_, mbc);
  MatrixX H = fd.H();
  H.diagonal() += armature_;
  return H;
}

template<class T>
typename SceneDynamicsTpl<T>::MatrixX SceneDynamicsTpl<T>::massMatrix(const VectorX & q) const
{
  return massMatrix(kinematics(q, VectorX::Zero(nv())));
}

template<class T>
typename SceneDynamicsTpl<T>::VectorX SceneDynamicsTpl<T>::forwardDynamics(const VectorX & q, const VectorX & alpha,
                                                                           const VectorX & tau,
                                                                           const Wrenches & wrenches) const
{
  checkSize(tau.size(), nv(), "tau");
  // (H + A) alphaD = tau - bias; Cholesky, LDLT if H + A is not numerically positive definite
  const MatrixX M = massMatrix(q);
  const VectorX rhs = tau - generalizedBias(q, alpha, wrenches);
  Eigen::LLT<MatrixX> llt(M);
  VectorX a = llt.info() == Eigen::Success ? VectorX(llt.solve(rhs)) : VectorX(M.ldlt().solve(rhs));
  if(!a.allFinite()) throw std::runtime_error("scene forward dynamics: acceleration is not finite");
  return a;
}

template<class T>
typename SceneDynamicsTpl<T>::VectorX SceneDynamicsTpl<T>::inverseDynamics(const VectorX & q, const VectorX & alpha,
                                                                           const VectorX & alphaD,
                                                                           const Wrenches & wrenches) const
{
  checkSize(alphaD.size(), nv(), "alphaD");
  // tau = (H + A) alphaD + bias
  return massMatrix(q) * alphaD + generalizedBias(q, alpha, wrenches);
}

template<class T>
typename SceneDynamicsTpl<T>::IdDerivatives SceneDynamicsTpl<T>::inverseDynamicsDerivatives(
    const VectorX & q, const VectorX & alpha, const VectorX & alphaD, const Wrenches & wrenches) const
{
  using std::sqrt;
  checkSize(alphaD.size(), nv(), "alphaD");
  // rigid-body part: RNEA with the scene's gravity and the caller's wrenches (held constant); alpha = 0
  // inside it without velocity terms (then d/dalpha of that part is zero)
  MultiBodyConfigTpl<T> mbc = kinematics(q, scene_.velocityTerms ? alpha : VectorX::Zero(nv()));
  mbc.gravity = -gravityW_;
  mbc.force = bodyForces(mbc, wrenches, false);
  vectorToDof<T>(alphaD, mbc.alphaD);
  InverseDynamicsDerivativesTpl<T> d(mb_);
  d.inverseDynamicsDerivatives(mb_, mbc);
  IdDerivatives out{d.dtauDq(), d.dtauDalpha()};
  // + D alpha + friction alpha / sqrt(alpha^2 + v_s^2): d/dalpha_i = D_i + friction_i v_s^2 / (alpha_i^2 + v_s^2)^(3/2)
  const T vs2 = T(scene_.frictionVelocity) * T(scene_.frictionVelocity);
  for(int i = 0; i < nv(); ++i)
  {
    const T r = alpha[i] * alpha[i] + vs2;
    out.dtauDalpha(i, i) += damping_[i] + friction_[i] * vs2 / (r * sqrt(r));
  }
  // - J_c^T F_c(q, alpha): the contacts always see the true velocities
  if(!contactPointsB_.empty()) subtractContactDerivatives(kinematics(q, alpha), alpha, out);
  return out;
}

template<class T>
void SceneDynamicsTpl<T>::subtractContactDerivatives(const MultiBodyConfigTpl<T> & mbc, const VectorX & alpha,
                                                     IdDerivatives & out) const
{
  using std::sqrt;
  // tau_j -= u_j . f with u_j = v_j + w_j x p the point-velocity column of dof j (world) and f(p, pdot)
  // the contact force. A tangent step of dof k turns the axes of the joints at and after k's joint on
  // the path (j after k) and moves p by u_k:
  //   du_j/dq_k = w_k x u_j (j after k),  w_j x u_k (j before k);   dp/dq_k = u_k
  //   dpdot/dq_k = w_k x V_k + W_k x u_k,  V_k = sum_{j after k} alpha_j u_j,  W_k = sum_{j before k} alpha_j w_j
  //   dtau_j/dq_k -= du_j/dq_k . f + u_j . (F_p u_k + F_v dpdot/dq_k),  dtau_j/dalpha_k -= u_j . F_v u_k
  // F_p = df/dp, F_v = df/dpdot of the model of contactForces (zero where the point is not pushed).
  const ContactModel & m = scene_.contactModel;
  const T k = T(m.stiffness), c = T(m.damping), mu = T(m.mu), vs = T(m.slipVelocity);
  const std::vector<Vector3> f = contactForces(mbc), pd = contactVelocities(mbc);
  for(std::size_t ic = 0; ic < f.size(); ++ic)
  {
    if(!(f[ic].z() > T(0))) continue; // not pushed: F = 0 around this state
    const Vector3 & v = pd[ic];
    const T r = sqrt(v.x() * v.x() + v.y() * v.y() + vs * vs), fn = f[ic].z();
    // fn = k (z0 - p_z) - c pdot_z;  ft = -mu fn vt / r,  r = sqrt(|vt|^2 + vs^2)
    Vector3 Fpz(mu * k * v.x() / r, mu * k * v.y() / r, -k); // F_p = [0 0 Fpz]
    Matrix3 Fv = Matrix3::Zero();
    Fv.template topLeftCorner<2, 2>() = -mu * fn / r * Eigen::Matrix<T, 2, 2>::Identity() +
                                        mu * fn / (r * r * r) * v.template head<2>() * v.template head<2>().transpose();
    Fv.template block<2, 1>(0, 2) = mu * c / r * v.template head<2>();
    Fv(2, 2) = -c;
    // the columns of the path: [w_j; u_j] at the point, world axes; dof index and joint position on the path
    JacobianTpl<T> jac(mb_, mb_.body(contactBodies_[ic]).name(), contactPointsB_[ic]);
    const MatrixX J = jac.jacobian(mb_, mbc);
    std::vector<int> dof, pos;
    for(std::size_t pj = 0; pj < jac.jointsPath().size(); ++pj)
    {
      const int j = jac.jointsPath()[pj];
      for(int d = 0; d < mb_.joint(j).dof(); ++d)
      {
        dof.push_back(mb_.jointPosInDof(j) + d);
        pos.push_back(static_cast<int>(pj));
      }
    }
    const auto n = static_cast<int>(dof.size());
    auto w = [&](int a) { return Vector3(J.template block<3, 1>(0, a)); };
    auto u = [&](int a) { return Vector3(J.template block<3, 1>(3, a)); };
    for(int kk = 0; kk < n; ++kk)
    {
      Vector3 V = Vector3::Zero(), W = Vector3::Zero();
      for(int j = 0; j < n; ++j)
      {
        if(pos[j] >= pos[kk]) V += alpha[dof[j]] * u(j);
        else W += alpha[dof[j]] * w(j);
      }
      const Vector3 dpd = w(kk).cross(V) + W.cross(u(kk));
      const Vector3 df = Fpz * u(kk).z() + Fv * dpd, FvU = Fv * u(kk);
      for(int j = 0; j < n; ++j)
      {
        const T du = pos[j] >= pos[kk] ? w(kk).cross(u(j)).dot(f[ic]) : w(j).cross(u(kk)).dot(f[ic]);
        out.dtauDq(dof[j], dof[kk]) -= du + u(j).dot(df);
        out.dtauDalpha(dof[j], dof[kk]) -= u(j).dot(FvU);
      }
    }
  }
}

template<class T>
typename SceneDynamicsTpl<T>::FdDerivatives SceneDynamicsTpl<T>::forwardDynamicsDerivatives(
    const VectorX & q, const VectorX & alpha, const VectorX & tau, const Wrenches & wrenches) const
{
  FdDerivatives out;
  out.alphaD = forwardDynamics(q, alpha, tau, wrenches);
  const MatrixX M = massMatrix(q);
  const MatrixX identity = MatrixX::Identity(nv(), nv());
  Eigen::LLT<MatrixX> llt(M);
  out.Minv = llt.info() == Eigen::Success ? MatrixX(llt.solve(identity)) : MatrixX(M.ldlt().solve(identity));
  const IdDerivatives id = inverseDynamicsDerivatives(q, alpha, out.alphaD, wrenches);
  out.dalphaDDq = -out.Minv * id.dtauDq;
  out.dalphaDDalpha = -out.Minv * id.dtauDalpha;
  return out;
}

template<class T>
std::vector<typename SceneDynamicsTpl<T>::Vector3> SceneDynamicsTpl<T>::contactPositions(const VectorX & q) const
{
  return contactPositions(kinematics(q, VectorX::Zero(nv())));
}

template<class T>
std::vector<typename SceneDynamicsTpl<T>::Vector3> SceneDynamicsTpl<T>::contactVelocities(const VectorX & q,
                                                                                          const VectorX & alpha) const
{
  return contactVelocities(kinematics(q, alpha));
}

template<class T>
std::vector<typename SceneDynamicsTpl<T>::Vector3> SceneDynamicsTpl<T>::contactForces(const VectorX & q,
                                                                                      const VectorX & alpha) const
{
  return contactForces(kinematics(q, alpha));
}

template<class T>
T SceneDynamicsTpl<T>::kineticEnergy(const VectorX & q, const VectorX & alpha) const
{
  // 1/2 alpha^T (H + A) alpha
  return T(0.5) * alpha.dot(massMatrix(q) * alpha);
}

template<class T>
T SceneDynamicsTpl<T>::potentialEnergy(const VectorX & q) const
{
  // V = -g . sum_i m_i c_i
  const MultiBodyConfigTpl<T> mbc = kinematics(q, VectorX::Zero(nv()));
  Vector3 mc = Vector3::Zero();
  for(int i = 0; i < mb_.nrBodies(); ++i)
  {
    const auto & I = mb_.body(i).inertia();
    if(I.mass() == T(0)) continue;
    mc += I.mass() * pointInWorld(mbc.bodyPosW[static_cast<std::size_t>(i)], Vector3(I.momentum() / I.mass()));
  }
  return -gravityW_.dot(mc);
}

template<class T>
T SceneDynamicsTpl<T>::contactEnergy(const VectorX & q) const
{
  // sum 1/2 k d^2 over the points with d = z0 - p_z > 0
  T e = T(0);
  const T k = T(scene_.contactModel.stiffness), z0 = T(scene_.contactModel.groundHeight);
  for(const Vector3 & p : contactPositions(q))
  {
    const T pen = z0 - p.z();
    if(pen > T(0)) e += T(0.5) * k * pen * pen;
  }
  return e;
}

template<class T>
sva::PTransform<T> SceneDynamicsTpl<T>::pose(const VectorX & q, const std::string & link) const
{
  // X_0_link = X_link_body^-1 X_0_body
  const MultiBodyConfigTpl<T> mbc = kinematics(q, VectorX::Zero(nv()));
  return linkToBody(link).inv() * mbc.bodyPosW[static_cast<std::size_t>(bodyIndex(link))];
}

template<class T>
typename SceneDynamicsTpl<T>::MatrixX SceneDynamicsTpl<T>::jacobian(const VectorX & q, const std::string & link) const
{
  const MultiBodyConfigTpl<T> mbc = kinematics(q, VectorX::Zero(nv()));
  // the link origin in body coordinates, world-aligned Jacobian there
  JacobianTpl<T> jac(mb_, link, pointInB(linkToBody(link), Vector3(Vector3::Zero())));
  const MatrixX compact = jac.jacobian(mb_, mbc);
  MatrixX full(6, nv());
  jac.fullJacobian(mb_, compact, full);
  return full;
}

template<class T>
typename SceneDynamicsTpl<T>::Vector3 SceneDynamicsTpl<T>::centerOfMass(const VectorX & q) const
{
  const MultiBodyConfigTpl<T> mbc = kinematics(q, VectorX::Zero(nv()));
  Vector3 mc = Vector3::Zero();
  for(int i = 0; i < mb_.nrBodies(); ++i)
  {
    const auto & I = mb_.body(i).inertia();
    if(I.mass() == T(0)) continue;
    mc += I.mass() * pointInWorld(mbc.bodyPosW[static_cast<std::size_t>(i)], Vector3(I.momentum() / I.mass()));
  }
  return mc / totalMass_;
}

template<class T>
sva::ForceVec<T> SceneDynamicsTpl<T>::centroidalMomentum(const VectorX & q, const VectorX & alpha) const
{
  const MultiBodyConfigTpl<T> mbc = kinematics(q, alpha);
  return computeCentroidalMomentum(mb_, mbc, centerOfMass(q));
}

template class SceneDynamicsTpl<double>;
template class SceneDynamicsTpl<long double>;

} // namespace rbd::scene
