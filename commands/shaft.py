r"""``ballrace shaft CASE.toml``: an elastic shaft on its ball bearings, from a case file.

Registered on the main Typer app by :func:`register` (see :mod:`ballrace.cli`).  Units
are parsed here only (:func:`ballrace.units.parse_quantity`); :func:`analyze` returns plain
SI numbers (what ``--json`` prints).

Case file (TOML, strict: unknown keys, wrong kinds of value, seats or loads outside the
shaft and seats on top of each other are one-line errors naming the key)::

    title = "Gearbox intermediate shaft"
    kind = "shaft"                      # required: marks a shaft case file

    [shaft]
    sections = [["40 mm", "35 mm", "0 mm"],    # (length, outer, inner diameter) from x = 0
                ["180 mm", "45 mm", "0 mm"],
                ["40 mm", "35 mm", "0 mm"]]
    material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }   # optional
    elements = 40                       # fewest beam elements (optional)
    thermal_expansion = "11.5e-6 1/K"   # optional
    weight = false                      # own weight along -y (optional)

    [bearings.b6208]                    # named bearings, referred to by the seats
    type = "deep-groove"                # or "angular-contact"
    ball_diameter = "12.7 mm"
    n_balls = 9
    pitch_diameter = "60 mm"
    f_inner = 0.52
    f_outer = 0.525
    diametral_clearance = "15 um"       # or free_contact_angle = "40 deg"
    # nominal_contact_angle = "0 deg"   # rating angle; default 0 (deep-groove) or the
                                        # free contact angle (angular-contact)
    # pair = "DB"; preload = "1.5 kN"   # a duplex pair (DB, DF, DT) of this bearing
    # dynamic_rating = "29.1 kN"        # C for the life (default: ISO 281 from geometry)

    [[seat]]
    name = "A"
    position = "20 mm"
    bearing = "b6208"
    direction = 1                       # thrust direction (+1 / -1), see docs/shaft.md
    floating = false                    # outer ring axially free (non-locating)
    # offset = "5 um"; spring_preload = "200 N"; clearance = "5 um"; row_spacing = "0 mm"
    # housing_stiffness = { axial = "1e9 N/m", radial = "5e8 N/m", tilt = "1e6 N*m/rad" }
    #   (a key left out is rigid: 1000 times the stiffest one given)

    [seat.fits]                         # optional, for the [[seat]] above: its operating
    bore = "40 mm"                      # clearance from the fits and ring temperatures
    outside_diameter = "80 mm"          # (ballrace.analytic.clearance)
    shaft_interference = "12 um"
    inner_temperature = "60 degC"
    outer_temperature = "45 degC"

    [[load]]                            # point load in the shaft frame
    position = "90 mm"
    Fy = "5 kN"                         # also Fa, Fz, My, Mz ("N*m")

    [[gear]]                            # spur/helical mesh force
    position = "150 mm"
    tangential_force = "4 kN"
    pitch_diameter = "120 mm"
    pressure_angle = "20 deg"
    helix_angle = "15 deg"
    mesh_azimuth = "0 deg"

    [[belt]]
    position = "250 mm"
    force = "1.2 kN"
    azimuth = "90 deg"

    [[duty]]                            # optional duty cycle: point loads x load_factor
    fraction = 0.3                      # time fraction (the fractions sum to 1)
    speed = "1500 rpm"
    load_factor = 1.0

    [operation]                         # optional
    speed = "1500 rpm"                  # for the lives in hours
    shaft_temperature_change = "10 K"   # from assembly
    housing_temperature_change = "5 K"
    housing_expansion = "11.5e-6 1/K"
"""
from __future__ import annotations

import json
import logging
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Literal, Optional

import numpy as np
import typer

from ballrace.console import UNITS_HELP

__all__ = ["register", "analyze", "load_shaft_case", "parse_shaft_case", "ShaftCase"]

log = logging.getLogger(__name__)


