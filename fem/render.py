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

:func:`render_3d` adds a 3-D picture with pyvista (imported inside it): the lower body
near the contact, cut away to show the sections y = 0 and x = 0, coloured by the von Mises
or Tresca stress recovered at the P2 nodes (:func:`nodal_stress`).  VTK's off-screen
window is chosen before the first window is made (:func:`offscreen_vtk`), so it prints
nothing on machines without X either.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["render", "render_3d", "render_roller", "roller_raceway_state", "FIELDS",
           "FIELDS_3D", "FIELDS_ROLLER", "section_comparison", "nodal_stress",
           "offscreen_vtk"]

FIELDS = ("von_mises", "max_shear", "tau_xz", "tau_yz", "pressure")
_TITLES = {"von_mises": "von Mises stress", "max_shear": "max shear (Tresca)",
           "tau_xz": "orthogonal shear tau_xz (LP tau_yz)", "pressure": "contact pressure"}


def section_comparison(r, field: str):
    """FE and analytic values of a stress ``field`` on the FE section y = 0.

    Parameters
    ----------
    r : FEResult
        A solved case (``r.fields`` holds the FE section and the analytic field on the
        same points, ``fields["analytic"]``, computed once by the solve).
    field : {"von_mises", "max_shear", "tau_xz"}
        Which stress.

    Returns
    -------
    x, z, fe, an : ndarray
        x from -x_max to x_max [m] (the FE quarter section mirrored), depth z [m], and the
        FE and analytic fields of shape (x.size, z.size) [Pa].  With a surface traction
        (``run_case(traction=...)``) the section of the loaded contact: normal and
        tangential FE solutions superposed (``fields["traction"]``, already over both
        signs of x, with a row just below the surface), against
        ``subsurface.stress(..., traction=mu)``.
    """
    f = r.fields
    t = f.get("traction")
    if t is not None:
        return (np.asarray(t["section_x"]), np.asarray(t["section_z"]),
                np.asarray(t[field], dtype=float), np.asarray(t["analytic"][field], dtype=float))
    xs, zs = np.asarray(f["section_x"]), np.asarray(f["section_z"])
    sgn = -1.0 if field == "tau_xz" else 1.0        # tau_xz is odd in x, the others even
    x = np.concatenate([-xs[:0:-1], xs])

    def mirrored(V):
        V = np.asarray(V, dtype=float)
        return np.concatenate([sgn * V[:0:-1], V], axis=0)
    return x, zs, mirrored(f[field]), mirrored(f["analytic"][field])


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
    trac = r.fields.get("traction")
    odd = field == "tau_xz" and trac is None
    peak = float(np.max(np.abs(an))) / 1e6
    if field == "tau_xz":
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
    if trac is not None:
        name = {"von_mises": "von Mises", "max_shear": "Tresca", "tau_xz": "|tau_xz|"}[field]
        pk = trac["peaks"].get({"max_shear": "tresca"}.get(field, field))
        if pk is None:                           # tau_xz: the section's largest |value|
            ka = np.unravel_index(np.argmax(np.abs(an)), an.shape)
            kf = np.unravel_index(np.argmax(np.abs(fe)), fe.shape)
            pk = {"analytic": (x[ka[0]], z[ka[1]]), "fe": (x[kf[0]], z[kf[1]])}
        apts = ([pk["analytic"][0] * mm], [pk["analytic"][1] * mm])
        fpts = ([pk["fe"][0] * mm], [pk["fe"][1] * mm])
        alab = f"analytic max {name} (traction {trac['mu']:g})"
        flab = f"FE max {name}"
    elif odd:
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
    if trac is not None:
        pa.plot(np.max(np.abs(fe), axis=0) / 1e6, z * mm, lw=1.6, label="FE")
        pa.plot(np.max(np.abs(an), axis=0) / 1e6, z * mm, "--", lw=1.4, color="k",
                label="analytic")
        pa.set_xlabel("max over x [MPa]", fontsize=8)
    elif odd:
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
    extra = "" if trac is None else (f", traction q = {trac['mu']:g} p along +x "
                                     f"({'FE' if trac['pressure'] == 'fe' else 'Hertz'} p)")
    fig.suptitle(f"{_TITLES[field]}: {_label(r)} - section y = 0{extra}", fontsize=10)


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


# --------------------------------------------------------------------------- 3-D (pyvista)
FIELDS_3D = ("von_mises", "max_shear")

