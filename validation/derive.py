r"""Independent derivations behind the ``kind = "independent derivation"`` cases.

The expected numbers of those cases were produced by this module, which shares no
code with :mod:`ballrace.analytic`: Hertz's transcendental equation for the
ellipticity is solved with :mod:`mpmath` at 30 significant digits (``findroot`` on
the elliptic-integral form, Hamrock & Dowson 1981 eq. 3.14 / Ricci 2009 eq. 14), the
semi-axes, approach and pressure follow from eqs. (3.8)–(3.16), and the subsurface
numbers from Johnson's closed-form axis stresses (Johnson 1985 eq. 3.45) and
line-contact stresses (McEwen 1949; Johnson 1985 eq. 4.47) maximised with ``mpmath``.
The kinematics and high-speed numbers come from the textbook closed forms for the defect
frequencies (Harris 2001 ch. 8), from rolling without slip written as vector algebra
(ball and ring surface velocities at both contact centres, plus zero spin on the
controlling race, solved with ``findroot``), from F_c = (1/2) m d_m omega_c^2 and
M_g = J omega_R omega_c sin(beta) (Hamrock & Dowson 1981 eqs. 3.106-3.108), and from
the static thrust equation (H&D eq. 3.55) with each race's stiffness from the mpmath
Hertz solution above.

Regenerate the tables with ``python -m ballrace.validation.derive``; the case files
quote the printed values (10 significant digits).

Examples
--------
>>> d = hertz_exact(1000, 5e-3, 5e-3, float("inf"), float("inf"), 219.78e9)
>>> round(d["a"] * 1e3, 4), round(d["k"], 12)
(0.3244, 1.0)
>>> f = defect_frequencies_exact("0.3126", "1.537", 9)      # CWRU 6205 (inches)
>>> round(f["bpfi"], 4), round(f["bpfo"], 4), round(2 * f["bsf"], 4)
(5.4152, 3.5848, 4.7134)
>>> k = race_control_kinematics("0.2", "1", 40, 40)         # outer control, inner ring turning
>>> round(k["cage_ratio"], 6), abs(k["spin_to_roll_outer"]) < 1e-25
(0.423396, True)
"""
from __future__ import annotations

import math

__all__ = ["hertz_exact", "circle_axis_max_shear", "line_max_shear",
           "lundberg_palmgren_circle", "defect_frequencies_exact",
           "race_control_kinematics", "ball_dynamics", "static_thrust", "main"]


def _mp():
    import mpmath

    mpmath.mp.dps = 30
    return mpmath


def hertz_exact(load, rx1, ry1, rx2, ry2, E_prime) -> dict:
    """Exact elliptical Hertz contact with mpmath (SI in, SI floats out)."""
    return {k: float(v) for k, v in _hertz_mp(load, rx1, ry1, rx2, ry2, E_prime).items()}


def _hertz_mp(load, rx1, ry1, rx2, ry2, E_prime) -> dict:
    """:func:`hertz_exact` with mpmath numbers out (30 digits)."""
    mp = _mp()
    inv = lambda r: mp.mpf(0) if mp.isinf(r) else 1 / mp.mpf(r)
    Rx = 1 / (inv(rx1) + inv(rx2))
    Ry = 1 / (inv(ry1) + inv(ry2))
    alpha = max(Rx, Ry) / min(Rx, Ry)
    R = Rx * Ry / (Rx + Ry)
    if alpha == 1:
        k, K, E = mp.mpf(1), mp.pi / 2, mp.pi / 2
    else:
        def f(lnk):
            k = mp.e ** lnk
            m = 1 - 1 / k**2
            K, E = mp.ellipk(m), mp.ellipe(m)
            return mp.log((k**2 * E - K) / (K - E)) - mp.log(alpha)

        lnk = mp.findroot(f, mp.log(alpha) * 2 / mp.pi)
        k = mp.e ** lnk
        m = 1 - 1 / k**2
        K, E = mp.ellipk(m), mp.ellipe(m)
    Q, Ep = mp.mpf(load), mp.mpf(E_prime)
    a = (6 * k**2 * E * Q * R / (mp.pi * Ep)) ** (mp.mpf(1) / 3)
    b = (6 * E * Q * R / (mp.pi * k * Ep)) ** (mp.mpf(1) / 3)
    delta = K * (mp.mpf(9) / (2 * E * R) * (Q / (mp.pi * k * Ep)) ** 2) ** (mp.mpf(1) / 3)
    p = 3 * Q / (2 * mp.pi * a * b)
    return {"Rx": Rx, "Ry": Ry, "k": k, "ellipk": K, "ellipe": E, "a": a, "b": b,
            "approach": delta, "p_max": p}


