"""High-speed (Jones 1960) equilibrium: static limit, independent re-derivation, trends,
equilibrium identities, options and robustness.

Reference bearing: the 218 angular-contact bearing of Ricci (2009) / Harris (2001)
(D = 22.225 mm, Z = 16, d_m = 125.26 mm, f_i = f_o = 0.5232, beta_f = 40 deg, steel
E = 200 GPa, nu = 0.3, rho = 7850 kg/m^3).

No published high-speed table was available to the author of these tests (Harris's
10,000 rpm example of the 218 bearing is in the book, not in the seeds); the high-speed
numbers are instead checked against an independent re-implementation of Harris's
equations (closed-form outer-race-control kinematics, scipy.optimize.fsolve) and against
exact identities.  Tolerances are stated with each test.
"""
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, fsolve

import ballrace
from ballrace.analytic import highspeed as hs
from ballrace.analytic import kinematics as kin
from ballrace.analytic import loaddist as ld

BRG = ballrace.BallBearing(ball_diameter=22.225e-3, n_balls=16, pitch_diameter=125.26e-3,
                           f_inner=0.5232, f_outer=0.5232, free_contact_angle=np.radians(40))
RPM = np.pi / 30.0


# ----------------------------------------------------------------- zero speed = static
def test_zero_speed_thrust_equals_static_and_closed_form():
    """At zero speed: Q_i = Q_o = the static ball load and alpha_i = alpha_o = beta of
    H&D (1981) eq. 3.55, F_a/Z = K_n(beta) (BD)^1.5 sin(beta) (cos beta_f / cos beta - 1)^1.5,
    solved here independently by brentq; delta_t = BD sin(beta - beta_f)/cos(beta) (eq. 3.60).
    Tolerance 1e-10 relative (both solved to ~1e-13)."""
    Fa = 17800.0
    A, bf, Z = BRG.curvature_center_distance, BRG.free_contact_angle, BRG.n_balls
    beta = brentq(lambda b: Z * BRG.contact_stiffness(b)[2] * A**1.5 * np.sin(b)
                  * (np.cos(bf) / np.cos(b) - 1) ** 1.5 - Fa, bf + 1e-12, 1.5, xtol=1e-15)
    r = hs.solve(BRG, Fa=Fa)
    np.testing.assert_allclose(r.inner_contact_angles, beta, rtol=1e-10)
    np.testing.assert_allclose(r.outer_contact_angles, beta, rtol=1e-10)
    np.testing.assert_allclose(r.inner_loads, Fa / (Z * np.sin(beta)), rtol=1e-10)
    np.testing.assert_allclose(r.outer_loads, r.inner_loads, rtol=1e-12)
    assert r.axial_deflection == pytest.approx(A * np.sin(beta - bf) / np.cos(beta), rel=1e-9)
    # and the general static solver
    s = ld.solve(BRG, Fa=Fa)
    np.testing.assert_allclose(r.inner_loads, s.ball_loads, rtol=1e-10)
    np.testing.assert_allclose(r.displacements, s.displacements, rtol=1e-9, atol=1e-18)
    # Harris's chart value for this case (Harris 2001, thrust-load chart): beta ~ 41.6 deg
    assert np.degrees(beta) == pytest.approx(41.6, abs=0.1)
    assert np.all(r.centrifugal_force == 0) and np.all(r.gyroscopic_moment == 0)


@pytest.mark.parametrize("Fr, Fa", [(8900.0, 17800.0), (8900.0, 1000.0), (8900.0, 0.0)])
def test_zero_speed_combined_equals_static(Fr, Fa):
    """Combined load (Jones; H&D 1981 eqs. 3.61-3.74), rings kept parallel: identical ball
    loads, contact angles and ring displacements as loaddist.combined (1e-9 relative to
    the largest ball load; angles of loaded balls to 1e-10 rad)."""
    r = hs.solve(BRG, Fa=Fa, Fr=Fr)
    s = ld.combined(BRG, Fr, Fa)
    Qmax = float(np.max(s.ball_loads))
    assert np.max(np.abs(r.inner_loads - s.ball_loads)) < 1e-9 * Qmax
    assert np.max(np.abs(r.outer_loads - s.ball_loads)) < 1e-9 * Qmax
    on = s.ball_loads > 0
    np.testing.assert_allclose(r.inner_contact_angles[on], s.contact_angles[on], atol=1e-10)
    np.testing.assert_allclose(r.displacements[:2], s.displacements[:2], rtol=1e-8)
    np.testing.assert_allclose(r.loads, s.loads, atol=1e-8 * Qmax * BRG.inner_groove_center_radius)


def test_zero_speed_with_free_tilt_equals_static_five_dof():
    """Moment load with free tilt: same as loaddist.solve (5 DOF)."""
    r = hs.solve(BRG, Fa=17800.0, Fr=8900.0, Mz=-200.0, tilt="free")
    s = ld.solve(BRG, Fa=17800.0, Fy=8900.0, Mz=-200.0)
    Qmax = float(np.max(s.ball_loads))
    assert np.max(np.abs(r.inner_loads - s.ball_loads)) < 1e-9 * Qmax
    np.testing.assert_allclose(r.displacements, s.displacements, rtol=1e-8, atol=1e-15)


def test_independent_start_converges_to_same_static_solution():
    """Started from a crude estimate instead of the static solution, the solver reaches the
    same equilibrium (1e-8 relative)."""
    for kw in (dict(Fa=17800.0), dict(Fa=17800.0, Fr=8900.0), dict(Fa=1000.0, Fr=8900.0)):
        a = hs.solve(BRG, **kw)
        b = hs.solve(BRG, start="estimate", **kw)
        Q = a.inner_loads.max()
        assert np.max(np.abs(a.inner_loads - b.inner_loads)) < 1e-8 * Q
        a = hs.solve(BRG, speed_inner=10000 * RPM, **kw)
        b = hs.solve(BRG, speed_inner=10000 * RPM, start="estimate", **kw)
        assert np.max(np.abs(a.outer_loads - b.outer_loads)) < 1e-8 * a.outer_loads.max()


