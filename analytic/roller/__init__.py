"""Roller bearings and the contact of a profiled roller.

* :mod:`~ballrace.analytic.roller.profile` — roller profiles (straight, ISO/TS 16281's
  default, circular crown, Lundberg's and Johns–Gohar's logarithmic crowns, tables).
* :mod:`~ballrace.analytic.roller.ratings` — ISO 281 / ISO 76 ratings, X/Y, a_ISO and
  rating life of roller bearings.
* :mod:`~ballrace.analytic.roller.life` — ISO/TS 16281 reference rating life from slice
  loads.
"""
from . import profile
from .profile import (ISO, Crowned, JohnsGohar, Lundberg, Profile, ProfileContext, Straight,
                      Table, as_profile)
from . import life, ratings

__all__ = ["profile", "Profile", "ProfileContext", "Straight", "ISO", "Crowned", "Lundberg",
           "JohnsGohar", "Table", "as_profile"]
__all__ += ["ratings", "life"]
