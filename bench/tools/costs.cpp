// Cost model: floating-point operations emitted per generated function (multiplications,
// additions, calls = sin/cos/sqrt/divisions...), next to Featherstone's counts for the same nv.
//
//   bench_costs name=urdf[:floating] ...      CSV on stdout:
//   robot,nv,algo,mults,adds,calls,sincos,feather_mults,feather_adds
// Featherstone's counts (RBDA, tables 5.x/6.x/7.x) hold for an unbranched chain of n revolute
// joints: RNEA (93n-69)m + (81n-66)a, CRBA (10n^2+22n-32)m + (6n^2+37n-43)a,
// ABA (224n-259)m + (205n-248)a; for a branched or floating robot they are given with n = nv as
// an indication only.
#include <cstdio>
#include <string>

#include <Generate.h>
#include <emit/Functions.h>

namespace
{

long countOf(const std::string & text, const std::string & what)
{
  long n = 0;
  for(std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

void row(const std::string & robot, int nv, const std::string & algo, const std::vector<rbdgen::emit::EmittedBody> & parts,
         long fm = -1, long fa = -1)
{
  long m = 0, a = 0, c = 0, sc = 0;
  for(const auto & p : parts)
  {
    m += p.ops.mults;
    a += p.ops.adds;
    c += p.ops.calls;
    sc += countOf(p.text, "sin(") + countOf(p.text, "cos(");
  }
  std::printf("%s,%d,%s,%ld,%ld,%ld,%ld,%s,%s\n", robot.c_str(), nv, algo.c_str(), m, a, c, sc,
              fm < 0 ? "" : std::to_string(fm).c_str(), fa < 0 ? "" : std::to_string(fa).c_str());
}

} // namespace

int main(int argc, char ** argv)
{
  namespace emit = rbdgen::emit;
  std::printf("robot,nv,algo,mults,adds,calls,sincos,feather_mults,feather_adds\n");
  for(int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    const auto eq = arg.find('=');
    if(eq == std::string::npos)
    {
      std::fprintf(stderr, "bench_costs: argument '%s': expected name=urdf[:floating]\n", argv[i]);
      return 1;
    }
    const std::string name = arg.substr(0, eq);
    std::string urdf = arg.substr(eq + 1);
    bool floating = false;
    if(urdf.size() > 9 && urdf.compare(urdf.size() - 9, 9, ":floating") == 0)
    {
      floating = true;
      urdf.resize(urdf.size() - 9);
    }
    try
    {
      rbd::parsers::ParserOptions opt;
      opt.fixed = !floating;
      const rbd::parsers::ParserResult robot = rbd::parsers::fromUrdfFile(urdf, opt);
      const rbdgen::RobotModel rm = rbdgen::robotModelFromUrdf(robot);
      const long n = rm.nv;
      const auto nle = emit::rneaBody(rm, {true, false, true});
      const auto kin = emit::linkPosesCallBody(rm, "kin.pose", true); // (kinematics(q): what jacobian and com read)
      row(name, rm.nv, "fk", {emit::forwardKinematicsBody(rm)});
      row(name, rm.nv, "fk_vel", {emit::bodyVelocitiesBody(rm)});
      row(name, rm.nv, "id", {emit::rneaBody(rm, {true, true, true})}, 93 * n - 69, 81 * n - 66);
      row(name, rm.nv, "gravity", {emit::rneaBody(rm, {false, false, true})});
      row(name, rm.nv, "nle", {nle});
      row(name, rm.nv, "mass_matrix", {emit::massMatrixLowerBody(rm).body}, 10 * n * n + 22 * n - 32, 6 * n * n + 37 * n - 43);
      row(name, rm.nv, "fd_crba", {emit::forwardDynamicsBody(rm), nle});
      row(name, rm.nv, "fd_aba", {emit::abaBody(rm)}, 224 * n - 259, 205 * n - 248);
      row(name, rm.nv, "jacobian", {kin, emit::jacobianBody(rm)});
      row(name, rm.nv, "com", {kin, emit::centerOfMassBody(rm)});
    }
    catch(const std::exception & e)
    {
      std::fprintf(stderr, "bench_costs: %s\n", e.what());
      return 1;
    }
  }
  return 0;
}
