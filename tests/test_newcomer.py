"""What a new user meets first: the package namespace, the command line's promises."""
from __future__ import annotations

import ballrace

SUBPACKAGES = {"analytic", "commands", "casefiles", "fem", "meshes", "validation", "reports", "cli",
               "console", "units", "errors", "teach"}


def test_public_namespace_is_the_documented_one():
    """dir(ballrace) shows the API (``__all__``) and sub-packages, not helper imports
    such as ``logging`` or ``annotations``."""
    public = {n for n in dir(ballrace) if not n.startswith("_")}
    assert public - SUBPACKAGES == set(ballrace.__all__) - {"__version__"}


# ------------------------------------------------ case-file messages: key, what was read, example
from pathlib import Path  # noqa: E402

import pytest  # noqa: E402

ISO = (Path(__file__).resolve().parents[1] / "examples" / "bearing_6305_iso.toml").read_text()


def _run_case(tmp_path, old, new):
    from typer.testing import CliRunner

    from ballrace.cli import app

    assert old in ISO, old
    p = tmp_path / "c.toml"
    p.write_text(ISO.replace(old, new, 1))
    return CliRunner().invoke(app, ["bearing", str(p)])


@pytest.mark.parametrize("old, new, says", [
    ('nu40 = "68 cSt"', 'nu40 = "68 mm"', "(e.g. mm^2/s (cSt)), got '68 mm'"),
    ('inner_temperature = "75 degC"', 'inner_temperature = "75 C"',
     "'C' is not a temperature unit (to pint, 'C' is the coulomb); write \"75 degC\""),
    ('inner_temperature = "75 degC"', "inner_temperature = 75",
     'give the value with its unit as a string, e.g. "75 degC"; got 75'),
    ('inner_temperature = "75 degC"', 'inner_temperature = "75 delta_degC"',
     "'delta_degC' is a temperature difference; an absolute temperature is expected"),
    ('inner_temperature = "75 degC"', 'inner_temperature = "75 K"',
     "'75 K' is -198.15 °C, outside -100 °C ... 500 °C"),
    ("reliability = 0.9", "reliability = 99", "a fraction, not a percentage: 0.99 for 99 %"),
    ('nu40 = "68 cSt"', 'viscosity = "20 cSt"',
     "viscosity (at the operating temperature) is given, so nu100 and temperature must not be"),
    ('nu40 = "68 cSt"', 'nu40 = "-68 cSt"', "[oil].nu40 must be > 0; got '-68 cSt'"),
])
def test_case_file_message_names_key_value_and_example(tmp_path, old, new, says):
    res = _run_case(tmp_path, old, new)
    assert res.exit_code == 2, res.output
    assert says in res.stderr and len(res.stderr.strip().splitlines()) == 1, res.stderr
    assert "e-05" not in res.stderr and "Traceback" not in res.stderr


def test_rev_per_min_is_a_speed(tmp_path):
    """The docs list rev/min beside rpm; pint alone does not know 'rev'."""
    from ballrace.units import ureg

    assert ureg().Quantity("3000 rev/min").to("rad/s").magnitude == pytest.approx(100 * 3.141592653589793)
    res = _run_case(tmp_path, 'speed = "3000 rpm"', 'speed = "3000 rev/min"')
    assert res.exit_code == 0, res.stderr


@pytest.mark.parametrize("call, says", [
    (lambda: __import__("ballrace.analytic.iso281", fromlist=["x"]).operating_viscosity(
        68, 8.7, 343.15), "were mm^2/s (cSt) given? (68 mm^2/s is 6.8e-05 m^2/s)"),
    (lambda: __import__("ballrace.analytic.iso281", fromlist=["x"]).operating_viscosity(
        68e-6, 8.7e-6, 70), "were degrees Celsius given? (70 °C is 343.15 K)"),
])
def test_temperature_and_viscosity_slips_in_the_api(call, says):
    with pytest.raises(ValueError) as exc:
        call()
    assert says in str(exc.value)


