"""The step control of ballrace's Newton iterations, in one place.

Every equilibrium solver of the package is a damped Newton iteration: the load
distribution of one bearing (:mod:`~ballrace.analytic.loaddist`, vectorised over load
cases, on one case, and in the optional compiled kernel ``analytic/_ldkernel.c``), the
shaft system (:mod:`~ballrace.analytic.shaft`), the quasi-static high-speed bearing
(:mod:`~ballrace.analytic.highspeed`), the duplex pair (:mod:`~ballrace.analytic.duplex`),
the lamina load distribution of a roller bearing
(:mod:`~ballrace.analytic.roller.loaddist`) and the finite line contact of a roller
(:mod:`~ballrace.analytic.roller.contact`, Newton on an active set of slices).  They share one policy: a trust radius on the step, a
Levenberg shift for unloaded directions, a backtracking line search with the Armijo
constant, a round-off floor below which the residual is not resolved, the best iterate
kept for when the iteration limit is reached, and one shape of the
:class:`~ballrace.errors.ConvergenceError` message.  The constants are the fields of
:class:`NewtonPolicy` (:data:`POLICY` is the one the solvers use); the pieces are plain
functions, vectorised over load cases where the load distribution needs it, with a
scalar twin where the single-case path runs on Python floats (both give the same
floating-point numbers as the formulas they replaced, operation for operation).

References
----------
Dennis & Schnabel, *Numerical Methods for Unconstrained Optimization and Nonlinear
Equations*, 1983, §6.3 (backtracking with the Armijo condition, alpha = 1e-4) and §6.4
(trust regions); Nocedal & Wright, *Numerical Optimization*, 2nd ed., 2006, §3.1 (the
sufficient-decrease constant) and §10.3 (Levenberg-Marquardt).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError

__all__ = ["NewtonPolicy", "POLICY", "trust_radius", "clip_factor", "levenberg_shift",
           "levenberg_shift_one", "armijo_ok", "backtrack", "backtrack_one", "roundoff_cap",
           "roundoff_limit", "roundoff_floor", "stalled", "keep_best", "accept_best",
           "convergence_error"]

_EPS = float(np.finfo(float).eps)


@dataclass(frozen=True)
class NewtonPolicy:
    """The constants of the damped Newton iterations (frozen).

    Attributes
    ----------
    trust_fraction : float
        Trust radius of a bearing's Newton step as a fraction of the groove curvature-centre
        distance A [-] (0.25: a step may move a ring by a quarter of A, the scale on which
        a ball's contact angle changes by tens of degrees; longer steps jump between
        basins).  Applied to the largest scaled component (translations [m], tilts times
        the inner-groove radius).
    levenberg_trace : float
        Levenberg shift as a fraction of the mean diagonal of the scaled tangent stiffness
        [-] (1e-12: regularises a singular tangent without changing a loaded one).
    levenberg_geometric : float
        Levenberg shift as a fraction of the geometric stiffness F / A [-] (1e-6, with F
        the larger of the applied load and the largest ball load [N]: scales with the
        load, so a light load still crosses a clearance in a few steps).
    levenberg_shaft : float
        The shaft's plain Levenberg shift as a fraction of the largest diagonal of its
        scaled tangent [-] (1e-10 against a shaft of ~1e9 N/m).
    levenberg_shaft_robust : float
        The same in the shaft's robust retry [-] (1e-16; the geometric term,
        ``levenberg_geometric``, then dominates).
    armijo : float
        Sufficient-decrease constant of every line search [-] (1e-4, Dennis & Schnabel
        1983, §6.3): a step t is taken if the merit falls by at least armijo t times the
        merit's directional derivative.
    potential_halvings : int
        Halvings of the step after the full step in the search on the frozen-stiffness
        potential (the load distribution's groove arm) [-] (59: the step reaches 2^-59, far
        below the round-off of a displacement).
    residual_halvings : int
        Halvings in the search on the residual norm (the load distribution's contact arm)
        [-] (40).
    shaft_halvings : int
        Halvings in the shaft's search on potential or residual norm [-] (39: 40
        evaluations).
    duplex_halvings : int
        Halvings in the duplex pair's search on the residual norm [-] (49: 50 evaluations).
    roundoff_factor : float
        Round-off of a ball's approach s - A in units of eps |u| [-] (20: the approach is the
        difference of lengths of the size of the rigid displacement u; with Q ~ delta^1.5
        the relative residual is resolved to about 20 eps |u| / delta_max).
    floor_cap : float
        Largest relative residual the round-off floor may accept, and the largest any
        solver returns [-] (1e-9; with rtol above 1e-11 the limit is floor_rtol rtol).
    floor_rtol : float
        Round-off floor and acceptance limit in units of rtol [-] (100).
    quadratic_region : float
        Relative residual below which Newton is taken to converge quadratically and full
        steps are taken without a line search [-] (1e-6).
    stall_ratio : float
        A step that leaves more than this fraction of the residual made no progress [-]
        (0.5; together with a residual at the round-off floor the iteration stops there).
    near_tolerance : float
        The shaft's residual, in units of rtol, below which a step without progress ends
        the iteration at the round-off floor [-] (1e3).
    highspeed_step : float
        Largest ball or ring-point displacement of a high-speed Newton step, as a fraction
        of the ball diameter [-] (0.05).
    duplex_step : float
        The duplex pair's step limit: this fraction of A plus ``duplex_step_growth`` times
        the largest deflection [-] (0.05).
    duplex_step_growth : float
        See ``duplex_step`` [-] (0.5: the limit grows with the deflection).
    roller_step : float
        Trust radius of a roller bearing's Newton step as a fraction of the roller diameter
        D_we [-] (0.01), applied to the largest scaled component (translations [m], tilts
        times d_m/2).  The lamina model holds up to a slice approach of 0.02 D_we (about
        three times the approach at the static capacity, ~0.007 D_we), so a step may cross
        half that range: the whole load range of a bearing in a few steps, while the
        approach's 10/9 power is still well described by the tangent it is taken from.  The
        roller's Levenberg shift is ``levenberg_trace`` / ``levenberg_geometric`` with the
        roller diameter D_we for the length (F / D_we the geometric stiffness).
    """

    trust_fraction: float = 0.25
    levenberg_trace: float = 1e-12
    levenberg_geometric: float = 1e-6
    levenberg_shaft: float = 1e-10
    levenberg_shaft_robust: float = 1e-16
    armijo: float = 1e-4
    potential_halvings: int = 59
    residual_halvings: int = 40
    shaft_halvings: int = 39
    duplex_halvings: int = 49
    roundoff_factor: float = 20.0
    floor_cap: float = 1e-9
    floor_rtol: float = 100.0
    quadratic_region: float = 1e-6
    stall_ratio: float = 0.5
    near_tolerance: float = 1e3
    highspeed_step: float = 0.05
    duplex_step: float = 0.05
    duplex_step_growth: float = 0.5
    roller_step: float = 0.01

    @property
    def roundoff_eps(self) -> float:
        """roundoff_factor times the machine epsilon [-]."""
        return self.roundoff_factor * _EPS


#: The policy every solver of the package uses.
POLICY = NewtonPolicy()


# ------------------------------------------------------------------ step size
def trust_radius(A, policy: NewtonPolicy = POLICY):
    """Trust radius of a bearing's Newton step [m] for a curvature-centre distance A [m]."""
    return policy.trust_fraction * A


