"""The validation report: one self-contained HTML file and ``results.json``.

:func:`write_report` renders ``templates/report.html.j2`` with jinja2 (autoescape on),
embeds every image as a base64 data URI (so the HTML can be mailed or archived alone),
and writes ``results.json`` with the same numbers in SI units.  The HTML shows values
in engineering units (:data:`ENGINEERING_UNITS`: mm, µm, MPa, N, deg, ...), one unit per
check so expected and computed values read side by side.  ``results.json`` also
embeds a regression snapshot, so it can be passed back as ``--baseline``.
"""
from __future__ import annotations

import json
import logging
import math
import re
import time
from pathlib import Path

__all__ = ["results_dict", "write_results", "render_html", "write_report", "AREA_TITLES",
           "ENGINEERING_UNITS", "engineering_unit", "format_eng", "tolerance_text",
           "scheduler_text"]

log = logging.getLogger(__name__)

RESULTS_FORMAT = "ballrace-results/1"

#: Report section titles, in display order.
AREA_TITLES = {
    "hertz": "Hertz contact",
    "subsurface": "Subsurface stresses",
    "bearing": "Bearing geometry and load distribution",
    "life": "Ratings and life",
    "ehl": "Elastohydrodynamic film",
    "kinematics": "Kinematics and defect frequencies",
    "highspeed": "High speed: centrifugal force, gyroscopic moment, Jones equilibrium",
    "shaft": "Shafts on their bearings",
    "roller": "Roller bearings and the finite line contact",
    "fem": "Finite-element checks",
}


def _num(v):
    return None if v is None or (isinstance(v, float) and not math.isfinite(v)) else v


def results_dict(run, drift=None) -> dict:
    """Everything of a run as plain JSON-able data (SI units)."""
    from ballrace.validation import baseline as bl
    from ballrace.validation.environment import environment

    cases = []
    for r in run.results:
        cases.append({
            "id": r.id, "title": r.title, "area": r.area, "kind": r.kind,
            "calculation": r.calculation, "source": r.source, "status": r.status,
            "message": r.message, "duration_s": r.duration, "inputs": r.inputs,
            "notes": r.notes,
            "outputs": {k: _num(v) for k, v in r.outputs.items()},
            "comparisons": [{"name": c.name, "dimension": c.dimension, "got": _num(c.got),
                             "expected": c.expected, "min": c.minimum, "max": c.maximum,
                             "error": _num(c.error), "rel_error": _num(c.rel_error),
                             "allowed": c.allowed, "tolerance": c.tolerance, "reason": c.reason,
                             "passed": c.passed} for c in r.comparisons],
            "points": list(r.points), "series": r.series,
            "pictures": [a[0] for a in r.artifacts],   # embedded in index.html
        })
    out = {
        "format": RESULTS_FORMAT,
        "summary": {**run.counts, "total": len(run.results), "ok": run.ok, "fem": run.fem,
                    "duration_s": run.duration, "scheduler": run.scheduler,
                    "started": time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(run.started))},
        "environment": environment(),
        "cases": cases,
        "baseline": {"format": bl.FORMAT, "created": time.strftime("%Y-%m-%d %H:%M:%S"),
                     "fem": run.fem, "values": bl.snapshot(run)},
    }
    if drift is not None:
        out["baseline_comparison"] = {
            "path": drift.path, "ok": drift.ok, "checked": drift.n_checked,
            "new_cases": list(drift.new_cases),
            "moved": [m.__dict__ for m in drift.moved]}
    return out


