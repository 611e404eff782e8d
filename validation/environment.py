"""The environment a validation run used: package versions, git commit, machine.

>>> env = environment()
>>> sorted(env)[:3]
['cpu_count', 'git_commit', 'git_dirty']
"""
from __future__ import annotations

import os
import platform
import subprocess
import sys
from pathlib import Path

__all__ = ["environment", "PACKAGES"]

#: Packages whose versions a run records.  The FE checks depend on the mesher (gmsh: its
#: meshes, hence the discretisation error of the FE rows, change between releases), the
#: FE basis (scikit-fem), the mesh cache format (meshio) and the sparse solvers
#: (scikit-sparse, pypardiso with mkl, pyamg): docs/fem.md "Versions".
PACKAGES = ("ballrace", "numpy", "scipy", "pint", "typer", "rich", "jinja2", "matplotlib",
            "dask", "distributed", "pyvista", "scikit-fem", "gmsh", "meshio", "scikit-sparse",
            "pypardiso", "mkl", "pyamg", "mpmath")


_ROOT = Path(__file__).resolve().parent.parent      # the package folder = the repo root


def _git(*args: str) -> str:
    root = _ROOT
    try:
        return subprocess.run(["git", *args], cwd=root, capture_output=True, text=True,
                              timeout=10, check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def _in_checkout() -> bool:
    """True when the package runs from its own git checkout (not from a wheel that merely
    sits inside some other repository, e.g. a virtualenv in a project folder)."""
    top = _git("rev-parse", "--show-toplevel")
    return bool(top) and Path(top).resolve() == _ROOT


def environment() -> dict:
    """Versions, git commit (and whether the tree had changes), machine and Python.

    ``git_commit`` is None when ballrace is not run from its git checkout (installed
    from a wheel); the report then names the package version (``packages["ballrace"]``).
    """
    from ballrace.fem.api import versions as installed

    versions = installed(PACKAGES)
    git = _in_checkout()
    status = _git("status", "--porcelain") if git else ""
    return {
        "python": sys.version.split()[0],
        "packages": versions,
        "git_commit": (_git("rev-parse", "HEAD") or None) if git else None,
        "git_dirty": bool(status),
        "machine": platform.machine(),
        "platform": platform.platform(),
        "processor": platform.processor() or platform.machine(),
        "hostname": platform.node(),
        "cpu_count": os.cpu_count(),
    }
