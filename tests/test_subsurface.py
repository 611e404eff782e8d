"""Tests of ballrace.analytic.subsurface.

Two kinds of reference data are kept apart (STYLE.md §9):

* verification values — published numbers (Johnson 1985; Hamrock & Dowson 1981) with a
  tolerance set by the digits printed, and independent closed forms (Hamilton 1983 for
  the circle anywhere, evaluated in 40-digit arithmetic; Johnson's axis and surface
  formulas; McEwen's line contact) with tolerances near rounding;
* regression snapshots — this module's own values to many digits, tight tolerance.

Stresses are compared in units of p_max, lengths in units of b (or a for the circle).
"""

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import optimize

import ballrace
from ballrace.analytic import subsurface
from ballrace.analytic.hertz import elliptical_contact, line_contact
from fieldref import alpha_for_k, divergence

E_PRIME = 219.78e9
GOLDEN = (1.0 + 5.0**0.5) / 2.0


def contact(k_alpha=1.0, load=1000.0, Rx=0.005):
    """Contact with Ry = k_alpha Rx (k_alpha >= 1: minor axis b along x)."""
    return elliptical_contact(load, Rx, Rx * k_alpha, E_PRIME)


def circle():
    return contact(1.0)


def nd(s, c):
    """Stress components of a StressState in units of p_max, stacked."""
    return np.array([s.sxx, s.syy, s.szz, s.sxy, s.sxz, s.syz]) / c.p_max


# ----------------------------------------------------------------- independent references
def hamilton_mp(x, y, z, nu, dps=40):
    """Hamilton (1983) eqs. for normal Hertz load of a circle (units a, p0), in mpmath.

    Tension positive, z into the body: the same conventions as ballrace.
    Returns (sxx, syy, szz, sxy, sxz, syz).
    """
    with mp.workdps(dps):
        x, y, z, nu = (mp.mpf(float(v)) for v in (x, y, z, nu))
        r2 = x * x + y * y
        A = r2 + z * z - 1
        S = mp.sqrt(A * A + 4 * z * z)
        M = mp.sqrt((S + A) / 2)
        N = mp.sqrt((S - A) / 2)
        phi = mp.atan2(1, M)
        G = M * M - N * N + z * M - N
        H = 2 * M * N + M + z * N
        third = mp.mpf(1) / 3
        if r2 == 0:      # on the axis: Johnson (1985) eq. 3.45
            sr = (1 + nu) * (z * mp.atan2(1, z) - 1) + 1 / (2 * (1 + z * z))
            return [float(v) for v in (sr, sr, -1 / (1 + z * z), 0, 0, 0)]
        common = (1 - nu) * N * z * z - (1 - 2 * nu) * third * (N * S + 2 * A * N + 1) - nu * M * z
        sxx = (1 + nu) * z * phi + ((y * y - x * x) / r2 * common - N * (x * x + 2 * nu * y * y)
                                    - M * x * x * z / S) / r2
        syy = (1 + nu) * z * phi + ((x * x - y * y) / r2 * common - N * (y * y + 2 * nu * x * x)
                                    - M * y * y * z / S) / r2
        szz = -N + z * M / S
        sxy = (x * y * (1 - 2 * nu) / r2**2 * (-N * r2 + 2 * third * N * (S + 2 * A)
                                                - z * (z * N + M) + 2 * third)
               + x * y * z / r2**2 * (-M * r2 / S - z * N + M))
        syz = -z * (y * N / S - y * z * H / (G * G + H * H))
        sxz = -z * (x * N / S - x * z * H / (G * G + H * H))
        return [float(v) for v in (sxx, syy, szz, sxy, sxz, syz)]


def johnson_circle_surface(r, nu):
    """Johnson (1985) eqs. 3.41-3.42 (Huber 1904): (sigma_r, sigma_theta)/p0 at z = 0."""
    r = np.asarray(r, float)
    inside = r < 1
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.sqrt(np.clip(1 - r * r, 0, None))
        # (1 - s^3)/r^2 = (1 + s + s^2)/(1 + s): no cancellation near the centre
        t = (1 - 2 * nu) / 3 * (1 + s + s * s) / (1 + s)
        sr = np.where(inside, t - s, (1 - 2 * nu) / (3 * r * r))
        st_ = np.where(inside, -t - 2 * nu * s, -(1 - 2 * nu) / (3 * r * r))
    return sr, st_


