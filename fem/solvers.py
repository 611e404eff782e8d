"""Sparse symmetric positive-definite solvers with a run-time fallback chain.

The FE check factorises one stiffness matrix per body and needs, per body, the
compliance ``F^T K^{-1} F`` of 30-300 pressure tents (F lives on the contact-surface
DOFs only) and one full solve per load for the displacement field.  Measured on this
project's 2-core machine (docs/fem.md; P2 elasticity, 209 inner race, standard level,
depth-graded mesh: 172k DOFs; idle machine):

==============================  ==========================  ============================
solver                          factorise / 286 tents       install
==============================  ==========================  ============================
PARDISO (MKL) through           ~16 s / 0.2 s (partial      pip only: pypardiso in
:class:`PardisoFactor`          solve of the surface rows)  ``ballrace[fem]`` on Linux and
                                                            Windows x86-64
CHOLMOD (scikit-sparse 0.4.16)  11.4 s / 5.8 s (full        apt libsuitesparse-dev +
+ OpenBLAS                      solves in blocks)           libopenblas0-pthread, then pip
                                                            (``make cholmod``)
pyamg SA + CG, rigid-body       44 CG iterations, ~10 s     pip only; opt-in
near-nullspace                  per tent (51k DOFs)
scipy SuperLU (``splu``)        ~100x CHOLMOD, ~10x memory  always present: last resort
==============================  ==========================  ============================

:func:`factorize` tries ``cholmod, pardiso, superlu`` (:data:`CHAIN`) and returns a
:class:`Factor`: ``factor(B)`` solves, ``factor.inner(F)`` gives ``F^T A^{-1} F``
(PARDISO: partial solve; the others: full solves in column blocks, never a dense
n x (tents) copy), ``factor.free()`` releases the memory.  ``amg`` is used only when
asked for (``solver="amg"`` or ``BALLRACE_SOLVER=amg``): even with the six rigid-body
modes as near-nullspace (:func:`rigid_body_modes`) one CG solve per pressure tent makes
it slower than a factorisation for every mesh of the FE check.
:func:`slow_solver_hint` tells the user at the start of a run when only a slow solver is
available, with the install line.
"""
from __future__ import annotations

import logging
import os

import numpy as np

__all__ = ["SOLVERS", "CHAIN", "INSTALL_HINT", "available_solvers", "chosen_solver",
           "slow_solver_hint", "factorize", "rigid_body_modes", "Factor", "PardisoFactor"]

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


class Factor:
    """A factorised SPD matrix: ``factor(B)`` solves ``A X = B``; :meth:`inner` gives
    ``F^T A^{-1} F`` (the compliance of the FE check) without the full solutions.

    Subclasses override :meth:`_solve` and, where the solver can do better than a full
    solve, :meth:`inner`.  Right-hand sides are solved in blocks of :attr:`block`
    columns so that a few hundred tents never need a dense ``n x m`` copy of the
    solutions.
    """

    name = "base"
    block = 64

    def __init__(self, n: int):
        self.n = n

    def _solve(self, B: np.ndarray) -> np.ndarray:        # pragma: no cover - abstract
        raise NotImplementedError

    def __call__(self, B) -> np.ndarray:
        B = np.asarray(B, dtype=float)
        return self._solve(B)

    def inner(self, F) -> np.ndarray:
        """``F^T A^{-1} F`` for F (n, m), sparse or dense, solved in column blocks."""
        import scipy.sparse as sp

        F = sp.csc_matrix(F)
        m = F.shape[1]
        out = np.empty((m, m))
        for j0 in range(0, m, self.block):
            X = self._solve(F[:, j0:j0 + self.block].toarray())
            out[:, j0:j0 + self.block] = np.asarray(F.T @ X)
        return out

    def free(self) -> None:
        """Release the factor's memory (the object cannot solve afterwards)."""


class _FnFactor(Factor):
    def __init__(self, n, fn, name):
        super().__init__(n)
        self._fn = fn
        self.name = name

    def _solve(self, B):
        return self._fn(B)

    def free(self):
        self._fn = None


def _cholmod(A):
    from sksparse.cholmod import cholesky

    fac = cholesky(A.tocsc(), ordering_method="default")
    return _FnFactor(A.shape[0], lambda B: fac(np.asarray(B)), "cholmod")


