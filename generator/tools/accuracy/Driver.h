#pragma once
// The generated variants: rbdgen generates the robot's header into a scratch directory, writes the
// driver (templates/accuracy_driver.cpp.in) beside it, compiles it (-O3 -march=native, Eigen only),
// runs it on the states file and reads back its timings and outputs (float and double).

#include <string>
#include <vector>

#include "States.h"
#include "Variants.h"

namespace rbdgen::accuracy
{

struct DriverOptions
{
  std::string urdf;          ///< robot
  bool floatingBase = false;
  std::string baseLink;
  std::string cxx;           ///< compiler; empty: $CXX, else the compiler rbdgen was built with
  std::string scratchDir;    ///< existing directory for the header, driver, states and outputs
  bool derivatives = true;   ///< generate and time the derivatives too
};

/// The compiler used when `requested` is empty: $CXX if set, else the one rbdgen was built with.
std::string defaultCompiler(const std::string & requested);

/// Generate, compile and run the driver; throws std::runtime_error (one line) on failure.
std::vector<VariantResult> runGeneratedVariants(const DriverOptions & opt, const std::vector<State> & states, int nq,
                                                int nv);

/// Parse the driver's output file (format in templates/accuracy_driver.cpp.in).
std::vector<VariantResult> readDriverOutputs(const std::string & path, int count);

} // namespace rbdgen::accuracy