def clip_factor(size, radius):
    """Factor that brings a step of largest component ``size`` [m] within ``radius`` [m].

    1 where the step is within the radius, else radius / size.  Arrays broadcast (a size
    of zero gives 1); a Python or NumPy scalar ``size`` gives a Python float 1.0 or
    radius / size.

    Examples
    --------
    >>> clip_factor(4.0, 1.0), clip_factor(0.5, 1.0)
    (0.25, 1.0)
    """
    if not isinstance(size, np.ndarray):
        return radius / size if size > radius else 1.0
    return np.minimum(1.0, radius / np.maximum(size, 1e-300))


def levenberg_shift(trace, load, length, n_free=1, policy: NewtonPolicy = POLICY):
    """Levenberg shift of a scaled Newton system (vectorised) [N/m].

    max(levenberg_trace |trace| / n_free, levenberg_geometric load / length): the
    larger of a fraction of the mean diagonal (``trace`` [N/m] over ``n_free`` [-] free
    directions) and of the geometric stiffness ``load`` [N] / ``length`` [m].
    """
    return np.maximum(policy.levenberg_trace * (np.abs(trace) / n_free),
                      policy.levenberg_geometric * load / length)


def levenberg_shift_one(trace, n_free, load, per_length, policy: NewtonPolicy = POLICY):
    """:func:`levenberg_shift` on Python floats, with ``per_length`` = levenberg_geometric /
    length [1/m] computed once (the single-case and compiled paths' order of operations)
    [N/m]."""
    return max(policy.levenberg_trace * abs(trace) / n_free, per_length * load)


