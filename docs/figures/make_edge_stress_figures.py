"""Figures of the page "Edge stress and crowning" (docs/edge-stress.md).

Writes PNGs to ``docs/_static/`` (committed; the docs build does not run this script):

* ``edge-profiles.png`` — the drop of five roller profiles and the pressure along the
  roller that each gives (:func:`ballrace.analytic.roller.line_contact`);
* ``edge-vonmises.png`` — the von Mises stress below the roller, in the plane through its
  axis, for a straight, a crowned and a Lundberg roller
  (:func:`ballrace.analytic.roller.subsurface_stress`);
* ``edge-straight-refinement.png`` — the straight roller's end: the pressure of
  line_contact at 21 to 161 slices and the FE pressure, which keep growing at the edge;
* ``edge-fe-pressure.png`` — FE (:func:`ballrace.fem.roller_contact`, half-space mode)
  against line_contact and the ISO/TS 16281 lamina model, three profiles;
* ``edge-fe-straight.png``, ``edge-fe-crowned.png``, ``edge-fe-lundberg.png`` — 3-D
  pictures of the FE von Mises field below the contact (pyvista, off-screen).

The case throughout: a roller of R1 = 6 mm, effective length 12 mm, steel
(:data:`ballrace.BEARING_STEEL`), 5 kN; on a 60 mm raceway (R2 = 30 mm) for the analytic
figures (the roller of the convergence table in :mod:`ballrace.analytic.roller.contact`)
and on a flat raceway for the FE (the case measured in :mod:`ballrace.fem.roller`).

Run from the repository root::

    .venv/bin/python docs/figures/make_edge_stress_figures.py            # all, FE quick
    .venv/bin/python docs/figures/make_edge_stress_figures.py --level standard
    .venv/bin/python docs/figures/make_edge_stress_figures.py --no-fe    # analytic only
    ... --level standard --reuse /tmp/edge   # keep the FE results, redraw without solving

Time (2 cores shared with other jobs, load average 6–9, PARDISO; measured with
/usr/bin/time): the analytic figures 4–6 s of CPU; everything at the quick level 40 s of
CPU (100 s of wall time, 0.8 GB), at the standard level 196 s of CPU (450 s of wall time,
3.2 GB peak: straight 207k DOFs, crowned 171k, Lundberg 139k), the meshes taken from the
cache; the 3-D pictures (:func:`ballrace.fem.render.render_roller`, drawn from the raceway
each result keeps) are included.
"""
from __future__ import annotations

import argparse
import logging
import math
import time
from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parents[1] / "_static"
Q, R1, L = 5000.0, 6e-3, 12e-3          # load [N], roller radius [m], length [m]
R2_ANALYTIC = 30e-3                     # raceway radius of the analytic figures [m]
N_SLICES = 41

log = logging.getLogger("edge_figures")


def _steel():
    import ballrace

    return ballrace.BEARING_STEEL


def profiles():
    """The profiles of the page, by label."""
    from ballrace.analytic.roller import Crowned, Lundberg

    return {"straight": "straight",
            "circular crown (4 mm flat, R = 0.5 m)": Crowned(flat_length=4e-3,
                                                             crown_radius=0.5),
            "ISO/TS 16281 default": "iso",
            "Lundberg (for 5 kN)": Lundberg(design_load=Q),
            "Johns-Gohar (for 5 kN)": "johns-gohar"}


def lamina_pressure(profile, R2, n_slices=N_SLICES):
    """Slice centres [m] and pressures [Pa] of the ISO/TS 16281 lamina model for one
    contact: the drop seen once, one of two like contacts in series (stiffness
    2^(10/9) c_L), each slice a 2-D Hertz contact, p = sqrt(q E' / (2 pi R w))."""
    from scipy.optimize import brentq

    from ballrace.analytic.materials import effective_modulus
    from ballrace.analytic.roller import ProfileContext, as_profile, lamina

    st = _steel()
    Ep = float(effective_modulus(st, st))
    R = R1 if not np.isfinite(R2) else 1.0 / (1.0 / R1 + 1.0 / R2)
    ctx = ProfileContext(length=L, diameter=2 * R1, E_prime=Ep, R=R, load=Q)
    x = lamina.slice_positions(L, n_slices)
    drop = np.asarray(as_profile(profile).drop(x, ctx), dtype=float)
    c1 = 2.0 ** (10.0 / 9.0) * lamina.lamina_stiffness(L, Ep)
    delta = brentq(lambda d: lamina.slice_loads(d - drop, c1, n_slices).sum() - Q,
                   drop.min(), drop.min() + 1e-3, xtol=1e-16, rtol=1e-14)
    q = lamina.slice_loads(delta - drop, c1, n_slices)
    return x, np.sqrt(q / (L / n_slices) * Ep / (2.0 * math.pi * R))


