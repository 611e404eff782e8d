r"""Duplex (paired) angular-contact ball bearings with axial preload.

Two identical single-row bearings on one shaft, mounted back-to-back (``"DB"``),
face-to-face (``"DF"``) or in tandem (``"DT"``), under an external axial load F_a and
radial load F_r.  Each bearing follows its own static load–deflection relation, the
Jones combined-load model of :mod:`ballrace.analytic.loaddist` (rigid rings, exact Hertz
K_n at each ball's contact angle, no misalignment; Hamrock & Dowson 1981 eqs.
3.61–3.74):

.. math::
    F_a(\delta_a, \delta_r) = \sum_j Q_j\sin\beta_j, \qquad
    F_r(\delta_a, \delta_r) = \sum_j Q_j\cos\beta_j\cos\psi_j,

    Q_j = K_n(\beta_j)\langle s_j - A\rangle^{3/2},\quad
    s_j = \sqrt{(A\sin\beta_f + \delta_a)^2 + (A\cos\beta_f + \delta_r\cos\psi_j)^2}.

Compatibility (Harris 2001 §7.5 "preloading"; Tata 2012, *Factors Influencing the
Performance of Ball and Roller Bearings*):

* **DB / DF** — the preload P presses each bearing axially to delta_0 with
  F_a(delta_0, 0) = P.  An external load moves the shaft axially by x: the bearing in
  the load path (bearing 1) deflects delta_0 + x, the other delta_0 - x (so
  delta_1 + delta_2 = 2 delta_0 = const); both share the radial displacement delta_r:

  .. math:: F_a = F_{a}(\delta_0 + x, \delta_r) - F_{a}(\delta_0 - x, \delta_r), \qquad
            F_r = F_{r}(\delta_0 + x, \delta_r) + F_{r}(\delta_0 - x, \delta_r).

  Bearing 2 unloads (separates) when x = delta_0, at the external load
  F_u = F_a(2 delta_0, 0); with the contact angle frozen F_a ~ delta^{3/2} and
  F_u = 2^{3/2} P = 2.83 P (the classical result for point contact).
  In this axial/radial model DB and DF behave the same; they differ in tilting
  stiffness (the spread of the load centres), which needs the ring widths and is not
  modelled here.
* **DT** — both bearings deflect equally and share the load:
  F_a = 2 F_a(delta, delta_r) - P_s, F_r = 2 F_r(delta, delta_r), where the optional
  ``preload`` P_s is a constant axial spring load on the pair in its load direction; the
  pair unloads when the external axial load reaches -P_s.

Positive F_a loads bearing 1 (for DT: loads both bearings); a negative F_a loads
bearing 2 of a DB/DF pair.
"""
from __future__ import annotations

import functools
import logging
from dataclasses import dataclass

import numpy as np

from ._checks import as_array, check_choice, check_nonnegative, check_positive
from .bearing import BallBearing
from ..errors import ConvergenceError
from . import newton
from .newton import POLICY
from .loaddist import MAX_APPROACH_RATIO, BallModel, fold_unloaded

__all__ = ["ARRANGEMENTS", "DuplexPair", "DuplexResult", "axial_load", "axial_deflection",
           "power_law_unloading_ratio"]

log = logging.getLogger(__name__)

ARRANGEMENTS = ("DB", "DF", "DT")


# =========================================================================== one bearing
def _groove_centres(bearing, da, dr):
    """(A, psi, x, z): radial and axial components of each ball's line of groove centres [m]
    at ring displacements (da, dr), vectorized over their leading axes (Jones 1960;
    H&D 1981 eqs. 3.61-3.63)."""
    A, sf, cf, psi, cpsi = _constants(bearing)
    z = A * sf + np.asarray(da, float)[..., None]
    x = A * cf + np.asarray(dr, float)[..., None] * cpsi
    return A, psi, x, z


def _constants(bearing):
    """(A, sin beta_f, cos beta_f, psi, cos psi) of a bearing, cached with its model."""
    m = BallModel.of(bearing)
    hit = _CONST.get(id(m))
    if hit is None or hit[0] is not m:
        if len(_CONST) > 256:                                # bounded: models come and go
            _CONST.clear()
        psi = 2.0 * np.pi * np.arange(m.Z) / m.Z            # bearing.azimuths(0.0)
        hit = _CONST[id(m)] = (m, (m.A, np.sin(m.beta_f), np.cos(m.beta_f), psi, np.cos(psi)))
    return hit[1]


