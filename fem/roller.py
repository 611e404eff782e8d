r"""FE check of the finite line contact of a profiled roller on its raceway.

Checks :func:`ballrace.analytic.roller.line_contact` (the strip method on the elastic
half-space) with a 3-D model of the real bodies:

* **geometry** (:mod:`ballrace.meshes.roller`): a quarter roller — radius ``R1`` in the
  rolling direction, half-length ``L/2``, its surface lowered by the profile's drop
  ``P(x)`` (radius ``R1 - P(x)``) — on a raceway block longer than the roller (flat,
  or bent onto a cylinder of radius ``R2``, negative concave), so the roller end is a
  real edge.  Symmetry planes: the mid-length plane ``x = 0`` (symmetric profile, no
  tilt) and the plane ``y = 0`` through the contact normal and the roller axis; the
  roller is held in z on the plane through its axis, the block on its bottom.  A tilt
  (or a profile whose drop is not even in x) takes the *half model*: the full length
  ``-L/2 <= x <= L/2``, only ``y = 0`` a symmetry plane, each quarter mesh joined to its
  mirror image (refined at both roller ends; :func:`ballrace.meshes.roller.mirror_x`),
  the x-translation held at one point (it carries nothing: no load along x acts);
  ``mode="half-space"`` replaces the two bodies by one elastic block under a rigid
  roller (modulus ``E'/2 (1 - nu^2)``): line_contact's own idealisation, with the roller
  end still a sharp edge of the loaded region;
* **contact** (:mod:`ballrace.fem.model`): P2 tetrahedra, frictionless, the pressure as
  bilinear tents on a tensor grid along the roller ``x`` (graded towards the roller end,
  where the edge peak lives) times across it ``y`` (some nodes per half-width ``b``),
  compliance matrix and non-negative least squares with the load ``Q/4`` on the
  quarter (``Q/2`` on the half); the initial gap is ``P(x) - x tan(psi) + y^2/(2R)``
  (the gap line_contact solves, ``psi`` the tilt, its sign convention: positive, the
  end at +x goes in; the tilt is imposed and ``Q`` given, the moment is a reaction);
* **extraction**: the pressure along the roller is the peak over ``y`` of the tent
  pressure at each grid ``x`` (``pressure``; the centre and the largest value in the
  outer half, the *edge peak*); the load of each of line_contact's slices from the FE
  pressure (``slice_loads``); the approach by the depth-point method of the ball model
  (docs/fem.md): the FE approach of two points at depth ``z_q = 3 b`` under the roller
  centre (one per body) plus the half-space displacements ``w_1(z_q) + w_2(z_q)`` under
  line_contact's pressure (Boussinesq, integrated over its strips) — comparable with
  line_contact's ``approach`` of distant points in two half-spaces at ``x = 0``; the
  von Mises maximum over depth in the raceway under the centre and under the edge peak,
  against :func:`ballrace.analytic.roller.subsurface_stress`.

Frame: that of :mod:`ballrace.analytic.roller.contact` (x along the roller axis, y the
rolling direction, z the contact normal into the roller; the raceway in z < 0).

Measured (R1 = 6 mm, L = 12 mm, flat raceway, 5 kN, steel, 41 slices; PARDISO)
------------------------------------------------------------------------------
The two cores were shared with other jobs (load average 7-10) while measuring, so the
wall times were 1-8 minutes; the CPU time (user + system, /usr/bin/time -v) is the
better measure, and PARDISO factorises on both cores.  Whether the standard level stays
under 60 s of wall time on an idle machine was not measured.

Half-space mode against line_contact (errors FE / line_contact - 1; "centre p" is the FE
peak pressure averaged over the centre slice, "peak" the largest slice-averaged pressure,
"VM" the von Mises maximum under the centre):

==================  ======  ======  =====  ========  ========  =========  =======
case / level        DOFs    RAM     CPU    centre p  approach  peak       VM
==================  ======  ======  =====  ========  ========  =========  =======
Lundberg quick      47k     0.6 GB  9 s    +3.66 %   -0.05 %   +6.1 %     -0.54 %
Lundberg standard   137k    1.8 GB  43 s   +0.30 %   +0.11 %   +2.4 %     +0.08 %
Lundberg fine       301k    4.7 GB  154 s  -0.64 %   +0.11 %   +3.4 %     --
crowned standard    170k    2.4 GB  63 s   -0.86 %   +0.06 %   +3.68 %    +0.11 %
straight quick      64k     0.8 GB  16 s   +5.22 %   +0.06 %   edge peak  --
straight standard   207k    3.1 GB  94 s   -0.53 %   +0.03 %   edge peak  -0.06 %
==================  ======  ======  =====  ========  ========  =========  =======

* Convergence (Lundberg, quick / standard / fine): the centre pressure +3.66 / +0.30 /
  -0.64 % off line_contact (standard to fine: -0.94 points, the size of the tents'
  scatter), the nodal pressure peak near the end 1.754 / 1.815 / 1.798 GPa (standard to
  fine -1.0 %), the approach -0.05 / +0.11 / +0.11 %.
* Lundberg's roller: the slice loads agree with line_contact's uniform 122.1 N within
  1 % on every slice but the end one (-9.5 %: the drop grows without bound at the end;
  the FE resolves the last 0.3 b, the strip averages it).  The FE pressure rises to
  1.81 GPa within the last half-width before it falls to zero there (the nodal
  "edge_pressure", +16 %): a feature of how the tents resolve the logarithmic end, not
  checked.
* Circular crown (4 mm flat, 0.5 m crown radius): the pressure peaks where the flat part
  ends (x = 2.3 mm).  The slice loads agree within 0.5 % everywhere (the peak slice
  +0.29 %), the slice-averaged peak pressure by +3.68 % (+1.94 % on an earlier mesh of
  the same level with a deeper edge box): the FE's point pressures scatter by +-2-4 %
  along the roller (tents against P2 surface elements), which sets
  :data:`EDGE_TOLERANCE`.
* Straight roller: the slice loads agree within 2 % up to the end slice (220.6 N against
  227.1 N), the approach within 0.03 %; the end pressure is singular on a half-space and
  the FE's nodal edge peak grows with refinement — 2.77 / 3.39 / 3.86 GPa at the quick /
  standard / fine levels (fine: 484k DOFs, 9.0 GB, 392 s CPU; averaged over the end
  slice 2.38 / not measured / 2.39 GPa) — while line_contact's end slice gives 2.13 GPa at 41 slices (and grows with the slice count,
  its own notes).  Neither is a converged pressure: read both as "an edge peak".
* The SuperLU fallback (no pypardiso wheel, no CHOLMOD) does not fit the standard
  level's budget (scipy's SuperLU took ~10 GB and 820 s for 83k P2 DOFs in the ball
  model's measurements), and not even the quick level's: forced to SuperLU
  (``solver="superlu"``) the quick level's 47k DOFs took 469 s of CPU time and 1.8 GB
  (the factorisation alone 466 s single-threaded; the same results as PARDISO).  Install
  a fast solver
  (:data:`ballrace.fem.solvers.INSTALL_HINT`).

Two bodies (``mode="two-body"``, the elastic finite roller on the block), standard level
with n = 5 (349k DOFs, 4.7 GB, 135 s CPU: beyond the standard budget, so it is not the
default): Lundberg's roller carries 5.7 % more load per length in the middle (129.1 N per
slice against 122.1 N) and 43 % less in the end slice — its free end face makes the
roller softer there than the half-space Lundberg's profile is designed on; the centre
pressure is +1.65 %, the approach +1.6 %.  That is the real roller "beyond the
half-space", a result, not an error.

Tilted roller: the half model (measured; half-space mode, same roller and load)
-------------------------------------------------------------------------------
``tilt=psi`` (line_contact's convention: positive, the end at +x goes in) takes the half
model: both roller ends resolved, twice the quarter model's DOFs and some 2-3 times its
CPU time and memory.  The standard level's 4.4-5.7 GB is beyond the 4 GB budget of the
quarter model's standard level; measured once each with ``/usr/bin/time -v`` on the
shared machine (load average 5-8: the wall times, 0.4 / 8.6 / 0.5 / 3.9 minutes, say
little).  Errors FE / line_contact - 1 on line_contact's 41 slices; "crown": the circular
crown tilted by 0.5 mrad, "Lundberg": Lundberg's roller tilted by 0.2 mrad; "peak p" the
largest slice-averaged pressure (and the x [mm] of the FE's largest; line_contact's:
2.34 mm for the crown, 5.85 mm, the end slice, for Lundberg's), "peak Q" the load of
line_contact's most loaded slice, "end qtr" the load on the outer quarter (|x| >= L/4)
at the loaded end (the row ``end_quarter_load``):

=================  =====  ======  =====  ========  ========  =============  =======  =======
case / level       DOFs   RAM     CPU    centre p  approach  peak p (x FE)  peak Q   end qtr
=================  =====  ======  =====  ========  ========  =============  =======  =======
crown quick        114k   1.4 GB  21 s   +0.88 %   +0.18 %   +2.25 % (2.6)  +0.71 %  -0.47 %
crown standard     357k   5.7 GB  181 s  +0.52 %   +0.14 %   +1.00 % (2.3)  +0.12 %  -0.22 %
Lundberg quick     100k   1.2 GB  19 s   +1.53 %   +0.17 %   +4.43 % (5.6)  -11.5 %  -0.76 %
Lundberg standard  306k   4.4 GB  120 s  +0.18 %   +0.13 %   -1.02 % (5.6)  -9.4 %   -0.42 %
=================  =====  ======  =====  ========  ========  =============  =======  =======

* Circular crown (4 mm flat, 0.5 m crown radius) tilted by 0.5 mrad: line_contact moves
  the peak to where the flat part ends on the +x side (x = 2.34 mm, 1.934 GPa against
  1.882 GPa at -2.34 mm; 1.855 GPa untilted) and leaves three slices at -x and one at
  +x unloaded (the contact inside the roller).  The FE puts the peak there too: at the
  standard level every slice carrying more than 20 N is within 2.1 % (-2.0 % on the
  34 N slice at -4.68 mm; the slice of largest load +0.12 %, the largest difference at
  the loaded end 0.84 % of the mean slice load Q/n); the quick level within 2.3 % of Q/n at the loaded end (-6.4 % on the
  22 N slice where the contact ends).  The approach within 0.2 %, the von Mises maximum
  under the centre +1.3 / +1.0 % (quick / standard).
* Lundberg's roller tilted by 0.2 mrad (line_contact: the end slices carry 91.0 N at
  -x and 148.1 N at +x against 118.7 N each untilted): every slice but the two end ones
  within 1.5 % (quick) and 1.2 % (standard); the end slices -12.6 / -11.5 % (quick) and
  -9.6 / -9.4 % (standard) at -x / +x, as the -9.5 % without tilt (the logarithmic
  drop grows without bound at the end; the strips average what the FE resolves).  So
  the tilt's shift of load between the ends (line_contact: 57.2 N between the end
  slices) is 52.0 N in the FE, -9 %; the loaded end's outer quarter -0.42 %.  The nodal
  "edge_pressure" (2.05 GPa at x = 5.89 mm, +19 %) is the end feature of the untilted
  Lundberg roller, not checked.
* The half model reproduces the quarter model: with a tilt of 1e-9 rad (Lundberg's roller,
  quick level) the slice loads agree with the quarter model's within 0.3 % (the
  curvature penalty weighs the tents at x = 0 differently) and are even in x within
  2e-6 of a slice load; the approach within 0.03 %.
* A profile table that is not even in x takes the half model too (quick level, a crown
  whose flat part runs from -3 to +1 mm: the centre pressure +0.55 %, the approach
  +0.27 %, the most loaded slice +0.06 %, the outer quarter at +x -0.11 %).  ``mode="two-body"`` takes it as well (the circular
  crown tilted by 0.5 mrad, quick level: 186k DOFs, 2.1 GB, 36 s CPU; the loaded end's
  outer quarter carries 4.3 % less than line_contact's, the finite roller's free end face
  as without tilt; a result, not checked; the standard level not run).
* The tolerance of a tilted roller (:data:`TILT_TOLERANCE`): the row
  ``end_quarter_load`` within 2 % (quick) and 1 % (standard), about twice the largest
  difference measured; the slices of that quarter within 4 % / 2 % of Q/n (a circular
  crown).  The other rows keep the quarter model's tolerances (all within them above).

>>> from ballrace import fem                                       # doctest: +SKIP
>>> f = fem.roller_contact(5000.0, 6e-3, np.inf, 12e-3, st, st, level="quick")  # doctest: +SKIP
>>> f.x, f.pressure, f.approach, f.n_dofs                          # doctest: +SKIP
"""
from __future__ import annotations

