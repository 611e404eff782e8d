"""Roller bearings as shaft seats (ballrace.analytic.shaft with RollerBearing, TaperedPair).

A gearbox shaft on a locating deep-groove ball bearing and a cylindrical roller bearing,
a preloaded pair of tapered roller bearings, and the lives of a shaft with ball and roller
seats (different Weibull slopes), each against statics, the roller load distribution
solved alone, or the life formulas re-derived here.
"""
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import ballrace
from ballrace.analytic import contract
from ballrace.analytic import shaft as S
from ballrace.analytic.roller import RollerBearing, RollerRow, TaperedPair
from ballrace.analytic.roller import loaddist as RL

STEEL = ballrace.Material(E=210e9, nu=0.3, density=7850.0, name="steel")
# 6208-size deep-groove ball bearing (as in gallery/plot_15) and an NU 207-size cylindrical
# roller bearing (the numbers of the public example, not a catalogue's)
BALL = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
CYL = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=20e-6)
TAP = RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered", contact_angle=np.radians(15))

XA, XB, XG = 0.015, 0.245, 0.09          # seats and gear [m]


def gearbox(Ft=5000.0):
    s = S.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)], STEEL)
    seats = [S.Seat(XA, BALL, name="A"), S.Seat(XB, CYL, name="B")]
    gear = S.gear_mesh(XG, Ft, 0.12, helix_angle=np.radians(15), mesh_azimuth=np.radians(90))
    return s, seats, gear


@pytest.fixture(scope="module")
def solved():
    s, seats, gear = gearbox()
    return s, seats, gear, S.solve(s, seats, [gear])


# --------------------------------------------------------------------------- the contract
def test_roller_bearings_satisfy_the_seat_contract():
    pair = TaperedPair(TAP, "DB", preload=1000.0)
    for b in (CYL, TAP, pair):
        assert isinstance(b, contract.SeatBearing) and contract.missing(b) == []
        for m in b.seat_rows(1, 0.0, 0.0, None):
            assert isinstance(m.row, contract.Row)
            assert contract.missing(m.row, contract.ROW_MEMBERS) == []
    assert CYL.carries_axial is False and TAP.carries_axial is True
    assert CYL.life_exponent == pytest.approx(10 / 3) and CYL.weibull_slope == 9 / 8
    assert CYL.equivalent_load(1000.0, 0.0) == 1000.0
    # tapered X/Y of ISO 281 (single row): Fa/Fr > e = 1.5 tan(15 deg) -> 0.4 Fr + 0.4 cot(a) Fa
    a = np.radians(15)
    assert TAP.equivalent_load(1000.0, 1000.0) == pytest.approx(400 + 400 / np.tan(a), rel=1e-12)
    # both rows of a pair share one model
    r1, r2 = (m.row for m in pair.seat_rows(1, 0.0, 0.0, None))
    assert r1 == r2 and hash(r1) == hash(r2)
    assert pair.seat_name == "tapered pair DB" and CYL.seat_name == "cylindrical"


