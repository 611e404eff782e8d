r"""The sliced (lamina) roller contact of ISO/TS 16281: slice stiffness and slicing.

A roller between two raceways is cut into ``n_s`` slices (laminae) of equal width
``L_we / n_s`` along its effective length.  Slice ``k`` of roller ``j`` has the approach

.. math:: \delta_{jk} = \delta_j + x_k\,\theta_j - 2 P(x_k)

(the ring approach at the roller's azimuth, the raceway misalignment ``theta_j`` seen by
the roller, and the profile drop ``P`` of :mod:`~ballrace.analytic.roller.profile` seen
at both contacts) and carries

.. math:: q_{jk} = \frac{c_L}{n_s}\,\langle\delta_{jk}\rangle^{10/9}, \qquad
          c_L = 35\,948\,L_{we}^{8/9}\quad[\mathrm{N},\ \mathrm{mm}]

for the roller between both raceways (the two contacts in series).  In SI,
``c_L = 35 948 x (10^3)^(8/9) x (10^3)^(10/9) L_we^(8/9) = 3.5948e10 L_we^(8/9)``
[N/m^(10/9)] with ``L_we`` in metres (the factor is exactly 10^6).  A whole straight roller
under a uniform approach carries ``Q = c_L delta^(10/9)``.

Stiffness laws (``stiffness=``)
-------------------------------
``"iso"``       ISO/TS 16281:2008's lamina constant 35 948 (N, mm), as reproduced by the
                open-source implementations and the secondary literature (the standard's
                own text was not read).
``"palmgren"``  Palmgren's line-contact deflection per contact,
                ``delta = 3.84e-5 Q^0.9 / l^0.8`` (mm, N; A. Palmgren, *Ball and Roller
                Bearing Engineering*, 3rd ed., SKF 1959; Harris & Kotzalas, *Essential
                Concepts of Bearing Technology*, 2007, eq. 6.43 — the equation number was
                not checked), two contacts in series:
                ``Q = (7.68e-5)^(-10/9) L^(8/9) delta^(10/9) = 37 310 L^(8/9) delta^(10/9)``
                (N, mm), about 4 % stiffer than ISO's constant.

Both constants are for steel rollers on steel rings.  For other materials they are scaled
with the contact modulus, ``c_L E' / E'_steel`` (``E'_steel`` of
:data:`~ballrace.analytic.materials.BEARING_STEEL`): the line-contact approach is, up to a
logarithm, proportional to ``Q / (E' L)``.  This scaling is an assumption of ballrace;
the standard gives the steel constant only.

Slice resolution
----------------
The slices sample the profile at their centres.  A crown that lies almost entirely within
the outermost slice is not resolved: :func:`check_resolution` warns when the drop at the
second-outermost slice centre is below a quarter of the drop at the outermost one
(:data:`RESOLUTION_RATIO`), naming the slice count that resolves it.  ISO's default profile
is resolved from 7 slices on; a short circular crown needs more.
"""
from __future__ import annotations

import math
import numbers

import numpy as np

from .._checks import as_array, check_positive
from ..materials import BEARING_STEEL, effective_modulus

__all__ = [
    "LINE_EXPONENT",
    "ISO_LAMINA_CONSTANT",
    "PALMGREN_CONSTANT",
    "STIFFNESS_LAWS",
    "DEFAULT_SLICES",
    "RESOLUTION_RATIO",
    "lamina_stiffness",
    "check_slices",
    "slice_positions",
    "slice_loads",
    "check_resolution",
]

#: Load-deflection exponent of a line contact in the lamina model, q ~ delta^(10/9) [-].
LINE_EXPONENT = 10.0 / 9.0

#: ISO/TS 16281's lamina constant for steel, c_L = 35 948 L_we^(8/9) [N, mm].
ISO_LAMINA_CONSTANT = 35948.0

#: Palmgren's two contacts in series, (2 x 3.84e-5)^(-10/9) [N, mm].
PALMGREN_CONSTANT = (2.0 * 3.84e-5) ** (-10.0 / 9.0)

#: Stiffness laws by name.
STIFFNESS_LAWS = ("iso", "palmgren")

#: Default number of slices (odd, so one slice sits at the roller centre).
DEFAULT_SLICES = 31

#: The crown is resolved when P(second-outermost centre) >= this fraction of P(outermost).
RESOLUTION_RATIO = 0.25

#: (N, mm) -> (N, m): x (10^3)^(8/9) for the length and (10^3)^(10/9) for the approach.
_MM_TO_SI = 1.0e6

_E_STEEL = float(effective_modulus(BEARING_STEEL))


