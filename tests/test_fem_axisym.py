"""Axisymmetric reference model of circular contacts (``ballrace.fem.axisym``).

The verification runs in the default suite (a few seconds each): the half-space mode
against Hertz / Lundberg–Palmgren, and the two-body mode of two very large balls
(a/R = 5.5e-4), where the real bodies are half-spaces to within the discretisation.
"""
from __future__ import annotations

import importlib

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from ballrace.fem import axisym


def _has_fem() -> bool:
    return all(importlib.util.find_spec(m) is not None for m in ("skfem", "gmsh"))


needs_fem = pytest.mark.skipif(not _has_fem(), reason="needs the fem extra (skfem, gmsh)")

QUANTITIES = ("a", "p_max", "approach", "tau0", "tau_x0z0", "z0", "z0_tangent_plane",
              "max_shear", "max_shear_depth", "von_mises", "von_mises_depth")


# --------------------------------------------------------------------------- formulas
@pytest.mark.parametrize("a, p0", [(1e-3, 2e9), (0.37e-3, 4.1e9), (2.5e-5, 1e8)])
def test_pressure_moment_radius_of_hertz_pressure(a, p0):
    # the moments of p0 (1 - r^2/a^2)^(1/2) by numerical quadrature (independent of the
    # closed form used in the docstring)
    def p(r):
        return p0 * np.sqrt(max(0.0, 1.0 - (r / a) ** 2))
    Q = quad(lambda r: p(r) * 2 * np.pi * r, 0.0, a, epsabs=0, epsrel=1e-13)[0]
    M2 = quad(lambda r: p(r) * r**3 * 2 * np.pi, 0.0, a, epsabs=0, epsrel=1e-13)[0]
    assert Q == pytest.approx(2 / 3 * np.pi * a**2 * p0, rel=1e-10)
    assert float(axisym.pressure_moment_radius(Q, M2)) == pytest.approx(a, rel=1e-10)


def test_pressure_moment_radius_broadcasts_and_rejects_bad_input():
    a = np.array([1e-3, 2e-3])
    out = axisym.pressure_moment_radius(2 / 3 * np.pi * a**2, 4 / 15 * np.pi * a**4)
    np.testing.assert_allclose(out, a, rtol=1e-14)
    with pytest.raises(ValueError, match="load"):
        axisym.pressure_moment_radius(0.0, 1.0)
    with pytest.raises(ValueError, match="second_moment"):
        axisym.pressure_moment_radius(1.0, -1.0)


@settings(max_examples=50, deadline=None)
@given(a=st.floats(1e-6, 1e-1), p0=st.floats(1e6, 1e10), s=st.floats(0.1, 10.0))
def test_pressure_moment_radius_scales(a, p0, s):
    # a depends on the shape of p(r) only: scaling the pressure leaves it, stretching r by
    # s (M2 ~ s^4, Q ~ s^2) multiplies it by s
    Q, M2 = 2 / 3 * np.pi * a**2 * p0, 4 / 15 * np.pi * p0 * a**4
    assert float(axisym.pressure_moment_radius(3.7 * Q, 3.7 * M2)) == pytest.approx(a, rel=1e-12)
    assert float(axisym.pressure_moment_radius(s**2 * Q, s**4 * M2)) == pytest.approx(s * a,
                                                                                  rel=1e-12)


def test_tent_integrals_are_exact_for_polynomials():
    L, n = 1.3e-3, 13
    tents = np.linspace(0.0, L, n + 1)
    I = axisym._tent_integrals(tents, lambda r: r * r / 0.01)
    # the hats sum to one: int 2 pi r dr, int r^2/0.01 2 pi r dr, int r^2 2 pi r dr over [0, L]
    assert I["m"].sum() == pytest.approx(np.pi * L**2, rel=1e-13)
    assert I["G0"].sum() == pytest.approx(np.pi * L**4 / 2 / 0.01, rel=1e-13)
    assert I["M2"].sum() == pytest.approx(np.pi * L**4 / 2, rel=1e-13)
    # one hat by quadrature: phi_3 centred at 3 dr
    dr = L / n
    phi = lambda r: max(0.0, 1.0 - abs(r - 3 * dr) / dr)  # noqa: E731
    ref = quad(lambda r: phi(r) * 2 * np.pi * r, 2 * dr, 4 * dr, points=[3 * dr],
               epsabs=0, epsrel=1e-13)[0]
    assert I["m"][3] == pytest.approx(ref, rel=1e-12)


