r"""Quarter-model meshes of a profiled roller on its raceway (gmsh imported lazily).

Frame (that of :mod:`ballrace.analytic.roller.contact`, not the ball model's): ``x``
along the roller axis from the roller's mid-length, ``y`` the rolling direction, ``z``
the contact normal pointing into the roller; the raceway occupies ``z < 0``.  The quarter
``x >= 0, y >= 0`` is modelled: the mid-length plane ``x = 0`` (a symmetric profile
without tilt) and the plane ``y = 0`` through the contact normal and the roller axis are
symmetry planes.

* :func:`roller_mesh` — the roller: the quarter ``x in [0, L/2]``, ``y >= 0``,
  ``z <= R1`` of a cylinder of radius ``R1`` about the axis ``z = R1``, its surface
  lowered by the profile's drop (radius ``R1 - P(x)``); the end face ``x = L/2`` is a
  real, sharp edge; the plane through the axis ``z = R1`` is the roller's support plane
  (a roller between two raceways).
* :func:`raceway_mesh` — the raceway: a block ``[0, X] x [0, Y] x [-H, 0]`` longer than
  the roller (``X > L/2``), its top bent onto a cylinder of radius ``R2`` in the rolling
  direction (``inf`` flat, negative concave) by :func:`bend_raceway`.
* the half model (a tilted roller or a profile that is not even in x: only ``y = 0`` is
  a symmetry plane): ``half=True`` joins each quarter mesh to its mirror image in the
  plane ``x = 0`` (:func:`mirror_x`) — the full length ``-L/2 <= x <= L/2`` with the
  refinement at both roller ends, a mesh symmetric about ``x = 0`` node for node.  The
  cache holds the quarter mesh (its key covers every parameter of it); the mirror is made
  from it on every call, and the roller's profile (any drop over ``-L/2 ... L/2``) is
  applied after mirroring.

Resolution.  The contact is a strip some half-widths ``b`` wide and ``L/(2b)`` (tens)
half-widths long; the pressure varies along the roller on the scale of ``L`` in the
middle and of ``b`` at the roller end, where the edge peak lives.  Each body is meshed in
a coordinate ``xi`` compressed along the roller (``dx/dxi = sigma(x)``: ``stretch`` in the
middle, 1 within ``edge_zone`` of the roller end, a smooth cosine step between) with an
isotropic size field, and the nodes are mapped back: elements ``sigma`` times longer along
the roller than across it in the middle, isotropic at the end.  The size field is
``min(h_far, h + g d)`` with ``d`` the distance (in ``xi``) to the union of a surface
layer over the whole contact strip (``layer`` deep), a full-depth column at the centre
(``x <= column``) and a full-depth box at the roller end (``|x - L/2| <= edge_zone``),
where the element size is ``h_edge``.  Deterministic (one thread, Delaunay 3-D,
:data:`ballrace.meshes.contact.GMSH_OPTIONS`), cached as VTU files by a hash of the
parameters (:func:`ballrace.meshes.contact.cache_dir`).
"""
from __future__ import annotations

import hashlib
import json
import logging
import math
from dataclasses import asdict, dataclass

import numpy as np

from .contact import TetMesh, build_cached, deterministic_options, extract_tets

__all__ = ["RollerMeshSpec", "roller_mesh", "raceway_mesh", "bend_raceway", "RacewaySurface",
           "RollerSurface", "AxialStretch", "MESHER_VERSION", "mirror_x"]

log = logging.getLogger(__name__)

#: Bump when the generated meshes change for the same parameters (invalidates the cache).
MESHER_VERSION = "ballrace-roller-mesh-2"


