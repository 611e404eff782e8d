"""The seat contract (ballrace.analytic.contract): what a shaft seat needs from a bearing.

BallBearing and DuplexPair satisfy it; a bearing type the shaft module has never heard of
(a linear spring row) is a seat once it implements the contract; anything else is refused
with a TypeError naming what it lacks.
"""
import types

import numpy as np
import pytest

import ballrace
from ballrace.analytic import contract, loaddist
from ballrace.analytic import shaft as S
from ballrace.analytic.duplex import DuplexPair

STEEL = ballrace.Material(E=207e9, nu=0.3, name="steel")
# 7208-like angular-contact bearing and a deep-groove one (as in tests/test_shaft.py)
AC = ballrace.BallBearing(12.7e-3, 13, 60e-3, 0.52, 0.52,
                          free_contact_angle=np.radians(40), material=STEEL)
DG = ballrace.BallBearing(7.938e-3, 9, 38.5e-3, 0.52, 0.53, diametral_clearance=10e-6,
                          material=STEEL)


# --------------------------------------------------------------------------- a linear spring
class SpringRow:
    """A row that is a diagonal linear spring K u (no contact law): F = K u, tangent K,
    energy u K u / 2."""

    reference_axial_offset = 0.0
    approach_limit = np.inf
    step_length = 1e-3
    moment_radius = 0.02

    def __init__(self, k):
        self.k = np.asarray(k, float)

    def ring_forces(self, u):
        u = np.asarray(u, float).reshape(-1, 5)
        F = u * self.k
        K = np.broadcast_to(np.diag(self.k), (u.shape[0], 5, 5)).copy()
        return F, K, np.abs(u[:, :3]).max(1), 0.5 * (u * F).sum(1)

    def element_loads(self, u):
        return np.abs(self.ring_forces(u)[0][..., :3]).max(-1, keepdims=True)

    def result(self, u):
        F = self.ring_forces(u)[0][0]
        return types.SimpleNamespace(loads=F, displacements=np.asarray(u, float),
                                     static_safety=np.inf, max_pressure=0.0)

    def rating_life(self, u, *, dynamic_rating=None, rotating="inner",
                    nominal_contact_angle=None):
        return types.SimpleNamespace(L10r=np.inf, C=dynamic_rating,
                                     modified=lambda **kw: np.inf)


class SpringBearing:
    """A seat bearing with one SpringRow; implements contract.SeatBearing."""

    accepts_clearance = False
    life_exponent = 3.0
    seat_name = "spring"

    def __init__(self, k, carries_axial=True):
        self.row = SpringRow(k)
        self.carries_axial = carries_axial

    def seat_rows(self, direction, offset, row_spacing, clearance):
        return (contract.RowMount(self.row, direction, 0.0, offset, True),)

    def spring_axial_load(self, direction):
        return 0.0

    def equivalent_load(self, radial_load, axial_load, contact_angle=None):
        return None

    def seat_warnings(self, what, results, tilt):
        return ()


def test_ball_bearing_and_duplex_pair_satisfy_the_contract():
    pair = DuplexPair(AC, "DB", preload=500.0)
    for b in (AC, DG, pair):
        assert isinstance(b, contract.SeatBearing)
        assert contract.missing(b) == []
        mounts = b.seat_rows(1, 0.0, 0.0, None)
        assert all(isinstance(m, contract.RowMount) for m in mounts)
        assert all(isinstance(m.row, contract.Row) for m in mounts)
    assert len(pair.seat_rows(1, 0.0, 0.0, None)) == 2
    assert not isinstance("7208", contract.SeatBearing)
    assert isinstance(SpringBearing(np.ones(5)), contract.SeatBearing)
    assert isinstance(SpringRow(np.ones(5)), contract.Row)


