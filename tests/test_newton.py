"""The Newton policy (ballrace.analytic.newton): its pieces on small problems with known
answers, the shape of the ConvergenceError every solver raises, and that the solvers take
their step control from it (no copies of its constants elsewhere)."""
import dataclasses
import pathlib
import re

import numpy as np
import pytest

import ballrace
from ballrace.analytic import duplex, highspeed, loaddist, newton
from ballrace.analytic import shaft as S
from ballrace.analytic.newton import POLICY
from ballrace.analytic.roller import RollerBearing, contact as RC, loaddist as RL
from ballrace.errors import ConvergenceError

ANALYTIC = pathlib.Path(loaddist.__file__).parent
EPS = np.finfo(float).eps
AC = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52, free_contact_angle=np.radians(40))
DG = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53, diametral_clearance=10e-6)
#: The cylindrical roller bearing of the public example (45 um clearance).
NU = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=45e-6)
ST = ballrace.BEARING_STEEL


def _damped_newton(f, jac, x, radius, rtol=1e-14, max_iter=50):
    """A damped Newton iteration built from the policy's pieces only (merit |f|^2 / 2)."""
    for it in range(max_iter):
        r = f(x)
        if np.abs(r).max() <= rtol:
            return x, it
        dx = -np.linalg.solve(jac(x), r)
        dx = dx * newton.clip_factor(float(np.abs(dx).max()), radius)
        m0, slope = 0.5 * r @ r, float(r @ jac(x) @ dx)
        t, ok = newton.backtrack_one(
            lambda t: newton.armijo_ok(0.5 * f(x + t * dx) @ f(x + t * dx), m0, t, slope),
            POLICY.residual_halvings)
        assert ok
        x = x + t * dx
    raise AssertionError("no convergence")


def test_policy_drives_a_1d_and_a_2d_system_to_their_roots():
    """x^3 = 8 from x = 10 (root 2, a trust radius of 1 clips the first steps) and the
    circle x^2 + y^2 = 4 cut by x = y from (3, 0.5) (root (sqrt 2, sqrt 2))."""
    x, it = _damped_newton(lambda x: np.array([x[0] ** 3 - 8.0]),
                           lambda x: np.array([[3.0 * x[0] ** 2]]), np.array([10.0]), 1.0)
    assert x[0] == pytest.approx(2.0, rel=1e-14) and it > 3
    x, _ = _damped_newton(lambda x: np.array([x[0] ** 2 + x[1] ** 2 - 4.0, x[0] - x[1]]),
                          lambda x: np.array([[2 * x[0], 2 * x[1]], [1.0, -1.0]]),
                          np.array([3.0, 0.5]), 0.5)
    assert x == pytest.approx([np.sqrt(2.0)] * 2, rel=1e-14)


def test_trust_radius_clips_a_step_exactly():
    """A step (3, -4) [m] against a radius of 1 m is scaled by exactly 1/4: its largest
    component becomes the radius; shorter steps are left alone (factor exactly 1)."""
    assert newton.trust_radius(2e-4) == 0.25 * 2e-4 == POLICY.trust_fraction * 2e-4
    step = np.array([3.0, -4.0])
    f = newton.clip_factor(float(np.abs(step).max()), 1.0)
    assert f == 0.25 and np.abs(step * f).max() == 1.0
    assert newton.clip_factor(0.5, 1.0) == 1.0
    # vectorised over cases (a zero step stays zero: factor 1)
    fv = newton.clip_factor(np.array([0.5, 4.0, 0.0]), 1.0)
    assert fv.tolist() == [1.0, 0.25, 1.0]


def test_levenberg_shift_is_the_larger_of_its_two_floors():
    """max(1e-12 |tr| / n, 1e-6 F / A): a trace of 5e13 N/m over 5 free directions gives
    10 N/m; with A = 1e-4 m the geometric term is 10 N/m for F = 1000 N (a tie) and
    30 N/m for F = 3000 N (it wins)."""
    mu = newton.levenberg_shift(np.array([5e13, 5e13]), np.array([1000.0, 3000.0]), 1e-4, 5)
    assert mu == pytest.approx([10.0, 30.0], rel=1e-14)
    one = newton.levenberg_shift_one(5e13, 5, 3000.0, POLICY.levenberg_geometric / 1e-4)
    assert one == pytest.approx(30.0, rel=1e-14)


