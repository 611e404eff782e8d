"""Finite-element calculations (:mod:`ballrace.fem`), run through dask by the runner.

The runner injects ``level`` (from ``--fem``), ``render_dir`` (the report's render folder,
or None) and ``case_id``.  A render that fails is logged and left out; it never fails
the case.
"""
from __future__ import annotations

import logging
import math
import os
import threading

from .calc_bearing import BEARING_INPUTS, make_bearing
from .registry import Param, calculation

log = logging.getLogger(__name__)

#: gmsh (meshing) is not thread-safe: concurrent meshing in two threads of one process
#: segfaults.  FE calculations in one process therefore run one at a time; separate
#: dask worker processes still run in parallel.
FE_LOCK = threading.Lock()

_FEM = "ballrace.fem"
_CONTEXT = {"level": Param("str", "quick", choices=("quick", "standard", "fine")),
            "render_dir": Param("str", None), "case_id": Param("str", "fe")}
_OPTIONS = {"mode": Param("str", "half-space", choices=("half-space", "two-body")),
            "gap": Param("str", "hertz", choices=("hertz", "exact"))}
#: A tangential surface traction q = traction * p along +x (run_case(traction=...)): the
#: section y = 0 of the loaded contact against subsurface.stress(..., traction=...).
_TRACTION = {"traction": Param("", 0.0),
             "traction_pressure": Param("str", "fe", choices=("fe", "hertz"))}
#: Outputs of the traction rows (NaN without traction): the maxima [Pa] and their
#: locations [m], the trailing-edge tension [Pa], and the errors as fem.api defines them
#: (relative for values, per minor semi-axis for locations, per p0 for the tension and
#: the section RMS, relative for the resultant).
TRACTION_OUT = ("traction_von_mises", "traction_von_mises_x", "traction_von_mises_depth",
                "traction_tresca", "traction_tresca_x", "traction_tresca_depth",
                "traction_sxx_trailing", "traction_section_rms", "traction_resultant")
_TRACTION_UNITS = {"traction_von_mises": "[pressure]", "traction_tresca": "[pressure]",
                   "traction_sxx_trailing": "[pressure]", "traction_section_rms": "[pressure]",
                   "traction_resultant": "[force]"}
_OUT = {"a": "[length]", "b": "[length]", "p_max": "[pressure]", "tau0": "[pressure]",
        "z0": "[length]", "tau_x0z0": "[pressure]", "max_shear": "[pressure]",
        "max_shear_depth": "[length]", "von_mises": "[pressure]",
        "von_mises_depth": "[length]", "approach": "[length]", "approach_vs_hertz": "",
        "approach_depth_point": "[length]", "approach_rigid": "[length]",
        "n_dofs": "", "wall_time": "[time]",
        **{f"{q}_vs_hertz": "" for q in ("a", "b", "p_max", "tau0", "max_shear", "z0",
                                         "max_shear_depth")},
        **{q: _TRACTION_UNITS.get(q, "[length]") for q in TRACTION_OUT},
        **{f"{q}_error": "" for q in TRACTION_OUT}}


def _outputs(r, render_dir, case_id) -> dict:
    out = {k: float(getattr(r, k)) for k in ("a", "b", "p_max", "tau0", "z0", "tau_x0z0",
                                              "max_shear", "max_shear_depth", "von_mises",
                                              "von_mises_depth", "approach",
                                              "approach_depth_point", "approach_rigid")}
    rows = {row["quantity"]: row for row in r.comparison}
    out["approach_vs_hertz"] = float(rows["approach"]["error"]) if "approach" in rows else math.nan
    for q in ("a", "b", "p_max", "tau0", "max_shear", "z0", "max_shear_depth"):
        out[f"{q}_vs_hertz"] = float(rows[q]["error"]) if q in rows else math.nan
    out["n_dofs"] = float(r.n_dofs)
    out["wall_time"] = float(r.timings.get("total", math.nan))
    for q in TRACTION_OUT:
        out[q] = float(rows[q]["fe"]) if q in rows else math.nan
        out[f"{q}_error"] = float(rows[q]["error"]) if q in rows else math.nan
    arts = []
    if render_dir:
        from ballrace import fem

        for field in ("von_mises", "tau_xz"):
            path = os.path.join(render_dir, f"{case_id}-{field}.png")
            try:
                fem.render(r, field=field, path=path)
                arts.append((field, path))
            except Exception as exc:  # noqa: BLE001 - a render must not fail the check
                log.warning("render of %s (%s) failed: %s: %s", case_id, field,
                            type(exc).__name__, exc)
                break
        arts.append(_render_3d(r, render_dir, case_id))
    out["_artifacts"] = arts
    return out