# ----------------------------------------------------------------- published numbers
class TestPublishedNumbers:
    """Johnson (1985) and Hamrock & Dowson (1981): tolerance = half a unit in the last
    printed digit (0.005 for two-digit values, 0.00005 for four)."""

    def test_circle_max_shear_johnson(self):
        # Johnson 1985 §3.4: 0.31 p0 at z = 0.48 a (nu = 0.3)
        c = circle()
        m = subsurface.max_shear(c, nu=0.3)
        assert m.tau_max / c.p_max == pytest.approx(0.31, abs=0.005)
        assert m.depth / c.a == pytest.approx(0.48, abs=0.005)
        # regression snapshot (depth converged to 1e-13 a)
        assert m.tau_max / c.p_max == pytest.approx(0.310020501954521, rel=1e-12)
        assert m.depth / c.a == pytest.approx(0.480864485292900, rel=1e-10)

    def test_circle_von_mises(self):
        # ~0.62 p0 at ~0.48 a (nu = 0.3); on the axis of a circle sigma_x = sigma_y, so
        # sigma_vm = |sigma_x - sigma_z| = 2 tau_max exactly, at the same depth.
        c = circle()
        v = subsurface.von_mises(c, nu=0.3)
        m = subsurface.max_shear(c, nu=0.3)
        assert v.sigma_vm / c.p_max == pytest.approx(0.62, abs=0.005)
        assert v.depth / c.a == pytest.approx(0.48, abs=0.01)
        assert v.sigma_vm == pytest.approx(2 * m.tau_max, rel=1e-13)
        assert v.depth == pytest.approx(m.depth, rel=1e-9)

    def test_line_max_shear_johnson(self):
        # Johnson 1985 §4.2: 0.30 p0 at 0.78 b.  Exact: phi^(-5/2) p0 at phi^(-1/2) b.
        lc = line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
        m = subsurface.line_max_shear(lc, nu=0.3)
        assert m.tau_max / lc.p_max == pytest.approx(0.30, abs=0.005)
        assert m.depth / lc.b == pytest.approx(0.78, abs=0.01)     # Johnson truncates 0.786
        assert m.tau_max / lc.p_max == pytest.approx(GOLDEN**-2.5, rel=1e-14)
        assert m.depth / lc.b == pytest.approx(GOLDEN**-0.5, rel=1e-12)

    def test_line_orthogonal_shear_johnson(self):
        # Johnson 1985 §4.2: 0.25 p0 at z = 0.5 b, x = +-0.87 b
        lc = line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
        o = subsurface.line_orthogonal_shear(lc)
        assert o.tau0 / lc.p_max == pytest.approx(0.25, rel=1e-15)
        assert o.z0 / lc.b == pytest.approx(0.5, rel=1e-15)
        assert o.x0 / lc.b == pytest.approx(0.87, abs=0.005)
        assert o.x0 / lc.b == pytest.approx(np.sqrt(3) / 2, rel=1e-15)
        assert o.t == 1.0

    def test_line_orthogonal_shear_is_the_max_of_mcewen(self):
        lc = line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
        b, p = float(lc.b), float(lc.p_max)

        def neg_tau(v):
            return float(subsurface.line_stress(lc, -v[0] * b, v[1] * b).sxz) / p * -1

        r = optimize.minimize(neg_tau, [0.8, 0.4], method="Nelder-Mead",
                              options=dict(xatol=1e-11, fatol=1e-15, maxiter=4000))
        assert -r.fun == pytest.approx(0.25, rel=1e-13)
        assert r.x == pytest.approx([np.sqrt(3) / 2, 0.5], abs=1e-7)
        # sign in this frame: tau_xz < 0 at +x0, > 0 at -x0
        assert float(subsurface.line_stress(lc, 0.866 * b, 0.5 * b).sxz) < 0

    @pytest.mark.parametrize("quantity, expected, tol", [
        ("t", 1.2808, 5e-5), ("tau0", 0.2139, 5e-5), ("z0", 0.3509, 5e-5)])
    def test_lp_circle_hamrock_dowson(self, quantity, expected, tol):
        # Hamrock & Dowson 1981 §3.1.2: circle t = 1.2808, z0 = 0.3509 b, tau0 = 0.2139 p_max
        c = circle()
        o = subsurface.orthogonal_shear(c)
        value = {"t": o.t, "tau0": o.tau0 / c.p_max, "z0": o.z0 / c.b}[quantity]
        assert value == pytest.approx(expected, abs=tol)

    def test_lp_line_limit(self):
        # b/a -> 0: t -> 1, tau0 -> 0.25 p_max, z0 -> 0.5 b, x0 -> sqrt(3)/2 b (O(1/k^2))
        c = contact(1e8)
        o = subsurface.orthogonal_shear(c)
        assert float(c.k) > 3e4
        assert o.t == pytest.approx(1.0, abs=1e-9)
        assert o.tau0 / c.p_max == pytest.approx(0.25, abs=1e-9)
        assert o.z0 / c.b == pytest.approx(0.5, abs=1e-9)
        assert o.x0 / c.b == pytest.approx(np.sqrt(3) / 2, abs=1e-9)

    def test_ellipse_max_shear_tends_to_line_contact(self):
        # max_shear of a slender ellipse -> line values, error O(b/a)
        c = contact(1e8)
        m = subsurface.max_shear(c)
        assert m.tau_max / c.p_max == pytest.approx(GOLDEN**-2.5, abs=2e-5)
        assert m.depth / c.b == pytest.approx(GOLDEN**-0.5, abs=1e-5)


