r"""Roller profiles: the drop of a roller's surface along its length.

A roller (or its raceway) is not a perfect cylinder: it is *crowned* so that the contact
pressure does not peak at the roller ends.  A profile gives the **drop** ``P(x)`` [m] of
the roller surface below the cylinder through its centre, at the axial position ``x`` [m]
measured from the roller centre, at *one* raceway contact.  Where both the roller and the
raceway are crowned, ``P`` is their sum (the gap the contact sees).

Every model of ballrace that needs a profile takes the same objects:

* the sliced (lamina) contact of ISO/TS 16281 in the roller-bearing load distribution,
  where a roller between two raceways sees the drop twice (``delta_k = delta - 2 P(x_k)
  - x_k tan psi``);
* the finite line contact on the elastic half-space (:func:`ballrace.analytic.roller.line_contact`)
  and its FE check, which see it once.

Profiles
--------
========================  ================================================================
``"straight"``            :class:`Straight`: no crown (a sharp edge: an edge peak that
                          grows without bound on a half-space).
``"iso"``                 :class:`ISO`: the default profile of ISO/TS 16281, used when the
                          real profile is not known.
:class:`Crowned`          a circular crown: a flat middle part and circular arcs.
``"lundberg"``            :class:`Lundberg`: Lundberg's logarithmic profile, uniform
                          pressure along the roller at its design load.
``"johns-gohar"``         :class:`JohnsGohar`: the Johns–Gohar logarithmic profile (a
                          finite drop at the roller end).
``(x, drop)`` arrays      :class:`Table`: a measured or drawn profile.
========================  ================================================================

A name or an object is turned into a profile by :func:`as_profile`; the profile is then
evaluated with the contact it sits in (:class:`ProfileContext`: the effective length, the
roller diameter, the contact modulus, the reduced radius and the design load), because
ISO's default profile scales with the roller diameter and the logarithmic profiles with
the load they are designed for.

Within the effective length, ``|x| < L/2``, the drop is finite (the logarithmic profiles
reach infinity only *at* the end, where no slice centre lies); at and beyond the roller
end, ``|x| >= L/2``, :meth:`Profile.drop` returns ``inf``: there is no roller there.

References
----------
* ISO/TS 16281:2008, *Rolling bearings — Methods for calculating the modified reference
  rating life for universally loaded bearings*, the default roller profile (its
  eqs. 42–44).  The short-roller form below (``L_we <= 2.5 D_we``) is the form reproduced
  by the open-source implementations and the secondary literature; the long-roller form
  (a flat middle part with the short-roller ends) is reconstructed from that description
  and was not checked against the standard's text.
* G. Lundberg, *Elastische Berührung zweier Halbräume*, Forschung auf dem Gebiete des
  Ingenieurwesens 10 (1939) 201–211: the crown ``(q / (pi E*)) ln[1 / (1 - (2x/L)^2)]``,
  ``q = Q/L``, ``E*`` the plane-strain contact modulus (``E' / 2``), gives a uniform
  pressure ``p0 = sqrt(q E* / (pi R))`` along the roller on a half-space.
* P. M. Johns and R. Gohar, *Roller bearings under radial and eccentric loads*,
  Tribology International 14 (1981) 131–136: the logarithmic crown with the Hertz
  half-width ``b`` in it, finite at the roller end.  Written here with Lundberg's
  factor, so that the two coincide as ``b/L -> 0`` (the original paper was not read; the
  form follows H. Fujiwara and T. Kawase, *Logarithmic profiles of rollers in roller
  bearings and optimization of the profiles*, NTN Technical Review 75 (2007)).

Examples
--------
>>> from ballrace.analytic.roller import profile as rp
>>> ctx = rp.ProfileContext(length=0.012, diameter=0.012, E_prime=2.2857e11, R=0.005,
...                         load=5000.0)
>>> p = rp.as_profile("iso")
>>> round(float(p.drop(0.0, ctx)), 12), round(float(p.drop(0.005, ctx)) * 1e6, 2)  # [m], [um]
(0.0, 4.98)
>>> float(rp.as_profile("straight").drop(0.006, ctx))        # at the roller end: no roller
inf
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import plausible
from .._checks import as_array, check_positive

__all__ = [
    "PROFILE_NAMES",
    "ISO_LONG_ROLLER",
    "ProfileContext",
    "Profile",
    "Straight",
    "ISO",
    "Crowned",
    "Lundberg",
    "JohnsGohar",
    "Table",
    "as_profile",
]

#: Profiles that can be given by name (:func:`as_profile`).
PROFILE_NAMES = ("straight", "iso", "lundberg", "johns-gohar")

#: ISO/TS 16281's default profile changes form beyond this ratio L_we / D_we [-].
ISO_LONG_ROLLER = 2.5

#: Coefficient of ISO/TS 16281's default profile, P = 0.00035 D_we ln[...] [-].
ISO_COEFFICIENT = 0.00035

#: A table must reach this fraction of the half-length from the centre on each side.
TABLE_REACH = 0.95


@dataclass(frozen=True)
class ProfileContext:
    """The contact a profile is evaluated in (frozen).

    Parameters
    ----------
    length : float
        Effective contact length L_we of the roller [m].
    diameter : float
        Roller diameter D_we [m] (the ISO profile scales with it).
    E_prime : float
        Contact modulus E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2] [Pa] (the logarithmic
        profiles).
    R : float
        Reduced radius of the contact in the rolling direction [m] (the Johns–Gohar
        profile's Hertz half-width).
    load : float
        Design load of a logarithmic profile given without one [N]: the contact's own
        load in :func:`~ballrace.analytic.roller.line_contact`; the bearing's choice
        (stated in its documentation) in a roller bearing.
    """

    length: float
    diameter: float
    E_prime: float = math.nan
    R: float = math.nan
    load: float = math.nan

    def __post_init__(self) -> None:
        for name, unit in (("length", "m"), ("diameter", "m")):
            v = float(check_positive(getattr(self, name), name, unit, bounded=True))
            object.__setattr__(self, name, v)
        for name, unit in (("E_prime", "Pa"), ("R", "m"), ("load", "N")):
            v = float(getattr(self, name))
            if not math.isnan(v):
                v = float(check_positive(v, name, unit, bounded=True))
            object.__setattr__(self, name, v)

    def need(self, *names: str, profile: str) -> None:
        """ValueError when a quantity the profile needs was not given."""
        missing = [n for n in names if math.isnan(getattr(self, n))]
        if missing:
            raise ValueError(f"the {profile} profile needs {', '.join(missing)} of the "
                             "contact (ProfileContext); got none")


class Profile:
    """Base of the roller profiles: :meth:`drop` at positions along the roller."""

    #: Short name for tables and reports.
    name = "profile"

    def drop(self, x, ctx: ProfileContext) -> np.ndarray:
        """Drop of the surface below the cylinder at ``x`` from the roller centre [m].

        Parameters
        ----------
        x : float or array_like
            Axial position from the roller centre [m].
        ctx : ProfileContext
            The contact (effective length, diameter, modulus, radius, design load).

        Returns
        -------
        ndarray
            Drop [m], >= 0 within the roller, ``inf`` at and beyond its ends
            (``|x| >= L/2``).
        """
        x = as_array(x, "x", unit="m")
        if not isinstance(ctx, ProfileContext):
            raise TypeError(f"ctx must be a ProfileContext; got {type(ctx).__name__}")
        self.check(ctx)
        u = np.abs(x) / (0.5 * ctx.length)              # 0 at the centre, 1 at the end
        inside = u < 1.0
        out = np.full(np.shape(u), np.inf)
        out[inside] = self._drop(np.abs(x)[inside], u[inside], x[inside], ctx)
        return out if out.ndim else out[()]

    def check(self, ctx: ProfileContext) -> None:
        """ValueError when this profile does not fit the roller of ``ctx``."""

    def _drop(self, ax, u, x, ctx):                     # pragma: no cover - abstract
        raise NotImplementedError

    def __repr__(self) -> str:
        return f"{type(self).__name__}()"


@dataclass(frozen=True, repr=False)
class Straight(Profile):
    """A straight (cylindrical) roller: no crown.

    On a half-space its pressure has a singular peak at each end; the lamina model of
    ISO/TS 16281 cannot see it (its slices are independent springs)."""

    name = "straight"

    def _drop(self, ax, u, x, ctx):
        return np.zeros_like(ax)


def _log_crown(u):
    """ln[1 / (1 - u^2)] for 0 <= u < 1 (without cancellation near u = 0)."""
    return -np.log1p(-u * u)


@dataclass(frozen=True, repr=False)
class ISO(Profile):
    r"""The default roller profile of ISO/TS 16281:2008 (eqs. 42–44).

    For ``L_we <= 2.5 D_we``:

    .. math:: P(x) = 0.00035\, D_{we} \ln\frac{1}{1 - (2x/L_{we})^2}

    For longer rollers the middle ``L_we - 2.5 D_we`` is straight and each end carries the
    ends of a ``2.5 D_we`` roller, ``P = 0.00035 D_we ln[1 / (1 - ((2|x| - (L_we - 2.5
    D_we)) / (2.5 D_we))^2)]`` beyond it (reconstructed; not checked against the
    standard's text).
    """

    name = "iso"

    def _drop(self, ax, u, x, ctx):
        L, D = ctx.length, ctx.diameter
        if L <= ISO_LONG_ROLLER * D:
            return ISO_COEFFICIENT * D * _log_crown(u)
        flat = L - ISO_LONG_ROLLER * D
        v = np.clip((2.0 * ax - flat) / (ISO_LONG_ROLLER * D), 0.0, None)
        return ISO_COEFFICIENT * D * _log_crown(v)


@dataclass(frozen=True, repr=False)
class Crowned(Profile):
    """A circular crown: straight over ``flat_length``, circular arcs of ``crown_radius``
    beyond (tangent to the straight part).

    Parameters
    ----------
    flat_length : float
        Length of the straight middle part [m], 0 <= flat_length < L_we.
    crown_radius : float
        Radius of the crown arcs in the axial plane [m] (typically some metres).
    """

    flat_length: float
    crown_radius: float
    name = "crowned"

    def __post_init__(self) -> None:
        from .._checks import check_nonnegative
        object.__setattr__(self, "flat_length", float(check_nonnegative(
            self.flat_length, "flat_length", "m", bounded=True, tiny_ok=True)))
        object.__setattr__(self, "crown_radius", float(check_positive(
            self.crown_radius, "crown_radius", "m", bounded=True)))

    def check(self, ctx):
        L = ctx.length
        if self.flat_length >= L:
            raise ValueError(f"flat_length must be shorter than the effective length "
                             f"L_we = {L:g} m; got {self.flat_length:g} m")
        reach = 0.5 * (L - self.flat_length)
        if self.crown_radius <= reach:
            raise ValueError(f"crown_radius must exceed the crowned length at each end, "
                             f"(L_we - flat_length)/2 = {reach:g} m; got "
                             f"{self.crown_radius:g} m (crown radii are some metres, "
                             "e.g. crown_radius=2.0)")

    def _drop(self, ax, u, x, ctx):
        s = np.clip(ax - 0.5 * self.flat_length, 0.0, None)
        R = self.crown_radius
        return s * s / (R + np.sqrt((R - s) * (R + s)))       # R - sqrt(R^2 - s^2)

    def __repr__(self) -> str:
        return f"Crowned(flat_length={self.flat_length!r}, crown_radius={self.crown_radius!r})"


def _design_load(own, ctx, profile, *more):
    """The design load [N] (the profile's own, else the context's), checking ``more``."""
    ctx.need(*((() if own is not None else ("load",)) + more), profile=profile)
    return ctx.load if own is None else own


@dataclass(frozen=True, repr=False)
class _DesignLoadProfile(Profile):
    """A logarithmic profile for a design load Q_d [N] (its own, else the context's)."""

    design_load: float | None = None

    def __post_init__(self) -> None:
        if self.design_load is not None:
            object.__setattr__(self, "design_load", float(check_positive(
                self.design_load, "design_load", "N", bounded=True)))

    def __repr__(self) -> str:
        return f"{type(self).__name__}(design_load={self.design_load!r})"


@dataclass(frozen=True, repr=False)
class Lundberg(_DesignLoadProfile):
    r"""Lundberg's logarithmic profile (1939) for a design load Q_d.

    .. math:: P(x) = \frac{2 Q_d}{\pi L E'} \ln\frac{1}{1 - (2x/L)^2}

    (``= (q/(pi E*)) ln[...]`` with ``q = Q_d/L`` and ``E* = E'/2``).  At Q_d on a
    half-space the pressure is uniform along the roller, ``p0 = sqrt(q E' / (2 pi R))``,
    the 2-D Hertz pressure.

    Parameters
    ----------
    design_load : float, optional
        Q_d [N]; default the context's load (in :func:`~ballrace.analytic.roller.line_contact`
        the load of the same call).
    """

    name = "lundberg"

    def _drop(self, ax, u, x, ctx):
        Q = _design_load(self.design_load, ctx, self.name, "E_prime")
        return 2.0 * Q / (math.pi * ctx.length * ctx.E_prime) * _log_crown(u)


@dataclass(frozen=True, repr=False)
class JohnsGohar(_DesignLoadProfile):
    r"""The Johns–Gohar logarithmic profile (1981) for a design load Q_d.

    .. math:: P(x) = \frac{2 Q_d}{\pi L E'}
              \ln\frac{1}{1 - \left(1 - (2b/L)^2\right)(2x/L)^2}

    with ``b = sqrt(8 Q_d R / (pi L E'))`` the 2-D Hertz half-width at Q_d.  Unlike
    Lundberg's, the drop is finite at the roller end, ``(4 Q_d/(pi L E')) ln(L/2b)``.

    Parameters
    ----------
    design_load : float, optional
        Q_d [N]; default the context's load.
    """

    name = "johns-gohar"

    def _drop(self, ax, u, x, ctx):
        Q = _design_load(self.design_load, ctx, self.name, "E_prime", "R")
        L = ctx.length
        b = math.sqrt(8.0 * Q * ctx.R / (math.pi * L * ctx.E_prime))
        k = max(1.0 - (2.0 * b / L) ** 2, 0.0)
        return 2.0 * Q / (math.pi * L * ctx.E_prime) * -np.log1p(-k * u * u)


class Table(Profile):
    """A profile given as a table of drops (a measured or drawn profile).

    Parameters
    ----------
    x : array_like
        Axial positions from the roller centre [m], strictly increasing.  A table that
        starts at 0 describes a symmetric profile (mirrored to negative x).
    drop : array_like
        Drop of the surface at each x [m], >= 0.

    Linear interpolation between the points; beyond the table's last point (within the
    roller) the end value is held.  The table must lie within the roller and reach at
    least 95 % of the half-length on each side (checked against the roller it is used
    with).
    """

    name = "table"

    def __init__(self, x, drop):
        x = np.array(as_array(x, "profile x", unit="m"), dtype=float).ravel()
        d = np.array(as_array(drop, "profile drop", unit="m"), dtype=float).ravel()
        if x.size != d.size or x.size < 2:
            raise ValueError(f"a profile table needs x and drop of the same length, at "
                             f"least 2 points; got {x.size} x and {d.size} drop values")
        if np.any(np.diff(x) <= 0):
            i = int(np.argmax(np.diff(x) <= 0))
            raise ValueError(f"profile x must be strictly increasing [m]; got x[{i + 1}] = "
                             f"{x[i + 1]:g} after x[{i}] = {x[i]:g} (example: x = [0, 2e-3, "
                             "4e-3, 6e-3], drop = [0, 0, 2e-6, 8e-6])")
        if np.any(d < 0):
            i = int(np.argmax(d < 0))
            raise ValueError(f"profile drop must be >= 0 [m] (below the cylinder through "
                             f"the centre); got drop[{i}] = {d[i]:g}")
        if x[0] > 0:
            raise ValueError(f"profile x must start at the roller centre (0) or before it; "
                             f"got x[0] = {x[0]:g} m")
        #: a table from the centre describes both halves (evaluated at |x|)
        self.symmetric = bool(x[0] == 0)
        plausible.length(np.abs(x), "profile x", 0.5, "roller", stacklevel=4)
        self.x, self.values = x, d
        self.x.setflags(write=False)
        self.values.setflags(write=False)

    def check(self, ctx):
        h = 0.5 * ctx.length
        x0 = -self.x[-1] if self.symmetric else self.x[0]
        if x0 < -h * (1 + 1e-9) or self.x[-1] > h * (1 + 1e-9):
            raise ValueError(f"the profile table reaches x = {x0:g} ... "
                             f"{self.x[-1]:g} m, outside the roller (|x| <= L_we/2 = {h:g} m)"
                             " - were millimetres given?")
        if x0 > -TABLE_REACH * h or self.x[-1] < TABLE_REACH * h:
            raise ValueError(f"the profile table covers x = {x0:g} ... {self.x[-1]:g}"
                             f" m of a roller with |x| <= {h:g} m; give points up to within "
                             f"{(1 - TABLE_REACH) * 100:g} % of each end")
        if float(self.values.max()) > 0.1 * ctx.length:
            raise ValueError(f"the profile table's largest drop, {self.values.max():g} m, "
                             f"exceeds a tenth of the roller length ({ctx.length:g} m); "
                             "drops are in metres (5 um = 5e-6)")

    def _drop(self, ax, u, x, ctx):
        return np.interp(ax if self.symmetric else x, self.x, self.values)

    def __eq__(self, other) -> bool:
        return (isinstance(other, Table) and np.array_equal(self.x, other.x)
                and np.array_equal(self.values, other.values))

    def __hash__(self) -> int:
        return hash((self.x.tobytes(), self.values.tobytes()))

    def __repr__(self) -> str:
        half = " from the centre, mirrored" if self.symmetric else ""
        return f"Table(<{self.x.size} points{half}, |x| <= {np.abs(self.x).max():g} m>)"


_BY_NAME = {"straight": Straight, "iso": ISO, "lundberg": Lundberg,
            "johns-gohar": JohnsGohar}


def as_profile(spec) -> Profile:
    """A profile from a name, a profile object, or an ``(x, drop)`` table [m].

    Parameters
    ----------
    spec : str, Profile or (array_like, array_like)
        ``"straight"``, ``"iso"``, ``"lundberg"``, ``"johns-gohar"`` (the logarithmic ones
        designed for the load of the contact they are used in), a :class:`Profile`, or a
        pair ``(x, drop)`` [m] (:class:`Table`).

    Examples
    --------
    >>> as_profile("lundberg")
    Lundberg(design_load=None)
    >>> as_profile(([0.0, 3e-3, 6e-3], [0.0, 1e-6, 5e-6]))
    Table(<3 points from the centre, mirrored, |x| <= 0.006 m>)
    """
    if isinstance(spec, Profile):
        return spec
    if isinstance(spec, str):
        key = spec.strip().lower().replace("_", "-")
        if key in ("crowned", "circular"):
            raise ValueError("a circular crown needs its sizes: profile=Crowned("
                             "flat_length=..., crown_radius=...) [m]")
        if key not in _BY_NAME:
            raise ValueError(f"profile must be one of {', '.join(PROFILE_NAMES)}, a "
                             f"Crowned(...) or Table(...) object, or an (x, drop) table "
                             f"[m]; got {spec!r}")
        return _BY_NAME[key]()
    if isinstance(spec, (tuple, list)) and len(spec) == 2:
        return Table(*spec)
    raise TypeError(f"profile must be a name ({', '.join(PROFILE_NAMES)}), a Profile or an "
                    f"(x, drop) pair of arrays [m]; got {type(spec).__name__}")
