"""`ballrace shaft` and `ballrace bearing`: what an engineer reads first, and the flags on
numbers a design engineer would otherwise act on.

The overhung-gear case below is one locating 6208 (9 balls of 11.906 mm, d_e = 60 mm,
f = 0.52 / 0.53, 15 um clearance) carrying a 6 kN gear 140 mm away: 840 N m on one
deep-groove bearing.
"""
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

import ballrace
from ballrace.analytic import ratings
from ballrace.analytic import shaft as S
from ballrace.cli import app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

OVERHUNG = '''
title = "Overhung gear on one locating 6208"
kind = "shaft"

[shaft]
sections = [["170 mm", "40 mm", "0 mm"]]
material = { E = "200 GPa", nu = 0.3, density = "7850 kg/m^3" }

[bearings.b6208]
type = "deep-groove"
ball_diameter = "11.906 mm"
n_balls = 9
pitch_diameter = "60 mm"
f_inner = 0.52
f_outer = 0.53
diametral_clearance = "15 um"

[[seat]]
name = "A"
position = "10 mm"
bearing = "b6208"

[[load]]
name = "gear"
position = "150 mm"
Fy = "-6 kN"

[operation]
speed = "1500 rpm"
'''


def _ballrace(*args, columns=80):
    """The installed console script, stdout piped (not a terminal), COLUMNS fixed."""
    env = {**os.environ, "COLUMNS": str(columns)}
    exe = Path(sys.executable).with_name("ballrace")
    return subprocess.run([str(exe), *args], capture_output=True, text=True, env=env,
                          timeout=300)


def _json(*args):
    res = CliRunner().invoke(app, [*args, "--json"])
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


@pytest.fixture
def overhung(tmp_path):
    p = tmp_path / "overhung.toml"
    p.write_text(OVERHUNG)
    return p


# ----------------------------------------------------------------------- the 6208 finding
def test_overhung_6208_is_flagged(overhung):
    """Exit 0 (the result is computed), but: the three warnings on stderr, the s0, beta and
    tilt cells marked !, and the note that the ISO 281 life does not see the 840 N m."""
    res = _ballrace("shaft", str(overhung))
    assert res.returncode == 0, res.stderr
    err = res.stderr.splitlines()
    assert len(err) == 3, res.stderr
    assert err[0].startswith("warning: shaft seats[0] 'A' (x = 10 mm): static safety s0 = 0.796 < 1")
    assert "contact angles up to 39.4 deg (limit 30 deg" in err[1]
    assert "tilted 14 mrad (48.1 arcmin)" in err[2]
    out = res.stdout
    assert "0.796 !" in out and "39.4 !" in out and "14 !" in out
    flat = " ".join(out.split())                       # notes wrap at 80 columns
    assert "note: ! beyond a limit: s0 < 1" in flat
    assert ("A: the catalog equivalent load P = X Fr + Y Fa ignores the moment 840 N m the "
            "seat carries") in flat
    assert "so the ISO 281 life above is not conservative" in flat
    assert max(len(line) for line in out.splitlines()) <= 80


def test_overhung_json_numbers(overhung):
    """--json: s0 from the largest pressure, the limits, the seat's Fr and moment, and the
    gear's deflection and slope equal to a direct solve's displacement at x = 150 mm."""
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = _json("shaft", str(overhung))
    assert len(rec) == 3                                  # s0, contact angle, tilt
    s = r["seats"][0]
    assert s["static_safety"] == pytest.approx((4200e6 / s["max_pressure"]) ** 3, rel=1e-12)
    assert s["misalignment_limit"] == ratings.PERMISSIBLE_MISALIGNMENT["deep-groove"]
    assert s["contact_angle_limit"] == ratings.DEEP_GROOVE_ANGLE_LIMIT
    assert s["radial_load"] == pytest.approx(6000.0, rel=1e-9)
    assert s["moment"] == pytest.approx(840.0, rel=1e-9)          # 6 kN x 140 mm
    assert s["operating_clearance"] == pytest.approx(15e-6, rel=1e-12)
    brg = ballrace.BallBearing(11.906e-3, 9, 60e-3, 0.52, 0.53, diametral_clearance=15e-6)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = S.solve(S.Shaft([(0.17, 0.04, 0.0)], ballrace.Material(200e9, 0.3)),
                    [S.Seat(0.01, brg)], [S.PointLoad(0.15, Fy=-6000.0)])
    u = d.displacement(0.15)
    g = r["loads"][0]
    np.testing.assert_allclose(g["displacement"], u, rtol=1e-9, atol=1e-15)
    assert g["deflection"] == pytest.approx(math.hypot(u[1], u[2]), rel=1e-12)
    assert g["slope"] == pytest.approx(math.hypot(u[3], u[4]), rel=1e-12)


