#include "Functions.h"

#include <fmt/format.h>

#include "Kernels.h"

namespace rbdgen::emit
{

EmittedBody finish(const Block & b)
{
  return {b.str("  "), OpCount{b.mults(), b.adds(), b.calls()}};
}

namespace
{


// Write a symbolic pose into `<dst>.rotation` / `<dst>.translation`.
void writePose(Block & b, const std::string & dst, const Xform & X)
{
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) b.line(fmt::format("{}.rotation({}, {}) = {};", dst, r, c, Block::text(X.E(r, c))));
  for(int i = 0; i < 3; ++i) b.line(fmt::format("{}.translation({}) = {};", dst, i, Block::text(X.r[i])));
}

// World poses of the links: X_0_link = X_owner_link X_0_owner.
void writeLinkPoses(Block & b, const RobotModel & rm, const std::vector<Xform> & X0, const std::string & dst)
{
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    const BodyFrame & bf = rm.bodies[i];
    b.comment(fmt::format("link '{}'", bf.name));
    const Xform C = constantXform(bf.X_owner_link);
    const Xform X = bf.owner < 0 ? C : compose(b, C, X0[static_cast<std::size_t>(bf.owner)], "X0_" + bf.ident);
    writePose(b, fmt::format("{}[{}]", dst, i), X);
  }
}

// Reads the world pose of moving frame k back from `kin.frame[k]`.
Xform kinFrame(int k)
{
  Xform X;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) X.E(r, c) = Scalar::var(fmt::format("kin.frame[{}].rotation({}, {})", k, r, c));
  for(int i = 0; i < 3; ++i) X.r[i] = Scalar::var(fmt::format("kin.frame[{}].translation({})", k, i));
  return X;
}

// Walk from link `body` to the root, with each joint's block emitted once:
//   switch(body) { case Body::<link>: goto <prefix>_<owner joint>; ... }
//   <prefix>_<joint>: { jointBlock(k) } goto <prefix>_<parent joint>; ...  <prefix>_done:
// Direct jumps, so the code grows with the number of joints, not with the sum of the path lengths.
template<typename F>
void emitPathWalk(Block & b, const RobotModel & rm, const std::string & prefix, F && jointBlock)
{
  auto label = [&](int k) {
    return k < 0 ? prefix + "_done" : fmt::format("{}_{}", prefix, rm.joints[static_cast<std::size_t>(k)].tag);
  };
  b.line("switch(body)");
  b.line("{");
  for(const BodyFrame & bf : rm.bodies) b.line(fmt::format("case Body::{}: goto {};", bf.ident, label(bf.owner)));
  b.line("}");
  for(std::size_t k = rm.joints.size(); k-- > 0;)
  {
    b.line(label(static_cast<int>(k)) + ":");
    b.line("{");
    jointBlock(k, rm.joints[k]);
    b.line("}");
    b.line(fmt::format("goto {};", label(rm.joints[k].parent)));
  }
  b.line(label(-1) + ":;");
}

// Composite inertias Ic_k (body coordinates): Ic_p += X_p_k^T Ic_k X_p_k, leaves to root.
std::vector<Inertia> emitCompositeInertias(Block & b, const RobotModel & rm, const std::vector<JointKernel> & K)
{
  const std::size_t n = rm.joints.size();
  std::vector<Inertia> Ic(n);
  for(std::size_t k = 0; k < n; ++k)
    Ic[k] = constantInertia(rm.joints[k].inertia.mass(), rm.joints[k].inertia.momentum(), rm.joints[k].inertia.inertia());
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    if(mj.parent < 0) continue;
    b.comment(fmt::format("{}: composite inertia into its parent", mj.tag));
    const Inertia Ij = transApply(b, K[k].Xj, Ic[k], mj.tag + "_Icj");
    const Inertia Ip = transApply(b, constantXform(mj.Xt), Ij, mj.tag + "_Icp");
    const auto p = static_cast<std::size_t>(mj.parent);
    Ic[p] = add(b, Ic[p], Ip, rm.joints[p].tag + "_Ic");
  }
  return Ic;
}

// First moment m c (world) of moving joint k's body: m_k o_k + E_0_k^T h_k.
Vec3 emitFirstMoment(Block & b, const MovingJoint & mj, const Xform & X0)
{
  return add(b, tmul(b, X0.E, Vec3::constant(mj.inertia.momentum()), mj.tag + "_h"),
             scale(b, Scalar::constant(mj.inertia.mass()), X0.r, mj.tag + "_mo"), mj.tag + "_mc");
}