# ----------------------------------------------------------------- Lundberg–Palmgren
class TestLundbergPalmgren:
    @pytest.mark.parametrize("k", [1.0, 2.0, 5.0, 10.0])
    def test_lp_is_the_maximum_of_the_stress_field(self, k):
        """The numerical max of |tau_xz(x, 0, z)| is LP's tau0 at (x0, z0): validates both
        the closed form (incl. the derived x0) and the field."""
        c = elliptical_contact(1000.0, 0.005, 0.005 * alpha_for_k(k), E_PRIME)
        assert float(c.k) == pytest.approx(k, rel=1e-10)
        o = subsurface.orthogonal_shear(c)
        b, p = float(c.b), float(c.p_max)

        def tau(x, z):
            return subsurface.stress(c, np.asarray(x) * b, 0.0, np.asarray(z) * b).sxz / p

        x0, z0 = float(o.x0 / b), float(o.z0 / b)
        # value at the LP point
        assert -tau(x0, z0) == pytest.approx(float(o.tau0 / p), rel=1e-13)
        assert tau(-x0, z0) == pytest.approx(float(o.tau0 / p), rel=1e-13)
        # stationary there: 4th-order central differences of the field
        h = 1e-3
        w = np.array([1, -8, 8, -1]) / (12 * h)
        dx = w @ tau(x0 + h * np.array([-2, -1, 1, 2]), z0)
        dz = w @ tau(x0, z0 + h * np.array([-2, -1, 1, 2]))
        assert abs(dx) < 1e-9 and abs(dz) < 1e-9
        # and a global maximum: a grid over the quarter plane never exceeds it
        X, Z = np.meshgrid(np.linspace(0.0, 3.0, 61), np.linspace(0.0, 2.0, 41))
        assert np.max(-tau(X, Z)) <= float(o.tau0 / p) * (1 + 1e-13)
        # Nelder-Mead from the best grid point lands on (x0, z0)
        G = -tau(X, Z)
        j = np.unravel_index(np.argmax(G), G.shape)
        r = optimize.minimize(lambda v: float(tau(v[0], v[1])), [X[j], Z[j]],
                              method="Nelder-Mead",
                              options=dict(xatol=1e-10, fatol=1e-16, maxiter=4000))
        assert -r.fun == pytest.approx(float(o.tau0 / p), rel=1e-12)
        assert r.x == pytest.approx([x0, z0], abs=1e-6)

    def test_t_solver_against_mpmath(self):
        ratios = np.array([1e-6, 1e-3, 0.01, 0.1, 0.3, 0.5, 0.9, 1.0])   # b/a
        t = subsurface.lundberg_palmgren_t(1.0 / ratios)
        for r, ti in zip(ratios, t):
            ref = mp.findroot(lambda s: (s * s - 1) * (2 * s - 1) - mp.mpf(r) ** 2,
                              (mp.mpf(1), mp.mpf(1.3)), solver="anderson")
            assert ti == pytest.approx(float(ref), abs=4.5e-16)
        assert subsurface.lundberg_palmgren_t(1.0) == pytest.approx(1.2807764064044151, abs=1e-15)

    def test_approximate_method_documented_error(self):
        # H&D (1981) eq. 3.33: t ~ 1 + 0.16 csch(k/2); documented max errors are tight
        ratio = np.logspace(-2, 0, 20001)
        c = elliptical_contact(1000.0, 0.005, 0.005 * alpha_for_k(1.0 / ratio), E_PRIME)
        ex = subsurface.orthogonal_shear(c, method="exact")
        ap = subsurface.orthogonal_shear(c, method="approximate")
        for q, bound in subsurface.LP_APPROXIMATION_ERROR.items():
            err = np.max(np.abs(getattr(ap, q) / getattr(ex, q) - 1))
            assert err <= bound, q
            assert err > bound - 1e-4, q          # the bound is the measured value rounded up
        # the circle value of the fit
        assert subsurface.lundberg_palmgren_t(1.0, "approximate") == pytest.approx(
            1 + 0.16 / np.sinh(0.5), rel=1e-15)

    def test_vectorized_and_broadcast(self):
        c = elliptical_contact(np.array([[100.0], [1000.0]]), 0.005,
                               np.array([0.005, 0.02, 0.2]), E_PRIME)
        o = subsurface.orthogonal_shear(c)
        assert o.tau0.shape == (2, 3)
        single = subsurface.orthogonal_shear(elliptical_contact(1000.0, 0.005, 0.02, E_PRIME))
        assert o.tau0[1, 1] == pytest.approx(single.tau0, rel=1e-15)
        assert o.x0[1, 1] == pytest.approx(single.x0, rel=1e-15)

    def test_major_axis_along_x_rejected(self):
        c = elliptical_contact(1000.0, 0.02, 0.005, E_PRIME)     # Rx > Ry
        with pytest.raises(ValueError, match=r"^c must have its minor semi-axis"):
            subsurface.orthogonal_shear(c)

    def test_bad_method(self):
        with pytest.raises(ValueError, match="method must be one of"):
            subsurface.orthogonal_shear(circle(), method="csch")