_CONST: dict = {}


def _forces(bearing, da, dr, jac=False):
    """(Fa, Fr, ball loads, contact angles) of one bearing at ring displacements (da, dr).

    Vectorized over leading axes of ``da`` and ``dr`` (broadcast); Jones combined-load
    model (H&D 1981 eqs. 3.61-3.70) with K_n at each ball's own angle.  With ``jac`` also
    the analytic derivatives d(Fa, Fr)/d(da, dr), shape (..., 2, 2): per ball, with
    e = (cos b, sin b), t = (-sin b, cos b) and X = (x, z) its groove-centre line,
    d(Q e)/dX = (k15 - Q/s) e e' + (Q/s) dlnK_n/db e t' + (Q/s) I, k15 = 1.5 K_n (s - A)^0.5,
    and dX/d(da, dr) = ((0, cos psi), (1, 0)).
    """
    A, psi, x, z = _groove_centres(bearing, da, dr)
    s = np.hypot(x, z)
    b = np.arctan2(z, x)
    # K_n from the bearing model's table (exact Hertz to 1e-13, as in loaddist.solve)
    model = BallModel.of(bearing)
    sb = np.maximum(s, 1e-300)
    c, sn = x / sb, z / sb
    Kn, dlnK = model.contact_stiffness(b, c, sn)
    # half-torus grooves: no contact where the groove-centre line points inwards (x <= 0);
    # unloaded balls report that line's angle folded into (-pi/2, pi/2] (as in loaddist)
    d = np.where(x > 0, np.maximum(s - A, 0.0), 0.0)
    sq = np.sqrt(d)
    Q = Kn * d * sq
    b = fold_unloaded(b, Q)
    cpsi = _constants(bearing)[4]
    Fa = np.sum(Q * np.sin(b), axis=-1)
    Fr = np.sum(Q * np.cos(b) * cpsi, axis=-1)
    if not jac:
        return Fa, Fr, Q, b
    qs = Q / sb
    a = 1.5 * Kn * sq - qs
    qk = qs * dlnK
    W00 = a * c * c - qk * c * sn + qs          # d(Q cos b)/dx
    W01 = a * c * sn + qk * c * c               # d(Q cos b)/dz
    W10 = a * sn * c - qk * sn * sn             # d(Q sin b)/dx
    W11 = a * sn * sn + qk * sn * c + qs        # d(Q sin b)/dz
    J = np.empty(np.shape(Fa) + (2, 2))
    J[..., 0, 0] = W11.sum(-1)                  # dFa/dda
    J[..., 0, 1] = (W10 * cpsi).sum(-1)         # dFa/ddr
    J[..., 1, 0] = (W01 * cpsi).sum(-1)         # dFr/dda
    J[..., 1, 1] = (W00 * cpsi * cpsi).sum(-1)  # dFr/ddr
    return Fa, Fr, Q, b, J


def _approach(bearing, da, dr):
    """Largest ball approach s - A of one bearing at ring displacements (da, dr) [m]."""
    A, _, x, z = _groove_centres(bearing, da, dr)
    return float(np.max(np.hypot(x, z) - A))


def _past_groove(bearing, da, dr):
    """True if a ball is pressed past 90 deg (x <= 0 with s > A) at displacements (da, dr)."""
    A, _, x, z = _groove_centres(bearing, da, dr)
    return bool(np.any((x <= 0) & (np.hypot(x, z) > A)))


