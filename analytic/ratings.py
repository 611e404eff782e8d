r"""Basic load ratings of radial and angular-contact ball bearings (ISO 281, ABMA 9, ISO 76).

Everything here is SI at the interface (m, N, rad); the standards' own unit system
(N with the ball diameter in mm) is used only inside the formulas, as the tables demand.

* :func:`dynamic_rating` — basic dynamic radial load rating C, ISO 281:2007 (with
  b_m = 1.3) or ABMA Std 9-1990 / ISO 281:1990 (no b_m);
* :func:`static_rating` — basic static radial load rating C0 = f0 i Z D² cos α (ISO 76);
* :func:`static_rating_pressure` — the contact pressure that C0 stands for (4200 MPa),
  computed with the library's exact Hertz solution, as a check of the f0 table;
* :func:`static_equivalent_load`, :func:`static_safety_factor` — ISO 76 P0 = X0 Fr + Y0 Fa
  and s0 = C0/P0;
* :func:`static_safety_from_pressure` — s0 from the largest contact pressure of an actual
  load distribution, s0 = (4200 MPa / p_max)^3, what the solvers' ``static_safety``
  reports;
* :data:`PERMISSIBLE_MISALIGNMENT`, :data:`DEEP_GROOVE_ANGLE_LIMIT` — the limits beyond
  which the solvers warn that a bearing is tilted more than its type tolerates, or a
  deep-groove bearing runs as an angular-contact one.

Each rating function takes either plain numbers ``(ball_diameter, n_balls,
pitch_diameter, contact_angle, n_rows)`` or a bearing object that has those attributes
(:class:`ballrace.BallBearing`: ``ball_diameter``, ``n_balls``, ``pitch_diameter``,
``nominal_contact_angle``, ``n_rows``).  The angle of every rating is the *nominal*
contact angle α of ISO 281:2007 §6.1.1 and ISO 76:2006 §5.1.1 — 0 for a radial
deep-groove bearing, the design angle for an angular-contact one — never the free
contact angle a deep-groove bearing's clearance gives (see
:class:`ballrace.BallBearing`).

Tables and their checks
-----------------------
``FC_TABLE`` (f_c, single-row radial and single/double-row angular-contact groove ball
bearings) is the 40-value table 0.01 … 0.40 of ISO 281:2007 Table 2; at every node of the
ANSI/AFBMA Std 9-1990 Table 2 (0.05 … 0.10 by 0.01, then by 0.02) the
values are identical.  ``FC_TABLE_DOUBLE_ROW_RADIAL`` is that table's second column
(0.05 … 0.40 only).  ``F0_TABLE`` (ISO 76:2006 Table 2, radial and angular-contact
groove ball bearings) is checked in ``tests/test_ratings.py`` against its definition:
with Q_max = 5 F/(i Z cos α), f_i = 0.52, f_o = 0.53, E = 207 GPa, ν = 0.3, the exact
Hertz pressure at F = C0 is 4200 MPa ± 0.15 % at every one of the 41 nodes.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from ._checks import (broadcast, check_choice, check_instance, check_integer, check_nonnegative,
                      check_positive, check_range)
from .materials import Material

__all__ = [
    "STANDARDS",
    "FC_GAMMA",
    "FC_TABLE",
    "FC_TABLE_DOUBLE_ROW_RADIAL_GAMMA",
    "FC_TABLE_DOUBLE_ROW_RADIAL",
    "F0_GAMMA",
    "F0_TABLE",
    "ISO76_STEEL",
    "STATIC_RATING_PRESSURE",
    "STATIC_RATING_PRESSURES",
    "PERMISSIBLE_MISALIGNMENT",
    "DEEP_GROOVE_ANGLE_LIMIT",
    "LBF",
    "INCH",
    "fc_factor",
    "fc_inch_pound",
    "f0_factor",
    "dynamic_rating",
    "static_rating",
    "static_rating_pressure",
    "StaticRatingPressure",
    "static_equivalent_load",
    "static_safety_factor",
    "static_safety_from_pressure",
    "bearing_type",
    "bearing_numbers",
]

log = logging.getLogger(__name__)

#: Rating standards understood by :func:`dynamic_rating`.
STANDARDS = ("ISO 281:2007", "ABMA 9-1990")

#: Pound-force [N] and inch [m] (exact definitions) for the inch–pound boundary.
LBF = 4.4482216152605
INCH = 0.0254

#: D cos α / d_m nodes of :data:`FC_TABLE` [-].
FC_GAMMA = np.round(np.arange(1, 41) * 0.01, 2)
#: f_c [N/mm^1.8] for single-row radial and single/double-row angular-contact groove ball
#: bearings, ISO 281:2007 Table 2 (= ANSI/AFBMA Std 9 Table 2 "metric" at its nodes).
FC_TABLE = np.array([
    29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
    56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
    59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
    55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4])
#: D cos α / d_m nodes of the double-row radial-contact column (ANSI/AFBMA Std 9-1990 Table 2) [-].
FC_TABLE_DOUBLE_ROW_RADIAL_GAMMA = np.array([
    0.05, 0.06, 0.07, 0.08, 0.09, 0.10, 0.12, 0.14, 0.16, 0.18, 0.20,
    0.22, 0.24, 0.26, 0.28, 0.30, 0.32, 0.34, 0.36, 0.38, 0.40])
#: f_c [N/mm^1.8] for double-row radial-contact groove ball bearings (ANSI/AFBMA Std 9
#: Table 2, second column; ISO 281 Table 2).
FC_TABLE_DOUBLE_ROW_RADIAL = np.array([
    44.2, 46.5, 48.4, 50.0, 51.4, 52.6, 54.5, 55.7, 56.5, 56.8, 56.8,
    56.5, 55.9, 55.1, 54.1, 53.0, 51.8, 50.4, 48.9, 47.4, 45.8])

#: D cos α / d_m nodes of :data:`F0_TABLE` [-].
F0_GAMMA = np.round(np.arange(0, 41) * 0.01, 2)
#: f0 [N/mm²] for radial and angular-contact groove ball bearings, ISO 76:2006 Table 2
#: (basis: 4200 MPa, groove radii 0.52 D inner / 0.53 D outer, E = 207 GPa, ν = 0.3).
F0_TABLE = np.array([
    14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,
    16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,
    14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
    11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4])

#: The steel ISO 76 bases f0 on (E = 2.07e5 N/mm², ν = 0.3).
ISO76_STEEL = Material(E=207e9, nu=0.3, name="ISO 76 reference steel")
#: Contact pressure at the centre of the most heavily loaded ball–raceway contact that
#: defines C0 for radial and angular-contact ball bearings (ISO 76:2006 §3.2) [Pa].
STATIC_RATING_PRESSURE = 4200e6
#: The contact pressure that defines C0, by bearing kind [Pa], with the exponent n of
#: load ~ p^n (point contact 3, line contact 2): ISO 76:2006 (4600 MPa self-aligning ball
#: bearings, 4200 MPa other ball bearings, 4000 MPa roller bearings; the values as
#: reproduced by the SKF rolling bearings catalogue, "Static bearing loads").
STATIC_RATING_PRESSURES = {"ball": (4200e6, 3), "self-aligning ball": (4600e6, 3),
                           "roller": (4000e6, 2)}

#: Permissible misalignment (tilt of the inner ring relative to the outer ring) by bearing
#: type [rad], above which the solvers warn (:func:`bearing_type` gives the key):
#:
#: * ``"deep-groove"``: 10 arcmin = 2.91 mrad, the upper end of the 2-10 arcmin that the
#:   SKF rolling bearings catalogue gives for single-row deep-groove ball bearings
#:   ("Misalignment"; RBC Bearings' guide, 0.0005-0.003 in/in = 0.5-3 mrad, agrees);
#: * ``"angular-contact"``: 2 arcmin = 0.58 mrad, the value commonly quoted for
#:   single-row angular-contact ball bearings, which tolerate very little tilt; this
#:   figure could not be checked against a manufacturer's table here.
#:
#: Guide values for quiet running and full life; misalignment beyond them brings edge
#: loading, noise and a shorter life, not immediate failure.
PERMISSIBLE_MISALIGNMENT = {"deep-groove": float(np.radians(10.0 / 60.0)),
                            "angular-contact": float(np.radians(2.0 / 60.0))}

#: Largest operating contact angle [rad] (30 deg) at which a deep-groove bearing (nominal
#: contact angle 0) is still treated as a radial bearing; beyond it the solvers warn that
#: it runs as an angular-contact bearing, whose life its ratings (C, C0 and X/Y at 0 deg)
#: do not describe.  A screening limit chosen here, not a standard's value: the largest
#: pure thrust SKF permits on a single-row deep-groove bearing (Fa <= 0.5 C0, SKF
#: catalogue, deep groove ball bearings, "Loads") puts a 6208-size bearing at 21-24 deg
#: for diametral clearances of 5-30 um (this library's load distribution), and the
#: radial-bearing X/Y table of ISO 281:2007 (e <= 0.44) corresponds, by e ~ 1.5 tan(alpha),
#: to about 16 deg.
DEEP_GROOVE_ANGLE_LIMIT = float(np.radians(30.0))

_B_M = {"ISO 281:2007": 1.3, "ABMA 9-1990": 1.0}


# --------------------------------------------------------------------------- inputs
def bearing_numbers(bearing_or_D, n_balls=None, pitch_diameter=None, contact_angle=None,
                    n_rows=1):
    """Return ``(D, Z, d_m, alpha, i)`` from plain numbers or a bearing object.

    A bearing object is anything with ``ball_diameter``, ``n_balls``, ``pitch_diameter``
    and ``nominal_contact_angle`` (and optionally ``n_rows``) attributes, such as
    :class:`ballrace.BallBearing`.  ``contact_angle`` (the standards' *nominal* angle α,
    ISO 281:2007 §6.1.1, ISO 76:2006 §5.1.1) defaults to 0 for plain numbers and to the
    bearing's ``nominal_contact_angle`` for a bearing object — 0 for a deep-groove
    bearing even when its clearance gives it a free contact angle.  A bearing object
    without ``nominal_contact_angle`` is a ``TypeError`` (its free contact angle is not a
    rating angle).  Checks the values and names the bad argument.

    Examples
    --------
    >>> bearing_numbers(0.0127, 9, 0.065)
    (0.0127, 9, 0.065, 0.0, 1)
    >>> import ballrace
    >>> brg = ballrace.BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=10e-6)
    >>> bearing_numbers(brg)[3]        # free contact angle 7.56 deg; rated at 0
    0.0
    """
    if hasattr(bearing_or_D, "ball_diameter"):
        b = bearing_or_D
        D, Z, dm = b.ball_diameter, b.n_balls, b.pitch_diameter
        if contact_angle is None:
            if getattr(b, "nominal_contact_angle", None) is None:
                raise TypeError("the bearing object has no nominal_contact_angle [rad] (the "
                                "rating angle of ISO 281 / ISO 76); pass contact_angle")
            alpha = b.nominal_contact_angle
        else:
            alpha = contact_angle
        i = getattr(b, "n_rows", 1)
        names = ("bearing.ball_diameter", "bearing.n_balls", "bearing.pitch_diameter",
                 "contact_angle" if contact_angle is not None
                 else "bearing.nominal_contact_angle", "bearing.n_rows")
    else:
        names = ("bearing_or_D (ball_diameter)", "n_balls", "pitch_diameter", "contact_angle",
                 "n_rows")
        D, Z, dm, alpha, i = bearing_or_D, n_balls, pitch_diameter, contact_angle, n_rows
        if Z is None or dm is None:
            raise TypeError("give a bearing object, or ball_diameter, n_balls and pitch_diameter")
        alpha = 0.0 if alpha is None else alpha
    D = float(_scalar_of(check_positive(D, names[0], "m", bounded=True), names[0]))
    dm = float(_scalar_of(check_positive(dm, names[2], "m", bounded=True), names[2]))
    Z = _scalar_of(check_integer(Z, names[1], 3), names[1])
    i = _scalar_of(check_integer(i, names[4], 1), names[4])
    if i not in (1, 2):
        raise ValueError(f"{names[4]} must be 1 or 2; got {i!r}")
    alpha = float(_scalar_of(check_range(alpha, names[3], 0.0, np.pi / 2, low_inclusive=True,
                                         unit="rad"), names[3]))
    if D >= dm:
        raise ValueError(f"ball_diameter must be < pitch_diameter [m]; got D={D!r}, d_m={dm!r}")
    return D, int(Z), dm, alpha, int(i)


def _scalar_of(arr: np.ndarray, name: str) -> float:
    """The single value of a checked 0-d array; ``TypeError`` for an array."""
    if arr.ndim:
        raise TypeError(f"{name} must be a single number, not an array; got shape {arr.shape}")
    return float(arr)


# --------------------------------------------------------------------------- factors
def fc_factor(gamma, *, double_row_radial: bool = False):
    r"""Rating factor f_c for ball bearings, linearly interpolated in γ = D cos α / d_m.

    Parameters
    ----------
    gamma : float or array_like
        D cos α / d_m [-], in [0.01, 0.40] (in [0.05, 0.40] for ``double_row_radial``).
    double_row_radial : bool
        Use the column for double-row radial-contact groove ball bearings.

    Returns
    -------
    float or ndarray
        f_c [N/mm^1.8] (C in N with D in mm).

    References
    ----------
    ISO 281:2007 Table 2; ANSI/AFBMA Std 9-1990 Table 2.  "Values for
    intermediate D cos α / d_m are obtained by linear interpolation."

    Examples
    --------
    >>> float(fc_factor(0.10)), round(float(fc_factor(0.105)), 3)
    (55.5, 56.05)
    """
    if double_row_radial:
        g = check_range(gamma, "gamma (D cos(alpha)/d_m)", 0.05, 0.40, low_inclusive=True,
                        high_inclusive=True, unit="-")
        return _s(np.interp(g, FC_TABLE_DOUBLE_ROW_RADIAL_GAMMA, FC_TABLE_DOUBLE_ROW_RADIAL))
    g = check_range(gamma, "gamma (D cos(alpha)/d_m)", 0.01, 0.40, low_inclusive=True,
                    high_inclusive=True, unit="-")
    return _s(np.interp(g, FC_GAMMA, FC_TABLE))


def fc_inch_pound(gamma, *, double_row_radial: bool = False):
    r"""f_c for C in pounds-force with D in inches.

    .. math:: f_{c,\,\mathrm{inch}} = f_{c,\,\mathrm{metric}}\,\frac{25.4^{1.8}}{4.448}

    (ANSI/AFBMA Std 9 Table 2 footnote 3).  Exact conversion uses
    1 lbf = 4.4482216 N; the standard's 4.448 differs by 5e-6.

    Examples
    --------
    >>> round(float(fc_inch_pound(0.05)))
    3547
    """
    return fc_factor(gamma, double_row_radial=double_row_radial) * 25.4**1.8 / LBF


def f0_factor(gamma):
    r"""Static rating factor f0 of ISO 76, linearly interpolated in γ = D cos α / d_m.

    Parameters
    ----------
    gamma : float or array_like
        D cos α / d_m [-], in [0, 0.40].

    Returns
    -------
    float or ndarray
        f0 [N/mm²] (C0 in N with D in mm).

    References
    ----------
    ISO 76:2006 Table 2, radial and angular-contact groove ball bearings.

    Examples
    --------
    >>> float(f0_factor(0.2)), round(float(f0_factor(0.195)), 2)
    (14.0, 14.1)
    """
    g = check_range(gamma, "gamma (D cos(alpha)/d_m)", 0.0, 0.40, low_inclusive=True,
                    high_inclusive=True, unit="-")
    return _s(np.interp(g, F0_GAMMA, F0_TABLE))


# --------------------------------------------------------------------------- ratings
def dynamic_rating(bearing_or_D, n_balls=None, pitch_diameter=None, contact_angle=None,
                   n_rows=1, *, standard: str = "ISO 281:2007",
                   double_row_radial: bool = False) -> float:
    r"""Basic dynamic radial load rating C of a radial or angular-contact ball bearing [N].

    .. math::
        C = b_m f_c (i \cos\alpha)^{0.7} Z^{2/3} D^{1.8} \quad (D \le 25.4\ \mathrm{mm}),
        \qquad
        C = 3.647\, b_m f_c (i \cos\alpha)^{0.7} Z^{2/3} D^{1.4} \quad (D > 25.4\ \mathrm{mm})

    with D in mm and C in N; b_m = 1.3 for ISO 281:2007, 1 for ABMA Std 9-1990 (and
    ISO 281:1990).  f_c from :func:`fc_factor` at γ = D cos α / d_m.

    Parameters
    ----------
    bearing_or_D : BallBearing or float
        A bearing object (see :func:`bearing_numbers`), or the ball diameter D [m].
    n_balls : int
        Number of balls per row Z [-] (plain-number form).
    pitch_diameter : float
        Pitch diameter d_m [m] (plain-number form).
    contact_angle : float, optional
        Nominal contact angle α [rad]; default 0 for plain numbers (radial, deep-groove
        bearings) and the ``nominal_contact_angle`` of a bearing object (ISO 281:2007
        §6.1.1 rates at the nominal angle, not at the free angle of a clearance).
    n_rows : int
        Number of rows i (1 or 2).
    standard : {"ISO 281:2007", "ABMA 9-1990"}
        Rating standard.
    double_row_radial : bool
        Double-row *radial-contact* groove bearing (the standard's separate f_c column).

    Returns
    -------
    float
        C [N], the constant radial load that 90 % of a group of bearings endure for 1e6
        revolutions of the inner ring.

    References
    ----------
    ISO 281:2007 §6.1.1 eqs. (2)–(3), Table 2; ANSI/AFBMA Std 9-1990 §5;
    Harris (2001) *Rolling Bearing Analysis* §18.

    Examples
    --------
    ANSI/AFBMA Std 9-1990 illustration: 10 balls of 1/16 in, races 0.330 / 0.452 in
    (d_m = 0.391 in), radial, ABMA (no b_m): C = 143 lb.

    >>> C = dynamic_rating(0.0625 * INCH, 10, 0.391 * INCH, standard="ABMA 9-1990")
    >>> round(C / LBF, 1)
    142.9
    """
    check_choice(standard, "standard", STANDARDS)
    D, Z, dm, alpha, i = bearing_numbers(bearing_or_D, n_balls, pitch_diameter, contact_angle,
                                         n_rows)
    gamma = D * np.cos(alpha) / dm
    fc = float(fc_factor(gamma, double_row_radial=double_row_radial))
    Dmm = D * 1e3
    core = _B_M[standard] * fc * (i * np.cos(alpha)) ** 0.7 * Z ** (2.0 / 3.0)
    if Dmm <= 25.4:
        return float(core * Dmm**1.8)
    return float(3.647 * core * Dmm**1.4)


def static_rating(bearing_or_D, n_balls=None, pitch_diameter=None, contact_angle=None,
                  n_rows=1) -> float:
    r"""Basic static radial load rating C0 of a radial or angular-contact ball bearing [N].

    .. math:: C_0 = f_0\, i\, Z\, D^2 \cos\alpha \qquad (C_0\ \mathrm{in\ N},\ D\ \mathrm{in\ mm})

    C0 is the static radial load that produces 4200 MPa at the centre of the most heavily
    loaded ball–raceway contact (ISO 76 §3.2); see :func:`static_rating_pressure`.

    Parameters
    ----------
    bearing_or_D : BallBearing or float
        A bearing object, or the ball diameter D [m].
    n_balls : int
        Balls per row Z [-].
    pitch_diameter : float
        Pitch diameter d_m [m].
    contact_angle : float, optional
        Nominal contact angle α [rad] (default as in :func:`dynamic_rating`).
    n_rows : int
        Number of rows i.

    Returns
    -------
    float
        C0 [N].

    References
    ----------
    ISO 76:2006 §5.1.1 eq. (1), Table 2.

    Examples
    --------
    209-size deep-groove bearing (D = 12.7 mm, Z = 9, d_m = 65 mm; γ = 0.1954, f0 = 14.09):

    >>> round(static_rating(0.0127, 9, 0.065))
    20457
    """
    D, Z, dm, alpha, i = bearing_numbers(bearing_or_D, n_balls, pitch_diameter, contact_angle,
                                         n_rows)
    f0 = float(f0_factor(D * np.cos(alpha) / dm))
    return float(f0 * i * Z * (D * 1e3) ** 2 * np.cos(alpha))


@dataclass(frozen=True)
class StaticRatingPressure:
    """Contact pressures at F = C0 (frozen).

    Attributes
    ----------
    C0 : Static rating [N].
    Q_max : Most heavily loaded ball's load, 5 C0 / (i Z cos α) [N].
    p_inner, p_outer : Hertz p_max at the inner and outer raceway contact [Pa].
    """

    C0: float
    Q_max: float
    p_inner: float
    p_outer: float

    @property
    def p_max(self) -> float:
        """The larger of the two raceway pressures [Pa]."""
        return max(self.p_inner, self.p_outer)


def static_rating_pressure(bearing_or_D, n_balls=None, pitch_diameter=None, contact_angle=None,
                           n_rows=1, *, f_inner: float = 0.52, f_outer: float = 0.53,
                           material: Material = ISO76_STEEL) -> StaticRatingPressure:
    r"""Exact Hertz pressures at the ball–race contacts when the bearing carries F = C0.

    Uses ISO 76's own rule for the most heavily loaded ball (the Stribeck estimate with
    allowance for clearance),

    .. math:: Q_{max} = \frac{5 F_r}{i Z \cos\alpha},

    and the library's exact elliptical Hertz solution (:mod:`ballrace.analytic.hertz`) for
    the inner contact (R_x = D(1 − γ)/2, R_y = f_i D / (2 f_i − 1)) and the outer contact
    (R_x = D(1 + γ)/2, R_y = f_o D / (2 f_o − 1)).  With the standard's basis (f_i = 0.52,
    f_o = 0.53, E = 207 GPa, ν = 0.3) the larger of the two is 4200 MPa to ±0.15 % over
    the whole f0 table, the check that the f0 table here is ISO 76's.

    Parameters
    ----------
    bearing_or_D, n_balls, pitch_diameter, contact_angle, n_rows
        As in :func:`static_rating`.  Only the geometry is read from a bearing object: the
        check is of the *standard's* basis, so groove radii and material are the ISO 76
        values unless given below.
    f_inner, f_outer : float
        Groove-radius ratios r/D [-] (> 0.5).
    material : Material
        Ball and ring material (same for both).

    Returns
    -------
    StaticRatingPressure

    References
    ----------
    ISO 76:2006 §3.2 and Annex (basis of f0); Hamrock & Dowson (1981) eqs. (3.8)–(3.16),
    (3.47)–(3.48) (Stribeck's 5).

    Examples
    --------
    >>> r = static_rating_pressure(0.0127, 9, 0.065)
    >>> round(r.p_max / 1e6)
    4203
    """
    from . import hertz

    D, Z, dm, alpha, i = bearing_numbers(bearing_or_D, n_balls, pitch_diameter, contact_angle,
                                         n_rows)
    check_range(f_inner, "f_inner", 0.5, None, unit="-")
    check_range(f_outer, "f_outer", 0.5, None, unit="-")
    check_instance(material, "material", Material, "ballrace.Material")
    C0 = static_rating(D, Z, dm, alpha, i)
    Q = 5.0 * C0 / (i * Z * np.cos(alpha))
    g = D * np.cos(alpha) / dm
    Ep = 2.0 / (2.0 * (1.0 - material.nu**2) / material.E)
    ry_i = f_inner * D / (2.0 * f_inner - 1.0)
    ry_o = f_outer * D / (2.0 * f_outer - 1.0)
    ci = hertz.elliptical_contact(Q, 0.5 * D * (1.0 - g), ry_i, Ep)
    co = hertz.elliptical_contact(Q, 0.5 * D * (1.0 + g), ry_o, Ep)
    return StaticRatingPressure(C0=C0, Q_max=float(Q), p_inner=float(ci.p_max),
                                p_outer=float(co.p_max))


# --------------------------------------------------------------------------- static load
# ISO 76:2006 Table 3, radial and angular-contact groove ball bearings:
# contact angle [deg] -> (X0, Y0) for single-row bearings; double row: X0 = 1, Y0 doubled.
_X0Y0_ANGLES = np.array([5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
_Y0_SINGLE = np.array([0.52, 0.50, 0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22])


def _x0y0(alpha: float, i: int):
    """X0, Y0 of ISO 76 Table 3 (radial: 0.6 / 0.5; angular: interpolated in α)."""
    deg = np.degrees(alpha)
    if deg == 0.0:
        return 0.6, 0.5
    if deg > 45.0:
        raise ValueError(f"contact_angle must be <= 45 deg for ISO 76 X0/Y0; got {deg:g} deg")
    y0 = float(np.interp(deg, _X0Y0_ANGLES, _Y0_SINGLE))  # below 5 deg: the 5 deg values
    return (0.5, y0) if i == 1 else (1.0, 2.0 * y0)


def static_equivalent_load(radial_load, axial_load, contact_angle=0.0, n_rows: int = 1):
    r"""Static equivalent radial load P0 of a radial or angular-contact ball bearing [N].

    .. math:: P_0 = \max(X_0 F_r + Y_0 F_a,\ F_r)

    Radial-contact (α = 0) groove ball bearings: X0 = 0.6, Y0 = 0.5 (single and double
    row).  Angular contact, single row: X0 = 0.5, Y0 = 0.52, 0.50, 0.46, 0.42, 0.38, 0.33,
    0.29, 0.26, 0.22 at α = 5°, 10°, … 45° (linear interpolation between); double row
    (and back-to-back / face-to-face pairs): X0 = 1, Y0 doubled.

    Parameters
    ----------
    radial_load : float or array_like
        Fr [N], >= 0.
    axial_load : float or array_like
        Fa [N], >= 0.
    contact_angle : float
        Nominal contact angle α [rad], in [0, 45°].
    n_rows : int
        1 or 2.

    Returns
    -------
    float or ndarray
        P0 [N].

    References
    ----------
    ISO 76:2006 §5.2, Table 3.  Cross-checked against a manufacturer's listing
    (LYC "Equivalent static load, angular contact ball bearings": 15° 0.5/0.46,
    25° 0.5/0.38, 40° 0.5/0.26; pairs Fr + 0.92/0.76/0.52 Fa).

    Examples
    --------
    >>> float(static_equivalent_load(1000.0, 1000.0))           # 0.6*1000 + 0.5*1000
    1100.0
    >>> float(static_equivalent_load(1000.0, 100.0))            # never below Fr
    1000.0
    """
    Fr = check_nonnegative(radial_load, "radial_load", "N", bounded=True)
    Fa = check_nonnegative(axial_load, "axial_load", "N", bounded=True)
    Fr, Fa = broadcast(radial_load=Fr, axial_load=Fa)
    alpha = float(_scalar_of(check_range(contact_angle, "contact_angle", 0.0, np.pi / 2,
                                         low_inclusive=True, unit="rad"), "contact_angle"))
    n_rows = int(_scalar_of(check_integer(n_rows, "n_rows", 1), "n_rows"))
    if n_rows not in (1, 2):
        raise ValueError(f"n_rows must be 1 or 2; got {n_rows!r}")
    x0, y0 = _x0y0(alpha, n_rows)
    return _s(np.maximum(x0 * Fr + y0 * Fa, Fr))


def static_safety_factor(static_rating_N, static_equivalent_load_N):
    r"""Static safety factor s0 = C0 / P0 [-].

    Guide values (ISO 76:2006 Annex / manufacturers): s0 >= 2 where smooth, quiet running
    matters; >= 1 for normal duty; >= 0.5 only for quiet, shock-free, non-critical service.

    Parameters
    ----------
    static_rating_N : float or array_like
        C0 [N], > 0.
    static_equivalent_load_N : float or array_like
        P0 [N], > 0.

    References
    ----------
    ISO 76:2006 §3.6 and Annex B.

    Examples
    --------
    >>> float(static_safety_factor(20000.0, 8000.0))
    2.5
    """
    C0 = check_positive(static_rating_N, "static_rating_N", "N", bounded=True)
    P0 = check_positive(static_equivalent_load_N, "static_equivalent_load_N", "N", bounded=True)
    C0, P0 = broadcast(static_rating_N=C0, static_equivalent_load_N=P0)
    return _s(C0 / P0)


def static_safety_from_pressure(p_max, kind: str = "ball"):
    r"""Static safety factor s0 from the largest contact pressure of a load distribution [-].

    .. math:: s_0 = \left(\frac{p_0}{p_{max}}\right)^{n}, \qquad
              p_0 = 4200\ \mathrm{MPa},\ n = 3 \ \text{(ball bearings)}

    ISO 76:2006 defines the basic static rating C0 as the load that produces a contact
    pressure p_0 at the centre of the most heavily loaded rolling element–raceway
    contact: 4200 MPa for radial and angular-contact ball bearings, 4600 MPa for
    self-aligning ball bearings, 4000 MPa for roller bearings.  In a point contact the load
    grows as p_max^3 (Hertz), in a line contact as p_max^2, so the load ratio C0/P0 of the
    catalogue check is, for the actual most loaded contact, (p_0 / p_max)^n.  Applied to
    the largest pressure of a computed load distribution (inner or outer raceway, any
    contact angle, clearance, preload, moment and tilt included -- the rolling-element
    loads of ISO/TS 16281:2008 rather than the X0 Fr + Y0 Fa of ISO 76) it is the static
    safety the solvers report as ``static_safety``.  The pressure basis is that of
    ISO 76:2006 and the exponents are those of the stress-based static safety of
    rolling-bearing calculation programs, both as reproduced by secondary sources (the
    SKF rolling bearings catalogue, "Static bearing loads"; the MESYS rolling bearing
    calculation manual, "static safety factor based on stress"); the standards' text was
    not consulted.  The 4200 MPa refers to bearing steel (ISO 76's E = 207 GPa,
    ν = 0.3); for ceramic balls manufacturers use other limits.

    Parameters
    ----------
    p_max : float or array_like
        Largest contact pressure (centre of the most heavily loaded contact) [Pa], >= 0;
        0 (no load) gives inf.
    kind : {"ball", "self-aligning ball", "roller"}
        Bearing kind: selects p_0 and n (:data:`STATIC_RATING_PRESSURES`).

    Returns
    -------
    float or ndarray
        s0 [-]; < 1 means the permanent deformation exceeds the one C0 allows (about
        1e-4 of the rolling-element diameter).

    References
    ----------
    ISO 76:2006 (definition of C0 by the contact stress; §3.2 as cited for
    :data:`STATIC_RATING_PRESSURE`); ISO/TS 16281:2008 (rolling-element loads of the
    actual load distribution); Hamrock & Dowson (1981) eqs. (3.8)–(3.16) (p_max ~ Q^1/3).

    Examples
    --------
    >>> float(static_safety_from_pressure(4200e6))
    1.0
    >>> round(float(static_safety_from_pressure(3000e6)), 4)      # (4.2/3)^3
    2.744
    """
    check_choice(kind, "kind", tuple(STATIC_RATING_PRESSURES))
    p = check_nonnegative(p_max, "p_max", "Pa", bounded=True)
    if np.any((p > 0) & (p < 1e5)):
        import warnings

        warnings.warn(f"p_max = {float(p[(p > 0) & (p < 1e5)].flat[0]):g} Pa: contact pressures "
                      "are in pascals [Pa] (4200 MPa = 4.2e9 Pa) - were MPa given?",
                      UserWarning, stacklevel=2)
    p0, n = STATIC_RATING_PRESSURES[kind]
    with np.errstate(divide="ignore"):
        return _s(np.where(p > 0, (p0 / np.where(p > 0, p, 1.0)) ** n, np.inf))


def bearing_type(bearing) -> str:
    """``"deep-groove"`` for a bearing rated as radial (nominal contact angle 0), else
    ``"angular-contact"``: the key of :data:`PERMISSIBLE_MISALIGNMENT`.

    Parameters
    ----------
    bearing : BallBearing
        Anything with a ``nominal_contact_angle`` [rad].

    Examples
    --------
    >>> import ballrace
    >>> bearing_type(ballrace.BallBearing(0.0127, 9, 0.065, 0.52, 0.52,
    ...                                   diametral_clearance=15e-6))
    'deep-groove'
    """
    a = getattr(bearing, "nominal_contact_angle", None)
    if a is None:
        raise TypeError("bearing must have a nominal_contact_angle [rad] (a ballrace."
                        f"BallBearing); got {type(bearing).__name__}")
    return "deep-groove" if a == 0.0 else "angular-contact"


def _s(x):
    x = np.asarray(x, dtype=float)
    return x[()] if x.ndim == 0 else x
