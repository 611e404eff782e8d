"""
Edge pressure along a roller: the half-space line contact beside the lamina slices
==================================================================================

The lamina model of ISO/TS 16281 treats the slices of a roller as independent springs, so
a straight roller carries the same pressure on every slice, right up to its ends.  On an
elastic half-space the slices are coupled: a straight roller on a longer raceway has a
pressure peak at each end (singular at a sharp edge; its height on a slice grows as the
slices narrow), a crown removes it, and Lundberg's logarithmic profile at its design load
gives the same pressure along the whole roller.

The bearing of the previous example (zero clearance, 6940 N radial) with three rollers:
straight, a circular crown (6 mm flat, 0.3 m crown radius) and Lundberg's profile designed
for the load of the most loaded roller.  For that roller the lamina pressures
(:meth:`~ballrace.analytic.roller.loaddist.RollerLoadDistribution.slice_pressures`, each
slice a 2-D Hertz contact) are drawn as steps, and the finite line contact at the inner
raceway at the same load and tilt
(:meth:`~ballrace.analytic.roller.loaddist.RollerLoadDistribution.roller_contact`,
:func:`ballrace.analytic.roller.line_contact`) as points, at the lamina's 31 slices and
at 121 slices.
"""
import math

import matplotlib.pyplot as plt
import numpy as np

from ballrace.analytic.roller import Crowned, Lundberg, RollerBearing

GEOMETRY = dict(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=14,
                pitch_diameter=70.65e-3)
FR = 6940.0


def lundberg_bearing():
    """Lundberg's profile designed for the load its most loaded roller then carries (a
    fixed point: the crown changes the load distribution a little)."""
    Qd = 4.0855 * FR / 14                     # Stribeck's number as the start
    for _ in range(20):
        b = RollerBearing(**GEOMETRY, profile=Lundberg(design_load=Qd))
        Q = b.solve(Fy=FR).max_roller_load
        if abs(Q / Qd - 1) < 1e-10:
            break
        Qd = Q
    return b


bearings = {"straight": RollerBearing(**GEOMETRY, profile="straight"),
            "crowned (6 mm flat, R = 0.3 m)": RollerBearing(
                **GEOMETRY, profile=Crowned(flat_length=6e-3, crown_radius=0.3)),
            "Lundberg (designed for Q_max)": lundberg_bearing()}
fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), sharey=True)
KEY = {}
for ax, (name, b) in zip(axes, bearings.items()):
    r = b.solve(Fy=FR)
    j = int(np.argmax(r.roller_loads))
    lam = r.slice_pressures("inner")[j]
    c31 = r.roller_contact(j, "inner")
    c121 = r.roller_contact(j, "inner", n_slices=121)
    x = b.slice_positions * 1e3
    w = b.slice_width * 1e3
    ax.stairs(lam / 1e6, np.append(x - w / 2, x[-1] + w / 2), color="0.4",
              label="lamina (ISO/TS 16281)")
    ax.plot(c31.x * 1e3, c31.pressure / 1e6, "o", ms=4, label="half-space, 31 slices")
    ax.plot(c121.x * 1e3, c121.pressure / 1e6, ".-", ms=2, lw=0.8,
            label="half-space, 121 slices")
    p0 = math.sqrt(r.inner_loads[j] / b.roller_length * b.E_prime
                   / (2 * math.pi * b.inner_radius))
    ax.axhline(p0 / 1e6, color="k", lw=0.6, ls=":", label="2-D Hertz at Q/L")
    ax.set(title=name, xlabel="x along the roller [mm]")
    mid = np.abs(c121.x) <= 0.4 * b.roller_length
    KEY[name] = {"end_over_lamina": float(c31.pressure[0] / lam[0]) if lam[0] > 0 else 0.0,
                 "peak_31": c31.max_pressure, "peak_121": c121.max_pressure,
                 "lamina_peak": float(lam.max()), "p0": p0,
                 "uniformity_121": float(np.max(np.abs(c121.pressure[mid] / p0 - 1))),
                 "s0": float(r.static_safety)}
    print(f"{name:32s}: Q = {r.inner_loads[j]:7.1f} N, lamina peak "
          f"{lam.max() / 1e6:6.0f} MPa, half-space peak {c31.max_pressure / 1e6:6.0f} MPa "
          f"(31 slices) / {c121.max_pressure / 1e6:6.0f} MPa (121), "
          f"2-D Hertz at Q/L {p0 / 1e6:6.0f} MPa")
axes[0].set_ylabel("contact pressure [MPa]")
axes[0].legend(fontsize=7, loc="lower center")
fig.suptitle("Inner contact of the most loaded roller, 6940 N radial")
fig.tight_layout()
