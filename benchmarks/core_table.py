"""Speed of the core: one table of rows, each with the floor or peer it is compared with.

Printed at the end of ``make bench`` (``benchmarks/conftest.py`` runs it in
``pytest_terminal_summary``) and by hand::

    .venv/bin/python benchmarks/core_table.py [--json out.json]

Each row measures, in the same process and run, the quantity and its floor or peer with
``time.perf_counter`` medians over repeats, the row and its floor timed in alternating
batches (:func:`timeit_pair`: on a shared machine the load changes from one second to
the next, and the ratio is the number that matters).  Columns:

``what | now | floor / peer | ratio | goal | met?``

where ``ratio`` is now / floor for times, now / floor for rates, and ``goal`` the target
(an absolute time, or a ratio against the floor).

To add a row (e.g. the shaft-system solver) append a function decorated with ``@row`` to
this module: it returns a :class:`Row`.  A row whose code is not there yet returns
``None`` and is printed as "not available".
"""
from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from dataclasses import asdict, dataclass

import numpy as np

ROWS = []


def row(fn):
    """Register a benchmark row (a function returning a Row or None)."""
    ROWS.append(fn)
    return fn


@dataclass
class Row:
    what: str
    now: float                  # seconds per call, or a rate [1/s] when ``rate``
    floor: float | None         # same unit as ``now``
    floor_what: str
    goal: str                   # e.g. "<= 20 us" or ">= 0.5 x floor"
    met: bool | None
    rate: bool = False          # now/floor are rates (higher is better)
    p95: float | None = None    # 95th percentile of ``now`` over varied cases, if measured

    @property
    def ratio(self):
        return None if not self.floor else self.now / self.floor


def timeit(fn, *, target: float = 0.15, repeats: int = 7, number: int | None = None):
    """Median seconds per call of ``fn()`` over ``repeats`` batches of ``number`` calls."""
    fn()
    if number is None:
        t0 = time.perf_counter()
        fn()
        one = max(time.perf_counter() - t0, 1e-7)
        number = max(1, int(target / repeats / one))
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        ts.append((time.perf_counter() - t0) / number)
    return statistics.median(ts)


def best(fn, n: int = 7, *, warmup: bool = False) -> float:
    """Shortest of ``n`` wall-clock times of one call ``fn()`` [s]; ``warmup`` first calls
    it once untimed."""
    if warmup:
        fn()
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return min(ts)


def timeit_pair(fn, floor, *, target: float = 0.3, repeats: int = 9):
    """Median seconds per call of ``fn()`` and of ``floor()``, measured alternately.

    On a shared machine the load changes from one second to the next; timing the two in
    alternating batches makes their ratio (the number that matters) far steadier than two
    separate medians.  Returns (t_fn, t_floor, median of the per-batch ratios t_fn/t_floor).
    """
    fn(), floor()
    t0 = time.perf_counter()
    fn()
    t1 = time.perf_counter()
    floor()
    t2 = time.perf_counter()
    n1 = max(1, int(target / 2 / repeats / max(t1 - t0, 1e-7)))
    n2 = max(1, int(target / 2 / repeats / max(t2 - t1, 1e-7)))
    a, b = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(n1):
            fn()
        t1 = time.perf_counter()
        for _ in range(n2):
            floor()
        t2 = time.perf_counter()
        a.append((t1 - t0) / n1)
        b.append((t2 - t1) / n2)
    return statistics.median(a), statistics.median(b), statistics.median(x / y for x, y in zip(a, b))


# --------------------------------------------------------------------------- inputs
def _bearing209():
    """Deep-groove 209 bearing (H&D 1981: D = 12.7 mm, d_e = 65 mm, f = 0.52), 9 balls,
    20 um diametral clearance."""
    import ballrace
    return ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, diametral_clearance=20e-6)


def _bearing218():
    """Ricci's (2009) 218 angular-contact bearing, 16 balls, beta_f = 40 deg."""
    import ballrace
    return ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
                                free_contact_angle=np.radians(40))


