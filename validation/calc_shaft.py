"""Calculations for an elastic shaft on its ball bearings (:mod:`ballrace.analytic.shaft`).

Each solves a shaft of one cross-section (steel, E = 200 GPa, nu = 0.3 unless given) on
identical single-row bearings and returns the seat reactions and deflections the
reference cases compare with beam theory.
"""
from __future__ import annotations

from .calc_bearing import BEARING_INPUTS, make_bearing
from .registry import Param, calculation

_SH = "ballrace.analytic.shaft"
_SHAFT = {"shaft_length": Param("[length]"), "shaft_diameter": Param("[length]"),
          "shaft_E": Param("[pressure]", 200e9), "shaft_nu": Param("", 0.3)}


def _split(kw):
    from ballrace import Material
    from ballrace.analytic import shaft

    brg = make_bearing(**{k: kw.pop(k) for k in list(kw) if k in BEARING_INPUTS})
    s = shaft.Shaft([(kw.pop("shaft_length"), kw.pop("shaft_diameter"), 0.0)],
                    Material(E=kw.pop("shaft_E"), nu=kw.pop("shaft_nu")))
    return brg, s, kw


@calculation("shaft.two_seats", requires=(_SH + ":solve",),
             inputs={**BEARING_INPUTS, **_SHAFT, "x_a": Param("[length]"),
                     "x_b": Param("[length]"), "x_load": Param("[length]"),
                     "Fy": Param("[force]")},
             outputs={"R_a": "[force]", "R_b": "[force]", "v_chord": "[length]"})
def two_seats(x_a, x_b, x_load, Fy, **kw):
    """Two seats, a lateral load between them: reactions and the deflection under the load
    measured from the chord through the seats (the beam's own bending and shear)."""
    from ballrace.analytic import shaft

    brg, s, _ = _split(kw)
    r = shaft.solve(s, [shaft.Seat(x_a, brg), shaft.Seat(x_b, brg)],
                    [shaft.PointLoad(x_load, Fy=Fy)])
    va, vb, vc = r.displacement([x_a, x_b, x_load])[:, 1]
    t = (x_load - x_a) / (x_b - x_a)
    return {"R_a": float(r.reactions[0, 1]), "R_b": float(r.reactions[1, 1]),
            "v_chord": float(vc - ((1 - t) * va + t * vb))}


@calculation("shaft.three_seats", requires=(_SH + ":solve",),
             inputs={**BEARING_INPUTS, **_SHAFT, "x_load": Param("[length]"),
                     "Fy": Param("[force]")},
             outputs={"R_1": "[force]", "R_2": "[force]", "R_3": "[force]"})
def three_seats(x_load, Fy, **kw):
    """Seats at both ends and in the middle of the shaft, a lateral load: the three reactions."""
    from ballrace.analytic import shaft

    brg, s, _ = _split(kw)
    L = s.length
    r = shaft.solve(s, [shaft.Seat(0.0, brg), shaft.Seat(0.5 * L, brg), shaft.Seat(L, brg)],
                    [shaft.PointLoad(x_load, Fy=Fy)])
    return {"R_1": float(r.reactions[0, 1]), "R_2": float(r.reactions[1, 1]),
            "R_3": float(r.reactions[2, 1])}


@calculation("shaft.thermal_lift_off", requires=(_SH + ":solve",),
             inputs={**BEARING_INPUTS, **_SHAFT, "x_a": Param("[length]"),
                     "x_b": Param("[length]"), "offset": Param("[length]"),
                     "expansion": Param("1 / [temperature]")},
             outputs={"preload": "[force]", "dT_lift_off": "[temperature]"})
def thermal_lift_off(x_a, x_b, offset, expansion, **kw):
    """Two bearings in O arrangement, each mounted ``offset`` deep: the preload, and the
    shaft-over-housing temperature at which it vanishes (bisection to 1e-7 relative)."""
    import dataclasses

    from ballrace.analytic import shaft

    brg, s, _ = _split(kw)
    s = dataclasses.replace(s, thermal_expansion=expansion)
    seats = [shaft.Seat(x_a, brg, 1, offset=offset), shaft.Seat(x_b, brg, -1, offset=offset)]

    def preload(dT):                  # no external load: the preload alone
        return shaft.solve(s, seats, [], shaft_temperature_change=dT).reactions[0, 0]

    P0 = preload(0.0)
    lo, hi = 0.0, 1.0
    while preload(hi) > 1e-9 * P0:
        lo, hi = hi, 2.0 * hi
    while hi - lo > 1e-7 * hi:
        mid = 0.5 * (lo + hi)
        if preload(mid) > 1e-9 * P0:
            lo = mid
        else:
            hi = mid
    return {"preload": float(P0), "dT_lift_off": 0.5 * (lo + hi)}
