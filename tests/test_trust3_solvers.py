"""Solver robustness: tandem pairs with little net thrust, the preload inversion at
subnormal preloads, the high-speed equilibrium near the speed where balls change race
control and under very light loads, a shaft on deep-groove seats with clearance under a
lateral load of a few mN, and the per-test time limit.

Equilibrium is checked from the returned ball loads and contact angles (not the solvers'
own residuals); the single-row reference of a tandem pair is
:func:`ballrace.analytic.loaddist.solve` with the tilts imposed zero (rings parallel).
"""
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import duplex as dx
from ballrace.analytic import highspeed as hs
from ballrace.analytic import loaddist as ld
from ballrace.analytic import shaft
from ballrace.analytic.loaddist import ConvergenceError
from hsref import rederive_highspeed

#: 55 mm bore, 40 deg angular-contact bearing of 7311 proportions (tests/test_duplex.py).
B7311 = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52,
                             free_contact_angle=np.radians(40))
#: A 90 mm bore angular-contact bearing of 7018 proportions (bore 90, OD 140 mm): 20 balls
#: of 5/8 in on a 115 mm pitch circle, f = 0.52 (an assumed internal geometry).
B7018 = ballrace.BallBearing(15.875e-3, 20, 115e-3, 0.52, 0.52,
                             free_contact_angle=np.radians(25))
RPM2100 = 2100 * np.pi / 30


# --------------------------------------------------------------------------- DT pairs
def _pair_balance(pair, r):
    """(axial, radial) imbalance [N] of a pair result, from its ball loads and angles."""
    psi = pair.bearing.azimuths(0.0)
    fa = (r.ball_loads * np.sin(r.contact_angles)).sum(1)
    fr = (r.ball_loads * np.cos(r.contact_angles) * np.cos(psi)).sum(1)
    if pair.arrangement == "DT":
        axial = fa.sum() - pair.preload - r.Fa
    else:
        axial = fa[0] - fa[1] - r.Fa
    return axial, fr.sum() - r.Fr


@pytest.mark.parametrize("P", [1.0, 100.0, 1000.0])
@pytest.mark.parametrize("frac", [0.0, 1e-6, 0.01, 0.05, 0.1, 0.2])
def test_tandem_pair_with_little_net_thrust_solves(P, frac):
    """Net thrust F_a + P in [0, 0.2 P] with F_r = P (ConvergenceError before at P = 1 and
    100 N): balanced to 1e-9 of the load scale, and each row is the single-row solution
    with the rings kept parallel at ((F_a + P)/2, F_r/2) (ball loads to 1e-6)."""
    pair = dx.DuplexPair(B7311, "DT", preload=P)
    Fa, Fr = -P + frac * P, P
    r = pair.solve(Fa=Fa, Fr=Fr)
    scale = max(abs(Fa), Fr, P, 1.0)
    assert max(map(abs, _pair_balance(pair, r))) <= 1e-9 * scale
    row = ld.solve(B7311, Fa=0.5 * (Fa + P), Fy=0.5 * Fr,
                   displacements=[np.nan, np.nan, np.nan, 0.0, 0.0])
    for q in r.ball_loads:
        assert np.allclose(q, row.ball_loads, rtol=1e-6, atol=1e-6 * row.ball_loads.max())


def test_tandem_pair_at_zero_net_thrust_sits_at_the_groove_bottom():
    """F_a = -P: no net thrust, so the balls' thrust components vanish: the axial
    deflection is -A sin(beta_f) (ball centres at the groove bottom, beta = 0)."""
    pair = dx.DuplexPair(B7311, "DT", preload=100.0)
    r = pair.solve(Fa=-100.0, Fr=100.0)
    A = B7311.curvature_center_distance
    assert r.axial_deflections == pytest.approx(-A * np.sin(B7311.free_contact_angle),
                                                abs=1e-12)
    loaded = r.ball_loads > 0
    assert np.all(np.abs(r.contact_angles[loaded]) < 1e-8)


@settings(max_examples=25, deadline=None)
@given(P=st.floats(0.1, 2e4), frac=st.floats(0.0, 0.2), fr=st.floats(0.5, 2.0),
       geometry=st.sampled_from([B7311, B7018,
                                 ballrace.BallBearing(6e-3, 12, 30e-3, 0.515, 0.53,
                                                      free_contact_angle=np.radians(15))]))
def test_tandem_pair_sweep(P, frac, fr, geometry):
    """Hypothesis sweep of the tandem pair: net thrust 0-0.2 P, radial load 0.5-2 P."""
    pair = dx.DuplexPair(geometry, "DT", preload=P)
    Fa, Fr = -P + frac * P, fr * P
    r = pair.solve(Fa=Fa, Fr=Fr)
    scale = max(abs(Fa), Fr, P, 1.0)
    assert max(map(abs, _pair_balance(pair, r))) <= 1e-9 * scale
    assert np.all(r.ball_loads >= 0)