def test_operating_clearance_at_75_kelvin_is_refused():
    import ballrace
    from ballrace.analytic import clearance

    brg = ballrace.BallBearing(11.5e-3, 7, 43.5e-3, 0.52, 0.53, diametral_clearance=10e-6)
    with pytest.raises(ValueError, match=r"inner_temperature must be an absolute temperature "
                                         r"in kelvin .* got 75; were degrees Celsius given"):
        clearance.operating_clearance(brg, bore=25e-3, outside_diameter=62e-3,
                                      shaft_interference=12e-6, inner_temperature=75.0)


def test_one_operating_state_in_the_bearing_report(tmp_path):
    """A 120 um shaft interference preloads the 6305: the geometry shows the operating
    clearance the load distribution used, and the catalogue lives (which cannot see it)
    are marked and explained."""
    from ballrace.casefiles.bearing import load_case
    from ballrace.commands.bearing import analyze, sections

    p = tmp_path / "c.toml"
    p.write_text(ISO.replace('shaft_interference = "12 um"', 'shaft_interference = "120 um"'))
    r = analyze(load_case(p))
    op = r["iso"]["clearance"]["operating"]
    assert op < 0 and r["bearing"]["operating_clearance"] == op
    # the distribution ran at that clearance: every ball loaded under the radial load
    assert min(r["distribution"]["ball_load"]) > 0
    geo = dict((n, v) for n, v, _ in sections(r)[0][1])
    assert geo["diametral clearance, operating (preload)"] == op
    assert geo["diametral clearance, unmounted"] == r["iso"]["clearance"]["initial"]
    life = [n for n, _, _ in sections(r)[1][1]] + [n for n, _, _ in sections(r)[-1][1]]
    assert "L10h (ISO 281:2007) *" in life and "modified rating life L_nmh *" in life
    note = [n for n in r["notes"] if n.startswith("* the operating clearance")]
    assert len(note) == 1 and "not its life" in note[0]
    assert not any("is used by the load distribution" in n and "free contact" in n
                   for n in r["notes"])


