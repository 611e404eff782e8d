"""The exceptions and warning categories of ballrace, in one place.

Every layer raises these (the formula modules, the solvers, the case-file readers, the
FE check), so this module imports nothing from the package: any module may import it
without closing a circle.

Errors
------
* :class:`ConvergenceError` (a ``RuntimeError``): an iteration did not converge; the
  message gives the residual and the iteration count.
* :class:`CaseFileError` (a ``ValueError``): a case file (bearing, shaft, FE or
  validation case) cannot be read, or its contents are invalid; the message names the
  file and the key.

Bad input to a function is a plain ``ValueError`` (or ``TypeError``) naming the argument,
what was given and the allowed range.

Warnings
--------
What a user must act on is a :class:`UserWarning` through :func:`warnings.warn` (it
reaches scripts and the command line); diagnostics go to the ``ballrace`` logger, silent
unless asked for (``-v`` on the command line).
"""
from __future__ import annotations

import os
import sys
import warnings

__all__ = ["ConvergenceError", "CaseFileError", "warn"]

_PACKAGE = os.path.dirname(os.path.abspath(__file__)) + os.sep
#: The package's sub-packages (a checkout also holds tests, gallery and examples beside
#: them: those are callers, not the library).
_SUBPACKAGES = ("analytic", "fem", "meshes", "validation", "reports")


def _in_package(filename: str) -> bool:
    path = os.path.abspath(filename)
    if not path.startswith(_PACKAGE):
        return False
    rest = path[len(_PACKAGE):].split(os.sep)
    return len(rest) == 1 or rest[0] in _SUBPACKAGES


class ConvergenceError(RuntimeError):
    """An iteration did not converge (the message gives residual and iterations)."""

    __module__ = "ballrace.errors"


class CaseFileError(ValueError):
    """A case file that cannot be read, or whose contents are invalid (the message names
    the file and the key)."""

    __module__ = "ballrace.errors"


def warn(message: str, category: type[Warning] = UserWarning) -> None:
    """Warn the user: ``warnings.warn`` attributed to the first caller outside the package.

    The library's policy for what a user must act on (an input outside a formula's range,
    a result beyond a bearing's limits): the warning reaches a script, a notebook and the
    command line, and names the user's line, however deep in the library it was raised.
    """
    f, level = sys._getframe(1), 2
    while f is not None and _in_package(f.f_code.co_filename):
        f, level = f.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)
