"""Unit parsing at the boundary (CLI, case files, reports) with pint.

The library itself is SI-only; this module turns strings such as ``"4.45 N"``,
``"6.35 mm"``, ``"200 GPa"``, ``"1000 lbf"`` or ``"inf"`` into SI floats, and refuses a
quantity of the wrong dimension with a message that names the field.
"""
from __future__ import annotations

import functools
import math
import re

__all__ = ["parse_quantity", "check_form", "to_si", "ureg", "example_unit", "plausible"]


@functools.cache
def ureg():
    """The shared pint UnitRegistry (created on first use), with ``rev`` (a revolution,
    so "3000 rev/min" reads as rpm) where pint lacks it."""
    import pint

    reg = pint.UnitRegistry()
    try:
        reg.Unit("rev")
    except pint.errors.UndefinedUnitError:
        reg.define("rev = revolution")
    return reg


#: SI unit each pint dimensionality is converted to.
_SI = {
    "[force]": "N", "[length]": "m", "[pressure]": "Pa", "[mass] / [length] / [time]": "Pa*s",
    "[time]": "s", "[mass]": "kg", "[mass] / [length] ** 3": "kg/m^3",
    "1 / [time]": "1/s", "[force] * [length]": "N*m", "[angle]": "rad",
    "[force] / [length]": "N/m", "[temperature]": "K", "1 / [pressure]": "1/Pa",
    "[length] / [time]": "m/s", "[length] ** 2 / [time]": "m^2/s",
}

#: An example unit to name in messages, where the SI one is not what people write.
_EXAMPLE = {"[length] ** 2 / [time]": "mm^2/s (cSt)", "[temperature]": "degC",
            "[pressure]": "MPa", "[length]": "mm", "1 / [time]": "rpm"}
#: The unit to write after a bare number in a message's example (no parenthesis).
_BARE = {"[length] ** 2 / [time]": "mm^2/s", "[temperature]": "degC", "[pressure]": "MPa",
         "[length]": "mm", "1 / [time]": "rpm", "[angle]": "deg"}


