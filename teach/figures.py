"""``ballrace teach subsurface``: the stress fields under a contact, depths marked
(with ``--traction``: the same contact with a tangential traction, :func:`traction_figure`).

Draws, in the plane y = 0 through the contact centre, the maximum shear stress
(Tresca), the von Mises stress and the orthogonal shear stress tau_xz (Lundberg &
Palmgren's tau_yz), all over p0, with the depths of the maxima from
:func:`~ballrace.analytic.subsurface.max_shear`, :func:`~.von_mises` and
:func:`~.orthogonal_shear` marked, plus their depth profiles on the axis.
"""
from __future__ import annotations

import logging
import math
from pathlib import Path

__all__ = ["subsurface_figure", "traction_figure", "title_text", "TRACTION_SWEEP"]

log = logging.getLogger(__name__)


def title_text(heading: str, load: float, c, nu: float, units: str = "eng") -> str:
    """The figure's title: the contact (Q, a, b, p0, nu) in the unit system ``units``
    (``"eng"``, ``"si"`` or ``"us"``, as the tables of :mod:`ballrace.console`).

    >>> from types import SimpleNamespace as C
    >>> c = C(a=1.0e-3, b=0.5e-3, p_max=2.0e9)
    >>> title_text("Subsurface stresses", 4448.2216152605, c, 0.3, "us")
    'Subsurface stresses: Q = 1000 lbf, a = 0.03937 in, b = 0.01969 in, p0 = 290.1 ksi, nu = 0.3'
    >>> title_text("Subsurface stresses", 2000.0, c, 0.3)
    'Subsurface stresses: Q = 2000 N, a = 1 mm, b = 0.5 mm, p0 = 2000 MPa, nu = 0.3'
    """
    from ballrace.console import convert, fmt, unit_label

    def q(v, kind):
        return f"{fmt(convert(float(v), kind, units), 4)} {unit_label(kind, units)}"

    return (f"{heading}: Q = {q(load, 'force')}, a = {q(c.a, 'length')}, "
            f"b = {q(c.b, 'length')}, p0 = {q(c.p_max, 'stress')}, nu = {nu:g}")


def _save(fig, path, heading: str, load: float, c, nu: float, units: str = "eng") -> None:
    """Title the figure with the contact (Q, a, b, p0, nu) and write it as a PNG."""
    fig.suptitle(title_text(heading, load, c, nu, units))
    fig.tight_layout()
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)


