r"""Elastic half-space quantities under a Hertz pressure, by quadrature (numpy only).

Used to make the FE approach comparable with Hertz's (docs/fem.md, "depth-point
method"): Hertz's approach delta is the approach of *distant* points, while a finite
FE body has its own bulk compliance.  The approach of two on-axis points at depth
z_q (one per body) is, by Hertz theory, ``delta - w1(z_q) - w2(z_q)`` with w the
half-space axial displacement below the centre of the ellipse, relative to infinity.

Boussinesq's point-load solution (Johnson 1985 eq. 3.22c), for a normal force P at
the surface origin, vertical displacement (into the body) at depth z, radius r:

.. math:: u_z = \frac{P}{4\pi G}\left[\frac{2(1-\nu)}{\rho} + \frac{z^2}{\rho^3}\right],
          \qquad \rho = \sqrt{r^2 + z^2},\quad G = \frac{E}{2(1+\nu)}

integrated over the Hertz ellipse ``p = p0 sqrt(1 - (x/ax)^2 - (y/ay)^2)`` with the
substitution ``x = ax sin(phi) cos(theta)``, ``y = ay sin(phi) sin(theta)``, which
makes the integrand smooth (``p dA = p0 ax ay sin(phi) cos^2(phi) dphi dtheta``).
"""
from __future__ import annotations

import numpy as np

__all__ = ["axial_displacement"]


def axial_displacement(z, semi_axis_x: float, semi_axis_y: float, p_max: float,
                       E: float, nu: float, n: int = 96):
    r"""Half-space displacement (into the body) on the axis at depth z [m].

    Parameters
    ----------
    z : float or array_like
        Depth below the centre of the contact [m], >= 0.
    semi_axis_x, semi_axis_y : float
        Semi-axes of the Hertz ellipse [m].
    p_max : float
        Central pressure [Pa].
    E, nu : float
        Young's modulus [Pa] and Poisson's ratio [-] of the body.
    n : int
        Gauss points per direction.

    Returns
    -------
    ndarray
        w(z) [m].

    References
    ----------
    Boussinesq (1885); Johnson (1985) eq. (3.22c) and §3.4.

    Examples
    --------
    At the surface of a circular contact, w(0) = pi a p0 (1 - nu^2) / (2 E)
    (Johnson 1985 eq. 3.41):

    >>> w = axial_displacement(0.0, 1e-3, 1e-3, 1e9, 200e9, 0.3)
    >>> bool(np.isclose(w, np.pi * 1e-3 * 1e9 * 0.91 / 4e11, rtol=1e-6))
    True
    """
    z = np.atleast_1d(np.asarray(z, dtype=float))
    G = E / (2.0 * (1.0 + nu))
    xg, wg = np.polynomial.legendre.leggauss(n)
    phi = 0.25 * np.pi * (xg + 1.0)                 # [0, pi/2]
    th = 0.25 * np.pi * (xg + 1.0)                  # quarter, x4 by symmetry
    wphi = 0.25 * np.pi * wg
    wth = 0.25 * np.pi * wg
    P, T = np.meshgrid(phi, th, indexing="ij")
    W = np.outer(wphi, wth) * 4.0
    s = np.sin(P)
    x = semi_axis_x * s * np.cos(T)
    y = semi_axis_y * s * np.sin(T)
    r2 = x * x + y * y
    load = p_max * semi_axis_x * semi_axis_y * s * np.cos(P) ** 2 * W     # p dA
    out = np.empty(z.shape)
    for i, zi in enumerate(z):
        rho2 = r2 + zi * zi
        with np.errstate(divide="ignore", invalid="ignore"):
            k = (2.0 * (1.0 - nu) / np.sqrt(rho2) + zi * zi / rho2**1.5) / (4.0 * np.pi * G)
        if zi == 0.0:
            k = 2.0 * (1.0 - nu) / np.sqrt(r2) / (4.0 * np.pi * G)
        out[i] = np.sum(load * k)
    return out if out.size > 1 else out[0]
