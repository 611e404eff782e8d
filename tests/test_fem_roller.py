"""FE check of the finite line contact of a profiled roller (ballrace.fem.roller_contact).

The reference is :func:`ballrace.analytic.roller.line_contact` for the same inputs, on
the 12 mm x 12 mm-class roller of its own tests (R1 = 6 mm, L = 12 mm, 5 kN, steel on a
flat raceway).  Tolerances are the differences measured at each level (docs in
ballrace.fem.roller), not wishes; the cheap parts (tent grid, node grading, the
half-space displacement integral) are checked exactly.
"""
import math

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


# ----------------------------------------------------------------------------- cheap parts
def test_graded_nodes_reach_the_end_with_the_end_spacing():
    x = fr.graded_nodes(6e-3, 44, 5e-5)
    d = np.diff(x)
    assert x[0] == 0.0 and x[-1] == 6e-3 and x.size == 44
    assert d[-1] == pytest.approx(5e-5, rel=1e-6)
    assert np.all(d > 0) and np.all(np.diff(d) <= 1e-15)      # never finer towards the centre


def test_tensor_grid_tents_integrate_exactly():
    g = fr.TensorGrid(fr.graded_nodes(1.0, 9, 0.05), np.linspace(0.0, 0.5, 6))
    I = g.integrals(lambda x, y: x + 2.0 * y)
    assert I["m"].sum() == pytest.approx(0.5, rel=1e-12)              # the area
    assert I["G0"].sum() == pytest.approx(0.5 * 0.5 + 2 * 0.125, rel=1e-12)
    lam = np.ones(g.n_tents)
    assert g.strip_loads(lam, [0.0], [1.0])[0] == pytest.approx(0.5, rel=1e-12)
    # a bilinear field is reproduced by the tents
    X, Y = np.meshgrid(g.xn, g.yn, indexing="ij")
    assert g.evaluate((3 * X + Y).ravel(), 0.37, 0.21) == pytest.approx(3 * 0.37 + 0.21)


def test_halfspace_depth_displacement_matches_a_uniform_strip_load():
    # Lundberg's roller carries a nearly uniform Hertz pressure: at depth z << L under
    # the centre the displacement relative to infinity is that of a long strip, and it
    # falls as the depth grows (Boussinesq; Johnson 1985 eq. 3.22c) -- check the
    # quadrature against a brute-force double sum over the same pressure
    c = roller.line_contact(Q, R1, np.inf, L, ST, ST, profile="lundberg", n_slices=21)
    z = 3e-4
    w = fr.halfspace_w(c, z, ST.E, ST.nu, n_x=16, n_y=32)
    G = ST.E / (2 * (1 + ST.nu))
    tot = 0.0
    for xk, pk, bk in zip(c.x, c.pressure, c.half_width):
        xs = np.linspace(xk - c.slice_width / 2, xk + c.slice_width / 2, 401)
        ys = np.linspace(-bk, bk, 801)
        X, Y = np.meshgrid(0.5 * (xs[1:] + xs[:-1]), 0.5 * (ys[1:] + ys[:-1]), indexing="ij")
        p = pk * np.sqrt(np.clip(1 - (Y / bk) ** 2, 0, None))
        rho = np.sqrt(X**2 + Y**2 + z**2)
        tot += float(np.sum(p * (2 * (1 - ST.nu) / rho + z**2 / rho**3))) * np.diff(xs)[0] \
            * np.diff(ys)[0]
    assert w == pytest.approx(tot / (4 * math.pi * G), rel=2e-3)
    assert fr.halfspace_w(c, 2 * z, ST.E, ST.nu) < w


def test_bad_level_and_mode_are_named():
    with pytest.raises(ValueError, match="level"):
        fem.roller_contact(Q, R1, np.inf, L, ST, ST, level="coarse")
    with pytest.raises(ValueError, match="mode"):
        fem.roller_contact(Q, R1, np.inf, L, ST, ST, level="quick", mode="rigid")


