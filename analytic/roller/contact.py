r"""The finite line contact of a profiled roller on the elastic half-space.

Hertz's line contact (:func:`ballrace.analytic.hertz.line_contact`) is a cylinder of
infinite length.  A real roller ends: a straight roller on a longer raceway has a pressure
peak at each end, a crown removes it, a tilt brings it back at one end.  The lamina model
of ISO/TS 16281 (independent slices) cannot see this; the half-space couples the slices.

Frame
-----
``x`` runs along the roller axis from the roller centre (as in
:mod:`~ballrace.analytic.roller.profile`), ``y`` is the rolling direction, ``z`` the
contact normal.  Body 1 is the roller (``R1`` its radius in the rolling direction, so the
roller diameter of ISO's default profile is ``D_we = 2 R1``), body 2 the raceway.  The
roller is tilted by ``tilt`` about the rolling direction ``y`` — the normal of the axial
plane that holds the roller axis and the load line::

    tilt psi > 0: the end at +x goes in (the roller's lower line, tilt exaggerated)

      -x end
        |''--..__
        |        ''--..__            roller
        |                ''--..__
                                 ''--..__                  +x end
                                         ''--..__            |
      ============================================''--..__===|====  raceway (z = 0)
      -x <------------------------ 0 ------------------------> +x
              (y, the rolling direction, points out of the page)

The gap between the unloaded surfaces at the approach ``delta`` of the roller centre is

.. math:: g(x) = P(x) - x \tan\psi - \delta ,

``P`` the profile's drop (seen once here; :mod:`~ballrace.analytic.roller.profile`),
``psi`` the tilt.

Method: slices coupled through the half-space (the strip method)
----------------------------------------------------------------
The effective length ``L`` is cut into ``n_slices`` strips of equal width ``w = L/n``.
Strip ``k`` carries the load per length ``q_k`` as a semi-elliptical (Hertz) pressure
across the rolling direction, ``p_k sqrt(1 - (y/b_k)^2)``, uniform over its width, with
the half-width and peak of the 2-D Hertz contact at ``q_k``:

.. math:: b_k = \sqrt{\frac{8 q_k R}{\pi E'}}, \qquad p_k = \frac{2 q_k}{\pi b_k},
          \qquad \frac{1}{R} = \frac{1}{R_1} + \frac{1}{R_2}

(so that the curvature across each strip is met exactly).  The strips are coupled along
the roller through the half-space: the normal displacement of the centre line of strip
``i`` (``y = 0``, ``x = x_i``) under all strips (Boussinesq; Johnson 1985 eq. 3.21,
``u = (1/(pi E*)) iint p / r dA`` with ``E* = E'/2``) is

.. math:: u_i = \frac{8}{\pi^2 E'} \sum_j q_j
          \left[G\!\left(\frac{x_j + w/2 - x_i}{b_j}\right)
              - G\!\left(\frac{x_j - w/2 - x_i}{b_j}\right)\right],
          \qquad G(s) = \int_0^1 \sqrt{1 - t^2}\,\operatorname{asinh}\frac{s}{t}\,dt ,

(the integral over the strip's width done in closed form, the one across it in ``G``).
``G`` is odd; its derivative is an elliptic integral,
``G'(s) = R_D(0, s^2/(1 + s^2), 1) / (3 sqrt(1 + s^2))`` (Carlson's ``R_D``; DLMF
19.25.1 with ``K - E``), and ``G`` is its integral, tabulated once (cubic Hermite in
``ln s``, 1e-10 relative; ``s ln(4/s)`` below ``s = 1e-8`` and
``(pi/4)(ln 4s + 1/2) + pi/(64 s^2)`` above ``1e5``).  Contact: ``u_i = delta - P(x_i)
+ x_i tan psi`` where ``q_i > 0``, ``u_i >= ...`` where ``q_i = 0``, and ``w sum q_k = Q``.
The nonlinear system (``b_k`` depends on ``q_k``) is solved by Newton's method with the
exact Jacobian on an active set (slices out of contact carry zero load, none carries a
negative one) to ``1e-12`` of the approach, started from the linear problem with every
half-width frozen at the 2-D Hertz value of the mean load (an active-set solution of the
linear complementarity problem); the load balance holds to rounding.  The active-set rule
for the non-negative loads is this solver's own; its round-off cap, best iterate at the
iteration limit and ConvergenceError are the package's Newton policy
(:mod:`~ballrace.analytic.newton`).

Why strips and not a 2-D grid: the quasi-2-D strip method (Reusner 1977; Teutsch & Sauer
2004) has one unknown per slice, so 41 slices solve in about 3 ms of CPU time (four
Newton steps; ``benchmarks/bench_roller_contact.py``) — the contact runs per roller inside
a bearing calculation — while a full grid in both directions
(de Mul, Kalker & Fredriksson 1986) needs some thousand unknowns for the same axial
resolution.  The price: across the rolling direction every strip is Hertzian, which is
exact in the middle of a long contact and an approximation within about one half-width
``b`` of a roller end or a sharp bend of the profile.  Checked against a grid of uniformly
loaded rectangles in both directions (Love 1929; the form of de Mul et al., no shape
assumed across; ``tests/test_roller_contact.py``), 21 slices x 40 cells, 5 kN on the
12 x 12 mm roller: the largest pressure agrees within 0.01 % (ISO profile) and 1.8 %
(straight roller, its edge slice), each slice's peak within 1 % and 1.8 % at the ends and
0.6 % elsewhere, the approach within 0.1 %.

The approach
------------
The approach of a 2-D line contact is infinite on a half-space (a load per length over an
infinite line), which is why :func:`~ballrace.analytic.hertz.line_contact` returns none.
The finite contact has a finite one: ``approach`` is the mutual approach of two points far
from the contact in the two half-spaces, at the roller centre ``x = 0`` — the reference of
Hertz's point-contact approach (:func:`~ballrace.analytic.hertz.point_contact`).  It is
*not* the approach of the roller's centre to the raceway (that adds the bodies' own
compliance, e.g. in Palmgren's formula).  For Lundberg's profile at its design load it is
Lundberg's (1939) ``delta = (4 q / (pi E')) [ln(L / 2b) + 1.8863]`` for both bodies —
re-derived here from ``G``'s limit, ``1.8863 = ln 4 + 1/2``; the per-body form
``2 q (1 - nu^2)/(pi E) (1.8864 + ln(L/2b))`` is the one quoted in the secondary
literature (Lundberg's paper itself was not read) — which the tests check.

Slice count and the straight roller
-----------------------------------
A crowned roller converges with the slice count: for the 12 x 12 mm roller of the tests
(R = 5 mm, 5 kN, steel; 2-D Hertz 1.707 GPa) the peak pressure of ISO/TS 16281's default
profile is 1.8816, 1.8791, 1.8795 and 1.8796 GPa at 21, 41, 81 and 161 slices (41 -> 81:
0.02 %), that of a circular crown (4 mm flat, 0.5 m crown radius) 2.0237, 2.0244, 2.0237,
2.0241 GPa.  A straight roller on a longer raceway does not converge: its end pressure is
singular on a half-space (a sharp edge), and the end slice's peak grows as the slice
narrows — 2.04, 2.30, 2.75 and 3.51 GPa at 21, 41, 81 and 161 slices — while the middle
settles (1.628, 1.623, 1.618, 1.614 GPa).  The end value of a straight (or edge-loaded)
roller is a property of the slicing, not of the roller: read it as "an edge peak", not as
a pressure.  The same holds for a crowned roller loaded beyond its :attr:`edge_load
<LineContactResult.edge_load>`.

A bend of the profile that is sharp on the scale of the half-width behaves like an edge
here too.  A straight roller with a 0.5 mm corner radius at each end (as an ``(x, drop)``
table of 4000 points; the same roller on a 30 mm raceway, 5 kN, half-width about 0.35 mm
at the corner) peaks where the rounding starts, 2.23, 3.47, 3.52 and 4.20 GPa at 41, 161,
321 and 641 slices: the contact ends within about 0.1 mm of the start of the rounding,
less than a half-width, which is where the strips' Hertzian shape across the rolling
direction is only an approximation (above).  The pressure of a real rounded corner is
bounded; this method does not resolve it, and no warning says so — read such a peak as
"an edge peak" too, or check it with the FE model (:func:`ballrace.fem.roller_contact`),
which has no such assumption.

The edge load itself is the load at which the end slices' *centres* touch.  For a circular
crown it converges as the slices narrow (6535, 6905, 7100 N at 41, 81, 161 slices for the
crown above: linearly in the slice width); for the logarithmic profiles (ISO, Lundberg,
Johns–Gohar), whose drop grows without bound towards the end, it keeps growing with the
slice count (ISO: 6705, 10142, 15678 N) — there the contact never quite reaches the end.

Sources consulted for published edge pressures
----------------------------------------------
Johns & Gohar (1981), Hartnett (1979) and de Mul, Kalker & Fredriksson (1986) show edge
pressures of straight and crowned rollers in figures.  The stored reference pages and
documentation searched here held none of the three papers, only the abstract of Fujiwara &
Kawase (NTN Technical Review 75, 2007), whose examples are computed by another numerical
method; without the full inputs and tabulated results no test compares against them.  The
tests compare against closed forms instead — Lundberg's uniform pressure and approach, 2-D
Hertz and McEwen's stresses in the middle of a long roller — and against an independent
solution on a grid of rectangles in both directions.

References
----------
* G. Lundberg, *Elastische Berührung zweier Halbräume*, Forschung auf dem Gebiete des
  Ingenieurwesens 10 (1939) 201–211: the logarithmic profile and the approach.
* K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, eqs. 3.21, 4.43.
* H. Reusner, *Druckflächenbelastung und Oberflächenverschiebung im Wälzkontakt von
  Rotationskörpern*, Dissertation, Universität Karlsruhe, 1977; R. Teutsch and B. Sauer,
  *An alternative slicing technique to consider pressure concentrations in non-Hertzian
  line contacts*, J. Tribology 126 (2004) 436–442: the strip (slicing) method.  Neither
  was read here; they are cited for the method, whose form above is derived from
  Boussinesq's solution directly (the strip function ``G`` and its table are this
  module's own).
* J. M. de Mul, J. J. Kalker and B. Fredriksson, *The contact between arbitrarily curved
  bodies of finite dimensions*, J. Tribology 108 (1986) 140–148 (the grid form; not read
  here).
* A. E. H. Love, *The stress produced in a semi-infinite solid by pressure on part of the
  boundary*, Phil. Trans. R. Soc. A 228 (1929) 377–420 (the uniformly loaded rectangle
  of the tests' grid).
* B. C. Carlson, DLMF §19.25 (the elliptic integral in ``G'``).

Examples
--------
>>> import ballrace
>>> from ballrace.analytic import roller
>>> c = roller.line_contact(5000.0, 0.006, 0.03, 0.012, ballrace.BEARING_STEEL,
...                         ballrace.BEARING_STEEL, profile="lundberg")
>>> round(float(c.pressure[20]) / 1e9, 3), round(c.approach * 1e6, 2)     # [GPa], [um]
(1.708, 13.38)
"""
from __future__ import annotations

