"""Run reference cases and compare with their expectations.

Analytic cases run in-process (they take milliseconds).  Finite-element cases and
sweep points run through :mod:`dask.distributed` (see :mod:`ballrace.validation.distributed`)
unless ``serial=True``; every task is a pure function of its inputs and the sweep
reductions are applied after gathering, in grid order, so a distributed run gives the
same numbers as a serial one, bit for bit.

Outcomes (:data:`STATUSES`):

===========  ======================================================================
``pass``     every expectation met;
``fail``     at least one expectation missed (or an expected output is NaN/absent);
``error``    the calculation raised;
``missing``  a library module the calculation needs is not available — counted as a
             failure of the run, never as a pass or a silent skip;
``skipped``  an FE case under ``--fem none`` ("skipped by request"), or an FE case
             whose ``fem_levels`` exclude the requested level.
===========  ======================================================================

Examples
--------
>>> from ballrace.validation.schema import parse_cases
>>> from ballrace.validation.runner import run_cases
>>> cases = parse_cases('''
... [[case]]
... id = "moose"
... title = "two spheres"
... kind = "published"
... calculation = "hertz.point_contact"
... source = {author = "MOOSE", year = 2020, reference = "hertz_spherical"}
... expected.a = {value = "0.1 m", rtol = 1e-9, reason = "exact closed form"}
... [case.inputs]
... load = "10000 N"
... rx1 = "2 m"
... ry1 = "2 m"
... rx2 = "2 m"
... ry2 = "2 m"
... E1 = "1.40625e7 Pa"
... nu1 = 0.25
... ''')
>>> run = run_cases(cases, serial=True)
>>> run.results[0].status, run.ok
('pass', True)
"""
from __future__ import annotations

import logging
import math
import time
import traceback
from dataclasses import dataclass, field
from typing import Callable, Iterable

from . import registry
from .schema import Case, Expectation

__all__ = ["STATUSES", "Comparison", "CaseResult", "Run", "run_cases", "execute", "compare",
           "reduce_points"]

log = logging.getLogger(__name__)

STATUSES = ("pass", "fail", "error", "missing", "skipped")
FEM_LEVELS = ("none", "quick", "standard")


@dataclass(frozen=True)
class Comparison:
    """One expected output against the computed value (frozen; SI)."""

    name: str
    dimension: str
    got: float | None
    expected: float | None
    minimum: float | None
    maximum: float | None
    error: float | None          # got - expected (value checks) or excess over the bound
    rel_error: float | None      # (got - expected)/|expected|
    allowed: float | None        # atol + rtol |expected|
    tolerance: str
    reason: str
    passed: bool


@dataclass(frozen=True)
class CaseResult:
    """Outcome of one case (frozen)."""

    id: str
    title: str
    area: str
    kind: str
    calculation: str
    source: str
    status: str
    message: str = ""
    duration: float = 0.0
    comparisons: tuple = ()
    outputs: dict = field(default_factory=dict)
    points: tuple = ()           # sweep: ({inputs..., outputs...}, ...)
    artifacts: tuple = ()        # (label, path) of files the calculation wrote (FE renders)
    series: dict = field(default_factory=dict)   # per-ball arrays etc. for the report's plots
    inputs: dict = field(default_factory=dict)   # as written in the case file
    notes: str = ""

    @property
    def ok(self) -> bool:
        return self.status in ("pass", "skipped")


@dataclass(frozen=True)
class Run:
    """All results of one validation run (frozen)."""

    results: tuple
    fem: str
    started: float
    duration: float
    scheduler: str = "serial"

    @property
    def counts(self) -> dict:
        out = {s: 0 for s in STATUSES}
        for r in self.results:
            out[r.status] += 1
        return out

    @property
    def ok(self) -> bool:
        """True when nothing failed, errored or was missing."""
        return all(r.ok for r in self.results)

    def by_area(self) -> dict:
        out: dict[str, list] = {}
        for r in self.results:
            out.setdefault(r.area, []).append(r)
        return out


