"""Elastic shaft on nonlinear ball bearings (ballrace.analytic.shaft).

Each validation case derives its expected value in its docstring: statics and
Timoshenko beam theory (Castigliano with shear), the three-moment equation of a
continuous beam, the single-bearing solver, the duplex pair and superposition.
"""
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import duplex as dx
from ballrace.analytic import loaddist as ld
from ballrace.analytic import shaft as S

STEEL = ballrace.BEARING_STEEL
#: 6208-like deep-groove bearing at zero clearance (D = 12.7 mm, Z = 9, d_e = 60 mm).
DG0 = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=0.0)
#: Small deep-groove bearing with 10 um clearance (doctest of shaft.solve).
DG = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53, diametral_clearance=10e-6)
#: 40 deg angular-contact bearing of 7311 proportions (as in tests/test_duplex.py).
AC = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52, free_contact_angle=np.radians(40))
#: A small, loosely conforming deep-groove bearing (low tilt stiffness, see the
#: three-seat test).
SMALL = ballrace.BallBearing(4e-3, 8, 18e-3, 0.57, 0.57, diametral_clearance=0.0)


def _props(D, d=0.0, mat=STEEL):
    E, nu = mat.E, mat.nu
    G = E / (2 * (1 + nu))
    A = np.pi / 4 * (D**2 - d**2)
    I = np.pi / 64 * (D**4 - d**4)
    return E, G, A, I, float(S.shear_coefficient(nu, d / D))


# --------------------------------------------------------------------------- frame & helpers
def test_shear_coefficient_cowper():
    """Cowper (1966) Table 1: solid circle 6(1+nu)/(7+6nu) = 0.8864 at nu = 0.3; thin
    tube (m -> 1): 2(1+nu)/(4+3nu) = 0.5306."""
    assert float(S.shear_coefficient(0.3)) == pytest.approx(6 * 1.3 / 8.8, rel=1e-15)
    assert float(S.shear_coefficient(0.3, 1 - 1e-9)) == pytest.approx(2 * 1.3 / 4.9, rel=1e-8)


def test_gear_mesh_components():
    """Helical gear, mesh point at phi = 90 deg (+z): F_t along e_t = -y, radial force
    towards the axis (-z), F_r = F_t tan(20)/cos(15) = 376.8 N, F_a = F_t tan(15) = 267.9 N
    for F_t = 1000 N; the moment of F_a at the pitch point (0, 0, r): M = p x F,
    M_y = r F_a, M_z = 0 (helical-gear force components, Shigley's *Mechanical
    Engineering Design*, ch. 13)."""
    p = S.gear_mesh(0.1, 1000.0, 0.2, helix_angle=np.radians(15), mesh_azimuth=np.pi / 2)
    Fr = 1000 * np.tan(np.radians(20)) / np.cos(np.radians(15))
    assert p.Fy == pytest.approx(-1000.0, rel=1e-12)
    assert p.Fz == pytest.approx(-Fr, rel=1e-12)
    assert p.Fa == pytest.approx(1000 * np.tan(np.radians(15)), rel=1e-12)
    assert p.My == pytest.approx(0.1 * p.Fa, rel=1e-12)
    assert abs(p.Mz) < 1e-12
    # |F| = F_t sqrt(1 + tan^2 a_n / cos^2 b + tan^2 b)
    assert np.linalg.norm([p.Fa, p.Fy, p.Fz]) == pytest.approx(
        1000 * np.sqrt(1 + np.tan(np.radians(20))**2 / np.cos(np.radians(15))**2
                       + np.tan(np.radians(15))**2), rel=1e-12)


def test_element_is_timoshenko_cantilever():
    """One element, clamped at node 1, tip force P: v = P L^3/(3EI) + P L/(kappa G A) and
    tip rotation P L^2/(2EI) (Timoshenko beam theory; the element is exact)."""
    L, D = 0.1, 0.03
    E, G, A, I, k = _props(D)
    K = S._element(L, E, G, A, I, k)
    Kf = K[5:, 5:]
    P = 1000.0
    u = np.linalg.solve(Kf, np.array([0, P, 0, 0, 0]))
    assert u[1] == pytest.approx(P * L**3 / (3 * E * I) + P * L / (k * G * A), rel=1e-12)
    assert u[4] == pytest.approx(P * L**2 / (2 * E * I), rel=1e-12)
    u = np.linalg.solve(Kf, np.array([0, 0, P, 0, 0]))       # x-z plane: theta_y = -dw/dx
    assert u[2] == pytest.approx(P * L**3 / (3 * E * I) + P * L / (k * G * A), rel=1e-12)
    assert u[3] == pytest.approx(-P * L**2 / (2 * E * I), rel=1e-12)


# --------------------------------------------------------------------------- validation
def test_two_seats_statics_and_timoshenko_deflection():
    r"""Two deep-groove bearings (zero clearance) at x_A = 0.03 and x_B = 0.23 m on a
    45 mm solid shaft, F_y = P = 5 kN at c = 0.09 m (a = 0.06, b = 0.14, l = 0.2 m).

    Reactions by statics: R_A = P b / l = 3500 N, R_B = P a / l = 1500 N.  The bearings'
    own tilt stiffness makes the beam very slightly clamped; its moments (< 1 N m here)
    shift the reactions by sum(M)/l, bounded by 1e-4 P.

    Deflection under the load (Castigliano with shear, unit load at c):

    .. math:: \delta = \frac{P a^2 b^2}{3 E I l} + \frac{P a b}{\kappa G A l}
              + \delta_A \frac{b}{l} + \delta_B \frac{a}{l}

    with delta_A, delta_B the radial deflections of a single bearing under R_A, R_B
    (``BallBearing.radial``), interpolated linearly along the span (rigid-body motion
    of the beam on its supports): 1 % (the bearings' tilt stiffness, end moments
    M ~ 0.75 N m against P a b / l = 210 N m, stiffens the span by ~0.5 %).

    Tight check, with the seat moments the solve finds (Mz_A, and R_A) put into the same
    beam theory: the bending moment in the span is
    M(x) = -(x - x_A) R_A + Mz_A + P <x - c>, the unit-load moment m(x) = b x'/l before
    c and a (l - x')/l after it, and v(c) - chord = -int m M / EI dx + int V_1 V /
    (kappa G A) dx (V = -R_A + P H(x - c), V_1 = -b/l + H(x - c)); the chord joins the
    single bearings' deflections under the seats' five loads (``BallBearing.solve``):
    1e-6.
    """
    from scipy.integrate import quad
    s = S.Shaft([(0.26, 45e-3, 0.0)], STEEL)
    P, xa, xb, c = 5000.0, 0.03, 0.23, 0.09
    r = S.solve(s, [S.Seat(xa, DG0), S.Seat(xb, DG0)], [S.PointLoad(c, Fy=P)])
    a, b, l = c - xa, xb - c, xb - xa
    Ra, Rb = P * b / l, P * a / l
    assert r.reactions[0, 1] == pytest.approx(Ra, abs=1e-4 * P)
    assert r.reactions[1, 1] == pytest.approx(Rb, abs=1e-4 * P)
    E, G, A, I, k = _props(45e-3)
    dA = DG0.radial(Ra).radial_deflection
    dB = DG0.radial(Rb).radial_deflection
    beam = P * a**2 * b**2 / (3 * E * I * l) + P * a * b / (k * G * A * l)
    expected = beam + dA * b / l + dB * a / l
    got = r.displacement(c)[1]
    assert got == pytest.approx(expected, rel=0.01)
    # tight: the same theory with the seat moments
    RA, MA = r.reactions[0, 1], r.reactions[0, 4]

    def M(x):
        return -(x - xa) * RA + MA + P * max(x - c, 0.0)

    def m(x):
        return b * (x - xa) / l if x < c else a * (xb - x) / l

    bend = -(quad(lambda x: m(x) * M(x), xa, c, epsabs=0, epsrel=1e-13)[0]
             + quad(lambda x: m(x) * M(x), c, xb, epsabs=0, epsrel=1e-13)[0]) / (E * I)
    shear = ((-b / l) * (-RA) * a + (a / l) * (P - RA) * b) / (k * G * A)
    yA = DG0.solve(*r.reactions[0]).displacements[1]
    yB = DG0.solve(*r.reactions[1]).displacements[1]
    expected = bend + shear + yA * b / l + yB * a / l
    assert got == pytest.approx(expected, rel=1e-6)
    assert r.displacement(xa)[1] == pytest.approx(yA, rel=1e-6)
    assert r.displacement(xb)[1] == pytest.approx(yB, rel=1e-6)


