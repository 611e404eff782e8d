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
           "ENGINEERING_UNITS", "engineering_unit", "format_eng", "scheduler_text"]

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


def _number(x: float) -> str:
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 1e7:
        return f"{x:.6g}"
    m, e = f"{x:.4e}".split("e")
    return f"{float(m):.4g}×10{str(int(e)).translate(_SUPERSCRIPT)}"


def format_eng(v, dimension: str = "", reference: float | None = None) -> str:
    """One SI value in engineering units, unit appended (``—`` for None).

    >>> format_eng(2.29953e9, "[pressure]"), format_eng(0.7740, "[angle]")
    ('2299.53 MPa', '44.3469 deg')
    >>> format_eng(1.9e-7, "[length]"), format_eng(3e-12, "")
    ('0.19 µm', '3×10⁻¹²')
    """
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "—" if v is None else str(v)
    unit, factor = engineering_unit(dimension, v if reference is None else reference)
    return f"{_number(v * factor)} {unit}".strip()


def _reference(c) -> float | None:
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


def _name_unit(c) -> str:
    if not c.dimension:
        for suffix, unit in NAME_UNITS:
            if c.name.endswith(suffix):
                return unit
    return ""


def _cfmt_text(c, what: str) -> str:
    s = format_eng(getattr(c, what), c.dimension, _reference(c))
    unit = _name_unit(c)
    return f"{s} {unit}" if unit and s != "—" else s


def _cfmt(c, what: str):
    """A value of comparison ``c`` ("expected", "got", "minimum", "maximum") in its unit."""
    return _nowrap(_cfmt_text(c, what))


def _err_text(c) -> str:
    if c.error is None:
        return "—"
    if c.rel_error is not None and c.expected is not None:
        return f"{100 * c.rel_error:+.2g} %"
    unit = _name_unit(c)
    if c.expected is None:
        s = format_eng(-c.error, c.dimension, _reference(c))
    else:
        s = format_eng(c.error, c.dimension, _reference(c))
        s = s if s.startswith("-") else "+" + s
    return f"{s} {unit}" if unit else s


def _err(c):
    """The error cell: a signed difference, or the margin to a bound (the word may wrap,
    the number never does)."""
    from markupsafe import Markup

    text = _err_text(c)
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


_E_NUMBER = re.compile(r"[^\s<>]*\d[eE][-+]\d+[^\s<>]*")


def _prose(text):
    """Prose (reasons, notes, sources): numbers in e-notation kept whole ("1.4e-5" would
    otherwise break after its hyphen in print)."""
    from markupsafe import Markup, escape

    text = "" if text is None else str(text)
    out, last = [], 0
    for m in _E_NUMBER.finditer(text):
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
