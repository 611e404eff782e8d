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

__all__ = ["Figure", "FIGURE_SOURCES", "all_figures", "hertz_figures", "subsurface_figures",
           "bearing_figures", "fem_figures", "overview_figure", "subsurface_fields"]

log = logging.getLogger(__name__)

_STEEL = dict(E=200e9, nu=0.3)


@dataclass(frozen=True)
class Figure:
    """One report figure (frozen): ``panels`` to draw, or a ``note`` saying why not.

    ``section`` is the report section it appears in: an area id ("hertz", "fem", ...,
    or a new one) or ``"summary"`` for the top of the report.  Panels are plain dicts
    drawn by :func:`ballrace.reports.plots.render_png`: ``kind`` "lines", "contour",
    "bars" or "strip", with an optional ``width`` ratio.
    """

    id: str
    section: str
    title: str
    caption: str = ""
    panels: tuple = ()
    note: str = ""
    images: tuple = ()          # (label, path) of ready-made PNGs (FE pictures)
    size: tuple = ()            # (width, height) [in] to draw the panels at; () = automatic


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
#: Where a bearing case's expected values sit in its plots: output name -> (panel,
#: azimuth rule).  Ball numbering follows ``validation.calc_bearing``: ball 1 on the load
#: line (psi[0]), ball 2 next (psi[1]), ball 3 its mirror (psi[-1]).
_PUBLISHED_AT = {"Q_1": ("Q", "first"), "Q_2": ("Q", "second"), "Q_3": ("Q", "last"),
                 "Q_max": ("Q", "max"), "Q": ("Q", "all"), "beta_0": ("beta", 0.0),
                 "beta_180": ("beta", 180.0), "contact_angle": ("beta", "all")}


def _published_points(r, psi, Q) -> dict:
    """Expected (published) values of a case placed at their azimuths [deg], per panel."""
    out = {"Q": ([], []), "beta": ([], [])}
    idx = {"first": 0, "second": 1 % len(psi), "last": -1, "max": int(np.argmax(Q))}
    for c in getattr(r, "comparisons", ()):
        where = _PUBLISHED_AT.get(c.name)
        if where is None or c.expected is None:
            continue
        panel, rule = where
        v = math.degrees(c.expected) if panel == "beta" else c.expected
        if rule == "all":
            out[panel + "_level"] = v         # the same value at every ball: drawn as a line
            continue
        elif isinstance(rule, float):
            xs = [rule]
        else:
            xs = [psi[idx[rule]]]
        out[panel][0].extend(xs)
        out[panel][1].extend([v] * len(xs))
    return out


def _published_series(pub: dict, panel: str, kind: str = "published") -> list:
    out = []
    what = "published (case file)" if kind == "published" else f"expected ({kind})"
    if pub[panel][0]:
        out.append({"x": np.array(pub[panel][0]), "y": np.array(pub[panel][1]),
                    "label": what, "style": "published"})
    if panel + "_level" in pub:
        v = pub[panel + "_level"]
        out.append({"x": np.array([-180.0, 180.0]), "y": np.array([v, v]),
                    "label": f"{what}: {v:.4g} at every ball", "style": "published-level"})
    return out


def _jones_curve(r, psi_sorted, Q_sorted):
    """Jones's closed-form distribution at the case's clearance, or None.

    Stribeck-Jones load zone: Q(psi) = Q_max [(cos psi - c)/(1 - c)]^1.5 for
    cos psi > c, with c = P_d / (2 delta_r) (the load zone 1 - (1 - cos psi)/(2 eps),
    2 eps = 1 - P_d / (2 delta_r)) and Q_max = Z_w F_r / Z (Hamrock & Dowson 1981, ch. 3:
    load zone eqs. (3.39)-(3.44), Z_w eq. (3.45)); Z_w F_r / Z is computed as
    Q_max Z_w / (Z Q_max / F_r) from the case's outputs.
    """
    o = getattr(r, "outputs", {}) or {}
    zw, ratio, dr = o.get("jones_zw"), o.get("zq_ratio"), o.get("radial_deflection")
    if not zw or not ratio or not dr or not (math.isfinite(zw) and dr > 0):
        return None
    raw = (r.inputs or {}).get("clearance", (r.inputs or {}).get("diametral_clearance", 0.0))
    try:
        from ballrace.units import to_si

        pd = to_si(raw, "[length]", "clearance") if isinstance(raw, str) else float(raw)
    except Exception:  # noqa: BLE001 - the overlay is optional
        return None
    c = pd / (2.0 * dr)
    q_max = float(np.max(Q_sorted)) * zw / ratio
    psi = np.linspace(-180.0, 180.0, 721)
    base = np.clip((np.cos(np.radians(psi)) - c) / (1.0 - c), 0.0, None)
    return {"x": psi, "y": q_max * base ** 1.5,
            "label": f"Jones's Z_w = {zw:.3f}: Q_max = Z_w F_r / Z, Stribeck load zone",
            "style": "dashed"}


