"""Figure data for the life section of the report (ISO 281:2007, ISO/TS 16281).

Computes only; :mod:`ballrace.reports.plots` draws (panels as in
:mod:`ballrace.validation.figures`).  Four figures:

* ``life-aiso`` — a_ISO against e_C C_u / P for several κ (the layout of ISO 281:2007
  Figure 14, radial ball bearings), log–log, with the cap at 50;
* ``life-clearance`` — ISO/TS 16281 L10r / L10 of a 6305 against its operating clearance
  (the optimum at a slight preload);
* ``life-misalignment`` — L10r / L10 against the tilt of the inner ring;
* ``life-ratio`` — L10r / L10 at zero clearance against the number of balls, with the
  ball set on and between the load line (→ 1: the tie of ISO/TS 16281 to C).

>>> figs = life_figures()
>>> [f.id for f in figs], all(f.panels for f in figs)
(['life-aiso', 'life-clearance', 'life-misalignment', 'life-ratio'], True)
"""
from __future__ import annotations

import logging

import numpy as np

import ballrace
from ballrace.analytic import iso281, life, loaddist, ratings

from .figures import Figure

__all__ = ["life_figures", "aiso_figure", "clearance_figure", "misalignment_figure",
           "ratio_figure", "AISO_KAPPAS"]

log = logging.getLogger(__name__)

#: κ values of the a_ISO curves (those of ISO 281:2007 Figure 14).
AISO_KAPPAS = (0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 2.0, 4.0)

_B6305 = dict(ball_diameter=0.0115, n_balls=7, pitch_diameter=0.0435, f_inner=0.52,
              f_outer=0.53)


def aiso_figure() -> Figure:
    """a_ISO(κ, e_C C_u / P) of radial ball bearings (ISO 281:2007 §9.3.3, Figure 14)."""
    x = np.logspace(np.log10(0.005), np.log10(5.0), 241)
    series = [{"x": x, "y": np.asarray(iso281.life_modification_factor(k, 1.0, x, 1.0)),
               "label": f"kappa = {k:g}"} for k in AISO_KAPPAS]
    return Figure("life-aiso", "life", "Life modification factor a_ISO, radial ball bearings",
                  caption="ISO 281:2007 §9.3.3: a_ISO against e_C C_u / P for the viscosity "
                          "ratios of the standard's Figure 14; kappa > 4 is taken as 4 and "
                          "a_ISO is capped at 50.  The curves are continuous across the "
                          "kappa-range boundaries 0.4 and 1 (asserted in the tests).",
                  panels=({"kind": "lines", "title": "a_ISO", "xlabel": "e_C C_u / P [-]",
                           "ylabel": "a_ISO [-]", "logx": True, "logy": True,
                           "hlines": ({"y": 50.0, "label": "cap 50"},),
                           "series": series},))


def _bearing(clearance=0.0):
    return ballrace.BallBearing(**_B6305, diametral_clearance=clearance)


def clearance_figure(load: float = 2000.0) -> Figure:
    """ISO/TS 16281 L10r / (C/F_r)³ of a 6305 against the operating clearance."""
    brg = _bearing()
    C = float(ratings.dynamic_rating(brg, contact_angle=0.0))
    series = []
    for Fr in (0.5 * load, load, 2.0 * load):
        pd = np.linspace(-30e-6, 40e-6, 71)
        L = np.array([life.reference_rating_life(brg, brg.radial(Fr, clearance=p),
                                                 nominal_contact_angle=0.0).L10r for p in pd])
        series.append({"x": pd * 1e6, "y": L / (C / Fr) ** 3, "label": f"F_r = {Fr:g} N"})
    return _ratio_figure("life-clearance", "Reference rating life against operating clearance",
                         "operating clearance [um]", series,
                         "6305 (Z = 7, D = 11.5 mm, D_pw = 43.5 mm, f = 0.52 / 0.53) under "
                         "radial load: ISO/TS 16281 L10r over the catalogue L10 = (C/F_r)^3 "
                         "against the diametral operating clearance (negative: preload).  The "
                         "optimum lies at a slight preload, a few micrometres for these "
                         "loads; heavy preload and large clearance both shorten the life.")