# --------------------------------------------------------------------------- analytic
def profiles_figure(path):
    """Drops and pressures of the five profiles."""
    from matplotlib.figure import Figure

    from ballrace.analytic.roller import ProfileContext, line_contact

    st = _steel()
    fig = Figure(figsize=(12, 4.4), layout="constrained")
    a_drop, a_p = fig.subplots(1, 2)
    xs = np.linspace(-0.5, 0.5, 801)[1:-1] * L
    rows = []
    for k, (name, prof) in enumerate(profiles().items()):
        c = line_contact(Q, R1, R2_ANALYTIC, L, st, st, profile=prof, n_slices=N_SLICES)
        pc = ProfileContext(length=L, diameter=2 * R1, E_prime=c.E_prime, R=c.R, load=Q)
        d = np.asarray(c.profile.drop(xs, pc), dtype=float)
        a_drop.plot(xs * 1e3, d * 1e6, color=f"C{k}", label=name)
        a_p.plot(c.x * 1e3, c.pressure / 1e9, ".-", color=f"C{k}", ms=3, lw=1, label=name)
        rows.append((name, c))
    p0 = rows[0][1].hertz_pressure
    a_p.axhline(p0 / 1e9, color="k", lw=0.6, ls=":", label="2-D Hertz at Q/L")
    a_drop.set(xlabel="x along the roller [mm]", ylabel="drop P(x) [µm]", ylim=(0, 30),
               title="profile: drop below the cylinder (seen once at a contact)")
    a_p.set(xlabel="x along the roller [mm]", ylabel="contact pressure [GPa]", ylim=(0, 2.5),
            title=f"pressure at {Q / 1e3:g} kN (line_contact, {N_SLICES} slices)")
    for ax in (a_drop, a_p):
        ax.grid(alpha=0.3)
    a_drop.legend(fontsize=8, loc="upper center")
    a_p.legend(fontsize=7, loc="lower center")
    fig.suptitle("12 mm roller (R1 = 6 mm) on a 60 mm raceway, steel: five profiles")
    fig.savefig(path, dpi=110, facecolor="white")
    return rows


def vonmises_figure(path):
    """Von Mises maps below a straight, a crowned and a Lundberg roller."""
    from matplotlib.figure import Figure

    from ballrace.analytic.roller import line_contact, subsurface_stress

    st = _steel()
    chosen = {k: v for k, v in profiles().items()
              if k.startswith(("straight", "circular", "Lundberg"))}
    fig = Figure(figsize=(12, 7.6), layout="constrained")
    axes = fig.subplots(len(chosen), 1, sharex=True)
    out = {}
    runs = []
    for name, prof in chosen.items():
        c = line_contact(Q, R1, R2_ANALYTIC, L, st, st, profile=prof, n_slices=N_SLICES)
        x = np.linspace(-0.5, 0.5, 241)[1:-1] * L
        # from 0.2 half-widths down, where the integration is accurate (its notes)
        s = subsurface_stress(c, nu=st.nu, x=x, depth=np.linspace(0.03, 0.40, 38) * 1e-3)
        runs.append((name, c, s))
    vmax = max(float(s.von_mises.max()) for _, _, s in runs) / 1e6
    for ax, (name, c, s) in zip(axes, runs):
        im = ax.pcolormesh(s.x * 1e3, s.depth * 1e3, s.von_mises.T / 1e6, cmap="viridis",
                           vmin=0, vmax=vmax, shading="gouraud")
        v, xv, zv = s.maximum()
        ax.plot(xv * 1e3, zv * 1e3, "wx", ms=8, mew=2)
        ax.plot(s.x * 1e3, np.where(s.loaded, s.von_mises_depth, np.nan) * 1e3, "w:", lw=0.8)
        ax.set_ylim(0.40, 0.0)
        ax.set_ylabel("depth [mm]")
        ax.set_title(f"{name}: largest {v / 1e6:.0f} MPa at x = {xv * 1e3:.2f} mm, "
                     f"{zv * 1e3:.3f} mm deep (x); dotted: depth of the maximum at each x",
                     fontsize=9)
        out[name] = (c, s)
    axes[-1].set_xlabel("x along the roller [mm]")
    cb = fig.colorbar(im, ax=axes, shrink=0.8, pad=0.01)
    cb.set_label("von Mises stress [MPa]")
    fig.suptitle(f"Von Mises stress below the roller (plane through its axis), {Q / 1e3:g} kN, "
                 f"12 mm roller on a 60 mm raceway (subsurface_stress, {N_SLICES} slices; "
                 "depth exaggerated)", fontsize=10)
    fig.savefig(path, dpi=110, facecolor="white")
    return out