def test_line_search_halves_k_times_on_a_known_merit():
    """phi(x) = x^4 from x = 1 along d = -8 (slope phi'(1) d = -32): the steps 1, 1/2 and
    1/4 land at x = -7, -3, -1 (phi 2401, 81, 1 > 1 - 1e-4 t 32), 1/8 at x = 0 is
    accepted: three halvings.  With only two allowed, the search ends unaccepted at 1/4."""
    phi = lambda x: x ** 4                                            # noqa: E731
    tried = []

    def accept(t):
        tried.append(t)
        return bool(newton.armijo_ok(phi(1.0 - 8.0 * t), 1.0, t, -32.0))

    assert newton.backtrack_one(accept, 40) == (0.125, True)
    assert tried == [1.0, 0.5, 0.25, 0.125]
    assert newton.backtrack_one(accept, 2) == (0.25, False)
    # the vectorised search: three cases, the second along d = -0.5 (full step accepted),
    # the third marked done beforehand (a case not searched)
    d = np.array([-8.0, -0.5, -8.0])

    def many(idx, t):
        return newton.armijo_ok(phi(1.0 + t * d[idx]), 1.0, t, 4.0 * d[idx])

    ok1 = np.array([False, bool(many(np.array([1]), np.ones(1))[0]), True])
    t, ok = newton.backtrack(many, ok1, 40)
    assert t.tolist() == [0.125, 1.0, 1.0] and ok.all()


def test_roundoff_floor_formula():
    """max(100 rtol, 20 eps u/delta), capped at max(1e-9, 100 rtol), 0 with no ball loaded."""
    assert newton.roundoff_cap(1e-12) == 1e-9
    assert newton.roundoff_cap(1e-6) == pytest.approx(1e-4, rel=1e-15)
    assert newton.roundoff_floor(1e-12, 1e-6, 1e-4) == pytest.approx(1e-10, rel=1e-15)
    assert newton.roundoff_floor(1e-12, 1e-9, 1e-4) == pytest.approx(20 * EPS * 1e5, rel=1e-15)
    assert newton.roundoff_floor(1e-12, 1e-12, 1e-4) == 1e-9
    assert newton.roundoff_floor(1e-12, 0.0, 1e-4) == 0.0
    v = newton.roundoff_floor(1e-12, np.array([1e-6, 1e-9, 0.0]), np.array([1e-4] * 3))
    assert v == pytest.approx([1e-10, 20 * EPS * 1e5, 0.0], rel=1e-15)
    assert newton.roundoff_limit(1e-4, 1e-9) == pytest.approx(20 * EPS * 1e5, rel=1e-15)
    assert newton.roundoff_limit(1e-4, 0.0) == np.inf
    assert newton.stalled(0.6, 1.0) and not newton.stalled(0.4, 1.0)


def test_best_iterate_is_kept_and_accepted_at_the_limit():
    """Cases 0..2 active at the iteration limit with best residuals 5e-10 (within the
    round-off cap 1e-9 at rtol 1e-12: takes its best iterate), 2e-9 and 1e-3 (stay)."""
    x = np.array([[1.0], [2.0], [3.0]])
    err = np.array([1e-3, 1e-2, 1.0])
    best_x, best_err = x.copy(), err.copy()
    newton.keep_best(best_x, best_err, np.arange(3), np.array([[10.0], [20.0], [30.0]]),
                     np.array([5e-10, 2e-9, 2.0]))
    assert best_x.ravel().tolist() == [10.0, 20.0, 3.0]
    left = newton.accept_best(np.arange(3), x, err, best_x, best_err, 1e-12)
    assert left.tolist() == [1, 2]
    assert x.ravel().tolist() == [10.0, 2.0, 3.0] and err[0] == 5e-10


def test_error_message_shape():
    e = newton.convergence_error("shaft equilibrium", 12, 3.5e-4, 1e-10, best=2e-4,
                                 newton=True, steps=" over all load steps",
                                 context="in load case 1", roundoff=1e-3,
                                 roundoff_hint="tiny loads")
    assert isinstance(e, ConvergenceError)
    assert str(e) == ("shaft equilibrium did not converge after 12 Newton iterations over all "
                      "load steps: relative residual 3.500e-04 (best 2.000e-04; > rtol=1e-10) "
                      "in load case 1 (round-off limit here ~1.0e-03: tiny loads)")
    # the round-off hint only where round-off is within a factor 10 of the best residual
    assert "round-off" not in str(newton.convergence_error("x", 1, 1.0, 1e-9, roundoff=1e-3))


SHAPE = r"^{} did not converge after \d+ {}iterations{}: {} \S+ \((best \S+; )?> rtol=\S+\)"


