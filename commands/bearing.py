"""``ballrace bearing CASE.toml``: load distribution, contacts, ratings, life and film.

Registered on the main Typer app by :func:`register` (see :mod:`ballrace.cli`).  The
case file format is documented in :mod:`ballrace.casefiles.bearing`.  Which solver runs
and which notes apply is decided by :func:`ballrace.casefiles.analysis.analyze`;
:func:`analyze` returns its plain SI numbers (what ``--json`` prints) and the command only
renders them.
"""
from __future__ import annotations

import json
import logging
import math
from pathlib import Path
from typing import Annotated, Optional

import typer

from ballrace.casefiles.analysis import FIT_MARK
from ballrace.casefiles.schema import ROLLER_TYPES
from ballrace.console import UNITS_HELP

__all__ = ["register", "analyze", "sections", "ball_columns", "roller_sections",
           "roller_columns", "plot_rollers"]

log = logging.getLogger(__name__)

def analyze(case) -> dict:
    """Run a validated :class:`~ballrace.casefiles.bearing.BearingCase`
    (:func:`ballrace.casefiles.analysis.analyze`).

    Returns
    -------
    dict
        ``{"title", "units", "bearing", "ratings", "distribution", "life", "film", "iso",
        "notes"}`` with SI values (lists per ball in ``distribution``).
    """
    from ballrace.casefiles import analysis

    return analysis.analyze(case).to_dict()


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


def _print_report(secs, title: str, columns, notes, units: str) -> None:
    """Print the first section, the per-element table ``columns`` (headers, rows) under
    ``title``, the other sections and the notes."""
    from ballrace.console import literal, make_console, print_columns, print_sections

    con = make_console()
    print_sections(con, secs[:1], units)
    print_columns(con, title, *columns)
    print_sections(con, secs[1:], units)
    for n in notes:
        con.print(literal(f"note: {n}"), style="dim")


def _render(r: dict, units: str = "eng") -> None:
    _print_report(sections(r), f"Load distribution: {r['distribution']['method']}",
                  ball_columns(r, units),
                  [*r["notes"], *(r.get("iso") or {}).get("notes", [])], units)


