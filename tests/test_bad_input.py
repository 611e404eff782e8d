"""Bad input at every public entry point: the documented error, naming the argument.

Every public function and input class of :mod:`ballrace.analytic` is found by walking
the ``__all__`` of every submodule (so a new function or module is covered as soon as it
exists: the first test fails, naming it, until it has a row in ``TABLE``).  Each row gives one valid call and
the *role* of each argument; the role says which bad values the argument must refuse:

========  =============================================================  ==============
role      meaning                                                        refuses
========  =============================================================  ==============
scale     positive dimensional quantity (length, modulus, density)        -1, 0, NaN,
                                                                         ±inf, 1e308
pos       positive dimensionless number                                  -1, 0, NaN, ±inf
life      positive, inf allowed (an unloaded bearing's life)             -1, 0, NaN
load      non-negative dimensional quantity (load, approach, roughness)  -1, NaN, ±inf,
                                                                         1e308
nonneg    non-negative dimensionless number                              -1, NaN, ±inf
signed    any finite dimensional value (axial load, speed)               NaN, ±inf, 1e308
coord     any finite coordinate                                          NaN, ±inf, 1e308
radius    principal radius (signed, inf = flat)                          0, NaN, 1e308
angle     angle in a bounded range [rad]                                 NaN, ±inf, 10
finite    any finite number                                              NaN, ±inf
count     integer >= 1                                                   0, -1, 2.5
unit      number in an open bounded interval (Poisson's ratio ...)       NaN, ±inf, 10
choice    one of a set of strings                                        "nonsense"
object    a Material, HertzContact, BallBearing ...                      str, float
========  =============================================================  ==============

Every numeric role also refuses a string (``"1.0"``, which numpy would turn into 1.0),
a boolean and a ragged list (``TypeError``); arguments that broadcast are also given
shapes (2,) and (3,) together (``ValueError`` naming both).  The expected error is
``TypeError`` for a wrong type and ``ValueError`` for a bad value, and its message must
name the argument.
"""
from __future__ import annotations

import importlib
import inspect
import math
import pkgutil

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
import ballrace.analytic
from ballrace.analytic import hertz, loaddist
from ballrace.analytic import shaft as shaft_mod
from ballrace.analytic.bearing import BallBearing
from ballrace.analytic.materials import Material

STEEL = Material(E=200e9, nu=0.3)
BEARING = BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, diametral_clearance=0.0)
ANGULAR = BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.4)
CONTACT = hertz.point_contact(1000.0, 6.35e-3, 6.35e-3, 30e-3, -6.6e-3, STEEL)
LINE = hertz.line_contact(1e6, 0.01, np.inf, STEEL)
RADIAL = loaddist.radial(BEARING, 5000.0)

#: Modules of ballrace.analytic that are not formula/solver APIs: the old paths of the
#: command line and the case-file reader (now ballrace.commands and ballrace.casefiles;
#: their input errors are CLI usage errors and CaseFileError, tested in
#: tests/test_cli*.py and tests/test_bearing_cli.py).
NOT_API = {"cli", "casefile", "isocase", "shaft_cli", "plausible", "roller", "newton"}
# plausible holds the unit-slip warnings the entry points call (their messages are tested
# in tests/test_trust3_errors.py); the roller sub-package tests its bad input in
# tests/test_roller_*.py; newton is the solvers' shared step control (its functions take the
# solvers' own arrays, tested in tests/test_newton.py), not a formula a user calls.
# shaft_cli is the ``ballrace shaft CASE.toml`` command and its case-file reader: its
# errors are one-line case-file errors naming the key (tests/test_shaft_cli.py); the
# numbers it passes on are checked by shaft.Shaft, Seat, PointLoad and solve (rows below).
# isocase is not a formula API either: ``iso_life`` takes a validated case (BearingCase,
# checked by the case-file reader) and its load distribution, and ``rows`` formats the
# dict that ``iso_life`` returns for the report; the numbers they pass on are checked in
# iso281, iso16281 and clearance, which have rows below.
MODULES = tuple(sorted(m.name for m in pkgutil.iter_modules(ballrace.analytic.__path__)
                       if not m.name.startswith("_") and m.name not in NOT_API))

#: Exported classes that are results or errors (never built from user input).
NOT_INPUTS = {"Curvature", "HertzContact", "LineContact", "OrthogonalShear", "MaxShear",
              "VonMisesMax", "StressState", "FilmThickness", "BallKinematics",
              "DefectFrequencies", "StaticRatingPressure", "EquivalentLoad",
              "LundbergPalmgrenLife", "LoadDistribution", "ConvergenceError",
              "DuplexResult", "HighSpeedResult", "FatigueLoadLimit",
              "ReferenceRatingLife", "OperatingClearance", "SurfaceTension",
              "ShaftResult", "ShaftLife", "DutyCycleLife", "ReferenceLifeMethods",
              "Row", "SeatBearing", "RowMount", "missing"}   # the seat contract: interfaces

BAD = {
    "scale": [-1.0, 0.0, math.nan, math.inf, -math.inf, 1e308],
    "pos": [-1.0, 0.0, math.nan, math.inf, -math.inf],
    "life": [-1.0, 0.0, math.nan],
    "load": [-1.0, math.nan, math.inf, -math.inf, 1e308],
    "nonneg": [-1.0, math.nan, math.inf, -math.inf],
    "signed": [math.nan, math.inf, -math.inf, 1e308],
    "coord": [math.nan, math.inf, -math.inf, 1e308],
    "radius": [0.0, math.nan, 1e308],
    "angle": [math.nan, math.inf, -math.inf, 10.0],
    "finite": [math.nan, math.inf, -math.inf],
    "count": [0, -1, 2.5],
    "unit": [math.nan, math.inf, -math.inf, 10.0],
    "choice": ["nonsense"],
    "object": [],
}
WRONG_TYPES = {
    "numeric": ["1.0", True, [[1.0, 2.0], [3.0]]],
    "choice": [1.0, True],
    "object": ["x", 1.0],
}

