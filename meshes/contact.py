"""Parametric, deterministic, cached gmsh meshes of the two bodies of a quarter contact model.

Two bodies, each a quarter (x >= 0, y >= 0) of the real body near the contact, in the
local contact frame of :mod:`ballrace.meshes.geometry`:

* :func:`block_mesh` — the lower body: a box ``[0, Lx] x [0, Ly] x [-H, 0]`` whose top
  face is the contact surface (later bent onto the race surface by
  :func:`morph_block`); also the elastic half-space of the "half-space" mode;
* :func:`ball_mesh` — the upper body: one eighth of a ball (the lower hemisphere's
  x, y >= 0 quarter), centre at ``(0, 0, R)``, touching the origin; its equator plane
  ``z = R`` is a symmetry plane of a ball squeezed between two races.

Local refinement: a size field ``h = min(h_far, h_c + g d)`` with ``d`` the distance
to a refinement region over the quarter contact ellipse: down to the depth of the
subsurface stress peak near y = 0, and a thin surface layer along the rest of a long
ellipse.  Anisotropy: when the ellipse is long (a/b >> 1) each body is
meshed in coordinates compressed along y by ``stretch`` and the nodes are then
stretched back, which gives elements elongated along the ellipse's major axis (the
stress gradients along y scale with a, across with b).  For the ball, the compressed
body is an ellipsoid.

Determinism (docs/fem.md): one thread, Delaunay 3-D (``Mesh.Algorithm3D = 1``), the OCC
sphere rotated so its poles and seam lie away from the contact; a test hashes the
node coordinates of two independent runs.

Meshes are cached as VTU files (meshio) under ``$BALLRACE_CACHE/meshes`` (default
``~/.cache/ballrace/meshes``), keyed by a SHA-256 of the parameters, the mesher
version and gmsh's version.  gmsh and meshio are imported inside the functions.
"""
from __future__ import annotations

import hashlib
import json
import logging
import math
import os
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

__all__ = ["MeshSpec", "TetMesh", "block_mesh", "ball_mesh", "morph_block", "cache_dir",
           "build_cached", "extract_tets", "mesh_hash", "MESHER_VERSION"]

log = logging.getLogger(__name__)

#: Bump when the generated meshes change for the same parameters (invalidates the cache).
MESHER_VERSION = "ballrace-mesh-4"


@dataclass(frozen=True)
class MeshSpec:
    """Parameters of one body's mesh (all lengths [m], physical coordinates).

    Attributes
    ----------
    kind : "block" or "ball".
    size : (Lx, Ly, H) for a block; (R, R, R) for a ball (radius R).
    fine : (fx, fy, fz) extent of the refinement box from the contact point
        (fz: depth into the body); or (fx, fy, fz, fy_deep, fz_shallow): the full depth
        fz only for y <= fy_deep, a layer fz_shallow deep elsewhere.
    h_contact : element size in the refinement box (across the ellipse, x and z) [m].
    h_far : largest element size [m].
    growth : size growth per unit distance from the refinement box [-].
    stretch : element elongation along y (>= 1) [-].
    probe : () or (x_lo, px, py, pz, hp, gp): a finer box ``[x_lo, px] x [0, py] x depth pz``
        of element size hp inside the refinement box, where the subsurface stresses are
        sampled, graded to the surrounding size with growth gp [m, m, m, m, m, -].
    """

    kind: str
    size: tuple
    fine: tuple
    h_contact: float
    h_far: float
    growth: float = 0.3
    stretch: float = 1.0
    probe: tuple = ()

    def key(self) -> str:
        """Cache key: SHA-256 over the parameters, the mesher and gmsh versions."""
        d = asdict(self)
        if not d["probe"]:
            del d["probe"]          # keys of meshes without a probe box are unchanged
        d = {k: ([float(f"{x:.12g}") for x in v] if isinstance(v, tuple) else
                 (float(f"{v:.12g}") if isinstance(v, float) else v)) for k, v in d.items()}
        return hashlib.sha256(json.dumps([MESHER_VERSION, _gmsh_version(), d],
                                         sort_keys=True).encode()).hexdigest()[:24]


@dataclass(frozen=True)
class TetMesh:
    """Linear tetrahedral mesh (frozen): ``points`` (n, 3) [m], ``tets`` (m, 4) int."""

    points: np.ndarray
    tets: np.ndarray
    spec: MeshSpec | None = None
    seconds: float = 0.0          # generation time (0 when loaded from the cache)

    @property
    def n_nodes(self) -> int:
        """Number of vertices."""
        return int(self.points.shape[0])

    def digest(self) -> str:
        """SHA-256 of node coordinates (rounded to 1e-12 of the body size) and connectivity."""
        scale = float(np.max(np.abs(self.points))) or 1.0
        q = np.round(self.points / scale * 1e12).astype(np.int64)
        h = hashlib.sha256(q.tobytes())
        h.update(np.ascontiguousarray(self.tets, dtype=np.int64).tobytes())
        return h.hexdigest()