def test_cli_reference_page_is_generated_from_every_command():
    """docs/_ext/clipage.py writes each command's own --help: nothing to drift."""
    import importlib.util

    import typer

    from ballrace.cli import app

    path = Path(__file__).resolve().parents[1] / "docs" / "_ext" / "clipage.py"
    spec = importlib.util.spec_from_file_location("clipage", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    text = mod.page()
    commands = [" ".join(p) for p, _ in mod._commands(typer.main.get_command(app))]
    assert {"contact", "bearing", "fem", "validate", "teach", "teach subsurface"} <= set(commands)
    for c in commands:
        assert f"``ballrace {c}``" in text and f"Usage: ballrace {c}" in text
    assert "--units UNITS" in text and "take precedence over the file" in text


def test_teach_prints_engineering_units(tmp_path):
    pytest.importorskip("matplotlib")
    from typer.testing import CliRunner

    from ballrace.analytic import hertz
    from ballrace.cli import app
    import ballrace

    res = CliRunner().invoke(app, ["teach", "subsurface", "--out", str(tmp_path / "t.png")])
    assert res.exit_code == 0, res.output
    c = hertz.point_contact(2000.0, 6.35e-3, 6.35e-3, float("inf"), float("inf"),
                            ballrace.Material(200e9, 0.3))
    rows = {ln.split("  ")[0].strip(): ln.split() for ln in res.stdout.splitlines()}
    assert rows["p_max"][-2:] == [f"{float(c.p_max) / 1e6:.6g}", "MPa"]
    assert "[Pa]" not in res.stdout and str(int(float(c.p_max))) not in res.stdout
    us = CliRunner().invoke(app, ["teach", "subsurface", "--units", "us",
                                  "--out", str(tmp_path / "u.png")])
    assert " ksi" in us.stdout and " in " in us.stdout


def test_us_units_reach_every_number_of_the_bearing_output():
    """--units us: the oil temperature in °F, forces in lbf, no SI number left in the notes."""
    import re

    from typer.testing import CliRunner

    from ballrace.cli import app

    p = Path(__file__).resolve().parents[1] / "examples" / "bearing_6305_iso.toml"
    out = CliRunner().invoke(app, ["bearing", str(p), "--units", "us"]).stdout
    temp = [ln.split() for ln in out.splitlines() if ln.strip().startswith("oil temperature")]
    assert temp and temp[0][-2:] == ["158", "°F"]                  # 70 degC
    notes = " ".join(ln for ln in out.splitlines() if ln.startswith("note"))
    assert not re.search(r"\d\s*(N|um|mm|MPa)\b", notes), notes


def test_hertz_beyond_its_validity_is_said_not_silent(capsys):
    """1e9 N on a 6.35 mm ball: a = 35 mm = 5.5 R.  The library warns, the CLI marks the
    result in a row and a note (a = (3 Q R / 4 E*)^(1/3) for a ball on a flat)."""
    import warnings

    from typer.testing import CliRunner

    import ballrace
    from ballrace.analytic import hertz
    from ballrace.cli import app

    steel = ballrace.Material(200e9, 0.3)
    with pytest.warns(UserWarning, match=r"a / R = 5.53 > 0.5"):
        hertz.point_contact(1e9, 6.35e-3, 6.35e-3, float("inf"), float("inf"), steel)
    with warnings.catch_warnings():                       # a bearing contact: no warning
        warnings.simplefilter("error")
        hertz.point_contact(4450.0, 6.35e-3, 6.35e-3, 26e-3, -6.604e-3, steel)
    a = (3 * 1e9 * 6.35e-3 / (4 * 200e9 / (2 * (1 - 0.09)))) ** (1 / 3)
    res = CliRunner().invoke(app, ["contact", "--load", "1e9 N", "--rx1", "6.35 mm",
                                   "--ry1", "6.35 mm", "--json"])
    import json

    v = json.loads(res.stdout)["values"]
    assert v["size_ratio"] == pytest.approx(a / 6.35e-3, rel=1e-9)
    assert "beyond Hertz's small-contact assumption" in v["note"]
    assert "Warning" not in res.stderr


def test_fe_table_says_when_hertz_is_extrapolated(monkeypatch, capsys):
    from types import SimpleNamespace as NS

    from ballrace.fem.cli import _table

    pytest.importorskip("skfem")
    monkeypatch.setenv("COLUMNS", "80")

    class R:
        case = NS(ball_radius=6.35e-3, lower_radii=(float("inf"), float("inf")),
                  analytic=NS(a=35e-3))

        def to_dict(self):
            return {"comparison": [], "case": "ball on plane", "load": 1e9, "mode": "half-space",
                    "gap": "hertz", "level": "quick", "n_dofs": 1, "solver": "x"}

    _table(R(), "eng")
    assert "a / R = 5.51 > 0.5: beyond Hertz" in capsys.readouterr().out


def test_unit_string_in_the_python_api_gets_a_hint():
    import ballrace
    from ballrace.analytic import hertz

    with pytest.raises(TypeError, match=r"rx1 must be a real number .* got str '6.35 mm' \(the "
                                        r"Python API takes SI floats: '6.35 mm' is 0.00635 in m"):
        hertz.point_contact(100.0, "6.35 mm", 6.35e-3, 1.0, 1.0, ballrace.BEARING_STEEL)


def test_shipped_text_cites_documents_not_how_the_project_was_made():
    """Sources are cited by author, title, year and equation; nothing in the code, docs,
    cases or report templates speaks of source files by number or of the machine the work
    was done on."""
    import re

    root = Path(__file__).resolve().parents[1]
    bad = re.compile(r"seeds? 00\d|\(seed [0-9]|seed's|seed scan|seed text|lost in the scan|"
                     r"scan lost|task requirement|from this machine|could not be opened", re.I)
    hits = []
    for folder in ("analytic", "fem", "meshes", "validation", "reports", "docs", "gallery",
                   "examples", "tests", "benchmarks"):
        for p in (root / folder).rglob("*"):
            if p.suffix in (".py", ".md", ".rst", ".toml", ".j2", ".html") and "_build" not in p.parts:
                for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
                    if bad.search(line) and p.name != "test_newcomer.py":
                        hits.append(f"{p.relative_to(root)}:{i}: {line.strip()[:80]}")
    readme = (root / "README.md").read_text(encoding="utf-8")
    hits += [f"README.md: {m.group(0)}" for m in bad.finditer(readme)]
    assert not hits, "\n".join(hits)
