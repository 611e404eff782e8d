"""Tests of the subsurface stress field with a tangential surface traction q = mu p.

References (independent of the module's method, Love's potentials in the ellipsoidal
coordinate):

* Cerruti's point-force solution (Johnson 1985 *Contact Mechanics* §3.2 eq. 3.18 for the
  displacements; the stresses below are checked here against Hooke's law applied to
  eq. 3.18 by numerical differentiation in 40-digit arithmetic), integrated over the
  Hertz ellipse by brute-force quadrature;
* the line contact of Smith & Liu (1953) / Johnson (1985) eq. 7.18, closed form;
* Hamilton & Goodman (1966): the tension at the trailing edge of a sliding circle,
  p0 [(1 - 2 nu)/3 + (4 + nu) pi mu / 8]; Johnson (1985) §7.2: 2 mu p0 for the line;
* surface equilibrium (sigma_zz = -p, tau_xz = -mu p, tau_yz = 0 on the patch, zero
  outside), linearity in mu, symmetry, far-field decay to the point forces.

Stresses are in units of p_max, lengths in units of b.
"""

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballrace
from ballrace.analytic import subsurface
from ballrace.analytic.hertz import elliptical_contact, line_contact
from fieldref import alpha_for_k, divergence

E_PRIME = 219.78e9
COMPS = ("sxx", "syy", "szz", "sxy", "sxz", "syz")


def contact(alpha=1.0, load=1000.0, Rx=0.005):
    """Contact with Ry = alpha Rx (alpha >= 1: minor axis b along x)."""
    return elliptical_contact(load, Rx, Rx * alpha, E_PRIME)


def line():
    return line_contact(1e6, 0.01, np.inf, ballrace.BEARING_STEEL)


def nd(s, p):
    return np.array([np.asarray(getattr(s, k), float) for k in COMPS]) / float(p)


def traction_part(c, x, y, z, mu, nu=0.3):
    """(stress(mu) - stress(0)) / (mu p_max), stacked."""
    s1 = nd(subsurface.stress(c, x, y, z, nu, traction=mu), c.p_max)
    s0 = nd(subsurface.stress(c, x, y, z, nu), c.p_max)
    return (s1 - s0) / mu


# ----------------------------------------------------------------- Cerruti reference
def cerruti(x, y, z, nu):
    """Stresses of a unit tangential point force along +x at the origin of the surface
    of the half-space z >= 0 (tension positive, z into the body); Johnson (1985) §3.2,
    Cerruti (1882)."""
    r = np.sqrt(x * x + y * y + z * z)
    rz = r + z
    c, m = 1 / (2 * np.pi), 1 - 2 * nu
    sx = c * (-3 * x**3 / r**5 + m * (x / r**3 - 3 * x / (r * rz**2) + x**3 / (r**3 * rz**2)
                                      + 2 * x**3 / (r**2 * rz**3)))
    sy = c * (-3 * x * y * y / r**5 + m * (x / r**3 - x / (r * rz**2)
                                           + x * y * y / (r**3 * rz**2)
                                           + 2 * x * y * y / (r**2 * rz**3)))
    sz = -c * 3 * x * z * z / r**5
    txy = c * (-3 * x * x * y / r**5 + m * (-y / (r * rz**2) + x * x * y / (r**3 * rz**2)
                                            + 2 * x * x * y / (r**2 * rz**3)))
    txz = -c * 3 * x * x * z / r**5
    tyz = -c * 3 * x * y * z / r**5
    return np.array([sx, sy, sz, txy, txz, tyz])