def write_results(run, outdir, drift=None) -> Path:
    """Write ``results.json`` into ``outdir``."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    path = outdir / "results.json"
    path.write_text(json.dumps(results_dict(run, drift), indent=1) + "\n", encoding="utf-8")
    return path


#: Engineering display units per dimension: ``(smallest |SI value|, unit, SI -> unit factor)``,
#: first match wins (the reference value of a check picks one unit for all its numbers).
ENGINEERING_UNITS = {
    "[length]": ((1.0, "m", 1.0), (1e-4, "mm", 1e3), (1e-8, "µm", 1e6), (0.0, "nm", 1e9)),
    "[pressure]": ((1e10, "GPa", 1e-9), (1e5, "MPa", 1e-6), (0.0, "Pa", 1.0)),
    "[force]": ((1e6, "kN", 1e-3), (0.0, "N", 1.0)),
    "[angle]": ((0.0, "deg", 180.0 / math.pi),),
    "[time]": ((3.6e5, "h", 1.0 / 3600.0), (0.1, "s", 1.0), (0.0, "ms", 1e3)),
    "[mass] / [length] / [time]": ((0.0, "mPa·s", 1e3),),
    "1 / [pressure]": ((0.0, "1/GPa", 1e9),),
    "[force] / [length]": ((0.0, "N/mm", 1e-3),),
    "[force] / [length] ** 1.5": ((0.0, "N/mm^1.5", 1e-3 ** 1.5),),
    "1 / [length]": ((0.0, "1/mm", 1e-3),),
    "[length] / [time]": ((0.0, "m/s", 1.0),),
    "1 / [time]": ((0.0, "rpm", 60.0 / (2.0 * math.pi)),),
    "[force] * [length]": ((0.0, "N·m", 1.0),),
    "[mass]": ((0.1, "kg", 1.0), (0.0, "g", 1e3)),
    "[length] ** 2 / [time]": ((0.0, "mm²/s", 1e6),),      # kinematic viscosity, mm²/s = cSt
    "[temperature]": ((0.0, "K", 1.0),),                   # a temperature difference
    "1 / [temperature]": ((0.0, "1/K", 1.0),),
    "[mass] / [length] ** 3": ((0.0, "kg/m³", 1.0),),
}


def engineering_unit(dimension: str, reference: float | None = None) -> tuple[str, float]:
    """``(unit, factor)`` to show SI values of ``dimension`` in: value_shown = factor * SI.

    >>> engineering_unit("[length]", 1.5e-4), engineering_unit("[pressure]", 2.3e9)
    (('mm', 1000.0), ('MPa', 1e-06))
    >>> engineering_unit("", 0.5)
    ('', 1.0)
    """
    ref = abs(reference) if reference is not None and math.isfinite(reference) else 0.0
    for floor, unit, factor in ENGINEERING_UNITS.get(dimension, ()):
        if ref >= floor or floor == 0.0:
            return unit, factor
    return "", 1.0


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _number(x: float, digits: int = 6) -> str:
    """``x`` to ``digits`` significant digits, plain from 1e-3 to 1e7, else as ``m×10ⁿ``
    (at most 4 digits in m); never Python's ``1e-08``.

    >>> _number(1234567.0), _number(5.729578e-08, 3), _number(-1.4e-8, 2), _number(1112.06, 3)
    ('1234570', '5.73×10⁻⁸', '-1.4×10⁻⁸', '1110')
    """
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 1e7:
        s = f"{x:.{digits}g}"
        if "e" not in s:
            return s
        return f"{round(x, digits - 1 - math.floor(math.log10(abs(x)))):.0f}"
    sig = min(digits, 4)
    m, e = f"{x:.{sig - 1}e}".split("e")
    return f"{float(m):.{sig}g}×10{str(int(e)).translate(_SUPERSCRIPT)}"


def format_eng(v, dimension: str = "", reference: float | None = None,
               digits: int = 6) -> str:
    """One SI value in engineering units, unit appended (``—`` for None).

    >>> format_eng(2.29953e9, "[pressure]"), format_eng(0.7740, "[angle]")
    ('2299.53 MPa', '44.3469 deg')
    >>> format_eng(1.9e-7, "[length]"), format_eng(3e-12, "")
    ('0.19 µm', '3×10⁻¹²')
    >>> format_eng(2.0123e-5, "[length] ** 2 / [time]")      # kinematic viscosity
    '20.123 mm²/s'
    """
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "—" if v is None else str(v)
    unit, factor = engineering_unit(dimension, v if reference is None else reference)
    return f"{_number(v * factor, digits)} {unit}".strip()


#: Significant digits of a tolerance (a tolerance is a judgement, not a measurement).
TOLERANCE_DIGITS = 3


def tolerance_text(exp, got: float | None = None) -> str:
    """The tolerance of expectation ``exp`` as people read it: absolute tolerances and
    bounds in the engineering unit its values are shown in (the unit the first nonzero of
    value, max, min, ``got`` picks, as in the report's columns), tolerances to
    :data:`TOLERANCE_DIGITS` significant digits, tiny or huge ones as ``m×10ⁿ``.

    ``exp`` needs ``name``, ``dimension``, ``value``, ``rtol``, ``atol``, ``min``, ``max``
    (SI), like :class:`ballrace.validation.schema.Expectation`.

    >>> from types import SimpleNamespace as E
    >>> tolerance_text(E(name="beta", dimension="[angle]", value=0.7, rtol=1e-6, atol=1e-9,
    ...                  min=None, max=None))
    '±1×10⁻⁶ rel + ±5.73×10⁻⁸ deg'
    >>> tolerance_text(E(name="preload", dimension="[force]", value=None, rtol=0, atol=0,
    ...                  min=100.0, max=None))
    '>= 100 N'
    """
    ref = next((v for v in (exp.value, exp.max, exp.min, got)
                if v is not None and math.isfinite(v) and v != 0), None)
    unit = name_unit(exp)

    def eng(v, digits):
        s = format_eng(v, exp.dimension, ref, digits)
        return f"{s} {unit}" if unit else s

    if exp.value is None:
        parts = []
        if exp.min is not None:
            parts.append(f">= {eng(exp.min, 6)}")
        if exp.max is not None:
            parts.append(f"<= {eng(exp.max, 6)}")
        return " and ".join(parts)
    parts = []
    if exp.rtol:
        parts.append(f"±{_number(exp.rtol, TOLERANCE_DIGITS)} rel")
    if exp.atol:
        parts.append(f"±{eng(exp.atol, TOLERANCE_DIGITS)}")
    return " + ".join(parts) or "exact"


def reference_value(c) -> float | None:
    """The value that sets the engineering prefix of comparison ``c``'s numbers (the first
    finite non-zero of expected, maximum, minimum, got), or None."""
    for v in (c.expected, c.maximum, c.minimum, c.got):
        if v is not None and math.isfinite(v) and v != 0:
            return v
    return None


#: Units of dimensionless outputs that are counts of a unit, by the end of their name
#: (``L10h_hours`` is a number of hours, ``L10_Mrev`` of millions of revolutions).
NAME_UNITS = (("_hours", "h"), ("_Mrev", "Mrev"), ("_percent", "%"))


def _nowrap(text: str):
    """A number with its unit as one unbreakable piece of HTML (never split across lines)."""
    from markupsafe import Markup, escape

    return Markup('<span class="n">') + escape(text) + Markup("</span>")


def name_unit(c) -> str:
    """The unit a dimensionless output counts, from the end of its name (NAME_UNITS)."""
    if not c.dimension:
        for suffix, unit in NAME_UNITS:
            if c.name.endswith(suffix):
                return unit
    return ""


def _cfmt_text(c, what: str) -> str:
    s = format_eng(getattr(c, what), c.dimension, reference_value(c))
    unit = name_unit(c)
    return f"{s} {unit}" if unit and s != "—" else s


def _cfmt(c, what: str):
    """A value of comparison ``c`` ("expected", "got", "minimum", "maximum") in its unit."""
    return _nowrap(_cfmt_text(c, what))


def error_text(c) -> str:
    """The error of comparison ``c`` as text: a relative error in %, else a signed
    difference (or the margin to a bound) in the output's unit."""
    if c.error is None:
        return "—"
    if c.rel_error is not None and c.expected is not None:
        s = _number(100 * c.rel_error, 2)
        return f"{s if s.startswith('-') else '+' + s} %"
    unit = name_unit(c)
    if c.expected is None:
        s = format_eng(-c.error, c.dimension, reference_value(c))
    else:
        s = format_eng(c.error, c.dimension, reference_value(c), 3)   # a difference: 3 digits
        s = s if s.startswith("-") else "+" + s
    return f"{s} {unit}" if unit else s


