"""``ballrace fem`` for a roller (contact = "roller"): the case file to SI, its errors, and
one quick-level run end to end against the Python API (fem.roller_contact)."""
import importlib.util
import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballrace
from ballrace.analytic.roller import Crowned, Table
from ballrace.cli import app
from ballrace.errors import CaseFileError
from ballrace.fem.cli import FERollerCaseFile, load_fe_case, parse_fe_case

runner = CliRunner()
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "fem_roller_lundberg.toml"


def roller(**case):
    return {"case": {"contact": "roller", **case}}


# ----------------------------------------------------------------------------- parsing
def test_defaults_are_the_measured_roller_in_si():
    fc = parse_fe_case(roller())
    assert isinstance(fc, FERollerCaseFile)
    assert (fc.load, fc.roller_radius, fc.length, fc.raceway_radius) == (5000.0, 6e-3, 12e-3,
                                                                         math.inf)
    assert (fc.profile, fc.n_slices, fc.level, fc.mode, fc.solver) == \
        ("lundberg", 41, "standard", "half-space", None)
    assert fc.roller_material == ballrace.BEARING_STEEL


def test_example_file_reads_to_si():
    fc = load_fe_case(EXAMPLE)
    assert fc.title == "Lundberg roller on a flat raceway, 5 kN"
    assert (fc.load, fc.roller_radius, fc.length, fc.raceway_radius, fc.level) == \
        (5000.0, 6e-3, 12e-3, math.inf, "quick")
    assert (fc.roller_material.E, fc.raceway_material.nu) == (200e9, 0.3)


def test_keys_in_units_and_profiles_like_the_bearing_case_files():
    fc = parse_fe_case({**roller(load="1000 lbf", roller_radius="0.25 in", roller_length="10 mm",
                                 raceway_radius="-40 mm",
                                 profile={"flat_length": "4 mm", "crown_radius": "0.5 m"},
                                 n_slices=21),
                        "materials": {"roller": {"E": "210 GPa", "nu": 0.29},
                                      "ring": {"E": "30e6 psi", "nu": 0.3}},
                        "fem": {"level": "quick", "mode": "two-body", "solver": "superlu"}})
    assert fc.load == pytest.approx(4448.2216152605, rel=1e-12)        # 1 lbf = 4.448... N
    assert fc.roller_radius == pytest.approx(6.35e-3, rel=1e-12)
    assert (fc.length, fc.raceway_radius, fc.n_slices) == (10e-3, -40e-3, 21)
    assert fc.profile == Crowned(4e-3, 0.5)
    assert fc.roller_material.E == 210e9 and fc.roller_material.nu == 0.29
    assert fc.raceway_material.E == pytest.approx(30e6 * 6894.757293168, rel=1e-9)
    assert (fc.level, fc.mode, fc.solver) == ("quick", "two-body", "superlu")
    t = parse_fe_case(roller(profile={"x": ["0 mm", "4 mm", "5.9 mm"],
                                      "drop": ["0 um", "1 um", "6 um"]}))
    assert isinstance(t.profile, Table)
    assert parse_fe_case(roller(raceway_radius="flat")).raceway_radius == math.inf


def test_command_line_values_replace_the_files():
    fc = parse_fe_case(roller(roller_radius="5 mm", profile="straight"), "x.toml",
                       load="2 kN", level="quick", roller_diameter="20 mm", profile="iso",
                       raceway_radius="-60 mm", roller_length="15 mm")
    assert (fc.load, fc.roller_radius, fc.length, fc.raceway_radius, fc.profile, fc.level) == \
        (2000.0, 10e-3, 15e-3, -60e-3, "iso", "quick")
    # --contact roller turns an empty file into the default roller case
    assert isinstance(parse_fe_case({}, contact="roller"), FERollerCaseFile)


