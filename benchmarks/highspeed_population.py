"""Failure rate, flags, correctness and time of ``highspeed.solve`` on a bearing population.

A plain script (not collected by pytest), run by hand::

    python benchmarks/highspeed_population.py [n_calls] [seed]

Population: deep-groove (diametral clearance) and angular-contact (15, 25, 40 deg)
steel bearings (E = 208 GPa, nu = 0.3, rho = 7850 kg/m^3), D 5-25 mm, D/d_m 0.12-0.3,
f_i 0.505-0.52, f_o 0.515-0.54, loads 1e-3-0.5 C (C = ``dynamic_rating()``, log-uniform;
axial, radial or combined), d_m n 5e4-1.5e6 mm rpm (log-uniform, inner ring), the three
race-control hypotheses.  Every returned result is re-derived independently
(``tests/hsref.py``).  Prints: calls, successes,
ConvergenceErrors, other errors, flagged (``result.warnings``), wrong by the
re-derivation, median / p95 / max time per call: the first call for each bearing (which
also builds the bearing's cached models: the K(alpha) series, the static model's tables)
and a second, identical call (the models cached, as in a loop over load cases).
"""
import importlib.util
import logging
import pathlib
import sys
import time

import numpy as np

import ballrace
from ballrace.analytic import highspeed
from ballrace.analytic.loaddist import ConvergenceError
from ballrace.analytic.materials import Material

HERE = pathlib.Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location("_hsref", HERE.parent / "tests" / "hsref.py")
_hsref = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_hsref)

STEEL = Material(E=208e9, nu=0.3, density=7850.0)


def population(n, seed):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        D = rng.uniform(5e-3, 25e-3)
        dm = D / rng.uniform(0.12, 0.3)
        Z = int(min(np.floor(0.9 * np.pi / np.arcsin(D / dm)), rng.integers(7, 20)))
        fi, fo = rng.uniform(0.505, 0.52), rng.uniform(0.515, 0.54)
        kind = rng.choice(["deep-groove", "15", "25", "40"])
        if kind == "deep-groove":
            A = (fi + fo - 1) * D
            brg = ballrace.BallBearing(D, Z, dm, fi, fo, material=STEEL,
                                       diametral_clearance=rng.uniform(0.005, 0.2) * A)
        else:
            brg = ballrace.BallBearing(D, Z, dm, fi, fo, material=STEEL,
                                       free_contact_angle=np.radians(float(kind)))
        C = brg.dynamic_rating()
        F = C * 10 ** rng.uniform(-3, np.log10(0.5))
        how = rng.choice(["axial", "radial", "combined"])
        if how == "axial":
            Fa, Fr = F, 0.0
        elif how == "radial":
            Fa, Fr = 0.0, F
        else:
            t = rng.uniform(0.1, 0.9)
            Fa, Fr = F * np.sin(t * np.pi / 2), F * np.cos(t * np.pi / 2)
        dmn = 10 ** rng.uniform(np.log10(5e4), np.log10(1.5e6))
        w = dmn / (dm * 1e3) * np.pi / 30
        control = str(rng.choice(highspeed.CONTROLS))
        yield brg, dict(Fa=Fa, Fr=Fr, speed_inner=w, control=control), kind


def main(n=400, seed=21):
    logging.disable(logging.WARNING)
    t_all, t_warm, counts, wrong_examples = [], [], dict.fromkeys(
        ("calls", "ok", "ConvergenceError", "other error", "flagged", "wrong"), 0), []
    slow = []
    by_control = {c: [0, 0] for c in highspeed.CONTROLS}      # calls, ConvergenceErrors
    reasons = {"skid": 0, "groove": 0, "orbital speed": 0}
    for brg, kw, kind in population(n, seed):
        by_control[kw["control"]][0] += 1
        counts["calls"] += 1
        t = time.perf_counter()
        try:
            r = highspeed.solve(brg, **kw)
        except ConvergenceError:
            counts["ConvergenceError"] += 1
            by_control[kw["control"]][1] += 1
            r = None
        except Exception as exc:                 # noqa: BLE001 - counted and shown
            counts["other error"] += 1
            print("error:", type(exc).__name__, str(exc)[:120], kind, kw)
            r = None
        dt = time.perf_counter() - t
        t_all.append(dt)
        t = time.perf_counter()
        try:
            highspeed.solve(brg, **kw)
        except Exception:                        # noqa: BLE001 - counted above
            pass
        t_warm.append(time.perf_counter() - t)
        if dt > 1.0:
            slow.append((round(dt, 2), kind, kw))
        if r is None:
            continue
        counts["ok"] += 1
        if getattr(r, "warnings", ()):
            counts["flagged"] += 1
            for k in reasons:
                reasons[k] += any(k in w for w in r.warnings)
        bad = _hsref.rederive_highspeed(brg, r)
        if bad:
            counts["wrong"] += 1
            wrong_examples.append((kind, kw, bad[:2]))
    t_all, t_warm = np.array(t_all) * 1e3, np.array(t_warm) * 1e3
    print(f"ballrace from {ballrace.__file__}")
    print(" ".join(f"{k}={v}" for k, v in counts.items()))
    print(f"time per call [ms]: median {np.median(t_all):.1f}  p95 {np.percentile(t_all, 95):.1f}"
          f"  max {t_all.max():.0f}  total {t_all.sum() / 1e3:.1f} s")
    print(f"  same call again, models cached [ms]: median {np.median(t_warm):.1f}  p95 "
          f"{np.percentile(t_warm, 95):.1f}  max {t_warm.max():.0f}  total "
          f"{t_warm.sum() / 1e3:.1f} s")
    print("ConvergenceErrors by control: " + ", ".join(
        f"{c} {e}/{n_} ({100 * e / max(n_, 1):.1f} %)" for c, (n_, e) in by_control.items()))
    print("flagged results by reason: " + ", ".join(f"{k} {v}" for k, v in reasons.items()))
    for w in wrong_examples[:8]:
        print("wrong:", w)
    for s in slow[:8]:
        print("slow:", s)


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:3]]
    main(*args)
