"""Fuzz suite for the solver entry points.

Hypothesis draws valid bearings (3 balls to the largest set that fits, D from 0.5 to
60 mm, pitch ratio D/d_m up to 0.85, conformities 0.505-0.6, free contact angle 0-89 deg
or a diametral clearance up to 2A, steel or silicon-nitride balls) and loads of every
size (zero, 1e-9 of the nominal capacity, ordinary, up to 100 times it) in every
direction, speeds up to d_m n = 2e6 mm rpm on either ring.  For every solver entry point
-- ``solve``, ``radial``, ``thrust``, ``combined``, ``eccentric_thrust``,
``DuplexPair.solve``, ``highspeed.solve`` -- it asserts:

* the only exceptions are the documented ``ValueError`` / ``TypeError`` /
  ``ConvergenceError`` (a ``ValueError`` for a valid bearing and load must say the load is
  beyond the range of the model);
* no NaN or inf in any result;
* equilibrium: relative residual <= 1e-9 (forces, moments over R_i, against the largest
  of the applied loads and Q_max), recomputed here from the returned ball loads and
  angles, not taken from the solver;
* contact angles in [-pi/2, pi/2], ball loads >= 0;
* downstream calls accept every result: Hertz contacts on both races, the
  Lundberg-Palmgren orthogonal shear, ``life.bearing_life``.

Extreme magnitudes (``test_extreme_magnitudes``): every entry point -- the static
load distribution, the duplex pair, the high-speed solver, the shaft -- given a
subnormal (5e-324), a tiny (1e-300) or a huge (1e300) load, preload or speed returns a
balanced result or raises a ValueError naming the range / a ConvergenceError saying why,
within seconds (a preload inversion once looped forever on 5e-324 N).

Profiles (tests/conftest.py): by default (and with ``HYPOTHESIS_PROFILE=ci``) each test
runs a fixed, derandomized set of examples that takes about a minute in all;
``HYPOTHESIS_PROFILE=fuzz`` (``make fuzz``) draws fresh random examples, weighted by
cost: of the profile's 10^4, 0.3 for the general solve, 0.15 each for the
radial/thrust/combined draws (three solver calls each) and eccentric thrust, 0.1 duplex,
0.01 vectorized pairs (three solves each), 0.005 high speed, 0.01 high speed on catalogue
bearings -- about 1.05 x 10^4 solver calls.  High-speed results are re-derived
independently (tests/hsref.py) from what they report.  The long run
records assertion failures with their inputs and goes on drawing (the last test then
fails), and with ``BALLRACE_FUZZ_REPORT=file`` appends a summary (cases, refusals,
convergence failures, failures, worst residual per entry point).
``BALLRACE_FUZZ_NOSHRINK=1`` reports a failure as drawn, without shrinking.
"""
import functools
import json
import os
import re
import time

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, event, given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import duplex, highspeed, life, loaddist, shaft
from ballrace.analytic.loaddist import ConvergenceError
from hsref import rederive_highspeed

PROFILE = os.environ.get("HYPOTHESIS_PROFILE", "default")
FUZZ = PROFILE == "fuzz"
N_FUZZ = settings.get_profile("fuzz").max_examples if FUZZ else 0
RTOL_EQ = 1e-9
STATS = {}


def _settings(n_default, weight=1.0):
    """Fixed-seed ``n_default`` examples in the default suite; ``weight`` x 10^4 when fuzzing."""
    n = max(n_default, int(N_FUZZ * weight)) if FUZZ else n_default
    kw = {}
    if os.environ.get("BALLRACE_FUZZ_NOSHRINK"):          # report the first failure as drawn
        kw["phases"] = [Phase.explicit, Phase.generate]
    return settings(max_examples=n, deadline=None, derandomize=not FUZZ, database=None,
                    suppress_health_check=list(HealthCheck), **kw)


CURRENT = {}
FAILURES = []


def _note(**inputs):
    """Remember the drawn inputs (reported with a failure in the long run)."""
    CURRENT.clear()
    CURRENT.update({k: repr(v) for k, v in inputs.items()})


