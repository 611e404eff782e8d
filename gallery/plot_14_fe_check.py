"""
An FE check next to the analytic field
======================================

The finite-element model of :mod:`ballrace.fem` solves the ball–race contact without
assuming Hertz's answer: a quarter model of the race meshed with gmsh, quadratic
tetrahedra in scikit-fem and frictionless unilateral contact.  Here the 209 inner-race
contact at 4450 N at the ``quick`` mesh level (a smoke level, about 15 s): the FE
renders of the contact pressure and of the orthogonal shear on the section y = 0, next
to the analytic tau_xz field of :func:`ballrace.analytic.subsurface.stress` on the same
section, and the comparison table.  How the model works and what agreement means:
:doc:`/teaching/fem_check`.
"""
import tempfile
from pathlib import Path

import matplotlib.image as mpimg
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace import fem
from ballrace.analytic import subsurface

brg = ballrace.BallBearing(ball_diameter=12.7e-3, n_balls=9, pitch_diameter=65e-3,
                           f_inner=0.52, f_outer=0.52, free_contact_angle=0.0)
r = fem.ball_on_race(brg, 4450.0, race="inner", level="quick")
c = r.analytic
print(f"{r.n_dofs} degrees of freedom, solver {r.solver}")
for row in r.comparison:
    tol = f"±{100 * row['tol']:.0f} %" if row["tol"] is not None else "—"
    print(f"{row['quantity']:>16s}: FE {row['fe']:.4g}  analytic {row['analytic']:.4g} "
          f"[{row['unit']}]  error {100 * row['error']:+6.2f} %  (quick tolerance {tol})")

# %%
# The library's own renders (pyvista, off-screen) beside the analytic field.
out = Path(tempfile.mkdtemp())
png_p = fem.render(r, "pressure", out / "pressure.png")
png_t = fem.render(r, "tau_xz", out / "tau_xz.png")

b, p0 = float(c.b), float(c.p_max)
osh = subsurface.orthogonal_shear(c)
x = np.linspace(-1.6, 1.6, 161) * float(c.semi_axis_x)
z = np.linspace(0.04, 1.6, 79) * b
X, Z = np.meshgrid(x, z)
T = subsurface.stress(c, X, 0.0 * X, Z, nu=brg.ring_material.nu).sxz / 1e6

fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
axes[0].imshow(mpimg.imread(png_p))
axes[0].set_title("FE: contact pressure, Hertz ellipse in red")
axes[1].imshow(mpimg.imread(png_t))
axes[1].set_title("FE: tau_xz on y = 0 (LP's ±x0, z0 as dots)")
for ax in axes[:2]:
    ax.axis("off")
lim = np.max(np.abs(T))
cf = axes[2].contourf(X * 1e3, -Z * 1e3, T, levels=np.linspace(-lim, lim, 17), cmap="RdBu_r")
axes[2].plot(np.array([1, -1]) * float(osh.x0) * 1e3, [-float(osh.z0) * 1e3] * 2, "ko")
axes[2].set(title="analytic tau_xz [MPa] on y = 0", xlabel="x [mm]", ylabel="z [mm]")
axes[2].set_aspect("equal")
fig.colorbar(cf, ax=axes[2], orientation="horizontal", pad=0.25)
fig.tight_layout()

KEY = {row["quantity"]: (row["error"], row["tol"]) for row in r.comparison}
KEY["passed"] = r.passed
