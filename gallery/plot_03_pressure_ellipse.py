"""
The pressure ellipse
====================

Hertz's pressure on the contact ellipse is a semi-ellipsoid,
p(x, y) = p_max sqrt(1 - (x/a_x)^2 - (y/a_y)^2).  Here for the 209 inner-race contact at
4450 N; the ellipse's semi-axes are marked and the pressure integrates back to the load.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import hertz

steel = ballrace.Material(E=200e9, nu=0.3)
D = 12.7e-3
c = hertz.point_contact(4450.0, D / 2, D / 2, 26.15e-3, -0.52 * D, steel, steel)
ax_, ay_ = float(c.semi_axis_x), float(c.semi_axis_y)   # rolling (x) and transverse (y) [m]

n = 801
x = np.linspace(-1.1 * ax_, 1.1 * ax_, n)
y = np.linspace(-1.1 * ay_, 1.1 * ay_, n)
X, Y = np.meshgrid(x, y, indexing="xy")
P = c.pressure(X, Y)                                     # Pa, zero outside the ellipse
load = float(np.sum(P) * (x[1] - x[0]) * (y[1] - y[0]))  # midpoint rule [N]
print(f"a = {ay_ * 1e3:.3f} mm across, b = {ax_ * 1e3:.4f} mm along rolling, "
      f"p_max = {float(c.p_max) / 1e9:.3f} GPa")
print(f"integral of p over the ellipse = {load:.1f} N (load 4450 N)")

fig, ax = plt.subplots(figsize=(8, 4))
cf = ax.contourf(Y * 1e3, X * 1e3, P / 1e9, levels=np.linspace(0, float(c.p_max) / 1e9, 12),
                 cmap="viridis")
t = np.linspace(0, 2 * np.pi, 361)
ax.plot(ay_ * np.cos(t) * 1e3, ax_ * np.sin(t) * 1e3, "r", lw=1.5, label="Hertz ellipse")
ax.annotate("", xy=(ay_ * 1e3, 0), xytext=(0, 0), arrowprops={"arrowstyle": "<->"})
ax.text(ay_ * 0.5e3, 0.02 * ax_ * 1e3, "a", ha="center", va="bottom")
ax.annotate("", xy=(0, ax_ * 1e3), xytext=(0, 0), arrowprops={"arrowstyle": "<->"})
ax.text(0.02 * ay_ * 1e3, ax_ * 0.5e3, "b", ha="left", va="center")
ax.set(xlabel="y, transverse [mm]", ylabel="x, rolling [mm]",
       title="contact pressure [GPa], 209 inner race, 4450 N")
ax.set_aspect("equal")
fig.colorbar(cf, ax=ax, orientation="horizontal", pad=0.2, label="p [GPa]")
ax.legend(loc="upper right")

# Key number: the pressure integrates to the load (p_max = 3Q/(2 pi a b)).
KEY = {"load": load, "p_max": float(c.p_max)}