// Sum of the first moments of every body, static ones included.
Vec3 emitTotalFirstMoment(Block & b, const RobotModel & rm, const std::vector<Xform> & X0)
{
  Vec3 sum = Vec3::constant(rm.staticMoment);
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
    if(rm.joints[k].inertia.mass() != 0.0)
      sum = add(b, sum, emitFirstMoment(b, rm.joints[k], X0[k]), rm.joints[k].tag + "_sum");
  return sum;
}

} // namespace

EmittedBody forwardKinematicsBody(const RobotModel & rm)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const auto X0 = emitWorldPoses(b, rm, K);
  writeLinkPoses(b, rm, X0, "res");
  return finish(b);
}

EmittedBody kinematicsBody(const RobotModel & rm)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const auto X0 = emitWorldPoses(b, rm, K);
  for(std::size_t k = 0; k < rm.joints.size(); ++k) writePose(b, fmt::format("kin.frame[{}]", k), X0[k]);
  writeLinkPoses(b, rm, X0, "kin.pose");
  return finish(b);
}

EmittedBody rneaBody(const RobotModel & rm, const RneaTerms & terms)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  std::vector<Xform> X0;
  if(terms.externalForces) X0 = emitWorldPoses(b, rm, K);
  const std::size_t n = rm.joints.size();
  std::vector<Motion> v(n), a(n);
  std::vector<Force> f(n);
  // a_0 = [0; g]: gravity as a fictitious upward acceleration of the world (RBDyn).
  Motion a0 = Motion::zero();
  if(terms.gravity)
    for(int c = 0; c < 3; ++c) a0.v[c] = Scalar::constant(-terms.gravityVector[c]);
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const std::string t = mj.tag;
    b.comment(fmt::format("{} forward pass: v = X_p_i v_p + S alpha, a = X_p_i a_p + S alphaD + v x S alpha", t));
    const Motion vJ = terms.velocity ? jointMotion(b, K[k], "alpha", mj.vIndex, t + "_vJ") : Motion::zero();
    const Motion aJ = terms.acceleration ? jointMotion(b, K[k], "alphaD", mj.vIndex, t + "_aJ") : Motion::zero();
    const Motion vp = mj.parent < 0 ? Motion::zero() : v[static_cast<std::size_t>(mj.parent)];
    const Motion ap = mj.parent < 0 ? a0 : a[static_cast<std::size_t>(mj.parent)];
    v[k] = add(b, toChild(b, mj, K[k], vp, t + "_Xv"), vJ, t + "_v");
    a[k] = add(b, add(b, toChild(b, mj, K[k], ap, t + "_Xa"), aJ, t + "_aa"), cross(b, v[k], vJ, t + "_vxvJ"),
               t + "_a");
    // f = I a + v x* I v
    const Inertia I = constantInertia(mj.inertia.mass(), mj.inertia.momentum(), mj.inertia.inertia());
    f[k] = add(b, apply(b, I, a[k], t + "_Ia"), crossDual(b, v[k], apply(b, I, v[k], t + "_Iv"), t + "_vxIv"), t + "_f");
  }
  if(terms.externalForces)
  {
    b.comment("external wrenches: f_k -= X_0_k^* fext (world coordinates at the world origin)");
    for(std::size_t i = 0; i < rm.bodies.size(); ++i)
    {
      const int o = rm.bodies[i].owner;
      if(o < 0) continue;
      Force fe;
      for(int c = 0; c < 3; ++c)
      {
        fe.n[c] = Scalar::var(fmt::format("fext[{}][{}]", i, c));
        fe.f[c] = Scalar::var(fmt::format("fext[{}][{}]", i, c + 3));
      }
      const auto ko = static_cast<std::size_t>(o);
      f[ko] = sub(b, f[ko], dualApply(b, X0[ko], fe, fmt::format("{}_fx{}", rm.joints[ko].tag, i)),
                  rm.joints[ko].tag + "_fe");
    }
  }
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    b.comment(fmt::format("{} backward pass: tau = S^T f, f_p += X_p_i^T f", mj.tag));
    const auto tau = projectForce(b, K[k], f[k], mj.tag + "_tau");
    for(int d = 0; d < mj.nv; ++d)
      b.line(fmt::format("tau[{}] = {};", mj.vIndex + d, Block::text(tau[static_cast<std::size_t>(d)])));
    if(mj.parent >= 0)
    {
      const auto p = static_cast<std::size_t>(mj.parent);
      f[p] = add(b, f[p], toParent(b, mj, K[k], f[k], mj.tag + "_fp"), rm.joints[p].tag + "_f");
    }
  }
  return finish(b);
}

