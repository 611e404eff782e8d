"""Bearing case files (TOML): loading, validation and conversion to SI.

A case file describes one bearing, its materials, the applied loads, the speed and the
lubricant, with unit strings parsed by pint at this boundary only
(:func:`ballrace.units.parse_quantity`)::

    title = "209 deep-groove ball bearing"

    [bearing]
    type = "deep-groove"          # or "angular-contact"
    ball_diameter = "12.7 mm"
    n_balls = 9
    pitch_diameter = "65 mm"
    f_inner = 0.52
    f_outer = 0.52
    diametral_clearance = "0.015 mm"   # or free_contact_angle = "40 deg"
    # nominal_contact_angle = "0 deg"  # rating angle; default 0 (deep-groove) or the
                                       # free contact angle (angular-contact)

    [materials]                   # optional; default bearing steel (200 GPa, 0.3)
    ball = { E = "200 GPa", nu = 0.3 }
    ring = { E = "200 GPa", nu = 0.3 }

    [loads]
    radial = "8900 N"
    axial = "0 N"
    # eccentricity = "50.8 mm"    # thrust applied off-axis (Ricci 2009)

    [operation]
    speed = "4000 rpm"            # of the rotating ring: rpm, rev/s or rad/s
    rotating_ring = "inner"

    [lubricant]                   # optional: film thickness and lubrication factor
    viscosity = "0.04 Pa*s"
    pressure_viscosity = "2.2e-8 1/Pa"
    roughness_race = "0.175 um"
    roughness_ball = "0.075 um"

    [life]                        # optional
    standard = "ISO 281:2007"     # or "ABMA 9-1990"
    material = "52100"            # life factors (Hamrock & Dowson 1981 §3.5)
    processing = "air-melt"
    hardness_hrc = 58
    reliability = 0.9             # ISO 281:2007 a1 (0.90 ... 0.9995)
    cleanliness = "normal cleanliness"   # ISO 281 Table 13 level, or contamination = 0.5
    fatigue_limit_method = "hertz"       # C_u: "hertz" (1.5 GPa) or "simplified" (C0/22),
                                         # or fatigue_limit = "1.2 kN"

    [oil]                         # optional: ISO 281 viscosity ratio kappa
    nu40 = "68 mm^2/s"            # "cSt" also accepted
    nu100 = "8.7 mm^2/s"
    temperature = "70 degC"       # operating temperature (or viscosity = "20 mm^2/s")
    ep_additives = false          # effective EP additives (ISO 281: kappa -> 1, a_ISO <= 3)

    [fits]                        # optional: operating clearance (thick-ring Lamé)
    bore = "25 mm"
    outside_diameter = "62 mm"
    shaft_interference = "12 um"  # diametral; negative = loose
    housing_interference = "0 um"
    shaft_bore = "0 mm"           # hollow shaft
    housing_diameter = "inf mm"   # outer diameter of the housing wall
    inner_temperature = "50 degC" # rings (shaft, housing); fits made at 20 degC
    outer_temperature = "40 degC"
    housing_expansion = "11.5e-6 1/K"    # e.g. 23e-6 1/K for aluminium

With ``[fits]`` the bearing's clearance is the unmounted one and the load distribution
uses the operating clearance (negative: preload).

Roller bearings
---------------
``type = "cylindrical-roller"`` or ``"tapered-roller"`` selects the roller keys of
``[bearing]`` (a ball key there, or a roller key in a ball bearing's, is an error)::

    title = "NU 210 cylindrical roller bearing"

    [bearing]
    type = "cylindrical-roller"   # or "tapered-roller"
    roller_diameter = "13 mm"     # tapered: at the middle of the roller
    roller_length = "11.8 mm"     # effective length L_we (without the end chamfers)
    n_rollers = 14
    pitch_diameter = "70.65 mm"
    # contact_angle = "15 deg"    # tapered only (required there): the cup angle
    diametral_clearance = "45 um" # default 0; negative: interference
    profile = "iso"               # "iso" (ISO/TS 16281's default), "straight", "lundberg",
                                  # "johns-gohar"; a circular crown:
    # profile = { flat_length = "8 mm", crown_radius = "2 m" }
                                  # or a table from the roller centre (mirrored), each
                                  # entry with its unit:
    # profile = { x = ["0 mm", "4 mm", "5.9 mm"], drop = ["0 um", "1 um", "6 um"] }
    n_slices = 31                 # slices of the lamina model: odd, >= 5 (default 31)

    [materials]                   # optional; one material for rollers and rings
    roller = { E = "208 GPa", nu = 0.3 }
    ring = { E = "208 GPa", nu = 0.3 }   # if both are given they must be equal

    [loads]
    radial = "6940 N"
    axial = "0 N"                 # cylindrical: 0 (the flanges are not modelled);
                                  # tapered: > 0, pressing the cone into the cup
    misalignment = "2 arcmin"     # optional: the inner ring's tilt, held (default 0)

``[operation]``, ``[life]`` (``standard``, ``reliability``, ``cleanliness`` or
``contamination``, ``fatigue_limit``) and ``[oil]`` are read as for a ball bearing.  A
table profile may equally be written as its own ``[bearing.profile]`` table (TOML makes
both the same); its points must lie within the roller, |x| <= L_we/2, and reach 95 % of
it.  ``[lubricant]`` (the ball contacts' film), ``[fits]`` and the ball-only ``[life]``
keys (``material``, ``processing``, ``hardness_hrc``, ``lubrication_factor``,
``fatigue_limit_method``) are refused for a roller bearing.

Validation uses pydantic v2 (unknown keys are errors, so typos do not pass silently);
every error names the file and the ``[table].key`` it is about.
"""
from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, Optional

import numpy as np

__all__ = ["CaseFileError", "BearingCase", "load_case", "parse_case", "parse_roller_case",
           "bearing_family", "roller_bearing_from_keys"]


from ballrace.errors import CaseFileError  # noqa: E402 - one class for every case file
from ballrace.casefiles.schema import bearing_keys  # noqa: E402,F401 - shared [bearing] keys
from ballrace.casefiles.schema import ROLLER_TYPES  # noqa: E402


