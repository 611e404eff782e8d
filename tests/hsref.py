"""Independent re-derivation of a high-speed (Jones 1960) equilibrium from what a
``HighSpeedResult`` reports (used by tests/test_fuzz.py, tests/test_highspeed.py and
benchmarks/highspeed_population.py).

Written from the model's equations (Jones 1960; Hamrock & Dowson 1981 eqs. 3.93-3.112;
Harris 2001 ch. 25), not from the solver's internals: only the bearing's geometry,
``hertz.contact_stiffness`` and the reported quantities are used.
"""
import numpy as np

from ballrace.analytic import hertz


def _hs_shares(r):
    """Friction shares (lambda_i, lambda_o) of a HighSpeedResult: as reported, or (results
    without them) the rule of Harris (2001) ch. 25 from the control and the treatment."""
    li, lo = getattr(r, "inner_friction_share", None), getattr(r, "outer_friction_share", None)
    if li is not None:
        return np.asarray(li, float), np.asarray(lo, float)
    outer = np.asarray(r.control) == "outer"
    if r.gyroscopic == "none":
        return np.zeros(outer.shape), np.zeros(outer.shape)
    li = np.where(outer, 0.0, 1.0 if r.gyroscopic == "harris" else 2.0)
    li = np.where(np.asarray(r.inner_loads) > 0, li, 0.0)     # an open contact passes its
    return li, np.where(np.asarray(r.outer_loads) > 0, 2.0 - li, 0.0)    # share on


