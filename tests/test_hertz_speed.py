"""The fast exact Hertz kernel against independent references.

* k, K and E come from piecewise polynomials of alpha_r (``hertz._poly_table``): on a
  dense sample of radius ratios 1 ... 1e6, both orientations, they agree with a 30-digit
  mpmath root of Hertz's relation (Hamrock & Dowson 1981 eq. 3.14) and mpmath's complete
  elliptic integrals (reference: one Newton step at 30 digits from the value under test,
  which corrects any error in it to first order, so a wrong value cannot pass).
* The relation check is the guarantee: a corrupted table is caught and Newton's method
  (SciPy's integrals) answers instead.
* The cube root (bit-level start, Halley, Newton) against mpmath, exactly 0 at 0, and its
  scalar twin bit for bit.
* The kernel's results satisfy the textbook formulas; small arrays (contact by contact)
  and a broadcast modulus give the kernel's bits; empty arrays give empty results.
* Plain float64 inputs, accepted by a few reductions, keep every documented error.
* The simplified methods are unchanged by the blocking of large arrays.
"""
import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballrace.analytic import hertz

mp.mp.dps = 30


def _alpha_of_k(k):
    """Hertz's relation alpha_r(k) = (k^2 E - K)/(K - E), m = 1 - 1/k^2, in mpmath."""
    m = 1 - 1 / k**2
    K, E = mp.ellipk(m), mp.ellipe(m)
    return (k**2 * E - K) / (K - E)


def _reference(alpha: float, k0: float):
    """k, K, E at 30 digits for the float alpha: one Newton step from k0 in mpmath."""
    a = mp.mpf(alpha)
    if a == 1:
        return mp.mpf(1), mp.pi / 2, mp.pi / 2
    k = mp.mpf(k0)
    h = k * mp.mpf("1e-12")
    slope = (_alpha_of_k(k + h) - _alpha_of_k(k - h)) / (2 * h)       # error ~1e-24
    k = k - (_alpha_of_k(k) - a) / slope
    m = 1 - 1 / k**2
    return k, mp.ellipk(m), mp.ellipe(m)


def _dense_ratios():
    """A random point in each of the table's 5100 intervals up to alpha_r = 1e6, plus
    ratios within 1e-15 ... 1e-1 of the circle, the circle itself, and 100 ratios 1e6 ...
    1e8."""
    rng = np.random.default_rng(2024)
    n = ((int(np.array(1e6).view(np.int64)) >> hertz._SHIFT) - hertz._IDX0) + 1
    alpha = hertz._interval_points(np.array([0.0]), n).ravel()
    width = np.ldexp(1.0, (np.arange(n) >> hertz._OCT_BITS) - hertz._OCT_BITS)
    pts = [alpha + width * rng.random(n)]
    pts.append(1.0 + 10 ** rng.uniform(-15, -1, 200))
    pts.append(10 ** rng.uniform(6, 8, 100))                # sparser to the range's end
    pts.append([1.0, 1e6, 1e8])
    return np.concatenate([np.ravel(p) for p in pts])


ALPHA = _dense_ratios()


@pytest.fixture(scope="module")
def dense_reference():
    ks = hertz.ellipticity(ALPHA)[0]
    return [_reference(a, k) for a, k in zip(ALPHA, ks)]


@pytest.mark.parametrize("orientation", ["Ry > Rx", "Rx > Ry"])
def test_tabulated_k_K_E_match_mpmath_densely(orientation, dense_reference):
    # a point in each of the table's intervals + 200 near the circle: the tables are
    # accurate to a few rounding errors (measured max 1.1e-15), asserted at 2e-15 (SciPy's
    # own ellipk/ellipe: 2.3e-16)
    Rx, Ry = (1.0, ALPHA) if orientation == "Ry > Rx" else (ALPHA, 1.0)   # ratio exact
    c = hertz.elliptical_contact(1.0, Rx, Ry, 2e11)
    worst = {}
    for q, i in (("k", 0), ("ellipk", 1), ("ellipe", 2)):
        got = np.asarray(getattr(c, q))
        err = [abs(float(mp.mpf(float(g)) / ref[i] - 1)) for g, ref in zip(got, dense_reference)]
        worst[q] = max(err)
    assert max(worst.values()) <= 2e-15, worst


