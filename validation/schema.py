"""Reference-case files: the schema, the loader and its checks.

A case file (TOML) holds one or more ``[[case]]`` tables and an optional ``[defaults]``
table merged into each case (``inputs`` and ``source`` key by key, everything else
replaced).  One case::

    [[case]]
    id = "hertz-moose-spherical"           # unique over all files
    title = "MOOSE hertz_spherical: two spheres, a = 0.1"
    kind = "published"                     # published | independent derivation |
                                           # FE check | regression baseline
    calculation = "hertz.point_contact"    # a name in ballrace.validation.registry
    [case.source]
    author = "MOOSE contact module"
    year = 2020
    reference = "test/tests/hertz_spherical, analytic a and approach in the test header"
    [case.inputs]                          # unit strings, converted to SI with pint
    load = "10000 N"
    rx1 = "2 m"
    [case.expected.a]                      # an output of the calculation
    value = "0.1 m"
    rtol = 1e-9                            # and/or atol = "1e-6 m"
    reason = "closed form: the numbers are exact in the test's consistent units"

Instead of ``value`` an expectation may give a bound, ``max = ...`` and/or
``min = ...`` (the approximations' documented error bounds).  Every tolerance or bound
needs a ``reason``.  Values, tolerances and bounds must be finite numbers (``"inf m"``,
``"1e400 m"``, which overflows to inf, or ``"-1e999 m"`` would make an expectation that
cannot fail).  A ``[case.sweep]`` table turns a case into a parameter sweep: each
key is an input with a list of values (or ``{linspace = [lo, hi, n]}`` /
``{logspace = [lo_exp, hi_exp, n]}``), the calculation runs on the Cartesian grid
(through dask), and ``[case.reduce]`` maps new output names to ``"max_abs(name)"``,
``"max(name)"``, ``"min(name)"`` or ``"mean(name)"`` over the grid, or
``"min_rise(name)"``: the smallest change of ``|name|`` from one grid point to the next
along the *last* sweep axis (``min = 0`` then checks that ``|name|`` never falls along
that axis); the expectations then refer to those reduced names.  A case tagged
``"on-demand"`` (``tags = ["on-demand"]``, e.g. a long FE sweep) is left out of the
default selection (all packaged cases) and runs only when its file is named with
``--cases``.

Loading checks everything that can be checked without running: unknown calculation,
missing or unknown fields, unit strings of the wrong dimension, tolerances without a
reason.  Errors are :class:`CaseFileError` naming the file, the case and the field.

Examples
--------
>>> from ballrace.validation.schema import parse_cases
>>> text = '''
... [[case]]
... id = "demo"
... title = "sphere on flat"
... kind = "independent derivation"
... calculation = "hertz.point_contact"
... source = {author = "Johnson", year = 1985, reference = "eq. (4.22)"}
... inputs = {load = "1000 N", rx1 = "5 mm", ry1 = "5 mm", E1 = "200 GPa", nu1 = 0.3}
... expected.a = {value = "0.3244 mm", rtol = 1e-3, reason = "4 digits quoted"}
... '''
>>> (case,) = parse_cases(text, "demo.toml")
>>> case.inputs["rx1"], case.expected[0].value
(0.005, 0.0003244)
>>> parse_cases(text.replace(', reason = "4 digits quoted"', ''), "demo.toml")
Traceback (most recent call last):
...
ballrace.errors.CaseFileError: demo.toml: case 'demo': expected.a: a tolerance needs a 'reason' (why this tolerance?)
"""
from __future__ import annotations

import glob as _glob
import itertools
import math
import os
import re
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from ballrace.units import parse_quantity

from . import registry

__all__ = ["KINDS", "CaseFileError", "Source", "Expectation", "Sweep", "Case", "parse_cases",
           "load_case_file", "load_cases", "default_case_dir"]

KINDS = ("published", "independent derivation", "FE check", "regression baseline")
_CASE_KEYS = {"id", "title", "kind", "calculation", "source", "inputs", "expected", "sweep",
              "reduce", "notes", "fem_levels", "tags"}
_SOURCE_KEYS = {"author", "year", "reference", "url", "note"}
_EXPECT_KEYS = {"value", "rtol", "atol", "max", "min", "reason"}
_REDUCERS = ("max_abs", "max", "min", "mean", "min_rise")
#: Cases with this tag run only when their file is selected with ``--cases``.
ON_DEMAND = "on-demand"
_FEM_LEVELS = ("quick", "standard")
_ID_RE = re.compile(r"^[a-z0-9][a-z0-9._-]*$")


