#pragma once
// Models built in code with MultiBodyGraph (no URDF): every joint type, arbitrary axes, backward
// joints (linked child-to-parent, or met when the tree is rooted inside the graph), several root
// joint types. The generator tool (make_models.cpp) and the test build the same models from the
// same seeds.

#include <string>
#include <vector>

#include <rbd/MultiBody.h>

namespace rbdgentest
{

struct ProgrammaticModel
{
  std::string name;
  rbd::MultiBody mb;
};

/// Number of programmatic models.
int programmaticModelCount();
/// Model k (deterministic).
ProgrammaticModel programmaticModel(int k);

} // namespace rbdgentest