def test_three_seats_three_moment_reactions():
    r"""Continuous beam on three supports, two equal spans l = 0.5 m, P at the middle of
    the first span.  Three-moment equation (Clapeyron), supports A, B, C, end moments 0:
    2 M_B (l + l) = -6 A_1 xbar_1 / l, and for a point load P at a from A (b from B)
    6 A_1 xbar_1 / l = P a (l^2 - a^2) / l = 3 P l^2 / 8 at a = l/2, so M_B = -3 P l / 32.
    Span AB about B: R_A l - P l/2 = M_B -> R_A = 13P/32; span BC about B: R_C l = M_B ->
    R_C = -3P/32; R_B = P - R_A - R_C = 11P/16.

    The bearings approach rigid simple supports: the radial compliance of a small,
    loose (f = 0.57) deep-groove bearing under these loads is ~1e-3 of the shaft's
    deflection, its tilt stiffness K_t ~ R R_i^2 / A gives K_t l / EI ~ 1e-3, and the shear
    parameter 12 EI/(kappa G A l^2) of the 20 mm shaft is ~1e-3: tolerance 1 % of P.
    The third bearing carries a negative load (-3P/32 pulls the shaft down): a
    deep-groove bearing takes -F_y as it takes +F_y (symmetric)."""
    s = S.Shaft([(1.0, 20e-3, 0.0)], STEEL)
    P = 200.0
    seats = [S.Seat(0.0, SMALL), S.Seat(0.5, SMALL), S.Seat(1.0, SMALL)]
    r = S.solve(s, seats, [S.PointLoad(0.25, Fy=P)])
    expected = np.array([13 / 32, 11 / 16, -3 / 32]) * P
    assert r.reactions[:, 1] == pytest.approx(expected, abs=0.01 * P)
    err = np.abs(r.reactions[:, 1] - expected).max() / P
    assert err > 0          # not trivially equal: the bearings are elastic
    assert r.bearings[2].loads[1] == pytest.approx(r.reactions[2, 1], rel=1e-9)
    assert r.bearings[2].loads[1] < 0


def test_single_seat_matches_single_bearing_solve():
    """One seat carrying a short stiff shaft, loads at the seat: the shaft passes them on
    unchanged, so the ball loads equal ``BallBearing.solve`` at the same loads (1e-8),
    for either mounting direction (direction=-1: loads mapped by diag(-1,-1,1,-1,1))."""
    s = S.Shaft([(0.02, 80e-3, 0.0)], STEEL)
    F = dict(Fa=5000.0, Fy=3000.0, Fz=-1000.0, My=15.0, Mz=20.0)
    r = S.solve(s, [S.Seat(0.01, AC)], [S.PointLoad(0.01, **F)])
    ref = AC.solve(**F)
    np.testing.assert_allclose(r.bearings[0].ball_loads, ref.ball_loads, rtol=1e-8,
                               atol=1e-8 * ref.max_ball_load)
    np.testing.assert_allclose(r.reactions[0], list(F.values()), rtol=1e-9, atol=1e-9)
    r = S.solve(s, [S.Seat(0.01, AC, direction=-1)],
                [S.PointLoad(0.01, Fa=-5000.0, Fy=-3000.0, Fz=-1000.0, My=-15.0, Mz=20.0)])
    np.testing.assert_allclose(r.bearings[0].ball_loads, ref.ball_loads, rtol=1e-8,
                               atol=1e-8 * ref.max_ball_load)
    # the seat stiffness is the bearing's tangent stiffness
    np.testing.assert_allclose(r.seat_stiffness[0], S.MIRROR[:, None] * ref.stiffness
                               * S.MIRROR[None, :], rtol=1e-6, atol=1e-6 * ref.stiffness.max())


def test_load_offset_from_seat_is_a_moment():
    """A radial load F_y at distance e from the only seat reaches the bearing as F_y and
    M_z = e F_y (statics; a short stiff overhang), to 1e-9."""
    s = S.Shaft([(0.05, 80e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.01, DG0)], [S.PointLoad(0.04, Fy=2000.0, Fz=-500.0)])
    np.testing.assert_allclose(r.reactions[0], [0, 2000, -500, -0.03 * -500, 0.03 * 2000],
                               rtol=1e-9, atol=1e-9 * 2000)


