"""Data for the report's figures, computed from the library and from a run's results.

This module computes; :mod:`ballrace.reports.plots` only draws.  Each figure is a
:class:`Figure` of one or more panels; a panel is a plain dict ("lines" or "contour")
of numpy arrays and labels.  A figure whose library module is missing comes back as
a Figure with ``note`` set and no panels, so the report shows why it is absent instead
of crashing.

>>> figs = hertz_figures()
>>> [f.id for f in figs][:1], bool(figs[0].panels)
(['hertz-pressure'], True)
"""
from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Figure", "all_figures", "hertz_figures", "subsurface_figures", "bearing_figures",
           "overview_figure", "subsurface_fields"]

log = logging.getLogger(__name__)

_STEEL = dict(E=200e9, nu=0.3)


@dataclass(frozen=True)
class Figure:
    """One report figure (frozen): ``panels`` to draw, or a ``note`` saying why not."""

    id: str
    section: str
    title: str
    caption: str = ""
    panels: tuple = ()
    note: str = ""
    images: tuple = ()          # (label, path) of ready-made PNGs (FE renders)


def _missing(fid, section, title, exc) -> Figure:
    return Figure(fid, section, title, note=f"omitted: {exc}")


# --------------------------------------------------------------------------- hertz
def hertz_figures(run=None) -> list[Figure]:
    """Pressure profiles of three contacts and the error maps of the simplified formulas."""
    try:
        from ballrace import Material
        from ballrace.analytic import hertz
    except ImportError as exc:  # pragma: no cover - hertz is always there
        return [_missing("hertz-pressure", "hertz", "Hertz pressure profiles", exc)]
    steel = Material(**_STEEL)
    D = 12.7e-3
    contacts = {
        "ball on plane": hertz.point_contact(2000.0, D / 2, D / 2, math.inf, math.inf, steel),
        "209 inner race": hertz.point_contact(2000.0, D / 2, D / 2, 26.15e-3, -0.52 * D, steel),
        "209 outer race": hertz.point_contact(2000.0, D / 2, D / 2, -38.85e-3, -0.52 * D, steel),
    }
    px, py = [], []
    for name, c in contacts.items():
        ax, ay = float(c.semi_axis_x), float(c.semi_axis_y)
        x = np.linspace(-1.2 * ax, 1.2 * ax, 241)
        y = np.linspace(-1.2 * ay, 1.2 * ay, 241)
        px.append({"x": x * 1e3, "y": np.asarray(c.pressure(x, 0.0)) / 1e9, "label":
                   f"{name}: p0 = {float(c.p_max) / 1e9:.2f} GPa, b = {ax * 1e3:.3f} mm"})
        py.append({"x": y * 1e3, "y": np.asarray(c.pressure(0.0, y)) / 1e9, "label":
                   f"{name}: a = {ay * 1e3:.3f} mm"})
    lc = hertz.line_contact(35e6, 0.05, math.inf, Material(E=70e9, nu=0.3),
                            Material(E=210e9, nu=0.3))
    xl = np.linspace(-1.2 * float(lc.b), 1.2 * float(lc.b), 241)
    figs = [Figure("hertz-pressure", "hertz", "Hertz pressure profiles (12.7 mm steel ball, 2000 N)",
                   caption="Pressure across the rolling direction x (left) and along the "
                           "transverse direction y (middle); the groove conformity spreads the "
                           "contact along y and lowers p0.  Right: NAFEMS D3613 line contact.",
                   panels=({"kind": "lines", "title": "along x (rolling)", "xlabel": "x [mm]",
                            "ylabel": "p [GPa]", "series": px},
                           {"kind": "lines", "title": "along y (transverse)", "xlabel": "y [mm]",
                            "ylabel": "p [GPa]", "series": py},
                           {"kind": "lines", "title": "NAFEMS D3613 line contact",
                            "xlabel": "x [mm]", "ylabel": "p [MPa]",
                            "series": [{"x": xl * 1e3, "y": np.asarray(lc.pressure(xl)) / 1e6,
                                        "label": f"p0 = {float(lc.p_max) / 1e6:.0f} MPa, "
                                                 f"b = {float(lc.b) * 1e3:.3f} mm"}]}))]
    figs.append(_error_map(run))
    return figs


