r"""Axisymmetric reference FE model of a circular contact (ball on ball, ball on a plane).

A circular Hertz contact between two bodies of revolution about the contact normal is
axisymmetric, so a 2-D model in (r, z) resolves it far more finely than the 3-D quarter
model of :mod:`ballrace.fem.api` for the same cost: h = a/40 … a/80 at 10^4–10^5 DOFs.
Its purpose is a *reference*: with the curved bodies resolved, the departure of the real
geometry from Hertz's half-spaces (what a converged solution gives) can be told apart from
the 3-D model's discretisation error (docs/fem-axisym.md).

Model (same formulation as :mod:`ballrace.fem.model`, in 2-D):

* each body is meshed in its own "lower" orientation (contact point at the origin, body
  in z <= 0; the compliance of the upper body is the same as that of its mirror image):
  a ball of radius R is the quarter disk between the contact point and its equator plane
  z = -R (held in z), a block is the rectangle [0, L] x [-H, 0] (bottom held in z);
  the axis r = 0 has u_r = 0.  gmsh 2-D (Frontal-Delaunay, one thread), element size
  h = a/n in a box 1.3 a wide and 2 a deep under the contact, growing linearly away;
* P2 triangles, linear elasticity in axisymmetric form (Zienkiewicz & Taylor 2000,
  Vol. 1 §6.2): strains :math:`(\varepsilon_{rr}, \varepsilon_{zz}, \varepsilon_{\theta\theta},
  \gamma_{rz}) = (\partial_r u_r, \partial_z u_z, u_r/r, \partial_z u_r + \partial_r u_z)`,
  stiffness :math:`\int \sigma(u):\varepsilon(v)\,2\pi r\,dA`;
* contact pressure ``p(r) = sum_k lambda_k phi_k(r)`` with 1-D hat functions on the
  surface-mesh vertices (the contact surface is meshed with vertices exactly at
  r_j = j h, so the hats are piecewise linear on the mesh and every integral below is
  exact); load vectors ``F_k = -int phi_k v_z 2 pi r |n_z| ds`` (the pressure acts along
  the contact normal z per unit projected area, as in the 3-D model);
* compliance ``C = sum_i F_i^T K_i^{-1} F_i``, weighted gap
  ``G0_k = int phi_k g0 2 pi r dr`` with Hertz's gap ``r^2/(2 R1) + r^2/(2 R2)`` (or the
  exact sphere gap), the non-negative least-squares contact solve of
  :func:`ballrace.fem.model.solve_contact` for the full load Q.

Post-processing on the lower body: a from the pressure moment (:func:`pressure_moment_radius`),
p_max = 3Q/(2 pi a^2), the Lundberg–Palmgren orthogonal-shear profile
``max_r |tau_rz|(depth)`` (tau_rz on the meridian plane is tau_xz on the 3-D section y = 0)
and its peak (:func:`ballrace.fem.extract.peak_fit`), and on the axis the Tresca and
von Mises maxima and their depths; all against :mod:`ballrace.analytic.hertz` and
:mod:`ballrace.analytic.subsurface` for the same contact.

gmsh and scikit-fem are imported inside the functions.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field

import numpy as np

from ballrace.analytic._checks import check_choice, check_positive, check_range
from ballrace.analytic.materials import BEARING_STEEL, Material

__all__ = ["AxisymResult", "MODES", "GAPS", "pressure_moment_radius", "run_axisym",
           "ball_on_ball", "ball_on_plane"]

log = logging.getLogger(__name__)

MODES = ("two-body", "half-space")
GAPS = ("hertz", "exact")

#: Extent of the verification half-space cylinder (radius = depth), in contact radii a.
HALFSPACE_EXTENT = 40.0
#: Extent of the plane block (radius = depth), in contact radii a (the 3-D block: 8 a).
PLANE_EXTENT = 8.0
#: Pressure grid and uniform surface mesh out to this many contact radii (as the 3-D grid).
GRID_EXTENT = 1.3
#: Depth of the refinement box, in contact radii.
REFINE_DEPTH = 2.0
#: Peak fit (:func:`ballrace.fem.extract.peak_fit`): samples within this fraction of the
#: largest, polynomial degree.  On the exact profiles sampled as here (ball on ball,
#: 2000 N) the fit returns z0 to +0.010 %, tau0 to -0.002 % and the on-axis depths to
#: 1e-6 (the 3-D default, 0.9 / 4, gives z0 -0.17 %).
FIT = {"window": 0.9, "degree": 6}


def pressure_moment_radius(load, second_moment):
    r"""Contact radius from the load and the second moment of a circular pressure [m].

    For Hertz's pressure :math:`p = p_0 (1 - r^2/a^2)^{1/2}` (Johnson 1985 eq. 3.39)

    .. math::
        Q = \int_0^a p\,2\pi r\,dr = \tfrac{2}{3}\pi a^2 p_0, \qquad
        M_2 = \int_0^a p\,r^2\,2\pi r\,dr = \pi p_0 a^4 B(2, \tfrac32) = \tfrac{4}{15}\pi p_0 a^4,

    so :math:`M_2 / Q = \tfrac{2}{5} a^2` and :math:`a = (5 M_2 / (2 Q))^{1/2}` — the
    axisymmetric form of ``a_x = (5 int p x^2 dA / Q)^(1/2)`` of
    :func:`ballrace.fem.extract.pressure_moments` (``int p x^2 dA = M_2 / 2``).

    Parameters
    ----------
    load : float or array_like
        Total load Q = int p dA [N], > 0.
    second_moment : float or array_like
        M_2 = int p r^2 dA [N m^2], > 0.

    Returns
    -------
    ndarray
        a [m].

    Examples
    --------
    >>> a, p0 = 1e-3, 2e9
    >>> Q, M2 = 2 / 3 * np.pi * a**2 * p0, 4 / 15 * np.pi * p0 * a**4
    >>> float(pressure_moment_radius(Q, M2))
    0.001
    """
    Q = check_positive(load, "load", "N")
    M2 = check_positive(second_moment, "second_moment", "N m^2")
    return np.sqrt(2.5 * M2 / Q)


# --------------------------------------------------------------------------- result
@dataclass(frozen=True)
class AxisymResult:
    """Result of an axisymmetric contact model (frozen; SI units).

    Attributes
    ----------
    name : str
        What was run: "ball on ball" or "ball on plane".
    mode : str
        "two-body" or "half-space".
    gap : str
        "hertz" or "exact".
    load : normal load Q [N].
    n : elements per contact radius at the contact, h = a_Hertz / n [-].
    h : element size at the contact [m].
    a : contact radius from the pressure moment [m].
    p_max : 3 Q / (2 pi a^2) [Pa].
    approach : FE estimate of Hertz's approach: the approach of two on-axis points 3 a deep
        (one per body) plus their half-space displacements under the Hertz pressure
        (as ``FEResult.approach``) [m].
    tau0, z0 : peak of ``max_r |tau_rz|`` over depth and its depth [Pa], [m]; depth is
        measured below the undeformed surface at the same r (as in the 3-D model).
    z0_tangent_plane : the same peak's depth measured below the tangent plane at the
        contact point instead [m] (differs from z0 of a curved lower body by about
        x0^2/(2 R_2): the definition of "depth" matters at the order of a/R).
    tau_x0z0 : |tau_rz| at Lundberg–Palmgren's (x0, z0) [Pa].
    max_shear, max_shear_depth : on-axis Tresca maximum [Pa] and its depth [m].
    von_mises, von_mises_depth : on-axis von Mises maximum [Pa] and its depth [m].
    n_dofs : DOFs of all bodies modelled (identical bodies are assembled once) [-].
    n_tents : pressure unknowns [-].
    seconds : wall time [s].
    comparison : rows (quantity, fe, analytic, error, analytic_fit, error_fit): the error
        against the exact Hertz / Lundberg–Palmgren value, and against the analytic field
        sampled on the same points and put through the same peak fit (the error of the
        FE field alone).
    analytic : the Hertz contact (:class:`ballrace.analytic.hertz.HertzContact`).
    profiles : sampled curves (pressure, section profile, axis) for plots.
    """

    name: str
    mode: str
    gap: str
    load: float
    n: float
    h: float
    a: float
    p_max: float
    approach: float
    tau0: float
    z0: float
    z0_tangent_plane: float
    tau_x0z0: float
    max_shear: float
    max_shear_depth: float
    von_mises: float
    von_mises_depth: float
    n_dofs: int
    n_tents: int
    seconds: float
    comparison: tuple
    analytic: object = field(repr=False)
    profiles: dict = field(default_factory=dict, repr=False, compare=False)

    def error(self, quantity: str, against: str = "exact") -> float:
        """Relative error FE/analytic - 1 of a quantity [-].

        Parameters
        ----------
        quantity : str
            A row of :attr:`comparison` ("a", "p_max", "approach", "tau0", "tau_x0z0",
            "z0", "z0_tangent_plane", "max_shear", "max_shear_depth", "von_mises",
            "von_mises_depth").
        against : {"exact", "fit"}
            The exact analytic value, or the analytic field through the same sampling
            and peak fit.
        """
        check_choice(against, "against", ("exact", "fit"))
        names = [r["quantity"] for r in self.comparison]
        if quantity not in names:
            raise ValueError(f"quantity must be one of {', '.join(names)}; got {quantity!r}")
        row = self.comparison[names.index(quantity)]
        return row["error" if against == "exact" else "error_fit"]

    @property
    def errors(self) -> dict:
        """{quantity: relative error against the exact analytic value} [-]."""
        return {r["quantity"]: r["error"] for r in self.comparison}


# --------------------------------------------------------------------------- meshing
def _surface_nodes(n_surf: int, h: float):
    return h * np.arange(n_surf + 1)


def _gmsh_body(kind: str, size: tuple, r_nodes, fine: tuple, hc: float, hf: float,
               growth: float):
    """2-D mesh of one body in its lower orientation: points (n, 2), triangles (m, 3).

    ``kind="ball"``: quarter disk of radius ``size[0]`` centred at (0, -R); ``"block"``:
    rectangle [0, size[0]] x [-size[1], 0].  The contact surface has vertices exactly at
    ``r_nodes`` (one element per interval), the rest follows the size field
    ``min(hf, hc + growth * dist(box [0, fine[0]] x [-fine[1], 0]))``.
    """
    import gmsh

    from ballrace.meshes.contact import deterministic_options

    gmsh.initialize(interruptible=False)
    try:
        deterministic_options(gmsh)     # the 3-D meshes' deterministic settings (one thread, ...)
        gmsh.model.add(kind)
        geo = gmsh.model.geo
        if kind == "ball":
            R = float(size[0])
            zc = -R
            surf = [geo.addPoint(r, zc + math.sqrt(R * R - r * r), 0.0) for r in r_nodes]
            centre = geo.addPoint(0.0, zc, 0.0)
            eq = geo.addPoint(R, zc, 0.0)
            curves = [geo.addCircleArc(surf[i], centre, surf[i + 1])
                      for i in range(len(surf) - 1)]
            small = list(curves)
            curves.append(geo.addCircleArc(surf[-1], centre, eq))
            curves.append(geo.addLine(eq, centre))
            curves.append(geo.addLine(centre, surf[0]))
        elif kind == "block":
            L, H = float(size[0]), float(size[1])
            surf = [geo.addPoint(r, 0.0, 0.0) for r in r_nodes]
            c1 = geo.addPoint(L, 0.0, 0.0)
            c2 = geo.addPoint(L, -H, 0.0)
            c3 = geo.addPoint(0.0, -H, 0.0)
            curves = [geo.addLine(surf[i], surf[i + 1]) for i in range(len(surf) - 1)]
            small = list(curves)
            curves += [geo.addLine(surf[-1], c1), geo.addLine(c1, c2), geo.addLine(c2, c3),
                       geo.addLine(c3, surf[0])]
        else:  # pragma: no cover - internal
            raise ValueError(f"kind must be 'ball' or 'block'; got {kind!r}")
        loop = geo.addCurveLoop(curves)
        geo.addPlaneSurface([loop])
        for c in small:
            geo.mesh.setTransfiniteCurve(c, 2)
        geo.synchronize()

        def pos(e):
            return f"(({e})+Abs({e}))/2"
        d = f"Sqrt(({pos(f'x-{fine[0]!r}')})^2+({pos(f'-y-{fine[1]!r}')})^2)"
        f = gmsh.model.mesh.field.add("MathEval")
        gmsh.model.mesh.field.setString(f, "F", f"Min({hf!r}, {hc!r}+{growth!r}*{d})")
        gmsh.model.mesh.field.setAsBackgroundMesh(f)
        gmsh.model.mesh.generate(2)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        etypes, _, enodes = gmsh.model.mesh.getElements(2)
        tris = np.concatenate([en.reshape(-1, 3) for et, en in zip(etypes, enodes) if et == 2])
    finally:
        gmsh.finalize()
    pts = coords.reshape(-1, 3)[:, :2]
    order = np.argsort(tags)
    tags, pts = tags[order], pts[order]
    used = np.unique(tris)
    remap = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    pts = pts[np.searchsorted(tags, used)].copy()
    tris = remap[tris]
    pts[np.abs(pts[:, 0]) < 1e-12 * max(size), 0] = 0.0
    # counter-clockwise triangles
    a, b, c = (pts[tris[:, i]] for i in range(3))
    neg = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) < 0
    tris[neg] = tris[neg][:, [0, 2, 1]]
    return pts, tris


# --------------------------------------------------------------------------- bodies
@dataclass
class _Body:
    """One body after assembly: mesh, bases, load matrix, factor and compliance."""

    kind: str
    radius: float          # ball radius, inf for a block [m]
    E: float
    nu: float
    mesh: object
    basis: object
    sdofs: np.ndarray      # scalar P2 element DOFs (6, n_elements)
    F: object
    free: np.ndarray
    factor: object
    C: np.ndarray
    n_dofs: int
    _loc: dict = field(default_factory=dict)

    def height(self, r):
        """Surface height z(r) in the lower orientation [m]."""
        if math.isinf(self.radius):
            return 0.0 * np.asarray(r, dtype=float)
        R = self.radius
        return -(R - np.sqrt(R * R - np.asarray(r, dtype=float) ** 2))

    def displacement(self, lam) -> np.ndarray:
        u = np.zeros(self.n_dofs)
        u[self.free] = self.factor(np.asarray(self.F[self.free] @ lam).ravel())
        return u

    def locate(self, pts):
        """Element and reference coordinates of points (n, 2)."""
        if not self._loc:
            from scipy.spatial import cKDTree

            P = self.mesh.p[:, self.mesh.t]                          # (2, 3, nt)
            A = np.stack([P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]], axis=-1)
            A = np.moveaxis(A, 1, 0)                                 # (nt, 2, 2)
            self._loc.update(inv=np.linalg.inv(A), origin=P[:, 0].T.copy(),
                             tree=cKDTree(P.mean(axis=1).T))
        inv, origin, tree = self._loc["inv"], self._loc["origin"], self._loc["tree"]
        k = min(16, inv.shape[0])
        _, cand = tree.query(pts, k=k)
        X = np.einsum("nkij,nkj->nki", inv[cand], pts[:, None, :] - origin[cand])
        lmin = np.minimum(X.min(axis=2), 1.0 - X.sum(axis=2))
        j = np.argmax(lmin, axis=1)
        best = lmin[np.arange(len(pts)), j]
        if np.any(best < -1e-9):
            raise ValueError(f"{int(np.sum(best < -1e-9))} probe points lie outside the "
                             f"mesh of the {self.kind}")
        return cand[np.arange(len(pts)), j], X[np.arange(len(pts)), j]

    def evaluate(self, u, pts):
        """Displacement (n, 2) and gradient (n, 2, 2), g[:, i, j] = du_i/dx_j, at points."""
        from skfem import ElementTriP2

        pts = np.asarray(pts, dtype=float)
        tind, X = self.locate(pts)
        el = ElementTriP2()
        U = u.reshape(-1, 2)
        inv = self._loc["inv"][tind]
        val = np.zeros((len(tind), 2))
        grad = np.zeros((len(tind), 2, 2))
        for i in range(6):
            phi, dphi = el.lbasis(X.T, i)
            ui = U[self.sdofs[i, tind]]
            val += phi[:, None] * ui
            g = np.einsum("nji,jn->ni", inv, dphi)
            grad += ui[:, :, None] * g[:, None, :]
        return val, grad

    def stresses(self, u, pts):
        """(s_rr, s_zz, s_tt, s_rz) at points (n, 2) [Pa] (mesh frame, z up)."""
        pts = np.asarray(pts, dtype=float)
        val, g = self.evaluate(u, pts)
        lam = self.E * self.nu / ((1 + self.nu) * (1 - 2 * self.nu))
        mu = self.E / (2 * (1 + self.nu))
        r = pts[:, 0]
        axis = r < 1e-12 * self.n_scale
        ett = np.where(axis, g[:, 0, 0], val[:, 0] / np.where(axis, 1.0, r))
        err, ezz, grz = g[:, 0, 0], g[:, 1, 1], g[:, 0, 1] + g[:, 1, 0]
        tr = err + ezz + ett
        return np.stack([lam * tr + 2 * mu * err, lam * tr + 2 * mu * ezz,
                         lam * tr + 2 * mu * ett, mu * grz], axis=1)

    @property
    def n_scale(self) -> float:
        return float(np.ptp(self.mesh.p))


def _assemble(kind, size, r_nodes, tents, fine, hc, hf, growth, E, nu, solver):
    """Mesh, assemble and factorise one body; its compliance for the tents."""
    import scipy.sparse as sp
    from skfem import (BilinearForm, Basis, ElementTriP2, ElementVector, FacetBasis, MeshTri,
                       asm)

    from .solvers import factorize

    pts, tris = _gmsh_body(kind, size, r_nodes, fine, hc, hf, growth)
    mesh = MeshTri(np.ascontiguousarray(pts.T), np.ascontiguousarray(tris.T))
    ev = ElementVector(ElementTriP2())
    basis = Basis(mesh, ev, intorder=4)
    sdofs = basis.with_element(ElementTriP2()).element_dofs
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = E / (2.0 * (1.0 + nu))

    @BilinearForm
    def axisym_elasticity(u, v, w):
        r = w.x[0]
        gu, gv = u.grad, v.grad
        eu = (gu[0][0], gu[1][1], u[0] / r, gu[0][1] + gu[1][0])
        ev_ = (gv[0][0], gv[1][1], v[0] / r, gv[0][1] + gv[1][0])
        tr = eu[0] + eu[1] + eu[2]
        s = (lam * tr + 2 * mu * eu[0], lam * tr + 2 * mu * eu[1],
             lam * tr + 2 * mu * eu[2], mu * eu[3])
        return (s[0] * ev_[0] + s[1] * ev_[1] + s[2] * ev_[2] + s[3] * ev_[3]) * 2 * np.pi * r

    K = asm(axisym_elasticity, basis)

    # contact facets: the boundary facets between consecutive surface nodes
    scale = float(np.ptp(pts))
    rmax = float(r_nodes[-1]) * (1 + 1e-9)
    bf = mesh.boundary_facets()
    fv = mesh.p[:, mesh.facets[:, bf]]                               # (2, 2, nf)
    if kind == "ball":
        R = float(size[0])
        dist = np.hypot(fv[0], fv[1] + R)
        on = np.all(np.abs(dist - R) < 1e-9 * R, axis=0) & np.all(fv[1] > -0.5 * R, axis=0)
    else:
        on = np.all(fv[1] == 0.0, axis=0)
    on &= np.all(fv[0] <= rmax, axis=0) & (np.abs(fv[0, 0] - fv[0, 1]) > 0)
    facets = bf[on]
    if facets.size != len(r_nodes) - 1:
        raise RuntimeError(f"{kind}: {facets.size} contact facets for {len(r_nodes) - 1} "
                           "surface intervals")
    fb = FacetBasis(mesh, ev, facets=facets, intorder=6)
    xq = np.asarray(fb.global_coordinates())                         # (2, nf, nq)
    rq = xq[0].ravel()
    wq = (fb.dx * np.abs(fb.normals[1])).ravel() * 2 * np.pi * rq    # projected, 2 pi r
    dt = tents[1] - tents[0]
    u_ = rq / dt
    i = np.clip(np.floor(u_).astype(np.int64), 0, len(tents) - 2)
    fr = np.clip(u_ - i, 0.0, 1.0)
    rows, cols, vals = [], [], []
    nq = fb.dx.shape[1]
    for j in range(len(fb.basis)):
        vz = np.asarray(fb.basis[j][0])[1].ravel()
        dofs = np.repeat(fb.element_dofs[j], nq)
        for k, wk in ((i, 1.0 - fr), (i + 1, fr)):
            val = -vz * wq * wk                                     # pushed towards -z
            keep = val != 0
            rows.append(dofs[keep])
            cols.append(k[keep])
            vals.append(val[keep])
    F = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(basis.N, len(tents))).tocsr()

    axis_f = mesh.facets_satisfying(lambda x: x[0] == 0.0, boundaries_only=True)
    zfix = -float(size[0]) if kind == "ball" else -float(size[1])
    far = mesh.facets_satisfying(lambda x: np.abs(x[1] - zfix) < 1e-9 * scale,
                                 boundaries_only=True)
    if axis_f.size == 0 or far.size == 0:
        raise RuntimeError(f"{kind}: the axis or the support was not found in the mesh")
    D = np.unique(np.concatenate([basis.get_dofs(axis_f).all(["u^1"]),
                                  basis.get_dofs(far).all(["u^2"])]))
    free = np.setdiff1d(np.arange(basis.N), D)
    Kff = K[free][:, free].tocsr()
    Ff = F[free].tocsc()
    rows_ = np.flatnonzero(np.diff(Ff.tocsr().indptr))
    fac, _ = factorize(Kff, solver, rows=rows_)
    C = fac.inner(Ff)
    radius = float(size[0]) if kind == "ball" else math.inf
    return _Body(kind=kind, radius=radius, E=E, nu=nu, mesh=mesh, basis=basis, sdofs=sdofs,
                 F=F, free=free, factor=fac, C=C, n_dofs=int(basis.N))


def _tent_integrals(tents, gap, order: int = 8):
    """m_k = int phi_k 2 pi r dr [m^2], G0_k = int phi_k g0 2 pi r dr [m^3],
    M_k = int phi_k r^2 2 pi r dr [m^4] (Gauss-Legendre, ``order`` points per interval)."""
    g, w = np.polynomial.legendre.leggauss(order)
    g, w = 0.5 * (g + 1.0), 0.5 * w
    r0, r1 = tents[:-1], tents[1:]
    L = (r1 - r0)[:, None]
    r = r0[:, None] + g[None, :] * L
    ww = w[None, :] * L * 2 * np.pi * r
    g0 = gap(r)
    out = {}
    for key, f in (("m", 1.0), ("G0", g0), ("M2", r * r)):
        v = np.zeros(len(tents))
        v[:-1] += ((1 - g)[None, :] * f * ww).sum(axis=1)
        v[1:] += (g[None, :] * f * ww).sum(axis=1)
        out[key] = v
    return out


# --------------------------------------------------------------------------- driver
def run_axisym(case, n: float = 20, mode: str = "two-body", gap: str = "hertz", *,
               tent_stride: int = 1, growth: float = 0.2,
               halfspace_extent: float = HALFSPACE_EXTENT,
               plane_extent: float = PLANE_EXTENT, solver: str | None = None) -> AxisymResult:
    r"""Solve a circular contact case axisymmetrically and compare it with Hertz / LP.

    Parameters
    ----------
    case : ballrace.fem.api.ContactCase
        A ball on a ball or on a plane (:func:`ballrace.fem.api.ball_case`,
        :func:`ballrace.fem.api.plane_case`): circular contacts only.
    n : float
        Elements per Hertz contact radius at the contact, h = a / n [-], >= 4.
    mode : {"two-body", "half-space"}
        Both bodies elastic with their real shapes, or one elastic cylinder (radius and
        depth ``halfspace_extent`` a) of modulus E* (1 - nu_2^2) under a rigid indenter of
        the combined curvature, as the 3-D half-space mode.
    gap : {"hertz", "exact"}
        Hertz's quadratic gap r^2/(2 R1) + r^2/(2 R2), or the exact sphere gap
        sum R_i - (R_i^2 - r^2)^(1/2).
    tent_stride : int
        Surface elements per pressure-tent interval [-], >= 1.
    growth : float
        Element size growth per unit distance from the refinement box [-], in (0, 1].
    halfspace_extent : float
        Radius and depth of the half-space cylinder, in contact radii [-], >= 8.
    plane_extent : float
        Radius and depth of the plane block of a ball on a plane (two-body), in contact
        radii [-], >= 4.
    solver : str, optional
        Force a sparse solver (:data:`ballrace.fem.solvers.SOLVERS`).

    Returns
    -------
    AxisymResult
    """
    from ballrace.analytic import subsurface as sub

    from . import halfspace
    from .extract import peak_fit, tresca_von_mises
    from .model import solve_contact

    t_start = time.perf_counter()
    if not hasattr(case, "analytic") or not hasattr(case, "lower_kind"):
        raise TypeError(f"case must be a ballrace.fem.ContactCase; got {type(case).__name__}")
    if case.lower_kind not in ("ball", "plane"):
        raise ValueError(f"case must be a ball on a ball or on a plane (circular contact); "
                         f"got lower body {case.lower_kind!r}")
    c = case.analytic
    if not np.isclose(float(c.semi_axis_x), float(c.semi_axis_y), rtol=1e-9):
        raise ValueError("case must have a circular contact (equal radii of curvature)")
    n = float(check_range(n, "n", 4.0, None, low_inclusive=True, unit="-"))
    check_choice(mode, "mode", MODES)
    check_choice(gap, "gap", GAPS)
    if isinstance(tent_stride, bool) or not isinstance(tent_stride, (int, float, np.integer)):
        raise TypeError(f"tent_stride must be a whole number [-]; got "
                        f"{type(tent_stride).__name__}")
    if not math.isfinite(tent_stride) or int(tent_stride) != tent_stride or tent_stride < 1:
        raise ValueError(f"tent_stride must be a whole number >= 1 [-]; got {tent_stride!r}")
    tent_stride = int(tent_stride)
    growth = float(check_range(growth, "growth", 0.0, 1.0, high_inclusive=True, unit="-"))
    halfspace_extent = float(check_range(halfspace_extent, "halfspace_extent", 8.0, None,
                                         low_inclusive=True, unit="-"))
    plane_extent = float(check_range(plane_extent, "plane_extent", 4.0, None,
                                     low_inclusive=True, unit="-"))

    a_h = float(c.a)
    R1 = float(case.ball_radius)
    R2 = float(case.lower_radii[0]) if case.lower_kind == "ball" else math.inf
    h = a_h / n
    n_surf = tent_stride * int(math.ceil(GRID_EXTENT * n / tent_stride - 1e-9))
    r_nodes = _surface_nodes(n_surf, h)
    tents = r_nodes[::tent_stride]
    fine = (float(r_nodes[-1]) + 2 * h, REFINE_DEPTH * a_h)

    m1, m2 = case.material1, case.material2
    specs = []                                    # (kind, size, E, nu, h_far)
    if mode == "half-space":
        E_hs = 0.5 * float(c.E_prime) * (1.0 - m2.nu ** 2)
        L = halfspace_extent * a_h
        specs.append(("block", (L, L), E_hs, m2.nu, L / 5))
    else:
        specs.append(("ball", (R1,), m1.E, m1.nu, R1 / 4))
        if case.lower_kind == "ball":
            specs.append(("ball", (R2,), m2.E, m2.nu, R2 / 4))
        else:
            L = plane_extent * a_h
            specs.append(("block", (L, L), m2.E, m2.nu, L / 5))
    bodies, built = [], {}
    for kind, size, E, nu, hf in specs:
        key = (kind, size, E, nu)
        if key not in built:
            built[key] = _assemble(kind, size, r_nodes, tents, fine, h, hf, growth, E, nu,
                                   solver)
        bodies.append(built[key])
    lower = bodies[-1]
    C = sum(b.C for b in bodies)
    C = 0.5 * (C + C.T)

    if gap == "hertz":
        def g0(r):
            return r * r / (2 * R1) + (0.0 if math.isinf(R2) else r * r / (2 * R2))
    else:
        def g0(r):
            out = R1 - np.sqrt(R1 * R1 - r * r)
            return out if math.isinf(R2) else out + R2 - np.sqrt(R2 * R2 - r * r)
    I = _tent_integrals(tents, g0)
    sol = solve_contact(C, I["G0"], I["m"], load=float(case.load), p_ref=float(c.p_max),
                        delta_ref=float(c.approach))
    lam = sol.lam
    if lam[-1] > 1e-6 * lam.max():
        log.warning("contact reaches the edge of the pressure grid: enlarge it")
    Q = float(lam @ I["m"])
    a_fe = float(pressure_moment_radius(Q, float(lam @ I["M2"])))
    p_fe = 1.5 * Q / (math.pi * a_fe ** 2)

    us = {id(b): b.displacement(lam) for b in built.values()}
    ul = us[id(lower)]

    # depth-point approach (as fem.api): points 3 a deep on the axis of each body
    zq = 3.0 * a_h
    d_fe, w_sum = sol.Delta, 0.0
    for b in bodies:
        d_fe += float(b.evaluate(us[id(b)], np.array([[0.0, -zq]]))[0][0, 1])
        w_sum += float(halfspace.axial_displacement(zq, a_h, a_h, float(c.p_max), b.E, b.nu))

    # orthogonal-shear section: max_r |tau_rz| against depth below the surface
    nu_low = lower.nu
    rs = np.linspace(0.0, 1.6, 321) * a_h
    zs = np.linspace(0.02, 1.6, 317) * a_h
    Rg, Zg = np.meshgrid(rs, zs, indexing="ij")
    pts = np.stack([Rg.ravel(), (lower.height(Rg) - Zg).ravel()], axis=1)
    S = lower.stresses(ul, pts)
    tau = S[:, 3].reshape(Rg.shape)
    prof = np.max(np.abs(tau), axis=0)
    z0_fe, tau0_fe = peak_fit(zs, prof, **FIT)
    if math.isinf(lower.radius):
        z0_tp = z0_fe
    else:                                      # depth below the tangent plane z = 0
        inside = (-Zg < lower.height(Rg)).ravel()          # points below the surface
        tp = np.zeros(Rg.size)
        tp[inside] = lower.stresses(ul, np.stack([Rg.ravel(), -Zg.ravel()], axis=1)[inside])[:, 3]
        z0_tp = peak_fit(zs, np.max(np.abs(tp.reshape(Rg.shape)), axis=0), **FIT)[0]
    s_an = sub.stress(c, Rg, 0.0 * Rg, Zg, nu=nu_low)
    prof_an = np.max(np.abs(np.asarray(s_an.tau_xz, dtype=float)), axis=0)
    z0_fit, tau0_fit = peak_fit(zs, prof_an, **FIT)
    osh = sub.orthogonal_shear(c)
    x0, z0 = float(osh.x0), float(osh.z0)
    tau_at = abs(float(lower.stresses(ul, np.array([[x0, float(lower.height(x0)) - z0]]))[0, 3]))

    # axis: Tresca and von Mises (s_rr = s_tt, tau_rz = 0 on the axis)
    za = np.linspace(0.02, 2.5, 497) * a_h
    Sa = lower.stresses(ul, np.stack([np.zeros_like(za), -za], axis=1))
    zero = np.zeros(za.size)            # (rr, zz, tt, rz) as (xx, yy, zz, xy, xz, yz)
    tr_a, vm_a = tresca_von_mises(np.stack([Sa[:, 0], Sa[:, 2], Sa[:, 1], zero, Sa[:, 3],
                                            zero], axis=1))
    ms_d, ms = peak_fit(za, tr_a, **FIT)
    vm_d, vmx = peak_fit(za, vm_a, **FIT)
    ax_an = sub.axis_stress(c, za, nu=nu_low)
    ms_fit = peak_fit(za, np.asarray(ax_an.tresca, dtype=float), **FIT)
    vm_fit = peak_fit(za, np.asarray(ax_an.von_mises, dtype=float), **FIT)
    msa = sub.max_shear(c, nu=nu_low)
    vma = sub.von_mises(c, nu=nu_low)

    rows = []

    def row(q, unit, fe, an, fit=None):
        fit = an if fit is None else fit
        rows.append({"quantity": q, "unit": unit, "fe": float(fe), "analytic": float(an),
                     "error": float(fe / an - 1.0), "analytic_fit": float(fit),
                     "error_fit": float(fe / fit - 1.0)})

    row("a", "m", a_fe, a_h)
    row("p_max", "Pa", p_fe, float(c.p_max))
    row("approach", "m", d_fe + w_sum, float(c.approach))
    row("tau0", "Pa", tau0_fe, float(osh.tau0), tau0_fit)
    row("tau_x0z0", "Pa", tau_at, float(osh.tau0))
    row("z0", "m", z0_fe, z0, z0_fit)
    row("z0_tangent_plane", "m", z0_tp, z0, z0_fit)
    row("max_shear", "Pa", ms, float(msa.tau_max), ms_fit[1])
    row("max_shear_depth", "m", ms_d, float(msa.depth), ms_fit[0])
    row("von_mises", "Pa", vmx, float(vma.sigma_vm), vm_fit[1])
    row("von_mises_depth", "m", vm_d, float(vma.depth), vm_fit[0])

    n_dofs = sum(b.n_dofs for b in built.values())
    for b in built.values():
        b.factor.free()
    seconds = time.perf_counter() - t_start
    profiles = {"tents": tents, "pressure": lam, "section_z": zs, "section_tau": prof,
                "section_tau_analytic": prof_an, "axis_z": za, "axis_tresca": tr_a,
                "axis_von_mises": vm_a, "complementarity": sol.complementarity}
    log.info("axisymmetric %s (%s, %s gap, n = %g): %d DOFs, %d tents in %.1f s",
             case.name, mode, gap, n, n_dofs, len(tents), seconds)
    return AxisymResult(name=case.name, mode=mode, gap=gap, load=float(case.load), n=n, h=h,
                        a=a_fe, p_max=p_fe, approach=d_fe + w_sum, tau0=tau0_fe, z0=z0_fe,
                        z0_tangent_plane=z0_tp,
                        tau_x0z0=tau_at, max_shear=ms, max_shear_depth=ms_d, von_mises=vmx,
                        von_mises_depth=vm_d, n_dofs=n_dofs, n_tents=len(tents),
                        seconds=seconds, comparison=tuple(rows), analytic=c,
                        profiles=profiles)


def ball_on_ball(ball_diameter: float, load: float, n: float = 20, mode: str = "two-body",
                 material: Material = BEARING_STEEL, other_diameter: float | None = None,
                 other_material: Material | None = None, **kwargs) -> AxisymResult:
    """Two balls pressed together, axisymmetric reference (:func:`run_axisym`).

    Parameters
    ----------
    ball_diameter : float
        Diameter D of the upper ball [m], > 0.
    load : float
        Normal load Q [N], > 0.
    n : float
        Elements per contact radius, h = a / n [-].
    mode : {"two-body", "half-space"}
    material : Material
        Upper ball material.
    other_diameter : float, optional
        Diameter of the lower ball [m] (default D).
    other_material : Material, optional
        Lower ball material (default ``material``).
    **kwargs
        Passed to :func:`run_axisym` (``gap``, ``tent_stride``, ``growth``, ...).
    """
    from .api import ball_case

    return run_axisym(ball_case(ball_diameter, load, material, other_diameter, other_material),
                      n=n, mode=mode, **kwargs)


def ball_on_plane(ball_diameter: float, load: float, n: float = 20, mode: str = "two-body",
                  material: Material = BEARING_STEEL, plane_material: Material | None = None,
                  **kwargs) -> AxisymResult:
    """A ball on a flat block (radius and depth ``plane_extent`` a), axisymmetric reference.

    Parameters
    ----------
    ball_diameter : float
        Ball diameter D [m], > 0.
    load : float
        Normal load Q [N], > 0.
    n : float
        Elements per contact radius, h = a / n [-].
    mode : {"two-body", "half-space"}
    material, plane_material : Material
        Ball and plane materials (the plane defaults to the ball's).
    **kwargs
        Passed to :func:`run_axisym`.
    """
    from .api import plane_case

    return run_axisym(plane_case(ball_diameter, load, material, plane_material), n=n,
                      mode=mode, **kwargs)