# --------------------------------------------------------------------------- execution
def execute(calc_name: str, inputs: dict) -> tuple[dict, float]:
    """Run one calculation on SI inputs; returns (outputs, seconds).  Worker entry point."""
    import warnings

    calc = registry.get(calc_name)
    t0 = time.perf_counter()
    # a reference case may sit where the library warns on purpose (the MOOSE spheres'
    # a / R, a soft benchmark material): the warning goes to the log (-v), not to stderr
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", UserWarning)
        out = calc.func(**inputs)
    dt = time.perf_counter() - t0
    for w in caught:
        if issubclass(w.category, UserWarning):
            log.info("%s: %s", calc_name, w.message)
        else:                                            # anything else as it would be
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    if not isinstance(out, dict):
        raise TypeError(f"{calc_name} returned {type(out).__name__}, not a dict of outputs")
    return out, dt


def execute_many(calc_name: str, points: list) -> tuple[list, float]:
    """Run a calculation on a chunk of sweep points (one dask task per chunk)."""
    t0 = time.perf_counter()
    outs = [execute(calc_name, p)[0] for p in points]
    return outs, time.perf_counter() - t0


def compare(exp: Expectation, got) -> Comparison:
    """Compare a computed value with an expectation (the tolerance text in the engineering
    units the report shows the values in)."""
    from ballrace.reports.html import tolerance_text

    g = None if got is None else float(got)
    err = rel = None
    if g is not None and math.isfinite(g):
        if exp.value is not None:
            err = g - exp.value
            rel = err / abs(exp.value) if exp.value != 0 else None
        else:
            over = []
            if exp.max is not None:
                over.append(g - exp.max)
            if exp.min is not None:
                over.append(exp.min - g)
            err = max(over)
    return Comparison(name=exp.name, dimension=exp.dimension, got=g, expected=exp.value,
                      minimum=exp.min, maximum=exp.max, error=err, rel_error=rel,
                      allowed=exp.allowed, tolerance=tolerance_text(exp, g), reason=exp.reason,
                      passed=exp.check(g) if g is not None else False)


def reduce_points(case: Case, outs: list) -> dict:
    """Apply a sweep case's reductions to its per-point outputs (in grid order)."""
    import numpy as np

    res = {}
    for new, how, name in case.sweep.reduce:
        v = np.array([o[name] for o in outs], dtype=float)
        if how == "min_rise":
            res[new] = _min_rise(case, v)
            continue
        res[new] = float({"max_abs": lambda x: np.max(np.abs(x)), "max": np.max,
                          "min": np.min, "mean": np.mean}[how](v))
    return res


def _min_rise(case: Case, v):
    """Smallest step of |v| along the last sweep axis (NaN when it has one value)."""
    import numpy as np

    shape = tuple(len(vals) for _, vals in case.sweep.axes)
    if shape[-1] < 2:
        return math.nan
    return float(np.min(np.diff(np.abs(v.reshape(shape)), axis=-1)))


def _finish(case: Case, outputs: dict, duration: float, points=(), artifacts=()) -> CaseResult:
    import numpy as np

    series = {k: [float(x) for x in np.ravel(v)] for k, v in outputs.get("_series", {}).items()}
    comps = tuple(compare(e, outputs.get(e.name)) for e in case.expected)
    missing = [c.name for c in comps if c.got is None]
    status = "pass" if all(c.passed for c in comps) else "fail"
    msg = ""
    if missing:
        msg = f"calculation returned no {', '.join(missing)}"
    elif status == "fail":
        bad = [c for c in comps if not c.passed]
        msg = "; ".join(f"{c.name} off by {_err_text(c)} (allowed {c.tolerance})" for c in bad)
    clean = {k: float(v) for k, v in outputs.items()
             if not k.startswith("_") and isinstance(v, (int, float))}
    return _result(case, status, msg, duration, comps, clean, points, artifacts, series)


def _err_text(c: Comparison) -> str:
    if c.got is None or not math.isfinite(c.got):
        return f"got {c.got}"
    from ballrace.reports import html

    if c.expected is None and c.error is not None:      # a bound: the excess over it
        s = html.format_eng(c.error, c.dimension, html.reference_value(c))
        unit = html.name_unit(c)
        s = s if s.startswith("-") else "+" + s
        return f"{s} {unit}" if unit else s
    return html.error_text(c)


def _result(case: Case, status: str, message: str, duration: float = 0.0, comps=(),
            outputs=None, points=(), artifacts=(), series=None) -> CaseResult:
    return CaseResult(id=case.id, title=case.title, area=case.area, kind=case.kind,
                      calculation=case.calculation, source=str(case.source), status=status,
                      message=message, duration=duration, comparisons=tuple(comps),
                      outputs=dict(outputs or {}), points=tuple(points),
                      artifacts=tuple(artifacts), inputs=dict(case.raw_inputs), notes=case.notes,
                      series=dict(series or {}))


