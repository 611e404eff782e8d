"""Input validation for the public boundary of :mod:`ballrace.analytic`.

One private module, as in pyvista's ``core/_validation``: every check takes the
argument's public ``name`` so the error says which argument is wrong and what
range is allowed.  ``TypeError`` for values that are not numbers, ``ValueError``
for numbers outside their allowed range.  Checks run once, at the public entry
point; internal kernels trust their inputs.

What counts as a number: Python and numpy integers and floats, and arrays (or nested
lists) of them.  Strings (even ``"1.0"``), booleans, ``None``, complex numbers and
arrays of those are a ``TypeError``: numpy would silently turn ``"1.0"`` and ``True``
into 1.0.

Physical magnitude: with ``bounded=True`` a dimensional input must be zero (where zero
is allowed) or have a magnitude in [``MIN_MAGNITUDE``, ``MAX_MAGNITUDE``] =
[1e-30, 1e30] in SI units.  No bearing quantity comes near those limits (a 10 m ring is
1e1 m, a diamond's modulus 1.2e12 Pa), and inside them the contact formulas, which
multiply up to a few such numbers, cannot overflow or underflow to inf, NaN or zero.

Broadcasting: :func:`broadcast` is ``np.broadcast_arrays`` with an error that names the
arguments whose shapes do not fit together.
"""
from __future__ import annotations

import numbers

import numpy as np

__all__ = [
    "MAX_MAGNITUDE",
    "MIN_MAGNITUDE",
    "as_array",
    "broadcast",
    "check_finite",
    "check_positive",
    "check_nonnegative",
    "check_range",
    "check_choice",
    "check_instance",
    "check_integer",
    "scalar_positive",
    "scalar_count",
    "store_checked",
]

#: Largest magnitude of a dimensional input accepted with ``bounded=True`` (SI units).
MAX_MAGNITUDE = 1e30
#: Smallest non-zero magnitude of a dimensional input accepted with ``bounded=True``.
MIN_MAGNITUDE = 1e-30

_BAD_KINDS = {"b": "boolean", "U": "text", "S": "bytes", "c": "complex", "O": "object",
              "M": "datetime", "m": "timedelta", "V": "void"}


def _where(mask: np.ndarray) -> str:
    """Describe the first offending entry of a boolean mask for an error message."""
    if mask.ndim == 0:
        return ""
    idx = np.argwhere(mask)[0]
    return f" (first at index {tuple(int(i) for i in idx) if len(idx) > 1 else int(idx[0])})"


def _first(value: np.ndarray, mask: np.ndarray) -> float:
    return float(value[mask].ravel()[0]) if value.ndim else float(value)


def _type_error(value, name: str) -> TypeError:
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    hint = ""
    if isinstance(value, str) and any(ch.isdigit() for ch in value):
        try:                                  # "6.35 mm": the API takes SI floats
            from ballrace.units import ureg

            q = ureg().Quantity(value.strip())
            si = q.to_base_units()
            if not q.dimensionless:
                hint = (f" (the Python API takes SI floats: {value!r} is "
                        f"{float(si.magnitude):.6g} in {si.units:~}; unit strings are for "
                        "the command line and case files)")
        except Exception:                     # noqa: BLE001 - no hint is better than a wrong one
            hint = (" (the Python API takes SI floats; unit strings are for the command line "
                    "and case files)")
    return TypeError(f"{name} must be a real number or an array of real numbers; "
                     f"got {type(value).__name__} {text}{hint}")


def _has_non_number(value) -> bool:
    """True when a (nested) list or tuple holds a bool, str, bytes or None."""
    if isinstance(value, (bool, np.bool_, str, bytes, type(None))):
        return True
    if isinstance(value, (list, tuple)):
        return any(_has_non_number(v) for v in value)
    return False


