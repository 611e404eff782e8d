r"""Operating radial clearance of a ball bearing from its fits and temperatures.

The initial (unmounted) diametral clearance P_d0 is reduced by the interference fits of the
inner ring on the shaft and of the outer ring in the housing, and changed by the rings'
temperatures (and by shaft and housing materials that expand differently from the rings):

.. math:: P_d = P_{d0} - \Delta_i - \Delta_e + \Delta_T

* **Fits** (thick-walled cylinders, Lamé): an interference I (diametral) at the seat
  diameter d creates the contact pressure

  .. math::
      \frac{I}{d} = \frac{p}{E_r}\left(\frac{F^2 + d^2}{F^2 - d^2} + \nu_r\right)
                  + \frac{p}{E_s}\left(\frac{d^2 + d_0^2}{d^2 - d_0^2} - \nu_s\right)

  (ring between d and its raceway diameter F, shaft between its bore d_0 and d), and the
  raceway diameter of the inner ring grows by :math:`\Delta_i = 2 p d^2 F / (E_r (F^2 - d^2))`.
  For the outer ring (seat diameter D, raceway diameter E, housing outer diameter D_h):

  .. math::
      \frac{I}{D} = \frac{p}{E_r}\left(\frac{D^2 + E^2}{D^2 - E^2} - \nu_r\right)
                  + \frac{p}{E_h}\left(\frac{D_h^2 + D^2}{D_h^2 - D^2} + \nu_h\right),
      \qquad \Delta_e = \frac{2 p D^2 E}{E_r (D^2 - E^2)}

  With equal moduli, a solid shaft and an infinite housing these reduce to the textbook
  rules Δ_i = I d/F and Δ_e = I E/D (e.g. Harris 2001 §4.3; SKF catalogue, "Reduction of
  radial internal clearance by interference fits").
* **Temperatures**: the outer raceway grows with the outer ring, the inner raceway with the
  inner ring and the balls with their own temperature (default the mean of the rings):

  .. math::
      \Delta_T = \alpha_r (T_e - T_0) d_e - \alpha_r (T_i - T_0) d_i - \alpha_b (T_b - T_0)\, 2D

  which is α (T_e − T_i) D_pw for a common α and T_b = (T_i + T_e)/2.  A shaft or housing of
  another material changes the interference by (α_s − α_r)(T_i − T_0) d and
  −(α_h − α_r)(T_e − T_0) D (an aluminium housing loosens when warm).

A negative result is preload (interference between balls and raceways), not an error: the
load distribution accepts it as ``clearance=`` or :meth:`OperatingClearance.bearing` makes a
:class:`~ballrace.BallBearing` with it when it is positive.

References
----------
Timoshenko, S. & Goodier, J.N. (1951) *Theory of Elasticity*, §28 (thick-walled cylinder,
Lamé 1852); Harris, T.A. (2001) *Rolling Bearing Analysis* 4th ed., ch. 4 (clearance
reduction by fits and temperature); ISO/TS 16281:2008 (operating clearance as input to the
reference life).
"""
from __future__ import annotations

import dataclasses
import logging
import math
from dataclasses import dataclass

import numpy as np

from . import plausible
from ._checks import (as_array, check_choice, check_instance, check_nonnegative,
                      check_positive, check_range)

__all__ = ["STEEL_EXPANSION", "OperatingClearance", "fit_pressure", "operating_clearance"]

log = logging.getLogger(__name__)

#: Linear thermal expansion coefficient of bearing steel (AISI 52100), 11.5e-6 1/K
#: (e.g. SKF; Harris 2001 Table 5.x lists 11.7e-6 1/K) [1/K].
STEEL_EXPANSION = 11.5e-6


