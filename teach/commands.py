"""``ballrace teach``: the teaching commands, registered on the root typer app.

* ``teach subsurface`` — the stress fields under a contact as a PNG
  (:mod:`ballrace.teach.figures`);
* ``teach roller`` — the pressure along a profiled roller and the stresses below its
  centre and its end (:func:`ballrace.teach.compute.compute_roller`);
* ``teach serve`` — the subsurface-stress explorer in the browser
  (:mod:`ballrace.teach.server`);
* ``teach export`` — the explorer as one self-contained HTML file
  (:mod:`ballrace.teach.page`).

Units are parsed here; heavy imports (matplotlib, rich's progress bar) happen inside the
commands.
"""
from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Annotated

import typer

from ballrace.console import UNITS_HELP, literal

from .compute import DEFAULTS, EXPORT_GRID, InputError, case_inputs, compute_safe, one_line
from .page import export_html
from .server import make_server

__all__ = ["teach_app", "TEACH_OUT", "SMALL_GRID", "register_commands", "register"]

teach_app = typer.Typer(add_completion=False, no_args_is_help=True, rich_markup_mode=None,
                        help="Teaching figures drawn from the library.")

#: Where ``teach`` writes its figures unless ``--out`` says otherwise (ballrace-out/ holds a
#: .gitignore of its own, so git ignores it wherever it is).
TEACH_OUT = Path("ballrace-out") / "teach"


def _usage(msg: str) -> None:
    """One-line error on stderr (printed literally), exit code 2."""
    typer.echo(f"error: {msg}", err=True)
    raise typer.Exit(code=2)


@teach_app.command("subsurface")
def teach_subsurface(
    load: Annotated[str, typer.Option(help='Normal load ("1000 N").')] = "2000 N",
    rx1: Annotated[str, typer.Option(help="Body 1 radius in x (rolling).")] = "6.35 mm",
    ry1: Annotated[str, typer.Option(help="Body 1 radius in y.")] = "6.35 mm",
    rx2: Annotated[str, typer.Option(help='Body 2 radius in x ("inf" flat, < 0 concave).')] = "inf",
    ry2: Annotated[str, typer.Option(help="Body 2 radius in y.")] = "inf",
    e1: Annotated[str, typer.Option("--E1", help="Young's modulus (both bodies).")] = "200 GPa",
    nu1: Annotated[float, typer.Option("--nu1", help="Poisson's ratio (both bodies).")] = 0.3,
    out: Annotated[Path, typer.Option("--out", help="PNG to write (its folder is created).")]
        = TEACH_OUT / "subsurface.png",
    traction: Annotated[float, typer.Option(
        help="Traction coefficient q/p along +x: draw the contact with and without it.")] = 0.0,
    units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
):
    """Draw max shear, von Mises and orthogonal shear under a contact, depths marked."""
    from rich.console import Console

    from ballrace.units import parse_quantity

    from . import figures

    console = Console()
    if units not in ("eng", "si", "us"):
        _usage(f"--units must be one of eng, si, us; got {units!r}")
    if out.is_dir():                      # --out FOLDER: the figure goes inside it
        out = out / "subsurface.png"
    elif not out.suffix:                  # matplotlib would add ".png" behind our back
        out = out.with_suffix(".png")
    try:
        q = parse_quantity(load, "[force]", "load")
        radii = [parse_quantity(v, "[length]", n, allow_inf=True)
                 for n, v in (("rx1", rx1), ("ry1", ry1), ("rx2", rx2), ("ry2", ry2))]
        e = parse_quantity(e1, "[pressure]", "E1")
    except ValueError as exc:
        _usage(str(exc))
    from ballrace.units import plausible

    for (n, v), r in zip((("--rx1", rx1), ("--ry1", ry1), ("--rx2", rx2), ("--ry2", ry2)), radii):
        plausible(r, v, n, "radius")                # "6.35 m" for "6.35 mm": a warning
    plausible(e, e1, "--E1", "modulus")             # "200 MPa" for "200 GPa": a warning
    from ballrace.console import output_folder
    from ballrace.validation.cli import missing_modules

    if missing_modules("matplotlib"):
        _usage('teach draws with matplotlib: pip install "ballrace[report]"')
    try:
        output_folder(out.parent)
    except ValueError as exc:
        _usage(str(exc))
    try:
        if traction:
            info = figures.traction_figure(q, *radii, E=e, nu=nu1, traction=traction,
                                           path=out, units=units)
        else:
            info = figures.subsurface_figure(q, *radii, E=e, nu=nu1, path=out, units=units)
    except ImportError as exc:
        typer.echo(f"error: the subsurface module is not available ({exc})", err=True)
        raise typer.Exit(code=1)
    except (ValueError, TypeError, OSError) as exc:
        _usage(str(exc))
    from ballrace.console import print_sections

    console.print(literal(f"wrote {out}"))
    print_sections(console, [("Marked on the figure", _teach_rows(info))], units)


