r"""Calculations that check the roller load distribution with clearance against the
load-zone integrals of Sjövall and the lamina slices against the half-space line contact.

* ``roller.load_zone_integral`` — a cylindrical bearing of many straight rollers with the
  ring approach imposed and the clearance set for a chosen load-zone factor epsilon:
  ``J_r = F_r / (Z Q_max)`` of the lamina model against Sjövall's radial integral

  .. math:: J_r(\varepsilon) = \frac{1}{2\pi}\int_{-\psi_l}^{\psi_l}
            \Big[1 - \frac{1 - \cos\psi}{2\varepsilon}\Big]^n \cos\psi\,d\psi,
            \qquad \cos\psi_l = 1 - 2\varepsilon\ (\varepsilon \le 1),\ \psi_l = \pi
            \ (\varepsilon > 1)

  (H. Sjövall, Teknisk Tidskrift, Mekanik, 1933; the definition as given by Harris &
  Kotzalas, *Essential Concepts of Bearing Technology*, 2007, the chapter on load
  distribution), evaluated here by quadrature for the lamina exponent n = 10/9 and for
  the exponent n = 1.1 of the published line-contact tables;
* ``roller.clearance_method`` — a bearing of few rollers under a radial load with
  clearance: Q_max of the lamina model against the discrete sum solved as one equation in
  the ring approach, and against the continuous J_r(epsilon) method (Q_max = F_r /
  (Z J_r), delta_r = P_d/2 + (Q_max/K)^(1/n), iterated on epsilon), the method of
  Oswald, Zaretsky & Poplawski (NASA/TM-2012-217115, 2012) and of Harris & Kotzalas;
* ``roller.lamina_vs_line_contact`` — the slice loads of the most loaded roller in the
  lamina model against the half-space line contact of the same roller
  (:meth:`~ballrace.analytic.roller.RollerLoadDistribution.roller_contact`).

The helpers :func:`radial_integral`, :func:`axial_integral` and :func:`jr_method` are
used by the report's roller figures too.
"""
from __future__ import annotations

import math

from .calc_roller import make_roller_bearing
from .registry import Param, calculation

__all__ = ["radial_integral", "axial_integral", "jr_method", "discrete_method",
           "load_zone_integral", "clearance_method", "lamina_vs_line_contact"]

_ROLLER = "ballrace.analytic.roller:RollerBearing"

_GEOMETRY = {
    "roller_diameter": Param("[length]"), "roller_length": Param("[length]"),
    "n_rollers": Param("int"), "pitch_diameter": Param("[length]"),
    "n_slices": Param("int", 5),
    "stiffness": Param("str", "iso", choices=("iso", "palmgren")),
    "E": Param("[pressure]", 200e9), "nu": Param("", 0.3),
}


def _zone_limit(eps: float) -> float:
    """Half-angle psi_l of the load zone [rad] for the load-zone factor ``eps`` [-]."""
    return math.acos(1.0 - 2.0 * eps) if eps <= 1.0 else math.pi


def radial_integral(eps: float, n: float = 10.0 / 9.0) -> float:
    """Sjövall's radial integral J_r(eps) for the load-deflection exponent ``n`` [-]
    (quadrature; module notes).

    >>> round(1.0 / radial_integral(0.5, 1.1), 3)     # line contact, zero clearance
    4.077
    """
    from scipy import integrate

    if not eps > 0.0:
        raise ValueError(f"eps must be > 0 (the load-zone factor); got {eps!r}")
    pl = _zone_limit(eps)

    def f(p):
        return max(0.0, 1.0 - (1.0 - math.cos(p)) / (2.0 * eps)) ** n * math.cos(p)

    return integrate.quad(f, 0.0, pl, limit=200, epsabs=1e-12, epsrel=1e-10)[0] / math.pi


def axial_integral(eps: float, n: float = 10.0 / 9.0) -> float:
    """Sjövall's axial integral J_a(eps) for the exponent ``n`` [-] (quadrature).

    >>> round(axial_integral(0.5, 1.1) / radial_integral(0.5, 1.1), 4)   # published: 1.260
    1.2595
    """
    from scipy import integrate

    if not eps > 0.0:
        raise ValueError(f"eps must be > 0 (the load-zone factor); got {eps!r}")
    pl = _zone_limit(eps)

    def f(p):
        return max(0.0, 1.0 - (1.0 - math.cos(p)) / (2.0 * eps)) ** n

    return integrate.quad(f, 0.0, pl, limit=200, epsabs=1e-12, epsrel=1e-10)[0] / math.pi