def fit_pressure(interference, seat_diameter, ring_diameter, mating_diameter, *,
                 E_ring, nu_ring, E_mate, nu_mate, ring: str = "inner"):
    r"""Contact pressure of a shrink fit between a ring and a shaft or housing [Pa].

    Parameters
    ----------
    interference : float or array_like
        Diametral interference I [m], >= 0 (a loose fit gives 0 pressure).
    seat_diameter : float
        Seat diameter: bore d of the inner ring or outside diameter D of the outer ring [m].
    ring_diameter : float
        Raceway diameter of the ring: F > d (inner) or E < D (outer) [m].
    mating_diameter : float
        Shaft bore d_0 < d (0 for a solid shaft) or housing outside diameter D_h > D
        (``np.inf`` for a rigid-walled, infinitely large housing) [m].
    E_ring, nu_ring, E_mate, nu_mate : float
        Young's moduli [Pa] and Poisson's ratios [-] of ring and shaft / housing.
    ring : {"inner", "outer"}
        Which fit.

    Returns
    -------
    float or ndarray
        p [Pa].

    References
    ----------
    Lamé; Timoshenko & Goodier (1951) §28; Shigley's *Mechanical Engineering Design*
    (press and shrink fits, eq. 3-56).

    Examples
    --------
    >>> round(float(fit_pressure(20e-6, 0.025, 0.032, 0.0, E_ring=208e9, nu_ring=0.3,
    ...                          E_mate=208e9, nu_mate=0.3)) / 1e6, 2)
    32.42
    """
    check_choice(ring, "ring", ("inner", "outer"))
    I = np.maximum(as_array(interference, "interference", bounded=True, tiny_ok=True,
                            unit="m"), 0.0)
    d = float(check_positive(seat_diameter, "seat_diameter", "m", bounded=True))
    F = float(check_positive(ring_diameter, "ring_diameter", "m", bounded=True))
    Er = float(check_positive(E_ring, "E_ring", "Pa", bounded=True))
    Em = float(check_positive(E_mate, "E_mate", "Pa", bounded=True))
    nr = float(check_range(nu_ring, "nu_ring", -1.0, 0.5, unit="-"))
    nm = float(check_range(nu_mate, "nu_mate", -1.0, 0.5, unit="-"))
    m = float(as_array(mating_diameter, "mating_diameter", allow_inf=True))
    if ring == "inner":
        if not F > d:
            raise ValueError(f"ring_diameter (inner raceway F = {F:g} m) must exceed the bore "
                             f"seat_diameter d = {d:g} m")
        if not 0.0 <= m < d:
            raise ValueError(f"mating_diameter (shaft bore) must be in [0, {d:g}) m; got {m!r}")
        k_ring = (F**2 + d**2) / (F**2 - d**2) + nr
        k_mate = (d**2 + m**2) / (d**2 - m**2) - nm
    elif ring == "outer":
        if not 0.0 < F < d:
            raise ValueError(f"ring_diameter (outer raceway E = {F:g} m) must be in (0, D) with "
                             f"the outside seat_diameter D = {d:g} m")
        if not m > d:
            raise ValueError(f"mating_diameter (housing outside diameter) must be > {d:g} m "
                             f"(np.inf for a large housing); got {m!r}")
        k_ring = (d**2 + F**2) / (d**2 - F**2) - nr
        k_mate = 1.0 + nm if math.isinf(m) else (m**2 + d**2) / (m**2 - d**2) + nm
    else:
        raise ValueError(f"ring must be one of 'inner', 'outer'; got {ring!r}")
    p = I / d / (k_ring / Er + k_mate / Em)
    return p[()] if p.ndim == 0 else p


