"""BallBearing geometry: Ricci (2009) eqs. (1)–(11), H&D (1981) §2 / §3.2, validation.

Verification values are Ricci's closed forms written out independently here; the 218
bearing is Ricci's (and Harris's) example.
"""
import dataclasses

import numpy as np
import pytest

import ballrace
from ballrace.analytic import hertz
from ballrace.analytic.bearing import BallBearing
from ballrace.analytic.materials import BEARING_STEEL, SILICON_NITRIDE, effective_modulus

STEEL = ballrace.Material(E=200e9, nu=0.3)


def ricci218(**kw):
    args = dict(ball_diameter=22.225e-3, n_balls=16, pitch_diameter=125.26e-3, f_inner=0.5232,
                f_outer=0.5232, free_contact_angle=np.radians(40), material=STEEL)
    args.update(kw)
    return BallBearing(**args)


def test_public_import():
    assert ballrace.BallBearing is BallBearing
    assert "BallBearing" in ballrace.__all__


def test_ricci_218_clearance_endplay():
    # Ricci (2009) eqs. (4)-(7): A = B D, P_d = 2A(1 - cos bf), P_e = 2A sin bf
    b = ricci218()
    A = (0.5232 + 0.5232 - 1) * 22.225e-3
    assert b.total_conformity == pytest.approx(0.0464, rel=1e-12)
    assert b.curvature_center_distance == pytest.approx(A, rel=1e-12)
    assert b.diametral_clearance == pytest.approx(2 * A * (1 - np.cos(np.radians(40))), rel=1e-12)
    assert b.free_endplay == pytest.approx(2 * A * np.sin(np.radians(40)), rel=1e-12)
    assert isinstance(b.diametral_clearance, float) and isinstance(b.free_contact_angle, float)


@pytest.mark.parametrize("deg", [0.0, 5.0, 15.0, 40.0, 89.0])
def test_clearance_angle_round_trip(deg):
    b1 = ricci218(free_contact_angle=np.radians(deg))
    b2 = ricci218(free_contact_angle=None, diametral_clearance=b1.diametral_clearance)
    assert b2.free_contact_angle == pytest.approx(np.radians(deg), abs=1e-7 if deg == 0 else 1e-12)
    assert b2.free_endplay == pytest.approx(b1.free_endplay, rel=1e-9, abs=1e-12)


def test_race_diameters():
    # Ricci (2009) eq. (1): d_e = (d_i + d_o)/2; fig. 2: P_d = d_o - d_i - 2D
    b = ricci218()
    assert 0.5 * (b.inner_race_diameter + b.outer_race_diameter) == pytest.approx(125.26e-3, rel=1e-14)
    assert b.outer_race_diameter - b.inner_race_diameter - 2 * b.ball_diameter == pytest.approx(
        b.diametral_clearance, rel=1e-9)


def test_groove_centre_radius_matches_ricci_for_equal_conformities():
    # Ricci (2009) after eq. (17): R_i = d_e/2 + (f_i - 0.5) D cos bf
    b = ricci218()
    assert b.inner_groove_center_radius == pytest.approx(
        125.26e-3 / 2 + (0.5232 - 0.5) * 22.225e-3 * np.cos(np.radians(40)), rel=1e-14)


