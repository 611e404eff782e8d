"""``ballrace fem``: run an FE check of a Hertz contact from a case file or flags.

``ballrace fem CASE.toml`` or ``ballrace fem --case inner --load "4450 N"`` meshes,
assembles and solves with a progress display, prints the FE-versus-analytic table,
writes ``result.json`` and PNG renders to ``--out``.  ``ballrace fem convergence``
runs a mesh-convergence study instead.  A case file (units parsed with pint)::

    [case]
    kind = "race"            # race | plane | ball
    race = "inner"
    load = "4450 N"
    contact_angle = "0 deg"
    [bearing]                # for kind = "race": the 209 bearing
    ball_diameter = "12.7 mm"
    n_balls = 9
    pitch_diameter = "65 mm"
    f_inner = 0.52
    f_outer = 0.52
    free_contact_angle = "0 deg"
    [fem]
    level = "standard"       # quick | standard | fine
    mode = "half-space"      # half-space | two-body
    gap = "hertz"            # hertz | exact
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Optional

import typer

__all__ = ["register"]

_BEARING_209 = {"ball_diameter": "12.7 mm", "n_balls": 9, "pitch_diameter": "65 mm",
                "f_inner": 0.52, "f_outer": 0.52, "free_contact_angle": "0 deg"}


def _case_from(spec: dict):
    import ballrace
    from ballrace.units import parse_quantity as q

    from . import api

    c = spec.get("case", {})
    kind = c.get("kind", "race")
    load = q(c.get("load", "4450 N"), "[force]", "load")
    if kind == "race":
        b = {**_BEARING_209, **spec.get("bearing", {})}
        brg = ballrace.BallBearing(
            q(b["ball_diameter"], "[length]", "ball_diameter"), int(b["n_balls"]),
            q(b["pitch_diameter"], "[length]", "pitch_diameter"), float(b["f_inner"]),
            float(b["f_outer"]),
            free_contact_angle=q(b.get("free_contact_angle", "0 deg"), "[angle]",
                                 "free_contact_angle"))
        return api.race_case(brg, load, c.get("race", "inner"),
                             q(c.get("contact_angle", "0 deg"), "[angle]", "contact_angle"))
    D = q(c.get("ball_diameter", "12.7 mm"), "[length]", "ball_diameter")
    if kind == "plane":
        return api.plane_case(D, load)
    if kind == "ball":
        return api.ball_case(D, load)
    raise ValueError(f"case.kind must be 'race', 'plane' or 'ball'; got {kind!r}")


def _table(r) -> None:
    from rich.console import Console
    from rich.table import Table

    scale = {"m": (1e3, "mm"), "Pa": (1e-6, "MPa")}
    t = Table(title=f"{r.case.name}, Q = {r.case.load:g} N — {r.mode}, {r.gap} gap, {r.level} "
                    f"({r.n_dofs:,} DOFs, {r.timings['total']:.1f} s, {r.solver})")
    for col in ("quantity", "FE", "analytic", "unit", "error", "tolerance", ""):
        t.add_column(col, justify="right" if col not in ("quantity", "unit") else "left")
    for row in r.comparison:
        f, u = scale.get(row["unit"], (1.0, row["unit"]))
        tol = "—" if row["tol"] is None else f"{100 * row['tol']:.1f} %"
        mark = "" if row["tol"] is None else ("[green]ok" if row["ok"] else "[red]FAIL")
        t.add_row(row["quantity"], f"{row['fe'] * f:.5g}", f"{row['analytic'] * f:.5g}", u,
                  f"{100 * row['error']:+.2f} %", tol, mark)
    Console().print(t)
    if r.gap == "exact":
        Console().print("exact sphere–torus gap: differences from Hertz are 'beyond Hertz' "
                        "results, not errors (no tolerances applied).")


def register(app: typer.Typer) -> None:
    """Add the ``fem`` command to the root ``ballrace`` app."""

    @app.command("fem")
    def fem_cmd(
        case_file: Annotated[Optional[str], typer.Argument(
            help="CASE.toml, or the word 'convergence' for a mesh-convergence study.")] = None,
        case: Annotated[str, typer.Option(
            help="race | plane | ball, or inner | outer for a race case (without a case "
                 "file)")] = "race",
        race: Annotated[str, typer.Option(help="inner | outer")] = "inner",
        load: Annotated[str, typer.Option(help='Ball load, e.g. "4450 N".')] = "4450 N",
        level: Annotated[str, typer.Option(help="quick | standard | fine")] = "standard",
        mode: Annotated[str, typer.Option(help="half-space | two-body")] = "half-space",
        gap: Annotated[str, typer.Option(help="hertz | exact")] = "hertz",
        out: Annotated[Path, typer.Option(help="Output folder (result.json, PNGs).")] = Path("fem-out"),
        render: Annotated[bool, typer.Option(help="Write PNG renders.")] = True,
        sizes: Annotated[str, typer.Option(help="Convergence: elements per minor semi-axis.")] = "4,6,8,11",
        solver: Annotated[Optional[str], typer.Option(help="Force a sparse solver.")] = None,
    ):
        """FE check of a Hertz ball contact (mesh, assemble, solve, compare, render)."""
        from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

        from . import api

        try:
            if case_file and case_file != "convergence":
                import tomllib

                spec = tomllib.loads(Path(case_file).read_text())
                f = spec.get("fem", {})
                level_, mode_, gap_ = f.get("level", level), f.get("mode", mode), f.get("gap", gap)
            else:
                if case in ("inner", "outer"):          # shorthand: --case inner
                    case, race = "race", case
                spec = {"case": {"kind": case, "race": race, "load": load}}
                level_, mode_, gap_ = level, mode, gap
            cse = _case_from(spec)
        except (ValueError, TypeError, OSError) as exc:
            typer.echo(f"error: {exc}", err=True)
            raise typer.Exit(code=2)
        out.mkdir(parents=True, exist_ok=True)
        cols = (SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn())
        if case_file == "convergence":
            from .convergence import QUANTITIES, convergence_study

            with Progress(*cols, transient=True) as prog:
                task = prog.add_task("convergence", total=None)
                st = convergence_study(cse, tuple(int(s) for s in sizes.split(",")), mode=mode_,
                                       gap=gap_, solver=solver,
                                       progress=lambda s: prog.update(task, description=s))
            from rich.console import Console
            from rich.table import Table

            t = Table(title=f"mesh convergence: {cse.name}, {mode_} (errors vs analytic; "
                            "rate = slope of log|error| vs log DOFs, x3 for h)")
            for col in ("n/minor", "DOFs", "s", *QUANTITIES):
                t.add_column(col, justify="right")
            for row in st.rows():
                t.add_row(str(row[0]), f"{row[1]:,}", f"{row[2]:.1f}",
                          *[f"{100 * e:+.2f} %" for e in row[3:]])
            t.add_row("rate", "per DOF", "", *[f"{st.rates[q]:.2f}" for q in QUANTITIES])
            Console(width=max(Console().width, 140)).print(t)
            (out / "convergence.json").write_text(json.dumps(
                {"n": st.n, "dofs": st.dofs, "seconds": st.seconds, "errors": st.errors,
                 "rates": st.rates}, indent=2))
            return
        with Progress(*cols, transient=True) as prog:
            task = prog.add_task("starting", total=None)
            r = api.run_case(cse, level=level_, mode=mode_, gap=gap_, solver=solver,
                             progress=lambda s: prog.update(task, description=s))
        _table(r)
        (out / "result.json").write_text(json.dumps(r.to_dict(), indent=2))
        if render:
            from .render import render as _render

            for field in ("von_mises", "tau_xz", "max_shear", "pressure"):
                _render(r, field=field, path=str(out / f"{field}.png"))
        typer.echo(f"wrote {out / 'result.json'}" + (" and renders" if render else ""))
        if not r.passed:
            raise typer.Exit(code=1)
