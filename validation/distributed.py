"""dask.distributed plumbing for FE cases and sweeps (imported lazily; dask is optional).

By default an in-process :class:`~dask.distributed.LocalCluster` (``processes=False``,
one worker with two threads) is started for the run and closed afterwards.  On this
2-core machine that is the fastest choice: FE solves keep multithreaded BLAS (dask
pins worker *processes* to one BLAS thread, which measured 2.5x slower per solve), and
gmsh, which is not thread-safe, is serialised by a lock in
:mod:`ballrace.validation.calc_fem` while analytic sweep points run on both threads.
``--workers N`` (N >= 1) starts N single-threaded worker processes instead;
``--scheduler tcp://host:8786`` connects to an existing cluster (its workers need
``ballrace`` installed).

Every wait on a cluster is bounded (:data:`TIMEOUT`, 30 s by default, or the
``BALLRACE_DASK_TIMEOUT`` environment variable in seconds): an unreachable scheduler, a
scheduler without workers and a cluster whose workers have all died raise
:class:`SchedulerError` (or, mid-run, turn the outstanding cases into errors, see
:func:`ballrace.validation.runner.run_cases`) instead of hanging.  A worker that dies
while others live is dask's business: the scheduler moves its tasks to the others (each
task may be on up to three workers that die before dask gives up with ``KilledWorker``,
which the runner reports as an error).
"""
from __future__ import annotations

import logging
import os

__all__ = ["SchedulerError", "TIMEOUT", "timeout", "make_client", "close", "describe",
           "n_threads", "n_workers"]

log = logging.getLogger(__name__)

#: Default bound [s] on waiting for a scheduler or for workers.
TIMEOUT = 30.0


class SchedulerError(RuntimeError):
    """The dask scheduler cannot be reached, or has no workers to run on."""


def timeout() -> float:
    """The wait bound [s]: ``BALLRACE_DASK_TIMEOUT`` if set (a positive number), else TIMEOUT."""
    raw = os.environ.get("BALLRACE_DASK_TIMEOUT")
    if raw is None:
        return TIMEOUT
    try:
        value = float(raw)
    except ValueError:
        value = -1.0
    if not 0 < value < float("inf"):
        raise SchedulerError(f"BALLRACE_DASK_TIMEOUT must be a positive number of seconds; "
                             f"got {raw!r}")
    return value


def make_client(scheduler: str | None = None, workers: int | None = None):
    """A dask Client: connected to ``scheduler``, or on a fresh LocalCluster.

    Parameters
    ----------
    scheduler : str, optional
        Address of a running scheduler (``tcp://host:8786``).
    workers : int, optional
        LocalCluster worker processes; None or 0 means one in-process worker with two
        threads (the default).
    """
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError as exc:  # pragma: no cover - optional extra
        raise RuntimeError("FE and sweep cases run through dask.distributed; install "
                           "ballrace[report] or pass --serial") from exc
    wait = timeout()                     # a bad BALLRACE_DASK_TIMEOUT is refused before any run
    if scheduler:
        log.info("connecting to dask scheduler %s (timeout %g s)", scheduler, wait)
        try:
            client = Client(scheduler, timeout=f"{wait}s")
        except (OSError, TimeoutError, ValueError) as exc:
            raise SchedulerError(f"cannot reach the dask scheduler {scheduler} within {wait:g} s "
                                 f"({type(exc).__name__}: {exc})") from None
        try:
            client.wait_for_workers(1, timeout=wait)
        except (TimeoutError, OSError) as exc:
            client.close()
            raise SchedulerError(f"the dask scheduler {scheduler} has no workers (waited "
                                 f"{wait:g} s); start some with 'dask worker {scheduler}' or "
                                 f"run without --scheduler") from exc
        return client
    if not workers:
        cluster = LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                               dashboard_address=None, silence_logs=logging.WARNING)
    else:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=None, silence_logs=logging.WARNING)
    log.info("started LocalCluster with %d worker(s)", len(cluster.workers))
    client = Client(cluster)
    client._ballrace_owns_cluster = cluster
    return client


def close(client) -> None:
    """Close a client made by :func:`make_client` (and its LocalCluster)."""
    cluster = getattr(client, "_ballrace_owns_cluster", None)
    client.close()
    if cluster is not None:
        cluster.close()


def n_threads(client) -> int:
    """Total worker threads of the cluster (at least 1)."""
    try:
        return max(1, sum(client.nthreads().values()))
    except Exception:  # pragma: no cover - scheduler without workers yet
        return 1


def n_workers(client) -> int:
    """Workers connected to the scheduler now (asks the scheduler; 0 when it cannot answer)."""
    try:
        return len(client.nthreads())
    except Exception:  # noqa: BLE001 - a scheduler that does not answer has no workers for us
        return 0


def describe(client) -> str:
    """Short description of the scheduler for the report."""
    try:
        info = client.scheduler_info()
        nw = len(info.get("workers", {}))
        addr = client.scheduler.address
        return f"dask {addr} ({nw} worker(s), {n_threads(client)} thread(s))"
    except Exception:  # pragma: no cover
        return "dask"