def _error_message(exc: BaseException) -> str:
    tb = traceback.extract_tb(exc.__traceback__)
    where = f" (at {tb[-1].filename.rsplit('/', 1)[-1]}:{tb[-1].lineno})" if tb else ""
    return f"{type(exc).__name__}: {exc}{where}"


def _inputs_for(case: Case, fem: str, artifact_dir) -> dict:
    inputs = dict(case.inputs)
    if case.fem:
        calc = registry.get(case.calculation)
        if "level" in calc.inputs:
            inputs["level"] = fem
        if "render_dir" in calc.inputs:
            inputs["render_dir"] = None if artifact_dir is None else str(artifact_dir)
        if "case_id" in calc.inputs:
            inputs["case_id"] = case.id
    return inputs


def _chunks(points: list, n_chunks: int) -> list[list]:
    size = max(1, math.ceil(len(points) / n_chunks))
    return [points[i:i + size] for i in range(0, len(points), size)]


def run_cases(cases: Iterable[Case], *, fem: str = "quick", serial: bool = False,
              client=None, scheduler: str | None = None, workers: int | None = None,
              artifact_dir=None, on_start: Callable | None = None,
              on_result: Callable[[CaseResult], None] | None = None) -> Run:
    """Run cases and compare them with their expectations.

    Parameters
    ----------
    cases : iterable of Case
    fem : {"none", "quick", "standard"}
        FE level; ``"none"`` skips FE cases ("skipped by request").
    serial : bool
        Run everything in-process (no dask) — the reference for the distributed run.
    client : dask.distributed.Client, optional
        Use this client; otherwise one is made for ``scheduler`` (an address such as
        ``tcp://host:8786``) or a LocalCluster, only when a distributed case is selected.
    workers : int, optional
        LocalCluster worker processes (default: an in-process cluster, two threads).
    artifact_dir : path, optional
        Where FE calculations write renders.
    on_start, on_result : callable, optional
        ``on_start(case)`` when a case is dispatched, ``on_result(result)`` as each finishes
        (the CLI's progress display).
    """
    if fem not in FEM_LEVELS:
        raise ValueError(f"fem must be one of {', '.join(FEM_LEVELS)}; got {fem!r}")
    cases = list(cases)
    t_start = time.time()
    t0 = time.perf_counter()
    results: dict[str, CaseResult] = {}

    def done(r: CaseResult) -> None:
        results[r.id] = r
        log.info("%s %s (%.3f s) %s", r.status.upper(), r.id, r.duration, r.message)
        if on_result:
            on_result(r)

    runnable: list[Case] = []
    for case in cases:
        calc = registry.get(case.calculation)
        if case.fem and fem == "none":
            done(_result(case, "skipped", "skipped by request (--fem none)"))
            continue
        if case.fem and fem not in case.fem_levels:
            done(_result(case, "skipped", f"--fem {'/'.join(case.fem_levels)} only "
                                          f"(requested {fem})"))
            continue
        try:
            registry.check_available(calc)
        except registry.ModuleMissing as exc:
            done(_result(case, "missing", str(exc)))
            continue
        runnable.append(case)

    local = [c for c in runnable if serial or not c.distributed]
    remote = [c for c in runnable if not serial and c.distributed]

    # distributed work is submitted first so it runs while the analytic cases are computed
    sched_name = "serial"
    own_client = None
    futures = {}
    if remote:
        from . import distributed

        if client is None:
            try:
                own_client = distributed.make_client(scheduler=scheduler, workers=workers)
            except distributed.SchedulerError as exc:
                log.error("%s", exc)
                for case in remote:
                    done(_result(case, "error", f"not run: {exc}"))
                remote = []
                sched_name = f"dask {scheduler} (unavailable)"
            client = own_client
        if remote:
            sched_name = distributed.describe(client)
        for case in remote:
            if on_start:
                on_start(case)
            inputs = _inputs_for(case, fem, artifact_dir)
            if case.sweep is None:
                fut = client.submit(execute, case.calculation, inputs, pure=False,
                                    key=f"case-{case.id}-{time.monotonic_ns()}")
                futures[fut] = (case, None)
            else:
                pts = [{**inputs, **p} for p in case.sweep.points()]
                n_chunks = max(1, min(len(pts), 4 * distributed.n_threads(client)))
                chunk_futs = [client.submit(execute_many, case.calculation, ch, pure=False)
                              for ch in _chunks(pts, n_chunks)]
                fut = client.submit(_gather_sweep, chunk_futs, pure=False)
                futures[fut] = (case, pts)

    try:
        for case in local:
            if on_start:
                on_start(case)
            done(_run_local(case, _inputs_for(case, fem, artifact_dir)))
        if futures:
            _collect(client, futures, done)
    finally:
        if own_client is not None:
            from . import distributed

            distributed.close(own_client)

    ordered = tuple(results[c.id] for c in cases)
    return Run(results=ordered, fem=fem, started=t_start, duration=time.perf_counter() - t0,
               scheduler=sched_name)


