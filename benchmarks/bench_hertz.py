"""Exact Hertz over 10^6 random elliptical contacts: throughput and accuracy.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_hertz.py

Inputs: Rx log-uniform in [1 mm, 100 mm], radius ratio Ry/Rx log-uniform in [1, 1e4]
(half the set swapped so Ry < Rx), load log-uniform in [1 N, 1e5 N], E' = 219.78 GPa.
Accuracy: max relative error of k, a, b, delta, p_max against the slow scalar mpmath
reference (tests/mpref.py) on a random sample of 200 contacts.
"""
from __future__ import annotations

import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))

from ballrace.analytic import hertz  # noqa: E402
from benchstats import record

N = 10**6


def make_inputs(n=N, seed=0):
    rng = np.random.default_rng(seed)
    Rx = 10 ** rng.uniform(-3, -1, n)
    alpha = 10 ** rng.uniform(0, 4, n)
    Ry = Rx * alpha
    swap = rng.random(n) < 0.5
    Rx, Ry = np.where(swap, Ry, Rx), np.where(swap, Rx, Ry)
    Q = 10 ** rng.uniform(0, 5, n)
    return Q, Rx, Ry, 219.78e9


def max_error(sample=200, seed=1):
    from mpref import hertz_exact

    Q, Rx, Ry, Ep = make_inputs(sample, seed)
    c = hertz.elliptical_contact(Q, Rx, Ry, Ep)
    worst = 0.0
    for i in range(sample):
        ref = hertz_exact(Q[i], Rx[i], Ry[i], Ep)
        for q in ("k", "a", "b", "approach", "p_max"):
            worst = max(worst, abs(float(getattr(c, q)[i]) / ref[q] - 1))
    return worst


def test_exact_hertz_throughput(benchmark):
    Q, Rx, Ry, Ep = make_inputs()
    hertz.elliptical_contact(1.0, 1.0, 2.0, 1.0)     # build the ellipticity tables once
    c = benchmark(hertz.elliptical_contact, Q, Rx, Ry, Ep)
    record(benchmark, "contacts_per_s", lambda t: N / t)
    assert np.all(np.isfinite(c.p_max))


def test_exact_hertz_accuracy(benchmark):
    err = benchmark.pedantic(max_error, rounds=1, iterations=1)
    benchmark.extra_info["max_rel_error"] = err
    assert err < 1e-11


if __name__ == "__main__":
    Q, Rx, Ry, Ep = make_inputs()
    t0 = time.perf_counter()
    hertz.elliptical_contact(1.0, 1.0, 2.0, 1.0)
    t_build = time.perf_counter() - t0
    times = []
    for _ in range(5):
        t0 = time.perf_counter()
        hertz.elliptical_contact(Q, Rx, Ry, Ep)
        times.append(time.perf_counter() - t0)
    best = min(times)
    sys.stdout.write(f"one-off table build: {t_build * 1e3:.1f} ms\n")
    sys.stdout.write(f"10^6 exact contacts: best {best:.3f} s -> {N / best / 1e6:.2f} million contacts/s\n")
    sys.stdout.write(f"max relative error vs mpmath (200 samples): {max_error():.2e}\n")
