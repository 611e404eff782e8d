r"""Hertz contact of two elastic bodies: point (elliptical) and line contact.

Conventions (Hamrock & Dowson 1981, ch. 3; Ricci 2009 §2):

* x is the rolling direction, y the transverse direction, z the depth into the body;
* principal radii ``rx1, ry1`` (body 1) and ``rx2, ry2`` (body 2) are positive for
  convex surfaces, negative for concave ones (a race groove), ``np.inf`` for flat;
* ``1/Rx = 1/rx1 + 1/rx2``, ``1/Ry = 1/ry1 + 1/ry2``, ``1/R = 1/Rx + 1/Ry``;
  radius ratio ``alpha_r = Ry/Rx``; curvature difference ``(1/Rx - 1/Ry) R``;
* ``a >= b`` always: ``a`` is the semi-major axis, lying along y when Ry >= Rx
  (the ball-bearing case) and along x otherwise; ``k = a/b >= 1``;
* ``E'`` is Hamrock & Dowson's effective modulus, twice Johnson's E*
  (:func:`ballrace.analytic.materials.effective_modulus`).

The exact solution needs the ellipticity k from Hertz's transcendental equation

.. math:: \alpha_r = \frac{R_y}{R_x} = \frac{k^2\,\mathcal{E}(m) - \mathcal{K}(m)}
          {\mathcal{K}(m) - \mathcal{E}(m)}, \qquad m = 1 - 1/k^2,

with the complete elliptic integrals K (first kind) and E (second kind).  It is
solved here to 1e-12 relative in k for 1 <= alpha_r <= 1e8.  k, E and D1 = (K - E)/m
are read from piecewise polynomials of alpha_r (256 intervals per octave, degree 4,
indexed by the bits of the float: no logarithm), built once, lazily, in some 20 ms from
exact values (k by Newton's method polished to rounding, E by SciPy's ``ellipe``, D1 by
Carlson's R_D, DLMF 19.25.1) and checked at every interval's midpoint; K = E + m D1.
Hertz's relation, in the form 1 + alpha_r = k^2 E / D1 (no cancellation anywhere, the
circle included), is checked for every contact before anything is returned: with E
and D1 right to rounding its residual bounds the error in k (a few 1e-16; beyond 1e-12,
or if a table were wrong, Newton's method with SciPy's K and E takes over,
``RuntimeError`` with the residual and iteration count if that ever fails).  Measured
max relative error of k, K and E against a 30-digit mpmath reference: 1.1e-15
(``tests/test_hertz_speed.py``, a point in each interval up to alpha_r = 1e6).  The
semi-axes come from one cube root (a bit-level start, one Halley and two Newton steps:
about one rounding error).  Throughput against SciPy's ``ellipk`` + ``ellipe`` alone in
``benchmarks/core_table.py`` (docs/performance.md).  One contact of plain numbers takes
a scalar path with the same operations (bit-for-bit the same result).

Accuracy of the simplified formulas: maximum |relative error| against the exact
solution over 1 <= alpha_r <= alpha_max (4001 log-spaced ratios; regenerate with
``python -m ballrace.analytic.hertz``).  Both fits were made for ball bearings
(alpha_r up to ~100); beyond that they drift badly, so use ``method="exact"``.

=====================  =========  ======= ======= ======= ======= ======= ========  =======
method                 alpha_max  k       E       K       a       b       approach  p_max
=====================  =========  ======= ======= ======= ======= ======= ========  =======
brewe-hamrock-1977     10          3.39 %  1.67 %  2.74 %  2.81 %  0.58 %   5.41 %   2.19 %
brewe-hamrock-1977     100         6.34 %  1.67 %  2.74 %  4.20 %  2.01 %   5.41 %   2.19 %
brewe-hamrock-1977     1e4        49.24 %  1.67 %  2.88 % 30.61 % 12.49 %  21.23 %  12.51 %
hamrock-brewe-1983     10          3.81 %  0.91 %  1.00 %  2.68 %  1.19 %   2.70 %   1.62 %
hamrock-brewe-1983     100         3.81 %  0.91 %  2.10 %  2.68 %  1.19 %   4.10 %   1.62 %
hamrock-brewe-1983     1e4        45.17 %  0.91 %  2.10 % 28.21 % 11.68 %  22.56 %  11.68 %
=====================  =========  ======= ======= ======= ======= ======= ========  =======

The documented bounds are :data:`APPROXIMATION_ERROR` (the table rounded up to
0.1 %) and are asserted by the test suite.
"""
from __future__ import annotations

import functools
import logging
import math
import struct
from dataclasses import dataclass

import numpy as np
from scipy import special

from ._checks import (MAX_MAGNITUDE, MIN_MAGNITUDE, as_array, broadcast, check_choice,
                      check_nonnegative, check_positive)
from .materials import Material, effective_modulus

__all__ = [
    "Curvature",
    "HertzContact",
    "LineContact",
    "METHODS",
    "APPROXIMATION_ERROR",
    "curvature",
    "ellipticity",
    "point_contact",
    "elliptical_contact",
    "contact_stiffness",
    "load_from_approach",
    "line_contact",
    "approximation_errors",
]

log = logging.getLogger(__name__)

METHODS = ("exact", "brewe-hamrock-1977", "hamrock-brewe-1983")

#: The quantities whose errors are bounded, in the order of the module's table.
_QUANTITIES = ("k", "ellipe", "ellipk", "a", "b", "approach", "p_max")


def _bounds(*errors):
    """{quantity: bound} of one row of the table, in the order of ``_QUANTITIES``."""
    return dict(zip(_QUANTITIES, errors))


#: Documented maximum |relative error| of each simplified method:
#: ``APPROXIMATION_ERROR[method][alpha_max][quantity]`` over 1 <= alpha_r <= alpha_max
#: (the module table rounded up to 0.1 %).  Asserted in ``tests/test_hertz.py``.
APPROXIMATION_ERROR = {
    #                                    k      E(e)   K(e)   a      b      delta  p_max
    "brewe-hamrock-1977": {10.0: _bounds(0.034, 0.017, 0.028, 0.029, 0.006, 0.055, 0.022),
                           100.0: _bounds(0.064, 0.017, 0.028, 0.043, 0.021, 0.055, 0.022),
                           1e4: _bounds(0.493, 0.017, 0.029, 0.307, 0.125, 0.213, 0.126)},
    "hamrock-brewe-1983": {10.0: _bounds(0.039, 0.010, 0.010, 0.027, 0.012, 0.027, 0.017),
                           100.0: _bounds(0.039, 0.010, 0.022, 0.027, 0.012, 0.042, 0.017),
                           1e4: _bounds(0.452, 0.010, 0.022, 0.283, 0.117, 0.226, 0.117)},
}

_ALPHA_MAX = 1e8          # largest radius ratio handled (k ~ 1.2e5)
_RTOL_K = 1e-12           # required relative accuracy of k
_SERIES_M = 0.3           # below this m, K - E is summed as a series (_SERIES_TERMS terms)
_SERIES_TERMS = 40        # 0.3^40 ~ 1e-21: exact to rounding for m < 0.3
_MIN, _MAX = np.minimum.reduce, np.maximum.reduce   # ndarray.min/max minus a Python layer


# --------------------------------------------------------------------------- geometry
@dataclass(frozen=True)
class Curvature:
    """Effective radii of two bodies in contact (frozen).

    Attributes
    ----------
    Rx, Ry : float or ndarray
        Effective radius in the rolling (x) and transverse (y) planes [m].
    """

    Rx: np.ndarray
    Ry: np.ndarray

    @property
    def curvature_sum(self):
        """Curvature sum 1/R = 1/Rx + 1/Ry [1/m] (Ricci 2009 eq. 8)."""
        return 1.0 / self.Rx + 1.0 / self.Ry

    @property
    def R(self):
        """Curvature-sum radius R = 1/(1/Rx + 1/Ry) [m] (Hamrock & Dowson 1981 eq. 3.2)."""
        return 1.0 / self.curvature_sum

    @property
    def curvature_difference(self):
        """Curvature difference (1/Rx - 1/Ry) R [-] (Ricci 2009 eq. 9)."""
        return (1.0 / self.Rx - 1.0 / self.Ry) * self.R

    @property
    def alpha_r(self):
        """Radius ratio Ry/Rx [-] (Hamrock & Dowson 1981 eq. 3.6)."""
        return self.Ry / self.Rx


