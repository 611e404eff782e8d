"""Finite-element check of the Hertz ball–race contact (optional extra ``ballrace[fem]``).

Quarter models (symmetry planes x = 0 and y = 0) meshed with gmsh
(:mod:`ballrace.meshes`), P2 tetrahedra in scikit-fem, frictionless unilateral
contact by a compliance matrix and non-negative least squares, compared with
:mod:`ballrace.analytic.hertz` and :mod:`ballrace.analytic.subsurface`.

>>> from ballrace import fem                                    # doctest: +SKIP
>>> r = fem.ball_on_plane(12.7e-3, 2000.0, level="quick")       # doctest: +SKIP
>>> r.a, r.b, r.p_max, r.approach, r.tau0, r.z0                 # doctest: +SKIP

Importing this package is cheap: gmsh, meshio, scikit-fem and pyvista are imported
only when a model is run or rendered.  Frame: x rolling, y transverse, z depth;
Lundberg–Palmgren's "tau_yz" (their y = rolling) is ``tau_xz`` here, and both names
are accepted by :func:`render`; :func:`render_3d` draws a 3-D pyvista picture
off-screen.  :mod:`ballrace.fem.axisym` is an axisymmetric model of circular contacts
(ball on ball, ball on a plane) resolved far beyond the 3-D model: the reference for
what real curved balls do (docs/fem-axisym.md).  ``run_case(..., traction=mu)`` (and
the ``ball_on_*`` helpers) adds a tangential surface traction q = mu p along +x and
compares the loaded section with :func:`ballrace.analytic.subsurface.stress`
(docs/fem.md, "Surface traction").
"""
from __future__ import annotations

from .api import (GAPS, LEVELS, MODES, TOLERANCES, TRACTION_TOLERANCES, ContactCase,
                  FEResult, MeshLevel,
                  ball_case, ball_on_ball, ball_on_groove, ball_on_plane, ball_on_race,
                  groove_case, plane_case, race_case, run_case)
from .render import render, render_3d
from .roller import ROLLER_LEVELS, RollerFEResult, RollerLevel, roller_contact
from .solvers import SOLVERS, available_solvers

__all__ = ["ball_on_race", "ball_on_plane", "ball_on_ball", "ball_on_groove", "run_case",
           "render", "render_3d", "race_case", "plane_case", "ball_case", "groove_case",
           "ContactCase", "FEResult", "LEVELS", "MeshLevel", "MODES", "GAPS", "TOLERANCES",
           "TRACTION_TOLERANCES", "SOLVERS", "available_solvers",
           "roller_contact", "RollerFEResult", "RollerLevel", "ROLLER_LEVELS"]