#: ``teach roller``'s options: the explorer's input -> the option that sets it.
_ROLLER_OPTIONS = {"load": "--load", "profile": "--profile", "flat": "--flat",
                   "crown": "--crown", "tilt": "--tilt", "r_roller": "--roller-radius",
                   "length": "--length", "r_race": "--raceway-radius", "E": "--E",
                   "nu": "--nu"}


@teach_app.command("roller")
def teach_roller(
    load: Annotated[str, typer.Option(help='Normal load on the roller ("5 kN").')]
        = DEFAULTS["load"],
    profile: Annotated[str, typer.Option(
        help="Roller profile: straight | iso | lundberg | johns-gohar | crowned (with "
             "--flat and --crown).")] = DEFAULTS["profile"],
    flat: Annotated[str, typer.Option(help="crowned: length of the straight middle.")]
        = DEFAULTS["flat"],
    crown: Annotated[str, typer.Option(help="crowned: radius of the crown arcs.")]
        = DEFAULTS["crown"],
    tilt: Annotated[str, typer.Option(
        help='Tilt about the rolling direction ("1 mrad"; > 0: the +x end goes in; '
             "at most 10 mrad).")] = DEFAULTS["tilt"],
    roller_radius: Annotated[str, typer.Option("--roller-radius", help="Roller radius R1.")]
        = DEFAULTS["r_roller"],
    length: Annotated[str, typer.Option(help="Effective roller length L.")]
        = DEFAULTS["length"],
    raceway_radius: Annotated[str, typer.Option(
        "--raceway-radius", help='Raceway radius R2 ("inf" flat, < 0 concave).')]
        = DEFAULTS["r_race"],
    e: Annotated[str, typer.Option("--E", help="Young's modulus (both bodies).")]
        = DEFAULTS["E"],
    nu: Annotated[str, typer.Option("--nu", help="Poisson's ratio (both bodies).")]
        = DEFAULTS["nu"],
    units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
    json_out: Annotated[bool, typer.Option("--json", help="Print the numbers as JSON (SI).")]
        = False,
):
    """Pressure along a profiled roller and the stresses below its centre and its end.

    The finite line contact of the roller on the raceway (half-space, 41 slices) and the
    von Mises and Tresca maxima over depth below it, as the explorer's roller mode.
    """
    import json

    from ballrace.console import make_console, print_sections

    from .compute import compute_roller

    if units not in ("eng", "si", "us"):
        _usage(f"--units must be one of eng, si, us; got {units!r}")
    params = {"mode": "roller", "load": load, "profile": profile, "flat": flat,
              "crown": crown, "tilt": tilt, "r_roller": roller_radius, "length": length,
              "r_race": raceway_radius, "E": e, "nu": nu}
    try:
        r = compute_roller(params)
    except InputError as exc:
        _usage(f"{_ROLLER_OPTIONS.get(exc.field, '--' + exc.field)}: {one_line(exc)}")
    t = r["table"]
    if json_out:
        typer.echo(json.dumps({"inputs": params, "result": t, "note": r["note"]}, indent=2))
        return
    if r["note"]:
        typer.echo(f"warning: {r['note']}", err=True)
    console = make_console()
    name = profile.strip().lower()
    title = f"{name} roller on a raceway, tilt {t['tilt'] * 1e3:.4g} mrad"
    print_sections(console, [
        (title, [("load Q", t["load"], "force"), ("length L", t["length"], "length"),
                 ("reduced radius R", t["R"], "length"),
                 ("2-D Hertz p0 at Q/L", t["p_hertz"], "stress"),
                 ("pressure at the centre", t["p_centre"], "stress"),
                 ("pressure at the contact's end", t["p_edge"], "stress"),
                 ("  its x", t["x_edge"], "length"),
                 ("largest pressure", t["p_max"], "stress"),
                 ("length in contact", t["contact_length"], "length"),
                 ("approach", t["approach"], "small"),
                 ("load to reach the roller ends", t["edge_load"], "force")]),
        ("Stresses below the roller (maxima over depth)", [
            (f"{label}, {where}{suffix}", t[f"{key}_{w}{part}"], kind)
            for key, label in (("vm", "von Mises"), ("tr", "Tresca"))
            for w, where in (("centre", "centre"), ("edge", "end"), ("maximum", "overall"))
            for part, suffix, kind in (("", "", "stress"), ("_x", ": x", "length"),
                                       ("_depth", ": depth", "length"))
            if not (part == "_x" and w == "centre")]),
    ], units)


