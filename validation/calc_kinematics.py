"""Calculations for ball kinematics, defect frequencies and the high-speed Jones model.

(:mod:`ballrace.analytic.kinematics`, :mod:`ballrace.analytic.highspeed`).  Two report
areas: ``kinematics`` (defect frequencies as multiples of the shaft speed, cage and ball
speeds, pitch angle and spin-to-roll ratios under race control) and ``highspeed``
(ball mass, centrifugal force and gyroscopic moment; the Jones (1960) equilibrium under
thrust at speed, compared with the static solution of :mod:`ballrace.analytic.loaddist`).

Kinematic ratios are returned per unit speed of the rotating ring (the other ring
stationary), the way defect frequencies are tabulated ("multiples of running speed");
speeds that enter the dynamics come in as angular velocities [rad/s] (pint turns
``"10000 rpm"`` into 1047.2 rad/s).
"""
from __future__ import annotations

import math

from .calc_bearing import BEARING_INPUTS
from .registry import Param, calculation

_KIN = "ballrace.analytic.kinematics"
_HS = "ballrace.analytic.highspeed"
_LD = "ballrace.analytic.loaddist"
_CONTROLS = ("outer", "inner", "perpendicular")
_DENSITY = Param("[mass] / [length] ** 3", 7850.0)

_DEFECT_OUTPUTS = {"ftf": "", "bpfo": "", "bpfi": "", "bsf": "", "bsf_x2": ""}


def _defects(f) -> dict:
    bsf = float(f.bsf)
    return {"ftf": float(f.ftf), "bpfo": float(f.bpfo), "bpfi": float(f.bpfi), "bsf": bsf,
            "bsf_x2": 2.0 * bsf}


def _ring_speeds(rotating: str) -> tuple[float, float]:
    return (1.0, 0.0) if rotating == "inner" else (0.0, 1.0)


@calculation("kinematics.defect_frequencies", requires=(_KIN + ":defect_frequencies",),
             inputs={"ball_diameter": Param("[length]"), "pitch_diameter": Param("[length]"),
                     "n_balls": Param("int"), "contact_angle": Param("[angle]", 0.0),
                     "rotating": Param("str", "inner", choices=("inner", "outer"))},
             outputs=_DEFECT_OUTPUTS)
def defect_frequencies(ball_diameter, pitch_diameter, n_balls, contact_angle, rotating):
    """FTF, BPFO, BPFI, BSF (and 2 BSF) as multiples of the rotating ring's speed."""
    from ballrace.analytic import kinematics

    wi, wo = _ring_speeds(rotating)
    return _defects(kinematics.defect_frequencies(ball_diameter, pitch_diameter, n_balls,
                                                  contact_angle, speed_inner=wi,
                                                  speed_outer=wo))


@calculation("kinematics.bearing_defect_frequencies",
             requires=(_KIN + ":bearing_defect_frequencies",
                       "ballrace.analytic.bearing:BallBearing"),
             inputs={**BEARING_INPUTS, "contact_angle": Param("[angle]", None),
                     "rotating": Param("str", "inner", choices=("inner", "outer"))},
             outputs=_DEFECT_OUTPUTS)
def bearing_defect_frequencies(contact_angle=None, rotating="inner", **kw):
    """Defect frequencies of a BallBearing (at its free contact angle unless given)."""
    from ballrace.analytic import kinematics

    from .calc_bearing import make_bearing

    brg = make_bearing(**kw)
    wi, wo = _ring_speeds(rotating)
    return _defects(kinematics.bearing_defect_frequencies(brg, speed_inner=wi, speed_outer=wo,
                                                          contact_angle=contact_angle))


@calculation("kinematics.ball", requires=(_KIN + ":ball_kinematics", _KIN + ":spin_to_roll"),
             inputs={"ball_diameter": Param("[length]"), "pitch_diameter": Param("[length]"),
                     "contact_angle_inner": Param("[angle]"),
                     "contact_angle_outer": Param("[angle]", None),
                     "control": Param("str", "outer", choices=_CONTROLS),
                     "rotating": Param("str", "inner", choices=("inner", "outer"))},
             outputs={"cage_ratio": "", "ball_ratio": "", "pitch_angle": "[angle]",
                      "spin_inner_ratio": "", "spin_outer_ratio": "",
                      "spin_to_roll_inner": "", "spin_to_roll_outer": "",
                      "spin_to_roll_inner_fn": "", "spin_to_roll_outer_fn": ""})