def test_roller_row_is_the_lamina_model_at_imposed_displacements():
    # ring_forces, element_loads and result are RollerBearing.solve with every DOF imposed;
    # the tangent is the derivative of the forces, the forces the gradient of the energy
    # (central differences, 1e-5 relative)
    u = np.array([[0.0, 30e-6, -8e-6, 2e-4, 4e-4]])
    for b in (CYL, TAP):
        row = RollerRow(b)
        uu = u.copy()
        if b.tapered:
            uu[0, 0] = 5e-6
        F, K, dmax, energy = row.ring_forces(uu)
        r = b.solve(displacements=row.to_bearing_frame(uu[0]))
        assert F[0] == pytest.approx(r.loads, rel=1e-12, abs=1e-9)
        assert K[0] == pytest.approx(r.stiffness, rel=1e-12, abs=1e-6)
        assert row.element_loads(uu[0]) == pytest.approx(r.roller_loads, rel=1e-12, abs=1e-9)
        assert dmax[0] == pytest.approx(r.approaches.max(), rel=1e-12)
        for i in range(5):
            h = 1e-9 if i < 3 else 1e-7
            up, um = uu.copy(), uu.copy()
            up[0, i] += h
            um[0, i] -= h
            Fp, _, _, Ep = row.ring_forces(up)
            Fm, _, _, Em = row.ring_forces(um)
            assert (Fp[0] - Fm[0]) / (2 * h) == pytest.approx(K[0][:, i], rel=1e-5,
                                                              abs=1e-6 * np.abs(K).max())
            assert (Ep[0] - Em[0]) / (2 * h) == pytest.approx(F[0, i], rel=1e-5,
                                                              abs=1e-6 * np.abs(F).max())
    # the cylindrical row has no axial law; the tapered row's u = 0 is just touching
    assert RollerRow(CYL).reference_axial_offset == 0.0
    t = RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered", contact_angle=np.radians(15),
                      diametral_clearance=40e-6)
    row = RollerRow(t)
    assert row.reference_axial_offset == pytest.approx(t.axial_clearance, rel=1e-12)
    assert row.ring_forces(np.array([[-1e-9, 0, 0, 0, 0]]))[0][0, 0] == 0.0
    assert row.ring_forces(np.array([[1e-7, 0, 0, 0, 0]]))[0][0, 0] > 0.0


# --------------------------------------------------------------------------- gearbox shaft
def test_gearbox_reactions_by_statics_and_no_axial_load_on_the_roller_seat(solved):
    # Rigid shaft on two supports (independent of the solver): the gear's forces
    # (Fy = -F_t, Fz = -F_t tan(20 deg)/cos(15 deg), Fa = F_t tan(15 deg) and the moment of
    # Fa at the pitch radius, My = r Fa) split by the lever rule,
    #   R_B = [(x_G - x_A) F + M] / (x_B - x_A),  R_A = F - R_B,
    # exact when the seats carry no moment.  They carry some (the roller bearing's tilt
    # stiffness and the ball bearing's, through the shaft's slope): the exact balance with
    # the seat moments included holds to 1e-9, the lever rule to the seat moments' share,
    # |M_A| + |M_B| over the span, and to 5 % of the gear force.
    s, seats, gear, r = solved
    R, F = r.reactions, gear.vector
    Ft = 5000.0
    assert F[1] == pytest.approx(-Ft, rel=1e-12)
    assert F[2] == pytest.approx(-Ft * np.tan(np.radians(20)) / np.cos(np.radians(15)),
                                 rel=1e-12)
    span = XB - XA
    # x-y plane: moments about z; x-z plane: moments about y (w = -theta_y x)
    RBy = ((XG - XA) * F[1] + F[4]) / span
    RBz = ((XG - XA) * F[2] - F[3]) / span
    assert R[:, :3].sum(0) == pytest.approx(F[:3], abs=1e-9 * Ft)
    exact_y = ((XG - XA) * F[1] + F[4] - R[0, 4] - R[1, 4]) / span
    exact_z = ((XG - XA) * F[2] - F[3] + R[0, 3] + R[1, 3]) / span
    assert R[1, 1] == pytest.approx(exact_y, abs=1e-9 * Ft)
    assert R[1, 2] == pytest.approx(exact_z, abs=1e-9 * Ft)
    for lever, got, M in ((RBy, R[1, 1], R[:, 4]), (RBz, R[1, 2], R[:, 3])):
        assert abs(got - lever) <= np.abs(M).sum() / span * (1 + 1e-9)
        assert got == pytest.approx(lever, abs=0.05 * Ft)
    assert R[0, 1] == pytest.approx(F[1] - RBy, abs=0.05 * Ft)
    # the whole thrust on the locating ball seat, none on the cylindrical roller seat
    assert R[0, 0] == pytest.approx(Ft * np.tan(np.radians(15)), rel=1e-9)
    assert R[1, 0] == 0.0
    assert np.abs(r.equilibrium_residual()).max() < 1e-8 * Ft


