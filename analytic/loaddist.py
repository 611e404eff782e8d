r"""Static load distribution in a single-row ball bearing with rigid rings.

Model (Jones 1946, 1960; Hamrock & Dowson 1981 §3.3; Harris 2001 §7; Ricci 2009 §4).
The outer ring is fixed; the inner ring moves by ``u = (dx, dy, dz, theta_y, theta_z)``
(axial, two radial translations [m], two tilts [rad]).  Ball j at azimuth psi_j (from +y
towards +z) joins the inner- and outer-groove curvature centres, whose separation is

.. math::
    x_j = x_0 + \delta_y\cos\psi_j + \delta_z\sin\psi_j, \qquad
    z_j = z_0 + \delta_x + \mathcal{R}_i(\theta_y\sin\psi_j - \theta_z\cos\psi_j),

    s_j = \sqrt{x_j^2 + z_j^2}, \quad \delta_{n,j} = s_j - A, \quad
    \beta_j = \operatorname{atan2}(z_j, x_j), \quad
    Q_j = K_n(\beta_j)\,\langle\delta_{n,j}\rangle^{3/2},

with A = (f_i + f_o - 1) D, R_i the radius of the inner-groove centre locus and K_n the
exact-Hertz ball stiffness at the ball's own contact angle (Hamrock & Dowson 1981
eqs. 3.33–3.38, 3.61–3.65; Ricci 2009 eqs. 16, 22–27).  The reference configuration
(u = 0) is the one where every ball just touches both races at the free contact angle:
x_0 = A - P_d/2 = A cos beta_f, z_0 = A sin beta_f (H&D eq. 3.61); :func:`radial` uses the
axially centred configuration z_0 = 0 instead (H&D eq. 3.39).  The groove torus is taken
as complete on both sides (deep-groove model): a ball may be loaded at negative contact
angle.  It is half a torus, though, facing the ball: a ball whose groove-centre line
points inwards (x_j <= 0, |beta_j| > 90 deg, possible only with a clearance near 2A) is
unloaded, and reports that line's angle folded into (-90, 90] deg.  Loads whose largest
ball approach would exceed 0.1 D are refused as beyond the load-deflection range.

Equilibrium of the inner ring (loads applied to it: Fa, Fy, Fz, My, Mz, right-handed
moments about the bearing centre):

.. math::
    F_a = \sum Q_j\sin\beta_j,\quad F_y = \sum Q_j\cos\beta_j\cos\psi_j,\quad
    F_z = \sum Q_j\cos\beta_j\sin\psi_j,

    M_y = \sum r_j Q_j\sin\beta_j\sin\psi_j,\quad M_z = -\sum r_j Q_j\sin\beta_j\cos\psi_j.

The moment arm r_j is ``moment_arm="groove"`` (default): r_j = R_i, consistent with the
kinematics, so the ball forces derive from a potential and the stiffness matrix is
(almost) symmetric (Harris 2001 §7.4); or ``moment_arm="contact"``: r_j = d_c/2 =
(d_e - D cos beta_j)/2, the inner contact radius used by Ricci (2009 eq. 29).

Solution: damped Newton with the analytic Jacobian (including dK_n/dbeta), a
Levenberg regularisation for unloaded directions (clearance) and an Armijo line search
on the frozen-stiffness potential, vectorized over load cases (the step control is the
one of :mod:`ballrace.analytic.newton`, shared by every solver).  Unloaded balls carry
Q = 0 exactly and keep their geometric angle atan2(z, x).  Inside the solver K_n(beta)
(which depends on beta only through cos beta) is evaluated from a per-bearing Chebyshev
series of ln K_n built from, and checked against, the exact Hertz solution to 1e-13
(:func:`ball_stiffness` and the result's ``inner``/``outer`` contacts use the exact
solution directly).
"""
from __future__ import annotations

import functools
import logging
import math
import os
import weakref
from dataclasses import dataclass, field, replace

import numpy as np

from . import hertz
from ._checks import (MAX_MAGNITUDE, as_array, broadcast, check_choice, check_integer, check_nonnegative,
                      check_positive, check_range)
from ..errors import ConvergenceError
from . import newton
from .newton import POLICY
from .bearing import BallBearing

__all__ = [
    "LoadDistribution",
    "ConvergenceError",
    "MOMENT_ARMS",
    "solve",
    "ring_forces",
    "RingModel",
    "MAX_APPROACH_RATIO",
    "radial",
    "thrust",
    "combined",
    "eccentric_thrust",
    "ball_stiffness",
    "jones_radial_factor",
    "stribeck_max_ball_load",
    "jones_max_ball_load",
    "STRIBECK_LIMIT",
]

log = logging.getLogger(__name__)

MOMENT_ARMS = ("groove", "contact")
DOF = ("x", "y", "z", "theta_y", "theta_z")

#: Stribeck's limit Z Q_max / F_r for zero clearance and many balls,
#: 2 pi / B(1/2, 7/4) = 4.3701 (Stribeck 1901; Hamrock & Dowson 1981 eq. 3.48).
STRIBECK_LIMIT = 2.0 * np.pi / (np.sqrt(np.pi) * 0.9190625268488832 / 1.1330030963193457)


# ConvergenceError is defined in ballrace.errors and imported above; it stays importable
# from here (``from ballrace.analytic.loaddist import ConvergenceError``).


# =========================================================================== stiffness
def _d1_and_derivative(m):
    """(K - E)/m and its m-derivative for small m by series (A&S 1964 eqs. 17.3.11-12)."""
    coef = hertz.d1_series_coefficients()
    return np.polyval(coef, m), np.polyval(np.polyder(coef), m)


def _race_stiffness(Rx, Ry, Ep):
    r"""Contact stiffness K and d ln K / d ln Rx at fixed Ry (exact Hertz, analytic).

    K = pi k E' sqrt(2 E R / (9 K^3)) (H&D 1981 eq. 3.33) with k(alpha) from Hertz's
    relation alpha = D2/(p D1), p = 1/k^2, D1 = (K - E)/m, D2 = K - D1 (H&D eq. 3.14);
    d/dk by the elliptic-integral derivatives dK/dm = (E - pK)/(2mp), dE/dm = (E - K)/(2m)
    (Abramowitz & Stegun 1964 eqs. 17.3.16-17.3.17 in parameter form).
    """
    swap = Ry < Rx
    alpha = np.where(swap, Rx / Ry, Ry / Rx)
    k, K, E = (np.asarray(v) for v in hertz.ellipticity(alpha))
    R = Rx * Ry / (Rx + Ry)
    stiff = np.pi * k * Ep * np.sqrt(2.0 * E * R / (9.0 * K**3))
    p = 1.0 / (k * k)
    m = (k - 1.0) * (k + 1.0) * p
    small = m < 0.05
    mb = np.where(small, 1.0, m)
    D1 = (K - E) / mb
    kD1k = (E - 2.0 * p * D1) / mb                                  # k dD1/dk
    if np.any(small):                                               # no cancellation near k = 1
        d1s, dd1s = _d1_and_derivative(np.where(small, m, 0.0))
        D1 = np.where(small, d1s, D1)
        kD1k = np.where(small, 2.0 * p * dd1s, kD1k)
    D2 = K - D1
    kD2k = D2 - kD1k                                                # k dD2/dk (k dK/dk = D2)
    dlna = kD2k / D2 + 2.0 - kD1k / D1                              # d ln alpha / d ln k
    dlng = 1.0 - 0.5 * p * D1 / E - 1.5 * D2 / K                    # d ln(K/sqrt R) / d ln k
    G = dlng / dlna
    dlnK_dlnRx = 0.5 * Ry / (Rx + Ry) + np.where(swap, G, -G)
    return stiff, dlnK_dlnRx


def _kn_exact(model, beta):
    """Ball stiffness K_n(beta) [N/m^1.5] and d ln K_n / d beta [1/rad], exact Hertz."""
    D, dm = model.D, model.dm
    cb, sb = np.cos(beta), np.sin(beta)
    g = D * cb / dm
    Rx = np.concatenate([(0.5 * D) * (1.0 - g).ravel(), (0.5 * D) * (1.0 + g).ravel()])
    Ry = np.concatenate([np.full(g.size, model.Ry_i), np.full(g.size, model.Ry_o)])
    Kc, dlnK = _race_stiffness(Rx, Ry, model.Ep)
    n = g.size
    Ki, Ko = Kc[:n].reshape(g.shape), Kc[n:].reshape(g.shape)
    dg = (D / dm) * sb                                       # = -d gamma / d beta
    dli = dlnK[:n].reshape(g.shape) * dg / (1.0 - g)         # d ln K_i / d beta
    dlo = -dlnK[n:].reshape(g.shape) * dg / (1.0 + g)        # d ln K_o / d beta
    wi, wo = Ki ** (-2.0 / 3.0), Ko ** (-2.0 / 3.0)
    Kn = (wi + wo) ** -1.5                                   # H&D (1981) eq. 3.38
    return Kn, (wi * dli + wo * dlo) / (wi + wo)


#: Required accuracy of the tabulated ln K_n(cos beta) against exact Hertz (absolute in
#: ln K_n, i.e. relative in K_n), checked when the table is built.
_TABLE_TOL = 1e-13
#: Required accuracy of its derivative d ln K_n / d beta, relative to the largest value.
_TABLE_DTOL = 5e-9


def _kn_table(model):
    """Chebyshev series of ln K_n in tau = 2 cos(beta) - 1 (beta in [0, 90] deg), or None.

    K_n depends on beta only through gamma = (D/d_e) cos(beta) (Ricci 2009 eqs. 8-11),
    an analytic function of t = cos(beta), so a Chebyshev interpolant converges
    geometrically.  Only t in [0, 1] is tabulated: a ball touches only where its
    groove-centre line points outwards (x > 0, |beta| < 90 deg); :func:`_kn` evaluates
    the exact solution for the rare t < 0.  The series is accepted only if it reproduces
    the exact Hertz value to ``_TABLE_TOL`` at 1001 check points and its derivative to
    ``_TABLE_DTOL`` relative (it enters only the Jacobian); otherwise the exact evaluation is used throughout.  Returns an
    (n, 2) array: the coefficients of ln K_n and of its tau-derivative.
    """
    C = np.polynomial.chebyshev
    b_chk = np.linspace(0.0, 0.5 * np.pi, 1001)
    tau_chk = 2.0 * np.cos(b_chk) - 1.0
    Kx, dx = _kn_exact(model, b_chk)
    for deg in (10, 12, 14, 16, 20, 24):       # rounding noise grows with the degree
        c = C.chebinterpolate(
            lambda x: np.log(_kn_exact(model, np.arccos(np.clip(0.5 * (x + 1.0), 0, 1)))[0]),
            deg)
        err = np.max(np.abs(C.chebval(tau_chk, c) - np.log(Kx)))
        cd = np.append(C.chebder(c), 0.0)
        d = -2.0 * np.sin(b_chk) * C.chebval(tau_chk, cd)
        derr = np.max(np.abs(d - dx)) / max(np.max(np.abs(dx)), 1e-300)
        if err <= _TABLE_TOL and derr <= _TABLE_DTOL:
            log.debug("K_n table: degree %d, max error %.2e (ln K_n), %.2e (derivative)",
                      deg, err, derr)
            return np.ascontiguousarray(np.stack([c, cd], axis=1))
    log.info("K_n table not accurate enough (%.2e, %.2e); using exact Hertz at every step",
             err, derr)
    return None


def _kn(model, beta, c=None, sn=None):
    """Ball stiffness K_n(beta) [N/m^1.5] and d ln K_n / d beta [1/rad] (arrays).

    With the table, ln K_n = sum a_k T_k(tau), tau = 2 cos(beta) - 1: T_k(tau) =
    cos(k theta), theta = arccos(tau), as one matrix product for small arrays, Clenshaw's
    recurrence for large ones; d ln K_n / d beta = -2 sin(beta) d ln K_n / d tau from the
    derivative series.  ``c``, ``sn``: cos(beta), sin(beta) when known.  Exact Hertz where
    cos(beta) < 0 (beyond the table; such balls are unloaded in the solver).
    """
    if model.table is None:
        return _kn_exact(model, beta)
    if c is None:
        c, sn = np.cos(beta), np.sin(beta)
    tab = model.table
    n = tab.shape[0]
    tau = 2.0 * c - 1.0
    if tau.size * n <= 4096:
        th = np.arccos(np.maximum(tau, -1.0))
        v = np.cos(th[..., None] * np.arange(n)) @ tab
        lnK, dtau = v[..., 0], v[..., 1]
    else:
        tau = np.maximum(tau, -1.0)
        t2 = 2.0 * tau
        out = []
        for col in (tab[:, 0], tab[:, 1]):             # Clenshaw for sum a_k T_k(tau)
            b1 = np.zeros_like(tau)
            b2 = np.zeros_like(tau)
            for ck in col[:0:-1]:
                b1, b2 = t2 * b1 - b2 + ck, b1
            out.append(tau * b1 - b2 + col[0])
        lnK, dtau = out
    Kn, d = np.exp(lnK), -2.0 * sn * dtau
    if not c.min(initial=0.0) >= 0.0:
        neg = c < 0
        Kn[neg], d[neg] = _kn_exact(model, np.asarray(beta)[neg])
    return Kn, d


