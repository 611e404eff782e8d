r"""Elastic bodies, the pressure grid, the compliance matrix and the NNLS contact solve.

Formulation (docs/fem.md; Kalker's variational principle in a discrete form):

* the contact pressure is ``p(x, y) = sum_k lambda_k phi_k(x, y)`` with bilinear tents
  ``phi_k`` on a structured grid over the expected quarter ellipse, independent of
  the FE mesh; ``lambda >= 0`` is ``p >= 0``;
* each body i (P2 tetrahedra, linear elasticity, symmetry planes x = 0 and y = 0,
  its far plane held in z) gets the load matrix
  ``F_i[:, k] = s_i int phi_k |n_z| v_z dA`` over its candidate contact facets
  (s_i = +1 for the ball, pushed up, -1 for the lower body, pushed down); the
  stiffness is factorised once;
* compliance ``C = sum_i F_i^T K_i^{-1} F_i`` (small, symmetric positive definite;
  PARDISO's partial solve computes only the contact-surface rows of ``K_i^{-1} F_i``);
* weighted gap ``G_k = G0_k + (C lambda)_k - Delta m_k`` with ``G0_k = int phi_k g0 dA``
  from the analytic surfaces and ``m_k = int phi_k dA``; Delta is the rigid approach
  of the bodies' far planes;
* for fixed Delta, ``min 1/2 l^T C l + (G0 - Delta m)^T l, l >= 0`` is the NNLS problem
  ``min |L^T l + L^{-1}(G0 - Delta m)|`` with ``C = L L^T``; an outer root-find on
  Delta matches ``m^T lambda`` to the (quarter) load;
* optionally C is replaced by ``C + P`` in the energy, P a curvature penalty on the tent
  pressures (:meth:`PressureGrid.curvature_penalty`) that damps the tent checkerboard
  of a pressure grid as fine as the mesh (``MeshLevel.smoothing``).

Everything heavy (scikit-fem) is imported inside the functions.
"""
from __future__ import annotations

import functools
import logging
import time
from dataclasses import dataclass, field

import numpy as np

__all__ = ["PressureGrid", "Body", "skfem_mesh", "BodyState", "assemble_body",
           "ContactSolution", "solve_contact", "compliance", "traction_response"]

log = logging.getLogger(__name__)


