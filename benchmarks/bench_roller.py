"""Roller-bearing lamina load distribution: timing against the ball solve in the same run.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_roller.py

Cylindrical: 14 rollers 13 x 11.8 mm on d_m = 70.65 mm, 31 slices, ISO profile, 45 um
clearance, Fy = 6.94 kN with an imposed tilt of 1 mrad.  Tapered: 17 rollers 10 x 15 mm on
d_m = 60 mm, 15 deg cup, 31 slices, Fa = 5 kN, Fy = 3 kN, My = 20 N m, five DOFs free.
Goal: <= 1 ms per solve.  The ratio to one BallBearing.solve (the 209 deep-groove bearing,
Fa = 1 kN, Fy = 3 kN) is recorded in ``extra_info``.
"""
from __future__ import annotations

import sys

import numpy as np

import ballrace
import core_table
from ballrace.analytic.roller import RollerBearing

CYLINDRICAL = dict(Fy=6940.0, displacements=[None, None, None, 0.0, 1e-3])
TAPERED = dict(Fa=5000.0, Fy=3000.0, My=20.0)


def cylindrical():
    return RollerBearing(13e-3, 11.8e-3, 14, 70.65e-3, diametral_clearance=45e-6)


def tapered():
    return RollerBearing(10e-3, 15e-3, 17, 60e-3, kind="tapered",
                         contact_angle=np.radians(15), diametral_clearance=20e-6)


def ball():
    """The 209 deep-groove bearing of the core table (9 balls, 20 um clearance)."""
    return ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, diametral_clearance=20e-6)


def _bench(benchmark, bearing, loads):
    r = benchmark(bearing.solve, **loads)
    b = ball()
    _, tb, ratio = core_table.timeit_pair(lambda: bearing.solve(**loads),
                                          lambda: b.solve(Fa=1000.0, Fy=3000.0), repeats=5)
    benchmark.extra_info["iterations"] = r.iterations
    benchmark.extra_info["ratio_to_ball_solve"] = ratio
    assert r.relative_residual < 1e-9


def test_roller_cylindrical_solve(benchmark):
    _bench(benchmark, cylindrical(), CYLINDRICAL)


def test_roller_tapered_solve(benchmark):
    _bench(benchmark, tapered(), TAPERED)


if __name__ == "__main__":
    for name in ("roller_cylindrical", "roller_tapered"):
        r = dict(core_table.measure([name]))[name]
        sys.stdout.write(f"{r.what}: {r.now * 1e3:.3f} ms, one ball solve "
                         f"{r.floor * 1e3:.3f} ms, ratio {r.ratio:.2f} (goal {r.goal})\n")
