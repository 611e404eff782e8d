"""
The FE check of a roller's edge pressure: a crowned and a straight roller
=========================================================================

:func:`ballrace.fem.roller_contact` solves a profiled roller on its raceway with
finite elements (a quarter model meshed with gmsh, quadratic tetrahedra, frictionless
contact; a rigid roller on one elastic block of the contact modulus — line_contact's own
half-space idealisation — with the roller end a real sharp edge of the loaded region) and
compares it with the strip method of :func:`ballrace.analytic.roller.line_contact`.  Here
the 12 mm roller (R1 = 6 mm) on a flat raceway, steel, 5 kN, at the ``quick`` mesh level
(a smoke level: some 10–20 s of CPU per roller with PARDISO, a few seconds more for the
picture):

* a circular crown (4 mm flat, 0.5 m crown radius): the pressure peaks where the flat
  part ends, the roller ends stay free, and FE and strips agree;
* a straight roller: the pressure rises to a peak at the roller end.  On a half-space that
  peak is singular — the FE's nodal peak grows as the mesh is refined, line_contact's end
  slice as the slices narrow — so both are read as "an edge peak", not as a pressure.

Beside them, the lamina model of ISO/TS 16281 for the same contact (independent slices,
q_k = (c/n) <delta - P(x_k)>^(10/9), each slice a 2-D Hertz contact of its load): no
coupling between the slices, so no edge peak.  The measured convergence of both methods
is in :doc:`/edge-stress`.
"""
import math

import matplotlib.pyplot as plt
import numpy as np
from scipy.optimize import brentq

import ballrace
from ballrace import fem
from ballrace.analytic.roller import Crowned, ProfileContext, as_profile, lamina
from ballrace.analytic.materials import effective_modulus

STEEL = ballrace.BEARING_STEEL
Q, R1, R2, L = 5000.0, 6e-3, np.inf, 12e-3          # [N], [m], [m] (flat), [m]
N_SLICES = 41


def lamina_pressure(profile, n_slices=N_SLICES):
    """Slice centres [m] and pressures [Pa] of the ISO/TS 16281 lamina model for one
    contact: the drop seen once, the stiffness of one of two like contacts in series
    (2^(10/9) c_L: the lamina's delta - 2P split in half), each slice a 2-D Hertz line
    contact of its load per length, p = sqrt(q E' / (2 pi R w))."""
    Ep = float(effective_modulus(STEEL, STEEL))
    R = R1 if not np.isfinite(R2) else 1.0 / (1.0 / R1 + 1.0 / R2)
    ctx = ProfileContext(length=L, diameter=2 * R1, E_prime=Ep, R=R, load=Q)
    x = lamina.slice_positions(L, n_slices)
    drop = np.asarray(as_profile(profile).drop(x, ctx), dtype=float)
    c1 = 2.0 ** (10.0 / 9.0) * lamina.lamina_stiffness(L, Ep)

    def load(delta):
        return lamina.slice_loads(delta - drop, c1, n_slices).sum()

    delta = brentq(lambda d: load(d) - Q, drop.min(), drop.min() + 1e-3, xtol=1e-16,
                   rtol=1e-14)
    q = lamina.slice_loads(delta - drop, c1, n_slices)
    return x, np.sqrt(q / (L / n_slices) * Ep / (2.0 * math.pi * R))


cases = {"crowned (4 mm flat, R = 0.5 m)": Crowned(flat_length=4e-3, crown_radius=0.5),
         "straight": "straight"}
results = {}
for name, prof in cases.items():
    r = fem.roller_contact(Q, R1, R2, L, STEEL, STEEL, profile=prof, level="quick",
                           n_slices=N_SLICES)
    results[name] = r
    print(f"\n{name}: {r.n_dofs} degrees of freedom, solver {r.solver}")
    print(f"{'quantity':>22s} {'FE':>10s} {'line_contact':>12s}  unit  error    tolerance")
    for row in r.comparison:
        tol = f"±{100 * row['tol']:.0f} %" if row["tol"] is not None else "—"
        err = f"{100 * row['error']:+6.2f} %" if np.isfinite(row["error"]) else "     — "
        print(f"{row['quantity']:>22s} {row['fe']:10.4g} {row['analytic']:12.4g} "
              f"{row['unit']:>4s} {err}  {tol}")