import logging
import math
import resource
import time
from dataclasses import dataclass, field

import numpy as np

from ballrace.analytic._checks import check_choice
from ballrace.analytic.materials import Material
from ballrace.analytic.roller import ProfileContext, line_contact, subsurface_stress

from . import model

__all__ = ["RollerLevel", "ROLLER_LEVELS", "ROLLER_TOLERANCES", "TILT_TOLERANCE",
           "RollerFEResult", "TensorGrid", "roller_contact"]

log = logging.getLogger(__name__)


# --------------------------------------------------------------------------- levels
@dataclass(frozen=True)
class RollerLevel:
    """Mesh and pressure-grid resolution of the roller model (frozen).

    Attributes
    ----------
    n : float
        Elements per half-width b across the strip and in depth: h = b/n [-].
    stretch : float
        Largest element elongation along the roller in its middle [-] (isotropic at the
        end); the elongation used keeps the middle tent spacing >= TENT_FLOOR_X elements.
    edge : float
        Element size at the roller end relative to h [-] (< 1: finer).
    nx : int
        Pressure-tent nodes along the half roller, graded towards the end [-] (the
        half model, over the full length: 2 nx - 1, graded towards both ends).
    dy : float
        Tent spacing across the strip in half-widths b [-].
    dx_end : float
        Tent spacing at the roller end in half-widths b [-].
    smoothing : float
        Weight of the curvature penalty on the tent pressures
        (:attr:`ballrace.fem.api.MeshLevel.smoothing`) [-].
    """

    n: float
    stretch: float
    edge: float
    nx: int
    dy: float
    dx_end: float
    smoothing: float = 1.0