def jr_method(Fr: float, n_rollers: int, K: float, clearance: float,
              n: float = 10.0 / 9.0) -> tuple[float, float, float]:
    """Q_max [N], ring approach delta_r [m] and eps [-] of a radially loaded bearing by the
    continuous J_r(eps) method: Z K (delta_r - P_d/2)^n J_r(eps) = F_r with
    eps = (1 - P_d / (2 delta_r)) / 2.

    Parameters
    ----------
    Fr : float
        Radial load [N].
    n_rollers : int
        Number of rollers Z [-].
    K : float
        Roller stiffness between both raceways, Q = K delta^n [N/m^n].
    clearance : float
        Diametral clearance P_d [m] (negative: preload).
    n : float
        Load-deflection exponent [-].
    """
    from scipy import optimize

    def residual(dr):
        eps = 0.5 * (1.0 - clearance / (2.0 * dr))
        return n_rollers * K * (dr - clearance / 2.0) ** n * radial_integral(eps, n) - Fr

    lo = max(clearance / 2.0, 0.0) * (1.0 + 1e-9) + 1e-12
    dr = optimize.brentq(residual, lo, 1e-2, xtol=1e-16, rtol=1e-13)
    return K * (dr - clearance / 2.0) ** n, dr, 0.5 * (1.0 - clearance / (2.0 * dr))


def discrete_method(Fr: float, azimuths, K: float, clearance: float,
                    n: float = 10.0 / 9.0) -> tuple[float, float]:
    """Q_max [N] and delta_r [m] of straight rollers at ``azimuths`` [rad]: the sum
    sum_j K <delta_r cos psi_j - P_d/2>^n cos psi_j = F_r solved as one equation in
    delta_r (the same equations as the lamina model, solved without it)."""
    import numpy as np
    from scipy import optimize

    c = np.cos(np.asarray(azimuths, dtype=float))

    def residual(dr):
        return float(np.sum(K * np.clip(dr * c - clearance / 2.0, 0.0, None) ** n * c)) - Fr

    lo = max(clearance / 2.0, 0.0) + 1e-12
    dr = optimize.brentq(residual, lo, 1e-2, xtol=1e-18, rtol=1e-14)
    return K * (dr - clearance / 2.0) ** n, dr


def _bearing(clearance, **kw):
    return make_roller_bearing(diametral_clearance=clearance, **kw)


@calculation("roller.load_zone_integral", requires=(_ROLLER,),
             inputs={**_GEOMETRY, "load_zone_factor": Param(""),
                     "radial_deflection": Param("[length]"),
                     "table_exponent": Param("", 1.1)},
             outputs={"J_r": "", "J_r_vs_integral": "", "J_r_vs_table_exponent": "",
                      "q_max_vs_stiffness": "", "clearance": "[length]",
                      "load_zone_half_angle": "[angle]", "n_loaded": ""})
def load_zone_integral(load_zone_factor, radial_deflection, table_exponent, **geo):
    """J_r = F_r / (Z Q_max) of straight rollers with the ring approach delta_r imposed and
    the clearance P_d = 2 delta_r (1 - 2 eps) that makes the load-zone factor eps; against
    Sjövall's J_r(eps) with the lamina exponent 10/9 and with the table exponent."""
    import numpy as np

    eps, dr = float(load_zone_factor), float(radial_deflection)
    pd = 2.0 * dr * (1.0 - 2.0 * eps)
    brg = _bearing(clearance=pd, profile="straight", **geo)
    r = brg.solve(displacements=[0.0, dr, 0.0, 0.0, 0.0])
    Q = np.asarray(r.roller_loads)
    Qmax = float(Q.max())
    Fr = float(r.loads[1])
    Z = brg.n_rollers
    jr = Fr / (Z * Qmax)
    loaded = np.asarray(r.azimuths)[Q > 1e-12 * Qmax]
    half = float(np.max(np.abs(np.angle(np.exp(1j * loaded)))))
    dmax = dr - pd / 2.0
    return {"J_r": jr, "J_r_vs_integral": jr / radial_integral(eps, 10.0 / 9.0) - 1.0,
            "J_r_vs_table_exponent": jr / radial_integral(eps, table_exponent) - 1.0,
            "q_max_vs_stiffness": Qmax / (brg.lamina_stiffness * dmax ** (10.0 / 9.0)) - 1.0,
            "clearance": pd, "load_zone_half_angle": half,
            "n_loaded": float(np.count_nonzero(Q > 1e-12 * Qmax))}


