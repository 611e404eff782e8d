"""The ``ballrace contact`` command and the unit boundary."""
import json
import math

import pytest
from typer.testing import CliRunner

from ballrace.cli import app
from ballrace.units import parse_quantity

runner = CliRunner()


def test_contact_json_in_mixed_units_matches_si():
    """1000 lbf on a 12.7 mm ball against a flat, E = 200 GPa: same as the SI call."""
    import ballrace
    from ballrace.analytic import hertz

    res = runner.invoke(app, ["contact", "--load", "1000 lbf", "--rx1", "0.25 in", "--ry1", "6.35 mm",
                              "--rx2", "inf", "--ry2", "inf", "--E1", "200 GPa", "--json"])
    assert res.exit_code == 0, res.output
    out = json.loads(res.output)
    c = hertz.point_contact(4448.2216152605, 6.35e-3, 6.35e-3, math.inf, math.inf,
                            ballrace.Material(200e9, 0.3))
    assert out["values"]["a"] == pytest.approx(float(c.a), rel=1e-12)
    assert out["values"]["p_max"] == pytest.approx(float(c.p_max), rel=1e-12)
    assert out["units"]["p_max"] == "Pa"


def test_contact_table_is_readable():
    res = runner.invoke(app, ["contact", "--load", "4.45 N", "--rx1", "6.35 mm", "--ry1", "6.35 mm",
                              "--ry2", "-6.604 mm"])
    assert res.exit_code == 0, res.output
    assert "p_max" in res.output and "Pa" in res.output


@pytest.mark.parametrize("args, msg", [
    (["--load", "3 kg"], "expected a quantity of dimension [force]"),
    (["--load", "-5 N"], "load must be >= 0"),
    (["--load", "5 N", "--ry2", "-3 mm"], "curvature sum in the y plane"),
    (["--load", "five newtons"], "cannot parse"),
])
def test_contact_bad_input_exits_2_with_message(args, msg):
    base = ["contact", "--rx1", "6.35 mm", "--ry1", "6.35 mm"]
    res = runner.invoke(app, base + args)
    assert res.exit_code == 2
    assert msg in res.output


def test_parse_quantity_conversions():
    assert parse_quantity("200 GPa", "[pressure]", "E") == pytest.approx(200e9, rel=1e-15)
    assert parse_quantity("0.04 Pa*s", "[mass] / [length] / [time]", "eta") == pytest.approx(0.04)
    assert parse_quantity("-0.52 in", "[length]", "r") == pytest.approx(-0.013208, rel=1e-15)
    assert parse_quantity("-inf", "[length]", "r", allow_inf=True) == -math.inf
    with pytest.raises(ValueError, match="r: 'inf' is not allowed"):
        parse_quantity("inf", "[length]", "r")
    with pytest.raises(ValueError, match="give a unit"):
        parse_quantity(5.0, "[length]", "r")
    with pytest.raises(ValueError, match="give the angle's unit"):
        parse_quantity("40", "[angle]", "beta")
