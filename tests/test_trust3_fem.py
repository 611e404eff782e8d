"""The FE check's verdict and flags (``FEResult.passed`` / ``valid`` / ``flags``, result.json)
and the package versions an FE result and a validation run record.

docs/fem.md "Verdict and flags": ``passed`` is None ("not checked") when the inputs lie
where the comparison with Hertz means nothing (a / R above hertz.SIZE_LIMIT) or when no
row has a tolerance (exact gap); ``within_tolerance`` keeps the rows' own verdict.
"""
from __future__ import annotations

import importlib.util
import json
import warnings

import pytest

import ballrace
from ballrace.analytic import hertz
from ballrace.fem import api


def _has_fem() -> bool:
    return all(importlib.util.find_spec(m) is not None for m in ("skfem", "gmsh", "meshio"))


@pytest.fixture(scope="module")
def brg209():
    # 209 radial bearing of Hamrock & Dowson (1981) Table 3.2; contact angle 0
    return ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)


def _result(case, gap="hertz", ok=True, tol=0.005, info=None):
    """An FEResult whose values are the analytic ones (the verdict logic only)."""
    c = case.analytic
    rows = [{"quantity": "a", "unit": "m", "fe": float(c.a), "analytic": float(c.a),
             "error": 0.0 if ok else 0.01, "tol": tol, "ok": ok},
            {"quantity": "b", "unit": "m", "fe": float(c.b), "analytic": float(c.b),
             "error": 0.0, "tol": tol, "ok": True}]
    z = 0.0
    return api.FEResult(case=case, mode="half-space", gap=gap, level="quick", a=float(c.a),
                        b=float(c.b), p_max=float(c.p_max), approach=float(c.approach),
                        approach_depth_point=z, approach_rigid=z, tau0=z, z0=z, tau_x0z0=z,
                        max_shear=z, max_shear_depth=z, von_mises=z, von_mises_depth=z,
                        n_dofs=1, timings={"total": 1.0}, solver="superlu", peak_rss=0,
                        comparison=rows, info=dict(info or {}))


def test_size_ratio_is_a_over_the_smallest_radius(brg209):
    # 209 inner race at 4450 N: a = 2.562 mm (race_case doctest); radii: ball D/2 =
    # 6.35 mm, groove f D = 6.604 mm, race (d_m - D)/2 = 26.15 mm; the smallest is D/2
    r = _result(api.race_case(brg209, 4450.0))
    assert r.size_ratio == pytest.approx(float(r.analytic.a) / (12.7e-3 / 2), rel=1e-12)
    assert r.size_ratio == pytest.approx(2.562 / 6.35, abs=0.001)


def test_ordinary_contact_passes_without_flags(brg209):
    r = _result(api.race_case(brg209, 4450.0))
    d = json.loads(json.dumps(r.to_dict()))
    assert d["flags"] == [] and d["valid"] is True
    assert d["passed"] is True and d["within_tolerance"] is True
    r = _result(api.race_case(brg209, 4450.0), ok=False)
    assert r.passed is False and r.to_dict()["passed"] is False


def test_beyond_hertz_load_is_not_a_pass(brg209):
    """1e9 N on the 209 inner race: a / R ~ 24.5 (a = 155.8 mm against D/2 = 6.35 mm);
    every row within its tolerance, yet the analytic column is an extrapolation."""
    case = api.race_case(brg209, 1e9)
    assert float(case.analytic.a) == pytest.approx(0.15578, rel=1e-3)   # (1e9/4450)^(1/3) a
    r = _result(case)
    d = json.loads(json.dumps(r.to_dict()))
    assert d["within_tolerance"] is True
    assert d["valid"] is False and d["passed"] is None
    (flag,) = d["flags"]
    assert flag["code"] == "beyond_hertz_size" and flag["invalidates"] is True
    assert f"{r.size_ratio:.3g}" in flag["message"] and "a << R" in flag["message"]
    assert d["size_ratio"] > hertz.SIZE_LIMIT


def test_exact_gap_has_no_verdict_but_is_valid(brg209):
    r = _result(api.race_case(brg209, 4450.0), gap="exact", tol=None)
    assert r.within_tolerance is None and r.passed is None and r.valid is True
    assert [f["code"] for f in r.flags] == ["exact_gap"]