# name -> (valid keyword arguments, {argument: role}, arguments that broadcast together)
TABLE: dict[str, tuple[dict, dict, tuple]] = {
    # materials
    "materials.Material": (dict(E=200e9, nu=0.3, density=7850.0),
                           dict(E="scale", nu="unit", density="scale"), ()),
    "materials.effective_modulus": (dict(material1=STEEL, material2=STEEL),
                                    dict(material1="object", material2="object"), ()),
    "materials.johnson_modulus": (dict(material1=STEEL, material2=STEEL),
                                  dict(material1="object", material2="object"), ()),
    # hertz
    "hertz.curvature": (dict(rx1=6.35e-3, ry1=6.35e-3, rx2=np.inf, ry2=-6.6e-3),
                        dict(rx1="radius", ry1="radius", rx2="radius", ry2="radius"),
                        ("rx1", "ry1", "rx2", "ry2")),
    "hertz.ellipticity": (dict(alpha_r=10.0, method="exact"),
                          dict(alpha_r="pos", method="choice"), ()),
    "hertz.point_contact": (dict(load=100.0, rx1=6.35e-3, ry1=6.35e-3, rx2=30e-3, ry2=-6.6e-3,
                                 material1=STEEL, material2=STEEL, method="exact"),
                            dict(load="load", rx1="radius", ry1="radius", rx2="radius",
                                 ry2="radius", material1="object", material2="object",
                                 method="choice"),
                            ("load", "rx1", "ry1", "rx2", "ry2")),
    "hertz.elliptical_contact": (dict(load=100.0, Rx=5e-3, Ry=0.1, E_prime=2.2e11),
                                 dict(load="load", Rx="scale", Ry="scale", E_prime="scale"),
                                 ("load", "Rx", "Ry", "E_prime")),
    "hertz.contact_stiffness": (dict(Rx=5e-3, Ry=0.1, E_prime=2.2e11, method="exact"),
                                dict(Rx="scale", Ry="scale", E_prime="scale", method="choice"),
                                ("Rx", "Ry", "E_prime")),
    "hertz.load_from_approach": (dict(approach=1e-6, Rx=5e-3, Ry=0.1, E_prime=2.2e11),
                                 dict(approach="load", Rx="scale", Ry="scale",
                                      E_prime="scale"),
                                 ("approach", "Rx", "Ry", "E_prime")),
    "hertz.line_contact": (dict(load_per_length=1e6, r1=0.01, r2=np.inf, material1=STEEL,
                                material2=STEEL),
                           dict(load_per_length="load", r1="radius", r2="radius",
                                material1="object", material2="object"),
                           ("load_per_length", "r1", "r2")),
    "hertz.approximation_errors": (dict(alpha_r=10.0, method="hamrock-brewe-1983"),
                                   dict(alpha_r="pos", method="choice"), ()),
    # subsurface
    "subsurface.lundberg_palmgren_t": (dict(k=2.0, method="exact"),
                                       dict(k="pos", method="choice"), ()),
    "subsurface.orthogonal_shear": (dict(c=CONTACT, method="exact"),
                                    dict(c="object", method="choice"), ()),
    "subsurface.axis_stress": (dict(c=CONTACT, z=1e-4, nu=0.3),
                               dict(c="object", z="load", nu="unit"), ("z", "nu")),
    "subsurface.max_shear": (dict(c=CONTACT, nu=0.3), dict(c="object", nu="unit"), ()),
    "subsurface.von_mises": (dict(c=CONTACT, nu=0.3), dict(c="object", nu="unit"), ()),
    "subsurface.stress": (dict(c=CONTACT, x=1e-4, y=0.0, z=1e-4, nu=0.3),
                          dict(c="object", x="coord", y="coord", z="load", nu="unit"),
                          ("x", "y", "z")),
    "subsurface.line_stress": (dict(lc=LINE, x=1e-5, z=1e-5, nu=0.3),
                               dict(lc="object", x="coord", z="load", nu="unit"), ("x", "z")),
    "subsurface.line_max_shear": (dict(lc=LINE, nu=0.3), dict(lc="object", nu="unit"), ()),
    "subsurface.line_orthogonal_shear": (dict(lc=LINE), dict(lc="object"), ()),
    # ehl
    "ehl.ellipticity_parameter": (dict(Rx=5e-3, Ry=0.1), dict(Rx="scale", Ry="scale"),
                                  ("Rx", "Ry")),
    "ehl.film_thickness": (dict(contact=CONTACT, entrainment_speed=5.0, viscosity=0.01,
                                pressure_viscosity=2e-8),
                           dict(contact="object", entrainment_speed="scale",
                                viscosity="scale", pressure_viscosity="scale"),
                           ("entrainment_speed", "viscosity", "pressure_viscosity")),
    "ehl.film_thickness_parts": (dict(load=1000.0, Rx=5e-3, Ry=0.1, E_prime=2.2e11,
                                      entrainment_speed=5.0, viscosity=0.01,
                                      pressure_viscosity=2e-8),
                                 dict(load="scale", Rx="scale", Ry="scale", E_prime="scale",
                                      entrainment_speed="scale", viscosity="scale",
                                      pressure_viscosity="scale"),
                                 ("load", "Rx", "Ry", "E_prime", "entrainment_speed")),
    "ehl.film_parameter": (dict(h_min=1e-6, roughness_race=0.1e-6, roughness_ball=0.05e-6),
                           dict(h_min="load", roughness_race="load", roughness_ball="load"),
                           ("h_min", "roughness_race", "roughness_ball")),
    "ehl.entrainment_speed": (dict(ball_diameter=12.7e-3, pitch_diameter=65e-3,
                                   contact_angle=0.0, speed_inner=100.0, speed_outer=0.0),
                              dict(ball_diameter="scale", pitch_diameter="scale",
                                   contact_angle="angle", speed_inner="signed",
                                   speed_outer="signed"),
                              ("ball_diameter", "pitch_diameter", "speed_inner")),
}

_KIN = dict(D=12.7e-3, d_m=65e-3)
_KIN_ROLES = dict(D="scale", d_m="scale")
for _f in ("pitch_ratio",):
    TABLE[f"kinematics.{_f}"] = ({**_KIN, "contact_angle": 0.3},
                                 {**_KIN_ROLES, "contact_angle": "angle"},
                                 ("D", "d_m", "contact_angle"))
for _f in ("cage_speed", "orbital_speed", "ball_speed"):
    TABLE[f"kinematics.{_f}"] = ({**_KIN, "contact_angle": 0.3, "speed_inner": 100.0,
                                  "speed_outer": 0.0},
                                 {**_KIN_ROLES, "contact_angle": "angle",
                                  "speed_inner": "signed", "speed_outer": "signed"},
                                 ("D", "d_m", "speed_inner"))
