"""The validation framework: case files, runner, CLI exit codes, baselines, dask = serial."""
from __future__ import annotations

import json
import math
import textwrap

import pytest
from typer.testing import CliRunner

from ballrace.validation import registry
from ballrace.validation.baseline import compare_baseline, write_baseline
from ballrace.validation.runner import run_cases
from ballrace.validation.schema import CaseFileError, load_cases, parse_cases

STEEL_BALL = 'inputs = { load = "1000 N", rx1 = "5 mm", ry1 = "5 mm", E1 = "200 GPa", nu1 = 0.3 }'


def case(cid, expected='expected.a = { value = "0.3244 mm", rtol = 1e-3, reason = "4 digits" }',
         calc="hertz.point_contact", inputs=STEEL_BALL, kind="independent derivation",
         extra=""):
    return textwrap.dedent(f"""
        [[case]]
        id = "{cid}"
        title = "test case {cid}"
        kind = "{kind}"
        calculation = "{calc}"
        source = {{ author = "Johnson", year = 1985, reference = "eq. (4.22)" }}
        {inputs}
        {expected}
        {extra}
        """)


# a calculation whose library module does not exist: must be MISSING, never a pass
@registry.calculation("hertz.test_missing_module", requires=("ballrace.analytic.no_such_module",),
                      inputs={"x": registry.Param("")}, outputs={"y": ""})
def _missing(x):  # pragma: no cover - never runs
    return {"y": x}


# a fake FE calculation (no mesher): lets the tests exercise --fem handling quickly
@registry.calculation("fem.test_fake", fem=True,
                      inputs={"x": registry.Param(""), "level": registry.Param("str", "quick")},
                      outputs={"y": "", "level_is_quick": ""})
def _fake_fem(x, level):
    return {"y": 2.0 * x, "level_is_quick": float(level == "quick")}


@pytest.fixture
def small_set(tmp_path):
    """Five cases: pass, fail (wrong number), error (impossible geometry), missing, FE."""
    text = "".join([
        case("good"),
        case("wrong", 'expected.a = { value = "0.5 mm", rtol = 1e-3, reason = "deliberately wrong" }'),
        case("raises", inputs='inputs = { load = "1000 N", rx1 = "5 mm", ry1 = "5 mm", '
                              'rx2 = "-4 mm", ry2 = "-4 mm", E1 = "200 GPa", nu1 = 0.3 }'),
        case("no-module", 'expected.y = { value = 1.0, atol = 0, reason = "n/a" }',
             calc="hertz.test_missing_module", inputs="inputs = { x = 1.0 }"),
        case("fake-fe", 'expected.y = { value = 4.0, atol = 0, reason = "exact" }',
             calc="fem.test_fake", inputs="inputs = { x = 2.0 }", kind="FE check"),
    ])
    p = tmp_path / "small.toml"
    p.write_text(text)
    return p


def test_all_packaged_cases_load_and_cover_the_areas():
    cases = load_cases()
    assert len(cases) >= 40
    areas = {c.area for c in cases}
    assert {"hertz", "subsurface", "bearing", "life", "ehl", "kinematics", "highspeed",
            "fem"} <= areas
    kinds = {c.kind for c in cases}
    assert {"published", "independent derivation", "FE check"} <= kinds
    for c in cases:
        assert c.source.author and c.source.reference
        assert all(e.reason for e in c.expected)
    assert any(c.sweep is not None for c in cases)


def test_runner_statuses(small_set):
    run = run_cases(load_cases(str(small_set)), serial=True, fem="quick")
    status = {r.id: r.status for r in run.results}
    assert status == {"good": "pass", "wrong": "fail", "raises": "error",
                      "no-module": "missing", "fake-fe": "pass"}
    assert not run.ok
    wrong = next(r for r in run.results if r.id == "wrong")
    (c,) = wrong.comparisons
    assert not c.passed and c.expected == pytest.approx(0.5e-3)
    assert c.got == pytest.approx(0.3244e-3, rel=1e-3)
    assert c.rel_error == pytest.approx(0.3244 / 0.5 - 1, rel=1e-3)
    raises = next(r for r in run.results if r.id == "raises")
    assert "ValueError" in raises.message and "curvature" in raises.message
    missing = next(r for r in run.results if r.id == "no-module")
    assert "ballrace.analytic.no_such_module" in missing.message