def test_every_solver_raises_the_same_shape():
    with pytest.raises(ConvergenceError) as e:
        loaddist.solve(AC, Fa=[100.0, 5.0], Fy=[3000.0, 5000.0], max_iter=2)
    assert re.match(SHAPE.format("load distribution", "", "", "relative equilibrium residual"),
                    str(e.value))
    with pytest.raises(ConvergenceError) as e:
        S.solve(S.Shaft([(0.26, 45e-3, 0.0)], ballrace.BEARING_STEEL),
                [S.Seat(0.03, DG), S.Seat(0.23, DG)], [S.PointLoad(0.09, Fy=5000.0)],
                max_iter=1)
    assert re.match(SHAPE.format("shaft equilibrium", "Newton ", " over all load steps",
                                 "relative residual"), str(e.value))
    with pytest.raises(ConvergenceError) as e:
        duplex.DuplexPair(AC, "DB", preload=2000.0).solve(Fa=1000.0, Fr=3000.0, max_iter=1)
    assert re.match(SHAPE.format("duplex pair equilibrium", "", "", "relative residual"),
                    str(e.value))
    with pytest.raises(ConvergenceError) as e:
        highspeed.solve(AC, Fa=1000.0, Fr=500.0, rtol=1e-300)
    assert re.match(SHAPE.format(r"high-speed equilibrium \(zero speed\)", "Newton ", "",
                                 "scaled residual"), str(e.value))
    with pytest.raises(ConvergenceError) as e:
        NU.solve(Fy=6940.0, max_iter=1)
    assert re.match(SHAPE.format("roller load distribution", "", "",
                                 "relative equilibrium residual"), str(e.value))


def test_line_contact_raises_the_same_shape(monkeypatch):
    """The finite line contact's Newton (iterations a module constant) after one step."""
    monkeypatch.setattr(RC, "MAX_ITERATIONS", 1)
    with pytest.raises(ConvergenceError) as e:
        RC.line_contact(5000.0, 0.006, 0.03, 0.012, ST, ST, profile="iso", tilt=5e-4)
    assert re.match(SHAPE.format("finite line contact", "Newton ", "",
                                 "contact residual relative to the approach"), str(e.value))
    assert "at Q = 5000 N on 41 slices" in str(e.value)


#: What the solvers had as their own copies of the policy (names and formulas).
OLD = [r"\b_FLOOR_CAP\b", r"\b_EPS20\b", r"def _floor\b", r"0\.25 \* (model\.A|pb\.A_ref)",
       r"1e-4 \* t\b", r"\(1\.0 - 1e-4", r"20\.0 \* (np\.finfo|eps)", r"1e-6 / model\.A",
       r"1e-12 \* (tr|abs)", r"0\.05 \* (sysm\.m\.D|A \+)", r"err\[a\] < 1e-6|err < 1e-6"]


#: What the roller solvers had as their own copies (the lamina load distribution's trust
#: radius, Levenberg floor, Armijo constant and halvings, quadratic region, stall ratio,
#: round-off cap and message; the line contact's penetration cap, returned-residual limit
#: and message).
OLD_ROLLER = [r"max\([^)]*100\.?0? \* rtol", r"1e-6 \* scale", r"0\.01\) \* case",
              r"0\.01 \* (case\.)?model\.D", r"1e-4 \* float", r"err >= 1e-6",
              r"\bt \*= 0\.5", r"0\.5 \* prev", r"PENETRATION = 1e-9", r"10 \* TOLERANCE",
              r"ConvergenceError\(\s*f?\"(roller load distribution|the finite line contact) "
              r"did not converge"]


@pytest.mark.parametrize("module, imports", [
    ("loaddist", "from .newton import POLICY"), ("shaft", "from .newton import POLICY"),
    ("highspeed", "from .newton import POLICY"), ("duplex", "from .newton import POLICY"),
    ("roller/loaddist", "from ..newton import POLICY"),
    ("roller/contact", "from .. import newton")])
def test_solvers_define_no_step_control_of_their_own(module, imports):
    src = (ANALYTIC / f"{module}.py").read_text()
    for pat in OLD + (OLD_ROLLER if module.startswith("roller/") else []):
        assert not re.search(pat, src), f"{module}.py: {pat}"
    assert imports in src


