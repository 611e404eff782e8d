"""``ballrace bearing CASE.toml``: load distribution, contacts, ratings, life and film.

Registered on the main Typer app by :func:`register` (see :mod:`ballrace.cli`).  The
case file format is documented in :mod:`ballrace.analytic.casefile`.  :func:`analyze`
does the work and returns plain SI numbers (what ``--json`` prints); the command only
renders them.
"""
from __future__ import annotations

import json
import logging
import math
from typing import Annotated

import numpy as np
import typer

__all__ = ["register", "analyze"]

log = logging.getLogger(__name__)


def analyze(case) -> dict:
    """Run a validated :class:`~ballrace.analytic.casefile.BearingCase`.

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
    out_life.update(P0=P0, s0=float(ratings.static_safety_factor(C0, P0)),
                    LP_inner=lp.L_inner, LP_outer=lp.L_outer, LP_L10=lp.L10,
                    LP_L10h=lp.hours(case.speed_rpm), Q_e_inner=lp.Q_e_inner,
                    Q_e_outer=lp.Q_e_outer)

    # ---------------------------------------------------------------- film
    film: dict | None = None
    F_lub = case.lubrication_factor
    if case.viscosity is not None:
        wi, wo = (case.speed, 0.0) if case.rotating_ring == "inner" else (0.0, case.speed)
        u = np.asarray(ehl.entrainment_speed(D, dm, beta, inner_speed=wi, outer_speed=wo))
        u = np.broadcast_to(u, Q.shape)
        fi = ehl.film_thickness(ci, entrainment_speed=u, viscosity=case.viscosity,
                                pressure_viscosity=case.pressure_viscosity)
        fo = ehl.film_thickness(co, entrainment_speed=u, viscosity=case.viscosity,
                                pressure_viscosity=case.pressure_viscosity)
        loaded = Q > 0
        film = {
            "entrainment_speed": _list(u),
            "h_min_inner": _list(fi.h_min), "h_central_inner": _list(fi.h_central),
            "h_min_outer": _list(fo.h_min), "h_central_outer": _list(fo.h_central),
            "k_inner": float(np.max(fi.k)), "k_outer": float(np.max(fo.k)),
            "G": float(np.max(fi.G)),
            "h_min": float(min(np.nanmin(fi.h_min[loaded] if fi.h_min.ndim else fi.h_min),
                               np.nanmin(fo.h_min[loaded] if fo.h_min.ndim else fo.h_min))),
        }
        if case.roughness_race is not None and case.roughness_ball is not None:
            lam = float(ehl.film_parameter(film["h_min"], case.roughness_race,
                                           case.roughness_ball))
            film["Lambda"] = lam
            if F_lub is None:
                F_lub = float(life.lubrication_factor(lam))
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
    if case.kind == "deep-groove" and brg.free_contact_angle > 0:
        notes.append(f"ratings at nominal contact angle 0 (deep groove); the free contact "
                     f"angle {math.degrees(brg.free_contact_angle):.2f} deg is used by the "
                     "load distribution")

    # ---------------------------------------------------------------- ISO 281 / 16281 (issue 12)
    from ballrace.analytic import isocase

    iso = isocase.iso_life(case, res, P=out_life.get("P"))

    return {
        "title": case.title,
        "units": {"length": "m", "force": "N", "pressure": "Pa", "angle": "rad",
                  "speed": "rad/s (speed_rpm: rev/min)", "life": "1e6 rev (…h: hours)"},
        "bearing": {"kind": case.kind, "ball_diameter": D, "n_balls": Z, "pitch_diameter": dm,
                    "f_inner": brg.f_inner, "f_outer": brg.f_outer,
                    "diametral_clearance": brg.diametral_clearance,
                    "free_contact_angle": brg.free_contact_angle, "E_prime": brg.E_prime,
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


def _render(r: dict) -> None:
    from rich.console import Console
    from rich.table import Table

    con = Console()
    b, rt, lf = r["bearing"], r["ratings"], r["life"]
    t = Table(title=r["title"] or "bearing")
    for col in ("quantity", "value", "unit"):
        t.add_column(col, justify="right" if col == "value" else "left")
    rows = [
        ("type", b["kind"], ""), ("ball diameter D", b["ball_diameter"] * 1e3, "mm"),
        ("balls Z", b["n_balls"], ""), ("pitch diameter d_m", b["pitch_diameter"] * 1e3, "mm"),
        ("f_i / f_o", f"{b['f_inner']:.4g} / {b['f_outer']:.4g}", ""),
        ("diametral clearance", b["diametral_clearance"] * 1e6, "um"),
        ("free contact angle", math.degrees(b["free_contact_angle"]), "deg"),
        ("E'", b["E_prime"] / 1e9, "GPa"),
        ("radial / axial load", f"{b['radial_load']:.6g} / {b['axial_load']:.6g}", "N"),
        ("speed", b["speed_rpm"], f"rpm ({b['rotating_ring']} ring)"),
        (f"C ({rt['standard']})", rt["C"] / 1e3, "kN"), ("C0 (ISO 76)", rt["C0"] / 1e3, "kN"),
    ]
    for name, v, u in rows:
        t.add_row(name, v if isinstance(v, str) else f"{v:.6g}", u)
    con.print(t)

    d = r["distribution"]
    f = r["film"]
    t = Table(title=f"Load distribution — {d['method']}")
    cols = ["ball", "psi [deg]", "Q [N]", "beta [deg]", "p_i [MPa]", "p_o [MPa]",
            "a_i x b_i [mm]"]
    if f:
        cols += ["h_min,i [um]", "h_min,o [um]"]
    for c in cols:
        t.add_column(c, justify="right")
    for j in range(len(d["ball_load"])):
        row = [str(j + 1), f"{math.degrees(d['azimuth'][j]):.1f}", f"{d['ball_load'][j]:.1f}",
               f"{math.degrees(d['contact_angle'][j]):.3f}",
               f"{d['p_max_inner'][j] / 1e6:.0f}", f"{d['p_max_outer'][j] / 1e6:.0f}",
               f"{d['a_inner'][j] * 1e3:.3f} x {d['b_inner'][j] * 1e3:.3f}"]
        if f:
            row += [_um(f["h_min_inner"][j]), _um(f["h_min_outer"][j])]
        t.add_row(*row)
    con.print(t)

    t = Table(title="Life")
    t.add_column("quantity")
    t.add_column("value", justify="right")
    t.add_column("unit")
    rows = []
    if "P" in lf:
        rows += [("equivalent load P = X Fr + Y Fa", lf["P"], f"N (X={lf['X']:.3g}, "
                  f"Y={lf['Y']:.3g}, e={lf['e']:.3g})"),
                 (f"L10 ({lf['standard']})", lf["L10"], "1e6 rev"),
                 (f"L10h ({lf['standard']})", lf["L10h"], "h")]
    rows += [("static equivalent load P0", lf["P0"], "N"), ("static safety s0 = C0/P0", lf["s0"], ""),
             ("LP inner-ring life", lf["LP_inner"], "1e6 rev"),
             ("LP outer-ring life", lf["LP_outer"], "1e6 rev"),
             ("LP bearing L10 (e = 10/9)", lf["LP_L10"], "1e6 rev"),
             ("LP bearing L10h", lf["LP_L10h"], "h"),
             ("factors D, E, F, G", f"{lf['material_factor']:.3g}, {lf['processing_factor']:.3g},"
              f" {lf['lubrication_factor']:.3g}, {lf['hardness_factor']:.3g}", ""),
             ("adjusted LP life", lf["adjusted_LP_L10h"], "h")]
    for name, v, u in rows:
        t.add_row(name, v if isinstance(v, str) else f"{v:.6g}", u)
    con.print(t)

    if f:
        t = Table(title="Lubricant film (Hamrock & Dowson 1977)")
        t.add_column("quantity")
        t.add_column("value", justify="right")
        t.add_column("unit")
        t.add_row("entrainment speed u (ball 1)", f"{f['entrainment_speed'][0]:.4g}", "m/s")
        t.add_row("G = xi E'", f"{f['G']:.4g}", "")
        t.add_row("k inner / outer", f"{f['k_inner']:.3f} / {f['k_outer']:.3f}", "")
        t.add_row("smallest h_min", _um(f["h_min"]), "um")
        if "Lambda" in f:
            t.add_row("film parameter Lambda", f"{f['Lambda']:.3g}", "")
        con.print(t)
    for n in r["notes"]:
        con.print(f"[dim]note: {n}[/dim]")
    if r.get("iso"):                      # ISO 281 / ISO/TS 16281 block (issue 12)
        from ballrace.analytic.isocase import render as _render_iso

        _render_iso(r["iso"], con)


def _um(x: float) -> str:
    return "-" if x is None or not np.isfinite(x) else f"{x * 1e6:.4f}"


def _clean(obj):
    """JSON-safe copy: NaN / inf become null."""
    if isinstance(obj, dict):
        return {k: _clean(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_clean(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def register(app) -> None:
    """Add the ``bearing`` command to a Typer app."""

    @app.command("bearing")
    def bearing(
        case_file: Annotated[str, typer.Argument(help="TOML case file (see ballrace.analytic.casefile).")],
        as_json: Annotated[bool, typer.Option("--json", help="Machine-readable JSON (SI units).")] = False,
    ):
        """Load distribution, Hertz contacts, ratings, life and EHL film of a bearing case."""
        from ballrace.analytic.casefile import CaseFileError, load_case

        try:
            case = load_case(case_file)
            result = analyze(case)
        except CaseFileError as exc:
            typer.echo(f"error: {exc}", err=True)
            raise typer.Exit(code=2)
        except (ValueError, RuntimeError) as exc:
            typer.echo(f"error: {case_file}: {exc}", err=True)
            raise typer.Exit(code=2)
        if as_json:
            typer.echo(json.dumps(_clean(result), indent=2))
            return
        _render(result)
