r"""A pair of tapered roller bearings at one shaft seat, with preload or end play.

Two identical single-row tapered roller bearings mounted back-to-back (``"DB"``, O) or
face-to-face (``"DF"``, X) at one seat: the pattern of
:class:`~ballrace.analytic.duplex.DuplexPair` for ball bearings, with the lamina model of
:mod:`ballrace.analytic.roller.loaddist` for each row
(:class:`~ballrace.analytic.roller.loaddist.RollerRow`).  The pair is a seat bearing
(:class:`~ballrace.analytic.contract.SeatBearing`): :func:`ballrace.analytic.shaft.solve`
solves the shaft with both rows, each with its own five-DOF roller load distribution.

Mounting (Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 2007, the
preloading of bearing pairs): each cone is pushed into its cup by delta_0 from the
just-touching position (the row's frame of
:class:`~ballrace.analytic.roller.loaddist.RollerRow`):

* ``preload`` P > 0: delta_0 > 0 with F_a(delta_0) = P, the axial force of one row under
  a pure axial displacement (every roller alike);
* ``end_play`` e > 0: delta_0 = -e/2 (the shaft moves e axially between the two
  just-touching positions);
* neither: delta_0 = 0 (both rows just touching).

An external axial load moves the shaft by x: the row in its path deflects delta_0 + x,
the other delta_0 - x; both share the radial displacement and tilt (rigid rings).  In
the shaft's frame the rows follow :meth:`TaperedPair.seat_rows` (as for a duplex pair):
in DB (O) the row carrying +x thrust sits on the -x side of the seat, in DF (X) on the
+x side, ``row_spacing`` apart; each row's pressure centre lies (d_m/2) tan(alpha) from
its middle (the normal line through the roller centre), outwards in DB.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._checks import check_choice, check_nonnegative
from .bearing import RollerBearing, seat_safety_message, seat_tilt_messages
from .loaddist import RollerRow

__all__ = ["TaperedPair", "ARRANGEMENTS"]

#: Arrangements of a tapered pair: back-to-back (O) and face-to-face (X).
ARRANGEMENTS = ("DB", "DF")


@dataclass(frozen=True)
class TaperedPair:
    r"""Two tapered roller bearings at one seat, back-to-back or face-to-face (frozen).

    Parameters
    ----------
    bearing : RollerBearing
        The single-row tapered bearing of both rows (``kind="tapered"``, ``n_rows=1``).
    arrangement : {"DB", "DF"}
        Back-to-back (O) or face-to-face (X).
    preload : float
        Axial preload of the pair [N], >= 0 (module notes).
    end_play : float
        Axial end play of the pair [m], >= 0; not together with a preload.

    Examples
    --------
    >>> import numpy as np
    >>> from ballrace.analytic.roller import RollerBearing, TaperedPair
    >>> t = RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered",
    ...                   contact_angle=np.radians(15))
    >>> p = TaperedPair(t, "DB", preload=2000.0)
    >>> round(p.preload_deflection * 1e6, 3), round(float(p.axial_load(p.preload_deflection)), 6)
    (17.05, 2000.0)
    """

    bearing: RollerBearing
    arrangement: str = "DB"
    preload: float = 0.0
    end_play: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.bearing, RollerBearing):
            raise TypeError(f"bearing must be a RollerBearing; got "
                            f"{type(self.bearing).__name__}")
        if not self.bearing.tapered:
            raise ValueError(f"bearing must be a tapered roller bearing (kind='tapered'): a "
                             f"pair of {self.bearing.kind} bearings carries no preload")
        if self.bearing.n_rows != 1:
            raise ValueError(f"bearing must be single-row (n_rows=1); got "
                             f"n_rows={self.bearing.n_rows}")
        check_choice(self.arrangement, "arrangement", ARRANGEMENTS)
        P = float(check_nonnegative(self.preload, "preload", "N", bounded=True, tiny_ok=True))
        e = float(check_nonnegative(self.end_play, "end_play", "m", bounded=True,
                                    tiny_ok=True))
        if P > 0 and e > 0:
            raise ValueError(f"give a preload [N] or an end play [m], not both; got "
                             f"preload={P!r}, end_play={e!r}")
        if e >= 0.1 * self.bearing.roller_diameter:
            raise ValueError(f"end_play must be below D_we/10 = "
                             f"{0.1 * self.bearing.roller_diameter:g} m (catalogue end plays "
                             f"are some 20-200 um, e.g. 50e-6); got {e!r}"
                             + (f" (were micrometres given? {e:g} um is {e * 1e-6:g} m)"
                                if e >= 1.0 else ""))
        object.__setattr__(self, "preload", P)
        object.__setattr__(self, "end_play", e)
        object.__setattr__(self, "_d0", self._deflection())

    @property
    def row(self) -> RollerRow:
        """The row model of both bearings (one model: evaluated together)."""
        return RollerRow(self.bearing)

    def axial_load(self, axial_deflection):
        """Axial load [N] of one row pushed axial_deflection [m] beyond its just-touching
        position (no radial displacement, no tilt; every roller alike)."""
        x = np.atleast_1d(np.asarray(axial_deflection, float))
        u = np.zeros(x.shape + (5,))
        u[..., 0] = x
        F = self.row.ring_forces(u.reshape(-1, 5))[0][:, 0].reshape(x.shape)
        return float(F[0]) if np.ndim(axial_deflection) == 0 else F

    @property
    def preload_deflection(self) -> float:
        """delta_0 [m]: each row's axial displacement beyond its just-touching position at
        mounting (module notes; negative: half the end play)."""
        return self._d0

    def _deflection(self) -> float:
        if self.end_play > 0:
            return -0.5 * self.end_play
        P = self.preload
        if P == 0:
            return 0.0
        row = self.row
        cap = row.approach_limit / math.sin(self.bearing.contact_angle)
        if not self.axial_load(cap) >= P:
            raise ValueError(f"preload={P:g} N is beyond the load-deflection range of the "
                             f"bearing (at most {self.axial_load(cap):.4g} N, at a slice "
                             f"approach of {row.approach_limit:.3g} m)")
        lo, hi = 0.0, cap
        x = hi
        for _ in range(200):                     # Newton on a monotone law, bracketed
            u = np.array([[x, 0.0, 0.0, 0.0, 0.0]])
            F, K = row.ring_forces(u)[:2]
            f, df = float(F[0, 0]) - P, float(K[0, 0, 0])
            if f > 0:
                hi = x
            else:
                lo = x
            xn = x - f / df if df > 0 else 0.5 * (lo + hi)
            if not lo < xn < hi:
                xn = 0.5 * (lo + hi)
            if abs(xn - x) <= 1e-15 * x or hi - lo <= 1e-15 * hi:
                return float(xn)
            x = xn
        return float(x)

    # ------------------------------------------------------------------ shaft seat
    # The seat contract (ballrace.analytic.contract.SeatBearing): two roller rows.
    accepts_clearance = False           # the rows keep their preload or end play
    carries_axial = True
    life_exponent = 10.0 / 3.0
    weibull_slope = 9.0 / 8.0

    @property
    def seat_name(self) -> str:
        """"tapered pair DB" or "tapered pair DF" (for tables)."""
        return "tapered pair " + self.arrangement

    def seat_rows(self, direction, offset, row_spacing, clearance):
        """The pair as a shaft seat: its two rows, each at delta_0 plus the seat's offset
        and kept there at the start; see
        :meth:`ballrace.analytic.contract.SeatBearing.seat_rows` (direction [-], offset
        [m], row_spacing [m], clearance [m] or None: the rows keep their own).  In DB (O)
        a row carrying +x shaft thrust sits on the -x side of the seat, in DF (X) on the
        +x side."""
        from ..contract import RowMount

        row = self.row                              # one model: both rows together
        d = direction
        d0 = self.preload_deflection + offset
        h = 0.5 * row_spacing
        s = -1.0 if self.arrangement == "DB" else 1.0
        return (RowMount(row, d, s * d * h, d0, False), RowMount(row, -d, -s * d * h, d0, False))

    def spring_axial_load(self, direction) -> float:
        """No spring: 0 [N] (direction [-] unused)."""
        return 0.0

    def equivalent_load(self, radial_load, axial_load, contact_angle=None):
        """None: a preloaded pair has no catalog (C/P)^(10/3) life here (its rows' ISO/TS
        16281 lives apply); radial_load, axial_load [N], contact_angle [rad] unused."""
        return None

    @property
    def permissible_misalignment(self) -> float:
        """Tilt the rows tolerate [rad]: that of the single bearing."""
        return self.bearing.permissible_misalignment

    def seat_warnings(self, what, results, tilt) -> tuple:
        """Messages (str or None) for the pair's rows: static safety below 1 (4000 MPa,
        ISO 76), a tilt [rad] beyond the bearing's permissible misalignment, edge-loaded
        rollers (:func:`~ballrace.analytic.roller.bearing.seat_tilt_messages`)."""
        return (seat_safety_message(what, results),
                *seat_tilt_messages(what, self.bearing, results, tilt))
