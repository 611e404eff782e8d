"""
An FE check next to the analytic field
======================================

The finite-element model of :mod:`ballrace.fem` solves the ball–race contact without
assuming Hertz's answer: a quarter model of the race meshed with gmsh, quadratic
tetrahedra in scikit-fem and frictionless unilateral contact.  Here the 209 inner-race
contact at 4450 N at the ``quick`` mesh level (a smoke level: about 15 s of CPU): the FE
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
print(f"{'quantity':>16s} {'FE':>10s} {'analytic':>10s}  unit  error    tolerance")
for row in r.comparison:
    tol = f"±{100 * row['tol']:.0f} %" if row["tol"] is not None else "—"
    print(f"{row['quantity']:>16s} {row['fe']:10.4g} {row['analytic']:10.4g} {row['unit']:>4s}"
          f" {100 * row['error']:+6.2f} %  {tol}")

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

fig = plt.figure(figsize=(12, 8.5))
grid = fig.add_gridspec(2, 2, height_ratios=[1.0, 0.9])
for k, (png, title) in enumerate(((png_p, "FE: contact pressure, Hertz ellipse in red"),
                                  (png_t, "FE: tau_xz on y = 0 (LP's ±x0, z0 as dots)"))):
    ax = fig.add_subplot(grid[0, k])
    ax.imshow(mpimg.imread(png))
    ax.set_title(title)
    ax.axis("off")
ax = fig.add_subplot(grid[1, :])
lim = np.max(np.abs(T))
cf = ax.contourf(X * 1e3, -Z * 1e3, T, levels=np.linspace(-lim, lim, 17), cmap="RdBu_r")
ax.plot(np.array([1, -1]) * float(osh.x0) * 1e3, [-float(osh.z0) * 1e3] * 2, "ko")
ax.set(title="analytic tau_xz [MPa] on y = 0 (same section and scale as the FE render)",
       xlabel="x, rolling [mm]", ylabel="z [mm]")
ax.set_aspect("equal")
fig.colorbar(cf, ax=ax, orientation="vertical", shrink=0.8)
fig.tight_layout()

# %%
# The analytic Hertz pressure of the same contact as a 3-D surface (pyvista, off-screen;
# the gallery's pyvista scraper picks the plotter up): the long, low ellipse of a ball in a
# conformal groove, heights exaggerated.
import pyvista as pv

xs = np.linspace(-1.0, 1.0, 81) * float(c.semi_axis_x)
ys = np.linspace(-1.0, 1.0, 161) * float(c.semi_axis_y)
XX, YY = np.meshgrid(xs, ys, indexing="ij")
PP = c.pressure(XX, YY)
hill = pv.StructuredGrid(XX * 1e3, YY * 1e3, PP / float(c.p_max) * 0.6)
hill["p [GPa]"] = (PP / 1e9).ravel(order="F")
pl = pv.Plotter(off_screen=True, window_size=(900, 500))
pl.set_background("white")
pl.add_mesh(hill, scalars="p [GPa]", cmap="viridis",
            scalar_bar_args={"color": "black", "title": "Hertz p [GPa]", "vertical": True,
                             "position_x": 0.86, "position_y": 0.15})
pl.add_text("analytic Hertz pressure, 209 inner race, 4450 N (x, y in mm)", font_size=10,
            color="black")
pl.view_isometric()
pl.camera.zoom(1.4)
pl.show()

KEY = {row["quantity"]: (row["error"], row["tol"]) for row in r.comparison}
KEY["passed"] = r.passed
