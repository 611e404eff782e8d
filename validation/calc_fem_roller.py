"""FE calculation of a profiled roller's line contact (:func:`ballrace.fem.roller_contact`),
run through dask by the runner like the ball FE cases (:mod:`ballrace.validation.calc_fem`).

Each FE value is returned beside line_contact's for the same inputs (``*_line``) and their
relative difference (``*_vs_line``), so a case can check the FE value against a number
written in the case file and the report can show both.  The pressure along the roller
(FE nodes, FE slice averages, line_contact's slices) goes to the report's figure through
``_series``; the picture of :func:`ballrace.fem.render.render_roller` is an artifact.
"""
from __future__ import annotations

import logging
import math
import os

from .calc_fem import FE_LOCK
from .registry import Param, calculation

log = logging.getLogger(__name__)

#: Profiles a case can name; "crowned" takes ``flat_length`` and ``crown_radius``.
PROFILES = ("straight", "iso", "lundberg", "johns-gohar", "crowned")
#: (output stem, comparison row of RollerFEResult, dimension).
ROWS = (("centre_pressure", "centre_pressure", "[pressure]"),
        ("max_pressure", "max_pressure", "[pressure]"),
        ("edge_pressure", "edge_pressure", "[pressure]"),
        ("peak_slice_load", "peak_slice_load", "[force]"),
        ("end_slice_load", "edge_slice_load", "[force]"),
        ("approach", "approach", "[length]"),
        ("von_mises_centre", "von_mises_centre", "[pressure]"),
        ("von_mises_centre_depth", "von_mises_centre_depth", "[length]"),
        ("von_mises_edge", "von_mises_edge", "[pressure]"),
        ("von_mises_edge_depth", "von_mises_edge_depth", "[length]"))
_OUT = {**{s: d for s, _, d in ROWS}, **{f"{s}_line": d for s, _, d in ROWS},
        **{f"{s}_vs_line": "" for s, _, _ in ROWS},
        "centre_slice_load": "[force]", "centre_slice_load_line": "[force]",
        "end_quarter_load": "[force]", "end_quarter_load_line": "[force]",
        "end_quarter_load_vs_line": "", "end_slice_load_deviation": "", "loaded_end": "",
        "slice_load_max_dev": "", "slice_load_max_dev_x": "[length]",
        "x_edge": "[length]", "n_dofs": "", "wall_time": "[time]"}


def roller_profile(profile: str, flat_length=None, crown_radius=None):
    """The profile of a case: a name, or a circular crown from ``flat_length`` [m] and
    ``crown_radius`` [m] (both needed for "crowned", refused otherwise)."""
    crown = (flat_length, crown_radius)
    if profile == "crowned":
        if None in crown:
            raise ValueError("profile 'crowned' needs flat_length [m] and crown_radius [m]")
        from ballrace.analytic.roller import Crowned

        return Crowned(float(flat_length), float(crown_radius))
    if any(v is not None for v in crown):
        raise ValueError(f"flat_length and crown_radius apply to profile 'crowned' only; "
                         f"got profile {profile!r}")
    return profile


