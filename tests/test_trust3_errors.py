"""Error and warning messages a user meets at the boundary: each names the option or the
case-file key once, quotes what was typed and gives a valid example of the right kind;
unit slips reach CLI users as one ``warning:`` line."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballrace.casefiles.bearing import key_text, parse_case

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
runner = CliRunner()


def _app():
    from ballrace.cli import app

    return app


def _main(args, cwd=None):
    """``ballrace ARGS`` through the console-script entry point (its warning format)."""
    code = (f"import sys\nsys.argv = ['ballrace', *{list(args)!r}]\n"
            "from ballrace.cli import main\nmain()\n")
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=cwd, env={**os.environ, "COLUMNS": "100"}, timeout=120)


CONTACT = ["contact", "--load", "1000 N", "--rx1", "6.35 mm", "--ry1", "6.35 mm"]


# ---------------------------------------------------------------------- contact: warnings
def test_modulus_slip_reaches_the_cli_user_as_one_line():
    """--E1 "200 MPa" (steel is 200 GPa) prints one warning line naming the option; the
    a/R note stays in the table (the size warning is not repeated on stderr)."""
    r = _main(CONTACT + ["--E1", "200 MPa"])
    assert r.returncode == 0, r.stderr
    assert r.stderr.splitlines() == [
        "warning: --E1 = '200 MPa' (0.2 GPa) is softer than the materials of rolling "
        "contacts (0.5 ... 2000 GPa); was '200 GPa' meant?"]
    assert "note: a / R" in r.stdout                  # 200 MPa: a/R = 0.553 > 0.5


def test_radius_slip_warns_with_the_millimetre_reading():
    with pytest.warns(UserWarning, match=r"^--rx1 = '6\.35 m' .* was '6\.35 mm' meant\?$"):
        res = runner.invoke(_app(), ["contact", "--load", "1000 N", "--rx1", "6.35 m",
                                     "--ry1", "6.35 mm"])
    assert res.exit_code == 0


def test_plausible_inputs_warn_nothing():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = runner.invoke(_app(), CONTACT + ["--rx2", "26 mm", "--ry2", "-6.604 mm"])
    assert res.exit_code == 0, res.output


def test_size_warning_is_a_table_note_only():
    """A contact far beyond a << R: the note is in the table, no warning on stderr."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = runner.invoke(_app(), ["contact", "--load", "100 kN", "--rx1", "1 mm",
                                     "--ry1", "1 mm"])
    assert res.exit_code == 0, res.output
    assert "note: a / R" in res.stdout


# ------------------------------------------------------------------- contact: errors
@pytest.mark.parametrize("args, expected", [
    (["--nu1", "0.6"], "error: --nu1: nu must be in (-1, 0.5) [-]; got 0.6 (steel: 0.3)"),
    (["--nu2", "-1.5"], "error: --nu2: nu must be in (-1, 0.5) [-]; got -1.5 (steel: 0.3)"),
    (["--E2", "-3 GPa"], "error: --E2: E must be"),
    (["--load", "1000"], "error: --load: give a unit with the number, e.g. '1000 N'; "
                         "got '1000'"),
    (["--load", "abc"], "error: --load: cannot parse 'abc' as a quantity: it does not start "
                        "with a number (e.g. '4450 N')"),
    (["--E1", "200"], "error: --E1: give a unit with the number, e.g. '200 GPa'"),
    (["--rx2", "inf N"], "error: --rx2: 'inf N': 'N' is not a unit of [length]; an infinite "
                         "length (a flat surface's radius) is written 'inf'"),
])
def test_contact_errors_name_the_option(args, expected):
    base = dict(zip(CONTACT[1::2], CONTACT[2::2]))
    for k, v in zip(args[::2], args[1::2]):
        base[k] = v
    res = runner.invoke(_app(), ["contact", *[x for kv in base.items() for x in kv]])
    assert res.exit_code == 2, res.output
    assert res.stderr.startswith(expected), res.stderr
    assert len(res.stderr.splitlines()) == 1


def test_inf_with_a_length_unit_is_a_flat():
    """--rx2 "inf mm" reads as the flat "inf" (as housing_diameter = "inf mm" in a case
    file): the same contact to the last bit."""
    out = []
    for rx2 in ("inf", "inf mm", "+inf m"):
        res = runner.invoke(_app(), CONTACT + ["--rx2", rx2, "--json"])
        assert res.exit_code == 0, res.output
        out.append(json.loads(res.stdout)["values"])
    assert out[0] == out[1] == out[2]


