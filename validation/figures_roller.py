"""Figure data for the roller section of the report (lamina load distribution, clearance,
the half-space line contact).

Computes only; :mod:`ballrace.reports.plots` draws (panels as in
:mod:`ballrace.validation.figures`).  Three figures:

* ``roller-stribeck`` — the load of each roller around the bearing: 20 straight rollers
  at zero clearance (the Stribeck case of ``roller.toml``) against Q_max cos^(10/9) psi,
  and the 210-size bearing with 45 um clearance against Sjövall's load zone
  Q_max [1 - (1 - cos psi)/(2 eps)]^(10/9);
* ``roller-tilt-profiles`` — slice loads of the most loaded roller of the 210-size bearing
  under 1 mrad tilt for straight, ISO/TS 16281 and Lundberg profiles (lamina), and beside
  them the pressure of the lamina slices and of the half-space line contact
  (:meth:`~ballrace.analytic.roller.RollerLoadDistribution.roller_contact`);
* ``roller-clearance`` — Q_max and the ISO/TS 16281 life of the 210-size bearing against
  its diametral clearance: the lamina model against the continuous J_r(eps) method of
  Oswald, Zaretsky & Poplawski (NASA/TM-2012-217115, 2012).  That report's own points
  could not be read, so none are drawn.

>>> figs = roller_figures()
>>> [f.id for f in figs], all(f.panels for f in figs)
(['roller-stribeck', 'roller-tilt-profiles', 'roller-clearance'], True)
"""
from __future__ import annotations

import logging
import math

import numpy as np

from .figures import Figure

__all__ = ["roller_figures", "stribeck_figure", "tilt_profiles_figure", "clearance_figure",
           "BEARING_210", "FR_210"]

log = logging.getLogger(__name__)

#: The 210-size cylindrical roller bearing (NASA/TM-2012-217115, Table III; L_we from
#: the catalogue C_0r by ISO 76) [m].
BEARING_210 = dict(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=14,
                   pitch_diameter=70.65e-3)
#: Radial load of the 210-size examples [N].
FR_210 = 6940.0
_STRIBECK = dict(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=20,
                 pitch_diameter=99.72e-3)
_EXP = 10.0 / 9.0


def _run_series(run, case_id):
    """The load series (psi, Q) of ``case_id`` from a validation run, or None."""
    if run is None:
        return None
    for r in getattr(run, "results", ()):
        if r.id == case_id and getattr(r, "series", None) and "psi" in r.series:
            return np.asarray(r.series["psi"]), np.asarray(r.series["Q"])
    return None


def _wrap_deg(psi):
    """Azimuths [rad] as degrees in (-180, 180]."""
    return np.degrees(np.angle(np.exp(1j * np.asarray(psi))))


def _sorted(x, y):
    i = np.argsort(x)
    return np.asarray(x)[i], np.asarray(y)[i]


def stribeck_figure(run=None) -> Figure:
    """Roller loads around the bearing: zero clearance (Stribeck) and 45 um clearance."""
    from ballrace.analytic.roller import RollerBearing

    from .calc_roller_published import jr_method

    src = "from the validation run"
    got = _run_series(run, "roller-stribeck-20-rollers")
    if got is None:
        src = "computed for the report"
        r = RollerBearing(**_STRIBECK, profile="straight").solve(Fy=6000.0)
        got = np.asarray(r.azimuths), np.asarray(r.roller_loads)
    psi, Q = got
    x, y = _sorted(_wrap_deg(psi), Q)
    t = np.linspace(-180.0, 180.0, 721)
    qmax = float(Q.max())
    curve = qmax * np.clip(np.cos(np.radians(t)), 0.0, None) ** _EXP
    zero = {"kind": "lines", "title": "20 straight rollers, zero clearance, 6000 N",
            "legend": "below",
            "xlabel": "azimuth psi [deg]", "ylabel": "roller load Q [N]",
            "series": [{"x": t, "y": curve, "label": "Q_max cos(psi)^(10/9)"},
                       {"x": x, "y": y, "style": "markers",
                        "label": f"lamina model ({src}): Z Q_max / F_r = "
                                 f"{20 * qmax / 6000.0:.4f}"}]}
    pd = 45e-6
    b = RollerBearing(**BEARING_210, diametral_clearance=pd, profile="straight", n_slices=5)
    r = b.solve(Fy=FR_210)
    Qj, dr, eps = jr_method(FR_210, b.n_rollers, b.lamina_stiffness, pd)
    x2, y2 = _sorted(_wrap_deg(r.azimuths), r.roller_loads)
    zone = Qj * np.clip(1.0 - (1.0 - np.cos(np.radians(t))) / (2.0 * eps), 0.0, None) ** _EXP
    clear = {"kind": "lines", "title": "210 bearing, 45 um clearance, 6940 N",
             "legend": "below",
             "xlabel": "azimuth psi [deg]", "ylabel": "roller load Q [N]",
             "series": [{"x": t, "y": zone, "label": f"continuous load zone, eps = {eps:.3f}"},
                        {"x": x2, "y": y2, "style": "markers",
                         "label": f"lamina model, Q_max = {float(np.max(y2)):.0f} N"}]}
    return Figure("roller-stribeck", "roller", "Load of each roller around the bearing",
                  caption="Left: the Stribeck case (zero clearance, equal straight rollers): "
                          "every loaded roller carries Q_max cos(psi)^(10/9), whatever the "
                          "geometry.  Right: with clearance fewer rollers carry load; the "
                          "curve is Sjovall's continuous load zone Q_max [1 - (1 - cos psi) "
                          "/ (2 eps)]^(10/9) with Q_max and eps from the J_r(eps) method, "
                          "which 14 discrete rollers miss by some 2 % in Q_max.",
                  panels=(zero, clear), size=(12.0, 3.8))


