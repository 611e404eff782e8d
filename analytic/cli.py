"""Moved to :mod:`ballrace.commands.bearing`; this path stays importable (the same module)."""
import sys

from ballrace.commands import bearing as _module

sys.modules[__name__] = _module
