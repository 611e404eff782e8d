"""``ballrace bearing CASE.toml``: the shipped example cases and the case-file checks."""
import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballrace.analytic import life, ratings
from ballrace.casefiles import bearing as casefile
from ballrace.cli import app
from caseref import BEARING_209

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
runner = CliRunner()


def _run_json(path):
    res = runner.invoke(app, ["bearing", str(path), "--json"])
    assert res.exit_code == 0, res.output
    return json.loads(res.output)


def test_example_218_reproduces_ricci_2009():
    """Ricci (2009): 218 bearing, F_a = 17,800 N at e = 50.8 mm:
    Q_max = 9,445 N, beta 44.317 deg (psi = 0) to 16.169 deg (psi = 180 deg).  The case
    file states 4000 lbf = 17,793 N; a faithful implementation is expected
    within 1 % on load and 0.5 deg on angles."""
    r = _run_json(EXAMPLES / "bearing_218.toml")
    d = r["distribution"]
    assert d["max_ball_load"] == pytest.approx(9445.0, rel=0.01)
    beta = np.degrees(d["contact_angle"])
    assert beta[0] == pytest.approx(44.317, abs=0.5)
    assert beta[8] == pytest.approx(16.169, abs=0.5)          # psi = 180 deg
    assert r["bearing"]["axial_load"] == pytest.approx(4000 * ratings.LBF)
    # ratings at the 40 deg nominal angle
    assert r["ratings"]["C"] == pytest.approx(
        ratings.dynamic_rating(22.225e-3, 16, 125.26e-3, math.radians(40)), rel=1e-12)
    assert r["ratings"]["C0"] == pytest.approx(
        ratings.static_rating(22.225e-3, 16, 125.26e-3, math.radians(40)), rel=1e-12)
    # the eccentric thrust's moment makes the LP life far shorter than the catalog life
    assert r["life"]["LP_L10"] < 0.1 * r["life"]["L10"]
    assert any("moment" in n for n in r["notes"])


def test_example_209_radial():
    r = _run_json(EXAMPLES / "bearing_209.toml")
    d = r["distribution"]
    psi, Q = np.array(d["azimuth"]), np.array(d["ball_load"])
    Fr = 2000 * ratings.LBF
    assert np.sum(Q * np.cos(psi)) == pytest.approx(Fr, rel=1e-9)       # equilibrium
    # deep groove: rated at alpha = 0 although the clearance gives a free angle
    assert r["ratings"]["C"] == pytest.approx(ratings.dynamic_rating(0.0127, 9, 0.065))
    assert r["life"]["P"] == pytest.approx(Fr)
    assert r["life"]["L10"] == pytest.approx(life.l10(r["ratings"]["C"], Fr))
    assert r["life"]["L10h"] == pytest.approx(r["life"]["L10"] * 1e6 / (60 * 4000))
    # film: inner contact thinner than outer; Lambda from 0.175 / 0.075 um
    f = r["film"]
    assert f["h_min_inner"][0] < f["h_min_outer"][0]
    assert f["Lambda"] == pytest.approx(f["h_min"] / math.hypot(0.175e-6, 0.075e-6))
    assert f["entrainment_speed"][0] == pytest.approx(
        (0.065**2 - 0.0127**2) / (4 * 0.065) * 4000 * 2 * math.pi / 60)


def test_rich_output_runs():
    res = runner.invoke(app, ["bearing", str(EXAMPLES / "bearing_209.toml")])
    assert res.exit_code == 0, res.output
    assert "Load distribution" in res.output and "Life" in res.output


def _write(tmp_path, text):
    p = tmp_path / "case.toml"
    p.write_text(text)
    return p


GOOD = BEARING_209 + """diametral_clearance = "0 mm"
[loads]
radial = "5 kN"
[operation]
speed = "1500 rpm"
"""


@pytest.mark.parametrize("edit, message", [
    (('ball_diameter = "12.7 mm"', 'ball_diameter = "12.7 kg"'), "ball_diameter"),
    (('n_balls = 9', 'n_balls = 9\nn_bals = 3'), "n_bals"),
    (('speed = "1500 rpm"', 'speed = "25 Hz"'), "speed"),
    (('diametral_clearance = "0 mm"', ''), "diametral_clearance"),
    (('radial = "5 kN"', 'radial = "0 N"'), "both zero"),
    (('f_inner = 0.52', 'f_inner = 0.45'), "f_inner"),
])
def test_case_errors_are_clear(tmp_path, edit, message):
    p = _write(tmp_path, GOOD.replace(*edit))
    with pytest.raises(casefile.CaseFileError, match=message):
        casefile.load_case(p)
    res = runner.invoke(app, ["bearing", str(p)])
    assert res.exit_code == 2
    assert message in res.output


def test_good_case_and_missing_file(tmp_path):
    case = casefile.load_case(_write(tmp_path, GOOD))
    assert case.radial_load == 5000.0 and case.speed_rpm == pytest.approx(1500.0)
    with pytest.raises(casefile.CaseFileError, match="no such file"):
        casefile.load_case(tmp_path / "missing.toml")