# %%
# The pressure along the half roller (x = 0 its centre, 6 mm its end): the FE pressure at
# its grid nodes (graded towards the end) and averaged over each of line_contact's
# slices, line_contact's slices, and the lamina slices.  Below: the load each slice
# carries, FE against line_contact.
fig, axes = plt.subplots(2, 2, figsize=(12, 7), sharex=True,
                         gridspec_kw={"height_ratios": [2.2, 1]})
KEY = {}
for k, (name, r) in enumerate(results.items()):
    c = r.analytic
    mid = (c.n_slices - 1) // 2
    xl, pl = lamina_pressure(cases[name])
    w = L / N_SLICES * 1e3
    ax = axes[0, k]
    ax.stairs(pl[mid:] / 1e9, np.append(xl[mid:] * 1e3 - w / 2, L / 2 * 1e3), color="0.5",
              baseline=None, label="lamina (ISO/TS 16281), independent slices")
    ax.plot(r.x * 1e3, r.pressure / 1e9, "-", lw=1.4, color="C0",
            label="FE, at the pressure-grid nodes")
    ax.plot(r.slice_x * 1e3, r.slice_pressure / 1e9, "o", ms=4, mfc="none", color="C0",
            label="FE, averaged over each slice")
    ax.plot(c.x[mid:] * 1e3, c.pressure[mid:] / 1e9, "x", ms=5, color="C3",
            label=f"line_contact, {N_SLICES} slices")
    ax.axhline(c.hertz_pressure / 1e9, color="k", lw=0.6, ls=":", label="2-D Hertz at Q/L")
    ax.set(title=name, ylabel="contact pressure [GPa]" if k == 0 else None, ylim=(0, 3.0))
    ax.grid(alpha=0.3)
    err = np.where(c.slice_loads[mid:] > 0,
                   r.slice_loads / np.where(c.slice_loads[mid:] > 0, c.slice_loads[mid:], 1)
                   - 1, np.nan)
    axes[1, k].bar(r.slice_x * 1e3, 100 * err, width=0.8 * w, color="C0")
    axes[1, k].axhline(0, color="k", lw=0.6)
    axes[1, k].set(xlabel="x along the roller [mm]",
                   ylabel="FE / line_contact - 1 [%]" if k == 0 else None,
                   title="load of each slice")
    axes[1, k].grid(alpha=0.3)
    KEY[name] = {"rows": {row["quantity"]: (row["error"], row["tol"]) for row in
                          r.comparison},
                 "within_tolerance": r.within_tolerance,
                 "edge_pressure": r.edge_pressure, "centre_pressure": r.centre_pressure,
                 "x_edge": r.x_edge, "lamina_pressure": pl, "p0": c.hertz_pressure,
                 "line_contact_pressure": np.asarray(c.pressure),
                 "slice_load_error": err}
axes[0, 0].legend(fontsize=7, loc="lower left")
fig.suptitle("12 mm roller on a flat raceway, 5 kN: FE (quick level, half-space mode) "
             "against line_contact and the lamina model")
fig.tight_layout()

# %%
# The library's picture of the straight roller (pyvista, off-screen:
# :func:`ballrace.fem.render.render_roller`): the raceway cut open under the roller axis,
# the von Mises field below the middle and below the roller end (the axis along the
# roller drawn compressed), and the pressure along the roller.
import tempfile
from pathlib import Path

import matplotlib.image as mpimg

from ballrace.fem.render import render_roller

png = render_roller(results["straight"], Path(tempfile.mkdtemp()) / "straight.png",
                    field="von_mises")
fig2, ax2 = plt.subplots(figsize=(12, 8.6))
ax2.imshow(mpimg.imread(png))
ax2.axis("off")
fig2.tight_layout()
