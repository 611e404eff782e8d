"""``ballrace fem``: run an FE check of a Hertz contact from a case file or flags.

``ballrace fem CASE.toml`` or ``ballrace fem --case inner --load "4450 N"`` meshes,
assembles and solves with a progress display, prints the FE-versus-analytic table,
writes ``result.json`` and PNG renders to ``--out`` (default ``ballrace-out/fem``).
``ballrace fem convergence`` runs a mesh-convergence study instead.

An FE case file (TOML, units parsed with pint; docs/casefiles.md)::

    title = "209 inner race, 1000 lbf"   # optional
    [case]
    contact = "inner"        # inner | outer (ball on a race) | plane | ball
    load = "4450 N"
    contact_angle = "0 deg"  # inner | outer only
    # ball_diameter = "12.7 mm"   # plane | ball only (a race case takes the bearing's)
    [bearing]                # inner | outer only; default: the 209 bearing below
    ball_diameter = "12.7 mm"
    n_balls = 9
    pitch_diameter = "65 mm"
    f_inner = 0.52
    f_outer = 0.52
    [materials]              # optional; default bearing steel (200 GPa, 0.3)
    ball = { E = "200 GPa", nu = 0.3 }
    ring = { E = "200 GPa", nu = 0.3 }   # the race, plane or second ball
    [fem]                    # optional
    level = "standard"       # quick | standard | fine
    mode = "half-space"      # half-space | two-body
    gap = "hertz"            # hertz | exact
    # solver = "cholmod"     # cholmod | pardiso | amg | superlu
    # traction = 0.3         # q = traction * p along +x on the lower body (default 0)
    # traction_pressure = "fe"   # fe (the FE's own pressure) | hertz

A roller on its raceway (:func:`ballrace.fem.roller_contact`, checked against
:func:`ballrace.analytic.roller.line_contact`) takes ``contact = "roller"`` and its own
``[case]`` keys (defaults: the roller of the measured table in :mod:`ballrace.fem.roller`)::

    title = "Lundberg roller, 5 kN"
    [case]
    contact = "roller"
    load = "5 kN"
    roller_diameter = "12 mm"   # or roller_radius (radius in the rolling direction)
    roller_length = "12 mm"     # effective length L_we
    raceway_radius = "inf"      # "inf" flat; "-40 mm" concave (outer ring), "30 mm" convex
    profile = "lundberg"        # as in roller bearing case files: "straight", "iso",
                                # "lundberg", "johns-gohar", a crown
    # profile = { flat_length = "4 mm", crown_radius = "0.5 m" }
                                # or a table { x = [...], drop = [...] }
    n_slices = 41               # slices of the line_contact compared with
    # tilt = "0.5 mrad"         # about the rolling direction (+: the end at +x goes in);
                                # a tilt takes the half model (ballrace.fem.roller)
    [materials]                 # optional; default bearing steel
    roller = { E = "200 GPa", nu = 0.3 }
    ring = { E = "200 GPa", nu = 0.3 }     # the raceway
    [fem]
    level = "standard"          # quick | standard | fine
    mode = "half-space"         # half-space | two-body

The ball keys (``[bearing]``, ``contact_angle``, ``ball_diameter``, ``[fem]`` gap and
traction) are refused for a roller, the roller keys for a ball.

Like bearing case files, unknown keys are errors (a typo never runs a default case) and
every message names the file and the ``[table].key``.  A bearing or validation case
file given here is refused with a pointer to the right command.  Options given on the
command line beside a case file take precedence over the file.
"""
from __future__ import annotations

import functools
import json
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Optional

import typer

from ballrace.console import UNITS_HELP

__all__ = ["register", "FECaseFile", "FERollerCaseFile", "load_fe_case", "parse_fe_case",
           "CONTACTS", "ROLLER_KEYS"]

#: Contacts an FE case describes: a ball on the inner or outer race of a bearing, on a
#: flat, or on another ball.
CONTACTS = ("inner", "outer", "plane", "ball")
LEVELS = ("quick", "standard", "fine")
MODES = ("half-space", "two-body")
GAPS = ("hertz", "exact")
#: The ``[case]`` keys of a roller contact (``contact = "roller"``), and of a ball one.
ROLLER_KEYS = ("roller_diameter", "roller_radius", "roller_length", "raceway_radius",
               "profile", "n_slices", "tilt")
BALL_KEYS = ("contact_angle", "ball_diameter")
#: The ``[fem]`` keys that apply to ball contacts only.
BALL_FEM_KEYS = ("gap", "traction", "traction_pressure")
#: The roller of the measured table of :mod:`ballrace.fem.roller`: the defaults of a roller case.
ROLLER_DEFAULTS = {"load": "5 kN", "roller_diameter": "12 mm", "roller_length": "12 mm",
                   "raceway_radius": "inf", "profile": "lundberg", "n_slices": 41,
                   "tilt": "0 rad"}
DEFAULT_OUT = Path("ballrace-out") / "fem"

_BEARING_209 = {"ball_diameter": "12.7 mm", "n_balls": 9, "pitch_diameter": "65 mm",
                "f_inner": 0.52, "f_outer": 0.52}


