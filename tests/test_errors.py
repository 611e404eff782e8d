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
    from ballrace.analytic import casefile
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
    assert all(m == "__future__" for m in imported), imported


def test_subsurface_no_longer_imports_the_bearing_layer():
    """subsurface raised ConvergenceError by importing loaddist (bearing <-> loaddist <->
    subsurface); it now takes it from ballrace.errors."""
    src = Path(ballrace.__file__).parent / "analytic" / "subsurface.py"
    tree = ast.parse(src.read_text(encoding="utf-8"))
    mods = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert "loaddist" not in mods and "bearing" not in mods
