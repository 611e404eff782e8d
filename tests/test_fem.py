"""Quick-level FE checks (default suite, well under a minute) and input validation.

Standard-level accuracy is asserted in ``tests/test_fem_slow.py`` (``make test-fem``).
"""
from __future__ import annotations

import importlib
import subprocess
import sys

import numpy as np
import pytest

import ballrace
from ballrace.analytic import hertz

def _has_fem() -> bool:
    return all(importlib.util.find_spec(m) is not None for m in ("skfem", "gmsh", "meshio"))


needs_fem = pytest.mark.skipif(not _has_fem(), reason="needs the fem extra (skfem, gmsh, meshio)")


@pytest.fixture(scope="session", autouse=True)
def _cache(tmp_path_factory):
    """A private mesh cache per test session (never the user's)."""
    mp = pytest.MonkeyPatch()
    mp.setenv("BALLRACE_CACHE", str(tmp_path_factory.mktemp("ballrace-cache")))
    yield
    mp.undo()


@pytest.fixture(scope="module")
def brg209():
    # 209 radial bearing of Hamrock & Dowson (1981) Table 3.2; contact angle 0
    return ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)


def test_import_is_light():
    code = ("import sys, ballrace.fem, ballrace.meshes; "
            "bad = [m for m in ('gmsh', 'skfem', 'pyvista', 'meshio') if m in sys.modules]; "
            "print(','.join(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


# --------------------------------------------------------------------------- bad input
def test_bad_inputs(brg209):
    from ballrace import fem

    with pytest.raises(ValueError, match="load"):
        fem.ball_on_race(brg209, 0.0, level="quick")
    with pytest.raises(ValueError, match="load"):
        fem.ball_on_plane(12.7e-3, -5.0, level="quick")
    with pytest.raises(ValueError, match="level"):
        fem.ball_on_plane(12.7e-3, 100.0, level="coarse")
    with pytest.raises(ValueError, match="mode"):
        fem.ball_on_plane(12.7e-3, 100.0, level="quick", mode="3-body")
    with pytest.raises(ValueError, match="race"):
        fem.ball_on_race(brg209, 100.0, race="middle")
    with pytest.raises(ValueError, match="ball_diameter"):       # D >= d_m
        fem.ball_on_race(_Brg(70e-3, 65e-3, 0.52), 100.0)
    with pytest.raises(ValueError, match="f_inner"):              # f <= 0.5
        fem.ball_on_race(_Brg(12.7e-3, 65e-3, 0.5), 100.0)
    with pytest.raises(TypeError):
        fem.ball_on_race("209", 100.0)


def test_cli_rejects_bad_input_before_meshing(tmp_path):
    """``ballrace fem`` exits 2 with the argument named; ``--case inner`` is a race case."""
    from typer.testing import CliRunner

    from ballrace.cli import app

    run = CliRunner().invoke
    res = run(app, ["fem", "--case", "inner", "--load", "-5 N", "--out", str(tmp_path)])
    assert res.exit_code == 2 and "load must be > 0" in res.output
    res = run(app, ["fem", "--case", "outer", "--load", "3 m", "--out", str(tmp_path)])
    assert res.exit_code == 2 and "load" in res.output
    res = run(app, ["fem", "--case", "cylinder", "--out", str(tmp_path)])
    assert res.exit_code == 2 and "--case must be one of" in res.output


def test_groove_case_from_plain_radii_equals_bearing_case(brg209):
    """A ball in a groove given by radii is the 209 race case without the bearing."""
    from ballrace import fem

    for race, Rr in (("inner", (65e-3 - 12.7e-3) / 2), ("outer", (65e-3 + 12.7e-3) / 2)):
        g = fem.groove_case(12.7e-3, 4450.0, Rr, 0.52 * 12.7e-3, race=race)
        c = fem.race_case(brg209, 4450.0, race)
        for q in ("a", "b", "p_max", "approach"):
            assert float(getattr(g.analytic, q)) == pytest.approx(float(getattr(c.analytic, q)),
                                                                  rel=1e-12)
        assert g.lower_radii == pytest.approx(c.lower_radii, rel=1e-12)
    with pytest.raises(ValueError, match="groove_radius"):
        fem.groove_case(12.7e-3, 100.0, 26e-3, 6.0e-3)               # r <= D/2
    with pytest.raises(ValueError, match="race_radius"):
        fem.groove_case(12.7e-3, 100.0, 10e-3, 6.6e-3, race="outer")  # inside the ball


class _Brg:
    """Duck-typed bearing that skips BallBearing's own checks (to reach fem's)."""

    def __init__(self, D, dm, f):
        self.ball_diameter, self.pitch_diameter, self.f_inner, self.f_outer = D, dm, f, f
        self.material = ballrace.BEARING_STEEL
        self.ball_material = self.ring_material = None

    def curvature(self, race, beta):  # pragma: no cover - not reached
        raise AssertionError


def test_bearing_rejects_bad_geometry():
    with pytest.raises(ValueError):
        ballrace.BallBearing(70e-3, 3, 65e-3, 0.52, 0.52, free_contact_angle=0.0)
    with pytest.raises(ValueError):
        ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.5, 0.52, free_contact_angle=0.0)