def _models():
    from pydantic import BaseModel, ConfigDict, Field

    from ballrace.casefiles.bearing import bearing_keys

    class _Strict(BaseModel):
        model_config = ConfigDict(extra="forbid", frozen=True)

    class MaterialSpec(_Strict):
        E: str
        nu: float = Field(gt=-1.0, lt=0.5)
        density: Optional[str] = None
        name: str = ""

    class ShaftSpec(_Strict):
        sections: list[list[str]]
        material: Optional[MaterialSpec] = None
        elements: int = Field(default=40, ge=1, le=10000)
        thermal_expansion: Optional[str] = None
        weight: bool = False

    class BearingSpec(bearing_keys()):
        material: Optional[MaterialSpec] = None
        pair: Optional[Literal["DB", "DF", "DT"]] = None
        preload: Optional[str] = None
        dynamic_rating: Optional[str] = None

    class HousingSpec(_Strict):
        axial: str = "inf N/m"
        radial: str = "inf N/m"
        tilt: str = "inf N*m/rad"

    class FitsSpec(_Strict):
        bore: str
        outside_diameter: str
        shaft_interference: str = "0 m"
        housing_interference: str = "0 m"
        housing_diameter: str = "inf m"
        inner_temperature: str = "20 degC"
        outer_temperature: str = "20 degC"
        reference_temperature: str = "20 degC"
        shaft_expansion: Optional[str] = None
        housing_expansion: Optional[str] = None

    class SeatSpec(_Strict):
        name: str = ""
        position: str
        bearing: str
        direction: Literal[1, -1] = 1
        floating: bool = False
        offset: Optional[str] = None
        spring_preload: Optional[str] = None
        clearance: Optional[str] = None
        row_spacing: Optional[str] = None
        housing_stiffness: Optional[HousingSpec] = None
        fits: Optional[FitsSpec] = None

    class LoadSpec(_Strict):
        name: str = ""
        position: str
        Fa: str = "0 N"
        Fy: str = "0 N"
        Fz: str = "0 N"
        My: str = "0 N*m"
        Mz: str = "0 N*m"

    class GearSpec(_Strict):
        name: str = "gear"
        position: str
        tangential_force: str
        pitch_diameter: str
        pressure_angle: str = "20 deg"
        helix_angle: str = "0 deg"
        mesh_azimuth: str = "0 deg"

    class BeltSpec(_Strict):
        name: str = "belt"
        position: str
        force: str
        azimuth: str = "0 deg"

    class OperationSpec(_Strict):
        speed: Optional[str] = None
        rotating_ring: Literal["inner", "outer"] = "inner"
        shaft_temperature_change: str = "0 K"
        housing_temperature_change: str = "0 K"
        housing_expansion: str = "0 1/K"

    class DutySpec(_Strict):
        fraction: float = Field(ge=0.0, le=1.0)
        speed: str
        load_factor: float = Field(default=1.0, ge=0.0)

    class CaseSpec(_Strict):
        title: str = ""
        kind: Literal["shaft"]
        shaft: ShaftSpec
        bearings: dict[str, BearingSpec]
        seat: list[SeatSpec] = Field(min_length=1)
        load: list[LoadSpec] = []
        gear: list[GearSpec] = []
        belt: list[BeltSpec] = []
        operation: OperationSpec = OperationSpec()
        duty: list[DutySpec] = []

    return CaseSpec


@dataclass(frozen=True)
class ShaftCase:
    """A validated shaft case in SI units (frozen).

    Attributes
    ----------
    title : Case title.
    shaft : :class:`~ballrace.analytic.shaft.Shaft`.
    seats : tuple of :class:`~ballrace.analytic.shaft.Seat`.
    loads : tuple of :class:`~ballrace.analytic.shaft.PointLoad` (gears and belts included).
    gravity : (g_x, g_y, g_z) [m/s^2] or None.
    speed_rpm : Shaft speed [rev/min] or None (no lives in hours).
    rotating_ring : "inner" or "outer".
    ratings : Per seat: C [N] or None (ISO 281 from the geometry).
    solve_options : Temperatures for :func:`ballrace.analytic.shaft.solve`.
    duty : Duty cycle: ((time fraction, speed [rev/min], load factor), ...) or ().
    notes : What the reader assumed (defaults taken), for the report.
    """

    title: str
    shaft: object
    seats: tuple
    loads: tuple
    gravity: Optional[tuple]
    speed_rpm: Optional[float]
    rotating_ring: str
    ratings: tuple
    solve_options: dict
    duty: tuple = ()
    notes: tuple = ()


def _kind_hint(data: dict, source: str) -> Optional[str]:
    if data.get("kind") == "shaft":
        return None
    if "bearing" in data and "loads" in data:
        return (f"{source}: this is a bearing case file; run it with `ballrace bearing "
                f"{source}` (a shaft case file has kind = \"shaft\")")
    if "fem" in data or isinstance(data.get("case"), (dict, list)):
        return f"{source}: this is not a shaft case file (FE or validation case)"
    return None