@dataclass(frozen=True)
class OperatingClearance:
    """Operating diametral clearance and its parts (frozen; negative = preload).

    Attributes
    ----------
    initial : Unmounted diametral clearance P_d0 [m].
    fit_inner : Reduction by the inner-ring fit, Δ_i [m] (>= 0).
    fit_outer : Reduction by the outer-ring fit, Δ_e [m] (>= 0).
    thermal : Change by the temperatures, Δ_T [m] (negative when the inner ring is warmer).
    operating : P_d = initial - fit_inner - fit_outer + thermal [m].
    pressure_inner, pressure_outer : Fit pressures [Pa].
    interference_inner, interference_outer : Effective interferences at temperature [m].
    """

    initial: float
    fit_inner: float
    fit_outer: float
    thermal: float
    operating: float
    pressure_inner: float
    pressure_outer: float
    interference_inner: float
    interference_outer: float

    @property
    def is_preload(self) -> bool:
        """True when the operating clearance is negative (the rings preload the balls)."""
        return self.operating < 0.0

    def bearing(self, bearing):
        """``bearing`` with the operating clearance (``dataclasses.replace``).

        A negative operating clearance cannot be a BallBearing's clearance (it is the
        free geometry); pass it to the load distribution as ``clearance=`` instead.
        """
        if self.operating < 0.0:
            raise ValueError(f"operating clearance {self.operating:.4g} m is negative "
                             "(preload): pass it to bearing.radial(..., clearance=...) or "
                             "loaddist.solve(..., clearance=...) instead")
        return dataclasses.replace(bearing, free_contact_angle=None,
                                   diametral_clearance=self.operating)


