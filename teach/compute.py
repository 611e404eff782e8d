"""The numbers of the subsurface-stress explorer (``ballrace teach serve`` and ``export``).

The user picks a contact (two bodies, or a ball in the inner or outer groove of a bearing,
typed in or read from a bearing case file), a load, Poisson's ratio and a traction
coefficient; :func:`compute` returns what the page shows: the sections y = 0 and x = 0 of
the stress fields, the depth profiles on the axis, a von Mises volume (all in units of p0
and of the minor semi-axis b) and the table of a, b, p0, delta, tau0, z0, tau_max and its
depth (SI).  No HTML here: :mod:`ballrace.teach.page` draws the page,
:mod:`ballrace.teach.server` serves it.  :func:`compute` takes the page's inputs as typed
(text with units, parsed with pint as at the command line) and solves the contact; the
sampling and the maxima work on that contact in SI.

Everything numeric comes from :mod:`ballrace.analytic`: :func:`~ballrace.analytic.hertz.
point_contact` / :func:`~ballrace.analytic.hertz.elliptical_contact`,
:func:`~ballrace.analytic.subsurface.stress`, :func:`~ballrace.analytic.subsurface.
max_shear`, :func:`~ballrace.analytic.subsurface.von_mises` and
:func:`~ballrace.analytic.subsurface.orthogonal_shear`.  This module only samples them on
coarse grids and packs the samples for the page.

The roller mode (``mode = "roller"``, :func:`compute_roller`) is the finite line contact
of a profiled roller on a raceway, :func:`~ballrace.analytic.roller.line_contact`, and the
von Mises and Tresca stresses below it, :func:`~ballrace.analytic.roller.subsurface_stress`:
the pressure of every slice, a von Mises map in the plane through the roller's axis and
the maxima at the centre and at the end of the contact (SI), cached on the SI inputs.  Its
inputs are bounded (:data:`TILT_MAX`, :data:`ROLLER_LOAD_MAX`,
:data:`SLICE_OVER_WIDTH_MAX`) so that a state answers in some tenths of a second.

The stress fields scale exactly with the contact: in units of p0 and of the minor
semi-axis b they depend only on the semi-axis ratio, nu and the traction coefficient.
The sampled fields are therefore cached on those three, and a change of load (or of the
size of the bodies at a fixed ratio) costs only the Hertz solution.
"""
from __future__ import annotations

import base64
import json
import logging
import math
import threading
import time

import numpy as np

__all__ = ["FIELDS", "DEFAULTS", "EXPORT_GRID", "TRACTION_MAX", "InputError", "one_line",
           "compute", "compute_safe", "case_inputs", "unpack", "export_grid",
           "export_params", "ROLLER_PROFILES", "ROLLER_SLICES", "ROLLER_DEPTHS", "TILT_MAX",
           "ROLLER_LOAD_MAX", "SLICE_OVER_WIDTH_MAX", "roller_inputs", "compute_roller"]

log = logging.getLogger(__name__)

#: Fields drawn in the sections: key -> label.
FIELDS = {"tau_xz": "orthogonal shear tau_xz", "tresca": "Tresca (sigma_1 - sigma_3)/2",
          "von_mises": "von Mises", "sigma_x": "sigma_x", "sigma_z": "sigma_z"}

#: The page's initial inputs (strings, as typed): a 12.7 mm ball in the inner groove of a
#: 209-size bearing (Hamrock & Dowson 1981 Table 3.2 geometry), or two bodies.
DEFAULTS = {
    "mode": "bodies", "load": "2000 N", "nu": "0.3", "traction": "0",
    "rx1": "6.35 mm", "ry1": "6.35 mm", "rx2": "inf", "ry2": "inf", "E": "200 GPa",
    "race": "inner", "D": "12.7 mm", "dm": "65 mm", "f": "0.52", "angle": "0 deg",
    "case": "",
    # roller mode (mode "roller"): a profiled roller on a raceway, the load above
    "profile": "iso", "flat": "8 mm", "crown": "0.5 m", "tilt": "0 mrad",
    "r_roller": "6 mm", "length": "12 mm", "r_race": "30 mm",
}

# Grids of one state (coordinates in units of the minor semi-axis b).
_NX, _NZ = 60, 40            # sections: 60 across, 40 in depth
_ZMAX = 2.0                  # sections and profiles: 0 <= z <= 2 b
_SEC_X = 2.0                 # section y = 0: |x| <= 2 a_x
_SEC_Y = 1.5                 # section x = 0: |y| <= 1.5 a_y
_NAX = 81                    # depth profile on the axis
_VOL = (18, 18, 13)          # von Mises volume: x, y, z points
_VOL_X, _VOL_Y, _VOL_Z = 1.3, 1.3, 1.6   # its extent: a_x, a_y, b units