# ------------------------------------------------------------------ line searches
def armijo_ok(merit, merit0, t, slope, policy: NewtonPolicy = POLICY):
    """Armijo's sufficient decrease: merit <= merit0 + armijo t slope (``slope`` < 0 the
    merit's derivative along the full step; NaN merits fail)."""
    return merit <= merit0 + policy.armijo * t * slope


def backtrack(evaluate, accepted, halvings):
    """Backtracking line search over many cases at once.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(idx, t)``: whether the steps ``t`` [-] of the cases ``idx`` are
        accepted (a boolean array); it may keep the state it evaluated.
    accepted : ndarray of bool
        Whether each case's full step (t = 1) is accepted (a case not to be searched is
        marked accepted).
    halvings : int
        Largest number of halvings [-].

    Returns
    -------
    (t, accepted) : the step of each case (the last one tried where none was accepted)
        [-] and whether it was accepted.
    """
    t = np.ones(len(accepted))
    todo = ~np.asarray(accepted, bool)
    for _ in range(halvings):
        idx = np.flatnonzero(todo)
        if not idx.size:
            break
        t[idx] *= 0.5
        todo[idx[evaluate(idx, t[idx])]] = False
    return t, ~todo


def backtrack_one(accept, halvings, t=1.0):
    """Backtracking line search for one case: ``accept(t)`` at t, then at t/2, t/4 ... (at
    most ``halvings`` halvings); returns (the first accepted step or the last one tried
    [-], whether it was accepted)."""
    if accept(t):
        return t, True
    for _ in range(halvings):
        t *= 0.5
        if accept(t):
            return t, True
    return t, False


# ------------------------------------------------------------------ round-off
def roundoff_cap(rtol, policy: NewtonPolicy = POLICY):
    """Largest relative residual a solver accepts, max(floor_cap, floor_rtol rtol) [-]."""
    return max(policy.floor_cap, policy.floor_rtol * rtol)


def roundoff_limit(umax, dmax, policy: NewtonPolicy = POLICY):
    """Relative residual round-off allows at a largest approach ``dmax`` [m] and rigid
    displacement ``umax`` [m]: 20 eps umax / dmax [-] (infinite where no ball is loaded;
    floats give a float)."""
    if not isinstance(dmax, np.ndarray):
        return policy.roundoff_eps * umax / dmax if dmax > 0 else np.inf
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(np.asarray(dmax) > 0, policy.roundoff_eps * umax / dmax, np.inf)