def test_roller_load_distribution_takes_its_trust_radius_from_the_policy(monkeypatch):
    """A trust radius of 1e-4 D_we (1.3 um) instead of POLICY.roller_step = 0.01 D_we
    (130 um) needs more steps to the equilibrium (a radial deflection of 41.8 um at 45 um
    clearance; the first step, which closes the gap, is not limited by it) and reaches the
    same equilibrium: the driver reads its trust radius from the policy."""
    r0 = NU.solve(Fy=6940.0)
    monkeypatch.setattr(RL, "POLICY", dataclasses.replace(POLICY, roller_step=1e-4))
    r1 = NU.solve(Fy=6940.0)
    assert r1.iterations > r0.iterations
    assert r1.displacements == pytest.approx(r0.displacements, rel=1e-9, abs=1e-15)


def test_roller_solvers_accept_the_best_iterate_at_round_off():
    """rtol = 1e-300 cannot be reached: the lamina load distribution stops at the policy's
    round-off floor, and, limited to the 5 iterations the default rtol needs, accepts its
    best iterate (within the round-off cap 1e-9) at the limit; both agree with the default
    solve to 1e-9."""
    r0 = NU.solve(Fy=6940.0)
    assert r0.iterations == 5
    floor = NU.solve(Fy=6940.0, rtol=1e-300)
    limit = NU.solve(Fy=6940.0, rtol=1e-300, max_iter=5)
    assert limit.iterations == 5 and floor.iterations < 100
    for r in (floor, limit):
        assert r.relative_residual <= newton.roundoff_cap(1e-300) == 1e-9
        assert r.displacements == pytest.approx(r0.displacements, rel=1e-9, abs=1e-15)
    with pytest.raises(ConvergenceError, match="best"):
        NU.solve(Fy=6940.0, rtol=1e-300, max_iter=4)


def test_line_contact_accepts_the_best_iterate_at_round_off(monkeypatch):
    """With a tolerance of 1e-300 (unreachable) the line contact's Newton runs to its
    iteration limit and returns its best iterate (residual within PENETRATION, the
    policy's round-off cap at TOLERANCE): the default solution to 1e-12, its load to
    rounding."""
    assert RC.PENETRATION == newton.roundoff_cap(RC.TOLERANCE) == 1e-9
    args = (5000.0, 0.006, 0.03, 0.012, ST, ST)
    c0 = RC.line_contact(*args, profile="iso", tilt=5e-4)
    monkeypatch.setattr(RC, "TOLERANCE", 1e-300)
    monkeypatch.setattr(RC, "MAX_ITERATIONS", 8)
    c = RC.line_contact(*args, profile="iso", tilt=5e-4)
    assert c.iterations == 8 and c0.iterations < 8
    assert c.pressure == pytest.approx(c0.pressure, rel=1e-12, abs=1e-12 * c0.max_pressure)
    assert c.slice_loads.sum() == pytest.approx(5000.0, rel=1e-14)


_N = r"([0-9.]+(?:e-?[0-9]+)?)"
#: Where each constant of the policy stands in the compiled Newton (analytic/_ldkernel.c).
KERNEL_CONSTANTS = [
    (rf"step_max = {_N} \* g->A", "trust_fraction"),
    (rf"lev = {_N} / g->A", "levenberg_geometric"),
    (rf"eps20 = {_N} \* DBL_EPSILON", "roundoff_factor"),
    (rf"cap = {_N} \* rtol > ", "floor_rtol"),
    (rf"rtol : {_N};", "floor_cap"),
    (rf"mu = {_N} \* fabs\(tr\)", "levenberg_trace"),
    (rf"local = err < {_N};", "quadratic_region"),
    (rf"k < {_N}; k\+\+\) {{\s*t \*= 0.5", "potential_halvings"),
    (rf"local \? 0 : {_N}", "residual_halvings"),
    (rf"phi0 \+ {_N} \* gslope", "armijo"),
    (rf"phi0 \+ {_N} \* t \* gslope", "armijo"),
    (rf"en > {_N} \* err", "stall_ratio"),
    (rf"fl < {_N} \* rtol", "floor_rtol"),
]


@pytest.mark.parametrize("pattern, name", KERNEL_CONSTANTS)
def test_compiled_kernel_constants_are_the_policys(pattern, name):
    """The compiled Newton (analytic/_ldkernel.c) cannot call Python: its compiled-in
    constants must be the policy's."""
    m = re.search(pattern, (ANALYTIC / "_ldkernel.c").read_text())
    assert m, pattern
    assert float(m.group(1)) == getattr(POLICY, name)


def test_policy_is_frozen():
    with pytest.raises(AttributeError):
        POLICY.armijo = 0.1