def tilt_profiles_figure(tilt: float = 1e-3) -> Figure:
    """Slice loads (lamina) and pressures (lamina and half-space) of the most loaded roller
    under tilt for three profiles."""
    from ballrace.analytic.roller import RollerBearing

    loads, press = [], []
    for prof in ("straight", "iso", "lundberg"):
        b = RollerBearing(**BEARING_210, profile=prof)
        r = b.solve(Fy=FR_210, displacements=[None, None, None, 0.0, tilt])
        j = int(np.argmax(r.roller_loads))
        x = b.slice_positions * 1e3
        loads.append({"x": x, "y": np.asarray(r.slice_loads_inner[j]) / (b.slice_width * 1e3),
                      "style": "markers", "label": f"{prof}"})
        c = r.roller_contact(j, "inner")
        p_lam = np.asarray(r.slice_pressures("inner"))[j] / 1e6
        press.append({"x": x, "y": p_lam, "style": "dashed", "label": f"{prof}: lamina"})
        press.append({"x": np.asarray(c.x) * 1e3, "y": np.asarray(c.pressure) / 1e6,
                      "label": f"{prof}: half-space, peak {float(np.max(c.pressure)) / 1e6:.0f}"
                               " MPa"})
    return Figure("roller-tilt-profiles", "roller",
                  f"Most loaded roller under {tilt * 1e3:g} mrad tilt: three profiles",
                  caption="210-size bearing (14 rollers of 13 x 11.8 mm, zero clearance), "
                          f"6940 N radial, inner ring tilted by {tilt * 1e3:g} mrad about z "
                          "(imposed), 31 slices, inner contact.  Left: lamina slice loads "
                          "per length.  Right: the lamina pressure (2-D Hertz per slice, "
                          "dashed) and the half-space line contact of the same roller at "
                          "the same load and tilt (solid), which couples the slices and "
                          "shows the edge peak of the straight roller (a singularity: its "
                          "value grows with the slice count).",
                  panels=({"kind": "lines", "title": "lamina slice loads",
                           "xlabel": "x along the roller [mm]",
                           "ylabel": "slice load per length [N/mm]", "series": loads},
                          {"kind": "lines", "title": "pressure: lamina and half-space",
                           "xlabel": "x along the roller [mm]", "ylabel": "p [MPa]",
                           "series": press, "width": 1.3}),
                  size=(12.0, 4.0))


def clearance_figure() -> Figure:
    """Q_max and L10r of the 210-size bearing against clearance: the lamina model against
    the continuous J_r(eps) method."""
    from ballrace.analytic.roller import RollerBearing
    from ballrace.analytic.roller import life as rlife

    from .calc_roller_published import jr_method

    pds = np.array([-15.0, -10.0, -5.0, 0.0, 10.0, 20.0, 30.0, 45.0, 60.0, 80.0, 100.0,
                    120.0]) * 1e-6
    q_model, q_jr, life_, eps = [], [], [], []
    for pd in pds:
        b = RollerBearing(**BEARING_210, diametral_clearance=float(pd), profile="straight",
                          n_slices=5)
        r = b.solve(Fy=FR_210)
        q_model.append(float(np.max(r.roller_loads)))
        Qj, _, e = jr_method(FR_210, b.n_rollers, b.lamina_stiffness, float(pd))
        q_jr.append(Qj)
        eps.append(e)
        life_.append(float(rlife.reference_rating_life(
            b, r, dynamic_rating=b.dynamic_rating()).L10r))
    i0 = int(np.flatnonzero(pds == 0.0)[0])
    um = pds * 1e6
    q_panel = {"kind": "lines", "title": "most loaded roller",
               "xlabel": "diametral clearance P_d [um]", "ylabel": "Q_max [N]",
               "series": [{"x": um, "y": np.array(q_jr),
                           "label": "J_r(eps) method (continuous load zone)"},
                          {"x": um, "y": np.array(q_model), "style": "markers",
                           "label": "lamina model (14 rollers)"}]}
    l_panel = {"kind": "lines", "title": "ISO/TS 16281 life",
               "xlabel": "diametral clearance P_d [um]",
               "ylabel": "L10r / L10r(P_d = 0) [-]",
               "series": [{"x": um, "y": np.array(life_) / life_[i0], "style": "markers",
                           "label": "lamina model, straight rollers"}]}
    return Figure("roller-clearance", "roller", "Clearance: maximum roller load and life",
                  caption="210-size cylindrical bearing (NASA/TM-2012-217115, Table III), "
                          "6940 N radial, straight rollers, ISO/TS 16281 stiffness.  Left: "
                          "Q_max of the lamina model against the continuous J_r(eps) method "
                          "of Oswald, Zaretsky & Poplawski (2012) with the same stiffness "
                          "and exponent 10/9: the discrete rollers step as they leave the "
                          "load zone.  Right: the ISO/TS 16281 reference life relative to "
                          "zero clearance, longest near zero clearance.  The report's own "
                          "points could not be read and are not drawn.",
                  panels=(q_panel, l_panel), size=(12.0, 3.8))


def roller_figures(run=None) -> list[Figure]:
    """All roller figures (``run`` supplies the Stribeck case's loads when it ran)."""
    figs = []
    for fn, args in ((stribeck_figure, (run,)), (tilt_profiles_figure, ()),
                     (clearance_figure, ())):
        try:
            figs.append(fn(*args))
        except Exception as exc:  # noqa: BLE001 - never let a figure break the report
            log.warning("roller figure failed: %s", exc, exc_info=True)
            figs.append(Figure(f"roller-{fn.__name__}", "roller", "A roller figure failed",
                               note=f"omitted: {type(exc).__name__}: {exc}"))
    return figs