def ball_stiffness(bearing: BallBearing, contact_angle):
    r"""Ball stiffness K_n(beta) and its logarithmic derivative with contact angle.

    .. math:: K_n = \left(K_i^{-2/3} + K_o^{-2/3}\right)^{-3/2}, \qquad
              \frac{d\ln K_n}{d\beta} = \sum_{r=i,o} w_r
              \frac{\partial\ln K_r}{\partial\ln R_{x,r}}\frac{d\ln R_{x,r}}{d\beta},
              \quad w_r = \frac{K_r^{-2/3}}{K_i^{-2/3} + K_o^{-2/3}}

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    contact_angle : float or array_like
        Contact angle beta [rad].

    Returns
    -------
    K_n : float or ndarray
        [N/m^1.5].
    dlnKn_dbeta : float or ndarray
        d ln K_n / d beta [1/rad], analytic (used by the Newton Jacobian).

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.14), (3.33), (3.38); Ricci (2009) eqs. (8)–(16).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> Kn, dlnK = ball_stiffness(brg, np.radians(40))
    >>> round(float(Kn) / 1e9, 4), bool(np.isclose(Kn, brg.contact_stiffness(np.radians(40))[2]))
    (14.2471, True)
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    b = check_range(contact_angle, "contact_angle", -np.pi, np.pi, low_inclusive=True,
                    high_inclusive=True, unit="rad")
    Kn, d = _kn_exact(_Model.of(bearing), b)
    return hertz.scalar_result(Kn), hertz.scalar_result(d)


# =========================================================================== model
@dataclass(frozen=True)
class BallModel:
    """Plain numbers of a single-row ball bearing used by the kernels (frozen; one per
    bearing, cached: build it with :meth:`of`).

    Other ball-row models (:mod:`~ballrace.analytic.duplex`,
    :mod:`~ballrace.analytic.highspeed`) share it so that every model uses the same ball
    stiffness and load range.

    Attributes
    ----------
    D, dm, A, Ri : float
        Ball diameter, pitch diameter, groove curvature-centre distance, inner-groove
        centre radius [m].
    Ep : float
        Effective modulus E' [Pa].
    Ry_i, Ry_o : float
        Transverse radii of the inner and outer contact [m].
    Z : int
        Number of balls [-].
    beta_f : float
        Free contact angle [rad].
    Pd : float
        Diametral clearance [m].
    table : ndarray or None
        Chebyshev table of ln K_n(beta) (None: exact Hertz at every call) [-].
    Kn_free : float
        K_n at the free contact angle [N/m^1.5].
    capacity : float
        Largest resultant the balls carry within :data:`MAX_APPROACH_RATIO` [N].
    """

    D: float
    dm: float
    A: float
    Ri: float
    Ep: float
    Ry_i: float
    Ry_o: float
    Z: int
    beta_f: float
    Pd: float
    table: np.ndarray | None = None
    Kn_free: float = 0.0
    capacity: float = np.inf
    geos: dict = field(default_factory=dict, repr=False, compare=False)  # _geo() cache

    @staticmethod
    def of(b: BallBearing) -> "BallModel":
        """The model of bearing ``b``: looked up by identity (a dict and a weak reference,
        about 0.3 us), else by value (hashing the frozen bearing, some us), else built."""
        hit = _MODELS.get(id(b))
        if hit is not None and hit[0]() is b:
            return hit[1]
        m = _Model._of(b)
        key = id(b)

        def forget(ref, key=key):
            if _MODELS.get(key, (None,))[0] is ref:
                del _MODELS[key]
        _MODELS[key] = (weakref.ref(b, forget), m)
        return m

    @staticmethod
    @functools.lru_cache(maxsize=64)
    def _of(b: BallBearing) -> "BallModel":
        if b.n_rows != 1:
            raise NotImplementedError(
                f"load distribution is implemented for single-row bearings (n_rows=1); "
                f"got n_rows={b.n_rows}")
        D = b.ball_diameter
        m = BallModel(D=D, dm=b.pitch_diameter, A=b.curvature_center_distance,
                   Ri=b.inner_groove_center_radius, Ep=b.E_prime,
                   Ry_i=b.f_inner * D / (2 * b.f_inner - 1),
                   Ry_o=b.f_outer * D / (2 * b.f_outer - 1), Z=b.n_balls,
                   beta_f=b.free_contact_angle, Pd=b.diametral_clearance)
        Kf = float(_kn_exact(m, np.array([m.beta_f]))[0][0])
        Kmax = 1.01 * float(np.max(_kn_exact(m, np.linspace(0.0, np.pi, 181))[0]))
        cap = m.Z * Kmax * (MAX_APPROACH_RATIO * D) ** 1.5
        return replace(m, table=_kn_table(m), Kn_free=Kf, capacity=cap)


    def contact_stiffness(self, beta, c=None, sn=None):
        """Ball stiffness K_n(beta) [N/m^1.5] and d ln K_n / d beta [1/rad] (arrays) from
        the model's table (exact Hertz where it does not reach); ``c``, ``sn``: cos(beta),
        sin(beta) [-] when known.  beta: contact angles [rad]."""
        return _kn(self, beta, c, sn)


_Model = BallModel               # the module's own short name

#: id(bearing) -> (weak reference to it, its _Model): see _Model.of
_MODELS: dict = {}


def _reference(model: _Model, clearance, centered: bool):
    """(x0, z0): groove-centre separation of the reference configuration (H&D 3.39, 3.61)."""
    if clearance is None:
        Pd = model.Pd
    else:
        Pd = float(check_range(clearance, "clearance", None, 2.0 * model.A, unit="m"))
    x0 = model.A - 0.5 * Pd
    z0 = 0.0 if centered or x0 >= model.A else float(np.sqrt(model.A**2 - x0**2))
    return Pd, x0, z0


# =========================================================================== kernel
def _geo(model, bearing, azimuth_offset, x0, z0):
    """The _Geo of a solve, cached on the model for plain finite float offsets."""
    key = (azimuth_offset, x0, z0)
    plain = type(azimuth_offset) is float and math.isfinite(azimuth_offset)
    if plain:
        g = model.geos.get(key)
        if g is not None:
            return g
    g = _Geo(model, bearing.azimuths(azimuth_offset), x0, z0)
    if plain and len(model.geos) < 64:
        model.geos[key] = g
    return g


class _Geo:
    """Per-solve constants: ball azimuths and the kinematic vectors dx_j/du, dz_j/du."""

    __slots__ = ("psi", "cp", "sp", "gx", "gz", "G", "G2", "kk", "xz0", "xz2", "M", "ar", "x0",
                 "z0", "A", "g0", "Kseat", "cpack")

    def __init__(self, model, psi, x0, z0):
        Z = psi.size
        self.psi, self.cp, self.sp = psi, np.cos(psi), np.sin(psi)
        gx = np.zeros((Z, 5))
        gx[:, 1], gx[:, 2] = self.cp, self.sp
        gz = np.zeros((Z, 5))
        gz[:, 0], gz[:, 3], gz[:, 4] = 1.0, model.Ri * self.sp, -model.Ri * self.cp
        self.gx, self.gz = gx, gz
        self.G = np.stack([gx, gz], axis=1)                  # (Z, 2, 5)
        self.G2 = np.concatenate([gx, gz])                   # (2Z, 5): (dx; dz) = G2 u
        kk = np.zeros((Z, 5))                                # d(contact-arm vector)/d r
        kk[:, 3], kk[:, 4] = self.sp, -self.cp
        self.kk = kk
        # one-case kernel (_one_case): (x; z) offsets of every ball, twice them, and the
        # per-ball trig moments (1, cos psi, sin psi, cos^2, cos sin, sin^2) (Z, 6)
        self.xz0 = np.concatenate([np.full(Z, x0), np.full(Z, z0)])
        self.xz2 = 2.0 * self.xz0
        cp, sp = self.cp, self.sp
        self.M = np.ascontiguousarray(np.stack([np.ones(Z), cp, sp, cp * cp, cp * sp, sp * sp], 1))
        self.ar = None if model.table is None else np.arange(float(model.table.shape[0]))[None]
        self.x0, self.z0, self.A = x0, z0, model.A
        self.Kseat = None                                    # see _one_case_seated
        self.cpack = None                                    # see _compiled_pack
        # x0^2 + z0^2 - A^2 without cancellation: 0 for the touching reference,
        # (x0 - A)(x0 + A) = -(P_d/2)(x0 + A) for the centred one
        self.g0 = 0.0 if z0 > 0 else (x0 - model.A) * (x0 + model.A)

    def xz(self, u):
        """Groove-centre separations x_j, z_j and approach s_j - A (N, Z) at u (N, 5).

        s - A = (g0 + 2 x0 dx + dx^2 + 2 z0 dz + dz^2)/(s + A) keeps full relative
        precision when the approach is many orders below A (light loads).
        """
        dx, dz = u @ self.gx.T, u @ self.gz.T
        x, z = self.x0 + dx, self.z0 + dz
        s = np.hypot(x, z)
        approach = (self.g0 + dx * (2.0 * self.x0 + dx) + dz * (2.0 * self.z0 + dz)) / (s + self.A)
        return x, z, s, approach


class _State:
    """Ball geometry, loads, resultant and (optionally) Jacobian at displacements u (N,5)."""

    __slots__ = ("s", "beta", "c", "sn", "delta", "Kn", "dlnK", "Q", "F", "J")

    def __init__(self, model, geo, u, arm, jac=True, Kn=None):
        if u.shape[0] == 1 and jac and Kn is None:
            self._one(model, geo, u[0], arm)
            return
        x, z, s, delta = geo.xz(u)
        s = np.maximum(s, 1e-300)
        c, sn = x / s, z / s
        beta = np.arctan2(z, x)
        # a ball touches only where the groove-centre line points outwards (x > 0): with
        # x <= 0 the surfaces of both grooves face away from it (the groove is half a torus)
        delta = np.where(x > 0, np.maximum(delta, 0.0), 0.0)
        if Kn is None:
            Kn, dlnK = _kn(model, beta)
        else:
            dlnK = np.zeros_like(Kn)
        Q = Kn * delta * np.sqrt(delta)
        fr, fa = Q * c, Q * sn
        F = fr @ geo.gx + fa @ geo.gz
        if arm == "contact":                                 # Ricci (2009) eq. 29 arm
            r = 0.5 * (model.dm - model.D * c)
            F[:, 3] = (r * fa) @ geo.sp
            F[:, 4] = -((r * fa) @ geo.cp)
        self.s, self.beta, self.c, self.sn = s, beta, c, sn
        self.delta, self.Kn, self.dlnK, self.Q, self.F = delta, Kn, dlnK, Q, F
        self.J = _jacobian(model, geo, self, arm) if jac else None

    def _one(self, model, geo, u, arm):
        """One load case (u of shape (5,)): the kernel :func:`_one_case`, as (1, ...) arrays."""
        self._set(model, _one_case(model, geo, u, arm))

    def _set(self, model, o):
        Ri = model.Ri
        sc = (1.0, 1.0, 1.0, Ri, Ri)
        Fs, Js = o.F, o.J
        self.s, self.c, self.sn = o.s[None], o.c[None], o.sn[None]
        self.beta = np.arctan2(o.z, o.x)[None]
        self.delta, self.Kn, self.dlnK, self.Q = o.delta[None], o.Kn[None], o.dlnK[None], o.Q[None]
        self.F = np.array([[Fs[i] * sc[i] for i in range(5)]])
        self.J = _unscaled_J(Js, Ri)[None]


def _unscaled_J(Js, Ri):
    """The (5, 5) array J = J_s (sc sc^T) of a scaled Jacobian (nested list) [SI]."""
    J = np.array(Js)
    J[3:] *= Ri
    J[:, 3:] *= Ri
    return J


#: Weights of the one-case kernel as combinations of the 20 products p_a t_b of
#: p = (k15, qk, qs, Q) and t = (cos b, sin b, cos^2 b, cos b sin b, sin^2 b) (row 5 a + b):
#: f_r = Q cos b, f_a = Q sin b and the four d(Q cos b, Q sin b)/d(x, z) (see _one_case).
_W_OF_PT = np.zeros((6, 20))
for _r, _terms in enumerate((((3, 0, 1),), ((3, 1, 1),),
                             ((0, 2, 1), (1, 3, -1), (2, 4, 1)),       # W_xx
                             ((0, 3, 1), (1, 2, 1), (2, 3, -1)),       # W_xz
                             ((0, 3, 1), (1, 4, -1), (2, 3, -1)),      # W_zx
                             ((0, 4, 1), (1, 3, 1), (2, 2, 1)))):      # W_zz
    for _a, _b, _v in _terms:
        _W_OF_PT[_r, 5 * _a + _b] = _v
del _r, _terms, _a, _b, _v


class _OneCase:
    """Result of :func:`_one_case` (plain attributes; F, J scaled, as Python lists)."""

    __slots__ = ("x", "z", "s", "c", "sn", "delta", "Kn", "dlnK", "Q", "F", "J", "qmax", "dmax")


def _kseat(model, geo):
    """K_n at the reference angle atan2(z_0, x_0) (exact Hertz), cached on the _Geo."""
    if geo.Kseat is None:
        geo.Kseat = float(_kn_exact(model, np.array([math.atan2(geo.z0, geo.x0)]))[0][0])
    return geo.Kseat


def _one_case_seated(model, geo):
    """:func:`_one_case` at u = 0 in the touching reference configuration (geo.g0 == 0):
    every ball at zero approach at the reference angle atan2(z_0, x_0), so Q = 0, F = 0,
    J = 0 exactly (K_n at that angle, exact Hertz, cached on the _Geo)."""
    Z = geo.cp.size
    o = _OneCase()
    o.x, o.z = np.full(Z, geo.x0), np.full(Z, geo.z0)
    s = math.hypot(geo.x0, geo.z0)
    o.s = np.full(Z, s)
    o.c, o.sn = o.x / s, o.z / s
    o.delta, o.Q, o.dlnK = np.zeros(Z), np.zeros(Z), np.zeros(Z)
    o.Kn = np.full(Z, _kseat(model, geo))
    o.F = [0.0] * 5
    o.J = [[0.0] * 5 for _ in range(5)]
    return o


def _one_case(model, geo, u, arm):
    r"""Ball loads, resultant and Jacobian for one case u = (5,) [m, rad], in scaled form.

    Returns an :class:`_OneCase` whose ``F`` (5 floats) and ``J`` (5 x 5 nested list) are
    the resultant and tangent stiffness with moments and tilts scaled by R_i
    (F_s = F / sc, J_s = J / (sc sc^T), sc = (1, 1, 1, R_i, R_i)), the form the Newton
    iteration works in.  Per ball, with e = (cos b, sin b), t = (-sin b, cos b),
    k15 = 1.5 K_n delta^0.5, qs = Q / s, qk = qs d ln K_n / d beta, the resultant of
    (Q cos b, Q sin b) changes with the groove-centre offsets (x, z) by
    W = k15 e (x) e + qk e (x) t + qs t (x) t; with g_x = (0, cos psi, sin psi, 0, 0),
    g_z = (1, 0, 0, sin psi, -cos psi) (scaled) and h = (1, 0, 0, rho sin psi,
    -rho cos psi) the force row (rho = 1, groove arm; rho = (d_e - D cos b)/(2 R_i),
    contact arm):

    .. math:: F = \sum Q(\cos b\, g_x + \sin b\, h), \quad
              J = \sum W_{xx} g_x g_x^T + W_{xz} g_x g_z^T + W_{zx} h g_x^T + W_{zz} h g_z^T
              [+ Q \sin b\, dh/db\, (db/du)^T]

    Every entry is a sum over the balls of a per-ball weight times one of the trig
    moments (1, cos psi, sin psi, cos^2 psi, cos psi sin psi, sin^2 psi), so the whole is
    one matrix product of weights and moments, then 30 scalar assignments: a handful of
    NumPy calls whatever Z.
    """
    Z = geo.cp.size
    d = np.dot(geo.G2, u)                                # (dx; dz)
    XZ = d + geo.xz0
    x, z = XZ[:Z], XZ[Z:]
    s = np.hypot(x, z)
    w = d * (d + geo.xz2)                                # dx (2 x0 + dx); dz (2 z0 + dz)
    approach = w[:Z] + w[Z:] if geo.g0 == 0 else (geo.g0 + w[:Z]) + w[Z:]
    approach /= s + geo.A
    if not min(s.tolist()) > 0.0:
        s = np.maximum(s, 1e-300)
    CS = XZ.reshape(2, Z) / s
    c, sn = CS[0], CS[1]
    delta = np.maximum(approach, 0.0)
    cmin = min(c.tolist())
    if not cmin > 0:
        delta[~(x > 0)] = 0.0
    # K_n from the table (see _kn): ln K_n = sum a_k cos(k arccos(2 cos b - 1))
    tab = model.table
    if tab is None or not cmin >= 0.0:
        Kn, dlnK = _kn(model, np.arctan2(z, x), c, sn)
    else:
        v = np.dot(np.cos(np.dot(np.arccos(c * 2.0 - 1.0)[:, None], geo.ar)), tab)
        Kn = np.exp(v[:, 0])
        dlnK = (-2.0 * sn) * v[:, 1]
    sq = np.sqrt(delta)
    P = np.empty((4, Z))
    np.multiply(Kn, sq, out=P[3])
    np.multiply(P[3], 1.5, out=P[0])                     # k15
    P[3] *= delta                                        # Q
    np.divide(P[3], s, out=P[2])                         # qs
    np.multiply(P[2], dlnK, out=P[1])                    # qk
    T = np.empty((5, Z))
    T[:2] = CS
    np.multiply(CS, c, out=T[2:4])
    np.multiply(sn, sn, out=T[4])
    Wt = np.dot(_W_OF_PT, (P[:, None, :] * T).reshape(20, Z))  # fr, fa, Wxx, Wxz, Wzx, Wzz
    S = np.dot(Wt, geo.M).tolist()
    fr, fa, Wxx, Wxz, Wzx, Wzz = S
    if arm == "groove":
        far, Wzxr, Wzzr = fa, Wzx, Wzz
    else:
        # rows 3, 4: arm rho = r / R_i, and the change of r = (d_e - D cos b)/2 with b:
        # Q sin b (D/2) sin b (sin psi, -cos psi) (x) (-sin b g_x + cos b g_z) / (R_i s)
        k = 0.5 * model.D / model.Ri
        rho = (0.5 * model.dm / model.Ri) - k * c
        Wr = Wt[[1, 4, 5]] * rho
        q3 = (k * P[2]) * T[4]
        Wr[1] -= q3 * sn
        Wr[2] += q3 * c
        far, Wzxr, Wzzr = np.dot(Wr, geo.M).tolist()
    # moments index: 0: 1, 1: cos, 2: sin, 3: cos^2, 4: cos sin, 5: sin^2
    o = _OneCase()
    o.F = [fa[0], fr[1], fr[2], far[2], -far[1]]
    o.J = [[Wzz[0], Wzx[1], Wzx[2], Wzz[2], -Wzz[1]],
           [Wxz[1], Wxx[3], Wxx[4], Wxz[4], -Wxz[3]],
           [Wxz[2], Wxx[4], Wxx[5], Wxz[5], -Wxz[4]],
           [Wzzr[2], Wzxr[4], Wzxr[5], Wzzr[5], -Wzzr[4]],
           [-Wzzr[1], -Wzxr[3], -Wzxr[4], -Wzzr[4], Wzzr[3]]]
    o.x, o.z, o.s, o.c, o.sn = x, z, s, c, sn
    o.delta, o.Kn, o.dlnK, o.Q = delta, Kn, dlnK, P[3]
    return o


def _jacobian(model, geo, st, arm):
    """Analytic dF/du (N,5,5) of the ball resultant (chain rule through x_j, z_j, beta_j)."""
    c, sn, s, Q, Kn = st.c, st.sn, st.s, st.Q, st.Kn
    k15 = 1.5 * Kn * np.sqrt(st.delta)
    qk = Q * st.dlnK / s
    dQx = k15 * c - qk * sn                       # dQ/dx
    dQz = k15 * sn + qk * c                       # dQ/dz
    qs = Q / s
    W = np.empty(c.shape + (2, 2))
    W[..., 0, 0] = dQx * c + qs * sn * sn         # d(Q cos b)/dx
    W[..., 0, 1] = dQz * c - qs * c * sn          # d(Q cos b)/dz
    W[..., 1, 0] = dQx * sn - qs * c * sn         # d(Q sin b)/dx
    W[..., 1, 1] = dQz * sn + qs * c * c          # d(Q sin b)/dz
    if arm == "groove":                           # F = sum gx fr + gz fa
        Z = geo.G.shape[0]
        WG = (W @ geo.G).reshape(c.shape[0], 2 * Z, 5)      # (N, 2Z, 5)
        return geo.G.reshape(2 * Z, 5).T @ WG
    # contact arm: F = sum gx fr + m fa, m = (1, 0, 0, r sin psi, -r cos psi), r = r(beta)
    gx, gz, cp, sp = geo.gx, geo.gz, geo.cp, geo.sp
    r = 0.5 * (model.dm - model.D * c)
    m = np.zeros(c.shape + (5,))
    m[..., 0], m[..., 3], m[..., 4] = 1.0, r * sp, -r * cp
    J = np.einsum("zi,nz,zj->nij", gx, W[..., 0, 0], gx) + np.einsum("zi,nz,zj->nij", gx, W[..., 0, 1], gz)
    J += np.einsum("nzi,nz,zj->nij", m, W[..., 1, 0], gx) + np.einsum("nzi,nz,zj->nij", m, W[..., 1, 1], gz)
    # d m / d beta = (0,0,0, r' sin psi, -r' cos psi), r' = D sin(beta)/2
    w = Q * sn * 0.5 * model.D * sn                 # fa * r'
    dm_ = np.zeros(c.shape + (5,))
    dm_[..., 3], dm_[..., 4] = w * sp, -w * cp
    J += np.einsum("nzi,nz,zj->nij", dm_, -sn / s, gx) + np.einsum("nzi,nz,zj->nij", dm_, c / s, gz)
    return J


def _potential(model, geo, u, Kn, F):
    """Frozen-stiffness potential sum 2/5 K delta^2.5 - F.u (free DOFs), per case."""
    x, _, _, d = geo.xz(u)
    d = np.where(x > 0, np.maximum(d, 0.0), 0.0)
    return 0.4 * (Kn * d * d * np.sqrt(d)).sum(1) - (F * u).sum(1)


def _masked(J, fixed, sc, mu):
    """Scaled Jacobian with imposed DOFs replaced by identity rows/columns, plus mu I."""
    Js = J / sc[None, :, None] / sc[None, None, :]
    Js = np.where(fixed[:, :, None] | fixed[:, None, :], 0.0, Js)
    diag = np.arange(5)
    Js[:, diag, diag] += np.where(fixed, 1.0, mu[:, None])
    return Js


#: Load-deflection range of the model: contact approach of a ball up to this fraction of D
#: (some ten times the approach at the static-capacity stress of 4.2 GPa).
MAX_APPROACH_RATIO = 0.1


def _overload(model, delta, F):
    """Raise ValueError when a ball approach exceeds the model's load-deflection range."""
    lim = MAX_APPROACH_RATIO * model.D
    d = np.asarray(delta)
    if np.any(d > lim):
        raise ValueError(
            f"the loads {np.asarray(F).tolist()} [N, N m] are beyond the load-deflection range "
            f"of the bearing: a ball approach reaches {float(np.max(d)):.3g} m > "
            f"{MAX_APPROACH_RATIO:g} D = {lim:.3g} m (the static capacity is reached near "
            f"0.01 D)")


