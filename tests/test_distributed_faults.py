"""Distributed validation runs under faults.

The slow tests start a real ``dask scheduler`` and ``dask worker`` processes on
127.0.0.1 (no nanny, so a killed worker stays dead), run ``ballrace validate
--scheduler ...`` as a subprocess, and kill a worker while it is computing.  Every wait
is bounded and every process started here is stopped in ``finally``.  The fast tests
check the bounded waits in-process: an unreachable scheduler and a scheduler without
workers turn the distributed cases into errors naming the cause, within the timeout.
"""
from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

pytest.importorskip("dask.distributed")

from ballrace.validation.runner import run_cases  # noqa: E402
from ballrace.validation.schema import load_cases, parse_cases  # noqa: E402
from caseref import case_header  # noqa: E402

BALLRACE = str(Path(sys.executable).with_name("ballrace"))

# A sweep long enough to kill a worker in the middle of it: 40 speeds, each solving the
# Jones high-speed model twice (about 0.2 s per point on one core).  Same inputs and
# expectations as the packaged case sweep-highspeed-218-contact-angles-vs-speed.
SLOW_SWEEP = "\n" + case_header(
    "fault-sweep-highspeed-218", "218 bearing under 17,800 N, 0-14,000 rpm, 40 speeds",
    "highspeed.angle_trend", author="Jones", year=1960,
    reference="J. Basic Eng. 82, 309-320") + textwrap.dedent('''\
    [case.inputs]
    ball_diameter = "22.225 mm"
    n_balls = 16
    pitch_diameter = "125.26 mm"
    f_inner = 0.5232
    f_outer = 0.5232
    free_contact_angle = "40 deg"
    Fa = "17800 N"
    speed_increment = "1000 rpm"
    [case.sweep]
    speed_inner = { linspace = ["0 rpm", "14000 rpm", 40] }
    [case.reduce]
    max_outer_angle_change = "max(outer_angle_change)"
    min_inner_angle_change = "min(inner_angle_change)"
    max_relative_residual = "max(relative_residual)"
    [case.expected.max_outer_angle_change]
    max = "-0.001 deg"
    reason = "the outer contact angle falls with speed (centrifugal force)"
    [case.expected.min_inner_angle_change]
    min = "0.001 deg"
    reason = "the inner contact angle rises with speed"
    [case.expected.max_relative_residual]
    max = 1e-9
    reason = "every equilibrium must actually be solved"
''')


def _cases_file(tmp_path) -> Path:
    """The slow sweep plus the packaged Hertz-approximation sweeps and analytic cases."""
    from ballrace.validation.schema import default_case_dir

    text = (default_case_dir() / "hertz_approximations.toml").read_text() + SLOW_SWEEP
    p = tmp_path / "faults.toml"
    p.write_text(text)
    return p


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start(args, log: Path) -> subprocess.Popen:
    return subprocess.Popen(args, stdout=log.open("wb"), stderr=subprocess.STDOUT,
                            start_new_session=True, env={**os.environ, "PYTHONUNBUFFERED": "1"})


