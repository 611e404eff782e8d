"""Calculations for the Hertz area (:mod:`ballrace.analytic.hertz`).

Each function takes SI inputs as keywords and returns a dict of SI floats.
"""
from __future__ import annotations

import math

from .registry import Param, calculation

_HERTZ = "ballrace.analytic.hertz"
_METHODS = ("exact", "brewe-hamrock-1977", "hamrock-brewe-1983")
_L = Param("[length]", allow_inf=True)
_MATERIAL = {"E1": Param("[pressure]"), "nu1": Param(""), "E2": Param("[pressure]", None),
             "nu2": Param("", None)}
_POINT_OUT = {"Rx": "[length]", "Ry": "[length]", "E_prime": "[pressure]", "k": "",
              "a": "[length]", "b": "[length]", "approach": "[length]", "p_max": "[pressure]",
              "p_mean": "[pressure]", "stiffness": "[force] / [length] ** 1.5", "ellipk": "",
              "ellipe": "", "load": "[force]"}
_ERR_OUT = {f"err_{q}": "" for q in ("k", "ellipk", "ellipe", "a", "b", "approach", "p_max")}


def materials(E1, nu1, E2=None, nu2=None):
    """Two :class:`ballrace.Material` from SI inputs (body 2 defaults to body 1)."""
    from ballrace import Material

    m1 = Material(E=E1, nu=nu1)
    m2 = Material(E=E1 if E2 is None else E2, nu=nu1 if nu2 is None else nu2)
    return m1, m2


def contact_outputs(c) -> dict:
    """SI floats of a :class:`~ballrace.analytic.hertz.HertzContact`."""
    return {k: float(getattr(c, k)) for k in _POINT_OUT}


@calculation("hertz.point_contact", requires=(_HERTZ,),
             inputs={"load": Param("[force]"), "rx1": _L, "ry1": _L,
                     "rx2": Param("[length]", math.inf, allow_inf=True),
                     "ry2": Param("[length]", math.inf, allow_inf=True), **_MATERIAL,
                     "method": Param("str", "exact", choices=_METHODS)},
             outputs=_POINT_OUT)
def point_contact(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2, method):
    """Elliptical Hertz contact from principal radii and materials."""
    from ballrace.analytic import hertz

    return contact_outputs(hertz.point_contact(load, rx1, ry1, rx2, ry2,
                                               *materials(E1, nu1, E2, nu2), method=method))


@calculation("hertz.point_contact_from_approach", requires=(_HERTZ,),
             inputs={"approach": Param("[length]"), "rx1": _L, "ry1": _L,
                     "rx2": Param("[length]", math.inf, allow_inf=True),
                     "ry2": Param("[length]", math.inf, allow_inf=True), **_MATERIAL},
             outputs=_POINT_OUT)
def point_contact_from_approach(approach, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2):
    """Hertz contact for a prescribed mutual approach (displacement-controlled tests)."""
    from ballrace.analytic import hertz
    from ballrace.analytic.materials import effective_modulus

    m1, m2 = materials(E1, nu1, E2, nu2)
    geo = hertz.curvature(rx1, ry1, rx2, ry2)
    Ep = effective_modulus(m1, m2)
    load = float(hertz.load_from_approach(approach, geo.Rx, geo.Ry, Ep))
    return contact_outputs(hertz.elliptical_contact(load, geo.Rx, geo.Ry, Ep))


@calculation("hertz.line_contact", requires=(_HERTZ,),
             inputs={"load_per_length": Param("[force] / [length]"), "r1": _L,
                     "r2": Param("[length]", math.inf, allow_inf=True), **_MATERIAL},
             outputs={"b": "[length]", "p_max": "[pressure]", "p_mean": "[pressure]",
                      "R": "[length]", "E_prime": "[pressure]"})