@dataclass(frozen=True)
class FECaseFile:
    """A validated FE case (SI), ready for :func:`ballrace.fem.run_case`.

    Attributes
    ----------
    title : str
    case : ballrace.fem.ContactCase
    contact : "inner", "outer", "plane" or "ball".
    level, mode, gap : run settings.
    solver : sparse solver or None (automatic).
    traction : tangential traction coefficient q/p along +x [-] (0: frictionless).
    traction_pressure : "fe" or "hertz": the pressure the traction is proportional to.
    """

    title: str
    case: object
    contact: str
    level: str
    mode: str
    gap: str
    solver: Optional[str]
    traction: float = 0.0
    traction_pressure: str = "fe"


#: The ``[bearing]`` keys an FE case file takes: the geometry of the shared bearing keys
#: (:func:`ballrace.casefiles.schema.bearing_keys`), in this order.
BEARING_KEYS = ("name", "ball_diameter", "n_balls", "pitch_diameter", "f_inner", "f_outer",
                "free_contact_angle", "diametral_clearance")


@dataclass(frozen=True)
class FERollerCaseFile:
    """A validated FE roller case (SI), ready for :func:`ballrace.fem.roller_contact`.

    Attributes
    ----------
    title : str
    load : float
        Normal roller load Q [N].
    roller_radius : float
        Roller radius R1 in the rolling direction [m].
    raceway_radius : float
        Raceway radius R2 [m]: ``inf`` flat, negative concave.
    length : float
        Effective roller length L_we [m].
    roller_material, raceway_material : Material
    profile : str or Profile
        As :func:`ballrace.analytic.roller.as_profile` takes it.
    n_slices : int
        Slices of the line_contact compared with [-].
    level, mode : run settings.
    solver : sparse solver or None (automatic).
    tilt : float
        Tilt of the roller about the rolling direction [rad] (line_contact's sign:
        positive, the end at +x goes in); nonzero takes the half model.
    """

    title: str
    load: float
    roller_radius: float
    raceway_radius: float
    length: float
    roller_material: object
    raceway_material: object
    profile: object
    n_slices: int
    level: str
    mode: str
    solver: Optional[str]
    contact: str = "roller"
    tilt: float = 0.0

    def inputs(self) -> dict:
        """The case in SI for result.json (a flat raceway's radius as null)."""
        import math

        prof = self.profile if isinstance(self.profile, str) else repr(self.profile)
        return {"contact": "roller", "load": self.load, "roller_radius": self.roller_radius,
                "raceway_radius": (self.raceway_radius if math.isfinite(self.raceway_radius)
                                   else None),
                "length": self.length, "profile": prof, "n_slices": self.n_slices,
                "tilt": self.tilt,
                "roller_material": {"E": self.roller_material.E, "nu": self.roller_material.nu},
                "raceway_material": {"E": self.raceway_material.E,
                                     "nu": self.raceway_material.nu}}


@functools.cache
def _roller_models():
    """Pydantic model of an FE roller case (``contact = "roller"``)."""
    from typing import Literal, Union

    from pydantic import Field

    from ballrace.casefiles import schema

    _Strict = schema.strict()
    d = ROLLER_DEFAULTS

    class RollerCaseSpec(_Strict):
        contact: Literal["roller"]
        load: str = d["load"]
        roller_diameter: Optional[str] = None
        roller_radius: Optional[str] = None
        roller_length: str = d["roller_length"]
        raceway_radius: str = d["raceway_radius"]
        profile: Union[str, dict] = d["profile"]
        n_slices: int = Field(default=d["n_slices"], ge=5, le=2001)
        tilt: str = d["tilt"]

    MaterialSpec = schema.subset(schema.material_keys(), "MaterialSpec", ("E", "nu", "name"))

    class RollerMaterials(_Strict):
        roller: Optional[MaterialSpec] = None
        ring: Optional[MaterialSpec] = None

    class RollerFem(_Strict):
        level: Literal["quick", "standard", "fine"] = "standard"
        mode: Literal["half-space", "two-body"] = "half-space"
        solver: Optional[Literal["cholmod", "pardiso", "amg", "superlu"]] = None

    class Spec(_Strict):
        title: str = ""
        case: RollerCaseSpec
        materials: RollerMaterials = RollerMaterials()
        fem: RollerFem = RollerFem()

    return Spec