for _f in ("pitch_angle", "spin_to_roll"):
    TABLE[f"kinematics.{_f}"] = ({**_KIN, "contact_angle_inner": 0.3,
                                  "contact_angle_outer": 0.3, "control": "outer"},
                                 {**_KIN_ROLES, "contact_angle_inner": "angle",
                                  "contact_angle_outer": "angle", "control": "choice"},
                                 ("D", "d_m", "contact_angle_inner"))
TABLE["kinematics.ball_kinematics"] = (
    {**_KIN, "contact_angle_inner": 0.3, "contact_angle_outer": 0.3, "speed_inner": 100.0,
     "speed_outer": 0.0, "control": "outer"},
    {**_KIN_ROLES, "contact_angle_inner": "angle", "contact_angle_outer": "angle",
     "speed_inner": "signed", "speed_outer": "signed", "control": "choice"},
    ("D", "d_m", "speed_inner"))
TABLE["kinematics.defect_frequencies"] = (
    {**_KIN, "n_balls": 9, "contact_angle": 0.3, "speed_inner": 100.0, "speed_outer": 0.0},
    {**_KIN_ROLES, "n_balls": "count", "contact_angle": "angle", "speed_inner": "signed",
     "speed_outer": "signed"},
    ("D", "d_m", "speed_inner"))
TABLE["kinematics.bearing_kinematics"] = (
    dict(bearing=ANGULAR, speed_inner=100.0, speed_outer=0.0, contact_angle=0.4,
         contact_angle_outer=0.4, control="outer"),
    dict(bearing="object", speed_inner="signed", speed_outer="signed", contact_angle="angle",
         contact_angle_outer="angle", control="choice"),
    ("speed_inner", "speed_outer", "contact_angle"))
TABLE["kinematics.bearing_defect_frequencies"] = (
    dict(bearing=ANGULAR, speed_inner=100.0, speed_outer=0.0, contact_angle=0.4),
    dict(bearing="object", speed_inner="signed", speed_outer="signed", contact_angle="angle"),
    ("speed_inner", "speed_outer", "contact_angle"))

# ratings
_RAT = dict(bearing_or_D=12.7e-3, n_balls=9, pitch_diameter=65e-3, contact_angle=0.0, n_rows=1)
_RAT_ROLES = dict(bearing_or_D="scale", n_balls="count", pitch_diameter="scale",
                  contact_angle="angle", n_rows="count")
TABLE.update({
    "ratings.fc_factor": (dict(gamma=0.2), dict(gamma="nonneg"), ()),
    "ratings.fc_inch_pound": (dict(gamma=0.2), dict(gamma="nonneg"), ()),
    "ratings.f0_factor": (dict(gamma=0.2), dict(gamma="nonneg"), ()),
    "ratings.dynamic_rating": ({**_RAT, "standard": "ISO 281:2007"},
                               {**_RAT_ROLES, "standard": "choice"}, ()),
    "ratings.static_rating": (dict(_RAT), dict(_RAT_ROLES), ()),
    "ratings.bearing_numbers": (dict(_RAT), dict(_RAT_ROLES), ()),
    "ratings.static_rating_pressure": ({**_RAT, "f_inner": 0.52, "f_outer": 0.53,
                                        "material": STEEL},
                                       {**_RAT_ROLES, "f_inner": "pos", "f_outer": "pos",
                                        "material": "object"}, ()),
    "ratings.static_equivalent_load": (dict(radial_load=1000.0, axial_load=500.0,
                                            contact_angle=0.0, n_rows=1),
                                       dict(radial_load="load", axial_load="load",
                                            contact_angle="angle", n_rows="count"),
                                       ("radial_load", "axial_load")),
    "ratings.static_safety_factor": (dict(static_rating_N=20e3, static_equivalent_load_N=1e3),
                                     dict(static_rating_N="scale",
                                          static_equivalent_load_N="scale"),
                                     ("static_rating_N", "static_equivalent_load_N")),
    "ratings.static_safety_from_pressure": (dict(p_max=3e9, kind="ball"),
                                            dict(p_max="load", kind="choice"), ()),
    "ratings.bearing_type": (dict(bearing=BEARING), dict(bearing="object"), ()),
})

# life
_LP = dict(ball_loads=np.array([2000.0, 1500.0, 500.0, 0, 0, 0, 0, 500.0, 1500.0]),
           contact_angles=0.0,
           ball_diameter=12.7e-3, pitch_diameter=65e-3, f_inner=0.52, f_outer=0.52,
           rotating="inner")
TABLE.update({
    "life.l10": (dict(C=30e3, P=3e3), dict(C="scale", P="scale"), ("C", "P")),
    "life.l10_hours": (dict(C=30e3, P=3e3, speed_rpm=1500.0),
                       dict(C="scale", P="scale", speed_rpm="scale"), ("C", "P", "speed_rpm")),
    "life.catalog_l10_hours": (dict(C=30e3, P=3e3, speed_rpm=1500.0),
                               dict(C="scale", P="scale", speed_rpm="scale"),
                               ("C", "P", "speed_rpm")),
    "life.miner": (dict(lives=[1e3, 2e3], fractions=[0.5, 0.5]),
                   dict(lives="pos", fractions="nonneg"), ("lives", "fractions")),
    "life.load_factor": (dict(load_stationary_relative_to="outer ring"),
                         dict(load_stationary_relative_to="choice"), ()),
    "life.xy_factors": (dict(relative_axial_load=0.1, contact_angle=0.0, n_rows=1,
                             standard="ISO 281:2007"),
                        dict(relative_axial_load="nonneg", contact_angle="angle",
                             n_rows="count", standard="choice"), ()),
    "life.equivalent_load": (dict(radial_load=1000.0, axial_load=500.0, static_rating=20e3, f0=14.0,
                                  contact_angle=0.0, n_rows=1, standard="ISO 281:2007"),
                             dict(radial_load="load", axial_load="load",
                                  static_rating="scale", f0="pos", contact_angle="angle",
                                  n_rows="count", standard="choice"),
                             ("radial_load", "axial_load")),
    "life.equivalent_load_for": (dict(bearing=BEARING, radial_load=1000.0, axial_load=500.0),
                                 dict(bearing="object", radial_load="load",
                                      axial_load="load"),
                                 ("radial_load", "axial_load")),
    "life.contact_capacity": (dict(ball_diameter=12.7e-3, n_balls=9, pitch_diameter=65e-3,
                                   contact_angle=0.0, conformity=0.52, race="inner"),
                              dict(ball_diameter="scale", n_balls="count",
                                   pitch_diameter="scale", contact_angle="angle",
                                   conformity="pos", race="choice"), ()),
    "life.lundberg_palmgren_life": (dict(_LP),
                                    dict(ball_loads="load", contact_angles="angle",
                                         ball_diameter="scale", pitch_diameter="scale",
                                         f_inner="pos", f_outer="pos", rotating="choice"),
                                    ()),
    "life.bearing_life": (dict(bearing=BEARING, result=RADIAL, rotating="inner"),
                          dict(bearing="object", result="object", rotating="choice"), ()),
    "life.material_factor": (dict(material="52100"), dict(material="choice"), ()),
    "life.processing_factor": (dict(process="air-melt"), dict(process="choice"), ()),
    "life.lubrication_factor": (dict(film_parameter=1.5), dict(film_parameter="nonneg"), ()),
    "life.hardness_factor": (dict(hardness_hrc=60.0), dict(hardness_hrc="pos"), ()),
    "life.adjusted_life": (dict(basic_life=100.0), dict(basic_life="nonneg"), ()),
})

