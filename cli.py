"""Command-line interface: ``ballrace <command> ...``.

Units are parsed here (with pint, see :mod:`ballrace.units`) and nowhere inside the
library.  Each area registers its own commands from a small module that imports its
heavy dependencies only when a command runs:

* ``contact``  — this module;
* ``bearing``  — :mod:`ballrace.analytic.cli` (when present);
* ``fem``      — :mod:`ballrace.fem.cli`;
* ``validate``, ``teach`` — :mod:`ballrace.validation.cli`.
"""
from __future__ import annotations

import importlib
import json
import logging
import sys
from typing import Annotated, Optional

import numpy as np
import typer

from ballrace.units import parse_quantity

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="ballrace: Hertz contact and ball-bearing calculations (SI inside).")

_SUBMODULES = ("ballrace.analytic.cli", "ballrace.fem.cli", "ballrace.validation.cli")


@app.callback()
def _main(verbose: Annotated[bool, typer.Option("--verbose", "-v", help="Log progress details.")] = False):
    logging.basicConfig(level=logging.DEBUG if verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")


@app.command()
def contact(
    load: Annotated[str, typer.Option(help='Normal load, e.g. "4.45 N", "1000 lbf".')],
    rx1: Annotated[str, typer.Option(help='Body 1 radius in the rolling plane x ("6.35 mm").')],
    ry1: Annotated[str, typer.Option(help="Body 1 radius in the transverse plane y.")],
    rx2: Annotated[str, typer.Option(help='Body 2 radius in x; "inf" for flat, negative if concave.')] = "inf",
    ry2: Annotated[str, typer.Option(help="Body 2 radius in y.")] = "inf",
    e1: Annotated[str, typer.Option("--E1", help="Young's modulus of body 1.")] = "200 GPa",
    nu1: Annotated[float, typer.Option("--nu1", help="Poisson's ratio of body 1.")] = 0.3,
    e2: Annotated[Optional[str], typer.Option("--E2", help="Young's modulus of body 2 (default: E1).")] = None,
    nu2: Annotated[Optional[float], typer.Option("--nu2", help="Poisson's ratio of body 2 (default: nu1).")] = None,
    method: Annotated[str, typer.Option(help="exact | brewe-hamrock-1977 | hamrock-brewe-1983")] = "exact",
    as_json: Annotated[bool, typer.Option("--json", help="Machine-readable JSON (SI units).")] = False,
):
    """Elliptical Hertz contact of two bodies, with the subsurface shear stresses."""
    from ballrace import Material
    from ballrace.analytic import hertz

    try:
        q = parse_quantity(load, "[force]", "load")
        radii = [parse_quantity(v, "[length]", n, allow_inf=True)
                 for n, v in (("rx1", rx1), ("ry1", ry1), ("rx2", rx2), ("ry2", ry2))]
        m1 = Material(E=parse_quantity(e1, "[pressure]", "E1"), nu=nu1)
        m2 = Material(E=parse_quantity(e2, "[pressure]", "E2") if e2 else m1.E,
                      nu=nu1 if nu2 is None else nu2)
        c = hertz.point_contact(q, *radii, m1, m2, method=method)
    except (ValueError, TypeError) as exc:
        _fail(str(exc))
    rows = [("load Q", float(c.load), "N"), ("Rx", float(c.Rx), "m"), ("Ry", float(c.Ry), "m"),
            ("E' (= 2 E*)", float(c.E_prime), "Pa"), ("k = a/b", float(c.k), "-"),
            ("a (semi-major)", float(c.a), "m"), ("b (semi-minor)", float(c.b), "m"),
            ("approach delta", float(c.approach), "m"), ("p_max", float(c.p_max), "Pa"),
            ("p_mean", float(c.p_mean), "Pa"), ("stiffness K", float(c.stiffness), "N/m^1.5")]
    from ballrace.analytic import subsurface

    nu = m1.nu if m1.nu == m2.nu else None
    note = None
    try:
        o = subsurface.orthogonal_shear(c)
        rows += [("LP tau0 (orthogonal shear)", float(o.tau0), "Pa"), ("LP z0", float(o.z0), "m"),
                 ("LP x0 (rolling offset)", float(o.x0), "m")]
    except ValueError as exc:  # major axis along the rolling direction: LP does not apply
        note = f"Lundberg-Palmgren shear not reported: {exc}"
    if nu is not None:
        mx = subsurface.max_shear(c, nu=nu)
        vm = subsurface.von_mises(c, nu=nu)
        rows += [("max shear (Tresca) on axis", float(mx.tau_max), "Pa"),
                 ("depth of max shear", float(mx.depth), "m"),
                 ("max von Mises on axis", float(vm.sigma_vm), "Pa"),
                 ("depth of max von Mises", float(vm.depth), "m")]
    else:
        note = (note + "; " if note else "") + \
            "subsurface stresses need one Poisson's ratio (nu1 != nu2): not reported"
    if as_json:
        out = {name: val for name, val, _ in rows}
        out["method"] = method
        if note:
            out["note"] = note
        typer.echo(json.dumps({"units": {n: u for n, _, u in rows}, "values": out}, indent=2))
        return
    _table(f"Hertz contact ({method})", rows)
    if note:
        typer.echo(note)


def _table(title: str, rows) -> None:
    from rich.console import Console
    from rich.table import Table

    t = Table(title=title)
    t.add_column("quantity")
    t.add_column("value", justify="right")
    t.add_column("unit")
    for name, val, unit in rows:
        t.add_row(name, f"{val:.6g}", unit)
    Console().print(t)


def _fail(message: str) -> None:
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)


def _register_submodules() -> None:
    for name in _SUBMODULES:
        try:
            mod = importlib.import_module(name)
        except ModuleNotFoundError as exc:
            if exc.name == name:
                continue
            raise
        mod.register(app)


_register_submodules()


def main() -> None:  # console-script entry point
    app()


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