def rating_angle(kind: str, nominal, raw, where: str):
    """Rating (nominal) contact angle of a case file's bearing [rad], or None.

    ``kind`` is the bearing ``type``; ``nominal`` the parsed
    ``nominal_contact_angle`` [rad] or None when not given, ``raw`` its text (for the
    message), ``where`` the table it sits in (e.g. ``"[bearing]"``).  A deep-groove
    bearing is rated at 0 deg (the nominal contact angle of ISO 281:2007's rating
    formulas for radial deep-groove bearings); None means "the bearing's free contact angle" (an
    angular-contact bearing's design angle).  ``ValueError`` for an angle outside
    [0, 90) deg or a non-zero angle on a deep-groove bearing.
    """
    if nominal is None:
        return 0.0 if kind == "deep-groove" else None
    if not 0.0 <= nominal < 0.5 * math.pi:
        raise ValueError(f"{where}.nominal_contact_angle must be in [0, 90) deg; got {raw!r}")
    if kind == "deep-groove" and nominal != 0.0:
        raise ValueError(f"{where}.nominal_contact_angle: a deep-groove bearing is rated at "
                         f"0 deg (ISO 281:2007); got {raw!r} - use type = "
                         "\"angular-contact\" for a bearing with a design angle")
    return nominal


def bearing_from_keys(b, q, source: str, where: str, **extra):
    """The :class:`ballrace.BallBearing` of a case file's bearing keys (:func:`bearing_keys`).

    ``q`` is the file's :func:`quantity_reader`, ``where`` the table (``"[bearing]"``),
    ``extra`` further BallBearing arguments (materials, name, rows).  The rating angle
    follows :func:`rating_angle`.  ``CaseFileError`` naming the file and the key.
    """
    import ballrace

    kw = dict(ball_diameter=q(b.ball_diameter, "[length]", f"{where}.ball_diameter"),
              n_balls=b.n_balls,
              pitch_diameter=q(b.pitch_diameter, "[length]", f"{where}.pitch_diameter"),
              f_inner=b.f_inner, f_outer=b.f_outer,
              diametral_clearance=q(b.diametral_clearance, "[length]",
                                    f"{where}.diametral_clearance"),
              free_contact_angle=q(b.free_contact_angle, "[angle]",
                                   f"{where}.free_contact_angle"))
    nominal = q(b.nominal_contact_angle, "[angle]", f"{where}.nominal_contact_angle")
    try:
        nominal = rating_angle(b.type, nominal, b.nominal_contact_angle, where)
    except ValueError as exc:
        raise CaseFileError(f"{source}: {exc}") from None
    try:
        brg = ballrace.BallBearing(**kw, **extra,
                                   nominal_contact_angle=0.0 if nominal is None else nominal)
        if nominal is None:   # angular-contact: its design angle is the free contact angle
            brg = dataclasses.replace(brg, nominal_contact_angle=brg.free_contact_angle)
    except (ValueError, TypeError) as exc:
        raise CaseFileError(f"{source}: {where}: {exc}") from None
    return brg


def _models():
    """Pydantic models, built on first use (pydantic is imported lazily); the shared
    sections come from :mod:`ballrace.casefiles.schema`."""
    from pydantic import Field

    from ballrace.casefiles import schema

    _Strict = schema.strict()

    class BearingSpec(bearing_keys()):
        n_rows: int = Field(default=1, ge=1, le=2)

    class LoadsSpec(_Strict):
        radial: str = "0 N"
        axial: str = "0 N"
        eccentricity: Optional[str] = None

    class LubricantSpec(_Strict):
        viscosity: str
        pressure_viscosity: str
        roughness_race: Optional[str] = None
        roughness_ball: Optional[str] = None

    class LifeSpec(_Strict):
        standard: Literal["ISO 281:2007", "ABMA 9-1990"] = "ISO 281:2007"
        material: Optional[str] = None
        processing: Optional[str] = None
        hardness_hrc: Optional[float] = Field(default=None, gt=0.0, le=70.0)
        lubrication_factor: Optional[float] = Field(default=None, gt=0.0)
        reliability: float = Field(default=0.9, ge=0.9, le=0.9995)
        contamination: Optional[float] = Field(default=None, ge=0.0, le=1.0)
        cleanliness: Optional[str] = None
        fatigue_limit: Optional[str] = None
        fatigue_limit_method: Literal["hertz", "simplified"] = "hertz"

    MaterialsSpec = schema.materials_keys()

    class CaseSpec(_Strict):
        title: str = ""
        bearing: BearingSpec
        materials: MaterialsSpec = MaterialsSpec()
        loads: LoadsSpec
        operation: schema.operation_keys()
        lubricant: Optional[LubricantSpec] = None
        life: LifeSpec = LifeSpec()
        oil: Optional[schema.oil_keys()] = None
        fits: Optional[schema.fits_keys()] = None

    return CaseSpec


@dataclass(frozen=True)
class BearingCase:
    """A validated bearing case in SI units (frozen).

    Attributes
    ----------
    title : Case title.
    bearing : :class:`ballrace.BallBearing`.
    kind : "deep-groove" or "angular-contact" (selects the default nominal contact angle
        of the ratings: 0 for deep-groove, the free contact angle for angular-contact;
        ``[bearing].nominal_contact_angle`` overrides it for angular-contact bearings).
    radial_load, axial_load : Fr, Fa [N].
    eccentricity : Thrust eccentricity [m] or None.
    speed : Angular speed of the rotating ring relative to the other [rad/s].
    rotating_ring : "inner" or "outer".
    viscosity : eta0 [Pa s] or None.
    pressure_viscosity : xi [1/Pa] or None.
    roughness_race, roughness_ball : RMS roughness [m] or None.
    standard : Rating standard.
    material, processing : Life-factor keys or None.
    hardness_hrc : Operating hardness [HRC] or None.
    lubrication_factor : Explicit lubrication factor F or None.
    reliability : ISO 281 reliability [-].
    contamination : e_C [-] (given or from ``cleanliness``) or None.
    cleanliness : ISO 281 Table 13 level or None.
    fatigue_limit : Explicit C_u [N] or None.
    fatigue_limit_method : "hertz" or "simplified".
    oil_viscosity : Kinematic viscosity at the operating temperature [m^2/s] or None.
    oil : dict(nu40, nu100 [m^2/s], temperature [K]) or None.
    ep_additives : Lubricant with effective EP additives (ISO 281 §9.3.3).
    clearance : :class:`~ballrace.analytic.clearance.OperatingClearance` from ``[fits]`` or None.
    misalignment : Roller bearings: the inner ring's tilt held in the plane of the radial
        load [rad] (None: aligned).
    """

    title: str
    bearing: object
    kind: str
    radial_load: float
    axial_load: float
    eccentricity: Optional[float]
    speed: float
    rotating_ring: str
    viscosity: Optional[float]
    pressure_viscosity: Optional[float]
    roughness_race: Optional[float]
    roughness_ball: Optional[float]
    standard: str
    material: Optional[str]
    processing: Optional[str]
    hardness_hrc: Optional[float]
    lubrication_factor: Optional[float]
    reliability: float = 0.9
    contamination: Optional[float] = None
    cleanliness: Optional[str] = None
    fatigue_limit: Optional[float] = None
    fatigue_limit_method: str = "hertz"
    oil_viscosity: Optional[float] = None
    oil: Optional[dict] = None
    clearance: Optional[object] = None
    ep_additives: bool = False
    misalignment: Optional[float] = None

    @property
    def is_roller(self) -> bool:
        """True for a roller-bearing case (``kind`` "cylindrical-roller" or
        "tapered-roller"; ``bearing`` a :class:`~ballrace.analytic.roller.RollerBearing`)."""
        return self.kind in ROLLER_TYPES

    @property
    def solver_options(self) -> dict:
        """Keyword arguments for the load distribution: the operating clearance of
        ``[fits]`` when it is a preload (a positive one is already the bearing's)."""
        if self.clearance is not None and self.clearance.operating < 0:
            return {"clearance": self.clearance.operating}
        return {}

    @property
    def speed_rpm(self) -> float:
        """Speed of the rotating ring [rev/min]."""
        return self.speed * 60.0 / (2.0 * math.pi)

    @property
    def nominal_contact_angle(self) -> float:
        """Nominal contact angle of the ratings and X/Y tables [rad]
        (the bearing's :attr:`~ballrace.BallBearing.nominal_contact_angle`)."""
        if self.is_roller:                  # rated at its contact angle (0, the cup angle)
            return float(self.bearing.contact_angle)
        return float(self.bearing.nominal_contact_angle)