def roundoff_floor(rtol, dmax, umax, policy: NewtonPolicy = POLICY):
    """Round-off floor of the relative residual at approach ``dmax`` and rigid displacement
    ``umax`` [m] [-].

    The approach s - A is resolved to ~eps |u| and Q ~ delta^1.5, so Newton cannot do
    better than ~20 eps umax / delta_max.  No floor while no ball is loaded (a step that
    lands exactly on first contact is not equilibrium), never below floor_rtol rtol and
    never above :func:`roundoff_cap`.  Arrays broadcast; floats give a float.

    Examples
    --------
    >>> roundoff_floor(1e-12, 1e-6, 1e-4)      # 100 rtol above 20 eps 1e-4 / 1e-6
    1e-10
    >>> roundoff_floor(1e-12, 0.0, 1e-4)       # no ball loaded: no floor
    0.0
    """
    if isinstance(dmax, float) and isinstance(umax, float):
        if not dmax > 0:
            return 0.0
        lo = policy.floor_rtol * rtol
        return min(max(lo, policy.roundoff_eps * umax / dmax), max(policy.floor_cap, lo))
    cap = roundoff_cap(rtol, policy)
    with np.errstate(divide="ignore", invalid="ignore"):
        fl = np.maximum(policy.floor_rtol * rtol, policy.roundoff_eps * umax / dmax)
    return np.where(np.asarray(dmax) > 0, np.minimum(fl, cap), 0.0)


def stalled(err_new, err, policy: NewtonPolicy = POLICY):
    """Whether a step left more than stall_ratio of the residual (no progress)."""
    return err_new > policy.stall_ratio * err


# ------------------------------------------------------------------ best iterate
def keep_best(best_x, best_err, idx, x, err):
    """Record the iterates ``x`` of the cases ``idx`` whose residual ``err`` is below the
    best so far (in place)."""
    better = err < best_err[idx]
    best_x[idx[better]], best_err[idx[better]] = x[better], err[better]


def accept_best(active, x, err, best_x, best_err, rtol, policy: NewtonPolicy = POLICY):
    """At the iteration limit: the cases of ``active`` whose best residual is within
    :func:`roundoff_cap` take their best iterate (``x`` and ``err`` in place); returns the
    cases that remain unconverged."""
    cap = roundoff_cap(rtol, policy)
    fine = active[best_err[active] <= cap]
    x[fine], err[fine] = best_x[fine], best_err[fine]
    return active[best_err[active] > cap]


# ------------------------------------------------------------------ the error
def convergence_error(what, iterations, residual, rtol, *, best=None, newton=False,
                      steps="", measure="relative residual", context="", roundoff=None,
                      roundoff_hint=""):
    """The ConvergenceError of a Newton iteration, in the one shape every solver uses.

    ``{what} did not converge after {iterations} [Newton ]iterations{steps}: {measure}
    {residual} ([best {best}; ]> rtol={rtol}) {context} [(round-off limit here ~{roundoff}:
    {roundoff_hint})]``; the round-off part only where the limit is above a tenth of the
    best residual (there round-off, not the iteration, is what stops it).

    Parameters
    ----------
    what : str
        The equilibrium solved (``"load distribution"``).
    iterations : int
        Iterations done [-].
    residual, best : float
        The final and the best residual [-] (``best`` None: not shown).
    rtol : float
        Tolerance [-].
    newton : bool
        Say "Newton iterations".
    steps : str
        Appended to "iterations" (``" over all load steps"``).
    measure : str
        The residual's name.
    context : str
        Load case, loads, displacements.
    roundoff : float or None
        Round-off limit of the residual at the last iterate [-].
    roundoff_hint : str
        Why round-off limits it.

    Returns
    -------
    ConvergenceError
    """
    ref = residual if best is None else best
    return ConvergenceError(
        f"{what} did not converge after {iterations} {'Newton ' if newton else ''}iterations"
        f"{steps}: {measure} {residual:.3e} ("
        + (f"best {best:.3e}; " if best is not None else "") + f"> rtol={rtol:g})"
        + (f" {context}" if context else "")
        + (f" (round-off limit here ~{roundoff:.1e}: {roundoff_hint})"
           if roundoff is not None and roundoff > 0.1 * ref else ""))
