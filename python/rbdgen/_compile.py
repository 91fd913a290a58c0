"""rbdgen.compile: generate a robot's dynamics, compile them into a Python module, import it.

The module is cached in ``cache_dir()`` under a key that is the sha256 of everything the result
depends on (URDF bytes, options, rbdgen's version, the wrapper template and headers, the compiler
command, the Python ABI, the CPU model since the code is built with -march=native), so a second
call with the same inputs only imports it.
"""
import hashlib
import importlib.util
import io
import os
import platform
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import threading
from pathlib import Path
from xml.etree import ElementTree

from . import _config, _core

_PKG_DIR = Path(__file__).resolve().parent
_INCLUDE_DIR = _PKG_DIR / "include"
_TEMPLATE = _PKG_DIR / "module_template.cpp"
_HEADERS = ("arrays.hpp", "parallel.hpp", "bind.hpp")
# $RBDGEN_COMPILE_OPT replaces -O2 (the test suite compiles at -O0: its results, not its speed, are checked)
CXXFLAGS = (os.environ.get("RBDGEN_COMPILE_OPT", "-O2"), "-march=native", "-DNDEBUG", "-std=c++17", "-fPIC", "-shared", "-fvisibility=hidden")

# sysconfig fills its variables lazily and not thread-safely (CPython 3.11: a second thread may see
# them half-initialised, EXT_SUFFIX None): read once, at import.
_EXT_SUFFIX = sysconfig.get_config_var("EXT_SUFFIX")
_PYTHON_INCLUDE = sysconfig.get_paths()["include"]

_loaded = {}  # module name -> module (an extension module is initialised once per process)
_locks = {}  # module name -> lock: one build per module at a time, different robots in parallel
_locks_lock = threading.Lock()


def cache_dir():
    """Where compiled robots are kept: $RBDGEN_CACHE_DIR, else $XDG_CACHE_HOME/rbdgen, else ~/.cache/rbdgen."""
    if os.environ.get("RBDGEN_CACHE_DIR"):
        return Path(os.environ["RBDGEN_CACHE_DIR"])
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "rbdgen"


def _compiler():
    return os.environ.get("RBDGEN_CXX") or _config.CXX or "c++"


def _cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def _cxx_string(text):
    """A C++ string literal for text (octal escapes for anything but letters, digits, ' _-.')."""
    out = []
    for b in text.encode("utf-8"):
        c = chr(b)
        out.append(c if (c.isascii() and c.isalnum()) or c in " _-." else "\\%03o" % b)
    return '"' + "".join(out) + '"'


def _is_scene(data):
    """True when the root element is <scene> (a malformed file is left to the URDF loader's errors)."""
    try:
        for _, element in ElementTree.iterparse(io.BytesIO(data), events=("start",)):
            return element.tag == "scene"
    except ElementTree.ParseError:
        pass
    return False


def module_source(template, module, namespace, robot_name, has_fd, has_derivatives, wrenches=False):
    """The module's C++ source from module_template.cpp's text (cmake/RbdgenPythonModule.cmake does the same)."""
    return (template.replace("@MODULE@", module).replace("@NS@", namespace)
            .replace("@ROBOT_STRING@", _cxx_string(robot_name))
            .replace("@HAS_FD@", "1" if has_fd else "0").replace("@HAS_DERIVATIVES@", "1" if has_derivatives else "0")
            .replace("@WRENCHES@", "1" if wrenches else "0"))


def _key(data, floating_base, base_link, cxx, derivatives=True, scene_urdf=None):
    h = hashlib.sha256()
    parts = [b"rbdgen", _core.__version__.encode(), data,
             b"scene robot: " + (Path(scene_urdf).read_bytes() if scene_urdf is not None else b""),
             repr((bool(floating_base), base_link or "", bool(derivatives))).encode(),
             _TEMPLATE.read_bytes()]
    parts += [(_INCLUDE_DIR / "rbdgen_py" / name).read_bytes() for name in _HEADERS]
    parts += [cxx.encode(), " ".join(CXXFLAGS).encode(), _config.EIGEN_INCLUDE.encode(), _config.XSIMD_INCLUDE.encode(),
              _EXT_SUFFIX.encode(), sys.version.encode(), _cpu_model().encode()]
    for p in parts:
        h.update(len(p).to_bytes(8, "little"))
        h.update(p)
    return h.hexdigest()