@dataclass(frozen=True)
class AxialStretch:
    """The map between the physical axial coordinate x and the meshing coordinate xi.

    ``dx/dxi = sigma(x)``: ``stretch`` for ``x <= x_end - edge_zone - ramp``, 1 for
    ``|x - x_end| <= edge_zone`` and beyond, a cosine step over ``ramp`` between [m, -].

    Examples
    --------
    >>> m = AxialStretch(stretch=4.0, x_end=10.0, edge_zone=1.0, ramp=2.0)
    >>> round(float(m.xi(7.0)), 6), round(float(m.x(m.xi(8.5))), 9)
    (1.75, 8.5)
    """

    stretch: float
    x_end: float
    edge_zone: float
    ramp: float

    def sigma(self, x):
        """Element elongation along x at x [-]."""
        x = np.asarray(x, dtype=float)
        x1 = self.x_end - self.edge_zone
        x0 = x1 - self.ramp
        t = np.clip((x - x0) / max(self.ramp, 1e-300), 0.0, 1.0)
        step = 0.5 * (1.0 - np.cos(math.pi * t))
        return self.stretch + (1.0 - self.stretch) * step

    def _ramp(self):
        """(x0, x1) of the step and a fine table of xi over it (the same for both maps,
        so that ``x(xi(x)) == x`` to rounding)."""
        x1 = self.x_end - self.edge_zone
        x0 = x1 - self.ramp
        xs = np.linspace(x0, x1, 20001)
        inv = 1.0 / self.sigma(xs)
        xi = np.concatenate([[0.0], np.cumsum(0.5 * (inv[1:] + inv[:-1]) * np.diff(xs))])
        return x0, x1, xs, x0 / self.stretch + xi

    def xi(self, x):
        """Meshing coordinate of physical x >= 0 [m]."""
        x = np.asarray(x, dtype=float)
        x0, x1, xs, tab = self._ramp()
        return np.where(x <= x0, x / self.stretch,
                        np.where(x >= x1, tab[-1] + (x - x1), np.interp(x, xs, tab)))

    def x(self, xi, x_max=None):
        """Physical x of meshing coordinate xi >= 0 [m] (``x_max`` is not used)."""
        xi = np.asarray(xi, dtype=float)
        x0, x1, xs, tab = self._ramp()
        return np.where(xi <= tab[0], xi * self.stretch,
                        np.where(xi >= tab[-1], x1 + (xi - tab[-1]), np.interp(xi, tab, xs)))


@dataclass(frozen=True)
class RollerMeshSpec:
    """Parameters of one body's mesh (all lengths [m], physical coordinates).

    Attributes
    ----------
    kind : "roller" or "raceway".
    size : (L/2, R1, R1) for the roller; (X, Y, H) for the raceway block.
    half_length : L/2, the roller end [m].
    strip : half-width of the refined strip across the rolling direction [m].
    layer, depth : depth of the surface layer and of the full-depth column and edge box [m].
    column : the centre column spans ``0 <= x <= column`` [m].
    edge_zone : the edge box spans ``|x - L/2| <= edge_zone`` [m].
    h, h_edge, h_far : element sizes in the strip, the edge box and far away [m].
    growth : size growth per unit distance [-].
    stretch, ramp : axial elongation in the middle [-] and the length of its step [m].
    drop : () or the profile drop (x, drop) sampled for the roller surface [m].
    """

    kind: str
    size: tuple
    half_length: float
    strip: float
    layer: float
    depth: float
    column: float
    edge_zone: float
    h: float
    h_edge: float
    h_far: float
    growth: float = 0.3
    stretch: float = 1.0
    ramp: float = 0.0
    drop: tuple = ()

    @property
    def axial(self) -> AxialStretch:
        """The axial map of this mesh."""
        return AxialStretch(self.stretch, self.half_length, self.edge_zone,
                            self.ramp if self.ramp > 0 else 4.0 * self.edge_zone)

    def key(self) -> str:
        """Cache key: SHA-256 over the parameters, the mesher and gmsh versions."""
        d = asdict(self)
        d = {k: ([float(f"{x:.12g}") for x in np.ravel(v)] if isinstance(v, tuple) else
                 (float(f"{v:.12g}") if isinstance(v, float) else v)) for k, v in d.items()}
        return hashlib.sha256(json.dumps([MESHER_VERSION, _gmsh_version(), d],
                                         sort_keys=True).encode()).hexdigest()[:24]


def _gmsh_version() -> str:
    try:
        from importlib.metadata import version
        return version("gmsh")
    except Exception:  # pragma: no cover - gmsh not installed
        return "unknown"