def _beyond_groove(model, geo, u, F):
    """ValueError when Newton failed with a ball pressed past 90 deg from the groove bottom.

    With x_j <= 0 and s_j > A the ball would be loaded on the far half of the groove torus,
    which does not exist: the loads need a contact at |beta| >= 90 deg and have no
    equilibrium in the groove (e.g. a thrust against a free-tilting ring with 3 balls).
    """
    x, _, _, d = geo.xz(np.asarray(u, float).reshape(1, 5))
    if np.any((x <= 0) & (d > 0)):
        raise ValueError(
            f"the loads {np.asarray(F).tolist()} [N, N m] have no equilibrium within the "
            "grooves: they need a ball contact at 90 deg or more from the groove bottom "
            "(beyond the range of the model)")


def _newton(model, geo, F, u0, fixed, arm, rtol, max_iter, strict=True):
    """Damped Newton for all N cases at once; returns (u (N,5), iterations (N,), ok (N,)).

    With ``strict`` a case still unconverged after ``max_iter`` iterations raises
    ConvergenceError; otherwise it is returned with ``ok`` False (for a retry)."""
    N = F.shape[0]
    sc = np.array([1.0, 1.0, 1.0, model.Ri, model.Ri])      # moments -> forces at R_i
    free = ~fixed
    F = np.where(free, F, 0.0)
    Fs_ext = np.abs(F / sc).max(1)
    step_max = newton.trust_radius(model.A)                 # trust radius [m]

    def residual(st, idx):
        R = np.where(free[idx], st.F - F[idx], 0.0) / sc
        scale = np.maximum(np.maximum(Fs_ext[idx], st.Q.max(1)), 1e-300)
        return R, np.abs(R).max(1) / scale

    u = u0.copy()
    st = _State(model, geo, u, arm)
    Kn, J, delta, qmax = st.Kn, st.J, st.delta, st.Q.max(1)
    Rs, err = residual(st, np.arange(N))
    iters = np.zeros(N, dtype=int)
    active = np.flatnonzero(~(err <= rtol))
    it = 0
    conv = np.ones(N, dtype=bool)
    best_u, best_err = u.copy(), np.where(np.isnan(err), np.inf, err)
    while active.size:
        if it >= max_iter:
            # a residual at round-off level is convergence: take the best iterate
            active = newton.accept_best(active, u, err, best_u, best_err, rtol)
            if not active.size:
                break
        if it >= max_iter and not strict:
            conv[active] = False
            break
        if it >= max_iter:
            i = active[np.argmax(np.nan_to_num(err[active], nan=np.inf))]
            _overload(model, delta[i], F[i])
            _beyond_groove(model, geo, u[i], F[i])
            raise newton.convergence_error(
                "load distribution", it, err[i], rtol, best=best_err[i],
                measure="relative equilibrium residual",
                context=f"in load case {int(i)}; loads {F[i].tolist()}, displacements "
                        f"{u[i].tolist()}",
                roundoff=newton.roundoff_limit(float(np.abs(u[i] * sc).max()),
                                               float(delta[i].max())),
                roundoff_hint="the largest ball approach is tiny against the ring "
                              "displacement")
        it += 1
        a = active
        ua, Ra, fx = u[a], Rs[a], fixed[a]
        n_free = np.maximum((~fx).sum(1), 1)
        Js = _masked(J[a], fx, sc, np.zeros(a.size))
        # Levenberg floor for unloaded / weak directions: 1e-6 of the geometric stiffness
        # ~ F/A (scales with the load, so light loads still cross clearances quickly)
        mu = newton.levenberg_shift(np.einsum("nii->n", np.where(fx[:, :, None], 0.0, Js)),
                                    np.maximum(Fs_ext[a], qmax[a]), model.A, n_free)
        Js[:, np.arange(5), np.arange(5)] += np.where(fx, 0.0, mu[:, None])
        dS = -np.linalg.solve(Js, Ra[..., None])[..., 0]
        g = (Ra * dS).sum(1)
        if arm == "groove" and np.any(~(g < 0)):
            # not a descent direction of the potential: use the symmetric frozen-K Hessian
            b = np.flatnonzero(~(g < 0))
            sb = _State(model, geo, ua[b], arm, Kn=Kn[a][b])
            Jb = _masked(0.5 * (sb.J + np.swapaxes(sb.J, 1, 2)), fx[b], sc, mu[b])
            dS[b] = -np.linalg.solve(Jb, Ra[b][..., None])[..., 0]
        dS *= newton.clip_factor(np.abs(dS).max(1), step_max)[:, None]
        g = (Ra * dS).sum(1)
        du = dS / sc
        local = err[a] < POLICY.quadratic_region      # quadratic convergence: full steps
        if arm == "groove":
            # Armijo on the frozen-stiffness potential (where every trial fails, this
            # driver ends one halving below the single-case one, at 2^-60)
            Kf, Fa_ = Kn[a], F[a]
            d = delta[a]
            phi0 = 0.4 * (Kf * d * d * np.sqrt(d)).sum(1) - (Fa_ * ua).sum(1)

            def armijo(idx, t):
                ph = _potential(model, geo, ua[idx] + t[:, None] * du[idx], Kf[idx], Fa_[idx])
                return newton.armijo_ok(ph, phi0[idx], t, g[idx])

            ok1 = local.copy()
            ok1[~local] = armijo(np.flatnonzero(~local), np.ones(int((~local).sum())))
            t, _ = newton.backtrack(armijo, ok1, POLICY.potential_halvings + 1)
            unew = ua + t[:, None] * du
            snew = _State(model, geo, unew, arm)
            Rn, en = residual(snew, a)
        else:
            # backtracking on the residual norm (no Armijo term: a NaN residual is taken)
            m0 = (Ra * Ra).sum(1)
            unew = ua + du
            snew = _State(model, geo, unew, arm)
            Rn, en = residual(snew, a)

            def decrease(w, t):
                unew[w] = ua[w] + t[:, None] * du[w]
                sw = _State(model, geo, unew[w], arm)
                Rw, ew = residual(sw, a[w])
                snew.Kn[w], snew.J[w], snew.delta[w], snew.Q[w] = sw.Kn, sw.J, sw.delta, sw.Q
                Rn[w], en[w] = Rw, ew
                return ~((Rw * Rw).sum(1) > m0[w])

            newton.backtrack(decrease, ~(((Rn * Rn).sum(1) > m0) & ~local),
                             POLICY.residual_halvings)
        u[a] = unew
        iters[a] += 1
        # round-off floor: the approach s - A of a lightly loaded ball is resolved only to
        # ~eps |rigid displacement|, so once Newton stops making progress accept
        # max(100 rtol, 20 eps max|du| / delta_max) (Q ~ delta^1.5)
        floor = (en <= newton.roundoff_floor(rtol, snew.delta.max(1),
                                             np.abs(unew * sc).max(1))) & \
            newton.stalled(en, err[a])
        if np.any(floor):
            log.debug("load distribution: %d cases stopped at the round-off floor (max %.2e)",
                      int(floor.sum()), float(en[floor].max()))
        Rs[a], err[a] = Rn, en
        newton.keep_best(best_u, best_err, a, unew, en)
        J[a], Kn[a], delta[a], qmax[a] = snew.J, snew.Kn, snew.delta, snew.Q.max(1)
        active = a[~(en <= rtol) & ~floor]
    if it:
        log.debug("load distribution: %d cases converged in at most %d Newton iterations", N, it)
    return u, iters, conv


_GESV = []

try:                                    # the optional compiled Newton (analytic/_ldkernel.c)
    from . import _ldkernel as _COMPILED
except ImportError:                     # not built (no C compiler at install): NumPy only
    _COMPILED = None
if os.environ.get("BALLRACE_NO_COMPILED"):
    _COMPILED = None


def _compiled_pack(model, geo):
    """The float64 buffer the compiled Newton reads (see analytic/_ldkernel.c), built once
    per _Geo: Z, the table length, R_i, A, x_0, z_0, g_0, K_n at the reference angle,
    d_e / (2 R_i) and D / (2 R_i) (the contact arm), the ball azimuths' cosines and sines
    and the K_n table (derivative column times -2)."""
    if geo.cpack is None:
        tab = model.table * np.array([1.0, -2.0])
        head = [float(model.Z), float(tab.shape[0]), model.Ri, model.A, geo.x0, geo.z0,
                geo.g0, _kseat(model, geo), 0.5 * model.dm / model.Ri, 0.5 * model.D / model.Ri]
        geo.cpack = np.ascontiguousarray(np.concatenate([head, geo.cp, geo.sp, tab.ravel()]))
    return geo.cpack


def _gesv(A, b):
    """Solve A x = b (5 x 5 nested lists) by LAPACK's gesv (LU with partial pivoting).

    ``numpy.linalg.LinAlgError`` if A is singular or the solution is not finite.
    scipy.linalg is imported on first use.
    """
    if not _GESV:
        from scipy.linalg import lapack
        _GESV.append(lapack.dgesv)
    x, info = _GESV[0](np.array(A), np.array(b))[2:]
    x = x.tolist()
    if info != 0 or not -np.inf < sum(x) < np.inf:
        raise np.linalg.LinAlgError("Singular matrix")
    return x


