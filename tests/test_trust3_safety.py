"""Static safety from the actual contact pressure, and the solvers' operating warnings.

s0 = (4200 MPa / p_max)^3 (ISO 76:2006 bases C0 on 4200 MPa at the most loaded ball
contact; p_max ~ Q^(1/3) in a Hertz point contact) on every solver's result, and a
UserWarning from the static, duplex, high-speed and shaft solvers when s0 < 1, when a
deep-groove bearing runs beyond ratings.DEEP_GROOVE_ANGLE_LIMIT and when the ring tilt
exceeds ratings.PERMISSIBLE_MISALIGNMENT -- and none at a normal load.
"""
import contextlib
import math
import warnings

import numpy as np
import pytest

import ballrace
from ballrace.analytic import duplex, hertz, highspeed, loaddist, ratings
from ballrace.analytic import shaft as S

STEEL = ballrace.BEARING_STEEL
#: 6208 deep-groove bearing: 9 balls of 15/32 in (11.906 mm) on a 60 mm pitch circle,
#: ISO 76 groove radii 0.52 / 0.53, 15 um diametral clearance.
B6208 = ballrace.BallBearing(11.906e-3, 9, 60e-3, 0.52, 0.53, diametral_clearance=15e-6)
C0_6208 = ratings.static_rating(B6208)
#: 40 deg angular-contact bearing of 7311 proportions (tests/test_duplex.py).
AC = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52, free_contact_angle=np.radians(40))
C0_AC = ratings.static_rating(AC)


