"""Roller bearings and the contact of a profiled roller.

* :mod:`~ballrace.analytic.roller.profile` — roller profiles (straight, ISO/TS 16281's
  default, circular crown, Lundberg's and Johns–Gohar's logarithmic crowns, tables).
* :mod:`~ballrace.analytic.roller.contact` — the finite line contact of a profiled roller on
  the elastic half-space (:func:`line_contact`) and the stresses below it
  (:func:`subsurface_stress`).
"""
from . import profile
from .profile import (ISO, Crowned, JohnsGohar, Lundberg, Profile, ProfileContext, Straight,
                      Table, as_profile)

__all__ = ["profile", "Profile", "ProfileContext", "Straight", "ISO", "Crowned", "Lundberg",
           "JohnsGohar", "Table", "as_profile"]

from . import contact
from .contact import LineContactResult, RollerStress, line_contact, subsurface_stress

__all__ += ["contact", "LineContactResult", "line_contact", "RollerStress", "subsurface_stress"]
