r"""An elastic shaft on two or more ball bearings, solved together.

The shaft is a straight, stepped, solid or hollow beam along x, discretised into
two-node Timoshenko beam elements (axial, two lateral translations, two rotations per
node; torsion is not modelled).  Every seat holds a bearing -- a
:class:`~ballrace.BallBearing`, a :class:`~ballrace.analytic.duplex.DuplexPair`, or any
bearing that implements the seat contract (:mod:`ballrace.analytic.contract`) -- whose
inner ring moves with the shaft node and whose outer ring sits in the housing (rigid, or through a given housing
stiffness).  The bearings keep their exact nonlinear five-degree-of-freedom
load–deflection law (:mod:`ballrace.analytic.loaddist`: rigid rings, exact Hertz K_n at
each ball's own contact angle, contact angles free); one global Newton iteration finds
the shaft displacements at which the beam, the bearings and the loads are in
equilibrium.

Frame and sign conventions
--------------------------
::

          y (radial)
          ^
          |        seat 0               load               seat 1
          |     ___[o]___________________|_________________[o]___
          +--> x ===|=====================v==================|=====  shaft axis
         /      ~~~[o]~~~              Fy < 0              ~~~[o]~~~
        z          housing                                  housing
      (radial, x × y)

    x     : the shaft axis, from the shaft's left end (x = 0) to its right end.
    y, z  : lateral axes, right-handed (z = x × y).
    node DOFs (u, v, w, theta_y, theta_z): axial, y and z translation [m] and right-handed
            rotations about y and z [rad]; for bending in the x–y plane theta_z = dv/dx,
            in the x–z plane theta_y = -dw/dx (Euler–Bernoulli limit).
    loads : (Fa, Fy, Fz, My, Mz) [N, N m] in the same frame, applied to the shaft.

This is the frame of :mod:`ballrace.analytic.loaddist` (x axial, y and z radial, ball
azimuth from +y towards +z, right-handed tilts), so a bearing mounted with
``direction=+1`` sees the shaft's displacements unchanged.  A bearing mounted the other
way round (``direction=-1``) is the same bearing turned by 180 deg about the z axis:
its own frame is (x, y, z) -> (-x, -y, z), so displacements and loads are mapped by
T = diag(-1, -1, 1, -1, 1) (rotations are axial vectors and turn with the frame).

Which way a bearing takes thrust (``direction``); upper half of a section through the
bearing, contact line through the ball centre::

        direction = +1                        direction = -1
      outer ring ------- *                  * ------- outer ring
                      ( o )               ( o )
      inner ring --- *                        * --- inner ring
        inner ring pushes the ball +x          inner ring pushes the ball -x
        ==> shaft thrust towards +x carried    ==> shaft thrust towards -x carried
        contact line "/", pressure centre      contact line "\", pressure centre
        on the axis to the left (-x)           on the axis to the right (+x)

    The free-contact-angle side of the bearing is loaded when the shaft (inner ring)
    moves towards +x relative to the housing (direction=+1) or towards -x (-1).  With
    the groove modelled as a complete torus (as in loaddist) a bearing also carries
    reverse thrust once the clearance is taken up; a deep-groove bearing is symmetric.

Two single angular-contact bearings at two seats form an O arrangement (back-to-back:
contact lines diverging towards the axis, pressure centres spread beyond the seats)
with ``direction=+1`` on the left seat and ``-1`` on the right one, and an X
arrangement (face-to-face) with ``-1`` on the left and ``+1`` on the right::

      O (back-to-back):   /o ........ o\        X (face-to-face):  o\ ........ /o
                          +1          -1                           -1          +1
      shaft growth unloads the pair           shaft growth loads the pair more

A duplex pair at one seat follows the same rule: ``direction`` is that of its bearing
1; in DB bearing 1 is the left row when ``direction=+1``.

Reactions
---------
``result.reactions[i]`` is the load (Fa, Fy, Fz, My, Mz) that seat i carries: the force
and moment the shaft applies to the bearing's inner ring at the seat position, in the
shaft frame (the bearing pushes back on the shaft with the opposite).  Global
equilibrium is therefore sum(reactions) = sum(applied loads), with the moments about a
common point carried along (:meth:`ShaftResult.equilibrium_residual`).

What the model neglects: torsion and the torque path; shaft–ring fit compliance and
ring deformation (rigid rings, as in loaddist); centrifugal and gyroscopic ball loads;
bearing width (a single bearing acts at one point; a duplex pair optionally as two
rows at ``row_spacing``); the shaft's own weight is applied as consistent nodal loads
of cubic (Euler–Bernoulli) elements, which is exact at the nodes only for slender
elements (the automatic refinement makes them short).

References
----------
Timoshenko, S.P. (1921) Phil. Mag. 41, 744–746 (shear deformation); Przemieniecki, J.S.
(1968) *Theory of Matrix Structural Analysis*, McGraw-Hill, ch. 5 (beam element with
shear deformation); Friedman, Z. & Kosmatka, J.B. (1993) Comput. Struct. 47(3) 473–481
(exact Timoshenko shape functions); Cowper, G.R. (1966) J. Appl. Mech.
33(2) 335–340 (shear coefficient of a hollow circle, Table 1); Harris, T.A. (2001)
*Rolling Bearing Analysis*, 4th ed., Wiley, §7.4 (5-DOF bearing stiffness); Jones, A.B.
(1960) J. Basic Eng. 82(2) 309–320.
"""
from __future__ import annotations

import copy
import functools
import logging
import math
from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import cho_solve_banded, cholesky_banded

from . import contract, loaddist, newton
from ._checks import (as_array, broadcast, check_choice, check_instance, check_integer,
                      check_nonnegative, check_positive, check_range)
from .clearance import OperatingClearance
from ..errors import ConvergenceError
from .newton import POLICY
from .materials import BEARING_STEEL, Material

__all__ = ["Shaft", "Seat", "PointLoad", "ShaftResult", "ConvergenceError", "solve",
           "gear_mesh", "belt_pull", "shear_coefficient", "MIRROR", "STANDARD_GRAVITY",
           "ShaftLife", "DutyCycleLife", "rating_lives", "system_life", "duty_cycle",
           "bearing_coefficients", "ross_bearings"]

log = logging.getLogger(__name__)

#: Map between the shaft frame and a bearing turned round (direction = -1):
#: (x, y, z) -> (-x, -y, z), tilts (theta_y, theta_z) -> (-theta_y, theta_z).
MIRROR = np.array([-1.0, -1.0, 1.0, -1.0, 1.0])

#: Standard acceleration of gravity g_n = 9.80665 m/s^2 (CGPM 1901).
STANDARD_GRAVITY = 9.80665

DOF_NAMES = ("axial translation u", "lateral translation v (y)", "lateral translation w (z)",
             "rotation about y", "rotation about z")


def _count(value, name, low=1) -> int:
    """A whole number >= low given as one number (TypeError for text, booleans, arrays)."""
    n = check_integer(value, name, low)
    if n.ndim:
        raise TypeError(f"{name} must be one whole number >= {low}; got shape {n.shape}")
    return int(n)


def _scalar(value, name, unit) -> float:
    """One finite number of physical magnitude (any sign, any small value) [unit]."""
    v = as_array(value, name, bounded=True, tiny_ok=True, unit=unit)
    if v.ndim:
        raise TypeError(f"{name} must be one number [{unit}]; got shape {v.shape}")
    return float(v)


# =========================================================================== the shaft
def shear_coefficient(nu, inner_ratio=0.0):
    r"""Timoshenko shear coefficient of a solid or hollow circular section [-].

    .. math:: \kappa = \frac{6(1+\nu)(1+m^2)^2}{(7+6\nu)(1+m^2)^2 + (20+12\nu)m^2},
              \qquad m = d_i/d_o

    (Cowper 1966, Table 1; 6(1+nu)/(7+6nu) for the solid section).

    Parameters
    ----------
    nu : float or array_like
        Poisson's ratio [-], in (-1, 0.5].
    inner_ratio : float or array_like
        Bore over outer diameter m [-], in [0, 1).

    Examples
    --------
    >>> round(float(shear_coefficient(0.3)), 4)
    0.8864
    """
    nu = check_range(nu, "nu", -1.0, 0.5, high_inclusive=True, unit="-")
    m = check_range(inner_ratio, "inner_ratio", 0.0, 1.0, low_inclusive=True, unit="-")
    nu, m = broadcast(nu=nu, inner_ratio=m)
    m2 = m**2
    return 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)


@dataclass(frozen=True)
class Shaft:
    r"""A straight stepped shaft along x (frozen).

    Parameters
    ----------
    sections : sequence of (length, outer_diameter, inner_diameter)
        Cylindrical sections from x = 0 [m, m, m]; inner diameter 0 for a solid section.
    material : Material
        Shaft material (E, nu, density) [Pa, -, kg/m^3].
    n_elements : int, optional
        Fewest beam elements over the whole length [-]; the mesh also has a node at every
        section step, seat and load (default 40).
    thermal_expansion : float, optional
        Linear thermal expansion coefficient alpha of the shaft [1/K] (used only with a
        shaft temperature change, see :func:`solve`).

    Examples
    --------
    >>> s = Shaft([(0.26, 45e-3, 0.0)], BEARING_STEEL)
    >>> round(s.length, 3), round(float(s.area(0.1)) * 1e6, 2)
    (0.26, 1590.43)
    """

    sections: tuple
    material: Material = BEARING_STEEL
    n_elements: int = 40
    thermal_expansion: float = 0.0

    def __post_init__(self) -> None:
        check_instance(self.material, "material", Material)
        secs = []
        try:
            if isinstance(self.sections, (str, bytes)):
                raise TypeError
            items = list(self.sections)
        except TypeError:
            raise TypeError("sections must be a sequence of (length, outer_diameter, "
                            f"inner_diameter) [m]; got {self.sections!r}") from None
        if not items:
            raise ValueError("sections must hold at least one (length, outer_diameter, "
                             "inner_diameter) [m]; got none")
        for k, s in enumerate(items):
            if len(s) != 3:
                raise ValueError(f"sections[{k}] must be (length, outer_diameter, "
                                 f"inner_diameter) [m]; got {s!r}")
            L = float(check_positive(s[0], f"sections[{k}] length", "m", bounded=True))
            D = float(check_positive(s[1], f"sections[{k}] outer_diameter", "m", bounded=True))
            d = float(check_nonnegative(s[2], f"sections[{k}] inner_diameter", "m",
                                        bounded=True, tiny_ok=True))
            if not d < D:
                raise ValueError(f"sections[{k}] inner_diameter must be < outer_diameter = "
                                 f"{D!r} m; got {d!r}")
            secs.append((L, D, d))
        object.__setattr__(self, "sections", tuple(secs))
        object.__setattr__(self, "n_elements", _count(self.n_elements, "n_elements"))
        a = float(check_nonnegative(self.thermal_expansion, "thermal_expansion", "1/K",
                                    bounded=True, tiny_ok=True))
        object.__setattr__(self, "thermal_expansion", a)

    @property
    def length(self) -> float:
        """Total length [m]."""
        return float(sum(s[0] for s in self.sections))

    @property
    def steps(self) -> np.ndarray:
        """x of the section ends, from 0 to the length [m]."""
        return np.concatenate([[0.0], np.cumsum([s[0] for s in self.sections])])

    def _section(self, x):
        """Index of the section at x (the right one at a step)."""
        st = self.steps
        return np.clip(np.searchsorted(st, np.asarray(x, float), side="right") - 1,
                       0, len(self.sections) - 1)

    def diameters(self, x):
        """(outer, inner) diameter at x [m] (the section to the right of a step)."""
        i = self._section(x)
        D = np.array([s[1] for s in self.sections])[i]
        d = np.array([s[2] for s in self.sections])[i]
        return D, d

    def area(self, x):
        """Cross-section area at x [m^2]."""
        D, d = self.diameters(x)
        return np.pi / 4 * (D**2 - d**2)

    def second_moment(self, x):
        """Second moment of area I = pi (D^4 - d^4)/64 at x [m^4]."""
        D, d = self.diameters(x)
        return np.pi / 64 * (D**4 - d**4)

    @property
    def mass(self) -> float:
        """Mass [kg]."""
        return float(sum(L * np.pi / 4 * (D**2 - d**2) for L, D, d in self.sections)
                     * self.material.density)


