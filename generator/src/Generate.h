#pragma once
// The driver: read the options, load the URDF or scene (loader/), build the runtime MultiBody, fold
// it into a RobotModel, report the model's warnings, hand it to the header assemblers (emit/Header.h,
// emit/SceneHeader.h) and write their files atomically.

#include <map>
#include <string>
#include <vector>

#include <rbd/parsers/MimicCoupling.h>
#include <rbd/parsers/urdf.h>

#include "model/RobotModel.h"

namespace rbdgen
{

struct GenerateOptions
{
  std::string urdf;          ///< input URDF path (empty with a scene: the scene names its URDF)
  std::string scene;         ///< scene file (rbd/scene/Scene.h): emit the scene-specialised header
  bool strict = false;       ///< mass matrix hazards (MassMatrixChecks.h) are an error, not a warning
  std::string outDir;        ///< output directory; the header goes to outDir/<namespace>/dynamics.hpp
  std::string ns;            ///< C++ namespace (default: the sanitised robot name)
  bool floatingBase = false;
  std::string baseLink;      ///< default: the URDF root link
  bool derivatives = false;  ///< also emit inverse/forward dynamics derivatives
  /// Mimic joints as independent joints with their own dofs (the URDF's coupling ignored); default:
  /// coupled (rbd/parsers/MimicCoupling.h), the full model then in namespace <ns>::independent.
  bool independentMimic = false;
  /// Also write <ns>/dynamics_double.cpp and dynamics_float.cpp with the explicit instantiations, and
  /// end the header with their `extern template` declarations (URDF only).
  bool instantiate = false;
  bool batch = false;        ///< also write <namespace>/batch.hpp: the functions over N states (xsimd packs, threads)
};

struct GeneratedFile
{
  std::string path;     ///< relative to outDir
  std::string content;
};

/// The text of every generated file, in memory (nothing written). Warnings go to stderr
/// ("rbdgen: warning: ..."): the loader's (robot.warnings: non-physical inertias, mimic joints
/// loaded as independent joints, a URDF floating joint used as the base, ...), never an error; and
/// the mass matrix checks (MassMatrixChecks.h): joints moving only massless links or two free
/// joints with a massless link between them make the mass matrix singular and the header then has
/// no forward dynamics; a dof of negligible effective inertia makes it ill-conditioned. Each of
/// these is an error with opt.strict. inputs (when given)
/// receives the files the output depends on (URDF, scene), for a depfile.
std::vector<GeneratedFile> generateFiles(const GenerateOptions & opt, std::vector<std::string> * inputs = nullptr);

/// Makefile-syntax depfile text: "target: input1 input2\n" (spaces escaped).
std::string depfileText(const std::string & target, const std::vector<std::string> & inputs);

/// Build the generator model of a loaded robot (link frames as in the URDF).
RobotModel robotModelFromUrdf(const rbd::parsers::ParserResult & robot);

/// Write files under outDir: each goes to a temporary file first and is renamed into place only
/// once all were written; a file whose content did not change is left untouched (mtime kept).
/// Returns the paths written or kept.
std::vector<std::string> writeFiles(const std::string & outDir, const std::vector<GeneratedFile> & files);

} // namespace rbdgen