def parse_speed(text: str, where: str) -> float:
    from ballrace.units import check_form, ureg

    s = str(text).strip()
    try:
        check_form(s, where, "4000 rpm")     # "4000,5 rpm" is 40005 rpm to pint
    except ValueError as exc:
        raise CaseFileError(str(exc)) from None
    low = s.lower()
    if not any(u in low for u in ("rpm", "rev", "rad", "deg")):
        raise CaseFileError(f"{where}: give the speed in rpm, rev/min, rev/s or rad/s "
                            f"(a bare 1/s or Hz is ambiguous); got {s!r}")
    try:
        q = ureg().Quantity(s)
        w = float(q.to("rad/s").magnitude)
    except Exception as exc:  # pint raises several error types
        raise CaseFileError(f"{where}: cannot read {s!r} as an angular speed ({exc})") from None
    if not w > 0:
        raise CaseFileError(f"{where}: must be > 0; got {s!r}")
    return w


def parse_temperature(text, where: str) -> float:
    """Absolute temperature [K] from "70 degC", "343.15 K", "158 degF".

    Refused, each in one line naming the key: a bare number (no unit), a temperature
    *difference* unit ("75 delta_degC" would be 75 K), "C" or "F" (pint reads the coulomb
    and the farad), and a temperature outside -100 °C ... 500 °C.
    """
    from ballrace.units import ureg

    from ballrace.analytic.plausible import TEMPERATURE_RANGE, temperature

    example = 'write e.g. "70 degC" or "343.15 K"'
    if isinstance(text, bool) or not isinstance(text, str):
        raise CaseFileError(f"{where}: give the temperature with its unit as a string; got "
                            f"{text!r} ({example})")
    s = text.strip()
    parts = s.split(None, 1)
    unit = parts[1].strip() if len(parts) > 1 else ""
    if not unit:
        raise CaseFileError(f"{where}: no unit in {s!r}; {example}")
    if "delta" in unit.lower():
        raise CaseFileError(f"{where}: {unit!r} is a temperature difference; an absolute "
                            f"temperature is expected here ({example})")
    if unit in ("C", "°", "F", "c", "f"):
        letter = unit.upper()
        raise CaseFileError(f"{where}: {unit!r} is not a temperature unit (to pint, 'C' is the "
                            f"coulomb); write \"{parts[0]} deg{letter}\"")
    try:
        value = float(parts[0])
        T = float(ureg().Quantity(value, unit).to("K").magnitude)
    except Exception:  # pint raises several error types
        raise CaseFileError(f"{where}: cannot read {s!r} as a temperature; {example}") from None
    try:
        temperature(T, "temperature")
    except ValueError:
        lo, hi = TEMPERATURE_RANGE
        raise CaseFileError(f"{where}: {s!r} is {T - 273.15:.6g} °C, outside -100 °C ... "
                            f"500 °C ({lo:g} ... {hi:g} K); {example}") from None
    return T


def _positive(value: float, text, where: str, example: str = "") -> float:
    """``value`` if > 0, else an error quoting what the file says (not the SI float) and a
    valid ``example``."""
    if not value > 0:
        raise CaseFileError(f"{where} must be > 0; got {text!r}"
                            + (f" (e.g. \"{example}\")" if example else ""))
    return value


def _iso_inputs(spec, brg, source, q):
    """ISO 281 / fits inputs of a case (see :func:`parse_case`)."""
    from ballrace.analytic import iso281
    from ballrace.casefiles.schema import read_material, read_operating_clearance

    out: dict = {}
    lf = spec.life
    if lf.contamination is not None and lf.cleanliness is not None:
        raise CaseFileError(f"{source}: [life]: give contamination or cleanliness, not both")
    eC = lf.contamination
    if lf.cleanliness is not None:
        if lf.cleanliness not in iso281.CONTAMINATION_LEVELS:
            raise CaseFileError(f"{source}: [life].cleanliness must be one of "
                                f"{', '.join(iso281.CONTAMINATION_LEVELS)}; got "
                                f"{lf.cleanliness!r}")
        eC = iso281.contamination_factor(lf.cleanliness, brg.pitch_diameter)
    out.update(reliability=lf.reliability, contamination=eC, cleanliness=lf.cleanliness,
               fatigue_limit=q(lf.fatigue_limit, "[force]", "[life].fatigue_limit"),
               fatigue_limit_method=lf.fatigue_limit_method)
    if out["fatigue_limit"] is not None and not out["fatigue_limit"] > 0:
        raise CaseFileError(f"{source}: [life].fatigue_limit must be > 0 N")
    oil = spec.oil
    if oil is not None:
        out["ep_additives"] = oil.ep_additives
        visc_dim = "[length] ** 2 / [time]"
        if oil.viscosity is not None:
            given = [k for k in ("nu40", "nu100", "temperature") if getattr(oil, k) is not None]
            if given:
                raise CaseFileError(f"{source}: [oil]: viscosity (at the operating "
                                    f"temperature) is given, so {' and '.join(given)} must not "
                                    f"be: give viscosity, or nu40, nu100 and temperature")
            out["oil_viscosity"] = _positive(q(oil.viscosity, visc_dim, "[oil].viscosity"),
                                             oil.viscosity, f"{source}: [oil].viscosity",
                                             "20 mm^2/s")
        else:
            missing = [k for k in ("nu40", "nu100", "temperature") if getattr(oil, k) is None]
            if missing:
                raise CaseFileError(f"{source}: [oil]: missing {', '.join(missing)} (or give "
                                    "viscosity at the operating temperature)")
            d = dict(nu40=_positive(q(oil.nu40, visc_dim, "[oil].nu40"), oil.nu40,
                                    f"{source}: [oil].nu40", "68 mm^2/s"),
                     nu100=_positive(q(oil.nu100, visc_dim, "[oil].nu100"), oil.nu100,
                                     f"{source}: [oil].nu100", "8.7 mm^2/s"),
                     temperature=parse_temperature(oil.temperature,
                                                   f"{source}: [oil].temperature"))
            try:
                out["oil_viscosity"] = float(iso281.operating_viscosity(**d))
            except ValueError as exc:
                raise CaseFileError(f"{source}: [oil]: {exc}") from None
            out["oil"] = d
    f = spec.fits
    if f is not None:
        mats = {}
        for which in ("shaft", "housing"):
            m = getattr(f, which)
            if m is not None:
                mats[which] = material(**read_material(m, q, f"[fits.{which}]", m.name or which,
                                                       density=False))
        out["clearance"] = read_operating_clearance(
            f, brg, q, source, "[fits]",
            shaft_bore=q(f.shaft_bore, "[length]", "[fits].shaft_bore"),
            shaft_material=mats.get("shaft"), housing_material=mats.get("housing"))
    return out


