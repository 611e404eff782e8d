"""Figure data of the FE sweep (validation/figures_fem.py) from a run's sweep points."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from ballrace.validation.figures import Figure
from ballrace.validation.figures_fem import fem_figures, sweep_series


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
    assert len(figs) == 1 and isinstance(figs[0], Figure) and not figs[0].note
    titles = [p["title"] for p in figs[0].panels]
    assert titles == ["a", "LP depth z0"]              # only the outputs present
    labels = [sr["label"] for sr in figs[0].panels[0]["series"]]
    assert labels == ["inner, f = 0.520, 0 deg", "inner, f = 0.520, 0 deg, exact gap"]
    assert "sweep-x" in figs[0].caption
    empty = fem_figures(SimpleNamespace(results=(other,)))
    assert empty[0].panels == () and empty[0].note