# ----------------------------------------------------------------------------- nominal angle
def test_deep_groove_case_rated_at_nominal_zero(tmp_path):
    """Deep groove with 10 um clearance: free angle > 0, ratings at the nominal angle 0
    (ISO 281:2007); both angles in the JSON and the geometry table."""
    p = _write(tmp_path, GOOD.replace('"0 mm"', '"10 um"'))
    r = _run_json(p)
    b = r["bearing"]
    # cos a_f = 1 - P_d / (2 (f_i + f_o - 1) D) = 1 - 10e-6 / (2 x 0.04 x 12.7e-3)
    assert math.cos(b["free_contact_angle"]) == pytest.approx(1 - 10e-6 / 1.016e-3, rel=1e-12)
    assert b["nominal_contact_angle"] == 0.0
    assert r["ratings"]["C"] == pytest.approx(ratings.dynamic_rating(0.0127, 9, 0.065),
                                              rel=1e-12)
    assert r["iso"]["C"] == pytest.approx(r["ratings"]["C"], rel=1e-12)
    assert any("nominal contact angle 0.00 deg" in n for n in r["notes"])
    res = runner.invoke(app, ["bearing", str(p)], terminal_width=200)
    assert res.exit_code == 0, res.output
    line = next(x for x in res.output.splitlines() if "nominal contact angle" in x)
    assert line.split()[-2:] == ["0", "deg"]


def test_angular_contact_nominal_angle_key(tmp_path):
    """[bearing].nominal_contact_angle of an angular-contact bearing is the rating angle;
    without it, the free contact angle (the design angle)."""
    text = GOOD.replace('diametral_clearance = "0 mm"',
                        'type = "angular-contact"\nfree_contact_angle = "25 deg"')
    case = casefile.load_case(_write(tmp_path, text))
    assert case.nominal_contact_angle == pytest.approx(math.radians(25), rel=1e-14)
    case = casefile.load_case(_write(tmp_path, text.replace(
        'free_contact_angle = "25 deg"',
        'free_contact_angle = "25 deg"\nnominal_contact_angle = "15 deg"')))
    assert case.bearing.nominal_contact_angle == pytest.approx(math.radians(15), rel=1e-14)
    assert case.bearing.free_contact_angle == pytest.approx(math.radians(25), rel=1e-14)
    from ballrace.commands import bearing as bcli
    r = bcli.analyze(case)
    assert r["ratings"]["C"] == pytest.approx(
        ratings.dynamic_rating(0.0127, 9, 0.065, math.radians(15)), rel=1e-12)
    # an angular-contact bearing given by its clearance: its free angle is its design angle
    brg = ballrace_bearing(free_contact_angle=math.radians(25))
    clr = f'diametral_clearance = "{brg.diametral_clearance * 1e6!r} um"'
    case = casefile.load_case(_write(tmp_path, text.replace('free_contact_angle = "25 deg"',
                                                            clr)))
    assert case.nominal_contact_angle == pytest.approx(math.radians(25), rel=1e-9)


def ballrace_bearing(**kw):
    import ballrace
    return ballrace.BallBearing(0.0127, 9, 0.065, 0.52, 0.52, **kw)


@pytest.mark.parametrize("kind, value, message", [
    ("deep-groove", '"5 deg"', "deep-groove bearing is rated at 0 deg"),
    ("angular-contact", '"90 deg"', r"\[0, 90\) deg"),
    ("angular-contact", '"-5 deg"', r"\[0, 90\) deg"),
    ("angular-contact", '"15"', "unit"),
    ("angular-contact", '"15 mm"', "nominal_contact_angle"),
    ("angular-contact", "15", "nominal_contact_angle"),
])
def test_nominal_angle_key_errors(tmp_path, kind, value, message):
    p = _write(tmp_path, GOOD.replace(
        'diametral_clearance = "0 mm"',
        f'type = "{kind}"\ndiametral_clearance = "20 um"\nnominal_contact_angle = {value}'))
    with pytest.raises(casefile.CaseFileError, match=message):
        casefile.load_case(p)


@pytest.mark.parametrize("old, new, key", [
    ('ball_diameter = "12.7 mm"', 'ball_diameter = "12.7 kg"', "[bearing].ball_diameter"),
    ('f_inner = 0.52', 'f_inner = 0.52\nn_rows = 2\nname = ""', None),
])
def test_bearing_key_errors_name_the_file_once(tmp_path, old, new, key):
    """A unit error in a bearing key names the file and the key once (it was prefixed
    twice: "c.toml: [bearing]: c.toml: [bearing].ball_diameter")."""
    assert old in GOOD
    p = _write(tmp_path, GOOD.replace(old, new))
    if key is None:                       # the shared keys plus n_rows are accepted
        assert casefile.load_case(p).bearing.n_rows == 2
        return
    with pytest.raises(casefile.CaseFileError) as e:
        casefile.load_case(p)
    msg = str(e.value)
    assert msg.count(p.name) == 1 and msg.count(key) == 1, msg