def cache_dir() -> Path:
    """Mesh cache folder: ``$BALLRACE_CACHE/meshes`` or ``~/.cache/ballrace/meshes``."""
    root = os.environ.get("BALLRACE_CACHE")
    base = Path(root) if root else Path.home() / ".cache" / "ballrace"
    return base / "meshes"


def mesh_hash(mesh: TetMesh) -> str:
    """Hash of a mesh's node coordinates and connectivity (see :meth:`TetMesh.digest`)."""
    return mesh.digest()


def _gmsh_version() -> str:
    try:
        from importlib.metadata import version
        return version("gmsh")
    except Exception:  # pragma: no cover - gmsh not installed
        return "unknown"


# --------------------------------------------------------------------------- gmsh helpers
def _size_field(gmsh, fine, s: float, zsign: float, z0: float,
                hc: float, hf: float, g: float, probe: tuple = ()) -> None:
    """Background size field ``min(hf, hc + g * dist(refinement region))`` in the
    computational coordinates (y compressed by ``s``).

    ``fine = (fx, fy, fz)``: the region is the box ``[0, fx] x [0, fy] x depth fz``;
    ``fine = (fx, fy, fz, fy_deep, fz_shallow)``: the union of the deep box
    ``[0, fx] x [0, fy_deep] x depth fz`` (the stress sections near y = 0) and the
    shallow layer ``[0, fx] x [0, fy] x depth fz_shallow`` (the rest of the contact
    surface) [m, physical].  ``probe = (x_lo, px, py, pz, hp, gp)`` adds
    ``min(.., hp + gp * dist(probe box))``."""
    def pos(e):  # positive part, written with Abs for gmsh's MathEval
        return f"(({e})+Abs({e}))/2"

    def dist(bx, by, bz, x_lo=None):   # to the box [x_lo or 0, bx] x [0, by] x depth bz
        dz = f"{zsign}*(z-({z0!r}))-{bz!r}"
        dx = pos(f'x-{bx!r}') if x_lo is None else f"{pos(f'{x_lo!r}-x')}+{pos(f'x-{bx!r}')}"
        return f"Sqrt(({dx})^2+({pos(f'y-{by / s!r}')})^2+({pos(dz)})^2)"
    fx, fy, fz = fine[:3]
    d = dist(fx, fy, fz)
    if len(fine) == 5:
        fy_deep, fz_shallow = min(fine[3], fy), min(fine[4], fz)
        if fy_deep < fy and fz_shallow < fz:
            d = f"Min({dist(fx, fy_deep, fz)},{dist(fx, fy, fz_shallow)})"
    expr = f"Min({hf!r}, {hc!r}+{g!r}*{d})"
    if probe:
        x_lo, px, py, pz, hp, gp = probe
        expr = f"Min({expr}, {hp!r}+{gp!r}*{dist(px, py, pz, x_lo)})"
    f = gmsh.model.mesh.field.add("MathEval")
    gmsh.model.mesh.field.setString(f, "F", expr)
    gmsh.model.mesh.field.setAsBackgroundMesh(f)