def roller_outputs(r) -> dict:
    """The case outputs of a :class:`~ballrace.fem.RollerFEResult` (SI), with the
    pressure along the roller in ``_series``.

    The quarter model (no tilt) holds the slices x >= 0, the half model (a tilt) every
    slice.  ``end_quarter_load`` is the FE load on the outer quarter (|x| >= L/4) of the
    more loaded end (line_contact's; +x in the quarter model), ``loaded_end`` the sign of
    x of the end whose outer quarter carries more load in the FE (+1 in the quarter
    model), ``end_slice_load_deviation`` the largest difference of that quarter's slice
    loads over the mean slice load Q/n."""
    import numpy as np

    out = {}
    for stem, q, _ in ROWS:
        row = r.row(q)
        out[stem] = float(row["fe"])
        out[f"{stem}_line"] = float(row["analytic"])
        out[f"{stem}_vs_line"] = float(row["error"])
    c = r.analytic
    mid = (c.n_slices - 1) // 2
    half = r.info.get("model") == "half"
    s0 = 0 if half else mid                   # line_contact's first slice in the result
    fe = np.asarray(r.slice_loads, dtype=float)
    sx = np.asarray(r.slice_x, dtype=float)
    lc = np.asarray(c.slice_loads, dtype=float)[s0:]
    out["centre_slice_load"] = float(fe[mid - s0])
    out["centre_slice_load_line"] = float(lc[mid - s0])
    # the largest slice-load difference over every slice but the end ones (the FE
    # resolves the end within the slice, the strip method averages it: fem.roller notes)
    inner = np.ones(fe.size, dtype=bool)
    inner[-1] = False
    if half:
        inner[0] = False
    dev = np.where(lc > 0, fe / np.where(lc > 0, lc, 1.0) - 1.0, 0.0)
    dev = np.where(inner, dev, 0.0)
    k = int(np.argmax(np.abs(dev)))
    out["slice_load_max_dev"] = float(abs(dev[k]))
    out["slice_load_max_dev_x"] = float(sx[k])
    if half:
        row = r.row("end_quarter_load")
        out["end_quarter_load"] = float(row["fe"])
        out["end_quarter_load_line"] = float(row["analytic"])
        out["end_quarter_load_vs_line"] = float(row["error"])
        out["end_slice_load_deviation"] = float(r.info["end_slice_load_deviation"])
        L = float(c.length)
        plus, minus = fe[sx >= 0.25 * L].sum(), fe[sx <= -0.25 * L].sum()
        out["loaded_end"] = 1.0 if plus >= minus else -1.0
    else:
        q_end = sx >= 0.25 * float(c.length)
        out["end_quarter_load"] = float(fe[q_end].sum())
        out["end_quarter_load_line"] = float(lc[q_end].sum())
        out["end_quarter_load_vs_line"] = out["end_quarter_load"] / out[
            "end_quarter_load_line"] - 1.0
        out["end_slice_load_deviation"] = float(
            np.max(np.abs(fe[q_end] - lc[q_end])) / (float(c.load) / c.n_slices))
        out["loaded_end"] = 1.0
    out["x_edge"] = float(r.x_edge)
    out["n_dofs"] = float(r.n_dofs)
    out["wall_time"] = float(r.timings.get("total", math.nan))
    out["_series"] = {"x": r.x, "pressure": r.pressure, "slice_x": r.slice_x,
                      "slice_pressure": r.slice_pressure, "slice_loads": r.slice_loads,
                      "line_x": np.asarray(c.x)[s0:],
                      "line_pressure": np.asarray(c.pressure)[s0:],
                      "line_slice_loads": lc, "length": [c.length],
                      "slice_width": [c.slice_width], "tilt": [float(r.info.get("tilt", 0.0))]}
    return out


def _render(r, render_dir, case_id) -> tuple:
    """("label", path) of the render_roller picture, or ("why not", "")."""
    from ballrace.fem.render import render_roller

    path = os.path.join(render_dir, f"{case_id}-roller.png")
    try:
        return ("3-D von Mises under the roller, pressure along it",
                render_roller(r, path))
    except ImportError as exc:
        log.warning("no roller picture of %s: pyvista or matplotlib missing (%s)", case_id, exc)
        return ("picture omitted: pyvista (VTK) or matplotlib is not installed", "")
    except Exception as exc:  # noqa: BLE001 - a picture must not fail the check
        log.warning("roller picture of %s failed: %s: %s", case_id, type(exc).__name__, exc)
        return (f"picture omitted: {type(exc).__name__}: {exc}", "")


@calculation("fem.roller_contact", requires=("ballrace.fem:roller_contact",), fem=True,
             inputs={"load": Param("[force]"), "roller_diameter": Param("[length]"),
                     "roller_length": Param("[length]"),
                     "raceway_radius": Param("[length]", math.inf, allow_inf=True),
                     "profile": Param("str", "lundberg", choices=PROFILES),
                     "flat_length": Param("[length]", None),
                     "crown_radius": Param("[length]", None),
                     "E": Param("[pressure]", 200e9), "nu": Param("", 0.3),
                     "n_slices": Param("int", 41), "tilt": Param("[angle]", 0.0),
                     "mode": Param("str", "half-space", choices=("half-space", "two-body")),
                     "level": Param("str", "quick", choices=("quick", "standard", "fine")),
                     "render_dir": Param("str", None), "case_id": Param("str", "fe")},
             outputs=_OUT)
def roller_contact(load, roller_diameter, roller_length, raceway_radius, profile, flat_length,
                   crown_radius, E, nu, n_slices, tilt, mode, level, render_dir, case_id):
    """FE profiled roller on its raceway against line_contact (same material both); a
    nonzero ``tilt`` [rad] takes the half model."""
    from ballrace import Material, fem

    prof = roller_profile(profile, flat_length, crown_radius)
    m = Material(E=E, nu=nu)
    with FE_LOCK:
        r = fem.roller_contact(load, 0.5 * roller_diameter, raceway_radius, roller_length, m, m,
                               profile=prof, level=level, mode=mode, n_slices=int(n_slices),
                               tilt=float(tilt))
        out = roller_outputs(r)
        out["_artifacts"] = ([_render(r, render_dir, case_id)]
                             if render_dir else [])
    return out
