"""FE check of a tilted roller (ballrace.fem.roller_contact(..., tilt=...)): the half model.

The reference is :func:`ballrace.analytic.roller.line_contact` at the same tilt, on the
roller of tests/test_fem_roller.py (R1 = 6 mm, L = 12 mm, 5 kN, steel on a flat
raceway) with the circular crown of ballrace.fem.roller's notes (4 mm flat, 0.5 m crown
radius) tilted by 0.5 mrad: line_contact puts the peak where the flat part ends on the +x
side (x = 2.34 mm) and leaves the end slices unloaded, the contact inside the roller.
The tolerances are the differences measured at each level (ballrace.fem.roller notes,
:data:`ballrace.fem.roller.TILT_TOLERANCE`).
"""
import importlib.util
import math
import warnings

import numpy as np
import pytest

import ballrace
from ballrace.analytic import roller

pytest.importorskip("skfem")
pytest.importorskip("gmsh")

from ballrace import fem  # noqa: E402
from ballrace.fem import roller as fr  # noqa: E402

ST = ballrace.BEARING_STEEL
Q, R1, L = 5000.0, 6e-3, 12e-3
CROWN = roller.Crowned(4e-3, 0.5)
TILT = 5e-4


# ----------------------------------------------------------------------------- cheap parts
def test_tilt_beyond_line_contacts_range_is_its_value_error():
    with pytest.raises(ValueError, match="tilt must be in"):
        fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=CROWN, level="quick", tilt=2.0)


def test_tilt_in_degrees_warns_and_fails_as_line_contact_does():
    # 0.3 "rad" is 17 degrees: line_contact's unit-slip warning, then its error (the
    # roller touches on one slice only) -- before any mesh is built
    with pytest.warns(UserWarning, match="degrees") as rec:
        with pytest.raises(ValueError, match="one slice"):
            fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=CROWN, level="quick",
                               tilt=0.3)
    assert any(r.filename == __file__ for r in rec)         # attributed to this line
    # 3 degrees typed as radians (0.052 rad): line_contact's warning that the contact
    # covers a few slices only, naming the tilt (as an error here: no FE run follows)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(UserWarning, match="check tilt = 0.0523599 rad"):
            fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=CROWN, level="quick",
                               tilt=math.radians(3.0))


def test_tensor_grid_over_both_sides_integrates_and_is_one_sided_at_both_ends():
    xq = fr.graded_nodes(1.0, 9, 0.05)
    g = fr.TensorGrid(np.concatenate([-xq[:0:-1], xq]), np.linspace(0.0, 0.5, 6))
    I = g.integrals(lambda x, y: x + 2.0 * y)
    assert I["m"].sum() == pytest.approx(1.0, rel=1e-12)               # the area 2 x 0.5
    assert I["G0"].sum() == pytest.approx(0.0 + 2.0 * 0.125 * 2, rel=1e-12)
    lam = np.ones(g.n_tents)
    assert g.strip_loads(lam, [-1.0, -0.3], [1.0, 0.2]) == pytest.approx([1.0, 0.25])
    # the penalty of a linear pressure along x vanishes inside and is the same at both ends
    X, _ = np.meshgrid(g.xn, g.yn, indexing="ij")
    R = g.curvature_penalty()
    r = (R @ np.ones(g.n_tents)).reshape(X.shape)
    assert np.allclose(r, r[::-1]) and r[0, 0] > 0


# ----------------------------------------------------------------------------- FE runs
@pytest.fixture(scope="module")
def tilted():
    return fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=CROWN, level="quick",
                              tilt=TILT)


@pytest.fixture(scope="module")
def untilted():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return (fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=CROWN, level="quick",
                                   tilt=0.0),
                fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=CROWN, level="quick"))


def test_tilted_roller_takes_the_half_model_over_the_full_length(tilted):
    f = tilted
    c = f.analytic
    assert f.info["model"] == "half" and f.info["tilt"] == TILT and c.tilt == TILT
    assert f.x[0] == pytest.approx(-L / 2) and f.x[-1] == pytest.approx(L / 2)
    assert f.slice_x.size == c.n_slices and len(f.side_by_side()) == c.n_slices
    # equilibrium of the half model x 2, and the slices' loads over the full length
    assert f.info["load_check"] == pytest.approx(Q, rel=1e-9)
    assert f.slice_loads.sum() == pytest.approx(Q, rel=0.005)
    assert f.info["slice_load_sum"] == f.slice_loads.sum()


