"""Fast paths give the same answers as the general ones.

* One contact of plain numbers (``hertz.point_contact`` / ``elliptical_contact`` with
  floats), and each contact of an array of up to ``hertz._SMALL``, runs a scalar path:
  bit-for-bit the vectorised kernel's result (same operations in the same order; IEEE
  double arithmetic is the same in Python and NumPy).
* The piecewise-polynomial ellipticity (``hertz._solve_k``) against the Newton solution
  it was built from, and against the 30-digit mpmath reference (tests/mpref.py).
* The single-case load-distribution driver against the vectorized one, and the
  analytic ring stiffness against central differences of the ring forces.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import hertz
from fdref import central_jacobian, in_force_units
from mpref import k_exact

STEEL = ballrace.Material(E=200e9, nu=0.3)
FIELDS = ("load", "Rx", "Ry", "E_prime", "k", "a", "b", "approach", "p_max", "stiffness",
          "ellipk", "ellipe")

radius = st.floats(1e-4, 1.0)
signed_ratio = st.one_of(st.floats(-0.999, -1e-3), st.floats(1e-3, 0.999))
load = st.one_of(st.just(0.0), st.floats(1e-3, 1e6))


def _same(c_scalar, c_array):
    for f in FIELDS:
        s, a = getattr(c_scalar, f), getattr(c_array, f)
        assert np.shape(s) == () and type(s) is np.float64, f
        assert a.shape == (N_KERNEL,)
        assert np.all(s == a), (f, s, a[0])     # bit for bit


# arrays above hertz._SMALL contacts run the vectorised kernel (smaller ones the scalar
# path contact by contact): the scalar path is compared with the kernel
N_KERNEL = hertz._SMALL + 3


def _rep(x):
    return np.full(N_KERNEL, x)


@settings(max_examples=300, deadline=None)
@given(Q=load, Rx=st.floats(1e-5, 10.0), ratio=st.floats(-7.99, 7.99),
       Ep=st.floats(1e9, 1e12))
def test_elliptical_contact_scalar_equals_array(Q, Rx, ratio, Ep):
    Ry = Rx * 10.0**ratio
    _same(hertz.elliptical_contact(Q, Rx, Ry, Ep),
          hertz.elliptical_contact(_rep(Q), _rep(Rx), _rep(Ry), Ep))


@pytest.mark.filterwarnings("ignore:point_contact. a / R:UserWarning")   # any size here
@settings(max_examples=300, deadline=None)
@given(Q=load, r1=radius, r2=radius, g1=signed_ratio, g2=signed_ratio,
       flat=st.booleans())
def test_point_contact_scalar_equals_array(Q, r1, r2, g1, g2, flat):
    # body 1 convex (r1, r2); body 2 concave or convex, less curved (|g| < 1), or flat
    rx2 = np.inf if flat else r1 / g1
    ry2 = r2 / g2
    c_s = hertz.point_contact(Q, r1, r2, rx2, ry2, STEEL)
    c_a = hertz.point_contact(_rep(Q), r1, r2, rx2, ry2, STEEL)
    _same(c_s, c_a)


def test_scalar_path_keeps_the_checks():
    # the fast path hands odd or out-of-range input to the array path and its errors
    with pytest.raises(ValueError, match="load must be >= 0"):
        hertz.point_contact(-1.0, 0.01, 0.01, 0.01, 0.01, STEEL)
    with pytest.raises(ValueError, match="rx1 must be non-zero"):
        hertz.point_contact(1.0, 0.0, 0.01, 0.01, 0.01, STEEL)
    with pytest.raises(ValueError, match="curvature sum in the y plane"):
        hertz.point_contact(1.0, 0.01, 0.01, 0.02, -0.01, STEEL)
    with pytest.raises(ValueError, match="radius ratio"):
        hertz.elliptical_contact(1.0, 1e-5, 1e4, 2e11)
    with pytest.raises(ValueError, match="E_prime must be finite; got nan"):
        hertz.elliptical_contact(1.0, 0.01, 0.02, float("nan"))
    with pytest.raises(TypeError):
        hertz.elliptical_contact(True, 0.01, 0.02, 2e11)


@settings(max_examples=200, deadline=None)
@given(v=st.floats(0.0, np.log(1e8)))
def test_tabulated_ellipticity_equals_newton(v):
    alpha = np.array([np.exp(v)])
    k, K, E = hertz._solve_k(alpha)
    kn, Kn, En = hertz._solve_k_newton(alpha)
    assert k[0] == pytest.approx(kn[0], rel=5e-15)
    assert K[0] == pytest.approx(Kn[0], rel=5e-15) and E[0] == pytest.approx(En[0], rel=5e-15)
    assert hertz._solve_k_scalar(float(alpha[0])) == (k[0], K[0], E[0])


@pytest.mark.parametrize("alpha", [1.0, 1.0 + 2**-40, 1.0 + 2**-8, 1.0 + 2**-8 - 2**-52, 1.04,
                                   1.3, 2.0 - 2**-45, 7.5, 1e3, 99999.9, 1e8])
def test_tabulated_ellipticity_at_interval_edges_matches_mpmath(alpha):
    # 30-digit mpmath reference at the circle, the tables' interval edges (1 + 2^-8 is the
    # second interval's start) and the range's end
    k, _, _ = hertz._solve_k(np.array([alpha]))
    assert k[0] == pytest.approx(k_exact(alpha), rel=5e-15, abs=0)


# --------------------------------------------------------------------------- load distribution
def _ricci218():
    return ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
                                free_contact_angle=np.radians(40), material=STEEL)


@pytest.mark.parametrize("arm", ["groove", "contact"])
def test_ring_forces_stiffness_is_the_derivative(arm):
    # central differences of F(u) (step 1e-9 m / 1e-8 rad; truncation ~1e-10 relative)
    from ballrace.analytic import loaddist
    brg = _ricci218()
    r = loaddist.solve(brg, Fa=17800.0, Fy=8900.0, Mz=-200.0, moment_arm=arm)
    F, K = loaddist.ring_forces(brg, r.displacements, moment_arm=arm)
    assert np.array_equal(F, r.loads) and np.array_equal(K, r.stiffness)
    fd = central_jacobian(lambda u: loaddist.ring_forces(brg, u, moment_arm=arm)[0],
                          r.displacements, np.array([1e-9, 1e-9, 1e-9, 1e-8, 1e-8]))
    Ks, fds = in_force_units(K, brg), in_force_units(fd, brg)
    assert np.max(np.abs(Ks - fds)) < 1e-8 * np.max(np.abs(Ks))


@settings(max_examples=60, deadline=None)
@given(u=st.tuples(st.floats(-3e-5, 8e-5), st.floats(-5e-5, 5e-5), st.floats(-5e-5, 5e-5),
                   st.floats(-1e-3, 1e-3), st.floats(-1e-3, 1e-3)),
       arm=st.sampled_from(["groove", "contact"]))
def test_ring_forces_one_case_equals_batch(u, arm):
    # one displacement runs the one-case kernel (_State._one), several the batch kernel
    from ballrace.analytic import loaddist
    brg = _ricci218()
    u = np.array(u)
    F1, K1 = loaddist.ring_forces(brg, u, moment_arm=arm)
    Fb, Kb = loaddist.ring_forces(brg, np.stack([u, 0.5 * u]), moment_arm=arm)
    scale = max(np.abs(F1).max(), 1.0)
    assert np.allclose(F1, Fb[0], rtol=1e-12, atol=1e-12 * scale)
    # A ball just touching (delta -> 0) has dQ/ddelta = 1.5 K_n delta^(1/2): rounding delta
    # by ~1e-16 A moves its stiffness by ~1.5 K_n (1e-16 A)^(1/2), about 1e-9 of the ring's
    # K for the 218 bearing (hypothesis found 1.2e-9 at u = (0, 5e-5, 5e-5, 0, 0)); the
    # two kernels round in different orders, so they agree to that, not to 1e-12.
    assert np.allclose(K1, Kb[0], rtol=1e-11, atol=1e-8 * max(np.abs(K1).max(), 1.0))


def test_lapack_small_solver_matches_numpy():
    # the one-case Newton solves its 5 x 5 systems by LAPACK gesv on nested lists
    from ballrace.analytic.loaddist import _gesv
    rng = np.random.default_rng(5)
    for _ in range(50):
        A = rng.normal(size=(5, 5)) + 5 * np.eye(5) * rng.uniform(0, 1)
        b = rng.normal(size=5)
        x = _gesv(A.tolist(), b.tolist())
        assert type(x) is list and np.allclose(x, np.linalg.solve(A, b), rtol=1e-10, atol=1e-12)
    with pytest.raises(np.linalg.LinAlgError):
        _gesv([[1.0, 2.0], [2.0, 4.0]], [1.0, 1.0])
    with pytest.raises(np.linalg.LinAlgError):
        _gesv([[1.0, 0.0], [0.0, np.nan]], [1.0, 1.0])


def test_blocked_vectorised_contact_equals_small_arrays():
    # arrays above two blocks run the in-place block kernel (_exact_block), small ones the
    # plain array path: the same operations, so the same bits (zero loads and a circle too)
    rng = np.random.default_rng(11)
    n = 3 * hertz._BLOCK + 123
    Rx = 10 ** rng.uniform(-3, -1, n)
    Ry = Rx * 10 ** rng.uniform(-4, 4, n)
    Q = 10 ** rng.uniform(0, 5, n)
    Q[::9] = 0.0
    Ry[5] = Rx[5]
    big = hertz.elliptical_contact(Q, Rx, Ry, 2.1e11)
    for i in range(0, n, 5000):
        sl = slice(i, i + 5000)
        small = hertz.elliptical_contact(Q[sl], Rx[sl], Ry[sl], 2.1e11)
        for f in FIELDS:
            assert np.array_equal(getattr(big, f)[sl], getattr(small, f)), f


# --------------------------------------------------------------------------- one-case solve
def _bearing209():
    return ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, diametral_clearance=20e-6,
                                material=STEEL)


def _load(lo, hi):
    # 0 or a magnitude in [lo, hi] of either sign (far lighter loads in a bearing with
    # clearance are the documented slow/ConvergenceError range, see test_loaddist.py)
    return st.one_of(st.just(0.0), st.floats(lo, hi), st.floats(-hi, -lo))


@settings(max_examples=40, deadline=None)
@given(f=st.tuples(*[_load(1.0, 3e3) for _ in range(3)], *[_load(0.01, 30.0) for _ in range(2)]),
       arm=st.sampled_from(["groove", "contact"]), ricci=st.booleans())
def test_one_case_result_equals_general_result(f, arm, ricci):
    # the one-case driver returns its kernel's floats (_result_one); the general _result
    # recomputes the state from the displacements with the array kernel: the same loads
    # to 1e-12 of the load scale, ball loads to 1e-12 of Q_max, angles to 1e-12 rad
    from ballrace.analytic import loaddist
    brg = _ricci218() if ricci else _bearing209()
    try:
        r = loaddist.solve(brg, *f, moment_arm=arm)
    except ValueError:
        return                                # beyond the model's range: nothing to compare
    model = loaddist._Model.of(brg)
    Pd, x0, z0 = loaddist._reference(model, None, False)
    u = r.displacements[None]
    g = loaddist._result(brg, model, r.azimuths, x0, z0, Pd, u, r.applied[None],
                         r.imposed[None], arm, np.array([r.iterations]), (), "exact")
    scale = max(np.abs(r.applied).max(), r.max_ball_load, 1e-300)
    assert np.allclose(r.loads, g.loads, rtol=0, atol=1e-12 * scale * 0.1)
    assert np.allclose(r.ball_loads, g.ball_loads, rtol=0,
                       atol=1e-12 * max(r.max_ball_load, 1e-300))
    assert np.allclose(r.contact_angles, g.contact_angles, rtol=0, atol=1e-12)
    assert np.allclose(r.stiffness, g.stiffness, rtol=1e-11,
                       atol=1e-8 * max(np.abs(g.stiffness).max(), 1.0))
    assert r.relative_residual < 1e-9 and r.iterations == g.iterations


@settings(max_examples=200, deadline=None)
@given(D=st.floats(1e-3, 0.03), ratio=st.floats(1.2, 8.0), zf=st.floats(0.0, 1.0),
       fi=st.floats(0.505, 0.56), bf=st.floats(0.0, 1.5), load=st.floats(-14.0, 0.0),
       ecc=st.floats(0.0, 0.999))
def test_eccentric_start_float_equals_array(D, ratio, zf, fi, bf, load, ecc):
    # the plain-number path of eccentric_thrust starts from _eccentric_start_one: the same
    # operations on floats as the array start (here on a 0-d array), so the same bits
    from ballrace.analytic import loaddist
    dm = D * ratio
    Z = 3 + int(zf * (int(np.floor(np.pi / np.arcsin(1.0 / ratio))) - 3))
    brg = ballrace.BallBearing(D, Z, dm, fi, fi, free_contact_angle=bf)
    m = loaddist._Model.of(brg)
    Fa, e = m.capacity * 10.0**load, ecc * 0.5 * dm
    one = loaddist._eccentric_start_one(m, Fa, e)
    arr = loaddist._eccentric_start(m, np.array(Fa), np.array(e))
    assert np.array_equal(one, arr)


def test_eccentric_thrust_float_path_equals_array_path():
    # plain numbers take the float path (no array checks), 0-d arrays the array path
    from ballrace.analytic import loaddist
    brg = _ricci218()
    for Fa, e in ((17800.0, 50.8e-3), (100.0, 0.0), (5000.0, 0.03), (17800.0, 0.06)):
        a = loaddist.eccentric_thrust(brg, Fa, e)
        b = loaddist.eccentric_thrust(brg, np.array(Fa), np.array(e))
        assert np.array_equal(a.ball_loads, b.ball_loads)
        assert np.array_equal(a.stiffness, b.stiffness)
    # the float path keeps every check of the array path
    for Fa, e, exc, msg in ((-1.0, 0.01, ValueError, "Fa must be >= 0"),
                            (1.0, -0.01, ValueError, "e must be >= 0"),
                            (float("nan"), 0.01, ValueError, "Fa must be finite"),
                            (1.0, float("inf"), ValueError, "e must be finite"),
                            (1e31, 0.01, ValueError, "Fa must have a physical magnitude"),
                            (1.0, 0.5 * brg.pitch_diameter, ValueError, "beyond what the thrust"),
                            (1e9, 0.01, ValueError, "beyond the load-deflection range"),
                            (True, 0.01, TypeError, "Fa")):
        with pytest.raises(exc, match=msg):
            loaddist.eccentric_thrust(brg, Fa, e)


def test_one_case_driver_seated_start_and_checks():
    # from the touching reference the first step is the line minimiser of the linearised
    # potential; the answer is the vectorised driver's (same equilibrium to 1e-12), and the
    # checks on what is returned still run (a NaN-free, balanced, in-range result)
    from ballrace.analytic import loaddist
    brg = _bearing209()
    r1 = brg.solve(Fa=1000.0, Fy=3000.0)
    r2 = brg.solve(Fa=[1000.0, 1000.0], Fy=3000.0)
    assert np.allclose(r1.ball_loads, r2.ball_loads[0], rtol=0, atol=1e-10 * r1.max_ball_load)
    assert r1.relative_residual < 1e-12 and r2.relative_residual[0] < 1e-12
    with pytest.raises(ValueError, match="beyond the load-deflection range"):
        brg.solve(Fa=1e9)
    with pytest.raises(loaddist.ConvergenceError, match="did not converge after 2 iterations"):
        brg.solve(Fa=1000.0, Fy=3000.0, max_iter=2)


@pytest.mark.parametrize("arm", ["groove", "contact"])
def test_one_case_kernel_stiffness_is_exact_hertz(arm):
    # the kernel's K_n is the table's (the batch kernel's _kn) and so exact Hertz to 1e-13
    from ballrace.analytic import loaddist
    brg = _ricci218()
    r = loaddist.solve(brg, Fa=17800.0, Fy=8900.0, Mz=-200.0, moment_arm=arm)
    model = loaddist._Model.of(brg)
    _, x0, z0 = loaddist._reference(model, None, False)
    geo = loaddist._geo(model, brg, 0.0, x0, z0)
    o = loaddist._one_case(model, geo, r.displacements.tolist(), arm)
    beta = np.arctan2(o.z, o.x)
    Kb, db = loaddist._kn(model, beta)
    Kx, dx = loaddist._kn_exact(model, beta)
    assert np.allclose(o.Kn, Kb, rtol=1e-15, atol=0) and np.allclose(o.dlnK, db, rtol=1e-13,
                                                                       atol=1e-15)
    assert np.allclose(o.Kn, Kx, rtol=1e-13, atol=0)
    assert np.allclose(o.dlnK, dx, rtol=0, atol=loaddist._TABLE_DTOL * np.abs(dx).max())


# --------------------------------------------------------------------------- compiled Newton
# The optional compiled iteration (analytic/_ldkernel.c) only proposes the equilibrium of
# one load case: loaddist evaluates its NumPy kernel there and iterates on if the residual
# is above rtol.  Tests that need the compiled module skip without it; the NumPy iteration
# is tested with it switched off (the ``numpy_only`` fixture), so both paths are covered
# whichever is installed.
def _compiled():
    from ballrace.analytic import loaddist
    return loaddist._COMPILED


needs_compiled = pytest.mark.skipif(
    _compiled() is None, reason="the optional compiled kernel is not built (no C compiler "
                                "at install time) or is switched off (BALLRACE_NO_COMPILED)")


@pytest.fixture
def numpy_only(monkeypatch):
    from ballrace.analytic import loaddist
    monkeypatch.setattr(loaddist, "_COMPILED", None)


def _solve_both(brg, monkeypatch, **kw):
    """(compiled result or exception, NumPy-only result or exception)."""
    from ballrace.analytic import loaddist
    out = []
    for c in (loaddist._COMPILED, None):
        monkeypatch.setattr(loaddist, "_COMPILED", c)
        try:
            out.append(loaddist.solve(brg, **kw))
        except (ValueError, loaddist.ConvergenceError) as exc:
            out.append(exc)
    return out


@st.composite
def _bearing_and_loads(draw):
    D = draw(st.floats(2e-3, 40e-3))
    dm = D * draw(st.floats(1.5, 12.0))
    Z = draw(st.integers(3, min(int(np.floor(np.pi / np.arcsin(D / dm))), 40)))
    fi, fo = draw(st.floats(0.505, 0.6)), draw(st.floats(0.505, 0.6))
    if draw(st.booleans()):
        brg = ballrace.BallBearing(D, Z, dm, fi, fo, free_contact_angle=np.radians(
            draw(st.floats(0.0, 60.0))), material=STEEL)
    else:
        brg = ballrace.BallBearing(D, Z, dm, fi, fo, material=STEEL, diametral_clearance=draw(
            st.floats(0.0, 1.0)) * 1e-3 * D)
    Fref = Z * float(brg.contact_stiffness(brg.free_contact_angle)[2]) * (0.01 * D) ** 1.5
    f = [draw(st.sampled_from([0.0, 1.0])) * draw(st.sampled_from([-1.0, 1.0]))
         * 10 ** draw(st.floats(-3.0, np.log10(3.0))) * Fref for _ in range(5)]
    f[0] = abs(f[0]) if draw(st.booleans()) else f[0]
    return brg, dict(zip(("Fa", "Fy", "Fz", "My", "Mz"), (f[0], f[1], f[2], f[3] * dm / 2,
                                                        f[4] * dm / 2)))


@needs_compiled
@settings(max_examples=80, deadline=None)
@given(case=_bearing_and_loads(), arm=st.sampled_from(["groove", "contact"]))
def test_compiled_newton_equals_numpy_newton(case, arm):
    # the same equilibrium through both one-case iterations: the same refusals, ball loads
    # to 1e-9 of Q_max (as the one-case and vectorized drivers), both balanced to rtol
    brg, loads = case
    with pytest.MonkeyPatch.context() as mp:           # hypothesis: no function fixtures
        rc, rn = _solve_both(brg, mp, moment_arm=arm, **loads)
    if isinstance(rn, Exception) or isinstance(rc, Exception):
        assert type(rc) is type(rn), (rc, rn)
        return
    assert np.allclose(rc.ball_loads, rn.ball_loads, rtol=0,
                       atol=1e-9 * max(rn.max_ball_load, 1e-300))
    assert np.allclose(rc.contact_angles[rn.ball_loads > 0], rn.contact_angles[rn.ball_loads > 0],
                       rtol=0, atol=1e-9)
    assert rc.relative_residual <= 1e-12 or rc.relative_residual <= rn.relative_residual * 10
    assert abs(rc.iterations - rn.iterations) <= 3


@needs_compiled
def test_compiled_newton_runs_the_numpy_kernel_once(monkeypatch):
    # the 9-ball radial + axial case of `make bench`: the compiled iteration converges
    # (status 0) and the NumPy kernel runs once, to check it; without the compiled module
    # the NumPy iteration takes 7 steps (8 kernel evaluations, one a rejected trial step)
    from ballrace.analytic import loaddist
    calls, status = [], []
    kernel, compiled = loaddist._one_case, loaddist._COMPILED

    class Spy:
        def newton_one(self, *a):
            r = compiled.newton_one(*a)
            status.append(r[0])
            return r

    monkeypatch.setattr(loaddist, "_one_case", lambda *a: calls.append(1) or kernel(*a))
    monkeypatch.setattr(loaddist, "_COMPILED", Spy())
    rc = _bearing209().solve(Fa=1000.0, Fy=3000.0)
    assert status == [0] and len(calls) == 1 and rc.relative_residual < 1e-12
    calls.clear()
    monkeypatch.setattr(loaddist, "_COMPILED", None)
    rn = _bearing209().solve(Fa=1000.0, Fy=3000.0)
    assert len(calls) == 8 and rn.iterations == 7 and rc.iterations == rn.iterations
    assert np.allclose(rc.ball_loads, rn.ball_loads, rtol=0, atol=1e-10 * rn.max_ball_load)


@needs_compiled
def test_compiled_newton_statuses():
    # 1: not converged within max_iter; 2: a case it leaves to loaddist (here a start with
    # a ball pressed beyond 90 deg, cos(beta) < 0); a malformed buffer is an error
    from ballrace.analytic import loaddist
    brg = _bearing209()
    model = loaddist._Model.of(brg)
    _, x0, z0 = loaddist._reference(model, None, False)
    geo = loaddist._geo(model, brg, 0.0, x0, z0)
    pack = loaddist._compiled_pack(model, geo)
    F, free = [1000.0, 3000.0, 0.0, 0.0, 0.0], [0.0] * 5
    status, it, u = loaddist._COMPILED.newton_one(pack, F, free, [0.0] * 5, 1e-12, 200, True, False)
    assert status == 0 and 5 <= it <= 10
    r = brg.solve(Fa=1000.0, Fy=3000.0)
    assert np.allclose(u, r.displacements, rtol=1e-9, atol=0)
    assert loaddist._COMPILED.newton_one(pack, F, free, [0.0] * 5, 1e-12, 2, True, False)[:2] == (1, 2)
    far = [0.0, -2.0 * model.A, 0.0, 0.0, 0.0]
    assert loaddist._COMPILED.newton_one(pack, F, free, far, 1e-12, 200, False, False)[0] == 2
    r2 = brg.solve(Fa=1000.0, Fy=3000.0, initial=[0.0, -0.9 * model.D, 0.0, 0.0, 0.0])
    assert np.allclose(r2.ball_loads, r.ball_loads, rtol=0, atol=1e-9 * r.max_ball_load)
    with pytest.raises(ValueError, match="inconsistent buffer size"):
        loaddist._COMPILED.newton_one(pack[:-1], F, free, [0.0] * 5, 1e-12, 200, True, False)


def test_numpy_newton_without_the_compiled_module(numpy_only):
    # the NumPy iteration alone: the same checks and answers (what users without a C
    # compiler at install time get)
    from ballrace.analytic import loaddist
    assert loaddist._COMPILED is None
    brg = _bearing209()
    r = brg.solve(Fa=1000.0, Fy=3000.0)
    assert r.relative_residual < 1e-12 and r.iterations == 7
    with pytest.raises(loaddist.ConvergenceError, match="did not converge after 2 iterations"):
        brg.solve(Fa=1000.0, Fy=3000.0, max_iter=2)


def test_environment_switches_the_compiled_module_off():
    import os
    import subprocess
    import sys
    code = ("from ballrace.analytic import loaddist; import ballrace; "
            "print(loaddist._COMPILED is None, ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, "
            "0.52, diametral_clearance=20e-6).solve(Fa=1000.0, Fy=3000.0).iterations)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ, BALLRACE_NO_COMPILED="1"), check=True)
    assert out.stdout.split() == ["True", "7"]
