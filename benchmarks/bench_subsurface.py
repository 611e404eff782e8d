"""Subsurface stresses: vectorized on-axis maxima and a full-field section.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_subsurface.py

Two workloads: the on-axis Tresca and von Mises maxima (depth search) of 10^4 elliptical
contacts of radius ratios 1 ... 200, and the full stress tensor on a 100 x 100 section of a
k = 20 contact (Love's potentials).  Both were timed tests before; speed lives here now.
"""
from __future__ import annotations

import time

import numpy as np

from ballrace.analytic import hertz, subsurface

E_PRIME = 219.78e9


def depth_search():
    Q = np.linspace(100, 5000, 10**4)
    c = hertz.elliptical_contact(Q, 0.005, np.logspace(np.log10(0.005), 0, 10**4), E_PRIME)
    return subsurface.max_shear(c), subsurface.von_mises(c)


def section_100x100():
    c = hertz.elliptical_contact(2000.0, 0.005, 0.1, E_PRIME)
    X, Z = np.meshgrid(np.linspace(-3, 3, 100) * c.b, np.linspace(0, 3, 100) * c.b)
    return subsurface.stress(c, X, 0.3 * c.a, Z)


def test_bench_depth_search(benchmark):
    m, v = benchmark(depth_search)
    assert np.all(np.isfinite(m.tau_max)) and np.all(np.isfinite(v.sigma_vm))


def test_bench_section_100x100(benchmark):
    s = benchmark(section_100x100)
    assert s.sxx.shape == (100, 100)


if __name__ == "__main__":
    for fn in (depth_search, section_100x100):
        fn()
        t0 = time.perf_counter()
        fn()
        print(f"{fn.__name__}: {time.perf_counter() - t0:.3f} s")