#: The export's parameter grid: radius ratio Ry/Rx of body 1 on a flat (rx1 = 6.35 mm),
#: load [N], Poisson's ratio, traction coefficient.
EXPORT_GRID = {"ratio": (1.0, 2.0, 4.0, 8.0, 16.0, 32.0),
               "load": (250.0, 500.0, 1000.0, 2000.0, 4000.0, 8000.0),
               "nu": (0.25, 0.3, 0.35),
               "mu": (0.0, 0.1, 0.2, 0.3, 0.4)}
_EXPORT_RX = "6.35 mm"
_EXPORT_E = "200 GPa"

#: Largest |traction coefficient| the explorer takes [-].  The library accepts 10, but its
#: maxima searches beyond 1 can take a minute (a traction coefficient above 1 is beyond
#: dry steel-on-steel friction anyway).
TRACTION_MAX = 1.0


class InputError(ValueError):
    """A bad input: ``field`` names the control, the message is the library's one line."""

    def __init__(self, field: str, message: str):
        super().__init__(message)
        self.field = field


def one_line(exc: BaseException) -> str:
    """An exception's message as one line (its type's name when it has none)."""
    text = " ".join(str(exc).split())
    return text or type(exc).__name__


def _guard(field: str, fun, *args, **kwargs):
    """Call ``fun``; a ValueError/TypeError becomes an :class:`InputError` for ``field``."""
    try:
        return fun(*args, **kwargs)
    except (ValueError, TypeError, ArithmeticError) as exc:
        raise InputError(field, one_line(exc)) from None


def _number(text, field: str) -> float:
    """A plain number from a text field (dimensionless inputs such as nu, f, traction)."""
    from ballrace.units import parse_quantity

    return _guard(field, parse_quantity, str(text), "", field)


# ------------------------------------------------------------------ the contact
def _contact(params: dict):
    """Parse the inputs and solve the Hertz contact; returns (contact, nu, mu, changed).

    ``changed`` holds inputs the server rewrote (the ellipticity slider sets ry1).
    """
    from ballrace import Material
    from ballrace.analytic import hertz
    from ballrace.analytic._checks import check_positive, check_range
    from ballrace.units import parse_quantity

    p = {**DEFAULTS, **{k: v for k, v in params.items() if v is not None}}
    changed = {}
    Q = _guard("load", parse_quantity, str(p["load"]), "[force]", "load")
    _guard("load", check_positive, Q, "load", "N", bounded=True)
    nu = _number(p["nu"], "nu")
    _guard("nu", check_range, nu, "nu", -1.0, 0.5, unit="-")
    mu = _number(p["traction"], "traction")
    _guard("traction", check_range, mu, "traction", -TRACTION_MAX, TRACTION_MAX,
           low_inclusive=True, high_inclusive=True, unit="-")
    E = _guard("E", parse_quantity, str(p["E"]), "[pressure]", "E")
    import warnings

    with warnings.catch_warnings():          # E has its unit here; the warning is for the API
        warnings.simplefilter("ignore", UserWarning)
        mat = _guard("E", Material, E=E, nu=nu)
    mode = p["mode"]
    if mode == "bodies":
        names = ("rx1", "ry1", "rx2", "ry2")
        r = {n: _guard(n, parse_quantity, str(p[n]), "[length]", n, allow_inf=True)
             for n in names}
        for n in names:
            if r[n] == 0:
                raise InputError(n, f"{n} must be non-zero [m] (inf for a flat); got 0")
        ratio = p.get("set_ratio")
        if ratio not in (None, ""):
            alpha = _number(ratio, "ratio")
            _guard("ratio", check_positive, alpha, "ratio Ry/Rx", "-", bounded=True)
            rx_eff = _guard("rx1", hertz.curvature, r["rx1"], r["rx1"], r["rx2"], r["rx2"]).Rx
            inv = 1.0 / (alpha * float(rx_eff)) - 1.0 / r["ry2"]
            if not inv > 0:
                raise InputError("ratio", f"ratio Ry/Rx = {alpha:g} cannot be reached by body 1 "
                                 f"with ry2 = {p['ry2']} (body 2 is the more curved)")
            r["ry1"] = 1.0 / inv
            changed["ry1"] = f"{r['ry1'] * 1e3:.6g} mm"
        try:
            hertz.curvature(*(r[n] for n in names))
        except ValueError as exc:
            msg = one_line(exc)
            field = "ry2" if "y plane" in msg else "rx2" if "x plane" in msg else "rx1"
            raise InputError(field, msg) from None
        import warnings

        with warnings.catch_warnings():      # a / R beyond Hertz: a note on the page instead
            warnings.simplefilter("ignore", UserWarning)
            c = _guard("rx1", hertz.point_contact, Q, r["rx1"], r["ry1"], r["rx2"], r["ry2"],
                       mat)
        size = hertz.size_ratio(c.a, tuple(r[n] for n in names))
        if size > hertz.SIZE_LIMIT:
            changed["_note"] = (f"a / R = {size:.3g} > {hertz.SIZE_LIMIT:g}: beyond Hertz's "
                                "small-contact assumption; the numbers are extrapolations")
    elif mode == "bearing":
        from ballrace.analytic.bearing import BallBearing

        race = p["race"]
        if race not in ("inner", "outer"):
            raise InputError("race", f"race must be 'inner' or 'outer'; got {race!r}")
        D = _guard("D", parse_quantity, str(p["D"]), "[length]", "D")
        dm = _guard("dm", parse_quantity, str(p["dm"]), "[length]", "dm")
        f = _number(p["f"], "f")
        angle = _guard("angle", parse_quantity, str(p["angle"]), "[angle]", "contact angle")
        fields = {"ball_diameter": "D", "pitch_diameter": "dm", "f_inner": "f",
                  "f_outer": "f", "free_contact_angle": "angle", "n_balls": "dm"}
        try:
            import warnings

            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                brg = BallBearing(ball_diameter=D, n_balls=3, pitch_diameter=dm, f_inner=f,
                                  f_outer=f, free_contact_angle=angle, material=mat)
        except (ValueError, TypeError) as exc:
            msg = one_line(exc)
            field = next((v for k, v in fields.items() if msg.startswith(k)), "D")
            raise InputError(field, msg) from None
        cv = brg.curvature(race, angle)
        c = _guard("D", hertz.elliptical_contact, Q, float(cv.Rx), float(cv.Ry), brg.E_prime)
    else:
        raise InputError("mode", f"mode must be 'bodies', 'bearing' or 'roller'; got {mode!r}")
    return c, nu, mu, changed


