"""Calculations for bearing geometry and load distribution.

(:mod:`ballrace.analytic.bearing`, :mod:`ballrace.analytic.loaddist`).  Load-distribution
calculations also return ``_series`` (azimuths, ball loads, contact angles) for the
report's plots.
"""
from __future__ import annotations

import math

from .registry import Param, calculation

_BRG = "ballrace.analytic.bearing:BallBearing"
_LD = "ballrace.analytic.loaddist"

BEARING_INPUTS = {
    "ball_diameter": Param("[length]"), "n_balls": Param("int"),
    "pitch_diameter": Param("[length]"), "f_inner": Param(""), "f_outer": Param(""),
    "free_contact_angle": Param("[angle]", None), "diametral_clearance": Param("[length]", None),
    "nominal_contact_angle": Param("[angle]", None),
    "E": Param("[pressure]", 200e9), "nu": Param("", 0.3),
}


def make_bearing(ball_diameter, n_balls, pitch_diameter, f_inner, f_outer,
                 free_contact_angle=None, diametral_clearance=None, nominal_contact_angle=None,
                 E=200e9, nu=0.3):
    """A :class:`ballrace.analytic.bearing.BallBearing` from SI inputs."""
    from ballrace import Material
    from ballrace.analytic.bearing import BallBearing

    return BallBearing(ball_diameter=ball_diameter, n_balls=n_balls,
                       pitch_diameter=pitch_diameter, f_inner=f_inner, f_outer=f_outer,
                       free_contact_angle=free_contact_angle,
                       diametral_clearance=diametral_clearance, material=Material(E=E, nu=nu),
                       nominal_contact_angle=nominal_contact_angle)


def _split(kw):
    brg = make_bearing(**{k: kw.pop(k) for k in list(kw) if k in BEARING_INPUTS})
    return brg, kw


def _series(ld) -> dict:
    import numpy as np

    return {"psi": np.asarray(ld.azimuths), "Q": np.asarray(ld.ball_loads),
            "beta": np.asarray(ld.contact_angles)}


def _ball_at(ld, psi: float) -> int:
    """Index of the ball closest to azimuth ``psi``."""
    import numpy as np

    d = np.angle(np.exp(1j * (np.asarray(ld.azimuths) - psi)))
    return int(np.argmin(np.abs(d)))


@calculation("bearing.geometry", requires=(_BRG,),
             inputs={**BEARING_INPUTS, "contact_angle": Param("[angle]", None)},
             outputs={"total_conformity": "", "curvature_center_distance": "[length]",
                      "diametral_clearance": "[length]", "free_contact_angle": "[angle]",
                      "nominal_contact_angle": "[angle]", "free_endplay": "[length]",
                      "inner_race_diameter": "[length]",
                      "outer_race_diameter": "[length]", "Rx_inner": "[length]",
                      "Ry_inner": "[length]", "Rx_outer": "[length]", "Ry_outer": "[length]",
                      "curvature_sum_inner": "1 / [length]", "curvature_difference_inner": "",
                      "K_n": "[force] / [length] ** 1.5"})
def geometry(contact_angle=None, **kw):
    """Internal geometry, effective radii and ball stiffness (at beta_f unless given), and
    the nominal (rating) contact angle."""
    brg, _ = _split(kw)
    beta = brg.free_contact_angle if contact_angle is None else contact_angle
    ci, co = brg.curvature("inner", beta), brg.curvature("outer", beta)
    _, _, Kn = brg.contact_stiffness(beta)
    return {"total_conformity": brg.total_conformity,
            "curvature_center_distance": brg.curvature_center_distance,
            "diametral_clearance": float(brg.diametral_clearance),
            "free_contact_angle": float(brg.free_contact_angle),
            "nominal_contact_angle": float(brg.nominal_contact_angle),
            "free_endplay": brg.free_endplay, "inner_race_diameter": brg.inner_race_diameter,
            "outer_race_diameter": brg.outer_race_diameter,
            "Rx_inner": float(ci.Rx), "Ry_inner": float(ci.Ry), "Rx_outer": float(co.Rx),
            "Ry_outer": float(co.Ry), "curvature_sum_inner": float(ci.curvature_sum),
            "curvature_difference_inner": float(ci.curvature_difference), "K_n": float(Kn)}


@calculation("bearing.radial", requires=(_BRG, _LD + ":radial"),
             inputs={**BEARING_INPUTS, "Fr": Param("[force]"),
                     "clearance": Param("[length]", None),
                     "azimuth_offset": Param("[angle]", 0.0)},
             outputs={"Q_max": "[force]", "Q_1": "[force]", "Q_2": "[force]", "Q_3": "[force]",
                      "zq_ratio": "", "loaded_zone": "[angle]", "radial_deflection": "[length]",
                      "n_loaded": "", "relative_residual": "", "jones_zw": "",
                      "jones_vs_exact": ""})