def test_cerruti_stresses_satisfy_hookes_law_on_johnsons_displacements():
    """The closed-form Cerruti stresses above equal Hooke's law applied to Johnson (1985)
    eq. 3.18 (displacements of a tangential point force), differentiated in mpmath."""
    mp.mp.dps = 40

    def u(i, x, y, z, nu):
        r = mp.sqrt(x * x + y * y + z * z)
        c = 1 / (4 * mp.pi * r)       # G = 1
        if i == 0:
            return c * (1 + x**2 / r**2 + (1 - 2 * nu) * (r / (r + z) - x**2 / (r + z) ** 2))
        if i == 1:
            return c * (x * y / r**2 - (1 - 2 * nu) * x * y / (r + z) ** 2)
        return c * (x * z / r**2 + (1 - 2 * nu) * x / (r + z))

    for pt, nu in [((0.3, -0.7, 0.5), 0.3), ((1.2, 0.4, 0.2), 0.1), ((-0.5, 0.9, 1.3), 0.45)]:
        p = tuple(mp.mpf(v) for v in pt)
        g = [[mp.diff(lambda *X, i=i: u(i, *X, nu), p, tuple(int(k == j) for k in range(3)))
              for j in range(3)] for i in range(3)]
        lam = 2 * nu / (1 - 2 * nu)
        div = g[0][0] + g[1][1] + g[2][2]
        S = [[float(g[i][j] + g[j][i] + (lam * div if i == j else 0)) for j in range(3)]
             for i in range(3)]
        ref = [S[0][0], S[1][1], S[2][2], S[0][1], S[0][2], S[1][2]]
        assert np.allclose(cerruti(*pt, nu), ref, rtol=0, atol=1e-14)


def cerruti_integrated(ax, ay, x, y, z, nu, n=300, m=600):
    """iint p(xi, eta) cerruti(x - xi, y - eta, z) over the Hertz ellipse (p0 = 1).

    xi = ax sin(phi) cos(t), eta = ay sin(phi) sin(t): p dA = ax ay cos^2(phi) sin(phi)
    dphi dt, smooth; Gauss-Legendre in phi, trapezoid in t (periodic).  For z >= 0.2 the
    kernel is smooth on the patch and n = 300, m = 600 nodes give ~1e-14 for a circle.
    """
    g, wg = np.polynomial.legendre.leggauss(n)
    ph, wp = (g + 1) * np.pi / 4, wg * np.pi / 4
    th = np.arange(m) * 2 * np.pi / m
    P, T = np.meshgrid(ph, th, indexing="ij")
    W = np.outer(wp, np.full(m, 2 * np.pi / m)) * ax * ay * np.cos(P) ** 2 * np.sin(P)
    xi, eta = ax * np.sin(P) * np.cos(T), ay * np.sin(P) * np.sin(T)
    return np.array([np.sum(W * k) for k in cerruti(x - xi, y - eta, z, nu)])


