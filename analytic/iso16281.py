r"""ISO/TS 16281:2008 reference rating life L10r from a bearing's internal load distribution.

Any static (or high-speed) load-distribution result — ball loads Q_j per ball, with
clearance, tilt and shifted contact angles already in them — gives the raceway lives and
the bearing's basic reference rating life, step by step (ISO/TS 16281:2008 §5 for
single-row ball bearings):

1. **Raceway capacities tied to the catalogue rating C** (ISO 281 C, which contains
   b_m = 1.3 and the f_c table) — eqs. for Q_ci, Q_ce:

   .. math::
       Q_{ci} = \frac{C}{0.407\, Z \cos\alpha\, i^{0.7}}\left(1 + T^{10/3}\right)^{3/10},\qquad
       Q_{ce} = \frac{C}{0.389\, Z \cos\alpha\, i^{0.7}}\left(1 + T^{-10/3}\right)^{3/10}

   .. math::
       T = 1.044 \left(\frac{1-\gamma}{1+\gamma}\right)^{1.72}
           \left(\frac{f_i (2 f_e - 1)}{f_e (2 f_i - 1)}\right)^{0.41},
       \qquad \gamma = \frac{D\cos\alpha}{D_{pw}}

   α is the *nominal* contact angle, the one C is rated at (ISO 281:2007 §6.1.1): 0 for a
   radial deep-groove bearing, the design angle for an angular-contact one
   (:attr:`ballrace.BallBearing.nominal_contact_angle`).  The free contact angle a
   deep-groove bearing's clearance gives is not a rating angle: with C fixed,
   Q_c ∝ 1/cos α, so using the 7.56° free angle of a 6305 size with 10 µm clearance
   would raise both Q_c by 1/cos α (and shift T slightly through γ) and L10r ∝ Q_c³ by
   1/cos³ α ≈ 1.0266 — L10r 2.65 % too long.  The clearance acts through the ball loads.

   T is the ratio of the inner- to the outer-ring rating of Lundberg & Palmgren, so that
   the ring ratings C_i = 0.407 Z cos α Q_ci and C_e = 0.389 Z cos α Q_ce combine back to
   exactly C: (C_i^(-10/3) + C_e^(-10/3))^(-3/10) = C.  0.407 = J_r/J_1 and
   0.389 = J_r/J_2 are Lundberg & Palmgren's load-integral ratios at ε = 0.5.
2. **Equivalent ball loads** of each raceway: the ring that rotates relative to the load
   meets every ball load (cubic mean); the stationary one keeps its loaded points
   (10/3 mean):

   .. math::
       Q_{e,rot} = \left(\frac{1}{Z}\sum_j Q_j^3\right)^{1/3},\qquad
       Q_{e,stat} = \left(\frac{1}{Z}\sum_j Q_j^{10/3}\right)^{3/10}
3. **Bearing life** (Weibull slope 10/9):

   .. math::
       L_{10r} = \left[\left(\frac{Q_{ci}}{Q_{ei}}\right)^{-10/3}
                 + \left(\frac{Q_{ce}}{Q_{ee}}\right)^{-10/3}\right]^{-9/10}
4. **Equivalent reference load** P_ref = C / L10r^(1/3) and the modified reference rating
   life L_nmr = a1 a_ISO(κ, e_C C_u / P_ref) L10r (ISO/TS 16281 §5.3 with ISO 281:2007
   §9.3).

For the Stribeck distribution of a zero-clearance radial bearing these steps return
L10r = (C/F_r)³ up to the discreteness of the ball set — the design intent of the tie to C.
How this differs from :func:`ballrace.analytic.life.bearing_life` (Lundberg & Palmgren's
1947 constant, no b_m) is measured in ``docs/life.md``.

References
----------
ISO/TS 16281:2008 *Rolling bearings — Methods for calculating the modified reference rating
life for universally loaded bearings*, §5 (transcribed independently in open public
code, against which the constants here were checked); ISO/TR 1281-1:2008 (the J
integrals); Harris, T.A. (2001) *Rolling Bearing Analysis* 4th ed. §18.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from ._checks import (check_choice, check_instance, check_integer, check_nonnegative,
                      check_positive, check_range)

__all__ = ["ReferenceRatingLife", "ReferenceLifeMethods", "raceway_capacities",
           "reference_rating_life"]

log = logging.getLogger(__name__)


def raceway_capacities(C, n_balls, ball_diameter, pitch_diameter, f_inner, f_outer,
                       contact_angle=0.0, n_rows: int = 1):
    r"""Basic dynamic load ratings of the inner and outer raceway, Q_ci and Q_ce [N].

    See the module notes (ISO/TS 16281:2008 §5.2).

    Parameters
    ----------
    C : float
        Basic dynamic load rating of the bearing (ISO 281) [N], > 0.
    n_balls : int
        Z [-].
    ball_diameter, pitch_diameter : float
        D, D_pw [m].
    f_inner, f_outer : float
        Groove conformities r/D [-], > 0.5.
    contact_angle : float
        Nominal contact angle α [rad], in [0, pi/2): the angle C is rated at (0 for a
        radial deep-groove bearing, the design angle for an angular-contact one), not the
        free contact angle of its clearance.
    n_rows : int
        Rows i [-].

    Returns
    -------
    (Q_ci, Q_ce) : floats [N].

    Examples
    --------
    >>> qi, qe = raceway_capacities(22500.0, 7, 0.0115, 0.0435, 0.52, 0.53)
    >>> round(qi), round(qe)
    (8099, 17585)
    """
    C = float(check_positive(C, "C", "N", bounded=True))
    Z = float(check_integer(n_balls, "n_balls", 1))
    D = float(check_positive(ball_diameter, "ball_diameter", "m", bounded=True))
    dm = float(check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True))
    fi = float(check_range(f_inner, "f_inner", 0.5, None, unit="-"))
    fo = float(check_range(f_outer, "f_outer", 0.5, None, unit="-"))
    a = float(check_range(contact_angle, "contact_angle", 0.0, np.pi / 2, low_inclusive=True,
                          unit="rad"))
    i = float(check_integer(n_rows, "n_rows", 1))
    g = D * np.cos(a) / dm
    T = (1.044 * ((1.0 - g) / (1.0 + g)) ** 1.72
         * (fi * (2.0 * fo - 1.0) / (fo * (2.0 * fi - 1.0))) ** 0.41)
    base = C / (Z * np.cos(a) * i ** 0.7)
    Qci = base / 0.407 * (1.0 + T ** (10.0 / 3.0)) ** 0.3
    Qce = base / 0.389 * (1.0 + T ** (-10.0 / 3.0)) ** 0.3
    return float(Qci), float(Qce)


class ReferenceLifeMethods:
    """Hours, a_ISO and modified life of an ISO/TS 16281 reference rating life: the methods
    shared by the ball (:class:`ReferenceRatingLife`) and the roller
    (:class:`ballrace.analytic.roller.life.ReferenceRatingLife`) results, which give
    ``L10r``, ``P_ref`` and the a_ISO function of their bearing type
    (``life_modification_factor()``)."""

    def hours(self, speed_rpm: float):
        """L10r in hours at ``speed_rpm`` [rev/min] [h]."""
        n = check_positive(speed_rpm, "speed_rpm", "rev/min")
        return _s(self.L10r * 1e6 / (60.0 * n))

    def a_iso(self, *, kappa, contamination, fatigue_limit, ep_additives=False):
        """a_ISO(κ, e_C C_u / P_ref) of the bearing type (ISO/TS 16281 §5.3; ISO 281:2007
        §9.3.3) [-]; the parameters as in :meth:`modified`."""
        return _s(self.life_modification_factor()(kappa, contamination, fatigue_limit,
                                                  self.P_ref, ep_additives=ep_additives))

    def modified(self, *, kappa, contamination, fatigue_limit, reliability=0.9,
                 ep_additives=False):
        """Modified reference rating life L_nmr = a1 a_ISO L10r [1e6 rev].

        Parameters
        ----------
        kappa : float
            Viscosity ratio [-], >= 0.1.
        contamination : float
            e_C [-], in [0, 1].
        fatigue_limit : float
            C_u [N] (e.g. :func:`ballrace.analytic.iso281.fatigue_load_limit_hertz`).
        reliability : float
            0.90 … 0.9995 [-].
        ep_additives : bool
            Lubricant with effective EP additives.
        """
        from .iso281 import reliability_factor

        a1 = reliability_factor(reliability)
        return _s(a1 * self.a_iso(kappa=kappa, contamination=contamination,
                                   fatigue_limit=fatigue_limit,
                                   ep_additives=ep_additives) * self.L10r)


@dataclass(frozen=True)
class ReferenceRatingLife(ReferenceLifeMethods):
    """ISO/TS 16281 reference rating life (frozen; arrays over the load cases of a
    vectorized result, floats for one load case).

    Attributes
    ----------
    L10r : Basic reference rating life [1e6 rev].
    L_inner, L_outer : Raceway lives (Q_c/Q_e)^3 [1e6 rev].
    Q_ci, Q_ce : Raceway dynamic load ratings [N].
    Q_ei, Q_ee : Equivalent ball loads of the raceways [N].
    P_ref : Dynamic equivalent reference load C / L10r^(1/3) [N].
    C : Basic dynamic load rating used [N].
    rotating : Ring rotating relative to the load ("inner" or "outer").
    """

    L10r: float
    L_inner: float
    L_outer: float
    Q_ci: float
    Q_ce: float
    Q_ei: float
    Q_ee: float
    P_ref: float
    C: float
    rotating: str

    def life_modification_factor(self):
        """a_ISO function of radial ball bearings
        (:func:`ballrace.analytic.iso281.life_modification_factor`)."""
        from .iso281 import life_modification_factor

        return life_modification_factor


def reference_rating_life(bearing, result, *, dynamic_rating=None, rotating: str = "inner",
                          nominal_contact_angle=None) -> ReferenceRatingLife:
    r"""ISO/TS 16281 basic reference rating life L10r from any load-distribution result.

    A roller bearing (:class:`ballrace.analytic.roller.RollerBearing`, or any bearing
    with a ``reference_rating_life`` method) is handed to its own method: the lamina life
    of ISO/TS 16281 (:func:`ballrace.analytic.roller.life.reference_rating_life`), whose
    result has the same L10r, L_inner, L_outer, Q_ci, Q_ce, Q_ei, Q_ee, P_ref, C and
    rotating.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        Geometry (D, Z, D_pw, f_i, f_o, rows).
    result : object
        A static solution with ``ball_loads`` [N] (one per ball, 0 for unloaded ones, a
        single load case; an optional ``ball_loads_outer`` for the outer raceway), or a
        high-speed solution (:class:`ballrace.analytic.highspeed.HighSpeedResult`) whose
        ``inner_loads`` and ``outer_loads`` [N] differ by the centrifugal force.
    dynamic_rating : float, optional
        Basic dynamic load rating C [N]; default the bearing's ISO 281:2007 rating at the
        nominal contact angle (:func:`ballrace.analytic.ratings.dynamic_rating`).
    rotating : {"inner", "outer"}
        Ring rotating relative to the load.
    nominal_contact_angle : float, optional
        α [rad] of the rating and the raceway capacities, in [0, pi/2); default the
        bearing's :attr:`~ballrace.BallBearing.nominal_contact_angle` (0 for a
        deep-groove bearing, whatever free contact angle its clearance gives; ISO/TS
        16281:2008 §5.2 takes Q_c from C at the nominal angle).

    Returns
    -------
    ReferenceRatingLife

    References
    ----------
    ISO/TS 16281:2008 §5 (steps in the module notes).

    Examples
    --------
    6305-type deep-groove bearing (D = 11.5 mm, Z = 7, D_pw = 43.5 mm, f_i = 0.52,
    f_o = 0.53), 1 kN radial load at zero clearance:

    >>> import ballrace
    >>> brg = ballrace.BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=0.0)
    >>> r = reference_rating_life(brg, brg.radial(1000.0))
    >>> round(r.C), round(r.L10r)
    (22381, 11518)

    With 10 µm diametral clearance the free contact angle is 7.56°, but C and Q_c stay
    at the nominal angle 0; the clearance shortens the life through the ball loads:

    >>> brg = ballrace.BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=10e-6)
    >>> r = reference_rating_life(brg, brg.radial(1000.0))
    >>> round(r.C), round(r.L10r)
    (22381, 9513)
    """
    from .bearing import BallBearing
    from .ratings import dynamic_rating as _rating

    if not isinstance(bearing, BallBearing) and callable(
            getattr(bearing, "reference_rating_life", None)):
        # a roller bearing computes its own (lamina) life: no import of it here
        if nominal_contact_angle is not None:
            raise ValueError("nominal_contact_angle is for ball bearings; a roller bearing "
                             "is rated at its own contact angle (give dynamic_rating [N] to "
                             f"use another C); got {nominal_contact_angle!r}")
        return bearing.reference_rating_life(result, dynamic_rating=dynamic_rating,
                                             rotating=rotating)
    check_instance(bearing, "bearing", BallBearing)
    check_choice(rotating, "rotating", ("inner", "outer"))
    if hasattr(result, "ball_loads"):
        Qi, Qo = result.ball_loads, getattr(result, "ball_loads_outer", None)
    elif hasattr(result, "inner_loads") and hasattr(result, "outer_loads"):
        Qi, Qo = result.inner_loads, result.outer_loads           # HighSpeedResult
    else:
        raise TypeError(f"result must have ball_loads (static solution) or inner_loads and "
                        f"outer_loads (high-speed solution); got {type(result).__name__}")
    Qi = check_nonnegative(np.asarray(Qi, dtype=float), "ball_loads", "N")
    if Qi.ndim < 1 or Qi.shape[-1] < 3:
        raise ValueError(f"result.ball_loads must have one load per ball (>= 3) on its last "
                         f"axis (leading axes: load cases); got shape {Qi.shape}")
    Qo = Qi if Qo is None else check_nonnegative(np.asarray(Qo, dtype=float),
                                                 "ball_loads_outer", "N")
    if Qo.shape != Qi.shape:
        raise ValueError(f"ball_loads_outer must have the shape of ball_loads {Qi.shape}; "
                         f"got {Qo.shape}")
    dead = ~np.any(Qi > 0, axis=-1) & ~np.any(Qo > 0, axis=-1)
    if np.any(dead):
        raise ValueError("ball_loads are all zero: the bearing carries no load (infinite life)"
                         + ("" if Qi.ndim == 1 else f" in load case {np.argwhere(dead)[0]}"))
    a = (bearing.nominal_contact_angle if nominal_contact_angle is None
         else float(check_range(nominal_contact_angle, "nominal_contact_angle", 0.0,
                                np.pi / 2, low_inclusive=True, unit="rad")))
    C = (float(_rating(bearing, contact_angle=a)) if dynamic_rating is None
         else float(check_positive(dynamic_rating, "dynamic_rating", "N", bounded=True)))
    Qci, Qce = raceway_capacities(C, bearing.n_balls, bearing.ball_diameter,
                                  bearing.pitch_diameter, bearing.f_inner, bearing.f_outer, a,
                                  getattr(bearing, "n_rows", 1))
    Z = Qi.shape[-1]
    p_i, p_o = (3.0, 10.0 / 3.0) if rotating == "inner" else (10.0 / 3.0, 3.0)
    Qei = np.mean(Qi ** p_i, axis=-1) ** (1.0 / p_i)
    Qee = np.mean(Qo ** p_o, axis=-1) ** (1.0 / p_o)
    with np.errstate(divide="ignore"):
        Li = np.where(Qei > 0, (Qci / np.where(Qei > 0, Qei, 1.0)) ** 3, np.inf)
        Lo = np.where(Qee > 0, (Qce / np.where(Qee > 0, Qee, 1.0)) ** 3, np.inf)
        L = (Li ** (-10.0 / 9.0) + Lo ** (-10.0 / 9.0)) ** -0.9
    if Z != bearing.n_balls:
        from ..errors import warn

        warn(f"reference_rating_life: {Z} ball loads for a bearing of {bearing.n_balls} "
             "balls")
    return ReferenceRatingLife(L10r=_s(L), L_inner=_s(Li), L_outer=_s(Lo), Q_ci=Qci,
                               Q_ce=Qce, Q_ei=_s(Qei), Q_ee=_s(Qee),
                               P_ref=_s(C / L ** (1.0 / 3.0)), C=C, rotating=rotating)


def _s(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x