import functools
import logging
import math
from dataclasses import dataclass, field

import numpy as np
from scipy import special

from ... import errors
from .. import newton, plausible
from .._checks import as_array, check_instance, check_nonnegative, check_positive
from ..materials import Material, effective_modulus
from .profile import JohnsGohar, Lundberg, Profile, ProfileContext, as_profile

__all__ = ["LineContactResult", "RollerStress", "line_contact", "strip_function",
           "subsurface_stress"]

log = logging.getLogger("ballrace")

#: Fewest slices (an odd number >= this): one in the middle, two at each end.
MIN_SLICES = 5
#: Most slices (the dense solve grows as n^3).
MAX_SLICES = 1001
#: Below this many slices in contact a warning asks for more slices.
FEW_SLICES = 5
#: Newton's tolerance on the contact condition, relative to the approach [-].
TOLERANCE = 1e-12
#: Penetration let be at a slice at the brink of contact, relative to the approach, and the
#: largest contact residual returned: the Newton policy's round-off cap at TOLERANCE,
#: max(1e-9, 100 TOLERANCE) [-] (:func:`ballrace.analytic.newton.roundoff_cap`).
PENETRATION = newton.roundoff_cap(TOLERANCE)
#: Newton iterations before ConvergenceError.
MAX_ITERATIONS = 200

# The active-set rule of the slice loads (q >= 0), this solver's own (the Newton policy has
# no constraints): a step that takes a slice's load below zero drops the slice from the
# contact, except a slice that came back into contact and still carries more than
# _SOFT_LOAD of the mean load per length, whose step is cut to go at most _TO_ZERO of the
# way to zero (a fraction-to-the-boundary rule: Newton's step on its q ln q term
# undershoots a small load); a slice that joins the contact starts at _JOIN_LOAD of the
# mean load per length; after _SETTLE changes of the active set, a slice at the brink of
# contact may penetrate by PENETRATION (it can go in and out on its load's log term).  The
# edge-load iteration, on a fixed active set, cuts a step to go at most _EDGE_TO_ZERO of
# the way to zero.
_SOFT_LOAD = 1e-9                   # [-] of Q / L
_TO_ZERO = 0.9                      # [-]
_JOIN_LOAD = 1e-3                   # [-] of Q / L
_SETTLE = 10                        # active-set changes
_EDGE_TO_ZERO = 0.5                 # [-]