def curvature(rx1, ry1, rx2, ry2) -> Curvature:
    r"""Effective radii of two bodies from their principal radii.

    .. math:: \frac{1}{R_x} = \frac{1}{r_{x1}} + \frac{1}{r_{x2}}, \qquad
              \frac{1}{R_y} = \frac{1}{r_{y1}} + \frac{1}{r_{y2}}

    Parameters
    ----------
    rx1, ry1 : float or array_like
        Principal radii of body 1 in the x (rolling) and y planes [m];
        negative for concave, ``np.inf`` for flat.
    rx2, ry2 : float or array_like
        Principal radii of body 2 [m], same convention.

    Returns
    -------
    Curvature
        ``Rx``, ``Ry`` [m] and derived curvature sum and difference.

    Raises
    ------
    ValueError
        When a radius is zero or NaN, or when the curvature sum in a plane is not
        positive (a concave body as curved as, or more curved than, the convex one:
        the bodies would conform and Hertz theory does not apply).

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.1)–(3.3); Ricci (2009) eqs. (8)–(11).

    Examples
    --------
    Ball of 12.7 mm diameter in a groove of radius 0.52 D, on a flat in rolling:

    >>> c = curvature(6.35e-3, 6.35e-3, np.inf, -0.52 * 12.7e-3)
    >>> round(float(c.Rx) * 1e3, 4), round(float(c.Ry) * 1e3, 4)
    (6.35, 165.1)
    """
    radii = {name: _radius(r, name) for name, r in
             (("rx1", rx1), ("ry1", ry1), ("rx2", rx2), ("ry2", ry2))}
    inv = dict(zip(radii, (1.0 / r for r in broadcast(**radii))))
    cx = inv["rx1"] + inv["rx2"]
    cy = inv["ry1"] + inv["ry2"]
    for plane, c, n1, n2 in (("x", cx, "rx1", "rx2"), ("y", cy, "ry1", "ry2")):
        if np.any(c <= 0):
            raise ValueError(
                f"curvature sum in the {plane} plane, 1/{n1} + 1/{n2}, must be > 0 [1/m]; "
                f"got {float(np.min(c)):g}. Zero means a line (cylinder) contact "
                "(use line_contact); negative means the concave body is more curved than "
                "the convex one (inconsistent for a Hertz contact)")
    return Curvature(Rx=_scalar(1.0 / cx), Ry=_scalar(1.0 / cy))


def _radius(r, name: str) -> np.ndarray:
    """A principal radius: non-zero, finite or inf (flat), of physical magnitude [m]."""
    arr = as_array(r, name, allow_inf=True, bounded=True, unit="m")
    if np.any(arr == 0):
        raise ValueError(f"{name} must be non-zero (use np.inf for a flat surface) [m]")
    return arr


# --------------------------------------------------------------------------- ellipticity
def _ellip_parts(k: np.ndarray):
    """Return (ln alpha_r(k), K(m), E(m)) for k >= 1 without cancellation near k = 1.

    Uses alpha_r = (E - (1-m) K) / ((1-m)(K - E)) = D2 / (p D1) with p = 1/k^2,
    D1 = (K - E)/m, D2 = (E - pK)/m = K - D1 (Hamrock & Dowson 1981 eq. 3.14 rearranged).
    """
    p = 1.0 / (k * k)
    m = 1.0 - p
    K = special.ellipkm1(p)           # K(m) with m = 1 - p; accurate as m -> 1
    E = special.ellipe(m)
    with np.errstate(divide="ignore", invalid="ignore"):
        D1 = np.atleast_1d((K - E) / m)
    small = np.atleast_1d(m < _SERIES_M)
    if np.any(small):
        ks = np.atleast_1d(k)[small]
        D1[small] = _d1_series((ks - 1.0) * (ks + 1.0) / (ks * ks))
    D1 = D1.reshape(np.shape(m))
    return np.log((K - D1) / (p * D1)), K, E


@functools.cache
def d1_series_coefficients(n_terms: int = 17) -> np.ndarray:
    """Coefficients (highest power first, for ``np.polyval``) of (K(m) - E(m))/m.

    K - E = (pi/2) sum_{n>=1} c_n 2n/(2n-1) m^n, c_n = [(2n)!/(4^n n!^2)]^2
    (Abramowitz & Stegun 1964, eqs. 17.3.11–17.3.12); 17 terms are exact to rounding
    for m < 0.05.  Shared by the stiffness derivatives in :mod:`ballrace.analytic.loaddist`.
    """
    coef = []
    c = 1.0
    for n in range(1, n_terms + 1):
        c *= ((2 * n - 1) / (2 * n)) ** 2
        coef.append(0.5 * np.pi * c * 2 * n / (2 * n - 1))      # coefficient of m^(n-1)
    return np.array(coef[::-1])


def _d1_series(m: np.ndarray) -> np.ndarray:
    """(K(m) - E(m))/m by its power series (:func:`d1_series_coefficients`), m < 0.3.

    K - E loses about log10(4/(3m)) digits to cancellation; the series below m = 0.3
    keeps Hertz's relation within a few rounding errors in :func:`_solve_k_newton`.
    """
    return np.polyval(d1_series_coefficients(_SERIES_TERMS), m)


_TABLE_N = 4096                       # intervals of the ln k(ln alpha) table


@functools.cache
def _table():
    """Cubic-Hermite table of u = ln k on a uniform grid of v = ln alpha_r in [0, ln 1e8].

    Built once (lazily) from the exact relation: a dense spline in u gives starting
    values, which vectorized Newton iterations polish to rounding; the slopes du/dv
    come from the same relation.  Returns (h, u_nodes, slope_nodes).
    """
    uu = np.linspace(0.0, np.log(1.3e5), 3001)
    vv, _, _ = _ellip_parts(np.exp(uu))
    vv[0] = 0.0
    h = np.log(_ALPHA_MAX) / _TABLE_N
    v = h * np.arange(_TABLE_N + 2)
    u = np.interp(v, vv, uu)                             # start, error ~1e-6
    s = np.interp(v, vv, np.gradient(uu, vv))            # approximate du/dv
    for _ in range(6):                                   # Newton polish of the nodes
        r, _, _ = _ellip_parts(np.exp(u))
        u = u - s * (r - v)
    u[0] = 0.0
    # slopes by a 4th-order central difference of the exact inverse relation
    d = 1e-3
    w = [_ellip_parts(np.exp(u + j * d))[0] for j in (-2, -1, 1, 2)]
    dv = (w[0] - 8 * w[1] + 8 * w[2] - w[3]) / (12 * d)
    dv[0] = (-25 * 0 + 48 * w[2][0] - 36 * _ellip_parts(np.exp(u[:1] + 2 * d))[0][0]
             + 16 * _ellip_parts(np.exp(u[:1] + 3 * d))[0][0]
             - 3 * _ellip_parts(np.exp(u[:1] + 4 * d))[0][0]) / (12 * d)
    return h, u, 1.0 / dv


def _table_lookup(v: np.ndarray):
    """Hermite interpolation of u(v) and du/dv from :func:`_table`."""
    h, un, sn = _table()
    x = v / h
    i = np.minimum(x.astype(np.intp), _TABLE_N)
    t = x - i
    u0, u1 = un[i], un[i + 1]
    s0, s1 = sn[i] * h, sn[i + 1] * h
    # Hermite basis: value and derivative (d/dt) of the cubic
    du = u1 - u0
    c2 = 3.0 * du - 2.0 * s0 - s1
    c3 = s0 + s1 - 2.0 * du
    u = u0 + t * (s0 + t * (c2 + t * c3))
    dudv = (s0 + t * (2.0 * c2 + 3.0 * c3 * t)) / h
    return u, dudv


def _solve_k_newton(alpha: np.ndarray):
    """Ellipticity k(alpha) for alpha >= 1 by Newton's method from the Hermite table.

    One Newton step from :func:`_table`'s start, then more while the residual says the
    relative error in k exceeds 1e-12.  The fallback of :func:`_solve_k` where the check
    of Hertz's relation fails (never so far).  Returns (k, K, E).
    """
    v = np.log(alpha)
    u, s = _table_lookup(v)
    r, _, _ = _ellip_parts(np.exp(u))
    u -= s * (r - v)                                     # one Newton step
    k = np.exp(u)
    r, K, E = _ellip_parts(k)
    err = np.abs(s * (r - v))
    it = 0
    while np.any(err > _RTOL_K):
        it += 1
        if it > 20:
            i = int(np.argmax(err))
            raise RuntimeError(
                f"Hertz ellipticity did not converge: residual {err.flat[i]:.3e} "
                f"(relative in k) after {it} iterations at alpha_r={alpha.flat[i]!r}")
        bad = err > _RTOL_K
        u = np.where(bad, u - s * (r - v), u)
        k = np.exp(u)
        r, K, E = _ellip_parts(k)
        err = np.abs(s * (r - v))
    if it:
        log.debug("ellipticity: %d extra Newton iterations", it)
    k = np.where(alpha == 1.0, 1.0, k)
    return k, K, E