# skfem P2 tetrahedron: vertices 0-3, then the midpoints of edges 01, 12, 02, 03, 13, 23
# (the same order as VTK's quadratic tetra).  Eight linear tets per P2 tet: four corners
# and the inner octahedron split along its diagonal m02-m13.
_SUBTETS = np.array([[0, 4, 6, 7], [4, 1, 5, 8], [6, 5, 2, 9], [7, 8, 9, 3],
                     [6, 8, 4, 5], [6, 8, 5, 9], [6, 8, 9, 7], [6, 8, 7, 4]])
_P2_REF = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [.5, 0, 0], [.5, .5, 0],
                    [0, .5, 0], [0, 0, .5], [.5, 0, .5], [0, .5, .5]], dtype=float)


def offscreen_vtk() -> None:
    """Choose VTK's off-screen render window before the first window is made.

    The pip VTK wheels (>= 9.4) try an X window first and print "bad X server
    connection" (with terminal colour codes) on a machine without a usable display
    before they fall back to EGL.  ``VTK_DEFAULT_OPENGL_WINDOW`` selects the window
    class directly; it is set (unless the user set it) to ``vtkEGLRenderWindow`` when
    libEGL is present, else to ``vtkOSOpenGLRenderWindow`` when libOSMesa is (Linux only;
    other systems keep VTK's default).  A missing library must not be named: VTK then
    crashes instead of falling back.
    """
    import ctypes.util
    import os
    import sys

    if "VTK_DEFAULT_OPENGL_WINDOW" in os.environ or not sys.platform.startswith("linux"):
        return
    if ctypes.util.find_library("EGL"):
        os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = "vtkEGLRenderWindow"
    elif ctypes.util.find_library("OSMesa"):
        os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = "vtkOSOpenGLRenderWindow"


