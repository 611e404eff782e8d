"""Accuracy and cost of the FE roller check at a mesh level (run by hand, prints a table).

    .venv/bin/python benchmarks/bench_fem_roller.py [--level standard] [--cases lundberg,...]

Each case runs in its own subprocess so its peak memory (ru_maxrss) and wall time are
its own (a first run also meshes; the mesh cache makes later runs faster).  The roller of
``ballrace.fem.roller``'s notes: R1 = 6 mm, L = 12 mm, flat steel raceway, 5 kN,
half-space mode.  Cases: ``lundberg``, ``crowned`` (4 mm flat, 0.5 m crown radius),
``straight``, ``iso``, and ``crowned-tilt`` (0.5 mrad: the half model).  Budget of the
check at the standard level: <= 60 s and 4 GB on a 2-core machine (the quarter model);
accuracy: the comparison rows' tolerances (``RollerFEResult.comparison``).
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time

CASES = {
    "lundberg": ("lundberg", 0.0),
    "crowned": ({"flat_length": 4e-3, "crown_radius": 0.5}, 0.0),
    "straight": ("straight", 0.0),
    "iso": ("iso", 0.0),
    "crowned-tilt": ({"flat_length": 4e-3, "crown_radius": 0.5}, 5e-4),
}

_CHILD = r"""
import json, sys, time, resource
import numpy as np
import ballrace
from ballrace import fem
from ballrace.analytic.roller import Crowned
profile, tilt, level = json.loads(sys.argv[1])
if isinstance(profile, dict):
    profile = Crowned(**profile)
st = ballrace.BEARING_STEEL
t0 = time.perf_counter()
r = fem.roller_contact(5000.0, 6e-3, np.inf, 12e-3, st, st, profile=profile, tilt=tilt,
                       level=level)
d = {"n_dofs": r.n_dofs, "wall": time.perf_counter() - t0, "solver": r.solver,
     "peak_gb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6,
     "errors": {row["quantity"]: row["error"] for row in r.comparison},
     "edge_pressure": r.edge_pressure}
print("RESULT" + json.dumps(d))
"""

#: comparison rows shown (FE / line_contact - 1)
ROWS = ("centre_pressure", "approach", "von_mises_centre", "max_pressure", "end_quarter_load")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--level", default="standard")
    ap.add_argument("--cases", default="lundberg,crowned,straight",
                    help=f"comma-separated, of: {', '.join(CASES)}")
    args = ap.parse_args(argv)
    head = (f"{'case':<14}{'DOFs':>9}{'wall s':>8}{'peak GB':>8}  "
            + "".join(f"{x[:12]:>13}" for x in ROWS) + "   edge node GPa  solver")
    print(head)
    print("-" * len(head))
    for name in args.cases.split(","):
        profile, tilt = CASES[name]
        t0 = time.perf_counter()
        p = subprocess.run([sys.executable, "-c", _CHILD,
                            json.dumps([profile, tilt, args.level])],
                           capture_output=True, text=True)
        line = [ln for ln in p.stdout.splitlines() if ln.startswith("RESULT")]
        if p.returncode or not line:
            print(f"{name:<14} FAILED after {time.perf_counter() - t0:.0f} s\n{p.stderr[-2000:]}")
            continue
        d = json.loads(line[0][6:])
        e = d["errors"]
        cells = "".join(f"{100 * e[q]:>+12.2f}%" if e.get(q) is not None
                        and e[q] == e[q] else f"{'-':>13}" for q in ROWS)
        print(f"{name:<14}{d['n_dofs']:>9,}{d['wall']:>8.1f}{d['peak_gb']:>8.2f}  {cells}"
              f"{d['edge_pressure'] / 1e9:>16.2f}  {d['solver']}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