# tabulated G: cubic Hermite in z = ln s on [ln S_LO, ln S_HI]
_S_LO, _S_HI = 1e-8, 1e5
_PER_UNIT = 64                      # nodes per unit of ln s


def _dG(s):
    """G'(s) = R_D(0, s^2/(1+s^2), 1) / (3 sqrt(1+s^2)) for s >= 0."""
    s2 = s * s
    return special.elliprd(0.0, s2 / (1.0 + s2), 1.0) / (3.0 * np.sqrt(1.0 + s2))


@functools.lru_cache(maxsize=1)
def _table():
    """z_0, the node spacing h in z = ln s, G(s_k) and h s_k G'(s_k) (built once)."""
    z0, z1 = math.log(_S_LO), math.log(_S_HI)
    n = int(math.ceil((z1 - z0) * _PER_UNIT))
    z = np.linspace(z0, z1, n + 1)
    h = z[1] - z[0]
    s = np.exp(z)
    ds = s * _dG(s)                               # dG/dz
    # G(s_{k+1}) - G(s_k) = int dG/dz dz: 10-point Gauss-Legendre per interval
    t, wt = np.polynomial.legendre.leggauss(10)
    zq = z[:-1, None] + 0.5 * h * (t[None, :] + 1.0)
    sq = np.exp(zq)
    inc = 0.5 * h * (sq * _dG(sq)) @ wt
    G = np.empty(n + 1)
    G[0] = _S_LO * math.log(4.0 / _S_LO)          # G(s) = s ln(4/s) + O(s^3 ln s)
    G[1:] = G[0] + np.cumsum(inc)
    return z0, h, G, ds * h


def strip_function(s):
    """The strip function ``G(s) = int_0^1 sqrt(1 - t^2) asinh(s/t) dt`` and ``G'(s)``.

    ``(8 q / (pi^2 E')) [G((x2 - x)/b) - G((x1 - x)/b)]`` is the normal displacement of
    the half-space surface at ``(x, 0)`` under the Hertz pressure of a 2-D contact of
    half-width ``b`` and load per length ``q``, laid over ``x1 <= x' <= x2`` (the
    displacement of both bodies, contact modulus ``E'``).

    Parameters
    ----------
    s : float or array_like
        Argument [-] (a length over a half-width).

    Returns
    -------
    (ndarray, ndarray)
        G(s) [-] and G'(s) [-]; G is odd, G(s) -> (pi/4)(ln 4|s| + 1/2) sign(s).

    Examples
    --------
    >>> g, dg = strip_function([1.0, 10.0])
    >>> [round(float(v), 9) for v in g]
    [1.523604463, 3.290428187]
    """
    s = np.asarray(s, dtype=float)
    return _strip(s)


def _strip_positive(a):
    """G(a) and a G'(a) (= dG/d ln a) for a > 0."""
    return _strip_log(np.log(a))


def _strip_log(z):
    """G and dG/dz at s = exp(z) (z = ln s, any real)."""
    z0, h, G, ds = _table()
    t = (z - z0) * (1.0 / h)
    k = t.astype(np.intp)
    np.clip(k, 0, G.size - 2, out=k)
    u = t - k
    g0, g1 = G[k], G[k + 1]
    d0, d1 = ds[k], ds[k + 1]                     # already times h
    # cubic Hermite: value and derivative in u
    c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1
    c3 = 2.0 * (g0 - g1) + d0 + d1
    val = g0 + u * (d0 + u * (c2 + u * c3))
    der = (d0 + u * (2.0 * c2 + 3.0 * u * c3)) * (1.0 / h)
    lo, hi = t < 0.0, t > G.size - 1
    if lo.any() or hi.any():
        al = np.exp(z[lo])
        val[lo] = al * np.log(4.0 / al)                            # s ln(4/s)
        der[lo] = al * (np.log(4.0 / al) - 1.0)
        ah = np.exp(z[hi])
        val[hi] = 0.25 * math.pi * (np.log(4.0 * ah) + 0.5) + math.pi / (64.0 * ah * ah)
        der[hi] = 0.25 * math.pi - math.pi / (32.0 * ah * ah)
    return val, der


def _strip(s):
    a = np.abs(s)
    pos = a > 0
    val = np.zeros(a.shape)
    der = np.zeros(a.shape)
    v, d = _strip_positive(a[pos])
    val[pos] = v
    with np.errstate(divide="ignore"):
        der[pos] = d / a[pos]
    der[~pos] = np.inf
    return np.sign(s) * val, der


# ----------------------------------------------------------------------------- result
@dataclass(frozen=True, eq=False)
class LineContactResult:
    """Result of :func:`line_contact` (frozen; arrays are read-only).

    Attributes
    ----------
    load : float
        Normal load Q [N].
    x : ndarray
        Slice centres from the roller centre [m], shape (n_slices,).
    pressure : ndarray
        Peak (Hertz) pressure of each slice [Pa]; 0 out of contact.
    half_width : ndarray
        Half-width of each slice's contact in the rolling direction [m]; 0 out of contact.
    slice_loads : ndarray
        Load carried by each slice [N]; sums to ``load``.
    approach : float
        Mutual approach of the two half-spaces at the roller centre, referred to points
        far from the contact [m] (see the module notes).
    length : float
        Effective contact length L [m].
    slice_width : float
        Width of each slice, L / n_slices [m].
    tilt : float
        Tilt about the rolling direction [rad] (positive: the +x end goes in).
    drop : ndarray
        The profile's drop at the slice centres [m] (seen once).
    gap : ndarray
        Gap between the deformed surfaces at each slice centre [m]; 0 in contact.
    E_prime : float
        Contact modulus E' [Pa].
    R : float
        Reduced radius in the rolling direction [m].
    profile : Profile
        The profile the contact was solved with.
    iterations : int
        Newton iterations used.
    """

    load: float
    x: np.ndarray
    pressure: np.ndarray
    half_width: np.ndarray
    slice_loads: np.ndarray
    approach: float
    length: float
    slice_width: float
    tilt: float
    drop: np.ndarray
    gap: np.ndarray
    E_prime: float
    R: float
    profile: Profile = field(repr=False)
    iterations: int = 0
    _solver: tuple = field(default=None, repr=False)

    @functools.cached_property
    def edge_load(self) -> float:
        """The load at which the contact reaches both roller ends (every slice in
        contact), with this profile and tilt [N].

        0 for an untilted straight roller; for a logarithmic profile given by name, the
        profile stays the one designed for :attr:`load` while the load varies.  Computed
        on first access (Newton's method on the contact with the last end slice just
        touching, about as long as the contact itself) and kept.
        """
        strips, h = self._solver
        q = self.load_per_length
        return _edge_load(strips, h, q if q.sum() > 0 else np.full(q.size, 1.0))

    @property
    def n_slices(self) -> int:
        """Number of slices [-]."""
        return int(self.x.size)

    @property
    def in_contact(self) -> np.ndarray:
        """Slices that carry load (bool array)."""
        return self.slice_loads > 0

    @property
    def load_per_length(self) -> np.ndarray:
        """Load per unit length of each slice, slice load / slice width [N/m]."""
        return self.slice_loads / self.slice_width

    @property
    def max_pressure(self) -> float:
        """Largest slice peak pressure [Pa]."""
        return float(self.pressure.max())

    @property
    def contact_length(self) -> float:
        """Length of the roller in contact, slice width times slices in contact [m]."""
        return float(np.count_nonzero(self.in_contact) * self.slice_width)

    @property
    def hertz_pressure(self) -> float:
        """2-D Hertz peak pressure at the mean load per length Q/L,
        sqrt(q E' / (2 pi R)) [Pa]."""
        return math.sqrt(self.load / self.length * self.E_prime / (2.0 * math.pi * self.R))


