#pragma once
// Helpers shared by the kinematics and dynamics tests: models with every joint type in both
// directions, random models in any scalar, Richardson central differences, energies.

#include <cmath>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <TestModels.h>

#include <rbd/ABA.h>
#include <rbd/EulerIntegration.h>
#include <rbd/FA.h>
#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>

namespace dyntest
{

using Scalars = ::testing::Types<double, long double>;

template<typename T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template<typename T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// tolDouble for double, tolLong for long double.
template<typename T>
double tol(double tolDouble, double tolLong)
{
  return std::is_same<T, double>::value ? tolDouble : tolLong;
}

/// FK then FV.
template<typename T>
void kinematics(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> & mbc)
{
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
}

/// A graph with every joint type (sketch below; "<" marks a joint linked child -> parent, i.e.
/// backward when rooted at b0), random static transforms, axes and inertias:
///
///   b0 -Rev- b1 -Prism- b2 -Spherical- b3 -Planar- b4 -Cylindrical- b5 -Free- b6 -Fixed- b7
///            |                          |
///            +-<Spherical- b9           +-<Rev- b8 -<Cylindrical- b10
inline rbd::MultiBodyGraph allJointsGraph(rbdtest::Rng & rng)
{
  using J = rbd::Joint;
  rbd::MultiBodyGraph g;
  for(int i = 0; i <= 10; ++i) g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b" + std::to_string(i)));
  struct E
  {
    J::Type type;
    int from, to;
    bool forward;
  };
  const std::vector<E> edges{{J::Rev, 0, 1, true},         {J::Prism, 1, 2, true},     {J::Spherical, 2, 3, true},
                             {J::Planar, 3, 4, true},      {J::Cylindrical, 4, 5, true}, {J::Free, 5, 6, true},
                             {J::Fixed, 6, 7, true},       {J::Rev, 3, 8, false},      {J::Spherical, 1, 9, false},
                             {J::Cylindrical, 8, 10, false}};
  for(std::size_t k = 0; k < edges.size(); ++k)
  {
    const E & e = edges[k];
    const std::string jn = "j" + std::to_string(k + 1);
    g.addJoint(J(e.type, rbdtest::randomUnit(rng), true, jn));
    const std::string a = "b" + std::to_string(e.from), b = "b" + std::to_string(e.to);
    // isB1toB2 == false: the joint moves a w.r.t. b, so walking a -> b traverses it backward.
    const sva::PTransformd X_a_j = rbdtest::randomTransform(rng), X_b_j = rbdtest::randomTransform(rng);
    g.linkBodies(a, X_a_j, b, X_b_j, jn, e.forward);
  }
  return g;
}

/// A tree of allJointsGraph and, for every body, X_j_b: from its frame in the tree back to its frame
/// in the graph (bodiesBaseTransform).
struct RootedModel
{
  rbd::MultiBody mb;
  std::map<std::string, sva::PTransformd> X_j_b;
};

/// Trees of allJointsGraph: rooted at b0 (Fixed), at b7 (Free, every chain joint backward) and at
/// b4 (Planar root, mixed directions).
inline std::vector<RootedModel> allJointsModels(rbdtest::Rng & rng)
{
  const rbd::MultiBodyGraph g = allJointsGraph(rng);
  const sva::PTransformd X7 = rbdtest::randomTransform(rng);
  return {{g.makeMultiBody("b0", rbd::Joint::Fixed, rbdtest::randomTransform(rng)), g.bodiesBaseTransform("b0")},
          {g.makeMultiBody("b7", rbd::Joint::Free, rbdtest::randomTransform(rng), X7), g.bodiesBaseTransform("b7", X7)},
          {g.makeMultiBody("b4", rbd::Joint(rbd::Joint::Planar, rbdtest::randomUnit(rng), true, "Root"),
                           rbdtest::randomTransform(rng)),
           g.bodiesBaseTransform("b4")}};
}

/// A random tree of n bodies (joints linked backward with probability backwardProbability), rooted
/// at a random body with a random root joint type (Free if freeRoot) and random X_0_j0.
inline rbd::MultiBody randomModel(rbdtest::Rng & rng, int n, double backwardProbability = 0.3, bool freeRoot = false)
{
  rbdtest::RandomTreeOptions opt;
  opt.backwardProbability = backwardProbability;
  const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, n, opt);
  const int root = std::uniform_int_distribution<int>(0, n - 1)(rng);
  const auto type = freeRoot ? rbd::Joint::Free : opt.types[std::uniform_int_distribution<std::size_t>(0, 6)(rng)];
  return g.makeMultiBody("b" + std::to_string(root), rbd::Joint(type, rbdtest::randomUnit(rng), true, "Root"),
                         rbdtest::randomTransform(rng));
}