def _err(c):
    """The error cell: a signed difference, or the margin to a bound (the word may wrap,
    the number never does)."""
    from markupsafe import Markup

    text = error_text(c)
    if c.error is not None and c.expected is None and not (
            c.rel_error is not None and c.expected is not None):
        return Markup("margin ") + _nowrap(text)
    return _nowrap(text)


def _tol(text: str):
    """A tolerance text: each of its terms unbreakable ("±5.73×10⁻⁸ deg + ±1e-6 rel")."""
    from markupsafe import Markup

    parts = [p for p in str(text).split(" ") if p]
    out, cur = [], []
    for p in parts:                       # keep number and unit together, split at the joiners
        if p in ("+", "and") and cur:
            out.append(" ".join(cur))
            out.append(p)
            cur = []
        else:
            cur.append(p)
    if cur:
        out.append(" ".join(cur))
    return Markup(" ").join(_nowrap(o) if o not in ("+", "and") else o for o in out)


#: Units that follow a number in prose ("1 % of P", "0.75 N m", "8 um", "68 mm^2/s").
_PROSE_UNITS = (r"(?:%|deg(?:C|/s)?|°C?|rad(?:/s)?|[µu]rad|arcsec|[µu]m|nm|mm(?:\^2/s|²/s)?"
                r"|m(?:/s|\^2/s|²/s)?|kN(?:/mm)?|N(?:/mm| m|·m|\*m)?|[kMG]?Pa(?:\*s|·s)?|cSt"
                r"|lbf?|in|psi|rpm|r/min|Hz|h|s|ms|K|kg(?:/m\^3|/m³)?|g|Mrev|rev)")
#: A number with a unit (and a relation sign before it) or a number in e-notation (whose
#: hyphen a browser would break after): each is one unbreakable piece of prose.
_PROSE_NUMBER = re.compile(
    r"(?:(?:<=|>=|[<>≤≥~≈±])\s?)?(?<![\w.])[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
    r"\s" + _PROSE_UNITS + r"(?![\w/^²³])"
    r"|[^\s<>]*\d[eE][-+]\d+[^\s<>]*(?:\s" + _PROSE_UNITS + r"(?![\w/^²³]))?")


