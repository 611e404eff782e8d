r"""Static load distribution of a single-row roller bearing: rigid rings, sliced rollers.

Frame and signs are those of :mod:`ballrace.analytic.loaddist`: the outer ring is fixed;
the inner ring moves by ``u = (dx, dy, dz, theta_y, theta_z)`` (axial, two radial
translations [m], two tilts [rad]); roller j sits at azimuth psi_j from +y towards +z;
loads (Fa, Fy, Fz, My, Mz) act on the inner ring, moments right-handed about the bearing
centre.

Model (ISO/TS 16281:2008 lamina model; Harris & Kotzalas, *Advanced Concepts of Bearing
Technology*, 2007, ch. 1; Sjövall 1933 for the load-zone integrals).  The raceway normal
at roller j (outer raceway, contact angle alpha: 0 for cylindrical, the cup angle for
tapered bearings) is ``n_j = (sin a, cos a cos psi_j, cos a sin psi_j)``; slice k lies
``s_k`` from the roller's middle along the raceway generatrix.  The inner ring's rigid
motion moves the slice towards the outer raceway by ``g_jk . u`` with

.. math::
    g_{jk} = (\sin\alpha,\ \cos\alpha\cos\psi_j,\ \cos\alpha\sin\psi_j,\
              m_k\sin\psi_j,\ -m_k\cos\psi_j), \qquad m_k = \tfrac{d_m}{2}\sin\alpha - s_k

(``m_k`` is the moment arm: the normal line through the contact passes through the roller
centre, at radius d_m/2 in the bearing's mid-plane), and the slice approach and load are

.. math::
    \delta_{jk} = g_{jk}\cdot u - \tfrac{P_d}{2}\cos\alpha - 2P(s_k), \qquad
    q_{jk} = \frac{c_L}{n_s}\langle\delta_{jk}\rangle^{10/9}

(:mod:`~ballrace.analytic.roller.lamina`).  The inner ring is in equilibrium when

.. math:: \sum_{j,k} q_{jk}\, g_{jk} = (F_a, F_y, F_z, M_y, M_z)

and the tangent stiffness is exactly
``K = sum (10/9) (c_L/n_s) <delta_jk>^(1/9) g_jk g_jk^T`` (symmetric: the slice forces
derive from the potential ``sum (9/19)(c_L/n_s) <delta>^(19/9)``, convex in u, whose
minimum the solver seeks).

The roller between two raceways with equal crowns and equal lamina stiffness is in its
own equilibrium with equal slice loads at both contacts: it takes half the raceways'
relative tilt, and each contact sees half the approach (hence c_L of the two contacts in
series).  For a tapered roller the cone contact carries Q_i and the rib Q_f, both fixed
multiples of the cup load Q_o (:class:`~ballrace.analytic.roller.RollerBearing`); the
compliance of the cone contact is taken equal to the cup's (the lamina constant is for
the pair), and of the rib contact neglected.

What is not modelled: the locating flanges of cylindrical bearings (an axial load is
refused; the axial DOF carries nothing and is held at 0 or its imposed value); roller
skew; centrifugal and gyroscopic roller loads; ring deformation; more than one row.

Solution: damped Newton on the free DOFs with the analytic tangent, vectorised over
rollers and slices, on the package's Newton policy (:mod:`~ballrace.analytic.newton`): its
Levenberg shift for directions not yet loaded (clearance), its trust radius (a fraction
``roller_step`` of D_we) and Armijo line search on the potential (:func:`_step`), its
round-off floor, best iterate at the iteration limit and ConvergenceError.  What is
returned balances the applied loads to ``newton.roundoff_cap(rtol) = max(1e-9, 100 rtol)``
relative (checked before returning).
"""
from __future__ import annotations

import functools
import logging
import math
from dataclasses import dataclass

import numpy as np

from ...errors import ConvergenceError
from .. import newton
from .._checks import as_array, check_integer, check_range
from ..newton import POLICY
from . import lamina
from .bearing import RollerBearing
from .profile import Profile

__all__ = ["RollerLoadDistribution", "RollerRow", "ConvergenceError", "solve", "DOF",
           "MAX_APPROACH_RATIO"]

log = logging.getLogger(__name__)

DOF = ("x", "y", "z", "theta_y", "theta_z")

#: Load-deflection range of the model: a slice approach up to this fraction of D_we
#: (about three times the approach at the static capacity, some 0.007 D_we).
MAX_APPROACH_RATIO = 0.02

_N = lamina.LINE_EXPONENT                     # 10/9


# =========================================================================== model
@dataclass(frozen=True)
class _Model:
    """What the solver needs of one bearing at one azimuth offset and clearance."""

    G: np.ndarray          # (Z n_s, 5) slice directions g_jk
    Gs: np.ndarray         # G / sc (scaled DOFs)
    b: np.ndarray          # (Z n_s,) approach at u = 0 [m]
    c: float               # c_L / n_s [N/m^(10/9)]
    Z: int
    n_s: int
    sc: np.ndarray         # (5,) DOF scales (1, 1, 1, d_m/2, d_m/2)
    D: float
    psi: np.ndarray        # (Z,)

    @staticmethod
    def of(bearing: RollerBearing, azimuth_offset: float, clearance: float) -> "_Model":
        return _model(bearing, float(azimuth_offset), float(clearance))


@functools.lru_cache(maxsize=32)
def _model(bearing, azimuth_offset, clearance):
    a = bearing.contact_angle
    sa, ca = math.sin(a), math.cos(a)
    psi = bearing.azimuths(azimuth_offset)
    cp, sp = np.cos(psi), np.sin(psi)
    s = bearing.slice_positions
    m = 0.5 * bearing.pitch_diameter * sa - s                    # (n_s,) moment arms
    Z, n_s = bearing.n_rollers, bearing.n_slices
    G = np.empty((Z, n_s, 5))
    G[..., 0] = sa
    G[..., 1] = (ca * cp)[:, None]
    G[..., 2] = (ca * sp)[:, None]
    G[..., 3] = sp[:, None] * m[None, :]
    G[..., 4] = -cp[:, None] * m[None, :]
    b = np.broadcast_to(-0.5 * clearance * ca - 2.0 * bearing.slice_drops, (Z, n_s))
    R = 0.5 * bearing.pitch_diameter
    G = np.ascontiguousarray(G.reshape(-1, 5))
    sc = np.array([1.0, 1.0, 1.0, R, R])
    model = _Model(G=G, Gs=G / sc, b=np.ascontiguousarray(b).ravel(),
                   c=bearing.lamina_stiffness / n_s, Z=Z, n_s=n_s,
                   sc=sc, D=bearing.roller_diameter, psi=psi)
    for v in (model.G, model.Gs, model.b, model.sc, model.psi):
        v.setflags(write=False)
    return model


