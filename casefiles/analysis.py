"""The analysis of a bearing case: which solver runs, its results and the notes on them.

:func:`analyze` takes a validated :class:`~ballrace.casefiles.bearing.BearingCase` and
returns a :class:`BearingAnalysis`: the load distribution :func:`load_distribution` chose,
the ratings, lives, film and ISO 281 / ISO/TS 16281 numbers in SI, and the notes that apply
to them, as data.  ``ballrace bearing`` (:mod:`ballrace.commands.bearing`) only renders it;
a report can call the same function.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import numpy as np

__all__ = ["BearingAnalysis", "analyze", "analyze_roller", "load_distribution",
           "roller_load_distribution", "FIT_MARK", "EHL_K_RANGE"]

#: Marks a number computed by a formula outside the range it was fitted on (a note says
#: which formula and which range).
FIT_MARK = " †"
#: Ellipticity parameters k of the Hamrock & Dowson (1977) film-thickness fits (1 <= k <= 8,
#: the range ``ehl.film_thickness_parts`` logs as extrapolated).
EHL_K_RANGE = (1.0, 8.0)


def load_distribution(case) -> tuple[str, object]:
    """Which load distribution solves ``case``, and its result: ``(method, result)``.

    A pure radial load: :meth:`~ballrace.BallBearing.radial` (Hamrock & Dowson, Ball
    Bearing Lubrication, 1981, eqs. 3.39-3.42); a pure thrust:
    :meth:`~ballrace.BallBearing.thrust` (eqs. 3.50-3.56), off-axis
    :meth:`~ballrace.BallBearing.eccentric_thrust` (Ricci 2009); both:
    :meth:`~ballrace.BallBearing.combined` (Jones; eqs. 3.61-3.74).  ``method`` names it
    for the report.  ``ValueError`` for a double-row bearing.
    """
    brg = case.bearing
    Fr, Fa = case.radial_load, case.axial_load
    if brg.n_rows != 1:
        raise ValueError("the load distribution handles single-row bearings only (n_rows = 1)")
    if Fa == 0.0:
        return "radial (H&D 1981 eqs. 3.39-3.42)", brg.radial(Fr, **case.solver_options)
    if Fr == 0.0 and case.eccentricity is None:
        return "thrust (H&D 1981 eqs. 3.50-3.56)", brg.thrust(Fa)
    if Fr == 0.0:
        return "eccentric thrust (Ricci 2009)", brg.eccentric_thrust(Fa, case.eccentricity)
    return ("combined radial and thrust (Jones; H&D 1981 eqs. 3.61-3.74)",
            brg.combined(Fr, Fa, **case.solver_options))


@dataclass(frozen=True)
class BearingAnalysis:
    """The results of a bearing case (frozen).

    Attributes
    ----------
    case : The :class:`~ballrace.casefiles.bearing.BearingCase` analysed.
    method : The load distribution that solved it (:func:`load_distribution`).
    distribution : Its result (a load distribution of :mod:`ballrace.analytic.loaddist`).
    values : The SI numbers by block: ``title``, ``units``, ``bearing``, ``ratings``,
        ``distribution`` (lists per ball), ``life``, ``film`` (or None), ``iso``.
    notes : What a reader of the numbers must know (models, ranges, what a number does
        not see), in the order they apply.
    """

    case: object
    method: str
    distribution: object
    values: dict
    notes: tuple = ()

    def to_dict(self) -> dict:
        """The values with the notes (``"notes"``, a list): what ``--json`` prints."""
        return {**self.values, "notes": list(self.notes)}


def analyze(case) -> BearingAnalysis:
    """Run a validated :class:`~ballrace.casefiles.bearing.BearingCase`: its load
    distribution (:func:`load_distribution`), ratings, lives and film, and the notes that
    apply to them.  A roller-bearing case goes to :func:`analyze_roller`.

    Returns
    -------
    BearingAnalysis
        The SI values (``to_dict()``: what ``ballrace bearing --json`` prints) and notes.
    """
    if getattr(case, "is_roller", False):
        return analyze_roller(case)
    from ballrace.analytic import ehl, life, ratings

    brg = case.bearing
    a_nom = case.nominal_contact_angle
    D, Z, dm = brg.ball_diameter, brg.n_balls, brg.pitch_diameter
    i = brg.n_rows
    notes = []
    C = ratings.dynamic_rating(brg, contact_angle=a_nom, standard=case.standard)
    C0 = ratings.static_rating(brg, contact_angle=a_nom)
    f0 = float(ratings.f0_factor(D * math.cos(a_nom) / dm))
    Fr, Fa = case.radial_load, case.axial_load

    # ---------------------------------------------------------------- load distribution
    method, res = load_distribution(case)
    Q = np.asarray(res.ball_loads, dtype=float)
    beta = np.asarray(res.contact_angles, dtype=float)
    ci, co = res.inner, res.outer
    psi = np.asarray(res.azimuths, dtype=float)

    # ---------------------------------------------------------------- ratings and life
    out_life: dict = {"standard": case.standard}
    try:
        eq = life.equivalent_load(Fr, Fa, static_rating=C0, f0=f0, contact_angle=a_nom,
                                  n_rows=i, standard=case.standard)
        P = float(eq.P)
        out_life.update(P=P, X=float(eq.X), Y=float(eq.Y), e=float(eq.e),
                        L10=float(life.l10(C, P)),
                        L10h=float(life.l10_hours(C, P, speed_rpm=case.speed_rpm)))
        if case.eccentricity is not None:
            notes.append("the catalog equivalent load P = X Fr + Y Fa ignores the moment of "
                         "an eccentric thrust, so the ISO life above is not conservative; "
                         "use the Lundberg-Palmgren life from the load distribution")
    except ValueError as exc:
        notes.append(f"equivalent load not available: {exc}")
    P0 = float(ratings.static_equivalent_load(Fr, Fa, a_nom, i))
    lp = life.bearing_life(brg, res, rotating=case.rotating_ring)
    notes.append("static safety: s0 = C0/P0 with P0 = X0 Fr + Y0 Fa (ISO 76, the catalogue "
                 "check); from p_max: s0 = (4200 MPa / p_max)^3 on the most loaded contact of "
                 "the load distribution (ISO 76 bases C0 on 4200 MPa)")
    out_life.update(P0=P0, s0=float(ratings.static_safety_factor(C0, P0)),
                    static_safety=float(res.static_safety),
                    LP_inner=lp.L_inner, LP_outer=lp.L_outer, LP_L10=lp.L10,
                    LP_L10h=lp.hours(case.speed_rpm), Q_e_inner=lp.Q_e_inner,
                    Q_e_outer=lp.Q_e_outer)

    # ---------------------------------------------------------------- film
    film: dict | None = None
    F_lub = case.lubrication_factor
    if case.viscosity is not None:
        wi, wo = (case.speed, 0.0) if case.rotating_ring == "inner" else (0.0, case.speed)
        u = np.asarray(ehl.entrainment_speed(D, dm, beta, speed_inner=wi, speed_outer=wo))
        u = np.broadcast_to(u, Q.shape)
        fi = ehl.film_thickness(ci, entrainment_speed=u, viscosity=case.viscosity,
                                pressure_viscosity=case.pressure_viscosity)
        fo = ehl.film_thickness(co, entrainment_speed=u, viscosity=case.viscosity,
                                pressure_viscosity=case.pressure_viscosity)
        loaded = Q > 0
        k_lo, k_hi = EHL_K_RANGE

        def outside(k):                   # any loaded ball beyond the fits' ellipticities
            k = np.broadcast_to(np.asarray(k, dtype=float), Q.shape)[loaded]
            return bool(np.any((k < k_lo) | (k > k_hi)))

        hi_i = np.nanmin(fi.h_min[loaded] if fi.h_min.ndim else fi.h_min)
        hi_o = np.nanmin(fo.h_min[loaded] if fo.h_min.ndim else fo.h_min)
        film = {
            "entrainment_speed": _list(u),
            "h_min_inner": _list(fi.h_min), "h_central_inner": _list(fi.h_central),
            "h_min_outer": _list(fo.h_min), "h_central_outer": _list(fo.h_central),
            "k_inner": float(np.max(fi.k)), "k_outer": float(np.max(fo.k)),
            "G": float(np.max(fi.G)),
            "h_min": float(min(hi_i, hi_o)),
            "h_min_race": "inner" if hi_i <= hi_o else "outer",
            "k_fit_range": [k_lo, k_hi],
            "extrapolated_inner": outside(fi.k), "extrapolated_outer": outside(fo.k),
        }
        if film["extrapolated_inner"] or film["extrapolated_outer"]:
            ks = ", ".join(f"{k:.3g} ({race} race)" for k, race, x in (
                (film["k_inner"], "inner", film["extrapolated_inner"]),
                (film["k_outer"], "outer", film["extrapolated_outer"])) if x)
            notes.append(f"{FIT_MARK.strip()} extrapolated: the ellipticity parameter k = {ks} "
                         f"is outside the range {k_lo:g} <= k <= {k_hi:g} of the Hamrock & "
                         "Dowson (1977) film-thickness fits; the film thicknesses marked "
                         f"{FIT_MARK.strip()} (and Lambda, F from them) are the fits used "
                         "beyond their range, an estimate")
        if case.roughness_race is not None and case.roughness_ball is not None:
            lam = float(ehl.film_parameter(film["h_min"], case.roughness_race,
                                           case.roughness_ball))
            film["Lambda"] = lam
            if F_lub is None:
                F_lub = float(life.lubrication_factor(lam, warn=False))
                film["lubrication_factor"] = F_lub
                notes.append("lubrication factor F from Lambda via an approximate "
                             "reconstruction of H&D (1981) fig. 3.16 (+-30 %)")
    Dm = life.material_factor(case.material) if case.material else 1.0
    Em = life.processing_factor(case.processing) if case.processing else 1.0
    G = float(life.hardness_factor(case.hardness_hrc)) if case.hardness_hrc else 1.0
    F = 1.0 if F_lub is None else float(F_lub)
    out_life.update(material_factor=Dm, processing_factor=Em, lubrication_factor=F,
                    hardness_factor=G,
                    adjusted_LP_L10=float(life.adjusted_life(lp.L10, material=Dm,
                                                             processing=Em, lubrication=F,
                                                             hardness=G)))
    out_life["adjusted_LP_L10h"] = out_life["adjusted_LP_L10"] * 1e6 / (60 * case.speed_rpm)
    notes.append("adjusted life = D E F G x Lundberg-Palmgren life (air-melt 52100 basis, "
                 "Bamberger et al. 1971); not applied to the ISO 281:2007 life, whose b_m "
                 "already credits modern steel")
    if case.rotating_ring == "outer":
        notes.append("outer ring rotating under a fixed load: the ISO life has no rotation "
                     "factor; Tata (2012) multiplies P by 1.25 (life.load_factor), the "
                     "Lundberg-Palmgren life accounts for it through the ring equivalent loads")
    preloaded = case.clearance is not None and case.clearance.operating < 0
    if preloaded:
        notes.append(f"ratings (C, C0, C_u, X/Y, ISO/TS 16281 Q_c) at the nominal contact "
                     f"angle {math.degrees(a_nom):.2f} deg (ISO 281:2007); the load "
                     "distribution uses the operating clearance (a preload)")
    elif not math.isclose(a_nom, brg.free_contact_angle, rel_tol=0.0, abs_tol=1e-12):
        notes.append(f"ratings (C, C0, C_u, X/Y, ISO/TS 16281 Q_c) at the nominal contact "
                     f"angle {math.degrees(a_nom):.2f} deg (ISO 281:2007); the free contact "
                     f"angle {math.degrees(brg.free_contact_angle):.2f} deg is used by the "
                     "load distribution")

    # ---------------------------------------------------------------- ISO 281 / 16281 -----------
    from ballrace.analytic import isocase

    iso = isocase.iso_life(case, res, P=out_life.get("P"))
    oc = case.clearance
    if oc is not None and "P" in out_life:
        # every number of the report from one operating state: say which do not see it
        notes.append("* the operating clearance (fits, temperatures; in the tables)"
                     " is used by the load distribution, the Lundberg-Palmgren and the "
                     "ISO/TS 16281 lives (L10r, L10mr) and the static safety from p_max; the "
                     "catalogue lives L10 and L_nm come from P = X Fr + Y Fa, and s0 = C0/P0 "
                     "from P0 = X0 Fr + Y0 Fa, which do not see the clearance"
                     + (" - for this preloaded bearing they are not its life and not its "
                        "static safety" if oc.operating < 0 else ""))

    values = {
        "title": case.title,
        "units": {"length": "m", "force": "N", "pressure": "Pa", "angle": "rad",
                  "speed": "rad/s (speed_rpm: rev/min)", "life": "1e6 rev (…h: hours)"},
        "bearing": {"kind": case.kind, "ball_diameter": D, "n_balls": Z, "pitch_diameter": dm,
                    "f_inner": brg.f_inner, "f_outer": brg.f_outer,
                    "diametral_clearance": brg.diametral_clearance,
                    "free_contact_angle": brg.free_contact_angle, "E_prime": brg.E_prime,
                    "unmounted_clearance": None if oc is None else oc.initial,
                    "operating_clearance": None if oc is None else oc.operating,
                    "nominal_contact_angle": a_nom, "speed": case.speed,
                    "speed_rpm": case.speed_rpm, "rotating_ring": case.rotating_ring,
                    "radial_load": Fr, "axial_load": Fa, "eccentricity": case.eccentricity},
        "ratings": {"C": C, "C0": C0, "f0": f0, "standard": case.standard},
        "distribution": {
            "method": method, "azimuth": _list(psi), "ball_load": _list(Q),
            "contact_angle": _list(np.broadcast_to(beta, Q.shape)),
            "p_max_inner": _list(ci.p_max), "p_max_outer": _list(co.p_max),
            "a_inner": _list(ci.a), "b_inner": _list(ci.b),
            "a_outer": _list(co.a), "b_outer": _list(co.b),
            "max_ball_load": float(np.max(Q)),
            "max_pressure": float(max(np.max(ci.p_max), np.max(co.p_max))),
        },
        "life": out_life,
        "film": film,
        "iso": iso,
    }
    return BearingAnalysis(case=case, method=method, distribution=res, values=values,
                           notes=tuple(notes))


# ============================================================================ roller bearings
def roller_load_distribution(case) -> tuple[str, object]:
    """The lamina load distribution of a roller-bearing case: ``(method, result)``.

    :meth:`~ballrace.analytic.roller.RollerBearing.solve` with the radial load along +y
    (``Fy = F_r``, roller 1 on the load line), ``Fa = F_a`` (tapered; a cylindrical
    bearing's axial DOF is held) and the inner ring's tilt held: theta_y = 0, theta_z =
    ``[loads].misalignment`` (default 0), so that the reaction moment holding it is part
    of the result (``result.loads``).
    """
    b = case.bearing
    mis = case.misalignment or 0.0
    disp = [None, None, None, 0.0, mis]
    method = ("ISO/TS 16281 lamina model, "
              + ("combined radial and axial" if b.tapered else "radial")
              + (", ring tilt held" if mis else ", rings held aligned"))
    return method, b.solve(Fa=case.axial_load, Fy=case.radial_load, displacements=disp)


def analyze_roller(case) -> BearingAnalysis:
    """The analysis of a roller-bearing case (:func:`analyze` hands it here): the lamina
    load distribution (:func:`roller_load_distribution`), the ISO 281 / ISO 76 ratings,
    the ISO 281 life from P (tapered: X, Y) with L10 = (C/P)^(10/3), the ISO/TS 16281
    reference life L10r from the slice loads, the static safety s0 (ISO 76) from the
    catalogue P0 and from the most loaded slice's pressure, a_ISO lives when ``[oil]``
    and the contamination are given, and the notes that apply.
    """
    from ballrace.analytic import iso281, life
    from ballrace.analytic.roller import ratings as rr

    b = case.bearing
    a = b.contact_angle
    Fr, Fa = case.radial_load, case.axial_load
    n = case.speed_rpm
    notes: list[str] = []
    C, C0 = b.dynamic_rating(), b.static_rating()

    method, res = roller_load_distribution(case)
    Q = np.asarray(res.roller_loads, dtype=float)
    p_in = np.asarray(res.slice_pressures("inner"), dtype=float)
    p_out = np.asarray(res.slice_pressures("outer"), dtype=float)
    p_roller = np.maximum(p_in.max(-1), p_out.max(-1))
    edge = np.asarray(res.edge_loaded, dtype=bool)

    # ---------------------------------------------------------------- ISO 281 / ISO 76
    out_life: dict = {"standard": case.standard}
    P = float(rr.dynamic_equivalent_load(Fr, Fa, a))
    if b.tapered:
        f = rr.tapered_factors(a)
        low = Fa <= f.e * Fr
        out_life.update(X=f.X1 if low else f.X2, Y=f.Y1 if low else f.Y2, e=f.e,
                        X0=f.X0, Y0=f.Y0)
    else:
        out_life.update(X=1.0, Y=0.0, e=None, X0=1.0, Y0=0.0)
    L10 = float(rr.rating_life(C, P))
    P0 = float(rr.static_equivalent_load(Fr, Fa, a))
    out_life.update(P=P, L10=L10, L10h=L10 * 1e6 / (60.0 * n), P0=P0, s0=C0 / P0,
                    static_safety=float(res.static_safety),
                    max_pressure=float(res.max_pressure))
    ref = life.reference_rating_life(b, res, dynamic_rating=C, rotating=case.rotating_ring)
    out_life.update(L10r=float(ref.L10r), L10r_h=float(ref.hours(n)), P_ref=float(ref.P_ref),
                    L_inner=float(ref.L_inner), L_outer=float(ref.L_outer),
                    Q_ci=float(ref.Q_ci), Q_ce=float(ref.Q_ce))
    a1 = float(iso281.reliability_factor(case.reliability))
    Cu = case.fatigue_limit if case.fatigue_limit is not None else \
        float(rr.fatigue_load_limit(C0, b.pitch_diameter))
    out_life.update(reliability=case.reliability, a1=a1, C_u=Cu,
                    C_u_source="given" if case.fatigue_limit is not None else
                    "C0/8.2 (ISO 281 Annex B, simplified)",
                    contamination=case.contamination, cleanliness=case.cleanliness)
    nu = case.oil_viscosity
    if nu is not None:
        out_life.update(viscosity=nu, nu1=float(iso281.reference_viscosity(n, b.pitch_diameter)),
                        kappa=float(iso281.viscosity_ratio(nu, n, b.pitch_diameter)))
    if nu is None or case.contamination is None:
        notes.append("a_ISO, L_nm and L10mr need [oil] and [life].cleanliness (or "
                     "contamination): not computed")
    elif out_life["kappa"] < iso281.KAPPA_MIN:
        notes.append(f"kappa = {out_life['kappa']:.3g} < 0.1: outside ISO 281:2007, no a_ISO")
    else:
        kw = dict(kappa=out_life["kappa"], contamination=case.contamination,
                  fatigue_limit=Cu, ep_additives=case.ep_additives)
        aiso = float(rr.life_modification_factor(load=P, **kw))
        Lnm = a1 * aiso * L10
        Lmr = float(ref.modified(reliability=case.reliability, **kw))
        out_life.update(a_ISO=aiso, L_nm=Lnm, L_nm_h=Lnm * 1e6 / (60.0 * n),
                        a_ISO_ref=float(ref.a_iso(**kw)), L10mr=Lmr,
                        L10mr_h=Lmr * 1e6 / (60.0 * n))
        if out_life["kappa"] > iso281.KAPPA_MAX:
            notes.append(f"kappa = {out_life['kappa']:.3g} > 4 taken as 4 (ISO 281:2007)")

    # ---------------------------------------------------------------- notes
    notes.append("lamina model (ISO/TS 16281): each roller cut into independent slices; "
                 "the rings are rigid, the rollers' centrifugal and gyroscopic loads and "
                 "skew are left out")
    if edge.any():
        js = ", ".join(str(j + 1) for j in np.flatnonzero(edge))
        notes.append(f"edge loading (rollers {js}): an end slice carries load; the lamina "
                     "model has no pressure peak at the roller end, so the slice pressure, "
                     "s0 from it and L10r miss the edge stress there (the half-space line "
                     "contact, RollerLoadDistribution.roller_contact, shows it)")
    if b.tapered:
        notes.append("tapered: the cone and rib loads are fixed multiples of the cup load "
                     "(the roller's own equilibrium, default rib angle); the rib contact's "
                     "compliance is neglected")
    else:
        notes.append("cylindrical: the locating flanges (NJ, NUP, NF) are not modelled; the "
                     "bearing carries no axial load here")
    M = np.asarray(res.loads, dtype=float)[3:]
    M = np.where(np.abs(M) < 1e-9 * (Fr + Fa) * b.pitch_diameter, 0.0, M)   # round-off
    held = "at the misalignment" if case.misalignment else "aligned"
    notes.append(f"the inner ring's tilt is held ({held}); the moment holding it is "
                 f"My = {M[0]:.4g} N m, Mz = {M[1]:.4g} N m")
    notes.append("static safety: s0 = C0/P0 (ISO 76, the catalogue check) and s0 = "
                 "(4000 MPa / p_max)^2 from the most loaded slice of the load distribution "
                 "(ISO 76 bases C0 of roller bearings on 4000 MPa; line contact: load ~ p^2)")
    if b.profile.name in ("lundberg", "johns-gohar"):
        notes.append(f"the {b.profile.name} profile is designed for Q_d = "
                     f"{b.design_load:.4g} N (4000 MPa at the inner contact of a uniformly "
                     "loaded roller)")

    half_space = _roller_half_space(res, p_in, p_out)
    if half_space is not None:
        notes.append(f"half-space: the finite line contact of the most loaded roller "
                     f"({half_space['roller'] + 1}) at the {half_space['raceway']} raceway, "
                     "its slices coupled through the elastic half-space (roller_contact), and "
                     "the stresses below it (subsurface_stress); read an end value of a "
                     "straight or edge-loaded roller as an edge peak that grows with the "
                     "slice count")
    tilts = np.asarray(res.roller_tilts, dtype=float)
    values = {
        "title": case.title,
        "units": {"length": "m", "force": "N", "pressure": "Pa", "angle": "rad",
                  "speed": "rad/s (speed_rpm: rev/min)", "life": "1e6 rev (…h: hours)",
                  "moment": "N m"},
        "bearing": {"kind": case.kind, "roller_diameter": b.roller_diameter,
                    "roller_length": b.roller_length, "n_rollers": b.n_rollers,
                    "pitch_diameter": b.pitch_diameter, "contact_angle": a,
                    "cone_angle": b.cone_angle if b.tapered else None,
                    "roller_half_angle": b.roller_half_angle,
                    "rib_contact_angle": b.rib_contact_angle if b.tapered else None,
                    "diametral_clearance": b.diametral_clearance,
                    "profile": b.profile.name, "n_slices": b.n_slices,
                    "slice_width": b.slice_width, "E_prime": b.E_prime,
                    "speed": case.speed, "speed_rpm": n, "rotating_ring": case.rotating_ring,
                    "radial_load": Fr, "axial_load": Fa, "misalignment": case.misalignment},
        "ratings": {"C": C, "C0": C0, "standard": case.standard},
        "distribution": {
            "method": method, "azimuth": _list(res.azimuths), "roller_load": _list(Q),
            "inner_load": _list(res.inner_loads), "rib_load": _list(res.rib_loads),
            "max_slice_pressure": _list(p_roller), "roller_tilt": _list(tilts),
            "edge_loaded": [bool(x) for x in edge],
            "edge_load_ratio": _list(res.edge_load_ratio),
            "slice_position": _list(b.slice_positions),
            "slice_loads": [_list(row) for row in np.asarray(res.slice_loads, float)],
            "slice_pressure_inner": [_list(row) for row in p_in],
            "slice_pressure_outer": [_list(row) for row in p_out],
            "displacements": _list(res.displacements), "loads": _list(res.loads),
            "max_roller_load": float(np.max(Q)), "max_pressure": float(res.max_pressure),
            "half_space": half_space,
        },
        "life": out_life,
    }
    return BearingAnalysis(case=case, method=method, distribution=res, values=values,
                           notes=tuple(notes))


def _roller_half_space(res, p_in, p_out) -> Optional[dict]:
    """The most loaded roller on the half-space at the raceway of the larger lamina
    pressure: its line contact's pressure peak and the von Mises / Tresca maxima below it
    (SI), or None without load."""
    from ballrace.analytic.roller import subsurface_stress

    raceway = "inner" if p_in.max() >= p_out.max() else "outer"
    j = res.most_loaded_roller(raceway)
    c = res.roller_contact(j, raceway)
    if not c.load > 0.0:
        return None
    s = subsurface_stress(c, nu=res.bearing.material.nu)     # = res.subsurface(raceway)
    k, i = int(np.argmax(c.pressure)), int(np.argmax(s.von_mises_max))
    t = int(np.argmax(s.tresca_max))
    return {"raceway": raceway, "roller": j, "load": float(c.load),
            "x": _list(c.x), "pressure": _list(c.pressure),
            "peak_pressure": float(c.pressure[k]), "peak_pressure_x": float(c.x[k]),
            "von_mises_max": float(s.von_mises_max[i]),
            "von_mises_depth": float(s.von_mises_depth[i]), "von_mises_x": float(s.x[i]),
            "tresca_max": float(s.tresca_max[t]), "tresca_depth": float(s.tresca_depth[t]),
            "tresca_x": float(s.x[t])}


def _list(x):
    return [float(v) for v in np.atleast_1d(np.asarray(x, dtype=float))]