def _hertz_inputs(n, seed=0):
    rng = np.random.default_rng(seed)
    Rx = 10 ** rng.uniform(-3, -1, n)
    Ry = Rx * 10 ** rng.uniform(0, 4, n)
    swap = rng.random(n) < 0.5
    Rx, Ry = np.where(swap, Ry, Rx), np.where(swap, Rx, Ry)
    Q = 10 ** rng.uniform(0, 5, n)
    return Q, Rx, Ry, 219.78e9


# --------------------------------------------------------------------------- rows
@row
def hertz_vectorised():
    from scipy import special

    from ballrace.analytic import hertz
    n = 200_000
    Q, Rx, Ry, Ep = _hertz_inputs(n)
    m = np.random.default_rng(1).uniform(0.0, 0.999, n)
    t, tf, _ = timeit_pair(lambda: hertz.elliptical_contact(Q, Rx, Ry, Ep),
                           lambda: (special.ellipk(m), special.ellipe(m)))
    now, floor = n / t, n / tf
    return Row(f"exact Hertz, vectorised ({n:.0e} contacts) [1/s]", now, floor,
               "scipy ellipk+ellipe alone", ">= 0.5 x floor", now >= 0.5 * floor, rate=True)


@row
def hertz_simplified():
    from ballrace.analytic import hertz
    n = 200_000
    Q, Rx, Ry, Ep = _hertz_inputs(n)
    t, ts, _ = timeit_pair(
        lambda: hertz.elliptical_contact(Q, Rx, Ry, Ep),
        lambda: hertz.elliptical_contact(Q, Rx, Ry, Ep, method="hamrock-brewe-1983"))
    return Row("exact Hertz vs simplified formulas [1/s]", n / t, n / ts,
               "hamrock-brewe-1983, same inputs", "(information)", None, rate=True)


@row
def hertz_scalar():
    from scipy import special

    import ballrace
    from ballrace.analytic import hertz
    steel = ballrace.Material(E=200e9, nu=0.3)
    t, tf, _ = timeit_pair(lambda: hertz.point_contact(1000.0, 6.35e-3, 6.35e-3, np.inf,
                                                       -0.52 * 12.7e-3, steel),
                           lambda: special.ellipk(0.7))
    return Row("one scalar hertz.point_contact call", t, tf, "one scalar scipy ellipk call",
               "<= 20 us", t <= 20e-6)


@row
def bearing_solve():
    brg = _bearing209()
    n = 1000
    rng = np.random.default_rng(2)
    Fa, Fy = rng.uniform(500, 2000, n), rng.uniform(1000, 5000, n)
    t, tv, _ = timeit_pair(lambda: brg.solve(Fa=1000.0, Fy=3000.0),
                           lambda: brg.solve(Fa=Fa, Fy=Fy), repeats=5)
    tv /= n
    return Row("one BallBearing.solve (9 balls, radial + axial)" + _compiled_note(), t, tv,
               f"vectorised solve, per case ({n} cases)", "<= 0.3 ms", t <= 0.3e-3)


def _compiled_note():
    from ballrace.analytic import loaddist
    return "" if loaddist._COMPILED is not None else " [NumPy iteration: not compiled]"


@row
def bearing_solve_numpy():
    """The same solve with the compiled iteration switched off (what an install without a
    C compiler runs): information, against the default path."""
    from ballrace.analytic import loaddist
    brg = _bearing209()
    compiled = loaddist._COMPILED
    if compiled is None:
        return None
    try:
        t = timeit(lambda: brg.solve(Fa=1000.0, Fy=3000.0))
        loaddist._COMPILED = None
        tn = timeit(lambda: brg.solve(Fa=1000.0, Fy=3000.0))
    finally:
        loaddist._COMPILED = compiled
    return Row("  the same, NumPy iteration only (BALLRACE_NO_COMPILED=1)", tn, t,
               "the default (compiled) solve", "(information)", None)


