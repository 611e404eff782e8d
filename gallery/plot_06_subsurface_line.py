"""
Stresses below a line contact
=============================

The plane-strain limit (McEwen 1949): a cylinder on a block, here the NAFEMS FENET
D3613 benchmark (aluminium cylinder R = 50 mm on a steel block, 35 kN/mm), whose Hertz
reference is p0 = 3585 MPa over a half-width b = 6.21 mm.  Johnson (1985, §4.2) gives
the maxima: tau_max = 0.30 p0 at z = 0.78 b on the axis, and the orthogonal shear
tau_xz = 0.25 p0 at z = 0.5 b, x = ±0.87 b.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import hertz, subsurface

alu = ballrace.Material(E=70e9, nu=0.3)
steel = ballrace.Material(E=210e9, nu=0.3)
lc = hertz.line_contact(35e6, 50e-3, np.inf, alu, steel)      # N/m, m
b, p0 = float(lc.b), float(lc.p_max)
ms = subsurface.line_max_shear(lc)
osh = subsurface.line_orthogonal_shear(lc)
print(f"b = {b * 1e3:.3f} mm, p0 = {p0 / 1e6:.0f} MPa (NAFEMS: 6.21 mm, 3585 MPa)")
print(f"tau_max = {float(ms.tau_max) / p0:.4f} p0 at z = {float(ms.depth) / b:.4f} b")
print(f"tau_xz max = {float(osh.tau0) / p0:.4f} p0 at z = {float(osh.z0) / b:.4f} b, "
      f"x = ±{float(osh.x0) / b:.4f} b")

x = np.linspace(-2.0, 2.0, 201) * b
z = np.linspace(0.005, 2.0, 160) * b
X, Z = np.meshgrid(x, z)
s = subsurface.line_stress(lc, X, Z, nu=0.3)
panels = [("Tresca tau_max / p0", s.tresca / p0, [(0.0, float(ms.depth))]),
          ("von Mises / p0", s.von_mises / p0, []),
          ("tau_xz / p0", s.sxz / p0, [(float(osh.x0), float(osh.z0)),
                                       (-float(osh.x0), float(osh.z0))])]
fig, axes = plt.subplots(1, 3, figsize=(12, 3.4), sharey=True)
for ax, (title, F, marks) in zip(axes, panels):
    odd = "xz" in title
    lim = float(np.max(np.abs(F)))
    levels = np.linspace(-lim, lim, 17) if odd else 15
    cf = ax.contourf(X / b, Z / b, F, levels=levels, cmap="RdBu_r" if odd else "jet")
    for xm, zm in marks:
        ax.plot(xm / b, zm / b, "wo", mec="k")
    ax.set(title=title, xlabel="x / b")
    fig.colorbar(cf, ax=ax)
axes[0].set_ylabel("depth z / b")
axes[0].invert_yaxis()
fig.tight_layout()

KEY = {"b": b, "p_max": p0, "tau_max": float(ms.tau_max) / p0, "depth": float(ms.depth) / b,
       "tau0": float(osh.tau0) / p0, "z0": float(osh.z0) / b, "x0": float(osh.x0) / b}