def test_duplex_seat_matches_duplex_pair_and_lifts_off():
    """A DB pair (7311 geometry, preload 2 kN) as one seat on a short stiff shaft:
    the rows carry the axial loads of ``DuplexPair.solve`` (1e-7), and row 2 lifts off
    exactly at ``DuplexPair.unloading_load`` F_u = F_a(2 delta_0) (Harris 2001 §7.5):
    at 0.98 F_u it still carries load (Q ~ delta^1.5: ~1 N), at F_u its largest ball load is
    below 1e-6 P."""
    P = 2000.0
    pair = dx.DuplexPair(AC, "DB", preload=P)
    s = S.Shaft([(0.02, 80e-3, 0.0)], STEEL)
    for Fa in (1000.0, 3000.0, -2500.0):
        r = S.solve(s, [S.Seat(0.01, pair)], [S.PointLoad(0.01, Fa=Fa)])
        ref = pair.solve(Fa=Fa)
        got = [float(b.loads[0]) for b in r.bearings[0]]
        np.testing.assert_allclose(np.maximum(got, 0), ref.axial_loads, rtol=1e-7)
    Fu = pair.unloading_load
    r = S.solve(s, [S.Seat(0.01, pair)], [S.PointLoad(0.01, Fa=0.98 * Fu)])
    assert r.bearings[0][1].max_ball_load > 0.1
    r = S.solve(s, [S.Seat(0.01, pair)], [S.PointLoad(0.01, Fa=Fu)])
    assert r.bearings[0][1].max_ball_load < 1e-6 * P
    assert r.reactions[0, 0] == pytest.approx(Fu, rel=1e-9)


def test_o_arrangement_offset_preload_lift_off():
    """Two single 7311-type bearings at two seats 20 mm apart in O arrangement
    (+1 left, -1 right), each mounted delta_0 = DuplexPair.preload_deflection into its
    contact: with the 80 mm shaft between them (EA/L ~ 5e10 N/m against ~1e9 N/m of
    the bearings) this is the DB pair, so the unloaded bearing lifts off near
    F_u (1 %), and each bearing carries the preload P (1 %) without external load."""
    P = 2000.0
    pair = dx.DuplexPair(AC, "DB", preload=P)
    d0 = pair.preload_deflection
    s = S.Shaft([(0.04, 80e-3, 0.0)], STEEL)
    seats = [S.Seat(0.01, AC, direction=1, offset=d0), S.Seat(0.03, AC, direction=-1, offset=d0)]
    r0 = S.solve(s, seats, [S.PointLoad(0.02, Fy=1e-3)])
    assert r0.reactions[0, 0] == pytest.approx(P, rel=0.01)
    assert r0.reactions[1, 0] == pytest.approx(-P, rel=0.01)
    Fu = pair.unloading_load
    r = S.solve(s, seats, [S.PointLoad(0.02, Fa=0.99 * Fu)])
    r2 = S.solve(s, seats, [S.PointLoad(0.02, Fa=1.01 * Fu)])
    assert r.bearings[1].max_ball_load > 0 or r2.bearings[1].max_ball_load == 0
    assert r2.bearings[1].max_ball_load == 0.0


def test_spring_preload_is_carried():
    """A floating seat pressed by a spring P carries exactly P axially (in its thrust
    direction) and the locating seat the opposite, under any radial load (equilibrium
    of the axially free outer ring)."""
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL)
    P = 300.0
    seats = [S.Seat(0.02, AC, direction=1), S.Seat(0.18, AC, direction=-1, floating=True,
                                                       spring_preload=P)]
    r = S.solve(s, seats, [S.PointLoad(0.1, Fy=2000.0)])
    assert r.reactions[1, 0] == pytest.approx(-P, rel=1e-9)
    assert r.reactions[0, 0] == pytest.approx(P, rel=1e-8)


def test_thermal_growth_equals_offset_change():
    """Superposition of an initial strain: a shaft warmer by dT between two locating
    angular-contact seats in O arrangement, L_AB = 0.16 m, grows by
    Delta = alpha dT L_AB between them, which unloads an O pair exactly as mounting
    both bearings Delta/2 less deep (offsets) at the original temperature.  Both
    solves must give the same reactions (1e-7); and the growth reduces the preload."""
    a = 11.5e-6
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL, thermal_expansion=a)
    off, dT, L = 20e-6, 15.0, 0.16
    ld_ = [S.PointLoad(0.08, Fy=3000.0)]
    hot = S.solve(s, [S.Seat(0.02, AC, 1, offset=off), S.Seat(0.18, AC, -1, offset=off)], ld_,
                  shaft_temperature_change=dT)
    d = a * dT * L
    cold = S.solve(s, [S.Seat(0.02, AC, 1, offset=off - d / 2),
                       S.Seat(0.18, AC, -1, offset=off - d / 2)], ld_)
    np.testing.assert_allclose(hot.reactions, cold.reactions, rtol=1e-7,
                               atol=1e-7 * np.abs(cold.reactions).max())
    base = S.solve(s, [S.Seat(0.02, AC, 1, offset=off), S.Seat(0.18, AC, -1, offset=off)], ld_)
    assert hot.reactions[0, 0] < base.reactions[0, 0]
    # a housing growing as much (same alpha, same dT) cancels the shaft's growth
    both = S.solve(s, [S.Seat(0.02, AC, 1, offset=off), S.Seat(0.18, AC, -1, offset=off)], ld_,
                   shaft_temperature_change=dT, housing_temperature_change=dT,
                   housing_expansion=a)
    np.testing.assert_allclose(both.reactions, base.reactions, rtol=1e-7,
                               atol=1e-7 * np.abs(base.reactions).max())


def test_housing_stiffness_in_series():
    """A radial housing spring k_h in series with the bearing: the seat's outer ring
    moves by R / k_h (equilibrium of the outer ring), the reactions stay the statics
    ones of a load midway between equal seats (P/2 each, symmetry)."""
    s = S.Shaft([(0.3, 40e-3, 0.0)], STEEL)
    kh = 5e7
    seats = [S.Seat(0.05, DG0, housing_stiffness=[1e9, kh, kh, 1e6, 1e6]),
             S.Seat(0.25, DG0, floating=True, housing_stiffness=[0, kh, kh, 1e6, 1e6])]
    r = S.solve(s, seats, [S.PointLoad(0.15, Fy=4000.0)])
    assert r.reactions[:, 1] == pytest.approx([2000.0, 2000.0], rel=1e-6)
    assert r.housing_displacements[:, 1] == pytest.approx(r.reactions[:, 1] / kh, rel=1e-3)
    assert r.reactions[1, 0] == pytest.approx(0.0, abs=1e-6)


def test_weight_resultant():
    """Own weight: m g with m = rho pi D^2 L / 4 (uniform shaft), carried half by each of
    two seats placed symmetrically (statics, 1e-6)."""
    s = S.Shaft([(0.4, 60e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.05, DG0), S.Seat(0.35, DG0)], [],
                gravity=(0.0, -S.STANDARD_GRAVITY, 0.0))
    W = STEEL.density * np.pi / 4 * 0.06**2 * 0.4 * S.STANDARD_GRAVITY
    assert r.reactions[:, 1] == pytest.approx([-W / 2, -W / 2], rel=1e-6)
    assert np.abs(r.equilibrium_residual(0.2)).max() < 1e-8 * W


