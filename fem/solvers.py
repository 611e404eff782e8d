"""Sparse symmetric positive-definite solvers with a run-time fallback chain.

The FE check factorises one stiffness matrix per body and solves it for 30–200
right-hand sides (the pressure tents).  Measured on this project's 2-core machine
(docs/fem.md; P2 elasticity, 209 inner race, quick level: 51k free DOFs, 4.0M
non-zeros; factorisation / 20 right-hand sides):

==============================  ==================  ================================
solver                          51k DOFs            install
==============================  ==================  ================================
CHOLMOD (scikit-sparse 0.4.16)  3.9 s / 0.3 s       apt libsuitesparse-dev +
+ OpenBLAS                                          libopenblas0-pthread, then pip
                                                    (``make cholmod``)
pypardiso (MKL)                 6.3 s / 1.6 s       pip only: in ``ballrace[fem]`` on
                                                    Linux and Windows x86-64
pyamg SA + CG, rigid-body       3.5 s / 44 CG       pip only; opt-in
near-nullspace                  iterations, ~10 s
                                per RHS
scipy SuperLU (``splu``)        ~100x CHOLMOD,      always present: last resort
                                ~10x memory
==============================  ==================  ================================

:func:`factorize` tries ``cholmod, pardiso, superlu`` (:data:`CHAIN`); ``amg`` is
used only when asked for (``solver="amg"`` or the environment variable
``BALLRACE_SOLVER=amg``): even with the six rigid-body modes as near-nullspace
(:func:`rigid_body_modes`, which cut the CG iterations to ~44 at rtol 1e-10) one
solve per pressure tent makes it slower than a direct factorisation for every mesh
of the FE check.  :func:`slow_solver_hint` tells the user at the start of a run when
only a slow solver is available, with the install line.
"""
from __future__ import annotations

import logging
import os
from typing import Callable

import numpy as np

__all__ = ["SOLVERS", "CHAIN", "INSTALL_HINT", "available_solvers", "chosen_solver",
           "slow_solver_hint", "factorize", "rigid_body_modes"]

log = logging.getLogger(__name__)

#: Every solver that can be forced, best first.
SOLVERS = ("cholmod", "pardiso", "amg", "superlu")
#: The automatic fallback chain (``amg`` only on request, see the module docstring).
CHAIN = ("cholmod", "pardiso", "superlu")
#: What to install for a fast solver.
INSTALL_HINT = ('pip install "ballrace[fem]" brings pypardiso (MKL) on Linux/Windows x86-64; '
                'elsewhere install scikit-sparse on SuiteSparse (apt: libsuitesparse-dev, '
                'or `make cholmod`); see docs/fem.md "Sparse solver"')
_MODULES = {"cholmod": "sksparse", "pardiso": "pypardiso", "amg": "pyamg", "superlu": "scipy"}


def _has(module: str) -> bool:
    from importlib.util import find_spec

    try:
        return find_spec(module) is not None
    except (ImportError, ValueError):  # pragma: no cover
        return False


def available_solvers() -> list[str]:
    """Solvers whose Python packages are importable here, best first (:data:`SOLVERS`)."""
    return [s for s in SOLVERS if _has(_MODULES[s])]


def chosen_solver(solver: str | None = None) -> str:
    """The solver :func:`factorize` will use: ``solver``, else ``$BALLRACE_SOLVER``, else
    the first importable one of :data:`CHAIN`.

    Examples
    --------
    >>> chosen_solver("superlu")
    'superlu'
    """
    wanted = solver or os.environ.get("BALLRACE_SOLVER") or None
    if wanted:
        if wanted not in SOLVERS:
            raise ValueError(f"solver must be one of {', '.join(SOLVERS)}; got {wanted!r}")
        return wanted
    avail = available_solvers()
    return next(s for s in CHAIN if s in avail)


def slow_solver_hint(solver: str | None = None, n_dofs: int | None = None) -> str | None:
    """A warning text when the run will use a slow solver, else None.

    Parameters
    ----------
    solver : str, optional
        Forced solver (as for :func:`factorize`).
    n_dofs : int, optional
        Expected number of DOFs, quoted in the message [-].

    Examples
    --------
    >>> "pip install" in slow_solver_hint("superlu", 50000)
    True
    >>> slow_solver_hint("cholmod") is None
    True
    """
    name = chosen_solver(solver)
    if name in ("cholmod", "pardiso"):
        return None
    size = f" for ~{n_dofs:,} DOFs" if n_dofs else ""
    what = ("scipy SuperLU (~100x slower than a sparse Cholesky, ~10x the memory)"
            if name == "superlu" else "pyamg + CG (one iterative solve per pressure tent)")
    return (f"the FE check will use {what}{size}: expect minutes to hours; "
            f"for a fast sparse direct solver: {INSTALL_HINT}")


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


