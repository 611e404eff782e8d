"""
Error map of the simplified Hertz formulas
==========================================

Brewe & Hamrock (1977) and Hamrock & Brewe (1983) replaced the elliptic integrals by
curve fits in the radius ratio alpha_r = Ry/Rx.  How far off are they?  The exact
solution (Hertz's transcendental equation solved to 1e-12) is the reference; the map
shows the relative error of each simplified quantity over 1 <= alpha_r <= 10^4.
Ball bearings live at alpha_r ~ 10-100, where both fits are within a few per cent;
beyond ~10^3 they drift badly.
"""
import matplotlib.pyplot as plt
import numpy as np

from ballrace.analytic import hertz

alpha_r = np.logspace(0, 4, 801)
quantities = ("k", "ellipk", "ellipe", "a", "b", "approach", "p_max")
fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True)
worst = {}
for ax, method in zip(axes, hertz.METHODS[1:]):
    err = hertz.approximation_errors(alpha_r, method)
    grid = np.array([100 * err[q] for q in quantities])
    im = ax.pcolormesh(alpha_r, np.arange(len(quantities) + 1), grid[:, :-1],
                       cmap="RdBu_r", vmin=-10, vmax=10, shading="flat")
    ax.set_xscale("log")
    ax.set_yticks(np.arange(len(quantities)) + 0.5, quantities)
    ax.set(xlabel="radius ratio alpha_r = Ry/Rx", title=method)
    ax.axvspan(3, 100, color="k", alpha=0.06, lw=0)
    mask = alpha_r <= 100
    worst[method] = {q: float(np.max(np.abs(err[q][mask]))) for q in quantities}
fig.colorbar(im, ax=axes, label="relative error [%] (clipped at ±10 %)")

for method, w in worst.items():
    print(method, "worst error up to alpha_r = 100:",
          ", ".join(f"{q} {100 * v:.2f} %" for q, v in w.items()))

# %%
# The shaded band is the usual ball-bearing range.  The worst errors up to alpha_r = 100
# are the documented bounds :data:`ballrace.analytic.hertz.APPROXIMATION_ERROR`.
KEY = worst