class TestAgainstCerruti:
    @pytest.mark.parametrize("alpha", [1.0, 4.0, 30.0, 0.25])
    def test_field_equals_integrated_point_forces(self, alpha):
        """Interior points, circle and ellipses (k = 1, ~2.5, ~9.5, and k = 2.5 with the
        major axis along the traction): the traction part agrees with Cerruti's point
        force integrated over the ellipse to ~1e-14 p0."""
        c = contact(alpha)
        ax, ay = float(c.semi_axis_x / c.b), float(c.semi_axis_y / c.b)
        rng = np.random.default_rng(7)
        pts = np.column_stack([rng.uniform(-1.5, 1.5, 3) * ax, rng.uniform(-1.5, 1.5, 3) * ay,
                               rng.uniform(0.25, 1.5, 3)])
        pts = np.vstack([pts, [[0.0, 0.0, 0.5], [-0.9 * ax, 0.3 * ay, 0.3]]])
        # the field is affine in nu, so two values check every nu; the reference needs
        # more nodes around a long ellipse (600 leave 1e-11 at k = 9.5, 1200 1e-14)
        m = 1200 if max(ax, ay) > 2 else 600
        for nu in (0.0, 0.5):
            for x, y, z in pts:
                got = traction_part(c, x * c.b, y * c.b, z * c.b, 1.0, nu)
                ref = cerruti_integrated(ax, ay, x, y, z, nu, 300, m)
                assert np.max(np.abs(got - ref)) < 2e-13, (x, y, z, nu)

    def test_near_the_surface_and_the_edge(self):
        """z = 0.03-0.05 b, inside and just outside the edge: the reference needs more
        nodes where the kernel is nearly singular (at z = 0.03 b, 500 x 2000 nodes leave
        2e-11, 800 x 3000 ~7e-15)."""
        c = contact(4.0)
        ax, ay = float(c.semi_axis_x / c.b), float(c.semi_axis_y / c.b)
        for x, y, z, n, m in ((-0.95, 0.2, 0.03, 800, 3000), (1.05, 0.0, 0.05, 400, 1500)):
            got = traction_part(c, x * c.b, y * c.b, z * c.b, 1.0, 0.3)
            ref = cerruti_integrated(ax, ay, x, y, z, 0.3, n, m)
            assert np.max(np.abs(got - ref)) < 5e-14, (x, y, z)

    def test_far_field_tends_to_the_point_forces(self):
        """Far away the traction part is Cerruti's field of Q = mu P, P = 2/3 pi a b p0,
        with a relative error O((a/R)^2), and decays as R^-2."""
        c = contact(3.0)
        ax, ay = float(c.semi_axis_x / c.b), float(c.semi_axis_y / c.b)
        Q = 2.0 / 3.0 * np.pi * ax * ay
        d = np.array([0.5, -0.3, 0.8]) / np.linalg.norm([0.5, -0.3, 0.8])
        errs, mags = [], []
        for R in (100.0, 1000.0):
            x, y, z = R * d * ay
            got = traction_part(c, x * c.b, y * c.b, z * c.b, 1.0)
            ref = Q * cerruti(x, y, z, 0.3)
            errs.append(np.max(np.abs(got - ref)) / np.max(np.abs(ref)))
            mags.append(np.max(np.abs(got)))
        assert errs[0] < 1e-4 and errs[1] < 1e-6
        assert errs[0] / errs[1] == pytest.approx(100, rel=0.05)      # O(R^-2) relative
        assert mags[0] / mags[1] == pytest.approx(100, rel=1e-3)      # sigma ~ R^-2


# ----------------------------------------------------------------- traction 0 == today
class TestFrictionlessUnchanged:
    def test_stress_bit_for_bit(self):
        c = contact(7.0)
        rng = np.random.default_rng(1)
        x, y = rng.uniform(-2, 2, (2, 400)) * float(c.a)
        z = np.concatenate([np.zeros(50), rng.uniform(0, 2, 350)]) * float(c.b)
        s0 = nd(subsurface.stress(c, x, y, z), 1.0)
        for mu in (0.0, -0.0, np.zeros(400)):
            assert np.array_equal(nd(subsurface.stress(c, x, y, z, traction=mu), 1.0), s0)
        # mixed: the points without traction are today's values to the last bit
        mu = np.where(np.arange(400) % 3 == 0, 0.0, 0.3)
        s = nd(subsurface.stress(c, x, y, z, traction=mu), 1.0)
        assert np.array_equal(s[:, mu == 0], s0[:, mu == 0])
        assert np.max(np.abs(s[:, mu != 0] - s0[:, mu != 0])) > 0.01 * float(c.p_max)

    def test_block_size_does_not_change_a_bit(self, monkeypatch):
        """The quadrature is summed in blocks of points (cache-sized, 2**16 nodes); each
        point's sum is the same whatever the block size - also 2**20, the former one."""
        c = contact(1.0)
        X, Z = np.meshgrid(np.linspace(-3, 3, 40) * c.b, np.linspace(0, 3, 40) * c.b)
        out = []
        for chunk in (1 << 20, 1 << 16, 1 << 12):
            monkeypatch.setattr(subsurface, "_CHUNK", chunk)
            out.append([nd(subsurface.stress(c, X, 0.2 * c.a, Z, traction=m), 1.0)
                        for m in (0.0, 0.3)])
        for o in out[1:]:
            assert np.array_equal(o[0], out[0][0]) and np.array_equal(o[1], out[0][1])

    def test_line_and_maxima_bit_for_bit(self):
        lc = line()
        x = np.linspace(-3, 3, 61) * lc.b
        z = np.linspace(0, 2, 61) * lc.b
        assert np.array_equal(nd(subsurface.line_stress(lc, x, z, traction=0.0), 1.0),
                              nd(subsurface.line_stress(lc, x, z), 1.0))
        c = elliptical_contact(1000.0, 0.005, np.array([0.005, 0.02, 0.3]), E_PRIME)
        for f, attr in ((subsurface.max_shear, "tau_max"), (subsurface.von_mises, "sigma_vm")):
            a, b = f(c), f(c, traction=0.0)
            assert np.array_equal(getattr(a, attr), getattr(b, attr))
            assert np.array_equal(a.depth, b.depth)
            assert np.all(b.x == 0) and np.all(b.y == 0)