def parse_inf(q, value, where):
    """``q`` that accepts an infinite length ("inf mm")."""
    if str(value).strip().lower().startswith("inf"):
        return math.inf
    return q(value, "[length]", where)


def validate_spec(model, data: dict, source: str):
    """``model.model_validate(data)``; pydantic's errors as one :class:`CaseFileError`.

    Each error becomes a line ``SOURCE: [table].key: message`` (shared by the bearing,
    shaft and FE case-file loaders); an entry of an array of tables is named by its
    position from 1 and its ``name`` (``[[seat]] #2 ("B").position``, see
    :func:`array_item`).
    """
    from pydantic import ValidationError

    try:
        return model.model_validate(data)
    except ValidationError as exc:
        lines = []
        for err in exc.errors():
            loc = list(err["loc"])
            key = key_text(loc, data)
            msg = err["msg"]
            x = err.get("input")
            le = (err.get("ctx") or {}).get("le")
            if (err.get("type") == "less_than_equal" and isinstance(x, (int, float))
                    and le is not None and float(le) <= 1.0 < float(x) <= 100.0):
                msg += (f"; a fraction, not a percentage: {float(x) / 100:g} for {x:g} %")
            if err.get("type") == "string_type" and isinstance(x, (int, float)) \
                    and not isinstance(x, bool):
                # a bare number where a quantity string is expected: say how to write it
                msg = (f"give the value with its unit as a string, e.g. "
                       f"\"{x:g} {_unit_example(loc, x)}\"; got {x!r}")
            if err.get("type") in ("float_parsing", "int_parsing") and isinstance(x, str):
                msg = _number_hint(loc, x, err["type"])
            lines.append(f"{source}: {key}: {msg}")
        raise CaseFileError("\n".join(lines)) from None


def array_item(table: str, k: int, item=None) -> str:
    """How a message names entry ``k`` (from 0) of an array of tables: its position from 1
    and the ``name`` the file gives it, if any, e.g. ``[[seat]] #2 ("B (floating)")``.

    ``item`` is the entry: its name as a string, its TOML table (a dict) or its validated
    pydantic model (a default name the file does not give is left out).

    >>> array_item("seat", 1, "B"), array_item("load", 0), array_item("gear", 2, {"name": "g"})
    ('[[seat]] #2 ("B")', '[[load]] #1', '[[gear]] #3 ("g")')
    """
    if hasattr(item, "model_fields_set"):
        name = getattr(item, "name", "") if "name" in item.model_fields_set else ""
    elif isinstance(item, dict):
        name = item.get("name")
    else:
        name = item
    return f"[[{table}]] #{k + 1}" + (f' ("{name}")' if isinstance(name, str) and name else "")


def key_text(loc, data) -> str:
    """``[table].key`` of a pydantic error location ``loc`` in the document ``data``:
    nested tables joined (``[bearings.b6208].n_balls``), an entry of an array of tables
    named by :func:`array_item`, a plain array's element by its index (``sections[0]``).
    """
    node, table, head, i = data, [], "", 0
    while i < len(loc) - 1:
        p = loc[i]
        nxt = node.get(p) if isinstance(node, dict) and isinstance(p, str) else None
        k = loc[i + 1]
        if isinstance(nxt, list) and isinstance(k, int) and 0 <= k < len(nxt) \
                and isinstance(nxt[k], dict):
            item = array_item(".".join([*table, p]), k, nxt[k])
            head = f"{head}.{item}" if head else item
            table, node, i = [], nxt[k], i + 2
            continue
        if isinstance(nxt, dict):
            table.append(p)
            node, i = nxt, i + 1
            continue
        break
    if not head and not table and i < len(loc) - 1 and isinstance(loc[i], str):
        if isinstance(loc[i + 1], int):        # not in the document: a table by its name
            head, i = array_item(loc[i], loc[i + 1]), i + 2
        else:
            table, i = [loc[i]], i + 1
    if table:
        head = f"{head}.{'.'.join(table)}" if head else f"[{'.'.join(table)}]"
    rest = ""
    for p in loc[i:]:
        rest += f"[{p}]" if isinstance(p, int) else (f".{p}" if rest or head else str(p))
    return head + rest


#: Units to suggest for a bare number, by the key's name (last key first, then the tables
#: it sits in): the dimension each key is read with.
_UNIT_BY_KEY = {
    "E": "GPa", "density": "kg/m^3", "speed": "rpm", "viscosity": "mm^2/s",
    "pressure_viscosity": "1/GPa", "nu40": "mm^2/s", "nu100": "mm^2/s",
    "temperature": "degC", "inner_temperature": "degC", "outer_temperature": "degC",
    "reference_temperature": "degC", "shaft_temperature_change": "K",
    "housing_temperature_change": "K",
    "load": "N", "radial": "N", "axial": "N", "force": "N", "tangential_force": "N",
    "preload": "N", "spring_preload": "N", "Fa": "N", "Fy": "N", "Fz": "N",
    "dynamic_rating": "kN", "fatigue_limit": "kN", "My": "N*m", "Mz": "N*m",
    "tilt": "N*m", "free_contact_angle": "deg", "nominal_contact_angle": "deg",
    "contact_angle": "deg", "pressure_angle": "deg", "helix_angle": "deg",
    "mesh_azimuth": "deg", "azimuth": "deg", "shaft_expansion": "1/K",
    "housing_expansion": "1/K", "thermal_expansion": "1/K", "shaft_interference": "um",
    "housing_interference": "um", "diametral_clearance": "um", "clearance": "um",
    "roughness_race": "um", "roughness_ball": "um", "offset": "um",
}