def axial_load(bearing: BallBearing, axial_deflection, radial_deflection=0.0):
    r"""Axial load of one bearing at given axial and radial ring displacements [N].

    .. math:: F_a = \sum_j K_n(\beta_j)\langle s_j - A\rangle^{3/2}\sin\beta_j

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    axial_deflection : float or array_like
        Axial displacement delta_a of the inner ring from the free state (balls just
        touching at the free contact angle) [m].
    radial_deflection : float or array_like
        Radial displacement delta_r towards ball 1 [m].

    Returns
    -------
    float or ndarray
        F_a [N].

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.61)–(3.67); Jones (1960).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> round(float(axial_load(brg, 36.79218841293e-6)), 3)   # the 17.8 kN thrust case
    17800.0
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    da = as_array(axial_deflection, "axial_deflection", bounded=True, tiny_ok=True)
    dr = as_array(radial_deflection, "radial_deflection", bounded=True, tiny_ok=True)
    Fa, _, _, _ = _forces(bearing, da, dr)
    return Fa[()] if np.ndim(Fa) == 0 else Fa


def axial_deflection(bearing: BallBearing, Fa, rtol: float = 1e-13, max_iter: int = 200):
    r"""Axial deflection of one bearing under pure thrust, inverse of :func:`axial_load` [m].

    Solves :math:`F_a(\delta_a, 0) = F_a` by a safeguarded secant/bisection on the
    monotonic load–deflection curve (equivalent to H&D 1981 eqs. 3.55–3.60,
    :math:`\delta_a = A\sin(\beta - \beta_f)/\cos\beta`).

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    Fa : float
        Thrust load [N], >= 0.  Loads below the model's round-off resolution, about
        Z K_n (eps A)^{3/2} (1e-18 N for a 20 mm ball), give a deflection at the round-off
        level eps A of the groove-centre distance A.
    rtol : float, optional
        Relative tolerance on the load [-].
    max_iter : int, optional
        Iteration limit.

    Returns
    -------
    float
        delta_a [m].

    Raises
    ------
    ConvergenceError
        If the tolerance is not reached.

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.50)–(3.60).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> round(axial_deflection(brg, 17800.0) * 1e6, 4)
    36.7922
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    F = float(check_nonnegative(Fa, "Fa", "N", bounded=True, tiny_ok=True))
    return _inverse(bearing, F, rtol, max_iter)


#: Doublings of the bracket in :func:`_inverse`: from the smallest positive float to 10 A
#: of any bearing is fewer than 1100; the bound only makes the loop visibly finite.
_MAX_DOUBLINGS = 2200


def _inverse(bearing, F, rtol=1e-13, max_iter=200, name="Fa"):
    """delta_a with F_a(delta_a, 0) = F [m] for F >= 0 [N] (any F down to the smallest
    positive float: every loop is bounded)."""
    if F == 0.0:
        return 0.0
    A = bearing.curvature_center_distance
    # upper end from the point-contact power law at the free angle, F = Z K_n
    # sin(b_f) (da sin(b_f))^1.5 (no more than a guess: the angle grows with the load)
    m = BallModel.of(bearing)
    sf = max(float(np.sin(m.beta_f)), 0.1)
    lo, hi = 0.0, min(1.5 * (F / (m.Z * m.Kn_free * sf)) ** (2.0 / 3.0) / sf, A)
    if not hi > 0.0:
        # F / (Z K_n) underflowed (F of order 1e-300 N or less): the same guess in logs,
        # never below the smallest positive float, so that doubling can grow it
        hi = min(max(1.5 * np.exp((np.log(F) - np.log(m.Z * m.Kn_free * sf)) / 1.5) / sf,
                     5e-324), A)
    f_hi, k_hi = _axial(bearing, hi)
    for _ in range(_MAX_DOUBLINGS):
        if not f_hi < F:
            break
        lo, hi = hi, 2.0 * hi
        if hi > 10.0 * A:
            raise ValueError(f"{name}={F!r} N is beyond the load-deflection range of the "
                             f"bearing")
        f_hi, k_hi = _axial(bearing, hi)
    else:
        raise ConvergenceError(f"axial deflection: no upper bound for {name}={F!r} N after "
                               f"{_MAX_DOUBLINGS} doublings (last {hi:.6g} m)")
    # Newton on the increasing, convex-ish curve from the upper end, kept inside the
    # bracket (bisection when a step leaves it), with the analytic slope dFa/dda
    x, fx, kx = hi, f_hi - F, k_hi
    for it in range(max_iter):
        xn = x - fx / kx if kx > 0 else 0.5 * (lo + hi)
        if not lo < xn < hi:
            xn = 0.5 * (lo + hi)
        x = xn
        fa, kx = _axial(bearing, x)
        fx = fa - F
        if abs(fx) <= rtol * F or (hi - lo) <= 1e-15 * A:
            return x
        if fx < 0:
            lo = x
        else:
            hi = x
    raise newton.convergence_error(
        "axial deflection", max_iter, abs(fx) / F, rtol,
        context=f"for Fa={F!r} N (bracket {lo:.6g}..{hi:.6g} m)")


def _axial(bearing, da):
    """(Fa, dFa/dda) of one bearing under pure axial displacement ``da`` (a float)."""
    Fa, _, _, _, J = _forces(bearing, np.array(da), np.array(0.0), jac=True)
    return float(Fa), float(J[0, 0])


