"""Calculations for load ratings and life (:mod:`ballrace.analytic.ratings`, :mod:`~ballrace.analytic.life`).

Speeds come in as angular velocities [rad/s] (pint turns ``"2000 rpm"`` into 209.4 rad/s)
and are converted to rev/min only where the catalog formulas are written that way.
"""
from __future__ import annotations

import math

from .registry import Param, calculation

_RAT = "ballrace.analytic.ratings"
_LIFE = "ballrace.analytic.life"
_STANDARDS = ("ISO 281:2007", "ABMA 9-1990")


def _rpm(omega: float) -> float:
    return omega * 60.0 / (2.0 * math.pi)


@calculation("life.dynamic_rating", requires=(_RAT + ":dynamic_rating",),
             inputs={"ball_diameter": Param("[length]"), "n_balls": Param("int"),
                     "pitch_diameter": Param("[length]"), "contact_angle": Param("[angle]", 0.0),
                     "n_rows": Param("int", 1),
                     "standard": Param("str", "ISO 281:2007", choices=_STANDARDS)},
             outputs={"C": "[force]"})
def dynamic_rating(ball_diameter, n_balls, pitch_diameter, contact_angle, n_rows, standard):
    """Basic dynamic load rating C (ISO 281 / ABMA Std 9)."""
    from ballrace.analytic import ratings

    return {"C": ratings.dynamic_rating(ball_diameter, n_balls, pitch_diameter, contact_angle,
                                        n_rows, standard=standard)}


@calculation("life.static_rating", requires=(_RAT + ":static_rating_pressure",),
             inputs={"ball_diameter": Param("[length]"), "n_balls": Param("int"),
                     "pitch_diameter": Param("[length]"), "contact_angle": Param("[angle]", 0.0),
                     "n_rows": Param("int", 1)},
             outputs={"C0": "[force]", "p_max_at_C0": "[pressure]"})
def static_rating(ball_diameter, n_balls, pitch_diameter, contact_angle, n_rows):
    """Basic static load rating C0 (ISO 76) and the Hertz pressure it stands for."""
    from ballrace.analytic import ratings

    C0 = ratings.static_rating(ball_diameter, n_balls, pitch_diameter, contact_angle, n_rows)
    sp = ratings.static_rating_pressure(ball_diameter, n_balls, pitch_diameter, contact_angle,
                                        n_rows)
    return {"C0": float(C0), "p_max_at_C0": float(sp.p_max)}


@calculation("life.catalog_hours", requires=(_LIFE + ":catalog_l10_hours",),
             inputs={"C": Param("[force]"), "P": Param("[force]"), "factor": Param("", 1.0),
                     "speed": Param("1 / [time]"), "exponent": Param("", 10.0 / 3.0)},
             outputs={"L10h": "[time]", "L10h_hours": ""})
def catalog_hours(C, P, factor, speed, exponent):
    """Catalog life L10 = 3000 (C / (P F))^n (500 / S) hours (Tata 2012)."""
    from ballrace.analytic import life

    h = float(life.catalog_l10_hours(C, P * factor, speed_rpm=_rpm(speed), exponent=exponent))
    return {"L10h": h * 3600.0, "L10h_hours": h}


@calculation("life.l10", requires=(_LIFE + ":l10_hours",),
             inputs={"C": Param("[force]"), "P": Param("[force]"), "speed": Param("1 / [time]"),
                     "exponent": Param("", 3.0)},
             outputs={"L10": "", "L10h_hours": ""})
def l10(C, P, speed, exponent):
    """ISO 281 basic rating life L10 [1e6 rev] and in hours at a speed."""
    from ballrace.analytic import life

    return {"L10": float(life.l10(C, P, exponent)),
            "L10h_hours": float(life.l10_hours(C, P, speed_rpm=_rpm(speed), exponent=exponent))}


@calculation("life.miner", requires=(_LIFE + ":miner",),
             inputs={"lives_hours": Param("list"), "fractions": Param("list")},
             outputs={"L_hours": ""})