# =========================================================================== Newton
class _Case:
    """One load case in scaled coordinates v = u * sc on its free DOFs (the imposed ones
    folded into the constant part of the approach)."""

    def __init__(self, model: _Model, F_app, u0, free):
        self.model = model
        self.idx = np.flatnonzero(free)
        Gs = model.Gs
        self.Gf = Gs if self.idx.size == 5 else np.ascontiguousarray(Gs[:, self.idx])
        fixed = np.flatnonzero(~free)
        self.b = model.b + Gs[:, fixed] @ (u0[fixed] * model.sc[fixed]) if fixed.size \
            else model.b
        self.F = (F_app / model.sc)[self.idx]
        self.c = model.c

    def state(self, v):
        """The state at the free values v: (approaches, loaded slices, their
        delta^(1/9), their loads, their rows of Gf, residual, potential).

        Powers are taken on the loaded slices only.  The potential
        sum (9/19) c <delta>^(19/9) - F . v is convex in v; its gradient is the residual."""
        d = self.Gf @ v + self.b
        on = np.flatnonzero(d > 0.0)
        if on.size == d.size:                        # every slice loaded (thrust)
            dp, Ga = d, self.Gf
        else:
            dp, Ga = d[on], self.Gf[on]
        r = dp ** (1.0 / 9.0)
        q = self.c * dp * r
        phi = (9.0 / 19.0) * float(q @ dp) - float(self.F @ v)
        return d, on, r, q, Ga, q @ Ga - self.F, phi

    def tangent(self, r, Ga):
        return (Ga.T * (_N * self.c * r)) @ Ga


def _step(case: _Case, v, st, err, scale):
    """One damped Newton step on the free DOFs (scaled): the new values and their state.

    The step control is the package's Newton policy (:mod:`~ballrace.analytic.newton`):
    the Newton direction of the tangent with its Levenberg shift (the geometric term
    ``levenberg_geometric`` times the load scale over D_we, for directions not yet in
    contact), the trust radius ``roller_step`` D_we and, away from the solution (relative
    residual above ``quadratic_region``), an Armijo backtracking line search on the convex
    potential.  What is this model's own is the start across a clearance: before any slice
    is in contact, the tangent is that of every slice at the approach a uniformly loaded
    roller set would have, halved (about half the rollers carry a radial load), and the
    step is lengthened by the distance to the first contact along it (a start of the right
    size across a clearance), limited only by the model's domain, D_we (beyond it
    :func:`_newton` gives up).
    """
    d, on, r, _, Ga, R, phi0 = st
    n = v.size
    first = not on.size
    if first:                                         # nothing in contact yet
        Qm = scale / case.model.Z
        Ga = case.Gf
        r = np.full(d.size, 0.5 * (Qm / (case.c * case.model.n_s)) ** 0.1)
    A = case.tangent(r, Ga)
    A.flat[:: n + 1] += newton.levenberg_shift_one(float(np.trace(A)), n, scale,
                                                   POLICY.levenberg_geometric / case.model.D)
    dv = -np.linalg.solve(A, R)
    if first:                                         # first close the gap along dv
        s = case.Gf @ dv
        pos = s > 0
        if pos.any():
            dv *= 1.0 + float(np.min(-d[pos] / s[pos]))
    f = newton.clip_factor(float(np.abs(dv).max()),
                           case.model.D if first else POLICY.roller_step * case.model.D)
    if f != 1.0:
        dv *= f
    new = case.state(v + dv)
    if err < POLICY.quadratic_region:                 # quadratic convergence: full steps
        return v + dv, new
    slope = float(R @ dv)
    if newton.armijo_ok(new[6], phi0, 1.0, slope):    # Armijo on the potential: full step
        return v + dv, new

    def armijo(t):                                    # backtracking from t = 1/2
        nonlocal new
        new = case.state(v + t * dv)
        return newton.armijo_ok(new[6], phi0, t, slope)

    t, _ = newton.backtrack_one(armijo, POLICY.potential_halvings - 1, 0.5)
    return v + t * dv, new