@calculation("roller.clearance_method", requires=(_ROLLER,),
             inputs={**_GEOMETRY, "diametral_clearance": Param("[length]", 0.0),
                     "Fr": Param("[force]")},
             outputs={"Q_max": "[force]", "Q_max_vs_discrete": "",
                      "radial_deflection_vs_discrete": "", "Q_max_vs_jr_method": "",
                      "load_zone_factor": "", "n_loaded": "", "relative_residual": ""})
def clearance_method(diametral_clearance, Fr, **geo):
    """Q_max of straight rollers under F_r with clearance: the lamina model against the
    discrete sum solved in delta_r alone and against the continuous J_r(eps) method (both
    with the bearing's roller stiffness and the exponent 10/9)."""
    import numpy as np

    brg = _bearing(clearance=diametral_clearance, profile="straight", **geo)
    r = brg.solve(Fy=Fr)
    Q = np.asarray(r.roller_loads)
    Qmax = float(Q.max())
    K = brg.lamina_stiffness
    Qd, drd = discrete_method(Fr, r.azimuths, K, diametral_clearance)
    Qj, drj, eps = jr_method(Fr, brg.n_rollers, K, diametral_clearance)
    return {"Q_max": Qmax, "Q_max_vs_discrete": Qmax / Qd - 1.0,
            "radial_deflection_vs_discrete": float(r.radial_deflection) / drd - 1.0,
            "Q_max_vs_jr_method": Qmax / Qj - 1.0, "load_zone_factor": eps,
            "n_loaded": float(np.count_nonzero(Q > 1e-12 * Qmax)),
            "relative_residual": float(r.relative_residual)}


@calculation("roller.lamina_vs_line_contact", requires=(_ROLLER,),
             inputs={**_GEOMETRY, "n_slices": Param("int", 31),
                     "diametral_clearance": Param("[length]", 0.0), "Fr": Param("[force]"),
                     "profile": Param("str", "iso", choices=("iso", "lundberg", "crowned")),
                     "flat_length": Param("[length]", 0.0),
                     "crown_radius": Param("[length]", 1.0),
                     "raceway": Param("str", "inner", choices=("inner", "outer"))},
             outputs={"middle_slice_diff": "", "peak_slice_diff": "",
                      "peak_pressure_diff": "", "load_balance": "",
                      "loaded_slices_lamina": "", "loaded_slices_halfspace": ""})
def lamina_vs_line_contact(diametral_clearance, Fr, profile, flat_length, crown_radius,
                           raceway, **geo):
    """Most loaded roller under F_r: its lamina slice loads against the half-space line
    contact of the same roller (roller_contact), as lamina / half-space - 1 at the middle
    slice, at the most loaded slice and at the peak pressure; both carry the roller load."""
    import numpy as np

    from ballrace.analytic.roller import Crowned

    prof = Crowned(flat_length, crown_radius) if profile == "crowned" else profile
    brg = _bearing(clearance=diametral_clearance, profile=prof, **geo)
    r = brg.solve(Fy=Fr)
    j = int(np.argmax(r.roller_loads))
    c = r.roller_contact(j, raceway)
    lam = np.asarray(r.slice_loads_inner[j] if raceway == "inner" else r.slice_loads[j])
    hs = np.asarray(c.slice_loads)
    p_lam = np.asarray(r.slice_pressures(raceway))[j]
    m = len(lam) // 2
    return {"middle_slice_diff": float(lam[m] / hs[m] - 1.0),
            "peak_slice_diff": float(lam.max() / hs.max() - 1.0),
            "peak_pressure_diff": float(p_lam.max() / np.max(c.pressure) - 1.0),
            "load_balance": float(hs.sum() / lam.sum() - 1.0),
            "loaded_slices_lamina": float(np.count_nonzero(lam > 0)),
            "loaded_slices_halfspace": float(np.count_nonzero(hs > 0)),
            "_series": {"x": np.asarray(c.x), "q_lamina": lam, "q_halfspace": hs,
                        "p_lamina": p_lam, "p_halfspace": np.asarray(c.pressure)}}
