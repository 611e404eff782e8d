"""``ballrace bearing CASE.toml``: load distribution, contacts, ratings, life and film.

Registered on the main Typer app by :func:`register` (see :mod:`ballrace.cli`).  The
case file format is documented in :mod:`ballrace.casefiles.bearing`.  :func:`analyze`
does the work and returns plain SI numbers (what ``--json`` prints); the command only
renders them.
"""
from __future__ import annotations

import json
import logging
import math
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from ballrace.console import UNITS_HELP

__all__ = ["register", "analyze", "sections", "ball_columns"]

log = logging.getLogger(__name__)

#: Marks a number computed by a formula outside the range it was fitted on (a note says
#: which formula and which range).
FIT_MARK = " †"
#: Ellipticity parameters k of the Hamrock & Dowson (1977) film-thickness fits (1 <= k <= 8,
#: the range ``ehl.film_thickness_parts`` logs as extrapolated).
EHL_K_RANGE = (1.0, 8.0)


def analyze(case) -> dict:
    """Run a validated :class:`~ballrace.casefiles.bearing.BearingCase`.

    Returns
    -------
    dict
        ``{"title", "units", "bearing", "ratings", "distribution", "life", "film",
        "notes"}`` with SI values (lists per ball in ``distribution``).
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
    if i != 1:
        raise ValueError("the load distribution handles single-row bearings only (n_rows = 1)")
    if Fa == 0.0:
        res = brg.radial(Fr, **case.solver_options)
        method = "radial (H&D 1981 eqs. 3.39-3.42)"
    elif Fr == 0.0 and case.eccentricity is None:
        res = brg.thrust(Fa)
        method = "thrust (H&D 1981 eqs. 3.50-3.56)"
    elif Fr == 0.0:
        res = brg.eccentric_thrust(Fa, case.eccentricity)
        method = "eccentric thrust (Ricci 2009)"
    else:
        res = brg.combined(Fr, Fa, **case.solver_options)
        method = "combined radial and thrust (Jones; H&D 1981 eqs. 3.61-3.74)"
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

    return {
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
        "notes": notes,
    }


def _list(x):
    return [float(v) for v in np.atleast_1d(np.asarray(x, dtype=float))]


def sections(r: dict) -> list:
    """The summary blocks of :func:`analyze`'s result, as ``(title, rows)`` pairs.

    Each row is ``(name, SI value, kind)``; ``kind`` selects the display unit
    (:data:`ballrace.console.SYSTEMS`: "length", "small", "force", "stress", "modulus",
    "angle", ...), ``None`` for a dimensionless number, or ``"=unit"`` for a value printed
    as is.  A new block of results is one more entry in this list.
    """
    b, rt, lf, f = r["bearing"], r["ratings"], r["life"], r["film"]
    out = [(r["title"] or "bearing", [
        ("type", b["kind"], None), ("ball diameter D", b["ball_diameter"], "length"),
        ("balls Z", b["n_balls"], None), ("pitch diameter d_m", b["pitch_diameter"], "length"),
        ("conformity f_i", b["f_inner"], None), ("conformity f_o", b["f_outer"], None),
        *_clearance_rows(b),
        ("nominal contact angle (ratings)", b["nominal_contact_angle"], "angle"),
        ("E'", b["E_prime"], "modulus"),
        ("radial load Fr", b["radial_load"], "force"), ("axial load Fa", b["axial_load"], "force"),
        *([("thrust eccentricity e", b["eccentricity"], "length")]
          if b["eccentricity"] is not None else []),
        (f"speed ({b['rotating_ring']} ring)", b["speed_rpm"], "=rpm"),
        (f"C ({rt['standard']})", rt["C"], "force"), ("C0 (ISO 76)", rt["C0"], "force"),
    ])]
    rows = []
    cat = " *" if b.get("operating_clearance") is not None else ""   # clearance not seen
    if "P" in lf:
        rows += [("equivalent load P = X Fr + Y Fa", lf["P"], "force"),
                 ("X / Y / e", f"{lf['X']:.3g} / {lf['Y']:.3g} / {lf['e']:.3g}", None),
                 (f"L10 ({lf['standard']}){cat}", lf["L10"], "=1e6 rev"),
                 (f"L10h ({lf['standard']}){cat}", lf["L10h"], "=h")]
    rows += [("static equivalent load P0", lf["P0"], "force"),
             (f"static safety s0 = C0/P0{cat}", lf["s0"], None),
             ("static safety from p_max", lf["static_safety"], None),
             ("LP inner-ring life", lf["LP_inner"], "=1e6 rev"),
             ("LP outer-ring life", lf["LP_outer"], "=1e6 rev"),
             ("LP bearing L10 (e = 10/9)", lf["LP_L10"], "=1e6 rev"),
             ("LP bearing L10h", lf["LP_L10h"], "=h"),
             ("life factors D, E, F, G", f"{lf['material_factor']:.3g}, "
              f"{lf['processing_factor']:.3g}, {lf['lubrication_factor']:.3g}, "
              f"{lf['hardness_factor']:.3g}", None),
             ("adjusted LP life", lf["adjusted_LP_L10h"], "=h")]
    out.append(("Life", rows))
    if f:
        xi, xo = f.get("extrapolated_inner", False), f.get("extrapolated_outer", False)
        xmin = xi if f.get("h_min_race") == "inner" else xo
        rows = [("entrainment speed u (ball 1)", f["entrainment_speed"][0], "speed"),
                ("G = xi E'", f["G"], None),
                ("k inner / outer", f"{f['k_inner']:.3f}{FIT_MARK if xi else ''} / "
                                    f"{f['k_outer']:.3f}{FIT_MARK if xo else ''}", None),
                ("smallest h_min" + (FIT_MARK if xmin else ""), f["h_min"], "small")]
        if "Lambda" in f:
            rows.append(("film parameter Lambda" + (FIT_MARK if xmin else ""), f["Lambda"],
                         None))
        out.append(("Lubricant film (Hamrock & Dowson 1977)", rows))
    if r.get("iso"):                      # ISO 281 / ISO/TS 16281 block
        from ballrace.analytic import isocase

        out.append((isocase.TITLE, isocase.rows(r["iso"], catalogue_mark=cat)))
    return out


def _clearance_rows(b: dict) -> list:
    """Clearance and free contact angle as the load distribution used them."""
    op = b.get("operating_clearance")
    if op is None:
        return [("diametral clearance P_d", b["diametral_clearance"], "small"),
                ("free contact angle", b["free_contact_angle"], "angle")]
    rows = [("diametral clearance, unmounted", b["unmounted_clearance"], "small"),
            ("diametral clearance, operating" + (" (preload)" if op < 0 else ""), op, "small")]
    if op < 0:
        rows.append(("free contact angle (unmounted)", b["free_contact_angle"], "angle"))
    else:
        rows.append(("free contact angle (operating)", b["free_contact_angle"], "angle"))
    return rows


def ball_columns(r: dict, units: str = "eng") -> tuple[list, list]:
    """Headers (each with its unit) and rows of the per-ball table in ``units``."""
    from ballrace.console import convert as cv
    from ballrace.console import fmt
    from ballrace.console import unit_label as ul

    d, f = r["distribution"], r["film"]
    L, S, A = ul("length", units), ul("small", units), ul("angle", units)
    headers = ["ball", f"psi [{A}]", f"Q [{ul('force', units)}]", f"beta [{A}]",
               f"p_i [{ul('stress', units)}]", f"p_o [{ul('stress', units)}]",
               f"a_i x b_i [{L}]", f"a_o x b_o [{L}]"]
    if f:
        headers += [f"h_min,i{FIT_MARK if f.get('extrapolated_inner') else ''} [{S}]",
                    f"h_min,o{FIT_MARK if f.get('extrapolated_outer') else ''} [{S}]"]

    def g(x, kind, digits=5):
        return fmt(cv(x, kind, units), digits)

    rows = []
    for j in range(len(d["ball_load"])):
        row = [str(j + 1), g(d["azimuth"][j], "angle", 4), g(d["ball_load"][j], "force"),
               g(d["contact_angle"][j], "angle"), g(d["p_max_inner"][j], "stress", 4),
               g(d["p_max_outer"][j], "stress", 4),
               f"{g(d['a_inner'][j], 'length', 4)} x {g(d['b_inner'][j], 'length', 4)}",
               f"{g(d['a_outer'][j], 'length', 4)} x {g(d['b_outer'][j], 'length', 4)}"]
        if f:
            row += [g(f["h_min_inner"][j], "small", 4), g(f["h_min_outer"][j], "small", 4)]
        rows.append(row)
    return headers, rows


def _render(r: dict, units: str = "eng") -> None:
    from ballrace.console import literal, make_console, print_columns, print_sections

    con = make_console()
    secs = sections(r)
    print_sections(con, secs[:1], units)
    headers, rows = ball_columns(r, units)
    print_columns(con, f"Load distribution: {r['distribution']['method']}", headers, rows)
    print_sections(con, secs[1:], units)
    for n in [*r["notes"], *(r.get("iso") or {}).get("notes", [])]:
        con.print(literal(f"note: {n}"), style="dim")


def jsonable(obj):
    """JSON-safe copy: NaN / inf become null."""
    if isinstance(obj, dict):
        return {k: jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [jsonable(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def register(app) -> None:
    """Add the ``bearing`` command to a Typer app."""

    @app.command("bearing")
    def bearing(
        case_file: Annotated[str, typer.Argument(
            help="Bearing case file (TOML; docs/casefiles.md).")],
        as_json: Annotated[bool, typer.Option("--json", help="Machine-readable JSON (SI units).")] = False,
        units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
    ):
        """Load distribution, Hertz contacts, ratings, life and EHL film of a bearing case."""
        from ballrace.casefiles.bearing import CaseFileError, load_case
        from ballrace.cli import check_units, fail

        check_units(units)
        p = Path(case_file)
        if p.is_dir():
            fail(f"{case_file}: is a directory; give a bearing case file (.toml)")
        try:
            case = load_case(case_file)
            result = analyze(case)
        except CaseFileError as exc:
            fail(_kind_hint(p) or str(exc))
        except UnicodeDecodeError:
            fail(f"{case_file}: not a text file; give a bearing case file (TOML)")
        except (OSError, ValueError, RuntimeError) as exc:
            fail(f"{case_file}: {exc}")
        if as_json:
            typer.echo(json.dumps(jsonable(result), indent=2))
            return
        _render(result, units)


def _kind_hint(path) -> str | None:
    """A message when ``path`` is an FE or validation case file rather than a bearing case."""
    import tomllib

    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if "fem" in data or isinstance(data.get("case"), dict):
        return f"{path}: this is an FE case file; run it with `ballrace fem {path}`"
    if isinstance(data.get("case"), list):
        return (f"{path}: this is a validation case file; run it with "
                f"`ballrace validate --cases {path}`")
    return None