def _stop(procs) -> None:
    for p in procs:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGTERM)
    deadline = time.monotonic() + 10
    for p in procs:
        try:
            p.wait(timeout=max(0.1, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=10)


class Cluster:
    """A scheduler and named worker processes on 127.0.0.1, stopped by :meth:`close`."""

    def __init__(self, tmp_path: Path, n_workers: int):
        self.address = f"tcp://127.0.0.1:{_free_port()}"
        self.procs = []
        self.workers = {}
        py = sys.executable
        self.procs.append(_start([py, "-m", "dask", "scheduler", "--host", "127.0.0.1",
                                  "--port", self.address.rsplit(":", 1)[1], "--no-dashboard"],
                                 tmp_path / "scheduler.log"))
        for i in range(n_workers):
            name = f"w{i}"
            p = _start([py, "-m", "dask", "worker", self.address, "--nthreads", "1",
                        "--no-nanny", "--no-dashboard", "--name", name],
                       tmp_path / f"{name}.log")
            self.procs.append(p)
            self.workers[name] = p
        from dask.distributed import Client

        self.client = Client(self.address, timeout="60s")
        self.client.wait_for_workers(n_workers, timeout=120)

    def worker_address(self, name: str) -> str:
        info = self.client.scheduler_info(n_workers=-1)["workers"]
        return next(a for a, w in info.items() if w.get("name") == name)

    def kill_when_busy(self, name: str, run: subprocess.Popen, timeout: float = 120.0) -> float:
        """SIGKILL worker ``name`` as soon as it is processing a task; returns when."""
        addr = self.worker_address(name)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if run.poll() is not None:
                pytest.fail("the validate run finished before a worker could be killed")
            if self.client.processing(workers=[addr]).get(addr):
                os.killpg(self.workers[name].pid, signal.SIGKILL)
                self.workers[name].wait(timeout=30)
                return time.monotonic()
            time.sleep(0.05)
        pytest.fail(f"worker {name} never got a task within {timeout} s")

    def close(self) -> None:
        try:
            self.client.close(timeout=10)
        finally:
            _stop(self.procs)


def _validate(cases: Path, report: Path, *extra, env=None) -> subprocess.Popen:
    return subprocess.Popen([BALLRACE, "validate", "--cases", str(cases), "--report",
                             str(report), "--no-plots", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            start_new_session=True, env={**os.environ, **(env or {})})


def _finish(p: subprocess.Popen, timeout: float = 300.0) -> tuple[int, str]:
    try:
        out, _ = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate(timeout=30)
        pytest.fail(f"ballrace validate did not finish within {timeout} s:\n{out.decode()}")
    return p.returncode, out.decode(errors="replace")


def _results(report: Path) -> dict:
    data = json.loads((report / "results.json").read_text())
    return {c["id"]: c for c in data["cases"]}


@pytest.mark.slow
def test_killing_one_of_two_workers_mid_run(tmp_path):
    """The killed worker's tasks are re-run on the other: the run equals a serial run."""
    cases = _cases_file(tmp_path)
    code, out = _finish(_validate(cases, tmp_path / "serial", "--serial"))
    assert code == 0, out
    serial = _results(tmp_path / "serial")
    cluster = Cluster(tmp_path, 2)
    try:
        run = _validate(cases, tmp_path / "dist", "--scheduler", cluster.address)
        cluster.kill_when_busy("w0", run)
        code, out = _finish(run)
    finally:
        cluster.close()
    dist = _results(tmp_path / "dist")
    assert set(dist) == set(serial)
    assert any(c["points"] for c in dist.values())
    for cid, s in serial.items():
        d = dist[cid]
        if d["status"] != s["status"]:          # a lost case: an error, never a pass
            assert d["status"] == "error", (cid, d["status"], d["message"])
            continue
        assert d["outputs"] == s["outputs"], cid        # bit for bit
        assert d["points"] == s["points"], cid
    statuses = {c["status"] for c in dist.values()}
    assert code == (0 if statuses == {"pass"} else 1), out
    assert dist["fault-sweep-highspeed-218"]["status"] in ("pass", "error")


def _one_worker_run(tmp_path):
    """A one-worker cluster and a ``validate`` run of SLOW_SWEEP on it (workers time out
    after 5 s); the caller closes the cluster."""
    cases = tmp_path / "one.toml"
    cases.write_text(SLOW_SWEEP)
    cluster = Cluster(tmp_path, 1)
    try:
        return cluster, _validate(cases, tmp_path / "dist", "--scheduler", cluster.address,
                                  env={"BALLRACE_DASK_TIMEOUT": "5"})
    except BaseException:
        cluster.close()
        raise


@pytest.mark.slow
def test_killing_the_only_worker_reports_lost_cases_as_errors(tmp_path):
    """With no worker left the outstanding cases become errors after the timeout."""
    cluster, run = _one_worker_run(tmp_path)
    try:
        killed = cluster.kill_when_busy("w0", run)
        code, out = _finish(run, timeout=120)
        waited = time.monotonic() - killed
    finally:
        cluster.close()
    assert code == 1, out
    (case,) = _results(tmp_path / "dist").values()
    assert case["status"] == "error"
    assert "no workers for 5 s" in case["message"], case["message"]
    assert waited < 60                      # bounded: timeout + polling + shutdown


@pytest.mark.slow
def test_killing_the_scheduler_reports_cases_as_errors(tmp_path):
    """A scheduler that dies mid-run: the outstanding cases are errors; the run ends."""
    cluster, run = _one_worker_run(tmp_path)
    try:
        addr = cluster.worker_address("w0")
        deadline = time.monotonic() + 120
        while not cluster.client.processing(workers=[addr]).get(addr):
            assert time.monotonic() < deadline and run.poll() is None
            time.sleep(0.05)
        scheduler = cluster.procs[0]
        os.killpg(scheduler.pid, signal.SIGKILL)
        scheduler.wait(timeout=30)
        code, out = _finish(run, timeout=120)
    finally:
        cluster.close()
    # (dask's own client logger reports the lost connection with a traceback on stderr; the
    # run itself completes: summary, report and exit code 1)
    assert code == 1 and "validation FAILED" in out, out
    (case,) = _results(tmp_path / "dist").values()
    assert case["status"] == "error" and "lost" in case["message"], case["message"]


# ------------------------------------------------------------------ fast: bounded waits
def _sweep_cases():
    return [c for c in load_cases("hertz_approximations.toml") if c.distributed]


def test_unreachable_scheduler_is_an_error_not_a_hang(monkeypatch):
    monkeypatch.setenv("BALLRACE_DASK_TIMEOUT", "2")
    port = _free_port()                     # nothing listens there
    t0 = time.monotonic()
    run = run_cases(_sweep_cases(), scheduler=f"tcp://127.0.0.1:{port}")
    assert time.monotonic() - t0 < 30
    assert run.results and {r.status for r in run.results} == {"error"}
    for r in run.results:
        assert f"cannot reach the dask scheduler tcp://127.0.0.1:{port} within 2 s" in r.message


def test_scheduler_without_workers_is_an_error_not_a_hang(monkeypatch):
    from dask.distributed import LocalCluster

    monkeypatch.setenv("BALLRACE_DASK_TIMEOUT", "2")
    with LocalCluster(n_workers=0, processes=False, dashboard_address=None) as cluster:
        t0 = time.monotonic()
        run = run_cases(_sweep_cases(), scheduler=cluster.scheduler_address)
        assert time.monotonic() - t0 < 30
    assert {r.status for r in run.results} == {"error"}
    assert all("has no workers (waited 2 s)" in r.message for r in run.results)


def test_analytic_cases_still_run_when_the_scheduler_is_unreachable(monkeypatch):
    monkeypatch.setenv("BALLRACE_DASK_TIMEOUT", "1")
    cases = load_cases("hertz_approximations.toml")
    run = run_cases(cases, scheduler=f"tcp://127.0.0.1:{_free_port()}")
    by = {r.id: r for r in run.results}
    for c in cases:
        assert by[c.id].status == ("error" if c.distributed else "pass"), c.id


@pytest.mark.parametrize("value", ["0", "-3", "soon", "inf"])
def test_bad_timeout_setting_is_named(monkeypatch, value):
    from ballrace.validation.distributed import SchedulerError, timeout

    monkeypatch.setenv("BALLRACE_DASK_TIMEOUT", value)
    with pytest.raises(SchedulerError, match="BALLRACE_DASK_TIMEOUT"):
        timeout()


def test_parse_of_the_slow_sweep():
    (c,) = parse_cases(SLOW_SWEEP)
    assert c.distributed and c.sweep.size == 40


def test_bad_timeout_setting_makes_distributed_cases_errors(monkeypatch):
    monkeypatch.setenv("BALLRACE_DASK_TIMEOUT", "soon")
    run = run_cases(_sweep_cases())           # default in-process LocalCluster
    assert {r.status for r in run.results} == {"error"}
    assert all("BALLRACE_DASK_TIMEOUT must be a positive number" in r.message
               for r in run.results)