def collect(name):
    """In the long run, record an assertion failure with its inputs and go on drawing
    (the last test then fails); otherwise let hypothesis shrink and report it."""
    def deco(f):
        @functools.wraps(f)
        def wrapper(data):
            if not FUZZ:
                return f(data)
            try:
                return f(data)
            except AssertionError as exc:
                _record(name, "failure")
                FAILURES.append({"test": name, "error": str(exc)[:500], **CURRENT})
        return wrapper
    return deco


def fuzz_test(name, n_default, weight=1.0):
    """A property test drawing from ``st.data()`` with :func:`_settings` (``n_default``,
    ``weight``), whose failures the long run records under ``name`` (:func:`collect`)."""
    def deco(f):
        return _settings(n_default, weight)(given(st.data())(collect(name)(f)))
    return deco


def _record(name, outcome, residual=0.0):
    s = STATS.setdefault(name, {"cases": 0, "ok": 0, "refused": 0, "convergence": 0,
                                "failure": 0, "worst_residual": 0.0})
    s["cases"] += 1
    s[outcome] += 1
    s["worst_residual"] = max(s["worst_residual"], float(residual))
    event(f"{name}: {outcome}")


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    path = os.environ.get("BALLRACE_FUZZ_REPORT")
    if path and STATS:
        with open(path, "a") as fh:
            fh.write(json.dumps({"profile": PROFILE, "stats": STATS,
                                 "failures": FAILURES}) + "\n")


# --------------------------------------------------------------------------- strategies
@st.composite
def bearings(draw, clearance=True):
    D = 10 ** draw(st.floats(np.log10(0.5e-3), np.log10(60e-3)))
    dm = D / draw(st.floats(0.067, 0.85))
    z_max = int(np.floor(np.pi / np.arcsin(D / dm) * (1 + 1e-12)))
    Z = draw(st.integers(3, max(3, min(z_max, 40))))
    fi, fo = draw(st.floats(0.505, 0.6)), draw(st.floats(0.505, 0.6))
    ball = draw(st.sampled_from([ballrace.BEARING_STEEL, ballrace.SILICON_NITRIDE]))
    if clearance and draw(st.booleans()):
        A = (fi + fo - 1.0) * D
        Pd = 2 * A * draw(st.sampled_from([0.0, 1e-6, 0.01, 0.3, 0.9, 0.999]))
        return ballrace.BallBearing(D, Z, dm, fi, fo, diametral_clearance=Pd, ball_material=ball)
    bf = np.radians(draw(st.sampled_from([0.0, 15.0, 25.0, 40.0, 60.0, 80.0, 89.0])))
    return ballrace.BallBearing(D, Z, dm, fi, fo, free_contact_angle=bf, ball_material=ball)


def nominal(brg):
    """Nominal capacity Z K_n (0.01 D)^1.5 [N]: contact approach 0.01 D (~static rating)."""
    Kn = float(brg.contact_stiffness(brg.free_contact_angle)[2])
    return brg.n_balls * Kn * (0.01 * brg.ball_diameter) ** 1.5


magnitudes = st.one_of(st.just(0.0), st.just(1e-9), st.floats(-9.0, -6.0).map(lambda x: 10**x),
                       st.floats(-3.0, 0.5).map(lambda x: 10**x),
                       st.floats(0.5, 2.0).map(lambda x: 10**x))


@st.composite
def load_vectors(draw, brg):
    """(Fa, Fy, Fz, My, Mz): a magnitude times a direction with some components zeroed."""
    mag = draw(magnitudes) * nominal(brg)
    v = np.array([draw(st.floats(-1.0, 1.0)) * draw(st.sampled_from([0.0, 1.0]))
                  for _ in range(5)])
    if not np.any(v):
        v[draw(st.integers(0, 4))] = draw(st.sampled_from([-1.0, 1.0]))
    v = v / np.abs(v).max() * mag
    v[3:] *= 0.5 * brg.pitch_diameter
    return [float(x) for x in v]


