#include "ProgrammaticScene.h"

#include <TestModels.h>

namespace sgprog
{

rbd::scene::Integrator integrator(int k)
{
  using rbd::scene::Integrator;
  return k == 0 ? Integrator::SemiImplicitEuler : (k == 1 ? Integrator::ExplicitEuler : Integrator::RK4);
}

std::string headerName(int k)
{
  return k == 0 ? "sgprog_semi" : (k == 1 ? "sgprog_explicit" : "sgprog_rk4");
}

rbd::scene::SceneRobot sceneRobot()
{
  using J = rbd::Joint;
  rbdtest::Rng rng(4242);
  rbd::MultiBodyGraph g;
  const int n = 10;
  for(int i = 0; i < n; ++i) g.addBody(rbd::Body(rbdtest::randomInertia(rng), "b" + std::to_string(i)));
  //   b0 -Rev- b1 -Prism- b2 -Planar- b3 -Cylindrical- b4 -Free- b5 -Fixed- b6
  //                        |
  //                        +-<Spherical- b7 -Spherical- b8 -<Rev- b9      (< : linked child -> parent)
  struct E
  {
    J::Type type;
    int from, to;
    bool forward;
  };
  const E edges[] = {{J::Rev, 0, 1, true},        {J::Prism, 1, 2, true},   {J::Planar, 2, 3, true},
                     {J::Cylindrical, 3, 4, true}, {J::Free, 4, 5, true},    {J::Fixed, 5, 6, true},
                     {J::Spherical, 2, 7, false},  {J::Spherical, 7, 8, true}, {J::Rev, 8, 9, false}};
  int k = 0;
  for(const E & e : edges)
  {
    const std::string jn = "j" + std::to_string(++k);
    g.addJoint(J(e.type, rbdtest::randomUnit(rng), true, jn));
    const std::string a = "b" + std::to_string(e.from), b = "b" + std::to_string(e.to);
    const sva::PTransformd X1 = rbdtest::randomTransform(rng), X2 = rbdtest::randomTransform(rng);
    if(e.forward) g.linkBodies(a, X1, b, X2, jn, true);
    else g.linkBodies(a, X1, b, X2, jn, false);
  }
  rbd::scene::SceneRobot sr;
  sr.robot.name = "prog_scene";
  sr.robot.mbg = g;
  sr.robot.mb = g.makeMultiBody("b0", J(J::Spherical, Eigen::Vector3d::UnitZ(), true, "Root"), rbdtest::randomTransform(rng));
  sr.robot.mbc = rbd::MultiBodyConfig(sr.robot.mb);
  for(int i = 0; i < n; ++i) sr.robot.bodyBaseTransforms["b" + std::to_string(i)] = sva::PTransformd::Identity();
  const int nv = sr.robot.mb.nrDof();
  sr.damping = Eigen::VectorXd::Zero(nv);
  sr.friction = Eigen::VectorXd::Zero(nv);
  sr.armature = Eigen::VectorXd::Zero(nv);
  for(int i = 0; i < nv; i += 3) sr.damping[i] = 0.2;
  sr.friction[1] = 0.3;
  sr.armature[2] = 0.01;
  return sr;
}

rbd::scene::Scene scene(rbd::scene::Integrator integ)
{
  rbd::scene::Scene s;
  s.file = "(programmatic)";
  s.name = "prog_scene";
  s.gravity = Eigen::Vector3d(0.5, -1.0, -9.81);
  s.velocityTerms = true;
  s.frictionVelocity = 0.1;
  s.outputs.derivatives = true;
  s.integrator = integ;
  return s;
}

} // namespace sgprog
