#include "MassMatrixChecks.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include <rbd/FK.h>
#include <rbd/MultiBodyConfig.h>

namespace rbdgen
{
namespace
{

std::string quoted(const std::vector<std::string> & names)
{
  std::string s;
  for(const auto & n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}

} // namespace

MassMatrixReport checkMassMatrix(const rbd::MultiBody & mb)
{
  MassMatrixReport rep;
  const auto n = static_cast<std::size_t>(mb.nrBodies());
  rbd::MultiBodyConfig mbc(mb);
  mbc.zero(mb);
  rbd::forwardKinematics(mb, mbc);

  // Composite inertias, leaves up, each in its body's frame: Ic_p += X_p_i^T Ic_i X_p_i.
  std::vector<sva::RBInertiad> Ic;
  for(const auto & b : mb.bodies()) Ic.push_back(b.inertia());
  for(std::size_t i = n; i-- > 1;)
  {
    const int p = mb.parent(static_cast<int>(i));
    if(p >= 0) Ic[static_cast<std::size_t>(p)] += mbc.parentToSon[i].transMul(Ic[i]);
  }
  for(const auto & b : mb.bodies()) rep.totalMass += b.inertia().mass();
  const double M = rep.totalMass;

  // L: largest distance from the root body's origin to a link origin or centre of mass (q = 0),
  // at least the radius of gyration about the root origin, sqrt(trace(I_o) / (2 M)).
  const Eigen::Vector3d root = mbc.bodyPosW[0].translation();
  for(std::size_t i = 0; i < n; ++i)
  {
    const sva::PTransformd & X = mbc.bodyPosW[i];
    rep.length = std::max(rep.length, (X.translation() - root).norm());
    const auto & I = mb.body(static_cast<int>(i)).inertia();
    if(I.mass() > 0)
    {
      // c_world = r + E^T c_body (E maps world coordinates into body coordinates).
      const Eigen::Vector3d c = X.translation() + X.rotation().transpose() * (I.momentum() / I.mass());
      rep.length = std::max(rep.length, (c - root).norm());
    }
  }
  if(M > 0) rep.length = std::max(rep.length, std::sqrt(std::max(0.0, Ic[0].inertia().trace()) / (2 * M)));
  const double ML2 = M * rep.length * rep.length;

  // Per dof: S^T Ic S at q = 0, relative to M L^2 (rotation) or M (translation).
  rep.smallest.ratio = HUGE_VAL;
  std::map<std::string, DofInertia> worstOfJoint;
  std::vector<std::string> order;
  for(std::size_t i = 0; i < n; ++i)
  {
    const rbd::Joint & j = mb.joint(static_cast<int>(i));
    if(j.dof() == 0) continue;
    if(Ic[i].mass() <= 0)
    {
      rep.masslessSubtrees.push_back(j.name());
      continue;
    }
    if(M <= 0 || ML2 <= 0) continue;
    const Eigen::Matrix<double, 6, 6> I6 = Ic[i].matrix();
    const auto & S = mbc.motionSubspace[i];
    for(int d = 0; d < j.dof(); ++d)
    {
      const Eigen::Matrix<double, 6, 1> s = S.col(d);
      DofInertia di;
      di.joint = j.name();
      di.dof = d;
      di.rotational = s.head<3>().norm() > 0;
      di.ratio = s.dot(I6 * s) / (di.rotational ? ML2 : M);
      if(di.ratio < rep.smallest.ratio) rep.smallest = di;
      if(di.ratio < kNegligibleRatio)
      {
        auto it = worstOfJoint.find(j.name());
        if(it == worstOfJoint.end())
        {
          order.push_back(j.name());
          worstOfJoint[j.name()] = di;
        }
        else if(di.ratio < it->second.ratio) it->second = di;
      }
    }
  }
  for(const auto & name : order) rep.negligible.push_back(worstOfJoint[name]);

  // Stacked free joints: F free, j a moving descendant, the part F moves outside j's subtree
  // (B = Ic_F - X_F_j^T Ic_j X_F_j, in F's frame) negligible by the same measure.
  auto isAncestor = [&](std::size_t a, std::size_t d) {
    for(int k = mb.parent(static_cast<int>(d)); k >= 0; k = mb.parent(k))
      if(static_cast<std::size_t>(k) == a) return true;
    return false;
  };
  if(M > 0 && ML2 > 0)
    for(std::size_t f = 0; f < n; ++f)
    {
      if(mb.joint(static_cast<int>(f)).type() != rbd::Joint::Free || Ic[f].mass() <= 0) continue;
      std::vector<std::size_t> hits;
      for(std::size_t k = f + 1; k < n; ++k)
      {
        if(mb.joint(static_cast<int>(k)).dof() == 0 || !isAncestor(f, k)) continue;
        const sva::PTransformd X_f_k = mbc.bodyPosW[k] * mbc.bodyPosW[f].inv();
        const Eigen::Matrix<double, 6, 6> B = Ic[f].matrix() - X_f_k.transMul(Ic[k]).matrix();
        bool negligible = true;
        for(int d = 0; d < 6; ++d) negligible = negligible && B(d, d) <= kNegligibleRatio * (d < 3 ? ML2 : M);
        if(negligible) hits.push_back(k);
      }
      // Report the nearest such joint only (any joint between F and it qualifies too).
      for(std::size_t k : hits)
      {
        bool nearest = true;
        for(std::size_t h : hits) nearest = nearest && !(h != k && isAncestor(h, k));
        if(nearest) rep.stackedFree.emplace_back(mb.joint(static_cast<int>(f)).name(), mb.joint(static_cast<int>(k)).name());
      }
    }
  return rep;
}

std::vector<std::string> MassMatrixReport::messages(const std::string & source) const
{
  std::vector<std::string> out;
  if(!masslessSubtrees.empty())
    out.push_back(fmt::format("{}: joint(s) {} move only massless links: the mass matrix is singular, the header has no "
                              "forward dynamics (give those links mass, or lock the joints / give them armature > 0 in a "
                              "scene)",
                              source, quoted(masslessSubtrees)));
  for(const auto & [F, j] : stackedFree)
    out.push_back(fmt::format("{}: free joint '{}' moves (but for a negligible part) only what joint '{}' moves: two free "
                              "joints with a massless link between them, the mass matrix is singular, the header has no "
                              "forward dynamics (keep one free joint: without --floating-base, or without the URDF's "
                              "floating joint)",
                              source, F, j));
  for(const DofInertia & d : negligible)
    out.push_back(fmt::format("{}: joint '{}': negligible effective inertia (dof {}, {}): S^T Ic S = {:.3g} {} is {:.2g} "
                              "of the robot's {} (M = {:.4g} kg, L = {:.3g} m; threshold {:g}): the mass matrix is "
                              "ill-conditioned (cond(H) of order {:.0e}), forward dynamics loses about {:.0f} digits; give the "
                              "links it moves realistic mass and inertia, or make the joint fixed",
                              source, d.joint, d.dof, d.rotational ? "rotation" : "translation",
                              d.ratio * (d.rotational ? totalMass * length * length : totalMass),
                              d.rotational ? "kg m^2" : "kg", d.ratio, d.rotational ? "M L^2" : "M", totalMass, length,
                              kNegligibleRatio, 1.0 / std::max(d.ratio, 1e-300), -std::log10(std::max(d.ratio, 1e-300))));
  return out;
}

} // namespace rbdgen