# --------------------------------------------------------------------------- geometry
def test_race_torus_matches_hertz_radii(brg209):
    from ballrace.meshes import geometry as geo

    for race in ("inner", "outer"):
        for beta in (0.0, np.radians(25.0)):
            t = geo.race_torus(12.7e-3, 65e-3, 0.52, race, beta)
            cur = brg209.curvature(race, beta)
            x = 5e-6
            kx = 2 * t.height(x, 0.0) / x**2           # race curvature (convex -> negative)
            ky = 2 * t.height(0.0, x) / x**2
            Rx = 1 / (2 / 12.7e-3 - kx)
            Ry = 1 / (2 / 12.7e-3 - ky)
            assert Rx == pytest.approx(float(cur.Rx), rel=1e-5)
            assert Ry == pytest.approx(float(cur.Ry), rel=1e-5)


@pytest.mark.parametrize("race", ["inner", "outer"])
def test_ring_surface_groove_and_lands(race):
    """Groove inside the shoulders, land cylinder (coaxial, h_s above the groove bottom)
    outside: checked against the closed forms of the contact-angle-0 cross-sections."""
    from ballrace.meshes import geometry as geo

    D, dm, f, hs = 12.7e-3, 65e-3, 0.52, 2.0e-3
    s = geo.ring_surface(D, dm, f, race, 0.0, shoulder_height=hs)
    r = f * D
    assert s.shoulder_y == pytest.approx(np.sqrt(r * r - (r - hs) ** 2), rel=1e-12)
    y = np.linspace(0.0, 0.95 * s.shoulder_y, 7)
    assert np.allclose(s.height(0.0, y), r - np.sqrt(r * r - y * y), rtol=0, atol=1e-12)
    # land along x: a circle about the bearing axis, radius R_L (convex inner, concave outer)
    R_L = (dm - D) / 2 + hs if race == "inner" else (dm + D) / 2 - hs
    x = np.linspace(0.0, 3e-3, 5)
    sign = -1.0 if race == "inner" else 1.0
    expect = hs + sign * (R_L - np.sqrt(R_L**2 - x * x))
    assert np.allclose(s.height(x, 1.5 * s.shoulder_y), expect, rtol=0, atol=1e-12)
    assert np.all(np.isfinite(s.height(x[:, None], np.linspace(0, 3 * r, 40))))


def test_halfspace_displacement_limits():
    from ballrace.fem.halfspace import axial_displacement

    c = hertz.elliptical_contact(1000.0, 0.004, 0.08, 219.78e9)
    nu = 0.3
    E = 0.5 * 219.78e9 * (1 - nu**2)      # E/(1-nu^2) = E'/2: w(0) is the whole approach
    w0 = axial_displacement(0.0, float(c.semi_axis_x), float(c.semi_axis_y), float(c.p_max), E, nu)
    assert w0 == pytest.approx(float(c.approach), rel=1e-6)


@needs_fem
@pytest.mark.parametrize("E, nu", [(200e9, 0.3), (3.1e11, 0.26), (1.0, 0.45)])
def test_fast_p2_elasticity_equals_scikit_fem(E, nu):
    """Our vectorized P2 stiffness equals scikit-fem's asm(linear_elasticity) to 1e-12."""
    from skfem import Basis, ElementTetP2, ElementVector, MeshTet, asm
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    from ballrace.fem.model import elasticity_p2

    m = MeshTet().refined(2)
    p = m.p + 0.03 * np.random.default_rng(1).standard_normal(m.p.shape)   # distorted
    m = MeshTet(p, m.t)
    b = Basis(m, ElementVector(ElementTetP2()), intorder=2)
    K0 = asm(linear_elasticity(*lame_parameters(E, nu)), b)
    sb = b.with_element(ElementTetP2())
    K1 = elasticity_p2(m.p, m.t, sb.element_dofs, b.N, E, nu, chunk=100)   # several chunks
    assert abs(K0 - K1).max() <= 1e-12 * abs(K0).max()
    # rigid-body modes are in the kernel: a translation and an infinitesimal rotation
    X = sb.doflocs                                   # vector DOF = 3 * scalar DOF + component
    for mode in (np.tile([1.0, 0, 0], sb.N), np.stack([-X[1], X[0], 0 * X[2]]).T.ravel()):
        assert np.abs(K1 @ mode).max() <= 1e-10 * abs(K1).max()