# ----------------------------------------------------------------- on-axis closed form
class TestAxis:
    def test_circle_axis_against_johnson(self):
        # Johnson (1985) eq. 3.45 (Huber 1904)
        c = circle()
        zeta = np.concatenate([[0.0, 1e-12], np.linspace(0.01, 10, 200), [1e3, 1e6]])
        for nu in (-0.5, 0.0, 0.3, 0.5):
            s = subsurface.axis_stress(c, zeta * c.a, nu=nu)
            with np.errstate(divide="ignore"):
                sr = -(1 + nu) * (1 - zeta * np.arctan2(1, zeta)) + 0.5 / (1 + zeta**2)
            assert np.allclose(s.sxx / c.p_max, sr, rtol=0, atol=2e-15)
            assert np.allclose(s.syy / c.p_max, sr, rtol=0, atol=2e-15)
            assert np.allclose(s.szz / c.p_max, -1 / (1 + zeta**2), rtol=0, atol=1e-15)

    def test_surface_centre_ellipse(self):
        # sigma_x(0) = -p0 [2 nu + (1 - 2 nu) a_y / (a_x + a_y)] (limit of the closed form)
        c = contact(30.0)
        s = subsurface.axis_stress(c, 0.0, nu=0.25)
        ax, ay = float(c.semi_axis_x), float(c.semi_axis_y)
        assert s.sxx / c.p_max == pytest.approx(-(0.5 + 0.5 * ay / (ax + ay)), rel=1e-14)
        assert s.syy / c.p_max == pytest.approx(-(0.5 + 0.5 * ax / (ax + ay)), rel=1e-14)
        assert s.szz / c.p_max == pytest.approx(-1.0, rel=1e-15)

    def test_szz_axis_closed_form(self):
        c = contact(10.0)
        z = np.linspace(0, 5, 51) * c.b
        s = subsurface.axis_stress(c, z)
        ref = -1 / np.sqrt((1 + (z / c.semi_axis_x) ** 2) * (1 + (z / c.semi_axis_y) ** 2))
        assert np.allclose(s.szz / c.p_max, ref, rtol=1e-14, atol=0)

    def test_depth_search_vectorized(self):
        # speed is measured in benchmarks/bench_subsurface.py, not here
        Q = np.linspace(100, 5000, 10**4)
        c = elliptical_contact(Q, 0.005, np.logspace(np.log10(0.005), 0, 10**4), E_PRIME)
        m = subsurface.max_shear(c)
        v = subsurface.von_mises(c)
        assert m.tau_max.shape == (10**4,)
        # spot-check against scalar calls and a brute-force grid
        for i in (0, 4321, 9999):
            ci = elliptical_contact(Q[i], 0.005, float(c.Ry[i]), E_PRIME)
            mi = subsurface.max_shear(ci)
            assert m.tau_max[i] == pytest.approx(mi.tau_max, rel=1e-14)
            z = np.linspace(0, 3, 30001) * ci.b
            tr = subsurface.axis_stress(ci, z).tresca
            assert np.max(tr) <= mi.tau_max * (1 + 1e-14)
            assert np.max(tr) == pytest.approx(mi.tau_max, rel=1e-8)
            assert z[np.argmax(tr)] == pytest.approx(mi.depth, abs=2e-4 * ci.b)
        assert np.all(np.isfinite(v.sigma_vm)) and np.all(v.depth > 0)

    def test_axis_maxima_are_global_maxima(self):
        # no larger Tresca or von Mises stress off the axis (grid over a quadrant)
        for alpha in (1.0, 4.0, 20.0):
            c = contact(alpha)
            b, a = float(c.b), float(c.a)
            X, Y, Z = np.meshgrid(np.linspace(0, 1.2, 13) * b, np.linspace(0, 1.2, 13) * a,
                                  np.linspace(0.05, 1.5, 30) * b, indexing="ij")
            s = subsurface.stress(c, X, Y, Z)
            assert np.max(s.tresca) <= subsurface.max_shear(c).tau_max * (1 + 1e-12)
            assert np.max(s.von_mises) <= subsurface.von_mises(c).sigma_vm * (1 + 1e-12)