# --------------------------------------------------------------------------- invariants
_PAIR = dx.DuplexPair(AC, "DB", preload=1000.0)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(x=st.floats(0.0, 0.3), Fy=st.floats(-8000, 8000), Fz=st.floats(-8000, 8000),
       Fa=st.floats(-2000, 2000), M=st.floats(-100, 100), cfg=st.integers(0, 3),
       off=st.floats(-20e-6, 20e-6))
def test_global_equilibrium(x, Fy, Fz, Fa, M, cfg, off):
    """sum(loads) - sum(reactions) = 0 with moments about any point, to the solver
    tolerance (1e-8 of the largest load), floating seats carry no thrust, and each
    bearing's own result carries its seat's reaction (mapped to its frame): deep-groove
    seats with a third floating seat, an O pair of angular-contact bearings with end play
    or preload, a DB pair with 20 mm row spacing and a floating deep-groove seat."""
    s = S.Shaft([(0.1, 40e-3, 0.0), (0.1, 50e-3, 10e-3), (0.1, 40e-3, 0.0)], STEEL)
    if cfg == 0:
        seats = [S.Seat(0.02, DG), S.Seat(0.28, DG, floating=True)]
    elif cfg == 1:
        seats = [S.Seat(0.02, DG0), S.Seat(0.15, DG, floating=True),
                 S.Seat(0.28, DG0, floating=True)]
    elif cfg == 2:
        seats = [S.Seat(0.02, AC, 1, offset=off), S.Seat(0.28, AC, -1, offset=off)]
    else:
        seats = [S.Seat(0.03, _PAIR, row_spacing=0.02), S.Seat(0.28, DG0, floating=True)]
    loads = [S.PointLoad(x, Fa=Fa, Fy=Fy, Fz=Fz, My=M), S.PointLoad(0.2, Fy=1000.0)]
    r = S.solve(s, seats, loads)
    scale = max(abs(Fa), abs(Fy), abs(Fz), 1000.0)
    for pt in (0.0, 0.13):
        res = r.equilibrium_residual(pt)
        assert np.abs(res[:3]).max() < 1e-8 * scale
        assert np.abs(res[3:]).max() < 1e-8 * scale * 0.3
    for k, seat in enumerate(seats):
        if seat.floating:
            assert abs(r.reactions[k, 0]) < 1e-8 * scale
        b = r.bearings[k]
        if isinstance(b, tuple):
            continue
        T = np.ones(5) if seat.direction > 0 else S.MIRROR
        np.testing.assert_allclose(b.loads, T * r.reactions[k], rtol=1e-9,
                                   atol=1e-9 * scale)


# --------------------------------------------------------------------------- bad input
def test_no_axial_support_is_named():
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL)
    with pytest.raises(ValueError, match="no axial support"):
        S.solve(s, [S.Seat(0.02, DG, floating=True), S.Seat(0.18, DG, floating=True)],
                [S.PointLoad(0.1, Fy=100.0)])
    with pytest.raises(ValueError, match="rigid-body"):
        S.solve(s, [], [S.PointLoad(0.1, Fy=100.0)])


@pytest.mark.parametrize("bad, match", [
    (dict(seats=[0.5]), "position"),
    (dict(seats=[0.05, 0.05]), "same position"),
    (dict(load=0.3), "loads\\[0\\].position"),
])
def test_bad_geometry(bad, match):
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL)
    seats = [S.Seat(x, DG) for x in bad.get("seats", [0.02, 0.18])]
    with pytest.raises(ValueError, match=match):
        S.solve(s, seats, [S.PointLoad(bad.get("load", 0.1), Fy=100.0)])


def test_bad_arguments():
    with pytest.raises(ValueError, match="inner_diameter"):
        S.Shaft([(0.2, 40e-3, 40e-3)], STEEL)
    with pytest.raises(ValueError, match="direction"):
        S.Seat(0.1, DG, direction=2)
    with pytest.raises(ValueError, match="spring_preload needs floating"):
        S.Seat(0.1, DG, spring_preload=10.0)
    with pytest.raises(ValueError, match="housing_stiffness"):
        S.Seat(0.1, DG, housing_stiffness=[1.0, 2.0])
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL)
    with pytest.raises(ValueError, match="within the shaft"):
        S.solve(s, [S.Seat(0.02, DG), S.Seat(0.18, DG)], [S.PointLoad(0.1, Fy=1.0)]
                ).displacement(0.3)


def test_overload_is_value_error():
    """Loads beyond the bearings' load-deflection range are refused, not returned."""
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL)
    with pytest.raises((ValueError, ld.ConvergenceError)):
        S.solve(s, [S.Seat(0.02, DG), S.Seat(0.18, DG)], [S.PointLoad(0.1, Fy=5e6)])


# --------------------------------------------------------------------------- clearance, life
def test_operating_clearance_seat():
    """A seat given an OperatingClearance uses its operating value: the ball loads are
    those of loaddist.solve with clearance = P_d (1e-8); the rings' temperature
    difference (inner 10 K warmer) reduces P_d by alpha dT d_i-ish (clearance module)."""
    from ballrace.analytic.clearance import operating_clearance
    brg = ballrace.BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=20e-6)
    oc = operating_clearance(brg, bore=0.025, outside_diameter=0.062, shaft_interference=15e-6,
                             inner_temperature=313.15, outer_temperature=303.15)
    s = S.Shaft([(0.02, 30e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.01, brg, clearance=oc)], [S.PointLoad(0.01, Fy=2000.0, Fa=200.0)])
    ref = ld.solve(brg, Fa=200.0, Fy=2000.0, clearance=oc.operating)
    np.testing.assert_allclose(r.bearings[0].ball_loads, ref.ball_loads, rtol=1e-8,
                               atol=1e-8 * ref.max_ball_load)
    assert r.bearings[0].clearance == pytest.approx(oc.operating, rel=1e-15)


