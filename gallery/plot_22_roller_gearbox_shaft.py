"""
A gearbox shaft on a ball and a cylindrical roller bearing
==========================================================

The shaft of ``plot_15`` with its floating bearing replaced by a cylindrical roller
bearing (NU 207 size: 14 rollers of 13 mm, 11.8 mm effective length, ISO/TS 16281's
default profile, 31 slices).  The deep-groove ball bearing A locates the shaft; the
cylindrical roller bearing B carries radial load and tilting moment but no axial load (its
flanges are not modelled, so it does not locate the shaft).  Shaft, ball bearing and
roller bearing are solved together (``ballrace.analytic.shaft``); each roller of B is cut
into slices (the lamina model of ISO/TS 16281).  At this load (some 850 N on the most
loaded roller) the crowned rollers carry over their middle only, and the shaft's slope
at B (about 0.2 mrad) barely shifts the slice loads off centre.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import shaft
from ballrace.analytic.roller import RollerBearing

ball = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
cyl = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=20e-6)
s = shaft.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)],
                ballrace.Material(E=210e9, nu=0.3, density=7850.0))
seats = [shaft.Seat(0.015, ball, name="A (ball)"), shaft.Seat(0.245, cyl, name="B (roller)")]
gear = shaft.gear_mesh(0.09, 5000.0, 0.12, helix_angle=np.radians(15),
                       mesh_azimuth=np.radians(90))
r = shaft.solve(s, seats, [gear])
lives = shaft.rating_lives(r)
for seat, R, L in zip(seats, r.reactions, lives.seat_lives):
    print(f"{seat.name}: Fa {R[0]:8.1f} N  Fy {R[1]:8.1f} N  Fz {R[2]:8.1f} N  "
          f"L10r {L:10.0f} x 1e6 rev")
print(f"system life (ball e = 10/9, roller e = 9/8): {lives.system:.0f} x 1e6 rev")
roller = r.bearings[1]

# %%
# The deflection line (bearing deflections included) and the slice loads of the loaded
# rollers of bearing B, from one end of the roller to the other.
x = np.linspace(0.0, s.length, 300)
d = r.displacement(x)
fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
ax[0].plot(x * 1e3, d[:, 1] * 1e6, label="v (y)")
ax[0].plot(x * 1e3, d[:, 2] * 1e6, label="w (z)")
for seat in seats:
    ax[0].axvline(seat.position * 1e3, color="grey", lw=0.8)
ax[0].axvline(gear.position * 1e3, color="C3", lw=0.8, ls="--")
ax[0].set(xlabel="x [mm]", ylabel="deflection [um]", title="shaft axis")
ax[0].legend()
xs = cyl.slice_positions * 1e3
for j in np.flatnonzero(roller.roller_loads > 0):
    ax[1].plot(xs, roller.slice_loads[j], marker=".",
               label=f"roller {j} ({np.degrees(roller.azimuths[j]):.0f} deg)")
ax[1].set(xlabel="position along the roller [mm]", ylabel="slice load [N]",
          title="bearing B: slice loads")
ax[1].legend(fontsize=7)
fig.tight_layout()

# Key numbers (tests/test_gallery.py): statics of the gear forces against the reactions,
# and the roller seat's reaction rebuilt from its slice loads.
KEY = {"reactions": r.reactions, "gear": gear.vector, "x_gear": gear.position,
       "x_seats": [seat.position for seat in seats], "slice_loads": roller.slice_loads,
       "azimuths": roller.azimuths, "roller_loads": roller.roller_loads,
       "ring_displacement": r.ring_displacements[1], "system": lives.system,
       "seat_lives": lives.seat_lives}