# ----------------------------------------------------------------- published closed forms
class TestPublished:
    @pytest.mark.parametrize("nu", [0.0, 0.25, 0.3, 0.5])
    @pytest.mark.parametrize("mu", [0.05, 0.2, 0.5])
    def test_circle_trailing_edge_tension(self, nu, mu):
        """Hamilton & Goodman (1966); Johnson (1985) §7.2: sigma_x at the trailing edge
        x = -a of a sliding circle = p0 [(1 - 2 nu)/3 + (4 + nu) pi mu / 8]."""
        c = contact(1.0)
        s = subsurface.stress(c, -c.a, 0.0, 0.0, nu, traction=mu)
        ref = (1 - 2 * nu) / 3 + (4 + nu) * np.pi * mu / 8
        assert s.sxx / c.p_max == pytest.approx(ref, abs=1e-14)
        # the largest surface tension sits there (for mu > 0)
        t = subsurface.surface_tension(c, nu, traction=mu)
        assert t.sigma1 / c.p_max == pytest.approx(ref, abs=1e-12)
        assert t.x / c.a == pytest.approx(-1.0, abs=1e-7)
        assert t.y / c.a == pytest.approx(0, abs=1e-7)
        # and the other direction mirrors it
        m = subsurface.stress(c, c.a, 0.0, 0.0, nu, traction=-mu)
        assert m.sxx / c.p_max == pytest.approx(ref, abs=1e-14)

    def test_frictionless_surface_tension(self):
        # Johnson (1985) eq. 3.41: radial tension (1 - 2 nu)/3 p0 at the edge of a circle
        c = contact(1.0)
        t = subsurface.surface_tension(c, 0.3)
        assert t.sigma1 / c.p_max == pytest.approx(0.4 / 3, rel=1e-12)
        assert np.hypot(t.x, t.y) / c.a == pytest.approx(1.0, abs=1e-7)

    @pytest.mark.parametrize("mu", [0.1, 0.3, 0.5])
    def test_line_trailing_edge_tension(self, mu):
        """Johnson (1985) §7.2 (Smith & Liu 1953): sigma_x = 2 mu p0 at x = -b, the largest
        tension; on the strip sigma_x^q = -2 mu p0 x/b and the in-plane principal shear
        sqrt(((sx - sz)/2)^2 + txz^2) = mu p0 (from sigma_x = -p - 2 mu p0 x/b,
        sigma_z = -p, tau_xz = -mu p)."""
        lc = line()
        b, p = float(lc.b), float(lc.p_max)
        s = subsurface.line_stress(lc, -b, 0.0, traction=mu)
        assert s.sxx / p == pytest.approx(2 * mu, rel=1e-15)
        x = np.linspace(-0.999, 0.999, 201)
        s = subsurface.line_stress(lc, x * b, 0.0, traction=mu)
        pr = np.sqrt(1 - x * x)
        assert np.allclose(s.sxx / p, -pr - 2 * mu * x, rtol=0, atol=1e-14)
        assert np.allclose(s.szz / p, -pr, rtol=0, atol=1e-15)
        assert np.allclose(s.sxz / p, -mu * pr, rtol=0, atol=1e-15)
        assert np.allclose(np.hypot((s.sxx - s.szz) / 2, s.sxz) / p, mu, rtol=1e-13)
        # outside the strip only sigma_x: tension behind, compression ahead, max at x = -b
        xo = np.concatenate([-np.geomspace(1.0 + 1e-9, 50, 50), np.geomspace(1 + 1e-9, 50, 50)])
        so = subsurface.line_stress(lc, xo * b, 0.0, traction=mu)
        assert np.all(so.sxx[:50] / p <= 2 * mu) and np.all(so.sxx[:50] > 0)
        assert np.all(so.sxx[50:] < 0)
        assert np.allclose(so.sxx / p, 2 * mu * (np.sign(xo) * np.sqrt(xo * xo - 1) - xo),
                           rtol=1e-9, atol=1e-15)

    def test_line_limit_of_the_ellipse(self):
        """At y = 0 the slender ellipse tends to the line contact (Johnson 1985 eq. 7.18):
        k = 1e4 within 1e-6 p0 for every component; errors fall ~k^-2."""
        rng = np.random.default_rng(3)
        x = np.concatenate([np.linspace(-2, 2, 41), rng.uniform(-3, 3, 150)])
        z = np.concatenate([np.zeros(41), rng.uniform(0, 3, 150)])
        lc = line()
        ref = (nd(subsurface.line_stress(lc, x * lc.b, z * lc.b, traction=0.3), lc.p_max)
               - nd(subsurface.line_stress(lc, x * lc.b, z * lc.b), lc.p_max)) / 0.3
        errs = {}
        for k in (1e3, 1e4):
            c = elliptical_contact(1000.0, 0.005, 0.005 * alpha_for_k(k), E_PRIME)
            got = traction_part(c, x * c.b, 0.0, z * c.b, 0.3)
            errs[k] = np.max(np.abs(got - ref))
        assert errs[1e4] < 1e-6
        assert errs[1e3] / errs[1e4] > 30

    def test_critical_traction_line_literature_range(self):
        """Johnson (1985) §7.2 / fig. 7.9: with mu above ~0.25-0.3 the maximum is at the
        surface (the printed range, not checked against the original figure)."""
        t = subsurface.critical_traction(0.0, 0.3, "tresca")
        v = subsurface.critical_traction(0.0, 0.3, "von_mises")
        assert 0.2 < t < 0.3 and 0.2 < v < 0.3
        for mu, crit in ((t, "tresca"), (v, "von_mises")):
            s = subsurface._search(1.0, np.inf, 0.3, mu, crit, "surface")[0]
            i = subsurface._search(1.0, np.inf, 0.3, mu, crit, "interior")[0]
            assert s == pytest.approx(i, abs=1e-8)        # the definition of mu_c


