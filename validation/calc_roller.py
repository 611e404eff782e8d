"""Calculations for roller bearings and the finite line contact of a roller.

(:mod:`ballrace.analytic.roller`: :class:`~ballrace.analytic.roller.RollerBearing`, its
lamina load distribution, ratings and ISO/TS 16281 life, and
:func:`~ballrace.analytic.roller.line_contact`.)  Load-distribution calculations return
``_series`` (azimuths and roller loads) for the report.
"""
from __future__ import annotations

import math

from .registry import Param, calculation

_ROLLER = "ballrace.analytic.roller:RollerBearing"
_CONTACT = "ballrace.analytic.roller:line_contact"

ROLLER_INPUTS = {
    "roller_diameter": Param("[length]"), "roller_length": Param("[length]"),
    "n_rollers": Param("int"), "pitch_diameter": Param("[length]"),
    "kind": Param("str", "cylindrical", choices=("cylindrical", "tapered")),
    "contact_angle": Param("[angle]", 0.0), "diametral_clearance": Param("[length]", 0.0),
    "profile": Param("str", "iso", choices=("straight", "iso", "lundberg", "johns-gohar")),
    "n_slices": Param("int", 31), "E": Param("[pressure]", 200e9), "nu": Param("", 0.3),
}


def make_roller_bearing(roller_diameter, roller_length, n_rollers, pitch_diameter,
                        kind="cylindrical", contact_angle=0.0, diametral_clearance=0.0,
                        profile="iso", n_slices=31, E=200e9, nu=0.3, stiffness="iso"):
    """A :class:`ballrace.analytic.roller.RollerBearing` from SI inputs."""
    from ballrace import Material
    from ballrace.analytic.roller import RollerBearing

    return RollerBearing(roller_diameter=roller_diameter, roller_length=roller_length,
                         n_rollers=n_rollers, pitch_diameter=pitch_diameter, kind=kind,
                         contact_angle=contact_angle,
                         diametral_clearance=diametral_clearance, profile=profile,
                         n_slices=n_slices, stiffness=stiffness, material=Material(E=E, nu=nu))


def _split(kw):
    brg = make_roller_bearing(**{k: kw.pop(k) for k in list(kw) if k in ROLLER_INPUTS})
    return brg, kw


def _series(r) -> dict:
    import numpy as np

    return {"psi": np.asarray(r.azimuths), "Q": np.asarray(r.roller_loads)}


@calculation("roller.load_distribution", requires=(_ROLLER,),
             inputs={**ROLLER_INPUTS, "Fr": Param("[force]", 0.0), "Fa": Param("[force]", 0.0),
                     "axial_displacement": Param("[length]", None)},
             outputs={"Q_max": "[force]", "Q_min": "[force]", "zq_ratio": "",
                      "axial_ratio": "", "thrust_ratio": "", "n_loaded": "",
                      "relative_residual": "", "max_pressure": "[pressure]",
                      "static_safety": ""})
def load_distribution(Fr=0.0, Fa=0.0, axial_displacement=None, **kw):
    """Lamina load distribution under F_r (along y) and F_a, or with the axial displacement
    imposed: Q_max, Z Q_max cos(a) / F_r, F_a / (F_r tan a), Q_max Z sin(a) / F_a."""
    import numpy as np

    brg, _ = _split(kw)
    disp = None
    if axial_displacement is not None:
        disp = [axial_displacement, None, None, 0.0, 0.0]     # tilts held: no moment
        Fa = 0.0
    elif brg.tapered:
        disp = [None, None, None, 0.0, 0.0]
    r = brg.solve(Fa=Fa, Fy=Fr, displacements=disp)
    Q = np.asarray(r.roller_loads)
    a = brg.contact_angle
    Z = brg.n_rollers
    # the applied loads, and the axial reaction where the axial displacement is imposed
    Fa_res = float(r.loads[0]) if axial_displacement is not None else Fa
    Qmax = float(Q.max())
    return {"Q_max": Qmax, "Q_min": float(Q.min()),
            "zq_ratio": Z * Qmax * math.cos(a) / Fr if Fr else math.nan,
            "axial_ratio": (Fa_res / (Fr * math.tan(a)) if Fr and a else math.nan),
            "thrust_ratio": Z * Qmax * math.sin(a) / Fa_res if Fa_res else math.nan,
            "n_loaded": float(np.count_nonzero(Q > 1e-9 * Qmax)),
            "relative_residual": float(r.relative_residual),
            "max_pressure": float(r.max_pressure), "static_safety": float(r.static_safety),
            "_series": _series(r)}


@calculation("roller.ratings", requires=(_ROLLER,),
             inputs={**ROLLER_INPUTS, "catalogue_static_rating": Param("[force]", None)},
             outputs={"C_r": "[force]", "C_0r": "[force]", "effective_length": "[length]",
                      "length_ratio": ""})
