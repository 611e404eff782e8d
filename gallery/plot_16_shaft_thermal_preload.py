"""
A preloaded O pair loses its preload as the shaft warms
=======================================================

Two 40 deg angular-contact bearings 160 mm apart on a 40 mm shaft, mounted back-to-back
(O arrangement) and adjusted with an axial offset of 8 um each.  When the shaft runs
warmer than the housing it grows between the bearings by alpha dT L and relieves both:
the preload vanishes when alpha dT L / 2 equals the offset (then no force is left, the
shaft is at its free length and both bearings just touch), at
dT* = 2 offset / (alpha L) = 8.7 K here.  ``ballrace.analytic.shaft`` solves the shaft with
the thermal strain and both bearings at each temperature.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import shaft

brg = ballrace.BallBearing(20.638e-3, 13, 87.5e-3, 0.52, 0.52, free_contact_angle=np.radians(40))
alpha, L, offset = 11.5e-6, 0.16, 8e-6
s = shaft.Shaft([(0.2, 40e-3, 0.0)], ballrace.BEARING_STEEL, thermal_expansion=alpha)
seats = [shaft.Seat(0.02, brg, direction=1, offset=offset),
         shaft.Seat(0.18, brg, direction=-1, offset=offset)]
load = [shaft.PointLoad(0.1, Fy=1e-3)]                       # a token load: axial only
dT_star = 2 * offset / (alpha * L)
dT = np.linspace(0.0, 1.2 * dT_star, 25)
preload = np.array([shaft.solve(s, seats, load, shaft_temperature_change=t).reactions[0, 0]
                    for t in dT])
P0 = preload[0]
P_star = shaft.solve(s, seats, load, shaft_temperature_change=dT_star).reactions[0, 0]
print(f"preload at assembly temperature: {P0:.0f} N; vanishes at dT* = {dT_star:.2f} K "
      f"(solved: {P_star:.2e} N there)")

fig, ax = plt.subplots(figsize=(6.5, 4))
ax.plot(dT, preload, "o-", ms=3)
ax.axvline(dT_star, color="grey", ls="--", lw=0.8, label="2 offset / (alpha L)")
ax.set(xlabel="shaft warmer than housing, dT [K]", ylabel="axial preload [N]",
       title="O arrangement, 8 um offset per bearing")
ax.legend()

KEY = {"P0": P0, "P_star": P_star, "dT_star": dT_star,
       "P_95": float(np.interp(0.95 * dT_star, dT, preload))}