@pytest.mark.parametrize("ratio, nu, crit, mu_c", [(0.2, 0.3, "von_mises", 0.3244),
                                                    (1.0, 0.3, "tresca", 0.2879)])
def test_critical_traction_table_by_grids(ratio, nu, crit, mu_c):
    """Values of the table in docs/traction.md, checked without the searches: on fine
    grids over the section y = 0 (z >= 0.05 b) and the surface, the subsurface maximum
    is larger at mu_c - 0.006 and the surface one at mu_c + 0.006."""
    ay = 1.0 / ratio
    X, Z = np.meshgrid(np.linspace(-1.3, 1.3, 131), np.linspace(0.05, 1.5, 59))
    Xs, Ys = np.meshgrid(np.linspace(-1.3, 1.3, 261), np.linspace(0, 1.3 * ay, 53))
    for mu, sign in ((mu_c - 0.006, -1), (mu_c + 0.006, 1)):
        sec = subsurface._criterion(subsurface._nd_stress(1.0, ay, nu, mu, X, 0.0, Z), crit)
        sur = subsurface._criterion(subsurface._nd_stress(1.0, ay, nu, mu, Xs, Ys, 0.0), crit)
        assert sign * (sur.max() - sec.max()) > 0, mu


# ----------------------------------------------------------------- maxima with traction
class TestMaxima:
    def test_small_traction_continuous_with_the_axis(self):
        c = contact(3.0)
        for f, attr in ((subsurface.max_shear, "tau_max"), (subsurface.von_mises, "sigma_vm")):
            a, b = f(c), f(c, traction=1e-9)
            assert getattr(b, attr) == pytest.approx(getattr(a, attr), rel=1e-10)
            assert b.depth == pytest.approx(a.depth, abs=1e-6 * c.b)
            assert abs(b.x) < 1e-6 * c.b and b.y == 0 and not b.at_surface

    @pytest.mark.parametrize("mu", [0.2, 0.45])
    def test_reported_maximum_is_the_field_maximum(self, mu):
        """The value reported is the criterion at the reported point, and no point of a
        fine grid over the section y = 0 and the surface exceeds it."""
        c = contact(4.0)
        b, a = float(c.b), float(c.a)
        for f, attr, prop in ((subsurface.max_shear, "tau_max", "tresca"),
                              (subsurface.von_mises, "sigma_vm", "von_mises")):
            m = f(c, traction=mu)
            at = getattr(subsurface.stress(c, m.x, m.y, m.depth, traction=mu), prop)
            assert at == pytest.approx(getattr(m, attr), rel=1e-12)
            X, Z = np.meshgrid(np.linspace(-1.5, 1.5, 121) * b, np.linspace(0, 1.5, 61) * b)
            sec = getattr(subsurface.stress(c, X, 0.0, Z, traction=mu), prop)
            Xs, Ys = np.meshgrid(np.linspace(-1.5, 1.5, 121) * b, np.linspace(0, 1.4, 57) * a)
            sur = getattr(subsurface.stress(c, Xs, Ys, 0.0, traction=mu), prop)
            assert max(sec.max(), sur.max()) <= getattr(m, attr) * (1 + 1e-12)
        if mu == 0.45:
            assert subsurface.von_mises(c, traction=mu).at_surface

    @pytest.mark.parametrize("mu", [0.1, 0.3])
    def test_line_max_shear(self, mu):
        lc = line()
        b, p = float(lc.b), float(lc.p_max)
        a, z = subsurface.line_max_shear(lc), subsurface.line_max_shear(lc, traction=0.0)
        assert (a.tau_max, a.depth, a.x) == (z.tau_max, z.depth, z.x)
        m = subsurface.line_max_shear(lc, traction=mu)
        assert subsurface.line_stress(lc, m.x, m.depth, traction=mu).tresca == pytest.approx(
            m.tau_max, rel=1e-12)
        X, Z = np.meshgrid(np.linspace(-1.5, 1.5, 301) * b, np.linspace(0, 1.5, 151) * b)
        assert subsurface.line_stress(lc, X, Z, traction=mu).tresca.max() <= m.tau_max * (1 + 1e-12)
        assert m.tau_max / p > a.tau_max / p
        assert m.at_surface == (mu > 0.2468)        # critical_traction(0, 0.3, "tresca")

    def test_negative_traction_mirrors_the_maximum(self):
        c = contact(1.0)
        m1, m2 = subsurface.max_shear(c, traction=0.15), subsurface.max_shear(c, traction=-0.15)
        assert m2.tau_max == pytest.approx(m1.tau_max, rel=1e-10)
        assert m2.x == pytest.approx(-m1.x, abs=1e-7 * c.b)
        assert m2.depth == pytest.approx(m1.depth, abs=1e-7 * c.b)