from ballrace.errors import CaseFileError  # noqa: E402 - one class for every case file


@dataclass(frozen=True)
class Source:
    """Where the expected numbers come from (frozen)."""

    author: str
    year: int | str
    reference: str
    url: str = ""
    note: str = ""

    def __str__(self) -> str:
        return f"{self.author} ({self.year}), {self.reference}"


@dataclass(frozen=True)
class Expectation:
    """An expected output with its tolerance and the reason for it (frozen; SI values).

    ``value`` with ``rtol``/``atol``: pass when |got - value| <= atol + rtol |value|.
    ``max``/``min``: pass when got <= max and got >= min.
    """

    name: str
    dimension: str
    reason: str
    value: float | None = None
    rtol: float = 0.0
    atol: float = 0.0
    max: float | None = None
    min: float | None = None
    text: str = ""               # the value or bound as written in the file

    @property
    def allowed(self) -> float | None:
        """Allowed |got - value| [SI], or None for a bound."""
        if self.value is None:
            return None
        return self.atol + self.rtol * abs(self.value)

    def check(self, got: float) -> bool:
        """True when ``got`` satisfies this expectation (NaN never does)."""
        if got is None or not math.isfinite(got):
            return False
        if self.value is not None:
            return abs(got - self.value) <= self.allowed * (1 + 1e-12) + 1e-300
        ok = True
        if self.max is not None:
            ok &= got <= self.max
        if self.min is not None:
            ok &= got >= self.min
        return bool(ok)

@dataclass(frozen=True)
class Sweep:
    """A parameter sweep (frozen): a grid of inputs and reductions of the outputs."""

    axes: tuple            # ((input name, (SI values, ...)), ...) in file order
    reduce: tuple          # ((new output name, reducer, point output name), ...)

    def points(self) -> list[dict[str, Any]]:
        """The Cartesian grid as a list of {input: SI value} in a fixed (row-major) order."""
        names = [n for n, _ in self.axes]
        return [dict(zip(names, vals)) for vals in itertools.product(*(v for _, v in self.axes))]

    @property
    def size(self) -> int:
        return math.prod(len(v) for _, v in self.axes)


@dataclass(frozen=True)
class Case:
    """One reference case (frozen; all inputs SI).

    Attributes
    ----------
    id, title, kind, calculation : str
    area : str
        Report section, from the calculation (``"sweep"`` cases keep the calculation's area).
    source : Source
    inputs : dict
        SI inputs (defaults of the calculation filled in).
    raw_inputs : dict
        The inputs as written (unit strings), for the report.
    expected : tuple of Expectation
    sweep : Sweep or None
    fem : bool
        Finite-element case (skippable with ``--fem none``).
    fem_levels : tuple of str
        FE levels at which the case runs (default: quick and standard).
    path : str
        The file it came from.
    """

    id: str
    title: str
    kind: str
    calculation: str
    area: str
    source: Source
    inputs: dict
    raw_inputs: dict
    expected: tuple
    sweep: Sweep | None = None
    fem: bool = False
    fem_levels: tuple = _FEM_LEVELS
    notes: str = ""
    tags: tuple = ()
    path: str = ""

    @property
    def distributed(self) -> bool:
        """FE and sweep cases run through dask."""
        return self.fem or self.sweep is not None


# --------------------------------------------------------------------------- parsing helpers
def _err(where: str, msg: str) -> CaseFileError:
    return CaseFileError(f"{where}: {msg}")


def _quantity(value, dimension: str, where: str, *, allow_inf: bool = False) -> float:
    """Parse one value of the given dimension (unit string, or number if dimensionless)."""
    if dimension == "[force] / [length] ** 1.5":
        if isinstance(value, (int, float)):
            raise _err(where, f"give a unit with the number, e.g. '{value} N/m^1.5'")
        from ballrace.units import ureg
        try:
            return float(ureg().Quantity(str(value)).to("N/m**1.5").magnitude)
        except Exception as exc:
            raise _err(where, f"expected a stiffness in N/m^1.5, got {value!r} ({exc})") from None
    if dimension in ("", "dimensionless"):
        if isinstance(value, bool) or not isinstance(value, (int, float, str)):
            raise _err(where, f"expected a number, got {value!r}")
    try:
        return parse_quantity(value, dimension, where, allow_inf=allow_inf)
    except ValueError as exc:
        raise CaseFileError(str(exc)) from None


