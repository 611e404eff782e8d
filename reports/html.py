"""The validation report: one self-contained HTML file and ``results.json``.

:func:`write_report` renders ``templates/report.html.j2`` with jinja2 (autoescape on),
embeds every image as a base64 data URI (so the HTML can be mailed or archived alone),
and writes ``results.json`` with the same numbers in SI units.  ``results.json`` also
embeds a regression snapshot, so it can be passed back as ``--baseline``.
"""
from __future__ import annotations

import json
import logging
import math
import time
from pathlib import Path

__all__ = ["results_dict", "write_results", "render_html", "write_report", "AREA_TITLES"]

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
            "artifacts": [list(a) for a in r.artifacts],
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


def _fmt(v, dimension="") -> str:
    from ballrace.validation.schema import format_value

    if v is None:
        return "—"
    return format_value(v, dimension)


def _err(c) -> str:
    if c.error is None:
        return "—"
    if c.rel_error is not None and c.expected is not None:
        return f"{100 * c.rel_error:+.3g} %"
    if c.expected is None:
        return f"margin {_fmt(-c.error, c.dimension)}"
    return _fmt(c.error, c.dimension)


def render_html(run, *, drift=None, plots: bool = True) -> str:
    """The report as one HTML string (images inlined)."""
    import jinja2

    from ballrace.validation.environment import environment

    from . import plots as pl

    figures = []
    if plots:
        from ballrace.validation.figures import all_figures

        for f in all_figures(run):
            uri, note = None, f.note
            if f.panels:
                try:
                    uri = pl.png_data_uri(pl.render_png(f))
                except Exception as exc:  # noqa: BLE001 - a broken plot must not sink the report
                    log.warning("figure %s failed to draw: %s", f.id, exc, exc_info=True)
                    note = f"omitted: drawing failed ({type(exc).__name__}: {exc})"
            images = [(label, pl.file_data_uri(p)) for label, p in f.images]
            figures.append({"id": f.id, "section": f.section, "title": f.title,
                            "caption": f.caption, "uri": uri, "note": note,
                            "images": [(lab, u) for lab, u in images if u]})
    areas = []
    by_area = run.by_area()
    order = list(AREA_TITLES) + sorted(set(by_area) - set(AREA_TITLES))
    for area in order:
        rows = by_area.get(area, [])
        figs = [f for f in figures if f["section"] == area]
        if not rows and not figs:
            continue
        areas.append({"id": area, "title": AREA_TITLES.get(area, area), "results": rows,
                      "counts": {s: sum(r.status == s for r in rows)
                                 for s in ("pass", "fail", "error", "missing", "skipped")},
                      "figures": figs})
    env = jinja2.Environment(loader=jinja2.PackageLoader("ballrace.reports", "templates"),
                             autoescape=jinja2.select_autoescape(["html", "j2"],
                                                                 default_for_string=True,
                                                                 default=True),
                             undefined=jinja2.StrictUndefined)
    env.filters["fmt"] = _fmt
    env.filters["err"] = _err
    tpl = env.get_template("report.html.j2")
    return tpl.render(run=run, counts=run.counts, areas=areas, env=environment(),
                      summary_figs=[f for f in figures if f["section"] == "summary"],
                      drift=drift, plots=plots,
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
