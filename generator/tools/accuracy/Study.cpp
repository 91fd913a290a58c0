#include "Study.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <rbd/parsers/urdf.h>
#include <rbd/scene/SceneLoader.h>

#include "Driver.h"
#include "Reference.h"
#include "Report.h"
#include "RuntimeVariants.h"
#include "StaticStudy.h"
#include "States.h"

namespace rbdgen::accuracy
{
namespace fs = std::filesystem;

namespace
{

/// A fresh directory under the system temporary directory, removed with its content.
class ScratchDir
{
public:
  ScratchDir()
  {
    std::string tmpl = (fs::temp_directory_path() / "rbdgen-accuracy-XXXXXX").string();
    if(!mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary directory in " + fs::temp_directory_path().string());
    path_ = tmpl;
  }
  ~ScratchDir()
  {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir &) = delete;
  ScratchDir & operator=(const ScratchDir &) = delete;
  const fs::path & path() const { return path_; }

private:
  fs::path path_;
};

void progress(const std::string & what)
{
  if(isatty(2)) std::cerr << "rbdgen accuracy: " << what << "\n";
}

void writeText(const fs::path & p, const std::string & text)
{
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
  if(!out) throw std::runtime_error(p.string() + ": cannot write");
}

bool haveGnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

} // namespace

void checkOutputDirectory(const std::string & dir)
{
  fs::path p = fs::absolute(dir);
  std::error_code ec;
  if(fs::exists(p, ec) && !fs::is_directory(p, ec)) throw std::runtime_error(dir + ": --out exists and is not a directory");
  while(!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if(!fs::is_directory(p, ec)) throw std::runtime_error(dir + ": --out cannot be created (" + p.string() + " is not a directory)");
  if(access(p.c_str(), W_OK | X_OK) != 0) throw std::runtime_error(dir + ": --out is not writable (" + p.string() + ")");
}

std::vector<std::string> runStudy(const StudyOptions & opt)
{
  checkOutputDirectory(opt.outDir);
  if(opt.states < 1) throw std::runtime_error("--states must be at least 1");
  // The robot: the scene's, or the URDF with the base options.
  rbd::scene::Scene scene;
  if(!opt.scene.empty())
    scene = rbd::scene::loadScene(opt.scene);
  else
  {
    scene.file = opt.urdf;
    scene.name = fs::path(opt.urdf).stem().string();
    scene.urdf = opt.urdf;
    scene.floatingBase = opt.floatingBase;
    scene.baseLink = opt.baseLink;
  }
  rbd::parsers::ParserOptions po;
  po.fixed = !scene.floatingBase;
  po.baseLink = scene.baseLink;
  const rbd::parsers::ParserResult robot = rbd::parsers::fromUrdfFile(scene.urdf, po);
  const int nq = robot.mb.nrParams(), nv = robot.mb.nrDof();

  StudyResults res;
  res.info.robot = opt.scene.empty() ? robot.name : robot.name + " (scene '" + scene.name + "')";
  res.info.urdf = opt.scene.empty() ? opt.urdf : scene.urdf;
  if(!opt.scene.empty()) res.info.options += " --scene " + opt.scene;
  if(scene.floatingBase && opt.scene.empty()) res.info.options += " --floating-base";
  if(!scene.baseLink.empty() && opt.scene.empty()) res.info.options += " --base-link " + scene.baseLink;
  res.info.nq = nq;
  res.info.nv = nv;
  res.info.states = opt.states;
  res.info.seed = opt.seed;
  res.info.compiler = defaultCompiler(opt.cxx) + " -O3 -march=native";

  const std::vector<State> states = randomStates(robot.mb, opt.states, opt.seed);
  progress("long double reference");
  const Reference ref = computeReference(robot, states, opt.derivatives);
  std::vector<double> cond = ref.condH;
  std::sort(cond.begin(), cond.end());
  res.info.condHMedian = cond[cond.size() / 2];
  res.info.condHMax = cond.back();

  ScratchDir scratch;
  progress("generating and compiling the driver in " + scratch.path().string());
  DriverOptions dopt;
  dopt.urdf = scene.urdf;
  dopt.floatingBase = scene.floatingBase;
  dopt.baseLink = scene.baseLink;
  dopt.cxx = opt.cxx;
  dopt.derivatives = opt.derivatives;
  dopt.scratchDir = scratch.path().string();
  std::vector<VariantResult> variants = runGeneratedVariants(dopt, states, nq, nv);
  progress("timing the runtime");
  for(VariantResult & v : runRuntimeVariants(robot, states, opt.derivatives)) variants.push_back(std::move(v));
  res.staticRows = evaluateStatic(variants, ref);

  if(opt.simulation)
  {
    progress("simulation study");
    SimulationOptions sim = opt.sim;
    sim.randomInitialState = opt.scene.empty();
    sim.seed = opt.seed;
    res.simulation = runSimulationStudy(scene, sim);
  }

  // Render into the scratch directory, plot there, then move everything into DIR.
  const fs::path stage = scratch.path() / "out";
  fs::create_directories(stage);
  std::vector<std::string> names;
  for(const auto & [name, text] : renderReport(res))
  {
    writeText(stage / name, text);
    names.push_back(name);
  }
  if(opt.plots && haveGnuplot())
  {
    for(const auto & [name, text] : renderReport(res))
    {
      if(fs::path(name).extension() != ".gp") continue;
      const std::string cmd = "cd '" + stage.string() + "' && gnuplot '" + name + "' >gnuplot.log 2>&1";
      if(std::system(cmd.c_str()) != 0) throw std::runtime_error("gnuplot failed on " + name);
    }
    for(const std::string & png : plotImages(res))
    {
      if(!fs::exists(stage / png)) throw std::runtime_error("gnuplot did not write " + png);
      names.push_back(png);
    }
  }
  else if(opt.plots)
    std::cerr << "rbdgen: warning: gnuplot not found: " << opt.outDir << " has the .dat and .gp files but no PNG\n";

  fs::create_directories(opt.outDir);
  std::vector<std::string> written;
  for(const std::string & name : names)
  {
    const fs::path dst = fs::path(opt.outDir) / name, tmp = fs::path(opt.outDir) / ("." + name + ".tmp");
    fs::copy_file(stage / name, tmp, fs::copy_options::overwrite_existing);
    fs::rename(tmp, dst);
    written.push_back(dst.string());
  }
  return written;
}

} // namespace rbdgen::accuracy