# loaddist, bearing, duplex, highspeed
TABLE.update({
    "loaddist.solve": (dict(bearing=BEARING, Fa=0.0, Fy=0.0, Fz=5000.0, My=0.0, Mz=0.0,
                            max_iter=200),
                       dict(bearing="object", Fa="signed", Fy="signed", Fz="signed",
                            My="signed", Mz="signed", max_iter="count"), ()),
    "loaddist.radial": (dict(bearing=BEARING, Fr=5000.0), dict(bearing="object", Fr="signed"),
                        ()),
    "loaddist.thrust": (dict(bearing=ANGULAR, Fa=5000.0), dict(bearing="object", Fa="load"),
                        ()),
    "loaddist.combined": (dict(bearing=ANGULAR, Fr=5000.0, Fa=5000.0),
                          dict(bearing="object", Fr="signed", Fa="signed"), ()),
    "loaddist.eccentric_thrust": (dict(bearing=ANGULAR, Fa=5000.0, e=0.005),
                                  dict(bearing="object", Fa="load", e="load"), ("Fa", "e")),
    "loaddist.ball_stiffness": (dict(bearing=BEARING, contact_angle=0.0),
                                dict(bearing="object", contact_angle="angle"), ()),
    "loaddist.jones_radial_factor": (dict(clearance_ratio=0.1),
                                     dict(clearance_ratio="nonneg"), ()),
    "loaddist.stribeck_max_ball_load": (dict(Fr=5000.0, n_balls=9, factor=5.0),
                                        dict(Fr="load", n_balls="count", factor="pos"), ()),
    "loaddist.jones_max_ball_load": (dict(Fr=5000.0, n_balls=9, Kn=1e10, clearance=0.0),
                                     dict(Fr="load", n_balls="count", Kn="scale",
                                          clearance="signed"), ()),   # < 0: interference
    "bearing.BallBearing": (dict(ball_diameter=12.7e-3, n_balls=9, pitch_diameter=65e-3,
                                 f_inner=0.52, f_outer=0.52, diametral_clearance=0.0,
                                 material=STEEL),
                            dict(ball_diameter="scale", n_balls="count", pitch_diameter="scale",
                                 f_inner="pos", f_outer="pos", diametral_clearance="signed",
                                 material="object"), ()),
    "duplex.DuplexPair": (dict(bearing=ANGULAR, arrangement="DB", preload=100.0),
                          dict(bearing="object", arrangement="choice", preload="load"), ()),
    "duplex.axial_load": (dict(bearing=ANGULAR, axial_deflection=1e-5, radial_deflection=0.0),
                          dict(bearing="object", axial_deflection="signed",
                               radial_deflection="signed"), ()),
    "duplex.axial_deflection": (dict(bearing=ANGULAR, Fa=1000.0),
                                dict(bearing="object", Fa="load"), ()),
    "duplex.power_law_unloading_ratio": (dict(exponent=1.5), dict(exponent="pos"), ()),
    "highspeed.ball_mass": (dict(D=12.7e-3, density=7850.0), dict(D="scale", density="scale"),
                            ("D", "density")),
    "highspeed.ball_inertia": (dict(D=12.7e-3, density=7850.0),
                               dict(D="scale", density="scale"), ("D", "density")),
    "highspeed.centrifugal_force": (dict(D=12.7e-3, density=7850.0, d_m=65e-3,
                                         orbital_speed=100.0),
                                    dict(D="scale", density="scale", d_m="scale",
                                         orbital_speed="signed"),
                                    ("D", "density", "d_m", "orbital_speed")),
    "highspeed.gyroscopic_moment": (dict(D=12.7e-3, density=7850.0, ball_speed=500.0,
                                         orbital_speed=100.0, pitch_angle=0.3),
                                    dict(D="scale", density="scale", ball_speed="signed",
                                         orbital_speed="signed", pitch_angle="angle"),
                                    ("D", "density", "ball_speed", "orbital_speed")),
    "highspeed.solve": (dict(bearing=ANGULAR, Fa=2000.0, Fr=0.0, speed_inner=500.0,
                             speed_outer=0.0, control="outer"),
                        dict(bearing="object", Fa="signed", Fr="signed", speed_inner="signed",
                             speed_outer="signed", control="choice"), ()),
})