# ----------------------------------------------------------------- invariants (hypothesis)
ALPHA = st.floats(1.0, 1e3)
UNIT = st.floats(-2.5, 2.5)
MU = st.floats(0.01, 1.0)


@settings(max_examples=40, deadline=None)
@given(alpha=ALPHA, xi=UNIT, eta=UNIT, mu=MU)
def test_surface_equilibrium(alpha, xi, eta, mu):
    """On the surface sigma_zz = -p, tau_xz = -mu p (the traction acts on the body along
    +x and the outward normal is -z), tau_yz = 0; zero outside the patch."""
    c = contact(alpha)
    x, y = xi * c.semi_axis_x, eta * c.semi_axis_y
    p = c.pressure(x, y) / c.p_max
    s = nd(subsurface.stress(c, x, y, 0.0, traction=mu), c.p_max)
    # near the edge p = sqrt(1 - rho^2) amplifies the rounding of the coordinates by
    # dp/drho ~ 1/p: 1e-16 in rho is 1e-16/p in p (xi = 0, eta = 0.99999 gives 1.2e-14)
    tol = 4e-15 + 2e-16 / max(float(p), 1e-3)
    assert s[2] == pytest.approx(-p, abs=tol)
    assert s[4] == pytest.approx(-mu * p, abs=tol)
    assert s[5] == 0
    s1 = nd(subsurface.stress(c, x, y, 1e-10 * c.b, traction=mu), c.p_max)
    if abs(1 - xi * xi - eta * eta) > 1e-3:   # away from the edge (singular gradient)
        assert np.max(np.abs(s1 - s)) < 1e-6


