"""Figure data of the FE check for the report (computes; :mod:`ballrace.reports.plots` draws).

:func:`fem_figures` turns the FE sweep cases of a validation run (calculation
``fem.ball_on_race`` with ``[case.sweep]``, e.g. conformity x load x contact angle on
dask) into :class:`ballrace.validation.figures.Figure` objects: the signed FE-versus-Hertz
/ Lundberg–Palmgren error of a, b, p0, delta, tau0 and z0 against the conformity measure
a/(f D) (semi-major axis over groove radius, from the FE a), one series per conformity
f, contact angle and gap.  Hertz's half-space assumption degrades as a/(f D) grows
(docs/fem.md), so this is where the map shows it.  Without a run, or without sweep
points, the figure comes back with ``note`` set and no panels.

:func:`limits_figures` does the same for the "where Hertz holds" sweep
(``fem.hertz_limits``, validation/cases/fem_hertz_limits.toml, docs/fem-sweep.md): the
departure of the exact sphere–torus gap from Hertz's quadratic gap on the same mesh
(``*_beyond``) against a/(f D), one line per race and conformity, with the +/-1 % band
and the a/(f D) where the first line leaves it (:func:`one_percent_limit`), and beside it
the Hertz-gap errors (the discretisation error) with the level's tolerance.

>>> fem_figures()[0].note.startswith("no FE sweep")
True
>>> pts = [{"race": "inner", "f": 0.52, "a_over_fD": s, "a_beyond": -0.16 * s * s}
...        for s in (0.1, 0.2, 0.3)]
>>> round(one_percent_limit(pts, "a_beyond")[0], 4)   # 0.16 s^2 = 1 % at s = 0.25
0.25
"""
from __future__ import annotations

import math

import numpy as np

from .figures import Figure

__all__ = ["fem_figures", "sweep_series", "limits_figures", "limits_series",
           "one_percent_limit", "roller_figures", "roller_panels"]

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
    """Error maps of the FE sweep cases in ``run`` (a :class:`validation.runner.Run`): the
    ``fem.ball_on_race`` sweeps, then the Hertz-limits figures (:func:`limits_figures`),
    then one figure per FE roller case (:func:`roller_figures`)."""
    return _sweep_figures(run) + limits_figures(run) + roller_figures(run)


def _sweep_figures(run) -> list[Figure]:
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


# --------------------------------------------------------------------------- Hertz limits
#: (output stem, panel title) of the Hertz-limits panels (outputs ``stem_beyond``,
#: ``stem_vs_hertz`` of ``fem.hertz_limits``).
LIMIT_PANELS = (("a", "a"), ("b", "b"), ("p_max", "p0"), ("approach", "delta"),
                ("tau0", "LP tau0"), ("z0", "LP depth z0"))
#: ISO 76 static-rating contact stress of ball bearings [Pa] (marked on the load panel).
STATIC_RATING_STRESS = 4.2e9
_LIMITS_ID = "fem-hertz-limits"
#: One colour per conformity (colour-blind-safe sequence), cycled.
_F_COLOURS = ("#0072B2", "#009E73", "#E69F00", "#CC79A7", "#D55E00", "#56B4E9", "#000000")


def limits_series(points, key: str, scale: float = 100.0) -> list[dict]:
    """Lines of one ``fem.hertz_limits`` output against a/(f D), one per (race, f).

    Parameters
    ----------
    points : sequence of dict
        Sweep points (inputs and outputs): ``race``, ``f`` [-], ``a_over_fD`` [-], ``key``.
    key : str
        Output, e.g. ``"a_beyond"`` (relative difference [-]).
    scale : float
        Factor applied to the values (100: per cent) [-].

    Returns
    -------
    list of dict
        ``{"x": a/(f D) [-], "y": value x scale, "label", "color", "style"}``; inner race
        solid with dots, outer race dashed with squares, one colour per f; x ascending.
    """
    groups: dict = {}
    for p in points:
        v = p.get(key, np.nan)
        if v is None or not np.isfinite(v):
            continue
        groups.setdefault((p.get("race", "inner"), float(p["f"])), []).append(
            (float(p["a_over_fD"]), scale * float(v)))
    fs = sorted({f for _, f in groups})
    out = []
    for (race, f), xy in sorted(groups.items()):
        xy.sort()
        out.append({"x": np.array([v[0] for v in xy]), "y": np.array([v[1] for v in xy]),
                    "label": f"{race}, f = {f:.3f}",
                    "color": _F_COLOURS[fs.index(f) % len(_F_COLOURS)],
                    "style": "markers" if race == "inner" else "dashed-markers"})
    return out