def parse_shaft_case(data: dict, source: str = "<case>") -> ShaftCase:
    """Validate a shaft case dictionary (parsed TOML) and convert it to SI.

    Raises
    ------
    ballrace.errors.CaseFileError
        Naming ``source`` and the offending key.
    """
    import ballrace
    from ballrace.analytic import shaft as S
    from ballrace.casefiles.bearing import (CaseFileError, parse_speed, array_item,
                                            bearing_from_keys, quantity_reader, validate_spec)
    from ballrace.analytic.duplex import DuplexPair

    hint = _kind_hint(data, source)
    if hint:
        raise CaseFileError(hint)
    spec = validate_spec(_models(), data, source)
    q = quantity_reader(source)

    def err(where, msg):
        return CaseFileError(f"{source}: {where}: {msg}")

    def material(m, where):
        if m is None:
            return ballrace.BEARING_STEEL
        kw = dict(E=q(m.E, "[pressure]", f"{where}.E"), nu=m.nu, name=m.name)
        if m.density is not None:
            kw["density"] = q(m.density, "[mass] / [length] ** 3", f"{where}.density")
        try:
            return ballrace.Material(**kw)
        except ValueError as exc:
            raise err(where, exc) from None

    sh = spec.shaft
    case_notes = []
    if sh.material is None:
        m = ballrace.BEARING_STEEL
        case_notes.append(f"[shaft].material not given: {m.name} assumed (E = {m.E / 1e9:g} GPa, "
                          f"nu = {m.nu:g}, density = {m.density:g} kg/m^3)")
    secs = []
    for k, s in enumerate(sh.sections):
        if len(s) != 3:
            raise err(f"[shaft].sections[{k}]", "give [length, outer diameter, inner "
                      f"diameter] as unit strings; got {s!r}")
        secs.append(tuple(q(v, "[length]", f"[shaft].sections[{k}]") for v in s))
    alpha = q(sh.thermal_expansion, "1 / [temperature]", "[shaft].thermal_expansion")
    try:
        shaft = S.Shaft(secs, material(sh.material, "[shaft].material"),
                        n_elements=sh.elements, thermal_expansion=alpha or 0.0)
    except (ValueError, TypeError) as exc:
        raise err("[shaft]", exc) from None
    L = shaft.length

    bearings, ratings = {}, {}
    for name, b in spec.bearings.items():
        where = f"[bearings.{name}]"
        kw = dict(name=b.name or name)
        if b.material is not None:
            kw["material"] = material(b.material, f"{where}.material")
        brg = bearing_from_keys(b, q, source, where, **kw)
        if b.pair is not None:
            P = q(b.preload, "[force]", f"{where}.preload") or 0.0
            try:
                brg = DuplexPair(brg, b.pair, preload=P)
            except (ValueError, TypeError) as exc:
                raise err(where, exc) from None
        elif b.preload is not None:
            raise err(f"{where}.preload", "a preload needs pair = \"DB\", \"DF\" or \"DT\" "
                      "(for single bearings use the seat's offset or spring_preload)")
        bearings[name] = brg
        ratings[name] = q(b.dynamic_rating, "[force]", f"{where}.dynamic_rating")

    def position(v, where):
        x = q(v, "[length]", where)
        if not -1e-12 * L <= x <= L * (1 + 1e-12):
            raise err(where, f"must be within the shaft [0, {L * 1e3:g} mm]; got {v!r}")
        return x

    seats, C = [], []
    for k, s in enumerate(spec.seat):
        where = array_item("seat", k, s)
        if s.bearing not in bearings:
            raise err(f"{where}.bearing", f"no bearing named {s.bearing!r} in [bearings] "
                      f"(have: {', '.join(bearings) or 'none'})")
        brg = bearings[s.bearing]
        kw = dict(direction=s.direction, floating=s.floating, name=s.name or f"seat {k + 1}")
        for key, dim in (("offset", "[length]"), ("spring_preload", "[force]"),
                         ("clearance", "[length]"), ("row_spacing", "[length]")):
            v = q(getattr(s, key), dim, f"{where}.{key}")
            if v is not None:
                kw[key] = v
        if s.fits is not None:
            if "clearance" in kw:
                raise err(f"{where}.fits", "give clearance or fits, not both")
            if isinstance(brg, DuplexPair):
                raise err(f"{where}.fits", "the operating clearance is for a single bearing; "
                          "a pair keeps its preload")
            kw["clearance"] = _fits(s.fits, brg, shaft, position(s.position,
                                                                 f"{where}.position"),
                                    q, source, where)
        if s.housing_stiffness is not None:
            h = s.housing_stiffness
            ka = q(h.axial, "[force] / [length]", f"{where}.housing_stiffness.axial")
            kr = q(h.radial, "[force] / [length]", f"{where}.housing_stiffness.radial")
            kt = q(h.tilt, "[force] * [length]", f"{where}.housing_stiffness.tilt")
            big = 1e3 * max(v for v in (ka, kr, kt) if math.isfinite(v)) if any(
                math.isfinite(v) for v in (ka, kr, kt)) else 1e15
            kw["housing_stiffness"] = [min(v, big) for v in (ka, kr, kr, kt, kt)]
        try:
            seats.append(S.Seat(position(s.position, f"{where}.position"), brg, **kw))
        except CaseFileError:
            raise
        except (ValueError, TypeError) as exc:
            raise err(where, exc) from None
        C.append(ratings[s.bearing])
    order = sorted(range(len(seats)), key=lambda i: seats[i].position)
    for i, j in zip(order[:-1], order[1:]):
        if seats[j].position - seats[i].position < 1e-6 * L:
            raise err(f"{array_item('seat', j, spec.seat[j])}.position",
                      f"on top of {array_item('seat', i, spec.seat[i])} (x = "
                      f"{seats[i].position * 1e3:g} mm); two bearings at one place are a "
                      "pair (pair = \"DB\" in [bearings])")

    loads = []
    for k, p in enumerate(spec.load):
        where = array_item("load", k, p)
        loads.append(S.PointLoad(position(p.position, f"{where}.position"),
                                 Fa=q(p.Fa, "[force]", f"{where}.Fa"),
                                 Fy=q(p.Fy, "[force]", f"{where}.Fy"),
                                 Fz=q(p.Fz, "[force]", f"{where}.Fz"),
                                 My=q(p.My, "[force] * [length]", f"{where}.My"),
                                 Mz=q(p.Mz, "[force] * [length]", f"{where}.Mz"),
                                 name=p.name or f"load {k + 1}"))
    for k, g in enumerate(spec.gear):
        where = array_item("gear", k, g)
        try:
            loads.append(S.gear_mesh(
                position(g.position, f"{where}.position"),
                q(g.tangential_force, "[force]", f"{where}.tangential_force"),
                q(g.pitch_diameter, "[length]", f"{where}.pitch_diameter"),
                pressure_angle=q(g.pressure_angle, "[angle]", f"{where}.pressure_angle"),
                helix_angle=q(g.helix_angle, "[angle]", f"{where}.helix_angle"),
                mesh_azimuth=q(g.mesh_azimuth, "[angle]", f"{where}.mesh_azimuth"),
                name=g.name))
        except CaseFileError:
            raise
        except ValueError as exc:
            raise err(where, exc) from None
    for k, b in enumerate(spec.belt):
        where = array_item("belt", k, b)
        try:
            loads.append(S.belt_pull(position(b.position, f"{where}.position"),
                                     q(b.force, "[force]", f"{where}.force"),
                                     q(b.azimuth, "[angle]", f"{where}.azimuth"), name=b.name))
        except CaseFileError:
            raise
        except ValueError as exc:
            raise err(where, exc) from None

    op = spec.operation
    speed = None if op.speed is None else parse_speed(op.speed, f"{source}: [operation].speed")
    opts = dict(shaft_temperature_change=_delta_T(op.shaft_temperature_change, source,
                                                  "[operation].shaft_temperature_change"),
                housing_temperature_change=_delta_T(op.housing_temperature_change, source,
                                                    "[operation].housing_temperature_change"),
                housing_expansion=q(op.housing_expansion, "1 / [temperature]",
                                    "[operation].housing_expansion"))
    if opts["shaft_temperature_change"] and not shaft.thermal_expansion:
        raise err("[operation].shaft_temperature_change",
                  "needs [shaft].thermal_expansion (e.g. \"11.5e-6 1/K\")")
    duty = []
    for k, d in enumerate(spec.duty):
        w = parse_speed(d.speed, f"{source}: {array_item('duty', k)}.speed")
        duty.append((d.fraction, w * 60 / (2 * math.pi), d.load_factor))
    if duty and abs(sum(d[0] for d in duty) - 1.0) > 1e-6:
        raise err("[[duty]]", f"the fractions must sum to 1; got "
                  f"{sum(d[0] for d in duty):.6g}")
    return ShaftCase(title=spec.title, duty=tuple(duty), shaft=shaft, seats=tuple(seats), loads=tuple(loads),
                     gravity=(0.0, -S.STANDARD_GRAVITY, 0.0) if sh.weight else None,
                     speed_rpm=None if speed is None else speed * 60 / (2 * math.pi),
                     rotating_ring=op.rotating_ring, ratings=tuple(C), solve_options=opts,
                     notes=tuple(case_notes))