def _newton_one(model, geo, F, u0, fixed, arm, rtol, max_iter):
    """`_newton` for a single load case, with scalar control flow.

    The same iteration -- scaled Newton step with the Levenberg floor, the symmetric
    frozen-stiffness fallback, the trust radius, the Armijo search on the frozen-stiffness
    potential ("groove" arm) or on the residual norm ("contact" arm), the round-off floor --
    without the vectorized driver's active-set indexing, on the one-case kernel
    (:func:`_one_case`, which returns the scaled resultant and Jacobian as Python floats),
    with the five-component bookkeeping (residual, Levenberg floor, step) in Python floats
    and the 5 x 5 solve by LAPACK.  Two shortcuts that leave the iterates' meaning alone:
    the full step's state gives its frozen-stiffness potential (``_potential`` runs only
    when the Armijo test rejects it), and from the touching reference configuration
    (u = 0, every ball at zero approach, no stiffness) the first step's length is the
    minimiser of the frozen potential along it with the approaches linearised,
    t^(3/2) = F.du / sum K_n <b_j>^(5/2), b_j = d(approach_j)/du . du (the homogeneous
    Hertz law), instead of halving from the trust radius.  ``tests/test_loaddist.py``
    checks that both drivers agree.  Returns (u (1,5), iterations (1,), final _OneCase).

    With the optional compiled module (``analytic/_ldkernel.c``, built at install time when
    a C compiler is present; ``BALLRACE_NO_COMPILED=1`` switches it off) the same iteration
    runs in C first and only proposes the equilibrium: the NumPy kernel is evaluated there
    and this iteration goes on from it while the residual is above ``rtol`` (in practice
    it stops at once), so every check and every reported number is this module's.  Cases
    the compiled iteration leaves (a ball at cos(beta) < 0, a non-descent step, no
    convergence within ``max_iter``) are solved here from the original start.
    ``tests/test_speed_paths.py`` compares both paths.
    """
    Ri = float(model.Ri)
    sc = (1.0, 1.0, 1.0, Ri, Ri)
    fx = [bool(v) for v in fixed[0]]
    anyfixed = any(fx)
    n_free = max(5 - sum(fx), 1)
    F = [0.0 if fx[i] else float(v) for i, v in enumerate(F[0])]
    Fsx = [F[0], F[1], F[2], F[3] / Ri, F[4] / Ri]            # applied, scaled
    Fs_ext = max(abs(Fsx[0]), abs(Fsx[1]), abs(Fsx[2]), abs(Fsx[3]), abs(Fsx[4]))
    step_max = newton.trust_radius(model.A)
    lev = POLICY.levenberg_geometric / model.A
    R5 = range(5)

    def residual(o):
        Fo = o.F
        R = [Fo[0] - Fsx[0], Fo[1] - Fsx[1], Fo[2] - Fsx[2], Fo[3] - Fsx[3], Fo[4] - Fsx[4]]
        if anyfixed:
            R = [0.0 if fx[i] else R[i] for i in R5]
        qmax = max(o.Q.tolist())
        return R, max(abs(R[0]), abs(R[1]), abs(R[2]), abs(R[3]), abs(R[4])) / \
            max(Fs_ext, qmax, 1e-300), qmax

    def scaled(J, mu):
        Js = [J[0][:], J[1][:], J[2][:], J[3][:], J[4][:]]
        if anyfixed:
            for i in R5:
                for j in R5:
                    if fx[i] or fx[j]:
                        Js[i][j] = 0.0
        if mu is None:                                    # Levenberg floor (see _newton)
            mu = newton.levenberg_shift_one(Js[0][0] + Js[1][1] + Js[2][2] + Js[3][3] + Js[4][4],
                                            n_free, max(Fs_ext, qmax), lev)
        if anyfixed:
            for i in R5:
                Js[i][i] += 1.0 if fx[i] else mu
        else:
            Js[0][0] += mu
            Js[1][1] += mu
            Js[2][2] += mu
            Js[3][3] += mu
            Js[4][4] += mu
        return Js, mu

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] + a[4] * b[4]

    def step(u, t, d):
        return [u[0] + t * d[0], u[1] + t * d[1], u[2] + t * d[2], u[3] + t * d[3],
                u[4] + t * d[4]]

    u = u0[0].tolist()
    seat = geo.g0 == 0 and not any(u) and Fs_ext > 0
    it0 = 0
    if _COMPILED is not None and model.table is not None:
        # the compiled iteration proposes the equilibrium; the NumPy kernel below checks it
        # (and iterates on if its residual is above rtol); any other status: NumPy alone
        status, it0, uc = _COMPILED.newton_one(_compiled_pack(model, geo), F,
                                               [1.0 if v else 0.0 for v in fx], u, rtol,
                                               min(max_iter, 2**31 - 1), seat,
                                               arm == "contact")
        if status == 0:
            u, seat, max_iter = list(uc), False, max_iter - it0
        else:
            it0 = 0
    if seat:                    # touching reference, u = 0: no ball loaded, no stiffness
        st = _one_case_seated(model, geo)
    else:
        st = _one_case(model, geo, u, arm)
    R, err, qmax = residual(st)
    best = (err if err == err else np.inf, u, st)
    it = 0
    while not err <= rtol:
        if it >= max_iter:
            if best[0] <= newton.roundoff_cap(rtol):    # round-off level: the best iterate
                err, u, st = best
                break
            raise newton.convergence_error(
                "load distribution", it, err, rtol, best=best[0],
                measure="relative equilibrium residual",
                context=f"in load case 0; loads {F}, displacements {u}",
                roundoff=newton.roundoff_limit(max(abs(v * s) for v, s in zip(u, sc)),
                                               max(st.delta.tolist())),
                roundoff_hint="the largest ball approach is tiny against the ring "
                              "displacement")
        it += 1
        Js, mu = scaled(st.J, None)
        x = _gesv(Js, R)
        dS = [-x[0], -x[1], -x[2], -x[3], -x[4]]
        if arm == "groove" and not dot(R, dS) < 0.0:
            sb = _State(model, geo, np.array(u)[None], arm, Kn=st.Kn[None])
            Jsym = (0.5 * (sb.J[0] + sb.J[0].T)).tolist()
            Jb, _ = scaled([[Jsym[i][j] / (sc[i] * sc[j]) for j in R5] for i in R5], mu)
            dS = [-v for v in _gesv(Jb, R)]
        size = max(abs(dS[0]), abs(dS[1]), abs(dS[2]), abs(dS[3]), abs(dS[4]))
        if seat and it == 1:
            # exact line minimiser of the linearised frozen potential (see above)
            du = [dS[0], dS[1], dS[2], dS[3] / Ri, dS[4] / Ri]
            dxz = np.dot(geo.G2, du)
            Z = st.c.size
            b = np.maximum(dxz[:Z] * st.c + dxz[Z:] * st.sn, 0.0)
            den = float(np.dot(st.Kn, b * b * np.sqrt(b)))
            num = dot(F, du)
            if den > 0.0 and num > 0.0:
                f = (num / den) ** (2.0 / 3.0)
                dS = [v * f for v in dS]
                size *= f
        f = newton.clip_factor(size, step_max)
        if f != 1.0:
            dS = [v * f for v in dS]
        g = dot(R, dS)
        du = [dS[0], dS[1], dS[2], dS[3] / Ri, dS[4] / Ri]
        local = err < POLICY.quadratic_region
        unew = step(u, 1.0, du)
        snew = _one_case(model, geo, unew, arm)
        if arm == "groove":
            # the full step's state gives its frozen-stiffness potential (the same
            # approaches as _potential); backtrack with _potential only if it is rejected
            if not local:
                Kf = st.Kn
                phi0 = 0.4 * float(np.dot(st.Q, st.delta)) - dot(F, u)
                dn = snew.delta
                ph1 = 0.4 * float(np.dot(Kf, dn * dn * np.sqrt(dn))) - dot(F, unew)

                def armijo(t):
                    if t == 1.0:
                        return newton.armijo_ok(ph1, phi0, t, g)
                    ut = np.array(step(u, t, du))[None]
                    ph = float(_potential(model, geo, ut, Kf[None], np.array(F)[None])[0])
                    return newton.armijo_ok(ph, phi0, t, g)

                t, _ = newton.backtrack_one(armijo, POLICY.potential_halvings)
                if t != 1.0:
                    unew = step(u, t, du)
                    snew = _one_case(model, geo, unew, arm)
            Rn, en, qn = residual(snew)
        else:
            m0 = dot(R, R)
            Rn, en, qn = residual(snew)
            if not local:
                def decrease(t):
                    nonlocal unew, snew, Rn, en, qn
                    if t != 1.0:
                        unew = step(u, t, du)
                        snew = _one_case(model, geo, unew, arm)
                        Rn, en, qn = residual(snew)
                    return dot(Rn, Rn) <= m0

                newton.backtrack_one(decrease, POLICY.residual_halvings)
        umx = max(abs(unew[0]), abs(unew[1]), abs(unew[2]), abs(unew[3] * Ri),
                  abs(unew[4] * Ri))
        floor = newton.roundoff_floor(rtol, max(snew.delta.tolist()), umx) >= en and \
            newton.stalled(en, err)
        u, st, R, err, qmax = unew, snew, Rn, en, qn
        if err < best[0]:
            best = (err, u, st)
        if floor and not err <= rtol:
            log.debug("load distribution: stopped at the round-off floor (%.2e)", err)
            break
    if it or it0:
        log.debug("load distribution: converged in %d Newton iterations (%d compiled)",
                  it + it0, it0)
    return np.array(u)[None], np.array([it + it0]), st


# =========================================================================== results
@dataclass(frozen=True)
class LoadDistribution:
    """Static load distribution of a ball bearing (frozen; leading axes = load cases).

    Attributes
    ----------
    bearing : BallBearing
        The bearing.
    azimuths : ndarray, shape (Z,)
        Ball azimuths psi_j from +y towards +z [rad].
    displacements : ndarray, shape (..., 5)
        Inner-ring displacement (dx, dy, dz [m], theta_y, theta_z [rad]) from the reference
        configuration (see ``axial_offset``).
    loads : ndarray, shape (..., 5)
        Resultant of the ball forces on the inner ring (Fa, Fy, Fz [N], My, Mz [N m]):
        the applied loads on free DOFs, the reactions on imposed ones.
    applied : ndarray, shape (..., 5)
        Applied loads (zero on imposed DOFs) [N, N m].
    imposed : ndarray of bool, shape (..., 5)
        DOFs whose displacement was imposed.
    ball_loads : ndarray, shape (..., Z)
        Ball normal loads Q_j [N] (0 for unloaded balls).
    contact_angles : ndarray, shape (..., Z)
        Contact angles beta_j [rad]; for an unloaded ball the angle of the line joining
        the groove centres (Ricci 2009 convention).
    stiffness : ndarray, shape (..., 5, 5)
        Tangent stiffness d(loads)/d(displacements) [N/m, N/rad, N m/m, N m/rad].
    clearance : float
        Diametral clearance P_d of the reference configuration [m] (negative: interference).
    axial_offset : float
        Axial offset z_0 of the groove centres in the reference configuration [m]:
        A sin(beta_f) (balls just touching; H&D 1981 eq. 3.61) or 0 (centred).
    moment_arm : str
        ``"groove"`` or ``"contact"`` (see the module notes).
    iterations : int
        Newton iterations (largest over the load cases).
    """

    bearing: BallBearing
    azimuths: np.ndarray
    displacements: np.ndarray
    loads: np.ndarray
    applied: np.ndarray
    imposed: np.ndarray
    ball_loads: np.ndarray
    contact_angles: np.ndarray
    stiffness: np.ndarray
    clearance: float
    axial_offset: float
    moment_arm: str = "groove"
    iterations: int = 0
    method: str = field(default="exact", repr=False)

    # ------------------------------------------------------------------ scalars
    @property
    def max_ball_load(self):
        """Largest ball load Q_max [N]."""
        return hertz.scalar_result(np.max(self.ball_loads, axis=-1))

    @property
    def residual(self):
        """Equilibrium residual loads - applied on free DOFs (0 on imposed ones) [N, N m]."""
        return np.where(self.imposed, 0.0, self.loads - self.applied)

    @property
    def relative_residual(self):
        """max |residual| (moments / R_i) over max(|applied|, Q_max) [-]."""
        sc = np.array([1.0, 1.0, 1.0, 1.0, 1.0])
        sc[3:] = self.bearing.inner_groove_center_radius
        r = np.abs(self.residual / sc).max(-1)
        scale = np.maximum(np.abs(self.applied / sc).max(-1), self.max_ball_load)
        return hertz.scalar_result(np.where(scale > 0, r / np.where(scale > 0, scale, 1.0), r))

    @property
    def axial_deflection(self):
        """Axial deflection of the bearing: the inner ring's displacement dx relative to the
        outer ring from the reference configuration [m]."""
        return hertz.scalar_result(self.displacements[..., 0])

    @property
    def radial_deflection(self):
        """Radial deflection of the bearing sqrt(dy^2 + dz^2) [m] (inner ring relative to
        the outer ring, from the reference configuration)."""
        return hertz.scalar_result(np.hypot(self.displacements[..., 1],
                                            self.displacements[..., 2]))

    @property
    def misalignment(self):
        """Tilt of the inner ring sqrt(theta_y^2 + theta_z^2) [rad]."""
        return hertz.scalar_result(np.hypot(self.displacements[..., 3], self.displacements[..., 4]))

    @property
    def max_pressure(self):
        """Largest contact pressure p_max over the balls and both races [Pa] (per case)."""
        return hertz.scalar_result(np.maximum(np.max(np.asarray(self.inner.p_max), axis=-1),
                                        np.max(np.asarray(self.outer.p_max), axis=-1)))

    @property
    def static_safety(self):
        r"""Static safety of the most loaded contact, s0 = (4200 MPa / p_max)^3 [-] (per case).

        From the actual largest contact pressure (inner or outer race; clearance, preload,
        moment and tilt included) by
        :func:`~ballrace.analytic.ratings.static_safety_from_pressure` (ISO 76:2006 bases
        C0 on 4200 MPa); inf without load.  The solvers warn when it is below 1.  Unlike
        the catalogue check C0/P0 (:func:`~ballrace.analytic.ratings.static_safety_factor`,
        P0 = X0 Fr + Y0 Fa) it sees the load distribution the bearing really has.
        """
        from .ratings import static_safety_from_pressure
        return hertz.scalar_result(static_safety_from_pressure(self.max_pressure))

    @functools.cached_property
    def loaded_zone(self):
        r"""Half-angle psi_l of the loaded arc [rad], in [0, pi].

        Half the angular measure of the azimuths at which a ball would be loaded,
        s(psi) > A, on the continuous pitch circle; for radial load
        psi_l = arccos(P_d / 2 delta_r) (Hamrock & Dowson 1981 eq. 3.43), for eccentric
        thrust psi_l = arccos(-delta_a / R_i theta) (Ricci 2009 eq. 21).
        """
        model = _Model.of(self.bearing)
        u = self.displacements.reshape(-1, 5)
        x0 = model.A - 0.5 * self.clearance
        return hertz.scalar_result(_loaded_zone(model, x0, self.axial_offset, u)
                             .reshape(self.displacements.shape[:-1]))

    # ------------------------------------------------------------------ contacts
    @functools.cached_property
    def inner(self) -> hertz.HertzContact:
        """Hertz contacts of the balls on the inner race (a, b, p_max, ...) per ball."""
        return self.bearing.contacts(self.ball_loads, self.contact_angles, "inner", self.method)

    @functools.cached_property
    def outer(self) -> hertz.HertzContact:
        """Hertz contacts of the balls on the outer race per ball."""
        return self.bearing.contacts(self.ball_loads, self.contact_angles, "outer", self.method)

    @functools.cached_property
    def inner_shear(self):
        """Lundberg–Palmgren orthogonal shear (.tau0 [Pa], .z0 [m]) under the inner contacts.

        Computed on first access by :func:`ballrace.analytic.subsurface.orthogonal_shear`
        (Hamrock & Dowson 1981 eqs. 3.19–3.27).
        """
        from .subsurface import orthogonal_shear
        return orthogonal_shear(self.inner)

    @functools.cached_property
    def outer_shear(self):
        """Lundberg–Palmgren orthogonal shear (.tau0 [Pa], .z0 [m]) under the outer contacts."""
        from .subsurface import orthogonal_shear
        return orthogonal_shear(self.outer)

    def truncation_margin(self, race: str):
        r"""Angular margin of the contact ellipse to the shoulder edge [rad].

        .. math:: \theta_s - \left(|\beta| + \arcsin\frac{a}{f D}\right)

        negative where the contact ellipse runs over the shoulder (truncated);
        Hamrock & Dowson (1981) eqs. (3.57)–(3.58).  ``None`` if that shoulder height
        was not given.  Unloaded balls get ``theta_s - |beta|``.

        Parameters
        ----------
        race : {"inner", "outer"}
            Which race.
        """
        theta_s = self.bearing.shoulder_angle(race)
        if theta_s is None:
            return None
        c = self.inner if race == "inner" else self.outer
        f = self.bearing.f_inner if race == "inner" else self.bearing.f_outer
        half = np.arcsin(np.clip(np.asarray(c.a) / (f * self.bearing.ball_diameter), 0.0, 1.0))
        return hertz.scalar_result(theta_s - (np.abs(self.contact_angles) + half))

    def truncated(self, race: str):
        """Per ball: True where the contact ellipse runs over the shoulder (``None`` if no
        shoulder height was given); see :meth:`truncation_margin`."""
        m = self.truncation_margin(race)
        return None if m is None else hertz.scalar_result((np.asarray(m) < 0) & (self.ball_loads > 0))


