"""Accuracy and cost of the FE check at a mesh level (run by hand, prints a table).

    .venv/bin/python benchmarks/bench_fem.py [--level standard] [--cases inner-hs,plane-hs,...]

Each case runs in its own subprocess so its peak memory (ru_maxrss) and wall time are
its own.  Cases: ``inner-hs`` / ``inner-2b`` (ball on the inner race of the 209 bearing,
D = 12.7 mm, d_m = 65 mm, f = 0.52, contact angle 0, Q = 4450 N; half-space / two
elastic bodies), ``outer-hs``, ``plane-hs`` / ``plane-2b`` (ball on plane, 2000 N),
``outer-2b``, ``ball-2b`` / ``ball-hs`` (two 12.7 mm balls, 2000 N), ``inner-exact`` (exact
sphere–torus gap), ``inner-hs-loads`` (three loads on one mesh and one factorisation).
Budgets of the FE check: half-space <= 30 s and 3 GB, two bodies <= 60 s and 6 GB, each
extra load of a list <= 1 s; accuracy: fem.TOLERANCES["standard"].
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time

CASES = {
    "inner-hs": ("race", "inner", 4450.0, "half-space", "hertz"),
    "inner-2b": ("race", "inner", 4450.0, "two-body", "hertz"),
    "outer-hs": ("race", "outer", 4450.0, "half-space", "hertz"),
    "outer-2b": ("race", "outer", 4450.0, "two-body", "hertz"),
    "ball-2b": ("ball", None, 2000.0, "two-body", "hertz"),
    "ball-hs": ("ball", None, 2000.0, "half-space", "hertz"),
    "plane-hs": ("plane", None, 2000.0, "half-space", "hertz"),
    "plane-2b": ("plane", None, 2000.0, "two-body", "hertz"),
    "inner-exact": ("race", "inner", 4450.0, "half-space", "exact"),
    # the curved two-body departure from Hertz against the contact size (a/R, a/(f D)):
    # the mesh scales with the ellipse, so the discretisation error is the same at every
    # load and what changes with the load is the geometry's departure from half-spaces
    "ball-2b-500": ("ball", None, 500.0, "two-body", "hertz"),
    "ball-2b-125": ("ball", None, 125.0, "two-body", "hertz"),
    "ball-2b-31": ("ball", None, 31.25, "two-body", "hertz"),
    "inner-2b-556": ("race", "inner", 556.0, "two-body", "hertz"),
    "inner-2b-70": ("race", "inner", 69.5, "two-body", "hertz"),
    "outer-2b-556": ("race", "outer", 556.0, "two-body", "hertz"),
    "outer-2b-70": ("race", "outer", 69.5, "two-body", "hertz"),
    # a load list on one mesh and one factorisation (run_case(..., loads=...)); the mesh is
    # sized by the smallest load, the pressure grid covers the largest
    "inner-hs-loads": ("race", "inner", [3000.0, 3700.0, 4450.0], "half-space", "hertz"),
}

_CHILD = r"""
import json, sys, time, resource
import ballrace
from ballrace import fem
kind, race, load, mode, gap, level = json.loads(sys.argv[1])
t0 = time.perf_counter()
if kind == "race":
    brg = ballrace.BallBearing(12.7e-3, 9, 65e-3, 0.52, 0.52, free_contact_angle=0.0)
    r = fem.ball_on_race(brg, load, race=race, level=level, mode=mode, gap=gap)
elif kind == "ball":
    r = fem.ball_on_ball(12.7e-3, load, level=level, mode=mode, gap=gap)
else:
    r = fem.ball_on_plane(12.7e-3, load, level=level, mode=mode, gap=gap)
rs = r if isinstance(r, list) else [r]
d = rs[-1].to_dict()
d["per_load"] = [x.timings["per_load"] for x in rs]
d["errors_per_load"] = {x.case.load: {row["quantity"]: row["error"] for row in x.comparison}
                        for x in rs}
d["wall"] = time.perf_counter() - t0
# contact size against the lower body's radius: the groove radius f D of a race, the ball's R
d["a_over_R"] = rs[-1].a / (0.52 * 12.7e-3 if kind == "race" else 6.35e-3)
d["peak_gb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6
print("RESULT" + json.dumps(d))
"""


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--level", default="standard")
    ap.add_argument("--cases", default="inner-hs,plane-hs,plane-2b,inner-2b",
                    help=f"comma-separated, of: {', '.join(CASES)}")
    ap.add_argument("--json", default=None, help="also write the results to this file")
    args = ap.parse_args(argv)
    out = {}
    q = ("a", "b", "p_max", "approach", "tau0", "z0", "max_shear", "max_shear_depth",
         "von_mises", "von_mises_depth")
    short = ("a", "b", "p0", "delta", "tau0", "z0", "tmax", "z_tmax", "vm", "z_vm")
    head = (f"{'case':<15}{'a/R':>6}{'DOFs':>9}{'wall s':>8}{'peak GB':>8}  "
            + "".join(f"{x:>9}" for x in short) + "  solver")
    print(head)
    print("-" * len(head))
    for name in args.cases.split(","):
        spec = list(CASES[name]) + [args.level]
        t0 = time.perf_counter()
        p = subprocess.run([sys.executable, "-c", _CHILD, json.dumps(spec)],
                           capture_output=True, text=True)
        line = [ln for ln in p.stdout.splitlines() if ln.startswith("RESULT")]
        if p.returncode or not line:
            print(f"{name:<12} FAILED after {time.perf_counter() - t0:.0f} s\n{p.stderr[-2000:]}")
            continue
        d = json.loads(line[0][6:])
        out[name] = d
        rows = {r["quantity"]: r for r in d["comparison"]}
        errs = "".join(f"{100 * rows[x]['error']:>+8.2f}%" for x in q)
        print(f"{name:<15}{d['a_over_R']:>6.3f}{d['n_dofs']:>9,}{d['wall']:>8.1f}{d['peak_gb']:>8.2f}  {errs}  "
              f"{d['solver']}", flush=True)
        if len(d["per_load"]) > 1:
            for load, e in d["errors_per_load"].items():
                print(f"{'  Q = ' + load + ' N':<40}"
                      + "".join(f"{100 * e[x]:>+8.2f}%" for x in q))
            print("  contact solve + extraction per load [s]: "
                  + ", ".join(f"{t:.2f}" for t in d["per_load"]), flush=True)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
