"""
Axial stiffness of a preloaded pair of tapered roller bearings
==============================================================

Two tapered roller bearings (17 rollers of 10 mm mean diameter, 15 mm effective length,
15 deg cup angle) back-to-back at one seat of a shaft (``roller.TaperedPair``), with an
axial preload P.  At zero external load both rows carry P; a small axial load on the shaft
loads one row and relieves the other, so the pair's axial stiffness is twice that of one
row at its preload deflection.

With straight rollers every slice of every roller carries the same load, so one row's
thrust is F = Z n_s c (x sin a)^(10/9) sin a (lamina model, x the cone's axial
displacement beyond touching) and the pair's stiffness at zero load is

    K = 2 dF/dx = (20/9) P / x_0(P),   x_0 = (P / (Z n_s c sin a))^(9/10) / sin a,

growing as P^(1/10): preload stiffens a line-contact pair much less than a ball pair
(P^(1/3)).  The ISO profile (crowned ends) is softer at light preload, where only the
middle of each roller touches.  Right: the shaft's axial deflection under an external
thrust; the relieved row unloads where the curve bends.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import shaft
from ballrace.analytic.roller import RollerBearing, TaperedPair

a = np.radians(15)
bearings = {name: RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered", contact_angle=a,
                                profile=name)
            for name in ("straight", "iso")}
s = shaft.Shaft([(0.2, 0.04, 0.0)], ballrace.BEARING_STEEL)
preloads = np.array([250.0, 500.0, 1000.0, 2000.0, 4000.0, 8000.0])
K = {}
for name, b in bearings.items():
    K[name] = np.array([shaft.solve(s, [shaft.Seat(0.05, TaperedPair(b, "DB", preload=P),
                                                   row_spacing=0.02)]).seat_stiffness[0][0, 0]
                        for P in preloads])
b = bearings["straight"]
c = b.lamina_stiffness / b.n_slices
x0 = (preloads / (b.n_rollers * b.n_slices * c * np.sin(a))) ** 0.9 / np.sin(a)
K_formula = 20.0 / 9.0 * preloads / x0
for P, ks, ki in zip(preloads, K["straight"], K["iso"]):
    print(f"P = {P:6.0f} N: K_axial = {ks / 1e6:7.1f} N/um (straight), "
          f"{ki / 1e6:7.1f} N/um (ISO profile)")

# %%
# Axial deflection of the shaft under an external thrust, three preloads (ISO profile).
Fa = np.linspace(0.0, 12000.0, 13)
curves = {}
for P in (0.0, 1000.0, 4000.0):
    pair = TaperedPair(bearings["iso"], "DB", preload=P)
    seats = [shaft.Seat(0.05, pair, row_spacing=0.02)]
    prev, xs = None, []
    for F in Fa:
        prev = shaft.solve(s, seats, [shaft.PointLoad(0.05, Fa=F)], initial=prev)
        xs.append(prev.ring_displacements[0, 0])
    curves[P] = np.array(xs)

fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
ax[0].loglog(preloads, K_formula / 1e6, "k-", lw=0.8, label="straight, closed form")
ax[0].loglog(preloads, K["straight"] / 1e6, "o", label="straight, shaft solve")
ax[0].loglog(preloads, K["iso"] / 1e6, "s", label="ISO profile, shaft solve")
ax[0].set(xlabel="preload P [N]", ylabel="axial stiffness [N/um]",
          title="pair at zero external load")
ax[0].legend(fontsize=8)
for axis in (ax[0].xaxis, ax[0].yaxis):
    axis.set_minor_formatter(plt.NullFormatter())
    axis.set_major_formatter(plt.ScalarFormatter())
for P, xs in curves.items():
    ax[1].plot(Fa / 1e3, xs * 1e6, marker=".", label=f"P = {P:.0f} N")
ax[1].set(xlabel="external thrust [kN]", ylabel="axial deflection [um]",
          title="load-deflection (ISO profile)")
ax[1].legend(fontsize=8)
fig.tight_layout()

# Key numbers (tests/test_gallery.py): the straight pair's stiffness against the closed
# form, and the stiffening with preload.
KEY = {"preloads": preloads, "K_straight": K["straight"], "K_iso": K["iso"],
       "K_formula": K_formula, "thrust": Fa, "deflection": curves}
