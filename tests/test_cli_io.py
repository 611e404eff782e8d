"""What a new user meets at the command line.

Each test is one finding: a silent misread, a traceback, an unclear error or output that
does not fit a terminal.  CLI runs go through typer's CliRunner (stdout and stderr apart)
or a subprocess where the terminal width or a pipe matters.
"""
import json
import logging
import math
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballrace.cli import app
from ballrace.units import parse_quantity
from caseref import BEARING_209

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
runner = CliRunner()
CONTACT = ["contact", "--load", "4.45 N", "--rx1", "6.35 mm", "--ry1", "6.35 mm",
           "--ry2", "-6.604 mm"]


def _ballrace(*args, columns=80, **kw):
    """Run the installed console script with its stdout piped (not a terminal)."""
    env = {**os.environ, "COLUMNS": str(columns)}
    exe = Path(sys.executable).with_name("ballrace")
    return subprocess.run([str(exe), *args], capture_output=True, text=True, env=env,
                          cwd=kw.get("cwd"), timeout=120)


# ----------------------------------------------------------------- item 1: silent misreads
@pytest.mark.parametrize("text, why", [
    ("6,35 mm", "comma"),            # pint: 635 mm
    ("1,000 N", "comma"),            # pint: 1000 N, but 1.000 to a German reader
    ("6 35 mm", "one number"),       # pint: 210 mm
    ("3 mm*2", "one number"),        # pint: 6 mm
    ("mm", "does not start with a number"),
    ("1e400 mm", "not a finite"),    # overflows to inf
])
def test_strings_pint_reads_differently_are_refused(text, why):
    with pytest.raises(ValueError, match=why):
        parse_quantity(text, "[length]", "rx1")
    res = runner.invoke(app, ["contact", "--load", "5 N", "--rx1", text, "--ry1", "6.35 mm"])
    assert res.exit_code == 2
    assert res.stdout == "" and "rx1" in res.stderr and why in res.stderr


def test_decimal_comma_in_a_bearing_case_file(tmp_path):
    """Both the pint quantities and the speed of a bearing case file (40005 rpm to pint)."""
    base = (EXAMPLES / "bearing_209.toml").read_text()
    for old, new, key in (('"12.7 mm"', '"12,7 mm"', "[bearing].ball_diameter"),
                          ('"4000 rpm"', '"4000,5 rpm"', "[operation].speed")):
        assert old in base
        p = tmp_path / "case.toml"
        p.write_text(base.replace(old, new, 1))
        res = runner.invoke(app, ["bearing", str(p)])
        assert res.exit_code == 2
        assert key in res.stderr and "comma" in res.stderr


@pytest.mark.parametrize("text, dim, si", [
    ("6.35 mm", "[length]", 6.35e-3), ("-.5 in", "[length]", -0.0127),
    ("2.2e-8 1/Pa", "1 / [pressure]", 2.2e-8), ("7800 kg/m^3", "[mass] / [length] ** 3", 7800.0),
    ("7800 kg*m**-3", "[mass] / [length] ** 3", 7800.0), ("1.5e3 lbf", "[force]", 6672.3324229),
    ("1/4 in", "[length]", 6.35e-3), ("40°", "[angle]", math.radians(40)),
])
def test_ordinary_unit_strings_still_parse(text, dim, si):
    assert parse_quantity(text, dim, "x") == pytest.approx(si, rel=1e-10)


# ----------------------------------------------------------------- item 2: strict FE case files
FE_CASE = """
title = "209 inner race"
[case]
contact = "inner"
load = "2000 N"
""" + BEARING_209 + """[fem]
level = "standard"
"""


def test_fe_case_file_typo_is_an_error_naming_file_and_key(tmp_path):
    p = tmp_path / "fe.toml"
    p.write_text(FE_CASE.replace('load = "2000 N"', 'lod = "2000 N"'))
    res = runner.invoke(app, ["fem", str(p)])
    assert res.exit_code == 2
    assert f"{p}: [case].lod: Extra inputs are not permitted" in res.stderr
    p.write_text(FE_CASE.replace("[fem]\n", "[fem]\nsovler = \"amg\"\n"))
    res = runner.invoke(app, ["fem", str(p)])
    assert res.exit_code == 2 and "[fem].sovler" in res.stderr


