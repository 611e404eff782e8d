"""What people read: the printed report's numbers and units, ``--units us`` on the shaft and
``teach`` outputs, and the docs pages on case files, the command line and the cases."""
from __future__ import annotations

import json
import math
import re
import sys
import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballrace.cli import app

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
sys.path.insert(0, str(DOCS / "_ext"))

LB = 0.45359237                    # kg, exact (international avoirdupois pound, 1959)
WIDE = {"COLUMNS": "200"}


# --------------------------------------------------------------------------- the report
def test_prose_keeps_each_number_with_its_unit():
    """Reasons and notes: "1 % of P", "(49.3 %)", "< 0.5 N", "0.75 N m" are unbreakable;
    a number without a unit and plain words are left alone."""
    from ballrace.reports.html import _prose

    html = str(_prose("shear each ~1e-3 of P: 1 % of P"))
    assert '<span class="n">1 %</span> of P' in html
    assert '<span class="n">~1e-3</span>' in html
    assert '<span class="n">49.3 %</span>' in str(_prose("1 <= alpha_r <= 1e4 (49.3 %); a"))
    html = str(_prose("moments below 1 N m shift the reactions by < 0.5 N"))
    assert '<span class="n">1 N m</span>' in html and '<span class="n">&lt; 0.5 N</span>' in html
    assert str(_prose("the third of 5 balls")) == "the third of 5 balls"
    assert '<span class="n">1 N</span> moment' in str(_prose("1 N moment"))


def test_report_titles_and_case_times_do_not_break_in_print():
    template = (ROOT / "reports" / "templates" / "report.html.j2").read_text()
    assert "{{ r.title|prose }}" in template and "{{ r.title }}" not in template
    assert '<span class="n">{{ "%.3f"|format(r.duration) }} s</span>' in template
    assert "{{ f.title|prose }}" in template


def test_every_output_dimension_has_an_engineering_unit():
    """No output of any registered calculation is printed as a bare SI number."""
    from ballrace.reports.html import ENGINEERING_UNITS
    from ballrace.validation import registry

    dims = {d for c in registry.all_calculations().values() for d in c.outputs.values()}
    assert dims - {""} <= set(ENGINEERING_UNITS), dims - {""} - set(ENGINEERING_UNITS)


def test_kinematic_viscosity_in_mm2_per_s():
    from ballrace.reports.html import format_eng

    # life_iso.toml, ISO VG 68 at 70 degC: nu = 20.12322 mm^2/s (1 mm^2/s = 1e-6 m^2/s = 1 cSt)
    assert format_eng(20.12322e-6, "[length] ** 2 / [time]") == "20.1232 mm²/s"
    assert format_eng(8.69565, "[temperature]") == "8.69565 K"


@pytest.mark.parametrize("atol, dim, value, text", [
    (1e-9, "[angle]", math.radians(40.0), "±5.73×10⁻⁸ deg"),    # 1e-9 rad = 5.7296e-8 deg
    (1112.06, "[force]", 2000.0, "±1110 N"),                     # 250 lbf, 3 digits
    (1e-9, "[length]", 16.5e-6, "±0.001 µm"),                   # in the values' unit
    (1e-12, "", 0.5, "±1×10⁻¹²"),
])
def test_tolerances_read_in_the_values_unit_to_three_digits(atol, dim, value, text):
    from types import SimpleNamespace as E

    from ballrace.reports.html import tolerance_text

    exp = E(name="x", dimension=dim, value=value, rtol=0.0, atol=atol, min=None, max=None)
    assert tolerance_text(exp) == text


def test_no_tolerance_or_error_of_a_run_is_in_python_e_notation():
    """Every tolerance and error text of the shaft and life_iso cases (angles, forces,
    viscosities, a temperature) reads as the report shows it: no "5.72958e-08"."""
    from ballrace.reports.html import _cfmt_text, error_text
    from ballrace.validation.runner import run_cases
    from ballrace.validation.schema import load_cases

    cases = load_cases("shaft.toml") + load_cases("life_iso.toml") + [
        c for c in load_cases("kinematics.toml") + load_cases("bearing.toml")
        if c.id in ("highspeed-218-zero-speed-equals-static", "bearing-209-geometry")]
    run = run_cases(cases, serial=True, fem="none")
    texts = [t for r in run.results for c in r.comparisons
             for t in (c.tolerance, error_text(c), _cfmt_text(c, "got"))]
    assert len(texts) > 60
    bad = [t for t in texts if re.search(r"\de[-+]?\d", t)]
    assert not bad, bad
    by_name = {(r.id, c.name): c for r in run.results for c in r.comparisons}
    assert _cfmt_text(by_name["life-iso281-kappa-vg68", "nu"], "got").endswith(" mm²/s")
    assert _cfmt_text(by_name["shaft-o-pair-thermal-lift-off", "dT_lift_off"],
                      "got").endswith(" K")
    assert by_name["bearing-209-geometry", "nominal_contact_angle"].tolerance == "±1×10⁻⁹ deg"