def test_fem_none_skips_by_request_and_level_is_passed(small_set):
    cases = load_cases(str(small_set))
    run = run_cases(cases, serial=True, fem="none")
    fe = next(r for r in run.results if r.id == "fake-fe")
    assert fe.status == "skipped" and "by request" in fe.message
    run = run_cases(cases, serial=True, fem="standard")
    fe = next(r for r in run.results if r.id == "fake-fe")
    assert fe.status == "pass" and fe.outputs["level_is_quick"] == 0.0


def test_cli_exits_nonzero_and_shows_failures(small_set, tmp_path):
    from ballrace.cli import app

    res = CliRunner().invoke(app, ["validate", "--cases", str(small_set), "--serial",
                                   "--report", str(tmp_path / "rep"), "--no-plots"])
    assert res.exit_code == 1, res.output
    for token in ("FAIL", "ERROR", "MISSING", "wrong", "raises", "no-module",
                  "Validation summary", "validation FAILED"):
        assert token in res.output
    data = json.loads((tmp_path / "rep" / "results.json").read_text())
    assert data["summary"]["fail"] == 1 and data["summary"]["error"] == 1
    assert data["summary"]["missing"] == 1 and data["summary"]["ok"] is False


def test_cli_passes_when_all_pass(tmp_path):
    from ballrace.cli import app

    p = tmp_path / "ok.toml"
    p.write_text(case("only-good"))
    res = CliRunner().invoke(app, ["validate", "--cases", str(p), "--serial"])
    assert res.exit_code == 0, res.output
    assert "validation passed" in res.output


@pytest.mark.parametrize("mutate, message", [
    (lambda t: t.replace("hertz.point_contact", "hertz.nope"), "unknown calculation 'hertz.nope'"),
    (lambda t: t.replace('title = "test case c"\n', ""), "missing field 'title'"),
    (lambda t: t.replace('"1000 N"', '"1000 kg"'), "inputs.load: expected a quantity of dimension [force]"),
    (lambda t: t.replace('"5 mm"', '"5 parsecz"', 1), "cannot parse"),
    (lambda t: t.replace(', reason = "4 digits"', ""), "a tolerance needs a 'reason'"),
    (lambda t: t.replace("rtol = 1e-3, ", ""), "'value' needs a tolerance"),
    (lambda t: t.replace("expected.a", "expected.zz"), "has no output 'zz'"),
    (lambda t: t.replace('kind = "independent derivation"', 'kind = "hearsay"'), "kind: must be one of"),
    (lambda t: t.replace("source = {", "source = { colour = 1, "), "unknown field(s) colour"),
])
def test_case_file_errors_are_clear(mutate, message):
    with pytest.raises(CaseFileError) as exc:
        parse_cases(mutate(case("c")), "bad.toml")
    assert message in str(exc.value)
    assert str(exc.value).startswith("bad.toml")


def test_cli_reports_bad_case_file_with_exit_2(tmp_path):
    from ballrace.cli import app

    p = tmp_path / "bad.toml"
    p.write_text(case("c").replace("hertz.point_contact", "hertz.nope"))
    res = CliRunner().invoke(app, ["validate", "--cases", str(p), "--serial"])
    assert res.exit_code == 2 and "unknown calculation" in res.output


def test_bounds_and_tolerances():
    (c,) = parse_cases(case("b", 'expected.k = { min = 1.0, max = 1.0000001, reason = "circle" }'))
    run = run_cases([c], serial=True)
    assert run.results[0].status == "pass"
    (c,) = parse_cases(case("b", 'expected.k = { max = 0.5, reason = "impossible" }'))
    r = run_cases([c], serial=True).results[0]
    assert r.status == "fail" and r.comparisons[0].error == pytest.approx(0.5)


def test_baseline_roundtrip_and_drift(tmp_path):
    cases = parse_cases(case("base") + case("other", 'expected.p_max = { value = "4.5383 GPa", '
                                                     'rtol = 1e-4, reason = "5 digits" }'))
    run = run_cases(cases, serial=True)
    path = write_baseline(run, tmp_path / "baseline.json")
    same = compare_baseline(run_cases(cases, serial=True), path)
    assert same.ok and same.n_checked == 2 * len(run.results[0].outputs)
    # a different load moves every load-dependent output of one case beyond 1e-9
    moved_cases = parse_cases(case("base", inputs=STEEL_BALL.replace("1000 N", "1000.001 N"))
                              + case("other", 'expected.p_max = { value = "4.5383 GPa", '
                                              'rtol = 1e-4, reason = "5 digits" }'))
    drift = compare_baseline(run_cases(moved_cases, serial=True), path)
    assert not drift.ok
    names = {(m.case, m.output) for m in drift.moved}
    assert ("base", "a") in names and ("base", "load") in names
    assert ("base", "k") not in names          # load-independent: did not move
    assert all(m.case == "base" for m in drift.moved)