def test_small_speed_tends_to_static_as_speed_squared():
    """The full high-speed equations (force balance of each ball, not the static shortcut)
    tend to the static solution; the difference scales with omega^2 like F_c (ratio of
    the differences at 1 and 0.1 rad/s within 1 % of 100)."""
    s = ld.combined(BRG, 8900.0, 1000.0)
    d = []
    for w in (0.1, 1.0):
        r = hs.solve(BRG, Fa=1000.0, Fr=8900.0, speed_inner=w)
        d.append(np.max(np.abs(r.outer_loads - s.ball_loads)))
        assert d[-1] < 1e-6 * s.ball_loads.max()
    assert d[1] / d[0] == pytest.approx(100.0, rel=0.01)


# ----------------------------------------------------------------- independent check
def _harris_pure_thrust(Fa, w, brg=BRG, start=None):
    """Independent re-implementation for pure thrust (all balls alike), outer-race control,
    gyroscopic moment reacted at the outer race (Harris 2001 ch. 25; H&D eqs. 3.93-3.112):
    unknowns X1, X2 (ball centre from outer-groove centre) and the axial displacement,
    kinematics from Harris's closed forms.  The grooves are full tori here (no groove
    edge).  ``start``: (X1, X2, da) [m], default the static solution."""
    D, dm, Z = brg.ball_diameter, brg.pitch_diameter, brg.n_balls
    fi, fo, bf = brg.f_inner, brg.f_outer, brg.free_contact_angle
    A = (fi + fo - 1) * D
    m = brg.ball_material.density * np.pi * D**3 / 6
    J = m * D**2 / 10
    g = D / dm

    def eqs(v):
        X1, X2, da = v[0] * 1e-3, v[1] * 1e-3, v[2] * 1e-6
        A1, A2 = A * np.sin(bf) + da, A * np.cos(bf)
        lo, li = np.hypot(X1, X2), np.hypot(A1 - X1, A2 - X2)
        do, di = lo - (fo - 0.5) * D, li - (fi - 0.5) * D
        so, co = X1 / lo, X2 / lo
        si, ci = (A1 - X1) / li, (A2 - X2) / li
        ai, ao = np.arctan2(si, ci), np.arctan2(so, co)
        Ki = brg.contact_stiffness(ai)[0]
        Ko = brg.contact_stiffness(ao)[1]
        Qi, Qo = Ki * max(di, 0) ** 1.5, Ko * max(do, 0) ** 1.5
        beta = np.arctan(so / (co + g))
        wm = w * (1 - g * ci) / (1 + np.cos(ai - ao))
        wR = -w / (((co + np.tan(beta) * so) / (1 + g * co)
                    + (ci + np.tan(beta) * si) / (1 - g * ci)) * g * np.cos(beta))
        de = dm + 2 * X2 - 2 * D * (fo - 0.5) * np.cos(bf)          # H&D eq. 3.107
        Fc = 0.5 * m * de * wm**2
        Mg = J * wR * wm * np.sin(beta)
        return [(Qi * si - Qo * so + 2 * Mg / D * co) / 1e3,
                (Qi * ci - Qo * co - 2 * Mg / D * so + Fc) / 1e3,
                (Z * Qi * si - Fa) / 1e3]

    if start is None:
        s = hs.solve(brg, Fa=Fa)
        start = (*s.ball_positions[0], s.axial_deflection)
    v = fsolve(eqs, [start[0] * 1e3, start[1] * 1e3, start[2] * 1e6], xtol=1e-12)
    assert np.max(np.abs(eqs(v))) < 1e-9
    return v[0] * 1e-3, v[1] * 1e-3, v[2] * 1e-6


@pytest.mark.parametrize("rpm", [5000.0, 10000.0, 20000.0])
def test_matches_independent_reimplementation(rpm):
    """Ball position and ring displacement agree with the independent implementation to
    1e-9 m (rounding of the two Newton solutions); loads to 1e-6 relative."""
    X1, X2, da = _harris_pure_thrust(17800.0, rpm * RPM)
    r = hs.solve(BRG, Fa=17800.0, speed_inner=rpm * RPM)
    assert r.ball_positions[0, 0] == pytest.approx(X1, abs=1e-9)
    assert r.ball_positions[0, 1] == pytest.approx(X2, abs=1e-9)
    assert r.axial_deflection == pytest.approx(da, abs=1e-10)
    np.testing.assert_allclose(r.ball_positions[:, 0], X1, atol=1e-9)    # all balls alike


# ----------------------------------------------------------------- physics
def test_contact_angles_diverge_with_speed():
    """Jones (1960), H&D (1981) §3.4: the outer contact angle falls and the inner one rises
    with speed; the outer load rises."""
    rpms = [0.0, 2500.0, 5000.0, 10000.0, 15000.0, 20000.0]
    res = [hs.solve(BRG, Fa=17800.0, speed_inner=n * RPM) for n in rpms]
    ai = np.array([r.inner_contact_angles[0] for r in res])
    ao = np.array([r.outer_contact_angles[0] for r in res])
    Qo = np.array([r.outer_loads[0] for r in res])
    assert np.all(np.diff(ai) > 0) and np.all(np.diff(ao) < 0) and np.all(np.diff(Qo) > 0)
    # regression snapshot (self-generated, 10,000 rpm): 50.04 / 31.28 deg
    assert np.degrees(ai[3]) == pytest.approx(50.04, abs=0.01)
    assert np.degrees(ao[3]) == pytest.approx(31.28, abs=0.01)