def refinement_figure(path, fe=None):
    """The straight roller's end: line_contact at 21..161 slices and the FE pressure."""
    from matplotlib.figure import Figure

    from ballrace.analytic.roller import line_contact

    st = _steel()
    fig = Figure(figsize=(12, 4.2), layout="constrained")
    a_all, a_end = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1]})
    R2 = math.inf if fe else R2_ANALYTIC
    for k, n in enumerate((21, 41, 81, 161)):
        c = line_contact(Q, R1, R2, L, st, st, profile="straight", n_slices=n)
        edges = np.append(c.x - 0.5 * c.slice_width, c.x[-1] + 0.5 * c.slice_width) * 1e3
        for ax in (a_all, a_end):       # each slice's pressure over its width
            ax.stairs(c.pressure / 1e9, edges, color=f"C{k}", baseline=None,
                      label=f"line_contact, {n} slices (each over its width)")
    for level, r in (fe or {}).items():
        for ax in (a_all, a_end):
            ax.plot(r.x * 1e3, r.pressure / 1e9, "-", lw=1.8, color="k",
                    alpha=0.5 if level == "quick" else 1.0,
                    label=f"FE, {level} level ({r.n_dofs // 1000}k DOFs), nodal")
    a_end.set_xlim(4.0, 6.05)
    a_all.set_ylim(0.0, 4.0)
    for ax in (a_all, a_end):
        ax.set(xlabel="x along the roller [mm]", ylabel="contact pressure [GPa]")
        ax.grid(alpha=0.3)
    a_all.set_title("the whole roller")
    a_end.set_title("the last 2 mm: the end peak grows with every refinement")
    a_end.legend(fontsize=7, loc="upper left")
    ground = "a flat raceway" if fe else "a 60 mm raceway"
    fig.suptitle(f"Straight 12 mm roller on {ground}, {Q / 1e3:g} kN: a sharp edge has no "
                 "converged pressure on a half-space")
    fig.savefig(path, dpi=110, facecolor="white")


# --------------------------------------------------------------------------- FE
def run_fe(level, reuse=None):
    """FE of the three rollers on a flat raceway (half-space mode), by label; with
    ``reuse`` (a folder), the results are kept there as pickles and read back on the next
    run with the same level (to redraw without solving again)."""
    import pickle

    from ballrace import fem

    store = Path(reuse) / f"edge-fe-{level}.pickle" if reuse else None
    if store is not None and store.exists():
        log.info("FE results read from %s", store)
        with open(store, "rb") as f:
            return pickle.load(f)

    st = _steel()
    chosen = {"straight": "straight",
              "circular crown (4 mm flat, R = 0.5 m)":
                  profiles()["circular crown (4 mm flat, R = 0.5 m)"],
              "Lundberg (for 5 kN)": profiles()["Lundberg (for 5 kN)"]}
    out = {}
    for name, prof in chosen.items():
        t0, c0 = time.time(), time.process_time()
        r = fem.roller_contact(Q, R1, math.inf, L, st, st, profile=prof, level=level,
                               n_slices=N_SLICES)
        log.info("FE %s, %s: %d DOFs, %.0f s wall, %.0f s CPU (this process)", name, level,
                 r.n_dofs, time.time() - t0, time.process_time() - c0)
        out[name] = r
    if store is not None:
        store.parent.mkdir(parents=True, exist_ok=True)
        with open(store, "wb") as f:
            pickle.dump(out, f)
    return out