namespace
{

// Composite rigid-body algorithm on symbols: H (lower triangle, by dof index) from kernels.
std::vector<std::vector<Scalar>> emitCrba(Block & b, const RobotModel & rm, const std::vector<JointKernel> & K)
{
  const std::size_t n = rm.joints.size();
  const std::vector<Inertia> Ic = emitCompositeInertias(b, rm, K);
  std::vector<std::vector<Scalar>> H(static_cast<std::size_t>(rm.nv),
                                     std::vector<Scalar>(static_cast<std::size_t>(rm.nv), Scalar::constant(0)));
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    b.comment(fmt::format("{}: mass matrix columns, F = Ic S carried to the root", mj.tag));
    for(int d = 0; d < mj.nv; ++d)
    {
      const std::string h = fmt::format("{}_F{}", mj.tag, d);
      Force F = apply(b, Ic[k], K[k].S[static_cast<std::size_t>(d)], h);
      const int col = mj.vIndex + d;
      // H_kk block (lower part: rows >= col)
      const auto own = projectForce(b, K[k], F, fmt::format("H_{}", col));
      for(int e = d; e < mj.nv; ++e) H[static_cast<std::size_t>(mj.vIndex + e)][static_cast<std::size_t>(col)] = own[static_cast<std::size_t>(e)];
      int j = static_cast<int>(k);
      while(rm.joints[static_cast<std::size_t>(j)].parent >= 0)
      {
        const MovingJoint & mjj = rm.joints[static_cast<std::size_t>(j)];
        F = toParent(b, mjj, K[static_cast<std::size_t>(j)], F, fmt::format("{}_{}", h, mjj.tag));
        j = mjj.parent;
        const MovingJoint & mp = rm.joints[static_cast<std::size_t>(j)];
        const auto Hp = projectForce(b, K[static_cast<std::size_t>(j)], F, fmt::format("H_{}", col));
        for(int e = 0; e < mp.nv; ++e) H[static_cast<std::size_t>(col)][static_cast<std::size_t>(mp.vIndex + e)] = Hp[static_cast<std::size_t>(e)];
      }
    }
  }
  return H;
}

// Parent of each dof in the dof tree (Featherstone's λ on dofs), -1 for a root dof.
std::vector<int> dofParents(const RobotModel & rm)
{
  std::vector<int> lambda(static_cast<std::size_t>(rm.nv), -1);
  for(const MovingJoint & mj : rm.joints)
  {
    const int first = mj.vIndex;
    lambda[static_cast<std::size_t>(first)] =
        mj.parent < 0 ? -1 : rm.joints[static_cast<std::size_t>(mj.parent)].vIndex + rm.joints[static_cast<std::size_t>(mj.parent)].nv - 1;
    for(int d = 1; d < mj.nv; ++d) lambda[static_cast<std::size_t>(first + d)] = first + d - 1;
  }
  return lambda;
}

} // namespace

std::vector<std::vector<Scalar>> emitMassMatrix(Block & b, const RobotModel & rm, const std::vector<double> & armature)
{
  const auto K = emitKernels(b, rm, "q");
  const auto Hfull = emitCrba(b, rm, K);
  const auto nv = static_cast<std::size_t>(rm.nv);
  // Symmetric view: L[r][c] for c <= r; H_ii += armature_i.
  std::vector<std::vector<Scalar>> L(nv, std::vector<Scalar>(nv, Scalar::constant(0)));
  for(std::size_t r = 0; r < nv; ++r)
    for(std::size_t c = 0; c <= r; ++c) L[r][c] = Hfull[r][c].isZero() ? Hfull[c][r] : Hfull[r][c];
  for(std::size_t i = 0; i < armature.size() && i < nv; ++i)
    if(armature[i] != 0.0) L[i][i] = b.sum({Term{1.0, {L[i][i]}}, Term{armature[i], {}}}, fmt::format("Ha{}", i));
  return L;
}