# ----------------------------------------------------------------------- the examples
def test_gearbox_table_at_80_columns_piped():
    """Nothing wider than 80 columns; Fr per seat; the floating seat's 1.7e-9 N of thrust
    (round-off of the solve) prints as 0 (the JSON keeps it); the gear's deflection and
    slope are in the table; no warning and no limit mark at this load."""
    res = _ballrace("shaft", str(EXAMPLES / "shaft_gearbox.toml"))
    assert res.returncode == 0 and res.stderr == "", res.stderr
    lines = res.stdout.splitlines()
    assert max(len(line) for line in lines) <= 80
    r = _json("shaft", str(EXAMPLES / "shaft_gearbox.toml"))
    fr = [s["radial_load"] for s in r["seats"]]
    assert fr == pytest.approx([math.hypot(*s["reaction"][1:3]) for s in r["seats"]], rel=1e-15)
    assert 0 < abs(r["seats"][1]["reaction"][0]) < 1e-6
    i = lines.index("Seats: forces carried (shaft frame)")
    head = lines[i + 2].split()
    assert head[:4] == ["seat", "x", "[mm]", "Fr"]
    row = next(line for line in lines[i:i + 8] if line.strip().startswith("B (floating)"))
    cells = row.split()                              # "B", "(floating)", x, Fr, Fa, ...
    assert cells[3] == f"{fr[1]:.5g}" and cells[4] == "0", row
    assert "Load points: shaft deflection and slope" in lines
    g = r["loads"][0]
    assert g["deflection"] == pytest.approx(math.hypot(g["displacement"][1],
                                                       g["displacement"][2]), rel=1e-15)
    row = next(line for line in lines if line.strip().startswith("helical gear"))
    assert f"{g['slope'] * 1e3:.4g}" in row.split()
    assert " !" not in res.stdout


def test_spindle_temperatures_that_change_nothing_are_a_note():
    """The spindle has one locating seat (the DB pair): its 8 K and 3 K change no load.
    The report says so in a note (not a warning); 0 K gives no note; 300 K is questioned
    on stderr, naming the key."""
    res = _ballrace("shaft", str(EXAMPLES / "shaft_spindle.toml"))
    assert res.returncode == 0 and res.stderr == "", res.stderr
    flat = " ".join(res.stdout.split())
    assert ("note: [operation] shaft_temperature_change = 8 K and housing_temperature_change "
            "= 3 K change nothing here: only one seat locates the shaft axially") in flat
    r = _json("shaft", str(EXAMPLES / "shaft_spindle.toml"))
    assert any("change nothing here" in n for n in r["notes"])
    assert r["seats"][0]["operating_clearance"] is None          # a preloaded pair


def test_spindle_temperature_variants(tmp_path):
    text = (EXAMPLES / "shaft_spindle.toml").read_text()
    cold = tmp_path / "cold.toml"
    cold.write_text(text.replace('"8 K"', '"0 K"').replace('"3 K"', '"0 K"'))
    assert not any("change nothing" in n for n in _json("shaft", str(cold))["notes"])
    hot = tmp_path / "hot.toml"
    hot.write_text(text.replace('"8 K"', '"300 K"'))
    res = _ballrace("shaft", str(hot))
    assert res.returncode == 0
    assert res.stderr.startswith("warning: shaft_temperature_change = 300 K: a uniform "
                                 "temperature change of more than 150 K"), res.stderr


def test_missing_shaft_material_is_said(tmp_path):
    p = tmp_path / "c.toml"
    text = (EXAMPLES / "shaft_gearbox.toml").read_text()
    line = 'material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }\n'
    assert text.count(line) == 1
    p.write_text(text.replace(line, ""))
    r = _json("shaft", str(p))
    m = ballrace.BEARING_STEEL
    assert r["shaft"]["material"]["E"] == m.E
    assert (f"[shaft].material not given: {m.name} assumed (E = 200 GPa, nu = 0.3, "
            "density = 7850 kg/m^3)") in r["notes"]
    full = _json("shaft", str(EXAMPLES / "shaft_gearbox.toml"))
    assert not any("[shaft].material" in n for n in full["notes"])


