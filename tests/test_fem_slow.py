"""Standard-level FE checks with their tolerances; run by ``make test-fem`` (``-m slow``).

Tolerances at "standard" (:data:`ballrace.fem.TOLERANCES`): a, b, p_max 0.5 %, approach
(the FE estimate of Hertz's delta) and the depth-point approach 1 %, tau0, tau at
(x0, z0), the on-axis max shear and von Mises maxima 1.5 %, z0 and the depths of the
maxima 2 %.  Two elastic bodies whose lower body is curved (race groove, ball) are held
to :data:`ballrace.fem.api.CURVED_BODY_TOLERANCE` on the stress maxima and their depths:
there the real geometry departs from Hertz's half-spaces (docs/fem.md).  Cost is
measured in ``benchmarks/bench_fem.py``, not here.
"""
from __future__ import annotations

import pytest

import ballrace

pytestmark = [pytest.mark.slow, pytest.mark.fem]
fem = pytest.importorskip("ballrace.fem")
pytest.importorskip("skfem")
pytest.importorskip("gmsh")

ALL = ("a", "b", "p_max", "approach", "approach_depth_point", "tau0", "tau_x0z0", "z0",
       "max_shear", "max_shear_depth", "von_mises", "von_mises_depth")


@pytest.fixture(scope="module")
def brg209():
    return ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)


def _assert_rows(r, names=ALL):
    rows = {row["quantity"]: row for row in r.comparison}
    assert all(rows[q]["tol"] is not None for q in names)
    bad = [f"{q}: {100 * rows[q]['error']:+.3f} % (tol {100 * rows[q]['tol']:.1f} %)"
           for q in names if not rows[q]["ok"]]
    assert not bad, "; ".join(bad)


def test_standard_inner_race_half_space(brg209):
    _assert_rows(fem.ball_on_race(brg209, 4450.0, race="inner", mode="half-space"))


def test_standard_outer_race_half_space(brg209):
    _assert_rows(fem.ball_on_race(brg209, 4450.0, race="outer", mode="half-space"))


def test_standard_ball_on_plane_half_space():
    _assert_rows(fem.ball_on_plane(12.7e-3, 2000.0, level="standard", mode="half-space"))


def test_standard_ball_on_plane_two_body():
    _assert_rows(fem.ball_on_plane(12.7e-3, 2000.0, level="standard", mode="two-body"))


def test_standard_ball_on_ball_half_space():
    _assert_rows(fem.ball_on_ball(12.7e-3, 2000.0, level="standard", mode="half-space"))


def test_standard_inner_race_two_body(brg209):
    # the race is the groove with its lands (meshes.geometry.RingSurface); a block cut off
    # at 0.75 f D beside the groove put a 0.3 % shortfall on a (docs/fem.md)
    _assert_rows(fem.ball_on_race(brg209, 4450.0, race="inner", mode="two-body"))


def test_standard_load_list_on_one_mesh(brg209):
    """Two loads on one mesh and one factorisation: each within the standard tolerances."""
    rs = fem.ball_on_race(brg209, [3500.0, 4450.0], race="inner", mode="half-space")
    assert rs[0].info["mesh_digests"] == rs[1].info["mesh_digests"]
    for r in rs:
        _assert_rows(r)


def test_exact_gap_is_beyond_hertz(brg209):
    """The exact sphere–torus gap changes the conformal inner-race ellipse (no tolerance)."""
    r = fem.ball_on_race(brg209, 4450.0, race="inner", level="quick", mode="half-space",
                         gap="exact")
    assert all(row["tol"] is None for row in r.comparison)
    assert r.a > 0 and r.b > 0


def _assert_standard(r, names=ALL):
    """Hold a result to the standard tolerances whatever mode it ran in."""
    tol = fem.TOLERANCES["standard"]
    rows = {row["quantity"]: row for row in r.comparison}
    bad = [f"{q}: {100 * rows[q]['error']:+.3f} % (tol {100 * tol[q]:.1f} %)"
           for q in names if abs(rows[q]["error"]) > tol[q]]
    assert not bad, "; ".join(bad)


@pytest.mark.parametrize("load", [69.5, 556.0])
def test_standard_inner_race_two_body_where_hertz_holds(brg209, load):
    """At a/(f D) = 0.10 and 0.19 the groove is shallow enough for Hertz's half-spaces: the
    two-body inner race meets the standard tolerances, depths included (measured: z0
    -0.86 / -0.76 %, max shear +0.68 / +1.13 %, docs/fem.md)."""
    r = fem.ball_on_race(brg209, load, race="inner", mode="two-body")
    assert r.a / (0.52 * 12.7e-3) < 0.2
    _assert_standard(r)


