"""Roller seats in shaft case files and the `ballrace shaft` command.

The two examples (a gearbox shaft on a locating deep-groove ball bearing and a floating
NU-type cylindrical roller bearing; a pinion shaft on a preloaded back-to-back tapered pair)
are read into the objects the Python API takes, run from the command line in table and
--json mode, and checked against statics and against the same shaft built by hand.  Bad
roller keys are one-line errors naming the key; a roller seat tilted beyond its permissible
misalignment, or edge loaded, is warned about.
"""
import json
import math
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballrace
from ballrace.analytic import shaft as S
from ballrace.analytic.roller import Crowned, RollerBearing, TaperedPair
from ballrace.analytic.roller import bearing as RB
from ballrace.analytic.roller.profile import ISO
from ballrace.casefiles.shaft import load_shaft_case, parse_shaft_case
from ballrace.cli import app
from ballrace.errors import CaseFileError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
GEARBOX = EXAMPLES / "shaft_gearbox_roller.toml"
PINION = EXAMPLES / "shaft_tapered_pair.toml"
runner = CliRunner()

STEEL = ballrace.Material(E=210e9, nu=0.3, density=7850.0)
G = S.STANDARD_GRAVITY


def _json(path):
    res = runner.invoke(app, ["shaft", str(path), "--json"])
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


@pytest.fixture(scope="module")
def gearbox_json():
    return _json(GEARBOX)


@pytest.fixture(scope="module")
def pinion_json():
    return _json(PINION)


# --------------------------------------------------------------------------- reading
def test_gearbox_case_reads_to_a_ball_and_a_cylindrical_seat_in_si():
    case = load_shaft_case(GEARBOX)
    a, b = case.seats
    assert isinstance(a.bearing, ballrace.BallBearing)
    cyl = b.bearing
    assert isinstance(cyl, RollerBearing) and cyl.kind == "cylindrical"
    for got, want in ((cyl.roller_diameter, 11e-3), (cyl.roller_length, 11.5e-3),
                      (cyl.pitch_diameter, 59.5e-3), (cyl.diametral_clearance, 30e-6),
                      (b.position, 0.245), (a.position, 0.015)):
        assert got == pytest.approx(want, rel=1e-12)
    assert cyl.n_rollers == 14 and cyl.n_slices == 31 and isinstance(cyl.profile, ISO)
    assert cyl.contact_angle == 0.0 and cyl.name == "nu208"
    assert b.direction == 1 and not b.floating and b.bearing.carries_axial is False
    assert case.ratings == (None, None)


def test_pinion_case_reads_to_a_preloaded_tapered_pair_in_si():
    case = load_shaft_case(PINION)
    (seat,) = case.seats
    pair = seat.bearing
    assert isinstance(pair, TaperedPair) and pair.arrangement == "DB"
    assert pair.preload == pytest.approx(3000.0, rel=1e-12) and pair.end_play == 0.0
    t = pair.bearing
    assert t.kind == "tapered" and t.n_rollers == 18 and t.n_slices == 31
    assert t.contact_angle == pytest.approx(math.radians(15.0), rel=1e-12)
    assert isinstance(t.profile, Crowned)
    assert t.profile.flat_length == pytest.approx(8e-3, rel=1e-12)
    assert t.profile.crown_radius == pytest.approx(1.5, rel=1e-12)
    assert seat.row_spacing == pytest.approx(0.06, rel=1e-12)
    assert seat.position == pytest.approx(0.095, rel=1e-12)