@pytest.mark.parametrize("rpm", [10000.0, 20000.0])
def test_outer_minus_inner_load_is_about_centrifugal_force(rpm):
    """Pure thrust without gyroscopic moment: the radial ball balance is exactly
    Q_o cos a_o - Q_i cos a_i = F_c and the axial one Q_i sin a_i = Q_o sin a_o = F_a/Z
    (H&D eqs. 3.104-3.105, 1e-8 relative); so Q_o - Q_i is F_c up to the cosines of the
    contact angles: between 0.6 F_c and F_c here (0.73 F_c at 10,000 rpm, 0.86 at 20,000)."""
    r = hs.solve(BRG, Fa=17800.0, speed_inner=rpm * RPM, gyroscopic="none")
    Qi, Qo, Fc = r.inner_loads, r.outer_loads, r.centrifugal_force
    ai, ao = r.inner_contact_angles, r.outer_contact_angles
    np.testing.assert_allclose(Qo * np.cos(ao) - Qi * np.cos(ai), Fc, rtol=1e-8)
    np.testing.assert_allclose(Qi * np.sin(ai), 17800.0 / 16, rtol=1e-8)
    np.testing.assert_allclose(Qo * np.sin(ao), 17800.0 / 16, rtol=1e-8)
    assert np.all((Qo - Qi > 0.6 * Fc) & (Qo - Qi < Fc))


def test_centrifugal_force_and_gyroscopic_moment_formulas():
    """Per ball: F_c = (1/2) m d_orbit omega_c^2 and M_g = J omega_R omega_c sin(beta)
    (H&D eqs. 3.106-3.108), with Jones's per-ball kinematics of the reported contact
    angles (orbital="ball")."""
    r = hs.solve(BRG, Fa=17800.0, Fr=4000.0, speed_inner=12000 * RPM, orbital="ball")
    D, rho = BRG.ball_diameter, BRG.ball_material.density
    m = rho * np.pi * D**3 / 6
    orbit = 2 * (0.5 * BRG.outer_race_diameter - BRG.f_outer * D + r.ball_positions[:, 1])
    np.testing.assert_allclose(r.centrifugal_force, 0.5 * m * orbit * r.orbital_speed**2,
                               rtol=1e-13)
    np.testing.assert_allclose(r.gyroscopic_moment, m * D**2 / 10 * r.spin_speed
                               * r.orbital_speed * np.sin(r.pitch_angle), rtol=1e-13)
    k = kin.ball_kinematics(D, BRG.pitch_diameter, r.inner_contact_angles,
                            r.outer_contact_angles, 12000 * RPM, 0.0, "outer")
    np.testing.assert_allclose(r.orbital_speed, k.cage_speed, rtol=1e-12)
    np.testing.assert_allclose(r.spin_speed, k.ball_speed, rtol=1e-12)
    i, o = kin.spin_to_roll(D, BRG.pitch_diameter, r.inner_contact_angles,
                            r.outer_contact_angles, "outer")
    np.testing.assert_allclose(r.spin_to_roll_inner, i, rtol=1e-10)
    assert np.all(r.spin_to_roll_outer == 0)
    # gyroscopic moment negative for inner-ring rotation (Harris's sign of omega_R)
    assert np.all(r.gyroscopic_moment < 0)


def test_cage_orbital_model():
    """orbital="cage": one orbital speed for all balls, the Q_i Q_o/(Q_i + Q_o)-weighted
    mean of the per-ball kinematic speeds; every ball rolls without slip on the
    controlling (outer) race at that speed (H&D eq. 3.77 with omega_c given), so
    M_g = J omega_R omega_c sin(beta) with omega_R from that rolling condition.  In pure
    thrust it coincides with Jones's per-ball model (1e-12)."""
    w = 12000 * RPM
    r = hs.solve(BRG, Fa=17800.0, Fr=8900.0, speed_inner=w)
    assert np.ptp(r.orbital_speed) == 0.0
    D, dm = BRG.ball_diameter, BRG.pitch_diameter
    ai, ao = r.inner_contact_angles, r.outer_contact_angles
    k = kin.ball_kinematics(D, dm, ai, ao, w, 0.0, "outer")
    q = r.inner_loads * r.outer_loads / (r.inner_loads + r.outer_loads)
    assert r.orbital_speed[0] == pytest.approx(np.sum(q * k.cage_speed) / np.sum(q), rel=1e-12)
    wR = (0.0 - r.orbital_speed) * (1 + D / dm * np.cos(ao)) / (D / dm * np.cos(ao - r.pitch_angle))
    np.testing.assert_allclose(r.spin_speed, wR, rtol=1e-12)
    a = hs.solve(BRG, Fa=17800.0, speed_inner=w, orbital="cage")
    b = hs.solve(BRG, Fa=17800.0, speed_inner=w, orbital="ball")
    np.testing.assert_allclose(a.outer_loads, b.outer_loads, rtol=1e-12)
    np.testing.assert_allclose(a.orbital_speed, b.orbital_speed, rtol=1e-12)


@pytest.mark.parametrize("kw", [dict(Fa=17800.0), dict(Fa=17800.0, Fr=8900.0),
                                dict(Fa=1000.0, Fr=8900.0), dict(Fr=8900.0)])
def test_equilibrium_residual_small(kw):
    """Ring equilibrium: resultant of the ball forces = applied loads (1e-8 relative);
    the reported residual is below 1e-9 of the load scale."""
    r = hs.solve(BRG, speed_inner=10000 * RPM, **kw)
    assert r.relative_residual < 1e-9
    np.testing.assert_allclose(r.loads[:2], r.applied[:2], atol=1e-8 * r.applied.max())
    # balls away from the load at pure radial load touch only the outer race: Q_o = F_c
    if kw.get("Fa", 0.0) == 0.0:
        off = r.inner_loads == 0
        assert off.sum() >= 10
        np.testing.assert_allclose(r.outer_loads[off], r.centrifugal_force[off], rtol=1e-6)


def test_outer_ring_rotation_faster_cage_larger_centrifugal_force():
    """Outer-ring rotation: omega_c ~ omega (1 + gamma)/2 instead of omega (1 - gamma)/2
    (Harris 2001 ch. 8), so F_c and the contact-angle split are larger."""
    w = 10000 * RPM
    ri = hs.solve(BRG, Fa=17800.0, speed_inner=w)
    ro = hs.solve(BRG, Fa=17800.0, speed_outer=w)
    assert ro.orbital_speed[0] > ri.orbital_speed[0]
    assert ro.centrifugal_force[0] > ri.centrifugal_force[0]
    assert ro.gyroscopic_moment[0] > 0 > ri.gyroscopic_moment[0]
    # both rings together: rigid rotation, the balls still feel F_c
    rb = hs.solve(BRG, Fa=17800.0, speed_inner=w, speed_outer=w)
    np.testing.assert_allclose(rb.orbital_speed, w, rtol=1e-12)
    np.testing.assert_allclose(rb.spin_speed, 0.0, atol=1e-9 * w)