def _collect(client, futures: dict, done: Callable, poll: float = 1.0) -> None:
    """Report each future's case as it finishes; never wait on a cluster without workers.

    A task lost with a dying worker is re-run by dask on another worker; one that dask gives
    up on (``KilledWorker``) or that raised is an ``error``.  When the cluster has had no
    worker at all for :func:`distributed.timeout` seconds, the cases still outstanding are
    reported as errors ("lost") and their futures cancelled: never a pass, never a hang.
    Futures that dask cancels (the scheduler connection was lost) are errors too.
    """
    from dask.distributed import wait

    from . import distributed

    limit = distributed.timeout()
    pending = set(futures)
    idle_since = None
    while pending:
        try:
            finished, pending = wait(pending, timeout=poll, return_when="FIRST_COMPLETED")
        except TimeoutError:
            finished = set()
        except Exception as exc:  # noqa: BLE001 - futures cancelled (scheduler connection lost)
            finished = {f for f in pending if f.done()}
            pending = pending - finished
            if not finished:
                msg = f"lost: {type(exc).__name__}: {' '.join(str(exc).split())}"
                for fut in sorted(pending, key=lambda f: futures[f][0].id):
                    done(_result(futures[fut][0], "error", msg))
                return
        for fut in finished:
            case, pts = futures[fut]
            try:
                if pts is None:
                    out, dt = fut.result()
                    done(_finish(case, out, dt, artifacts=_artifacts(out)))
                else:
                    outs, dt = fut.result()
                    done(_finish(case, reduce_points(case, outs), dt, points=_points(pts, outs)))
            except Exception as exc:  # the calculation raised on a worker, or dask gave up
                done(_result(case, "error", _error_message(exc)))
        if finished or not pending:
            idle_since = None
            continue
        if distributed.n_workers(client) > 0:
            idle_since = None
            continue
        now = time.monotonic()
        idle_since = idle_since or now
        if now - idle_since < limit:
            continue
        msg = (f"lost: the dask cluster has had no workers for {limit:g} s (all died or "
               "none connected); the case did not run to completion")
        log.error("%s; %d case(s) outstanding", msg, len(pending))
        for fut in sorted(pending, key=lambda f: futures[f][0].id):
            done(_result(futures[fut][0], "error", msg))
        client.cancel(list(pending))
        pending = set()


def _gather_sweep(chunks):
    """Concatenate chunk results in grid order (runs on a worker; dask resolves the futures)."""
    outs, dt = [], 0.0
    for o, t in chunks:
        outs.extend(o)
        dt += t
    return outs, dt


def _points(pts: list, outs: list) -> tuple:
    keep = []
    for p, o in zip(pts, outs):
        row = {k: v for k, v in p.items() if isinstance(v, (int, float, str)) or v is None}
        row.update({k: float(v) for k, v in o.items() if isinstance(v, (int, float))})
        keep.append(row)
    return tuple(keep)


def _artifacts(out: dict) -> tuple:
    return tuple(tuple(a) for a in out.get("_artifacts", ()))


def _run_local(case: Case, inputs: dict) -> CaseResult:
    t0 = time.perf_counter()
    try:
        if case.sweep is None:
            out, dt = execute(case.calculation, inputs)
            return _finish(case, out, dt, artifacts=_artifacts(out))
        pts = [{**inputs, **p} for p in case.sweep.points()]
        outs, dt = execute_many(case.calculation, pts)
        return _finish(case, reduce_points(case, outs), dt, points=_points(pts, outs))
    except Exception as exc:
        log.debug("case %s raised", case.id, exc_info=True)
        return _result(case, "error", _error_message(exc), time.perf_counter() - t0)