def miner(lives_hours, fractions):
    """Palmgren–Miner life under a duty cycle."""
    from ballrace.analytic import life

    return {"L_hours": float(life.miner(list(lives_hours), list(fractions)))}


@calculation("life.hardness", requires=(_LIFE + ":hardness_factor",),
             inputs={"hardness_hrc": Param("")},
             outputs={"G": "", "life_drop": ""})
def hardness(hardness_hrc):
    """Hardness life factor G and the relative drop in life 1 - G."""
    from ballrace.analytic import life

    g = float(life.hardness_factor(hardness_hrc))
    return {"G": g, "life_drop": 1.0 - g}


# --------------------------------------------------------------------------- ISO 281:2007,
# ISO/TS 16281 and operating clearance
_ISO281 = "ballrace.analytic.iso281"
_ISO16281 = "ballrace.analytic.iso16281"
_CLEAR = "ballrace.analytic.clearance"


@calculation("life.iso_reliability", requires=(_ISO281 + ":reliability_factor",),
             inputs={"reliability": Param("")},
             outputs={"a1": "", "a1_formula": ""})
def iso_reliability(reliability):
    """ISO 281:2007 a1: Table 12 value and the Weibull formula behind it."""
    from ballrace.analytic import iso281

    return {"a1": float(iso281.reliability_factor(reliability)),
            "a1_formula": float(iso281.reliability_factor(reliability, method="formula"))}


@calculation("life.iso_viscosity", requires=(_ISO281 + ":operating_viscosity",),
             inputs={"nu40": Param("[length] ** 2 / [time]"),
                     "nu100": Param("[length] ** 2 / [time]"),
                     "temperature": Param("[temperature]"),
                     "speed": Param("1 / [time]"), "pitch_diameter": Param("[length]")},
             outputs={"nu": "[length] ** 2 / [time]", "nu1": "[length] ** 2 / [time]",
                      "kappa": ""})
def iso_viscosity(nu40, nu100, temperature, speed, pitch_diameter):
    """Walther / ASTM D341 viscosity at temperature, ISO 281 nu1 and kappa."""
    from ballrace.analytic import iso281

    nu = float(iso281.operating_viscosity(nu40, nu100, temperature))
    n = _rpm(speed)
    return {"nu": nu, "nu1": float(iso281.reference_viscosity(n, pitch_diameter)),
            "kappa": float(iso281.viscosity_ratio(nu, n, pitch_diameter))}


@calculation("life.iso_a_iso", requires=(_ISO281 + ":life_modification_factor",),
             inputs={"kappa": Param(""), "load_ratio": Param("")},
             outputs={"a_ISO": "", "jump_at_0p4": "", "jump_at_1": ""})
def iso_a_iso(kappa, load_ratio):
    """a_ISO(kappa, e_C C_u / P) of radial ball bearings and its relative jumps at the
    kappa-range boundaries 0.4 and 1 (at the same load ratio)."""
    from ballrace.analytic import iso281

    f = iso281.life_modification_factor

    def jump(k):
        lo, hi = float(f(k * (1 - 1e-12), 1.0, load_ratio, 1.0)), float(f(k, 1.0, load_ratio, 1.0))
        return abs(hi / lo - 1.0)

    return {"a_ISO": float(f(kappa, 1.0, load_ratio, 1.0)), "jump_at_0p4": jump(0.4),
            "jump_at_1": jump(1.0)}


@calculation("life.iso_fatigue_limit", requires=(_ISO281 + ":fatigue_load_limit_hertz",),
             inputs={"ball_diameter": Param("[length]"), "n_balls": Param("int"),
                     "pitch_diameter": Param("[length]"), "f_inner": Param(""),
                     "f_outer": Param(""), "E": Param("[pressure]"), "nu": Param("")},
             outputs={"C_u_hertz": "[force]", "C_u_simplified": "[force]", "ratio": ""})