@needs_fem
def test_rigid_body_modes_are_the_kernel_and_amg_solves():
    """The six rigid-body modes are in the kernel of the unconstrained P2 stiffness, and
    the amg path (with them as near-nullspace) solves a constrained system like CHOLMOD
    or SuperLU."""
    from skfem import Basis, ElementTetP2, ElementVector, MeshTet

    from ballrace.fem.model import elasticity_p2
    from ballrace.fem.solvers import factorize, rigid_body_modes

    m = MeshTet().refined(2)
    b = Basis(m, ElementVector(ElementTetP2()), intorder=1)
    sb = b.with_element(ElementTetP2())
    K = elasticity_p2(m.p, m.t, sb.element_dofs, b.N, 200e9, 0.3)
    dof = np.arange(b.N)
    B = rigid_body_modes(sb.doflocs[:, dof // 3].T, dof % 3)
    assert np.linalg.matrix_rank(B) == 6
    assert np.abs(K @ B).max() <= 1e-9 * abs(K).max()
    fixed = b.get_dofs(lambda x: x[2] == 0.0).all()
    free = np.setdiff1d(dof, fixed)
    A = K[free][:, free].tocsc()
    rhs = np.random.default_rng(2).standard_normal((free.size, 2))
    x_ref = factorize(A, "superlu")[0](rhs)
    solve, name = factorize(A, "amg", near_nullspace=B[free])
    assert name == "amg"
    assert np.allclose(solve(rhs), x_ref, rtol=0, atol=1e-8 * np.abs(x_ref).max())


def test_solver_choice_and_slow_hint(monkeypatch):
    from ballrace.fem import solvers

    monkeypatch.setenv("BALLRACE_SOLVER", "superlu")
    assert solvers.chosen_solver() == "superlu"
    hint = solvers.slow_solver_hint(n_dofs=268_000)
    assert "268,000 DOFs" in hint and 'pip install "ballrace[fem]"' in hint
    monkeypatch.setenv("BALLRACE_SOLVER", "gauss")
    with pytest.raises(ValueError, match="solver must be one of"):
        solvers.chosen_solver()
    monkeypatch.delenv("BALLRACE_SOLVER")
    assert solvers.chosen_solver() in solvers.CHAIN            # amg only on request
    assert solvers.slow_solver_hint("cholmod") is None


def test_pressure_grid_moments():
    from ballrace.fem.model import PressureGrid
    from ballrace.fem.extract import pressure_moments

    c = hertz.elliptical_contact(1000.0, 0.004, 0.02, 219.78e9)
    ax, ay = float(c.semi_axis_x), float(c.semi_axis_y)
    g = PressureGrid(1.3 * ax, 1.3 * ay, 60, 60)
    xk, yk = g.nodes()
    lam = c.pressure(xk, yk)
    mom = pressure_moments(lam, g.integrals(lambda x, y: 0 * x))
    assert mom["ax"] == pytest.approx(ax, rel=3e-3)
    assert mom["ay"] == pytest.approx(ay, rel=3e-3)


# --------------------------------------------------------------------------- meshes
@needs_fem
@pytest.mark.fem
def test_mesh_determinism():
    from ballrace.meshes import ball_mesh, block_mesh

    a = 0.4e-3
    h1 = block_mesh((3e-3, 3e-3, 3e-3), (1.3 * a, 1.3 * a, a), a / 4, use_cache=False).digest()
    h2 = block_mesh((3e-3, 3e-3, 3e-3), (1.3 * a, 1.3 * a, a), a / 4, use_cache=False).digest()
    assert h1 == h2
    b1 = ball_mesh(6.35e-3, (a, 4 * a, a), a / 3, stretch=3.0, use_cache=False)
    b2 = ball_mesh(6.35e-3, (a, 4 * a, a), a / 3, stretch=3.0, use_cache=False)
    assert b1.digest() == b2.digest()
    r = np.linalg.norm(b1.points - [0, 0, 6.35e-3], axis=1)
    assert r.max() == pytest.approx(6.35e-3, rel=1e-5)
    assert b1.points[:, 2].min() == pytest.approx(0.0, abs=1e-12)   # touches the origin
    # a different parameter gives a different mesh
    h3 = block_mesh((3e-3, 3e-3, 3e-3), (1.3 * a, 1.3 * a, a), a / 5, use_cache=False).digest()
    assert h3 != h1


@needs_fem
@pytest.mark.fem
def test_mesh_cache_roundtrip(tmp_path, monkeypatch):
    from ballrace.meshes import block_mesh, cache_dir

    monkeypatch.setenv("BALLRACE_CACHE", str(tmp_path))
    m1 = block_mesh((2e-3, 2e-3, 2e-3), (5e-4, 5e-4, 5e-4), 2e-4)
    files = list(cache_dir().glob("block-*.vtu"))
    assert len(files) == 1
    m2 = block_mesh((2e-3, 2e-3, 2e-3), (5e-4, 5e-4, 5e-4), 2e-4)
    assert m2.seconds == 0.0 and m1.digest() == m2.digest()


# --------------------------------------------------------------------------- quick FE runs
def _check(r, names=("a", "b", "p_max", "approach", "tau0", "z0")):
    rows = {row["quantity"]: row for row in r.comparison}
    bad = [f"{q}: {100 * rows[q]['error']:+.2f} % (tol {100 * rows[q]['tol']:.1f} %)"
           for q in names if not rows[q]["ok"]]
    assert not bad, "; ".join(bad)


@needs_fem
@pytest.mark.fem
def test_quick_ball_on_plane():
    from ballrace import fem

    r = fem.ball_on_plane(12.7e-3, 2000.0, ballrace.BEARING_STEEL, level="quick")
    c = r.analytic
    assert r.a == pytest.approx(float(c.a), rel=0.05)
    assert r.b == pytest.approx(float(c.b), rel=0.05)
    assert r.p_max == pytest.approx(float(c.p_max), rel=0.06)
    _check(r)
    assert r.info["complementarity"] < 1e-8
    assert r.n_dofs > 0 and r.timings["total"] > 0


@needs_fem
@pytest.mark.fem
def test_quick_ball_on_inner_race(brg209):
    from ballrace import fem

    r = fem.ball_on_race(brg209, 4450.0, race="inner", level="quick", mode="half-space")
    c = r.analytic
    assert float(c.a) / float(c.b) > 9                  # a long, thin ellipse along y
    assert r.a == pytest.approx(float(c.a), rel=0.05)
    assert r.b == pytest.approx(float(c.b), rel=0.05)
    assert r.p_max == pytest.approx(float(c.p_max), rel=0.06)
    # approach: the FE estimate of Hertz's delta, directly comparable with analytic.approach
    rows = {row["quantity"]: row for row in r.comparison}
    assert rows["approach"]["analytic"] == float(c.approach)
    assert r.approach == pytest.approx(float(c.approach), rel=0.03)
    w = r.info["halfspace_w_depth_points"]
    assert r.approach == pytest.approx(r.approach_depth_point + w, rel=1e-12)
    assert rows["approach_depth_point"]["analytic"] == pytest.approx(float(c.approach) - w)
    # the rigid approach of the far planes includes the finite block's bulk compliance
    assert r.approach_rigid != pytest.approx(r.approach, rel=1e-3)
    d = r.to_dict()
    assert {"approach", "approach_depth_point", "approach_rigid"} <= set(d)
    _check(r, names=("a", "b", "p_max", "approach", "approach_depth_point", "tau0", "z0"))


@needs_fem
@pytest.mark.fem
def test_load_list_shares_mesh_and_factorisation():
    """loads=[...]: one mesh and one factorisation; each load gets its own Hertz reference
    and the contact scales as Hertz says (a ~ Q^(1/3), delta ~ Q^(2/3))."""
    from ballrace import fem

    rs = fem.ball_on_plane(12.7e-3, [1000.0, 2000.0], level="quick")
    assert [r.case.load for r in rs] == [1000.0, 2000.0]
    assert rs[0].info["mesh_digests"] == rs[1].info["mesh_digests"]
    assert rs[0].n_dofs == rs[1].n_dofs
    assert rs[0].timings["factorize"] == rs[1].timings["factorize"]      # shared, once
    for r in rs:
        assert r.analytic.load == r.case.load
        assert r.info["complementarity"] < 1e-8
        _check(r, names=("a", "b", "p_max", "approach", "tau0"))
    assert rs[1].a / rs[0].a == pytest.approx(2.0 ** (1 / 3), rel=0.01)
    assert rs[1].approach / rs[0].approach == pytest.approx(2.0 ** (2 / 3), rel=0.01)
    with pytest.raises(ValueError, match="loads"):
        fem.run_case(fem.plane_case(12.7e-3, 1.0), level="quick", loads=[1000.0, -1.0])


def test_factor_inner_partial_solve_matches_full_solve():
    """Factor.inner(F) = F^T A^-1 F: PARDISO's partial solve (rows of F only) against
    SuperLU's full solves, on a small P2 elasticity matrix; the full solve after a
    partial-solve factorisation still returns the whole solution."""
    import scipy.sparse as sp
    from skfem import Basis, ElementTetP2, ElementVector, MeshTet

    from ballrace.fem.model import elasticity_p2
    from ballrace.fem.solvers import available_solvers, factorize

    m = MeshTet().refined(2)
    b = Basis(m, ElementVector(ElementTetP2()), intorder=1)
    sb = b.with_element(ElementTetP2())
    K = elasticity_p2(m.p, m.t, sb.element_dofs, b.N, 200e9, 0.3)
    free = np.setdiff1d(np.arange(b.N), b.get_dofs(lambda x: x[2] == 0.0).all())
    A = K[free][:, free].tocsr()
    rng = np.random.default_rng(3)
    rows = rng.choice(A.shape[0], 40, replace=False)          # a "contact surface"
    F = sp.csc_matrix((rng.standard_normal(120), (np.repeat(rows, 3),
                       rng.integers(0, 7, 120))), shape=(A.shape[0], 7))
    ref, _ = factorize(A.tocsc(), "superlu")
    C_ref = F.T @ ref(F.toarray())
    C_lu = ref.inner(F)
    assert np.allclose(C_lu, C_ref, rtol=1e-12, atol=1e-12 * np.abs(C_ref).max())
    if "pardiso" not in available_solvers():
        pytest.skip("pypardiso not installed")
    fac, name = factorize(A, "pardiso", rows=np.flatnonzero(np.diff(F.tocsr().indptr)))
    assert name == "pardiso" and fac._iparm[30] == 1            # partial solve prepared
    C = fac.inner(F)
    assert np.allclose(C, C_ref, rtol=0, atol=1e-9 * np.abs(C_ref).max())
    rhs = rng.standard_normal(A.shape[0])
    assert np.allclose(fac(rhs), ref(rhs), rtol=0, atol=1e-9 * np.abs(ref(rhs)).max())
    fac.free()


@pytest.mark.parametrize("kind", ["plane", "inner", "outer"])
def test_tent_spacing_never_below_one_element(kind):
    """Tents closer than one surface element make the pressures oscillate (inf-sup):
    the grid rounds its cell count down when rounding to nearest would cross that."""
    import ballrace
    from ballrace.fem import api

    brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)
    for q in np.geomspace(30.0, 6000.0, 23):
        case = (api.plane_case(12.7e-3, q) if kind == "plane"
                else api.race_case(brg, q, kind, 0.0))
        for name in ("quick", "standard", "fine"):
            sz = api.sizing(case, name)
            assert sz.grid.dx >= sz.h * (1 - 1e-9), (q, name)
            assert sz.grid.dy >= sz.h * sz.stretch * (1 - 1e-9), (q, name)


def test_graded_refinement_region(tmp_path, monkeypatch):
    """A five-value refinement region (full depth only near y = 0, a thin layer along the
    rest) meshes fewer elements than the full box, with the same size at the surface."""
    pytest.importorskip("gmsh")
    from ballrace.meshes import contact as mc

    monkeypatch.setenv("BALLRACE_CACHE", str(tmp_path))
    box = (0.3, 1.2, 0.3)
    full = mc.block_mesh((2.0, 2.0, 2.0), box, 0.05, 0.5, stretch=2.0, use_cache=False)
    graded = mc.block_mesh((2.0, 2.0, 2.0), box + (0.3, 0.1), 0.05, 0.5, stretch=2.0,
                           use_cache=False)
    assert graded.tets.shape[0] < 0.8 * full.tets.shape[0]

    def surface_edge(msh, ylo, yhi):   # mean edge length of the top faces in a y band
        p, t = msh.points, msh.tets
        e = []
        for i, j in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)):
            a, b = p[t[:, i]], p[t[:, j]]
            top = (np.abs(a[:, 2]) < 1e-12) & (np.abs(b[:, 2]) < 1e-12)
            mid = 0.5 * (a[:, 1] + b[:, 1])
            sel = top & (mid > ylo) & (mid < yhi) & (np.maximum(a[:, 0], b[:, 0]) < 0.3)
            e.append(np.abs(a[sel, 0] - b[sel, 0]))
        return np.concatenate(e).mean()
    for lo, hi in ((0.0, 0.3), (0.7, 1.1)):
        assert surface_edge(graded, lo, hi) == pytest.approx(surface_edge(full, lo, hi),
                                                             rel=0.25)


