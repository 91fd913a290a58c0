#pragma once
// Helpers for the scene tests: scenes from text (URDF paths relative to robots/), random states.

#include <random>
#include <string>

#include <gtest/gtest.h>

#include <rbd/EulerIntegration.h>
#include <rbd/scene/Integrators.h>
#include <rbd/scene/SceneDynamics.h>
#include <rbd/scene/SceneLoader.h>

namespace scenetest
{

inline std::string sourceDir() { return RBDGEN_SOURCE_DIR; }
inline std::string robotsDir() { return sourceDir() + "/robots"; }
inline std::string scenesDir() { return sourceDir() + "/scenes"; }

/// A scene from XML text whose URDF paths are relative to robots/.
inline rbd::scene::Scene sceneFromText(const std::string & xml, const std::string & name = "test.xml")
{
  return rbd::scene::loadSceneString(xml, name, robotsDir());
}

/// <scene><robot urdf=.../> + body </scene>.
inline std::string sceneXml(const std::string & urdf, const std::string & body, const std::string & base = "fixed")
{
  return "<scene name=\"t\">\n  <robot urdf=\"" + urdf + "\" base=\"" + base + "\"/>\n" + body + "\n</scene>\n";
}

template<class T>
struct Model
{
  rbd::scene::Scene scene;
  rbd::scene::SceneRobot robot;
  rbd::scene::SceneDynamicsTpl<T> dyn;
  explicit Model(const rbd::scene::Scene & s) : scene(s), robot(rbd::scene::loadSceneRobot(s)), dyn(robot, scene) {}
};

template<class T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

/// Random q (unit quaternions) and alpha, entries in [-range, range].
template<class T>
rbd::scene::SceneState<T> randomState(const rbd::MultiBodyTpl<T> & mb, std::mt19937 & rng, double range = 1.0)
{
  std::uniform_real_distribution<double> u(-range, range);
  rbd::scene::SceneState<T> s;
  s.q = VecX<T>(mb.nrParams());
  s.alpha = VecX<T>(mb.nrDof());
  for(Eigen::Index k = 0; k < s.q.size(); ++k) s.q[k] = T(u(rng));
  for(Eigen::Index k = 0; k < s.alpha.size(); ++k) s.alpha[k] = T(u(rng));
  rbd::scene::normalizeQuaternions(mb, s.q);
  return s;
}

template<class T>
VecX<T> randomVector(Eigen::Index n, std::mt19937 & rng, double range = 1.0)
{
  std::uniform_real_distribution<double> u(-range, range);
  VecX<T> v(n);
  for(Eigen::Index k = 0; k < n; ++k) v[k] = T(u(rng));
  return v;
}

/// max |a - b| / max(1, max |b|).
template<class A, class B>
double relErr(const A & a, const B & b)
{
  const double scale = std::max(1.0, static_cast<double>(b.cwiseAbs().maxCoeff()));
  return static_cast<double>((a - b).cwiseAbs().maxCoeff()) / scale;
}

} // namespace scenetest