def test_truncated_contact_is_flagged(brg209):
    r = _result(api.race_case(brg209, 4450.0), info={"pressure_at_grid_edge": True})
    assert r.valid is False and r.passed is None
    assert [f["code"] for f in r.flags] == ["pressure_at_grid_edge"]


def test_result_json_records_the_fe_package_versions(brg209):
    from importlib import metadata

    v = _result(api.race_case(brg209, 4450.0)).to_dict()["versions"]
    for p in ("gmsh", "scikit-fem", "meshio", "numpy", "scipy"):
        assert p in v
    assert v["numpy"] == metadata.version("numpy")


def test_validation_environment_records_the_fe_package_versions():
    """results.json ("environment") and the report's Environment table list them."""
    from ballrace.reports.html import render_html, results_dict
    from ballrace.validation.schema import load_cases
    from ballrace.validation.runner import run_cases

    run = run_cases(load_cases("subsurface.toml")[:1], serial=True)
    env = results_dict(run)["environment"]["packages"]
    for p in ("gmsh", "scikit-fem", "meshio", "numpy", "scipy", "pypardiso"):
        assert p in env
    html = render_html(run, plots=False)
    env_html = html[html.index('id="environment"'):]
    assert f"numpy {env['numpy']}" in env_html
    for p in ("gmsh", "scikit-fem", "meshio", "scipy"):
        assert f"{p} {env[p] or '—'}" in env_html


# --------------------------------------------------------------------------- CLI
def _invoke(monkeypatch, tmp_path, result, *args):
    from typer.testing import CliRunner

    from ballrace.cli import app

    monkeypatch.setattr(api, "run_case", lambda case, **kw: result)
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["fem", *args, "--no-render", "--out", str(out)])
    return res, json.loads((out / "result.json").read_text())


def test_cli_beyond_hertz_load_writes_the_flag_and_exits_1(monkeypatch, tmp_path, brg209):
    r = _result(api.race_case(brg209, 1e9))
    res, d = _invoke(monkeypatch, tmp_path, r, "--load", "1e9 N", "--level", "quick")
    assert res.exit_code == 1, res.output
    assert d["passed"] is None and d["valid"] is False
    assert d["flags"][0]["code"] == "beyond_hertz_size"
    text = " ".join(res.stdout.split())
    assert "note: a / R = " in text and "not checked" in text


def test_cli_exact_gap_exits_0_with_its_note(monkeypatch, tmp_path, brg209):
    r = _result(api.race_case(brg209, 4450.0), gap="exact", tol=None)
    res, d = _invoke(monkeypatch, tmp_path, r, "--gap", "exact", "--level", "quick")
    assert res.exit_code == 0, res.output
    assert d["passed"] is None and d["valid"] is True
    assert "note: exact gap" in " ".join(res.stdout.split())


def test_cli_ordinary_result_passes(monkeypatch, tmp_path, brg209):
    res, d = _invoke(monkeypatch, tmp_path, _result(api.race_case(brg209, 4450.0)),
                     "--level", "quick")
    assert res.exit_code == 0 and d["passed"] is True and d["flags"] == []
    assert "note:" not in res.stdout


# --------------------------------------------------------------------------- FE run
@pytest.mark.fem
@pytest.mark.skipif(not _has_fem(), reason="needs the fem extra (skfem, gmsh, meshio)")
def test_quick_fe_run_beyond_hertz_is_not_checked(tmp_path, monkeypatch):
    """A real quick-level run of a ball on a plane at 1 MN (a / R = 0.84): the half-space
    with Hertz's gap is self-similar in the load, so the rows agree with Hertz as at
    2000 N, but the verdict is "not checked"."""
    from ballrace import fem

    monkeypatch.setenv("BALLRACE_CACHE", str(tmp_path / "cache"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)       # point_contact's a/R warning
        r = fem.ball_on_plane(12.7e-3, 1e6, level="quick")
    # a = 0.4426 mm (1e6 / 2000)^(1/3) = 3.513 mm over R = 6.35 mm
    assert r.size_ratio == pytest.approx(0.5532, rel=1e-3)
    assert r.within_tolerance is True
    assert r.passed is None and r.valid is False
    d = json.loads(json.dumps(r.to_dict()))
    assert d["passed"] is None and d["flags"][0]["code"] == "beyond_hertz_size"