def test_cli_update_and_compare_baseline(tmp_path):
    from ballrace.cli import app

    p = tmp_path / "c.toml"
    p.write_text(case("one"))
    b = tmp_path / "b.json"
    r = CliRunner().invoke(app, ["validate", "--cases", str(p), "--serial", "--baseline", str(b),
                                 "--update-baseline"])
    assert r.exit_code == 0 and b.exists(), r.output
    data = json.loads(b.read_text())
    data["values"]["one"]["a"]["value"] *= 1.01
    b.write_text(json.dumps(data))
    r = CliRunner().invoke(app, ["validate", "--cases", str(p), "--serial", "--baseline", str(b)])
    assert r.exit_code == 1 and "Moved against baseline" in r.output, r.output


@pytest.fixture(scope="module")
def dask_client():
    from ballrace.validation.distributed import close, make_client

    client = make_client(workers=0)      # LocalCluster(processes=False)
    yield client
    close(client)


def test_dask_run_equals_serial_run(dask_client, small_set):
    cases = load_cases("hertz_approximations.toml") + load_cases(str(small_set))
    serial = run_cases(cases, serial=True)
    dist = run_cases(cases, client=dask_client)
    assert dist.scheduler.startswith("dask")
    for s, d in zip(serial.results, dist.results):
        assert (s.id, s.status) == (d.id, d.status)
        assert s.outputs == d.outputs                # bit for bit
        assert s.points == d.points
    sweep = next(r for r in dist.results if r.id == "sweep-hertz-approx-hb83")
    assert len(sweep.points) == 121 and sweep.status == "pass"


def test_sweep_reduction_is_the_max_over_points():
    (c,) = load_cases("hertz_approximations.toml")[-1:]
    r = run_cases([c], serial=True).results[0]
    errs = [abs(p["err_a"]) for p in r.points]
    assert r.outputs["max_abs_err_a"] == max(errs)
    assert r.points[0]["alpha_r"] == 1.0 and math.isclose(r.points[-1]["alpha_r"], 1e4)


def test_teach_subsurface_writes_png(tmp_path):
    pytest.importorskip("ballrace.analytic.subsurface")
    from ballrace.cli import app

    out = tmp_path / "t.png"
    r = CliRunner().invoke(app, ["teach", "subsurface", "--load", "1000 N", "--out", str(out)])
    assert r.exit_code == 0, r.output
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "max shear" in r.output and "0.31" in r.output


# ------------------------------------------------------------------ nothing that cannot fail
@pytest.mark.parametrize("expected, field", [
    ('expected.a = { value = "0.3244 mm", atol = "inf m", reason = "r" }', "expected.a.atol"),
    ('expected.a = { value = "1e400 m", rtol = 1e-3, reason = "r" }', "expected.a.value"),
    ('expected.a = { min = "-1e999 m", reason = "r" }', "expected.a.min"),
    ('expected.a = { max = "inf m", reason = "r" }', "expected.a.max"),
    ('expected.a = { value = "nan m", rtol = 1e-3, reason = "r" }', "expected.a.value"),
    ('expected.k = { value = nan, rtol = 1e-3, reason = "r" }', "expected.k.value"),
    ('expected.k = { max = inf, reason = "r" }', "expected.k.max"),
])
def test_expectations_that_cannot_fail_are_refused(expected, field):
    """Issue 14 item 0: these loaded and then passed whatever the code computed."""
    # "must be a finite number" (schema) or "is not a finite quantity" (unit parser)
    with pytest.raises(CaseFileError, match="must be a finite number|is not a finite quantity") as exc:
        parse_cases(case("c", expected), "inf.toml")
    assert field in str(exc.value) and str(exc.value).startswith("inf.toml")


def test_bound_with_min_above_max_is_refused():
    with pytest.raises(CaseFileError, match="min must not exceed max"):
        parse_cases(case("c", 'expected.k = { min = 2.0, max = 1.0, reason = "r" }'))


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
@pytest.mark.parametrize("key", ["value", "rtol", "atol"])
def test_baseline_entries_must_be_finite(tmp_path, key, bad):
    """Issue 14 item 0: a NaN or Infinity entry compared as 'unchanged' forever."""
    (c,) = parse_cases(case("base"))
    run = run_cases([c], serial=True)
    path = write_baseline(run, tmp_path / "b.json")
    data = json.loads(path.read_text())
    data["values"]["base"]["a"][key] = bad
    path.write_text(json.dumps(data))          # Python writes NaN / Infinity tokens
    with pytest.raises(ValueError, match=rf"values\['base'\]\['a'\]\.{key} must be a finite"):
        compare_baseline(run, path)


