"""Plausibility warnings for likely unit slips at the public entry points (SI inside).

The library takes SI floats; a value that no rolling bearing has is most often a unit slip
at the call (millimetres typed as metres, GPa as Pa, percent as a ratio, °C as K).  These
helpers warn (``UserWarning``, pointing at the caller) naming the argument, what was given
and the likely slip; out-of-range values that cannot be meant are refused by the callers
with ``ValueError`` instead.
"""
from __future__ import annotations

import warnings

import numpy as np

__all__ = ["modulus", "length", "depth"]

#: Young's moduli outside this range [Pa] are not bearing materials (elastomers start near
#: 1e6 Pa, polymers 1e9 Pa, steel 2e11 Pa, diamond 1.2e12 Pa).
MODULUS_RANGE = (1e8, 2e12)


def _warn(message: str, stacklevel: int) -> None:
    warnings.warn(message, UserWarning, stacklevel=stacklevel + 1)


def modulus(E, name: str = "E", stacklevel: int = 3) -> None:
    """Warn when a Young's modulus [Pa] is outside :data:`MODULUS_RANGE`."""
    e = np.asarray(E, float)
    if e.size == 0 or not np.all(np.isfinite(e)):
        return
    lo, hi = float(np.min(e)), float(np.max(e))
    if lo < MODULUS_RANGE[0]:
        hint = (f" - were GPa given? ({lo:g} GPa is {lo * 1e9:.3g} Pa)" if lo < 1e4
                else " - were MPa given?" if lo < 1e7 else "")
        _warn(f"{name} = {lo:g} Pa is below any bearing material ({MODULUS_RANGE[0]:g} Pa); "
              f"moduli are in pascals [Pa]{hint}", stacklevel)
    elif hi > MODULUS_RANGE[1]:
        _warn(f"{name} = {hi:g} Pa is above any material ({MODULUS_RANGE[1]:g} Pa); moduli "
              "are in pascals [Pa]", stacklevel)


def length(value, name: str, largest: float, what: str, stacklevel: int = 3) -> None:
    """Warn when a length [m] exceeds ``largest`` (e.g. a ball diameter above 0.25 m)."""
    v = np.abs(np.asarray(value, float))
    v = v[np.isfinite(v)] if v.ndim else (v if np.isfinite(v) else np.array([]))
    if np.size(v) and float(np.max(v)) > largest:
        big = float(np.max(v))
        _warn(f"{name} = {big:g} m is larger than any {what} (up to ~{largest:g} m); "
              f"lengths are in metres [m] - were millimetres given? ({big:g} mm is "
              f"{big * 1e-3:g} m)", stacklevel)


#: Absolute temperatures [K] a bearing calculation accepts: -100 °C to 500 °C.  Below, the
#: value is almost always degrees Celsius typed for kelvin (a bearing at 75 K is a slip);
#: neither the oil data, the expansion coefficients nor ISO 281's factors reach further.
TEMPERATURE_RANGE = (173.15, 773.15)


def _outside(values, lo: float, hi: float):
    """The first value outside [lo, hi] (a float), or None when all are inside."""
    v = np.asarray(values, float)
    bad = ~((v >= lo) & (v <= hi))
    if not np.any(bad):
        return None
    return float(v[bad].flat[0]) if v.ndim else float(v)


def temperature(T, name: str):
    """Check an absolute temperature [K]; ``ValueError`` outside :data:`TEMPERATURE_RANGE`
    naming the likely slip (°C given for K).  Returns the float array."""
    lo, hi = TEMPERATURE_RANGE
    v = _outside(T, lo, hi)
    if v is not None:
        hint = (f"; were degrees Celsius given? ({v:g} °C is {v + 273.15:g} K)"
                if -100.0 <= v <= 500.0 and v < lo else "")
        raise ValueError(f"{name} must be an absolute temperature in kelvin in [{lo:g}, {hi:g}] "
                         f"[K] (-100 °C to 500 °C); got {v:g}{hint}")
    return np.asarray(T, float)


#: Kinematic viscosities [m²/s] of lubricating oils: ISO VG 2 to VG 10000 and beyond.
VISCOSITY_RANGE = (1e-7, 0.05)


def viscosity(nu, name: str):
    """Check a kinematic viscosity [m²/s]; ``ValueError`` naming a mm²/s (cSt) slip."""
    lo, hi = VISCOSITY_RANGE
    x = _outside(nu, lo, hi)
    if x is not None:
        hint = (f"; were mm^2/s (cSt) given? ({x:g} mm^2/s is {x * 1e-6:g} m^2/s)"
                if x > hi else "")
        raise ValueError(f"{name} must be a kinematic viscosity in [{lo:g}, {hi:g}] [m^2/s]; "
                         f"got {x:g}{hint}")
    return np.asarray(nu, float)


#: Depths below a contact beyond this many of its larger semi-axis are warned about: the
#: stressed zone reaches a few semi-axes (the maxima lie within one), and 100 of them is
#: where a depth typed in millimetres (z = 0.5 for 0.5 mm) lands for bearing contacts.
DEPTH_FACTOR = 100.0


def depth(z, semi_axis, name: str = "z", stacklevel: int = 3) -> None:
    """Warn when a depth [m] is more than :data:`DEPTH_FACTOR` times the contact's larger
    semi-axis ``semi_axis`` [m] (0 or non-finite semi-axes are skipped)."""
    try:
        zz, aa = np.broadcast_arrays(np.asarray(z, float), np.asarray(semi_axis, float))
    except ValueError:                       # the callers report shapes that do not fit
        return
    ok = np.isfinite(zz) & np.isfinite(aa) & (aa > 0)
    if not np.any(ok):
        return
    ratio = np.where(ok, zz / np.where(ok, aa, 1.0), 0.0)
    i = int(np.argmax(ratio))
    r = float(ratio.flat[i])
    if r > DEPTH_FACTOR:
        zi, ai = float(zz.flat[i]), float(aa.flat[i])
        _warn(f"{name} = {zi:g} m is {r:.3g} times the contact's semi-axis ({ai:.3g} m), far "
              f"below its stressed zone (a few semi-axes deep); depths are in metres [m] - "
              f"were millimetres given? ({zi:g} mm is {zi * 1e-3:g} m)", stacklevel)
