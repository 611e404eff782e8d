"""
A preloaded pair
================

Two angular-contact bearings mounted back to back (DB) with an axial preload: an
external thrust loads one bearing and relieves the other until, at the unloading load,
the second separates.  Tata (2012) gives a spindle with 3000 lb preload and a 2500 lb work
load whose bearings end at about 4500 lb and 2000 lb (Tata rounds to 500 lb).  The bearing
is assumed (Tata gives only the 55 mm bore): 7211-size, 40 deg, thirteen 20.638 mm balls.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic.duplex import DuplexPair

lbf = 4.4482216152605                                     # N
brg = ballrace.BallBearing(ball_diameter=20.638e-3, n_balls=13, pitch_diameter=87.5e-3,
                           f_inner=0.52, f_outer=0.52, free_contact_angle=np.radians(40))
pair = DuplexPair(brg, "DB", preload=3000 * lbf)
r = pair.solve(Fa=2500 * lbf)
F1, F2 = (float(v) / lbf for v in r.axial_loads)
print(f"bearing 1 carries {F1:.0f} lb, bearing 2 {F2:.0f} lb (Tata: 4500 / 2000 lb)")
print(f"unloading load: {float(pair.unloading_load) / lbf:.0f} lb")

Fa = np.linspace(0.0, 1.3 * float(pair.unloading_load), 60)
loads = np.array([np.asarray(pair.solve(Fa=F).axial_loads) for F in Fa])
fig, ax = plt.subplots(figsize=(6.5, 4))
ax.plot(Fa / lbf, loads[:, 0] / lbf, label="bearing 1 (loaded by F_a)")
ax.plot(Fa / lbf, loads[:, 1] / lbf, label="bearing 2 (relieved)")
ax.plot(Fa / lbf, Fa / lbf, "k:", lw=0.8, label="F_a (no preload)")
ax.axvline(float(pair.unloading_load) / lbf, color="grey", ls="--", lw=0.8)
ax.set(xlabel="external thrust F_a [lbf]", ylabel="axial load in bearing [lbf]",
       title="DB pair, 3000 lbf preload")
ax.legend()

KEY = {"F1": F1 * lbf, "F2": F2 * lbf}