@settings(max_examples=30, deadline=None)
@given(alpha=ALPHA, xi=UNIT, eta=UNIT, zeta=st.floats(0, 3), mu=MU, nu=st.floats(-0.9, 0.5))
def test_linear_in_mu_and_symmetric(alpha, xi, eta, zeta, mu, nu):
    """stress(mu) - stress(0) = mu T with T independent of mu (superposition); T has the
    opposite x-parity of the normal field (sxx, syy, szz, syz odd; sxy, sxz even) and the
    same y-parity (sxy, syz odd)."""
    c = contact(alpha)

    def T(xs, ys, m):
        return traction_part(c, xs * c.semi_axis_x, ys * c.semi_axis_y, zeta * c.b, m, nu)

    t = T(xi, eta, mu)
    assert np.max(np.abs(T(xi, eta, 0.37) - t)) < 1e-13
    assert np.max(np.abs(T(xi, eta, -mu) - t)) < 1e-13
    odd_x = np.array([-1, -1, -1, 1, 1, -1])
    odd_y = np.array([1, 1, 1, -1, 1, -1])
    assert np.max(np.abs(T(-xi, eta, mu) - odd_x * t)) < 1e-13
    assert np.max(np.abs(T(xi, -eta, mu) - odd_y * t)) < 1e-13


@settings(max_examples=25, deadline=None)
@given(alpha=st.floats(1.0, 100.0), xi=st.floats(-2, 2), eta=st.floats(-2, 2),
       zeta=st.floats(0.1, 2.0), nu=st.floats(0.0, 0.5))
def test_equilibrium(alpha, xi, eta, zeta, nu):
    """div(sigma) = 0 for the traction field (4th-order central differences)."""
    div = divergence(contact(alpha), xi, eta, zeta, nu, traction=0.5)
    assert np.max(np.abs(div)) < 1e-7


