#pragma once
// The fk layout of Variants.h for the runtime, in any scalar: per body, the world-to-link transform
// X_0_link = X_body_link * bodyPosW (X_body_link: identity unless the base is not the URDF root),
// flattened as rotation (3 x 3 column-major) then translation, converted to double.

#include <vector>

#include <Eigen/Core>

#include <rbd/parsers/urdf.h>

namespace rbdgen::accuracy
{

template<typename T>
Eigen::VectorXd flattenPosesT(const rbd::parsers::ParserResult & robot, const std::vector<sva::PTransform<T>> & bodyPosW)
{
  const auto & bodies = robot.mb.bodies();
  Eigen::VectorXd out(12 * static_cast<Eigen::Index>(bodies.size()));
  for(std::size_t k = 0; k < bodies.size(); ++k)
  {
    // bodyBaseTransforms holds X_link_body (URDF link frame to body frame): its inverse maps body to link.
    const auto it = robot.bodyBaseTransforms.find(bodies[k].name());
    const sva::PTransform<T> X_body_link =
        it == robot.bodyBaseTransforms.end() ? sva::PTransform<T>::Identity() : it->second.inv().template cast<T>();
    const sva::PTransform<T> X_0_link = X_body_link * bodyPosW[k];
    const auto i = static_cast<Eigen::Index>(12 * k);
    for(int c = 0; c < 3; ++c)
      for(int r = 0; r < 3; ++r) out(i + 3 * c + r) = static_cast<double>(X_0_link.rotation()(r, c));
    for(int r = 0; r < 3; ++r) out(i + 9 + r) = static_cast<double>(X_0_link.translation()(r));
  }
  return out;
}

} // namespace rbdgen::accuracy