def power_law_unloading_ratio(exponent: float = 1.5) -> float:
    r"""Unloading load over preload of a DB/DF pair with F ~ delta^n, 2^n [-].

    With F_a = k delta^n for each bearing and preload P = k delta_0^n, bearing 2
    unloads at x = delta_0, where the external load is k (2 delta_0)^n = 2^n P:
    2.83 for point contact (n = 3/2), 2.16 for line contact (n = 10/9).

    Parameters
    ----------
    exponent : float
        Load–deflection exponent n [-] (3/2 for Hertz point contact).

    References
    ----------
    Harris (2001) §7.5 (preloading); Hamrock & Dowson (1981) eq. (3.34) (n = 3/2).

    Examples
    --------
    >>> round(power_law_unloading_ratio(1.5), 4)
    2.8284
    """
    n = float(check_positive(exponent, "exponent", "-"))
    return 2.0**n


# =========================================================================== the pair
@dataclass(frozen=True)
class DuplexResult:
    """Load sharing in a duplex pair (frozen).  Index 0 = bearing 1, 1 = bearing 2.

    Attributes
    ----------
    pair : DuplexPair
        The pair.
    Fa, Fr : float
        External axial and radial loads [N].
    axial_loads : ndarray, shape (2,)
        Axial load carried by each bearing [N] (>= 0).
    radial_loads : ndarray, shape (2,)
        Radial load carried by each bearing [N].
    axial_deflections : ndarray, shape (2,)
        Axial deflection of each bearing from its free state, in its own loading
        direction [m] (negative: the bearing has separated).
    axial_displacement : float
        Shaft axial displacement x from the preloaded position [m].
    radial_displacement : float
        Shaft radial displacement delta_r [m].
    ball_loads : ndarray, shape (2, Z)
        Ball loads of each bearing [N].
    contact_angles : ndarray, shape (2, Z)
        Contact angles of each bearing [rad].
    stiffness : ndarray, shape (2, 2)
        Tangent stiffness of the pair d(Fa, Fr)/d(x, delta_r) [N/m].
    unloading_load : float
        External axial load at which bearing 2 unloads (DB/DF), or the reverse axial
        load that unloads a DT pair [N].
    separated : bool
        True when a bearing carries no load.
    residual : float
        Largest equilibrium residual [N] (``relative_residual``: over the load scale).
    """

    pair: "DuplexPair"
    Fa: float
    Fr: float
    axial_loads: np.ndarray
    radial_loads: np.ndarray
    axial_deflections: np.ndarray
    axial_displacement: float
    radial_displacement: float
    ball_loads: np.ndarray
    contact_angles: np.ndarray
    stiffness: np.ndarray
    unloading_load: float
    separated: bool
    residual: float

    @property
    def relative_residual(self) -> float:
        """``residual`` over the load scale max(|Fa|, Fr, preload, 1 N) [-]: the measure
        :meth:`DuplexPair.solve` holds below ``rtol``."""
        return float(self.residual / max(abs(self.Fa), self.Fr, self.pair.preload, 1.0))

    @property
    def axial_stiffness(self) -> float:
        """Pair axial stiffness dFa/dx at fixed radial displacement [N/m]."""
        return float(self.stiffness[0, 0])

    @property
    def radial_stiffness(self) -> float:
        """Pair radial stiffness dFr/d(delta_r) at fixed axial displacement [N/m]."""
        return float(self.stiffness[1, 1])

    @functools.cached_property
    def inner_contacts(self):
        """Hertz contacts on the inner races (a, b, p_max, ...), shape (2, Z)."""
        return self.pair.bearing.contacts(self.ball_loads, self.contact_angles, "inner")

    @functools.cached_property
    def outer_contacts(self):
        """Hertz contacts on the outer races, shape (2, Z)."""
        return self.pair.bearing.contacts(self.ball_loads, self.contact_angles, "outer")

    @property
    def max_pressure(self) -> float:
        """Largest contact pressure p_max of the pair (both bearings, both races) [Pa]."""
        return float(max(np.max(self.inner_contacts.p_max), np.max(self.outer_contacts.p_max)))

    @property
    def static_safety(self) -> float:
        r"""Static safety of the pair's most loaded contact, s0 = (4200 MPa / p_max)^3 [-].

        From the actual largest contact pressure of either bearing, preload included
        (:func:`~ballrace.analytic.ratings.static_safety_from_pressure`; ISO 76:2006 bases
        C0 on 4200 MPa); :meth:`DuplexPair.solve` warns when it is below 1.
        """
        from .ratings import static_safety_from_pressure
        return float(static_safety_from_pressure(self.max_pressure))


