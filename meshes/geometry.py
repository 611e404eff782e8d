r"""Analytic surfaces of the contacting bodies in the local contact frame (numpy only).

Frame (the whole of :mod:`ballrace.fem` and :mod:`ballrace.meshes` uses it):

* origin at the undeformed first-contact point;
* x along the rolling direction, y transverse (in the bearing's axial plane),
  z along the contact normal pointing *into the ball* (body 1), so the race or
  plane (body 2) occupies z < 0 and the depth below its surface is -z;
* a surface is described by its height ``z = h(x, y)`` over the tangent plane.

The initial gap between the bodies is ``g0(x, y) = h_ball(x, y) - h_race(x, y) >= 0``.
Hertz's gap is the quadratic ``x^2/(2 Rx) + y^2/(2 Ry)`` (Hamrock & Dowson 1981
eq. 3.1); the exact gap uses the sphere and the race torus.  The two differ by
several per cent of the gap at the end of a conformal ball–race ellipse
(a / (f D) ~ 0.3, see ``docs/fem.md``).

Race torus (Ricci 2009 §2, eqs. 1–11): the groove of radius ``r_t = f D`` is swept
around the bearing axis; its centre lies on the contact normal through the ball
centre, ``(f - 1/2) D`` beyond the ball centre.  In a bearing frame with the axis
along Y and the ball centre at ``(0, 0, d_m/2)``, the unit vector from the ball
centre to the contact is ``u = -(0, sin b, cos b)`` for the inner race and
``+(0, sin b, cos b)`` for the outer race at contact angle ``b``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Surface", "Plane", "Sphere", "Paraboloid", "RaceTorus", "RingSurface", "race_torus",
           "ring_surface", "gap"]


class Surface:
    """Height ``h(x, y)`` [m] of a body's surface over the tangent plane z = 0."""

    def height(self, x, y):  # pragma: no cover - interface
        raise NotImplementedError


@dataclass(frozen=True)
class Plane(Surface):
    """Flat surface z = 0."""

    def height(self, x, y):
        """Height [m]: zero everywhere."""
        return np.zeros(np.broadcast(np.asarray(x), np.asarray(y)).shape)


