#include "SharedPasses.h"

#include <cctype>
#include <map>
#include <set>

#include <fmt/format.h>

#include "BackwardForce.h"
#include "CompositeInertia.h"
#include "ForwardMotion.h"

namespace rbdgen::passes
{
namespace
{

thread_local SharedPasses * currentShared = nullptr;

bool isIdentifier(const std::string & s)
{
  for(char c : s)
    if(!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return !s.empty();
}

void collect(std::vector<Scalar *> & out, Vec3 & v)
{
  for(int i = 0; i < 3; ++i) out.push_back(&v[i]);
}
void collect(std::vector<Scalar *> & out, Mat3 & m)
{
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) out.push_back(&m(r, c));
}
void collect(std::vector<Scalar *> & out, Xform & X)
{
  collect(out, X.E);
  collect(out, X.r);
}
void collect(std::vector<Scalar *> & out, Motion & m)
{
  collect(out, m.w);
  collect(out, m.v);
}
void collect(std::vector<Scalar *> & out, Force & f)
{
  collect(out, f.n);
  collect(out, f.f);
}

// The block b computed the non-constant scalars *outs: they become the members of
// `detail::<Struct><S>` returned by `detail::<fn><S>(params)`, and *outs are rewritten to read
// them from the caller's `<var>`. Returns the definitions.
std::string exportPass(Block & b, const std::vector<Scalar *> & outs, const std::string & structName, const std::string & fn,
                       const std::string & params, const std::string & var, const std::string & doc)
{
  std::vector<std::string> members;
  std::set<std::string> seen;
  std::map<std::string, Scalar> inputs; // an input read directly (e.g. q[5]), once per input
  for(Scalar * s : outs)
  {
    if(s->isConst()) continue;
    auto found = inputs.find(s->name());
    if(found == inputs.end() && !isIdentifier(s->name()))
    {
      std::string hint = s->name(); // alpha[3] -> alpha_3
      for(char & c : hint)
        if(!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      while(!hint.empty() && hint.back() == '_') hint.pop_back();
      found = inputs.emplace(s->name(), b.def(s->name(), hint)).first;
    }
    const Scalar local = found == inputs.end() ? *s : found->second;
    if(seen.insert(local.name()).second) members.push_back(local.name());
    *s = Scalar::var(var + "." + local.name());
  }
  // the results as one aggregate, members in declaration order
  std::string ret = "return {", retLine = ret;
  for(std::size_t i = 0; i < members.size(); ++i)
  {
    const std::string item = members[i] + (i + 1 < members.size() ? "," : "");
    if(retLine.size() + item.size() > 112)
    {
      ret += "\n    ";
      retLine = "    ";
    }
    else if(i > 0)
    {
      ret += " ";
      retLine += " ";
    }
    ret += item;
    retLine += item;
  }
  b.line(ret + "};");
  std::string decl;
  std::string line = "  S";
  for(std::size_t i = 0; i < members.size(); ++i)
  {
    const std::string item = fmt::format(" {}{}", members[i], i + 1 < members.size() ? "," : ";");
    if(line.size() + item.size() > 110)
    {
      decl += line + "\n";
      line = "   ";
    }
    line += item;
  }
  if(members.empty()) line = "  char none = 0;";
  decl += line + "\n";
  return fmt::format("/// {}\ntemplate<class S>\nstruct {}\n{{\n{}}};\n\n"
                     "template<class S>\nRBDGEN_INLINE {}<S> {}({}) noexcept\n{{\n{}}}\n",
                     doc, structName, decl, structName, fn, params, b.str("  "));
}

} // namespace

SharedPasses::SharedPasses(const RobotModel & rm) : rm_(rm) {}

template<class T>
const T & SharedPasses::publish(std::optional<T> & slot, T && value, Block & b, const std::vector<Scalar *> & outs,
                                const Export & e)
{
  definitions_.push_back(exportPass(b, outs, e.structName, e.fn, e.params, e.var, e.doc));
  slot = std::move(value);
  return *slot;
}

SharedPasses * SharedPasses::current()
{
  return currentShared;
}

SharedPasses::Scope::Scope(SharedPasses & s) : previous_(currentShared)
{
  currentShared = &s;
}

SharedPasses::Scope::~Scope()
{
  currentShared = previous_;
}

const std::vector<JointKernel> & SharedPasses::kernels()
{
  if(kernels_) return *kernels_;
  Block b;
  std::vector<JointKernel> K;
  for(const MovingJoint & mj : rm_.joints)
  {
    b.comment(fmt::format("{}: joint '{}' ({})", mj.tag, mj.name, describeJoint(mj)));
    K.push_back(emitJointKernel(b, mj, "q"));
  }
  std::vector<Scalar *> outs;
  for(JointKernel & k : K)
  {
    collect(outs, k.Xj);
    for(Motion & s : k.S) collect(outs, s);
  }
  return publish(kernels_, std::move(K), b, outs,
                 {"JointKernels", "joint_kernels", "[[maybe_unused]] const Config<S> & q", "K",
                  "Joint transforms X_j(q) and motion subspaces S(q) of every joint (non-constant entries)."});
}

const std::vector<Xform> & SharedPasses::poses()
{
  if(poses_) return *poses_;
  Block b;
  PassContext ctx(b, rm_, kernels());
  std::vector<Xform> X0 = forwardMotion(ctx, MotionRequest::make(true, false), ctx.allJoints()).X0;
  std::vector<Scalar *> outs;
  for(Xform & X : X0) collect(outs, X);
  return publish(poses_, std::move(X0), b, outs,
                 {"JointPoses", "joint_poses", "[[maybe_unused]] const JointKernels<S> & K", "X0s",
                  "World pose X_0_k = X_j X_T X_0_p of every joint's body frame."});
}

const std::pair<std::vector<Motion>, std::vector<Motion>> & SharedPasses::velocities()
{
  if(velocities_) return *velocities_;
  Block b;
  PassContext ctx(b, rm_, kernels());
  MotionState m = forwardMotion(ctx, MotionRequest::make(false, true), ctx.allJoints());
  std::vector<Scalar *> outs;
  for(std::size_t k = 0; k < m.v.size(); ++k)
  {
    collect(outs, m.vJ[k]);
    collect(outs, m.v[k]);
  }
  return publish(velocities_, std::make_pair(std::move(m.vJ), std::move(m.v)), b, outs,
                 {"JointVelocities", "joint_velocities",
                  "[[maybe_unused]] const JointKernels<S> & K, [[maybe_unused]] const Tangent<S> & alpha", "Vs",
                  "Joint velocities vJ_k = S_k alpha_k and body velocities v_k = X_p_k v_p + vJ_k (body coordinates)."});
}

const VelocityProducts & SharedPasses::velocityProducts()
{
  if(products_) return *products_;
  const auto & [vJ, v] = velocities(); // (its definition first: this one takes a JointVelocities)
  Block b;
  VelocityProducts vp;
  for(std::size_t k = 0; k < rm_.joints.size(); ++k)
  {
    const MovingJoint & mj = rm_.joints[k];
    b.comment(fmt::format("{}: c = v x vJ, p = v x* I v", mj.tag));
    vp.c.push_back(velocityBias(b, mj, v[k], vJ[k], mj.tag + "_vxvJ"));
    vp.p.push_back(crossDual(b, v[k], apply(b, bodyInertia(mj), v[k], mj.tag + "_Iv"), mj.tag + "_vxIv"));
  }
  std::vector<Scalar *> outs;
  for(Motion & c : vp.c) collect(outs, c);
  for(Force & p : vp.p) collect(outs, p);
  return publish(products_, std::move(vp), b, outs,
                 {"VelocityProducts", "velocity_products", "[[maybe_unused]] const JointVelocities<S> & Vs", "VPs",
                  "Velocity products of every joint: c_k = v_k x vJ_k (acceleration bias) and "
                  "p_k = v_k x* I_k v_k (force bias)."});
}

const std::vector<Inertia> & SharedPasses::compositeInertias()
{
  if(inertias_) return *inertias_;
  Block b;
  PassContext ctx(b, rm_, kernels());
  std::vector<Inertia> Ic = passes::compositeInertias(ctx);
  std::vector<Scalar *> outs;
  for(Inertia & I : Ic)
  {
    collect(outs, I.h);
    collect(outs, I.I);
  }
  return publish(inertias_, std::move(Ic), b, outs,
                 {"CompositeInertias", "composite_inertias", "[[maybe_unused]] const JointKernels<S> & K", "Ics",
                  "Composite inertia of every joint's subtree, in its body frame (Ic_p += X_p_i^T Ic_i X_p_i)."});
}

std::string SharedPasses::definitions() const
{
  std::string s;
  for(const std::string & d : definitions_) s += (s.empty() ? "" : "\n") + d;
  return s;
}

} // namespace rbdgen::passes