def _newton(model, F_app, u0, free, rtol, max_iter):
    """Equilibrium of one load case: (u, iterations, (approaches, loaded slices, their
    delta^(1/9), their loads)).

    Converged at ``rtol``, or at the policy's round-off floor when a step makes no
    progress; at ``max_iter`` the best iterate is taken if it is within the policy's
    round-off cap (:func:`~ballrace.analytic.newton.roundoff_cap`), else ConvergenceError.
    """
    case = _Case(model, F_app, u0, free)
    sc = model.sc
    v = (u0 * sc)[case.idx]
    load_scale = float(np.abs(F_app / sc).max())
    best = (math.inf, v.copy(), None)
    prev = math.inf
    n_s = model.n_s
    st = case.state(v)
    for it in range(max_iter + 1):
        d, on, q, R = st[0], st[1], st[3], st[5]
        Qmax = float(np.bincount(on // n_s, weights=q, minlength=1).max()) if on.size else 0.0
        scale = max(load_scale, Qmax, 1e-300)
        err = float(np.abs(R).max(initial=0.0)) / scale
        if err < best[0]:
            best = (err, v.copy(), st)
        if err <= rtol or (newton.stalled(err, prev) and err <= newton.roundoff_floor(
                rtol, float(d.max()), float(np.abs(v).max(initial=0.0)))):
            return _full(u0, case.idx, v, sc), it, st[:4]   # converged, or at round-off level
        if it == max_iter:
            break
        if float(np.abs(v).max(initial=0.0)) > model.D:
            raise ValueError(
                f"the loads {F_app.tolist()} [N, N m] have no equilibrium in the bearing: "
                f"the inner ring moves beyond D_we = {model.D:g} m (a single tapered bearing "
                "needs an axial load and cannot carry a moment by itself: impose the tilt "
                "(displacements) or give the moment of the load's point of application)")
        prev = err
        v, st = _step(case, v, st, err, scale if Qmax > 0 else load_scale)
    err_best, vb, stb = best
    if err_best <= newton.roundoff_cap(rtol):          # round-off level: the best iterate
        return _full(u0, case.idx, vb, sc), max_iter, stb[:4]
    if float(np.abs(vb).max(initial=0.0)) > 0.05 * model.D:
        raise ValueError(
            f"the loads {F_app.tolist()} [N, N m] have no equilibrium within the bearing's "
            f"load-deflection range: after {max_iter} iterations the inner ring has moved "
            f"{float(np.abs(vb).max()):.3g} m (more than 0.05 D_we); a single tapered bearing "
            "needs an axial load and carries little moment by itself: impose the tilt "
            "(displacements) or give the moment of the load's point of application")
    raise newton.convergence_error(
        "roller load distribution", max_iter, err, rtol, best=err_best,
        measure="relative equilibrium residual",
        context=f"with loads {F_app.tolist()}, displacements "
                f"{_full(u0, case.idx, v, sc).tolist()}",
        roundoff=newton.roundoff_limit(float(np.abs(v).max(initial=0.0)),
                                       float(st[0].max())),
        roundoff_hint="the largest slice approach is tiny against the ring displacement")


def _full(u0, idx, v, sc):
    u = u0.copy()
    u[idx] = v / sc[idx]
    return u


# =========================================================================== result
@dataclass(frozen=True)
class RollerLoadDistribution:
    """Static load distribution of a roller bearing (frozen; leading axes = load cases).

    Attributes
    ----------
    bearing : RollerBearing
        The bearing.
    azimuths : ndarray, shape (Z,)
        Roller azimuths psi_j from +y towards +z [rad].
    displacements : ndarray, shape (..., 5)
        Inner-ring displacement (dx, dy, dz [m], theta_y, theta_z [rad]).
    loads : ndarray, shape (..., 5)
        Resultant of the roller forces on the inner ring (Fa, Fy, Fz [N], My, Mz [N m]):
        the applied loads on free DOFs, the reactions on imposed ones.
    applied : ndarray, shape (..., 5)
        Applied loads (zero on imposed DOFs) [N, N m].
    imposed : ndarray of bool, shape (..., 5)
        DOFs whose displacement was imposed (a cylindrical bearing's axial DOF always).
    roller_loads : ndarray, shape (..., Z)
        Outer-raceway (cup) normal load Q_j of each roller, the sum of its slice loads [N].
    slice_loads : ndarray, shape (..., Z, n_slices)
        Slice loads q_jk [N].
    approaches : ndarray, shape (..., Z, n_slices)
        Slice approaches delta_jk [m] (negative: a gap).
    raceway_tilts : ndarray, shape (..., Z)
        Relative tilt of the inner to the outer raceway in the plane of roller j,
        theta_z cos psi_j - theta_y sin psi_j [rad] (the approach grows with it along +x).
    stiffness : ndarray, shape (..., 5, 5)
        Tangent stiffness d(loads)/d(displacements) [N/m, N/rad, N m/m, N m/rad], exact
        (a cylindrical bearing's axial row and column are 0).
    clearance : float
        Diametral clearance used [m].
    iterations : int
        Newton iterations (largest over the load cases).
    """

    bearing: RollerBearing
    azimuths: np.ndarray
    displacements: np.ndarray
    loads: np.ndarray
    applied: np.ndarray
    imposed: np.ndarray
    roller_loads: np.ndarray
    slice_loads: np.ndarray
    approaches: np.ndarray
    raceway_tilts: np.ndarray
    stiffness: np.ndarray
    clearance: float
    iterations: int = 0

    @property
    def max_roller_load(self):
        """Largest roller load Q_max [N]."""
        return _scalar(np.max(self.roller_loads, axis=-1))

    @property
    def residual(self):
        """loads - applied on free DOFs (0 on imposed ones) [N, N m]."""
        return np.where(self.imposed, 0.0, self.loads - self.applied)

    @property
    def relative_residual(self):
        """max |residual| (moments / (d_m/2)) over max(|applied|, Q_max) [-]."""
        sc = np.array([1.0, 1.0, 1.0, 1.0, 1.0])
        sc[3:] = 0.5 * self.bearing.pitch_diameter
        r = np.abs(self.residual / sc).max(-1)
        scale = np.maximum(np.abs(self.applied / sc).max(-1), self.max_roller_load)
        return _scalar(np.where(scale > 0, r / np.where(scale > 0, scale, 1.0), r))

    @property
    def axial_deflection(self):
        """Axial inner-ring displacement dx [m]."""
        return _scalar(self.displacements[..., 0])

    @property
    def radial_deflection(self):
        """Radial inner-ring displacement sqrt(dy^2 + dz^2) [m]."""
        return _scalar(np.hypot(self.displacements[..., 1], self.displacements[..., 2]))

    @property
    def misalignment(self):
        """Tilt of the inner ring sqrt(theta_y^2 + theta_z^2) [rad]."""
        return _scalar(np.hypot(self.displacements[..., 3], self.displacements[..., 4]))

    @property
    def roller_tilts(self):
        """Tilt of each roller relative to the outer raceway, half the raceway tilt [rad]
        (equal slice loads at both contacts; module notes), shape (..., Z)."""
        return 0.5 * self.raceway_tilts

    @property
    def edge_loaded(self):
        """Per roller: True where an end slice (either end) is loaded, shape (..., Z): the
        contact reaches the roller end, where a real contact has an edge stress the
        lamina model does not resolve."""
        q = self.slice_loads
        return (q[..., 0] > 0) | (q[..., -1] > 0)

    @property
    def edge_load_ratio(self):
        """Per roller: load of the more loaded end slice over the roller's mean slice load
        Q_j / n_s [-] (1 for a straight roller without tilt; 0 for unloaded rollers and
        unloaded ends), shape (..., Z)."""
        q = self.slice_loads
        end = np.maximum(q[..., 0], q[..., -1])
        Q = self.roller_loads
        mean = Q / q.shape[-1]
        return np.where(Q > 0, end / np.where(Q > 0, mean, 1.0), 0.0)

    @property
    def inner_loads(self):
        """Inner-raceway (cone) normal load of each roller, Q_i = Q_o sin(a_o + a_f) /
        sin(a_i + a_f) (tapered; = roller_loads for cylindrical) [N]."""
        return self.roller_loads * self.bearing.inner_load_ratio

    @property
    def rib_loads(self):
        """Rib (flange) load of each roller, Q_f = Q_o sin(a_o - a_i) / sin(a_i + a_f)
        (tapered; 0 for cylindrical: flanges not modelled) [N]."""
        return self.roller_loads * self.bearing.rib_load_ratio

    @property
    def slice_loads_inner(self):
        """Slice loads at the inner raceway (cone), q_jk Q_i/Q_o [N], shape (..., Z, n_s)
        (= :attr:`slice_loads` for a cylindrical bearing and for a tapered one with the
        default rib angle, where Q_i = Q_o).  The ISO/TS 16281 life uses them for the
        inner raceway."""
        return self.slice_loads * self.bearing.inner_load_ratio

    # ------------------------------------------------------------ pressures and safety
    def slice_pressures(self, raceway: str = "inner"):
        r"""Contact pressure of every slice of the lamina model at one raceway [Pa].

        Each slice is taken as a 2-D Hertz line contact of its load per length
        q_jk / w (w = L_we / n_s) on the reduced radius of the raceway contact, R_i or
        R_o (:attr:`RollerBearing.inner_radius`, :attr:`RollerBearing.outer_radius`):

        .. math:: p_{jk} = \sqrt{\frac{q_{jk}\,E'}{2\pi R\,w}}

        (Johnson, *Contact Mechanics*, 1985, eq. 4.45 with E' = 2E*), the inner raceway
        with the cone load q_jk Q_i/Q_o.  The slices are independent here: the pressure
        peak at a roller end that the elastic half-space couples in is missing (see
        :meth:`roller_contact`, which solves the finite line contact of a roller).

        Parameters
        ----------
        raceway : {"inner", "outer"}
            The contact.

        Returns
        -------
        ndarray
            Shape (..., Z, n_s) [Pa].
        """
        from .._checks import check_choice

        check_choice(raceway, "raceway", ("inner", "outer"))
        b = self.bearing
        q = self.slice_loads_inner if raceway == "inner" else self.slice_loads
        R = b.inner_radius if raceway == "inner" else b.outer_radius
        return np.sqrt(q / b.slice_width * b.E_prime / (2.0 * math.pi * R))

    @property
    def max_pressure(self):
        """Largest slice pressure of the lamina model over both raceways [Pa] (per load
        case; :meth:`slice_pressures`)."""
        p = np.maximum(self.slice_pressures("inner").max(axis=(-2, -1)),
                       self.slice_pressures("outer").max(axis=(-2, -1)))
        return _scalar(p)

    @property
    def static_safety(self):
        r"""Static safety of the most loaded slice, s0 = (4000 MPa / p_max)^2 [-] (per case).

        ISO 76:2006 bases C_0r of roller bearings on 4000 MPa at the most heavily loaded
        contact; in a line contact the load grows as p^2, so s0 = (4000 MPa / p_max)^2
        (:func:`~ballrace.analytic.ratings.static_safety_from_pressure`, ``kind="roller"``)
        from :attr:`max_pressure`, the lamina pressure of the most loaded slice (clearance,
        tilt and profile included).  ``inf`` without load.  :func:`solve` warns when it is
        below 1.  The lamina pressure has no edge peak: a straight or edge-loaded roller
        has a higher pressure at its end on the half-space (:meth:`roller_contact`).
        """
        from ..ratings import static_safety_from_pressure

        return _scalar(static_safety_from_pressure(self.max_pressure, kind="roller"))

    # ------------------------------------------------------------ finite line contact
    def roller_contact(self, j: int, raceway: str = "inner", *, n_slices=None):
        """The finite line contact of roller ``j`` on the elastic half-space, at its load
        and tilt in this solution (:func:`~ballrace.analytic.roller.contact.line_contact`).

        The lamina model's slices are independent springs; here the slices of one roller
        are coupled through the half-space, which shows the pressure peaks at the roller
        ends that the lamina model cannot.  The contact is solved with

        * the roller's load at that raceway: :attr:`inner_loads` (cone) or
          :attr:`roller_loads` (cup) [N];
        * the roller's tilt against each raceway, :attr:`roller_tilts` (half the raceway
          tilt; positive: the end at +x goes in, the frame of both models);
        * R1 = D_we/2 and the raceway radius :attr:`RollerBearing.inner_raceway_radius` or
          :attr:`RollerBearing.outer_raceway_radius` (reduced radius R_i or R_o);
        * the bearing's profile exactly as the lamina model sees it (a logarithmic profile
          given by name keeps the bearing's design load), seen once;
        * ``n_slices`` slices, by default the bearing's, so that ``x`` are the lamina
          slice centres and :meth:`slice_pressures` compare slice by slice.

        The line contact is solved alone: its approach and load distribution along the
        roller do not feed back into the bearing's equilibrium.

        Parameters
        ----------
        j : int
            Roller index [-], 0 ... Z-1 (roller 0 at the azimuth offset from +y).
        raceway : {"inner", "outer"}
            The contact.
        n_slices : int, optional
            Slices of the line contact [-], odd, >= 5; default the bearing's.

        Returns
        -------
        LineContactResult

        Raises
        ------
        ValueError
            For a result of several load cases (index the load case first by solving it
            alone), a bad roller index or raceway.
        """
        from .._checks import check_choice
        from .contact import line_contact

        check_choice(raceway, "raceway", ("inner", "outer"))
        if self.roller_loads.ndim != 1:
            raise ValueError(f"roller_contact needs a result of one load case; this one has "
                             f"load cases of shape {self.roller_loads.shape[:-1]} (solve the "
                             "case alone)")
        Z = self.bearing.n_rollers
        if isinstance(j, bool) or not isinstance(j, (int, np.integer)) or not -Z <= j < Z:
            raise ValueError(f"j must be a roller index in [0, {Z - 1}]; got {j!r}")
        b = self.bearing
        Q = float((self.inner_loads if raceway == "inner" else self.roller_loads)[j])
        R2 = b.inner_raceway_radius if raceway == "inner" else b.outer_raceway_radius
        n = b.n_slices if n_slices is None else n_slices
        return line_contact(Q, 0.5 * b.roller_diameter, R2, b.roller_length, b.material,
                            b.material, profile=_bound_profile(b),
                            tilt=math.atan(float(self.roller_tilts[j])), n_slices=n)

    def roller_contacts(self, raceway: str = "inner", *, n_slices=None) -> dict:
        """:meth:`roller_contact` of every loaded roller: ``{j: LineContactResult}`` in
        roller order [-].

        Parameters
        ----------
        raceway : {"inner", "outer"}
            The contact.
        n_slices : int, optional
            Slices of the line contacts [-]; default the bearing's.
        """
        if self.roller_loads.ndim != 1:
            raise ValueError(f"roller_contacts needs a result of one load case; this one has "
                             f"load cases of shape {self.roller_loads.shape[:-1]}")
        return {int(j): self.roller_contact(int(j), raceway, n_slices=n_slices)
                for j in np.flatnonzero(self.roller_loads > 0)}

    def most_loaded_roller(self, raceway: str = "inner") -> int:
        """Index of the roller with the largest load at ``raceway`` [-] (one load case).

        Parameters
        ----------
        raceway : {"inner", "outer"}
            The contact: :attr:`inner_loads` (cone) or :attr:`roller_loads` (cup).
        """
        from .._checks import check_choice

        check_choice(raceway, "raceway", ("inner", "outer"))
        if self.roller_loads.ndim != 1:
            raise ValueError(f"most_loaded_roller needs a result of one load case; this one "
                             f"has load cases of shape {self.roller_loads.shape[:-1]}")
        return int(np.argmax(self.inner_loads if raceway == "inner" else self.roller_loads))

    def subsurface(self, raceway: str = "inner", *, roller=None, n_slices=None,
                   n_depth: int = 24):
        """Stresses below the most loaded roller's contact with ``raceway`` (one load case).

        The roller's finite line contact on the half-space (:meth:`roller_contact`: its
        load, tilt and profile in this solution) and the von Mises and Tresca stresses
        below it (:func:`~ballrace.analytic.roller.contact.subsurface_stress`, Poisson's
        ratio of the bearing's material): the maxima over depth at every slice centre,
        their depths, and so the stress under an edge peak beside the stress in the
        middle.  In the middle of a uniformly loaded roller the maxima are those of 2-D
        Hertz (McEwen): von Mises 0.557 p0 at 0.70 b, Tresca 0.300 p0 at 0.79 b for
        nu = 0.3 (Johnson, *Contact Mechanics*, 1985, §4.2); checked in the tests.

        Parameters
        ----------
        raceway : {"inner", "outer"}
            The contact.
        roller : int, optional
            Roller index [-]; default :meth:`most_loaded_roller`.
        n_slices : int, optional
            Slices of the line contact [-], odd, >= 5; default the bearing's.
        n_depth : int, optional
            Depths of the stress grid [-] (:func:`subsurface_stress`).

        Returns
        -------
        RollerStress
            Its ``von_mises_max.max()`` is the largest von Mises stress below the roller
            [Pa]; ``x`` the slice centres [m].

        Raises
        ------
        ValueError
            For a result of several load cases, or a roller without load.
        """
        from .contact import subsurface_stress

        j = self.most_loaded_roller(raceway) if roller is None else roller
        c = self.roller_contact(j, raceway, n_slices=n_slices)
        if not c.load > 0.0:
            raise ValueError(f"roller: roller {j} carries no load at the {raceway} raceway in "
                             "this solution, so there is no stress below it (solve with a "
                             "load, or choose a loaded roller, e.g. roller=None)")
        return subsurface_stress(c, nu=self.bearing.material.nu, n_depth=n_depth)


def _scalar(x):
    a = np.asarray(x)
    return float(a) if a.ndim == 0 else a


class _BoundProfile(Profile):
    """A bearing's profile evaluated in the bearing's own context, whatever contact it is
    used in: the finite line contact of a roller then sees the very drop the lamina model
    sees (a logarithmic profile given by name keeps the bearing's design load)."""

    def __init__(self, profile, context):
        self.profile, self.context = profile, context
        self.name = profile.name

    def _drop(self, ax, u, x, ctx):
        return np.asarray(self.profile.drop(x, self.context), dtype=float)

    def __repr__(self) -> str:
        return f"{self.profile!r} (of the bearing)"


def _bound_profile(bearing: RollerBearing) -> Profile:
    return _BoundProfile(bearing.profile, bearing.profile_context)


def _warn_overload(r: "RollerLoadDistribution") -> "RollerLoadDistribution":
    """``r``, after a UserWarning (at the user's line) when its static safety is below 1;
    nothing inside a nested solve that silences the operating checks."""
    from .. import _operating

    if _operating.silenced() or not r.roller_loads.size:
        return r
    s0 = np.asarray(r.static_safety, float)
    bad = s0 < 1.0
    if not np.any(bad):
        return r
    i = np.unravel_index(int(np.argmin(s0)), s0.shape) if s0.ndim else ()
    p = float(np.asarray(r.max_pressure, float)[i])
    cases = "" if s0.ndim == 0 or s0.size == 1 else f" in {int(bad.sum())} of {s0.size} load cases"
    _operating.warn(f"roller load distribution: static safety s0 = {float(s0[i]):.3g} < 1{cases}: "
                    f"the most loaded slice of the lamina model reaches p_max = {p / 1e6:.0f} "
                    f"MPa, above the 4000 MPa on which ISO 76 bases C_0r of roller bearings "
                    "(s0 = (4000 MPa / p_max)^2); the permanent raceway deformation exceeds "
                    "the 1e-4 D_we that C_0r allows")
    return r


# =========================================================================== solve
def _loads_array(Fa, Fy, Fz, My, Mz):
    vals = (Fa, Fy, Fz, My, Mz)
    if all(type(v) in (float, int) and -1e30 <= v <= 1e30 for v in vals):
        return np.array(vals, dtype=float)                     # what the checks would give
    arrs = [as_array(v, n, bounded=True, tiny_ok=True)
            for v, n in ((Fa, "Fa"), (Fy, "Fy"), (Fz, "Fz"), (My, "My"), (Mz, "Mz"))]
    try:
        b = np.broadcast_arrays(*arrs)
    except ValueError:
        shapes = ", ".join(f"{n} {np.shape(a)}" for n, a in zip(DOF, arrs))
        raise ValueError(f"the loads Fa, Fy, Fz, My, Mz must broadcast together; got "
                         f"shapes {shapes}") from None
    return np.stack(b, axis=-1)


def _displacements(value) -> np.ndarray:
    """Imposed displacements as floats, ``None`` -> NaN (free)."""
    obj = np.array(value, dtype=object)
    if obj.dtype == object:
        obj = np.where(np.equal(obj, None), np.nan, obj)
    try:
        return np.asarray(obj, dtype=float)
    except (TypeError, ValueError):
        raise TypeError("displacements must be numbers or None/NaN (free) [m, rad]; got "
                        f"{value!r}") from None


def solve(bearing: RollerBearing, Fa=0.0, Fy=0.0, Fz=0.0, My=0.0, Mz=0.0, *,
          displacements=None, clearance=None, azimuth_offset: float = 0.0,
          rtol: float = 1e-10, max_iter: int = 100, initial=None) -> RollerLoadDistribution:
    r"""Five-degree-of-freedom static load distribution of a roller bearing (lamina model).

    Solves ``sum_jk q_jk(u) g_jk = F`` for the inner-ring displacement u (module notes).
    Any DOF can be imposed instead of loaded: give ``displacements`` with numbers for the
    imposed DOFs and ``None``/NaN for the free ones; the reaction appears in
    ``result.loads``.  Arguments and result names mirror
    :func:`ballrace.analytic.loaddist.solve`.

    A **cylindrical** bearing carries radial loads and tilting moments; its locating
    flanges are not modelled, so ``Fa`` must be 0 (ValueError otherwise) and the axial DOF
    is held (at 0 or its imposed value, reaction 0).  A single **tapered** bearing needs
    an axial load pressing the cone into the cup (``Fa > 0`` when x is free): the axial
    components of its roller loads all point one way.  Its roller forces also have a
    moment about the bearing centre under radial load, which a single bearing with a free
    tilt can balance only through the roller ends: impose the tilt (as a shaft does) or
    give the moment of the load's point of application.

    Parameters
    ----------
    bearing : RollerBearing
        Single-row bearing.
    Fa : float or array_like
        Axial load on the inner ring [N] (tapered: > 0 presses the cone into the cup).
    Fy, Fz : float or array_like
        Radial loads [N].
    My, Mz : float or array_like
        Tilting moments about y and z [N m].
    displacements : array_like, optional
        Shape (..., 5): imposed (dx, dy, dz [m], theta_y, theta_z [rad]), ``None``/NaN for
        free DOFs.  The load on an imposed DOF must be 0.
    clearance : float, optional
        Diametral clearance of the reference configuration [m]; default the bearing's.
        Negative: interference.
    azimuth_offset : float, optional
        Azimuth of roller 0 from +y [rad].
    rtol : float, optional
        Equilibrium tolerance relative to max(|applied load|, Q_max), moments divided by
        d_m/2 [-].
    max_iter : int, optional
        Newton iteration limit per load case.
    initial : array_like, optional
        Starting displacements, shape (..., 5) [m, rad].

    Returns
    -------
    RollerLoadDistribution

    Raises
    ------
    ValueError
        For invalid arguments (named); an axial load on a cylindrical bearing; a tapered
        bearing without an axial load pressing it together; loads beyond the model's
        load-deflection range (a slice approach above :data:`MAX_APPROACH_RATIO` D_we);
        loads with no equilibrium (the ring runs away).
    ConvergenceError
        When Newton does not reach ``rtol`` within ``max_iter`` iterations (residual and
        iteration count in the message), and when what would be returned does not balance
        the loads to max(1e-9, 100 rtol) (never returned).

    References
    ----------
    ISO/TS 16281:2008 (lamina model; the standard's text was not read); Harris & Kotzalas,
    *Advanced Concepts of Bearing Technology*, 2007, ch. 1 (roller load distribution,
    tapered rollers).

    Examples
    --------
    >>> from ballrace.analytic.roller import RollerBearing
    >>> b = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=45e-6)
    >>> r = b.solve(Fy=6940.0)
    >>> round(float(r.max_roller_load)), int((r.roller_loads > 0).sum())
    (2915, 5)
    >>> bool(r.relative_residual < 1e-9), bool(np.allclose(r.slice_loads.sum(-1), r.roller_loads))
    (True, True)
    """
    if not isinstance(bearing, RollerBearing):
        raise TypeError(f"bearing must be a RollerBearing; got {type(bearing).__name__}")
    if bearing.n_rows != 1:
        raise ValueError(f"n_rows: the load distribution handles single-row bearings; the "
                         f"bearing has n_rows={bearing.n_rows}")
    L = _loads_array(Fa, Fy, Fz, My, Mz)
    if displacements is None:
        shape = L.shape[:-1]
        L = L.reshape(-1, 5)
        Dsp = np.full(L.shape, np.nan)
    else:
        Dsp = _displacements(displacements)
        if Dsp.shape[-1:] != (5,):
            raise ValueError("displacements must have shape (..., 5): (dx, dy, dz, theta_y, "
                             f"theta_z) with None/NaN for free DOFs; got shape {Dsp.shape}")
        if np.any(np.isinf(Dsp)):
            raise ValueError("displacements must be finite or None/NaN (free) [m, rad]")
        L, Dsp = np.broadcast_arrays(L, Dsp)
        shape = L.shape[:-1]
        L, Dsp = L.reshape(-1, 5).astype(float), Dsp.reshape(-1, 5).copy()
    imposed = Dsp == Dsp
    if not bearing.tapered:
        imposed[:, 0] = True
        Dsp[:, 0] = np.where(Dsp[:, 0] == Dsp[:, 0], Dsp[:, 0], 0.0)
    for li, im in zip(L.tolist(), imposed.tolist()):
        _check_case(bearing, li, im)
    Pd = bearing.diametral_clearance if clearance is None else float(
        check_range(clearance, "clearance", -0.1 * bearing.roller_diameter,
                    0.1 * bearing.roller_diameter, unit="m"))
    off = float(as_array(azimuth_offset, "azimuth_offset", unit="rad"))
    if not (type(rtol) is float and 0.0 < rtol <= 1e-3):
        rtol = float(check_range(rtol, "rtol", 0.0, 1e-3, high_inclusive=True, unit="-"))
    if not (type(max_iter) is int and max_iter >= 1):
        max_iter = int(check_integer(max_iter, "max_iter", 1))
    model = _Model.of(bearing, off, Pd)
    lim = model.D / model.sc
    Dz = np.where(imposed, Dsp, 0.0)
    if np.any(np.abs(Dz) > lim):
        raise ValueError(f"imposed displacements must be within +-D_we = {model.D:g} m "
                         f"(translations) and +-2 D_we/d_m = {lim[3]:g} rad (tilts)")
    cap = model.Z * model.n_s * model.c * (MAX_APPROACH_RATIO * model.D) ** _N
    Fm = np.abs(L / model.sc).max(-1)
    if not Fm.max() <= cap:
        i = int(np.argmax(Fm))
        raise ValueError(f"the loads {L[i].tolist()} [N, N m] are beyond the load-deflection "
                         f"range of the bearing: {model.Z} rollers carry at most {cap:.4g} N "
                         f"(moments over d_m/2) at an approach of {MAX_APPROACH_RATIO:g} D_we")
    u0 = np.zeros_like(L)
    if initial is not None:
        u0 = np.broadcast_to(as_array(initial, "initial"), shape + (5,)).reshape(-1, 5).copy()
        if np.any(np.abs(u0) > lim):
            raise ValueError(f"initial must be within +-D_we = {model.D:g} m (translations) "
                             f"and +-2 D_we/d_m = {lim[3]:g} rad (tilts)")
    u0 = np.where(imposed, Dz, u0)
    N = L.shape[0]
    F_app = np.where(imposed, 0.0, L)
    out_u = np.empty((N, 5))
    out_J = np.empty((N, 5, 5))
    out_q = np.zeros((N, model.Z * model.n_s))
    out_d = np.empty((N, model.Z * model.n_s))
    iters = 0
    G = model.G
    for i in range(N):
        u, it, (d, on, r, q) = _newton(model, F_app[i], u0[i], ~imposed[i], rtol, max_iter)
        Ga = G[on]
        out_u[i], out_d[i] = u, d
        out_q[i, on] = q
        out_J[i] = (Ga.T * (_N * model.c * r)) @ Ga          # the exact tangent, all DOFs
        iters = max(iters, it)
    log.debug("roller load distribution: %d cases, at most %d Newton iterations", N, iters)
    return _warn_overload(_checked(bearing, model, out_u, out_J, out_q, out_d, F_app,
                                   imposed, shape, Pd, iters, rtol))


def _check_case(bearing, L, imposed):
    """ValueError for the loads of one case (lists of 5) the bearing cannot take."""
    for k in range(5):
        if imposed[k] and L[k] != 0 and (k or bearing.tapered):
            raise ValueError(f"the load on DOF {DOF[k]!r} must be 0 when its displacement is "
                             "imposed (the reaction is returned in result.loads)")
    if not bearing.tapered:
        if L[0] != 0:
            raise ValueError(f"Fa must be 0 for a cylindrical roller bearing: its locating "
                             f"flanges (NJ, NUP, NF designs), which carry axial load, are "
                             f"not modelled; got Fa={L[0]!r}")
        return
    if imposed[0]:
        return
    if L[0] < 0 or (L[0] == 0 and any(L[1:])):
        raise ValueError(f"Fa must be > 0 [N] for a single tapered roller bearing under "
                         f"load (it presses the cone into the cup; a radial load alone "
                         f"induces an axial force of about 1.26 F_r tan(alpha) that must "
                         f"be held); got Fa={L[0]!r} with loads {L} - or impose the axial "
                         "displacement (displacements)")
    # with x free the roller loads sum to Fa / sin(a): the radial load and the moments the
    # rollers can balance are bounded by it
    a = bearing.contact_angle
    arm = 0.5 * bearing.pitch_diameter * math.sin(a) + 0.5 * bearing.roller_length
    Qsum = L[0] / math.sin(a)
    Fr = math.hypot(0.0 if imposed[1] else L[1], 0.0 if imposed[2] else L[2])
    M = math.hypot(0.0 if imposed[3] else L[3], 0.0 if imposed[4] else L[4])
    if Fr > Qsum * math.cos(a) or M > Qsum * arm:
        raise ValueError(
            f"the loads {L} [N, N m] have no equilibrium in a single tapered roller bearing: "
            f"with Fa = {L[0]:g} N its rollers carry sum Q = Fa/sin(a) = {Qsum:.4g} N, at "
            f"most F_r = Fa/tan(a) = {Qsum * math.cos(a):.4g} N radially and "
            f"{Qsum * arm:.4g} N m of moment (arm d_m sin(a)/2 + L_we/2); increase Fa or "
            "impose the displacements a shaft holds")


def _checked(bearing, model, u, J, q, d, F_app, imposed, shape, Pd, iters, rtol):
    """The result, after checking that it balances the loads and lies in the model's range
    (ConvergenceError / ValueError otherwise: never an unbalanced result)."""
    Z, n_s = model.Z, model.n_s
    q3 = q.reshape(-1, Z, n_s)
    Q = q3.sum(-1)
    # re-derive the resultant from the slice loads and compare with the applied loads
    Fchk = q @ model.G
    sc = model.sc
    res = np.abs(np.where(imposed, 0.0, Fchk - F_app) / sc).max(-1)
    scale = np.maximum(np.abs(F_app / sc).max(-1), Q.max(-1))
    rel = np.where(scale > 0, res / np.where(scale > 0, scale, 1.0), res)
    tol = newton.roundoff_cap(rtol)
    if not (np.isfinite(u).all() and np.isfinite(Fchk).all() and np.isfinite(J).all()
            and rel.max() <= tol):
        finite = np.isfinite(u).all(-1) & np.isfinite(Fchk).all(-1) & \
            np.isfinite(J.reshape(len(u), -1)).all(-1)
        i = int(np.flatnonzero(~finite | ~(rel <= tol))[0])
        raise ConvergenceError(
            f"roller load distribution did not reach equilibrium: relative residual "
            f"{rel[i]:.3e} (> {tol:g}) after {iters} iterations in load case {i}; loads "
            f"{F_app[i].tolist()}, displacements {u[i].tolist()}")
    dmax = float(d.max(initial=0.0))
    if dmax > MAX_APPROACH_RATIO * model.D:
        i = int(np.argmax(d.max(-1)))
        raise ValueError(
            f"the loads {F_app[i].tolist()} [N, N m] are beyond the load-deflection range of "
            f"the bearing: a slice approach reaches {dmax:.3g} m > {MAX_APPROACH_RATIO:g} "
            f"D_we = {MAX_APPROACH_RATIO * model.D:.3g} m")
    psi = model.psi
    tilt = u[:, 4:5] * np.cos(psi) - u[:, 3:4] * np.sin(psi)
    return RollerLoadDistribution(
        bearing=bearing, azimuths=psi.copy(),
        displacements=u.reshape(shape + (5,)), loads=Fchk.reshape(shape + (5,)),
        applied=F_app.reshape(shape + (5,)), imposed=imposed.reshape(shape + (5,)),
        roller_loads=Q.reshape(shape + (Z,)), slice_loads=q3.reshape(shape + (Z, n_s)),
        approaches=d.reshape(shape + (Z, n_s)), raceway_tilts=tilt.reshape(shape + (Z,)),
        stiffness=J.reshape(shape + (5, 5)), clearance=float(Pd), iterations=int(iters))


# =========================================================================== shaft seat
class RollerRow:
    r"""One roller row at a fixed clearance, as a shaft seat sees it: the
    :class:`~ballrace.analytic.contract.Row` of a :class:`RollerBearing`.

    The lamina model of :func:`solve` (module notes) evaluated at imposed inner-ring
    displacements, every DOF imposed (no equilibrium iteration), with the slice directions
    g_jk and the unloaded approaches built once: the fast path an outer Newton iteration
    (:mod:`~ballrace.analytic.shaft`) calls many times.  Two rows of equal bearings at the
    same clearance compare equal (their rows are evaluated together).

    Frame: that of :func:`solve` shifted axially to the just-touching reference, as the
    seat contract asks: the row's u = 0 is the bearing's dx = x_t (the first slice just
    touching under a pure axial displacement; for a tapered bearing x_t = (P_d cos(alpha)/2
    + 2 min P(s_k)) / sin(alpha), the :attr:`~RollerBearing.axial_clearance` for a profile
    without drop at the middle), and x_t is :attr:`reference_axial_offset`, so that the
    rollers sit centred at u_x = -x_t.  A cylindrical row has no axial law (the flanges
    are not modelled): x_t = 0, and its forces and tangent have no axial row or column.

    Parameters
    ----------
    bearing : RollerBearing
        Single-row bearing.
    clearance : float, optional
        Diametral clearance P_d of the reference configuration [m]; default the bearing's.

    Attributes
    ----------
    reference_axial_offset : float
        x_t [m] (above; 0 for a cylindrical row).
    approach_limit : float
        :data:`MAX_APPROACH_RATIO` D_we [m].
    step_length : float
        D_we / 10 [m] (the approaches change character over a fraction of the roller).
    moment_radius : float
        d_m / 2 [m].

    Examples
    --------
    >>> from ballrace.analytic.roller import RollerBearing
    >>> b = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=45e-6)
    >>> r = b.solve(Fy=6940.0)
    >>> F, K, dmax, energy = RollerRow(b).ring_forces(r.displacements[None])
    >>> bool(np.allclose(F[0], r.loads, rtol=1e-12, atol=1e-9))
    True
    """

    __slots__ = ("bearing", "clearance", "reference_axial_offset", "approach_limit",
                 "step_length", "moment_radius", "_G", "_b", "_c", "_key")

    def __init__(self, bearing: RollerBearing, clearance=None):
        if not isinstance(bearing, RollerBearing):
            raise TypeError(f"bearing must be a RollerBearing; got {type(bearing).__name__}")
        if bearing.n_rows != 1:
            raise ValueError(f"bearing must be single-row (n_rows=1) to be a seat row; got "
                             f"n_rows={bearing.n_rows}")
        Pd = bearing.diametral_clearance if clearance is None else float(
            check_range(clearance, "clearance", -0.1 * bearing.roller_diameter,
                        0.1 * bearing.roller_diameter, unit="m"))
        G, b = _row_geometry(bearing, Pd)
        sa = math.sin(bearing.contact_angle)
        xt = float(np.min(-b)) / sa if sa > 0 else 0.0
        self.bearing, self.clearance = bearing, clearance
        self._G = G
        self._b = b + sa * xt                    # approaches at the row's u = 0
        self._b.setflags(write=False)
        self._c = bearing.lamina_stiffness / bearing.n_slices
        self.reference_axial_offset = xt
        self.approach_limit = MAX_APPROACH_RATIO * bearing.roller_diameter
        self.step_length = 0.1 * bearing.roller_diameter
        self.moment_radius = 0.5 * bearing.pitch_diameter
        self._key = (bearing, Pd)

    def __eq__(self, other):
        return type(other) is RollerRow and self._key == other._key

    def __hash__(self):
        return hash(self._key)

    def __repr__(self):
        return f"RollerRow({self.bearing!r}, clearance={self.clearance!r})"

    @property
    def diametral_clearance(self) -> float:
        """P_d of the row [m]."""
        return self._key[1]

    def to_bearing_frame(self, u) -> np.ndarray:
        """Displacements u (..., 5) of the row's frame in the frame of :func:`solve`:
        dx + x_t [m, rad]."""
        v = np.array(u, dtype=float)
        v[..., 0] += self.reference_axial_offset
        return v

    def approaches(self, u) -> np.ndarray:
        """Slice approaches delta_jk [m], shape u.shape[:-1] + (Z, n_s), at displacements
        u (..., 5) [m, rad] (negative: a gap)."""
        u = np.asarray(u, float)
        b = self.bearing
        d = u.reshape(-1, 5) @ self._G.T + self._b
        return d.reshape(u.shape[:-1] + (b.n_rollers, b.n_slices))

    def ring_forces(self, u):
        r"""Roller-force resultant on the inner ring, its exact tangent, the largest slice
        approach and the elastic energy at imposed displacements; the numbers of
        ``solve(bearing, displacements=to_bearing_frame(u), clearance=...)`` (``.loads``,
        ``.stiffness``).

        Parameters
        ----------
        u : ndarray, shape (N, 5)
            Inner-ring displacements (dx, dy, dz [m], theta_y, theta_z [rad]), row frame.

        Returns
        -------
        F : ndarray, shape (N, 5)
            sum q_jk g_jk (Fa, Fy, Fz [N], My, Mz [N m]).
        K : ndarray, shape (N, 5, 5)
            sum (10/9) (c_L/n_s) <delta_jk>^(1/9) g_jk g_jk^T [N/m, N/rad, N m/m, N m/rad].
        delta_max : ndarray, shape (N,)
            Largest slice approach [m].
        energy : ndarray, shape (N,)
            Slice potential sum (9/19) (c_L/n_s) <delta_jk>^(19/9) [J], whose gradient is F.
        """
        u = np.asarray(u, float).reshape(-1, 5)
        G = self._G
        d = u @ G.T + self._b                                   # (N, Z n_s)
        dp = np.maximum(d, 0.0)
        r = dp ** (1.0 / 9.0)
        q = self._c * dp * r
        F = q @ G
        w = (_N * self._c) * r
        K = np.einsum("nk,ki,kj->nij", w, G, G, optimize=True)
        return F, K, d.max(1), (9.0 / 19.0) * np.einsum("nk,nk->n", q, dp)

    def slice_loads(self, u) -> np.ndarray:
        """Slice loads q_jk at the outer raceway [N], shape u.shape[:-1] + (Z, n_s), at
        displacements u (..., 5) [m, rad]."""
        dp = np.maximum(self.approaches(u), 0.0)
        return self._c * dp ** _N

    def element_loads(self, u) -> np.ndarray:
        """Roller loads Q_j (outer raceway) [N], shape u.shape[:-1] + (Z,), at
        displacements u (..., 5) [m, rad]."""
        return self.slice_loads(u).sum(-1)

    def result(self, u) -> RollerLoadDistribution:
        """The checked :class:`RollerLoadDistribution` at imposed displacements u (5,)
        [m, rad] of the row's frame (its ``displacements`` are in the frame of
        :func:`solve`: :meth:`to_bearing_frame`)."""
        return solve(self.bearing, displacements=self.to_bearing_frame(u),
                     clearance=self.diametral_clearance)

    def rating_life(self, u, *, dynamic_rating=None, rotating: str = "inner",
                    nominal_contact_angle=None):
        """ISO/TS 16281 reference rating life of the row at displacements u (..., 5)
        [m, rad] (:func:`ballrace.analytic.roller.life.reference_rating_life` of its slice
        loads, the cone's q_jk Q_i/Q_o at the inner raceway); dynamic_rating [N] (default
        the bearing's ISO 281 C_r).  ``nominal_contact_angle`` must be None: a roller
        bearing is rated at its own contact angle.  A row without load raises ValueError
        (infinite life), as a ball row does."""
        from types import SimpleNamespace

        from . import life

        if nominal_contact_angle is not None:
            raise ValueError("nominal_contact_angle is for ball bearings; a roller bearing is "
                             "rated at its own contact angle (give dynamic_rating [N] to use "
                             f"another C); got {nominal_contact_angle!r}")
        q = self.slice_loads(u)
        res = SimpleNamespace(slice_loads=q, slice_loads_inner=q * self.bearing.inner_load_ratio)
        return life.reference_rating_life(self.bearing, res, dynamic_rating=dynamic_rating,
                                          rotating=rotating)


@functools.lru_cache(maxsize=32)
def _row_geometry(bearing: RollerBearing, clearance: float):
    """(G (Z n_s, 5), b (Z n_s,)) of :class:`RollerRow`: the slice directions g_jk and the
    approaches at u = 0 of the module notes (azimuth offset 0), read-only."""
    model = _model(bearing, 0.0, clearance)
    return model.G, model.b
