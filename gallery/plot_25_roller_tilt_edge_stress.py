"""
Tilt and the edge stress of a roller: straight, crowned and logarithmic profiles
================================================================================

A tilted roller (a misaligned ring, a bent shaft) presses one end harder than the other.
Here the finite line contact on the elastic half-space
(:func:`ballrace.analytic.roller.line_contact`, 41 slices coupled through Boussinesq's
solution) and the stresses below it
(:func:`ballrace.analytic.roller.subsurface_stress`) for a 12 x 12 mm roller
(R1 = 6 mm) on a 60 mm raceway (R2 = 30 mm), steel, 5 kN, as the tilt grows from 0 to
2 mrad (positive: the end at +x goes in), for three profiles:

* straight — an edge peak at both ends even without tilt (singular on a half-space: its
  height on the end slice grows as the slices narrow, so read it as "an edge peak", not
  as a pressure);
* a circular crown, 4 mm flat and 0.5 m crown radius — the peak sits where the flat part
  ends and the roller ends stay free up to the tilt (or load) that brings them in;
* Lundberg's logarithmic profile designed for these 5 kN — the 2-D Hertz pressure along
  the whole roller without tilt (Lundberg 1939), but a full-length contact, so any tilt
  loads its end at once.

The top row shows the pressure along the roller at four tilts, the bottom row the largest
pressure and the largest von Mises stress (over depth and along the roller) against the
tilt.  Each state takes some 0.05 s of CPU (0.3 s for the first, which builds the strip
table).  See :doc:`/edge-stress` for what the numbers mean.
"""
import matplotlib.pyplot as plt
import numpy as np

import ballrace
from ballrace.analytic.roller import Crowned, Lundberg, line_contact, subsurface_stress

STEEL = ballrace.BEARING_STEEL
Q, R1, R2, L = 5000.0, 6e-3, 30e-3, 12e-3          # [N], [m], [m], [m]
PROFILES = {"straight": "straight",
            "crowned (4 mm flat, R = 0.5 m)": Crowned(flat_length=4e-3, crown_radius=0.5),
            "Lundberg (designed for 5 kN)": Lundberg(design_load=Q)}
TILTS = np.linspace(0.0, 2e-3, 21)                  # [rad]
SHOWN = (0.0, 0.5e-3, 1e-3, 2e-3)                   # tilts drawn along the roller [rad]

KEY = {}
rows = {}
for name, prof in PROFILES.items():
    out = {"p_max": [], "x_p": [], "vm_max": [], "x_vm": [], "z_vm": [], "tr_max": [],
           "vm_end": [], "contact": {}}
    for psi in TILTS:
        c = line_contact(Q, R1, R2, L, STEEL, STEEL, profile=prof, tilt=psi, n_slices=41)
        s = subsurface_stress(c, nu=STEEL.nu)
        v, xv, zv = s.maximum("von_mises")
        out["p_max"].append(c.max_pressure)
        out["x_p"].append(float(c.x[np.argmax(c.pressure)]))
        out["vm_max"].append(v)
        out["x_vm"].append(xv)
        out["z_vm"].append(zv)
        out["tr_max"].append(s.maximum("tresca")[0])
        out["vm_end"].append(s.edge("von_mises")[0])
        if any(np.isclose(psi, t) for t in SHOWN):
            out["contact"][float(psi)] = c
        if psi == 0.0:
            out["centre"] = (c, s.centre("von_mises"))
    rows[name] = {k: (np.array(v) if isinstance(v, list) else v) for k, v in out.items()}

