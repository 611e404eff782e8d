"""Moved to :mod:`ballrace.casefiles.bearing`; this path stays importable (the same module)."""
import sys

from ballrace.casefiles import bearing as _module

sys.modules[__name__] = _module
