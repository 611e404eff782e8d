"""Regression baselines: self-generated snapshots of every computed value.

These are kept apart from the verification values in the case files (STYLE practice 9):
a case file holds *published or independently derived* numbers with a justified
tolerance; a baseline holds *what this code computed last time*, with a tight tolerance,
to catch any change at all.  ``--update-baseline`` writes one; ``--baseline FILE``
compares every value of the current run with it and flags each value that moved
beyond its tolerance, each value that disappeared (the case now errors) and each case
that is new.

Tolerances: analytic values ``rtol = 1e-9`` (double-precision iterations converge to
~1e-12; this survives BLAS and platform differences); finite-element values
``rtol = 1e-4`` (direct-solver round-off and mesher differences between machines);
``atol = 1e-12`` in SI units for values that are zero.  They are stored in the file, so
a baseline can be loosened by hand for a specific value.  Loading checks every entry:
values and tolerances must be finite numbers (a NaN or Infinity entry, which Python's
JSON reader accepts, would compare as "unchanged" forever), ``0 <= rtol < 1`` and
``atol >= 0``; a file that is not JSON text (a binary file, say) is refused with its name.

Examples
--------
>>> import json, tempfile, os
>>> from ballrace.validation.runner import CaseResult, Run
>>> r = CaseResult(id="c", title="", area="hertz", kind="published", calculation="x",
...                source="", status="pass", outputs={"a": 1.0})
>>> run = Run(results=(r,), fem="none", started=0.0, duration=0.0)
>>> path = os.path.join(tempfile.mkdtemp(), "b.json")
>>> _ = write_baseline(run, path)
>>> moved = Run(results=(CaseResult(**{**r.__dict__, "outputs": {"a": 1.001}}),),
...             fem="none", started=0.0, duration=0.0)
>>> d = compare_baseline(moved, path)
>>> d.ok, [(m.case, m.output, m.change) for m in d.moved]
(False, [('c', 'a', '+0.1 %')])
"""
from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass
from pathlib import Path

__all__ = ["FORMAT", "RTOL_ANALYTIC", "RTOL_FEM", "ATOL", "snapshot", "write_baseline",
           "load_baseline", "compare_baseline", "Moved", "Drift"]

FORMAT = "ballrace-baseline/1"
RTOL_ANALYTIC = 1e-9
RTOL_FEM = 1e-4
ATOL = 1e-12


@dataclass(frozen=True)
class Moved:
    """One value that moved, vanished or is new (frozen)."""

    case: str
    output: str
    old: float | None
    new: float | None
    change: str
    tolerance: str


@dataclass(frozen=True)
class Drift:
    """Result of comparing a run with a baseline (frozen)."""

    path: str
    n_checked: int
    moved: tuple
    new_cases: tuple
    created: str = ""

    @property
    def ok(self) -> bool:
        return not self.moved


def snapshot(run) -> dict:
    """{case id: {output: {"value", "rtol", "atol"}}} of every computed value of ``run``."""
    out = {}
    for r in run.results:
        if r.status not in ("pass", "fail") or not r.outputs:
            continue
        rtol = RTOL_FEM if r.area == "fem" else RTOL_ANALYTIC
        out[r.id] = {k: {"value": v, "rtol": rtol, "atol": ATOL}
                     for k, v in sorted(r.outputs.items()) if math.isfinite(v)}
    return out


def write_baseline(run, path) -> Path:
    """Write the snapshot of ``run`` to ``path`` (JSON); returns the path."""
    from .environment import environment

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    data = {"format": FORMAT, "created": time.strftime("%Y-%m-%d %H:%M:%S"),
            "fem": run.fem, "environment": environment(), "values": snapshot(run)}
    path.write_text(json.dumps(data, indent=1, sort_keys=False) + "\n", encoding="utf-8")
    return path


def load_baseline(path) -> dict:
    """Read a baseline file (or a report's results.json, which embeds one).

    Raises
    ------
    OSError
        The file cannot be read.
    ValueError
        The file is not a results/baseline JSON, or an entry is not a finite value with
        finite tolerances; the message names the file (and the case and output).
    """
    path = Path(path)
    raw = path.read_bytes()
    try:
        data = json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise ValueError(f"{path} is not a results JSON (not UTF-8 text: a binary file?)") \
            from None
    except json.JSONDecodeError as exc:
        raise ValueError(f"{path} is not a results JSON ({exc})") from None
    if not isinstance(data, dict):
        raise ValueError(f"{path} is not a results JSON (top level is a "
                         f"{type(data).__name__}, not an object)")
    if data.get("format") != FORMAT:
        if isinstance(data.get("baseline"), dict) and data["baseline"].get("format") == FORMAT:
            data = data["baseline"]
        else:
            raise ValueError(f"{path}: not a ballrace baseline (format {data.get('format')!r}, "
                             f"expected {FORMAT!r})")
    _check_values(data.get("values"), path)
    return data


def _check_values(values, path) -> None:
    """Every entry {"value", "rtol", "atol"} holds finite numbers in range."""
    if not isinstance(values, dict):
        raise ValueError(f"{path}: 'values' must be an object {{case: {{output: entry}}}}")
    for cid, outs in values.items():
        if not isinstance(outs, dict):
            raise ValueError(f"{path}: values[{cid!r}] must be an object {{output: entry}}")
        for name, spec in outs.items():
            where = f"{path}: values[{cid!r}][{name!r}]"
            if not isinstance(spec, dict) or set(spec) != {"value", "rtol", "atol"}:
                raise ValueError(f"{where} must be {{\"value\", \"rtol\", \"atol\"}}; "
                                 f"got {spec!r}")
            for key in ("value", "rtol", "atol"):
                v = spec[key]
                if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                    raise ValueError(f"{where}.{key} must be a finite number; got {v!r}")
            if not 0 <= spec["rtol"] < 1:
                raise ValueError(f"{where}.rtol must be in [0, 1); got {spec['rtol']!r}")
            if spec["atol"] < 0:
                raise ValueError(f"{where}.atol must be >= 0; got {spec['atol']!r}")


def compare_baseline(run, path) -> Drift:
    """Compare ``run`` with the baseline at ``path``; every value beyond its tolerance is listed."""
    base = load_baseline(path)
    now = snapshot(run)
    ran = {r.id: r for r in run.results}
    moved = []
    n = 0
    for cid, vals in base["values"].items():
        r = ran.get(cid)
        if r is None:
            continue                       # case not selected in this run
        if r.status == "skipped":
            continue
        cur = now.get(cid, {})
        for name, spec in vals.items():
            n += 1
            old = spec["value"]
            tol = f"rtol {spec['rtol']:.0e}, atol {spec['atol']:.0e}"
            if name not in cur:
                moved.append(Moved(cid, name, old, None, f"vanished ({r.status})", tol))
                continue
            new = cur[name]["value"]
            if abs(new - old) > spec["atol"] + spec["rtol"] * abs(old):
                rel = f"{100 * (new - old) / abs(old):+.3g} %" if old else f"{new - old:+.3g}"
                moved.append(Moved(cid, name, old, new, rel, tol))
    new_cases = tuple(sorted(set(now) - set(base["values"])))
    return Drift(path=str(path), n_checked=n, moved=tuple(moved), new_cases=new_cases,
                 created=base.get("created", ""))