# ------------------------------------------------------------------ packing
def _pack(arr) -> dict:
    """An array as 16-bit levels between its min and max, base64 (row-major, C order)."""
    a = np.asarray(arr, dtype=float)
    lo, hi = float(a.min()), float(a.max())
    span = hi - lo if hi > lo else 1.0
    q = np.rint((a - lo) / span * 65535.0).astype("<u2")
    return {"shape": list(a.shape), "lo": lo, "hi": hi,
            "data": base64.b64encode(q.tobytes()).decode("ascii")}


def unpack(d: dict) -> np.ndarray:
    """Inverse of the packing (for tests): the array to 1/65535 of its range."""
    q = np.frombuffer(base64.b64decode(d["data"]), dtype="<u2").astype(float)
    return (d["lo"] + q / 65535.0 * (d["hi"] - d["lo"])).reshape(d["shape"])


def _fields_of(s, p0: float) -> dict:
    """The five section fields of a StressState, in units of p0."""
    return {"tau_xz": s.sxz / p0, "tresca": s.tresca / p0, "von_mises": s.von_mises / p0,
            "sigma_x": s.sxx / p0, "sigma_z": s.szz / p0}


def _grid_max(f: np.ndarray, u: np.ndarray, z: np.ndarray) -> list:
    """[u, z, value] of the largest |value| on a section grid (rows z, columns u)."""
    j, i = np.unravel_index(int(np.argmax(np.abs(f))), f.shape)
    return [float(u[i]), float(z[j]), float(f[j, i])]


# ------------------------------------------------------------------ one state
_CACHE: dict = {}
_CACHE_MAX = 512
_CACHE_LOCK = threading.Lock()


def _key(c, nu, mu) -> tuple:
    return (round(float(c.semi_axis_x) / float(c.b), 12),
            round(float(c.semi_axis_y) / float(c.b), 12), float(nu), float(mu))


def _cached(kind: str, c, nu: float, mu: float, fun, compute: bool = True):
    """``fun(c, nu, mu)`` cached on (kind, a_x/b, a_y/b, nu, mu): in units of p0 and b the
    load and the size of the bodies only scale the result, so a contact of the same shape
    reuses the first one computed.  None when not cached and ``compute`` is False."""
    key = (kind, *_key(c, nu, mu))
    with _CACHE_LOCK:
        hit = _CACHE.get(key)
    if hit is None:
        if not compute:
            return None
        hit = json.dumps(fun(c, float(nu), float(mu)))
        with _CACHE_LOCK:
            if len(_CACHE) >= _CACHE_MAX:
                _CACHE.pop(next(iter(_CACHE)))
            _CACHE[key] = hit
    return json.loads(hit)


