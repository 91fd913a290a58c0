#include <rbd/Checks.h>
#include <rbd/EulerIntegration.h>

namespace rbd
{

template<typename T>
void sEulerIntegration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc,
                       typename MultiBodyConfigTpl<T>::Scalar step)
{
  checkMatchJointVector(mb, mbc.q, "q", VectorKind::Param);
  checkMatchJointVector(mb, mbc.alpha, "alpha", VectorKind::Dof);
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
  eulerIntegration(mb, mbc, step);
}

template std::vector<std::vector<double>> integrateConfiguration(const MultiBodyTpl<double> &,
                                                                 std::vector<std::vector<double>>,
                                                                 const std::vector<std::vector<double>> &);
template std::vector<std::vector<long double>> integrateConfiguration(const MultiBodyTpl<long double> &,
                                                                      std::vector<std::vector<long double>>,
                                                                      const std::vector<std::vector<long double>> &);
template Eigen::VectorXd integrateConfiguration(const MultiBodyTpl<double> &, const Eigen::VectorXd &,
                                                const Eigen::VectorXd &);
template Eigen::Matrix<long double, Eigen::Dynamic, 1> integrateConfiguration(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
template Eigen::VectorXd configurationDerivative(const MultiBodyTpl<double> &, const Eigen::VectorXd &,
                                                 const Eigen::VectorXd &);
template Eigen::Matrix<long double, Eigen::Dynamic, 1> configurationDerivative(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
template void eulerIntegration<double>(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, double);
template void eulerIntegration<long double>(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &,
                                            long double);
template void sEulerIntegration<double>(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, double);
template void sEulerIntegration<long double>(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &,
                                             long double);

} // namespace rbd
