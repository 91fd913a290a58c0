"""rbdgen: robot dynamics from a URDF, with numpy in and out.

- ``rbdgen.Robot.from_urdf(path, floating_base=False, base_link=None)`` and
  ``rbdgen.Robot.from_scene(path)``: rbdgen's runtime (generic rbd:: algorithms in double).
- ``rbdgen.compile(path, floating_base=False, base_link=None, derivatives=True)``: the robot's
  generated C++ (every recursion unrolled), compiled into a Python module once and cached.

Both give an object with ``nq``, ``nv``, ``dof_names``, ``body_names`` and ``forward_kinematics(q)``,
``inverse_dynamics(q, v, a)``, ``mass_matrix(q)``, ``forward_dynamics(q, v, tau)``,
``jacobian(body, q)``, ``center_of_mass(q)``, ``inverse_dynamics_derivatives(q, v, a)`` ->
(dtau_dq, dtau_dv) and ``forward_dynamics_derivatives(q, v, tau)`` -> (a, da_dq, da_dv, Minv)
(d/dq in the tangent space: nv columns); each takes one state (shape (n,)) or a batch
(shape (N, n)) of float64 C-contiguous arrays, and ``threads=`` for batches (the GIL is released).
Conventions are RBDyn's: q of a free joint = [qw qx qy qz x y z], v = [w; v] in the child frame,
gravity 9.81 m/s^2 along world -z.
"""
from ._core import Robot, __version__
from ._compile import compile, cache_dir

__all__ = ["Robot", "compile", "cache_dir", "__version__"]