def _value(v) -> str:
    """A TOML value: strings, numbers, booleans, lists and inline tables."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {_value(x)}" for k, x in v.items()) + " }"
    return repr(v)


def _toml(doc: dict) -> str:
    """The TOML text of a shaft case dictionary of :func:`_doc` (sub-tables inline)."""
    out = [f"kind = {_value(doc['kind'])}", "[shaft]"]
    out += [f"{k} = {_value(v)}" for k, v in doc["shaft"].items()]
    for name, b in doc["bearings"].items():
        out += [f"[bearings.{name}]"] + [f"{k} = {_value(v)}" for k, v in b.items()]
    for table in ("seat", "load"):
        for item in doc.get(table, []):
            out += [f"[[{table}]]"] + [f"{k} = {_value(v)}" for k, v in item.items()]
    return "\n".join(out) + "\n"


def _doc(bearings: dict, seats: list, extra=None) -> dict:
    d = {"kind": "shaft", "shaft": {"sections": [["300 mm", "40 mm", "0 mm"]]},
         "bearings": bearings, "seat": seats,
         "load": [{"position": "150 mm", "Fy": "-2 kN", "Fa": "300 N"}]}
    d.update(extra or {})
    return d


BALL = {"type": "deep-groove", "ball_diameter": "12.7 mm", "n_balls": 9,
        "pitch_diameter": "60 mm", "f_inner": 0.52, "f_outer": 0.525,
        "diametral_clearance": "15 um"}
NU = {"type": "cylindrical-roller", "roller_diameter": "11 mm", "roller_length": "11.5 mm",
      "n_rollers": 14, "pitch_diameter": "59.5 mm", "diametral_clearance": "30 um"}
TAPERED = {"type": "tapered-roller", "roller_diameter": "9.5 mm", "roller_length": "14 mm",
           "n_rollers": 18, "pitch_diameter": "58 mm", "contact_angle": "15 deg"}
SEATS = [{"name": "A", "position": "10 mm", "bearing": "ball"},
         {"name": "B", "position": "290 mm", "bearing": "nu"}]


def test_profile_table_end_play_material_and_rating_are_read():
    nu = {**NU, "profile": {"x": ["0 mm", "4 mm", "5.75 mm"], "drop": ["0 um", "1 um", "8 um"]},
          "n_slices": 21, "material": {"E": "208 GPa", "nu": 0.3}, "dynamic_rating": "62 kN"}
    tp = {**TAPERED, "pair": "DF", "end_play": "40 um"}
    case = parse_shaft_case(_doc({"ball": BALL, "nu": nu, "tp": tp},
                                 SEATS + [{"position": "150 mm", "bearing": "tp",
                                           "row_spacing": "30 mm"}]))
    cyl = case.seats[1].bearing
    assert cyl.n_slices == 21 and cyl.material.E == pytest.approx(208e9, rel=1e-12)
    assert cyl.slice_drops.max() <= 8e-6 * (1 + 1e-12)          # the table, in metres
    assert case.ratings[1] == pytest.approx(62e3, rel=1e-12)
    pair = case.seats[2].bearing
    assert pair.arrangement == "DF" and pair.end_play == pytest.approx(40e-6, rel=1e-12)
    assert pair.preload_deflection == pytest.approx(-20e-6, rel=1e-12)   # half the end play


# --------------------------------------------------------------------------- the command
@pytest.mark.parametrize("path", [GEARBOX, PINION], ids=lambda p: p.stem)
def test_examples_run_in_table_and_json_mode(path):
    res = runner.invoke(app, ["shaft", str(path)], env={"COLUMNS": "100"})
    assert res.exit_code == 0, res.output
    assert "warning" not in res.output
    assert re.search(r"Q_max", res.stdout) and "roller" in res.stdout
    d = _json(path)
    assert all(s["rolling_element"] == "roller" for s in d["seats"] if "max_roller_load" in s)
    # the note explains the ball rule (4200 MPa, cubic) only where a ball seat is shown
    text = " ".join(res.stdout.split())
    has_ball = any(s.get("rolling_element") != "roller" for s in d["seats"])
    assert ("(4200 MPa / p_max)^3" in text) == has_ball
    assert "(4000 MPa / p_max)^2" in text


def _statics(d, weight_at=None):
    """(sum of the seat reactions, sum of the loads and the weight) as (Fa, Fy, Fz, My, Mz)
    about x = 0: a force F at x adds (0, -x F_z, x F_y) to the moments."""
    def about0(v, x):
        v = np.asarray(v, float)
        return v + np.array([0.0, 0.0, 0.0, -x * v[2], x * v[1]])

    R = sum(about0(s["reaction"], s["position"]) for s in d["seats"])
    F = sum(about0(p["vector"], p["position"]) for p in d["loads"])
    if weight_at is not None:
        F = F + about0([0.0, -d["shaft"]["mass"] * G, 0.0, 0.0, 0.0], weight_at)
    return R, F


def test_json_reactions_balance_the_loads(gearbox_json, pinion_json):
    # the gearbox shaft is symmetric (30 / 200 / 30 mm, ends alike): its weight acts at
    # L/2; the pinion shaft has no weight
    for d, xw in ((gearbox_json, 0.5 * gearbox_json["shaft"]["length"]), (pinion_json, None)):
        R, F = _statics(d, xw)
        scale = max(np.abs(F[:3]).max(), np.abs(F[3:]).max() / d["shaft"]["length"])
        assert np.abs(R - F).max() <= 1e-9 * scale * max(1.0, d["shaft"]["length"]), (R, F)


def test_cylindrical_seat_carries_no_axial_load(gearbox_json):
    a, b = gearbox_json["seats"]
    assert b["reaction"][0] == 0.0
    assert a["reaction"][0] == pytest.approx(sum(p["vector"][0] for p in gearbox_json["loads"]),
                                             rel=1e-9)
    assert b["bearing"] == "cylindrical" and b["carries_axial"] is False
    assert b["contact_angle_min"] == b["contact_angle_max"] == 0.0
    assert b["misalignment_limit"] == pytest.approx(math.radians(4 / 60), rel=1e-12)
    assert b["weibull_slope"] == 9 / 8 and b["life_exponent"] == pytest.approx(10 / 3)
    assert "max_ball_load" not in b and "max_roller_load" in b
    assert gearbox_json["life"]["seat_weibull_slopes"] == pytest.approx([10 / 9, 9 / 8])
    assert gearbox_json["life"]["weibull_slope"] is None          # the seats' slopes differ


def _by_hand_gearbox():
    ball = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
    cyl = RollerBearing(11e-3, 11.5e-3, 14, 59.5e-3, diametral_clearance=30e-6,
                        profile="iso", n_slices=31)
    s = S.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)], STEEL, n_elements=40)
    seats = [S.Seat(0.015, ball), S.Seat(0.245, cyl)]
    gear = S.gear_mesh(0.17, 6000.0, 0.12, pressure_angle=math.radians(20),
                       helix_angle=math.radians(15), mesh_azimuth=math.radians(90))
    return S.solve(s, seats, [gear], gravity=(0.0, -G, 0.0))


def _by_hand_pinion():
    t = RollerBearing(9.5e-3, 14e-3, 18, 58e-3, kind="tapered", contact_angle=math.radians(15),
                      profile=Crowned(8e-3, 1.5), n_slices=31)
    s = S.Shaft([(0.04, 0.05, 0.0), (0.11, 0.04, 0.0), (0.05, 0.035, 0.0)], STEEL, n_elements=40)
    seats = [S.Seat(0.095, TaperedPair(t, "DB", preload=3000.0), row_spacing=0.06)]
    loads = [S.gear_mesh(0.02, 8000.0, 0.05, pressure_angle=math.radians(20),
                         helix_angle=math.radians(25), mesh_azimuth=0.0),
             S.PointLoad(0.19, Fz=400.0)]
    return S.solve(s, seats, loads)


@pytest.mark.parametrize("which", ["gearbox", "pinion"])
def test_json_is_the_python_api_result(which, gearbox_json, pinion_json):
    # the same shaft built by hand in SI (the case file's unit strings parse to the same
    # numbers up to the last bits: 1e-9 relative)
    d, r = (gearbox_json, _by_hand_gearbox()) if which == "gearbox" else \
        (pinion_json, _by_hand_pinion())
    lf = S.rating_lives(r)
    scale = np.abs(r.reactions[:, :3]).max()
    for k, s in enumerate(d["seats"]):
        assert np.allclose(s["reaction"], r.reactions[k], rtol=1e-9, atol=1e-9 * scale)
        assert s["misalignment"] == pytest.approx(r.misalignment[k], rel=1e-6, abs=1e-12)
        assert s["static_safety"] == pytest.approx(r.static_safety[k], rel=1e-8)
        assert s["max_pressure"] == pytest.approx(r.max_pressure[k], rel=1e-8)
        assert s["L10r"] == pytest.approx(lf.seat_lives[k], rel=1e-8)
        if lf.catalog_lives[k] is None:
            assert s["L10_iso281"] is None
        else:
            assert s["L10_iso281"] == pytest.approx(lf.catalog_lives[k], rel=1e-8)
        rows = r.bearings[k] if isinstance(r.bearings[k], tuple) else (r.bearings[k],)
        if "max_roller_load" in s:
            Q = max(float(np.max(x.roller_loads)) for x in rows)
            assert s["max_roller_load"] == pytest.approx(Q, rel=1e-8)
            assert s["edge_load_ratio"] == pytest.approx(
                max(RB.edge_load_ratio(x.slice_loads) for x in rows), rel=1e-6, abs=1e-9)
    assert d["life"]["system"] == pytest.approx(lf.system, rel=1e-8)


def test_pair_table_row_names_the_pair_and_has_no_catalogue_life(pinion_json):
    (s,) = pinion_json["seats"]
    assert s["bearing"] == "tapered pair DB" and s["operating_clearance"] is None
    assert s["L10_iso281"] is None and s["weibull_slope"] == 9 / 8
    assert s["contact_angle_min"] == pytest.approx(math.radians(15), rel=1e-12)
    assert any("no ISO 281 catalogue life (its rows share the thrust" in n
               for n in pinion_json["notes"])
    assert pinion_json["life"]["weibull_slope"] == 9 / 8


def test_duty_cycle_with_a_roller_seat(tmp_path):
    text = GEARBOX.read_text() + """