def test_ball_on_ball_two_body_departure_scales_with_contact_size():
    """Inside a ball the on-axis max shear falls below Hertz's half-space value in
    proportion to a/R (the mesh scales with the contact, so the discretisation error does
    not change with the load): at 2000 N (a/R = 0.055) about twice the departure at 250 N
    (a/R = 0.028), and both below the half-space result of the same contact."""
    r1 = fem.ball_on_ball(12.7e-3, 250.0, mode="two-body")
    r2 = fem.ball_on_ball(12.7e-3, 2000.0, mode="two-body")
    e = [{row["quantity"]: row["error"] for row in r.comparison}["max_shear"] for r in (r1, r2)]
    assert r2.a / r1.a == pytest.approx(2.0, rel=0.01)
    assert e[0] < 0 and e[1] < 0
    assert e[1] / e[0] == pytest.approx(2.0, rel=0.3)


@pytest.mark.parametrize("load", [31.25, 125.0, 2000.0])
def test_ball_on_ball_two_body_z0_against_the_axisymmetric_reference(load):
    """The 3-D shear depth z0 of two balls against a resolved axisymmetric model of the
    same two balls (:mod:`ballrace.fem.axisym`, n = 40: its half-space mode is within
    0.11 % of Lundberg–Palmgren, docs/fem-axisym.md).  The real balls put z0 0.9 / 4.0 %
    above LP's at a/R = 0.014 / 0.055; the 3-D standard level is within 2 % of the
    reference (measured +0.44 / +0.39 / +0.22 pp at 31 / 125 / 2000 N; 125 N was
    +3.0 pp before the probe box, docs/fem.md)."""
    from ballrace.fem import axisym

    ref = axisym.ball_on_ball(12.7e-3, load, n=40, mode="two-body")
    r = fem.ball_on_ball(12.7e-3, load, mode="two-body")
    assert r.z0 / ref.z0 - 1 == pytest.approx(0.0, abs=0.02)
    # and the max shear's departure from Hertz is the real one (within 0.3 % of it)
    assert r.max_shear / ref.max_shear - 1 == pytest.approx(0.0, abs=0.003)


# --------------------------------------------------------------------------- traction
TRACTION_ROWS = ("traction_von_mises", "traction_von_mises_x", "traction_von_mises_depth",
                 "traction_tresca", "traction_tresca_x", "traction_tresca_depth",
                 "traction_sxx_trailing", "traction_section_rms", "traction_resultant")


def _assert_traction(r):
    """The traction rows within fem.TRACTION_TOLERANCES['standard'] (docs/fem.md "Surface
    traction": measured errors at the quick and standard levels, with the margin stated
    there); a location is unchecked only where the surface and interior maxima lie
    within the value tolerance of each other (near the critical traction)."""
    rows = {row["quantity"]: row for row in r.comparison}
    for q in ("traction_von_mises", "traction_tresca", "traction_sxx_trailing",
              "traction_section_rms", "traction_resultant"):
        assert rows[q]["tol"] is not None, q
    bad = [f"{q}: {rows[q]['error']:+.4f} (tol {rows[q]['tol']})" for q in TRACTION_ROWS
           if not rows[q]["ok"]]
    assert not bad, "; ".join(bad)
    t = r.info["traction"]
    assert t["resultant"] == pytest.approx(t["mu"] * t["normal_resultant"], rel=1e-12)
    assert t["resultant"] == pytest.approx(t["mu"] * r.case.load, rel=1e-3)


@pytest.mark.parametrize("mu", [0.1, 0.3])
def test_standard_traction_ball_on_plane(mu):
    _assert_traction(fem.ball_on_plane(12.7e-3, 2000.0, level="standard", traction=mu))


@pytest.mark.parametrize("mu", [0.1, 0.3])
def test_standard_traction_inner_race(brg209, mu):
    r = fem.ball_on_race(brg209, 2000.0, race="inner", level="standard", traction=mu)
    _assert_traction(r)
    rows = {row["quantity"]: row for row in r.comparison}
    if mu == 0.1:          # well below the critical traction: the location is checked
        assert rows["traction_von_mises_depth"]["tol"] is not None


def test_standard_traction_hertz_pressure_matches_fe_pressure():
    """traction_pressure="hertz" loads the exact Hertz traction: the section agrees with
    the FE-pressure run to the FE pressure's own error (p_max within 0.5 %)."""
    a = fem.ball_on_plane(12.7e-3, 2000.0, level="standard", traction=0.3)
    b = fem.ball_on_plane(12.7e-3, 2000.0, level="standard", traction=0.3,
                          traction_pressure="hertz")
    ra = {row["quantity"]: row for row in a.comparison}
    rb = {row["quantity"]: row for row in b.comparison}
    assert rb["traction_resultant"]["error"] == pytest.approx(0.0, abs=1e-3)
    assert rb["traction_von_mises"]["fe"] == pytest.approx(ra["traction_von_mises"]["fe"],
                                                           rel=0.005)
