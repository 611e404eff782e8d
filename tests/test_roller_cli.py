"""Roller bearings through the boundary: roller case files (``[bearing] type =
"cylindrical-roller" / "tapered-roller"``), their analysis and ``ballrace bearing``."""
import json
import math
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballrace.analytic import life
from ballrace.analytic.roller import Crowned, RollerBearing
from ballrace.analytic.roller import ratings as rr
from ballrace.casefiles.analysis import analyze
from ballrace.casefiles.bearing import load_case
from ballrace.cli import app

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
NU210 = EXAMPLES / "bearing_nu210_roller.toml"
TAPERED = EXAMPLES / "bearing_tapered.toml"
runner = CliRunner()


def _ballrace(*args, columns=80):
    """The installed console script with its stdout piped (not a terminal)."""
    env = {**os.environ, "COLUMNS": str(columns)}
    exe = Path(sys.executable).with_name("ballrace")
    return subprocess.run([str(exe), *args], capture_output=True, text=True, env=env,
                          cwd=ROOT, timeout=300)


def _json(path):
    res = runner.invoke(app, ["bearing", str(path), "--json"])
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


# ------------------------------------------------------------------ case-file errors
CYL = """title = "t"
[bearing]
type = "cylindrical-roller"
roller_diameter = "13 mm"
roller_length = "11.8 mm"
n_rollers = 14
pitch_diameter = "70.65 mm"
diametral_clearance = "45 um"
{extra}
[loads]
radial = "6940 N"
axial = "{axial}"

[operation]
speed = "3000 rpm"
{tail}"""

BALL = """[bearing]
ball_diameter = "12.7 mm"
n_balls = 9
pitch_diameter = "65 mm"
f_inner = 0.52
f_outer = 0.52
diametral_clearance = "15 um"
{extra}
[loads]
radial = "2 kN"

[operation]
speed = "3000 rpm"
"""


def _case(tmp_path, text):
    p = tmp_path / "case.toml"
    p.write_text(text)
    return p


