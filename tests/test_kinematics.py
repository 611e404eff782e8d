"""Ball-bearing kinematics: textbook closed forms, published defect-frequency factors,
race-control identities and invariants.

Sources are named in each test.  Tolerances: algebraic identities 1e-12; published
factors quoted to 4-5 significant figures to one unit of their last digit.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import kinematics as kin


# ----------------------------------------------------------- published defect factors
@pytest.mark.parametrize("name, D, d_m, Z, expected, tol", [
    # Case Western Reserve University Bearing Data Center, "Bearing information"
    # (defect frequencies in multiples of running speed, inner ring rotating):
    # drive end 6205-2RS JEM SKF: ball 0.3126 in, pitch 1.537 in, 9 balls
    # -> inner 5.4152, outer 3.5848, cage 0.39828, rolling element 4.7135;
    ("6205", 0.3126, 1.537, 9, dict(bpfi=5.4152, bpfo=3.5848, ftf=0.39828, re=4.7135), 1e-4),
    # fan end 6203-2RS JEM SKF: ball 0.2656 in, pitch 1.122 in, 8 balls
    # -> inner 4.9469, outer 3.0530, cage 0.3817, rolling element 3.9874.
    ("6203", 0.2656, 1.122, 8, dict(bpfi=4.9469, bpfo=3.0530, ftf=0.3817, re=3.9874), 3e-4),
])
def test_cwru_defect_factors(name, D, d_m, Z, expected, tol):
    """CWRU factors are quoted to 4-5 digits.  Drive end: all four agree with the closed
    forms to 4e-5 (cage 0.39828 vs 0.5 (1 - 0.3126/1.537) = 0.39831).  Fan end: the
    published cage (0.3817) and rolling-element (3.9874) factors differ from the closed
    forms (0.38164, 3.98768) by up to 2.8e-4, presumably rounding of the published ball
    and pitch diameters, hence 3e-4.  CWRU's "rolling element" frequency is 2 x BSF (a
    ball defect strikes both races)."""
    f = kin.defect_frequencies(D, d_m, Z, 0.0, speed_inner=1.0)
    assert f.bpfi == pytest.approx(expected["bpfi"], abs=tol)
    assert f.bpfo == pytest.approx(expected["bpfo"], abs=tol)
    assert f.ftf == pytest.approx(expected["ftf"], abs=tol)
    assert 2 * f.bsf == pytest.approx(expected["re"], abs=tol)


def test_defect_frequency_closed_forms_and_scaling():
    """Randall & Antoni (2011) eq. (1); Harris (2001) ch. 8: with outer ring fixed
    BPFO = Z/2 f (1 - g), BPFI = Z/2 f (1 + g), FTF = f/2 (1 - g),
    BSF = d_m/(2D) f (1 - g^2), g = D cos a / d_m; linear in the shaft frequency."""
    D, d_m, Z, a, f = 11.1e-3, 56.0e-3, 10, np.radians(25.0), 24.75
    g = D * np.cos(a) / d_m
    r = kin.defect_frequencies(D, d_m, Z, a, speed_inner=f)
    assert r.bpfo == pytest.approx(Z / 2 * f * (1 - g), rel=1e-14)
    assert r.bpfi == pytest.approx(Z / 2 * f * (1 + g), rel=1e-14)
    assert r.ftf == pytest.approx(f / 2 * (1 - g), rel=1e-14)
    assert r.bsf == pytest.approx(d_m / (2 * D) * f * (1 - g * g), rel=1e-14)
    # BPFO + BPFI = Z f (exact identity)
    assert r.bpfo + r.bpfi == pytest.approx(Z * f, rel=1e-14)


def test_outer_ring_rotating():
    """Outer ring rotating at f, inner fixed: FTF = f/2 (1 + g) (Harris 2001 ch. 8);
    the pass frequencies depend on the relative speed only and so keep their values."""
    D, d_m, Z, f = 0.3126, 1.537, 9, 1.0
    g = D / d_m
    out = kin.defect_frequencies(D, d_m, Z, 0.0, speed_inner=0.0, speed_outer=f)
    inn = kin.defect_frequencies(D, d_m, Z, 0.0, speed_inner=f)
    assert out.ftf == pytest.approx(0.5 * f * (1 + g), rel=1e-14)
    assert out.bpfo == pytest.approx(inn.bpfo, rel=1e-14)
    assert out.bpfi == pytest.approx(inn.bpfi, rel=1e-14)
    assert out.bsf == pytest.approx(inn.bsf, rel=1e-14)


def test_both_rings_rotating_superposition():
    """The cage speed is linear in the ring speeds; rotating both rings together at the
    same speed turns the whole bearing rigidly (no ball spin, no pass events)."""
    D, d_m, a = 12.7e-3, 60e-3, np.radians(15)
    wc = kin.cage_speed(D, d_m, a, 300.0, 120.0)
    assert wc == pytest.approx(kin.cage_speed(D, d_m, a, 300.0, 0.0)
                               + kin.cage_speed(D, d_m, a, 0.0, 120.0), rel=1e-14)
    rigid = kin.defect_frequencies(D, d_m, 12, a, 50.0, 50.0)
    assert rigid.ftf == pytest.approx(50.0, rel=1e-14)
    assert rigid.bpfo == pytest.approx(0.0, abs=1e-12)
    assert rigid.bpfi == pytest.approx(0.0, abs=1e-12)
    assert rigid.bsf == 0.0
    k = kin.ball_kinematics(D, d_m, a, a, 50.0, 50.0)
    assert k.ball_speed == pytest.approx(0.0, abs=1e-12)
    assert k.cage_speed == pytest.approx(50.0, rel=1e-14)


# ----------------------------------------------------------- race control (Jones / Harris)
def test_pitch_angle_closed_forms():
    """H&D (1981) eqs. 3.89-3.90 (Harris 2001 ch. 8): outer control
    tan b = sin a_o / (cos a_o + D/d_m); inner control tan b = sin a_i / (cos a_i - D/d_m)."""
    D, d_m, ai, ao = 22.225e-3, 125.26e-3, np.radians(44.0), np.radians(33.0)
    r = D / d_m
    bo = kin.pitch_angle(D, d_m, ai, ao, "outer")
    bi = kin.pitch_angle(D, d_m, ai, ao, "inner")
    assert np.tan(bo) == pytest.approx(np.sin(ao) / (np.cos(ao) + r), rel=1e-13)
    assert np.tan(bi) == pytest.approx(np.sin(ai) / (np.cos(ai) - r), rel=1e-13)
    assert kin.pitch_angle(D, d_m, ai, ao, "perpendicular") == pytest.approx(0.5 * (ai + ao))


@pytest.mark.parametrize("control", ["outer", "inner"])
def test_no_spin_on_controlling_race(control):
    """Jones (1959) race control: zero spin about the normal of the controlling contact."""
    D, d_m = 22.225e-3, 125.26e-3
    ai, ao = np.radians([44.0, 40.0, 30.0]), np.radians([33.0, 40.0, 30.0])
    k = kin.ball_kinematics(D, d_m, ai, ao, speed_inner=1047.2, control=control)
    spin = k.spin_outer if control == "outer" else k.spin_inner
    assert np.max(np.abs(spin)) < 1e-10 * 1047.2


def test_harris_outer_control_cage_and_ball_speed():
    """Harris (2001) ch. 8, outer-race control, outer ring fixed:
    w_c / w_i = (1 - g' cos a_i) / (1 + cos(a_i - a_o)) and
    w_R / w_i = -1 / {[(cos a_o + tan b sin a_o)/(1 + g' cos a_o)
                       + (cos a_i + tan b sin a_i)/(1 - g' cos a_i)] g' cos b}."""
    D, d_m, wi = 22.225e-3, 125.26e-3, 1047.2
    g = D / d_m
    ai, ao = np.radians(np.array([40.0, 44.3, 47.0])), np.radians(np.array([40.0, 35.1, 28.0]))
    k = kin.ball_kinematics(D, d_m, ai, ao, speed_inner=wi, control="outer")
    b = np.arctan(np.sin(ao) / (np.cos(ao) + g))
    wc = wi * (1 - g * np.cos(ai)) / (1 + np.cos(ai - ao))
    wR = -wi / (((np.cos(ao) + np.tan(b) * np.sin(ao)) / (1 + g * np.cos(ao))
                 + (np.cos(ai) + np.tan(b) * np.sin(ai)) / (1 - g * np.cos(ai))) * g * np.cos(b))
    np.testing.assert_allclose(k.cage_speed, wc, rtol=1e-13)
    np.testing.assert_allclose(k.ball_speed, wR, rtol=1e-13)
    np.testing.assert_allclose(k.pitch_angle, b, rtol=1e-13)


def test_equal_angles_reduce_to_classical_formulas():
    """With a_i = a_o and the ball axis perpendicular to the contact line the general
    kinematics give the classical cage speed and ball speed (Harris 2001 ch. 8)."""
    D, d_m, a = 12.7e-3, 64e-3, np.radians([0.0, 15.0, 25.0, 40.0])
    k = kin.ball_kinematics(D, d_m, a, a, speed_inner=100.0, speed_outer=-20.0,
                            control="perpendicular")
    np.testing.assert_allclose(k.cage_speed, kin.cage_speed(D, d_m, a, 100.0, -20.0), rtol=1e-13)
    np.testing.assert_allclose(k.ball_speed, kin.ball_speed(D, d_m, a, 100.0, -20.0), rtol=1e-13)
    # both contacts spin (except at a = 0): -(w_j - w_c) sin a about each normal
    np.testing.assert_allclose(k.spin_inner, -(100.0 - k.cage_speed) * np.sin(a), atol=1e-12)
    np.testing.assert_allclose(k.spin_outer, -(-20.0 - k.cage_speed) * np.sin(a), atol=1e-12)
    # the cage speed does not depend on the control hypothesis when a_i = a_o
    for c in ("outer", "inner"):
        kc = kin.ball_kinematics(D, d_m, a, a, 100.0, -20.0, control=c)
        np.testing.assert_allclose(kc.cage_speed, k.cage_speed, rtol=1e-13)


def test_spin_to_roll_closed_form():
    """Spin-to-roll ratios (Harris 2001 ch. 8):
    inner (1 - g_i) tan(a_i - b) + (D/d_m) sin a_i, outer (1 + g_o) tan(a_o - b) - (D/d_m) sin a_o;
    for a_i = a_o = a and outer control the inner ratio is 2 (D/d_m) sin a / (1 + g).
    Checked against the ratio of spin to roll from the velocity analysis."""
    D, d_m = 22.225e-3, 125.26e-3
    r = D / d_m
    a = np.radians(np.array([10.0, 25.0, 40.0]))
    i, o = kin.spin_to_roll(D, d_m, a, control="outer")
    np.testing.assert_allclose(i, 2 * r * np.sin(a) / (1 + r * np.cos(a)), rtol=1e-12)
    assert np.all(o == 0.0)
    ai, ao = np.radians(44.0), np.radians(33.0)
    for c in ("outer", "inner", "perpendicular"):
        i, o = kin.spin_to_roll(D, d_m, ai, ao, control=c)
        k = kin.ball_kinematics(D, d_m, ai, ao, 500.0, 0.0, control=c)
        assert i == pytest.approx(k.spin_to_roll_inner, rel=1e-11, abs=1e-13)
        assert o == pytest.approx(k.spin_to_roll_outer, rel=1e-11, abs=1e-13)


def test_radial_bearing_has_no_spin():
    """Zero contact angle: the ball axis is parallel to the bearing axis, no spin."""
    i, o = kin.spin_to_roll(7.94e-3, 39.04e-3, 0.0, control="outer")
    assert i == 0.0 and o == 0.0
    assert kin.pitch_angle(7.94e-3, 39.04e-3, 0.0) == 0.0


# ----------------------------------------------------------- BallBearing convenience
def test_bearing_convenience_matches_plain_functions():
    brg = ballrace.BallBearing(ball_diameter=22.225e-3, n_balls=16, pitch_diameter=125.26e-3,
                               f_inner=0.5232, f_outer=0.5232, free_contact_angle=np.radians(40))
    f = kin.bearing_defect_frequencies(brg, 10000 / 60)
    g = kin.defect_frequencies(22.225e-3, 125.26e-3, 16, np.radians(40), 10000 / 60)
    assert f == g
    k = kin.bearing_kinematics(brg, 1047.2)
    assert k.cage_speed == pytest.approx(float(kin.cage_speed(22.225e-3, 125.26e-3,
                                                              np.radians(40), 1047.2)))
    with pytest.raises(TypeError, match="bearing"):
        kin.bearing_defect_frequencies(object(), 1.0)


# ----------------------------------------------------------- input validation
def test_bad_inputs_name_the_argument():
    with pytest.raises(ValueError, match="D must be > 0"):
        kin.cage_speed(-1.0, 2.0)
    with pytest.raises(ValueError, match="D must be < d_m"):
        kin.cage_speed(3.0, 2.0)
    with pytest.raises(ValueError, match="contact_angle"):
        kin.cage_speed(1.0, 5.0, 2.0)
    with pytest.raises(ValueError, match="n_balls"):
        kin.defect_frequencies(1.0, 5.0, 0)
    with pytest.raises(ValueError, match="control"):
        kin.ball_kinematics(1.0, 5.0, 0.3, control="cage")
    with pytest.raises(ValueError, match="speed_inner"):
        kin.cage_speed(1.0, 5.0, 0.0, np.nan)


@settings(max_examples=200, deadline=None)
@given(rho=st.floats(0.02, 0.45), ai=st.floats(0.0, 1.3), ao=st.floats(0.0, 1.3),
       wi=st.floats(-2000, 2000), wo=st.floats(-2000, 2000),
       control=st.sampled_from(kin.CONTROLS))
def test_kinematics_finite_and_rolling_holds(rho, ai, ao, wi, wo, control):
    """No NaN; rolling without slip holds at both contact centres for any input."""
    k = kin.ball_kinematics(rho, 1.0, ai, ao, wi, wo, control)
    vals = [k.cage_speed, k.ball_speed, k.pitch_angle, k.spin_inner, k.spin_outer]
    assert np.all(np.isfinite(vals))
    b = k.pitch_angle
    lhs_o = k.ball_speed * rho / 2 * np.cos(ao - b)
    rhs_o = (wo - k.cage_speed) / 2 * (1 + rho * np.cos(ao))
    lhs_i = k.ball_speed * rho / 2 * np.cos(ai - b)
    rhs_i = (k.cage_speed - wi) / 2 * (1 - rho * np.cos(ai))
    scale = 1 + abs(wi) + abs(wo)
    assert abs(lhs_o - rhs_o) < 1e-11 * scale
    assert abs(lhs_i - rhs_i) < 1e-11 * scale
