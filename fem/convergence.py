"""Mesh-convergence study: errors against Hertz / Lundberg–Palmgren versus DOFs.

For each mesh size (elements per minor semi-axis ``n``) the case is solved and the
relative error of each quantity recorded; the observed rate is the slope of
``log|error|`` against ``log(DOFs)`` (least squares, as in scikit-fem's
``tests/test_convergence.py``).  For a 3-D mesh ``DOFs ~ h^-3``, so a rate r in DOFs
is ``3 r`` in h.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, replace

import numpy as np

__all__ = ["ConvergenceStudy", "convergence_study", "fitted_rate"]

log = logging.getLogger(__name__)

QUANTITIES = ("a", "b", "p_max", "approach", "tau0", "z0", "max_shear", "von_mises",
              "tau_profile")
#: ``tau_profile``: RMS over the section depths 0.04-1.6 b of the difference between the FE
#: and the analytic ``max_x |tau_xz|(z)``, in units of tau0 (``FEResult.info
#: ["tau_profile_rms"]``) — the error of the whole subsurface profile, which converges
#: steadily where the depth of its flat peak (z0) scatters.


def fitted_rate(dofs, errors) -> float:
    """Slope of log|error| against log(DOFs) (NaN with fewer than two non-zero errors).

    Examples
    --------
    >>> round(fitted_rate([1e3, 8e3, 64e3], [1e-2, 2.5e-3, 6.25e-4]), 6)
    -0.666667
    """
    d = np.asarray(dofs, dtype=float)
    e = np.abs(np.asarray(errors, dtype=float))
    ok = e > 0
    if ok.sum() < 2:
        return float("nan")
    return float(np.polyfit(np.log(d[ok]), np.log(e[ok]), 1)[0])


@dataclass(frozen=True)
class ConvergenceStudy:
    """Result of :func:`convergence_study`: ``n``, ``dofs``, ``seconds``, ``errors[q]``,
    ``rates[q]`` (per DOF)."""

    n: tuple
    dofs: tuple
    seconds: tuple
    errors: dict
    rates: dict

    def rows(self):
        """Table rows: (n, DOFs, seconds, error per quantity...)."""
        return [(n, d, s, *[self.errors[q][i] for q in QUANTITIES])
                for i, (n, d, s) in enumerate(zip(self.n, self.dofs, self.seconds))]


def convergence_study(case, sizes=(4, 6, 8, 11), mode: str = "half-space",
                      progress=None, max_stretch: float | None = None,
                      **kwargs) -> ConvergenceStudy:
    """Solve ``case`` at several mesh sizes and fit error rates.

    The refinement is uniform: every element dimension scales with 1/n, the anisotropy
    (elongation along a long ellipse's major axis) is held fixed and the pressure grid
    is tied to the mesh (tents one surface element apart, no cap), so both
    discretisations converge together.

    Parameters
    ----------
    case : ContactCase
        From :func:`ballrace.fem.race_case` / ``plane_case`` / ``ball_case``.
    sizes : sequence of int
        Elements per minor semi-axis at the contact.
    mode : {"half-space", "two-body"}
    progress : callable(str), optional
        Called before each run.
    max_stretch : float, optional
        Element elongation cap (:class:`ballrace.fem.MeshLevel`); default the standard
        level's.  Everything else (tent smoothing, refinement column and layer, the
        probe box at h/probe over the sampled region) is the standard level's too, so
        the point n = 9 is the standard level with its tents one element apart.
    """
    from . import api

    cap = api.LEVELS["standard"].max_stretch if max_stretch is None else max_stretch
    errs = {q: [] for q in QUANTITIES}
    dofs, secs = [], []
    for n in sizes:
        if progress:
            progress(f"n = {n}")
        level = replace(api.LEVELS["standard"], n=float(n), max_stretch=cap,
                        tents_per_axis=float("inf"))
        r = api.run_case(case, level=level, mode=mode, **kwargs)
        rows = {row["quantity"]: row for row in r.comparison}
        for q in QUANTITIES:
            errs[q].append(r.info["tau_profile_rms"] if q == "tau_profile"
                           else rows[q]["error"])
        dofs.append(r.n_dofs)
        secs.append(r.timings["total"])
        log.info("convergence n=%s: %d DOFs, %.1f s", n, r.n_dofs, r.timings["total"])
    rates = {q: fitted_rate(dofs, errs[q]) for q in QUANTITIES}
    return ConvergenceStudy(tuple(sizes), tuple(dofs), tuple(secs), errs, rates)
