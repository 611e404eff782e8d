"""Figure data of the FE sweep (validation/figures_fem.py) from a run's sweep points."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from ballrace.validation.figures import Figure
from ballrace.validation.figures_fem import (fem_figures, limits_figures, one_percent_limit,
                                             sweep_series)


def _point(f, load, a, err_a, angle=0.0, gap="hertz"):
    return {"ball_diameter": 12.7e-3, "f_inner": f, "f_outer": 0.52, "race": "inner",
            "load": load, "contact_angle": angle, "gap": gap, "a": a, "a_vs_hertz": err_a,
            "z0_vs_hertz": -err_a}


def test_sweep_series_groups_and_orders_by_conformity_measure():
    pts = [_point(0.53, 4000.0, 2.0e-3, 0.004), _point(0.515, 1000.0, 1.5e-3, -0.002),
           _point(0.53, 1000.0, 1.2e-3, 0.001), _point(0.515, 4000.0, 2.4e-3, 0.003),
           _point(0.53, 1000.0, 1.2e-3, 0.002, angle=np.radians(30.0))]
    s = sweep_series(pts, "a_vs_hertz")
    assert [x["label"] for x in s] == ["inner, f = 0.515, 0 deg", "inner, f = 0.530, 0 deg",
                                       "inner, f = 0.530, 30 deg"]
    # x = a / (f D), ascending; y in per cent
    assert s[0]["x"] == pytest.approx([1.5e-3 / (0.515 * 12.7e-3), 2.4e-3 / (0.515 * 12.7e-3)])
    assert s[0]["y"] == pytest.approx([-0.2, 0.3])
    assert s[1]["y"] == pytest.approx([0.1, 0.4])
    assert sweep_series(pts, "not_an_output") == []


def test_fem_figures_from_a_run_and_without_one():
    res = SimpleNamespace(id="sweep-x", calculation="fem.ball_on_race",
                          points=(_point(0.52, 1000.0, 1.4e-3, 0.001),
                                  _point(0.52, 4000.0, 2.2e-3, -0.003, gap="exact")))
    other = SimpleNamespace(id="hertz-x", calculation="hertz.point_contact", points=())
    figs = fem_figures(SimpleNamespace(results=(other, res)))
    assert len(figs) == 2 and isinstance(figs[0], Figure) and not figs[0].note
    # no Hertz-limits sweep in this run: its figure says how to get one
    assert figs[1].id == "fem-hertz-limits" and "make validate-sweep" in figs[1].note
    titles = [p["title"] for p in figs[0].panels]
    assert titles == ["a", "LP depth z0"]              # only the outputs present
    labels = [sr["label"] for sr in figs[0].panels[0]["series"]]
    assert labels == ["inner, f = 0.520, 0 deg", "inner, f = 0.520, 0 deg, exact gap"]
    assert "sweep-x" in figs[0].caption
    empty = fem_figures(SimpleNamespace(results=(other,)))
    assert empty[0].panels == () and empty[0].note


def _limits_run(level="quick"):
    """A synthetic fem.hertz_limits run (no FE): departure of a = -c (a/fD)^2 with c = 0.25
    (inner) and 0.4 (outer), the Hertz-gap error a constant 0.3 %."""
    pts = []
    for race, c in (("inner", 0.25), ("outer", 0.4)):
        for f in (0.515, 0.55):
            for s in (0.1, 0.15, 0.2, 0.3):
                pts.append({"race": race, "f": f, "a_over_fD": s, "a_beyond": -c * s * s,
                            "a_vs_hertz": 0.003, "approach_beyond": 0.02 * s,
                            "approach_vs_hertz": -0.001, "p_max_hertz": 2e9 * s / 0.2})
    res = SimpleNamespace(id="sweep-fem-hertz-limits-quick", calculation="fem.hertz_limits",
                          points=tuple(pts))
    return SimpleNamespace(results=(res,), fem=level)


def test_one_percent_limit_interpolates_the_first_crossing():
    run = _limits_run()
    pts = run.results[0].points
    # outer: |dep| = 0.4 s^2 is 0.9 % at 0.15 and 1.6 % at 0.2, 1 % at s = sqrt(0.025);
    # the interpolation in s^2 recovers a square law exactly
    x, text = one_percent_limit(pts, "a_beyond")
    assert x == pytest.approx(0.025 ** 0.5, rel=1e-12) and text == "0.16"
    inner = [p for p in pts if p["race"] == "inner"]
    assert one_percent_limit(inner, "a_beyond")[0] == pytest.approx(0.2)   # 0.25 * 0.2^2
    assert one_percent_limit(pts, "approach_beyond") == (pytest.approx(float("nan"),
                                                                       nan_ok=True), "> 0.3")
    big = [{**p, "a_beyond": 0.05} for p in pts]
    assert one_percent_limit(big, "a_beyond")[1] == "< 0.1"
    assert one_percent_limit(pts, "tau0_beyond")[1] == "n/a"


def test_limits_figures_draw_the_map_and_mark_the_1_percent_line():
    from ballrace.reports.plots import render_png

    beyond, errors = limits_figures(_limits_run())
    assert not beyond.note and not errors.note
    titles = [p["title"] for p in beyond.panels]
    assert titles[0] == "a: within 1 % below a/(fD) = 0.16"
    assert titles[1].startswith("delta") and titles[1].endswith("> 0.3")
    assert titles[-1].startswith("Hertz p0 of the points")
    a = beyond.panels[0]
    assert a["hband"] == 1.0                                  # the +/-1 % band
    assert a["vlines"][0]["x"] == pytest.approx(0.025 ** 0.5)
    assert beyond.panels[1]["vlines"] == []                   # never leaves the band
    assert [s["label"] for s in a["series"]] == ["inner, f = 0.515", "inner, f = 0.550",
                                                 "outer, f = 0.515", "outer, f = 0.550"]
    # one colour per conformity, race by line style; values in per cent
    assert a["series"][0]["color"] == a["series"][2]["color"] != a["series"][1]["color"]
    assert a["series"][2]["y"] == pytest.approx([-0.4, -0.9, -1.6, -3.6])
    assert beyond.panels[-1]["hlines"][0]["y"] == pytest.approx(4.2)
    assert "a 0.16" in beyond.caption and "delta > 0.3" in beyond.caption
    # the discretisation panels carry the level's tolerance band
    assert errors.panels[0]["hband"] == pytest.approx(100 * ballrace_fem_tol("quick", "a"))
    assert errors.panels[0]["series"][0]["y"] == pytest.approx([0.3] * 4)
    for fig in (beyond, errors):
        png = render_png(fig)
        assert png[:8] == b"\x89PNG\r\n\x1a\n"


def ballrace_fem_tol(level, q):
    from ballrace.fem import TOLERANCES

    return TOLERANCES[level][q]