#: Named levels.  quick: CI smoke level (seconds); standard: the check (<= 60 s and
#: <= 4 GB on 2 cores with PARDISO in half-space mode, measured in the module notes);
#: fine: the convergence reference (some 6 GB).
ROLLER_LEVELS = {"quick": RollerLevel(3.0, 8.0, 1.0, 20, 0.45, 0.6),
                 "standard": RollerLevel(4.5, 6.0, 0.8, 40, 0.25, 0.30),
                 "fine": RollerLevel(6.0, 6.0, 0.7, 56, 0.2, 0.22)}
#: Least tent spacing along the roller in elements (inf-sup: tents as fine as the mesh
#: make the tent pressures oscillate, docs/fem.md); it caps the elongation [-].
TENT_FLOOR_X = 1.5
#: Tolerances of the comparison rows per level (relative) — measured, see
#: :func:`roller_contact` notes; ``None``: reported, not checked.
ROLLER_TOLERANCES = {
    "standard": {"centre_pressure": 0.03, "approach": 0.01, "von_mises_centre": 0.02},
    "quick": {"centre_pressure": 0.06, "approach": 0.03, "von_mises_centre": 0.05},
}
ROLLER_TOLERANCES["fine"] = ROLLER_TOLERANCES["standard"]
MODES = ("half-space", "two-body")
#: Relative tolerances of the edge peak of a circular crown (its largest pressure, where
#: the flat part ends) against line_contact at the standard level, half-space mode
#: (4 mm flat, 0.5 m crown radius, 12 mm roller, 5 kN): the slice-averaged FE pressure
#: was +1.94 % and +3.68 % off on two meshes of the level (the tents' +-2-4 % scatter
#: along the roller), the load of that slice +0.29 %.
EDGE_TOLERANCE = {"crowned": 0.05, "crowned_slice_load": 0.01}
#: Relative tolerances of a tilted roller (the half model, half-space mode) per level:
#: ``end_quarter_load``, the load on the outer quarter of the roller at the more loaded
#: end (the comparison row of that name); ``end_slices``, the largest difference of one
#: of that quarter's slice loads over the mean slice load Q/n (``info
#: ["end_slice_load_deviation"]``; a profile whose drop stays finite at the end, such as
#: a circular crown: the end slice of a logarithmic profile differs by some 10 %, as
#: without tilt).  Measured (module notes, 12 mm roller, 5 kN): end quarter -0.47 / -0.22 %
#: (crown, 0.5 mrad; quick / standard) and -0.76 / -0.42 % (Lundberg, 0.2 mrad); end
#: slices 2.3 / 0.84 % of the mean slice load (crown).
TILT_TOLERANCE = {"quick": {"end_quarter_load": 0.02, "end_slices": 0.04},
                  "standard": {"end_quarter_load": 0.01, "end_slices": 0.02}}
TILT_TOLERANCE["fine"] = TILT_TOLERANCE["standard"]

#: Raceway block beyond the roller end, in roller lengths L [-]; width (rolling
#: direction) and depth, in L [-].  The pressure along the roller is coupled through the
#: far field on the scale of L (line_contact's strips interact as 1/r): a block 4 mm
#: (24 b) wide and deep under the 12 mm roller tilted the slice loads of Lundberg's
#: profile by 10 % from the centre to the end (measured, quick level, half-space mode).
OVERHANG = 1.0
BLOCK_L = 1.5
#: Depth points of the approach, in half-widths b [-].
DEPTH_POINT = 3.0