def test_tilt_reads_to_radians_and_the_command_line_replaces_it():
    # [case].tilt in any angle unit, to SI (rad); line_contact's sign (+: the +x end in)
    assert parse_fe_case(roller()).tilt == 0.0
    fc = parse_fe_case(roller(tilt="0.5 mrad", profile={"flat_length": "4 mm",
                                                        "crown_radius": "0.5 m"}))
    assert fc.tilt == pytest.approx(5e-4, rel=1e-12) and fc.inputs()["tilt"] == fc.tilt
    assert parse_fe_case(roller(tilt="-0.03 deg")).tilt == pytest.approx(
        -math.radians(0.03), rel=1e-12)
    assert parse_fe_case(roller(tilt="2 arcmin")).tilt == pytest.approx(
        2 / 60 * math.pi / 180, rel=1e-12)
    assert parse_fe_case(roller(tilt="0.5 mrad"), "x.toml", tilt="-1 mrad").tilt == \
        pytest.approx(-1e-3, rel=1e-12)


@pytest.mark.parametrize("tilt, message", [
    ("0.5", "give the angle's unit"),                      # a number without its unit
    (0.0005, 'give the value with its unit as a string, e.g. "0.0005 rad"'),   # bare
    (0.5, '"0.5 mrad"'),
    ("0.5 mm", "expected an angle"),
    ("2 rad", "tilt must be in (-pi/2, pi/2)"),            # line_contact's range
    ("-100 deg", "tilt must be in (-pi/2, pi/2)"),
])
def test_bad_tilts_name_the_key(tilt, message):
    with pytest.raises(CaseFileError) as e:
        parse_fe_case(roller(tilt=tilt), "r.toml")
    msg = str(e.value)
    assert msg.startswith("r.toml: [case].tilt") and message in msg and "\n" not in msg


def test_degrees_typed_as_radians_warn_and_fail_naming_the_key():
    # "0.3 rad" is likely 0.3 degrees meant: line_contact's unit-slip warning, then its
    # error (one slice touches), named as the case file's key
    with pytest.warns(UserWarning, match="degrees"):
        with pytest.raises(CaseFileError, match=r"r.toml: \[case\].tilt = '0.3 rad': .*one "
                                                r"slice"):
            parse_fe_case(roller(tilt="0.3 rad"), "r.toml")


def test_roller_table_shows_the_tilt_and_the_end_quarter_row(capsys):
    from types import SimpleNamespace

    from ballrace.fem.cli import _roller_table

    def row(q, fe, an, tol=None):
        err = fe / an - 1 if an else float("nan")
        return {"quantity": q, "unit": "N", "fe": fe, "analytic": an, "error": err,
                "tol": tol, "ok": True}
    rows = [row("edge_slice_load", 1.04, 0.0), row("end_quarter_load", 1022.17, 1027.03, 0.02)]
    r = SimpleNamespace(row=lambda q: next((x for x in rows if x["quantity"] == q), None)
                        or (_ for _ in ()).throw(KeyError(q)),
                        timings={"total": 21.0}, mode="half-space", level="quick",
                        n_dofs=113_712, solver="pardiso",
                        info={"model": "half", "x_edge_slice": 5.85e-3})
    fc = parse_fe_case(roller(tilt="0.5 mrad", profile={"flat_length": "4 mm",
                                                        "crown_radius": "0.5 m"}))
    _roller_table(r, fc, "eng")
    out = capsys.readouterr().out
    assert "tilt 0.5 mrad, half-space, half model, quick, 113,712 DOFs" in out
    line = next(x for x in out.splitlines() if "load of end quarter" in x)
    assert "1022.2" in line and "-0.47% / 2% ok" in line
    # line_contact's end slice is unloaded (0 N): no relative error, a dash
    line = next(x for x in out.splitlines() if "load of end slice" in x)
    assert line.rstrip().endswith("-") and "nan" not in out
    assert "the more loaded end, +x" in out
    assert max(len(x) for x in out.splitlines()) <= 80