# ----------------------------------------------------------------------------- solver
class _Strips:
    """The strip influence of a roller of n slices of width w.

    The edges of strip j lie (j - i + 1/2) w and (j - i - 1/2) w from the centre of strip
    i: G is needed, per loaded strip j, only at (k + 1/2) w / b_j, k = 0 ... n-1 (G odd).
    """

    def __init__(self, n, w, R, Ep):
        self.n, self.w, self.R, self.Ep = n, w, R, Ep
        k = np.arange(n)
        self.lt = np.log((k + 0.5) * w)                            # (n,)
        # index into [-G(t_{n-1}) ... -G(t_0), G(t_0) ... G(t_{n-1})] of the edges of
        # strip j seen from strip i: upper edge k = j - i, lower edge k = j - i - 1
        self.i_hi = (k[None, :] - k[:, None]) + n                  # [i, j]
        self.i_lo = self.i_hi - 1
        self.c = 8.0 / (math.pi ** 2 * Ep)
        self.kb = 8.0 * R / (math.pi * Ep)                         # b^2 = kb q

    def half_width(self, q):
        return np.sqrt(self.kb * np.clip(q, 0.0, None))

    def displacement(self, q, cols, matrix=False):
        """u (n,) under the loads q (zero outside ``cols``) and du/dq[:, cols]; with
        ``matrix``, the influence matrix du/dq at frozen half-widths instead of u."""
        lb = 0.5 * np.log(self.kb * q[cols])                       # ln b_j
        g, e = _strip_log(self.lt[None, :] - lb[:, None])          # [j, k]
        gf = np.concatenate([-g[:, ::-1], g], axis=1)             # odd extension
        ef = np.concatenate([-e[:, ::-1], e], axis=1)
        jj = np.arange(cols.size)[None, :]
        ih, il = self.i_hi[:, cols], self.i_lo[:, cols]
        D = gf[jj, ih] - gf[jj, il]                                # [i, j]
        if matrix:
            return self.c * D, None
        u = self.c * (D @ q[cols])
        # d/dq_j of q_j D_ij(b_j), b_j^2 = kb q_j: D - (1/2) [s G'(s)] between the edges
        J = self.c * (D - 0.5 * (ef[jj, ih] - ef[jj, il]))
        return u, J


def _linear_start(strips, h, Q):
    """Loads and approach with every strip's half-width frozen at the 2-D Hertz value of
    the mean load per length (a linear complementarity problem, by active sets)."""
    n, w = strips.n, strips.w
    L = n * w
    A0, _ = strips.displacement(np.full(n, Q / L), np.arange(n), matrix=True)
    active = np.ones(n, bool)
    q = np.zeros(n)
    delta = float(np.min(h))
    for _ in range(2 * n):
        cols = np.flatnonzero(active)
        m = cols.size
        A = np.empty((m + 1, m + 1))
        A[:m, :m] = A0[np.ix_(cols, cols)]
        A[:m, m] = -1.0
        A[m, :m] = w
        A[m, m] = 0.0
        sol = np.linalg.solve(A, np.append(-h[cols], Q))
        qa, delta = sol[:m], float(sol[m])
        if np.any(qa <= 0) and m > 1:
            keep = qa > 0
            if not keep.any():
                keep[np.argmax(qa)] = True
            active[cols[~keep]] = False
            continue
        q = np.zeros(n)
        q[cols] = qa
        gap = A0[:, cols] @ qa - delta + h
        pen = (~active) & (gap < 0)
        if not pen.any():
            break
        active |= pen
    return np.where(q > 0, q, 0.0), delta


def _solve_load(strips, h, Q):
    """Slice loads per length q >= 0, the approach and the iterations for the load Q [N].

    Newton's method with the exact Jacobian on the active set (the rule for q >= 0 in the
    module's constants), converged when the contact residual is below TOLERANCE of the
    approach and no slice out of contact penetrates.  At MAX_ITERATIONS the best iterate
    is taken if its residual is within the Newton policy's round-off cap and nothing
    penetrates by more, else ConvergenceError (:func:`ballrace.analytic.newton.
    convergence_error`)."""
    n, w = strips.n, strips.w
    L = n * w
    if Q == 0.0:
        return np.zeros(n), float(np.min(h)), 0
    q, delta = _linear_start(strips, h, Q)
    active = q > 0
    res = math.inf
    best = (math.inf, None, None)
    changes = 0
    rejoined = np.zeros(n, bool)
    for it in range(1, MAX_ITERATIONS + 1):
        cols = np.flatnonzero(active)
        u, J = strips.displacement(q, cols)
        r = u[cols] - delta + h[cols]
        rl = w * q[cols].sum() - Q
        m = cols.size
        A = np.empty((m + 1, m + 1))
        A[:m, :m] = J[cols]
        A[:m, m] = -1.0
        A[m, :m] = w
        A[m, m] = 0.0
        rhs = -np.append(r, rl)
        step = np.linalg.solve(A, rhs)
        dq, dd = step[:m], step[m]
        qa = q[cols]
        neg = qa + dq <= 0.0
        if np.any(neg) and m > 1:
            # the active-set rule (module constants): a rejoined slice is stepped towards
            # zero, any other slice the step takes below zero leaves the contact
            soft = neg & rejoined[cols] & (qa > _SOFT_LOAD * Q / L)
            hard = neg & ~soft
            if hard.any():
                q[cols[hard]] = 0.0
                active[cols[hard]] = False
                changes += 1
                if not active.any():                   # keep the slice that carries most
                    most = int(cols[np.argmax(qa)])
                    active[most] = True
                    q[most] = Q / w
                continue
            alpha = min(1.0, float(np.min(_TO_ZERO * qa[soft] / -dq[soft])))
            q[cols] = qa + alpha * dq
            delta += alpha * dd
            continue
        scale = max(abs(delta), float(np.max(np.abs(u))), 1e-300)
        res = float(np.max(np.abs(r))) / scale
        if res < best[0] and abs(rl) <= PENETRATION * Q:    # the iterate before the step
            best = (res, q.copy(), delta)
        q[cols] = qa + dq
        delta += dd
        if res < TOLERANCE:
            done = _settled(strips, h, Q, q, delta, active, rejoined,
                            TOLERANCE if changes < _SETTLE else PENETRATION)
            if done is None:                           # slices that penetrate joined
                changes += 1
                continue
            if done:
                return q, delta, it
    if best[0] <= PENETRATION:                          # round-off level: the best iterate
        q, delta = best[1], best[2]
        if _settled(strips, h, Q, q, delta, q > 0, np.zeros(n, bool), PENETRATION,
                    join=False):
            return q, delta, MAX_ITERATIONS
    raise newton.convergence_error(
        "finite line contact", MAX_ITERATIONS, res, TOLERANCE, best=best[0], newton=True,
        measure="contact residual relative to the approach",
        context=f"at Q = {Q:g} N on {n} slices ({int(np.count_nonzero(active))} in contact)")