# --------------------------------------------------------------------------- checks
def _refused(exc):
    """A ValueError for a valid bearing and load must be the documented range refusal."""
    msg = str(exc)
    assert ("beyond the load-deflection range" in msg or "no equilibrium within the grooves"
            in msg or "beyond what the thrust alone can carry" in msg), msg


def check_distribution(brg, r, downstream=True):
    """Invariants of a LoadDistribution, recomputed from its ball loads; returns residual.
    ``downstream``: also the contacts, shear and life of the result."""
    Q, beta = np.asarray(r.ball_loads), np.asarray(r.contact_angles)
    for a in (Q, beta, r.displacements, r.loads, r.stiffness, r.applied):
        assert np.all(np.isfinite(a))
    assert np.all(Q >= 0)
    assert np.all(np.abs(beta) <= np.pi / 2)
    # resultant from the ball loads (groove arm R_i or contact arm (d_e - D cos b)/2)
    psi = r.azimuths
    fa, fr = Q * np.sin(beta), Q * np.cos(beta)
    arm = (brg.inner_groove_center_radius if r.moment_arm == "groove"
           else 0.5 * (brg.pitch_diameter - brg.ball_diameter * np.cos(beta)))
    F = np.stack([fa.sum(-1), (fr * np.cos(psi)).sum(-1), (fr * np.sin(psi)).sum(-1),
                  (arm * fa * np.sin(psi)).sum(-1), -(arm * fa * np.cos(psi)).sum(-1)], -1)
    Ri = brg.inner_groove_center_radius
    sc = np.array([1.0, 1.0, 1.0, Ri, Ri])
    res = np.abs(np.where(r.imposed, 0.0, F - r.applied) / sc).max(-1)
    scale = np.maximum(np.abs(r.applied / sc).max(-1), Q.max(-1))
    rel = np.where(scale > 0, res / np.where(scale > 0, scale, 1.0), res)
    assert np.all(rel <= RTOL_EQ), rel
    assert np.allclose(rel, r.relative_residual, rtol=0, atol=1e-12)
    if not downstream:
        return float(np.max(rel))
    # downstream: contacts, Lundberg-Palmgren shear, life
    for c in (r.inner, r.outer):
        for v in (c.a, c.b, c.p_max):
            assert np.all(np.isfinite(v)) and np.all(np.asarray(v) >= 0)
    for s in (r.inner_shear, r.outer_shear):
        assert np.all(np.isfinite(s.tau0)) and np.all(np.isfinite(s.z0))
    for q, b in zip(Q.reshape(-1, Q.shape[-1]), beta.reshape(-1, Q.shape[-1])):
        if np.any(q > 0):
            lf = life.bearing_life(brg, type("R", (), {"ball_loads": q, "contact_angles": b}))
            assert np.isfinite(lf.L10) and lf.L10 > 0
    assert 0.0 <= float(np.min(r.loaded_zone)) and float(np.max(r.loaded_zone)) <= np.pi
    return float(np.max(rel))


def _size(brg, L):
    """Largest load component [N] (moments over d_m/2, as drawn)."""
    return max(abs(x) for x in list(L[:3]) + [v / (0.5 * brg.pitch_diameter) for v in L[3:]])


def run(name, brg, fn, light=False):
    """Call a solver; ``light`` (loads <= 1e-6 of nominal) allows ConvergenceError in the
    fixed set: there the ball approach can be ~1e-7 of the ring's rigid displacement and
    the residual's round-off limit above 1e-9 (the solver then raises, as documented)."""
    try:
        r = fn()
    except ValueError as exc:
        _refused(exc)
        _record(name, "refused")
        return None
    except ConvergenceError:
        _record(name, "convergence")
        if not (FUZZ or light):          # the fixed set has none at ordinary loads
            raise
        return None
    res = check_distribution(brg, r) if isinstance(r, loaddist.LoadDistribution) else 0.0
    _record(name, "ok", res)
    return r