EmittedBody massMatrixBody(const RobotModel & rm, const std::vector<double> & armature)
{
  Block b;
  const auto L = emitMassMatrix(b, rm, armature);
  for(int r = 0; r < rm.nv; ++r)
    for(int c = 0; c <= r; ++c)
    {
      const Scalar & x = L[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
      if(x.isZero()) continue;
      b.line(fmt::format("H({}, {}) = {};", r, c, Block::text(x)));
      if(r != c) b.line(fmt::format("H({}, {}) = {};", c, r, Block::text(x)));
    }
  return finish(b);
}

EmittedBody forwardDynamicsBody(const RobotModel & rm, const FdOptions & opt)
{
  Block b;
  const auto nv = static_cast<std::size_t>(rm.nv);
  std::vector<std::vector<Scalar>> L = emitMassMatrix(b, rm, opt.armature);
  // Right-hand side: tau - C.
  std::vector<Scalar> x(nv);
  if(opt.biasCall.empty())
    for(std::size_t i = 0; i < nv; ++i) x[i] = Scalar::var(fmt::format("tau[{}]", i));
  else
  {
    b.line("const Tangent<S> C = " + opt.biasCall + ";");
    for(std::size_t i = 0; i < nv; ++i) x[i] = b.sum({Term{1.0, {Scalar::var(fmt::format("tau[{}]", i))}}, Term{-1.0, {Scalar::var(fmt::format("C[{}]", i))}}}, fmt::format("x{}", i));
  }
  const std::vector<int> lambda = dofParents(rm);
  b.comment("tree-sparse factorisation H = L^T D L (Featherstone, RBDA 6.5), in place on the lower triangle");
  std::vector<Scalar> invD(nv);
  for(std::size_t k = nv; k-- > 0;)
  {
    invD[k] = b.def("S(1) / " + Block::text(L[k][k]), fmt::format("invD{}", k));
    for(int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)])
    {
      const auto ii = static_cast<std::size_t>(i);
      const Scalar a = mul(b, L[k][ii], invD[k], fmt::format("L{}_{}", k, i));
      for(int j = i; j >= 0; j = lambda[static_cast<std::size_t>(j)])
      {
        const auto jj = static_cast<std::size_t>(j);
        L[ii][jj] = b.sum({Term{1.0, {L[ii][jj]}}, Term{-1.0, {L[k][jj], a}}}, fmt::format("H{}_{}", i, j));
      }
      L[k][ii] = a;
    }
  }
  b.comment("solve L^T D L alphaD = tau - C");
  for(std::size_t i = nv; i-- > 0;)
    for(int j = lambda[i]; j >= 0; j = lambda[static_cast<std::size_t>(j)])
    {
      const auto jj = static_cast<std::size_t>(j);
      x[jj] = b.sum({Term{1.0, {x[jj]}}, Term{-1.0, {L[i][jj], x[i]}}}, fmt::format("x{}", j));
    }
  for(std::size_t i = 0; i < nv; ++i) x[i] = mul(b, x[i], invD[i], fmt::format("x{}", i));
  for(std::size_t i = 0; i < nv; ++i)
    for(int j = lambda[i]; j >= 0; j = lambda[static_cast<std::size_t>(j)])
      x[i] = b.sum({Term{1.0, {x[i]}}, Term{-1.0, {L[i][static_cast<std::size_t>(j)], x[static_cast<std::size_t>(j)]}}}, fmt::format("x{}", i));
  for(std::size_t i = 0; i < nv; ++i) b.line(fmt::format("alphaD[{}] = {};", i, Block::text(x[i])));
  return finish(b);
}