def _prose(text):
    """Prose (reasons, notes, sources, titles, captions): a number and its unit kept
    together ("49.3 %", "< 0.5 N"), numbers in e-notation kept whole ("1.4e-5" would
    otherwise break after its hyphen in print)."""
    from markupsafe import Markup, escape

    text = "" if text is None else str(text)
    out, last = [], 0
    for m in _PROSE_NUMBER.finditer(text):
        out.append(escape(text[last:m.start()]))
        out.append(_nowrap(m.group(0)))
        last = m.end()
    out.append(escape(text[last:]))
    return Markup("").join(out)


def _wbr(name: str):
    """A quantity name that may wrap after its underscores, and only there."""
    from markupsafe import Markup, escape

    return Markup("_<wbr>").join(escape(p) for p in str(name).split("_"))


def scheduler_text(scheduler: str) -> str:
    """The scheduler without a local dask address (``tcp://127.0.0.1:...``, ``inproc://``).

    >>> scheduler_text("dask inproc://192.0.2.2/8907/1 (1 worker(s), 2 thread(s))")
    'dask, local (1 worker(s), 2 thread(s))'
    >>> scheduler_text("dask tcp://cluster.example:8786 (4 worker(s), 8 thread(s))")
    'dask tcp://cluster.example:8786 (4 worker(s), 8 thread(s))'
    """
    import re

    local = r"(inproc://\S+|tcp://(127\.0\.0\.1|localhost|\[::1\]):\d+)"
    return re.sub(r"\s*" + local, ", local", scheduler or "serial")


def _figure_entries(run) -> list[dict]:
    from ballrace.validation.figures import all_figures

    from . import plots as pl

    out = []
    for f in all_figures(run):
        uri, note = None, f.note
        if f.panels:
            try:
                uri = pl.png_data_uri(pl.render_png(f))
            except Exception as exc:  # noqa: BLE001 - a broken plot must not sink the report
                log.warning("figure %s failed to draw: %s", f.id, exc, exc_info=True)
                note = f"omitted: drawing failed ({type(exc).__name__}: {exc})"
        images = [(label, pl.file_data_uri(p)) for label, p in f.images]
        out.append({"id": f.id, "section": f.section, "title": f.title, "caption": f.caption,
                    "uri": uri, "note": note, "images": [(lab, u) for lab, u in images if u]})
    return out


def render_html(run, *, drift=None, plots: bool = True) -> str:
    """The report as one HTML string (images inlined)."""
    import jinja2

    from ballrace.validation.environment import environment

    figures = _figure_entries(run) if plots else []
    areas = []
    by_area = run.by_area()
    extra = sorted((set(by_area) | {f["section"] for f in figures}) - set(AREA_TITLES)
                   - {"summary"})
    for area in list(AREA_TITLES) + extra:
        rows = by_area.get(area, [])
        figs = [f for f in figures if f["section"] == area]
        if not rows and not figs:
            continue
        ratios = [abs(c.error) / c.allowed for r in rows for c in r.comparisons
                  if c.allowed and c.error is not None]
        areas.append({"id": area, "title": AREA_TITLES.get(area, area), "results": rows,
                      "counts": {s: sum(r.status == s for r in rows)
                                 for s in ("pass", "fail", "error", "missing", "skipped")},
                      "n_checks": sum(len(r.comparisons) for r in rows),
                      "worst": max(ratios) if ratios else None,
                      "work": sum(r.duration for r in rows), "figures": figs})
    env = jinja2.Environment(loader=jinja2.PackageLoader("ballrace.reports", "templates"),
                             autoescape=jinja2.select_autoescape(["html", "j2"],
                                                                 default_for_string=True,
                                                                 default=True),
                             undefined=jinja2.StrictUndefined)
    env.filters["fmt"] = format_eng
    env.filters["cfmt"] = _cfmt
    env.filters["err"] = _err
    env.filters["tol"] = _tol
    env.filters["wbr"] = _wbr
    env.filters["prose"] = _prose
    tpl = env.get_template("report.html.j2")
    return tpl.render(run=run, counts=run.counts, areas=areas, env=environment(),
                      summary_figs=[f for f in figures if f["section"] == "summary"],
                      drift=drift, plots=plots, scheduler=scheduler_text(run.scheduler),
                      work=sum(r.duration for r in run.results),
                      started=time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(run.started)))


def write_report(run, outdir, *, baseline=None, plots: bool = True) -> Path:
    """Write ``index.html`` and ``results.json`` into ``outdir``; returns the HTML path."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    write_results(run, outdir, baseline)
    html = render_html(run, drift=baseline, plots=plots)
    path = outdir / "index.html"
    path.write_text(html, encoding="utf-8")
    return path