def test_plot_draws_both_lateral_planes(tmp_path):
    """The picture has the x-y and the x-z plane, each with its forces: the gear's
    Fy = -5000 N and Fz = -1884 N are both labelled."""
    import matplotlib

    from ballrace.commands.shaft import analyze, load_shaft_case, plot

    r = analyze(load_shaft_case(EXAMPLES / "shaft_gearbox.toml"))
    f = tmp_path / "s.svg"
    with matplotlib.rc_context({"svg.fonttype": "none"}):          # text stays text
        plot(r, f)
    svg = f.read_text()
    fz = r["loads"][0]["vector"][2]
    assert round(fz) == -1884
    assert "x-y plane" in svg and "x-z plane" in svg
    assert "-5000 N" in svg and f"{fz:.4g} N" in svg


# ----------------------------------------------------------------------- ballrace bearing
def test_bearing_film_outside_the_fit_range_is_marked():
    """209 example: k = 9.5 at the inner race, beyond the Hamrock-Dowson fits (1..8); the
    k, smallest h_min and Lambda cells and the inner h_min column are marked, with a note,
    without -v.  With f_i = 0.53 (k = 7.4) nothing is marked."""
    res = _ballrace("bearing", str(EXAMPLES / "bearing_209.toml"), columns=120)
    assert res.returncode == 0, res.stderr
    out = res.stdout
    assert "9.525 † / 7.393" in out
    assert "smallest h_min †" in out and "film parameter Lambda †" in out
    assert "h_min,i † [µm]" in out and "h_min,o [µm]" in out
    flat = " ".join(out.split())
    assert ("note: † extrapolated: the ellipticity parameter k = 9.52 (inner race) is outside "
            "the range 1 <= k <= 8") in flat
    r = _json("bearing", str(EXAMPLES / "bearing_209.toml"))
    assert r["film"]["extrapolated_inner"] and not r["film"]["extrapolated_outer"]


def test_bearing_film_inside_the_fit_range_is_not_marked(tmp_path):
    p = tmp_path / "c.toml"
    text = (EXAMPLES / "bearing_209.toml").read_text()
    assert text.count("f_inner = 0.52") == 1
    p.write_text(text.replace("f_inner = 0.52", "f_inner = 0.53"))
    r = _json("bearing", str(p))
    assert r["film"]["k_inner"] < 8 and not r["film"]["extrapolated_inner"]
    assert not any("extrapolated" in n for n in r["notes"])


def test_preloaded_bearing_s0_rows(tmp_path):
    """6305 with a 120 um shaft interference (a preload): s0 = C0/P0 comes from the
    external load only, so it is starred with the catalogue lives and the note names it;
    the stress-based s0 (which sees the preload) is the library's and is lower."""
    from ballrace.casefiles.bearing import load_case
    from ballrace.commands.bearing import analyze, sections

    p = tmp_path / "c.toml"
    p.write_text((EXAMPLES / "bearing_6305_iso.toml").read_text()
                 .replace('shaft_interference = "12 um"', 'shaft_interference = "120 um"'))
    case = load_case(p)
    r = analyze(case)
    lf = r["life"]
    rows = dict((n, v) for n, v, _ in sections(r)[1][1])
    assert rows["static safety s0 = C0/P0 *"] == lf["s0"]
    assert rows["static safety from p_max"] == lf["static_safety"]
    assert lf["static_safety"] == pytest.approx(
        (4200e6 / r["distribution"]["max_pressure"]) ** 3, rel=1e-12)
    assert lf["static_safety"] < lf["s0"]                  # the preload loads the balls
    note = next(n for n in r["notes"] if n.startswith("* the operating clearance"))
    assert "s0 = C0/P0 from P0 = X0 Fr + Y0 Fa" in note and "not its static safety" in note
    plain = analyze(load_case(EXAMPLES / "bearing_209.toml"))
    names = [n for n, _, _ in sections(plain)[1][1]]
    assert "static safety s0 = C0/P0" in names                       # no clearance: no star
    assert any(n.startswith("static safety: s0 = C0/P0 with P0 = X0 Fr + Y0 Fa (ISO 76") and
               "(4200 MPa / p_max)^3" in n for n in plain["notes"])
