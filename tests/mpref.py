"""Slow, independent scalar references for Hertz contact (mpmath, 30 digits).

Used by the tests and the benchmark as the "slow scalar reference".  Two routes,
both independent of the library's solver:

* :func:`k_exact` — Hertz's relation alpha = (k^2 E - K)/(K - E) solved with mpmath's
  ``findroot`` on complete elliptic integrals at 30 significant digits;
* :func:`potential_checks` — the Hertz pressure's surface potential
  V = (pi a b p0 / 2) int_0^inf [1 - x^2/(a^2+w) - y^2/(b^2+w)] dw / sqrt((a^2+w)(b^2+w)w)
  (Johnson 1985 §3.7, Love 1929) integrated numerically: the elastic displacement
  must equal delta - x^2/(2Rx) - y^2/(2Ry) inside the ellipse.
"""
from __future__ import annotations

import mpmath as mp

mp.mp.dps = 30


def k_exact(alpha: float) -> float:
    """Ellipticity k for radius ratio alpha >= 1, by mpmath root finding."""
    alpha = mp.mpf(alpha)
    if alpha == 1:
        return 1.0

    def f(lnk):
        k = mp.e ** lnk
        m = 1 - 1 / k**2
        K, E = mp.ellipk(m), mp.ellipe(m)
        return mp.log((k**2 * E - K) / (K - E)) - mp.log(alpha)

    return float(mp.e ** mp.findroot(f, mp.log(1.0339 * alpha**0.636) * 0.98 + 1e-6))


def hertz_exact(load: float, Rx: float, Ry: float, E_prime: float) -> dict:
    """a, b, approach, p_max from the exact Hertz formulas evaluated in mpmath."""
    Q, Rx, Ry, Ep = map(mp.mpf, (load, Rx, Ry, E_prime))
    alpha = max(Ry / Rx, Rx / Ry)
    k = mp.mpf(k_exact(float(alpha)))
    # polish k at 30 digits
    k = mp.findroot(lambda kk: (kk**2 * mp.ellipe(1 - 1 / kk**2) - mp.ellipk(1 - 1 / kk**2))
                    / (mp.ellipk(1 - 1 / kk**2) - mp.ellipe(1 - 1 / kk**2)) - alpha, k) \
        if alpha != 1 else mp.mpf(1)
    m = 1 - 1 / k**2
    K, E = (mp.ellipk(m), mp.ellipe(m)) if alpha != 1 else (mp.pi / 2, mp.pi / 2)
    R = 1 / (1 / Rx + 1 / Ry)
    a = mp.cbrt(6 * k**2 * E * Q * R / (mp.pi * Ep))
    b = mp.cbrt(6 * E * Q * R / (mp.pi * k * Ep))
    d = K * mp.cbrt(9 / (2 * E * R) * (Q / (mp.pi * k * Ep)) ** 2)
    return {"k": float(k), "a": float(a), "b": float(b), "approach": float(d),
            "p_max": float(3 * Q / (2 * mp.pi * a * b))}


def potential_checks(a: float, b: float, p_max: float, E_prime: float) -> dict:
    """Approach and gap curvatures implied by a Hertz pressure ellipse (semi-axes a >= b).

    Returns ``approach`` [m] = (2/(pi E')) V(0, 0), and ``R_major``, ``R_minor`` [m],
    the effective radii along the a- and b-axes for which the surface displacement
    equals delta - s^2/(2R) (Johnson 1985 eqs. 3.63–3.65 with E' = 2E*).
    """
    a, b, p0, Ep = map(mp.mpf, (a, b, p_max, E_prime))

    def I(shift):
        f = lambda w: 1 / ((shift + w) * mp.sqrt((a * a + w) * (b * b + w) * w))  # noqa: E731
        return mp.quad(f, [0, b * b, a * a, 100 * a * a, mp.inf])

    I0 = mp.quad(lambda w: 1 / mp.sqrt((a * a + w) * (b * b + w) * w), [0, b * b, a * a, 100 * a * a, mp.inf])
    c = a * b * p0 / Ep
    return {"approach": float(c * I0),
            "R_major": float(1 / (2 * c * I(a * a))),
            "R_minor": float(1 / (2 * c * I(b * b)))}