@contextlib.contextmanager
def _quiet():
    """Any warning in the block is an error (the normal-load cases)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


# ----------------------------------------------------------------------- the function
@pytest.mark.filterwarnings("ignore:point_contact. a / R")    # a = 0.56 D/2 at 4200 MPa
def test_static_safety_is_one_at_the_c0_pressure():
    """A ball on a 6208 inner groove loaded so that hertz.point_contact gives exactly
    4200 MPa: p ~ Q^(1/3) at fixed geometry, so Q* = Q1 (4200 MPa / p1)^3 reaches it; its
    s0 is 1 (1e-9, the exact-Hertz solve's tolerance)."""
    D, dm, fi = 11.906e-3, 60e-3, 0.52
    radii = (D / 2, D / 2, (dm - D) / 2, -fi * D)
    p1 = float(hertz.point_contact(1000.0, *radii, STEEL, STEEL).p_max)
    Q = 1000.0 * (4200e6 / p1) ** 3
    p = float(hertz.point_contact(Q, *radii, STEEL, STEEL).p_max)
    assert p == pytest.approx(4200e6, rel=1e-9)
    assert float(ratings.static_safety_from_pressure(p)) == pytest.approx(1.0, rel=1e-9)


def test_static_safety_function_values_and_input():
    # (4200 / 3000)^3 = 2.744; roller (4000 / 2000)^2 = 4; self-aligning (4600 / 4600)^3 = 1
    assert float(ratings.static_safety_from_pressure(3000e6)) == pytest.approx(2.744, rel=1e-14)
    assert float(ratings.static_safety_from_pressure(2000e6, "roller")) == pytest.approx(4.0)
    assert float(ratings.static_safety_from_pressure(4600e6, "self-aligning ball")) == 1.0
    assert np.isinf(ratings.static_safety_from_pressure(0.0))          # no load
    np.testing.assert_allclose(ratings.static_safety_from_pressure([4200e6, 8400e6]),
                               [1.0, 0.125], rtol=1e-14)
    with pytest.raises(ValueError, match="p_max"):
        ratings.static_safety_from_pressure(-1.0)
    with pytest.raises(ValueError, match="kind"):
        ratings.static_safety_from_pressure(1e9, "needle")
    with pytest.warns(UserWarning, match=r"p_max = 4200 Pa.*were MPa given"):
        ratings.static_safety_from_pressure(4200.0)


def test_limits_are_the_documented_values():
    """10 arcmin (SKF, deep-groove upper guide value), 2 arcmin (angular contact), 30 deg."""
    assert ratings.PERMISSIBLE_MISALIGNMENT["deep-groove"] == pytest.approx(
        math.radians(10 / 60), rel=1e-15)
    assert ratings.PERMISSIBLE_MISALIGNMENT["angular-contact"] == pytest.approx(
        math.radians(2 / 60), rel=1e-15)
    assert ratings.DEEP_GROOVE_ANGLE_LIMIT == pytest.approx(math.radians(30), rel=1e-15)
    assert ratings.bearing_type(B6208) == "deep-groove"
    assert ratings.bearing_type(AC) == "angular-contact"


# ----------------------------------------------------------------------- on the results
def test_load_distribution_static_safety_from_an_independent_hertz_contact():
    """Radial load on the 6208 (centred, ball 1 on the load line at beta = 0): s0 is
    (4200 MPa / p)^3 with p the larger of the inner and outer pressures of ball 1 from
    hertz.point_contact with the race radii (d_e -+ D)/2 and groove radii f D (1e-9)."""
    with _quiet():
        r = loaddist.radial(B6208, 5000.0)
    Q = float(r.ball_loads[0])
    assert Q == pytest.approx(float(r.max_ball_load), rel=1e-15)
    D, dm = B6208.ball_diameter, B6208.pitch_diameter
    pi = float(hertz.point_contact(Q, D / 2, D / 2, (dm - D) / 2, -0.52 * D, STEEL, STEEL).p_max)
    po = float(hertz.point_contact(Q, D / 2, D / 2, -(dm + D) / 2, -0.53 * D, STEEL,
                                   STEEL).p_max)
    assert float(r.max_pressure) == pytest.approx(max(pi, po), rel=1e-9)
    assert float(r.static_safety) == pytest.approx((4200e6 / max(pi, po)) ** 3, rel=1e-9)


def test_static_safety_at_c0_against_iso76():
    """ISO 76's own bearing (f 0.52 / 0.53, E = 207 GPa, nu = 0.3), zero clearance, radial
    F = C0.  ISO 76 takes Q_max = 5 C0 / Z; the rigid-ring distribution with zero
    clearance gives Q_max = F / sum(cos^2.5 psi_j) over the loaded half (Hamrock & Dowson
    1981 eq. 3.45 with P_d = 0): for Z = 9, 1 + 2 cos^2.5 40 + 2 cos^2.5 80 = 2.0525, so
    Z Q_max / F = 4.385 instead of 5.  Hence

    * s0 Q_max / (5 C0 / Z) = (4200 MPa / p_ISO)^3 exactly (same contact, p ~ Q^1/3; 1e-9),
      p_ISO from ratings.static_rating_pressure;
    * s0 = 5 / 4.385 = 1.140 within 0.5 %: the f0 table gives 4200 MPa only to +-0.15 %
      (ratings module notes), +-0.45 % in s0."""
    iso = ballrace.Material(E=207e9, nu=0.3)
    brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.53, diametral_clearance=0.0,
                               material=iso)
    C0 = ratings.static_rating(brg)
    r = loaddist.radial(brg, C0)                       # s0 > 1: no warning expected
    s0 = float(r.static_safety)
    q_iso = 5 * C0 / 9
    p_iso = ratings.static_rating_pressure(brg).p_max
    assert s0 * float(r.max_ball_load) / q_iso == pytest.approx((4200e6 / p_iso) ** 3, rel=1e-9)
    cos = np.cos(np.radians([0, 40, 80]))
    zq_f = 9 / (cos[0] ** 2.5 + 2 * cos[1] ** 2.5 + 2 * cos[2] ** 2.5)
    assert 9 * float(r.max_ball_load) / C0 == pytest.approx(zq_f, rel=1e-6)
    assert s0 == pytest.approx(5 / zq_f, rel=5e-3)


# ----------------------------------------------------------------------- warnings
def test_static_solver_warns_at_2_to_3_c0_and_not_at_a_normal_load():
    for f in (2.0, 2.5, 3.0):
        with pytest.warns(UserWarning, match=r"load distribution: static safety s0 = 0\.\d+ < 1"
                          ) as rec:
            r = loaddist.radial(B6208, f * C0_6208)
        assert float(r.static_safety) < 1.0                  # still returned
        assert all(w.filename == __file__ for w in rec)      # points at the caller
    with _quiet():
        r = loaddist.radial(B6208, 0.3 * C0_6208)
        B6208.combined(0.3 * C0_6208, 0.1 * C0_6208)
        B6208.thrust(0.25 * C0_6208)
    assert float(r.static_safety) > 1.0


