"""Command-line interface: ``ballrace <command> ...``.

Units are parsed here (with pint, see :mod:`ballrace.units`) and nowhere inside the
library.  Each area registers its own commands from a small module that imports its
heavy dependencies only when a command runs:

* ``contact``  — this module;
* ``bearing``  — :mod:`ballrace.commands.bearing` (when present);
* ``shaft``    — :mod:`ballrace.commands.shaft`;
* ``fem``      — :mod:`ballrace.fem.cli`;
* ``validate`` — :mod:`ballrace.validation.cli`;
* ``teach``    — :mod:`ballrace.teach.commands`.

Global options: ``--version``, and ``-v`` / ``-vv`` (ballrace's progress logging /
everything, including the libraries underneath), accepted before or after the command
(``ballrace fem -v``).  Errors are one line on stderr with exit code 2.
"""
from __future__ import annotations

import importlib
import json
import logging
import re
import sys
from typing import Annotated, Optional

import typer
from typer.core import TyperGroup

from ballrace.console import UNITS_HELP, literal, make_console, print_sections, unit_label
from ballrace.units import parse_quantity

_VERBOSE = re.compile(r"-v+|--verbose")


class _Group(TyperGroup):
    """The root command group: ``-v`` / ``--verbose`` is accepted after the command too,
    and ``--help`` shows ``--load LOAD`` instead of typer's ``<str>`` placeholders."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        _name_metavars(self)

    def parse_args(self, ctx, args):
        args = list(args)
        end = args.index("--") if "--" in args else len(args)
        flags = [a for a in args[:end] if _VERBOSE.fullmatch(a)]
        rest = [a for a in args[:end] if not _VERBOSE.fullmatch(a)] + args[end:]
        return super().parse_args(ctx, flags + rest)


def _name_metavars(cmd) -> None:
    """Give every value-taking parameter of ``cmd`` and its sub-commands a named metavar."""
    for p in getattr(cmd, "params", ()):
        if getattr(p, "metavar", "") is None and not getattr(p, "is_flag", False) \
                and not getattr(p, "count", False):
            p.metavar = (p.name or "value").upper()
        if getattr(p, "param_type_name", "") == "argument":
            p.display_type_rich = lambda ctx: None      # "CASE_FILE", not "CASE_FILE <str>"
    for sub in getattr(cmd, "commands", {}).values():
        _name_metavars(sub)


app = typer.Typer(cls=_Group, add_completion=False, no_args_is_help=True,
                  rich_markup_mode=None, pretty_exceptions_enable=False,
                  help="ballrace: Hertz contact and ball-bearing calculations (SI inside; "
                       "tables in engineering units, --units to choose; --json in SI).")

_SUBMODULES = ("ballrace.commands.bearing", "ballrace.commands.shaft", "ballrace.fem.cli",
               "ballrace.validation.cli", "ballrace.teach.commands")

#: Values of the ``--units`` option of the table-printing commands.
UNIT_SYSTEMS = ("eng", "si", "us")


def _version() -> str:
    try:
        from importlib.metadata import version

        return version("ballrace")
    except Exception:  # not installed (run from a checkout)
        from ballrace import __version__

        return __version__


def _show_version(value: bool):
    if value:
        typer.echo(f"ballrace {_version()}")
        raise typer.Exit()


@app.callback()
def _main(
    verbose: Annotated[int, typer.Option(
        "--verbose", "-v", count=True, show_default=False,
        help="-v: log ballrace's progress; -vv: also the libraries underneath "
             "(scikit-fem, dask, ...).  Accepted after the command too.")] = 0,
    version: Annotated[bool, typer.Option(
        "--version", is_eager=True, callback=_show_version,
        help="Print the version and exit.")] = False,
):
    configure_logging(verbose)


def configure_logging(verbose: int) -> None:
    """WARNING for everything; ballrace at DEBUG with ``-v``; everything at DEBUG with ``-vv``."""
    root = logging.getLogger()
    if not root.handlers:
        logging.basicConfig(format="%(levelname)s %(name)s: %(message)s")
    root.setLevel(logging.DEBUG if verbose >= 2 else logging.WARNING)
    logging.getLogger("ballrace").setLevel(logging.DEBUG if verbose >= 1 else logging.NOTSET)


def check_units(units: str) -> str:
    """Validate a ``--units`` value (exit 2 with a one-line error)."""
    if units not in UNIT_SYSTEMS:
        fail(f"--units must be one of {', '.join(UNIT_SYSTEMS)}; got {units!r}")
    return units


#: The keys of ``ballrace contact --json`` ("values", "units" and "labels"), in SI:
#: stable identifiers, the attribute names of HertzContact and the subsurface results.
CONTACT_JSON_KEYS = ("load", "Rx", "Ry", "E_prime", "k", "a", "b", "approach", "p_max",
                     "p_mean", "stiffness", "size_ratio", "tau0", "z0", "x0", "max_shear", "max_shear_depth",
                     "von_mises", "von_mises_depth")


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
    units: Annotated[str, typer.Option("--units", help=UNITS_HELP)] = "eng",
):
    """Elliptical Hertz contact of two bodies, with the subsurface shear stresses."""
    from ballrace.analytic import hertz

    check_units(units)
    import warnings

    from ballrace.units import plausible

    try:
        q = parse_quantity(load, "[force]", "--load")
        radii = []
        for n, v in (("--rx1", rx1), ("--ry1", ry1), ("--rx2", rx2), ("--ry2", ry2)):
            radii.append(parse_quantity(v, "[length]", n, allow_inf=True))
            plausible(radii[-1], v, n, "radius")        # "6.35 m" for "6.35 mm": a warning
        m1 = _material(e1, nu1, "--E1", "--nu1")
        m2 = m1 if e2 is None and nu2 is None else _material(
            e2 or e1, nu1 if nu2 is None else nu2, "--E2" if e2 else "--E1",
            "--nu2" if nu2 is not None else "--nu1")
        with warnings.catch_warnings():       # a/R beyond Hertz: said in the table instead
            warnings.filterwarnings("ignore", message=r"point_contact: a / R",
                                    category=UserWarning)
            c = hertz.point_contact(q, *radii, m1, m2, method=method)
    except (ValueError, TypeError) as exc:
        fail(str(exc))
    size = hertz.size_ratio(c.a, radii)
    # (JSON key, table label, SI value, kind of quantity for the display units; None:
    # dimensionless).  The keys are stable identifiers (the HertzContact / subsurface
    # attribute names, CONTACT_JSON_KEYS); the labels are for people and may change.
    rows = [("load", "load Q", float(c.load), "force"), ("Rx", "Rx", float(c.Rx), "length"),
            ("Ry", "Ry", float(c.Ry), "length"),
            ("E_prime", "E' (= 2 E*)", float(c.E_prime), "modulus"),
            ("k", "k = a/b", float(c.k), None),
            ("a", "a (semi-major)", float(c.a), "length"),
            ("b", "b (semi-minor)", float(c.b), "length"),
            ("approach", "approach delta", float(c.approach), "small"),
            ("p_max", "p_max", float(c.p_max), "stress"),
            ("p_mean", "p_mean", float(c.p_mean), "stress"),
            ("stiffness", "stiffness K", float(c.stiffness), "stiffness"),
            ("size_ratio", "a / smallest radius", size, None)]
    from ballrace.analytic import subsurface

    nu = m1.nu if m1.nu == m2.nu else None
    note = None
    if size > hertz.SIZE_LIMIT:
        note = (f"a / R = {size:.3g} > {hertz.SIZE_LIMIT:g}: beyond Hertz's small-contact "
                "assumption (a << R); these numbers are extrapolations, not a contact")
    try:
        o = subsurface.orthogonal_shear(c)
        rows += [("tau0", "LP tau0 (orthogonal shear)", float(o.tau0), "stress"),
                 ("z0", "LP z0", float(o.z0), "length"),
                 ("x0", "LP x0 (rolling offset)", float(o.x0), "length")]
    except ValueError as exc:  # major axis along the rolling direction: LP does not apply
        note = (note + "; " if note else "") + f"Lundberg-Palmgren shear not reported: {exc}"
    if nu is not None:
        mx = subsurface.max_shear(c, nu=nu)
        vm = subsurface.von_mises(c, nu=nu)
        rows += [("max_shear", "max shear (Tresca) on axis", float(mx.tau_max), "stress"),
                 ("max_shear_depth", "depth of max shear", float(mx.depth), "length"),
                 ("von_mises", "max von Mises on axis", float(vm.sigma_vm), "stress"),
                 ("von_mises_depth", "depth of max von Mises", float(vm.depth), "length")]
    else:
        note = (note + "; " if note else "") + \
            "subsurface stresses need one Poisson's ratio (nu1 != nu2): not reported"
    if as_json:
        out = {key: val for key, _, val, _ in rows}
        out["method"] = method
        if note:
            out["note"] = note
        typer.echo(json.dumps({"units": {key: unit_label(k, "si") or "-"
                                         for key, _, _, k in rows},
                               "labels": {key: label for key, label, _, _ in rows},
                               "values": out}, indent=2))
        return
    con = make_console()
    print_sections(con, [(f"Hertz contact ({method})",
                          [(label, val, k) for _, label, val, k in rows])], units)
    if note:
        con.print(literal(f"note: {note}"))


def _material(e_text: str, nu: float, e_opt: str, nu_opt: str):
    """A Material from the ``--E1``/``--nu1`` (or ``--E2``/``--nu2``) options; errors and
    the modulus warning name the option and quote what was typed."""
    import warnings

    from ballrace import Material
    from ballrace.units import plausible

    E = parse_quantity(e_text, "[pressure]", e_opt)
    plausible(E, e_text, e_opt, "modulus")          # "200 MPa" for "200 GPa": a warning
    try:
        with warnings.catch_warnings():             # the library's warning speaks of Pa;
            warnings.filterwarnings("ignore", message=r".*moduli are in pascals")  # said above
            return Material(E=E, nu=nu)
    except ValueError as exc:
        opt = nu_opt if str(exc).startswith("nu") else e_opt
        hint = " (steel: 0.3)" if opt == nu_opt else ""
        raise ValueError(f"{opt}: {exc}{hint}") from None


def fail(message: str) -> None:
    """One-line error on stderr, exit code 2 (printed literally)."""
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)


_fail = fail


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


def _one_line_warning(message, category, filename, lineno, line=None) -> str:
    return f"warning: {message}\n"


def main() -> None:  # console-script entry point
    import warnings

    warnings.formatwarning = _one_line_warning    # "warning: ...", not a source excerpt
    app()


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