class PardisoFactor(Factor):
    """Intel MKL PARDISO through ctypes on the ``mkl_rt`` that pypardiso loads.

    pypardiso's own ``solve`` is used by nobody here: it re-hashes the matrix on every
    call, copies the right-hand sides twice and has no partial solve.  This driver
    factorises the upper triangle once (``mtype = 2``, real SPD; METIS nested
    dissection) and offers the *partial solve* of PARDISO (``iparm[30] = 1``, Intel
    oneMKL Developer Reference, "pardiso iparm parameter"): when the right-hand sides
    are non-zero only on a few rows S and only the rows S of the solution are wanted —
    exactly ``F^T A^{-1} F`` with F living on the contact-surface DOFs — only the
    elimination-tree paths of S are visited.  Measured (209 inner race, 261k DOFs, 286
    tents): 0.2 s instead of 45 s for the full solves.
    """

    name = "pardiso"

    def __init__(self, A):
        import ctypes

        import pypardiso
        import scipy.sparse as sp

        super().__init__(A.shape[0])
        self._ct = ctypes
        lib = pypardiso.PyPardisoSolver().libmkl
        fn = lib.pardiso
        P = ctypes.POINTER
        i32 = ctypes.c_int32
        fn.argtypes = [P(ctypes.c_int64), P(i32), P(i32), P(i32), P(i32), P(i32),
                       ctypes.c_void_p, P(i32), P(i32), P(i32), P(i32), P(i32), P(i32),
                       ctypes.c_void_p, ctypes.c_void_p, P(i32)]
        fn.restype = None
        self._fn = fn
        U = sp.triu(A, format="csr")
        U.sort_indices()
        U.sum_duplicates()
        if U.nnz >= 2**31:  # pragma: no cover - far beyond the FE check's meshes
            raise ValueError("matrix too large for 32-bit PARDISO indices")
        self._a = np.ascontiguousarray(U.data, dtype=float)
        self._ia = U.indptr.astype(np.int32)
        self._ja = U.indices.astype(np.int32)
        self._pt = np.zeros(64, dtype=np.int64)
        self._iparm = np.zeros(64, dtype=np.int32)
        ip = self._iparm
        ip[0] = 1          # user-set iparm
        ip[1] = 2          # METIS nested dissection
        ip[9] = 13         # pivot perturbation 1e-13 (not used by mtype 2)
        ip[34] = 1         # zero-based indices
        # the partial solve must be announced at the reordering, with the rows in perm
        self._perm = np.zeros(self.n, dtype=np.int32)
        self._rows = None
        self._factored = False

    def _call(self, phase, B=None, X=None, nrhs=1):
        ct = self._ct
        err = ct.c_int32(0)

        def i32(v):
            return ct.byref(ct.c_int32(v))
        P = ct.POINTER(ct.c_int32)
        self._fn(self._pt.ctypes.data_as(ct.POINTER(ct.c_int64)), i32(1), i32(1), i32(2),
                 i32(phase), i32(self.n), self._a.ctypes.data, self._ia.ctypes.data_as(P),
                 self._ja.ctypes.data_as(P), self._perm.ctypes.data_as(P), i32(nrhs),
                 self._iparm.ctypes.data_as(P), i32(0),
                 None if B is None else B.ctypes.data, None if X is None else X.ctypes.data,
                 ct.byref(err))
        if err.value != 0:
            raise RuntimeError(f"PARDISO error {err.value} in phase {phase} "
                               f"(n = {self.n}; -2: out of memory, -4: zero pivot, "
                               f"the matrix is not positive definite)")

    def factor(self, rows=None):
        """Reorder and factorise; ``rows`` (indices) prepares the partial solve on them."""
        if rows is not None:
            self._perm[:] = 0
            self._perm[np.asarray(rows)] = 1
            self._rows = np.asarray(rows)
            self._iparm[30] = 1
        dummy = np.zeros(self.n)
        self._call(11, dummy, dummy.copy())
        self._call(22, dummy, dummy.copy())
        self._factored = True
        log.info("PARDISO: factor %.0f MB (peak %.0f MB during factorisation)",
                 self._iparm[16] / 1e3, max(self._iparm[14], self._iparm[15] + self._iparm[16]) / 1e3)
        return self

    def _solve(self, B):
        B = np.asarray(B, dtype=float)
        one = B.ndim == 1
        B2 = B.reshape(self.n, -1)
        out = np.empty_like(B2)
        saved = int(self._iparm[30])
        self._iparm[30] = 0
        try:
            for j0 in range(0, B2.shape[1], self.block):
                Bj = np.asfortranarray(B2[:, j0:j0 + self.block])
                Xj = np.zeros_like(Bj)
                self._call(33, Bj, Xj, Bj.shape[1])
                out[:, j0:j0 + self.block] = Xj
        finally:
            self._iparm[30] = saved
        return out[:, 0] if one else out

    def inner(self, F):
        import scipy.sparse as sp

        F = sp.csc_matrix(F)
        rows = np.flatnonzero(np.diff(sp.csr_matrix(F).indptr))
        if self._rows is None or not np.isin(rows, self._rows).all():
            return super().inner(F)
        m = F.shape[1]
        FS = F[self._rows].toarray()                   # (|S|, m)
        out = np.empty((m, m))
        for j0 in range(0, m, self.block):
            Bj = np.zeros((self.n, min(self.block, m - j0)), order="F")
            Bj[self._rows] = FS[:, j0:j0 + self.block]
            Xj = np.zeros_like(Bj)
            self._call(33, Bj, Xj, Bj.shape[1])        # iparm[30] = 1: only rows S
            out[:, j0:j0 + self.block] = FS.T @ Xj[self._rows]
        return out

    def free(self):
        if self._factored:
            self._call(-1)
            self._factored = False

    def __del__(self):
        try:
            self.free()
        except Exception:  # pragma: no cover - interpreter shutdown
            pass