# ISO 281:2007 life modification, ISO/TS 16281 reference rating life, operating clearance
_ISO = dict(kappa=1.5, contamination=0.5, fatigue_limit=1e3)
_ISO_ROLES = dict(kappa="pos", contamination="unit", fatigue_limit="scale")
TABLE.update({
    "iso281.reliability_factor": (dict(reliability=0.99, method="table"),
                                  dict(reliability="unit", method="choice"), ()),
    "iso281.reference_viscosity": (dict(speed_rpm=1500.0, pitch_diameter=65e-3),
                                   dict(speed_rpm="scale", pitch_diameter="scale"),
                                   ("speed_rpm", "pitch_diameter")),
    "iso281.viscosity_ratio": (dict(viscosity=20e-6, speed_rpm=1500.0, pitch_diameter=65e-3),
                               dict(viscosity="scale", speed_rpm="scale",
                                    pitch_diameter="scale"),
                               ("viscosity", "speed_rpm", "pitch_diameter")),
    "iso281.walther_constants": (dict(nu40=68e-6, nu100=8.7e-6),
                                 dict(nu40="scale", nu100="scale"), ("nu40", "nu100")),
    "iso281.operating_viscosity": (dict(nu40=68e-6, nu100=8.7e-6, temperature=343.15),
                                   dict(nu40="scale", nu100="scale", temperature="scale"),
                                   ("nu40", "nu100", "temperature")),
    "iso281.fatigue_load_limit": (dict(static_rating=20e3, pitch_diameter=65e-3),
                                  dict(static_rating="scale", pitch_diameter="scale"),
                                  ("static_rating", "pitch_diameter")),
    "iso281.fatigue_load_limit_hertz": (dict(bearing=BEARING, contact_angle=0.0,
                                             stress_limit=1.5e9),
                                        dict(bearing="object", contact_angle="angle",
                                             stress_limit="scale"), ()),
    "iso281.contamination_factor": (dict(level="normal cleanliness", pitch_diameter=65e-3,
                                         which="mean"),
                                    dict(level="choice", pitch_diameter="scale",
                                         which="choice"), ()),
    "iso281.life_modification_factor": ({**_ISO, "load": 3e3, "bearing_type": "radial ball",
                                         "cap": 50.0},
                                        {**_ISO_ROLES, "load": "scale",
                                         "bearing_type": "choice", "cap": "pos"},
                                        ("kappa", "contamination", "fatigue_limit", "load")),
    "iso281.a_iso_equation": ({**_ISO, "load": 3e3, "x1": 2.5671, "x2": (2.2649, 1.9987),
                               "exponents": (0.83, 1.0 / 3.0, 9.3), "cap": 50.0},
                              {**_ISO_ROLES, "load": "scale", "cap": "pos"},
                              ("kappa", "contamination", "fatigue_limit", "load")),
    "iso281.modified_rating_life": ({**_ISO, "C": 30e3, "P": 3e3, "reliability": 0.9},
                                    {**_ISO_ROLES, "C": "scale", "P": "scale",
                                     "reliability": "unit"},
                                    ("C", "P", "kappa", "contamination", "fatigue_limit",
                                     "reliability")),
    "iso281.modified_rating_life_hours": ({**_ISO, "C": 30e3, "P": 3e3, "speed_rpm": 1500.0,
                                          "reliability": 0.9},
                                         {**_ISO_ROLES, "C": "scale", "P": "scale",
                                          "speed_rpm": "scale", "reliability": "unit"},
                                         ("C", "P", "speed_rpm", "kappa")),
    "iso16281.raceway_capacities": (dict(C=30e3, n_balls=9, ball_diameter=12.7e-3,
                                         pitch_diameter=65e-3, f_inner=0.52, f_outer=0.52,
                                         contact_angle=0.0, n_rows=1),
                                    dict(C="scale", n_balls="count", ball_diameter="scale",
                                         pitch_diameter="scale", f_inner="pos",
                                         f_outer="pos", contact_angle="angle",
                                         n_rows="count"), ()),
    "iso16281.reference_rating_life": (dict(bearing=BEARING, result=RADIAL,
                                            dynamic_rating=30e3, rotating="inner",
                                            nominal_contact_angle=0.0),
                                       dict(bearing="object", result="object",
                                            dynamic_rating="scale", rotating="choice",
                                            nominal_contact_angle="angle"), ()),
    # inner ring on a solid shaft: mating_diameter is the shaft bore (>= 0); a negative
    # interference is a loose fit (zero pressure), so interference is "signed"
    "clearance.fit_pressure": (dict(interference=15e-6, seat_diameter=0.025,
                                    ring_diameter=0.03, mating_diameter=0.0, E_ring=208e9,
                                    nu_ring=0.3, E_mate=208e9, nu_mate=0.3, ring="inner"),
                               dict(interference="signed", seat_diameter="scale",
                                    ring_diameter="scale", mating_diameter="load",
                                    E_ring="scale", nu_ring="unit", E_mate="scale",
                                    nu_mate="unit", ring="choice"), ()),
    "clearance.operating_clearance": (
        dict(bearing=BEARING, bore=0.04, outside_diameter=0.09, initial_clearance=20e-6,
             shaft_interference=15e-6, housing_interference=0.0, shaft_bore=0.0,
             housing_diameter=0.12,
             inner_temperature=313.15, outer_temperature=303.15, ball_temperature=308.15,
             reference_temperature=293.15, ring_expansion=11.5e-6, ball_expansion=11.5e-6,
             shaft_expansion=11.5e-6, housing_expansion=11.5e-6, shaft_material=STEEL,
             housing_material=STEEL),
        dict(bearing="object", bore="scale", outside_diameter="scale",
             initial_clearance="signed", shaft_interference="signed",
             housing_interference="signed", shaft_bore="load",
             housing_diameter="radius",      # refuses 0, NaN, 1e308 (inf: a large housing)
             inner_temperature="scale",
             outer_temperature="scale", ball_temperature="scale",
             reference_temperature="scale", ring_expansion="finite", ball_expansion="finite",
             shaft_expansion="finite", housing_expansion="finite", shaft_material="object",
             housing_material="object"), ()),
})

# subsurface: surface tension and the traction at which the maximum reaches the surface
TABLE.update({
    "subsurface.surface_tension": (dict(c=CONTACT, nu=0.3, traction=0.2),
                                   dict(c="object", nu="unit", traction="finite"),
                                   ("nu", "traction")),   # traction in [-10, 10]
    "subsurface.critical_traction": (dict(ratio=0.5, nu=0.3, criterion="tresca"),
                                     dict(ratio="unit", nu="unit", criterion="choice"),
                                     ("ratio", "nu")),    # ratio b/a in [0, 1]
    # ring displacements (..., 5): a scalar is refused for its shape or its value
    "loaddist.ring_forces": (dict(bearing=ANGULAR, displacements=[1e-5, 1e-5, 0.0, 0.0, 0.0],
                                  moment_arm="groove", clearance=10e-6, azimuth_offset=0.1),
                             dict(bearing="object", displacements="coord",
                                  moment_arm="choice", clearance="signed",
                                  azimuth_offset="finite"), ()),
    "loaddist.RingModel": (dict(bearing=ANGULAR, clearance=10e-6),
                           dict(bearing="object", clearance="signed"), ()),
})