@pytest.mark.parametrize("deg", [0.0, 16.169, 40.0, 44.317, 75.0])
def test_curvature_sum_and_difference_ricci_eqs_8_to_11(deg):
    b = ricci218(f_outer=0.53)
    D, dm = b.ball_diameter, b.pitch_diameter
    g = D * np.cos(np.radians(deg)) / dm
    fi, fo = b.f_inner, b.f_outer
    inv_Ri = (4 - 1 / fi + 2 * g / (1 - g)) / D                                  # eq. 8
    Gi = (1 / fi + 2 * g / (1 - g)) / (4 - 1 / fi + 2 * g / (1 - g))           # eq. 9
    inv_Ro = (4 - 1 / fo - 2 * g / (1 + g)) / D                                  # eq. 10
    Go = (1 / fo - 2 * g / (1 + g)) / (4 - 1 / fo - 2 * g / (1 + g))           # eq. 11
    ci = b.curvature("inner", np.radians(deg))
    co = b.curvature("outer", np.radians(deg))
    assert isinstance(ci, hertz.Curvature)
    assert float(ci.curvature_sum) == pytest.approx(inv_Ri, rel=1e-13)
    assert float(ci.curvature_difference) == pytest.approx(Gi, rel=1e-13)
    assert float(co.curvature_sum) == pytest.approx(inv_Ro, rel=1e-13)
    assert float(co.curvature_difference) == pytest.approx(Go, rel=1e-13)
    # the same from the principal radii (Ricci's r_ax, r_bx, r_by) via hertz.curvature
    rbx_i = (dm - D * np.cos(np.radians(deg))) / (2 * np.cos(np.radians(deg))) if deg < 90 else np.inf
    ref = hertz.curvature(D / 2, D / 2, rbx_i, -fi * D)
    assert float(ci.Rx) == pytest.approx(float(ref.Rx), rel=1e-13)
    assert float(ci.Ry) == pytest.approx(float(ref.Ry), rel=1e-13)


def test_curvature_vectorized_and_gamma():
    b = ricci218()
    beta = np.radians([10.0, 20.0, 30.0])
    c = b.curvature("outer", beta)
    assert c.Rx.shape == (3,) and c.Ry.shape == (3,)
    assert np.allclose(b.gamma(beta), b.ball_diameter * np.cos(beta) / b.pitch_diameter, rtol=1e-15)


def test_contact_stiffness_combination_hd_3_38():
    b = ricci218()
    beta = np.radians([30.0, 40.0, 50.0])
    Ki, Ko, Kn = b.contact_stiffness(beta)
    ci, co = b.curvature("inner", beta), b.curvature("outer", beta)
    assert np.allclose(Ki, hertz.contact_stiffness(ci.Rx, ci.Ry, b.E_prime), rtol=1e-14)
    assert np.allclose(Ko, hertz.contact_stiffness(co.Rx, co.Ry, b.E_prime), rtol=1e-14)
    assert np.allclose(Kn, (Ki ** (-2 / 3) + Ko ** (-2 / 3)) ** -1.5, rtol=1e-14)
    # delta_n = delta_i + delta_o = (Q/K_n)^(2/3) (H&D eqs. 3.35-3.37)
    Q = np.array([1000.0, 5000.0, 9445.0])
    di = b.contacts(Q, beta, "inner").approach
    do = b.contacts(Q, beta, "outer").approach
    assert np.allclose(di + do, (Q / Kn) ** (2 / 3), rtol=1e-11)


def test_contacts_vectorized_unloaded():
    b = ricci218()
    c = b.contacts(np.array([[0.0, 100.0], [2000.0, 0.0]]), np.radians(40), "inner")
    assert c.a.shape == (2, 2)
    assert c.p_max[0, 0] == 0.0 and c.a[1, 1] == 0.0
    assert np.all(np.isfinite(c.p_max))


def test_ceramic_balls_effective_modulus():
    hybrid = ricci218(ball_material=SILICON_NITRIDE)
    assert hybrid.ball_material is SILICON_NITRIDE and hybrid.ring_material is STEEL
    assert hybrid.E_prime == pytest.approx(effective_modulus(SILICON_NITRIDE, STEEL), rel=1e-15)
    assert hybrid.E_prime > ricci218().E_prime
    # stiffer contacts with ceramic balls
    assert hybrid.contact_stiffness(0.7)[2] > ricci218().contact_stiffness(0.7)[2]
    assert hybrid.ball_mass == pytest.approx(np.pi * 22.225e-3**3 * 3200.0 / 6, rel=1e-14)


