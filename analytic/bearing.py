r"""Ball-bearing internal geometry (frozen :class:`BallBearing`) and thin load methods.

Geometry after Ricci (2009) eqs. (1)–(11) and Hamrock & Dowson (1981) §2 / §3.2:

* pitch diameter d_e = (d_i + d_o)/2 (Ricci eq. 1), race (groove-bottom) diameters
  d_i = d_e - D - P_d/2, d_o = d_e + D + P_d/2, so P_d = d_o - d_i - 2D;
* conformities f_i = r_i/D, f_o = r_o/D > 1/2, total conformity B = f_i + f_o - 1 and
  distance between the groove curvature centres A = B D (Ricci eq. 4);
* free contact angle and diametral clearance, one given and the other derived:
  cos beta_f = 1 - P_d/(2A) (Ricci eqs. 5–6); free endplay P_e = 2 A sin beta_f (eq. 7);
* effective radii of the ball–inner and ball–outer contacts at any contact angle beta,
  with gamma = D cos beta / d_e (Ricci eqs. 8–11):
  R_x = D (1 -+ gamma)/2 (upper sign inner race), R_y = f D / (2f - 1).

Coordinates used by the load distribution (:mod:`ballrace.analytic.loaddist`): x is the
bearing axis; y and z are radial; ball j sits at azimuth psi_j measured from +y towards +z.
Loads (Fa, Fy, Fz, My, Mz) act on the inner ring relative to a fixed outer ring; moments
are right-handed about the bearing centre, so a thrust Fa applied at y = e gives
Mz = -e Fa and one applied at z = e gives My = +e Fa.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from . import hertz
from ._checks import (as_array, broadcast, check_choice, check_nonnegative, check_range,
                      scalar_count, scalar_positive, store_checked)
from .materials import BEARING_STEEL, Material, effective_modulus

__all__ = ["BallBearing", "RACES"]

log = logging.getLogger(__name__)

#: Names accepted for the ``race`` argument.
RACES = ("inner", "outer")


#: Groove conformity r/D above which a warning is given: catalogue ball bearings have
#: about 0.505-0.57 (ISO 281:2007 §6.1.1 takes its ratings for groove radii up to 0.52 D
#: inner and 0.53 D outer).
CONFORMITY_WARN = 0.6


def _conformity(value, name: str) -> float:
    """A groove conformity r/D: in (0.5, 1), with a warning above CONFORMITY_WARN."""
    f = float(check_range(value, name, 0.5, None, unit="-"))
    if f >= 1.0:
        raise ValueError(f"{name} must be a groove conformity r/D in (0.5, 1), typically "
                         f"0.505-0.57 [-]; got {f:g}"
                         + (f" (a percentage? {f:g} % is {f / 100:g})" if 50 < f < 100 else ""))
    if f > CONFORMITY_WARN:
        import warnings

        warnings.warn(f"{name} = {f:g}: groove conformity r/D is usually 0.505-0.57; a groove "
                      f"this open is a very unusual bearing - check the value", UserWarning,
                      stacklevel=4)
    return f




def _nominal_angle(value, free_angle: float, angle_given: bool) -> float:
    """The nominal (rating) contact angle [rad]: ``value`` checked, or the default rule of
    :class:`BallBearing` (0 for a bearing given by its clearance, else the free angle)."""
    if value is None:
        if angle_given:
            return free_angle
        if free_angle > np.radians(20.0):
            from ..errors import warn

            warn(f"BallBearing: the diametral clearance gives a free contact angle of "
                 f"{np.degrees(free_angle):.1f} deg, more than a deep-groove bearing's "
                 "clearance gives; the ratings use the nominal contact angle 0 (radial "
                 "bearing) - pass nominal_contact_angle (the design angle [rad]) for an "
                 "angular-contact bearing")
        return 0.0
    arr = as_array(value, "nominal_contact_angle")
    if arr.ndim:
        raise TypeError(f"nominal_contact_angle must be a scalar [rad]; got an array of shape "
                        f"{arr.shape}")
    a = float(arr)
    if not 0.0 <= a < 0.5 * np.pi:
        hint = (f" ({a:g} looks like degrees: pass numpy.radians({a:g}))"
                if 0.5 * np.pi < a < 90.0 else "")
        raise ValueError(f"nominal_contact_angle must be in [0, {0.5 * np.pi:g}) [rad] "
                         f"(0 for radial deep-groove bearings, the design angle for "
                         f"angular-contact ones); got {value!r}{hint}")
    return a


@dataclass(frozen=True)
class BallBearing:
    r"""Internal geometry and materials of a single-row ball bearing (frozen).

    Give **either** the free contact angle ``free_contact_angle`` **or** the diametral
    clearance ``diametral_clearance``; the other is derived (Ricci 2009 eqs. 5–6):

    .. math:: \cos\beta_f = 1 - \frac{P_d}{2A}, \qquad A = (f_i + f_o - 1) D

    Both attributes are set after construction.  Passing both is accepted only when
    they agree (so ``dataclasses.replace`` of a material works); after changing D or a
    conformity with ``replace``, set the one to be re-derived to ``None``.

    **Nominal (rating) contact angle.**  The load ratings belong to the bearing type, not
    to its clearance: ISO 281:2007 (§6.1.1, eqs. 2–3) gives C, and ISO 76:2006 (§5.1.1)
    C0, at the *nominal* contact angle α, and ISO/TS 16281:2008 (§5.2) derives the raceway
    capacities Q_ci, Q_ce from C with cos α of that same nominal angle.  For a radial
    deep-groove bearing α = 0, whatever free contact angle its clearance gives (about 7.6°
    for a 6305 size with 10 µm diametral clearance); for an angular-contact bearing α is
    the design angle.  ``nominal_contact_angle`` is that α; every rating (C, C0, C_u, the
    X/Y/e tables, Q_c of ISO/TS 16281) uses it, while the load distribution, the Hertz
    contacts and the kinematics use the free (unloaded) and the operating contact angles.
    When it is not given (``None``) it is derived by one explicit rule:

    * bearing given by its ``diametral_clearance`` — a radial (deep-groove) bearing whose
      free contact angle comes only from its clearance: α = 0 (a logged warning when that
      free angle exceeds 20°, beyond a deep-groove bearing's clearance);
    * bearing given by its ``free_contact_angle`` (an angular-contact bearing's design
      angle): α = ``free_contact_angle``.

    ``dataclasses.replace`` keeps the value (an operating clearance from fits does not
    change the rating angle); set it to ``None`` to derive it again.

    Parameters
    ----------
    ball_diameter : float
        Ball diameter D [m], in (0, pitch_diameter).
    n_balls : int
        Number of balls Z [-], >= 3, and no more than fit on the pitch circle,
        Z arcsin(D/d_e) <= pi.
    pitch_diameter : float
        Pitch diameter d_e = (d_i + d_o)/2 [m] (Ricci 2009 eq. 1), > D.
    f_inner, f_outer : float
        Groove conformities r/D of the inner and outer race [-], in (0.5, 1); typically
        0.505–0.57.  A value of 1 or more is refused (52 for 0.52 is a percentage slip);
        above 0.6 a warning names the likely slip.
    free_contact_angle : float, optional
        Free (unloaded) contact angle beta_f [rad], in [0, pi/2).
    diametral_clearance : float, optional
        Diametral clearance P_d = d_o - d_i - 2D [m], in [0, 2A).
    nominal_contact_angle : float, optional
        Nominal (rating) contact angle α of ISO 281 / ISO 76 / ISO/TS 16281 [rad], in
        [0, pi/2): 0 for radial deep-groove bearings, the design angle for
        angular-contact ones.  Default ``None``: derived as described above.
    material : Material, optional
        Material of balls and rings (default :data:`BEARING_STEEL`).
    ball_material, ring_material : Material, optional
        Separate ball / ring materials (e.g. silicon-nitride balls); each defaults to
        ``material``.
    shoulder_height_inner, shoulder_height_outer : float, optional
        Shoulder (land) height above the groove bottom [m], in (0, f D]; enables the
        contact-ellipse truncation check (Hamrock & Dowson 1981 eqs. 3.57–3.58).
    n_rows : int, optional
        Number of rows i [-] (used by the load ratings; the load distribution handles
        single-row bearings only).  Default 1.
    name : str, optional
        Label for reports.

    References
    ----------
    Ricci, M.C. (2009) "Ball bearings subjected to a variable eccentric thrust load",
    DINCON'09, eqs. (1)–(11); Hamrock, B.J. & Dowson, D. (1981) *Ball Bearing
    Lubrication*, Wiley, ch. 2–3 (NASA TM-81691).

    Examples
    --------
    The 218 angular-contact bearing of Ricci (2009):

    >>> import ballrace
    >>> brg = ballrace.BallBearing(ball_diameter=22.225e-3, n_balls=16,
    ...                            pitch_diameter=125.26e-3, f_inner=0.5232, f_outer=0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> round(brg.total_conformity, 4), round(brg.diametral_clearance * 1e3, 4)
    (0.0464, 0.4825)
    >>> round(brg.free_endplay * 1e3, 4)
    1.3257
    >>> round(float(np.degrees(brg.nominal_contact_angle)), 10)   # the design angle
    40.0
    >>> brg2 = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                             diametral_clearance=brg.diametral_clearance,
    ...                             nominal_contact_angle=np.radians(40))
    >>> round(float(np.degrees(brg2.free_contact_angle)), 10)
    40.0

    A 6305-size deep-groove bearing with 10 µm diametral clearance: free contact angle
    7.56°, rated at α = 0:

    >>> dg = ballrace.BallBearing(11.5e-3, 7, 43.5e-3, 0.52, 0.53, diametral_clearance=10e-6)
    >>> round(float(np.degrees(dg.free_contact_angle)), 2), dg.nominal_contact_angle
    (7.56, 0.0)
    """

    ball_diameter: float
    n_balls: int
    pitch_diameter: float
    f_inner: float
    f_outer: float
    free_contact_angle: float | None = None
    diametral_clearance: float | None = None
    material: Material = BEARING_STEEL
    ball_material: Material | None = None
    ring_material: Material | None = None
    shoulder_height_inner: float | None = None
    shoulder_height_outer: float | None = None
    n_rows: int = 1
    name: str = ""
    nominal_contact_angle: float | None = None

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        angle_given = self.free_contact_angle is not None
        D = scalar_positive(self.ball_diameter, "ball_diameter", "m")
        dm = scalar_positive(self.pitch_diameter, "pitch_diameter", "m")
        if not D < dm:
            raise ValueError(f"ball_diameter must be in (0, pitch_diameter) = (0, {dm:g}) [m]; "
                             f"got {D:g}")
        if D > 0.25 or dm > 20.0:  # mm typed as m would give C = 677 MN without a word
            import warnings

            warnings.warn(f"ball_diameter = {D:g} m, pitch_diameter = {dm:g} m: larger than any "
                          "rolling bearing (balls up to ~0.2 m); lengths are in metres [m] - "
                          "were millimetres given?", UserWarning, stacklevel=3)
        Z = scalar_count(self.n_balls, "n_balls", 3)
        z_max = int(np.floor(np.pi / np.arcsin(D / dm) * (1 + 1e-12)))
        if Z > z_max:
            raise ValueError(f"n_balls must be in [3, {z_max}] for D = {D:g} m on a pitch "
                             f"diameter of {dm:g} m (Z arcsin(D/d_e) <= pi); got {Z}")
        fi = _conformity(self.f_inner, "f_inner")
        fo = _conformity(self.f_outer, "f_outer")
        A = (fi + fo - 1.0) * D
        for m in ("material", "ball_material", "ring_material"):
            v = getattr(self, m)
            if v is not None and not isinstance(v, Material):
                raise TypeError(f"{m} must be a ballrace.Material; got {type(v).__name__}")
        if self.material is None:
            raise TypeError("material must be a ballrace.Material; got None")

        bf, pd = self.free_contact_angle, self.diametral_clearance
        if bf is None and pd is None:
            raise ValueError("give one of free_contact_angle [rad] (in [0, pi/2)) or "
                             "diametral_clearance [m] (in [0, 2(f_i + f_o - 1)D)); got neither")
        if bf is not None:
            bf = float(check_range(bf, "free_contact_angle", 0.0, 0.5 * np.pi,
                                   low_inclusive=True, unit="rad"))
            pd_from_bf = float(2.0 * A * (1.0 - np.cos(bf)))                 # Ricci (2009) eq. 6
            if pd is not None:
                pd = float(as_array(pd, "diametral_clearance"))
                if not np.isclose(pd, pd_from_bf, rtol=1e-9, atol=1e-15):
                    raise ValueError(
                        "give either free_contact_angle or diametral_clearance, not both: "
                        f"free_contact_angle={bf!r} rad implies diametral_clearance="
                        f"{pd_from_bf:.6g} m, got {pd:.6g} m (with dataclasses.replace, set "
                        "the one to be re-derived to None)")
            pd = pd_from_bf
        else:
            pd = float(check_range(pd, "diametral_clearance", 0.0, 2.0 * A, low_inclusive=True,
                                   unit="m"))
            bf = float(np.arccos(1.0 - pd / (2.0 * A)))               # Ricci (2009) eq. 5
        store_checked(self, ball_diameter=D, pitch_diameter=dm, n_balls=Z, f_inner=fi,
                      f_outer=fo, free_contact_angle=bf, diametral_clearance=pd,
                      nominal_contact_angle=_nominal_angle(self.nominal_contact_angle, bf,
                                                           angle_given))
        if self.ball_material is None:
            set_(self, "ball_material", self.material)
        if self.ring_material is None:
            set_(self, "ring_material", self.material)
        for race, f in (("inner", fi), ("outer", fo)):
            name = f"shoulder_height_{race}"
            h = getattr(self, name)
            if h is not None:
                h = float(check_range(h, name, 0.0, f * D, high_inclusive=True, unit="m"))
                set_(self, name, h)
        set_(self, "n_rows", scalar_count(self.n_rows, "n_rows", 1))

    # ------------------------------------------------------------------ derived geometry
    @property
    def total_conformity(self) -> float:
        """Total conformity ratio B = f_i + f_o - 1 [-] (Ricci 2009 eq. 4)."""
        return self.f_inner + self.f_outer - 1.0

    @property
    def curvature_center_distance(self) -> float:
        """Distance A = B D between the groove curvature centres when the ball touches both
        races without load [m] (Ricci 2009 eqs. 3–4; Hamrock & Dowson 1981 eq. 2.7)."""
        return self.total_conformity * self.ball_diameter

    @property
    def free_endplay(self) -> float:
        """Free endplay P_e = 2 A sin beta_f [m] (Ricci 2009 eq. 7)."""
        return float(2.0 * self.curvature_center_distance * np.sin(self.free_contact_angle))

    @property
    def inner_race_diameter(self) -> float:
        """Inner-race groove-bottom diameter d_i = d_e - D - P_d/2 [m] (Ricci 2009 eqs. 1–2)."""
        return self.pitch_diameter - self.ball_diameter - 0.5 * self.diametral_clearance

    @property
    def outer_race_diameter(self) -> float:
        """Outer-race groove-bottom diameter d_o = d_e + D + P_d/2 [m] (Ricci 2009 eqs. 1–2)."""
        return self.pitch_diameter + self.ball_diameter + 0.5 * self.diametral_clearance

    @property
    def inner_groove_center_radius(self) -> float:
        r"""Radius of the locus of inner-groove curvature centres R_i = d_i/2 + f_i D [m].

        Equals Ricci's (2009, after eq. 17) :math:`d_e/2 + (f_i - 1/2) D \cos\beta_f`
        when f_i = f_o, and is the exact value otherwise.
        """
        return 0.5 * self.inner_race_diameter + self.f_inner * self.ball_diameter

    @property
    def E_prime(self) -> float:
        """Effective modulus E' of the ball–race contacts [Pa] (Hamrock & Dowson 1981 eq. 3.4)."""
        return float(effective_modulus(self.ball_material, self.ring_material))

    @property
    def ball_mass(self) -> float:
        """Mass of one ball, pi D^3 rho / 6 [kg]."""
        return float(np.pi * self.ball_diameter**3 * self.ball_material.density / 6.0)

    def azimuths(self, azimuth_offset: float = 0.0) -> np.ndarray:
        """Ball azimuths psi_j = offset + 2 pi (j - 1)/Z, j = 1..Z [rad] (Ricci 2009 fig. 6).

        Parameters
        ----------
        azimuth_offset : float
            Azimuth of ball 1 from the +y axis [rad].
        """
        off = float(as_array(azimuth_offset, "azimuth_offset"))
        return off + 2.0 * np.pi * np.arange(self.n_balls) / self.n_balls

    def gamma(self, contact_angle):
        """gamma = D cos(beta) / d_e [-] (Ricci 2009, before eq. 8).

        Parameters
        ----------
        contact_angle : float or array_like
            Contact angle beta [rad].
        """
        b = as_array(contact_angle, "contact_angle")
        return hertz.scalar_result(self.ball_diameter * np.cos(b) / self.pitch_diameter)

    def curvature(self, race: str, contact_angle) -> hertz.Curvature:
        r"""Effective radii Rx, Ry of the ball–race contact at contact angle beta.

        .. math::
            R_{x,i} = \frac{D}{2}(1 - \gamma), \quad R_{x,o} = \frac{D}{2}(1 + \gamma),
            \quad R_y = \frac{f D}{2 f - 1}, \quad \gamma = \frac{D\cos\beta}{d_e}

        so that 1/R_i = (4 - 1/f_i + 2 gamma/(1 - gamma))/D and
        1/R_o = (4 - 1/f_o - 2 gamma/(1 + gamma))/D.

        Parameters
        ----------
        race : {"inner", "outer"}
            Which race.
        contact_angle : float or array_like
            Contact angle beta [rad].

        Returns
        -------
        hertz.Curvature
            ``Rx`` (rolling direction) and ``Ry`` (transverse) [m]; ``curvature_sum`` and
            ``curvature_difference`` give Ricci's 1/R and Gamma.

        References
        ----------
        Ricci (2009) eqs. (8)–(11); Hamrock & Dowson (1981) eqs. (2.18)–(2.25).

        Examples
        --------
        >>> import ballrace
        >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
        ...                            free_contact_angle=np.radians(40))
        >>> c = brg.curvature("inner", np.radians(40))
        >>> round(float(c.Rx) * 1e3, 4), round(float(c.Ry) * 1e3, 3)
        (9.6021, 250.606)
        >>> round(float(c.curvature_sum), 3), round(float(c.curvature_difference), 4)  # eqs. 8, 9
        (108.134, 0.9262)
        """
        check_choice(race, "race", RACES)
        g = np.asarray(self.gamma(contact_angle))
        D = self.ball_diameter
        f = self.f_inner if race == "inner" else self.f_outer
        Rx = 0.5 * D * (1.0 - g) if race == "inner" else 0.5 * D * (1.0 + g)
        Ry = f * D / (2.0 * f - 1.0) + 0.0 * Rx
        return hertz.Curvature(Rx=hertz.scalar_result(Rx), Ry=hertz.scalar_result(Ry))

    def contact_stiffness(self, contact_angle, method: str = "exact"):
        r"""Load–deflection constants of the inner, outer and ball-between-races contacts.

        .. math:: Q = K \delta^{3/2}, \qquad
                  K_n = \left(K_i^{-2/3} + K_o^{-2/3}\right)^{-3/2}

        Parameters
        ----------
        contact_angle : float or array_like
            Contact angle beta [rad].
        method : {"exact", "brewe-hamrock-1977", "hamrock-brewe-1983"}
            Exact Hertz or a simplified ellipticity.

        Returns
        -------
        K_inner, K_outer, K_n : float or ndarray
            [N/m^1.5].

        References
        ----------
        Hamrock & Dowson (1981) eqs. (3.33)–(3.38); Ricci (2009) eqs. (15)–(16).

        Examples
        --------
        >>> import ballrace
        >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
        ...                            free_contact_angle=np.radians(40))
        >>> Ki, Ko, Kn = brg.contact_stiffness(np.radians(40))
        >>> round(float(Kn) / 1e9, 4)
        14.2471
        """
        Ep = self.E_prime
        ci = self.curvature("inner", contact_angle)
        co = self.curvature("outer", contact_angle)
        Ki = hertz.contact_stiffness(ci.Rx, ci.Ry, Ep, method)
        Ko = hertz.contact_stiffness(co.Rx, co.Ry, Ep, method)
        Kn = (Ki ** (-2.0 / 3.0) + Ko ** (-2.0 / 3.0)) ** -1.5
        return Ki, Ko, hertz.scalar_result(Kn)

    def contacts(self, ball_loads, contact_angles, race: str,
                 method: str = "exact") -> hertz.HertzContact:
        """Hertz contacts of the balls on one race (vectorized).

        Parameters
        ----------
        ball_loads : float or array_like
            Ball–race normal loads Q [N], >= 0.
        contact_angles : float or array_like
            Contact angles beta [rad], broadcast against ``ball_loads``.
        race : {"inner", "outer"}
            Which race.
        method : {"exact", "brewe-hamrock-1977", "hamrock-brewe-1983"}
            Exact Hertz or a simplified ellipticity.

        Returns
        -------
        hertz.HertzContact
            Semi-axes a, b [m], p_max [Pa], approach [m], ... per ball.

        References
        ----------
        Hamrock & Dowson (1981) eqs. (3.8)–(3.16); Ricci (2009) eqs. (12)–(14).

        Examples
        --------
        >>> import ballrace
        >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
        ...                            free_contact_angle=np.radians(40))
        >>> c = brg.contacts(9445.0, np.radians(44.317), "inner")
        >>> round(float(c.p_max) / 1e6)
        2640
        """
        broadcast(ball_loads=check_nonnegative(ball_loads, "ball_loads", "N", bounded=True),
                  contact_angles=as_array(contact_angles, "contact_angles"))
        c = self.curvature(race, contact_angles)
        return hertz.elliptical_contact(ball_loads, c.Rx, c.Ry, self.E_prime, method)

    def shoulder_angle(self, race: str):
        r"""Angle from the groove bottom to the shoulder edge, seen from the groove centre.

        .. math:: \theta_s = \arccos\left(1 - \frac{h_s}{f D}\right)

        Parameters
        ----------
        race : {"inner", "outer"}
            Which race.

        Returns
        -------
        float or None
            theta_s [rad], ``None`` when that shoulder height was not given.

        References
        ----------
        Hamrock & Dowson (1981) eq. (3.58) (form restored from the geometry; docs/sources.md), fig. 2.17.
        """
        check_choice(race, "race", RACES)
        h = self.shoulder_height_inner if race == "inner" else self.shoulder_height_outer
        if h is None:
            return None
        f = self.f_inner if race == "inner" else self.f_outer
        return float(np.arccos(1.0 - h / (f * self.ball_diameter)))

    # ------------------------------------------------------------------ load distribution
    def thrust(self, Fa, **kwargs):
        """Pure thrust load; see :func:`ballrace.analytic.loaddist.thrust`."""
        from .loaddist import thrust
        return thrust(self, Fa, **kwargs)

    def radial(self, Fr, clearance=None, azimuth_offset: float = 0.0, **kwargs):
        """Pure radial load; see :func:`ballrace.analytic.loaddist.radial`."""
        from .loaddist import radial
        return radial(self, Fr, clearance=clearance, azimuth_offset=azimuth_offset, **kwargs)

    def combined(self, Fr, Fa, **kwargs):
        """Combined radial and thrust load (Jones); see :func:`ballrace.analytic.loaddist.combined`."""
        from .loaddist import combined
        return combined(self, Fr, Fa, **kwargs)

    def eccentric_thrust(self, Fa, e, **kwargs):
        """Eccentric thrust (Ricci 2009); see :func:`ballrace.analytic.loaddist.eccentric_thrust`."""
        from .loaddist import eccentric_thrust
        return eccentric_thrust(self, Fa, e, **kwargs)

    def solve(self, Fa=0.0, Fy=0.0, Fz=0.0, My=0.0, Mz=0.0, **kwargs):
        """General five-degree-of-freedom load distribution; see :func:`ballrace.analytic.loaddist.solve`."""
        from .loaddist import solve
        return solve(self, Fa=Fa, Fy=Fy, Fz=Fz, My=My, Mz=Mz, **kwargs)

    # ------------------------------------------------------------------ ratings
    def dynamic_rating(self, standard: str = "ISO 281:2007"):
        """Basic dynamic load rating C [N]; see :func:`ballrace.analytic.ratings.dynamic_rating`."""
        from .ratings import dynamic_rating
        return dynamic_rating(self, standard=standard)

    def static_rating(self):
        """Basic static load rating C0 [N]; see :func:`ballrace.analytic.ratings.static_rating`."""
        from .ratings import static_rating
        return static_rating(self)

    # ------------------------------------------------------------------ shaft seat
    # The seat contract (ballrace.analytic.contract.SeatBearing): one ball row.  Plain
    # class attributes, not dataclass fields.
    accepts_clearance = True
    carries_axial = True
    life_exponent = 3.0
    seat_name = "single"

    def seat_rows(self, direction, offset, row_spacing, clearance):
        """The bearing as a shaft seat: its one row (a
        :class:`~ballrace.analytic.loaddist.RingModel`), centred at the seat; see
        :meth:`ballrace.analytic.contract.SeatBearing.seat_rows` (direction [-], offset
        [m], row_spacing [m], clearance [m] or None)."""
        from .contract import RowMount
        from .loaddist import RingModel
        if self.n_rows != 1:
            raise ValueError(f"bearing must be single-row (n_rows=1); got n_rows={self.n_rows}")
        return (RowMount(RingModel(self, clearance), direction, 0.0, offset, True),)

    def spring_axial_load(self, direction) -> float:
        """No spring inside a single bearing: 0 [N] (direction [-] unused)."""
        return 0.0

    def equivalent_load(self, radial_load, axial_load, contact_angle=None):
        """Dynamic equivalent load P [N] (ISO 281:2007, clause 6.2, X and Y from the
        geometry; :func:`ballrace.analytic.life.equivalent_load_for`), or None where the
        standard gives none; radial_load, axial_load [N], contact_angle [rad]."""
        from .life import equivalent_load_for
        try:
            return float(equivalent_load_for(self, radial_load, axial_load,
                                             contact_angle=contact_angle).P)
        except ValueError:
            return None

    def seat_warnings(self, what, results, tilt) -> tuple:
        """Static safety, contact angle and tilt messages of the seat
        (:func:`ballrace.analytic.loaddist.seat_warnings`); tilt [rad]."""
        from .loaddist import seat_warnings
        return seat_warnings(self, what, results, tilt)