def _unit_example(loc, x: float = 1.0) -> str:
    """The unit to suggest after the bare number ``x`` at the error location ``loc``: the
    key's usual unit, or the one the number's size shows it is in (``E = 2e11`` is
    pascals, ``diametral_clearance = 0.015`` millimetres)."""
    keys = [p for p in loc if isinstance(p, str)]
    last = keys[-1] if keys else ""
    x = abs(float(x))
    if "housing_stiffness" in keys and last in ("axial", "radial"):
        return "N/um"
    if last == "viscosity" and "lubricant" in keys:
        return "Pa*s" if x < 1 else "mPa*s"    # [lubricant]: dynamic viscosity
    if last == "tilt" and keys[0] == "case":   # an FE roller's tilt: an angle, not a moment
        return "rad" if x < 0.01 else "mrad"
    unit = _UNIT_BY_KEY.get(last, "mm")        # the other keys are lengths
    if unit == "GPa" and x >= 1e4:
        return "Pa"
    if unit == "1/GPa" and x < 1e-3:
        return "1/Pa"
    if unit == "um" and 0 < x < 1:
        return "mm"
    if unit == "kN" and x >= 1e3:
        return "N"
    return unit


def _number_hint(loc, text: str, kind: str) -> str:
    """The message for text where a plain number is expected (``reliability = "99 %"``)."""
    keys = [p for p in loc if isinstance(p, str)]
    key = keys[-1] if keys else "value"
    s = text.strip()
    pct = re.fullmatch(r"([+-]?\d+(?:\.\d*)?|\.\d+)\s*(%|percent)", s)
    if pct and kind == "float_parsing":
        v = float(pct.group(1))
        return (f"give a fraction as a plain number, not a percentage: {key} = {v / 100:g} "
                f"for {v:g} %; got {text!r}")
    what = "an integer" if kind == "int_parsing" else "a number"
    example = {"reliability": "0.99", "n_balls": "9", "f_inner": "0.52",
               "f_outer": "0.52", "nu": "0.3", "hardness_hrc": "60", "elements": "40",
               "contamination": "0.5", "fraction": "0.5"}.get(key, "1" if kind ==
                                                              "int_parsing" else "0.5")
    return f"give {what} without quotes or unit, e.g. {key} = {example}; got {text!r}"


def quantity_reader(source: str):
    """``q(value, dimension, where)``: a unit string to SI, ``None`` kept; a bad string is a
    :class:`CaseFileError` naming ``source`` and ``where``."""
    from ballrace.units import parse_quantity

    def q(value, dim, where):
        if value is None:
            return None
        try:
            v = parse_quantity(value, dim, where)
        except ValueError as exc:
            raise CaseFileError(f"{source}: {exc}") from None
        if dim == "[pressure]" and where.rsplit(".", 1)[-1] == "E":
            modulus_slip(v, value, f"{source}: {where}")
        return v

    return q


def modulus_slip(E: float, text, where: str) -> None:
    """Warn, naming ``where`` and quoting ``text``, when a Young's modulus [Pa] is not that
    of a rolling-contact material (``E = "200 MPa"`` for steel's 200 GPa): before any
    calculation, so that the load distribution's complaint is not the first word."""
    from ballrace.units import plausible

    plausible(E, text, where, "modulus", stacklevel=3)


def material(**kw):
    """:class:`ballrace.Material` of a case file's values, whose modulus
    :func:`quantity_reader` has checked already (the library's warning, which speaks of
    pascals typed as numbers, would repeat it)."""
    import warnings

    import ballrace

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r".*moduli are in pascals")
        return ballrace.Material(**kw)


def _kind_hint(data: dict, source: str):
    """A one-line pointer when ``data`` is a shaft case file, not a bearing case file."""
    if data.get("kind") == "shaft" or "shaft" in data or "seat" in data:
        return (f"{source}: this is a shaft case file (kind = \"shaft\": bearings on a shaft), "
                f"not a bearing case file; run it with `ballrace shaft {source}`")
    return None


def _radial_axial(loads, q, source: str, example: str):
    """(F_r, F_a) [N] of a ``[loads]`` table: both >= 0 and not both zero; ``example``
    (``"8900 N"``) is the valid value an error shows."""
    Fr = q(loads.radial, "[force]", "[loads].radial")
    Fa = q(loads.axial, "[force]", "[loads].axial")
    for name, v in (("radial", Fr), ("axial", Fa)):
        if v < 0:
            raise CaseFileError(f"{source}: [loads].{name} must be >= 0 N; got "
                                f"{getattr(loads, name)!r} (e.g. \"{example}\")")
    if Fr == 0 and Fa == 0:
        raise CaseFileError(f"{source}: [loads]: radial and axial are both zero")
    return Fr, Fa


