"""Roller load distribution with clearance against Sjövall's load-zone integrals, the lamina
slices against the half-space line contact (validation/cases/roller_published.toml), and
the report's roller figures."""
import math

import numpy as np
import pytest

from ballrace.validation import calc_roller_published as crp
from ballrace.validation import figures_roller
from ballrace.validation.runner import run_cases
from ballrace.validation.schema import default_case_dir, load_case_file

CASE_FILE = default_case_dir() / "roller_published.toml"


@pytest.fixture(scope="module")
def run():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)      # s0 warnings of heavy cases
        return run_cases(load_case_file(CASE_FILE), serial=True, fem="none")


def test_every_case_passes_within_its_tolerance(run):
    assert len(run.results) == 11
    bad = [(r.id, r.status, r.message) for r in run.results if r.status != "pass"]
    assert not bad, bad
    areas = {r.area for r in run.results}
    assert areas == {"roller"}


def test_cases_compare_real_numbers(run):
    # every case has at least one comparison with a finite value, and the J_r cases state
    # both exponents: against 10/9 (J_r_vs_integral) and the table's 1.1 (J_r)
    for r in run.results:
        assert r.comparisons, r.id
        assert all(math.isfinite(float(r.outputs[c.name])) for c in r.comparisons), r.id
    for r in run.results:
        if r.id.startswith("roller-sjovall-jr-"):
            q = {c.name for c in r.comparisons}
            assert {"J_r", "J_r_vs_integral"} <= q, r.id


def test_radial_integral_reproduces_the_published_half_load_zone():
    # NSK, Rolling Bearings, technical section 5, eqs. (4), (5) and the text before them:
    # eps = 0.5 -> Q_max = 4.08 F_r / (Z cos a) (line), 4.37 (point);
    # F_a = 1.260 F_r tan a (line), 1.216 (point); tables for n = 1.1 and 1.5
    assert 1.0 / crp.radial_integral(0.5, 1.1) == pytest.approx(4.08, abs=0.005)
    assert 1.0 / crp.radial_integral(0.5, 1.5) == pytest.approx(4.37, abs=0.005)
    # 1.2595 by quadrature; the published 1.260 is the ratio of the 4-digit table entries
    # (rounded twice), so 1e-3
    assert (crp.axial_integral(0.5, 1.1) / crp.radial_integral(0.5, 1.1)
            == pytest.approx(1.260, abs=1e-3))
    assert (crp.axial_integral(0.5, 1.5) / crp.radial_integral(0.5, 1.5)
            == pytest.approx(1.216, abs=1e-3))


def test_radial_integral_limits():
    # eps -> infinity: every roller equal, J_r -> (1/2pi) int cos^+ ... = 0 for the radial
    # part of a uniform ring load; the axial integral -> 1 (NSK eq. (6): Q = F_a/(Z sin a))
    assert crp.axial_integral(1e6, 10 / 9) == pytest.approx(1.0, rel=1e-5)
    assert crp.radial_integral(1e6, 10 / 9) == pytest.approx(0.0, abs=1e-5)
    # eps = 1: the load reaches psi = 180 deg; J_r is continuous across it
    assert (crp.radial_integral(1.0 - 1e-9) == pytest.approx(crp.radial_integral(1.0 + 1e-9),
                                                              rel=1e-6))
    with pytest.raises(ValueError, match="eps"):
        crp.radial_integral(0.0)


def test_jr_method_at_zero_clearance_is_stribeck_continuous():
    # P_d = 0: eps = 0.5 and Q_max = F_r / (Z J_r(0.5)) whatever the stiffness
    Q, dr, eps = crp.jr_method(6940.0, 14, 3.5948e10 * 0.0118 ** (8 / 9), 0.0)
    assert eps == pytest.approx(0.5, abs=1e-12)
    assert Q == pytest.approx(6940.0 / (14 * crp.radial_integral(0.5)), rel=1e-9)