def rederive_highspeed(brg, r):
    """Re-derive the high-speed equilibrium from what a HighSpeedResult reports.

    Written from the model's equations (Jones 1960; Hamrock & Dowson 1981 eqs. 3.93-3.112;
    Harris 2001 ch. 25), not from the solver: the inner-groove centre from the ring
    displacements, each contact's approach from the ball position, the loads from the
    exact-Hertz stiffness at the contact angle of the geometry (a contact only on the
    groove's half torus, i.e. less than 90 deg from the groove bottom), F_c and M_g from
    the reported speeds, then the two force balances of every ball and the five ring
    balances.  Returns a list of (what, relative error) for every check failing 1e-8 of
    the load scale (max applied load, ball load, F_c), or the round-off floor of the
    contact law for loads of ~1e-8 N; empty when the result is right.
    """
    D, dm, Z = brg.ball_diameter, brg.pitch_diameter, brg.n_balls
    fi, fo, bf = brg.f_inner, brg.f_outer, brg.free_contact_angle
    A = (fi + fo - 1.0) * D
    Ri = brg.inner_groove_center_radius
    Roc = 0.5 * brg.outer_race_diameter - fo * D
    m = brg.ball_material.density * np.pi * D**3 / 6.0
    J = m * D**2 / 10.0
    psi = np.asarray(r.azimuths, float)
    dx, dy, dz, ty, tz = np.asarray(r.displacements, float)
    A1 = A * np.sin(bf) + dx + Ri * (ty * np.sin(psi) - tz * np.cos(psi))
    A2 = A * np.cos(bf) + dy * np.cos(psi) + dz * np.sin(psi)
    X1, X2 = np.asarray(r.ball_positions, float).T
    e1, e2 = A1 - X1, A2 - X2
    d_o = np.hypot(X1, X2) - (fo - 0.5) * D
    d_i = np.hypot(e1, e2) - (fi - 0.5) * D
    a_o, a_i = np.arctan2(X1, X2), np.arctan2(e1, e2)
    on_o, on_i = (X2 > 0) & (d_o > 0), (e2 > 0) & (d_i > 0)    # half-torus grooves
    g = D / dm

    def K(a, f, sign):
        Rx = 0.5 * D * (1.0 + sign * g * np.cos(a))
        return hertz.contact_stiffness(Rx, np.full(np.shape(a), f * D / (2 * f - 1)),
                                       brg.E_prime)

    Qo = np.where(on_o, K(a_o, fo, 1.0) * np.maximum(d_o, 0.0) ** 1.5, 0.0)
    Qi = np.where(on_i, K(a_i, fi, -1.0) * np.maximum(d_i, 0.0) ** 1.5, 0.0)
    wc, wR, beta = (np.asarray(v, float) for v in (r.orbital_speed, r.spin_speed,
                                                     r.pitch_angle))
    Fc = m * (Roc + X2) * wc**2                      # (1/2) m d_orbit omega_c^2
    Mg = J * wR * wc * np.sin(beta)
    li, lo = _hs_shares(r)
    if r.gyroscopic == "none":
        li, lo = np.zeros(Z), np.zeros(Z)
    scale = max(float(np.max(np.abs(r.applied))), float(np.max(Qi, initial=0.0)),
                float(np.max(Qo, initial=0.0)), float(np.max(Fc)), 1e-300)
    bad = []
    # round-off floor of the force checks: Q ~ delta^1.5 with delta a difference of
    # lengths of size |X| and A, each known to some eps |X| (differences of differences,
    # hypot, s - A: 1000 eps is generous); this matters only for loads so small that
    # delta ~ 1e-8 |X|, e.g. 1e-7 N on a 3 mm ball (2e-10 of the load at delta = 1e-3 |X|)
    d_max = max(float(np.max(np.r_[np.where(on_i, d_i, 0.0), np.where(on_o, d_o, 0.0)])),
                1e-300)                                     # (of the loaded contacts)
    floor = 1e3 * np.finfo(float).eps * max(float(np.max(np.abs(r.ball_positions))), A) / d_max

    def check(what, err, tol=1e-8):
        e = float(np.max(np.abs(err), initial=0.0)) / scale
        limit = max(tol, floor) if tol > 0 else 0.0       # (exact checks stay exact)
        if not e <= limit:
            bad.append((what, e))

    check("inner deflection", (d_i - r.inner_deflections) * scale / D, 1e-9)
    check("outer deflection", (d_o - r.outer_deflections) * scale / D, 1e-9)
    check("inner loads", Qi - r.inner_loads)
    check("outer loads", Qo - r.outer_loads)
    ai_r, ao_r = np.asarray(r.inner_contact_angles), np.asarray(r.outer_contact_angles)
    check("inner angles of loaded contacts", np.where(on_i, a_i - ai_r, 0.0) * scale, 1e-9)
    check("outer angles of loaded contacts", np.where(on_o, a_o - ao_r, 0.0) * scale, 1e-9)
    check("angles within +-90 deg", np.maximum(np.abs(np.r_[ai_r, ao_r]) - np.pi / 2, 0.0)
          * scale, 0.0)
    check("centrifugal force", Fc - r.centrifugal_force)
    check("gyroscopic moment", (Mg - r.gyroscopic_moment) / D)
    check("friction without load", np.r_[np.where(r.inner_loads > 0, 0.0, li),
                                         np.where(r.outer_loads > 0, 0.0, lo)] * scale, 0.0)
    # ball balances (H&D eqs. 3.104-3.105) with the REPORTED loads and angles
    Qi_r, Qo_r = np.asarray(r.inner_loads), np.asarray(r.outer_loads)
    gi, go = li * Mg / D, lo * Mg / D
    si, ci, so, co = np.sin(ai_r), np.cos(ai_r), np.sin(ao_r), np.cos(ao_r)
    check("ball axial balance", Qi_r * si - Qo_r * so - gi * ci + go * co)
    check("ball radial balance", Qi_r * ci - Qo_r * co + gi * si - go * so + Fc)
    # ring balance (H&D eqs. 3.111-3.112 on five DOFs)
    T = Qi_r * si - gi * ci
    P = Qi_r * ci + gi * si
    Mt = Ri * T + fi * li * Mg
    F = np.array([T.sum(), (P * np.cos(psi)).sum(), (P * np.sin(psi)).sum(),
                  (Mt * np.sin(psi)).sum(), -(Mt * np.cos(psi)).sum()])
    sc = np.array([1.0, 1.0, 1.0, Ri, Ri])
    check("ring resultant = reported loads", (F - r.loads) / sc)
    check("applied forces carried", (F - r.applied)[:3])    # (moments: reactions if held)
    return bad