def parse_case(data: dict, source: str = "<case>") -> BearingCase:
    """Validate a case dictionary (parsed TOML) and convert it to SI.

    Parameters
    ----------
    data : dict
        The TOML document.
    source : str
        Name used in error messages (the file name).

    Returns
    -------
    BearingCase

    Raises
    ------
    CaseFileError
        Naming ``source`` and the offending ``[table].key``.

    Examples
    --------
    >>> case = parse_case({"bearing": {"ball_diameter": "12.7 mm", "n_balls": 9,
    ...                                "pitch_diameter": "65 mm", "f_inner": 0.52,
    ...                                "f_outer": 0.52, "diametral_clearance": "0 mm"},
    ...                    "loads": {"radial": "2 kN"}, "operation": {"speed": "1500 rpm"}})
    >>> case.radial_load, round(case.speed_rpm, 6)
    (2000.0, 1500.0)
    >>> parse_case({"bearing": {}, "loads": {}, "operation": {}})  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ballrace.errors.CaseFileError: <case>: [bearing].ball_diameter: Field required...
    """
    hint = _kind_hint(data, source)
    if hint:
        raise CaseFileError(hint)
    if _bearing_type(data, source) in ROLLER_TYPES:
        return parse_roller_case(data, source)
    from ballrace.casefiles.schema import read_materials

    spec = validate_spec(_models(), data, source)
    q = quantity_reader(source)

    b = spec.bearing
    mats = read_materials(spec.materials, q, source, material)
    if (b.diametral_clearance is None) == (b.free_contact_angle is None):
        raise CaseFileError(f"{source}: [bearing]: give exactly one of diametral_clearance "
                            "and free_contact_angle")
    brg = bearing_from_keys(b, q, source, "[bearing]", ball_material=mats.get("ball"),
                            ring_material=mats.get("ring"), n_rows=b.n_rows,
                            name=b.name or spec.title)

    Fr, Fa = _radial_axial(spec.loads, q, source, "8900 N")
    ecc = q(spec.loads.eccentricity, "[length]", "[loads].eccentricity")
    if ecc is not None and Fr != 0:
        raise CaseFileError(f"{source}: [loads].eccentricity applies to a pure thrust load; "
                            "set radial = \"0 N\"")
    lub = spec.lubricant
    visc = xi = rq_r = rq_b = None
    if lub is not None:
        visc = q(lub.viscosity, "[mass] / [length] / [time]", "[lubricant].viscosity")
        xi = q(lub.pressure_viscosity, "1 / [pressure]", "[lubricant].pressure_viscosity")
        rq_r = q(lub.roughness_race, "[length]", "[lubricant].roughness_race")
        rq_b = q(lub.roughness_ball, "[length]", "[lubricant].roughness_ball")
        for name, v in (("viscosity", visc), ("pressure_viscosity", xi)):
            if not v > 0:
                raise CaseFileError(f"{source}: [lubricant].{name} must be > 0; got {v!r}")
    lf = spec.life
    from ballrace.analytic import life as _life

    if lf.material is not None and lf.material not in _life.MATERIAL_FACTOR:
        raise CaseFileError(f"{source}: [life].material must be one of "
                            f"{', '.join(_life.MATERIAL_FACTOR)}; got {lf.material!r}")
    if lf.processing is not None and lf.processing not in _life.PROCESSING_FACTOR:
        raise CaseFileError(f"{source}: [life].processing must be one of "
                            f"{', '.join(_life.PROCESSING_FACTOR)}; got {lf.processing!r}")
    if spec.bearing.type == "deep-groove" and np.degrees(brg.free_contact_angle) > 20:
        raise CaseFileError(f"{source}: [bearing]: a deep-groove bearing with a free contact "
                            f"angle of {np.degrees(brg.free_contact_angle):.1f} deg; use "
                            "type = \"angular-contact\"")
    iso = _iso_inputs(spec, brg, source, q)
    oc = iso.get("clearance")
    if oc is not None:
        if oc.operating >= 0:
            brg = oc.bearing(brg)
        elif Fa != 0 and Fr == 0:
            raise CaseFileError(f"{source}: [fits]: the operating clearance "
                                f"{oc.operating * 1e6:.3g} um is a preload; the thrust "
                                "solvers take no preload: give a radial load component")
    return BearingCase(
        title=spec.title, bearing=brg, kind=spec.bearing.type, radial_load=Fr, axial_load=Fa,
        eccentricity=ecc, speed=parse_speed(spec.operation.speed, f"{source}: [operation].speed"),
        rotating_ring=spec.operation.rotating_ring, viscosity=visc, pressure_viscosity=xi,
        roughness_race=rq_r, roughness_ball=rq_b, standard=lf.standard, material=lf.material,
        processing=lf.processing, hardness_hrc=lf.hardness_hrc,
        lubrication_factor=lf.lubrication_factor, **iso)


# ============================================================================ roller bearings
#: [bearing] keys of a ball bearing only, and what a roller bearing takes instead.
BALL_KEYS = {
    "ball_diameter": 'roller_diameter = "13 mm"', "n_balls": "n_rollers = 14",
    "f_inner": 'roller_length = "11.8 mm" and profile = "iso" (no groove conformity)',
    "f_outer": 'roller_length = "11.8 mm" and profile = "iso" (no groove conformity)',
    "free_contact_angle": 'contact_angle = "15 deg" (tapered: the cup angle)',
    "nominal_contact_angle": 'contact_angle = "15 deg" (tapered: the cup angle)',
    "n_rows": "one row (n_rows is not a roller key)",
}
#: [bearing] keys of a roller bearing only.
ROLLER_KEYS = ("roller_diameter", "roller_length", "n_rollers", "contact_angle", "profile",
               "n_slices")
#: Sections and [life] keys of a ball case that a roller case refuses, and why.
_NOT_FOR_ROLLERS = {
    "lubricant": "[lubricant]: the film thickness is computed for ball contacts only; remove "
                 "it from a roller-bearing case (give [oil] for the ISO 281 viscosity ratio)",
    "fits": "[fits]: the operating clearance from fits is computed for ball bearings only; "
            "give the mounted clearance as [bearing].diametral_clearance (e.g. "
            "diametral_clearance = \"30 um\")",
}
_BALL_LIFE_KEYS = ("material", "processing", "hardness_hrc", "lubrication_factor",
                   "fatigue_limit_method")


def _bearing_type(data: dict, source: str):
    """The ``[bearing].type`` of a case dictionary, after refusing the keys of the other
    family (:func:`bearing_family`)."""
    b = data.get("bearing")
    if not isinstance(b, dict):
        return None
    return bearing_family(b, source, "[bearing]")


def bearing_family(b: dict, source: str, where: str):
    """The ``type`` of a bearing table ``b`` at ``where`` (``"[bearing]"``,
    ``"[bearings.NAME]"``), after refusing the keys of the other family: a ball key in a
    roller bearing's table and a roller key in a ball bearing's (``CaseFileError`` naming
    the key and what to give instead)."""
    typ = b.get("type", "deep-groove")
    if typ in ROLLER_TYPES:
        for key, instead in BALL_KEYS.items():
            if key in b:
                raise CaseFileError(f"{source}: {where}.{key} is a ball-bearing key; a "
                                    f"{typ} bearing takes {instead}")
    else:
        for key in ROLLER_KEYS:
            if key in b:
                raise CaseFileError(
                    f"{source}: {where}.{key} is a roller-bearing key; give type = "
                    f"\"cylindrical-roller\" or \"tapered-roller\" for a roller bearing (a "
                    f"{typ!s} ball bearing takes ball_diameter, n_balls, f_inner, f_outer)")
    return typ


def _roller_models():
    """Pydantic model of a roller-bearing case (built on first use)."""
    from pydantic import Field

    from ballrace.casefiles import schema

    _Strict = schema.strict()
    M = schema.material_keys()

    class RollerLoads(_Strict):
        radial: str = "0 N"
        axial: str = "0 N"
        misalignment: Optional[str] = None

    class RollerLife(_Strict):
        standard: Literal["ISO 281:2007"] = "ISO 281:2007"
        reliability: float = Field(default=0.9, ge=0.9, le=0.9995)
        contamination: Optional[float] = Field(default=None, ge=0.0, le=1.0)
        cleanliness: Optional[str] = None
        fatigue_limit: Optional[str] = None

    class RollerMaterials(_Strict):
        roller: Optional[M] = None
        ring: Optional[M] = None

    class RollerCaseSpec(_Strict):
        title: str = ""
        bearing: schema.roller_bearing_keys()
        materials: RollerMaterials = RollerMaterials()
        loads: RollerLoads
        operation: schema.operation_keys()
        life: RollerLife = RollerLife()
        oil: Optional[schema.oil_keys()] = None

    return RollerCaseSpec