def as_array(value, name: str, *, allow_inf: bool = False, bounded: bool = False,
             tiny_ok: bool = False, unit: str = "") -> np.ndarray:
    """Convert ``value`` to a float array; reject non-numbers and NaN (and inf unless allowed).

    ``TypeError`` for strings, booleans, ``None``, complex or object values and ragged
    lists; ``ValueError`` for NaN or inf.  With ``bounded``, also ``ValueError`` for a
    non-zero finite magnitude outside [MIN_MAGNITUDE, MAX_MAGNITUDE] (only above
    MAX_MAGNITUDE with ``tiny_ok``, for coordinates, where any small value is meaningful).

    Examples
    --------
    >>> as_array([1, 2.5], "x")
    array([1. , 2.5])
    >>> as_array("1.0", "E")
    Traceback (most recent call last):
    ...
    TypeError: E must be a real number or an array of real numbers; got str '1.0'
    >>> as_array(1e308, "load", bounded=True, unit="N")
    Traceback (most recent call last):
    ...
    ValueError: load must have a physical magnitude, 0 or in [1e-30, 1e+30] [N]; got 1e+308
    """
    if type(value) is np.ndarray and value.dtype == np.float64 and value.size:
        # fast path: two reductions instead of elementwise masks (min/max propagate NaN);
        # anything not plainly fine goes the elementwise way below, which words the error
        lo, hi = float(value.min()), float(value.max())
        if lo == lo and hi == hi and (allow_inf or (-np.inf < lo and hi < np.inf)):
            if not bounded:
                return value
            if tiny_ok:
                if -MAX_MAGNITUDE <= lo and hi <= MAX_MAGNITUDE:
                    return value
            elif MIN_MAGNITUDE <= lo and hi <= MAX_MAGNITUDE:
                return value
    if _has_non_number(value):
        raise _type_error(value, name)
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):
        raise _type_error(value, name) from None
    if raw.dtype.kind in _BAD_KINDS:
        if raw.dtype.kind != "O":
            raise _type_error(value, name)
        try:   # object arrays of plain numbers (e.g. Fraction, Decimal) are fine
            flat = [v for v in raw.ravel()]
            if any(_has_non_number(v) or isinstance(v, complex) for v in flat):
                raise TypeError
            raw = np.array([float(v) for v in flat]).reshape(raw.shape)
        except (TypeError, ValueError):
            raise _type_error(value, name) from None
    arr = raw.astype(float, copy=False)
    bad = np.isnan(arr) if allow_inf else ~np.isfinite(arr)
    if bad.any():
        kind = "not NaN" if allow_inf else "finite"
        raise ValueError(f"{name} must be {kind}; got {_first(arr, bad)!r}{_where(bad)}")
    if bounded:
        mag = np.abs(arr)
        low = 0.0 if tiny_ok else MIN_MAGNITUDE
        bad = np.isfinite(mag) & (mag != 0) & ((mag < low) | (mag > MAX_MAGNITUDE))
        if bad.any():
            u = f" [{unit}]" if unit else ""
            rng = (f"within ±{MAX_MAGNITUDE:g}" if tiny_ok else
                   f"0 or in [{MIN_MAGNITUDE:g}, {MAX_MAGNITUDE:g}]")
            raise ValueError(f"{name} must have a physical magnitude, {rng}{u}; "
                             f"got {_first(arr, bad)!r}{_where(bad)}")
    return arr


def broadcast(**arrays) -> list:
    """``np.broadcast_arrays`` of the named arrays; ``ValueError`` naming those that clash.

    Examples
    --------
    >>> Fa, e = broadcast(Fa=np.ones(2), e=np.ones(3))
    Traceback (most recent call last):
    ...
    ValueError: Fa (shape (2,)) and e (shape (3,)) do not broadcast together
    """
    arrs = [np.asarray(a) for a in arrays.values()]
    try:
        return list(np.broadcast_arrays(*arrs))
    except ValueError:
        pass
    names = list(arrays)
    shape = ()
    so_far = []
    for n, a in zip(names, arrs):
        try:
            shape = np.broadcast_shapes(shape, a.shape)
            so_far.append(n)
        except ValueError:
            clash = [m for m, b in zip(so_far, arrs) if b.ndim]
            others = " and ".join(f"{m} (shape {np.shape(arrays[m])})" for m in clash) \
                or "the other arguments"
            raise ValueError(f"{others} and {n} (shape {a.shape}) do not broadcast "
                             "together") from None
    raise AssertionError("unreachable")  # pragma: no cover


def check_finite(value, name: str, unit: str = "", *, bounded: bool = False) -> np.ndarray:
    """Array of finite floats, else ``ValueError`` naming ``name``."""
    return as_array(value, name, bounded=bounded, unit=unit)