def ball(ball_diameter, pitch_diameter, contact_angle_inner, contact_angle_outer, control,
         rotating):
    """Cage and ball speeds per unit ring speed, pitch angle, spin and spin-to-roll ratios
    (from ball_kinematics; the ``_fn`` outputs from spin_to_roll, a separate code path)."""
    from ballrace.analytic import kinematics

    wi, wo = _ring_speeds(rotating)
    k = kinematics.ball_kinematics(ball_diameter, pitch_diameter, contact_angle_inner,
                                   contact_angle_outer, speed_inner=wi, speed_outer=wo,
                                   control=control)
    si, so = kinematics.spin_to_roll(ball_diameter, pitch_diameter, contact_angle_inner,
                                     contact_angle_outer, control=control)
    return {"cage_ratio": float(k.cage_speed), "ball_ratio": float(k.ball_speed),
            "pitch_angle": float(k.pitch_angle), "spin_inner_ratio": float(k.spin_inner),
            "spin_outer_ratio": float(k.spin_outer),
            "spin_to_roll_inner": float(k.spin_to_roll_inner),
            "spin_to_roll_outer": float(k.spin_to_roll_outer),
            "spin_to_roll_inner_fn": float(si), "spin_to_roll_outer_fn": float(so)}


@calculation("highspeed.ball_dynamics",
             requires=(_HS + ":centrifugal_force", _HS + ":gyroscopic_moment",
                       _KIN + ":ball_kinematics"),
             inputs={"ball_diameter": Param("[length]"), "pitch_diameter": Param("[length]"),
                     "contact_angle": Param("[angle]", 0.0), "density": _DENSITY,
                     "speed_inner": Param("1 / [time]"),
                     "speed_outer": Param("1 / [time]", 0.0)},
             outputs={"ball_mass": "[mass]", "orbital_speed": "1 / [time]",
                      "ball_speed": "1 / [time]", "pitch_angle": "[angle]", "Fc": "[force]",
                      "gyroscopic_moment": "[force] * [length]"})
def ball_dynamics(ball_diameter, pitch_diameter, contact_angle, density, speed_inner,
                  speed_outer):
    """Ball mass, cage speed (outer-race control), F_c = m d_m omega_c^2 / 2 and M_g."""
    from ballrace.analytic import highspeed, kinematics

    k = kinematics.ball_kinematics(ball_diameter, pitch_diameter, contact_angle, None,
                                   speed_inner=speed_inner, speed_outer=speed_outer,
                                   control="outer")
    wc, wR, beta = float(k.cage_speed), float(k.ball_speed), float(k.pitch_angle)
    return {"ball_mass": float(highspeed.ball_mass(ball_diameter, density)),
            "orbital_speed": wc, "ball_speed": wR, "pitch_angle": beta,
            "Fc": float(highspeed.centrifugal_force(ball_diameter, density, pitch_diameter, wc)),
            "gyroscopic_moment": float(highspeed.gyroscopic_moment(ball_diameter, density, wR,
                                                                   wc, beta))}


HS_INPUTS = {**BEARING_INPUTS, "density": _DENSITY, "Fa": Param("[force]"),
             "speed_inner": Param("1 / [time]", 0.0), "speed_outer": Param("1 / [time]", 0.0),
             "control": Param("str", "outer", choices=("outer", "inner", "jones")),
             "gyroscopic": Param("str", "harris", choices=("harris", "controlling-race",
                                                           "none"))}


def _hs_bearing(ball_diameter, n_balls, pitch_diameter, f_inner, f_outer,
                free_contact_angle=None, diametral_clearance=None, E=200e9, nu=0.3,
                density=7850.0, nominal_contact_angle=None):
    """A BallBearing whose steel has the given density (ball mass for F_c and M_g)."""
    from ballrace import Material
    from ballrace.analytic.bearing import BallBearing

    return BallBearing(ball_diameter=ball_diameter, n_balls=n_balls,
                       pitch_diameter=pitch_diameter, f_inner=f_inner, f_outer=f_outer,
                       free_contact_angle=free_contact_angle,
                       diametral_clearance=diametral_clearance,
                       nominal_contact_angle=nominal_contact_angle,
                       material=Material(E=E, nu=nu, density=density))


def _split_hs(kw):
    keys = set(BEARING_INPUTS) | {"density"}
    return _hs_bearing(**{k: kw.pop(k) for k in list(kw) if k in keys}), kw


def _worst(x):
    """The element of largest magnitude (signed), as a float."""
    import numpy as np

    x = np.ravel(np.asarray(x, dtype=float))
    return float(x[int(np.argmax(np.abs(x)))])


@calculation("highspeed.thrust", requires=(_HS + ":solve", _LD + ":thrust"),
             inputs=HS_INPUTS,
             outputs={"Q_inner": "[force]", "Q_outer": "[force]", "alpha_inner": "[angle]",
                      "alpha_outer": "[angle]", "Fc": "[force]", "orbital_speed": "1 / [time]",
                      "axial_displacement": "[length]", "relative_residual": "",
                      "Fc_vs_orbit_formula": "", "ring_axial_balance": "",
                      "ball_axial_balance": "", "ball_radial_balance": "",
                      "Q_inner_vs_static": "",
                      "Q_outer_vs_static": "", "alpha_inner_vs_static": "[angle]",
                      "alpha_outer_vs_static": "[angle]", "axial_vs_static": ""})