def _settled(strips, h, Q, q, delta, active, rejoined, tol, join=True):
    """Whether the contact (q, delta) holds: no slice out of contact penetrates by more
    than ``tol`` of the approach (with ``join``, those that do join the contact, with
    _JOIN_LOAD of the mean load, and None is returned) and the contact residual of the
    slices in contact is within PENETRATION; if it holds, q is scaled to carry Q (in
    place: the load balance to rounding)."""
    w = strips.w
    L = strips.n * w
    cols = np.flatnonzero(active)
    u, _ = strips.displacement(q, cols)
    gap = u - delta + h
    scale = max(abs(delta), float(np.max(np.abs(u))), 1e-300)
    pen = (~active) & (gap < -tol * scale)
    if np.any(pen):
        if not join:
            return False
        active |= pen
        rejoined |= pen
        q[pen] = _JOIN_LOAD * Q / L
        return None
    if float(np.max(np.abs(gap[cols]))) / scale <= PENETRATION:
        q *= Q / (w * q.sum())
        return True
    return False


def _edge_load(strips, h, q_start):
    """The load [N] at which the contact reaches both ends (every slice in contact)."""
    n, w = strips.n, strips.w
    span = float(np.ptp(h))
    if span <= 1e-14 * n * w:
        return 0.0                                  # straight and untilted: at once
    symmetric = np.array_equal(h, h[::-1])
    # the end that touches last carries zero load at the edge load; try the end with the
    # larger unloaded gap first
    ends = [0, n - 1] if h[0] >= h[-1] else [n - 1, 0]
    for last in ends:
        free = np.ones(n, bool)
        free[last] = False
        if symmetric:
            free[n - 1 - last] = False
        cols = np.flatnonzero(free)
        q = np.where(free, np.maximum(q_start, 0.05 * q_start.max()), 0.0)
        delta = 0.0
        ok = False
        for _ in range(MAX_ITERATIONS):
            u, J = strips.displacement(q, cols)
            # symmetric: the last row mirrors the first (both ends unloaded)
            rows = np.arange(n - 1 if symmetric else n)
            r = u[rows] - delta + h[rows]
            A = np.hstack([J[rows], -np.ones((rows.size, 1))])
            step = np.linalg.solve(A, -r)
            dq, dd = step[:-1], step[-1]
            qa = q[cols]
            neg = qa + dq <= 0.0
            alpha = 1.0
            if np.any(neg):
                alpha = min(1.0, float(np.min(_EDGE_TO_ZERO * qa[neg] / -dq[neg])))
            q[cols] = qa + alpha * dq
            delta += alpha * dd
            scale = max(abs(delta), float(np.max(np.abs(u))), 1e-300)
            if float(np.max(np.abs(r))) / scale < TOLERANCE and alpha == 1.0:
                ok = True
                break
        if ok and np.all(q[cols] > 0):
            return float(w * q.sum())
    return _edge_load_bisection(strips, h, q_start)


def _edge_load_bisection(strips, h, q_start):
    """Fallback: bisection on the load for the first load with every slice in contact."""
    w = strips.w
    lo, hi = 0.0, max(float(w * q_start.sum()), 1e-6)
    q_hi = None
    for _ in range(200):
        q, _, _ = _solve_load(strips, h, hi)
        if np.all(q > 0):
            q_hi = q
            break
        lo, hi = hi, 2.0 * hi
    if q_hi is None:
        raise errors.ConvergenceError("the load at which the contact reaches the roller "
                                      "ends was not found below 2^200 times the load")
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        q, _, _ = _solve_load(strips, h, mid)
        if np.all(q > 0):
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-10 * hi:
            break
    return hi


def _frozen(a):
    a = np.asarray(a, dtype=float)
    a.setflags(write=False)
    return a


def _scalar_arg(value, name, unit, check, **kw):
    arr = check(value, name, unit, **kw)
    if arr.ndim:
        raise TypeError(f"{name} must be a single real number [{unit}], not an array; got "
                        f"shape {arr.shape}")
    return float(arr)