# --------------------------------------------------------------------------- tests
@fuzz_test('solve', 40, 0.3)
def test_fuzz_solve(data):
    brg = data.draw(bearings())
    L = data.draw(load_vectors(brg))
    arm = data.draw(st.sampled_from(loaddist.MOMENT_ARMS))
    _note(bearing=brg, loads=L, moment_arm=arm)
    light = _size(brg, L) <= 1e-6 * nominal(brg)
    run("solve", brg, lambda: brg.solve(*L, moment_arm=arm), light)


@fuzz_test('radial/thrust/combined', 30, 0.15)
def test_fuzz_radial_thrust_combined(data):
    brg = data.draw(bearings())
    m = nominal(brg)
    Fr, Fa = abs(data.draw(magnitudes)) * m, abs(data.draw(magnitudes)) * m
    off = data.draw(st.floats(0.0, 2 * np.pi / brg.n_balls))
    _note(bearing=brg, Fr=Fr, Fa=Fa, azimuth_offset=off)
    light = max(Fr, Fa) <= 1e-6 * m
    run("radial", brg, lambda: brg.radial(Fr, azimuth_offset=off), light)
    run("thrust", brg, lambda: brg.thrust(Fa), light)
    run("combined", brg, lambda: brg.combined(Fr, Fa, azimuth_offset=off), light)


@fuzz_test('eccentric_thrust', 40, 0.15)
def test_fuzz_eccentric_thrust(data):
    brg = data.draw(bearings())
    Fa = abs(data.draw(magnitudes)) * nominal(brg)
    e = data.draw(st.floats(0.0, 1.2)) * 0.5 * brg.pitch_diameter
    _note(bearing=brg, Fa=Fa, e=e)
    r = run("eccentric_thrust", brg, lambda: brg.eccentric_thrust(Fa, e),
            Fa <= 1e-6 * nominal(brg))
    if r is not None and e >= 0.5 * brg.pitch_diameter:
        pytest.fail("eccentric_thrust accepted e >= d_e/2")


@fuzz_test('solve (vectorized)', 20, 0.01)
def test_fuzz_vectorized_equals_scalar(data):
    brg = data.draw(bearings())
    L1, L2 = data.draw(load_vectors(brg)), data.draw(load_vectors(brg))
    _note(bearing=brg, loads=[L1, L2])
    try:
        one = [brg.solve(*L) for L in (L1, L2)]
    except (ValueError, ConvergenceError):
        return
    light = max(_size(brg, L1), _size(brg, L2)) <= 1e-6 * nominal(brg)
    both = run("solve (vectorized)", brg, lambda: brg.solve(*np.array([L1, L2]).T), light)
    if both is not None:
        for k in range(2):
            q = one[k].ball_loads
            assert np.allclose(both.ball_loads[k], q, rtol=1e-6, atol=1e-6 * max(q.max(), 1e-300))


@fuzz_test('duplex', 40, 0.1)
def test_fuzz_duplex(data):
    brg = data.draw(bearings(clearance=False))
    m = nominal(brg)
    arr = data.draw(st.sampled_from(duplex.ARRANGEMENTS))
    P = abs(data.draw(magnitudes)) * m
    Fa = data.draw(st.sampled_from([-1.0, 1.0])) * abs(data.draw(magnitudes)) * m
    Fr = abs(data.draw(magnitudes)) * m
    pair = duplex.DuplexPair(brg, arr, preload=P)
    _note(bearing=brg, arrangement=arr, preload=P, Fa=Fa, Fr=Fr)
    try:
        r = pair.solve(Fa=Fa, Fr=Fr)
    except ValueError as exc:
        msg = str(exc)
        assert ("beyond the load-deflection range" in msg or "tandem (DT)" in msg
                or "no equilibrium within the grooves" in msg), msg
        _record("duplex", "refused")
        return
    except ConvergenceError:
        _record("duplex", "convergence")
        if not (FUZZ or max(abs(Fa), Fr, P) <= 1e-6 * m):     # see run()
            raise
        return
    for a in (r.axial_loads, r.radial_loads, r.ball_loads, r.contact_angles, r.stiffness,
              r.axial_deflections):
        assert np.all(np.isfinite(a))
    assert np.all(np.abs(r.contact_angles) <= np.pi / 2)
    scale = max(abs(Fa), Fr, P, 1.0)
    assert r.residual <= 1e-9 * scale
    for q, b in zip(r.ball_loads, r.contact_angles):
        c = brg.contacts(q, b, "inner")
        assert np.all(np.isfinite(c.p_max))
        if np.any(q > 0):
            assert np.isfinite(life.bearing_life(
                brg, type("R", (), {"ball_loads": q, "contact_angles": b})).L10)
    _record("duplex", "ok", r.residual / scale)


