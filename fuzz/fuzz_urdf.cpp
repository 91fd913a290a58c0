// libFuzzer target: bytes as URDF text -> loader (rbd::parsers::fromUrdfString) -> generator model
// (rbdgen::robotModelFromUrdf) -> emitted header (rbdgen::emit::emitDynamicsHeader).
//
// Contract under test: the loader reports every problem of the file as rbd::parsers::UrdfError
// (loader/include/rbd/parsers/urdf.h); anything else escaping it (std::out_of_range,
// std::logic_error, a crash, ASan/UBSan report) is a bug. The generator stages may only refuse a
// loaded model with std::invalid_argument. A fixed or floating base is chosen by the input's
// length parity so that both code paths are fuzzed; models above kMaxBodies bodies are skipped
// (emitting a large model takes long and finds nothing new), so each input runs in milliseconds.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <rbd/parsers/urdf.h>

#include "Generate.h"
#include "emit/Header.h"

namespace
{
constexpr std::size_t kMaxInput = 1 << 16;
constexpr int kMaxBodies = 30;
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  if(size > kMaxInput) return 0;
  const std::string xml(reinterpret_cast<const char *>(data), size);
  rbd::parsers::ParserOptions opt;
  opt.fixed = size % 2 == 0;
  rbd::parsers::ParserResult robot;
  try
  {
    robot = rbd::parsers::fromUrdfString(xml, opt, "fuzz.urdf");
  }
  catch(const rbd::parsers::UrdfError & e)
  {
    // One line naming the file: the documented form of every loader error.
    const std::string what = e.what();
    if(what.rfind("fuzz.urdf: ", 0) != 0 || what.find('\n') != std::string::npos) __builtin_trap();
    return 0;
  }
  if(robot.mb.nrBodies() > kMaxBodies) return 0;
  try
  {
    const rbdgen::RobotModel rm = rbdgen::robotModelFromUrdf(robot);
    const std::string provenance = rbdgen::emit::plainProvenance(rm, "fuzz.urdf", "0", opt.fixed ? "fixed base" : "floating base");
    const std::string header = rbdgen::emit::emitDynamicsHeader(rm, rbdgen::emit::plainHeaderSpec(rm, "fuzz", provenance));
    if(header.find("namespace fuzz") == std::string::npos) __builtin_trap();
  }
  catch(const std::invalid_argument &)
  {
  }
  return 0;
}