# --------------------------------------------------------------------------- pressure grid
class TensorGrid:
    """Bilinear tents on a tensor grid ``xn x yn`` (x graded), the interface of
    :class:`ballrace.fem.model.PressureGrid` (``Lx, Ly, n_tents, weights, evaluate,
    integrals, boundary_tents``).  Tent index ``k = i * ny + j``.  ``xn`` starts at 0
    (the quarter model: x = 0 a symmetry plane) or below it (the half model: both ends of
    the grid are roller ends).

    Examples
    --------
    >>> g = TensorGrid([0.0, 0.5, 1.0], [0.0, 1.0])
    >>> g.n_tents, round(float(g.integrals(lambda x, y: 0 * x)["m"].sum()), 12)
    (6, 1.0)
    """

    def __init__(self, xn, yn):
        self.xn = np.asarray(xn, dtype=float)
        self.yn = np.asarray(yn, dtype=float)
        self.Lx, self.Ly = float(self.xn[-1]), float(self.yn[-1])
        self.X0 = float(self.xn[0])

    @property
    def n_tents(self) -> int:
        """Number of tents [-]."""
        return self.xn.size * self.yn.size

    def _cell(self, v, nodes):
        i = np.clip(np.searchsorted(nodes, v, side="right") - 1, 0, nodes.size - 2)
        f = (v - nodes[i]) / (nodes[i + 1] - nodes[i])
        return i, np.clip(f, 0.0, 1.0)

    def weights(self, x, y):
        """(point index, tent index, weight), 4 per point; zero outside the grid."""
        x = np.asarray(x, dtype=float).ravel()
        y = np.asarray(y, dtype=float).ravel()
        inside = (x >= self.X0) & (x <= self.Lx) & (y >= 0) & (y <= self.Ly)
        i, fu = self._cell(x, self.xn)
        j, fv = self._cell(y, self.yn)
        return model.bilinear_weights(i, j, fu, fv, inside, self.yn.size)

    def evaluate(self, lam, x, y):
        """Pressure at points [Pa]."""
        return model.evaluate_tents(self, lam, x, y)

    def integrals(self, gap, order: int = 6) -> dict:
        """``m = int phi_k``, ``G0 = int phi_k g0``, ``Mx = int phi_k x`` per tent."""
        g, w = np.polynomial.legendre.leggauss(order)
        g, w = 0.5 * (g + 1.0), 0.5 * w
        nx, ny = self.xn.size, self.yn.size
        ci, cj = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1), indexing="ij")
        ci, cj = ci.ravel(), cj.ravel()
        dx = np.diff(self.xn)[ci]
        dy = np.diff(self.yn)[cj]
        GU, GV = np.meshgrid(g, g, indexing="ij")
        fu, fv = GU.ravel(), GV.ravel()
        WW = np.outer(w, w).ravel()[None, :] * (dx * dy)[:, None]
        x = self.xn[ci][:, None] + fu[None, :] * dx[:, None]
        y = self.yn[cj][:, None] + fv[None, :] * dy[:, None]
        g0 = gap(x, y)
        out = {k: np.zeros(self.n_tents) for k in ("m", "G0", "Mx")}
        for di, dj, phi in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)),
                            (0, 1, (1 - fu) * fv), (1, 1, fu * fv)):
            k = (ci + di) * ny + (cj + dj)
            pw = phi[None, :] * WW
            np.add.at(out["m"], k, pw.sum(axis=1))
            np.add.at(out["G0"], k, (g0 * pw).sum(axis=1))
            np.add.at(out["Mx"], k, (x * pw).sum(axis=1))
        return out

    def curvature_penalty(self) -> np.ndarray:
        """``R = Dx^T Dx + Dy^T Dy``: squared second differences of the tents along x and
        y (index differences, mirrored at x = 0 and y = 0, one-sided at the far edges;
        one-sided at both ends along x when the grid spans both sides of x = 0)
        [-] — the stabilisation of :meth:`ballrace.fem.model.PressureGrid.curvature_penalty`
        on this grid."""
        def d2(n, mirror_end, mirror_start=True):
            D = np.zeros((n, n))
            for i in range(n):
                D[i, i] -= 2.0
                if i > 0 or mirror_start:
                    D[i, abs(i - 1)] += 1.0
                if i + 1 < n:
                    D[i, i + 1] += 1.0
                elif mirror_end:
                    D[i, i - 1] += 1.0
            return D
        nx, ny = self.xn.size, self.yn.size
        Dx = np.kron(d2(nx, False, self.X0 == 0.0), np.eye(ny))
        Dy = np.kron(np.eye(nx), d2(ny, True))
        return Dx.T @ Dx + Dy.T @ Dy

    def boundary_tents(self) -> np.ndarray:
        """Tents on the outer edge y = Ly (the roller end x = Lx is a real edge)."""
        i, j = np.meshgrid(np.arange(self.xn.size), np.arange(self.yn.size), indexing="ij")
        return np.flatnonzero((j == self.yn.size - 1).ravel())

    def strip_loads(self, lam, x_lo, x_hi, n: int = 8):
        """Load of the grid's side y >= 0 between x_lo and x_hi (arrays) [N]:
        ``int int p dx dy`` by Gauss-Legendre along x (``n`` per strip) and the
        trapezoid rule of the exact bilinear profile across."""
        lam = np.asarray(lam).reshape(self.xn.size, self.yn.size)
        tx, wx = np.polynomial.legendre.leggauss(n)
        out = []
        wy = np.zeros(self.yn.size)
        d = np.diff(self.yn)
        wy[:-1] += 0.5 * d
        wy[1:] += 0.5 * d
        for a, b in zip(np.atleast_1d(x_lo), np.atleast_1d(x_hi)):
            xs = 0.5 * (a + b) + 0.5 * (b - a) * tx
            i, f = self._cell(np.clip(xs, self.X0, self.Lx), self.xn)
            row = (1 - f)[:, None] * lam[i] + f[:, None] * lam[i + 1]     # (n, ny)
            row = np.where(((xs <= self.Lx) & (xs >= self.X0))[:, None], row, 0.0)
            out.append(float(0.5 * (b - a) * wx @ (row @ wy)))
        return np.array(out)


def graded_nodes(length: float, n: int, d_end: float, ratio: float = 1.15) -> np.ndarray:
    """``n`` nodes on ``[0, length]``: spacing ``d_end`` at ``length``, growing by
    ``ratio`` per cell towards 0 up to a uniform middle spacing [m].

    Examples
    --------
    >>> x = graded_nodes(10.0, 21, 0.1)
    >>> round(float(x[-1] - x[-2]), 6), float(x[0]), float(x[-1])
    (0.1, 0.0, 10.0)
    """
    m = n - 1
    if d_end * m >= length:
        return np.linspace(0.0, length, n)
    k = np.arange(m)
    lo, hi = d_end, length

    def total(cap, q):
        return np.minimum(d_end * q ** k, cap).sum()

    q = ratio
    while total(np.inf, q) < length:
        q *= 1.05
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if total(mid, q) < length:
            lo = mid
        else:
            hi = mid
    d = np.minimum(d_end * q ** k, 0.5 * (lo + hi))
    d *= length / d.sum()
    x = length - np.concatenate([[0.0], np.cumsum(d)])
    x = x[::-1]
    x[0], x[-1] = 0.0, length
    return x