# --------------------------------------------------------------------------- surfaces
@dataclass(frozen=True)
class RacewaySurface:
    """Raceway surface ``z = h(x, y)``: a cylinder of radius R2 about an axis parallel
    to x (``inf`` flat, > 0 convex, < 0 concave) [m]."""

    R2: float

    def height(self, x, y):
        """Height [m] (<= 0 for a convex raceway)."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        if not np.isfinite(self.R2):
            return np.zeros(np.broadcast(x, y).shape)
        r = abs(self.R2)
        s = y * y / (r + np.sqrt(np.clip(r * r - y * y, 0.0, None)))   # r - sqrt(r^2 - y^2)
        return -math.copysign(1.0, self.R2) * s + 0.0 * x


@dataclass(frozen=True)
class RollerSurface:
    """Roller surface ``z = h(x, y)``: radius ``R1 - P(x)`` about the axis z = R1 [m].

    The drop table ``(drop_x, drop_v)`` covers ``x >= 0`` (an even profile, mirrored) or,
    when its first x is negative, the signed x of a half model."""

    R1: float
    drop_x: tuple = ()
    drop_v: tuple = ()

    def drop(self, x):
        """Profile drop used by the mesh at x [m] (interpolated, capped)."""
        x = np.asarray(x, dtype=float)
        if not self.drop_x:
            return np.zeros(x.shape)
        if self.drop_x[0] >= 0.0:
            x = np.abs(x)
        return np.interp(x, self.drop_x, self.drop_v)

    def height(self, x, y):
        """Height [m] (>= 0)."""
        y = np.asarray(y, dtype=float)
        r = self.R1 - self.drop(x)
        return self.R1 - np.sqrt(np.clip(r * r - y * y, 0.0, None))


# --------------------------------------------------------------------------- gmsh
def _size_field(gmsh, spec: RollerMeshSpec, zsign: float, z0: float) -> None:
    """``min(h_far, h + g d_strip, h_edge + g d_edge)`` in meshing coordinates."""
    ax = spec.axial

    def pos(e):
        return f"(({e})+Abs({e}))/2"

    def dist(x_lo, x_hi, y_hi, depth):
        dz = f"{zsign}*(z-({z0!r}))-{depth!r}"
        dx = f"{pos(f'{x_lo!r}-x')}+{pos(f'x-{x_hi!r}')}"
        return f"Sqrt(({dx})^2+({pos(f'y-{y_hi!r}')})^2+({pos(dz)})^2)"

    xi_end = float(ax.xi(spec.half_length))
    xi_col = float(ax.xi(spec.column))
    xi_e0 = float(ax.xi(max(0.0, spec.half_length - spec.edge_zone)))
    xi_e1 = float(ax.xi(spec.half_length + spec.edge_zone))
    g = spec.growth
    d_layer = dist(0.0, xi_end, spec.strip, spec.layer)
    d_col = dist(0.0, xi_col, spec.strip, spec.depth)
    d_edge = dist(xi_e0, xi_e1, spec.strip, spec.depth)
    expr = (f"Min({spec.h_far!r}, Min({spec.h!r}+{g!r}*Min({d_layer},{d_col}), "
            f"{spec.h_edge!r}+{g!r}*{d_edge}))")
    f = gmsh.model.mesh.field.add("MathEval")
    gmsh.model.mesh.field.setString(f, "F", expr)
    gmsh.model.mesh.field.setAsBackgroundMesh(f)


def _generate(spec: RollerMeshSpec):
    import gmsh

    ax = spec.axial
    gmsh.initialize(interruptible=False)
    try:
        deterministic_options(gmsh)
        gmsh.model.add(spec.kind)
        occ = gmsh.model.occ
        if spec.kind == "raceway":
            X, Y, H = spec.size
            occ.addBox(0.0, 0.0, -H, float(ax.xi(X)), Y, H)
            occ.synchronize()
            _size_field(gmsh, spec, -1.0, 0.0)
        elif spec.kind == "roller":
            Lh, R1, _ = spec.size
            xi_end = float(ax.xi(Lh))
            cyl = occ.addCylinder(0.0, 0.0, R1, xi_end, 0.0, 0.0, R1)
            box = occ.addBox(0.0, 0.0, 0.0, xi_end, R1, R1)
            occ.intersect([(3, cyl)], [(3, box)])
            occ.synchronize()
            _size_field(gmsh, spec, 1.0, 0.0)
        else:
            raise ValueError(f"kind must be 'roller' or 'raceway'; got {spec.kind!r}")
        gmsh.model.mesh.generate(3)
        pts, tets = extract_tets(gmsh)
    finally:
        gmsh.finalize()
    scale = max(spec.size)
    for j in (0, 1):
        pts[np.abs(pts[:, j]) < 1e-12 * scale, j] = 0.0
    pts[:, 0] = ax.x(pts[:, 0], x_max=max(spec.size[0], spec.half_length))
    if spec.kind == "roller":
        Lh, R1, _ = spec.size
        pts[np.abs(pts[:, 0] - Lh) < 1e-9 * scale, 0] = Lh
        pts[np.abs(pts[:, 2] - R1) < 1e-12 * scale, 2] = R1
    else:
        pts[np.abs(pts[:, 2]) < 1e-12 * scale, 2] = 0.0
    return pts, tets


def _build(spec: RollerMeshSpec, use_cache: bool) -> TetMesh:
    return build_cached(spec, use_cache, _generate)


def mirror_x(mesh: TetMesh) -> TetMesh:
    """The mesh joined to its mirror image in the plane ``x = 0`` (nodes with x exactly 0
    shared, the mirrored tetrahedra reoriented): a quarter mesh ``x >= 0`` becomes the
    half mesh ``-X <= x <= X``, symmetric node for node [m].

    Examples
    --------
    >>> m = TetMesh(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]),
    ...             np.array([[0, 1, 2, 3]]))
    >>> h = mirror_x(m)
    >>> h.n_nodes, h.tets.tolist()
    (5, [[0, 1, 2, 3], [0, 2, 4, 3]])
    """
    p = np.asarray(mesh.points, dtype=float)
    n = p.shape[0]
    new = np.flatnonzero(p[:, 0] != 0.0)
    idx = np.arange(n)
    idx[new] = n + np.arange(new.size)
    pm = p[new].copy()
    pm[:, 0] = -pm[:, 0]
    tm = idx[np.asarray(mesh.tets)][:, [0, 2, 1, 3]]      # a mirror flips the orientation
    return TetMesh(points=np.vstack([p, pm]), tets=np.vstack([mesh.tets, tm]),
                   spec=mesh.spec, seconds=mesh.seconds)


def _common(half_length, strip, layer, depth, column, edge_zone, h, h_edge, h_far, growth,
            stretch, ramp):
    return dict(half_length=float(half_length), strip=float(strip), layer=float(layer),
                depth=float(depth), column=float(column), edge_zone=float(edge_zone),
                h=float(h), h_edge=float(h_edge), h_far=float(h_far), growth=float(growth),
                stretch=float(stretch), ramp=float(ramp))


def roller_mesh(R1: float, half_length: float, *, strip: float, layer: float, depth: float,
                column: float, edge_zone: float, h: float, h_edge: float,
                h_far: float | None = None, growth: float = 0.3, stretch: float = 1.0,
                ramp: float = 0.0, drop=None, half: bool = False,
                use_cache: bool = True) -> TetMesh:
    """Quarter roller ``0 <= x <= L/2``, ``y >= 0``, ``z <= R1`` touching the origin
    (with ``half``: the half roller ``-L/2 <= x <= L/2``).

    Parameters
    ----------
    R1 : float
        Roller radius [m].
    half_length : float
        Half the roller length L/2 [m].
    strip, layer, depth, column, edge_zone : float
        Refinement regions (:class:`RollerMeshSpec`) [m].
    h, h_edge, h_far : float
        Element sizes [m].
    growth, stretch : float
        Size growth [-] and axial elongation in the middle [-].
    ramp : float
        Length of the elongation's step [m] (default 4 ``edge_zone``).
    drop : (x, drop) arrays, optional
        The profile drop [m] at x >= 0 [m] (finite; cap a logarithmic profile's end);
        the surface radius becomes ``R1 - drop(x)``.  With ``half``, x may run over
        ``-L/2 ... L/2`` (a profile that is not even in x).
    half : bool
        The half model: the quarter mesh joined to its mirror image (:func:`mirror_x`),
        the profile applied after mirroring.
    use_cache : bool
        Read from / write to the mesh cache.

    Returns
    -------
    TetMesh
        Nodes on the roller's curved surface lie on the profiled surface.
    """
    R1 = float(R1)
    dr = () if drop is None else (tuple(float(v) for v in np.asarray(drop[0]).ravel()),
                                  tuple(float(v) for v in np.asarray(drop[1]).ravel()))
    # the quarter mesh (cached) does not depend on the drop, which is applied below; a
    # signed drop table of a half model keys it by its x >= 0 part as before
    keep = [i for i, v in enumerate(dr[0]) if v >= 0.0] if dr else []
    dq = (tuple(dr[0][i] for i in keep), tuple(dr[1][i] for i in keep)) if dr else ()
    spec = RollerMeshSpec("roller", (float(half_length), R1, R1), drop=dq,
                          **_common(half_length, strip, layer, depth, column, edge_zone, h,
                                    h_edge, h_far if h_far is not None else R1 / 3, growth,
                                    stretch, ramp))
    m = _build(spec, use_cache)
    if half:
        m = mirror_x(m)
    p = m.points.copy()
    r = np.hypot(p[:, 1], R1 - p[:, 2])
    on = (np.abs(r - R1) < 1e-5 * R1) & (p[:, 2] < R1 * (1 - 1e-9))
    surf = RollerSurface(R1, *dr) if dr else RollerSurface(R1)
    target = R1 - surf.drop(p[:, 0])
    # each section x scales radially about the axis by (R1 - P(x)) / R1; the surface
    # nodes land exactly on the profiled surface
    fac = np.where(on, target / np.where(r > 0, r, 1.0), target / R1)
    p[:, 1] *= fac
    p[:, 2] = R1 - (R1 - p[:, 2]) * fac
    return TetMesh(points=p, tets=m.tets, spec=m.spec, seconds=m.seconds)


def raceway_mesh(size, half_length: float, *, strip: float, layer: float, depth: float,
                 column: float, edge_zone: float, h: float, h_edge: float,
                 h_far: float | None = None, growth: float = 0.3, stretch: float = 1.0,
                 ramp: float = 0.0, half: bool = False, use_cache: bool = True) -> TetMesh:
    """Quarter raceway block ``[0, X] x [0, Y] x [-H, 0]``, X beyond the roller end
    (with ``half``: ``[-X, X] x [0, Y] x [-H, 0]``, :func:`mirror_x`).

    Parameters are as in :func:`roller_mesh`; ``size = (X, Y, H)`` [m].
    """
    size = tuple(float(v) for v in size)
    if not size[0] > half_length:
        raise ValueError(f"the raceway must be longer than the roller: X = {size[0]:g} m "
                         f"<= L/2 = {half_length:g} m")
    spec = RollerMeshSpec("raceway", size,
                          **_common(half_length, strip, layer, depth, column, edge_zone, h,
                                    h_edge, h_far if h_far is not None else min(size) / 4,
                                    growth, stretch, ramp))
    m = _build(spec, use_cache)
    return mirror_x(m) if half else m


def bend_raceway(mesh: TetMesh, surface: RacewaySurface, depth: float) -> TetMesh:
    """Bend the block's top z = 0 onto the raceway surface; its bottom z = -H stays flat
    (each node moves by ``h(x, y) (1 + z/H)``) [m]."""
    p = mesh.points.copy()
    h = surface.height(p[:, 0], p[:, 1])
    if not np.all(np.isfinite(h)):
        raise ValueError("raceway surface height is not finite over the block")
    p[:, 2] += h * (1.0 + p[:, 2] / depth)
    return TetMesh(points=p, tets=mesh.tets, spec=mesh.spec, seconds=mesh.seconds)