def test_gyroscopic_options_and_slip_check():
    """The gyroscopic moment changes the outer loads by a few percent at 10,000 rpm
    (friction 2 M_g / D ~ 133 N against ~1.9 kN ball loads: 2.4 %); the harris and controlling-race
    treatments coincide for outer control; mu = 0.01 cannot resist it, mu = 0.1 can."""
    w = 10000 * RPM
    a = hs.solve(BRG, Fa=17800.0, speed_inner=w, gyroscopic="harris")
    b = hs.solve(BRG, Fa=17800.0, speed_inner=w, gyroscopic="none")
    c = hs.solve(BRG, Fa=17800.0, speed_inner=w, gyroscopic="controlling-race")
    np.testing.assert_allclose(a.outer_loads, c.outer_loads, rtol=1e-12)
    rel = np.max(np.abs(a.outer_loads - b.outer_loads) / b.outer_loads)
    assert 1e-2 < rel < 5e-2
    assert not np.any(hs.solve(BRG, Fa=17800.0, speed_inner=w, friction_coefficient=0.1)
                      .gyroscopic_slip)
    assert np.all(hs.solve(BRG, Fa=17800.0, speed_inner=w, friction_coefficient=0.01)
                  .gyroscopic_slip)


def test_race_control_options():
    """Inner-race control: no spin at the inner contacts; Jones's criterion picks outer
    control for this heavily thrust-loaded 40 deg bearing (Q_o a_o E_o > Q_i a_i E_i)."""
    w = 10000 * RPM
    r = hs.solve(BRG, Fa=17800.0, speed_inner=w, control="inner")
    assert np.all(r.control == "inner") and np.all(r.spin_to_roll_inner == 0)
    assert np.all(r.spin_to_roll_outer != 0)
    j = hs.solve(BRG, Fa=17800.0, speed_inner=w, control="jones")
    assert np.all(j.control == "outer")
    o = hs.solve(BRG, Fa=17800.0, speed_inner=w, control="outer")
    np.testing.assert_allclose(j.outer_loads, o.outer_loads, rtol=1e-12)


# ----------------------------------------------------------------- formulas and inputs
def test_formula_functions():
    """m = rho pi D^3/6, J = m D^2/10 (solid sphere), F_c = m d_m w^2 / 2."""
    D, rho = 22.225e-3, 7850.0
    m = rho * np.pi * D**3 / 6
    assert hs.ball_mass(D, rho) == pytest.approx(m, rel=1e-15)
    assert hs.ball_inertia(D, rho) == pytest.approx(m * D * D / 10, rel=1e-15)
    assert hs.centrifugal_force(D, rho, 0.125, 400.0) == pytest.approx(0.5 * m * 0.125 * 400**2)
    assert hs.gyroscopic_moment(D, rho, -2000.0, 400.0, 0.5) == pytest.approx(
        m * D * D / 10 * -2000 * 400 * np.sin(0.5))


def test_bad_inputs_name_the_argument():
    with pytest.raises(ValueError, match="control"):
        hs.solve(BRG, Fa=1000.0, control="cage")
    with pytest.raises(ValueError, match="orbital"):
        hs.solve(BRG, Fa=1000.0, orbital="race")
    with pytest.raises(ValueError, match="gyroscopic"):
        hs.solve(BRG, Fa=1000.0, gyroscopic="yes")
    with pytest.raises(ValueError, match="My and Mz"):
        hs.solve(BRG, Fa=1000.0, Mz=10.0)
    with pytest.raises(ValueError, match="apply a load"):
        hs.solve(BRG, speed_inner=100.0)
    with pytest.raises(ValueError, match="friction_coefficient"):
        hs.solve(BRG, Fa=1000.0, friction_coefficient=-0.1)
    with pytest.raises(ValueError, match="speed_inner"):
        hs.solve(BRG, Fa=1000.0, speed_inner=np.nan)
    with pytest.raises(TypeError, match="bearing"):
        hs.solve(object(), Fa=1000.0)
    with pytest.raises(ValueError, match="density"):
        hs.ball_mass(0.01, -1.0)


@pytest.mark.parametrize("rpm, gyro", [(3000, "harris"), (3358, "harris"), (4000, "harris"),
                                       (4000, "none")])
def test_light_thrust_moderate_speed_converges(rpm, gyro):
    """Found by hypothesis: 200 N thrust at 3000-4000 rpm (centrifugal force ~3x the
    thrust share of a ball) left the damped Newton creeping at step 1/64 until
    ConvergenceError; the Levenberg-Marquardt rescue must reach equilibrium."""
    r = hs.solve(BRG, Fa=200.0, control="outer", gyroscopic=gyro, speed_inner=rpm * RPM)
    assert r.relative_residual < 1e-8
    assert np.all(r.outer_contact_angles < r.inner_contact_angles)   # F_c loads the outer race
    assert np.all(r.outer_loads > r.inner_loads)


@settings(max_examples=25, deadline=None)
@given(Fa=st.floats(200.0, 40000.0), Fr=st.floats(0.0, 20000.0),
       rpm=st.floats(0.0, 15000.0), outer_ring=st.booleans(),
       control=st.sampled_from(["outer", "jones"]),
       gyro=st.sampled_from(list(hs.GYROSCOPIC)))
