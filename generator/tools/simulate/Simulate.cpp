// `rbdgen simulate`: scene -> runtime simulation -> CSV (+ gnuplot script and PNG).
// Files are written under temporary names and renamed only when the run succeeded.
#include "Simulate.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include <rbd/scene/Controller.h>
#include <rbd/scene/Integrators.h>
#include <rbd/scene/SceneDynamics.h>
#include <rbd/scene/SceneLoader.h>

namespace rbdgen::simulate
{

namespace fs = std::filesystem;

namespace
{

/// At most this many CSV rows: longer runs write every k-th step (and the last).
constexpr long maxRows = 20000;

/// A file written to path + ".rbdgen-tmp", renamed by commit(), removed if never committed.
class StagedFile
{
public:
  explicit StagedFile(std::string path) : path_(std::move(path)), tmp_(path_ + ".rbdgen-tmp"), out_(tmp_)
  {
    if(!out_) throw std::runtime_error(path_ + ": cannot write file");
  }
  ~StagedFile()
  {
    if(!committed_)
    {
      out_.close();
      std::error_code ec;
      fs::remove(tmp_, ec);
    }
  }
  std::ofstream & out() { return out_; }
  void commit()
  {
    out_.close();
    if(!out_) throw std::runtime_error(path_ + ": cannot write file");
    fs::rename(tmp_, path_);
    committed_ = true;
  }

private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

std::string shellQuote(const std::string & s)
{
  std::string q = "'";
  for(char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Progress in percent: a rewritten line on a terminal, else one line every 10 %.
class Progress
{
public:
  Progress(std::ostream & os, long steps) : os_(os), steps_(steps), tty_(isatty(STDERR_FILENO) != 0) {}
  void update(long step)
  {
    if(steps_ < 2000) return; // short runs: no progress indication
    const int pct = static_cast<int>(100 * step / steps_);
    if(pct == last_) return;
    if(tty_) os_ << "\rsimulate: " << std::setw(3) << pct << "%" << (pct == 100 ? "\n" : "") << std::flush;
    else if(pct / 10 != last_ / 10) os_ << "simulate: " << pct << "%\n" << std::flush;
    last_ = pct;
  }

private:
  std::ostream & os_;
  long steps_;
  bool tty_;
  int last_ = -1;
};

} // namespace

rbd::scene::Integrator parseIntegrator(const std::string & name)
{
  if(name == "semi_implicit_euler") return rbd::scene::Integrator::SemiImplicitEuler;
  if(name == "explicit_euler") return rbd::scene::Integrator::ExplicitEuler;
  if(name == "rk4") return rbd::scene::Integrator::RK4;
  throw std::invalid_argument("--integrator '" + name + "': expected semi_implicit_euler, explicit_euler or rk4");
}

std::vector<std::string> csvHeader(const rbd::MultiBody & mb, const rbd::scene::Scene & scene)
{
  std::vector<std::string> h{"t"};
  for(const char * prefix : {"q_", "alpha_"})
    for(const rbd::Joint & j : mb.joints())
    {
      const int n = std::string(prefix) == "q_" ? j.params() : j.dof();
      for(int k = 0; k < n; ++k) h.push_back(prefix + j.name() + (n > 1 ? "_" + std::to_string(k) : ""));
    }
  for(const char * e : {"kinetic", "potential", "contact_energy", "total_energy"}) h.push_back(e);
  for(const auto & c : scene.contacts) h.push_back("fn_" + c.name);
  return h;
}

SimulateResult runSimulation(const SimulateOptions & o, std::ostream & progress)
{
  using namespace rbd::scene;
  Scene scene = loadScene(o.scene);
  if(o.duration) scene.duration = *o.duration;
  if(o.dt) scene.dt = *o.dt;
  if(o.integrator) scene.integrator = *o.integrator;
  if(!(scene.dt > 0) || !std::isfinite(scene.dt)) throw std::invalid_argument("--dt must be > 0");
  if(!(scene.duration > 0) || !std::isfinite(scene.duration)) throw std::invalid_argument("--duration must be > 0");
  const SceneRobot robot = loadSceneRobot(scene);
  const SceneDynamics dyn(robot, scene);

  SimulateResult r;
  const std::string stem = fs::path(o.scene).stem().string();
  r.csv = o.csv.empty() ? stem + ".csv" : o.csv;
  const std::string png = o.png.empty() ? fs::path(r.csv).replace_extension(".png").string() : o.png;
  r.gp = fs::path(r.csv).replace_extension(".gp").string();

  const long steps = std::max(1L, std::lround(scene.duration / scene.dt));
  const long every = std::max(1L, (steps + maxRows - 1) / maxRows);
  SceneState<double> s = initialState(dyn);
  const SceneController controller(dyn, s);
  const std::vector<std::string> header = csvHeader(robot.robot.mb, scene);

  StagedFile csv(r.csv);
  csv.out() << std::setprecision(10);
  for(std::size_t c = 0; c < header.size(); ++c) csv.out() << (c ? "," : "") << header[c];
  csv.out() << "\n";
  Progress bar(progress, steps);
  auto writeRow = [&](double t) {
    const double T = dyn.kineticEnergy(s.q, s.alpha), V = dyn.potentialEnergy(s.q), C = dyn.contactEnergy(s.q);
    if(!std::isfinite(T + V + C) || !s.q.allFinite() || !s.alpha.allFinite())
      throw std::runtime_error("simulation diverged at t = " + std::to_string(t) + " s (try a smaller --dt or rk4)");
    csv.out() << t;
    for(Eigen::Index k = 0; k < s.q.size(); ++k) csv.out() << "," << s.q[k];
    for(Eigen::Index k = 0; k < s.alpha.size(); ++k) csv.out() << "," << s.alpha[k];
    csv.out() << "," << T << "," << V << "," << C << "," << T + V + C;
    for(const auto & f : dyn.contactForces(s.q, s.alpha)) csv.out() << "," << f.z();
    csv.out() << "\n";
    ++r.rows;
    return T + V + C;
  };
  r.energyStart = writeRow(0.0);
  r.energyEnd = r.energyStart;
  for(long k = 1; k <= steps; ++k)
  {
    step(dyn, s, controller.torque(s.q, s.alpha), scene.dt, scene.integrator);
    if(k % every == 0 || k == steps) r.energyEnd = writeRow(static_cast<double>(k) * scene.dt);
    bar.update(k);
  }
  r.steps = steps;

  if(!o.plot)
  {
    csv.commit();
    return r;
  }
  StagedFile gp(r.gp);
  gp.out() << gnuplotScript(fs::path(r.csv).filename().string(), fs::path(png).filename().string(), header,
                            scene.name + " (" + fs::path(o.scene).filename().string() + ")");
  csv.commit();
  gp.commit();
  // gnuplot runs in the CSV's directory, the PNG is written there and moved into place.
  const fs::path dir = fs::absolute(r.csv).parent_path();
  const fs::path pngInDir = dir / fs::path(png).filename();
  if(std::system("command -v gnuplot >/dev/null 2>&1") != 0)
  {
    r.warnings.push_back("gnuplot not found (apt-get install gnuplot-nox): wrote " + r.csv + " and " + r.gp +
                         ", no " + png);
    return r;
  }
  const std::string cmd = "cd " + shellQuote(dir.string()) + " && gnuplot " +
                          shellQuote(fs::path(r.gp).filename().string()) + " 2>" + shellQuote(r.gp + ".log");
  const int status = std::system(cmd.c_str());
  std::error_code ec;
  if(status != 0 || !fs::exists(pngInDir))
  {
    r.warnings.push_back("gnuplot failed (see " + r.gp + ".log): no " + png);
    return r;
  }
  fs::remove(r.gp + ".log", ec);
  if(fs::absolute(png) != pngInDir) fs::rename(pngInDir, png);
  r.png = png;
  return r;
}

} // namespace rbdgen::simulate