def radial(Fr, clearance=None, azimuth_offset=0.0, **kw):
    """Pure radial load: ball loads (balls 1, 2, 3 from the load line), Z Q_max / F_r,
    and Jones's closed-form factor Z_w at the computed clearance ratio for comparison."""
    import numpy as np

    from ballrace.analytic import loaddist

    brg, _ = _split(kw)
    ld = brg.radial(Fr, clearance=clearance, azimuth_offset=azimuth_offset)
    Q = np.asarray(ld.ball_loads)
    dr = float(ld.radial_deflection)
    Pd = float(ld.clearance)
    zw = float(loaddist.jones_radial_factor(Pd / (2 * dr))) if dr > 0 else math.nan
    ratio = brg.n_balls * float(ld.max_ball_load) / Fr
    return {"Q_max": float(ld.max_ball_load), "Q_1": float(Q[0]), "Q_2": float(Q[1]),
            "Q_3": float(Q[-1]), "zq_ratio": ratio,
            "loaded_zone": float(ld.loaded_zone), "radial_deflection": dr,
            # a ball exactly at 90 deg gets delta_r cos(90 deg) ~ 1e-17 delta_r: count balls
            # carrying more than 1e-9 Q_max, so rounding does not decide the count
            "n_loaded": float(np.count_nonzero(Q > 1e-9 * float(ld.max_ball_load))),
            "relative_residual": float(ld.relative_residual), "jones_zw": zw,
            "jones_vs_exact": zw / ratio - 1.0, "_series": _series(ld)}


@calculation("bearing.thrust", requires=(_BRG, _LD + ":thrust"),
             inputs={**BEARING_INPUTS, "Fa": Param("[force]")},
             outputs={"Q": "[force]", "contact_angle": "[angle]", "axial_deflection": "[length]",
                      "relative_residual": "", "p_max_inner": "[pressure]"})
def thrust(Fa, **kw):
    """Pure (concentric) thrust: ball load, contact angle, axial deflection."""
    import numpy as np

    brg, _ = _split(kw)
    ld = brg.thrust(Fa)
    return {"Q": float(ld.max_ball_load),
            "contact_angle": float(np.mean(np.asarray(ld.contact_angles))),
            "axial_deflection": float(ld.axial_deflection),
            "relative_residual": float(ld.relative_residual),
            "p_max_inner": float(np.max(np.asarray(ld.inner.p_max))), "_series": _series(ld)}


@calculation("bearing.eccentric_thrust", requires=(_BRG, _LD + ":eccentric_thrust"),
             inputs={**BEARING_INPUTS, "Fa": Param("[force]"), "e": Param("[length]")},
             outputs={"Q_max": "[force]", "beta_0": "[angle]", "beta_180": "[angle]",
                      "loaded_zone": "[angle]", "axial_deflection": "[length]",
                      "tilt": "[angle]", "relative_residual": ""})
def eccentric_thrust(Fa, e, **kw):
    """Eccentric thrust (Ricci 2009): Q_max, contact angles at psi = 0 and 180 deg, loaded zone."""
    brg, _ = _split(kw)
    ld = brg.eccentric_thrust(Fa, e)
    import numpy as np

    beta = np.asarray(ld.contact_angles)
    return {"Q_max": float(ld.max_ball_load), "beta_0": float(beta[_ball_at(ld, 0.0)]),
            "beta_180": float(beta[_ball_at(ld, math.pi)]),
            "loaded_zone": float(ld.loaded_zone), "axial_deflection": float(ld.axial_deflection),
            "tilt": float(ld.misalignment), "relative_residual": float(ld.relative_residual),
            "_series": _series(ld)}


@calculation("bearing.jones_factor", requires=(_LD + ":jones_radial_factor",),
             inputs={"clearance_ratio": Param("")},
             outputs={"Z_w": "", "stribeck_limit": ""})
def jones_factor(clearance_ratio):
    """Jones's radial load-distribution factor Z_w and the exact Stribeck limit constant."""
    from ballrace.analytic import loaddist

    return {"Z_w": float(loaddist.jones_radial_factor(clearance_ratio)),
            "stribeck_limit": float(loaddist.STRIBECK_LIMIT)}


@calculation("bearing.duplex", requires=("ballrace.analytic.duplex:DuplexPair",),
             inputs={**BEARING_INPUTS, "arrangement": Param("str", "DB", choices=("DB", "DF", "DT")),
                     "preload": Param("[force]"), "Fa": Param("[force]"),
                     "Fr": Param("[force]", 0.0)},
             outputs={"F1": "[force]", "F2": "[force]", "F1_minus_F2": "[force]",
                      "unloading_ratio": "", "residual": "[force]"})
def duplex(arrangement, preload, Fa, Fr, **kw):
    """Axial load sharing of a preloaded duplex pair under an external axial load."""
    from ballrace.analytic.duplex import DuplexPair

    brg, _ = _split(kw)
    r = DuplexPair(brg, arrangement, preload=preload).solve(Fa=Fa, Fr=Fr)
    f1, f2 = (float(v) for v in r.axial_loads)
    return {"F1": f1, "F2": f2, "F1_minus_F2": f1 - f2,
            "unloading_ratio": float(r.unloading_load) / preload if preload else math.nan,
            "residual": float(r.residual)}