#: gmsh options set before every mesh.  The first group chooses the algorithms; the second
#: states gmsh's own defaults (identical in 4.13.1 and 4.15.2, checked option by option)
#: so that a release which changes a default cannot change the meshes unnoticed.  The
#: meshes still differ between gmsh releases (4.13.1 and 4.15.x give other nodes for the
#: same options: the OCC kernel and the Delaunay code changed), which is why the cache
#: key and every FE result record gmsh's version (docs/fem.md "Versions").
GMSH_OPTIONS = {
    "General.Terminal": 0,
    "General.NumThreads": 1,
    "Mesh.Algorithm": 6,            # Frontal-Delaunay 2-D
    "Mesh.Algorithm3D": 1,          # Delaunay 3-D: reproducible (HXT with threads is not)
    "Mesh.MeshSizeExtendFromBoundary": 0,
    "Mesh.MeshSizeFromPoints": 0,
    "Mesh.MeshSizeFromCurvature": 0,
    "Mesh.Optimize": 1,
    "Mesh.ElementOrder": 1,
    "Mesh.RandomSeed": 1,
    # gmsh's defaults, stated
    "Mesh.MeshSizeFromParametricPoints": 0,
    "Mesh.MeshSizeMin": 0.0,
    "Mesh.MeshSizeMax": 1e22,
    "Mesh.MeshSizeFactor": 1.0,
    "Mesh.OptimizeNetgen": 0,
    "Mesh.OptimizeThreshold": 0.3,
    "Mesh.Smoothing": 1,
    "Mesh.QualityType": 2,
    "Mesh.RandomFactor": 1e-9,
    "Mesh.RandomFactor3D": 1e-12,
    "Mesh.ToleranceInitialDelaunay": 1e-12,
    "Mesh.AngleToleranceFacetOverlap": 0.1,
    "Mesh.MinimumCirclePoints": 7,
    "Mesh.MinimumCurvePoints": 3,
    "Mesh.AnisoMax": 1e33,
    "Mesh.LcIntegrationPrecision": 1e-9,
    "Geometry.Tolerance": 1e-8,
    "Geometry.OCCFixDegenerated": 0,
    "Geometry.OCCFixSmallEdges": 0,
    "Geometry.OCCFixSmallFaces": 0,
    "Geometry.OCCSewFaces": 0,
    "Geometry.OCCParallel": 0,
    "Geometry.OCCScaling": 1.0,
    "Geometry.OCCBooleanPreserveNumbering": 1,
}


def deterministic_options(gmsh) -> None:
    for name, value in GMSH_OPTIONS.items():
        gmsh.option.setNumber(name, value)