def _fits(f, brg, shaft, x, q, source, where):
    """OperatingClearance of a seat from its fits and ring temperatures (clearance module;
    the shaft's bore at the seat and its material)."""
    from ballrace.analytic import clearance as _cl
    from ballrace.casefiles.bearing import CaseFileError, parse_inf, parse_temperature

    w = f"{where}.fits"
    T = {k: parse_temperature(getattr(f, k), f"{source}: {w}.{k}")
         for k in ("inner_temperature", "outer_temperature", "reference_temperature")}
    exp = {k: q(getattr(f, k), "1 / [temperature]", f"{w}.{k}")
           for k in ("shaft_expansion", "housing_expansion")}
    if exp["shaft_expansion"] is None and shaft.thermal_expansion > 0:
        exp["shaft_expansion"] = shaft.thermal_expansion
    try:
        return _cl.operating_clearance(
            brg, bore=q(f.bore, "[length]", f"{w}.bore"),
            outside_diameter=q(f.outside_diameter, "[length]", f"{w}.outside_diameter"),
            shaft_interference=q(f.shaft_interference, "[length]", f"{w}.shaft_interference"),
            housing_interference=q(f.housing_interference, "[length]",
                                   f"{w}.housing_interference"),
            shaft_bore=float(shaft.diameters(x)[1]), shaft_material=shaft.material,
            housing_diameter=parse_inf(q, f.housing_diameter, f"{w}.housing_diameter"),
            **T, **exp)
    except CaseFileError:
        raise
    except ValueError as exc:
        raise CaseFileError(f"{source}: {w}: {exc}") from None


def _delta_T(text, source, where) -> float:
    """A temperature difference [K] from "10 K", "10 delta_degC" (not "10 degC")."""
    from ballrace.errors import CaseFileError
    from ballrace.units import ureg

    s = str(text).strip()
    try:
        qq = ureg().Quantity(s)
        if "degC" in s and "delta" not in s or "degF" in s and "delta" not in s:
            raise ValueError("give a difference in K or delta_degC")
        v = float(qq.to("K").magnitude) if str(qq.units) in ("kelvin",) else \
            float(qq.to("delta_degC").magnitude)
    except Exception as exc:  # pint raises several error types
        raise CaseFileError(f"{source}: {where}: cannot read {s!r} as a temperature "
                            f"difference such as \"10 K\" ({exc})") from None
    return v


def load_shaft_case(path) -> ShaftCase:
    """Read and validate a shaft case file (TOML)."""
    from ballrace.errors import CaseFileError

    p = Path(path)
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise CaseFileError(f"{path}: not valid TOML ({exc})") from None
    return parse_shaft_case(data, str(path))