def lamina_stiffness(length, E_prime=_E_STEEL, stiffness: str = "iso"):
    r"""Stiffness c_L of a whole roller between two raceways, Q = c_L delta^(10/9).

    .. math:: c_L = C\,(E'/E'_{steel})\,L_{we}^{8/9}\times 10^6 \quad [N/m^{10/9}]

    with ``C`` = 35 948 (ISO/TS 16281) or 37 310 (Palmgren) in N and mm (module notes).

    Parameters
    ----------
    length : float or array_like
        Effective roller length L_we [m].
    E_prime : float or array_like, optional
        Contact modulus E' [Pa] (default that of bearing steel: the constant unscaled).
    stiffness : {"iso", "palmgren"}
        The stiffness law.

    Returns
    -------
    float or ndarray
        c_L [N/m^(10/9)].

    Examples
    --------
    >>> c = lamina_stiffness(1e-3)                  # L_we = 1 mm [N/m^(10/9)]
    >>> round(c / 1e3 ** (10 / 9), 6)               # in N/mm^(10/9): 35 948 x 1^(8/9)
    35948.0
    """
    L = check_positive(length, "length", "m", bounded=True)
    Ep = check_positive(E_prime, "E_prime", "Pa", bounded=True)
    if stiffness not in STIFFNESS_LAWS:
        raise ValueError(f"stiffness must be one of {', '.join(map(repr, STIFFNESS_LAWS))}; "
                         f"got {stiffness!r}")
    C = ISO_LAMINA_CONSTANT if stiffness == "iso" else PALMGREN_CONSTANT
    out = C * _MM_TO_SI * (Ep / _E_STEEL) * L ** (8.0 / 9.0)
    return out if np.ndim(out) else float(out)


def check_slices(n_slices) -> int:
    """The slice count: None -> :data:`DEFAULT_SLICES`; else an odd integer >= 5.

    Parameters
    ----------
    n_slices : int or None
        Number of slices [-].
    """
    if n_slices is None:
        return DEFAULT_SLICES
    if isinstance(n_slices, bool) or not isinstance(n_slices, numbers.Real):
        raise TypeError(f"n_slices must be an odd integer >= 5 (or None for "
                        f"{DEFAULT_SLICES}); got {type(n_slices).__name__} {n_slices!r}")
    if not (math.isfinite(float(n_slices)) and float(n_slices).is_integer()):
        raise ValueError(f"n_slices must be an odd integer >= 5 (e.g. {DEFAULT_SLICES}); "
                         f"got {n_slices!r}")
    n = int(n_slices)
    if n < 5 or n % 2 == 0:
        raise ValueError(f"n_slices must be an odd integer >= 5 (one slice at the roller "
                         f"centre; e.g. {DEFAULT_SLICES}); got {n}")
    return n


def slice_positions(length: float, n_slices: int) -> np.ndarray:
    """Slice centres x_k = (k + 1/2) L/n_s - L/2 from the roller centre [m].

    Parameters
    ----------
    length : float
        Effective roller length L_we [m].
    n_slices : int
        Number of slices [-].

    Examples
    --------
    >>> slice_positions(0.01, 5) * 1e3
    array([-4., -2.,  0.,  2.,  4.])
    """
    w = float(length) / n_slices
    return (np.arange(n_slices) + 0.5) * w - 0.5 * float(length)


def slice_loads(approach, c_L, n_slices: int):
    """Slice loads q = (c_L / n_s) <delta>^(10/9) [N] (0 where delta <= 0).

    Parameters
    ----------
    approach : array_like
        Slice approaches delta [m].
    c_L : float
        Whole-roller stiffness [N/m^(10/9)] (:func:`lamina_stiffness`).
    n_slices : int
        Number of slices [-].

    Examples
    --------
    >>> c = lamina_stiffness(0.01)
    >>> q = slice_loads(np.full(31, 2e-5), c, 31)
    >>> bool(np.isclose(q.sum(), c * 2e-5 ** (10 / 9)))
    True
    """
    d = np.maximum(as_array(approach, "approach", unit="m"), 0.0)
    return (float(c_L) / n_slices) * d ** LINE_EXPONENT


def check_resolution(drops, n_slices: int, what: str = "the roller profile") -> bool:
    """Warn when the slices do not resolve the crown; True when they do.

    The crown is taken as unresolved when the drop at the second-outermost slice centre
    (either end) is below :data:`RESOLUTION_RATIO` of the drop at the outermost one: most
    of the crown then lies inside one slice.

    Parameters
    ----------
    drops : array_like
        Profile drop at the slice centres [m], shape (n_slices,).
    n_slices : int
        Number of slices [-].
    what : str
        Name used in the warning.
    """
    P = np.asarray(drops, float)
    ok = True
    for end, nxt in ((P[0], P[1]), (P[-1], P[-2])):
        if end > 0 and nxt < RESOLUTION_RATIO * end:
            ok = False
    if not ok:
        from ...errors import warn

        warn(f"n_slices = {n_slices}: the slices do not resolve {what} (the drop at the "
             f"second-outermost slice, {min(P[1], P[-2]) * 1e6:.3g} um, is below "
             f"{RESOLUTION_RATIO:g} of that at the outermost, {max(P[0], P[-1]) * 1e6:.3g} "
             "um): most of the crown lies within one slice; give more slices (n_slices, odd)")
    return ok
