"""One class per error, whatever path it is imported from; the errors module imports
nothing of the package (any layer may raise its errors without an import circle)."""
import ast
from pathlib import Path

import pytest

import ballrace
from ballrace import errors


def test_one_convergence_error_everywhere():
    from ballrace.analytic import duplex, highspeed, loaddist, shaft

    assert loaddist.ConvergenceError is errors.ConvergenceError
    for mod in (duplex, highspeed, shaft):
        assert mod.ConvergenceError is errors.ConvergenceError
    assert issubclass(errors.ConvergenceError, RuntimeError)


def test_one_case_file_error_for_bearing_and_validation_files():
    from ballrace.casefiles import bearing as casefile
    from ballrace.validation import schema

    assert casefile.CaseFileError is schema.CaseFileError is errors.CaseFileError
    assert issubclass(errors.CaseFileError, ValueError)
    with pytest.raises(errors.CaseFileError, match="demo.toml: case 'x': missing field 'expected'"):
        schema.parse_cases('[[case]]\nid = "x"\ntitle = "t"\nkind = "published"\n'
                           'calculation = "hertz.point_contact"\nsource = {}\n', "demo.toml")


def test_errors_module_imports_nothing_of_the_package():
    tree = ast.parse(Path(errors.__file__).read_text(encoding="utf-8"))
    imported = [n.module or "" for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)]
    imported += [a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names]
    assert set(imported) <= {"__future__", "os", "sys", "warnings"}, imported


def test_subsurface_no_longer_imports_the_bearing_layer():
    """subsurface raised ConvergenceError by importing loaddist (bearing <-> loaddist <->
    subsurface); it now takes it from ballrace.errors."""
    src = Path(ballrace.__file__).parent / "analytic" / "subsurface.py"
    tree = ast.parse(src.read_text(encoding="utf-8"))
    mods = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert "loaddist" not in mods and "bearing" not in mods


@pytest.mark.parametrize("call, match", [
    (lambda: __import__("ballrace.analytic.iso281", fromlist=["x"]).walther_constants(10e-6, 1.5e-6),
     "nu100 < 2 mm\\^2/s"),
    (lambda: __import__("ballrace.analytic.life", fromlist=["x"]).contact_capacity(
        30e-3, 10, 150e-3, 0.0, 0.52, "inner"), "D = 30 mm > 25.4 mm"),
    (lambda: __import__("ballrace.analytic.life", fromlist=["x"]).load_factor(
        oscillation_angle=0.5), "false brinelling"),
])
def test_warnings_once_only_logged_reach_the_caller(call, match):
    """These went to a logger under the package's NullHandler (never seen); they are
    UserWarnings now, attributed to the line that called the library."""
    with pytest.warns(UserWarning, match=match) as rec:
        call()
    assert rec[0].filename == __file__
