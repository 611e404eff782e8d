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

__all__ = ["ConvergenceError", "CaseFileError"]


class ConvergenceError(RuntimeError):
    """An iteration did not converge (the message gives residual and iterations)."""

    __module__ = "ballrace.errors"


class CaseFileError(ValueError):
    """A case file that cannot be read, or whose contents are invalid (the message names
    the file and the key)."""

    __module__ = "ballrace.errors"