@fuzz_test('highspeed', 12, 0.005)
def test_fuzz_highspeed(data):
    brg = data.draw(bearings())
    m = nominal(brg)
    Fa = abs(data.draw(magnitudes)) * m * 0.1
    Fr = abs(data.draw(magnitudes)) * m * 0.1
    if Fa == 0 and Fr == 0:
        Fa = 1e-3 * m
    # d_m n up to 2e6 mm rpm on either ring
    w_max = 2e6 / (brg.pitch_diameter * 1e3) * np.pi / 30
    wi = data.draw(st.sampled_from([0.0, 1.0])) * data.draw(st.floats(0.0, 1.0)) * w_max
    wo = data.draw(st.sampled_from([0.0, 1.0])) * data.draw(st.floats(-1.0, 1.0)) * w_max
    control = data.draw(st.sampled_from(highspeed.CONTROLS))
    orbital = data.draw(st.sampled_from(highspeed.ORBITALS))
    gyro = data.draw(st.sampled_from(highspeed.GYROSCOPIC))
    _note(bearing=brg, Fa=Fa, Fr=Fr, speed_inner=wi, speed_outer=wo, control=control,
          orbital=orbital, gyroscopic=gyro)
    try:
        r = highspeed.solve(brg, Fa=Fa, Fr=Fr, speed_inner=wi, speed_outer=wo, control=control,
                            orbital=orbital, gyroscopic=gyro)
    except ValueError as exc:
        _refused(exc)
        _record("highspeed", "refused")
        return
    except ConvergenceError:
        _record("highspeed", "convergence")     # documented (light load at high speed)
        return
    for a in (r.inner_loads, r.outer_loads, r.inner_contact_angles, r.outer_contact_angles,
              r.orbital_speed, r.spin_speed, r.loads, r.displacements, r.centrifugal_force):
        assert np.all(np.isfinite(a))
    assert np.all(np.abs(r.inner_contact_angles) <= np.pi / 2)
    assert np.all(np.abs(r.outer_contact_angles) <= np.pi / 2)
    assert r.relative_residual <= RTOL_EQ
    assert np.all(np.isfinite(r.inner_contacts.p_max)) and np.all(np.isfinite(r.outer_contacts.a))
    if np.any(r.inner_loads > 0):
        assert np.isfinite(life.bearing_life(brg, type(
            "R", (), {"ball_loads": r.inner_loads, "contact_angles": r.inner_contact_angles,
                      "ball_loads_outer": r.outer_loads,
                      "contact_angles_outer": r.outer_contact_angles})).L10)
    check_highspeed(brg, r)
    _record("highspeed", "ok", r.relative_residual)


def check_highspeed(brg, r):
    """The result re-derived independently (tests/hsref.py: groove centres from the ring
    displacement, deflections from the ball positions, Q from hertz.contact_stiffness on
    half-torus grooves, ball and ring balances from the reported loads, angles, friction
    shares, F_c and M_g) to 1e-8 of the load scale; flags consistent with the warnings."""
    bad = rederive_highspeed(brg, r)
    assert not bad, bad
    flagged = (np.any(r.skidding) or np.any(r.beyond_groove_inner)
               or np.any(r.beyond_groove_outer))
    assert (not flagged) or r.warnings
    assert np.all(r.inner_loads[r.beyond_groove_inner & (r.inner_deflections > 0)] == 0) or \
        brg.shoulder_height_inner is not None