_OCT_BITS = 8                          # 2^8 = 256 intervals per octave of alpha_r
_SHIFT = 52 - _OCT_BITS                # float64 bits >> _SHIFT: exponent and top mantissa bits
_FRAC_MASK = (1 << _SHIFT) - 1         # the remaining mantissa bits: position in the interval
_ONE_BITS = int(np.array(1.0).view(np.int64))     # the bits of 1.0 (its low 52 bits are 0)
_IDX0 = _ONE_BITS >> _SHIFT
_DEG = 4                               # polynomial degree of k, E, D1 on each interval
_TABLE_TOL = 2e-15                     # largest relative error allowed when built


def _ellip_e_d1(k: np.ndarray):
    """E(m) and D1 = (K(m) - E(m))/m at m = 1 - 1/k^2, both to a few rounding errors.

    Below m = 0.9 (k < 3.2), where K - E cancels, D1 = R_D(0, 1 - m, 1)/3 (Carlson's
    symmetric integral; DLMF 19.25.1: K - E = (m/3) R_D(0, 1 - m, 1)); above, (K - E)/m
    loses at most a bit and costs a tenth.
    """
    p = 1.0 / (k * k)
    m = 1.0 - p
    E = special.ellipe(m)
    D1 = (special.ellipkm1(p) - E) / m
    near = m < 0.9
    D1[near] = special.elliprd(0.0, p[near], 1.0) / 3.0
    return E, D1


def _exact_nodes(alpha: np.ndarray):
    """k, E, D1 at radius ratios alpha > 1 to rounding (table building).

    Newton's method on Hertz's relation in the form k^2 E / D1 = 1 + alpha_r (no
    cancellation, no logarithm) from :func:`_table`'s start (~1e-14: one step reaches
    rounding); ``RuntimeError`` unless the final residual bounds the relative error in k
    by :data:`_TABLE_TOL`.
    """
    u, s = _table_lookup(np.log(alpha))                  # ln k, d ln k / d ln alpha_r
    g = s * (1.0 + alpha) / alpha                         # d ln k / d ln(1 + alpha_r)
    k = np.exp(u)
    for it in range(2):
        E, D1 = _ellip_e_d1(k)
        F = k * k * E / (D1 * (1.0 + alpha)) - 1.0       # relative residual in 1 + alpha_r
        if it == 0:
            k = k - k * F * g
    err = float(np.max(np.abs(F * g)))
    if not err <= _TABLE_TOL:
        raise RuntimeError(f"Hertz ellipticity tables: Newton residual {err:.2e} (relative "
                           f"in k) after one step (> {_TABLE_TOL:g})")
    return k, E, D1


def _interval_points(t: np.ndarray, n: int) -> np.ndarray:
    """alpha_r at positions t in [0, 1) of each of the first n intervals (shape (n, len(t)))."""
    i = np.arange(n)
    e, j = i >> _OCT_BITS, i & ((1 << _OCT_BITS) - 1)
    width = np.ldexp(1.0, e - _OCT_BITS)
    return np.ldexp(1.0, e)[:, None] + width[:, None] * (j[:, None] + t[None, :])


@functools.cache
def _poly_table():
    """Piecewise polynomials of k, E and D1 = (K - E)/m in alpha_r, 256 intervals per octave.

    Interval i = 256 e + j covers alpha_r in [2^e (1 + j/256), 2^e (1 + (j + 1)/256)),
    1 <= alpha_r <= 1e8; it is read from the bits of the float64 alpha_r (exponent and the
    top eight mantissa bits), and the remaining mantissa bits are the position t in [0, 1)
    inside it, so neither a logarithm nor an exponential is needed.  On each interval each
    quantity is the degree-4 polynomial through its exact values at five Chebyshev points
    of t (:func:`_exact_nodes`: k by Newton's method polished to rounding, E(m) by SciPy's
    ``ellipe``, D1 by Carlson's R_D, both within 3e-16 of a 30-digit reference).  Built
    once, lazily (some 20 ms), and checked at every interval's midpoint against the same
    exact values: ``RuntimeError`` if any is off by more than 2e-15 relative (measured
    max 1.1e-15 against 30-digit mpmath, ``tests/test_hertz_speed.py``).

    Returns (coefs, s_max, pair): ``coefs`` the coefficient arrays of k, E, D1, each of
    shape (5, n), row d the coefficients of f^d, f = t/256 = the low 44 mantissa bits
    times 2^-52 (those of t^d times 256^d, an exact scaling); s_max >= d ln k / d ln
    alpha_r, which turns the residual of Hertz's relation into a bound on the relative
    error in k (:func:`_check_relation`); ``pair`` those of k and D1 interleaved
    (:func:`_pair`).
    """
    n = ((int(np.array(_ALPHA_MAX).view(np.int64)) >> _SHIFT) - _IDX0) + 1
    tc = 0.5 - 0.5 * np.cos((2 * np.arange(_DEG + 1) + 1) * np.pi / (2 * _DEG + 2))
    V = np.vander(tc, _DEG + 1, increasing=True)          # values at tc = V coef
    scale = np.ldexp(1.0, _OCT_BITS * np.arange(_DEG + 1))[:, None]    # t^d -> f^d
    exact = _exact_nodes(_interval_points(tc, n).ravel())
    coefs = []
    for y, circle in zip(exact, (1.0, 0.5 * np.pi, 0.25 * np.pi)):
        c = np.linalg.solve(V, y.reshape(n, _DEG + 1).T)
        c[0, 0] = circle                                  # alpha_r = 1 exactly: k = 1, pi/2, pi/4
        coefs.append(np.ascontiguousarray(c * scale))
    coefs = tuple(coefs)
    exact = _exact_nodes(_interval_points(np.array([0.5]), n).ravel())   # the midpoints
    f = np.full(n, 0.5 * 2.0 ** -_OCT_BITS)
    idx = np.arange(n)
    for c, y in zip(coefs, exact):
        err = float(np.max(np.abs(_horner(c, idx, f, np.empty(n), np.empty(n)) / y - 1.0)))
        if not err <= _TABLE_TOL:
            raise RuntimeError(f"Hertz ellipticity tables: relative error {err:.2e} at an "
                               f"interval midpoint (> {_TABLE_TOL:g})")
    s_max = 1.05 * float(np.max(_table()[2]))
    return coefs, s_max, _pair(coefs[0], coefs[2])


def _pair(ck: np.ndarray, cD: np.ndarray) -> np.ndarray:
    """The coefficients of k and D1 side by side, shape (5, n, 2): one gather of 16 bytes
    per contact and degree fetches both (:func:`_ellipticity_kernel`)."""
    return np.ascontiguousarray(np.stack([ck, cD], axis=-1))


def _horner(c: np.ndarray, idx: np.ndarray, f: np.ndarray, out: np.ndarray, w: np.ndarray):
    """sum_d c[d, idx] f^d into ``out`` by Horner's rule (``w``: work array)."""
    deg = len(c) - 1
    c[deg].take(idx, out=out, mode="wrap")               # indices are in range
    for d in range(deg - 1, -1, -1):
        np.multiply(out, f, out=out)
        c[d].take(idx, out=w, mode="wrap")
        np.add(out, w, out=out)
    return out