def _quantities(values, q, dim: str, source: str, where: str, example: str) -> list:
    """A list of quantity strings (``["0 mm", "4 mm"]``) in SI; an error names the entry."""
    if not isinstance(values, list) or not values:
        raise CaseFileError(f"{source}: {where} must be a list of quantities with units, e.g. "
                            f"{example}; got {values!r}")
    out = []
    for k, v in enumerate(values):
        if isinstance(v, bool) or not isinstance(v, str):
            raise CaseFileError(f"{source}: {where}[{k}]: give each value with its unit as a "
                                f"string, e.g. {example}; got {v!r}")
        out.append(q(v, dim, f"{where}[{k}]"))
    return out


def read_profile(spec, q, source: str, where: str, length: float, diameter: float):
    """The roller profile of a case file's ``profile`` value at ``where``
    (``"[bearing].profile"``) for a roller of effective length ``length`` [m]: a name, a
    circular crown ``{flat_length, crown_radius}`` or a table ``{x, drop}`` (each entry a
    quantity string; x from the roller centre, mirrored); ``diameter`` is the roller's
    D_we [m].  ``CaseFileError`` naming the key, with a valid example; also for a crown
    whose drop at the roller end exceeds 1 % of D_we and a table reaching beyond the roller
    or dropping more than a tenth of its length (units slipped)."""
    from ballrace.analytic.roller import profile as rp

    table_example = '{ x = ["0 mm", "4 mm", "5.9 mm"], drop = ["0 um", "1 um", "6 um"] }'
    crown_example = '{ flat_length = "8 mm", crown_radius = "2 m" }'
    if isinstance(spec, str):
        key = spec.strip().lower().replace("_", "-")
        if key not in rp.PROFILE_NAMES:
            raise CaseFileError(f"{source}: {where} must be one of "
                                f"{', '.join(rp.PROFILE_NAMES)}, a crown {crown_example} or a "
                                f"table {table_example}; got {spec!r}")
        return key
    keys = set(spec)
    if keys == {"flat_length", "crown_radius"}:
        flat = q(spec["flat_length"], "[length]", f"{where}.flat_length")
        radius = q(spec["crown_radius"], "[length]", f"{where}.crown_radius")
        try:
            crown = rp.Crowned(flat, radius)
            crown.check(rp.ProfileContext(length=length, diameter=diameter))
        except (ValueError, TypeError) as exc:
            raise CaseFileError(f"{source}: {where}: {exc}; e.g. profile = {crown_example}") \
                from None
        s = 0.5 * (length - flat)
        end = s * s / (radius + math.sqrt((radius - s) * (radius + s)))
        if end > 0.01 * diameter:         # a crown radius in mm typed where m was meant
            raise CaseFileError(
                f"{source}: {where}.crown_radius: the crown drops {end * 1e6:.4g} um at the "
                f"roller end, more than 1 % of D_we = {diameter * 1e3:g} mm; crown radii are "
                f"some metres (were millimetres typed?), e.g. profile = {crown_example}")
        return crown
    if keys == {"x", "drop"}:
        x = _quantities(spec["x"], q, "[length]", source, f"{where}.x",
                        '["0 mm", "4 mm", "5.9 mm"]')
        d = _quantities(spec["drop"], q, "[length]", source, f"{where}.drop",
                        '["0 um", "1 um", "6 um"]')
        h = 0.5 * length
        far = max(abs(v) for v in x)
        if far > h * (1 + 1e-9):
            raise CaseFileError(
                f"{source}: {where}.x reaches {far * 1e3:g} mm, beyond the roller's half-"
                f"length L_we/2 = {h * 1e3:g} mm (x is measured from the roller centre; were "
                f"millimetres typed as metres?); e.g. profile = {table_example}")
        if max(d) > 0.1 * length:
            raise CaseFileError(
                f"{source}: {where}.drop reaches {max(d) * 1e3:g} mm, more than a tenth of the "
                f"roller length ({length * 1e3:g} mm; were micrometres meant?); e.g. profile "
                f"= {table_example}")
        try:
            return rp.Table(x, d)
        except (ValueError, TypeError) as exc:
            raise CaseFileError(f"{source}: {where}: {exc}") from None
    raise CaseFileError(f"{source}: {where}: a profile table takes the keys x and drop "
                        f"({table_example}), a circular crown flat_length and crown_radius "
                        f"({crown_example}); got {', '.join(sorted(keys)) or 'an empty table'}")


def _roller_material(spec, q, source: str):
    """The one material of rollers and rings (``[materials]`` roller and/or ring)."""
    from ballrace.casefiles.schema import read_materials

    mats = read_materials(spec, q, source, material, parts=("roller", "ring"))
    if len(mats) == 2:
        a, b = mats["roller"], mats["ring"]
        if (a.E, a.nu) != (b.E, b.nu):
            raise CaseFileError(f"{source}: [materials]: the roller model takes one material for "
                                "rollers and rings; give roller and ring the same E and nu (or "
                                "only one of them)")
    return mats.get("roller") or mats.get("ring")