# ----------------------------------------------------------------------- unit examples
@pytest.mark.parametrize("dim, name, example", [
    ("[force]", "tangential_force", "'5000 N'"), ("[length]", "x", "'5000 mm'"),
    ("[pressure]", "[materials.ring].E", "'5000 GPa'"), ("[pressure]", "stress", "'5000 MPa'"),
    ("[angle]", "angle", "'5000 deg'"),
])
def test_bare_number_example_follows_the_dimension(dim, name, example):
    from ballrace.units import parse_quantity

    with pytest.raises(ValueError, match=f"^{name.replace('[', '.').replace(']', '.')}: give "
                                         f"a unit with the number, e.g. {example}$"):
        parse_quantity(5000, dim, name)


def _edited_example(example, path, old, new):
    """The example case file with its first ``old`` replaced by ``new``, written to path."""
    text = (EXAMPLES / example).read_text(encoding="utf-8")
    assert old in text
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    return path


def _shaft(tmp_path, old, new):
    return _edited_example("shaft_gearbox.toml", tmp_path / "s.toml", old, new)


def _one_error(args):
    res = runner.invoke(_app(), [str(a) for a in args])
    assert res.exit_code == 2, res.output
    lines = res.stderr.splitlines()
    assert len(lines) == 1, res.stderr
    return lines[0]


@pytest.mark.parametrize("old, new, expected", [
    ('tangential_force = "5 kN"', "tangential_force = 5000",
     '[[gear]] #1 ("helical gear").tangential_force: give the value with its unit as a '
     'string, e.g. "5000 N"; got 5000'),
    ('position = "245 mm"', 'position = "1245 mm"',
     '[[seat]] #2 ("B (floating)").position: must be within the shaft [0, 260 mm]; got '
     "'1245 mm'"),
    ('position = "245 mm"', 'position = "15 mm"',
     '[[seat]] #2 ("B (floating)").position: on top of [[seat]] #1 ("A (locating)") '
     "(x = 15 mm)"),
    ('shaft_interference = "10 um"', 'shaft_interference = "abc"',
     '[[seat]] #1 ("A (locating)").fits.shaft_interference: cannot parse \'abc\''),
    ('shaft_interference = "10 um"', "shaft_interference = 10",
     '[[seat]] #1 ("A (locating)").fits.shaft_interference: give the value with its unit '
     'as a string, e.g. "10 um"'),
    ('n_balls = 9', 'n_balls = "nine"',
     "[bearings.b6208].n_balls: give an integer without quotes or unit, e.g. n_balls = 9; "
     "got 'nine'"),
    ('material = { E = "210 GPa"', "material = { E = 210",
     '[shaft.material].E: give the value with its unit as a string, e.g. "210 GPa"; got 210'),
    ('material = { E = "210 GPa"', "material = { E = 2.1e11",
     '[shaft.material].E: give the value with its unit as a string, e.g. "2.1e+11 Pa"'),
])
def test_shaft_errors_name_file_and_key_once(tmp_path, old, new, expected):
    """Each shaft-file error names the file and the key once; entries of [[seat]] and
    [[gear]] by their position from 1 and their name; a bare force gets a force example."""
    p = _shaft(tmp_path, old, new)
    line = _one_error(["shaft", p])
    assert line.startswith(f"error: {p}: {expected}"), line
    assert line.count(str(p)) == 1 and line.count("s.toml") == 1


def test_a_shaft_file_given_to_bearing_points_at_shaft():
    p = EXAMPLES / "shaft_gearbox.toml"
    line = _one_error(["bearing", p])
    assert line == (f"error: {p}: this is a shaft case file (kind = \"shaft\": bearings on a "
                    f"shaft), not a bearing case file; run it with `ballrace shaft {p}`")


def test_a_bearing_file_given_to_shaft_points_at_bearing():
    """The reverse mistake, as before: one line."""
    line = _one_error(["shaft", EXAMPLES / "bearing_209.toml"])
    assert "run it with `ballrace bearing" in line


def _bearing(tmp_path, old, new):
    return _edited_example("bearing_209.toml", tmp_path / "b.toml", old, new)


