"""Life figures (validation/figures_life.py): the a_ISO family and the ISO/TS 16281 curves."""
import numpy as np
import pytest

from ballrace.validation import figures, figures_life


@pytest.fixture(scope="module")
def figs():
    return {f.id: f for f in figures_life.life_figures()}


def test_figures_are_report_figures(figs):
    assert set(figs) == {"life-aiso", "life-clearance", "life-misalignment", "life-ratio"}
    for f in figs.values():
        assert isinstance(f, figures.Figure) and f.section == "life" and f.panels and not f.note


def test_aiso_family_matches_the_standard_figure(figs):
    """ISO 281:2007 Figure 14: curves ordered by kappa, rising with e_C C_u / P, capped at
    50; the kappa = 0.1 curve stays at 0.1 (2.5671 - 2.2649 / 0.1^0.054381 = 1e-4)."""
    series = figs["life-aiso"].panels[0]["series"]
    Y = np.array([s["y"] for s in series])
    assert np.all(np.diff(Y, axis=0) >= -1e-12)          # higher kappa, higher a_ISO
    assert np.all(np.diff(Y, axis=1) >= -1e-12)          # lighter load, higher a_ISO
    assert Y.max() == 50.0
    assert np.all(np.abs(Y[0] - 0.1) < 2e-3)
    # kappa = 4 reaches the cap at e_C C_u / P = 0.2311 (derived in tests/test_iso281.py)
    x = series[-1]["x"]
    assert x[np.argmax(Y[-1] >= 50.0)] == pytest.approx(0.2311, rel=0.03)


def test_clearance_optimum_is_a_slight_preload(figs):
    for s in figs["life-clearance"].panels[0]["series"]:
        best = s["x"][int(np.argmax(s["y"]))]
        assert -25.0 <= best < 0.0          # interior optimum (the curve starts at -30)


def test_misalignment_eventually_shortens_life(figs):
    for s in figs["life-misalignment"].panels[0]["series"]:
        assert s["y"][-1] < 0.5 * s["y"][0]


def test_ratio_tends_to_one(figs):
    on, off = figs["life-ratio"].panels[0]["series"]
    mean = 0.5 * (np.asarray(on["y"]) + np.asarray(off["y"]))
    assert np.all(np.abs(mean - 1.0) < 0.01)
    assert np.all(np.abs(np.asarray(on["y"])[-3:] - 1.0) < 0.01)