def _ellipticity_kernel(alpha, k, K, E, r, kk, D1, w, idx, fbits, pbuf):
    """k, K, E of ``alpha`` (contiguous float64 in [1, 1e8]) and the check of Hertz's relation.

    Writes into the given arrays of alpha's length: ``k`` and ``E`` from
    :func:`_poly_table`, ``K`` = E + m D1 (m = 1 - 1/k^2, D1 = (K - E)/m tabulated too),
    ``kk`` = k^2, ``w`` = 1 + alpha_r and ``r`` = k^2 E / (D1 (1 + alpha_r)), which is 1
    by Hertz's relation alpha_r = (k^2 E - K)/(K - E) (Hamrock & Dowson 1981 eq. 3.14) in
    the form 1 + alpha_r = k^2 E / D1: no cancellation anywhere, the circle included.
    ``D1`` (float), ``idx`` and ``fbits`` (int64) and ``pbuf`` (float, 6 times alpha's
    length) are work arrays.  k and D1 are evaluated together, on their coefficients side
    by side (:func:`_pair`): the same operations per value as :func:`_horner`, half the
    gathers.  Returns (min r, max r).  :func:`_solve_k_scalar` repeats these operations
    for one Python float.
    """
    (_, cE, _), _, pair = _poly_table()
    bits = alpha.view(np.int64)
    np.subtract(bits, _ONE_BITS, out=idx)                # interval: exponent and top bits
    np.right_shift(idx, _SHIFT, out=idx)
    np.bitwise_and(bits, _FRAC_MASK, out=fbits)          # position: 1 + f, f in [0, 1/256)
    np.bitwise_or(fbits, _ONE_BITS, out=fbits)
    f = fbits.view(np.float64)
    np.subtract(f, 1.0, out=f)                            # exact
    n = alpha.size
    acc, f2, g = (pbuf[i * 2 * n:(i + 1) * 2 * n] for i in range(3))   # (k, D1) interleaved
    acc2, f22, g2 = (x.reshape(n, 2) for x in (acc, f2, g))
    f22[:, 0] = f
    f22[:, 1] = f
    pair[_DEG].take(idx, axis=0, out=acc2, mode="wrap")
    for d in range(_DEG - 1, -1, -1):
        np.multiply(acc, f2, out=acc)
        pair[d].take(idx, axis=0, out=g2, mode="wrap")
        np.add(acc, g, out=acc)
    np.copyto(k, acc2[:, 0])
    np.copyto(D1, acc2[:, 1])
    _horner(cE, idx, f, E, w)
    np.multiply(k, k, out=kk)
    np.divide(D1, kk, out=K)                              # K = E + (D1 - D1/k^2)
    np.subtract(D1, K, out=K)
    np.add(E, K, out=K)
    np.add(alpha, 1.0, out=w)                             # Hertz's relation
    np.multiply(w, D1, out=D1)
    np.multiply(kk, E, out=r)
    np.divide(r, D1, out=r)
    return float(_MIN(r)), float(_MAX(r))


def _check_relation(alpha, k, K, E, r, lo, hi):
    """Where the residual bounds the relative error in k above 1e-12: Newton's method.

    alpha_r(k)/alpha_r - 1 = (r - 1)(1 + 1/alpha_r), at most 2 |r - 1|, and s_max times it
    bounds the relative error in k (a few 1e-16 with the tables).  Beyond 1e-12,
    :func:`_solve_k_newton` (K, E from SciPy) replaces k, K, E.
    """
    tol = _RTOL_K / (2.0 * _poly_table()[1])
    if not (1.0 - lo <= tol and hi - 1.0 <= tol):
        bad = ~(np.abs(r - 1.0) <= tol)
        log.debug("ellipticity: %d values polished by Newton", int(bad.sum()))
        kb, Kb, Eb = _solve_k_newton(alpha[bad])
        k[bad], K[bad], E[bad] = kb, Kb, Eb


def _solve_k(alpha: np.ndarray):
    """Ellipticity k(alpha) for alpha >= 1 to 1e-12 relative; returns (k, K, E).

    k, K and E from :func:`_poly_table` and Hertz's relation checked
    (:func:`_ellipticity_kernel`, :func:`_check_relation`).
    """
    shape = np.shape(alpha)
    alpha = np.array(alpha, dtype=float, copy=None).reshape(-1)    # contiguous, 1-d
    if not alpha.flags.c_contiguous:
        alpha = alpha.copy()
    n = alpha.size
    k, K, E, r, kk, D1, w = np.empty((7, n))
    if n == 0:
        return k.reshape(shape), K.reshape(shape), E.reshape(shape)
    idx, fbits = np.empty((2, n), dtype=np.int64)
    lo, hi = _ellipticity_kernel(alpha, k, K, E, r, kk, D1, w, idx, fbits, np.empty(6 * n))
    _check_relation(alpha, k, K, E, r, lo, hi)
    return k.reshape(shape), K.reshape(shape), E.reshape(shape)


_FLOAT64, _INT64 = struct.Struct("d"), struct.Struct("q")
_F_SCALE = 2.0 ** -52


def _scalar_rows(coefs, s_max):
    """The tables for :func:`_solve_k_scalar`: per interval the coefficients c0 ... c4 of
    k, E and D1 in one row (shape (n, 15)), an empty cache of those rows as tuples of
    Python floats (filled as intervals are used), and the check's tolerance."""
    return np.ascontiguousarray(np.concatenate(coefs, axis=0).T), {}, _RTOL_K / (2.0 * s_max)


@functools.cache
def _scalar_table():
    coefs, s_max, _ = _poly_table()
    return _scalar_rows(coefs, s_max)


def _solve_k_scalar(alpha: float):
    """:func:`_solve_k` for one Python float, the same operations in the same order
    (Horner's rule unrolled for degree 4; bit-for-bit the same result,
    ``tests/test_speed_paths.py``)."""
    bits = _INT64.unpack(_FLOAT64.pack(alpha))[0]
    f = float(bits & _FRAC_MASK) * _F_SCALE              # = (1 + f) - 1 of the array path
    table, rows, tol = _scalar_table()
    i = (bits - _ONE_BITS) >> _SHIFT
    row = rows.get(i)
    if row is None:
        row = rows[i] = tuple(table[i].tolist())
    k0, k1, k2, k3, k4, e0, e1, e2, e3, e4, d0, d1, d2, d3, d4 = row
    k = (((k4 * f + k3) * f + k2) * f + k1) * f + k0
    E = (((e4 * f + e3) * f + e2) * f + e1) * f + e0
    D1 = (((d4 * f + d3) * f + d2) * f + d1) * f + d0
    kk = k * k
    K = E + (D1 - D1 / kk)
    r = kk * E / ((alpha + 1.0) * D1)
    if not (1.0 - r <= tol and r - 1.0 <= tol):
        kb, Kb, Eb = _solve_k_newton(np.array([alpha]))
        return float(kb[0]), float(Kb[0]), float(Eb[0])
    return k, K, E


def _approx_k(alpha: np.ndarray, method: str):
    """Simplified ellipticity and elliptic integrals (k, K, E) for alpha >= 1."""
    if method == "brewe-hamrock-1977":
        # Brewe & Hamrock (1977) J. Lubr. Technol. 99(4) 485-487; H&D (1981) eqs. 3.28-3.30
        k = 1.0339 * alpha**0.6360
        E = 1.0003 + 0.5968 / alpha
        K = 1.5277 + 0.6023 * np.log(alpha)
    else:
        # Hamrock & Brewe (1983) J. Lubr. Technol. 105(2) 171-177, eqs. (8)-(10)
        q = 0.5 * np.pi - 1.0
        k = alpha ** (2.0 / np.pi)
        E = 1.0 + q / alpha
        K = 0.5 * np.pi + q * np.log(alpha)
    return k, K, E


def _ellipticity(alpha: np.ndarray, method: str):
    """Internal: (k, K, E) for alpha >= 1, validated already."""
    if method == "exact":
        return _solve_k(alpha)
    return _approx_k(alpha, method)


def ellipticity(alpha_r, method: str = "exact"):
    r"""Ellipticity k = a/b and the elliptic integrals of an elliptical Hertz contact.

    Solves Hertz's transcendental equation (Hamrock & Dowson 1981 eq. 3.14; Ricci 2009
    eq. 14) in the form

    .. math:: \alpha_r = \frac{k^2\,\mathcal{E} - \mathcal{K}}{\mathcal{K} - \mathcal{E}},
              \quad m = 1 - k^{-2}

    to 1e-12 relative in k, or evaluates one of the simplified formulas.

    Parameters
    ----------
    alpha_r : float or array_like
        Radius ratio, the larger effective radius over the smaller [-]; values below
        1 are inverted (the axes are swapped), so k >= 1 always.  Must be in
        [1e-8, 1e8].
    method : {"exact", "brewe-hamrock-1977", "hamrock-brewe-1983"}
        Exact solution or simplified formula.

    Returns
    -------
    k : ndarray
        Ellipticity a/b >= 1 [-].
    ellipk, ellipe : ndarray
        Complete elliptic integrals of the first and second kind at m = 1 - 1/k^2 [-]
        (their approximations for the simplified methods).

    Examples
    --------
    >>> k, K, E = ellipticity(1.0)
    >>> float(k), round(float(K), 12) == round(np.pi / 2, 12)
    (1.0, True)
    >>> k, K, E = ellipticity(np.array([10.0, 100.0]))
    >>> np.round(k, 6)
    array([ 4.499447, 18.187103])
    """
    check_choice(method, "method", METHODS)
    alpha = check_positive(alpha_r, "alpha_r", "-")
    alpha = np.where(alpha < 1.0, 1.0 / alpha, alpha)
    if np.any(alpha > _ALPHA_MAX):
        raise ValueError(f"alpha_r must be in [1e-8, 1e8] [-]; got {float(np.max(alpha)):g} "
                         "(close to line contact: use line_contact)")
    k, K, E = _ellipticity(alpha, method)
    return _scalar(k), _scalar(K), _scalar(E)


