"""Calculations for load ratings and life (:mod:`ballrace.analytic.ratings`, :mod:`~.life`).

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
