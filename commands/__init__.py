"""The command-line commands of the formula layer (boundary code).

``ballrace bearing`` (:mod:`ballrace.commands.bearing`) and ``ballrace shaft``
(:mod:`ballrace.commands.shaft`): each module reads its case file, calls the formulas of
:mod:`ballrace.analytic` with SI floats, and renders the result as tables in engineering
units or, with ``--json``, as SI numbers.  Registered on the main app by :mod:`ballrace.cli`.
"""

from pathlib import Path

__all__ = ["run_case_file"]


def run_case_file(case_file: str, units: str, kind: str, load, analyze, message=str):
    """``analyze(load(case_file))`` for a command, after checking ``--units``; every failure
    is one ``error: ...`` line with exit code 2 (:func:`ballrace.cli.fail`).

    ``kind`` names the case file in the messages (``"bearing"``: "give a bearing case file");
    ``message`` turns a :class:`~ballrace.errors.CaseFileError` into the line shown.
    """
    from ballrace.cli import check_units, fail
    from ballrace.errors import CaseFileError

    check_units(units)
    if Path(case_file).is_dir():
        fail(f"{case_file}: is a directory; give a {kind} case file (.toml)")
    try:
        return analyze(load(case_file))
    except CaseFileError as exc:
        fail(message(exc))
    except UnicodeDecodeError:
        fail(f"{case_file}: not a text file; give a {kind} case file (TOML)")
    except (OSError, ValueError, RuntimeError) as exc:
        fail(f"{case_file}: {exc}")