EmittedBody jacobianBody(const RobotModel & rm)
{
  // Column of dof d of joint k (world axes, at the link origin p):
  //   [R s_w; R s_v + (R s_w) x (p - o_k)],  R = E_0_k^T, o_k = origin of joint k's frame.
  // Each joint's columns are emitted once; a link jumps to its owner's block, and every block
  // jumps to its parent's: the path to the root is walked by direct jumps (no per-link copies,
  // so the code grows with nv, not with the sum of the path lengths).
  Block b;
  b.line("const Eigen::Matrix<S, 3, 1> p = kin.pose[static_cast<std::size_t>(body)].translation;");
  Vec3 p;
  for(int c = 0; c < 3; ++c) p[c] = Scalar::var(fmt::format("p({})", c));
  emitPathWalk(b, rm, "jac", [&](std::size_t k, const MovingJoint & mj) {
    b.comment(fmt::format("joint '{}': its columns", mj.name));
    const JointKernel K = emitJointKernel(b, mj, "kin.q"); // S depends on q only for backward multi-dof joints
    const Xform X0 = kinFrame(static_cast<int>(k));
    const std::string h = fmt::format("J_{}", mj.tag);
    const Vec3 po = sub(b, p, X0.r, h + "_po");
    for(int d = 0; d < mj.nv; ++d)
    {
      const Motion & Sd = K.S[static_cast<std::size_t>(d)];
      const Vec3 w = tmul(b, X0.E, Sd.w, fmt::format("{}_w{}", h, d));
      const Vec3 v = add(b, tmul(b, X0.E, Sd.v, fmt::format("{}_Rv{}", h, d)), cross(b, w, po, fmt::format("{}_wxp{}", h, d)),
                         fmt::format("{}_v{}", h, d));
      const int col = mj.vIndex + d;
      for(int r = 0; r < 3; ++r)
      {
        if(!w[r].isZero()) b.line(fmt::format("J({}, {}) = {};", r, col, Block::text(w[r])));
        if(!v[r].isZero()) b.line(fmt::format("J({}, {}) = {};", r + 3, col, Block::text(v[r])));
      }
    }
  });
  return finish(b);
}

namespace
{

// com = (sum_k m_k o_k + E_0_k^T h_k + static first moment) / M, from the joints' world frames.
void writeCenterOfMass(Block & b, const RobotModel & rm, const std::vector<Xform> & X0)
{
  b.comment("com = (sum_k m_k o_k + E_0_k^T h_k + static first moment) / M");
  const Vec3 sum = emitTotalFirstMoment(b, rm, X0);
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  for(int c = 0; c < 3; ++c) b.line(fmt::format("com({}) = {};", c, Block::text(b.sum({Term{invM, {sum[c]}}}, fmt::format("com_{}", c)))));
}

} // namespace

EmittedBody centerOfMassBody(const RobotModel & rm)
{
  Block b;
  std::vector<Xform> X0;
  for(std::size_t k = 0; k < rm.joints.size(); ++k) X0.push_back(kinFrame(static_cast<int>(k)));
  writeCenterOfMass(b, rm, X0);
  return finish(b);
}

EmittedBody centerOfMassFromConfigBody(const RobotModel & rm)
{
  Block b;
  b.comment("joint frames only: the link poses of kinematics() are not needed");
  const auto K = emitKernels(b, rm, "q");
  writeCenterOfMass(b, rm, emitWorldPoses(b, rm, K));
  return finish(b);
}