# --------------------------------------------------------------------------- --units us
def _mass_row(out: str) -> tuple[float, str]:
    m = re.search(r"^\s*mass\s+([0-9.]+)\s+(\S+)\s*$", out, re.M)
    assert m, out
    return float(m.group(1)), m.group(2)


def test_shaft_mass_follows_the_unit_system():
    case = str(ROOT / "examples" / "shaft_gearbox.toml")
    res = CliRunner().invoke(app, ["shaft", case, "--json"])
    assert res.exit_code == 0, res.output
    kg = json.loads(res.output)["shaft"]["mass"]
    # 260 mm of 40/48 mm steel at 7850 kg/m^3: pi/4 (0.06 * 0.04^2 + 0.2 * 0.048^2) 7850
    assert kg == pytest.approx(math.pi / 4 * (0.06 * 0.04**2 + 0.2 * 0.048**2) * 7850, rel=1e-9)
    for units, unit, factor in (("us", "lb", 1 / LB), ("eng", "kg", 1.0), ("si", "kg", 1.0)):
        res = CliRunner().invoke(app, ["shaft", case, "--units", units], env=WIDE)
        assert res.exit_code == 0, res.output
        value, shown = _mass_row(res.output)
        assert shown == unit, units
        assert value == pytest.approx(kg * factor, rel=1e-5), units


def test_teach_title_in_the_chosen_units():
    from types import SimpleNamespace as C

    from ballrace.teach.figures import title_text

    c = C(a=1.0e-3, b=0.5e-3, p_max=2.0e9)
    us = title_text("Subsurface stresses", 4448.2216152605, c, 0.3, "us")
    # 1000 lbf; 1 mm = 0.03937 in; 2 GPa = 290.1 ksi
    assert us == ("Subsurface stresses: Q = 1000 lbf, a = 0.03937 in, b = 0.01969 in, "
                  "p0 = 290.1 ksi, nu = 0.3")
    si = title_text("Subsurface stresses", 2000.0, c, 0.3, "si")
    assert "Q = 2000 N" in si and "a = 0.001 m" in si and "p0 = 2e+09 Pa" in si   # console.fmt, as the si tables
    eng = title_text("Subsurface stresses", 2000.0, c, 0.3)
    assert "a = 1 mm" in eng and "p0 = 2000 MPa" in eng and "GPa" not in eng


@pytest.mark.parametrize("extra", [[], ["--traction", "0.2"]])
def test_teach_passes_the_unit_system_to_the_figure(monkeypatch, tmp_path, extra):
    from ballrace.teach import figures

    seen = {}

    def fake(*args, **kw):
        seen.update(kw)
        return {"p_max [Pa]": 1e9}

    monkeypatch.setattr(figures, "subsurface_figure", fake)
    monkeypatch.setattr(figures, "traction_figure", fake)
    res = CliRunner().invoke(app, ["teach", "subsurface", "--units", "us",
                                   "--out", str(tmp_path / "t.png"), *extra], env=WIDE)
    assert res.exit_code == 0, res.output
    assert seen["units"] == "us"


# --------------------------------------------------------------------------- docs
PAGE = DOCS / "casefiles.md"


def _shaft_section() -> str:
    text = PAGE.read_text(encoding="utf-8")
    start = text.index("## Shaft case (`ballrace shaft`)")
    return text[start:text.index("\n## ", start + 1)]


def _shaft_example() -> str:
    (block,) = re.findall(r"```toml\n(.*?)```", _shaft_section(), re.S)
    return block


def _schema_keys(model, prefix=""):
    """(dotted path, key) of every key the strict pydantic schema accepts, recursively."""
    import typing

    for key, field in model.model_fields.items():
        yield prefix, key
        ann = field.annotation
        stack = [ann]
        while stack:                       # Optional[X], list[X], dict[str, X] -> X
            t = stack.pop()
            if hasattr(t, "model_fields"):
                yield from _schema_keys(t, f"{prefix}{key}.")
            stack.extend(typing.get_args(t))


