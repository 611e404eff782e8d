r"""Independent derivations behind the ``kind = "independent derivation"`` cases.

The expected numbers of those cases were produced by this module, which shares no
code with :mod:`ballrace.analytic`: Hertz's transcendental equation for the
ellipticity is solved with :mod:`mpmath` at 30 significant digits (``findroot`` on
the elliptic-integral form, Hamrock & Dowson 1981 eq. 3.14 / Ricci 2009 eq. 14), the
semi-axes, approach and pressure follow from eqs. (3.8)–(3.16), and the subsurface
numbers from Johnson's closed-form axis stresses (Johnson 1985 eq. 3.45) and
line-contact stresses (McEwen 1949; Johnson 1985 eq. 4.47) maximised with ``mpmath``.

Regenerate the tables with ``python -m ballrace.validation.derive``; the case files
quote the printed values (10 significant digits).

Examples
--------
>>> d = hertz_exact(1000, 5e-3, 5e-3, float("inf"), float("inf"), 219.78e9)
>>> round(d["a"] * 1e3, 4), round(d["k"], 12)
(0.3244, 1.0)
"""
from __future__ import annotations

import math

__all__ = ["hertz_exact", "circle_axis_max_shear", "line_max_shear", "main"]


def _mp():
    import mpmath

    mpmath.mp.dps = 30
    return mpmath


def hertz_exact(load, rx1, ry1, rx2, ry2, E_prime) -> dict:
    """Exact elliptical Hertz contact with mpmath (SI in, SI floats out)."""
    mp = _mp()
    inv = lambda r: mp.mpf(0) if math.isinf(r) else 1 / mp.mpf(r)
    Rx = 1 / (inv(rx1) + inv(rx2))
    Ry = 1 / (inv(ry1) + inv(ry2))
    alpha = max(Rx, Ry) / min(Rx, Ry)
    R = Rx * Ry / (Rx + Ry)
    if alpha == 1:
        k, K, E = mp.mpf(1), mp.pi / 2, mp.pi / 2
    else:
        def f(lnk):
            k = mp.e ** lnk
            m = 1 - 1 / k**2
            K, E = mp.ellipk(m), mp.ellipe(m)
            return mp.log((k**2 * E - K) / (K - E)) - mp.log(alpha)

        lnk = mp.findroot(f, mp.log(alpha) * 2 / mp.pi)
        k = mp.e ** lnk
        m = 1 - 1 / k**2
        K, E = mp.ellipk(m), mp.ellipe(m)
    Q, Ep = mp.mpf(load), mp.mpf(E_prime)
    a = (6 * k**2 * E * Q * R / (mp.pi * Ep)) ** (mp.mpf(1) / 3)
    b = (6 * E * Q * R / (mp.pi * k * Ep)) ** (mp.mpf(1) / 3)
    delta = K * (mp.mpf(9) / (2 * E * R) * (Q / (mp.pi * k * Ep)) ** 2) ** (mp.mpf(1) / 3)
    p = 3 * Q / (2 * mp.pi * a * b)
    return {"Rx": float(Rx), "Ry": float(Ry), "k": float(k), "ellipk": float(K),
            "ellipe": float(E), "a": float(a), "b": float(b), "approach": float(delta),
            "p_max": float(p)}


def circle_axis_max_shear(nu: float) -> dict:
    r"""Max of the principal shear stress on the axis of a circular Hertz contact.

    Johnson (1985) eq. (3.45): with :math:`\zeta = z/a`,
    :math:`\sigma_z/p_0 = -1/(1+\zeta^2)`,
    :math:`\sigma_r/p_0 = -(1+\nu)(1 - \zeta\arctan(1/\zeta)) + 1/(2(1+\zeta^2))`,
    :math:`\tau_1 = |\sigma_r - \sigma_z|/2`; returns tau/p0, depth/a and von Mises/p0.
    """
    mp = _mp()
    nu = mp.mpf(nu)

    def tau(z):
        sz = -1 / (1 + z**2)
        sr = -(1 + nu) * (1 - z * mp.atan(1 / z)) + 1 / (2 * (1 + z**2))
        return (sr - sz) / 2

    z = mp.findroot(lambda z: mp.diff(tau, z), 0.48)
    t = tau(z)
    return {"tau_max": float(abs(t)), "depth": float(z), "von_mises": float(2 * abs(t))}