def rigid_body_modes(coords, components) -> np.ndarray:
    """The six rigid-body modes of 3-D elasticity at the given DOFs (n, 6) [m, -].

    Columns: translations along x, y, z, then rotations about x, y, z (``omega x r``)
    about the centroid, each normalised; rows are the DOFs with node coordinates
    ``coords`` (n, 3) [m] and displacement component ``components`` (n,) in {0, 1, 2}.
    They are the near-nullspace that smoothed aggregation needs for elasticity
    (Vanek, Mandel & Brezina 1996 §4): with the default constant vector alone the
    coarse spaces miss the rotations and CG crawls.

    Examples
    --------
    >>> B = rigid_body_modes(np.eye(3), np.array([0, 1, 2]))
    >>> B.shape
    (3, 6)
    """
    x = np.asarray(coords, dtype=float)
    c = np.asarray(components)
    x = x - x.mean(axis=0)
    n = x.shape[0]
    B = np.zeros((n, 6))
    for k in range(3):
        B[c == k, k] = 1.0
    # rotation about axis k: u = e_k x r
    for k, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):
        # (e_k x r)_i = -r_j, (e_k x r)_j = r_i
        B[c == i, 3 + k] = -x[c == i, j]
        B[c == j, 3 + k] = x[c == j, i]
    nrm = np.linalg.norm(B, axis=0)
    return B / np.where(nrm > 0, nrm, 1.0)


def _amg(A, near_nullspace=None, rtol: float = 1e-10, maxiter: int = 1000):
    import pyamg

    A = A.tocsr()
    kw = {}
    if near_nullspace is not None:
        kw["B"] = np.ascontiguousarray(near_nullspace, dtype=float)
        kw["BH"] = kw["B"].copy()
    else:
        log.warning("pyamg without the rigid-body near-nullspace: slow convergence expected")
    ml = pyamg.smoothed_aggregation_solver(A, symmetry="hermitian", max_coarse=1000,
                                           smooth=("energy", {"krylov": "cg"}), **kw)
    log.info("pyamg hierarchy: %s", " -> ".join(str(lv.A.shape[0]) for lv in ml.levels))

    def solve(B):
        B = np.asarray(B)
        B2 = B.reshape(B.shape[0], -1)
        X = np.empty_like(B2)
        iters = []
        for j in range(B2.shape[1]):
            if not np.any(B2[:, j]):
                X[:, j] = 0.0
                continue
            res = []
            x = ml.solve(B2[:, j], tol=rtol, accel="cg", maxiter=maxiter, residuals=res)
            if res[-1] > rtol * res[0]:
                from ballrace.analytic.loaddist import ConvergenceError

                raise ConvergenceError(f"pyamg+CG: residual {res[-1] / res[0]:.1e} after "
                                       f"{len(res) - 1} iterations (RHS {j})")
            iters.append(len(res) - 1)
            X[:, j] = x
        if iters:
            log.info("pyamg+CG: %d right-hand sides, %.0f iterations each (max %d)",
                     len(iters), np.mean(iters), max(iters))
        return X.reshape(B.shape)
    return solve


def _superlu(A):
    from scipy.sparse.linalg import splu

    log.warning("using scipy SuperLU: slow and memory-hungry on 3-D P2 problems; %s",
                INSTALL_HINT)
    lu = splu(A.tocsc(), permc_spec="MMD_AT_PLUS_A")
    return lambda B: lu.solve(np.asarray(B))


_FACTORY = {"cholmod": _cholmod, "pardiso": _pardiso, "amg": _amg, "superlu": _superlu}


def factorize(A, solver: str | None = None, *, near_nullspace=None
              ) -> tuple[Callable[[np.ndarray], np.ndarray], str]:
    """Factorise a sparse SPD matrix with the best available solver.

    Parameters
    ----------
    A : scipy.sparse matrix
        Symmetric positive-definite matrix (n, n).
    solver : str, optional
        One of :data:`SOLVERS` to force a solver; default: ``$BALLRACE_SOLVER`` or
        the first available in :data:`CHAIN`.
    near_nullspace : ndarray (n, k), optional
        Near-nullspace for ``amg`` (:func:`rigid_body_modes`) [-]; ignored otherwise.

    Returns
    -------
    solve : callable
        ``solve(B)`` -> ``A^{-1} B`` for a dense (n,) or (n, m) array.
    name : str
        The solver used.
    """
    wanted = solver or os.environ.get("BALLRACE_SOLVER") or None
    if wanted and wanted not in SOLVERS:
        raise ValueError(f"solver must be one of {', '.join(SOLVERS)}; got {wanted!r}")
    avail = available_solvers()
    chain = [wanted] if wanted else [s for s in CHAIN if s in avail]
    last = None
    for name in chain:
        try:
            solve = (_FACTORY[name](A, near_nullspace) if name == "amg"
                     else _FACTORY[name](A))
        except ImportError as exc:
            log.info("solver %s unavailable: %s", name, exc)
            last = exc
            continue
        log.info("sparse solver: %s (n = %d, nnz = %d)", name, A.shape[0], A.nnz)
        return solve, name
    raise RuntimeError(f"no sparse solver available (last error: {last})")
