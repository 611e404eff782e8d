"""The pip path: a command that needs a missing extra says which in one line, before any
work, and the README's commands are those a pip user can type.

The missing extra is simulated by running the CLI in a subprocess whose ``sys.modules``
holds ``None`` for the extra's modules (an import then fails, ``find_spec`` returns None),
so these tests pass whether or not the extras are installed here.
"""
from __future__ import annotations

import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FEM = ("gmsh", "skfem", "meshio", "pyvista")
REPORT = ("matplotlib", "jinja2", "dask", "distributed")


def run_without(modules, args, cwd):
    """``ballrace ARGS`` through the console-script entry point with ``modules`` absent."""
    code = ("import sys\n"
            f"for m in {tuple(modules)!r}:\n    sys.modules[m] = None\n"
            f"sys.argv = ['ballrace', *{list(args)!r}]\n"
            "from ballrace.cli import main\nmain()\n")
    env = {**os.environ, "COLUMNS": "100", "MPLBACKEND": "Agg"}
    return subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True,
                          text=True, env=env, timeout=300)


def test_fem_without_the_extra_is_one_line_before_any_work(tmp_path):
    """`ballrace fem` without gmsh: one line naming the extra and both install forms, exit
    2, no solver hint before it and no (empty) output folder left behind."""
    r = run_without(FEM, ["fem", "--level", "quick"], tmp_path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert r.stderr.splitlines() == [
        'error: the FE check needs the fem extra (gmsh, scikit-fem, meshio not installed): '
        'pip install "ballrace[fem]" (in a checkout: pip install ".[fem]")'], r.stderr
    assert r.stdout == ""
    assert "SuperLU" not in r.stderr + r.stdout
    assert list(tmp_path.iterdir()) == []            # no ballrace-out/fem


def test_fem_without_gmsh_alone_names_gmsh(tmp_path):
    r = run_without(("gmsh",), ["fem", "--case", "plane", "--load", "1 kN"], tmp_path)
    assert r.returncode == 2
    assert r.stderr.startswith("error: the FE check needs the fem extra (gmsh not installed)")
    assert len(r.stderr.splitlines()) == 1
    assert not (tmp_path / "ballrace-out").exists()


def test_fem_checks_its_options_before_the_extra(tmp_path):
    """A bad option is named as such with or without the extra (the extra's line comes
    after the options are checked and before any work)."""
    r = run_without(FEM, ["fem", "--case", "inner", "--load", "-5 N"], tmp_path)
    assert r.returncode == 2 and "load must be > 0" in r.stderr, r.stderr
    assert "fem extra" not in r.stderr and not (tmp_path / "ballrace-out").exists()


def test_fem_help_needs_no_extra(tmp_path):
    r = run_without(FEM + REPORT, ["fem", "--help"], tmp_path)
    assert r.returncode == 0 and "--load" in r.stdout, r.stderr


def test_validate_at_an_fe_level_without_the_extra_is_one_line(tmp_path):
    """The default `ballrace validate` (--fem quick) without the fem extra: one line that
    names the extra and --fem none, before any case runs (no rows, no summary)."""
    r = run_without(FEM, ["validate"], tmp_path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert len(r.stderr.splitlines()) == 1, r.stderr
    assert r.stderr.startswith("error: --fem quick: the FE cases need the fem extra (gmsh, "
                               "scikit-fem, meshio not installed)")
    assert 'pip install "ballrace[fem]"' in r.stderr and "--fem none" in r.stderr
    assert r.stdout == ""
    assert "SuperLU" not in r.stderr


def test_validate_without_fe_cases_needs_no_fem_extra(tmp_path):
    """The check looks at the selected cases: analytic cases at --fem quick run."""
    r = run_without(FEM, ["validate", "--cases", "ehl.toml", "--serial"], tmp_path)
    assert r.returncode == 0, (r.stdout, r.stderr)
    assert "validation passed" in r.stdout and r.stderr == ""


def test_validate_fem_none_without_any_extra(tmp_path):
    r = run_without(FEM + REPORT, ["validate", "--fem", "none", "--cases", "ehl.toml"], tmp_path)
    assert r.returncode == 0, (r.stdout, r.stderr)
    assert "validation passed" in r.stdout


# ------------------------------------------------------------------------------ README
def _readme_commands():
    exe = ROOT / ".ci" / "readme-commands"
    r = subprocess.run([sys.executable, str(exe), str(ROOT / "README.md"), "BALLRACE",
                        "EXAMPLES"], capture_output=True, text=True, check=True)
    return [(need, shlex.split(cmd)) for need, cmd in
            (line.split("\t", 1) for line in r.stdout.splitlines())]


def test_readme_commands_are_found_with_what_they_need():
    """.ci/pip-path runs every `ballrace` line of the README's sh blocks; this is the
    extraction it relies on (continued lines joined, comments dropped, paths rewritten)."""
    cmds = _readme_commands()
    by_head = {" ".join(c[1:3]): need for need, c in cmds}
    assert by_head["contact --load"] == "-"
    assert by_head["fem --case"] == "fem"
    assert by_head["fem --help"] == "-"
    assert by_head["teach subsurface"] == "report:matplotlib"    # the extra; the module it needs
    assert by_head["teach serve"] == "skip"
    assert {"fem,report", "-"} <= {n for n, c in cmds if c[1] == "validate"}
    contact = next(c for _, c in cmds if c[1] == "contact")
    assert contact[-2:] == ["--E1", "200 GPa"]        # the continued line is joined
    for _, c in cmds:
        assert c[0] == "BALLRACE"
        for arg in c:
            if arg.startswith("EXAMPLES/"):
                assert (ROOT / "examples" / arg.split("/", 1)[1]).is_file(), arg
    assert sum(arg.startswith("EXAMPLES/") for _, c in cmds for arg in c) >= 3


def test_readme_speaks_to_pip_users():
    """The command examples are typed as `ballrace ...` (what pip installs; `make` users
    are told about .venv/bin/ballrace), and the checkout's install forms are shown."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    import re

    blocks = "\n".join(re.findall(r"^```sh\n(.*?)^```", text, re.M | re.S))
    assert ".venv/bin/ballrace" not in blocks
    assert ".venv/bin/ballrace" in text               # said once, in prose
    for form in ("pip install ballrace", 'pip install "ballrace[fem]"', "pip install .",
                 'pip install ".[fem]"'):
        assert form in blocks, form


@pytest.mark.parametrize("script", ["pip-path", "browser"])
def test_ci_scripts_are_valid_bash(script):
    r = subprocess.run(["bash", "-n", str(ROOT / ".ci" / script)], capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr


def test_ci_browser_checks_python_before_apt():
    """.ci/browser installs pytest (and hypothesis, playwright) into its Python, or stops
    with a message, before it would apt-install chromium."""
    text = (ROOT / ".ci" / "browser").read_text(encoding="utf-8")
    assert text.index("import pytest") < text.index("apt-get")
    assert text.index("pip install") < text.index("apt-get")
    r = subprocess.run(["bash", str(ROOT / ".ci" / "browser")], capture_output=True,
                       text=True, env={**os.environ, "PYTHON": "/nonexistent/python"})
    assert r.returncode == 1 and "no Python interpreter" in r.stdout