# ----------------------------------------------------------------- full field accuracy
class TestField:
    def test_circle_against_hamilton_mpmath(self):
        rng = np.random.default_rng(7)
        n = 60
        x = rng.uniform(-2.5, 2.5, n)
        y = rng.uniform(-2.5, 2.5, n)
        z = np.concatenate([np.zeros(10), rng.uniform(1e-6, 0.05, 10), rng.uniform(0, 3, n - 20)])
        c = circle()
        a = float(c.a)
        for nu in (0.0, 0.3, 0.5):
            got = nd(subsurface.stress(c, x * a, y * a, z * a, nu=nu), c)
            ref = np.array([hamilton_mp(*p, nu) for p in zip(x, y, z)]).T
            assert np.max(np.abs(got - ref)) < 5e-15

    def test_circle_surface_against_johnson(self):
        c = circle()
        r = np.concatenate([np.linspace(0.001, 0.999, 50), np.linspace(1.001, 5, 50)])
        theta = 0.7
        for nu in (0.2, 0.3):
            s = subsurface.stress(c, r * np.cos(theta) * c.a, r * np.sin(theta) * c.a, 0.0, nu)
            sr, st_ = johnson_circle_surface(r, nu)
            C, S = np.cos(theta), np.sin(theta)
            # 5e-15: at r = 0.999 sqrt(1 - r^2) amplifies the rounding of the coordinates
            assert np.allclose(s.sxx / c.p_max, sr * C * C + st_ * S * S, rtol=0, atol=5e-15)
            assert np.allclose(s.syy / c.p_max, sr * S * S + st_ * C * C, rtol=0, atol=5e-15)
            assert np.allclose(s.sxy / c.p_max, (sr - st_) * S * C, rtol=0, atol=5e-15)
            assert np.allclose(s.szz / c.p_max, -np.sqrt(np.clip(1 - r * r, 0, None)), atol=1e-15)
            assert np.all(s.sxz == 0) and np.all(s.syz == 0)

    @pytest.mark.parametrize("alpha", [1.0, 3.0, 30.0, 3000.0])
    def test_field_on_axis_matches_closed_form(self, alpha):
        c = contact(alpha)
        z = np.concatenate([[0.0, 1e-10], np.linspace(0.01, 5, 100), [100.0]]) * c.b
        f = subsurface.stress(c, 0.0, 0.0, z, nu=0.3)
        a = subsurface.axis_stress(c, z, nu=0.3)
        assert np.max(np.abs(nd(f, c) - nd(a, c))) < 5e-15
        # and just off the axis (continuity; the gradient there is O(1) per unit b)
        g = subsurface.stress(c, 1e-9 * c.b, 1e-9 * c.b, z, nu=0.3)
        assert np.max(np.abs(nd(g, c) - nd(a, c))) < 1e-8

    def test_line_contact_limit(self):
        """At y = 0 the ellipse tends to McEwen's plane-strain field: sigma_z and tau_xz
        with error O((b/a)^2), sigma_x and sigma_y with error O(b/a)."""
        rng = np.random.default_rng(3)
        x = np.concatenate([np.linspace(-2, 2, 41), rng.uniform(-3, 3, 200)])
        z = np.concatenate([np.zeros(41), rng.uniform(0, 3, 200)])
        errs = {}
        for k in (1e3, 1e4):
            c = elliptical_contact(1000.0, 0.005, 0.005 * alpha_for_k(k), E_PRIME)
            b = float(c.b)
            lc = line_contact(1.0, 1.0, np.inf, ballrace.BEARING_STEEL)
            ref = nd(subsurface.line_stress(lc, x * lc.b, z * lc.b, nu=0.3), lc)
            got = nd(subsurface.stress(c, x * b, 0.0, z * b, nu=0.3), c)
            errs[k] = np.max(np.abs(got - ref), axis=1)
            assert np.all(got[[3, 5]] == 0)            # sxy = syz = 0 on y = 0
        assert errs[1e4][2] < 2e-8 and errs[1e4][4] < 1e-8       # szz, sxz: O(k^-2)
        assert errs[1e4][0] < 5e-5 and errs[1e4][1] < 5e-5       # sxx, syy: O(k^-1)
        assert errs[1e3][0] / errs[1e4][0] == pytest.approx(10, rel=0.01)
        assert errs[1e3][2] / errs[1e4][2] == pytest.approx(100, rel=0.01)

    def test_trace_is_proportional_to_one_plus_nu(self):
        """sigma_kk = (1 + nu)/pi * dV/dz: checks the quadrature of the H-terms through
        Laplace's identity H_xx + H_yy = -V_z."""
        rng = np.random.default_rng(11)
        c = contact(12.0)
        x = rng.uniform(-3, 3, 300) * c.b
        y = rng.uniform(-3, 3, 300) * c.a
        z = np.concatenate([np.zeros(50), rng.uniform(0, 3, 250)]) * c.b
        tr = []
        for nu in (0.0, 0.45):
            s = subsurface.stress(c, x, y, z, nu=nu)
            tr.append((s.sxx + s.syy + s.szz) / c.p_max / (1 + nu))
        assert np.max(np.abs(tr[0] - tr[1])) < 5e-15

    def test_field_100x100_shape(self):
        # speed is measured in benchmarks/bench_subsurface.py, not here
        c = contact(20.0)
        X, Z = np.meshgrid(np.linspace(-3, 3, 100) * c.b, np.linspace(0, 3, 100) * c.b)
        s = subsurface.stress(c, X, 0.3 * c.a, Z)
        assert s.sxx.shape == (100, 100) and np.all(np.isfinite(s.sxx))

    def test_slender_and_far_points_finite(self):
        c = contact(1e8)                     # k ~ 3.3e4
        b, a = float(c.b), float(c.a)
        x = np.array([0.0, b, 2 * b, 0.5 * b, 1e4 * a, 0.0])
        y = np.array([0.0, 0.5 * a, 0.0, 0.999 * a, 0.0, 1e-300])
        z = np.array([0.0, 0.0, 0.3 * b, 1e-12 * b, 0.0, 1e4 * a])
        s = nd(subsurface.stress(c, x, y, z), c)
        assert np.all(np.isfinite(s))
        assert np.abs(s[:, 4:]).max() < 1e-7   # far away: small

    def test_quadrature_converged(self, monkeypatch):
        rng = np.random.default_rng(5)
        c = contact(50.0)
        x = rng.uniform(-2, 2, 200) * c.b
        y = rng.uniform(-1.5, 1.5, 200) * c.a
        z = np.concatenate([np.zeros(40), 10.0 ** rng.uniform(-9, 0.5, 160)]) * c.b
        coarse = nd(subsurface.stress(c, x, y, z), c)
        monkeypatch.setattr(subsurface, "_H_STEP", 0.2)
        monkeypatch.setattr(subsurface, "_S_BELOW", 110.0)
        monkeypatch.setattr(subsurface, "_S_ABOVE", 60.0)
        fine = nd(subsurface.stress(c, x, y, z), c)
        assert np.max(np.abs(coarse - fine)) < 3e-15

    def test_major_axis_along_x_is_the_transpose(self):
        cy = elliptical_contact(1000.0, 0.005, 0.03, E_PRIME)     # a along y
        cx = elliptical_contact(1000.0, 0.03, 0.005, E_PRIME)     # a along x
        rng = np.random.default_rng(2)
        x, y, z = rng.uniform(-2, 2, (3, 50)) * float(cy.a)
        z = np.abs(z)
        s1 = subsurface.stress(cy, x, y, z)
        s2 = subsurface.stress(cx, y, x, z)
        p = float(cy.p_max)
        for u, v in (("sxx", "syy"), ("syy", "sxx"), ("szz", "szz"), ("sxy", "sxy"),
                     ("sxz", "syz"), ("syz", "sxz")):
            assert np.allclose(getattr(s1, u) / p, getattr(s2, v) / p, rtol=0, atol=1e-14)
        m1, m2 = subsurface.max_shear(cy), subsurface.max_shear(cx)
        assert m1.tau_max == pytest.approx(m2.tau_max, rel=1e-13)

    def test_unloaded_contact_is_zero_not_nan(self):
        c = elliptical_contact(0.0, 0.005, 0.05, E_PRIME)
        s = subsurface.stress(c, 1e-4, 1e-4, 1e-4)
        assert all(getattr(s, f) == 0 for f in ("sxx", "syy", "szz", "sxy", "sxz", "syz"))
        m, v, o = subsurface.max_shear(c), subsurface.von_mises(c), subsurface.orthogonal_shear(c)
        assert (m.tau_max, m.depth, v.sigma_vm, o.tau0, o.z0) == (0, 0, 0, 0, 0)

    def test_principal_tresca_von_mises(self):
        c = contact(5.0)
        s = subsurface.stress(c, np.array([0.3, -0.7]) * c.b, np.array([0.2, 1.1]) * c.a,
                              np.array([0.5, 0.2]) * c.b)
        P = s.principal()
        assert P.shape == (2, 3) and np.all(np.diff(P, axis=-1) <= 0)
        T = s.tensor()
        assert np.allclose(np.trace(T, axis1=-2, axis2=-1), P.sum(-1), rtol=1e-13)
        assert np.allclose(s.tresca, 0.5 * (P[:, 0] - P[:, 2]), rtol=1e-14)
        vm = np.sqrt(0.5 * ((P[:, 0] - P[:, 1]) ** 2 + (P[:, 1] - P[:, 2]) ** 2
                            + (P[:, 2] - P[:, 0]) ** 2))
        assert np.allclose(s.von_mises, vm, rtol=1e-12)
        assert np.all(s.tau_xz == s.sxz)


