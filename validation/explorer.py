"""``ballrace teach serve`` and ``ballrace teach export``: the subsurface-stress explorer.

A teaching app in the browser.  The user picks a contact (two bodies, or a ball in the
inner or outer groove of a bearing, typed in or read from a bearing case file), a load,
Poisson's ratio and a traction coefficient; the page shows the pressure ellipse, the
sections y = 0 and x = 0 of a chosen stress field with the Lundberg–Palmgren point and
the maximum marked, the depth profiles on the axis, an iso-surface of the von Mises
stress (rotatable) and a table of a, b, p0, delta, tau0, z0, tau_max and its depth.

Everything numeric comes from :mod:`ballrace.analytic`: :func:`~ballrace.analytic.hertz.
point_contact` / :func:`~ballrace.analytic.hertz.elliptical_contact`,
:func:`~ballrace.analytic.subsurface.stress`, :func:`~ballrace.analytic.subsurface.
max_shear`, :func:`~ballrace.analytic.subsurface.von_mises` and
:func:`~ballrace.analytic.subsurface.orthogonal_shear`.  This module only samples them on
coarse grids, packs the samples for the page and serves them.

The server is the standard library's :class:`http.server.ThreadingHTTPServer` bound to
127.0.0.1; the page is one HTML file with its CSS and JavaScript inline (a canvas front
end, no external asset), so the same page works as a self-contained export
(:func:`export_html`) with a precomputed parameter grid embedded.

The stress fields scale exactly with the contact: in units of p0 and of the minor
semi-axis b they depend only on the semi-axis ratio, nu and the traction coefficient.
:func:`_dimensionless` is therefore cached on those three, and a change of load (or of
the size of the bodies at a fixed ratio) costs only the Hertz solution.
"""
from __future__ import annotations

import base64
import gzip
import json
import logging
import math
import re
import threading
import time
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

__all__ = ["FIELDS", "DEFAULTS", "compute", "case_inputs", "export_html", "export_grid",
           "make_server", "page", "register_commands", "EXPORT_GRID"]

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

_STATIC = Path(__file__).with_name("explorer_static")

# Bounds of the work one request may ask for (the server refuses more with a 400).  The
# grids are fixed above, so a request chooses only the inputs; these bound their size.
#: Largest |traction coefficient| the explorer takes [-].  The library accepts 10, but its
#: maxima searches beyond 1 can take a minute (a traction coefficient above 1 is beyond
#: dry steel-on-steel friction anyway).
TRACTION_MAX = 1.0
MAX_BODY = 16_384        # bytes of a POST /api/compute body
MAX_QUERY = 2_048        # characters of a GET query string
MAX_TEXT = 100           # characters of one input
MAX_CASE_BYTES = 1_000_000   # size of a case file /api/case reads
_PARAMS = frozenset(DEFAULTS) | {"set_ratio", "_maxima"}
_POW = re.compile(r"\^|\*\*")
_POW_ARG = re.compile(r"\s*\(?\s*[+-]?\d{1,2}(?:\.\d{1,3})?(?![\d.])\s*\)?")


class InputError(ValueError):
    """A bad input: ``field`` names the control, the message is the library's one line."""

    def __init__(self, field: str, message: str):
        super().__init__(message)
        self.field = field


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return text or type(exc).__name__


def _guard(field: str, fun, *args, **kwargs):
    """Call ``fun``; a ValueError/TypeError becomes an :class:`InputError` for ``field``."""
    try:
        return fun(*args, **kwargs)
    except (ValueError, TypeError, ArithmeticError) as exc:
        raise InputError(field, _one_line(exc)) from None


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
            msg = _one_line(exc)
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
            msg = _one_line(exc)
            field = next((v for k, v in fields.items() if msg.startswith(k)), "D")
            raise InputError(field, msg) from None
        cv = brg.curvature(race, angle)
        c = _guard("D", hertz.elliptical_contact, Q, float(cv.Rx), float(cv.Ry), brg.E_prime)
    else:
        raise InputError("mode", f"mode must be 'bodies' or 'bearing'; got {mode!r}")
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
        return {"ok": False, "field": "general", "error": _one_line(exc)}


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


