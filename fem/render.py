"""Pictures of an FE contact result beside the analytic solution (matplotlib, imported lazily).

Fields: ``"von_mises"``, ``"max_shear"`` (Tresca), ``"tau_xz"`` (orthogonal shear;
``"tau_yz"`` is accepted as Lundberg–Palmgren's name for the same stress, their y
being our rolling direction x) and ``"pressure"``.

A stress field is drawn on the section y = 0 through the contact (x rolling, depth z
down), mirrored to x < 0 (tau_xz is odd in x), as four panels: the FE field, the
analytic field of :func:`ballrace.analytic.subsurface.stress` on the same points and
colour scale, their difference FE - analytic, and a depth profile of both.  Analytic
maxima (the Lundberg–Palmgren points (+-x0, z0), the depths of the maximum shear and
von Mises stress) and the FE maxima are marked and named in a legend.  ``"pressure"``
shows the FE pressure on the contact patch with the Hertz ellipse outlined and the
profiles along x and y beside Hertz's.

Drawing uses matplotlib's object API on the Agg canvas (no pyplot state, no display,
no VTK), so it is safe in dask worker threads and silent on machines without X.
"""
from __future__ import annotations

import numpy as np

__all__ = ["render", "FIELDS", "section_comparison"]

FIELDS = ("von_mises", "max_shear", "tau_xz", "tau_yz", "pressure")
_TITLES = {"von_mises": "von Mises stress", "max_shear": "max shear (Tresca)",
           "tau_xz": "orthogonal shear tau_xz (LP tau_yz)", "pressure": "contact pressure"}


def section_comparison(r, field: str):
    """FE and analytic values of a stress ``field`` on the FE section y = 0.

    Parameters
    ----------
    r : FEResult
        A solved case (``r.fields`` holds the section).
    field : {"von_mises", "max_shear", "tau_xz"}
        Which stress.

    Returns
    -------
    x, z, fe, an : ndarray
        x from -x_max to x_max [m] (the FE quarter section mirrored), depth z [m], and the
        FE and analytic fields of shape (x.size, z.size) [Pa].
    """
    from ballrace.analytic import subsurface

    f = r.fields
    xs, zs = np.asarray(f["section_x"]), np.asarray(f["section_z"])
    V = np.asarray(f[field])
    sgn = -1.0 if field == "tau_xz" else 1.0
    x = np.concatenate([-xs[:0:-1], xs])
    fe = np.concatenate([sgn * V[:0:-1], V], axis=0)
    X, Z = np.meshgrid(x, zs, indexing="ij")
    s = subsurface.stress(r.analytic, X, 0.0 * X, Z, nu=_nu(r))
    an = {"von_mises": s.von_mises, "max_shear": s.tresca, "tau_xz": s.sxz}[field]
    return x, zs, fe, np.asarray(an, dtype=float)


def _nu(r) -> float:
    m = getattr(r.case, "material2", None)
    return float(getattr(m, "nu", 0.3))


def _label(r) -> str:
    return (f"{r.case.name}, Q = {r.case.load:g} N ({r.mode}, {r.gap} gap, "
            f"{r.level} mesh)")


def render(r, field: str = "von_mises", path: str = "out.png", *,
           window_size=(1280, 330)) -> str:
    """Draw one field of an :class:`~ballrace.fem.FEResult` beside the analytic one to a PNG.

    Parameters
    ----------
    r : FEResult
        A solved case (``r.fields`` holds the section and pressure data).
    field : {"von_mises", "max_shear", "tau_xz", "tau_yz", "pressure"}
        What to draw.
    path : str
        Output PNG path.
    window_size : (int, int)
        Image size [px] (width, height).

    Returns
    -------
    str
        The path written.
    """
    from ballrace.analytic._checks import check_choice

    check_choice(field, "field", FIELDS)
    if field == "tau_yz":
        field = "tau_xz"
    from matplotlib.figure import Figure

    dpi = 100
    fig = Figure(figsize=(window_size[0] / dpi, window_size[1] / dpi), dpi=dpi,
                 layout="constrained")
    if field == "pressure":
        _pressure(fig, r)
    else:
        _section(fig, r, field)
    fig.savefig(str(path), dpi=dpi, facecolor="white")
    return str(path)