def circle_axis_max_shear(nu: float) -> dict:
    r"""Max of the principal shear stress on the axis of a circular Hertz contact.

    Johnson (1985) eq. (3.45): with :math:`\zeta = z/a`,
    :math:`\sigma_z/p_0 = -1/(1+\zeta^2)`,
    :math:`\sigma_r/p_0 = -(1+\nu)(1 - \zeta\arctan(1/\zeta)) + 1/(2(1+\zeta^2))`,
    :math:`\tau_1 = |\sigma_r - \sigma_z|/2`; returns tau/p0, depth/a and von Mises/p0.
    """
    mp = _mp()
    nu = mp.mpf(nu)

    def tau(z):
        sz = -1 / (1 + z**2)
        sr = -(1 + nu) * (1 - z * mp.atan(1 / z)) + 1 / (2 * (1 + z**2))
        return (sr - sz) / 2

    z = mp.findroot(lambda z: mp.diff(tau, z), 0.48)
    t = tau(z)
    return {"tau_max": float(abs(t)), "depth": float(z), "von_mises": float(2 * abs(t))}


def line_max_shear() -> dict:
    r"""Max principal shear under a Hertz line contact, on the centre line (plane strain).

    Johnson (1985) eq. (4.47) at x = 0, :math:`\zeta = z/b`:
    :math:`\sigma_x = -p_0[(1+2\zeta^2)/\sqrt{1+\zeta^2} - 2\zeta]`,
    :math:`\sigma_z = -p_0/\sqrt{1+\zeta^2}`, :math:`\tau_1 = |\sigma_x-\sigma_z|/2`
    (independent of nu).
    """
    mp = _mp()

    def tau(z):
        sx = -((1 + 2 * z**2) / mp.sqrt(1 + z**2) - 2 * z)
        sz = -1 / mp.sqrt(1 + z**2)
        return (sx - sz) / 2

    z = mp.findroot(lambda z: mp.diff(tau, z), 0.78)
    return {"tau_max": float(abs(tau(z))), "depth": float(z)}


def lundberg_palmgren_circle() -> dict:
    """Lundberg–Palmgren orthogonal shear for a circle (b/a = 1): t, tau0/p_max, z0/b.

    Hamrock & Dowson (1981) eqs. (3.19)–(3.27): solve (t^2 - 1)(2t - 1) = (b/a)^2 = 1.
    """
    mp = _mp()
    t = mp.findroot(lambda t: (t**2 - 1) * (2 * t - 1) - 1, 1.28)
    return {"t": float(t), "tau0": float(mp.sqrt(2 * t - 1) / (2 * t * (t + 1))),
            "z0": float(1 / ((t + 1) * mp.sqrt(2 * t - 1)))}


def defect_frequencies_exact(D, d_m, n_balls, contact_angle_deg=0, rotating="inner") -> dict:
    r"""FTF, BPFO, BPFI and BSF as multiples of the rotating ring's speed (mpmath).

    Harris (2001) ch. 8 closed forms with :math:`\gamma = D\cos\alpha/d_m`: the cage
    turns at :math:`(1 \mp \gamma)/2` of the rotating ring's speed (inner / outer ring
    rotating), BPFO = Z(1 - gamma)/2, BPFI = Z(1 + gamma)/2 and
    BSF = (d_m/2D)(1 - gamma^2) for either ring.  Lengths in any one unit (strings keep
    the printed digits exact); the angle in degrees.
    """
    mp = _mp()
    D, d_m = mp.mpf(D), mp.mpf(d_m)
    g = D * mp.cos(mp.radians(mp.mpf(contact_angle_deg))) / d_m
    Z = mp.mpf(n_balls)
    ftf = (1 - g) / 2 if rotating == "inner" else (1 + g) / 2
    return {"gamma": float(g), "ftf": float(ftf), "bpfo": float(Z * (1 - g) / 2),
            "bpfi": float(Z * (1 + g) / 2), "bsf": float(d_m / (2 * D) * (1 - g**2))}


