"""
Life and film thickness over a duty cycle
=========================================

A 209 bearing runs a duty cycle of three conditions, each with its own radial load,
speed and oil viscosity (temperature).  For each condition: the load distribution,
the Lundberg–Palmgren L10 from the ball loads, the Hamrock–Dowson (1977) minimum film
at the most heavily loaded inner contact and the film parameter Lambda; then the
Palmgren–Miner life of the whole cycle.

First the check point: the film of the validation case ehl-hd77-209-inner (209 inner
race, 4 kN, u = 10 m/s, 0.04 Pa s), whose reference h_min = 0.7560653780 um was
evaluated independently in 30-digit arithmetic.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import ehl, hertz, life

steel = ballrace.Material(E=200e9, nu=0.3)
D, d_m = 12.7e-3, 65e-3
check = hertz.point_contact(4000.0, D / 2, D / 2, 26.15e-3, -0.52 * D, steel, steel)
film = ehl.film_thickness(check, entrainment_speed=10.0, viscosity=0.04,
                          pressure_viscosity=2.2e-8)
h_check = float(film.h_min)
print(f"check point: h_min = {h_check * 1e6:.10f} um (reference 0.7560653780 um)")

# %%
# The duty cycle.  Roughness 0.1 um rms on balls and races.
brg = ballrace.BallBearing(ball_diameter=D, n_balls=9, pitch_diameter=d_m, f_inner=0.52,
                           f_outer=0.52, diametral_clearance=0.01e-3, material=steel)
cycle = [  # (fraction of time, radial load [N], speed [rpm], viscosity [Pa s])
    (0.6, 3000.0, 3000.0, 0.030),
    (0.3, 6000.0, 1500.0, 0.045),
    (0.1, 9000.0, 500.0, 0.060),
]
hours, h_min, lam = [], [], []
for frac, Fr, n, eta in cycle:
    ld = brg.radial(Fr)
    L = life.bearing_life(brg, ld)
    hours.append(L.hours(n))
    j = int(np.argmax(ld.ball_loads))
    c = hertz.elliptical_contact(float(ld.ball_loads[j]), float(ld.inner.Rx[j]),
                                 float(ld.inner.Ry[j]), float(ld.inner.E_prime[j]))
    u = float(ehl.entrainment_speed(D, d_m, speed_inner=n * 2 * np.pi / 60))
    f = ehl.film_thickness(c, entrainment_speed=u, viscosity=eta, pressure_viscosity=2.2e-8)
    h_min.append(float(f.h_min))
    lam.append(float(ehl.film_parameter(f.h_min, 0.1e-6, 0.1e-6)))
    print(f"{frac:4.0%} at {Fr:5.0f} N, {n:4.0f} rpm: L10 = {hours[-1]:9.0f} h, "
          f"h_min = {h_min[-1] * 1e6:.3f} um, Lambda = {lam[-1]:.2f}")
fractions = [c[0] for c in cycle]
L_cycle = float(life.miner(hours, fractions))
print(f"Palmgren-Miner life of the cycle: {L_cycle:.0f} h")

fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
labels = [f"{Fr / 1e3:.0f} kN\n{n:.0f} rpm\n{frac:.0%}" for frac, Fr, n, _ in cycle]
ax[0].bar(labels, hours, color="tab:blue")
ax[0].axhline(L_cycle, color="k", ls="--", label=f"cycle (Miner): {L_cycle:.0f} h")
ax[0].set(yscale="log", ylabel="L10 [h]", title="life per condition")
ax[0].legend()
ax[1].bar(labels, lam, color="tab:green")
ax[1].axhline(1.0, color="r", ls=":", label="Lambda = 1")
ax[1].set(ylabel="film parameter Lambda", title="film at the heaviest inner contact")
ax[1].legend()
fig.tight_layout()

KEY = {"h_min_check": h_check, "miner_tata": float(life.miner([10000.0, 2000.0], [0.8, 0.2])),
       "L_cycle": L_cycle, "hours": hours}