@pytest.mark.parametrize("doc, key", [
    (roller(ball_diameter="12 mm"), "[case].ball_diameter"),
    (roller(contact_angle="10 deg"), "[case].contact_angle"),
    ({**roller(), "bearing": {"ball_diameter": "12.7 mm"}}, "[bearing]"),
    ({**roller(), "fem": {"gap": "exact"}}, "[fem].gap"),
    ({**roller(), "fem": {"traction": 0.3}}, "[fem].traction"),
    ({"case": {"contact": "inner", "profile": "iso"}}, "[case].profile"),
    ({"case": {"contact": "plane", "roller_length": "12 mm"}}, "[case].roller_length"),
    (roller(roller_diameter="12 mm", roller_radius="6 mm"), "[case].roller_radius"),
    (roller(raceway_radius="-5 mm"), "[case].raceway_radius"),
    (roller(raceway_radius="40"), "[case].raceway_radius"),
    (roller(roller_length="12"), "[case].roller_length"),
    (roller(roller_length="-12 mm"), "[case].roller_length"),
    (roller(load="5 kg"), "[case].load"),
    (roller(load="0 N"), "[case].load"),
    (roller(profile="banana"), "[case].profile"),
    (roller(profile={"flat_length": "4 mm", "crown_radius": "0.5 mm"}), "[case].profile"),
    (roller(profle="iso"), "[case].profle"),
    (roller(n_slices=2), "[case].n_slices"),
    ({**roller(), "materials": {"ball": {"E": "200 GPa", "nu": 0.3}}}, "[materials].ball"),
    ({**roller(), "fem": {"level": "coarse"}}, "[fem].level"),
])
def test_bad_roller_cases_name_the_file_and_key(doc, key):
    with pytest.raises(CaseFileError) as e:
        parse_fe_case(doc, "r.toml")
    msg = str(e.value)
    assert msg.startswith("r.toml: ") and key in msg and "\n" not in msg


@pytest.mark.parametrize("args, message", [
    (["--contact", "roller", "--gap", "exact"], "--gap applies to ball contacts only"),
    (["--contact", "roller", "--traction", "0.2"], "--traction applies to ball contacts only"),
    (["--contact", "inner", "--profile", "iso"], "--profile applies to --contact roller only"),
    (["--raceway-radius", "-40 mm"], "--raceway-radius applies to --contact roller only"),
    (["convergence", "--contact", "roller"], "convergence: the mesh-convergence study is of "
                                             "ball contacts"),
    (["--contact", "roller", "--roller-diameter", "12"], "[case].roller_diameter: give a unit"),
    (["--contact", "rollr"], "--case must be one of inner, outer, plane, ball, roller"),
    (["--contact", "inner", "--tilt", "1 mrad"], "--tilt applies to --contact roller only"),
    (["--contact", "roller", "--tilt", "0.5"], "--tilt: give the angle's unit"),
    (["--contact", "roller", "--tilt", "2 rad"], "[case].tilt = '2 rad': tilt must be in"),
])
def test_bad_roller_commands_are_one_line_errors(args, message):
    res = runner.invoke(app, ["fem", *args])
    assert res.exit_code == 2
    assert message in res.stderr
    assert res.stderr.startswith("error: ") and res.stderr.count("\n") == 1


# ----------------------------------------------------------------------------- FE run
needs_fe = pytest.mark.skipif(importlib.util.find_spec("skfem") is None
                              or importlib.util.find_spec("gmsh") is None,
                              reason="the fem extra is not installed")
can_draw = all(importlib.util.find_spec(m) is not None for m in ("pyvista", "matplotlib"))


@pytest.fixture(scope="module")
def api_result():
    from ballrace import fem

    st = ballrace.BEARING_STEEL
    return fem.roller_contact(5000.0, 6e-3, math.inf, 12e-3, st, st, profile="lundberg",
                              level="quick", n_slices=41)


def _same(a, b, where="result"):
    """JSON values equal to the API's (floats to 1e-9: the same solve twice)."""
    if isinstance(b, dict):
        assert set(a) == set(b), where
        for k in b:
            _same(a[k], b[k], f"{where}.{k}")
    elif isinstance(b, (list, tuple)):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{where}[{i}]")
    elif isinstance(b, float) and not isinstance(b, bool):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-300, nan_ok=True), where
    else:
        assert a == b, where


