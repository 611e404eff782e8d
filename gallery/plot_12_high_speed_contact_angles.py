"""
High-speed contact angles
=========================

At speed each ball is thrown outwards by its centrifugal force F_c = m d_m omega_c^2 / 2
and turned by its gyroscopic moment: the outer contact angle falls and the inner one
rises (Jones 1960; Hamrock & Dowson 1981 §3.4).  The 218 bearing under 17,800 N thrust
from rest to 15,000 rpm.  At zero speed the two angles are equal and match the static
thrust solution, 41.53045976 deg (a 30-digit mpmath solution of H&D eq. 3.55, validation
case highspeed-218-zero-speed-equals-static).
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import highspeed

brg = ballrace.BallBearing(ball_diameter=22.225e-3, n_balls=16, pitch_diameter=125.26e-3,
                           f_inner=0.5232, f_outer=0.5232, free_contact_angle=np.radians(40))
rpm = np.linspace(0.0, 15000.0, 13)
inner, outer, Qi, Qo = [], [], [], []
for n in rpm:
    r = highspeed.solve(brg, Fa=17800.0, speed_inner=n * 2 * np.pi / 60)
    inner.append(np.degrees(float(np.mean(r.inner_contact_angles))))
    outer.append(np.degrees(float(np.mean(r.outer_contact_angles))))
    Qi.append(float(np.mean(r.inner_loads)))
    Qo.append(float(np.mean(r.outer_loads)))
print(f"0 rpm: inner {inner[0]:.8f} deg, outer {outer[0]:.8f} deg")
print(f"{rpm[-1]:.0f} rpm: inner {inner[-1]:.2f} deg, outer {outer[-1]:.2f} deg, "
      f"Q_i = {Qi[-1]:.0f} N, Q_o = {Qo[-1]:.0f} N")

fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
ax[0].plot(rpm, inner, "o-", label="inner contact")
ax[0].plot(rpm, outer, "s-", label="outer contact")
ax[0].set(xlabel="inner-ring speed [rpm]", ylabel="contact angle [deg]",
          title="218 bearing, 17.8 kN thrust")
ax[0].legend()
ax[1].plot(rpm, Qi, "o-", label="inner")
ax[1].plot(rpm, Qo, "s-", label="outer")
ax[1].set(xlabel="inner-ring speed [rpm]", ylabel="ball load [N]", title="ball loads")
ax[1].legend()
fig.tight_layout()

KEY = {"alpha_inner_0": inner[0], "alpha_outer_0": outer[0],
       "alpha_inner_max": inner[-1], "alpha_outer_max": outer[-1]}