def test_life_single_seat_and_system():
    """Single seat: the seat life is ISO/TS 16281 L10r of the bearing's own solve
    (iso16281.reference_rating_life, 1e-8).  A duplex pair's two rows and two seats
    combine by the weakest-link rule L = (sum L_i^-e)^(-1/e), e = 10/9: two equal
    lives give L 2^(-9/10)."""
    from ballrace.analytic.iso16281 import reference_rating_life
    s = S.Shaft([(0.02, 30e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.01, DG0)], [S.PointLoad(0.01, Fy=3000.0, Fa=500.0)])
    lf = S.rating_lives(r)
    ref = reference_rating_life(DG0, DG0.solve(Fa=500.0, Fy=3000.0))
    assert lf.seat_lives[0] == pytest.approx(ref.L10r, rel=1e-8)
    assert lf.system == pytest.approx(ref.L10r, rel=1e-8)
    assert float(S.system_life([7.0, 7.0])) == pytest.approx(7.0 * 2 ** -0.9, rel=1e-14)
    assert lf.weibull_slope == pytest.approx(10 / 9)
    # the DB pair without external load: both rows carry the preload alike
    pair = dx.DuplexPair(AC, "DB", preload=2000.0)
    r = S.solve(s, [S.Seat(0.01, pair)], [S.PointLoad(0.01, Fy=1e-6)])
    lf = S.rating_lives(r)
    a, b = lf.row_lives[0]
    assert a == pytest.approx(b, rel=1e-6)
    assert lf.seat_lives[0] == pytest.approx(a * 2 ** -0.9, rel=1e-6)


def test_duty_cycle_miner():
    """Two cases (30 % at 1500 rpm, 70 % at 3000 rpm): each seat's life is the
    Palmgren–Miner sum 1/(t1/L1 + t2/L2) of its lives in hours under each case alone,
    the lives from separate solves (1e-9); the system life combines the seats."""
    s = S.Shaft([(0.26, 45e-3, 0.0)], STEEL)
    seats = [S.Seat(0.03, DG), S.Seat(0.23, DG, floating=True)]
    c1, c2 = [S.PointLoad(0.09, Fy=3000.0)], [S.PointLoad(0.09, Fy=1000.0, Fa=300.0)]
    d = S.duty_cycle(s, seats, [(c1, 0.3, 1500.0), (c2, 0.7, 3000.0)])
    h1 = S.rating_lives(S.solve(s, seats, c1)).hours(1500.0)[0]
    h2 = S.rating_lives(S.solve(s, seats, c2)).hours(3000.0)[0]
    expected = 1.0 / (0.3 / h1 + 0.7 / h2)
    np.testing.assert_allclose(d.seat_hours, expected, rtol=1e-9)
    assert d.system_hours == pytest.approx(
        np.sum(expected ** (-10 / 9)) ** (-0.9), rel=1e-9)


# --------------------------------------------------------------------------- case files / CLI
def _cli():
    from typer.testing import CliRunner

    from ballrace.cli import app
    return CliRunner(), app


EXAMPLES = __import__("pathlib").Path(__file__).resolve().parents[1] / "examples"


def _gearbox_clearance(brg, mat):
    """Seat A of examples/shaft_gearbox.toml: 10 um fit on a solid shaft of ``mat``, inner
    ring at 60 degC, outer at 50 degC (clearance module)."""
    from ballrace.analytic.clearance import operating_clearance
    return operating_clearance(brg, bore=0.04, outside_diameter=0.08,
                               shaft_interference=10e-6, inner_temperature=333.15,
                               outer_temperature=323.15, shaft_material=mat)


def test_gearbox_example_against_direct_solve_and_statics(tmp_path):
    """``ballrace shaft examples/shaft_gearbox.toml --json``: the reactions are those of a
    direct solve with the same inputs (1e-9), the gear's axial force F_t tan(15 deg) =
    1339.7 N goes to the locating seat alone (the other floats), and the lateral
    reactions plus the loads and the weight balance (1e-8)."""
    import json
    runner, app = _cli()
    res = runner.invoke(app, ["shaft", str(EXAMPLES / "shaft_gearbox.toml"), "--json",
                              "--plot", str(tmp_path / "s.png")])
    assert res.exit_code == 0, res.output
    r = json.loads(res.output)
    assert (tmp_path / "s.png").stat().st_size > 1000
    brg = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
    mat = ballrace.Material(E=210e9, nu=0.3, density=7850.0)
    s = S.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)], mat)
    seats = [S.Seat(0.015, brg, clearance=_gearbox_clearance(brg, mat)),
             S.Seat(0.245, brg, floating=True)]
    gear = S.gear_mesh(0.09, 5000.0, 0.12, pressure_angle=np.radians(20),
                       helix_angle=np.radians(15), mesh_azimuth=np.radians(90))
    d = S.solve(s, seats, [gear], gravity=(0, -S.STANDARD_GRAVITY, 0))
    got = np.array([x["reaction"] for x in r["seats"]])
    np.testing.assert_allclose(got, d.reactions, rtol=1e-9, atol=1e-9 * 5000)
    assert got[0, 0] == pytest.approx(5000 * np.tan(np.radians(15)), rel=1e-9)
    assert abs(got[1, 0]) < 1e-8 * 5000
    assert np.abs(r["shaft"]["equilibrium_residual"]).max() < 1e-8 * 5000
    assert r["life"]["system"] < min(x["L10r"] for x in r["seats"])
    assert r["seats"][0]["clearance"] == pytest.approx(seats[0].clearance, rel=1e-12)
    assert r["seats"][0]["clearance"] < 15e-6              # fit and warm inner ring


def test_spindle_example_runs_and_keeps_the_preload():
    """The spindle example (DB pair front, floating rear): the rear seat carries no axial
    load, the pair carries the whole cutting thrust (-800 N), and the table prints."""
    import json
    runner, app = _cli()
    res = runner.invoke(app, ["shaft", str(EXAMPLES / "shaft_spindle.toml"), "--json"])
    assert res.exit_code == 0, res.output
    r = json.loads(res.output)
    assert r["seats"][0]["reaction"][0] == pytest.approx(-800.0, rel=1e-9)
    assert abs(r["seats"][1]["reaction"][0]) < 1e-8 * 800
    assert r["seats"][0]["L10_iso281"] is None and r["seats"][1]["L10_iso281"] > 0
    assert any(n.startswith("front pair: no ISO 281 catalogue life") for n in r["notes"])
    assert not any(n.startswith("rear:") for n in r["notes"])
    res = runner.invoke(app, ["shaft", str(EXAMPLES / "shaft_spindle.toml")])
    assert res.exit_code == 0, res.output
    assert "front pair" in res.output


_BASE = '''
kind = "shaft"
[shaft]
sections = [["200 mm", "40 mm", "0 mm"]]
[bearings.b]
ball_diameter = "7.938 mm"
n_balls = 9
pitch_diameter = "38.5 mm"
f_inner = 0.52
f_outer = 0.53
diametral_clearance = "10 um"
[[seat]]
position = "{x1}"
bearing = "b"
[[seat]]
position = "{x2}"
bearing = "b"
floating = true
[[load]]
position = "{xl}"
Fy = "1 kN"
{extra}
'''


