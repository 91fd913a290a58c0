# generate_robot_dynamics(): generate robot-specific dynamics C++ from a URDF at build time.
#
#   find_package(rbdgen CONFIG REQUIRED)
#   generate_robot_dynamics(TARGET panda_dynamics URDF robots/panda.urdf
#                           [NAMESPACE panda] [FLOATING_BASE] [BASE_LINK link] [OUTPUT_DIR dir] [STRICT]
#                           [DERIVATIVES] [INDEPENDENT_MIMIC] [INSTANTIATE] [BATCH] [PYTHON_MODULE module])
#   generate_robot_dynamics(TARGET quadruped_sim SCENE scenes/quadruped_ground.xml
#                           [NAMESPACE ns] [OUTPUT_DIR dir] [STRICT] [DERIVATIVES] [BATCH] [PYTHON_MODULE module])
#   target_link_libraries(my_controller PRIVATE panda_dynamics)
#   // #include <panda/dynamics.hpp>
#
# Defines the INTERFACE library TARGET (include directory + Eigen; STATIC with INSTANTIATE). The header
# <OUTPUT_DIR>/<NAMESPACE>/dynamics.hpp is regenerated when the URDF (or the scene, or the URDF
# the scene names: rbdgen writes a depfile) or the rbdgen executable (whose templates are built in)
# changes, and only then. With SCENE the header is specialised to the scene's effects; the URDF,
# base and base link come from the scene (URDF, FLOATING_BASE and BASE_LINK are errors then).
# NAMESPACE defaults to the URDF robot name made into an identifier (with SCENE: the TARGET name);
# OUTPUT_DIR to ${CMAKE_CURRENT_BINARY_DIR}/<TARGET>. rbdgen's warnings (the loader's: non-physical
# inertias, a mimic of a fixed joint, a URDF floating joint used as the base; the
# mass matrix checks: joints moving only massless links, two free joints with a massless link
# between them, dofs of negligible effective inertia) are printed by the build as
# "rbdgen: warning: ..." (Ninja and Make show a custom command's output) and never fail it.
# STRICT: the mass matrix checks are errors instead of warnings. DERIVATIVES: the header also has
# inverse_dynamics_derivatives() and forward_dynamics_derivatives() (rbdgen generate --derivatives).
# Mimic joints are coupled to the joints they follow (not dofs; the full model is in NS::independent);
# INDEPENDENT_MIMIC keeps them as independent joints with their own dofs (rbdgen --independent-mimic).
# INSTANTIATE (URDF only): TARGET is a STATIC library compiling <NAMESPACE>/dynamics_double.cpp and
# dynamics_float.cpp, every function instantiated there for double and float and declared
# `extern template` in the header, so that the robot's code is compiled once rather than in every
# translation unit that includes the header.
# BATCH: also <OUTPUT_DIR>/<NAMESPACE>/batch.hpp, the functions over N states at a time on
# xsimd packs and threads (rbdgen generate --batch; with SCENE, the scene's functions, and the scene
# header gets forward_kinematics, jacobian and center_of_mass); TARGET then carries xsimd's include
# directory (Debian: libxsimd-dev; the header only, its CMake package is not used) and Threads::Threads.
# With SCENE, DERIVATIVES adds the scene's <derivatives/> output.
#
# PYTHON_MODULE module: also a pybind11 module target `module` (`import module`;
# module.robot() is the object of rbdgen.compile: the API of rbdgen.Robot, with the derivatives when
# DERIVATIVES is given; implies BATCH: batches run on NS/batch.hpp), built from the Python package's
# module template and headers (installed by rbdgen's component `python`). Needs pybind11, found by the caller first:
#   find_package(Python3 COMPONENTS Interpreter Development.Module REQUIRED)
#   find_package(pybind11 CONFIG REQUIRED)
#   generate_robot_dynamics(TARGET panda_dynamics URDF panda.urdf DERIVATIVES PYTHON_MODULE panda_py)
# The module lands in the current binary directory (set its LIBRARY_OUTPUT_DIRECTORY to move it) and
# is compiled with the project's flags (rbdgen.compile adds -O2 -march=native).
include_guard(GLOBAL)

function(_rbdgen_identifier out text)
  string(REGEX REPLACE "[^A-Za-z0-9]" "_" id "${text}")
  string(REGEX REPLACE "__+" "_" id "${id}")
  string(REGEX REPLACE "_+$" "" id "${id}")
  if(id STREQUAL "" OR id MATCHES "^[0-9]")
    set(id "_${id}")
  endif()
  if(id MATCHES "^_[A-Z]")
    set(id "x${id}")
  endif()
  set(${out} "${id}" PARENT_SCOPE)
endfunction()