def _pardiso(A, rows=None):
    return PardisoFactor(A).factor(rows)


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
                from ballrace.errors import ConvergenceError

                raise ConvergenceError(f"pyamg+CG: residual {res[-1] / res[0]:.1e} after "
                                       f"{len(res) - 1} iterations (RHS {j})")
            iters.append(len(res) - 1)
            X[:, j] = x
        if iters:
            log.info("pyamg+CG: %d right-hand sides, %.0f iterations each (max %d)",
                     len(iters), np.mean(iters), max(iters))
        return X.reshape(B.shape)
    return _FnFactor(A.shape[0], solve, "amg")


def _superlu(A):
    from scipy.sparse.linalg import splu

    log.warning("using scipy SuperLU: slow and memory-hungry on 3-D P2 problems; %s",
                INSTALL_HINT)
    lu = splu(A.tocsc(), permc_spec="MMD_AT_PLUS_A")
    return _FnFactor(A.shape[0], lambda B: lu.solve(np.asarray(B)), "superlu")


_FACTORY = {"cholmod": _cholmod, "pardiso": _pardiso, "amg": _amg, "superlu": _superlu}


def factorize(A, solver: str | None = None, *, near_nullspace=None, rows=None
              ) -> tuple[Factor, str]:
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
    rows : array of int, optional
        The rows on which the right-hand sides of :meth:`Factor.inner` live (the
        contact-surface DOFs); PARDISO then prepares its partial solve.

    Returns
    -------
    factor : Factor
        ``factor(B)`` -> ``A^{-1} B`` for a dense (n,) or (n, m) array;
        ``factor.inner(F)`` -> ``F^T A^{-1} F``; ``factor.free()`` releases it.
    name : str
        The solver used.

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> A = sp.diags([2.0, 4.0, 8.0]).tocsc()
    >>> f, name = factorize(A, "superlu")
    >>> f(np.array([2.0, 4.0, 8.0])).tolist(), f.inner(np.eye(3)[:, :1]).tolist()
    ([1.0, 1.0, 1.0], [[0.5]])
    """
    wanted = solver or os.environ.get("BALLRACE_SOLVER") or None
    if wanted and wanted not in SOLVERS:
        raise ValueError(f"solver must be one of {', '.join(SOLVERS)}; got {wanted!r}")
    avail = available_solvers()
    chain = [wanted] if wanted else [s for s in CHAIN if s in avail]
    last = None
    for name in chain:
        try:
            if name == "amg":
                fac = _amg(A, near_nullspace)
            elif name == "pardiso":
                fac = _pardiso(A, rows)
            else:
                fac = _FACTORY[name](A)
        except ImportError as exc:
            log.info("solver %s unavailable: %s", name, exc)
            last = exc
            continue
        log.info("sparse solver: %s (n = %d, nnz = %d)", name, A.shape[0], A.nnz)
        return fac, name
    raise RuntimeError(f"no sparse solver available (last error: {last})")