#: The ISO 281 note of a seat: when the moment the seat carries, taken as a couple of
#: forces 2|M|/d_m at the pitch radius, exceeds this fraction of the seat's force
#: resultant, the note says that P = X Fr + Y Fa (ISO 281) does not see it.
MOMENT_NOTE_RATIO = 0.25

#: Forces and moments smaller than this fraction of the largest load (moments: of the
#: largest load times the shaft length) are round-off of the equilibrium solve and are
#: printed as 0 in the table (the --json output keeps them).
ROUND_OFF = 1e-9

_NO_EFFECT = r"(shaft|housing)_temperature_change = .* has no effect"


def _thermal_note(case: ShaftCase) -> str | None:
    """The note when the case's temperature changes cannot change a load."""
    o = case.solve_options
    names = [f"{k} = {o[k]:g} K" for k, on in (
        ("shaft_temperature_change", o["shaft_temperature_change"] != 0.0),
        ("housing_temperature_change", o["housing_temperature_change"] != 0.0
         and o["housing_expansion"] != 0.0)) if on]
    n_loc = sum(not s.floating for s in case.seats)
    if not names or n_loc > 1:
        return None
    return (f"[operation] {' and '.join(names)} change nothing here: "
            + ("only one seat locates" if n_loc else "no seat locates")
            + " the shaft axially (the others float), so shaft and housing grow freely; "
            "temperatures load the bearings only between two or more locating seats")


def analyze(case: ShaftCase) -> dict:
    """Solve a :class:`ShaftCase`; plain SI numbers (``--json``)."""
    import warnings

    from ballrace.analytic import ratings
    from ballrace.analytic import shaft as S
    from ballrace.analytic.duplex import DuplexPair

    notes = list(case.notes)
    thermal = _thermal_note(case)
    with warnings.catch_warnings():
        if thermal:                             # said in a note instead
            warnings.filterwarnings("ignore", message=_NO_EFFECT, category=UserWarning)
        r = S.solve(case.shaft, case.seats, case.loads, gravity=case.gravity,
                    **case.solve_options)
    if thermal:
        notes.append(thermal)
    try:
        lf = S.rating_lives(r, rotating=case.rotating_ring,
                            dynamic_rating=[c for c in case.ratings] if any(
                                c is not None for c in case.ratings) else None)
    except ValueError as exc:
        lf = None
        notes.append(f"lives not available: {exc}")
    s0 = r.static_safety
    seats = []
    for k, s in enumerate(case.seats):
        b = r.bearings[k]
        rows = b if isinstance(b, tuple) else (b,)
        Q = np.concatenate([np.atleast_1d(x.ball_loads) for x in rows])
        pmax = max(float(np.max(x.inner.p_max)) for x in rows) if Q.max() > 0 else 0.0
        pmax = max(pmax, max(float(np.max(x.outer.p_max)) for x in rows) if Q.max() > 0 else 0)
        beta = np.concatenate([np.atleast_1d(x.contact_angles)[np.atleast_1d(x.ball_loads) > 0]
                               for x in rows]) if Q.max() > 0 else np.zeros(1)
        R = r.reactions[k]
        kind = ratings.bearing_type(s.ball_bearing)
        pair = isinstance(s.bearing, DuplexPair)
        d = dict(name=s.name, position=s.position,
                 bearing=("pair " + s.bearing.arrangement) if pair else "single",
                 direction=s.direction, floating=s.floating,
                 clearance=(s.ball_bearing.diametral_clearance if s.clearance is None
                            else s.clearance),
                 operating_clearance=None if pair else (
                     s.ball_bearing.diametral_clearance if s.clearance is None else s.clearance),
                 reaction=[float(v) for v in R], radial_load=float(np.hypot(R[1], R[2])),
                 moment=float(np.hypot(R[3], R[4])),
                 max_ball_load=float(Q.max()), max_pressure=pmax,
                 static_safety=float(s0[k]),
                 contact_angle_min=float(beta.min()), contact_angle_max=float(beta.max()),
                 contact_angle_limit=(ratings.DEEP_GROOVE_ANGLE_LIMIT if kind == "deep-groove"
                                      else None),
                 misalignment=float(r.misalignment[k]),
                 misalignment_limit=ratings.PERMISSIBLE_MISALIGNMENT[kind],
                 radial_deflection=float(np.hypot(*r.ring_displacements[k, 1:3])),
                 axial_deflection=float(r.ring_displacements[k, 0]),
                 stiffness=[[float(v) for v in row] for row in r.seat_stiffness[k]])
        if lf is not None:
            d["L10r"] = float(lf.seat_lives[k])
            d["L10_iso281"] = lf.catalog_lives[k]
            if case.speed_rpm:
                d["L10r_h"] = float(lf.hours(case.speed_rpm)[0][k])
                if lf.catalog_lives[k] is not None:
                    d["L10_iso281_h"] = lf.catalog_lives[k] * 1e6 / (60 * case.speed_rpm)
        seats.append(d)
    for d, st in zip(seats, case.seats):
        if lf is not None and d.get("L10_iso281") is None:
            why = ("its rows share the thrust in a way the catalogue formula does not know"
                   if isinstance(st.bearing, DuplexPair) else
                   "the X/Y tables do not cover its load")
            notes.append(f"{d['name']}: no ISO 281 catalogue life ({why}); its life is "
                         "L10r (ISO/TS 16281)")
        elif lf is not None:
            note = _moment_note(d, st.ball_bearing.pitch_diameter)
            if note:
                notes.append(note)
    L = case.shaft.length
    xs = np.linspace(0.0, L, 201)
    disp = r.displacement(xs)
    at = r.displacement(np.array([p.position for p in case.loads])) if case.loads else \
        np.zeros((0, 5))
    out = {
        "title": case.title,
        "units": {"length": "m", "force": "N", "moment": "N m", "angle": "rad",
                  "life": "1e6 rev (…_h: hours)"},
        "shaft": {"length": L, "sections": [list(s) for s in case.shaft.sections],
                  "elements": int(r.nodes.size - 1), "mass": case.shaft.mass,
                  "material": {"E": case.shaft.material.E, "nu": case.shaft.material.nu,
                               "density": case.shaft.material.density,
                               "name": case.shaft.material.name},
                  "iterations": int(r.iterations), "residual": float(r.relative_residual),
                  "max_deflection": float(np.hypot(disp[:, 1], disp[:, 2]).max()),
                  "equilibrium_residual": [float(v) for v in r.equilibrium_residual()]},
        "loads": [dict(name=p.name, position=p.position, vector=[float(v) for v in p.vector],
                       displacement=[float(v) for v in u],
                       deflection=float(np.hypot(u[1], u[2])),
                       slope=float(np.hypot(u[3], u[4])))
                  for p, u in zip(case.loads, at)],
        "seats": seats,
        "deflection": {"x": [float(v) for v in xs], "v": [float(v) for v in disp[:, 1]],
                       "w": [float(v) for v in disp[:, 2]], "u": [float(v) for v in disp[:, 0]]},
        "life": None if lf is None else {
            "kind": lf.kind, "weibull_slope": lf.weibull_slope, "system": float(lf.system),
            "system_h": float(lf.hours(case.speed_rpm)[1]) if case.speed_rpm else None},
        "notes": notes,
        "duty": None,
    }
    if case.duty:
        def scaled(p, f):
            return S.PointLoad(p.position, *(f * p.vector), name=p.name)

        kw = dict(rotating=case.rotating_ring,
                  dynamic_rating=[c for c in case.ratings] if any(
                      c is not None for c in case.ratings) else None,
                  gravity=case.gravity, **case.solve_options)
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=_NO_EFFECT, category=UserWarning)
            dc = S.duty_cycle(case.shaft, case.seats,
                              [([scaled(p, f) for p in case.loads], t, n)
                               for t, n, f in case.duty], **kw)
        out["duty"] = {"fractions": [t for t, _, _ in case.duty],
                       "speed_rpm": [n for _, n, _ in case.duty],
                       "load_factor": [f for _, _, f in case.duty],
                       "case_hours": [[float(v) for v in row] for row in dc.case_hours],
                       "seat_hours": [float(v) for v in dc.seat_hours],
                       "system_hours": float(dc.system_hours),
                       "weibull_slope": dc.weibull_slope}
    return out