# --------------------------------------------------------------------------- preload
@pytest.mark.timeout(30)
@pytest.mark.parametrize("P", [5e-324, 1e-300, 1e-31])
def test_subnormal_preload_is_refused_at_once(P):
    """A preload below 1e-30 N (MIN_MAGNITUDE) is a ValueError naming it (before: a
    doubling loop on an upper bound that had underflowed to 0, forever)."""
    t = time.perf_counter()
    with pytest.raises(ValueError, match=r"preload must have a physical magnitude, 0 or in "
                                         r"\[1e-30, 1e\+30\] \[N\]"):
        dx.DuplexPair(B7311, "DB", preload=P)
    assert time.perf_counter() - t < 1.0


@pytest.mark.timeout(60)
@pytest.mark.parametrize("F", [5e-324, 1e-310, 1e-300, 1e-30])
def test_preload_inversion_is_bounded_for_tiny_loads(F):
    """The inversion F_a(delta) = F ends for any F > 0 (its power-law guess underflows
    below ~1e-300 N): the deflection is finite, non-negative and below the round-off
    level eps A where the load is below the model's resolution."""
    t = time.perf_counter()
    d = dx.axial_deflection(B7311, F)
    assert np.isfinite(d) and 0.0 <= d <= 1e3 * np.finfo(float).eps * \
        B7311.curvature_center_distance
    assert time.perf_counter() - t < 5.0
    # and the smallest accepted preload gives a pair that solves
    r = dx.DuplexPair(B7311, "DB", preload=1e-30).solve(Fa=0.0, Fr=1.0)
    assert max(map(abs, _pair_balance(r.pair, r))) <= 1e-9


# --------------------------------------------------------------------------- high speed
def _check_hs(brg, r):
    assert r.relative_residual <= 1e-9
    bad = rederive_highspeed(brg, r)
    assert not bad, bad


#: A 90 mm-bore class bearing (15 deg, f_i 0.515, f_o 0.53) whose balls change race
#: control by Jones's criterion near 2100 rpm under 80 N thrust and 160 N radial load.
B15 = ballrace.BallBearing(14.288e-3, 22, 115e-3, 0.515, 0.53, free_contact_angle=np.radians(15))


@pytest.mark.parametrize("f", [0.98, 0.99, 1.0, 1.02, 1.03])
def test_jones_control_near_the_switch_speed(f):
    """control='jones' failed at 0.99 and 1.02 x 2100 rpm: the round with three balls
    changed to inner control started again from the static start.  Now it solves, the
    choice is Jones's at the result, and the result re-derives independently."""
    r = hs.solve(B15, Fa=80.0, Fr=160.0, speed_inner=f * RPM2100, control="jones")
    _check_hs(B15, r)
    model = hs._Model.of(B15)
    sysm = hs._System(model, r.azimuths, np.array([80.0, 160.0, 0, 0, 0]),
                      hs._free_dofs(np.array([80.0, 160.0, 0, 0, 0]), "fixed"),
                      r.speed_inner, 0.0, "harris", False, 1.0, 1.0)
    x = np.concatenate([r.ball_positions[:, 0], r.ball_positions[:, 1],
                        r.displacements[[0, 1]]])
    jones = hs._jones_outer(B15, sysm.balls(x))
    assert np.array_equal(jones, np.asarray(r.control) == "outer")


#: 40 deg, 12 balls, light thrust (3 N against ~14 N of F_c per ball at 2100 rpm): the inner
#: contact angle swings from 52 to ~90 deg between 10 and 50 % of the speed.
BSTEEP = ballrace.BallBearing(0.018714198364704508, 12, 0.11233496109503273,
                              0.5110059789722445, 0.5358975478585484,
                              free_contact_angle=np.radians(40))
FA_STEEP = 2.9659418050616257