@pytest.mark.parametrize("old, new, expected", [
    ("hardness_hrc = 58", 'hardness_hrc = 58\nreliability = "99 %"',
     "[life].reliability: give a fraction as a plain number, not a percentage: "
     "reliability = 0.99 for 99 %; got '99 %'"),
    ("hardness_hrc = 58", "hardness_hrc = 58\nreliability = 99",
     "[life].reliability: Input should be less than or equal to 0.9995; a fraction, not a "
     "percentage: 0.99 for 99 %"),
    ('viscosity = "0.04 Pa*s"', "viscosity = 0.04",
     '[lubricant].viscosity: give the value with its unit as a string, e.g. "0.04 Pa*s"; '
     'got 0.04'),
    ('pressure_viscosity = "2.2e-8 1/Pa"', "pressure_viscosity = 2.2e-8",
     '[lubricant].pressure_viscosity: give the value with its unit as a string, e.g. '
     '"2.2e-08 1/Pa"; got 2.2e-08'),
    ('diametral_clearance = "0.015 mm"', "diametral_clearance = 0.015",
     '[bearing].diametral_clearance: give the value with its unit as a string, e.g. '
     '"0.015 mm"; got 0.015'),
    ('radial = "2000 lbf"', 'radial = "-2000 lbf"',
     "[loads].radial must be >= 0 N; got '-2000 lbf' (e.g. \"8900 N\")"),
    ("hardness_hrc = 58", 'hardness_hrc = 58\n[oil]\nnu40 = "-68 cSt"\nnu100 = "8.7 cSt"\n'
                          'temperature = "70 degC"',
     "[oil].nu40 must be > 0; got '-68 cSt' (e.g. \"68 mm^2/s\")"),
])
def test_bearing_file_errors_give_an_example(tmp_path, old, new, expected):
    p = _bearing(tmp_path, old, new)
    line = _one_error(["bearing", p])
    assert line == f"error: {p}: {expected}", line


def test_a_soft_modulus_is_named_before_the_loads_fail(tmp_path):
    """ring = { E = "200 MPa" }: a warning naming [materials.ring].E comes first (the load
    distribution then fails on the 1000-times-softer rings)."""
    p = _bearing(tmp_path, 'ring = { E = "200 GPa"', 'ring = { E = "200 MPa"')
    import tomllib

    data = tomllib.loads(p.read_text(encoding="utf-8"))
    with pytest.warns(UserWarning) as rec:
        parse_case(data, "b.toml")
    msgs = [str(w.message) for w in rec]
    assert msgs == ["b.toml: [materials.ring].E = '200 MPa' (0.2 GPa) is softer than the "
                    "materials of rolling contacts (0.5 ... 2000 GPa); was '200 GPa' meant?"]
    r = _main(["bearing", str(p)])
    assert r.returncode == 2
    lines = r.stderr.splitlines()
    assert lines[0].startswith("warning: ") and "[materials.ring].E" in lines[0]
    assert lines[1].startswith("error: ") and len(lines) == 2


def test_key_text_of_nested_and_array_tables():
    data = {"seat": [{"name": "A", "fits": {}}, {}], "bearings": {"b": {}},
            "shaft": {"sections": [["1 mm"]]}}
    assert key_text(["seat", 0, "fits", "bore"], data) == '[[seat]] #1 ("A").fits.bore'
    assert key_text(["seat", 1, "position"], data) == "[[seat]] #2.position"
    assert key_text(["bearings", "b", "n_balls"], data) == "[bearings.b].n_balls"
    assert key_text(["shaft", "sections", 0, 0], data) == "[shaft].sections[0][0]"
    assert key_text(["gear", 0, "position"], data) == "[[gear]] #1.position"
    assert key_text(["loads", "radial"], data) == "[loads].radial"
    assert key_text(["title"], data) == "title"


# ------------------------------------------------------------------------------ fem
def test_fem_load_error_names_the_option():
    """fem --load abc names --load (not the case file's [case].load), with a force example;
    the options are checked before the fem extra is looked for."""
    res = runner.invoke(_app(), ["fem", "--load", "abc"])
    assert res.exit_code == 2
    assert res.stderr == ("error: --load: cannot parse 'abc' as a quantity: it does not start "
                          "with a number (e.g. '4450 N')\n")