STEEL208 = ballrace.Material(E=208e9, nu=0.3, density=7850.0)


@st.composite
def catalogue_bearings(draw):
    """Bearings like a catalogue's: deep-groove (clearance) or angular-contact 15/25/40 deg,
    D 5-25 mm, D/d_m 0.12-0.3, f_i 0.505-0.52, f_o 0.515-0.54, steel (E 208 GPa)."""
    D = draw(st.floats(5e-3, 25e-3))
    dm = D / draw(st.floats(0.12, 0.3))
    Z = int(min(np.floor(0.9 * np.pi / np.arcsin(D / dm)), draw(st.integers(7, 20))))
    fi, fo = draw(st.floats(0.505, 0.52)), draw(st.floats(0.515, 0.54))
    kind = draw(st.sampled_from([None, 15.0, 25.0, 40.0]))
    if kind is None:
        A = (fi + fo - 1) * D
        return ballrace.BallBearing(D, Z, dm, fi, fo, material=STEEL208,
                                    diametral_clearance=draw(st.floats(0.005, 0.2)) * A)
    return ballrace.BallBearing(D, Z, dm, fi, fo, material=STEEL208,
                                free_contact_angle=np.radians(kind))


@fuzz_test('highspeed (catalogue)', 16, 0.01)
def test_fuzz_highspeed_catalogue(data):
    """The population of reported hard cases: catalogue bearings, loads 1e-3-0.5 C (axial, radial or
    combined), d_m n 5e4-1.5e6 mm rpm, all three race controls.  Every result must pass
    the independent re-derivation; ConvergenceError must say where the equilibrium ends."""
    brg = data.draw(catalogue_bearings())
    C = brg.dynamic_rating()
    F = C * 10 ** data.draw(st.floats(-3.0, np.log10(0.5)))
    t = data.draw(st.sampled_from([0.0, 1.0, None]))
    t = data.draw(st.floats(0.1, 0.9)) if t is None else t
    Fa, Fr = F * np.sin(t * np.pi / 2), F * np.cos(t * np.pi / 2)
    w = 10 ** data.draw(st.floats(np.log10(5e4), np.log10(1.5e6))) / (
        brg.pitch_diameter * 1e3) * np.pi / 30
    control = data.draw(st.sampled_from(highspeed.CONTROLS))
    _note(bearing=brg, Fa=Fa, Fr=Fr, speed_inner=w, control=control)
    try:
        r = highspeed.solve(brg, Fa=Fa, Fr=Fr, speed_inner=w, control=control)
    except ConvergenceError as exc:
        assert "high-speed equilibrium" in str(exc) and "Newton iterations" in str(exc)
        _record("highspeed (catalogue)", "convergence")
        return
    check_highspeed(brg, r)
    _record("highspeed (catalogue)", "ok", r.relative_residual)


@pytest.mark.skipif(not FUZZ, reason="the long run only (HYPOTHESIS_PROFILE=fuzz)")
def test_fuzz_run_had_no_failures():
    """The long run records failures instead of stopping at the first; none may occur."""
    assert not FAILURES, json.dumps(FAILURES[:5], indent=1)