def _error_map(run) -> Figure:
    """Signed error of the simplified formulas against alpha_r: from the sweep cases if they
    ran, else computed here."""
    from ballrace.analytic import hertz

    series = {}
    src = "computed for the report"
    if run is not None:
        for r in run.results:
            if r.calculation == "hertz.approximation_error" and r.points:
                m = r.points[0].get("method", r.id)
                series[m] = {k: np.array([p[k] for p in r.points], dtype=float)
                             for k in r.points[0] if isinstance(r.points[0][k], float)}
                src = "from the sweep cases (dask)"
    if not series:
        alpha = np.logspace(0, 4, 121)
        for m in hertz.METHODS[1:]:
            e = hertz.approximation_errors(alpha, m)
            series[m] = {"alpha_r": alpha, **{f"err_{q}": v for q, v in e.items()}}
    panels = []
    for m, d in sorted(series.items()):
        bounds = hertz.APPROXIMATION_ERROR[m][100.0]
        panels.append({"kind": "lines", "title": m, "xlabel": "radius ratio alpha_r = Ry/Rx",
                       "ylabel": "relative error [%]", "logx": True,
                       "series": [{"x": d["alpha_r"], "y": 100 * d[f"err_{q}"], "label": q}
                                  for q in ("k", "ellipk", "ellipe", "a", "b", "approach",
                                            "p_max")],
                       "vlines": [{"x": 100.0, "label": "fit range limit (alpha_r = 100)"}],
                       "hband": 100 * max(bounds.values())})
    return Figure("hertz-error-map", "hertz", "Error of the simplified Hertz formulas",
                  caption=f"Signed relative error against the exact solution ({src}); the "
                          "grey band is the largest documented bound up to alpha_r = 100.",
                  panels=tuple(panels))


# --------------------------------------------------------------------------- subsurface
def subsurface_fields(contact, nu: float = 0.3, n: int = 121, depth: float = 3.0):
    """Max shear, von Mises and orthogonal shear under ``contact`` in the plane y = 0.

    Returns ``(x, z, fields)`` with x, z in units of the semi-axis along x and
    ``fields = {"tau_max", "von_mises", "tau_xz"}`` in units of p_max, evaluated with
    :func:`ballrace.analytic.subsurface.stress` (ImportError when it is missing).
    """
    from ballrace.analytic import subsurface

    bx = float(contact.semi_axis_x)
    x = np.linspace(-2.0, 2.0, n)
    z = np.linspace(1e-3, depth, n)
    X, Z = np.meshgrid(x, z)
    s = subsurface.stress(contact, X * bx, 0.0 * X, Z * bx, nu=nu)
    comps = _components(s)
    p0 = float(contact.p_max)
    sig = np.array([[comps["xx"], comps["xy"], comps["xz"]],
                    [comps["xy"], comps["yy"], comps["yz"]],
                    [comps["xz"], comps["yz"], comps["zz"]]])
    sig = np.moveaxis(sig, (0, 1), (-2, -1))
    ev = np.linalg.eigvalsh(sig)
    tau = 0.5 * (ev[..., -1] - ev[..., 0])
    vm = np.sqrt(0.5 * ((ev[..., 0] - ev[..., 1]) ** 2 + (ev[..., 1] - ev[..., 2]) ** 2
                        + (ev[..., 2] - ev[..., 0]) ** 2))
    return x, z, {"tau_max": tau / p0, "von_mises": vm / p0, "tau_xz": comps["xz"] / p0}


