"""fem.render.render_3d: the pyvista off-screen picture of an FE case, silent without X."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

pytest.importorskip("skfem")
pytest.importorskip("gmsh")


@pytest.fixture(scope="module")
def r():
    from ballrace import fem

    return fem.ball_on_plane(12.7e-3, 2000.0, level="quick")


def test_nodal_stress_is_exact_for_a_uniform_strain(r):
    """A linear displacement u = G x is represented exactly by P2: the averaged nodal stress
    is Hooke's law of the symmetric part of G at every node (to round-off)."""
    from ballrace.fem.render import nodal_stress

    state = r.fields["states"][-1]
    G = np.array([[1.0, 0.3, -0.2], [0.5, -0.7, 0.1], [0.2, 0.4, 0.6]]) * 1e-3
    X = np.asarray(state.scalar_basis.doflocs).T
    pts, cells, S = nodal_stress(state, (X @ G.T).ravel())
    E, nu = state.body.E, state.body.nu
    eps = 0.5 * (G + G.T)
    sig = E / (1 + nu) * (eps + nu / (1 - 2 * nu) * np.trace(eps) * np.eye(3))
    want = np.array([sig[0, 0], sig[1, 1], sig[2, 2], sig[0, 1], sig[0, 2], sig[1, 2]])
    assert np.max(np.abs(S - want)) <= 1e-6 * np.max(np.abs(want))
    assert pts.shape == (state.scalar_basis.N, 3)
    assert cells.shape == (8 * state.scalar_basis.element_dofs.shape[1], 4)
    # the eight sub-tetrahedra of every P2 tetrahedron fill it exactly
    P = pts[cells]
    vol = np.abs(np.einsum("ij,ij->i", np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]),
                           P[:, 3] - P[:, 0])) / 6
    m = state.mesh
    Q = m.p[:, m.t].transpose(2, 1, 0)
    vol_p2 = np.abs(np.einsum("ij,ij->i", np.cross(Q[:, 1] - Q[:, 0], Q[:, 2] - Q[:, 0]),
                              Q[:, 3] - Q[:, 0])) / 6
    assert vol.sum() == pytest.approx(vol_p2.sum(), rel=1e-12)


def test_nodal_von_mises_peak_matches_the_fe_result(r):
    """The field drawn has the on-axis maximum the FE result reports (within 3 %: nodal
    averaging against the exact element gradient on the quick mesh)."""
    from ballrace.fem.extract import tresca_von_mises
    from ballrace.fem.render import nodal_stress

    state = r.fields["states"][-1]
    pts, _, S = nodal_stress(state, r.fields["u"][-1])
    _, vm = tresca_von_mises(S)
    near = np.hypot(pts[:, 0], pts[:, 1]) < 0.05 * r.a
    assert np.max(vm[near]) == pytest.approx(r.von_mises, rel=0.03)


_SCRIPT = textwrap.dedent("""
    import os, sys
    from ballrace import fem
    from ballrace.fem.render import render_3d

    r = fem.ball_on_plane(12.7e-3, 2000.0, level="quick")
    os.environ.pop("DISPLAY", None)
    render_3d(r, sys.argv[1], window_size=(640, 360))
    os.environ["DISPLAY"] = ":97"         # a display that does not exist
    render_3d(r, sys.argv[2], field="max_shear")
""")


def test_render_3d_draws_a_png_and_prints_nothing(tmp_path):
    """Two renders in a fresh process, without DISPLAY and with a dead one: PNGs of the asked
    size with a picture in them, and nothing from VTK (no "bad X server connection")."""
    pytest.importorskip("pyvista")
    from matplotlib.image import imread

    a, b = tmp_path / "a.png", tmp_path / "b.png"
    env = {k: v for k, v in os.environ.items() if k != "VTK_DEFAULT_OPENGL_WINDOW"}
    out = subprocess.run([sys.executable, "-c", _SCRIPT, str(a), str(b)], env=env,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert "X server" not in out.stderr and "vtk" not in out.stderr.lower(), out.stderr
    assert out.stderr.strip() == "" and out.stdout.strip() == ""
    for p, size in ((a, (640, 360)), (b, (1280, 720))):
        img = imread(p)[..., :3]
        assert img.shape[:2] == size[::-1]
        white = np.all(img > 0.97, axis=-1).mean()
        assert 0.3 < white < 0.9, (p, white)          # a body on a white background
        # many colours: a shaded, colour-mapped field, not a flat silhouette
        assert len(np.unique((img * 255).astype(np.uint8).reshape(-1, 3), axis=0)) > 1000
        # both ends of the colour map (viridis dark purple and the yellow top ~15 %) are on
        # the body, left of the scalar bar: the field spans the colour range
        body = img[:, : int(0.85 * img.shape[1])]
        assert np.any((body[..., 0] > 0.6) & (body[..., 1] > 0.6) & (body[..., 2] < 0.25))
        assert np.any((body[..., 0] > 0.2) & (body[..., 0] < 0.35) & (body[..., 2] > 0.3)
                      & (body[..., 1] < 0.1))


def test_missing_pyvista_gives_a_note_in_the_report(tmp_path, monkeypatch):
    """Without pyvista the FE case still gives its matplotlib pictures, and the report figure
    says why the 3-D one is missing."""
    import types

    from ballrace.validation import calc_fem
    from ballrace.validation.figures import fem_figures

    monkeypatch.setitem(sys.modules, "pyvista", None)
    label, path = calc_fem._render_3d(None, str(tmp_path), "case")
    assert path == "" and "pyvista" in label
    run = types.SimpleNamespace(results=[types.SimpleNamespace(
        id="case", title="t", area="fem", status="pass",
        artifacts=(("von_mises", str(tmp_path / "x.png")), (label, path)))])
    (fig,) = fem_figures(run)
    assert fig.images == (("von_mises", str(tmp_path / "x.png")),)
    assert "pyvista" in fig.note


@pytest.mark.parametrize("v, top, step", [(3081.0, 3200.0, 400.0), (747.0, 800.0, 100.0),
                                          (999.0, 1000.0, 200.0), (12.3, 14.0, 2.0)])
def test_colour_bar_top_is_round(v, top, step):
    from ballrace.fem.render import _nice_top

    assert _nice_top(v) == pytest.approx((top, step))