# --------------------------------------------------------------------------- result
@dataclass
class RollerFEResult:
    """Result of :func:`roller_contact` (SI units).

    Attributes
    ----------
    x : ndarray
        Axial positions of the pressure nodes, 0 (roller centre) to L/2 (roller end) in
        the quarter model, -L/2 to L/2 in the half model (a tilt; ``info["model"]``) [m].
    pressure : ndarray
        Peak over the rolling direction of the FE pressure at each x [Pa].
    approach : float
        FE estimate of line_contact's approach (distant points at x = 0): the depth-point
        approach plus the half-space displacements of the depth points [m].
    approach_depth_point : float
        Approach of the two depth points measured in the FE model [m].
    approach_rigid : float
        Rigid approach of the supports (roller axis plane, block bottom) [m]; includes the
        bodies' bulk compliance.
    centre_pressure : float
        FE peak pressure averaged over line_contact's centre slice [Pa] (the comparison
        row "centre_pressure"; "centre_pressure_node" is the value at x = 0).
    edge_pressure : float
        The largest nodal pressure in the outer halves (|x| >= L/4) [Pa]: the edge peak
        (in the half model, that of the more loaded end).
    x_edge : float
        Where that edge peak lies [m].
    slice_x, slice_loads : ndarray
        line_contact's slice centres (x >= 0 in the quarter model, all in the half
        model) and the FE load on each slice [m], [N] (the centre slice whole: both
        halves).
    slice_pressure : ndarray
        FE peak pressure (over y) averaged over each slice [Pa]; its largest value is the
        row "max_pressure" ("max_pressure_node": the largest nodal value).
    von_mises_centre, von_mises_centre_depth, von_mises_edge, von_mises_edge_depth : float
        Von Mises maximum over depth in the raceway and its depth, under the roller centre
        and under line_contact's edge peak (``info["x_stress_edge"]``) [Pa], [m].
    n_dofs : int
        Degrees of freedom of all bodies [-].
    timings : dict
        Seconds per stage [s].
    peak_rss : int
        Peak resident memory of the process [bytes].
    analytic : LineContactResult
        line_contact for the same inputs.
    comparison : list of dict
        Rows ``quantity, unit, fe, analytic, error, tol, ok``.
    fields : dict
        What a picture needs (:func:`ballrace.fem.render.render_roller`): the pressure
        grid and tent pressures (``grid``, ``lam`` [Pa]), the displacements of each body
        (``u`` [m]), the raceway body (``raceway``: a :class:`ballrace.fem.model.Body`,
        its mesh points [m] and tetrahedra, E [Pa], nu [-] and surface; no stiffness or
        factor is kept) and the von Mises profiles under the centre and the edge peak
        (``depth`` [m], ``von_mises``, ``analytic_von_mises`` [Pa]).
    info : dict
        Mesh and run details; ``roller_radius`` R1 and ``raceway_radius`` R2 [m] of the
        solve (``None``: a flat raceway), ``model`` ("quarter" or "half") and ``tilt``
        [rad].
    """

    level: str
    mode: str
    x: np.ndarray
    pressure: np.ndarray
    approach: float
    approach_depth_point: float
    approach_rigid: float
    centre_pressure: float
    edge_pressure: float
    x_edge: float
    slice_x: np.ndarray
    slice_loads: np.ndarray
    slice_pressure: np.ndarray
    von_mises_centre: float
    von_mises_centre_depth: float
    von_mises_edge: float
    von_mises_edge_depth: float
    n_dofs: int
    timings: dict
    peak_rss: int
    solver: str
    analytic: object
    comparison: list
    fields: dict = field(default_factory=dict, repr=False)
    info: dict = field(default_factory=dict)

    @property
    def within_tolerance(self) -> bool | None:
        """True when every row with a tolerance is within it; None when none has one."""
        checked = [r["ok"] for r in self.comparison if r["tol"] is not None]
        return all(checked) if checked else None

    def row(self, quantity: str) -> dict:
        """The comparison row of ``quantity``."""
        for r in self.comparison:
            if r["quantity"] == quantity:
                return r
        raise KeyError(quantity)

    def side_by_side(self) -> list:
        """Per slice of line_contact (x >= 0; every slice in the half model): ``x`` [m],
        FE and line_contact slice pressure [Pa] and slice load [N], as dicts."""
        c = self.analytic
        s0 = c.n_slices - len(self.slice_x)         # 0 in the half model: every slice
        return [{"x": float(x), "pressure_fe": float(pf), "pressure_line_contact": float(pa),
                 "load_fe": float(lf), "load_line_contact": float(la)}
                for x, pf, pa, lf, la in zip(self.slice_x, self.slice_pressure,
                                             c.pressure[s0:], self.slice_loads,
                                             c.slice_loads[s0:])]

    def to_dict(self) -> dict:
        """JSON-ready summary (SI units)."""
        keys = ("level", "mode", "approach", "approach_depth_point", "approach_rigid",
                "centre_pressure", "edge_pressure", "x_edge", "von_mises_centre",
                "von_mises_centre_depth", "von_mises_edge", "von_mises_edge_depth",
                "n_dofs", "peak_rss", "solver")
        out = {k: getattr(self, k) for k in keys}
        out["x"] = self.x.tolist()
        out["pressure"] = self.pressure.tolist()
        out["timings"] = dict(self.timings)
        out["comparison"] = list(self.comparison)
        out["slices"] = self.side_by_side()
        out["info"] = {k: v for k, v in self.info.items()}
        return out