# --------------------------------------------------------------------------- point contact
@dataclass(frozen=True)
class HertzContact:
    """Result of an elliptical Hertz contact (frozen).  Arrays when inputs were arrays.

    Attributes
    ----------
    load : Normal load Q [N].
    Rx, Ry : Effective radii in the rolling and transverse planes [m].
    E_prime : Hamrock–Dowson effective modulus E' = 2E* [Pa].
    k : Ellipticity a/b >= 1 [-].
    a, b : Semi-major and semi-minor axes of the contact ellipse [m]; a >= b.
    approach : Mutual approach of distant points of the two bodies, delta [m].
    p_max : Maximum (central) contact pressure p0 [Pa].
    stiffness : Load-deflection constant K with Q = K delta^1.5 [N/m^1.5].
    ellipk, ellipe : Complete elliptic integrals of the first and second kind [-].
    method : Solution method used.
    """

    load: np.ndarray
    Rx: np.ndarray
    Ry: np.ndarray
    E_prime: np.ndarray
    k: np.ndarray
    a: np.ndarray
    b: np.ndarray
    approach: np.ndarray
    p_max: np.ndarray
    stiffness: np.ndarray
    ellipk: np.ndarray
    ellipe: np.ndarray
    method: str = "exact"

    @property
    def R(self):
        """Curvature-sum radius 1/(1/Rx + 1/Ry) [m]."""
        return self.Rx * self.Ry / (self.Rx + self.Ry)

    @property
    def alpha_r(self):
        """Radius ratio Ry/Rx [-] (below 1 when the major axis lies along x)."""
        return self.Ry / self.Rx

    @property
    def p_mean(self):
        """Mean contact pressure Q/(pi a b) = 2/3 p_max [Pa]."""
        return 2.0 / 3.0 * self.p_max

    @property
    def area(self):
        """Contact area pi a b [m^2]."""
        return np.pi * self.a * self.b

    @property
    def major_axis_along_y(self):
        """True where the semi-major axis a lies along y (Ry >= Rx)."""
        return np.asarray(self.Ry >= self.Rx)[()]

    @property
    def semi_axis_x(self):
        """Semi-axis of the ellipse along the rolling direction x [m]."""
        return np.where(self.major_axis_along_y, self.b, self.a)[()]

    @property
    def semi_axis_y(self):
        """Semi-axis of the ellipse along the transverse direction y [m]."""
        return np.where(self.major_axis_along_y, self.a, self.b)[()]

    def pressure(self, x, y):
        r"""Hertz pressure p0 sqrt(1 - (x/ax)^2 - (y/ay)^2) at surface point (x, y) [Pa].

        Parameters
        ----------
        x, y : float or array_like
            Coordinates along the rolling and transverse directions [m]; broadcast
            against the contact's shape.

        References
        ----------
        Hertz (1882); Johnson (1985) eq. (4.35).
        """
        s = 1.0 - (np.asarray(x) / self.semi_axis_x) ** 2 - (np.asarray(y) / self.semi_axis_y) ** 2
        return self.p_max * np.sqrt(np.clip(s, 0.0, None))


def _radius_ratio(Rx, Ry) -> np.ndarray:
    """Larger over smaller effective radius, checked against the ellipticity solver's range."""
    alpha = np.maximum(Rx, Ry)
    alpha /= np.minimum(Rx, Ry)
    if not alpha.max(initial=1.0) <= _ALPHA_MAX:
        raise ValueError(f"radius ratio Ry/Rx must be in [1e-8, 1e8] [-]; got "
                         f"{float(np.max(alpha)):g} (close to line contact: use line_contact)")
    return alpha


def _contact_from_parts(Q, Rx, Ry, Ep, method) -> HertzContact:
    r"""Internal: contact for validated, broadcast arrays.

    Hamrock & Dowson (1981) eqs. 3.8-3.16, 3.33; Ricci (2009) eqs. 12-13.  The exact
    method runs :func:`_exact_kernel` on blocks that stay in cache; the simplified ones
    :func:`_contact_arrays`.
    """
    if method == "exact":
        out = _contact_exact(Q, Rx, Ry, Ep)
    elif np.ndim(Q) == 1 and np.size(Q) > 2 * _BLOCK_SIMPLIFIED:
        n = np.size(Q)
        out = [np.empty(n) for _ in range(8)]
        for i in range(0, n, _BLOCK_SIMPLIFIED):
            j = min(i + _BLOCK_SIMPLIFIED, n)
            for dst, v in zip(out, _contact_arrays(Q[i:j], Rx[i:j], Ry[i:j], Ep[i:j],
                                                   method)):
                dst[i:j] = v
    else:
        out = _contact_arrays(Q, Rx, Ry, Ep, method)
    k, a, b, approach, p_max, stiffness, K, E = out
    s = _scalar
    return HertzContact(load=s(Q), Rx=s(Rx), Ry=s(Ry), E_prime=s(Ep), k=s(k), a=s(a), b=s(b),
                        approach=s(approach), p_max=s(p_max), stiffness=s(stiffness),
                        ellipk=s(K), ellipe=s(E), method=method)


_BLOCK = 32768                         # elements per block of the exact vectorized contact
_BLOCK_SIMPLIFIED = 8192               # the same for the simplified methods
_SMALL = 16                            # arrays up to this size: the scalar path per contact
_PI_6 = np.pi / 6.0
_STIFF = np.pi * math.sqrt(2.0) / 3.0   # pi k E' sqrt(2 E R / (9 K^3)) = this k E' sqrt(ER/K)/K
_CBRT_MAGIC = 0x2A9F7893782DA1CE        # bits of a first cube root: bits(c)/3 + this
_THIRD = 1.0 / 3.0


def _contact_exact(Q, Rx, Ry, Ep):
    """(k, a, b, approach, p_max, stiffness, K, E) of the exact method, any shape.

    Flattened, in blocks of :data:`_BLOCK` contacts written into one preallocated output
    (the temporaries of a whole 10^5-element array would be fresh megabyte allocations
    and cache misses); up to :data:`_SMALL` contacts one by one with
    :func:`_exact_scalar` (the same bits, without the kernel's hundred NumPy calls).  A
    modulus that is one number broadcast (zero strides) enters the kernel as a Python
    float: the same products, without a pass for them.
    """
    shape = np.shape(Q)
    n = int(np.size(Q))
    if n == 0:
        return [np.empty(shape) for _ in range(8)]
    if n <= _SMALL:                                      # contact by contact: same bits
        rows = [_exact_scalar(*v) for v in zip(*(np.ravel(x).tolist() for x in (Q, Rx, Ry, Ep)))]
        if None in rows:
            _radius_ratio(Rx, Ry)                      # raises, worded for the whole array
        return list(np.array(rows).T.copy().reshape((8, *shape)))
    Q, Rx, Ry = (np.reshape(x, -1) for x in (Q, Rx, Ry))
    Ep = np.asarray(Ep)
    ep = float(Ep.flat[0]) if not any(Ep.strides) else np.reshape(Ep, -1)
    out = np.empty((8, n))
    nb = min(n, _BLOCK)
    work = np.empty((6, nb))
    iwork = np.empty((2, nb), dtype=np.int64)
    pbuf = np.empty(6 * nb)
    for i in range(0, n, nb):
        j = min(i + nb, n)
        L = j - i
        if not _exact_kernel(Q[i:j], Rx[i:j], Ry[i:j], ep if type(ep) is float else ep[i:j],
                             out[:, i:j], work[:, :L], iwork[:, :L], pbuf[:6 * L]):
            _radius_ratio(Rx, Ry)                      # raises, worded for the whole array
    return [v.reshape(shape) for v in out]