def _parse_roller(data: dict, source: str) -> FERollerCaseFile:
    """The roller branch of :func:`parse_fe_case` (``data`` merged, ``contact = "roller"``)."""
    import math

    import ballrace
    from ballrace.casefiles.bearing import (CaseFileError, parse_inf, quantity_reader,
                                            read_profile, validate_spec)
    from ballrace.casefiles.schema import read_materials

    case = data.get("case", {})
    for key in BALL_KEYS:
        if key in case:
            raise CaseFileError(f"{source}: [case].{key} applies to ball contacts only (this "
                                "case is contact = 'roller'; give roller_diameter, "
                                "roller_length, raceway_radius, profile)")
    if "bearing" in data:
        raise CaseFileError(f"{source}: [bearing] applies to ball-race contacts only (a "
                            "roller case gives its geometry in [case]: roller_diameter, "
                            "roller_length, raceway_radius)")
    fem_t = data.get("fem")
    for key in BALL_FEM_KEYS:
        if isinstance(fem_t, dict) and key in fem_t:
            raise CaseFileError(f"{source}: [fem].{key} applies to ball contacts only (this "
                                "case is contact = 'roller')")
    spec = validate_spec(_roller_models(), data, source)
    q = quantity_reader(source)
    c = spec.case
    if c.roller_diameter is not None and c.roller_radius is not None:
        raise CaseFileError(f"{source}: [case].roller_radius: give roller_diameter or "
                            "roller_radius, not both")
    if c.roller_radius is not None:
        R1 = q(c.roller_radius, "[length]", "[case].roller_radius")
        where = "[case].roller_radius"
    else:
        R1 = 0.5 * q(c.roller_diameter or ROLLER_DEFAULTS["roller_diameter"], "[length]",
                     "[case].roller_diameter")
        where = "[case].roller_diameter"
    if not R1 > 0:
        raise CaseFileError(f"{source}: {where} must be > 0; e.g. roller_diameter = \"12 mm\"")
    L = q(c.roller_length, "[length]", "[case].roller_length")
    if not L > 0:
        raise CaseFileError(f"{source}: [case].roller_length must be > 0; e.g. "
                            "roller_length = \"12 mm\"")
    text = str(c.raceway_radius).strip().lower()
    R2 = math.inf if text == "flat" else parse_inf(q, c.raceway_radius, "[case].raceway_radius")
    if R2 == 0 or (math.isfinite(R2) and 1.0 / R1 + 1.0 / R2 <= 0):
        raise CaseFileError(f"{source}: [case].raceway_radius = {c.raceway_radius!r}: a concave "
                            f"raceway must be larger than the roller (|R2| > R1 = "
                            f"{R1 * 1e3:g} mm); e.g. raceway_radius = \"-40 mm\" (outer ring) "
                            "or \"inf\" (flat)")
    load = q(c.load, "[force]", "[case].load")
    if not load > 0:
        raise CaseFileError(f"{source}: [case].load must be > 0; e.g. load = \"5 kN\"")
    prof = read_profile(c.profile, q, source, "[case].profile", L, 2.0 * R1)
    tilt = q(c.tilt, "[angle]", "[case].tilt")
    mats = read_materials(spec.materials, q, source, ballrace.Material,
                          parts=("roller", "ring"))
    m1 = mats.get("roller", ballrace.BEARING_STEEL)
    m2 = mats.get("ring", ballrace.BEARING_STEEL)
    try:                                     # the analytic side checks the rest up front
        from ballrace.analytic.roller import line_contact

        line_contact(load, R1, R2, L, m1, m2, profile=prof, tilt=tilt, n_slices=c.n_slices)
    except (ValueError, TypeError) as exc:
        if str(exc).startswith("tilt"):
            raise CaseFileError(f"{source}: [case].tilt = {c.tilt!r}: {exc}") from None
        raise CaseFileError(f"{source}: [case]: {exc}") from None
    f = spec.fem
    return FERollerCaseFile(title=spec.title, load=load, roller_radius=R1, raceway_radius=R2,
                            length=L, roller_material=m1, raceway_material=m2, profile=prof,
                            n_slices=int(c.n_slices), level=f.level, mode=f.mode,
                            solver=f.solver, tilt=float(tilt))


@functools.cache
def _models():
    from typing import Literal

    from pydantic import Field

    from ballrace.casefiles import schema

    _Strict = schema.strict()

    class CaseSpec(_Strict):
        contact: Literal["inner", "outer", "plane", "ball"] = "inner"
        load: str = "4450 N"
        contact_angle: Optional[str] = None
        ball_diameter: Optional[str] = None

    BearingSpec = schema.subset(schema.bearing_keys(), "BearingSpec", BEARING_KEYS)
    MaterialSpec = schema.subset(schema.material_keys(), "MaterialSpec", ("E", "nu", "name"))
    MaterialsSpec = schema.materials_keys(MaterialSpec)

    class FemSpec(_Strict):
        level: Literal["quick", "standard", "fine"] = "standard"
        mode: Literal["half-space", "two-body"] = "half-space"
        gap: Literal["hertz", "exact"] = "hertz"
        solver: Optional[Literal["cholmod", "pardiso", "amg", "superlu"]] = None
        traction: float = Field(default=0.0, ge=-10.0, le=10.0)
        traction_pressure: Literal["fe", "hertz"] = "fe"

    class Spec(_Strict):
        title: str = ""
        case: CaseSpec = CaseSpec()
        bearing: Optional[BearingSpec] = None
        materials: MaterialsSpec = MaterialsSpec()
        fem: FemSpec = FemSpec()

    return Spec