def nodal_stress(state, u) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Stress recovered at the P2 nodes of a body by averaging the elements around each node.

    Parameters
    ----------
    state : BodyState
        An assembled body (``r.fields["states"][i]``).
    u : ndarray
        Its displacement vector (``r.fields["u"][i]``) [m].

    Returns
    -------
    points : ndarray (n, 3)
        The P2 nodes (vertices and edge midpoints) [m].
    cells : ndarray (m, 4)
        Linear tetrahedra on those nodes, eight per P2 tetrahedron.
    stress : ndarray (n, 6)
        Averaged stress ``sxx, syy, szz, sxy, sxz, syz`` in the mesh frame [Pa].
    """
    from skfem import ElementTetP2

    from .extract import locator

    sb = state.scalar_basis
    edofs = sb.element_dofs                                 # (10, nt)
    inv = locator(state)["inv"]                            # (nt, 3, 3)
    U = np.asarray(u).reshape(-1, 3)
    E, nu = state.body.E, state.body.nu
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    el = ElementTetP2()
    n = sb.N
    acc = np.zeros((n, 6))
    cnt = np.zeros(n)
    for k in range(10):                                     # evaluate at node k of every element
        X = _P2_REF[k][:, None]
        grad = np.zeros((edofs.shape[1], 3, 3))
        for i in range(10):
            _, dphi = el.lbasis(X, i)                        # (3, 1) reference gradient
            g = np.einsum("nji,j->ni", inv, dphi[:, 0])
            grad += U[edofs[i]][:, :, None] * g[:, None, :]
        eps = 0.5 * (grad + grad.transpose(0, 2, 1))
        tr = np.trace(eps, axis1=1, axis2=2)
        s = 2 * mu * eps + lam * tr[:, None, None] * np.eye(3)
        comp = np.stack([s[:, 0, 0], s[:, 1, 1], s[:, 2, 2], s[:, 0, 1], s[:, 0, 2],
                         s[:, 1, 2]], axis=1)
        np.add.at(acc, edofs[k], comp)
        np.add.at(cnt, edofs[k], 1.0)
    cells = edofs.T[:, _SUBTETS].reshape(-1, 4)
    return np.asarray(sb.doflocs).T.copy(), cells, acc / np.maximum(cnt, 1.0)[:, None]


def render_3d(r, path: str = "out-3d.png", *, field: str = "von_mises",
              window_size=(1280, 720)) -> str:
    """Off-screen pyvista picture of the FE stress field in the body under the contact.

    The lower body (plane, half-space or race) of the quarter model is cut to a box of
    about 2.5 semi-axes around the contact, mirrored about the symmetry planes x = 0 and
    y = 0 and drawn with the quadrant towards the viewer removed, so the two cut faces
    show the field on the sections y = 0 (rolling) and x = 0 (transverse) and the top
    shows it on the surface.  The Hertz contact ellipse is outlined on the surface;
    on the axis where the cuts meet, an open circle marks the analytic depth of the
    maximum and a cross the FE one.  The field is the element stress (exact P2 gradient)
    averaged at the P2 nodes, in MPa; coordinates are in mm.

    pyvista and VTK are imported here only, and VTK's off-screen window is chosen
    first (:func:`offscreen_vtk`), so nothing is printed on machines without X.

    Parameters
    ----------
    r : FEResult
        A solved case (``r.fields`` holds ``states`` and the displacements ``u``).
    path : str
        Output PNG path.
    field : {"von_mises", "max_shear"}
        von Mises or maximum shear (Tresca) stress.
    window_size : (int, int)
        Image size [px] (width, height).

    Returns
    -------
    str
        The path written.

    Raises
    ------
    ImportError
        If pyvista (VTK) is not installed.
    """
    from ballrace.analytic import subsurface
    from ballrace.analytic._checks import check_choice

    from .extract import tresca_von_mises

    check_choice(field, "field", FIELDS_3D)
    offscreen_vtk()
    import pyvista as pv                      # first: without pyvista, say that

    if r.fields.get("traction") is not None:
        raise NotImplementedError(
            "no 3-D picture of a contact with surface traction: the quarter model is "
            "mirrored as a symmetric field, the tangential part is antisymmetric in x; "
            "the section y = 0 (render) shows the loaded field")

    f = r.fields
    state = f["states"][-1]
    c = r.analytic
    pts, cells, S = nodal_stress(state, f["u"][-1])
    tres, vm = tresca_von_mises(S)
    val = (vm if field == "von_mises" else tres) / 1e6

    mm = 1e3
    ax_, ay_ = float(c.semi_axis_x), float(c.semi_axis_y)
    minor = min(ax_, ay_)
    surf = state.body.surface
    z_top = float(surf.height(0.0, 0.0)) if surf is not None else float(pts[:, 2].max())
    # a box of 2.5 semi-axes (1.6 along a much longer one), 2.5 minor semi-axes deep
    X, Y, D = 2.5 * ax_, 2.5 * ay_, 2.5 * minor
    X, Y = min(X, max(1.6 * ax_, 5.0 * Y)), min(Y, max(1.6 * ay_, 5.0 * X))
    tets = state.scalar_basis.element_dofs[:4].T             # the FE mesh (vertices first)
    depth = (np.asarray(surf.height(pts[:, 0], pts[:, 1]), dtype=float) - pts[:, 2]
             if surf is not None else z_top - pts[:, 2])
    near = np.all((pts[tets, 0] <= 1.5 * X) & (pts[tets, 1] <= 1.5 * Y)
                  & (depth[tets] <= 1.5 * D), axis=1)
    cells = cells.reshape(-1, 8, 4)[near].reshape(-1, 4)
    zlo, zhi = float(pts[:, 2].min()) * mm, float(pts[:, 2].max()) * mm
    box = (0.0, X * mm, 0.0, Y * mm, zlo - 1.0, zhi + 1.0)     # x, y only: depth clips z
    body = _cutaway(pv, cells, pts * mm, box, depth * mm, D * mm, val)
    edges = _cutaway(pv, tets[near], pts * mm, box, depth * mm, D * mm)

    pv.OFF_SCREEN = True
    title = {"von_mises": "von Mises stress", "max_shear": "max shear stress (Tresca)"}[field]
    pl = pv.Plotter(off_screen=True, window_size=tuple(int(v) for v in window_size))
    try:
        pl.set_background("white")
        hi, step = _nice_top(float(np.max(val[np.unique(cells)])))
        # mostly ambient light: the faces keep the colours of the scalar bar
        pl.add_mesh(body, scalars="MPa", cmap="viridis", clim=(0.0, hi), ambient=0.6,
                    diffuse=0.45, specular=0.0,
                    scalar_bar_args={"title": f"{title} [MPa]", "color": "black",
                                     "n_labels": int(round(hi / step)) + 1,
                                     "vertical": True, "position_x": 0.88, "position_y": 0.25,
                                     "height": 0.6, "width": 0.05, "fmt": "%.0f",
                                     "title_font_size": 14, "label_font_size": 12})
        pl.add_mesh(edges, style="wireframe", color="black", opacity=0.25, line_width=0.5)
        # Hertz ellipse on the surface (the removed quadrant left out)
        t = np.linspace(0.5 * np.pi, 2.0 * np.pi, 181)
        ex_, ey_ = ax_ * np.cos(t), ay_ * np.sin(t)
        ez = (np.asarray(surf.height(ex_, ey_), dtype=float) if surf is not None
              else np.full(t.size, z_top))
        line = np.stack([ex_, ey_, ez + 0.01 * minor], axis=1) * mm
        pl.add_mesh(pv.lines_from_points(line), color="red", line_width=3)
        nu = float(state.body.nu)
        if field == "von_mises":
            za, zf, fmax = (float(subsurface.von_mises(c, nu=nu).depth), r.von_mises_depth,
                            r.von_mises)
        else:
            za, zf, fmax = (float(subsurface.max_shear(c, nu=nu).depth), r.max_shear_depth,
                            r.max_shear)
        # analytic maximum: a sphere on the axis where the cuts meet; FE maximum: short
        # black lines at its depth on both cut faces
        pl.add_mesh(pv.Sphere(radius=0.05 * minor * mm, center=(0.0, 0.0, (z_top - za) * mm)),
                    color="magenta")
        zl, w = (z_top - zf) * mm, 0.6 * minor * mm
        for q in ((w, 0.0), (0.0, w)):
            seg = np.array([[0.0, 0.0, zl], [q[0], q[1], zl]]) + 1e-3 * w
            pl.add_mesh(pv.lines_from_points(seg), color="black", line_width=5)
        pl.add_legend([[f"Hertz contact ellipse (a = {ax_ * mm:.3f} mm, b = {ay_ * mm:.3f} mm)",
                        "red"],
                       [f"analytic max {_peak(c, nu, field):.0f} MPa "
                        f"at depth {za * mm:.3f} mm", "magenta"],
                       [f"FE max {fmax / 1e6:.0f} MPa at depth {zf * mm:.3f} mm "
                        "(black lines)", "black"]],
                      bcolor="white", border=False, size=(0.4, 0.12), loc="lower left",
                      face="circle")
        pl.add_text(f"{title}: {_label(r)}\nlower body, three quadrants of the mirrored "
                    "quarter model (sections y = 0 and x = 0), coordinates in mm",
                    position="upper_left", font_size=10, color="black")
        pl.show_bounds(location="outer", color="black", font_size=16, xtitle="x rolling [mm]",
                       ytitle="y transverse [mm]", ztitle="z [mm]", n_xlabels=3, n_ylabels=3,
                       n_zlabels=3, fmt="%.2f")
        view = (1.6, 1.25, 1.0) if Y <= 2 * X else (1.6, 0.6, 0.8)   # long side in view
        pl.camera_position = [view, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)]
        pl.reset_camera()
        pl.camera.zoom(1.1)
        pl.screenshot(str(path))
    finally:
        pl.close()
    return str(path)


def _cutaway(pv, cells, pts, box, depth, dmax, values=None, open_quadrant=(1, 1)):
    """Surface of the quarter-model mesh cut to ``box`` and ``depth <= dmax``, mirrored to
    the three quadrants but the one towards the viewer, ``open_quadrant`` (the signs of x
    and y: (1, 1) leaves x, y > 0 open; (1, -1), x > 0, y < 0).  ``open_quadrant = (0,
    -1)``: a half model's mesh (both signs of x, y >= 0), not mirrored (the side y < 0
    open)."""
    import warnings

    grid = pv.UnstructuredGrid({pv.CellType.TETRA: np.asarray(cells)}, np.asarray(pts))
    if values is not None:
        grid.point_data["MPa"] = values
    grid.point_data["depth"] = depth
    grid = grid.clip_box(box, invert=False, crinkle=False)
    grid = grid.clip_scalar(scalars="depth", invert=True, value=dmax)
    o = (0.0, 0.0, 0.0)
    if tuple(open_quadrant) == (0, -1):
        parts = [grid]
    else:
        mx, my = grid.reflect((1, 0, 0), point=o), grid.reflect((0, 1, 0), point=o)
        quads = {(1, 1): grid, (-1, 1): mx, (1, -1): my,
                 (-1, -1): mx.reflect((0, 1, 0), point=o)}
        parts = [g for q, g in quads.items() if q != tuple(open_quadrant)]
    with warnings.catch_warnings():      # pyvista's notice of a future default
        warnings.filterwarnings("ignore", message="The default value of `algorithm`")
        warnings.filterwarnings("ignore", message=".*extract_surface` will change")
        merged = parts[0].merge(parts[1:]) if len(parts) > 1 else parts[0]
        return merged.extract_surface()


def _peak(c, nu: float, field: str) -> float:
    from ballrace.analytic import subsurface

    if field == "von_mises":
        return float(subsurface.von_mises(c, nu=nu).sigma_vm) / 1e6
    return float(subsurface.max_shear(c, nu=nu).tau_max) / 1e6


def _nice_top(v: float) -> tuple[float, float]:
    """Colour-bar top at or above ``v`` and a round label step giving 4 to 8 steps."""
    e = 10.0 ** np.floor(np.log10(max(v, 1e-12)))
    step = next(m * e for m in (0.1, 0.2, 0.25, 0.4, 0.5, 1.0, 2.0) if np.ceil(v / (m * e)) <= 8)
    return float(np.ceil(v / step) * step), float(step)


# --------------------------------------------------------------------------- roller (pyvista)
FIELDS_ROLLER = ("von_mises", "max_shear")


def roller_raceway_state(r, *, raceway_radius=None, material=None):
    """The raceway body of a :class:`~ballrace.fem.RollerFEResult`, ready for drawing.

    The result keeps the raceway's mesh, elastic constants and surface
    (``fields["raceway"]``) and its displacements (``fields["u"]``); this builds the
    scikit-fem mesh and P2 basis on them (no stiffness matrix: a second or two) and
    checks the von Mises stress they give under the roller centre against the result's
    own (``fields["von_mises"]``).  Quarter and half models (a tilted roller) alike, at
    any level.

    Parameters
    ----------
    r : RollerFEResult
        A solved :func:`ballrace.fem.roller_contact`.
    raceway_radius : float, optional
        Deprecated, not needed: the result keeps its raceway (``info["raceway_radius"]``)
        [m].  Given, a DeprecationWarning; another value than the solve's, a ValueError.
    material : Material, optional
        Deprecated, not needed: the result keeps the raceway's E and nu [-].  Given, a
        DeprecationWarning; another Poisson's ratio than the solve's, a ValueError.

    Returns
    -------
    state : SimpleNamespace
        ``body`` (name, E [Pa], nu [-], surface), ``mesh``, ``scalar_basis``: what
        :func:`nodal_stress` and :mod:`ballrace.fem.extract` read.
    u : ndarray
        The raceway's displacement vector [m].

    Raises
    ------
    ValueError
        A result without its raceway body, or a deprecated ``raceway_radius`` or
        ``material`` that is not the solve's.
    """
    from types import SimpleNamespace

    from skfem import Basis, ElementTetP2, ElementVector

    from ballrace.errors import warn

    from . import extract as ex
    from .model import skfem_mesh

    body = r.fields.get("raceway")
    if body is None:
        raise ValueError("r: the result keeps no raceway body to draw (fields['raceway']); "
                         "solve it again with ballrace.fem.roller_contact")
    R2 = r.info.get("raceway_radius")
    R2 = math.inf if R2 is None else float(R2)
    if raceway_radius is not None:
        warn("render_roller / roller_raceway_state: raceway_radius is no longer needed "
             "(the result keeps its raceway) and will be removed; leave it out",
             DeprecationWarning)
        if not (float(raceway_radius) == R2
                or math.isclose(float(raceway_radius), R2, rel_tol=1e-12)):
            raise ValueError(f"raceway_radius = {raceway_radius!r} m: the contact was solved "
                             f"with R2 = {R2!r} m; leave raceway_radius out")
    if material is not None:
        warn("render_roller / roller_raceway_state: material is no longer needed (the "
             "result keeps the raceway's E and nu) and will be removed; leave it out",
             DeprecationWarning)
        if not math.isclose(float(material.nu), float(body.nu), rel_tol=1e-12):
            raise ValueError(f"material: nu = {material.nu!r}, the raceway was solved with "
                             f"nu = {body.nu!r}; leave material out")
    mesh = skfem_mesh(np.asarray(body.points), np.asarray(body.tets))   # as assembled
    sbasis = Basis(mesh, ElementVector(ElementTetP2()), intorder=1).with_element(ElementTetP2())
    surface = body.surface
    state = SimpleNamespace(body=SimpleNamespace(name=body.name, E=float(body.E),
                                                 nu=float(body.nu), surface=surface),
                            mesh=mesh, scalar_basis=sbasis)
    u = np.asarray(r.fields["u"][-1])
    if u.size != 3 * sbasis.N:
        raise ValueError("r: the raceway's displacements do not fit its mesh "
                         f"({u.size} values for {sbasis.N} P2 nodes)")
    # the result's own von Mises profile under the centre, recomputed on the body
    zs = np.asarray(r.fields["depth"])
    eps = 1e-7 * float(r.info["h"])
    pts = np.stack([np.full(zs.size, eps), np.full(zs.size, eps),
                    surface.height(0.0, 0.0) - zs], axis=1)
    vm = ex.tresca_von_mises(ex.to_depth_frame(ex.stresses(state, u, pts)))[1]
    if not np.allclose(vm, r.fields["von_mises"][0], rtol=1e-6):
        raise ValueError("r: the stress on the raceway body is not the result's own")
    return state, u


def _roller_half(r) -> bool:
    """True for a result of the half model (a tilt or an uneven profile)."""
    return r.info.get("model") == "half"


def _roller_loaded_end(r) -> float:
    """+1 when the more loaded end of a half-model result is at +x, -1 at -x (+1 for the
    quarter model) [-]."""
    if not _roller_half(r):
        return 1.0
    return -1.0 if float(r.info.get("x_edge_slice", 1.0)) < 0.0 else 1.0


def _roller_label(r) -> str:
    c = r.analytic
    prof = getattr(c.profile, "name", None) or type(c.profile).__name__
    tilt = float(r.info.get("tilt", 0.0) or 0.0)
    tilted = f", tilt {tilt * 1e3:.3g} mrad" if tilt else ""
    return (f"{prof} roller, Q = {c.load:g} N, L = {c.length * 1e3:g} mm{tilted} "
            f"({r.mode}, {r.info.get('model', 'quarter')} model, {r.level} level, "
            f"{r.n_dofs:,} DOFs)")


def render_roller(r, path: str = "roller.png", *, field: str = "von_mises",
                  raceway_radius=None, material=None, window_size=(1400, 1000)) -> str:
    """Picture of an FE roller contact: the stress below the contact and the pressure
    along the roller.

    Top: an off-screen pyvista view of the raceway block under the roller (the roller a
    grey segment above it), coloured by the stress recovered at the P2 nodes
    (:func:`nodal_stress`) in MPa.  The quarter model (no tilt) is mirrored to the
    whole roller length and cut open over ``x > 0, y < 0``, so that the section ``y = 0``
    under the roller axis — the field under the middle and below the roller end, the
    edge region — and the section ``x = 0`` across the rolling direction show the
    stress.  The half model (a tilted roller, or an uneven profile) spans the whole
    length already and is drawn as solved, its mirror image ``y < 0`` left open: the
    section ``y = 0`` shows the field under the whole length, seen from the more loaded
    end.  The axis along the
    roller is drawn compressed (the contact is some 40 half-widths long): the scale is
    written on the picture, the tick labels are true millimetres.
    Bottom: the pressure along the roller — the FE peak over the rolling direction at
    the tent nodes, its average over each of line_contact's slices, and line_contact's
    slice pressures; the title gives the end slice's load (FE and line_contact) and,
    for a tilted roller, the tilt and the load of the loaded end's outer quarter.

    pyvista (VTK) and matplotlib are imported here only; VTK's off-screen window is
    chosen first (:func:`offscreen_vtk`).

    Parameters
    ----------
    r : RollerFEResult
        A solved :func:`ballrace.fem.roller_contact` (it keeps its raceway body,
        :func:`roller_raceway_state`).
    path : str
        Output PNG path.
    field : {"von_mises", "max_shear"}
        von Mises or maximum shear (Tresca) stress.
    raceway_radius : float, optional
        Deprecated, not needed (the result keeps R1 and R2) [m]; given, a
        DeprecationWarning (:func:`roller_raceway_state`).
    material : Material, optional
        Deprecated, not needed; given, a DeprecationWarning.
    window_size : (int, int)
        Image size [px] (width, height).

    Returns
    -------
    str
        The path written.

    Raises
    ------
    ImportError
        If pyvista (VTK) or matplotlib is not installed.
    """
    from ballrace.analytic._checks import check_choice

    from .extract import tresca_von_mises

    check_choice(field, "field", FIELDS_ROLLER)
    offscreen_vtk()
    import pyvista as pv
    from matplotlib.figure import Figure

    state, u = roller_raceway_state(r, raceway_radius=raceway_radius, material=material)
    pts, cells, S = nodal_stress(state, u)
    tres, vm = tresca_von_mises(S)
    val = (vm if field == "von_mises" else tres) / 1e6
    c = r.analytic
    mm = 1e3
    half = _roller_half(r)
    end = _roller_loaded_end(r)
    Lh = 0.5 * float(c.length)
    b0 = float(r.info["b_hertz"])
    surf = state.body.surface
    depth = np.asarray(surf.height(pts[:, 0], pts[:, 1]), dtype=float) - pts[:, 2]
    # the box drawn: the roller and a little beyond its end (to a round length, the step
    # of the labels along it), 3 half-widths across and deep
    step_x = _nice_step(mm * (Lh + 8.0 * b0) / 3.0) / mm
    X, Y, D = math.ceil((Lh + 8.0 * b0) / step_x - 1e-9) * step_x, 3.0 * b0, 3.0 * b0
    sx = min(1.0, 3.0 * Y / X)                       # axial compression of the picture
    tets = state.scalar_basis.element_dofs[:4].T
    near = np.all((np.abs(pts[tets, 0]) <= 1.2 * X) & (pts[tets, 1] <= 1.5 * Y)
                  & (depth[tets] <= 1.5 * D), axis=1)
    cells = cells.reshape(-1, 8, 4)[near].reshape(-1, 4)
    P = pts * mm
    P[:, 0] *= sx
    zlo, zhi = float(P[:, 2].min()), float(P[:, 2].max())
    box = (-X * mm * sx if half else 0.0, X * mm * sx, 0.0, Y * mm, zlo - 1.0, zhi + 1.0)
    body = _cutaway(pv, cells, P, box, depth * mm, D * mm, val,
                    open_quadrant=(0, -1) if half else (1, -1))
    title = {"von_mises": "von Mises stress", "max_shear": "max shear stress (Tresca)"}[field]

    pl = pv.Plotter(off_screen=True, window_size=(int(window_size[0]),
                                                  int(0.62 * window_size[1])))
    try:
        pl.set_background("white")
        hi, step = _nice_top(float(np.max(val[np.unique(cells)])))
        pl.add_mesh(body, scalars="MPa", cmap="viridis", clim=(0.0, hi), ambient=0.6,
                    diffuse=0.45, specular=0.0,
                    scalar_bar_args={"title": {"von_mises": "von Mises [MPa]",
                                               "max_shear": "Tresca [MPa]"}[field],
                                     "color": "black", "n_labels": int(round(hi / step)) + 1,
                                     "vertical": True, "position_x": 0.88, "position_y": 0.2,
                                     "height": 0.65, "width": 0.04, "fmt": "%.0f",
                                     "title_font_size": 16, "label_font_size": 14})
        # the roller: a grey, translucent segment of its profiled surface resting on the
        # contact behind the section y = 0 (0 <= y <= Y), over its whole length
        from ballrace.analytic.roller import ProfileContext

        R1 = float(r.info["roller_radius"])
        ctx = ProfileContext(length=c.length, diameter=2.0 * R1, E_prime=c.E_prime, R=c.R,
                             load=c.load)
        XX, YY = np.meshgrid(np.linspace(-Lh, Lh, 241), np.linspace(0.0, Y, 13), indexing="ij")
        cap = 0.5 * D
        dr = np.asarray(c.profile.drop(np.clip(XX, -Lh * (1 - 1e-9), Lh * (1 - 1e-9)), ctx),
                        dtype=float)
        dr = np.minimum(np.where(np.isfinite(dr), dr, cap), cap)
        ZZ = dr + R1 - np.sqrt(np.clip(R1 * R1 - YY * YY, 0.0, None)) + float(surf.height(0, 0))
        roller = pv.StructuredGrid(XX * mm * sx, YY * mm, ZZ * mm + 0.01 * D * mm)
        pl.add_mesh(roller, color="silver", opacity=0.45, smooth_shading=True)
        for xe in (-Lh, Lh):                      # the roller ends
            yl = np.linspace(0.0, Y, 13)
            dz = float(np.minimum(cap, np.nan_to_num(
                float(c.profile.drop(xe * (1 - 1e-9), ctx)), nan=cap, posinf=cap)))
            zl = dz + R1 - np.sqrt(R1 * R1 - yl * yl) + 0.01 * D
            pl.add_mesh(pv.lines_from_points(np.stack([np.full(yl.size, xe * sx), yl, zl],
                                                      axis=1) * mm), color="dimgray",
                        line_width=2)
        if half:
            cut = ("cut open at the section y = 0 (under the roller axis) over the whole "
                   f"length, seen from the more loaded end (x {'>' if end > 0 else '<'} 0)")
        else:
            cut = ("cut open at the sections y = 0 (under the roller axis) and x = 0 "
                   "(mid-length)")
        pl.add_text(f"{title}: {_roller_label(r)}\nraceway under the roller (grey), {cut}; "
                    f"x drawn at {sx:.2g} of scale, coordinates in mm",
                    position="upper_left", font_size=11, color="black")
        axes = _roller_bounds(pl, body, sx, X * mm, step_x * mm, Y * mm)
        # seen from y < 0 (x grows to the right), from the loaded end's side of x = 0
        pl.camera_position = [(0.9 * end, -1.6, 0.75), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)]
        pl.reset_camera()
        pl.camera.zoom(1.6)
        axes()
        img = pl.screenshot(return_img=True)
    finally:
        pl.close()

    dpi = 100
    fig = Figure(figsize=(window_size[0] / dpi, window_size[1] / dpi), dpi=dpi,
                 layout="constrained")
    ax3, axp = fig.subplots(2, 1, gridspec_kw={"height_ratios": [0.62, 0.38]})
    ax3.imshow(img)
    ax3.set_axis_off()
    _roller_pressure_axes(axp, r)
    fig.savefig(str(path), dpi=dpi, facecolor="white")
    return str(path)


def _nice_step(v: float) -> float:
    """The largest of 1, 2, 2.5, 5 x 10^k at or below ``v`` (> 0)."""
    e = 10.0 ** math.floor(math.log10(v))
    return max(m * e for m in (1.0, 2.0, 2.5, 5.0) if m * e <= v * (1 + 1e-12))


def _roller_bounds(pl, body, sx: float, X: float, step: float, Y: float):
    """Cube axes of the roller picture; returns the function that writes its labels
    (called once the camera is set: pyvista rewrites them when the bounds change).

    Along the roller, drawn compressed by ``sx``, the labels are true mm at every
    ``step`` over ``-X <= x <= X`` [mm], the two end ones left blank (they met the z and
    y labels at the corners); the short y axis, seen nearly end-on, carries its range in
    its title instead of tick labels that overlapped it."""
    from vtkmodules.vtkCommonCore import vtkStringArray

    bb = np.array(body.bounds, dtype=float)
    bb[:2] /= sx                                 # the ranges in true mm
    actor = pl.show_bounds(location="outer", color="black", font_size=14,
                           xtitle="x along the roller [mm]", axes_ranges=bb.tolist(),
                           ytitle=f"y rolling, {bb[2]:.2f} to {bb[3]:.2f} mm",
                           ztitle="z [mm]", n_xlabels=3, n_ylabels=2, n_zlabels=3,
                           fmt="%.2f", show_ylabels=False)
    n = int(round(2.0 * X / step))

    def labels():
        arr = vtkStringArray()
        for i in range(n + 1):
            v = -X + i * step
            arr.InsertNextValue("" if i in (0, n) else f"{0.0 if abs(v) < 1e-9 * X else v:g}")
        actor.SetAxisLabels(0, arr)
    return labels


def _roller_pressure_axes(ax, r) -> None:
    """Pressure along the roller: FE nodes, FE slice averages, line_contact's slices.

    The quarter model's half roller (x >= 0) is mirrored to the whole length; the half
    model's results span it already."""
    c = r.analytic
    mm = 1e3
    half = _roller_half(r)
    x = np.asarray(r.x)
    p = np.asarray(r.pressure)
    sx = np.asarray(r.slice_x)
    sp = np.asarray(r.slice_pressure)
    if not half:
        x, p = np.concatenate([-x[:0:-1], x]), np.concatenate([p[:0:-1], p])
        sx, sp = np.concatenate([-sx[:0:-1], sx]), np.concatenate([sp[:0:-1], sp])
    xa = np.asarray(c.x)
    w = c.slice_width
    ax.plot(x * mm, p / 1e6, "-", color="C0", lw=1.2, marker=".", ms=4,
            label="FE: peak over y at the tent nodes")
    ax.step(sx * mm, sp / 1e6, where="mid", color="C1", lw=1.6,
            label="FE: averaged over each slice")
    ax.step(xa * mm, np.asarray(c.pressure) / 1e6, where="mid", color="k", ls="--", lw=1.3,
            label=f"line_contact ({c.n_slices} slices)")
    ax.axvline(-0.5 * c.length * mm, color="grey", lw=0.8, ls=":")
    ax.axvline(0.5 * c.length * mm, color="grey", lw=0.8, ls=":")
    ax.set_xlabel("x along the roller [mm]", fontsize=10)
    ax.set_ylabel("pressure [MPa]", fontsize=10)
    ax.set_xlim(-(0.5 * c.length + w) * mm, (0.5 * c.length + w) * mm)
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.tick_params(labelsize=9)
    e = r.row("edge_slice_load")
    cp = 100 * r.row("centre_pressure")["error"]
    if half:
        tilt = float(r.info.get("tilt", 0.0) or 0.0)
        side = "+x" if _roller_loaded_end(r) > 0 else "-x"
        q = r.row("end_quarter_load")
        ax.set_title(f"pressure along the roller, tilt {tilt * 1e3:.3g} mrad (the loaded "
                     f"end at {side}: end slice FE {e['fe']:.1f} N, line_contact "
                     f"{e['analytic']:.1f} N; outer quarter FE {q['fe']:.0f} N, "
                     f"{100 * q['error']:+.1f} %; centre pressure {cp:+.1f} %)", fontsize=10)
    else:
        ax.set_title(f"pressure along the roller (end slice load: FE {e['fe']:.1f} N, "
                     f"line_contact {e['analytic']:.1f} N; centre pressure {cp:+.1f} %)",
                     fontsize=10)
    ax.legend(fontsize=9, loc="lower center", ncol=3)