# =========================================================================== seats
def _housing(k, name):
    """5x5 housing stiffness from None (rigid), a 5-vector (diagonal) or a 5x5 matrix."""
    if k is None:
        return None
    K = as_array(k, name, allow_inf=False)
    if K.shape == (5,):
        K = np.diag(K)
    if K.shape != (5, 5):
        raise ValueError(f"{name} must be a 5-vector (diagonal) or a 5x5 matrix "
                         f"[N/m, N/rad, N m/m, N m/rad]; got shape {K.shape}")
    if np.any(np.diag(K) < 0):
        raise ValueError(f"{name} must have a non-negative diagonal; got {np.diag(K)}")
    return 0.5 * (K + K.T)


@dataclass(frozen=True)
class Seat:
    r"""A bearing seat on the shaft (frozen).

    Parameters
    ----------
    position : float
        x of the bearing centre on the shaft [m].
    bearing : BallBearing, DuplexPair or SeatBearing
        The bearing: a single-row ball bearing (any free contact angle), a duplex
        pair (DB/DF/DT; its preload is kept: each row starts at the preload deflection
        delta_0 of :attr:`DuplexPair.preload_deflection`), or any object implementing
        :class:`~ballrace.analytic.contract.SeatBearing`.
    direction : {+1, -1}
        Which way the bearing (for a pair: its bearing 1) takes thrust in the shaft
        frame: +1 when the shaft moving towards +x loads its free-contact-angle side,
        -1 when mounted the other way round (see the module notes).
    housing_stiffness : array_like, optional
        Housing (outer-ring support) stiffness, a 5-vector (diagonal) or a 5x5 matrix in
        the shaft frame [N/m, N/rad, N m/m, N m/rad]; default rigid.
    floating : bool
        The outer ring slides axially in the housing (a non-locating seat): the seat
        carries no axial load (except a ``spring_preload``).
    offset : float
        Rigid (position) preload: the inner ring is mounted this far [m] beyond the
        just-touching position, in the bearing's thrust direction (negative: end play).
    spring_preload : float
        Spring (constant force) preload [N], >= 0: a spring pushes the floating outer
        ring so that the bearing carries this thrust in its thrust direction.  Needs
        ``floating=True``.
    clearance : float or OperatingClearance, optional
        Operating diametral clearance P_d of a single bearing [m] (negative: preload),
        or the :class:`~ballrace.analytic.clearance.OperatingClearance` of the seat's
        fits and ring temperatures (:func:`~ballrace.analytic.clearance.operating_clearance`);
        default the bearing's.  The free contact angle follows from it
        (cos beta_f = 1 - P_d / 2A).
    row_spacing : float
        Axial distance between the two rows of a duplex pair [m] (default 0: both rows
        at the seat position, as in :class:`DuplexPair`).  Rows follow the pair's
        arrangement: in DB (O) bearing 1 sits on the side it does not push towards.
    name : str
        Label for tables.
    """

    position: float
    bearing: object
    direction: int = 1
    housing_stiffness: object = None
    floating: bool = False
    offset: float = 0.0
    spring_preload: float = 0.0
    clearance: float | None = None
    row_spacing: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        lacks = contract.missing(self.bearing)
        if lacks:
            raise TypeError("bearing must be a ballrace.BallBearing or a DuplexPair (or "
                            "implement ballrace.analytic.contract.SeatBearing); got "
                            f"{type(self.bearing).__name__}, which lacks {', '.join(lacks)}")
        set_(self, "position", _scalar(self.position, "position", "m"))
        if isinstance(self.direction, (bool, np.bool_)) or self.direction not in (1, -1):
            raise ValueError(f"direction must be +1 or -1; got {self.direction!r}")
        set_(self, "direction", int(self.direction))
        set_(self, "housing_stiffness", _housing(self.housing_stiffness, "housing_stiffness"))
        set_(self, "offset", _scalar(self.offset, "offset", "m"))
        set_(self, "spring_preload", float(check_nonnegative(self.spring_preload,
                                                             "spring_preload", "N",
                                                             bounded=True, tiny_ok=True)))
        if self.spring_preload > 0 and not self.floating:
            raise ValueError("spring_preload needs floating=True (the spring pushes the "
                             "axially free outer ring)")
        if self.clearance is not None:
            if isinstance(self.clearance, OperatingClearance):
                set_(self, "clearance", self.clearance.operating)
            if not self.bearing.accepts_clearance:
                raise ValueError("clearance is for a single bearing; a "
                                 f"{type(self.bearing).__name__}'s rows keep their own "
                                 "preload")
            set_(self, "clearance", _scalar(self.clearance, "clearance", "m"))
        set_(self, "row_spacing", float(check_nonnegative(self.row_spacing, "row_spacing",
                                                          "m", bounded=True, tiny_ok=True)))
        set_(self, "floating", bool(self.floating))
        mounts = tuple(self.bearing.seat_rows(self.direction, self.offset, self.row_spacing,
                                              self.clearance))
        for m in mounts:
            lacks = contract.missing(m.row, contract.ROW_MEMBERS)
            if lacks:
                raise TypeError(f"the rows of a {type(self.bearing).__name__} must implement "
                                "ballrace.analytic.contract.Row; a "
                                f"{type(m.row).__name__} lacks {', '.join(lacks)}")
        set_(self, "_mounts", mounts)

    @property
    def mounts(self) -> tuple:
        """The bearing's rows as mounted here
        (:class:`~ballrace.analytic.contract.RowMount`)."""
        return self._mounts

    @property
    def ball_bearing(self):
        """The single-row ball bearing of the rows (of each row for a pair); None for a
        bearing whose rows are not ball rows (a roller bearing's)."""
        from .bearing import BallBearing
        b = getattr(self._mounts[0].row, "bearing", None)
        return b if isinstance(b, BallBearing) else None

    def rows(self):
        """[(direction, axial offset of the row from the seat [m], mounted offset [m])]."""
        return [(m.direction, m.axial_offset, m.mounted_offset) for m in self._mounts]

    @property
    def constant_axial(self) -> float:
        """Constant axial load of a spring in the seat, in the shaft frame [N].

        The seat's reaction gains ``-direction * P`` for a DT pair's spring preload P
        (DuplexPair: Fa = 2 F(delta) - P); see
        :meth:`~ballrace.analytic.contract.SeatBearing.spring_axial_load`."""
        return float(self.bearing.spring_axial_load(self.direction))


# =========================================================================== loads
@dataclass(frozen=True)
class PointLoad:
    """A concentrated load on the shaft at x, in the shaft frame (frozen).

    Parameters
    ----------
    position : float
        x [m].
    Fa, Fy, Fz : float
        Axial and lateral forces [N].
    My, Mz : float
        Moments about y and z [N m] (right-handed).
    name : str
        Label.
    """

    position: float
    Fa: float = 0.0
    Fy: float = 0.0
    Fz: float = 0.0
    My: float = 0.0
    Mz: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        for k, unit in (("position", "m"), ("Fa", "N"), ("Fy", "N"), ("Fz", "N"),
                        ("My", "N m"), ("Mz", "N m")):
            object.__setattr__(self, k, _scalar(getattr(self, k), k, unit))

    @property
    def vector(self) -> np.ndarray:
        """(Fa, Fy, Fz, My, Mz) [N, N m]."""
        return np.array([self.Fa, self.Fy, self.Fz, self.My, self.Mz])


def gear_mesh(position, tangential_force, pitch_diameter, *, pressure_angle=np.radians(20.0),
              helix_angle=0.0, mesh_azimuth=0.0, name="gear") -> PointLoad:
    r"""The mesh force of a spur or helical gear on the shaft, as a point load at x.

    The mating gear touches at the pitch point p = r (0, cos phi, sin phi), r = d/2,
    phi = ``mesh_azimuth`` from +y towards +z.  With e_t = (0, -sin phi, cos phi) and
    e_r = (0, cos phi, sin phi) the force on this gear is

    .. math::
        \mathbf F = F_t\,\mathbf e_t - F_r\,\mathbf e_r + F_a\,\mathbf e_x,\qquad
        F_r = |F_t|\frac{\tan\alpha_n}{\cos\beta},\qquad F_a = F_t\tan\beta

    (normal pressure angle alpha_n, helix angle beta; the helical-gear force components
    of e.g. Shigley's *Mechanical Engineering Design*, ch. 13), acting at p; moved to the
    shaft axis it adds the moment of the axial force, M = p x F_a e_x:
    M_y = r sin(phi) F_a, M_z = -r cos(phi) F_a (the torque about x is not modelled).

    Parameters
    ----------
    position : float
        x of the gear's mid-plane [m].
    tangential_force : float
        F_t [N], signed along e_t (towards increasing azimuth at the pitch point).
    pitch_diameter : float
        d [m].
    pressure_angle : float
        Normal pressure angle alpha_n [rad] (default 20 deg).
    helix_angle : float
        Helix angle beta [rad], signed: the axial force on this gear is F_t tan(beta)
        (choose the sign from the hand of the helix and the direction of rotation).
    mesh_azimuth : float
        Azimuth phi of the pitch point [rad] from +y towards +z.
    name : str
        Label.

    Examples
    --------
    >>> p = gear_mesh(0.1, 1000.0, 0.2, helix_angle=np.radians(15))
    >>> round(p.Fy, 1), round(p.Fz, 1), round(p.Fa, 1), round(p.Mz, 2)
    (-376.8, 1000.0, 267.9, -26.79)
    """
    Ft = _scalar(tangential_force, "tangential_force", "N")
    r = 0.5 * float(check_positive(pitch_diameter, "pitch_diameter", "m", bounded=True))
    an = float(as_array(pressure_angle, "pressure_angle"))
    b = float(as_array(helix_angle, "helix_angle"))
    if not 0.0 <= an < 0.5 * np.pi:
        raise ValueError(f"pressure_angle must be in [0, pi/2) rad; got {an!r}")
    if not abs(b) < 0.5 * np.pi:
        raise ValueError(f"helix_angle must be in (-pi/2, pi/2) rad; got {b!r}")
    phi = float(as_array(mesh_azimuth, "mesh_azimuth"))
    Fr = abs(Ft) * np.tan(an) / np.cos(b)
    Fa = Ft * np.tan(b)
    c, s = np.cos(phi), np.sin(phi)
    Fy = -Ft * s - Fr * c
    Fz = Ft * c - Fr * s
    return PointLoad(position, Fa=Fa, Fy=Fy, Fz=Fz, My=r * s * Fa, Mz=-r * c * Fa, name=name)


def belt_pull(position, force, azimuth=0.0, name="belt") -> PointLoad:
    r"""The resultant pull of a belt or chain on its pulley, as a lateral point load [N].

    F = force (0, cos phi, sin phi): the sum of both strands' tensions (e.g.
    F = (F_1 + F_2) for parallel strands), pointing from the shaft towards the driven
    pulley at azimuth phi from +y towards +z.

    Parameters
    ----------
    position : float
        x of the pulley [m].
    force : float
        Magnitude of the resultant pull [N], >= 0.
    azimuth : float
        Direction phi of the pull [rad].
    name : str
        Label.

    Examples
    --------
    >>> p = belt_pull(0.0, 800.0, np.pi / 2)
    >>> round(p.Fy, 9), p.Fz
    (0.0, 800.0)
    """
    F = float(check_nonnegative(force, "force", "N", bounded=True, tiny_ok=True))
    phi = float(as_array(azimuth, "azimuth"))
    return PointLoad(position, Fy=F * np.cos(phi), Fz=F * np.sin(phi), name=name)


# =========================================================================== beam element
def _elements(L, E, G, A, I, kappa):
    """Timoshenko element stiffnesses (n, 10, 10), DOFs (u, v, w, theta_y, theta_z) at both
    nodes, for arrays of element length L, area A, second moment I, shear coefficient.

    Przemieniecki (1968), beam element with shear deformation, with
    Phi = 12 E I / (kappa G A L^2); bending in x–z
    uses theta_y = -dw/dx (the coupling terms change sign)."""
    L, A, I, kappa = (np.atleast_1d(np.asarray(v, float)) for v in (L, A, I, kappa))
    phi = 12 * E * I / (kappa * G * A * L * L)
    c = E * I / ((1 + phi) * L**3)
    z = np.zeros_like(L)
    kb = c[:, None, None] * np.stack([
        np.stack([12 + z, 6 * L, -12 + z, 6 * L], -1),
        np.stack([6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L], -1),
        np.stack([-12 + z, -6 * L, 12 + z, -6 * L], -1),
        np.stack([6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L], -1)], -2)
    K = np.zeros(L.shape + (10, 10))
    ka = E * A / L
    K[:, 0, 0] = K[:, 5, 5] = ka
    K[:, 0, 5] = K[:, 5, 0] = -ka
    iv = np.array([1, 4, 6, 9])           # v1, theta_z1, v2, theta_z2
    K[:, iv[:, None], iv[None, :]] = kb
    sgn = np.array([1, -1, 1, -1])        # (w, -theta_y) behaves as (v, theta_z)
    iw = np.array([2, 3, 7, 8])
    K[:, iw[:, None], iw[None, :]] = kb * np.outer(sgn, sgn)
    return K