def _exact_kernel(Q, Rx, Ry, ep, out, w, iw, pbuf) -> bool:
    r"""The exact contact of one block, in place: no allocation per operation.

    Writes ``out`` = (k, a, b, approach, p_max, stiffness, K, E); ``w`` (6 float),
    ``iw`` (2 int64) and ``pbuf`` (float, 6 times the block) are work arrays; ``ep`` is E'
    (array or float).  With k, K, E from
    :func:`_ellipticity_kernel` (checked by :func:`_check_relation`),
    R = Rx Ry/(Rx + Ry) = max(Rx, Ry)/(1 + alpha_r) and one cube root
    (:func:`_cbrt_kernel`),

    .. math:: b = \left(\frac{6 \mathcal{E} R Q}{\pi k E'}\right)^{1/3}, \quad a = k b,
              \quad \delta = \frac{\mathcal{K} b^2}{2 \mathcal{E} R}, \quad
              p_{max} = \frac{3 Q}{2 \pi a b} = \frac{E' b}{4 \mathcal{E} R}, \quad
              K_c = \pi k E' \left(\frac{2 \mathcal{E} R}{9 \mathcal{K}^3}\right)^{1/2}

    (the p_max form follows from b^3; it is 0 for Q = 0 without a special case).
    Returns False when a radius ratio exceeds 1e8 (nothing else computed).
    :func:`_contact_scalar` repeats these operations for one contact.
    """
    k, a, b, approach, p_max, stiff, K, E = out
    mx, mn, alpha, kk, D1, t = w
    np.maximum(Rx, Ry, out=mx)
    np.minimum(Rx, Ry, out=mn)
    np.divide(mx, mn, out=alpha)
    if not _MAX(alpha) <= _ALPHA_MAX:
        return False
    r = a                                                # a, b: work space until the end
    lo, hi = _ellipticity_kernel(alpha, k, K, E, r, kk, D1, t, iw[0], iw[1], pbuf)
    _check_relation(alpha, k, K, E, r, lo, hi)
    ER, c = kk, D1
    np.divide(mx, t, out=ER)                             # R = Rx Ry/(Rx + Ry) = max/(1 + alpha_r)
    np.multiply(E, ER, out=ER)                           # E R
    np.multiply(ER, Q, out=c)
    np.divide(c, ep * _PI_6, out=c)
    np.divide(c, k, out=c)
    _cbrt_kernel(c, b, alpha, mn, iw[0])
    np.multiply(b, k, out=a)
    h = t
    np.add(ER, ER, out=h)
    np.divide(b, h, out=h)                               # b / (2 E R)
    np.multiply(h, ep * 0.5, out=p_max)
    np.multiply(K, b, out=approach)
    np.multiply(approach, h, out=approach)
    np.divide(ER, K, out=ER)
    np.sqrt(ER, out=ER)
    np.divide(ER, K, out=ER)
    np.multiply(ER, k, out=ER)
    np.multiply(ER, ep * _STIFF, out=stiff)
    return True


def _cbrt_kernel(c, y, t, u, ibuf):
    """Cube root of ``c`` >= 0 into ``y``, to about one rounding error (3e-16 measured).

    A first value from the bits (the exponent divided by 3: relative error below 3.2 %),
    one Halley step y (y^3 + 2c)/(2y^3 + c) (error ~1e-5) and two Newton steps
    y - (y - c/y^2)/3 (~1e-10, then rounding): some 20 cheap passes instead of
    ``np.cbrt``'s libm call per element, which costs as much as an elliptic integral.
    Exactly 0 for c = 0.  ``t``, ``u`` (float), ``ibuf`` (int64): work arrays.
    :func:`_cbrt_scalar` repeats these operations for one Python float.
    """
    yi = y.view(np.int64)
    np.floor_divide(c.view(np.int64), 3, out=yi)
    np.add(yi, _CBRT_MAGIC, out=yi)
    np.multiply(y, y, out=t)                             # Halley
    np.multiply(t, y, out=t)
    np.add(t, c, out=u)
    np.add(u, c, out=u)
    np.add(t, t, out=t)
    np.add(t, c, out=t)
    np.divide(u, t, out=u)
    np.multiply(y, u, out=y)
    for _ in range(2):                                   # Newton
        np.multiply(y, y, out=t)
        np.divide(c, t, out=t)
        np.subtract(y, t, out=t)
        np.multiply(t, _THIRD, out=t)
        np.subtract(y, t, out=y)
    if not _MIN(c) > 0.0:                                # zero loads
        np.copyto(y, 0.0, where=c == 0.0)
    return y