def _moment_note(d: dict, pitch_diameter: float) -> str | None:
    """The note that the ISO 281 life of a seat does not see its moment, when the moment
    matters (:data:`MOMENT_NOTE_RATIO`); None otherwise."""
    R = d["reaction"]
    F = math.hypot(d["radial_load"], R[0])
    couple = 2.0 * d["moment"] / pitch_diameter
    if not couple > MOMENT_NOTE_RATIO * F:
        return None
    text = (f"{d['name']}: the catalog equivalent load P = X Fr + Y Fa ignores the moment "
            f"{d['moment']:.4g} N m the seat carries (a couple of {couple:.4g} N at the pitch "
            f"radius against {F:.4g} N of force)")
    if d["L10r"] < d["L10_iso281"]:
        return text + (f", so the ISO 281 life above is not conservative (L10r / L10 = "
                       f"{d['L10r'] / d['L10_iso281']:.3g}); use L10r (ISO/TS 16281), from "
                       "the load distribution")
    return text + "; L10r (ISO/TS 16281), from the load distribution, includes it"


def _render(r: dict, units: str = "eng") -> None:
    from ballrace.analytic import ratings
    from ballrace.console import convert as cv
    from ballrace.console import fmt, literal, make_console, print_columns, print_sections
    from ballrace.console import unit_label as ul

    con = make_console()
    sh = r["shaft"]
    rows = [("length", sh["length"], "length"), ("beam elements", sh["elements"], None),
            ("mass", sh["mass"], "mass"), ("largest lateral deflection", sh["max_deflection"],
                                          "small"),
            ("Newton iterations", sh["iterations"], None),
            ("relative residual", sh["residual"], None)]
    if r["life"]:
        lf = r["life"]
        rows.append((f"system life {lf['kind']} (e = {lf['weibull_slope']:.4g})",
                     lf["system"], "=1e6 rev"))
        if lf["system_h"] is not None:
            rows.append(("system life", lf["system_h"], "=h"))
    print_sections(con, [(r["title"] or "shaft", rows)], units)

    def g(x, kind, digits=5):
        return fmt(cv(x, kind, units), digits)

    # round-off of the equilibrium solve (a floating seat's 5e-8 N of thrust) prints as 0
    fscale = max([abs(v) for s in r["seats"] for v in s["reaction"][:3]]
                 + [abs(v) for p in r["loads"] for v in p["vector"][:3]] + [0.0])
    mscale = fscale * sh["length"]

    def force(x):
        return g(0.0 if abs(x) < ROUND_OFF * fscale else x, "force")

    def moment(x):
        return g(0.0 if abs(x) < ROUND_OFF * mscale else x, "moment", 4)

    F, M, Ln, Sm, A = (ul(k, units) for k in ("force", "moment", "length", "small", "angle"))
    flagged = False
    t1, t2, t3, t4 = [], [], [], []
    for s in r["seats"]:
        R = s["reaction"]
        bad_s0 = s["static_safety"] < 1.0
        lim = s["contact_angle_limit"]
        bad_beta = lim is not None and max(abs(s["contact_angle_min"]),
                                           abs(s["contact_angle_max"])) > lim
        bad_tilt = s["misalignment"] > s["misalignment_limit"]
        flagged |= bad_s0 or bad_beta or bad_tilt
        oc = s["operating_clearance"]
        n = s["name"]
        t1.append([n, g(s["position"], "length"), force(s["radial_load"]), force(R[0]),
                   force(R[1]), force(R[2])])
        t2.append([n, f"{s['bearing']} {'+' if s['direction'] > 0 else '-'}x"
                   + (" floating" if s["floating"] else ""), moment(R[3]), moment(R[4]),
                   fmt(s["misalignment"] * 1e3, 3) + (" !" if bad_tilt else "")])
        t3.append([n, "-" if oc is None else g(oc, "small", 4), g(s["max_ball_load"], "force"),
                   g(s["max_pressure"], "stress", 4),
                   fmt(s["static_safety"], 3) + (" !" if bad_s0 else ""),
                   f"{g(s['contact_angle_min'], 'angle', 3)}.."
                   f"{g(s['contact_angle_max'], 'angle', 3)}" + (" !" if bad_beta else "")])
        t4.append([n, g(s["radial_deflection"], "small", 4),
                   fmt(s["L10r_h"], 4) if s.get("L10r_h") is not None else "-",
                   fmt(s["L10_iso281_h"], 4) if s.get("L10_iso281_h") is not None else "-"])
    print_columns(con, "Seats: forces carried (shaft frame)",
                  ["seat", f"x [{Ln}]", f"Fr [{F}]", f"Fa [{F}]", f"Fy [{F}]", f"Fz [{F}]"], t1)
    print_columns(con, "Seats: moments carried and tilt",
                  ["seat", "bearing", f"My [{M}]", f"Mz [{M}]", "tilt [mrad]"], t2)
    print_columns(con, "Seats: contacts",
                  ["seat", f"P_d [{Sm}]", f"Q_max [{F}]", f"p_max [{ul('stress', units)}]",
                   "s0", f"beta [{A}]"], t3)
    print_columns(con, "Seats: deflection and lives",
                  ["seat", f"radial defl. [{Sm}]", "L10r [h]", "ISO 281 L10 [h]"], t4)
    legend = ("Fr = sqrt(Fy^2 + Fz^2); P_d: the seat's operating diametral clearance "
              "(negative: preload); s0 = (4200 MPa / p_max)^3 from the most loaded contact "
              "(ISO 76 bases C0 on 4200 MPa); L10r: ISO/TS 16281 life from the ball loads, "
              "ISO 281 L10 from P = X Fr + Y Fa")
    if r["loads"]:
        dscale = max([p["deflection"] for p in r["loads"]] + [0.0])
        tscale = max([p["slope"] for p in r["loads"]] + [0.0])

        def small(x):
            return g(0.0 if abs(x) < ROUND_OFF * dscale else x, "small", 4)

        def mrad(x):
            return fmt(0.0 if abs(x) < ROUND_OFF * tscale else x * 1e3, 4)

        headers = ["load", f"x [{Ln}]", f"F [{F}]", f"deflection [{Sm}]", "slope [mrad]"]
        rows = [[p["name"], g(p["position"], "length"), force(math.hypot(*p["vector"][:3])),
                 small(p["deflection"]), mrad(p["slope"])] for p in r["loads"]]
        print_columns(con, "Load points: shaft deflection and slope", headers, rows)
        legend += ("; F: magnitude of the load's force; deflection and slope: sqrt(v^2 + w^2) "
                   "and the rotation of the shaft "
                   "section at the load point (a gear's mesh misalignment; components in "
                   "--json)")
    notes = [legend]
    if flagged:
        notes.append(
            "! beyond a limit: s0 < 1 (the contact pressure exceeds the 4200 MPa of C0, "
            "ISO 76), a deep-groove bearing beyond "
            f"{math.degrees(ratings.DEEP_GROOVE_ANGLE_LIMIT):.0f} deg of contact angle, or a "
            "tilt beyond the permissible misalignment of the bearing type (deep-groove "
            f"{math.degrees(ratings.PERMISSIBLE_MISALIGNMENT['deep-groove']) * 60:.0f} arcmin, "
            "angular-contact "
            f"{math.degrees(ratings.PERMISSIBLE_MISALIGNMENT['angular-contact']) * 60:.0f} "
            "arcmin; ballrace.analytic.ratings)")
    if r.get("duty"):
        d = r["duty"]
        rows = [(f"{s['name']}: L10r (Palmgren-Miner)", h, "=h")
                for s, h in zip(r["seats"], d["seat_hours"])]
        rows.append((f"system (e = {d['weibull_slope']:.4g})", d["system_hours"], "=h"))
        print_sections(con, [(f"Duty cycle ({len(d['fractions'])} cases)", rows)], units)
    for n in notes + r["notes"]:
        con.print(literal(f"note: {n}"), style="dim")