def _element(L, E, G, A, I, kappa):
    """One 10x10 Timoshenko element stiffness (see :func:`_elements`)."""
    return _elements(L, E, G, A, I, kappa)[0]


def _shape(xi, L, phi):
    """Timoshenko shape functions (Friedman & Kosmatka 1993) for (v1, t1, v2, t2):
    deflection N (..., 4) and section rotation M (..., 4) at xi in [0, 1]."""
    xi = np.asarray(xi, float)
    f = 1.0 / (1.0 + phi)
    N = np.stack([f * (2 * xi**3 - 3 * xi**2 - phi * xi + 1 + phi),
                  f * L * (xi**3 - (2 + phi / 2) * xi**2 + (1 + phi / 2) * xi),
                  f * (-2 * xi**3 + 3 * xi**2 + phi * xi),
                  f * L * (xi**3 - (1 - phi / 2) * xi**2 - (phi / 2) * xi)], -1)
    M = np.stack([f * 6 / L * (xi**2 - xi),
                  f * (3 * xi**2 - (4 + phi) * xi + 1 + phi),
                  -f * 6 / L * (xi**2 - xi),
                  f * (3 * xi**2 - (2 - phi) * xi)], -1)
    return N, M


# =========================================================================== bearing forces
def _ring_forces(bearing, clearance, u, balls: bool = False):
    """(F, K, delta_max, energy[, ball loads]) of a single-row ball bearing at imposed
    inner-ring displacements u (N, 5) [m, rad], in its own frame:
    :meth:`loaddist.RingModel.ring_forces` (kept for callers that hold a bearing and a
    clearance [m] rather than a row)."""
    row = loaddist.RingModel(bearing, clearance)
    out = row.ring_forces(u)
    return out + (row.element_loads(np.asarray(u, float).reshape(-1, 5)),) if balls else out


# =========================================================================== result
@dataclass(frozen=True)
class ShaftResult:
    r"""Equilibrium of a shaft on its bearings (frozen).

    Attributes
    ----------
    shaft : Shaft
        The shaft.
    seats : tuple of Seat
        The seats.
    loads : tuple of PointLoad
        The applied point loads (the gear and belt helpers give PointLoads), plus the
        weight as ``gravity``.
    nodes : ndarray, shape (n,)
        Node positions x [m].
    node_displacements : ndarray, shape (n, 5)
        (u, v, w [m], theta_y, theta_z [rad]) at the nodes.
    reactions : ndarray, shape (n_seats, 5)
        (Fa, Fy, Fz [N], My, Mz [N m]) each seat carries, in the shaft frame (see the
        module notes; sum(reactions) = sum(loads) with moments carried).
    ring_displacements : ndarray, shape (n_seats, 5)
        Inner ring relative to outer ring at the seat, in the shaft frame [m, rad].
    housing_displacements : ndarray, shape (n_seats, 5)
        Outer-ring displacements (housing compliance, thermal growth, floating) [m, rad].
    seat_stiffness : ndarray, shape (n_seats, 5, 5)
        Linearised stiffness dReaction/d(inner relative to outer) of each seat at the
        operating point, in the shaft frame [N/m, N/rad, N m/m, N m/rad].
    iterations : int
        Newton iterations (summed over load steps).
    residual : float
        Relative equilibrium residual of the global system [-].
    gravity : ndarray, shape (3,)
        Acceleration applied to the shaft mass (x, y, z) [m/s^2].
    """

    shaft: Shaft
    seats: tuple
    loads: tuple
    nodes: np.ndarray
    node_displacements: np.ndarray
    reactions: np.ndarray
    ring_displacements: np.ndarray
    housing_displacements: np.ndarray
    seat_stiffness: np.ndarray
    iterations: int
    residual: float
    gravity: np.ndarray
    _phi: np.ndarray = field(repr=False, default=None)
    _weight: np.ndarray = field(repr=False, default=None)
    _rows: tuple = field(repr=False, default=())
    _X: np.ndarray = field(repr=False, default=None)
    _pb: object = field(repr=False, default=None, compare=False)

    @functools.cached_property
    def bearings(self) -> tuple:
        """Per seat: the :class:`~ballrace.analytic.loaddist.LoadDistribution` of a single
        bearing (in the bearing's own frame: for ``direction=-1`` loads and displacements
        are those of the shaft frame mapped by :data:`MIRROR`), or a tuple of two
        (bearing 1, bearing 2) for a duplex pair; ball loads, contact angles, Hertz
        contacts, subsurface shear and truncation as for a single bearing.  Built on
        first access by loaddist's own checked solver with every DOF imposed.  For any
        other seat bearing: its rows' :meth:`~ballrace.analytic.contract.Row.result`."""
        from . import _operating

        out = []
        with _operating.quiet():            # solve() has said what needs saying
            for k in range(len(self.seats)):
                ld = [row.result(ul) for kk, row, ul in self._rows if kk == k]
                out.append(ld[0] if len(ld) == 1 else tuple(ld))
        return tuple(out)

    def _seat_rows(self, k) -> tuple:
        b = self.bearings[k]
        return b if isinstance(b, tuple) else (b,)

    @property
    def max_pressure(self) -> np.ndarray:
        """Largest contact pressure p_max of each seat (all its rows, both races) [Pa],
        (n_seats,)."""
        return np.array([max(float(np.max(ld.max_pressure)) for ld in self._seat_rows(k))
                         for k in range(len(self.seats))])

    @property
    def static_safety(self) -> np.ndarray:
        r"""Static safety of each seat's most loaded contact [-], (n_seats,): the smallest
        ``static_safety`` of its rows' results.

        From the actual largest contact pressure at the seat -- radial and axial load,
        moment, tilt, clearance and preload included: s0 = (4200 MPa / p_max)^3 for ball
        rows (:func:`~ballrace.analytic.ratings.static_safety_from_pressure`; ISO 76:2006
        bases C0 on 4200 MPa), (4000 MPa / p_max)^2 of the most loaded slice for roller
        rows; inf for an unloaded seat.  :func:`solve` warns when it is below 1.
        """
        return np.array([min(float(np.min(ld.static_safety)) for ld in self._seat_rows(k))
                         for k in range(len(self.seats))])

    @property
    def relative_residual(self) -> float:
        """Relative equilibrium residual of the global system [-] (the number ``residual``
        holds; ``relative_residual`` is its name on every result)."""
        return float(self.residual)

    def stiffness(self, x) -> np.ndarray:
        r"""Linearised 5x5 stiffness of the whole shaft on its bearings at a node [N/m, N/rad,
        N m/m, N m/rad].

        The inverse of the compliance at the node nearest x: the response (u, v, w,
        theta_y, theta_z) of the node to small loads (Fa, Fy, Fz, My, Mz) there, with the
        beam, every bearing at its tangent stiffness at the operating point (preload and
        loads included) and the housing springs in the path.

        Parameters
        ----------
        x : float
            Position [m]; the nearest node is used (``nodes`` lists them: a seat or a load
            is always a node).
        """
        x = float(as_array(x, "x"))
        pb = self._pb
        i = pb.node(x)
        _, J, _, _, _ = pb.evaluate(self._X)
        n, nb = pb.n, pb.nb
        Cm = np.zeros((5, 5))
        for j in range(5):
            f = np.zeros(n)
            f[5 * i + j] = 1.0
            fi = f[pb.iidx]
            rhs = np.zeros(pb.N)
            rhs[:nb] = f[pb.bidx] - (pb.Zb.T @ fi if fi.size else 0.0)
            dY = np.linalg.solve(J, rhs)
            U = np.zeros(n)
            U[pb.bidx] = dY[:nb]
            if fi.size:
                U[pb.iidx] = cho_solve_banded((pb.chol, False), fi) - pb.Zb @ dY[:nb]
            Cm[:, j] = U[5 * i:5 * i + 5]
        return np.linalg.inv(Cm)

    @property
    def misalignment(self) -> np.ndarray:
        """Tilt of each bearing's inner ring relative to its outer ring [rad], (n_seats,)."""
        return np.hypot(self.ring_displacements[:, 3], self.ring_displacements[:, 4])

    @property
    def weight(self) -> np.ndarray:
        """Resultant of the shaft's weight (Fa, Fy, Fz, My, Mz about x = 0) [N, N m]."""
        return self._weight

    def displacement(self, x):
        """Shaft axis displacement (u, v, w [m], theta_y, theta_z [rad]) at x, (..., 5).

        Interpolated within the element holding x with the Timoshenko shape functions
        (exact for a prismatic element loaded at its nodes); theta_y, theta_z are the
        rotations of the cross-section.

        Parameters
        ----------
        x : float or array_like
            Position(s) along the shaft [m], in [0, length].
        """
        x = as_array(x, "x")
        L = self.shaft.length
        if np.any((x < -1e-12 * L) | (x > L * (1 + 1e-12))):
            raise ValueError(f"x must be within the shaft [0, {L!r}] m; got {x!r}")
        xs = x.ravel()
        nd = self.nodes
        e = np.clip(np.searchsorted(nd, xs, side="right") - 1, 0, nd.size - 2)
        Le = nd[e + 1] - nd[e]
        xi = np.clip((xs - nd[e]) / Le, 0.0, 1.0)
        N, M = _shape(xi[:, None], Le[:, None], self._phi[e][:, None])
        N, M = N[:, 0], M[:, 0]
        U1, U2 = self.node_displacements[e], self.node_displacements[e + 1]
        out = np.empty((xs.size, 5))
        out[:, 0] = (1 - xi) * U1[:, 0] + xi * U2[:, 0]
        qv = np.stack([U1[:, 1], U1[:, 4], U2[:, 1], U2[:, 4]], -1)
        qw = np.stack([U1[:, 2], -U1[:, 3], U2[:, 2], -U2[:, 3]], -1)
        out[:, 1] = (N * qv).sum(-1)
        out[:, 4] = (M * qv).sum(-1)
        out[:, 2] = (N * qw).sum(-1)
        out[:, 3] = -(M * qw).sum(-1)
        return out.reshape(x.shape + (5,))

    def equilibrium_residual(self, point=0.0) -> np.ndarray:
        """sum(loads) + weight - sum(reactions), moments about x = point [N, N m] (5,).

        Zero to solver tolerance: what the shaft receives from the loads, it gives to the
        seats.  A force (Fa, Fy, Fz) at x has the moment (My, Mz) += (-(x - point) Fz,
        (x - point) Fy) about (point, 0, 0).
        """
        def moved(F, x):
            F = np.array(F, float)
            F[3] += -(x - point) * F[2]
            F[4] += (x - point) * F[1]
            return F
        tot = sum((moved(p.vector, p.position) for p in self.loads), np.zeros(5))
        tot = tot + moved(self._weight, 0.0) if self._weight is not None else tot
        for s, R in zip(self.seats, self.reactions):
            tot = tot - moved(R, s.position)
        return tot


