"""Moved to :mod:`ballrace.teach.figures`; this path stays importable (the same module)."""
import sys

from ballrace.teach import figures as _module

sys.modules[__name__] = _module
