"""Unit parsing at the boundary (CLI, case files, reports) with pint.

The library itself is SI-only; this module turns strings such as ``"4.45 N"``,
``"6.35 mm"``, ``"200 GPa"``, ``"1000 lbf"`` or ``"inf"`` into SI floats, and refuses a
quantity of the wrong dimension with a message that names the field.
"""
from __future__ import annotations

import functools
import math

__all__ = ["parse_quantity", "to_si", "ureg"]


@functools.cache
def ureg():
    """The shared pint UnitRegistry (created on first use)."""
    import pint

    return pint.UnitRegistry()


#: SI unit each pint dimensionality is converted to.
_SI = {
    "[force]": "N", "[length]": "m", "[pressure]": "Pa", "[mass] / [length] / [time]": "Pa*s",
    "[time]": "s", "[mass]": "kg", "[mass] / [length] ** 3": "kg/m^3",
    "1 / [time]": "1/s", "[force] * [length]": "N*m", "[angle]": "rad",
    "[force] / [length]": "N/m", "[temperature]": "K", "1 / [pressure]": "1/Pa",
    "[length] / [time]": "m/s",
}


def parse_quantity(text, dimension: str, name: str, *, allow_inf: bool = False) -> float:
    """Parse a unit string into an SI float of the given pint dimensionality.

    Parameters
    ----------
    text : str or float
        ``"6.35 mm"``, ``"1000 lbf"``, ``"-0.52 in"``, ``"inf"`` (lengths only, with
        ``allow_inf``).  A bare number is refused unless ``dimension`` is dimensionless.
    dimension : str
        pint dimensionality, e.g. ``"[length]"``, ``"[force]"``, ``"[pressure]"``,
        ``"[angle]"``, ``"[mass] / [length] / [time]"`` (dynamic viscosity).
    name : str
        Field name used in error messages.
    allow_inf : bool
        Accept ``"inf"`` / ``"-inf"`` (a flat surface's radius).

    Returns
    -------
    float
        The value in SI units (N, m, Pa, rad, Pa*s, ...).

    Examples
    --------
    >>> round(parse_quantity("1000 lbf", "[force]", "load"), 6)
    4448.221615
    >>> parse_quantity("6.35 mm", "[length]", "rx1")
    0.00635
    >>> parse_quantity("40 deg", "[angle]", "contact angle")  # doctest: +ELLIPSIS
    0.69813170079...
    >>> parse_quantity("inf", "[length]", "rx2", allow_inf=True)
    inf
    >>> parse_quantity("3 kg", "[force]", "load")
    Traceback (most recent call last):
    ...
    ValueError: load: expected a quantity of dimension [force] (e.g. N), got '3 kg' ([mass])
    """
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        if dimension in ("", "dimensionless"):
            return float(text)
        raise ValueError(f"{name}: give a unit with the number, e.g. '{text} {_SI.get(dimension, '')}'")
    s = str(text).strip()
    if s.lower() in ("inf", "+inf", "-inf", "infinity"):
        if not allow_inf:
            raise ValueError(f"{name}: 'inf' is not allowed here")
        return -math.inf if s.startswith("-") else math.inf
    reg = ureg()
    try:
        q = reg.Quantity(s)
    except Exception as exc:  # pint raises several error types for malformed strings
        raise ValueError(f"{name}: cannot parse {s!r} as a quantity ({exc})") from None
    if dimension in ("", "dimensionless"):
        if not q.dimensionless:
            raise ValueError(f"{name}: expected a dimensionless number, got {s!r}")
        return float(q.to("dimensionless").magnitude)
    if dimension == "[angle]":
        if str(q.units) == "dimensionless":
            raise ValueError(f"{name}: give the angle's unit ('deg' or 'rad'), got {s!r}")
        return float(q.to("radian").magnitude)
    if not q.check(dimension):
        raise ValueError(f"{name}: expected a quantity of dimension {dimension} "
                         f"(e.g. {_SI.get(dimension, '')}), got {s!r} ({q.dimensionality})")
    if dimension in _SI:
        return float(q.to(_SI[dimension]).magnitude)
    return float(q.to_base_units().magnitude)


def to_si(text, dimension: str, name: str, *, allow_inf: bool = False) -> float:
    """Alias of :func:`parse_quantity` for case-file loaders."""
    return parse_quantity(text, dimension, name, allow_inf=allow_inf)