# ----------------------------------------------------------------------------- FE runs
@pytest.fixture(scope="module")
def quick_lundberg():
    return fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile="lundberg", level="quick",
                              mode="half-space")


def test_quick_half_space_lundberg(quick_lundberg):
    f = quick_lundberg
    c = f.analytic
    # equilibrium of the quarter model x 4
    assert f.info["load_check"] == pytest.approx(Q, rel=1e-9)
    assert f.x[0] == 0.0 and f.x[-1] == pytest.approx(L / 2)
    assert f.pressure.shape == f.x.shape and f.n_dofs > 10_000
    # Lundberg's profile: uniform load along the roller (measured at quick: every slice
    # but the end one within 2 % of line_contact's 122.1 N)
    inner = slice(0, -1)
    assert np.allclose(f.slice_loads[inner], c.slice_loads[c.n_slices // 2:][inner], rtol=0.02)
    assert f.row("centre_pressure")["ok"]
    assert f.row("approach")["ok"]


STANDARD = {}


def _standard(profile, mode="half-space"):
    key = (str(profile), mode)
    if key not in STANDARD:
        STANDARD[key] = fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile=profile,
                                           level="standard", mode=mode)
    return STANDARD[key]


@pytest.mark.slow
def test_standard_lundberg_centre_pressure_within_3_percent():
    f = _standard("lundberg")
    r = f.row("centre_pressure")
    assert abs(r["error"]) <= 0.03, r
    assert abs(f.row("approach")["error"]) <= 0.01


@pytest.mark.slow
def test_standard_crowned_edge_peak():
    # circular crown, 4 mm flat, 0.5 m crown radius: the pressure peaks where the flat
    # part ends; FE and line_contact agree there within the tolerance measured at the
    # standard level (ballrace.fem.roller.EDGE_TOLERANCE)
    f = _standard(roller.Crowned(4e-3, 0.5))
    r = f.row("max_pressure")
    assert abs(r["error"]) <= fr.EDGE_TOLERANCE["crowned"], r
    r = f.row("peak_slice_load")
    assert abs(r["error"]) <= fr.EDGE_TOLERANCE["crowned_slice_load"], r
    # the load peaks off the centre, where the flat part ends (line_contact: x = 2.34 mm)
    c = f.analytic
    assert np.argmax(f.slice_loads) == np.argmax(c.slice_loads[c.n_slices // 2:])
    assert 1.5e-3 < f.slice_x[np.argmax(f.slice_loads)] < 3.0e-3


@pytest.mark.slow
def test_standard_straight_roller_edge_peak_is_reported():
    # a straight roller's edge pressure is singular: the FE edge peak is a property of
    # the mesh (it grows with refinement) -- reported, its position at the roller end
    f = _standard("straight")
    assert f.edge_pressure > 1.2 * f.centre_pressure
    assert f.x_edge == pytest.approx(L / 2, abs=2 * f.info["b_hertz"])
    assert f.row("edge_pressure")["tol"] is None


@pytest.mark.slow
def test_quick_two_body_finite_roller_shifts_load_to_the_middle():
    # the elastic roller of finite length on the block: its free end face makes the end
    # softer than the half-space Lundberg's profile is designed on, so the middle slices
    # carry more than line_contact's uniform load and the end slice less (measured at
    # the two-body standard level with n = 5: +5.7 % in the middle, -43 % at the end)
    f = fem.roller_contact(Q, R1, np.inf, L, ST, ST, profile="lundberg", level="quick",
                           mode="two-body")
    c = f.analytic
    an = c.slice_loads[c.n_slices // 2:]
    assert f.info["load_check"] == pytest.approx(Q, rel=1e-9)
    assert f.slice_loads[0] > 1.03 * an[0]
    assert f.slice_loads[-1] < 0.8 * an[-1]
    assert all(r["tol"] is None for r in f.comparison)    # a result, not a check
