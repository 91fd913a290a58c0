#include "ProgrammaticModels.h"

#include "TestModels.h"

namespace rbdgentest
{

int programmaticModelCount()
{
  return 4;
}

ProgrammaticModel programmaticModel(int k)
{
  rbdtest::Rng rng(static_cast<unsigned>(1000 + k));
  rbdtest::RandomTreeOptions opt;
  switch(k)
  {
    case 0:
    {
      // A chain through every joint type, forward, fixed root.
      opt.chainProbability = 1.0;
      const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 9, opt);
      return {"prog_chain_all_types", g.makeMultiBody("b0", rbd::Joint::Fixed, rbdtest::randomTransform(rng))};
    }
    case 1:
    {
      // A branching tree with half of its joints linked backward, free-floating root.
      opt.backwardProbability = 0.5;
      opt.chainProbability = 0.4;
      const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 10, opt);
      return {"prog_tree_backward", g.makeMultiBody("b0", rbd::Joint::Free)};
    }
    case 2:
    {
      // The same kind of graph rooted inside: joints towards b0 become backward; spherical root.
      opt.backwardProbability = 0.2;
      const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 10, opt);
      return {"prog_rooted_inside", g.makeMultiBody("b5", rbd::Joint::Spherical, rbdtest::randomTransform(rng),
                                                    rbdtest::randomTransform(rng))};
    }
    default:
    {
      // Planar root, revolute/prismatic/cylindrical joints about arbitrary axes only.
      opt.types = {rbd::Joint::Rev, rbd::Joint::Prism, rbd::Joint::Cylindrical};
      opt.backwardProbability = 0.3;
      const rbd::MultiBodyGraph g = rbdtest::randomGraph(rng, 10, opt);
      return {"prog_planar_root", g.makeMultiBody("b0", rbd::Joint::Planar, rbdtest::randomTransform(rng))};
    }
  }
}

} // namespace rbdgentest