def test_discrete_method_equals_the_lamina_model_with_clearance():
    # the 210 bearing, 45 um: the 5-DOF lamina Newton solve against a scalar root
    from ballrace.analytic.roller import RollerBearing

    b = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=45e-6,
                      profile="straight", n_slices=5)
    r = b.solve(Fy=6940.0)
    Q, dr = crp.discrete_method(6940.0, r.azimuths, b.lamina_stiffness, 45e-6)
    assert float(np.max(r.roller_loads)) == pytest.approx(Q, rel=1e-9)
    assert float(r.radial_deflection) == pytest.approx(dr, rel=1e-9)
    assert Q == pytest.approx(2956.63, rel=1e-6)          # the value of the case file


def test_load_zone_half_angle_follows_eps():
    # clearance shrinks the load zone: psi_l = acos(1 - 2 eps) for eps <= 1
    out = crp.load_zone_integral(0.25, 10e-6, 1.1, roller_diameter=6e-3, roller_length=6e-3,
                                 n_rollers=120, pitch_diameter=0.3, n_slices=5,
                                 stiffness="iso", E=200e9, nu=0.3)
    assert out["clearance"] == pytest.approx(10e-6, rel=1e-12)
    assert math.radians(57.0) <= out["load_zone_half_angle"] <= math.radians(60.0)
    assert out["J_r_vs_integral"] == pytest.approx(0.0, abs=5e-4)


# ------------------------------------------------------------------ report figures
@pytest.fixture(scope="module")
def figs():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return {f.id: f for f in figures_roller.roller_figures()}


def test_roller_figures_build(figs):
    assert list(figs) == ["roller-stribeck", "roller-tilt-profiles", "roller-clearance"]
    for f in figs.values():
        assert f.section == "roller"
        assert not f.note, f.note
        assert f.panels


def test_stribeck_figure_series(figs):
    zero, clear = figs["roller-stribeck"].panels
    curve, model = zero["series"]
    assert curve["label"] == "Q_max cos(psi)^(10/9)"
    assert len(model["x"]) == 20
    # the model's loaded rollers lie on the curve Q_max cos^(10/9) psi
    qmax = float(np.max(model["y"]))
    expect = qmax * np.clip(np.cos(np.radians(model["x"])), 0, None) ** (10 / 9)
    np.testing.assert_allclose(model["y"], expect, rtol=1e-8, atol=1e-8 * qmax)
    assert 20 * qmax / 6000.0 == pytest.approx(4.084553291, rel=1e-8)
    assert len(clear["series"][1]["x"]) == 14


def test_tilt_profile_figure_series(figs):
    loads, press = figs["roller-tilt-profiles"].panels
    assert [s["label"] for s in loads["series"]] == ["straight", "iso", "lundberg"]
    labels = [s["label"] for s in press["series"]]
    for prof in ("straight", "iso", "lundberg"):
        assert f"{prof}: lamina" in labels
        assert any(lab.startswith(f"{prof}: half-space") for lab in labels)
    # under tilt the straight roller's load runs to one end: the end slices differ
    straight = loads["series"][0]["y"]
    assert straight[-1] > 2.0 * straight[0]


def test_clearance_figure_series(figs):
    q, life_ = figs["roller-clearance"].panels
    jr, model = q["series"]
    assert "J_r(eps) method" in jr["label"] and "lamina" in model["label"]
    x = np.asarray(model["x"])
    # Q_max grows with clearance beyond zero; the two methods agree within 4 %
    pos = x >= 0
    assert np.all(np.diff(np.asarray(model["y"])[pos]) > 0)
    np.testing.assert_allclose(model["y"], jr["y"], rtol=0.04)
    # the life, relative to zero clearance, is 1 at zero and falls with large clearance
    L = np.asarray(life_["series"][0]["y"])
    assert L[x == 0.0][0] == pytest.approx(1.0)
    assert L[-1] < 0.5


def test_load_distribution_figures_of_roller_cases_speak_of_rollers():
    from ballrace.validation import figures

    run = run_cases(load_case_file(CASE_FILE.with_name("roller.toml")), serial=True, fem="none")
    figs = [f for f in figures.bearing_figures(run) if f.id.startswith("bearing-roller-")]
    assert figs, "the roller cases with a load distribution give a figure"
    for f in figs:
        assert f.section == "roller" and f.panels[0]["title"] == "roller loads"
        assert f.panels[0]["series"][0]["label"] == "ballrace (per roller)"