def line_max_shear() -> dict:
    r"""Max principal shear under a Hertz line contact, on the centre line (plane strain).

    Johnson (1985) eq. (4.47) at x = 0, :math:`\zeta = z/b`:
    :math:`\sigma_x = -p_0[(1+2\zeta^2)/\sqrt{1+\zeta^2} - 2\zeta]`,
    :math:`\sigma_z = -p_0/\sqrt{1+\zeta^2}`, :math:`\tau_1 = |\sigma_x-\sigma_z|/2`
    (independent of nu).
    """
    mp = _mp()

    def tau(z):
        sx = -((1 + 2 * z**2) / mp.sqrt(1 + z**2) - 2 * z)
        sz = -1 / mp.sqrt(1 + z**2)
        return (sx - sz) / 2

    z = mp.findroot(lambda z: mp.diff(tau, z), 0.78)
    return {"tau_max": float(abs(tau(z))), "depth": float(z)}


def lundberg_palmgren_circle() -> dict:
    """Lundberg–Palmgren orthogonal shear for a circle (b/a = 1): t, tau0/p_max, z0/b.

    Hamrock & Dowson (1981) eqs. (3.19)–(3.27): solve (t^2 - 1)(2t - 1) = (b/a)^2 = 1.
    """
    mp = _mp()
    t = mp.findroot(lambda t: (t**2 - 1) * (2 * t - 1) - 1, 1.28)
    return {"t": float(t), "tau0": float(mp.sqrt(2 * t - 1) / (2 * t * (t + 1))),
            "z0": float(1 / ((t + 1) * mp.sqrt(2 * t - 1)))}


_CASES = {
    # Hamrock & Dowson (1981) Table 3.2 geometries: D = 12.7 mm, F = 4.45 N, E' = 2.28e11 Pa
    "hd-ball-on-ball": (4.45, 6.35e-3, 6.35e-3, 6.35e-3, 6.35e-3, 2.28e11),
    "hd-ball-on-plane": (4.45, 6.35e-3, 6.35e-3, math.inf, math.inf, 2.28e11),
    "hd-209-outer": (4.45, 6.35e-3, 6.35e-3, -38.85e-3, -0.52 * 12.7e-3, 2.28e11),
    "hd-209-inner": (4.45, 6.35e-3, 6.35e-3, 26.15e-3, -0.52 * 12.7e-3, 2.28e11),
    # Ricci (2009) 218 bearing at beta_f = 40 deg, Q = 9445 N, E' = 200e9/(1 - 0.09)
    "ricci-218-inner": (9445.0, 22.225e-3 / 2, 22.225e-3 / 2,
                        (125.26e-3 / math.cos(math.radians(40)) - 22.225e-3) / 2,
                        -0.5232 * 22.225e-3, 200e9 / 0.91),
    "ricci-218-outer": (9445.0, 22.225e-3 / 2, 22.225e-3 / 2,
                        -(125.26e-3 / math.cos(math.radians(40)) + 22.225e-3) / 2,
                        -0.5232 * 22.225e-3, 200e9 / 0.91),
    # hybrid: Si3N4 ball (310 GPa, 0.27) 12.7 mm on a steel flat (200 GPa, 0.3), 1000 N
    "hybrid-ball-on-plane": (1000.0, 6.35e-3, 6.35e-3, math.inf, math.inf,
                             2 / ((1 - 0.27**2) / 310e9 + (1 - 0.3**2) / 200e9)),
    # a long thin ellipse: crossed cylinders of radii 1 m and 1 mm... Rx = 1 mm, Ry = 10 m
    "narrow-ellipse": (100.0, 1e-3, 10.0, math.inf, math.inf, 200e9 / 0.91),
}


def main() -> None:  # pragma: no cover - writes the tables quoted by the case files
    import sys

    def out(line: str) -> None:
        sys.stdout.write(line + "\n")

    for name, args in _CASES.items():
        d = hertz_exact(*args)
        out(name + " " + " ".join(f"{k}={v:.10g}" for k, v in d.items()))
    for nu in (0.25, 0.3):
        out(f"circle axis nu {nu} {circle_axis_max_shear(nu)}")
    out(f"line {line_max_shear()}")
    out(f"LP circle {lundberg_palmgren_circle()}")


if __name__ == "__main__":  # pragma: no cover
    main()