@pytest.mark.parametrize("kw, match", [
    (dict(x1="250 mm"), r"\[\[seat\]\] #1\.position: must be within the shaft"),
    (dict(x2="20 mm"), r"\[\[seat\]\] #2\.position: on top of \[\[seat\]\] #1 "),
    (dict(xl="-5 mm"), r"\[\[load\]\] #1\.position: must be within the shaft"),
    (dict(extra="colour = 1"), r"colour"),
    (dict(extra="[operation]\nspede = \"1 rpm\""), r"\[operation\]\.spede"),
    (dict(extra="[[gear]]\nposition = \"100 mm\"\ntangential_force = \"1 kN\"\n"
                "pitch_diameter = \"10 kg\""), r"\[\[gear\]\] #1\.pitch_diameter"),
    (dict(extra="[seat.fits]\nbore = \"30 mm\"\noutside_diameter = \"40 mm\""),
     r"\[\[seat\]\] #2\.fits: outside_diameter must exceed"),
])
def test_case_file_errors_are_one_line_naming_the_key(tmp_path, kw, match):
    runner, app = _cli()
    args = dict(x1="20 mm", x2="180 mm", xl="100 mm", extra="")
    args.update(kw)
    p = tmp_path / "c.toml"
    p.write_text(_BASE.format(**args))
    res = runner.invoke(app, ["shaft", str(p)])
    assert res.exit_code == 2, res.output
    assert len(res.output.strip().splitlines()) == 1, res.output
    assert __import__("re").search(match, res.output), res.output


@pytest.mark.parametrize("kind, key, match", [
    ("deep-groove", 'nominal_contact_angle = "5 deg"', "deep-groove bearing is rated at 0 deg"),
    ("angular-contact", 'nominal_contact_angle = "95 deg"', r"\[0, 90\) deg"),
    ("angular-contact", 'nominal_contact_angle = "15 mm"', "nominal_contact_angle"),
])
def test_case_file_nominal_angle_errors(tmp_path, kind, key, match):
    """A shaft case file's bearing takes the rating-angle key of the bearing case file,
    with the same checks, and the message names the bearing's table."""
    runner, app = _cli()
    text = _BASE.format(x1="20 mm", x2="180 mm", xl="100 mm", extra="").replace(
        'diametral_clearance = "10 um"',
        f'type = "{kind}"\ndiametral_clearance = "10 um"\n{key}')
    p = tmp_path / "c.toml"
    p.write_text(text)
    res = runner.invoke(app, ["shaft", str(p)])
    assert res.exit_code == 2, res.output
    assert len(res.output.strip().splitlines()) == 1, res.output
    assert "[bearings.b]" in res.output
    assert __import__("re").search(match, res.output), res.output


def test_case_file_nominal_angle_key():
    """The rating angle of a shaft case file's bearing: the free (design) angle for an
    angular-contact bearing unless nominal_contact_angle is given, 0 for deep-groove;
    the bearing's ISO 281 rating follows it."""
    import tomllib

    from ballrace.analytic import ratings
    from ballrace.commands.shaft import parse_shaft_case

    def front(text):
        b = parse_shaft_case(tomllib.loads(text)).seats[0].bearing
        return getattr(b, "bearing", b)              # a pair's single bearing

    text = (EXAMPLES / "shaft_spindle.toml").read_text()
    assert front(text).nominal_contact_angle == pytest.approx(np.radians(25), rel=1e-14)
    b15 = front(text.replace('free_contact_angle = "25 deg"',
                             'free_contact_angle = "25 deg"\nnominal_contact_angle = "15 deg"', 1))
    assert b15.nominal_contact_angle == pytest.approx(np.radians(15), rel=1e-14)
    assert b15.free_contact_angle == pytest.approx(np.radians(25), rel=1e-14)
    assert ratings.dynamic_rating(b15) == pytest.approx(
        ratings.dynamic_rating(b15.ball_diameter, b15.n_balls, b15.pitch_diameter,
                               np.radians(15)), rel=1e-14)
    dg = parse_shaft_case(tomllib.loads(_BASE.format(x1="20 mm", x2="180 mm", xl="100 mm",
                                                     extra=""))).seats[0].bearing
    assert dg.nominal_contact_angle == 0.0 and dg.free_contact_angle > 0.0


def test_bearing_case_file_is_not_a_shaft_case():
    runner, app = _cli()
    res = runner.invoke(app, ["shaft", str(EXAMPLES / "bearing_209.toml")])
    assert res.exit_code == 2
    assert "ballrace bearing" in res.output


def test_system_stiffness_at_seat_and_mid_span():
    """At the only seat of a short shaft the system stiffness is the seat's tangent
    stiffness (the free shaft adds nothing in series; 1e-8).  Under the load of a
    two-seat shaft the lateral compliance is the beam's a^2 b^2/(3EIl) + a b/(kappa G A l)
    plus the seats' radial compliances 1/k weighted by (b/l)^2 and (a/l)^2 (unit load
    shared by statics): 1 % (the seats' tilt stiffness and the radial-tilt coupling
    are left out of this estimate)."""
    s = S.Shaft([(0.02, 80e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.01, AC)], [S.PointLoad(0.01, Fa=3000.0, Fy=2000.0)])
    K = r.stiffness(0.01)
    np.testing.assert_allclose(K, r.seat_stiffness[0], rtol=1e-8,
                               atol=1e-8 * np.abs(r.seat_stiffness[0]).max())
    s = S.Shaft([(0.26, 45e-3, 0.0)], STEEL)
    P, xa, xb, c = 5000.0, 0.03, 0.23, 0.09
    r = S.solve(s, [S.Seat(xa, DG0), S.Seat(xb, DG0)], [S.PointLoad(c, Fy=P)])
    a, b, l = c - xa, xb - c, xb - xa
    E, G, A, I, k = _props(45e-3)
    kA, kB = r.seat_stiffness[0, 1, 1], r.seat_stiffness[1, 1, 1]
    cexp = a**2 * b**2 / (3 * E * I * l) + a * b / (k * G * A * l) + (b / l)**2 / kA \
        + (a / l)**2 / kB
    C = np.linalg.inv(r.stiffness(c))
    assert C[1, 1] == pytest.approx(cexp, rel=0.01)