/// mb in scalar T, with the rotations of its static transforms re-orthonormalised in T (a double
/// rotation is orthogonal to ~1e-16 only, which would cap every long double identity there).
template<typename T>
rbd::MultiBodyTpl<T> castModel(const rbd::MultiBody & mb)
{
  rbd::MultiBodyTpl<T> out = mb.template cast<T>();
  for(int i = 0; i < out.nrJoints(); ++i)
  {
    const sva::PTransform<T> & X = out.transform(i);
    const sva::Matrix3<T> E = Eigen::Quaternion<T>(X.rotation()).normalized().toRotationMatrix();
    out.transform(i, sva::PTransform<T>(E, X.translation()));
  }
  return out;
}

/// Random external forces (world coordinates, world origin).
template<typename T>
void randomForces(rbdtest::Rng & rng, rbd::MultiBodyConfigTpl<T> & mbc, double scale = 1.0)
{
  for(auto & f : mbc.force)
  {
    Eigen::Matrix<double, 6, 1> v;
    for(int c = 0; c < 6; ++c) v(c) = rbdtest::uniform(rng, -scale, scale);
    f = sva::ForceVec<T>(Eigen::Matrix<T, 6, 1>(v.cast<T>()));
  }
}

/// df/dt at 0 by central differences with one Richardson step (error O(h^4)).
template<typename T, typename F>
auto derivative(F f, T h) -> decltype(f(h))
{
  using V = decltype(f(h));
  const V d1 = (f(h) - f(-h)) / (T(2) * h);
  const V d2 = (f(h / T(2)) - f(-h / T(2))) / h;
  return (T(4) * d2 - d1) / T(3);
}

/// Flat q / alpha / alphaD / jointTorque of a configuration.
template<typename T>
VecX<T> qOf(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  return rbd::paramToVector(mb, mbc.q);
}
template<typename T>
VecX<T> dofOf(const rbd::MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v)
{
  return rbd::dofToVector(mb, v);
}

/// Kinetic energy sum_i v_i . I_i v_i / 2 (needs FV).
template<typename T>
T kineticEnergy(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  T e = 0;
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & v = mbc.bodyVelB[static_cast<std::size_t>(i)];
    e += T(0.5) * v.dot(mb.body(i).inertia() * v);
  }
  return e;
}

/// Potential energy sum_i m_i gravity . c_i (gravity = (0, 0, 9.81) means g along -z; needs FK).
template<typename T>
T potentialEnergy(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  T e = 0;
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & I = mb.body(i).inertia();
    const auto & X = mbc.bodyPosW[static_cast<std::size_t>(i)];
    // m c_world = m (E^T c + r) = E^T h + m r
    const sva::Vector3<T> mc = X.rotation().transpose() * I.momentum() + I.mass() * X.translation();
    e += mbc.gravity.dot(mc);
  }
  return e;
}

/// Total spatial momentum in world coordinates at the world origin: sum_i X_0_i^T (I_i v_i).
template<typename T>
Eigen::Matrix<T, 6, 1> worldMomentum(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  Eigen::Matrix<T, 6, 1> h = Eigen::Matrix<T, 6, 1>::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    h += mbc.bodyPosW[k].transMul(mb.body(i).inertia() * mbc.bodyVelB[k]).vector();
  }
  return h;
}

} // namespace dyntest