# =========================================================================== assembly
class _Problem:
    """Mesh, stiffness, seats and loads of one solve (internal)."""

    def __init__(self, shaft, seats, loads, gravity, shaft_dT, housing_dT, housing_expansion,
                 reference):
        self.shaft, self.seats, self.loads = shaft, seats, loads
        L = shaft.length
        # key points, seats first: a point closer than dmin to an earlier one joins it (a
        # load is then moved there rigidly, with the moment of the shift; statics exact)
        dmin = 1e-6 * L
        key = []
        for x in [s.position for s in seats] + [0.0, L] + list(shaft.steps) + \
                [p.position for p in loads]:
            x = min(max(float(x), 0.0), L)
            if not key or min(abs(x - k) for k in key) >= dmin:
                key.append(x)
        key = np.array(sorted(key))
        tol = 0.5 * dmin
        h = L / shaft.n_elements
        nodes = [key[0]]
        for a, b in zip(key[:-1], key[1:]):
            if b - a < 0.5 * tol:
                continue
            n = max(1, int(math.ceil((b - a) / h - 1e-9)))
            nodes.extend(a + (b - a) * np.arange(1, n + 1) / n)
        self.nodes = nd = np.array(nodes)
        nd[-1] = L
        ne = nd.size - 1
        self.n = n = nd.size * 5
        mat = shaft.material
        E, nu = mat.E, mat.nu
        G = E / (2 * (1 + nu))
        xm = 0.5 * (nd[:-1] + nd[1:])
        Do, Di = shaft.diameters(xm)
        A = np.pi / 4 * (Do**2 - Di**2)
        I = np.pi / 64 * (Do**4 - Di**4)
        kap = shear_coefficient(nu, Di / Do)
        Le = np.diff(nd)
        self.phi = 12 * E * I / (kap * G * A * Le**2)
        K = np.zeros((n, n))
        f = np.zeros(n)
        g = np.zeros(3) if gravity is None else np.asarray(gravity, float)
        rho = mat.density
        weight = np.zeros(5)
        eps_th = shaft.thermal_expansion * shaft_dT
        Ke = _elements(Le, E, G, A, I, kap)
        for e in range(ne):
            K[5 * e:5 * e + 10, 5 * e:5 * e + 10] += Ke[e]
        if eps_th:
            # thermal strain: the free expansion eps L is an initial strain (axial forces
            # -EA eps at node 1, +EA eps at node 2)
            np.add.at(f, 5 * np.arange(ne), -E * A * eps_th)
            np.add.at(f, 5 * np.arange(ne) + 5, E * A * eps_th)
        if np.any(g):
            q = (rho * A * Le)[:, None] * g[None, :]         # (ne, 3) element weight
            fe = np.zeros((ne, 10))
            fe[:, [0, 5]] = 0.5 * q[:, :1]
            fe[:, [1, 6]] = 0.5 * q[:, 1:2]
            fe[:, [2, 7]] = 0.5 * q[:, 2:3]
            fe[:, 4], fe[:, 9] = q[:, 1] * Le / 12, -q[:, 1] * Le / 12   # theta_z (v-plane)
            fe[:, 3], fe[:, 8] = -q[:, 2] * Le / 12, q[:, 2] * Le / 12   # theta_y = -dw/dx
            for e in range(ne):
                f[5 * e:5 * e + 10] += fe[e]
            weight[:3] = q.sum(0)
            weight[3] = -(xm * q[:, 2]).sum()
            weight[4] = (xm * q[:, 1]).sum()
        self.weight = weight
        self.Ks = K
        self.f_base = f                   # weight and thermal strain
        self.f_loads = self._load_vector(loads)
        self.seat_node = [self.node(s.position) for s in seats]
        ns = len(seats)
        # static condensation of the linear shaft onto the seat nodes: the interior DOFs
        # follow U_i = K_ii^-1 (f_i - K_ib U_b) (banded Cholesky, K_ii is positive
        # definite once the seat nodes are held)
        bidx = np.concatenate([np.arange(5 * i, 5 * i + 5) for i in self.seat_node])
        mask = np.ones(n, bool)
        mask[bidx] = False
        iidx = np.flatnonzero(mask)
        self.bidx, self.iidx = bidx, iidx
        Kbb = K[np.ix_(bidx, bidx)]
        if iidx.size:
            Kii = K[np.ix_(iidx, iidx)]
            Kib = K[np.ix_(iidx, bidx)]
            bw = min(9, iidx.size - 1)          # within two nodes of 5 DOFs
            ab = np.zeros((bw + 1, iidx.size))
            for d in range(bw + 1):
                ab[bw - d, d:] = np.diagonal(Kii, d)
            ch = cholesky_banded(ab, lower=False)
            self.chol = ch
            self.Kib = Kib
            self.Zb = cho_solve_banded((ch, False), Kib)
            self.Kc = Kbb - Kib.T @ self.Zb
        else:
            self.chol = None
            self.Kib = np.zeros((0, bidx.size))
            self.Zb = np.zeros((0, bidx.size))
            self.Kc = Kbb
        self._condense_loads()
        self.Kc = 0.5 * (self.Kc + self.Kc.T)
        self.nb = nb = 5 * ns
        # outer-ring DOFs after the seat DOFs: the free ones of each seat
        self.outer = []            # per seat: (indices into 5, reduced indices, Kh block)
        self.w0 = np.zeros((ns, 5))       # imposed outer-ring displacement (thermal)
        self.spring = np.zeros((ns, 5))   # spring force on the outer ring
        nxt = nb
        for k, s in enumerate(seats):
            self.w0[k, 0] = housing_expansion * housing_dT * (s.position - reference)
            self.spring[k, 0] = -s.direction * s.spring_preload
            loc, Kh = _outer_dofs(s)
            gl = list(range(nxt, nxt + len(loc)))
            nxt += len(loc)
            self.outer.append((np.array(loc, int), np.array(gl, int), Kh))
        self.N = nxt
        # rows: (seat k, contract Row, G (5x5 map shaft rel. -> local), mounted offset,
        # centred start)
        self.rows = []
        for k, s in enumerate(seats):
            for m in s.mounts:
                a = m.axial_offset
                P = np.eye(5)
                P[1, 4], P[2, 3] = a, -a            # rigid ring: row at x + a
                T = np.ones(5) if m.direction > 0 else MIRROR
                self.rows.append((k, m.row, T[:, None] * P, m.mounted_offset, m.centred))
        self.rk = np.array([r[0] for r in self.rows], int)
        self.Gr = np.array([r[2] for r in self.rows])
        self.roff = np.array([r[3] for r in self.rows])
        grp = {}                                    # equal rows: one call for all of them
        for i, r in enumerate(self.rows):
            grp.setdefault(r[1], (r[1], []))[1].append(i)
        self.groups = [(row, np.array(v)) for row, v in grp.values()]
        self.dmax = np.zeros(len(self.rows))
        self.fmax = np.zeros(len(self.rows))      # largest row force (preloaded pairs)
        self.const = np.zeros((ns, 5))
        for k, s in enumerate(seats):
            self.const[k, 0] = s.constant_axial
        self.A_ref = min(r[1].step_length for r in self.rows)
        self.moment_radius = max(r[1].moment_radius for r in self.rows)

    def node(self, x):
        return int(np.argmin(np.abs(self.nodes - x)))

    def _load_vector(self, loads):
        """Nodal load vector: weight, thermal strain and the point loads (a load off its
        node moved there with the moment of the shift)."""
        f = self.f_base.copy()
        for p in loads:
            i = self.node(p.position)
            F = p.vector
            d = p.position - self.nodes[i]
            F[3] += -d * F[2]
            F[4] += d * F[1]
            f[5 * i:5 * i + 5] += F
        return f

    def _condense_loads(self):
        fi = self.f_loads[self.iidx]
        self.zf = cho_solve_banded((self.chol, False), fi) if fi.size else np.zeros(0)
        self.fc = self.f_loads[self.bidx] - (self.Kib.T @ self.zf if fi.size else 0.0)

    def with_loads(self, loads):
        """The same mesh, seats and condensation with other loads at the same positions."""
        new = copy.copy(self)
        new.loads = loads
        new.f_loads = self._load_vector(loads)
        new._condense_loads()
        new.dmax = np.zeros_like(self.dmax)
        new.fmax = np.zeros_like(self.fmax)
        return new

    def seat_rel(self, Y):
        """Inner minus outer ring displacement at every seat (n_seats, 5), outer (.., 5)."""
        W = self.w0.copy()
        for k, (loc, gl, _) in enumerate(self.outer):
            W[k, loc] += Y[gl]
        return Y[:self.nb].reshape(-1, 5) - W, W

    def full(self, Y, lam=1.0):
        """All shaft node displacements (n_nodes, 5) from the reduced unknowns."""
        U = np.zeros(self.n)
        U[self.bidx] = Y[:self.nb]
        U[self.iidx] = lam * self.zf - self.Zb @ Y[:self.nb]
        return U.reshape(-1, 5)

    def rigid_modes(self):
        """The shaft's five rigid-body motions at the seat nodes, (N, 5): axial, the two
        lateral translations, rotation about z (v = theta_z x) and about y (w = -theta_y x),
        zero on the outer-ring DOFs; the condensed stiffness maps them to zero."""
        T = np.zeros((self.N, 5))
        for k, i in enumerate(self.seat_node):
            x, o = float(self.nodes[i]), 5 * k
            T[o, 0] = T[o + 1, 1] = T[o + 2, 2] = 1.0
            T[o + 1, 3], T[o + 4, 3] = x, 1.0
            T[o + 2, 4], T[o + 3, 4] = -x, 1.0
        return T

    def evaluate(self, Y, lam=1.0, want_J=True, Yd=None):
        """Residual (N,), Jacobian (N, N), seat reactions (n_seats, 5), seat K, max approach.

        ``Yd``: Y less a rigid-body motion of the shaft (the same residual in exact
        arithmetic), from which the shaft's elastic forces are taken: they are then not
        lost in the round-off of a rigid displacement much larger than the deformation."""
        rel, _ = self.seat_rel(Y)
        ns = len(self.seats)
        Rs = self.const.copy()
        Ks = np.zeros((ns, 5, 5))
        ul = np.einsum("rij,rj->ri", self.Gr, rel[self.rk])
        ul[:, 0] += self.roff
        energy = 0.0
        for row, idx in self.groups:
            F, J, dm, en = row.ring_forces(ul[idx])
            energy += float(en.sum())
            self.fmax[idx] = np.abs(F[:, :3]).max(1)
            for j, r in enumerate(idx):
                Gm = self.Gr[r]
                Rs[self.rk[r]] += Gm.T @ F[j]
                Ks[self.rk[r]] += Gm.T @ J[j] @ Gm
            self.dmax[idx] = dm
        dmax = self.dmax
        nb = self.nb
        R = np.empty(self.N)
        Ye = Y[:nb] if Yd is None else Yd[:nb]
        Kb = self.Kc @ Ye
        R[:nb] = Kb - lam * self.fc + Rs.ravel()
        # total potential (the residual is its gradient): shaft, loads, bearings, springs
        pot = 0.5 * float(Ye @ Kb) - lam * float(self.fc @ Y[:nb]) + energy + \
            float((self.const * rel).sum())
        for k, (loc, gl, Kh) in enumerate(self.outer):
            if loc.size:
                # outer ring: the housing spring and a preload spring balance the balls
                R[gl] = Kh @ Y[gl] - Rs[k, loc] - self.spring[k, loc]
                pot += 0.5 * float(Y[gl] @ Kh @ Y[gl]) - float(self.spring[k, loc] @ Y[gl])
        self.potential = pot
        if not want_J:
            return R, None, Rs, Ks, dmax
        Jm = np.zeros((self.N, self.N))
        Jm[:nb, :nb] = self.Kc
        for k in range(ns):
            s5 = slice(5 * k, 5 * k + 5)
            Jm[s5, s5] += Ks[k]
            loc, gl, Kh = self.outer[k]
            if loc.size:
                Jm[s5, gl] -= Ks[k][:, loc]
                Jm[np.ix_(gl, np.arange(5 * k, 5 * k + 5))] -= Ks[k][loc, :]
                Jm[np.ix_(gl, gl)] += Kh + Ks[k][np.ix_(loc, loc)]
        return R, Jm, Rs, Ks, dmax


#: The last few problems (mesh, stiffness, condensation) by shaft, seats and load positions:
#: a duty cycle or sweep with loads at fixed places reuses them.
_PROBLEMS: dict = {}


def _sequence(value, name, what) -> tuple:
    """A tuple of the items of a sequence (TypeError naming ``name`` for anything else)."""
    try:
        if isinstance(value, (str, bytes)):
            raise TypeError
        return tuple(value)
    except TypeError:
        raise TypeError(f"{name} must be a sequence of {what}; got "
                        f"{type(value).__name__} {value!r}"[:120]) from None


