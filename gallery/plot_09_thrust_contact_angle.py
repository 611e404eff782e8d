"""
Thrust load and contact angle
=============================

Under thrust an angular-contact bearing's contact angle grows with the load, from its
free value beta_f towards the point where the ellipse runs over the shoulder.  Here the
218 bearing of Ricci (2009) and Harris (2001): sixteen 22.225 mm balls, d_e = 125.26 mm,
f = 0.5232, beta_f = 40 deg.  Harris (2001, p. 252, chart method) quotes about 41.6 deg at
17,800 N.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace

brg = ballrace.BallBearing(ball_diameter=22.225e-3, n_balls=16, pitch_diameter=125.26e-3,
                           f_inner=0.5232, f_outer=0.5232, free_contact_angle=np.radians(40))
Fa = np.linspace(500.0, 60e3, 60)                        # N
angles, deflection, Qball = [], [], []
for F in Fa:
    r = brg.thrust(F)
    angles.append(np.degrees(float(np.mean(r.contact_angles))))
    deflection.append(float(r.axial_deflection) * 1e6)
    Qball.append(float(r.max_ball_load))

r = brg.thrust(17800.0)
beta = np.degrees(float(np.mean(r.contact_angles)))
print(f"17,800 N: contact angle {beta:.2f} deg (Harris: about 41.6 deg), "
      f"ball load {float(r.max_ball_load):.0f} N, "
      f"axial deflection {float(r.axial_deflection) * 1e6:.2f} um")

fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
ax[0].plot(Fa / 1e3, angles)
ax[0].plot([17.8], [beta], "ko")
ax[0].annotate(f"{beta:.2f} deg at 17.8 kN", (17.8, beta), (25, beta - 0.8))
ax[0].set(xlabel="thrust F_a [kN]", ylabel="contact angle [deg]", title="contact angle")
ax[1].plot(Fa / 1e3, deflection)
ax[1].set(xlabel="thrust F_a [kN]", ylabel="axial deflection [um]",
          title="axial deflection (stiffening)")
fig.tight_layout()

KEY = {"contact_angle_deg": beta}
