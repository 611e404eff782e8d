"""Parametric gmsh meshes of the ball–race contact bodies (gmsh imported lazily).

* :mod:`ballrace.meshes.geometry` — analytic surfaces (sphere, race torus, paraboloid)
  in the local contact frame (numpy only);
* :mod:`ballrace.meshes.contact` — quarter-model block and ball meshes, refined at the
  contact, deterministic, cached by a hash of their parameters.
"""
from __future__ import annotations

from .contact import TetMesh, ball_mesh, block_mesh, cache_dir, mesh_hash, morph_block
from .geometry import Paraboloid, Plane, RaceTorus, Sphere, race_torus

__all__ = ["TetMesh", "block_mesh", "ball_mesh", "morph_block", "cache_dir", "mesh_hash",
           "Plane", "Sphere", "Paraboloid", "RaceTorus", "race_torus"]