def test_one_warning_per_solve_for_a_sweep():
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = loaddist.radial(B6208, np.array([0.5, 2.0, 3.0]) * C0_6208)
    msg = [str(w.message) for w in rec]
    assert len(msg) == 1 and "in 2 of 3 load cases" in msg[0], msg
    assert (np.asarray(r.static_safety) < 1).tolist() == [False, True, True]


def test_duplex_solver_warns_at_2_to_3_c0():
    """A DB pair carries radial load on two rows: 2.5 x (2 C0) puts s0 near 0.5."""
    pair = duplex.DuplexPair(AC, "DB", preload=3000.0)
    with pytest.warns(UserWarning, match=r"duplex pair \(DB\): static safety s0 = 0\.\d+ < 1"):
        r = pair.solve(Fr=2.5 * 2 * C0_AC)
    assert r.static_safety < 1.0
    assert r.static_safety == pytest.approx(
        float(ratings.static_safety_from_pressure(r.max_pressure)), rel=1e-14)
    with _quiet():
        r = pair.solve(Fa=5000.0, Fr=2000.0)
    assert r.static_safety > 1.0


def test_high_speed_solver_warns_at_2_to_3_c0_once():
    """The static start of the high-speed solve says nothing: one warning, from the
    high-speed result."""
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = highspeed.solve(B6208, Fr=2.5 * C0_6208, speed_inner=500.0)
    msg = [str(w.message) for w in rec]
    assert len(msg) == 1 and msg[0].startswith("high-speed equilibrium: static safety s0 = "), msg
    assert r.static_safety < 1.0
    with _quiet():
        r = highspeed.solve(B6208, Fr=0.2 * C0_6208, Fa=0.05 * C0_6208, speed_inner=500.0)
    assert r.static_safety > 1.0


def test_shaft_seat_warns_at_2_to_3_c0():
    """Two 6208 seats 160 mm apart, 5 C0 at mid-span: each seat carries 2.5 C0."""
    shaft = S.Shaft([(0.2, 0.04, 0.0)], STEEL)
    seats = [S.Seat(0.02, B6208, name="A"), S.Seat(0.18, B6208, floating=True, name="B")]
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = S.solve(shaft, seats, [S.PointLoad(0.1, Fy=5 * C0_6208)])
    msg = [str(w.message) for w in rec]
    assert sum(m.startswith("shaft seats[0] 'A' (x = 20 mm): static safety s0 = ") for m in msg) == 1
    assert sum(m.startswith("shaft seats[1] 'B' (x = 180 mm): static safety s0 = ") for m in msg) == 1
    assert np.all(r.static_safety < 1.0)
    np.testing.assert_allclose(r.static_safety,
                               ratings.static_safety_from_pressure(r.max_pressure), rtol=1e-14)
    with _quiet():
        r = S.solve(shaft, seats, [S.PointLoad(0.1, Fy=0.3 * C0_6208)])
        r.bearings
    assert np.all(r.static_safety > 1.0)


def test_overhung_gear_on_one_6208():
    """One locating 6208 carrying a 6 kN gear 140 mm away (840 N m): s0 < 1, contact
    angles near 40 deg, tilt 14 mrad -- three warnings, one each, and none again when the
    per-seat load distributions are looked at."""
    shaft = S.Shaft([(0.17, 0.04, 0.0)], STEEL)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = S.solve(shaft, [S.Seat(0.01, B6208, name="A")], [S.PointLoad(0.15, Fy=-6000.0)])
        ld = r.bearings[0]
    msg = [str(w.message) for w in rec]
    assert len(msg) == 3, msg
    assert "static safety s0 = 0.796 < 1" in msg[0]
    assert "contact angles up to 39.4 deg (limit 30 deg" in msg[1]
    assert "tilted 14 mrad" in msg[2] and "10 arcmin (2.91 mrad)" in msg[2]
    assert r.reactions[0, 4] == pytest.approx(-840.0, rel=1e-9)
    assert float(ld.static_safety) == pytest.approx(float(r.static_safety[0]), rel=1e-14)


