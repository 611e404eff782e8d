"""ISO life inputs of bearing case files ([oil], [life] ISO keys, [fits]) and the CLI rows."""
import json
import math
from pathlib import Path

import pytest

from ballrace.analytic import iso281, life
from ballrace.casefiles import bearing as casefile
from ballrace.commands import bearing as cli

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "bearing_6305_iso.toml"

BASE = {"bearing": {"ball_diameter": "11.5 mm", "n_balls": 7, "pitch_diameter": "43.5 mm",
                    "f_inner": 0.52, "f_outer": 0.53, "diametral_clearance": "20 um"},
        "loads": {"radial": "2 kN"}, "operation": {"speed": "3000 rpm"}}


def _case(**extra):
    return casefile.parse_case({**BASE, **extra})


def test_oil_in_cst_and_mm2s_and_degC():
    a = _case(oil={"nu40": "68 cSt", "nu100": "8.7 cSt", "temperature": "70 degC"})
    b = _case(oil={"nu40": "68 mm^2/s", "nu100": "8.7 mm^2/s", "temperature": "343.15 K"})
    assert a.oil_viscosity == pytest.approx(b.oil_viscosity, rel=1e-12)
    assert a.oil_viscosity == pytest.approx(float(iso281.operating_viscosity(68e-6, 8.7e-6,
                                                                             343.15)), rel=1e-12)
    c = _case(oil={"viscosity": "20 cSt"})
    assert c.oil_viscosity == pytest.approx(20e-6)


@pytest.mark.parametrize("oil, msg", [
    ({"nu40": "68 cSt"}, "missing"),
    ({"viscosity": "20 cSt", "nu40": "68 cSt"}, "is given, so nu40 must not be"),
    ({"nu40": "68 cSt", "nu100": "8.7 cSt", "temperature": "70"}, "temperature"),
    ({"nu40": "8 cSt", "nu100": "68 cSt", "temperature": "70 degC"}, "nu100"),
    ({"viscosity": "20 Pa*s"}, "viscosity"),
])
def test_oil_errors(oil, msg):
    with pytest.raises(casefile.CaseFileError, match=msg):
        _case(oil=oil)


def test_life_iso_keys():
    c = _case(life={"cleanliness": "high cleanliness", "reliability": 0.99,
                    "fatigue_limit": "0.7 kN"})
    assert c.contamination == pytest.approx(0.7) and c.reliability == 0.99
    assert c.fatigue_limit == pytest.approx(700.0)
    with pytest.raises(casefile.CaseFileError, match="cleanliness"):
        _case(life={"cleanliness": "spotless"})
    with pytest.raises(casefile.CaseFileError, match="not both"):
        _case(life={"cleanliness": "high cleanliness", "contamination": 0.5})
    with pytest.raises(casefile.CaseFileError, match="reliability"):
        _case(life={"reliability": 0.5})
    with pytest.raises(casefile.CaseFileError, match="contamination"):
        _case(life={"contamination": 1.5})


def test_fits_give_the_operating_clearance():
    fits = {"bore": "25 mm", "outside_diameter": "62 mm", "shaft_interference": "12 um",
            "inner_temperature": "75 degC", "outer_temperature": "65 degC"}
    c = _case(fits=fits)
    oc = life.operating_clearance(
        casefile.parse_case(BASE).bearing, bore=0.025, outside_diameter=0.062,
        shaft_interference=12e-6, inner_temperature=348.15, outer_temperature=338.15)
    assert c.clearance.operating == pytest.approx(oc.operating, rel=1e-12)
    assert c.bearing.diametral_clearance == pytest.approx(oc.operating, rel=1e-12)
    assert c.solver_options == {}
    # a heavy fit: preload, handed to the solver
    p = _case(fits={**fits, "shaft_interference": "40 um"})
    assert p.clearance.operating < 0
    assert p.solver_options == {"clearance": p.clearance.operating}
    assert p.bearing.diametral_clearance == pytest.approx(20e-6)


