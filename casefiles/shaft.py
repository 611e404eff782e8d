r"""Shaft case files (TOML): loading, validation and conversion to SI.

The ``ballrace shaft CASE.toml`` command (:mod:`ballrace.commands.shaft`) reads its case
file here; units are parsed with pint at this boundary only
(:func:`ballrace.units.parse_quantity`).  The bearing, material, fits and operation keys are
those of :mod:`ballrace.casefiles.schema`.

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

    [bearings.nu208]                    # a roller bearing: the roller keys of a bearing
    type = "cylindrical-roller"         # case file (casefiles.schema.roller_bearing_keys)
    roller_diameter = "12 mm"           # or type = "tapered-roller" with contact_angle
    roller_length = "12 mm"
    n_rollers = 14
    pitch_diameter = "60 mm"
    diametral_clearance = "30 um"
    profile = "iso"                     # a name, a table { x, drop } or a crown
    n_slices = 31                       # { flat_length, crown_radius }
    # material = { E = "208 GPa", nu = 0.3 }; dynamic_rating = "62 kN"
    # tapered only: pair = "DB" or "DF" with preload = "2 kN" or end_play = "30 um"
    # (a cylindrical seat takes no direction, offset, spring_preload; no roller seat
    # takes fits: give its clearance)

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

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, Optional

__all__ = ["ShaftCase", "load_shaft_case", "parse_shaft_case"]


def _models():
    """Pydantic models, built on first use; the bearing, material, fits and operation
    keys are the shared ones of :mod:`ballrace.casefiles.schema` (a roller bearing's
    ``[bearings.NAME]`` table: :func:`_roller_models`)."""
    from pydantic import Field

    from ballrace.casefiles import schema

    _Strict = schema.strict()
    MaterialSpec = schema.material_keys()

    class ShaftSpec(_Strict):
        sections: list[list[str]]
        material: Optional[MaterialSpec] = None
        elements: int = Field(default=40, ge=1, le=10000)
        thermal_expansion: Optional[str] = None
        weight: bool = False

    class BearingSpec(schema.bearing_keys()):
        material: Optional[MaterialSpec] = None
        pair: Optional[Literal["DB", "DF", "DT"]] = None
        preload: Optional[str] = None
        dynamic_rating: Optional[str] = None

    class HousingSpec(_Strict):
        axial: str = "inf N/m"
        radial: str = "inf N/m"
        tilt: str = "inf N*m/rad"

    FitsSpec = schema.subset(schema.fits_keys(), "FitsSpec", schema.SEAT_FITS)

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

    class Placed(_Strict):                # a load, gear or belt: where on the shaft
        name: str = ""
        position: str

    class LoadSpec(Placed):
        Fa: str = "0 N"
        Fy: str = "0 N"
        Fz: str = "0 N"
        My: str = "0 N*m"
        Mz: str = "0 N*m"

    class GearSpec(Placed):
        name: str = "gear"
        tangential_force: str
        pitch_diameter: str
        pressure_angle: str = "20 deg"
        helix_angle: str = "0 deg"
        mesh_azimuth: str = "0 deg"

    class BeltSpec(Placed):
        name: str = "belt"
        force: str
        azimuth: str = "0 deg"

    class OperationSpec(schema.operation_keys()):
        speed: Optional[str] = None
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


def _roller_models():
    """Pydantic model of the roller bearings of a shaft case file (``{"bearings": {NAME:
    table}}``, the tables whose ``type`` is a roller type): the roller keys of
    :func:`ballrace.casefiles.schema.roller_bearing_keys` and the shaft's own."""
    from ballrace.casefiles import schema

    MaterialSpec = schema.material_keys()

    class RollerBearingSpec(schema.roller_bearing_keys()):
        material: Optional[MaterialSpec] = None
        pair: Optional[Literal["DB", "DF"]] = None
        preload: Optional[str] = None
        end_play: Optional[str] = None
        dynamic_rating: Optional[str] = None

    class RollerBearings(schema.strict()):
        bearings: dict[str, RollerBearingSpec]

    return RollerBearings


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
                                            bearing_family, bearing_from_keys, quantity_reader,
                                            roller_bearing_from_keys, validate_spec)
    from ballrace.casefiles.schema import ROLLER_TYPES, read_material, read_operating_clearance
    from ballrace.analytic.duplex import DuplexPair

    hint = _kind_hint(data, source)
    if hint:
        raise CaseFileError(hint)
    raw = data.get("bearings")
    rollers = {}
    if isinstance(raw, dict):                 # roller tables: their own model
        for name, table in raw.items():
            if isinstance(table, dict) and bearing_family(
                    table, source, f"[bearings.{name}]") in ROLLER_TYPES:
                rollers[name] = table
        if rollers:
            data = {**data, "bearings": {n: t for n, t in raw.items() if n not in rollers}}
    spec = validate_spec(_models(), data, source)
    roller_specs = validate_spec(_roller_models(), {"bearings": rollers},
                                 source).bearings if rollers else {}
    q = quantity_reader(source)

    def err(where, msg):
        return CaseFileError(f"{source}: {where}: {msg}")

    def material(m, where):
        if m is None:
            return ballrace.BEARING_STEEL
        kw = read_material(m, q, where, m.name)
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
    for name in raw if isinstance(raw, dict) else ():      # in the file's order
        if name in roller_specs:
            b = roller_specs[name]
            bearings[name] = _roller_bearing(b, name, q, source, material,
                                             roller_bearing_from_keys)
            ratings[name] = q(b.dynamic_rating, "[force]",
                              f"[bearings.{name}].dynamic_rating")
            continue
        b = spec.bearings[name]
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
        _roller_seat_keys(s, brg, source, where)
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
            x = position(s.position, f"{where}.position")
            kw["clearance"] = read_operating_clearance(
                s.fits, brg, q, source, f"{where}.fits", shaft_bore=float(shaft.diameters(x)[1]),
                shaft_material=shaft.material, shaft_expansion=shaft.thermal_expansion)
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