# ============================================================================ roller bearings
def roller_sections(r: dict) -> list:
    """The summary blocks of a roller-bearing analysis (``--json``'s dict), as
    ``(title, rows)`` pairs for :func:`ballrace.console.print_sections`."""
    b, rt, lf, d = r["bearing"], r["ratings"], r["life"], r["distribution"]
    tapered = b["kind"] == "tapered-roller"
    profile = b["profile"]
    geo = [("type", b["kind"], None),
           ("roller diameter D_we", b["roller_diameter"], "length"),
           ("effective length L_we", b["roller_length"], "length"),
           ("rollers Z", b["n_rollers"], None),
           ("pitch diameter d_m", b["pitch_diameter"], "length")]
    if tapered:
        geo += [("cup angle alpha_o", b["contact_angle"], "angle"),
                ("cone angle alpha_i", b["cone_angle"], "angle")]
    geo += [("diametral clearance P_d", b["diametral_clearance"], "small"),
            ("profile / slices", f"{profile} / {b['n_slices']}", None),
            ("E'", b["E_prime"], "modulus"),
            ("radial load Fr", b["radial_load"], "force"),
            ("axial load Fa", b["axial_load"], "force")]
    if b.get("misalignment"):
        geo.append(("misalignment (held)", b["misalignment"], "angle"))
    geo += [(f"speed ({b['rotating_ring']} ring)", b["speed_rpm"], "=rpm"),
            (f"C_r ({rt['standard']})", rt["C"], "force"),
            ("C_0r (ISO 76)", rt["C0"], "force")]
    out = [(r["title"] or "roller bearing", geo)]
    dist = [("largest roller load Q_max", d["max_roller_load"], "force"),
            ("largest slice pressure p_max", d["max_pressure"], "stress"),
            ("rollers edge-loaded", f"{sum(d['edge_loaded'])} of {len(d['edge_loaded'])}",
             None),
            ("radial deflection", math.hypot(d["displacements"][1], d["displacements"][2]),
             "small")]
    if tapered:
        dist.append(("axial deflection", d["displacements"][0], "small"))
    out.append(("Load distribution", dist))
    h = d.get("half_space")
    if h:
        where = f"roller {h['roller'] + 1}, {h['raceway']}"
        out.append((f"Half-space line contact ({where})", [
            ("roller load Q", h["load"], "force"),
            ("peak pressure along the roller", h["peak_pressure"], "stress"),
            ("  at x (from the roller centre)", h["peak_pressure_x"], "length"),
            ("von Mises max below it", h["von_mises_max"], "stress"),
            ("  at depth / x", f"{h['von_mises_depth'] * 1e6:.4g} µm / "
             f"{h['von_mises_x'] * 1e3:.4g} mm", None),
            ("Tresca max (sigma1 - sigma3)/2", h["tresca_max"], "stress"),
            ("  at depth / x", f"{h['tresca_depth'] * 1e6:.4g} µm / "
             f"{h['tresca_x'] * 1e3:.4g} mm", None)]))
    rows = []
    if tapered:
        rows.append(("X / Y / e", f"{lf['X']:.3g} / {lf['Y']:.3g} / {lf['e']:.3g}", None))
    rows += [("equivalent load P" + (" = X Fr + Y Fa" if tapered else " = Fr"), lf["P"],
              "force"),
             (f"L10 = (C/P)^(10/3) ({lf['standard']})", lf["L10"], "=1e6 rev"),
             ("L10h", lf["L10h"], "=h"),
             ("static equivalent load P0", lf["P0"], "force"),
             ("static safety s0 = C0/P0 (ISO 76)", lf["s0"], None),
             ("s0 = (4000 MPa / p_max)^2, slices", lf["static_safety"], None),
             ("reference life L10r (ISO/TS 16281)", lf["L10r"], "=1e6 rev"),
             ("reference life L10rh", lf["L10r_h"], "=h"),
             ("equivalent reference load P_ref", lf["P_ref"], "force"),
             ("fatigue load limit C_u", lf["C_u"], "force")]
    if "kappa" in lf:
        rows.append(("viscosity ratio kappa", lf["kappa"], None))
    if lf.get("contamination") is not None:
        rows.append(("contamination factor e_C", lf["contamination"], None))
    rows.append((f"reliability {lf['reliability'] * 100:g} %: a1", lf["a1"], None))
    if "a_ISO" in lf:
        rows += [("a_ISO (e_C C_u / P)", lf["a_ISO"], None),
                 ("modified rating life L_nm", lf["L_nm"], "=1e6 rev"),
                 ("L_nmh", lf["L_nm_h"], "=h"),
                 ("a_ISO (e_C C_u / P_ref)", lf["a_ISO_ref"], None),
                 ("modified reference life L10mr", lf["L10mr"], "=1e6 rev"),
                 ("L10mrh", lf["L10mr_h"], "=h")]
    out.append(("Ratings and life", rows))
    return out


def roller_columns(r: dict, units: str = "eng") -> tuple[list, list]:
    """Headers (each with its unit) and rows of the per-roller table in ``units``: azimuth,
    cup load Q (tapered: the rib load, and the cone load where it differs from Q), the
    largest slice pressure of either raceway, the roller's tilt against the raceways and
    the edge flag (an end slice loaded)."""
    from ballrace.console import convert as cv
    from ballrace.console import fmt
    from ballrace.console import unit_label as ul

    d = r["distribution"]
    tapered = r["bearing"]["kind"] == "tapered-roller"
    F, A = ul("force", units), ul("angle", units)
    # the cone load differs from the cup load only with a rib angle of its own
    cone = tapered and any(abs(qi - qo) > 1e-12 * max(qo, 1.0)
                           for qi, qo in zip(d["inner_load"], d["roller_load"]))
    headers = ["roller", f"psi [{A}]", f"Q [{F}]"]
    if cone:
        headers.append(f"Q_cone [{F}]")
    if tapered:
        headers.append(f"Q_rib [{F}]")
    headers += [f"p_max [{ul('stress', units)}]", f"tilt [{A}]", "edge"]

    def g(x, kind, digits=5):
        return fmt(cv(x, kind, units), digits)

    rows = []
    for j in range(len(d["roller_load"])):
        row = [str(j + 1), g(d["azimuth"][j], "angle", 4), g(d["roller_load"][j], "force")]
        if cone:
            row.append(g(d["inner_load"][j], "force"))
        if tapered:
            row.append(g(d["rib_load"][j], "force"))
        row += [g(d["max_slice_pressure"][j], "stress", 4),
                g(d["roller_tilt"][j], "angle", 3),
                "yes" if d["edge_loaded"][j] else "-"]
        rows.append(row)
    return headers, rows