def test_fits_errors():
    with pytest.raises(casefile.CaseFileError, match=r"\[fits\].bore"):
        _case(fits={"bore": "25 kg", "outside_diameter": "62 mm"})
    with pytest.raises(casefile.CaseFileError, match="bore"):
        _case(fits={"bore": "40 mm", "outside_diameter": "62 mm"})
    with pytest.raises(casefile.CaseFileError, match="thrust"):
        casefile.parse_case({**BASE, "loads": {"axial": "1 kN"},
                             "fits": {"bore": "25 mm", "outside_diameter": "62 mm",
                                      "shaft_interference": "40 um"}})


def test_analyze_reports_iso_life_of_example():
    case = casefile.load_case(EXAMPLE)
    r = cli.analyze(case)
    iso = r["iso"]
    # kappa from nu(70 degC) = 20.12 mm^2/s and nu1 = 4500 / sqrt(3000 * 43.5) = 12.457
    assert iso["kappa"] == pytest.approx(20.1232 / 12.4568, rel=1e-4)
    assert iso["contamination"] == pytest.approx(0.55)
    P = r["life"]["P"]
    a = float(life.life_modification_factor(iso["kappa"], 0.55, iso["C_u"], P))
    assert iso["L_nm"] == pytest.approx(a * (iso["C"] / P) ** 3, rel=1e-12)
    assert iso["C_u"] == pytest.approx(iso["C_u_hertz"])
    assert iso["clearance"]["operating"] == pytest.approx(case.bearing.diametral_clearance)
    assert iso["L10mr"] == pytest.approx(iso["a_ISO_ref"] * iso["L10r"], rel=1e-12)
    json.dumps(cli.jsonable(r))      # JSON-safe


def test_analyze_without_oil_notes_it():
    r = cli.analyze(_case())
    assert "a_ISO" not in r["iso"] and "L10r" in r["iso"]
    assert any("no [oil]" in n for n in r["iso"]["notes"])


def test_kappa_below_range_is_a_note_not_a_crash():
    r = cli.analyze(_case(oil={"viscosity": "0.5 cSt"}, life={"contamination": 0.5}))
    assert r["iso"]["kappa"] < 0.1 and "a_ISO" not in r["iso"]
    assert any("outside ISO 281" in n for n in r["iso"]["notes"])


def test_cli_prints_iso_rows(tmp_path):
    from typer.testing import CliRunner

    from ballrace.cli import app

    res = CliRunner().invoke(app, ["bearing", str(EXAMPLE)])
    assert res.exit_code == 0, res.output
    for word in ("kappa", "e_C", "C_u", "a_ISO", "L_nm", "L10r", "L10mr", "operating clearance",
                 "mm^2/s"):
        assert word in res.output
    res = CliRunner().invoke(app, ["bearing", str(EXAMPLE), "--json"])
    data = json.loads(res.output)
    assert math.isfinite(data["iso"]["L10mr"])


def test_cli_notes_keep_their_brackets(tmp_path):
    """Rich markup must not swallow "[oil]" in the notes."""
    from typer.testing import CliRunner

    from ballrace.cli import app

    case = tmp_path / "c.toml"
    case.write_text('[bearing]\nball_diameter = "11.5 mm"\nn_balls = 7\n'
                    'pitch_diameter = "43.5 mm"\nf_inner = 0.52\nf_outer = 0.53\n'
                    'diametral_clearance = "0 mm"\n[loads]\nradial = "1 kN"\n'
                    '[operation]\nspeed = "3000 rpm"\n')
    res = CliRunner().invoke(app, ["bearing", str(case)])
    assert res.exit_code == 0, res.output
    assert "no [oil]" in res.output


def test_ep_additives_in_oil_table():
    c = _case(oil={"viscosity": "4 cSt", "ep_additives": True},
              life={"contamination": 0.5})
    assert c.ep_additives
    r = cli.analyze(c)["iso"]
    assert r["kappa"] < 1 and r["a_ISO"] <= 3.0
    assert any("EP additives" in n for n in r["notes"])