def test_an_unwritable_out_folder_names_the_option(tmp_path, monkeypatch):
    """A folder the file system refuses although os.access says yes (root on /sys): the
    probe file fails and the message names --out, without an errno."""
    import tempfile

    import ballrace.validation.cli as vcli
    from ballrace.console import output_folder

    def refuse(*a, **k):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(tempfile, "TemporaryFile", refuse)
    with pytest.raises(ValueError, match=r"^--out .*: cannot write there \(permission denied\); "
                                         r"choose another folder with --out$"):
        output_folder(tmp_path / "o")
    monkeypatch.setattr(vcli, "missing_fem", lambda: [])
    res = runner.invoke(_app(), ["fem", "--out", str(tmp_path / "fe"), "--level", "quick"])
    assert res.exit_code == 2 and "--out" in res.stderr and "Errno" not in res.stderr
    monkeypatch.setattr(vcli, "missing_modules", lambda *m: [])
    res = runner.invoke(_app(), ["validate", "--fem", "none", "--cases", "ehl.toml",
                                 "--report", str(tmp_path / "rep")])
    assert res.exit_code == 2, res.output
    assert res.stderr.startswith("error: --report ") and "Errno" not in res.stderr
    assert "PASS" not in res.stdout                   # refused before any case ran


def test_summary_names_no_local_dask_address():
    from ballrace.validation.cli import _where_run

    assert _where_run("dask inproc://192.0.2.2/5327/1 (1 worker(s), 2 thread(s))") == \
        "dask, local (1 worker(s), 2 thread(s))"
    assert _where_run("serial") == "serial"
    assert _where_run("dask tcp://cluster.example:8786 (4 worker(s), 8 thread(s))") == \
        "dask tcp://cluster.example:8786 (4 worker(s), 8 thread(s))"


# ------------------------------------------------------------------- subsurface depth
def test_a_depth_typed_in_millimetres_warns():
    """stress(..., z=0.5) with a 0.32 mm contact: 0.5 m is 1540 semi-axes deep; the
    warning names z and the millimetre reading.  Depths within the stressed zone do not
    warn (a grid to 5 a, and 100 a exactly)."""
    import ballrace
    from ballrace.analytic import subsurface
    from ballrace.analytic.hertz import elliptical_contact, line_contact

    c = elliptical_contact(1000.0, 0.005, 0.005, 219.78e9)     # a = 0.324 mm
    with pytest.warns(UserWarning, match=r"^z = 0\.5 m is 1\.54e\+03 times the contact's "
                                         r"semi-axis .* were millimetres given\? \(0\.5 mm is "
                                         r"0\.0005 m\)$"):
        subsurface.stress(c, 0.0, 0.0, 0.5, traction=0.3)
    lc = line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
    with pytest.warns(UserWarning, match=r"^z = 0\.5 m is .* were millimetres given"):
        subsurface.line_stress(lc, 0.0, 0.5, traction=0.3)
    with pytest.warns(UserWarning, match=r"^z = 0\.5 m"):
        subsurface.axis_stress(c, np.array([1e-4, 0.5]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        subsurface.stress(c, 0.0, 0.0, np.linspace(0, 5, 11) * float(c.a), traction=0.3)
        subsurface.stress(c, 0.0, 0.0, 100 * float(c.a))
        subsurface.line_stress(lc, 0.0, 100 * float(lc.b))


@pytest.mark.parametrize("text", ["9^9^9 N", "2**2**2**2**2 N", "1 N*m^99999999", "3 m^2^9 N"])
def test_exponent_bombs_refused_at_once(text):
    """pint evaluates '9^9^9' as an integer of 370 million digits (it never returns); the
    boundary refuses a power tower or a long exponent before pint sees it."""
    from ballrace.units import parse_quantity

    with pytest.raises(ValueError, match="exponent"):
        parse_quantity(text, "[force]", "load")
    assert parse_quantity("68 mm^2/s", "[length] ** 2 / [time]", "nu40") == pytest.approx(6.8e-5)


def test_teach_subsurface_warns_unit_slips_like_contact(tmp_path):
    """`teach subsurface` reads the same options as `contact`: the same one-line warnings."""
    r = _main(["teach", "subsurface", "--E1", "200 MPa", "--rx1", "6.35 m",
               "--out", str(tmp_path / "t.png")])
    lines = r.stderr.splitlines()
    assert lines[0].startswith("warning: --rx1 = '6.35 m' (6.35 m) is larger than")
    assert lines[1] == ("warning: --E1 = '200 MPa' (0.2 GPa) is softer than the materials of "
                        "rolling contacts (0.5 ... 2000 GPa); was '200 GPa' meant?")