def _loaded_zone(model, x0, z0, u):
    """Half measure of {psi : s(psi) > A} for each case (grid + ball azimuths, bisection)."""
    N = u.shape[0]
    psi_b = np.mod(2.0 * np.pi * np.arange(model.Z) / model.Z, 2 * np.pi)
    grid = np.unique(np.concatenate([np.linspace(0.0, 2 * np.pi, 1441)[:-1], psi_b]))
    grid = np.append(grid, 2 * np.pi)
    extra = np.mod(np.arctan2(u[:, 2], u[:, 1]), 2 * np.pi)      # direction of radial shift

    g0 = 0.0 if z0 > 0 else (x0 - model.A) * (x0 + model.A)

    def f(psi, uu):          # s(psi) - A without cancellation (see _Geo.xz); x > 0 only
        dx = uu[:, 1:2] * np.cos(psi) + uu[:, 2:3] * np.sin(psi)
        dz = uu[:, 0:1] + model.Ri * (uu[:, 3:4] * np.sin(psi) - uu[:, 4:5] * np.cos(psi))
        return np.where(x0 + dx > 0, g0 + dx * (2.0 * x0 + dx) + dz * (2.0 * z0 + dz), -1.0)

    g = np.sort(np.concatenate([np.broadcast_to(grid, (N, grid.size)), extra[:, None]], 1), 1)
    v = f(g, u)
    pos = v > 0
    lo, hi = g[:, :-1], g[:, 1:]
    plo, phi = pos[:, :-1], pos[:, 1:]
    measure = np.where(plo & phi, hi - lo, 0.0).sum(1)
    ci, cj = np.nonzero(plo != phi)
    if ci.size:
        a, b = lo[ci, cj].copy(), hi[ci, cj].copy()
        la = plo[ci, cj]
        uu = u[ci]
        for _ in range(55):
            mid = 0.5 * (a + b)
            pm = f(mid[:, None], uu)[:, 0] > 0
            same = pm == la
            a = np.where(same, mid, a)
            b = np.where(same, b, mid)
        r = 0.5 * (a + b)
        part = np.where(la, r - lo[ci, cj], hi[ci, cj] - r)
        np.add.at(measure, ci, part)
    return 0.5 * measure


# =========================================================================== public solvers
def fold_unloaded(beta, Q):
    """Contact angles with those of unloaded balls folded into (-pi/2, pi/2] [rad].

    An unloaded ball reports the angle of its line of groove centres (a line has no sense,
    so atan2's pi on the far side becomes 0).  Loaded balls have x > 0 and |beta| <= pi/2
    already; they are left alone, so a loaded ball at beta = -pi/2 in floating point keeps
    its sign (and its thrust).

    Parameters
    ----------
    beta : array_like
        Contact angles [rad].
    Q : array_like
        Ball loads [N] (same shape).
    """
    unl = ~(np.asarray(Q) > 0)
    beta = np.where(unl & (np.abs(beta) > 0.5 * np.pi), beta - np.copysign(np.pi, beta), beta)
    return np.where(unl & (beta <= -0.5 * np.pi), beta + np.pi, beta)


_fold_unloaded = fold_unloaded


def _plain(v) -> bool:
    """A plain finite float (or moderate int, not bool) within the load bound 1e30."""
    t = type(v)
    return (t is float or t is np.float64 or (t is int and -(2**53) <= v <= 2**53)) and \
        -MAX_MAGNITUDE <= v <= MAX_MAGNITUDE


def _loads_array(Fa, Fy, Fz, My, Mz):
    if _plain(Fa) and _plain(Fy) and _plain(Fz) and _plain(My) and _plain(Mz):
        return np.array([Fa, Fy, Fz, My, Mz], dtype=float)    # what the checks would give
    arrs = [as_array(v, n, bounded=True, tiny_ok=True)
            for v, n in ((Fa, "Fa"), (Fy, "Fy"), (Fz, "Fz"), (My, "My"), (Mz, "Mz"))]
    b = np.broadcast_arrays(*arrs)
    return np.stack(b, axis=-1)


def _check_loads(model, L):
    """ValueError if applied loads (N, 5) exceed what Z balls can carry in the model's range.

    Every component of the resultant is at most sum Q_j <= Z K_max (0.1 D)^1.5 (moments
    over the largest arm, max(R_i, (d_e + D)/2)).
    """
    arm = max(model.Ri, 0.5 * (model.dm + model.D))
    cap = model.capacity
    if type(L) is np.ndarray and L.shape == (1, 5):          # one case: Python floats
        a, b, c, d, e = L[0].tolist()
        if max(abs(a), abs(b), abs(c), abs(d) / arm, abs(e) / arm) <= cap:
            return
    Fm = np.abs(np.asarray(L, float) / np.array([1.0, 1.0, 1.0, arm, arm])).max(-1)
    if np.any(Fm > cap):
        i = int(np.argmax(Fm))
        raise ValueError(
            f"the loads {np.asarray(L).reshape(-1, 5)[i].tolist()} [N, N m] are beyond the "
            f"load-deflection range of the bearing: {model.Z} balls carry at most "
            f"{cap:.4g} N (moments over the arm {arm:.4g} m) at a contact approach of "
            f"{MAX_APPROACH_RATIO:g} D")


def check_load_range(bearing: BallBearing, loads) -> None:
    """ValueError if loads exceed what the bearing's balls carry within the model's range
    (:data:`MAX_APPROACH_RATIO`): the same check and words as :func:`solve`.

    Parameters
    ----------
    bearing : BallBearing
        Single-row bearing.
    loads : array_like
        (Fa, Fy, Fz [N], My, Mz [N m]), shape (5,) or (N, 5).
    """
    _check_loads(_Model.of(bearing), np.reshape(np.asarray(loads, float), (-1, 5)))


def _result(bearing, model, psi, x0, z0, Pd, u, applied, imposed, arm, iters, shape, method,
            state=None, rtol=1e-12, what="load distribution"):
    """Build the LoadDistribution, after checking what is returned.

    Raises ConvergenceError if any value is not finite or the relative equilibrium residual
    exceeds newton.roundoff_cap(rtol) = max(1e-9, 100 rtol); ValueError if a ball approach
    is beyond the load-deflection range.  Unloaded balls report the angle of the line of groove centres
    folded into (-pi/2, pi/2] (the line, not its direction).
    """
    if type(state) is _OneCase:
        return _result_one(bearing, model, psi, z0, Pd, u, applied, imposed, arm, iters, shape,
                           method, state, rtol, what)
    st = _State(model, _Geo(model, psi, x0, z0), u, arm) if state is None else state
    Z = model.Z
    app = np.where(imposed, 0.0, applied)
    sc = np.array([1.0, 1.0, 1.0, model.Ri, model.Ri])
    with np.errstate(invalid="ignore", over="ignore"):
        res = np.abs(np.where(imposed, 0.0, st.F - app) / sc).max(-1)
        scale = np.maximum(np.abs(app / sc).max(-1), st.Q.max(-1))
        rel = np.where(scale > 0, res / np.where(scale > 0, scale, 1.0), res)
    finite = np.all(np.isfinite(u), -1) & np.all(np.isfinite(st.F), -1) & \
        np.all(np.isfinite(st.Q), -1) & np.all(np.isfinite(st.J.reshape(len(u), -1)), -1)
    tol = newton.roundoff_cap(rtol)
    bad = ~finite | ~(rel <= tol)
    dmax = np.where(finite, st.delta.max(-1), 0.0)
    _overload(model, dmax.max(), app[int(np.argmax(dmax))])
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ConvergenceError(
            f"{what} did not reach equilibrium: relative residual {rel[i]:.3e} "
            f"(> {tol:g}) after {int(np.max(iters, initial=0))} iterations in load case {i}; "
            f"loads {app[i].tolist()}, displacements {u[i].tolist()}")
    beta = _fold_unloaded(st.beta, st.Q)
    return _checked(LoadDistribution(
        bearing=bearing, azimuths=psi,
        displacements=u.reshape(shape + (5,)), loads=st.F.reshape(shape + (5,)),
        applied=app.reshape(shape + (5,)),
        imposed=imposed.reshape(shape + (5,)),
        ball_loads=st.Q.reshape(shape + (Z,)), contact_angles=beta.reshape(shape + (Z,)),
        stiffness=st.J.reshape(shape + (5, 5)), clearance=float(Pd), axial_offset=float(z0),
        moment_arm=arm, iterations=int(np.max(iters, initial=0)), method=method))


def _result_one(bearing, model, psi, z0, Pd, u, applied, imposed, arm, iters, shape, method,
                o, rtol, what):
    """:func:`_result` for one case solved by :func:`_newton_one` (its final _OneCase
    ``o``): the same checks and the same LoadDistribution, on Python floats."""
    Ri = model.Ri
    sc = (1.0, 1.0, 1.0, Ri, Ri)
    imp = imposed.reshape(5).tolist()
    app = [0.0 if imp[i] else v for i, v in enumerate(applied.reshape(5).tolist())]
    Fs, Jl, ul = o.F, o.J, u.reshape(5).tolist()
    Ql = o.Q.tolist()
    res = max(0.0 if imp[i] else abs(Fs[i] - app[i] / sc[i]) for i in range(5))
    scale = max(max(abs(app[i] / sc[i]) for i in range(5)), max(Ql))
    rel = res / scale if scale > 0 else res
    finite = math.isfinite(sum(ul) + sum(Fs) + sum(Ql) + sum(sum(r) for r in Jl))
    tol = newton.roundoff_cap(rtol)
    dmax = max(o.delta.tolist()) if finite else 0.0
    if dmax > MAX_APPROACH_RATIO * model.D:
        _overload(model, dmax, np.array(app))
    if not (finite and rel <= tol):
        raise ConvergenceError(
            f"{what} did not reach equilibrium: relative residual {rel:.3e} "
            f"(> {tol:g}) after {int(np.max(iters, initial=0))} iterations in load case 0; "
            f"loads {app}, displacements {ul}")
    beta = np.arctan2(o.z, o.x)
    if not (min(beta.tolist()) > -0.5 * np.pi and max(beta.tolist()) <= 0.5 * np.pi):
        beta = _fold_unloaded(beta, o.Q)
    J = _unscaled_J(Jl, Ri)
    Z = model.Z
    return _checked(LoadDistribution(
        bearing=bearing, azimuths=psi, displacements=u.reshape(shape + (5,)),
        loads=np.array([Fs[0], Fs[1], Fs[2], Fs[3] * Ri, Fs[4] * Ri]).reshape(shape + (5,)),
        applied=np.array(app).reshape(shape + (5,)), imposed=imposed.reshape(shape + (5,)),
        ball_loads=o.Q.reshape(shape + (Z,)), contact_angles=beta.reshape(shape + (Z,)),
        stiffness=J.reshape(shape + (5, 5)), clearance=float(Pd), axial_offset=float(z0),
        moment_arm=arm, iterations=int(iters[0]), method=method))


def _checked(r: LoadDistribution) -> LoadDistribution:
    """``r``, after warning (UserWarning, once per check) where the bearing works beyond its
    limits: static safety s0 < 1 (:attr:`LoadDistribution.static_safety`), a deep-groove
    bearing beyond :data:`~ballrace.analytic.ratings.DEEP_GROOVE_ANGLE_LIMIT`, a tilt
    beyond :data:`~ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT` that an applied
    moment caused (not one the caller imposed, nor the zero-moment tilt of a free ring)."""
    from . import _operating as op

    if op.silenced():
        return r
    what = "load distribution"
    safety = None
    if op.may_be_overloaded(r.bearing, r.ball_loads):
        safety = op.safety_message(what, r.static_safety, r.max_pressure)
    tilt = None
    # An imposed tilt is the caller's choice; a free ring under no moment takes whatever tilt
    # makes its moment zero, an artefact of that boundary condition (a shaft holds it): only
    # a tilt caused by an applied moment is the bearing's.
    free = ~np.asarray(r.imposed[..., 3:], bool)
    if np.any(free & (np.asarray(r.applied[..., 3:]) != 0.0)):
        tilt = op.tilt_message(what, r.bearing, r.misalignment)
        if tilt:
            tilt += ("; the ring is free to tilt here: where a shaft holds it, impose its tilt "
                     "(displacements) or solve the shaft (ballrace.analytic.shaft)")
    op.emit(safety, op.angle_message(what, r.bearing, r.ball_loads, r.contact_angles), tilt)
    return r


def solve(bearing: BallBearing, Fa=0.0, Fy=0.0, Fz=0.0, My=0.0, Mz=0.0, *, displacements=None,
          clearance=None, azimuth_offset: float = 0.0, moment_arm: str = "groove",
          rtol: float = 1e-12, max_iter: int = 200, initial=None) -> LoadDistribution:
    r"""General five-degree-of-freedom static load distribution (rigid rings, exact Hertz).

    Solves, for the inner-ring displacement u = (dx, dy, dz, theta_y, theta_z), the
    equilibrium of the module equations (Jones 1960; Harris 2001 §7.4; Hamrock & Dowson
    1981 eqs. 3.61–3.74 generalised to five DOFs; Ricci 2009 eqs. 26–31):

    .. math:: \sum_j Q_j(u)\,\frac{\partial \delta_{n,j}}{\partial u} = F,
              \qquad Q_j = K_n(\beta_j)\,\langle s_j(u) - A\rangle^{3/2}

    Any DOF can be imposed instead of loaded (misalignment, fixed shaft position): give
    ``displacements`` with numbers for the imposed DOFs and ``None``/NaN for the free
    ones; the reaction appears in ``result.loads``.

    Parameters
    ----------
    bearing : BallBearing
        Single-row bearing.
    Fa : float or array_like
        Axial (thrust) load on the inner ring [N]; positive loads the free-contact-angle
        side.
    Fy, Fz : float or array_like
        Radial loads [N].
    My, Mz : float or array_like
        Tilting moments about y and z [N m] (right-handed: thrust Fa at y = e gives
        Mz = -e Fa).
    displacements : array_like, optional
        Shape (..., 5): imposed (dx, dy, dz [m], theta_y, theta_z [rad]) with ``None`` or
        NaN for free DOFs.  The load on an imposed DOF must be 0.
    clearance : float, optional
        Diametral clearance P_d of the reference configuration [m], < 2A; default the
        bearing's.  Negative means interference (preload).
    azimuth_offset : float, optional
        Azimuth of ball 1 from +y [rad].
    moment_arm : {"groove", "contact"}
        Moment arm of the ball thrust components: R_i (consistent, default) or the
        inner contact radius (d_e - D cos beta)/2 of Ricci (2009) eq. 29.
    rtol : float, optional
        Equilibrium tolerance, relative to max(|applied load|, Q_max) with moments
        divided by R_i [-].
    max_iter : int, optional
        Newton iteration limit.
    initial : array_like, optional
        Starting displacements, shape (..., 5) [m, rad].

    Returns
    -------
    LoadDistribution

    Raises
    ------
    ConvergenceError
        If the equilibrium residual is not below ``rtol`` after ``max_iter`` iterations
        (the message gives the residual, the iteration count and the load case), after a
        second attempt by load continuation; and if what would be returned is not finite
        or has a relative residual above max(1e-9, 100 rtol) (never returned).
    ValueError
        For invalid arguments (named in the message); for loads beyond the
        load-deflection range (a ball approach above :data:`MAX_APPROACH_RATIO` D, or any
        load component above Z K_max (0.1 D)^1.5); and when Newton fails with a ball
        pressed past 90 deg from the groove bottom (no equilibrium within the grooves).

    References
    ----------
    Jones, A.B. (1960) J. Basic Eng. 82(2) 309–320; Harris, T.A. (2001) *Rolling Bearing
    Analysis*, 4th ed., Wiley, §7.4; Hamrock & Dowson (1981) eqs. (3.31)–(3.74);
    Ricci (2009) eqs. (16)–(31).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = solve(brg, Fa=17800.0)
    >>> round(float(np.degrees(r.contact_angles[0])), 3), round(float(r.max_ball_load), 1)
    (41.53, 1677.9)
    >>> r = solve(brg, Fa=17800.0, Fy=8900.0, Mz=-200.0)
    >>> bool(r.relative_residual < 1e-9), round(float(r.max_ball_load))
    (True, 4073)
    """
    return _solve(bearing, Fa, Fy, Fz, My, Mz, displacements=displacements,
                  clearance=clearance, azimuth_offset=azimuth_offset, moment_arm=moment_arm,
                  rtol=rtol, max_iter=max_iter, initial=initial)