def race_control_kinematics(D, d_m, alpha_i_deg, alpha_o_deg, control="outer",
                            speed_inner=1, speed_outer=0) -> dict:
    r"""Ball kinematics from rolling without slip, by vector algebra (mpmath).

    Cage frame, x along the bearing axis, z radially outward through the ball centre
    c = (0, 0, d_m/2) (a right-handed x, y, z; y is the rolling direction).  The ball
    spins relative to the cage at Omega = omega_R (cos beta, 0, -sin beta); a ring turns
    at (omega_j - omega_c) x.  The contact normals (ball centre to contact) are
    n_o = (sin a_o, 0, cos a_o) and n_i = -(sin a_i, 0, cos a_i).  Unknowns omega_c,
    omega_R, beta; equations: the surface velocities of ball and ring are equal at both
    contact centres, Omega x (D/2) n = (omega_j - omega_c) x x (c + (D/2) n), and the
    ball does not spin relative to the controlling race, (Omega - (omega_j - omega_c) x)
    . (sin a_j, 0, cos a_j) = 0 (Jones 1959).  Spin and roll at each contact are the
    components of the relative angular velocity along (sin a_j, 0, cos a_j) and
    (cos a_j, 0, -sin a_j).  Solved with ``findroot``; nothing here uses the closed
    forms of Hamrock & Dowson (1981) eqs. (3.76)-(3.90).
    """
    mp = _mp()
    D, d_m = mp.mpf(D), mp.mpf(d_m)
    ai, ao = mp.radians(mp.mpf(alpha_i_deg)), mp.radians(mp.mpf(alpha_o_deg))
    wi, wo = mp.mpf(speed_inner), mp.mpf(speed_outer)
    c = (mp.mpf(0), mp.mpf(0), d_m / 2)
    n = {"inner": (-mp.sin(ai), mp.mpf(0), -mp.cos(ai)),
         "outer": (mp.sin(ao), mp.mpf(0), mp.cos(ao))}
    s = {"inner": (mp.sin(ai), mp.mpf(0), mp.cos(ai)), "outer": n["outer"]}
    t = {"inner": (mp.cos(ai), mp.mpf(0), -mp.sin(ai)),
         "outer": (mp.cos(ao), mp.mpf(0), -mp.sin(ao))}
    ring = {"inner": wi, "outer": wo}

    def cross(u, v):
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0])

    def dot(u, v):
        return sum(a * b for a, b in zip(u, v))

    def parts(wc, wR, beta):
        Om = (wR * mp.cos(beta), mp.mpf(0), -wR * mp.sin(beta))
        slip, spin, roll = {}, {}, {}
        for j in ("inner", "outer"):
            w = (ring[j] - wc, mp.mpf(0), mp.mpf(0))
            p = tuple(ci + D / 2 * ni for ci, ni in zip(c, n[j]))
            v_ball = cross(Om, tuple(D / 2 * ni for ni in n[j]))
            v_ring = cross(w, p)
            slip[j] = v_ball[1] - v_ring[1]
            rel = tuple(a - b for a, b in zip(Om, w))
            spin[j], roll[j] = dot(rel, s[j]), dot(rel, t[j])
        return slip, spin, roll

    def eqs(wc, wR, beta):
        slip, spin, _ = parts(wc, wR, beta)
        return [slip["inner"] / D, slip["outer"] / D, spin[control]]

    rho = D / d_m
    guess = [(wi * (1 - rho * mp.cos(ai)) + wo * (1 + rho * mp.cos(ao))) / 2,
             (wo - wi) / (2 * rho), (ai + ao) / 2]
    wc, wR, beta = mp.findroot(eqs, guess)
    _, spin, roll = parts(wc, wR, beta)
    return {"cage_speed": float(wc), "ball_speed": float(wR), "pitch_angle": float(beta),
            "pitch_angle_deg": float(mp.degrees(beta)),
            "cage_ratio": float(wc / (wi - wo)) if wi != wo else math.nan,
            "ball_ratio": float(wR / (wi - wo)) if wi != wo else math.nan,
            "spin_inner": float(spin["inner"]), "spin_outer": float(spin["outer"]),
            "spin_to_roll_inner": float(spin["inner"] / roll["inner"]),
            "spin_to_roll_outer": float(spin["outer"] / roll["outer"])}


