r"""Elastohydrodynamic film thickness of elliptical contacts (Hamrock & Dowson 1977).

Isothermal, fully flooded, Newtonian lubricant with the Barus pressure–viscosity law;
the formulas are the curve fits Hamrock & Dowson obtained from their numerical solutions
(ellipticity 1 <= k <= 8, W'/U, G within the ranges of hard EHL):

.. math::
    \hat H_{min} = \frac{h_{min}}{R_x} = 3.63\, U^{0.68} G^{0.49} W^{-0.073}
                   \left(1 - e^{-0.68 k}\right), \qquad
    \hat H_c = \frac{h_c}{R_x} = 2.69\, U^{0.67} G^{0.53} W^{-0.067}
                   \left(1 - 0.61\, e^{-0.73 k}\right)

with U = η0 u / (E' R_x), G = ξ E', W = Q / (E' R_x²), u the mean entrainment (rolling)
speed (u_a + u_b)/2, and the ellipticity parameter of the fits k = 1.03 (R_y/R_x)^0.64.
E' is Hamrock & Dowson's effective modulus (twice Johnson's E*).

References
----------
Hamrock, B.J. & Dowson, D. (1977) "Isothermal elastohydrodynamic lubrication of point
contacts, Part III — Fully flooded results", *J. Lubr. Technol.* 99(2) 264–276 (h_min,
eq. 16; central film and k = 1.03 α^0.64) and Part IV (starvation results), 99(1) 15–23;
Hamrock & Dowson (1981) *Ball Bearing Lubrication* ch. 8 (same fits); docs/sources.md.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from ._checks import (as_array, broadcast, check_instance, check_nonnegative, check_positive,
                      check_range)
from ._renames import renamed_keywords
from .hertz import HertzContact

__all__ = [
    "FilmThickness",
    "ellipticity_parameter",
    "film_thickness",
    "film_thickness_parts",
    "film_parameter",
    "entrainment_speed",
]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class FilmThickness:
    """EHL film of an elliptical contact (frozen).  Arrays when inputs were arrays.

    Attributes
    ----------
    h_central : Central film thickness h_c [m].
    h_min : Minimum film thickness h_min [m].
    U : Dimensionless speed η0 u / (E' Rx) [-].
    G : Dimensionless materials parameter ξ E' [-].
    W : Dimensionless load Q / (E' Rx²) [-].
    k : Ellipticity parameter of the fits, 1.03 (Ry/Rx)^0.64 [-].
    Rx : Effective radius in the rolling direction [m].
    entrainment_speed : Mean entrainment speed u [m/s].
    """

    h_central: np.ndarray
    h_min: np.ndarray
    U: np.ndarray
    G: np.ndarray
    W: np.ndarray
    k: np.ndarray
    Rx: np.ndarray
    entrainment_speed: np.ndarray

    @property
    def H_min(self):
        """Dimensionless minimum film h_min / Rx [-]."""
        return self.h_min / self.Rx

    @property
    def H_central(self):
        """Dimensionless central film h_c / Rx [-]."""
        return self.h_central / self.Rx


def ellipticity_parameter(Rx, Ry):
    r"""Hamrock & Dowson's ellipticity approximation k = 1.03 (Ry/Rx)^0.64 [-].

    This is the k their film-thickness fits were built with (Hamrock & Dowson 1977 Part
    III; Hamrock & Dowson 1981 eq. 3.28 gives the closer 1.0339 α^0.636).  It is within
    3.5 % of the exact Hertz k for 1 <= Ry/Rx <= 40 (3 % high for a circle, 8 % high at
    Ry/Rx = 100).

    Parameters
    ----------
    Rx, Ry : float or array_like
        Effective radii in the rolling and transverse directions [m], > 0.

    Examples
    --------
    >>> round(float(ellipticity_parameter(0.005, 0.05)), 4)
    4.4961
    """
    Rx = check_positive(Rx, "Rx", "m", bounded=True)
    Ry = check_positive(Ry, "Ry", "m", bounded=True)
    Rx, Ry = broadcast(Rx=Rx, Ry=Ry)
    return _s(1.03 * (Ry / Rx) ** 0.64)


def film_thickness_parts(load, Rx, Ry, E_prime, *, entrainment_speed, viscosity,
                         pressure_viscosity) -> FilmThickness:
    r"""Hamrock–Dowson 1977 central and minimum film thickness from plain numbers.

    Parameters
    ----------
    load : float or array_like
        Normal load Q [N], > 0.
    Rx, Ry : float or array_like
        Effective radii in the rolling (entrainment) and transverse directions [m], > 0.
    E_prime : float or array_like
        Effective modulus E' = 2 / [(1-ν_a²)/E_a + (1-ν_b²)/E_b] [Pa], > 0.
    entrainment_speed : float or array_like
        Mean entrainment speed u = (u_a + u_b)/2 [m/s], > 0.
    viscosity : float or array_like
        Dynamic viscosity at atmospheric pressure and the inlet temperature η0 [Pa s], > 0.
    pressure_viscosity : float or array_like
        Pressure–viscosity coefficient ξ (Barus) [1/Pa], > 0.

    Returns
    -------
    FilmThickness

    References
    ----------
    Hamrock & Dowson (1977) Part III eqs. for H_min and H_c; Hamrock & Dowson (1981) ch. 8.

    Examples
    --------
    Ball–inner-race contact of a 209 bearing (Rx = 5.11 mm, Ry = 168 mm), 4 kN, u = 10 m/s,
    η0 = 0.04 Pa s, ξ = 2.2e-8 1/Pa, steel E' = 219.8 GPa:

    >>> f = film_thickness_parts(4000.0, 5.11e-3, 0.168, 219.8e9, entrainment_speed=10.0,
    ...                          viscosity=0.04, pressure_viscosity=2.2e-8)
    >>> round(float(f.h_min) * 1e6, 3), round(float(f.h_central) * 1e6, 3)
    (0.756, 0.937)
    """
    Q = check_positive(load, "load", "N", bounded=True)
    Rx = check_positive(Rx, "Rx", "m", bounded=True)
    Ry = check_positive(Ry, "Ry", "m", bounded=True)
    Ep = check_positive(E_prime, "E_prime", "Pa", bounded=True)
    u = check_positive(entrainment_speed, "entrainment_speed", "m/s", bounded=True)
    eta = check_positive(viscosity, "viscosity", "Pa*s", bounded=True)
    xi = check_positive(pressure_viscosity, "pressure_viscosity", "1/Pa", bounded=True)
    Q, Rx, Ry, Ep, u, eta, xi = broadcast(load=Q, Rx=Rx, Ry=Ry, E_prime=Ep, entrainment_speed=u,
                                          viscosity=eta, pressure_viscosity=xi)
    k = 1.03 * (Ry / Rx) ** 0.64
    if np.any((k < 1.0) | (k > 8.0)):
        log.info("EHL: ellipticity parameter k outside the fitted range 1..8 (min %.3g, "
                 "max %.3g): the Hamrock-Dowson fits are extrapolated", np.min(k), np.max(k))
    U = eta * u / (Ep * Rx)
    G = xi * Ep
    W = Q / (Ep * Rx**2)
    H_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1.0 - np.exp(-0.68 * k))
    H_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k))
    Q, Rx, U, G, W, k, H_min, H_c, u = np.broadcast_arrays(Q, Rx, U, G, W, k, H_min, H_c, u)
    return FilmThickness(h_central=_s(H_c * Rx), h_min=_s(H_min * Rx), U=_s(U), G=_s(G),
                         W=_s(W), k=_s(k), Rx=_s(Rx), entrainment_speed=_s(u))


def film_thickness(contact, *, entrainment_speed, viscosity, pressure_viscosity) -> FilmThickness:
    r"""Hamrock–Dowson 1977 film thickness of a Hertz contact.

    Uses the contact's load, ``Rx`` (rolling direction), ``Ry`` and ``E_prime``
    (:class:`ballrace.analytic.hertz.HertzContact`, e.g. from
    :meth:`ballrace.BallBearing.contacts`).  Unloaded balls (Q = 0) get NaN films.

    Parameters
    ----------
    contact : HertzContact
        The contact(s).
    entrainment_speed : float or array_like
        Mean entrainment speed u [m/s] (:func:`entrainment_speed`), > 0.
    viscosity : float or array_like
        η0 [Pa s], > 0.
    pressure_viscosity : float or array_like
        ξ [1/Pa], > 0.

    Returns
    -------
    FilmThickness
        ``h_central``, ``h_min`` [m] and U, G, W, k.

    References
    ----------
    Hamrock & Dowson (1977) Part III; Hamrock & Dowson (1981) ch. 8.

    Examples
    --------
    >>> from ballrace.analytic import hertz
    >>> c = hertz.elliptical_contact(4000.0, 5.11e-3, 0.168, 219.8e9)
    >>> f = film_thickness(c, entrainment_speed=10.0, viscosity=0.04, pressure_viscosity=2.2e-8)
    >>> round(float(f.h_min) * 1e6, 3)
    0.756
    """
    check_instance(contact, "contact", HertzContact)
    u = check_positive(entrainment_speed, "entrainment_speed", "m/s", bounded=True)
    eta = check_positive(viscosity, "viscosity", "Pa*s", bounded=True)
    xi = check_positive(pressure_viscosity, "pressure_viscosity", "1/Pa", bounded=True)
    broadcast(entrainment_speed=u, viscosity=eta, pressure_viscosity=xi,
              contact=np.asarray(contact.load))
    Q = np.asarray(contact.load, dtype=float)
    loaded = Q > 0
    Qs = np.where(loaded, Q, 1.0)
    f = film_thickness_parts(Qs, contact.Rx, contact.Ry, contact.E_prime,
                             entrainment_speed=entrainment_speed, viscosity=viscosity,
                             pressure_viscosity=pressure_viscosity)
    if np.all(loaded):
        return f
    nan = lambda x: _s(np.where(loaded, x, np.nan))  # noqa: E731
    return FilmThickness(h_central=nan(f.h_central), h_min=nan(f.h_min), U=f.U, G=f.G,
                         W=nan(f.W), k=f.k, Rx=f.Rx, entrainment_speed=f.entrainment_speed)


def film_parameter(h_min, roughness_race, roughness_ball):
    r"""Film parameter Λ = h_min / (R_q,race² + R_q,ball²)^(1/2) [-].

    Parameters
    ----------
    h_min : float or array_like
        Minimum film thickness [m], >= 0.
    roughness_race, roughness_ball : float or array_like
        RMS surface roughness of race and ball R_q [m], >= 0, not both 0.

    References
    ----------
    Hamrock & Dowson (1981) eq. (3.125); Tallian (1967).

    Examples
    --------
    >>> round(float(film_parameter(0.3e-6, 0.175e-6, 0.075e-6)), 3)
    1.576
    """
    h = check_nonnegative(h_min, "h_min", "m", bounded=True)
    rr = check_nonnegative(roughness_race, "roughness_race", "m", bounded=True)
    rb = check_nonnegative(roughness_ball, "roughness_ball", "m", bounded=True)
    h, rr, rb = broadcast(h_min=h, roughness_race=rr, roughness_ball=rb)
    s = np.sqrt(rr**2 + rb**2)
    if np.any(s == 0):
        raise ValueError("roughness_race and roughness_ball must not both be 0 [m]")
    return _s(h / s)


@renamed_keywords(inner_speed="speed_inner", outer_speed="speed_outer")
def entrainment_speed(ball_diameter, pitch_diameter, contact_angle=0.0, *, speed_inner,
                      speed_outer=0.0):
    r"""Mean entrainment (rolling) speed of the ball–race contacts for pure rolling [m/s].

    .. math:: u = \frac{d_m^2 - D^2 \cos^2\beta}{4 d_m}\,\lvert\omega_i - \omega_o\rvert

    Same for the inner and outer contact: each race surface and the ball surface move at
    this speed relative to the contact, which travels with the cage.

    Parameters
    ----------
    ball_diameter : float
        D [m], > 0.
    pitch_diameter : float
        d_m [m], > D.
    contact_angle : float or array_like
        Contact angle β [rad].
    speed_inner : float or array_like
        Angular speed of the inner ring ω_i [rad/s] (2π N/60 for N rev/min); the old
        keyword ``inner_speed`` still works (DeprecationWarning).
    speed_outer : float or array_like
        Angular speed of the outer ring ω_o [rad/s]; old keyword ``outer_speed``.

    Returns
    -------
    float or ndarray
        u [m/s].

    References
    ----------
    Hamrock & Dowson (1981) ch. 2 (kinematics: ω_c = ω_i (1 − γ)/2 for a fixed outer ring)
    and ch. 8; Harris (2001) §8.1.

    Examples
    --------
    209 bearing, inner ring at 4000 rev/min:

    >>> round(float(entrainment_speed(0.0127, 0.065, speed_inner=4000 * 2 * np.pi / 60)), 3)
    6.547
    """
    D = check_positive(ball_diameter, "ball_diameter", "m", bounded=True)
    dm = check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True)
    b = check_range(contact_angle, "contact_angle", -np.pi / 2, np.pi / 2, unit="rad")
    wi = as_array(speed_inner, "speed_inner", bounded=True, tiny_ok=True, unit="rad/s")
    wo = as_array(speed_outer, "speed_outer", bounded=True, tiny_ok=True, unit="rad/s")
    D, dm, b, wi, wo = broadcast(ball_diameter=D, pitch_diameter=dm, contact_angle=b,
                                 speed_inner=wi, speed_outer=wo)
    if np.any(D >= dm):
        raise ValueError("ball_diameter must be < pitch_diameter [m]")
    return _s((dm**2 - (D * np.cos(b)) ** 2) / (4.0 * dm) * np.abs(wi - wo))


def _s(x):
    x = np.asarray(x, dtype=float)
    return x[()] if x.ndim == 0 else x