def _solve(bearing, Fa=0.0, Fy=0.0, Fz=0.0, My=0.0, Mz=0.0, *, displacements=None,
           clearance=None, azimuth_offset=0.0, moment_arm="groove", rtol=1e-12, max_iter=200,
           initial=None, centered: bool = False, contact_direct: bool = False):
    """:func:`solve`, with the reference configuration centred (``centered``: axial offset 0,
    as :func:`radial` needs) and, for ``moment_arm="contact"``, Newton started directly on
    the contact arm from ``initial`` (``contact_direct``: :func:`eccentric_thrust`)."""
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    check_choice(moment_arm, "moment_arm", MOMENT_ARMS)
    model = _Model.of(bearing)
    L = _loads_array(Fa, Fy, Fz, My, Mz)
    if displacements is None:
        shape = L.shape[:-1]
        L = L.reshape(-1, 5)
        D = None
        imposed = np.zeros(L.shape, dtype=bool)
    else:
        D = np.asarray(displacements, dtype=float)
        if D.shape[-1:] != (5,):
            raise ValueError("displacements must have shape (..., 5): (dx, dy, dz, theta_y, "
                             f"theta_z) with None/NaN for free DOFs; got shape {D.shape}")
        if np.any(np.isinf(D)):
            raise ValueError("displacements must be finite or None/NaN (free) [m, rad]")
        L, D = np.broadcast_arrays(L, D)
        shape = L.shape[:-1]
        L = L.reshape(-1, 5).astype(float)
        D = D.reshape(-1, 5)
        imposed = ~np.isnan(D)
        if np.any(imposed & (L != 0)):
            k = int(np.argwhere(imposed & (L != 0))[0][1])
            raise ValueError(f"the load on DOF {DOF[k]!r} must be 0 when its displacement is "
                             "imposed (the reaction is returned in result.loads)")
    Pd, x0, z0 = _reference(model, clearance, centered)
    geo = _geo(model, bearing, azimuth_offset, x0, z0)
    psi = geo.psi.copy()
    lim = np.array([1.0, 1.0, 1.0, 1.0 / model.Ri, 1.0 / model.Ri]) * model.D
    if D is not None and np.any(np.abs(np.nan_to_num(D)) > lim):
        raise ValueError("imposed displacements must be within +-D = "
                         f"{model.D:g} m (translations) and +-D/R_i = {lim[3]:g} rad (tilts)")
    _check_loads(model, L)
    u0 = np.zeros_like(L)
    if initial is not None:
        u0 = np.broadcast_to(as_array(initial, "initial"), shape + (5,)).reshape(-1, 5).copy()
        if np.any(np.abs(u0) > lim):
            raise ValueError("initial must be within +-D = "
                             f"{model.D:g} m (translations) and +-D/R_i = {lim[3]:g} rad "
                             "(tilts)")
    if D is not None:
        u0 = np.where(imposed, np.nan_to_num(D), u0)
    if not (type(rtol) is float and 0.0 < rtol <= 1e-3):
        rtol = float(check_range(rtol, "rtol", 0.0, 1e-3, high_inclusive=True, unit="-"))
    if not (type(max_iter) is int and max_iter >= 1):
        max_iter = int(check_integer(max_iter, "max_iter", 1))
    return _solve_checked(bearing, model, geo, psi, x0, z0, Pd, L, imposed, u0, shape,
                          moment_arm, rtol, max_iter, moment_arm == "contact" and contact_direct)


def _solve_checked(bearing, model, geo, psi, x0, z0, Pd, L, imposed, u0, shape, moment_arm,
                   rtol, max_iter, direct):
    """The drivers of :func:`solve` on checked inputs: loads L (N, 5), imposed (N, 5),
    start u0 (N, 5) (imposed values in place), result shape ``shape``."""
    st = None
    if L.shape[0] == 1:
        try:
            st = None
            if direct:                  # straight from a close start (eccentric_thrust)
                try:
                    u, iters, st = _newton_one(model, geo, L, u0, imposed, "contact", rtol,
                                               max_iter)
                except ConvergenceError:
                    st = None
            if st is None:
                u, iters, st = _newton_one(model, geo, L, u0, imposed, "groove", rtol, max_iter)
                if moment_arm == "contact":
                    u, it2, st = _newton_one(model, geo, L, u, imposed, "contact", rtol,
                                             max_iter)
                    iters = iters + it2
        except ConvergenceError:
            u, iters = _retry(model, geo, L, u0, imposed, moment_arm, rtol, max_iter,
                              np.zeros(1, bool), u0.copy(), np.zeros(1, int))
            st = None
    elif direct:                        # straight from a close start (eccentric_thrust)
        u, iters, ok = _newton(model, geo, L, u0, imposed, "contact", rtol, max_iter,
                               strict=False)
        if not np.all(ok):
            b = ~ok
            ub, ib, okb = _newton(model, geo, L[b], u0[b], imposed[b], "groove", rtol,
                                  max_iter, strict=False)
            u2, it2, ok2 = _newton(model, geo, L[b][okb], ub[okb], imposed[b][okb], "contact",
                                   rtol, max_iter, strict=False)
            ub[okb], ib[okb] = u2, ib[okb] + it2
            okb[okb] = ok2
            u[b], iters[b], ok[b] = ub, iters[b] + ib, okb
        if not np.all(ok):
            u, iters = _retry(model, geo, L, u0, imposed, moment_arm, rtol, max_iter, ok, u,
                              iters)
    else:
        u, iters, ok = _newton(model, geo, L, u0, imposed, "groove", rtol, max_iter,
                               strict=False)
        if moment_arm == "contact":
            u2, it2, ok2 = _newton(model, geo, L[ok], u[ok], imposed[ok], "contact", rtol,
                                   max_iter, strict=False)
            u[ok], iters[ok] = u2, iters[ok] + it2
            ok[ok] = ok2
        if not np.all(ok):
            u, iters = _retry(model, geo, L, u0, imposed, moment_arm, rtol, max_iter, ok, u,
                              iters)
    return _result(bearing, model, psi, x0, z0, Pd, u, L, imposed, moment_arm, iters, shape,
                   "exact", state=st, rtol=rtol)