# --------------------------------------------------------------------------- pressure grid
@dataclass(frozen=True)
class PressureGrid:
    """Structured grid of bilinear tents on ``[0, Lx] x [0, Ly]`` (quarter model).

    Attributes
    ----------
    Lx, Ly : float
        Extent [m].
    nx, ny : int
        Number of cells along x and y.

    Examples
    --------
    >>> g = PressureGrid(1.0, 2.0, 4, 8)
    >>> g.n_tents, round(float(g.integrals(lambda x, y: 0 * x)["m"].sum()), 12)
    (45, 2.0)
    """

    Lx: float
    Ly: float
    nx: int
    ny: int

    @property
    def n_tents(self) -> int:
        """Number of tents (grid nodes)."""
        return (self.nx + 1) * (self.ny + 1)

    @property
    def dx(self) -> float:
        """Cell size along x [m]."""
        return self.Lx / self.nx

    @property
    def dy(self) -> float:
        """Cell size along y [m]."""
        return self.Ly / self.ny

    def nodes(self):
        """Tent centres (x, y), each (n_tents,), index k = i * (ny + 1) + j [m]."""
        X, Y = np.meshgrid(np.linspace(0, self.Lx, self.nx + 1),
                           np.linspace(0, self.Ly, self.ny + 1), indexing="ij")
        return X.ravel(), Y.ravel()

    def weights(self, x, y):
        """Bilinear tent weights at points: (point index, tent index, weight), 4 per point.

        Points outside the grid get zero weights.
        """
        x = np.asarray(x, dtype=float).ravel()
        y = np.asarray(y, dtype=float).ravel()
        u = x / self.dx
        v = y / self.dy
        inside = (u >= 0) & (u <= self.nx) & (v >= 0) & (v <= self.ny)
        i = np.clip(np.floor(u).astype(np.int64), 0, self.nx - 1)
        j = np.clip(np.floor(v).astype(np.int64), 0, self.ny - 1)
        fu = np.clip(u - i, 0.0, 1.0)
        fv = np.clip(v - j, 0.0, 1.0)
        return bilinear_weights(i, j, fu, fv, inside, self.ny + 1)

    def evaluate(self, lam, x, y):
        """Pressure ``sum lambda_k phi_k`` at points (x, y) [Pa]."""
        return evaluate_tents(self, lam, x, y)


    def integrals(self, gap, order: int = 6) -> dict:
        """Tent integrals over the grid (Gauss, ``order`` points per direction per cell).

        Returns ``m = int phi_k``, ``G0 = int phi_k g0``, ``Mxx = int phi_k x^2``,
        ``Myy = int phi_k y^2`` (arrays of length n_tents) for ``gap(x, y)`` [m].
        """
        g, w = np.polynomial.legendre.leggauss(order)
        g = 0.5 * (g + 1.0)
        w = 0.5 * w
        ci, cj = np.meshgrid(np.arange(self.nx), np.arange(self.ny), indexing="ij")
        ci, cj = ci.ravel(), cj.ravel()
        GU, GV = np.meshgrid(g, g, indexing="ij")
        WW = np.outer(w, w).ravel() * self.dx * self.dy
        fu, fv = GU.ravel(), GV.ravel()
        x = (ci[:, None] + fu[None, :]) * self.dx
        y = (cj[:, None] + fv[None, :]) * self.dy
        g0 = gap(x, y)
        out = {k: np.zeros(self.n_tents) for k in ("m", "G0", "Mxx", "Myy")}
        for di, dj, phi in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)),
                            (0, 1, (1 - fu) * fv), (1, 1, fu * fv)):
            k = (ci + di) * (self.ny + 1) + (cj + dj)
            pw = phi * WW
            np.add.at(out["m"], k, np.full(k.size, pw.sum()))
            np.add.at(out["G0"], k, (g0 * pw).sum(axis=1))
            np.add.at(out["Mxx"], k, (x * x * pw).sum(axis=1))
            np.add.at(out["Myy"], k, (y * y * pw).sum(axis=1))
        return out

    def curvature_penalty(self) -> np.ndarray:
        """Dense (n_tents, n_tents) matrix ``R = Dx^T Dx + Dy^T Dy`` of the tents' second
        differences along x and y (the grid mirrored about its first and last tents: the
        symmetry edges x = 0, y = 0 and the outer edges, where the pressure is zero) [-].  ``lam^T R lam`` is 16 per tent for the checkerboard
        ``lam_ij = (-1)^(i+j)`` and of order ``(spacing / wavelength)^4`` for a smooth
        pressure (used by :func:`solve_contact` to damp the tent oscillation: a
        Tikhonov (1963) penalty on the discrete multiplier, in the spirit of the
        stabilised Lagrange multipliers of Barbosa & Hughes (1991) that circumvent the
        inf-sup condition; docs/fem.md).

        Examples
        --------
        >>> g = PressureGrid(1.0, 1.0, 4, 4)
        >>> i, j = np.meshgrid(np.arange(5), np.arange(5), indexing="ij")
        >>> chk = ((-1.0) ** (i + j)).ravel()
        >>> R = g.curvature_penalty()
        >>> float(R @ np.ones(25) @ np.ones(25)), bool(chk @ R @ chk > 8 * 25)
        (0.0, True)
        """
        def d2(n):
            D = np.zeros((n, n))
            for i in range(n):
                D[i, i] -= 2.0
                D[i, abs(i - 1)] += 1.0
                if i + 1 < n:
                    D[i, i + 1] += 1.0
                else:
                    D[i, i - 1] += 1.0
            return D
        nx, ny = self.nx + 1, self.ny + 1
        Dx = np.kron(d2(nx), np.eye(ny))
        Dy = np.kron(np.eye(nx), d2(ny))
        return Dx.T @ Dx + Dy.T @ Dy

    def boundary_tents(self) -> np.ndarray:
        """Indices of the tents on the outer edges x = Lx or y = Ly."""
        i, j = np.meshgrid(np.arange(self.nx + 1), np.arange(self.ny + 1), indexing="ij")
        mask = (i == self.nx) | (j == self.ny)
        return np.flatnonzero(mask.ravel())


