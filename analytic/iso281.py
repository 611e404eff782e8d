r"""ISO 281:2007 modified rating life L_nm = a1 a_ISO L10 of radial ball bearings.

SI at the interface (N, m, m²/s, K); the standard's own units (mm, mm²/s, r/min) are used
only inside the formulas, where its constants demand them.

* :func:`reliability_factor` — a1 for 90 … 99.95 % reliability (Table 12 and the Weibull
  formula behind it);
* :func:`reference_viscosity`, :func:`viscosity_ratio` — ν1 from speed and pitch diameter,
  κ = ν/ν1;
* :func:`operating_viscosity`, :func:`walther_constants` — the oil's kinematic viscosity at a
  temperature from ν40 and ν100 (ASTM D341 / Walther);
* :func:`fatigue_load_limit` (the simplified C0/22 rule of Annex B) and
  :func:`fatigue_load_limit_hertz` (the 1.5 GPa contact-stress method of Annex B with the
  library's exact Hertz solution);
* :func:`contamination_factor` — e_C from the cleanliness levels of Table 13;
* :func:`life_modification_factor` — a_ISO(κ, e_C C_u / P) for radial ball bearings;
* :func:`modified_rating_life`, :func:`modified_rating_life_hours` — L_nm.

Sources and second sources
--------------------------
Every constant below was checked against a second, independent transcription of the
standard (open implementations of ISO 281:2007 in public code, one of them a full
transcription of Annex B, and a catalogue-style summary); ``docs/life.md`` lists the checks.
Two of them deserve a word:

* the κ exponent of the middle range (0.4 ≤ κ < 1) is **0.19087**; one public
  transcription prints 0.019087.  Only 0.19087 makes a_ISO continuous at κ = 0.4
  (2.2649 / 0.4^0.054381 = 2.38057 and 1.9987 / 0.4^0.19087 = 2.38054), and the standard's
  curves are continuous, so the test suite asserts continuity at both boundaries;
* the constant 22 of the simplified C_u rule is (4200/1500)³ = 21.95: the 1.5 GPa fatigue
  limit against the 4.2 GPa of the static rating C0 (ISO 76), with p ∝ Q^(1/3).
  :func:`fatigue_load_limit_hertz` computes the same limit from the bearing's own contacts.

Thrust ball bearings have their own a_ISO constants in ISO 281:2007; no second source for
them was available, so they are not implemented (a ValueError says so).
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from . import plausible
from ._checks import as_array, broadcast, check_choice, check_instance, check_positive, check_range

__all__ = [
    "RELIABILITY_TABLE",
    "CONTAMINATION_LEVELS",
    "KAPPA_MIN",
    "KAPPA_MAX",
    "A_ISO_MAX",
    "FATIGUE_STRESS_LIMIT",
    "reliability_factor",
    "reference_viscosity",
    "viscosity_ratio",
    "walther_constants",
    "operating_viscosity",
    "fatigue_load_limit",
    "FatigueLoadLimit",
    "fatigue_load_limit_hertz",
    "contamination_factor",
    "life_modification_factor",
    "a_iso_equation",
    "modified_rating_life",
    "modified_rating_life_hours",
]

log = logging.getLogger(__name__)

#: ISO 281:2007 Table 12: reliability [-] -> life modification factor a1 [-].
RELIABILITY_TABLE = {0.90: 1.0, 0.95: 0.64, 0.96: 0.55, 0.97: 0.47, 0.98: 0.37, 0.99: 0.25,
                     0.992: 0.22, 0.994: 0.19, 0.996: 0.16, 0.998: 0.12, 0.999: 0.093,
                     0.9992: 0.087, 0.9994: 0.080, 0.9995: 0.077}

#: ISO 281:2007 Table 13: cleanliness level -> ((low, high) e_C for D_pw < 100 mm,
#: (low, high) for D_pw >= 100 mm).
CONTAMINATION_LEVELS = {
    "extreme cleanliness": ((1.0, 1.0), (1.0, 1.0)),
    "high cleanliness": ((0.6, 0.8), (0.8, 0.9)),
    "normal cleanliness": ((0.5, 0.6), (0.6, 0.8)),
    "slight contamination": ((0.3, 0.5), (0.4, 0.6)),
    "typical contamination": ((0.1, 0.3), (0.2, 0.4)),
    "severe contamination": ((0.0, 0.1), (0.0, 0.1)),
    "very severe contamination": ((0.0, 0.0), (0.0, 0.0)),
}

#: Lowest viscosity ratio the a_ISO formulas cover (ISO 281:2007 §9.3.3) [-].
KAPPA_MIN = 0.1
#: Viscosity ratios above this are taken as 4 (ISO 281:2007 §9.3.3) [-].
KAPPA_MAX = 4.0
#: Upper limit of a_ISO (ISO 281:2007 §9.3.3) [-].
A_ISO_MAX = 50.0
#: Contact stress at the fatigue load limit, 1500 MPa for ball bearings of common
#: high-quality steel (ISO 281:2007 Annex B) [Pa].
FATIGUE_STRESS_LIMIT = 1500e6

# a_ISO of radial ball bearings, ISO 281:2007 eqs. in §9.3.3 / Figure 14:
# a_ISO = 0.1 [1 - (x1 - x2 / kappa^e)^0.83 (e_C C_u / P)^(1/3)]^-9.3
_AISO_BALL = dict(x1=2.5671, x2=(2.2649, 1.9987), exponents=(0.83, 1.0 / 3.0, 9.3))
_TYPES = ("radial ball",)


# =========================================================================== a1
def reliability_factor(reliability, method: str = "table"):
    r"""Life modification factor for reliability a1 [-] (ISO 281:2007 Table 12).

    The table values come from a three-parameter Weibull distribution of slope 1.5 whose
    minimum life is 0.05 L10 (ISO 281:2007 §9.2; ISO/TR 1281-2):

    .. math:: a_1 = 0.95 \left(\frac{\ln(1/R)}{\ln(1/0.9)}\right)^{2/3} + 0.05

    ``method="table"`` returns the standard's rounded table values at its nodes and linear
    interpolation between them; ``method="formula"`` evaluates the formula (within 0.003
    of the table).

    Parameters
    ----------
    reliability : float or array_like
        Reliability R [-], in [0.90, 0.9995] (90 … 99.95 %).
    method : {"table", "formula"}
        Table 12 values or the Weibull formula.

    Returns
    -------
    float or ndarray
        a1 [-].

    References
    ----------
    ISO 281:2007 §9.2, Table 12; ISO/TR 1281-2:2008 (derivation).

    Examples
    --------
    >>> float(reliability_factor(0.99)), round(float(reliability_factor(0.99, "formula")), 4)
    (0.25, 0.2483)
    """
    check_choice(method, "method", ("table", "formula"))
    R = check_range(reliability, "reliability", 0.90, 0.9995, low_inclusive=True,
                    high_inclusive=True, unit="- (ISO 281:2007 Table 12: 0.90 ... 0.9995)")
    if method == "formula":
        return _s(0.95 * (np.log(1.0 / R) / np.log(1.0 / 0.9)) ** (2.0 / 3.0) + 0.05)
    x = np.array(list(RELIABILITY_TABLE))
    y = np.array(list(RELIABILITY_TABLE.values()))
    return _s(np.interp(R, x, y))


# =========================================================================== viscosity
def reference_viscosity(speed_rpm, pitch_diameter):
    r"""Reference kinematic viscosity ν1 for adequate lubrication [m²/s].

    .. math::
        \nu_1 = 45000\, n^{-0.83} D_{pw}^{-0.5} \quad (n < 1000\ \mathrm{r/min}), \qquad
        \nu_1 = 4500\, n^{-0.5} D_{pw}^{-0.5} \quad (n \ge 1000\ \mathrm{r/min})

    with ν1 in mm²/s, n in r/min and D_pw in mm (the two fits of the chart differ by 2.3 %
    at 1000 r/min, where they meet).

    Parameters
    ----------
    speed_rpm : float or array_like
        Rotational speed n [rev/min], > 0.
    pitch_diameter : float or array_like
        Pitch diameter D_pw [m], > 0.

    Returns
    -------
    float or ndarray
        ν1 [m²/s].

    References
    ----------
    ISO 281:2007 §9.3.3, Figure 13 and its formulas (also SKF's and other catalogues'
    closed form of the chart).

    Examples
    --------
    >>> round(float(reference_viscosity(3000.0, 0.0435)) * 1e6, 3)     # mm²/s
    12.457
    """
    n = check_positive(speed_rpm, "speed_rpm", "rev/min", bounded=True)
    dpw = check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True) * 1e3
    n, dpw = broadcast(speed_rpm=n, pitch_diameter=dpw)
    nu1 = np.where(n < 1000.0, 45000.0 * n ** -0.83, 4500.0 * n ** -0.5) * dpw ** -0.5
    return _s(nu1 * 1e-6)


def viscosity_ratio(viscosity, speed_rpm, pitch_diameter):
    r"""Viscosity ratio κ = ν / ν1 [-] (ISO 281:2007 §9.3.3).

    Parameters
    ----------
    viscosity : float or array_like
        Kinematic viscosity ν of the lubricant at the operating temperature [m²/s], > 0.
    speed_rpm : float or array_like
        n [rev/min], > 0.
    pitch_diameter : float or array_like
        D_pw [m], > 0.

    Returns
    -------
    float or ndarray
        κ [-].

    Examples
    --------
    >>> round(float(viscosity_ratio(20e-6, 3000.0, 0.0435)), 3)
    1.606
    """
    nu = check_positive(viscosity, "viscosity", "m^2/s", bounded=True)
    broadcast(viscosity=nu, speed_rpm=as_array(speed_rpm, "speed_rpm"),
              pitch_diameter=as_array(pitch_diameter, "pitch_diameter"))
    return _s(nu / reference_viscosity(speed_rpm, pitch_diameter))


def walther_constants(nu40, nu100):
    r"""Constants A, B of the Walther / ASTM D341 viscosity–temperature line.

    .. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B \log_{10} T

    with ν in mm²/s and T in K, through (313.15 K, ν40) and (373.15 K, ν100).

    Parameters
    ----------
    nu40, nu100 : float or array_like
        Kinematic viscosity at 40 °C and 100 °C [m²/s], ν40 > ν100 > 0.

    Returns
    -------
    (A, B) : floats or ndarrays [-].

    References
    ----------
    ASTM D341 (Walther 1931 equation, Z = ν + 0.7, valid for ν >= 2 mm²/s).

    Examples
    --------
    >>> A, B = walther_constants(68e-6, 8.7e-6)
    >>> round(float(A), 4), round(float(B), 4)
    (9.3097, 3.6244)
    """
    v40 = plausible.viscosity(check_positive(nu40, "nu40", "m^2/s", bounded=True),
                               "nu40") * 1e6
    v100 = plausible.viscosity(check_positive(nu100, "nu100", "m^2/s", bounded=True),
                                "nu100") * 1e6
    v40, v100 = broadcast(nu40=v40, nu100=v100)
    if np.any(v100 >= v40):
        raise ValueError(f"nu100 must be < nu40 (oil thins when heated); got nu40 = "
                         f"{np.max(v40):g} mm^2/s, nu100 = {np.max(v100):g} mm^2/s")
    if np.any(v100 < 2.0):
        from ..errors import warn

        warn("walther_constants: nu100 < 2 mm^2/s, below the range of the Z = nu + 0.7 "
             "form of ASTM D341 (the viscosity-temperature line is extrapolated)")
    y40, y100 = np.log10(np.log10(v40 + 0.7)), np.log10(np.log10(v100 + 0.7))
    x40, x100 = np.log10(313.15), np.log10(373.15)
    B = (y40 - y100) / (x100 - x40)
    A = y40 + B * x40
    return _s(A), _s(B)


def operating_viscosity(nu40, nu100, temperature):
    r"""Kinematic viscosity of an oil at a temperature from ν40 and ν100 [m²/s].

    .. math:: \nu = 10^{10^{A - B \log_{10} T}} - 0.7 \quad (\mathrm{mm^2/s})

    with A, B from :func:`walther_constants`.  Reproduces ν40 and ν100 exactly.

    Parameters
    ----------
    nu40, nu100 : float or array_like
        Kinematic viscosity at 40 °C and 100 °C [m²/s].
    temperature : float or array_like
        Operating absolute temperature T [K] (kelvin, not °C: 343.15 K for 70 °C), in
        [173.15, 773.15].

    Returns
    -------
    float or ndarray
        ν [m²/s].

    References
    ----------
    ASTM D341; Walther, C. (1931) *Erdöl und Teer* 7, 382.

    Examples
    --------
    ISO VG 68 mineral oil (ν100 = 8.7 mm²/s) at 70 °C:

    >>> round(float(operating_viscosity(68e-6, 8.7e-6, 343.15)) * 1e6, 2)
    20.12
    """
    A, B = walther_constants(nu40, nu100)
    T = plausible.temperature(check_positive(temperature, "temperature", "K", bounded=True),
                               "temperature")
    broadcast(nu40=as_array(nu40, "nu40"), nu100=as_array(nu100, "nu100"), temperature=T)
    nu = 10.0 ** (10.0 ** (A - B * np.log10(T))) - 0.7
    return _s(nu * 1e-6)


# =========================================================================== C_u
def fatigue_load_limit(static_rating, pitch_diameter):
    r"""Fatigue load limit C_u of a ball bearing, simplified rule [N].

    .. math::
        C_u = \frac{C_0}{22} \quad (D_{pw} \le 100\ \mathrm{mm}), \qquad
        C_u = \frac{C_0}{22}\left(\frac{100}{D_{pw}}\right)^{0.5} \quad (D_{pw} > 100\ \mathrm{mm})

    22 = (4200/1500)³: the 1500 MPa fatigue stress limit against the 4200 MPa of C0.

    Parameters
    ----------
    static_rating : float or array_like
        Basic static load rating C0 [N], > 0.
    pitch_diameter : float or array_like
        D_pw [m], > 0.

    Returns
    -------
    float or ndarray
        C_u [N].

    References
    ----------
    ISO 281:2007 Annex B, simplified method for ball bearings (B.3.2).

    Examples
    --------
    >>> round(float(fatigue_load_limit(11000.0, 0.0435)), 1)
    500.0
    >>> round(float(fatigue_load_limit(22000.0, 0.4)), 1)      # (100/400)^0.5 = 0.5
    500.0
    """
    C0 = check_positive(static_rating, "static_rating", "N", bounded=True)
    dpw = check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True) * 1e3
    C0, dpw = broadcast(static_rating=C0, pitch_diameter=dpw)
    return _s(C0 / 22.0 * np.where(dpw > 100.0, np.sqrt(100.0 / np.maximum(dpw, 1e-300)), 1.0))


@dataclass(frozen=True)
class FatigueLoadLimit:
    """Fatigue load limit from the contact-stress criterion (frozen).

    Attributes
    ----------
    C_u : Fatigue load limit of the bearing [N] (the smaller ring value, size-corrected).
    Q_u_inner, Q_u_outer : Ball load giving the stress limit at each race [N].
    C_u_inner, C_u_outer : Radial loads giving the stress limit at each race [N].
    size_factor : (100/D_pw)^0.5 above 100 mm, else 1 [-].
    stress_limit : Contact stress criterion [Pa].
    """

    C_u: float
    Q_u_inner: float
    Q_u_outer: float
    C_u_inner: float
    C_u_outer: float
    size_factor: float
    stress_limit: float


def fatigue_load_limit_hertz(bearing, contact_angle: float | None = None,
                             stress_limit: float = FATIGUE_STRESS_LIMIT) -> FatigueLoadLimit:
    r"""Fatigue load limit C_u from the 1.5 GPa contact-stress criterion [N].

    The ball load Q_u that raises the maximum Hertz pressure of a race contact to the
    stress limit follows from the library's exact Hertz solution (p ∝ Q^(1/3)); the
    bearing load that puts Q_u on the most heavily loaded ball of a zero-clearance radial
    bearing is

    .. math:: C_u = 0.2288\, i\, Z\, Q_u \cos\alpha

    (0.2288 = J_r(0.5) = 1/4.37, Stribeck's radial load integral), the smaller of the
    inner and outer race values, times (100/D_pw)^0.5 above D_pw = 100 mm.

    Parameters
    ----------
    bearing : BallBearing
        Geometry (D, Z, d_m, f_i, f_o) and materials.
    contact_angle : float, optional
        Nominal contact angle α [rad], in [0, pi/2); default the bearing's
        :attr:`~ballrace.BallBearing.nominal_contact_angle` (0 for deep-groove bearings,
        whatever free contact angle their clearance gives; the design angle for
        angular-contact ones).
    stress_limit : float
        Contact stress at the fatigue limit [Pa]; 1500 MPa for ball bearings.

    Returns
    -------
    FatigueLoadLimit

    References
    ----------
    ISO 281:2007 Annex B (B.3.1: σ_Hu = 1500 MPa, Q_u from the Hertz solution,
    C_u = 0.2288 Z Q_u i cos α, size factor above 100 mm); Harris (2001) §6.2 (J_r = 0.2288).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(0.0127, 9, 0.065, 0.52, 0.52, diametral_clearance=0.0)
    >>> round(fatigue_load_limit_hertz(brg).C_u)
    1140
    """
    from .bearing import BallBearing

    check_instance(bearing, "bearing", BallBearing)
    a = (float(bearing.nominal_contact_angle) if contact_angle is None
         else float(check_range(contact_angle, "contact_angle", 0.0, np.pi / 2,
                                low_inclusive=True, unit="rad")))
    s = float(check_positive(stress_limit, "stress_limit", "Pa", bounded=True))
    Qref = 1000.0
    Qu = {}
    for race in ("inner", "outer"):
        c = bearing.contacts(Qref, a, race)
        Qu[race] = Qref * (s / float(c.p_max)) ** 3
    Z, i = bearing.n_balls, getattr(bearing, "n_rows", 1)
    k = 0.2288 * i * Z * np.cos(a)
    dpw = bearing.pitch_diameter * 1e3
    size = float(np.sqrt(100.0 / dpw)) if dpw > 100.0 else 1.0
    Ci, Co = k * Qu["inner"] * size, k * Qu["outer"] * size
    return FatigueLoadLimit(C_u=float(min(Ci, Co)), Q_u_inner=float(Qu["inner"]),
                            Q_u_outer=float(Qu["outer"]), C_u_inner=float(Ci),
                            C_u_outer=float(Co), size_factor=size, stress_limit=s)


# =========================================================================== e_C
def contamination_factor(level: str, pitch_diameter, which: str = "mean"):
    """Contamination factor e_C from a cleanliness level (ISO 281:2007 Table 13) [-].

    Levels (Table 13, with its typical conditions): "extreme cleanliness" (particle size of
    the order of the film thickness; laboratory), "high cleanliness" (oil through an extremely
    fine filter; sealed greased-for-life bearings), "normal cleanliness" (oil through a fine
    filter; shielded greased-for-life bearings), "slight contamination", "typical
    contamination" (no integral seals, coarse filtering, wear particles), "severe
    contamination" (heavily contaminated surroundings, insufficient sealing) and "very
    severe contamination".  The table gives a range for D_pw < 100 mm and one for
    D_pw >= 100 mm; ``which`` picks its low end, high end or mean.

    Annex A of the standard refines e_C from ISO 4406 oil cleanliness codes, filter ratings,
    κ and D_pw; those formulas are not implemented here (no second source was available to
    check their constants): pass an explicit e_C when you have one.

    Parameters
    ----------
    level : str
        One of :data:`CONTAMINATION_LEVELS`.
    pitch_diameter : float
        D_pw [m], > 0.
    which : {"mean", "low", "high"}
        Point of the table's range.

    Returns
    -------
    float
        e_C [-], in [0, 1].

    References
    ----------
    ISO 281:2007 §9.3.4, Table 13.

    Examples
    --------
    >>> contamination_factor("normal cleanliness", 0.0435)
    0.55
    >>> contamination_factor("normal cleanliness", 0.15, "low")
    0.6
    """
    check_choice(level, "level", tuple(CONTAMINATION_LEVELS))
    check_choice(which, "which", ("mean", "low", "high"))
    dpw = float(check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True))
    lo, hi = CONTAMINATION_LEVELS[level][0 if dpw < 0.1 else 1]
    return {"low": lo, "high": hi, "mean": round(0.5 * (lo + hi), 12)}[which]


# =========================================================================== a_ISO
def life_modification_factor(kappa, contamination, fatigue_limit, load, *,
                             bearing_type: str = "radial ball", cap: float = A_ISO_MAX,
                             ep_additives: bool = False):
    r"""Life modification factor a_ISO of radial ball bearings [-] (ISO 281:2007 §9.3.3).

    .. math::
        a_{ISO} = 0.1\left[1 - \left(2.5671 - \frac{x_2}{\kappa^{e}}\right)^{0.83}
                  \left(\frac{e_C C_u}{P}\right)^{1/3}\right]^{-9.3}

    with (x2, e) = (2.2649, 0.054381) for 0.1 ≤ κ < 0.4, (1.9987, 0.19087) for
    0.4 ≤ κ < 1 and (1.9987, 0.071739) for 1 ≤ κ ≤ 4.  κ above 4 is taken as 4; a_ISO is
    limited to 50 (also where the bracket reaches zero, i.e. the load is below the
    fatigue limit).  κ below 0.1 is outside the standard and raises ``ValueError`` (no
    silent extrapolation).

    Lubricants with proven effective EP additives (``ep_additives=True``): where κ < 1 and
    e_C >= 0.2, κ = 1 is used and a_ISO is limited to 3 (ISO 281:2007 §9.3.3).

    Parameters
    ----------
    kappa : float or array_like
        Viscosity ratio κ = ν/ν1 [-], >= 0.1.
    contamination : float or array_like
        Contamination factor e_C [-], in [0, 1].
    fatigue_limit : float or array_like
        Fatigue load limit C_u [N], > 0.
    load : float or array_like
        Dynamic equivalent load P [N], > 0.
    bearing_type : {"radial ball"}
        Only radial ball bearings (their constants have a second source).
    cap : float
        Upper limit of a_ISO [-] (50 in ISO 281; lower limits such as 3.8 are used in wind
        turbine guidelines).
    ep_additives : bool
        The lubricant contains proven effective EP additives (see above).

    Returns
    -------
    float or ndarray
        a_ISO [-], in (0, cap].

    References
    ----------
    ISO 281:2007 §9.3.3, equations for radial ball bearings and Figure 14; ISO/TR 1281-2:2008
    (background); constants cross-checked against two independent public transcriptions
    (docs/life.md).

    Examples
    --------
    >>> round(float(life_modification_factor(1.0, 0.5, 500.0, 2500.0)), 4)
    2.4305
    >>> float(life_modification_factor(4.0, 1.0, 1000.0, 1000.0))
    50.0
    >>> float(life_modification_factor(0.3, 0.5, 500.0, 500.0, ep_additives=True))
    3.0
    """
    if not isinstance(bearing_type, str):
        check_choice(bearing_type, "bearing_type", ("radial ball",))   # TypeError
    if bearing_type != "radial ball":
        raise ValueError(f"bearing_type must be 'radial ball' (the thrust-bearing constants of "
                         f"ISO 281:2007 are not implemented: no second source); got "
                         f"{bearing_type!r}")
    return a_iso_equation(kappa, contamination, fatigue_limit, load, **_AISO_BALL, cap=cap,
                          ep_additives=ep_additives)


def a_iso_equation(kappa, contamination, fatigue_limit, load, *, x1, x2, exponents,
                   cap: float = A_ISO_MAX, ep_additives: bool = False):
    r"""Life modification factor a_ISO in the common form of ISO 281:2007 §9.3.3 [-].

    .. math::
        a_{ISO} = 0.1\left[1 - \left(x_1 - \frac{x_2}{\kappa^{e}}\right)^{m}
                  \left(\frac{e_C C_u}{P}\right)^{n}\right]^{-q}

    with e = 0.054381 for 0.1 <= κ < 0.4, 0.19087 for 0.4 <= κ < 1 and 0.071739 for
    1 <= κ <= 4, and x2 taking its first value below κ = 0.4 and its second above.  The
    rules shared by the bearing types: κ above 4 is taken as 4; κ below 0.1 raises
    ``ValueError``; a_ISO is limited to ``cap``, also where the bracket reaches zero;
    ``ep_additives``: where κ < 1 and e_C >= 0.2, κ = 1 is used and a_ISO is limited to 3.
    The constants of a bearing type: :func:`life_modification_factor` (radial ball),
    :func:`ballrace.analytic.roller.ratings.life_modification_factor` (radial roller).

    Parameters
    ----------
    kappa, contamination, fatigue_limit, load, cap, ep_additives
        κ [-], e_C [-], C_u [N], P [N], the upper limit of a_ISO [-] and the EP flag, as in
        :func:`life_modification_factor`.
    x1 : float
        x_1 [-].
    x2 : (float, float)
        x_2 for κ < 0.4 and for κ >= 0.4 [-].
    exponents : (float, float, float)
        m, n, q [-].

    Returns
    -------
    float or ndarray
        a_ISO [-], in (0, cap], with the constants given.

    Examples
    --------
    >>> round(float(a_iso_equation(1.0, 0.5, 500.0, 2500.0, x1=2.5671,
    ...                            x2=(2.2649, 1.9987), exponents=(0.83, 1 / 3, 9.3))), 4)
    2.4305
    """
    k = check_positive(kappa, "kappa", "-")
    if np.any(k < KAPPA_MIN):
        raise ValueError(f"kappa must be >= {KAPPA_MIN} [-]: ISO 281:2007 gives no a_ISO below "
                         f"kappa = 0.1 and ballrace does not extrapolate; got "
                         f"{float(np.min(k))!r}")
    eC = check_range(contamination, "contamination", 0.0, 1.0, low_inclusive=True,
                     high_inclusive=True, unit="-")
    Cu = check_positive(fatigue_limit, "fatigue_limit", "N", bounded=True)
    P = check_positive(load, "load", "N", bounded=True)
    cap = float(check_positive(cap, "cap", "-"))
    k, eC, Cu, P = broadcast(kappa=k, contamination=eC, fatigue_limit=Cu, load=P)
    k = np.minimum(k, KAPPA_MAX)
    ep = np.zeros(np.broadcast(k, eC).shape, dtype=bool)
    if ep_additives:
        ep = (k < 1.0) & (eC >= 0.2)
        k = np.where(ep, 1.0, k)
    m, n, q = exponents
    x2 = np.where(k < 0.4, x2[0], x2[1])
    e = np.where(k < 0.4, 0.054381, np.where(k < 1.0, 0.19087, 0.071739))
    base = x1 - x2 / k ** e
    if m != 1.0:
        base = base ** m
    bracket = 1.0 - base * (eC * Cu / P) ** n
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(bracket > 0.0, 0.1 * np.abs(bracket) ** -q, np.inf)
    return _s(np.minimum(a, np.where(ep, min(cap, 3.0), cap)))


def modified_rating_life(C, P, *, kappa, contamination, fatigue_limit, reliability=0.9,
                         ep_additives: bool = False):
    r"""Modified rating life L_nm = a1 a_ISO L10 of a radial ball bearing [1e6 rev].

    .. math:: L_{nm} = a_1\, a_{ISO} \left(\frac{C}{P}\right)^3

    Parameters
    ----------
    C : float or array_like
        Basic dynamic load rating [N], > 0.
    P : float or array_like
        Dynamic equivalent load [N], > 0.
    kappa : float or array_like
        Viscosity ratio [-], >= 0.1.
    contamination : float or array_like
        e_C [-], in [0, 1].
    fatigue_limit : float or array_like
        C_u [N], > 0.
    reliability : float or array_like
        Reliability [-], 0.90 … 0.9995.
    ep_additives : bool
        Lubricant with effective EP additives (see :func:`life_modification_factor`).

    Returns
    -------
    float or ndarray
        L_nm [1e6 rev].

    References
    ----------
    ISO 281:2007 §9.1, eq. (19).

    Examples
    --------
    >>> round(float(modified_rating_life(22500.0, 2500.0, kappa=1.0, contamination=0.5,
    ...                                  fatigue_limit=500.0, reliability=0.99)), 1)
    443.0
    """
    C = check_positive(C, "C", "N", bounded=True)
    P = check_positive(P, "P", "N", bounded=True)
    broadcast(C=C, P=P, kappa=as_array(kappa, "kappa"),
              contamination=as_array(contamination, "contamination"),
              fatigue_limit=as_array(fatigue_limit, "fatigue_limit"),
              reliability=as_array(reliability, "reliability"))
    a1 = reliability_factor(reliability)
    a = life_modification_factor(kappa, contamination, fatigue_limit, P,
                                 ep_additives=ep_additives)
    return _s(a1 * a * (C / P) ** 3)


def modified_rating_life_hours(C, P, *, speed_rpm, kappa, contamination, fatigue_limit,
                               reliability=0.9, ep_additives: bool = False):
    """Modified rating life in operating hours at a constant speed [h].

    ``L_nmh = 1e6 L_nm / (60 n)``; see :func:`modified_rating_life`.

    Parameters
    ----------
    speed_rpm : float or array_like
        n [rev/min], > 0.

    Examples
    --------
    >>> round(float(modified_rating_life_hours(22500.0, 2500.0, speed_rpm=3000.0, kappa=1.0,
    ...       contamination=0.5, fatigue_limit=500.0)))
    9844
    """
    n = check_positive(speed_rpm, "speed_rpm", "rev/min", bounded=True)
    broadcast(C=as_array(C, "C"), P=as_array(P, "P"), speed_rpm=n,
              kappa=as_array(kappa, "kappa"))
    L = modified_rating_life(C, P, kappa=kappa, contamination=contamination,
                             fatigue_limit=fatigue_limit, reliability=reliability,
                             ep_additives=ep_additives)
    return _s(1e6 * L / (60.0 * n))


def _s(x):
    x = np.asarray(x, dtype=float)
    return x[()] if x.ndim == 0 else x