@pytest.mark.parametrize("text, key, example", [
    # an axial load on a cylindrical bearing: flanges not modelled
    (CYL.format(extra="", axial="500 N", tail=""), "[loads].axial", 'axial = "0 N"'),
    # an even slice count
    (CYL.format(extra="n_slices = 30", axial="0 N", tail=""), "[bearing].n_slices",
     "n_slices = 31"),
    (CYL.format(extra="n_slices = 3", axial="0 N", tail=""), "[bearing].n_slices",
     "n_slices = 31"),
    # a profile table in metres where millimetres were meant: outside the roller
    (CYL.format(extra='profile = { x = ["0 m", "3 m", "5.9 m"], drop = ["0 um", "1 um", '
                      '"6 um"] }', axial="0 N", tail=""),
     "[bearing].profile.x", 'x = ["0 mm", "4 mm", "5.9 mm"]'),
    # the same as a [bearing.profile] table, just beyond the half-length
    (CYL.format(extra='[bearing.profile]\nx = ["0 mm", "3 mm", "6.5 mm"]\n'
                      'drop = ["0 um", "1 um", "6 um"]', axial="0 N", tail=""),
     "[bearing].profile.x", "L_we/2 = 5.9 mm"),
    # drops in millimetres typed where micrometres were meant
    (CYL.format(extra='profile = { x = ["0 mm", "3 mm", "5.9 mm"], drop = ["0 mm", "1 mm", '
                      '"6 mm"] }', axial="0 N", tail=""),
     "[bearing].profile.drop", 'drop = ["0 um", "1 um", "6 um"]'),
    # a table entry without its unit
    (CYL.format(extra='profile = { x = [0, 3, 5.9], drop = ["0 um", "1 um", "6 um"] }',
                axial="0 N", tail=""), "[bearing].profile.x[0]", '"0 mm"'),
    (CYL.format(extra='profile = "crowned"', axial="0 N", tail=""), "[bearing].profile",
     'flat_length = "8 mm"'),
    (CYL.format(extra='profile = { flat_length = "8 mm" }', axial="0 N", tail=""),
     "[bearing].profile", 'crown_radius = "2 m"'),
    # a crown radius in millimetres where metres were meant: a drop of 1.4 mm at the end
    (CYL.format(extra='profile = { flat_length = "8 mm", crown_radius = "2 mm" }',
                axial="0 N", tail=""), "[bearing].profile.crown_radius", 'crown_radius = "2 m"'),
    (CYL.format(extra='profile = { flat_length = "8 mm", crown_radius = "1 mm" }',
                axial="0 N", tail=""), "[bearing].profile", 'crown_radius = "2 m"'),
    # a ball key given for a roller type ...
    (CYL.format(extra='ball_diameter = "13 mm"', axial="0 N", tail=""),
     "[bearing].ball_diameter", 'roller_diameter = "13 mm"'),
    (CYL.format(extra="f_inner = 0.52", axial="0 N", tail=""), "[bearing].f_inner",
     'roller_length = "11.8 mm"'),
    # ... and a roller key for a ball type (or no type at all)
    (BALL.format(extra='roller_length = "11.8 mm"'), "[bearing].roller_length",
     'type = "cylindrical-roller"'),
    (BALL.format(extra='type = "deep-groove"\nn_rollers = 14'), "[bearing].n_rollers",
     'type = "cylindrical-roller"'),
    # a cylindrical bearing with a contact angle; a tapered one without
    (CYL.format(extra='contact_angle = "15 deg"', axial="0 N", tail=""),
     "[bearing].contact_angle", 'type = "tapered-roller"'),
    (CYL.format(extra="", axial="0 N", tail="").replace("cylindrical-roller",
                                                        "tapered-roller"),
     "[bearing].contact_angle", 'contact_angle = "15 deg"'),
    # a tapered bearing whose axial load cannot hold the radial one
    (CYL.format(extra='contact_angle = "15 deg"', axial="500 N", tail="")
     .replace("cylindrical-roller", "tapered-roller"), "[loads].axial", "axial = \""),
    # sections of the ball path a roller case does not take
    (CYL.format(extra="", axial="0 N", tail='[fits]\nbore = "50 mm"\n'
                                           'outside_diameter = "90 mm"\n'),
     "[fits]", 'diametral_clearance = "30 um"'),
    (CYL.format(extra="", axial="0 N", tail='[lubricant]\nviscosity = "0.04 Pa*s"\n'
                                           'pressure_viscosity = "2.2e-8 1/Pa"\n'),
     "[lubricant]", "[oil]"),
    (CYL.format(extra="", axial="0 N", tail="[life]\nhardness_hrc = 60\n"),
     "[life].hardness_hrc", 'fatigue_limit = "9.4 kN"'),
    (CYL.format(extra="", axial="0 N", tail='[materials]\nroller = { E = "200 GPa", nu = 0.3 }'
                                           '\nring = { E = "210 GPa", nu = 0.3 }\n'),
     "[materials]", "the same E and nu"),
    (CYL.format(extra="", axial="0 N", tail='[materials]\nball = { E = "200 GPa", nu = 0.3 }\n'),
     "[materials].ball", 'roller = { E = "208 GPa", nu = 0.3 }'),
    (CYL.format(extra="", axial="0 N", tail="").replace('"13 mm"', "13"),
     "[bearing].roller_diameter", '"13 mm"'),
    (CYL.format(extra="", axial="0 N", tail="").replace("[loads]",
                                                        '[loads]\nmisalignment = "2 deg"'),
     "[loads].misalignment", 'misalignment = "2 arcmin"'),
])
def test_case_file_error_is_one_line_naming_file_key_and_example(tmp_path, text, key, example):
    p = _case(tmp_path, text)
    res = runner.invoke(app, ["bearing", str(p)])
    assert res.exit_code == 2, res.output
    err = res.stderr.strip()
    assert len(err.splitlines()) == 1, err
    assert err.startswith(f"error: {p}: {key}"), err
    assert example in err, err
    assert "Traceback" not in res.output


def test_case_file_error_in_python():
    """The reader raises CaseFileError (not ValueError) with the same line."""
    from ballrace.casefiles.bearing import parse_case
    from ballrace.errors import CaseFileError

    import tomllib
    data = tomllib.loads(CYL.format(extra="n_slices = 30", axial="0 N", tail=""))
    with pytest.raises(CaseFileError, match=r"^x\.toml: \[bearing\]\.n_slices must be odd"):
        parse_case(data, "x.toml")


# ------------------------------------------------------------------ examples run clean
@pytest.mark.parametrize("path", [NU210, TAPERED])
def test_examples_run_clean(path):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        a = analyze(load_case(path))
    assert a.values["life"]["L10r"] > 0
    res = _ballrace("bearing", str(path))
    assert res.returncode == 0 and res.stderr == "", res.stderr