def bilinear_weights(i, j, fu, fv, inside, n_y_nodes: int):
    """Bilinear tent weights of points in cells (i, j) at fractions (fu, fv) [-]:
    (point index, tent index k = i * n_y_nodes + j, weight), 4 per point, zero where not
    ``inside`` (shared by the uniform and the graded grids)."""
    pid = np.arange(np.size(i))
    rows, cols, vals = [], [], []
    for di, dj, w in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)),
                      (0, 1, (1 - fu) * fv), (1, 1, fu * fv)):
        rows.append(pid)
        cols.append((i + di) * n_y_nodes + (j + dj))
        vals.append(np.where(inside, w, 0.0))
    return np.concatenate(rows), np.concatenate(cols), np.concatenate(vals)


def evaluate_tents(grid, lam, x, y):
    """Pressure ``sum lambda_k phi_k`` at points (x, y) of a grid with ``weights`` [Pa]."""
    x = np.asarray(x, dtype=float)
    r, c, w = grid.weights(x, y)
    out = np.zeros(x.size)
    np.add.at(out, r, w * np.asarray(lam)[c])
    return out.reshape(x.shape)


# --------------------------------------------------------------------------- bodies
@dataclass
class Body:
    """One elastic body of the quarter model.

    Attributes
    ----------
    name : label ("ball", "race", "plane", "half-space").
    points, tets : mesh (physical coordinates [m]) and connectivity.
    E, nu : Young's modulus [Pa] and Poisson's ratio [-].
    side : +1 for the upper body (ball, surface below it), -1 for the lower body.
    z_fixed : the plane z = z_fixed is held in z (block bottom, ball equator) [m].
    contact_nodes : boolean mask of the vertices on the candidate contact surface.
    surface : object with ``height(x, y)`` for the body's surface (depth reference).
    symmetric_x : True (default): the plane x = 0 is a symmetry plane of the model
        (u_x = 0 on it).  False: the body spans both sides of x = 0 (a half model); its
        x-translation is held by the one u_x DOF nearest ``(0, 0, z_fixed)``, which
        carries no load (frictionless normal tractions, supports normal to their planes).
    """

    name: str
    points: np.ndarray
    tets: np.ndarray
    E: float
    nu: float
    side: int
    z_fixed: float
    contact_nodes: np.ndarray
    surface: object = None
    symmetric_x: bool = True


@dataclass
class BodyState:
    """A body after assembly and factorisation: basis, load matrix F, the body's
    compliance ``C = F^T K^{-1} F`` and the factor for the displacements."""

    body: Body
    basis: object
    scalar_basis: object
    F: object               # sparse (n_dofs, n_tents)
    C: np.ndarray           # dense (n_tents, n_tents) [m^5/N]
    free: np.ndarray        # free DOFs
    factor: object          # fem.solvers.Factor on the free DOFs (None once released)
    n_dofs: int
    solver: str
    timings: dict = field(default_factory=dict)

    def displacement(self, lam) -> np.ndarray:
        """Displacement vector ``u = K^{-1} F lambda`` on all DOFs [m] for tent pressures
        ``lam`` [Pa]: one solve with the stored factor."""
        if self.factor is None:
            raise RuntimeError(f"{self.body.name}: the factor was released; use the "
                               "displacements stored in FEResult.fields['u']")
        u = np.zeros(self.n_dofs)
        u[self.free] = self.factor(np.asarray(self.F[self.free] @ np.asarray(lam)).ravel())
        return u

    def release(self) -> None:
        """Free the factor's memory."""
        if self.factor is not None:
            self.factor.free()
            self.factor = None

    @property
    def mesh(self):
        """The scikit-fem mesh."""
        return self.basis.mesh