function(generate_robot_dynamics)
  cmake_parse_arguments(PARSE_ARGV 0 arg "FLOATING_BASE;STRICT;DERIVATIVES;INDEPENDENT_MIMIC;INSTANTIATE;BATCH" "TARGET;URDF;SCENE;NAMESPACE;BASE_LINK;OUTPUT_DIR;PYTHON_MODULE" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "generate_robot_dynamics: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR (NOT arg_URDF AND NOT arg_SCENE))
    message(FATAL_ERROR "generate_robot_dynamics: TARGET and URDF (or SCENE) are required")
  endif()
  if(arg_SCENE AND (arg_URDF OR arg_FLOATING_BASE OR arg_BASE_LINK))
    message(FATAL_ERROR "generate_robot_dynamics(${arg_TARGET}): SCENE names the URDF and the base: "
                        "URDF, FLOATING_BASE and BASE_LINK cannot be given with it")
  endif()
  if(arg_PYTHON_MODULE)
    set(arg_BATCH ON) # the module evaluates batches with NS/batch.hpp
  endif()
  if(arg_SCENE)
    get_filename_component(input "${arg_SCENE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  else()
    get_filename_component(input "${arg_URDF}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  endif()
  set(urdf "${input}")
  if(NOT EXISTS "${input}")
    message(FATAL_ERROR "generate_robot_dynamics(${arg_TARGET}): '${input}' does not exist")
  endif()
  set(robot_name "")
  file(READ "${input}" text)
  if(NOT arg_SCENE AND text MATCHES "<robot[^>]*name=\"([^\"]*)\"")
    set(robot_name "${CMAKE_MATCH_1}")
  elseif(arg_SCENE AND text MATCHES "<scene[^>]*name=\"([^\"]*)\"")
    set(robot_name "${CMAKE_MATCH_1}") # (the name rbdgen.Robot.from_scene gives)
  elseif(arg_SCENE)
    set(robot_name "${arg_TARGET}")
  endif()
  if(arg_NAMESPACE)
    set(ns "${arg_NAMESPACE}")
  elseif(arg_SCENE)
    _rbdgen_identifier(ns "${arg_TARGET}")
  else()
    if(robot_name STREQUAL "")
      message(FATAL_ERROR "generate_robot_dynamics(${arg_TARGET}): ${urdf}: no <robot name=...>; give NAMESPACE")
    endif()
    _rbdgen_identifier(ns "${robot_name}")
  endif()
  if(arg_OUTPUT_DIR)
    get_filename_component(outdir "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  else()
    set(outdir "${CMAKE_CURRENT_BINARY_DIR}/${arg_TARGET}")
  endif()
  set(header "${outdir}/${ns}/dynamics.hpp")
  set(outputs "${header}")
  if(arg_BATCH)
    list(APPEND outputs "${outdir}/${ns}/batch.hpp")
  endif()

  set(options --out "${outdir}" --namespace "${ns}")
  if(arg_STRICT)
    list(APPEND options --strict)
  endif()
  if(arg_FLOATING_BASE)
    list(APPEND options --floating-base)
  endif()
  if(arg_DERIVATIVES)
    list(APPEND options --derivatives)
  endif()
  if(arg_INDEPENDENT_MIMIC)
    list(APPEND options --independent-mimic)
  endif()
  if(arg_INSTANTIATE)
    if(arg_SCENE)
      message(FATAL_ERROR "generate_robot_dynamics(${arg_TARGET}): INSTANTIATE takes a URDF, not a SCENE")
    endif()
    list(APPEND options --instantiate)
    list(APPEND outputs "${outdir}/${ns}/dynamics_double.cpp" "${outdir}/${ns}/dynamics_float.cpp")
  endif()
  if(arg_BATCH)
    list(APPEND options --batch)
  endif()
  if(arg_BASE_LINK)
    list(APPEND options --base-link "${arg_BASE_LINK}")
  endif()
  if(TARGET rbdgen::rbdgen)
    set(tool rbdgen::rbdgen)
  else()
    message(FATAL_ERROR "generate_robot_dynamics: no rbdgen::rbdgen target (use find_package(rbdgen))")
  endif()

  if(arg_SCENE)
    # The scene names its URDF: rbdgen lists both in a depfile (Ninja and Makefile generators).
    set(depfile "${outdir}/${ns}/dynamics.hpp.d")
    add_custom_command(OUTPUT ${outputs}
      COMMAND ${tool} generate --scene "${input}" ${options} --depfile "${depfile}"
      DEPENDS "${input}" ${tool}
      DEPFILE "${depfile}"
      COMMENT "rbdgen: ${arg_SCENE} -> ${ns}/dynamics.hpp"
      VERBATIM)
  else()
    add_custom_command(OUTPUT ${outputs}
      COMMAND ${tool} generate "${urdf}" ${options}
      DEPENDS "${urdf}" ${tool}
      COMMENT "rbdgen: ${arg_URDF} -> ${ns}/dynamics.hpp"
      VERBATIM)
  endif()
  add_custom_target(${arg_TARGET}_generate DEPENDS ${outputs})
  if(arg_INSTANTIATE) # a static library: the robot's code compiled once, in dynamics_{double,float}.cpp
    add_library(${arg_TARGET} STATIC "${outdir}/${ns}/dynamics_double.cpp" "${outdir}/${ns}/dynamics_float.cpp")
    set_target_properties(${arg_TARGET} PROPERTIES POSITION_INDEPENDENT_CODE ON) # also into shared objects
    set(scope PUBLIC)
  else()
    add_library(${arg_TARGET} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_dependencies(${arg_TARGET} ${arg_TARGET}_generate)
  target_include_directories(${arg_TARGET} ${scope} "$<BUILD_INTERFACE:${outdir}>")
  target_link_libraries(${arg_TARGET} ${scope} Eigen3::Eigen)
  target_compile_features(${arg_TARGET} ${scope} cxx_std_17)
  set_target_properties(${arg_TARGET} PROPERTIES RBDGEN_HEADER "${header}" RBDGEN_NAMESPACE "${ns}")
  if(arg_BATCH)
    _rbdgen_batch_requirements(${arg_TARGET})
  endif()

  if(arg_PYTHON_MODULE)
    _rbdgen_python_module(${arg_TARGET} "${arg_PYTHON_MODULE}" "${header}" "${ns}" "${robot_name}")
  endif()
endfunction()

# What batch.hpp needs: xsimd's headers (found by path: the Debian package's CMake config names a
# target xtl that it does not ship) and std::thread.
function(_rbdgen_batch_requirements target)
  find_path(RBDGEN_XSIMD_INCLUDE_DIR xsimd/xsimd.hpp DOC "include directory of xsimd (BATCH)")
  if(NOT RBDGEN_XSIMD_INCLUDE_DIR)
    message(FATAL_ERROR "generate_robot_dynamics(${target}): BATCH needs the xsimd headers (Debian: libxsimd-dev); "
                        "set RBDGEN_XSIMD_INCLUDE_DIR to the directory holding xsimd/xsimd.hpp")
  endif()
  find_package(Threads REQUIRED)
  target_include_directories(${target} SYSTEM INTERFACE "${RBDGEN_XSIMD_INCLUDE_DIR}")
  target_link_libraries(${target} INTERFACE Threads::Threads)
endfunction()

# The pybind11 module `module` over the generated header of `target` (see PYTHON_MODULE above).
# RBDGEN_PYTHON_PACKAGE_DIR: the directory of the package rbdgen (module_template.cpp, include/),
# set by rbdgenConfig.cmake (installed tree) or by rbdgen's own python/CMakeLists.txt (build tree).
function(_rbdgen_python_module target module header ns robot_name)
  if(NOT module MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "generate_robot_dynamics(${target}): PYTHON_MODULE '${module}' is not a Python identifier")
  endif()
  if(NOT COMMAND pybind11_add_module)
    message(FATAL_ERROR "generate_robot_dynamics(${target}): PYTHON_MODULE needs pybind11: call "
                        "find_package(Python3 COMPONENTS Interpreter Development.Module REQUIRED) and "
                        "find_package(pybind11 CONFIG REQUIRED) first (Debian: python3-dev pybind11-dev)")
  endif()
  set(template "${RBDGEN_PYTHON_PACKAGE_DIR}/module_template.cpp")
  if(NOT RBDGEN_PYTHON_PACKAGE_DIR OR (NOT EXISTS "${template}" AND NOT TARGET rbdgen_python))
    message(FATAL_ERROR "generate_robot_dynamics(${target}): PYTHON_MODULE needs rbdgen's Python package "
                        "(its module template and headers): install rbdgen's component 'python' into the same "
                        "prefix (cmake --install BUILD --component python, from a build with the package); "
                        "looked for '${template}'")
  endif()
  get_filename_component(outdir "${header}" DIRECTORY)
  get_filename_component(outdir "${outdir}" DIRECTORY)
  set(source "${outdir}/${module}_module.cpp")
  add_custom_command(OUTPUT "${source}"
    COMMAND ${CMAKE_COMMAND} "-DHEADER=${header}" "-DTEMPLATE=${template}" "-DOUTPUT=${source}" "-DMODULE=${module}"
            "-DNS=${ns}" "-DROBOT=${robot_name}" -P "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/RbdgenPythonModule.cmake"
    DEPENDS "${header}" "${template}" "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/RbdgenPythonModule.cmake"
    COMMENT "rbdgen: ${ns}/dynamics.hpp -> Python module ${module}"
    VERBATIM)
  pybind11_add_module(${module} MODULE "${source}")
  target_include_directories(${module} PRIVATE "${RBDGEN_PYTHON_PACKAGE_DIR}/include")
  target_link_libraries(${module} PRIVATE ${target})
  if(TARGET rbdgen_python) # rbdgen's build tree: the package's files are copied there by rbdgen_python
    add_dependencies(${module} rbdgen_python)
  endif()
endfunction()