def test_no_nan_for_valid_inputs(Fa, Fr, rpm, outer_ring, control, gyro):
    """Random valid loads and speeds: finite results, converged equilibrium (an
    unconverged solve raises ConvergenceError and fails).  Inner-race control is left
    out: 2 of 400 random inner-control cases still raise (e.g. Fa = 446 N, Fr = 1158 N,
    13,975 rpm, Harris gyroscopics: residual 2e-3) -- light load at high speed, where the
    inner contact may be unable to control the ball; whether an equilibrium exists there
    is not established.  Outer and Jones control: 0 failures in 300 random cases."""
    w = rpm * RPM
    kw = dict(speed_outer=w) if outer_ring else dict(speed_inner=w)
    r = hs.solve(BRG, Fa=Fa, Fr=Fr, control=control, gyroscopic=gyro, **kw)
    for a in (r.inner_loads, r.outer_loads, r.inner_contact_angles, r.outer_contact_angles,
              r.centrifugal_force, r.gyroscopic_moment, r.orbital_speed, r.spin_speed,
              r.displacements, r.spin_to_roll_inner, r.spin_to_roll_outer):
        assert np.all(np.isfinite(a))
    assert r.relative_residual < 1e-8
    assert np.all(r.inner_loads >= 0) and np.all(r.outer_loads >= 0)


def test_inner_control_light_inner_contact_converges_and_flags_slip():
    """Fa = 1000 N at 8641 rpm, inner control, gyroscopic moment reacted at the inner race:
    the inner contact carries ~3 N against ~220 N at the outer.  The equations do have a
    solution (the damped Newton from the static start stalls here; the continuation in
    speed finds it), but with mu = 0.1 every ball would pivot.
    An unreachable rtol still raises, naming residual, iterations and the hint."""
    kw = dict(Fa=1000.0, speed_inner=8641 * RPM, control="inner",
              gyroscopic="controlling-race")
    r = hs.solve(BRG, friction_coefficient=0.1, **kw)
    assert r.relative_residual < 1e-8 and np.all(r.gyroscopic_slip)
    assert r.inner_loads.max() < 0.05 * r.outer_loads.min()
    with pytest.raises(hs.ConvergenceError,
                       match=r"residual .* after \d+ Newton iterations.*control='outer'"):
        hs.solve(BRG, rtol=1e-300, **kw)

def test_outer_ring_rotation_without_inner_speed():
    # 6 balls, D = 1.62 mm, P_d = 30.3 um, Fr = 175.7 N, outer ring at 66.1 rad/s, outer
    # control, Jones's per-ball orbit: "Rx must be finite; got nan" (a far-side ball's open
    # contact took the groove-centre line's angle near pi into the kinematics).  The report
    # gives no conformities; f_i = 0.505, f_o = 0.51 reproduce the NaN.
    brg = ballrace.BallBearing(1.62e-3, 6, 10.5e-3, 0.505, 0.51, diametral_clearance=30.3e-6)
    r = hs.solve(brg, Fr=175.7, speed_outer=66.1, control="outer", orbital="ball")
    assert r.relative_residual < 1e-9
    assert abs(r.loads[1] - 175.7) <= 1e-9 * 175.7
    for a in (r.inner_contact_angles, r.outer_contact_angles, r.orbital_speed, r.spin_speed):
        assert np.all(np.isfinite(a))
    assert np.all(np.abs(r.inner_contact_angles) <= np.pi / 2)
    assert np.all(np.abs(r.outer_contact_angles) <= np.pi / 2)
    # the cage turns with the outer ring at about (1 + D/d_m)/2 of its speed
    loaded = r.outer_loads > 0
    assert np.allclose(r.orbital_speed[loaded] / 66.1, 0.5 * (1 + 1.62 / 10.5), rtol=0.02)


def test_overload_reported_like_the_static_solver():
    brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
                               free_contact_angle=np.radians(40))
    with pytest.raises(ValueError, match="beyond the load-deflection range"):
        hs.solve(brg, Fa=1e9, speed_inner=1000.0)
    with pytest.raises(ValueError, match="beyond the load-deflection range"):
        ld.solve(brg, Fa=1e9)


# ----------------------------------------------------------------- convergence of the high-speed solver
from hsref import rederive_highspeed  # noqa: E402

STEEL208 = ballrace.Material(E=208e9, nu=0.3, density=7850.0)
R40 = np.radians(40.0)


def _reproducer(D, Z, dm, fi, fo, angle_deg, **run):
    """(bearing of STEEL208 with free contact angle ``angle_deg``, loads and speed)."""
    return (ballrace.BallBearing(D, Z, dm, fi, fo, free_contact_angle=np.radians(angle_deg),
                                 material=STEEL208), run)


# four reported cases: (bearing, loads and speed)
ISSUE21 = {
    "40deg-light-combined-inner": _reproducer(
        0.011472, 11, 0.05729, 0.5068, 0.5133, 40.0,
        Fa=39.445, Fr=28.333, speed_inner=738.5108, control="inner"),
    "40deg-pure-radial-inner": _reproducer(
        0.010351, 7, 0.04465, 0.5076, 0.5387, 40.0,
        Fa=0.0, Fr=190.046, speed_inner=547.086, control="inner"),
    "25deg-light-combined-inner": _reproducer(
        0.006654, 10, 0.02771, 0.5101, 0.5333, 25.0,
        Fa=27.0, Fr=49.843, speed_inner=3729.6389, control="inner"),
    "40deg-thrust-outer": _reproducer(
        0.020265, 10, 0.13107, 0.5109, 0.54, 40.0,
        Fa=3230.782, Fr=0.0, speed_inner=798.9605, control="outer"),
}