[[duty]]
fraction = 0.5
speed = "1000 rpm"
load_factor = 1.2

[[duty]]
fraction = 0.5
speed = "2000 rpm"
load_factor = 0.6
"""
    p = tmp_path / "duty.toml"
    p.write_text(text)
    d = _json(p)
    assert d["duty"]["seat_weibull_slopes"] == pytest.approx([10 / 9, 9 / 8])
    # the system's L10 with two slopes: sum (L/L_i)^e_i = 1 (analytic.shaft.system_life)
    L, Ls = d["duty"]["system_hours"], d["duty"]["seat_hours"]
    assert sum((L / x) ** e for x, e in zip(Ls, (10 / 9, 9 / 8))) == pytest.approx(1.0, rel=1e-9)
    res = runner.invoke(app, ["shaft", str(p)])
    assert res.exit_code == 0 and "per seat" in res.stdout


# --------------------------------------------------------------------------- bad keys
BAD = [
    ({"nu": {**NU, "pair": "DB"}}, None, r"\[bearings\.nu\]\.pair: a pair is of tapered"),
    ({"nu": {**NU, "n_balls": 14}}, None, r"\[bearings\.nu\]\.n_balls is a ball-bearing key"),
    ({"ball": {**BALL, "roller_length": "10 mm"}}, None,
     r"\[bearings\.ball\]\.roller_length is a roller-bearing key"),
    ({"nu": {**NU, "n_slices": 30}}, None, r"\[bearings\.nu\]\.n_slices must be odd"),
    ({"nu": {**NU, "profile": "barrel"}}, None, r"\[bearings\.nu\]\.profile must be one of"),
    ({"nu": {**NU, "preload": "1 kN"}}, None, r"\[bearings\.nu\]\.preload: a preload needs pair"),
    ({"nu": {**TAPERED, "pair": "DT", "preload": "1 kN"}}, None, r"\[bearings\.nu\]\.pair"),
    ({"nu": {**TAPERED, "pair": "DB", "preload": "1 kN", "end_play": "20 um"}}, None,
     r"\[bearings\.nu\]: give a preload \[N\] or an end play \[m\], not both"),
    ({"nu": {k: v for k, v in TAPERED.items() if k != "contact_angle"}}, None,
     r"\[bearings\.nu\]\.contact_angle: a tapered roller bearing needs its cup angle"),
    ({"nu": {**NU, "roller_diameter": 11}}, None, r"\[bearings\.nu\]\.roller_diameter"),
    (None, {"direction": -1}, r'\[\[seat\]\] #2 \("B"\)\.direction: a thrust direction means '
                              r"nothing for a cylindrical roller bearing"),
    (None, {"offset": "5 um"}, r'\[\[seat\]\] #2 \("B"\)\.offset'),
    (None, {"floating": True, "spring_preload": "100 N"},
     r'\[\[seat\]\] #2 \("B"\)\.spring_preload'),
    (None, {"row_spacing": "10 mm"}, r'\[\[seat\]\] #2 \("B"\)\.row_spacing: a single'),
    (None, {"fits": {"bore": "40 mm", "outside_diameter": "80 mm"}},
     r'\[\[seat\]\] #2 \("B"\)\.fits: the operating clearance from fits is computed for ball'),
]


@pytest.mark.parametrize("bearings, seat_b, pattern", BAD)
def test_bad_roller_keys_are_one_line_errors_naming_the_key(tmp_path, bearings, seat_b,
                                                              pattern):
    brg = {"ball": BALL, "nu": NU, **(bearings or {})}
    seats = [SEATS[0], {**SEATS[1], **(seat_b or {})}]
    p = tmp_path / "bad.toml"
    p.write_text(_toml(_doc(brg, seats)))
    res = runner.invoke(app, ["shaft", str(p)])
    assert res.exit_code == 2, res.output
    err = res.stderr.strip()
    assert len(err.splitlines()) == 1, err
    assert err.startswith("error: ") and str(p) in err
    assert re.search(pattern, err), err


def test_clearance_on_a_tapered_pair_names_the_key():
    doc = _doc({"ball": BALL, "tp": {**TAPERED, "pair": "DB", "preload": "1 kN"}},
               [SEATS[0], {"name": "P", "position": "290 mm", "bearing": "tp",
                           "clearance": "10 um"}])
    with pytest.raises(CaseFileError, match=r'#2 \("P"\)\.clearance: a tapered pair DB keeps'):
        parse_shaft_case(doc, "x.toml")


def test_a_cylindrical_seat_may_be_floating_and_a_single_tapered_takes_a_direction():
    doc = _doc({"ball": BALL, "nu": NU, "t": TAPERED},
               [SEATS[0], {**SEATS[1], "floating": True},
                {"position": "150 mm", "bearing": "t", "direction": -1, "offset": "-5 um"}])
    case = parse_shaft_case(doc)
    assert case.seats[1].floating and case.seats[2].direction == -1
    assert case.seats[2].offset == pytest.approx(-5e-6, rel=1e-12)


# --------------------------------------------------------------------------- warnings
def _bent(F):
    """A 35 mm shaft, 300 mm long, on a ball bearing and the NU 208-size roller bearing,
    loaded at mid-span: the seats tilt with the shaft's slope, about F L^2 / (16 E I)."""
    ball = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
    cyl = RollerBearing(11e-3, 11.5e-3, 14, 59.5e-3, diametral_clearance=30e-6)
    s = S.Shaft([(0.3, 0.035, 0.0)], STEEL)
    seats = [S.Seat(0.01, ball, name="A"), S.Seat(0.29, cyl, name="B")]
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = S.solve(s, seats, [S.PointLoad(0.15, Fy=-F)])
    return r, [str(x.message) for x in w]