def test_roller_seat_loads_are_the_bearings_own_solution(solved):
    # RollerBearing.solve at the seat's ring displacement (shaft frame = bearing frame for
    # direction +1) gives the seat's reaction and roller loads
    s, seats, gear, r = solved
    u = r.ring_displacements[1]
    alone = CYL.solve(displacements=u)
    assert alone.loads == pytest.approx(r.reactions[1], rel=1e-10, abs=1e-9)
    seat = r.bearings[1]
    assert isinstance(seat, RL.RollerLoadDistribution)
    assert seat.roller_loads == pytest.approx(alone.roller_loads, rel=1e-12, abs=1e-9)
    assert seat.slice_loads.shape == (14, CYL.n_slices)
    assert r.seat_stiffness[1] == pytest.approx(alone.stiffness, rel=1e-10, abs=1e-3)
    assert r.static_safety[1] == pytest.approx(alone.static_safety, rel=1e-12)
    assert seat.roller_loads.max() > 0 and (seat.roller_loads == 0).sum() >= 7
    assert seats[1].ball_bearing is None and seats[0].ball_bearing is BALL


def test_a_shaft_on_cylindrical_roller_bearings_only_is_refused():
    s, _, gear = gearbox()
    seats = [S.Seat(XA, CYL), S.Seat(XB, CYL)]
    with pytest.raises(ValueError, match="no axial support"):
        S.solve(s, seats, [gear])


# --------------------------------------------------------------------------- tapered pair
def _pair_shaft(pair, loads=()):
    s = S.Shaft([(0.2, 0.04, 0.0)], STEEL)
    return S.solve(s, [S.Seat(0.05, pair, row_spacing=0.02)], list(loads))


def test_preloaded_tapered_pair_at_zero_load_carries_its_preload_in_both_rows():
    P = 2000.0
    pair = TaperedPair(TAP, "DB", preload=P)
    # delta_0 from the row's own axial law: all 17 rollers alike
    d0 = pair.preload_deflection
    assert pair.axial_load(d0) == pytest.approx(P, rel=1e-12)
    r = _pair_shaft(pair)
    assert np.abs(r.reactions[0]).max() < 1e-6 * P
    rows = r.bearings[0]
    assert len(rows) == 2
    for ld in rows:
        assert ld.loads[0] == pytest.approx(P, rel=1e-9)              # each row: the preload
        # each roller alike: Q sin(alpha_o) = P / Z
        assert ld.roller_loads == pytest.approx(
            np.full(17, P / (17 * np.sin(TAP.contact_angle))), rel=1e-9)
    # the pair's axial stiffness is both rows' (parallel springs): 2 dF/dx at delta_0
    k1 = RollerRow(TAP).ring_forces(np.array([[d0, 0, 0, 0, 0]]))[1][0, 0, 0]
    assert r.seat_stiffness[0][0, 0] == pytest.approx(2 * k1, rel=1e-9)


def test_preload_stiffens_the_pair_and_end_play_is_taken_up_first():
    Fa = 1000.0
    free = TaperedPair(TAP, "DB")
    pre = TaperedPair(TAP, "DB", preload=2000.0)
    play = TaperedPair(TAP, "DB", end_play=40e-6)
    assert play.preload_deflection == pytest.approx(-20e-6, rel=1e-15)
    x = {}
    for name, p in (("free", free), ("pre", pre), ("play", play)):
        r = _pair_shaft(p, [S.PointLoad(0.05, Fa=Fa)])
        x[name] = r.ring_displacements[0, 0]
        assert r.reactions[0, 0] == pytest.approx(Fa, rel=1e-9)
    assert 0 < x["pre"] < 0.5 * x["free"]
    # pure thrust: with end play the shaft first crosses half the play, then deflects as
    # the free pair's loaded row (the other row is off in both)
    assert x["play"] == pytest.approx(x["free"] + 20e-6, rel=1e-6)
    with pytest.raises(ValueError, match="not both"):
        TaperedPair(TAP, "DB", preload=100.0, end_play=1e-5)
    with pytest.raises(ValueError, match="tapered"):
        TaperedPair(CYL, "DB", preload=100.0)
    with pytest.raises(ValueError, match="arrangement"):
        TaperedPair(TAP, "DT", preload=100.0)


