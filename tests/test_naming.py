"""The decided names (docs/naming.md): every result carries them, the renamed ones keep
working as deprecated aliases that give the same number and a DeprecationWarning naming the
new name (attributed to the caller's line), and an old keyword given with its new one is a
TypeError."""
import inspect
import math
import warnings

import numpy as np
import pytest

import ballrace
from ballrace.analytic import duplex, ehl, highspeed, kinematics, loaddist
from ballrace.analytic import shaft as S
from ballrace.analytic._renames import renamed_keywords

#: Harris (2001) ch. 25 / Jones 1960 example bearing (218 angular contact, 40 deg).
B218 = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
                            free_contact_angle=np.radians(40))
DG = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, diametral_clearance=0.0)
W = 10000 * math.pi / 30                  # 10000 rev/min [rad/s]


def _new_names_only(func, *args, **kwargs):
    """func(*args, **kwargs) with any DeprecationWarning turned into an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        return func(*args, **kwargs)


def _warns_here(new, func, *args, **kwargs):
    """The call's DeprecationWarning names ``new`` and points at this file."""
    with pytest.warns(DeprecationWarning, match=new) as rec:
        out = func(*args, **kwargs)
    assert [w.filename for w in rec if w.category is DeprecationWarning] == [__file__]
    return out


# ------------------------------------------------------------------ speeds
def test_entrainment_speed_takes_speed_inner_and_speed_outer():
    D, dm, b, wi, wo = 0.0127, 0.065, 0.3, 4000 * 2 * math.pi / 60, 500.0
    # u = (d_m^2 - D^2 cos^2 b) / (4 d_m) |w_i - w_o|  (Hamrock & Dowson 1981 ch. 2)
    u = (dm**2 - (D * math.cos(b)) ** 2) / (4 * dm) * abs(wi - wo)
    got = _new_names_only(ehl.entrainment_speed, D, dm, b, speed_inner=wi, speed_outer=wo)
    assert got == pytest.approx(u, rel=1e-14)
    assert list(inspect.signature(ehl.entrainment_speed).parameters)[3:] == ["speed_inner",
                                                                             "speed_outer"]


def test_entrainment_speed_old_keywords_warn_and_give_the_same_number():
    D, dm, b, wi, wo = 0.0127, 0.065, 0.3, 418.9, 20.0
    new = ehl.entrainment_speed(D, dm, b, speed_inner=wi, speed_outer=wo)
    old = _warns_here("'speed_inner'", ehl.entrainment_speed, D, dm, b, inner_speed=wi,
                      speed_outer=wo)
    assert old == new
    old = _warns_here("'speed_outer'", ehl.entrainment_speed, D, dm, b, speed_inner=wi,
                      outer_speed=wo)
    assert old == new


@pytest.mark.parametrize("old, new", [("inner_speed", "speed_inner"),
                                      ("outer_speed", "speed_outer")])
def test_entrainment_speed_old_and_new_keyword_together_is_a_type_error(old, new):
    kw = {"speed_inner": 100.0, old: 200.0, new: 200.0}
    with pytest.raises(TypeError, match=f"{old!r}.*{new!r}"):
        ehl.entrainment_speed(0.0127, 0.065, **kw)


def test_renamed_positional_and_old_keyword_together_is_a_type_error():
    @renamed_keywords(old="new")
    def f(a, new=0.0):
        return a + new

    assert f(1.0, 2.0) == 3.0
    with pytest.warns(DeprecationWarning, match="'new'"):
        assert f(1.0, old=2.0) == 3.0
    with pytest.raises(TypeError, match="'new'"):
        f(1.0, 2.0, old=5.0)


def test_highspeed_and_kinematics_already_use_speed_inner():
    for func in (highspeed.solve, kinematics.cage_speed, kinematics.bearing_kinematics):
        params = inspect.signature(func).parameters
        assert "speed_inner" in params and "speed_outer" in params
        assert "inner_speed" not in params and "outer_speed" not in params


# ------------------------------------------------------------------ deflections
def test_highspeed_deflections_have_the_load_distribution_names():
    r = _new_names_only(highspeed.solve, B218, Fa=17800.0, Fr=4450.0, speed_inner=W)
    u = r.displacements
    assert _new_names_only(lambda: r.axial_deflection) == u[0]
    assert _new_names_only(lambda: r.radial_deflection) == math.hypot(u[1], u[2])
    # at rest, pure thrust: the same deflection as the static solver, which is Jones's
    # A sin(beta - beta_f) / cos(beta) (Hamrock & Dowson 1981 eq. 3.60; tests/test_highspeed)
    h0 = highspeed.solve(B218, Fa=17800.0)
    s0 = loaddist.solve(B218, Fa=17800.0)
    assert h0.axial_deflection == pytest.approx(float(s0.axial_deflection), rel=1e-9)
    assert h0.radial_deflection == pytest.approx(0.0, abs=1e-15)
    assert float(s0.radial_deflection) == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("old, new", [("axial_displacement", "axial_deflection"),
                                      ("radial_displacement", "radial_deflection")])