def ring_forces(bearing: BallBearing, displacements, *, moment_arm: str = "groove",
                clearance=None, azimuth_offset: float = 0.0):
    r"""Resultant of the ball forces on the inner ring and its tangent stiffness at given
    ring displacements (no equilibrium solve): the inner loop of a shaft-system Newton.

    .. math:: F(u) = \sum_j Q_j(u)\,\frac{\partial \delta_{n,j}}{\partial u}, \qquad
              K(u) = \frac{\partial F}{\partial u}

    with the model of :func:`solve` (same reference configuration, K_n table, moment arm);
    K is analytic (chain rule through each ball's approach and contact angle, including
    dK_n/dbeta), not a finite difference.  ``solve(...).loads`` and ``.stiffness`` are
    these at the equilibrium displacements.

    Parameters
    ----------
    bearing : BallBearing
        Single-row bearing.
    displacements : array_like
        Shape (..., 5): inner-ring (dx, dy, dz [m], theta_y, theta_z [rad]) from the
        reference configuration, within +-D (translations) and +-D/R_i (tilts).
    moment_arm : {"groove", "contact"}
        As in :func:`solve`.
    clearance : float, optional
        Diametral clearance P_d [m], < 2A; default the bearing's.
    azimuth_offset : float, optional
        Azimuth of ball 1 from +y [rad].

    Returns
    -------
    F : ndarray, shape (..., 5)
        (Fa, Fy, Fz [N], My, Mz [N m]) carried by the balls.
    K : ndarray, shape (..., 5, 5)
        dF/du [N/m, N/rad, N m/m, N m/rad].

    References
    ----------
    Jones (1960); Harris (2001) §7.4; Hamrock & Dowson (1981) eqs. (3.61)–(3.74).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = solve(brg, Fa=17800.0, Fy=8900.0, Mz=-200.0)
    >>> F, K = ring_forces(brg, r.displacements)
    >>> bool(np.allclose(F, r.loads, rtol=1e-12) and np.allclose(K, r.stiffness, rtol=1e-12))
    True
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    check_choice(moment_arm, "moment_arm", MOMENT_ARMS)
    model = _Model.of(bearing)
    u = as_array(displacements, "displacements", bounded=True, tiny_ok=True)
    if u.shape[-1:] != (5,):
        raise ValueError("displacements must have shape (..., 5): (dx, dy, dz, theta_y, "
                         f"theta_z); got shape {u.shape}")
    lim = np.array([1.0, 1.0, 1.0, 1.0 / model.Ri, 1.0 / model.Ri]) * model.D
    if np.any(np.abs(u) > lim):
        raise ValueError("displacements must be within +-D = "
                         f"{model.D:g} m (translations) and +-D/R_i = {lim[3]:g} rad (tilts)")
    Pd, x0, z0 = _reference(model, clearance, False)
    geo = _geo(model, bearing, azimuth_offset, x0, z0)
    shape = u.shape[:-1]
    st = _State(model, geo, u.reshape(-1, 5), moment_arm)
    return st.F.reshape(shape + (5,)), st.J.reshape(shape + (5, 5))


class RingModel:
    r"""One ball row at a fixed clearance, as a shaft seat sees it: the
    :class:`~ballrace.analytic.contract.Row` of a :class:`~ballrace.BallBearing`.

    The model of :func:`solve` (exact-Hertz K_n(beta) at each ball's own angle, contact
    angles free, groove moment arm) evaluated at imposed inner-ring displacements, with the
    bearing's model, reference configuration and ball kinematics built once: the fast path
    an outer Newton iteration (:mod:`~ballrace.analytic.shaft`) calls many times.  Two ring
    models of equal bearings at the same clearance compare equal (their rows are evaluated
    together).

    Parameters
    ----------
    bearing : BallBearing
        Single-row bearing.
    clearance : float, optional
        Diametral clearance P_d of the reference configuration [m], < 2A; default the
        bearing's.

    Attributes
    ----------
    reference_axial_offset : float
        z0 of the just-touching reference [m] (0 without clearance); at u_x = -z0 the balls
        sit at the groove bottoms.
    approach_limit : float
        :data:`MAX_APPROACH_RATIO` D [m].
    step_length : float
        Groove curvature-centre distance A [m].
    moment_radius : float
        Inner-groove centre radius R_i [m].

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = solve(brg, Fa=17800.0, Fy=8900.0, Mz=-200.0)
    >>> F, K, dmax, energy = RingModel(brg).ring_forces(r.displacements[None])
    >>> bool(np.allclose(F[0], r.loads, rtol=1e-12))
    True
    """

    __slots__ = ("bearing", "clearance", "_model", "_geo", "reference_axial_offset",
                 "approach_limit", "step_length", "moment_radius", "_key")

    def __init__(self, bearing: BallBearing, clearance=None):
        if not isinstance(bearing, BallBearing):
            raise TypeError(f"bearing must be a ballrace.BallBearing; got "
                            f"{type(bearing).__name__}")
        model = _Model.of(bearing)
        _, x0, z0 = _reference(model, clearance, False)
        self.bearing, self.clearance = bearing, clearance
        self._model = model
        self._geo = _geo(model, bearing, 0.0, x0, z0)
        self.reference_axial_offset = z0
        self.approach_limit = MAX_APPROACH_RATIO * bearing.ball_diameter
        self.step_length = bearing.curvature_center_distance
        self.moment_radius = bearing.inner_groove_center_radius
        self._key = (bearing, clearance)

    def __eq__(self, other):
        return type(other) is RingModel and self._key == other._key

    def __hash__(self):
        return hash(self._key)

    def __repr__(self):
        return f"RingModel({self.bearing!r}, clearance={self.clearance!r})"

    def _state(self, u):
        return _State(self._model, self._geo, np.asarray(u, float).reshape(-1, 5), "groove")

    def ring_forces(self, u):
        """Ball-force resultant on the inner ring, its analytic tangent, largest approach
        and elastic energy at imposed displacements, every DOF imposed (no equilibrium
        iteration); the same numbers as ``solve(bearing, displacements=u,
        clearance=clearance)`` (``.loads``, ``.stiffness``).

        Parameters
        ----------
        u : ndarray, shape (N, 5)
            Inner-ring displacements (dx, dy, dz [m], theta_y, theta_z [rad]).

        Returns
        -------
        F : ndarray, shape (N, 5)
            (Fa, Fy, Fz [N], My, Mz [N m]).
        K : ndarray, shape (N, 5, 5)
            dF/du [N/m, N/rad, N m/m, N m/rad].
        delta_max : ndarray, shape (N,)
            Largest ball approach [m].
        energy : ndarray, shape (N,)
            Elastic energy of the ball contacts, sum 2/5 K_n(beta_j) delta_j^(5/2) [J]
            (the potential of F with K_n held at each ball's angle).
        """
        st = self._state(u)
        d = st.delta
        return st.F, st.J, d.max(1), 0.4 * (st.Kn * d * d * np.sqrt(d)).sum(1)

    def element_loads(self, u) -> np.ndarray:
        """Ball loads [N], shape u.shape[:-1] + (Z,), at displacements u (..., 5)
        [m, rad]."""
        u = np.asarray(u, float)
        return self._state(u).Q.reshape(u.shape[:-1] + (-1,))

    def result(self, u) -> "LoadDistribution":
        """The checked :class:`LoadDistribution` at imposed displacements u (5,) [m, rad]."""
        return solve(self.bearing, displacements=np.asarray(u, float), clearance=self.clearance)

    def rating_life(self, u, *, dynamic_rating=None, rotating: str = "inner",
                    nominal_contact_angle=None):
        """ISO/TS 16281 reference rating life of the row at displacements u (..., 5)
        [m, rad] (:func:`~ballrace.analytic.iso16281.reference_rating_life` of its ball
        loads); dynamic_rating [N], nominal_contact_angle [rad] as there."""
        from .iso16281 import reference_rating_life
        return reference_rating_life(self.bearing, _BallLoads(self.element_loads(u)),
                                     dynamic_rating=dynamic_rating, rotating=rotating,
                                     nominal_contact_angle=nominal_contact_angle)


@dataclass(frozen=True)
class _BallLoads:
    """Ball loads of one row [N] (what the ISO/TS 16281 life reads from a result)."""

    ball_loads: np.ndarray


def seat_warnings(bearing: BallBearing, what: str, results, tilt) -> tuple:
    """Messages (str or None) for ball rows working beyond their limits: static safety
    s0 < 1 (only computed where a ball load may reach 4200 MPa), a deep-groove bearing
    beyond :data:`~ballrace.analytic.ratings.DEEP_GROOVE_ANGLE_LIMIT`, a tilt beyond
    :data:`~ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT`.

    Parameters
    ----------
    bearing : BallBearing
        The bearing of the rows.
    what : str
        Names the seat in the messages.
    results : sequence of LoadDistribution
        The rows' results.
    tilt : float
        Inner-ring tilt relative to the outer ring [rad].
    """
    from . import _operating as op
    from .ratings import static_safety_from_pressure

    Q = np.concatenate([np.atleast_1d(ld.ball_loads) for ld in results])
    beta = np.concatenate([np.atleast_1d(ld.contact_angles) for ld in results])
    safety = None
    if op.may_be_overloaded(bearing, Q):
        p = max(float(np.max(ld.max_pressure)) for ld in results)
        safety = op.safety_message(what, np.asarray(static_safety_from_pressure(p), float), p)
    return safety, op.angle_message(what, bearing, Q, beta), op.tilt_message(what, bearing, tilt)


def _retry(model, geo, L, u0, imposed, arm, rtol, max_iter, ok, u, iters):
    """Second attempts for the cases (``~ok``) where the direct path did not converge.

    With the contact arm, straight from the start (the groove-arm solution can lie in
    another basin: an eccentric thrust carried by reverse contacts); then load
    continuation from the previous solution: for loads below 1e-4 of the capacity down
    from 1e-3 of it by decades (a light load with clearance: the rigid ring must find its
    seat while the balls hardly resist), otherwise up a quarter of the load at a time.  Raises
    ConvergenceError (or ValueError for an overload) for what still fails.
    """
    bad = np.flatnonzero(~ok)
    Lb, fx = L[bad], imposed[bad]
    ub, ib = u0[bad].copy(), iters[bad].copy()
    done = np.zeros(bad.size, bool)
    zero = np.where(fx, u0[bad], 0.0)
    if arm == "contact":
        for start in (ub, zero):
            todo = np.flatnonzero(~done)
            if not todo.size:
                break
            uu, it2, okk = _newton(model, geo, Lb[todo], start[todo], fx[todo], "contact", rtol,
                                   max_iter, strict=False)
            ub[todo[okk]], done[todo[okk]] = uu[okk], True
            ib[todo] += it2
    sc = np.array([1.0, 1.0, 1.0, model.Ri, model.Ri])
    for k in np.flatnonzero(~done):
        uk = zero[k][None].copy()
        # light loads: down from 1e-3 of the capacity by decades (the contact geometry then
        # hardly changes from one decade to the next); otherwise up in quarters
        k0 = 1e-3 * model.capacity / max(float(np.abs(Lb[k] / sc).max()), 1e-300)
        n = int(np.ceil(np.log10(k0))) if k0 > 10.0 else 0
        if n:
            # below the round-off resolution (the approach s - A is resolved to ~20 eps |u|,
            # see newton.roundoff_floor): no decade walk down to it, which would take
            # ~log10(k0) failing Newton runs (300 for a load of 1e-300 N)
            Fm = float(np.abs(Lb[k] / sc).max())
            d_est = (Fm / model.Kn_free) ** (2.0 / 3.0)          # one ball carrying it all
            travel = max(model.A - geo.x0, geo.z0)              # rigid travel to a seat
            if not d_est > POLICY.roundoff_eps * travel:
                raise ConvergenceError(
                    f"load distribution: the loads {Lb[k].tolist()} [N, N m] are too small "
                    f"for the model to resolve: a ball approach of about {d_est:.1e} m is "
                    f"below the round-off (~{POLICY.roundoff_eps * travel:.1e} m) of "
                    f"the ring's travel of {travel:.2g} m to its seat in the clearance")
        fracs = np.logspace(n, 0.0, n + 1) if n else (0.25, 0.5, 0.75, 1.0)
        for i, frac in enumerate(fracs):
            last = i == len(fracs) - 1
            Lk = Lb[k][None] * frac
            if arm == "groove" or i == 0:
                uk, itk, _ = _newton(model, geo, Lk, uk, fx[k][None], "groove", rtol, max_iter,
                                     strict=last and arm == "groove")
                ib[k] += itk[0]
            if arm == "contact":
                uk, itk, _ = _newton(model, geo, Lk, uk, fx[k][None], "contact", rtol,
                                     max_iter, strict=last)
                ib[k] += itk[0]
        ub[k] = uk[0]
    u, iters = u.copy(), iters.copy()
    u[bad], iters[bad] = ub, ib
    return u, iters


def radial(bearing: BallBearing, Fr, clearance=None, azimuth_offset: float = 0.0,
           **kwargs) -> LoadDistribution:
    r"""Pure radial load with diametral clearance (rings axially centred, no tilt).

    .. math:: \delta_\psi = \delta_r\cos\psi - P_d/2, \qquad
              Q_\psi = K_n \langle\delta_\psi\rangle^{3/2}, \qquad
              F_r = \sum Q_\psi \cos\psi

    (Hamrock & Dowson 1981 eqs. 3.39–3.42; Jones 1946).  Here both radial components
    are free, so a ball set rotated by ``azimuth_offset`` is handled exactly (the ring
    then also moves slightly across the load line); the load acts along +y.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    Fr : float or array_like
        Radial load along +y [N], >= 0.
    clearance : float, optional
        Diametral clearance P_d [m], < 2A; negative for interference (preload).
        Default: the bearing's.
    azimuth_offset : float, optional
        Azimuth of ball 1 from the load line [rad]; 0 puts a ball on the load line,
        pi/Z straddles it.
    **kwargs
        ``rtol``, ``max_iter`` as in :func:`solve`.

    Returns
    -------
    LoadDistribution
        With ``axial_offset = 0`` (centred reference configuration).

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.39)–(3.48); Stribeck (1907) Trans. ASME 29 420–463.

    Examples
    --------
    Tata (2012), *Principles and Use of Ball Bearings*: 8 balls, 570 lb radial, zero
    clearance: ball 1 carries 310 lb, balls 2 and 3 carry 184 lb each.

    >>> import ballrace
    >>> brg = ballrace.BallBearing(12.7e-3, 8, 50e-3, 0.52, 0.52, diametral_clearance=0.0)
    >>> lbf = 4.4482216152605
    >>> r = radial(brg, 570 * lbf)
    >>> np.round(r.ball_loads[[0, 1, 7]] / lbf, 1)        # psi = 0, +45, -45 deg
    array([309.6, 184.1, 184.1])
    >>> round(float(np.degrees(r.loaded_zone)), 6)
    90.0
    """
    Fr = check_nonnegative(Fr, "Fr", "N")
    Fr = as_array(Fr, "Fr", bounded=True, tiny_ok=True)          # named before it becomes Fy
    d = np.array([0.0, np.nan, np.nan, 0.0, 0.0])
    return _solve(bearing, Fy=Fr, displacements=d, clearance=clearance,
                  azimuth_offset=azimuth_offset, centered=True, **kwargs)


def combined(bearing: BallBearing, Fr, Fa, azimuth_offset: float = 0.0,
             **kwargs) -> LoadDistribution:
    r"""Combined radial and thrust load after Jones: ring displacements delta_a, delta_r,
    no misalignment (the tilting moment is a reaction).

    .. math::
        s(\psi) = \left[(A\sin\beta_f + \delta_a)^2
                  + (A\cos\beta_f + \delta_r\cos\psi)^2\right]^{1/2}, \quad
        \tan\beta = \frac{A\sin\beta_f + \delta_a}{A\cos\beta_f + \delta_r\cos\psi},

        F_a = \sum Q\sin\beta, \qquad F_r = \sum Q\cos\beta\cos\psi

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    Fr : float or array_like
        Radial load along +y [N].
    Fa : float or array_like
        Thrust load [N].
    azimuth_offset : float, optional
        Azimuth of ball 1 from the load line [rad].
    **kwargs
        ``rtol``, ``max_iter``, ``clearance`` as in :func:`solve`.

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.61)–(3.74); Jones (1946).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = combined(brg, 8900.0, 17800.0)
    >>> round(float(r.max_ball_load)), round(float(np.degrees(r.loaded_zone)), 2)
    (3275, 180.0)
    """
    Fr, Fa = broadcast(Fr=as_array(Fr, "Fr", bounded=True, tiny_ok=True),   # named before
                       Fa=as_array(Fa, "Fa", bounded=True, tiny_ok=True))   # Fr becomes Fy
    d = np.array([np.nan, np.nan, np.nan, 0.0, 0.0])
    return solve(bearing, Fa=Fa, Fy=Fr, displacements=d, azimuth_offset=azimuth_offset, **kwargs)


def thrust(bearing: BallBearing, Fa, *, rtol: float = 1e-13, max_iter: int = 100) -> LoadDistribution:
    r"""Pure thrust load: contact angle by Newton–Raphson, axial deflection.

    .. math::
        \frac{F_a}{Z} = K_n(\beta)\,A^{3/2} \sin\beta
        \left(\frac{\cos\beta_f}{\cos\beta} - 1\right)^{3/2}, \qquad
        \delta_t = \frac{A\sin(\beta - \beta_f)}{\cos\beta}

    solved for beta by safeguarded Newton–Raphson with K_n evaluated (exact Hertz) at
    beta (Hamrock & Dowson 1981 eqs. 3.50–3.56, 3.60), then polished by the Newton of
    :func:`solve` with radial displacement and tilt held at zero (near beta_f = 90 deg
    eq. 3.60 loses its digits, and at light loads a tolerance on beta is none on the
    thrust); the result's equilibrium is checked like every solver's.  Each ball carries
    Q = F_a / (Z sin beta).  If shoulder heights are given, ``result.truncated(race)``
    reports whether the contact ellipse runs over the shoulder (H&D eqs. 3.57–3.58).

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    Fa : float or array_like
        Thrust load [N], >= 0.
    rtol : float, optional
        Tolerance on beta [rad] and on the relative thrust residual.
    max_iter : int, optional
        Iteration limit.

    Returns
    -------
    LoadDistribution
        ``displacements[..., 0]`` is delta_t.

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.50)–(3.60); Harris (2001) §7.2.

    Examples
    --------
    Ricci's 218 bearing under 17,800 N (Harris's chart: beta = 41.6 deg):

    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = thrust(brg, 17800.0)
    >>> round(float(np.degrees(r.contact_angles[0])), 3), round(float(r.axial_deflection) * 1e6, 2)
    (41.53, 36.79)
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    model = _Model.of(bearing)
    Fa_ = check_nonnegative(Fa, "Fa", "N", bounded=True, tiny_ok=True)
    rtol = float(check_range(rtol, "rtol", 0.0, 1e-3, high_inclusive=True, unit="-"))
    shape = Fa_.shape
    Fv = Fa_.ravel()
    Lc = np.zeros((Fv.size, 5))
    Lc[:, 0] = Fv
    _check_loads(model, Lc)
    bf, A = model.beta_f, model.A
    beta = _thrust_angle(model, Fv, rtol, max_iter)
    dt = A * np.sin(beta - bf) / np.cos(beta)                         # H&D eq. 3.60
    u = np.zeros((Fv.size, 5))
    u[:, 0] = dt
    Pd, x0, z0 = _reference(model, None, False)
    geo = _geo(model, bearing, 0.0, x0, z0)
    psi = geo.psi.copy()
    L = np.zeros_like(u)
    L[:, 0] = Fv
    imposed = np.zeros(u.shape, dtype=bool)
    # polish with the 5-DOF Newton (radial and tilt held at 0): near beta_f = 90 deg the
    # deflection A sin(beta - beta_f)/cos(beta) loses its digits, and at light loads the
    # tolerance on beta is not one on the thrust
    fixed = np.zeros(u.shape, dtype=bool)
    fixed[:, 1:] = True
    u, iters, _ = _newton(model, geo, L, u, fixed, "groove", max(rtol, 1e-13), max_iter)
    return _result(bearing, model, psi, x0, z0, Pd, u, L, imposed, "groove",
                   iters, shape, "exact", rtol=rtol, what="thrust")


