"""
ISO 281 modified life, ISO/TS 16281 reference life and the operating clearance
==============================================================================

A 6305-size deep-groove ball bearing (D = 11.5 mm, Z = 7, D_pw = 43.5 mm, f_i = 0.52,
f_o = 0.53, 20 um unmounted clearance) under 2 kN radial load at 3000 rpm, ISO VG 68 oil
at 70 degC, normal cleanliness.  The inner ring is pressed on a solid steel shaft with an
interference that we sweep from 0 to 60 um:

* the fit takes clearance away: for a solid shaft of the ring's steel the raceway grows by
  I d/F (thick-ring Lamé; Harris 2001 §4.3), checked below;
* the ISO/TS 16281 modified reference life L10mr comes from the load distribution at that
  operating clearance, so it sees the clearance shrink and then the preload: it is
  longest at a slight preload, where more balls share the load, and falls fast beyond
  (the clearance-life curve of Oswald, Zaretsky & Poplawski 2012, NASA/TM-2012-217115);
* the ISO 281 modified life L_nm comes from the catalogue load P = X Fr + Y Fa and cannot
  see the clearance at all.  That is why the bearing report marks it when [fits] is given.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import clearance, iso16281, iso281, ratings

brg = ballrace.BallBearing(11.5e-3, 7, 43.5e-3, 0.52, 0.53, diametral_clearance=20e-6)
Fr, n, d, Do = 2000.0, 3000.0, 25e-3, 62e-3
C = float(ratings.dynamic_rating(brg))                     # at the nominal angle, 0 deg
C0 = float(ratings.static_rating(brg))
nu = float(iso281.operating_viscosity(68e-6, 8.7e-6, 343.15))
kappa = float(iso281.viscosity_ratio(nu, n, brg.pitch_diameter))
eC = float(iso281.contamination_factor("normal cleanliness", brg.pitch_diameter))
Cu = iso281.fatigue_load_limit_hertz(brg).C_u
L_nm = float(iso281.modified_rating_life(C, Fr, kappa=kappa, contamination=eC,
                                         fatigue_limit=Cu))
print(f"C = {C:.0f} N, C0 = {C0:.0f} N, nu = {nu * 1e6:.2f} mm^2/s, kappa = {kappa:.3f}, "
      f"e_C = {eC:.2f}, C_u = {Cu:.0f} N: L_nm = {L_nm:.0f} x 1e6 rev")

# %%
# The sweep: operating clearance, then the load distribution at it and L10r.
interference = np.linspace(0.0, 60e-6, 13)
operating, L10r, fit_check = [], [], []
F = brg.pitch_diameter - brg.ball_diameter - 0.5 * brg.diametral_clearance  # inner raceway
for I in interference:
    oc = clearance.operating_clearance(brg, bore=d, outside_diameter=Do, shaft_interference=I)
    fit_check.append(oc.fit_inner - I * d / F)              # Lamé against I d/F: zero
    operating.append(oc.operating)
    ld = brg.radial(Fr, clearance=oc.operating)
    ref = iso16281.reference_rating_life(brg, ld)
    L10r.append(ref.modified(kappa=kappa, contamination=eC, fatigue_limit=Cu))
    print(f"I = {I * 1e6:4.0f} um: operating clearance {oc.operating * 1e6:+6.1f} um, "
          f"L10mr = {L10r[-1]:7.0f} x 1e6 rev")
operating, L10r = np.array(operating), np.array(L10r)

fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
ax[0].plot(interference * 1e6, operating * 1e6, "o-")
ax[0].axhline(0.0, color="k", lw=0.8)
ax[0].set(xlabel="shaft interference [um]", ylabel="operating clearance [um]",
          title="clearance after the fit (negative: preload)")
ax[1].semilogy(interference * 1e6, L10r, "o-", label="L10mr (ISO/TS 16281, sees the clearance)")
ax[1].axhline(L_nm, color="tab:red", ls="--", label="L_nm (ISO 281, from P only)")
ax[1].set(xlabel="shaft interference [um]", ylabel="life [1e6 rev]", title="life")
ax[1].legend(fontsize=8)
fig.tight_layout()

KEY = {"C": C, "fit_check": float(np.max(np.abs(fit_check))), "operating": operating,
       "interference": interference, "L10r": L10r, "L_nm": L_nm, "initial": 20e-6,
       "d_over_F": d / F}
