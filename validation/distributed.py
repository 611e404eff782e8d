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
"""
from __future__ import annotations

import logging

__all__ = ["make_client", "close", "describe", "n_threads"]

log = logging.getLogger(__name__)


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
    if scheduler:
        log.info("connecting to dask scheduler %s", scheduler)
        return Client(scheduler, timeout="20s")
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


def describe(client) -> str:
    """Short description of the scheduler for the report."""
    try:
        info = client.scheduler_info()
        nw = len(info.get("workers", {}))
        addr = client.scheduler.address
        return f"dask {addr} ({nw} worker(s), {n_threads(client)} thread(s))"
    except Exception:  # pragma: no cover
        return "dask"