def _roller_bearing(b, name, q, source, material, from_keys):
    """The seat bearing of a roller ``[bearings.NAME]`` table ``b``
    (:func:`_roller_models`): a :class:`~ballrace.analytic.roller.RollerBearing`, or with
    ``pair`` a :class:`~ballrace.analytic.roller.TaperedPair` (its ``preload`` [N] or
    ``end_play`` [m]).  ``material`` reads a material table, ``from_keys`` is
    :func:`ballrace.casefiles.bearing.roller_bearing_from_keys`."""
    from ballrace.analytic.roller import TaperedPair
    from ballrace.errors import CaseFileError

    where = f"[bearings.{name}]"
    kw = dict(name=b.name or name)
    if b.material is not None:
        kw["material"] = material(b.material, f"{where}.material")
    brg = from_keys(b, q, source, where, **kw)
    extra = {"preload": q(b.preload, "[force]", f"{where}.preload"),
             "end_play": q(b.end_play, "[length]", f"{where}.end_play")}
    if b.pair is None:
        for key, v in extra.items():
            if v is not None:
                raise CaseFileError(
                    f"{source}: {where}.{key}: a {key.replace('_', ' ')} needs pair = \"DB\" "
                    "or \"DF\" (two tapered roller bearings at one seat); for a single bearing "
                    "use the seat's offset")
        return brg
    if not brg.tapered:
        raise CaseFileError(
            f"{source}: {where}.pair: a pair is of tapered roller bearings (type = "
            f"\"tapered-roller\"); a {b.type} bearing carries no axial load to preload "
            "(remove pair, or give two seats)")
    try:
        return TaperedPair(brg, b.pair, **{k: v for k, v in extra.items() if v is not None})
    except (ValueError, TypeError) as exc:
        raise CaseFileError(f"{source}: {where}: {exc}") from None


def _roller_seat_keys(s, brg, source: str, where: str) -> None:
    """``CaseFileError`` for a ``[[seat]]`` key that means nothing for its roller bearing:
    a thrust direction, offset or spring preload on a bearing that carries no axial load
    (cylindrical), a row spacing on a single bearing, a clearance or fits on a preloaded
    pair, fits on any roller bearing (ball bearings only).  Ball seats are not checked
    here."""
    from ballrace.analytic.roller import RollerBearing, TaperedPair
    from ballrace.errors import CaseFileError

    if not isinstance(brg, (RollerBearing, TaperedPair)):
        return
    given = s.model_fields_set
    if not brg.carries_axial:
        for key, why in (("direction", "a thrust direction"), ("offset", "an axial offset"),
                         ("spring_preload", "a spring preload")):
            if key in given and getattr(s, key) is not None:
                raise CaseFileError(
                    f"{source}: {where}.{key}: {why} means nothing for a {brg.seat_name} "
                    "roller bearing: it carries no axial load (its flanges are not modelled) "
                    "and does not locate the shaft; remove the key (another seat locates)")
    if isinstance(brg, RollerBearing) and s.row_spacing is not None:
        raise CaseFileError(f"{source}: {where}.row_spacing: a single {brg.seat_name} roller "
                            "bearing has one row; row_spacing is for a pair (pair = \"DB\" in "
                            "[bearings])")
    if isinstance(brg, TaperedPair) and s.clearance is not None:
        raise CaseFileError(f"{source}: {where}.clearance: a {brg.seat_name} keeps its preload "
                            "or end play ([bearings] preload, end_play); remove the clearance")
    if s.fits is not None:
        raise CaseFileError(
            f"{source}: {where}.fits: the operating clearance from fits is computed for ball "
            "bearings only; " + ("a tapered pair keeps its preload or end play ([bearings] "
                                 "preload, end_play)" if isinstance(brg, TaperedPair) else
                                 "give the roller seat's operating clearance as clearance "
                                 "(e.g. clearance = \"30 um\")"))


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