fig = plt.figure(figsize=(12, 7.2))
grid = fig.add_gridspec(2, 3, height_ratios=[1.0, 1.0])
colours = plt.cm.viridis(np.linspace(0.0, 0.85, len(SHOWN)))
p0 = None
for k, (name, r) in enumerate(rows.items()):
    ax = fig.add_subplot(grid[0, k])
    for col, psi in zip(colours, SHOWN):
        c = r["contact"][psi]
        ax.plot(c.x * 1e3, c.pressure / 1e9, ".-", color=col, ms=3, lw=1,
                label=f"tilt {psi * 1e3:.1f} mrad")
        p0 = c.hertz_pressure
    ax.axhline(p0 / 1e9, color="k", lw=0.6, ls=":", label="2-D Hertz at Q/L")
    ax.set(title=name, xlabel="x along the roller [mm]", ylim=(0, 4.0))
    if k == 0:
        ax.set_ylabel("contact pressure [GPa]")
        ax.legend(fontsize=7, loc="lower center")

ax_p = fig.add_subplot(grid[1, 0:2])
ax_v = fig.add_subplot(grid[1, 2])
for (name, r), mk in zip(rows.items(), ("o", "s", "^")):
    t = TILTS * 1e3
    ax_p.plot(t, r["p_max"] / 1e9, marker=mk, ms=4, label=name)
    ax_v.plot(t, r["vm_max"] / 1e6, marker=mk, ms=4, label=name)
ax_p.axhline(p0 / 1e9, color="k", lw=0.6, ls=":")
ax_p.set(xlabel="tilt [mrad]", ylabel="largest contact pressure [GPa]",
         title="largest pressure (for the straight roller: the end slice's edge peak)")
ax_p.legend(fontsize=8)
ax_v.set(xlabel="tilt [mrad]", ylabel="largest von Mises stress [MPa]",
         title="von Mises maximum below the contact")
for ax in (ax_p, ax_v):
    ax.grid(alpha=0.3)
fig.suptitle("12 x 12 mm roller on a 60 mm raceway, 5 kN: edge pressure and stress "
             "against tilt (line_contact, 41 slices)")
fig.tight_layout()

# %%
# The numbers behind the plots: the largest pressure, and the von Mises maximum with its
# position (x from the roller centre, depth below the surface), at each tilt drawn above.
print(f"{'profile':32s} {'tilt':>5s} {'p_max':>7s} {'at x':>6s} {'VM max':>7s} {'at x':>6s} "
      f"{'depth':>6s} {'Tresca':>7s}")
print(f"{'':32s} {'mrad':>5s} {'GPa':>7s} {'mm':>6s} {'MPa':>7s} {'mm':>6s} {'mm':>6s} "
      f"{'MPa':>7s}")
for name, r in rows.items():
    for psi in SHOWN:
        i = int(np.argmin(np.abs(TILTS - psi)))
        print(f"{name:32s} {psi * 1e3:5.1f} {r['p_max'][i] / 1e9:7.3f} "
              f"{r['x_p'][i] * 1e3:6.2f} {r['vm_max'][i] / 1e6:7.0f} "
              f"{r['x_vm'][i] * 1e3:6.2f} {r['z_vm'][i] * 1e3:6.3f} "
              f"{r['tr_max'][i] / 1e6:7.0f}")

# %%
# Reading the plots.  Without tilt the straight roller already peaks at its ends; the
# crown moves the peak inwards to the end of its flat part, and Lundberg's profile gives
# the 2-D Hertz pressure along the whole roller.  With tilt the straight and the
# Lundberg roller load their +x end at once (both touch over the full length), while the
# crown takes up some tilt before its end comes in.  The von Mises maximum follows the
# largest pressure, at about 0.6 times it and some 0.7 half-widths deep; below a roller
# end it lies shallower than in the middle.
for name, r in rows.items():
    c0, (v0, x0, z0) = r["centre"]
    KEY[name] = {"tilts": TILTS.copy(), "p_max": r["p_max"], "vm_max": r["vm_max"],
                 "x_p": r["x_p"], "x_vm": r["x_vm"], "z_vm": r["z_vm"],
                 "tr_max": r["tr_max"], "vm_end": r["vm_end"],
                 "p0": c0.hertz_pressure, "pressure_0": np.asarray(c0.pressure),
                 "x_0": np.asarray(c0.x), "half_width_centre": float(c0.half_width[20]),
                 "pressure_centre": float(c0.pressure[20]), "vm_centre": v0,
                 "vm_centre_depth": z0}
