"""ballrace — Hertz contact and ball-bearing load distribution you can check.

SI units throughout (N, m, Pa, rad).  Sub-packages:

* :mod:`ballrace.analytic` — Hertz contact, subsurface stresses, bearing geometry,
  load distribution, life and lubrication (numpy/scipy only);
* :mod:`ballrace.fem` and :mod:`ballrace.meshes` — the finite-element check of the
  ball–race contact (optional extra ``ballrace[fem]``);
* :mod:`ballrace.validation` and :mod:`ballrace.reports` — reference cases, the
  validation runner and the HTML report.
"""
import logging as _logging

from ballrace.analytic.materials import BEARING_STEEL, SILICON_NITRIDE, Material
from ballrace.analytic.bearing import BallBearing

__version__ = "0.1.0"
__all__ = ["Material", "BallBearing", "BEARING_STEEL", "SILICON_NITRIDE", "__version__"]

_logging.getLogger(__name__).addHandler(_logging.NullHandler())
