"""Roller profiles: values re-derived by hand, identities between the profiles, bad input."""
import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from ballrace.analytic.roller import profile as rp

#: A 12 x 12 mm roller on steel (E' = 2 / (2 (1 - 0.3^2) / 208 GPa) = 228.6 GPa), R = 5 mm.
EP = 208e9 / (1 - 0.3 ** 2)
CTX = rp.ProfileContext(length=0.012, diameter=0.012, E_prime=EP, R=0.005, load=5000.0)


def test_iso_short_roller_by_hand():
    # ISO/TS 16281 default profile, L_we <= 2.5 D_we: 0.00035 D ln[1/(1 - (2x/L)^2)]
    # x = 5 mm of L = 12 mm: (2x/L)^2 = 25/36, ln(36/11) = 1.18562..., times 4.2e-6 m
    assert rp.ISO().drop(0.005, CTX) == pytest.approx(4.2e-6 * math.log(36 / 11), rel=1e-12)
    assert rp.ISO().drop(0.0, CTX) == 0.0


def test_iso_long_roller_is_flat_in_the_middle_and_matches_short_ends():
    # L = 40 mm, D = 12 mm: 10 mm straight middle, 30 mm-roller ends
    ctx = rp.ProfileContext(length=0.040, diameter=0.012)
    x = np.array([0.0, 0.004, 0.005])
    assert np.all(rp.ISO().drop(x, ctx) == 0.0)
    short = rp.ProfileContext(length=0.030, diameter=0.012)
    # 2 mm beyond the flat part on the long roller = 2 mm from the centre of the short one
    assert rp.ISO().drop(0.007, ctx) == pytest.approx(rp.ISO().drop(0.002, short), rel=1e-12)


def test_crowned_is_a_circle_tangent_to_the_flat():
    p = rp.Crowned(flat_length=0.006, crown_radius=2.0)
    s = 0.002                                  # 2 mm into the crown: R - sqrt(R^2 - s^2)
    assert p.drop(0.003 + s, CTX) == pytest.approx(2.0 - math.sqrt(4.0 - s * s), rel=1e-12)
    assert p.drop(-0.005, CTX) == p.drop(0.005, CTX)
    assert p.drop(0.003, CTX) == 0.0


def test_lundberg_prefactor_is_q_over_pi_e_star():
    # Lundberg 1939: (q / (pi E*)) ln[1/(1 - (2x/L)^2)], q = Q/L, E* = E'/2
    q, Es = 5000.0 / 0.012, EP / 2
    x = 0.004
    expect = q / (math.pi * Es) * math.log(1 / (1 - (2 * x / 0.012) ** 2))
    assert rp.Lundberg().drop(x, CTX) == pytest.approx(expect, rel=1e-12)
    # its own design load overrides the context's
    assert rp.Lundberg(2500.0).drop(x, CTX) == pytest.approx(expect / 2, rel=1e-12)


def test_johns_gohar_tends_to_lundberg_and_is_finite_at_the_end():
    x = np.linspace(-0.0059, 0.0059, 11)
    tiny = rp.ProfileContext(length=0.012, diameter=0.012, E_prime=EP, R=1e-12, load=5000.0)
    np.testing.assert_allclose(rp.JohnsGohar().drop(x, tiny), rp.Lundberg().drop(x, tiny),
                               rtol=1e-9)
    # at the end: (2 Q/(pi L E')) ln(1/(2b/L)^2) = (4 Q/(pi L E')) ln(L/(2b))
    b = math.sqrt(8 * 5000.0 * 0.005 / (math.pi * 0.012 * EP))
    end = 4 * 5000.0 / (math.pi * 0.012 * EP) * math.log(0.012 / (2 * b))
    near = rp.JohnsGohar().drop(0.006 * (1 - 1e-12), CTX)
    assert near == pytest.approx(end, rel=1e-6)
    assert rp.JohnsGohar().drop(0.005, CTX) < rp.Lundberg().drop(0.005, CTX)


def test_no_roller_at_and_beyond_the_ends():
    for name in rp.PROFILE_NAMES:
        d = rp.as_profile(name).drop(np.array([-0.007, -0.006, 0.006, 0.01]), CTX)
        assert np.all(np.isinf(d)), name


