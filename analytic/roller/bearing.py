r"""Roller-bearing internal geometry (frozen :class:`RollerBearing`) and its load methods.

Two kinds, one row:

* ``"cylindrical"``: rollers of diameter D_we and effective length L_we between two
  cylindrical raceways; contact angle 0; carries radial loads and tilting moments.  Axial
  loads are carried by locating flanges (ribs) in NJ, NUP and NF designs: **the flanges
  are not modelled**, so an axial load on a cylindrical bearing is refused.
* ``"tapered"``: conical rollers between the cone (inner ring) and the cup (outer ring),
  all apexes on one point of the bearing axis (true rolling).  ``contact_angle`` is the
  cup angle alpha_o (the angle between the outer raceway's normal and the radial plane,
  equal to the cup's half-cone angle); D_we is the roller diameter at the middle of its
  length.  The roller's half-angle gamma, the roller axis angle alpha_m, the cone angle
  alpha_i and the rib angle alpha_f follow from the apex condition (below); the cone's
  large-end rib holds the roller.

Tapered roller geometry (apex condition)
----------------------------------------
With the roller centre at the pitch radius d_m/2 and its axis at alpha_m to the bearing
axis, the roller's apex on the bearing axis is (d_m/2)/sin(alpha_m) from its centre, so

.. math:: \tan\gamma = \frac{D_{we}}{d_m}\sin\alpha_m, \qquad
          \alpha_m = \alpha_o - \gamma, \qquad \alpha_i = \alpha_o - 2\gamma,
          \qquad \alpha_f = \pi/2 - \alpha_m

(the rib face normal along the roller axis, through the roller's end face centre).  The
roller's own equilibrium at low speed (no centrifugal or gyroscopic load) gives the cone
and rib loads from the cup load Q_o (Harris & Kotzalas, *Advanced Concepts of Bearing
Technology*, 2007, ch. 1, the static equilibrium of a tapered roller; the chapter and
equation numbers were not checked against the book):

.. math:: Q_i = Q_o\frac{\sin(\alpha_o + \alpha_f)}{\sin(\alpha_i + \alpha_f)}, \qquad
          Q_f = Q_o\frac{\sin(\alpha_o - \alpha_i)}{\sin(\alpha_i + \alpha_f)}

(re-derived here from the axial and radial force balance of the roller).  Since the
roller is in equilibrium, the cone and its rib together receive exactly the cup's force on
the roller: the inner ring's equilibrium is written with Q_o at the cup angle.

Clearance
---------
``diametral_clearance`` P_d is, for both kinds, the radial free movement of the inner ring
from contact on one side to contact on the other with the rings axially in their reference
position: each roller has the normal gap (P_d/2) cos(alpha_o) at zero displacement.  For a
tapered bearing the same gap is closed by an axial movement of the cone into the cup of
:attr:`RollerBearing.axial_clearance` = P_d / (2 tan alpha_o) (the end play of the single
bearing from its reference position); a negative P_d is an interference (preload).

Coordinates are those of :mod:`ballrace.analytic.loaddist`: x is the bearing axis, y and z
radial, roller j at azimuth psi_j from +y towards +z; loads (Fa, Fy, Fz, My, Mz) act on the
inner ring, moments right-handed about the bearing centre.  A positive Fa presses a
tapered bearing's cone into its cup.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from .. import plausible
from .._checks import (as_array, check_choice, check_range, scalar_count, scalar_positive,
                       store_checked)
from ..materials import BEARING_STEEL, Material, effective_modulus
from . import lamina
from .profile import ProfileContext, as_profile

__all__ = ["RollerBearing", "KINDS", "STATIC_PRESSURE", "PERMISSIBLE_MISALIGNMENT",
           "EDGE_LOAD_RATIO", "edge_load_ratio"]

#: Kinds of roller bearing.
KINDS = ("cylindrical", "tapered")

#: Contact pressure at the static rating of roller bearings, ISO 76:2006 §5.1 [Pa]: the
#: design load of a logarithmic profile given by name (see :class:`RollerBearing`).
STATIC_PRESSURE = 4000e6

#: Largest roller diameter / length that is not warned about as a unit slip [m].
LARGEST_ROLLER = 0.3

#: Permissible misalignment (tilt of the inner ring relative to the outer ring) of a
#: single-row roller bearing [rad], above which a shaft seat warns
#: (:meth:`RollerBearing.seat_warnings`):
#:
#: * ``"cylindrical"``: 4 arcmin = 1.16 mrad, "0.0012 radian (4 arcminutes) for cylindrical
#:   roller bearings" (Pumps & Systems, *Prevent Bearing Misalignment*, as a general
#:   acceptable alignment); manufacturers' guides give 1 to 4 arcmin depending on the series
#:   (Autodesk Inventor's bearing generator uses 6 arcmin for the NU2, NU3, NU4 series);
#: * ``"tapered"``: 2 arcmin = 0.58 mrad, the value of the table "Permissible bearing tilt"
#:   of the Autodesk Inventor help for single-row tapered roller bearings.
#:
#: Guide values from secondary sources; the manufacturers' catalogues themselves were not
#: read here.  Beyond them a roller runs edge loaded, which the lamina model shows in its
#: end slices (:data:`EDGE_LOAD_RATIO`) but whose edge stress peak it does not resolve.
PERMISSIBLE_MISALIGNMENT = {"cylindrical": float(np.radians(4.0 / 60.0)),
                            "tapered": float(np.radians(2.0 / 60.0))}

#: Edge loading a seat warns about [-]: an end slice of a roller carrying more than this
#: multiple of the mean slice load Q_max / n_s of the most loaded roller (1 for straight
#: rollers without tilt, below 1 for crowned ones; cf.
#: :attr:`~ballrace.analytic.roller.loaddist.RollerLoadDistribution.edge_load_ratio`, per
#: roller).  A screening value chosen
#: here, not a standard's: the lamina model has no edge stress peak, so a loaded roller end
#: means a real pressure above the lamina's there (``roller_contact`` solves it).
EDGE_LOAD_RATIO = 1.5




def _half_angle(k: float, alpha_o: float) -> float:
    """Roller half-angle gamma from tan(gamma) = k sin(alpha_o - gamma), k = D_we/d_m."""
    g = 0.0
    for _ in range(200):                 # a contraction (|derivative| <= k < 1)
        g_new = math.atan(k * math.sin(alpha_o - g))
        if abs(g_new - g) <= 1e-16:
            return g_new
        g = g_new
    return g


@dataclass(frozen=True)
class RollerBearing:
    r"""Internal geometry and material of a single-row roller bearing (frozen).

    Parameters
    ----------
    roller_diameter : float
        Roller diameter D_we [m] (tapered: at the middle of the roller), in
        (0, pitch_diameter).
    roller_length : float
        Effective contact length L_we [m] (the length without the end chamfers).
    n_rollers : int
        Number of rollers Z [-], >= 3, no more than fit on the pitch circle,
        Z arcsin(D_we/d_m) <= pi (rollers touching at the pitch circle).
    pitch_diameter : float
        Pitch diameter d_m [m] (of the roller centres), > D_we.
    kind : {"cylindrical", "tapered"}
        Bearing kind (module notes).
    contact_angle : float
        Cylindrical: 0 (the only value).  Tapered: the cup angle alpha_o [rad], in
        (0, pi/3) (catalogue tapered bearings have 10-30 deg).
    diametral_clearance : float
        Diametral clearance P_d [m] (module notes), |P_d| < D_we/10; negative: interference.
    profile : str, Profile or (array_like, array_like)
        Roller profile (:func:`~ballrace.analytic.roller.profile.as_profile`): ``"iso"``
        (ISO/TS 16281's default, the default here), ``"straight"``, ``"lundberg"``,
        ``"johns-gohar"``, a ``Crowned(...)`` or an ``(x, drop)`` table [m].  It is the
        drop at one contact; the lamina model sees it twice.  A logarithmic profile given
        by name is designed for :attr:`design_load`.
    n_slices : int, optional
        Number of slices of the lamina model [-], odd, >= 5; default
        :data:`~ballrace.analytic.roller.lamina.DEFAULT_SLICES` (31).  A warning when the
        slices do not resolve the profile
        (:func:`~ballrace.analytic.roller.lamina.check_resolution`).
    material : Material, optional
        Material of rollers and rings (default :data:`~ballrace.BEARING_STEEL`).
    stiffness : {"iso", "palmgren"}
        Lamina stiffness law (:mod:`~ballrace.analytic.roller.lamina`); default ISO/TS 16281.
    n_rows : int, optional
        Number of rows i [-] for the load ratings (the load distribution handles one row:
        :meth:`solve` refuses more).  Default 1.
    name : str, optional
        Label for reports.
    rib_angle : float, optional
        Tapered: the rib contact angle alpha_f [rad] (the angle of the rib's normal force
        to the radial plane), in (0, pi/2).  Default ``None``: pi/2 - alpha_m, the rib
        normal along the roller axis (then Q_i = Q_o and Q_f = 2 Q_o sin(gamma)).
        Cylindrical: must be ``None``.

    Notes
    -----
    Load ratings: :meth:`dynamic_rating` (ISO 281 C_r) and :meth:`static_rating` (ISO 76
    C_0r) from :mod:`~ballrace.analytic.roller.ratings`; the ISO/TS 16281 reference rating
    life of a solution: :meth:`reference_rating_life` (also reached through
    :func:`ballrace.analytic.life.reference_rating_life`).

    Examples
    --------
    A cylindrical roller bearing of the NU 207 size class (the numbers of the public
    example, not a catalogue's):

    >>> from ballrace.analytic.roller import RollerBearing
    >>> b = RollerBearing(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=14,
    ...                   pitch_diameter=70.65e-3, diametral_clearance=45e-6)
    >>> b.kind, b.n_slices, round(b.slice_width * 1e3, 4)
    ('cylindrical', 31, 0.3806)
    >>> round(b.lamina_stiffness / 1e6, 2)      # 35 948e6 L_we^(8/9) [N/m^(10/9)]
    694.69

    A tapered bearing with a 15 deg cup:

    >>> t = RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered",
    ...                   contact_angle=np.radians(15))
    >>> round(float(np.degrees(t.cone_angle)), 3), round(float(np.degrees(t.rib_contact_angle)), 3)
    (10.747, 77.127)
    """

    roller_diameter: float
    roller_length: float
    n_rollers: int
    pitch_diameter: float
    kind: str = "cylindrical"
    contact_angle: float = 0.0
    diametral_clearance: float = 0.0
    profile: object = "iso"
    n_slices: int | None = None
    material: Material = BEARING_STEEL
    stiffness: str = "iso"
    n_rows: int = 1
    name: str = ""
    rib_angle: float | None = None

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        D = scalar_positive(self.roller_diameter, "roller_diameter", "m")
        L = scalar_positive(self.roller_length, "roller_length", "m")
        dm = scalar_positive(self.pitch_diameter, "pitch_diameter", "m")
        plausible.length(D, "roller_diameter", LARGEST_ROLLER, "roller", stacklevel=4)
        plausible.length(L, "roller_length", LARGEST_ROLLER, "roller", stacklevel=4)
        plausible.length(dm, "pitch_diameter", 10.0, "rolling bearing", stacklevel=4)
        if not D < dm:
            raise ValueError(f"roller_diameter must be in (0, pitch_diameter) = (0, {dm:g}) "
                             f"[m]; got {D:g}")
        Z = scalar_count(self.n_rollers, "n_rollers", 3)
        z_max = int(np.floor(np.pi / np.arcsin(D / dm) * (1 + 1e-12)))
        if Z > z_max:
            raise ValueError(f"n_rollers must be in [3, {z_max}] for D_we = {D:g} m on a pitch "
                             f"diameter of {dm:g} m (Z arcsin(D_we/d_m) <= pi: the rollers "
                             f"must fit on the pitch circle); got {Z}")
        kind = check_choice(self.kind, "kind", KINDS)
        a = as_array(self.contact_angle, "contact_angle", unit="rad")
        if a.ndim:
            raise TypeError(f"contact_angle must be a scalar [rad]; got an array of shape "
                            f"{a.shape}")
        a = float(a)
        if kind == "cylindrical" and a != 0.0:
            raise ValueError(f"contact_angle of a cylindrical roller bearing must be 0 [rad]; "
                             f"got {a!r} (give kind='tapered' for a tapered bearing)")
        if kind == "tapered" and not 0.0 < a < np.pi / 3:
            hint = (f" ({a:g} looks like degrees: pass numpy.radians({a:g}))"
                    if 1.0 < a < 90.0 else "")
            raise ValueError(f"contact_angle (the cup angle) of a tapered roller bearing must "
                             f"be in (0, {np.pi / 3:.6g}) [rad], typically 10-30 deg; got "
                             f"{a!r}{hint}")
        pd = as_array(self.diametral_clearance, "diametral_clearance", unit="m")
        if pd.ndim:
            raise TypeError("diametral_clearance must be a scalar [m]; got an array of shape "
                            f"{pd.shape}")
        pd = float(pd)
        if not abs(pd) < 0.1 * D:
            raise ValueError(f"diametral_clearance must be in (-{0.1 * D:g}, {0.1 * D:g}) [m] "
                             f"(|P_d| < D_we/10; catalogue clearances are some 10-200 um, "
                             f"e.g. 45e-6); got {pd:g}"
                             + (f" (were micrometres given? {pd:g} um is {pd * 1e-6:g} m)"
                                if abs(pd) >= 1.0 else ""))
        if not isinstance(self.material, Material):
            raise TypeError(f"material must be a ballrace.Material; got "
                            f"{type(self.material).__name__}")
        check_choice(self.stiffness, "stiffness", lamina.STIFFNESS_LAWS)
        n_s = lamina.check_slices(self.n_slices)
        rib = self.rib_angle
        if rib is not None:
            if kind != "tapered":
                raise ValueError(f"rib_angle is for tapered bearings (the flanges of a "
                                 f"cylindrical bearing are not modelled); got {rib!r}")
            rib = float(check_range(rib, "rib_angle", 0.0, 0.5 * np.pi, unit="rad"))
            set_(self, "rib_angle", rib)
        prof = as_profile(self.profile)
        store_checked(self, roller_diameter=D, roller_length=L, pitch_diameter=dm, n_rollers=Z,
                      contact_angle=a, diametral_clearance=pd, n_slices=n_s, profile=prof,
                      n_rows=scalar_count(self.n_rows, "n_rows", 1))
        drops = prof.drop(self.slice_positions, self.profile_context)   # checks the fit
        if not np.all(np.isfinite(drops)):
            raise ValueError("the profile's drop is not finite at every slice centre")
        lamina.check_resolution(drops, n_s, f"the {prof.name} profile")

    # ------------------------------------------------------------------ geometry
    @property
    def tapered(self) -> bool:
        """True for a tapered roller bearing."""
        return self.kind == "tapered"

    @property
    def roller_half_angle(self) -> float:
        """Half-angle gamma of the roller cone [rad] (0 for a cylindrical roller)."""
        if not self.tapered:
            return 0.0
        return _half_angle(self.roller_diameter / self.pitch_diameter, self.contact_angle)

    @property
    def roller_axis_angle(self) -> float:
        """Angle alpha_m of the roller axis to the bearing axis, alpha_o - gamma [rad]."""
        return self.contact_angle - self.roller_half_angle

    @property
    def cone_angle(self) -> float:
        """Cone (inner raceway) angle alpha_i = alpha_o - 2 gamma [rad] (module notes)."""
        return self.contact_angle - 2.0 * self.roller_half_angle

    @property
    def rib_contact_angle(self) -> float:
        """Rib contact angle alpha_f [rad]: ``rib_angle`` if given, else pi/2 - alpha_m (rib
        normal along the roller axis; module notes).  ``nan`` for a cylindrical bearing
        (no rib modelled)."""
        if not self.tapered:
            return math.nan
        if self.rib_angle is not None:
            return self.rib_angle
        return 0.5 * np.pi - self.roller_axis_angle

    @property
    def inner_load_ratio(self) -> float:
        """Q_i / Q_o = sin(alpha_o + alpha_f) / sin(alpha_i + alpha_f) [-] (1 cylindrical)."""
        if not self.tapered:
            return 1.0
        af = self.rib_contact_angle
        return math.sin(self.contact_angle + af) / math.sin(self.cone_angle + af)

    @property
    def rib_load_ratio(self) -> float:
        """Q_f / Q_o = sin(alpha_o - alpha_i) / sin(alpha_i + alpha_f) [-] (0 cylindrical)."""
        if not self.tapered:
            return 0.0
        return (math.sin(self.contact_angle - self.cone_angle)
                / math.sin(self.cone_angle + self.rib_contact_angle))

    @property
    def axial_clearance(self) -> float:
        """Axial movement of the cone into the cup that closes the clearance,
        P_d / (2 tan alpha_o) [m] (tapered; ``inf`` for a cylindrical bearing)."""
        if not self.tapered:
            return math.inf
        return 0.5 * self.diametral_clearance / math.tan(self.contact_angle)

    @property
    def gamma(self) -> float:
        """gamma = D_we cos(alpha_o) / d_m [-]."""
        return self.roller_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    @property
    def inner_radius(self) -> float:
        """Reduced radius of the inner contact in the rolling direction,
        R_i = D_we (1 - gamma)/2 [m] (tapered: at the middle of the roller, the
        cylindrical form applied to the mean diameter)."""
        return 0.5 * self.roller_diameter * (1.0 - self.gamma)

    @property
    def outer_radius(self) -> float:
        """Reduced radius of the outer contact in the rolling direction,
        R_o = D_we (1 + gamma)/2 [m]."""
        return 0.5 * self.roller_diameter * (1.0 + self.gamma)

    @property
    def E_prime(self) -> float:
        """Contact modulus E' of roller and rings [Pa] (Hamrock–Dowson, 2 E*)."""
        return float(effective_modulus(self.material, self.material))

    @property
    def design_load(self) -> float:
        r"""Design load Q_d of a logarithmic profile given by name [N].

        The roller load at which the inner contact (the smaller radius) of a roller
        with uniform line load reaches the static-rating pressure of ISO 76:2006,
        p0 = 4000 MPa: from p0 = sqrt(Q E' / (2 pi R_i L_we)),

        .. math:: Q_d = 2\pi R_i L_{we}\,p_0^2 / E'.

        A profile designed for this load has no edge stress up to the static capacity.
        A different design load: ``profile=Lundberg(design_load=...)``.
        """
        return (2.0 * math.pi * self.inner_radius * self.roller_length * STATIC_PRESSURE ** 2
                / self.E_prime)

    @property
    def profile_context(self) -> ProfileContext:
        """The contact the profile is evaluated in: L_we, D_we, E', the outer contact's
        reduced radius R_o, and :attr:`design_load`."""
        return ProfileContext(length=self.roller_length, diameter=self.roller_diameter,
                              E_prime=self.E_prime, R=self.outer_radius, load=self.design_load)

    @property
    def slice_width(self) -> float:
        """Slice width L_we / n_s [m]."""
        return self.roller_length / self.n_slices

    @property
    def slice_positions(self) -> np.ndarray:
        """Slice centres x_k from the roller centre [m], shape (n_slices,)."""
        return lamina.slice_positions(self.roller_length, self.n_slices)

    @functools.cached_property
    def slice_drops(self) -> np.ndarray:
        """Profile drop P(x_k) at the slice centres, one contact [m], shape (n_slices,)."""
        d = self.profile.drop(self.slice_positions, self.profile_context)
        d.setflags(write=False)
        return d

    @property
    def lamina_stiffness(self) -> float:
        """Whole-roller stiffness c_L of the lamina model [N/m^(10/9)]
        (:func:`~ballrace.analytic.roller.lamina.lamina_stiffness`)."""
        return lamina.lamina_stiffness(self.roller_length, self.E_prime, self.stiffness)

    def azimuths(self, azimuth_offset: float = 0.0) -> np.ndarray:
        """Roller azimuths psi_j = offset + 2 pi j/Z, j = 0..Z-1 [rad].

        Parameters
        ----------
        azimuth_offset : float
            Azimuth of roller 0 from the +y axis [rad].
        """
        off = float(as_array(azimuth_offset, "azimuth_offset", unit="rad"))
        return off + 2.0 * np.pi * np.arange(self.n_rollers) / self.n_rollers

    @property
    def inner_raceway_radius(self) -> float:
        """Radius of the inner raceway in the rolling direction at the middle of the roller,
        D_we (1 - gamma) / (2 gamma) [m] ((d_m - D_we)/2 for a cylindrical bearing): with the
        roller's D_we/2 it gives :attr:`inner_radius`."""
        g = self.gamma
        return 0.5 * self.roller_diameter * (1.0 - g) / g

    @property
    def outer_raceway_radius(self) -> float:
        """Radius of the outer raceway in the rolling direction, negative (concave),
        -D_we (1 + gamma) / (2 gamma) [m] (-(d_m + D_we)/2 for a cylindrical bearing): with
        the roller's D_we/2 it gives :attr:`outer_radius`."""
        g = self.gamma
        return -0.5 * self.roller_diameter * (1.0 + g) / g

    # ------------------------------------------------------------------ ratings and life
    def dynamic_rating(self) -> float:
        r"""Basic dynamic radial load rating C_r of ISO 281:2007 [N].

        .. math:: C_r = b_m\, f_c\, (i\, L_{we}\cos\alpha)^{7/9} Z^{3/4} D_{we}^{29/27}

        (N, mm inside) with b_m = 1.1 (cylindrical and tapered roller bearings, ISO 281:2007
        Table 1), f_c from Lundberg & Palmgren's line-contact expression at
        gamma = D_we cos(alpha)/d_m (:func:`~ballrace.analytic.roller.ratings.fc_factor`),
        i = :attr:`n_rows`, alpha = :attr:`contact_angle` (0 cylindrical, the cup angle of a
        tapered bearing), L_we = :attr:`roller_length`, D_we = :attr:`roller_diameter` (the
        mean diameter of a tapered roller).  Both kinds are rated as radial bearings.

        What was checked (:mod:`~ballrace.analytic.roller.ratings`): the f_c expression
        against the ISO/TS 16281 raceway capacities and Lundberg & Palmgren's raceway
        capacity (0.5 %), and the catalogue ratings of seven cylindrical roller bearings
        (Oswald, Zaretsky & Poplawski, NASA/TM-2012-217115, 2012, Table III), recomputed
        to +0.6 ... +0.9 % with L_we taken from the catalogue C_0r (also a validation case,
        ``validation/cases/roller.toml``).  The printed f_c table of ISO 281 was not read.

        Examples
        --------
        >>> from ballrace.analytic.roller import RollerBearing
        >>> round(RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3).dynamic_rating())
        75809
        """
        from . import ratings

        return float(ratings.dynamic_rating(self.roller_diameter, self.roller_length,
                                            self.n_rollers, self.pitch_diameter,
                                            self.contact_angle, self.n_rows,
                                            b_m=ratings.B_M[self.kind]))

    def static_rating(self) -> float:
        r"""Basic static radial load rating C_0r of ISO 76:2006 [N].

        .. math:: C_{0r} = 44\left(1 - \frac{D_{we}\cos\alpha}{d_m}\right)
                  i\, Z\, L_{we}\, D_{we}\cos\alpha

        (N, mm inside; :func:`~ballrace.analytic.roller.ratings.static_rating`), radial for
        both kinds.  Checked: with ISO 76's most loaded roller, Q_max = 5 C_0r/(i Z cos a),
        on a straight roller the inner contact reaches 3991 MPa for every geometry (the
        4000 MPa of the definition; 44 is 44.2 rounded,
        :func:`~ballrace.analytic.roller.ratings.static_rating_pressure`).  The static safety
        of an actual load distribution is
        :attr:`RollerLoadDistribution.static_safety
        <ballrace.analytic.roller.loaddist.RollerLoadDistribution.static_safety>`.

        Examples
        --------
        >>> from ballrace.analytic.roller import RollerBearing
        >>> round(RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3).static_rating())
        77107
        """
        from . import ratings

        return float(ratings.static_rating(self.roller_diameter, self.roller_length,
                                           self.n_rollers, self.pitch_diameter,
                                           self.contact_angle, self.n_rows))

    def reference_rating_life(self, result, *, dynamic_rating=None, rotating: str = "inner"):
        """ISO/TS 16281 basic reference rating life L10r of a solution of this bearing.

        :func:`ballrace.analytic.roller.life.reference_rating_life` with the slice loads of
        ``result`` (the cup's, and the cone's where they differ: ``slice_loads_inner``);
        :func:`ballrace.analytic.life.reference_rating_life` hands a roller bearing to this
        method.

        Parameters
        ----------
        result : RollerLoadDistribution
            A solution of this bearing (:meth:`solve`).
        dynamic_rating : float, optional
            C [N]; default :meth:`dynamic_rating`.
        rotating : {"inner", "outer"}
            Ring rotating relative to the load.

        Returns
        -------
        ballrace.analytic.roller.life.ReferenceRatingLife
        """
        from . import life

        bearing = getattr(result, "bearing", self)
        if bearing is not self and bearing != self:
            raise ValueError("result is the solution of another bearing: solve this bearing "
                             "(bearing.solve(...)) and pass its result")
        return life.reference_rating_life(self, result, dynamic_rating=dynamic_rating,
                                          rotating=rotating)

    # ------------------------------------------------------------------ load distribution
    def solve(self, Fa=0.0, Fy=0.0, Fz=0.0, My=0.0, Mz=0.0, **kwargs):
        """Five-degree-of-freedom lamina load distribution; see
        :func:`ballrace.analytic.roller.loaddist.solve`."""
        from .loaddist import solve
        return solve(self, Fa=Fa, Fy=Fy, Fz=Fz, My=My, Mz=Mz, **kwargs)


    # ------------------------------------------------------------------ shaft seat
    # The seat contract (ballrace.analytic.contract.SeatBearing): one roller row
    # (loaddist.RollerRow).  Plain class attributes, not dataclass fields.
    accepts_clearance = True
    life_exponent = 10.0 / 3.0          # ISO 281:2007, roller bearings
    #: Weibull slope e of roller bearings for the system life (Lundberg & Palmgren 1952;
    #: ISO 281:2007, the life adjustment factor for reliability of roller bearings).
    weibull_slope = 9.0 / 8.0

    @property
    def carries_axial(self) -> bool:
        """False for a cylindrical bearing (its flanges are not modelled: a seat with it
        does not locate the shaft), True for a tapered one."""
        return self.tapered

    @property
    def seat_name(self) -> str:
        """"cylindrical" or "tapered" (for tables)."""
        return self.kind

    def seat_rows(self, direction, offset, row_spacing, clearance):
        """The bearing as a shaft seat: its one row (a
        :class:`~ballrace.analytic.roller.loaddist.RollerRow`), centred at the seat; see
        :meth:`ballrace.analytic.contract.SeatBearing.seat_rows` (direction [-], offset
        [m] beyond the just-touching position, row_spacing [m], clearance [m] or None)."""
        from ..contract import RowMount
        from .loaddist import RollerRow

        if self.n_rows != 1:
            raise ValueError(f"bearing must be single-row (n_rows=1) to be a shaft seat; got "
                             f"n_rows={self.n_rows}")
        return (RowMount(RollerRow(self, clearance), direction, 0.0, offset, True),)

    def spring_axial_load(self, direction) -> float:
        """No spring inside a single bearing: 0 [N] (direction [-] unused)."""
        return 0.0

    def equivalent_load(self, radial_load, axial_load, contact_angle=None):
        """Dynamic equivalent radial load P_r [N] of the catalog life (ISO 281:2007):
        cylindrical P_r = F_r (the seat carries no axial load), tapered X F_r + Y F_a
        (:func:`~ballrace.analytic.roller.ratings.dynamic_equivalent_load`, single row).
        radial_load, axial_load [N]; contact_angle [rad] must be None (the bearing's)."""
        from . import ratings

        if contact_angle is not None and float(contact_angle) != self.contact_angle:
            raise ValueError("nominal_contact_angle is for ball bearings; a roller bearing "
                             f"is rated at its own contact angle; got {contact_angle!r}")
        if not self.tapered:
            return float(radial_load)
        return float(ratings.dynamic_equivalent_load(radial_load, axial_load,
                                                     self.contact_angle, 1))

    @property
    def permissible_misalignment(self) -> float:
        """Tilt of the inner ring against the outer ring the bearing tolerates [rad]
        (:data:`PERMISSIBLE_MISALIGNMENT` of its kind)."""
        return PERMISSIBLE_MISALIGNMENT[self.kind]

    def seat_warnings(self, what, results, tilt) -> tuple:
        """Messages (str or None) for the seat's rows (``results``: their
        :class:`~ballrace.analytic.roller.loaddist.RollerLoadDistribution`): static safety
        below 1, a tilt beyond :attr:`permissible_misalignment`, edge-loaded rollers
        (:func:`seat_tilt_messages`); ``what`` names the seat, tilt [rad]."""
        return (seat_safety_message(what, results),
                *seat_tilt_messages(what, self, results, tilt))


def seat_tilt_messages(what: str, bearing, results, tilt) -> tuple:
    """(tilt message, edge message), each str or None, for a roller seat: the ring tilt
    [rad] beyond :data:`PERMISSIBLE_MISALIGNMENT` of ``bearing``'s kind (a
    :class:`RollerBearing`), and the end slice of a roller (any of ``results``, roller load
    distributions) carrying more than :data:`EDGE_LOAD_RATIO` times the mean slice load of
    the most loaded roller; ``what`` names the seat."""
    lim = PERMISSIBLE_MISALIGNMENT[bearing.kind]
    t = float(np.max(tilt)) if np.size(tilt) else 0.0
    ratio = max((edge_load_ratio(r.slice_loads) for r in results), default=0.0)
    if t > lim:
        return (f"{what}: the inner ring is tilted {t * 1e3:.3g} mrad "
                f"({math.degrees(t) * 60:.3g} arcmin) against the outer ring, more than the "
                f"{math.degrees(lim) * 60:.0f} arcmin ({lim * 1e3:.2f} mrad) a {bearing.kind} "
                "roller bearing tolerates (roller.bearing.PERMISSIBLE_MISALIGNMENT, guide "
                "values): expect a shorter life; roller end slices carry up to "
                f"{ratio:.3g} times the most loaded roller's mean slice load (edge loading "
                f"above {EDGE_LOAD_RATIO:g}, with an edge stress the lamina model does not "
                "resolve)"), None
    if ratio > EDGE_LOAD_RATIO:
        return None, (f"{what}: edge-loaded rollers: an end slice carries {ratio:.3g} times "
                      f"the most loaded roller's mean slice load (above {EDGE_LOAD_RATIO:g}) "
                      f"at a tilt of {t * 1e3:.3g} mrad, within the permissible misalignment: the "
                      "roller ends see an edge stress the lamina model does not resolve "
                      "(check the profile, or solve the roller's line contact: "
                      "RollerLoadDistribution.roller_contact)")
    return None, None


def edge_load_ratio(q) -> float:
    """Edge loading of a roller set [-]: the largest end-slice load of any roller over the
    mean slice load Q_max / n_s of the most loaded roller, of slice loads q (..., Z, n_s)
    [N] (0 without load): 1 for straight rollers without tilt; a lightly loaded roller
    touching at one end only counts no more than its load."""
    q = np.asarray(q, float)
    Qmax = float(q.sum(-1).max(initial=0.0))
    if not Qmax > 0:
        return 0.0
    end = float(np.maximum(q[..., 0], q[..., -1]).max())
    return end / (Qmax / q.shape[-1])


def seat_safety_message(what: str, results) -> str | None:
    """A message when the most loaded slice of any of ``results`` (roller load
    distributions) has a static safety below 1 (ISO 76: 4000 MPa), else None; ``what``
    names the seat."""
    s0 = min((float(np.min(r.static_safety)) for r in results), default=math.inf)
    if not s0 < 1.0:
        return None
    p = max(float(np.max(r.max_pressure)) for r in results)
    return (f"{what}: static safety s0 = {s0:.3g} < 1: the most loaded slice of the lamina "
            f"model reaches p_max = {p / 1e6:.0f} MPa, above the 4000 MPa on which ISO 76 "
            "bases C_0r of roller bearings (s0 = (4000 MPa / p_max)^2)")