def test_per_z0_refines_the_mesh_not_the_pressure_grid():
    """MeshLevel.per_z0: h = min(b/n, z0/per_z0); the tents keep the b/n spacing (to the
    nearest whole number of cells, which the finer mesh no longer has to round down)."""
    from ballrace.analytic.subsurface import orthogonal_shear
    from ballrace.fem import api

    case = api.plane_case(12.7e-3, 2000.0)
    b = float(case.analytic.semi_axis_x)
    z0 = float(orthogonal_shear(case.analytic).z0)
    base = api.sizing(case, api.MeshLevel(9, 2.3))
    fine = api.sizing(case, api.MeshLevel(9, 2.3, per_z0=4.2))
    assert base.h == pytest.approx(b / 9)
    assert fine.h == pytest.approx(min(b / 9, z0 / 4.2)) and fine.h < base.h   # z0 = 0.35 b
    for sz in (base, fine):
        assert sz.grid.dx == pytest.approx(b / 9, rel=0.1)
    assert fine.grid.dx > 1.2 * fine.h                          # tents ~1.33 elements apart


def test_probe_box_refines_where_the_stresses_are_sampled(tmp_path, monkeypatch):
    """MeshLevel.probe: a box of size h/probe over the stress sections (x from 0.6 to
    1.4 semi-axes, y over the section spread, 1 minor semi-axis deep); elsewhere the
    refinement box keeps h, the tents keep their spacing, and a mesh without a probe
    keeps its cache key."""
    pytest.importorskip("gmsh")
    from ballrace.fem import api
    from ballrace.meshes import contact as mc

    monkeypatch.setenv("BALLRACE_CACHE", str(tmp_path))
    case = api.plane_case(12.7e-3, 2000.0)
    b = float(case.analytic.semi_axis_x)
    base = api.sizing(case, api.MeshLevel(6, 2.3))
    sz = api.sizing(case, api.MeshLevel(6, 2.3, probe=2.0))
    assert base.probe == () and sz.h == base.h == pytest.approx(b / 6)
    x_lo, x_hi, y_hi, z_hi, hp, gp = sz.probe
    assert hp == pytest.approx(b / 12)
    assert x_lo == pytest.approx(0.6 * b - hp) and x_hi == pytest.approx(1.4 * b + hp)
    assert y_hi == pytest.approx((api.SECTION_SPREAD + 1) * hp) and z_hi == pytest.approx(b)
    assert sz.grid.dx == pytest.approx(base.grid.dx)
    assert mc.MeshSpec("block", (1.0, 1.0, 1.0), (0.1, 0.1, 0.1), 0.01, 0.2).key() != \
        mc.MeshSpec("block", (1.0, 1.0, 1.0), (0.1, 0.1, 0.1), 0.01, 0.2,
                    probe=(0.0, 0.1, 0.1, 0.1, 0.005, 0.6)).key()

    L = 8 * b
    msh = {k: mc.block_mesh((L, L, L), s.fine, s.h, L / 5, probe=s.probe, use_cache=False)
           for k, s in (("base", base), ("probe", sz))}

    def edge(m, box):     # median edge length of the tets whose centroid lies in box
        p, t = m.points, m.tets
        c = p[t].mean(axis=1)
        sel = np.all([(c[:, i] > lo) & (c[:, i] < hi) for i, (lo, hi) in enumerate(box)], 0)
        e = [np.linalg.norm(p[t[sel, i]] - p[t[sel, j]], axis=1)
             for i, j in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3))]
        return float(np.median(np.concatenate(e)))
    inside = ((0.7 * b, 1.3 * b), (0.0, 0.3 * b), (-0.8 * b, -0.2 * b))
    outside = ((0.0, 1.2 * b), (0.9 * b, 1.2 * b), (-0.8 * b, -0.2 * b))
    assert edge(msh["probe"], inside) == pytest.approx(0.5 * edge(msh["base"], inside), rel=0.2)
    assert edge(msh["probe"], outside) == pytest.approx(edge(msh["base"], outside), rel=0.2)