def test_fe_case_file_kind_is_checked(tmp_path):
    res = runner.invoke(app, ["fem", str(EXAMPLES / "bearing_209.toml")])
    assert res.exit_code == 2
    assert "bearing case file" in res.stderr and "ballrace bearing" in res.stderr
    v = ROOT / "validation" / "cases" / "hertz.toml"
    res = runner.invoke(app, ["fem", str(v)])
    assert res.exit_code == 2 and "ballrace validate --cases" in res.stderr
    p = tmp_path / "fe.toml"
    p.write_text(FE_CASE)
    res = runner.invoke(app, ["bearing", str(p)])
    assert res.exit_code == 2 and "FE case file" in res.stderr and "ballrace fem" in res.stderr


def test_fe_case_file_toml_error_names_the_file(tmp_path):
    p = tmp_path / "broken.toml"
    p.write_text("[case\nload = 3\n")
    res = runner.invoke(app, ["fem", str(p)])
    assert res.exit_code == 2 and str(p) in res.stderr and "not valid TOML" in res.stderr


def test_flags_beside_a_case_file_take_precedence(tmp_path, monkeypatch):
    """The file says 2000 N at the standard level; --load and --level win."""
    from ballrace.fem import api
    from ballrace.fem.cli import load_fe_case

    p = tmp_path / "fe.toml"
    p.write_text(FE_CASE)
    fc = load_fe_case(p)
    assert (fc.case.load, fc.level, fc.contact) == (2000.0, "standard", "inner")
    fc = load_fe_case(p, load="3000 N", level="quick", contact="outer")
    assert (fc.case.load, fc.level, fc.contact) == (3000.0, "quick", "outer")
    assert fc.case.name == "ball on outer race"

    seen = {}

    def fake_run_case(case, level, mode, gap, solver=None, progress=None, **options):
        seen.update(load=case.load, name=case.name, level=level, mode=mode, gap=gap)
        raise ValueError("stop here")

    monkeypatch.setattr(api, "run_case", fake_run_case)
    res = runner.invoke(app, ["fem", str(p), "--load", "1000 lbf", "--level", "quick",
                              "--mode", "two-body", "--out", str(tmp_path / "o")])
    assert res.exit_code == 2 and "stop here" in res.stderr
    assert seen == {"load": pytest.approx(4448.2216152605, rel=1e-12), "name": "ball on inner race",
                    "level": "quick", "mode": "two-body", "gap": "hertz"}
    res = runner.invoke(app, ["fem", "--help"])
    assert "take precedence" in " ".join(res.stdout.split())


def test_fe_quick_run_from_a_case_file_with_a_flag_override(tmp_path, monkeypatch):
    """End to end at the quick level: the file's plane case at the flag's load; the table
    in engineering units within 80 columns; result.json in SI under --out."""
    pytest.importorskip("skfem")
    monkeypatch.setenv("COLUMNS", "80")
    p = tmp_path / "fe.toml"
    p.write_text('title = "[b]plane\\u001b[31m"\n[case]\ncontact = "plane"\nload = "2000 N"\n'
                 '[fem]\nlevel = "quick"\n')
    out = tmp_path / "out"
    res = runner.invoke(app, ["fem", str(p), "--load", "1 kN", "--no-render", "--out", str(out)])
    assert res.exit_code == 0, res.output
    data = json.loads((out / "result.json").read_text())
    assert data["load"] == 1000.0 and data["level"] == "quick" and data["case"] == "ball on plane"
    assert res.stdout.lstrip().startswith("[b]plane\\x1b[31m\n")                  # title, literally
    assert max(len(ln) for ln in res.stdout.splitlines() if not ln.startswith("wrote")) <= 80
    assert "(1/2)" not in res.stdout                 # one table, not split into parts
    # one row per quantity: name, FE, analytic, unit, "error% / tolerance% verdict";
    # parsed by pattern, not by the column widths the solver's digits happen to give
    row = re.compile(r"^\s*(\w+)\s+(\S+)\s+(\S+)\s+(\S+)\s+([+-]\d+\.\d\d)% / "
                     r"(\d+(?:\.\d+)?)% (ok|FAIL)\s*$")
    rows = {m[1]: m.groups() for m in map(row.match, res.stdout.splitlines()) if m}
    assert {"a", "b", "p_max", "approach", "tau0", "z0"} <= set(rows), res.stdout
    # Hertz a for a 12.7 mm steel ball on a steel flat at 1 kN: (3 F R / 4 E*)^(1/3)
    a = (3 * 1000 * 6.35e-3 / (4 * 200e9 / (2 * (1 - 0.3**2)))) ** (1 / 3)
    assert float(rows["a"][2]) == pytest.approx(a * 1e3, rel=1e-4) and rows["a"][3] == "mm"
    assert rows["p_max"][3] == "MPa"
    assert data["a"] == pytest.approx(float(rows["a"][1]) * 1e-3, rel=1e-4)   # SI in the JSON
    # the printed error is the FE value against the analytic one, as printed (rounding)
    fe, an = float(rows["a"][1]), float(rows["a"][2])
    assert float(rows["a"][4]) == pytest.approx(100 * (fe / an - 1), abs=0.02)
    assert rows["a"][6] == ("ok" if abs(float(rows["a"][4])) <= float(rows["a"][5]) else "FAIL")


