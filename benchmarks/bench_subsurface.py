"""Subsurface stresses: vectorized on-axis maxima and full-field sections, with and without
a tangential traction.

Run with ``make bench`` (pytest-benchmark) or by hand::

    .venv/bin/python benchmarks/bench_subsurface.py

Workloads: the on-axis Tresca and von Mises maxima (depth search) of 10^4 elliptical
contacts of radius ratios 1 ... 200; the full stress tensor on a 100 x 100 section of a
k = 20 contact (Love's potentials); the same section of the ellipse, of a circle and of a
line contact with a traction coefficient 0.3, each next to its frictionless peer measured
in the same run (the goal: an ellipse section with traction in <= 0.5 s; the circle and
the line at the speed of their frictionless fields, printed as ratios).
"""
from __future__ import annotations

import numpy as np
import pytest

import ballrace
from ballrace.analytic import hertz, subsurface
from core_table import best

E_PRIME = 219.78e9


def depth_search():
    Q = np.linspace(100, 5000, 10**4)
    c = hertz.elliptical_contact(Q, 0.005, np.logspace(np.log10(0.005), 0, 10**4), E_PRIME)
    return subsurface.max_shear(c), subsurface.von_mises(c)


def section_100x100():
    c = hertz.elliptical_contact(2000.0, 0.005, 0.1, E_PRIME)
    X, Z = np.meshgrid(np.linspace(-3, 3, 100) * c.b, np.linspace(0, 3, 100) * c.b)
    return subsurface.stress(c, X, 0.3 * c.a, Z)


def _section(Ry, traction):
    c = hertz.elliptical_contact(2000.0, 0.005, Ry, E_PRIME)
    X, Z = np.meshgrid(np.linspace(-3, 3, 100) * c.b, np.linspace(0, 3, 100) * c.b)
    return subsurface.stress(c, X, 0.0, Z, traction=traction)


def ellipse_section_frictionless():
    return _section(0.1, 0.0)


def ellipse_section_traction():
    return _section(0.1, 0.3)


def circle_section_frictionless():
    return _section(0.005, 0.0)


def circle_section_traction():
    return _section(0.005, 0.3)


def _line(traction):
    lc = hertz.line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
    X, Z = np.meshgrid(np.linspace(-3, 3, 100) * lc.b, np.linspace(0, 3, 100) * lc.b)
    return subsurface.line_stress(lc, X, Z, traction=traction)


def line_section_frictionless():
    return _line(0.0)


def line_section_traction():
    return _line(0.3)


def test_bench_depth_search(benchmark):
    m, v = benchmark(depth_search)
    assert np.all(np.isfinite(m.tau_max)) and np.all(np.isfinite(v.sigma_vm))


def test_bench_section_100x100(benchmark):
    s = benchmark(section_100x100)
    assert s.sxx.shape == (100, 100)


SECTIONS = [f"{shape}_section_{kind}" for shape in ("ellipse", "circle", "line")
            for kind in ("frictionless", "traction")]


@pytest.mark.parametrize("name", SECTIONS)
def test_bench_section(benchmark, name):
    assert benchmark(globals()[name]).sxx.shape == (100, 100)


if __name__ == "__main__":
    for fn in (depth_search, section_100x100):
        print(f"{fn.__name__}: {best(fn, 1, warmup=True):.3f} s")
    for name in ("ellipse", "circle", "line"):
        t0 = best(globals()[f"{name}_section_frictionless"], warmup=True)
        t1 = best(globals()[f"{name}_section_traction"], warmup=True)
        print(f"{name} 100 x 100: frictionless {t0:.4f} s, traction 0.3 {t1:.4f} s, "
              f"ratio {t1 / t0:.2f}")