class RequestError(ValueError):
    """A request the server refuses before any computation (HTTP 400): too large, an
    unknown input, an exponent that would make pint compute a huge integer."""

    def __init__(self, field: str, message: str):
        super().__init__(message)
        self.field = field


def check_text(field: str, text) -> str:
    """One input of a request, bounded: at most :data:`MAX_TEXT` characters, and every
    exponent (``^`` or ``**``) a plain number of at most two digits that is not raised
    again (pint evaluates ``9^9^9`` as an integer of 370 million digits).

    Raises :class:`RequestError`; returns the text.
    """
    s = str(text)
    if len(s) > MAX_TEXT:
        raise RequestError(field, f"{field}: at most {MAX_TEXT} characters; got {len(s)}")
    for m in _POW.finditer(s):
        rest = s[m.end():]
        arg = _POW_ARG.match(rest)
        if arg is None or _POW.match(rest[arg.end():].lstrip()):
            raise RequestError(field, f"{field}: {s!r}: an exponent must be a number of at "
                               "most two digits, not raised again (e.g. '200 N/mm^2')")
    return s


def check_request(body) -> tuple[dict, bool]:
    """The inputs of a POST /api/compute body, bounded (see :func:`check_text`): a JSON
    object of at most the page's inputs; returns ``(params, maxima)``.

    Raises :class:`RequestError` naming the input.
    """
    if not isinstance(body, dict):
        raise RequestError("general", "the request body must be a JSON object")
    unknown = sorted(str(k) for k in body if k not in _PARAMS)
    if unknown:
        name = check_text("general", unknown[0][:40])
        raise RequestError("general", f"unknown input {name!r}; the inputs are "
                           f"{', '.join(sorted(_PARAMS))}")
    maxima = bool(body.pop("_maxima", True))
    params = {}
    for k, v in body.items():
        if v is not None and not isinstance(v, (str, int, float)):
            raise RequestError(k, f"{k}: give a text or a number; got {type(v).__name__}")
        params[k] = None if v is None else check_text(k, v)
    return params, maxima


def resolve_case(text, root, allowed=()) -> Path:
    """The case file ``text`` names, if the explorer may read it: one of ``allowed`` (the
    ``--case`` file), or a ``.toml`` file in the folder ``root`` or below it (a relative
    path is taken from ``root``; symbolic links are followed before the check, so none
    leads out).  Anything else is one refusal that says nothing of the file.

    Raises :class:`InputError` for the field ``case``.
    """
    root = Path(root).resolve()
    refuse = InputError("case", "case: the explorer reads only the case file it was started "
                        "with (--case) and .toml case files in the folder it was started in "
                        "or below it")
    s = str(text).strip()
    if not s:
        raise InputError("case", "case: give the path of a bearing case file (.toml), "
                         "relative to the folder the explorer was started in")
    try:
        real = (root / s).resolve()          # an absolute s replaces root
    except (OSError, ValueError, RuntimeError):
        raise refuse from None
    if real not in {Path(a).resolve() for a in allowed} and (
            real.suffix.lower() != ".toml" or not real.is_relative_to(root)):
        raise refuse
    if not real.is_file():
        raise InputError("case", f"case: no case file {s!r} in the folder the explorer was "
                         "started in")
    if real.stat().st_size > MAX_CASE_BYTES:
        raise InputError("case", f"case: {s!r} is larger than {MAX_CASE_BYTES // 1000} kB; "
                         "a case file is a few kB")
    return real


# ------------------------------------------------------------------ the page
def page(data: dict | None = None, initial: dict | None = None) -> str:
    """The explorer's HTML page: CSS and JavaScript inline; ``data`` embedded (export);
    ``initial`` inputs replace those of :data:`DEFAULTS`."""
    html = (_STATIC / "explorer.html").read_text(encoding="utf-8")
    css = (_STATIC / "explorer.css").read_text(encoding="utf-8")
    js = (_STATIC / "explorer.js").read_text(encoding="utf-8")
    blob = ""
    if data is not None:
        raw = json.dumps(data, separators=(",", ":")).encode("utf-8")
        blob = base64.b64encode(gzip.compress(raw, 9, mtime=0)).decode("ascii")
    init = json.dumps({**DEFAULTS, **(initial or {})}).replace("</", "<\\/")
    fields = json.dumps(FIELDS)
    return (html.replace("/*CSS*/", css)
            .replace("/*JS*/", js.replace("</", "<\\/"))
            .replace("__DEFAULTS__", init).replace("__FIELDS__", fields)
            .replace("__DATA__", blob))


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