def roller_bearing_from_keys(b, q, source: str, where: str, **extra):
    """The :class:`~ballrace.analytic.roller.RollerBearing` of a case file's roller bearing
    keys (:func:`~ballrace.casefiles.schema.roller_bearing_keys`; the ``[bearing]`` table of
    a bearing case file, a ``[bearings.NAME]`` table of a shaft case file).

    ``q`` is the file's :func:`quantity_reader`, ``where`` the table (``"[bearing]"``),
    ``extra`` further RollerBearing arguments (material, name).  ``CaseFileError`` naming
    the file and the key, with a valid example.
    """
    from ballrace.analytic.roller import RollerBearing

    W = where
    kind = "tapered" if b.type == "tapered-roller" else "cylindrical"
    D = _positive(q(b.roller_diameter, "[length]", f"{W}.roller_diameter"), b.roller_diameter,
                  f"{source}: {W}.roller_diameter", "13 mm")
    L = _positive(q(b.roller_length, "[length]", f"{W}.roller_length"), b.roller_length,
                  f"{source}: {W}.roller_length", "11.8 mm")
    dm = _positive(q(b.pitch_diameter, "[length]", f"{W}.pitch_diameter"), b.pitch_diameter,
                   f"{source}: {W}.pitch_diameter", "70.65 mm")
    alpha = q(b.contact_angle, "[angle]", f"{W}.contact_angle")
    if kind == "cylindrical" and alpha not in (None, 0.0):
        raise CaseFileError(f"{source}: {W}.contact_angle: a cylindrical roller bearing has "
                            f"contact angle 0; got {b.contact_angle!r} (use type = "
                            "\"tapered-roller\" for a bearing with a cup angle)")
    if kind == "tapered":
        if alpha is None:
            raise CaseFileError(f"{source}: {W}.contact_angle: a tapered roller bearing needs "
                                "its cup angle, e.g. contact_angle = \"15 deg\"")
        if not 0.0 < alpha < math.pi / 3:
            raise CaseFileError(f"{source}: {W}.contact_angle (the cup angle) must be in "
                                f"(0, 60) deg, typically 10 ... 30 deg; got {b.contact_angle!r}"
                                " (e.g. contact_angle = \"15 deg\")")
    if b.n_slices is not None and (b.n_slices < 5 or b.n_slices % 2 == 0):
        good = b.n_slices + 1 if b.n_slices >= 5 else 31
        raise CaseFileError(f"{source}: {W}.n_slices must be odd and >= 5 (one slice at the "
                            f"roller middle); got {b.n_slices} (e.g. n_slices = {good})")
    profile = read_profile(b.profile, q, source, f"{W}.profile", L, D)
    kw = dict(roller_diameter=D, roller_length=L, n_rollers=b.n_rollers, pitch_diameter=dm,
              kind=kind, contact_angle=alpha or 0.0,
              diametral_clearance=q(b.diametral_clearance, "[length]",
                                    f"{W}.diametral_clearance"),
              profile=profile, n_slices=b.n_slices)
    try:
        return RollerBearing(**kw, **extra)
    except (ValueError, TypeError) as exc:
        raise CaseFileError(f"{source}: {W}: {exc}") from None


def parse_roller_case(data: dict, source: str = "<case>") -> BearingCase:
    """Validate a roller-bearing case dictionary (``[bearing].type`` "cylindrical-roller" or
    "tapered-roller"; module notes) and convert it to SI.

    Returns
    -------
    BearingCase
        With ``bearing`` a :class:`~ballrace.analytic.roller.RollerBearing` and ``kind`` the
        ``type``.

    Raises
    ------
    CaseFileError
        Naming ``source`` and the offending ``[table].key``, with a valid example.

    Examples
    --------
    >>> case = parse_roller_case({"bearing": {"type": "cylindrical-roller",
    ...     "roller_diameter": "13 mm", "roller_length": "11.8 mm", "n_rollers": 14,
    ...     "pitch_diameter": "70.65 mm"}, "loads": {"radial": "6940 N"},
    ...     "operation": {"speed": "1500 rpm"}})
    >>> case.bearing.kind, case.bearing.n_slices, case.radial_load
    ('cylindrical', 31, 6940.0)
    """
    import types

    for section, message in _NOT_FOR_ROLLERS.items():
        if section in data:
            raise CaseFileError(f"{source}: {message}")
    life_table = data.get("life")
    if isinstance(life_table, dict):
        for key in _BALL_LIFE_KEYS:
            if key in life_table:
                raise CaseFileError(
                    f"{source}: [life].{key} belongs to the ball bearings' Lundberg-Palmgren "
                    "life and film; a roller case takes standard, reliability, cleanliness "
                    "or contamination, and fatigue_limit (e.g. fatigue_limit = \"9.4 kN\")")
    mt = data.get("materials")
    if isinstance(mt, dict) and "ball" in mt:
        raise CaseFileError(f"{source}: [materials].ball: a roller bearing's materials are "
                            "roller and ring, e.g. roller = { E = \"208 GPa\", nu = 0.3 }")
    spec = validate_spec(_roller_models(), data, source)
    q = quantity_reader(source)
    b = spec.bearing
    mat = _roller_material(spec.materials, q, source)
    brg = roller_bearing_from_keys(b, q, source, "[bearing]", name=b.name or spec.title,
                                   **({} if mat is None else {"material": mat}))
    kind, alpha = brg.kind, brg.contact_angle

    loads = spec.loads
    Fr, Fa = _radial_axial(loads, q, source, "6940 N")
    if kind == "cylindrical" and Fa != 0:
        raise CaseFileError(f"{source}: [loads].axial: a cylindrical roller bearing carries "
                            f"no axial load here (its locating flanges, NJ, NUP, NF, are not "
                            f"modelled); got {loads.axial!r}: set axial = \"0 N\", or use type "
                            "= \"tapered-roller\"")
    if kind == "tapered":
        t = math.tan(alpha)
        if Fa == 0 or Fr > Fa / t:
            need = max(1.26 * Fr * t, 1.0)
            raise CaseFileError(
                f"{source}: [loads].axial: a single tapered roller bearing needs an axial load "
                f"pressing the cone into the cup, more than F_r tan(alpha) = {Fr * t:.4g} N "
                f"(its rollers carry at most F_a / tan(alpha) radially); got "
                f"{loads.axial!r} (e.g. axial = \"{need:.0f} N\", the force a radial load "
                "induces with half the rollers loaded)")
    mis = q(loads.misalignment, "[angle]", "[loads].misalignment")
    if mis is not None and not abs(mis) < 0.01:
        raise CaseFileError(f"{source}: [loads].misalignment must be within +-0.01 rad "
                            f"(34 arcmin); got {loads.misalignment!r} (e.g. misalignment = "
                            "\"2 arcmin\")")
    shim = types.SimpleNamespace(
        life=types.SimpleNamespace(**spec.life.model_dump(), fatigue_limit_method="simplified"),
        oil=spec.oil, fits=None)
    iso = _iso_inputs(shim, brg, source, q)
    return BearingCase(
        title=spec.title, bearing=brg, kind=b.type, radial_load=Fr, axial_load=Fa,
        eccentricity=None,
        speed=parse_speed(spec.operation.speed, f"{source}: [operation].speed"),
        rotating_ring=spec.operation.rotating_ring, viscosity=None, pressure_viscosity=None,
        roughness_race=None, roughness_ball=None, standard=spec.life.standard, material=None,
        processing=None, hardness_hrc=None, lubrication_factor=None,
        misalignment=mis, **iso)


def load_case(path) -> BearingCase:
    """Read and validate a TOML case file (see the module docstring for the format).

    Parameters
    ----------
    path : str or Path
        The case file.

    Raises
    ------
    CaseFileError
        File missing, not TOML, or invalid contents (the message names the key).
    """
    p = Path(path)
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise CaseFileError(f"{p}: no such file") from None
    except tomllib.TOMLDecodeError as exc:
        raise CaseFileError(f"{p}: not valid TOML ({exc})") from None
    return parse_case(data, str(p))
