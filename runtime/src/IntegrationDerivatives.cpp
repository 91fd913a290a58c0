// Explicit instantiations of rbd/IntegrationDerivatives.h for double and long double.
#include <rbd/IntegrationDerivatives.h>

namespace rbd
{

template IntegrationDerivativesTpl<double> integrateConfigurationDerivatives(const MultiBodyTpl<double> &,
                                                                             const Eigen::VectorXd &);
template IntegrationDerivativesTpl<long double> integrateConfigurationDerivatives(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
template Eigen::VectorXd configurationDifference(const MultiBodyTpl<double> &, const Eigen::VectorXd &,
                                                 const Eigen::VectorXd &);
template Eigen::Matrix<long double, Eigen::Dynamic, 1> configurationDifference(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
template Eigen::MatrixXd configurationTangentMap(const MultiBodyTpl<double> &, const Eigen::VectorXd &);
template Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> configurationTangentMap(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
template Eigen::MatrixXd configurationTangentProjection(const MultiBodyTpl<double> &, const Eigen::VectorXd &);
template Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> configurationTangentProjection(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);
template ConfigurationDerivativeJacobiansTpl<double> configurationDerivativeJacobians(const MultiBodyTpl<double> &,
                                                                                      const Eigen::VectorXd &,
                                                                                      const Eigen::VectorXd &);
template ConfigurationDerivativeJacobiansTpl<long double> configurationDerivativeJacobians(
    const MultiBodyTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &);

} // namespace rbd