def line_contact(Q, R1, R2, length, mat1: Material, mat2: Material, profile="lundberg",
                 tilt=0.0, n_slices=41) -> LineContactResult:
    """The finite line contact of a profiled roller on the elastic half-space.

    Slices coupled through the half-space (module notes: the method, the approach, the
    slice count).

    Parameters
    ----------
    Q : float
        Normal load [N], >= 0.
    R1 : float
        Radius of the roller (body 1) in the rolling direction [m], > 0; ISO/TS 16281's
        default profile takes D_we = 2 R1.
    R2 : float
        Radius of the raceway (body 2) in the rolling direction [m]: ``np.inf`` for a
        flat, negative for a concave (outer) raceway, ``1/R1 + 1/R2 > 0``.
    length : float
        Effective contact length L_we of the roller [m] (the raceway is longer).
    mat1, mat2 : Material
        Materials of the roller and the raceway.
    profile : str, Profile or (array_like, array_like), optional
        The roller profile (:func:`~ballrace.analytic.roller.profile.as_profile`), its
        drop seen once; ``"lundberg"`` or ``"johns-gohar"`` by name are designed for this
        ``Q``.  Default ``"lundberg"``.
    tilt : float, optional
        Tilt of the roller about the rolling direction [rad]; positive: the end at +x goes
        in (module sketch).  Default 0.
    n_slices : int, optional
        Number of slices [-], odd, >= 5 (a slice at the centre).  Default 41.

    Returns
    -------
    LineContactResult
        Slice centres, pressures, half-widths and loads, the approach and the load at
        which the contact reaches the roller ends.

    Raises
    ------
    ValueError
        Bad input (naming the argument), or a tilt so large that only one slice touches.
    ConvergenceError
        Newton's method did not converge (residual and iterations in the message).

    Examples
    --------
    >>> import ballrace
    >>> st = ballrace.BEARING_STEEL
    >>> c = line_contact(5000.0, 0.006, np.inf, 0.012, st, st, profile="iso")
    >>> round(float(c.slice_loads.sum()), 6), int(c.in_contact.sum()), c.n_slices
    (5000.0, 39, 41)
    """
    Q = _scalar_arg(Q, "Q", "N", check_nonnegative, bounded=True)
    R1 = _scalar_arg(R1, "R1", "m", check_positive, bounded=True)
    r2 = as_array(R2, "R2", allow_inf=True, unit="m")
    if r2.ndim:
        raise TypeError(f"R2 must be a single real number [m], not an array; got shape "
                        f"{r2.shape}")
    R2 = float(r2)
    if R2 == 0.0:
        raise ValueError("R2 must be nonzero [m] (np.inf for a flat, negative for a "
                         "concave raceway); got 0.0")
    curv = 1.0 / R1 + 1.0 / R2
    if not curv > 0.0:
        raise ValueError(f"R2 must leave a convex contact, 1/R1 + 1/R2 > 0 [1/m]: a concave "
                         f"raceway is larger than the roller, |R2| > R1; got R1 = {R1:g} m, "
                         f"R2 = {R2:g} m (example: R1=0.006, R2=-0.04)")
    R = 1.0 / curv
    L = _scalar_arg(length, "length", "m", check_positive, bounded=True)
    psi = _scalar_arg(tilt, "tilt", "rad", lambda v, n, u: as_array(v, n, unit=u))
    if abs(psi) >= 0.5 * math.pi:
        raise ValueError(f"tilt must be in (-pi/2, pi/2) [rad] (a tilt of a roller is some "
                         f"milliradians, e.g. tilt=1e-3); got {psi!r}")
    check_instance(mat1, "mat1", Material)
    check_instance(mat2, "mat2", Material)
    if isinstance(n_slices, bool) or not isinstance(n_slices, (int, np.integer)):
        if not (isinstance(n_slices, float) and n_slices.is_integer()):
            raise ValueError(f"n_slices must be an odd whole number >= {MIN_SLICES}; got "
                             f"{n_slices!r} (example: n_slices=41)")
    n = int(n_slices)
    if n < MIN_SLICES or n % 2 == 0 or n > MAX_SLICES:
        raise ValueError(f"n_slices must be an odd whole number in [{MIN_SLICES}, "
                         f"{MAX_SLICES}] (a slice at the roller centre); got {n} "
                         "(example: n_slices=41)")
    plausible.length(L, "length", 0.5, "roller", stacklevel=3)
    plausible.length(R1, "R1", 0.5, "roller", stacklevel=3)
    if abs(psi) > 0.1:
        errors.warn(f"tilt = {psi:g} rad ({math.degrees(psi):.3g} degrees) is far beyond "
                    "any roller's misalignment (some milliradians); tilts are in radians "
                    "- were degrees or milliradians given?")
    Ep = float(effective_modulus(mat1, mat2))
    prof = as_profile(profile)
    if Q == 0.0 and isinstance(prof, (Lundberg, JohnsGohar)) and prof.design_load is None:
        raise ValueError(f"Q must be > 0 [N] for the {prof.name} profile given by name (it is "
                         f"designed for Q); got 0.0 (give {type(prof).__name__}(design_load=...) "
                         "to load such a roller with nothing)")
    ctx = ProfileContext(length=L, diameter=2.0 * R1, E_prime=Ep, R=R,
                         load=Q if Q > 0 else math.nan)
    w = L / n
    x = (np.arange(n) - (n - 1) // 2) * w          # exactly antisymmetric
    drop = np.asarray(prof.drop(x, ctx), dtype=float)
    h = drop - x * math.tan(psi)
    strips = _Strips(n, w, R, Ep)
    q, delta, iterations = _solve_load(strips, h, Q)
    k = int(np.count_nonzero(q > 0))
    if Q > 0 and k == 1 and psi != 0.0:
        raise ValueError(f"tilt = {psi:g} rad is so large that the roller touches on one "
                         f"slice only (of {n}): an edge load, not a line contact; reduce "
                         "the tilt or raise n_slices")
    if Q > 0 and k < FEW_SLICES:
        errors.warn(f"the contact covers only {k} of n_slices = {n} slices "
                    f"({k * w:.3g} of {L:.3g} m): its pressures are poorly resolved; "
                    + ("raise n_slices" if psi == 0.0 else
                       f"raise n_slices (or check tilt = {psi:g} rad)"))
    u, _ = strips.displacement(q, np.flatnonzero(q > 0)) if Q > 0 else (np.zeros(n), None)
    gap = np.where(q > 0, 0.0, np.clip(u - delta + h, 0.0, None))
    b = strips.half_width(q)
    p = np.where(q > 0, 2.0 * q / (math.pi * np.where(b > 0, b, 1.0)), 0.0)
    log.debug("line_contact: %d of %d slices in contact, %d Newton iterations", k, n,
              iterations)
    return LineContactResult(
        load=Q, x=_frozen(x), pressure=_frozen(p), half_width=_frozen(b),
        slice_loads=_frozen(q * w), approach=float(delta), length=L,
        slice_width=w, tilt=psi, drop=_frozen(drop), gap=_frozen(gap), E_prime=Ep, R=R,
        profile=prof, iterations=iterations, _solver=(strips, _frozen(h)))


# ----------------------------------------------------------------------------- stresses
#: Default depths searched, in units of the largest half-width: 0.2 b ... 2.5 b.
DEPTH_RANGE = (0.2, 2.5)


@dataclass(frozen=True, eq=False)
class RollerStress:
    """Subsurface stresses below a finite line contact, in the plane ``y = 0`` under the
    contact's centre line (frozen; arrays read-only).

    Frame of :func:`line_contact`: ``x`` along the roller axis, ``y`` the rolling
    direction, ``z`` the depth.

    Attributes
    ----------
    x : ndarray
        Axial positions [m], shape (nx,).
    depth : ndarray
        Depths [m], shape (nz,).
    stress : StressState
        The stress tensor at every (x, depth) [Pa], arrays of shape (nx, nz); ``sxx``
        along the roller axis, ``syy`` along the rolling direction (``sxy = syz = 0`` on
        this plane of symmetry).
    von_mises, tresca : ndarray
        Von Mises equivalent stress and maximum shear stress (sigma_1 - sigma_3)/2 at every
        (x, depth) [Pa], shape (nx, nz).
    von_mises_max, tresca_max : ndarray
        Their maxima over depth at each x [Pa], shape (nx,).
    von_mises_depth, tresca_depth : ndarray
        The depths of these maxima [m] (refined by a parabola through the grid's three
        best points).
    loaded : ndarray
        Whether each x lies on a slice in contact (bool), shape (nx,).
    """

    x: np.ndarray
    depth: np.ndarray
    stress: object
    von_mises: np.ndarray
    tresca: np.ndarray
    von_mises_max: np.ndarray
    von_mises_depth: np.ndarray
    tresca_max: np.ndarray
    tresca_depth: np.ndarray
    loaded: np.ndarray = None

    def _at(self, values, depths, i):
        return float(values[i]), float(self.x[i]), float(depths[i])

    def maximum(self, criterion: str = "von_mises"):
        """The largest stress over all x and depths: (value [Pa], x [m], depth [m]).

        ``criterion`` is ``"von_mises"`` or ``"tresca"``."""
        v, d = self._pick(criterion)
        return self._at(v, d, int(np.argmax(v)))

    def centre(self, criterion: str = "von_mises"):
        """The maximum over depth at the position nearest the roller centre:
        (value [Pa], x [m], depth [m])."""
        v, d = self._pick(criterion)
        return self._at(v, d, int(np.argmin(np.abs(self.x))))

    def edge(self, criterion: str = "von_mises"):
        """The larger of the maxima over depth at the two outermost positions on slices in
        contact (the ends of the contact): (value [Pa], x [m], depth [m])."""
        v, d = self._pick(criterion)
        on = np.flatnonzero(self.loaded)
        i, j = (int(on[0]), int(on[-1])) if on.size else (0, v.size - 1)
        return self._at(v, d, i if v[i] >= v[j] else j)

    def _pick(self, criterion):
        if criterion == "von_mises":
            return self.von_mises_max, self.von_mises_depth
        if criterion == "tresca":
            return self.tresca_max, self.tresca_depth
        raise ValueError(f"criterion must be 'von_mises' or 'tresca'; got {criterion!r}")


def _boussinesq_sum(xt, zt, xs, ys, P, nu):
    """Stresses (sxx, syy, szz, sxz) at (xt, 0, zt) under normal point loads P at
    (xs, +-ys, 0) (each load given once, mirrored in y), compression negative.

    Boussinesq (Johnson 1985 eq. 3.21), written without cancellation on the load's axis:
    with rho^2 = r^2 + z^2, A = 1 / (rho (rho + z)),
    sigma_theta = -(P/2pi)(1 - 2nu)(A - z/rho^3),
    sigma_r - sigma_theta = (P/2pi) r^2 B, B = (1 - 2nu)(2 rho + z)/(rho^3 (rho + z)^2)
    - 3 z / rho^5, sigma_xx = sigma_theta + (P/2pi) B dx^2 and so on,
    sigma_z = -(3P/2pi) z^3/rho^5, tau_xz = -(3P/2pi) dx z^2 / rho^5.
    """
    dx = xt[:, None] - xs[None, :]
    dy2 = (ys * ys)[None, :]
    z = zt[:, None]
    rho2 = dx * dx + dy2 + z * z
    rho = np.sqrt(rho2)
    rz = rho + z
    k = 1.0 - 2.0 * nu
    inv3 = 1.0 / (rho2 * rho)
    inv5 = inv3 / rho2
    A = 1.0 / (rho * rz)
    st = -k * (A - z * inv3)
    B = k * (2.0 * rho + z) * inv3 / (rz * rz) - 3.0 * z * inv5
    Pw = 2.0 * P[None, :] / (2.0 * math.pi)            # both mirrored loads
    sxx = (Pw * (st + B * dx * dx)).sum(axis=1)
    syy = (Pw * (st + B * dy2)).sum(axis=1)
    szz = (Pw * (-3.0 * z ** 3 * inv5)).sum(axis=1)
    sxz = (Pw * (-3.0 * dx * z * z * inv5)).sum(axis=1)
    return sxx, syy, szz, sxz


def _strip_nodes(contact, k, spacing, bmax):
    """Point loads standing for the pressure of the strips ``k``: Gauss–Legendre along
    the roller, Gauss–Chebyshev (second kind) across, at most ``spacing`` apart (None: a
    coarse set of 3 x 4).  Returns xs, ys (>= 0; each load to be mirrored in y), P and
    the strip index of each load."""
    w = contact.slice_width
    if spacing is None:
        ngx, ny = 3, 4
    else:
        # the nodes' spacing in their middle: pi w / (2 ngx) and pi b / ny
        ngx = max(2, int(math.ceil(0.5 * math.pi * w / spacing)))
        ny = max(4, int(math.ceil(math.pi * bmax / spacing)))
    tx, wx = np.polynomial.legendre.leggauss(ngx)
    j = np.arange(1, ny // 2 + 1)                   # the half t > 0 (mirrored in y)
    theta = j * math.pi / (ny + 1)
    ty, wy = np.cos(theta), math.pi / (ny + 1) * np.sin(theta) ** 2
    if ny % 2:                                      # the node t = 0: given once, mirrored
        ty = np.append(ty, 0.0)
        wy = np.append(wy, 0.5 * math.pi / (ny + 1))
    nk = k.size
    xs = contact.x[k][:, None, None] + 0.5 * w * tx[None, :, None] + 0 * ty[None, None, :]
    b = contact.half_width[k][:, None, None]
    ys = b * ty[None, None, :] + 0 * tx[None, :, None]
    P = (contact.pressure[k][:, None, None] * b * (0.5 * w * wx)[None, :, None]
         * wy[None, None, :])
    idx = np.broadcast_to(np.arange(nk)[:, None, None], P.shape)
    return xs.ravel(), ys.ravel(), P.ravel(), idx.ravel()


def _peak_depth(values, z):
    """Maximum over the last axis and its depth, refined by a parabola."""
    i = np.argmax(values, axis=-1)
    rows = np.arange(values.shape[0])
    vmax = values[rows, i].copy()
    zmax = z[i].copy()
    inner = (i > 0) & (i < z.size - 1)
    if np.any(inner):
        r, k = rows[inner], i[inner]
        f0, f1, f2 = values[r, k - 1], values[r, k], values[r, k + 1]
        den = f0 - 2.0 * f1 + f2
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(den < 0, 0.5 * (f0 - f2) / den, 0.0)
        s = np.clip(s, -0.5, 0.5)
        h = z[1] - z[0]
        vmax[inner] = f1 - 0.25 * (f0 - f2) * s
        zmax[inner] = z[k] + s * h
    return vmax, zmax


def subsurface_stress(contact: LineContactResult, nu=0.3, x=None, depth=None,
                      n_depth=24) -> RollerStress:
    """Von Mises and Tresca stresses below a finite line contact, with depth and along the
    roller, in the plane under the contact's centre line.

    The slices' pressures (each a Hertz semi-ellipse across the rolling direction,
    uniform over its width) are integrated over the half-space's point-load solution
    (Boussinesq; Johnson 1985 eq. 3.21) by Gauss–Legendre nodes along the roller and
    Gauss–Chebyshev nodes across it (exact for the semi-ellipse times a polynomial), in
    the middle of a slice no more than 0.4 times the depth apart (per band of depths, an
    octave; three by four nodes for slices far from the point) — so the integration is accurate for
    depths of some tenths of a half-width and more, where the maxima of a frictionless
    contact lie (0.70 b for von Mises, 0.79 b for Tresca in 2-D Hertz, nu = 0.3), not at
    the surface.  The stresses are those of one body (Poisson's ratio ``nu``); the
    pressure is the contact's, whatever the other body.  Frictionless.  Some 0.05 s for
    41 slices at 24 depths (``benchmarks/bench_roller_contact.py``).

    In the middle of a long, uniformly loaded roller (Lundberg's profile) the field is
    McEwen's plane-strain line contact (:func:`ballrace.analytic.subsurface.line_stress`,
    the axial stress ``nu (sigma_y + sigma_z)``); checked in the tests.  At the end of a
    straight or edge-loaded roller the stresses follow the end slice's pressure, which
    depends on the slice count (:func:`line_contact`'s notes): read them as an edge
    concentration, not a converged value.

    Parameters
    ----------
    contact : LineContactResult
        The contact (:func:`line_contact`).
    nu : float, optional
        Poisson's ratio of the body whose stresses are wanted [-], in (-1, 0.5); default
        0.3.
    x : array_like, optional
        Axial positions [m], within the roller (|x| < L/2); default the slice centres.
    depth : array_like, optional
        Depths [m], > 0, evenly spaced (the maxima are refined between them); default
        ``n_depth`` depths from 0.2 to 2.5 times the largest half-width.
    n_depth : int, optional
        Number of default depths [-], >= 5; default 24 (0.1 b apart).

    Returns
    -------
    RollerStress
        The stress tensor, von Mises and Tresca stresses at every (x, depth), their maxima
        over depth at each x and where; ``maximum()``, ``centre()``, ``edge()``.

    Examples
    --------
    >>> import ballrace
    >>> st = ballrace.BEARING_STEEL
    >>> c = line_contact(5000.0, 0.006, 0.03, 0.012, st, st, profile="lundberg")
    >>> s = subsurface_stress(c)
    >>> v, x, z = s.centre()
    >>> round(float(v / c.pressure[20]), 3), round(float(z / c.half_width[20]), 2)
    (0.559, 0.71)

    (2-D Hertz: 0.557 p0 at 0.70 b; the 12 mm roller's finite length and the depth grid
    make the difference, see the tests.)
    """
    from ..subsurface import StressState

    check_instance(contact, "contact", LineContactResult)
    nu = _scalar_arg(nu, "nu", "-", lambda v, n, u: as_array(v, n, unit=u))
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu must be in (-1, 0.5) [-]; got {nu!r}")
    on = contact.slice_loads > 0
    L, w = contact.length, contact.slice_width
    bmax = float(contact.half_width.max())
    if x is None:
        xt = np.array(contact.x, dtype=float)
    else:
        xt = np.atleast_1d(as_array(x, "x", unit="m")).astype(float).ravel()
        if np.any(np.abs(xt) >= 0.5 * L):
            raise ValueError(f"x must lie within the roller, |x| < L/2 = {0.5 * L:g} m; got "
                             f"{float(xt[np.argmax(np.abs(xt))]):g}")
    if depth is None:
        if isinstance(n_depth, bool) or int(n_depth) != n_depth or n_depth < 5:
            raise ValueError(f"n_depth must be a whole number >= 5; got {n_depth!r}")
        zt = np.linspace(DEPTH_RANGE[0], DEPTH_RANGE[1], int(n_depth)) * max(bmax, 1e-300)
    else:
        zt = np.atleast_1d(check_positive(depth, "depth", "m")).astype(float).ravel()
        if zt.size < 3 or not np.allclose(np.diff(zt), zt[1] - zt[0], rtol=1e-9):
            raise ValueError("depth must be at least 3 evenly spaced depths [m] (e.g. "
                             "np.linspace(0.2, 2.5, 24) * b)")
        plausible.depth(zt, bmax, "depth", stacklevel=3)
    shape = (xt.size, zt.size)
    slice_of = np.clip(np.floor((xt + 0.5 * L) / w).astype(int), 0, contact.n_slices - 1)
    loaded = on[slice_of]
    loaded.setflags(write=False)
    comp = [np.zeros(shape) for _ in range(4)]
    if bmax > 0:
        k = np.flatnonzero(on)
        coarse = _strip_nodes(contact, k, None, bmax)
        out = [np.empty(shape) for _ in range(4)]
        # depth bands [z0, 2 z0), [2 z0, 4 z0) ...: each with nodes at most 0.4 times its
        # smallest depth apart (deeper points see a smoother kernel)
        band = np.floor(np.log2(zt / zt.min()) + 1e-12).astype(int)
        for bi in np.unique(band):
            rows = np.flatnonzero(band == bi)
            z_b = zt[rows]
            fine = _strip_nodes(contact, k, 0.4 * float(z_b.min()), bmax)
            # strips farther than this from a target position take the coarse nodes (the
            # kernel is smooth there on the scale of a slice)
            near = 2.0 * float(z_b.max()) + 2.0 * bmax + w
            for i, xi in enumerate(xt):
                close = np.abs(contact.x[k] - xi) <= near
                src = [np.concatenate([fine[c][close[fine[3]]], coarse[c][~close[coarse[3]]]])
                       for c in range(3)]
                for o, v in zip(out, _boussinesq_sum(np.full(z_b.size, xi), z_b, *src, nu)):
                    o[i, rows] = v
        comp = out
    sxx, syy, szz, sxz = comp
    zero = np.zeros(shape)
    ss = StressState(sxx=_frozen(sxx), syy=_frozen(syy), szz=_frozen(szz), sxy=zero,
                     sxz=_frozen(sxz), syz=zero)
    vm = np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2)
                 + 3.0 * sxz ** 2)
    # principal stresses: syy is one (sxy = syz = 0); the others from the x-z block
    mean = 0.5 * (sxx + szz)
    rad = np.sqrt(0.25 * (sxx - szz) ** 2 + sxz ** 2)
    s_all = np.stack([mean + rad, mean - rad, syy])
    tr = 0.5 * (s_all.max(axis=0) - s_all.min(axis=0))
    vmax, vz = _peak_depth(vm, zt)
    tmax, tz = _peak_depth(tr, zt)
    return RollerStress(x=_frozen(xt), depth=_frozen(zt), stress=ss, von_mises=_frozen(vm),
                        tresca=_frozen(tr), von_mises_max=_frozen(vmax),
                        von_mises_depth=_frozen(vz), tresca_max=_frozen(tmax),
                        tresca_depth=_frozen(tz), loaded=loaded)