def one_percent_limit(points, key: str, level: float = 0.01) -> tuple[float, str]:
    """Largest a/(f D) below which every (race, f) line of ``key`` stays within ``level``.

    Along each line (ascending a/(f D)) the first crossing of ``|value| = level`` is
    interpolated between the last point inside and the first outside, linearly in
    (a/(f D))² (the departure of the exact gap grows as (a/(f D))², docs/fem-sweep.md, so a
    pure square law is recovered exactly); the limit is the smallest crossing over the
    lines.

    Parameters
    ----------
    points : sequence of dict
        ``fem.hertz_limits`` sweep points (``race``, ``f``, ``a_over_fD``, ``key``).
    key : str
        Output, e.g. ``"a_beyond"`` [-].
    level : float
        Bound on ``|value|`` [-] (0.01: 1 %).

    Returns
    -------
    (float, str)
        The limit a/(f D) [-] (NaN without data) and its text: ``"0.22"``, ``"< 0.1"``
        (already outside at the smallest a/(f D) swept) or ``"> 0.6"`` (never outside).
    """
    lines = limits_series(points, key, scale=1.0)
    if not lines:
        return math.nan, "n/a"
    lo = min(float(s["x"][0]) for s in lines)
    hi = max(float(s["x"][-1]) for s in lines)
    best = math.inf
    for s in lines:
        x, y = s["x"], np.abs(s["y"])
        out = np.nonzero(y >= level)[0]
        if not out.size:
            continue
        i = int(out[0])
        if i == 0:
            return float(x[0]), f"< {x[0]:.2g}"
        x0, x1, y0, y1 = x[i - 1] ** 2, x[i] ** 2, y[i - 1], y[i]
        best = min(best, float(np.sqrt(x0 + (level - y0) / (y1 - y0) * (x1 - x0))))
    if best == math.inf:
        return math.nan, f"> {hi:.2g}"
    return best, f"{best:.2f}" if best >= lo else f"< {lo:.2g}"


def _tolerances(level: str) -> dict:
    try:
        from ballrace.fem import TOLERANCES
    except ImportError:  # pragma: no cover - fem is part of the package
        return {}
    return TOLERANCES.get(level, {})


def limits_figures(run=None) -> list[Figure]:
    """The "where Hertz holds" figures of the ``fem.hertz_limits`` cases in ``run``."""
    pts, src = [], []
    for r in getattr(run, "results", ()) or ():
        if r.calculation == "fem.hertz_limits" and r.points:
            pts.extend(r.points)
            src.append(r.id)
    title = "Where Hertz holds: exact sphere-torus gap against Hertz's gap"
    if not pts:
        return [Figure(_LIMITS_ID, _SECTION, title,
                       note="no Hertz-limits sweep in this run (it is long and runs on "
                            "demand: make validate-sweep, docs/fem-sweep.md)")]
    level = getattr(run, "fem", "quick")
    limits, beyond, errors = [], [], []
    for i, (stem, name) in enumerate(LIMIT_PANELS):
        series = limits_series(pts, f"{stem}_beyond")
        if not series:
            continue
        x1, text = one_percent_limit(pts, f"{stem}_beyond")
        limits.append(f"{name} {text}")
        beyond.append({"kind": "lines", "title": f"{name}: within 1 % below a/(fD) = {text}",
                       "xlabel": "a / (f D)", "ylabel": "exact / Hertz-gap FE - 1 [%]",
                       "series": series, "hband": 1.0,
                       "vlines": [{"x": x1}] if np.isfinite(x1) else [],
                       "legend": "best" if i == 0 else "none"})
        tol = _tolerances(level).get(stem)
        err = {"kind": "lines", "title": f"{name}: Hertz-gap error ({level} mesh)",
               "xlabel": "a / (f D)", "ylabel": "FE - analytic [%]",
               "series": limits_series(pts, f"{stem}_vs_hertz"),
               "legend": "best" if i == 0 else "none"}
        if tol:
            err["hband"] = 100.0 * tol
        errors.append(err)
    p0 = limits_series(pts, "p_max_hertz", scale=1e-9)
    load = {"kind": "lines", "title": "Hertz p0 of the points (dashed: 4.2 GPa, ISO 76)",
            "xlabel": "a / (f D)",
            "ylabel": "p0 [GPa]", "series": p0, "legend": "none",
            "hlines": [{"y": STATIC_RATING_STRESS * 1e-9,
                        "label": "4.2 GPa (ISO 76 static rating)"}]}
    where = ", ".join(src)
    size = (14.0, 7.4)
    return [
        Figure(_LIMITS_ID, _SECTION, title, panels=tuple(beyond) + (load,), size=size,
               caption="Half-space FE models of a ball in a race groove (inner race: dots, "
                       "solid; outer race: squares, dashed; one colour per conformity f) "
                       "with the exact sphere-torus gap against the same model with Hertz's "
                       "quadratic gap on the same mesh, so the discretisation error cancels "
                       "and the geometric departure from Hertz is left.  Grey: +/-1 %; "
                       "dotted line: the a/(f D) (semi-major axis over groove radius) where "
                       "the first line leaves it.  Half-space Hertz is good to 1 % below "
                       f"a/(f D) = {'; '.join(limits)}.  Last panel: the Hertz p0 of each "
                       "point and the ISO 76 static-rating stress 4.2 GPa.  Case(s) "
                       f"{where}, --fem {level}."),
        Figure(_LIMITS_ID + "-discretisation", _SECTION,
               "Where Hertz holds: the Hertz-gap errors (discretisation) of the same sweep",
               panels=tuple(errors), size=size,
               caption="The Hertz-gap FE against the analytic Hertz / Lundberg-Palmgren "
                       "values at the same points: the mesh's discretisation error, which "
                       "the self-similar Hertz-gap problem keeps independent of the load; "
                       f"grey: the {level} level's tolerance (fem.TOLERANCES)."),
    ]


