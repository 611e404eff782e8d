"""
Traction moves the critical point to the surface
================================================

A tangential traction q = mu p on a Hertz contact (sliding, EHL shear, skidding) adds to
the subsurface stresses.  Below a critical traction coefficient the maximum von Mises
stress stays below the surface; above it the surface carries the largest stress, which is
why surface-initiated fatigue exists.  Johnson (1985, *Contact Mechanics* §7.2) gives
about 0.25-0.3 for the line and the circle.

Left: the circle (a 12.7 mm ball on a flat, 2 kN), the von Mises maximum and its depth as
the traction grows.  Right: the critical coefficient of the line contact against
Poisson's ratio (plane strain), :func:`ballrace.analytic.subsurface.critical_traction`.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import hertz, subsurface

steel = ballrace.Material(E=200e9, nu=0.3)
c = hertz.point_contact(2000.0, 6.35e-3, 6.35e-3, np.inf, np.inf, steel)
b, p0 = float(c.b), float(c.p_max)
mus = np.array([0.0, 0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5])
vm = [subsurface.von_mises(c, nu=0.3, traction=m) for m in mus]
value = np.array([float(v.sigma_vm) / p0 for v in vm])
depth = np.array([float(v.depth) / b for v in vm])
for m, v, d in zip(mus, value, depth):
    print(f"traction {m:4.2f}: von Mises max {v:.4f} p0 at depth {d:.4f} b")

# %%
# The line contact: the critical coefficient against nu.
nus = np.array([0.25, 0.3, 0.35])
mu_c = np.array([float(subsurface.critical_traction(0.0, nu=n)) for n in nus])
for n, m in zip(nus, mu_c):
    print(f"line contact, nu = {n:.2f}: von Mises maximum at the surface above mu = {m:.4f}")

fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
ax[0].plot(mus, value, "o-", label="von Mises max / p0")
ax2 = ax[0].twinx()
ax2.plot(mus, depth, "s--", color="tab:red", label="its depth / b")
ax[0].set(xlabel="traction coefficient mu", ylabel="stress / p0",
          title="circle: the maximum climbs to the surface")
ax2.set_ylabel("depth / b")
ax[0].legend(loc="upper left", fontsize=8)
ax2.legend(loc="upper right", fontsize=8)
ax[1].plot(nus, mu_c, "o-")
ax[1].axhspan(0.25, 0.3, color="0.9", label="Johnson (1985): about 0.25-0.3")
ax[1].set(xlabel="Poisson's ratio nu", ylabel="critical traction mu_c",
          title="line contact (von Mises)")
ax[1].legend(fontsize=8)
fig.tight_layout()

KEY = {"mus": mus, "value": value, "depth": depth, "nus": nus, "mu_c": mu_c}
