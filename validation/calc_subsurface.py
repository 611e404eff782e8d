"""Calculations for the subsurface-stress area (:mod:`ballrace.analytic.subsurface`).

Outputs are nondimensional, as Johnson and Lundberg–Palmgren tabulate them: stresses
over p_max, depths and offsets over the semi-minor axis b (= a for a circle).
"""
from __future__ import annotations

import math

from .calc_hertz import materials
from .registry import Param, calculation

_SUB = "ballrace.analytic.subsurface"
_L = Param("[length]", allow_inf=True)
_MAT = {"E1": Param("[pressure]", 200e9), "nu1": Param("", 0.3), "E2": Param("[pressure]", None),
        "nu2": Param("", None)}


def _contact(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2):
    from ballrace.analytic import hertz

    return hertz.point_contact(load, rx1, ry1, rx2, ry2, *materials(E1, nu1, E2, nu2))


@calculation("subsurface.point", requires=(_SUB,),
             inputs={"load": Param("[force]"), "rx1": _L, "ry1": _L,
                     "rx2": Param("[length]", math.inf, allow_inf=True),
                     "ry2": Param("[length]", math.inf, allow_inf=True), **_MAT,
                     "nu": Param("", 0.3)},
             outputs={"tau_max_p0": "", "tau_max_depth_b": "", "von_mises_p0": "",
                      "von_mises_depth_b": "", "tau0_p0": "", "z0_b": "", "x0_b": "", "t": "",
                      "k": ""})
def point(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2, nu):
    """Max shear, von Mises and Lundberg–Palmgren orthogonal shear of a point contact."""
    from ballrace.analytic import subsurface

    c = _contact(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2)
    p0, b = float(c.p_max), float(c.b)
    mx = subsurface.max_shear(c, nu=nu)
    vm = subsurface.von_mises(c, nu=nu)
    o = subsurface.orthogonal_shear(c)
    return {"tau_max_p0": float(mx.tau_max) / p0, "tau_max_depth_b": float(mx.depth) / b,
            "von_mises_p0": float(vm.sigma_vm) / p0, "von_mises_depth_b": float(vm.depth) / b,
            "tau0_p0": float(o.tau0) / p0, "z0_b": float(o.z0) / b, "x0_b": float(o.x0) / b,
            "t": float(o.t), "k": float(c.k)}


@calculation("subsurface.line", requires=(_SUB,),
             inputs={"load_per_length": Param("[force] / [length]"), "r1": _L,
                     "r2": Param("[length]", math.inf, allow_inf=True), **_MAT,
                     "nu": Param("", 0.3)},
             outputs={"tau_max_p0": "", "tau_max_depth_b": "", "tau0_p0": "", "z0_b": "",
                      "x0_b": ""})
def line(load_per_length, r1, r2, E1, nu1, E2, nu2, nu):
    """Max shear and orthogonal shear under a Hertz line contact."""
    from ballrace.analytic import hertz, subsurface

    lc = hertz.line_contact(load_per_length, r1, r2, *materials(E1, nu1, E2, nu2))
    p0, b = float(lc.p_max), float(lc.b)
    mx = subsurface.line_max_shear(lc, nu=nu)
    o = subsurface.line_orthogonal_shear(lc)
    return {"tau_max_p0": float(mx.tau_max) / p0, "tau_max_depth_b": float(mx.depth) / b,
            "tau0_p0": float(o.tau0) / p0, "z0_b": float(o.z0) / b, "x0_b": float(o.x0) / b}


@calculation("subsurface.stress_at", requires=(_SUB,),
             inputs={"load": Param("[force]"), "rx1": _L, "ry1": _L,
                     "rx2": Param("[length]", math.inf, allow_inf=True),
                     "ry2": Param("[length]", math.inf, allow_inf=True), **_MAT,
                     "nu": Param("", 0.3), "x_a": Param(""), "y_a": Param("", 0.0),
                     "z_a": Param("")},
             outputs={"sxx_p0": "", "syy_p0": "", "szz_p0": "", "sxz_p0": "", "tresca_p0": "",
                      "von_mises_p0": ""})
def stress_at(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2, nu, x_a, y_a, z_a):
    """Stress components at (x, y, z) given in units of the semi-major axis a."""
    from ballrace.analytic import subsurface

    c = _contact(load, rx1, ry1, rx2, ry2, E1, nu1, E2, nu2)
    a, p0 = float(c.a), float(c.p_max)
    s = subsurface.stress(c, x_a * a, y_a * a, z_a * a, nu=nu)
    return {"sxx_p0": float(s.sxx) / p0, "syy_p0": float(s.syy) / p0,
            "szz_p0": float(s.szz) / p0, "sxz_p0": float(s.sxz) / p0,
            "tresca_p0": float(s.tresca) / p0, "von_mises_p0": float(s.von_mises) / p0}
