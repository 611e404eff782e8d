"""Elastic shaft on two ball bearings (ballrace.analytic.shaft): timing of one solve.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_shaft.py

Case: a 260 mm, 45 mm solid steel shaft on two deep-groove bearings (D = 7.938 mm,
Z = 9, d_e = 38.5 mm, P_d = 10 um) at x = 30 and 230 mm, 40 beam elements, a helical
gear mesh at x = 90 mm (F_t = 5 kN, d = 120 mm, 20 deg, 15 deg helix).  Goal: one
solve <= 20 ms.  The peer measured in the same run is one general 5-DOF
``loaddist.solve`` of the same bearing at the larger reaction, so the ratio
shaft solve / single-bearing solve is machine-independent.
"""
from __future__ import annotations

import sys
import time

import numpy as np

import ballrace
from ballrace.analytic import shaft as S


def case():
    brg = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53, diametral_clearance=10e-6)
    s = S.Shaft([(0.26, 45e-3, 0.0)], ballrace.BEARING_STEEL, n_elements=40)
    seats = [S.Seat(0.03, brg), S.Seat(0.23, brg, floating=True)]
    loads = [S.gear_mesh(0.09, 5000.0, 0.12, helix_angle=np.radians(15))]
    return brg, s, seats, loads


def test_shaft_two_seats_40_elements(benchmark):
    brg, s, seats, loads = case()
    r = S.solve(s, seats, loads)                  # K_n tables built once
    R = r.reactions[0]
    t0 = time.perf_counter()
    for _ in range(20):
        brg.solve(*R)
    peer = (time.perf_counter() - t0) / 20
    r = benchmark(S.solve, s, seats, loads)
    benchmark.extra_info["iterations"] = r.iterations
    benchmark.extra_info["ratio_to_single_bearing_solve"] = benchmark.stats.stats.min / peer
    assert np.abs(r.equilibrium_residual()).max() < 1e-8 * 5000


if __name__ == "__main__":
    brg, s, seats, loads = case()
    t0 = time.perf_counter()
    r = S.solve(s, seats, loads)
    t_first = time.perf_counter() - t0
    ts = []
    for _ in range(50):
        t0 = time.perf_counter()
        r = S.solve(s, seats, loads)
        ts.append(time.perf_counter() - t0)
    tp = []
    for _ in range(50):
        t0 = time.perf_counter()
        brg.solve(*r.reactions[0])
        tp.append(time.perf_counter() - t0)
    sys.stdout.write(f"first call: {t_first * 1e3:.1f} ms\n")
    sys.stdout.write(f"shaft solve ({r.nodes.size - 1} elements, {r.iterations} Newton "
                     f"iterations): best {min(ts) * 1e3:.2f} ms, median "
                     f"{np.median(ts) * 1e3:.2f} ms; single-bearing solve best "
                     f"{min(tp) * 1e3:.2f} ms (ratio {min(ts) / min(tp):.1f})\n")