# --------------------------------------------------------------------------- rollers
_ROLLER_CAPTION = (
    "A profiled roller on a flat raceway, FE (ballrace.fem.roller_contact, half-space mode: "
    "a rigid roller on one elastic block longer than the roller, so its end is a real "
    "edge) against line_contact (the strip method on the half-space).  Left: the pressure "
    "along the half roller from its centre - the FE peak over the rolling direction at "
    "the pressure nodes (graded towards the end), the FE pressure averaged over each of "
    "line_contact's slices, and line_contact's slice pressures; right: the load each "
    "slice carries.  The picture (pyvista, off-screen) shows the raceway under the roller "
    "cut open at the section under the roller axis and at mid-length, coloured by the FE "
    "von Mises stress (the axis along the roller drawn compressed), above the pressure "
    "along the whole roller.")
_TILTED_CAPTION = (
    "A profiled roller tilted about the rolling direction on a flat raceway, FE "
    "(ballrace.fem.roller_contact, half-space mode, the half model: the whole length, "
    "both roller ends resolved) against line_contact at the same tilt (the strip method "
    "on the half-space; a positive tilt puts the end at +x in).  Left: the pressure along "
    "the whole roller - the FE peak over the rolling direction at the pressure nodes, the "
    "FE pressure averaged over each of line_contact's slices, and line_contact's slice "
    "pressures; right: the load each slice carries.  The picture (pyvista, off-screen) "
    "shows the raceway under the roller cut open at the section under the roller axis "
    "over the whole length, seen from the more loaded end, coloured by the FE von Mises "
    "stress (the axis along the roller drawn compressed), above the pressure along the "
    "roller.")


def _steps(x, y, width):
    """Step-line coordinates of slice values ``y`` centred at ``x`` of ``width`` [any]
    (the slices of a half roller, all ``x >= 0``, start at its centre 0)."""
    xs, ys = [], []
    floor = 0.0 if min(x, default=0.0) >= 0 else -math.inf
    for xc, v in zip(x, y):
        lo = max(xc - 0.5 * width, floor)
        xs += [lo, xc + 0.5 * width]
        ys += [v, v]
    return xs, ys