def ball_dynamics(D, d_m, alpha_deg, density, speed_inner_rpm, speed_outer_rpm=0) -> dict:
    r"""Ball mass, cage speed, centrifugal force and gyroscopic moment (mpmath).

    :math:`m = \rho\pi D^3/6`, :math:`J = m D^2/10`,
    :math:`F_c = \tfrac12 m d_m \omega_c^2`, :math:`M_g = J\omega_R\omega_c\sin\beta`
    (Hamrock & Dowson 1981 eqs. 3.106-3.108), with omega_c, omega_R and beta from
    :func:`race_control_kinematics` (outer-race control, both contact angles alpha).
    Ring speeds in rev/min, converted here (2 pi / 60); SI out.
    """
    mp = _mp()
    D, d_m, rho = mp.mpf(D), mp.mpf(d_m), mp.mpf(density)
    wi = mp.mpf(speed_inner_rpm) * 2 * mp.pi / 60
    wo = mp.mpf(speed_outer_rpm) * 2 * mp.pi / 60
    k = race_control_kinematics(D, d_m, alpha_deg, alpha_deg, "outer", wi, wo)
    wc, wR, beta = (mp.mpf(k[x]) for x in ("cage_speed", "ball_speed", "pitch_angle"))
    m = rho * mp.pi * D**3 / 6
    J = m * D**2 / 10
    return {"ball_mass": float(m), "orbital_speed": float(wc), "ball_speed": float(wR),
            "pitch_angle": float(beta), "Fc": float(m * d_m * wc**2 / 2),
            "gyroscopic_moment": float(J * wR * wc * mp.sin(beta))}


def static_thrust(D, d_m, n_balls, f_i, f_o, beta_f_deg, E, nu, Fa) -> dict:
    r"""Concentric thrust at zero speed: contact angle, ball load, axial deflection.

    Hamrock & Dowson (1981) eq. (3.55):
    :math:`F_a/Z = K_n(\beta) A^{3/2}\sin\beta\,(\cos\beta_f/\cos\beta - 1)^{3/2}`,
    A = (f_i + f_o - 1) D, Q = F_a/(Z sin beta), delta_a = A sin(beta - beta_f)/cos beta
    (eq. 3.60), with :math:`K_n = (K_i^{-2/3} + K_o^{-2/3})^{-3/2}` and each race's
    K = Q/delta^{3/2} from the mpmath Hertz solution (:func:`_hertz_mp`) for a ball of
    radius D/2 against a race of radii (d_m/cos beta -+ D)/2 (rolling; + outer, concave)
    and -f D (transverse).  E' = E/(1 - nu^2) (ball and rings of one steel).
    """
    mp = _mp()
    D, d_m, Z = mp.mpf(D), mp.mpf(d_m), mp.mpf(n_balls)
    f_i, f_o, Fa = mp.mpf(f_i), mp.mpf(f_o), mp.mpf(Fa)
    Ep = mp.mpf(E) / (1 - mp.mpf(nu) ** 2)
    bf = mp.radians(mp.mpf(beta_f_deg))
    A = (f_i + f_o - 1) * D

    def K(beta, race):
        sgn = 1 if race == "inner" else -1
        f = f_i if race == "inner" else f_o
        r = _hertz_mp(1, D / 2, D / 2, sgn * (d_m / mp.cos(beta) - sgn * D) / 2, -f * D, Ep)
        return 1 / r["approach"] ** mp.mpf(1.5)

    def Kn(beta):
        return (K(beta, "inner") ** (-mp.mpf(2) / 3)
                + K(beta, "outer") ** (-mp.mpf(2) / 3)) ** (-mp.mpf(3) / 2)

    def h(beta):
        return Kn(beta) * A**1.5 * mp.sin(beta) * (mp.cos(bf) / mp.cos(beta) - 1) ** 1.5 - Fa / Z

    beta = mp.findroot(h, bf + mp.radians(2))
    return {"contact_angle": float(beta), "contact_angle_deg": float(mp.degrees(beta)),
            "Q": float(Fa / (Z * mp.sin(beta))),
            "axial_deflection": float(A * mp.sin(beta - bf) / mp.cos(beta)),
            "K_n": float(Kn(beta))}


