"""ballrace — Hertz contact and rolling-bearing load distribution you can check.

SI units throughout (N, m, Pa, rad).  Sub-packages:

* :mod:`ballrace.analytic` — Hertz contact, subsurface stresses, bearing geometry,
  load distribution, life and lubrication (numpy/scipy only); roller bearings and the
  finite line contact in :mod:`ballrace.analytic.roller`;
* :mod:`ballrace.fem` and :mod:`ballrace.meshes` — the finite-element check of the
  ball–race contact (optional extra ``ballrace[fem]``);
* :mod:`ballrace.validation` and :mod:`ballrace.reports` — reference cases, the
  validation runner and the HTML report;
* :mod:`ballrace.teach` — ``ballrace teach``: the subsurface-stress explorer.
"""
import logging as _logging

from ballrace.analytic.materials import BEARING_STEEL, SILICON_NITRIDE, Material
from ballrace.analytic.bearing import BallBearing

__version__ = "0.1.0"
__all__ = ["Material", "BallBearing", "RollerBearing", "BEARING_STEEL", "SILICON_NITRIDE", "__version__"]

_logging.getLogger(__name__).addHandler(_logging.NullHandler())


def __getattr__(name):
    # the roller sub-package (its ratings, life, line contact) is imported on first use,
    # so that ``import ballrace`` and the commands that need no roller do not pay for it
    if name == "RollerBearing":
        from ballrace.analytic.roller.bearing import RollerBearing

        globals()["RollerBearing"] = RollerBearing
        return RollerBearing
    raise AttributeError(f"module 'ballrace' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
