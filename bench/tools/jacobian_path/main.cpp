// jacobian(body, q) of headers from two generators (before, after) in one binary: agreement first,
// then alternating timed runs; a Markdown table on stdout.
//   jacobian_path ROBOT:LINK[,LINK...] ...
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Case.h"

std::vector<JacobianCase> & jacobianCases()
{
  static std::vector<JacobianCase> cases;
  return cases;
}

namespace
{

const JacobianCase * find(const std::string & robot, const std::string & version)
{
  for(const JacobianCase & c : jacobianCases())
    if(c.robot == robot && c.version == version) return &c;
  return nullptr;
}

// Random states: angles in [-1, 1], unit quaternions in the first 4 entries of a free base (nq > nv).
std::vector<double> states(const JacobianCase & c, int count)
{
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> s(static_cast<std::size_t>(count * c.nq));
  for(int k = 0; k < count; ++k)
  {
    double * q = s.data() + k * c.nq;
    for(int i = 0; i < c.nq; ++i) q[i] = u(rng);
    if(c.nq > c.nv)
    {
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      for(int i = 0; i < 4; ++i) q[i] /= n;
    }
  }
  return s;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char ** argv)
{
  std::printf("| robot | link | before ns | after ns | before / after | max abs difference |\n|---|---|--:|--:|--:|--:|\n");
  int status = 0;
  for(int a = 1; a < argc; ++a)
  {
    const std::string spec = argv[a];
    const std::string robot = spec.substr(0, spec.find(':'));
    const JacobianCase * before = find(robot, "before");
    const JacobianCase * after = find(robot, "after");
    if(!before || !after || before->nq != after->nq || before->nv != after->nv)
    {
      std::fprintf(stderr, "jacobian_path: no matching before/after headers for '%s'\n", robot.c_str());
      return 2;
    }
    const int count = 1024;
    const std::vector<double> s = states(*before, count);
    std::stringstream links(spec.substr(spec.find(':') + 1));
    for(std::string link; std::getline(links, link, ',');)
    {
      const int bb = before->body(link), ba = after->body(link);
      if(bb < 0 || ba < 0)
      {
        std::fprintf(stderr, "jacobian_path: %s has no link '%s'\n", robot.c_str(), link.c_str());
        return 2;
      }
      // agreement: every state, every entry
      double diff = 0;
      std::vector<double> Jb(static_cast<std::size_t>(6 * before->nv)), Ja(Jb.size());
      for(int k = 0; k < count; ++k)
      {
        before->eval(bb, s.data() + k * before->nq, Jb.data());
        after->eval(ba, s.data() + k * after->nq, Ja.data());
        for(std::size_t i = 0; i < Jb.size(); ++i) diff = std::max(diff, std::abs(Jb[i] - Ja[i]));
      }
      if(!(diff < 1e-12)) status = 1;
      // alternating runs, the median of each
      std::vector<double> tb, ta;
      const int iters = 200000;
      for(int r = 0; r < 9; ++r)
      {
        tb.push_back(before->time(bb, s.data(), count, iters));
        ta.push_back(after->time(ba, s.data(), count, iters));
      }
      const double mb = median(tb), ma = median(ta);
      std::printf("| %s | %s | %.1f | %.1f | %.2f× | %.1e |\n", robot.c_str(), link.c_str(), mb, ma, mb / ma, diff);
    }
  }
  if(status) std::fprintf(stderr, "jacobian_path: before and after disagree (> 1e-12)\n");
  return status;
}