def test_default_material_is_bearing_steel():
    b = BallBearing(0.01, 9, 0.05, 0.52, 0.52, diametral_clearance=0.0)
    assert b.material is BEARING_STEEL and b.ball_material is BEARING_STEEL
    assert b.free_contact_angle == 0.0 and b.free_endplay == 0.0


def test_frozen_and_replace():
    b = ricci218()
    with pytest.raises(dataclasses.FrozenInstanceError):
        b.n_balls = 12
    b2 = dataclasses.replace(b, material=SILICON_NITRIDE, ball_material=None, ring_material=None)
    assert b2.free_contact_angle == b.free_contact_angle and b2.E_prime != b.E_prime
    with pytest.raises(ValueError, match="not both"):
        dataclasses.replace(b, f_inner=0.52)          # stale derived clearance
    b3 = dataclasses.replace(b, f_inner=0.52, diametral_clearance=None)
    assert b3.free_contact_angle == pytest.approx(np.radians(40), rel=1e-14)


def test_shoulder_angle():
    b = ricci218(shoulder_height_inner=0.2 * 22.225e-3)
    theta = b.shoulder_angle("inner")
    assert theta == pytest.approx(np.arccos(1 - 0.2 / 0.5232), rel=1e-14)
    assert b.shoulder_angle("outer") is None


@pytest.mark.parametrize("kw, name", [
    (dict(f_inner=0.5), "f_inner"),
    (dict(f_outer=0.45), "f_outer"),
    (dict(n_balls=2), "n_balls"),
    (dict(n_balls=40), "n_balls"),                       # does not fit on the pitch circle
    (dict(ball_diameter=0.2), "ball_diameter"),
    (dict(ball_diameter=-1e-3), "ball_diameter"),
    (dict(pitch_diameter=0.0), "pitch_diameter"),
    (dict(free_contact_angle=np.pi / 2), "free_contact_angle"),
    (dict(free_contact_angle=-0.1), "free_contact_angle"),
    (dict(free_contact_angle=None, diametral_clearance=-1e-6), "diametral_clearance"),
    (dict(free_contact_angle=None, diametral_clearance=0.01), "diametral_clearance"),
    (dict(diametral_clearance=1e-4), "not both"),
    (dict(free_contact_angle=None), "neither"),
    (dict(shoulder_height_inner=0.0), "shoulder_height_inner"),
    (dict(shoulder_height_outer=0.02), "shoulder_height_outer"),
    (dict(n_rows=0), "n_rows"),
])
def test_invalid_geometry_names_argument(kw, name):
    with pytest.raises(ValueError, match=name):
        ricci218(**kw)


def test_type_errors():
    with pytest.raises(ValueError, match="n_balls must be a whole number"):
        ricci218(n_balls=12.5)                  # a number, but not a count: a bad value
    with pytest.raises(TypeError, match="n_balls"):
        ricci218(n_balls=True)
    with pytest.raises(TypeError, match="material"):
        ricci218(ball_material="steel")
    with pytest.raises(TypeError, match="ball_diameter"):
        ricci218(ball_diameter="big")


def test_race_argument_checked():
    with pytest.raises(ValueError, match="race"):
        ricci218().curvature("middle", 0.5)


def test_rating_delegation():
    pytest.importorskip("ballrace.analytic.ratings")
    from ballrace.analytic import ratings
    b = ricci218()
    assert b.dynamic_rating() == ratings.dynamic_rating(b, standard="ISO 281:2007")
    assert b.static_rating() == ratings.static_rating(b)


def test_thin_methods_delegate():
    from ballrace.analytic import loaddist
    b = ricci218()
    assert np.array_equal(b.thrust(17800.0).ball_loads, loaddist.thrust(b, 17800.0).ball_loads)
    assert np.array_equal(b.solve(Fa=1000.0, Fy=500.0).ball_loads,
                          loaddist.solve(b, Fa=1000.0, Fy=500.0).ball_loads)


