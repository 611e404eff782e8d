"""One schema for the sections the bearing, shaft and FE case files share, and the
bearing case's analysis as data (casefiles.schema, casefiles.analysis)."""
from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def _fields(model):
    return {k: (f.annotation, f.default, repr(f.metadata)) for k, f in model.model_fields.items()}


def test_fe_and_shaft_sections_are_the_shared_keys():
    """The FE [bearing], [materials] and a shaft seat's [seat.fits] take the shared keys'
    definitions (defaults, constraints), only fewer of them."""
    import typing

    from ballrace.casefiles import schema
    from ballrace.casefiles.shaft import _models as shaft_models
    from ballrace.fem.cli import _models as fe_models

    shared = _fields(schema.bearing_keys())
    fe = fe_models()
    fe_bearing = typing.get_args(fe.model_fields["bearing"].annotation)[0]
    for k, v in _fields(fe_bearing).items():
        assert v == shared[k], k
    assert "type" not in fe_bearing.model_fields           # FE: geometry only
    seat = typing.get_args(shaft_models().model_fields["seat"].annotation)[0]
    fits = typing.get_args(seat.model_fields["fits"].annotation)[0]
    all_fits = _fields(schema.fits_keys())
    assert list(fits.model_fields) == list(schema.SEAT_FITS)
    for k, v in _fields(fits).items():
        assert v == all_fits[k], k


def test_fe_case_refuses_keys_outside_its_subset():
    from ballrace.errors import CaseFileError
    from ballrace.fem.cli import parse_fe_case

    geo = {"ball_diameter": "12.7 mm", "n_balls": 9, "pitch_diameter": "65 mm",
           "f_inner": 0.52, "f_outer": 0.52}
    with pytest.raises(CaseFileError, match=r"^x.toml: \[bearing\].type: Extra inputs"):
        parse_fe_case({"case": {"contact": "inner"}, "bearing": {**geo, "type": "deep-groove"}},
                      "x.toml")
    with pytest.raises(CaseFileError, match=r"^x.toml: \[bearing\].n_balls: Input should be "
                                            r"greater than or equal to 3"):
        parse_fe_case({"case": {"contact": "inner"}, "bearing": {**geo, "n_balls": 2}}, "x.toml")


def test_fits_error_names_the_file_once(tmp_path):
    """A bad [fits] quantity: 'FILE: [fits].bore: ...', the file and table named once."""
    from ballrace.cli import app

    text = (EXAMPLES / "bearing_209.toml").read_text()
    p = tmp_path / "f.toml"
    p.write_text(text + '\n[fits]\nbore = "45 xx"\noutside_diameter = "85 mm"\n')
    r = CliRunner().invoke(app, ["bearing", str(p)])
    assert r.exit_code == 2
    assert r.output.strip().startswith(f"error: {p}: [fits].bore: cannot parse '45 xx'")
    assert r.output.count(str(p)) == 1


@pytest.mark.parametrize("radial, axial, extra, method", [
    ("2 kN", "0 N", "", "radial"),
    ("0 N", "2 kN", "", "thrust"),
    ("0 N", "2 kN", 'eccentricity = "10 mm"', "eccentric thrust"),
    ("2 kN", "1 kN", "", "combined radial and thrust"),
])
def test_analysis_chooses_the_solver_and_the_command_renders_it(radial, axial, extra, method):
    from ballrace.casefiles.analysis import BearingAnalysis, analyze, load_distribution
    from ballrace.casefiles.bearing import parse_case
    from ballrace.commands import bearing as command

    case = parse_case({"bearing": {"type": "angular-contact", "ball_diameter": "12.7 mm",
                                   "n_balls": 9, "pitch_diameter": "65 mm", "f_inner": 0.52,
                                   "f_outer": 0.52, "free_contact_angle": "30 deg"},
                       "loads": {"radial": radial, "axial": axial,
                                 **({"eccentricity": "10 mm"} if extra else {})},
                       "operation": {"speed": "3000 rpm"}})
    a = analyze(case)
    assert isinstance(a, BearingAnalysis)
    assert a.method.startswith(method + " (")
    assert load_distribution(case)[0] == a.method
    assert a.values["distribution"]["method"] == a.method
    assert a.notes and all(isinstance(n, str) for n in a.notes)
    # the command's --json is the analysis as a dict, notes last
    d = command.analyze(case)
    assert d == a.to_dict()
    assert list(d)[-1] == "notes" and d["notes"] == list(a.notes)
    # equilibrium of the chosen solver: the ball loads carry the applied thrust
    Fa = case.axial_load
    if Fa:
        import numpy as np
        Q = np.asarray(d["distribution"]["ball_load"])
        beta = np.asarray(d["distribution"]["contact_angle"])
        assert float(np.sum(Q * np.sin(beta))) == pytest.approx(Fa, rel=1e-6)
