"""Finite-difference helpers shared by the stiffness tests (test_loaddist.py,
test_speed_paths.py)."""
from __future__ import annotations

import numpy as np


def central_jacobian(forces, u, h):
    """dF/du of the 5 ring forces F = forces(u) by central differences, step h[j] in u[j]."""
    fd = np.empty((5, 5))
    for j in range(5):
        up, um = u.copy(), u.copy()
        up[j] += h[j]
        um[j] -= h[j]
        fd[:, j] = (forces(up) - forces(um)) / (2 * h[j])
    return fd


def in_force_units(K, brg):
    """A 5x5 ring stiffness with the tilt rows and columns divided by the inner groove
    centre radius (so forces and moments, displacements and tilts compare alike)."""
    sc = np.array([1, 1, 1, brg.inner_groove_center_radius, brg.inner_groove_center_radius])
    return K / sc[:, None] / sc[None, :]