# ----------------------------------------------------------------- invariants (hypothesis)
ALPHA = st.floats(1.0, 1e4)
UNIT = st.floats(-2.5, 2.5)


def _stress_nd(c, xi, eta, zeta, nu=0.3):
    """Stress / p_max at (xi semi_axis_x, eta semi_axis_y, zeta b)."""
    return nd(subsurface.stress(c, xi * c.semi_axis_x, eta * c.semi_axis_y, zeta * c.b, nu), c)


@settings(max_examples=40, deadline=None)
@given(alpha=ALPHA, load=st.floats(1.0, 1e4), xi=UNIT, eta=UNIT, zeta=st.floats(0, 3))
def test_scaling_with_load(alpha, load, xi, eta, zeta):
    """Stresses scale with p_max and lengths with b: the nondimensional field is
    independent of the load (and of Rx) for a fixed radius ratio."""
    c1 = elliptical_contact(1000.0, 0.005, 0.005 * alpha, E_PRIME)
    c2 = elliptical_contact(load, 0.02, 0.02 * alpha, E_PRIME)
    s1, s2 = _stress_nd(c1, xi, eta, zeta), _stress_nd(c2, xi, eta, zeta)
    assert np.max(np.abs(s1 - s2)) < 1e-13


@settings(max_examples=40, deadline=None)
@given(alpha=ALPHA, xi=UNIT, eta=UNIT, zeta=st.floats(0, 3), nu=st.floats(-0.9, 0.5))
def test_symmetry(alpha, xi, eta, zeta, nu):
    c = contact(alpha)
    s = _stress_nd(c, xi, eta, zeta, nu)
    sx = _stress_nd(c, -xi, eta, zeta, nu)
    sy = _stress_nd(c, xi, -eta, zeta, nu)
    even_x = np.array([1, 1, 1, -1, -1, 1])     # sxy, sxz odd in x
    even_y = np.array([1, 1, 1, -1, 1, -1])     # sxy, syz odd in y
    assert np.max(np.abs(sx - even_x * s)) < 1e-14
    assert np.max(np.abs(sy - even_y * s)) < 1e-14