namespace
{

// Forward pass on a set of joints (ascending, closed under parents): v = X v_p + S alpha and, when
// asked, a = X a_p + S alphaD + v x S alpha (no gravity). Joints outside the set read as zero.
void emitMotionPass(Block & b, const RobotModel & rm, const std::vector<JointKernel> & K, const std::vector<int> & set,
                    bool acceleration, bool withAlphaD, std::vector<Motion> & v, std::vector<Motion> & a)
{
  v.assign(rm.joints.size(), Motion::zero());
  a.assign(rm.joints.size(), Motion::zero());
  for(int k : set)
  {
    const auto kk = static_cast<std::size_t>(k);
    const MovingJoint & mj = rm.joints[kk];
    const std::string t = mj.tag;
    const Motion vJ = jointMotion(b, K[kk], "alpha", mj.vIndex, t + "_vJ");
    const Motion vp = mj.parent < 0 ? Motion::zero() : v[static_cast<std::size_t>(mj.parent)];
    v[kk] = add(b, toChild(b, mj, K[kk], vp, t + "_Xv"), vJ, t + "_v");
    if(!acceleration) continue;
    const Motion aJ = withAlphaD ? jointMotion(b, K[kk], "alphaD", mj.vIndex, t + "_aJ") : Motion::zero();
    const Motion ap = mj.parent < 0 ? Motion::zero() : a[static_cast<std::size_t>(mj.parent)];
    a[kk] = add(b, add(b, toChild(b, mj, K[kk], ap, t + "_Xa"), aJ, t + "_aa"), cross(b, v[kk], vJ, t + "_vxvJ"), t + "_a");
  }
}

std::vector<int> allJoints(const RobotModel & rm)
{
  std::vector<int> all;
  for(std::size_t k = 0; k < rm.joints.size(); ++k) all.push_back(static_cast<int>(k));
  return all;
}

void writeMotion(Block & b, const std::string & dst, const Motion & m)
{
  for(int i = 0; i < 3; ++i)
  {
    b.line(fmt::format("{}[{}] = {};", dst, i, Block::text(m.w[i])));
    b.line(fmt::format("{}[{}] = {};", dst, i + 3, Block::text(m.v[i])));
  }
}

EmittedBody linkMotions(const RobotModel & rm, bool acceleration)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  std::vector<Motion> v, a;
  emitMotionPass(b, rm, K, allJoints(rm), acceleration, true, v, a);
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    const BodyFrame & bf = rm.bodies[i];
    b.comment(fmt::format("link '{}'", bf.name));
    if(bf.owner < 0)
    {
      b.line(fmt::format("res[{}].setZero();", i));
      continue;
    }
    const Motion & m = acceleration ? a[static_cast<std::size_t>(bf.owner)] : v[static_cast<std::size_t>(bf.owner)];
    writeMotion(b, fmt::format("res[{}]", i), apply(b, constantXform(bf.X_owner_link), m, fmt::format("L{}", i)));
  }
  return finish(b);
}

} // namespace

EmittedBody bodyVelocitiesBody(const RobotModel & rm)
{
  return linkMotions(rm, false);
}

EmittedBody bodyAccelerationsBody(const RobotModel & rm)
{
  return linkMotions(rm, true);
}

EmittedBody jacobianDotTimesAlphaBody(const RobotModel & rm)
{
  // World frame (Pluecker coordinates at the world origin). Joint k's velocity contribution is
  // C_k = X_0_k^-1 (S_k alpha_k); the link's velocity is V = sum of C_k over its path and, at
  // alphaD = 0, its acceleration is A = sum_k V_k x C_k with V_k the sum up to k (the body-frame
  // recursion a_k = X a_p + v_k x vJ_k, summed in world coordinates). Writing V_k = V - U_k, U_k the
  // sum of the contributions leafward of k, and V x V = 0: A = sum_k C_k x U_k, accumulated while
  // walking from the link to the root (U += C_k after the term). Each joint's block is emitted
  // once; the walk is a chain of direct jumps, as in jacobian().
  Block b;
  b.line("const Eigen::Matrix<S, 3, 1> p = kin.pose[static_cast<std::size_t>(body)].translation;");
  b.line("Eigen::Matrix<S, 6, 1> U = Eigen::Matrix<S, 6, 1>::Zero(), A = Eigen::Matrix<S, 6, 1>::Zero();");
  auto motionVar = [](const std::string & name) {
    Motion m;
    for(int c = 0; c < 3; ++c)
    {
      m.w[c] = Scalar::var(fmt::format("{}({})", name, c));
      m.v[c] = Scalar::var(fmt::format("{}({})", name, c + 3));
    }
    return m;
  };
  const Motion U = motionVar("U"), A = motionVar("A");
  auto accumulate = [&](const std::string & dst, const Motion & m) {
    for(int c = 0; c < 3; ++c)
    {
      if(!m.w[c].isZero()) b.line(fmt::format("{}({}) += {};", dst, c, Block::text(m.w[c])));
      if(!m.v[c].isZero()) b.line(fmt::format("{}({}) += {};", dst, c + 3, Block::text(m.v[c])));
    }
  };
  emitPathWalk(b, rm, "jd", [&](std::size_t k, const MovingJoint & mj) {
    b.comment(fmt::format("joint '{}': A += C x U, U += C", mj.name));
    const JointKernel K = emitJointKernel(b, mj, "kin.q");
    const Motion vJ = jointMotion(b, K, "alpha", mj.vIndex, mj.tag + "_vJ");
    const Motion C = invApply(b, kinFrame(static_cast<int>(k)), vJ, mj.tag + "_C");
    accumulate("A", cross(b, C, U, mj.tag + "_CxU"));
    accumulate("U", C);
  });
  b.comment("angular: A_w; classical acceleration of the origin p: A_v + A_w x p + V_w x (V_v + V_w x p)");
  Vec3 p;
  for(int c = 0; c < 3; ++c) p[c] = Scalar::var(fmt::format("p({})", c));
  const Vec3 vp = add(b, U.v, cross(b, U.w, p, "Vwxp"), "vp");
  const Vec3 lin = add(b, add(b, A.v, cross(b, A.w, p, "Awxp"), "ap"), cross(b, U.w, vp, "Vwxvp"), "acc");
  writeMotion(b, "res", {A.w, lin});
  return finish(b);
}