@needs_fe
def test_quick_roller_run_end_to_end(tmp_path, api_result):
    out = tmp_path / "out"
    args = ["fem", str(EXAMPLE), "--out", str(out)] + ([] if can_draw else ["--no-render"])
    res = runner.invoke(app, args)
    assert res.exit_code == 0, res.output
    # the progress display's log handler leaves the levels as it found them (without -v
    # the library's INFO lines, e.g. the mesh cache's, stay hidden after the table)
    import logging
    assert not logging.getLogger("ballrace.meshes.contact").isEnabledFor(logging.INFO)
    # the table: engineering units, every row within 80 columns
    assert "Lundberg roller on a flat raceway, 5 kN" in res.stdout
    assert "lundberg roller\nQ = 5000 N, D = 12 mm, L = 12 mm, flat raceway" in res.stdout
    for label in ("centre pressure (slice)", "approach", "von Mises, centre", "load of end slice"):
        assert label in res.stdout
    assert "MPa" in res.stdout and "µm" in res.stdout
    table = [line for line in res.stdout.splitlines() if not line.startswith("wrote ")]
    assert max(len(line) for line in table) <= 80
    doc = json.loads((out / "result.json").read_text())
    ref = api_result.to_dict()
    for k in ("timings", "peak_rss"):          # run-dependent, not results
        doc.pop(k), ref.pop(k)
    assert doc.pop("passed") is api_result.within_tolerance is True
    case = doc.pop("case")
    assert case["load"] == 5000.0 and case["roller_radius"] == 6e-3
    assert case["raceway_radius"] is None and case["profile"] == "lundberg"
    _same(doc, json.loads(json.dumps(ref)))
    # the quick level's measured centre pressure: +3.66 % off line_contact (fem.roller notes)
    assert doc["comparison"][0]["quantity"] == "centre_pressure"
    assert doc["comparison"][0]["error"] == pytest.approx(0.036, abs=0.01)
    if can_draw:
        for name in ("roller_von_mises.png", "roller_max_shear.png"):
            assert (out / name).stat().st_size > 50_000


@needs_fe
def test_roller_raceway_state_is_the_results_own_body(api_result):
    from ballrace.fem.render import roller_raceway_state

    # the result keeps its raceway (mesh, E, nu, surface) and R1, R2: no rebuild, no
    # stiffness matrix, no keywords
    body = api_result.fields["raceway"]
    assert (api_result.info["roller_radius"], api_result.info["raceway_radius"]) == (6e-3, None)
    assert not hasattr(body, "C") and not hasattr(body, "factor")
    state, u = roller_raceway_state(api_result)
    assert u.size == 3 * state.scalar_basis.N and np.isfinite(u).all()
    assert state.mesh.p.shape[1] == body.points.shape[0]
    # half-space mode: one block for both bodies' compliance, of modulus E'/2 (1 - nu^2)
    # = E/2 for two equal steels (E' = 2 E* = E / (1 - nu^2), Hamrock-Dowson)
    assert state.body.E == pytest.approx(0.5 * ballrace.BEARING_STEEL.E, rel=1e-12)
    assert state.body.nu == ballrace.BEARING_STEEL.nu


@needs_fe
def test_roller_raceway_state_old_keywords_are_deprecated(api_result):
    from ballrace.fem.render import roller_raceway_state

    st = ballrace.BEARING_STEEL
    with pytest.warns(DeprecationWarning, match="raceway_radius is no longer needed") as rec:
        roller_raceway_state(api_result, raceway_radius=math.inf)
    assert rec[0].filename == __file__                    # attributed to the caller's line
    with pytest.warns(DeprecationWarning, match="material is no longer needed"):
        roller_raceway_state(api_result, material=st)
    # a value that is not the solve's is refused, naming the keyword
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="raceway_radius"):
        roller_raceway_state(api_result, raceway_radius=-0.02)
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="material"):
        roller_raceway_state(api_result, material=ballrace.Material(E=200e9, nu=0.25))


@needs_fe
@pytest.mark.skipif(not can_draw, reason="pyvista or matplotlib missing")
def test_render_roller_refuses_a_field_it_does_not_draw(tmp_path, api_result):
    from ballrace.fem.render import render_roller

    with pytest.raises(ValueError, match="field"):
        render_roller(api_result, str(tmp_path / "x.png"), field="tau_xz")