@settings(max_examples=30, deadline=None)
@given(alpha=st.floats(1.0, 100.0), xi=st.floats(-2, 2), eta=st.floats(-2, 2),
       zeta=st.floats(0.1, 2.0), nu=st.floats(0.0, 0.5))
def test_equilibrium(alpha, xi, eta, zeta, nu):
    """div(sigma) = 0 by 4th-order central differences (h = 1e-3 z, so the truncation
    error stays small near the surface where the field varies on the scale z)."""
    div = divergence(contact(alpha), xi, eta, zeta, nu)
    assert np.max(np.abs(div)) < 1e-7


@settings(max_examples=40, deadline=None)
@given(alpha=ALPHA, xi=UNIT, eta=UNIT)
def test_surface_traction(alpha, xi, eta):
    """sigma_zz = -p and tau_xz = tau_yz = 0 on the surface (p = 0 outside), and the
    interior field tends to it as z -> 0+."""
    c = contact(alpha)
    x, y = xi * c.semi_axis_x, eta * c.semi_axis_y
    p = c.pressure(x, y) / c.p_max
    s0 = nd(subsurface.stress(c, x, y, 0.0), c)
    assert s0[2] == pytest.approx(-p, abs=4e-15)    # sqrt(1 - r^2) near the edge
    assert s0[4] == 0 and s0[5] == 0
    s1 = nd(subsurface.stress(c, x, y, 1e-10 * c.b), c)
    q = 1 - xi * xi - eta * eta
    if abs(q) > 1e-3:    # away from the contact edge, where the gradient is singular
        assert np.max(np.abs(s1 - s0)) < 1e-6