def test_tilt_warning_fires_for_a_misaligned_roller_seat_only():
    r, msgs = _bent(6000.0)
    lim = RB.PERMISSIBLE_MISALIGNMENT["cylindrical"]
    assert r.misalignment[1] > lim                      # some 1.9 mrad > 1.16 mrad
    assert r.misalignment[0] < ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT["deep-groove"]
    tilt = [m for m in msgs if "tolerates" in m]
    assert len(tilt) == 1 and "seats[1] 'B'" in tilt[0]
    assert "4 arcmin (1.16 mrad) a cylindrical roller bearing tolerates" in tilt[0]
    assert f"{r.misalignment[1] * 1e3:.3g} mrad" in tilt[0]
    r, msgs = _bent(1000.0)                               # the same shaft, aligned enough
    assert r.misalignment[1] < lim and not msgs


@pytest.mark.filterwarnings("ignore:shaft seats")
def test_tilt_warning_reaches_the_command_line(tmp_path):
    text = GEARBOX.read_text().replace('["200 mm", "48 mm", "0 mm"]', '["200 mm", "22 mm", "0 mm"]')
    p = tmp_path / "slender.toml"
    p.write_text(text)
    exe = Path(sys.executable).with_name("ballrace")      # the console script: warnings
    res = subprocess.run([str(exe), "shaft", str(p)], capture_output=True, text=True,
                         env={**os.environ, "COLUMNS": "100"}, timeout=300)
    assert res.returncode == 0, res.stderr
    d = _json(p)
    b = d["seats"][1]
    assert b["misalignment"] > b["misalignment_limit"]
    assert re.search(r"warning: shaft seats\[1\] 'B \(NU roller\)'.*cylindrical roller "
                     r"bearing tolerates", res.stderr)
    assert re.search(r"B \(NU roller\).*cylindrical\s+\S+\s+\S+\s+[\d.]+ !", res.stdout)