def ratings(catalogue_static_rating=None, **kw):
    """ISO 281 C_r and ISO 76 C_0r of a roller bearing (RollerBearing methods); with a
    catalogue C_0r, the effective length L_we is first taken from it by ISO 76 (C_0r is
    linear in L_we) and C_r is computed for that L_we."""
    brg, _ = _split(kw)
    if catalogue_static_rating is not None:
        unit = make_roller_bearing(**{**_inputs_of(brg), "roller_length": 1e-3}).static_rating()
        lwe = catalogue_static_rating / unit * 1e-3
        brg = make_roller_bearing(**{**_inputs_of(brg), "roller_length": lwe})
    return {"C_r": brg.dynamic_rating(), "C_0r": brg.static_rating(),
            "effective_length": brg.roller_length,
            "length_ratio": brg.roller_length / brg.roller_diameter}


def _inputs_of(brg) -> dict:
    """The SI inputs of :func:`make_roller_bearing` that rebuild ``brg`` (named profiles)."""
    return dict(roller_diameter=brg.roller_diameter, roller_length=brg.roller_length,
                n_rollers=brg.n_rollers, pitch_diameter=brg.pitch_diameter, kind=brg.kind,
                contact_angle=brg.contact_angle, diametral_clearance=brg.diametral_clearance,
                profile=brg.profile.name, n_slices=brg.n_slices, E=brg.material.E,
                nu=brg.material.nu)


@calculation("roller.reference_life", requires=(_ROLLER, "ballrace.analytic.life"),
             inputs={**ROLLER_INPUTS, "Fr": Param("[force]")},
             outputs={"L10r": "", "life_factor": "", "load_factor": "",
                      "public_vs_direct": "", "gamma": ""})
def reference_life(Fr, **kw):
    """ISO/TS 16281 reference rating life of a radially loaded roller bearing through
    ballrace.analytic.life: L10r, K = L10r (0.83 F_r / C)^4, L10r^(1/4) F_r / C, and the
    public path against the roller package's own function."""
    from ballrace.analytic import life
    from ballrace.analytic.roller import life as rlife

    brg, _ = _split(kw)
    r = brg.solve(Fy=Fr)
    C = brg.dynamic_rating()
    L = float(life.reference_rating_life(brg, r, dynamic_rating=C).L10r)
    direct = float(rlife.reference_rating_life(brg, r, dynamic_rating=C).L10r)
    return {"L10r": L, "life_factor": L * (0.83 * Fr / C) ** 4,
            "load_factor": L ** 0.25 * Fr / C, "public_vs_direct": L / direct - 1.0,
            "gamma": brg.gamma}


@calculation("roller.line_contact", requires=(_CONTACT,),
             inputs={"Q": Param("[force]"), "R1": Param("[length]"),
                     "R2": Param("[length]", math.inf, allow_inf=True),
                     "length": Param("[length]"), "E": Param("[pressure]", 200e9),
                     "nu": Param("", 0.3),
                     "profile": Param("str", "lundberg", choices=(
                         "straight", "iso", "lundberg", "johns-gohar", "crowned")),
                     "flat_length": Param("[length]", 0.0),
                     "crown_radius": Param("[length]", 1.0),
                     "tilt": Param("[angle]", 0.0), "n_slices": Param("int", 41)},
             outputs={"p_max": "[pressure]", "p_center": "[pressure]",
                      "hertz_pressure": "[pressure]", "middle_uniformity": "",
                      "approach": "[length]", "approach_vs_lundberg": "",
                      "contact_length": "[length]", "center_vs_hertz": "",
                      "plateau_flatness": ""})
def line_contact(Q, R1, R2, length, E, nu, profile, flat_length, crown_radius, tilt,
                 n_slices):
    """Finite line contact of a profiled roller on the half-space: peak and centre
    pressures, the spread over the middle 80 % against 2-D Hertz at Q/L, the approach
    against Lundberg's closed form, the centre against 2-D Hertz at Q over the loaded
    length, and the flatness of the middle 20 %."""
    import numpy as np

    from ballrace import Material
    from ballrace.analytic.roller import Crowned, line_contact as lc

    mat = Material(E=E, nu=nu)
    prof = Crowned(flat_length, crown_radius) if profile == "crowned" else profile
    c = lc(Q, R1, R2, length, mat, mat, profile=prof, tilt=tilt, n_slices=n_slices)
    i = c.n_slices // 2
    p0 = c.hertz_pressure
    middle = np.abs(c.x) <= 0.4 * length
    q = Q / length
    b = math.sqrt(8.0 * q * c.R / (math.pi * c.E_prime))
    lundberg = 4.0 * q / (math.pi * c.E_prime) * (math.log(length / (2.0 * b))
                                                  + math.log(4.0) + 0.5)
    lc_len = c.contact_length
    p_lc = math.sqrt(Q / lc_len * c.E_prime / (2.0 * math.pi * c.R))
    plateau = np.abs(c.x) <= 0.1 * length
    return {"p_max": c.max_pressure, "p_center": float(c.pressure[i]), "hertz_pressure": p0,
            "middle_uniformity": float(np.max(np.abs(c.pressure[middle] / p0 - 1.0))),
            "approach": c.approach, "approach_vs_lundberg": c.approach / lundberg - 1.0,
            "contact_length": lc_len, "center_vs_hertz": float(c.pressure[i]) / p_lc - 1.0,
            "plateau_flatness": float(np.ptp(c.pressure[plateau]) / c.pressure[i]),
            "_series": {"x": np.asarray(c.x), "p": np.asarray(c.pressure)}}