def subsurface_figure(load, rx1, ry1, rx2=math.inf, ry2=math.inf, *, E=200e9, nu=0.3,
                      path="subsurface.png", n: int = 121, units: str = "eng") -> dict:
    """Write the teaching figure to ``path``; returns the marked numbers (SI and over p0 / b).

    Parameters
    ----------
    load : float
        Normal load [N].
    rx1, ry1, rx2, ry2 : float
        Principal radii [m] (concave < 0, ``inf`` flat).
    E, nu : float
        Young's modulus [Pa] and Poisson's ratio [-] of both bodies.
    path : path
        PNG to write.
    units : str
        Unit system of the title: ``"eng"`` (N, mm, MPa), ``"si"`` or ``"us"`` (lbf, in,
        ksi).
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import numpy as np

    from ballrace import Material
    from ballrace.analytic import hertz, subsurface

    from ballrace.validation.figures import subsurface_fields

    c = hertz.point_contact(load, rx1, ry1, rx2, ry2, Material(E=E, nu=nu))
    x, z, f = subsurface_fields(c, nu=nu, n=n)
    b = float(c.semi_axis_x)
    p0 = float(c.p_max)
    mx = subsurface.max_shear(c, nu=nu)
    vm = subsurface.von_mises(c, nu=nu)
    o = subsurface.orthogonal_shear(c)
    marks = {"max shear": (0.0, float(mx.depth) / b, float(mx.tau_max) / p0),
             "von Mises": (0.0, float(vm.depth) / b, float(vm.sigma_vm) / p0),
             "orthogonal shear": (float(o.x0) / b, float(o.z0) / b, float(o.tau0) / p0)}
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    panels = (("tau_max", "max shear (Tresca) / p0", "viridis", "max shear"),
              ("von_mises", "von Mises / p0", "viridis", "von Mises"),
              ("tau_xz", "orthogonal shear tau_xz / p0", "RdBu_r", "orthogonal shear"))
    try:
        for ax, (key, title, cmap, mark) in zip(axes.ravel(), panels):
            cs = ax.contourf(x, z, f[key], levels=24, cmap=cmap)
            ax.contour(x, z, f[key], levels=12, colors="k", linewidths=0.3)
            fig.colorbar(cs, ax=ax, shrink=0.85)
            mx0, mz0, mv = marks[mark]
            xs = (mx0, -mx0) if mx0 else (0.0,)
            for xm in xs:
                ax.plot(xm, mz0, "w+", ms=12, mew=2)
            ax.axhline(mz0, color="w", ls="--", lw=0.8)
            # the value in a corner of the panel (inside it, whatever the mark's place)
            ax.text(0.02, 0.03, f"{mark}: {mv:.3f} p0 at z = {mz0:.3f} b",
                    transform=ax.transAxes, fontsize=8, va="bottom", ha="left",
                    bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="none", alpha=0.8))
            ax.set_title(title, fontsize=10)
            ax.set_xlabel("x / b (rolling direction)")
            ax.set_ylabel("depth z / b")
            ax.invert_yaxis()
            ax.set_aspect("equal")
        ax = axes[1, 1]
        mid = len(x) // 2
        ax.plot(f["tau_max"][:, mid], z, label="max shear on the axis")
        ax.plot(f["von_mises"][:, mid], z, label="von Mises on the axis")
        ax.plot(np.max(np.abs(f["tau_xz"]), axis=1), z, label="max |tau_xz| over x")
        depths: dict[float, list[str]] = {}        # one label per depth: names that share
        for name, (_, mz0, _) in marks.items():    # a depth (the circle's max shear and
            depths.setdefault(round(mz0, 3), []).append(name)   # von Mises) are joined
        for mz0, names in depths.items():
            ax.axhline(mz0, ls="--", lw=0.7, color="k")
            ax.annotate(", ".join(names), (0.98, mz0), xycoords=("axes fraction", "data"),
                        ha="right", va="bottom", fontsize=7)
        ax.invert_yaxis()
        ax.set_xlabel("stress / p0")
        ax.set_ylabel("depth z / b")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        _save(fig, path, "Subsurface stresses", load, c, nu, units)
    finally:
        plt.close(fig)
    log.info("wrote %s", path)
    return {"p_max [Pa]": p0, "b (semi-axis along x) [m]": b,
            **{f"{k}: value / p0, depth / b": (round(v, 4), round(d, 4))
               for k, (_, d, v) in marks.items()}}


#: Traction coefficients of the sweep drawn by :func:`traction_figure`.
TRACTION_SWEEP = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5)


def traction_figure(load, rx1, ry1, rx2=math.inf, ry2=math.inf, *, E=200e9, nu=0.3,
                    traction=0.3, path="subsurface-traction.png", n: int = 101,
                    units: str = "eng") -> dict:
    """Write the traction teaching figure to ``path``; returns the marked numbers.

    Four panels for one contact: the von Mises field in the plane y = 0 without traction
    and with ``traction`` (maxima marked), the maxima of the von Mises and Tresca
    stresses and their depths over the traction coefficients of :data:`TRACTION_SWEEP`
    plus ``traction``, and the surface stress sigma_x along y = 0 (the tension at the
    trailing edge x = -b).  The traction q = traction * p acts on the body along +x.

    Parameters
    ----------
    load : float
        Normal load [N].
    rx1, ry1, rx2, ry2 : float
        Principal radii [m] (concave < 0, ``inf`` flat).
    E, nu : float
        Young's modulus [Pa] and Poisson's ratio [-] of both bodies.
    traction : float
        Traction coefficient q/p [-], in [-10, 10].
    path : path
        PNG to write.
    n : int
        Grid points per side of the section.
    units : str
        Unit system of the title: ``"eng"`` (N, mm, MPa), ``"si"`` or ``"us"`` (lbf, in,
        ksi).
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import numpy as np

    from ballrace import Material
    from ballrace.analytic import hertz, subsurface

    c = hertz.point_contact(load, rx1, ry1, rx2, ry2, Material(E=E, nu=nu))
    mu = float(traction)
    b, p0 = float(c.semi_axis_x), float(c.p_max)
    x = np.linspace(-2.0, 2.0, n)
    z = np.linspace(0.0, 1.5, (n + 1) // 2)
    X, Z = np.meshgrid(x, z)
    sweep = sorted(set(TRACTION_SWEEP) | {abs(mu)})
    vms = [subsurface.von_mises(c, nu=nu, traction=m) for m in sweep]
    trs = [subsurface.max_shear(c, nu=nu, traction=m) for m in sweep]
    vm_mu = subsurface.von_mises(c, nu=nu, traction=mu)
    tr_mu = subsurface.max_shear(c, nu=nu, traction=mu)
    edge = -np.sign(mu) * b if mu else -b
    tension = float(subsurface.stress(c, edge, 0.0, 0.0, nu=nu, traction=mu).sxx) / p0
    st = subsurface.surface_tension(c, nu=nu, traction=mu)
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    try:
        for ax, m, v in ((axes[0, 0], 0.0, vms[0]), (axes[0, 1], mu, vm_mu)):
            f = subsurface.stress(c, X * b, 0.0, Z * b, nu=nu, traction=m).von_mises / p0
            cs = ax.contourf(x, z, f, levels=24, cmap="viridis")
            ax.contour(x, z, f, levels=12, colors="k", linewidths=0.3)
            fig.colorbar(cs, ax=ax, shrink=0.85)
            xm, zm = float(v.x) / b, float(v.depth) / b
            ax.plot(xm, zm, "w+", ms=12, mew=2)
            ax.set_title(f"von Mises / p0, traction {m:g}: max {float(v.sigma_vm) / p0:.3f} "
                         f"at x = {xm:.2f} b, z = {zm:.2f} b", fontsize=9)
            ax.set_xlabel("x / b (traction along +x)")
            ax.set_ylabel("depth z / b")
            ax.invert_yaxis()
            ax.set_aspect("equal")
        ax = axes[1, 0]
        ax.plot(sweep, [float(v.sigma_vm) / p0 for v in vms], "o-", label="max von Mises / p0")
        ax.plot(sweep, [float(t.tau_max) / p0 for t in trs], "s-", label="max Tresca / p0")
        ax2 = ax.twinx()
        ax2.plot(sweep, [float(v.depth) / b for v in vms], "o--", color="C2",
                 label="depth of the von Mises max / b")
        ax2.plot(sweep, [float(t.depth) / b for t in trs], "s--", color="C3",
                 label="depth of the Tresca max / b")
        ax2.set_ylabel("depth / b")
        ax.axvline(abs(mu), color="k", lw=0.7, ls=":")
        ax.set_xlabel("traction coefficient")
        ax.set_ylabel("stress / p0")
        ax.legend(fontsize=7, loc="upper left")
        ax2.legend(fontsize=7, loc="center right")
        ax.grid(alpha=0.3)
        ax = axes[1, 1]
        xs = np.linspace(-2.0, 2.0, 801)
        for m in (0.0, mu):
            ax.plot(xs, subsurface.stress(c, xs * b, 0.0, 0.0, nu=nu, traction=m).sxx / p0,
                    label=f"sigma_x at the surface, traction {m:g}")
        ax.plot(edge / b, tension, "ko")
        ax.set_title(f"surface: tension {tension:.3f} p0 at the trailing edge "
                     f"x = {edge / b:g} b", fontsize=9)
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_xlabel("x / b")
        ax.set_ylabel("stress / p0")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        _save(fig, path, f"Traction {mu:g}", load, c, nu, units)
    finally:
        plt.close(fig)
    log.info("wrote %s", path)
    return {"p_max [Pa]": p0, "b (semi-axis along x) [m]": b, "traction [-]": mu,
            "von Mises max / p0 at (x, z) / b": (round(float(vm_mu.sigma_vm) / p0, 4),
                                                 round(float(vm_mu.x) / b, 4),
                                                 round(float(vm_mu.depth) / b, 4)),
            "Tresca max / p0 at (x, z) / b": (round(float(tr_mu.tau_max) / p0, 4),
                                              round(float(tr_mu.x) / b, 4),
                                              round(float(tr_mu.depth) / b, 4)),
            "trailing-edge sigma_x / p0": round(tension, 4),
            "largest surface tension / p0 at (x, y) / b": (round(float(st.sigma1) / p0, 4),
                                                           round(float(st.x) / b, 4),
                                                           round(float(st.y) / b, 4))}