def export_html(path, grid: dict | None = None, progress=None) -> Path:
    """Write the self-contained explorer handout to ``path``; returns the path."""
    data = export_grid(grid, progress)
    if progress:
        n = len(data["tables"])
        progress(n, n, "compressing and writing the page")
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(page(data), encoding="utf-8")
    log.info("wrote %s (%d bytes)", path, path.stat().st_size)
    return path


# ------------------------------------------------------------------ the server
def _hosts(host: str, port: int) -> frozenset:
    """The Host headers the server answers: its loopback names with its port (a page of
    another site whose name was made to point at 127.0.0.1 sends its own name)."""
    names = {"127.0.0.1", "localhost", "[::1]", f"[{host}]" if ":" in host else host}
    out = {f"{n}:{port}" for n in names}
    if port == 80:
        out |= names
    return frozenset(n.lower() for n in out)


def make_server(port: int = 0, host: str = "127.0.0.1", initial: dict | None = None,
                root=None, cases=()):
    """A ThreadingHTTPServer serving the explorer (not started); port 0 picks a free port;
    ``initial`` inputs (strings, as :data:`DEFAULTS`) are the page's first state.

    ``GET /api/case`` reads only the files of ``cases`` (the ``--case`` file) and ``.toml``
    files in the folder ``root`` (default: the current folder) or below it (see
    :func:`resolve_case`).  A request whose ``Host`` is not 127.0.0.1, localhost or [::1]
    with the server's port, or whose ``Origin`` is another site, is refused (403); a request
    larger than the bounds (:data:`MAX_BODY`, :data:`MAX_QUERY`, :func:`check_text`) gets a
    400 with a one-line message.
    """
    from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
    from urllib.parse import parse_qs, urlparse

    html = page(None, initial).encode("utf-8")
    root = Path(root if root is not None else Path.cwd()).resolve()
    cases = tuple(Path(c).resolve() for c in cases)
    # one view computation at a time, and one maxima search at a time: the slow searches
    # with traction (second request) never hold up the views of the next change
    locks = {False: threading.Lock(), True: threading.Lock()}
    # the page talks to this server only and is shown in no other site's frame
    csp = "connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'"

    class Handler(BaseHTTPRequestHandler):
        server_version = "ballrace-explorer"
        sys_version = ""
        timeout = 30                            # a client that stalls is dropped

        def log_message(self, fmt, *args):      # no request log on the terminal
            log.debug("explorer: " + fmt, *args)

        def _send(self, code: int, body: bytes, ctype: str) -> None:
            try:
                self.send_response(code)
                self.send_header("Content-Type", ctype)
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Cache-Control", "no-store")
                self.send_header("X-Content-Type-Options", "nosniff")
                self.send_header("Referrer-Policy", "no-referrer")
                if ctype.startswith("text/html"):
                    self.send_header("Content-Security-Policy", csp)
                self.end_headers()
                self.wfile.write(body)
            except (BrokenPipeError, ConnectionResetError):
                pass

        def _json(self, obj, code: int = 200) -> None:
            self._send(code, json.dumps(obj).encode("utf-8"), "application/json")

        def _refuse(self, field: str, message: str) -> None:
            self._json({"ok": False, "field": field, "error": message}, 400)

        def _allowed(self) -> bool:
            """The Host (and Origin, when sent) name this server; else a bare 403."""
            hosts = _hosts(*self.server.server_address[:2])
            got = self.headers.get_all("Host") or []
            origin = self.headers.get_all("Origin") or []
            ok = (len(got) == 1 and got[0].strip().lower() in hosts and len(origin) <= 1
                  and all(o.strip().lower() in {"http://" + h for h in hosts}
                          for o in origin))
            if not ok:
                self.close_connection = True
                self._send(403, b"forbidden\n", "text/plain")
            return ok

        def do_GET(self):  # noqa: N802 - http.server's name
            if not self._allowed():
                return
            url = urlparse(self.path)
            if url.path in ("/", "/index.html"):
                self._send(200, html, "text/html; charset=utf-8")
            elif url.path == "/api/case":
                if len(url.query) > MAX_QUERY:
                    self._refuse("case", f"case: the query is longer than {MAX_QUERY} "
                                 "characters")
                    return
                q = {k: v[0] for k, v in parse_qs(url.query).items()}
                race = q.get("race", "inner")
                if race not in ("inner", "outer"):
                    self._refuse("race", "race must be 'inner' or 'outer'")
                    return
                text, path = q.get("path", ""), None
                try:
                    path = resolve_case(text, root, cases)
                    inputs = case_inputs(str(path), race)
                except InputError as exc:      # the path as typed, not as resolved
                    msg = str(exc) if path is None else str(exc).replace(str(path), text)
                    self._json({"ok": False, "field": "case", "error": msg})
                except Exception:
                    log.debug("explorer: case file", exc_info=True)
                    self._json({"ok": False, "field": "case",
                                "error": "case: the file cannot be read as a case file"})
                else:
                    self._json({"ok": True, "inputs": inputs})
            elif url.path == "/favicon.ico":
                self._send(204, b"", "image/x-icon")
            else:
                self._send(404, b"not found", "text/plain")

        def do_POST(self):  # noqa: N802
            if not self._allowed():
                return
            if urlparse(self.path).path != "/api/compute":
                self._send(404, b"not found", "text/plain")
                return
            self.close_connection = True
            try:
                n = int(self.headers.get("Content-Length") or 0)
            except ValueError:
                n = -1
            if not 0 <= n <= MAX_BODY:
                self._refuse("general", f"the request body must be 0 to {MAX_BODY} bytes "
                             f"(Content-Length); got {self.headers.get('Content-Length')!r}"[:200])
                return
            try:
                body = json.loads(self.rfile.read(n) or b"{}")
                params, maxima = check_request(body)
            except RequestError as exc:
                self._refuse(exc.field, str(exc))
                return
            except (ValueError, UnicodeDecodeError, RecursionError) as exc:
                self._refuse("general", "the request body is not JSON: "
                             + _one_line(exc)[:200])
                return
            with locks[maxima]:
                self._json(compute_safe(params, maxima))

    class Server(ThreadingHTTPServer):
        daemon_threads = True

        def handle_error(self, request, client_address):  # never a traceback on stderr
            log.debug("explorer: request error", exc_info=True)

    return Server((host, port), Handler)