def _cbrt_scalar(c: float) -> float:
    """:func:`_cbrt_kernel` for one Python float (bit-for-bit the same)."""
    if c == 0.0:
        return 0.0
    y = _FLOAT64.unpack(_INT64.pack(_INT64.unpack(_FLOAT64.pack(c))[0] // 3 + _CBRT_MAGIC))[0]
    t = y * y * y
    y = y * ((t + c + c) / (t + t + c))
    for _ in range(2):
        y = y - (y - c / (y * y)) * _THIRD
    return y


def _contact_arrays(Q, Rx, Ry, Ep, method):
    """(k, a, b, approach, p_max, stiffness, K, E) of validated, broadcast arrays."""
    k, K, E = _ellipticity(_radius_ratio(Rx, Ry), method)
    R = Rx * Ry
    R /= Rx + Ry
    ER = E * R
    c = (6.0 / np.pi) * ER
    c *= Q
    c /= Ep
    c /= k
    b = np.cbrt(c)
    a = b * k
    approach = K * b
    approach *= b
    approach /= 2.0 * ER
    ab = a * b
    if (Q == 0).any():
        with np.errstate(divide="ignore", invalid="ignore"):
            p_max = np.where(Q == 0, 0.0, (1.5 / np.pi) * Q / ab)
    else:
        p_max = (1.5 / np.pi) * Q
        p_max /= ab
    # Hamrock & Dowson (1981) eq. 3.33: Q = K delta^1.5
    w = (2.0 / 9.0) * ER
    w /= K * K * K
    stiffness = (np.pi * k) * Ep
    stiffness *= np.sqrt(w)
    return k, a, b, approach, p_max, stiffness, K, E


def _exact_scalar(Q: float, Rx: float, Ry: float, Ep: float):
    """:func:`_exact_kernel` for one contact of Python floats (validated).

    The same operations in the same order on Python floats (IEEE double, like NumPy's):
    bit-for-bit the array path's result (``tests/test_speed_paths.py``).  Returns
    (k, a, b, approach, p_max, stiffness, K, E), or None when the radius ratio exceeds 1e8.
    """
    mx, mn = (Rx, Ry) if Rx >= Ry else (Ry, Rx)
    alpha = mx / mn
    if not alpha <= _ALPHA_MAX:
        return None
    k, K, E = _solve_k_scalar(alpha)
    ER = E * (mx / (alpha + 1.0))
    b = _cbrt_scalar(ER * Q / (Ep * _PI_6) / k)
    h = b / (ER + ER)
    return (k, b * k, b, K * b * h, h * (Ep * 0.5), math.sqrt(ER / K) / K * k * (Ep * _STIFF),
            K, E)


def _contact_scalar(Q: float, Rx: float, Ry: float, Ep: float) -> HertzContact:
    """One contact of Python floats (validated) by :func:`_exact_scalar`: some 20 times
    faster than the array path, bit-for-bit its result."""
    v = _exact_scalar(Q, Rx, Ry, Ep)
    if v is None:
        return _contact_from_parts(*np.broadcast_arrays(Q, Rx, Ry, Ep), "exact")  # raises
    f = np.float64
    k, a, b, approach, p_max, stiffness, K, E = v
    return HertzContact(load=f(Q), Rx=f(Rx), Ry=f(Ry), E_prime=f(Ep), k=f(k), a=f(a), b=f(b),
                        approach=f(approach), p_max=f(p_max), stiffness=f(stiffness),
                        ellipk=f(K), ellipe=f(E), method="exact")


def elliptical_contact(load, Rx, Ry, E_prime, method: str = "exact") -> HertzContact:
    r"""Elliptical Hertz contact from effective radii and effective modulus.

    .. math::
        a = \left(\frac{6 k^2 \mathcal{E} Q R}{\pi E'}\right)^{1/3},\quad
        b = \left(\frac{6 \mathcal{E} Q R}{\pi k E'}\right)^{1/3},\quad
        \delta = \mathcal{K}\left[\frac{9}{2\mathcal{E}R}
                 \left(\frac{Q}{\pi k E'}\right)^2\right]^{1/3},\quad
        p_{max} = \frac{3Q}{2\pi a b}

    Parameters
    ----------
    load : float or array_like
        Normal load Q [N], >= 0.
    Rx, Ry : float or array_like
        Effective radii in the rolling and transverse planes [m], > 0.
    E_prime : float or array_like
        Hamrock–Dowson effective modulus E' [Pa], > 0.
    method : {"exact", "brewe-hamrock-1977", "hamrock-brewe-1983"}
        Exact Hertz or a simplified formula (errors in ``APPROXIMATION_ERROR``).

    Returns
    -------
    HertzContact

    References
    ----------
    Hamrock & Dowson (1981) *Ball Bearing Lubrication* ch. 3, eqs. (3.8)–(3.16), (3.33);
    Ricci (2009) eqs. (12)–(16); Harris (2001) *Rolling Bearing Analysis* §6.

    Examples
    --------
    Sphere of radius 5 mm on a flat, steel on steel (Johnson 1985 eq. 4.22:
    a = (3QR/4E*)^(1/3) = 0.3244 mm):

    >>> c = elliptical_contact(1000.0, 0.005, 0.005, 219.78e9)
    >>> round(float(c.a) * 1e3, 4), round(float(c.p_max) / 1e9, 4)
    (0.3244, 4.5383)
    """
    if method == "exact":                       # one contact of plain numbers: fast path
        q, x, y, e = _real(load), _real(Rx), _real(Ry), _real(E_prime)
        if (q is not None and x is not None and y is not None and e is not None
                and _load_ok(q) and _size_ok(x) and _size_ok(y) and _size_ok(e)):
            return _contact_scalar(q, x, y, e)
    check_choice(method, "method", METHODS)
    if _plain_ok(load, True) and _plain_ok(Rx) and _plain_ok(Ry) and _plain_ok(E_prime):
        # float64 arrays or floats, all in [1e-30, 1e30] (loads also 0): what the checks
        # below accept, decided by two reductions per array instead of five
        Q, Rx, Ry, Ep = (np.asarray(x) for x in (load, Rx, Ry, E_prime))
    else:
        Q = check_nonnegative(load, "load", "N", bounded=True)
        Rx = check_positive(Rx, "Rx", "m", bounded=True)
        Ry = check_positive(Ry, "Ry", "m", bounded=True)
        Ep = check_positive(E_prime, "E_prime", "Pa", bounded=True)
    Q, Rx, Ry, Ep = broadcast(load=Q, Rx=Rx, Ry=Ry, E_prime=Ep)
    return _contact_from_parts(Q, Rx, Ry, Ep, method)


# scalar fast paths: plain float checks that accept exactly what the array checks accept;
# anything else (arrays, odd types, a value out of range) goes the array way, which
# raises the documented errors
def _real(x):
    """``x`` as a Python float if it is a plain float or a moderate int (not bool), else None."""
    t = type(x)
    if t is float or t is np.float64:
        return float(x)
    if t is int and -(2**53) <= x <= 2**53:
        return float(x)
    return None


def _plain_ok(x, zero_ok: bool = False) -> bool:
    """``x`` is a non-empty float64 array, a float or a NumPy float64 with every entry in
    [1e-30, 1e30], or 0 with ``zero_ok`` (min and max: NaN and inf fail the comparisons;
    with zeros, a third reduction over the positive entries)."""
    t = type(x)
    if t is np.ndarray:
        if not (x.dtype == np.float64 and x.size > 0 and _MAX(x, None) <= MAX_MAGNITUDE):
            return False
        lo = _MIN(x, None)
        if zero_ok and lo == 0.0:
            lo = _MIN(x, None, initial=np.inf, where=x > 0.0)
        return MIN_MAGNITUDE <= lo
    if t is float or t is np.float64:
        return MIN_MAGNITUDE <= x <= MAX_MAGNITUDE or (zero_ok and x == 0.0)
    return False


def _load_ok(q: float) -> bool:
    """check_nonnegative(..., bounded=True) passes: 0, or finite in [1e-30, 1e30]."""
    return q == 0.0 or MIN_MAGNITUDE <= q <= MAX_MAGNITUDE


def _size_ok(x: float) -> bool:
    """check_positive(..., bounded=True) passes: in [1e-30, 1e30]."""
    return MIN_MAGNITUDE <= x <= MAX_MAGNITUDE


def _radius_ok(r: float) -> bool:
    """:func:`_radius` passes: non-zero, +-inf, or magnitude in [1e-30, 1e30]."""
    a = abs(r)
    return a == math.inf or MIN_MAGNITUDE <= a <= MAX_MAGNITUDE


#: Largest contact size a / R (semi-major axis over the smallest radius of either body)
#: for which :func:`point_contact` answers without a warning.  Hertz's theory assumes
#: a << R; for a ball in a conformal groove the half-space solution departs from the real
#: bodies by about 1 % near a/(f D) = 0.17 and a few percent at 0.4 (docs/fem-sweep.md).
#: Beyond 0.5 the numbers are extrapolations of the theory, not a contact.
SIZE_LIMIT = 0.5


def size_ratio(a, radii) -> float:
    """max(a) / min |R| over the finite radii [-] (0 when every surface is flat)."""
    rmin = min(float(np.min(np.where(np.isfinite(x), np.abs(x), np.inf))) for x in radii)
    return float(np.max(a)) / rmin if math.isfinite(rmin) and rmin > 0 else 0.0


def _warn_size(c, radii):
    ratio = size_ratio(c.a, radii)
    if ratio > SIZE_LIMIT:
        import warnings

        warnings.warn(f"point_contact: a / R = {ratio:.3g} > {SIZE_LIMIT:g} (semi-axis a = "
                      f"{float(np.max(c.a)):.4g} m against the smallest radius): beyond "
                      "Hertz's small-contact assumption a << R; the results are "
                      "extrapolations, not a contact", UserWarning, stacklevel=3)
    return c


def point_contact(load, rx1, ry1, rx2, ry2, material1: Material,
                  material2: Material | None = None, method: str = "exact") -> HertzContact:
    r"""Hertz contact of two bodies given their principal radii and materials.

    Parameters
    ----------
    load : float or array_like
        Normal load Q [N], >= 0.
    rx1, ry1 : float or array_like
        Principal radii of body 1 in the x (rolling) and y planes [m]; concave < 0,
        ``np.inf`` for flat.
    rx2, ry2 : float or array_like
        Principal radii of body 2 [m], same convention.
    material1 : Material
        Body 1.
    material2 : Material, optional
        Body 2 (default: same as body 1).
    method : {"exact", "brewe-hamrock-1977", "hamrock-brewe-1983"}
        Exact Hertz or a simplified formula.

    Returns
    -------
    HertzContact
        ``a >= b`` [m], ``k``, ``approach`` [m], ``p_max`` [Pa], ``stiffness`` [N/m^1.5],
        ``Rx``, ``Ry`` [m], ``E_prime`` [Pa], ``load`` [N].

    Warns
    -----
    UserWarning
        When a exceeds :data:`SIZE_LIMIT` times the smallest radius of either body: the
        theory assumes a << R, and such a result is an extrapolation.

    References
    ----------
    Hamrock & Dowson (1981) ch. 3, eqs. (3.1)–(3.16); Ricci (2009) eqs. (8)–(16).

    Examples
    --------
    Two steel balls of 12.7 mm diameter pressed together with 100 N:

    >>> import ballrace
    >>> steel = ballrace.Material(E=200e9, nu=0.3)
    >>> c = point_contact(100.0, 6.35e-3, 6.35e-3, 6.35e-3, 6.35e-3, steel, steel)
    >>> round(float(c.a) * 1e6, 2), round(float(c.p_max) / 1e6, 1), round(float(c.approach) * 1e6, 3)
    (129.4, 2851.3, 5.274)
    """
    if method == "exact":                       # one contact of plain numbers: fast path
        q, x1, y1, x2, y2 = _real(load), _real(rx1), _real(ry1), _real(rx2), _real(ry2)
        if (q is not None and x1 is not None and y1 is not None and x2 is not None
                and y2 is not None and _load_ok(q) and _radius_ok(x1) and _radius_ok(y1)
                and _radius_ok(x2) and _radius_ok(y2)):
            cx = 1.0 / x1 + 1.0 / x2                    # as curvature()
            cy = 1.0 / y1 + 1.0 / y2
            if cx > 0.0 and cy > 0.0:
                Ep = effective_modulus(material1, material2)
                c = _contact_scalar(q, 1.0 / cx, 1.0 / cy, Ep)
                rmin = min(abs(x1), abs(y1), abs(x2), abs(y2))
                if c.a > SIZE_LIMIT * rmin:          # a << R no longer holds
                    _warn_size(c, (x1, y1, x2, y2))
                return c
    check_choice(method, "method", METHODS)
    Ep = effective_modulus(material1, material2)
    Q = check_nonnegative(load, "load", "N", bounded=True)
    radii = {name: _radius(r, name) for name, r in
             (("rx1", rx1), ("ry1", ry1), ("rx2", rx2), ("ry2", ry2))}
    Q, *radii_b = broadcast(load=Q, **radii)
    geo = curvature(*radii_b)
    # derived radii and modulus may pass 1e30 a little (cancelling curvatures, nu near -1):
    # the formulas stay finite, so they are not checked against the input limits again
    Q, Rx, Ry, Ep = np.broadcast_arrays(Q, geo.Rx, geo.Ry, Ep)
    return _warn_size(_contact_from_parts(Q, Rx, Ry, Ep, method), radii_b)


def contact_stiffness(Rx, Ry, E_prime, method: str = "exact"):
    r"""Load–deflection constant K of a point contact, Q = K delta^(3/2) [N/m^1.5].

    .. math:: K = \pi k E' \left(\frac{2 \mathcal{E} R}{9 \mathcal{K}^3}\right)^{1/2}

    Parameters
    ----------
    Rx, Ry : float or array_like
        Effective radii in the rolling and transverse planes [m], > 0.
    E_prime : float or array_like
        Effective modulus E' [Pa], > 0.
    method : {"exact", "brewe-hamrock-1977", "hamrock-brewe-1983"}
        Exact or simplified ellipticity.

    References
    ----------
    Hamrock & Dowson (1981) eqs. (3.31)–(3.33); Ricci (2009) eqs. (15)–(16).

    Examples
    --------
    >>> K = contact_stiffness(0.005, 0.005, 219.78e9)
    >>> c = elliptical_contact(1000.0, 0.005, 0.005, 219.78e9)
    >>> bool(np.isclose(K * c.approach**1.5, 1000.0, rtol=1e-12))
    True
    """
    check_choice(method, "method", METHODS)
    Rx = check_positive(Rx, "Rx", "m", bounded=True)
    Ry = check_positive(Ry, "Ry", "m", bounded=True)
    Ep = check_positive(E_prime, "E_prime", "Pa", bounded=True)
    Rx, Ry, Ep = broadcast(Rx=Rx, Ry=Ry, E_prime=Ep)
    R = Rx * Ry / (Rx + Ry)
    k, K, E = _ellipticity(_radius_ratio(Rx, Ry), method)
    return _scalar(np.pi * k * Ep * np.sqrt(2.0 * E * R / (9.0 * K**3)))


def load_from_approach(approach, Rx, Ry, E_prime, method: str = "exact"):
    r"""Normal load Q = K delta^(3/2) for a given approach [N].

    Parameters
    ----------
    approach : float or array_like
        Elastic approach delta [m], >= 0.
    Rx, Ry : float or array_like
        Effective radii [m], > 0.
    E_prime : float or array_like
        Effective modulus E' [Pa], > 0.
    method : str
        As in :func:`elliptical_contact`.

    References
    ----------
    Hamrock & Dowson (1981) eq. (3.33).

    Examples
    --------
    >>> c = elliptical_contact(250.0, 0.004, 0.08, 219.78e9)
    >>> round(float(load_from_approach(c.approach, 0.004, 0.08, 219.78e9)), 9)
    250.0
    """
    d = check_nonnegative(approach, "approach", "m", bounded=True)
    K = contact_stiffness(Rx, Ry, E_prime, method)
    d, K = broadcast(approach=d, **{"Rx, Ry, E_prime": K})
    return _scalar(K * d**1.5)


# --------------------------------------------------------------------------- line contact
@dataclass(frozen=True)
class LineContact:
    """Result of a Hertz line (cylinder) contact (frozen).

    Attributes
    ----------
    load_per_length : Load per unit length w [N/m].
    R : Effective radius 1/(1/r1 + 1/r2) [m].
    E_prime : Effective modulus E' [Pa].
    b : Half-width of the contact strip [m].
    p_max : Maximum pressure [Pa].
    """

    load_per_length: np.ndarray
    R: np.ndarray
    E_prime: np.ndarray
    b: np.ndarray
    p_max: np.ndarray

    @property
    def p_mean(self):
        """Mean pressure w/(2b) = pi/4 p_max [Pa]."""
        return np.pi / 4.0 * self.p_max

    def pressure(self, x):
        """Hertz pressure p_max sqrt(1 - (x/b)^2) at distance x from the centre line [Pa]."""
        s = 1.0 - (np.asarray(x) / self.b) ** 2
        return self.p_max * np.sqrt(np.clip(s, 0.0, None))


def line_contact(load_per_length, r1, r2, material1: Material,
                 material2: Material | None = None) -> LineContact:
    r"""Hertz contact of two parallel cylinders (plane strain).

    .. math:: b = \left(\frac{8 w R}{\pi E'}\right)^{1/2}, \qquad
              p_{max} = \frac{2 w}{\pi b}

    The approach of a line contact depends on the size of the bodies and is not
    returned.

    Parameters
    ----------
    load_per_length : float or array_like
        Load per unit axial length w [N/m], >= 0.
    r1, r2 : float or array_like
        Cylinder radii [m]; concave < 0, ``np.inf`` for a flat.
    material1 : Material
        Body 1.
    material2 : Material, optional
        Body 2 (default: same as body 1).

    References
    ----------
    Johnson (1985) eqs. (4.43)–(4.45) (with E' = 2E*); Hamrock & Dowson (1981) §3.1.

    Examples
    --------
    NAFEMS FENET D3613 cylinder on block (35 kN/mm, R = 50 mm, E = 70 / 210 GPa):

    >>> import ballrace
    >>> al = ballrace.Material(E=70e9, nu=0.3); st = ballrace.Material(E=210e9, nu=0.3)
    >>> c = line_contact(35e6, 0.05, np.inf, al, st)
    >>> round(float(c.b) * 1e3, 2), round(float(c.p_max) / 1e6)
    (6.21, 3585)
    """
    Ep = effective_modulus(material1, material2)
    w = check_nonnegative(load_per_length, "load_per_length", "N/m", bounded=True)
    w, a1, a2 = broadcast(load_per_length=w, r1=_radius(r1, "r1"), r2=_radius(r2, "r2"))
    c = 1.0 / a1 + 1.0 / a2
    if np.any(c <= 0):
        raise ValueError(f"curvature sum 1/r1 + 1/r2 must be > 0 [1/m]; got {float(np.min(c)):g}")
    R = 1.0 / c
    b = np.sqrt(8.0 * w * R / (np.pi * Ep))
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.where(w > 0, 2.0 * w / (np.pi * b), 0.0)
    return LineContact(load_per_length=_scalar(w), R=_scalar(R), E_prime=_scalar(Ep + 0 * w),
                       b=_scalar(b), p_max=_scalar(p))


# --------------------------------------------------------------------------- error study
def approximation_errors(alpha_r, method: str) -> dict[str, np.ndarray]:
    """Signed relative error of a simplified method against the exact solution.

    Parameters
    ----------
    alpha_r : array_like
        Radius ratios Ry/Rx >= 1 [-].
    method : {"brewe-hamrock-1977", "hamrock-brewe-1983"}
        The simplified method.

    Returns
    -------
    dict
        ``{"k", "ellipk", "ellipe", "a", "b", "approach", "p_max"}`` -> relative error
        (approximate/exact - 1) at each ratio.  Load and modulus cancel out.

    Examples
    --------
    >>> e = approximation_errors([1.0, 10.0], "hamrock-brewe-1983")
    >>> bool(abs(e["k"][0]) < 1e-15)
    True
    """
    check_choice(method, "method", METHODS[1:])
    alpha = check_positive(alpha_r, "alpha_r", "-")
    ex = elliptical_contact(1.0, 1.0, alpha, 1.0, method="exact")
    ap = elliptical_contact(1.0, 1.0, alpha, 1.0, method=method)
    return {q: np.asarray(getattr(ap, q)) / np.asarray(getattr(ex, q)) - 1.0
            for q in ("k", "ellipk", "ellipe", "a", "b", "approach", "p_max")}


def scalar_result(x):
    """A broadcasting formula's result as the caller expects it: a 0-d array becomes a
    numpy scalar (scalar inputs give a scalar), any other array passes through unchanged.

    The one place the package turns 0-d results into scalars; other modules wrap their
    results with it so that scalar in, scalar out holds alike everywhere.

    Parameters
    ----------
    x : array_like
        The result, in whatever unit it carries [-].
    """
    x = np.asarray(x)
    return x[()] if x.ndim == 0 else x


_scalar = scalar_result          # the module's own short name


def _error_table() -> str:  # pragma: no cover - documentation generator
    qs = _QUANTITIES
    out = ["| method | alpha_max | " + " | ".join(qs) + " |", "|---" * (len(qs) + 2) + "|"]
    for meth in METHODS[1:]:
        for hi in (10.0, 100.0, 1e4):
            e = approximation_errors(np.logspace(0, np.log10(hi), 4001), meth)
            out.append(f"| {meth} | {hi:g} | "
                       + " | ".join(f"{100 * np.max(np.abs(e[q])):.2f} %" for q in qs) + " |")
    return "\n".join(out)


if __name__ == "__main__":  # pragma: no cover
    import sys

    sys.stdout.write(_error_table() + "\n")