def _sample(c, nu: float, mu: float) -> dict:
    """The sampled fields and the library's maxima of one contact (uncached)."""
    from ballrace.analytic import subsurface

    k = float(c.k)
    b, p0 = float(c.b), float(c.p_max)
    sx, sy = float(c.semi_axis_x) / b, float(c.semi_axis_y) / b
    z = np.linspace(0.0, _ZMAX, _NZ)
    out = {"ax": sx, "ay": sy, "k": k}
    # section y = 0; without traction it is even in x (tau_xz odd): half is computed
    xs = np.linspace(-_SEC_X * sx, _SEC_X * sx, _NX)
    if mu == 0:
        half = xs[_NX // 2:]
        X, Z = np.meshgrid(half, z)
        f = _fields_of(subsurface.stress(c, X * b, 0.0, Z * b, nu=nu), p0)
        f = {n: np.hstack([(-v if n == "tau_xz" else v)[:, ::-1], v]) for n, v in f.items()}
    else:
        X, Z = np.meshgrid(xs, z)
        f = _fields_of(subsurface.stress(c, X * b, 0.0, Z * b, nu=nu, traction=mu), p0)
    out["sec_y0"] = {"u": [float(xs[0]), float(xs[-1]), _NX], "z": [0.0, _ZMAX, _NZ],
                     "fields": {n: _pack(v) for n, v in f.items()},
                     "gridmax": {n: _grid_max(v, xs, z) for n, v in f.items()}}
    taux = np.max(np.abs(f["tau_xz"]), axis=1)
    # section x = 0: even in y for these fields (the traction is along x)
    ys = np.linspace(-_SEC_Y * sy, _SEC_Y * sy, _NX)
    Y, Z = np.meshgrid(ys[_NX // 2:], z)
    g = _fields_of(subsurface.stress(c, 0.0, Y * b, Z * b, nu=nu, traction=mu), p0)
    g = {n: np.hstack([v[:, ::-1], v]) for n, v in g.items()}
    out["sec_x0"] = {"u": [float(ys[0]), float(ys[-1]), _NX], "z": [0.0, _ZMAX, _NZ],
                     "fields": {n: _pack(v) for n, v in g.items()},
                     "gridmax": {n: _grid_max(v, ys, z) for n, v in g.items()}}
    # depth profiles on the axis
    za = np.linspace(0.0, _ZMAX, _NAX)
    s = subsurface.stress(c, 0.0, 0.0, za * b, nu=nu, traction=mu)
    out["axis"] = {"z": [0.0, _ZMAX, _NAX],
                   "curves": {"sigma_x": _r(s.sxx / p0), "sigma_y": _r(s.syy / p0),
                              "sigma_z": _r(s.szz / p0), "tresca": _r(s.tresca / p0),
                              "von_mises": _r(s.von_mises / p0)},
                   "tau_xz_max": {"z": [0.0, _ZMAX, _NZ], "v": _r(taux)}}
    # von Mises volume (even in y: the half y >= 0 is computed)
    nx, ny, nz = _VOL
    vx = np.linspace(-_VOL_X * sx, _VOL_X * sx, nx)
    vy = np.linspace(-_VOL_Y * sy, _VOL_Y * sy, ny)
    vz = np.linspace(0.0, _VOL_Z, nz)
    X, Y, Z = np.meshgrid(vx, vy[ny // 2:], vz, indexing="ij")
    vm = subsurface.stress(c, X * b, Y * b, Z * b, nu=nu, traction=mu).von_mises / p0
    vm = np.concatenate([vm[:, ::-1, :], vm], axis=1)
    out["vol"] = {"x": [float(vx[0]), float(vx[-1]), nx], "y": [float(vy[0]), float(vy[-1]), ny],
                  "z": [0.0, _VOL_Z, nz], "vm": _pack(vm)}
    return out


def _maxima_of(c, nu: float, mu: float) -> dict:
    """The library's maxima (Tresca, von Mises, Lundberg–Palmgren) in units of p0 and b."""
    from ballrace.analytic import subsurface

    b, p0 = float(c.b), float(c.p_max)
    m = subsurface.max_shear(c, nu=nu, traction=mu)
    v = subsurface.von_mises(c, nu=nu, traction=mu)
    out = {"tresca_max": {"v": float(m.tau_max) / p0, "x": float(m.x) / b,
                          "y": float(m.y) / b, "z": float(m.depth) / b},
           "vm_max": {"v": float(v.sigma_vm) / p0, "x": float(v.x) / b, "y": float(v.y) / b,
                      "z": float(v.depth) / b}}
    if bool(c.major_axis_along_y) or float(c.k) <= 1.0 + 1e-9:
        o = subsurface.orthogonal_shear(c)
        out["lp"] = {"tau0": float(o.tau0) / p0, "z0": float(o.z0) / b, "x0": float(o.x0) / b,
                     "t": float(o.t)}
    else:
        out["lp"] = None
    return out


def _r(a) -> list:
    return [float(f"{v:.6g}") for v in np.asarray(a, dtype=float).ravel()]


def compute(params: dict, maxima: bool = True) -> dict:
    """One state of the explorer as a JSON-ready dict (raises :class:`InputError`).

    ``params`` holds the page's inputs as typed (strings with units; see
    :data:`DEFAULTS`).  The result has ``table`` (SI values of the contact and its
    stresses), ``dimless`` (the sampled fields in units of p0 and b, and the maxima) and
    ``inputs`` rewritten by the server (``ry1`` when ``set_ratio`` was given).

    With a traction the maxima of the Tresca and von Mises stresses are searches of
    0.2–1.5 s; with ``maxima=False`` they are left out unless cached (``pending`` is then
    True and the table's ``tau_max``, ``vm_max`` rows are None): the page asks for them in a
    second request so that the views do not wait.
    """
    if {**DEFAULTS, **{k: v for k, v in params.items() if v is not None}}["mode"] == "roller":
        return compute_roller(params)
    c, nu, mu, changed = _contact(params)
    b, p0 = float(c.b), float(c.p_max)
    sx, sy = float(c.semi_axis_x), float(c.semi_axis_y)
    if not (b > 0 and p0 > 0):
        raise InputError("load", f"load gives no contact (b = {b:g} m)")
    d = _cached("fields", c, nu, mu, _sample)
    mx = _cached("maxima", c, nu, mu, _maxima_of, compute=maxima or mu == 0)
    table = {"load": float(c.load), "Rx": float(c.Rx), "Ry": float(c.Ry), "k": float(c.k),
             "a": float(c.a), "b": b, "ax": sx, "ay": sy, "p0": p0,
             "delta": float(c.approach), "nu": float(nu), "mu": float(mu)}
    table.update(_scaled(mx, b, p0))
    note = changed.pop("_note", "")
    return {"ok": True, "table": table, "dimless": d, "maxima": mx, "pending": mx is None,
            "inputs": changed, "note": note}


def _scaled(mx: dict | None, b: float, p0: float) -> dict:
    """The table rows of the maxima in SI units (None where not computed)."""
    out = dict.fromkeys(("tau_max", "tau_max_depth", "tau_max_x", "vm_max", "vm_depth",
                         "vm_x", "tau0", "z0", "x0"))
    if mx is None:
        return out
    t, v = mx["tresca_max"], mx["vm_max"]
    out.update(tau_max=t["v"] * p0, tau_max_depth=t["z"] * b, tau_max_x=t["x"] * b,
               vm_max=v["v"] * p0, vm_depth=v["z"] * b, vm_x=v["x"] * b)
    if mx["lp"] is not None:
        out.update(tau0=mx["lp"]["tau0"] * p0, z0=mx["lp"]["z0"] * b, x0=mx["lp"]["x0"] * b)
    return out


def compute_safe(params: dict, maxima: bool = True) -> dict:
    """:func:`compute`, with any error turned into ``{"ok": False, "field", "error"}``."""
    try:
        return compute(params, maxima)
    except InputError as exc:
        return {"ok": False, "field": exc.field, "error": str(exc)}
    except Exception as exc:  # the server never dies: an unexpected error is one line too
        log.debug("explorer: unexpected error", exc_info=True)
        return {"ok": False, "field": "general", "error": one_line(exc)}


def case_inputs(path: str, race: str = "inner") -> dict:
    """The bearing inputs (strings) of a bearing case file, for the page's bearing mode.

    Uses the free contact angle, the conformity of ``race`` and the ball's material.
    """
    from ballrace.casefiles.bearing import load_case

    try:
        case = _guard("case", load_case, path)
    except InputError:
        raise
    brg = case.bearing
    f = brg.f_inner if race == "inner" else brg.f_outer
    mat = brg.ball_material
    return {"mode": "bearing", "D": f"{brg.ball_diameter * 1e3:.6g} mm",
            "dm": f"{brg.pitch_diameter * 1e3:.6g} mm", "f": f"{f:.6g}",
            "angle": f"{math.degrees(brg.free_contact_angle):.6g} deg",
            "E": f"{mat.E / 1e9:.6g} GPa", "nu": f"{mat.nu:.6g}", "race": race,
            "title": case.title}



def export_grid(grid: dict | None = None, progress=None) -> dict:
    """The export's data: every grid point computed by :func:`compute`.

    Returns ``{"grid", "geometry", "tables": {"i,j,l,m": table}, "dimless":
    {"i,l,m": {"fields", "maxima"}}}`` with i over ratios, j loads, l nu, m traction.
    ``progress(done, total, text)``, if given, is called as each shape (one ratio, nu and
    traction: the loads of a shape cost only the Hertz solution) starts and once at the
    end, ``done`` and ``total`` counting grid points; each shape is also logged (INFO).
    """
    g = {k: tuple(float(v) for v in (grid or EXPORT_GRID)[k]) for k in EXPORT_GRID}
    tables, dimless = {}, {}
    shapes = [(i, alpha, l, nu, m, mu) for i, alpha in enumerate(g["ratio"])
              for l, nu in enumerate(g["nu"]) for m, mu in enumerate(g["mu"])]
    n = len(shapes) * len(g["load"])
    log.info("export: %d grid points, %d shapes", n, len(shapes))
    done, t0 = 0, time.perf_counter()
    for s, (i, alpha, l, nu, m, mu) in enumerate(shapes, 1):
        what = (f"shape {s}/{len(shapes)}: Ry/Rx = {alpha:g}, nu = {nu:g}, "
                f"traction = {mu:g}")
        if progress:
            progress(done, n, what)
        ts = time.perf_counter()
        for j, Q in enumerate(g["load"]):
            r = compute(export_params(alpha, Q, nu, mu))
            tables[f"{i},{j},{l},{m}"] = r["table"]
            dimless.setdefault(f"{i},{l},{m}", {"fields": r["dimless"],
                                                "maxima": r["maxima"]})
            done += 1
        log.info("export: %s in %.2f s", what, time.perf_counter() - ts)
    if progress:
        progress(done, n, f"{len(shapes)} shapes computed")
    log.info("export: %d shapes in %.1f s", len(shapes), time.perf_counter() - t0)
    return {"grid": {k: list(v) for k, v in g.items()},
            "geometry": {"rx1": _EXPORT_RX, "rx2": "inf", "ry2": "inf", "E": _EXPORT_E},
            "tables": tables, "dimless": dimless}


def export_params(alpha: float, load: float, nu: float, mu: float) -> dict:
    """The live app's inputs of one export grid point (body 1 of radii rx1, alpha rx1 on a
    flat of the same material)."""
    rx = float(_EXPORT_RX.split()[0])
    return {"mode": "bodies", "rx1": _EXPORT_RX, "ry1": f"{alpha * rx:.12g} mm",
            "rx2": "inf", "ry2": "inf", "E": _EXPORT_E, "load": f"{load:.12g} N",
            "nu": f"{nu:.12g}", "traction": f"{mu:.12g}"}



# ------------------------------------------------------------------ roller mode
#: The roller mode's profiles (the page's choices): name -> label.  "crowned" takes the
#: inputs ``flat`` (flat length) and ``crown`` (crown radius).
ROLLER_PROFILES = {"straight": "straight", "iso": "ISO/TS 16281 logarithmic",
                   "lundberg": "Lundberg (for this load)",
                   "johns-gohar": "Johns–Gohar (for this load)",
                   "crowned": "circular crown (flat length, crown radius)"}

#: Slices of the roller mode's line contact, and depths of its stress map (the library's
#: defaults: 41 slices; 24 depths from 0.2 to 2.5 times the largest half-width).
ROLLER_SLICES = 41
ROLLER_DEPTHS = 24

#: Largest |tilt| the roller mode takes [rad].  The library takes any tilt below pi/2 and
#: warns beyond 0.1 rad; a roller's misalignment is some milliradians, and beyond 10 mrad
#: a 12 mm roller of the default size touches on a few slices only.
TILT_MAX = 0.01

#: Largest load of the roller mode [N] (1 MN: far beyond any roller's load; it keeps the
#: inputs finite, the computing time does not grow with the load).
ROLLER_LOAD_MAX = 1.0e6

#: Largest slice width over the contact's largest half-width [-].  The stress below the
#: contact is integrated with nodes some tenths of the half-width apart along the roller
#: (:func:`ballrace.analytic.roller.subsurface_stress`), so its time grows with this
#: ratio.  CPU time of the stress map: 30-70 ms up to a ratio of 4, 0.2 s at 7.6, 0.5 s at
#: 11, 4 s at 27 and 6.6 s at 38 (wall time some 4 times that on a 2-core machine shared
#: with other jobs, load average 7-10).  The bound keeps a request well below 0.5 s of
#: CPU; a lightly loaded long roller is refused, with the load that would do.
SLICE_OVER_WIDTH_MAX = 4.0


def roller_inputs(params: dict) -> dict:
    """The roller mode's inputs parsed to SI (raises :class:`InputError` naming the input).

    Returns ``{"Q", "R1", "R2", "length", "E", "nu", "tilt", "profile"}`` [N, m, m, m, Pa,
    -, rad, -] with ``profile`` a name of :data:`ROLLER_PROFILES` or ``("crowned",
    flat_length, crown_radius)`` [m].
    """
    from ballrace.analytic._checks import check_positive, check_range
    from ballrace.units import parse_quantity

    p = {**DEFAULTS, **{k: v for k, v in params.items() if v is not None}}
    Q = _guard("load", parse_quantity, str(p["load"]), "[force]", "load")
    _guard("load", check_range, Q, "load", 0.0, ROLLER_LOAD_MAX, low_inclusive=False,
           high_inclusive=True, unit="N")
    nu = _number(p["nu"], "nu")
    _guard("nu", check_range, nu, "nu", -1.0, 0.5, unit="-")
    E = _guard("E", parse_quantity, str(p["E"]), "[pressure]", "E")
    _guard("E", check_positive, E, "E", "Pa", bounded=True)
    R1 = _guard("r_roller", parse_quantity, str(p["r_roller"]), "[length]", "roller radius")
    _guard("r_roller", check_positive, R1, "roller radius", "m", bounded=True)
    L = _guard("length", parse_quantity, str(p["length"]), "[length]", "roller length")
    _guard("length", check_positive, L, "roller length", "m", bounded=True)
    R2 = _guard("r_race", parse_quantity, str(p["r_race"]), "[length]", "raceway radius",
                allow_inf=True)
    if R2 == 0 or not 1.0 / R1 + 1.0 / R2 > 0:
        raise InputError("r_race", f"raceway radius must be nonzero (inf for a flat, < 0 "
                         f"for a concave outer raceway) and, when concave, larger than the "
                         f"roller's: |R2| > R1 = {R1 * 1e3:.4g} mm; got {p['r_race']!r}")
    tilt = _guard("tilt", parse_quantity, str(p["tilt"]), "[angle]", "tilt")
    if not abs(tilt) <= TILT_MAX:
        raise InputError("tilt", f"tilt must be within ±{TILT_MAX * 1e3:g} mrad "
                         f"(±{math.degrees(TILT_MAX):.3g} deg; a roller's misalignment is some "
                         f"milliradians, e.g. 1 mrad); got {p['tilt']!r} = "
                         f"{tilt * 1e3:.4g} mrad")
    name = str(p["profile"]).strip().lower()
    if name not in ROLLER_PROFILES:
        raise InputError("profile", f"profile must be one of {', '.join(ROLLER_PROFILES)}; "
                         f"got {p['profile']!r}")
    prof = name
    if name == "crowned":
        flat = _guard("flat", parse_quantity, str(p["flat"]), "[length]", "flat length")
        if not 0.0 <= flat < L:
            raise InputError("flat", f"flat length must be in [0, L) = [0, {L * 1e3:.4g} mm) "
                             f"(the roller length); got {p['flat']!r}")
        crown = _guard("crown", parse_quantity, str(p["crown"]), "[length]", "crown radius")
        reach = 0.5 * (L - flat)
        _guard("crown", check_positive, crown, "crown radius", "m", bounded=True)
        if crown <= reach:
            raise InputError("crown", f"crown radius must exceed the crowned length at each "
                             f"end, (L - flat)/2 = {reach * 1e3:.4g} mm; got {p['crown']!r} "
                             "(crown radii are some metres, e.g. 2 m)")
        prof = ("crowned", flat, crown)
    return {"Q": Q, "R1": R1, "R2": R2, "length": L, "E": E, "nu": nu, "tilt": tilt,
            "profile": prof}


def _roller_profile(prof):
    """The library's profile of :func:`roller_inputs`' ``profile``."""
    from ballrace.analytic import roller

    if isinstance(prof, tuple):
        return roller.Crowned(flat_length=prof[1], crown_radius=prof[2])
    return prof


def _light_load(c, inp: dict, mat) -> float:
    """The smallest load of two significant digits (within some 25 %) whose contact meets
    :data:`SLICE_OVER_WIDTH_MAX` [N]: a few more line contacts of some ms each."""
    from ballrace.analytic import roller

    w = float(c.slice_width)
    need = inp["Q"] * (w / (SLICE_OVER_WIDTH_MAX * float(c.half_width.max()))) ** 2
    for _ in range(30):
        need = float(f"{need:.2g}")
        if need >= ROLLER_LOAD_MAX:
            return ROLLER_LOAD_MAX
        t = roller.line_contact(need, inp["R1"], inp["R2"], inp["length"], mat, mat,
                                profile=_roller_profile(inp["profile"]), tilt=inp["tilt"],
                                n_slices=ROLLER_SLICES)
        if w <= SLICE_OVER_WIDTH_MAX * float(t.half_width.max()):
            return need
        need *= 1.25
    return need


def _roller_sample(inp: dict) -> dict:
    """One roller state (uncached): the line contact, its stresses, packed for the page."""
    import warnings

    from ballrace import Material
    from ballrace.analytic import roller

    notes = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mat = Material(E=inp["E"], nu=inp["nu"])
        c = _guard("load", roller.line_contact, inp["Q"], inp["R1"], inp["R2"],
                   inp["length"], mat, mat, profile=_roller_profile(inp["profile"]),
                   tilt=inp["tilt"], n_slices=ROLLER_SLICES)
        w, bmax = float(c.slice_width), float(c.half_width.max())
        if not w <= SLICE_OVER_WIDTH_MAX * bmax:
            need = _light_load(c, inp, mat)
            raise InputError("load", f"load: {inp['Q']:.4g} N is too light for the "
                             "stresses below this roller to be computed quickly: the slice "
                             f"width L/{ROLLER_SLICES} = {w * 1e3:.3g} mm is more than "
                             f"{SLICE_OVER_WIDTH_MAX:g} times the contact half-width b = "
                             f"{bmax * 1e6:.3g} µm (they would take seconds to minutes); "
                             f"raise the load to about {need:g} N or more, or shorten the "
                             "roller")
        s = _guard("load", roller.subsurface_stress, c, inp["nu"], n_depth=ROLLER_DEPTHS)
        edge_load = float(c.edge_load)
    for wm in caught:
        if issubclass(wm.category, UserWarning):
            notes.append(one_line(wm.message))
    n = c.n_slices
    on = np.flatnonzero(c.in_contact)
    ends = (int(on[0]), int(on[-1])) if on.size else (0, n - 1)
    e = ends[0] if c.pressure[ends[0]] >= c.pressure[ends[1]] else ends[1]
    table = {"load": float(c.load), "length": float(c.length), "R": float(c.R),
             "E_prime": float(c.E_prime), "p_hertz": float(c.hertz_pressure),
             "p_max": float(c.max_pressure), "p_centre": float(c.pressure[n // 2]),
             "p_edge": float(c.pressure[e]), "x_edge": float(c.x[e]),
             "b_centre": float(c.half_width[n // 2]), "approach": float(c.approach),
             "contact_length": float(c.contact_length), "edge_load": edge_load,
             "tilt": float(c.tilt), "nu": float(inp["nu"])}
    marks = {}
    for crit, key in (("von_mises", "vm"), ("tresca", "tr")):
        for where in ("centre", "edge", "maximum"):
            v, x, z = getattr(s, where)(crit)
            marks[f"{key}_{where}"] = [float(v), float(x), float(z)]
            table[f"{key}_{where}"] = float(v)
            table[f"{key}_{where}_x"] = float(x)
            table[f"{key}_{where}_depth"] = float(z)
    line = {"x": [float(v) for v in c.x], "pressure": [float(v) for v in c.pressure],
            "half_width": [float(v) for v in c.half_width],
            "slice_loads": [float(v) for v in c.slice_loads],
            "drop": [float(v) for v in c.drop]}
    vmap = {"x": [float(v) for v in s.x], "z": [float(v) for v in s.depth],
            "vm": _pack(np.asarray(s.von_mises).T),          # rows: depth, columns: x
            "vm_depth": [float(v) for v in s.von_mises_depth],
            "loaded": [bool(v) for v in s.loaded]}
    return {"ok": True, "kind": "roller", "table": table, "line": line, "map": vmap,
            "marks": marks, "note": "; ".join(dict.fromkeys(notes))}


def compute_roller(params: dict) -> dict:
    """One state of the roller mode as a JSON-ready dict (raises :class:`InputError`).

    :func:`ballrace.analytic.roller.line_contact` of the roller on the raceway (both of
    the material E, nu; :data:`ROLLER_SLICES` slices) and
    :func:`ballrace.analytic.roller.subsurface_stress` below it (the slice centres,
    :data:`ROLLER_DEPTHS` depths).  The result has ``table`` (SI: the 2-D Hertz p0 at the
    mean load per length, the pressures at the centre, the contact's end and their
    largest, the approach, the load at which the contact reaches the roller ends, and the
    von Mises / Tresca maxima over depth at the centre, at the end and overall with their
    positions), ``line`` (the pressure, half-width, slice load and drop of every slice),
    ``map`` (the von Mises stress at every slice centre and depth, packed, rows = depth)
    and ``marks`` ([value, x, depth] of the maxima).  Cached on the SI inputs: a state
    seen before costs nothing.
    """
    inp = roller_inputs(params)
    key = ("roller",) + tuple(inp[k] for k in ("Q", "R1", "R2", "length", "E", "nu", "tilt",
                                               "profile"))
    with _CACHE_LOCK:
        hit = _CACHE.get(key)
    if hit is None:
        hit = json.dumps(_roller_sample(inp))
        with _CACHE_LOCK:
            if len(_CACHE) >= _CACHE_MAX:
                _CACHE.pop(next(iter(_CACHE)))
            _CACHE[key] = hit
    out = json.loads(hit)
    out["inputs"] = {}
    return out