def _render_3d(r, render_dir, case_id) -> tuple:
    """("3-D", path) of the pyvista picture, or ("3-D", "") with the reason logged."""
    from ballrace.fem.render import render_3d

    path = os.path.join(render_dir, f"{case_id}-3d.png")
    try:
        return ("3-D von Mises", render_3d(r, path))
    except ImportError as exc:
        log.warning("no 3-D render of %s: pyvista is not installed (%s)", case_id, exc)
        return ("3-D render omitted: pyvista (VTK) is not installed", "")
    except NotImplementedError as exc:          # a traction case: the section shows it
        log.info("no 3-D render of %s: %s", case_id, exc)
        return ("3-D render omitted: the contact carries a surface traction; the section "
                "y = 0 above shows the loaded field", "")
    except Exception as exc:  # noqa: BLE001 - a render must not fail the check
        log.warning("3-D render of %s failed: %s: %s", case_id, type(exc).__name__, exc)
        return (f"3-D render omitted: {type(exc).__name__}: {exc}", "")


@calculation("fem.ball_on_plane", requires=(_FEM + ":ball_on_plane",), fem=True,
             inputs={"ball_diameter": Param("[length]"), "load": Param("[force]"),
                     "E": Param("[pressure]", 200e9), "nu": Param("", 0.3), **_OPTIONS,
                     **_TRACTION, **_CONTEXT},
             outputs=_OUT)
def ball_on_plane(ball_diameter, load, E, nu, mode, gap, level, render_dir, case_id,
                  traction=0.0, traction_pressure="fe"):
    """FE ball on a flat of the same material (optionally with a surface traction)."""
    from ballrace import Material, fem

    with FE_LOCK:
        r = fem.ball_on_plane(ball_diameter, load, Material(E=E, nu=nu), level=level,
                              mode=mode, gap=gap, traction=traction,
                              traction_pressure=traction_pressure)
        return _outputs(r, render_dir, case_id)   # renders (VTK) under the lock too


@calculation("fem.ball_on_ball", requires=(_FEM + ":ball_on_ball",), fem=True,
             inputs={"ball_diameter": Param("[length]"), "load": Param("[force]"),
                     "E": Param("[pressure]", 200e9), "nu": Param("", 0.3), **_OPTIONS,
                     **_CONTEXT},
             outputs=_OUT)
def ball_on_ball(ball_diameter, load, E, nu, mode, gap, level, render_dir, case_id):
    """FE of two equal balls pressed together (SSNV104, MOOSE hertz_spherical)."""
    from ballrace import Material, fem

    with FE_LOCK:
        r = fem.ball_on_ball(ball_diameter, load, Material(E=E, nu=nu), level=level,
                             mode=mode, gap=gap)
        return _outputs(r, render_dir, case_id)   # renders (VTK) under the lock too


@calculation("fem.ball_on_race", requires=(_FEM + ":ball_on_race",), fem=True,
             inputs={**{k: v for k, v in BEARING_INPUTS.items() if k not in ("E", "nu")},
                     "E": Param("[pressure]", 200e9), "nu": Param("", 0.3),
                     "load": Param("[force]"),
                     "race": Param("str", "inner", choices=("inner", "outer")),
                     "contact_angle": Param("[angle]", 0.0), **_OPTIONS, **_TRACTION,
                     **_CONTEXT},
             outputs=_OUT)
def ball_on_race(load, race, contact_angle, mode, gap, level, render_dir, case_id,
                 traction=0.0, traction_pressure="fe", **kw):
    """FE ball on an inner or outer race groove (optionally with a surface traction)."""
    from ballrace import fem

    brg = make_bearing(**kw)
    with FE_LOCK:
        r = fem.ball_on_race(brg, load, race=race, contact_angle=contact_angle, level=level,
                             mode=mode, gap=gap, traction=traction,
                             traction_pressure=traction_pressure)
        return _outputs(r, render_dir, case_id)   # renders (VTK) under the lock too


#: Quantities of the Hertz-limits sweep: (output stem, FEResult attribute).
LIMIT_QUANTITIES = ("a", "b", "p_max", "approach", "tau0", "z0")
_LIMITS_OUT = {"load": "[force]", "p_max_hertz": "[pressure]", "a_over_fD": "",
               "a_over_b": "", "n_dofs": "", "wall_time": "[time]",
               **{f"{q}_{kind}": "" for q in LIMIT_QUANTITIES
                  for kind in ("vs_hertz", "exact_vs_hertz", "beyond")}}