def skfem_mesh(points, tets):
    """The scikit-fem ``MeshTet`` of a tetrahedral mesh, every tetrahedron oriented
    positively (as the bodies are assembled).

    Parameters
    ----------
    points : ndarray, shape (n, 3)
        Node coordinates [m].
    tets : ndarray, shape (m, 4)
        Node indices of each tetrahedron [-].
    """
    from skfem import MeshTet

    p = np.ascontiguousarray(points.T)
    t = np.ascontiguousarray(tets.T)
    # orient every tetrahedron positively
    a, b, c, d = (p[:, t[i]] for i in range(4))
    vol = np.einsum("ij,ij->j", np.cross(b - a, c - a, axis=0), d - a)
    neg = vol < 0
    if np.any(neg):
        t = t.copy()
        t[[1, 2]] = np.where(neg, t[[2, 1]], t[[1, 2]])
    return MeshTet(p, t)


@functools.lru_cache(maxsize=1)
def _p2_gradient_products():
    """M[a, k, b, l] = (1/V) int c_ak c_bl dV for the P2 tetrahedron, with the gradients
    of the ten scalar basis functions written as grad N_a = sum_k c_ak(lambda) grad lambda_k.

    Vertex i: N = lambda_i (2 lambda_i - 1), c_ai = 4 lambda_i - 1; edge (i, j):
    N = 4 lambda_i lambda_j, c_ai = 4 lambda_j, c_aj = 4 lambda_i (local order of
    scikit-fem's ``ElementTetP2.doflocs``).  The products are quadratic in lambda, so the
    4-point rule (Keast 1986, degree 2, weights V/4) integrates them exactly.
    """
    from skfem import ElementTetP2

    locs = np.asarray(ElementTetP2().doflocs, dtype=float)          # (10, 3) reference
    bary = np.column_stack([1.0 - locs.sum(axis=1), locs])           # (10, 4)
    pa, pb = 0.5854101966249685, 0.1381966011250105
    q = np.full((4, 4), pb) + np.eye(4) * (pa - pb)                  # barycentric quad points
    c = np.zeros((4, 10, 4))                                         # (point, a, k)
    for a, lam in enumerate(bary):
        nz = np.flatnonzero(lam > 0.25)
        if nz.size == 1:                                             # vertex
            i = nz[0]
            c[:, a, i] = 4.0 * q[:, i] - 1.0
        else:                                                        # edge midpoint
            i, j = nz
            c[:, a, i] = 4.0 * q[:, j]
            c[:, a, j] = 4.0 * q[:, i]
    return 0.25 * np.einsum("pak,pbl->akbl", c, c)