def bearing_figures(run) -> list[Figure]:
    """Ball loads (and contact angles, when they vary) around the bearing, with the published
    values the case checks plotted at their balls."""
    figs = []
    if run is None:
        return figs
    for r in run.results:
        s = getattr(r, "series", None) or {}
        if "psi" not in s or "Q" not in s:
            continue
        element = "roller" if r.calculation.startswith("roller.") else "ball"
        psi = np.degrees(np.asarray(s["psi"], dtype=float))
        psi = (psi + 180.0) % 360.0 - 180.0
        Q = np.asarray(s["Q"], dtype=float)
        pub = _published_points(r, psi, Q)
        if np.any(np.isclose(psi, -180.0)):   # the element at psi = 180 deg shows at both ends
            k = int(np.argmin(np.abs(psi + 180.0)))
            psi, Q = np.append(psi, 180.0), np.append(Q, Q[k])
            if "beta" in s:
                s = {**s, "beta": np.append(np.asarray(s["beta"], dtype=float), s["beta"][k])}
        order = np.argsort(psi)
        q_series = [{"x": psi[order], "y": Q[order], "label": f"ballrace (per {element})",
                     "style": "markers"}]
        jones = _jones_curve(r, psi[order], Q[order])
        if jones is not None:
            q_series.append(jones)
        q_series += _published_series(pub, "Q", r.kind)
        panels = [{"kind": "lines", "title": f"{element} loads", "xlabel": "azimuth psi [deg]",
                   "ylabel": "Q [N]", "series": q_series, "xticks": [-180, -90, 0, 90, 180],
                   "legend": "below"}]
        caption = f"Case {r.id} ({r.status}); psi = 0 on the load line."
        if "beta" in s:
            beta = np.degrees(np.asarray(s["beta"], dtype=float))
            if np.ptp(beta) > 1e-6 or pub["beta"][0] or "beta_level" in pub:
                b_series = [{"x": psi[order], "y": beta[order],
                             "label": f"ballrace (per {element})",
                             "style": "markers"}, *_published_series(pub, "beta", r.kind)]
                panels.append({"kind": "lines", "title": "contact angles",
                               "xlabel": "azimuth psi [deg]", "ylabel": "beta [deg]",
                               "series": b_series, "xticks": [-180, -90, 0, 90, 180],
                               "legend": "below"})
            else:
                caption += (f" Contact angle {beta[0]:.3g} deg at every {element} (not "
                            "plotted).")
        if pub["Q"][0] or pub["beta"][0] or "Q_level" in pub or "beta_level" in pub:
            caption += (f" Red: the {'published ' if r.kind == 'published' else ''}values "
                        f"the case checks (open markers at their {element}s; a dotted line "
                        f"when the value holds at every {element}).")
        if jones is not None:
            caption += (" Dashed: Jones's closed-form distribution at the same clearance "
                        "ratio.")
        figs.append(Figure(f"bearing-{r.id}", "roller" if element == "roller" else "bearing",
                           f"Load distribution: {r.title}",
                           caption=caption, panels=tuple(panels), size=(5.0 * len(panels), 3.6)))
    if not any(f.section == "bearing" for f in figs):
        figs.append(Figure("bearing", "bearing", "Load distribution",
                           note="omitted: no bearing case produced a load distribution in this "
                                "run (module missing or cases not selected)"))
    return figs


# --------------------------------------------------------------------------- fem
_FEM_CAPTION = ("Section y = 0 through the contact (x rolling, depth z down; the FE quarter "
                "model mirrored).  Left to right: the FE field, the analytic Hertz field "
                "(ballrace.analytic.subsurface.stress) on the same points and colour scale, "
                "their difference FE - analytic, and both along depth.  Open circles mark the "
                "analytic maxima (for tau_xz the Lundberg-Palmgren points +-x0, z0), crosses "
                "the FE maxima.  The 3-D picture (pyvista, off-screen) shows the FE von Mises "
                "stress in the lower body near the contact, the quarter model mirrored with "
                "the quadrant towards the viewer cut away, the FE mesh drawn faintly, the "
                "Hertz ellipse in red and the analytic and FE depths of the maximum on the "
                "axis.")


_FEM_TRACTION_CAPTION = (
    "Section y = 0 through the contact (x rolling, depth z down), loaded by the normal "
    "pressure and a tangential traction q = mu p along +x, so the field is not symmetric in "
    "x and the section is the FE's own (not mirrored).  Left to right: the FE field, the "
    "analytic field with the same traction (ballrace.analytic.subsurface.stress(..., "
    "traction=mu)) on the same points and colour scale, their difference FE - analytic, "
    "and both along depth.  Open circles mark the analytic maxima, crosses the FE maxima.")


def _is_traction(r) -> bool:
    return "traction" in (getattr(r, "title", "") or "") or "traction" in (r.id or "")