@dataclass(frozen=True)
class Paraboloid(Surface):
    r"""Quadratic surface :math:`h = s\,(x^2/(2 r_x) + y^2/(2 r_y))`.

    Parameters
    ----------
    rx, ry : float
        Principal radii [m], positive convex, negative concave, ``inf`` flat
        (the sign convention of :func:`ballrace.analytic.hertz.curvature`).
    side : {+1, -1}
        +1 for the upper body (ball, bulging down towards -z is *positive* gap),
        -1 for the lower body.

    Examples
    --------
    >>> round(float(Paraboloid(0.01, 0.01, +1).height(1e-3, 0.0)) * 1e6, 6)
    50.0
    """

    rx: float
    ry: float
    side: int = 1

    def height(self, x, y):
        """Height [m]."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        return self.side * (x * x / (2.0 * self.rx) + y * y / (2.0 * self.ry))


@dataclass(frozen=True)
class Sphere(Surface):
    r"""Sphere of radius R touching the origin; ``side=+1`` above (ball), ``-1`` below.

    .. math:: h = \pm\left(R - \sqrt{R^2 - x^2 - y^2}\right)

    Examples
    --------
    >>> round(float(Sphere(0.00635).height(1e-3, 0.0)) * 1e6, 3)
    79.234
    """

    radius: float
    side: int = 1

    def height(self, x, y):
        """Height [m] (NaN outside the sphere's silhouette)."""
        r2 = np.asarray(x, dtype=float) ** 2 + np.asarray(y, dtype=float) ** 2
        with np.errstate(invalid="ignore"):
            # R - sqrt(R^2 - r2) = r2 / (R + sqrt(R^2 - r2)): no cancellation near the axis
            return self.side * r2 / (self.radius + np.sqrt(self.radius**2 - r2))


@dataclass(frozen=True)
class RaceTorus(Surface):
    """Race groove surface (torus), given in the local contact frame.

    Attributes
    ----------
    axis_point : (3,) ndarray
        A point on the bearing axis, local coordinates [m].
    axis_dir : (3,) ndarray
        Unit vector along the bearing axis, local coordinates [-].
    major_radius : float
        Distance from the axis to the groove-centre circle [m].
    minor_radius : float
        Groove radius f D [m].
    """

    axis_point: tuple
    axis_dir: tuple
    major_radius: float
    minor_radius: float

    def implicit(self, x, y, z):
        """Signed torus function: < 0 inside the tube (the ball's side) [m^2]."""
        c = np.asarray(self.axis_point)
        e = np.asarray(self.axis_dir)
        qx, qy, qz = x - c[0], y - c[1], z - c[2]
        t = qx * e[0] + qy * e[1] + qz * e[2]
        rho = np.sqrt(np.maximum(qx * qx + qy * qy + qz * qz - t * t, 0.0))
        return (rho - self.major_radius) ** 2 + t * t - self.minor_radius**2

    def height(self, x, y, *, iterations: int = 30):
        """Height of the race surface over (x, y) [m], by Newton on the torus equation.

        Valid while |y| stays well inside the groove (|y| < 0.9 f D).
        """
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        x, y = np.broadcast_arrays(x, y)
        z = np.zeros(x.shape)
        h = 1e-7 * self.minor_radius
        for _ in range(iterations):
            f = self.implicit(x, y, z)
            df = (self.implicit(x, y, z + h) - self.implicit(x, y, z - h)) / (2 * h)
            step = f / df
            z = z - step
            if np.all(np.abs(step) < 1e-15 * self.minor_radius):
                break
        return z


@dataclass(frozen=True)
class RingSurface(Surface):
    """Race groove with its lands: the ring surface ``h = min(h_groove, h_land)``.

    The ring is the material inside the land cylinder (inner ring; outside it for the
    outer ring) with the groove torus cut away; seen from the contact, the surface is the
    first of the two met, i.e. the lower height.  The land cylinder is coaxial with the
    bearing, ``shoulder_height`` above the groove bottom (Hamrock & Dowson 1981 fig. 2.17).

    Attributes
    ----------
    groove : RaceTorus
    land_radius : float
        Radius of the land cylinder about the bearing axis [m].
    valid_y : float
        The groove height is used for |y| <= valid_y (inside the groove, where the torus
        Newton iteration is reliable); the land beyond [m].
    shoulder_y : float
        |y| of the shoulder edge (groove meets land) at contact angle 0 [m].
    """

    groove: RaceTorus
    land_radius: float
    valid_y: float
    shoulder_y: float = float("nan")

    def land_height(self, x, y):
        """Height of the land cylinder over (x, y), the root nearest the contact [m]."""
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        c = np.asarray(self.groove.axis_point)
        e = np.asarray(self.groove.axis_dir)
        q0 = np.stack([x - c[0], y - c[1], np.full(x.shape, -c[2])])
        qe = np.tensordot(e, q0, axes=1)
        A = 1.0 - e[2] ** 2
        B = 2.0 * (q0[2] - qe * e[2])
        C = (q0 * q0).sum(0) - qe * qe - self.land_radius**2
        disc = np.sqrt(np.maximum(B * B - 4 * A * C, 0.0))
        r1, r2 = (-B - disc) / (2 * A), (-B + disc) / (2 * A)
        return np.where(np.abs(r1) < np.abs(r2), r1, r2)

    def height(self, x, y):
        """Ring surface height [m]: groove inside ``valid_y``, otherwise the land."""
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        inside = np.abs(y) <= self.valid_y
        hl = self.land_height(x, y)
        hg = self.groove.height(x, np.where(inside, y, 0.0))
        return np.where(inside, np.minimum(hg, hl), hl)


def ring_surface(ball_diameter: float, pitch_diameter: float, f: float, race: str,
                 contact_angle: float = 0.0, shoulder_height: float | None = None
                 ) -> RingSurface:
    """Groove and lands of a race in the local contact frame (see :class:`RingSurface`).

    Parameters
    ----------
    ball_diameter, pitch_diameter, f, race, contact_angle
        As for :func:`race_torus` [m, m, -, -, rad].
    shoulder_height : float, optional
        Land height above the groove bottom [m]; default 0.2 D (typical of deep-groove
        ball bearings, Harris 2001 §2.2).  Capped so that the shoulder edge lies
        within 0.85 f D of the groove centre plane.

    Examples
    --------
    209 inner race: the groove bottom at the contact, the land 2.54 mm above it.

    >>> s = ring_surface(12.7e-3, 65e-3, 0.52, "inner")
    >>> abs(float(s.height(0.0, 0.0))) < 1e-15, round(float(s.height(0.0, 8e-3)) * 1e3, 4)
    (True, 2.54)
    """
    D, r = ball_diameter, f * ball_diameter
    t = race_torus(D, pitch_diameter, f, race, contact_angle)
    hs = 0.2 * D if shoulder_height is None else float(shoulder_height)
    h_max = r * (1.0 - np.sqrt(1.0 - 0.85**2))          # shoulder edge at y = 0.85 r
    hs = min(hs, h_max)
    land = t.major_radius - r + hs if race == "inner" else t.major_radius + r - hs
    y_edge = np.sqrt(r * r - (r - hs) ** 2)
    return RingSurface(groove=t, land_radius=float(land),
                       valid_y=float(min(0.9 * r, y_edge + 0.05 * r)), shoulder_y=float(y_edge))


def race_torus(ball_diameter: float, pitch_diameter: float, f: float, race: str,
               contact_angle: float = 0.0) -> RaceTorus:
    """Race groove torus in the local contact frame of a ball at ``contact_angle``.

    Parameters
    ----------
    ball_diameter : float
        Ball diameter D [m].
    pitch_diameter : float
        Pitch diameter d_m [m].
    f : float
        Groove conformity r/D [-], > 0.5.
    race : {"inner", "outer"}
        Which race.
    contact_angle : float
        Contact angle [rad].

    References
    ----------
    Ricci (2009) eqs. (1)–(11); Hamrock & Dowson (1981) §3.2.

    Examples
    --------
    Curvature in the rolling plane of the 209 inner race, (d_m - D)/2 = 26.15 mm:

    >>> t = race_torus(12.7e-3, 65e-3, 0.52, "inner")
    >>> x = 1e-4; round(float(-x * x / (2 * t.height(x, 0.0))) * 1e3, 3)
    26.15
    """
    s = -1.0 if race == "inner" else 1.0
    cb, sb = np.cos(contact_angle), np.sin(contact_angle)
    # bearing frame: axis along Y, ball centre at (0, 0, d_m/2)
    Ob = np.array([0.0, 0.0, pitch_diameter / 2.0])
    u = s * np.array([0.0, sb, cb])                 # ball centre -> contact
    P = Ob + 0.5 * ball_diameter * u                # contact point
    G = Ob + (0.5 - f) * ball_diameter * u          # groove centre
    ez = -u                                         # into the ball
    ex = np.array([1.0, 0.0, 0.0])
    ey = np.cross(ez, ex)
    Rm = np.stack([ex, ey, ez])                     # rows: local axes in bearing frame
    axis_pt = np.array([0.0, G[1], 0.0])            # on the axis, in the groove-centre plane
    major = float(np.hypot(G[0], G[2]))
    return RaceTorus(axis_point=tuple(Rm @ (axis_pt - P)), axis_dir=tuple(Rm @ np.array([0, 1.0, 0])),
                     major_radius=major, minor_radius=f * ball_diameter)


def gap(upper: Surface, lower: Surface, x, y):
    """Initial gap g0 = h_upper - h_lower [m] at (x, y) [m]."""
    return upper.height(x, y) - lower.height(x, y)