def line_contact(load_per_length, r1, r2, E1, nu1, E2, nu2):
    """Hertz line contact of two parallel cylinders (plane strain)."""
    from ballrace.analytic import hertz

    c = hertz.line_contact(load_per_length, r1, r2, *materials(E1, nu1, E2, nu2))
    return {k: float(getattr(c, k)) for k in ("b", "p_max", "p_mean", "R", "E_prime")}


@calculation("hertz.ellipticity", requires=(_HERTZ,),
             inputs={"alpha_r": Param(""), "method": Param("str", "exact", choices=_METHODS)},
             outputs={"k": "", "ellipk": "", "ellipe": ""})
def ellipticity(alpha_r, method):
    """Ellipticity k and the elliptic integrals for a radius ratio."""
    from ballrace.analytic import hertz

    k, K, E = hertz.ellipticity(alpha_r, method=method)
    return {"k": float(k), "ellipk": float(K), "ellipe": float(E)}


@calculation("hertz.approximation_error", requires=(_HERTZ,),
             inputs={"alpha_r": Param(""), "method": Param("str", choices=_METHODS[1:])},
             outputs=_ERR_OUT)
def approximation_error(alpha_r, method):
    """Signed relative error of a simplified Hertz formula at one radius ratio."""
    from ballrace.analytic import hertz

    e = hertz.approximation_errors([alpha_r], method)
    return {f"err_{q}": float(v[0]) for q, v in e.items()}


@calculation("hertz.approximation_error_max", requires=(_HERTZ,),
             inputs={"method": Param("str", choices=_METHODS[1:]), "alpha_max": Param(""),
                     "n": Param("int", 4001)},
             outputs={f"max_abs_{k}": "" for k in _ERR_OUT})
def approximation_error_max(method, alpha_max, n):
    """Largest |relative error| of a simplified formula over 1 <= alpha_r <= alpha_max."""
    import numpy as np

    from ballrace.analytic import hertz

    e = hertz.approximation_errors(np.logspace(0.0, np.log10(alpha_max), n), method)
    return {f"max_abs_err_{q}": float(np.max(np.abs(v))) for q, v in e.items()}


@calculation("hertz.load_scaling", requires=(_HERTZ,),
             inputs={"load_lo": Param("[force]"), "load_hi": Param("[force]"), "rx1": _L,
                     "ry1": _L, "rx2": Param("[length]", math.inf, allow_inf=True),
                     "ry2": Param("[length]", math.inf, allow_inf=True), **_MATERIAL},
             outputs={"slope_a": "", "slope_b": "", "slope_approach": "", "slope_p_max": "",
                      "roundtrip_load_rel": "", "energy_rel": ""})
def load_scaling(load_lo, load_hi, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2):
    """Log-log slopes of a, b, delta, p_max against load, a load round trip, and the energy.

    The energy check integrates Q d(delta) numerically from 0 to the high load and
    compares with (2/5) Q delta (Johnson 1985 eq. 4.25 integrated).
    """
    import numpy as np
    from scipy import integrate

    from ballrace.analytic import hertz

    m1, m2 = materials(E1, nu1, E2, nu2)
    lo = hertz.point_contact(load_lo, rx1, ry1, rx2, ry2, m1, m2)
    hi = hertz.point_contact(load_hi, rx1, ry1, rx2, ry2, m1, m2)
    r = math.log(load_hi / load_lo)
    out = {f"slope_{q}": math.log(float(getattr(hi, q)) / float(getattr(lo, q))) / r
           for q in ("a", "b", "approach", "p_max")}
    back = float(hertz.load_from_approach(hi.approach, hi.Rx, hi.Ry, hi.E_prime))
    out["roundtrip_load_rel"] = back / load_hi - 1.0
    d = np.linspace(0.0, float(hi.approach), 2001)
    q = np.asarray(hertz.load_from_approach(d, hi.Rx, hi.Ry, hi.E_prime))
    work = integrate.simpson(q, x=d)
    out["energy_rel"] = work / (0.4 * load_hi * float(hi.approach)) - 1.0
    return out