# shaft: a short shaft on two deep-groove bearings (a solve takes milliseconds)
_SHAFT = shaft_mod.Shaft([(0.2, 0.04, 0.0)], STEEL, n_elements=8, thermal_expansion=11.5e-6)
_SEATS = (shaft_mod.Seat(0.02, BEARING), shaft_mod.Seat(0.18, BEARING, floating=True))
_LOADS = (shaft_mod.PointLoad(0.1, Fy=2000.0, Fa=100.0),)
SHAFT_RESULT = shaft_mod.solve(_SHAFT, _SEATS, _LOADS)
TABLE.update({
    "shaft.shear_coefficient": (dict(nu=0.3, inner_ratio=0.5),
                                dict(nu="unit", inner_ratio="unit"),   # m = d_i/d_o in [0, 1)
                                ("nu", "inner_ratio")),
    # sections is a sequence of (length, outer, inner diameter): a text or a number is a
    # TypeError; the numbers in it are checked one by one (tests/test_shaft.py)
    "shaft.Shaft": (dict(sections=[(0.2, 0.04, 0.0)], material=STEEL, n_elements=8,
                         thermal_expansion=11.5e-6),
                    dict(sections="object", material="object", n_elements="count",
                         thermal_expansion="load"), ()),
    # direction (+1 or -1), housing_stiffness (5-vector or 5x5) and floating have no
    # scalar role: tests/test_shaft.py
    "shaft.Seat": (dict(position=0.02, bearing=BEARING, offset=1e-6, spring_preload=10.0,
                        floating=True, clearance=5e-6, row_spacing=0.01),
                   dict(position="coord", bearing="object", offset="signed",
                        spring_preload="load", clearance="signed", row_spacing="load"), ()),
    "shaft.PointLoad": (dict(position=0.1, Fa=100.0, Fy=2000.0, Fz=-500.0, My=1.0, Mz=-2.0),
                        dict(position="coord", Fa="signed", Fy="signed", Fz="signed",
                             My="signed", Mz="signed"), ()),
    "shaft.gear_mesh": (dict(position=0.1, tangential_force=1000.0, pitch_diameter=0.2,
                             pressure_angle=0.35, helix_angle=0.26, mesh_azimuth=0.5),
                        dict(position="coord", tangential_force="signed",
                             pitch_diameter="scale", pressure_angle="angle",
                             helix_angle="angle", mesh_azimuth="finite"), ()),
    "shaft.belt_pull": (dict(position=0.1, force=800.0, azimuth=1.0),
                        dict(position="coord", force="load", azimuth="finite"), ()),
    # gravity is a 3-vector (no scalar role); initial is None or a ShaftResult
    "shaft.solve": (dict(shaft=_SHAFT, seats=_SEATS, loads=_LOADS,
                         shaft_temperature_change=10.0, housing_temperature_change=5.0,
                         housing_expansion=11.5e-6, thermal_reference=0.02, rtol=1e-10,
                         max_iter=100, initial=SHAFT_RESULT),
                    dict(shaft="object", seats="object", loads="object",
                         shaft_temperature_change="signed",
                         housing_temperature_change="signed", housing_expansion="load",
                         thermal_reference="coord", rtol="pos", max_iter="count",
                         initial="object"), ()),
    # modified is a dict of ISO 281 factors (checked by iso281, rows above)
    "shaft.rating_lives": (dict(result=SHAFT_RESULT, rotating="inner", dynamic_rating=30e3,
                                nominal_contact_angle=0.0, weibull_slope=10 / 9),
                           dict(result="object", rotating="choice", dynamic_rating="scale",
                                nominal_contact_angle="angle", weibull_slope="pos"), ()),
    "shaft.system_life": (dict(lives=[1e3, 2e3, np.inf], weibull_slope=10 / 9),
                          dict(lives="life", weibull_slope="pos"), ()),
    "shaft.duty_cycle": (dict(shaft=_SHAFT, seats=_SEATS,
                              cases=[(_LOADS, 0.5, 1500.0),
                                     ((shaft_mod.PointLoad(0.1, Fy=500.0),), 0.5, 3000.0)],
                              rotating="inner", dynamic_rating=30e3,
                              nominal_contact_angle=0.0, weibull_slope=10 / 9),
                         dict(shaft="object", seats="object", cases="object",
                              rotating="choice", dynamic_rating="scale",
                              nominal_contact_angle="angle", weibull_slope="pos"), ()),
    "shaft.bearing_coefficients": (dict(result=SHAFT_RESULT, tilt="free"),
                                   dict(result="object", tilt="choice"), ()),
    # nodes: one ROSS node index per seat (a sequence, no scalar role)
    "shaft.ross_bearings": (dict(result=SHAFT_RESULT, nodes=[1, 7], tilt="held",
                                 damping=100.0),
                            dict(result="object", tilt="choice", damping="load"), ()),
})
#: Rows whose valid call needs an optional package (skipped without it; the bad values
#: are refused before the package is imported).
NEEDS = {"shaft.ross_bearings": "ross"}

# methods of input classes (called on the instance in METHOD_OF)
TABLE.update({
    "bearing.BallBearing.contacts": (dict(ball_loads=np.full(9, 500.0), contact_angles=0.4,
                                          race="inner"),
                                     dict(ball_loads="load", contact_angles="finite",
                                          race="choice"),
                                     ("ball_loads", "contact_angles")),
    "bearing.BallBearing.eccentric_thrust": (dict(Fa=5000.0, e=0.005),
                                             dict(Fa="load", e="load"), ("Fa", "e")),
})
METHOD_OF = {"bearing.BallBearing": ANGULAR}

#: Known gaps in the solver modules, one test id each; they
#: are strict xfails, so a fix makes the test XPASS and fail: then delete its line.
KNOWN: set[str] = set()   # none left; add an id here only for a tracked gap


def _public():
    out = []
    for mod in MODULES:
        m = importlib.import_module(f"ballrace.analytic.{mod}")
        for name in m.__all__:
            obj = getattr(m, name)
            if not callable(obj) or name in NOT_INPUTS:
                continue
            if getattr(obj, "__module__", "") != m.__name__:
                continue               # re-exported from elsewhere
            out.append(f"{mod}.{name}")
    return out


def _func(key):
    mod, name, *method = key.split(".")
    if method:
        return getattr(METHOD_OF[f"{mod}.{name}"], method[0])
    return getattr(importlib.import_module(f"ballrace.analytic.{mod}"), name)