@row
def duplex_solve():
    from ballrace.analytic.duplex import DuplexPair
    brg = _bearing218()
    pair = DuplexPair(brg, "DB", preload=5000.0)
    t, tb, _ = timeit_pair(lambda: pair.solve(Fa=8000.0, Fr=3000.0),
                           lambda: brg.solve(Fa=8000.0, Fy=3000.0))
    return Row("DuplexPair.solve (218 pair, DB, 5 kN preload)", t, 2 * tb,
               "2 x one BallBearing.solve of its bearing", "<= 2 ms", t <= 2e-3)


@row
def highspeed_solve():
    from ballrace.analytic import highspeed
    brg = _bearing218()
    rng = np.random.default_rng(3)
    cases = [dict(Fa=float(rng.uniform(2e3, 2e4)), Fr=float(rng.uniform(0, 1e4)),
                  speed_inner=float(rng.uniform(1e3, 1.5e4)) * np.pi / 30) for _ in range(12)]
    per = []
    for c in cases:
        try:
            per.append(timeit(lambda c=c: highspeed.solve(brg, **c), repeats=3, number=1))
        except Exception:            # noqa: BLE001 - a failing case is reported, not timed
            per.append(float("nan"))
    per = np.array(per)
    ok = per[np.isfinite(per)]
    med, p95 = float(np.median(ok)), float(np.percentile(ok, 95))
    tb = timeit(lambda: brg.solve(Fa=cases[0]["Fa"], Fy=cases[0]["Fr"]))
    return Row(f"highspeed.solve (218, {len(ok)}/{len(cases)} random cases)", med, tb,
               "one static BallBearing.solve", "<= 5 ms (p95 <= 20 ms)",
               med <= 5e-3 and p95 <= 20e-3, p95=p95)


@row
def eccentric_thrust():
    from ballrace.analytic import loaddist
    brg = _bearing218()
    t, tt, _ = timeit_pair(lambda: loaddist.eccentric_thrust(brg, 17800.0, 50.8e-3),
                           lambda: loaddist.thrust(brg, 17800.0))
    return Row("eccentric_thrust (218, Ricci's case)", t, tt, "thrust() of the same bearing",
               "<= 0.5 ms", t <= 0.5e-3)


@row
def shaft_system():
    """The shaft-system solver (ballrace.analytic.shaft): a 260 mm, 45 mm steel shaft on
    two deep-groove bearings, 40 beam elements, a helical gear between them (the case of
    benchmarks/bench_shaft.py); the peer is one 5-DOF BallBearing.solve of the same
    bearing at the larger seat's reaction, so the ratio says how many bearing solves one
    shaft solve costs."""
    import ballrace
    from ballrace.analytic import shaft as S

    brg = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53, diametral_clearance=10e-6)
    sh = S.Shaft([(0.26, 45e-3, 0.0)], ballrace.BEARING_STEEL, n_elements=40)
    seats = [S.Seat(0.03, brg), S.Seat(0.23, brg, floating=True)]
    loads = [S.gear_mesh(0.09, 5000.0, 0.12, helix_angle=np.radians(15))]
    R = S.solve(sh, seats, loads).reactions[0]          # K_n tables built once
    t, tb, _ = timeit_pair(lambda: S.solve(sh, seats, loads),
                           lambda: brg.solve(Fa=float(R[0]), Fy=float(R[1]), Fz=float(R[2])))
    return Row("shaft.solve (2 seats, 40 elements, gear)", t, tb,
               "one BallBearing.solve at the larger reaction", "<= 20 ms", t <= 20e-3)


def _roller_row(what, bearing, loads):
    """A roller-bearing lamina solve against one BallBearing.solve (209, radial + axial)."""
    ball = _bearing209()
    t, tb, _ = timeit_pair(lambda: bearing.solve(**loads),
                           lambda: ball.solve(Fa=1000.0, Fy=3000.0))
    return Row(what, t, tb, "one BallBearing.solve (209)", "<= 1 ms", t <= 1e-3)


