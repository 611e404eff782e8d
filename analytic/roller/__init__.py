"""Roller bearings and the contact of a profiled roller.

* :mod:`~ballrace.analytic.roller.profile` — roller profiles (straight, ISO/TS 16281's
  default, circular crown, Lundberg's and Johns–Gohar's logarithmic crowns, tables).
* :mod:`~ballrace.analytic.roller.contact` — the finite line contact of a profiled roller on
  the elastic half-space (:func:`line_contact`) and the stresses below it
  (:func:`subsurface_stress`).
* :mod:`~ballrace.analytic.roller.bearing` — :class:`RollerBearing`, cylindrical and tapered.
* :mod:`~ballrace.analytic.roller.lamina` — the sliced contact of ISO/TS 16281.
* :mod:`~ballrace.analytic.roller.loaddist` — the five-DOF load distribution (lamina model).
* :mod:`~ballrace.analytic.roller.ratings` — ISO 281 / ISO 76 ratings, X/Y, a_ISO and
  rating life of roller bearings.
* :mod:`~ballrace.analytic.roller.life` — ISO/TS 16281 reference rating life from slice
  loads.
* :mod:`~ballrace.analytic.roller.pair` — :class:`TaperedPair`, two tapered bearings at
  one shaft seat with preload or end play.
"""
from . import profile
from .profile import (ISO, Crowned, JohnsGohar, Lundberg, Profile, ProfileContext, Straight,
                      Table, as_profile)
from . import contact
from .contact import LineContactResult, RollerStress, line_contact, subsurface_stress
from . import bearing, lamina, loaddist
from .bearing import RollerBearing
from .loaddist import RollerLoadDistribution
from . import life, ratings
from . import pair
from .loaddist import RollerRow
from .pair import TaperedPair

__all__ = ["profile", "Profile", "ProfileContext", "Straight", "ISO", "Crowned", "Lundberg",
           "JohnsGohar", "Table", "as_profile",
           "contact", "LineContactResult", "line_contact", "RollerStress", "subsurface_stress",
           "bearing", "lamina", "loaddist", "RollerBearing", "RollerLoadDistribution",
           "ratings", "life", "pair", "RollerRow", "TaperedPair"]