def elasticity_p2(points, tets, element_dofs, n_dofs, E, nu, chunk: int = 20000):
    r"""Stiffness matrix of isotropic linear elasticity on affine P2 tetrahedra [N/m].

    The same matrix as scikit-fem's ``asm(linear_elasticity(lam, mu), Basis(mesh,
    ElementVector(ElementTetP2())))`` (a test checks this to 1e-12), assembled about 10x
    faster: on an affine tetrahedron ``grad N_a = sum_k c_ak(lambda) grad lambda_k``
    with constant ``grad lambda_k``, so

    .. math:: \int \partial_i N_a \partial_j N_b\,dV = V \sum_{kl} M_{akbl}\,
              (\nabla\lambda_k)_i (\nabla\lambda_l)_j

    with the element-independent M of :func:`_p2_gradient_products`, and
    ``K_(ai)(bj) = lam A_abij + mu A_abji + mu delta_ij sum_m A_abmm``
    (the weak form of sigma(u) : epsilon(v); e.g. Hughes 1987 §2.7).

    Parameters
    ----------
    points : ndarray (3, n_vertices)
        Vertex coordinates [m].
    tets : ndarray (4, n_elements)
        Positively oriented tetrahedra.
    element_dofs : ndarray (10, n_elements)
        Scalar P2 DOFs of each element (vector DOF = 3 * scalar DOF + component).
    n_dofs : int
        Number of vector DOFs.
    E : float
        Young's modulus [Pa].
    nu : float
        Poisson's ratio [-].
    """
    import scipy.sparse as sp

    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = E / (2.0 * (1.0 + nu))
    M = _p2_gradient_products().transpose(0, 2, 1, 3).reshape(100, 16)   # (ab, kl)
    comp = np.arange(3)
    itype = np.int32 if n_dofs < 2**31 - 1 else np.int64
    K = None
    for s0 in range(0, tets.shape[1], chunk):
        t = tets[:, s0:s0 + chunk]
        P = points[:, t]                                                  # (3, 4, e)
        Jm = np.stack([P[:, 1] - P[:, 0], P[:, 2] - P[:, 0], P[:, 3] - P[:, 0]], axis=-1)
        Jm = np.moveaxis(Jm, 1, 0)                                        # (e, 3, 3) columns
        inv = np.linalg.inv(Jm)                                           # rows: grad lambda_1..3
        V = np.abs(np.linalg.det(Jm)) / 6.0
        g = np.concatenate([-inv.sum(axis=1, keepdims=True), inv], axis=1)   # (e, 4, 3)
        H = np.einsum("eki,elj->eklij", g, g).reshape(-1, 16, 9)
        A = (M @ H).reshape(-1, 10, 10, 3, 3) * V[:, None, None, None, None]  # A[e,a,b,i,j]
        Ke = lam * A + mu * A.transpose(0, 1, 2, 4, 3)
        Ke += mu * np.einsum("eabmm->eab", A)[..., None, None] * np.eye(3)
        Ke = Ke.transpose(0, 1, 3, 2, 4).reshape(-1, 30, 30)             # (e, (a,i), (b,j))
        d = (3 * element_dofs[:, s0:s0 + chunk].T[:, :, None] + comp).reshape(-1, 30)
        d = d.astype(itype)
        # COO -> CSR per chunk sums the duplicate (shared-DOF) entries; summing the chunks
        # keeps the peak memory at one chunk's triplets
        Kc = sp.csr_matrix((Ke.ravel(), (np.repeat(d, 30, axis=1).ravel(),
                                         np.tile(d, (1, 30)).ravel())), shape=(n_dofs, n_dofs))
        del Ke, A, H
        K = Kc if K is None else K + Kc
    return K


