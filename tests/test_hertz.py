"""Hertz contact: published values, independent derivations and invariants.

Sources of expected values are given with each test.  Tolerances: closed-form
identities to 1e-12; values quoted to 4-5 significant figures in the literature to
half a unit of their last digit.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import hertz
from ballrace.analytic.materials import effective_modulus, johnson_modulus

from mpref import hertz_exact, k_exact, potential_checks

STEEL = ballrace.Material(E=200e9, nu=0.3)


# --------------------------------------------------------------------- published values
def test_sphere_on_flat_matches_johnson_closed_form():
    """Johnson (1985) eqs. 4.22-4.23: a = (3QR/4E*)^1/3, delta = a^2/R, p0 = 3Q/(2 pi a^2)."""
    Q, R = 2000.0, 6.35e-3
    c = hertz.point_contact(Q, R, R, np.inf, np.inf, STEEL)
    Es = johnson_modulus(STEEL)
    a = (3 * Q * R / (4 * Es)) ** (1 / 3)
    assert c.k == 1.0
    assert c.a == pytest.approx(a, rel=1e-13)
    assert c.b == pytest.approx(a, rel=1e-13)
    assert c.approach == pytest.approx(a * a / R, rel=1e-13)
    assert c.p_max == pytest.approx(3 * Q / (2 * np.pi * a * a), rel=1e-13)


def test_code_aster_ssnv104_two_hemispheres():
    """Code_Aster SSNV104: R = 50 mm, E = 20 000 MPa, nu = 0.3, total approach 4 mm
    -> a = 10 mm, p0 = 2798.3 MPa (published to 5 figures: rel 2e-5)."""
    m = ballrace.Material(E=20000e6, nu=0.3)
    Ep = effective_modulus(m)
    Q = hertz.load_from_approach(4e-3, 25e-3, 25e-3, Ep)
    c = hertz.point_contact(Q, 50e-3, 50e-3, 50e-3, 50e-3, m)
    assert c.a == pytest.approx(10e-3, rel=1e-12)
    assert c.p_max == pytest.approx(2798.3e6, rel=2e-5)
    assert c.approach == pytest.approx(4e-3, rel=1e-12)


def test_moose_hertz_spherical():
    """MOOSE contact test hertz_spherical: R1 = R2 = 2, nu = 0.25, E = 1.40625e7,
    F = 10 000 -> a = 0.1, approach = 0.01 (exact in the test's design)."""
    with pytest.warns(UserWarning, match="below any bearing material"):   # not steel
        m = ballrace.Material(E=1.40625e7, nu=0.25)
    c = hertz.point_contact(10000.0, 2.0, 2.0, 2.0, 2.0, m)
    assert c.a == pytest.approx(0.1, rel=1e-12)
    assert c.approach == pytest.approx(0.01, rel=1e-12)


def test_nafems_d3613_line_contact():
    """NAFEMS FENET D3613: cylinder (E = 70 GPa) on block (E = 210 GPa), nu = 0.3,
    35 kN/mm, R = 50 mm -> p0 = 3585 MPa, half-width 6.21 mm (published to 4 / 3 figures)."""
    c = hertz.line_contact(35e6, 50e-3, np.inf, ballrace.Material(70e9, 0.3),
                           ballrace.Material(210e9, 0.3))
    assert c.p_max == pytest.approx(3585e6, rel=1.5e-4)
    assert c.b == pytest.approx(6.21e-3, rel=1e-3)
    assert c.p_mean * 2 * c.b == pytest.approx(35e6, rel=1e-14)


def test_effective_modulus_is_twice_johnson():
    """Hamrock & Dowson (1981) eq. 3.4 E' vs Johnson (1985) E*: E' = 2E*."""
    ceramic = ballrace.SILICON_NITRIDE
    ep = effective_modulus(STEEL, ceramic)
    assert ep == pytest.approx(2 / ((1 - 0.09) / 200e9 + (1 - 0.27**2) / 310e9), rel=1e-15)
    assert johnson_modulus(STEEL, ceramic) == pytest.approx(ep / 2, rel=1e-15)


# --------------------------------------------------------------------- exact ellipticity
ALPHAS = [1.0 + 1e-9, 1.0 + 1e-6, 1.001, 1.3, 2.0, 3.7, 10.0, 31.6, 100.0, 562.0, 1e3, 5e3, 1e4]


@pytest.mark.parametrize("alpha", ALPHAS)
def test_ellipticity_matches_mpmath_to_1e12(alpha):
    """k(alpha) against an mpmath root of Hertz's relation at 30 digits (H&D 1981 eq. 3.14)."""
    k, K, E = hertz.ellipticity(alpha)
    assert k == pytest.approx(k_exact(alpha), rel=1e-12, abs=0)


def test_ellipticity_random_vector_matches_mpmath():
    rng = np.random.default_rng(7)
    alpha = 10 ** rng.uniform(0, 4, 40)
    k, _, _ = hertz.ellipticity(alpha)
    ref = np.array([k_exact(x) for x in alpha])
    assert np.max(np.abs(k / ref - 1)) < 1e-12


def test_ellipticity_below_one_swaps_axes():
    k1, K1, E1 = hertz.ellipticity(0.1)
    k2, K2, E2 = hertz.ellipticity(10.0)
    assert (k1, K1, E1) == (k2, K2, E2)


@pytest.mark.parametrize("alpha", [1.0, 1.7, 12.0, 250.0, 4000.0])
def test_exact_contact_matches_mpmath_formulas(alpha):
    """All outputs against the same formulas evaluated independently at 30 digits."""
    c = hertz.elliptical_contact(3000.0, 5e-3, 5e-3 * alpha, 2.2e11)
    ref = hertz_exact(3000.0, 5e-3, 5e-3 * alpha, 2.2e11)
    for q in ("k", "a", "b", "approach", "p_max"):
        assert float(getattr(c, q)) == pytest.approx(ref[q], rel=1e-11), q


@pytest.mark.parametrize("alpha", [1.0, 4.0, 37.0, 300.0])
def test_contact_satisfies_elasticity_by_quadrature(alpha):
    """Independent derivation: the Hertz ellipse's surface potential (Johnson 1985 §3.7)
    integrated numerically must reproduce the approach and both gap curvatures."""
    c = hertz.elliptical_contact(500.0, 4e-3, 4e-3 * alpha, 2.2e11)
    chk = potential_checks(float(c.a), float(c.b), float(c.p_max), 2.2e11)
    assert chk["approach"] == pytest.approx(float(c.approach), rel=1e-10)
    assert chk["R_major"] == pytest.approx(4e-3 * alpha, rel=1e-10)
    assert chk["R_minor"] == pytest.approx(4e-3, rel=1e-10)


# --------------------------------------------------------------------- approximations
@pytest.mark.parametrize("method", hertz.METHODS[1:])
@pytest.mark.parametrize("alpha_max", [10.0, 100.0, 1e4])
def test_approximations_within_documented_error(method, alpha_max):
    """Brewe & Hamrock (1977) and Hamrock & Brewe (1983) stay inside the documented
    bounds (APPROXIMATION_ERROR) on a grid offset from the one that produced them."""
    rng = np.random.default_rng(3)
    alpha = np.concatenate([[1.0, alpha_max], 10 ** rng.uniform(0, np.log10(alpha_max), 3000)])
    err = hertz.approximation_errors(alpha, method)
    bound = hertz.APPROXIMATION_ERROR[method][alpha_max]
    for q, e in err.items():
        assert np.max(np.abs(e)) <= bound[q], (q, float(np.max(np.abs(e))))


def test_approximation_bounds_are_tight():
    """The documented bounds are not padded: each is within 0.1 % of the worst error seen."""
    for method, table in hertz.APPROXIMATION_ERROR.items():
        for alpha_max, bounds in table.items():
            err = hertz.approximation_errors(np.logspace(0, np.log10(alpha_max), 4001), method)
            for q, e in err.items():
                assert bounds[q] - np.max(np.abs(e)) < 1.0e-3, (method, alpha_max, q)


# --------------------------------------------------------------------- invariants
radius = st.floats(1e-4, 1.0)
ratio = st.floats(1.0, 1e4)
load = st.floats(1e-3, 1e6)


@settings(max_examples=60, deadline=None)
@given(Q=load, Rx=radius, alpha=ratio, s=st.floats(1.01, 1000.0))
def test_power_laws_in_load(Q, Rx, alpha, s):
    """a, b ∝ Q^(1/3); delta ∝ Q^(2/3); p_max ∝ Q^(1/3) (Hertz 1882)."""
    c1 = hertz.elliptical_contact(Q, Rx, Rx * alpha, 2.2e11)
    c2 = hertz.elliptical_contact(Q * s, Rx, Rx * alpha, 2.2e11)
    assert c2.a / c1.a == pytest.approx(s ** (1 / 3), rel=1e-12)
    assert c2.b / c1.b == pytest.approx(s ** (1 / 3), rel=1e-12)
    assert c2.approach / c1.approach == pytest.approx(s ** (2 / 3), rel=1e-12)
    assert c2.p_max / c1.p_max == pytest.approx(s ** (1 / 3), rel=1e-12)
    assert c1.k == c2.k


@settings(max_examples=60, deadline=None)
@given(Q=load, Rx=radius, alpha=st.floats(1e-4, 1e4))
def test_a_ge_b_and_axes_follow_the_larger_radius(Q, Rx, alpha):
    c = hertz.elliptical_contact(Q, Rx, Rx * alpha, 2.2e11)
    d = hertz.elliptical_contact(Q, Rx * alpha, Rx, 2.2e11)
    assert c.a >= c.b and c.k >= 1.0
    for q in ("a", "b", "approach", "p_max", "stiffness"):
        assert getattr(c, q) == pytest.approx(getattr(d, q), rel=1e-13)
    assert c.semi_axis_x == pytest.approx(d.semi_axis_y, rel=1e-13)


@settings(max_examples=40, deadline=None)
@given(Q=load, Rx=radius, alpha=st.floats(1.0, 1e3))
def test_pressure_integrates_to_load(Q, Rx, alpha):
    """∫ p dA = Q by 2-D Gauss quadrature of HertzContact.pressure in elliptical polars."""
    c = hertz.elliptical_contact(Q, Rx, Rx * alpha, 2.2e11)
    # elliptical polars x = ax r cos(th), y = ay r sin(th), dA = ax ay r dr dth; with
    # r = sqrt(1 - t^2) the sqrt edge becomes smooth: r dr = -t dt
    t, wt = np.polynomial.legendre.leggauss(20)
    t, wt = 0.5 * (t + 1), 0.5 * wt
    th = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    rr = np.sqrt(1 - t * t)
    x = c.semi_axis_x * rr[None, :] * np.cos(th)[:, None]
    y = c.semi_axis_y * rr[None, :] * np.sin(th)[:, None]
    p = c.pressure(x, y)
    F = c.semi_axis_x * c.semi_axis_y * (2 * np.pi / 64) * np.sum(p * (t * wt)[None, :])
    assert F == pytest.approx(Q, rel=1e-10)
    assert np.all(p >= 0)


@settings(max_examples=60, deadline=None)
@given(Q=load, Rx=radius, alpha=ratio)
def test_load_from_approach_round_trip(Q, Rx, alpha):
    """Q(delta(Q)) = Q (Hamrock & Dowson 1981 eq. 3.33)."""
    c = hertz.elliptical_contact(Q, Rx, Rx * alpha, 2.2e11)
    assert hertz.load_from_approach(c.approach, Rx, Rx * alpha, 2.2e11) == pytest.approx(Q, rel=1e-12)
    assert c.stiffness == pytest.approx(hertz.contact_stiffness(Rx, Rx * alpha, 2.2e11), rel=1e-15)


def test_continuity_at_circular_limit():
    alpha = 1.0 + np.array([0.0, 1e-12, 1e-9, 1e-6, 1e-4])
    c = hertz.elliptical_contact(1000.0, 0.01, 0.01 * alpha, 2.2e11)
    # k - 1 is linear in alpha - 1 near the circle; every output varies smoothly
    for q in ("a", "b", "approach", "p_max", "ellipk", "ellipe"):
        v = np.asarray(getattr(c, q))
        assert np.all(np.abs(v / v[0] - 1) <= 2 * (alpha - 1) + 1e-15), q
    slope = (c.k[1:] - 1) / (alpha[1:] - 1)
    assert np.allclose(slope[1:], slope[-1], rtol=1e-3)


def test_broadcasting_and_zero_load():
    Q = np.array([[0.0], [10.0], [1000.0]])
    Ry = np.array([0.01, 0.1, 1.0])
    c = hertz.elliptical_contact(Q, 0.005, Ry, 2.2e11)
    assert c.a.shape == (3, 3)
    assert np.all(c.a[0] == 0) and np.all(c.p_max[0] == 0) and np.all(c.approach[0] == 0)
    assert np.all(np.isfinite(c.p_max))
    assert c.stiffness.shape == (3, 3)


def test_simplified_methods_agree_at_their_fit_point():
    c0 = hertz.elliptical_contact(100.0, 0.005, 0.1, 2.2e11)
    for m in hertz.METHODS[1:]:
        c = hertz.elliptical_contact(100.0, 0.005, 0.1, 2.2e11, method=m)
        assert c.method == m
        assert abs(c.a / c0.a - 1) < hertz.APPROXIMATION_ERROR[m][100.0]["a"]


# --------------------------------------------------------------------- bad input
@pytest.mark.parametrize("kwargs, match", [
    (dict(load=-1.0), "load must be >= 0"),
    (dict(load=np.inf), "load must be finite"),
    (dict(load=np.nan), "load must be finite"),
    (dict(rx1=0.0), "rx1 must be non-zero"),
    (dict(ry2=-0.004), "curvature sum in the y plane"),   # concave more curved than the ball
    (dict(ry1=np.inf, ry2=np.inf), "line"),
    (dict(method="hertz"), "method must be one of"),
])
def test_bad_input_names_the_argument(kwargs, match):
    args = dict(load=100.0, rx1=0.005, ry1=0.005, rx2=np.inf, ry2=-0.0052, method="exact")
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        hertz.point_contact(args["load"], args["rx1"], args["ry1"], args["rx2"], args["ry2"],
                            STEEL, STEEL, method=args["method"])


@pytest.mark.parametrize("kwargs, match", [
    (dict(E=0.0, nu=0.3), "E must be > 0"),
    (dict(E=-1e9, nu=0.3), "E must be > 0"),
    (dict(E=200e9, nu=0.5), r"nu must be in \(-1, 0.5\)"),
    (dict(E=200e9, nu=-1.0), r"nu must be in \(-1, 0.5\)"),
    (dict(E=np.nan, nu=0.3), "E must be finite"),
])
def test_bad_material(kwargs, match):
    with pytest.raises(ValueError, match=match):
        ballrace.Material(**kwargs)


def test_material_type_checked():
    with pytest.raises(TypeError, match="material1 must be a ballrace.Material"):
        hertz.point_contact(1.0, 1.0, 1.0, 1.0, 1.0, 200e9)


def test_index_of_bad_entry_reported():
    with pytest.raises(ValueError, match=r"index 2"):
        hertz.elliptical_contact([1.0, 2.0, -3.0], 0.01, 0.02, 2e11)