def thrust(Fa, speed_inner, speed_outer, control, gyroscopic, **kw):
    """Jones (1960) equilibrium under concentric thrust at speed (ball 1), the solver's
    F_c against m (d_orbit/2) omega_c^2, equilibrium balances recomputed from the
    reported loads and angles, and the differences from the static thrust solution
    (loaddist.thrust; relative for loads and deflection, absolute for angles)."""
    import numpy as np

    from ballrace.analytic import highspeed, loaddist

    brg, _ = _split_hs(kw)
    r = highspeed.solve(brg, Fa=Fa, speed_inner=speed_inner, speed_outer=speed_outer,
                        control=control, gyroscopic=gyroscopic)
    st = loaddist.thrust(brg, Fa)
    Qs = float(st.max_ball_load)
    beta = float(np.mean(np.asarray(st.contact_angles)))
    dt = float(st.axial_deflection)
    Qi, Qo = np.asarray(r.inner_loads), np.asarray(r.outer_loads)
    ai, ao = np.asarray(r.inner_contact_angles), np.asarray(r.outer_contact_angles)
    # H&D (1981) eq. 3.107: F_c = (1/2) m d_orbit omega_c^2, d_orbit/2 = radius of the
    # outer-groove curvature centre + the radial ball-centre offset X2 from it
    r_orbit = 0.5 * brg.outer_race_diameter - brg.f_outer * brg.ball_diameter \
        + np.asarray(r.ball_positions)[:, 1]
    wc = np.asarray(r.orbital_speed)
    Fc = np.asarray(r.centrifugal_force)
    ref = brg.ball_mass * r_orbit * wc**2
    fc_check = _worst(Fc / ref - 1.0) if np.all(ref > 0) else _worst(Fc - ref)
    # Equilibrium from the reported numbers (H&D 1981 eqs. 3.104-3.105, 3.111).  The
    # friction forces that resist M_g are not reported, so the balances are formed only
    # where they vanish: at the inner race under outer-race control (lambda_i = 0) for
    # the ring, everywhere with gyroscopic="none" for the ball.
    si, so, ci, co = np.sin(ai), np.sin(ao), np.cos(ai), np.cos(ao)
    no_gyro = gyroscopic == "none"
    ring = (float(np.sum(Qi * si)) / Fa - 1.0
            if no_gyro or np.all(np.asarray(r.control) == "outer") else math.nan)
    ball_ax = _worst((Qi * si - Qo * so) / Qo) if no_gyro else math.nan
    ball_rad = _worst((Qo * co - Qi * ci - Fc) / Qo) if no_gyro else math.nan
    return {"Q_inner": float(Qi[0]), "Q_outer": float(Qo[0]), "alpha_inner": float(ai[0]),
            "alpha_outer": float(ao[0]), "Fc": float(Fc[0]), "orbital_speed": float(wc[0]),
            "axial_displacement": float(r.axial_deflection),
            "relative_residual": float(r.relative_residual),
            "Fc_vs_orbit_formula": fc_check, "ring_axial_balance": ring,
            "ball_axial_balance": ball_ax, "ball_radial_balance": ball_rad,
            "Q_inner_vs_static": _worst(Qi / Qs - 1.0), "Q_outer_vs_static": _worst(Qo / Qs - 1.0),
            "alpha_inner_vs_static": _worst(ai - beta), "alpha_outer_vs_static": _worst(ao - beta),
            "axial_vs_static": float(r.axial_deflection) / dt - 1.0 if dt else math.nan}


@calculation("highspeed.angle_trend", requires=(_HS + ":solve",),
             inputs={**HS_INPUTS, "speed_increment": Param("1 / [time]")},
             outputs={"outer_angle_change": "[angle]", "inner_angle_change": "[angle]",
                      "relative_residual": ""})
def angle_trend(Fa, speed_inner, speed_outer, control, gyroscopic, speed_increment, **kw):
    """Change of the contact angles (ball 1) when the inner-ring speed rises by
    ``speed_increment``: alpha(omega + d omega) - alpha(omega)."""
    from ballrace.analytic import highspeed

    brg, _ = _split_hs(kw)
    res = [highspeed.solve(brg, Fa=Fa, speed_inner=w, speed_outer=speed_outer,
                           control=control, gyroscopic=gyroscopic)
           for w in (speed_inner, speed_inner + speed_increment)]
    a0, a1 = res
    return {"outer_angle_change": float(a1.outer_contact_angles[0] - a0.outer_contact_angles[0]),
            "inner_angle_change": float(a1.inner_contact_angles[0] - a0.inner_contact_angles[0]),
            "relative_residual": max(float(x.relative_residual) for x in res)}