def test_ball_row_is_the_load_distribution_at_imposed_displacements():
    # the row's forces and tangent are loaddist.ring_forces' (the same model, bit for bit);
    # its result is loaddist.solve with every DOF imposed
    row = AC.seat_rows(1, 0.0, 0.0, None)[0].row
    u = np.array([[30e-6, 10e-6, -5e-6, 1e-4, -2e-4], [20e-6, 0.0, 0.0, 0.0, 0.0]])
    F, K, dmax, energy = row.ring_forces(u)
    F2, K2 = loaddist.ring_forces(AC, u)
    assert np.array_equal(F, F2) and np.array_equal(K, K2)
    ld = row.result(u[0])
    assert np.allclose(ld.loads, F[0], rtol=1e-12, atol=1e-9)
    assert dmax[0] > 0 and energy[0] > 0
    # A DB pair's two rows share one model (evaluated together); a clearance reaches the row
    r1, r2 = (m.row for m in DuplexPair(AC, "DB", 500.0).seat_rows(1, 0.0, 0.0, None))
    assert r1 == r2
    c = DG.seat_rows(1, 0.0, 0.0, 20e-6)[0].row
    assert c.clearance == 20e-6 and c != DG.seat_rows(1, 0.0, 0.0, None)[0].row


def test_a_spring_bearing_is_a_shaft_seat_in_equilibrium():
    # Shaft 0.2 m, seats at 0.02 and 0.18 m with linear springs without tilt stiffness (so
    # the seats carry no moment), Fy = -1000 N and Fa = 300 N at x = 0.06 m; the right seat
    # floats.  Statics (simply supported beam): R_left = F (0.18 - 0.06) / 0.16 = 0.75 F,
    # R_right = 0.25 F; the whole thrust goes to the locating left seat.  The seat's ring
    # displacement is then R / k exactly (a linear spring).
    k = np.array([2e8, 1e8, 1e8, 0.0, 0.0])
    shaft = S.Shaft([(0.2, 0.03, 0.0)], material=STEEL)
    seats = [S.Seat(0.02, SpringBearing(k)), S.Seat(0.18, SpringBearing(k), floating=True)]
    load = S.PointLoad(0.06, Fy=-1000.0, Fa=300.0)
    r = S.solve(shaft, seats, [load])
    assert r.reactions[0] == pytest.approx([300.0, -750.0, 0.0, 0.0, 0.0], abs=1e-6)
    assert r.reactions[1] == pytest.approx([0.0, -250.0, 0.0, 0.0, 0.0], abs=1e-6)
    assert r.ring_displacements[0, :3] == pytest.approx([300.0 / 2e8, -750.0 / 1e8, 0.0],
                                                        rel=1e-9, abs=1e-15)
    assert np.abs(r.equilibrium_residual()).max() < 1e-6
    assert r.bearings[0].loads == pytest.approx(r.reactions[0], abs=1e-6)
    assert seats[0].ball_bearing is None and seats[0].bearing.seat_name == "spring"


def test_a_seat_bearing_that_carries_no_thrust_does_not_locate_the_shaft():
    k = np.array([2e8, 1e8, 1e8, 0.0, 0.0])
    shaft = S.Shaft([(0.2, 0.03, 0.0)], material=STEEL)
    seats = [S.Seat(0.02, SpringBearing(k, carries_axial=False)),
             S.Seat(0.18, SpringBearing(k), floating=True)]
    with pytest.raises(ValueError, match="no axial support"):
        S.solve(shaft, seats, [S.PointLoad(0.06, Fy=-1000.0)])


def test_a_non_bearing_is_refused_naming_what_it_lacks():
    with pytest.raises(TypeError, match=r"bearing must be a ballrace.BallBearing or a "
                                        r"DuplexPair.*got str, which lacks seat_rows"):
        S.Seat(0.0, "7208")

    class Quiet:                            # everything but seat_warnings
        accepts_clearance = carries_axial = True
        life_exponent, seat_name = 3.0, "quiet"
        seat_rows = SpringBearing.seat_rows
        spring_axial_load = SpringBearing.spring_axial_load
        equivalent_load = SpringBearing.equivalent_load

    with pytest.raises(TypeError, match=r"got Quiet, which lacks seat_warnings$"):
        S.Seat(0.0, Quiet())

    class Rowless(SpringBearing):
        def seat_rows(self, direction, offset, row_spacing, clearance):
            return (contract.RowMount(object(), direction, 0.0, offset),)

    with pytest.raises(TypeError, match=r"a object lacks ring_forces, element_loads"):
        S.Seat(0.0, Rowless(np.ones(5)))
    # a pair refuses a seat clearance with today's words
    with pytest.raises(ValueError, match="clearance is for a single bearing; a DuplexPair's "
                                         "rows keep their own preload"):
        S.Seat(0.0, DuplexPair(AC, "DB", 500.0), clearance=10e-6)