def limits_load(brg, race: str, contact_angle: float, a_over_fD=None, p_max=None) -> float:
    """Ball load Q [N] that gives a Hertz contact of a/(f D) = ``a_over_fD`` or ``p_max`` [Pa].

    Hertz's semi-axes grow as Q^(1/3) and p_max as Q^(1/3) (Hamrock & Dowson 1981 eqs.
    (3.8)-(3.16)), so Q = (x / x_1)^3 with x_1 the value at Q = 1 N.

    Parameters
    ----------
    brg : ballrace.BallBearing
        Bearing (groove conformities f_inner, f_outer [-], ball diameter D [m]).
    race : {"inner", "outer"}
        Race whose contact sets the load.
    contact_angle : float
        Contact angle [rad].
    a_over_fD : float, optional
        Semi-major axis over groove radius of the Hertz contact, in (0, 1) [-].
    p_max : float, optional
        Hertz maximum pressure [Pa], > 0.

    Returns
    -------
    float
        Ball load Q [N].

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)
    >>> round(limits_load(brg, "inner", 0.0, p_max=4.2e9))     # 209 inner race, ISO 76
    12150
    """
    from ballrace import fem

    if (a_over_fD is None) == (p_max is None):
        raise ValueError("give exactly one of a_over_fD [-] and p_max [Pa] for the load")
    c1 = fem.race_case(brg, 1.0, race, contact_angle).analytic
    if p_max is not None:
        if not 0 < p_max < math.inf:
            raise ValueError(f"p_max must be > 0 [Pa]; got {p_max!r}")
        return float((p_max / float(c1.p_max)) ** 3)
    f = float(brg.f_inner if race == "inner" else brg.f_outer)
    if not 0 < a_over_fD < 1:
        raise ValueError(f"a_over_fD must be in (0, 1) [-] (the ellipse inside the groove); "
                         f"got {a_over_fD!r}")
    return float((a_over_fD * f * float(brg.ball_diameter) / float(c1.a)) ** 3)


@calculation("fem.hertz_limits", requires=(_FEM + ":ball_on_race",), fem=True,
             inputs={"ball_diameter": Param("[length]"), "pitch_diameter": Param("[length]"),
                     "f": Param(""), "race": Param("str", "inner", choices=("inner", "outer")),
                     "contact_angle": Param("[angle]", 0.0), "E": Param("[pressure]", 200e9),
                     "nu": Param("", 0.3), "a_over_fD": Param("", None),
                     "p_max": Param("[pressure]", None),
                     "mode": _OPTIONS["mode"], "level": _CONTEXT["level"]},
             outputs=_LIMITS_OUT)
def hertz_limits(ball_diameter, pitch_diameter, f, race, contact_angle, E, nu, a_over_fD,
                 p_max, mode, level):
    """FE ball on a race with Hertz's gap and with the exact sphere-torus gap, same mesh.

    The load is set by the Hertz a/(f D) or p_max it gives (:func:`limits_load`).  Outputs
    per quantity q of :data:`LIMIT_QUANTITIES`: ``q_vs_hertz`` (Hertz-gap FE against the
    analytic value: the discretisation error), ``q_exact_vs_hertz`` (exact-gap FE against
    the analytic value) and ``q_beyond`` = exact-gap FE / Hertz-gap FE - 1 (both on one
    mesh, so the discretisation error cancels and the geometric departure from Hertz's
    quadratic gap is left).
    """
    from ballrace import Material, fem
    from ballrace.analytic.bearing import BallBearing

    brg = BallBearing(ball_diameter, 9, pitch_diameter, f, f,
                      free_contact_angle=contact_angle, material=Material(E=E, nu=nu))
    load = limits_load(brg, race, contact_angle, a_over_fD, p_max)
    c = fem.race_case(brg, load, race, contact_angle).analytic
    res = {}
    with FE_LOCK:
        for gap in ("hertz", "exact"):       # the mesh depends on the Hertz ellipse only
            res[gap] = fem.ball_on_race(brg, load, race=race, contact_angle=contact_angle,
                                        level=level, mode=mode, gap=gap)
    h, e = res["hertz"], res["exact"]
    if h.info.get("mesh_digests") != e.info.get("mesh_digests"):
        raise RuntimeError("the Hertz-gap and exact-gap models were meshed differently; "
                           "their difference would not cancel the discretisation error")
    out = {"load": load, "p_max_hertz": float(c.p_max),
           "a_over_fD": float(c.a) / (f * ball_diameter), "a_over_b": float(c.a / c.b),
           "n_dofs": float(h.n_dofs),
           "wall_time": float(h.timings["total"] + e.timings["total"])}
    rows = {g: {row["quantity"]: row for row in r.comparison} for g, r in res.items()}
    for q in LIMIT_QUANTITIES:
        out[f"{q}_vs_hertz"] = float(rows["hertz"][q]["error"])
        out[f"{q}_exact_vs_hertz"] = float(rows["exact"][q]["error"])
        out[f"{q}_beyond"] = float(getattr(e, q) / getattr(h, q) - 1.0)
    return out