def test_ellipticity_function_matches_mpmath_densely(dense_reference):
    k, K, E = hertz.ellipticity(ALPHA)
    for j, (kk, KK, EE) in enumerate(zip(k, K, E)):
        rk, rK, rE = dense_reference[j]
        for got, ref in ((kk, rk), (KK, rK), (EE, rE)):
            assert abs(float(mp.mpf(float(got)) / ref - 1)) <= 2e-15, ALPHA[j]


def test_relation_check_catches_a_corrupted_table(monkeypatch, caplog):
    # spoil k on one interval (alpha_r in [10, 10.03125)) by 1e-9 relative: the check of
    # Hertz's relation must see it and Newton's method must answer, in both paths
    caplog.set_level("DEBUG", logger="ballrace.analytic.hertz")
    coefs, s_max, _ = hertz._poly_table()
    i = (int(np.array(10.0).view(np.int64)) >> hertz._SHIFT) - hertz._IDX0
    bad_k = coefs[0].copy()
    bad_k[0, i] *= 1 + 1e-9
    bad = ((bad_k, coefs[1], coefs[2]), s_max, hertz._pair(bad_k, coefs[2]))
    monkeypatch.setattr(hertz, "_poly_table", lambda: bad)
    rows = hertz._scalar_rows(bad[0], s_max)
    monkeypatch.setattr(hertz, "_scalar_table", lambda: rows)
    alpha = np.array([10.0, 10.01, 10.03, 3.0])
    k, K, E = hertz._solve_k(alpha)
    assert "ellipticity: 3 values polished by Newton" in caplog.text
    for a, kk, KK, EE in zip(alpha, k, K, E):
        rk, rK, rE = _reference(a, kk)
        assert abs(float(mp.mpf(kk) / rk - 1)) < 1e-12
        assert abs(float(mp.mpf(KK) / rK - 1)) < 1e-12 and abs(float(mp.mpf(EE) / rE - 1)) < 1e-12
        ks, Ks, Es = hertz._solve_k_scalar(float(a))
        assert abs(ks / kk - 1) < 1e-13 and abs(Ks / KK - 1) < 1e-13


def test_cube_root_matches_mpmath():
    rng = np.random.default_rng(5)
    c = np.concatenate([10 ** rng.uniform(-120, 120, 3000), [1.0, 8.0, 27.0, 2.0**-300],
                        [np.nextafter(1.0, 2.0), np.nextafter(8.0, 0.0)]])
    y = np.empty_like(c)
    w = [np.empty_like(c) for _ in range(2)]
    hertz._cbrt_kernel(c, y, *w, np.empty(c.size, dtype=np.int64))
    err = max(abs(float(mp.mpf(float(v)) / mp.cbrt(mp.mpf(float(x))) - 1)) for v, x in zip(y, c))
    assert err <= 4e-16                                   # about one rounding error
    assert y[-6] == 1.0 and y[-5] == 2.0 and y[-4] == 3.0 and y[-3] == 2.0**-100
    z = np.array([0.0, 5.0, 0.0])
    hertz._cbrt_kernel(z, y[:3], w[0][:3], w[1][:3], np.empty(3, dtype=np.int64))
    assert y[0] == 0.0 and y[2] == 0.0 and abs(y[1] / 5.0 ** (1 / 3) - 1) < 4e-16