def extract_tets(gmsh) -> tuple[np.ndarray, np.ndarray]:
    """The current gmsh model's tetrahedra: points (n, 3) [m] and connectivity (m, 4),
    renumbered compactly over the nodes the tetrahedra use."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    pts = coords.reshape(-1, 3)
    etypes, _, enodes = gmsh.model.mesh.getElements(3)
    tets = None
    for et, en in zip(etypes, enodes):
        if et == 4:
            tets = en.reshape(-1, 4)
    if tets is None:
        raise RuntimeError("gmsh produced no tetrahedra")
    # compact renumbering: only nodes used by tetrahedra, in order of node tag
    order = np.argsort(tags)
    tags, pts = tags[order], pts[order]
    used = np.unique(tets)
    idx = np.searchsorted(tags, used)
    remap = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    return pts[idx].copy(), remap[tets].astype(np.int64)


def _generate(spec: MeshSpec) -> tuple[np.ndarray, np.ndarray]:
    import gmsh

    s = float(spec.stretch)
    gmsh.initialize(interruptible=False)
    try:
        deterministic_options(gmsh)
        gmsh.model.add(spec.kind)
        occ = gmsh.model.occ
        if spec.kind == "block":
            Lx, Ly, H = spec.size
            occ.addBox(0.0, 0.0, -H, Lx, Ly / s, H)
            occ.synchronize()
            _size_field(gmsh, spec.fine, s, -1.0, 0.0, spec.h_contact, spec.h_far, spec.growth,
                        spec.probe)
        elif spec.kind == "ball":
            R = spec.size[0]
            sph = occ.addSphere(0.0, 0.0, R, R)
            # move the poles and the seam away from the contact point (docs/fem.md): the seam
            # meridian ends up in z >= R (cut away) and the poles on or beyond the equator.
            occ.rotate([(3, sph)], 0.0, 0.0, R, 0.0, 0.0, 1.0, 1.25 * math.pi)
            occ.rotate([(3, sph)], 0.0, 0.0, R, 1.0, -1.0, 0.0, -0.5 * math.pi)
            if s != 1.0:
                occ.dilate([(3, sph)], 0.0, 0.0, R, 1.0, 1.0 / s, 1.0)
            box = occ.addBox(0.0, 0.0, 0.0, R, R, R)
            occ.intersect([(3, sph)], [(3, box)])
            occ.synchronize()
            _size_field(gmsh, spec.fine, s, 1.0, 0.0, spec.h_contact, spec.h_far, spec.growth,
                        spec.probe)
        else:
            raise ValueError(f"kind must be 'block' or 'ball'; got {spec.kind!r}")
        gmsh.model.mesh.generate(3)
        pts, tets = extract_tets(gmsh)
    finally:
        gmsh.finalize()
    pts[:, 1] *= s
    # snap symmetry planes exactly (OCC tolerances leave ~1e-17 noise)
    for j in (0, 1):
        pts[np.abs(pts[:, j]) < 1e-12 * max(spec.size), j] = 0.0
    return pts, tets


def _build(spec: MeshSpec, use_cache: bool) -> TetMesh:
    return build_cached(spec, use_cache, _generate)


def build_cached(spec, use_cache: bool, generate) -> TetMesh:
    """The mesh of ``spec`` from the cache folder, or made by ``generate(spec) -> (points,
    tets)`` and stored there (written to a temporary name, then moved, so parallel
    workers never read half a file).  ``spec`` needs ``kind`` and ``key()``."""
    path = cache_dir() / f"{spec.kind}-{spec.key()}.vtu"
    if use_cache and path.exists():
        import meshio

        m = meshio.read(path)
        log.info("mesh %s: loaded %s", spec.kind, path)
        return TetMesh(points=np.asarray(m.points, dtype=float),
                       tets=np.asarray(m.cells_dict["tetra"], dtype=np.int64), spec=spec)
    t0 = time.perf_counter()
    pts, tets = generate(spec)
    dt = time.perf_counter() - t0
    log.info("mesh %s: %d nodes, %d tets in %.2f s", spec.kind, len(pts), len(tets), dt)
    if use_cache:
        import meshio

        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.vtu")
        meshio.write(tmp, meshio.Mesh(pts, [("tetra", tets)]), binary=True)
        os.replace(tmp, path)
    return TetMesh(points=pts, tets=tets, spec=spec, seconds=dt)


def block_mesh(size, fine, h_contact: float, h_far: float | None = None, *,
               growth: float = 0.3, stretch: float = 1.0, probe=(),
               use_cache: bool = True) -> TetMesh:
    """Quarter block ``[0, Lx] x [0, Ly] x [-H, 0]`` refined at the origin.

    Parameters
    ----------
    size : (Lx, Ly, H)
        Block extent [m].
    fine : (fx, fy, fz) or (fx, fy, fz, fy_deep, fz_shallow)
        Refinement box ``[0, fx] x [0, fy] x [-fz, 0]`` [m]; with five values the
        depth fz is refined only for ``y <= fy_deep`` and a layer ``fz_shallow`` deep
        elsewhere (a long contact ellipse needs its full-depth resolution only near the
        stress sections at y = 0).
    h_contact : float
        Element size in the refinement box (x and z; along y it is ``stretch`` times
        larger) [m].
    h_far : float, optional
        Largest element size [m] (default: a quarter of the smallest extent).
    growth : float
        Size increase per unit distance from the refinement box [-].
    stretch : float
        Elongation of the elements along y [-], >= 1.
    use_cache : bool
        Read from / write to the mesh cache.

    Returns
    -------
    TetMesh
    """
    size = tuple(float(v) for v in size)
    spec = MeshSpec("block", size, tuple(float(v) for v in fine), float(h_contact),
                    float(h_far if h_far is not None else min(size) / 4), float(growth),
                    float(stretch), tuple(float(v) for v in probe))
    return _build(spec, use_cache)


def ball_mesh(radius: float, fine, h_contact: float, h_far: float | None = None, *,
              growth: float = 0.3, stretch: float = 1.0, probe=(),
              use_cache: bool = True) -> TetMesh:
    """One eighth of a ball (x, y >= 0, z <= R), centre (0, 0, R), touching the origin.

    Parameters are as in :func:`block_mesh`; ``fine = (fx, fy, fz)`` is the box
    ``[0, fx] x [0, fy] x [0, fz]`` above the contact point [m].
    """
    R = float(radius)
    spec = MeshSpec("ball", (R, R, R), tuple(float(v) for v in fine), float(h_contact),
                    float(h_far if h_far is not None else R / 4), float(growth), float(stretch),
                    tuple(float(v) for v in probe))
    return _build(spec, use_cache)


def morph_block(mesh: TetMesh, surface, depth: float) -> TetMesh:
    """Bend the block's top face z = 0 onto ``surface`` (height h(x, y) [m]).

    Each node moves vertically by ``h(x, y) (1 + z/H)``: the top follows the surface,
    the bottom ``z = -H`` stays flat; symmetry planes stay planes.

    Parameters
    ----------
    mesh : TetMesh
        Output of :func:`block_mesh`.
    surface : object with ``height(x, y)``
        For instance :class:`ballrace.meshes.geometry.RaceTorus` [m].
    depth : float
        Block depth H [m].
    """
    p = mesh.points.copy()
    h = surface.height(p[:, 0], p[:, 1])
    if not np.all(np.isfinite(h)):
        raise ValueError("surface height is not finite over the block: reduce the block size")
    p[:, 2] += h * (1.0 + p[:, 2] / depth)
    return TetMesh(points=p, tets=mesh.tets, spec=mesh.spec, seconds=mesh.seconds)
