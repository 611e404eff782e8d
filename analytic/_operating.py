"""Operating-condition checks of the solvers' results (internal).

After a load distribution is solved, three things are checked and, when they fail, said
in one ``UserWarning`` per check and solve (the result is still returned):

* the static safety s0 = (4200 MPa / p_max)^3 of the most loaded contact
  (:func:`ballrace.analytic.ratings.static_safety_from_pressure`) is below 1;
* a deep-groove bearing (nominal contact angle 0) runs at contact angles beyond
  :data:`~ballrace.analytic.ratings.DEEP_GROOVE_ANGLE_LIMIT`;
* the tilt of the inner ring exceeds the
  :data:`~ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT` of the bearing type.

The warnings point at the first caller outside the package (the user's
script), and a solver that calls another one internally (a start value, a per-seat
result) silences the inner one with :func:`quiet`.
"""
from __future__ import annotations

import contextlib
import contextvars
import functools
import math

import numpy as np

from . import ratings

_QUIET = contextvars.ContextVar("ballrace_operating_quiet", default=False)


@contextlib.contextmanager
def quiet():
    """Within this block the operating checks warn nothing (nested solves)."""
    token = _QUIET.set(True)
    try:
        yield
    finally:
        _QUIET.reset(token)


def silenced() -> bool:
    """True inside :func:`quiet`."""
    return _QUIET.get()


def warn(message: str) -> None:
    """A ``UserWarning`` through :func:`ballrace.errors.warn` (at the user's line), unless
    inside :func:`quiet`."""
    if _QUIET.get():
        return
    from ..errors import warn as _warn

    _warn(message)


@functools.lru_cache(maxsize=128)
def _critical_load(bearing) -> float:
    """The smallest ball load [N] that can reach the C0 pressure (4200 MPa) on either race
    at any contact angle, less 2 %: a ball load below it has s0 > 1 for certain.

    p_max ~ Q^(1/3) at fixed geometry (Hertz), and p_max at a given load depends on the
    contact angle only through R_x = D (1 -+ D cos(beta) / d_e) / 2, monotonically, so
    the largest unit-load pressure lies on the grid's ends; 19 angles for safety."""
    beta = np.radians(np.linspace(0.0, 90.0, 19))
    p1 = max(float(np.max(bearing.contacts(1.0, beta, race).p_max)) for race in ("inner", "outer"))
    return 0.98 * (ratings.STATIC_RATING_PRESSURE / p1) ** 3


def may_be_overloaded(bearing, ball_loads) -> bool:
    """False when no ball load can reach 4200 MPa (cheap screen before the exact s0)."""
    Q = np.asarray(ball_loads, dtype=float)
    return bool(Q.size) and float(Q.max()) >= _critical_load(bearing)


def _cases(mask) -> str:
    m = np.asarray(mask)
    return "" if m.ndim == 0 or m.size == 1 else f" in {int(m.sum())} of {m.size} load cases"


def safety_message(what: str, s0, p_max) -> str | None:
    """The s0 < 1 warning text, or None."""
    s0 = np.asarray(s0, float)
    bad = s0 < 1.0
    if not np.any(bad):
        return None
    i = np.unravel_index(int(np.argmin(s0)), s0.shape) if s0.ndim else ()
    p = float(np.asarray(p_max, float)[i])
    return (f"{what}: static safety s0 = {float(s0[i]):.3g} < 1{_cases(bad)}: the most loaded "
            f"ball-raceway contact reaches p_max = {p / 1e6:.0f} MPa, above the "
            f"{ratings.STATIC_RATING_PRESSURE / 1e6:.0f} MPa on which ISO 76 bases C0 "
            "(s0 = (4200 MPa / p_max)^3); the permanent raceway deformation exceeds the "
            "1e-4 D that C0 allows")


def angle_message(what: str, bearing, ball_loads, angles) -> str | None:
    """Warning text when a deep-groove bearing runs beyond DEEP_GROOVE_ANGLE_LIMIT."""
    if bearing.nominal_contact_angle != 0.0:
        return None
    Q = np.asarray(ball_loads, float)
    if not Q.size:
        return None
    big = float((np.abs(np.asarray(angles, float)) * (Q > 0)).max())
    lim = ratings.DEEP_GROOVE_ANGLE_LIMIT
    if not big > lim:
        return None
    return (f"{what}: the deep-groove bearing runs at contact angles up to "
            f"{math.degrees(big):.1f} deg (limit {math.degrees(lim):.0f} deg, "
            "ratings.DEEP_GROOVE_ANGLE_LIMIT): it works as an angular-contact bearing, which "
            "its ratings (C, C0 and X/Y at the nominal 0 deg) and its catalogue life do not "
            "describe, and the contact ellipse may run over the shoulder (give the shoulder "
            "heights to check)")


def tilt_message(what: str, bearing, tilt) -> str | None:
    """Warning text when the ring tilt exceeds PERMISSIBLE_MISALIGNMENT of the type."""
    t = np.asarray(tilt, float)
    if not t.size:
        return None
    big = float(t.max())
    kind = "deep-groove" if bearing.nominal_contact_angle == 0.0 else "angular-contact"
    lim = ratings.PERMISSIBLE_MISALIGNMENT[kind]
    if not big > lim:
        return None
    return (f"{what}: the inner ring is tilted {big * 1e3:.3g} mrad "
            f"({math.degrees(big) * 60:.3g} arcmin) against the outer ring{_cases(t > lim)}, "
            f"more than the {math.degrees(lim) * 60:.0f} arcmin ({lim * 1e3:.2f} mrad) "
            f"{'a' if kind == 'deep-groove' else 'an'} {kind} ball bearing tolerates "
            "(ratings.PERMISSIBLE_MISALIGNMENT, manufacturers' guide values): expect edge "
            "loading, noise and a shorter life")


def emit(*messages) -> None:
    """Warn each message that is not None."""
    for m in messages:
        if m:
            warn(m)
