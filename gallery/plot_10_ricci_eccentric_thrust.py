"""
Ricci's eccentric thrust
========================

A thrust that does not act on the bearing axis tilts the inner ring: the balls on the
load side carry more and turn to larger contact angles.  Ricci (2009, §4) solved the 218
bearing (beta_f = 40 deg) under 17,800 N at an eccentricity of 50.8 mm and published
Q_max = 9,445 N, contact angles from 44.317 deg (psi = 0) to 16.169 deg (psi = 180 deg)
and a loaded-zone angle psi_l = 53.66 deg.  Ricci does not state his steel constants, so the
library (E = 200 GPa, nu = 0.3) lands within 1 % and 0.5 deg of his numbers.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace

brg = ballrace.BallBearing(ball_diameter=22.225e-3, n_balls=16, pitch_diameter=125.26e-3,
                           f_inner=0.5232, f_outer=0.5232, free_contact_angle=np.radians(40))
r = brg.eccentric_thrust(17800.0, 50.8e-3)                 # N, m
psi = (np.degrees(np.asarray(r.azimuths)) + 180.0) % 360.0 - 180.0   # -180 ... 180 deg
Q = np.asarray(r.ball_loads)
beta = np.degrees(np.asarray(r.contact_angles))
print(f"Q_max = {float(r.max_ball_load):.0f} N (Ricci 2009: 9445 N)")
i0, i180 = np.argmin(np.abs(psi)), np.argmin(np.abs(np.abs(psi) - 180.0))
print(f"contact angle {beta[i0]:.3f} deg at psi = 0 (44.317), "
      f"{beta[i180]:.3f} deg at psi = 180 deg (16.169)")

fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
order = np.argsort(psi)
psi, Q, beta = psi[order], Q[order], beta[order]
ax[0].bar(psi, Q, width=15)
ax[0].set(xlabel="ball azimuth psi [deg]", ylabel="ball load Q [N]", title="ball loads")
ax[1].plot(psi, beta, "o-")
ax[1].axhline(40, color="k", lw=0.8, ls="--")
ax[1].set(xlabel="ball azimuth psi [deg]", ylabel="contact angle [deg]",
          title="contact angles (free angle dashed)")
fig.tight_layout()

KEY = {"Q_max": float(r.max_ball_load), "beta_0": beta[np.argmin(np.abs(psi))],
       "beta_180": beta[np.argmin(np.abs(np.abs(psi) - 180.0))]}