def assemble_body(body: Body, grid: PressureGrid, solver: str | None = None) -> BodyState:
    """Assemble the stiffness and load matrices of a body and solve for every tent.

    Boundary conditions: ``u_x = 0`` on x = 0, ``u_y = 0`` on y = 0 (symmetry) and
    ``u_z = 0`` on ``z = z_fixed``; no rigid-body mode remains.  A body with
    ``symmetric_x=False`` (a half model) has its u_x held at one DOF instead
    (:class:`Body`).

    Parameters
    ----------
    body : Body
    grid : PressureGrid
    solver : str, optional
        Force a sparse solver (:data:`ballrace.fem.solvers.SOLVERS`).
    """
    import scipy.sparse as sp
    from skfem import Basis, ElementTetP2, ElementVector, FacetBasis

    from .solvers import chosen_solver, factorize, rigid_body_modes

    tm = {}
    t0 = time.perf_counter()
    mesh = skfem_mesh(body.points, body.tets)
    ev = ElementVector(ElementTetP2())
    basis = Basis(mesh, ev, intorder=1)        # DOF numbering only; K is assembled below
    sbasis = basis.with_element(ElementTetP2())
    K = elasticity_p2(mesh.p, mesh.t, sbasis.element_dofs, basis.N, body.E, body.nu)
    tm["assemble"] = time.perf_counter() - t0

    # candidate contact facets: boundary facets with all vertices on the contact surface,
    # restricted to the grid region (plus a margin)
    t0 = time.perf_counter()
    bf = mesh.boundary_facets()
    fv = mesh.facets[:, bf]
    cand = np.all(body.contact_nodes[fv], axis=0)
    xy = mesh.p[:2, fv]                                   # (2, 3, nf)
    cand &= (xy[0].min(axis=0) <= grid.Lx * 1.02) & (xy[1].min(axis=0) <= grid.Ly * 1.02)
    facets = bf[cand]
    if facets.size == 0:
        raise RuntimeError(f"{body.name}: no candidate contact facets found")
    fb = FacetBasis(mesh, ev, facets=facets, intorder=6)
    xq = np.asarray(fb.global_coordinates())                    # (3, nf, nq)
    wq = fb.dx * np.abs(fb.normals[2])                     # projected area weights
    r, c, w = grid.weights(xq[0], xq[1])
    nf, nq = wq.shape
    rows, cols, vals = [], [], []
    wflat = wq.ravel()
    for j in range(len(fb.basis)):
        vz = np.asarray(fb.basis[j][0])[2].ravel()             # (nf*nq,)
        dofs = np.repeat(fb.element_dofs[j], nq)           # global dof per quadrature point
        val = body.side * vz[r] * wflat[r] * w
        keep = val != 0
        rows.append(dofs[r][keep])
        cols.append(c[keep])
        vals.append(val[keep])
    F = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(basis.N, grid.n_tents)).tocsr()
    tm["load_matrix"] = time.perf_counter() - t0

    # Dirichlet DOFs
    sym_y = mesh.facets_satisfying(lambda x: x[1] == 0.0, boundaries_only=True)
    zf = body.z_fixed
    tol = 1e-9 * float(np.ptp(mesh.p))
    far = mesh.facets_satisfying(lambda x: np.abs(x[2] - zf) < tol, boundaries_only=True)
    if body.symmetric_x:
        sym_x = mesh.facets_satisfying(lambda x: x[0] == 0.0, boundaries_only=True)
        held_x = basis.get_dofs(sym_x).all(["u^1"])
    else:                   # a half model: hold the x-translation at one point
        sym_x = far
        fx = basis.get_dofs(far).all(["u^1"])
        loc = basis.doflocs[:, fx]
        held_x = fx[[int(np.argmin(np.abs(loc[0]) + np.abs(loc[1])))]] if fx.size else fx
    D = np.unique(np.concatenate([held_x,
                                  basis.get_dofs(sym_y).all(["u^2"]),
                                  basis.get_dofs(far).all(["u^3"])]))
    if sym_x.size == 0 or sym_y.size == 0 or far.size == 0:
        raise RuntimeError(f"{body.name}: a symmetry or support plane was not found in the mesh")
    free = np.setdiff1d(np.arange(basis.N), D)
    t0 = time.perf_counter()
    Kff = K[free][:, free].tocsr()
    del K
    Ff = F[free].tocsc()
    rows = np.flatnonzero(np.diff(Ff.tocsr().indptr))       # contact-surface DOFs
    nns = None
    if chosen_solver(solver) == "amg":
        nns = rigid_body_modes(sbasis.doflocs[:, free // 3].T, free % 3)
    fac, name = factorize(Kff, solver, near_nullspace=nns, rows=rows)
    del Kff
    tm["factorize"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    C = fac.inner(Ff)
    tm["solve"] = time.perf_counter() - t0
    log.info("%s: %d DOFs, %d contact facets, %d tents; %s", body.name, basis.N, facets.size,
             grid.n_tents, ", ".join(f"{k} {v:.2f} s" for k, v in tm.items()))
    return BodyState(body=body, basis=basis, scalar_basis=sbasis, F=F, C=C, free=free,
                     factor=fac, n_dofs=basis.N, solver=name, timings=tm)


def compliance(states) -> np.ndarray:
    """Compliance matrix ``C = sum_i F_i^T K_i^{-1} F_i`` (symmetrised) [m^5/N]."""
    C = sum(s.C for s in states)
    return 0.5 * (C + C.T)


# --------------------------------------------------------------------------- contact solve
@dataclass
class ContactSolution:
    """Tent pressures ``lam`` [Pa], rigid approach ``Delta`` [m], load (quarter) [N]."""

    lam: np.ndarray
    Delta: float
    load: float
    gap: np.ndarray          # weighted gap G0 + C lam - Delta m [m^3]
    complementarity: float   # |lam . gap| / (|lam| |gap|)
    seconds: float


def solve_contact(C, G0, m, *, load: float | None = None, approach: float | None = None,
                  p_ref: float = 1.0, delta_ref: float = 1.0,
                  penalty: np.ndarray | None = None) -> ContactSolution:
    """Frictionless unilateral contact for a given (quarter) load or rigid approach.

    Parameters
    ----------
    C : (n, n) ndarray
        Compliance matrix [m^5/N].
    G0, m : (n,) ndarray
        Weighted initial gaps [m^3] and tent areas [m^2].
    load : float, optional
        Load carried by the modelled sector [N].
    approach : float, optional
        Rigid approach of the far planes [m] (instead of ``load``).
    p_ref, delta_ref : float
        Pressure [Pa] and length [m] scales (Hertz p0 and delta) for conditioning.
    penalty : (n, n) ndarray, optional
        Symmetric positive semi-definite matrix added to C in the energy (a stabilisation
        of the tent pressures, see :meth:`PressureGrid.curvature_penalty`) [m^5/N].  The
        returned ``gap`` is that of C alone.
    """
    from scipy.optimize import brentq, nnls
    from scipy.linalg import cholesky, solve_triangular

    if (load is None) == (approach is None):
        raise ValueError("give exactly one of load [N] and approach [m]")
    t0 = time.perf_counter()
    A = float(np.mean(m))
    Ch = C * p_ref / (delta_ref * A)
    Gh = G0 / (delta_ref * A)
    mh = m / A
    L = cholesky(Ch if penalty is None else Ch + penalty * p_ref / (delta_ref * A), lower=True)

    def lam_of(d):
        q = Gh - d * mh
        rhs = -solve_triangular(L, q, lower=True)
        lam, _ = nnls(L.T, rhs, maxiter=50 * len(q))
        return lam

    def load_of(d):
        return float(m @ lam_of(d)) * p_ref

    if approach is not None:
        dh = approach / delta_ref
    else:
        hi = 1.5
        while load_of(hi) < load:
            hi *= 2.0
            if hi > 1e3:
                raise RuntimeError("contact solve: load not reached (check the pressure grid)")
        lo = 0.0
        dh = brentq(lambda d: load_of(d) - load, lo, hi, xtol=1e-13, rtol=1e-13)
    lam = lam_of(dh)
    gap = (Gh + Ch @ lam - dh * mh) * delta_ref * A
    lam = lam * p_ref
    nl, ng = np.linalg.norm(lam), np.linalg.norm(gap)
    comp = float(abs(lam @ gap) / (nl * ng)) if nl > 0 and ng > 0 else 0.0
    return ContactSolution(lam=lam, Delta=dh * delta_ref, load=float(m @ lam), gap=gap,
                           complementarity=comp, seconds=time.perf_counter() - t0)


# --------------------------------------------------------------------------- tangential load
def traction_response(state: BodyState, tractions, solver: str | None = None):
    r"""Displacement [m] of a body under a tangential surface traction along x.

    The traction ``traction(x, y)`` [Pa] (a force per unit *projected* area, like the
    tent pressures) acts along ``-side * x``: +x on the lower body (``side = -1``) and -x
    on the ball, equal and opposite.  It is applied on the body's candidate contact facets
    (``F_t = int q |n_z| v_x dA``), and the quarter model is solved again with the
    boundary conditions of a load that is even in x and y but points along x: the load
    is *antisymmetric* about the plane x = 0 (``u_y = u_z = 0`` there, u_x free),
    symmetric about y = 0 (``u_y = 0``), and the far plane ``z = z_fixed`` is held in x
    and z (it carries the resultant).  These are other Dirichlet DOFs than those of the
    normal problem, so the stiffness is assembled and factorised once more (the normal
    factor cannot be reused in a quarter model); the factor is released on return.

    Parameters
    ----------
    state : BodyState
        The assembled body (:func:`assemble_body`); its factor may be released.
    tractions : sequence of callable
        Each ``q(x, y)`` [Pa] on the surface, e.g. ``mu * grid.evaluate(lam, x, y)``;
        one factorisation serves them all.
    solver : str, optional
        Force a sparse solver.

    Returns
    -------
    us : list of ndarray
        Displacement on all DOFs [m] per traction (interleaved u_x, u_y, u_z per scalar
        DOF), valid for x >= 0; the field at x < 0 follows from the antisymmetry (u_x even, u_y and
        u_z odd in x; stresses sxx, syy, szz, syz odd, sxy, sxz even).
    resultants : list of float
        x-resultant of each applied load vector on the quarter model [N] (``sum f_x``;
        the equilibrium check: mu Q / 4 on the lower body for q = mu p).

    References
    ----------
    Johnson, K.L. (1985) *Contact Mechanics*, §7.1: for bodies of identical elastic
    constants a tangential traction causes no normal displacement difference, so the
    normal (Hertz) and the tangential problems uncouple and superpose.
    """
    import scipy.sparse as sp
    from skfem import ElementTetP2, ElementVector, FacetBasis

    from .solvers import factorize

    tm = state.timings
    body = state.body
    mesh, basis = state.mesh, state.basis
    t0 = time.perf_counter()
    K = elasticity_p2(mesh.p, mesh.t, state.scalar_basis.element_dofs, basis.N, body.E,
                      body.nu)
    bf = mesh.boundary_facets()
    fv = mesh.facets[:, bf]
    facets = bf[np.all(body.contact_nodes[fv], axis=0)]
    fb = FacetBasis(mesh, ElementVector(ElementTetP2()), facets=facets, intorder=6)
    xq = np.asarray(fb.global_coordinates())
    wq = fb.dx * np.abs(fb.normals[2])                             # projected area weights
    fs = []
    for traction in tractions:
        q = np.asarray(traction(xq[0], xq[1]), dtype=float) * wq
        f = np.zeros(basis.N)
        for j in range(len(fb.basis)):
            vx = np.asarray(fb.basis[j][0])[0]                     # (nf, nq)
            np.add.at(f, fb.element_dofs[j], -body.side * np.sum(vx * q, axis=1))
        fs.append(f)
    sym_x = mesh.facets_satisfying(lambda x: x[0] == 0.0, boundaries_only=True)
    sym_y = mesh.facets_satisfying(lambda x: x[1] == 0.0, boundaries_only=True)
    zf = body.z_fixed
    tol = 1e-9 * float(np.ptp(mesh.p))
    far = mesh.facets_satisfying(lambda x: np.abs(x[2] - zf) < tol, boundaries_only=True)
    D = np.unique(np.concatenate([basis.get_dofs(sym_x).all(["u^2", "u^3"]),
                                  basis.get_dofs(sym_y).all(["u^2"]),
                                  basis.get_dofs(far).all(["u^1", "u^3"])]))
    free = np.setdiff1d(np.arange(basis.N), D)
    Kff = sp.csr_matrix(K[free][:, free])
    del K
    tm["traction_assemble"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    fac, _ = factorize(Kff, solver)
    del Kff
    us = []
    try:
        for f in fs:
            u = np.zeros(basis.N)
            u[free] = fac(f[free])
            us.append(u)
    finally:
        fac.free()
    tm["traction_solve"] = time.perf_counter() - t0
    res = [float(f.reshape(-1, 3)[:, 0].sum()) for f in fs]
    log.info("%s: tangential traction, %d load(s), %.2f s", body.name, len(fs),
             tm["traction_solve"])
    return us, res