# --------------------------------------------------------------------------- half-space
def halfspace_w(contact, z: float, E: float, nu: float, n_x: int = 8, n_y: int = 16) -> float:
    r"""Displacement (into the body) at depth ``z`` under the roller centre ``x = 0`` of
    one half-space loaded by line_contact's pressure [m].

    Boussinesq (Johnson 1985 eq. 3.22c): ``u_z = P/(4 pi G) [2 (1 - nu)/rho + z^2/rho^3]``
    integrated over every loaded strip (Gauss-Legendre along it, Gauss-Chebyshev of the
    second kind across, exact for the semi-ellipse weight).

    Parameters
    ----------
    contact : LineContactResult
    z : float
        Depth [m], > 0.
    E, nu : float
        Young's modulus [Pa] and Poisson's ratio [-] of the body.
    """
    G = E / (2.0 * (1.0 + nu))
    w = contact.slice_width
    tx, wx = np.polynomial.legendre.leggauss(n_x)
    j = np.arange(1, n_y + 1)
    th = j * math.pi / (n_y + 1)
    ty, wy = np.cos(th), math.pi / (n_y + 1) * np.sin(th) ** 2
    total = 0.0
    for xk, pk, bk in zip(contact.x, contact.pressure, contact.half_width):
        if pk <= 0:
            continue
        xs = xk + 0.5 * w * tx
        ys = bk * ty
        X, Y = np.meshgrid(xs, ys, indexing="ij")
        W = np.outer(0.5 * w * wx, bk * wy) * pk
        rho = np.sqrt(X * X + Y * Y + z * z)
        total += float(np.sum(W * (2.0 * (1.0 - nu) / rho + z * z / rho**3)))
    return total / (4.0 * math.pi * G)


