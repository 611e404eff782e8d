"""Invariants of the finite line contact (roller.line_contact) over random loads, profiles,
radii and tilts (hypothesis): the load balance, each strip a Hertz semi-ellipse of its own
load, complementarity of gap and load, symmetry without tilt, the side a tilt loads, and
an approach that grows with the load."""
import math
import warnings

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic.roller import Crowned, line_contact

STEEL = ballrace.BEARING_STEEL
PROFILES = ["iso", "lundberg", "johns-gohar", Crowned(4e-3, 0.5)]

cases = st.fixed_dictionaries({
    "Q": st.floats(500.0, 20000.0),
    "R1": st.floats(4e-3, 10e-3),
    "R2": st.sampled_from([math.inf, 0.03, -0.05]),
    "profile": st.sampled_from(PROFILES),
    "n": st.sampled_from([21, 31, 41]),
})


def solve(c, tilt=0.0, Q=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)       # few-slice notes at heavy tilt
        return line_contact(c["Q"] if Q is None else Q, c["R1"], c["R2"], 12e-3, STEEL, STEEL,
                            profile=c["profile"], tilt=tilt, n_slices=c["n"])


@settings(max_examples=40, deadline=None)
@given(cases, st.floats(-4e-4, 4e-4))
def test_balance_strip_shape_and_complementarity(c, tilt):
    r = solve(c, tilt)
    F, w = np.asarray(r.slice_loads), r.slice_width
    assert np.all(np.isfinite(r.pressure)) and np.all(np.asarray(r.pressure) >= 0)
    assert abs(F.sum() - c["Q"]) <= 1e-9 * c["Q"]
    on = F > 0
    q = F[on] / w                                            # load per length [N/m]
    b = np.asarray(r.half_width)[on]
    # each loaded strip: 2-D Hertz semi-ellipse of its own load (Johnson 1985, eq. 4.45)
    np.testing.assert_allclose(b, np.sqrt(8.0 * r.R * q / (math.pi * r.E_prime)), rtol=1e-12)
    np.testing.assert_allclose(np.asarray(r.pressure)[on], 2.0 * q / (math.pi * b), rtol=1e-12)
    gap = np.asarray(r.gap)
    assert np.all(gap >= 0.0) and np.all(gap[on] == 0.0)
    assert r.approach > 0.0


@settings(max_examples=25, deadline=None)
@given(cases)
def test_symmetric_without_tilt_and_the_tilt_loads_its_side(c):
    r0 = solve(c)
    F0 = np.asarray(r0.slice_loads)
    np.testing.assert_allclose(F0, F0[::-1], rtol=1e-7, atol=1e-9 * c["Q"])
    r = solve(c, tilt=2e-4)                                  # + : the end at +x goes in
    F, x = np.asarray(r.slice_loads), np.asarray(r.x)
    assert F[x > 0].sum() > F[x < 0].sum()


@settings(max_examples=25, deadline=None)
@given(cases)
def test_approach_grows_with_the_load(c):
    lo = solve(c, Q=0.5 * c["Q"])
    hi = solve(c)
    assert hi.approach > lo.approach
