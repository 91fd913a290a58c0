#pragma once
// Passes emitted once per header as detail functions and called by every function that runs them
// over all joints: the joint kernels, the joints' world poses, the joint velocities, their
// velocity products (the bias terms of RNEA and ABA) and the composite inertias. Each returns a
// struct of the pass's non-constant results; the callers' statements read its members, and
// constant entries still fold at generation time (a struct holds no constant), so the emitted
// arithmetic is the same as when every function repeated the pass.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "JointKernels.h"

namespace rbdgen::passes
{

/// The velocity-product terms of every joint k at the shared velocities:
/// c_k = v_k x vJ_k (the acceleration bias) and p_k = v_k x* I_k v_k (the force bias).
struct VelocityProducts
{
  std::vector<Motion> c;
  std::vector<Force> p;
};

class SharedPasses
{
public:
  explicit SharedPasses(const RobotModel & rm);

  /// A large tree (more moving joints than kMaxSmallTree) shares no velocities (nor their
  /// products), and its RNEA bodies call no shared pass at all. There the shared structs — every
  /// joint's kernel, v, vJ, v x vJ, v x* I v, computed first — are more live values than the
  /// registers hold, and RNEA, which reads them joint by joint in two passes, spills: on
  /// talos_reduced + free base (33 joints, g++ -O3) inverse_dynamics had 2,456 stack operands and
  /// ran ~1.5x slower than when each function emitted its own passes; in place, 1,040. ur5 and
  /// solo12 (13 joints) are as fast or faster shared, and their headers smaller.
  static constexpr std::size_t kMaxSmallTree = 16;
  static bool largeTree(const RobotModel & rm) { return rm.joints.size() > kMaxSmallTree; }

  /// Kernels of every joint, entries read from `K` (`const auto K = detail::joint_kernels<S>(q);`).
  const std::vector<JointKernel> & kernels();
  /// X_0_k of every joint, entries read from `X0s` (`detail::joint_poses<S>(K)`).
  const std::vector<Xform> & poses();
  /// The statement that declares `X0s` in a body.
  static const char * posesCall() { return "[[maybe_unused]] const auto X0s = detail::joint_poses<S>(K);"; }
  /// vJ_k = S_k alpha_k and v_k of every joint, entries read from `Vs` (`detail::joint_velocities<S>(K, alpha)`).
  const std::pair<std::vector<Motion>, std::vector<Motion>> & velocities();
  /// c_k and p_k of every joint at velocities(), entries read from `VPs` (`detail::velocity_products<S>(Vs)`).
  const VelocityProducts & velocityProducts();
  /// Composite inertia of every joint's subtree, entries read from `Ics` (`detail::composite_inertias<S>(K)`).
  const std::vector<Inertia> & compositeInertias();

  /// The definitions of the shared passes used so far (structs and functions, dependencies first).
  std::string definitions() const;

  /// The shared passes the PassContexts of this thread use (nullptr: every function emits its own).
  static SharedPasses * current();
  /// Makes `s` current for its lifetime.
  class Scope
  {
  public:
    explicit Scope(SharedPasses & s);
    ~Scope();
    Scope(const Scope &) = delete;
    Scope & operator=(const Scope &) = delete;

  private:
    SharedPasses * previous_;
  };

private:
  const RobotModel & rm_;
  std::optional<std::vector<JointKernel>> kernels_;
  std::optional<std::vector<Xform>> poses_;
  std::optional<std::pair<std::vector<Motion>, std::vector<Motion>>> velocities_;
  std::optional<VelocityProducts> products_;
  std::optional<std::vector<Inertia>> inertias_;
  std::vector<std::string> definitions_;

  /// How an exported pass reads in the emitted code: struct, function, its parameters, the caller's
  /// variable, the struct's documentation.
  struct Export
  {
    const char * structName, * fn, * params, * var, * doc;
  };
  /// Exports the pass emitted in b (its results: the scalars outs points to, inside value), keeps its
  /// definition and stores value (its entries now read from e.var) in slot.
  template<class T>
  const T & publish(std::optional<T> & slot, T && value, Block & b, const std::vector<Scalar *> & outs, const Export & e);
};

} // namespace rbdgen::passes
