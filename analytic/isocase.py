"""ISO 281:2007 / ISO/TS 16281 life and operating clearance of a bearing case.

Used by ``ballrace bearing CASE.toml`` (:mod:`ballrace.commands.bearing`): :func:`iso_life`
computes plain SI numbers from a validated case and its load distribution; :func:`rows`
turns them into (quantity, value, unit) rows for the report table.
"""
from __future__ import annotations

import logging
import math

__all__ = ["iso_life", "rows"]

log = logging.getLogger(__name__)


def iso_life(case, result, P=None) -> dict:
    """κ, e_C, C_u, a_ISO, L_nm, L10r, L10mr and the operating clearance of a case.

    Parameters
    ----------
    case : BearingCase
        Validated case (:func:`ballrace.casefiles.bearing.load_case`).
    result : LoadDistribution
        Its load distribution (one load case).
    P : float, optional
        ISO 281 dynamic equivalent load [N]; without it L_nm is not computed.

    Returns
    -------
    dict
        SI values (N, m, m²/s, 1e6 rev; ``*_h`` in hours) and ``notes``.

    Examples
    --------
    >>> from ballrace.casefiles.bearing import parse_case
    >>> case = parse_case({"bearing": {"ball_diameter": "11.5 mm", "n_balls": 7,
    ...     "pitch_diameter": "43.5 mm", "f_inner": 0.52, "f_outer": 0.53,
    ...     "diametral_clearance": "0 mm"}, "loads": {"radial": "1 kN"},
    ...     "operation": {"speed": "3000 rpm"}, "oil": {"viscosity": "20 mm^2/s"},
    ...     "life": {"cleanliness": "normal cleanliness"}})
    >>> r = iso_life(case, case.bearing.radial(1000.0), P=1000.0)
    >>> round(r["kappa"], 3), r["contamination"], round(r["L10r"])
    (1.606, 0.55, 11518)
    """
    from ballrace.analytic import iso281, iso16281, ratings

    brg = case.bearing
    a_nom = case.nominal_contact_angle
    dm = brg.pitch_diameter
    notes: list[str] = []
    C = float(ratings.dynamic_rating(brg, contact_angle=a_nom, standard="ISO 281:2007"))
    C0 = float(ratings.static_rating(brg, contact_angle=a_nom))
    Cu_simple = float(iso281.fatigue_load_limit(C0, dm))
    Cu_hertz = iso281.fatigue_load_limit_hertz(brg, a_nom).C_u
    if case.fatigue_limit is not None:
        Cu, Cu_src = case.fatigue_limit, "given"
    elif case.fatigue_limit_method == "simplified":
        Cu, Cu_src = Cu_simple, "C0/22 (ISO 281 Annex B, simplified)"
    else:
        Cu, Cu_src = Cu_hertz, "1.5 GPa contact stress (ISO 281 Annex B, Hertz)"
    out: dict = {"C": C, "C_u": Cu, "C_u_source": Cu_src, "C_u_simplified": Cu_simple,
                 "C_u_hertz": Cu_hertz, "reliability": case.reliability,
                 "a1": float(iso281.reliability_factor(case.reliability)),
                 "contamination": case.contamination, "cleanliness": case.cleanliness}
    ref = iso16281.reference_rating_life(brg, result, dynamic_rating=C,
                                         rotating=case.rotating_ring,
                                         nominal_contact_angle=a_nom)
    n = case.speed_rpm
    out.update(L10r=ref.L10r, L10r_h=ref.hours(n), P_ref=ref.P_ref, Q_ci=ref.Q_ci,
               Q_ce=ref.Q_ce, Q_ei=ref.Q_ei, Q_ee=ref.Q_ee)
    nu = case.oil_viscosity
    if nu is not None:
        out["viscosity"] = nu
        out["nu1"] = float(iso281.reference_viscosity(n, dm))
        out["kappa"] = float(iso281.viscosity_ratio(nu, n, dm))
        if case.oil:
            out["oil_temperature"] = case.oil["temperature"]
    else:
        notes.append("no [oil]: kappa, a_ISO, L_nm and L10mr not computed")
    if case.contamination is None:
        notes.append("no [life].contamination or cleanliness: a_ISO, L_nm and L10mr not "
                     "computed")
    if "kappa" in out and case.contamination is not None:
        if out["kappa"] < iso281.KAPPA_MIN:
            notes.append(f"kappa = {out['kappa']:.3g} < 0.1: outside ISO 281:2007, no a_ISO")
        else:
            kw = dict(kappa=out["kappa"], contamination=case.contamination, fatigue_limit=Cu,
                      ep_additives=case.ep_additives)
            if P is not None:
                a = float(iso281.life_modification_factor(load=P, **kw))
                L = out["a1"] * a * (C / P) ** 3
                out.update(P=P, a_ISO=a, L_nm=L, L_nm_h=L * 1e6 / (60.0 * n))
            aref = ref.a_iso(**kw)
            Lmr = ref.modified(reliability=case.reliability, **kw)
            out.update(a_ISO_ref=aref, L10mr=Lmr, L10mr_h=Lmr * 1e6 / (60.0 * n))
            if case.ep_additives and out["kappa"] < 1.0 and case.contamination >= 0.2:
                notes.append("EP additives: kappa = 1 used and a_ISO limited to 3 "
                             "(ISO 281:2007 §9.3.3)")
            if out["kappa"] > iso281.KAPPA_MAX:
                notes.append(f"kappa = {out['kappa']:.3g} > 4 taken as 4 (ISO 281:2007)")
    oc = case.clearance
    if oc is not None:
        out["clearance"] = {"initial": oc.initial, "fit_inner": oc.fit_inner,
                            "fit_outer": oc.fit_outer, "thermal": oc.thermal,
                            "operating": oc.operating, "pressure_inner": oc.pressure_inner,
                            "pressure_outer": oc.pressure_outer}
    notes.append(f"C_u from {Cu_src} (both methods are in the table; Hertz / simplified = "
                 f"{Cu_hertz / Cu_simple:.3f})")
    out["notes"] = notes
    return out