def roller_panels(series: dict) -> tuple:
    """The two panels of a roller case's figure from its ``series`` (SI; the outputs of
    :func:`ballrace.validation.calc_fem_roller.roller_outputs`): the pressure along the roller
    [MPa] and the slice loads [N] against x [mm].

    Examples
    --------
    >>> s = {"x": [0.0, 1e-3, 2e-3], "pressure": [1e9, 1e9, 1.2e9], "slice_x": [0.0, 1e-3],
    ...      "slice_pressure": [1e9, 1.1e9], "slice_loads": [100.0, 90.0],
    ...      "line_x": [0.0, 1e-3], "line_pressure": [1e9, 1.05e9],
    ...      "line_slice_loads": [101.0, 91.0], "length": [4e-3], "slice_width": [1e-3]}
    >>> p, q = roller_panels(s)
    >>> [x["label"].split(":")[0] for x in p["series"]], p["vlines"][0]["x"]
    (['FE', 'FE', 'line_contact (slices)'], 2.0)
    >>> q["series"][1]["y"]
    [101.0, 91.0]
    """
    mm, mpa = 1e3, 1e-6
    w = float(series["slice_width"][0]) * mm
    half = 0.5 * float(series["length"][0]) * mm
    # the half model (a tilt) spans the whole length: both roller ends marked
    ends = [{"x": -half}, {"x": half}] if min(series["x"]) < 0 else [{"x": half}]
    sx = [v * mm for v in series["slice_x"]]
    lx = [v * mm for v in series["line_x"]]
    fx, fy = _steps(sx, [v * mpa for v in series["slice_pressure"]], w)
    ax_, ay_ = _steps(lx, [v * mpa for v in series["line_pressure"]], w)
    pressure = {"kind": "lines", "title": "pressure along the roller", "width": 1.4,
                "xlabel": "x from the roller centre [mm]", "ylabel": "pressure [MPa]",
                "series": [{"x": [v * mm for v in series["x"]],
                            "y": [v * mpa for v in series["pressure"]],
                            "label": "FE: peak over y at the nodes", "style": "markers"},
                           {"x": fx, "y": fy, "label": "FE: slice average", "color": "C1"},
                           {"x": ax_, "y": ay_, "label": "line_contact (slices)",
                            "style": "dashed", "color": "k"}],
                "vlines": ends, "legend": "below"}
    loads = {"kind": "lines", "title": "slice loads", "xlabel": "slice centre x [mm]",
             "ylabel": "load per slice [N]",
             "series": [{"x": sx, "y": [float(v) for v in series["slice_loads"]],
                         "label": "FE", "style": "markers"},
                        {"x": lx, "y": [float(v) for v in series["line_slice_loads"]],
                         "label": "line_contact", "style": "dashed-markers", "color": "k"}],
             "vlines": ends, "legend": "below"}
    return pressure, loads


def roller_figures(run=None) -> list[Figure]:
    """One figure per FE roller case of ``run`` (calculation ``fem.roller_contact``,
    validation/cases/fem_roller.toml): :func:`roller_panels` and the case's picture
    (:func:`ballrace.fem.render.render_roller`); the edge peak of the run is written in the
    caption, checked or not as the case says.  No roller case in the run: no figure."""
    figs, seen = [], False
    for r in getattr(run, "results", ()) or ():
        if r.calculation != "fem.roller_contact":
            continue
        seen = True
        s = getattr(r, "series", None) or {}
        if "x" not in s:
            continue
        o = r.outputs
        edge = ""
        if "edge_pressure" in o:
            edge = (f"  This run's edge peak: the largest nodal FE pressure in the outer half "
                    f"{o['edge_pressure'] / 1e9:.3g} GPa at x = {o.get('x_edge', math.nan) * 1e3:.3g}"
                    f" mm; line_contact's largest slice pressure "
                    f"{o.get('max_pressure_line', math.nan) / 1e9:.3g} GPa"
                    + (" - reported, not checked (see the case notes)."
                       if "straight" in r.id else "."))
        imgs = tuple(tuple(a) for a in r.artifacts if a[1])
        note = "; ".join(a[0] for a in r.artifacts if not a[1])
        tilt = float((s.get("tilt") or [0.0])[0])
        if tilt:
            end = "+x" if o.get("loaded_end", 1.0) > 0 else "-x"
            edge += (f"  Tilt {tilt * 1e3:.3g} mrad: the loaded end at {end}; its outer "
                     f"quarter (|x| >= L/4) carries {o.get('end_quarter_load', math.nan):.4g} N "
                     f"in the FE, {o.get('end_quarter_load_line', math.nan):.4g} N in "
                     f"line_contact ({100 * o.get('end_quarter_load_vs_line', math.nan):+.2f} %).")
        figs.append(Figure(f"fem-roller-{r.id}", _SECTION,
                           f"FE roller against line_contact: {r.title}",
                           caption=(_TILTED_CAPTION if tilt else _ROLLER_CAPTION) + edge,
                           panels=roller_panels(s),
                           images=imgs, note=note, size=(11.0, 3.6)))
    if seen and not figs:
        return [Figure("fem-roller", _SECTION, "FE roller against line_contact",
                       note="omitted: no FE roller case ran (--fem none, module missing or "
                            "another level)")]
    return figs