def test_steep_branch_solves_in_the_band():
    """Default options failed at 0.97-0.99 and 1.01, 1.03, 1.04 x 2100 rpm and solved at
    1.0 and 1.02: the continuation gave up at the sharp bend near 16 % of the speed.  Now
    every speed solves, the inner contact angle rises monotonically with speed, and each
    result is the equilibrium Newton finds from its neighbour's (one branch)."""
    fs = [0.97, 0.98, 0.99, 1.0, 1.01, 1.03, 1.04]
    rs = [hs.solve(BSTEEP, Fa=FA_STEEP, speed_inner=f * RPM2100) for f in fs]
    for r in rs:
        _check_hs(BSTEEP, r)
    ai = np.array([r.inner_contact_angles[0] for r in rs])
    assert np.all(np.diff(ai) > 0) and np.all(ai < np.pi / 2)
    # the neighbour check: Newton at 0.98 from the 0.97 solution lands on the 0.98 result
    model = hs._Model.of(BSTEEP)
    L = np.array([FA_STEEP, 0, 0, 0, 0])
    free = hs._free_dofs(L, "fixed")
    w = 0.98 * RPM2100
    wc = 0.5 * w * (1 - model.D / model.dm)
    F_ref = max(FA_STEEP, model.Z * model.mass * (model.Roc + model.ro) * wc**2)
    sysm = hs._System(model, rs[0].azimuths, L, free, w, 0.0, "harris", False, F_ref,
                      F_ref / model.Z)
    x0 = np.concatenate([rs[0].ball_positions[:, 0], rs[0].ball_positions[:, 1],
                         rs[0].displacements[free]])
    _, b, err, _ = hs._damped_newton(sysm, x0, 1e-10, 60)
    assert err <= 1e-10
    assert np.degrees(abs(b.ai[0] - rs[1].inner_contact_angles[0])) < 1e-7


@pytest.mark.parametrize("control, Fa, f", [("outer", 0.001, 1.0), ("jones", 0.001, 1.0),
                                            ("outer", 0.03, 1.0), ("jones", 0.03, 0.97),
                                            ("jones", 0.03, 1.03)])
def test_very_light_thrust_on_a_90mm_bearing(control, Fa, f):
    """A thrust of 1-30 mN against ~8 N of F_c per ball: failed at full speed (Newton and
    the first step of the continuation), now solves around 2100 rpm; the outer contact
    angle is near zero (F_c presses the balls to the outer groove bottom), the inner ring
    carries the thrust."""
    r = hs.solve(B7018, Fa=Fa, speed_inner=f * RPM2100, control=control)
    _check_hs(B7018, r)
    assert np.all(np.abs(r.outer_contact_angles) < np.radians(1.0))
    thrust = (r.inner_loads * np.sin(r.inner_contact_angles)).sum()
    assert thrust == pytest.approx(Fa, rel=1e-4)


def test_end_of_branch_at_the_groove_edge_is_reported():
    """Where the branch followed from the static solution ends (inner contact angles
    reaching the 90 deg groove edge at ~76 % of the speed), the error says so."""
    brg = ballrace.BallBearing(0.017922545316813195, 16, 0.1106531495115017,
                               0.5053858119237626, 0.5387505008698588,
                               free_contact_angle=np.radians(30))
    with pytest.raises(ConvergenceError, match=r"ends at 7\d\.\d+ % of the speed.*groove edge"):
        hs.solve(brg, Fa=103.58101016993336, speed_inner=RPM2100)


def test_load_lost_in_the_tolerance_is_reported():
    """A thrust of 1e-30 N against the centrifugal load scale is below what the tolerance
    resolves: the error says so instead of claiming a turning point."""
    brg = ballrace.BallBearing(12.7e-3, 12, 60e-3, 0.52, 0.52, free_contact_angle=np.radians(25))
    with pytest.raises(ConvergenceError, match="below 1e3 rtol of the load scale"):
        hs.solve(brg, Fa=1e-30, speed_inner=1000.0)


def test_solver_follows_the_equilibrium_connected_to_the_static_solution():
    """Two equilibria exist under this thrust with a 1 N radial load: the nearly
    axisymmetric one, and one with the ring shifted 11 um against the radial load and two
    balls past the inner groove edge (reached from another start, flagged).  solve()
    returns the first, which is the one followed in speed from the static solution (a
    hand continuation in 1/16 steps agrees to 1e-9 rad)."""
    brg = ballrace.BallBearing(0.01281897577966027, 9, 0.06959917461491105,
                               0.5061666689254735, 0.5366609817946951,
                               free_contact_angle=np.radians(40))
    Fa, Fr, w = 3481.9347109378414, 1.0, 111.38356379651813
    r = hs.solve(brg, Fa=Fa, Fr=Fr, speed_inner=w)
    other = hs.solve(brg, Fa=Fa, Fr=Fr, speed_inner=w, start="estimate")
    _check_hs(brg, r)
    assert not r.warnings and not np.any(r.beyond_groove_inner)
    assert np.any(other.beyond_groove_inner)                        # another equilibrium
    assert abs(other.displacements[1] - r.displacements[1]) > 1e-5
    model = hs._Model.of(brg)
    L = np.array([Fa, Fr, 0, 0, 0])
    free = hs._free_dofs(L, "fixed")
    u0 = ld.solve(brg, Fa=Fa, Fy=Fr, displacements=[np.nan, np.nan, np.nan, 0.0, 0.0])
    x = hs._start(model, r.azimuths, np.asarray(u0.displacements, float), 0.0, 0.0, free,
                  True)
    for s in np.arange(1, 17) / 16:
        wc = 0.5 * s * w * (1 - model.D / model.dm)
        F_ref = max(Fa, model.Z * model.mass * (model.Roc + model.ro) * wc**2)
        sysm = hs._System(model, r.azimuths, L, free, s * w, 0.0, "harris", False, F_ref,
                          F_ref / model.Z)
        x, b, err, _ = hs._damped_newton(sysm, x, 1e-10, 60)
        assert err <= 1e-10
    assert np.abs(b.ai - r.inner_contact_angles).max() < 1e-9