# --------------------------------------------------------------------------- extremes
DG = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
AC = ballrace.BallBearing(12.7e-3, 12, 60e-3, 0.52, 0.52, free_contact_angle=np.radians(25))
SHAFT = shaft.Shaft(sections=[(0.26, 45e-3, 0.0)], material=ballrace.BEARING_STEEL)
EXTREME_ENTRY_POINTS = {
    "solve Fa": lambda v: AC.solve(Fa=v),
    "solve Fy (clearance)": lambda v: DG.solve(Fy=v),
    "solve My": lambda v: AC.solve(Fa=1000.0, My=v),
    "radial": lambda v: DG.radial(v),
    "thrust": lambda v: AC.thrust(v),
    "combined": lambda v: AC.combined(v, v),
    "eccentric_thrust": lambda v: AC.eccentric_thrust(v, 0.01),
    "duplex DB preload": lambda v: duplex.DuplexPair(AC, "DB", preload=v).solve(Fa=1.0, Fr=1.0),
    "duplex DT preload": lambda v: duplex.DuplexPair(AC, "DT", preload=v).solve(Fa=1.0, Fr=1.0),
    "duplex DB loads": lambda v: duplex.DuplexPair(AC, "DB", preload=100.0).solve(Fa=v, Fr=v),
    "duplex DT loads": lambda v: duplex.DuplexPair(AC, "DT").solve(Fa=v, Fr=v),
    "axial_deflection": lambda v: duplex.axial_deflection(AC, v),
    "highspeed Fa": lambda v: highspeed.solve(AC, Fa=v, speed_inner=1000.0),
    "highspeed Fr (clearance)": lambda v: highspeed.solve(DG, Fr=v, speed_inner=1000.0),
    "highspeed speed": lambda v: highspeed.solve(AC, Fa=100.0, speed_inner=v),
    "shaft Fy (clearance)": lambda v: shaft.solve(
        SHAFT, [shaft.Seat(0.03, DG), shaft.Seat(0.23, DG, floating=True)],
        [shaft.PointLoad(0.09, Fy=v)]),
    "shaft Fa (angular contact)": lambda v: shaft.solve(
        SHAFT, [shaft.Seat(0.03, AC, direction=1), shaft.Seat(0.23, AC, direction=-1)],
        [shaft.PointLoad(0.09, Fa=v, Fy=1.0)]),
}


def _check_extreme_result(name, r, v):
    """The result of an extreme input is balanced (each kind by its own invariant)."""
    if isinstance(r, loaddist.LoadDistribution):
        # equilibrium only: the Hertz contacts of ball loads below 1e-30 N are refused
        # (MIN_MAGNITUDE of the contact formulas)
        check_distribution(DG if "clearance" in name or name == "radial" else AC, r,
                           downstream=bool(np.max(r.ball_loads) >= 1e-30))
    elif isinstance(r, duplex.DuplexResult):
        psi = r.pair.bearing.azimuths(0.0)
        fa = (r.ball_loads * np.sin(r.contact_angles)).sum(1)
        fr = (r.ball_loads * np.cos(r.contact_angles) * np.cos(psi)).sum(1)
        axial = fa.sum() - r.pair.preload if r.pair.arrangement == "DT" else fa[0] - fa[1]
        scale = max(abs(r.Fa), r.Fr, r.pair.preload, 1.0)
        assert abs(axial - r.Fa) <= 1e-9 * scale and abs(fr.sum() - r.Fr) <= 1e-9 * scale
    elif isinstance(r, highspeed.HighSpeedResult):
        assert r.relative_residual <= RTOL_EQ
        check_highspeed(r.bearing, r)
    elif isinstance(r, shaft.ShaftResult):
        applied = sum(p.vector for p in r.loads)
        scale = max(float(np.abs(applied[:3]).max()), 1e-300)
        assert np.all(np.abs(r.reactions.sum(0)[:3] - applied[:3]) <= 1e-7 * scale)
    else:                                         # axial_deflection: a deflection [m]
        assert np.isfinite(r) and r >= 0.0


@pytest.mark.timeout(120)
@pytest.mark.parametrize("v", [5e-324, 1e-300, 1e300])
@pytest.mark.parametrize("name", list(EXTREME_ENTRY_POINTS))
def test_extreme_magnitudes(name, v):
    """Subnormal, tiny and huge inputs: a balanced result, or a ValueError naming the
    allowed range / a ConvergenceError saying why, within 30 s."""
    t = time.perf_counter()
    try:
        r = EXTREME_ENTRY_POINTS[name](v)
    except ValueError as exc:
        assert re.search(r"physical magnitude|beyond the load-deflection range|must be >= 0",
                         str(exc)), str(exc)
    except ConvergenceError as exc:
        assert re.search(r"residual|round-off|too small|below", str(exc)), str(exc)
    else:
        _check_extreme_result(name, r, v)
    assert time.perf_counter() - t < 30.0