def _check_setup(shaft, seats, loads):
    L = shaft.length
    if not seats:
        raise ValueError("seats must hold at least one Seat: a shaft without bearings has "
                         "free rigid-body modes (all five)")
    for k, s in enumerate(seats):
        check_instance(s, f"seats[{k}]", Seat)
        if not -1e-12 * L <= s.position <= L * (1 + 1e-12):
            raise ValueError(f"seats[{k}].position must be within the shaft [0, {L!r}] m; "
                             f"got {s.position!r}")
    pos = sorted(s.position for s in seats)
    for a, b in zip(pos[:-1], pos[1:]):
        if b - a < 1e-6 * L:
            raise ValueError(f"two seats at the same position x = {a!r} m; a pair of "
                             "bearings at one place is a DuplexPair seat")
    for k, p in enumerate(loads):
        check_instance(p, f"loads[{k}]", PointLoad)
        if not -1e-12 * L <= p.position <= L * (1 + 1e-12):
            raise ValueError(f"loads[{k}].position must be within the shaft [0, {L!r}] m; "
                             f"got {p.position!r}")
    # rigid-body modes of the shaft on its supports: a seat restrains what both its
    # bearing (all five DOFs once loaded) and its housing restrain (rigid, or a spring
    # with a non-zero diagonal; a floating seat never axially); the rigid shaft's motion
    # (u0, v0, w0, theta_y, theta_z) about x = 0 moves a seat at x by
    # (u0, v0 + theta_z x, w0 - theta_y x, theta_y, theta_z)
    if not any(not s.floating and s.bearing.carries_axial and
               (s.housing_stiffness is None or s.housing_stiffness[0, 0] > 0) for s in seats):
        raise ValueError("the shaft has no axial support: every seat is floating, has no "
                         "axial housing stiffness or a bearing that carries no axial load "
                         "(give one locating seat, floating=False) "
                         f"-- free rigid-body mode: {DOF_NAMES[0]}")
    Kr = np.zeros((5, 5))
    for s in seats:
        held = np.ones(5) if s.housing_stiffness is None else \
            (np.diag(s.housing_stiffness) > 0).astype(float)
        if s.floating or not s.bearing.carries_axial:
            held[0] = 0.0
        T = np.eye(5)
        T[1, 4], T[2, 3] = s.position, -s.position
        Kr += T.T @ (held[:, None] * T)
    w, V = np.linalg.eigh(Kr)
    if w[0] <= 1e-12 * max(w[-1], 1.0):
        mode = V[:, 0] * np.array([1, 1, 1, L, L])
        names = [DOF_NAMES[i] for i in np.flatnonzero(np.abs(mode) > 0.1 * np.abs(mode).max())]
        raise ValueError("the seats leave the shaft a free rigid-body mode: "
                         f"{' with '.join(names)} (housing stiffness zero or seats floating)")


# =========================================================================== solve
def solve(shaft: Shaft, seats, loads=(), *, gravity=None, shaft_temperature_change=0.0,
          housing_temperature_change=0.0, housing_expansion=0.0, thermal_reference=None,
          rtol: float = 1e-10, max_iter: int = 100, initial=None) -> ShaftResult:
    r"""Equilibrium of an elastic shaft on its ball bearings under point loads.

    Finds the shaft node displacements U and free outer-ring displacements W with

    .. math::
        \mathbf K_s \mathbf U + \sum_{\rm seats} \mathbf B_k^T\,
        \mathbf F_k\!\left(\mathbf B_k\mathbf U - \mathbf W_k\right) = \mathbf f,
        \qquad \mathbf K_{h,k}\mathbf W_k = \mathbf F_k

    where K_s is the Timoshenko beam stiffness, f the loads (and weight and thermal
    strain), and F_k the exact nonlinear ball-force resultant of seat k (loaddist model,
    each row mapped to its own frame; see the module notes), by Newton's method with the
    analytic bearing tangent stiffness, a Levenberg floor for unloaded directions
    (clearance), a trust radius of a quarter of the groove-centre distance A on every
    bearing's relative displacement, a backtracking (Armijo) line search on the total
    potential -- beam, loads, springs and the bearings' contact energies, whose gradient
    is the residual -- or on the scaled residual norm, and load stepping (quarters of the
    load, then finer) when the full load fails.  Where that fails, or where its result
    does not balance once the shaft's rigid-body motion is taken out of its elastic
    forces (the condensed stiffness maps a rigid motion to zero only to ~1e-13 of its
    size, ~1e-8 N for a shaft moved 0.1 mm through its clearance), a robust iteration
    keeps that motion apart from the deformation, scales the Levenberg floor with the
    loads' geometric stiffness F/A, and starts with the balls of every single-row seat at
    the bottom of their grooves: a lateral load of a few mN down to 1e-6 N on deep-groove
    seats with clearance then balances to rtol.  Below that the ConvergenceError names the
    round-off limit.

    Parameters
    ----------
    shaft : Shaft
        The shaft.
    seats : sequence of Seat
        Bearing seats (at distinct positions).
    loads : sequence of PointLoad
        Loads on the shaft (see :func:`gear_mesh`, :func:`belt_pull`).
    gravity : array_like, optional
        Acceleration (g_x, g_y, g_z) on the shaft's own mass [m/s^2], e.g.
        ``(0, -STANDARD_GRAVITY, 0)``; default no weight.
    shaft_temperature_change : float
        Uniform temperature change of the shaft from assembly [K] (uses
        ``shaft.thermal_expansion``).
    housing_temperature_change : float
        Uniform temperature change of the housing [K].
    housing_expansion : float
        Thermal expansion coefficient of the housing [1/K]: it moves the seats' outer
        rings axially by alpha_h dT_h (x - x_ref).
    thermal_reference : float, optional
        x_ref of the housing's thermal growth [m] (default the first locating seat);
        irrelevant unless two seats locate axially.
    rtol : float
        Equilibrium tolerance: largest residual force (moments over the largest bearing
        pitch radius) relative to the largest applied or reaction load [-], in (0, 1).
    max_iter : int
        Newton iterations per load step (and 10 max_iter over all load steps).
    initial : ShaftResult, optional
        A solution of the same shaft and seats to start from (a neighbouring load case
        of a sweep or duty cycle); ignored if it does not fit.

    Returns
    -------
    ShaftResult

    Raises
    ------
    ValueError
        For bad input (named), a shaft without axial support or with a free rigid-body
        mode (named), loads beyond the bearings' load–deflection range.
    ConvergenceError
        If equilibrium is not reached (residual and iterations in the message).

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53,
    ...                            diametral_clearance=10e-6)
    >>> s = Shaft([(0.26, 45e-3, 0.0)], ballrace.BEARING_STEEL)
    >>> r = solve(s, [Seat(0.03, brg), Seat(0.23, brg)], [PointLoad(0.09, Fy=5000.0)])
    >>> np.round(r.reactions[:, 1]).tolist()          # 5000 N (140/200, 60/200)
    [3500.0, 1500.0]
    """
    check_instance(shaft, "shaft", Shaft)
    seats = _sequence(seats, "seats", "Seat")
    loads = _sequence(loads, "loads", "PointLoad")
    _check_setup(shaft, seats, loads)
    dTs = _scalar(shaft_temperature_change, "shaft_temperature_change", "K")
    dTh = _scalar(housing_temperature_change, "housing_temperature_change", "K")
    ah = float(check_nonnegative(housing_expansion, "housing_expansion", "1/K", bounded=True,
                                 tiny_ok=True))
    rtol = float(check_range(rtol, "rtol", 0.0, 1.0, unit="-"))
    max_iter = _count(max_iter, "max_iter")
    if dTs and shaft.thermal_expansion == 0.0:
        raise ValueError("shaft_temperature_change needs shaft.thermal_expansion [1/K] > 0")
    _thermal_checks(seats, dTs, dTh, ah)
    if thermal_reference is None:
        loc = [s.position for s in seats if not s.floating]
        thermal_reference = loc[0] if loc else seats[0].position
    ref = _scalar(thermal_reference, "thermal_reference", "m")
    if gravity is not None:
        gravity = as_array(gravity, "gravity", bounded=True, tiny_ok=True, unit="m/s^2")
        if gravity.shape != (3,):
            raise ValueError(f"gravity must be (g_x, g_y, g_z) [m/s^2]; got shape "
                             f"{gravity.shape}")
    key = (id(shaft), tuple(map(id, seats)), tuple(p.position for p in loads),
           None if gravity is None else tuple(gravity), dTs, dTh, ah, ref)
    hit = _PROBLEMS.get(key)
    if hit is not None and hit[0] is shaft and all(a is b for a, b in zip(hit[1], seats)):
        pb = hit[2].with_loads(loads)
    else:
        pb = _Problem(shaft, seats, loads, gravity, dTs, dTh, ah, ref)
        if len(_PROBLEMS) >= 8:
            _PROBLEMS.pop(next(iter(_PROBLEMS)))
        _PROBLEMS[key] = (shaft, seats, pb)
    X0 = None
    if initial is not None:
        check_instance(initial, "initial", ShaftResult)
        X0 = initial._X
    X, its, res = _newton(pb, rtol, max_iter, X0)
    R, _, Rs, Ks, dmax = pb.evaluate(X, want_J=False)
    for (k, row, _, _, _), d in zip(pb.rows, dmax):
        lim = row.approach_limit
        if d > lim:
            raise ValueError(
                f"the loads are beyond the load-deflection range of the bearing at seat {k} "
                f"(x = {seats[k].position:g} m): a rolling-element approach reaches {d:.3g} m "
                f"> {lim:.3g} m (the row's approach_limit: {loaddist.MAX_APPROACH_RATIO:g} D "
                "for balls)")
    rel, W = pb.seat_rel(X)
    rows = []
    for k, row, Gm, off, _ in pb.rows:
        ul = Gm @ rel[k]
        ul[0] += off
        rows.append((k, row, ul))
    U = pb.full(X)
    return _checked(ShaftResult(shaft=shaft, seats=seats, loads=loads, nodes=pb.nodes,
                                node_displacements=U, reactions=Rs,
                                ring_displacements=rel, housing_displacements=W,
                                seat_stiffness=Ks, iterations=its, residual=res,
                                gravity=np.zeros(3) if gravity is None else gravity,
                                _phi=pb.phi, _weight=pb.weight, _rows=tuple(rows), _X=X,
                                _pb=pb))


#: A uniform temperature change from assembly [K] beyond which :func:`solve` asks whether
#: the value is meant: service temperatures of steel shafts in rolling bearings stay
#: within about 150 K of assembly (bearing steels are dimensionally stabilised for
#: 120-200 degC).
TEMPERATURE_CHANGE_WARN = 150.0


def _thermal_checks(seats, dTs, dTh, ah) -> None:
    """UserWarnings for temperature changes that do nothing (one axial location) or that
    are implausibly large."""
    from . import _operating

    for name, dT in (("shaft_temperature_change", dTs), ("housing_temperature_change", dTh)):
        if abs(dT) > TEMPERATURE_CHANGE_WARN:
            _operating.warn(f"{name} = {dT:g} K: a uniform temperature change of more than "
                            f"{TEMPERATURE_CHANGE_WARN:g} K from assembly is unusual for a "
                            "bearing shaft and its housing - check the value (a temperature "
                            "given where a change is meant?)")
    n_loc = sum(not s.floating for s in seats)
    if n_loc <= 1:
        for name, dT, active in (("shaft_temperature_change", dTs, dTs != 0.0),
                                 ("housing_temperature_change", dTh, dTh != 0.0 and ah != 0.0)):
            if active:
                _operating.warn(
                    f"{name} = {dT:g} K has no effect: "
                    + ("only one seat locates" if n_loc else "no seat locates")
                    + " the shaft axially (the others float), so the thermal growth of shaft "
                    "and housing is free and changes no load; it matters with two or more "
                    "locating seats (e.g. an O or X arrangement of two angular-contact seats)")


def _checked(r: ShaftResult) -> ShaftResult:
    """``r``, after UserWarnings for each seat working beyond its limits: static safety
    s0 < 1, a deep-groove bearing beyond
    :data:`~ballrace.analytic.ratings.DEEP_GROOVE_ANGLE_LIMIT`, a tilt beyond
    :data:`~ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT`."""
    from . import _operating as op

    if op.silenced():
        return r
    try:
        r.bearings
    except (ValueError, ConvergenceError) as exc:         # pragma: no cover - defensive
        log.debug("shaft: seat checks skipped (%s)", exc)
        return r
    tilt = r.misalignment
    for k, s in enumerate(r.seats):
        what = (f"shaft seats[{k}]" + (f" '{s.name}'" if s.name else "")
                + f" (x = {s.position * 1e3:g} mm)")
        op.emit(*s.bearing.seat_warnings(what, r._seat_rows(k), tilt[k]))
    return r


