"""Sphinx extension: the command-line reference, generated from the CLI itself.

At ``builder-inited`` every ``ballrace`` command's ``--help`` (the text a user sees, at
88 columns) is written to ``docs/cli/index.rst`` (git-ignored, rewritten on each build),
under a short introduction to what all commands share.  A new option or command appears
on the next build; the page cannot drift from the program.
"""
from __future__ import annotations

from pathlib import Path

OUT = "cli"

INTRO = """\
Command line
============

``ballrace`` is installed with the package (``pip install ballrace``; the extras are in the
README).  What every command shares:

* **Units at the boundary.** Options and case files take quantities as strings with units,
  read with pint: ``"6.35 mm"``, ``"1000 lbf"``, ``"200 GPa"``, ``"70 degC"``,
  ``"3000 rpm"`` (or ``rev/min``).  A decimal comma, a bare number where a unit is needed,
  a temperature difference (``delta_degC``) where a temperature is needed, ``"70 C"``
  (pint's coulomb) are refused with a one-line message naming the option or key.  The
  Python API takes SI floats instead.
* **Output units.** Tables are printed in engineering units (mm, µm, MPa, N, deg) with the
  unit in every column header; ``--units si`` or ``--units us`` choose others.  ``--json``
  is always SI, with stable identifier keys (the attribute names of the results).
* **Case files and flags.** {case_commands} read TOML case files
  (:doc:`../casefiles`); an option given beside a case file takes precedence over the
  file's value.
* **Errors** are one line on stderr with exit code 2; ``validate`` exits 1 when a case
  fails.  ``-v`` logs progress (``-vv`` also the libraries underneath), before or after
  the command.
* **Output files.** ``fem`` and ``teach`` write under ``ballrace-out/`` unless ``--out``
  says otherwise; that folder carries its own ``.gitignore``.

"""


def _commands(group, prefix=()):
    """(path, click command) for every command under ``group``, depth first."""
    for name in sorted(group.commands):
        cmd = group.commands[name]
        path = (*prefix, name)
        if getattr(cmd, "commands", None):            # a group (typer's is no click.Group)
            yield path, cmd
            yield from _commands(cmd, path)
        else:
            yield path, cmd


def case_file_commands() -> list[str]:
    """The commands that read a case file: those with an argument or option whose help
    names a case file (``ballrace shaft CASE``, ``validate --cases``, ...), in order."""
    import typer

    from ballrace.cli import app

    out = []
    for path, cmd in _commands(typer.main.get_command(app)):
        if any("case file" in (getattr(p, "help", None) or "").lower()
               for p in getattr(cmd, "params", ())):
            out.append(" ".join(path))
    return out


def _and(items: list[str]) -> str:
    """``a``, ``b`` and ``c`` as reStructuredText literals.

    >>> _and(["bearing", "fem", "validate"])
    '``bearing``, ``fem`` and ``validate``'
    """
    lits = [f"``{i}``" for i in items]
    return lits[0] if len(lits) == 1 else ", ".join(lits[:-1]) + " and " + lits[-1]


def help_text(args: list[str]) -> str:
    """``ballrace ARGS --help`` as the user sees it at 88 columns (no colour)."""
    from typer.testing import CliRunner

    from ballrace.cli import app

    res = CliRunner().invoke(app, [*args, "--help"], prog_name="ballrace",
                             env={"COLUMNS": "88", "NO_COLOR": "1", "TERM": "dumb"})
    if res.exit_code != 0:
        raise RuntimeError(f"ballrace {' '.join(args)} --help failed: {res.output}")
    return res.output.rstrip()


def page() -> str:
    import typer

    from ballrace.cli import app

    root = typer.main.get_command(app)
    out = [INTRO.replace("{case_commands}", _and(case_file_commands())), "``ballrace``\n" + "-" * 12 + "\n\n.. code-block:: text\n\n"
           + _indent(help_text([])) + "\n"]
    for path, _ in _commands(root):
        title = f"``ballrace {' '.join(path)}``"
        out.append(f"{title}\n{'-' * len(title)}\n\n.. code-block:: text\n\n"
                   + _indent(help_text(list(path))) + "\n")
    return "\n".join(out)


def _indent(text: str) -> str:
    return "\n".join(("   " + ln) if ln.strip() else "" for ln in text.splitlines()) + "\n"


def _generate(app) -> None:
    outdir = Path(app.srcdir) / OUT
    outdir.mkdir(exist_ok=True)
    target = outdir / "index.rst"
    text = page()
    if not target.exists() or target.read_text(encoding="utf-8") != text:
        target.write_text(text, encoding="utf-8")


def setup(app):
    app.connect("builder-inited", _generate)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