# --------------------------------------------------------------------------- bad input
def test_bad_input():
    from ballrace.fem import api

    case = api.ball_case(12.7e-3, 2000.0)
    for kwargs, name in [({"n": 2}, "n"), ({"mode": "3-body"}, "mode"),
                         ({"gap": "cubic"}, "gap"), ({"tent_stride": 0}, "tent_stride"),
                         ({"tent_stride": 1.5}, "tent_stride"), ({"growth": 0.0}, "growth"),
                         ({"growth": 2.0}, "growth"),
                         ({"halfspace_extent": 5.0}, "halfspace_extent"),
                         ({"plane_extent": 1.0}, "plane_extent")]:
        with pytest.raises(ValueError, match=name):
            axisym.run_axisym(case, **kwargs)
    with pytest.raises(TypeError, match="mode"):
        axisym.run_axisym(case, mode=2)
    with pytest.raises(TypeError, match="tent_stride"):
        axisym.run_axisym(case, tent_stride="2")
    with pytest.raises(TypeError, match="case"):
        axisym.run_axisym("ball on ball")
    import ballrace

    brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)
    with pytest.raises(ValueError, match="circular"):
        axisym.run_axisym(api.race_case(brg, 4450.0))
    with pytest.raises(ValueError, match="load"):
        axisym.ball_on_ball(12.7e-3, -1.0)
    with pytest.raises(ValueError, match="ball_diameter"):
        axisym.ball_on_plane(0.0, 10.0)


# --------------------------------------------------------------------------- verification
@needs_fem
def test_half_space_verification():
    # elastic cylinder 40 a wide and deep under a rigid indenter of the combined curvature of
    # two 12.7 mm steel balls at 2000 N: Hertz (Johnson 1985 §4.2) and Lundberg–Palmgren
    # (1947) within 0.2 % at n = 40 (measured: a -0.02 %, tau0 +0.06 %, z0 -0.12 %,
    # max shear +0.04 %, docs/fem-axisym.md)
    r = axisym.ball_on_ball(12.7e-3, 2000.0, n=40, mode="half-space")
    for q in QUANTITIES:
        assert abs(r.error(q)) < 2e-3, (q, r.error(q))
    assert r.a == pytest.approx(float(r.analytic.a), rel=2e-3)
    assert r.z0_tangent_plane == r.z0            # a flat lower body: one definition of depth
    assert r.n_tents == 53 and r.profiles["complementarity"] < 1e-8
    with pytest.raises(ValueError, match="quantity"):
        r.error("z1")
    with pytest.raises(ValueError, match="against"):
        r.error("z0", against="exactly")


@needs_fem
def test_half_space_error_falls_with_h():
    errs = {n: axisym.ball_on_ball(12.7e-3, 500.0, n=n, mode="half-space") for n in (10, 20)}
    for q in ("a", "p_max", "tau0", "max_shear"):
        assert abs(errs[20].error(q)) < 0.5 * abs(errs[10].error(q)), q


@needs_fem
def test_two_body_large_balls_tend_to_hertz():
    # D = 1.27 m at 20 N: a/R = 5.5e-4, where the curved-body departure from half-spaces
    # (about -37 % of a/R for the max shear, docs/fem-axisym.md) is 0.02 %: the two-body
    # model of the real spheres reproduces Hertz / LP to its discretisation error
    r = axisym.ball_on_ball(1.27, 20.0, n=40)
    assert float(r.analytic.a) / 0.635 == pytest.approx(5.5e-4, rel=0.02)
    for q in QUANTITIES:
        assert abs(r.error(q)) < 2e-3, (q, r.error(q))


@needs_fem
@pytest.mark.slow
def test_two_body_reference_is_converged():
    # the reference of docs/fem-axisym.md: two 12.7 mm balls at 2000 N (a/R = 0.055), n = 40
    # and n = 60 agree to 0.1 pp in every quantity (measured: tau0 0.048 pp, z0 0.021 pp,
    # max shear 0.008 pp, its depth 0.019 pp, a 0.013 pp)
    r1, r2 = (axisym.ball_on_ball(12.7e-3, 2000.0, n=n) for n in (40, 60))
    for q in QUANTITIES:
        assert abs(r1.error(q) - r2.error(q)) < 1e-3, (q, r1.error(q), r2.error(q))
    # and the converged field departs from Hertz's half-spaces (ball curvature): the
    # on-axis max shear is lower and deeper than Hertz's by more than the verification error
    assert r2.error("max_shear") < -0.01 and r2.error("max_shear_depth") > 0.02