@pytest.mark.parametrize("units", ["eng", "si", "us"])
def test_fe_table_fits_80_columns_whatever_the_digits(units, monkeypatch, capsys):
    """The widest numbers fmt() can print in each unit system, a failing row and the
    longest quantity name: still one table within 80 columns."""
    from ballrace.fem.cli import _table

    monkeypatch.setenv("COLUMNS", "80")

    class Wide:
        def to_dict(self):
            rows = [{"quantity": q, "fe": v * (1 + 1.234567e-5), "analytic": v * 1.0000987,
                     "unit": u, "error": e, "tol": t, "ok": ok}
                    for q, v, u, e, t, ok in (
                        ("approach_depth_point", 1.23456789e-5, "m", -0.5612, 0.125, False),
                        ("max_shear_depth", 9.87654321e-4, "m", 0.0123, 0.3, True),
                        ("p_max", 4.98765432e9, "Pa", -0.0345, 0.06, True),
                        ("tau_x0z0", 1.23456789e9, "Pa", 0.99, 0.15, False))]
            return {"comparison": rows, "case": "ball on ball", "load": 12345.678,
                    "mode": "two bodies", "gap": "hertz", "level": "standard",
                    "n_dofs": 278123, "timings": {"total": 123.4}, "solver": "superlu"}

    _table(Wide(), units)
    out = capsys.readouterr().out
    assert "(1/2)" not in out, out
    assert max(len(ln) for ln in out.splitlines()) <= 80, out
    assert out.count("FAIL") == 2 and out.count(" ok") == 2


def test_fe_case_plane_and_ball(tmp_path):
    from ballrace.analytic import hertz
    from ballrace.fem.cli import parse_fe_case

    fc = parse_fe_case({"case": {"contact": "plane", "load": "2 kN", "ball_diameter": "12.7 mm"},
                        "materials": {"ball": {"E": "310 GPa", "nu": 0.26}}})
    c = hertz.point_contact(2000.0, 6.35e-3, 6.35e-3, math.inf, math.inf,
                            __import__("ballrace").Material(310e9, 0.26))
    assert float(fc.case.analytic.a) == pytest.approx(float(c.a), rel=1e-12)
    from ballrace.casefiles.bearing import CaseFileError

    with pytest.raises(CaseFileError, match=r"\[bearing\] applies to inner \| outer"):
        parse_fe_case({"case": {"contact": "ball"}, "bearing": {
            "ball_diameter": "1 mm", "n_balls": 9, "pitch_diameter": "5 mm",
            "f_inner": 0.52, "f_outer": 0.52}})


# ----------------------------------------------------------------- item 3: a ball of metres
def test_ball_in_metres_warns_naming_the_unit():
    import ballrace

    with pytest.warns(UserWarning, match=r"metres \[m\].*millimetres"):
        ballrace.BallBearing(ball_diameter=12.7, n_balls=9, pitch_diameter=65.0, f_inner=0.52,
                             f_outer=0.52, free_contact_angle=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)


