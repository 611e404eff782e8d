"""``ballrace validate``: registered on the root typer app (``ballrace teach`` is
:mod:`ballrace.teach.commands`).

The library logs; this module prints (rich).  Heavy imports happen inside the commands.
"""
from __future__ import annotations

import logging
import textwrap
from pathlib import Path
from typing import Annotated, Optional

import typer

from ballrace.console import literal

__all__ = ["register"]

log = logging.getLogger(__name__)

_STYLE = {"pass": "green", "fail": "bold red", "error": "bold magenta", "missing": "bold yellow",
          "skipped": "dim"}
_MARK = {"pass": "PASS", "fail": "FAIL", "error": "ERROR", "missing": "MISSING",
         "skipped": "SKIP"}

def validate(
    cases: Annotated[Optional[list[str]], typer.Option(
        "--cases", help="Glob of case files (default: all packaged cases); a relative pattern "
                        "such as 'hertz*' is also tried in the packaged case folder.  Give "
                        "it again for more (--cases roller --cases 'fem_roller*').")] = None,
    fem: Annotated[str, typer.Option(
        "--fem", help="FE level: quick | standard | none (none reports FE cases as skipped "
                      "by request).")] = "quick",
    scheduler: Annotated[Optional[str], typer.Option(
        "--scheduler", help="dask scheduler address (tcp://host:8786); default: a LocalCluster "
                            "for FE and sweep cases.")] = None,
    workers: Annotated[Optional[int], typer.Option(
        "--workers", help="LocalCluster worker processes (default: one in-process worker, 2 threads).")] = None,
    serial: Annotated[bool, typer.Option(
        "--serial", help="Run everything in this process, without dask.")] = False,
    report: Annotated[Optional[Path], typer.Option(
        "--report", help="Write index.html and results.json to this folder.")] = None,
    baseline: Annotated[Optional[Path], typer.Option(
        "--baseline", help="Compare with this stored results/baseline file.")] = None,
    update_baseline: Annotated[bool, typer.Option(
        "--update-baseline", help="Write the --baseline file from this run.")] = False,
    no_plots: Annotated[bool, typer.Option(
        "--no-plots", help="Report without plots (faster).")] = False,
):
    """Run the reference cases, print a summary, optionally write the report and baseline.

    Exits 1 when any case fails, errors or is missing (or a baseline value moved), 2 on
    bad options or case files.
    """
    from rich.console import Console

    from .runner import FEM_LEVELS
    from .schema import CaseFileError, load_cases

    console = Console()
    if fem not in FEM_LEVELS:
        _usage(console, f"--fem must be one of {', '.join(FEM_LEVELS)}; got {fem!r}")
    if update_baseline and baseline is None:
        _usage(console, "--update-baseline needs --baseline FILE (where to write it)")
    if baseline is not None and not update_baseline:
        _check_baseline(console, baseline)
    for pattern in cases or ():
        if Path(pattern).is_dir():
            _usage(console, f"--cases {pattern}: is a directory; give a file or a glob such as "
                            f"'{Path(pattern) / '*.toml'}'")
    if report is not None and report.exists() and not report.is_dir():
        _usage(console, f"--report {report}: exists and is not a folder")
    try:
        selected = load_cases(cases)
    except (CaseFileError, OSError) as exc:
        _usage(console, str(exc))
    serial = _preflight(console, selected, fem=fem, serial=serial, scheduler=scheduler,
                        workers=workers, report=report, plots=not no_plots)
    if logging.getLogger().level > logging.DEBUG:   # dask's INFO chatter drowns the progress
        _quiet_dask()
    code = run_and_report(selected, console=console, fem=fem, scheduler=scheduler,
                          workers=workers, serial=serial, report=report, baseline=baseline,
                          update_baseline=update_baseline, plots=not no_plots)
    raise typer.Exit(code=code)


#: The modules of the fem extra the FE check imports (pip names: gmsh, scikit-fem, meshio)
#: and the line that installs them.
FEM_MODULES = ("gmsh", "skfem", "meshio")
FEM_INSTALL = 'pip install "ballrace[fem]" (in a checkout: pip install ".[fem]")'


def missing_fem() -> list[str]:
    """The pip names of the fem extra's modules that are not installed (checked without
    importing them)."""
    names = {"skfem": "scikit-fem"}
    return [names.get(m, m) for m in missing_modules(*FEM_MODULES)]


def missing_modules(*modules: str) -> list[str]:
    """The modules of ``modules`` that cannot be imported (checked without importing)."""
    import importlib.util

    out = []
    for m in modules:
        try:
            if importlib.util.find_spec(m) is None:
                out.append(m)
        except (ImportError, ValueError):
            out.append(m)
    return out


