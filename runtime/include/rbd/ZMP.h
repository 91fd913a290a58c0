#pragma once
// Centroidal ZMP: the point of the plane z = altitude about which the contact wrench that produces
// the centroidal motion has no horizontal moment. With f the total contact force and n_G its moment
// about the CoM c (n_p = n_G + (c - p) x f, n_p,x = n_p,y = 0):
//   p_x = c_x - (n_G,y + (c_z - h) f_x) / f_z,   p_y = c_y + (n_G,x - (c_z - h) f_y) / f_z,   p_z = h.
// f = M (cdd + gravity) (mbc.gravity is the opposite of the gravity acceleration, as in RBDyn).

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Point-mass ZMP (zero angular momentum rate about the CoM, n_G = 0), from the CoM position com
/// and acceleration comA (world coordinates) and mbc.gravity:
///   p_xy = c_xy - (c_z - h) (cdd_xy + g_xy) / (cdd_z + g_z),   p_z = h.
template<typename T>
sva::Vector3<T> computeCentroidalZMP(const MultiBodyConfigTpl<T> & mbc, const sva::Vector3<T> & com,
                                     const sva::Vector3<T> & comA, T altitude)
{
  const sva::Vector3<T> f = comA + mbc.gravity; // contact force per unit mass
  const T dz = com.z() - altitude;
  return sva::Vector3<T>(com.x() - dz * f.x() / f.z(), com.y() - dz * f.y() / f.z(), altitude);
}

/// Full centroidal ZMP from the centroidal momentum rate momentumDot = d/dt h_G = [kd_G; M cdd]
/// (computeCentroidalMomentumDot) about com: f = kd_lin + M gravity, n_G = kd_G (M: total mass of mb).
template<typename T>
sva::Vector3<T> computeCentroidalZMP(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                     const sva::Vector3<T> & com, const sva::ForceVec<T> & momentumDot, T altitude)
{
  T M = T(0);
  for(const auto & b : mb.bodies()) M += b.inertia().mass();
  const sva::Vector3<T> f = momentumDot.force() + M * mbc.gravity;
  const sva::Vector3<T> & n = momentumDot.couple();
  const T dz = com.z() - altitude;
  return sva::Vector3<T>(com.x() - (n.y() + dz * f.x()) / f.z(), com.y() + (n.x() - dz * f.y()) / f.z(), altitude);
}

extern template sva::Vector3<double> computeCentroidalZMP(const MultiBodyConfigTpl<double> &,
                                                          const sva::Vector3<double> &,
                                                          const sva::Vector3<double> &, double);
extern template sva::Vector3<long double> computeCentroidalZMP(const MultiBodyConfigTpl<long double> &,
                                                               const sva::Vector3<long double> &,
                                                               const sva::Vector3<long double> &, long double);
extern template sva::Vector3<double> computeCentroidalZMP(const MultiBodyTpl<double> &,
                                                          const MultiBodyConfigTpl<double> &,
                                                          const sva::Vector3<double> &,
                                                          const sva::ForceVec<double> &, double);
extern template sva::Vector3<long double> computeCentroidalZMP(const MultiBodyTpl<long double> &,
                                                               const MultiBodyConfigTpl<long double> &,
                                                               const sva::Vector3<long double> &,
                                                               const sva::ForceVec<long double> &, long double);

} // namespace rbd