def _render_roller(r: dict, units: str = "eng") -> None:
    _print_report(roller_sections(r), f"Rollers: {r['distribution']['method']}",
                  roller_columns(r, units), r["notes"], units)


def plot_rollers(r: dict, path, most: int = 3) -> None:
    """Picture of a roller-bearing analysis: the slice pressure of every roller (rollers x
    slices, a heat map; the larger of the two raceways) and, beside it, the pressure along
    the ``most`` most loaded rollers; written to ``path`` (PNG, SVG, PDF)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    d = r["distribution"]
    p = np.maximum(np.array(d["slice_pressure_inner"]), np.array(d["slice_pressure_outer"]))
    x = np.array(d["slice_position"]) * 1e3
    Z, ns = p.shape
    half = 0.5 * r["bearing"]["roller_length"] * 1e3
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(10, 4.2),
                                   gridspec_kw={"width_ratios": [1.1, 1]})
    im = ax0.imshow(p / 1e6, aspect="auto", origin="lower", cmap="viridis",
                    extent=(-half, half, 0.5, Z + 0.5), interpolation="nearest")
    ax0.set_xlabel("x along the roller [mm]")
    ax0.set_ylabel("roller")
    ax0.set_title("slice pressure [MPa] (larger raceway)", fontsize=9)
    fig.colorbar(im, ax=ax0)
    order = np.argsort(d["roller_load"])[::-1][:most]
    for j in order:
        if d["roller_load"][j] <= 0:
            continue
        ax1.plot(x, p[j] / 1e6, "o-", ms=3,
                 label=f"roller {j + 1}, Q = {d['roller_load'][j]:.4g} N"
                 + (" (edge)" if d["edge_loaded"][j] else ""))
    ax1.set_xlim(-half, half)
    ax1.set_xlabel("x along the roller [mm]")
    ax1.set_ylabel("slice pressure [MPa]")
    ax1.set_title(f"the {most} most loaded rollers (lamina model, {ns} slices)", fontsize=9)
    ax1.legend(fontsize=8)
    ax1.grid(alpha=0.3)
    fig.suptitle(r["title"] or "roller bearing", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


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
        plot_file: Annotated[Optional[str], typer.Option(
            "--plot", help="Roller bearings: write a picture of the slice pressures "
                           "(PNG/SVG/PDF) to this file.")] = None,
    ):
        """Load distribution, Hertz contacts, ratings, life and EHL film of a bearing case."""
        from ballrace.casefiles.bearing import load_case
        from ballrace.commands import run_case_file

        result = run_case_file(case_file, units, "bearing", load_case, analyze,
                               lambda exc: _kind_hint(Path(case_file)) or str(exc))
        roller = result["bearing"]["kind"] in ROLLER_TYPES
        if plot_file:
            from ballrace.cli import fail

            if not roller:
                fail("--plot draws the slice pressures of a roller bearing; a ball-bearing "
                     "case has no picture (drop --plot)")
            try:
                plot_rollers(result, plot_file)
            except ImportError:
                fail("--plot needs matplotlib (pip install matplotlib)")
            except (OSError, ValueError) as exc:
                fail(f"--plot {plot_file}: {exc}")
            if not as_json:
                typer.echo(f"picture: {plot_file}")
        if as_json:
            typer.echo(json.dumps(jsonable(result), indent=2))
            return
        if roller:
            _render_roller(result, units)
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
