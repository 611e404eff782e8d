"""Operating clearance from fits (Lamé) and temperatures.

Reference values are the textbook closed forms that the general Lamé solution must reduce
to (derived in the comments), and exact thermal identities.
"""
import math

import numpy as np
import pytest

import ballrace
from ballrace.analytic import clearance, life

BRG = ballrace.BallBearing(0.0115, 7, 0.0435, 0.52, 0.53, diametral_clearance=20e-6)
d, Do = 0.025, 0.062
F = 0.0435 - 0.0115 - 10e-6          # inner raceway diameter (P_d0/2 deducted)
E = 0.0435 + 0.0115 + 10e-6          # outer raceway diameter


def test_solid_shaft_same_material():
    """Equal moduli, solid shaft: I/d = 2 p F^2 / (E (F^2 - d^2)), so the raceway grows by
    exactly I d / F (Harris 2001 ch. 4; SKF's rule)."""
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=15e-6)
    assert oc.fit_inner == pytest.approx(15e-6 * d / F, rel=1e-12)
    assert oc.fit_outer == 0.0 and oc.thermal == 0.0
    assert oc.operating == pytest.approx(20e-6 - 15e-6 * d / F, rel=1e-12)


def _same_material_fit(interference, fit, raceway, other):
    """Raceway diameter change of a ring of one material with its shaft or housing (Lamé):
    I (F/d) (d^2 - d0^2) / (F^2 - d0^2) for the fit diameter d, the raceway diameter F and
    the mate's other boundary d0 (a hollow shaft's bore, a finite housing's outside
    diameter) [m]; a solid shaft (d0 = 0) gives I d / F, an infinite housing I F / d."""
    return interference * (raceway / fit) * (fit**2 - other**2) / (raceway**2 - other**2)


def test_infinite_housing_same_material():
    """Infinite housing: Delta_e = I E / D."""
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, housing_interference=10e-6)
    assert oc.fit_outer == pytest.approx(10e-6 * E / Do, rel=1e-12)


@pytest.mark.parametrize("attribute, fits, fit, raceway, other", [
    # shaft bore d0: Delta = I (d/F) (1 - (d0/d)^2) / (1 - (d0/F)^2)
    ("fit_inner", {"shaft_interference": 15e-6, "shaft_bore": 0.015}, d, F, 0.015),
    # housing of outside diameter Dh: Delta_e = I (E/D) (1 - (D/Dh)^2) / (1 - (E/Dh)^2)
    ("fit_outer", {"housing_interference": 10e-6, "housing_diameter": 0.1}, Do, E, 0.1),
])
def test_hollow_shaft_and_finite_housing_same_material(attribute, fits, fit, raceway, other):
    """Same material, a hollow shaft or a finite housing: the two-ring Lamé closed form
    (derived from the two Lamé compliances; the hollow-shaft rule of bearing catalogues)."""
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, **fits)
    interference = fits.get("shaft_interference", fits.get("housing_interference"))
    expected = _same_material_fit(interference, fit, raceway, other)
    assert getattr(oc, attribute) == pytest.approx(expected, rel=1e-12)


def test_softer_shaft_takes_more_of_the_interference():
    alu = ballrace.Material(E=70e9, nu=0.33)
    steel = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=15e-6)
    soft = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=15e-6,
                                    shaft_material=alu)
    assert soft.fit_inner < steel.fit_inner
    assert soft.pressure_inner < steel.pressure_inner


def test_loose_fit_changes_nothing():
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=-5e-6,
                                  housing_interference=-10e-6)
    assert oc.operating == pytest.approx(20e-6, abs=1e-18)