def check_positive(value, name: str, unit: str = "", *, allow_inf: bool = False,
                   bounded: bool = False) -> np.ndarray:
    """Array of floats > 0, else ``ValueError`` naming ``name`` and the allowed range."""
    arr = as_array(value, name, allow_inf=allow_inf)
    if arr.size and arr.min() > 0:                      # one reduction when all is well
        bad = None
    else:
        bad = ~(arr > 0)
    if bad is not None and bad.any():
        u = f" [{unit}]" if unit else ""
        raise ValueError(f"{name} must be > 0{u}; got {_first(arr, bad)!r}{_where(bad)}")
    if bounded:
        as_array(arr, name, allow_inf=allow_inf, bounded=True, unit=unit)
    return arr


def check_nonnegative(value, name: str, unit: str = "", *, bounded: bool = False,
                      tiny_ok: bool = False) -> np.ndarray:
    """Array of finite floats >= 0, else ``ValueError`` naming ``name``."""
    arr = as_array(value, name)
    if not (arr.size and arr.min() >= 0):               # one reduction when all is well
        bad = arr < 0
        if bad.any():
            u = f" [{unit}]" if unit else ""
            raise ValueError(f"{name} must be >= 0{u}; got {_first(arr, bad)!r}{_where(bad)}")
    if bounded:
        as_array(arr, name, bounded=True, tiny_ok=tiny_ok, unit=unit)
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
    """``value`` must be one of ``choices`` (strings); ``TypeError`` when it is not a string."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {', '.join(repr(c) for c in choices)}; "
                        f"got {type(value).__name__} {value!r}")
    if value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(repr(c) for c in choices)}; got {value!r}")
    return value


def check_instance(value, name: str, cls, what: str | None = None):
    """``value`` must be an instance of ``cls``, else ``TypeError`` naming ``name``."""
    if not isinstance(value, cls):
        what = what or cls.__name__
        raise TypeError(f"{name} must be a {what}; got {type(value).__name__}")
    return value


def check_integer(value, name: str, low: int | None = None) -> np.ndarray:
    """Array of whole numbers (>= ``low``), else ``ValueError`` naming ``name``.

    Whole-valued floats (``9.0``) are accepted; booleans and strings are a ``TypeError``.

    Examples
    --------
    >>> check_integer(2.5, "n_balls", 1)
    Traceback (most recent call last):
    ...
    ValueError: n_balls must be a whole number >= 1; got 2.5
    """
    arr = as_array(value, name)
    bad = arr != np.round(arr)
    if low is not None:
        bad |= arr < low
    if bad.any():
        lo = f" >= {low}" if low is not None else ""
        raise ValueError(f"{name} must be a whole number{lo}; "
                         f"got {_first(arr, bad)!r}{_where(bad)}")
    return arr


def scalar_positive(value, name: str, unit: str) -> float:
    """One positive, bounded number as a float (a geometry field of a bearing), else
    ``ValueError`` as :func:`check_positive`; an array is a ``TypeError``.

    Examples
    --------
    >>> scalar_positive([1.0, 2.0], "ball_diameter", "m")
    Traceback (most recent call last):
    ...
    TypeError: ball_diameter must be a scalar [m]; got an array of shape (2,)
    """
    arr = check_positive(value, name, unit, bounded=True)
    if arr.ndim:
        raise TypeError(f"{name} must be a scalar [{unit}]; got an array of shape {arr.shape}")
    return float(arr)


def scalar_count(value, name: str, low: int) -> int:
    """One whole number >= ``low`` as an int (a count of balls, rollers or rows), else
    ``ValueError``; whole-valued floats (``9.0``) are accepted, booleans, text and arrays
    are a ``TypeError``.

    Examples
    --------
    >>> scalar_count(9.0, "n_balls", 3)
    9
    >>> scalar_count(2, "n_balls", 3)
    Traceback (most recent call last):
    ...
    ValueError: n_balls must be an integer >= 3; got 2
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be an integer; got {type(value).__name__} {value!r}")
    if not isinstance(value, numbers.Integral):
        if not float(value).is_integer():
            raise ValueError(f"{name} must be a whole number >= {low}; got {value!r}")
    value = int(value)
    if value < low:
        raise ValueError(f"{name} must be an integer >= {low}; got {value}")
    return value


def store_checked(instance, **values) -> None:
    """Write checked, normalised values onto the fields of a frozen dataclass (from its
    ``__post_init__``), field name = keyword."""
    for name, value in values.items():
        object.__setattr__(instance, name, value)
