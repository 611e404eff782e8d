"""Moved to :mod:`ballrace.commands.shaft`; this path stays importable (the same module)."""
import sys

from ballrace.commands import shaft as _module

sys.modules[__name__] = _module