def test_bearing_coefficients_rotordynamics_axes():
    """ROSS axes (x, y, z) = ballrace (y, z, x): k_xx = K_vv, k_yy = K_ww, k_zz = K_uu of
    the seat's tangent stiffness (exact); with the tilt free the lateral stiffness is the
    Schur complement, never stiffer (positive semi-definite difference)."""
    s = S.Shaft([(0.26, 45e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.03, AC, 1, offset=10e-6), S.Seat(0.23, AC, -1, offset=10e-6)],
                [S.PointLoad(0.13, Fy=4000.0, Fz=1000.0)])
    c = S.bearing_coefficients(r)
    K = r.seat_stiffness[0]
    assert (c[0]["kxx"], c[0]["kyy"], c[0]["kxy"], c[0]["kzz"]) == (K[1, 1], K[2, 2], K[1, 2],
                                                                   K[0, 0])
    f = S.bearing_coefficients(r, tilt="free")
    d = np.array([[c[0]["kxx"] - f[0]["kxx"], c[0]["kxy"] - f[0]["kxy"]],
                  [c[0]["kyx"] - f[0]["kyx"], c[0]["kyy"] - f[0]["kyy"]]])
    assert np.linalg.eigvalsh(0.5 * (d + d.T)).min() > -1e-9 * K[1, 1]
    with pytest.raises(ValueError, match="tilt"):
        S.bearing_coefficients(r, tilt="x")


def test_rigid_body_modes_are_named():
    """A single seat whose housing has no tilt stiffness leaves the shaft free to rotate;
    a seat with zero axial housing stiffness does not locate; both are ValueErrors."""
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL)
    with pytest.raises(ValueError, match="rotation about"):
        S.solve(s, [S.Seat(0.1, DG, housing_stiffness=[1e8, 1e8, 1e8, 0.0, 0.0])],
                [S.PointLoad(0.1, Fy=100.0)])
    with pytest.raises(ValueError, match="no axial support"):
        S.solve(s, [S.Seat(0.02, DG, housing_stiffness=[0.0, 1e8, 1e8, 1e5, 1e5]),
                    S.Seat(0.18, DG, floating=True)], [S.PointLoad(0.1, Fy=100.0)])
    # two seats with radial springs only: supported (tilt from the pair of seats)
    r = S.solve(s, [S.Seat(0.02, DG, housing_stiffness=[1e9, 1e8, 1e8, 0, 0]),
                    S.Seat(0.18, DG, housing_stiffness=[0, 1e8, 1e8, 0, 0], floating=True)],
                [S.PointLoad(0.1, Fy=100.0)])
    assert r.reactions[:, 1].sum() == pytest.approx(100.0, rel=1e-9)


def test_catalog_life_from_reaction():
    """ISO 281 catalogue life of a seat: (C/P)^3 with P = X F_r + Y F_a of the seat's
    reaction (life.equivalent_load_for, at alpha = 0 for a deep-groove bearing) and the
    same C as the reference life (1e-12); a duplex seat has none."""
    from ballrace.analytic.life import equivalent_load_for
    s = S.Shaft([(0.26, 45e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.03, DG0), S.Seat(0.23, DG0, floating=True)],
                [S.PointLoad(0.09, Fy=4000.0, Fa=800.0)])
    lf = S.rating_lives(r, nominal_contact_angle=0.0)
    R = r.reactions[0]
    P = equivalent_load_for(DG0, np.hypot(R[1], R[2]), abs(R[0]), contact_angle=0.0).P
    assert lf.catalog_lives[0] == pytest.approx((lf.ratings[0][0].C / P) ** 3, rel=1e-12)
    pair = dx.DuplexPair(AC, "DB", preload=1000.0)
    r = S.solve(S.Shaft([(0.02, 80e-3, 0.0)], STEEL), [S.Seat(0.01, pair)],
                [S.PointLoad(0.01, Fy=500.0)])
    assert S.rating_lives(r).catalog_lives == (None,)


@pytest.mark.parametrize("arr, Fa", [("DF", 2500.0), ("DT", 3000.0), ("DT", -500.0)])
def test_df_dt_seats_match_duplex_pair(arr, Fa):
    """DF (rows at one place: the DB numbers) and DT (both rows loaded alike, a constant
    spring preload P on the pair: F_a = 2 F(delta) - P) seats carry the row loads of
    ``DuplexPair.solve`` (1e-7 of the preload)."""
    pair = dx.DuplexPair(AC, arr, preload=1500.0)
    s = S.Shaft([(0.02, 80e-3, 0.0)], STEEL)
    r = S.solve(s, [S.Seat(0.01, pair)], [S.PointLoad(0.01, Fa=Fa)])
    got = np.maximum([float(b.loads[0]) for b in r.bearings[0]], 0)
    np.testing.assert_allclose(got, pair.solve(Fa=Fa).axial_loads, rtol=1e-7, atol=1e-7 * 1500)
    assert r.reactions[0, 0] == pytest.approx(Fa, rel=1e-9)


def test_case_file_duty_cycle():
    """The gearbox example's [[duty]] cases (point loads x 1.4, 1.0, 0.5 at 1000, 1500,
    2000 rpm for 20/50/30 % of the time) give the lives of shaft.duty_cycle on the same
    scaled loads (1e-9)."""
    import json
    runner, app = _cli()
    res = runner.invoke(app, ["shaft", str(EXAMPLES / "shaft_gearbox.toml"), "--json"])
    r = json.loads(res.output)
    brg = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
    mat = ballrace.Material(E=210e9, nu=0.3, density=7850.0)
    s = S.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)], mat)
    seats = [S.Seat(0.015, brg, clearance=_gearbox_clearance(brg, mat)),
             S.Seat(0.245, brg, floating=True)]

    def gear(f):
        return [S.gear_mesh(0.09, 5000.0 * f, 0.12, helix_angle=np.radians(15),
                            mesh_azimuth=np.radians(90))]
    d = S.duty_cycle(s, seats, [(gear(1.4), 0.2, 1000.0), (gear(1.0), 0.5, 1500.0),
                                (gear(0.5), 0.3, 2000.0)],
                     nominal_contact_angle=0.0, gravity=(0, -S.STANDARD_GRAVITY, 0))
    np.testing.assert_allclose(r["duty"]["seat_hours"], d.seat_hours, rtol=1e-9)
    assert r["duty"]["system_hours"] == pytest.approx(d.system_hours, rel=1e-9)


def test_convergence_error_reports_residual_and_iterations():
    """A solve cut short (max_iter=1) raises ConvergenceError naming the residual and the
    iteration count, instead of returning an unbalanced result."""
    s = S.Shaft([(0.26, 45e-3, 0.0)], STEEL)
    with pytest.raises(ld.ConvergenceError,
                       match=r"after \d+ Newton iterations.*: relative residual "):
        S.solve(s, [S.Seat(0.03, DG), S.Seat(0.23, DG)], [S.PointLoad(0.09, Fy=5000.0)],
                max_iter=1)