def test_even_fit_returns_the_value_at_y0_of_an_even_quartic():
    """extract.even_fit is exact for c0 + c2 y^2 + c4 y^4 (any coefficients, any shape of
    the leading axes) and averages zero-mean scatter instead of following it."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from ballrace.fem.extract import even_fit

    y = np.linspace(0.0, 3.5e-5, 9)

    @settings(max_examples=50, deadline=None)
    @given(st.lists(st.floats(-1e9, 1e9), min_size=3, max_size=3))
    def check(c):
        v = c[0] + c[1] * (y / 1e-5) ** 2 + c[2] * (y / 1e-5) ** 4
        vals = np.stack([v, 2 * v], axis=0)[:, None, :]          # (2, 1, 9)
        out = even_fit(vals, y)
        assert out.shape == (2, 1)
        np.testing.assert_allclose(out[:, 0], [c[0], 2 * c[0]], atol=1e-6 * (1 + max(map(abs, c))))

    check()
    rng = np.random.default_rng(1)
    noise = rng.normal(0.0, 1.0, (4000, 9))
    # the fitted c0 of pure noise scatters less than one sample does
    assert np.std(even_fit(noise, y)) < 0.9


def test_tent_smoothing_damps_a_checkerboard_the_compliance_does_not_resist():
    """solve_contact with PressureGrid.curvature_penalty: on a compliance that is nearly
    blind to the tent checkerboard (a smooth kernel), the unpenalised NNLS pressure
    oscillates; the penalty removes most of the oscillation and keeps the load."""
    from ballrace.fem.model import PressureGrid, solve_contact

    g = PressureGrid(1.3, 1.3, 12, 12)
    x, y = g.nodes()
    d2 = (x[:, None] - x[None]) ** 2 + (y[:, None] - y[None]) ** 2
    C = np.exp(-d2 / 0.3**2) + 1e-6 * np.eye(g.n_tents)      # smooth: checkerboard ~free
    I = g.integrals(lambda xx, yy: 0.5 * (xx**2 + yy**2))
    i, j = np.meshgrid(np.arange(13), np.arange(13), indexing="ij")
    chk = ((-1.0) ** (i + j)).ravel()
    inside = x**2 + y**2 < 0.6**2

    def oscillation(lam):
        return abs(float(np.mean((lam * chk)[inside]))) / float(np.mean(lam[inside]))

    R = g.curvature_penalty()
    s0 = solve_contact(C, I["G0"], I["m"], load=0.05)
    s1 = solve_contact(C, I["G0"], I["m"], load=0.05, penalty=np.mean(np.diag(C)) / 16 * R)
    assert s1.load == pytest.approx(0.05, rel=1e-9)
    assert s0.load == pytest.approx(0.05, rel=1e-9)
    assert oscillation(s1.lam) < 0.25 * oscillation(s0.lam)


def test_locate_finds_inside_points_and_names_outside_ones():
    """extract.locate: barycentric coordinates of inside points; a point outside the mesh
    raises a ValueError naming it (the search widens 64-fold at most, it does not grow
    over the whole mesh: an offset bug once asked it for 6 GB)."""
    from types import SimpleNamespace

    from skfem import MeshTet

    from ballrace.fem import extract as ex

    m = MeshTet().refined(3)
    state = SimpleNamespace(mesh=m, body=SimpleNamespace(name="cube"))
    pts = np.array([[0.21, 0.33, 0.47], [0.9, 0.05, 0.5]])
    tind, X = ex.locate(state, pts)
    P = m.p[:, m.t[:, tind]]                                  # (3, 4, n)
    back = P[:, 0] + np.einsum("ikn,nk->in", P[:, 1:] - P[:, :1], X)
    np.testing.assert_allclose(back.T, pts, atol=1e-12)
    assert np.all(X >= -1e-9) and np.all(X.sum(axis=1) <= 1 + 1e-9)
    with pytest.raises(ValueError, match=r"1 probe points lie outside the mesh of cube"):
        ex.locate(state, np.array([[0.5, 0.5, 0.5], [5.0, 5.0, 5.0]]))


# --------------------------------------------------------------------------- traction
TRACTION_ROWS = ("traction_von_mises", "traction_von_mises_x", "traction_von_mises_depth",
                 "traction_tresca", "traction_tresca_x", "traction_tresca_depth",
                 "traction_sxx_trailing", "traction_section_rms", "traction_resultant")


def test_traction_bad_input(brg209):
    from ballrace import fem

    with pytest.raises(ValueError, match="traction"):
        fem.ball_on_plane(12.7e-3, 100.0, level="quick", traction=11.0)
    with pytest.raises(ValueError, match="traction"):
        fem.ball_on_plane(12.7e-3, 100.0, level="quick", traction=float("nan"))
    with pytest.raises(ValueError, match="traction_pressure"):
        fem.ball_on_race(brg209, 100.0, level="quick", traction=0.1, traction_pressure="x")


def test_traction_in_the_fe_case_file():
    from ballrace.casefiles.bearing import CaseFileError
    from ballrace.fem.cli import parse_fe_case

    fc = parse_fe_case({"case": {"contact": "plane", "load": "2 kN"},
                        "fem": {"traction": 0.3, "traction_pressure": "hertz"}})
    assert (fc.traction, fc.traction_pressure) == (0.3, "hertz")
    assert parse_fe_case({}, traction=0.1).traction == 0.1          # --traction wins
    assert parse_fe_case({}).traction == 0.0
    with pytest.raises(CaseFileError, match=r"\[fem\]\.traction"):
        parse_fe_case({"fem": {"traction": 20}}, "x.toml")


@needs_fem
@pytest.mark.fem
def test_traction_zero_is_the_frictionless_result_bit_for_bit():
    """traction = 0 runs exactly today's path: every number and field is identical."""
    from ballrace import fem

    r0 = fem.ball_on_plane(12.7e-3, 2000.0, level="quick")
    r1 = fem.ball_on_plane(12.7e-3, 2000.0, level="quick", traction=0.0)
    assert r1.comparison == r0.comparison
    for k in ("tau_xz", "von_mises", "max_shear", "lam"):
        assert np.array_equal(r1.fields[k], r0.fields[k])
    assert "traction" not in r1.fields and r1.to_dict()["traction"] == 0.0