def _kind_error(data: dict, source: str) -> str | None:
    """Refuse a bearing or validation case file with a pointer to the right command."""
    if isinstance(data.get("case"), list):
        return (f"{source}: this is a validation case file ([[case]] tables); run it with "
                f"`ballrace validate --cases {source}`")
    if any(k in data for k in ("loads", "operation", "lubricant", "life")) \
            or ("bearing" in data and "case" not in data and "fem" not in data):
        return (f"{source}: this is a bearing case file, not an FE case file (it has no [case] "
                f"table); run it with `ballrace bearing {source}`")
    return None


def parse_fe_case(data: dict, source: str = "<case>", **overrides) -> FECaseFile:
    """Validate an FE case dictionary (parsed TOML) and build the contact case.

    Parameters
    ----------
    data : dict
        The TOML document (``{}``: the default case, 209 inner race at 4450 N).
    source : str
        Name used in error messages (the file name).
    **overrides
        ``contact``, ``load`` (unit string), ``level``, ``mode``, ``gap``, ``solver``,
        ``traction``, ``traction_pressure``, and for a roller ``profile`` (a name),
        ``roller_diameter``, ``roller_length``, ``raceway_radius``, ``tilt`` (unit
        strings): values given on the command line; ``None`` keeps the file's value.

    Returns
    -------
    FECaseFile, or FERollerCaseFile for ``contact = "roller"``.

    Raises
    ------
    ballrace.errors.CaseFileError
        Naming ``source`` and the offending ``[table].key``.

    Examples
    --------
    >>> c = parse_fe_case({"case": {"contact": "plane", "load": "2 kN"}}, level="quick")
    >>> c.case.name, c.case.load, c.level
    ('ball on plane', 2000.0, 'quick')
    >>> parse_fe_case({"case": {"lod": "2 kN"}}, "x.toml")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ballrace.errors.CaseFileError: x.toml: [case].lod: Extra inputs are not permitted
    """
    import ballrace
    from ballrace.casefiles.bearing import CaseFileError, quantity_reader, validate_spec
    from ballrace.casefiles.schema import read_materials

    from . import api

    msg = _kind_error(data, source)
    if msg:
        raise CaseFileError(msg)
    data = _merge(data, overrides)
    case_t = data.get("case")
    if isinstance(case_t, dict) and case_t.get("contact") == "roller":
        return _parse_roller(data, source)
    if isinstance(case_t, dict):
        for key in ROLLER_KEYS:
            if key in case_t:
                raise CaseFileError(f"{source}: [case].{key} applies to contact = 'roller' "
                                    f"only (this case is contact = "
                                    f"{case_t.get('contact', 'inner')!r})")
    spec = validate_spec(_models(), data, source)
    q = quantity_reader(source)

    c = spec.case
    mats = read_materials(spec.materials, q, source, ballrace.Material)
    load = q(c.load, "[force]", "[case].load")
    race = c.contact in ("inner", "outer")
    if race and c.ball_diameter is not None:
        raise CaseFileError(f"{source}: [case].ball_diameter: a {c.contact}-race case takes "
                            "the ball diameter from [bearing]")
    if not race:
        for key, val in (("[bearing]", spec.bearing), ("[case].contact_angle", c.contact_angle)):
            if val is not None:
                raise CaseFileError(f"{source}: {key} applies to inner | outer race contacts "
                                    f"only (this case is contact = {c.contact!r})")
    try:
        if race:
            b = spec.bearing
            geo = dict(_BEARING_209) if b is None else b.model_dump(exclude_none=True)
            kw = {}
            if geo.get("diametral_clearance") is not None:
                kw["diametral_clearance"] = q(geo["diametral_clearance"], "[length]",
                                              "[bearing].diametral_clearance")
            else:
                kw["free_contact_angle"] = q(geo.get("free_contact_angle", "0 deg"), "[angle]",
                                             "[bearing].free_contact_angle")
            if "ball" in mats:
                kw["ball_material"] = mats["ball"]
            if "ring" in mats:
                kw["ring_material"] = mats["ring"]
            brg = ballrace.BallBearing(
                q(geo["ball_diameter"], "[length]", "[bearing].ball_diameter"),
                int(geo["n_balls"]), q(geo["pitch_diameter"], "[length]",
                                       "[bearing].pitch_diameter"),
                float(geo["f_inner"]), float(geo["f_outer"]), **kw)
            cse = api.race_case(brg, load, c.contact,
                                q(c.contact_angle or "0 deg", "[angle]", "[case].contact_angle"))
        else:
            D = q(c.ball_diameter or "12.7 mm", "[length]", "[case].ball_diameter")
            m1 = mats.get("ball", ballrace.BEARING_STEEL)
            if c.contact == "plane":
                cse = api.plane_case(D, load, material=m1, plane_material=mats.get("ring"))
            else:
                cse = api.ball_case(D, load, material=m1, other_material=mats.get("ring"))
    except CaseFileError:
        raise
    except (ValueError, TypeError) as exc:
        raise CaseFileError(f"{source}: {exc}") from None
    f = spec.fem
    return FECaseFile(title=spec.title, case=cse, contact=c.contact, level=f.level,
                      mode=f.mode, gap=f.gap, solver=f.solver, traction=float(f.traction),
                      traction_pressure=f.traction_pressure)


