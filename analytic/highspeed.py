r"""High-speed ball-bearing equilibrium with ball centrifugal force and gyroscopic moment.

Quasi-static model of Jones (1960), as given by Hamrock & Dowson (1981) §3.4,
eqs. (3.93)–(3.112), and Harris (2001) ch. 25 (high-speed operation).  The outer ring
is fixed in space, the inner ring moves by u = (dx, dy, dz, theta_y, theta_z) exactly as
in :mod:`ballrace.analytic.loaddist` (same axes, same reference configuration: balls
just touching at the free contact angle, groove-centre separation
``(A sin beta_f, A cos beta_f)``, A = (f_i + f_o - 1) D).

Per ball j (azimuth psi_j) the unknowns are the axial and radial position
(X1, X2) of the ball centre relative to the outer-groove curvature centre (Harris's
V_1, V_2 form of H&D's L3, L4).  The inner-groove centre sits at

.. math::
    A_{1j} = A\sin\beta_f + d_x + \mathcal{R}_i(\theta_y\sin\psi_j - \theta_z\cos\psi_j),
    \qquad A_{2j} = A\cos\beta_f + d_y\cos\psi_j + d_z\sin\psi_j

(H&D eqs. 3.93–3.95), and the contact geometry follows (H&D eqs. 3.96–3.101):

.. math::
    l_o = \sqrt{X_1^2 + X_2^2}, \quad \delta_o = l_o - (f_o - \tfrac12)D, \quad
    \tan\alpha_o = X_1 / X_2,

    l_i = \sqrt{(A_1 - X_1)^2 + (A_2 - X_2)^2}, \quad \delta_i = l_i - (f_i - \tfrac12)D,
    \quad \tan\alpha_i = (A_1 - X_1)/(A_2 - X_2),

    Q_i = K_i(\alpha_i)\langle\delta_i\rangle^{3/2}, \qquad
    Q_o = K_o(\alpha_o)\langle\delta_o\rangle^{3/2}

with exact-Hertz K at each contact's own angle (H&D eq. 3.33; at zero speed this is the
``K_n(beta)`` model of :mod:`~ballrace.analytic.loaddist`).  Ball equilibrium (H&D eqs.
3.104–3.105; Harris 2001 ch. 25):

.. math::
    Q_i\sin\alpha_i - Q_o\sin\alpha_o
        - \frac{\lambda_i M_g}{D}\cos\alpha_i + \frac{\lambda_o M_g}{D}\cos\alpha_o = 0,

    Q_i\cos\alpha_i - Q_o\cos\alpha_o
        + \frac{\lambda_i M_g}{D}\sin\alpha_i - \frac{\lambda_o M_g}{D}\sin\alpha_o
        + F_c = 0,

with the centrifugal force and gyroscopic moment (H&D eqs. 3.106–3.108)

.. math::
    F_c = \tfrac12 m\, d_{orbit}\, \omega_c^2, \qquad
    M_g = J\,\omega_R\,\omega_c \sin\beta, \qquad m = \rho\pi D^3/6, \quad J = m D^2/10,

where omega_c, omega_R and the pitch angle beta come from the race-control kinematics of
:mod:`ballrace.analytic.kinematics` at the current contact angles, and d_orbit is the
actual orbit diameter of the ball centre (H&D eq. 3.107).  omega_R is signed as in
Harris (negative for inner-ring rotation), so M_g is negative then; the friction forces
lambda M_g / D that resist it are derived here from the ball's angular-momentum balance
and agree in sign with Harris's equations.  lambda_o = 2, lambda_i = 0 for outer-race
control; lambda_i = lambda_o = 1 otherwise (Harris 2001), or all of it at the
controlling race (``gyroscopic="controlling-race"``, H&D eq. 3.104 with lambda = 0, 1).

Inner-ring equilibrium (H&D eqs. 3.111–3.112 extended to five DOFs as in
:mod:`~ballrace.analytic.loaddist`, moment arm R_i of the groove centres, plus the
moment f_i lambda_i M_g of the inner friction force about the groove centre):

.. math::
    F_a = \sum_j T_j,\quad T_j = Q_{ij}\sin\alpha_{ij} - \frac{\lambda_i M_{gj}}{D}\cos\alpha_{ij},
    \qquad F_y = \sum_j P_j\cos\psi_j,\quad F_z = \sum_j P_j\sin\psi_j,\quad
    P_j = Q_{ij}\cos\alpha_{ij} + \frac{\lambda_i M_{gj}}{D}\sin\alpha_{ij},

    M_y = \sum_j (\mathcal{R}_i T_j + f_i\lambda_i M_{gj})\sin\psi_j, \qquad
    M_z = -\sum_j (\mathcal{R}_i T_j + f_i\lambda_i M_{gj})\cos\psi_j .

The grooves are half tori, as in :mod:`~ballrace.analytic.loaddist`: a race touches a
ball only where the line of centres lies less than 90 deg from its groove bottom
(A_2 - X_2 > 0 at the inner race, X_2 > 0 at the outer race); a ball that overlaps the
full torus beyond that edge carries nothing there (it would bear on the land) and is
flagged.  The angles reported (``inner_contact_angles``, ``outer_contact_angles``) are
those of the lines of centres, along which Q and the friction forces lambda M_g / D act:
with the reported loads, friction shares (``inner_friction_share``,
``outer_friction_share``), M_g and F_c they satisfy every ball balance and the ring
balance above to the solver tolerance.  The speeds use kinematic angles (reported
separately) that blend an open contact's undefined angle into the line of groove centres
over its first 1e-5 D of approach; with it inner-race control fades into outer-race
control, and the friction share of a contact into zero, as the contact opens (a smooth
step, 3t^2 - 2t^3).

Where the quasi-static model's assumptions break, the result says so
(``result.warnings``, per-ball flags, each also logged as a warning): a ball past a
groove edge (or beyond a given shoulder), a ball whose contact would need more friction
than ``friction_coefficient`` (default :data:`TRACTION_LIMIT`) times its load to resist
M_g (it skids), or a cage speed outside the rolling range (:data:`CAGE_RATIO_RANGE`).

Solution: Newton on all 2Z + (free ring DOFs) unknowns at once, the Jacobian by central
differences exploiting the block structure (ball residuals depend only on their own
ball, the cage speed and the ring; ring residuals are sums over balls; all perturbed
states evaluated in one batch), with a backtracking line search on the scaled residual
(the halved steps evaluated in one batch) and, once Newton converges quadratically,
chord steps that reuse the last factorised Jacobian.
Starting values come from the static solution (:func:`ballrace.analytic.loaddist.solve`):
loaded balls on their static line of centres, unloaded balls pressed by the centrifugal
force onto the outer race as near its groove bottom as the inner race lets them.  If
Newton fails from there, the solution is followed in speed from the static one (Euler
predictor, Newton corrector, adaptive step; where the branch bends sharply, steps down to
2^-14 of the speed); where that branch ends before the full speed -- at a groove edge,
or where the friction needed exceeds the contact loads -- :class:`ConvergenceError` says
where and why.  Where other equilibria exist for the same inputs, this is the one
connected to the static solution (see :func:`solve`, Notes).  At zero speed every ball
lies on the line of centres with the deflection shared in the ratio of the contact
stiffnesses, which is exactly the static model; this is used when both ring speeds are
zero.  The exact-Hertz
K(alpha) of each race is evaluated from a Chebyshev series in cos(alpha) fitted once per
bearing to 1e-13 of :func:`ballrace.analytic.hertz.contact_stiffness`.
"""
from __future__ import annotations

import functools
import logging
from dataclasses import dataclass

import numpy as np

from . import _operating, hertz, newton
from ._checks import as_array, broadcast, check_choice, check_positive, check_range
from .bearing import BallBearing
from ..errors import ConvergenceError
from .newton import POLICY

__all__ = [
    "CAGE_RATIO_RANGE",
    "CONTROLS",
    "GYROSCOPIC",
    "TRACTION_LIMIT",
    "ORBITALS",
    "HighSpeedResult",
    "ConvergenceError",
    "ball_mass",
    "ball_inertia",
    "centrifugal_force",
    "gyroscopic_moment",
    "solve",
]

log = logging.getLogger(__name__)

#: Race-control hypotheses accepted by :func:`solve`.
CONTROLS = ("outer", "inner", "jones")
#: Orbital-speed models accepted by :func:`solve`: one cage speed for all balls, or
#: Jones's independent kinematics of every ball.
ORBITALS = ("cage", "ball")
#: Treatments of the gyroscopic moment accepted by :func:`solve`.
GYROSCOPIC = ("harris", "controlling-race", "none")
#: Traction coefficient [-] above which a ball is flagged as skidding when no
#: ``friction_coefficient`` is given: an upper value of the traction of lubricated
#: rolling contacts (order of magnitude; not checked against a specific source).
TRACTION_LIMIT = 0.1
#: Rolling range of the cage speed ratio f = (omega_c - omega_o)/(omega_i - omega_o):
#: flagged below CAGE_RATIO_RANGE[0] (1 - D/d_m) and above CAGE_RATIO_RANGE[1].  Rolling
#: without slip on both races at contact angles between 0 and 90 deg gives
#: f = (1 - (D/d_m) cos alpha)/2, between (1 - D/d_m)/2 and 1/2 (H&D 1981 eq. 3.77);
#: the flags are set at half the lower and 0.9 (the balls nearly carried round with the
#: ring) -- screening limits, not material data.
CAGE_RATIO_RANGE = (0.25, 0.9)


# =========================================================================== formulas
def ball_mass(D, density):
    r"""Mass of a solid ball m = rho pi D^3 / 6 [kg].

    .. math:: m = \frac{\rho\pi D^3}{6}

    Parameters
    ----------
    D : float or array_like
        Ball diameter [m].
    density : float or array_like
        Ball material density [kg/m^3].

    References
    ----------
    Hamrock & Dowson (1981) eq. (3.106) (m); Harris (2001) ch. 25.

    Examples
    --------
    >>> round(float(ball_mass(22.225e-3, 7850.0)) * 1e3, 3)   # 7/8 in steel ball [g]
    45.123
    """
    D = check_positive(D, "D", "m", bounded=True)
    rho = check_positive(density, "density", "kg/m^3", bounded=True)
    D, rho = broadcast(D=D, density=rho)
    return hertz.scalar_result(rho * np.pi * D**3 / 6.0)


def ball_inertia(D, density):
    r"""Polar mass moment of inertia of a solid ball J = m D^2 / 10 [kg m^2].

    .. math:: J = \frac{m D^2}{10} = \frac{\rho\pi D^5}{60}

    Parameters
    ----------
    D : float or array_like
        Ball diameter [m].
    density : float or array_like
        Ball material density [kg/m^3].

    References
    ----------
    Hamrock & Dowson (1981) eq. (3.108) (I_p); Harris (2001) ch. 25.

    Examples
    --------
    >>> round(float(ball_inertia(22.225e-3, 7850.0)) * 1e6, 4)   # [kg mm^2]
    2.2288
    """
    return hertz.scalar_result(np.asarray(ball_mass(D, density)) * np.asarray(D, float) ** 2 / 10.0)