def _finite(value, dimension: str, where: str) -> float:
    """An expected value, tolerance or bound: a finite number (inf would never fail)."""
    v = _quantity(value, dimension, where)
    if not math.isfinite(v):
        raise _err(where, f"must be a finite number; got {value!r} (= {v!r} in SI units)")
    return v


def _param_value(p: registry.Param, value, where: str):
    if p.dimension == "str":
        if not isinstance(value, str):
            raise _err(where, f"expected text, got {value!r}")
        if p.choices and value not in p.choices:
            raise _err(where, f"must be one of {', '.join(map(repr, p.choices))}; got {value!r}")
        return value
    if p.dimension == "int":
        if isinstance(value, bool) or not isinstance(value, int):
            raise _err(where, f"expected an integer, got {value!r}")
        return value
    if p.dimension == "list":
        if not isinstance(value, list) or not all(
                isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
            raise _err(where, f"expected a list of numbers, got {value!r}")
        return tuple(float(v) for v in value)
    if p.dimension == "bool":
        if not isinstance(value, bool):
            raise _err(where, f"expected true or false, got {value!r}")
        return value
    return _quantity(value, p.dimension, where, allow_inf=p.allow_inf)


def _axis_values(p: registry.Param, spec, where: str) -> tuple:
    if isinstance(spec, dict):
        if len(spec) != 1 or next(iter(spec)) not in ("linspace", "logspace"):
            raise _err(where, "a sweep axis is a list or {linspace = [lo, hi, n]} or "
                              "{logspace = [lo_exponent, hi_exponent, n]}")
        (kind, args), = spec.items()
        if not (isinstance(args, list) and len(args) == 3 and isinstance(args[2], int)
                and args[2] >= 1):
            raise _err(where, f"{kind} takes [lo, hi, n] with an integer n >= 1; got {args!r}")
        import numpy as np

        if kind == "logspace":
            if p.dimension not in ("", "dimensionless"):
                raise _err(where, "logspace is for dimensionless inputs (exponents of 10)")
            return tuple(float(v) for v in np.logspace(float(args[0]), float(args[1]), args[2]))
        lo = _param_value(p, args[0], where + "[lo]")
        hi = _param_value(p, args[1], where + "[hi]")
        return tuple(float(v) for v in np.linspace(lo, hi, args[2]))
    if not isinstance(spec, list) or not spec:
        raise _err(where, "a sweep axis needs a non-empty list of values")
    return tuple(_param_value(p, v, f"{where}[{i}]") for i, v in enumerate(spec))


def _parse_expectation(name: str, spec, dimension: str, where: str) -> Expectation:
    if not isinstance(spec, dict):
        raise _err(where, "an expectation is a table {value = ..., rtol = ..., reason = ...}")
    unknown = set(spec) - _EXPECT_KEYS
    if unknown:
        raise _err(where, f"unknown field(s) {', '.join(sorted(unknown))}; allowed: "
                          f"{', '.join(sorted(_EXPECT_KEYS))}")
    reason = spec.get("reason")
    if not isinstance(reason, str) or not reason.strip():
        raise _err(where, "a tolerance needs a 'reason' (why this tolerance?)")
    has_value = "value" in spec
    has_bound = "max" in spec or "min" in spec
    if has_value == has_bound:
        raise _err(where, "give either 'value' (with 'rtol' and/or 'atol') or a bound "
                          "'max' and/or 'min'")
    if has_value:
        if "rtol" not in spec and "atol" not in spec:
            raise _err(where, "'value' needs a tolerance: 'rtol' and/or 'atol'")
        rtol = spec.get("rtol", 0.0)
        if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not 0 <= rtol < 1:
            raise _err(where + ".rtol", f"must be a number in [0, 1); got {rtol!r}")
        atol = (_finite(spec["atol"], dimension, where + ".atol") if "atol" in spec else 0.0)
        if atol < 0:
            raise _err(where + ".atol", f"must be >= 0; got {spec['atol']!r}")
        return Expectation(name=name, dimension=dimension, reason=reason.strip(),
                           value=_finite(spec["value"], dimension, where + ".value"),
                           rtol=float(rtol), atol=atol, text=str(spec["value"]))
    lo = _finite(spec["min"], dimension, where + ".min") if "min" in spec else None
    hi = _finite(spec["max"], dimension, where + ".max") if "max" in spec else None
    if lo is not None and hi is not None and lo > hi:
        raise _err(where, f"min must not exceed max; got min {spec['min']!r} > max {spec['max']!r}")
    text = " and ".join(x for x in (f">= {spec['min']}" if "min" in spec else "",
                                    f"<= {spec['max']}" if "max" in spec else "") if x)
    return Expectation(name=name, dimension=dimension, reason=reason.strip(), max=hi, min=lo,
                       text=text)


def _merge(defaults: dict, case: dict) -> dict:
    out = dict(defaults)
    for key, val in case.items():
        if key in ("inputs", "source") and isinstance(val, dict) and isinstance(out.get(key), dict):
            out[key] = {**out[key], **val}
        else:
            out[key] = val
    return out


def _parse_case(raw: dict, fname: str) -> Case:
    cid = raw.get("id")
    if not isinstance(cid, str) or not _ID_RE.match(cid):
        raise _err(fname, f"every case needs an 'id' of lowercase letters, digits, '.', '_' "
                          f"or '-'; got {cid!r}")
    where = f"{fname}: case {cid!r}"
    unknown = set(raw) - _CASE_KEYS
    if unknown:
        raise _err(where, f"unknown field(s) {', '.join(sorted(unknown))}")
    for key in ("title", "kind", "calculation", "source", "expected"):
        if key not in raw:
            raise _err(where, f"missing field '{key}'")
    if raw["kind"] not in KINDS:
        raise _err(where + ": kind", f"must be one of {', '.join(map(repr, KINDS))}; "
                                     f"got {raw['kind']!r}")
    try:
        calc = registry.get(raw["calculation"])
    except KeyError as exc:
        raise _err(where + ": calculation", exc.args[0]) from None

    src = raw["source"]
    if not isinstance(src, dict):
        raise _err(where + ": source", "must be a table {author, year, reference}")
    for key in ("author", "year", "reference"):
        if key not in src:
            raise _err(where + ": source", f"missing field '{key}' (author, year and the "
                                           "table/equation/example number)")
    if set(src) - _SOURCE_KEYS:
        raise _err(where + ": source", f"unknown field(s) {', '.join(sorted(set(src) - _SOURCE_KEYS))}")
    source = Source(**{k: src[k] for k in src})

    raw_inputs = dict(raw.get("inputs", {}))
    sweep_raw = dict(raw.get("sweep", {}))
    unknown = (set(raw_inputs) | set(sweep_raw)) - set(calc.inputs)
    if unknown:
        raise _err(where + ": inputs", f"unknown input(s) {', '.join(sorted(unknown))} for "
                                       f"{calc.name}; it takes {', '.join(calc.inputs)}")
    both = set(raw_inputs) & set(sweep_raw)
    if both:
        raise _err(where, f"input(s) {', '.join(sorted(both))} given both in inputs and sweep")
    inputs = {}
    for pname, p in calc.inputs.items():
        if pname in sweep_raw:
            continue
        if pname in raw_inputs:
            inputs[pname] = _param_value(p, raw_inputs[pname], f"{where}: inputs.{pname}")
        elif p.required:
            raise _err(where + ": inputs", f"missing input '{pname}' "
                                           f"({p.dimension or 'dimensionless'}) for {calc.name}")
        else:
            inputs[pname] = p.default

    outputs = dict(calc.outputs)
    sweep = None
    if sweep_raw:
        axes = tuple((n, _axis_values(calc.inputs[n], s, f"{where}: sweep.{n}"))
                     for n, s in sweep_raw.items())
        reduce_raw = raw.get("reduce")
        if not isinstance(reduce_raw, dict) or not reduce_raw:
            raise _err(where, "a sweep needs a [reduce] table: new_name = \"max_abs(output)\"")
        reds = []
        red_outputs = {}
        for new, spec in reduce_raw.items():
            m = re.fullmatch(r"\s*(\w+)\(\s*(\w+)\s*\)\s*", str(spec))
            if not m or m.group(1) not in _REDUCERS or m.group(2) not in calc.outputs:
                raise _err(f"{where}: reduce.{new}",
                           f"expected one of {', '.join(r + '(output)' for r in _REDUCERS)} with "
                           f"an output of {calc.name} ({', '.join(calc.outputs)}); got {spec!r}")
            reds.append((new, m.group(1), m.group(2)))
            red_outputs[new] = calc.outputs[m.group(2)]
        sweep = Sweep(axes=axes, reduce=tuple(reds))
        outputs = red_outputs
    elif "reduce" in raw:
        raise _err(where, "'reduce' only makes sense with a 'sweep'")

    exp_raw = raw["expected"]
    if not isinstance(exp_raw, dict) or not exp_raw:
        raise _err(where + ": expected", "needs at least one expected output")
    expected = []
    for name, spec in exp_raw.items():
        if name not in outputs:
            raise _err(f"{where}: expected.{name}",
                       f"{calc.name}{' (after reduce)' if sweep else ''} has no output {name!r}; "
                       f"outputs: {', '.join(outputs)}")
        expected.append(_parse_expectation(name, spec, outputs[name], f"{where}: expected.{name}"))

    levels = raw.get("fem_levels", list(_FEM_LEVELS))
    if not isinstance(levels, list) or not levels or set(levels) - set(_FEM_LEVELS):
        raise _err(where + ": fem_levels", f"a list from {_FEM_LEVELS}; got {levels!r}")
    if raw["kind"] == "FE check" and not calc.fem:
        raise _err(where, f"kind 'FE check' needs a finite-element calculation; {calc.name} is not")
    return Case(id=cid, title=str(raw["title"]), kind=raw["kind"], calculation=calc.name,
                area=calc.area, source=source, inputs=inputs, raw_inputs={**raw_inputs, **sweep_raw},
                expected=tuple(expected), sweep=sweep, fem=calc.fem, fem_levels=tuple(levels),
                notes=str(raw.get("notes", "")), tags=tuple(raw.get("tags", ())), path=fname)


def parse_cases(text: str, fname: str = "<string>") -> list[Case]:
    """Parse the text of a case file; :class:`CaseFileError` on any problem."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise _err(fname, f"not valid TOML: {exc}") from None
    unknown = set(data) - {"case", "defaults"}
    if unknown:
        raise _err(fname, f"unknown top-level key(s) {', '.join(sorted(unknown))}; a case file "
                          "holds [[case]] tables and an optional [defaults] table")
    cases = data.get("case")
    if not isinstance(cases, list) or not cases:
        raise _err(fname, "no [[case]] tables")
    defaults = data.get("defaults", {})
    return [_parse_case(_merge(defaults, c), fname) for c in cases]


def load_case_file(path) -> list[Case]:
    """Load and check one case file."""
    path = Path(path)
    return parse_cases(path.read_text(encoding="utf-8"), os.fspath(path))


def default_case_dir() -> Path:
    """The packaged case directory ``ballrace/validation/cases``."""
    return Path(str(resources.files("ballrace.validation") / "cases"))


def _case_files(pattern: str) -> list[Path]:
    """The case files of one ``--cases`` glob (files only: 'fem*' run from a checkout also
    matches the fem/ package folder), tried in the packaged case folder when a relative
    pattern matches nothing here."""
    files = sorted(Path(p) for p in _glob.glob(pattern) if os.path.isfile(p))
    if not files and not os.path.isabs(pattern):
        pat = pattern if pattern.endswith(".toml") else pattern + ".toml"
        files = sorted(default_case_dir().glob(pat))
    if not files:
        raise CaseFileError(f"--cases {pattern!r}: no case files match (looked in the "
                            f"working directory and {default_case_dir()})")
    return files


def load_cases(pattern=None) -> list[Case]:
    """Load every case file matching ``pattern`` (default: all packaged cases), sorted by path.

    The default selection leaves out the cases tagged :data:`ON_DEMAND`.

    ``pattern`` is a glob, or a list of globs (their files together, each once); a
    relative pattern that matches nothing in the working directory is tried inside the
    packaged case directory (``--cases 'hertz*'``).  Case ids must be unique.
    """
    if pattern is None or (not isinstance(pattern, str) and not pattern):
        pattern = None
        files = sorted(default_case_dir().glob("*.toml"))
    else:
        patterns = [pattern] if isinstance(pattern, str) else list(pattern)
        found = {f.resolve(): f for pat in patterns for f in _case_files(pat)}
        files = sorted(found.values())
    out: list[Case] = []
    seen: dict[str, str] = {}
    for f in files:
        for case in load_case_file(f):
            if case.id in seen:
                raise CaseFileError(f"{f}: case id {case.id!r} already used in {seen[case.id]}")
            seen[case.id] = os.fspath(f)
            if pattern is None and ON_DEMAND in case.tags:
                continue
            out.append(case)
    return out
