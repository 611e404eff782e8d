"""docs/casefiles.md: every example on the page loads and runs.

The page holds one complete example of each case file, in this order: bearing case,
shaft case, FE case, validation case (the shaft example is checked in
tests/test_trust3_output.py).  The examples are read from the page itself, so the page
cannot drift from what the loaders accept.
"""
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballrace.cli import app

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "casefiles.md"
LBF = 4.4482216152605


def _examples():
    blocks = re.findall(r"```toml\n(.*?)```", PAGE.read_text(encoding="utf-8"), re.S)
    assert len(blocks) == 4, "docs/casefiles.md: one example per kind of case file"
    return dict(zip(("bearing", "shaft", "fem", "validation"), blocks))


def test_bearing_example_runs_and_matches_the_shipped_209_case(tmp_path):
    from ballrace.casefiles.bearing import load_case
    from ballrace.commands.bearing import analyze

    p = tmp_path / "bearing.toml"
    p.write_text(_examples()["bearing"])
    case = load_case(p)
    assert case.radial_load == pytest.approx(2000 * LBF, rel=1e-12)
    assert case.bearing.diametral_clearance == pytest.approx(15e-6, rel=1e-12)
    assert case.speed_rpm == pytest.approx(4000.0, rel=1e-12)
    r = analyze(case)
    ref = analyze(load_case(ROOT / "examples" / "bearing_209.toml"))
    d, dref = r["distribution"], ref["distribution"]
    np.testing.assert_allclose(d["ball_load"], dref["ball_load"], rtol=1e-12)
    psi, Q = np.array(d["azimuth"]), np.array(d["ball_load"])
    assert np.sum(Q * np.cos(psi)) == pytest.approx(2000 * LBF, rel=1e-9)   # equilibrium
    assert r["life"]["hardness_factor"] == pytest.approx(1.0)                # 62 HRC: none
    res = CliRunner().invoke(app, ["bearing", str(p)])
    assert res.exit_code == 0, res.output
    assert "209 deep-groove ball bearing, radial load" in res.stdout


def test_fe_example_loads_into_the_209_inner_race_case(tmp_path):
    import ballrace
    from ballrace.fem import api
    from ballrace.fem.cli import load_fe_case

    p = tmp_path / "fe.toml"
    p.write_text(_examples()["fem"])
    fc = load_fe_case(p)
    assert (fc.contact, fc.level, fc.mode, fc.gap, fc.solver) == \
        ("inner", "quick", "half-space", "hertz", None)
    assert fc.case.load == pytest.approx(1000 * LBF, rel=1e-12)
    brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)
    ref = api.race_case(brg, 1000 * LBF, "inner")
    for q in ("a", "b", "p_max", "approach"):
        assert float(getattr(fc.case.analytic, q)) == \
            pytest.approx(float(getattr(ref.analytic, q)), rel=1e-12)
    # an empty FE case file is the 209 inner-race contact at 4450 N
    e = tmp_path / "empty.toml"
    e.write_text("")
    fe = load_fe_case(e)
    assert (fe.case.load, fe.contact, fe.level) == (4450.0, "inner", "standard")


def test_validation_example_loads_and_passes(tmp_path):
    from ballrace.validation.runner import run_cases
    from ballrace.validation.schema import load_case_file

    p = tmp_path / "val.toml"
    p.write_text(_examples()["validation"])
    (case,) = load_case_file(p)
    assert case.id == "demo-sphere-on-flat" and case.inputs["rx1"] == 5e-3
    run = run_cases([case], serial=True)
    (res,) = run.results
    assert res.status == "pass", res.message
    # Johnson (1985) eq. (4.22), derived independently here
    E_star = 200e9 / (2 * (1 - 0.3**2))
    a = (3 * 1000 * 5e-3 / (4 * E_star)) ** (1 / 3)
    assert res.outputs["a"] == pytest.approx(a, rel=1e-9)
    assert res.outputs["p_max"] == pytest.approx(3 * 1000 / (2 * math.pi * a * a), rel=1e-9)


def test_every_example_is_valid_toml_and_named_on_the_page():
    ex = _examples()
    for kind, text in ex.items():
        tomllib.loads(text)
    page = PAGE.read_text(encoding="utf-8")
    for cmd in ("ballrace bearing", "ballrace fem", "ballrace validate"):
        assert cmd in page
    assert "take precedence" in " ".join(page.split())


def test_bearing_example_documents_every_accepted_key():
    """Every key the strict bearing schema accepts appears on the page (so none is
    accepted but undocumented), and ep_additives is shown under [oil], where it is read."""
    import re

    from ballrace.casefiles.bearing import _models

    page = PAGE.read_text()
    example = _examples()["bearing"]
    spec = _models()
    for table, field in spec.model_fields.items():
        sub = field.annotation
        sub = getattr(sub, "__args__", (sub,))[0]
        for key in getattr(sub, "model_fields", {}):
            assert f"`{key}`" in page or re.search(rf"^{key} =", example, re.M), (table, key)
    oil = example.split("[oil]")[1].split("\n[")[0]
    assert "ep_additives" in oil and "ep_additives" not in example.split("[life]")[1].split("\n[")[0]