def test_deep_groove_angle_warning():
    """Pure thrust on the 6208: 0.5 C0 (SKF's limit) runs at about 22 deg, no warning;
    2.5 C0 at 31.6 deg > 30 deg, a warning (s0 is still above 1 there)."""
    with _quiet():
        r = B6208.thrust(0.5 * C0_6208)
    assert 20 < np.degrees(r.contact_angles.max()) < 25
    with pytest.warns(UserWarning, match=r"deep-groove bearing runs at contact angles up to "
                                         r"31\.\d deg \(limit 30 deg"):
        r = B6208.thrust(2.5 * C0_6208)
    assert float(r.static_safety) > 1.0
    with _quiet():                                     # angular contact: no angle check
        AC.thrust(0.5 * C0_AC)


@pytest.mark.parametrize("brg, Fa, ok, bad, limit", [
    (B6208, 200.0, 1.0, 3.0, "10 arcmin (2.91 mrad)"),       # 2.61 / 3.22 mrad
    (AC, 5000.0, 5.0, 20.0, "2 arcmin (0.58 mrad)")])        # 0.32 / 1.20 mrad
def test_tilt_warning_at_the_permissible_misalignment(brg, Fa, ok, bad, limit):
    """A moment tilts the ring below and beyond the permissible misalignment of the type
    (deep-groove 2.91 mrad, angular-contact 0.58 mrad): one warning for the second, none
    for the first; an imposed tilt (the caller's choice) is not flagged."""
    with _quiet():
        r = loaddist.solve(brg, Fa=Fa, Fy=500.0 if brg is B6208 else 0.0, Mz=ok)
    assert r.misalignment < ratings.PERMISSIBLE_MISALIGNMENT[ratings.bearing_type(brg)]
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = loaddist.solve(brg, Fa=Fa, Fy=500.0 if brg is B6208 else 0.0, Mz=bad)
    msg = [str(w.message) for w in rec]
    assert len(msg) == 1 and "inner ring is tilted" in msg[0] and limit in msg[0], msg
    assert r.misalignment > ratings.PERMISSIBLE_MISALIGNMENT[ratings.bearing_type(brg)]
    with _quiet():
        loaddist.solve(brg, Fa=Fa, displacements=[np.nan, np.nan, np.nan, 0.0, 2 * r.misalignment])


# ----------------------------------------------------------------------- temperatures
def _spindle(**kw):
    shaft = S.Shaft([(0.3, 0.05, 0.02)], STEEL, thermal_expansion=11.5e-6)
    seats = [S.Seat(0.03, B6208, name="front"), S.Seat(0.27, B6208, floating=True, name="rear")]
    return S.solve(shaft, seats, [S.PointLoad(0.0, Fy=-1000.0, Fa=-300.0)], **kw)


def test_temperature_change_without_effect_is_said():
    with pytest.warns(UserWarning, match=r"shaft_temperature_change = 8 K has no effect: only "
                                         r"one seat locates"):
        r8 = _spindle(shaft_temperature_change=8.0)
    with _quiet():
        r0 = _spindle()
    np.testing.assert_allclose(r8.reactions, r0.reactions, rtol=1e-9, atol=1e-9 * 1000)


def test_implausible_temperature_change_is_questioned():
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        _spindle(shaft_temperature_change=300.0)
    msg = [str(w.message) for w in rec]
    assert any(m.startswith("shaft_temperature_change = 300 K: a uniform temperature change "
                            "of more than 150 K") for m in msg), msg
    assert any(m.startswith("shaft_temperature_change = 300 K has no effect") for m in msg)


def test_temperature_change_between_two_locating_seats_is_not_flagged():
    """An O arrangement of two angular-contact seats: the growth of the shaft changes the
    preload, so no 'no effect' warning, and the reactions change."""
    shaft = S.Shaft([(0.2, 0.045, 0.0)], STEEL, thermal_expansion=11.5e-6)
    seats = [S.Seat(0.02, AC, direction=1, offset=5e-6),
             S.Seat(0.18, AC, direction=-1, offset=5e-6)]
    with _quiet():
        r0 = S.solve(shaft, seats, [S.PointLoad(0.1, Fy=2000.0)])
        r1 = S.solve(shaft, seats, [S.PointLoad(0.1, Fy=2000.0)],
                     shaft_temperature_change=10.0)
    assert abs(r1.reactions[0, 0] - r0.reactions[0, 0]) > 10.0