def test_edge_loading_within_the_permissible_tilt():
    # straight rollers, 2 um radial approach: a tilt of 0.5 mrad (within 4 arcmin) loads the
    # roller ends 2.4 times the most loaded roller's mean slice load; aligned, every slice
    # carries the same (ratio 1, no message)
    b = RollerBearing(11e-3, 11.5e-3, 14, 59.5e-3, profile="straight")
    aligned = b.solve(displacements=[0.0, 2e-6, 0.0, 0.0, 0.0])
    assert RB.edge_load_ratio(aligned.slice_loads) == pytest.approx(1.0, rel=1e-12)
    assert b.seat_warnings("B", [aligned], 0.0)[1:] == (None, None)
    tilted = b.solve(displacements=[0.0, 2e-6, 0.0, 0.0, 0.5e-3])
    ratio = RB.edge_load_ratio(tilted.slice_loads)
    assert ratio > RB.EDGE_LOAD_RATIO
    tilt_msg, edge_msg = b.seat_warnings("B", [tilted], 0.5e-3)[1:]
    assert tilt_msg is None and f"{ratio:.3g} times" in edge_msg
    # by definition: the largest end-slice load over Q_max / n_s
    q = tilted.slice_loads
    assert ratio == pytest.approx(max(q[:, 0].max(), q[:, -1].max())
                                  / (q.sum(-1).max() / b.n_slices), rel=1e-12)


def test_every_roller_seat_key_is_documented():
    from ballrace.casefiles.shaft import _roller_models

    text = (Path(__file__).resolve().parents[1] / "docs" / "casefiles.md").read_text()
    section = text[text.index("## Shaft case"):text.index("## FE case")]
    spec = _roller_models().model_fields["bearings"].annotation.__args__[1]
    spans = re.findall(r"`([^`\n]+)`", section)
    missing = [k for k in spec.model_fields
               if not any(re.search(rf"(?<![\w.-]){k}(?![\w-])", sp) for sp in spans)]
    assert not missing, missing