def _checked(r: DuplexResult) -> DuplexResult:
    """``r``, after a UserWarning where a bearing of the pair works beyond its limits:
    s0 < 1 or, for deep-groove bearings, contact angles beyond
    :data:`~ballrace.analytic.ratings.DEEP_GROOVE_ANGLE_LIMIT` (the pair is not tilted in
    this model)."""
    from . import _operating as op

    if op.silenced():
        return r
    what = f"duplex pair ({r.pair.arrangement})"
    b = r.pair.bearing
    safety = None
    if op.may_be_overloaded(b, r.ball_loads):
        safety = op.safety_message(what, r.static_safety, r.max_pressure)
    op.emit(safety, op.angle_message(what, b, r.ball_loads, r.contact_angles))
    return r


@dataclass(frozen=True)
class DuplexPair:
    r"""Two identical angular-contact ball bearings mounted as a preloaded pair (frozen).

    Parameters
    ----------
    bearing : BallBearing
        Each of the two (identical) bearings.
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face or tandem.
    preload : float
        Axial preload P [N]: 0 (no preload) or in [1e-30, 1e30] N; for DB/DF the axial
        load in each bearing with no external load; for DT a constant axial spring load
        on the pair.  A positive preload below 1e-30 N (e.g. a subnormal float) is refused
        with a ValueError rather than read as zero: it would deflect the rings by less
        than 1e-26 m, which no pair can be set to, and is most likely a slip.

    References
    ----------
    Harris (2001) §7.5; Tata (2012) *Factors influencing the performance of ball and
    roller bearings*, "Preloading"; Hamrock & Dowson (1981) eqs. (3.61)–(3.74).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52,
    ...                            free_contact_angle=np.radians(40))
    >>> lbf = 4.4482216152605
    >>> r = DuplexPair(brg, "DB", preload=3000 * lbf).solve(Fa=2500 * lbf)
    >>> np.round(r.axial_loads / lbf)
    array([4350., 1850.])
    """

    bearing: BallBearing
    arrangement: str = "DB"
    preload: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.bearing, BallBearing):
            raise TypeError("bearing must be a ballrace.BallBearing; got "
                            f"{type(self.bearing).__name__}")
        check_choice(self.arrangement, "arrangement", ARRANGEMENTS)
        # 0 or a physical magnitude in [1e-30, 1e30] N (MIN_MAGNITUDE, MAX_MAGNITUDE): a
        # preload below 1e-30 N (a subnormal one above all) deflects the rings by less
        # than 1e-26 m, nothing a pair can be set to; it is refused rather than read as 0
        p = check_nonnegative(self.preload, "preload", "N", bounded=True)
        if p.ndim:
            raise TypeError("preload must be a scalar [N]")
        object.__setattr__(self, "preload", float(p))

    @functools.cached_property
    def preload_deflection(self) -> float:
        """Axial deflection delta_0 of each bearing under the preload alone [m]."""
        half = 0.5 if self.arrangement == "DT" else 1.0
        try:
            return _inverse(self.bearing, half * self.preload)
        except ValueError:
            raise ValueError(f"preload={self.preload!r} N is beyond the load-deflection range "
                             f"of the pair") from None

    @functools.cached_property
    def unloading_load(self) -> float:
        r"""External axial load at which the pair unloads [N].

        DB/DF: bearing 2 loses its preload at F_u = F_a(2 delta_0, 0) (Harris 2001 §7.5;
        2^{3/2} P = 2.83 P for a frozen contact angle).  DT: the reverse axial load equal
        to the spring preload.
        """
        if self.arrangement == "DT":
            return self.preload
        return float(_forces(self.bearing, 2.0 * self.preload_deflection, 0.0)[0])

    def _state(self, x, dr):
        d0 = self.preload_deflection
        if self.arrangement == "DT":
            d = np.array([d0 + x, d0 + x])
        else:
            d = np.array([d0 + x, d0 - x])
        Fa, Fr, Q, b = _forces(self.bearing, d, np.array([dr, dr]))
        return d, Fa, Fr, Q, b

    def _pair(self, x, dr, jac=False):
        """Resultant (Fa, Fr) of the pair at shaft displacements (x, dr) [N]; with ``jac``
        also its analytic derivative d(Fa, Fr)/d(x, dr) [N/m]."""
        d0 = self.preload_deflection
        dt = self.arrangement == "DT"
        d = np.array([d0 + x, d0 + x]) if dt else np.array([d0 + x, d0 - x])
        out = _forces(self.bearing, d, np.array([dr, dr]), jac=jac)
        Fa, Fr = out[0], out[1]
        Fa_pair = Fa[0] + Fa[1] - self.preload if dt else Fa[0] - Fa[1]
        r = np.array([Fa_pair, Fr[0] + Fr[1]])
        if not jac:
            return r
        J1, J2 = out[4]
        s2 = 1.0 if dt else -1.0               # d(deflection of bearing 2)/dx
        sa = 1.0 if dt else -1.0               # sign of bearing 2's axial load in the pair's
        J = np.array([[J1[0, 0] + sa * s2 * J2[0, 0], J1[0, 1] + sa * J2[0, 1]],
                      [J1[1, 0] + s2 * J2[1, 0], J1[1, 1] + J2[1, 1]]])
        return r, J

    def _jacobian(self, x, dr):
        """Analytic tangent stiffness d(Fa, Fr)/d(x, dr) of the pair [N/m]."""
        return self._pair(x, dr, jac=True)[1]

    def _secant(self, x, dr, h):
        """Central differences of (Fa, Fr) over +-h [N/m] (where the tangent is singular)."""
        J = np.empty((2, 2))
        for k, (ex, er) in enumerate(((h, 0.0), (0.0, h))):
            J[:, k] = (self._pair(x + ex, dr + er) - self._pair(x - ex, dr - er)) / (2 * h)
        return J

    def _newton(self, x, dr, target, scale, radial_free, rtol, max_iter):
        """Damped Newton on the pair's equilibrium from (x, dr) [m]; returns
        (x, dr, residual, Jacobian, relative residual, iterations)."""
        A = self.bearing.curvature_center_distance
        d0 = self.preload_deflection
        r, J = self._pair(x, dr, jac=True)
        r = r - target
        err = np.max(np.abs(r if radial_free else r[:1])) / scale
        it = 0
        while err > rtol and it < max_iter:
            it += 1
            if (J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0] == 0.0) if radial_free else J[0, 0] == 0:
                # no ball loaded yet (all just touching): the tangent is singular, the
                # secant over a small step below the deflections is not
                h = 1e-7 * min(A, max(abs(x), abs(dr), d0, 1e-6 * A))
                J = self._secant(x, dr, h)
            if radial_free:
                try:
                    step = np.linalg.solve(J, -r)
                except np.linalg.LinAlgError:
                    step = np.linalg.lstsq(J, -r, rcond=None)[0]
            else:
                step = np.array([-r[0] / J[0, 0] if J[0, 0] != 0 else 1e-3 * A, 0.0])
            if not np.all(np.isfinite(step)):
                step = np.array([1e-3 * A * np.sign(-r[0] or 1.0), 0.0])
            # step limit, growing with the deflection
            cap = POLICY.duplex_step * A + POLICY.duplex_step_growth * max(abs(x), abs(dr), d0)
            ratio = newton.clip_factor(np.max(np.abs(step)), cap)
            if ratio != 1.0:
                step *= ratio
            f0 = float(np.sum(r**2))

            def accept(t):
                # Armijo on |r|^2 for the (possibly shortened) Newton step
                nonlocal xn, drn, rn, Jn
                xn, drn = x + t * step[0], dr + t * step[1]
                rn, Jn = self._pair(xn, drn, jac=True)
                rn = rn - target
                if not radial_free:
                    rn[1] = 0.0
                return float(np.sum(rn**2)) < (1 - POLICY.armijo * t * ratio) * f0

            xn = drn = rn = Jn = None
            if not newton.backtrack_one(accept, POLICY.duplex_halvings)[1]:
                break
            x, dr, r, J = xn, drn, rn, Jn
            err = np.max(np.abs(r)) / scale
        return x, dr, r, J, err, it

    def _row_start(self, Fa, Fr):
        """(x, dr) of a tandem pair from the single-row solver [m], or None where it fails."""
        from .loaddist import solve as _row_solve
        try:
            u = _row_solve(self.bearing, Fa=0.5 * (Fa + self.preload), Fy=0.5 * Fr,
                           displacements=[np.nan, np.nan, np.nan, 0.0, 0.0]).displacements
        except (ValueError, ConvergenceError):
            return None
        if not np.all(np.isfinite(u)):
            return None
        return float(u[0]) - self.preload_deflection, float(u[1])

    def solve(self, Fa=0.0, Fr=0.0, rtol: float = 1e-10, max_iter: int = 100) -> DuplexResult:
        r"""Load sharing of the pair under external axial and radial loads.

        Parameters
        ----------
        Fa : float
            External axial load on the shaft [N]; positive loads bearing 1.
        Fr : float
            External radial load [N], >= 0.
        rtol : float, optional
            Equilibrium tolerance relative to max(|Fa|, Fr, preload, 1 N) [-].
        max_iter : int, optional
            Newton iteration limit.

        Returns
        -------
        DuplexResult

        Notes
        -----
        Damped Newton in (x, delta_r) from a power-law start.  A tandem pair is one row
        carrying ((F_a + P_s)/2, F_r/2) with its rings parallel; where its Newton fails
        (little net thrust against the radial load: the equilibrium lies near the groove
        bottom, far from the thrust-only start) it restarts from the single-row solution
        (:func:`ballrace.analytic.loaddist.solve` with the tilts imposed zero).

        Raises
        ------
        ConvergenceError
            If equilibrium is not reached (message gives residual and iterations).
        ValueError
            If a tandem pair is loaded against its contact direction beyond its preload,
            or a pair without preload has no load at all in its axial direction.

        References
        ----------
        Harris (2001) §7.5; Hamrock & Dowson (1981) eqs. (3.61)–(3.74).

        Examples
        --------
        >>> import ballrace
        >>> brg = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52,
        ...                            free_contact_angle=np.radians(40))
        >>> pair = DuplexPair(brg, "DB", preload=5000.0)
        >>> r = pair.solve(Fa=20000.0)
        >>> r.separated, round(float(r.axial_loads[0]))
        (True, 20000)
        """
        Fa = float(as_array(Fa, "Fa"))
        Fr = float(check_nonnegative(Fr, "Fr", "N"))
        P = self.preload
        if self.arrangement == "DT" and Fa + P < 0:
            raise ValueError(f"Fa must be >= -preload = {-P:g} N for a tandem (DT) pair: it "
                             f"carries thrust in one direction only; got {Fa!r}")
        if self.arrangement != "DT" and P == 0 and Fa == 0 and Fr > 0:
            log.info("duplex: no preload and no axial load; the radial load alone sets "
                     "the axial position")
        cap = 2.0 * BallModel.of(self.bearing).capacity
        if max(abs(Fa) + P, Fr) > cap:
            raise ValueError(
                f"Fa={Fa!r} N, Fr={Fr!r} N (preload {P:g} N) are beyond the load-deflection "
                f"range of the pair: its {2 * self.bearing.n_balls} balls carry at most "
                f"{cap:.4g} N at a contact approach of {MAX_APPROACH_RATIO:g} D")
        scale = max(abs(Fa), Fr, P, 1.0)                 # 1 N floor: tiny loads
        target = np.array([Fa, Fr])
        d0 = self.preload_deflection
        # start: rough power-law split for x, small radial displacement
        if self.arrangement == "DT":
            x = _inverse(self.bearing, 0.5 * (Fa + P)) - d0 if Fa + P > 0 else 0.0
        else:
            # beyond the unloading load bearing 2 is off and bearing 1 carries Fa alone
            x = 0.0 if Fa == 0 else float(np.sign(Fa)) * (
                _inverse(self.bearing, abs(Fa)) - d0 if abs(Fa) >= self.unloading_load
                else min(_inverse(self.bearing, abs(Fa) + P) - d0, d0))
        radial_free = Fr > 0
        x, dr, r, J, err, it = self._newton(x, 0.0, target, scale, radial_free, rtol, max_iter)
        if not err <= rtol and self.arrangement == "DT" and radial_free:
            # A tandem pair is one row carrying ((F_a + P_s)/2, F_r/2) with its rings kept
            # parallel.  With little net thrust against the radial load its equilibrium lies
            # far from the thrust-only start (at zero net thrust the balls sit at the groove
            # bottom, delta_a = -A sin(beta_f)), where the damped Newton above crawls; the
            # single-row solver (tilts imposed zero) gives a start next to it, polished here.
            start = self._row_start(Fa, Fr)
            if start is not None:
                x2, dr2, r2, J2, err2, it2 = self._newton(start[0], start[1], target, scale,
                                                          radial_free, rtol, max_iter)
                it += it2
                if err2 <= rtol or not err2 >= err:
                    x, dr, r, J, err = x2, dr2, r2, J2, err2
        if not err <= rtol:
            d, _, _, Q, b = self._state(x, dr)
            lim = MAX_APPROACH_RATIO * self.bearing.ball_diameter
            if np.max(Q) > 0 and _approach(self.bearing, d, dr) > lim:
                raise ValueError(f"Fa={Fa!r} N, Fr={Fr!r} N are beyond the load-deflection "
                                 f"range of the pair: a ball approach exceeds "
                                 f"{MAX_APPROACH_RATIO:g} D = {lim:.3g} m")
            if _past_groove(self.bearing, d, dr):
                raise ValueError(f"Fa={Fa!r} N, Fr={Fr!r} N have no equilibrium within the "
                                 "grooves: they need a ball contact at 90 deg or more from "
                                 "the groove bottom (beyond the range of the model)")
            raise newton.convergence_error("duplex pair equilibrium", it, err, rtol,
                                           context=f"(Fa={Fa!r} N, Fr={Fr!r} N)")
        d, Fa_b, Fr_b, Q, b = self._state(x, dr)
        K = J                                       # analytic, at the solution
        return _checked(DuplexResult(
            pair=self, Fa=Fa, Fr=Fr, axial_loads=np.maximum(Fa_b, 0.0), radial_loads=Fr_b,
            axial_deflections=d, axial_displacement=float(x), radial_displacement=float(dr),
            ball_loads=Q, contact_angles=b, stiffness=K, unloading_load=self.unloading_load,
            separated=bool(np.any(np.max(Q, axis=-1) == 0.0)),
            residual=float(np.max(np.abs(r if radial_free else r[:1])))))

    # ------------------------------------------------------------------ shaft seat
    # The seat contract (ballrace.analytic.contract.SeatBearing): two ball rows.  Plain
    # class attributes, not dataclass fields.
    accepts_clearance = False           # the rows keep their preload
    carries_axial = True
    life_exponent = 3.0

    @property
    def seat_name(self) -> str:
        """"pair DB", "pair DF" or "pair DT" (for tables)."""
        return "pair " + self.arrangement

    def seat_rows(self, direction, offset, row_spacing, clearance):
        """The pair as a shaft seat: its two rows (bearing 1, bearing 2), each at the
        preload deflection delta_0 plus the seat's offset, and kept there at the start;
        see :meth:`ballrace.analytic.contract.SeatBearing.seat_rows` (direction [-],
        offset [m], row_spacing [m], clearance [m] or None).

        The rows follow the arrangement: in DT both take thrust the same way; in DB (O) a
        row carrying +x shaft thrust sits on the -x side of the seat, in DF (X) on the +x
        side."""
        from .contract import RowMount
        from .loaddist import RingModel
        if self.bearing.n_rows != 1:
            raise ValueError("bearing must be single-row (n_rows=1); got "
                             f"n_rows={self.bearing.n_rows}")
        row = RingModel(self.bearing, clearance)     # one model: both rows evaluated together
        d = direction
        d0 = self.preload_deflection + offset
        h = 0.5 * row_spacing
        if self.arrangement == "DT":
            return (RowMount(row, d, -h, d0, False), RowMount(row, d, h, d0, False))
        s = -1.0 if self.arrangement == "DB" else 1.0
        return (RowMount(row, d, s * d * h, d0, False), RowMount(row, -d, -s * d * h, d0, False))

    def spring_axial_load(self, direction) -> float:
        """The seat's reaction gains ``-direction * P`` for a DT pair's spring preload P
        [N] (Fa = 2 F(delta) - P); 0 for DB and DF.  direction: +1 or -1 [-]."""
        if self.arrangement == "DT":
            return -direction * self.preload
        return 0.0

    def equivalent_load(self, radial_load, axial_load, contact_angle=None):
        """None: a preloaded pair has no catalog (C/P)^3 life here (its rows' ISO/TS 16281
        lives apply); radial_load, axial_load [N], contact_angle [rad] unused."""
        return None

    def seat_warnings(self, what, results, tilt) -> tuple:
        """Static safety, contact angle and tilt messages of the seat's two rows
        (:func:`ballrace.analytic.loaddist.seat_warnings`); tilt [rad]."""
        from .loaddist import seat_warnings
        return seat_warnings(self.bearing, what, results, tilt)
