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

import numpy as np

__all__ = ["BearingAnalysis", "analyze", "load_distribution", "FIT_MARK", "EHL_K_RANGE"]

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
    apply to them.

    Returns
    -------
    BearingAnalysis
        The SI values (``to_dict()``: what ``ballrace bearing --json`` prints) and notes.
    """
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


def _list(x):
    return [float(v) for v in np.atleast_1d(np.asarray(x, dtype=float))]


