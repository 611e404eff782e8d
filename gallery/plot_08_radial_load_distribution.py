"""
Radial load distribution with clearance
=======================================

The 209 deep-groove bearing of Hamrock & Dowson (1981, Table 3.2: nine 12.7 mm balls on
a 65 mm pitch circle, f = 0.52) under 8900 N radial.  With zero clearance five balls
carry the load, Q_psi = Q_max cos^(3/2) psi (Stribeck), and Z Q_max / F_r = 4.385;
diametral clearance shrinks the loaded zone and raises the most heavily loaded ball.
Jones's closed-form factor Z_w (H&D eq. 3.45) is shown against the exact solution.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import loaddist

Fr = 8900.0
clearances = np.array([0.0, 0.015e-3, 0.05e-3])          # diametral clearance P_d [m]
fig = plt.figure(figsize=(10, 4))
ax_polar = fig.add_subplot(1, 2, 1, projection="polar")
ax_zw = fig.add_subplot(1, 2, 2)
rows = []
for Pd in clearances:
    brg = ballrace.BallBearing(ball_diameter=12.7e-3, n_balls=9, pitch_diameter=65e-3,
                               f_inner=0.52, f_outer=0.52, diametral_clearance=Pd)
    ld = brg.radial(Fr)
    Q = np.asarray(ld.ball_loads)
    ratio = brg.n_balls * float(ld.max_ball_load) / Fr
    dr = float(ld.radial_deflection)
    zw = float(loaddist.jones_radial_factor(Pd / (2 * dr)))
    rows.append((Pd, ratio, zw, float(ld.loaded_zone)))
    psi = np.append(ld.azimuths, ld.azimuths[0])
    ax_polar.plot(psi, np.append(Q, Q[0]), "o-", label=f"P_d = {Pd * 1e3:.3f} mm")
    print(f"P_d = {Pd * 1e3:.3f} mm: Q_max = {float(ld.max_ball_load):.0f} N, "
          f"Z Q_max/F_r = {ratio:.4f} (Jones Z_w = {zw:.4f}), "
          f"loaded zone ±{np.degrees(float(ld.loaded_zone)):.1f} deg")
ax_polar.set_theta_zero_location("N")
ax_polar.set_title("ball loads [N] around the bearing", pad=18)
ax_polar.legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.25, -0.2))

# Z Q_max / F_r against clearance: the exact solver and Jones's fit.
Pd = np.linspace(0.0, 0.08e-3, 17)
exact, jones = [], []
for p in Pd:
    brg = ballrace.BallBearing(ball_diameter=12.7e-3, n_balls=9, pitch_diameter=65e-3,
                               f_inner=0.52, f_outer=0.52, diametral_clearance=p,
                               nominal_contact_angle=0.0)   # radial, even at 80 um
    ld = brg.radial(Fr)
    exact.append(9 * float(ld.max_ball_load) / Fr)
    jones.append(float(loaddist.jones_radial_factor(p / (2 * float(ld.radial_deflection)))))
ax_zw.plot(Pd * 1e3, exact, "o-", label="exact (9 balls)")
ax_zw.plot(Pd * 1e3, jones, "--", label="Jones Z_w (H&D eq. 3.45)")
ax_zw.set(xlabel="diametral clearance P_d [mm]", ylabel="Z Q_max / F_r",
          title="209 bearing, F_r = 8900 N")
ax_zw.legend()
fig.tight_layout()

KEY = {"ratio_zero_clearance": rows[0][1], "jones_vs_exact_15um": rows[1][2] / rows[1][1] - 1}