def test_tilted_roller_peak_at_the_end_that_goes_in(tilted):
    # tilt > 0: the +x end goes in (line_contact's convention): the load and the
    # pressure peak where the flat part ends on the +x side, in both models
    f = tilted
    c = f.analytic
    assert c.x[np.argmax(c.pressure)] == pytest.approx(2.34e-3, abs=0.2e-3)
    assert 1.5e-3 < f.slice_x[np.argmax(f.slice_loads)] < 3.5e-3
    assert 1.5e-3 < f.slice_x[np.argmax(f.slice_pressure)] < 3.5e-3
    assert 0 < f.x_edge and f.info["x_edge_slice"] > 0
    plus = f.slice_x >= L / 4
    assert f.slice_loads[plus].sum() > 1.5 * f.slice_loads[f.slice_x <= -L / 4].sum()


def test_tilted_roller_loads_at_the_loaded_end_match_line_contact(tilted):
    # measured at the quick level (ballrace.fem.roller notes): the load of the outer
    # quarter at +x -0.47 %, each of its slices within 2.3 % of the mean slice load
    f = tilted
    r = f.row("end_quarter_load")
    assert r["tol"] == fr.TILT_TOLERANCE["quick"]["end_quarter_load"]
    assert abs(r["error"]) <= r["tol"] and r["ok"], r
    assert f.info["end_slice_load_deviation"] <= fr.TILT_TOLERANCE["quick"]["end_slices"]
    assert f.row("centre_pressure")["ok"] and f.row("approach")["ok"]


def test_untilted_roller_keeps_the_quarter_model(untilted, tilted):
    q0, qd = untilted
    assert q0.info["model"] == qd.info["model"] == "quarter"
    assert q0.n_dofs == qd.n_dofs and np.array_equal(q0.pressure, qd.pressure)
    assert q0.x[0] == 0.0 and q0.slice_x.size == (q0.analytic.n_slices + 1) // 2
    # the half model's meshes are the quarter's joined to their mirror images
    nq, nh = q0.info["mesh_nodes"][0], tilted.info["mesh_nodes"][0]
    assert 1.8 * nq < nh < 2 * nq and tilted.n_dofs > 1.8 * q0.n_dofs


# ----------------------------------------------------------------------------- pictures
can_draw = all(importlib.util.find_spec(m) is not None for m in ("pyvista", "matplotlib"))


def test_pressure_along_a_tilted_roller_is_drawn_over_the_whole_length(tilted, untilted):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure

    import importlib

    render = importlib.import_module("ballrace.fem.render")   # fem.render is a function

    # the half model: its nodes and slices as solved (-L/2 .. L/2), not mirrored; the
    # title says the tilt and the loaded end
    ax = Figure().subplots()
    render._roller_pressure_axes(ax, tilted)
    fe_nodes, fe_slices, lc = ax.get_lines()[:3]
    assert np.array_equal(fe_nodes.get_xdata(), tilted.x * 1e3)
    assert np.array_equal(fe_slices.get_xdata(), tilted.slice_x * 1e3)
    assert np.array_equal(lc.get_xdata(), tilted.analytic.x * 1e3)
    assert "tilt 0.5 mrad" in ax.get_title() and "loaded end at +x" in ax.get_title()
    assert "tilt 0.5 mrad" in render._roller_label(tilted)
    # the quarter model: mirrored about the centre to the whole length
    q0 = untilted[0]
    ax = Figure().subplots()
    render._roller_pressure_axes(ax, q0)
    x = ax.get_lines()[0].get_xdata()
    assert x.size == 2 * q0.x.size - 1 and np.allclose(x, -x[::-1])
    assert "tilt" not in ax.get_title() and "tilt" not in render._roller_label(q0)


@pytest.mark.skipif(not can_draw, reason="pyvista or matplotlib missing")
def test_tilted_roller_picture_from_the_results_own_raceway(tilted, tmp_path):
    from ballrace.fem.render import render_roller, roller_raceway_state

    state, u = roller_raceway_state(tilted)
    # the half model's raceway spans both ends of the roller
    assert state.mesh.p[0].min() < -L / 2 and state.mesh.p[0].max() > L / 2
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        p = render_roller(tilted, str(tmp_path / "tilted.png"), field="max_shear")
    assert (tmp_path / "tilted.png").stat().st_size > 50_000 and p.endswith("tilted.png")
