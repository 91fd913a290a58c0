// rbdgen._core: the runtime (rbdgen.Robot) and the generator (rbdgen.compile's first step).
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Generate.h>
#include <rbd/parsers/urdf.h>
#include <rbd/scene/SceneLoader.h>

#include <rbdgen_py/bind.hpp>

#include "RuntimeModels.h"

namespace py = pybind11;
using rbdgen_py::Robot;
using rbdgen_py::RuntimeModel;

namespace
{

/// str or os.PathLike -> str
std::string fspath(const py::object & path)
{
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

/// The headers generated for a URDF or a scene (nothing written), NS/dynamics.hpp and, with batch,
/// NS/batch.hpp: rbdgen.compile's input.
py::list generateHeaders(const py::object & path, bool floatingBase, const std::string & baseLink, const std::string & ns,
                         bool derivatives, bool batch, bool scene)
{
  rbdgen::GenerateOptions opt;
  (scene ? opt.scene : opt.urdf) = fspath(path);
  opt.floatingBase = floatingBase;
  opt.baseLink = baseLink;
  opt.ns = ns;
  opt.derivatives = derivatives;
  opt.batch = batch;
  py::list result;
  for(const rbdgen::GeneratedFile & f : rbdgen::generateFiles(opt))
  {
    py::dict file;
    file["path"] = f.path;
    file["content"] = py::bytes(f.content);
    result.append(file);
  }
  return result;
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "rbdgen's C++ core: the runtime (Robot) and the header generator";
  m.attr("__version__") = RBDGEN_VERSION;

  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const rbd::parsers::UrdfError & e)
    {
      if(e.element() == "file") PyErr_SetString(PyExc_FileNotFoundError, e.what());
      else PyErr_SetString(PyExc_ValueError, e.what());
    }
    catch(const rbd::scene::SceneError & e)
    {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  auto cls = rbdgen_py::bindRobot<RuntimeModel>(
      m, "Robot",
      "A robot evaluated by rbdgen's runtime (rbd:: algorithms in double). Build it with Robot.from_urdf or "
      "Robot.from_scene. Conventions (RBDyn's): q of a free joint = [qw qx qy qz x y z], v = [w; v] in the child "
      "frame, gravity 9.81 m/s^2 along world -z.");
  cls.def_static(
         "from_urdf",
         [](const py::object & path, bool floatingBase, const py::object & baseLink) {
           const std::string base = baseLink.is_none() ? std::string() : baseLink.cast<std::string>();
           return Robot<RuntimeModel>(std::make_shared<const RuntimeModel>(std::in_place_type<rbdgen_py::UrdfModel>,
                                                                           fspath(path), floatingBase, base));
         },
         py::arg("path"), py::arg("floating_base") = false, py::arg("base_link") = py::none(),
         "Load a URDF. floating_base: attach the base link to the world by a free joint (q starts with [qw qx qy qz "
         "x y z]); base_link: root the tree at another link. A broken URDF raises ValueError naming the file, "
         "element and reason; a missing file FileNotFoundError.")
      .def_static(
          "from_scene",
          [](const py::object & path) {
            return Robot<RuntimeModel>(
                std::make_shared<const RuntimeModel>(std::in_place_type<rbdgen_py::SceneModel>, fspath(path)));
          },
          py::arg("path"),
          "Load a scene file (docs/SCENES.md): the scene's robot (locked joints removed) with the scene's effects: "
          "inverse_dynamics, mass_matrix (+ armature) and forward_dynamics include its gravity, damping, friction "
          "and ground contacts (no external wrench). A broken scene raises ValueError.");

  m.def("_generate_headers", &generateHeaders, py::arg("path"), py::arg("floating_base"), py::arg("base_link"),
        py::arg("namespace"), py::arg("derivatives") = false, py::arg("batch") = false, py::arg("scene") = false,
        "The generated headers of a URDF (or a scene), in memory: [dict(path=relative path, content=bytes)], "
        "dynamics.hpp first.");
  m.def(
      "_scene_urdf", [](const py::object & path) { return rbd::scene::loadScene(fspath(path)).urdf; }, py::arg("path"),
      "The path of the URDF a scene file names (a broken scene raises ValueError).");
}
