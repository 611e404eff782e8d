"""
How z0 and tau0 move with b/a
=============================

Lundberg–Palmgren's orthogonal shear depends only on the ellipse's aspect ratio b/a
through the auxiliary parameter t, (b/a)^2 = (t^2 - 1)(2t - 1) (Hamrock & Dowson 1981
eqs. 3.19-3.27): from the circle (t = 1.2808, z0 = 0.3509 b, tau0 = 0.2139 p_max) to the
line contact (t = 1, z0 = 0.5 b, tau0 = 0.25 p_max).  The maximum shear on the axis
(Tresca, nu = 0.3) moves the same way but deeper.  Dashed: Hamrock & Dowson's csch fit
for t.
"""
import matplotlib.pyplot as plt
import numpy as np

from ballrace.analytic import hertz, subsurface

Rx = 5e-3                                      # rolling-direction radius [m]
E_prime = 2.2e11                               # Pa
alpha_r = np.logspace(0, 4, 161)               # Ry/Rx: circle to a very long ellipse
contacts = hertz.elliptical_contact(1000.0, Rx, Rx * alpha_r, E_prime)
ba = 1.0 / contacts.k
osh = subsurface.orthogonal_shear(contacts)
approx = subsurface.orthogonal_shear(contacts, method="approximate")
ms = subsurface.max_shear(contacts, nu=0.3)
b, p = contacts.b, contacts.p_max

fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
ax[0].semilogx(ba, osh.z0 / b, label="z0 / b (LP, exact t)")
ax[0].semilogx(ba, approx.z0 / b, "--", label="z0 / b (csch fit)")
ax[0].semilogx(ba, ms.depth / b, label="depth of tau_max / b")
ax[0].set(xlabel="b / a", ylabel="depth / b", title="depths")
ax[0].invert_yaxis()
ax[0].legend()
ax[1].semilogx(ba, osh.tau0 / p, label="tau0 / p_max (LP)")
ax[1].semilogx(ba, approx.tau0 / p, "--", label="tau0 / p_max (csch fit)")
ax[1].semilogx(ba, ms.tau_max / p, label="tau_max / p_max (Tresca)")
ax[1].set(xlabel="b / a", ylabel="stress / p_max", title="maxima")
ax[1].legend()
fig.tight_layout()

# %%
# The circle (b/a = 1), reproduced from the exact t:
t_circle = float(subsurface.lundberg_palmgren_t(1.0))
circle = subsurface.orthogonal_shear(hertz.elliptical_contact(1000.0, Rx, Rx, E_prime))
c0 = hertz.elliptical_contact(1000.0, Rx, Rx, E_prime)
print(f"circle: t = {t_circle:.4f}, z0 = {float(circle.z0 / c0.b):.4f} b, "
      f"tau0 = {float(circle.tau0 / c0.p_max):.4f} p_max")
KEY = {"t": t_circle, "z0": float(circle.z0 / c0.b), "tau0": float(circle.tau0 / c0.p_max),
       "z0_line_end": float(osh.z0[-1] / b[-1]), "tau0_line_end": float(osh.tau0[-1] / p[-1])}
