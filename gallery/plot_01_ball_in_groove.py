"""
Contact of a ball in a groove
=============================

A 12.7 mm ball in the inner-race groove of the 209 bearing of Hamrock & Dowson (1981,
Table 3.2: pitch diameter 65 mm, conformity f = 0.52), pressed with 4.45 N as in their
example and then with a working load.  The ball is convex in both planes; the groove is
convex in the rolling direction (race radius 26.15 mm) and concave across it (groove
radius -0.52 D): the contact ellipse is long across the rolling direction.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic import hertz

steel = ballrace.Material(E=207.48e9, nu=0.3)      # H&D's steel, E' = 228 GPa
D, d_e, f = 12.7e-3, 65e-3, 0.52
rx1 = ry1 = D / 2                                   # ball [m]
rx2, ry2 = (d_e - D) / 2, -f * D                    # inner race: convex x, concave y [m]

c = hertz.point_contact(4.45, rx1, ry1, rx2, ry2, steel, steel)
print(f"k = a/b = {float(c.k):.6f}")
print(f"a = {float(c.a) * 1e3:.5f} mm, b = {float(c.b) * 1e3:.5f} mm")
print(f"p_max = {float(c.p_max) / 1e6:.2f} MPa, approach = {float(c.approach) * 1e9:.1f} nm")

# %%
# The same groove over a range of loads: a, b ~ Q^(1/3), p_max ~ Q^(1/3), delta ~ Q^(2/3).
Q = np.logspace(0, 3.7, 38)                         # N, up to 5 kN (a / R < 0.5)
cs = hertz.point_contact(Q, rx1, ry1, rx2, ry2, steel, steel)   # broadcasts over Q
fig, ax = plt.subplots(1, 2, figsize=(9, 3.6))
ax[0].loglog(Q, cs.a * 1e3, label="a (across rolling)")
ax[0].loglog(Q, cs.b * 1e3, label="b (rolling direction)")
ax[0].set(xlabel="ball load Q [N]", ylabel="semi-axis [mm]", title="contact ellipse")
ax[0].legend()
ax[1].loglog(Q, cs.p_max / 1e9)
ax[1].set(xlabel="ball load Q [N]", ylabel="p_max [GPa]", title="peak pressure")
fig.tight_layout()

# Key number (tests/test_gallery.py): Hertz's transcendental equation solved by the
# library; the reference is a 30-digit mpmath solution (validation case hertz-hd-209-inner).
KEY = {"k": float(c.k), "a": float(c.a), "b": float(c.b), "p_max": float(c.p_max)}