def test_shaft_free_in_its_end_play():
    """Past lift-off (shaft warmer by more than 2 offset/(alpha L)) an O pair has a gap:
    with no other load the equilibrium has no force at all, and the solver finds it (it
    must not stall on a flat residual or lose its scale)."""
    s = S.Shaft([(0.2, 40e-3, 0.0)], STEEL, thermal_expansion=11.5e-6)
    seats = [S.Seat(0.02, AC, 1, offset=8e-6), S.Seat(0.18, AC, -1, offset=8e-6)]
    for dT in (9.0, 16.0):
        r = S.solve(s, seats, [], shaft_temperature_change=dT)
        assert np.abs(r.reactions).max() < 1e-6
        # no force: the seats move apart by the free thermal growth alpha dT L
        grow = r.ring_displacements[1, 0] - r.ring_displacements[0, 0]
        assert grow == pytest.approx(11.5e-6 * dT * 0.16, rel=1e-6)


def test_ring_forces_are_loaddist_at_imposed_displacements():
    """The shaft's bearing kernel gives loaddist.solve's loads and tangent stiffness with
    every DOF imposed (1e-12), for a deep-groove bearing with clearance and an
    angular-contact bearing under a general displacement."""
    for brg, u in ((DG, [3e-6, 2e-5, -7e-6, 1e-4, -2e-4]),
                   (AC, [2e-5, 1e-5, 4e-6, -1e-4, 3e-4])):
        F, K, _, _ = S._ring_forces(brg, None, np.array([u]))
        ref = ld.solve(brg, displacements=u)
        np.testing.assert_allclose(F[0], ref.loads, rtol=1e-12, atol=1e-12 * np.abs(F).max())
        np.testing.assert_allclose(K[0], ref.stiffness, rtol=1e-12,
                                   atol=1e-12 * np.abs(K).max())


def test_bearing_coefficients_seat_to_ground_in_series():
    """A seat's stiffness to the ground is the bearing and its housing as springs in
    series, K = (K_b^-1 + K_h^-1)^-1 (both invertible here: a DB pair with row spacing
    and preload is stiff in all five DOFs) — the textbook series formula, independent of
    the condensation the code uses; 1e-9.  A floating seat in a rigid housing has no axial
    stiffness to the ground (its outer ring slides), and a rigid locating seat exports the
    bearing's own tangent stiffness unchanged."""
    pair = dx.DuplexPair(AC, "DB", preload=1000.0)
    Kh = np.array([2e8, 3e8, 4e8, 2e6, 3e6])
    s = S.Shaft([(0.3, 60e-3, 0.0)], STEEL)
    seats = [S.Seat(0.03, pair, housing_stiffness=Kh, row_spacing=0.02),
             S.Seat(0.27, DG0, floating=True), S.Seat(0.15, DG0)]
    r = S.solve(s, seats, [S.PointLoad(0.1, Fy=3000.0, Fz=-1000.0, Fa=500.0)])
    c = S.bearing_coefficients(r)
    Kb = r.seat_stiffness[0]
    series = np.linalg.inv(np.linalg.inv(Kb) + np.diag(1 / Kh))
    np.testing.assert_allclose(c[0]["stiffness"], series, rtol=0, atol=1e-9 * np.abs(series).max())
    assert c[0]["kxx"] == pytest.approx(series[1, 1], rel=1e-9)
    assert c[0]["kzz"] == pytest.approx(series[0, 0], rel=1e-9)
    assert abs(c[1]["kzz"]) < 1e-9 * c[1]["kxx"]
    assert c[1]["kxx"] > 0
    np.testing.assert_array_equal(c[2]["stiffness"], r.seat_stiffness[2])


def test_ross_bearings_in_a_ross_rotor():
    """ross_bearings gives one ROSS BearingElement per seat whose 3x3 stiffness at any
    frequency is [[kxx, kxy, 0], [kyx, kyy, 0], [0, 0, kzz]] of bearing_coefficients at the
    operating point (exact), at the seat's node; a ROSS rotor of ShaftElements on
    result.nodes with them assembles and its modal analysis runs (finite, positive
    frequencies)."""
    ross = pytest.importorskip("ross")
    if not hasattr(ross, "BearingElement"):
        pytest.skip("the module named ross is not ROSS")
    s = S.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)], STEEL)
    seats = [S.Seat(0.015, DG0, name="A"), S.Seat(0.245, DG0, floating=True, name="B")]
    r = S.solve(s, seats, [S.gear_mesh(0.09, 5000.0, 0.12, helix_angle=np.radians(15))])
    for tilt in ("held", "free"):
        c = S.bearing_coefficients(r, tilt=tilt)
        els = S.ross_bearings(r, tilt=tilt, damping=50.0)
        assert [e.n for e in els] == [int(np.argmin(abs(r.nodes - x))) for x in (0.015, 0.245)]
        assert [e.tag for e in els] == ["A", "B"]
        for e, ck in zip(els, c):
            np.testing.assert_array_equal(
                e.K(0.0), [[ck["kxx"], ck["kxy"], 0], [ck["kyx"], ck["kyy"], 0],
                           [0, 0, ck["kzz"]]])
            np.testing.assert_array_equal(np.diag(e.C(0.0)), [50.0, 50.0, 50.0])
    # ROSS axes (x, y, z) = ballrace (y, z, x), rigid housing: the tangent stiffness itself
    K0 = r.seat_stiffness[0]
    held = S.ross_bearings(r)
    assert (held[0].K(0.0)[0, 0], held[0].K(0.0)[1, 1], held[0].K(0.0)[0, 1],
            held[0].K(0.0)[2, 2]) == (K0[1, 1], K0[2, 2], K0[1, 2], K0[0, 0])
    assert held[1].K(0.0)[2, 2] == pytest.approx(0.0, abs=1e-9 * K0[1, 1])  # floating
    mat = ross.Material(name="test_steel", rho=STEEL.density, E=STEEL.E, Poisson=STEEL.nu)
    els = [ross.ShaftElement(L=float(b - a), idl=float(s.diameters(0.5 * (a + b))[1]),
                             odl=float(s.diameters(0.5 * (a + b))[0]), material=mat, n=i)
           for i, (a, b) in enumerate(zip(r.nodes[:-1], r.nodes[1:]))]
    rotor = ross.Rotor(els, bearing_elements=held)
    wn = np.asarray(rotor.run_modal(speed=0.0, num_modes=8).wn)
    assert np.all(np.isfinite(wn)) and np.all(wn > 0)
    with pytest.raises(ValueError, match="nodes"):
        S.ross_bearings(r, [3])
    # ROSS finds elements by tag: two seats of one name get distinct tags
    twin = S.solve(s, [S.Seat(0.015, DG0, name="A"), S.Seat(0.245, DG0, floating=True,
                                                            name="A")],
                   [S.PointLoad(0.09, Fy=2000.0)])
    assert [e.tag for e in S.ross_bearings(twin)] == ["A_0", "A_1"]