@settings(max_examples=30, deadline=None)
@given(xi=st.floats(-3, 3), zeta=st.floats(0.05, 3), nu=st.floats(0, 0.5), mu=MU)
def test_line_equilibrium_and_parity(xi, zeta, nu, mu):
    lc = line()
    b, p = float(lc.b), float(lc.p_max)
    h = 1e-3 * zeta * b
    off = np.array([-2, -1, 1, 2]) * h
    w = np.array([1, -8, 8, -1]) / (12 * h)
    sx = subsurface.line_stress(lc, xi * b + off, zeta * b, nu, traction=mu)
    sz = subsurface.line_stress(lc, xi * b, zeta * b + off, nu, traction=mu)
    assert abs(w @ sx.sxx + w @ sz.sxz) * b / p < 1e-7
    assert abs(w @ sx.sxz + w @ sz.szz) * b / p < 1e-7
    s = subsurface.line_stress(lc, xi * b, zeta * b, nu, traction=mu)
    m = subsurface.line_stress(lc, -xi * b, zeta * b, nu, traction=-mu)   # mirror
    assert m.sxx == pytest.approx(s.sxx, abs=1e-15 * p)
    assert m.szz == pytest.approx(s.szz, abs=1e-15 * p)
    assert m.sxz == pytest.approx(-s.sxz, abs=1e-15 * p)


# ----------------------------------------------------------------- convergence
def test_quadrature_converges(monkeypatch):
    """The trapezoid in ln(w - lambda) converges exponentially: the traction part at step
    0.5 (the default) agrees with steps 0.35 and 0.2 (and wider ranges) to < 5e-15 p0,
    while a coarse step 1.0 is visibly off - the differences fall as the step shrinks."""
    rng = np.random.default_rng(5)
    c = contact(50.0)
    x = rng.uniform(-2, 2, 150) * c.b
    y = rng.uniform(-1.5, 1.5, 150) * c.a
    z = np.concatenate([np.zeros(30), 10.0 ** rng.uniform(-9, 0.5, 120)]) * c.b
    out = {}
    for step, below, above in ((1.0, 80.0, 38.0), (0.7, 80.0, 38.0), (0.5, 80.0, 38.0),
                               (0.35, 95.0, 50.0), (0.2, 110.0, 60.0)):
        monkeypatch.setattr(subsurface, "_H_STEP", step)
        monkeypatch.setattr(subsurface, "_S_BELOW", below)
        monkeypatch.setattr(subsurface, "_S_ABOVE", above)
        out[step] = traction_part(c, x, y, z, 1.0)
    d = {s: np.max(np.abs(out[s] - out[0.2])) for s in (1.0, 0.7, 0.5, 0.35)}
    assert d[0.5] < 5e-15 and d[0.35] < 5e-15
    assert d[1.0] > d[0.7] > 10 * d[0.5]


# ----------------------------------------------------------------- teaching figure
def test_teach_traction_figure(tmp_path):
    """``ballrace teach subsurface --traction``: the figure is written and the numbers it
    marks are the library's (circle: the Hamilton-Goodman edge tension)."""
    from ballrace.teach import figures

    out = tmp_path / "t.png"
    info = figures.traction_figure(2000.0, 6.35e-3, 6.35e-3, E=200e9, nu=0.3, traction=0.3,
                                   path=out, n=21)
    assert out.stat().st_size > 10_000
    ref = 0.4 / 3 + 4.3 * np.pi * 0.3 / 8
    assert info["trailing-edge sigma_x / p0"] == pytest.approx(ref, abs=1e-4)
    assert info["largest surface tension / p0 at (x, y) / b"] == pytest.approx((ref, -1, 0),
                                                                            abs=1e-4)
    assert info["Tresca max / p0 at (x, z) / b"][2] == 0.0      # above mu_c = 0.288


# ----------------------------------------------------------------- input validation
def test_traction_range():
    c = contact(1.0)
    with pytest.raises(ValueError, match=r"^traction must be in \[-10, 10\]"):
        subsurface.stress(c, 0.0, 0.0, 1e-4, traction=11.0)
    with pytest.raises(ValueError, match=r"^traction must be"):
        subsurface.line_stress(line(), 0.0, 0.0, traction=np.nan)
    with pytest.raises(ValueError, match=r"^ratio must be in \[0, 1\]"):
        subsurface.critical_traction(1.5)
    with pytest.raises(ValueError, match="criterion must be one of"):
        subsurface.critical_traction(0.0, criterion="principal")
