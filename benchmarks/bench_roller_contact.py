"""The finite line contact of a profiled roller (analytic/roller/contact.py): one roller of
41 and of 81 slices, as a bearing calculation runs it per roller.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_roller_contact.py

Workload: a 12 x 12 mm roller on a 60 mm raceway (R = 5 mm), 5 kN, ISO/TS 16281's default
profile, tilted by 0.5 mrad (the contact reaches one end), steel on steel.  The goal: one
contact of 41 slices in <= 10 ms, asserted on the process's CPU time per call (the wall
time of a shared machine says more about its other users).  The load at which the contact
reaches the ends (``edge_load``, computed on first access) and the subsurface stresses
(41 positions x 24 depths) are timed separately.
"""
from __future__ import annotations

import time
import timeit

import ballrace
from ballrace.analytic import roller

ST = ballrace.BEARING_STEEL
GOAL = 10e-3                          # [s] one contact of 41 slices


def one_contact(n_slices=41):
    return roller.line_contact(5000.0, 0.006, 0.03, 0.012, ST, ST, profile="iso",
                               tilt=5e-4, n_slices=n_slices)


def with_edge_load(n_slices=41):
    return one_contact(n_slices).edge_load


def cpu_per_call(f, n=20):
    """Process CPU time of one call [s] (the mean of n)."""
    t = time.process_time()
    for _ in range(n):
        f()
    return (time.process_time() - t) / n


def test_line_contact_41_slices(benchmark):
    one_contact()                                 # build the strip function's table once
    c = benchmark(one_contact)
    cpu = cpu_per_call(one_contact)
    benchmark.extra_info["goal_s"] = GOAL
    benchmark.extra_info["cpu_s"] = cpu
    assert abs(c.slice_loads.sum() - 5000.0) < 1e-9 * 5000.0
    assert cpu < GOAL


def test_line_contact_81_slices(benchmark):
    one_contact(81)
    c = benchmark(one_contact, 81)
    assert abs(c.slice_loads.sum() - 5000.0) < 1e-9 * 5000.0


def test_subsurface_stress_41_slices(benchmark):
    c = one_contact()
    s = benchmark(roller.subsurface_stress, c)
    assert s.maximum()[0] > 0


def test_line_contact_41_slices_with_edge_load(benchmark):
    one_contact()
    e = benchmark(with_edge_load)
    assert 0 < e


if __name__ == "__main__":
    one_contact()
    for name, f in (("41 slices", one_contact), ("81 slices", lambda: one_contact(81)),
                    ("41 slices + edge load", with_edge_load),
                    ("stresses below 41 slices",
                     lambda c=one_contact(): roller.subsurface_stress(c))):
        t = min(timeit.repeat(f, number=20, repeat=5)) / 20
        print(f"{name:24s} {t * 1e3:7.2f} ms wall (best of 5), {cpu_per_call(f) * 1e3:7.2f} ms "
              "CPU")
