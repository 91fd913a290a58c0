#include <rbd/IDIM.h>

namespace rbd
{

template Eigen::Matrix<double, 10, 1> inertiaToVector(const sva::RBInertia<double> &);
template Eigen::Matrix<long double, 10, 1> inertiaToVector(const sva::RBInertia<long double> &);
template sva::RBInertia<double> vectorToInertia(const Eigen::Matrix<double, 10, 1> &);
template sva::RBInertia<long double> vectorToInertia(const Eigen::Matrix<long double, 10, 1> &);
template Eigen::Matrix<double, Eigen::Dynamic, 1> multiBodyToInertialVector(const MultiBodyTpl<double> &);
template Eigen::Matrix<long double, Eigen::Dynamic, 1> multiBodyToInertialVector(
  const MultiBodyTpl<long double> &);
template Eigen::Matrix<double, 6, 10> IMPhi(const sva::MotionVec<double> &);
template Eigen::Matrix<long double, 6, 10> IMPhi(const sva::MotionVec<long double> &);
template Eigen::Matrix<double, 6, 10> newtonEulerPhi(const sva::MotionVec<double> &,
                                                    const sva::MotionVec<double> &);
template Eigen::Matrix<long double, 6, 10> newtonEulerPhi(const sva::MotionVec<long double> &,
                                                         const sva::MotionVec<long double> &);
template class IDIMTpl<double>;
template class IDIMTpl<long double>;

} // namespace rbd