def iso_fatigue_limit(ball_diameter, n_balls, pitch_diameter, f_inner, f_outer, E, nu):
    """C_u by the 1.5 GPa Hertz method and by C0/22 (ISO 281:2007 Annex B)."""
    import ballrace
    from ballrace.analytic import iso281, ratings

    brg = ballrace.BallBearing(ball_diameter, n_balls, pitch_diameter, f_inner, f_outer,
                               diametral_clearance=0.0, material=ballrace.Material(E=E, nu=nu))
    h = iso281.fatigue_load_limit_hertz(brg).C_u
    s = float(iso281.fatigue_load_limit(ratings.static_rating(brg, contact_angle=0.0),
                                        pitch_diameter))
    return {"C_u_hertz": h, "C_u_simplified": s, "ratio": h / s}


@calculation("life.iso_reference_life",
             requires=(_ISO16281 + ":reference_rating_life", _LIFE + ":bearing_life"),
             inputs={"ball_diameter": Param("[length]"), "n_balls": Param("int"),
                     "pitch_diameter": Param("[length]"), "f_inner": Param(""),
                     "f_outer": Param(""), "radial_load": Param("[force]"),
                     "clearance": Param("[length]", 0.0), "azimuth_offset": Param("[angle]", 0.0)},
             outputs={"C": "[force]", "L10r": "", "L10": "", "L10r_over_L10": "",
                      "L10r_over_LP": "", "free_contact_angle": "[angle]",
                      "nominal_contact_angle": "[angle]"})
def iso_reference_life(ball_diameter, n_balls, pitch_diameter, f_inner, f_outer, radial_load,
                       clearance, azimuth_offset):
    """ISO/TS 16281 L10r of a deep-groove bearing under radial load, against (C/Fr)^3 and
    against the Lundberg-Palmgren bearing_life of the same ball loads.  C and the raceway
    capacities are the library's defaults: the bearing's nominal contact angle (0 for a
    deep-groove bearing given by its clearance)."""
    import ballrace
    from ballrace.analytic import life

    brg = ballrace.BallBearing(ball_diameter, n_balls, pitch_diameter, f_inner, f_outer,
                               diametral_clearance=max(clearance, 0.0))
    res = brg.radial(radial_load, clearance=clearance, azimuth_offset=azimuth_offset)
    r = life.reference_rating_life(brg, res)
    L10 = (r.C / radial_load) ** 3
    return {"C": r.C, "L10r": r.L10r, "L10": L10, "L10r_over_L10": r.L10r / L10,
            "L10r_over_LP": r.L10r / life.bearing_life(brg, res).L10,
            "free_contact_angle": float(brg.free_contact_angle),
            "nominal_contact_angle": float(brg.nominal_contact_angle)}


@calculation("life.operating_clearance", requires=(_CLEAR + ":operating_clearance",),
             inputs={"ball_diameter": Param("[length]"), "pitch_diameter": Param("[length]"),
                     "initial_clearance": Param("[length]"), "bore": Param("[length]"),
                     "outside_diameter": Param("[length]"),
                     "shaft_interference": Param("[length]", 0.0),
                     "housing_interference": Param("[length]", 0.0),
                     "shaft_bore": Param("[length]", 0.0),
                     "inner_temperature": Param("[temperature]", 293.15),
                     "outer_temperature": Param("[temperature]", 293.15)},
             outputs={"fit_inner": "[length]", "fit_outer": "[length]", "thermal": "[length]",
                      "operating": "[length]"})
def operating_clearance(ball_diameter, pitch_diameter, initial_clearance, bore,
                        outside_diameter, shaft_interference, housing_interference, shaft_bore,
                        inner_temperature, outer_temperature):
    """Operating clearance from fits (Lamé) and ring temperatures (steel throughout)."""
    import ballrace
    from ballrace.analytic import clearance as cl

    brg = ballrace.BallBearing(ball_diameter, 7, pitch_diameter, 0.52, 0.53,
                               diametral_clearance=initial_clearance)
    oc = cl.operating_clearance(brg, bore=bore, outside_diameter=outside_diameter,
                                shaft_interference=shaft_interference,
                                housing_interference=housing_interference,
                                shaft_bore=shaft_bore, inner_temperature=inner_temperature,
                                outer_temperature=outer_temperature)
    return {"fit_inner": oc.fit_inner, "fit_outer": oc.fit_outer, "thermal": oc.thermal,
            "operating": oc.operating}