def centrifugal_force(D, density, d_m, orbital_speed):
    r"""Ball centrifugal force F_c = (1/2) m d_m omega_c^2 [N].

    .. math:: F_c = \tfrac12\, m\, d_m\, \omega_c^2

    Parameters
    ----------
    D : float or array_like
        Ball diameter [m].
    density : float or array_like
        Ball density [kg/m^3].
    d_m : float or array_like
        Diameter of the ball-centre orbit (pitch diameter) [m].
    orbital_speed : float or array_like
        Orbital (cage) angular speed omega_c [rad/s].

    References
    ----------
    Hamrock & Dowson (1981) eq. (3.106); Jones (1960); Harris (2001) ch. 25.

    Examples
    --------
    218 bearing ball (D = 22.225 mm, d_m = 125.26 mm), cage at 0.415 x 10,000 rpm:

    >>> wc = 0.415 * 10000 * 2 * np.pi / 60
    >>> round(float(centrifugal_force(22.225e-3, 7850.0, 125.26e-3, wc)), 1)
    533.7
    """
    m = np.asarray(ball_mass(D, density))
    d_m = check_positive(d_m, "d_m", "m", bounded=True)
    w = as_array(orbital_speed, "orbital_speed", bounded=True, tiny_ok=True, unit="rad/s")
    broadcast(D=D, density=density, d_m=d_m, orbital_speed=w)
    return hertz.scalar_result(0.5 * m * d_m * w * w)


def gyroscopic_moment(D, density, ball_speed, orbital_speed, pitch_angle):
    r"""Gyroscopic moment on a ball M_g = J omega_R omega_c sin(beta) [N m].

    .. math:: M_g = J\,\omega_R\,\omega_c\,\sin\beta, \qquad J = \frac{m D^2}{10}

    Signed with omega_R as in :mod:`ballrace.analytic.kinematics` (negative for a
    positive inner-ring speed).

    Parameters
    ----------
    D : float or array_like
        Ball diameter [m].
    density : float or array_like
        Ball density [kg/m^3].
    ball_speed : float or array_like
        Ball angular speed about its own axis relative to the cage omega_R [rad/s].
    orbital_speed : float or array_like
        Orbital (cage) speed omega_c [rad/s].
    pitch_angle : float or array_like
        Angle beta of the ball axis to the bearing axis [rad].

    References
    ----------
    Hamrock & Dowson (1981) eq. (3.108); Jones (1960); Harris (2001) ch. 25.

    Examples
    --------
    >>> round(float(gyroscopic_moment(22.225e-3, 7850.0, -2600.0, 435.0, np.radians(35))), 4)
    -1.4459
    """
    J = np.asarray(ball_inertia(D, density))
    wR = as_array(ball_speed, "ball_speed", bounded=True, tiny_ok=True, unit="rad/s")
    wc = as_array(orbital_speed, "orbital_speed", bounded=True, tiny_ok=True, unit="rad/s")
    b = check_range(pitch_angle, "pitch_angle", -np.pi / 2, np.pi / 2, low_inclusive=True,
                    high_inclusive=True, unit="rad")
    broadcast(D=D, density=density, ball_speed=wR, orbital_speed=wc, pitch_angle=b)
    return hertz.scalar_result(J * wR * wc * np.sin(b))


# =========================================================================== model
@dataclass(frozen=True)
class _Model:
    """Plain numbers of a bearing for the kernels."""

    D: float
    dm: float
    Z: int
    A: float
    sbf: float
    cbf: float
    Ri: float
    Roc: float
    ri: float
    ro: float
    f_i: float
    Ep: float
    Ry_i: float
    Ry_o: float
    mass: float
    J: float
    cheb: tuple = (None, None)
    rho: float = 0.0
    cp: object = None          # cos, sin of the ball azimuths psi_j (BallBearing.azimuths(0))
    sp: object = None
    zero: object = None        # zeros, shape (Z,)

    @staticmethod
    @functools.lru_cache(maxsize=64)
    def of(b: BallBearing) -> "_Model":
        if b.n_rows != 1:
            raise NotImplementedError("high-speed analysis is implemented for single-row "
                                      f"bearings (n_rows=1); got n_rows={b.n_rows}")
        D = b.ball_diameter
        A = b.curvature_center_distance
        m = b.ball_mass
        model = _Model(D=D, dm=b.pitch_diameter, Z=b.n_balls, A=A,
                      sbf=float(np.sin(b.free_contact_angle)),
                      cbf=float(np.cos(b.free_contact_angle)),
                      Ri=b.inner_groove_center_radius,
                      Roc=0.5 * b.outer_race_diameter - b.f_outer * D,
                      ri=(b.f_inner - 0.5) * D, ro=(b.f_outer - 0.5) * D, f_i=b.f_inner,
                      Ep=b.E_prime, Ry_i=b.f_inner * D / (2 * b.f_inner - 1),
                      Ry_o=b.f_outer * D / (2 * b.f_outer - 1), mass=m, J=m * D * D / 10.0)
        psi = b.azimuths(0.0)
        return _Model(**{**model.__dict__, "cheb": _stiffness_fit(model), "rho": D / model.dm,
                         "cp": np.cos(psi), "sp": np.sin(psi),
                         "zero": np.zeros(b.n_balls)})


def _stiffness_exact(model, ci, co):
    """K_i, K_o [N/m^1.5] at cos(alpha_i) = ci, cos(alpha_o) = co (H&D 1981 eq. 3.33)."""
    rho = model.D / model.dm
    Rx = np.concatenate([0.5 * model.D * (1.0 - rho * ci), 0.5 * model.D * (1.0 + rho * co)])
    Ry = np.concatenate([np.full(np.shape(ci), model.Ry_i), np.full(np.shape(co), model.Ry_o)])
    K = hertz.contact_stiffness(Rx, Ry, model.Ep)
    n = np.size(ci)
    return K[:n], K[n:]


def _stiffness_fit(model):
    """Chebyshev series of K_i, K_o in cos(alpha) over [-1, 1] (degree 80), or None where
    the series is not within 1e-13 of the exact K at 97 check points.

    K is analytic in cos(alpha) on [-1, 1] (R_x > 0 for D/d_m < 1), so the series
    converges geometrically; the solver evaluates it instead of solving for the
    ellipticity at every call (same values to ~1e-15)."""
    from numpy.polynomial import chebyshev as ch
    n = 81                                  # Chebyshev nodes; coefficients by the DCT
    th = np.pi * (np.arange(n) + 0.5) / n
    c = np.cos(th)
    Ki, Ko = _stiffness_exact(model, c, c)
    dct = (2.0 / n) * np.cos(np.outer(np.arange(n), th))
    dct[0] *= 0.5
    t = np.linspace(-1.0, 1.0, 97)
    ti, to = _stiffness_exact(model, t, t)
    out = []
    for K, T in ((Ki, ti), (Ko, to)):
        full = dct @ K
        coef = None
        for n in (12, 16, 20, 24, 32, 40, 48, 64, 80):     # shortest series that is exact
            if np.max(np.abs(ch.chebval(t, full[:n + 1]) / T - 1.0)) <= 1e-13:
                coef = full[:n + 1]
                break
        out.append(coef)
    return tuple(out)


def _stiffness(model, ai, ao):
    """Race contact stiffnesses K_i(alpha_i), K_o(alpha_o) [N/m^1.5] (H&D 1981 eq. 3.33)."""
    fi, fo = model.cheb
    if fi is None or fo is None:
        return _stiffness_exact(model, np.cos(ai), np.cos(ao))
    # T_k(cos a) = cos(k a): the series is a cosine series in the angle itself
    return (np.cos(np.multiply.outer(ai, _ARANGE[:fi.size])) @ fi,
            np.cos(np.multiply.outer(ao, _ARANGE[:fo.size])) @ fo)


_ARANGE = np.arange(81.0)


def _lambdas(outer, gyro):
    """(lambda_i, lambda_o) per ball for the race control mask ``outer`` (Harris 2001)."""
    if gyro == "harris":
        li = np.where(outer, 0.0, 1.0)
        lo = np.where(outer, 2.0, 1.0)
    else:                                              # controlling race (H&D eq. 3.104)
        li = np.where(outer, 0.0, 2.0)
        lo = np.where(outer, 2.0, 0.0)
    return li, lo


#: Largest reported angle [rad]: the groove edge, just inside pi/2 (Hertz curvatures need
#: |alpha| < pi/2).
_EDGE = float(np.nextafter(0.5 * np.pi, 0.0))