def _components(s) -> dict:
    """Stress components from whatever ``subsurface.stress`` returns (object, dict or array)."""
    names = {"xx": ("sxx", "sigma_xx", "s_xx", "xx"), "yy": ("syy", "sigma_yy", "s_yy", "yy"),
             "zz": ("szz", "sigma_zz", "s_zz", "zz"), "xy": ("sxy", "tau_xy", "s_xy", "xy"),
             "yz": ("syz", "tau_yz", "s_yz", "yz"), "xz": ("sxz", "tau_xz", "s_xz", "xz")}
    out = {}
    for k, alts in names.items():
        for a in alts:
            v = s.get(a) if isinstance(s, dict) else getattr(s, a, None)
            if v is not None:
                out[k] = np.asarray(v, dtype=float)
                break
        else:
            if isinstance(s, np.ndarray) and s.shape[-2:] == (3, 3):
                i, j = "xyz".index(k[0]), "xyz".index(k[1])
                out[k] = s[..., i, j]
            else:
                raise TypeError(f"cannot find stress component {k} in {type(s).__name__}")
    return out


def subsurface_figures() -> list[Figure]:
    """Depth profiles and contour maps under a circular and a 209-inner-race contact."""
    title = "Subsurface stresses"
    try:
        from ballrace import Material
        from ballrace.analytic import hertz, subsurface
    except ImportError as exc:
        return [_missing("subsurface", "subsurface", title, exc)]
    try:
        steel = Material(**_STEEL)
        D = 12.7e-3
        figs = []
        for fid, name, c in (
                ("subsurface-circle", "ball on plane (circle)",
                 hertz.point_contact(2000.0, D / 2, D / 2, math.inf, math.inf, steel)),
                ("subsurface-209", "209 inner race (k = 9.3)",
                 hertz.point_contact(2000.0, D / 2, D / 2, 26.15e-3, -0.52 * D, steel))):
            x, z, f = subsurface_fields(c)
            mid = len(x) // 2
            mx = subsurface.max_shear(c)
            o = subsurface.orthogonal_shear(c)
            b = float(c.semi_axis_x)
            depth_mx = float(mx.depth) / b
            depth_o = float(o.z0) / b
            prof = {"kind": "lines", "title": f"{name}: on the axis / at x0",
                    "xlabel": "stress / p0", "ylabel": "depth z / b", "invert_y": True,
                    "series": [{"x": f["tau_max"][:, mid], "y": z, "label": "max shear (Tresca)"},
                               {"x": f["von_mises"][:, mid], "y": z, "label": "von Mises"},
                               {"x": np.max(np.abs(f["tau_xz"]), axis=1), "y": z,
                                "label": "|tau_xz| max over x (orthogonal shear)"}],
                    "hlines": [{"y": depth_mx, "label": f"max shear depth {depth_mx:.3f} b"},
                               {"y": depth_o, "label": f"LP z0 = {depth_o:.3f} b"}]}
            maps = [{"kind": "contour", "title": lab, "x": x, "y": z, "field": f[key],
                     "xlabel": "x / b", "ylabel": "z / b", "invert_y": True,
                     "cmap": "RdBu_r" if key == "tau_xz" else "viridis",
                     "markers": [{"x": 0.0, "y": depth_mx, "label": "max shear"}]
                     if key != "tau_xz" else
                     [{"x": float(o.x0) / b, "y": depth_o, "label": "+tau0"},
                      {"x": -float(o.x0) / b, "y": depth_o, "label": "-tau0"}]}
                    for key, lab in (("tau_max", "max shear / p0"), ("von_mises", "von Mises / p0"),
                                     ("tau_xz", "orthogonal shear tau_xz / p0"))]
            figs.append(Figure(fid, "subsurface", f"Subsurface stresses: {name}",
                               caption="Plane y = 0 through the contact centre (x rolling, "
                                       "z depth, both over the semi-axis b along x); depths of "
                                       "the maxima marked.",
                               panels=(prof, *maps)))
        return figs
    except Exception as exc:  # noqa: BLE001 - a figure must never break the report
        log.warning("subsurface figures failed: %s", exc, exc_info=True)
        return [_missing("subsurface", "subsurface", title, f"{type(exc).__name__}: {exc}")]