def _merge(data: dict, overrides: dict) -> dict:
    """The document with command-line values (not None) put in place of the file's."""
    out = {k: (dict(v) if isinstance(v, dict) else v) for k, v in data.items()}
    for key, table in (("contact", "case"), ("load", "case"), ("level", "fem"),
                       ("mode", "fem"), ("gap", "fem"), ("solver", "fem"),
                       ("traction", "fem"), ("traction_pressure", "fem"),
                       ("profile", "case"), ("roller_diameter", "case"),
                       ("roller_length", "case"), ("raceway_radius", "case"),
                       ("tilt", "case")):
        if overrides.get(key) is not None:
            t = out.setdefault(table, {})
            if not isinstance(t, dict):
                continue                 # reported by the validation
            t[key] = overrides[key]
            if key == "roller_diameter":     # the command line's diameter replaces a radius
                t.pop("roller_radius", None)
    return out


def load_fe_case(path, **overrides) -> FECaseFile:
    """Read and validate an FE case file (format: module docstring, docs/casefiles.md).

    Raises
    ------
    ballrace.errors.CaseFileError
        File missing, a directory, not TOML, of another kind, or with invalid contents.
    """
    from ballrace.errors import CaseFileError

    p = Path(path)
    if p.is_dir():
        raise CaseFileError(f"{p}: is a directory; give an FE case file (.toml)")
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise CaseFileError(f"{p}: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise CaseFileError(f"{p}: cannot read ({exc})") from None
    except tomllib.TOMLDecodeError as exc:
        raise CaseFileError(f"{p}: not valid TOML ({exc})") from None
    return parse_fe_case(data, str(p), **overrides)


def _check_choice(value, option: str, allowed) -> None:
    from ballrace.cli import fail

    if value is not None and value not in allowed:
        fail(f"{option} must be one of {', '.join(allowed)}; got {value!r}")


def _check_cell(err, tol, ok):
    """The error, its tolerance and the verdict in one cell: ``+0.21% / 5% ok``.

    One column instead of three keeps the FE table within 80 columns whatever digits the
    solver prints (a separate two-letter status column once split the table in two)."""
    from rich.text import Text

    from ballrace.console import fmt

    if err is None or err != err:            # none, or NaN (a zero reference value)
        return Text("-")
    cell = Text(f"{100 * err:+.2f}%")
    if tol is not None:
        cell.append(f" / {fmt(100 * tol, 3)}% ")
        cell.append("ok" if ok else "FAIL", style="green" if ok else "bold red")
    return cell


def _table(r, units: str, heading: str = "") -> None:
    """The FE-versus-analytic table, driven by the result's comparison rows."""
    from ballrace.console import convert, fmt, literal, make_console, print_columns, unit_label

    d = r.to_dict()
    kinds = {"m": "length", "Pa": "stress", "N": "force"}
    rows = []
    for row in d.get("comparison", []):
        kind = kinds.get(row.get("unit"))
        if kind == "length" and str(row.get("quantity", "")).startswith("approach"):
            kind = "small"                 # deformations in µm, as `ballrace contact` prints them
        unit = unit_label(kind, units) if kind else (row.get("unit") or "")
        ref = str(row.get("error_ref") or "relative")
        per = {"minor semi-axis": " (err/b)", "p0": " (err/p0)"}.get(ref.split(" (")[0], "")
        rows.append([str(row.get("quantity", "")) + per,
                     fmt(convert(row.get("fe"), kind, units), 5),
                     fmt(convert(row.get("analytic"), kind, units), 5), unit,
                     _check_cell(row.get("error"), row.get("tol"), row.get("ok"))])
    total = d.get("timings", {}).get("total")
    title = (f"{d.get('case', '')}, Q = {fmt(convert(d.get('load'), 'force', units))} "
             f"{unit_label('force', units)}\n{d.get('mode')}, {d.get('gap')} gap, "
             f"{d.get('level')}, {d.get('n_dofs', 0):,} DOFs"
             + (f", {total:.1f} s" if total is not None else "") + f", {d.get('solver')}")
    con = make_console()
    if heading:                              # the case file's title, printed literally
        con.print(literal(heading), style="bold")
    print_columns(con, title, ["quantity", "FE", "analytic", "unit", "error / tolerance"],
                  rows, justify=["left", "right", "right", "left", "left"])
    flags = d.get("flags")
    if flags is None:                        # a result without flags: its size at least
        from .api import size_flags

        flags = size_flags(r.case) if getattr(r, "case", None) is not None else []
    for flag in flags:                       # the same notes result.json carries
        con.print(literal(f"note: {flag['message']}"))
    if not d.get("valid", True):
        con.print(literal("verdict: not checked (result.json: \"passed\": null, "
                          "\"valid\": false)"))


def register(app: typer.Typer) -> None:
    """Add the ``fem`` command to the root ``ballrace`` app."""

    @app.command("fem")
    def fem_cmd(
        case_file: Annotated[Optional[str], typer.Argument(
            help="FE case file (docs/casefiles.md), or the word 'convergence' for a "
                 "mesh-convergence study.")] = None,
        case: Annotated[Optional[str], typer.Option(
            "--case", "--contact",
            help="inner | outer (ball on the 209 bearing's race) | plane | ball | roller "
                 "(a profiled roller on its raceway) [default: inner]")] = None,
        load: Annotated[Optional[str], typer.Option(
            help='Ball or roller load, e.g. "4450 N", "1000 lbf" [default: 4450 N; '
                 'roller 5 kN].')] = None,
        level: Annotated[Optional[str], typer.Option(
            help="quick | standard | fine [default: standard]")] = None,
        mode: Annotated[Optional[str], typer.Option(
            help="half-space | two-body [default: half-space]")] = None,
        gap: Annotated[Optional[str], typer.Option(help="hertz | exact [default: hertz]")] = None,
        solver: Annotated[Optional[str], typer.Option(
            help="Force a sparse solver: cholmod | pardiso | amg | superlu "
                 "[default: the best available].")] = None,
        out: Annotated[Path, typer.Option(
            help="Output folder (result.json, PNGs); under ballrace-out/ it holds a .gitignore, so git ignores it.")] = DEFAULT_OUT,
        render: Annotated[bool, typer.Option(help="Write PNG renders.")] = True,
        sizes: Annotated[str, typer.Option(
            help="Convergence: elements per minor semi-axis.")] = "4,6,8,11",
        units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
        traction: Annotated[Optional[float], typer.Option(
            help="Tangential traction coefficient q/p along +x on the lower body; the "
                 "section is compared with the analytic field with traction "
                 "[default: 0].")] = None,
        traction_pressure: Annotated[Optional[str], typer.Option(
            help="fe | hertz: the pressure the traction follows [default: fe].")] = None,
        profile: Annotated[Optional[str], typer.Option(
            help="Roller: straight | iso | lundberg | johns-gohar (a crown or table: in a "
                 "case file) [default: lundberg].")] = None,
        roller_diameter: Annotated[Optional[str], typer.Option(
            help='Roller: its diameter, e.g. "12 mm" [default: 12 mm].')] = None,
        roller_length: Annotated[Optional[str], typer.Option(
            help='Roller: effective length L_we, e.g. "12 mm" [default: 12 mm].')] = None,
        raceway_radius: Annotated[Optional[str], typer.Option(
            help='Roller: raceway radius in the rolling direction, "inf" flat, negative '
                 'concave, e.g. "-40 mm" [default: inf].')] = None,
        tilt: Annotated[Optional[str], typer.Option(
            help='Roller: tilt about the rolling direction, e.g. "0.5 mrad" (+: the end '
                 'at +x goes in; takes the half model) [default: 0].')] = None,
    ):
        """FE check of a Hertz ball contact or a profiled roller's line contact (mesh,
        assemble, solve, compare, render).

        Options given beside a case file take precedence over the file's values.
        """
        from ballrace.errors import CaseFileError
        from ballrace.cli import check_units, fail
        from ballrace.validation.cli import FEM_INSTALL, missing_modules, missing_fem

        from ballrace.units import parse_quantity

        for value, dim, option in ((load, "[force]", "--load"), (tilt, "[angle]", "--tilt")):
            if value is not None:             # named as the option, not as [case].load
                try:
                    parse_quantity(value, dim, option)
                except ValueError as exc:
                    fail(str(exc))
        check_units(units)
        _check_choice(case, "--case", CONTACTS + ("roller",))
        _check_choice(level, "--level", LEVELS)
        _check_choice(mode, "--mode", MODES)
        _check_choice(gap, "--gap", GAPS)
        _check_choice(traction_pressure, "--traction-pressure", ("fe", "hertz"))
        from .solvers import SOLVERS, available_solvers

        _check_choice(solver, "--solver", SOLVERS)
        if solver is not None and solver not in available_solvers():
            fail(f"--solver {solver}: not installed here (available: "
                 f"{', '.join(available_solvers())})")
        n_sizes = ()
        if case_file == "convergence":
            try:
                n_sizes = tuple(int(s) for s in sizes.split(","))
            except ValueError:
                fail(f"--sizes must be comma-separated integers, e.g. 4,6,8; got {sizes!r}")
        overrides = dict(contact=case, load=load, level=level, mode=mode, gap=gap, solver=solver,
                         traction=traction, traction_pressure=traction_pressure,
                         profile=profile, roller_diameter=roller_diameter,
                         roller_length=roller_length, raceway_radius=raceway_radius,
                         tilt=tilt)
        ball_flags = {"--gap": gap, "--traction": traction,
                      "--traction-pressure": traction_pressure}
        roller_flags = {"--profile": profile, "--roller-diameter": roller_diameter,
                        "--roller-length": roller_length, "--raceway-radius": raceway_radius,
                        "--tilt": tilt}
        def parse(**kw):
            if case_file and case_file != "convergence":
                return load_fe_case(case_file, **kw)
            return parse_fe_case({}, "command line", **kw)

        neutral = {k: None for k in ("gap", "traction", "traction_pressure", "profile",
                                     "roller_diameter", "roller_length", "raceway_radius",
                                     "tilt")}
        try:
            fc = parse(**{**overrides, **neutral})       # which kind of contact, first
            is_roller = isinstance(fc, FERollerCaseFile)
            for flag, v in (ball_flags if is_roller else roller_flags).items():
                if v is not None:
                    fail(f"{flag} applies to "
                         + ("ball contacts only (this case is a roller)" if is_roller else
                            "--contact roller only (this case is a ball contact)"))
            fc = parse(**overrides)
        except CaseFileError as exc:
            fail(str(exc))
        if is_roller and case_file == "convergence":
            fail("convergence: the mesh-convergence study is of ball contacts; compare a "
                 "roller's levels with --level quick | standard | fine")
        miss = missing_fem()      # options checked, no work done: no output folder, no solver hint
        if miss:
            fail(f"the FE check needs the fem extra ({', '.join(miss)} not installed): "
                 f"{FEM_INSTALL}")
        if render and case_file != "convergence" and missing_modules("matplotlib"):
            typer.echo('note: the PNG renders need matplotlib (pip install "ballrace[report]"); '
                       "this run writes result.json only", err=True)
            render = False
        from ballrace.console import output_folder

        try:
            out = output_folder(out)
        except ValueError as exc:
            fail(str(exc))
        if case_file == "convergence":
            _convergence(fc, n_sizes, out)
            return
        if is_roller:
            _run_roller(fc, out, render, units)
            return
        from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

        from . import api

        cols = (SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn())
        try:
            with Progress(*cols, transient=True) as prog:
                task = prog.add_task("starting", total=None)
                r = api.run_case(fc.case, level=fc.level, mode=fc.mode, gap=fc.gap,
                                 solver=fc.solver, traction=fc.traction,
                                 traction_pressure=fc.traction_pressure,
                                 progress=lambda s: prog.update(task, description=s))
        except (ValueError, TypeError, ImportError) as exc:
            fail(str(exc))
        _table(r, units, fc.title)
        (out / "result.json").write_text(json.dumps(r.to_dict(), indent=2))
        if render:
            from .render import render as _render

            for field in ("von_mises", "tau_xz", "max_shear", "pressure"):
                _render(r, field=field, path=str(out / f"{field}.png"))
        typer.echo(f"wrote {out / 'result.json'}" + (" and renders" if render else ""))
        # exit 1 when a row is outside its tolerance or the check means nothing here
        # (r.valid False: result.json "passed": null); an exact-gap run has no
        # tolerances and exits 0
        if r.passed is False or not r.valid:
            raise typer.Exit(code=1)


#: Rows of the roller table, in this order: (comparison quantity, label, display kind).
ROLLER_ROWS = (("centre_pressure", "centre pressure (slice)", "stress"),
               ("max_pressure", "max pressure (slice)", "stress"),
               ("edge_pressure", "edge peak (node)", "stress"),
               ("peak_slice_load", "load of peak slice", "force"),
               ("edge_slice_load", "load of end slice", "force"),
               ("end_quarter_load", "load of end quarter", "force"),
               ("approach", "approach", "small"),
               ("von_mises_centre", "von Mises, centre", "stress"),
               ("von_mises_centre_depth", "  its depth", "length"),
               ("von_mises_edge", "von Mises, edge", "stress"),
               ("von_mises_edge_depth", "  its depth", "length"))


def _profile_text(prof) -> str:
    if isinstance(prof, str):
        return prof
    from ballrace.analytic.roller import profile as rp

    if isinstance(prof, rp.Crowned):
        return (f"crowned (flat {prof.flat_length * 1e3:g} mm, crown radius "
                f"{prof.crown_radius:g} m)")
    return getattr(prof, "name", type(prof).__name__)


def _roller_table(r, fc, units: str) -> None:
    """The FE-versus-line_contact table of a roller result (engineering units, 80 columns)."""
    import math

    from ballrace.console import convert, fmt, literal, make_console, print_columns, unit_label

    rows = []
    for q, label, kind in ROLLER_ROWS:
        try:
            row = r.row(q)
        except KeyError:
            continue
        rows.append([label, fmt(convert(row["fe"], kind, units), 5),
                     fmt(convert(row["analytic"], kind, units), 5), unit_label(kind, units),
                     _check_cell(row["error"], row["tol"], row["ok"])])
    R2 = fc.raceway_radius
    race = ("flat raceway" if not math.isfinite(R2) else
            f"raceway R2 = {fmt(convert(R2, 'length', units), 5)} {unit_label('length', units)}")
    total = r.timings.get("total")
    lu = unit_label("length", units)
    title = (f"{_profile_text(fc.profile)} roller\n"       # a line of its own: fits 80 columns
             f"Q = {fmt(convert(fc.load, 'force', units))} "
             f"{unit_label('force', units)}, D = "
             f"{fmt(convert(2 * fc.roller_radius, 'length', units), 5)} {lu}, L = "
             f"{fmt(convert(fc.length, 'length', units), 5)} {lu}, {race}\n"
             + (f"tilt {fmt(fc.tilt * 1e3, 4)} mrad, " if fc.tilt else "")
             + f"{r.mode}, {r.info.get('model', 'quarter')} model, {r.level}, "
             f"{r.n_dofs:,} DOFs"
             + (f", {total:.1f} s" if total is not None else "") + f", {r.solver}")
    con = make_console()
    if fc.title:
        con.print(literal(fc.title), style="bold")
    print_columns(con, title, ["quantity", "FE", "line_contact", "unit", "error / tolerance"],
                  rows, justify=["left", "right", "right", "left", "left"])
    if fc.profile == "straight" or (hasattr(fc.profile, "name") and fc.profile.name == "straight"):
        con.print(literal("note: a straight roller's end pressure is singular on a half-space: "
                          "the edge peak grows with refinement in the FE and with the slice "
                          "count in line_contact; neither value is converged"))
    if r.mode == "two-body":
        con.print(literal("note: two bodies (the finite elastic roller) depart from "
                          "line_contact's half-spaces by design; no tolerances apply"))
    if r.info.get("model") == "half":
        side = "+x" if float(r.info.get("x_edge_slice", 1.0)) > 0 else "-x"
        con.print(literal(f"note: the half model (the whole length); the end slice and the end "
                          f"quarter (|x| >= L/4) are those of the more loaded end, {side}"))


def _run_roller(fc, out: Path, render: bool, units: str) -> None:
    """Solve an FE roller case with a progress display; table, result.json, renders."""
    import logging

    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from ballrace.cli import fail

    from .roller import roller_contact

    logger = logging.getLogger("ballrace")
    shown = logger.getEffectiveLevel()           # what the user asked to see (-v)

    class _Stage(logging.Handler):
        """The library's log lines as progress stages; those the user would have seen
        passed on as before."""

        def __init__(self, update):
            super().__init__(logging.INFO)
            self.update = update

        def emit(self, record):
            msg = record.getMessage().splitlines()[0]
            self.update(msg if len(msg) <= 70 else msg[:67] + "...")
            if record.levelno >= shown:
                logging.getLogger().handle(record)

    cols = (SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn())
    saved = (logger.level, logger.propagate)
    try:
        with Progress(*cols, transient=True) as prog:
            task = prog.add_task(f"roller contact, {fc.level} level: meshing", total=None)
            h = _Stage(lambda m: prog.update(task, description=m))
            logger.addHandler(h)
            logger.setLevel(min(shown, logging.INFO))
            logger.propagate = False
            try:
                r = roller_contact(fc.load, fc.roller_radius, fc.raceway_radius, fc.length,
                                   fc.roller_material, fc.raceway_material,
                                   profile=fc.profile, level=fc.level, mode=fc.mode,
                                   n_slices=fc.n_slices, tilt=fc.tilt, solver=fc.solver)
            finally:
                logger.removeHandler(h)
                logger.setLevel(saved[0])         # setLevel: clears the loggers' level caches
                logger.propagate = saved[1]
    except (ValueError, TypeError, ImportError) as exc:
        fail(str(exc))
    _roller_table(r, fc, units)
    doc = r.to_dict()
    doc["case"] = fc.inputs()
    doc["passed"] = r.within_tolerance
    from ballrace.commands.bearing import jsonable

    # valid JSON: a relative error against a zero reference (line_contact's unloaded end
    # slice of a tilted roller) is NaN in the result, null in the file
    (out / "result.json").write_text(json.dumps(jsonable(doc), indent=2))
    if render:
        from .render import render_roller

        for field in ("von_mises", "max_shear"):
            render_roller(r, str(out / f"roller_{field}.png"), field=field)
    typer.echo(f"wrote {out / 'result.json'}" + (" and renders" if render else ""))
    if r.within_tolerance is False:           # a row outside its tolerance
        raise typer.Exit(code=1)


def _convergence(fc, n: tuple, out: Path) -> None:
    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from ballrace.cli import fail
    from ballrace.console import make_console, print_columns

    from .convergence import QUANTITIES, convergence_study

    cols = (SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn())
    try:
        with Progress(*cols, transient=True) as prog:
            task = prog.add_task("convergence", total=None)
            st = convergence_study(fc.case, n, mode=fc.mode, gap=fc.gap, solver=fc.solver,
                                   progress=lambda s: prog.update(task, description=s))
    except (ValueError, TypeError, ImportError) as exc:
        fail(str(exc))
    rows = [[str(row[0]), f"{row[1]:,}", f"{row[2]:.1f}", *[f"{100 * e:+.2f} %" for e in row[3:]]]
            for row in st.rows()]
    rows.append(["rate", "per DOF", "", *[f"{st.rates[q]:.2f}" for q in QUANTITIES]])
    print_columns(make_console(),
                  f"mesh convergence: {fc.case.name}, {fc.mode} (errors vs analytic; "
                  "rate = slope of log|error| vs log DOFs, x3 for h)",
                  ["n/minor", "DOFs", "s", *QUANTITIES], rows)
    (out / "convergence.json").write_text(json.dumps(
        {"n": st.n, "dofs": st.dofs, "seconds": st.seconds, "errors": st.errors,
         "rates": st.rates}, indent=2))