def _smoothstep(t):
    """0 for t <= 0, 1 for t >= 1, 3t^2 - 2t^3 between (continuous slope) [-]."""
    t = np.minimum(np.maximum(t, 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def _blend(full, on, d, a, base, d_ref):
    """(weight, kinematic angle) of one race's contacts: the mechanical angle ``a`` where
    the contact is closed beyond the blend deflection ``d_ref``, the groove-centre line
    angle ``base`` where it is open, smoothly in between; ``full``: every contact closed
    beyond the blend (weight 1, the same bits as the general formula)."""
    if full:
        return np.ones(a.shape), base + (a - base)
    w = np.where(on, _smoothstep(d / d_ref), 0.0)
    return w, base + w * (np.where(on, a, base) - base)


def _groove_centres(m, u):
    """Inner-groove curvature centres (A1, A2) of the balls [m] for ring displacements u
    (..., 5) (H&D 1981 eqs. 3.93-3.95); shape (..., Z)."""
    cp, sp = m.cp, m.sp
    u = np.asarray(u, float)
    if u.ndim == 1:                          # (plain floats: cheaper than (1,) arrays)
        u0, u1, u2, u3, u4 = (float(v) for v in u)
        tilt, off = u3 != 0.0 or u4 != 0.0, u2 != 0.0
    else:
        u0, u1, u2, u3, u4 = (u[..., k:k + 1] for k in range(5))
        tilt, off = bool(u[..., 3:].any()), bool(u2.any())
    # (terms of a zero displacement are left out: same values)
    a1 = m.A * m.sbf + u0
    A1 = a1 + m.Ri * (u3 * sp - u4 * cp) if tilt else a1 + m.zero
    A2 = m.A * m.cbf + u1 * cp + u2 * sp if off else m.A * m.cbf + u1 * cp
    return A1, A2


def _static_positions(m, A1, A2):
    """Ball centres (X1, X2) [m] of the zero-speed equilibrium for inner-groove centres
    (A1, A2): on the line of centres, the deflection shared in the ratio of the contact
    stiffnesses."""
    s = np.hypot(A1, A2)
    a = np.arctan2(A1, A2)
    Ki, Ko = _stiffness(m, a, a)
    wo_ = Ko ** (-2.0 / 3.0) / (Ki ** (-2.0 / 3.0) + Ko ** (-2.0 / 3.0))
    lo_ = m.ro + wo_ * (s - m.A)
    # (a ball whose line of groove centres points past 90 deg is unloaded, as in
    # loaddist: it rests at the outer-groove bottom, clear of both races)
    past = ~(A2 > 0)
    return np.where(past, 0.0, lo_ * np.sin(a)), np.where(past, m.ro, lo_ * np.cos(a))


class _Balls:
    """Per-ball state: geometry, loads, kinematics, residuals and ring contributions.

    Arrays X1, X2 have shape (..., Z) and u shape (..., 5): several states at once (the
    Jacobian evaluates all its perturbed states in one batch).  Written for few NumPy
    calls per state (the solver spends its time here): terms that vanish exactly (no
    tilt, no inner-controlled ball) are skipped, which changes no value."""

    def __init__(self, model, X1, X2, u, wi, wo, outer, gyro, static,
                 orbital="ball", wc_fixed=None):
        m = model
        cp, sp = m.cp, m.sp
        self.A1, self.A2 = A1, A2 = _groove_centres(m, u)
        if static:
            self.X1s, self.X2s = _static_positions(m, A1, A2)
        self.X1, self.X2 = X1, X2
        lo = np.hypot(X1, X2)
        e1, e2 = A1 - X1, A2 - X2
        li = np.hypot(e1, e2)
        self.do = lo - m.ro
        self.di = li - m.ri
        self.sao, self.cao = sao, cao = X1 / lo, X2 / lo
        self.sai, self.cai = sai, cai = e1 / li, e2 / li
        self.ao = np.arctan2(X1, X2)
        self.ai = np.arctan2(e1, e2)
        # The grooves are half tori: a race touches the ball only where the line of
        # centres lies less than 90 deg from its groove bottom (e2 > 0 at the inner race,
        # X2 > 0 at the outer race); beyond that there is no ring material and the
        # contact carries nothing, as in the static model (loaddist._State).
        on_i, on_o = e2 > 0, X2 > 0
        if static:
            # on the line of centres both contacts share its angle: the groove-centre
            # line itself must point outwards, as in loaddist (x > 0), so that round-off
            # at 90 deg cannot load one contact of a ball and not the other
            on_i = on_i & (A2 > 0)
            on_o = on_o & (A2 > 0)
        self.on_i, self.on_o = on_i, on_o
        Ki, Ko = _stiffness(m, self.ai, self.ao)
        # every contact of the race closed beyond the blend (1e-5 D, below): the blend
        # weights are 1 and the masks all true, so those terms are left out (same values)
        d_ref = 1e-5 * m.D
        full_i = bool((on_i & (self.di >= d_ref)).all())
        full_o = bool((on_o & (self.do >= d_ref)).all())
        self.full = full_i and full_o
        self.Qi = Qi = (Ki * self.di ** 1.5 if full_i
                        else np.where(on_i, Ki * np.maximum(self.di, 0.0) ** 1.5, 0.0))
        self.Qo = Qo = (Ko * self.do ** 1.5 if full_o
                        else np.where(on_o, Ko * np.maximum(self.do, 0.0) ** 1.5, 0.0))
        # An open contact has no contact angle: for the kinematics it takes the angle of
        # the line of groove centres, blended in over a deflection of 1e-5 D (loads there
        # are ~1 N or less) so that the equations stay continuous.
        # (the line, not its direction: folded into (-pi/2, pi/2], so that a far-side ball
        # of a ring displaced by more than A cos(beta_f) does not get an angle near pi)
        # These kinematic angles set only the speeds; the forces act along the
        # mechanical angles ai, ao (|ai|, |ao| < pi/2 wherever the contact is loaded).
        z = A2 == 0.0
        base = np.arctan(A1 / np.where(z, 1e-300, A2) if z.any() else A1 / A2)
        self.wgt_i, self.ai_k = wgt_i, ai_k = _blend(full_i, on_i, self.di, self.ai, base, d_ref)
        self.wgt_o, self.ao_k = wgt_o, ao_k = _blend(full_o, on_o, self.do, self.ao, base, d_ref)
        # kinematics (race control) at the current angles
        rho = m.rho
        # a ball cannot be controlled by a race it does not touch: inner control fades
        # into outer control as the inner contact opens (same blend)
        outer = np.asarray(outer, bool)
        all_outer = bool(outer.all())
        c_ao, c_ai = np.cos(ao_k), np.cos(ai_k)
        b_o = np.arctan2(np.sin(ao_k), c_ao + rho)
        if all_outer:
            beta = b_o
        else:
            b_i = np.arctan2(np.sin(ai_k), c_ai - rho)
            beta = np.where(outer, b_o, b_o + wgt_i * (b_i - b_o))
        self.beta = beta
        # race-control kinematics (kinematics._kinematics_beta, the speeds only)
        co = np.cos(ao_k - beta)
        A_o = (1.0 + rho * c_ao) / co
        A_i = (1.0 - rho * c_ai) / np.cos(ai_k - beta)
        wc = (wi * A_i + wo * A_o) / (A_i + A_o)
        self.wR = (wo - wc) * A_o / rho
        self.wc = wc
        if orbital == "cage":
            # One cage: every ball orbits at the cage speed, the mean of the balls'
            # kinematic orbital speeds weighted by Q_i Q_o / (Q_i + Q_o) (balls with an
            # open contact do not drive the cage); each ball rolls without slip on its
            # controlling race at that speed (H&D 1981 eqs. 3.76-3.77 with omega_c given).
            sQ = Qi + Qo
            if full_i and full_o:                # (all loaded: q > 0)
                q = Qi * Qo / sQ
                self.num, self.den = q * wc, q
            else:
                pos = sQ > 0
                q = np.where(pos, Qi * Qo / np.where(pos, sQ, 1.0), 0.0)
                self.num, self.den = q * np.where(q > 0, wc, 0.0), q
            sq = q.sum(axis=-1, keepdims=True)
            if (full_i and full_o) or (sq > 0).all():
                wc = self.num.sum(axis=-1, keepdims=True) / sq
            else:
                wc = np.where(sq > 0, self.num.sum(axis=-1, keepdims=True)
                              / np.where(sq > 0, sq, 1.0),
                              # no ball drives: classical value
                              0.5 * (wi * (1 - rho * np.cos(base))
                                     + wo * (1 + rho * np.cos(base))))
            if wc_fixed is not None:      # (Jacobian: hold the cage speed; nan: do not)
                wf = np.asarray(wc_fixed, float)
                wc = np.where(np.isnan(wf), wc, wf)
            self.wc = wc = wc + np.zeros(Qi.shape)
            self.wc_cage = wc.sum(axis=-1) / m.Z
            # (cos(ao_k - b_o) is co where beta = b_o)
            wR_o = (wo - wc) * (1.0 + rho * c_ao) / (
                rho * (co if all_outer else np.cos(ao_k - b_o)))
            if all_outer:
                self.wR = wR_o
            else:
                wR_i = (wc - wi) * (1.0 - rho * c_ai) / (rho * np.cos(ai_k - b_i))
                self.wR = np.where(outer, wR_o, wR_o + wgt_i * (wR_i - wR_o))
        self.Fc = Fc = m.mass * (m.Roc + X2) * wc**2              # (1/2) m d_orbit wc^2
        self.Mg = Mg = m.J * self.wR * wc * np.sin(beta)           # H&D eq. 3.108
        # friction shares (the terms of a zero share are left out: same values)
        if gyro == "none":                      # (reported, not in the equilibrium)
            li_ = lo_ = np.zeros(Fc.shape)
            fric_i = fric_o = False
        elif all_outer:                         # lambda_i = 0, lambda_o = 2 (both rules)
            li_, lo_ = np.zeros(Fc.shape), wgt_o * 2.0
            fric_i, fric_o = False, True
        else:
            li_, lo_ = _lambdas(outer, gyro)
            # no friction without a normal load: an open contact passes its share on
            li_ = wgt_i * li_
            lo_ = wgt_o * (2.0 - li_)
            fric_i = fric_o = True
        self.lam_i, self.lam_o = li_, lo_
        # ball equilibrium (H&D eqs. 3.104-3.105; Harris 2001 ch. 25)
        R1 = Qi * sai - Qo * sao
        R2 = Qi * cai - Qo * cao
        self.T = Qi * sai
        self.P = Qi * cai
        if fric_i:
            gi = li_ * Mg / m.D
            R1 = R1 - gi * cai
            R2 = R2 + gi * sai
            self.T = self.T - gi * cai
            self.P = self.P + gi * sai
        if fric_o:
            go = lo_ * Mg / m.D
            R1 = R1 + go * cao
            R2 = R2 - go * sao
        if static:
            self.R1, self.R2 = X1 - self.X1s, X2 - self.X2s
        else:
            self.R1, self.R2 = R1, R2 + Fc
        # forces on the inner ring (H&D eqs. 3.111-3.112, five DOFs): axial T, radial P,
        # moment Mt about the groove centre's circle
        self.Mt = m.Ri * self.T + m.f_i * li_ * Mg if fric_i else m.Ri * self.T
        self._cp, self._sp = cp, sp

    def ring(self, free):
        """Per-ball forces on the inner ring in the DOFs ``free``, shape (..., Z, nf)."""
        cols = {0: lambda: self.T, 1: lambda: self.P * self._cp, 2: lambda: self.P * self._sp,
                3: lambda: self.Mt * self._sp, 4: lambda: -self.Mt * self._cp}
        if len(free) == 0:
            return np.zeros(self.T.shape + (0,))
        return np.stack([cols[int(k)]() for k in free], axis=-1)

    def ring_sum(self, free):
        """Resultant of the ball forces on the inner ring in the DOFs ``free``, shape
        (..., nf)."""
        cp, sp = self._cp, self._sp
        out = [self.T.sum(axis=-1) if k == 0 else self.P @ cp if k == 1 else
               self.P @ sp if k == 2 else self.Mt @ sp if k == 3 else -(self.Mt @ cp)
               for k in free]
        return np.array(out).T if out else np.zeros(self.T.shape[:-1] + (0,))

    def row(self, k):
        """State k of a batch of states."""
        new = object.__new__(_Balls)
        for name, v in vars(self).items():
            new.__dict__[name] = v[k] if isinstance(v, np.ndarray) and v.ndim >= 2 else v
        if "wc_cage" in new.__dict__:
            new.wc_cage = self.wc_cage[k]
        return new

    @property
    def C(self):
        """Per-ball forces on the inner ring (Fa, Fy, Fz, My, Mz), shape (..., Z, 5)."""
        return self.ring(range(5))

    @property
    def R(self):
        """Ball residuals (axial, radial), shape (..., Z, 2)."""
        return np.stack([self.R1, self.R2], axis=-1)


# =========================================================================== result
@dataclass(frozen=True)
class HighSpeedResult:
    """High-speed equilibrium of a ball bearing (frozen).  Per-ball arrays have shape (Z,).

    Attributes
    ----------
    bearing : BallBearing
        The bearing.
    azimuths : ndarray
        Ball azimuths psi_j from +y towards +z [rad].
    speed_inner, speed_outer : float
        Ring angular speeds [rad/s].
    inner_loads, outer_loads : ndarray
        Ball–race normal loads Q_i, Q_o [N].
    inner_contact_angles, outer_contact_angles : ndarray
        Contact angles alpha_i, alpha_o [rad]: the angles of the lines of centres along
        which Q_i, Q_o and the friction forces act in the force balances (the module
        equations hold with exactly these).  A contact without load reports its line of
        centres, limited to the groove edge (+-pi/2, just inside) where it lies beyond.
    inner_kinematic_angles, outer_kinematic_angles : ndarray
        Angles [rad] used for the speeds (omega_c, omega_R, beta): the contact angle of a
        loaded contact, blended into the angle of the line of groove centres over the
        first 1e-5 D of deflection (an open contact has no rolling point).  Not used in
        the force balances.
    inner_deflections, outer_deflections : ndarray
        Contact deflections delta_i, delta_o [m] (negative: contact open; positive
        without load where the line of centres is past the groove edge, see
        ``beyond_groove_inner``).
    ball_positions : ndarray, shape (Z, 2)
        Axial and radial position (X1, X2) of each ball centre relative to its
        outer-groove curvature centre [m].
    centrifugal_force : ndarray
        Ball centrifugal force F_c [N].
    gyroscopic_moment : ndarray
        Gyroscopic moment M_g = J omega_R omega_c sin(beta) [N m] (signed; resisted by
        friction whether or not it is counted in the equilibrium, see ``gyroscopic``).
    orbital_speed : ndarray
        Ball orbital (cage) angular speed omega_c [rad/s].
    spin_speed : ndarray
        Ball angular speed about its own axis relative to the cage omega_R [rad/s]
        (Harris's sign: negative for inner-ring rotation).
    pitch_angle : ndarray
        Angle beta of the ball's rotation axis to the bearing axis [rad].
    spin_to_roll_inner, spin_to_roll_outer : ndarray
        Spin-to-roll ratios at the two contacts [-].
    control : ndarray of str
        Controlling race of each ball ("outer" or "inner").
    displacements : ndarray, shape (5,)
        Inner-ring displacement (dx, dy, dz [m], theta_y, theta_z [rad]) from the
        reference configuration, as in :mod:`ballrace.analytic.loaddist`.
    loads : ndarray, shape (5,)
        Resultant of the ball forces on the inner ring (Fa, Fy, Fz [N], My, Mz [N m]):
        the applied loads, or the reaction on a DOF held fixed (tilt when
        ``tilt="fixed"``).
    applied : ndarray, shape (5,)
        Applied loads [N, N m].
    residual : float
        Largest equilibrium residual over all ball and ring equations [N] (moments
        divided by R_i).
    relative_residual : float
        ``residual`` over the load scale (max applied load, Z F_c) [-].
    iterations : int
        Newton iterations in total (chord steps, which reuse the last Jacobian,
        included).
    gyroscopic : str
        Treatment of the gyroscopic moment.
    friction_coefficient : float or None
        Friction coefficient used for ``gyroscopic_slip``.
    gyroscopic_slip : ndarray of bool or None
        Per ball, True where the friction needed to resist M_g exceeds mu Q at a
        reacting contact (the ball would pivot; Harris 2001 ch. 25).
    inner_friction_share, outer_friction_share : ndarray
        lambda_i, lambda_o [-]: the friction force resisting M_g at each contact is
        lambda M_g / D (module equations; 0 for a contact without load and for
        ``gyroscopic="none"``).  With the reported loads, angles, M_g and F_c they
        rebuild every ball balance and the ring balance.
    beyond_groove_inner, beyond_groove_outer : ndarray of bool
        Per ball, True where the ball overlaps the full groove torus but its line of
        centres lies 90 deg or more from the groove bottom (no ring material there: the
        contact is taken as unloaded, as in the static model; the ball would bear on
        the land), or where a loaded contact lies beyond the shoulder edge
        (``BallBearing.shoulder_angle``, when given).
    skidding : ndarray of bool
        Per ball, True where the friction needed at a loaded contact to resist the
        gyroscopic moment exceeds ``friction_coefficient`` (default 0.1) times its
        normal load, so that the ball cannot roll as the race-control hypothesis
        assumes (always False with ``gyroscopic="none"``).
    cage_speed_ratio : float
        (omega_c - omega_o) / (omega_i - omega_o) [-] of the mean orbital speed (nan
        when the rings turn together).
    warnings : tuple of str
        Where the quasi-static model's assumptions break: contacts past the groove edge,
        skidding balls, or a cage speed outside the rolling range
        (:data:`CAGE_RATIO_RANGE`); each also logged at WARNING level.  Empty when none.
    """

    bearing: BallBearing
    azimuths: np.ndarray
    speed_inner: float
    speed_outer: float
    inner_loads: np.ndarray
    outer_loads: np.ndarray
    inner_contact_angles: np.ndarray
    outer_contact_angles: np.ndarray
    inner_deflections: np.ndarray
    outer_deflections: np.ndarray
    ball_positions: np.ndarray
    centrifugal_force: np.ndarray
    gyroscopic_moment: np.ndarray
    orbital_speed: np.ndarray
    spin_speed: np.ndarray
    pitch_angle: np.ndarray
    spin_to_roll_inner: np.ndarray
    spin_to_roll_outer: np.ndarray
    control: np.ndarray
    displacements: np.ndarray
    loads: np.ndarray
    applied: np.ndarray
    residual: float
    relative_residual: float
    iterations: int
    gyroscopic: str
    friction_coefficient: float | None = None
    gyroscopic_slip: np.ndarray | None = None
    inner_kinematic_angles: np.ndarray | None = None
    outer_kinematic_angles: np.ndarray | None = None
    inner_friction_share: np.ndarray | None = None
    outer_friction_share: np.ndarray | None = None
    beyond_groove_inner: np.ndarray | None = None
    beyond_groove_outer: np.ndarray | None = None
    skidding: np.ndarray | None = None
    cage_speed_ratio: float = float("nan")
    warnings: tuple = ()

    @property
    def axial_deflection(self) -> float:
        """Axial deflection of the bearing: the inner ring's axial displacement dx relative
        to the outer ring from the reference configuration [m] (as in
        :attr:`ballrace.analytic.loaddist.LoadDistribution.axial_deflection`)."""
        return float(self.displacements[0])

    @property
    def radial_deflection(self) -> float:
        """Radial deflection of the bearing sqrt(dy^2 + dz^2) [m] (inner ring relative to
        the outer ring)."""
        return float(np.hypot(self.displacements[1], self.displacements[2]))

    @property
    def axial_displacement(self) -> float:
        """Deprecated name of :attr:`axial_deflection` (same value) [m]."""
        from ._renames import warn_renamed
        warn_renamed("HighSpeedResult.axial_displacement", "HighSpeedResult.axial_deflection")
        return self.axial_deflection

    @property
    def radial_displacement(self) -> float:
        """Deprecated name of :attr:`radial_deflection` (same value) [m]."""
        from ._renames import warn_renamed
        warn_renamed("HighSpeedResult.radial_displacement", "HighSpeedResult.radial_deflection")
        return self.radial_deflection

    @property
    def max_inner_load(self) -> float:
        """Largest inner-race ball load [N]."""
        return float(np.max(self.inner_loads))

    @property
    def max_outer_load(self) -> float:
        """Largest outer-race ball load [N]."""
        return float(np.max(self.outer_loads))

    @functools.cached_property
    def inner_contacts(self) -> hertz.HertzContact:
        """Hertz contacts on the inner race (a, b, p_max, ...) per ball."""
        return self.bearing.contacts(self.inner_loads, self.inner_contact_angles, "inner")

    @functools.cached_property
    def outer_contacts(self) -> hertz.HertzContact:
        """Hertz contacts on the outer race per ball."""
        return self.bearing.contacts(self.outer_loads, self.outer_contact_angles, "outer")

    @property
    def max_pressure(self) -> float:
        """Largest contact pressure p_max over the balls and both races [Pa]."""
        return float(max(np.max(self.inner_contacts.p_max), np.max(self.outer_contacts.p_max)))

    @property
    def static_safety(self) -> float:
        r"""Static safety of the most loaded contact, s0 = (4200 MPa / p_max)^3 [-].

        From the actual largest contact pressure, inner or outer race (at speed the outer
        contacts also carry the centrifugal force), by
        :func:`~ballrace.analytic.ratings.static_safety_from_pressure` (ISO 76:2006 bases C0
        on 4200 MPa); :func:`solve` warns when it is below 1.
        """
        from .ratings import static_safety_from_pressure
        return float(static_safety_from_pressure(self.max_pressure))

    @property
    def misalignment(self) -> float:
        """Tilt of the inner ring sqrt(theta_y^2 + theta_z^2) [rad]."""
        return float(np.hypot(self.displacements[3], self.displacements[4]))


def _checked(r: HighSpeedResult) -> HighSpeedResult:
    """``r``, after a UserWarning (once per check) where the bearing works beyond its
    limits: s0 < 1, a deep-groove bearing beyond
    :data:`~ballrace.analytic.ratings.DEEP_GROOVE_ANGLE_LIMIT`, a tilt beyond
    :data:`~ballrace.analytic.ratings.PERMISSIBLE_MISALIGNMENT` (these are not part of
    ``r.warnings``, which lists where the quasi-static model itself breaks)."""
    from . import _operating as op

    if op.silenced():
        return r
    what = "high-speed equilibrium"
    b = r.bearing
    safety = None
    if op.may_be_overloaded(b, np.maximum(r.inner_loads, r.outer_loads)):
        safety = op.safety_message(what, r.static_safety, r.max_pressure)
    Q = np.concatenate([r.inner_loads, r.outer_loads])
    angles = np.concatenate([r.inner_contact_angles, r.outer_contact_angles])
    op.emit(safety, op.angle_message(what, b, Q, angles),
            op.tilt_message(what, b, r.misalignment))
    return r


# =========================================================================== solver
def _free_dofs(L, tilt):
    """Free ring DOFs; the others are zero by symmetry or held (tilt="fixed")."""
    Fa, Fy, Fz, My, Mz = L
    free = [0]
    t = tilt == "free"
    if Fy != 0 or (t and Mz != 0):
        free.append(1)
    if Fz != 0 or (t and My != 0):
        free.append(2)
    if t and (My != 0 or Fz != 0):
        free.append(3)
    if t and (Mz != 0 or Fy != 0):
        free.append(4)
    return np.array(free)


class _System:
    """Residual vector, scaling and block finite-difference Jacobian."""

    def __init__(self, model, psi, L, free, wi, wo, gyro, static, F_ref, Q_ref,
                 orbital="cage"):
        self.m, self.psi, self.L, self.free = model, psi, L, free
        self.Lf = L[free]
        self.free_list = [int(k) for k in free]
        self._diag = self._rows = None
        self.orbital = orbital
        self.wi, self.wo, self.gyro, self.static = wi, wo, gyro, static
        self.Z = model.Z
        sc = np.ones(5)
        sc[3:] = 1.0 / model.Ri
        self.load_sc = sc[free] / F_ref             # ring residual scale (moments / R_i)
        self.ball_sc = 1.0 / Q_ref if not static else 1.0 / (1e-4 * model.D)
        self.u_sc = np.where(free >= 3, model.Ri, 1.0)
        # (residual and step scales as vectors over all unknowns)
        self.res_sc = np.concatenate([np.full(2 * self.Z, self.ball_sc), self.load_sc])
        self.step_sc = np.concatenate([np.ones(2 * self.Z), self.u_sc])
        self.outer = np.ones(model.Z, bool)

    def unpack(self, x):
        Z = self.Z
        u = np.zeros(5)
        u[self.free] = x[2 * Z:]
        return x[:Z], x[Z:2 * Z], u

    def balls(self, x, wc_fixed=None):
        X1, X2, u = self.unpack(x)
        return _Balls(self.m, X1, X2, u, self.wi, self.wo, self.outer, self.gyro,
                      self.static, self.orbital, wc_fixed)

    def residual(self, b):
        ring = self.Lf - b.ring_sum(self.free_list)
        return np.concatenate([b.R1, b.R2, ring], axis=-1)

    def scaled(self, r):
        return r * self.res_sc

    def balls_rows(self, X, wc_fixed=None):
        """States of the rows of X (k, 2Z + nf) in one batch."""
        Z = self.Z
        u = np.zeros((X.shape[0], 5))
        u[:, self.free] = X[:, 2 * Z:]
        return _Balls(self.m, X[:, :Z], X[:, Z:2 * Z], u, self.wi, self.wo, self.outer,
                      self.gyro, self.static, self.orbital, wc_fixed)

    def jacobian(self, x, b0=None):
        """Central differences: all balls' X1 (then X2) at once, the cage speed (held for
        the others), then each ring DOF; all perturbed states evaluated together in one
        batch, the differences taken and scaled for all of them at once."""
        if b0 is None:
            b0 = self.balls(x)
        X, wcf, steps = self._jacobian_states(x, b0)
        return self._jacobian_from(self.balls_rows(X, wcf), steps, b0)

    def _jacobian_states(self, x, b0):
        """The perturbed states of the Jacobian at x: rows X (N, n), held cage speeds
        (N, 1) or None, and the steps; step sizes from the state b0, the cage held at
        b0's speed."""
        Z, nf = self.Z, self.free.size
        n = 2 * Z + nf
        # steps: 1e-9 D (1e-4 of the blend width 1e-5 D, so that the differences resolve
        # the blends to ~1e-8), but below 1 % of each contact's deflection or gap so that
        # the difference never straddles the contact edge (delta^1.5 is not smooth at 0)
        hmax, hmin = 1e-9 * self.m.D, 1e-12 * self.m.D
        if getattr(b0, "full", False):      # every contact closed by 1e-5 D: all steps hmax
            hb, h = np.full(Z, hmax), hmax
        else:
            d = 1e-2 * np.minimum(np.abs(b0.di), np.abs(b0.do))
            hb = np.minimum(np.maximum(d, hmin), hmax)
            h = min(max(float(d.min()), hmin), hmax)
        # one cage speed couples all balls: hold it fixed for the per-ball blocks and add
        # the rank-one coupling d(residual)/d(omega_c) x d(omega_c)/dX afterwards
        cage = self.orbital == "cage" and not self.static
        k0 = 4 + 2 * cage
        N = k0 + 2 * nf
        hu = h / self.u_sc
        X = np.empty((N, n))
        X[:] = x
        X[0, :Z] += hb
        X[1, :Z] -= hb
        X[2, Z:2 * Z] += hb
        X[3, Z:2 * Z] -= hb
        rp, rm, cu = self._ring_rows(k0)
        X[rp, cu] += hu
        X[rm, cu] -= hu
        wcf = None
        # inverse steps 1/(2h) of the N/2 differences: X1, X2 per ball, cage, ring DOFs
        inv = np.empty((N // 2, Z))
        inv[0] = inv[1] = 0.5 / hb
        inv[k0 // 2:] = (0.5 / hu)[:, None]
        if cage:
            wcf = np.full((N, 1), np.nan)
            wc0 = float(b0.wc_cage)
            hw = 1e-7 * max(abs(wc0), abs(self.wi), abs(self.wo), 1e-300)
            wcf[:4] = wc0
            wcf[4, 0], wcf[5, 0] = wc0 + hw, wc0 - hw
            inv[2] = 0.5 / hw
        return X, wcf, (inv, k0, cage)

    def _jacobian_from(self, B, steps, b0, first=0):
        """The Jacobian from the batch B of perturbed states (from row ``first``) of
        _jacobian_states; the cage coupling at the state b0."""
        Z, nf = self.Z, self.free.size
        n = 2 * Z + nf
        inv, k0, cage = steps
        R1, R2 = B.R1[first:], B.R2[first:]
        C = B.ring(self.free_list)[first:]                           # (N, Z, nf)
        D1 = (R1[0::2] - R1[1::2]) * inv                             # (N/2, Z)
        D2 = (R2[0::2] - R2[1::2]) * inv
        DC = (C[0::2] - C[1::2]) * inv[:, :, None]                   # (N/2, Z, nf)
        J = np.zeros((n, n))
        Jf = J.reshape(-1)
        Jf[self._diag_index()] = np.concatenate([D1[0], D2[0], D1[1], D2[1]])
        J[2 * Z:, :2 * Z] = -DC[:2].transpose(2, 0, 1).reshape(nf, 2 * Z)
        if cage:
            den = float(b0.den.sum())
            if den > 0:
                # d(omega_c)/dX of the Q_i Q_o/(Q_i + Q_o)-weighted mean
                wc0 = float(b0.wc_cage)
                num, dn = B.num[first:], B.den[first:]
                dnum = (num[0:4:2] - num[1:4:2]) * inv[:2]
                dden = (dn[0:4:2] - dn[1:4:2]) * inv[:2]
                g = ((dnum - wc0 * dden) / den).reshape(2 * Z)
                col = np.concatenate([D1[2], D2[2], -DC[2].sum(axis=0)])
                J[:, :2 * Z] += np.multiply.outer(col, g)
        if nf:
            J[:Z, 2 * Z:] = D1[k0 // 2:].T
            J[Z:2 * Z, 2 * Z:] = D2[k0 // 2:].T
            J[2 * Z:, 2 * Z:] = -DC[k0 // 2:].sum(axis=1).T
        return J

    def _ring_rows(self, k0):
        """Rows (+h, -h) and columns of the ring-DOF perturbations in the Jacobian batch."""
        if self._rows is None:
            ju = np.arange(self.free.size)
            self._rows = (k0 + 2 * ju, k0 + 1 + 2 * ju, 2 * self.Z + ju)
        return self._rows

    def _diag_index(self):
        """Flat indices of the per-ball 2 x 2 blocks in the Jacobian (d R1/d X1, d R2/d X1,
        d R1/d X2, d R2/d X2 of every ball)."""
        if self._diag is None:
            Z, n = self.Z, 2 * self.Z + self.free.size
            i = np.arange(Z)
            self._diag = np.concatenate([i * n + i, (Z + i) * n + i, i * n + Z + i,
                                         (Z + i) * n + Z + i])
        return self._diag


def _damped_newton(sysm, x, rtol, max_iter, min_step=2.0**-39, chord_steps=True):
    """Damped Newton; returns (x, balls, scaled max residual, iterations).

    Stops (unconverged) when the line search needs a step below ``min_step``, or steps
    below 1/32 in 5 successive iterations (stalled: the Newton direction does not
    describe the residual, e.g. at the kinks of the contact law or of the blends).

    The line search tries the full step alone, then the halved steps 1/2 ... 1/64 in one
    batch (and so on; after a shortened step, 1 ... 1/32 in one batch), taking the
    longest that decreases the merit enough: the steps of a plain backtracking search,
    for fewer evaluations.  Where Newton converges
    quadratically (a full step from a residual below _CHORD_START that reduced it
    tenfold), the next step reuses the last factorised Jacobian (a chord step) as long as
    that reduces the residual by _CHORD_RATE or more; chord steps are counted in the
    iterations returned but not against ``max_iter``.  ``chord_steps=False``: Newton
    only (the continuation in speed, whose step control counts Newton iterations)."""
    b = sysm.balls(x)
    r_raw = sysm.residual(b)
    r = sysm.scaled(r_raw)
    err = float(np.abs(r).max())
    it = chord = 0
    step_cap = POLICY.highspeed_step * sysm.m.D
    short = 0
    lu = lu_last = None
    damped = False
    _getrf, _getrs = _lapack()
    while err > rtol and it < max_iter and short < 5:
        if lu is not None:
            # chord step: the Jacobian of the last Newton iteration
            dx = _getrs(*lu, -r_raw)[0]
            lu = None
            if np.isfinite(dx).all() and _step_size(sysm, dx) <= step_cap:
                xn = x + dx
                bn = sysm.balls(xn)
                rn_raw = sysm.residual(bn)
                rn = sysm.scaled(rn_raw)
                en = float(np.abs(rn).max())
                if np.isfinite(en) and en <= _CHORD_RATE * err:
                    chord += 1
                    x, b, r, r_raw, err = xn, bn, rn, rn_raw, en
                    lu = lu_last
                    log.debug("highspeed: chord step, scaled residual %.3e", err)
                    continue
        it += 1
        J = sysm.jacobian(x, b)
        dx = None
        if np.isfinite(J).all():
            lu_, piv, info = _getrf(J)
            fac = (lu_, piv)
            if info == 0:                                # (info > 0: exactly singular)
                dx = _getrs(lu_, piv, -r_raw)[0]
                if not np.isfinite(dx).all():
                    dx = None
        if dx is None:                                   # singular: least squares
            fac = None
            dx = np.linalg.lstsq(J, -r_raw, rcond=1e-14)[0]
        f = newton.clip_factor(_step_size(sysm, dx), step_cap)
        if f != 1.0:
            dx *= f
        f0 = 0.5 * float(r @ r)
        # line search: t = 1, then 1/2 ... 1/64 in one batch, and so on (after a
        # shortened step, 1 ... 1/32 in one batch at once)
        t = 1.0
        if not damped:
            xn = x + dx
            bn = sysm.balls(xn)
            rn_raw = sysm.residual(bn)
            rn = sysm.scaled(rn_raw)
        if damped or not (np.isfinite(rn).all()
                          and 0.5 * float(rn @ rn) <= (1.0 - POLICY.armijo) * f0):
            t = 1.0 if damped else 0.5
            while t >= min_step:
                ts = t * _HALVINGS
                ts = ts[ts >= min_step]
                X = x + ts[:, None] * dx
                B = sysm.balls_rows(X)
                R_raw = sysm.residual(B)
                R = sysm.scaled(R_raw)
                with np.errstate(invalid="ignore", over="ignore"):
                    ok = np.all(np.isfinite(R), axis=1) & (
                        0.5 * np.einsum("ij,ij->i", R, R) <= (1.0 - POLICY.armijo * ts) * f0)
                if np.any(ok):
                    j = int(np.argmax(ok))
                    t, xn, bn, rn_raw, rn = ts[j], X[j], B.row(j), R_raw[j], R[j]
                    break
                t = 0.5 * ts[-1]
            else:
                log.debug("highspeed: line search failed at iteration %d (residual %.3e)",
                          it, err)
                break
        en = float(np.abs(rn).max())
        if (chord_steps and fac is not None and t == 1.0 and err < _CHORD_START
                and en < 0.1 * err):
            lu = lu_last = fac
        x, b, r, r_raw = xn, bn, rn, rn_raw
        damped = t < 1.0
        short = short + 1 if t < 1.0 / 32 else 0
        err = en
        log.debug("highspeed: iteration %d, step %.3g, scaled residual %.3e", it, t, err)
    return x, b, err, it + chord


#: Scaled residual below which a Newton iteration converging quadratically may be
#: followed by chord steps (see :func:`_damped_newton`).
_CHORD_START = 1e-2
#: Residual reduction a chord step must reach to be followed by another (else Newton).
_CHORD_RATE = 0.1
_HALVINGS = 0.5 ** np.arange(6.0)


@functools.lru_cache(maxsize=1)
def _lapack():
    """LAPACK LU factorisation and solve, dgetrf and dgetrs (what numpy.linalg.solve
    does, without its overhead); scipy.linalg is imported on first use."""
    import scipy.linalg
    return scipy.linalg.get_lapack_funcs(("getrf", "getrs"), (np.zeros((2, 2)),))


def _step_size(sysm, dx):
    """Largest ball or ring-point displacement of a Newton step [m]."""
    return float(np.abs(dx * sysm.step_sc).max())


def _start(model, psi, u, wi, wo, free, static):
    """Starting ball positions from ring displacements u (static line of centres)."""
    Z = model.Z
    x = np.concatenate([np.zeros(2 * Z), u[free]])
    A1, A2 = _groove_centres(model, u)
    X1, X2 = _static_positions(model, A1, A2)
    if not static:
        # unloaded (static) balls: on the outer race only, pressed by the centrifugal force
        s = np.hypot(A1, A2)
        unl = s <= model.A * (1.0 + 1e-9)
        if np.any(unl):
            wc = 0.5 * (wi * (1 - model.D / model.dm) + wo * (1 + model.D / model.dm))
            Fc = model.mass * (model.Roc + model.ro) * wc**2
            _, Ko = _stiffness(model, np.zeros(1), np.zeros(1))
            # as near the outer-groove bottom as the inner race lets it: the ball centre
            # on the circle |X| = r_o + d, d the approach under F_c, on the arc within
            # r_i + d of the inner-groove centre (angle a +- phi, law of cosines), at the
            # angle nearest 0 (where F_c alone would hold it): at the arc's end both
            # contacts carry about F_c, and the ball is held in both directions.  (At
            # the bottom itself an angular-contact ball can overlap the inner race by up
            # to ~A sin(beta_f).)
            a = np.arctan2(A1, A2)
            dc = (Fc / Ko[0]) ** (2.0 / 3.0)
            lo = model.ro + dc
            cphi = (lo**2 + s**2 - (model.ri + dc)**2) / (2.0 * lo * np.maximum(s, 1e-300))
            phi = np.arccos(np.clip(cphi, -1.0, 1.0))
            th = np.clip(0.0, a - phi, a + phi)
            # ... unless the inner race does not hold it at the bottom (contact open there,
            # or past the inner groove's edge)
            e2 = A2 - lo
            free_ = ~((e2 > 0) & (np.hypot(A1, e2) > model.ri))
            th = np.clip(np.where(free_, 0.0, th), -0.49 * np.pi, 0.49 * np.pi)
            X1 = np.where(unl, lo * np.sin(th), X1)
            X2 = np.where(unl, lo * np.cos(th), X2)
    x[:Z], x[Z:2 * Z] = X1, X2
    return x


def solve(bearing: BallBearing, Fa=0.0, Fr=0.0, speed_inner=0.0, speed_outer=0.0, *,
          Fz=0.0, My=0.0, Mz=0.0, control: str = "outer", gyroscopic: str = "harris",
          tilt: str = "fixed", orbital: str = "cage", friction_coefficient=None,
          rtol: float = 1e-10,
          max_iter: int = 60, start: str = "static") -> HighSpeedResult:
    r"""High-speed equilibrium (Jones 1960) of a ball bearing under Fa, Fr at given speeds.

    Solves the module equations (H&D 1981 eqs. 3.93–3.112; Harris 2001 ch. 25) for the
    ball-centre positions and the inner-ring displacement; see the module docstring.

    Parameters
    ----------
    bearing : BallBearing
        Single-row bearing; ``ball_material.density`` gives the ball mass.
    Fa : float
        Axial (thrust) load on the inner ring [N]; positive loads the
        free-contact-angle side.
    Fr : float
        Radial load on the inner ring along +y (towards ball 1) [N].
    speed_inner, speed_outer : float
        Absolute angular speeds of the inner and outer rings [rad/s].
    Fz : float, optional
        Radial load along +z [N].
    My, Mz : float, optional
        Tilting moments [N m] (right-handed, as in :func:`ballrace.analytic.loaddist.solve`);
        need ``tilt="free"``.
    control : {"outer", "inner", "jones"}
        (With ``"inner"`` and light thrust at high speed the friction needed at the inner
        contact to resist M_g can exceed its normal load many times; there is then no
        equilibrium and :class:`ConvergenceError` is raised.)
        Race control: outer or inner for all balls, or per ball by Jones's criterion
        (outer control where Q_o a_o E(k_o) cos(alpha_i - alpha_o) > Q_i a_i E(k_i),
        Harris 2001 ch. 8; H&D 1981 eq. 3.92 without the cosine), iterated to a
        consistent choice.
    gyroscopic : {"harris", "controlling-race", "none"}
        How the gyroscopic moment enters the ball equilibrium: resisted by friction at
        the outer race for outer control and shared equally otherwise (Harris 2001);
        resisted at the controlling race only (H&D 1981 eq. 3.104); or ignored
        (it is still reported).
    tilt : {"fixed", "free"}
        "fixed" (default): rings stay parallel, as assumed by Jones (1960) and H&D §3.4;
        the reaction moment is in ``result.loads``.  "free": tilt is solved for with the
        applied moments.
    orbital : {"cage", "ball"}
        "cage" (default): all balls orbit at one cage speed, the mean of the balls'
        kinematic orbital speeds weighted by Q_i Q_o/(Q_i + Q_o), and each ball rolls
        without slip on its controlling race at that speed (its omega_R, M_g follow).
        "ball": Jones's (1960) model as printed, every ball with its own kinematic
        orbital speed from its own contact angles.  The two agree when all balls are
        loaded alike (pure thrust); under combined load at high speed "ball" gives the
        lightly loaded balls, whose inner contact angle approaches 80 deg, orbital speeds
        near 0.8 omega_i and can make the equilibrium ill-posed (such balls are flagged
        when their orbital speed leaves the rolling range, see ``result.warnings``).
    friction_coefficient : float, optional
        Coefficient of friction mu for the gyroscopic-slip check (``result.gyroscopic_slip``
        and ``result.skidding``; without it ``skidding`` uses :data:`TRACTION_LIMIT`).
    rtol : float, optional
        Tolerance on the residuals relative to the load scale [-].
    max_iter : int, optional
        Newton iteration limit (per continuation step).
    start : {"static", "estimate"}
        Where the iteration starts: the static load distribution of the same loads
        (default), or a crude estimate (a ring displacement of 1e-3 D in the direction of
        each load) — to check that the equilibrium found does not depend on the start.

    Returns
    -------
    HighSpeedResult

    Notes
    -----
    Which equilibrium.  The quasi-static equations can have more than one solution for
    the same loads and speeds: e.g. under pure thrust, besides the axisymmetric one,
    equilibria with the inner ring shifted radially and a few balls past the inner
    groove edge (flagged in ``result.warnings``), or with inner-race control two nearby
    equilibria.  This solver follows the one connected to the static solution: Newton
    from the static solution's ball positions (loaded balls on their static line of
    centres, unloaded ones pressed outwards by F_c) at the full speed, and where Newton
    does not converge from there, the equilibrium followed in speed from the static
    solution at zero speed (continuation with an Euler predictor; where that gives up
    at a sharp bend of the branch -- a contact angle swinging towards the groove edge as
    F_c grows under a light load -- it goes on from where it stopped with steps down to
    2^-14 of the speed).  Other equilibria are not searched for.  With
    ``control="jones"`` it starts with outer-race control for every ball and changes
    the balls' control round by round to Jones's choice, each round from the static
    start and, where that fails, from the previous round's equilibrium.

    Raises
    ------
    ConvergenceError
        If the equilibrium is not found: the message gives residual and iterations, the
        fraction of the speed up to which the equilibrium was followed from the static
        one, and the state of the balls there (contact angles at the groove edge,
        friction needed beyond the contact load).  Results where the model's
        assumptions break are returned flagged instead (``result.warnings``).
    ValueError
        For invalid arguments (named in the message), and for loads beyond the
        load-deflection range (as :func:`ballrace.analytic.loaddist.solve`).

    References
    ----------
    Jones, A.B. (1960) "A general theory for elastically constrained ball and radial
    roller bearings under arbitrary load and speed conditions", J. Basic Eng. 82,
    309–320; Hamrock & Dowson (1981) eqs. (3.93)–(3.112); Harris, T.A. (2001) *Rolling
    Bearing Analysis*, 4th ed., ch. 25.

    Examples
    --------
    The 218 angular-contact bearing under 17.8 kN thrust at 10,000 rpm (inner ring):

    >>> import ballrace
    >>> brg = ballrace.BallBearing(22.225e-3, 16, 125.26e-3, 0.5232, 0.5232,
    ...                            free_contact_angle=np.radians(40))
    >>> r = solve(brg, Fa=17800.0, speed_inner=10000 * np.pi / 30)
    >>> np.degrees([r.inner_contact_angles[0], r.outer_contact_angles[0]]).round(2)
    array([50.04, 31.28])
    >>> round(r.outer_loads[0] - r.inner_loads[0]), round(float(r.centrifugal_force[0]))
    (472, 643)
    """
    if not isinstance(bearing, BallBearing):
        raise TypeError(f"bearing must be a ballrace.BallBearing; got {type(bearing).__name__}")
    check_choice(control, "control", CONTROLS)
    check_choice(gyroscopic, "gyroscopic", GYROSCOPIC)
    check_choice(tilt, "tilt", ("fixed", "free"))
    check_choice(orbital, "orbital", ORBITALS)
    check_choice(start, "start", ("static", "estimate"))
    L = np.array([float(a) if a.ndim == 0 else np.nan
                  for a in (as_array(v, n, bounded=True, tiny_ok=True) for v, n in
                            ((Fa, "Fa"), (Fr, "Fr"), (Fz, "Fz"), (My, "My"), (Mz, "Mz")))])
    if np.any(np.isnan(L)):
        raise TypeError("Fa, Fr, Fz, My and Mz must be scalars (one load case per call)")
    wi = as_array(speed_inner, "speed_inner", bounded=True, tiny_ok=True, unit="rad/s")
    wo = as_array(speed_outer, "speed_outer", bounded=True, tiny_ok=True, unit="rad/s")
    if wi.ndim or wo.ndim:
        raise TypeError("speed_inner and speed_outer must be scalars [rad/s]")
    wi, wo = float(wi), float(wo)
    if tilt == "fixed" and (L[3] != 0 or L[4] != 0):
        raise ValueError("My and Mz must be 0 with tilt='fixed' (rings kept parallel); "
                         "use tilt='free' to apply a moment")
    if np.all(L == 0):
        raise ValueError("apply a load (Fa, Fr, Fz, My or Mz non-zero): without one the "
                         "inner ring is not located")
    mu = None
    if friction_coefficient is not None:
        mu = float(check_positive(friction_coefficient, "friction_coefficient", "-"))
    rtol = float(check_range(rtol, "rtol", 0.0, 1e-3, high_inclusive=True, unit="-"))
    from .loaddist import check_load_range
    check_load_range(bearing, L[None])     # overload: the static model's words
    model = _Model.of(bearing)
    psi = bearing.azimuths(0.0)
    Z = model.Z
    free = _free_dofs(L, tilt)
    static = wi == 0.0 and wo == 0.0

    # ---- static solution: starting values (Jones 1960 / H&D 3.61-3.74)
    u0 = np.zeros(5)
    if start == "static":
        from .loaddist import solve as static_solve
        d = np.zeros(5)
        d[free] = np.nan
        try:
            with _operating.quiet():            # the result below says it, if need be
                st = static_solve(bearing, Fa=L[0], Fy=L[1], Fz=L[2], My=L[3], Mz=L[4],
                                  displacements=d)
            u0 = np.asarray(st.displacements, float).reshape(5)
        except (ConvergenceError, ValueError) as exc:       # pragma: no cover - fallback
            log.info("highspeed: static start failed (%s); starting from the free state", exc)
    else:
        if L[0] != 0:
            u0[0] = np.sign(L[0]) * 1e-3 * model.D
        if L[1] != 0:
            u0[1] = np.sign(L[1]) * 1e-3 * model.D

    # ---- scales
    wc0 = abs(0.5 * (wi * (1 - model.D / model.dm) + wo * (1 + model.D / model.dm)))
    Fc0 = model.mass * (model.Roc + model.ro) * wc0**2
    Fmax = max(abs(L[0]), abs(L[1]), abs(L[2]), abs(L[3]) / model.Ri, abs(L[4]) / model.Ri)
    F_ref = max(Fmax, Z * Fc0)
    Q_ref = max(F_ref / Z, Fc0)

    outer = np.full(Z, control != "inner")
    count = [0]
    what = (f"Fa={L[0]:g} N, Fr={L[1]:g} N, Fz={L[2]:g} N, speed_inner={wi:g} rad/s, "
            f"speed_outer={wo:g} rad/s, control={control!r}, gyroscopic={gyroscopic!r}, "
            f"orbital={orbital!r}")
    prev = None
    for _ in range(8 if control == "jones" else 1):
        try:
            sysm, x, b = _equilibrium(model, psi, L, free, wi, wo, gyroscopic, static, F_ref,
                                      Q_ref, orbital, outer, u0, rtol, max_iter, count, what)
        except ConvergenceError:
            if prev is None:
                raise
            # a new Jones race-control choice: the equilibrium of the previous choice is the
            # start (continuation in the choice; from the static start, and in speed from
            # the static solution, a few balls changed to inner control can fail where the
            # neighbouring equilibrium is a few Newton steps away)
            sysm = _System(model, psi, L, free, wi, wo, gyroscopic, static, F_ref, Q_ref,
                           orbital)
            sysm.outer = outer
            x, b, err, it = _damped_newton(sysm, prev, rtol, max_iter)
            count[0] += it
            if not err <= rtol:
                raise
            log.debug("highspeed: Jones round solved from the previous round's equilibrium")
        if control != "jones" or static:
            break
        new = _jones_outer(bearing, b)
        if np.array_equal(new, outer):
            break
        log.debug("highspeed: Jones race control changed for %d balls", int(np.sum(new != outer)))
        outer = new
        u0 = sysm.unpack(x)[2]
        prev = x
    else:
        _operating.warn("highspeed: Jones race-control choice did not settle after 8 rounds "
                        "(the result uses the last choice; race control may be mixed)")
    total_it = count[0]

    return _checked(_result(bearing, model, psi, sysm, x, b, L, wi, wo, sysm.outer, gyroscopic,
                            mu, total_it, F_ref, Q_ref, rtol))


def _equilibrium(model, psi, L, free, wi, wo, gyro, static, F_ref, Q_ref, orbital, outer,
                 u0, rtol, max_iter, count, what):
    """Solve the equilibrium at the full speeds; returns (system, x, balls).

    Damped Newton from the static start first.  If that fails, the solution branch is
    followed in speed (omega s, s from 0 to 1; F_c grows as s^2) from the static
    solution with an adaptive step and a secant predictor.  If the branch cannot be
    continued to s = 1 (the step falls below 1/1000 at a turning point of the branch,
    or at the edge of the model: a contact at the groove edge, a friction force needed
    beyond the contact load), ConvergenceError names the speed fraction reached and the
    state of the balls there.
    """
    def system(s):
        sysm = _System(model, psi, L, free, wi * s, wo * s, gyro, static, F_ref, Q_ref,
                       orbital)
        sysm.outer = outer
        return sysm

    sysm = system(1.0)
    x, b, err, it = _damped_newton(sysm, _start(model, psi, u0, wi, wo, free, static), rtol,
                                   max_iter if static else min(max_iter, 30))
    count[0] += it
    if err <= rtol:
        return sysm, x, b
    if static:
        raise newton.convergence_error("high-speed equilibrium (zero speed)", count[0], err,
                                       rtol, newton=True, measure="scaled residual",
                                       context=f"({what})")
    b_direct = b
    log.info("highspeed: direct Newton failed (residual %.3e); continuing in speed", err)
    s, ds = 0.0, 0.25
    last = tangent = None
    while s < 1.0 and ds >= 1.0 / 128:
        s_new = min(1.0, s + ds)
        if last is None:
            xg = _start(model, psi, u0, wi * s_new, wo * s_new, free, static)
        else:                                   # Euler predictor along the branch
            xg = last[1] + (s_new - s) * tangent
        sy = system(s_new)
        # from the predictor a step converges in a few full Newton steps; a step that
        # needs heavy damping or more iterations is halved instead
        xn, bn, err, it = (
            _damped_newton(sy, xg, rtol, min(max_iter, 30), chord_steps=False) if last is None
            else _damped_newton(sy, xg, rtol, min(max_iter, 12), 1.0 / 16, chord_steps=False))
        count[0] += it
        log.debug("highspeed: continuation to %.4g of the speed: %s after %d iterations",
                  s_new, "converged" if err <= rtol else f"failed ({err:.3e})", it)
        if err <= rtol:
            s = s_new
            last = (sy, xn, bn)
            if s < 1.0:                         # tangent dx/ds = -J^-1 dR/ds
                tangent = _tangent(system, s, sy, xn, bn)
            ds = min(2.0 * ds, 0.5)
        else:
            ds = 0.5 * (s_new - s)
    careful = s < 1.0
    if careful and last is None:
        # not even the first step: from the static solution itself (exact at zero speed,
        # where F_c and M_g vanish with their derivatives in s: zero tangent)
        s0 = system(0.0)
        x0 = _start(model, psi, u0, 0.0, 0.0, free, True)
        b0 = s0.balls(x0)
        if float(np.abs(s0.scaled(s0.residual(b0))).max()) <= rtol:
            last, tangent = (s0, x0, b0), np.zeros_like(x0)
    exhausted = False
    if careful and last is not None:
        s, last, err, exhausted = _continue_carefully(system, s, last, tangent, rtol,
                                                      max_iter, count)
    if s >= 1.0:
        return last
    hint = (". With inner-race control the gyroscopic moment may need more friction than "
            "a lightly loaded inner contact can give; control='outer' or 'jones', or "
            "gyroscopic='none', may have a solution" if gyro != "none" and np.any(~outer)
            else "")
    if last is None:
        raise ConvergenceError(
            f"high-speed equilibrium not found: Newton did not converge at full speed nor "
            f"at {100 / 128:.2g} % of it (scaled residual {err:.3e}, rtol {rtol:g}, after "
            f"{count[0]} Newton iterations; {what})"
            + "".join(f"; at the last full-speed iterate {w}"
                      for w in _model_limits(model, b_direct)) + hint)
    reasons = _model_limits(model, last[2])
    Fmax = max(abs(L[0]), abs(L[1]), abs(L[2]), abs(L[3]) / model.Ri, abs(L[4]) / model.Ri)
    if not reasons and Fmax <= 1e3 * rtol * F_ref:
        # not a property of the model: the load is lost in the tolerance of the residual
        raise ConvergenceError(
            f"high-speed equilibrium not found (scaled residual {err:.3e}, rtol {rtol:g}, "
            f"after {count[0]} Newton iterations; {what}): the applied load, {Fmax:.3g} N, "
            f"is below 1e3 rtol of the load scale {F_ref:.4g} N (the balls' centrifugal "
            f"forces), so the inner ring is hardly located at this tolerance and round-off "
            f"hides the equilibrium; a larger load (or a larger rtol) may solve")
    if exhausted:
        raise ConvergenceError(
            f"high-speed equilibrium not found: Newton from the static start failed, and the "
            f"equilibrium followed in speed from the static solution reached only "
            f"{100 * s:.4g} % of the speed in the careful steps' budget (scaled "
            f"residual {err:.3e}, rtol {rtol:g}, after {count[0]} Newton iterations; "
            f"{what}); whether the branch goes on to the full speed is not known"
            + "".join(f"; there {w}" for w in reasons) + hint)
    raise ConvergenceError(
        f"high-speed equilibrium not found: Newton from the static start failed, and the "
        f"equilibrium followed in speed from the static solution ends at {100 * s:.4g} % "
        f"of the speed (none found within {100 * 2 * _CAREFUL_DS_MIN:.2g} % beyond; scaled "
        f"residual {err:.3e}, rtol {rtol:g}, after {count[0]} Newton iterations; {what}). "
        "There: "
        + ("; ".join(reasons) if reasons else "a turning point of the solution branch")
        + ". The quasi-static model has no solution on this branch at the given speed"
        + hint)


def _tangent(system, s, sy, x, b):
    """dx/ds = -J^-1 dR/ds of the branch at speed fraction s (central differences in s);
    zero where J is singular."""
    h = 1e-6
    sp_, sm_ = system(s + h), system(s - h)
    dR = (sp_.residual(sp_.balls(x)) - sm_.residual(sm_.balls(x))) / (2 * h)
    try:
        t = np.linalg.solve(sy.jacobian(x, b), -dR)
    except np.linalg.LinAlgError:
        return np.zeros_like(x)
    return t if np.all(np.isfinite(t)) else np.zeros_like(x)


#: Smallest speed step of the careful continuation [-], its number of steps and of Newton
#: iterations (bounds on the time a case without equilibrium takes to say so).
_CAREFUL_DS_MIN = 2.0**-14
_CAREFUL_STEPS = 400
_CAREFUL_ITERATIONS = 1000


def _continue_carefully(system, s, last, tangent, rtol, max_iter, count):
    """Go on along the branch from (s, last) where the first continuation gave up.

    Where the branch bends sharply (a contact angle swinging towards the groove edge as
    F_c grows under a light load), the Euler predictor lands far off and a step of 1/128
    of the speed still needs more Newton iterations than the first pass allows.  Here:
    steps down to 2^-14 of the speed, the Euler predictor and, if it fails, the last
    solution itself (zero-order predictor), up to 30 Newton iterations per step, and
    steps of at most 1/16 of the speed (small steps keep Newton on the branch).  At most
    _CAREFUL_STEPS steps and _CAREFUL_ITERATIONS Newton iterations.  Returns (s, last,
    scaled residual, True if the budget ran out before the branch ended or reached s = 1).
    """
    ds, err = 1.0 / 256, np.inf
    used = 0
    for _ in range(_CAREFUL_STEPS):
        if not (s < 1.0 and ds >= _CAREFUL_DS_MIN):
            return s, last, err, False
        if used >= _CAREFUL_ITERATIONS:
            break
        s_new = min(1.0, s + ds)
        sy = system(s_new)
        x0 = last[1]
        ok = False
        for xg in (x0 + (s_new - s) * tangent, x0):
            xn, bn, err, it = _damped_newton(sy, xg, rtol, min(max_iter, 30), 2.0**-20,
                                             chord_steps=False)
            count[0] += it
            used += it
            ok = err <= rtol
            if ok:
                break
        log.debug("highspeed: careful continuation to %.6g of the speed: %s", s_new,
                  "converged" if ok else f"failed ({err:.3e})")
        if ok:
            s, last = s_new, (sy, xn, bn)
            if s < 1.0:
                tangent = _tangent(system, s, sy, xn, bn)
            ds = min(2.0 * ds, 1.0 / 16)
        else:
            ds = 0.5 * (s_new - s)
    return s, last, err, s < 1.0 and ds >= _CAREFUL_DS_MIN


def _model_limits(model, b):
    """Descriptions of balls at the limits of the model (for error messages)."""
    out = []

    def balls_(mask):
        return ", ".join(str(k + 1) for k in np.flatnonzero(mask))

    for race, Q, a, lam, d, on in (("inner", b.Qi, b.ai, b.lam_i, b.di, b.on_i),
                                   ("outer", b.Qo, b.ao, b.lam_o, b.do, b.on_o)):
        past = ~on & (d > 0)
        if np.any(past):
            out.append(f"balls {balls_(past)} are pressed past the {race} groove edge (90 "
                       "deg from the groove bottom, no ring material: they would ride on "
                       "the land)")
        edge = (Q > 0) & (np.abs(a) > np.radians(80.0))
        if np.any(edge):
            out.append(f"balls {balls_(edge)} have {race} contact angles up to "
                       f"{np.degrees(np.max(np.abs(a[edge]))):.1f} deg, approaching the "
                       "groove edge (90 deg), beyond which the race carries nothing")
        f = np.abs(lam * b.Mg) / model.D
        need = np.where(Q > 0, f / np.where(Q > 0, Q, 1.0), 0.0)
        big = need > 1.0
        if np.any(big):
            out.append(f"the friction resisting the gyroscopic moment at the {race} race is "
                       f"up to {float(np.max(need)):.3g} x the contact load (balls "
                       f"{balls_(big)}): no traction can hold it")
    return out


def _jones_outer(bearing, b):
    """Jones's race-control criterion per ball (Harris 2001 ch. 8): outer control where
    Q_o a_o E(k_o) cos(alpha_i - alpha_o) > Q_i a_i E(k_i)."""
    ci = bearing.contacts(b.Qi, b.ai, "inner")
    co = bearing.contacts(b.Qo, b.ao, "outer")
    mo = b.Qo * np.asarray(co.a) * np.asarray(co.ellipe) * np.cos(b.ai - b.ao)
    mi = b.Qi * np.asarray(ci.a) * np.asarray(ci.ellipe)
    return mo > mi


def _result(bearing, model, psi, sysm, x, b, L, wi, wo, outer, gyro, mu, iters, F_ref, Q_ref,
            rtol=1e-10):
    r = sysm.residual(b)
    Z = model.Z
    raw = np.concatenate([np.abs(r[:2 * Z]) if not sysm.static else np.zeros(2 * Z),
                          np.abs(r[2 * Z:]) * np.where(sysm.free >= 3, 1.0 / model.Ri, 1.0)])
    res = float(np.max(raw))
    u = sysm.unpack(x)[2]
    rho = model.D / model.dm
    sr_i = (1 - rho * np.cos(b.ai_k)) * np.tan(b.ai_k - b.beta) + rho * np.sin(b.ai_k)
    sr_o = (1 + rho * np.cos(b.ao_k)) * np.tan(b.ao_k - b.beta) - rho * np.sin(b.ao_k)
    sr_i = np.where(outer, sr_i, 0.0)              # no spin on the controlling race
    sr_o = np.where(outer, 0.0, sr_o)
    # ---- where the model's assumptions break (flags and warnings)
    warn = []

    def balls_(mask):
        return ", ".join(str(k + 1) for k in np.flatnonzero(mask))

    fi = np.abs(b.lam_i * b.Mg) / model.D
    fo = np.abs(b.lam_o * b.Mg) / model.D
    mu_s = TRACTION_LIMIT if mu is None else mu
    skid = ((b.Qi > 0) & (fi > mu_s * b.Qi)) | ((b.Qo > 0) & (fo > mu_s * b.Qo))
    slip = None if mu is None else skid
    if np.any(skid):
        need = np.maximum(np.where(b.Qi > 0, fi / np.where(b.Qi > 0, b.Qi, 1.0), 0.0),
                          np.where(b.Qo > 0, fo / np.where(b.Qo > 0, b.Qo, 1.0), 0.0))
        warn.append(f"balls {balls_(skid)} skid: the friction needed to resist the "
                    f"gyroscopic moment is up to {float(np.max(need)):.3g} x the contact "
                    f"load (> {mu_s:g}); the balls cannot roll as race control assumes")
    past_i = ~b.on_i & (b.di > 0)
    past_o = ~b.on_o & (b.do > 0)
    for race, past, Q, a in (("inner", past_i, b.Qi, b.ai), ("outer", past_o, b.Qo, b.ao)):
        if np.any(past):
            warn.append(f"balls {balls_(past)}: {race} line of centres 90 deg or more from "
                        "the groove bottom (no ring material there; taken as unloaded, the "
                        "ball would bear on the land)")
        ts = bearing.shoulder_angle(race)
        if ts is not None:
            over = (Q > 0) & (np.abs(a) > ts)
            if np.any(over):
                warn.append(f"balls {balls_(over)}: {race} contact angle beyond the shoulder "
                            f"edge ({np.degrees(ts):.1f} deg from the groove bottom)")
            past = past | over
        if race == "inner":
            past_i = past
        else:
            past_o = past
    ratio = float("nan")
    if wi != wo and not sysm.static:
        f = (b.wc - wo) / (wi - wo)
        ratio = float(np.mean(f))
        lo_, hi_ = CAGE_RATIO_RANGE[0] * (1.0 - rho), CAGE_RATIO_RANGE[1]
        out = (f < lo_) | (f > hi_)
        if np.any(out):
            warn.append(f"balls {balls_(out)}: orbital speed {float(np.min(f)):.3g}"
                        + (f"-{float(np.max(f)):.3g}" if np.ptp(f) > 1e-9 else "")
                        + f" x the relative ring speed, outside the rolling range "
                        f"[{lo_:.3g}, {hi_:.3g}]: the balls cannot roll on both races "
                        "(gross sliding; the quasi-static model does not apply)")
    for w in warn:
        _operating.warn(f"highspeed: {w}")
    loads = b.C.sum(axis=0)
    arrays = (b.Qi, b.Qo, b.ai_k, b.ao_k, b.di, b.do, b.X1, b.X2, b.Fc, b.Mg, b.wc, b.wR,
              b.beta, sr_i, sr_o, u, loads)
    finite = np.isfinite(np.concatenate([np.ravel(a) for a in arrays])).all()
    if not (finite and res / F_ref <= max(1e-9, rtol)):
        raise ConvergenceError(f"high-speed equilibrium: the solution is not finite or not "
                               f"balanced (relative residual {res / F_ref:.3e}) after {iters} "
                               "Newton iterations")
    return HighSpeedResult(
        bearing=bearing, azimuths=psi, speed_inner=wi, speed_outer=wo,
        inner_loads=b.Qi, outer_loads=b.Qo,
        inner_contact_angles=np.clip(b.ai, -_EDGE, _EDGE),
        outer_contact_angles=np.clip(b.ao, -_EDGE, _EDGE),
        inner_deflections=b.di, outer_deflections=b.do,
        ball_positions=np.stack([b.X1, b.X2], axis=-1), centrifugal_force=b.Fc,
        gyroscopic_moment=b.Mg, orbital_speed=b.wc, spin_speed=b.wR, pitch_angle=b.beta,
        spin_to_roll_inner=sr_i, spin_to_roll_outer=sr_o,
        control=np.where(outer, "outer", "inner"), displacements=u, loads=loads, applied=L,
        residual=res, relative_residual=res / F_ref, iterations=int(iters), gyroscopic=gyro,
        friction_coefficient=mu, gyroscopic_slip=slip,
        inner_kinematic_angles=b.ai_k, outer_kinematic_angles=b.ao_k,
        inner_friction_share=np.array(b.lam_i, float),
        outer_friction_share=np.array(b.lam_o, float),
        beyond_groove_inner=past_i, beyond_groove_outer=past_o, skidding=skid,
        cage_speed_ratio=ratio, warnings=tuple(warn))