_CASES = {
    # Hamrock & Dowson (1981) Table 3.2 geometries: D = 12.7 mm, F = 4.45 N, E' = 2.28e11 Pa
    "hd-ball-on-ball": (4.45, 6.35e-3, 6.35e-3, 6.35e-3, 6.35e-3, 2.28e11),
    "hd-ball-on-plane": (4.45, 6.35e-3, 6.35e-3, math.inf, math.inf, 2.28e11),
    "hd-209-outer": (4.45, 6.35e-3, 6.35e-3, -38.85e-3, -0.52 * 12.7e-3, 2.28e11),
    "hd-209-inner": (4.45, 6.35e-3, 6.35e-3, 26.15e-3, -0.52 * 12.7e-3, 2.28e11),
    # Ricci (2009) 218 bearing at beta_f = 40 deg, Q = 9445 N, E' = 200e9/(1 - 0.09)
    "ricci-218-inner": (9445.0, 22.225e-3 / 2, 22.225e-3 / 2,
                        (125.26e-3 / math.cos(math.radians(40)) - 22.225e-3) / 2,
                        -0.5232 * 22.225e-3, 200e9 / 0.91),
    "ricci-218-outer": (9445.0, 22.225e-3 / 2, 22.225e-3 / 2,
                        -(125.26e-3 / math.cos(math.radians(40)) + 22.225e-3) / 2,
                        -0.5232 * 22.225e-3, 200e9 / 0.91),
    # hybrid: Si3N4 ball (310 GPa, 0.27) 12.7 mm on a steel flat (200 GPa, 0.3), 1000 N
    "hybrid-ball-on-plane": (1000.0, 6.35e-3, 6.35e-3, math.inf, math.inf,
                             2 / ((1 - 0.27**2) / 310e9 + (1 - 0.3**2) / 200e9)),
    # a long thin ellipse: crossed cylinders of radii 1 m and 1 mm... Rx = 1 mm, Ry = 10 m
    "narrow-ellipse": (100.0, 1e-3, 10.0, math.inf, math.inf, 200e9 / 0.91),
}


def main() -> None:  # pragma: no cover - writes the tables quoted by the case files
    import sys

    def out(line: str) -> None:
        sys.stdout.write(line + "\n")

    for name, args in _CASES.items():
        d = hertz_exact(*args)
        out(name + " " + " ".join(f"{k}={v:.10g}" for k, v in d.items()))
    for nu in (0.25, 0.3):
        out(f"circle axis nu {nu} {circle_axis_max_shear(nu)}")
    out(f"line {line_max_shear()}")
    out(f"LP circle {lundberg_palmgren_circle()}")

    def table(label: str, d: dict) -> None:
        out(label + " " + " ".join(f"{k}={v:.10g}" for k, v in d.items()))

    # kinematics: CWRU bearings (inches), the 218 bearing at 40 deg, unequal angles
    table("cwru-6205-de", defect_frequencies_exact("0.3126", "1.537", 9))
    table("cwru-6203-fe", defect_frequencies_exact("0.2656", "1.122", 8))
    table("218-40deg", defect_frequencies_exact("22.225", "125.26", 16, 40))
    table("218-40deg-outer-rotating",
          defect_frequencies_exact("22.225", "125.26", 16, 40, rotating="outer"))
    table("218-50/31deg-outer-control", race_control_kinematics("22.225", "125.26", 50, 31))
    table("218-50/31deg-inner-control",
          race_control_kinematics("22.225", "125.26", 50, 31, "inner"))
    # high speed: 218 bearing ball, steel 7850 kg/m^3, 10,000 rpm inner ring
    table("218-10000rpm-dynamics", ball_dynamics("22.225e-3", "125.26e-3", 40, 7850, 10000))
    # zero speed: 218 bearing, 17,800 N thrust, E = 200 GPa, nu = 0.3
    table("218-17800N-static", static_thrust("22.225e-3", "125.26e-3", 16, "0.5232", "0.5232",
                                             40, "200e9", "0.3", 17800))


if __name__ == "__main__":  # pragma: no cover
    main()
