r"""What a shaft seat needs from a bearing: the seat contract.

:func:`ballrace.analytic.shaft.solve` solves a shaft on its bearings without knowing
their type.  A :class:`~ballrace.analytic.shaft.Seat` holds any object that satisfies
:class:`SeatBearing`; the seat bearing hands the shaft its rolling-element rows
(:class:`RowMount`), each row an object that satisfies :class:`Row`.  The shaft then
only maps displacements into each row's frame, asks the row for its forces and tangent
stiffness, and sums them.  :class:`~ballrace.BallBearing` (one row) and
:class:`~ballrace.analytic.duplex.DuplexPair` (two rows) implement the contract; their
rows are :class:`~ballrace.analytic.loaddist.RingModel`.

A new bearing type becomes a seat by implementing both protocols (the members below);
nothing in :mod:`ballrace.analytic.shaft` names a bearing type.

Frame of a row: that of :mod:`ballrace.analytic.loaddist` -- x axial (positive where the
row takes thrust from the inner ring), y and z radial, right-handed tilts; the shaft maps
its displacements into it (mirror for ``direction=-1``, rigid-ring lever for a row off the
seat centre) and adds the mounted offset to the axial displacement.

Both protocols are ``typing.Protocol`` classes marked ``runtime_checkable``, so
``isinstance(obj, SeatBearing)`` checks that the members exist (not their signatures);
:func:`missing` names the ones an object lacks.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol, Sequence, runtime_checkable

import numpy as np

__all__ = ["Row", "SeatBearing", "RowMount", "ROW_MEMBERS", "SEAT_BEARING_MEMBERS", "missing"]


@runtime_checkable
class Row(Protocol):
    r"""One rolling-element row as the shaft sees it, at a fixed clearance.

    Attributes
    ----------
    reference_axial_offset : float
        Axial offset z0 [m] of the row's reference configuration (inner ring at
        u = 0): for a clearance, the just-touching position, where the elements touch
        both races without load.  At u_x = -z0 the elements sit centred (e.g. a ball at
        the bottom of both grooves); the shaft starts its iteration there.
    approach_limit : float
        Largest element approach [m] for which the row's load law holds; the shaft
        reports loads beyond it as out of range.
    step_length : float
        A length [m] over which the row's force law changes character (for a ball row the
        distance A between the groove curvature centres); the shaft's Newton steps are
        limited to a fraction of it.
    moment_radius : float
        Radius [m] by which the row's moments compare with its forces (for a ball row the
        inner-groove centre radius R_i); it scales the shaft's residual.
    """

    reference_axial_offset: float
    approach_limit: float
    step_length: float
    moment_radius: float

    def ring_forces(self, u) -> tuple:
        r"""Element-force resultant on the inner ring at imposed displacements, its
        analytic tangent and what the shaft's iteration needs.

        Parameters
        ----------
        u : ndarray, shape (N, 5)
            Inner-ring displacements (dx, dy, dz [m], theta_y, theta_z [rad]) in the row's
            frame, from the reference configuration.

        Returns
        -------
        F : ndarray, shape (N, 5)
            (Fa, Fy, Fz [N], My, Mz [N m]) the elements carry.
        K : ndarray, shape (N, 5, 5)
            dF/du [N/m, N/rad, N m/m, N m/rad], analytic (the shaft's Newton uses it as is).
        delta_max : ndarray, shape (N,)
            Largest element approach [m] (the range check, and the shaft's round-off floor:
            an approach is resolved to about eps |u| / delta_max relative).
        energy : ndarray, shape (N,)
            Elastic energy of the contacts [J], whose gradient is F (the line search's
            merit function).
        """

    def element_loads(self, u) -> np.ndarray:
        """Rolling-element loads [N], shape u.shape[:-1] + (Z,), at displacements u
        (..., 5) [m, rad]."""

    def result(self, u) -> Any:
        """The checked per-row result at displacements u (5,) [m, rad]: an object with
        ``static_safety``, ``max_pressure`` [Pa], ``loads`` [N, N m] and ``displacements``
        [m, rad] (a :class:`~ballrace.analytic.loaddist.LoadDistribution` for a ball
        row)."""

    def rating_life(self, u, *, dynamic_rating=None, rotating="inner",
                    nominal_contact_angle=None) -> Any:
        """The row's reference rating life at displacements u (..., 5) [m, rad]: an object
        with ``L10r`` [1e6 rev], ``C`` [N] and ``modified(**kw)`` (ISO/TS 16281:2008 for
        a ball row).  dynamic_rating [N], nominal_contact_angle [rad] as in
        :func:`~ballrace.analytic.iso16281.reference_rating_life`."""


@dataclass(frozen=True)
class RowMount:
    """One row of a seat bearing, as mounted at the seat (frozen).

    Attributes
    ----------
    row : Row
        The row.  Rows that compare equal are evaluated together in one call.
    direction : int
        +1 or -1 [-]: the row takes thrust towards +x (-x) of the shaft frame.
    axial_offset : float
        Axial position of the row relative to the seat position [m].
    mounted_offset : float
        Axial displacement [m] of the row's inner ring at zero seat displacement (a
        preload deflection or a rigid preload), in the row's frame.
    centred : bool
        Start the shaft's iteration with this row centred (its axial displacement at
        ``-row.reference_axial_offset``); False keeps the row at its mounted offset (rows
        of a preloaded pair).
    """

    row: Any
    direction: int
    axial_offset: float
    mounted_offset: float
    centred: bool = True


@runtime_checkable
class SeatBearing(Protocol):
    r"""What a :class:`~ballrace.analytic.shaft.Seat` holds: a bearing with one or more rows.

    Attributes
    ----------
    accepts_clearance : bool
        Whether a seat's operating clearance applies (a preloaded pair keeps its own).
    carries_axial : bool
        Whether the bearing locates the shaft axially (a cylindrical roller bearing does
        not): a seat whose bearing does not is treated like a floating seat in the
        support check.
    life_exponent : float
        Exponent p of the catalog life (C/P)^p [-]: 3 for ball bearings, 10/3 for roller
        bearings (ISO 281:2007, clause 6.1).
    seat_name : str
        Short name of the bearing kind for tables (e.g. "single", "pair DB").

    Optional attributes, read with ``getattr`` where present (not members of the protocol:
    a seat bearing without them still satisfies it, and ``isinstance`` does not ask for
    them):

    weibull_slope : float
        Weibull slope e [-] of the bearing's life scatter: its rows combine into the
        seat's life, and the seats into the system life, with it
        (:func:`~ballrace.analytic.shaft.rating_lives`,
        :func:`~ballrace.analytic.shaft.duty_cycle`, :func:`~ballrace.analytic.shaft.system_life`).
        Default 10/9 where absent (ball bearings, Lundberg & Palmgren 1947;
        :data:`ballrace.analytic.life.BALL_WEIBULL_SLOPE`); roller bearings give 9/8
        (Lundberg & Palmgren 1952).
    permissible_misalignment : float
        Ring tilt the bearing tolerates [rad], shown next to the seat's tilt by
        ``ballrace shaft`` (roller bearings; a ball bearing's follows its type,
        :data:`ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT`).
    """

    accepts_clearance: bool
    carries_axial: bool
    life_exponent: float
    seat_name: str

    def seat_rows(self, direction: int, offset: float, row_spacing: float,
                  clearance) -> Sequence[RowMount]:
        """The rows as mounted at a seat.

        Parameters
        ----------
        direction : int
            +1 or -1 [-]: which way the bearing (for a pair: its first row) takes thrust.
        offset : float
            Rigid preload of the seat [m] (negative: end play).
        row_spacing : float
            Axial distance between rows [m] (0: all at the seat position).
        clearance : float or None
            Operating clearance [m]; None: the bearing's own.

        Raises ValueError if the bearing cannot be a seat (with the reason)."""

    def spring_axial_load(self, direction: int) -> float:
        """Constant axial load [N], shaft frame, that a spring inside the bearing adds to
        the seat's reaction (0 without one); direction +1 or -1 [-] as in seat_rows."""

    def equivalent_load(self, radial_load: float, axial_load: float,
                        contact_angle=None):
        """Dynamic equivalent load P = X Fr + Y Fa [N] of the catalog life (ISO 281:2007,
        clause 6.2), or None where a catalog life does not apply (e.g. a preloaded pair).
        radial_load, axial_load [N], contact_angle [rad] (None: the nominal one)."""

    def seat_warnings(self, what: str, results: Sequence, tilt: float) -> tuple:
        """Messages (str or None) for a seat working beyond the bearing's limits: static
        safety below 1, a contact angle or a tilt out of range.  ``what`` names the seat,
        ``results`` are its rows' :meth:`Row.result`, ``tilt`` the ring tilt [rad]."""


#: Members of each protocol, in the order they are documented (what :func:`missing` checks).
ROW_MEMBERS = ("ring_forces", "element_loads", "result", "rating_life",
               "reference_axial_offset", "approach_limit", "step_length", "moment_radius")
SEAT_BEARING_MEMBERS = ("seat_rows", "spring_axial_load", "equivalent_load", "seat_warnings",
                        "accepts_clearance", "carries_axial", "life_exponent", "seat_name")


def missing(obj, members: Sequence[str] = SEAT_BEARING_MEMBERS) -> list:
    """The names in ``members`` that ``obj`` does not have (empty: it satisfies the
    protocol's members)."""
    return [m for m in members if not hasattr(obj, m)]