EmittedBody comJacobianBody(const RobotModel & rm)
{
  Block b;
  const std::size_t n = rm.joints.size();
  // Subtree mass and first moment (world): M_j, h_j = sum over the subtree of m_k o_k + E_0_k^T h_k.
  std::vector<double> mass(n, 0.0);
  std::vector<Vec3> moment(n, Vec3::zero());
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    const Xform X0 = kinFrame(static_cast<int>(k));
    if(mj.inertia.mass() != 0.0)
    {
      moment[k] = add(b, moment[k], emitFirstMoment(b, mj, X0), mj.tag + "_hs");
    }
    mass[k] += mj.inertia.mass();
    if(mj.parent >= 0)
    {
      const auto p = static_cast<std::size_t>(mj.parent);
      mass[p] += mass[k];
      moment[p] = add(b, moment[p], moment[k], rm.joints[p].tag + "_hs");
    }
  }
  // Column of dof d of joint j: (w x (h_j - M_j o_j) + M_j R s_v) / M, with w = R s_w.
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const JointKernel K = emitJointKernel(b, mj, "kin.q");
    const Xform X0 = kinFrame(static_cast<int>(k));
    const Vec3 rel = sub(b, moment[k], scale(b, Scalar::constant(mass[k]), X0.r, mj.tag + "_Mo"), mj.tag + "_rel");
    for(int d = 0; d < mj.nv; ++d)
    {
      const Motion & Sd = K.S[static_cast<std::size_t>(d)];
      const std::string h = fmt::format("{}_c{}", mj.tag, d);
      const Vec3 w = tmul(b, X0.E, Sd.w, h + "_w");
      const Vec3 col = add(b, cross(b, w, rel, h + "_wxh"), scale(b, Scalar::constant(mass[k]), tmul(b, X0.E, Sd.v, h + "_Rv"), h + "_Mv"), h);
      for(int r = 0; r < 3; ++r)
      {
        const Scalar x = b.sum({Term{invM, {col[r]}}}, fmt::format("{}_{}", h, r));
        if(!x.isZero()) b.line(fmt::format("J({}, {}) = {};", r, mj.vIndex + d, Block::text(x)));
      }
    }
  }
  return finish(b);
}

EmittedBody centroidalMomentumMatrixBody(const RobotModel & rm)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const auto X0 = emitWorldPoses(b, rm, K);
  const std::size_t n = rm.joints.size();
  const std::vector<Inertia> Ic = emitCompositeInertias(b, rm, K);
  const Vec3 sum = emitTotalFirstMoment(b, rm, X0);
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  const Vec3 com = scale(b, Scalar::constant(invM), sum, "com");
  // Column: momentum of the subtree moving with S: X_0_j^T (Ic_j S) in world at the origin, then
  // about the CoM: n_G = n_O - com x f.
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    for(int d = 0; d < mj.nv; ++d)
    {
      const std::string h = fmt::format("{}_A{}", mj.tag, d);
      const Force F = apply(b, Ic[k], K[k].S[static_cast<std::size_t>(d)], h + "_F");
      const Force Fw = transApply(b, X0[k], F, h + "_Fw");
      const Vec3 nG = sub(b, Fw.n, cross(b, com, Fw.f, h + "_cxf"), h + "_nG");
      for(int r = 0; r < 3; ++r)
      {
        if(!nG[r].isZero()) b.line(fmt::format("A({}, {}) = {};", r, mj.vIndex + d, Block::text(nG[r])));
        if(!Fw.f[r].isZero()) b.line(fmt::format("A({}, {}) = {};", r + 3, mj.vIndex + d, Block::text(Fw.f[r])));
      }
    }
  }
  return finish(b);
}

} // namespace rbdgen::emit
