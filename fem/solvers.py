"""Sparse symmetric positive-definite solvers with a run-time fallback chain.

The FE check factorises one stiffness matrix per body and solves it for 30–200
right-hand sides (the pressure tents).  Measured on 2 cores (docs/fem.md, P2
elasticity, 83k DOFs, factorisation / 100 right-hand sides):

==============================  ===============  ==========================
solver                          83k DOFs         install
==============================  ===============  ==========================
CHOLMOD (scikit-sparse 0.4.16)  3.5 s / 0.7 s    apt libsuitesparse-dev +
+ OpenBLAS                                       libopenblas0-pthread; pip
pypardiso (MKL)                 4–5 s / 4 s      pip only (~1 GB)
pyamg SA + CG                   2.4 s per RHS    pip only
scipy SuperLU (``splu``)        820 s, 10 GB     always present: last resort
==============================  ===============  ==========================

:func:`factorize` tries them in the order ``cholmod, pardiso, amg, superlu``
(override with the environment variable ``BALLRACE_SOLVER`` set to one name), logs
the one it used at INFO level and returns a callable ``solve(B)`` for a dense
right-hand side block ``B`` (n, m).  SuperLU is used with a WARNING because on 3-D
P2 problems it is two orders of magnitude slower and needs ~10x the memory.
"""
from __future__ import annotations

import logging
import os
from typing import Callable

import numpy as np

__all__ = ["SOLVERS", "available_solvers", "factorize"]

log = logging.getLogger(__name__)

#: Fallback chain, best first.
SOLVERS = ("cholmod", "pardiso", "amg", "superlu")


def _has(module: str) -> bool:
    from importlib.util import find_spec

    try:
        return find_spec(module) is not None
    except (ImportError, ValueError):  # pragma: no cover
        return False


def available_solvers() -> list[str]:
    """Solvers whose Python packages are importable here, in fallback order."""
    mods = {"cholmod": "sksparse", "pardiso": "pypardiso", "amg": "pyamg", "superlu": "scipy"}
    return [s for s in SOLVERS if _has(mods[s])]


def _cholmod(A):
    from sksparse.cholmod import cholesky

    fac = cholesky(A.tocsc(), ordering_method="default")
    return lambda B: fac(np.asarray(B))


def _pardiso(A):
    import pypardiso

    solver = pypardiso.PyPardisoSolver(mtype=2)        # real symmetric positive definite
    import scipy.sparse as sp

    Au = sp.triu(A, format="csr")
    solver.factorize(Au)
    return lambda B: solver.solve(Au, np.asarray(B))


def _amg(A):
    import pyamg
    from scipy.sparse.linalg import cg

    A = A.tocsr()
    ml = pyamg.smoothed_aggregation_solver(A, symmetry="symmetric", max_coarse=500)
    M = ml.aspreconditioner(cycle="V")

    def solve(B):
        B = np.asarray(B)
        B2 = B.reshape(B.shape[0], -1)
        X = np.empty_like(B2)
        for j in range(B2.shape[1]):
            nb = np.linalg.norm(B2[:, j])
            if nb == 0:
                X[:, j] = 0.0
                continue
            x, info = cg(A, B2[:, j], rtol=1e-10, atol=0.0, M=M, maxiter=2000)
            if info != 0:
                log.warning("pyamg+CG did not converge for RHS %d (info=%d)", j, info)
            X[:, j] = x
        return X.reshape(B.shape)
    return solve


def _superlu(A):
    from scipy.sparse.linalg import splu

    log.warning("using scipy SuperLU: slow and memory-hungry on 3-D P2 problems; install "
                "scikit-sparse (CHOLMOD) or pypardiso (see docs/fem.md)")
    lu = splu(A.tocsc(), permc_spec="MMD_AT_PLUS_A")
    return lambda B: lu.solve(np.asarray(B))


_FACTORY = {"cholmod": _cholmod, "pardiso": _pardiso, "amg": _amg, "superlu": _superlu}


def factorize(A, solver: str | None = None) -> tuple[Callable[[np.ndarray], np.ndarray], str]:
    """Factorise a sparse SPD matrix with the best available solver.

    Parameters
    ----------
    A : scipy.sparse matrix
        Symmetric positive-definite matrix (n, n).
    solver : str, optional
        One of :data:`SOLVERS` to force a solver; default: ``$BALLRACE_SOLVER`` or
        the first available in the chain.

    Returns
    -------
    solve : callable
        ``solve(B)`` -> ``A^{-1} B`` for a dense (n,) or (n, m) array.
    name : str
        The solver used.
    """
    wanted = solver or os.environ.get("BALLRACE_SOLVER") or None
    chain = [wanted] if wanted else available_solvers()
    if wanted and wanted not in SOLVERS:
        raise ValueError(f"solver must be one of {', '.join(SOLVERS)}; got {wanted!r}")
    last = None
    for name in chain:
        try:
            solve = _FACTORY[name](A)
        except ImportError as exc:
            log.info("solver %s unavailable: %s", name, exc)
            last = exc
            continue
        log.info("sparse solver: %s (n = %d, nnz = %d)", name, A.shape[0], A.nnz)
        return solve, name
    raise RuntimeError(f"no sparse solver available (last error: {last})")