@pytest.mark.parametrize("gyro", ["harris", "none"])
@pytest.mark.parametrize("case", list(ISSUE21))
def test_reproducers_converge_correctly_or_say_why(case, gyro):
    """Each reproducer either converges to a result that the independent re-derivation
    (tests/hsref.py: deflections from the ball positions and groove centres, Q from
    hertz.contact_stiffness, half-torus grooves, ball and ring balances from the REPORTED
    loads, angles, friction shares, F_c and M_g) confirms to 1e-8 of the load scale, or
    raises ConvergenceError naming where the equilibrium ends and why.  Which of the two
    is stated per case (the no-solution cases are checked further below)."""
    brg, kw = ISSUE21[case]
    fails = gyro == "harris" and case in ("25deg-light-combined-inner", "40deg-thrust-outer")
    if fails:
        with pytest.raises(hs.ConvergenceError,
                           match=r"ends at .* % of the speed.*There: .*(friction|groove edge)"):
            hs.solve(brg, gyroscopic=gyro, **kw)
        return
    r = hs.solve(brg, gyroscopic=gyro, **kw)
    assert rederive_highspeed(brg, r) == []
    assert np.all(np.abs(r.inner_contact_angles) <= np.pi / 2)
    assert np.all(np.abs(r.outer_contact_angles) <= np.pi / 2)
    # a ball overlapping the full inner torus beyond its edge carries nothing, is flagged
    # and named in a warning (as in the static model, where it is unloaded)
    past = r.beyond_groove_inner
    assert np.all(r.inner_loads[past] == 0)
    if np.any(past):
        assert any("90 deg or more from the groove bottom" in w for w in r.warnings)


def test_light_combined_flags_balls_past_the_groove_edge():
    """40 deg, tight inner (f_i 0.5068) / loose outer (0.5133) groove, 39 N thrust + 28 N
    radial at d_m n 4e5: the far-side balls' inner lines of centres lie beyond 90 deg from
    the groove bottom while the ball overlaps the full torus (the ball would ride on the
    land).  They carry no inner load, the result says so, and the reported angles of the
    loaded balls are the geometric ones (re-derived)."""
    brg, kw = ISSUE21["40deg-light-combined-inner"]
    r = hs.solve(brg, **kw)
    D = brg.ball_diameter
    A = brg.curvature_center_distance
    psi = r.azimuths
    A2 = A * np.cos(brg.free_contact_angle) + r.displacements[1] * np.cos(psi)
    e2 = A2 - r.ball_positions[:, 1]
    past = (e2 <= 0) & (r.inner_deflections > 0)
    assert np.any(past)
    np.testing.assert_array_equal(r.beyond_groove_inner, past)
    assert np.all(r.inner_loads[past] == 0) and np.all(r.inner_friction_share[past] == 0)
    assert r.warnings and np.all(np.isfinite(r.cage_speed_ratio))
    assert np.all(r.inner_deflections[past] < 0.05 * D)


def test_thrust_needs_an_inner_contact_past_the_groove_edge():
    """Reproducer 4 (40 deg, f_i 0.5109 / f_o 0.54, 5 % C thrust at d_m n 1e6, outer-race
    control, Harris gyroscopics): followed in speed, the inner contact angle reaches the
    groove edge before the full speed.  Independent check: Harris's pure-thrust equations
    with full-torus grooves (``_harris_pure_thrust``, fsolve), continued in speed from the
    solver's solution at 80 %, give an inner contact angle beyond 90 deg at full speed --
    no ring material is there, so the model has no solution in the grooves."""
    brg, kw = ISSUE21["40deg-thrust-outer"]
    with pytest.raises(hs.ConvergenceError, match="groove edge"):
        hs.solve(brg, **kw)
    w, Fa = kw["speed_inner"], kw["Fa"]
    r = hs.solve(brg, Fa=Fa, speed_inner=0.8 * w)
    v = (*r.ball_positions[0], r.axial_deflection)
    for f in np.linspace(0.8, 1.0, 11)[1:]:
        v = _harris_pure_thrust(Fa, f * w, brg, start=v)
    A = brg.curvature_center_distance
    bf = brg.free_contact_angle
    ai = np.arctan2(A * np.sin(bf) + v[2] - v[0], A * np.cos(bf) - v[1])
    assert np.degrees(ai) > 90.0


def test_inner_control_friction_beyond_the_load_is_named():
    """Reproducer 3 (25 deg, light load, d_m n 1.4e6, inner-race control, Harris
    gyroscopics): the branch followed from the static solution ends where the friction
    that resists M_g at the inner race is several times the inner contact load; the error
    says so.  Without the gyroscopic moment the same case converges (re-derived)."""
    brg, kw = ISSUE21["25deg-light-combined-inner"]
    with pytest.raises(hs.ConvergenceError, match=r"friction .* inner race is up to"):
        hs.solve(brg, **kw)
    r = hs.solve(brg, gyroscopic="none", **kw)
    assert rederive_highspeed(brg, r) == []


def test_bearing_at_zero_speed_equals_static_model():
    """The bearing of reproducer 1 under its load at zero speed: the same ball loads and
    angles as the static model (loaddist, rings parallel; loads 1e-9 of the largest,
    angles of loaded balls 1e-9 rad), and at 1 rad/s within 1e-4 (F_c ~ omega^2),
    re-derived."""
    brg, kw = ISSUE21["40deg-light-combined-inner"]
    s = ld.solve(brg, Fa=kw["Fa"], Fy=kw["Fr"], displacements=[np.nan, np.nan, 0, 0, 0])
    r = hs.solve(brg, Fa=kw["Fa"], Fr=kw["Fr"])
    Qm = s.ball_loads.max()
    assert np.max(np.abs(r.inner_loads - s.ball_loads)) <= 1e-9 * Qm
    on = s.ball_loads > 1e-6 * Qm
    np.testing.assert_allclose(r.inner_contact_angles[on], s.contact_angles[on], atol=1e-9)
    r1 = hs.solve(brg, Fa=kw["Fa"], Fr=kw["Fr"], speed_inner=1.0, control="inner")
    assert np.max(np.abs(r1.inner_loads - s.ball_loads)) <= 1e-4 * Qm
    assert rederive_highspeed(brg, r1) == []


def test_reported_angles_are_the_solved_ones_for_barely_touching_contacts():
    """Barely touching contacts (0 < delta < 1e-5 D, where the kinematics blend into the
    line of groove centres) report their geometric contact angle; the blended angle is in
    ``*_kinematic_angles``.  The ring balance rebuilt from the reported quantities (H&D
    eqs. 3.111-3.112) closes to 1e-9 of the applied load."""
    brg, kw = ISSUE21["40deg-light-combined-inner"]
    r = hs.solve(brg, gyroscopic="none", **kw)
    D = brg.ball_diameter
    lam = r.inner_friction_share * r.gyroscopic_moment / D
    T = r.inner_loads * np.sin(r.inner_contact_angles) - lam * np.cos(r.inner_contact_angles)
    P = r.inner_loads * np.cos(r.inner_contact_angles) + lam * np.sin(r.inner_contact_angles)
    assert abs(T.sum() - kw["Fa"]) <= 1e-9 * kw["Fa"]
    assert abs((P * np.cos(r.azimuths)).sum() - kw["Fr"]) <= 1e-9 * kw["Fa"]
    assert rederive_highspeed(brg, r) == []