# ------------------------------------------------------------------ the commands
def register_commands(teach_app) -> None:
    """Add ``serve`` and ``export`` to the ``ballrace teach`` typer group."""
    @teach_app.command("serve")
    def teach_serve(
        port: Annotated[int, typer.Option(
            "--port", help="Port on 127.0.0.1 (default 0: a free one, printed).")] = 0,
        case: Annotated[Path | None, typer.Option(
            "--case", help="Start with the ball in a groove of this bearing case file.")] = None,
        race: Annotated[str, typer.Option(
            "--race", help="With --case: inner | outer.")] = "inner",
    ):
        """Serve the interactive subsurface-stress explorer on 127.0.0.1 (Ctrl-C stops it)."""
        if not 0 <= port <= 65535:
            typer.echo(f"error: --port must be in [0, 65535]; got {port}", err=True)
            raise typer.Exit(code=2)
        initial = {}
        if race not in ("inner", "outer"):
            typer.echo(f"error: --race must be inner or outer; got {race!r}", err=True)
            raise typer.Exit(code=2)
        try:
            if case is not None:
                try:
                    initial = case_inputs(str(case), race)
                except InputError as exc:
                    typer.echo(f"error: --case {exc}", err=True)
                    raise typer.Exit(code=2) from None
                initial["case"] = str(case)
                initial.pop("title", None)
            first = compute_safe({**DEFAULTS, **initial})   # imports and the first state
            if not first["ok"]:
                typer.echo(f"error: {first['error']}", err=True)
                raise typer.Exit(code=2)
            try:
                server = make_server(port, initial=initial,
                                     cases=() if case is None else (case,))
            except OSError as exc:
                typer.echo(f"error: cannot listen on 127.0.0.1:{port} ({_one_line(exc)})",
                           err=True)
                raise typer.Exit(code=2) from None
            host, port = server.server_address[:2]
            import signal

            def _stop(signum, frame):           # a SIGTERM stops it as Ctrl-C does
                raise KeyboardInterrupt

            signal.signal(signal.SIGTERM, _stop)
            typer.echo(f"ballrace explorer: http://{host}:{port}/  (Ctrl-C stops it)")
            try:
                server.serve_forever(poll_interval=0.2)
            finally:
                server.server_close()
        except KeyboardInterrupt:
            pass
        typer.echo("ballrace explorer: stopped")

    @teach_app.command("export")
    def teach_export(
        out: Annotated[Path, typer.Argument(
            help="HTML file to write (default ballrace-out/teach/explorer.html).")]
            = Path("ballrace-out") / "teach" / "explorer.html",
        small: Annotated[bool, typer.Option(
            "--small", help="A 2 x 3 x 1 x 2 grid (ratio, load, nu, traction), for a quick look.")]
            = False,
    ):
        """Write the explorer as one self-contained HTML file (a precomputed grid, sliders)."""
        from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn,
                                   TimeElapsedColumn)

        from ballrace.console import make_console, output_folder

        if out.is_dir():
            out = out / "explorer.html"
        elif not out.suffix:
            out = out.with_suffix(".html")
        try:
            output_folder(out.parent, "OUT")
        except ValueError as exc:
            typer.echo(f"error: {_one_line(exc)}", err=True)
            raise typer.Exit(code=2) from None
        grid = {k: tuple((SMALL_GRID if small else EXPORT_GRID)[k]) for k in EXPORT_GRID}
        n = math.prod(len(v) for v in grid.values())
        shapes = n // len(grid["load"])
        err = make_console(stderr=True)
        typer.echo(f"ballrace explorer: computing {n} grid points ({shapes} shapes) for "
                   f"{out} ...", err=True)
        try:
            if err.is_terminal:      # a bar on the terminal, else a line every tenth
                with Progress(TextColumn("{task.description}"), BarColumn(),
                              MofNCompleteColumn(), TimeElapsedColumn(), console=err,
                              transient=True) as prog:
                    task = prog.add_task("starting", total=n)
                    path = export_html(out, grid, lambda i, n, text: prog.update(
                        task, completed=i, total=n, description=text))
            else:
                path = export_html(out, grid, _ProgressLines(n))
        except KeyboardInterrupt:
            typer.echo("ballrace explorer: export interrupted, nothing written", err=True)
            raise typer.Exit(code=130) from None
        except (OSError, ValueError) as exc:
            typer.echo(f"error: {_one_line(exc)}", err=True)
            raise typer.Exit(code=2) from None
        size = path.stat().st_size
        typer.echo(f"wrote {path} ({size / 1e6:.2f} MB)")


class _ProgressLines:
    """``teach export``'s progress when stderr is not a terminal: a line per tenth of the
    grid (and the last step), with the time so far."""

    def __init__(self, total: int):
        self.total, self.shown, self.t0 = total, -1, time.perf_counter()

    def __call__(self, done: int, total: int, text: str) -> None:
        tenth = 10 * done // max(total, 1)
        if tenth > self.shown or done >= total:
            self.shown = tenth
            typer.echo(f"  {done}/{total} grid points, {text} "
                       f"({time.perf_counter() - self.t0:.0f} s)", err=True)


#: The ``--small`` export grid.
SMALL_GRID = {"ratio": (1.0, 8.0), "load": (500.0, 2000.0, 8000.0), "nu": (0.3,),
              "mu": (0.0, 0.3)}