@pytest.fixture(scope="module")
def plane_traction():
    from ballrace import fem

    return fem.ball_on_plane(12.7e-3, 2000.0, level="quick", traction=0.3)


@needs_fem
@pytest.mark.fem
def test_quick_traction_ball_on_plane_against_analytic(plane_traction, tmp_path):
    """The loaded section (normal + tangential FE solutions superposed) against
    subsurface.stress(..., traction=0.3), within fem.TRACTION_TOLERANCES['quick']
    (measured and derived in docs/fem.md "Surface traction")."""
    from ballrace import fem
    from ballrace.analytic import subsurface as sub

    r = plane_traction
    rows = {row["quantity"]: row for row in r.comparison}
    bad = [f"{q}: {rows[q]['error']:+.4f} (tol {rows[q]['tol']})" for q in TRACTION_ROWS
           if not rows[q]["ok"]]
    assert not bad, "; ".join(bad)
    quick = fem.TRACTION_TOLERANCES["quick"]
    assert all(rows[q]["tol"] in (None, quick[q], quick.get(q + "_surface"))
               for q in TRACTION_ROWS)
    for q in ("traction_von_mises", "traction_tresca", "traction_sxx_trailing",
              "traction_section_rms", "traction_resultant"):
        assert rows[q]["tol"] is not None, q
    # the references are the analytic maxima with traction (an independent module):
    # at mu = 0.3 the circle's von Mises maximum is still below the surface, ahead of the
    # axis, and its Tresca maximum on the surface behind it (critical traction of the
    # circle ~0.24 for Tresca, ~0.31 for von Mises, docs/traction.md)
    c = r.analytic
    vm = sub.von_mises(c, nu=0.3, traction=0.3)
    assert rows["traction_von_mises"]["analytic"] == float(vm.sigma_vm)
    assert rows["traction_von_mises_x"]["analytic"] > 0.0
    assert rows["traction_tresca_x"]["analytic"] < 0.0
    assert rows["traction_tresca_depth"]["analytic"] == r.info["traction"]["surface_row_depth"]
    assert rows["traction_tresca"]["tol"] == fem.TRACTION_TOLERANCES["quick"][
        "traction_tresca_surface"]
    # equilibrium: the applied tangential load is mu times the normal load of the same
    # pressure on the same facets (one quadrature: to round-off), and mu Q to the
    # quadrature error of the tents on the facets
    t = r.info["traction"]
    assert t["resultant"] == pytest.approx(0.3 * t["normal_resultant"], rel=1e-12)
    assert t["resultant"] == pytest.approx(0.3 * 2000.0, rel=1e-3)
    # the picture: FE left, analytic right, on the full section -x_max..x_max
    from ballrace.fem.render import render, section_comparison

    x, z, fe_f, an_f = section_comparison(r, "von_mises")
    assert fe_f.shape == an_f.shape == (x.size, z.size) and x[0] == -x[-1]
    assert z[0] < 0.01 * float(c.b)                   # a row just below the surface
    assert render(r, "von_mises", str(tmp_path / "vm.png")).endswith("vm.png")


@needs_fem
@pytest.mark.fem
def test_quick_traction_inner_race_against_analytic(brg209):
    """The 209 inner race (a/b = 9.3), traction 0.1, FE pressure, quick level."""
    from ballrace import fem

    r = fem.ball_on_race(brg209, 2000.0, race="inner", level="quick", traction=0.1)
    rows = {row["quantity"]: row for row in r.comparison}
    bad = [f"{q}: {rows[q]['error']:+.4f} (tol {rows[q]['tol']})" for q in TRACTION_ROWS
           if not rows[q]["ok"]]
    assert not bad, "; ".join(bad)
    t = r.info["traction"]
    assert t["resultant"] == pytest.approx(0.1 * t["normal_resultant"], rel=1e-12)
    assert r.to_dict()["traction"] == 0.1
