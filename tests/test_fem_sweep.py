"""The "where Hertz holds" sweep: its case file, the load it picks, the min_rise reduction,
and two real quick-level sweep points (Hertz gap against the exact sphere–torus gap)."""
from __future__ import annotations

import importlib

import numpy as np
import pytest

import ballrace
from ballrace import fem
from ballrace.analytic import hertz
from ballrace.validation.schema import ON_DEMAND, load_cases, parse_cases
from caseref import case_header

CASE_FILE = "fem_hertz_limits.toml"


def _has_fem() -> bool:
    return all(importlib.util.find_spec(m) is not None for m in ("skfem", "gmsh", "meshio"))


needs_fem = pytest.mark.skipif(not _has_fem(), reason="needs the fem extra (skfem, gmsh, meshio)")


@pytest.fixture()
def _cache(tmp_path, monkeypatch):
    """A private mesh cache (never the user's)."""
    monkeypatch.setenv("BALLRACE_CACHE", str(tmp_path / "cache"))


def test_case_file_loads_and_is_on_demand():
    cases = load_cases(CASE_FILE)                  # found in the packaged case folder
    (quick,) = [c for c in cases if c.fem_levels == ("quick",)]
    assert quick.calculation == "fem.hertz_limits" and ON_DEMAND in quick.tags
    axes = dict(quick.sweep.axes)
    assert axes["race"] == ("inner", "outer")
    assert axes["f"][0] == 0.505 and axes["f"][-1] == 0.57
    # the last axis is the contact size: min_rise runs along it
    assert quick.sweep.axes[-1][0] == "a_over_fD"
    assert list(axes["a_over_fD"]) == sorted(axes["a_over_fD"])
    reducers = {new: how for new, how, _ in quick.sweep.reduce}
    assert reducers["max_err_a"] == "max_abs" and reducers["rise_a"] == "min_rise"
    for e in quick.expected:
        assert e.reason
        if e.name.startswith("max_err_"):
            tol = fem.TOLERANCES["quick"][e.name.removeprefix("max_err_")]
            assert e.max == pytest.approx(tol)       # the level's tolerance, not looser
    (std,) = [c for c in cases if c.fem_levels == ("standard",)]
    assert ON_DEMAND in std.tags and std.sweep.axes[-1][0] == "a_over_fD"
    for e in std.expected:
        if e.name.startswith("max_err_"):
            assert e.max == pytest.approx(fem.TOLERANCES["standard"][e.name[8:]])
    # the default selection (make validate) leaves the long sweep out
    ids = {c.id for c in load_cases()}
    assert not ids & {c.id for c in cases}
    assert "sweep-fem-race-conformity-load-angle" in ids


def test_min_rise_reduction_along_the_last_axis():
    from ballrace.validation.runner import reduce_points

    (case,) = parse_cases(case_header("rise", "min_rise", "hertz.point_contact") + '''\
inputs = {rx1 = "5 mm", ry1 = "5 mm", E1 = "200 GPa", nu1 = 0.3}
[case.sweep]
rx2 = ["4 mm", "6 mm"]
load = ["1 N", "2 N", "3 N"]
[case.reduce]
rise = "min_rise(a)"
[case.expected.rise]
min = "0 m"
reason = "a grows with the load"
''')
    # grid order: rx2 outer, load inner (last axis); |a| rises 1 -> 2 -> 4 and 3 -> 2.5 -> 5
    outs = [{"a": v} for v in (1.0, 2.0, 4.0, -3.0, 2.5, 5.0)]
    assert reduce_points(case, outs)["rise"] == pytest.approx(-0.5)
    outs = [{"a": v} for v in (1.0, 2.0, 4.0, 2.0, 2.5, 5.0)]
    assert reduce_points(case, outs)["rise"] == pytest.approx(0.5)


@pytest.mark.parametrize("race", ["inner", "outer"])
def test_limits_load_gives_the_requested_contact(race):
    from ballrace.validation.calc_fem import limits_load

    f = 0.53
    brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, f, f, free_contact_angle=0.0)
    cur = brg.curvature(race, 0.0)
    ep = ballrace.analytic.materials.effective_modulus(brg.material, brg.material)

    def contact(q):       # independent of fem.race_case: Hertz on the bearing's curvature
        return hertz.elliptical_contact(q, float(cur.Rx), float(cur.Ry), ep)

    q = limits_load(brg, race, 0.0, a_over_fD=0.3)
    assert float(contact(q).a) / (f * 12.7e-3) == pytest.approx(0.3, rel=1e-9)
    q = limits_load(brg, race, 0.0, p_max=4.2e9)
    assert float(contact(q).p_max) == pytest.approx(4.2e9, rel=1e-9)
    with pytest.raises(ValueError, match="exactly one"):
        limits_load(brg, race, 0.0)
    with pytest.raises(ValueError, match="a_over_fD"):
        limits_load(brg, race, 0.0, a_over_fD=1.2)


@needs_fem
def test_two_quick_sweep_points(_cache):
    """Two points of the sweep on the quick mesh (~10 s): the Hertz gap within the quick
    tolerance, the exact gap smaller and stiffer (its gap exceeds Hertz's by a quartic
    term), by more at the larger contact."""
    from ballrace.validation import registry

    calc = registry.get("fem.hertz_limits")
    kw = dict(ball_diameter=12.7e-3, pitch_diameter=65e-3, f=0.57, race="inner",
              contact_angle=0.0, E=200e9, nu=0.3, p_max=None, mode="half-space",
              level="quick")
    small, large = (calc.func(a_over_fD=s, **kw) for s in (0.15, 0.45))
    tol = fem.TOLERANCES["quick"]
    for out in (small, large):
        for q in ("a", "b", "p_max", "approach", "tau0", "z0"):
            assert abs(out[f"{q}_vs_hertz"]) <= tol[q], (q, out[f"{q}_vs_hertz"])
            # the difference is the exact-gap FE over the Hertz-gap FE, on one mesh
            assert (1 + out[f"{q}_exact_vs_hertz"]) / (1 + out[f"{q}_vs_hertz"]) - 1 == \
                pytest.approx(out[f"{q}_beyond"], rel=1e-9, abs=1e-12)
        assert out["a_beyond"] < 0 < out["p_max_beyond"] and out["approach_beyond"] > 0
    assert small["a_over_fD"] == pytest.approx(0.15) and large["a_over_fD"] == pytest.approx(0.45)
    assert np.abs(large["a_beyond"]) > 2 * np.abs(small["a_beyond"])
    assert large["p_max_beyond"] > 2 * small["p_max_beyond"]