# --------------------------------------------------------------------------- model
def roller_contact(Q, R1, R2, length, mat1: Material, mat2: Material, profile="lundberg",
                   level="standard", *, mode: str = "half-space", n_slices: int = 41,
                   tilt: float = 0.0, solver: str | None = None,
                   use_cache: bool = True) -> RollerFEResult:
    """FE check of a profiled roller on its raceway against
    :func:`ballrace.analytic.roller.line_contact` (module notes).

    Parameters
    ----------
    Q : float
        Normal roller load [N], > 0.
    R1 : float
        Roller radius in the rolling direction [m].
    R2 : float
        Raceway radius in the rolling direction [m]: ``np.inf`` flat, negative concave.
    length : float
        Effective roller length L [m].
    mat1, mat2 : Material
        Roller and raceway materials.
    profile : str, Profile or (x, drop)
        Roller profile (:func:`ballrace.analytic.roller.as_profile`); "lundberg" by name
        is designed for ``Q``.  A profile whose drop is not even in x takes the half
        model (as a tilt does).
    level : {"quick", "standard", "fine"} or RollerLevel
        Mesh level (:data:`ROLLER_LEVELS`).
    mode : {"half-space", "two-body"}
        A rigid roller on one elastic block of modulus E'/2 (1 - nu2^2), large against
        the roller (line_contact's idealisation: the verification, default), or the
        roller and the raceway both elastic (the real finite roller, "beyond the
        half-space": its free end face shifts load to the middle; module notes).
    n_slices : int
        Slices of the line_contact compared with [-].
    tilt : float
        Tilt of the roller about the rolling direction [rad], as in
        :func:`ballrace.analytic.roller.line_contact` (positive: the end at +x goes in;
        the tilt imposed, ``Q`` given, the moment a reaction): the gap gains line_contact's
        ``- x tan(tilt)``.  Its checks apply (the ValueError beyond (-pi/2, pi/2) or when
        one slice only touches, the warning beyond 0.1 rad: degrees typed as radians).
        A nonzero tilt takes the half model (module notes); 0 keeps the quarter model.
    solver : str, optional
        Force a sparse solver (:data:`ballrace.fem.solvers.SOLVERS`).
    use_cache : bool
        Use the mesh cache.

    Returns
    -------
    RollerFEResult
    """
    from ballrace.meshes import roller as mr

    from . import extract as ex
    from .model import Body, assemble_body, compliance, solve_contact
    from .solvers import slow_solver_hint

    t_all = time.perf_counter()
    c = line_contact(Q, R1, R2, length, mat1, mat2, profile=profile, tilt=tilt,
                     n_slices=n_slices)
    if not Q > 0:
        raise ValueError(f"Q must be > 0 [N] for the FE check; got {Q!r}")
    if isinstance(level, RollerLevel):
        name, lv = "custom", level
    else:
        check_choice(level, "level", tuple(ROLLER_LEVELS))
        name, lv = level, ROLLER_LEVELS[level]
    check_choice(mode, "mode", MODES)
    prof = c.profile
    ctx = ProfileContext(length=c.length, diameter=2.0 * float(R1), E_prime=c.E_prime, R=c.R,
                         load=float(Q))
    probe = np.linspace(-0.45, 0.45, 19) * c.length
    psi = float(c.tilt)
    # the quarter model needs x = 0 as a symmetry plane: no tilt and an even profile
    half = psi != 0.0 or not np.allclose(prof.drop(probe, ctx), prof.drop(-probe, ctx),
                                         rtol=1e-9, atol=1e-15)
    n_parts = 2 if half else 4          # the model is a half or a quarter of the contact
    hint = slow_solver_hint(solver)
    if hint:
        log.warning(hint)
    R1, R2, L = float(R1), float(R2), float(c.length)
    Lh = 0.5 * L
    R = c.R
    Ep = c.E_prime
    q0 = Q / L
    b0 = math.sqrt(8.0 * q0 * R / (math.pi * Ep))            # 2-D Hertz half-width
    bmax = max(float(np.max(c.half_width)), b0)
    h = b0 / lv.n
    timings = {}

    # pressure grid: across to 1.3 of the widest slice, along graded to the end
    Ly = 1.3 * bmax + lv.dy * b0
    ny = max(3, int(math.ceil(Ly / (lv.dy * b0))))
    yn = np.linspace(0.0, Ly, ny + 1)
    xn = graded_nodes(Lh, lv.nx, lv.dx_end * b0)
    if half:                            # graded towards both ends
        xn = np.concatenate([-xn[:0:-1], xn])
    grid = TensorGrid(xn, yn)

    # meshes: elements along the roller no longer than the tent spacing allows
    stretch = float(np.clip(np.max(np.diff(xn)) / (TENT_FLOOR_X * h), 1.0, lv.stretch))
    t0 = time.perf_counter()
    strip = Ly + 2.0 * h
    # full-depth refinement (the von Mises maxima lie at 0.7 b) under the centre and over
    # the last 1.5 b of the roller; a thin layer along the rest of the strip
    kw = dict(strip=strip, layer=0.5 * b0, depth=1.2 * bmax + 0.4 * b0, column=2.0 * b0,
              edge_zone=1.5 * bmax, h=h, h_edge=lv.edge * h, growth=0.3,
              stretch=stretch, use_cache=use_cache)
    X = Lh + OVERHANG * L
    Yb = min(BLOCK_L * L, 0.5 * abs(R2)) if np.isfinite(R2) else BLOCK_L * L
    Hb = BLOCK_L * L
    blk = mr.raceway_mesh((X, Yb, Hb), Lh, half=half, **kw)
    race_surface = mr.RacewaySurface(R2 if mode == "two-body" else math.inf)
    cn = blk.points[:, 2] == 0.0
    if mode == "two-body" and np.isfinite(R2):
        blk = mr.bend_raceway(blk, race_surface, Hb)
    meshes = [blk]
    bodies = []
    if mode == "two-body":
        xs = np.linspace(-Lh if half else 0.0, Lh, 1601 if half else 801)
        xe = Lh * (1 - 1e-9)
        dr = np.asarray(prof.drop(np.clip(xs, -xe, xe), ctx), dtype=float)
        dr = np.minimum(np.where(np.isfinite(dr), dr, np.inf), 0.3 * b0)
        rol = mr.roller_mesh(R1, Lh, drop=(xs, dr), half=half, **kw)
        p = rol.points
        r = np.hypot(p[:, 1], R1 - p[:, 2])
        target = R1 - np.interp(p[:, 0], xs, dr)
        on = (np.abs(r - target) < 1e-6 * R1) & (p[:, 2] < 0.5 * R1)
        bodies.append(Body("roller", p, rol.tets, mat1.E, mat1.nu, +1, R1, on,
                           mr.RollerSurface(R1, tuple(xs), tuple(dr)),
                           symmetric_x=not half))
        meshes.insert(0, rol)
        bodies.append(Body("raceway", blk.points, blk.tets, mat2.E, mat2.nu, -1, -Hb, cn,
                           race_surface, symmetric_x=not half))
    else:
        E_hs = 0.5 * Ep * (1.0 - mat2.nu**2)
        bodies.append(Body("half-space", blk.points, blk.tets, E_hs, mat2.nu, -1, -Hb, cn,
                           race_surface, symmetric_x=not half))
    timings["mesh"] = time.perf_counter() - t0

    states = []
    for b in bodies:
        st = assemble_body(b, grid, solver)
        states.append(st)
        for k, v in st.timings.items():
            timings[k] = timings.get(k, 0.0) + v
    n_dofs = int(sum(s.n_dofs for s in states))

    # gap: the profile drop (seen once) and the quadratic gap across; the half model
    # adds line_contact's tilt term - x tan(psi), shifted by its least value g_min <= 0
    # so that the gap is >= 0 at zero approach (the approach is then Delta + g_min)
    t0 = time.perf_counter()
    cap = 50.0 * max(c.approach, b0 * b0 / R)

    def g_axial(x):
        d = np.asarray(prof.drop(np.clip(x, -Lh * (1 - 1e-12), Lh * (1 - 1e-12)), ctx),
                       dtype=float)
        return np.minimum(np.where(np.isfinite(d), d, cap), cap) - x * math.tan(psi)

    g_min = min(0.0, float(np.min(g_axial(np.linspace(-Lh, Lh, 4001))))) if half else 0.0

    def g0(x, y):
        if half:
            return g_axial(x) - g_min + y * y / (2.0 * R)
        d = np.asarray(prof.drop(np.minimum(x, Lh * (1 - 1e-12)), ctx), dtype=float)
        d = np.minimum(np.where(np.isfinite(d), d, cap), cap)
        return d + y * y / (2.0 * R)

    I = grid.integrals(g0)
    C = compliance(states)
    timings["compliance"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    p2d = math.sqrt(q0 * Ep / (2.0 * math.pi * R))
    pen = None
    if lv.smoothing > 0:
        pen = lv.smoothing * float(np.mean(np.diag(C))) / 16.0 * grid.curvature_penalty()
    sol = solve_contact(C, I["G0"], I["m"], load=Q / n_parts, p_ref=p2d,
                        delta_ref=c.approach, penalty=pen)
    Delta = sol.Delta + g_min
    timings["contact"] = time.perf_counter() - t0

    # ---- extraction
    t0 = time.perf_counter()
    lam = sol.lam.reshape(xn.size, yn.size)
    yf = np.linspace(0.0, Ly, 8 * ny + 1)
    P = np.array([grid.evaluate(sol.lam, np.full(yf.size, xi), yf).max() for xi in xn])
    at_edge = bool(np.any(lam[:, -1] > 1e-6 * lam.max()))
    if at_edge:
        log.warning("roller contact reaches the edge of the pressure grid across the strip")
    i_0 = int(np.flatnonzero(xn == 0.0)[0])            # the roller centre
    p_c = float(P[i_0])
    outer = np.abs(xn) >= 0.5 * Lh                      # the edge peak: the larger end
    k_e = int(np.flatnonzero(outer)[np.argmax(P[outer])])
    p_e, x_e = float(P[k_e]), float(xn[k_e])
    # line_contact's side: the slices x >= 0 (quarter model) or all (half model)
    mid = (c.n_slices - 1) // 2
    s0 = 0 if half else mid
    i_c = mid - s0                                      # the centre slice
    cx = np.asarray(c.x)[s0:]
    cp = np.asarray(c.pressure)[s0:]
    outer_c = np.abs(cx) >= 0.25 * L
    k_ce = int(np.flatnonzero(outer_c)[np.argmax(cp[outer_c])])
    w = c.slice_width
    lo = cx - 0.5 * w if half else np.maximum(cx - 0.5 * w, 0.0)
    hi = cx + 0.5 * w
    fl = 2.0 * grid.strip_loads(sol.lam, lo, hi)        # both sides of y = 0
    if not half:
        fl[0] *= 2.0                                    # the centre slice: both sides of x = 0
    # the FE peak pressure averaged over each of line_contact's slices (the strip
    # method's slice pressure is that of the slice's mean load): the tents' scatter
    # along the roller (+-2 %) averages out
    sp = []
    for a, b_ in zip(lo, hi):
        xx = np.linspace(a, min(b_, Lh), 17)
        sp.append(float(np.mean([grid.evaluate(sol.lam, np.full(yf.size, v), yf).max()
                                 for v in xx])))
    sp = np.array(sp)
    us = [ex.displacement(s, sol.lam) for s in states]
    eps = 1e-7 * h
    zq = DEPTH_POINT * b0
    d_fe = Delta
    w_sum = 0.0
    low = states[-1]
    for s, u in zip(states, us):
        b = s.body
        pt = np.array([[eps, eps, b.side * zq]])
        d_fe -= b.side * ex.probe_displacement(s, u, pt)[0, 2]
        if mode == "two-body":
            w_sum += halfspace_w(c, zq, b.E, b.nu)
    if mode == "half-space":        # both bodies of line_contact in the one block
        w_sum = halfspace_w(c, zq, mat1.E, mat1.nu) + halfspace_w(c, zq, mat2.E, mat2.nu)
    approach_fe = d_fe + w_sum
    # von Mises over depth in the raceway, under the centre and under the edge peak
    x_se = float(cx[k_ce])
    zs = np.linspace(0.1, 2.5, 49) * b0
    vm_fe = []
    for xv in (0.0, x_se):
        pts = np.stack([np.full(zs.size, xv + eps), np.full(zs.size, eps),
                        race_surface.height(xv, 0.0) - zs], axis=1)
        S = ex.to_depth_frame(ex.stresses(low, us[-1], pts))
        vm_fe.append(ex.tresca_von_mises(S)[1])
    (zc, vc), (ze, ve) = (ex.peak_fit(zs, v) for v in vm_fe)
    an = subsurface_stress(c, nu=low.body.nu, x=[0.0, x_se], depth=zs)
    timings["extract"] = time.perf_counter() - t0
    timings["total"] = time.perf_counter() - t_all

    # two bodies: the finite roller departs from line_contact's half-spaces (module
    # notes) -- its differences are results, no tolerances apply
    tol = ROLLER_TOLERANCES.get(name, ROLLER_TOLERANCES["standard"]) if mode == "half-space" \
        else {}
    if half and mode == "half-space":
        tol = dict(tol, end_quarter_load=TILT_TOLERANCE.get(
            name, TILT_TOLERANCE["standard"])["end_quarter_load"])
    rows = []

    def row(q, unit, fe, an_):
        err = fe / an_ - 1.0 if an_ else float("nan")
        t = tol.get(q)
        rows.append({"quantity": q, "unit": unit, "fe": float(fe), "analytic": float(an_),
                     "error": float(err), "tol": t, "ok": bool(t is None or abs(err) <= t)})

    row("centre_pressure", "Pa", float(sp[i_c]), float(cp[i_c]))
    row("centre_pressure_node", "Pa", p_c, float(cp[i_c]))
    row("edge_pressure", "Pa", p_e, float(cp[k_ce]))
    row("max_pressure", "Pa", float(sp.max()), float(cp.max()))
    row("max_pressure_node", "Pa", float(P.max()), float(cp.max()))
    k_pk = int(np.argmax(cp))
    row("peak_slice_load", "N", float(fl[k_pk]), float(c.slice_loads[s0 + k_pk]))
    row("approach", "m", approach_fe, float(c.approach))
    row("approach_depth_point", "m", d_fe, float(c.approach) - w_sum)
    # the end slice at the more loaded end (line_contact's outer quarters compared; +x in
    # the quarter model and on a tie)
    cl = np.asarray(c.slice_loads)
    k_end = 0 if half and cl[c.x <= -0.25 * L].sum() > cl[c.x >= 0.25 * L].sum() else -1
    row("edge_slice_load", "N", float(fl[k_end]), float(c.slice_loads[k_end]))
    if half:
        # the load on the outer quarter of the roller at the more loaded end (|x| >= L/4,
        # line_contact's slices), and its slices' largest difference over the mean
        # slice load Q/n: where a tilt puts the load
        sgn = -1.0 if k_end == 0 else 1.0
        q_end = sgn * cx >= 0.25 * L
        an_end = np.asarray(c.slice_loads)[q_end]
        row("end_quarter_load", "N", float(fl[q_end].sum()), float(an_end.sum()))
        end_dev = float(np.max(np.abs(fl[q_end] - an_end))) / (Q / c.n_slices)
    row("von_mises_centre", "Pa", vc, float(an.von_mises_max[0]))
    row("von_mises_centre_depth", "m", zc, float(an.von_mises_depth[0]))
    row("von_mises_edge", "Pa", ve, float(an.von_mises_max[1]))
    row("von_mises_edge_depth", "m", ze, float(an.von_mises_depth[1]))
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    info = {"b_hertz": b0, "h": h, "stretch": stretch, "n_tents": grid.n_tents, "grid_nx": xn.size,
            "grid_ny": yn.size, "depth_point": zq, "halfspace_w_depth_points": w_sum,
            "complementarity": sol.complementarity, "pressure_at_grid_edge": at_edge,
            "x_stress_edge": x_se, "x_edge_analytic": x_se,
            "mesh_nodes": [int(m.n_nodes) for m in meshes],
            "mesh_digests": [m.digest() for m in meshes], "load_check": n_parts * sol.load,
            "model": "half" if half else "quarter", "tilt": psi,
            "slice_load_sum": float(fl.sum() if half else 2.0 * fl.sum() - fl[0]),
            "x_edge_slice": float(cx[k_end]), "roller_radius": R1,
            "raceway_radius": R2 if math.isfinite(R2) else None}
    if half:
        info["end_slice_load_deviation"] = end_dev
    for s in states:
        s.release()
    res = RollerFEResult(
        level=name, mode=mode, x=xn, pressure=P, approach=approach_fe,
        approach_depth_point=d_fe, approach_rigid=Delta, centre_pressure=float(sp[i_c]),
        edge_pressure=p_e, x_edge=x_e, slice_x=cx, slice_loads=fl, slice_pressure=sp,
        von_mises_centre=vc,
        von_mises_centre_depth=zc, von_mises_edge=ve, von_mises_edge_depth=ze,
        n_dofs=n_dofs, timings=timings, peak_rss=int(peak), solver=states[0].solver,
        analytic=c, comparison=rows,
        fields={"grid": grid, "lam": sol.lam, "depth": zs, "von_mises": vm_fe,
                "analytic_von_mises": an.von_mises, "u": us, "raceway": bodies[-1]},
        info=info)
    log.info("roller contact (%s, %s): %d DOFs in %.1f s", mode, name, n_dofs,
             timings["total"])
    return res