@settings(max_examples=40, deadline=None)
@given(xi=st.floats(-3, 3), zeta=st.floats(0.05, 3), nu=st.floats(0, 0.5))
def test_line_contact_equilibrium_and_plane_strain(xi, zeta, nu):
    lc = line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
    b, p = float(lc.b), float(lc.p_max)
    h = 1e-3 * zeta * b
    off = np.array([-2, -1, 1, 2]) * h
    w = np.array([1, -8, 8, -1]) / (12 * h)
    sx = subsurface.line_stress(lc, xi * b + off, zeta * b, nu)
    sz = subsurface.line_stress(lc, xi * b, zeta * b + off, nu)
    assert abs(w @ sx.sxx + w @ sz.sxz) * b / p < 1e-7
    assert abs(w @ sx.sxz + w @ sz.szz) * b / p < 1e-7
    s = subsurface.line_stress(lc, xi * b, zeta * b, nu)
    assert s.syy == pytest.approx(nu * (s.sxx + s.szz), rel=1e-15, abs=1e-300)
    assert subsurface.line_stress(lc, -xi * b, zeta * b, nu).sxz == pytest.approx(-s.sxz)


def test_line_contact_surface():
    lc = line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)
    x = np.linspace(-3, 3, 601) * lc.b
    s = subsurface.line_stress(lc, x, 0.0)
    assert np.allclose(s.szz, -lc.pressure(x), rtol=0, atol=1e-15 * lc.p_max)
    assert np.allclose(s.sxx, -lc.pressure(x), rtol=0, atol=1e-15 * lc.p_max)
    assert np.all(s.sxz == 0)
    assert np.all(np.isfinite(subsurface.line_stress(lc, lc.b, 0.0).sxx))   # strip edge


# ----------------------------------------------------------------- input validation
class TestValidation:
    def test_negative_depth(self):
        with pytest.raises(ValueError, match=r"^z must be >= 0 \[m\]"):
            subsurface.stress(circle(), 0.0, 0.0, -1e-6)
        with pytest.raises(ValueError, match=r"^z must be >= 0"):
            subsurface.axis_stress(circle(), -1.0)
        with pytest.raises(ValueError, match=r"^z must be >= 0"):
            subsurface.line_stress(line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL),
                                   0.0, -1.0)

    @pytest.mark.parametrize("nu", [-1.0, 0.51, np.nan])
    def test_nu_range(self, nu):
        with pytest.raises(ValueError, match=r"^nu must be"):
            subsurface.max_shear(circle(), nu=nu)

    def test_nan_coordinate(self):
        with pytest.raises(ValueError, match=r"^x must be finite"):
            subsurface.stress(circle(), np.nan, 0.0, 1e-4)

    def test_wrong_types(self):
        with pytest.raises(TypeError, match="c must be a HertzContact"):
            subsurface.max_shear(1.0)
        with pytest.raises(TypeError, match="lc must be a LineContact"):
            subsurface.line_max_shear(circle())

    def test_far_coordinates(self):
        c = circle()
        with pytest.raises(ValueError, match=r"^y must be within 1e\+30 semi-axes b"):
            subsurface.stress(c, 0.0, 1e31 * c.b, 1e-4)
        with pytest.raises(ValueError, match=r"^z must be within"):
            subsurface.axis_stress(c, 1e31 * c.b)
        assert np.isfinite(subsurface.stress(c, 0.0, 1e29 * c.b, 1e29 * c.b).szz)

    def test_k_range(self):
        with pytest.raises(ValueError, match=r"^k must be in \[1"):
            subsurface.lundberg_palmgren_t(0.5)
