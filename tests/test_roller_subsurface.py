"""Stresses below the most loaded roller of a solved roller bearing
(RollerLoadDistribution.subsurface): the finite line contact of that roller on the
half-space and the von Mises / Tresca maxima below it."""
import numpy as np
import pytest

import ballrace
from ballrace.analytic.roller import subsurface_stress

# McEwen's plane-strain line contact, nu = 0.3 (Johnson, Contact Mechanics, 1985, §4.2):
# von Mises max 0.5562 p0 at 0.7034 b, Tresca max 0.3005 p0 at 0.7861 b.
VM, Z_VM, TR, Z_TR = 0.5562, 0.7034, 0.3005, 0.7861


def bearing(profile, clearance=0.0):
    return ballrace.RollerBearing(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=14,
                                  pitch_diameter=70.65e-3, kind="cylindrical",
                                  diametral_clearance=clearance, profile=profile)


def test_most_loaded_roller_is_the_one_under_the_load():
    r = bearing("iso", 20e-6).solve(Fy=15000.0)
    j = r.most_loaded_roller("inner")
    assert r.inner_loads[j] == r.inner_loads.max()
    assert r.most_loaded_roller("outer") == int(np.argmax(r.roller_loads))
    # roller 0 sits at +y, the load's direction (RollerBearing azimuth convention)
    assert j == 0


def test_subsurface_is_the_line_contact_of_that_roller():
    r = bearing("iso").solve(Fy=15000.0)
    s = r.subsurface("outer")
    ref = subsurface_stress(r.roller_contact(r.most_loaded_roller("outer"), "outer"), nu=0.3)
    np.testing.assert_array_equal(s.von_mises_max, ref.von_mises_max)
    np.testing.assert_array_equal(s.tresca_depth, ref.tresca_depth)


def test_middle_of_a_lundberg_roller_is_plane_strain_hertz():
    # Lundberg's profile: nearly uniform pressure along the roller, so the middle slice
    # sees McEwen's field; 2 %: the pressure still varies along the roller within the
    # ~0.7 b depth that the maximum reads (the profile is designed for the bearing's
    # design load, not this roller's load).
    r = bearing("lundberg").solve(Fy=20000.0)
    j = r.most_loaded_roller()
    c = r.roller_contact(j)
    s = r.subsurface()
    m = len(c.x) // 2
    p0, b = c.pressure[m], c.half_width[m]
    assert s.von_mises_max[m] / p0 == pytest.approx(VM, rel=0.02)
    assert s.von_mises_depth[m] / b == pytest.approx(Z_VM, rel=0.03)
    assert s.tresca_max[m] / p0 == pytest.approx(TR, rel=0.02)
    assert s.tresca_depth[m] / b == pytest.approx(Z_TR, rel=0.03)


def test_straight_roller_stress_peaks_below_its_ends():
    # A straight roller on the half-space: the end slices carry the edge peak, and the
    # stress below them exceeds the middle's by the same order as the pressure does.
    r = bearing("straight").solve(Fy=20000.0)
    s = r.subsurface()
    c = r.roller_contact(r.most_loaded_roller())
    m = len(s.x) // 2
    assert s.von_mises_max[0] > 1.3 * s.von_mises_max[m]
    assert s.von_mises_max[-1] > 1.3 * s.von_mises_max[m]
    assert c.pressure[0] > 1.3 * c.pressure[m]


def test_unloaded_or_multi_case_results_are_refused():
    b = bearing("iso", 20e-6)
    with pytest.raises(ValueError, match="carries no load"):
        b.solve(Fy=5000.0).subsurface(roller=7)           # roller 7 at 180 deg: unloaded
    with pytest.raises(ValueError, match="one load case"):
        b.solve(Fy=np.array([5000.0, 6000.0])).subsurface()
    with pytest.raises(ValueError, match="raceway"):
        b.solve(Fy=5000.0).most_loaded_roller("middle")


# ------------------------------------------------------------------ through ballrace bearing
def test_bearing_command_reports_the_most_loaded_roller_on_the_half_space():
    import json
    from pathlib import Path

    from typer.testing import CliRunner

    from ballrace.casefiles.bearing import load_case
    from ballrace.cli import app

    path = Path(__file__).resolve().parents[1] / "examples" / "bearing_nu210_roller.toml"
    res = CliRunner().invoke(app, ["bearing", str(path), "--json"])
    assert res.exit_code == 0, res.output
    h = json.loads(res.stdout)["distribution"]["half_space"]
    case = load_case(path)
    r = case.bearing.solve(Fy=case.radial_load)
    raceway = h["raceway"]
    j = r.most_loaded_roller(raceway)
    s = r.subsurface(raceway)
    assert h["roller"] == j
    assert h["load"] == pytest.approx(r.roller_contact(j, raceway).load, rel=1e-9)
    assert h["von_mises_max"] == pytest.approx(s.von_mises_max.max(), rel=1e-9)
    # the NU 210 example's inner contact has the higher pressure (smaller reduced radius)
    assert raceway == "inner"
    table = CliRunner().invoke(app, ["bearing", str(path)])
    assert "Half-space line contact (roller 1, inner)" in table.stdout