def example_unit(dimension: str, name: str = "", value=None) -> str:
    """The unit to suggest after a bare number of ``dimension`` for the field ``name``
    (a Young's modulus ``E`` in GPa, or in Pa when ``value`` is already pascals; other
    pressures in MPa, lengths in mm, forces in N).

    >>> example_unit("[force]", "load"), example_unit("[pressure]", "--E1", 200)
    ('N', 'GPa')
    >>> example_unit("[pressure]", "E", 2e11)
    'Pa'
    """
    key = name.rsplit(".", 1)[-1].lstrip("-").rstrip("12")
    if dimension == "[pressure]" and key in ("E", "modulus"):
        return "Pa" if value is not None and abs(value) >= 1e4 else "GPa"
    return _BARE.get(dimension, _SI.get(dimension, ""))


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

    A string that pint would read differently from a person is refused rather than
    guessed: a decimal comma (pint reads ``"6,35 mm"`` as 635 mm), a thousands separator,
    or numbers inside the unit (``"6 35 mm"`` is 210 mm to pint):

    >>> parse_quantity("6,35 mm", "[length]", "rx1")
    Traceback (most recent call last):
    ...
    ValueError: rx1: '6,35 mm' contains a comma; write the decimal point as '.' and no thousands separator (e.g. '6.35 mm')
    """
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        if dimension in ("", "dimensionless"):
            return float(text)
        raise ValueError(f"{name}: give a unit with the number, e.g. "
                         f"'{text:g} {example_unit(dimension, name, text)}'")
    s = str(text).strip()
    if s.lower() in ("inf", "+inf", "-inf", "infinity"):
        if not allow_inf:
            raise ValueError(f"{name}: 'inf' is not allowed here")
        return -math.inf if s.startswith("-") else math.inf
    inf_unit = re.fullmatch(r"([+-]?)inf(?:inity)?\s+(.+)", s, re.I)
    if inf_unit and allow_inf:          # "inf mm": infinite whatever the unit, if it fits
        try:
            ok = ureg().Unit(inf_unit.group(2)).dimensionality == ureg().get_dimensionality(
                dimension)
        except Exception:  # pint raises several error types
            ok = False
        if not ok:
            raise ValueError(f"{name}: {s!r}: {inf_unit.group(2)!r} is not a unit of "
                             f"{dimension}; an infinite length (a flat surface's radius) is "
                             "written 'inf'")
        return -math.inf if inf_unit.group(1) == "-" else math.inf
    check_form(s, name, sample(dimension, name) if dimension not in ("", "dimensionless")
               else "0.3")
    reg = ureg()
    try:
        q = reg.Quantity(s)
    except Exception as exc:  # pint raises several error types for malformed strings
        raise ValueError(f"{name}: cannot parse {s!r} as a quantity ({exc})") from None
    if dimension in ("", "dimensionless"):
        if not q.dimensionless:
            raise ValueError(f"{name}: expected a dimensionless number, got {s!r}")
        return _finite(float(q.to("dimensionless").magnitude), s, name)
    if dimension == "[angle]":
        if str(q.units) == "dimensionless":
            raise ValueError(f"{name}: give the angle's unit ('deg' or 'rad'), got {s!r}")
        if not q.check("[]"):           # "15 mm": pint's DimensionalityError is a TypeError
            raise ValueError(f"{name}: expected an angle (e.g. deg or rad), got {s!r} "
                             f"({q.dimensionality})")
        return _finite(float(q.to("radian").magnitude), s, name)
    if not q.check(dimension):
        if str(q.units) == "dimensionless":         # "1000" where "1000 N" is meant
            raise ValueError(f"{name}: give a unit with the number, e.g. "
                             f"'{s} {example_unit(dimension, name)}'; got {s!r}")
        example = _EXAMPLE.get(dimension, _SI.get(dimension, ""))
        raise ValueError(f"{name}: expected a quantity of dimension {dimension} "
                         f"(e.g. {example}), got {s!r} ({q.dimensionality})")
    if dimension in _SI:
        return _finite(float(q.to(_SI[dimension]).magnitude), s, name)
    return _finite(float(q.to_base_units().magnitude), s, name)


#: One number (or a fraction such as "1/4"), then an optional unit expression.
_NUMBER = re.compile(r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?(?:\s*/\s*\d+(?:\.\d*)?)?")
#: Exponents inside a unit expression ("m^2", "m**-3"): the only digits allowed there.
_EXPONENT = re.compile(r"(?:\^|\*\*)\s*\(?\s*[+-]?\d+(?:\.\d+)?\s*\)?")
#: An exponent raised again ("m^2^9"): pint would evaluate a power tower.
_CHAINED = re.compile(_EXPONENT.pattern + r"\s*(?:\^|\*\*)")


#: A valid value of each dimension, for the examples in messages.
_SAMPLE = {"[force]": "4450 N", "[length]": "6.35 mm", "[pressure]": "1500 MPa",
           "[angle]": "40 deg", "1 / [time]": "3000 rpm", "[temperature]": "70 degC",
           "[length] ** 2 / [time]": "68 mm^2/s", "[mass] / [length] / [time]": "0.04 Pa*s",
           "1 / [pressure]": "2.2e-8 1/Pa", "[force] * [length]": "50 N*m"}


def sample(dimension: str, name: str = "") -> str:
    """A valid value of ``dimension`` to quote in a message (``"200 GPa"`` for a modulus).

    >>> sample("[force]"), sample("[pressure]", "[materials.ring].E")
    ('4450 N', '200 GPa')
    """
    if example_unit(dimension, name) == "GPa":
        return "200 GPa"
    return _SAMPLE.get(dimension, f"1 {_SI.get(dimension, '')}".strip())


def check_form(s: str, name: str, example: str = "6.35 mm") -> None:
    """Refuse strings that pint parses differently than a person reads them [-].

    Raises ``ValueError`` naming ``name`` for a comma (decimal or thousands separator),
    a string that does not start with a number, or numbers inside the unit; the messages
    quote ``example`` as a valid value.
    """
    if "," in s:
        raise ValueError(f"{name}: {s!r} contains a comma; write the decimal point as '.' and "
                         f"no thousands separator (e.g. '{example}')")
    m = _NUMBER.match(s)
    if m is None and re.match(r"\s*[+-]?(inf|nan)", s, re.I):
        raise ValueError(f"{name}: {s!r} is not a finite quantity")
    if m is None:
        raise ValueError(f"{name}: cannot parse {s!r} as a quantity: it does not start with a "
                         f"number (e.g. '{example}')")
    unit = s[m.end():].strip()
    if unit.startswith("1/"):                  # "2.2e-8 1/Pa"
        unit = unit[2:]
    if re.match(r"(?:\^|\*\*)", unit) or _CHAINED.search(unit) or any(
            len(re.sub(r"\D", "", e.split(".")[0])) > 2 for e in _EXPONENT.findall(unit)):
        raise ValueError(f"{name}: {s!r}: an exponent is a unit's power of at most two "
                         f"digits, not raised again (e.g. '68 mm^2/s')")
    if re.search(r"\d", _EXPONENT.sub("", unit)):
        raise ValueError(f"{name}: {s!r}: write one number followed by its unit (pint would "
                         "multiply the numbers in it, e.g. '6 35 mm' = 210 mm)")


#: What a unit-typed value may be before :func:`plausible` asks whether another unit was
#: meant: (low, high) in SI, the SI unit, what is outside, and the unit to suggest.
#: Moduli: rolling contacts are polymers (about 0.5 ... 5 GPa), light alloys, steels
#: (about 200 GPa) and ceramics (up to about 450 GPa); "200 MPa" for steel is a slip.
#: Radii of a contacting body: balls, rollers and races up to about 1 m (a flat is "inf").
PLAUSIBLE = {"modulus": (5e8, 2e12, "Pa", "GPa"), "radius": (0.0, 1.0, "m", "mm")}


def plausible(value: float, text, name: str, kind: str, stacklevel: int = 2) -> None:
    """Warn (``UserWarning``) when a parsed value is outside :data:`PLAUSIBLE` [SI].

    The message quotes what was typed and the likely intended unit, e.g.
    ``--E1 = '200 MPa' (0.2 GPa) is softer than the materials of rolling contacts
    (0.5 ... 2000 GPa); was '200 GPa' meant?``.  Nothing is refused: a soft polymer or a
    large radius may be meant.
    """
    import warnings

    lo, hi, si, meant = PLAUSIBLE[kind]
    v = abs(float(value))
    if not math.isfinite(v) or lo <= v <= hi:
        return
    m = _NUMBER.match(str(text))
    num = m.group(0).strip() if m else ""
    hint = ""
    if num:
        guess = float(ureg().Quantity(f"{num} {meant}").to(si).magnitude)
        if lo <= abs(guess) <= hi and guess != value:
            hint = f"; was '{num} {meant}' meant?"
    if kind == "modulus":
        what = ("softer than the materials of rolling contacts" if v < lo else
                "stiffer than any material")
        shown = f"{v / 1e9:.3g} GPa"
        span = f"{lo / 1e9:g} ... {hi / 1e9:g} GPa"
    else:
        what = "larger than the radii of balls, rollers and races"
        shown = f"{v:.4g} m"
        span = f"up to about {hi:g} m; a flat surface is 'inf'"
    warnings.warn(f"{name} = {str(text).strip()!r} ({shown}) is {what} ({span}){hint}",
                  UserWarning, stacklevel=stacklevel + 1)


def _finite(value: float, s: str, name: str) -> float:
    if not math.isfinite(value):
        raise ValueError(f"{name}: {s!r} is not a finite quantity")
    return value


def to_si(text, dimension: str, name: str, *, allow_inf: bool = False) -> float:
    """Alias of :func:`parse_quantity` for case-file loaders."""
    return parse_quantity(text, dimension, name, allow_inf=allow_inf)