def test_bearing_case_in_metres_warns_in_one_line(tmp_path):
    p = tmp_path / "m.toml"
    p.write_text((EXAMPLES / "bearing_209.toml").read_text()
                 .replace('"12.7 mm"', '"12.7 m"').replace('"65 mm"', '"65 m"'))
    res = _ballrace("bearing", str(p), "--json")
    assert res.stderr.startswith("warning: ball_diameter = 12.7 m, pitch_diameter = 65 m: "
                                 "larger than any rolling bearing"), res.stderr
    assert "lengths are in metres [m]" in res.stderr.splitlines()[0]


# ----------------------------------------------------------------- item 4: one-line errors
@pytest.mark.parametrize("args, message", [
    (["fem", "--case", "inner", "--level", "quik"], "--level must be one of quick, standard, fine"),
    (["fem", "--solver", "foo"], "--solver must be one of cholmod, pardiso, amg, superlu"),
    (["fem", "--case", "innr"], "--case must be one of inner, outer, plane, ball, roller; got 'innr'"),
    (["fem", "--mode", "3d"], "--mode must be one of half-space, two-body"),
    (["fem", "convergence", "--sizes", "4,six"], "--sizes must be comma-separated integers"),
    (["bearing", str(EXAMPLES)], "is a directory"),
    (["fem", str(EXAMPLES)], "is a directory"),
    (["bearing", "nosuch.toml"], "no such file"),
    (["contact", "--load", "1 N", "--rx1", "1 mm", "--ry1", "1 mm", "--units", "cgs"],
     "--units must be one of eng, si, us"),
])
def test_bad_choices_are_one_line_errors(args, message):
    res = runner.invoke(app, args)
    assert res.exit_code == 2
    assert message in res.stderr
    assert res.stderr.count("\n") == 1 and "Traceback" not in res.output


# ----------------------------------------------------------------- item 5: messages
def test_dimension_text_is_not_eaten_by_markup():
    res = runner.invoke(app, ["teach", "subsurface", "--load", "5 kg"])
    assert res.exit_code == 2
    assert "expected a quantity of dimension [force] (e.g. N), got '5 kg' ([mass])" in res.stderr


def test_fem_help_says_one_way_to_name_the_case():
    text = " ".join(runner.invoke(app, ["fem", "--help"]).stdout.split())
    assert "inner | outer (ball on the 209 bearing's race) | plane | ball" in text
    assert not re.search(r"--race\b", text)          # (--raceway-radius is a roller option)


# ----------------------------------------------------------------- item 6: fail fast, stderr
def test_validate_missing_baseline_fails_before_running_anything(tmp_path):
    res = runner.invoke(app, ["validate", "--serial", "--baseline", str(tmp_path / "nosuch.json")])
    assert res.exit_code == 2
    assert "no such file" in res.stderr and res.stdout == ""      # no case ran


def test_validate_binary_baseline_is_named(tmp_path):
    b = tmp_path / "b.json"
    b.write_bytes(bytes(range(256)))
    res = runner.invoke(app, ["validate", "--serial", "--baseline", str(b)])
    assert res.exit_code == 2 and res.stdout == ""
    assert f"--baseline {b}: not a baseline or results JSON" in res.stderr


def test_validate_and_teach_errors_on_stderr(tmp_path):
    res = runner.invoke(app, ["validate", "--fem", "fast"])
    assert res.exit_code == 2 and "--fem must be one of" in res.stderr and res.stdout == ""
    res = runner.invoke(app, ["validate", "--cases", str(tmp_path / "none*.toml")])
    assert res.exit_code == 2 and "no case files match" in res.stderr
    res = runner.invoke(app, ["teach", "subsurface", "--rx1", "-1 mm"])
    assert res.exit_code == 2 and res.stderr.startswith("error: ")


# ----------------------------------------------------------------- item 7: version, -v, help
def test_version():
    import ballrace

    res = runner.invoke(app, ["--version"])
    assert res.exit_code == 0 and res.stdout.strip() == f"ballrace {ballrace.__version__}"


