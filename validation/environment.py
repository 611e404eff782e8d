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
from importlib import metadata
from pathlib import Path

__all__ = ["environment", "PACKAGES"]

PACKAGES = ("ballrace", "numpy", "scipy", "pint", "typer", "rich", "jinja2", "matplotlib",
            "dask", "distributed", "pyvista", "scikit-fem", "gmsh", "meshio", "scikit-sparse",
            "mpmath")


def _git(*args: str) -> str:
    root = Path(__file__).resolve().parent.parent
    try:
        return subprocess.run(["git", *args], cwd=root, capture_output=True, text=True,
                              timeout=10, check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def environment() -> dict:
    """Versions, git commit (and whether the tree had changes), machine and Python."""
    versions = {}
    for p in PACKAGES:
        try:
            versions[p] = metadata.version(p)
        except metadata.PackageNotFoundError:
            versions[p] = None
    status = _git("status", "--porcelain")
    return {
        "python": sys.version.split()[0],
        "packages": versions,
        "git_commit": _git("rev-parse", "HEAD") or None,
        "git_dirty": bool(status),
        "machine": platform.machine(),
        "platform": platform.platform(),
        "processor": platform.processor() or platform.machine(),
        "hostname": platform.node(),
        "cpu_count": os.cpu_count(),
    }