def _teach_rows(info: dict) -> list:
    """``teach``'s numbers as table rows in display units: a key ending in [Pa] is a stress,
    [m] a length, [-] a number; a tuple (value / p0, position / b) is printed as such."""
    rows = []
    for key, v in info.items():
        kind = {"[Pa]": "stress", "[m]": "length", "[-]": None}.get(key.rsplit(" ", 1)[-1], "")
        name = key.rsplit(" [", 1)[0] if kind != "" else key
        if isinstance(v, tuple):
            rows.append((name, ", ".join(f"{x:.4g}" for x in v), None))
        else:
            rows.append((name, float(v), kind or None))
    return rows


def register_commands(teach_app) -> None:
    """Add ``serve`` and ``export`` to the ``ballrace teach`` typer group."""
    @teach_app.command("serve")
    def teach_serve(
        port: Annotated[int, typer.Option(
            "--port", help="Port on 127.0.0.1 (default 0: a free one, printed).")] = 0,
        case: Annotated[Path | None, typer.Option(
            "--case", help="Start with the ball in a groove of this bearing case file.")] = None,
        race: Annotated[str, typer.Option(
            "--race", help="With --case: inner | outer.")] = "inner",
    ):
        """Serve the interactive subsurface-stress explorer on 127.0.0.1 (Ctrl-C stops it)."""
        if not 0 <= port <= 65535:
            typer.echo(f"error: --port must be in [0, 65535]; got {port}", err=True)
            raise typer.Exit(code=2)
        initial = {}
        if race not in ("inner", "outer"):
            typer.echo(f"error: --race must be inner or outer; got {race!r}", err=True)
            raise typer.Exit(code=2)
        try:
            if case is not None:
                try:
                    initial = case_inputs(str(case), race)
                except InputError as exc:
                    typer.echo(f"error: --case {exc}", err=True)
                    raise typer.Exit(code=2) from None
                initial["case"] = str(case)
                initial.pop("title", None)
            first = compute_safe({**DEFAULTS, **initial})   # imports and the first state
            if not first["ok"]:
                typer.echo(f"error: {first['error']}", err=True)
                raise typer.Exit(code=2)
            try:
                server = make_server(port, initial=initial,
                                     cases=() if case is None else (case,))
            except OSError as exc:
                typer.echo(f"error: cannot listen on 127.0.0.1:{port} ({one_line(exc)})",
                           err=True)
                raise typer.Exit(code=2) from None
            host, port = server.server_address[:2]
            import signal

            def _stop(signum, frame):           # a SIGTERM stops it as Ctrl-C does
                raise KeyboardInterrupt

            signal.signal(signal.SIGTERM, _stop)
            typer.echo(f"ballrace explorer: http://{host}:{port}/  (Ctrl-C stops it)")
            try:
                server.serve_forever(poll_interval=0.2)
            finally:
                server.server_close()
        except KeyboardInterrupt:
            pass
        typer.echo("ballrace explorer: stopped")

    @teach_app.command("export")
    def teach_export(
        out: Annotated[Path, typer.Argument(
            help="HTML file to write (default ballrace-out/teach/explorer.html).")]
            = Path("ballrace-out") / "teach" / "explorer.html",
        small: Annotated[bool, typer.Option(
            "--small", help="A 2 x 3 x 1 x 2 grid (ratio, load, nu, traction), for a quick look.")]
            = False,
    ):
        """Write the explorer as one self-contained HTML file (a precomputed grid, sliders)."""
        from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn,
                                   TimeElapsedColumn)

        from ballrace.console import make_console, output_folder

        if out.is_dir():
            out = out / "explorer.html"
        elif not out.suffix:
            out = out.with_suffix(".html")
        try:
            output_folder(out.parent, "OUT")
        except ValueError as exc:
            typer.echo(f"error: {one_line(exc)}", err=True)
            raise typer.Exit(code=2) from None
        grid = {k: tuple((SMALL_GRID if small else EXPORT_GRID)[k]) for k in EXPORT_GRID}
        n = math.prod(len(v) for v in grid.values())
        shapes = n // len(grid["load"])
        err = make_console(stderr=True)
        typer.echo(f"ballrace explorer: computing {n} grid points ({shapes} shapes) for "
                   f"{out} ...", err=True)
        try:
            if err.is_terminal:      # a bar on the terminal, else a line every tenth
                with Progress(TextColumn("{task.description}"), BarColumn(),
                              MofNCompleteColumn(), TimeElapsedColumn(), console=err,
                              transient=True) as prog:
                    task = prog.add_task("starting", total=n)
                    path = export_html(out, grid, lambda i, n, text: prog.update(
                        task, completed=i, total=n, description=text))
            else:
                path = export_html(out, grid, _ProgressLines(n))
        except KeyboardInterrupt:
            typer.echo("ballrace explorer: export interrupted, nothing written", err=True)
            raise typer.Exit(code=130) from None
        except (OSError, ValueError) as exc:
            typer.echo(f"error: {one_line(exc)}", err=True)
            raise typer.Exit(code=2) from None
        size = path.stat().st_size
        typer.echo(f"wrote {path} ({size / 1e6:.2f} MB)")


class _ProgressLines:
    """``teach export``'s progress when stderr is not a terminal: a line per tenth of the
    grid (and the last step), with the time so far."""

    def __init__(self, total: int):
        self.total, self.shown, self.t0 = total, -1, time.perf_counter()

    def __call__(self, done: int, total: int, text: str) -> None:
        tenth = 10 * done // max(total, 1)
        if tenth > self.shown or done >= total:
            self.shown = tenth
            typer.echo(f"  {done}/{total} grid points, {text} "
                       f"({time.perf_counter() - self.t0:.0f} s)", err=True)


#: The ``--small`` export grid.
SMALL_GRID = {"ratio": (1.0, 8.0), "load": (500.0, 2000.0, 8000.0), "nu": (0.3,),
              "mu": (0.0, 0.3)}


register_commands(teach_app)


def register(app: typer.Typer) -> None:
    """Add the ``teach`` group to the root app."""
    app.add_typer(teach_app, name="teach")