def test_verbose_after_the_command_and_without_library_debug():
    try:
        res = runner.invoke(app, ["fem", "-v", "--case", "innr"])
        assert res.exit_code == 2 and "--case must be one of" in res.stderr   # -v accepted
        assert logging.getLogger("ballrace").getEffectiveLevel() == logging.DEBUG
        assert logging.getLogger("skfem").getEffectiveLevel() == logging.WARNING
        res = runner.invoke(app, ["contact", *CONTACT[1:], "-vv", "--json"])
        assert res.exit_code == 0
        assert logging.getLogger("skfem").getEffectiveLevel() == logging.DEBUG
    finally:
        runner.invoke(app, ["contact", *CONTACT[1:], "--json"])   # back to quiet
    assert logging.getLogger("ballrace").getEffectiveLevel() == logging.WARNING


@pytest.mark.parametrize("cmd", [[], ["contact"], ["bearing"], ["fem"], ["validate"],
                                 ["teach", "subsurface"]])
def test_help_has_no_type_placeholders(cmd):
    res = runner.invoke(app, [*cmd, "--help"])
    assert res.exit_code == 0
    for placeholder in ("<bool>", "<str>", "<path>", "<int>"):
        assert placeholder not in res.stdout


# ----------------------------------------------------------------- item 8: output units
def test_contact_engineering_units_by_default_si_on_request():
    res = runner.invoke(app, CONTACT)
    assert res.exit_code == 0
    lines = {ln.split()[0] + " " + ln.split()[1]: ln.split() for ln in res.stdout.splitlines()
             if len(ln.split()) >= 3}
    # Hertz (1881) for this contact: p_max = 272.17 MPa, a = 0.25203 mm (test_cli's SI run)
    assert lines["a (semi-major)"][-2:] == ["0.252025", "mm"]
    assert lines["p_max 272.171"][-1] == "MPa"
    assert "e-0" not in res.stdout and "e+" not in res.stdout
    si = runner.invoke(app, CONTACT + ["--units", "si"]).stdout
    assert "0.000252025" in si and " Pa " in si
    us = runner.invoke(app, ["contact", "--load", "1000 lbf", "--rx1", "0.25 in", "--ry1",
                             "0.25 in", "--units", "us"]).stdout
    assert " 1000 " in us and "lbf" in us and "ksi" in us


def test_json_stays_si_whatever_the_units():
    a = json.loads(runner.invoke(app, CONTACT + ["--json"]).stdout)
    b = json.loads(runner.invoke(app, CONTACT + ["--json", "--units", "us"]).stdout)
    assert a == b
    assert a["units"]["p_max"] == "Pa" and a["units"]["a"] == "m"
    assert a["values"]["a"] == pytest.approx(0.252025e-3, rel=1e-5)
    # stable identifiers, each a HertzContact or subsurface attribute; labels for people
    from ballrace.cli import CONTACT_JSON_KEYS

    assert list(a["units"]) == list(CONTACT_JSON_KEYS) == list(a["labels"])
    assert all(k.isidentifier() for k in a["values"])
    assert a["labels"]["E_prime"] == "E' (= 2 E*)"


def test_bearing_tables_have_a_unit_in_every_column_header():
    from ballrace.commands.bearing import analyze, ball_columns
    from ballrace.casefiles.bearing import load_case

    r = analyze(load_case(EXAMPLES / "bearing_209.toml"))
    for units, length in (("eng", "mm"), ("si", "m"), ("us", "in")):
        headers, rows = ball_columns(r, units)
        assert all("[" in h for h in headers[1:]), headers
        assert f"a_i x b_i [{length}]" in headers
    headers, rows = ball_columns(r, "eng")
    # ball 1 of the 209 case: Q = 4520.8 N at psi = 0 (test_bearing_cli's equilibrium run)
    assert rows[0][:3] == ["1", "0", f"{r['distribution']['ball_load'][0]:.1f}"]
    assert rows[0][4] == f"{r['distribution']['p_max_inner'][0] / 1e6:.0f}"


@pytest.mark.parametrize("case, columns", [("bearing_209.toml", 80), ("bearing_218.toml", 80),
                                           ("bearing_218.toml", 60)])