# --------------------------------------------------------------------------- lives
def test_system_life_of_ball_and_roller_seats_by_hand(solved):
    # Each row's ISO/TS 16281 life: the ball row from its ball loads, the roller row from
    # its slice loads (RollerBearing.reference_rating_life of the solution alone).  The
    # system: S_sys(L) = 0.9^((L/L_b)^(10/9)) 0.9^((L/L_r)^(9/8)) = 0.9 at L = L_sys,
    # solved here by brentq.
    s, seats, gear, r = solved
    L = S.rating_lives(r)
    alone = CYL.solve(displacements=r.ring_displacements[1])
    Lr = CYL.reference_rating_life(alone).L10r
    assert L.seat_lives[1] == pytest.approx(Lr, rel=1e-10)
    Lb = L.seat_lives[0]
    assert L.seat_weibull_slopes == (10 / 9, 9 / 8) and math.isnan(L.weibull_slope)
    f = lambda x: (x / Lb) ** (10 / 9) + (x / Lr) ** (9 / 8) - 1.0
    hand = brentq(f, 1e-6 * min(Lb, Lr), min(Lb, Lr), xtol=1e-13 * min(Lb, Lr), rtol=1e-15)
    assert L.system == pytest.approx(hand, rel=1e-12)
    # between the common-slope lives with either slope
    lo, hi = sorted(S.system_life([Lb, Lr], e) for e in (10 / 9, 9 / 8))
    assert lo <= L.system <= hi
    # the roller seat's catalogue life: (C_r / F_r)^(10/3), F_r from the reaction
    Fr = math.hypot(r.reactions[1, 1], r.reactions[1, 2])
    assert L.catalog_lives[1] == pytest.approx((CYL.dynamic_rating() / Fr) ** (10 / 3),
                                               rel=1e-12)
    # one slope given: used for all seats (the common-slope formula)
    L1 = S.rating_lives(r, weibull_slope=10 / 9)
    assert L1.system == pytest.approx((Lb ** (-10 / 9) + Lr ** (-10 / 9)) ** -0.9, rel=1e-12)


def test_system_life_with_per_bearing_slopes():
    # equal slopes reduce to the closed form; a bearing of infinite life drops out
    assert S.system_life([1000.0, 2000.0], [10 / 9, 10 / 9]) == pytest.approx(
        (1000.0 ** (-10 / 9) + 2000.0 ** (-10 / 9)) ** -0.9, rel=1e-14)
    assert S.system_life([1000.0, np.inf], [10 / 9, 9 / 8]) == pytest.approx(1000.0, rel=1e-14)
    L = S.system_life([1000.0, 1000.0], [10 / 9, 9 / 8])
    assert (L / 1000) ** (10 / 9) + (L / 1000) ** (9 / 8) == pytest.approx(1.0, abs=1e-14)
    with pytest.raises(ValueError, match="weibull_slope"):
        S.system_life([1000.0, 1000.0], [10 / 9, 9 / 8, 1.0])