def _section(fig, r, field: str) -> None:
    from matplotlib.colors import Normalize, TwoSlopeNorm

    from ballrace.analytic import subsurface

    mm = 1e3
    x, z, fe, an = section_comparison(r, field)
    diff = fe - an
    c = r.analytic
    nu = _nu(r)
    odd = field == "tau_xz"
    peak = float(np.max(np.abs(an))) / 1e6
    if odd:
        vmax = max(float(np.max(np.abs(fe))), float(np.max(np.abs(an)))) / 1e6
        norm, cmap = TwoSlopeNorm(0.0, -vmax, vmax), "RdBu_r"
    else:
        norm = Normalize(0.0, max(float(fe.max()), float(an.max())) / 1e6)
        cmap = "viridis"
    dmax = max(float(np.max(np.abs(diff))) / 1e6, 1e-9)
    axes = fig.subplots(1, 4, gridspec_kw={"width_ratios": [1, 1, 1, 0.62]})
    ext = (x[0] * mm, x[-1] * mm, z[-1] * mm, z[0] * mm)
    ims = []
    for ax, data, title, nrm, cm in (
            (axes[0], fe / 1e6, "FE", norm, cmap),
            (axes[1], an / 1e6, "analytic (Hertz, subsurface.stress)", norm, cmap),
            (axes[2], diff / 1e6, "FE - analytic", TwoSlopeNorm(0.0, -dmax, dmax), "PuOr_r")):
        ims.append(ax.imshow(data.T, extent=ext, origin="upper", aspect="auto", norm=nrm,
                             cmap=cm, interpolation="bilinear"))
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("x (rolling) [mm]", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.locator_params(axis="x", nbins=5)
        ax.locator_params(axis="y", nbins=4)
    axes[0].set_ylabel("depth z [mm]", fontsize=8)
    for ax in axes[1:3]:
        ax.tick_params(labelleft=False)
    cb = fig.colorbar(ims[1], ax=axes[:2], shrink=0.9, pad=0.01, aspect=25)
    cb.ax.set_title("MPa", fontsize=7)
    cb.ax.tick_params(labelsize=7)
    cb2 = fig.colorbar(ims[2], ax=axes[2], shrink=0.9, pad=0.01, aspect=25)
    cb2.ax.set_title("MPa", fontsize=7)
    cb2.ax.tick_params(labelsize=7)
    axes[2].set_title(f"FE - analytic (max |diff| = {100 * dmax / peak:.1f} % of peak)",
                      fontsize=9)

    # analytic and FE maxima, named in one legend
    if odd:
        o = subsurface.orthogonal_shear(c)
        xa, za = float(o.x0) * mm, float(o.z0) * mm
        apts = ([xa, -xa], [za, za])
        alab = "analytic max |tau_xz| (Lundberg-Palmgren +-x0, z0)"
        fpts = ([xa, -xa], [r.z0 * mm] * 2)
        flab = "FE max |tau_xz| depth (at +-x0)"
    elif field == "max_shear":
        m = subsurface.max_shear(c, nu=nu)
        apts, fpts = ([0.0], [float(m.depth) * mm]), ([0.0], [r.max_shear_depth * mm])
        alab, flab = "analytic max shear (on the axis)", "FE max shear (on the axis)"
    else:
        m = subsurface.von_mises(c, nu=nu)
        apts, fpts = ([0.0], [float(m.depth) * mm]), ([0.0], [r.von_mises_depth * mm])
        alab, flab = "analytic max von Mises (on the axis)", "FE max von Mises (on the axis)"
    for ax in axes[:3]:
        ax.plot(*apts, "o", mfc="white", mec="black", ms=6, label=alab)
        ax.plot(*fpts, "x", color="black", ms=6, mew=1.5, label=flab)

    # depth profile: on the axis, or max over x for tau_xz
    pa = axes[3]
    if odd:
        pa.plot(np.max(np.abs(fe), axis=0) / 1e6, z * mm, lw=1.6, label="FE")
        pa.plot(np.max(np.abs(an), axis=0) / 1e6, z * mm, "--", lw=1.4, color="k",
                label="analytic")
        pa.set_xlabel("max over x of |tau_xz| [MPa]", fontsize=8)
    else:
        f = r.fields
        key = {"max_shear": "axis_tresca", "von_mises": "axis_von_mises"}[field]
        za_ = np.asarray(f.get("axis_z", z))
        prof = np.asarray(f.get(key, fe[len(x) // 2]))
        st = subsurface.axis_stress(c, za_, nu=nu)
        an_ax = np.asarray(st.tresca if field == "max_shear" else st.von_mises)
        pa.plot(prof / 1e6, za_ * mm, lw=1.6, label="FE")
        pa.plot(an_ax / 1e6, za_ * mm, "--", lw=1.4, color="k", label="analytic")
        pa.set_xlabel("on the axis x = y = 0 [MPa]", fontsize=8)
    pa.invert_yaxis()
    pa.set_ylabel("depth z [mm]", fontsize=8)
    pa.set_title("depth profile", fontsize=9)
    pa.tick_params(labelsize=7)
    pa.locator_params(axis="x", nbins=4)
    pa.grid(alpha=0.3)
    pa.legend(fontsize=7, loc="lower right")
    h, lab = axes[0].get_legend_handles_labels()
    fig.legend(h, lab, loc="outside lower center", ncol=2, fontsize=7, frameon=False)
    fig.suptitle(f"{_TITLES[field]}: {_label(r)} - section y = 0", fontsize=10)


def _pressure(fig, r) -> None:
    mm = 1e3
    f = r.fields
    c = r.analytic
    g = f["grid"]
    ax_, ay_ = float(c.semi_axis_x), float(c.semi_axis_y)
    x = np.linspace(-g.Lx, g.Lx, 161)
    y = np.linspace(-g.Ly, g.Ly, 161)
    X, Y = np.meshgrid(x, y, indexing="ij")
    P = np.asarray(g.evaluate(f["lam"], np.abs(X), np.abs(Y))) / 1e6
    axes = fig.subplots(1, 3, gridspec_kw={"width_ratios": [1.2, 1, 1]})
    im = axes[0].imshow(P.T, extent=(x[0] * mm, x[-1] * mm, y[0] * mm, y[-1] * mm),
                        origin="lower", aspect="auto", cmap="viridis")
    t = np.linspace(0, 2 * np.pi, 361)
    axes[0].plot(ax_ * np.cos(t) * mm, ay_ * np.sin(t) * mm, "r-", lw=1.2,
                 label="Hertz ellipse")
    axes[0].set_xlabel("x (rolling) [mm]", fontsize=8)
    axes[0].set_ylabel("y (transverse) [mm]", fontsize=8)
    axes[0].set_title("FE contact pressure (axes not to scale)", fontsize=9)
    axes[0].legend(fontsize=7, loc="lower right")
    cb = fig.colorbar(im, ax=axes[0], shrink=0.9, pad=0.01)
    cb.ax.set_title("MPa", fontsize=7)
    cb.ax.tick_params(labelsize=7)
    for ax, u, lab, along in ((axes[1], x, "x (rolling)", "x"),
                              (axes[2], y, "y (transverse)", "y")):
        fe = (np.asarray(g.evaluate(f["lam"], np.abs(u), 0.0 * u)) if along == "x" else
              np.asarray(g.evaluate(f["lam"], 0.0 * u, np.abs(u)))) / 1e6
        hz = (np.asarray(c.pressure(u, 0.0)) if along == "x" else
              np.asarray(c.pressure(0.0, u))) / 1e6
        ax.plot(u * mm, fe, lw=1.6, label="FE")
        ax.plot(u * mm, hz, "--", color="k", lw=1.4, label="Hertz")
        ax.set_xlabel(f"{lab} [mm]", fontsize=8)
        ax.set_ylabel("p [MPa]", fontsize=8)
        ax.set_title(f"profile along {along}", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    for ax in axes:
        ax.tick_params(labelsize=7)
        ax.locator_params(axis="x", nbins=5)
    fig.suptitle(f"contact pressure: {_label(r)}", fontsize=10)
