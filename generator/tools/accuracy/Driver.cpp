#include "Driver.h"

#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "Generate.h"
#include "emit/Template.h"

#ifndef RBDGEN_CXX_COMPILER
#define RBDGEN_CXX_COMPILER "c++"
#endif
#ifndef RBDGEN_EIGEN_INCLUDE_DIR
#define RBDGEN_EIGEN_INCLUDE_DIR "/usr/include/eigen3"
#endif

namespace rbdgen::accuracy
{
namespace fs = std::filesystem;

namespace
{

std::string shellQuote(const std::string & s)
{
  std::string q = "'";
  for(char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Run a shell command, stdout and stderr to logPath; the exit status (-1: did not exit normally).
int runLogged(const std::string & command, const std::string & logPath)
{
  const int status = std::system((command + " >" + shellQuote(logPath) + " 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The first line of a log containing "error" (else its first line), for a one-line message.
std::string firstErrorLine(const std::string & logPath)
{
  std::ifstream in(logPath);
  std::string line, first;
  while(std::getline(in, line))
  {
    if(first.empty()) first = line;
    if(line.find("error") != std::string::npos) return line;
  }
  return first;
}

} // namespace

std::string defaultCompiler(const std::string & requested)
{
  if(!requested.empty()) return requested;
  const char * env = std::getenv("CXX");
  return env && *env ? std::string(env) : std::string(RBDGEN_CXX_COMPILER);
}

std::vector<VariantResult> runGeneratedVariants(const DriverOptions & opt, const std::vector<State> & states, int nq,
                                                int nv)
{
  const fs::path dir = opt.scratchDir;
  GenerateOptions gen;
  gen.urdf = opt.urdf;
  gen.floatingBase = opt.floatingBase;
  gen.baseLink = opt.baseLink;
  gen.outDir = dir.string();
  gen.ns = "robot";
  gen.derivatives = opt.derivatives;
  writeFiles(gen.outDir, generateFiles(gen));

  const auto & templates = embeddedTemplates();
  const auto it = templates.find("accuracy_driver.cpp.in");
  if(it == templates.end()) throw std::runtime_error("templates/accuracy_driver.cpp.in is not embedded in rbdgen");
  const std::string robotName = fs::path(opt.urdf).stem().string();
  const std::string driverText =
      fillTemplate(selectSections(it->second, {{"derivatives", opt.derivatives}}, "templates/accuracy_driver.cpp.in"),
                   {{"robot", robotName}, {"namespace", gen.ns}}, "templates/accuracy_driver.cpp.in");
  const fs::path source = dir / "accuracy_driver.cpp", exe = dir / "accuracy_driver";
  {
    std::ofstream out(source, std::ios::binary | std::ios::trunc);
    out << driverText;
    if(!out) throw std::runtime_error(source.string() + ": cannot write the driver");
  }
  const fs::path statesPath = dir / "states.bin", outputsPath = dir / "outputs.bin";
  writeStates(statesPath.string(), states, nq, nv);

  const std::string cxx = defaultCompiler(opt.cxx);
  const std::string compile = shellQuote(cxx) + " -std=c++17 -O3 -march=native -DNDEBUG -I" + shellQuote(dir.string()) +
                              " -isystem " + shellQuote(RBDGEN_EIGEN_INCLUDE_DIR) + " " + shellQuote(source.string()) +
                              " -o " + shellQuote(exe.string());
  const std::string compileLog = (dir / "compile.log").string();
  if(runLogged(compile, compileLog) != 0)
    throw std::runtime_error("compiling the accuracy driver with '" + cxx + "' failed: " + firstErrorLine(compileLog));
  const std::string runLog = (dir / "run.log").string();
  if(runLogged(shellQuote(exe.string()) + " " + shellQuote(statesPath.string()) + " " + shellQuote(outputsPath.string()),
               runLog) != 0)
    throw std::runtime_error("the accuracy driver failed: " + firstErrorLine(runLog));
  return readDriverOutputs(outputsPath.string(), static_cast<int>(states.size()));
}

std::vector<VariantResult> readDriverOutputs(const std::string & path, int count)
{
  std::ifstream in(path, std::ios::binary);
  const auto fail = [&] { return std::runtime_error(path + ": malformed accuracy driver output"); };
  const auto i32 = [&] {
    std::int32_t v = 0;
    in.read(reinterpret_cast<char *>(&v), sizeof(v));
    if(!in || v < 0) throw fail();
    return v;
  };
  const auto f64 = [&] {
    double v = 0;
    in.read(reinterpret_cast<char *>(&v), sizeof(v));
    if(!in) throw fail();
    return v;
  };
  const auto str = [&] {
    std::string s(static_cast<std::size_t>(i32()), '\0');
    in.read(s.data(), static_cast<std::streamsize>(s.size()));
    if(!in) throw fail();
    return s;
  };
  std::vector<VariantResult> results;
  const int variants = i32();
  for(int v = 0; v < variants; ++v)
  {
    VariantResult r;
    r.function = str();
    r.scalar = str();
    r.implementation = "generated";
    r.nsPerCall = f64();
    const int size = i32();
    for(int s = 0; s < count; ++s)
    {
      Eigen::VectorXd x(size);
      for(int k = 0; k < size; ++k) x(k) = f64();
      r.outputs.push_back(std::move(x));
    }
    results.push_back(std::move(r));
  }
  return results;
}

} // namespace rbdgen::accuracy