def test_every_shaft_key_is_documented():
    from ballrace.casefiles.shaft import _models

    section = _shaft_section()
    keys = sorted({k for _, k in _schema_keys(_models())})
    assert len(keys) > 60
    # a key is named in code: `key`, a table `[seat.fits]`, an inline table `{E, nu, ...}`
    spans = re.findall(r"`([^`\n]+)`", section)
    missing = [k for k in keys if not any(re.search(rf"(?<![\w.-]){k}(?![\w-])", sp)
                                          for sp in spans)]
    assert not missing, f"docs/casefiles.md, shaft section: undocumented keys {missing}"


def test_shaft_example_uses_every_table_and_solves(tmp_path):
    from ballrace.analytic import shaft as S
    from ballrace.commands.shaft import analyze, load_shaft_case

    text = _shaft_example()
    data = tomllib.loads(text)
    assert {"shaft", "bearings", "seat", "load", "gear", "belt", "operation",
            "duty"} <= set(data)
    path = tmp_path / "shaft.toml"
    path.write_text(text, encoding="utf-8")
    case = load_shaft_case(path)
    r = analyze(case)
    assert r["shaft"]["residual"] < 1e-8
    # statics: the seats carry the loads and the weight (reactions = what each seat carries)
    fy = sum(s["reaction"][1] for s in r["seats"])
    fz = sum(s["reaction"][2] for s in r["seats"])
    assert fy == pytest.approx(sum(p.Fy for p in case.loads)
                               - r["shaft"]["mass"] * S.STANDARD_GRAVITY, rel=1e-6)
    assert fz == pytest.approx(sum(p.Fz for p in case.loads), rel=1e-6)
    res = CliRunner().invoke(app, ["shaft", str(path)], env=WIDE)
    assert res.exit_code == 0, res.output
    assert "Duty cycle" in res.output


def test_casefiles_page_names_the_shaft_command():
    text = PAGE.read_text(encoding="utf-8")
    assert "| shaft case      | `ballrace shaft CASE.toml`" in text
    assert "four kinds of TOML case file" in text


def test_cli_page_lists_every_command_that_reads_a_case_file():
    import clipage

    cmds = clipage.case_file_commands()
    assert {"bearing", "shaft", "fem", "validate"} <= set(cmds)
    intro = clipage.page().split("``ballrace``\n")[0]
    line = " ".join(intro.split())
    assert "``bearing``, ``fem``, ``shaft``, ``teach serve`` and ``validate`` read TOML case " \
           "files" in line or all(f"``{c}``" in line for c in cmds)
    assert "{case_commands}" not in intro


def test_double_hyphens_are_never_typeset_as_dashes(tmp_path):
    """Sphinx's smart quotes would turn "--cases" into "–cases": dashes are off, and the
    case pages show the commands of a case file's comment as literals."""
    import importlib.util

    import casepages

    import logging

    levels = {n: logging.getLogger(n).level for n in ("ballrace", "skfem")}
    spec = importlib.util.spec_from_file_location("ballrace_docs_conf_t3", DOCS / "conf.py")
    conf = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(conf)               # conf.py sets these loggers' levels
    finally:
        for n, level in levels.items():
            logging.getLogger(n).setLevel(level)
    assert "d" not in conf.smartquotes_action.lower()
    casepages.write_pages(tmp_path)
    page = (tmp_path / "cases" / "fem_hertz_limits.rst").read_text(encoding="utf-8")
    assert "``ballrace validate --cases fem_hertz_limits.toml --fem quick --workers 2``" in page
    for f in (tmp_path / "cases").glob("*.rst"):
        outside = re.sub(r"``.*?``", "", f.read_text(encoding="utf-8"))
        assert not re.search(r"(?<!-)--[a-z]", outside), f.name


def test_case_index_counts_what_the_runner_runs(tmp_path):
    import casepages

    from ballrace.validation.schema import load_cases

    runner = len(load_cases())                      # the default selection of the runner
    everything = len(load_cases(str(ROOT / "validation" / "cases" / "*.toml")))
    assert everything > runner > 0
    casepages.write_pages(tmp_path)
    index = " ".join((tmp_path / "cases" / "index.rst").read_text(encoding="utf-8").split())
    assert f"— {everything} cases in" in index
    assert f"``ballrace validate`` runs {runner} of them; the other {everything - runner}" in index
    assert f"* - all files - {everything} - {runner}" in index
    page = (tmp_path / "cases" / "fem_hertz_limits.rst").read_text(encoding="utf-8")
    assert "(2 cases, on demand)" in page and ":runs: on demand only" in page
