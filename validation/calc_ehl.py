"""Calculations for elastohydrodynamic film thickness (:mod:`ballrace.analytic.ehl`)."""
from __future__ import annotations

import math

from .calc_hertz import materials
from .registry import Param, calculation

_EHL = "ballrace.analytic.ehl"
_L = Param("[length]", allow_inf=True)


@calculation("ehl.film_thickness", requires=(_EHL + ":film_thickness",),
             inputs={"load": Param("[force]"), "rx1": _L, "ry1": _L,
                     "rx2": Param("[length]", math.inf, allow_inf=True),
                     "ry2": Param("[length]", math.inf, allow_inf=True),
                     "E1": Param("[pressure]", 200e9), "nu1": Param("", 0.3),
                     "E2": Param("[pressure]", None), "nu2": Param("", None),
                     "entrainment_speed": Param("[length] / [time]"),
                     "viscosity": Param("[mass] / [length] / [time]"),
                     "pressure_viscosity": Param("1 / [pressure]"),
                     "speed_factor": Param("", 2.0)},
             outputs={"h_min": "[length]", "h_central": "[length]", "k_ehl": "", "U": "",
                      "G": "", "W": "", "speed_exponent_min": "", "load_exponent_min": ""})
def film_thickness(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2, entrainment_speed, viscosity,
                   pressure_viscosity, speed_factor):
    """Hamrock–Dowson 1977 film thickness of a Hertz contact, with its speed and load exponents."""
    from ballrace.analytic import ehl, hertz

    m1, m2 = materials(E1, nu1, E2, nu2)

    def h(Q, u):
        c = hertz.point_contact(Q, rx1, ry1, rx2, ry2, m1, m2)
        return ehl.film_thickness(c, entrainment_speed=u, viscosity=viscosity,
                                  pressure_viscosity=pressure_viscosity)

    f = h(load, entrainment_speed)
    fu = h(load, entrainment_speed * speed_factor)
    fq = h(load * speed_factor, entrainment_speed)
    r = math.log(speed_factor)
    return {"h_min": float(f.h_min), "h_central": float(f.h_central), "k_ehl": float(f.k),
            "U": float(f.U), "G": float(f.G), "W": float(f.W),
            "speed_exponent_min": math.log(float(fu.h_min) / float(f.h_min)) / r,
            "load_exponent_min": math.log(float(fq.h_min) / float(f.h_min)) / r}


@calculation("ehl.film_parameter", requires=(_EHL + ":film_parameter",),
             inputs={"h_min": Param("[length]"), "roughness_race": Param("[length]"),
                     "roughness_ball": Param("[length]")},
             outputs={"Lambda": ""})
def film_parameter(h_min, roughness_race, roughness_ball):
    """Film parameter Lambda = h_min / sqrt(Rq_race^2 + Rq_ball^2)."""
    from ballrace.analytic import ehl

    return {"Lambda": float(ehl.film_parameter(h_min, roughness_race, roughness_ball))}