def test_highspeed_old_displacement_names_warn_and_give_the_same_number(old, new):
    r = highspeed.solve(B218, Fa=17800.0, Fr=4450.0, speed_inner=W)
    value = _warns_here(f"HighSpeedResult.{new}", getattr, r, old)
    assert value == getattr(r, new) and value > 0


# ------------------------------------------------------------------ residuals
def _results():
    ld = loaddist.solve(B218, Fa=17800.0, Fy=8900.0)
    pair = duplex.DuplexPair(B218, "DB", preload=2000.0).solve(Fa=3000.0, Fr=1000.0)
    hs = highspeed.solve(B218, Fa=17800.0, Fr=4450.0, speed_inner=W)
    sh = S.solve(S.Shaft([(0.2, 0.04, 0.0)], ballrace.Material(200e9, 0.3, density=7850.0),
                         n_elements=8),
                 (S.Seat(0.02, DG), S.Seat(0.18, DG, floating=True)),
                 (S.PointLoad(0.1, Fy=2000.0, Fa=100.0),))
    return {"LoadDistribution": ld, "DuplexResult": pair, "HighSpeedResult": hs,
            "ShaftResult": sh}


RESULTS = _results()


@pytest.mark.parametrize("name", sorted(RESULTS))
def test_every_result_has_relative_residual_a_float_at_or_below_its_tolerance(name):
    r = RESULTS[name]
    assert type(r).__name__ == name
    rel = _new_names_only(lambda: r.relative_residual)
    assert isinstance(rel, float) and 0.0 <= rel
    assert rel <= 1e-9                    # each solver's default rtol is 1e-9 or tighter
    assert hasattr(r, "residual")


def test_duplex_relative_residual_is_the_residual_over_the_load_scale():
    r = RESULTS["DuplexResult"]
    # load scale max(|Fa|, Fr, preload, 1 N) = 3000 N here
    assert r.relative_residual == pytest.approx(r.residual / 3000.0, rel=1e-15)


def test_shaft_relative_residual_is_its_residual():
    r = RESULTS["ShaftResult"]
    assert r.relative_residual == r.residual


def test_load_distribution_residual_is_the_per_dof_vector_of_the_relative_one():
    r = RESULTS["LoadDistribution"]
    assert r.residual.shape == (5,)
    assert np.array_equal(r.residual, np.where(r.imposed, 0.0, r.loads - r.applied))


@pytest.mark.parametrize("name", ["LoadDistribution", "HighSpeedResult"])
def test_ring_results_share_the_displacement_names(name):
    r = RESULTS[name]
    for attr in ("displacements", "loads", "applied", "axial_deflection", "radial_deflection",
                 "misalignment", "static_safety", "max_pressure"):
        _new_names_only(getattr, r, attr)
    assert np.shape(r.displacements) == np.shape(r.loads) == (5,)


# ------------------------------------------------------------------ signatures
def test_loaddist_solve_has_no_private_parameters():
    params = inspect.signature(loaddist.solve).parameters
    assert not [p for p in params if p.startswith("_")]
    assert list(params)[:6] == ["bearing", "Fa", "Fy", "Fz", "My", "Mz"]
    with pytest.raises(TypeError):
        loaddist.solve(B218, Fa=1000.0, _centered=True)


def test_radial_and_eccentric_thrust_keep_their_reference_and_balance():
    r = loaddist.radial(DG, 5000.0)
    assert r.axial_offset == 0.0 and r.relative_residual < 1e-9
    # solve() keeps the balls-just-touching reference: z0 = A sin(beta_f) (H&D 1981 eq. 3.61)
    g = loaddist.solve(B218, Fa=1000.0)
    A = B218.curvature_center_distance
    assert g.axial_offset == pytest.approx(A * math.sin(B218.free_contact_angle), rel=1e-14)
    e = loaddist.eccentric_thrust(B218, 17800.0, 0.02)
    assert e.moment_arm == "contact" and e.relative_residual < 1e-9
    assert e.loads[4] == pytest.approx(-0.02 * 17800.0, rel=1e-9)


# ------------------------------------------------------------------ shaft lives
def test_shaft_rating_lives_and_its_deprecated_name():
    r = RESULTS["ShaftResult"]
    new = _new_names_only(S.rating_lives, r, dynamic_rating=30e3)
    old = _warns_here("shaft.rating_lives", S.life, r, dynamic_rating=30e3)
    assert old.system == new.system and np.array_equal(old.seat_lives, new.seat_lives)
    # two rows in series: L_sys = (sum L^-e)^(-1/e) <= the shorter one
    assert new.system <= min(new.seat_lives)
    assert "rating_lives" in S.__all__ and "life" not in S.__all__