def _preflight(console, selected, *, fem, serial, scheduler, workers, report, plots) -> bool:
    """Optional dependencies checked before any case runs; returns the serial flag to use.

    FE cases at the requested level without the fem extra (gmsh, scikit-fem, meshio) are a
    one-line error naming the extra and ``--fem none``.  Without dask (``ballrace[report]``)
    the cases run in this process, said in one line; an explicit ``--scheduler``/``--workers``
    without dask, or ``--report`` without jinja2 (or without matplotlib unless
    ``--no-plots``), is a one-line error before any work, as is a ``--report`` folder that
    cannot be written.
    """
    if fem != "none" and any(c.fem and fem in c.fem_levels for c in selected):
        miss = missing_fem()
        if miss:
            _usage(console, f"--fem {fem}: the FE cases need the fem extra ({', '.join(miss)} "
                            f"not installed): {FEM_INSTALL}; or run the analytic cases "
                            "alone with --fem none")
    if not serial and missing_modules("dask", "distributed"):
        if scheduler or workers:
            _usage(console, f"{'--scheduler' if scheduler else '--workers'} needs dask.distributed: "
                            "pip install \"ballrace[report]\" (or run without it)")
        if fem != "none" and any(c.distributed for c in selected):
            console.print(literal("dask is not installed (extra ballrace[report]): "
                                  "cases run one by one"))
        serial = True
    if report is not None:
        need = ["jinja2"] + (["matplotlib"] if plots else [])
        miss = missing_modules(*need)
        if miss:
            _usage(console, f"--report needs {' and '.join(miss)}: pip install "
                            f"\"ballrace[report]\""
                            + (" (or add --no-plots)" if miss == ["matplotlib"] else ""))
        from ballrace.console import output_folder

        try:
            output_folder(report, "--report")
        except ValueError as exc:
            _usage(console, str(exc))
    return serial


def _check_baseline(console, path: Path) -> None:
    """Refuse a missing or unreadable --baseline before any case runs."""
    from . import baseline as bl

    if not path.exists():
        _usage(console, f"--baseline {path}: no such file (write one with --update-baseline)")
    if path.is_dir():
        _usage(console, f"--baseline {path}: is a directory; give a baseline or results.json file")
    try:
        bl.load_baseline(path)
    except UnicodeDecodeError:
        _usage(console, f"--baseline {path}: not a baseline or results JSON (not text)")
    except (OSError, ValueError, AttributeError) as exc:
        _usage(console, f"--baseline {path}: not a baseline or results JSON ({exc})")


def _quiet_dask() -> None:
    try:
        import distributed  # noqa: F401 - configures its loggers on import
    except ImportError:
        return
    for name in list(logging.root.manager.loggerDict):
        if name.split(".")[0] in ("distributed", "dask"):
            logging.getLogger(name).setLevel(logging.WARNING)


def run_and_report(selected, *, console, fem="quick", scheduler=None, workers=None,
                   serial=False, report=None, baseline=None, update_baseline=False,
                   plots=True, client=None) -> int:
    """Run ``selected`` cases with a progress display; returns the exit code."""
    from rich.progress import (BarColumn, MofNCompleteColumn, Progress, SpinnerColumn,
                               TextColumn, TimeElapsedColumn)

    from . import baseline as bl
    from .runner import run_cases

    artifact_dir = None
    if report is not None:
        import tempfile

        report.mkdir(parents=True, exist_ok=True)
        # FE pictures go to a scratch folder: the report embeds them, so none is left beside it
        artifact_dir = Path(tempfile.mkdtemp(prefix="ballrace-fe-pictures-"))
    id_width = min(40, max((len(c.id) for c in selected), default=10))
    head = f"{len(selected)} case(s), --fem {fem}"
    head += (f", scheduler {scheduler}" if scheduler else "") + (", serial" if serial else "")
    console.print("[bold]ballrace validate[/]:", literal(head))
    with Progress(SpinnerColumn(), TextColumn("[progress.description]{task.description}"),
                  BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                  console=console, transient=True) as progress:
        task = progress.add_task("running", total=len(selected))

        def on_start(case):
            progress.update(task, description=f"running {case.id}")

        def on_result(r):
            from rich.text import Text

            line = Text(f"{_MARK[r.status]:>7}", style=_STYLE[r.status])
            line.append(f" {literal(r.id).plain:<{id_width}} {r.duration:8.3f} s")
            if r.message:
                # the note beside the row when it fits, else below it (indented, folded
                # at spaces): a progress line never wraps mid-word
                msg = literal(r.message).plain
                if len(line) + 1 + len(msg) <= progress.console.width - 1:
                    line.append(" " + msg, style="dim")
                else:
                    progress.console.print(line, highlight=False)
                    line = Text(textwrap.indent(textwrap.fill(
                        msg, max(30, progress.console.width - 9)), " " * 8), style="dim")
            progress.console.print(line, highlight=False)
            progress.advance(task)

        run = run_cases(selected, fem=fem, serial=serial, client=client, scheduler=scheduler,
                        workers=workers, artifact_dir=artifact_dir, on_start=on_start,
                        on_result=on_result)
    _summary(console, run)

    drift = None
    if baseline is not None and update_baseline:
        path = bl.write_baseline(run, baseline)
        console.print(literal(f"baseline written: {path} "
                              f"({sum(len(v) for v in bl.snapshot(run).values())} values)"))
    elif baseline is not None:
        try:
            drift = bl.compare_baseline(run, baseline)
        except (OSError, ValueError) as exc:
            _usage(console, f"--baseline {baseline}: {exc}")
        _baseline_summary(console, drift, baseline)

    if report is not None:
        from ballrace.reports import html

        path = html.write_report(run, report, baseline=drift, plots=plots)
        import shutil

        shutil.rmtree(artifact_dir, ignore_errors=True)
        console.print(literal(f"report: {path}  (results: {report / 'results.json'})"))
    code = 0 if run.ok and (drift is None or drift.ok) else 1
    if code:
        console.print("[bold red]validation FAILED[/] (see the rows above)")
    else:
        console.print("[bold green]validation passed[/]")
    return code