# --------------------------------------------------------------------------- bearing
def bearing_figures(run) -> list[Figure]:
    """Ball loads and contact angles around the bearing from the cases that returned series."""
    figs = []
    if run is None:
        return figs
    for r in run.results:
        s = getattr(r, "series", None) or {}
        if "psi" not in s or "Q" not in s:
            continue
        psi = np.degrees(np.asarray(s["psi"], dtype=float))
        psi = (psi + 180.0) % 360.0 - 180.0
        order = np.argsort(psi)
        panels = [{"kind": "lines", "title": "ball loads", "xlabel": "azimuth psi [deg]",
                   "ylabel": "Q [N]", "markers_only": True,
                   "series": [{"x": psi[order], "y": np.asarray(s["Q"])[order], "label": "Q"}]}]
        if "beta" in s:
            panels.append({"kind": "lines", "title": "contact angles",
                           "xlabel": "azimuth psi [deg]", "ylabel": "beta [deg]",
                           "markers_only": True,
                           "series": [{"x": psi[order],
                                       "y": np.degrees(np.asarray(s["beta"]))[order],
                                       "label": "beta"}]})
        figs.append(Figure(f"bearing-{r.id}", "bearing", f"Load distribution: {r.title}",
                           caption=f"Case {r.id} ({r.status}).", panels=tuple(panels)))
    if not figs:
        figs.append(Figure("bearing", "bearing", "Load distribution",
                           note="omitted: no bearing case produced a load distribution in this "
                                "run (module missing or cases not selected)"))
    return figs


def fem_figures(run) -> list[Figure]:
    """FE renders written by the FE cases (PNG paths)."""
    if run is None:
        return []
    imgs = tuple((f"{r.id}: {label}", path) for r in run.results for label, path in r.artifacts)
    fem_ran = any(r.area == "fem" and r.status in ("pass", "fail") for r in run.results)
    if not imgs:
        why = ("the FE cases wrote no renders" if fem_ran else
               "no FE case ran (--fem none, module missing or not selected)")
        return [Figure("fem-renders", "fem", "FE renders", note=f"omitted: {why}")]
    return [Figure("fem-renders", "fem", "FE renders", images=imgs,
                   caption="pyvista renders of the FE solutions (fem.render).")]


def overview_figure(run) -> Figure:
    """|error| / allowed for every value check of the run (log scale; < 1 passes)."""
    labels, ratio, ok = [], [], []
    for r in run.results:
        for c in r.comparisons:
            if c.allowed and c.error is not None:
                labels.append(f"{r.id}:{c.name}")
                ratio.append(max(abs(c.error) / c.allowed, 1e-6))
                ok.append(c.passed)
    if not labels:
        return Figure("overview", "summary", "Error against tolerance", note="no value checks ran")
    return Figure("overview", "summary", "Error against tolerance",
                  caption="Each bar is one expected value: |got - expected| / allowed.  Below 1 "
                          "passes; bars far below 1 mean a generous tolerance or an exact match.",
                  panels=({"kind": "bars", "labels": labels, "values": np.array(ratio),
                           "ok": np.array(ok), "logx": True, "xlabel": "|error| / allowed",
                           "line": 1.0},))


def all_figures(run) -> list[Figure]:
    """Every report figure for ``run`` (sections: summary, hertz, subsurface, bearing, fem)."""
    figs = [overview_figure(run)]
    for fn in (lambda: hertz_figures(run), subsurface_figures, lambda: bearing_figures(run),
               lambda: fem_figures(run)):
        try:
            figs.extend(fn())
        except Exception as exc:  # noqa: BLE001 - never let a figure break the report
            log.warning("figure generation failed: %s", exc, exc_info=True)
            figs.append(Figure("figure-error", "summary", "A figure failed",
                               note=f"omitted: {type(exc).__name__}: {exc}"))
    return figs