def test_thermal_common_expansion():
    """With rings and balls of one alpha and T_b = (T_i + T_e)/2 the change is
    alpha [(T_e - T_i) D_pw + (T_i + T_e - 2 T_0) P_d0 / 2]; with T_i + T_e = 2 T_0 exactly
    alpha (T_e - T_i) D_pw."""
    a = clearance.STEEL_EXPANSION
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do,
                                  inner_temperature=303.15, outer_temperature=283.15)
    assert oc.thermal == pytest.approx(a * (-20.0) * 0.0435, rel=1e-12)
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do,
                                  inner_temperature=343.15, outer_temperature=333.15)
    assert oc.thermal == pytest.approx(a * (-10.0 * 0.0435 + 90.0 * 10e-6), rel=1e-12)


def test_aluminium_housing_loosens_when_warm():
    """A 23e-6 1/K housing 50 K above the fit temperature loses (23 - 11.5)e-6 * 50 * D
    = 35.65 um of interference: a 20 um fit becomes loose."""
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, housing_interference=20e-6,
                                  housing_expansion=23e-6, inner_temperature=343.15,
                                  outer_temperature=343.15)
    assert oc.fit_outer == 0.0
    cold = life.operating_clearance(BRG, bore=d, outside_diameter=Do,
                                    housing_interference=20e-6, housing_expansion=23e-6)
    assert cold.fit_outer == pytest.approx(20e-6 * E / Do, rel=1e-3)


def test_preload_is_a_result_not_an_error():
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=25e-6,
                                  inner_temperature=323.15, outer_temperature=303.15)
    assert oc.operating < 0 and oc.is_preload
    with pytest.raises(ValueError, match="preload"):
        oc.bearing(BRG)
    res = BRG.radial(2000.0, clearance=oc.operating)       # the solver takes it directly
    assert float(res.clearance) == pytest.approx(oc.operating)
    oc2 = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=5e-6)
    b2 = oc2.bearing(BRG)
    assert b2.diametral_clearance == pytest.approx(oc2.operating)


@pytest.mark.parametrize("kw, name", [
    (dict(bore=0.04), "bore"), (dict(outside_diameter=0.05), "outside_diameter"),
    (dict(shaft_bore=0.03), "mating_diameter"), (dict(housing_diameter=0.06), "mating_diameter"),
    (dict(inner_temperature=-3.0), "inner_temperature"),
])
def test_bad_input(kw, name):
    args = dict(bore=d, outside_diameter=Do, shaft_interference=10e-6,
                housing_interference=10e-6)
    args.update(kw)
    with pytest.raises(ValueError, match=name):
        life.operating_clearance(BRG, **args)


def test_fit_pressure_broadcasts():
    p = clearance.fit_pressure(np.array([0.0, 10e-6, 20e-6]), d, F, 0.0, E_ring=200e9,
                               nu_ring=0.3, E_mate=200e9, nu_mate=0.3)
    assert p.shape == (3,) and p[0] == 0.0 and p[2] == pytest.approx(2 * p[1])
    assert math.isfinite(float(clearance.fit_pressure(1e-5, Do, E, math.inf, E_ring=2e11,
                                                      nu_ring=0.3, E_mate=2e11, nu_mate=0.3,
                                                      ring="outer")))


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=40, deadline=None)
@given(I=st.floats(1e-9, 60e-6), d0=st.floats(0.0, 0.02), Eratio=st.floats(0.3, 3.0))
def test_fit_reduction_bounded_and_monotone(I, d0, Eratio):
    """The raceway can never grow more than on a rigid shaft, where the bore takes the whole
    interference: Delta_F = I 2 d F / (F^2 + d^2 + nu (F^2 - d^2)) (Lamé, internal pressure);
    a solid shaft pushes it out further than a hollow one."""
    shaft = ballrace.Material(E=200e9 * Eratio, nu=0.3)
    oc = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=I,
                                  shaft_bore=d0, shaft_material=shaft)
    assert 0.0 <= oc.fit_inner <= I * 2 * d * F / (F**2 + d**2 + 0.3 * (F**2 - d**2)) * (1 + 1e-12)
    solid = life.operating_clearance(BRG, bore=d, outside_diameter=Do, shaft_interference=I,
                                     shaft_material=shaft)
    assert oc.fit_inner <= solid.fit_inner * (1 + 1e-12)