def _scales(pb):
    """Residual scale per reduced DOF: forces 1, moments / R (largest inner-groove radius)."""
    R = pb.moment_radius
    sc = np.ones(pb.N)
    sc[3:pb.nb:5] = R
    sc[4:pb.nb:5] = R
    for loc, gl, _ in pb.outer:
        sc[gl] = np.where(loc >= 3, R, 1.0)
    return sc, R


def _newton(pb, rtol, max_iter, X0=None):
    """Global Newton with load stepping; returns (X, iterations, relative residual)."""
    sc, _ = _scales(pb)
    Fext = max([float(np.abs(p.vector).max()) for p in pb.loads]
               + [float(np.abs(pb.f_base).max()), 0.0])
    if 0.0 < Fext < 1e-290:
        # the residual's scale has a floor of 1e-300 N: such loads would "converge" at the
        # unloaded position without being carried
        raise ConvergenceError(
            f"shaft equilibrium: the loads (largest {Fext:.3g} N) are below what the solver "
            "resolves (the residual's scale has a floor of 1e-300 N); apply 0 or a load of "
            "physical size")
    total = 0

    def checked(X, err):
        """(X, err) if the plain iteration's result balances once the shaft's elastic
        forces are taken without its rigid-body motion, else a robust polish from X (or
        None).  The condensed stiffness maps a rigid motion to zero only to ~1e-13 of its
        size: a shaft moved ~0.1 mm through its clearance feels spurious forces of
        ~1e-8 N, which hide the imbalance of a load of a few mN."""
        if _split_error(pb, X, sc) <= POLICY.floor_rtol * rtol:
            return X, err
        nonlocal total
        Xr, it, er, okr = _newton_step(pb, X, 1.0, sc, rtol, max_iter, robust=True)
        total += it
        return (Xr, er) if okr else None

    if X0 is not None and X0.shape == (pb.N,):
        X, it, err, ok = _newton_step(pb, X0.copy(), 1.0, sc, rtol, max_iter)
        total += it
        if ok:
            good = checked(X, err)
            if good is not None:
                return good[0], total, good[1]
    fracs = [1.0]
    last_err = None
    for attempt in range(4):
        X = np.zeros(pb.N)
        ok = True
        for lam in fracs:
            # an overall budget of 10 max_iter keeps a hopeless case from running long
            budget = min(max_iter, 10 * max_iter - total)
            if budget <= 0:
                ok = False
                break
            X, it, err, ok = _newton_step(pb, X, lam, sc, rtol, budget)
            total += it
            last_err = err
            if not ok:
                break
        if ok:
            good = checked(X, err)
            if good is not None:
                return good[0], total, good[1]
            break
        n = 4 ** (attempt + 1)
        fracs = list(np.arange(1, n + 1) / n)
        log.debug("shaft: Newton failed (residual %.2e); load stepping in %d steps", err, n)
    # Retry (only here, so that what converged above is untouched): the robust iteration
    # of _newton_step, first from the start with every single-row seat's balls at the
    # bottom of their grooves (a deep-groove bearing's axial position under a light
    # radial load, -A sin(beta_f) from the one-sided reference, which the plain iteration
    # crawls towards in steps of ~sqrt(A delta)), then from the reference position.
    rnd, umax = 0.0, 0.0
    for X0 in (_centred_start(pb), np.zeros(pb.N)):
        X, it, err, ok = _newton_step(pb, X0, 1.0, sc, rtol, max_iter, robust=True)
        total += it
        if ok:
            log.debug("shaft: converged by the robust retry (residual %.2e)", err)
            return X, total, err
        last_err = min(last_err, err) if last_err is not None else err
        r_, u_ = _roundoff(pb, X)
        rnd, umax = max(rnd, r_), max(umax, u_)
    raise newton.convergence_error(
        "shaft equilibrium", total, last_err, rtol, newton=True, steps=" over all load steps",
        roundoff=rnd,
        roundoff_hint=f"the loads, {_load_scale(pb):.3g} N, are too small to be resolved "
                      f"against the shaft's stiffness and the rings' displacement of "
                      f"{umax:.3g} m through their clearance")


def _split_error(pb, X, sc):
    """Relative residual at X (load factor 1) with the shaft's elastic forces taken from X
    less its rigid-body motion (the same in exact arithmetic; see _Problem.evaluate)."""
    nb = pb.nb
    T = pb.rigid_modes()[:nb]
    Xd = X.copy()
    Xd[:nb] -= T @ (np.linalg.pinv(T) @ X[:nb])
    R, _, Rs, _, _ = pb.evaluate(X, 1.0, want_J=False, Yd=Xd)
    s5 = sc[:5]
    scf = np.ones(pb.n)
    scf[3::5] = scf[4::5] = s5[3]
    ext = max([np.abs(p.vector / s5).max() for p in pb.loads]
              + [np.abs(pb.f_base / scf).max()])
    scale = max(ext, np.abs(Rs / sc[:5]).max(), pb.fmax.max(), 1e-300)
    return float(np.abs(R / sc).max() / scale)


def _load_scale(pb):
    """Largest applied force [N] (else the largest row force)."""
    F = max([float(np.abs(p.vector[:3]).max()) for p in pb.loads] + [1e-300])
    return F if F > 1e-300 else max(float(pb.fmax.max()), 1e-300)


def _roundoff(pb, X):
    """(relative residual below which round-off hides equilibrium at X, largest relative
    ring translation [m]).  The shaft's rigid displacement u (e.g. through a clearance) is
    resolved to ~eps |u|, so its elastic forces only to ~eps |K| |u| against its
    stiffness K, and a ball's approach s - A to ~eps |u| (Q ~ delta^1.5,
    :func:`ballrace.analytic.newton.roundoff_limit`)."""
    eps = np.finfo(float).eps
    rel, _ = pb.seat_rel(X)
    umax = float(np.abs(rel[:, :3]).max())
    dm = float(np.max(pb.dmax)) if pb.dmax.size else 0.0
    rnd = max(eps * float(np.abs(pb.Kc).max()) * float(np.abs(X[:pb.nb]).max())
              / _load_scale(pb), newton.roundoff_limit(umax, dm) if dm > 0 else 0.0)
    return rnd, umax


def _centred_start(pb):
    """Start with the balls of every single-row seat at the bottom of their grooves: the
    shaft's axial position and each floating seat's outer ring chosen (least squares) so
    that each such row's axial displacement is -z0 of its reference
    (:attr:`~ballrace.analytic.contract.Row.reference_axial_offset`); rows not marked
    ``centred`` (duplex rows) keep their mounted position."""
    X = np.zeros(pb.N)
    cols = {("a",): 0}
    for k, (loc, gl, _) in enumerate(pb.outer):
        if pb.seats[k].floating and 0 in loc:
            cols[("b", k)] = len(cols)
    A = np.zeros((len(pb.rows), len(cols)))
    rhs = np.zeros(len(pb.rows))
    for i, (k, row, G, off, centred) in enumerate(pb.rows):
        g = G[0, 0]
        A[i, 0] = g
        if ("b", k) in cols:
            A[i, cols[("b", k)]] = -g
        target = off
        if centred:
            target = -row.reference_axial_offset
        rhs[i] = target - off + g * pb.w0[k, 0]
    sol = np.linalg.lstsq(A, rhs, rcond=None)[0]
    X[0:pb.nb:5] = sol[0]
    for (tag, *k), j in cols.items():
        if tag == "b":
            loc, gl, _ = pb.outer[k[0]]
            X[gl[list(loc).index(0)]] = sol[j]
    return X


def _newton_step(pb, X, lam, sc, rtol, max_iter, robust=False):
    """Newton iterations at load factor lam from X; returns (X, its, err, converged).

    ``robust`` (the retry after the plain iteration failed): the unknowns are kept as a
    rigid-body motion of the shaft plus the rest (the shaft's elastic forces from the
    rest only, see :meth:`_Problem.evaluate`), and the Levenberg term scales with the
    geometric stiffness of the loads, 1e-6 F/A, instead of 1e-10 of the largest stiffness
    (which, against a shaft of 1e9 N/m, swamps the ~F/A stiffness of balls at the bottom
    of their grooves under a load of a few mN and makes Newton crawl)."""
    dlim = newton.trust_radius(pb.A_ref)
    nb = pb.nb
    if robust:
        T = pb.rigid_modes()[:nb]
        Tp = np.linalg.pinv(T)
        r = Tp @ X[:nb]
        Xd = X.copy()
        Xd[:nb] -= T @ r
        X = Xd.copy()
        X[:nb] += T @ r
    else:
        Xd = None
    R, J, Rs, _, _ = pb.evaluate(X, lam, Yd=Xd)
    # scale of the applied loads: point loads, weight and the thermal strain's nodal
    # forces (self-equilibrated, but the residual's round-off scales with them; without
    # them a shaft free in its end play, loaded by nothing else, has no scale at all)
    s5 = sc[:5]
    scf = np.ones(pb.n)
    scf[3::5] = scf[4::5] = s5[3]
    ext = lam * max([np.abs(p.vector / s5).max() for p in pb.loads]
                    + [np.abs(pb.f_base / scf).max()])

    def error(R, Rs):
        scale = max(ext, np.abs(Rs / sc[:5]).max(), pb.fmax.max(), 1e-300)
        return np.abs(R / sc).max() / scale

    err = error(R, Rs)
    it = 0
    Rmax = pb.moment_radius
    # unknown scaling: tilts in units of 1/R, so rotations weigh like translations
    D = np.ones(pb.N)
    D[3:pb.nb:5] = 1.0 / Rmax
    D[4:pb.nb:5] = 1.0 / Rmax
    for loc, gl, _ in pb.outer:
        D[gl] = np.where(loc >= 3, 1.0 / Rmax, 1.0)
    while not err <= rtol:
        if it >= max_iter:
            return X, it, err, False
        it += 1
        Jd = (J * D[None, :]) / sc[:, None]
        if robust:
            mu = max(POLICY.levenberg_shaft_robust * np.abs(np.diag(Jd)).max(),
                     POLICY.levenberg_geometric * ext / pb.A_ref)
        else:
            mu = POLICY.levenberg_shaft * np.abs(np.diag(Jd)).max()
        Jd[np.diag_indices_from(Jd)] += mu
        try:
            dY = -np.linalg.solve(Jd, R / sc)
        except np.linalg.LinAlgError:
            dY = -np.linalg.lstsq(Jd, R / sc, rcond=None)[0]
        dX = dY * D
        # trust radius on every bearing's relative displacement (tilts times R)
        rel_step = dX[:pb.nb].reshape(-1, 5).copy()
        for k, (loc, gl, _) in enumerate(pb.outer):
            rel_step[k, loc] -= dX[gl]
        size = max(np.abs(rel_step[:, :3]).max(), np.abs(rel_step[:, 3:]).max() * Rmax)
        if not np.all(np.isfinite(dX)):
            return X, it, err, False
        g = float(R @ dX)
        if not g < 0.0:
            # not a descent direction of the potential: the symmetric part, then the
            # scaled gradient
            Jsym = 0.5 * (Jd * sc[:, None] / D[None, :] + (Jd * sc[:, None] / D[None, :]).T)
            try:
                dX = -np.linalg.solve(Jsym, R)
            except np.linalg.LinAlgError:
                dX = -R / np.maximum(np.abs(np.diag(Jsym)), 1e-300)
            if not float(R @ dX) < 0.0:
                dX = -R / np.maximum(np.abs(np.diag(Jsym)), 1e-300)
            rel_step = dX[:pb.nb].reshape(-1, 5).copy()
            for k, (loc, gl, _) in enumerate(pb.outer):
                rel_step[k, loc] -= dX[gl]
            size = max(np.abs(rel_step[:, :3]).max(), np.abs(rel_step[:, 3:]).max() * Rmax)
            g = float(R @ dX)
        f = newton.clip_factor(size, dlim)
        if f != 1.0:
            dX *= f
            g *= f
        if robust:
            dr = Tp @ dX[:nb]
            dXd = dX.copy()
            dXd[:nb] -= T @ dr
        # Armijo on the total potential (the residual is its gradient; bearing energies
        # with K_n at each ball's angle), which falls through a clearance gap where the
        # residual stays flat and rises on an overshoot into a contact; or on the scaled
        # residual norm, which the potential's round-off cannot judge near the solution.
        p0 = pb.potential
        m0 = float(np.sum((R / sc) ** 2))

        def accept(t):
            nonlocal rn, Xdn, Xn, Rn, Jn, Rsn
            if robust:
                rn, Xdn = r + t * dr, Xd + t * dXd
                Xn = Xdn.copy()
                Xn[:nb] += T @ rn
            else:
                Xn, Xdn = X + t * dX, None
            Rn, Jn, Rsn, _, _ = pb.evaluate(Xn, lam, Yd=Xdn)
            return newton.armijo_ok(pb.potential, p0, t, g) or \
                float(np.sum((Rn / sc) ** 2)) <= (1 - POLICY.armijo * t) * m0

        rn = Xdn = Xn = Rn = Jn = Rsn = None
        newton.backtrack_one(accept, POLICY.shaft_halvings)
        en = error(Rn, Rsn)
        if newton.stalled(en, err) and err < POLICY.near_tolerance * rtol:
            # no more progress near the tolerance: the round-off floor of the sums
            best = min(en, err)
            if en < err:
                X, err = Xn, en
            return X, it, best, best <= POLICY.floor_rtol * rtol
        X, R, J, Rs, err = Xn, Rn, Jn, Rsn, en
        if robust:
            r, Xd = rn, Xdn
    return X, it, err, True