def test_bearing_output_fits_a_narrow_pipe(case, columns):
    res = _ballrace("bearing", str(EXAMPLES / case), columns=columns)
    assert res.returncode == 0, res.stderr
    lines = res.stdout.splitlines()
    assert max(len(ln) for ln in lines) <= columns
    assert "…" not in res.stdout                      # nothing truncated
    assert "\x1b" not in res.stdout                   # no colour codes into a pipe
    # every per-ball row is whole: one line per ball in each part of the table
    n_balls = 9 if "209" in case else 16
    for ball in range(1, n_balls + 1):
        assert any(ln.split()[:1] == [str(ball)] for ln in lines)
    assert "Load distribution" in res.stdout and "Life" in res.stdout


def test_contact_output_fits_80_columns():
    res = _ballrace(*CONTACT, columns=80)
    assert res.returncode == 0 and max(map(len, res.stdout.splitlines())) <= 80


# ----------------------------------------------------------------- item 10: output folders
def test_teach_writes_under_the_ignored_output_folder(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.chdir(tmp_path)
    res = runner.invoke(app, ["teach", "subsurface", "--load", "1000 N"])
    assert res.exit_code == 0, res.output
    assert "wrote ballrace-out/teach/subsurface.png" in res.stdout
    png = tmp_path / "ballrace-out" / "teach" / "subsurface.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert list(tmp_path.iterdir()) == [tmp_path / "ballrace-out"]
    ignored = (ROOT / ".gitignore").read_text().split()
    assert "ballrace-out/" in ignored and "fem-out/" in ignored
    # outside this repository too: the output root carries its own .gitignore
    assert (tmp_path / "ballrace-out" / ".gitignore").read_text().splitlines()[-1] == "*"


def test_out_that_is_a_file_or_unwritable_is_one_line(tmp_path):
    """No raw errno text: the option, the path and what to do."""
    from ballrace.console import output_folder

    f = tmp_path / "afile"
    f.write_text("x")
    with pytest.raises(ValueError, match=r"^--out .*afile.* exists and is not a folder"):
        output_folder(f)
    with pytest.raises(ValueError, match=r"exists and is not a folder"):
        output_folder(f / "sub")
    res = runner.invoke(app, ["fem", "--out", str(f), "--no-render", "--level", "quick"])
    assert res.exit_code == 2 and "Errno" not in res.stderr
    assert "exists and is not a folder" in res.stderr and len(res.stderr.splitlines()) == 1
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        if os.access(ro, os.W_OK):                     # root ignores permissions
            import unittest.mock as um

            with um.patch("ballrace.console._writable", return_value=False):
                res = runner.invoke(app, ["teach", "subsurface", "--out", str(ro / "x.png")])
        else:
            res = runner.invoke(app, ["teach", "subsurface", "--out", str(ro / "x.png")])
    finally:
        ro.chmod(0o700)
    assert res.exit_code == 2 and "Errno" not in res.stderr, res.stderr
    assert "cannot write there" in res.stderr and "--out" in res.stderr


def test_teach_out_folder_or_bare_name(tmp_path):
    pytest.importorskip("matplotlib")
    res = runner.invoke(app, ["teach", "subsurface", "--out", str(tmp_path)])
    assert res.exit_code == 0 and (tmp_path / "subsurface.png").is_file()
    res = runner.invoke(app, ["teach", "subsurface", "--out", str(tmp_path / "fig")])
    assert res.exit_code == 0 and f"wrote {tmp_path / 'fig.png'}" in res.stdout
    assert (tmp_path / "fig.png").is_file()


def test_validate_refuses_a_folder_of_cases_and_a_file_as_report(tmp_path):
    res = runner.invoke(app, ["validate", "--cases", str(ROOT / "examples")])
    assert res.exit_code == 2 and "is a directory" in res.stderr and res.stdout == ""
    f = tmp_path / "file"
    f.write_text("x")
    res = runner.invoke(app, ["validate", "--fem", "none", "--report", str(f)])
    assert res.exit_code == 2 and "exists and is not a folder" in res.stderr


def test_bearing_binary_file_is_named(tmp_path):
    b = tmp_path / "case.toml"
    b.write_bytes(bytes(range(256)))
    res = runner.invoke(app, ["bearing", str(b)])
    assert res.exit_code == 2 and f"{b}: not a text file" in res.stderr


def test_fem_default_output_folder_is_ignored():
    from ballrace.fem.cli import DEFAULT_OUT

    assert DEFAULT_OUT.parts[0] == "ballrace-out"


# ----------------------------------------------------------------- item 11: install metadata
def test_pyproject_uses_spdx_license_and_lists_data_folders():
    import tomllib

    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert meta["project"]["license"] == "MIT" and (ROOT / "LICENSE").is_file()
    pk = meta["tool"]["setuptools"]
    for data in pk["package-data"]:
        assert data in pk["packages"]                 # else "absent from packages" warnings
        folder = ROOT.joinpath(*data.split(".")[1:])
        assert any(f for pattern in pk["package-data"][data] for f in folder.glob(pattern))


# ----------------------------------------------------------------- earlier regressions
NASTY = '[/bold] x [link=http://evil.example]click[/link] \\u001b]8;;http://e\\u001b\\\\y [m]'


def _bearing_case(tmp_path, title):
    p = tmp_path / "case.toml"
    p.write_text((EXAMPLES / "bearing_209.toml").read_text().replace(
        'title = "', f'title = "{title} ', 1))
    return p


def test_case_file_text_is_printed_literally(tmp_path):
    p = _bearing_case(tmp_path, NASTY)
    assert NASTY.split()[0] in p.read_text()
    res = runner.invoke(app, ["bearing", str(p)])
    assert res.exit_code == 0, res.output
    out = res.stdout
    assert "[/bold] x [link=http://evil.example]click[/link]" in out
    assert "\x1b" not in out and "\\x1b]8;;http://e\\x1b\\y [m]" in out
    res = _ballrace("bearing", str(p))                 # the real console, piped
    assert res.returncode == 0 and "\x1b" not in res.stdout and "[/bold] x" in res.stdout


def test_library_messages_keep_bracketed_units():
    from types import SimpleNamespace

    from rich.console import Console

    from ballrace.validation import cli as vcli

    msg = "approach 0.1 [m] at 0.2 [rad] outside [bold]tolerance[/bold] \x1b[31m"
    r = SimpleNamespace(id="case-[x]", status="fail", duration=0.1, ok=False, message=msg)
    run = SimpleNamespace(fem="none", duration=0.1, scheduler="serial", results=[r],
                          by_area=lambda: {"hertz": [r]})
    con = Console(width=200, record=True, force_terminal=False)
    vcli._summary(con, run)
    text = con.export_text()
    assert "approach 0.1 [m] at 0.2 [rad] outside [bold]tolerance[/bold] \\x1b[31m" in text
    assert "case-[x]" in text and "\x1b" not in text
    assert "case time [s]" in text                     # the column header keeps its unit
    assert "wall-clock 0.1 s" in text


def test_literal_escapes_controls_and_bidi_overrides_only():
    from ballrace.console import literal

    assert literal("a\u202eb\x1b[31mc\x07").plain == "a\\u202eb\\x1b[31mc\\x07"
    assert literal("tab\tnew\nline µm ≤ [m]").plain == "tab\tnew\nline µm ≤ [m]"


def test_a_new_block_of_bearing_rows_is_one_more_section():
    """How the ISO life rows join the bearing output: (title, [(name, SI, kind)])."""
    from rich.console import Console

    from ballrace.casefiles.bearing import load_case
    from ballrace.commands.bearing import analyze, sections
    from ballrace.console import print_sections

    secs = sections(analyze(load_case(EXAMPLES / "bearing_209.toml")))
    assert [t for t, _ in secs][1:3] == ["Life", "Lubricant film (Hamrock & Dowson 1977)"]
    assert secs[-1][0].startswith("Life: ISO 281:2007")       # the ISO block
    secs.append(("ISO 281 life", [("viscosity ratio kappa", 1.5, None),
                                  ("L_nm", 123.4, "=1e6 rev"),
                                  ("operating clearance", 10e-6, "small"),
                                  ("fatigue load limit C_u", 4448.2216152605, "force")]))
    for units, expect in (("eng", ["10   µm", "4448.22   N"]), ("us", ["393.701   µin",
                                                                       "1000   lbf"])):
        con = Console(width=80, record=True)
        print_sections(con, secs[-1:], units)
        text = con.export_text()
        assert "ISO 281 life" in text and "123.4   1e6 rev" in text and "1.5" in text
        for e in expect:
            assert e in text, text