def rows(iso: dict, catalogue_mark: str = "") -> list[tuple[str, object, object]]:
    """``(quantity, SI value, kind)`` rows of :func:`iso_life` for the ``bearing`` tables.

    ``kind`` follows :func:`ballrace.console.print_sections`: a unit kind converted to the
    display system (``"force"``, ``"small"``), ``None`` for a number, ``"=unit"`` printed as is.
    ``catalogue_mark`` is appended to the lives from the catalogue load P (an asterisk: they
    do not see the operating clearance, said in the notes).

    Examples
    --------
    >>> rows({"C": 22381.0, "C_u": 660.0, "C_u_source": "given", "a1": 1.0,
    ...       "reliability": 0.9, "L10r": 11518.0, "L10r_h": 63989.0,
    ...       "P_ref": 991.0})[0]
    ('C (ISO 281:2007)', 22381.0, 'force')
    """
    r: list[tuple[str, object, object]] = [
        ("C (ISO 281:2007)", iso["C"], "force"),
        ("fatigue load limit C_u", iso["C_u"], "force"),
    ]
    if "C_u_simplified" in iso and "C_u_hertz" in iso:
        r += [("- C_u by C0/22 (Annex B, simplified)", iso["C_u_simplified"], "force"),
              ("- C_u by 1.5 GPa contact stress (Hertz)", iso["C_u_hertz"], "force")]
    if "viscosity" in iso:
        if "oil_temperature" in iso:
            r.append(("oil temperature", iso["oil_temperature"], "temperature"))
        r += [("operating viscosity nu", iso["viscosity"] * 1e6, "=mm^2/s"),
              ("reference viscosity nu1", iso["nu1"] * 1e6, "=mm^2/s"),
              ("viscosity ratio kappa", iso["kappa"], None)]
    if iso.get("contamination") is not None:
        lvl = f" ({iso['cleanliness']})" if iso.get("cleanliness") else ""
        r.append((f"contamination factor e_C{lvl}", iso["contamination"], None))
    r.append((f"reliability {iso['reliability'] * 100:g} %: a1", iso["a1"], None))
    if "a_ISO" in iso:
        r += [("a_ISO (e_C C_u / P)", iso["a_ISO"], None),
              (f"modified rating life L_nm{catalogue_mark}", iso["L_nm"], "=1e6 rev"),
              (f"modified rating life L_nmh{catalogue_mark}", iso["L_nm_h"], "=h")]
    r += [("reference rating life L10r (ISO/TS 16281)", iso["L10r"], "=1e6 rev"),
          ("reference rating life L10rh", iso["L10r_h"], "=h"),
          ("equivalent reference load P_ref", iso["P_ref"], "force")]
    if "L10mr" in iso:
        r += [("a_ISO (e_C C_u / P_ref)", iso["a_ISO_ref"], None),
              ("modified reference life L10mr", iso["L10mr"], "=1e6 rev"),
              ("modified reference life L10mrh", iso["L10mr_h"], "=h")]
    c = iso.get("clearance")
    if c:
        r += [("unmounted clearance", c["initial"], "small"),
              ("- inner-ring fit", c["fit_inner"], "small"),
              ("- outer-ring fit", c["fit_outer"], "small"),
              ("+ temperatures", c["thermal"], "small"),
              ("operating clearance" + (" (preload)" if c["operating"] < 0 else ""),
               c["operating"], "small")]
    return [(q, v if isinstance(v, str) or not math.isfinite(v) else float(v), u)
            for q, v, u in r]


#: Title of the ISO block in the ``bearing`` output.
TITLE = "Life: ISO 281:2007 modified rating life, ISO/TS 16281 reference life"