# =========================================================================== life
@dataclass(frozen=True)
class ShaftLife:
    r"""Fatigue lives of the seats and of the bearing system (frozen).

    Attributes
    ----------
    seat_lives : ndarray, shape (n_seats,)
        Life of each seat [1e6 rev] (a duplex pair: its two rows combined as a system).
    row_lives : tuple
        Per seat: the lives of its rows [1e6 rev] (one or two).
    ratings : tuple
        Per seat: the :class:`~ballrace.analytic.iso16281.ReferenceRatingLife` of each
        row (one or two).
    system : float
        System life over all rows [1e6 rev]: L_sys = (sum L_i^-e)^(-1/e) with a common
        slope, else the L with sum (L/L_i)^e_i = 1 (:func:`system_life`).
    weibull_slope : float
        e [-] common to all seats (10/9 for ball bearings, Lundberg & Palmgren 1947; 9/8
        for roller bearings, Lundberg & Palmgren 1952); ``nan`` when the seats' slopes
        differ (see ``seat_weibull_slopes``).
    kind : str
        ``"L10r"`` (ISO/TS 16281 basic reference rating life) or ``"Lnmr"`` (modified,
        a1 a_ISO L10r, ISO 281:2007 §9.3 via ISO/TS 16281 §5.3).
    seat_weibull_slopes : tuple
        e of each seat [-] (its rows combine with it; the system with all of them).
    catalog_lives : tuple
        Per seat: the ISO 281:2007 catalogue life from the seat's reaction, (C/P)^p with
        the bearing's equivalent load P = X F_r + Y F_a and life exponent p (3 ball, 10/3
        roller bearings), or L_nm = a1 a_ISO (C/P)^p with ``modified`` [1e6 rev]; ``None`` for a duplex pair (its rows share the thrust in a
        way the catalogue formula does not know) or where the X/Y tables do not apply.
    """

    seat_lives: np.ndarray
    row_lives: tuple
    ratings: tuple
    system: float
    weibull_slope: float
    kind: str
    catalog_lives: tuple = ()
    seat_weibull_slopes: tuple = ()

    def hours(self, speed_rpm):
        """(seat lives (n_seats,), system life) in hours at ``speed_rpm`` [rev/min] [h]."""
        n = float(check_positive(speed_rpm, "speed_rpm", "rev/min"))
        f = 1e6 / (60.0 * n)
        return self.seat_lives * f, self.system * f


def system_life(lives, weibull_slope=None):
    r"""Life of a system of bearings that fails with its first bearing [same unit].

    .. math:: L_{sys} = \Big(\sum_i L_i^{-e}\Big)^{-1/e}

    the weakest-link rule of Weibull-distributed lives with a common slope e
    (Lundberg & Palmgren 1947; e = 10/9 for ball bearings, 9/8 for roller bearings:
    Lundberg & Palmgren 1952, and ISO 281:2007's reliability factor a1 uses the same two
    slopes).

    Bearings with different slopes (ball and roller seats on one shaft): each bearing
    survives to L with probability S_i(L) = 0.9^((L/L_i)^e_i), the system with their
    product, so the system's L10 is the L with

    .. math:: \sum_i (L/L_i)^{e_i} = 1,

    solved here for L (the sum grows monotonically with L; safeguarded Newton in ln L to
    round-off).  For a common slope it is the formula above.

    Parameters
    ----------
    lives : array_like
        L10 of each bearing [1e6 rev or h], > 0 (``inf`` for an unloaded one).
    weibull_slope : float or array_like, optional
        e [-], one for all or one per bearing; default
        :data:`ballrace.analytic.life.BALL_WEIBULL_SLOPE` = 10/9.

    Examples
    --------
    >>> round(float(system_life([1000.0, 1000.0])), 1)     # 2^(-9/10) L
    535.9
    >>> round(float(system_life([1000.0, 1000.0], [10 / 9, 9 / 8])), 1)   # a ball, a roller
    538.0
    """
    from .life import BALL_WEIBULL_SLOPE
    L = check_positive(lives, "lives", "", allow_inf=True)
    e = np.asarray(BALL_WEIBULL_SLOPE if weibull_slope is None else
                   check_positive(weibull_slope, "weibull_slope", "-"), float)
    if e.ndim and e.shape != L.shape:
        raise ValueError(f"weibull_slope must be one number or one per life {L.shape}; got "
                         f"shape {e.shape}")
    e = np.broadcast_to(e, L.shape)
    fin = np.isfinite(L)
    L, e = L[fin], e[fin]
    if not L.size:
        return np.inf
    if np.all(e == e.flat[0]):
        e0 = float(e.flat[0])
        return float(np.sum(L ** -e0)) ** (-1.0 / e0)
    lnL = np.log(L)
    hi = float(lnL.min())                        # sum >= 1 there
    lo = hi - math.log(L.size) / float(e.min()) - 1.0   # every term < 1/n there
    t = hi
    for _ in range(200):
        x = np.exp(e * (t - lnL))
        f, df = float(x.sum()) - 1.0, float((e * x).sum())
        if f > 0:
            hi = t
        else:
            lo = t
        tn = t - f / df
        if not lo < tn < hi:
            tn = 0.5 * (lo + hi)
        if abs(tn - t) <= 4e-16 * max(abs(t), 1.0) or hi - lo <= 4e-16 * max(abs(t), 1.0):
            t = tn
            break
        t = tn
    return float(math.exp(t))


def rating_lives(result: ShaftResult, *, rotating: str = "inner", dynamic_rating=None,
                 nominal_contact_angle=None, modified=None, weibull_slope=None) -> ShaftLife:
    r"""ISO/TS 16281 lives of the seats of a solved shaft and of the bearing system.

    Each row's element loads give the basic reference rating life L10r (a ball row's
    ball loads: :func:`ballrace.analytic.iso16281.reference_rating_life`; a roller row's
    slice loads: :func:`ballrace.analytic.roller.life.reference_rating_life`), or with
    ``modified`` the modified reference rating life L_nmr = a1 a_ISO L10r; the rows of a
    seat combine with its bearing's Weibull slope, and the rows of all seats into the
    system life (:func:`system_life`; ball and roller seats with their own slopes, 10/9
    and 9/8).

    Parameters
    ----------
    result : ShaftResult
        The solved shaft.
    rotating : {"inner", "outer"}
        Ring rotating relative to the load (the shaft rotates: "inner").
    dynamic_rating : float or sequence, optional
        C of each seat's bearing [N]; default the ISO 281 rating of the geometry.
    nominal_contact_angle : float or sequence, optional
        alpha of the rating [rad] per seat; default each bearing's
        ``nominal_contact_angle``.
    modified : dict, optional
        ``kappa``, ``contamination``, ``fatigue_limit`` [-, -, N] and optionally
        ``reliability`` and ``ep_additives`` for L_nmr (ISO 281:2007 §9.3).
    weibull_slope : float, optional
        e of the system life [-], for every seat; default each seat bearing's own
        (``weibull_slope`` of the bearing: 10/9 for ball bearings, 9/8 for roller
        bearings; :func:`system_life` combines different slopes exactly).

    Returns
    -------
    ShaftLife
    """
    check_instance(result, "result", ShaftResult)
    check_choice(rotating, "rotating", ("inner", "outer"))
    es = _slopes(result.seats, weibull_slope)
    ns = len(result.seats)
    C = _per_seat(dynamic_rating, "dynamic_rating", ns)
    alpha = _per_seat(nominal_contact_angle, "nominal_contact_angle", ns)
    rows, ratings, seat, cat = [], [], [], []
    for k, s in enumerate(result.seats):
        # the rows' lives from their element loads (without building result.bearings)
        rr = [row.rating_life(ul, dynamic_rating=C[k], rotating=rotating,
                              nominal_contact_angle=alpha[k])
              for kk, row, ul in result._rows if kk == k]
        Ls = [float(r.modified(**modified)) if modified else float(r.L10r) for r in rr]
        cat.append(_catalog_life(s, result.reactions[k], rr[0].C, alpha[k], modified))
        ratings.append(tuple(rr))
        rows.append(tuple(Ls))
        seat.append(system_life(Ls, es[k]))
    allrows = [x for r in rows for x in r]
    slopes = [es[k] for k, r in enumerate(rows) for _ in r]
    common = es[0] if all(x == es[0] for x in es) else math.nan
    return ShaftLife(seat_lives=np.array(seat), row_lives=tuple(rows), ratings=tuple(ratings),
                     system=float(system_life(allrows, slopes)), weibull_slope=common,
                     kind="Lnmr" if modified else "L10r", catalog_lives=tuple(cat),
                     seat_weibull_slopes=tuple(es))


def _slopes(seats, weibull_slope) -> list:
    """The Weibull slope e [-] of each seat: ``weibull_slope`` for all if given, else each
    seat bearing's ``weibull_slope`` (10/9, that of ball bearings, where it has none)."""
    from .life import BALL_WEIBULL_SLOPE

    if weibull_slope is not None:
        return [float(check_positive(weibull_slope, "weibull_slope", "-"))] * len(seats)
    return [float(getattr(s.bearing, "weibull_slope", BALL_WEIBULL_SLOPE)) for s in seats]


def life(result: ShaftResult, **kwargs) -> ShaftLife:
    """Deprecated name of :func:`rating_lives` (same arguments, same result; it also
    hid the :mod:`ballrace.analytic.life` module's name)."""
    from ._renames import warn_renamed
    warn_renamed("ballrace.analytic.shaft.life", "ballrace.analytic.shaft.rating_lives")
    return rating_lives(result, **kwargs)


def _per_seat(v, name, ns):
    """None, one number or one per seat (None: that seat's default) -> a list of ns.

    TypeError for text, booleans and nested lists; the values are checked where used."""
    if v is None:
        return [None] * ns
    if isinstance(v, (list, tuple)) and any(x is None for x in v):
        if len(v) != ns:
            raise ValueError(f"{name} must be a number or one per seat ({ns}); got {len(v)}")
        out = []
        for k, x in enumerate(v):
            a = None if x is None else as_array(x, f"{name}[{k}]", allow_inf=True)
            if a is not None and a.ndim:
                raise ValueError(f"{name}[{k}] must be one number; got shape {a.shape}")
            out.append(None if a is None else float(a))
        return out
    arr = as_array(v, name, allow_inf=True)
    if arr.ndim == 0:
        return [float(arr)] * ns
    if arr.ndim != 1 or arr.size != ns:
        raise ValueError(f"{name} must be a number or one per seat ({ns}); got shape "
                         f"{arr.shape}")
    return [float(x) for x in arr]


def _catalog_life(seat, R, C, alpha, modified):
    """ISO 281 (C/P)^p (or L_nm) of a seat from its reaction, with the bearing's
    equivalent load and life exponent p (contract.SeatBearing); None if n/a."""
    from .iso281 import modified_rating_life

    Fr, Fa = float(np.hypot(R[1], R[2])), float(abs(R[0]))
    P = seat.bearing.equivalent_load(Fr, Fa, alpha)
    if P is None or not P > 0:
        return None
    if modified:
        return float(modified_rating_life(C, P, **modified))
    return float((C / P) ** seat.bearing.life_exponent)


