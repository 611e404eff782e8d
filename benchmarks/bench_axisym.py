"""Axisymmetric reference model of circular contacts: verification and reference tables.

    nice -n 15 .venv/bin/python benchmarks/bench_axisym.py [--coarse 60] [--fine 80]
        [--verify 10,20,40,60,80] [--json out.json]

Prints (docs/fem-axisym.md):

1. the verification: two 12.7 mm steel balls at 2000 N in half-space mode (one elastic
   cylinder 40 a wide and deep under a rigid indenter of the combined curvature) against
   Hertz / Lundberg–Palmgren, for n = h/a elements per contact radius;
2. the extent of the half-space cylinder (8 a as the 3-D block … 80 a);
3. the reference: the two balls as two elastic bodies of their real shape at 31.25, 125,
   500, 2000 N (a/R = 0.014 … 0.055), two larger balls (D = 127 mm at 200 N and 1.27 m at
   20 N: a/R = 0.0055 and 0.00055), and a ball on a plane block (8 a as the 3-D block,
   and 40 a) at 2000 N, each at two resolutions, with the difference between them;
4. the departure from Hertz / LP against a/R, from the finer resolution: least-squares
   line (slope, intercept) over the four 12.7 mm loads, and a quadratic through zero
   over all six ball-on-ball contacts.

Run by hand (not a timed test); each model takes a few seconds.
"""
from __future__ import annotations

import argparse
import json
import resource
import time

QUANTITIES = ("a", "p_max", "approach", "tau0", "z0", "z0_tangent_plane", "max_shear",
              "max_shear_depth", "von_mises", "von_mises_depth")
SHORT = {"a": "a", "p_max": "p0", "approach": "δ", "tau0": "τ0", "z0": "z0", "z0_tangent_plane": "z0 (tangent plane)",
         "max_shear": "max shear", "max_shear_depth": "depth", "von_mises": "von Mises",
         "von_mises_depth": "depth"}
D = 12.7e-3
LOADS = (31.25, 125.0, 500.0, 2000.0)


def _pct(x: float) -> str:
    return f"{100 * x:+.2f} %".replace("-", "−")


def _run(kind: str, load: float, n: float, mode: str, diameter: float = D, **kwargs) -> dict:
    from ballrace.fem import axisym

    fn = axisym.ball_on_ball if kind == "ball" else axisym.ball_on_plane
    t0 = time.perf_counter()
    r = fn(diameter, load, n=n, mode=mode, **kwargs)
    return {"kind": kind, "diameter": diameter, "load": load, "n": n, "mode": mode,
            "options": kwargs, "dofs": r.n_dofs, "tents": r.n_tents,
            "wall": time.perf_counter() - t0, "a_over_R": float(r.analytic.a) / (diameter / 2),
            "errors": r.errors, "fit_errors": {q: r.error(q, "fit") for q in QUANTITIES}}


def _header(first: list[str]) -> str:
    cols = first + [SHORT[q] for q in QUANTITIES]
    return "| " + " | ".join(cols) + " |\n|" + "---|" * len(cols)


def _row(first: list[str], res: dict) -> str:
    return "| " + " | ".join(first + [_pct(res["errors"][q]) for q in QUANTITIES]) + " |"


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--verify", default="10,20,40,60,80",
                    help="resolutions n = a/h of the half-space verification")
    ap.add_argument("--coarse", type=float, default=60.0)
    ap.add_argument("--fine", type=float, default=80.0)
    ap.add_argument("--json", default=None, help="write every result to this file")
    args = ap.parse_args(argv)
    out = {"verify": [], "reference": []}

    print("## Verification: two 12.7 mm balls, 2000 N, half-space mode\n")
    print(_header(["n", "DOFs", "wall"]))
    for n in (float(v) for v in args.verify.split(",")):
        res = _run("ball", 2000.0, n, "half-space")
        out["verify"].append(res)
        print(_row([f"{n:g}", f"{res['dofs'] / 1e3:.1f}k", f"{res['wall']:.1f} s"], res),
              flush=True)

    print("\n## The extent of the half-space cylinder (n = 40; radius = depth, in a)\n")
    print(_header(["extent", "DOFs"]))
    for ext in (8.0, 16.0, 40.0, 80.0):
        res = _run("ball", 2000.0, 40.0, "half-space", halfspace_extent=ext)
        out.setdefault("extent", []).append(res)
        print(_row([f"{ext:g} a", f"{res['dofs'] / 1e3:.1f}k"], res), flush=True)

    print("\n## Reference: two bodies of their real shape\n")
    print(_header(["case", "a/R", "n", "DOFs", "wall"]))
    cases = [("ball", D, q, {}) for q in LOADS]
    cases += [("ball", 10 * D, 200.0, {}), ("ball", 100 * D, 20.0, {})]
    cases += [("plane", D, 2000.0, {}), ("plane", D, 2000.0, {"plane_extent": 40.0})]
    pairs = []
    for kind, dia, q, kw in cases:
        rr = []
        for n in (args.coarse, args.fine):
            res = _run(kind, q, n, "two-body", dia, **kw)
            out["reference"].append(res)
            rr.append(res)
            label = f"ball on {kind}, D = {dia * 1e3:g} mm, {q:g} N"
            if kind == "plane":
                label += f", block {kw.get('plane_extent', 8.0):g} a"
            print(_row([label, f"{res['a_over_R']:.5f}", f"{n:g}",
                        f"{res['dofs'] / 1e3:.1f}k", f"{res['wall']:.1f} s"], res), flush=True)
        pairs.append(rr)
    print("\nLargest difference between the two resolutions (percentage points):")
    for q in QUANTITIES:
        d = max(abs(c["errors"][q] - f["errors"][q]) for c, f in pairs)
        print(f"  {q:16s} {100 * d:.3f}")

    import numpy as np

    fine = sorted((f for c, f in pairs if f["kind"] == "ball"), key=lambda f: f["a_over_R"])
    x = np.array([f["a_over_R"] for f in fine])
    lin = np.array([f["diameter"] == D for f in fine])
    out["fit"] = {}
    print("\n## Ball on ball, departure from Hertz / LP against a/R "
          f"(n = {args.fine:g})\n")
    print("Line over the four 12.7 mm loads, error = k (a/R) + c; quadratic through zero over "
          "all six contacts, error = k1 (a/R) + k2 (a/R)^2 (errors in %):\n")
    print("| quantity | k | c | residual | k1 | k2 | residual |")
    print("|---|---|---|---|---|---|---|")
    for q in QUANTITIES:
        y = np.array([f["errors"][q] for f in fine])
        k, c0 = np.polyfit(x[lin], y[lin], 1)
        r1 = float(np.max(np.abs(y[lin] - (k * x[lin] + c0))))
        A = np.stack([x, x * x], axis=1)
        (k1, k2), *_ = np.linalg.lstsq(A, y, rcond=None)
        r2 = float(np.max(np.abs(y - A @ np.array([k1, k2]))))
        out["fit"][q] = {"slope": float(k), "intercept": float(c0), "residual": r1,
                         "k1": float(k1), "k2": float(k2), "residual_quadratic": r2}
        print(f"| {q} | {100 * k:+.1f} | {100 * c0:+.3f} | {100 * r1:.3f} | {100 * k1:+.1f} | "
              f"{100 * k2:+.0f} | {100 * r2:.3f} |")
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"\npeak RSS of the whole run: {peak:.0f} MB")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=1)
    return out


if __name__ == "__main__":
    main()