def test_every_public_function_is_in_the_table():
    missing = sorted(set(_public()) - set(TABLE))
    assert not missing, f"add rows to TABLE for: {missing}"
    functions = {k for k in TABLE if k.count(".") == 1}
    assert not sorted(functions - set(_public()))


@pytest.mark.parametrize("key", sorted(TABLE))
def test_valid_row_runs(key):
    """The table's valid call works, so every failure below is due to the one bad argument."""
    if key in NEEDS:
        pytest.importorskip(NEEDS[key])
    kwargs, _, _ = TABLE[key]
    _func(key)(**kwargs)


def _param(*values, id):
    marks = [pytest.mark.xfail(strict=True, reason="known gap")] if id in KNOWN else []
    return pytest.param(*values, id=id, marks=marks)


def _cases():
    for key, (kwargs, roles, together) in sorted(TABLE.items()):
        for arg, role in roles.items():
            numeric = role not in ("choice", "object")
            for v in BAD[role]:
                yield _param(key, arg, v, ValueError, id=f"{key}-{arg}-{v!r}")
            for v in WRONG_TYPES["numeric" if numeric else role]:
                yield _param(key, arg, v, TypeError,
                             id=f"{key}-{arg}-{type(v).__name__}-{v!r}"[:80])


@pytest.mark.parametrize("key, arg, value, error", list(_cases()))
def test_bad_value_names_the_argument(key, arg, value, error):
    kwargs, _, _ = TABLE[key]
    with pytest.raises(error) as info:
        _func(key)(**{**kwargs, arg: value})
    assert arg in str(info.value), f"{error.__name__} does not name {arg!r}: {info.value}"


def _shape_cases():
    for key, (kwargs, _, together) in sorted(TABLE.items()):
        for a, b in zip(together, together[1:]):
            yield _param(key, a, b, id=f"{key}-{a}-{b}")


@pytest.mark.parametrize("key, a, b", list(_shape_cases()))
def test_shapes_that_do_not_broadcast_name_both_arguments(key, a, b):
    kwargs, _, _ = TABLE[key]
    args = {**kwargs, a: np.full(2, np.ravel(kwargs[a])[0]), b: np.full(3, np.ravel(kwargs[b])[0])}
    with pytest.raises(ValueError) as info:
        _func(key)(**args)
    msg = str(info.value)
    assert a in msg and b in msg and "broadcast" in msg, msg


# ------------------------------------------------------------------ regressions
def test_material_refuses_text_booleans_and_arrays():
    """Issue 14 item 7: these were accepted (numpy turns "1.0" and True into 1.0)."""
    for bad in ("1.0", True, np.array([200e9, 210e9]), [200e9]):
        with pytest.raises(TypeError, match=r"^E must be"):
            Material(E=bad, nu=0.3)
    with pytest.raises(TypeError, match=r"^density must be"):
        Material(E=200e9, nu=0.3, density=np.array([7850.0, 3200.0]))
    with pytest.raises(TypeError, match=r"^nu must be"):
        Material(E=200e9, nu=False)
    assert Material(E=np.float64(200e9), nu=0.3).E == 200e9   # numpy scalars are numbers


def test_radii_refuse_text_and_booleans():
    with pytest.raises(TypeError, match="rx1"):
        hertz.curvature("0.006", 0.006, np.inf, -0.0066)
    with pytest.raises(TypeError, match="ry2"):
        hertz.curvature(0.006, 0.006, np.inf, True)
    with pytest.raises(TypeError, match="alpha_r"):
        hertz.ellipticity(True)


def test_life_refuses_ball_at_or_above_pitch_diameter():
    """Issue 14 item 6: contact_capacity and lundberg_palmgren_life returned NaN."""
    from ballrace.analytic import life
    for D in (0.065, 0.07):
        with pytest.raises(ValueError, match="ball_diameter must be < pitch_diameter"):
            life.contact_capacity(D, 9, 0.065, 0.0, 0.52, "inner")
        with pytest.raises(ValueError, match="ball_diameter must be < pitch_diameter"):
            life.lundberg_palmgren_life(np.full(9, 100.0), 0.0, ball_diameter=D,
                                        pitch_diameter=0.065, f_inner=0.52, f_outer=0.52)


@pytest.mark.parametrize("speed, error", [(math.nan, ValueError), (math.inf, ValueError),
                                          (-math.inf, ValueError), (None, TypeError)])
def test_entrainment_speed_refuses_nan_inf_none(speed, error):
    """Issue 14 item 6: entrainment_speed returned NaN for these speeds."""
    from ballrace.analytic import ehl
    with pytest.raises(error, match="speed_inner"):
        ehl.entrainment_speed(0.0127, 0.065, speed_inner=speed)
    with pytest.raises(error, match="speed_outer"):
        ehl.entrainment_speed(0.0127, 0.065, speed_inner=100.0, speed_outer=speed)


def test_shapes_2_and_3_are_named():
    """Issue 14 item 8: numpy's 'shape mismatch ... arg 0 ... arg 1' named no argument."""
    from ballrace.analytic import subsurface
    with pytest.raises(ValueError, match=r"Fa \(shape \(2,\)\) and e \(shape \(3,\)\)"):
        ANGULAR.eccentric_thrust(np.array([17800.0, 100.0]), np.array([0.0, 0.01, 0.02]))
    with pytest.raises(ValueError, match=r"ball_loads \(shape \(2,\)\) and contact_angles"):
        ANGULAR.contacts(np.ones(2), np.full(3, 0.3), "inner")
    with pytest.raises(ValueError, match=r"x \(shape \(2,\)\) and y \(shape \(3,\)\)"):
        subsurface.stress(CONTACT, np.zeros(2), np.zeros(3), 1e-4)