@dataclass(frozen=True)
class DutyCycleLife:
    r"""Lives under a duty cycle (frozen).

    Attributes
    ----------
    seat_hours : ndarray, shape (n_seats,)
        Palmgren–Miner life of each seat [h].
    system_hours : float
        System life from the seats' duty-cycle lives, (sum L_k^-e)^(-1/e) [h] (with
        different slopes: :func:`system_life`).
    case_hours : ndarray, shape (n_cases, n_seats)
        Life of each seat under each case alone [h].
    fractions : ndarray, shape (n_cases,)
        Time fractions [-].
    results : tuple of ShaftResult
        The solved cases.
    weibull_slope : float
        e [-] common to all seats; ``nan`` when they differ (ball and roller seats).
    seat_weibull_slopes : tuple
        e of each seat [-] (its rows combine with it).
    """

    seat_hours: np.ndarray
    system_hours: float
    case_hours: np.ndarray
    fractions: np.ndarray
    results: tuple
    weibull_slope: float
    seat_weibull_slopes: tuple = ()


def duty_cycle(shaft: Shaft, seats, cases, *, rotating: str = "inner", dynamic_rating=None,
               nominal_contact_angle=None, modified=None, weibull_slope=None,
               **solve_kwargs) -> DutyCycleLife:
    r"""Seat and system lives of a shaft under a duty cycle (Palmgren–Miner).

    Each case (loads, time fraction t_i, speed n_i) is solved; each seat's life in hours
    under it alone is L_ki = L10r,ki 1e6 / (60 n_i); the seat's duty-cycle life is
    L_k = 1 / sum_i (t_i / L_ki) (:func:`ballrace.analytic.life.miner`; Palmgren 1924,
    Miner 1945) and the system life (sum_k L_k^-e)^(-1/e).  Successive cases start from
    the previous solution.

    Parameters
    ----------
    shaft : Shaft
        The shaft.
    seats : sequence of Seat
        The seats.
    cases : sequence of (loads, fraction, speed_rpm)
        Loads (a sequence of PointLoad), time fraction [-] (summing to 1) and shaft speed
        [rev/min] of each case.
    rotating, dynamic_rating, nominal_contact_angle, modified, weibull_slope
        As for :func:`rating_lives`.
    **solve_kwargs
        Passed to :func:`solve` (gravity, temperatures, ...).

    Returns
    -------
    DutyCycleLife
    """
    from .life import miner

    cases = list(_sequence(cases, "cases", "(loads, fraction, speed_rpm)"))
    if not cases:
        raise ValueError("cases must hold at least one (loads, fraction, speed_rpm)")
    check_choice(rotating, "rotating", ("inner", "outer"))
    es = _slopes(_sequence(seats, "seats", "Seat"), weibull_slope)
    res, speeds, fr = [], [], []
    prev = None
    for i, c in enumerate(cases):
        if isinstance(c, (str, bytes)) or not hasattr(c, "__len__"):
            raise TypeError(f"cases[{i}] must be (loads, fraction, speed_rpm); got "
                            f"{type(c).__name__} {c!r}")
        try:
            loads, t, n = c
        except (TypeError, ValueError):
            raise ValueError(f"cases[{i}] must be (loads, fraction, speed_rpm); got {c!r}") \
                from None
        t = float(check_range(t, f"cases[{i}] fraction", 0.0, 1.0, low_inclusive=True,
                              high_inclusive=True, unit="-"))
        speeds.append(float(check_positive(n, f"cases[{i}] speed_rpm", "rev/min",
                                           bounded=True)))
        r = solve(shaft, seats, loads, initial=prev, **solve_kwargs)
        fr.append(t)
        res.append(r)
        prev = r
    # the lives of every row over all cases at once (the same rules as rating_lives())
    ns = len(res[0].seats)
    C = _per_seat(dynamic_rating, "dynamic_rating", ns)
    A = _per_seat(nominal_contact_angle, "nominal_contact_angle", ns)
    seat_L = np.zeros((len(res), ns))
    for i, (k, row, _) in enumerate(res[0]._rows):
        U = np.array([r._rows[i][2] for r in res])
        rr = row.rating_life(U, dynamic_rating=C[k], rotating=rotating,
                             nominal_contact_angle=A[k])
        L = np.asarray(rr.modified(**modified) if modified else rr.L10r, float)
        with np.errstate(divide="ignore"):
            seat_L[:, k] += np.where(np.isinf(L), 0.0, L ** -es[k])
    e = np.array(es)
    with np.errstate(divide="ignore"):
        Lk = np.where(seat_L > 0, seat_L ** (-1.0 / e), np.inf)      # per case and seat
    H = Lk * 1e6 / (60.0 * np.array(speeds)[:, None])
    t = np.array(fr)
    seat_h = np.array([miner(H[:, k], t) for k in range(H.shape[1])])
    common = es[0] if all(x == es[0] for x in es) else math.nan
    return DutyCycleLife(seat_hours=seat_h, system_hours=float(system_life(seat_h, es)),
                         case_hours=H, fractions=t, results=tuple(res), weibull_slope=common,
                         seat_weibull_slopes=tuple(es))


# =========================================================================== rotordynamics
def _outer_dofs(seat) -> tuple[list, np.ndarray]:
    """The outer-ring DOFs of a seat that move (indices into the 5) and the housing
    stiffness on them: none in a rigid housing (only the axial one of a floating seat);
    all five in an elastic housing, the axial one then free of it when floating."""
    if seat.housing_stiffness is None:
        loc = [0] if seat.floating else []
        return loc, np.zeros((len(loc), len(loc)))
    Kh = seat.housing_stiffness.copy()
    if seat.floating:
        Kh[0, :] = 0.0
        Kh[:, 0] = 0.0
    return [0, 1, 2, 3, 4], Kh


def _seat_to_ground(K, seat) -> np.ndarray:
    """5x5 stiffness from the shaft node to the ground of one seat: the bearing's tangent
    stiffness K in series with its housing (outer-ring DOFs condensed out)."""
    loc, Kh = _outer_dofs(seat)
    if not loc:
        return K.copy()
    Koo = K[np.ix_(loc, loc)] + Kh
    # outer ring in equilibrium: (K_oo + K_h) w = K_o u; a direction in which the outer ring
    # is free and the bearing stiffness is zero carries nothing (pseudo-inverse)
    return K - K[:, loc] @ np.linalg.pinv(Koo, rcond=1e-12) @ K[loc, :]


def bearing_coefficients(result: ShaftResult, tilt: str = "held"):
    r"""Each seat's linearised stiffness in the axes of a rotordynamics code.

    ROSS puts the shaft along its z axis: (x, y, z)_ROSS = (y, z, x)_ballrace (a cyclic
    permutation, so both frames are right-handed, and ROSS's rotations alpha, beta about
    its x, y are ballrace's theta_y, theta_z).  The seat's
    stiffness from the shaft node to the ground is the bearing's 5x5 tangent stiffness
    at the operating point (``result.seat_stiffness``) in series with its housing: the
    housing springs of ``housing_stiffness``, and no axial stiffness for a floating seat
    (its outer ring slides).  Of that 5x5 K:

    * ``tilt="held"`` — the translational block as it is (the ring held square: what the
      bearing shows when the shaft prevents it from tilting);
    * ``tilt="free"`` — the translational stiffness with the bearing free to tilt, the
      Schur complement K_tt - K_tr K_rr^-1 K_rt over the two tilts (softer or equal).

    A ROSS ``BearingElement`` acts on the three translations of its node only (a 3x3
    block with kxx, kxy, kyx, kyy and kzz, no axial–lateral terms), so the bearing's tilt
    stiffness (a rotational spring, large for an axially loaded or preloaded bearing)
    is not exported; either choice drops it.  The axial–lateral coupling terms are
    returned (``kzx``, ``kzy``, ``kxz``, ``kyz``) but ROSS has no place for them.

    Parameters
    ----------
    result : ShaftResult
        The solved shaft.
    tilt : {"held", "free"}
        How the tilt DOFs are treated.

    Returns
    -------
    list of dict
        Per seat: ``x`` [m], ``node`` (index into ``result.nodes``), ``kxx``, ``kxy``,
        ``kyx``, ``kyy`` (lateral, ROSS axes), ``kzz`` (axial), ``kxz``, ``kyz``, ``kzx``,
        ``kzy`` (axial–lateral) [N/m], and ``stiffness``, the whole 5x5 seat stiffness
        to the ground in the shaft frame (u, v, w, theta_y, theta_z) [N/m, N/rad, N m/m,
        N m/rad], tilts included.

    Examples
    --------
    >>> import ballrace
    >>> brg = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53, diametral_clearance=0.0)
    >>> s = Shaft([(0.26, 45e-3, 0.0)], ballrace.BEARING_STEEL)
    >>> r = solve(s, [Seat(0.03, brg), Seat(0.23, brg)], [PointLoad(0.13, Fy=4000.0)])
    >>> c = bearing_coefficients(r)
    >>> bool(c[0]["kxx"] > c[0]["kyy"] > 0)     # stiffer along the load
    True
    """
    check_instance(result, "result", ShaftResult)
    check_choice(tilt, "tilt", ("held", "free"))
    out = []
    for k, s in enumerate(result.seats):
        K = _seat_to_ground(result.seat_stiffness[k], s)
        T = K[:3, :3]
        if tilt == "free":
            Krr = K[3:, 3:]
            # K_tr K_rr^+ K_rt: a tilt without stiffness (and so without coupling) drops out
            T = T - K[:3, 3:] @ np.linalg.pinv(Krr, rcond=1e-12) @ K[3:, :3]
        out.append(dict(x=s.position, node=int(np.argmin(np.abs(result.nodes - s.position))),
                        kxx=float(T[1, 1]), kxy=float(T[1, 2]), kyx=float(T[2, 1]),
                        kyy=float(T[2, 2]), kzz=float(T[0, 0]), kxz=float(T[1, 0]),
                        kyz=float(T[2, 0]), kzx=float(T[0, 1]), kzy=float(T[0, 2]),
                        stiffness=K))
    return out


def ross_bearings(result: ShaftResult, nodes=None, *, tilt: str = "held", damping: float = 0.0):
    """ROSS ``BearingElement`` objects of the seats (needs ``ballrace[rotor]``).

    Each element carries the seat's :func:`bearing_coefficients` at the operating point:
    kxx, kxy, kyx, kyy (lateral) and kzz (axial) [N/m], constant in speed; the tilt
    stiffness and the axial–lateral terms are not exported (a ROSS bearing acts on the
    three translations of its node only).

    Parameters
    ----------
    result : ShaftResult
        The solved shaft.
    nodes : sequence of int, optional
        The ROSS rotor node of each seat (in the ROSS model's own numbering); default
        the index of the seat's node in ``result.nodes``, right for a ROSS rotor built
        with one ``ShaftElement`` per interval of ``result.nodes``.
    tilt : {"held", "free"}
        See :func:`bearing_coefficients`.
    damping : float
        Direct damping c_xx = c_yy = c_zz [N s/m], >= 0 (a rolling bearing's is small and
        not modelled).

    Returns
    -------
    list of ross.BearingElement
        In the order of ``result.seats``, tagged with the seat names (``seat<k>`` for a
        seat without one; ``_<k>`` appended to all when two are alike).
    """
    coeffs = bearing_coefficients(result, tilt)
    if nodes is None:
        nodes = [c["node"] for c in coeffs]
    nodes = check_integer(nodes, "nodes", 0)
    if nodes.shape != (len(coeffs),):
        raise ValueError(f"nodes must give one ROSS node per seat ({len(coeffs)}); got "
                         f"shape {nodes.shape}")
    c_d = float(check_nonnegative(damping, "damping", "N s/m", bounded=True, tiny_ok=True))
    try:
        import ross
    except ImportError:
        raise ImportError("ross_bearings needs ROSS: pip install 'ballrace[rotor]' "
                          "(ross-rotordynamics)") from None
    tags = [s.name or f"seat{k}" for k, s in enumerate(result.seats)]
    if len(set(tags)) < len(tags):          # ROSS finds its elements by tag
        tags = [f"{t}_{k}" for k, t in enumerate(tags)]
    return [ross.BearingElement(n=int(n), kxx=c["kxx"], kyy=c["kyy"], kxy=c["kxy"],
                                kyx=c["kyx"], kzz=c["kzz"], cxx=c_d, cyy=c_d, czz=c_d,
                                tag=t)
            for n, c, t in zip(nodes, coeffs, tags)]
