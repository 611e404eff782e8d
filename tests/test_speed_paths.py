"""Fast paths give the same answers as the general ones.

* One contact of plain numbers (``hertz.point_contact`` / ``elliptical_contact`` with
  floats) runs a scalar path: bit-for-bit the 1-element-array result (same operations
  in the same order; IEEE double arithmetic is the same in Python and NumPy).
* The piecewise-polynomial ellipticity (``hertz._solve_k``) against the Newton solution
  it was built from, and against the 30-digit mpmath reference (tests/mpref.py).
* The single-case load-distribution driver against the vectorized one, and the
  analytic ring stiffness against central differences of the ring forces.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import hertz
from mpref import k_exact

STEEL = ballrace.Material(E=200e9, nu=0.3)
FIELDS = ("load", "Rx", "Ry", "E_prime", "k", "a", "b", "approach", "p_max", "stiffness",
          "ellipk", "ellipe")

radius = st.floats(1e-4, 1.0)
signed_ratio = st.one_of(st.floats(-0.999, -1e-3), st.floats(1e-3, 0.999))
load = st.one_of(st.just(0.0), st.floats(1e-3, 1e6))


def _same(c_scalar, c_array):
    for f in FIELDS:
        s, a = getattr(c_scalar, f), getattr(c_array, f)
        assert np.shape(s) == () and type(s) is np.float64, f
        assert a.shape == (1,)
        assert s == a[0], (f, s, a[0])          # bit for bit


@settings(max_examples=300, deadline=None)
@given(Q=load, Rx=st.floats(1e-5, 10.0), ratio=st.floats(-7.99, 7.99),
       Ep=st.floats(1e9, 1e12))
def test_elliptical_contact_scalar_equals_array(Q, Rx, ratio, Ep):
    Ry = Rx * 10.0**ratio
    _same(hertz.elliptical_contact(Q, Rx, Ry, Ep),
          hertz.elliptical_contact(np.array([Q]), np.array([Rx]), np.array([Ry]), Ep))


@settings(max_examples=300, deadline=None)
@given(Q=load, r1=radius, r2=radius, g1=signed_ratio, g2=signed_ratio,
       flat=st.booleans())
def test_point_contact_scalar_equals_array(Q, r1, r2, g1, g2, flat):
    # body 1 convex (r1, r2); body 2 concave or convex, less curved (|g| < 1), or flat
    rx2 = np.inf if flat else r1 / g1
    ry2 = r2 / g2
    c_s = hertz.point_contact(Q, r1, r2, rx2, ry2, STEEL)
    c_a = hertz.point_contact(np.array([Q]), r1, r2, rx2, ry2, STEEL)
    _same(c_s, c_a)


def test_scalar_path_keeps_the_checks():
    # the fast path hands odd or out-of-range input to the array path and its errors
    with pytest.raises(ValueError, match="load must be >= 0"):
        hertz.point_contact(-1.0, 0.01, 0.01, 0.01, 0.01, STEEL)
    with pytest.raises(ValueError, match="rx1 must be non-zero"):
        hertz.point_contact(1.0, 0.0, 0.01, 0.01, 0.01, STEEL)
    with pytest.raises(ValueError, match="curvature sum in the y plane"):
        hertz.point_contact(1.0, 0.01, 0.01, 0.02, -0.01, STEEL)
    with pytest.raises(ValueError, match="radius ratio"):
        hertz.elliptical_contact(1.0, 1e-5, 1e4, 2e11)
    with pytest.raises(ValueError, match="E_prime must be finite; got nan"):
        hertz.elliptical_contact(1.0, 0.01, 0.02, float("nan"))
    with pytest.raises(TypeError):
        hertz.elliptical_contact(True, 0.01, 0.02, 2e11)


@settings(max_examples=200, deadline=None)
@given(v=st.floats(0.0, np.log(1e8)))
def test_tabulated_ellipticity_equals_newton(v):
    alpha = np.array([np.exp(v)])
    k, K, E = hertz._solve_k(alpha)
    kn, Kn, En = hertz._solve_k_newton(alpha)
    assert k[0] == pytest.approx(kn[0], rel=5e-15)
    assert K[0] == pytest.approx(Kn[0], rel=5e-15) and E[0] == pytest.approx(En[0], rel=5e-15)
    assert hertz._solve_k_scalar(float(alpha[0])) == (k[0], K[0], E[0])


@pytest.mark.parametrize("alpha", [1.0, 1.0 + 2**-40, 1.04, 1.3, 2.0 - 2**-45, 7.5, 1e3, 99999.9,
                                   1e8])
def test_tabulated_ellipticity_at_interval_edges_matches_mpmath(alpha):
    # 30-digit mpmath reference; near m = 0.05 the direct K - E lost 1e-14 before the
    # series range was widened to m < 0.3
    k, _, _ = hertz._solve_k(np.array([alpha]))
    assert k[0] == pytest.approx(k_exact(alpha), rel=5e-15, abs=0)
