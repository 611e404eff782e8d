"""
Stresses below a circular contact
=================================

A 12.7 mm steel ball on a steel flat at 2000 N: a circular contact.  On the axis the
maximum shear stress (Tresca) peaks at 0.31 p0 about half a contact radius below the
surface (Johnson 1985, §3.4, nu = 0.3); von Mises peaks at the same depth.  The
orthogonal shear tau_xz vanishes on the axis and peaks off it, at (±x0, z0).
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import hertz, subsurface

steel = ballrace.Material(E=200e9, nu=0.3)
c = hertz.point_contact(2000.0, 6.35e-3, 6.35e-3, np.inf, np.inf, steel, steel)
a, p0 = float(c.a), float(c.p_max)
ms = subsurface.max_shear(c, nu=0.3)
vm = subsurface.von_mises(c, nu=0.3)
osh = subsurface.orthogonal_shear(c)
print(f"a = {a * 1e3:.4f} mm, p0 = {p0 / 1e9:.3f} GPa")
print(f"tau_max = {float(ms.tau_max) / p0:.4f} p0 at z = {float(ms.depth) / a:.4f} a")
print(f"von Mises = {float(vm.sigma_vm) / p0:.4f} p0 at z = {float(vm.depth) / a:.4f} a")
print(f"tau0 = {float(osh.tau0) / p0:.4f} p0 at z0 = {float(osh.z0) / a:.4f} a, "
      f"x0 = {float(osh.x0) / a:.4f} a")

# %%
# The section y = 0 through the centre, in units of a and p0.
x = np.linspace(-2.0, 2.0, 121) * a
z = np.linspace(0.005, 1.6, 81) * a
X, Z = np.meshgrid(x, z)
s = subsurface.stress(c, X, 0.0 * X, Z, nu=0.3)
fields = [("Tresca tau_max / p0", s.tresca / p0, ms.depth, 0.0),
          ("von Mises / p0", s.von_mises / p0, vm.depth, 0.0),
          ("tau_xz / p0", s.sxz / p0, osh.z0, osh.x0)]
fig, axes = plt.subplots(1, 3, figsize=(12, 3.4), sharey=True)
for ax, (title, F, depth, x0) in zip(axes, fields):
    lim = np.max(np.abs(F))
    cf = ax.contourf(X / a, Z / a, F, levels=15, cmap="RdBu_r" if "xz" in title else "jet",
                     vmin=-lim if "xz" in title else None, vmax=lim if "xz" in title else None)
    ax.plot(np.array([1, -1]) * float(x0) / a if x0 else [0.0],
            [float(depth) / a] * (2 if x0 else 1), "wo", mec="k")
    ax.set(title=title, xlabel="x / a")
    fig.colorbar(cf, ax=ax)
axes[0].set_ylabel("depth z / a")
axes[0].invert_yaxis()
fig.tight_layout()

# %%
# Depth profiles on the axis (closed form).
zz = np.linspace(0.0, 3.0, 301) * a
ax_st = subsurface.axis_stress(c, zz, nu=0.3)
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(ax_st.tresca / p0, zz / a, label="Tresca tau_max")
ax.plot(ax_st.von_mises / p0, zz / a, label="von Mises")
ax.plot(-ax_st.szz / p0, zz / a, "--", label="-sigma_z")
ax.axhline(float(ms.depth) / a, color="k", lw=0.8)
ax.invert_yaxis()
ax.set(xlabel="stress / p0", ylabel="depth z / a", title="on the axis x = y = 0")
ax.legend()

KEY = {"tau_max": float(ms.tau_max) / p0, "depth": float(ms.depth) / a,
       "von_mises": float(vm.sigma_vm) / p0}