def misalignment_figure(load: float = 2000.0) -> Figure:
    """ISO/TS 16281 L10r / L10 of a 6305 against inner-ring tilt."""
    series = []
    arcmin = np.linspace(0.0, 30.0, 31)
    for pd in (0.0, 10e-6, 20e-6):
        brg = _bearing(pd)
        C = float(ratings.dynamic_rating(brg, contact_angle=0.0))
        L = []
        for a in arcmin:
            d = [np.nan] * 5
            d[4] = np.radians(a / 60.0)          # tilt about the axis across the load
            res = loaddist.solve(brg, Fy=load, displacements=d)
            L.append(life.reference_rating_life(brg, res, nominal_contact_angle=0.0).L10r)
        series.append({"x": arcmin, "y": np.array(L) / (C / load) ** 3,
                       "label": f"clearance {pd * 1e6:g} um"})
    return _ratio_figure("life-misalignment", "Reference rating life against misalignment",
                         "misalignment [arcmin]", series,
                         f"6305 under F_r = {load:g} N with the inner ring tilted about the "
                         "axis across the load.  The balls first ride up the groove (their "
                         "deflection changes only to second order in the tilt) and L10r stays "
                         "flat; past a knee, 15 arcmin at zero clearance and later with "
                         "clearance, the opposite side of the ball set is squeezed and L10r "
                         "falls steeply.")


def ratio_figure(load: float = 2000.0) -> Figure:
    """L10r / L10 at zero clearance against Z, ball on / between the load line."""
    Zs = np.arange(6, 15)
    on, off = [], []
    for Z in Zs:
        D, dm = 0.0115, 0.0435 * max(1.0, Z / 7.0)
        brg = ballrace.BallBearing(D, int(Z), dm, 0.52, 0.53, diametral_clearance=0.0)
        C = float(ratings.dynamic_rating(brg, contact_angle=0.0))
        for store, off_ in ((on, 0.0), (off, np.pi / Z)):
            r = life.reference_rating_life(brg, brg.radial(load, azimuth_offset=off_),
                                           nominal_contact_angle=0.0)
            store.append(r.L10r / (C / load) ** 3)
    series = [{"x": Zs, "y": np.array(on), "label": "ball on load line"},
              {"x": Zs, "y": np.array(off), "label": "load between two balls"}]
    return _ratio_figure("life-ratio", "L10r / L10 for a pure radial load at zero clearance",
                         "balls Z", series,
                         "ISO/TS 16281 ties its raceway capacities to the catalogue C, so for "
                         "the zero-clearance (Stribeck) distribution L10r equals (C/F_r)^3 up "
                         "to the discreteness of the ball set: above 1 with a ball on the "
                         "load line, below with the load between two balls; the mean tends to "
                         "1 as Z grows.")


def _ratio_figure(fid: str, title: str, xlabel: str, series: list, caption: str) -> Figure:
    """A figure of curves of L10r / L10 (the ISO/TS 16281 reference life over the
    catalogue life)."""
    return Figure(fid, "life", title, caption=caption,
                  panels=({"kind": "lines", "title": "L10r / L10", "xlabel": xlabel,
                           "ylabel": "L10r / L10 [-]", "series": series},))


def life_figures(run=None) -> list[Figure]:
    """All life figures (``run`` is accepted for the report's calling convention)."""
    figs = []
    for fn in (aiso_figure, clearance_figure, misalignment_figure, ratio_figure):
        try:
            figs.append(fn())
        except Exception as exc:  # noqa: BLE001 - never let a figure break the report
            log.warning("life figure failed: %s", exc, exc_info=True)
            figs.append(Figure(f"life-{fn.__name__}", "life", "A life figure failed",
                               note=f"omitted: {type(exc).__name__}: {exc}"))
    return figs


def write_pngs(folder) -> list:
    """Draw the life figures as PNGs into ``folder`` (for docs/life.md); returns the paths.

    ``python -m ballrace.validation.figures_life docs`` regenerates the documentation
    images.  matplotlib is imported here only.
    """
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = []
    for f in life_figures():
        if not f.panels:
            continue
        p = f.panels[0]
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for s in p["series"]:
            ax.plot(s["x"], s["y"], lw=1.4, label=s.get("label"))
        for h in p.get("hlines", ()):
            ax.axhline(h["y"], ls="--", lw=0.8, color="k", alpha=0.6)
        if p.get("logx"):
            ax.set_xscale("log")
        if p.get("logy"):
            ax.set_yscale("log")
        ax.set_xlabel(p["xlabel"])
        ax.set_ylabel(p["ylabel"])
        ax.set_title(f.title, fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="best")
        fig.tight_layout()
        path = Path(folder) / f"{f.id}.png"
        fig.savefig(path, dpi=110)
        plt.close(fig)
        out.append(path)
    return out


if __name__ == "__main__":  # pragma: no cover - documentation images
    import sys

    for p in write_pngs(sys.argv[1] if len(sys.argv) > 1 else "."):
        sys.stdout.write(f"{p}\n")