def test_shaft_arguments_without_a_scalar_role():
    """What the table's scalar roles cannot reach: direction, gravity, duty-cycle cases."""
    with pytest.raises(ValueError, match="direction must be"):
        shaft_mod.Seat(0.02, BEARING, direction=True)
    with pytest.raises(ValueError, match="gravity must have a physical magnitude"):
        shaft_mod.solve(_SHAFT, _SEATS, _LOADS, gravity=(0.0, -1e308, 0.0))
    with pytest.raises(ValueError, match=r"cases\[0\] fraction must be finite"):
        shaft_mod.duty_cycle(_SHAFT, _SEATS, [(_LOADS, math.nan, 1500.0)])
    for t in (-0.5, 1.5):
        with pytest.raises(ValueError, match=r"cases\[0\] fraction must be in \[0, 1\]"):
            shaft_mod.duty_cycle(_SHAFT, _SEATS, [(_LOADS, t, 1500.0)])
    with pytest.raises(TypeError, match=r"cases\[0\] must be \(loads, fraction"):
        shaft_mod.duty_cycle(_SHAFT, _SEATS, [1.0])
    with pytest.raises(ValueError, match=r"dynamic_rating must be a number or one per seat"):
        shaft_mod.rating_lives(SHAFT_RESULT, dynamic_rating=[30e3, 30e3, 30e3])
    with pytest.raises(TypeError, match=r"dynamic_rating\[1\] must be a real number"):
        shaft_mod.rating_lives(SHAFT_RESULT, dynamic_rating=[None, "30 kN"])
    # None in a per-seat list: that seat's default rating (as the case-file reader passes)
    mixed = shaft_mod.rating_lives(SHAFT_RESULT, dynamic_rating=[None, 30e3])
    default = shaft_mod.rating_lives(SHAFT_RESULT)
    assert mixed.ratings[0][0].C == default.ratings[0][0].C
    assert mixed.ratings[1][0].C == 30e3
    with pytest.raises(ValueError, match=r"nodes must give one ROSS node per seat"):
        shaft_mod.ross_bearings(SHAFT_RESULT, [1])


@pytest.mark.parametrize("call", [
    lambda v: hertz.point_contact(v, 6.35e-3, 6.35e-3, 30e-3, -6.6e-3, STEEL),
    lambda v: hertz.point_contact(100.0, v, 6.35e-3, np.inf, -6.6e-3, STEEL),
    lambda v: hertz.point_contact(100.0, 6.35e-3, 6.35e-3, 30e-3, -6.6e-3, Material(E=v, nu=0.3)),
    lambda v: hertz.line_contact(v, 0.01, np.inf, STEEL),
    lambda v: hertz.line_contact(1e6, v, np.inf, STEEL),
    lambda v: hertz.contact_stiffness(v, 0.1, 2.2e11),
    lambda v: hertz.contact_stiffness(5e-3, 0.1, v),
    lambda v: ballrace.analytic.kinematics.cage_speed(0.0127, 0.065, 0.0, v),
    lambda v: ballrace.analytic.highspeed.centrifugal_force(0.0127, 7850.0, 0.065, v),
], ids=["load", "radius", "modulus", "line load", "line radius", "Rx", "E_prime", "speed",
        "orbital speed"])
def test_magnitudes_near_the_float_range_are_refused(call):
    """Issue 14 item 9: 1e308 gave inf/NaN; 1e30 (the documented limit) still computes."""
    with pytest.raises(ValueError, match="physical magnitude"):
        call(1e308)
    try:
        out = call(1e30)
    except ValueError as exc:     # e.g. a radius ratio beyond 1e8: a different, stated limit
        assert "physical magnitude" not in str(exc)
        return
    values = [getattr(out, f) for f in ("a", "b", "p_max", "approach", "stiffness")
              if hasattr(out, f)] or [out]
    assert all(np.all(np.isfinite(np.asarray(v, float))) for v in values)


_mag = st.floats(-30.0, 30.0).map(lambda e: 10.0 ** e)


@settings(max_examples=300, deadline=None)
@given(Q=st.one_of(st.just(0.0), _mag), Rx=_mag, ratio=st.floats(-8.0, 8.0), Ep=_mag)
def test_inside_the_magnitude_limits_contacts_are_finite(Q, Rx, ratio, Ep):
    """Any load, radii and modulus inside [1e-30, 1e30] (radius ratio within 1e8) give
    finite a, b, approach, p_max and stiffness: the limits leave room for the products."""
    Ry = Rx * 10.0 ** ratio
    if not 1e-30 <= Ry <= 1e30:
        return
    c = hertz.elliptical_contact(Q, Rx, Ry, Ep)
    for f in ("a", "b", "approach", "p_max", "stiffness", "k"):
        v = float(getattr(c, f))
        assert math.isfinite(v), f
        assert v > 0 or (Q == 0 and f in ("a", "b", "approach", "p_max")), f


# ------------------------------------------------ likely unit slips: percent, GPa, mm
def test_conformity_typed_as_percent_is_refused_and_an_open_groove_warned():
    import ballrace

    with pytest.raises(ValueError, match=r"f_inner must be a groove conformity r/D in "
                                         r"\(0.5, 1\).*got 52 \(a percentage\? 52 % is 0.52\)"):
        ballrace.BallBearing(0.0127, 9, 0.065, 52, 0.52, diametral_clearance=0.0)
    with pytest.raises(ValueError, match="f_outer must be a groove conformity"):
        ballrace.BallBearing(0.0127, 9, 0.065, 0.52, 1.0, diametral_clearance=0.0)
    with pytest.warns(UserWarning, match=r"f_inner = 0.7: groove conformity r/D is usually"):
        ballrace.BallBearing(0.0127, 9, 0.065, 0.7, 0.52, diametral_clearance=0.0)


def test_conformity_percent_in_a_case_file_is_one_line(tmp_path):
    from pathlib import Path

    from typer.testing import CliRunner

    from ballrace.cli import app

    base = (Path(__file__).resolve().parents[1] / "examples" / "bearing_209.toml").read_text()
    assert "f_inner = 0.52" in base
    p = tmp_path / "c.toml"
    p.write_text(base.replace("f_inner = 0.52", "f_inner = 52"))
    res = CliRunner().invoke(app, ["bearing", str(p)])
    assert res.exit_code == 2 and "52 % is 0.52" in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("E, slip", [(200.0, "were GPa given"), (200e3, "were MPa given"),
                                     (2e14, "above any material")])
def test_modulus_unit_slip_warns(E, slip):
    import ballrace

    with pytest.warns(UserWarning, match=slip):
        ballrace.Material(E=E, nu=0.3)


def test_steel_and_ceramics_do_not_warn():
    import warnings

    import ballrace

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ballrace.Material(E=208e9, nu=0.3)
        ballrace.Material(E=310e9, nu=0.26)
        ballrace.Material(E=3.6e9, nu=0.38)                    # PEEK cage or ball


def test_fem_ball_diameter_in_mm_warns():
    pytest.importorskip("skfem")
    from ballrace.fem import api

    with pytest.warns(UserWarning, match=r"ball_diameter = 12.7 m .* were millimetres given"):
        api.plane_case(12.7, 2000.0)
