"""Input validation for the public boundary of :mod:`ballrace.analytic`.

One private module, as in pyvista's ``core/_validation``: every check takes the
argument's public ``name`` so the error says which argument is wrong and what
range is allowed.  ``TypeError`` for values that are not numbers, ``ValueError``
for numbers outside their allowed range.  Checks run once, at the public entry
point; internal kernels trust their inputs.
"""
from __future__ import annotations

import numpy as np

__all__ = [
    "as_array",
    "check_finite",
    "check_positive",
    "check_nonnegative",
    "check_range",
    "check_choice",
]


def _where(mask: np.ndarray) -> str:
    """Describe the first offending entry of a boolean mask for an error message."""
    if mask.ndim == 0:
        return ""
    idx = np.argwhere(mask)[0]
    return f" (first at index {tuple(int(i) for i in idx) if len(idx) > 1 else int(idx[0])})"


def _first(value: np.ndarray, mask: np.ndarray) -> float:
    return float(value[mask].ravel()[0]) if value.ndim else float(value)


def as_array(value, name: str, *, allow_inf: bool = False) -> np.ndarray:
    """Convert ``value`` to a float array; reject non-numbers and NaN (and inf unless allowed)."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a real number or an array of real numbers; "
                        f"got {type(value).__name__} {value!r}") from None
    bad = np.isnan(arr) if allow_inf else ~np.isfinite(arr)
    if bad.any():
        kind = "not NaN" if allow_inf else "finite"
        raise ValueError(f"{name} must be {kind}; got {_first(arr, bad)!r}{_where(bad)}")
    return arr


def check_finite(value, name: str) -> np.ndarray:
    """Array of finite floats, else ``ValueError`` naming ``name``."""
    return as_array(value, name)


def check_positive(value, name: str, unit: str = "", *, allow_inf: bool = False) -> np.ndarray:
    """Array of floats > 0, else ``ValueError`` naming ``name`` and the allowed range."""
    arr = as_array(value, name, allow_inf=allow_inf)
    bad = ~(arr > 0)
    if bad.any():
        u = f" [{unit}]" if unit else ""
        raise ValueError(f"{name} must be > 0{u}; got {_first(arr, bad)!r}{_where(bad)}")
    return arr


def check_nonnegative(value, name: str, unit: str = "") -> np.ndarray:
    """Array of finite floats >= 0, else ``ValueError`` naming ``name``."""
    arr = as_array(value, name)
    bad = arr < 0
    if bad.any():
        u = f" [{unit}]" if unit else ""
        raise ValueError(f"{name} must be >= 0{u}; got {_first(arr, bad)!r}{_where(bad)}")
    return arr


def check_range(value, name: str, low: float | None = None, high: float | None = None, *,
                low_inclusive: bool = False, high_inclusive: bool = False,
                unit: str = "") -> np.ndarray:
    """Array of finite floats inside the given interval, else ``ValueError`` stating it."""
    arr = as_array(value, name)
    bad = np.zeros(arr.shape, dtype=bool)
    if low is not None:
        bad |= (arr < low) if low_inclusive else (arr <= low)
    if high is not None:
        bad |= (arr > high) if high_inclusive else (arr >= high)
    if bad.any():
        lo = "(-inf" if low is None else ("[" if low_inclusive else "(") + f"{low:g}"
        hi = "inf)" if high is None else f"{high:g}" + ("]" if high_inclusive else ")")
        u = f" [{unit}]" if unit else ""
        raise ValueError(f"{name} must be in {lo}, {hi}{u}; got {_first(arr, bad)!r}{_where(bad)}")
    return arr


def check_choice(value: str, name: str, choices) -> str:
    """``value`` must be one of ``choices`` (strings)."""
    if value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(repr(c) for c in choices)}; got {value!r}")
    return value
