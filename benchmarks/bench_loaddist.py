"""General 5-DOF load distribution (exact Hertz at each ball's contact angle): timing.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_loaddist.py

Bearing: Ricci's 218 angular-contact bearing (16 balls, D = 22.225 mm, d_e = 125.26 mm,
f = 0.5232, beta_f = 40 deg).  One case: Fa = 17.8 kN, Fy = 8.9 kN, Mz = -200 N m.
Duty cycle: 10^4 random cases, Fa in [0, 20] kN, Fy in [0, 10] kN, Fz in [-5, 5] kN,
My, Mz in [-300, 300] N m, solved in one vectorized call.  Goals: <= 2 ms per single
case, <= 5 s for the 10^4 cases.  Every case must balance to 1e-9 relative.
"""
from __future__ import annotations

import sys
import time

import numpy as np

import ballrace
from ballrace.analytic import loaddist
from benchstats import record

N = 10**4


def bearing():
    return ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
                                free_contact_angle=np.radians(40),
                                material=ballrace.Material(E=200e9, nu=0.3))


def duty_cycle(n=N, seed=0):
    rng = np.random.default_rng(seed)
    return dict(Fa=rng.uniform(0, 2e4, n), Fy=rng.uniform(0, 1e4, n),
                Fz=rng.uniform(-5e3, 5e3, n), My=rng.uniform(-300, 300, n),
                Mz=rng.uniform(-300, 300, n))


SINGLE = dict(Fa=17800.0, Fy=8900.0, Mz=-200.0)


def test_solve_single_case(benchmark):
    brg = bearing()
    loaddist.solve(brg, **SINGLE)                 # builds the per-bearing K_n table once
    r = benchmark(loaddist.solve, brg, **SINGLE)
    benchmark.extra_info["iterations"] = r.iterations
    assert r.relative_residual < 1e-9


def test_solve_duty_cycle_10k(benchmark):
    brg = bearing()
    loads = duty_cycle()
    loaddist.solve(brg, **SINGLE)
    r = benchmark.pedantic(loaddist.solve, args=(brg,), kwargs=loads, rounds=3, iterations=1)
    record(benchmark, "cases_per_s", lambda t: N / t)
    benchmark.extra_info["max_iterations"] = r.iterations
    assert np.all(r.relative_residual < 1e-9)


if __name__ == "__main__":
    brg = bearing()
    t0 = time.perf_counter()
    loaddist.solve(brg, **SINGLE)
    t_first = time.perf_counter() - t0
    ts = []
    for _ in range(200):
        t0 = time.perf_counter()
        r = loaddist.solve(brg, **SINGLE)
        ts.append(time.perf_counter() - t0)
    loads = duty_cycle()
    td = []
    for _ in range(3):
        t0 = time.perf_counter()
        rd = loaddist.solve(brg, **loads)
        td.append(time.perf_counter() - t0)
    sys.stdout.write(f"first call (K_n table build + solve): {t_first * 1e3:.1f} ms\n")
    sys.stdout.write(f"single case: best {min(ts) * 1e3:.2f} ms, median {np.median(ts) * 1e3:.2f} ms "
                     f"({r.iterations} Newton iterations)\n")
    sys.stdout.write(f"10^4-case duty cycle: best {min(td):.2f} s ({N / min(td):.0f} cases/s), "
                     f"max {rd.iterations} iterations, worst residual "
                     f"{rd.relative_residual.max():.1e}\n")
