"""Shared helpers of the subsurface-field tests (test_subsurface.py, test_traction.py)."""
from __future__ import annotations

import numpy as np

from ballrace.analytic import subsurface


def alpha_for_k(k):
    """Radius ratio Ry/Rx giving ellipticity k (inverse of Hertz's relation)."""
    from scipy.special import ellipe, ellipk
    k = np.asarray(k, float)
    m = 1 - 1 / k**2
    with np.errstate(divide="ignore", invalid="ignore"):
        a = (k**2 * ellipe(m) - ellipk(m)) / (ellipk(m) - ellipe(m))
    return np.where(k == 1, 1.0, a)


def divergence(c, xi, eta, zeta, nu, traction=0.0):
    """div(sigma) b / p_max at (xi a_x, eta a_y, zeta b) by 4th-order central differences
    (h = 1e-3 z, so the truncation error stays small near the surface where the field
    varies on the scale z)."""
    b = float(c.b)
    x0, y0, z0 = xi * float(c.semi_axis_x), eta * float(c.semi_axis_y), zeta * b
    h = 1e-3 * z0
    off = np.array([-2, -1, 1, 2]) * h
    w = np.array([1, -8, 8, -1]) / (12 * h)
    sx = subsurface.stress(c, x0 + off, y0, z0, nu, traction=traction)
    sy = subsurface.stress(c, x0, y0 + off, z0, nu, traction=traction)
    sz = subsurface.stress(c, x0, y0, z0 + off, nu, traction=traction)
    return np.array([w @ sx.sxx + w @ sy.sxy + w @ sz.sxz,
                     w @ sx.sxy + w @ sy.syy + w @ sz.syz,
                     w @ sx.sxz + w @ sy.syz + w @ sz.szz]) * b / c.p_max