def _summary(console, run) -> None:
    from rich.table import Table

    from .runner import STATUSES

    t = Table(title=literal(f"Validation summary (--fem {run.fem}, {_where_run(run.scheduler)}, "
                            f"wall-clock {run.duration:.1f} s)"),
              caption=literal("case time: each case's own computing time, summed; FE cases "
                              "and sweeps run in parallel, so the sum can exceed the wall time"))
    t.add_column("area")
    for s in STATUSES:
        t.add_column(s, justify="right", style=_STYLE[s] if s != "pass" else "green")
    t.add_column(literal("case time [s]"), justify="right")
    total = {s: 0 for s in STATUSES}
    for area, rows in run.by_area().items():
        counts = {s: sum(r.status == s for r in rows) for s in STATUSES}
        for s in STATUSES:
            total[s] += counts[s]
        t.add_row(literal(area), *[str(counts[s]) if counts[s] else "" for s in STATUSES],
                  f"{sum(r.duration for r in rows):.2f}")
    t.add_row("[bold]total[/]", *[f"[bold]{total[s]}[/]" for s in STATUSES],
              f"{sum(r.duration for r in run.results):.2f}", end_section=True)
    console.print(t)
    bad = [r for r in run.results if not r.ok]
    if bad:
        # a list, not a table: the reasons are sentences that must not be cut into columns
        from rich.text import Text

        console.print("Not passing", style="bold")
        for r in bad:
            line = Text(f"{_MARK[r.status]:>7} ", style=_STYLE[r.status])
            line.append(literal(r.id).plain, style="bold")
            console.print(line)
            if r.message:
                console.print(Text("        ") + literal(r.message))


def _where_run(scheduler: str) -> str:
    """Where the cases ran, for the summary, as the report says it: ``serial``, ``dask,
    local (1 worker(s), 2 thread(s))`` for a cluster on this machine (its ``inproc://`` or
    127.0.0.1 address means nothing to a reader), or a remote scheduler's address."""
    from ballrace.reports.html import scheduler_text

    return scheduler_text(scheduler)


def _baseline_summary(console, drift, path) -> None:
    from rich.table import Table

    if drift.ok:
        console.print(literal(f"baseline {path}: {drift.n_checked} value(s) unchanged within "
                              "tolerance"))
        return
    t = Table(title=literal(f"Moved against baseline {path}"))
    for c in ("case", "output", "baseline", "now", "change", "tolerance"):
        t.add_column(c)
    for d in drift.moved:
        t.add_row(literal(d.case), literal(d.output),
                  f"{d.old:.6g}" if d.old is not None else "-",
                  f"{d.new:.6g}" if d.new is not None else "-", literal(d.change),
                  literal(d.tolerance))
    console.print(t)


def _usage(console, msg: str) -> None:
    """One-line error on stderr (printed literally), exit code 2."""
    typer.echo(f"error: {msg}", err=True)
    raise typer.Exit(code=2)


def register(app: typer.Typer) -> None:
    """Add ``validate`` to the root app."""
    app.command("validate")(validate)