def test_table_mirrors_and_interpolates():
    t = rp.Table([0.0, 0.003, 0.006], [0.0, 1e-6, 4e-6])
    assert t.drop(0.0045, CTX) == pytest.approx(2.5e-6, rel=1e-12)
    assert t.drop(-0.0045, CTX) == t.drop(0.0045, CTX)
    assert rp.as_profile(([0.0, 0.003, 0.006], [0.0, 1e-6, 4e-6])) == t
    asym = rp.Table([-0.006, 0.0, 0.006], [2e-6, 0.0, 4e-6])
    assert asym.drop(-0.003, CTX) == pytest.approx(1e-6)
    assert asym.drop(0.003, CTX) == pytest.approx(2e-6)


@pytest.mark.parametrize("x, drop, match", [
    ([0.0, 0.003, 0.003], [0, 1e-6, 2e-6], "strictly increasing"),
    ([0.0, 0.003, 0.006], [0, -1e-6, 2e-6], ">= 0"),
    ([0.001, 0.003, 0.006], [0, 1e-6, 2e-6], "start at the roller centre"),
    ([0.0, 0.003], [0.0], "same length"),
])
def test_table_bad_input(x, drop, match):
    with pytest.raises(ValueError, match=match):
        rp.Table(x, drop)


def test_table_must_fit_the_roller():
    with pytest.warns(UserWarning), pytest.raises(ValueError, match="outside the roller.*millimetres"):
        rp.Table([0.0, 3.0, 6.0], [0.0, 1e-6, 4e-6]).drop(0.0, CTX)   # mm typed as m
    with pytest.raises(ValueError, match="give points up to within 5 %"):
        rp.Table([0.0, 0.003, 0.005], [0.0, 1e-6, 4e-6]).drop(0.0, CTX)
    with pytest.raises(ValueError, match="drops are in metres"):
        rp.Table([0.0, 0.003, 0.006], [0.0, 1e-3, 4e-3]).drop(0.0, CTX)


def test_table_in_millimetres_warns():
    with pytest.warns(UserWarning, match="profile x = 6 m .* millimetres"):
        rp.Table([0.0, 3.0, 6.0], [0.0, 1e-6, 4e-6])


def test_crowned_bad_input():
    with pytest.raises(ValueError, match="crown_radius must exceed"):
        rp.Crowned(0.0, 0.004).drop(0.0, CTX)
    with pytest.raises(ValueError, match="flat_length must be shorter"):
        rp.Crowned(0.012, 2.0).drop(0.0, CTX)
    with pytest.raises(ValueError, match="crown_radius"):
        rp.Crowned(0.0, -1.0)


def test_names_and_errors():
    assert isinstance(rp.as_profile(" ISO "), rp.ISO)
    assert isinstance(rp.as_profile("johns_gohar"), rp.JohnsGohar)
    with pytest.raises(ValueError, match="one of straight, iso, lundberg, johns-gohar"):
        rp.as_profile("parabolic")
    with pytest.raises(ValueError, match="Crowned"):
        rp.as_profile("crowned")
    with pytest.raises(TypeError, match="profile must be"):
        rp.as_profile(3.0)
    bare = rp.ProfileContext(length=0.012, diameter=0.012)
    with pytest.raises(ValueError, match="lundberg profile needs load, E_prime"):
        rp.Lundberg().drop(0.0, bare)
    with pytest.raises(ValueError, match="length"):
        rp.ProfileContext(length=-0.012, diameter=0.012)


@given(st.floats(0.0, 0.99), st.floats(0.0, 0.99),
       st.sampled_from(["straight", "iso", "lundberg", "johns-gohar"]))
def test_named_profiles_are_even_nonnegative_and_grow_outwards(u1, u2, name):
    p = rp.as_profile(name)
    lo, hi = sorted((u1, u2))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        a, b = p.drop(np.array([lo, hi]) * 0.006, CTX)
        assert p.drop(-hi * 0.006, CTX) == b
    assert 0.0 <= a <= b