def test_baseline_tolerances_in_range(tmp_path):
    (c,) = parse_cases(case("base"))
    run = run_cases([c], serial=True)
    path = write_baseline(run, tmp_path / "b.json")
    original = path.read_text()
    for key, bad, msg in (("rtol", 1.5, r"rtol must be in \[0, 1\)"),
                          ("atol", -1e-9, "atol must be >= 0")):
        data = json.loads(original)
        data["values"]["base"]["a"][key] = bad
        path.write_text(json.dumps(data))
        with pytest.raises(ValueError, match=msg):
            compare_baseline(run, path)


@pytest.mark.parametrize("content", [bytes(range(256)) * 4, b"\x89PNG\r\n\x1a\n\x00\x00",
                                     b"not json at all", b"[1, 2, 3]"])
def test_cli_baseline_that_is_not_a_results_json(tmp_path, content):
    """Issue 14 item 10: a binary --baseline printed a UnicodeDecodeError text."""
    from ballrace.cli import app

    p = tmp_path / "c.toml"
    p.write_text(case("one"))
    b = tmp_path / "picture.png"
    b.write_bytes(content)
    r = CliRunner().invoke(app, ["validate", "--cases", str(p), "--serial", "--baseline", str(b)])
    assert r.exit_code == 2, r.output
    out = " ".join(r.output.split())
    assert "picture.png" in out and "is not a results JSON" in out, r.output
    assert "UnicodeDecodeError" not in r.output and "Traceback" not in r.output


def test_case_glob_ignores_folders(tmp_path, monkeypatch):
    """'fem*' run from the repository root also matched the fem/ folder (IsADirectoryError)."""
    from ballrace.validation.schema import load_cases

    (tmp_path / "fem").mkdir()
    monkeypatch.chdir(tmp_path)
    cases = load_cases("fem*")
    assert cases and all(c.area == "fem" for c in cases)


# ------------------------------------------------ the plain `pip install ballrace` path
def _without(monkeypatch, *modules):
    """Make ``validation.cli`` see ``modules`` as not installed."""
    from ballrace.validation import cli as vcli

    real = vcli.missing_modules
    monkeypatch.setattr(vcli, "missing_modules",
                        lambda *m: [x for x in m if x in modules] + real(*[x for x in m
                                                                          if x not in modules]))


def test_without_dask_fe_cases_run_serially_said_in_one_line(small_set, monkeypatch):
    """No dask (no [report] extra): the FE case runs in this process, with one line saying so."""
    from ballrace.cli import app

    _without(monkeypatch, "dask", "distributed")
    res = CliRunner().invoke(app, ["validate", "--cases", str(small_set)])
    assert res.exit_code == 1, res.output            # the small set holds failing cases
    assert "Traceback" not in res.output and "dask.distributed" not in res.output
    said = [ln for ln in res.output.splitlines() if "dask is not installed" in ln]
    assert len(said) == 1 and "ballrace[report]" in said[0]
    assert "fake-fe" in res.output and "validation FAILED" in res.output


@pytest.mark.parametrize("args, missing, message", [
    (["--workers", "2"], ("dask", "distributed"), "--workers needs dask.distributed"),
    (["--scheduler", "tcp://127.0.0.1:1"], ("dask", "distributed"), "--scheduler needs dask"),
    (["--report", "REP"], ("jinja2",), "--report needs jinja2"),
    (["--report", "REP"], ("matplotlib",), "(or add --no-plots)"),
])
def test_missing_optional_dependency_is_one_line_before_any_work(small_set, tmp_path, monkeypatch,
                                                                 args, missing, message):
    from ballrace.cli import app

    _without(monkeypatch, *missing)
    args = [str(tmp_path / "rep") if a == "REP" else a for a in args]
    res = CliRunner().invoke(app, ["validate", "--cases", str(small_set), *args])
    assert res.exit_code == 2
    assert res.stdout.count("\n") <= 1 and "running" not in res.stdout   # no case ran
    assert message in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "rep").exists()


def test_teach_without_matplotlib_names_the_extra(monkeypatch, tmp_path):
    from ballrace.cli import app

    _without(monkeypatch, "matplotlib")
    res = CliRunner().invoke(app, ["teach", "subsurface", "--out", str(tmp_path / "t.png")])
    assert res.exit_code == 2 and 'pip install "ballrace[report]"' in res.stderr
    assert not (tmp_path / "t.png").exists()