# ------------------------------------------------------------------ --json = the Python API
def test_json_of_the_cylindrical_example_equals_the_api():
    r = _json(NU210)
    b = RollerBearing(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=14,
                      pitch_diameter=70.65e-3, diametral_clearance=45e-6, profile="iso",
                      n_slices=31)
    res = b.solve(Fy=6940.0, displacements=[None, None, None, 0.0, 0.0])
    d = r["distribution"]
    np.testing.assert_allclose(d["roller_load"], res.roller_loads, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(np.array(d["slice_loads"]), res.slice_loads, rtol=1e-12,
                               atol=1e-9)
    assert np.array(d["slice_loads"]).shape == (14, 31)
    np.testing.assert_allclose(d["azimuth"], b.azimuths(), rtol=1e-15)
    p = np.maximum(res.slice_pressures("inner").max(-1), res.slice_pressures("outer").max(-1))
    np.testing.assert_allclose(d["max_slice_pressure"], p, rtol=1e-12)
    assert d["edge_loaded"] == [bool(x) for x in res.edge_loaded]
    assert d["max_pressure"] == pytest.approx(float(res.max_pressure), rel=1e-12)
    # equilibrium: sum Q_j cos psi_j = F_r (independent of the solver's own check)
    assert np.sum(np.array(d["roller_load"]) * np.cos(d["azimuth"])) == pytest.approx(
        6940.0, rel=1e-9)
    C, C0 = b.dynamic_rating(), b.static_rating()
    assert r["ratings"]["C"] == pytest.approx(C, rel=1e-15)
    assert r["ratings"]["C0"] == pytest.approx(C0, rel=1e-15)
    lf = r["life"]
    assert lf["P"] == 6940.0 and lf["P0"] == 6940.0
    assert lf["L10"] == pytest.approx((C / 6940.0) ** (10 / 3), rel=1e-12)   # ISO 281 rollers
    assert lf["L10h"] == pytest.approx(lf["L10"] * 1e6 / (60 * 3000), rel=1e-12)
    assert lf["s0"] == pytest.approx(C0 / 6940.0, rel=1e-12)
    assert lf["static_safety"] == pytest.approx(float(res.static_safety), rel=1e-12)
    assert lf["static_safety"] == pytest.approx((4000e6 / float(res.max_pressure)) ** 2,
                                                rel=1e-12)
    ref = life.reference_rating_life(b, res, dynamic_rating=C)
    assert lf["L10r"] == pytest.approx(ref.L10r, rel=1e-12)
    assert lf["P_ref"] == pytest.approx(ref.P_ref, rel=1e-12)
    # a_ISO and L_nm from the example's oil (VG 68 at 70 degC) and cleanliness
    assert lf["C_u"] == pytest.approx(C0 / 8.2, rel=1e-12)
    assert lf["L_nm"] == pytest.approx(
        rr.modified_rating_life(C, 6940.0, kappa=lf["kappa"], contamination=lf["contamination"],
                                fatigue_limit=C0 / 8.2), rel=1e-12)
    assert lf["L10mr"] == pytest.approx(
        ref.modified(kappa=lf["kappa"], contamination=lf["contamination"],
                     fatigue_limit=C0 / 8.2), rel=1e-12)
    assert r["bearing"]["kind"] == "cylindrical-roller"
    assert any("flanges" in n for n in r["notes"])


def test_json_of_the_tapered_example_equals_the_api():
    r = _json(TAPERED)
    a = math.radians(14.0)
    b = RollerBearing(7.5e-3, 11.5e-3, 17, 46.5e-3, kind="tapered", contact_angle=a,
                      profile=Crowned(6e-3, 1.5), n_slices=31)
    Fr, Fa = 4000.0, 2500.0
    res = b.solve(Fa=Fa, Fy=Fr, displacements=[None, None, None, 0.0, 0.0])
    d = r["distribution"]
    np.testing.assert_allclose(d["roller_load"], res.roller_loads, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(np.array(d["slice_loads"]), res.slice_loads, rtol=1e-12,
                               atol=1e-9)
    np.testing.assert_allclose(d["rib_load"], res.rib_loads, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(d["loads"], res.loads, rtol=1e-12, atol=1e-6)
    # equilibrium along the axis: sum Q_j sin(alpha_o) = F_a
    assert np.sum(d["roller_load"]) * math.sin(a) == pytest.approx(Fa, rel=1e-9)
    # ISO 281: e = 1.5 tan a = 0.374 < Fa/Fr = 0.625: P = 0.4 Fr + 0.4 cot(a) Fa
    P = 0.4 * Fr + 0.4 / math.tan(a) * Fa
    lf = r["life"]
    assert lf["P"] == pytest.approx(P, rel=1e-12)
    assert (lf["X"], lf["Y"]) == (0.4, pytest.approx(0.4 / math.tan(a), rel=1e-12))
    C = b.dynamic_rating()
    assert lf["L10"] == pytest.approx((C / P) ** (10 / 3), rel=1e-12)
    # ISO 76: P0 = max(0.5 Fr + 0.22 cot(a) Fa, Fr)
    P0 = max(0.5 * Fr + 0.22 / math.tan(a) * Fa, Fr)
    assert lf["s0"] == pytest.approx(b.static_rating() / P0, rel=1e-12)
    assert lf["L10r"] == pytest.approx(
        life.reference_rating_life(b, res, dynamic_rating=C).L10r, rel=1e-12)
    # the example's crown leaves the most loaded rollers' ends loaded: flagged and noted
    assert d["edge_loaded"][0] is True
    assert any(n.startswith("edge loading (rollers 1,") for n in r["notes"])


def test_misalignment_is_held_and_tilts_the_rollers(tmp_path):
    p = _case(tmp_path, CYL.format(extra="", axial="0 N", tail="").replace(
        "[loads]", '[loads]\nmisalignment = "2 arcmin"'))
    r = _json(p)
    d = r["distribution"]
    theta = math.radians(2 / 60)
    assert d["displacements"][4] == pytest.approx(theta, rel=1e-12)
    # roller j tilts by half the raceway tilt theta cos(psi_j) (equal loads at both contacts)
    np.testing.assert_allclose(d["roller_tilt"], 0.5 * theta * np.cos(d["azimuth"]),
                               rtol=1e-12, atol=1e-18)
    assert r["bearing"]["misalignment"] == pytest.approx(theta)


# ------------------------------------------------------------------ the tables
@pytest.mark.parametrize("path, units", [(NU210, "eng"), (TAPERED, "eng"), (TAPERED, "us"),
                                         (NU210, "si")])
def test_table_fits_80_columns_without_ansi_codes(path, units):
    res = _ballrace("bearing", str(path), "--units", units, columns=80)
    assert res.returncode == 0, res.stderr
    out = res.stdout
    assert max(len(line) for line in out.splitlines()) <= 80
    assert "\x1b" not in out and "…" not in out
    # one table of rollers (not split into parts), one line per roller
    assert "(1/2)" not in out
    Z = 14 if path == NU210 else 17
    rows = [ln.split() for ln in out.splitlines()]
    numbered = [r[0] for r in rows if r and r[0].isdigit() and len(r) >= 6]
    assert numbered[:Z] == [str(j) for j in range(1, Z + 1)]
    assert "static safety s0 = C0/P0" in out and "reference life L10r" in out


def test_us_units_convert_the_roller_loads():
    res = _ballrace("bearing", str(NU210), "--units", "us")
    r = _json(NU210)
    row = next(ln.split() for ln in res.stdout.splitlines() if ln.split()[:1] == ["1"])
    assert float(row[2]) == pytest.approx(r["distribution"]["roller_load"][0] / 4.4482216152605,
                                          rel=1e-4)
    assert "Q [lbf]" in res.stdout


# ------------------------------------------------------------------ --plot
def test_plot_writes_a_png(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "rollers.png"
    res = runner.invoke(app, ["bearing", str(TAPERED), "--plot", str(out)])
    assert res.exit_code == 0, res.output
    assert f"picture: {out}" in res.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert out.stat().st_size > 10_000
    # with --json the output stays pure JSON
    out2 = tmp_path / "r2.png"
    res = runner.invoke(app, ["bearing", str(NU210), "--json", "--plot", str(out2)])
    assert res.exit_code == 0 and json.loads(res.stdout)["title"] and out2.is_file()


def test_plot_of_a_ball_case_is_refused(tmp_path):
    res = runner.invoke(app, ["bearing", str(EXAMPLES / "bearing_209.toml"), "--plot",
                              str(tmp_path / "x.png")])
    assert res.exit_code == 2
    assert "--plot" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "x.png").exists()
