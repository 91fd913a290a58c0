#include "Generate.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include <rbd/scene/SceneLoader.h>

#include "emit/Header.h"
#include "emit/Instantiations.h"
#include "emit/MimicCoupled.h"
#include "emit/RobotValues.h"
#include "emit/SceneHeader.h"
#include "util/Sha256.h"


namespace rbdgen
{
namespace fs = std::filesystem;

namespace
{

std::string readFile(const std::string & path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw std::runtime_error(path + ": cannot read file");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The loader's warnings (non-physical inertias, mimic joints, a floating joint used as the base,
/// ...) on stderr, "rbdgen: warning: ...": never an error.
void printLoaderWarnings(const std::vector<std::string> & warnings)
{
  for(const std::string & w : warnings) std::cerr << "rbdgen: warning: " << w << "\n";
}

/// The mass matrix policy (MassMatrixChecks.h): massless subtrees (in a scene: those without
/// armature), stacked free joints and negligible inertias are each a warning naming the joints,
/// the first one an error when strict.
void massMatrixPolicy(MassMatrixReport report, const std::vector<std::string> & singularJoints, const std::string & source,
                      bool strict)
{
  report.masslessSubtrees = singularJoints;
  const std::vector<std::string> lines = report.messages(source);
  if(strict && !lines.empty()) throw std::runtime_error(lines.front() + " [--strict]");
  for(const std::string & w : lines) std::cerr << "rbdgen: warning: " << w << "\n";
}

std::string checkedNamespace(const std::string & wanted, const std::string & fallback)
{
  const std::string ns = wanted.empty() ? sanitizeIdentifier(fallback) : wanted;
  if(ns != sanitizeIdentifier(ns)) throw std::invalid_argument("--namespace '" + ns + "': not a valid C++ identifier (or a keyword)");
  return ns;
}

// A model without a degree of freedom has no dynamics to generate (and no zero-size arrays in C++).
void requireDofs(const RobotModel & rm, const std::string & file, const std::string & robotName)
{
  if(rm.nv == 0)
    throw std::invalid_argument(fmt::format("{}: robot '{}': no moving joint (every joint fixed, fixed base): nothing to "
                                            "generate; a free body needs --floating-base (in a scene: <robot ... base=\"floating\"/>)",
                                            file, robotName));
}

std::vector<GeneratedFile> generateScene(const GenerateOptions & opt, std::vector<std::string> * inputs)
{
  if(!opt.urdf.empty())
    throw std::invalid_argument(opt.scene + ": give either a URDF or --scene (the scene names its URDF), not both");
  if(opt.floatingBase || !opt.baseLink.empty())
    throw std::invalid_argument(opt.scene + ": --floating-base and --base-link come from the scene with --scene");
  if(opt.instantiate) throw std::invalid_argument(opt.scene + ": --instantiate takes a URDF (not a scene)");
  rbd::scene::Scene scene = rbd::scene::loadScene(opt.scene);
  // --derivatives adds the scene's <derivatives/>; --batch its <kinematics/> (the batch API's
  // forward_kinematics, jacobian and center_of_mass)
  scene.outputs.derivatives = scene.outputs.derivatives || opt.derivatives;
  scene.outputs.kinematics = scene.outputs.kinematics || opt.batch;
  const rbd::scene::SceneRobot sr = rbd::scene::loadSceneRobot(scene);
  const RobotModel rm = robotModelFromUrdf(sr.robot);
  requireDofs(rm, opt.scene, sr.robot.name);
  const std::string ns = checkedNamespace(opt.ns, scene.name.empty() ? sr.robot.name : scene.name);
  const emit::SceneEffects fx = emit::sceneEffects(rm, scene, sr);
  printLoaderWarnings(sr.robot.warnings);
  std::vector<std::string> mimicWarnings;
  const rbd::parsers::MimicCoupling coupling =
      opt.independentMimic ? rbd::parsers::MimicCoupling{} : rbd::parsers::coupleMimics(sr.robot, scene.urdf, &mimicWarnings);
  if(opt.independentMimic)
    for(const std::string & m : rbd::parsers::coupleMimics(sr.robot, scene.urdf, nullptr).coupled)
      mimicWarnings.push_back(opt.scene + ": mimic joint not coupled (--independent-mimic), its own dof: " + m);
  printLoaderWarnings(mimicWarnings);
  // The singular joints of the system the API solves: the coupled one when mimic joints are coupled.
  std::vector<std::string> singular = emit::unregularisedMasslessJoints(rm, fx);
  if(!coupling.empty())
  {
    const std::vector<std::string> groups = emit::coupledMasslessJoints(rm, coupling);
    singular.erase(std::remove_if(singular.begin(), singular.end(),
                                  [&](const std::string & j) { return std::find(groups.begin(), groups.end(), j) == groups.end(); }),
                   singular.end());
  }
  massMatrixPolicy(rm.checks, singular, opt.scene, opt.strict);
  const std::string sceneText = readFile(opt.scene), urdfText = readFile(scene.urdf);
  std::string p;
  p += emit::generatedByLine() + "\n";
  p += fmt::format("// Scene: {} (sha256 {})\n", fs::path(opt.scene).filename().string(), sha256Hex(sceneText));
  p += fmt::format("// Robot: {} (sha256 {}), {}{}\n", fs::path(scene.urdf).filename().string(), sha256Hex(urdfText),
                   scene.floatingBase ? "floating base" : "fixed base",
                   scene.baseLink.empty() ? "" : ", base link " + scene.baseLink);
  p += fmt::format("// Effects: {}.\n", emit::describeEffects(scene, fx));
  const std::string options = fmt::format("{}{}{}", opt.derivatives ? ", derivatives" : "", opt.batch ? ", batch" : "",
                                          opt.independentMimic ? ", independent mimic joints" : "");
  if(!options.empty()) p += fmt::format("// Options: {}.\n", options.substr(2));
  p += emit::robotSummaryLine(rm);
  if(inputs) *inputs = {fs::absolute(opt.scene).lexically_normal().string(), fs::absolute(scene.urdf).lexically_normal().string()};
  std::vector<GeneratedFile> files{
      GeneratedFile{ns + "/dynamics.hpp", emit::emitDynamicsHeader(rm, emit::sceneHeaderSpec(rm, scene, sr, ns, p, coupling))}};
  if(opt.batch)
  {
    emit::BatchFunctions bf;
    bf.forwardDynamics = coupling.empty() ? emit::hasForwardDynamics(rm, fx)
                                          : emit::coupledSceneForwardDynamics(rm, fx, coupling);
    bf.derivatives = scene.outputs.derivatives;
    bf.gravityTorques = fx.gravity.has_value();
    bf.nonlinearEffects = fx.gravity.has_value() || fx.velocityTerms;
    bf.wrenches = !fx.wrenchBodies.empty();
    bf.massMatrixLower = coupling.empty();
    files.push_back(GeneratedFile{ns + "/batch.hpp", emit::emitBatchHeader(ns, coupling.empty() ? ns : ns + "::independent", p, bf)});
  }
  return files;
}

} // namespace

RobotModel robotModelFromUrdf(const rbd::parsers::ParserResult & robot)
{
  std::vector<sva::PTransformd> X_mb_link;
  for(const auto & b : robot.mb.bodies())
  {
    const auto it = robot.bodyBaseTransforms.find(b.name());
    X_mb_link.push_back(it == robot.bodyBaseTransforms.end() ? sva::PTransformd::Identity() : it->second.inv());
  }
  return buildRobotModel(robot.mb, X_mb_link, robot.name);
}

std::vector<GeneratedFile> generateFiles(const GenerateOptions & opt, std::vector<std::string> * inputs)
{
  if(!opt.scene.empty()) return generateScene(opt, inputs);
  if(opt.urdf.empty()) throw std::invalid_argument("no input: give a URDF or --scene");
  rbd::parsers::ParserOptions po;
  po.fixed = !opt.floatingBase;
  po.baseLink = opt.baseLink;
  const rbd::parsers::ParserResult robot = rbd::parsers::fromUrdfFile(opt.urdf, po);
  const RobotModel rm = robotModelFromUrdf(robot);
  requireDofs(rm, opt.urdf, robot.name);
  const std::string ns = checkedNamespace(opt.ns, robot.name);
  printLoaderWarnings(robot.warnings);
  std::vector<std::string> mimicWarnings;
  const rbd::parsers::MimicCoupling coupling =
      opt.independentMimic ? rbd::parsers::MimicCoupling{} : rbd::parsers::coupleMimics(robot, opt.urdf, &mimicWarnings);
  if(opt.independentMimic)
    for(const std::string & m : rbd::parsers::coupleMimics(robot, opt.urdf, nullptr).coupled)
      mimicWarnings.push_back(opt.urdf + ": mimic joint not coupled (--independent-mimic), its own dof: " + m);
  printLoaderWarnings(mimicWarnings);
  massMatrixPolicy(rm.checks, coupling.empty() ? rm.masslessSubtrees : emit::coupledMasslessJoints(rm, coupling), opt.urdf,
                   opt.strict);
  if(inputs) *inputs = {fs::absolute(opt.urdf).lexically_normal().string()};
  const std::string options = fmt::format("{}{}{}{}{}", opt.floatingBase ? "floating base" : "fixed base",
                                          opt.baseLink.empty() ? "" : ", base link " + opt.baseLink,
                                          opt.derivatives ? ", derivatives" : "",
                                          opt.independentMimic ? ", independent mimic joints" : "",
                                          opt.instantiate ? ", instantiated in dynamics_double.cpp and dynamics_float.cpp" : "");
  const std::string text = readFile(opt.urdf);
  const std::string source = fs::path(opt.urdf).filename().string(), hash = sha256Hex(text);
  std::string header = emit::emitDynamicsHeader(
      rm, emit::plainHeaderSpec(rm, ns, emit::plainProvenance(rm, source, hash, options), opt.derivatives, coupling));
  // The API's forward dynamics: the coupled system's when mimic joints are coupled.
  const bool fd = coupling.empty() ? rm.regularMassMatrix() : emit::coupledForwardDynamics(rm, coupling);
  const emit::InstantiatedFunctions instantiated{fd, opt.derivatives};
  if(opt.instantiate) header += emit::externInstantiations(ns, instantiated);
  std::vector<GeneratedFile> files{GeneratedFile{ns + "/dynamics.hpp", header}};
  if(opt.instantiate)
  {
    const std::string firstLine = header.substr(0, header.find('\n')); // "// Generated by rbdgen ..."
    for(const std::string scalar : {"double", "float"})
      files.push_back({ns + "/dynamics_" + scalar + ".cpp", emit::instantiationSource(ns, scalar, instantiated, firstLine)});
  }
  if(opt.batch)
  {
    std::string p;
    p += emit::generatedByLine() + "\n";
    p += fmt::format("// Source: {} (sha256 {})\n", source, hash);
    p += fmt::format("// Options: {}, batch", options);
    const std::string codeNs = coupling.empty() ? ns : ns + "::independent";
    emit::BatchFunctions bf;
    bf.forwardDynamics = fd;
    bf.derivatives = opt.derivatives;
    bf.massMatrixLower = coupling.empty();
    files.push_back(GeneratedFile{ns + "/batch.hpp", emit::emitBatchHeader(ns, codeNs, p, bf)});
  }
  return files;
}

std::string depfileText(const std::string & target, const std::vector<std::string> & inputs)
{
  auto escape = [](const std::string & path) {
    std::string e;
    for(char c : path)
    {
      if(c == ' ' || c == '#') e += '\\';
      if(c == '$') e += '$';
      e += c;
    }
    return e;
  };
  std::string s = escape(target) + ":";
  for(const auto & i : inputs) s += " " + escape(i);
  return s + "\n";
}

std::vector<std::string> writeFiles(const std::string & outDir, const std::vector<GeneratedFile> & files)
{
  std::vector<std::pair<fs::path, fs::path>> staged; // temporary -> final
  std::vector<std::string> written;
  fs::path createdRoot;
  try
  {
    for(const GeneratedFile & f : files)
    {
      const fs::path dst = fs::path(outDir) / f.path;
      written.push_back(dst.string());
      std::error_code ec;
      if(fs::exists(dst, ec))
      {
        std::ifstream in(dst, std::ios::binary);
        const std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if(old == f.content) continue; // unchanged: keep the file and its mtime
      }
      // Remember the first directory we create, to take it away again if anything fails.
      for(fs::path d = dst.parent_path(); !d.empty() && !fs::exists(d, ec); d = d.parent_path()) createdRoot = d;
      fs::create_directories(dst.parent_path(), ec);
      if(ec) throw std::runtime_error(dst.parent_path().string() + ": cannot create directory: " + ec.message());
      const fs::path tmp = dst.string() + ".rbdgen-tmp";
      {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if(!out) throw std::runtime_error(tmp.string() + ": cannot write file");
        out << f.content;
        out.flush();
        if(!out) throw std::runtime_error(tmp.string() + ": write failed");
      }
      staged.emplace_back(tmp, dst);
    }
    for(const auto & [tmp, dst] : staged)
    {
      std::error_code ec;
      fs::rename(tmp, dst, ec);
      if(ec) throw std::runtime_error(dst.string() + ": cannot replace file: " + ec.message());
    }
  }
  catch(...)
  {
    std::error_code ec;
    for(const auto & st : staged) fs::remove(st.first, ec);
    if(!createdRoot.empty()) fs::remove_all(createdRoot, ec);
    throw;
  }
  return written;
}

} // namespace rbdgen
