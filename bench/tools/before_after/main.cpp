// The functions of headers from two generators (before, after) in one binary: agreement first,
// then alternating timed runs; a Markdown table on stdout.
//   before_after [--raw] [--functions NAME;NAME...] ROBOT[:LINK[,LINK...]] ...
// A function that takes a Body is timed on each LINK given; the others once per robot. --raw: one
// tab-separated line per row instead (robot, function, link, before ns, after ns, difference), for
// before_after.sh to merge the runs of several code layouts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Case.h"

std::vector<HeaderCase> & headerCases()
{
  static std::vector<HeaderCase> cases;
  return cases;
}

namespace
{

const HeaderCase * find(const std::string & robot, const std::string & version)
{
  for(const HeaderCase & c : headerCases())
    if(c.robot == robot && c.version == version) return &c;
  return nullptr;
}

const FunctionCase * function(const HeaderCase & c, const std::string & name)
{
  for(const FunctionCase & f : c.functions)
    if(f.name == name) return &f;
  return nullptr;
}

// Random states: angles, velocities and accelerations in [-1, 1], wrenches in [-10, 10], a unit
// quaternion in the first 4 entries of q when nq > nv (a free base at the root).
std::vector<State> states(const HeaderCase & c, int count)
{
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<State> out(static_cast<std::size_t>(count));
  for(State & s : out)
  {
    for(int i = 0; i < c.nq; ++i) s.q.push_back(u(rng));
    if(c.nq > c.nv)
    {
      const double n = std::sqrt(s.q[0] * s.q[0] + s.q[1] * s.q[1] + s.q[2] * s.q[2] + s.q[3] * s.q[3]);
      for(int i = 0; i < 4; ++i) s.q[static_cast<std::size_t>(i)] /= n;
    }
    for(int i = 0; i < c.nv; ++i) s.alpha.push_back(u(rng));
    for(int i = 0; i < c.nv; ++i) s.alphaD.push_back(u(rng));
    for(int i = 0; i < 6 * c.nbodies; ++i) s.fext.push_back(10 * u(rng));
  }
  return out;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Largest difference between the two versions over every state and entry, relative to
// max(1, largest magnitude).
double disagreement(const FunctionCase & fb, const FunctionCase & fa, int bb, int ba, const std::vector<State> & s)
{
  double diff = 0, scale = 1;
  std::vector<double> rb, ra;
  for(const State & x : s)
  {
    fb.eval(bb, x, rb);
    fa.eval(ba, x, ra);
    if(rb.size() != ra.size()) return INFINITY;
    for(std::size_t i = 0; i < rb.size(); ++i)
    {
      diff = std::max(diff, std::abs(rb[i] - ra[i]));
      scale = std::max(scale, std::abs(rb[i]));
    }
  }
  return diff / scale;
}

} // namespace

int main(int argc, char ** argv)
{
  std::vector<std::string> only, specs;
  bool raw = false;
  for(int a = 1; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if(arg == "--raw") raw = true;
    else if(arg == "--functions" && a + 1 < argc)
    {
      std::stringstream names(argv[++a]);
      for(std::string n; std::getline(names, n, ';');) only.push_back(n);
    }
    else specs.push_back(arg);
  }
  if(!raw)
    std::printf("| robot | function | link | before ns | after ns | before / after | max difference (relative) |\n"
                "|---|---|---|--:|--:|--:|--:|\n");
  int status = 0;
  for(const std::string & spec : specs)
  {
    const std::string robot = spec.substr(0, spec.find(':'));
    std::vector<std::string> links;
    if(spec.find(':') != std::string::npos)
    {
      std::stringstream l(spec.substr(spec.find(':') + 1));
      for(std::string link; std::getline(l, link, ',');) links.push_back(link);
    }
    const HeaderCase * before = find(robot, "before");
    const HeaderCase * after = find(robot, "after");
    if(!before || !after || before->nq != after->nq || before->nv != after->nv || before->nbodies != after->nbodies)
    {
      std::fprintf(stderr, "before_after: no matching before/after headers for '%s'\n", robot.c_str());
      return 2;
    }
    const std::vector<State> s = states(*before, 256);
    for(const FunctionCase & fa : after->functions)
    {
      if(!only.empty() && std::find(only.begin(), only.end(), fa.name) == only.end()) continue;
      const FunctionCase * fb = function(*before, fa.name);
      if(!fb) continue;
      std::vector<std::string> on = fa.link ? links : std::vector<std::string>{"-"};
      for(const std::string & link : on)
      {
        const int bb = fa.link ? before->body(link) : 0, ba = fa.link ? after->body(link) : 0;
        if(bb < 0 || ba < 0)
        {
          std::fprintf(stderr, "before_after: %s has no link '%s'\n", robot.c_str(), link.c_str());
          return 2;
        }
        const double diff = disagreement(*fb, fa, bb, ba, s);
        if(!(diff < 1e-12))
        {
          std::fprintf(stderr, "before_after: %s %s disagrees: %.1e\n", robot.c_str(), fa.name.c_str(), diff);
          status = 1;
        }
        // about 20 ms a run, 9 alternating runs each (run r places the data as Wrapper.cpp's time says),
        // the median of each
        const double estimate = std::max(fa.time(ba, s, 2000, 0), 1.0);
        const int iters = static_cast<int>(std::max(2000.0, 2e7 / estimate));
        std::vector<double> tb, ta;
        for(int r = 0; r < 9; ++r)
        {
          tb.push_back(fb->time(bb, s, iters, r));
          ta.push_back(fa.time(ba, s, iters, r));
        }
        const double mb = median(tb), ma = median(ta);
        if(raw) std::printf("%s\t%s\t%s\t%.1f\t%.1f\t%.1e\n", robot.c_str(), fa.name.c_str(), link.c_str(), mb, ma, diff);
        else
          std::printf("| %s | %s | %s | %.1f | %.1f | %.2f× | %.1e |\n", robot.c_str(), fa.name.c_str(), link.c_str(),
                      mb, ma, mb / ma, diff);
        std::fflush(stdout);
      }
    }
  }
  return status;
}