def _build(path, floating_base, base_link, derivatives, name, robot_name, cxx, final_dir, verbose, scene=False):
    """Generate, write and compile into a temporary directory, then move it to final_dir."""
    final_dir.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=name + ".tmp-", dir=final_dir.parent))
    try:
        files = _core._generate_headers(path, floating_base, base_link or "", name, derivatives, batch=True, scene=scene)
        for f in files:  # NS/dynamics.hpp, NS/batch.hpp (batches run on SIMD packs)
            (work / f["path"]).parent.mkdir(parents=True, exist_ok=True)
            (work / f["path"]).write_bytes(f["content"])
        header = files[0]
        has_fd = b"constexpr bool has_forward_dynamics = true;" in header["content"]
        has_derivatives = b"constexpr bool has_derivatives = true;" in header["content"]
        wrenches = b"constexpr int nwrenches = " in header["content"]  # a scene's external wrenches (held at zero)
        source = module_source(_TEMPLATE.read_text(), name, name, robot_name, has_fd, has_derivatives, wrenches)
        (work / "module.cpp").write_text(source)
        so_name = name + _EXT_SUFFIX
        includes = [str(work), str(_INCLUDE_DIR)] + _config.EIGEN_INCLUDE.split(";") + \
            [_config.XSIMD_INCLUDE, _config.PYBIND11_INCLUDE, _PYTHON_INCLUDE]
        cmd = [cxx, *CXXFLAGS] + ["-I" + d for d in includes if d] + [str(work / "module.cpp"), "-o", str(work / so_name)]
        (work / "command.txt").write_text(" ".join(cmd) + "\n")
        if verbose:
            print("rbdgen.compile:", " ".join(cmd), file=sys.stderr)
        result = subprocess.run(cmd, capture_output=True, text=True)
        if result.returncode != 0:
            raise RuntimeError("rbdgen.compile: the C++ compiler failed (exit %d) on %s:\n%s\ncommand: %s"
                               % (result.returncode, work / "module.cpp", result.stderr[-4000:], " ".join(cmd)))
        try:
            os.rename(work, final_dir)  # atomic; another process may have won the race
        except OSError:
            if not (final_dir / so_name).exists():
                raise
    finally:
        if work.exists():
            shutil.rmtree(work, ignore_errors=True)


def module_of(robot):
    """The module rbdgen.compile built for a compiled robot (its __file__ is in the cache directory,
    beside the generated header <name>/dynamics.hpp and the module's source module.cpp)."""
    module = _loaded.get(type(robot).__module__)
    if module is None:
        raise TypeError("rbdgen.module_of: not a robot made by rbdgen.compile in this process")
    return module


def compile(path, floating_base=False, base_link=None, *, derivatives=True, cache=None, cxx=None, verbose=False):
    """The robot of a URDF or a scene, evaluated by its generated C++ (same API as rbdgen.Robot).

    The first call generates the header (rbdgen's generator), writes a pybind11 module around it,
    compiles it with the system C++ compiler (``$RBDGEN_CXX``, else the one rbdgen was built with;
    flags ``-O2 -march=native``) and imports it; the result is cached in ``cache`` (default
    ``cache_dir()``) under the sha256 of the inputs and rbdgen's version, so the next call with the
    same inputs only imports it. ``derivatives``: also generate inverse_dynamics_derivatives and
    forward_dynamics_derivatives (default; False compiles faster and the two raise RuntimeError).
    A scene file (docs/SCENES.md) gives the scene's dynamics (its gravity, damping, friction,
    armature, contacts; external wrenches held at zero), as ``rbdgen.Robot.from_scene`` does; its
    URDF and base come from the scene (``floating_base`` and ``base_link`` are errors then).
    Raises FileNotFoundError (no such file), ValueError (a broken URDF or scene), RuntimeError (the
    compiler failed; the message holds its errors and the command).
    """
    path = os.fspath(path)
    with open(path, "rb") as f:
        data = f.read()
    scene = _is_scene(data)
    if scene and (floating_base or base_link):
        raise ValueError("rbdgen.compile: %s is a scene file: its base comes from the scene (floating_base and "
                         "base_link cannot be given)" % path)
    scene_urdf = _core._scene_urdf(path) if scene else None  # (a broken scene raises ValueError here)
    cxx = cxx or _compiler()
    key = _key(data, floating_base, base_link, cxx, derivatives, scene_urdf)
    name = "rbdgen_robot_" + key[:24]
    final_dir = Path(cache) if cache is not None else cache_dir()
    final_dir = final_dir / name
    so = final_dir / (name + _EXT_SUFFIX)
    with _locks_lock:
        lock = _locks.setdefault(name, threading.Lock())
    with lock:
        module = _loaded.get(name)
        if module is None:
            if not so.exists():
                # the runtime checks the URDF or scene (one-line errors) and gives the robot's name
                robot_name = (_core.Robot.from_scene(path) if scene else _core.Robot.from_urdf(path, floating_base, base_link)).name
                _build(path, floating_base, base_link, derivatives, name, robot_name, cxx, final_dir, verbose, scene)
            spec = importlib.util.spec_from_file_location(name, so)
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            _loaded[name] = module
    return module.robot()
