"""Figure data of the FE check for the report (computes; :mod:`ballrace.reports.plots` draws).

:func:`fem_figures` turns the FE sweep cases of a validation run (calculation
``fem.ball_on_race`` with ``[case.sweep]``, e.g. conformity x load x contact angle on
dask) into :class:`ballrace.validation.figures.Figure` objects: the signed FE-versus-Hertz
/ Lundberg–Palmgren error of a, b, p0, delta, tau0 and z0 against the conformity measure
a/(f D) (semi-major axis over groove radius, from the FE a), one series per conformity
f, contact angle and gap.  Hertz's half-space assumption degrades as a/(f D) grows
(docs/fem.md), so this is where the map shows it.  Without a run, or without sweep
points, the figure comes back with ``note`` set and no panels.

>>> fem_figures()[0].note.startswith("no FE sweep")
True
"""
from __future__ import annotations

import numpy as np

from .figures import Figure

__all__ = ["fem_figures", "sweep_series"]

#: (output key, panel title) of the error panels; keys missing from a run are skipped.
QUANTITIES = (("a_vs_hertz", "a"), ("b_vs_hertz", "b"), ("p_max_vs_hertz", "p0"),
              ("approach_vs_hertz", "approach delta"), ("tau0_vs_hertz", "LP tau0"),
              ("z0_vs_hertz", "LP depth z0"))

_ID = "fem-sweep-errors"
_SECTION = "fem"
_TITLE = "FE versus Hertz over conformity and load"


def sweep_series(points, key: str) -> list[dict]:
    """Lines of one error output against a/(f D), one per (race, f, contact angle, gap).

    Parameters
    ----------
    points : sequence of dict
        Sweep points of a ``fem.ball_on_race`` case (inputs and outputs, SI): needs
        ``ball_diameter`` [m], ``f_inner``/``f_outer`` [-], ``a`` [m], ``load`` [N]
        and ``key``.
    key : str
        Output to plot, e.g. ``"a_vs_hertz"`` (relative error [-]).

    Returns
    -------
    list of dict
        ``{"x": a/(f D) [-], "y": error [%], "label": str}``, x ascending.
    """
    groups: dict = {}
    for p in points:
        if key not in p or not np.isfinite(p.get(key, np.nan)):
            continue
        race = p.get("race", "inner")
        f = float(p["f_inner"] if race == "inner" else p["f_outer"])
        beta = float(np.degrees(p.get("contact_angle", 0.0)))
        gap = p.get("gap", "hertz")
        x = float(p["a"]) / (f * float(p["ball_diameter"]))
        groups.setdefault((race, f, beta, gap), []).append((x, 100.0 * float(p[key])))
    out = []
    # Hertz gap first, then the exact ('beyond Hertz') gap of the same geometry
    for (race, f, beta, gap), xy in sorted(groups.items(),
                                           key=lambda kv: (*kv[0][:3], kv[0][3] != "hertz")):
        xy.sort()
        label = f"{race}, f = {f:.3f}, {beta:.0f} deg" + ("" if gap == "hertz" else
                                                          f", {gap} gap")
        out.append({"x": np.array([v[0] for v in xy]), "y": np.array([v[1] for v in xy]),
                    "label": label})
    return out


def fem_figures(run=None) -> list[Figure]:
    """Error maps of the FE sweep cases in ``run`` (a :class:`validation.runner.Run`)."""
    pts, src = [], []
    for r in getattr(run, "results", ()) or ():
        if r.calculation == "fem.ball_on_race" and r.points:
            pts.extend(r.points)
            src.append(r.id)
    if not pts:
        return [Figure(_ID, _SECTION, _TITLE,
                       note="no FE sweep points in this run (the sweep cases of "
                            "validation/cases/fem.toml run with --fem quick)")]
    panels = []
    for key, title in QUANTITIES:
        series = sweep_series(pts, key)
        if series:
            panels.append({"kind": "lines", "title": title, "xlabel": "a / (f D)",
                           "ylabel": "FE - analytic [%]", "series": series})
    return [Figure(_ID, _SECTION, _TITLE,
                   caption="Signed relative error of the FE check against Hertz and "
                           "Lundberg-Palmgren over the conformity measure a/(f D) (semi-"
                           "major axis over groove radius), from the sweep case(s) "
                           f"{', '.join(src)} (each point an independent FE model on "
                           "dask).  The mesh level sets the discretisation error; a "
                           "growing trend with a/(f D) is the half-space assumption.",
                   panels=tuple(panels))]
