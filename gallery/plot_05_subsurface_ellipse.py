"""
Orthogonal shear below an elliptical contact
============================================

Lundberg & Palmgren (1947) based bearing life on the orthogonal shear tau_xz (their
tau_yz, their y being the rolling direction): as the ball rolls over a point it swings
from -tau0 to +tau0, the largest stress *range* below the contact.  Here the 209
inner-race contact at 4450 N (a/b ≈ 9): the field on the section y = 0 with LP's closed-form
(±x0, z0) marked, and LP's tau0 against the largest absolute tau_xz found on the grid.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import hertz, subsurface

steel = ballrace.Material(E=200e9, nu=0.3)
D = 12.7e-3
c = hertz.point_contact(4450.0, D / 2, D / 2, 26.15e-3, -0.52 * D, steel, steel)
b, p0 = float(c.b), float(c.p_max)
osh = subsurface.orthogonal_shear(c)
print(f"a/b = {float(c.k):.3f}, b = {b * 1e3:.4f} mm, p0 = {p0 / 1e9:.3f} GPa")
print(f"LP: tau0 = {float(osh.tau0) / p0:.4f} p0 at z0 = {float(osh.z0) / b:.4f} b, "
      f"x0 = ±{float(osh.x0) / b:.4f} b")

x = np.linspace(-2.0, 2.0, 161) * b
z = np.linspace(0.01, 1.5, 150) * b
X, Z = np.meshgrid(x, z)
s = subsurface.stress(c, X, 0.0 * X, Z, nu=0.3)
T = s.sxz / p0
grid_max = float(np.max(np.abs(T)))
print(f"largest |tau_xz| on the grid = {grid_max:.4f} p0")

fig, axes = plt.subplots(1, 2, figsize=(11, 3.6), sharey=True)
lim = np.max(np.abs(T))
cf = axes[0].contourf(X / b, Z / b, T, levels=np.linspace(-lim, lim, 17), cmap="RdBu_r")
axes[0].plot([float(osh.x0) / b, -float(osh.x0) / b], [float(osh.z0) / b] * 2, "ko")
axes[0].set(title="tau_xz / p0 (LP's ±x0, z0 marked)", xlabel="x / b (rolling)",
            ylabel="depth z / b")
fig.colorbar(cf, ax=axes[0])
V = s.von_mises / p0
cf = axes[1].contourf(X / b, Z / b, V, levels=15, cmap="jet")
vm = subsurface.von_mises(c, nu=0.3)
axes[1].plot([0.0], [float(vm.depth) / b], "wo", mec="k")
axes[1].set(title="von Mises / p0 (maximum marked)", xlabel="x / b (rolling)")
fig.colorbar(cf, ax=axes[1])
axes[0].invert_yaxis()
fig.tight_layout()

KEY = {"tau0": float(osh.tau0) / p0, "grid_max": grid_max, "z0": float(osh.z0) / b}
