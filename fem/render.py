"""Off-screen renders of an FE contact result (pyvista, imported lazily).

Fields: ``"von_mises"``, ``"max_shear"`` (Tresca), ``"tau_xz"`` (orthogonal shear;
``"tau_yz"`` is accepted as Lundberg–Palmgren's name for the same stress, their y
being our rolling direction x) on the section y = 0 through the contact, mirrored to
x < 0 (tau_xz is odd in x), with the analytic (+-x0, z0) marked; and ``"pressure"``
on the contact patch with the analytic Hertz ellipse outlined.
"""
from __future__ import annotations

import os

import numpy as np

__all__ = ["render", "FIELDS"]

FIELDS = ("von_mises", "max_shear", "tau_xz", "tau_yz", "pressure")
_TITLES = {"von_mises": "von Mises stress [MPa]", "max_shear": "max shear (Tresca) [MPa]",
           "tau_xz": "orthogonal shear tau_xz (LP tau_yz) [MPa]",
           "pressure": "contact pressure [MPa]"}


def render(r, field: str = "von_mises", path: str = "out.png", *,
           window_size=(1200, 800)) -> str:
    """Render one field of an :class:`~ballrace.fem.FEResult` to a PNG file.

    Parameters
    ----------
    r : FEResult
        A solved case (``r.fields`` holds the section and pressure data).
    field : {"von_mises", "max_shear", "tau_xz", "tau_yz", "pressure"}
        What to draw.
    path : str
        Output PNG path.
    window_size : (int, int)
        Image size [px].

    Returns
    -------
    str
        The path written.
    """
    from ballrace.analytic._checks import check_choice

    check_choice(field, "field", FIELDS)
    if field == "tau_yz":
        field = "tau_xz"
    os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")
    import pyvista as pv

    pv.OFF_SCREEN = True
    f = r.fields
    c = r.analytic
    mm = 1e3
    pl = pv.Plotter(off_screen=True, window_size=list(window_size))
    pl.set_background("white")
    if field == "pressure":
        g = f["grid"]
        x = np.linspace(-g.Lx, g.Lx, 161)
        y = np.linspace(-g.Ly, g.Ly, 161)
        X, Y = np.meshgrid(x, y, indexing="ij")
        P = g.evaluate(f["lam"], np.abs(X), np.abs(Y)) / 1e6
        sg = pv.StructuredGrid(X * mm, Y * mm, np.zeros_like(X))
        sg[_TITLES[field]] = P.ravel(order="F")
        pl.add_mesh(sg, scalars=_TITLES[field], cmap="viridis", show_edges=False,
                    scalar_bar_args={"color": "black", "title": _TITLES[field]})
        t = np.linspace(0, 2 * np.pi, 361)
        ell = np.stack([float(c.semi_axis_x) * np.cos(t) * mm, float(c.semi_axis_y) * np.sin(t) * mm,
                        np.full(t.size, 1e-6)], axis=1)
        pl.add_mesh(pv.lines_from_points(ell), color="red", line_width=3,
                    label="Hertz ellipse")
        pl.add_legend(bcolor="white", face=None)
        pl.view_xy()
        pl.add_text(f"{r.case.name}, Q = {r.case.load:g} N ({r.mode}, {r.gap} gap, {r.level}): "
                    f"x rolling, y transverse [mm]", font_size=10, color="black")
    else:
        xs, zs = f["section_x"], f["section_z"]
        V = f[field] / 1e6
        sgn = -1.0 if field == "tau_xz" else 1.0
        xf = np.concatenate([-xs[:0:-1], xs])
        Vf = np.concatenate([sgn * V[:0:-1], V], axis=0)
        X, Z = np.meshgrid(xf, zs, indexing="ij")
        sg = pv.StructuredGrid(X * mm, np.zeros_like(X), -Z * mm)
        sg[_TITLES[field]] = Vf.ravel(order="F")
        cmap = "RdBu_r" if field == "tau_xz" else "jet"
        clim = [-np.abs(Vf).max(), np.abs(Vf).max()] if field == "tau_xz" else None
        pl.add_mesh(sg, scalars=_TITLES[field], cmap=cmap, clim=clim,
                    scalar_bar_args={"color": "black", "title": _TITLES[field]})
        if field == "tau_xz":
            from ballrace.analytic import subsurface

            o = subsurface.orthogonal_shear(c)
            pts = np.array([[float(o.x0) * mm, 1e-6, -float(o.z0) * mm],
                            [-float(o.x0) * mm, 1e-6, -float(o.z0) * mm]])
            pl.add_points(pts, color="black", point_size=12, render_points_as_spheres=True)
        pl.view_xz()
        pl.add_text(f"{r.case.name}, Q = {r.case.load:g} N: section y = 0, x rolling, "
                    f"z depth [mm] ({r.mode}, {r.gap} gap, {r.level})", font_size=10,
                    color="black")
    pl.show_bounds(color="black", xtitle="x [mm]", ytitle="y [mm]", ztitle="z [mm]")
    pl.screenshot(str(path))
    pl.close()
    return str(path)