# ----------------------------------------------------------------------------- nominal angle
def test_nominal_contact_angle_default_rule():
    """The rating angle belongs to the bearing type (ISO 281:2007 §6.1.1, ISO 76:2006
    §5.1.1): given by its clearance (deep groove) -> 0; given by its angle (angular
    contact) -> that design angle; stated explicitly -> kept."""
    b = ricci218()
    assert b.nominal_contact_angle == np.radians(40)
    dg = BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=10e-6)
    # cos a_f = 1 - P_d / (2 (f_i + f_o - 1) D) = 1 - 10e-6 / 1.15e-3 (Ricci 2009 eq. 5)
    assert np.cos(dg.free_contact_angle) == pytest.approx(1 - 10e-6 / 1.15e-3, rel=1e-13)
    assert dg.nominal_contact_angle == 0.0
    both = ricci218(diametral_clearance=b.diametral_clearance)     # both given, agreeing
    assert both.nominal_contact_angle == np.radians(40)
    c = ricci218(free_contact_angle=None, diametral_clearance=b.diametral_clearance,
                 nominal_contact_angle=np.radians(40))
    assert c.nominal_contact_angle == np.radians(40)
    assert ricci218(nominal_contact_angle=np.radians(15)).nominal_contact_angle == \
        pytest.approx(np.radians(15), rel=1e-15)
    assert ricci218(nominal_contact_angle=np.float64(0.5)).nominal_contact_angle == 0.5


def test_nominal_contact_angle_survives_replace():
    """An operating clearance (dataclasses.replace of the clearance, as
    clearance.OperatingClearance.bearing does) does not change the rating angle; None
    derives it again."""
    b = ricci218()
    looser = dataclasses.replace(b, free_contact_angle=None,
                                 diametral_clearance=1.2 * b.diametral_clearance)
    assert looser.free_contact_angle > b.free_contact_angle
    assert looser.nominal_contact_angle == np.radians(40)
    dg = BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=10e-6)
    tighter = dataclasses.replace(dg, free_contact_angle=None, diametral_clearance=2e-6)
    assert tighter.nominal_contact_angle == 0.0
    again = dataclasses.replace(b, free_contact_angle=None, nominal_contact_angle=None)
    assert again.nominal_contact_angle == 0.0       # now given by its clearance


@pytest.mark.parametrize("value, extra", [
    (-0.1, ""), (np.pi / 2, ""), (2.0, "degrees"), (40.0, "degrees"), (120.0, ""),
])
def test_nominal_contact_angle_range(value, extra):
    with pytest.raises(ValueError, match="nominal_contact_angle") as err:
        ricci218(nominal_contact_angle=value)
    assert "[0, 1.5708)" in str(err.value) and repr(value) in str(err.value)
    assert extra in str(err.value)
    if not extra:
        assert "degrees" not in str(err.value)


def test_nominal_contact_angle_types():
    with pytest.raises(TypeError, match="nominal_contact_angle"):
        ricci218(nominal_contact_angle="40 deg")
    with pytest.raises(TypeError, match="nominal_contact_angle"):
        ricci218(nominal_contact_angle=[0.1, 0.2])
    with pytest.raises(ValueError, match="nominal_contact_angle"):
        ricci218(nominal_contact_angle=float("nan"))


def test_large_clearance_angle_defaulted_to_zero_warns_the_caller():
    """A clearance giving a 40 deg free angle is an angular-contact bearing's: rated at 0
    by the default rule, so a UserWarning (not a log record nobody sees) says to pass the
    nominal angle, attributed to the caller's line."""
    import warnings

    b = ricci218()
    with pytest.warns(UserWarning, match="free contact angle of 40.0 deg.*nominal_contact_angle"
                      ) as rec:
        ricci218(free_contact_angle=None, diametral_clearance=b.diametral_clearance)
    assert rec[0].filename == __file__
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=10e-6)
        ricci218(free_contact_angle=None, diametral_clearance=b.diametral_clearance,
                 nominal_contact_angle=np.radians(40))