def test_unphysical_cage_speed_is_flagged():
    """The cage-speed ratio (omega_c - omega_o)/(omega_i - omega_o) is reported (Harris's
    closed form for outer-race control, 1e-9); the 218 bearing at 10,000 rpm stays in the
    rolling range, without warnings; far outside it (the outer ring turning with the
    inner one nearly, so that the balls are carried round) the result is flagged."""
    r = hs.solve(BRG, Fa=17800.0, speed_inner=10000 * RPM)
    g = BRG.ball_diameter / BRG.pitch_diameter
    ai, ao = r.inner_contact_angles[0], r.outer_contact_angles[0]
    # Harris (2001) outer-race control: omega_c / omega_i = (1 - g cos a_i)/(1 + cos(a_i - a_o))
    assert r.cage_speed_ratio == pytest.approx((1 - g * np.cos(ai)) / (1 + np.cos(ai - ao)),
                                               rel=1e-9)
    assert r.warnings == () and not np.any(r.skidding)
    assert not np.any(r.beyond_groove_inner) and not np.any(r.beyond_groove_outer)
    lo, hi = hs.CAGE_RATIO_RANGE
    assert lo * (1 - g) < r.cage_speed_ratio < hi


def test_skidding_flag_without_friction_coefficient():
    """Inner control, gyroscopic moment at the inner race, light thrust at 8641 rpm: the
    inner friction needed exceeds 0.1 Q_i; the result flags it and logs a warning naming
    the balls, with or without ``friction_coefficient``."""
    kw = dict(Fa=1000.0, speed_inner=8641 * RPM, control="inner",
              gyroscopic="controlling-race")
    with pytest.warns(UserWarning) as rec:
        r = hs.solve(BRG, **kw)
    assert np.all(r.skidding) and r.gyroscopic_slip is None
    assert any("skid" in w for w in r.warnings)
    assert any("skid" in str(w.message) and "balls 1, 2" in str(w.message) for w in rec)
    assert all(w.filename == __file__ for w in rec)          # the caller's line
    need = np.abs(r.inner_friction_share * r.gyroscopic_moment) / BRG.ball_diameter
    assert np.all(need > hs.TRACTION_LIMIT * r.inner_loads)


def test_tight_inner_loose_outer_light_preload_is_not_silent():
    """40 deg, tight inner / loose outer groove (f_i 0.511, f_o 0.54), preload 0.1 % C at
    d_m n 6e5 mm rpm.  Outer-race control: the inner contact angle runs into the groove
    edge before full speed (the solver once returned angles of 91-98 deg there), so
    ConvergenceError names it.  Inner-race control: a result, flagged -- the balls skid
    (M_g needs more than 0.1 Q of friction) and the cage turns at 0.16 of the shaft
    speed, below the rolling range CAGE_RATIO_RANGE[0] (1 - D/d_m); both logged."""
    brg = ballrace.BallBearing(0.0127, 12, 0.0635, 0.511, 0.54, free_contact_angle=R40,
                               material=STEEL208)
    kw = dict(Fa=1e-3 * brg.dynamic_rating(), speed_inner=6e5 / 63.5 * RPM)
    with pytest.raises(hs.ConvergenceError, match="groove edge"):
        hs.solve(brg, control="outer", **kw)
    with pytest.warns(UserWarning) as rec:
        r = hs.solve(brg, control="inner", **kw)
    g = brg.ball_diameter / brg.pitch_diameter
    assert r.cage_speed_ratio < hs.CAGE_RATIO_RANGE[0] * (1 - g)
    assert np.all(r.skidding)
    assert any("orbital speed" in w and "outside the rolling range" in w for w in r.warnings)
    assert sum(str(w.message).startswith("highspeed:") for w in rec) >= 2
    assert rederive_highspeed(brg, r) == []


# ------------------------------------------------- fast paths of the solver
def _near_solution_system(kw, control="outer", gyroscopic="harris", orbital="cage",
                          tilt="fixed", seed=0):
    """The solver's system at a state 1e-4 (relative) off a solved equilibrium."""
    r = hs.solve(BRG, control=control, gyroscopic=gyroscopic, orbital=orbital, tilt=tilt,
                 **kw)
    model = hs._Model.of(BRG)
    L = r.applied
    free = hs._free_dofs(L, tilt)
    sysm = hs._System(model, r.azimuths, L, free, r.speed_inner, r.speed_outer, gyroscopic,
                      False, max(np.abs(L).max(), 1.0), r.outer_loads.max(), orbital)
    sysm.outer = r.control == "outer"
    X1, X2 = r.ball_positions.T
    x = np.concatenate([X1, X2, r.displacements[free]])
    rng = np.random.default_rng(seed)
    return sysm, x * (1.0 + 1e-4 * rng.standard_normal(x.size))