def test_duty_cycle_with_a_roller_seat():
    # Palmgren-Miner per seat, then the mixed-slope system life of the seats' hours
    s, seats, gear = gearbox()
    g2 = S.gear_mesh(XG, 3000.0, 0.12, helix_angle=np.radians(15), mesh_azimuth=np.radians(90))
    cases = [([gear], 0.4, 1000.0), ([g2], 0.6, 1500.0)]
    d = S.duty_cycle(s, seats, cases)
    H = np.array([S.rating_lives(S.solve(s, seats, ld)).seat_lives * 1e6 / (60 * n)
                  for ld, _, n in cases])
    assert d.case_hours == pytest.approx(H, rel=1e-9)
    seat_h = 1.0 / (0.4 / H[0] + 0.6 / H[1])
    assert d.seat_hours == pytest.approx(seat_h, rel=1e-9)
    seat_h = d.seat_hours                      # the system from the seats' hours
    f = lambda x: (x / seat_h[0]) ** (10 / 9) + (x / seat_h[1]) ** (9 / 8) - 1.0
    hand = brentq(f, 1e-9 * seat_h.min(), seat_h.min(), xtol=1e-13 * seat_h.min(), rtol=1e-15)
    assert d.system_hours == pytest.approx(hand, rel=1e-12)
    assert d.seat_weibull_slopes == (10 / 9, 9 / 8)


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="preload"):
        TaperedPair(TAP, "DB", preload=-1.0)
    with pytest.raises(ValueError, match=r"end_play.*were micrometres given"):
        TaperedPair(TAP, "DB", end_play=50.0)
    with pytest.raises(ValueError, match="preload=1e\\+09 N is beyond the load-deflection"):
        TaperedPair(TAP, "DB", preload=1e9)
    with pytest.raises(TypeError, match="bearing must be a RollerBearing; got BallBearing"):
        TaperedPair(BALL, "DB", preload=100.0)
    with pytest.raises(TypeError, match="bearing must be a RollerBearing"):
        RollerRow(BALL)
    with pytest.raises(ValueError, match="clearance"):
        RollerRow(CYL, clearance=5e-3)
    with pytest.raises(ValueError, match="clearance is for a single bearing"):
        S.Seat(0.0, TaperedPair(TAP, "DB", preload=100.0), clearance=1e-5)
    two = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, n_rows=2)
    with pytest.raises(ValueError, match="n_rows=1"):
        S.Seat(0.0, two)
    with pytest.raises(ValueError, match="nominal_contact_angle is for ball bearings"):
        RollerRow(CYL).rating_life(np.array([0, 1e-5, 0, 0, 0.0]), nominal_contact_angle=0.1)


def test_two_single_tapered_seats_in_o_arrangement():
    # Seat.offset of a single tapered bearing is beyond its just-touching position (the
    # seat contract's frame): both seats with an offset preload the O pair; at zero load
    # the two reactions cancel and each row carries the same thrust, below that of a row
    # pushed by the whole offset (the shaft's axial compliance takes some of it).
    s = S.Shaft([(0.2, 0.04, 0.0)], STEEL)
    off = 5e-6
    seats = [S.Seat(0.03, TAP, direction=1, offset=off),
             S.Seat(0.17, TAP, direction=-1, offset=off)]
    r = S.solve(s, seats, [])
    Fa0 = TaperedPair(TAP, "DB").axial_load(off)       # one row at the offset, rigid shaft
    assert r.reactions[0, 0] == pytest.approx(-r.reactions[1, 0], rel=1e-9)
    b0, b1 = r.bearings
    assert b0.loads[0] == pytest.approx(b1.loads[0], rel=1e-9)
    assert 0.5 * Fa0 < b0.loads[0] < Fa0
    # a radial load: the induced thrust of the loaded seat, 1.26 F_r tan(a)-sized, is held
    # by the other seat (the reactions' thrusts still cancel: no external thrust)
    r = S.solve(s, seats, [S.PointLoad(0.05, Fy=-5000.0)])
    assert r.reactions[0, 0] == pytest.approx(-r.reactions[1, 0], rel=1e-9)
    assert r.reactions[:, 1].sum() == pytest.approx(-5000.0, rel=1e-9)