def operating_clearance(bearing, *, bore, outside_diameter, initial_clearance=None,
                        shaft_interference=0.0, housing_interference=0.0,
                        shaft_bore=0.0, housing_diameter=math.inf,
                        inner_temperature=293.15, outer_temperature=293.15,
                        ball_temperature=None, reference_temperature=293.15,
                        ring_expansion=STEEL_EXPANSION, ball_expansion=None,
                        shaft_expansion=None, housing_expansion=None,
                        shaft_material=None, housing_material=None) -> OperatingClearance:
    r"""Operating diametral clearance from fits and temperatures (see the module notes).

    Parameters
    ----------
    bearing : BallBearing
        Gives D, D_pw, the initial clearance (default) and the ring material.
    bore, outside_diameter : float
        Bearing bore d and outside diameter D_o [m].
    initial_clearance : float, optional
        Unmounted diametral clearance [m]; default the bearing's.
    shaft_interference, housing_interference : float
        Diametral interference of the inner ring on the shaft and of the outer ring in the
        housing at the reference temperature [m]; <= 0 is a loose fit (no reduction).
    shaft_bore : float
        Bore of a hollow shaft [m] (0: solid).
    housing_diameter : float
        Outside diameter of the housing around the seat [m] (``math.inf``: large housing).
    inner_temperature, outer_temperature : float
        Ring (and shaft / housing) absolute temperatures [K] (kelvin, not °C: 70 °C is
        343.15 K), in [173.15, 773.15].
    ball_temperature : float, optional
        Ball temperature [K]; default the mean of the rings.
    reference_temperature : float
        Temperature of the fits and the initial clearance [K] (20 °C).
    ring_expansion, ball_expansion, shaft_expansion, housing_expansion : float
        Linear expansion coefficients [1/K]; ball, shaft and housing default to the rings'.
    shaft_material, housing_material : Material, optional
        Elastic constants of shaft and housing; default the ring material.

    Returns
    -------
    OperatingClearance

    References
    ----------
    Lamé thick-walled cylinders (Timoshenko & Goodier 1951 §28); Harris (2001) ch. 4.

    Examples
    --------
    6305 (d = 25 mm, D = 62 mm) with 20 µm clearance, a 15 µm interference on a solid steel
    shaft and an inner ring 10 K warmer than the outer ring:

    >>> import ballrace
    >>> brg = ballrace.BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=20e-6)
    >>> oc = operating_clearance(brg, bore=0.025, outside_diameter=0.062,
    ...                          shaft_interference=15e-6, inner_temperature=313.15,
    ...                          outer_temperature=303.15)
    >>> round(oc.fit_inner * 1e6, 2), round(oc.thermal * 1e6, 2), round(oc.operating * 1e6, 2)
    (11.72, -5.0, 3.28)
    """
    from .bearing import BallBearing
    from .materials import Material

    check_instance(bearing, "bearing", BallBearing)
    for m, n in ((shaft_material, "shaft_material"), (housing_material, "housing_material")):
        if m is not None:
            check_instance(m, n, Material)
    D = bearing.ball_diameter
    dm = bearing.pitch_diameter
    d = float(check_positive(bore, "bore", "m", bounded=True))
    Do = float(check_positive(outside_diameter, "outside_diameter", "m", bounded=True))
    P0 = (bearing.diametral_clearance if initial_clearance is None
          else float(as_array(initial_clearance, "initial_clearance", bounded=True,
                              tiny_ok=True, unit="m")))
    shaft_bore = float(check_nonnegative(shaft_bore, "shaft_bore", "m", bounded=True,
                                         tiny_ok=True))
    housing_diameter = float(as_array(housing_diameter, "housing_diameter", allow_inf=True,
                                      bounded=True, unit="m"))
    if not housing_diameter > Do:
        raise ValueError(f"housing_diameter (the mating_diameter of the outer-ring fit) must be "
                         f"> outside_diameter = {Do:g} m "
                         f"(math.inf for a large housing) [m]; got {housing_diameter!r}")
    F = dm - D - 0.5 * P0            # inner raceway diameter
    Er = dm + D + 0.5 * P0           # outer raceway diameter
    if not d < F:
        raise ValueError(f"bore must be smaller than the inner raceway diameter "
                         f"{F * 1e3:.4g} mm; got {d * 1e3:.4g} mm")
    if not Do > Er:
        raise ValueError(f"outside_diameter must exceed the outer raceway diameter "
                         f"{Er * 1e3:.4g} mm; got {Do * 1e3:.4g} mm")
    Ti, Te = (float(plausible.temperature(check_positive(t, n, "K", bounded=True), n))
              for t, n in ((inner_temperature, "inner_temperature"),
                           (outer_temperature, "outer_temperature")))
    T0 = float(plausible.temperature(check_positive(
        reference_temperature, "reference_temperature", "K", bounded=True),
        "reference_temperature"))
    Tb = 0.5 * (Ti + Te) if ball_temperature is None else float(plausible.temperature(
        check_positive(ball_temperature, "ball_temperature", "K", bounded=True),
        "ball_temperature"))
    ar = float(as_array(ring_expansion, "ring_expansion"))
    ab = ar if ball_expansion is None else float(as_array(ball_expansion, "ball_expansion"))
    a_s = ar if shaft_expansion is None else float(as_array(shaft_expansion, "shaft_expansion"))
    ah = ar if housing_expansion is None else float(as_array(housing_expansion,
                                                            "housing_expansion"))
    rm = bearing.ring_material
    sm = rm if shaft_material is None else shaft_material
    hm = rm if housing_material is None else housing_material
    Ii = float(as_array(shaft_interference, "shaft_interference", bounded=True,
                        tiny_ok=True, unit="m")) + (a_s - ar) * (Ti - T0) * d
    Ie = float(as_array(housing_interference, "housing_interference", bounded=True,
                        tiny_ok=True, unit="m")) - (ah - ar) * (Te - T0) * Do
    pi_ = float(fit_pressure(Ii, d, F, shaft_bore, E_ring=rm.E, nu_ring=rm.nu, E_mate=sm.E,
                             nu_mate=sm.nu, ring="inner"))
    pe = float(fit_pressure(Ie, Do, Er, housing_diameter, E_ring=rm.E, nu_ring=rm.nu,
                            E_mate=hm.E, nu_mate=hm.nu, ring="outer"))
    di = 2.0 * pi_ * d**2 * F / (rm.E * (F**2 - d**2))
    de = 2.0 * pe * Do**2 * Er / (rm.E * (Do**2 - Er**2))
    dT = ar * (Te - T0) * Er - ar * (Ti - T0) * F - ab * (Tb - T0) * 2.0 * D
    Pd = P0 - di - de + dT
    if Pd < 0:
        log.info("operating clearance %.3g um: preload", Pd * 1e6)
    return OperatingClearance(initial=float(P0), fit_inner=float(di), fit_outer=float(de),
                              thermal=float(dT), operating=float(Pd), pressure_inner=pi_,
                              pressure_outer=pe, interference_inner=float(max(Ii, 0.0)),
                              interference_outer=float(max(Ie, 0.0)))
