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
from typing import Annotated

import typer

from ballrace.casefiles.analysis import FIT_MARK
from ballrace.console import UNITS_HELP

__all__ = ["register", "analyze", "sections", "ball_columns"]

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
        from ballrace.casefiles.bearing import load_case
        from ballrace.commands import run_case_file

        result = run_case_file(case_file, units, "bearing", load_case, analyze,
                               lambda exc: _kind_hint(Path(case_file)) or str(exc))
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