def fe_pressure_figure(path, results):
    """FE against line_contact and the lamina model, pressure along the half roller."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(13, 4.3), layout="constrained")
    axes = fig.subplots(1, len(results), sharey=True)
    w = L / N_SLICES * 1e3
    for ax, (name, r) in zip(axes, results.items()):
        c = r.analytic
        mid = (c.n_slices - 1) // 2
        xl, pl = lamina_pressure(c.profile, math.inf)
        ax.stairs(pl[mid:] / 1e9, np.append(xl[mid:] * 1e3 - w / 2, L / 2 * 1e3),
                  color="0.5", baseline=None, label="lamina (ISO/TS 16281)")
        ax.plot(r.x * 1e3, r.pressure / 1e9, "-", lw=1.4, color="C0",
                label=f"FE, {r.level} level, nodal")
        ax.plot(r.slice_x * 1e3, r.slice_pressure / 1e9, "o", ms=4, mfc="none", color="C0",
                label="FE, averaged over each slice")
        ax.plot(c.x[mid:] * 1e3, c.pressure[mid:] / 1e9, "x", ms=5, color="C3",
                label=f"line_contact, {N_SLICES} slices")
        ax.axhline(c.hertz_pressure / 1e9, color="k", lw=0.6, ls=":",
                   label="2-D Hertz at Q/L")
        ax.set(title=name, xlabel="x along the roller [mm]")
        ax.grid(alpha=0.3)
    top = max(float(np.max(r.pressure)) for r in results.values()) / 1e9
    axes[0].set_ylim(0.0, max(3.0, 1.05 * top))
    axes[0].set_ylabel("contact pressure [GPa]")
    axes[0].legend(fontsize=7, loc="lower left")
    fig.suptitle(f"Half roller (x = 0 centre, 6 mm end) on a flat raceway, {Q / 1e3:g} kN: "
                 "FE (half-space mode) against line_contact and the lamina model")
    fig.savefig(path, dpi=110, facecolor="white")


def fe_pictures(results, stem="edge-fe"):
    """3-D pictures of the FE von Mises field (ballrace.fem.render.render_roller)."""
    from ballrace.fem.render import render_roller

    names = {"straight": "straight", "circular crown (4 mm flat, R = 0.5 m)": "crowned",
             "Lundberg (for 5 kN)": "lundberg"}
    paths = []
    for name, r in results.items():
        p = OUT / f"{stem}-{names[name]}.png"
        render_roller(r, p, field="von_mises")
        paths.append(p)
    return paths


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--level", default="quick", help="FE mesh level (quick | standard)")
    ap.add_argument("--no-fe", action="store_true", help="analytic figures only")
    ap.add_argument("--no-3d", action="store_true", help="no pyvista pictures")
    ap.add_argument("--reuse", metavar="FOLDER",
                    help="keep the FE results in FOLDER and reuse them when present")
    args = ap.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    OUT.mkdir(parents=True, exist_ok=True)
    t0 = time.process_time()
    rows = profiles_figure(OUT / "edge-profiles.png")
    for name, c in rows:
        log.info("%-40s centre %.4f GPa, max %.4f GPa at x = %.2f mm, in contact %.2f mm",
                 name, c.pressure[N_SLICES // 2] / 1e9, c.max_pressure / 1e9,
                 c.x[int(np.argmax(c.pressure))] * 1e3, c.contact_length * 1e3)
    vonmises_figure(OUT / "edge-vonmises.png")
    log.info("analytic figures: %.1f s CPU", time.process_time() - t0)
    if args.no_fe:
        refinement_figure(OUT / "edge-straight-refinement.png")
        return
    results = run_fe(args.level, args.reuse)
    fe_pressure_figure(OUT / "edge-fe-pressure.png", results)
    straight = {args.level: results["straight"]}
    refinement_figure(OUT / "edge-straight-refinement.png", straight)
    if not args.no_3d:
        for p in fe_pictures(results):
            log.info("wrote %s", p)
    for name, r in results.items():
        log.info("%s: centre %.4f GPa (line_contact %.4f), edge peak %.3f GPa at x = %.2f mm, "
                 "VM centre %.0f MPa at %.3f mm, VM under the peak %.0f MPa at %.3f mm",
                 name, r.centre_pressure / 1e9, r.row("centre_pressure")["analytic"] / 1e9,
                 r.edge_pressure / 1e9, r.x_edge * 1e3, r.von_mises_centre / 1e6,
                 r.von_mises_centre_depth * 1e3, r.von_mises_edge / 1e6,
                 r.von_mises_edge_depth * 1e3)
    log.info("total: %.0f s CPU (this process)", time.process_time() - t0)


if __name__ == "__main__":
    main()
