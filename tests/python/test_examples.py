"""examples/python/rollout.py runs (the runtime, a small batch: seconds) and writes its data and plot."""
import os
import shutil
import subprocess
import sys

import numpy as np

from conftest import ROBOTS, ROOT


def test_rollout_writes_data_and_plot(tmp_path):
    out = tmp_path / "rollout.png"
    subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "rollout.py"), "--runtime", "--robot",
                    str(ROBOTS / "ur5e.urdf"), "--states", "20", "--duration", "0.05", "--threads", "2",
                    "--out", str(out)], check=True, capture_output=True, env=dict(os.environ), cwd=tmp_path)
    data = np.loadtxt(tmp_path / "rollout.dat")
    assert data.shape[1] == 11 and np.isfinite(data).all()
    assert abs(data[-1, 0] - 0.05) < 1e-12  # the last recorded time
    if shutil.which("gnuplot"):
        assert out.stat().st_size > 1000