@row
def roller_cylindrical():
    """The lamina load distribution of a cylindrical roller bearing (14 rollers 13 x 11.8
    mm, 31 slices, ISO profile, 45 um clearance) under radial load with an imposed tilt."""
    from ballrace.analytic.roller import RollerBearing
    b = RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=45e-6)
    return _roller_row("RollerBearing.solve, cylindrical (14 x 31 slices, tilt)", b,
                       dict(Fy=6940.0, displacements=[None, None, None, 0.0, 1e-3]))


@row
def roller_tapered():
    """The same for a tapered roller bearing (17 rollers, 15 deg cup, 31 slices), combined
    radial, axial and moment load, all five DOFs free."""
    from ballrace.analytic.roller import RollerBearing
    b = RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered", contact_angle=np.radians(15),
                      diametral_clearance=20e-6)
    return _roller_row("RollerBearing.solve, tapered (17 x 31 slices, 5 DOF)", b,
                       dict(Fa=5000.0, Fy=3000.0, My=20.0))


# --------------------------------------------------------------------------- table
def _fmt_time(t):
    if t is None or not np.isfinite(t):
        return "-"
    for unit, f in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if t >= f:
            return f"{t / f:.3g} {unit}"
    return f"{t * 1e9:.3g} ns"


def _fmt(r: Row, v):
    if v is None:
        return "-"
    return f"{v:.3g} /s" if r.rate else _fmt_time(v)


def measure(names=None):
    """Run the rows (all, or those whose function name is in ``names``)."""
    out = []
    for fn in ROWS:
        if names and fn.__name__ not in names:
            continue
        try:
            r = fn()
        except Exception as exc:     # noqa: BLE001 - one broken row must not hide the others
            r = Row(f"{fn.__name__}: failed ({type(exc).__name__}: {exc})"[:90], float("nan"),
                    None, "-", "-", False)
        out.append((fn.__name__, r))
    return out


def table(results) -> str:
    head = ("what", "now", "floor / peer", "ratio", "goal", "met?")
    rows = []
    for name, r in results:
        if r is None:
            rows.append((name.replace("_", " ") + " (not available yet)", "-", "-", "-", "-", "-"))
            continue
        now = _fmt(r, r.now) + (f" (p95 {_fmt_time(r.p95)})" if r.p95 is not None else "")
        fl = "-" if r.floor is None else f"{_fmt(r, r.floor)} ({r.floor_what})"
        ratio = "-" if r.ratio is None else f"{r.ratio:.3g}"
        met = "-" if r.met is None else ("yes" if r.met else "NO")
        rows.append((r.what, now, fl, ratio, r.goal, met))
    w = [max(len(str(x[i])) for x in rows + [head]) for i in range(len(head))]
    line = "| " + " | ".join(h.ljust(w[i]) for i, h in enumerate(head)) + " |"
    sep = "|" + "|".join("-" * (w[i] + 2) for i in range(len(head))) + "|"
    body = ["| " + " | ".join(str(x[i]).ljust(w[i]) for i in range(len(head))) + " |"
            for x in rows]
    return "\n".join([line, sep] + body)


def machine() -> str:
    import os

    import scipy
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(ln.split(":", 1)[1].strip() for ln in f if ln.startswith("model name"))
    except (OSError, StopIteration):
        pass
    from ballrace.analytic import loaddist
    return (f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, "
            f"NumPy {np.__version__}, SciPy {scipy.__version__}, compiled load-distribution "
            f"kernel {'built' if loaddist._COMPILED is not None else 'not built'}")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--json", help="also write the rows to this JSON file")
    p.add_argument("rows", nargs="*", help="row function names (default: all)")
    a = p.parse_args(argv)
    res = measure(a.rows)
    import sys
    sys.stdout.write(f"machine: {machine()}\n{table(res)}\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"machine": machine(),
                       "rows": {n: (None if r is None else {**asdict(r), "ratio": r.ratio})
                                for n, r in res}}, f, indent=1)


if __name__ == "__main__":
    main()