@settings(max_examples=300, deadline=None)
@given(c=st.one_of(st.just(0.0), st.floats(1e-120, 1e120)))
def test_cube_root_scalar_equals_array(c):
    y = np.empty(1)
    hertz._cbrt_kernel(np.array([c]), y, np.empty(1), np.empty(1), np.empty(1, dtype=np.int64))
    assert hertz._cbrt_scalar(c) == y[0]


@pytest.mark.parametrize("method", hertz.METHODS[1:])
def test_simplified_methods_blocked_equals_small_arrays(method):
    # large 1-d arrays run the simplified formulas block by block: the same bits
    rng = np.random.default_rng(12)
    n = 2 * hertz._BLOCK_SIMPLIFIED + 777
    Rx = 10 ** rng.uniform(-3, -1, n)
    Ry = Rx * 10 ** rng.uniform(-4, 4, n)
    Q = 10 ** rng.uniform(0, 5, n)
    big = hertz.elliptical_contact(Q, Rx, Ry, 2.1e11, method=method)
    for i in (0, n // 2, n - 300):
        sl = slice(i, i + 300)
        small = hertz.elliptical_contact(Q[sl], Rx[sl], Ry[sl], 2.1e11, method=method)
        for f in ("k", "a", "b", "approach", "p_max", "stiffness", "ellipk", "ellipe"):
            assert np.array_equal(getattr(big, f)[sl], getattr(small, f)), f


def test_modulus_array_equals_broadcast_scalar():
    # E' as one broadcast number enters the kernel as a float, an array of E' elementwise:
    # the same operations, the same bits
    rng = np.random.default_rng(13)
    n = 1000
    Rx = 10 ** rng.uniform(-3, -1, n)
    Ry = Rx * 10 ** rng.uniform(-4, 4, n)
    Q = 10 ** rng.uniform(0, 5, n)
    Q[::7] = 0.0
    a = hertz.elliptical_contact(Q, Rx, Ry, 2.1e11)
    b = hertz.elliptical_contact(Q, Rx, Ry, np.full(n, 2.1e11))
    for f in ("k", "a", "b", "approach", "p_max", "stiffness", "ellipk", "ellipe"):
        assert np.array_equal(getattr(a, f), getattr(b, f)), f
    assert np.all(a.a[::7] == 0) and np.all(a.p_max[::7] == 0) and np.all(a.approach[::7] == 0)


@pytest.mark.parametrize("bad, match", [
    (dict(load=np.array([1.0, np.nan])), "load must be finite"),
    (dict(load=np.array([1.0, -2.0])), "load must be >= 0"),
    (dict(load=np.array([1.0, 1e31])), "load must have a physical magnitude"),
    (dict(load=np.array([0.0, 1e-31])), "load must have a physical magnitude"),
    (dict(load=np.array([0.0, -0.0, -1e-300])), "load must be >= 0"),
    (dict(load=np.array([0.0, np.nan])), "load must be finite"),
    (dict(Rx=np.array([0.01, np.inf])), "Rx must be finite"),
    (dict(Rx=np.array([0.01, 0.0])), "Rx must be > 0"),
    (dict(Ry=np.array([0.01, 1e-31])), "Ry must have a physical magnitude"),
    (dict(E_prime=np.array([2e11, -1.0])), "E_prime must be > 0"),
])
def test_plain_float64_checks_keep_the_errors(bad, match):
    # float64 arrays are accepted by two reductions each; whatever they reject goes to the
    # generic checks, which name the argument and the entry
    args = dict(load=np.array([1.0, 2.0]), Rx=np.array([0.01, 0.02]), Ry=np.array([0.03, 0.01]),
                E_prime=2e11)
    args.update(bad)
    with pytest.raises(ValueError, match=match):
        hertz.elliptical_contact(**args)


def test_plain_float64_path_equals_generic_path():
    # lists take the generic checks, float64 arrays the two-reduction test (zero loads a
    # third): same arrays in, same bits out
    rng = np.random.default_rng(14)
    Q = 10 ** rng.uniform(-3, 5, 40)
    Q[::3] = 0.0
    Rx, Ry = 10 ** rng.uniform(-3, -1, 40), 10 ** rng.uniform(-3, -1, 40)
    a = hertz.elliptical_contact(Q.tolist(), Rx.tolist(), Ry.tolist(), 2e11)
    b = hertz.elliptical_contact(Q, Rx, Ry, 2e11)
    for f in ("k", "a", "b", "approach", "p_max", "stiffness", "ellipk", "ellipe"):
        assert np.array_equal(getattr(a, f), getattr(b, f)), f
    assert np.all(b.a[::3] == 0) and np.all(b.p_max[::3] == 0)


def test_empty_arrays():
    # no contact in, no contact out (the kernels' reductions have nothing to reduce)
    c = hertz.elliptical_contact(np.array([]), 0.01, 0.02, 2e11)
    assert c.a.shape == (0,) and c.k.shape == (0,) and c.stiffness.shape == (0,)
    c = hertz.elliptical_contact(1.0, np.empty((0, 3)), 0.02, 2e11)
    assert c.p_max.shape == (0, 3) and c.ellipk.shape == (0, 3)
    assert hertz.ellipticity(np.array([]))[0].shape == (0,)
    assert hertz.contact_stiffness(np.array([]), 0.1, 2e11).shape == (0,)


def test_kernel_results_satisfy_their_equations():
    # the kernel's shortcuts (p_max = E' b/(4 E R), delta = K b h, R = max/(1 + alpha_r))
    # against the textbook forms (Hamrock & Dowson 1981 eqs. 3.8-3.16, 3.33) on 5000 contacts
    rng = np.random.default_rng(15)
    n = 5000
    Rx = 10 ** rng.uniform(-4, 0, n)
    Ry = Rx * 10 ** rng.uniform(-6, 6, n)
    Q = 10 ** rng.uniform(-3, 6, n)
    Ep = 10 ** rng.uniform(9, 12, n)
    c = hertz.elliptical_contact(Q, Rx, Ry, Ep)
    R = Rx * Ry / (Rx + Ry)
    b = np.cbrt(6 * c.ellipe * Q * R / (np.pi * c.k * Ep))
    rel = {
        "b": c.b / b - 1,
        "a = k b": c.a / (c.k * c.b) - 1,
        "p_max": c.p_max / (3 * Q / (2 * np.pi * c.a * c.b)) - 1,
        "approach": c.approach / (c.ellipk * np.cbrt(4.5 / (c.ellipe * R)
                                                     * (Q / (np.pi * c.k * Ep)) ** 2)) - 1,
        "Q = K delta^1.5": c.stiffness * c.approach**1.5 / Q - 1,
    }
    worst = {q: float(np.max(np.abs(v))) for q, v in rel.items()}
    assert max(worst.values()) < 1e-14, worst


@settings(max_examples=100, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, hertz._SMALL))
def test_small_arrays_equal_the_kernel(seed, n):
    # up to hertz._SMALL contacts go contact by contact through the scalar path; the same
    # contacts inside a larger array go through the vectorised kernel: the same bits
    rng = np.random.default_rng(seed)
    m = n + hertz._SMALL + 1
    Rx = 10 ** rng.uniform(-4, 0, m)
    Ry = Rx * 10 ** rng.uniform(-7.9, 7.9, m)
    Q = np.where(rng.random(m) < 0.2, 0.0, 10 ** rng.uniform(-3, 6, m))
    Ep = 10 ** rng.uniform(9, 12, m)
    big = hertz.elliptical_contact(Q, Rx, Ry, Ep)
    small = hertz.elliptical_contact(Q[:n], Rx[:n], Ry[:n], Ep[:n])
    for f in ("k", "a", "b", "approach", "p_max", "stiffness", "ellipk", "ellipe"):
        assert np.array_equal(getattr(small, f), getattr(big, f)[:n]), f