# --------------------------------------------------------------------------- shaft
BRG6 = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
SHAFT = shaft.Shaft(sections=[(0.26, 45e-3, 0.0)], material=ballrace.BEARING_STEEL)
SEATS = [shaft.Seat(0.03, BRG6), shaft.Seat(0.23, BRG6, floating=True)]


@pytest.mark.parametrize("F", [1e-2, 1e-3, 1e-4, 1e-6])
def test_shaft_with_clearance_under_a_tiny_lateral_load(F):
    """The README shaft on two deep-groove seats with 15 um clearance: a lateral load of
    1e-3 N or less failed (ConvergenceError); down to 1e-6 N (what the single bearing
    solves) it now solves.  Statics: reactions 140/200 and 60/200 of the load (load at
    0.09 m between seats at 0.03 and 0.23 m); the balls sit at the groove bottom (ring
    axial displacement -A sin(beta_f)) with the radial clearance taken up (P_d/2) and one
    ball per seat loaded."""
    r = shaft.solve(SHAFT, SEATS, [shaft.PointLoad(0.09, Fy=F)])
    assert r.residual <= 1e-8          # rtol 1e-10; the plain iteration stops at <= 100 rtol
    assert r.reactions[:, 1] / F == pytest.approx([0.7, 0.3], rel=1e-6)
    # statics to 1e-7: at 1e-2 N (plain iteration) the shaft's elastic forces, ~1e9 N/m
    # times the 92 um travel, are resolved to ~3e-10 N
    assert abs(r.reactions.sum(0)[1] - F) <= 1e-7 * F
    A, bf = BRG6.curvature_center_distance, BRG6.free_contact_angle
    # (to 1 nm: the rings' tilt of a few nrad moves the loaded ball by R_i theta ~ 0.1 nm)
    assert r.ring_displacements[:, 0] == pytest.approx(-A * np.sin(bf), abs=1e-9)
    # one ball per seat carries its reaction Q at beta = 0: radial displacement
    # P_d/2 + (Q/K_n)^(2/3) (H&D 1981 eq. 3.34 with the clearance of eq. 3.39)
    Kn = float(BRG6.contact_stiffness(0.0)[2])
    Q = r.reactions[:, 1]
    assert r.ring_displacements[:, 1] == pytest.approx(7.5e-6 + (Q / Kn) ** (2 / 3),
                                                       rel=1e-9, abs=1e-15)


def test_shaft_tiny_load_beyond_round_off_says_so():
    """1e-9 N against a shaft of ~1e9 N/m moved 92 um through the clearance is below the
    round-off of its elastic forces: ConvergenceError naming the round-off limit."""
    with pytest.raises(ConvergenceError, match="round-off limit"):
        shaft.solve(SHAFT, SEATS, [shaft.PointLoad(0.09, Fy=1e-9)])


def test_shaft_subnormal_load_is_not_returned_uncarried():
    with pytest.raises(ConvergenceError, match="below what the solver resolves"):
        shaft.solve(SHAFT, SEATS, [shaft.PointLoad(0.09, Fy=5e-324)])


def test_shaft_ordinary_load_unchanged():
    """The README's example (3500.04 / 1499.96 N, 50.7 um under the load)."""
    r = shaft.solve(SHAFT, SEATS, [shaft.PointLoad(0.09, Fy=5000.0)])
    assert r.reactions[:, 1] == pytest.approx([3500.04, 1499.96], abs=0.01)


# --------------------------------------------------------------------------- time limit
def test_every_test_has_a_time_limit(request):
    """pytest-timeout (dev extra) is active with the 300 s default of pyproject.toml, so a
    solver that stops converging fails its test instead of holding the suite."""
    assert request.config.pluginmanager.hasplugin("timeout")
    assert float(request.config.getini("timeout")) == 300.0
