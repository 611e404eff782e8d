"""
Roller slice loads under tilt: straight, ISO and logarithmic profiles
=====================================================================

A cylindrical roller bearing of the NU 207 size class (14 rollers of 13 x 11.8 mm on a
70.65 mm pitch circle, zero clearance) under 6940 N radial, solved by the lamina model of
ISO/TS 16281 (:meth:`ballrace.analytic.roller.RollerBearing.solve`): each roller is cut
into 31 slices, each slice a spring q = (c_L/n_s) delta^(10/9).  The inner ring is tilted
by 1 mrad about z (imposed, as a shaft would hold it); the roller in the load line sees
half of it.

Without tilt a straight roller carries equal slices (the lamina model knows no edge
stress); with the tilt the load runs to one end.  A crown (ISO/TS 16281's default
profile, or Lundberg's logarithmic profile for the bearing's static-rating load) keeps
the ends lightly loaded and moves the peak inwards.  The pressure peaks at the roller
ends that the elastic half-space adds are the subject of the next example.
"""
import matplotlib.pyplot as plt
import numpy as np

from ballrace.analytic.roller import RollerBearing

TILT = 1e-3                                   # inner-ring tilt theta_z [rad]
profiles = ["straight", "iso", "lundberg"]
fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), sharey=True)
KEY = {}
for ax, prof in zip(axes, profiles):
    b = RollerBearing(roller_diameter=13e-3, roller_length=11.8e-3, n_rollers=14,
                      pitch_diameter=70.65e-3, profile=prof)
    x = b.slice_positions * 1e3               # [mm]
    for tilt, style in ((0.0, "o-"), (TILT, "s--")):
        r = b.solve(Fy=6940.0, displacements=[None, None, None, 0.0, tilt])
        j = int(np.argmax(r.roller_loads))
        q = r.slice_loads[j] / (b.slice_width * 1e3)              # [N/mm]
        ax.plot(x, q, style, ms=3, label=f"tilt {tilt * 1e3:g} mrad (roller {j})")
        print(f"{prof:9s} tilt {tilt * 1e3:g} mrad: Q_max = {r.max_roller_load:7.1f} N, "
              f"end slices {r.slice_loads[j, 0]:6.1f} / {r.slice_loads[j, -1]:6.1f} N, "
              f"edge/mean {float(r.edge_load_ratio[j]):.2f}, "
              f"s0 = {float(r.static_safety):.2f}")
        KEY[(prof, tilt)] = r
    ax.set(title=f"{prof} profile", xlabel="x along the roller [mm]")
    ax.legend(fontsize=8)
axes[0].set_ylabel("slice load per length [N/mm]")
fig.suptitle("Most loaded roller, 6940 N radial: lamina slice loads without and with tilt")
fig.tight_layout()

straight0 = KEY[("straight", 0.0)]
KEY = {
    # a straight untilted roller: every slice alike (Q_j / n_s)
    "straight_spread": float(np.ptp(straight0.slice_loads[0]) / straight0.slice_loads[0].max()),
    # zero clearance, straight rollers: Z Q_max / F_r = 14 / sum cos^(19/9) psi_j
    "straight_zq": 14 * straight0.max_roller_load / 6940.0,
    # the edge ratio under tilt falls from the straight roller to the crowned ones
    "edge_ratio": {p: float(KEY[(p, TILT)].edge_load_ratio[0]) for p in profiles},
    "tilt_seen": float(KEY[("straight", TILT)].roller_tilts[0]),
}
