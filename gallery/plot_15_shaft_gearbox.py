"""
A gearbox shaft on two deep-groove bearings
===========================================

A 260 mm stepped shaft on two 6208-size deep-groove bearings, a helical gear between them
(F_t = 5 kN on a 120 mm pitch circle, 20 deg pressure angle, 15 deg helix).  Bearing A
locates the shaft axially, bearing B floats in its housing bore.  The shaft and both
bearings are solved together (``ballrace.analytic.shaft``): the gear's axial force goes to
bearing A alone, which it turns into an angular-contact bearing (contact angles of
about 13-17 deg), and the moment of that force at the pitch radius tilts the shaft.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import shaft

brg = ballrace.BallBearing(12.7e-3, 9, 60e-3, 0.52, 0.525, diametral_clearance=15e-6)
s = shaft.Shaft([(0.03, 0.04, 0.0), (0.2, 0.048, 0.0), (0.03, 0.04, 0.0)],
                ballrace.Material(E=210e9, nu=0.3, density=7850.0))
seats = [shaft.Seat(0.015, brg, name="A"), shaft.Seat(0.245, brg, floating=True, name="B")]
gear = shaft.gear_mesh(0.09, 5000.0, 0.12, helix_angle=np.radians(15),
                       mesh_azimuth=np.radians(90))
r = shaft.solve(s, seats, [gear])
for seat, R, b in zip(seats, r.reactions, r.bearings):
    print(f"{seat.name}: Fa {R[0]:8.1f} N  Fy {R[1]:8.1f} N  Fz {R[2]:8.1f} N  "
          f"Q_max {b.max_ball_load:6.0f} N  beta {np.degrees(b.contact_angles.max()):5.1f} deg")

# %%
# The deflection line (the bearings' own deflections included) and the ball loads.
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
for seat, b in zip(seats, r.bearings):
    ax[1].bar(np.degrees(b.azimuths) + (5 if seat.name == "B" else -5), b.ball_loads, width=10,
              label=seat.name)
ax[1].set(xlabel="ball azimuth [deg]", ylabel="ball load [N]", title="ball loads")
ax[1].legend()
fig.tight_layout()

# Key numbers (tests/test_gallery.py): statics of the gear forces against the reactions.
KEY = {"reactions": r.reactions, "gear": gear.vector, "x_gear": gear.position,
       "x_seats": [seat.position for seat in seats]}
