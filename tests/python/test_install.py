"""`cmake --install BUILD --component python` puts a working package under the prefix (run by ctest's
python_tests, which says where the build is; skipped when pytest runs on its own)."""
import os
import subprocess
import sys
import textwrap

import pytest

from conftest import ROBOTS

BUILD = os.environ.get("RBDGEN_TEST_BUILD_DIR")
SITE = os.environ.get("RBDGEN_TEST_PYTHON_INSTALL_DIR")


@pytest.mark.skipif(not BUILD or not SITE, reason="needs the build directory (set by ctest)")
def test_installed_package(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", BUILD, "--component", "python", "--prefix", str(prefix)], check=True,
                   capture_output=True)
    site = prefix / SITE
    for f in ["__init__.py", "_compile.py", "_config.py", "module_template.cpp", "include/rbdgen_py/bind.hpp"]:
        assert (site / "rbdgen" / f).is_file(), f
    script = textwrap.dedent("""
        import sys, numpy as np, rbdgen
        assert rbdgen.__file__.startswith(sys.argv[1]), rbdgen.__file__
        r = rbdgen.Robot.from_urdf(sys.argv[2])
        print(r.nv, float(r.mass_matrix(np.zeros(r.nq))[0, 0]))
    """)
    env = dict(os.environ, PYTHONPATH=str(site))
    # (cwd: not ctest's, build/python, whose rbdgen python -c would import first)
    out = subprocess.run([sys.executable, "-c", script, str(site), str(ROBOTS / "pendulum.urdf")], env=env,
                         cwd=tmp_path, check=True, capture_output=True, text=True).stdout.split()
    assert out[0] == "1" and abs(float(out[1]) - (1 + 4e-5)) < 1e-12