def _thrust_angle(model, Fa, rtol, max_iter):
    """beta solving H&D (1981) eq. 3.55 (vector), bracketed Newton–Raphson (eq. 3.56)."""
    bf, A, Z = model.beta_f, model.A, model.Z
    cf = np.cos(bf)
    c = Z * A**1.5

    def h(beta):
        Kn, dl = _kn(model, beta)
        cb, sb = np.cos(beta), np.sin(beta)
        g = np.maximum(cf / cb - 1.0, 0.0)
        dg = cf * sb / cb**2
        val = c * Kn * sb * g**1.5
        der = c * Kn * (dl * sb * g**1.5 + cb * g**1.5 + 1.5 * sb * np.sqrt(g) * dg)
        return val, der

    Kf, _ = _kn(model, np.array([bf]))
    t = Fa / (c * Kf[0])
    # small-deflection starts: beta_f > 0: sin(bf)(tan(bf) db)^1.5 = t; beta_f = 0: b^4/2^1.5 = t
    d1 = (t / np.sin(bf)) ** (2 / 3) / np.tan(bf) if bf > 1e-6 else np.inf
    d2 = (2**1.5 * t) ** 0.25
    beta = np.minimum(bf + np.minimum(d1, d2), 0.5 * (bf + 0.5 * np.pi))
    lo = np.full(Fa.shape, bf)
    hi = np.full(Fa.shape, 0.5 * np.pi)
    done = Fa == 0
    beta = np.where(done, bf, beta)
    for it in range(max_iter):
        if np.all(done):
            break
        val, der = h(beta)
        r = val - Fa
        lo = np.where(r < 0, beta, lo)
        hi = np.where(r > 0, beta, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            nb = beta - r / der
        out = ~((nb >= lo) & (nb <= hi)) | ~np.isfinite(nb)
        nb = np.where(out, 0.5 * (lo + hi), nb)
        small = np.abs(r) <= rtol * Fa                      # converged: keep this beta
        nb = np.where(small, beta, nb)
        conv = small | (np.abs(nb - beta) <= rtol)
        beta = np.where(done, beta, nb)
        done |= conv
    else:
        i = int(np.argmax(~done))
        raise ConvergenceError(f"thrust contact angle did not converge after {max_iter} "
                               f"iterations for Fa={Fa[i]!r} N")
    return beta


def eccentric_thrust(bearing: BallBearing, Fa, e, *, rtol: float = 1e-12,
                     max_iter: int = 200) -> LoadDistribution:
    r"""Eccentric thrust load: Ricci's Z + 2 equations.

    Unknowns delta_a, theta and beta_j (j = 1..Z); psi_j = 2 pi (j - 1)/Z with ball 1 on
    the side of the load (the thrust acts at y = e, so Mz = -e Fa):

    .. math::
        \delta_a + R_i\theta\cos\psi_j - A\frac{\sin(\beta_j - \beta_f)}{\cos\beta_j} = 0
        \quad (26)

        F_a - A^{3/2}\sum_j K_{nj}\sin\beta_j
              \left(\frac{\cos\beta_f}{\cos\beta_j} - 1\right)^{3/2} = 0 \quad (30)

        e F_a - \frac{A^{3/2}}{2}\sum_j K_{nj}\, d_{cj}\cos\psi_j\sin\beta_j
              \left(\frac{\cos\beta_f}{\cos\beta_j} - 1\right)^{3/2} = 0 \quad (31)

    with d_cj = d_e - D cos beta_j and K_nj the exact-Hertz ball stiffness at beta_j
    (unloaded balls, beta_j < beta_f, contribute nothing).  The radial displacement is
    zero (radial reaction in ``result.loads``), and the moment arm is the inner contact
    radius d_c/2, so this equals ``solve(..., Mz=-e*Fa, moment_arm="contact",
    displacements=[None, 0, 0, 0, None])``, and is solved that way: eq. (26) gives each
    beta_j from (delta_a, theta), which leaves the two equilibrium equations (30), (31)
    in delta_a and theta, solved by the damped Newton of :func:`solve` (one solver for
    both, with its round-off floor, per-case convergence over arrays and the final
    residual check) from the solution of the constant-angle, linearised model (the
    discrete form of Harris's J-integrals; the pure-thrust solution for e >= 0.95 r_f or
    beta_f < 0.15 rad, see ``_eccentric_start``).  Solving the Z + 2 equations
    directly failed on a quarter of the feasible inputs at e > 0.3 R_i.

    The thrust line must pass inside the pitch circle, e < d_e/2: every contact radius
    d_c/2 = (d_e - D cos beta)/2 is smaller than d_e/2, so beyond it the thrust contacts
    cannot balance the moment and the ring would tip (``ValueError`` naming e and the
    limit; with a moment in :func:`solve` the reverse groove flanks of a deep-groove
    bearing can carry it).

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    Fa : float or array_like
        Thrust load [N], >= 0.
    e : float or array_like
        Eccentricity of the thrust from the bearing axis [m], in [0, d_e/2).
    rtol : float, optional
        Equilibrium tolerance as in :func:`solve` [-].
    max_iter : int, optional
        Iteration limit.

    Returns
    -------
    LoadDistribution
        ``displacements = (delta_a, 0, 0, 0, -theta)``; ``loaded_zone`` is Ricci's
        psi_l = arccos(-delta_a / (R_i theta)) (eq. 21).

    References
    ----------
    Ricci, M.C. (2009) "Ball bearings subjected to a variable eccentric thrust load",
    DINCON'09, eqs. (17)–(31).

    Examples
    --------
    Ricci's 218 bearing, F_a = 17,800 N at e = 50.8 mm (published: Q_max = 9,445 N,
    beta from 44.317 to 16.169 deg, psi_l = 53.66 deg):

    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = eccentric_thrust(brg, 17800.0, 50.8e-3)
    >>> round(float(r.max_ball_load)), np.round(np.degrees(r.contact_angles[[0, 8]]), 3)
    (9398, array([44.47 , 15.898]))
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    model = _Model.of(bearing)
    e_max = 0.5 * model.dm
    if _plain(Fa) and _plain(e) and Fa >= 0 and 0 <= e < e_max and type(rtol) is float and \
            0.0 < rtol <= 1e-3:
        # one case of plain numbers (what the checks below would accept): what
        # solve(Fa, Mz=-e Fa, displacements=_ECC_FREE, initial=start) does, without arrays
        F1, e1 = float(Fa), float(e)
        L = np.array([[F1, 0.0, 0.0, 0.0, -e1 * F1]])
        _check_loads(model, L)
        u0 = _eccentric_start_one(model, F1, e1)
        lim = model.D / model.Ri
        if abs(u0[0]) <= model.D and abs(u0[4]) <= lim:
            Pd, x0, z0 = _reference(model, None, False)
            geo = _geo(model, bearing, 0.0, x0, z0)
            res = _solve_checked(bearing, model, geo, geo.psi.copy(), x0, z0, Pd, L,
                                 _ECC_IMPOSED.copy(), u0[None], (), "contact", rtol, max_iter,
                                 True)
            log.debug("eccentric thrust: converged in %d Newton iterations", res.iterations)
            return res
    F0 = check_nonnegative(Fa, "Fa", "N", bounded=True, tiny_ok=True)
    e0 = check_nonnegative(e, "e", "m")
    Fa_, e_ = broadcast(Fa=F0, e=e0)
    if np.any(e_ >= e_max):
        bad = float(e_[e_ >= e_max].ravel()[0])
        raise ValueError(
            f"e = {bad!r} m is beyond what the thrust alone can carry: the thrust line must "
            f"pass inside the pitch circle, e < d_e/2 = {e_max:.6g} m (every contact radius "
            "is smaller), or the ring tips; apply the moment with solve(Fa=..., Mz=-e*Fa) "
            "to let the reverse groove flanks carry it")
    F = Fa_.astype(float)
    Lc = np.zeros(F.shape + (5,))
    Lc[..., 0], Lc[..., 4] = F, -e_ * F
    _check_loads(model, Lc.reshape(-1, 5))
    u0 = _eccentric_start(model, F, e_)
    res = _solve(bearing, Fa=F, Mz=-e_ * F, displacements=_ECC_FREE, moment_arm="contact",
                 rtol=rtol, max_iter=max_iter, initial=u0, contact_direct=True)
    log.debug("eccentric thrust: converged in %d Newton iterations", res.iterations)
    return res


#: The DOFs of eccentric_thrust: axial and tilt about z free, the rest held at 0.
_ECC_FREE = np.array([np.nan, 0.0, 0.0, 0.0, np.nan])
_ECC_FREE.flags.writeable = False
_ECC_IMPOSED = ~np.isnan(_ECC_FREE)[None]
_ECC_IMPOSED.flags.writeable = False


@functools.lru_cache(maxsize=64)
def _eccentric_grid(Z):
    """(rho, g(rho), S(rho)) on a grid of rho in (-1, 50]: g = sum <rho + cos psi_j>^1.5
    cos psi_j / S, S = sum <rho + cos psi_j>^1.5, psi_j = 2 pi j / Z (g decreasing)."""
    cp = np.cos(2.0 * np.pi * np.arange(Z) / Z)
    rho = np.concatenate([-np.cos(np.linspace(0.0, np.pi, 97)[1:]), np.geomspace(1.02, 50.0, 48)])
    w = np.maximum(rho[:, None] + cp, 0.0)
    w = w * np.sqrt(w)
    S = w.sum(1)
    g = w @ cp / S
    return rho, g, S, g[::-1].copy(), rho[::-1].copy(), S[::-1].copy()


def _eccentric_start(model, Fa, e):
    r"""Start (delta_a, 0, 0, 0, theta_z) of :func:`eccentric_thrust` (shape Fa.shape + (5,)).

    The constant-angle, linearised model: ball j's approach sin(beta_f) (a + b cos psi_j)
    with a = delta_a, b = -R_i theta_z, K_n and the contact radius r_f = (d_e - D cos
    beta_f)/2 at the free angle, so that

    .. math:: \frac{e}{r_f} = \frac{\sum\langle\rho + \cos\psi_j\rangle^{3/2}\cos\psi_j}
              {\sum\langle\rho + \cos\psi_j\rangle^{3/2}}, \qquad
              F_a = K_n \sin^{5/2}\beta_f\, b^{3/2} \sum\langle\rho + \cos\psi_j\rangle^{3/2}

    (rho = a / b; the discrete form of Harris's J-integrals), rho interpolated from a
    tabulated grid, then a + b scaled so that the most loaded ball has that approach on the
    exact geometry.  Only a start: Newton on the exact equations follows.  For
    e / r_f >= ``_ECC_LINEAR`` (the model has no solution at e >= r_f) or beta_f below
    ``_ECC_MIN_ANGLE`` the pure-thrust solution is the start.
    """
    rho_g, g_g, S_g, g_r, rho_r, S_r = _eccentric_grid(model.Z)
    sf = math.sin(model.beta_f)
    C = model.Kn_free * max(sf, 1e-3) ** 2.5
    rf = 0.5 * (model.dm - model.D * math.cos(model.beta_f))
    Fa = np.asarray(Fa, float)
    tau = np.broadcast_to(np.asarray(e, float) / rf, Fa.shape)
    far = ~(tau < _ECC_LINEAR) | (model.beta_f < _ECC_MIN_ANGLE)
    if np.all(far):
        return _thrust_start(model, Fa)
    tau = np.minimum(tau, g_g[0])
    rho = np.interp(tau, g_r, rho_r)
    S = np.interp(tau, g_r, S_r)
    b = (Fa / (C * S)) ** (2.0 / 3.0)
    # the most loaded ball (psi = 0) at the approach the linear model gives it,
    # sin(beta_f) (a + b), on the exact geometry: a + b = sqrt((A + delta)^2 - x0^2) - z0
    A, x0, z0 = model.A, model.A * math.cos(model.beta_f), model.A * sf
    d1 = np.minimum(sf * (rho + 1.0) * b, MAX_APPROACH_RATIO * model.D)
    top = np.sqrt((A + d1 - x0) * (A + d1 + x0)) - z0
    with np.errstate(invalid="ignore", divide="ignore"):
        f = np.where(b > 0, top / ((rho + 1.0) * b), 0.0)
    b = np.minimum(b * f, 0.5 * model.D)
    u0 = np.zeros(Fa.shape + (5,))
    u0[..., 0] = np.clip(rho * b, -0.5 * model.D, 0.5 * model.D)
    u0[..., 4] = -b / model.Ri
    if np.any(far):
        u0[far] = _thrust_start(model, Fa[far])
    return u0


def _eccentric_start_one(model, Fa, e):
    """:func:`_eccentric_start` for one case of floats (the same operations on floats)."""
    rho_g, g_g, S_g, g_r, rho_r, S_r = _eccentric_grid(model.Z)
    sf = math.sin(model.beta_f)
    rf = 0.5 * (model.dm - model.D * math.cos(model.beta_f))
    tau = e / rf
    if not tau < _ECC_LINEAR or model.beta_f < _ECC_MIN_ANGLE:
        return _thrust_start(model, np.array(Fa))
    C = model.Kn_free * max(sf, 1e-3) ** 2.5
    tau = min(tau, float(g_g[0]))
    rho = float(np.interp(tau, g_r, rho_r))
    b = (Fa / (C * float(np.interp(tau, g_r, S_r)))) ** (2.0 / 3.0)
    A, x0, z0 = model.A, model.A * math.cos(model.beta_f), model.A * sf
    d1 = min(sf * (rho + 1.0) * b, MAX_APPROACH_RATIO * model.D)
    top = math.sqrt((A + d1 - x0) * (A + d1 + x0)) - z0
    f = top / ((rho + 1.0) * b) if b > 0 else 0.0
    b = min(b * f, 0.5 * model.D)
    return np.array([min(max(rho * b, -0.5 * model.D), 0.5 * model.D), 0.0, 0.0, 0.0,
                     -b / model.Ri])


def _thrust_start(model, Fa):
    """(delta_t, 0, 0, 0, 0) of the pure-thrust solution (H&D eq. 3.60), shape Fa.shape + (5,)."""
    bt = _thrust_angle(model, Fa.ravel(), 1e-14, 100)
    u0 = np.zeros(Fa.shape + (5,))
    u0[..., 0] = (model.A * np.sin(bt - model.beta_f) / np.cos(bt)).reshape(Fa.shape)
    return u0


#: Largest e / r_f (r_f the contact radius at the free angle) for which eccentric_thrust
#: starts from the linearised model (:func:`_eccentric_start`); beyond it the ring tips
#: onto few balls at angles far from beta_f and the pure-thrust start serves better.
_ECC_LINEAR = 0.95
#: Smallest free contact angle [rad] for that start: near beta_f = 0 the axial approach
#: is quadratic in the axial shift, not linear.
_ECC_MIN_ANGLE = 0.15


# =========================================================================== approximations
def jones_radial_factor(clearance_ratio):
    r"""Jones's load-distribution factor Z_w for radial load with clearance.

    .. math:: Z_w = \frac{\pi (1 - c)^{3/2}}
              {2.491\left\{\left[1 + \left(\frac{1 - c}{1.23}\right)^2\right]^{1/2} - 1\right\}},
              \qquad c = \frac{P_d}{2\delta_r}

    so that Q_max = Z_w F_r / Z; it fits the exact integral to about 2 % and tends to
    Stribeck's 4.37 at zero clearance.

    Parameters
    ----------
    clearance_ratio : float or array_like
        c = P_d / (2 delta_r) [-], < 1 (negative for interference).

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.45)–(3.48); Jones (1946).

    Examples
    --------
    >>> round(float(jones_radial_factor(0.0)), 4)
    4.3671
    """
    c = check_range(clearance_ratio, "clearance_ratio", 0.0, 1.0, low_inclusive=True, unit="-")
    q = 1.0 - c
    return hertz.scalar_result(np.pi * q**1.5 / (2.491 * (np.sqrt(1.0 + (q / 1.23) ** 2) - 1.0)))


def stribeck_max_ball_load(Fr, n_balls, factor: float = 5.0):
    r"""Stribeck's maximum ball load Q_max = factor F_r / Z (factor 5 in practice).

    .. math:: Q_{max} = \frac{5 F_r}{Z}

    Stribeck's theoretical factor for zero clearance and many balls is
    :data:`STRIBECK_LIMIT` = 4.37; 5 allows for clearance.

    Parameters
    ----------
    Fr : float or array_like
        Radial load [N], >= 0.
    n_balls : int
        Number of balls Z [-], >= 1.
    factor : float, optional
        Stribeck factor [-], > 0.

    References
    ----------
    Stribeck (1907) Trans. ASME 29 420–463; Hamrock & Dowson (1981) eq. (3.49).

    Examples
    --------
    >>> float(stribeck_max_ball_load(1000.0, 10))
    500.0
    """
    Fr = check_nonnegative(Fr, "Fr", "N", bounded=True, tiny_ok=True)
    Z = float(check_integer(n_balls, "n_balls", 1))
    f = float(check_range(factor, "factor", 0.0, None, unit="-"))
    return hertz.scalar_result(f * Fr / Z)


def jones_max_ball_load(Fr, n_balls, Kn, clearance=0.0):
    r"""Maximum ball load under radial load by Jones's closed-form approximation.

    Solves K_n (delta_r - P_d/2)^{3/2} = Z_w(P_d / 2 delta_r) F_r / Z for delta_r
    (Hamrock & Dowson 1981 eqs. 3.46–3.48), with a constant ball stiffness K_n.

    Parameters
    ----------
    Fr : float or array_like
        Radial load [N], > 0.
    n_balls : int
        Number of balls Z [-].
    Kn : float
        Ball stiffness K_n [N/m^1.5], > 0 (e.g. ``bearing.contact_stiffness(0)[2]``).
    clearance : float, optional
        Diametral clearance P_d [m] (negative for interference).

    Returns
    -------
    Q_max : float or ndarray
        [N].
    delta_r : float or ndarray
        Radial ring displacement [m].

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.42)–(3.48).

    Examples
    --------
    >>> Q, dr = jones_max_ball_load(1000.0, 10, 1e10)
    >>> round(float(Q / 100.0), 4)   # = Z_w(0) F_r / Z
    4.3671
    """
    Fr = check_positive(Fr, "Fr", "N", bounded=True)
    Z = float(check_integer(n_balls, "n_balls", 1))
    Kn = float(check_positive(Kn, "Kn", "N/m^1.5", bounded=True))
    Pd = float(as_array(clearance, "clearance", bounded=True, tiny_ok=True, unit="m"))
    half = 0.5 * Pd
    # bisection on ln t, t = delta_r - P_d/2 > 0 (LHS - RHS increases with t)
    lo = np.full(Fr.shape, -60.0)
    hi = np.full(Fr.shape, 5.0)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        t = np.exp(mid)
        dr = t + half
        c = np.where(dr > 0, half / np.where(dr > 0, dr, 1.0), -np.inf)
        q = 1.0 - c
        zw = np.pi * q**1.5 / (2.491 * (np.sqrt(1.0 + (q / 1.23) ** 2) - 1.0))
        pos = Kn * t**1.5 - zw * Fr / Z > 0
        hi = np.where(pos, mid, hi)
        lo = np.where(pos, lo, mid)
    t = np.exp(0.5 * (lo + hi))
    return hertz.scalar_result(Kn * t**1.5), hertz.scalar_result(t + half)