def plot(r: dict, path) -> float:
    """Picture of the shaft, its seats, loads, exaggerated deflection line and forces, in the
    two lateral planes (x-y above, x-z below); returns the deflection scale factor."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    L = r["shaft"]["length"]
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    x = np.array(r["deflection"]["x"])
    v = np.array(r["deflection"]["v"])
    w = np.array(r["deflection"]["w"])
    Dmax = max(s[1] for s in r["shaft"]["sections"])
    vmax = max(np.abs(v).max(), np.abs(w).max(), 1e-300)
    scale = 0.6 * Dmax / vmax
    # one arrow scale for both planes: the largest lateral force component
    Fmax = max([abs(c) for s in r["seats"] for c in s["reaction"][1:3]]
               + [abs(c) for p in r["loads"] for c in p["vector"][1:3]] + [1e-300])
    arrow = 0.8 * Dmax * 1e3 / Fmax
    for ax, j, defl, name, colour in ((axes[0], 1, v, "y", "C0"), (axes[1], 2, w, "z", "C2")):
        x0 = 0.0
        for length, D, d in r["shaft"]["sections"]:
            ax.add_patch(plt.Rectangle((x0 * 1e3, -D / 2 * 1e3), length * 1e3, D * 1e3,
                                       fc="0.85", ec="0.4"))
            x0 += length
        ax.plot(x * 1e3, defl * scale * 1e3, colour, lw=2,
                label=f"{'v' if j == 1 else 'w'} ({name}) x {scale:.3g}")
        for s in r["seats"]:
            xs = s["position"] * 1e3
            ax.plot([xs], [-Dmax * 0.75e3], "k^", ms=12)
            Fs = -s["reaction"][j]               # force of the bearing on the shaft
            ax.annotate("", (xs, 0), (xs, -Fs * arrow),
                        arrowprops=dict(arrowstyle="->", color="C3"))
            ax.text(xs, -Dmax * 1.05e3, f"{s['name']}\n{s['reaction'][j]:.4g} N", ha="center",
                    va="top", fontsize=8)
        for p in r["loads"]:
            xp = p["position"] * 1e3
            Fp = p["vector"][j]
            ax.annotate("", (xp, 0), (xp, -Fp * arrow),
                        arrowprops=dict(arrowstyle="->", color="C1", lw=2))
            ax.text(xp, Dmax * 1.1e3, f"{p['name']}\n{Fp:.4g} N", ha="center", fontsize=8)
        ax.set_ylim(-1.6 * Dmax * 1e3, 1.6 * Dmax * 1e3)
        ax.set_ylabel(f"{name} [mm]")
        ax.set_title(f"x-{name} plane: {name} forces on the shaft (seats: the load they carry)",
                     fontsize=9)
        ax.legend(loc="upper right", fontsize=8)
    axes[1].set_xlim(-0.05 * L * 1e3, 1.05 * L * 1e3)
    axes[1].set_xlabel("x [mm]")
    fig.suptitle((r["title"] or "shaft") + f"\ndeflection exaggerated x {scale:.3g}",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return scale


def _clean(obj):
    """JSON-safe copy: NaN / inf become null (as ``ballrace bearing --json``)."""
    from ballrace.commands.bearing import jsonable as clean

    return clean(obj)


def register(app) -> None:
    """Add the ``shaft`` command to a Typer app."""

    @app.command("shaft")
    def shaft_cmd(
        case_file: Annotated[str, typer.Argument(
            help="Shaft case file (TOML, kind = \"shaft\"; docs/shaft.md).")],
        as_json: Annotated[bool, typer.Option(
            "--json", help="Machine-readable JSON (SI units).")] = False,
        units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
        plot_file: Annotated[Optional[str], typer.Option(
            "--plot", help="Write a picture of the shaft (PNG/SVG/PDF) to this file.")] = None,
    ):
        """An elastic shaft on its ball bearings: reactions, ball loads, deflection, lives."""
        from ballrace.errors import CaseFileError
        from ballrace.cli import check_units, fail

        check_units(units)
        p = Path(case_file)
        if p.is_dir():
            fail(f"{case_file}: is a directory; give a shaft case file (.toml)")
        try:
            case = load_shaft_case(case_file)
            result = analyze(case)
        except CaseFileError as exc:
            fail(str(exc).splitlines()[0] if "\n" in str(exc) else str(exc))
        except UnicodeDecodeError:
            fail(f"{case_file}: not a text file; give a shaft case file (TOML)")
        except (OSError, ValueError, RuntimeError) as exc:
            fail(f"{case_file}: {exc}")
        if plot_file:
            scale = plot(result, plot_file)
            if not as_json:
                typer.echo(f"picture: {plot_file} (deflection scale x {scale:.3g})")
        if as_json:
            typer.echo(json.dumps(_clean(result), indent=2))
            return
        _render(result, units)