@pytest.mark.parametrize("kw, opts", [
    (dict(Fa=5000.0, Fr=2000.0, speed_inner=10000 * RPM), dict()),
    (dict(Fa=3000.0, Fr=2000.0, Fz=500.0, My=30.0, speed_inner=12000 * RPM),
     dict(tilt="free", control="inner")),
    (dict(Fa=3000.0, Fr=2000.0, speed_inner=12000 * RPM), dict(orbital="ball")),
    (dict(Fa=4000.0, Fr=1000.0, speed_inner=8000 * RPM),
     dict(control="inner", gyroscopic="controlling-race")),
    (dict(Fa=4000.0, Fr=1000.0, speed_inner=8000 * RPM), dict(gyroscopic="none")),
])
def test_jacobian_equals_columnwise_central_differences(kw, opts):
    """The solver's Jacobian (all perturbed states in one batch, per-ball 2 x 2 blocks
    scattered by index, the cage speed held in the ball blocks and its coupling added
    as a rank-one term) equals the plain definition: central differences of the full
    residual vector one unknown at a time, the cage speed recomputed (step 1e-9 D, or
    1e-9 D / R_i for a tilt).  Both are differences of the same residual, so they agree
    to the differences' truncation and round-off: 1e-6 of the largest entry."""
    sysm, x = _near_solution_system(kw, **opts)
    J = sysm.jacobian(x)
    n = x.size
    Jref = np.empty((n, n))
    for k in range(n):
        h = 1e-9 * BRG.ball_diameter / (sysm.u_sc[k - 2 * sysm.Z] if k >= 2 * sysm.Z else 1)
        e = np.zeros(n)
        e[k] = h
        Jref[:, k] = (sysm.residual(sysm.balls(x + e))
                      - sysm.residual(sysm.balls(x - e))) / (2 * h)
    # (tilt columns per metre at the groove-centre radius, like the others)
    sc = np.r_[np.ones(2 * sysm.Z), sysm.u_sc]
    assert np.max(np.abs((J - Jref) / sc)) <= 1e-6 * np.max(np.abs(Jref / sc))


def test_batched_line_search_takes_the_plain_backtracking_steps(monkeypatch, caplog):
    """The line search evaluates the halved steps 1/2 ... 1/64 in one batch and takes the
    longest that decreases the merit enough; evaluated one at a time (plain
    backtracking, ``_HALVINGS = [1]``) it must take the same steps: same iteration
    count, same equilibrium to 1e-9.  A light combined load at 12,218 rpm, where the
    first Newton steps are damped to 1/16."""
    kw = dict(Fa=3541.685, Fr=2368.105, speed_inner=12218.0 * RPM)
    with caplog.at_level("DEBUG", logger="ballrace.analytic.highspeed"):
        a = hs.solve(BRG, **kw)
    steps = [float(m.group(1)) for m in (
        re.search(r"iteration \d+, step ([0-9.e+-]+)", rec.getMessage())
        for rec in caplog.records) if m]
    assert min(steps) < 0.5                       # the search did backtrack
    monkeypatch.setattr(hs, "_HALVINGS", np.array([1.0]))
    b = hs.solve(BRG, **kw)
    assert a.iterations == b.iterations
    Q = a.outer_loads.max()
    assert np.max(np.abs(a.inner_loads - b.inner_loads)) <= 1e-9 * Q
    assert np.max(np.abs(a.outer_loads - b.outer_loads)) <= 1e-9 * Q
    assert np.max(np.abs(a.inner_contact_angles - b.inner_contact_angles)) <= 1e-9


def test_batch_row_equals_single_state():
    """A state taken from a batch evaluation (line search, Jacobian) is the state
    evaluated alone, bit for bit in every per-ball quantity (the ring resultants to
    1e-12: summation order).  The batch holds states with an open inner and an open
    outer contact, so it takes the general path (blend weights, masks) while the single
    states, all contacts closed, take the short one: this also checks that the short
    path leaves out only terms that change nothing."""
    sysm, x = _near_solution_system(dict(Fa=5000.0, Fr=2000.0, speed_inner=10000 * RPM))
    X = x + np.outer([0.0, 0.5, 0.25, 0.0, 0.0], 1e-6 * x)
    X[3, sysm.Z] += 0.01 * BRG.ball_diameter         # ball 1 pulled off the inner race
    X[4, sysm.Z] -= 0.01 * BRG.ball_diameter         # ... and off the outer race
    B = sysm.balls_rows(X)
    assert B.row(3).Qi[0] == 0 and B.row(3).wgt_i[0] == 0
    assert B.row(4).Qo[0] == 0 and B.row(4).wgt_o[0] == 0
    for k in range(3):
        a, b = B.row(k), sysm.balls(X[k])
        assert np.all(b.Qi > 0) and np.all(b.Qo > 0)
        for name in ("Qi", "Qo", "ai", "ao", "ai_k", "ao_k", "wgt_i", "wgt_o", "wc", "wR",
                     "Fc", "Mg", "lam_i", "lam_o", "R1", "R2", "T", "P", "Mt"):
            assert np.array_equal(getattr(a, name), getattr(b, name)), name
        assert np.allclose(sysm.residual(a), sysm.residual(b), rtol=0,
                           atol=1e-12 * np.max(np.abs(sysm.residual(b))))


@pytest.mark.parametrize("kw", [dict(Fa=12478.9, Fr=941.3, speed_inner=7064.0 * RPM),
                                dict(Fa=18766.3, Fr=2071.9, speed_inner=9821.0 * RPM),
                                dict(Fa=4046.1, Fr=3912.3, speed_inner=8234.0 * RPM)])
def test_chord_steps_do_not_change_the_equilibrium(kw, monkeypatch, caplog):
    """Once Newton converges quadratically the solver reuses the last factorised
    Jacobian (chord steps).  Without them (``_CHORD_START = 0``: a new Jacobian every
    step) the equilibrium is the same to 1e-9 of the largest load and 1e-9 rad, and
    both satisfy the independent re-derivation (tests/hsref.py)."""
    with caplog.at_level("DEBUG", logger="ballrace.analytic.highspeed"):
        a = hs.solve(BRG, **kw)
    assert any("chord step" in rec.getMessage() for rec in caplog.records)
    monkeypatch.setattr(hs, "_CHORD_START", 0.0)
    b = hs.solve(BRG, **kw)
    Q = a.outer_loads.max()
    for name in ("inner_loads", "outer_loads"):
        assert np.max(np.abs(getattr(a, name) - getattr(b, name))) <= 1e-9 * Q
    for name in ("inner_contact_angles", "outer_contact_angles"):
        assert np.max(np.abs(getattr(a, name) - getattr(b, name))) <= 1e-9
    assert rederive_highspeed(BRG, a) == [] and rederive_highspeed(BRG, b) == []