def fem_figures(run) -> list[Figure]:
    """One figure per FE case: the pictures its calculation drew (``fem.render``)."""
    if run is None:
        return []
    figs = []
    for r in run.results:
        if not r.artifacts or getattr(r, "calculation", "") == "fem.roller_contact":
            continue                                              # figures_fem draws it
        imgs = tuple(tuple(a) for a in r.artifacts if a[1])
        note = "; ".join(a[0] for a in r.artifacts if not a[1])   # a picture not drawn
        caption = _FEM_TRACTION_CAPTION if _is_traction(r) else _FEM_CAPTION
        figs.append(Figure(f"fem-{r.id}", "fem", f"FE against analytic: {r.title}",
                           caption=caption, images=imgs, note=note))
    if not figs:
        fem_cases = [getattr(r, "calculation", "") for r in run.results if r.area == "fem"]
        if fem_cases and set(fem_cases) == {"fem.roller_contact"}:
            return []                         # roller cases only: figures_fem draws them
        fem_ran = any(r.area == "fem" and r.status in ("pass", "fail") for r in run.results)
        why = ("the FE cases wrote no pictures" if fem_ran else
               "no FE case ran (--fem none, module missing or not selected)")
        return [Figure("fem-renders", "fem", "FE against analytic", note=f"omitted: {why}")]
    return figs


# --------------------------------------------------------------------------- overview
#: Floor of |error|/allowed on the log axis (exact matches are drawn here).
RATIO_FLOOR = 1e-6


def _checks(run):
    """(area, case id, quantity, |error|/allowed, passed) of every value check."""
    for r in run.results:
        for c in r.comparisons:
            if c.allowed and c.error is not None:
                yield r.area, r.id, c.name, max(abs(c.error) / c.allowed, RATIO_FLOOR), c.passed


def overview_figure(run, *, worst: int = 20) -> Figure:
    """|error| / allowed of every value check: one row of dots per area, and the ``worst``
    checks by name (log scale; below 1 passes)."""
    rows = list(_checks(run))
    if not rows:
        return Figure("overview", "summary", "Error against tolerance", note="no value checks ran")
    areas = list(dict.fromkeys(a for a, *_ in rows))
    strip = {"kind": "strip", "title": f"all {len(rows)} value checks, by area",
             "rows": [f"{a} ({sum(x[0] == a for x in rows)})" for a in areas],
             "values": [np.array([x[3] for x in rows if x[0] == a]) for a in areas],
             "ok": [np.array([x[4] for x in rows if x[0] == a]) for a in areas],
             "logx": True, "xlabel": "|error| / allowed", "line": 1.0, "width": 1.15}
    top = sorted(rows, key=lambda x: -x[3])[:worst]
    bars = {"kind": "bars", "title": f"the {len(top)} checks closest to their tolerance",
            "labels": [f"{cid}: {q}" for _, cid, q, _, _ in top],
            "values": np.array([x[3] for x in top]), "ok": np.array([x[4] for x in top]),
            "logx": True, "xlabel": "|error| / allowed", "line": 1.0, "width": 1.0}
    n_bad = sum(not x[4] for x in rows)
    return Figure("overview", "summary", "Error against tolerance",
                  caption="Each mark is one expected value: |got - expected| / allowed, where "
                          "allowed is the case's tolerance.  Below 1 passes (green), above 1 "
                          f"fails (red; {n_bad} here).  Marks far below 1 mean an exact match "
                          f"or a generous tolerance; exact matches sit at {RATIO_FLOOR:g}.",
                  panels=(strip, bars), size=(13.0, max(3.2, 0.36 * max(len(areas), 11))))


# --------------------------------------------------------------------------- registry
#: Figure sources, in report order: ``"module:function"``, each ``function(run)`` returning
#: a Figure or a list of Figures.  A figure module of another area plugs in with one line;
#: a source whose module is missing shows as a note in the report instead of failing it.
FIGURE_SOURCES = [
    "ballrace.validation.figures:overview_figure",
    "ballrace.validation.figures:hertz_figures",
    "ballrace.validation.figures:subsurface_figures",
    "ballrace.validation.figures:bearing_figures",
    "ballrace.validation.figures:fem_figures",
    "ballrace.validation.figures_life:life_figures",
    "ballrace.validation.figures_roller:roller_figures",
    "ballrace.validation.figures_fem:fem_figures",
]


def _call(source: str, run) -> list[Figure]:
    import importlib
    import inspect

    mod, _, name = source.partition(":")
    fn = getattr(importlib.import_module(mod), name)
    out = fn(run) if inspect.signature(fn).parameters else fn()
    return [out] if isinstance(out, Figure) else list(out)


def all_figures(run, sources=None) -> list[Figure]:
    """Every report figure for ``run``: the figures of each of ``sources`` (default
    :data:`FIGURE_SOURCES`); a source that fails adds a note instead."""
    figs = []
    for src in FIGURE_SOURCES if sources is None else sources:
        try:
            figs.extend(_call(src, run))
        except Exception as exc:  # noqa: BLE001 - never let a figure break the report
            log.warning("figure source %s failed: %s", src, exc, exc_info=True)
            figs.append(Figure(f"figure-error-{src.rpartition(':')[2]}", "summary",
                               f"Figures of {src} failed",
                               note=f"omitted: {type(exc).__name__}: {exc}"))
    return figs
